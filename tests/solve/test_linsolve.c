/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The three SuiteSparse backends: manufactured solutions of 1-D and 2-D
 * Poisson matrices, factorisation counting, refactorisation, and failures
 * (singular, not positive definite, not symmetric, unknown names). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/solve/linsolve.h"
#include "core/solve/sparse.h"
#include "poisson.h"
#include "testing.h"

static const char *const backends[] = {"umfpack", "klu", "cholmod"};

/* max |x - y| / max |y| */
static double rel_err(const double *x, const double *y, int32_t n) {
  double e = 0, m = 0;
  for (int32_t i = 0; i < n; ++i) {
    if (fabs(x[i] - y[i]) > e) e = fabs(x[i] - y[i]);
    if (fabs(y[i]) > m) m = fabs(y[i]);
  }
  return e / m;
}

/* Pick x, form b = A x, solve, compare; and, with ordering given, the
 * fill-reducing ordering the backend reports. */
static void manufactured(const char *name, int nx, int ny, const char *ordering) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  CHECK(poisson_build(&A, nx, ny, 0.0, &d) == 0);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = sin(0.37 * i) + 0.01 * i + 1.0;
  sl_csr_matvec(&A, xe, b);
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, name, &d) == 0);
  int rc = sl_linsolve_solve(ls, &A, b, x, &d);
  CHECK_MSG(rc == 0, "%s %dx%d: %s", name, nx, ny, d.msg);
  double e = rel_err(x, xe, n);
  CHECK_MSG(e <= 1e-12, "%s %dx%d: relative error %.3g", name, nx, ny, e);
  const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
  CHECK(st->rcond > 0 && st->rcond <= 1);
  if (ordering)
    CHECK_MSG(st->ordering && strcmp(st->ordering, ordering) == 0, "%s %dx%d: ordering %s, expected %s", name, nx, ny,
              st->ordering ? st->ordering : "(none)", ordering);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(xe), free(b), free(x);
}

/* 1 symbolic + 1 numeric for 10 solves of an unchanged matrix; changed values
 * give one more numeric and no symbolic; a new pattern a new symbolic. */
static void counting(const char *name) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  CHECK(poisson_build(&A, 20, 20, 0.0, &d) == 0);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = cos(0.1 * i);
  sl_csr_matvec(&A, xe, b);
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, name, &d) == 0);
  CHECK(strcmp(sl_linsolve_name(ls), name) == 0);
  for (int k = 0; k < 10; ++k) CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0);
  const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
  CHECK_MSG(st->n_symbolic == 1 && st->n_numeric == 1 && st->n_solves == 10,
            "%s: %ld symbolic, %ld numeric, %ld solves", name, st->n_symbolic, st->n_numeric, st->n_solves);
  CHECK(st->t_symbolic >= 0 && st->t_numeric > 0 && st->t_solve > 0);

  /* New values (a reaction term on the diagonal), same pattern. */
  for (int32_t i = 0; i < n; ++i) A.values[sl_csr_find(&A, i, i)] += 0.5 + 0.001 * i;
  sl_csr_touch(&A);
  sl_csr_matvec(&A, xe, b);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0);
  CHECK(rel_err(x, xe, n) <= 1e-12);
  CHECK(st->n_symbolic == 1 && st->n_numeric == 2 && st->n_solves == 11);
  if (strcmp(name, "klu") == 0) CHECK(st->n_refactor == 1 && st->n_refactor_redo == 0);

  /* In place (x == b). */
  memcpy(x, b, (size_t)n * sizeof *x);
  CHECK(sl_linsolve_solve(ls, &A, x, x, &d) == 0);
  CHECK(rel_err(x, xe, n) <= 1e-12);
  CHECK(st->n_numeric == 2);

  /* Re-assembled with the same values (a constant operator): no refactorisation. */
  for (int32_t p = 0; p < A.nnz; ++p) A.values[p] = A.values[p] * 1.0;
  sl_csr_touch(&A);
  CHECK(sl_linsolve_factor(ls, &A, &d) == 0);
  CHECK(st->n_numeric == 2 && st->n_numeric_skipped == 1);
  /* One changed entry is noticed. */
  A.values[0] *= 1.0 + 1e-15;
  sl_csr_touch(&A);
  CHECK(sl_linsolve_factor(ls, &A, &d) == 0);
  CHECK(st->n_numeric == 3);
  A.values[0] /= 1.0 + 1e-15;
  sl_csr_touch(&A);

  /* The caller may force a numeric factorisation. */
  sl_linsolve_values_changed(ls);
  CHECK(sl_linsolve_factor(ls, &A, &d) == 0);
  CHECK(st->n_symbolic == 1 && st->n_numeric == 4);
  CHECK(sl_linsolve_factor(ls, &A, &d) == 0);
  CHECK(st->n_numeric == 4);

  /* A rebuilt pattern (same shape) needs a new symbolic analysis. */
  sl_csr_free(&A);
  CHECK(poisson_build(&A, 20, 20, 0.0, &d) == 0);
  sl_csr_matvec(&A, xe, b);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0);
  CHECK(rel_err(x, xe, n) <= 1e-12);
  CHECK(st->n_symbolic == 2 && st->n_numeric == 5);

  char line[256];
  sl_linsolve_summary(ls, line, sizeof line);
  CHECK_CONTAINS(line, name);
  CHECK_CONTAINS(line, "2 symbolic");
  CHECK_CONTAINS(line, "13 solves");
  printf("%s\n", line);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(xe), free(b), free(x);
}

