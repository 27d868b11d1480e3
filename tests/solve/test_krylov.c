/* SPDX-License-Identifier: GPL-2.0-or-later */
/* FGMRES (core/solve/krylov.h) on systems with known answers, and the
 * factorisation reuse of the linear solvers built on it:
 *  - a diagonal matrix with k distinct eigenvalues: the exact solution in k
 *    iterations (the minimal polynomial has degree k);
 *  - a nonsymmetric convection-diffusion matrix, unpreconditioned: the
 *    manufactured solution to the tolerance, with and without restarts;
 *  - the exact LU as preconditioner: one iteration; a stale LU (the matrix
 *    of 5 % smaller diagonal shift): a few; a bad one (the LU of another
 *    matrix) stops early, before its budget, as stagnated;
 *  - sl_linsolve_solve_rtol for each backend: a changed matrix is answered
 *    with the old factorisation to the tolerance, a far one refactorised
 *    with its reason; counts and reasons add up;
 *  - Newton on a nonlinear problem: the same iterations and the same
 *    solution (to 1e-12) with reuse as with a factorisation per iteration;
 *  - the default solver by size and BLAS. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/solve/krylov.h"
#include "core/solve/linsolve.h"
#include "core/solve/newton.h"
#include "core/util/blas.h"
#include "poisson.h"
#include "testing.h"

static double norm2(const double *x, int32_t n) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s += x[i] * x[i];
  return sqrt(s);
}

static double max_diff(const double *x, const double *y, int32_t n) {
  double e = 0.0;
  for (int32_t i = 0; i < n; ++i) e = fmax(e, fabs(x[i] - y[i]));
  return e;
}

static int apply_csr(void *user, const double *x, double *y, sl_diag *d) {
  (void)d;
  sl_csr_matvec(user, x, y);
  return 0;
}

/* ---- diagonal with three distinct eigenvalues --------------------------------- */

typedef struct diag_op {
  int32_t n;
  const double *a;
} diag_op;

static int apply_diag(void *user, const double *x, double *y, sl_diag *d) {
  (void)d;
  const diag_op *o = user;
  for (int32_t i = 0; i < o->n; ++i) y[i] = o->a[i] * x[i];
  return 0;
}

static void distinct_eigenvalues(void) {
  enum { N = 60 };
  double a[N], b[N], x[N];
  for (int i = 0; i < N; ++i) a[i] = 1.0 + (i % 3), b[i] = 1.0 + sin(0.7 * i), x[i] = 0.0;
  diag_op op = {N, a};
  sl_krylov k;
  sl_diag d = {{0}};
  CHECK(sl_krylov_init(&k, N, 10, &d) == 0);
  sl_krylov_opts o = {.rtol = 1e-13, .restart = 10, .max_iterations = 10};
  sl_krylov_result r;
  CHECK(sl_fgmres(&k, apply_diag, &op, NULL, NULL, b, x, &o, &r, &d) == 0);
  double e = 0.0;
  for (int i = 0; i < N; ++i) e = fmax(e, fabs(x[i] - b[i] / a[i]));
  printf("diagonal, 3 distinct eigenvalues: %d iterations, residual %.2e, error %.2e\n", r.iterations,
         r.residual / norm2(b, N), e);
  CHECK_MSG(r.status == SL_KRYLOV_CONVERGED && r.iterations == 3, "status %d after %d iterations", r.status,
            r.iterations);
  CHECK(e < 1e-12);
  /* b = 0: x = 0 without an iteration */
  memset(b, 0, sizeof b);
  for (int i = 0; i < N; ++i) x[i] = 0.0;
  CHECK(sl_fgmres(&k, apply_diag, &op, NULL, NULL, b, x, &o, &r, &d) == 0);
  CHECK(r.status == SL_KRYLOV_CONVERGED && r.iterations == 0 && max_diff(x, b, N) == 0.0);
  sl_krylov_free(&k);
}

/* ---- convection-diffusion ------------------------------------------------------ */

