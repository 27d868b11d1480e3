/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Periodic boundary pairs in the transport:
 *  - a 2-D box [0, 1] x [0, 0.25] (quads) periodic left/right, uniform
 *    advection u = (1, 0), phi = 0.3 + 0.2 sin(2 pi x): after one period the
 *    profile is back; the L1 error falls at order 1 (Godunov) and about 2
 *    (MUSCL, MC limiter) under refinement, mass is conserved to round-off;
 *    the same on a 1-D periodic interval gives the same cell values;
 *  - the unit square on triangles, periodic both ways, advection along the
 *    diagonal u = (1, 1), phi = 0.3 + 0.2 sin(2 pi x) sin(2 pi y): after one
 *    period back to within the scheme's error, which falls at order 2 on
 *    "/" triangles; mass to round-off, bounds kept (union jack too); both
 *    pairs' translations;
 *  - errors: boundaries that do not match (a moved vertex: the face is
 *    named; different face counts; a boundary with itself; a boundary
 *    already paired; a radial translation in an axisymmetric geometry; an
 *    unknown name), and a periodic boundary cannot become a wall. */
#include <stdlib.h>

#include "core/mesh/mesh.h"
#include "core/transport/transport.h"
#include "testing.h"
#include "transport/transport_testing.h"

#define PHI_MAX 0.64

static sl_transport *open_t(const sl_mesh *m, int order, sl_transport_geometry geo) {
  sl_diag d;
  sl_transport *t;
  sl_transport_opts o = {.phi_max = PHI_MAX, .order = order, .geometry = geo, .settling = no_settling};
  if (sl_transport_create(m, &o, &t, &d)) die("transport", &d);
  return t;
}

typedef struct result {
  double l1, linf, mass_err, lo, hi;
  long substeps;
  int fallbacks;
} result;

/* Advances phi by T in outer steps of dt with the face fluxes of the uniform
 * velocity u, and compares with phi0. */
static result advect(sl_transport *t, const double u[2], double *phi, const double *phi0, double T, double dt) {
  sl_diag d;
  const sl_mesh *m = sl_transport_mesh(t);
  result r = {0};
  double *q = alloc(m->n_faces);
  sl_transport_settling_uniform(t, u, q); /* q_f = A_f u.n_f */
  double m0 = sl_transport_mass(t, phi);
  r.lo = HUGE_VAL, r.hi = -HUGE_VAL;
  int n = (int)lround(T / dt);
  for (int s = 0; s < n; ++s) {
    sl_transport_stats st;
    if (sl_transport_step(t, dt, q, NULL, phi, &st, &d)) die("step", &d);
    r.substeps += st.n_substeps;
    r.fallbacks += st.n_fallbacks;
    CHECK_MSG(st.max_divergence < 1e-13, "divergence %g", st.max_divergence);
    for (int c = 0; c < m->n_cells; ++c) r.lo = fmin(r.lo, phi[c]), r.hi = fmax(r.hi, phi[c]);
  }
  const double *v = sl_transport_volumes(t);
  double V = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double e = fabs(phi[c] - phi0[c]);
    r.l1 += v[c] * e, V += v[c];
    r.linf = fmax(r.linf, e);
  }
  r.l1 /= V;
  r.mass_err = fabs(sl_transport_mass(t, phi) - m0) / m0;
  free(q);
  return r;
}

/* Cell average of 0.3 + 0.2 sin(2 pi x) over [x0, x1]. */
static double sine_avg(double x0, double x1) {
  const double k = 2 * M_PI;
  return 0.3 + 0.2 * (cos(k * x0) - cos(k * x1)) / (k * (x1 - x0));
}

static void cell_x_range(const sl_mesh *m, int c, double *x0, double *x1) {
  *x0 = HUGE_VAL, *x1 = -HUGE_VAL;
  for (int k = 0; k < m->nv_per_cell; ++k) {
    double x = m->xy[2 * m->cell_vertices[(size_t)c * m->nv_per_cell + k]];
    *x0 = fmin(*x0, x), *x1 = fmax(*x1, x);
  }
}

