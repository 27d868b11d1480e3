/* SPDX-License-Identifier: GPL-2.0-or-later */
/* CHOLMOD backend: Cholesky for symmetric positive definite matrices.
 * The CSR arrays are wrapped (not copied) as a CHOLMOD matrix with stype = 1,
 * so CHOLMOD reads one triangle only; with stype = 0 it would factorise
 * A A^T instead and silently solve the wrong system. Since only one triangle
 * is read, the numeric step first checks that A really is symmetric. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include <cholmod.h>

#include "core/solve/linsolve.h"

#define STR_(x) #x
#define STR(x) STR_(x)

typedef struct chol_state {
  cholmod_common c;
  int started;
  cholmod_factor *L;
  cholmod_dense *X, *Y, *E; /* solve workspace, reused by cholmod_solve2 */
} chol_state;

static const char *chol_status_text(int s) {
  switch (s) {
    case CHOLMOD_OK:
      return "ok";
    case CHOLMOD_NOT_INSTALLED:
      return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "problem too large";
    case CHOLMOD_INVALID:
      return "invalid input";
    case CHOLMOD_GPU_PROBLEM:
      return "GPU problem";
    case CHOLMOD_NOT_POSDEF:
      return "matrix is not positive definite";
    case CHOLMOD_DSMALL:
      return "tiny diagonal entry in D";
    default:
      return "unknown status";
  }
}

static int chol_fail(const chol_state *s, const char *stage, int32_t n, sl_diag *d) {
  return sl_diag_set(d, SL_EFAILED, "cholmod: %s (status %d) in the %s of a %d x %d matrix",
                     chol_status_text(s->c.status), s->c.status, stage, (int)n, (int)n);
}

/* A view of the CSR arrays: column j of this CSC is row j of A, so stype = 1
 * (entries with row index <= column index) is A's lower triangle, which
 * equals the upper one for a symmetric A. */
static cholmod_sparse view(const sl_csr *A) {
  cholmod_sparse S = {0};
  S.nrow = S.ncol = (size_t)A->n_rows;
  S.nzmax = (size_t)A->nnz;
  S.p = A->row_ptr;
  S.i = A->col_idx;
  S.x = A->values;
  S.stype = 1;
  S.itype = CHOLMOD_INT;
  S.xtype = CHOLMOD_REAL;
  S.dtype = CHOLMOD_DOUBLE;
  S.sorted = 1;
  S.packed = 1;
  return S;
}

static int chol_create(void **backend, sl_diag *d) {
  chol_state *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "cholmod: out of memory");
  if (!cholmod_start(&s->c)) {
    free(s);
    return sl_diag_set(d, SL_EFAILED, "cholmod: cholmod_start failed");
  }
  s->started = 1;
  s->c.print = 0; /* errors come back as status codes and sl_diag messages */
  *backend = s;
  return 0;
}

static int chol_symbolic(void *backend, const sl_csr *A, sl_diag *d) {
  chol_state *s = backend;
  if (s->L) cholmod_free_factor(&s->L, &s->c);
  cholmod_sparse S = view(A);
  s->L = cholmod_analyze(&S, &s->c);
  if (!s->L) return chol_fail(s, "symbolic analysis", A->n_rows, d);
  return 0;
}

/* |A(i,j) - A(j,i)| must be small against the larger of the two rows. */
static int check_symmetric(const sl_csr *A, sl_diag *d) {
  int32_t n = A->n_rows;
  double *rowmax = calloc((size_t)n, sizeof *rowmax);
  if (!rowmax) return sl_diag_set(d, SL_ENOMEM, "cholmod: out of memory");
  for (int32_t i = 0; i < n; ++i)
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p)
      if (fabs(A->values[p]) > rowmax[i]) rowmax[i] = fabs(A->values[p]);
  for (int32_t i = 0; i < n; ++i) {
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) {
      int32_t j = A->col_idx[p];
      if (j <= i) continue;
      int32_t q = sl_csr_find(A, j, i);
      double aij = A->values[p], aji = q >= 0 ? A->values[q] : 0.0;
      double scale = rowmax[i] > rowmax[j] ? rowmax[i] : rowmax[j];
      if (fabs(aij - aji) > 1e-12 * scale) {
        free(rowmax);
        return sl_diag_set(d, SL_EFAILED,
                           "cholmod: matrix is not symmetric: A(%d,%d) = %.17g but A(%d,%d) = %.17g; cholmod needs a "
                           "symmetric positive definite matrix (use umfpack or klu)",
                           (int)i, (int)j, aij, (int)j, (int)i, aji);
      }
    }
  }
  free(rowmax);
  return 0;
}

static int chol_numeric(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d) {
  chol_state *s = backend;
  int rc = check_symmetric(A, d);
  if (rc) return rc;
  cholmod_sparse S = view(A);
  int ok = cholmod_factorize(&S, s->L, &s->c);
  if (!ok || s->c.status < CHOLMOD_OK) return chol_fail(s, "numeric factorisation", A->n_rows, d);
  if (s->c.status == CHOLMOD_NOT_POSDEF || s->L->minor < s->L->n)
    return sl_diag_set(d, SL_EFAILED,
                       "cholmod: matrix is not positive definite (factorisation broke down at pivot %d of %d, in the "
                       "fill-reducing order); use umfpack or klu for indefinite or nonsymmetric matrices",
                       (int)s->L->minor + 1, (int)A->n_rows);
  st->rcond = cholmod_rcond(s->L, &s->c);
  if (!(st->rcond >= DBL_EPSILON))
    return sl_diag_set(d, SL_EFAILED,
                       "cholmod: matrix is numerically singular (rcond %.3g) in the numeric "
                       "factorisation of a %d x %d matrix",
                       st->rcond, (int)A->n_rows, (int)A->n_rows);
  return 0;
}

static int chol_solve(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  chol_state *s = backend;
  cholmod_dense B = {0};
  B.nrow = B.nzmax = B.d = (size_t)A->n_rows;
  B.ncol = 1;
  B.x = (void *)b; /* read only */
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(CHOLMOD_A, s->L, &B, NULL, &s->X, NULL, &s->Y, &s->E, &s->c))
    return chol_fail(s, "solve", A->n_rows, d);
  const double *xs = s->X->x;
  for (int32_t i = 0; i < A->n_rows; ++i) x[i] = xs[i];
  return 0;
}

static void chol_destroy(void *backend) {
  chol_state *s = backend;
  if (!s) return;
  if (s->L) cholmod_free_factor(&s->L, &s->c);
  if (s->X) cholmod_free_dense(&s->X, &s->c);
  if (s->Y) cholmod_free_dense(&s->Y, &s->c);
  if (s->E) cholmod_free_dense(&s->E, &s->c);
  if (s->started) cholmod_finish(&s->c);
  free(s);
}

const sl_linsolve_ops sl_linsolve_cholmod_ops = {
    .name = "cholmod",
    .description = "CHOLMOD " STR(CHOLMOD_MAIN_VERSION) "." STR(CHOLMOD_SUB_VERSION) "." STR(
        CHOLMOD_SUBSUB_VERSION) ": sparse Cholesky, symmetric positive definite matrices",
    .create = chol_create,
    .symbolic = chol_symbolic,
    .numeric = chol_numeric,
    .solve = chol_solve,
    .destroy = chol_destroy,
};