/* The 5-point Laplacian on an m x m grid plus a first-order upwind
 * convection c (d/dx + d/dy): nonsymmetric, positive real part. */
static int convdiff(sl_csr *A, int m, double c, sl_diag *d) {
  int rc = poisson_build(A, m, m, 0.0, d);
  for (int32_t r = 0; !rc && r < A->n_rows; ++r) {
    int i = r % m, j = r / m;
    A->values[sl_csr_find(A, r, r)] += 2.0 * c;
    if (i > 0) A->values[sl_csr_find(A, r, r - 1)] -= c;
    if (j > 0) A->values[sl_csr_find(A, r, r - m)] -= c;
  }
  if (!rc) sl_csr_touch(A);
  return rc;
}

static void unpreconditioned(void) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  CHECK(convdiff(&A, 16, 0.8, &d) == 0);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = calloc((size_t)n, sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = cos(0.2 * i) + 0.5;
  sl_csr_matvec(&A, xe, b);
  const int restarts[2] = {200, 20};
  int its[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    sl_krylov kr;
    CHECK(sl_krylov_init(&kr, n, restarts[k], &d) == 0);
    sl_krylov_opts o = {.rtol = 1e-10, .restart = restarts[k], .max_iterations = 2000};
    sl_krylov_result r;
    memset(x, 0, (size_t)n * sizeof *x);
    CHECK(sl_fgmres(&kr, apply_csr, &A, NULL, NULL, b, x, &o, &r, &d) == 0);
    double e = max_diff(x, xe, n);
    printf("convection-diffusion %d unknowns, GMRES(%d): %d iterations, %d restarts, residual %.2e, error %.2e\n",
           (int)n, restarts[k], r.iterations, r.restarts, r.residual / norm2(b, n), e);
    CHECK(r.status == SL_KRYLOV_CONVERGED);
    CHECK(r.residual <= 1e-10 * norm2(b, n));
    CHECK(e < 1e-7);
    CHECK(k == 0 ? r.restarts == 0 : r.restarts > 0);
    its[k] = r.iterations;
    sl_krylov_free(&kr);
  }
  /* restarting loses the space: never fewer iterations than full GMRES, which minimises over all of it */
  CHECK(its[1] >= its[0]);
  sl_csr_free(&A);
  free(xe), free(b), free(x);
}

/* ---- the LU of a (nearby) matrix as preconditioner ------------------------------- */

typedef struct lu_prec {
  sl_linsolve *ls;
  const sl_csr *M; /* the matrix it factorised */
} lu_prec;

static int apply_lu(void *user, const double *x, double *y, sl_diag *d) {
  lu_prec *p = user;
  return sl_linsolve_solve(p->ls, p->M, x, y, d);
}

/* Iterations of FGMRES(20) on A x = b preconditioned with the LU of M. */
static sl_krylov_result with_lu(const sl_csr *A, const sl_csr *M, const double *b, double *x, int predict) {
  sl_diag d = {{0}};
  int32_t n = A->n_rows;
  sl_krylov kr;
  sl_krylov_result r = {0};
  lu_prec p = {NULL, M};
  CHECK(sl_krylov_init(&kr, n, 20, &d) == 0 && sl_linsolve_create(&p.ls, "klu", &d) == 0);
  sl_krylov_opts o = {.rtol = 1e-10, .restart = 20, .max_iterations = 20, .predict = predict};
  memset(x, 0, (size_t)n * sizeof *x);
  CHECK(sl_fgmres(&kr, apply_csr, (void *)A, apply_lu, &p, b, x, &o, &r, &d) == 0);
  sl_linsolve_destroy(p.ls);
  sl_krylov_free(&kr);
  return r;
}

