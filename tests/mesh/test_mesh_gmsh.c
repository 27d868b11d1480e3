/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Gmsh reader: 2.2 and 4.1 files of the same geometry give the same mesh;
 * every malformed file gives SL_EBADINPUT with the right file:line. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/fe/geometry.h"
#include "mesh_checks.h"

static sl_diag d;

static const char *data(const char *file) {
  static char path[1024];
  const char *src = getenv("SLUICE_SOURCE_DIR");
  if (src) snprintf(path, sizeof path, "%s/tests/mesh/data/%s", src, file);
  else snprintf(path, sizeof path, "%s/%s", SLUICE_MESH_DATA, file);
  return path;
}

static sl_mesh *read(const char *file) {
  sl_mesh *m = NULL;
  int rc = sl_mesh_read_gmsh(data(file), &m, &d);
  CHECK_MSG(rc == 0, "%s: %s", file, d.msg);
  return m;
}

static int same_ints(const int *a, const int *b, size_t n) {
  return (a == NULL) == (b == NULL) && (!a || memcmp(a, b, n * sizeof *a) == 0);
}

/* Identical node, cell, face and group sets (bit for bit). */
static void check_same(const sl_mesh *a, const sl_mesh *b) {
  CHECK(a->dim == b->dim && a->cell_type == b->cell_type);
  CHECK(a->n_vertices == b->n_vertices && a->n_cells == b->n_cells && a->n_faces == b->n_faces);
  if (a->n_vertices != b->n_vertices || a->n_cells != b->n_cells || a->n_faces != b->n_faces) return;
  CHECK(memcmp(a->xy, b->xy, 2 * (size_t)a->n_vertices * sizeof *a->xy) == 0);
  CHECK(same_ints(a->cell_vertices, b->cell_vertices, (size_t)a->n_cells * a->nv_per_cell));
  CHECK(same_ints(a->face_vertices, b->face_vertices, 2 * (size_t)a->n_faces));
  CHECK(same_ints(a->face_tag, b->face_tag, (size_t)a->n_faces));
  CHECK(a->n_boundaries == b->n_boundaries && a->n_regions == b->n_regions);
  if (a->n_boundaries != b->n_boundaries || a->n_regions != b->n_regions) return;
  int names = 1;
  for (int i = 0; i < a->n_boundaries; ++i) names &= strcmp(a->boundary_names[i], b->boundary_names[i]) == 0;
  for (int i = 0; i < a->n_regions; ++i) names &= strcmp(a->region_names[i], b->region_names[i]) == 0;
  CHECK(names);
  CHECK(same_ints(a->cell_region, b->cell_region, (size_t)a->n_cells));
}

static void test_box_tri(void) {
  sl_mesh *a = read("box_tri_22.msh"), *b = read("box_tri_41.msh");
  if (!a || !b) goto done;
  check_same(a, b);
  CHECK(a->dim == 2 && a->cell_type == SL_CELL_TRI3);
  CHECK(a->n_vertices == 18 && a->n_cells == 22);
  CHECK(euler(a) == 1);
  CHECK(a->n_boundary_faces == 12);
  CHECK_CLOSE(total_area(a), 2.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "bottom"), 2.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "top"), 2.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "left"), 1.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "right"), 1.0, 1e-14);
  CHECK(boundary_count(a, "bottom") == 4 && boundary_count(a, "right") == 2);
  int id;
  CHECK(sl_mesh_region_id(a, "fluid", &id, &d) == 0 && id == 0);
  int all = 1;
  for (int c = 0; c < a->n_cells; ++c) all &= a->cell_region[c] == 0;
  CHECK(all);
  check_mesh_invariants(a);
  CHECK(sl_mesh_boundary_id(a, "wall", &id, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "bottom, right, top, left");
done:
  sl_mesh_destroy(a);
  sl_mesh_destroy(b);
}

