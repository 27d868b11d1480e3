/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Mesh construction (faces, boundary lists), geometry, names, quality. */
#include "core/mesh/mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Relative tolerance below which a corner Jacobian counts as zero. */
#define SL_MESH_DEGENERATE_TOL 1e-12

/* ---- small helpers ------------------------------------------------------ */

static char *dup_string(const char *s) {
  size_t n = strlen(s) + 1;
  char *p = malloc(n);
  if (p) memcpy(p, s, n);
  return p;
}

static void free_names(char **names, int n) {
  if (!names) return;
  for (int i = 0; i < n; ++i) free(names[i]);
  free(names);
}

/* "source:line: " or "source: " or "" for diagnostics. */
static void where(char *buf, size_t size, const char *source, const int *lines, int index) {
  if (source && lines && index >= 0) snprintf(buf, size, "%s:%d: ", source, lines[index]);
  else if (source) snprintf(buf, size, "%s: ", source);
  else buf[0] = '\0';
}

static const double *vx(const sl_mesh *m, int v) { return m->xy + 2 * (size_t)v; }

/* Appends " v (x, y)" for each vertex of cell c. */
static void describe_cell(const sl_mesh *m, int c, char *buf, size_t size) {
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < m->nv_per_cell && used < size; ++k) {
    int v = m->cell_vertices[(size_t)c * m->nv_per_cell + k];
    const double *p = vx(m, v);
    int w = m->dim == 1 ? snprintf(buf + used, size - used, "%s%d (%.10g)", k ? ", " : "", v, p[0])
                        : snprintf(buf + used, size - used, "%s%d (%.10g, %.10g)", k ? ", " : "", v, p[0], p[1]);
    if (w < 0) break;
    used += (size_t)w;
  }
}

static void describe_vertex(const sl_mesh *m, int v, char *buf, size_t size) {
  const double *p = vx(m, v);
  if (m->dim == 1) snprintf(buf, size, "vertex %d (%.10g)", v, p[0]);
  else snprintf(buf, size, "vertex %d (%.10g, %.10g)", v, p[0], p[1]);
}

const char *sl_cell_type_name(sl_cell_type t) {
  switch (t) {
    case SL_CELL_LINE2:
      return "line2";
    case SL_CELL_TRI3:
      return "tri3";
    case SL_CELL_QUAD4:
      return "quad4";
  }
  return "unknown";
}

/* ---- destroy ------------------------------------------------------------ */

void sl_mesh_destroy(sl_mesh *m) {
  if (!m) return;
  free(m->xy);
  free(m->cell_vertices);
  free(m->cell_faces);
  free(m->face_vertices);
  free(m->face_cells);
  free(m->face_local);
  free(m->face_tag);
  free_names(m->boundary_names, m->n_boundaries);
  free(m->bface_start);
  free(m->bface);
  free_names(m->region_names, m->n_regions);
  free(m->cell_region);
  free(m->face_mid);
  free(m->cell_mid);
  free(m);
}

/* ---- validity of cells -------------------------------------------------- */

/* 0, or SL_EBADINPUT naming the first inverted or degenerate cell. */
static int check_cells(const sl_mesh *m, const char *source, const int *cell_line, sl_diag *d) {
  const int nv = m->nv_per_cell;
  for (int c = 0; c < m->n_cells; ++c) {
    const int *cv = m->cell_vertices + (size_t)c * nv;
    int inverted = -1, degenerate = -1;
    if (m->dim == 1) {
      double a = vx(m, cv[0])[0], b = vx(m, cv[1])[0];
      double scale = fmax(fabs(a), fabs(b));
      if (fabs(b - a) <= SL_MESH_DEGENERATE_TOL * scale) degenerate = 0;
      else if (b < a) inverted = 0;
    } else {
      /* Jacobian of the corner k: (p[k+1] - p[k]) x (p[k-1] - p[k]) > 0 for
       * a counter-clockwise cell; for a quad this is the bilinear map's
       * Jacobian determinant at that corner (the extremes are at corners). */
      for (int k = 0; k < nv; ++k) {
        const double *p = vx(m, cv[k]), *pn = vx(m, cv[(k + 1) % nv]), *pp = vx(m, cv[(k + nv - 1) % nv]);
        double e1x = pn[0] - p[0], e1y = pn[1] - p[1], e2x = pp[0] - p[0], e2y = pp[1] - p[1];
        double j = e1x * e2y - e1y * e2x;
        double s = hypot(e1x, e1y) * hypot(e2x, e2y);
        if (fabs(j) <= SL_MESH_DEGENERATE_TOL * s) {
          if (degenerate < 0) degenerate = k;
        } else if (j < 0 && inverted < 0) {
          inverted = k;
        }
      }
    }
    if (inverted >= 0 || degenerate >= 0) {
      char at[512], verts[512];
      where(at, sizeof at, source, cell_line, c);
      describe_cell(m, c, verts, sizeof verts);
      if (inverted >= 0)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%scell %d is inverted (negative Jacobian at its local vertex %d; cells must be "
                           "counter-clockwise): vertices %s",
                           at, c, inverted, verts);
      return sl_diag_set(d, SL_EBADINPUT, "%scell %d is degenerate (zero area at its local vertex %d): vertices %s", at,
                         c, degenerate, verts);
    }
  }
  return 0;
}