/* KLU refactorisation reuses pivots; when the new values make an old pivot
 * zero, the backend factorises afresh instead of failing. */
static void klu_refactor_fallback(void) {
  sl_diag d = {{0}};
  const int32_t el[] = {0, 1};
  sl_csr A = {0};
  CHECK(sl_csr_build_uniform(&A, 2, 1, 2, el, &d) == 0);
  /* [[4, 1], [1, 1]]: pivots on the diagonal */
  A.values[0] = 4, A.values[1] = 1, A.values[2] = 1, A.values[3] = 1;
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0);
  double b[2] = {5, 2}, x[2];
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0);
  CHECK_CLOSE(x[0], 1.0, 1e-14);
  CHECK_CLOSE(x[1], 1.0, 1e-14);
  /* [[0, 1], [1, 1]]: regular, but the old first pivot is now zero */
  A.values[0] = 0;
  sl_csr_touch(&A);
  double b2[2] = {1, 2};
  int rc = sl_linsolve_solve(ls, &A, b2, x, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  CHECK_CLOSE(x[0], 1.0, 1e-14);
  CHECK_CLOSE(x[1], 1.0, 1e-14);
  const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
  CHECK(st->n_refactor == 1 && st->n_refactor_redo == 1 && st->n_numeric == 2);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
}

/* KLU in the preconditioner role solves with its factors in single precision (core/solve/ls_klu.c): the
 * solution within a small multiple of 2^-24 times the condition number of the exact one. A nonsymmetric 7 x 7
 * matrix of three diagonal blocks coupled one way (KLU's block triangular form, with off-diagonal entries), rows
 * scaled by 1e3 and 1e-2 (KLU's row scaling) and a small leading diagonal (pivoting); then the 2-D Poisson
 * matrix on 40 x 40, condition number (4 / pi^2) 41^2 = 681 (its extreme eigenvalues 8 sin^2(pi / 82) and
 * 8 cos^2(pi / 82)). */
