/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Generators: counts, Euler, exact areas and boundary lengths, grading,
 * normals, names. */
#include "mesh_checks.h"

static sl_diag d;

static void test_interval(void) {
  sl_mesh *m;
  CHECK(sl_mesh_interval(0.5, 2.5, 10, NULL, &m, &d) == 0);
  if (!m) return;
  CHECK(m->dim == 1 && m->cell_type == SL_CELL_LINE2 && m->nv_per_cell == 2 && m->nf_per_cell == 2);
  CHECK(m->n_vertices == 11 && m->n_cells == 10 && m->n_faces == 11 && m->n_boundary_faces == 2);
  CHECK(m->n_boundaries == 2 && strcmp(m->boundary_names[0], "left") == 0 &&
        strcmp(m->boundary_names[1], "right") == 0);
  CHECK(m->n_regions == 0 && m->cell_region == NULL);
  CHECK_CLOSE(total_area(m), 2.0, 1e-15);
  check_mesh_invariants(m);
  /* The boundary faces are the end points, with outward normals -1 and +1. */
  int f = m->bface[m->bface_start[0]];
  double n[2], c[2];
  sl_mesh_face_normal(m, f, n);
  sl_mesh_face_centroid(m, f, c);
  CHECK(n[0] == -1 && c[0] == 0.5);
  f = m->bface[m->bface_start[1]];
  sl_mesh_face_normal(m, f, n);
  sl_mesh_face_centroid(m, f, c);
  CHECK(n[0] == 1 && c[0] == 2.5);
  CHECK(sl_mesh_face_length(m, f) == 1.0);
  /* Interior faces point from the owner (left cell) to the right. */
  int ok = 1;
  for (f = 0; f < m->n_faces; ++f)
    if (m->face_cells[2 * f + 1] >= 0) {
      sl_mesh_face_normal(m, f, n);
      ok &= n[0] == 1 && m->face_cells[2 * f + 1] == m->face_cells[2 * f] + 1;
      ok &= m->face_vertices[2 * f + 1] == -1;
    }
  CHECK(ok);
  sl_mesh_destroy(m);
}

