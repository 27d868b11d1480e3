/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Newton on linear problems, and the flow problem keeping its matrix:
 *  - a linear solve assembles once and reports the residual b - A du, which
 *    agrees with the residual assembled at the new iterate;
 *  - with matrix_current only the right-hand side is assembled, A keeps its
 *    values generation (no refactorisation) and the solution is bitwise
 *    that of a full assembly and a fresh factorisation;
 *  - a Stokes problem (sl_flow_problem) re-solved with new history and new
 *    constraint values assembles its matrix once and matches fresh solves
 *    bit for bit; a change of any matrix input (mass coefficient, viscosity,
 *    density, the set of constrained dofs, a write into the matrix, a
 *    viscosity callback, a problem not declared linear) assembles it again;
 *  - a time step's solve (opts.predicted) from a start 1e-3 off the solution
 *    of a cubic reaction-diffusion problem ends after one correction, one
 *    matrix and one residual-only assembly, within its tolerance of the
 *    solution (Newton's quadratic contraction); without `predicted` the same
 *    solve takes a second correction after a second full assembly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mesh/mesh.h"
#include "core/models/navier_stokes/flow_problem.h"
#include "core/solve/newton.h"
#include "poisson.h"
#include "testing.h"

/* ---- a linear algebraic problem R(u) = K u - f ------------------------- */

typedef struct lin_problem {
  const sl_csr *K;
  const double *f;
  double *Ku;
  int matrices, residuals; /* callback calls */
} lin_problem;

static int lin_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d) {
  lin_problem *p = user;
  (void)d;
  if (mode == SL_NL_RESIDUAL) ++p->residuals;
  else {
    ++p->matrices;
    memcpy(A->values, p->K->values, (size_t)A->nnz * sizeof *A->values);
    sl_csr_touch(A);
  }
  sl_csr_matvec(p->K, u, p->Ku);
  for (int32_t i = 0; i < p->K->n_rows; ++i) b[i] = p->f[i] - p->Ku[i];
  return 0;
}

static double norm2(const double *x, int32_t n) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s += x[i] * x[i];
  return sqrt(s);
}

