/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Meshes of dimension 1 or 2: vertices, cells of one type, the unique face
 * list with neighbours, named boundaries and optional cell regions.
 *
 * Conventions
 *  - Coordinates are (x, y); in an axisymmetric scene x is r and y is z. A
 *    1-D mesh lies on the x axis (y = 0): a vertical column uses x as its
 *    height and the model decides where gravity points.
 *  - One cell type per mesh: line2 (1-D), tri3 or quad4 (2-D). Connectivity
 *    is 0-based. A 2-D mesh may carry second-order geometry (geom_order 2,
 *    from a Gmsh mesh made with -order 2): a node on each face and, on
 *    quadrangles, one in the centre; the cells are then the images of the
 *    reference cell under the quadratic (P2 / Q2) map through those nodes,
 *    so curved walls are curved. The finite-element geometry
 *    (core/fe/geometry.h) and sl_mesh_face_arc_length use it; the planar
 *    measures below (areas, face lengths, normals: the finite-volume view)
 *    stay those of the straight-sided cells through the vertices. 2-D cells are counter-clockwise (positive Jacobian at every
 *    corner); 1-D cells run towards increasing x.
 *  - Local face k of a 2-D cell joins its local vertices k and (k + 1) % nv.
 *    In 1-D the faces are points: local face 0 is vertex 0 (the left end),
 *    local face 1 is vertex 1 (the right end).
 *  - Each face is stored once. face_cells[2f] is its owner: the lower-
 *    numbered cell, from which the face normal points outwards. On the
 *    boundary face_cells[2f + 1] == -1 and the normal is the outward normal
 *    of the domain; inside it points from the owner into the neighbour.
 *    face_vertices[2f], [2f + 1] follow the owner's counter-clockwise order,
 *    so the normal is (dy, -dx) / length of that edge.
 *  - Measures are planar: the "area" of a cell is its area in the (x, y)
 *    plane (its length in 1-D) and a face's "length" its length (1 in 1-D).
 *    An axisymmetric scheme multiplies by r (and 2 pi) itself, e.g. at the
 *    quadrature points or at the face/cell centroids.
 *  - Every boundary face carries a boundary tag (an index into
 *    boundary_names); sl_mesh_create refuses a mesh with an untagged
 *    boundary face. Interior faces have tag -1.
 *  - A created mesh is valid: no inverted or degenerate cell, no edge shared
 *    by more than two cells, consistent orientation across every face.
 *
 * Ownership: a sl_mesh owns all its arrays; sl_mesh_destroy frees them. The
 * fields are read-only for users. */
#ifndef SLUICE_MESH_MESH_H
#define SLUICE_MESH_MESH_H

#include <stdio.h>

#include "core/util/diag.h"

/* The value is the number of vertices (and of faces in 2-D) per cell. */
typedef enum sl_cell_type { SL_CELL_LINE2 = 2, SL_CELL_TRI3 = 3, SL_CELL_QUAD4 = 4 } sl_cell_type;

typedef struct sl_mesh {
  int dim; /* 1 or 2 */
  sl_cell_type cell_type;
  int nv_per_cell; /* vertices per cell: 2, 3 or 4 */
  int nf_per_cell; /* faces per cell: 2 (1-D), 3 or 4 */

  int n_vertices;
  double *xy; /* [2 * n_vertices]: x, y of vertex v at 2v, 2v + 1 */

  int n_cells;
  int *cell_vertices; /* [nv_per_cell * n_cells], counter-clockwise */
  int *cell_faces;    /* [nf_per_cell * n_cells]: face of local face k */

  int n_faces;
  int n_boundary_faces;
  int *face_vertices; /* [2 * n_faces]; in 1-D [2f + 1] == -1 */
  int *face_cells;    /* [2 * n_faces]: owner, neighbour (-1 on the boundary) */
  int *face_local;    /* [2 * n_faces]: local face index in each of those cells (-1) */
  int *face_tag;      /* [n_faces]: boundary index, -1 for interior faces */

  int n_boundaries;
  char **boundary_names; /* [n_boundaries] */
  int *bface_start;      /* [n_boundaries + 1]: faces of boundary b are      */
  int *bface;            /* bface[bface_start[b] .. bface_start[b + 1] - 1], ascending */

  int n_regions;       /* 0 when the mesh has no cell regions */
  char **region_names; /* [n_regions] */
  int *cell_region;    /* [n_cells], region index or -1; NULL when n_regions == 0 */

  /* Second-order geometry (2-D only). geom_order 1: straight-sided cells,
   * face_mid and cell_mid NULL. geom_order 2: face_mid[2f], [2f + 1] is the
   * node on face f (its midpoint when the face is straight); on quads
   * cell_mid[2c], [2c + 1] is the centre node. A mesh whose face nodes all
   * sit at the midpoints of straight faces (and centres at the bilinear
   * centre) is stored as geom_order 1. */
  int geom_order;
  double *face_mid; /* [2 * n_faces] or NULL */
  double *cell_mid; /* [2 * n_cells] (quads, geom_order 2) or NULL */
} sl_mesh;

