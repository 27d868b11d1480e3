/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Steady generalized-Newtonian Navier–Stokes with manufactured solutions
 * (flow_exact.h), solved by Newton on n = 8, 16, 32:
 *  - planar Q2/Q1 and P2/P1 with convection, density rho = 1 + x/5 and a
 *    shear-thinning viscosity mu = 0.4 + 1/(1 + gamma^2);
 *  - planar Q2/Q1 with the out-of-plane velocity w of a cross-section;
 *  - axisymmetric (r, z) Q2/Q1 on [0, 1]^2 with swirl, the axis a boundary
 *    (u_r = u_theta = 0 there, u_z free), r-weighted norms.
 * Expected orders (Taylor–Hood): velocity L2 3, velocity H1 2, pressure
 * L2 2, asserted within 0.25 on the finest pair; Newton must converge
 * quadratically at the end (correction c_k <= 30 c_{k-1}^2 for c_k > 1e-9) and in at most
 * 10 iterations from a zero start. */
#include "core/models/navier_stokes/flow_problem.h"
#include "fe_study.h"
#include "flow_exact.h"
#include "testing.h"

static void u_planar(const double x[2], double t, double u[3]) {
  (void)t;
  const double a = M_PI, b = 2.0 * M_PI;
  u[0] = sin(a * x[0]) * cos(b * x[1]) / a;
  u[1] = -cos(a * x[0]) * sin(b * x[1]) / b;
  u[2] = x[0] * (1.0 - x[0]) * exp(x[1]);
}
static double p_planar(const double x[2], double t) {
  (void)t;
  return 2.0 * sin(M_PI * x[0]) * cos(M_PI * x[1]);
}
/* Axisymmetric, regular on the axis: from the stream function r^2 cos(r) sin(pi z),
 * u_r = -(1/r) d_z psi, u_z = (1/r) d_r psi; the swirl odd in r. */
static void u_axi(const double x[2], double t, double u[3]) {
  (void)t;
  double r = x[0], z = x[1];
  u[0] = -r * cos(r) * M_PI * cos(M_PI * z);
  u[1] = (2.0 * cos(r) - r * sin(r)) * sin(M_PI * z);
  u[2] = r * exp(-r * r) * (1.0 + z);
}
static double p_axi(const double x[2], double t) {
  (void)t;
  return cos(M_PI * x[0]) * (x[1] - 0.5);
}
static double rho_var(const double x[2]) { return 1.0 + 0.2 * x[0]; }
static void mu_thin(double g, double *mu, double *dmu) {
  double q = 1.0 + g * g;
  *mu = 0.4 + 1.0 / q, *dmu = -2.0 * g / (q * q);
}

typedef struct comp_exact {
  const flow_exact *e;
  int comp;
} comp_exact;
static void comp_fn(void *user, const double x[2], double *v, double g[2]) {
  const comp_exact *c = user;
  double u[3];
  flow_exact_u(c->e, x, c->e->t, u);
  *v = u[c->comp];
  if (g) {
    double G[3][2];
    flow_exact_grad(c->e, x, G);
    g[0] = G[c->comp][0], g[1] = G[c->comp][1];
  }
}
static void p_fn(void *user, const double x[2], double *v, double g[2]) {
  const flow_exact *e = user;
  *v = e->p(x, e->t);
  if (g) g[0] = g[1] = 0.0;
}

typedef struct errors {
  double u_l2, u_h1, p_l2;
  int iterations;
  double rate; /* c_k / c_{k-1}^2 of the last two corrections above round-off */
} errors;

