/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Meshes as Gmsh writes them, made by the gmsh program in the test: a
 * square with a circular hole of radius R = 0.05 in second-order
 * triangles, 9-node and 8-node quadrangles, ASCII and binary MSH 4.1;
 * physical names with spaces; a mesh of triangles and quadrangles.
 *
 * Exact values: the hole's perimeter 2 pi R, the domain's area
 * L^2 - pi R^2. The straight-sided (order 1) mesh of the same geometry
 * misses the perimeter by about 2 pi R pi^2 / (6 N^2) (N faces: the
 * polygon's perimeter 2 N R sin(pi / N)); the second-order one must be
 * within 1e-5 of it. Skipped (exit 77) when gmsh is not installed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/fe/element.h"
#include "core/fe/geometry.h"
#include "core/mesh/mesh.h"
#include "mesh_checks.h"
#include "testing.h"

static sl_diag d;
static const double R = 0.05, L = 0.4;

/* Writes NAME.geo (the square [-L/2, L/2]^2 minus the disc of radius R, and
 * `extra` lines) and runs gmsh with `opts`; 0 on success. */
static int make(const char *name, const char *extra, const char *opts) {
  char geo[256], cmd[1024];
  snprintf(geo, sizeof geo, "%s.geo", name);
  FILE *f = fopen(geo, "w");
  if (!f) return -1;
  fprintf(f,
          "h = 0.04; hc = 0.01;\n"
          "Point(1) = {-0.2, -0.2, 0, h}; Point(2) = {0.2, -0.2, 0, h}; Point(3) = {0.2, 0.2, 0, h};\n"
          "Point(4) = {-0.2, 0.2, 0, h}; Point(5) = {0, 0, 0, hc};\n"
          "Point(6) = {0.05, 0, 0, hc}; Point(7) = {0, 0.05, 0, hc}; Point(8) = {-0.05, 0, 0, hc};\n"
          "Point(9) = {0, -0.05, 0, hc};\n"
          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
          "Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8}; Circle(7) = {8, 5, 9}; Circle(8) = {9, 5, 6};\n"
          "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};\n"
          "Plane Surface(1) = {1, 2};\n"
          "Physical Curve(\"left wall\") = {4}; Physical Curve(\"outer\") = {1, 2, 3};\n"
          "Physical Curve(\"hole\") = {5, 6, 7, 8}; Physical Surface(\"fluid\") = {1};\n"
          "%s\n",
          extra);
  fclose(f);
  snprintf(cmd, sizeof cmd, "gmsh -2 %s %s -o %s.msh > %s.log 2>&1", opts, geo, name, name);
  return system(cmd);
}

static sl_mesh *read(const char *name) {
  char path[256];
  snprintf(path, sizeof path, "%s.msh", name);
  sl_mesh *m = NULL;
  int rc = sl_mesh_read_gmsh(path, &m, &d);
  CHECK_MSG(rc == 0, "%s: %s", path, d.msg);
  return m;
}

static double hole_length(const sl_mesh *m, const char *name, int *faces) {
  int b;
  if (sl_mesh_boundary_id(m, name, &b, &d)) return -1;
  double len = 0;
  for (int k = m->bface_start[b]; k < m->bface_start[b + 1]; ++k) len += sl_mesh_face_arc_length(m, m->bface[k]);
  *faces = m->bface_start[b + 1] - m->bface_start[b];
  return len;
}

/* The same length through the finite-element face map (core/fe/geometry.h):
 * the 5-point Gauss rule of sl_mesh_face_arc_length on |dx/ds| of each face. */
static double fe_hole_length(const sl_mesh *m, const char *name) {
  int b;
  if (sl_mesh_boundary_id(m, name, &b, &d)) return -1;
  static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
  double len = 0;
  for (int k = m->bface_start[b]; k < m->bface_start[b + 1]; ++k) {
    int f = m->bface[k];
    for (int q = 0; q < 5; ++q) {
      double xi[2], x[2], n[2], ds;
      sl_fe_face_point(m, m->face_cells[2 * f], m->face_local[2 * f], 0.5 * (1 + gx[q]), xi, x, n, &ds);
      len += 0.5 * gw[q] * ds;
      /* the outward normal of the hole points to its centre (the origin) */
      CHECK_MSG(fabs(n[0] + x[0] / R) < 1e-2 && fabs(n[1] + x[1] / R) < 1e-2, "normal (%g, %g) at (%g, %g)", n[0], n[1],
                x[0], x[1]);
    }
  }
  return len;
}

/* The area as the finite-element integration sees it: sum of JxW. */
static double fe_area(const sl_mesh *m) {
  const sl_element *el = sl_element_lagrange(m->cell_type, 2);
  sl_fe_values *fv;
  if (sl_fe_values_create(&fv, m, 1, &el, 4, 0, &d)) return -1;
  double a = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    if (sl_fe_values_reinit(fv, c, &d)) {
      a = -1;
      break;
    }
    for (int q = 0; q < fv->quad.n; ++q) a += fv->JxW[q];
  }
  sl_fe_values_destroy(fv);
  return a;
}