int sl_mesh_check(const sl_mesh *m, sl_diag *d) {
  int rc = check_cells(m, NULL, NULL, d);
  return rc ? rc : sl_mesh_check_curved(m, NULL, NULL, d);
}

/* ---- faces -------------------------------------------------------------- */

typedef struct half_face {
  int lo, hi; /* sorted vertex pair (lo == hi in 1-D) */
  int cell, local;
} half_face;

static int cmp_half_face(const void *pa, const void *pb) {
  const half_face *a = pa, *b = pb;
  if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
  if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
  if (a->cell != b->cell) return a->cell < b->cell ? -1 : 1;
  return (a->local > b->local) - (a->local < b->local);
}

/* First vertex of local face k of cell c in the cell's own order. */
static int face_first_vertex(const sl_mesh *m, int c, int k) {
  return m->cell_vertices[(size_t)c * m->nv_per_cell + k];
}
static int face_second_vertex(const sl_mesh *m, int c, int k) {
  if (m->dim == 1) return -1;
  return m->cell_vertices[(size_t)c * m->nv_per_cell + (k + 1) % m->nv_per_cell];
}

/* Position of the first half face with key (lo, hi) in the sorted array, or -1. */
static long find_key(const half_face *h, long n, int lo, int hi) {
  long a = 0, b = n;
  while (a < b) {
    long mid = a + (b - a) / 2;
    if (h[mid].lo < lo || (h[mid].lo == lo && h[mid].hi < hi)) a = mid + 1;
    else b = mid;
  }
  return a < n && h[a].lo == lo && h[a].hi == hi ? a : -1;
}

/* Faces, owners, neighbours and local indices. On success `sorted`/`group`
 * (the half faces sorted by key and the face of each) stay for side look-up. */