static void klu_single(void) {
  sl_diag d = {{0}};
  enum { N = 7 };
  const double a[N][N] = {{1e-3, 2, 0, 0, 1, 0, 0},  {3, 1, 1, 0, 0, 0.5, 0},  {1e3, 0, 4e3, 0, 0, 0, 2e3},
                          {0, 0, 0, 2, 1, 0, 1},       {0, 0, 0, -1, 3, 0, 0},  {0, 0, 0, 0, 0, 0.05, -0.02},
                          {0, 0, 0, 0, 0, 0.01, 0.03}};
  int32_t rptr[N + 1], rows[N], cptr[N + 1], cols[N * N], k = 0;
  rptr[0] = cptr[0] = 0;
  for (int i = 0; i < N; ++i) {
    rows[i] = i, rptr[i + 1] = i + 1;
    for (int j = 0; j < N; ++j)
      if (a[i][j] != 0.0) cols[k++] = j;
    cptr[i + 1] = k;
  }
  sl_csr A = {0};
  CHECK(sl_csr_build(&A, N, N, N, rptr, rows, cptr, cols, &d) == 0);
  for (int32_t i = 0; i < N; ++i)
    for (int32_t p = A.row_ptr[i]; p < A.row_ptr[i + 1]; ++p) A.values[p] = a[i][A.col_idx[p]];
  double xe[N], b[N], x[N], y[N];
  for (int i = 0; i < N; ++i) xe[i] = 1.0 + 0.3 * i - 0.05 * i * i;
  sl_csr_matvec(&A, xe, b);
  sl_linsolve *ls = NULL, *lsd = NULL;
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0 && sl_linsolve_create(&lsd, "klu", &d) == 0);
  CHECK(sl_linsolve_set_role(ls, SL_LINSOLVE_ROLE_PRECONDITIONER, &d) == 0);
  CHECK_MSG(sl_linsolve_solve(ls, &A, b, x, &d) == 0, "%s", d.msg);
  CHECK_MSG(sl_linsolve_solve(lsd, &A, b, y, &d) == 0, "%s", d.msg);
  double es = rel_err(x, xe, N), ed = rel_err(y, xe, N);
  printf("  klu single precision: 7 x 7 block triangular, relative error %.2e (double %.2e)\n", es, ed);
  CHECK_MSG(es <= 1e-5 && es > 0.0, "single precision error %.3g", es); /* 2^-24 = 6e-8 times a condition near 1e2 */
  CHECK_MSG(ed <= 1e-13, "double precision error %.3g", ed);
  sl_linsolve_destroy(ls), sl_linsolve_destroy(lsd);
  sl_csr_free(&A);
  CHECK(poisson_build(&A, 40, 40, 0.0, &d) == 0);
  int32_t n = A.n_rows;
  double *pe = malloc((size_t)n * sizeof *pe), *pb = malloc((size_t)n * sizeof *pb), *px = malloc((size_t)n * sizeof *px);
  for (int32_t i = 0; i < n; ++i) pe[i] = sin(0.37 * i) + 0.01 * i + 1.0;
  sl_csr_matvec(&A, pe, pb);
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0);
  CHECK(sl_linsolve_set_role(ls, SL_LINSOLVE_ROLE_PRECONDITIONER, &d) == 0);
  CHECK_MSG(sl_linsolve_solve(ls, &A, pb, px, &d) == 0, "%s", d.msg);
  es = rel_err(px, pe, n);
  printf("  klu single precision: 2-D Poisson 40 x 40, relative error %.2e (2^-24 x 681 = %.2e)\n", es,
         681.0 * ldexp(1.0, -24));
  CHECK_MSG(es <= 10.0 * 681.0 * ldexp(1.0, -24), "single precision error %.3g", es);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(pe), free(pb), free(px);
}

static void singular(const char *name) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  /* Rows 1 and 2 equal: exactly singular, symmetric positive semi-definite. */
  const int32_t el[] = {0, 1, 2};
  CHECK(sl_csr_build_uniform(&A, 3, 1, 3, el, &d) == 0);
  const double v[9] = {2, 1, 1, 1, 1, 1, 1, 1, 1};
  CHECK(sl_csr_add_element(&A, 3, el, 3, el, v, &d) == 0);
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, name, &d) == 0);
  double b[3] = {1, 2, 3}, x[3];
  d.msg[0] = 0;
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, name);
  if (strcmp(name, "cholmod") == 0) CHECK_CONTAINS(d.msg, "not positive definite");
  else CHECK_CONTAINS(d.msg, "singular");
  printf("%s, singular: %s\n", name, d.msg);
  /* A failure leaves no factorisation behind: the next call tries again. */
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK(sl_linsolve_get_stats(ls)->n_numeric == 0 && sl_linsolve_get_stats(ls)->n_solves == 0);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);

  /* The pure Neumann Laplacian (rows sum to zero) is singular as well. */
  CHECK(poisson_build(&A, 30, 1, 0.0, &d) == 0);
  A.values[sl_csr_find(&A, 0, 0)] = 1.0;
  A.values[sl_csr_find(&A, 29, 29)] = 1.0;
  sl_csr_touch(&A);
  double *bb = calloc(30, sizeof *bb), *xx = calloc(30, sizeof *xx);
  CHECK(sl_linsolve_create(&ls, name, &d) == 0);
  CHECK(sl_linsolve_solve(ls, &A, bb, xx, &d) == SL_EFAILED);
  printf("%s, Neumann Laplacian: %s\n", name, d.msg);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(bb), free(xx);
}

/* A backend whose every numeric factorisation fails: as a singular matrix (pivot ratio 1e-19) or, with
 * fake_singular = 0, as something else (out of memory). */
static int fake_singular = 1;
static int fake_create(void **backend, sl_diag *d) {
  (void)d;
  *backend = malloc(1);
  return *backend ? 0 : SL_ENOMEM;
}
static int fake_symbolic(void *backend, const sl_csr *A, sl_diag *d) {
  (void)backend, (void)A, (void)d;
  return 0;
}
static int fake_numeric(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d) {
  (void)backend, (void)A;
  st->rcond = 1e-19;
  st->singular = fake_singular;
  return sl_diag_set(d, SL_EFAILED, fake_singular ? "fake: matrix is numerically singular" : "fake: out of memory");
}
static int fake_solve(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  (void)backend, (void)A, (void)b, (void)x;
  return sl_diag_set(d, SL_EFAILED, "fake: solve without a factorisation");
}
static void fake_destroy(void *backend) { free(backend); }
static const sl_linsolve_ops fake_ops = {.name = "fake",
                                         .create = fake_create,
                                         .symbolic = fake_symbolic,
                                         .numeric = fake_numeric,
                                         .solve = fake_solve,
                                         .destroy = fake_destroy};