/* One second-order mesh: its hole against 2 pi R and the polygon, its area. */
static void check_curved(const char *name, const char *extra, const char *opts, sl_cell_type type) {
  const double pi = acos(-1.0), perimeter = 2 * pi * R, area = L * L - pi * R * R;
  if (make(name, extra, opts) != 0) {
    CHECK_MSG(0, "%s: gmsh failed (see %s.log)", name, name);
    return;
  }
  sl_mesh *m = read(name);
  if (!m) return;
  CHECK(m->cell_type == type && m->geom_order == 2 && m->face_mid != NULL);
  CHECK(type != SL_CELL_QUAD4 || m->cell_mid != NULL);
  check_mesh_invariants(m);
  int n = 0, b;
  double len = hole_length(m, "hole", &n), polygon = 2 * n * R * sin(pi / n);
  printf("%s: %d %s cells, hole of %d faces: perimeter %.9f (2 pi R = %.9f, the polygon's %.9f)\n", name, m->n_cells,
         sl_cell_type_name(m->cell_type), n, len, perimeter, polygon);
  CHECK_MSG(fabs(len - perimeter) < 1e-5, "%s: hole perimeter %.9f, 2 pi R = %.9f", name, len, perimeter);
  CHECK_MSG(fabs(polygon - perimeter) > 1e-4, "%s: the polygon (%.9f) would pass too", name, polygon);
  CHECK_CLOSE(fe_hole_length(m, "hole"), len, 1e-12);
  double a = fe_area(m);
  printf("%s: area %.10f (exact %.10f)\n", name, a, area);
  CHECK_MSG(fabs(a - area) < 1e-6 * area, "%s: area %.10f, exact %.10f", name, a, area);
  /* straight sides stay straight: the outer square's length is exact */
  CHECK_CLOSE(hole_length(m, "outer", &n), 3 * L, 1e-13);
  /* the name with a space is addressed as left_wall */
  CHECK(sl_mesh_boundary_id(m, "left_wall", &b, &d) == 0);
  CHECK(sl_mesh_boundary_id(m, "left wall", &b, &d) == SL_EBADINPUT);
  sl_mesh_destroy(m);
}

/* Binary MSH 4.1 gives the very mesh the ASCII file gives. */
static void check_binary(void) {
  if (make("hole_tri_bin", "", "-order 2 -format msh41 -bin") != 0) {
    CHECK_MSG(0, "gmsh failed (hole_tri_bin.log)");
    return;
  }
  FILE *f = fopen("hole_tri_bin.msh", "rb");
  char head[64] = "";
  if (f) {
    size_t n = fread(head, 1, sizeof head - 1, f);
    head[n] = '\0';
    fclose(f);
  }
  CHECK_MSG(strstr(head, "4.1 1 8") != NULL, "hole_tri_bin.msh is not binary 4.1: %.20s", head);
  sl_mesh *a = read("hole_tri"), *b = read("hole_tri_bin");
  if (a && b) {
    CHECK(a->n_vertices == b->n_vertices && a->n_cells == b->n_cells && a->n_faces == b->n_faces);
    CHECK(a->geom_order == 2 && b->geom_order == 2);
    if (a->n_vertices == b->n_vertices && a->n_cells == b->n_cells && a->n_faces == b->n_faces) {
      /* the ASCII file has 16 significant digits, the binary one all 17 */
      double dx = 0, dm = 0;
      for (int i = 0; i < 2 * a->n_vertices; ++i) dx = fmax(dx, fabs(a->xy[i] - b->xy[i]));
      for (int i = 0; i < 2 * a->n_faces; ++i) dm = fmax(dm, fabs(a->face_mid[i] - b->face_mid[i]));
      CHECK_MSG(dx < 1e-16 && dm < 1e-16, "binary and ASCII differ by %g (vertices), %g (face nodes)", dx, dm);
      CHECK(memcmp(a->cell_vertices, b->cell_vertices, 3 * (size_t)a->n_cells * sizeof *a->cell_vertices) == 0);
      CHECK(a->n_boundaries == b->n_boundaries && strcmp(b->boundary_names[0], a->boundary_names[0]) == 0);
    }
  }
  sl_mesh_destroy(a);
  sl_mesh_destroy(b);
}