static int build_faces(sl_mesh *m, const char *source, const int *cell_line, half_face **sorted_out,
                       int **face_of_sorted_out, sl_diag *d) {
  const int nf = m->nf_per_cell;
  const long nh = (long)m->n_cells * nf;
  half_face *h = malloc((size_t)nh * sizeof *h);
  int *pos = malloc((size_t)nh * sizeof *pos);     /* cell*nf+local -> sorted index */
  int *first = malloc((size_t)nh * sizeof *first); /* sorted index -> first of its group */
  int *face_of = malloc((size_t)nh * sizeof *face_of);
  int rc = 0;
  if (!h || !pos || !first || !face_of) {
    rc = sl_diag_set(d, SL_ENOMEM, "out of memory building the faces of a mesh with %d cells", m->n_cells);
    goto fail;
  }
  for (int c = 0; c < m->n_cells; ++c)
    for (int k = 0; k < nf; ++k) {
      half_face *e = h + (size_t)c * nf + k;
      int a = face_first_vertex(m, c, k), b = m->dim == 1 ? a : face_second_vertex(m, c, k);
      e->lo = a < b ? a : b;
      e->hi = a < b ? b : a;
      e->cell = c;
      e->local = k;
    }
  qsort(h, (size_t)nh, sizeof *h, cmp_half_face);

  /* Groups of equal keys: one half face on the boundary, two inside. */
  for (long i = 0; i < nh;) {
    long j = i + 1;
    while (j < nh && h[j].lo == h[i].lo && h[j].hi == h[i].hi) ++j;
    char at[512], va[160], vb[160];
    if (j - i > 2) {
      where(at, sizeof at, source, cell_line, h[i].cell);
      describe_vertex(m, h[i].lo, va, sizeof va);
      describe_vertex(m, h[i].hi, vb, sizeof vb);
      rc = m->dim == 1
               ? sl_diag_set(d, SL_EBADINPUT, "%s%s is shared by %ld cells (%d, %d, %d, ...); at most two may meet", at,
                             va, j - i, h[i].cell, h[i + 1].cell, h[i + 2].cell)
               : sl_diag_set(d, SL_EBADINPUT,
                             "%sthe edge between %s and %s is shared by %ld cells (%d, %d, %d, ...); at most "
                             "two may share an edge",
                             at, va, vb, j - i, h[i].cell, h[i + 1].cell, h[i + 2].cell);
      goto fail;
    }
    if (j - i == 2) {
      /* Two counter-clockwise cells on opposite sides of an edge run along it
       * in opposite directions; the same direction means they overlap. */
      int same = m->dim == 1 ? h[i].local == h[i + 1].local
                             : face_first_vertex(m, h[i].cell, h[i].local) ==
                                   face_first_vertex(m, h[i + 1].cell, h[i + 1].local);
      if (same) {
        where(at, sizeof at, source, cell_line, h[i + 1].cell);
        describe_vertex(m, h[i].lo, va, sizeof va);
        describe_vertex(m, h[i].hi, vb, sizeof vb);
        rc = m->dim == 1
                 ? sl_diag_set(d, SL_EBADINPUT, "%scells %d and %d overlap at %s", at, h[i].cell, h[i + 1].cell, va)
                 : sl_diag_set(d, SL_EBADINPUT,
                               "%scells %d and %d overlap: both lie on the same side of their shared edge "
                               "between %s and %s (a folded or tangled mesh)",
                               at, h[i].cell, h[i + 1].cell, va, vb);
        goto fail;
      }
    }
    for (long k = i; k < j; ++k) {
      first[k] = (int)i;
      pos[(size_t)h[k].cell * nf + h[k].local] = (int)k;
    }
    i = j;
  }

  /* Number the faces by first appearance in cell order: the owner is then
   * the lower-numbered cell and neighbouring faces get nearby numbers. */
  for (long i = 0; i < nh; ++i) face_of[i] = -1;
  int n_faces = 0;
  for (long i = 0; i < nh; ++i)
    if (first[i] == i) ++n_faces;
  m->n_faces = n_faces;
  m->cell_faces = malloc((size_t)nh * sizeof *m->cell_faces);
  m->face_vertices = malloc(2 * (size_t)n_faces * sizeof *m->face_vertices);
  m->face_cells = malloc(2 * (size_t)n_faces * sizeof *m->face_cells);
  m->face_local = malloc(2 * (size_t)n_faces * sizeof *m->face_local);
  m->face_tag = malloc((size_t)n_faces * sizeof *m->face_tag);
  if (!m->cell_faces || !m->face_vertices || !m->face_cells || !m->face_local || !m->face_tag) {
    rc = sl_diag_set(d, SL_ENOMEM, "out of memory building %d faces", n_faces);
    goto fail;
  }
  int next = 0;
  for (int c = 0; c < m->n_cells; ++c)
    for (int k = 0; k < nf; ++k) {
      int g = first[pos[(size_t)c * nf + k]];
      int f = face_of[g];
      if (f < 0) {
        f = face_of[g] = next++;
        m->face_vertices[2 * f] = face_first_vertex(m, c, k);
        m->face_vertices[2 * f + 1] = face_second_vertex(m, c, k);
        m->face_cells[2 * f] = c;
        m->face_local[2 * f] = k;
        m->face_cells[2 * f + 1] = -1;
        m->face_local[2 * f + 1] = -1;
        m->face_tag[f] = -1;
      } else {
        m->face_cells[2 * f + 1] = c;
        m->face_local[2 * f + 1] = k;
      }
      m->cell_faces[(size_t)c * nf + k] = f;
    }
  m->n_boundary_faces = 0;
  for (int f = 0; f < n_faces; ++f)
    if (m->face_cells[2 * f + 1] < 0) ++m->n_boundary_faces;
  /* Keep, per sorted index, the face number (for the side look-up). */
  for (long i = 0; i < nh; ++i) face_of[i] = face_of[first[i]];
  free(pos);
  free(first);
  *sorted_out = h;
  *face_of_sorted_out = face_of;
  return 0;
fail:
  free(h);
  free(pos);
  free(first);
  free(face_of);
  return rc;
}

/* Tags boundary faces from the spec's sides, then checks every boundary
 * face got one and builds the per-boundary face lists. */