static void preconditioned(void) {
  sl_diag d = {{0}};
  sl_csr A = {0}, stale = {0}, bad = {0};
  /* A: convection-diffusion with a reaction 0.4; stale: the reaction 5 % smaller; bad: an indefinite
     Helmholtz-like matrix (the Laplacian shifted by 3.5) */
  CHECK(convdiff(&A, 20, 0.5, &d) == 0 && convdiff(&stale, 20, 0.5, &d) == 0);
  CHECK(poisson_build(&bad, 20, 20, 3.5, &d) == 0);
  for (int32_t i = 0; i < A.n_rows; ++i) {
    A.values[sl_csr_find(&A, i, i)] += 0.4;
    stale.values[sl_csr_find(&stale, i, i)] += 0.38;
  }
  sl_csr_touch(&A), sl_csr_touch(&stale);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = sin(0.05 * i) + 0.1 * (i % 7);
  sl_csr_matvec(&A, xe, b);
  sl_krylov_result exact = with_lu(&A, &A, b, x, 1);
  printf("exact LU: %d iteration, residual %.2e\n", exact.iterations, exact.residual / norm2(b, n));
  CHECK(exact.status == SL_KRYLOV_CONVERGED && exact.iterations == 1 && max_diff(x, xe, n) < 1e-12);
  sl_krylov_result st = with_lu(&A, &stale, b, x, 1);
  printf("stale LU (5 %% of the reaction): %d iterations, rate %.2e, residual %.2e\n", st.iterations, st.rate,
         st.residual / norm2(b, n));
  CHECK(st.status == SL_KRYLOV_CONVERGED && st.iterations > 1 && st.iterations <= 8);
  CHECK(st.residual <= 1e-10 * norm2(b, n) && max_diff(x, xe, n) < 1e-8);
  sl_krylov_result bd = with_lu(&A, &bad, b, x, 1), bd_full = with_lu(&A, &bad, b, x, 0);
  printf("bad LU: stopped after %d iterations (rate %.3f), %d without the prediction\n", bd.iterations, bd.rate,
         bd_full.iterations);
  CHECK(bd.status == SL_KRYLOV_STAGNATED && bd.iterations < 20);
  CHECK(bd_full.status == SL_KRYLOV_MAX_ITERATIONS && bd_full.iterations == 20);
  sl_csr_free(&A), sl_csr_free(&stale), sl_csr_free(&bad);
  free(xe), free(b), free(x);
}

/* trust_estimate (the split step's velocity solve): the same iterations and bitwise the same x as with the last
 * product, the true residual b - A x within rtol |b|, and the returned estimate that residual's norm up to rounding
 * (equal in exact arithmetic: Saad 2003, Proposition 6.9, for FGMRES with its kept Z, section 9.4.1). */