/* Triangles and quadrangles in one mesh: refused with the reason. */
static void check_mixed(void) {
  /* a second surface, apart from the first, recombined into quadrangles */
  const char *extra =
      "Point(10) = {0.3, -0.2, 0, h}; Point(11) = {0.7, -0.2, 0, h}; Point(12) = {0.7, 0.2, 0, h};\n"
      "Point(13) = {0.3, 0.2, 0, h};\n"
      "Line(9) = {10, 11}; Line(10) = {11, 12}; Line(11) = {12, 13}; Line(12) = {13, 10};\n"
      "Curve Loop(3) = {9, 10, 11, 12}; Plane Surface(2) = {3};\n"
      "Transfinite Surface{2}; Recombine Surface{2};\n"
      "Physical Curve(\"right\") = {9, 10, 11, 12}; Physical Surface(\"solid\") = {2};";
  if (make("mixed", extra, "-order 1 -format msh41") != 0) {
    CHECK_MSG(0, "gmsh failed (mixed.log)");
    return;
  }
  sl_mesh *m = NULL;
  int rc = sl_mesh_read_gmsh("mixed.msh", &m, &d);
  CHECK(rc == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "mixed.msh:");
  CHECK_CONTAINS(d.msg, "a mesh of both triangles and quadrangles is not supported");
  CHECK_CONTAINS(d.msg, "split_quads = true");
  /* split: all triangles, the same area (two 0.4 x 0.4 squares less the hole's polygon), every cell valid */
  sl_gmsh_opts o = {.split_quads = 1};
  int n_quads = 0, n_tris = 0;
  rc = sl_mesh_read_gmsh_opts("mixed.msh", &o, &m, &d);
  CHECK_MSG(rc == 0, "split: %s", d.msg);
  if (m) {
    CHECK(m->cell_type == SL_CELL_TRI3 && m->geom_order == 1);
    double a = 0;
    for (int c = 0; c < m->n_cells; ++c) a += sl_mesh_cell_area(m, c);
    int nh = 0;
    hole_length(m, "hole", &nh);
    const double pi = acos(-1.0), polygon_area = 0.5 * nh * R * R * sin(2 * pi / nh);
    CHECK_CLOSE(a, 2 * L * L - polygon_area, 1e-12);
    int solid;
    CHECK(sl_mesh_region_id(m, "solid", &solid, &d) == 0);
    for (int c = 0; c < m->n_cells; ++c) n_quads += m->cell_region[c] == solid, n_tris += m->cell_region[c] != solid;
    printf("mixed, split: %d triangles (%d from quadrangles), area %.12f\n", m->n_cells, n_quads, a);
    CHECK(n_quads > 0 && n_quads % 2 == 0 && n_tris > 0);
    check_mesh_invariants(m);
  }
  sl_mesh_destroy(m);
  /* second order: the quads' centre nodes become the diagonals' nodes; the hole stays curved */
  if (make("mixed2", extra, "-order 2 -format msh41") != 0) {
    CHECK_MSG(0, "gmsh failed (mixed2.log)");
    return;
  }
  rc = sl_mesh_read_gmsh_opts("mixed2.msh", &o, &m, &d);
  CHECK_MSG(rc == 0, "split, order 2: %s", d.msg);
  if (m) {
    CHECK(m->cell_type == SL_CELL_TRI3 && m->geom_order == 2);
    int nh = 0;
    CHECK(fabs(hole_length(m, "hole", &nh) - 2 * acos(-1.0) * R) < 1e-5);
    double a = fe_area(m), exact = 2 * L * L - acos(-1.0) * R * R;
    printf("mixed, split, order 2: area %.10f (exact %.10f)\n", a, exact);
    CHECK_MSG(fabs(a - exact) < 1e-6 * exact, "area %.10f, exact %.10f", a, exact);
    check_mesh_invariants(m);
  }
  sl_mesh_destroy(m);
}

int main(void) {
  if (system("gmsh --version > /dev/null 2>&1") != 0) {
    printf("skipped: the gmsh program is not installed (Debian: apt-get install gmsh)\n");
    return 77;
  }
  check_curved("hole_tri", "", "-order 2 -format msh41", SL_CELL_TRI3);
  check_curved("hole_tri_22", "", "-order 2 -format msh22", SL_CELL_TRI3);
  check_curved("hole_quad9", "Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1;", "-order 2 -format msh41",
               SL_CELL_QUAD4);
  check_curved("hole_quad8", "Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1; Mesh.SecondOrderIncomplete = 1;",
               "-order 2 -format msh41", SL_CELL_QUAD4);
  check_binary();
  check_mixed();
  return sl_test_summary();
}