/* h_last / h_first and h_mid / h_end of graded point sets. */
static void test_grading(void) {
  double x[41];
  sl_grading g = {SL_GRADE_GEOMETRIC, 5.0};
  CHECK(sl_mesh_graded_points(1.0, 3.0, 8, &g, x, &d) == 0);
  CHECK(x[0] == 1.0 && x[8] == 3.0);
  CHECK_CLOSE((x[8] - x[7]) / (x[1] - x[0]), 5.0, 1e-12);
  int mono = 1;
  for (int i = 1; i < 8; ++i) mono &= (x[i + 1] - x[i]) > (x[i] - x[i - 1]);
  CHECK(mono);

  g.ratio = 0.1; /* refines towards the end */
  CHECK(sl_mesh_graded_points(0.0, 1.0, 40, &g, x, &d) == 0);
  CHECK_CLOSE((x[40] - x[39]) / (x[1] - x[0]), 0.1, 1e-12);

  g = (sl_grading){SL_GRADE_SYMMETRIC, 4.0};
  for (int n = 9; n <= 10; ++n) { /* odd and even counts */
    CHECK(sl_mesh_graded_points(-1.0, 2.0, n, &g, x, &d) == 0);
    int mid = (n - 1) / 2;
    CHECK_CLOSE((x[mid + 1] - x[mid]) / (x[1] - x[0]), 4.0, 1e-12);
    CHECK_CLOSE((x[n] - x[n - 1]) / (x[1] - x[0]), 1.0, 1e-12);
    int sym = 1;
    for (int i = 0; i <= n; ++i) sym &= fabs((x[i] - -1.0) - (2.0 - x[n - i])) < 1e-15;
    CHECK(sym);
  }

  g = (sl_grading){SL_GRADE_GEOMETRIC, 1.0}; /* ratio 1 is uniform */
  CHECK(sl_mesh_graded_points(0.0, 1.0, 4, &g, x, &d) == 0);
  CHECK(x[1] == 0.25 && x[2] == 0.5 && x[3] == 0.75);

  /* Bad parameters. */
  g = (sl_grading){SL_GRADE_GEOMETRIC, -2.0};
  CHECK(sl_mesh_graded_points(0.0, 1.0, 4, &g, x, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "positive");
  g = (sl_grading){SL_GRADE_SYMMETRIC, 2.0};
  CHECK(sl_mesh_graded_points(0.0, 1.0, 2, &g, x, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "at least 3");
  CHECK(sl_mesh_graded_points(1.0, 1.0, 2, NULL, x, &d) == SL_EBADINPUT);

  /* A graded interval reproduces the ratio in its cell lengths. */
  sl_mesh *m;
  g = (sl_grading){SL_GRADE_GEOMETRIC, 0.25};
  CHECK(sl_mesh_interval(0.0, 1.0, 12, &g, &m, &d) == 0);
  if (m) {
    CHECK_CLOSE(sl_mesh_cell_area(m, 11) / sl_mesh_cell_area(m, 0), 0.25, 1e-12);
    CHECK_CLOSE(total_area(m), 1.0, 1e-15);
    sl_mesh_quality q;
    sl_mesh_quality_compute(m, &q);
    CHECK_CLOSE(q.max_size_jump, pow(4.0, 1.0 / 11), 1e-12);
    sl_mesh_destroy(m);
  }
}

/* The rectangle in quads and in the three triangle patterns. */
static void test_rectangle(void) {
  const double x0 = 0.1, x1 = 2.3, y0 = -1.0, y1 = 0.7;
  const int nx = 7, ny = 5;
  sl_grid_opts o[4] = {{.cell_type = SL_CELL_QUAD4},
                       {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_RIGHT},
                       {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_LEFT},
                       {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK}};
  for (int k = 0; k < 4; ++k) {
    sl_mesh *m;
    CHECK(sl_mesh_rectangle(x0, x1, y0, y1, nx, ny, &o[k], &m, &d) == 0);
    if (!m) continue;
    int tri = k > 0;
    CHECK(m->dim == 2 && m->cell_type == (tri ? SL_CELL_TRI3 : SL_CELL_QUAD4));
    CHECK(m->n_vertices == (nx + 1) * (ny + 1));
    CHECK(m->n_cells == nx * ny * (tri ? 2 : 1));
    CHECK(m->n_faces == nx * (ny + 1) + ny * (nx + 1) + (tri ? nx * ny : 0));
    CHECK(m->n_boundary_faces == 2 * (nx + ny));
    CHECK(euler(m) == 1);
    CHECK_CLOSE(total_area(m), (x1 - x0) * (y1 - y0), 1e-14);
    CHECK_CLOSE(boundary_length(m, "bottom"), x1 - x0, 1e-14);
    CHECK_CLOSE(boundary_length(m, "top"), x1 - x0, 1e-14);
    CHECK_CLOSE(boundary_length(m, "left"), y1 - y0, 1e-14);
    CHECK_CLOSE(boundary_length(m, "right"), y1 - y0, 1e-14);
    CHECK(boundary_count(m, "bottom") == nx && boundary_count(m, "left") == ny);
    check_mesh_invariants(m);
    /* Boundary normals are the axis directions. */
    int id, ok = 1;
    const char *names[4] = {"bottom", "right", "top", "left"};
    const double want[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (int b = 0; b < 4; ++b) {
      CHECK(sl_mesh_boundary_id(m, names[b], &id, &d) == 0 && id == b);
      for (int i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) {
        double n[2];
        sl_mesh_face_normal(m, m->bface[i], n);
        ok &= n[0] == want[b][0] && n[1] == want[b][1];
      }
    }
    CHECK(ok);
    /* Area-weighted centroids give the box's centroid. */
    double sx = 0, sy = 0, c[2];
    for (int i = 0; i < m->n_cells; ++i) {
      sl_mesh_cell_centroid(m, i, c);
      sx += sl_mesh_cell_area(m, i) * c[0];
      sy += sl_mesh_cell_area(m, i) * c[1];
    }
    double a = (x1 - x0) * (y1 - y0);
    CHECK_CLOSE(sx / a, 0.5 * (x0 + x1), 1e-13);
    CHECK_CLOSE(sy / a, 0.5 * (y0 + y1), 1e-13);
    sl_mesh_quality q;
    sl_mesh_quality_compute(m, &q);
    CHECK_CLOSE(q.min_area, q.max_area, 1e-12);
    if (!tri) CHECK_CLOSE(q.min_angle, acos(-1.0) / 2, 1e-12);
    sl_mesh_destroy(m);
  }

  /* The union jack alternates the diagonal: cell (0,0) "/" and (1,0) "\". */
  sl_mesh *m;
  CHECK(sl_mesh_rectangle(0, 2, 0, 1, 2, 1, &o[3], &m, &d) == 0);
  if (m) {
    /* vertices 0 1 2 / 3 4 5: "/" joins 0-4, "\" joins 2-4 */
    int has04 = 0, has24 = 0;
    for (int f = 0; f < m->n_faces; ++f) {
      int a = m->face_vertices[2 * f], b = m->face_vertices[2 * f + 1];
      has04 |= (a == 0 && b == 4) || (a == 4 && b == 0);
      has24 |= (a == 2 && b == 4) || (a == 4 && b == 2);
    }
    CHECK(has04 && has24);
    sl_mesh_destroy(m);
  }
}

static void test_graded_rectangle(void) {
  sl_grid_opts o = {
      .cell_type = SL_CELL_QUAD4, .grade_x = {SL_GRADE_GEOMETRIC, 0.2}, .grade_y = {SL_GRADE_SYMMETRIC, 3.0}};
  sl_mesh *m;
  CHECK(sl_mesh_rectangle(0, 1, 0, 2, 10, 9, &o, &m, &d) == 0);
  if (!m) return;
  CHECK_CLOSE(total_area(m), 2.0, 1e-14);
  check_mesh_invariants(m);
  /* Cells are numbered row by row: (i, j) is j nx + i. */
  double w0 = sl_mesh_cell_area(m, 0), w9 = sl_mesh_cell_area(m, 9);
  CHECK_CLOSE(w9 / w0, 0.2, 1e-12);
  double h0 = sl_mesh_cell_area(m, 0), h4 = sl_mesh_cell_area(m, 4 * 10), h8 = sl_mesh_cell_area(m, 8 * 10);
  CHECK_CLOSE(h4 / h0, 3.0, 1e-12);
  CHECK_CLOSE(h8 / h0, 1.0, 1e-12);
  sl_mesh_destroy(m);
}

static void test_annulus(void) {
  const double pi = acos(-1.0);
  for (int axis = 0; axis < 2; ++axis) {
    double ri = axis ? 0.0 : 0.3, ro = 1.2, z0 = -0.5, z1 = 1.5;
    for (int tri = 0; tri < 2; ++tri) {
      sl_grid_opts o = {.cell_type = tri ? SL_CELL_TRI3 : SL_CELL_QUAD4, .grade_x = {SL_GRADE_GEOMETRIC, 0.5}};
      sl_mesh *m;
      CHECK(sl_mesh_annulus(ri, ro, z0, z1, 6, 8, &o, &m, &d) == 0);
      if (!m) continue;
      int id;
      CHECK(sl_mesh_boundary_id(m, axis ? "axis" : "inner", &id, &d) == 0 && id == 3);
      CHECK(sl_mesh_boundary_id(m, axis ? "inner" : "axis", &id, &d) == SL_EBADINPUT);
      CHECK(sl_mesh_boundary_id(m, "outer", &id, &d) == 0 && id == 1);
      CHECK_CLOSE(total_area(m), (ro - ri) * (z1 - z0), 1e-14);
      CHECK_CLOSE(boundary_length(m, "outer"), z1 - z0, 1e-14);
      CHECK_CLOSE(boundary_length(m, "bottom"), ro - ri, 1e-14);
      CHECK(euler(m) == 1);
      check_mesh_invariants(m);
      /* Pappus: the volume of revolution is 2 pi sum(r_centroid A), exact
       * for polygons: pi (ro^2 - ri^2) (z1 - z0). */
      ksum v = {0, 0};
      for (int c = 0; c < m->n_cells; ++c) {
        double cc[2];
        sl_mesh_cell_centroid(m, c, cc);
        ksum_add(&v, 2 * pi * cc[0] * sl_mesh_cell_area(m, c));
      }
      CHECK_CLOSE(v.s, pi * (ro * ro - ri * ri) * (z1 - z0), 1e-13);
      sl_mesh_destroy(m);
    }
  }
  sl_mesh *m;
  CHECK(sl_mesh_annulus(-0.1, 1, 0, 1, 2, 2, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "inner radius");
}

static void test_inclined(void) {
  const double pi = acos(-1.0), a = pi / 4, W = 0.3, H = 1.1, x0 = 1.0, y0 = -2.0;
  sl_mesh *m;
  CHECK(sl_mesh_inclined_box(x0, y0, W, H, a, 6, 20, NULL, &m, &d) == 0);
  if (!m) return;
  CHECK(m->n_cells == 120 && m->n_vertices == 7 * 21);
  CHECK_CLOSE(total_area(m), W * H, 1e-14);
  CHECK_CLOSE(boundary_length(m, "bottom"), W, 1e-14);
  CHECK_CLOSE(boundary_length(m, "left"), H, 1e-14);
  CHECK_CLOSE(boundary_length(m, "top"), W, 1e-14);
  CHECK_CLOSE(boundary_length(m, "right"), H, 1e-14);
  CHECK(euler(m) == 1);
  check_mesh_invariants(m);
  /* The corners: (x0, y0) fixed; the bottom-right at (x0 + W cos a, y0 + W sin a). */
  CHECK(m->xy[0] == x0 && m->xy[1] == y0);
  CHECK_CLOSE(m->xy[2 * 6], x0 + W * cos(a), 1e-15);
  CHECK_CLOSE(m->xy[2 * 6 + 1], y0 + W * sin(a), 1e-14);
  /* The rotated bottom's outward normal is (sin a, -cos a). */
  int ok = 1;
  for (int i = m->bface_start[0]; i < m->bface_start[1]; ++i) {
    double n[2];
    sl_mesh_face_normal(m, m->bface[i], n);
    ok &= fabs(n[0] - sin(a)) < 1e-14 && fabs(n[1] + cos(a)) < 1e-14;
  }
  CHECK(ok);
  sl_mesh_destroy(m);
  CHECK(sl_mesh_inclined_box(0, 0, -1, 1, a, 2, 2, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
}

static void test_bad_arguments(void) {
  sl_mesh *m;
  CHECK(sl_mesh_interval(0, 1, 0, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "number of cells");
  CHECK(sl_mesh_interval(1, 0, 3, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK(sl_mesh_rectangle(0, 1, 0, 1, 0, 3, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK(sl_mesh_rectangle(0, 1, 1, 1, 3, 3, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "rectangle");
  sl_grid_opts o = {.grade_y = {SL_GRADE_GEOMETRIC, 0}};
  CHECK(sl_mesh_rectangle(0, 1, 0, 1, 3, 3, &o, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "ratio");
  CHECK(sl_mesh_rectangle(0, 1, 0, 1, 100000, 100000, NULL, &m, &d) == SL_EBADINPUT && m == NULL);
}

int main(void) {
  test_interval();
  test_grading();
  test_rectangle();
  test_graded_rectangle();
  test_annulus();
  test_inclined();
  test_bad_arguments();
  return sl_test_summary();
}
