/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Finite-difference Poisson matrices for the solver tests and the benchmark:
 * the 3-point (1-D) and 5-point (2-D) Laplacians with Dirichlet boundaries
 * eliminated, built through the sparsity builder with one "element" per row
 * (rows = {i}, columns = the stencil). */
#ifndef SLUICE_TESTS_SOLVE_POISSON_H
#define SLUICE_TESTS_SOLVE_POISSON_H

#include <stdlib.h>

#include "core/solve/sparse.h"

/* n x n grid in 2-D (ny = n), or n points in 1-D (ny = 1). shift is
 * subtracted from the diagonal (shift > 0 can make the matrix indefinite). */
static inline int poisson_build(sl_csr *A, int nx, int ny, double shift, sl_diag *d) {
  int32_t n = (int32_t)nx * ny;
  int32_t *rptr = malloc(((size_t)n + 1) * sizeof *rptr), *rows = malloc((size_t)n * sizeof *rows);
  int32_t *cptr = malloc(((size_t)n + 1) * sizeof *cptr), *cols = malloc((size_t)n * 5 * sizeof *cols);
  double *vals = malloc((size_t)n * 5 * sizeof *vals);
  int rc = SL_EFAILED;
  if (!rptr || !rows || !cptr || !cols || !vals) goto done;
  rptr[0] = cptr[0] = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int32_t r = (int32_t)j * nx + i, k = cptr[r];
      double diag = (ny > 1 ? 4.0 : 2.0) - shift;
      rows[r] = r;
      rptr[r + 1] = r + 1;
      cols[k] = r, vals[k++] = diag;
      if (i > 0) cols[k] = r - 1, vals[k++] = -1.0;
      if (i < nx - 1) cols[k] = r + 1, vals[k++] = -1.0;
      if (j > 0) cols[k] = r - nx, vals[k++] = -1.0;
      if (j < ny - 1) cols[k] = r + nx, vals[k++] = -1.0;
      cptr[r + 1] = k;
    }
  rc = sl_csr_build(A, n, n, n, rptr, rows, cptr, cols, d);
  for (int32_t r = 0; !rc && r < n; ++r)
    rc = sl_csr_add_element(A, 1, &r, (int)(cptr[r + 1] - cptr[r]), cols + cptr[r], vals + cptr[r], d);
done:
  free(rptr), free(rows), free(cptr), free(cols), free(vals);
  return rc;
}

#endif