static void linear_newton(void) {
  sl_diag d = {{0}};
  sl_csr K = {0}, A = {0};
  CHECK(poisson_build(&K, 12, 12, 0.0, &d) == 0 && poisson_build(&A, 12, 12, 0.0, &d) == 0);
  int32_t n = K.n_rows;
  double *f = malloc((size_t)n * sizeof *f), *b = malloc((size_t)n * sizeof *b), *Ku = malloc((size_t)n * sizeof *Ku);
  double *u = calloc((size_t)n, sizeof *u), *v = calloc((size_t)n, sizeof *v);
  for (int32_t i = 0; i < n; ++i) f[i] = 1.0 + sin(0.3 * i);
  lin_problem p = {&K, f, Ku, 0, 0};
  sl_linsolve *ls = NULL, *ls2 = NULL;
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0 && sl_linsolve_create(&ls2, "klu", &d) == 0);
  sl_newton_opts o = {.linear = 1};
  sl_newton_stats st;

  int rc = sl_newton_solve(&A, b, n, u, lin_assemble, &p, ls, &o, &st, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  CHECK(st.iterations == 1 && st.assemblies == 1 && st.residuals == 0 && p.matrices == 1 && p.residuals == 0);
  /* the reported residual is that of the new iterate */
  for (int32_t i = 0; i < n; ++i) b[i] = 0.0;
  lin_assemble(&p, u, SL_NL_RESIDUAL, &A, b, &d);
  double assembled = norm2(b, n);
  CHECK_MSG(fabs(st.residual - assembled) <= 1e-12 * norm2(f, n), "residual %.3g, assembled %.3g", st.residual,
            assembled);
  CHECK(st.residual <= 1e-12 * norm2(f, n));

  /* new data, the operator kept: the right-hand side only */
  for (int32_t i = 0; i < n; ++i) f[i] = cos(0.7 * i), u[i] = v[i] = 0.01 * i;
  uint64_t gen = A.values_gen;
  o.matrix_current = 1;
  p.matrices = p.residuals = 0;
  rc = sl_newton_solve(&A, b, n, u, lin_assemble, &p, ls, &o, &st, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  CHECK(st.iterations == 1 && st.assemblies == 0 && st.residuals == 1 && p.matrices == 0 && p.residuals == 1);
  CHECK(A.values_gen == gen);
  const sl_linsolve_stats *ss = sl_linsolve_get_stats(ls);
  CHECK(ss->n_numeric == 1 && ss->n_numeric_skipped == 0 && ss->n_solves == 2);
  /* the same step through a full assembly and a fresh factorisation */
  o.matrix_current = 0;
  rc = sl_newton_solve(&A, b, n, v, lin_assemble, &p, ls2, &o, &st, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  CHECK_MSG(memcmp(u, v, (size_t)n * sizeof *u) == 0, "a kept matrix changed the solution");

  sl_linsolve_destroy(ls), sl_linsolve_destroy(ls2);
  sl_csr_free(&K), sl_csr_free(&A);
  free(f), free(b), free(Ku), free(u), free(v);
}

/* ---- a Stokes step problem ----------------------------------------------- */

typedef struct stokes_case {
  double lid, mass_coef, viscosity, density;
  int extra_fixed; /* also fix the first interior velocity dof */
  int callback;    /* the viscosity through a callback */
} stokes_case;

static const sl_th_space *g_th;

/* Walls, a lid, a pressure datum: the constraints of c in bc. */
static int fix(sl_constraints *bc, const stokes_case *c, sl_diag *d) {
  int rc = 0;
  for (int k = 0; k < 2 && !rc; ++k)
    rc = sl_constraints_fix_boundary(bc, g_th->vel, "top", sl_th_vel_dof(g_th, k, 0), NULL, NULL, k ? 0.0 : c->lid, d);
  const char *walls[] = {"bottom", "left", "right"};
  for (int w = 0; w < 3 && !rc; ++w)
    for (int k = 0; k < 2 && !rc; ++k)
      rc = sl_constraints_fix_boundary(bc, g_th->vel, walls[w], sl_th_vel_dof(g_th, k, 0), NULL, NULL, 0.0, d);
  if (!rc) sl_stokes_fix_pressure_datum(bc, g_th);
  if (!rc && c->extra_fixed)
    for (int32_t i = 0; i < g_th->vel->n_nodes; ++i)
      if (!bc->fixed[i]) {
        sl_constraints_fix(bc, i, 0.0);
        break;
      }
  return rc;
}

/* mu = the case's viscosity, through a callback */
static int viscosity_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const stokes_case *c = user;
  (void)d;
  for (int q = 0; q < b->n; ++q) out[2 * q] = c->viscosity, out[2 * q + 1] = 0.0;
  return 0;
}

static void set_opts(sl_flow_opts *o, const stokes_case *c, const double *hist) {
  o->density = (sl_coef){NULL, NULL, c->density};
  o->viscosity = c->callback ? viscosity_fn : NULL;
  o->viscosity_user = (void *)c;
  o->viscosity_value = c->viscosity;
  o->mass_coef = c->mass_coef;
  o->history = hist;
}

/* One step of c from u0 on a new problem (full assembly, fresh factorisation). */
static int fresh(const stokes_case *c, const double *hist, const double *u0, double *u, sl_diag *d) {
  sl_flow_problem q;
  sl_linsolve *ls = NULL;
  int rc = sl_flow_problem_init(&q, g_th, d);
  if (rc) return rc;
  set_opts(&q.opts, c, hist);
  sl_newton_opts no = {.linear = 1};
  sl_newton_stats st;
  memcpy(u, u0, (size_t)g_th->n_dofs * sizeof *u);
  if (!(rc = fix(&q.bc, c, d)) && !(rc = sl_linsolve_create(&ls, "umfpack", d)))
    rc = sl_flow_problem_solve(&q, u, ls, &no, &st, d);
  if (!rc && st.assemblies != 1) rc = sl_diag_set(d, SL_EFAILED, "a fresh problem assembled %d times", st.assemblies);
  sl_linsolve_destroy(ls);
  sl_flow_problem_free(&q);
  return rc;
}

static void stokes_steps(void) {
  sl_diag d = {{0}};
  sl_mesh *m = NULL;
  sl_th_space *th = NULL;
  sl_grid_opts go = {.cell_type = SL_CELL_QUAD4};
  int rc = sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 4, &go, &m, &d);
  if (!rc) rc = sl_th_create(m, 2, &th, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  g_th = th;
  int32_t n = th->n_dofs;
  double *u = calloc((size_t)n, sizeof *u), *v = malloc((size_t)n * sizeof *v), *u0 = malloc((size_t)n * sizeof *u0);
  double *hist = malloc((size_t)n * sizeof *hist);
  sl_flow_problem p;
  sl_linsolve *ls = NULL;
  CHECK(sl_flow_problem_init(&p, th, &d) == 0 && sl_linsolve_create(&ls, "umfpack", &d) == 0);
  sl_newton_opts no = {.linear = 1};
  sl_newton_stats st;
  stokes_case c = {1.0, 100.0, 1.0, 1.0, 0, 0};
  /* the steps: what changes before each and whether the matrix is then assembled */
  enum { NONE, HISTORY, LID, MASS, VISCOSITY, DENSITY, FIXED, WRITTEN, CALLBACK, NOT_LINEAR, N_STEPS };
  static const char *const what[N_STEPS] = {
      "first solve", "new history",        "new lid velocity",        "mass coefficient",     "viscosity",
      "density",     "one more fixed dof", "a write into the matrix", "a viscosity callback", "not declared linear"};
  static const int assembles[N_STEPS] = {1, 0, 0, 1, 1, 1, 1, 1, 1, 1};
  for (int k = 0; k < N_STEPS && !rc; ++k) {
    for (int32_t i = 0; i < n; ++i) hist[i] = -100.0 * u[i] + (k == HISTORY ? 0.1 * sin(0.1 * i) : 0.0);
    if (k == LID) c.lid = 2.0;
    if (k == MASS) c.mass_coef = 50.0;
    if (k == VISCOSITY) c.viscosity = 0.5;
    if (k == DENSITY) c.density = 2.0;
    if (k == FIXED) c.extra_fixed = 1;
    if (k == WRITTEN) sl_csr_zero(&p.sys.A);
    if (k == CALLBACK) c.callback = 1;
    if (k == NOT_LINEAR) no.linear = 0, no.rtol = 1e-10;
    rc = fix(&p.bc, &c, &d); /* the same dofs again, maybe new values */
    set_opts(&p.opts, &c, hist);
    memcpy(u0, u, (size_t)n * sizeof *u);
    if (!rc) rc = sl_flow_problem_solve(&p, u, ls, &no, &st, &d);
    CHECK_MSG(rc == 0, "%s: %s", what[k], d.msg);
    if (rc) break;
    CHECK_MSG((st.assemblies > 0) == assembles[k], "%s: %d matrix assemblies, %d residual-only", what[k], st.assemblies,
              st.residuals);
    if (!assembles[k]) {
      CHECK(st.residuals == 1);
      if ((rc = fresh(&c, hist, u0, v, &d)) == 0)
        CHECK_MSG(memcmp(u, v, (size_t)n * sizeof *u) == 0, "%s: the kept matrix changed the solution", what[k]);
      CHECK_MSG(rc == 0, "%s", d.msg);
    }
  }
  sl_linsolve_destroy(ls);
  sl_flow_problem_free(&p);
  free(u), free(v), free(u0), free(hist);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

/* ---- a time step's Newton: R(u) = f - K u - u^3 / 2 from a close start -------------------------------- */

typedef struct cubic_problem {
  const sl_csr *K;
  const double *f;
  int matrices, residuals;
} cubic_problem;

static int cubic_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d) {
  cubic_problem *p = user;
  (void)d;
  int32_t n = p->K->n_rows;
  sl_csr_matvec(p->K, u, b);
  for (int32_t i = 0; i < n; ++i) b[i] = p->f[i] - b[i] - 0.5 * u[i] * u[i] * u[i];
  if (mode == SL_NL_RESIDUAL) {
    ++p->residuals;
    return 0;
  }
  ++p->matrices;
  memcpy(A->values, p->K->values, (size_t)A->nnz * sizeof *A->values);
  for (int32_t i = 0; i < n; ++i) A->values[sl_csr_find(A, i, i)] += 1.5 * u[i] * u[i];
  sl_csr_touch(A);
  return 0;
}

static void predicted_newton(void) {
  sl_diag d = {{0}};
  sl_csr K = {0}, A = {0};
  CHECK(poisson_build(&K, 20, 20, 0.0, &d) == 0 && poisson_build(&A, 20, 20, 0.0, &d) == 0);
  int32_t n = K.n_rows;
  double *f = malloc((size_t)n * sizeof *f), *b = malloc((size_t)n * sizeof *b);
  double *exact = calloc((size_t)n, sizeof *exact), *u = malloc((size_t)n * sizeof *u);
  for (int32_t i = 0; i < n; ++i) f[i] = 2.0 + sin(0.1 * i);
  cubic_problem p = {&K, f, 0, 0};
  sl_linsolve *ls = NULL;
  CHECK(sl_linsolve_create(&ls, "klu", &d) == 0);
  sl_newton_stats st;
  sl_newton_opts o = {.rtol = 1e-13};
  CHECK_MSG(sl_newton_solve(&A, b, n, exact, cubic_assemble, &p, ls, &o, &st, &d) == 0, "%s", d.msg);
  double scale = 0.0;
  for (int32_t i = 0; i < n; ++i) scale = fmax(scale, fabs(exact[i]));
  for (int k = 0; k < 2; ++k) { /* predicted, then not */
    for (int32_t i = 0; i < n; ++i) u[i] = exact[i] * (1.0 + 1e-3 * cos(0.37 * i));
    p.matrices = p.residuals = 0;
    sl_newton_opts q = {.rtol = 1e-6, .predicted = k == 0};
    int rc = sl_newton_solve(&A, b, n, u, cubic_assemble, &p, ls, &q, &st, &d);
    CHECK_MSG(rc == 0, "%s", d.msg);
    double err = 0.0;
    for (int32_t i = 0; i < n; ++i) err = fmax(err, fabs(u[i] - exact[i]));
    printf(
        "Newton from a start 1e-3 off, %s: %d corrections, %d matrix and %d residual-only assemblies, error %.2e of "
        "the solution (tolerance 1e-6)\n",
        k == 0 ? "predicted" : "not predicted", st.iterations, p.matrices, p.residuals, err / scale);
    CHECK(err <= 1e-6 * scale);
    if (k == 0) CHECK(st.iterations == 1 && st.estimated && p.matrices == 1 && p.residuals == 1);
    else CHECK(st.iterations == 2 && p.matrices >= 2);
  }
  sl_linsolve_destroy(ls);
  sl_csr_free(&K), sl_csr_free(&A);
  free(f), free(b), free(exact), free(u);
}

int main(void) {
  linear_newton();
  predicted_newton();
  stokes_steps();
  return sl_test_summary();
}