static void trusted_estimate(void) {
  sl_diag d = {{0}};
  sl_csr A = {0}, stale = {0};
  CHECK(convdiff(&A, 20, 0.5, &d) == 0 && convdiff(&stale, 20, 0.5, &d) == 0);
  for (int32_t i = 0; i < A.n_rows; ++i) {
    A.values[sl_csr_find(&A, i, i)] += 0.4;
    stale.values[sl_csr_find(&stale, i, i)] += 0.38;
  }
  sl_csr_touch(&A), sl_csr_touch(&stale);
  int32_t n = A.n_rows;
  double *b = malloc((size_t)n * sizeof *b), *x[2], *r = malloc((size_t)n * sizeof *r);
  x[0] = malloc((size_t)n * sizeof *x[0]), x[1] = malloc((size_t)n * sizeof *x[1]);
  for (int32_t i = 0; i < n; ++i) b[i] = cos(0.07 * i) + 0.2 * (i % 5);
  sl_krylov_result res[2];
  for (int t = 0; t < 2; ++t) {
    sl_krylov kr;
    lu_prec p = {NULL, &stale};
    CHECK(sl_krylov_init(&kr, n, 20, &d) == 0 && sl_linsolve_create(&p.ls, "klu", &d) == 0);
    sl_krylov_opts o = {.rtol = 1e-6, .restart = 20, .max_iterations = 20, .predict = 1, .trust_estimate = t};
    memset(x[t], 0, (size_t)n * sizeof *x[t]);
    CHECK(sl_fgmres(&kr, apply_csr, &A, apply_lu, &p, b, x[t], &o, &res[t], &d) == 0);
    sl_linsolve_destroy(p.ls);
    sl_krylov_free(&kr);
  }
  sl_csr_matvec(&A, x[1], r);
  for (int32_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
  double rt = norm2(r, n), bn = norm2(b, n);
  printf("trusted estimate: %d and %d iterations, estimate %.6e, true residual %.6e (of |b| %.3e)\n",
         res[1].iterations, res[0].iterations, res[1].residual, rt, bn);
  CHECK(res[0].status == SL_KRYLOV_CONVERGED && res[1].status == SL_KRYLOV_CONVERGED);
  CHECK(res[0].iterations == res[1].iterations && max_diff(x[0], x[1], n) == 0.0);
  CHECK(rt <= 1e-6 * bn && res[0].residual == rt);
  CHECK(fabs(res[1].residual - rt) <= 1e-6 * rt);
  sl_csr_free(&A), sl_csr_free(&stale);
  free(b), free(r), free(x[0]), free(x[1]);
}

/* ---- reuse in the linear solvers --------------------------------------------------- */

static void reuse(const char *name) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  int spd = strcmp(name, "cholmod") == 0;
  CHECK(spd ? poisson_build(&A, 20, 20, 0.0, &d) == 0 : convdiff(&A, 20, 0.5, &d) == 0);
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  double *r = malloc((size_t)n * sizeof *r);
  for (int32_t i = 0; i < n; ++i) xe[i] = cos(0.13 * i) + 1.0;
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, name, &d) == 0);
  const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
  const double rtol = 1e-10;
  const sl_linsolve_reuse pol0 = sl_linsolve_get_reuse(ls);
  sl_csr_matvec(&A, xe, b);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0);
  CHECK(st->n_numeric == 1 && st->refactor_reason[SL_REFACTOR_FIRST] == 1 && st->n_reused == 0);

  /* the diagonal 0.25 % larger: the old factorisation answers, to the tolerance */
  for (int32_t i = 0; i < n; ++i) A.values[sl_csr_find(&A, i, i)] *= 1.0025;
  sl_csr_touch(&A);
  sl_csr_matvec(&A, xe, b);
  memcpy(x, b, (size_t)n * sizeof *x); /* in place */
  CHECK(sl_linsolve_solve_rtol(ls, &A, x, x, rtol, &d) == 0);
  sl_csr_matvec(&A, x, r);
  for (int32_t i = 0; i < n; ++i) r[i] -= b[i];
  printf("%s: the diagonal 0.25 %% larger: reused with %ld FGMRES iterations, residual %.2e\n", name,
         st->n_krylov_iterations, norm2(r, n) / norm2(b, n));
  CHECK(st->n_numeric == 1 && st->n_reused == 1 && st->n_krylov_iterations >= 2 &&
        st->n_krylov_iterations <= pol0.slow_iterations);
  CHECK(norm2(r, n) <= rtol * norm2(b, n));
  /* the same matrix again: still reused (its own factorisation is older) */
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0 && st->n_reused == 2 && st->n_numeric == 1);
  /* an exact solve refactorises ("direct"), after which the factorisation is current: a direct solve */
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, 0.0, &d) == 0);
  CHECK(st->n_numeric == 2 && st->refactor_reason[SL_REFACTOR_DIRECT] == 1);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0 && st->n_numeric == 2 && st->n_reused == 2);
  CHECK(max_diff(x, xe, n) < 1e-12 * 2.0);

  /* far away (the diagonal doubled): FGMRES gives up, the matrix is refactorised and solved exactly */
  for (int32_t i = 0; i < n; ++i) A.values[sl_csr_find(&A, i, i)] *= spd ? 30.0 : 2.0;
  sl_csr_touch(&A);
  sl_csr_matvec(&A, xe, b);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, 1e-14, &d) == 0);
  long gave_up = st->refactor_reason[SL_REFACTOR_ITERATIONS] + st->refactor_reason[SL_REFACTOR_STAGNATION];
  printf("%s: far: %ld FGMRES iterations in all, %ld failed; reasons: stagnation %ld, iterations %ld\n", name,
         st->n_krylov_iterations, st->n_krylov_failed, st->refactor_reason[SL_REFACTOR_STAGNATION],
         st->refactor_reason[SL_REFACTOR_ITERATIONS]);
  CHECK(st->n_numeric == 3 && st->n_krylov_failed == 1 && gave_up == 1);
  CHECK(max_diff(x, xe, n) < 1e-12 * 2.0);

  /* a reuse slower than slow_iterations refactorises at the next solve */
  sl_linsolve_reuse pol = sl_linsolve_get_reuse(ls);
  CHECK(pol.enabled && pol.max_iterations == 20 && pol.slow_iterations == 7);
  pol.slow_iterations = 1;
  sl_linsolve_set_reuse(ls, &pol);
  for (int k = 0; k < 2; ++k) {
    for (int32_t i = 0; i < n; ++i) A.values[sl_csr_find(&A, i, i)] *= 1.01;
    sl_csr_touch(&A);
    sl_csr_matvec(&A, xe, b);
    CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0);
  }
  CHECK(st->n_reused == 3 && st->n_numeric == 4 && st->refactor_reason[SL_REFACTOR_SLOW] == 1);

  /* reuse off: every new matrix is factorised */
  CHECK(sl_linsolve_set_reuse_name(ls, "never", &d) == 0 && !sl_linsolve_get_reuse(ls).enabled);
  A.values[0] *= 1.001;
  sl_csr_touch(&A);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0 && st->n_numeric == 5 && st->n_reused == 3);
  CHECK(sl_linsolve_set_reuse_name(ls, "nevr", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'never'");
  CHECK(sl_linsolve_set_reuse_name(ls, "auto", &d) == 0 && sl_linsolve_get_reuse(ls).slow_iterations == 7);

  /* forced and a new pattern */
  sl_linsolve_values_changed(ls);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0 && st->refactor_reason[SL_REFACTOR_FORCED] == 1);
  sl_csr_free(&A);
  CHECK(spd ? poisson_build(&A, 20, 20, 0.0, &d) == 0 : convdiff(&A, 20, 0.5, &d) == 0);
  CHECK(sl_linsolve_solve_rtol(ls, &A, b, x, rtol, &d) == 0 && st->refactor_reason[SL_REFACTOR_PATTERN] == 1);
  long sum = 0;
  for (int k = 0; k < SL_REFACTOR_N; ++k) sum += st->refactor_reason[k];
  CHECK_MSG(sum == st->n_numeric, "reasons add up to %ld, %ld numeric factorisations", sum, st->n_numeric);
  char line[256];
  sl_linsolve_summary(ls, line, sizeof line);
  printf("%s\n", line);
  CHECK_CONTAINS(line, "3 reused");
  CHECK(strcmp(sl_refactor_reason_name(SL_REFACTOR_STAGNATION), "stagnation") == 0);
  sl_linsolve_destroy(ls);
  sl_csr_free(&A);
  free(xe), free(b), free(x), free(r);
}

