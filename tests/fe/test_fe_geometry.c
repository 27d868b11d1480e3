/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The integration context: areas, physical gradients, quadrature points on
 * affine and bilinear cells, the axisymmetric r weighting, and refusals. */
#include <math.h>

#include "core/fe/geometry.h"
#include "testing.h"

/* Sum over cells and points of JxW g(x, y). */
static double integrate(sl_fe_values *fv, double (*g)(const double x[2])) {
  double s = 0.0;
  for (int c = 0; c < fv->mesh->n_cells; ++c) {
    if (sl_fe_values_reinit(fv, c, NULL)) return NAN;
    for (int q = 0; q < fv->quad.n; ++q) s += fv->JxW[q] * g(fv->x[q]);
  }
  return s;
}

static double one(const double x[2]) {
  (void)x;
  return 1.0;
}
static double x_times_y2(const double x[2]) { return x[0] * x[1] * x[1]; }

/* The inclined box is made of parallelograms; rotating it changes nothing. */
static void test_areas(void) {
  const sl_cell_type types[] = {SL_CELL_QUAD4, SL_CELL_TRI3};
  for (int t = 0; t < 2; ++t) {
    sl_grid_opts o = {.cell_type = types[t], .grade_x = {SL_GRADE_GEOMETRIC, 3.0}};
    sl_mesh *m;
    CHECK(sl_mesh_inclined_box(0.5, -0.25, 2.0, 1.5, 0.3, 5, 4, &o, &m, NULL) == 0);
    const sl_element *p1 = sl_element_lagrange(types[t], 1);
    sl_fe_values *fv;
    CHECK(sl_fe_values_create(&fv, m, 1, &p1, 2, 0, NULL) == 0);
    CHECK_CLOSE(integrate(fv, one), 3.0, 1e-13);
    for (int c = 0; c < m->n_cells; ++c) {
      sl_fe_values_reinit(fv, c, NULL);
      double a = 0.0;
      for (int q = 0; q < fv->quad.n; ++q) a += fv->JxW[q];
      CHECK_CLOSE(a, sl_mesh_cell_area(m, c), 1e-13);
    }
    sl_fe_values_destroy(fv);
    sl_mesh_destroy(m);
  }
}

/* On a genuinely bilinear (non-parallelogram) quad the physical gradients
 * of the Q1/Q2 interpolants of linear functions are exact. */
static void test_gradients_bilinear(void) {
  const double xy[] = {0.0, 0.0, 2.0, 0.1, 1.7, 1.9, -0.2, 1.0};
  const int cv[] = {0, 1, 2, 3};
  const char *names[] = {"wall"};
  const int sides[] = {0, 1, 1, 2, 2, 3, 3, 0}, tags[] = {0, 0, 0, 0};
  sl_mesh_spec s = {.dim = 2,
                    .cell_type = SL_CELL_QUAD4,
                    .n_vertices = 4,
                    .xy = xy,
                    .n_cells = 1,
                    .cell_vertices = cv,
                    .n_boundaries = 1,
                    .boundary_names = names,
                    .n_sides = 4,
                    .side_vertices = sides,
                    .side_tag = tags};
  sl_mesh *m;
  CHECK(sl_mesh_create(&s, &m, NULL) == 0);
  const sl_element *sp[2] = {sl_element_lagrange(SL_CELL_QUAD4, 2), sl_element_lagrange(SL_CELL_QUAD4, 1)};
  sl_fe_values *fv;
  CHECK(sl_fe_values_create(&fv, m, 2, sp, 4, 0, NULL) == 0);
  CHECK(sl_fe_values_reinit(fv, 0, NULL) == 0);
  double worst = 0.0, worst_x = 0.0;
  for (int s2 = 0; s2 < 2; ++s2)
    for (int q = 0; q < fv->quad.n; ++q) {
      double g[2] = {0.0, 0.0}, xq[2] = {0.0, 0.0};
      for (int b = 0; b < sp[s2]->n_basis; ++b) {
        double xn[2];
        sl_fe_map_point(m, 0, sp[s2]->nodes[b], xn);
        double u = 3.0 * xn[0] - 2.0 * xn[1] + 1.0; /* u = 3x - 2y + 1 */
        g[0] += u * fv->grad[s2][q][b][0], g[1] += u * fv->grad[s2][q][b][1];
        xq[0] += fv->phi[s2][q][b] * xn[0], xq[1] += fv->phi[s2][q][b] * xn[1];
      }
      worst = fmax(worst, fabs(g[0] - 3.0) + fabs(g[1] + 2.0));
      worst_x = fmax(worst_x, fabs(xq[0] - fv->x[q][0]) + fabs(xq[1] - fv->x[q][1]));
      /* det J against J's entries, and J^-T grad at the corner-free points. */
      CHECK_CLOSE(fv->detJ[q], fv->J[q][0][0] * fv->J[q][1][1] - fv->J[q][0][1] * fv->J[q][1][0], 1e-14);
    }
  CHECK_MSG(worst < 1e-12, "bilinear quad: gradient of a linear function off by %g", worst);
  CHECK_MSG(worst_x < 1e-14, "isoparametric interpolation of x off by %g", worst_x);
  /* The area of the quad, by the shoelace formula. */
  double a = 0.0;
  for (int q = 0; q < fv->quad.n; ++q) a += fv->JxW[q];
  CHECK_CLOSE(a, sl_mesh_cell_area(m, 0), 1e-14);
  sl_fe_values_destroy(fv);
  sl_mesh_destroy(m);
}