static int run(const flow_exact *e, sl_cell_type cell, int n, errors *err, sl_diag *d) {
  sl_grid_opts go = {.cell_type = cell, .diagonal = SL_DIAGONAL_UNION_JACK};
  sl_mesh *m = NULL;
  sl_th_space *th = NULL;
  sl_flow_problem p;
  sl_linsolve *ls = NULL;
  double *u = NULL;
  int rc = e->axisymmetric ? sl_mesh_annulus(0.0, 1.0, 0.0, 1.0, n, n, &go, &m, d)
                           : sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, n, n, &go, &m, d);
  if (!rc) rc = sl_th_create(m, e->n_comp, &th, d);
  if (rc) goto out;
  if ((rc = sl_flow_problem_init(&p, th, d))) goto out;
  u = calloc((size_t)th->n_dofs, sizeof *u);
  comp_exact ce[3] = {{e, 0}, {e, 1}, {e, 2}};
  /* Dirichlet data everywhere but the top, where the exact traction is
   * prescribed: the pressure is then determined, with no datum. */
  const char *walls_planar[] = {"bottom", "right", "left"};
  const char *walls_axi[] = {"bottom", "outer"};
  const char *const *walls = e->axisymmetric ? walls_axi : walls_planar;
  int n_walls = e->axisymmetric ? 2 : 3;
  p.traction[p.n_tractions++] = (sl_flow_traction){"top", flow_exact_traction_fn, (void *)e};
  for (int w = 0; w < n_walls && !rc; ++w)
    for (int c = 0; c < e->n_comp && !rc; ++c)
      rc = sl_constraints_fix_boundary(&p.bc, th->vel, walls[w], sl_th_vel_dof(th, c, 0), comp_fn, &ce[c], 0.0, d);
  if (e->axisymmetric && !rc) {
    /* the axis: no radial flow, no swirl; u_z is free */
    rc = sl_constraints_fix_boundary(&p.bc, th->vel, "axis", sl_th_vel_dof(th, 0, 0), NULL, NULL, 0.0, d);
    if (!rc) rc = sl_constraints_fix_boundary(&p.bc, th->vel, "axis", sl_th_vel_dof(th, 2, 0), NULL, NULL, 0.0, d);
  }
  p.opts = (sl_flow_opts){.axisymmetric = e->axisymmetric,
                          .density = {flow_exact_rho_fn, (void *)e, 0.0},
                          .viscosity = flow_exact_mu_fn,
                          .viscosity_user = (void *)e,
                          .convection = e->convection,
                          .body_force = flow_exact_force_fn,
                          .body_force_user = (void *)e};
  sl_newton_opts no = {.rtol = 1e-10, .max_iterations = 20};
  sl_newton_stats st;
  if (!rc) rc = sl_linsolve_create(&ls, "umfpack", d);
  if (!rc) rc = sl_flow_problem_solve(&p, u, ls, &no, &st, d);
  if (!rc) {
    err->iterations = st.iterations;
    err->rate = NAN;
    for (int k = 1; k < st.iterations && k < SL_NEWTON_HISTORY; ++k)
      if (st.history[k] > 1e-9) err->rate = st.history[k] / (st.history[k - 1] * st.history[k - 1]);
    double l2 = 0.0, h1 = 0.0;
    int deg = cell == SL_CELL_TRI3 ? 5 : 6;
    for (int c = 0; c < e->n_comp && !rc; ++c) {
      double a, b;
      rc = sl_fe_error_norms(th->vel, u + sl_th_vel_dof(th, c, 0), comp_fn, &ce[c], e->axisymmetric, deg, &a, &b, d);
      l2 += a * a, h1 += b * b;
    }
    err->u_l2 = sqrt(l2), err->u_h1 = sqrt(h1);
    if (!rc)
      rc = sl_fe_error_norms(th->pres, u + th->p_offset, p_fn, (void *)e, e->axisymmetric, deg, &err->p_l2, NULL, d);
  }
  sl_linsolve_destroy(ls);
  sl_flow_problem_free(&p);
out:
  free(u);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
  return rc;
}

static void study(const char *name, const flow_exact *e, sl_cell_type cell) {
  errors er[3];
  const int ns[3] = {8, 16, 32};
  for (int k = 0; k < 3; ++k) {
    sl_diag d = {{0}};
    int rc = run(e, cell, ns[k], &er[k], &d);
    CHECK_MSG(rc == 0, "%s n=%d: %s", name, ns[k], d.msg);
    if (rc) return;
    printf("%-28s n=%2d: |u-uh| %.3e  |u-uh|_H1 %.3e  |p-ph| %.3e  (%d Newton iterations, c_k/c_{k-1}^2 %.2g)\n", name,
           ns[k], er[k].u_l2, er[k].u_h1, er[k].p_l2, er[k].iterations, er[k].rate);
    CHECK_MSG(er[k].iterations <= 10, "%s: %d Newton iterations", name, er[k].iterations);
    CHECK_MSG(er[k].rate < 30.0, "%s: Newton not quadratic (c_k / c_{k-1}^2 = %.3g)", name, er[k].rate);
  }
  double ou = observed_order(er[1].u_l2, er[2].u_l2), oh = observed_order(er[1].u_h1, er[2].u_h1),
         op = observed_order(er[1].p_l2, er[2].p_l2);
  printf("%-28s orders: velocity L2 %.2f, H1 %.2f, pressure L2 %.2f\n", name, ou, oh, op);
  CHECK_MSG(fabs(ou - 3.0) < 0.25, "%s: velocity L2 order %.2f", name, ou);
  CHECK_MSG(fabs(oh - 2.0) < 0.25, "%s: velocity H1 order %.2f", name, oh);
  CHECK_MSG(fabs(op - 2.0) < 0.25, "%s: pressure L2 order %.2f", name, op);
}

/* argv[1] = planar or axisymmetric runs those studies alone (two ctest
 * entries that run in parallel); none: all. */
int main(int argc, char **argv) {
  int planar_part = argc < 2 || strcmp(argv[1], "planar") == 0,
      axi_part = argc < 2 || strcmp(argv[1], "axisymmetric") == 0;
  if (!planar_part && !axi_part) return fprintf(stderr, "unknown part '%s' (planar, axisymmetric)\n", argv[1]), 2;
  flow_exact planar = {
      .axisymmetric = 0, .n_comp = 2, .convection = 1, .u = u_planar, .p = p_planar, .rho = rho_var, .mu = mu_thin};
  if (planar_part) {
    study("planar Q2/Q1", &planar, SL_CELL_QUAD4);
    study("planar P2/P1", &planar, SL_CELL_TRI3);
    flow_exact section = planar;
    section.n_comp = 3;
    study("planar Q2/Q1 + out-of-plane", &section, SL_CELL_QUAD4);
  }
  flow_exact axi = {
      .axisymmetric = 1, .n_comp = 3, .convection = 1, .u = u_axi, .p = p_axi, .rho = rho_var, .mu = mu_thin};
  if (axi_part) {
    study("axisymmetric Q2/Q1 swirl", &axi, SL_CELL_QUAD4);
    study("axisymmetric P2/P1 swirl", &axi, SL_CELL_TRI3);
  }
  return sl_test_summary();
}
