/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Flow on periodic Taylor–Hood spaces.
 *
 * 1. Periodic Poiseuille channel [0, L] x [0, 1], L = 2.5, periodic in x,
 *    no-slip walls at the bottom and the top, driven by a uniform body force
 *    f = (3, 0) (and f_w = 1.5 on the out-of-plane velocity of a
 *    cross-section), rho = 1.3, mu = 0.7, convection on, through the flow
 *    problem of core/models/flow_problem.h (Newton):
 *      u = f y (1 - y) / (2 mu),  v = 0,  p = const,
 *    quadratic in y, so in the space: reproduced to round-off at every node
 *    (Q2/Q1 on a graded grid, P2/P1 on union-jack triangles). The pressure
 *    datum fixes the constant: p = 0 to round-off.
 * 2. Doubly periodic steady Stokes on [0, 2] x [0, 1] with the Taylor–Green
 *    like u = (sin(a x) cos(b y) / a, -cos(a x) sin(b y) / b), a = pi,
 *    b = 2 pi, p = 4 sin(a x) cos(b y), viscosity mu = 1 + sin(a x + b y) / 2
 *    (sl_assemble_stokes). Velocity is defined up to a constant and pressure
 *    up to a constant: the velocity at the origin is pinned to the exact
 *    value, the pressure by the datum, then shifted to zero mean.
 * 3. The same velocity and pressure for steady Navier–Stokes with
 *    convection, density 1 + sin(pi x) / 5 and the shear-thinning
 *    mu = 0.4 + 1 / (1 + gamma^2) through the flow problem (Newton).
 * Orders over n = 6, 12, 24 (nx = 2 n): velocity L2 3, H1 2, pressure L2 2,
 * within 0.25; the errors are measured after shifting the velocity and the
 * pressure to zero mean (the pins only choose those constants). Newton
 * starts from the interpolant of the exact solution. */
#include <string.h>

#include "core/models/navier_stokes/flow_problem.h"
#include "fe_study.h"
#include "flow_exact.h"
#include "testing.h"

static const sl_periodic_pair PX[] = {{"left", "right"}}, PXY[] = {{"left", "right"}, {"bottom", "top"}};

/* ---- 1. Poiseuille ---------------------------------------------------------- */

#define POIS_L 2.5
#define POIS_MU 0.7
static const double POIS_F[3] = {3.0, 0.0, 1.5};

static int pois_force(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  int nc = *(const int *)user;
  (void)d;
  for (int i = 0; i < b->n; ++i)
    for (int c = 0; c < nc; ++c) out[nc * i + c] = POIS_F[c];
  return 0;
}

static double pois_u(int comp, const double x[2]) { return POIS_F[comp] * x[1] * (1.0 - x[1]) / (2.0 * POIS_MU); }

