/* SPDX-License-Identifier: GPL-2.0-or-later */
/* UMFPACK backend (general sparse LU, the default). The CSR arrays of A are
 * handed over as the CSC of A^T and the system is solved with UMFPACK_At.
 * The 64-bit interface (umfpack_dl): the 32-bit one runs out of index space
 * in the factor's workspace near 2 GB (a 590k-unknown Q2/Q1 Stokes matrix),
 * whatever memory the machine has. Its index arrays are 64-bit copies of the
 * pattern, made once per symbolic analysis. */
#include <float.h>
#include <stdlib.h>
#include <umfpack.h>

#include "core/solve/linsolve.h"

typedef struct umf_state {
  void *sym, *num;
  SuiteSparse_long *ptr, *idx; /* the pattern's row_ptr and col_idx, 64-bit */
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
} umf_state;

static const char *umf_status_text(int s) {
  switch (s) {
    case UMFPACK_OK:
      return "ok";
    case UMFPACK_WARNING_singular_matrix:
      return "matrix is singular";
    case UMFPACK_WARNING_determinant_underflow:
      return "determinant underflow";
    case UMFPACK_WARNING_determinant_overflow:
      return "determinant overflow";
    case UMFPACK_ERROR_out_of_memory:
      return "out of memory";
    case UMFPACK_ERROR_invalid_Numeric_object:
      return "invalid Numeric object";
    case UMFPACK_ERROR_invalid_Symbolic_object:
      return "invalid Symbolic object";
    case UMFPACK_ERROR_argument_missing:
      return "argument missing";
    case UMFPACK_ERROR_n_nonpositive:
      return "matrix size is not positive";
    case UMFPACK_ERROR_invalid_matrix:
      return "invalid matrix (unsorted or out-of-range indices)";
    case UMFPACK_ERROR_different_pattern:
      return "pattern changed since the symbolic analysis";
    case UMFPACK_ERROR_invalid_system:
      return "invalid system";
    case UMFPACK_ERROR_ordering_failed:
      return "ordering failed";
    case UMFPACK_ERROR_internal_error:
      return "internal error";
    default:
      return "unknown status";
  }
}

static int umf_fail(int status, const char *stage, int32_t n, sl_diag *d) {
  return sl_diag_set(d, SL_EFAILED, "umfpack: %s (status %d) in the %s of a %d x %d matrix", umf_status_text(status),
                     status, stage, (int)n, (int)n);
}

static int umf_create(void **backend, sl_diag *d) {
  umf_state *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "umfpack: out of memory");
  umfpack_dl_defaults(s->control);
  s->control[UMFPACK_PRL] = 0; /* never print */
  *backend = s;
  return 0;
}

static void umf_drop(umf_state *s) {
  if (s->num) umfpack_dl_free_numeric(&s->num);
  if (s->sym) umfpack_dl_free_symbolic(&s->sym);
  s->num = s->sym = NULL;
  free(s->ptr), free(s->idx);
  s->ptr = s->idx = NULL;
}

static int umf_symbolic(void *backend, const sl_csr *A, sl_diag *d) {
  umf_state *s = backend;
  umf_drop(s);
  s->ptr = malloc(((size_t)A->n_rows + 1) * sizeof *s->ptr);
  s->idx = malloc(((size_t)A->nnz + 1) * sizeof *s->idx);
  if (!s->ptr || !s->idx) {
    umf_drop(s);
    return sl_diag_set(d, SL_ENOMEM, "umfpack: out of memory for the pattern of a %d x %d matrix", (int)A->n_rows,
                       (int)A->n_rows);
  }
  for (int32_t i = 0; i <= A->n_rows; ++i) s->ptr[i] = A->row_ptr[i];
  for (int32_t k = 0; k < A->nnz; ++k) s->idx[k] = A->col_idx[k];
  int st = (int)umfpack_dl_symbolic(A->n_rows, A->n_cols, s->ptr, s->idx, A->values, &s->sym, s->control, s->info);
  if (st != UMFPACK_OK) {
    if (s->sym) umfpack_dl_free_symbolic(&s->sym);
    s->sym = NULL;
    return umf_fail(st, "symbolic analysis", A->n_rows, d);
  }
  return 0;
}

static int umf_numeric(void *backend, const sl_csr *A, sl_linsolve_stats *stats, sl_diag *d) {
  umf_state *s = backend;
  if (s->num) umfpack_dl_free_numeric(&s->num);
  s->num = NULL;
  int st = (int)umfpack_dl_numeric(s->ptr, s->idx, A->values, s->sym, &s->num, s->control, s->info);
  stats->rcond = s->info[UMFPACK_RCOND];
  /* The singular-matrix warning is positive: UMFPACK still returns a factor,
   * but its solutions contain Inf/NaN, so it is a failure for us. */
  if (st != UMFPACK_OK && st != UMFPACK_WARNING_determinant_underflow && st != UMFPACK_WARNING_determinant_overflow) {
    if (s->num) umfpack_dl_free_numeric(&s->num);
    s->num = NULL;
    stats->singular = st == UMFPACK_WARNING_singular_matrix;
    return umf_fail(st, "numeric factorisation", A->n_rows, d);
  }
  /* Crude estimate min|U_ii| / max|U_ii| of the scaled matrix: below the
   * machine epsilon the solution has no correct digit. */
  if (!(s->info[UMFPACK_RCOND] >= DBL_EPSILON)) {
    umfpack_dl_free_numeric(&s->num);
    s->num = NULL;
    stats->singular = 1;
    return sl_diag_set(d, SL_EFAILED,
                       "umfpack: matrix is numerically singular (pivot ratio %.3g) in the numeric factorisation of a "
                       "%d x %d matrix",
                       s->info[UMFPACK_RCOND], (int)A->n_rows, (int)A->n_rows);
  }
  return 0;
}

static int umf_solve(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  umf_state *s = backend;
  /* CSR of A = CSC of A^T: UMFPACK factored A^T, so solve with its transpose. */
  int st = (int)umfpack_dl_solve(UMFPACK_At, s->ptr, s->idx, A->values, x, b, s->num, s->control, s->info);
  if (st != UMFPACK_OK) return umf_fail(st, "solve", A->n_rows, d);
  return 0;
}

/* A preconditioner application: the factorisation's own solve, without
 * UMFPACK's iterative refinement (default up to 2 steps, each a product
 * with A and a solve), which FGMRES does better. */
static int umf_precond(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  umf_state *s = backend;
  double irstep = s->control[UMFPACK_IRSTEP];
  s->control[UMFPACK_IRSTEP] = 0;
  int rc = umf_solve(backend, A, b, x, d);
  s->control[UMFPACK_IRSTEP] = irstep;
  return rc;
}

static void umf_destroy(void *backend) {
  umf_state *s = backend;
  if (!s) return;
  umf_drop(s);
  free(s);
}

const sl_linsolve_ops sl_linsolve_umfpack_ops = {
    .name = "umfpack",
    .description = UMFPACK_VERSION ": multifrontal LU, general square matrices",
    .create = umf_create,
    .symbolic = umf_symbolic,
    .numeric = umf_numeric,
    .solve = umf_solve,
    .destroy = umf_destroy,
    .precond = umf_precond,
};
