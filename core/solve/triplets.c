/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Triplet assembly into CSR with the pattern kept (triplets.h). */
#include "core/solve/triplets.h"

#include <stdlib.h>
#include <string.h>

int sl_triplets_add(sl_triplets *t, int32_t row, int32_t col, double v) {
  if (row < 0 || col < 0) return 0;
  if (t->n == t->cap) {
    int32_t cap = t->cap ? 2 * t->cap : 1024;
    int32_t *r = realloc(t->row, (size_t)cap * sizeof *r);
    if (r) t->row = r;
    int32_t *c = realloc(t->col, (size_t)cap * sizeof *c);
    if (c) t->col = c;
    double *x = realloc(t->val, (size_t)cap * sizeof *x);
    if (x) t->val = x;
    if (!r || !c || !x) return -1;
    t->cap = cap;
  }
  t->row[t->n] = row, t->col[t->n] = col, t->val[t->n] = v, ++t->n;
  return 0;
}

int sl_triplets_to_csr(sl_triplets *t, sl_csr *A, int32_t n, sl_diag *d) {
  int same = t->n_pattern && A->nnz > 0 && t->n == t->n_pattern &&
             memcmp(t->prow, t->row, (size_t)t->n * sizeof *t->row) == 0 &&
             memcmp(t->pcol, t->col, (size_t)t->n * sizeof *t->col) == 0;
  if (!same) {
    int32_t *iota = malloc((size_t)(t->n + 1) * sizeof *iota);
    int32_t *pos = realloc(t->pos, (size_t)(t->n > 0 ? t->n : 1) * sizeof *pos);
    if (pos) t->pos = pos;
    if (!iota || !pos) {
      free(iota);
      return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory");
    }
    for (int32_t k = 0; k <= t->n; ++k) iota[k] = k;
    sl_csr_free(A);
    int rc = sl_csr_build(A, n, n, t->n, iota, t->row, iota, t->col, d);
    free(iota);
    if (rc) return rc;
    for (int32_t k = 0; k < t->n; ++k) t->pos[k] = sl_csr_find(A, t->row[k], t->col[k]);
    int32_t *pr = realloc(t->prow, (size_t)(t->n > 0 ? t->n : 1) * sizeof *pr);
    if (pr) t->prow = pr;
    int32_t *pc = realloc(t->pcol, (size_t)(t->n > 0 ? t->n : 1) * sizeof *pc);
    if (pc) t->pcol = pc;
    if (!pr || !pc) return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory");
    memcpy(t->prow, t->row, (size_t)t->n * sizeof *pr);
    memcpy(t->pcol, t->col, (size_t)t->n * sizeof *pc);
    t->n_pattern = t->n;
  }
  sl_csr_zero(A);
  for (int32_t k = 0; k < t->n; ++k) A->values[t->pos[k]] += t->val[k];
  sl_csr_touch(A);
  return 0;
}

void sl_triplets_free(sl_triplets *t) {
  free(t->row), free(t->col), free(t->val), free(t->prow), free(t->pcol), free(t->pos);
  memset(t, 0, sizeof *t);
}