/* int over [1, 3] x [0, 2] of x y^2 (r weighted: of r^2 z^2) and of r. */
static void test_axisymmetric(void) {
  const sl_cell_type types[] = {SL_CELL_QUAD4, SL_CELL_TRI3};
  for (int t = 0; t < 2; ++t) {
    sl_grid_opts o = {.cell_type = types[t]};
    sl_mesh *m;
    CHECK(sl_mesh_annulus(1.0, 3.0, 0.0, 2.0, 3, 2, &o, &m, NULL) == 0);
    const sl_element *p2 = sl_element_lagrange(types[t], 2);
    sl_fe_values *planar, *axi;
    CHECK(sl_fe_values_create(&planar, m, 1, &p2, 4, 0, NULL) == 0);
    CHECK(sl_fe_values_create(&axi, m, 1, &p2, 4, 1, NULL) == 0);
    CHECK_CLOSE(integrate(planar, x_times_y2), 4.0 * 8.0 / 3.0, 1e-13);     /* (9-1)/2 * 8/3 */
    CHECK_CLOSE(integrate(axi, one), 8.0, 1e-13);                           /* (9-1)/2 * 2 */
    CHECK_CLOSE(integrate(axi, x_times_y2), 26.0 / 3.0 * 8.0 / 3.0, 1e-13); /* (27-1)/3 * 8/3 */
    sl_fe_values_destroy(planar);
    sl_fe_values_destroy(axi);
    sl_mesh_destroy(m);
  }
}

static void test_line(void) {
  sl_mesh *m;
  sl_grading g = {SL_GRADE_GEOMETRIC, 4.0};
  CHECK(sl_mesh_interval(1.0, 2.0, 7, &g, &m, NULL) == 0);
  const sl_element *p2 = sl_element_lagrange(SL_CELL_LINE2, 2);
  sl_fe_values *fv;
  CHECK(sl_fe_values_create(&fv, m, 1, &p2, 5, 1, NULL) == 0);
  CHECK_CLOSE(integrate(fv, one), 1.5, 1e-14); /* int_1^2 r dr */
  /* Gradients of the P2 basis sum to zero and map by 1/J. */
  sl_fe_values_reinit(fv, 3, NULL);
  double h = m->xy[2 * 4] - m->xy[2 * 3];
  CHECK_CLOSE(fv->detJ[0], 0.5 * h, 1e-14);
  CHECK_CLOSE(fv->grad[0][0][1][0], fv->dphi_ref[0][0][1][0] * 2.0 / h, 1e-14);
  sl_fe_values_destroy(fv);
  sl_mesh_destroy(m);
}

static void test_refusals(void) {
  sl_mesh *m;
  sl_diag d;
  CHECK(sl_mesh_rectangle(-1.0, 1.0, 0.0, 1.0, 2, 2, NULL, &m, NULL) == 0);
  const sl_element *tri = sl_element_lagrange(SL_CELL_TRI3, 1), *q1 = sl_element_lagrange(SL_CELL_QUAD4, 1);
  sl_fe_values *fv = NULL;
  CHECK(sl_fe_values_create(&fv, m, 1, &tri, 2, 0, &d) == SL_EBADINPUT && fv == NULL);
  CHECK_CONTAINS(d.msg, "quad");
  CHECK(sl_fe_values_create(&fv, m, 1, &q1, 99, 0, &d) == SL_EBADINPUT);
  CHECK(sl_fe_values_create(&fv, m, 1, &q1, 2, 1, &d) == 0);
  CHECK(sl_fe_values_reinit(fv, 0, &d) == SL_EBADINPUT); /* x < 0 with r weighting */
  CHECK_CONTAINS(d.msg, "r = ");
  sl_fe_values_destroy(fv);
  sl_mesh_destroy(m);
}

int main(void) {
  test_areas();
  test_gradients_bilinear();
  test_axisymmetric();
  test_line();
  test_refusals();
  return sl_test_summary();
}