static void test_box_quad(void) {
  sl_mesh *a = read("box_quad_22.msh"), *b = read("box_quad_41.msh");
  if (!a || !b) goto done;
  check_same(a, b);
  CHECK(a->cell_type == SL_CELL_QUAD4 && a->n_cells == 10 && a->n_vertices == 18);
  CHECK(euler(a) == 1);
  CHECK_CLOSE(total_area(a), 2.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "bottom"), 2.0, 1e-14);
  CHECK(boundary_count(a, "bottom") == 5);
  CHECK_CLOSE(boundary_length(a, "outlet"), 1.0, 1e-14);
  CHECK_CLOSE(boundary_length(a, "inlet"), 1.0, 1e-14);
  CHECK(a->n_regions == 2);
  int left, right, nl = 0, nr = 0;
  CHECK(sl_mesh_region_id(a, "lower_left", &left, &d) == 0);
  CHECK(sl_mesh_region_id(a, "right_part", &right, &d) == 0);
  CHECK(sl_mesh_region_id(a, "rigth_part", &right, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean \"right_part\"?");
  sl_mesh_region_id(a, "right_part", &right, &d);
  double area_left = 0;
  for (int c = 0; c < a->n_cells; ++c) {
    nl += a->cell_region[c] == left;
    nr += a->cell_region[c] == right;
    if (a->cell_region[c] == left) area_left += sl_mesh_cell_area(a, c);
  }
  CHECK(nl == 4 && nr == 6);
  CHECK_CLOSE(area_left, 0.8, 1e-14);
  check_mesh_invariants(a);
done:
  sl_mesh_destroy(a);
  sl_mesh_destroy(b);
}

static void test_line(void) {
  sl_mesh *a = read("line_22.msh"), *b = read("line_41.msh");
  if (!a || !b) goto done;
  check_same(a, b);
  CHECK(a->dim == 1 && a->cell_type == SL_CELL_LINE2);
  CHECK(a->n_vertices == 10 && a->n_cells == 9 && a->n_faces == 10 && a->n_boundary_faces == 2);
  CHECK_CLOSE(total_area(a), 3.0, 1e-14);
  CHECK(boundary_count(a, "left") == 1 && boundary_count(a, "right") == 1);
  int id;
  CHECK(sl_mesh_region_id(a, "column", &id, &d) == 0);
  double n[2], c[2];
  sl_mesh_face_normal(a, a->bface[a->bface_start[0]], n);
  sl_mesh_face_centroid(a, a->bface[a->bface_start[0]], c);
  CHECK(n[0] == -1 && c[0] == 0);
  check_mesh_invariants(a);
done:
  sl_mesh_destroy(a);
  sl_mesh_destroy(b);
}

/* A clockwise surface: the reader turns every cell round. */
static void test_clockwise(void) {
  sl_mesh *m = read("box_cw_41.msh");
  if (!m) return;
  CHECK(m->n_cells == 22);
  CHECK_CLOSE(total_area(m), 2.0, 1e-14);
  check_mesh_invariants(m);
  sl_mesh_destroy(m);
}

/* The quarter ring 0.5 < r < 1 in 6-node triangles: curved walls of length
 * pi/4 and pi/2, area 3 pi / 16; the binary file gives the ASCII file's mesh. */