static int tag_boundaries(sl_mesh *m, const sl_mesh_spec *s, const half_face *h, const int *face_of, sl_diag *d) {
  const long nh = (long)m->n_cells * m->nf_per_cell;
  const int per_side = m->dim == 1 ? 1 : 2;
  for (int i = 0; i < s->n_sides; ++i) {
    int a = s->side_vertices[per_side * i], b = m->dim == 1 ? a : s->side_vertices[per_side * i + 1];
    int t = s->side_tag[i];
    long k = find_key(h, nh, a < b ? a : b, a < b ? b : a);
    int f = k < 0 ? -1 : face_of[k];
    if (k >= 0 && m->face_cells[2 * f + 1] < 0 && (m->face_tag[f] < 0 || m->face_tag[f] == t)) {
      m->face_tag[f] = t;
      continue;
    }
    char at[512], va[160], vb[160];
    where(at, sizeof at, s->source, s->side_line, i);
    describe_vertex(m, a, va, sizeof va);
    describe_vertex(m, b, vb, sizeof vb);
    if (k < 0) {
      if (m->dim == 1) return sl_diag_set(d, SL_EBADINPUT, "%sboundary point %s is not an end of any cell", at, va);
      return sl_diag_set(d, SL_EBADINPUT, "%sboundary side from %s to %s is not an edge of any cell", at, va, vb);
    }
    if (m->face_cells[2 * f + 1] >= 0) {
      if (m->dim == 1)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%sboundary point %s of \"%s\" lies inside the domain (between cells %d and %d)", at, va,
                           m->boundary_names[t], m->face_cells[2 * f], m->face_cells[2 * f + 1]);
      return sl_diag_set(d, SL_EBADINPUT,
                         "%sboundary side from %s to %s of \"%s\" lies inside the domain (between cells %d and %d); "
                         "boundaries must be on the domain's boundary",
                         at, va, vb, m->boundary_names[t], m->face_cells[2 * f], m->face_cells[2 * f + 1]);
    }
    return sl_diag_set(d, SL_EBADINPUT, "%sthe boundary face at %s%s%s is on two boundaries, \"%s\" and \"%s\"", at, va,
                       m->dim == 1 ? "" : " - ", m->dim == 1 ? "" : vb, m->boundary_names[m->face_tag[f]],
                       m->boundary_names[t]);
  }
  for (int f = 0; f < m->n_faces; ++f)
    if (m->face_cells[2 * f + 1] < 0 && m->face_tag[f] < 0) {
      char va[160], vb[160];
      describe_vertex(m, m->face_vertices[2 * f], va, sizeof va);
      if (m->dim == 1)
        return sl_diag_set(d, SL_EBADINPUT, "%s%sboundary point %s carries no boundary tag%s",
                           s->source ? s->source : "", s->source ? ": " : "", va,
                           s->source ? " (in a Gmsh file: it is in no physical point group)" : "");
      describe_vertex(m, m->face_vertices[2 * f + 1], vb, sizeof vb);
      return sl_diag_set(d, SL_EBADINPUT, "%s%sthe boundary face from %s to %s carries no boundary tag%s",
                         s->source ? s->source : "", s->source ? ": " : "", va, vb,
                         s->source ? " (in a Gmsh file: the curve through it is in no physical curve group)" : "");
    }

  m->bface_start = calloc((size_t)m->n_boundaries + 1, sizeof *m->bface_start);
  m->bface = malloc(((size_t)m->n_boundary_faces + 1) * sizeof *m->bface);
  if (!m->bface_start || !m->bface) return sl_diag_set(d, SL_ENOMEM, "out of memory listing boundary faces");
  for (int f = 0; f < m->n_faces; ++f)
    if (m->face_tag[f] >= 0) ++m->bface_start[m->face_tag[f] + 1];
  for (int b = 0; b < m->n_boundaries; ++b) m->bface_start[b + 1] += m->bface_start[b];
  int *fill = malloc(((size_t)m->n_boundaries + 1) * sizeof *fill);
  if (!fill) return sl_diag_set(d, SL_ENOMEM, "out of memory listing boundary faces");
  memcpy(fill, m->bface_start, (size_t)m->n_boundaries * sizeof *fill);
  for (int f = 0; f < m->n_faces; ++f)
    if (m->face_tag[f] >= 0) m->bface[fill[m->face_tag[f]]++] = f;
  free(fill);
  return 0;
}

/* ---- second-order geometry ---------------------------------------------- */

/* The spec's face and centre nodes onto the faces; straight meshes stay
 * geom_order 1. */
static int set_curved(sl_mesh *m, const sl_mesh_spec *s, sl_diag *d) {
  const int nf = m->nf_per_cell, quad = m->cell_type == SL_CELL_QUAD4;
  if (quad && !s->cell_centre)
    return sl_diag_set(d, SL_EBADINPUT, "a second-order quadrilateral mesh needs its centre nodes");
  m->face_mid = malloc(2 * (size_t)m->n_faces * sizeof *m->face_mid);
  unsigned char *seen = calloc((size_t)m->n_faces + 1, 1);
  if (quad) m->cell_mid = malloc(2 * (size_t)m->n_cells * sizeof *m->cell_mid);
  if (!m->face_mid || !seen || (quad && !m->cell_mid)) {
    free(seen);
    return sl_diag_set(d, SL_ENOMEM, "out of memory for the second-order geometry of %d faces", m->n_faces);
  }
  double dev = 0; /* the largest distance of a node from its straight position, relative to the face length */
  for (int c = 0; c < m->n_cells; ++c)
    for (int k = 0; k < nf; ++k) {
      int f = m->cell_faces[(size_t)c * nf + k];
      const double *p = s->edge_mid + 2 * ((size_t)nf * c + k);
      const double *a = vx(m, m->face_vertices[2 * f]), *b = vx(m, m->face_vertices[2 * f + 1]);
      double len = hypot(b[0] - a[0], b[1] - a[1]);
      char at[512];
      if (!isfinite(p[0]) || !isfinite(p[1])) {
        where(at, sizeof at, s->source, s->cell_line, c);
        free(seen);
        return sl_diag_set(d, SL_EBADINPUT, "%scell %d: the node on its face %d has a non-finite coordinate", at, c, k);
      }
      if (seen[f]) {
        const double *q = m->face_mid + 2 * (size_t)f;
        if (hypot(q[0] - p[0], q[1] - p[1]) > 1e-9 * len) {
          where(at, sizeof at, s->source, s->cell_line, c);
          free(seen);
          return sl_diag_set(d, SL_EBADINPUT,
                             "%scells %d and %d give different nodes, (%.10g, %.10g) and (%.10g, %.10g), on their "
                             "shared face",
                             at, m->face_cells[2 * f], c, q[0], q[1], p[0], p[1]);
        }
        continue;
      }
      seen[f] = 1;
      m->face_mid[2 * (size_t)f] = p[0], m->face_mid[2 * (size_t)f + 1] = p[1];
      dev = fmax(dev, hypot(p[0] - 0.5 * (a[0] + b[0]), p[1] - 0.5 * (a[1] + b[1])) / len);
    }
  free(seen);
  for (int c = 0; quad && c < m->n_cells; ++c) {
    const double *p = s->cell_centre + 2 * (size_t)c;
    const int *cv = m->cell_vertices + 4 * (size_t)c;
    double cx = 0, cy = 0;
    for (int k = 0; k < 4; ++k) cx += 0.25 * vx(m, cv[k])[0], cy += 0.25 * vx(m, cv[k])[1];
    m->cell_mid[2 * (size_t)c] = p[0], m->cell_mid[2 * (size_t)c + 1] = p[1];
    dev = fmax(dev, hypot(p[0] - cx, p[1] - cy) / sqrt(fabs(sl_mesh_cell_area(m, c))));
  }
  if (!(dev > 1e-10)) { /* straight: the linear map is the same map (and cheaper) */
    free(m->face_mid), free(m->cell_mid);
    m->face_mid = m->cell_mid = NULL;
    return 0;
  }
  m->geom_order = 2;
  return sl_mesh_check_curved(m, s->source, s->cell_line, d);
}