static void test_box_orders(void) {
  const int ns[4] = {25, 50, 100, 200};
  const double u[2] = {1, 0};
  for (int order = 1; order <= 2; ++order) {
    double l1[4];
    for (int i = 0; i < 4; ++i) {
      sl_diag d;
      sl_mesh *m, *m1;
      if (sl_mesh_rectangle(0, 1, 0, 0.25, ns[i], 2, NULL, &m, &d)) die("mesh", &d);
      if (sl_mesh_interval(0, 1, ns[i], NULL, &m1, &d)) die("mesh", &d);
      sl_transport *t = open_t(m, order, SL_TRANSPORT_PLANAR), *t1 = open_t(m1, order, SL_TRANSPORT_PLANAR);
      CHECK(sl_transport_set_periodic_named(t, "left", "right", &d) == 0);
      CHECK(sl_transport_set_periodic_named(t1, "left", "right", &d) == 0);
      double s[2] = {0, 0};
      /* The pair's translation, left -> right, asked through either boundary. */
      CHECK(sl_transport_periodic_shift(t, 1, s, &d) == 0);
      CHECK_MSG(fabs(s[0] - 1) < 1e-15 && s[1] == 0, "shift of 'right' (%g, %g)", s[0], s[1]);
      CHECK(sl_transport_periodic_shift(t, 3, s, &d) == 0);
      CHECK_MSG(fabs(s[0] - 1) < 1e-15 && s[1] == 0, "shift of 'left' (%g, %g)", s[0], s[1]);
      CHECK(sl_transport_periodic_shift(t, 0, s, &d) == SL_EBADINPUT);
      double *phi = alloc(m->n_cells), *phi0 = alloc(m->n_cells), *p1 = alloc(ns[i]), *p10 = alloc(ns[i]);
      for (int c = 0; c < m->n_cells; ++c) {
        double x0, x1;
        cell_x_range(m, c, &x0, &x1);
        phi[c] = phi0[c] = sine_avg(x0, x1);
      }
      for (int c = 0; c < ns[i]; ++c) {
        double x0, x1;
        cell_x_range(m1, c, &x0, &x1);
        p1[c] = p10[c] = sine_avg(x0, x1);
      }
      /* Outer steps of 5 cells: 6 (order 1) or 12 (order 2) sub-steps each at every level, so the Courant
       * number (5/6, 5/12) is the same on every level. */
      double dt = 5.0 / ns[i];
      result r = advect(t, u, phi, phi0, 1.0, dt), r1 = advect(t1, u, p1, p10, 1.0, dt);
      /* Every row of the box equals the 1-D run. */
      double diff = 0;
      const double *xc = sl_transport_cell_points(t);
      for (int c = 0; c < m->n_cells; ++c) diff = fmax(diff, fabs(phi[c] - p1[(int)(xc[2 * c] * ns[i])]));
      l1[i] = r.l1;
      printf(
          "box %3dx2 quads, order %d, one period: L1 error %.3e, max %.3e, phi in [%.4f, %.4f], mass change %.1e, "
          "%ld sub-steps, %d fallbacks; rows against the 1-D periodic interval %.1e\n",
          ns[i], order, r.l1, r.linf, r.lo, r.hi, r.mass_err, r.substeps, r.fallbacks, diff);
      CHECK_MSG(r.mass_err < 1e-14, "mass changed by %.2e", r.mass_err);
      CHECK_MSG(r1.mass_err < 1e-14, "1-D mass changed by %.2e", r1.mass_err);
      CHECK_MSG(diff < 1e-13, "rows differ from the 1-D run by %.2e", diff);
      CHECK(r.lo >= 0.1 - 1e-12 && r.hi <= 0.5 + 1e-12 && r.fallbacks == 0);
      free(phi), free(phi0), free(p1), free(p10);
      sl_transport_destroy(t), sl_transport_destroy(t1);
      sl_mesh_destroy(m), sl_mesh_destroy(m1);
    }
    double o[3];
    for (int i = 0; i < 3; ++i) o[i] = log2(l1[i] / l1[i + 1]);
    printf("order %d: observed L1 orders %.2f, %.2f, %.2f\n", order, o[0], o[1], o[2]);
    if (order == 1) CHECK_MSG(o[1] > 0.85 && o[2] > 0.9, "order 1: %.2f %.2f", o[1], o[2]);
    else CHECK_MSG(o[1] > 1.7 && o[2] > 1.8, "order 2: %.2f %.2f", o[1], o[2]);
  }
}

static void test_doubly_periodic_triangles(void) {
  const int ns[3] = {16, 32, 64};
  const double u[2] = {1, 1};
  double l1[3];
  /* Uniform "/" diagonals: three levels for the order; union jack: one level, mass and bounds (its order:
   * test_transport_muscl.c). */
  for (int i = 0; i < 4; ++i) {
    sl_diag d;
    sl_mesh *m;
    int uj = i == 3, n = uj ? 32 : ns[i];
    sl_grid_opts go = {.cell_type = SL_CELL_TRI3, .diagonal = uj ? SL_DIAGONAL_UNION_JACK : SL_DIAGONAL_RIGHT};
    if (sl_mesh_rectangle(0, 1, 0, 1, n, n, &go, &m, &d)) die("mesh", &d);
    sl_transport *t = open_t(m, 2, SL_TRANSPORT_PLANAR);
    CHECK(sl_transport_set_periodic_named(t, "left", "right", &d) == 0);
    CHECK(sl_transport_set_periodic_named(t, "bottom", "top", &d) == 0);
    double s[2];
    CHECK(sl_transport_periodic_shift(t, 2, s, &d) == 0 && fabs(s[1] - 1) < 1e-15 && s[0] == 0);
    double *phi = alloc(m->n_cells), *phi0 = alloc(m->n_cells);
    const double *xc = sl_transport_cell_points(t);
    for (int c = 0; c < m->n_cells; ++c)
      phi[c] = phi0[c] = 0.3 + 0.2 * sin(2 * M_PI * xc[2 * c]) * sin(2 * M_PI * xc[2 * c + 1]);
    result r = advect(t, u, phi, phi0, 1.0, 0.1);
    if (!uj) l1[i] = r.l1;
    printf(
        "unit square, %d^2 x 2 %s triangles, doubly periodic, u = (1, 1), order 2, one period: L1 error "
        "%.3e, max %.3e, phi in [%.4f, %.4f], mass change %.1e, %ld sub-steps, %d fallbacks\n",
        n, uj ? "union-jack" : "\"/\"", r.l1, r.linf, r.lo, r.hi, r.mass_err, r.substeps, r.fallbacks);
    CHECK_MSG(r.mass_err < 1e-14, "mass changed by %.2e", r.mass_err);
    CHECK(r.lo >= 0.1 - 1e-12 && r.hi <= 0.5 + 1e-12);
    free(phi), free(phi0);
    sl_transport_destroy(t);
    sl_mesh_destroy(m);
  }
  double o1 = log2(l1[0] / l1[1]), o2 = log2(l1[1] / l1[2]);
  printf("doubly periodic \"/\" triangles: observed L1 orders %.2f, %.2f\n", o1, o2);
  CHECK_MSG(o1 > 1.8 && o2 > 1.8, "L1 orders %.2f, %.2f", o1, o2);
}