static void test_ring(void) {
  sl_mesh *a = read("ring_p2_41.msh"), *b = read("ring_p2_41_bin.msh");
  if (!a || !b) goto done;
  const double pi = acos(-1.0);
  CHECK(a->geom_order == 2 && b->geom_order == 2);
  int in, out;
  CHECK(sl_mesh_boundary_id(a, "inner_wall", &in, &d) == 0 && sl_mesh_boundary_id(a, "outer_wall", &out, &d) == 0);
  double li = 0, lo = 0, area = 0;
  for (int k = a->bface_start[in]; k < a->bface_start[in + 1]; ++k) li += sl_mesh_face_arc_length(a, a->bface[k]);
  for (int k = a->bface_start[out]; k < a->bface_start[out + 1]; ++k) lo += sl_mesh_face_arc_length(a, a->bface[k]);
  for (int c = 0; c < a->n_cells; ++c) area += sl_mesh_cell_curved_area(a, c);
  printf("ring: %d cells, inner wall %.8f (pi/4 %.8f), outer %.8f (pi/2 %.8f), area %.8f (3 pi/16 %.8f)\n", a->n_cells,
         li, pi / 4, lo, pi / 2, area, 3 * pi / 16);
  CHECK(fabs(li - pi / 4) < 1e-4 && fabs(lo - pi / 2) < 1e-4 && fabs(area - 3 * pi / 16) < 1e-4);
  CHECK(a->n_cells == b->n_cells && a->n_vertices == b->n_vertices && a->n_faces == b->n_faces);
  if (a->n_cells == b->n_cells && a->n_faces == b->n_faces) {
    double dm = 0;
    for (int i = 0; i < 2 * a->n_faces; ++i) dm = fmax(dm, fabs(a->face_mid[i] - b->face_mid[i]));
    CHECK(dm < 1e-15);
    CHECK(memcmp(a->cell_vertices, b->cell_vertices, 3 * (size_t)a->n_cells * sizeof *a->cell_vertices) == 0);
  }
done:
  sl_mesh_destroy(a);
  sl_mesh_destroy(b);
}

/* Only regular files are read, and at most SLUICE_MESH_MAX_BYTES of them:
 * a FIFO without a writer, /dev/zero and /dev/stdin are refused at once. */