/* ---- create ------------------------------------------------------------- */

static int copy_names(char ***dst, const char *const *src, int n, const char *what, sl_diag *d) {
  *dst = NULL;
  if (n == 0) return 0;
  char **names = calloc((size_t)n, sizeof *names);
  if (!names) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  *dst = names;
  for (int i = 0; i < n; ++i) {
    if (!src[i] || !src[i][0]) return sl_diag_set(d, SL_EBADINPUT, "%s %d has no name", what, i);
    for (int j = 0; j < i; ++j)
      if (strcmp(src[i], src[j]) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "two %ss are named \"%s\"; names must be unique", what, src[i]);
    if (!(names[i] = dup_string(src[i]))) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  }
  return 0;
}

static int validate_spec(const sl_mesh_spec *s, sl_diag *d) {
  if (s->dim != 1 && s->dim != 2)
    return sl_diag_set(d, SL_EBADINPUT, "mesh dimension %d: only 1 and 2 are supported", s->dim);
  if (s->dim == 1 && s->cell_type != SL_CELL_LINE2) return sl_diag_set(d, SL_EBADINPUT, "a 1-D mesh needs line2 cells");
  if (s->dim == 2 && s->cell_type != SL_CELL_TRI3 && s->cell_type != SL_CELL_QUAD4)
    return sl_diag_set(d, SL_EBADINPUT, "a 2-D mesh needs tri3 or quad4 cells");
  if (s->n_vertices < 1 || s->n_cells < 1 || !s->xy || !s->cell_vertices)
    return sl_diag_set(d, SL_EBADINPUT, "a mesh needs at least one cell (got %d vertices, %d cells)", s->n_vertices,
                       s->n_cells);
  if ((long long)s->n_cells * s->cell_type > 0x3fffffff || s->n_vertices > 0x3fffffff)
    return sl_diag_set(d, SL_EBADINPUT, "mesh too large (%d cells)", s->n_cells);
  if (s->n_boundaries < 0 || (s->n_boundaries > 0 && !s->boundary_names) || s->n_sides < 0 ||
      (s->n_sides > 0 && (!s->side_vertices || !s->side_tag)) || s->n_regions < 0 ||
      (s->n_regions > 0 && (!s->region_names || !s->cell_region)))
    return sl_diag_set(d, SL_EBADINPUT, "inconsistent mesh specification (names, sides or regions missing)");
  char at[512];
  for (int v = 0; v < s->n_vertices; ++v) {
    double x = s->xy[2 * v], y = s->xy[2 * v + 1];
    if (!isfinite(x) || !isfinite(y))
      return sl_diag_set(d, SL_EBADINPUT, "%s%svertex %d has a non-finite coordinate", s->source ? s->source : "",
                         s->source ? ": " : "", v);
    if (s->dim == 1 && y != 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s%svertex %d has y = %g: a 1-D mesh lies on the x axis",
                         s->source ? s->source : "", s->source ? ": " : "", v, y);
  }
  for (int c = 0; c < s->n_cells; ++c)
    for (int k = 0; k < (int)s->cell_type; ++k) {
      int v = s->cell_vertices[(size_t)c * s->cell_type + k];
      if (v < 0 || v >= s->n_vertices) {
        where(at, sizeof at, s->source, s->cell_line, c);
        return sl_diag_set(d, SL_EBADINPUT, "%scell %d refers to vertex %d, outside 0..%d", at, c, v,
                           s->n_vertices - 1);
      }
    }
  const int per_side = s->dim == 1 ? 1 : 2;
  for (int i = 0; i < s->n_sides; ++i) {
    where(at, sizeof at, s->source, s->side_line, i);
    for (int k = 0; k < per_side; ++k) {
      int v = s->side_vertices[per_side * i + k];
      if (v < 0 || v >= s->n_vertices)
        return sl_diag_set(d, SL_EBADINPUT, "%sboundary side %d refers to vertex %d, outside 0..%d", at, i, v,
                           s->n_vertices - 1);
    }
    if (s->side_tag[i] < 0 || s->side_tag[i] >= s->n_boundaries)
      return sl_diag_set(d, SL_EBADINPUT, "%sboundary side %d has tag %d, outside 0..%d", at, i, s->side_tag[i],
                         s->n_boundaries - 1);
  }
  if (s->n_regions > 0)
    for (int c = 0; c < s->n_cells; ++c)
      if (s->cell_region[c] < -1 || s->cell_region[c] >= s->n_regions) {
        where(at, sizeof at, s->source, s->cell_line, c);
        return sl_diag_set(d, SL_EBADINPUT, "%scell %d has region %d, outside -1..%d", at, c, s->cell_region[c],
                           s->n_regions - 1);
      }
  return 0;
}