static void test_errors(void) {
  sl_diag d;
  sl_mesh *m;
  /* A moved vertex on 'right': its faces have no partner. */
  if (sl_mesh_rectangle(0, 2, 0, 1, 4, 8, NULL, &m, &d)) die("mesh", &d);
  for (int v = 0; v < m->n_vertices; ++v)
    if (m->xy[2 * v] == 2 && fabs(m->xy[2 * v + 1] - 0.5) < 1e-12) m->xy[2 * v + 1] = 0.5 + 1e-6;
  sl_transport *t = open_t(m, 2, SL_TRANSPORT_PLANAR);
  int rc = sl_transport_set_periodic_named(t, "left", "right", &d);
  printf("moved vertex: %s\n", d.msg);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'left' / 'right'");
  CHECK_CONTAINS(d.msg, "the node (2, 0.500001) of 'right' has no partner on 'left' at (0, 0.500001)");
  /* The same vertex moved across the boundary (x): the misplaced node is the one named. */
  for (int v = 0; v < m->n_vertices; ++v)
    if (fabs(m->xy[2 * v] - 2) < 1e-12 && fabs(m->xy[2 * v + 1] - 0.5) < 1e-5)
      m->xy[2 * v + 1] = 0.5, m->xy[2 * v] = 2 + 1e-6;
  rc = sl_transport_set_periodic_named(t, "left", "right", &d);
  printf("moved vertex, across: %s\n", d.msg);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "the node (2.000001, 0.5) of 'right' has no partner on 'left'");
  /* The failed pairings changed nothing: 'left' is not periodic. */
  CHECK(sl_transport_set_boundary(t, 3, SL_TRANSPORT_OPEN, 0.1, &d) == 0);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);

  if (sl_mesh_rectangle(0, 2, 0, 1, 4, 3, NULL, &m, &d)) die("mesh", &d);
  t = open_t(m, 2, SL_TRANSPORT_PLANAR);
  rc = sl_transport_set_periodic_named(t, "bottom", "left", &d);
  printf("different counts: %s\n", d.msg);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'bottom' has 5 nodes and 4 faces, 'left' 4 nodes and 3 faces");
  CHECK(sl_transport_set_periodic(t, 1, 1, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "with itself");
  CHECK(sl_transport_set_periodic(t, 1, 7, &d) == SL_EBADINPUT);
  rc = sl_transport_set_periodic_named(t, "left", "rigth", &d);
  printf("unknown name: %s\n", d.msg);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "right");
  /* bottom/top match; then each is taken. */
  CHECK(sl_transport_set_periodic_named(t, "bottom", "top", &d) == 0);
  CHECK(sl_transport_set_periodic_named(t, "top", "left", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'top' is already periodic");
  CHECK(sl_transport_set_boundary(t, 0, SL_TRANSPORT_WALL, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'bottom' is periodic");
  sl_transport_destroy(t);
  sl_mesh_destroy(m);

  /* An axisymmetric annulus: inner/outer would be a radial translation. */
  if (sl_mesh_annulus(0.5, 1, 0, 1, 3, 3, NULL, &m, &d)) die("mesh", &d);
  t = open_t(m, 2, SL_TRANSPORT_AXISYMMETRIC);
  rc = sl_transport_set_periodic_named(t, "inner", "outer", &d);
  printf("radial pair: %s\n", d.msg);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "along z");
  CHECK(sl_transport_set_periodic_named(t, "bottom", "top", &d) == 0); /* along z: fine */
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
}

int main(void) {
  test_box_orders();
  test_doubly_periodic_triangles();
  test_errors();
  return sl_test_summary();
}
