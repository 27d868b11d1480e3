/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Periodic boundary pairs at the mesh level: the translation, the vertex and
 * face correspondence on rectangles (quads, triangles), an inclined box and
 * an interval, and the refusals (unknown name, self pair, different counts,
 * rotation, a displaced node). */
#include <math.h>
#include <stdlib.h>

#include "core/mesh/mesh.h"
#include "testing.h"

/* Every pair maps by the shift, both lists ascend in the first entry, and
 * every vertex / face of both boundaries appears once. */
static void check_pairs(const sl_mesh *m, const sl_mesh_periodic *p, double sx, double sy) {
  CHECK_MSG(fabs(p->shift[0] - sx) < 1e-12 && fabs(p->shift[1] - sy) < 1e-12, "shift (%g, %g), expected (%g, %g)",
            p->shift[0], p->shift[1], sx, sy);
  double worst = 0.0;
  int ascending = 1;
  for (int i = 0; i < p->n_vertices; ++i) {
    const double *a = m->xy + 2 * p->vertex_pairs[2 * i], *b = m->xy + 2 * p->vertex_pairs[2 * i + 1];
    worst = fmax(worst, fabs(b[0] - a[0] - sx) + fabs(b[1] - a[1] - sy));
    if (i > 0) ascending &= p->vertex_pairs[2 * i] > p->vertex_pairs[2 * i - 2];
  }
  for (int i = 0; i < p->n_faces; ++i) {
    double a[2], b[2];
    sl_mesh_face_centroid(m, p->face_pairs[2 * i], a);
    sl_mesh_face_centroid(m, p->face_pairs[2 * i + 1], b);
    worst = fmax(worst, fabs(b[0] - a[0] - sx) + fabs(b[1] - a[1] - sy));
    CHECK(m->face_tag[p->face_pairs[2 * i]] == p->boundary && m->face_tag[p->face_pairs[2 * i + 1]] == p->partner);
    if (i > 0) ascending &= p->face_pairs[2 * i] > p->face_pairs[2 * i - 2];
  }
  CHECK_MSG(worst < 1e-12, "pairs off the translation by %g", worst);
  CHECK(ascending);
  CHECK(p->n_faces == m->bface_start[p->boundary + 1] - m->bface_start[p->boundary]);
  /* each partner vertex once */
  char *seen = calloc((size_t)m->n_vertices, 1);
  int once = 1;
  for (int i = 0; i < p->n_vertices; ++i) {
    once &= !seen[p->vertex_pairs[2 * i + 1]];
    seen[p->vertex_pairs[2 * i + 1]] = 1;
  }
  CHECK(once);
  free(seen);
}

static void test_rectangle(sl_cell_type cell) {
  sl_grid_opts o = {.cell_type = cell, .diagonal = SL_DIAGONAL_UNION_JACK, .grade_y = {SL_GRADE_SYMMETRIC, 3.0}};
  sl_mesh *m = NULL;
  sl_diag d = {{0}};
  CHECK(sl_mesh_rectangle(-1.0, 2.0, 0.5, 1.5, 6, 5, &o, &m, &d) == 0);
  sl_mesh_periodic p;
  CHECK_MSG(sl_mesh_periodic_match(m, "left", "right", &p, &d) == 0, "%s", d.msg);
  CHECK(p.n_vertices == 6 && p.n_faces == 5);
  check_pairs(m, &p, 3.0, 0.0);
  sl_mesh_periodic_free(&p);
  CHECK_MSG(sl_mesh_periodic_match(m, "bottom", "top", &p, &d) == 0, "%s", d.msg);
  CHECK(p.n_vertices == 7 && p.n_faces == 6);
  check_pairs(m, &p, 0.0, 1.0);
  sl_mesh_periodic_free(&p);
  /* the other way round: the shift changes sign */
  CHECK_MSG(sl_mesh_periodic_match(m, "top", "bottom", &p, &d) == 0, "%s", d.msg);
  check_pairs(m, &p, 0.0, -1.0);
  sl_mesh_periodic_free(&p);
  sl_mesh_destroy(m);
}