int sl_mesh_create(const sl_mesh_spec *s, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  half_face *h = NULL;
  int *face_of = NULL;
  int rc = validate_spec(s, d);
  if (rc) return rc;
  sl_mesh *m = calloc(1, sizeof *m);
  if (!m) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  m->dim = s->dim;
  m->cell_type = s->cell_type;
  m->nv_per_cell = (int)s->cell_type;
  m->nf_per_cell = s->dim == 1 ? 2 : (int)s->cell_type;
  m->n_vertices = s->n_vertices;
  m->n_cells = s->n_cells;
  size_t ncv = (size_t)s->n_cells * m->nv_per_cell;
  m->xy = malloc(2 * (size_t)s->n_vertices * sizeof *m->xy);
  m->cell_vertices = malloc(ncv * sizeof *m->cell_vertices);
  if (!m->xy || !m->cell_vertices) {
    rc = sl_diag_set(d, SL_ENOMEM, "out of memory for a mesh of %d cells", s->n_cells);
    goto fail;
  }
  memcpy(m->xy, s->xy, 2 * (size_t)s->n_vertices * sizeof *m->xy);
  memcpy(m->cell_vertices, s->cell_vertices, ncv * sizeof *m->cell_vertices);
  /* Names are copied before counts are set so destroy frees only what exists. */
  rc = copy_names(&m->boundary_names, s->boundary_names, s->n_boundaries, "boundary", d);
  m->n_boundaries = s->n_boundaries;
  if (rc) goto fail;
  if (s->n_regions > 0) {
    rc = copy_names(&m->region_names, s->region_names, s->n_regions, "region", d);
    m->n_regions = s->n_regions;
    if (rc) goto fail;
    m->cell_region = malloc((size_t)s->n_cells * sizeof *m->cell_region);
    if (!m->cell_region) {
      rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
      goto fail;
    }
    memcpy(m->cell_region, s->cell_region, (size_t)s->n_cells * sizeof *m->cell_region);
  }
  /* Cells first: an inverted cell would otherwise surface as an overlap. */
  rc = check_cells(m, s->source, s->cell_line, d);
  if (rc) goto fail;
  rc = build_faces(m, s->source, s->cell_line, &h, &face_of, d);
  if (rc) goto fail;
  rc = tag_boundaries(m, s, h, face_of, d);
  free(h);
  free(face_of);
  if (rc) goto fail;
  m->geom_order = 1;
  if (s->edge_mid && m->dim == 2 && (rc = set_curved(m, s, d))) goto fail;
  *out = m;
  return 0;
fail:
  sl_mesh_destroy(m);
  return rc;
}

/* ---- names ------------------------------------------------------------- */

int sl_mesh_scene_name(const char *name, char *out, size_t size) {
  if (!size) return 0;
  size_t n = strlen(name), k = 0;
  int changed = 0;
  for (size_t i = 0; i < n && k + 1 < size; ++i) {
    char c = name[i];
    int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (c == '.') ok = i > 0 && i + 1 < n && name[i - 1] != '.' && name[i + 1] != '.';
    out[k++] = ok ? c : '_';
    changed |= !ok;
  }
  out[k] = '\0';
  return changed || k < n;
}