/* ---- construction ------------------------------------------------------ */

/* Everything sl_mesh_create needs; all arrays are copied. Boundary sides
 * (edges in 2-D, vertices in 1-D) name which faces carry which tag; their
 * vertex order does not matter. */
typedef struct sl_mesh_spec {
  int dim;
  sl_cell_type cell_type;
  int n_vertices;
  const double *xy; /* [2 * n_vertices] */
  int n_cells;
  const int *cell_vertices; /* [nv * n_cells] */
  int n_boundaries;
  const char *const *boundary_names;
  int n_sides;
  const int *side_vertices; /* [2 * n_sides] in 2-D, [n_sides] in 1-D */
  const int *side_tag;      /* [n_sides], in [0, n_boundaries) */
  int n_regions;            /* 0: no regions (cell_region ignored) */
  const char *const *region_names;
  const int *cell_region; /* [n_cells], -1 or a region index */
  /* Optional, for diagnostics of meshes read from a file: the file name and
   * the line of each cell / side, so errors read "file:line: ...". */
  const char *source;
  const int *cell_line;
  const int *side_line;
  /* Optional second-order geometry (2-D): the node on local face k of cell
   * c at edge_mid[2 (nf c + k)], [.. + 1] (nf = faces per cell), and for
   * quads the centre node at cell_centre[2c], [2c + 1] (required with
   * edge_mid on quads). Two cells sharing a face must give the same node.
   * NULL: straight-sided cells. */
  const double *edge_mid;
  const double *cell_centre;
} sl_mesh_spec;

/* Builds the faces, the boundary lists and checks the mesh (sl_mesh_check).
 * Returns 0, SL_EBADINPUT (bad spec or invalid mesh; *out is NULL) or
 * SL_EFAILED (out of memory). */
int sl_mesh_create(const sl_mesh_spec *spec, sl_mesh **out, sl_diag *d);
/* Frees the mesh and everything it owns; NULL is allowed. */
void sl_mesh_destroy(sl_mesh *m);

/* ---- generators -------------------------------------------------------- */

/* Grading of the cell sizes along one direction (zero-initialised: uniform).
 *  - SL_GRADE_GEOMETRIC: sizes grow geometrically from the first cell to the
 *    last; ratio = h_last / h_first (ratio < 1 refines towards the end, as
 *    OpenFOAM's expansion ratio). Needs n >= 2 unless ratio == 1.
 *  - SL_GRADE_SYMMETRIC: mirror-symmetric about the middle, geometric from
 *    each end to the middle; ratio = h_middle / h_end, so ratio > 1 refines
 *    towards both ends (walls), ratio < 1 towards the middle. Cell i has
 *    size h_end * q^min(i, n-1-i) with q = ratio^(1 / floor((n-1)/2)).
 *    Needs n >= 3 unless ratio == 1. */
typedef enum sl_grading_kind { SL_GRADE_UNIFORM = 0, SL_GRADE_GEOMETRIC, SL_GRADE_SYMMETRIC } sl_grading_kind;

typedef struct sl_grading {
  sl_grading_kind kind;
  double ratio; /* > 0; ignored for SL_GRADE_UNIFORM */
} sl_grading;

