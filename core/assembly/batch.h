/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Internal to core/assembly: the quadrature-point batches through which the
 * operators evaluate their coefficients. */
#ifndef SLUICE_ASSEMBLY_BATCH_H
#define SLUICE_ASSEMBLY_BATCH_H

#include "core/assembly/operators.h"

typedef struct sl_asm_batch {
  int nq;             /* quadrature points per cell */
  int first, n_cells; /* the cells of the current batch */
  double (*x)[2];     /* [SL_ASSEMBLY_BATCH_CELLS * nq] */
  int32_t *cell;
  double *shear_rate; /* NULL unless asked for */
} sl_asm_batch;

int sl_asm_batch_init(sl_asm_batch *b, int nq, int with_shear_rate, sl_diag *d);
void sl_asm_batch_free(sl_asm_batch *b);
/* The view a coefficient receives. */
sl_qp_batch sl_asm_batch_view(const sl_asm_batch *b);
/* out[width * i + c] for the batch: the constant, or the callback with its
 * output checked for non-finite values. `what` names the coefficient in
 * messages. */
int sl_asm_coef_eval(const sl_coef *cf, const char *what, const sl_qp_batch *qb, int width, double *out, sl_diag *d);
/* True when the coefficient is the constant zero: the term is skipped. */
static inline int sl_asm_coef_is_zero(const sl_coef *cf) { return !cf->fn && cf->value == 0.0; }

#endif