static int name_id(char *const *names, int n, const char *kind, const char *kinds, const char *name, int *id,
                   sl_diag *d) {
  for (int i = 0; i < n; ++i)
    if (strcmp(names[i], name) == 0) {
      *id = i;
      return 0;
    }
  *id = -1;
  if (n == 0) return sl_diag_set(d, SL_EBADINPUT, "the mesh has no %s named \"%s\": it has no %s", kind, name, kinds);
  char list[1024];
  size_t used = 0;
  list[0] = '\0';
  for (int i = 0; i < n && used < sizeof list; ++i) {
    int w = snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", names[i]);
    if (w < 0) break;
    used += (size_t)w;
  }
  const char *hint = sl_suggest(name, (const char *const *)names, n);
  if (hint)
    return sl_diag_set(d, SL_EBADINPUT, "the mesh has no %s named \"%s\"; did you mean \"%s\"? (%s: %s)", kind, name,
                       hint, kinds, list);
  return sl_diag_set(d, SL_EBADINPUT, "the mesh has no %s named \"%s\" (%s: %s)", kind, name, kinds, list);
}

int sl_mesh_boundary_id(const sl_mesh *m, const char *name, int *id, sl_diag *d) {
  return name_id(m->boundary_names, m->n_boundaries, "boundary", "boundaries", name, id, d);
}

int sl_mesh_region_id(const sl_mesh *m, const char *name, int *id, sl_diag *d) {
  return name_id(m->region_names, m->n_regions, "region", "regions", name, id, d);
}

/* ---- geometry ---------------------------------------------------------- */

double sl_mesh_cell_area(const sl_mesh *m, int c) {
  const int *cv = m->cell_vertices + (size_t)c * m->nv_per_cell;
  const double *p0 = vx(m, cv[0]), *p1 = vx(m, cv[1]);
  if (m->dim == 1) return p1[0] - p0[0];
  const double *p2 = vx(m, cv[2]);
  if (m->cell_type == SL_CELL_TRI3)
    return 0.5 * ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]));
  /* Quadrilateral: A = (d1 x d2) / 2 with the diagonals d1 = p2 - p0, d2 = p3 - p1. */
  const double *p3 = vx(m, cv[3]);
  return 0.5 * ((p2[0] - p0[0]) * (p3[1] - p1[1]) - (p2[1] - p0[1]) * (p3[0] - p1[0]));
}

void sl_mesh_cell_centroid(const sl_mesh *m, int c, double centroid[2]) {
  const int *cv = m->cell_vertices + (size_t)c * m->nv_per_cell;
  const double *p0 = vx(m, cv[0]);
  if (m->dim == 1) {
    centroid[0] = 0.5 * (p0[0] + vx(m, cv[1])[0]);
    centroid[1] = 0;
    return;
  }
  /* Fan of triangles from p0 (relative coordinates, against cancellation):
   * the centroid is the area-weighted mean of the triangles' centroids. */
  double sa = 0, sx = 0, sy = 0;
  for (int k = 1; k + 1 < m->nv_per_cell; ++k) {
    const double *a = vx(m, cv[k]), *b = vx(m, cv[k + 1]);
    double ax = a[0] - p0[0], ay = a[1] - p0[1], bx = b[0] - p0[0], by = b[1] - p0[1];
    double t = 0.5 * (ax * by - ay * bx);
    sa += t;
    sx += t * (ax + bx) / 3;
    sy += t * (ay + by) / 3;
  }
  centroid[0] = p0[0] + sx / sa;
  centroid[1] = p0[1] + sy / sa;
}

double sl_mesh_face_length(const sl_mesh *m, int f) {
  if (m->dim == 1) return 1.0;
  const double *a = vx(m, m->face_vertices[2 * f]), *b = vx(m, m->face_vertices[2 * f + 1]);
  return hypot(b[0] - a[0], b[1] - a[1]);
}

void sl_mesh_face_normal(const sl_mesh *m, int f, double n[2]) {
  if (m->dim == 1) {
    /* Local face 0 is the owner's left end. */
    n[0] = m->face_local[2 * f] == 0 ? -1.0 : 1.0;
    n[1] = 0;
    return;
  }
  /* The owner runs a -> b counter-clockwise: its outward normal is (dy, -dx). */
  const double *a = vx(m, m->face_vertices[2 * f]), *b = vx(m, m->face_vertices[2 * f + 1]);
  double dx = b[0] - a[0], dy = b[1] - a[1], len = hypot(dx, dy);
  n[0] = dy / len;
  n[1] = -dx / len;
}

void sl_mesh_face_centroid(const sl_mesh *m, int f, double c[2]) {
  const double *a = vx(m, m->face_vertices[2 * f]);
  if (m->dim == 1) {
    c[0] = a[0];
    c[1] = 0;
    return;
  }
  const double *b = vx(m, m->face_vertices[2 * f + 1]);
  c[0] = 0.5 * (a[0] + b[0]);
  c[1] = 0.5 * (a[1] + b[1]);
}

/* ---- quality ----------------------------------------------------------- */