/* How each quadrilateral of a structured grid is split into triangles. */
typedef enum sl_diagonal {
  SL_DIAGONAL_RIGHT = 0, /* "/": lower-left to upper-right corner */
  SL_DIAGONAL_LEFT,      /* "\": lower-right to upper-left corner */
  SL_DIAGONAL_UNION_JACK /* alternating "/" and "\" in a checkerboard */
} sl_diagonal;

/* Options of the 2-D generators; NULL means quadrilaterals, uniform. */
typedef struct sl_grid_opts {
  sl_cell_type cell_type; /* SL_CELL_QUAD4 (also when 0) or SL_CELL_TRI3 */
  sl_diagonal diagonal;   /* triangles only */
  sl_grading grade_x;     /* along x (r) */
  sl_grading grade_y;     /* along y (z) */
} sl_grid_opts;

/* The points a + (b - a) * s_i, i = 0..n with the grading's s_i: exposed for
 * the generators' users and tests. x holds n + 1 values; x[0] == a and
 * x[n] == b exactly. */
int sl_mesh_graded_points(double a, double b, int n, const sl_grading *g, double *x, sl_diag *d);

/* [a, b] with n line cells; boundaries "left" (x = a, id 0) and "right"
 * (x = b, id 1). g may be NULL (uniform). */
int sl_mesh_interval(double a, double b, int n, const sl_grading *g, sl_mesh **out, sl_diag *d);

/* [x0, x1] x [y0, y1] with nx by ny quads (or 2 nx ny triangles);
 * boundaries "bottom" (0), "right" (1), "top" (2), "left" (3). */
int sl_mesh_rectangle(double x0, double x1, double y0, double y1, int nx, int ny, const sl_grid_opts *o, sl_mesh **out,
                      sl_diag *d);

/* The axisymmetric (r, z) box [r_in, r_out] x [z0, z1]: a rectangle with r
 * as x, boundaries "bottom" (0), "outer" (1), "top" (2) and "inner" (3), or
 * "axis" (3) when r_in == 0. */
int sl_mesh_annulus(double r_in, double r_out, double z0, double z1, int nr, int nz, const sl_grid_opts *o,
                    sl_mesh **out, sl_diag *d);

/* A width x height rectangle with its lower-left corner at (x0, y0), rotated
 * counter-clockwise by `angle` (radians) about that corner (the Boycott
 * vessel: angle = pi/4). nx cells along the width, ny along the height.
 * Boundaries as for the rectangle, named by the box's own sides: "bottom" is
 * the rotated side that started at y = y0. */
int sl_mesh_inclined_box(double x0, double y0, double width, double height, double angle, int nx, int ny,
                         const sl_grid_opts *o, sl_mesh **out, sl_diag *d);

/* ---- Gmsh -------------------------------------------------------------- */

/* Reads a Gmsh MSH 2.2 (ASCII) or 4.1 (ASCII or binary) file. Elements:
 * 2-node lines (1), 3-node triangles (2), 4-node quads (3), and their
 * second-order forms: 3-node lines (8), 6-node triangles (9), 9-node and
 * 8-node quads (10, 16; the centre of an 8-node quad is the image of the
 * reference centre under its serendipity map); points (15) are ignored in
 * 2-D. Second-order cells give the mesh second-order geometry
 * (geom_order 2); in 1-D the mid node of a 3-node line is dropped (the
 * cell is the straight segment either way). Triangles and quadrangles in
 * one mesh are refused (one cell type per mesh) unless split_quads is set
 * (sl_mesh_read_gmsh_opts): each quadrangle then becomes two triangles
 * along its shorter diagonal (second-order quads: the diagonal's node is
 * the quad's centre node).
 * Only regular files of at most SL_MESH_GMSH_MAX_BYTES are read (a FIFO,
 * a device or a terminal is refused before anything is read from it).
 * Physical names become boundary and region names with the scene rule
 * (sl_mesh_scene_name): "left wall" is addressed as left_wall.
 * Physical groups of dimension 1 name the boundaries (their lines tag
 * boundary faces), groups of dimension 2 are cell regions; names come from
 * $PhysicalNames (required). Every boundary face must lie in a physical
 * curve. A mesh without triangles or quads is read as 1-D: lines are cells,
 * physical points are boundaries, physical curves regions; the nodes must
 * lie on the x axis. Vertices and cells are numbered in the order of their
 * Gmsh tags (unused nodes dropped), so 2.2 and 4.1 files of one mesh give
 * the same sl_mesh. A mesh whose cells are all clockwise (a surface with
 * normal -z) is reoriented; a mix is refused as inverted cells.
 * Errors name file:line and return SL_EBADINPUT. */