static void poiseuille(const char *name, sl_cell_type cell, int n_comp) {
  sl_grid_opts go = {.cell_type = cell,
                     .diagonal = SL_DIAGONAL_UNION_JACK,
                     .grade_x = {SL_GRADE_GEOMETRIC, 1.5},
                     .grade_y = {SL_GRADE_SYMMETRIC, 2.5}};
  sl_mesh *m = NULL;
  sl_th_space *th = NULL;
  sl_flow_problem p;
  int have_p = 0;
  sl_linsolve *ls = NULL;
  double *u = NULL;
  sl_diag d = {{0}};
  int rc = sl_mesh_rectangle(0.0, POIS_L, 0.0, 1.0, 7, 6, &go, &m, &d);
  if (!rc) rc = sl_th_create_periodic(m, n_comp, PX, 1, &th, &d);
  if (!rc) rc = sl_flow_problem_init(&p, th, &d), have_p = !rc;
  if (rc) goto out;
  u = calloc((size_t)th->n_dofs, sizeof *u);
  for (int c = 0; c < n_comp && !rc; ++c) {
    rc = sl_constraints_fix_boundary(&p.bc, th->vel, "bottom", sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, &d);
    if (!rc) rc = sl_constraints_fix_boundary(&p.bc, th->vel, "top", sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, &d);
  }
  sl_stokes_fix_pressure_datum(&p.bc, th);
  p.opts.density.value = 1.3;
  p.opts.viscosity_value = POIS_MU;
  p.opts.convection = 1;
  p.opts.body_force = pois_force;
  p.opts.body_force_user = &n_comp;
  sl_newton_opts no = {.rtol = 1e-12, .max_iterations = 5};
  sl_newton_stats st;
  if (!rc) rc = sl_linsolve_create(&ls, "umfpack", &d);
  if (!rc) rc = sl_flow_problem_solve(&p, u, ls, &no, &st, &d);
  CHECK_MSG(rc == 0, "%s: %s", name, d.msg);
  if (rc) goto out;
  /* at every dof, and at every geometric node through node_dof (the
   * right-hand side x = L included) */
  double eu = 0.0, ep = 0.0, umax = 0.0;
  for (int32_t i = 0; i < th->vel->n_nodes; ++i) {
    const double *x = th->vel->node_xy + 2 * (size_t)i;
    for (int c = 0; c < n_comp; ++c) {
      double uh = u[sl_th_vel_dof(th, c, th->vel->node_dof[i])], ex = pois_u(c, x);
      eu = fmax(eu, fabs(uh - ex)), umax = fmax(umax, fabs(ex));
    }
  }
  for (int32_t j = 0; j < th->pres->n_dofs; ++j) ep = fmax(ep, fabs(u[th->p_offset + j]));
  /* between the nodes as well: the velocity at points next to the partner side */
  int cell_hint = -1;
  double ev = 0.0;
  for (int k = 0; k < 9; ++k) {
    double x[2] = {POIS_L - 1e-4, 0.05 + 0.1 * k}, xi[2], v;
    if (sl_fe_locate(m, x, &cell_hint, xi, &d) != 0) break;
    sl_fe_eval(th->vel, u, cell_hint, xi, &v, NULL);
    ev = fmax(ev, fabs(v - pois_u(0, x)));
  }
  printf("%-34s %d Newton iterations: max |u - u_exact| %.2e (u_max %.3f), max |p| %.2e, near x = L %.2e\n", name,
         st.iterations, eu, umax, ep, ev);
  CHECK_MSG(eu <= 1e-12 * umax, "%s: velocity off by %.3e", name, eu);
  CHECK_MSG(ev <= 1e-12 * umax, "%s: velocity off by %.3e next to x = L", name, ev);
  CHECK_MSG(ep <= 1e-11 * POIS_F[0], "%s: pressure not constant: %.3e", name, ep);
  CHECK_MSG(fabs(umax - POIS_F[0] / (8.0 * POIS_MU)) < 1e-14, "%s: u_max %.17g", name, umax);
  CHECK(st.iterations <= 3);
out:
  sl_linsolve_destroy(ls);
  if (have_p) sl_flow_problem_free(&p);
  free(u);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

/* ---- 2. and 3. doubly periodic manufactured solutions --------------------------- */

static const double A_ = M_PI, B_ = 2.0 * M_PI;
#define P_AMP 4.0

static void tg_u(const double x[2], double t, double u[3]) {
  (void)t;
  u[0] = sin(A_ * x[0]) * cos(B_ * x[1]) / A_;
  u[1] = -cos(A_ * x[0]) * sin(B_ * x[1]) / B_;
  u[2] = 0.0;
}
static double tg_p(const double x[2], double t) {
  (void)t;
  return P_AMP * sin(A_ * x[0]) * cos(B_ * x[1]);
}
static double rho_per(const double x[2]) { return 1.0 + 0.2 * sin(M_PI * x[0]); }
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

/* Stokes with a position-dependent viscosity: f = -div(2 mu D(u)) + grad p. */
static double stokes_mu(const double x[2], double gm[2]) {
  double c = cos(A_ * x[0] + B_ * x[1]);
  gm[0] = 0.5 * A_ * c, gm[1] = 0.5 * B_ * c;
  return 1.0 + 0.5 * sin(A_ * x[0] + B_ * x[1]);
}

static int stokes_viscosity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) {
    double g[2];
    out[i] = stokes_mu(b->x[i], g);
  }
  return 0;
}