static void test_inclined_and_interval(void) {
  sl_mesh *m = NULL;
  sl_diag d = {{0}};
  double ang = 0.6;
  CHECK(sl_mesh_inclined_box(0.3, -0.2, 2.0, 1.0, ang, 7, 4, NULL, &m, &d) == 0);
  sl_mesh_periodic p;
  CHECK_MSG(sl_mesh_periodic_match(m, "left", "right", &p, &d) == 0, "%s", d.msg);
  check_pairs(m, &p, 2.0 * cos(ang), 2.0 * sin(ang));
  sl_mesh_periodic_free(&p);
  sl_mesh_destroy(m);

  CHECK(sl_mesh_interval(0.0, 1.5, 5, NULL, &m, &d) == 0);
  CHECK_MSG(sl_mesh_periodic_match(m, "left", "right", &p, &d) == 0, "%s", d.msg);
  CHECK(p.n_vertices == 1 && p.n_faces == 1);
  CHECK(p.vertex_pairs[0] == 0 && p.vertex_pairs[1] == 5);
  check_pairs(m, &p, 1.5, 0.0);
  sl_mesh_periodic_free(&p);
  sl_mesh_destroy(m);
}

static void expect_error(const sl_mesh *m, const char *a, const char *b, const char *const *needles, int n) {
  sl_mesh_periodic p;
  sl_diag d = {{0}};
  int rc = sl_mesh_periodic_match(m, a, b, &p, &d);
  CHECK_MSG(rc == SL_EBADINPUT, "'%s'/'%s': rc %d", a ? a : "NULL", b ? b : "NULL", rc);
  CHECK(p.vertex_pairs == NULL && p.face_pairs == NULL);
  for (int k = 0; k < n; ++k) CHECK_CONTAINS(d.msg, needles[k]);
  printf("  %s\n", d.msg);
}

static void test_errors(void) {
  sl_mesh *m = NULL;
  sl_diag d = {{0}};
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 3, NULL, &m, &d) == 0);
  expect_error(m, "lefft", "right", (const char *[]){"'lefft'", "did you mean \"left\""}, 2);
  expect_error(m, "left", "rigth", (const char *[]){"did you mean \"right\""}, 1);
  expect_error(m, "left", "left", (const char *[]){"its own partner"}, 1);
  expect_error(m, NULL, "left", (const char *[]){"both boundary names"}, 1);
  /* 4 vertices on the left, 5 at the bottom */
  expect_error(m, "left", "bottom", (const char *[]){"'left' has 4 nodes", "'bottom' 5 nodes", "node for node"}, 3);
  sl_mesh_destroy(m);

  /* A square: left and bottom have the same counts but are rotations of
   * each other, not translates. */
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 3, 3, NULL, &m, &d) == 0);
  expect_error(m, "left", "bottom",
               (const char *[]){"of 'bottom' has no partner on 'left'", "not translates", "rotation"}, 3);
  sl_mesh_destroy(m);

  /* One interior node of the right side displaced along it by 1e-6: the
   * node is named, with where its partner was looked for. */
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 4, NULL, &m, &d) == 0);
  int moved = -1;
  for (int v = 0; v < m->n_vertices; ++v)
    if (m->xy[2 * v] == 1.0 && m->xy[2 * v + 1] == 0.5) moved = v;
  CHECK(moved >= 0);
  if (moved >= 0) {
    m->xy[2 * moved + 1] += 1e-6;
    CHECK(sl_mesh_check(m, &d) == 0);
    expect_error(m, "left", "right",
                 (const char *[]){"the node (1, 0.500001) of 'right' has no partner on 'left' at (0, 0.500001)"}, 1);
    /* within the tolerance (1e-9 of the diagonal): accepted */
    m->xy[2 * moved + 1] = 0.5 + 1e-11;
    sl_mesh_periodic p;
    CHECK_MSG(sl_mesh_periodic_match(m, "left", "right", &p, &d) == 0, "%s", d.msg);
    sl_mesh_periodic_free(&p);
  }
  sl_mesh_destroy(m);
}

int main(void) {
  test_rectangle(SL_CELL_QUAD4);
  test_rectangle(SL_CELL_TRI3);
  test_inclined_and_interval();
  test_errors();
  return sl_test_summary();
}