int sl_mesh_read_gmsh(const char *path, sl_mesh **out, sl_diag *d);
/* The largest mesh file read: 1 GiB, about 5 million second-order
 * triangles of ASCII text (the environment variable SLUICE_MESH_MAX_BYTES,
 * a number of bytes, sets another limit; at most 2^31 - 1). */
#define SL_MESH_GMSH_MAX_BYTES (1024L * 1024 * 1024)
/* The same from text in memory; `name` is used in diagnostics. */
int sl_mesh_read_gmsh_string(const char *text, size_t len, const char *name, sl_mesh **out, sl_diag *d);
/* Reader options (zero-initialised: the defaults; NULL: the defaults). */
typedef struct sl_gmsh_opts {
  int split_quads; /* split every quadrangle into two triangles */
} sl_gmsh_opts;
int sl_mesh_read_gmsh_opts(const char *path, const sl_gmsh_opts *opts, sl_mesh **out, sl_diag *d);
int sl_mesh_read_gmsh_string_opts(const char *text, size_t len, const char *name, const sl_gmsh_opts *opts,
                                  sl_mesh **out, sl_diag *d);

/* ---- names ------------------------------------------------------------- */

/* Boundary (region) index by name. An unknown name returns SL_EBADINPUT
 * with a message listing the mesh's names and a did-you-mean. */
int sl_mesh_boundary_id(const sl_mesh *m, const char *name, int *id, sl_diag *d);
int sl_mesh_region_id(const sl_mesh *m, const char *name, int *id, sl_diag *d);

const char *sl_cell_type_name(sl_cell_type t);

/* The name a scene section can address: every character other than a
 * letter, digit, '_', '-' or '.' becomes '_', and so does a '.' at either
 * end or next to another '.' (a scene section name has no empty dotted
 * part). "left wall" -> "left_wall", "inlet (1)" -> "inlet__1_". Writes at
 * most size - 1 characters; returns 1 when the name changed, 0 when not. */
int sl_mesh_scene_name(const char *name, char *out, size_t size);

/* ---- periodic boundaries ------------------------------------------------ */

/* Two boundaries that are translates of each other: `partner` is the image
 * of `boundary` under x -> x + shift, vertex for vertex and face for face.
 * The pairing behind periodic dof maps (core/fe/dofmap.h); a finite-volume
 * scheme can link the paired faces the same way. */
typedef struct sl_mesh_periodic {
  int boundary, partner; /* boundary ids */
  double shift[2];       /* partner = boundary + shift */
  int n_vertices;
  int *vertex_pairs; /* [2 * n_vertices]: (vertex of boundary, its image on partner),
                            ascending in the first */
  int n_faces;
  int *face_pairs; /* [2 * n_faces]: (face of boundary, its image on partner),
                            ascending in the first */
} sl_mesh_periodic;

/* Relative tolerance of the match: two points coincide when they differ by
 * at most this times the diagonal of the mesh's bounding box, per
 * coordinate. */
#define SL_MESH_PERIODIC_TOL 1e-9

/* Finds the translation (from the boundaries' bounding boxes) and pairs
 * every vertex and face of `partner` with one of `boundary`. SL_EBADINPUT,
 * with both names in the message, for an unknown name (did-you-mean), a
 * boundary paired with itself, different vertex or face counts, boundaries
 * that are not translates of each other (extents differ: rotated or
 * reflected), or a vertex of `partner` with no vertex of `boundary` at
 * x - shift (the point and where its partner was expected are named).
 * SL_EFAILED: out of memory. On error *out is zeroed. */
