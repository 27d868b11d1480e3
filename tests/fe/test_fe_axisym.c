/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Axisymmetric Poisson with a manufactured solution on the (r, z) box
 * [0, 1] x [0, 1] with the axis as a boundary (natural condition there):
 *   -(1/r) d/dr(r k du/dr) - d/dz(k du/dz) = f,
 *   u = cos(pi r / 2) exp(z)   (du/dr = 0 on the axis, u = 0 at r = 1),
 *   k = 1 + r^2.
 * Observed orders in the r-weighted norms over n = 8, 16, 32: L2 p + 1,
 * H1 p (+-0.2). The same data assembled without the r weight converge to
 * another function: that error must not fall. */
#include "fe_study.h"
#include "testing.h"

static const double K_ = M_PI / 2.0;

static void exact(void *user, const double x[2], double *v, double g[2]) {
  (void)user;
  double e = exp(x[1]);
  *v = cos(K_ * x[0]) * e;
  if (g) g[0] = -K_ * sin(K_ * x[0]) * e, g[1] = *v;
}

static int diffusivity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = 1.0 + b->x[i][0] * b->x[i][0];
  return 0;
}

/* f = -[k (u_rr + u_r / r) + k_r u_r] - k u_zz; quadrature points have r > 0. */
static int source(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) {
    double r = b->x[i][0], e = exp(b->x[i][1]), k = 1.0 + r * r;
    double ur = -K_ * sin(K_ * r) * e, urr = -K_ * K_ * cos(K_ * r) * e, uzz = cos(K_ * r) * e;
    out[i] = -(k * (urr + ur / r) + 2.0 * r * ur) - k * uzz;
  }
  return 0;
}

static int solve_and_measure(sl_cell_type cell, int order, int n, int axisymmetric, double *l2, double *h1,
                             sl_diag *d) {
  static const char *const dirichlet[] = {"bottom", "outer", "top"}; /* "axis": natural */
  sl_grid_opts o = {.cell_type = cell};
  sl_mesh *m = NULL;
  sl_dofmap *dm = NULL;
  double *x = NULL;
  sl_diffusion_opts opts = {
      .diffusivity = {diffusivity, NULL, 0.0}, .source = {source, NULL, 0.0}, .axisymmetric = axisymmetric};
  int rc = sl_mesh_annulus(0.0, 1.0, 0.0, 1.0, n, n, &o, &m, d);
  if (!rc) rc = sl_dofmap_create(m, order, &dm, d);
  if (!rc && !(x = calloc((size_t)dm->n_dofs, sizeof *x))) rc = SL_EFAILED;
  if (!rc) rc = solve_diffusion(dm, &opts, dirichlet, 3, exact, NULL, "cholmod", x, d);
  /* Errors always in the r-weighted norms, the problem's own; one degree
   * more for the weight (the triangle rules stop at 5). */
  int degree = cell == SL_CELL_TRI3 ? 5 : error_quad_degree(cell, order) + 1;
  if (!rc) rc = sl_fe_error_norms(dm, x, exact, NULL, 1, degree, l2, h1, d);
  free(x);
  sl_dofmap_destroy(dm);
  sl_mesh_destroy(m);
  return rc;
}

static void run(const char *name, sl_cell_type cell, int order) {
  const int sizes[] = {8, 16, 32};
  double l2[3], h1[3];
  for (int k = 0; k < 3; ++k) {
    sl_diag d = {{0}};
    int rc = solve_and_measure(cell, order, sizes[k], 1, &l2[k], &h1[k], &d);
    CHECK_MSG(rc == 0, "%s n=%d: %s", name, sizes[k], d.msg);
    if (rc) return;
  }
  printf("axisymmetric %-4s L2 %.3e %.3e %.3e orders %.3f %.3f | H1 %.3e %.3e %.3e orders %.3f %.3f\n", name, l2[0],
         l2[1], l2[2], observed_order(l2[0], l2[1]), observed_order(l2[1], l2[2]), h1[0], h1[1], h1[2],
         observed_order(h1[0], h1[1]), observed_order(h1[1], h1[2]));
  for (int k = 0; k < 2; ++k) {
    double ol2 = observed_order(l2[k], l2[k + 1]), oh1 = observed_order(h1[k], h1[k + 1]);
    CHECK_MSG(fabs(ol2 - (order + 1)) <= 0.2, "%s: axisymmetric L2 order %.3f, expected %d", name, ol2, order + 1);
    CHECK_MSG(fabs(oh1 - order) <= 0.2, "%s: axisymmetric H1 order %.3f, expected %d", name, oh1, order);
  }
  /* Without the r weight the discrete problem is a different one. */
  double pl2[2], ph1[2];
  sl_diag d = {{0}};
  CHECK(solve_and_measure(cell, order, 8, 0, &pl2[0], &ph1[0], &d) == 0);
  CHECK(solve_and_measure(cell, order, 16, 0, &pl2[1], &ph1[1], &d) == 0);
  printf("planar (wrong) %-4s L2 %.3e %.3e\n", name, pl2[0], pl2[1]);
  CHECK(pl2[1] > 0.5 * pl2[0] && pl2[1] > 100.0 * l2[1]);
}

int main(void) {
  run("Q1", SL_CELL_QUAD4, 1);
  run("Q2", SL_CELL_QUAD4, 2);
  run("P1", SL_CELL_TRI3, 1);
  run("P2", SL_CELL_TRI3, 2);
  return sl_test_summary();
}
