/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sl_mesh_create from arrays: refusal of inverted, degenerate, overlapping
 * and untagged meshes; name look-up with did-you-mean; quality report. */
#define _POSIX_C_SOURCE 200809L /* open_memstream */
#include <stdio.h>

#include "mesh_checks.h"

static sl_diag d;
static const char *const walls[] = {"wall", "inlet"};

/* Two triangles on the unit square, diagonal 0-2; all sides "wall". */
static const double sq_xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
static const int sq_sides[] = {0, 1, 1, 2, 2, 3, 3, 0};
static const int sq_tags[] = {0, 0, 1, 0};

static int make(const double *xy, int nv, sl_cell_type t, const int *cells, int nc, const int *sides, const int *tags,
                int ns, sl_mesh **m) {
  sl_mesh_spec s = {.dim = 2,
                    .cell_type = t,
                    .n_vertices = nv,
                    .xy = xy,
                    .n_cells = nc,
                    .cell_vertices = cells,
                    .n_boundaries = 2,
                    .boundary_names = walls,
                    .n_sides = ns,
                    .side_vertices = sides,
                    .side_tag = tags};
  return sl_mesh_create(&s, m, &d);
}

static void test_valid(void) {
  const int cells[] = {0, 1, 2, 0, 2, 3};
  sl_mesh *m;
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, sq_sides, sq_tags, 4, &m) == 0);
  if (!m) return;
  CHECK(m->n_faces == 5 && m->n_boundary_faces == 4);
  check_mesh_invariants(m);
  CHECK(boundary_count(m, "inlet") == 1 && boundary_count(m, "wall") == 3);
  CHECK_CLOSE(total_area(m), 1.0, 1e-15);
  /* The interior face (the diagonal) is owned by cell 0, below it: normal (-1, 1)/sqrt2. */
  int ok = 0;
  for (int f = 0; f < m->n_faces; ++f)
    if (m->face_cells[2 * f + 1] >= 0) {
      double n[2];
      sl_mesh_face_normal(m, f, n);
      ok = m->face_cells[2 * f] == 0 && m->face_cells[2 * f + 1] == 1 && fabs(n[0] + sqrt(0.5)) < 1e-15 &&
           fabs(n[1] - sqrt(0.5)) < 1e-15 && fabs(sl_mesh_face_length(m, f) - sqrt(2.0)) < 1e-15;
    }
  CHECK(ok);
  sl_mesh_quality q;
  sl_mesh_quality_compute(m, &q);
  CHECK_CLOSE(q.min_angle, acos(-1.0) / 4, 1e-14);
  CHECK_CLOSE(q.max_angle, acos(-1.0) / 2, 1e-14);
  CHECK_CLOSE(q.max_aspect, sqrt(2.0), 1e-14);
  CHECK_CLOSE(q.min_area, 0.5, 1e-15);
  CHECK(sl_mesh_check(m, &d) == 0);

  /* The report. */
  char *buf = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&buf, &len);
  CHECK(f != NULL);
  if (f) {
    sl_mesh_print_report(m, f);
    fclose(f);
    CHECK_CONTAINS(buf, "2 tri3 cells, 4 vertices, 5 faces (4 on the boundary)");
    CHECK_CONTAINS(buf, "wall (3 faces, length 3)");
    CHECK_CONTAINS(buf, "inlet (1 face, length 1)");
    CHECK_CONTAINS(buf, "angles 45 .. 90 deg");
    CHECK_CONTAINS(buf, "max aspect ratio 1.414");
    free(buf);
  }

  /* Moving a vertex through the diagonal inverts cell 1. */
  m->xy[2 * 3] = 2.0, m->xy[2 * 3 + 1] = 0.5;
  CHECK(sl_mesh_check(m, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "cell 1 is inverted");
  CHECK_CONTAINS(d.msg, "3 (2, 0.5)");
  sl_mesh_destroy(m);
}