/* ---- Newton with reuse --------------------------------------------------------------- */

/* R(u) = K u + u^3 / 2 - f: a Laplacian with a cubic reaction. */
typedef struct cubic {
  const sl_csr *K;
  const double *f;
} cubic;

static int cubic_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d) {
  (void)d;
  const cubic *p = user;
  int32_t n = p->K->n_rows;
  sl_csr_matvec(p->K, u, b);
  for (int32_t i = 0; i < n; ++i) b[i] = p->f[i] - b[i] - 0.5 * u[i] * u[i] * u[i];
  if (mode == SL_NL_RESIDUAL) return 0;
  memcpy(A->values, p->K->values, (size_t)A->nnz * sizeof *A->values);
  for (int32_t i = 0; i < n; ++i) A->values[sl_csr_find(A, i, i)] += (mode == SL_NL_NEWTON ? 1.5 : 0.5) * u[i] * u[i];
  sl_csr_touch(A);
  return 0;
}

static void newton_reuse(void) {
  sl_diag d = {{0}};
  sl_csr K = {0}, A = {0};
  CHECK(poisson_build(&K, 30, 30, 0.0, &d) == 0 && poisson_build(&A, 30, 30, 0.0, &d) == 0);
  int32_t n = K.n_rows;
  double *f = malloc((size_t)n * sizeof *f), *b = malloc((size_t)n * sizeof *b);
  double *u[2] = {calloc((size_t)n, sizeof(double)), calloc((size_t)n, sizeof(double))};
  for (int32_t i = 0; i < n; ++i) f[i] = 2.0 + sin(0.1 * i);
  cubic p = {&K, f};
  sl_newton_stats ns[2];
  const sl_linsolve_stats *ls_st[2];
  sl_linsolve *ls[2] = {NULL, NULL};
  for (int k = 0; k < 2; ++k) {
    CHECK(sl_linsolve_create(&ls[k], "klu", &d) == 0);
    if (k == 1) CHECK(sl_linsolve_set_reuse_name(ls[k], "never", &d) == 0);
    sl_newton_opts o = {.rtol = 1e-12};
    int rc = sl_newton_solve(&A, b, n, u[k], cubic_assemble, &p, ls[k], &o, &ns[k], &d);
    CHECK_MSG(rc == 0, "%s", d.msg);
    ls_st[k] = sl_linsolve_get_stats(ls[k]);
  }
  double scale = 0.0;
  for (int32_t i = 0; i < n; ++i) scale = fmax(scale, fabs(u[1][i]));
  printf(
      "Newton, cubic reaction: %d iterations with reuse (%ld factorisations, %ld reused, %ld FGMRES iterations), "
      "%d without (%ld factorisations); solutions within %.2e\n",
      ns[0].iterations, ls_st[0]->n_numeric, ls_st[0]->n_reused, ls_st[0]->n_krylov_iterations, ns[1].iterations,
      ls_st[1]->n_numeric, max_diff(u[0], u[1], n) / scale);
  CHECK(ns[0].iterations == ns[1].iterations && ns[0].iterations >= 4);
  CHECK(ls_st[1]->n_numeric == ns[1].iterations && ls_st[0]->n_numeric < ns[0].iterations);
  CHECK(ls_st[0]->n_reused + ls_st[0]->n_numeric == ns[0].iterations);
  CHECK(max_diff(u[0], u[1], n) <= 1e-12 * scale);
  for (int k = 0; k < 2; ++k) sl_linsolve_destroy(ls[k]), free(u[k]);
  sl_csr_free(&K), sl_csr_free(&A);
  free(f), free(b);
}

/* The default solver: KLU for the small systems, UMFPACK for the large unless the BLAS is the reference one. */
static void default_solver(void) {
  const char *blas = sl_blas_description();
  int reference = strncmp(blas, "reference", 9) == 0;
  printf("default solver: %s at 7 195 unknowns, %s at 149 000 (BLAS: %s)\n", sl_linsolve_default_name(7195),
         sl_linsolve_default_name(149000), blas);
  CHECK(strcmp(sl_linsolve_default_name(7195), "klu") == 0);
  CHECK(strcmp(sl_linsolve_default_name(SL_LINSOLVE_KLU_MAX_UNKNOWNS), reference ? "klu" : "umfpack") == 0);
  CHECK(strcmp(sl_linsolve_default_name(149000), reference ? "klu" : "umfpack") == 0);
}

int main(void) {
  default_solver();
  distinct_eigenvalues();
  unpreconditioned();
  preconditioned();
  trusted_estimate();
  reuse("umfpack");
  reuse("klu");
  reuse("cholmod");
  newton_reuse();
  return sl_test_summary();
}