int sl_mesh_periodic_match(const sl_mesh *m, const char *boundary, const char *partner, sl_mesh_periodic *out,
                           sl_diag *d);
void sl_mesh_periodic_free(sl_mesh_periodic *p);

/* ---- geometry ---------------------------------------------------------- */

/* Planar area of cell c (length in 1-D). Exact for straight-sided cells:
 * triangles by the cross product, quads by half the cross product of the
 * diagonals (the area of the bilinear quad with straight edges). */
double sl_mesh_cell_area(const sl_mesh *m, int c);
/* Area centroid of cell c (the polygon centroid, not the vertex average). */
void sl_mesh_cell_centroid(const sl_mesh *m, int c, double centroid[2]);
/* Length of face f (1 in 1-D). */
double sl_mesh_face_length(const sl_mesh *m, int f);
/* Unit normal of face f, pointing out of its owner face_cells[2f]. */
void sl_mesh_face_normal(const sl_mesh *m, int f, double n[2]);
/* Midpoint of face f (the vertex itself in 1-D). */
void sl_mesh_face_centroid(const sl_mesh *m, int f, double c[2]);

/* ---- second-order geometry (core/mesh/curved.c) ------------------------- */

/* The geometric nodes of cell c in the element order of core/fe/element.h
 * (vertices, then one per face, then the quad's centre): nv_per_cell nodes
 * for geom_order 1, 6 (triangle) or 9 (quadrangle) for geom_order 2.
 * Returns their number. */
int sl_mesh_cell_nodes(const sl_mesh *m, int c, double (*x)[2]);
/* The point of face f at s in [0, 1] (s = 0 at face_vertices[2f], 1 at
 * [2f + 1]) and dx/ds there: the quadratic through the face's node when the
 * mesh is curved, the straight edge otherwise. t may be NULL. 2-D only. */
void sl_mesh_face_point(const sl_mesh *m, int f, double s, double x[2], double t[2]);
/* Length of face f along the curve (sl_mesh_face_length when straight):
 * 5-point Gauss-Legendre of |dx/ds|. */
double sl_mesh_face_arc_length(const sl_mesh *m, int f);
/* Area of cell c under its second-order map (sl_mesh_cell_area when
 * geom_order is 1): Gauss quadrature of det J, exact for the polynomial
 * det J of the P2 / Q2 map. */
double sl_mesh_cell_curved_area(const sl_mesh *m, int c);
/* Refuses a second-order cell whose map folds (det J <= 0 at one of its
 * nodes or quadrature points): SL_EBADINPUT with the cell, the point and
 * its nodes. 0 for geom_order 1. */
int sl_mesh_check_curved(const sl_mesh *m, const char *source, const int *cell_line, sl_diag *d);

/* ---- quality ----------------------------------------------------------- */

typedef struct sl_mesh_quality {
  double min_area, max_area; /* cell areas (lengths in 1-D) */
  double min_angle;          /* smallest interior angle, radians (0 in 1-D) */
  double max_angle;          /* largest interior angle, radians (0 in 1-D) */
  double max_aspect;         /* largest longest-edge / shortest-edge ratio (1 in 1-D) */
  double max_size_jump;      /* largest area ratio of two face neighbours (>= 1) */
  int min_area_cell, max_area_cell, min_angle_cell, max_aspect_cell;
} sl_mesh_quality;

void sl_mesh_quality_compute(const sl_mesh *m, sl_mesh_quality *q);
/* Refuses inverted (negative Jacobian at a corner) and degenerate (zero
 * area, zero-length edge or straight angle) cells, and second-order cells
 * whose map folds (sl_mesh_check_curved): SL_EBADINPUT with the cell index
 * and its vertices' coordinates. sl_mesh_create calls it; call it
 * again after moving vertices. */
int sl_mesh_check(const sl_mesh *m, sl_diag *d);
/* A few lines: sizes, boundaries with face counts and lengths, quality. */
void sl_mesh_print_report(const sl_mesh *m, FILE *out);

#endif