/* sl_linsolve_set_fallback: a backend that finds the matrix singular hands it to KLU once, which solves it
 * (the manufactured solution to 1e-12) and stays; the summary starts with what happened. A failure that is
 * not a singular matrix is not handed over; a matrix KLU finds singular too fails with KLU's message, once. */
static void singular_fallback(void) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  CHECK(poisson_build(&A, 20, 20, 0.0, &d) == 0);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = sin(0.37 * i) + 1.0;
  sl_csr_matvec(&A, xe, b);
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create_ops(&ls, &fake_ops, &d) == 0);
  CHECK(sl_linsolve_set_fallback(ls, "klu", SL_ORDERING_AUTO, &d) == 0);
  CHECK(sl_linsolve_fallback_note(ls)[0] == '\0');
  int rc = sl_linsolve_solve(ls, &A, b, x, &d);
  CHECK_MSG(rc == 0, "fallback: %s", d.msg);
  CHECK_MSG(rel_err(x, xe, n) <= 1e-12, "fallback: relative error %.3g", rel_err(x, xe, n));
  CHECK(strcmp(sl_linsolve_name(ls), "klu") == 0);
  CHECK(sl_linsolve_get_stats(ls)->n_numeric == 1 && sl_linsolve_get_stats(ls)->n_solves == 1);
  CHECK_CONTAINS(sl_linsolve_fallback_note(ls),
                 "fake found the matrix numerically singular (pivot ratio 1e-19): klu took over");
  char sum[512];
  sl_linsolve_summary(ls, sum, sizeof sum);
  printf("fallback: %s\n", sum);
  CHECK(strncmp(sum, "fake found the matrix numerically singular", 42) == 0);
  CHECK_CONTAINS(sum, "; klu (amd ordering): ");
  /* new values: KLU factorises them (it stays) */
  for (int32_t k = 0; k < A.nnz; ++k) A.values[k] *= 2.0;
  sl_csr_touch(&A);
  for (int32_t i = 0; i < n; ++i) b[i] *= 2.0;
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0 && rel_err(x, xe, n) <= 1e-12);
  CHECK(strcmp(sl_linsolve_name(ls), "klu") == 0 && sl_linsolve_get_stats(ls)->n_numeric == 2);
  sl_linsolve_destroy(ls);

  fake_singular = 0; /* not a singular matrix: no fallback */
  CHECK(sl_linsolve_create_ops(&ls, &fake_ops, &d) == 0);
  CHECK(sl_linsolve_set_fallback(ls, "klu", SL_ORDERING_AUTO, &d) == 0);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "fake: out of memory");
  CHECK(strcmp(sl_linsolve_name(ls), "fake") == 0 && sl_linsolve_fallback_note(ls)[0] == '\0');
  sl_linsolve_destroy(ls);
  fake_singular = 1;
  CHECK(sl_linsolve_create(&ls, "umfpack", &d) == 0);
  CHECK(sl_linsolve_set_fallback(ls, "pardiso", SL_ORDERING_AUTO, &d) == SL_EBADINPUT);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);

  /* exactly singular (rows 1 and 2 equal): UMFPACK says so, KLU takes over and says so too */
  const int32_t el[] = {0, 1, 2};
  CHECK(sl_csr_build_uniform(&A, 3, 1, 3, el, &d) == 0);
  const double v[9] = {2, 1, 1, 1, 1, 1, 1, 1, 1};
  CHECK(sl_csr_add_element(&A, 3, el, 3, el, v, &d) == 0);
  CHECK(sl_linsolve_create(&ls, "umfpack", &d) == 0);
  CHECK(sl_linsolve_set_fallback(ls, "klu", SL_ORDERING_AUTO, &d) == 0);
  double b3[3] = {1, 2, 3}, x3[3];
  CHECK(sl_linsolve_solve(ls, &A, b3, x3, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "klu");
  CHECK_CONTAINS(sl_linsolve_fallback_note(ls), "umfpack found the matrix numerically singular");
  CHECK(sl_linsolve_solve(ls, &A, b3, x3, &d) == SL_EFAILED);
  CHECK(strcmp(sl_linsolve_name(ls), "klu") == 0);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(xe), free(b), free(x);
}