static void test_not_regular(void) {
  sl_mesh *m = NULL;
  CHECK(sl_mesh_read_gmsh("/dev/zero", &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "/dev/zero: the mesh file is a character device; a Gmsh mesh must be a regular file");
  const char *fifo = "test_mesh_gmsh.fifo";
  remove(fifo);
  if (mkfifo(fifo, 0600) == 0) {
    CHECK(sl_mesh_read_gmsh(fifo, &m, &d) == SL_EBADINPUT && m == NULL);
    CHECK_CONTAINS(d.msg, "is a FIFO (named pipe)");
    remove(fifo);
  }
  CHECK(sl_mesh_read_gmsh(".", &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "is a directory");
  setenv("SLUICE_MESH_MAX_BYTES", "100", 1);
  CHECK(sl_mesh_read_gmsh(data("box_tri_41.msh"), &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "more than the limit of 100");
  unsetenv("SLUICE_MESH_MAX_BYTES");
  CHECK(sl_mesh_read_gmsh(data("box_tri_41.msh"), &m, &d) == 0 && m != NULL);
  sl_mesh_destroy(m);
}

/* Physical names as a scene addresses them (sl_mesh_scene_name). */
static void test_scene_names(void) {
  char out[64];
  CHECK(sl_mesh_scene_name("left wall", out, sizeof out) == 1 && strcmp(out, "left_wall") == 0);
  CHECK(sl_mesh_scene_name("inlet (1)", out, sizeof out) == 1 && strcmp(out, "inlet__1_") == 0);
  CHECK(sl_mesh_scene_name("wall-2.top", out, sizeof out) == 0 && strcmp(out, "wall-2.top") == 0);
  CHECK(sl_mesh_scene_name(".a..b.", out, sizeof out) == 1 && strcmp(out, "_a__b_") == 0);
  const char *text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 1 \"left wall\"\n"
      "1 2 \"left_wall\"\n2 3 \"fluid\"\n$EndPhysicalNames\n";
  sl_mesh *m = NULL;
  CHECK(sl_mesh_read_gmsh_string(text, strlen(text), "t.msh", &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg,
                 "t.msh:7: physical name \"left_wall\" is addressed in a scene as left_wall, and so is the "
                 "name of physical group 1 (line 6)");
}

/* One 6-node triangle, (0,0), (1,0), (0,1), its hypotenuse's node moved out
 * by delta along (1, 1): the parabolic segment adds 2/3 chord x height =
 * 2/3 sqrt(2) (delta sqrt(2)) = 4 delta / 3 to the area 1/2 (Archimedes).
 * The area is exact under the P2 map: from the mesh and from the FE
 * integration context. A node moved too far folds the cell: refused. */
static char *tri6(double mx, double my) {
  static char buf[1024];
  snprintf(buf, sizeof buf,
           "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n1 1 \"wall\"\n2 2 \"fluid\"\n"
           "$EndPhysicalNames\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.5 0 0\n5 %.17g %.17g 0\n6 0 0.5 0\n"
           "$EndNodes\n$Elements\n4\n1 8 2 1 1 1 2 4\n2 8 2 1 1 2 3 5\n3 8 2 1 1 3 1 6\n"
           "4 9 2 2 1 1 2 3 4 5 6\n$EndElements\n",
           mx, my);
  return buf;
}

static void test_curved_triangle(void) {
  const double delta = 0.1, exact = 0.5 + 4 * delta / 3;
  const char *t = tri6(0.5 + delta, 0.5 + delta);
  sl_mesh *m = NULL;
  CHECK(sl_mesh_read_gmsh_string(t, strlen(t), "t.msh", &m, &d) == 0);
  if (!m) return;
  CHECK(m->geom_order == 2 && m->n_cells == 1);
  CHECK_CLOSE(sl_mesh_cell_curved_area(m, 0), exact, 1e-14);
  const sl_element *p2 = sl_element_lagrange(SL_CELL_TRI3, 2);
  sl_fe_values *fv;
  if (sl_fe_values_create(&fv, m, 1, &p2, 2, 0, &d) == 0) {
    double a = 0;
    CHECK(sl_fe_values_reinit(fv, 0, &d) == 0);
    for (int q = 0; q < fv->quad.n; ++q) a += fv->JxW[q];
    CHECK_CLOSE(a, exact, 1e-14);
    /* the hypotenuse's midpoint maps onto its node */
    double x[2];
    sl_fe_map_point(m, 0, (const double[2]){0.5, 0.5}, x);
    CHECK_CLOSE(x[0], 0.5 + delta, 1e-15);
    sl_fe_values_destroy(fv);
  }
  sl_mesh_destroy(m);
  t = tri6(0.2, 0.2); /* the node pulled in most of the way to the far corner: det J < 0 near the corners */
  CHECK(sl_mesh_read_gmsh_string(t, strlen(t), "t.msh", &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg,
                 "t.msh:23: cell 0 folds under its second-order map: det J = -0.2 at the reference point (1, 0)");
}

/* Second-order elements on straight edges (Gmsh -order 2 of a polygon): the
 * face nodes sit at the edge midpoints, so the mesh keeps the linear map. */
static void test_p2_straight(void) {
  sl_mesh *m = read("p2_straight_22.msh");
  if (!m) return;
  CHECK(m->n_cells == 2 && m->n_vertices == 3 + 1 && m->cell_type == SL_CELL_TRI3);
  CHECK(m->geom_order == 1 && m->face_mid == NULL);
  CHECK_CLOSE(total_area(m), 0.5, 1e-14);
  check_mesh_invariants(m);
  sl_mesh_destroy(m);
}

/* Each malformed file: SL_EBADINPUT, "file:line:" and the key words. */
static void bad_file(const char *file, int line, const char *words) {
  sl_mesh *m = (sl_mesh *)&d; /* must be reset to NULL */
  char where[1200];
  int rc = sl_mesh_read_gmsh(data(file), &m, &d);
  CHECK_MSG(rc == SL_EBADINPUT && m == NULL, "%s: rc %d", file, rc);
  snprintf(where, sizeof where, "%s:%d: ", data(file), line);
  CHECK_CONTAINS(d.msg, where);
  CHECK_CONTAINS(d.msg, words);
  sl_mesh_destroy(rc ? NULL : m);
}

static void test_bad_files(void) {
  bad_file("bad_version_30.msh", 2, "version 3.0 is not supported; sluice reads ASCII MSH 2.2 and 4.1");
  bad_file("bad_truncated_41.msh", 60, "unexpected end of file in $Nodes");
  bad_file("bad_mixed_41.msh", 78, "a mesh of both triangles and quadrangles is not supported");
  bad_file("bad_untagged_41.msh", 60, "line element 8 is in no physical group");
  bad_file("bad_twogroups_22.msh", 37, "element 2 repeats element 1 (line 36) with physical group 5");
  bad_file("bad_twogroups_41.msh", 19, "curve 1 is in 2 physical groups (tags 1, 5)");
  sl_mesh *m;
  CHECK(sl_mesh_read_gmsh(data("no_such_file.msh"), &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "cannot open");
}

/* ---- in-memory variants of a two-triangle mesh --------------------------- */

static const char *const base22[] = {
    "$MeshFormat",       /* 1 */
    "2.2 0 8",           /* 2 */
    "$EndMeshFormat",    /* 3 */
    "$PhysicalNames",    /* 4 */
    "2",                 /* 5 */
    "1 1 \"wall\"",      /* 6 */
    "2 2 \"fluid\"",     /* 7 */
    "$EndPhysicalNames", /* 8 */
    "$Nodes",            /* 9 */
    "4",                 /* 10 */
    "1 0 0 0",           /* 11 */
    "2 1 0 0",           /* 12 */
    "3 1 1 0",           /* 13 */
    "4 0 1 0",           /* 14 */
    "$EndNodes",         /* 15 */
    "$Elements",         /* 16 */
    "6",                 /* 17 */
    "1 1 2 1 1 1 2",     /* 18 */
    "2 1 2 1 1 2 3",     /* 19 */
    "3 1 2 1 1 3 4",     /* 20 */
    "4 1 2 1 1 4 1",     /* 21 */
    "5 2 2 2 1 1 2 3",   /* 22 */
    "6 2 2 2 1 1 3 4",   /* 23 */
    "$EndElements",      /* 24 */
};
#define NBASE ((int)(sizeof base22 / sizeof *base22))

/* The base text with line `at` (1-based) replaced by `with` (NULL: deleted),
 * keeping only the first `keep` lines (0: all). */
static char *variant(int at, const char *with, int keep) {
  static char buf[4096];
  size_t used = 0;
  for (int i = 0; i < NBASE && (keep == 0 || i < keep); ++i) {
    const char *l = i + 1 == at ? with : base22[i];
    if (!l) continue;
    used += (size_t)snprintf(buf + used, sizeof buf - used, "%s\n", l);
  }
  return buf;
}

static void bad_text(const char *text, int line, const char *words) {
  sl_mesh *m = (sl_mesh *)&d;
  char where[64];
  int rc = sl_mesh_read_gmsh_string(text, strlen(text), "t.msh", &m, &d);
  CHECK_MSG(rc == SL_EBADINPUT && m == NULL, "expected an error with \"%s\", got rc %d", words, rc);
  snprintf(where, sizeof where, "t.msh:%d: ", line);
  CHECK_CONTAINS(d.msg, where);
  CHECK_CONTAINS(d.msg, words);
  if (rc == 0) sl_mesh_destroy(m);
}

static void test_bad_texts(void) {
  sl_mesh *m;
  const char *ok = variant(0, NULL, 0);
  CHECK(sl_mesh_read_gmsh_string(ok, strlen(ok), "t.msh", &m, &d) == 0);
  if (m) {
    CHECK(m->n_cells == 2 && m->n_boundary_faces == 4 && m->n_boundaries == 1);
    sl_mesh_destroy(m);
  }
  /* CRLF line ends are fine. */
  char crlf[4096];
  size_t k = 0;
  for (const char *p = ok; *p; ++p) {
    if (*p == '\n') crlf[k++] = '\r';
    crlf[k++] = *p;
  }
  crlf[k] = '\0';
  CHECK(sl_mesh_read_gmsh_string(crlf, k, "t.msh", &m, &d) == 0);
  sl_mesh_destroy(m);

  bad_text(variant(2, "4.0 0 8", 0), 2, "version 4.0 is not supported");
  bad_text(variant(2, "2.2 1 8", 0), 2, "binary MSH 2.2 files are not supported");
  bad_text(variant(1, "hello", 0), 1, "not a Gmsh MSH file");
  bad_text(variant(22, "5 9 2 2 1 1 2 3 5 6 7", 0), 22, "element 5 refers to node 5, which is not in $Nodes");
  bad_text(variant(22, "5 21 2 2 1 1 2 3 5 6 7 8 9 10 11", 0), 22,
           "type 21 (10-node triangle), which is not supported; supported types: 1 (2-node line)");
  bad_text(variant(22, "5 4 2 2 1 1 2 3 4", 0), 22, "3-D meshes are not supported");
  bad_text(variant(23, "6 3 2 2 1 1 3 4 2", 0), 23, "a mesh of both triangles and quadrangles");
  bad_text(variant(20, "3 1 2 0 1 3 4", 0), 20, "line element 3 is in no physical group");
  bad_text(variant(19, "2 1 2 3 1 2 3", 0), 19, "physical group 3 of dimension 1, which has no name");
  bad_text(variant(22, "5 2 2 2 1 1 2 9", 0), 22, "refers to node 9, which is not in $Nodes");
  bad_text(variant(22, "5 2 2 2 1 1 2", 0), 22, "needs 3 node tags, found 2");
  bad_text(variant(23, "6 2 2 2 1 1 4 3", 0), 23, "cell 1 is inverted");
  bad_text(variant(12, "2 1 0 0.5", 0), 12, "only planar meshes");
  bad_text(variant(13, "3 1 x 0", 0), 13, "malformed node");
  bad_text(variant(10, "5", 0), 15, "malformed node");        /* count too large: $EndNodes read as a node */
  bad_text(variant(17, "5", 0), 23, "expected $EndElements"); /* count too small */
  bad_text(variant(0, NULL, 20), 20, "unexpected end of file in $Elements");
  bad_text(variant(0, NULL, 12), 12, "unexpected end of file in $Nodes");
  bad_text(variant(0, NULL, 6), 6, "unexpected end of file in $PhysicalNames");
  bad_text(variant(0, NULL, 15), 15, "no $Elements section");
  bad_text(variant(18, "1 1 2 1 1 1 3", 0), 18, "lies inside the domain");
  CHECK(sl_mesh_read_gmsh_string("", 0, "t.msh", &m, &d) == SL_EBADINPUT && m == NULL);
  CHECK_CONTAINS(d.msg, "t.msh: empty file");

  /* No $PhysicalNames: the first element with a physical tag is named. */
  char text[4096];
  size_t used = 0;
  for (int i = 0; i < NBASE; ++i)
    if (i < 3 || i > 7) used += (size_t)snprintf(text + used, sizeof text - used, "%s\n", base22[i]);
  bad_text(text, 13, "no $PhysicalNames section");

  /* An unknown section is skipped; an unterminated one is a truncation. */
  used = 0;
  for (int i = 0; i < NBASE; ++i) {
    used += (size_t)snprintf(text + used, sizeof text - used, "%s\n", base22[i]);
    if (i == 2) used += (size_t)snprintf(text + used, sizeof text - used, "$Comments\nmade by hand\n$EndComments\n");
  }
  CHECK(sl_mesh_read_gmsh_string(text, used, "t.msh", &m, &d) == 0);
  sl_mesh_destroy(m);
  bad_text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Comments\nabc\n", 5, "has no $EndComments");
}

/* 4.1 specifics: the physical group through $Entities, block headers. */
static const char *const base41 =
    "$MeshFormat\n"                /* 1 */
    "4.1 0 8\n"                    /* 2 */
    "$EndMeshFormat\n"             /* 3 */
    "$PhysicalNames\n"             /* 4 */
    "2\n"                          /* 5 */
    "1 1 \"wall\"\n"               /* 6 */
    "2 2 \"fluid\"\n"              /* 7 */
    "$EndPhysicalNames\n"          /* 8 */
    "$Entities\n"                  /* 9 */
    "0 1 1 0\n"                    /* 10 */
    "1 0 0 0 1 1 0 1 1 0\n"        /* 11: curve 1, physical 1 */
    "1 0 0 0 1 1 0 1 2 1 1\n"      /* 12: surface 1, physical 2 */
    "$EndEntities\n"               /* 13 */
    "$Nodes\n"                     /* 14 */
    "1 4 1 4\n"                    /* 15 */
    "2 1 0 4\n"                    /* 16 */
    "1\n2\n3\n4\n"                 /* 17-20 */
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n" /* 21-24 */
    "$EndNodes\n"                  /* 25 */
    "$Elements\n"                  /* 26 */
    "2 6 1 6\n"                    /* 27 */
    "1 1 1 4\n"                    /* 28 */
    "1 1 2\n2 2 3\n3 3 4\n4 4 1\n" /* 29-32 */
    "2 1 2 2\n"                    /* 33 */
    "5 1 2 3\n6 1 3 4\n"           /* 34-35 */
    "$EndElements\n";              /* 36 */

static char *replace41(const char *from, const char *to) {
  static char buf[4096];
  const char *p = strstr(base41, from);
  if (!p) return NULL;
  snprintf(buf, sizeof buf, "%.*s%s%s", (int)(p - base41), base41, to, p + strlen(from));
  return buf;
}

static void test_41(void) {
  sl_mesh *m;
  CHECK(sl_mesh_read_gmsh_string(base41, strlen(base41), "t.msh", &m, &d) == 0);
  if (m) {
    CHECK(m->n_cells == 2 && m->n_boundary_faces == 4 && boundary_count(m, "wall") == 4);
    CHECK(m->n_regions == 1 && m->cell_region[0] == 0 && m->cell_region[1] == 0);
    sl_mesh_destroy(m);
  }
  /* The curve carries no physical tag. */
  bad_text(replace41("1 0 0 0 1 1 0 1 1 0\n", "1 0 0 0 1 1 0 0 0\n"), 29, "line element 1 is in no physical group");
  /* The curve is in two physical groups. */
  bad_text(replace41("1 0 0 0 1 1 0 1 1 0\n", "1 0 0 0 1 1 0 2 1 3 0\n"), 11, "curve 1 is in 2 physical groups");
  /* An unsupported element type is named at its block header. */
  bad_text(replace41("2 1 2 2\n", "2 1 9 2\n"), 34, "element 5 (6-node triangle) needs 6 node tags, found 3");
  /* Node block counts that do not add up. */
  bad_text(replace41("1 4 1 4\n", "1 5 1 4\n"), 24, "announces 5 nodes but its blocks hold 4");
  bad_text(replace41("2 6 1 6\n", "2 7 1 6\n"), 35, "announces 7 elements but its blocks hold 6");
  bad_text(replace41("$EndNodes\n", ""), 25, "expected $EndNodes");
}

int main(void) {
  test_box_tri();
  test_box_quad();
  test_line();
  test_clockwise();
  test_p2_straight();
  test_curved_triangle();
  test_not_regular();
  test_ring();
  test_scene_names();
  test_bad_files();
  test_bad_texts();
  test_41();
  return sl_test_summary();
}