static int stokes_force(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) {
    const double *x = b->x[i];
    double sa = sin(A_ * x[0]), ca = cos(A_ * x[0]), sb = sin(B_ * x[1]), cb = cos(B_ * x[1]);
    double u[2] = {sa * cb / A_, -ca * sb / B_};
    double G[2][2] = {{ca * cb, -B_ / A_ * sa * sb}, {A_ / B_ * sa * sb, -ca * cb}};
    double gm[2], mu = stokes_mu(x, gm);
    double D[2][2] = {{G[0][0], 0.5 * (G[0][1] + G[1][0])}, {0.5 * (G[0][1] + G[1][0]), G[1][1]}};
    double gp[2] = {P_AMP * A_ * ca * cb, -P_AMP * B_ * sa * sb};
    for (int a = 0; a < 2; ++a) /* div u = 0: div(2 mu D) = 2 D grad mu + mu lap u, lap u = -(a^2 + b^2) u */
      out[2 * i + a] = -(2.0 * (gm[0] * D[a][0] + gm[1] * D[a][1]) - (A_ * A_ + B_ * B_) * mu * u[a]) + gp[a];
  }
  return 0;
}

typedef struct errors {
  double u_l2, u_h1, p_l2;
  int iterations;
} errors;

/* Pins the velocity at dof 0 (the origin) to the exact value, and the pressure datum. */
static void pin(sl_constraints *bc, const sl_th_space *th, const flow_exact *e) {
  double u0[3];
  flow_exact_u(e, th->vel->xy, e->t, u0);
  for (int c = 0; c < th->n_comp; ++c) sl_constraints_fix(bc, sl_th_vel_dof(th, c, 0), u0[c]);
  sl_stokes_fix_pressure_datum(bc, th);
}

/* Errors after shifting the pressure and each velocity component to zero
 * mean, as the exact ones: the constants the pins chose are not part of
 * the discretisation error. */
static int measure(const sl_th_space *th, const flow_exact *e, double *x, errors *er, sl_diag *d) {
  int rc = sl_stokes_zero_mean_pressure(th, x, d), deg = th->mesh->cell_type == SL_CELL_TRI3 ? 5 : 6;
  comp_exact ce[3] = {{e, 0}, {e, 1}, {e, 2}};
  for (int c = 0; c < th->n_comp && !rc; ++c) {
    double *uc = x + sl_th_vel_dof(th, c, 0), mean, area;
    rc = sl_fe_integrate(th->vel, uc, 0, &mean, &area, d);
    for (int32_t i = 0; i < th->n_vel && !rc; ++i) uc[i] -= mean / area;
  }
  double l2 = 0.0, h1 = 0.0;
  for (int c = 0; c < th->n_comp && !rc; ++c) {
    double a, b;
    rc = sl_fe_error_norms(th->vel, x + sl_th_vel_dof(th, c, 0), comp_fn, &ce[c], 0, deg, &a, &b, d);
    l2 += a * a, h1 += b * b;
  }
  er->u_l2 = sqrt(l2), er->u_h1 = sqrt(h1);
  if (!rc) rc = sl_fe_error_norms(th->pres, x + th->p_offset, p_fn, (void *)e, 0, deg, &er->p_l2, NULL, d);
  return rc;
}

static int run(int navier_stokes, const flow_exact *e, sl_cell_type cell, int n, errors *er, sl_diag *d) {
  sl_grid_opts go = {.cell_type = cell, .diagonal = SL_DIAGONAL_UNION_JACK};
  sl_mesh *m = NULL;
  sl_th_space *th = NULL;
  sl_linsolve *ls = NULL;
  double *x = NULL;
  int rc = sl_mesh_rectangle(0.0, 2.0, 0.0, 1.0, 2 * n, n, &go, &m, d);
  if (!rc) rc = sl_th_create_periodic(m, e->n_comp, PXY, 2, &th, d);
  if (!rc) rc = sl_linsolve_create(&ls, "umfpack", d);
  if (rc) goto out;
  x = calloc((size_t)th->n_dofs, sizeof *x);
  er->iterations = 1;
  if (navier_stokes) {
    sl_flow_problem p;
    if ((rc = sl_flow_problem_init(&p, th, d))) goto out;
    pin(&p.bc, th, e);
    /* Newton from the interpolant of the exact solution (the test is about
     * the discretisation, flow_mms about Newton from a cold start) */
    comp_exact ce[2] = {{e, 0}, {e, 1}};
    for (int c = 0; c < 2; ++c) sl_fe_interpolate(th->vel, comp_fn, &ce[c], x + sl_th_vel_dof(th, c, 0));
    sl_fe_interpolate(th->pres, p_fn, (void *)e, x + th->p_offset);
    p.opts = (sl_flow_opts){.density = {flow_exact_rho_fn, (void *)e, 0.0},
                            .viscosity = flow_exact_mu_fn,
                            .viscosity_user = (void *)e,
                            .convection = e->convection,
                            .body_force = flow_exact_force_fn,
                            .body_force_user = (void *)e};
    /* from that start the second correction is ~1e-7 and the error after
     * it at round-off: two factorisations per mesh */
    sl_newton_opts no = {.rtol = 1e-6, .max_iterations = 20};
    sl_newton_stats st;
    rc = sl_flow_problem_solve(&p, x, ls, &no, &st, d);
    er->iterations = st.iterations;
    sl_flow_problem_free(&p);
  } else {
    sl_system s;
    sl_constraints bc;
    if ((rc = sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, d))) goto out;
    if ((rc = sl_constraints_init(&bc, th->n_dofs, d))) {
      sl_system_free(&s);
      goto out;
    }
    sl_stokes_opts o = {.viscosity = {stokes_viscosity, NULL, 0.0}, .body_force = stokes_force};
    rc = sl_assemble_stokes(&s, th, &o, d);
    pin(&bc, th, e);
    if (!rc) rc = sl_constraints_apply(&bc, &s, 1, d);
    if (!rc) rc = sl_linsolve_solve(ls, &s.A, s.b, x, d);
    sl_constraints_free(&bc);
    sl_system_free(&s);
  }
  if (!rc) rc = measure(th, e, x, er, d);