static void cholmod_rejects(void) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  sl_linsolve *ls = NULL;
  /* Symmetric indefinite: the 2-D Laplacian shifted by 3 (eigenvalues from
   * about -3 to 5). */
  CHECK(poisson_build(&A, 10, 10, 3.0, &d) == 0);
  int32_t n = A.n_rows;
  double *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) b[i] = 1.0;
  CHECK(sl_linsolve_create(&ls, "cholmod", &d) == 0);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "not positive definite");
  printf("cholmod, indefinite: %s\n", d.msg);
  /* The same matrix is fine for the LU backends. */
  for (int k = 0; k < 2; ++k) {
    sl_linsolve *lu = NULL;
    CHECK(sl_linsolve_create(&lu, backends[k], &d) == 0);
    CHECK_MSG(sl_linsolve_solve(lu, &A, b, x, &d) == 0, "%s: %s", backends[k], d.msg);
    sl_linsolve_destroy(lu);
  }
  /* Nonsymmetric: cholmod would read one triangle only, so it refuses. */
  A.values[sl_csr_find(&A, 0, 0)] = 10.0, A.values[sl_csr_find(&A, 0, 1)] = -2.0;
  sl_csr_touch(&A);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "not symmetric");
  CHECK_CONTAINS(d.msg, "A(0,1)");
  /* NaN entries are caught before any backend sees them. */
  A.values[sl_csr_find(&A, 5, 5)] = NAN;
  sl_csr_touch(&A);
  CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "(5, 5) is not finite");
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(b), free(x);
}

static void names(void) {
  sl_diag d = {{0}};
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, "umfpak", &d) == SL_EBADINPUT);
  CHECK(ls == NULL);
  CHECK_CONTAINS(d.msg, "unknown linear solver 'umfpak'");
  CHECK_CONTAINS(d.msg, "did you mean 'umfpack'");
  CHECK(sl_linsolve_create(&ls, "cholmd", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'cholmod'");
  CHECK(sl_linsolve_create(&ls, "pardiso", &d) == SL_EBADINPUT);
  CHECK(strstr(d.msg, "did you mean") == NULL);
  CHECK_CONTAINS(d.msg, "umfpack, klu, cholmod, petsc");
#ifdef SLUICE_WITH_PETSC
  CHECK(sl_linsolve_create(&ls, "petsc", &d) == 0);
  sl_linsolve_destroy(ls);
  ls = NULL;
#else
  CHECK(sl_linsolve_create(&ls, "petsc", &d) == SL_EBADINPUT);
  CHECK(ls == NULL);
  CHECK_CONTAINS(d.msg, "built without PETSc");
#endif
  CHECK(sl_linsolve_create(&ls, NULL, &d) == 0);
  CHECK(strcmp(sl_linsolve_name(ls), "umfpack") == 0);
  CHECK_CONTAINS(sl_linsolve_description(ls), "UMFPACK V5");
  sl_linsolve_destroy(ls);
  int n = 0;
  const char *const *all = sl_linsolve_names(&n);
#ifdef SLUICE_WITH_PETSC
  CHECK(n == 4 && strcmp(all[3], "petsc") == 0);
#else
  CHECK(n == 3 && strcmp(all[1], "klu") == 0);
#endif
  sl_linsolve_destroy(NULL);

  /* Shape errors are bad input. */
  sl_csr R = {0};
  const int32_t rptr[] = {0, 1}, r[] = {0}, cptr[] = {0, 2}, c[] = {0, 1};
  CHECK(sl_csr_build(&R, 1, 2, 1, rptr, r, cptr, c, &d) == 0);
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0);
  double b[2] = {1, 1}, x[2];
  CHECK(sl_linsolve_solve(ls, &R, b, x, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "not square");
  sl_linsolve_destroy(ls);
  sl_csr_free(&R);
}

int main(void) {
  for (int k = 0; k < 3; ++k) {
    manufactured(backends[k], 200, 1, NULL);
    manufactured(backends[k], 40, 40, NULL);
    manufactured(backends[k], 7, 3, NULL);
    counting(backends[k]);
    singular(backends[k]);
  }
  /* KLU orders by AMD below 30 000 unknowns, by METIS nested dissection from there (core/solve/ls_klu.c) */
  manufactured("klu", 170, 170, "amd");   /* 28 900 unknowns */
  manufactured("klu", 180, 180, "metis"); /* 32 400 */
  klu_refactor_fallback();
  klu_single();
  singular_fallback();
  cholmod_rejects();
  names();
  return sl_test_summary();
}