static void test_names(void) {
  sl_mesh *m;
  CHECK(sl_mesh_rectangle(0, 1, 0, 1, 2, 2, NULL, &m, &d) == 0);
  if (!m) return;
  int id = 7;
  CHECK(sl_mesh_boundary_id(m, "top", &id, &d) == 0 && id == 2);
  CHECK(sl_mesh_boundary_id(m, "Top", &id, &d) == SL_EBADINPUT && id == -1);
  CHECK_CONTAINS(d.msg, "no boundary named \"Top\"");
  CHECK_CONTAINS(d.msg, "did you mean \"top\"?");
  CHECK_CONTAINS(d.msg, "(boundaries: bottom, right, top, left)");
  CHECK(sl_mesh_boundary_id(m, "rigth", &id, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean \"right\"?");
  CHECK(sl_mesh_boundary_id(m, "botom", &id, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean \"bottom\"?");
  CHECK(sl_mesh_boundary_id(m, "inflow_port", &id, &d) == SL_EBADINPUT);
  CHECK(strstr(d.msg, "did you mean") == NULL);
  CHECK(sl_mesh_region_id(m, "fluid", &id, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no regions");
  sl_mesh_destroy(m);
}

static void test_refused(void) {
  sl_mesh *m;
  /* Clockwise triangle 1: inverted, named with its coordinates. */
  const int inv[] = {0, 1, 2, 0, 3, 2};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, inv, 2, sq_sides, sq_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 1 is inverted");
  CHECK_CONTAINS(d.msg, "0 (0, 0), 3 (0, 1), 2 (1, 1)");

  /* A triangle with three collinear vertices: degenerate. */
  const double line_xy[] = {0, 0, 1, 0, 2, 0};
  const int deg[] = {0, 1, 2};
  const int deg_sides[] = {0, 1, 1, 2, 2, 0}, deg_tags[] = {0, 0, 0};
  CHECK(make(line_xy, 3, SL_CELL_TRI3, deg, 1, deg_sides, deg_tags, 3, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 0 is degenerate");
  CHECK_CONTAINS(d.msg, "2 (2, 0)");

  /* A repeated vertex: zero-length edge. */
  const int rep[] = {0, 1, 1, 0, 2, 3};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, rep, 2, sq_sides, sq_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 0 is degenerate");

  /* A non-convex ("arrow") quad: negative Jacobian at the re-entrant corner. */
  const double arrow_xy[] = {0, 0, 1, 0.5, 2, 0, 1, 2};
  const int arrow[] = {0, 1, 2, 3};
  const int arrow_sides[] = {0, 1, 1, 2, 2, 3, 3, 0}, arrow_tags[] = {0, 0, 0, 0};
  CHECK(make(arrow_xy, 4, SL_CELL_QUAD4, arrow, 1, arrow_sides, arrow_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 0 is inverted (negative Jacobian at its local vertex 1");
  /* A bow-tie quad. */
  const int bow[] = {0, 1, 2, 3};
  const double bow_xy[] = {0, 0, 1, 1, 1, 0, 0, 1};
  CHECK(make(bow_xy, 4, SL_CELL_QUAD4, bow, 1, arrow_sides, arrow_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "inverted");

  /* Two triangles on the same side of an edge: overlap. */
  const double ov_xy[] = {0, 0, 1, 0, 0.5, 1, 0.5, 0.5};
  const int ov[] = {0, 1, 2, 0, 1, 3};
  const int ov_sides[] = {0, 1}, ov_tags[] = {0};
  CHECK(make(ov_xy, 4, SL_CELL_TRI3, ov, 2, ov_sides, ov_tags, 1, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cells 0 and 1 overlap");

  /* Three triangles on one edge. */
  const double fan_xy[] = {0, 0, 1, 0, 0.5, 1, 0.5, -1, 0.5, 2};
  const int fan[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  CHECK(make(fan_xy, 5, SL_CELL_TRI3, fan, 3, ov_sides, ov_tags, 0, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "shared by 3 cells");

  /* An untagged boundary face. */
  const int cells[] = {0, 1, 2, 0, 2, 3};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, sq_sides, sq_tags, 3, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "carries no boundary tag");
  /* A side inside the domain, a side that is no edge, a face on two boundaries. */
  const int in_sides[] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2}, in_tags[] = {0, 0, 0, 0, 1};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, in_sides, in_tags, 5, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "lies inside the domain");
  const int no_sides[] = {0, 1, 1, 2, 2, 3, 3, 0, 1, 3}, two_tags[] = {0, 0, 0, 0, 1};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, no_sides, two_tags, 5, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "is not an edge of any cell");
  const int dup_sides[] = {0, 1, 1, 2, 2, 3, 3, 0, 1, 0};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, dup_sides, two_tags, 5, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "on two boundaries, \"wall\" and \"inlet\"");

  /* Out-of-range vertex and tag. */
  const int oob[] = {0, 1, 9, 0, 2, 3};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, oob, 2, sq_sides, sq_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 0 refers to vertex 9");
  const int bad_tags[] = {0, 0, 5, 0};
  CHECK(make(sq_xy, 4, SL_CELL_TRI3, cells, 2, sq_sides, bad_tags, 4, &m) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "tag 5");

  /* 1-D: a cell running towards -x is inverted; a zero-length one degenerate. */
  const double x1[] = {0, 0, 1, 0, 2, 0};
  const int c1[] = {0, 1, 2, 1}, s1[] = {0, 2}, t1[] = {0, 1};
  sl_mesh_spec s = {.dim = 1,
                    .cell_type = SL_CELL_LINE2,
                    .n_vertices = 3,
                    .xy = x1,
                    .n_cells = 2,
                    .cell_vertices = c1,
                    .n_boundaries = 2,
                    .boundary_names = walls,
                    .n_sides = 2,
                    .side_vertices = s1,
                    .side_tag = t1};
  CHECK(sl_mesh_create(&s, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 1 is inverted");
  CHECK_CONTAINS(d.msg, "2 (2), 1 (1)");
  const int c2[] = {0, 1, 1, 1};
  s.cell_vertices = c2;
  CHECK(sl_mesh_create(&s, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cell 1 is degenerate");
  /* Duplicate boundary names. */
  const char *const same[] = {"wall", "wall"};
  const int c3[] = {0, 1, 1, 2};
  s.cell_vertices = c3;
  s.boundary_names = same;
  CHECK(sl_mesh_create(&s, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "named \"wall\"");
  s.boundary_names = walls;
  CHECK(sl_mesh_create(&s, &m, &d) == 0);
  if (m) {
    CHECK(m->n_faces == 3 && m->n_boundary_faces == 2);
    check_mesh_invariants(m);
    sl_mesh_destroy(m);
  }
}

/* A mesh read from a "file" names file:line in the create diagnostics. */
static void test_source_lines(void) {
  const int inv[] = {0, 1, 2, 0, 3, 2}, lines[] = {40, 41}, side_lines[] = {10, 11, 12, 13};
  sl_mesh_spec s = {.dim = 2,
                    .cell_type = SL_CELL_TRI3,
                    .n_vertices = 4,
                    .xy = sq_xy,
                    .n_cells = 2,
                    .cell_vertices = inv,
                    .n_boundaries = 2,
                    .boundary_names = walls,
                    .n_sides = 4,
                    .side_vertices = sq_sides,
                    .side_tag = sq_tags,
                    .source = "box.msh",
                    .cell_line = lines,
                    .side_line = side_lines};
  sl_mesh *m;
  CHECK(sl_mesh_create(&s, &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "box.msh:41: cell 1 is inverted");
}

int main(void) {
  test_valid();
  test_names();
  test_refused();
  test_source_lines();
  sl_mesh_destroy(NULL);
  return sl_test_summary();
}