out:
  free(x);
  sl_linsolve_destroy(ls);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
  return rc;
}

static void study(const char *name, int navier_stokes, const flow_exact *e, sl_cell_type cell, const int ns[3]) {
  errors er[3];
  for (int k = 0; k < 3; ++k) {
    sl_diag d = {{0}};
    int rc = run(navier_stokes, e, cell, ns[k], &er[k], &d);
    CHECK_MSG(rc == 0, "%s n=%d: %s", name, ns[k], d.msg);
    if (rc) return;
    printf("%-34s n=%2d: |u-uh| %.3e  |u-uh|_H1 %.3e  |p-ph| %.3e  (%d iterations)\n", name, ns[k], er[k].u_l2,
           er[k].u_h1, er[k].p_l2, er[k].iterations);
    CHECK_MSG(er[k].iterations <= 10, "%s: %d Newton iterations", name, er[k].iterations);
  }
  double ou = observed_order(er[1].u_l2, er[2].u_l2), oh = observed_order(er[1].u_h1, er[2].u_h1),
         op = observed_order(er[1].p_l2, er[2].p_l2);
  printf("%-34s orders: velocity L2 %.2f, H1 %.2f, pressure L2 %.2f\n", name, ou, oh, op);
  CHECK_MSG(fabs(ou - 3.0) < 0.25, "%s: velocity L2 order %.2f", name, ou);
  CHECK_MSG(fabs(oh - 2.0) < 0.25, "%s: velocity H1 order %.2f", name, oh);
  CHECK_MSG(fabs(op - 2.0) < 0.25, "%s: pressure L2 order %.2f", name, op);
}

/* "channel": Poiseuille and Stokes; "ns": Navier–Stokes; no argument: all
 * (CTest runs the two halves as fe_periodic_flow and fe_periodic_ns). */
int main(int argc, char **argv) {
  int all = argc < 2, channel = all || strcmp(argv[1], "channel") == 0, ns = all || strcmp(argv[1], "ns") == 0;
  const int sizes[3] = {6, 12, 24};
  if (channel) {
    poiseuille("Poiseuille Q2/Q1 (graded)", SL_CELL_QUAD4, 2);
    poiseuille("Poiseuille P2/P1", SL_CELL_TRI3, 2);
    poiseuille("Poiseuille Q2/Q1 + out-of-plane", SL_CELL_QUAD4, 3);
    flow_exact stokes = {.n_comp = 2, .u = tg_u, .p = tg_p, .rho = rho_per, .mu = mu_thin};
    study("Taylor-Green Stokes Q2/Q1", 0, &stokes, SL_CELL_QUAD4, sizes);
    study("Taylor-Green Stokes P2/P1", 0, &stokes, SL_CELL_TRI3, sizes);
  }
  if (ns) {
    flow_exact nse = {.n_comp = 2, .convection = 1, .u = tg_u, .p = tg_p, .rho = rho_per, .mu = mu_thin};
    study("Taylor-Green Navier-Stokes Q2/Q1", 1, &nse, SL_CELL_QUAD4, sizes);
  }
  if (!channel && !ns) CHECK_MSG(0, "unknown part '%s' (channel, ns)", argv[1]);
  return sl_test_summary();
}
