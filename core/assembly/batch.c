/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Quadrature-point batches and coefficient evaluation. */
#include "core/assembly/batch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sl_asm_batch_init(sl_asm_batch *b, int nq, int with_shear_rate, sl_diag *d) {
  memset(b, 0, sizeof *b);
  size_t cap = (size_t)SL_ASSEMBLY_BATCH_CELLS * nq;
  b->nq = nq;
  b->x = malloc(cap * sizeof *b->x);
  b->cell = malloc(cap * sizeof *b->cell);
  if (with_shear_rate) b->shear_rate = malloc(cap * sizeof *b->shear_rate);
  if (!b->x || !b->cell || (with_shear_rate && !b->shear_rate)) {
    sl_asm_batch_free(b);
    return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for a batch of %zu points", cap);
  }
  return 0;
}

void sl_asm_batch_free(sl_asm_batch *b) {
  free(b->x);
  free(b->cell);
  free(b->shear_rate);
  memset(b, 0, sizeof *b);
}

sl_qp_batch sl_asm_batch_view(const sl_asm_batch *b) {
  return (sl_qp_batch){
      .n = b->n_cells * b->nq, .x = (const double(*)[2])b->x, .cell = b->cell, .shear_rate = b->shear_rate};
}

int sl_asm_coef_eval(const sl_coef *cf, const char *what, const sl_qp_batch *qb, int width, double *out, sl_diag *d) {
  size_t n = (size_t)qb->n * width;
  if (!cf->fn) {
    for (size_t i = 0; i < n; ++i) out[i] = cf->value;
    return 0;
  }
  int rc = cf->fn(cf->user, qb, out, d);
  if (rc) return sl_diag_prefix(d, rc, "assembly: %s", what);
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(out[i])) {
      size_t p = i / (size_t)width;
      return sl_diag_set(d, SL_EFAILED, "assembly: %s is %g at (%g, %g) in cell %d", what, out[i], qb->x[p][0],
                         qb->x[p][1], (int)qb->cell[p]);
    }
  return 0;
}