void sl_mesh_quality_compute(const sl_mesh *m, sl_mesh_quality *q) {
  memset(q, 0, sizeof *q);
  q->min_area = HUGE_VAL;
  q->max_area = -HUGE_VAL;
  q->min_angle = m->dim == 1 ? 0 : HUGE_VAL;
  q->max_aspect = 1;
  q->max_size_jump = 1;
  const int nv = m->nv_per_cell;
  for (int c = 0; c < m->n_cells; ++c) {
    double a = sl_mesh_cell_area(m, c);
    if (a < q->min_area) q->min_area = a, q->min_area_cell = c;
    if (a > q->max_area) q->max_area = a, q->max_area_cell = c;
    if (m->dim == 1) continue;
    const int *cv = m->cell_vertices + (size_t)c * nv;
    double emin = HUGE_VAL, emax = 0;
    for (int k = 0; k < nv; ++k) {
      const double *p = vx(m, cv[k]), *pn = vx(m, cv[(k + 1) % nv]), *pp = vx(m, cv[(k + nv - 1) % nv]);
      double e1x = pn[0] - p[0], e1y = pn[1] - p[1], e2x = pp[0] - p[0], e2y = pp[1] - p[1];
      double ang = atan2(e1x * e2y - e1y * e2x, e1x * e2x + e1y * e2y);
      if (ang < q->min_angle) q->min_angle = ang, q->min_angle_cell = c;
      if (ang > q->max_angle) q->max_angle = ang;
      double len = hypot(e1x, e1y);
      if (len < emin) emin = len;
      if (len > emax) emax = len;
    }
    if (emax / emin > q->max_aspect) q->max_aspect = emax / emin, q->max_aspect_cell = c;
  }
  for (int f = 0; f < m->n_faces; ++f) {
    int c1 = m->face_cells[2 * f + 1];
    if (c1 < 0) continue;
    double a0 = sl_mesh_cell_area(m, m->face_cells[2 * f]), a1 = sl_mesh_cell_area(m, c1);
    double jump = a0 > a1 ? a0 / a1 : a1 / a0;
    if (jump > q->max_size_jump) q->max_size_jump = jump;
  }
}

void sl_mesh_print_report(const sl_mesh *m, FILE *out) {
  sl_mesh_quality q;
  sl_mesh_quality_compute(m, &q);
  fprintf(out, "mesh: %d-D, %d %s cells%s, %d vertices, %d faces (%d on the boundary)\n", m->dim, m->n_cells,
          sl_cell_type_name(m->cell_type), m->geom_order == 2 ? " with second-order (curved) geometry" : "",
          m->n_vertices, m->n_faces, m->n_boundary_faces);
  fprintf(out, "  boundaries:");
  for (int b = 0; b < m->n_boundaries; ++b) {
    double len = 0;
    for (int i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) len += sl_mesh_face_arc_length(m, m->bface[i]);
    int nb = m->bface_start[b + 1] - m->bface_start[b];
    if (m->dim == 1) fprintf(out, "%s %s (%d point%s)", b ? "," : "", m->boundary_names[b], nb, nb == 1 ? "" : "s");
    else
      fprintf(out, "%s %s (%d face%s, length %.6g)", b ? "," : "", m->boundary_names[b], nb, nb == 1 ? "" : "s", len);
  }
  fputc('\n', out);
  if (m->n_regions > 0) {
    fprintf(out, "  regions:");
    for (int r = 0; r < m->n_regions; ++r) {
      int n = 0;
      for (int c = 0; c < m->n_cells; ++c) n += m->cell_region[c] == r;
      fprintf(out, "%s %s (%d cell%s)", r ? "," : "", m->region_names[r], n, n == 1 ? "" : "s");
    }
    fputc('\n', out);
  }
  /* where the smallest and largest cells are: a graded mesh shows which way it is refined */
  const char *what = m->dim == 1 ? "length" : "area";
  double c_min[2], c_max[2];
  sl_mesh_cell_centroid(m, q.min_area_cell, c_min);
  sl_mesh_cell_centroid(m, q.max_area_cell, c_max);
  if (m->dim == 1)
    fprintf(out, "  cell %s %.6g (cell %d at x = %.4g) .. %.6g (cell %d at x = %.4g), largest neighbour ratio %.4g\n",
            what, q.min_area, q.min_area_cell, c_min[0], q.max_area, q.max_area_cell, c_max[0], q.max_size_jump);
  else
    fprintf(out,
            "  cell %s %.6g (cell %d at (%.4g, %.4g)) .. %.6g (cell %d at (%.4g, %.4g)), largest neighbour ratio "
            "%.4g\n",
            what, q.min_area, q.min_area_cell, c_min[0], c_min[1], q.max_area, q.max_area_cell, c_max[0], c_max[1],
            q.max_size_jump);
  if (m->dim == 2) {
    const double deg = 180 / acos(-1.0);
    fprintf(out, "  angles %.4g .. %.4g deg (smallest in cell %d), max aspect ratio %.4g (cell %d)\n",
            q.min_angle * deg, q.max_angle * deg, q.min_angle_cell, q.max_aspect, q.max_aspect_cell);
  }
}
