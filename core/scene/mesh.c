/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The mesh a scene's [mesh] section describes (see mesh.h). */
#include "core/scene/mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/scene/scene.h"
#include "core/scene/schema.h"

/* Degenerate meshes: the smallest cell must be at least SIZE_RATIO times the
 * larger of the domain's extent and its largest coordinate (a grading or an
 * aspect ratio beyond 1e10, or cells that the coordinates' 16 digits cannot
 * resolve, make the matrices singular to round-off), and the extent must
 * lie in [MIN_EXTENT, MAX_EXTENT] metres. */
#define SIZE_RATIO 1e-10
#define MIN_EXTENT 1e-12
#define MAX_EXTENT 1e12

/* Bytes per cell that a 2-D run needs at least: the Taylor-Hood flow's matrix
 * (about 530 non-zeros a Q2/Q1 cell, 12 bytes each) and as much again for
 * the vectors, the mesh and a factorisation no larger than the matrix. The
 * factorisations measured need 60-80 kB a cell (UMFPACK, cavity 64^2 and
 * 128^2), so this is a lower bound: a run refused with it could not have run.
 * 1-D meshes: 1 kB a cell (banded systems). */
#define BYTES_PER_CELL_2D 16384.0
#define BYTES_PER_CELL_1D 1024.0

/* The machine's memory, MemTotal of /proc/meminfo (bytes), or 0 when unknown. */
static double machine_memory(void) {
  FILE *f = fopen("/proc/meminfo", "r");
  if (!f) return 0;
  char line[256];
  double kb = 0;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "MemTotal: %lf kB", &kb) == 1) break;
  fclose(f);
  return kb * 1024.0;
}

/* Refuses, before anything is allocated, a mesh whose run cannot fit: the
 * estimate against [mesh] memory_limit, or the machine's memory. */
static int check_memory_at(const sl_scene *sc, const char *where, double n_cells, int dim, sl_diag *d) {
  double need = n_cells * (dim == 1 ? BYTES_PER_CELL_1D : BYTES_PER_CELL_2D);
  double limit = sc->mesh_config.memory_limit, have = limit > 0 ? limit : machine_memory();
  if (!(have > 0) || need <= have) return 0;
  return sl_diag_set(d, SL_EBADINPUT,
                     "%s: %.0f cells need at least %.3g GB (%.0f kB a cell; a direct solver's factorisation needs "
                     "several times more), more than the %.3g GB %s; set [mesh] memory_limit = <bytes> to allow it",
                     where, n_cells, need / 1e9, need / n_cells / 1024, have / 1e9,
                     limit > 0 ? "of [mesh] memory_limit" : "this machine has (MemTotal in /proc/meminfo)");
}

static int check_memory(const sl_scene *sc, double n_cells, int dim, sl_diag *d) {
  const sl_src *e = sl_scene_src(sc, &sc->mesh_config.cells);
  char where[600];
  snprintf(where, sizeof where, "%s:%d: [mesh] cells", e ? e->file : "?", e ? e->line : 0);
  return check_memory_at(sc, where, n_cells, dim, d);
}

/* The graded points of one direction must give cells of a size the solver
 * can use (see SIZE_RATIO). key: the range's key; gkey: its grading's. */
static int check_spacing(const sl_scene *sc, const void *range_field, const char *key, const char *gkey,
                         const void *grading_field, double a, double b, int n, const sl_grading *g, double extent,
                         sl_diag *d) {
  const sl_src *e = sl_scene_src(sc, range_field);
  const sl_src *eg = sl_scene_src(sc, grading_field);
  if (!(extent >= MIN_EXTENT && extent <= MAX_EXTENT))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [mesh] %s: the domain's largest extent is %g m, outside [%g, %g] m (lengths are in "
                       "metres)",
                       e ? e->file : "?", e ? e->line : 0, key, extent, MIN_EXTENT, MAX_EXTENT);
  double *x = malloc(((size_t)n + 1) * sizeof *x);
  if (!x) return sl_diag_set(d, SL_ENOMEM, "mesh: out of memory");
  sl_diag inner;
  int rc = sl_mesh_graded_points(a, b, n, g, x, &inner);
  double hmin = HUGE_VAL;
  for (int i = 0; i < n && !rc; ++i) hmin = fmin(hmin, x[i + 1] - x[i]);
  free(x);
  const sl_src *at = g && g->kind != SL_GRADE_UNIFORM && g->ratio != 1 && eg ? eg : e;
  const char *what = at == eg ? gkey : key;
  if (rc)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s: %s", at ? at->file : "?", at ? at->line : 0, what,
                       inner.msg);
  double scale = fmax(extent, fmax(fabs(a), fabs(b)));
  if (!(hmin >= SIZE_RATIO * scale))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [mesh] %s: the smallest cell along %s is %g m, less than %g times the domain's size "
                       "%g m: a degenerate mesh (allowed: cells of at least %g m)",
                       at ? at->file : "?", at ? at->line : 0, what, key, hmin, SIZE_RATIO, scale, SIZE_RATIO * scale);
  return 0;
}

/* A mesh from a file: the same test on its faces (every edge at least
 * SIZE_RATIO times the bounding box's size and the largest coordinate). */
static int check_read_mesh(const char *path, const sl_mesh *m, sl_diag *d) {
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, big = 0;
  for (int v = 0; v < m->n_vertices; ++v)
    for (int i = 0; i < 2; ++i) {
      double c = m->xy[2 * v + i];
      lo[i] = fmin(lo[i], c), hi[i] = fmax(hi[i], c), big = fmax(big, fabs(c));
    }
  double extent = fmax(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(extent >= MIN_EXTENT && extent <= MAX_EXTENT))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: the mesh's largest extent is %g m, outside [%g, %g] m (lengths are in metres)", path,
                       extent, MIN_EXTENT, MAX_EXTENT);
  double scale = fmax(extent, big);
  for (int f = 0; f < m->n_faces && m->dim == 2; ++f) {
    double len = sl_mesh_face_length(m, f);
    if (len >= SIZE_RATIO * scale) continue;
    const double *a = m->xy + 2 * m->face_vertices[2 * f];
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: the edge at (%g, %g) is %g m long, less than %g times the mesh's size %g m: a degenerate "
                       "mesh",
                       path, a[0], a[1], len, SIZE_RATIO, scale);
  }
  for (int c = 0; c < m->n_cells && m->dim == 1; ++c) {
    double len = sl_mesh_cell_area(m, c);
    if (len >= SIZE_RATIO * scale) continue;
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: cell %d is %g m long, less than %g times the mesh's size %g m: a degenerate mesh", path, c,
                       len, SIZE_RATIO, scale);
  }
  return 0;
}

/* A physical boundary the scene does not name (by its own section or as the
 * partner of a periodic pair) gets the model's default type (a wall for the
 * flow models): say so, once per boundary. */
static void warn_unnamed(const sl_scene *sc, const char *path, const sl_mesh *m) {
  const sl_key *type = sc->schema ? sl_schema_key(sc->schema, "boundary", "type") : NULL;
  char def[64] = "its default";
  if (type && type->choices) {
    const char *p = type->choices;
    for (int k = 0; k < (int)type->def && *p; ++k) p += strcspn(p, "|"), p += *p == '|';
    snprintf(def, sizeof def, "type = %.*s", (int)strcspn(p, "|"), p);
  }
  for (int b = 0; b < m->n_boundaries; ++b) {
    char name[300];
    snprintf(name, sizeof name, "boundary.%s", m->boundary_names[b]);
    if (sl_ini_find_section(sc->ini, name)) continue;
    int partner = 0; /* the partner of a periodic pair takes its type from the pair */
    for (int i = 0; i < sc->ini->n_sections && !partner; ++i) {
      const sl_ini_section *sec = &sc->ini->sections[i];
      if (strncmp(sec->name, "boundary.", 9) != 0) continue;
      const sl_ini_entry *e = sl_ini_find(sc->ini, sec->name, "partner");
      partner = e && strcmp(e->value, m->boundary_names[b]) == 0;
    }
    if (partner) continue;
    fprintf(stderr, "sluice: warning: %s: the physical boundary '%s' has no [%s] section in the scene: it gets %s\n",
            path, m->boundary_names[b], name, def);
  }
}

/* "geometric:1.5", "symmetric:2" or a bare ratio (geometric). */
static int grading(const sl_scene *sc, const char *const *text, const char *key, sl_grading *g, sl_diag *d) {
  const char *s = *text;
  if (!s || !*s) return 0;
  const sl_src *e = sl_scene_src(sc, text);
  const char *colon = strchr(s, ':');
  g->kind = SL_GRADE_GEOMETRIC;
  const char *num = s;
  if (colon) {
    if (strncmp(s, "geometric", (size_t)(colon - s)) == 0 && colon - s == 9) g->kind = SL_GRADE_GEOMETRIC;
    else if (strncmp(s, "symmetric", (size_t)(colon - s)) == 0 && colon - s == 9) g->kind = SL_GRADE_SYMMETRIC;
    else
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s = %s: expected geometric:RATIO or symmetric:RATIO", e->file,
                         e->line, key, s);
    num = colon + 1;
  }
  if (sl_parse_real(num, &g->ratio) || !(g->ratio > 0.0))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s: '%s' is not a positive ratio", e->file, e->line, key, num);
  return 0;
}

/* A required key of the generator that the scene does not give. */
static int missing(const sl_scene *sc, const char *key, sl_diag *d) {
  const sl_ini_section *s = sl_ini_find_section(sc->ini, "mesh");
  return sl_diag_set(d, SL_EBADINPUT, "%s:%d:1: error: [mesh] is missing the required key '%s'", s ? s->file : "?",
                     s ? s->line : 0, key);
}

static int range(const sl_scene *sc, const sl_reals *r, const char *key, double v[2], sl_diag *d) {
  const sl_src *e = sl_scene_src(sc, r);
  if (!e) return missing(sc, key, d);
  if (r->n != 2 || !(r->v[1] > r->v[0]))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s: expected two increasing numbers, e.g. %s = 0, 1", e->file,
                       e->line, key, key);
  v[0] = r->v[0], v[1] = r->v[1];
  return 0;
}

static int cells(const sl_scene *sc, int want, int n[2], sl_diag *d) {
  const sl_reals *r = &sc->mesh_config.cells;
  const sl_src *e = sl_scene_src(sc, r);
  if (!e) return missing(sc, "cells", d);
  double v[2] = {r->v[0], r->n > 1 ? r->v[1] : 0.0};
  int k = r->n;
  if (k == 1 && want == 2) v[1] = v[0], k = 2;
  for (int i = 0; i < k; ++i)
    if (v[i] < 1 || v[i] > 1e6 || v[i] != (int)v[i])
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] cells: %g is not a cell count in [1, 1000000]", e->file,
                         e->line, v[i]);
  if (k != want)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] cells: %d count%s given, %d expected", e->file, e->line, k,
                       k == 1 ? "" : "s", want);
  n[0] = (int)v[0], n[1] = want == 2 ? (int)v[1] : 1;
  return 0;
}

/* A 2-D structured grid: its memory, then both directions' cells. */
static int check_grid(const sl_scene *sc, const sl_grid_opts *o, const char *kx, const char *ky, const void *fx,
                      const void *fy, const double x[2], const double y[2], const int n[2], sl_diag *d) {
  const sl_mesh_config *c = &sc->mesh_config;
  double extent = fmax(x[1] - x[0], y[1] - y[0]);
  double n_cells = (double)n[0] * n[1] * (o->cell_type == SL_CELL_TRI3 ? 2 : 1);
  int rc = check_memory(sc, n_cells, 2, d);
  if (!rc) rc = check_spacing(sc, fx, kx, "grading_x", &c->grading_x, x[0], x[1], n[0], &o->grade_x, extent, d);
  if (!rc) rc = check_spacing(sc, fy, ky, "grading_y", &c->grading_y, y[0], y[1], n[1], &o->grade_y, extent, d);
  return rc;
}

int sl_scene_mesh_build(const sl_scene *sc, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  const sl_mesh_config *c = &sc->mesh_config;
  int rc;
  sl_grid_opts o = {0};
  o.cell_type = c->cell_type ? SL_CELL_TRI3 : SL_CELL_QUAD4;
  o.diagonal = (sl_diagonal)c->diagonal;
  if ((rc = grading(sc, &c->grading_x, "grading_x", &o.grade_x, d)) ||
      (rc = grading(sc, &c->grading_y, "grading_y", &o.grade_y, d)))
    return rc;
  double x[2], y[2];
  int n[2];
  switch (c->generator) {
    case 0: /* interval */
      if ((rc = range(sc, &c->x, "x", x, d)) || (rc = cells(sc, 1, n, d))) return rc;
      if ((rc = check_memory(sc, n[0], 1, d)) || (rc = check_spacing(sc, &c->x, "x", "grading_x", &c->grading_x, x[0],
                                                                     x[1], n[0], &o.grade_x, x[1] - x[0], d)))
        return rc;
      return sl_mesh_interval(x[0], x[1], n[0], &o.grade_x, out, d);
    case 1: /* rectangle */
      if ((rc = range(sc, &c->x, "x", x, d)) || (rc = range(sc, &c->y, "y", y, d)) || (rc = cells(sc, 2, n, d)))
        return rc;
      if ((rc = check_grid(sc, &o, "x", "y", &c->x, &c->y, x, y, n, d))) return rc;
      if ((rc = sl_mesh_rectangle(x[0], x[1], y[0], y[1], n[0], n[1], &o, out, d))) return rc;
      /* a parallelogram: x moves by shear (y - y0); the map has determinant 1, so cells keep their orientation */
      for (int v = 0; v < (*out)->n_vertices && c->shear != 0.0; ++v)
        (*out)->xy[2 * v] += c->shear * ((*out)->xy[2 * v + 1] - y[0]);
      return 0;
    case 2: /* annulus: (r, z) box */
      if ((rc = range(sc, &c->r, "r", x, d)) || (rc = range(sc, &c->z, "z", y, d)) || (rc = cells(sc, 2, n, d)))
        return rc;
      if (x[0] < 0.0) {
        const sl_src *e = sl_scene_src(sc, &c->r);
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] r: the inner radius %g is negative", e->file, e->line, x[0]);
      }
      if ((rc = check_grid(sc, &o, "r", "z", &c->r, &c->z, x, y, n, d))) return rc;
      return sl_mesh_annulus(x[0], x[1], y[0], y[1], n[0], n[1], &o, out, d);
    case 3: { /* inclined box */
      double origin[2] = {c->origin.n > 0 ? c->origin.v[0] : 0.0, c->origin.n > 1 ? c->origin.v[1] : 0.0};
      if (!sl_scene_given(sc, &c->width)) return missing(sc, "width", d);
      if (!sl_scene_given(sc, &c->height)) return missing(sc, "height", d);
      if ((rc = cells(sc, 2, n, d))) return rc;
      double w[2] = {0, c->width}, h[2] = {0, c->height};
      if ((rc = check_grid(sc, &o, "width", "height", &c->width, &c->height, w, h, n, d))) return rc;
      return sl_mesh_inclined_box(origin[0], origin[1], c->width, c->height, c->angle, n[0], n[1], &o, out, d);
    }
    default: { /* gmsh, relative to the scene file */
      const sl_src *e = sl_scene_src(sc, &c->file);
      if (!e) return missing(sc, "file", d);
      char *path = sl_ini_path_relative(e->file, c->file);
      if (!path) return sl_diag_set(d, SL_ENOMEM, "mesh: out of memory");
      sl_gmsh_opts go = {.split_quads = c->split_quads};
      rc = sl_mesh_read_gmsh_opts(path, &go, out, d);
      /* a mesh file's run: estimated once the mesh is read, before the model allocates its systems */
      if (!rc &&
          ((rc = check_read_mesh(path, *out, d)) || (rc = check_memory_at(sc, path, (*out)->n_cells, (*out)->dim, d))))
        sl_mesh_destroy(*out), *out = NULL;
      if (!rc) warn_unnamed(sc, path, *out);
      free(path);
      /* the scene's line that named the file, before what is wrong with it */
      if (rc == SL_EBADINPUT) sl_diag_prefix(d, rc, "%s:%d: [mesh] file", e->file, e->line);
      return rc;
    }
  }
}

int sl_scene_line_chain(const sl_mesh *m, int *vertex, int *cell, sl_diag *d) {
  if (m->dim != 1)
    return sl_diag_set(d, SL_EBADINPUT, "the mesh is %d-D; a 1-D mesh (geometry = line) is needed", m->dim);
  int n = m->n_cells;
  /* 1-D cells run towards increasing x: start at the vertex that begins a cell and ends none */
  int *next = malloc((size_t)m->n_vertices * sizeof *next), *cell_at = malloc((size_t)m->n_vertices * sizeof *cell_at);
  int *ends = calloc((size_t)m->n_vertices, sizeof *ends);
  if (!next || !cell_at || !ends) {
    free(next), free(cell_at), free(ends);
    return sl_diag_set(d, SL_ENOMEM, "mesh: out of memory");
  }
  for (int v = 0; v < m->n_vertices; ++v) next[v] = -1;
  for (int e = 0; e < n; ++e) {
    int a = m->cell_vertices[2 * e], b = m->cell_vertices[2 * e + 1];
    next[a] = b, cell_at[a] = e, ends[b] = 1;
  }
  int v = -1, ok = 1;
  for (int k = 0; k < m->n_vertices; ++k)
    if (next[k] >= 0 && !ends[k]) v = k;
  for (int i = 0; i < n && ok; ++i) {
    if (v < 0 || next[v] < 0) ok = 0;
    else vertex[i] = v, cell[i] = cell_at[v], v = next[v];
  }
  if (ok) vertex[n] = v;
  free(next), free(cell_at), free(ends);
  if (!ok || v < 0) return sl_diag_set(d, SL_EBADINPUT, "the 1-D mesh is not a single chain of cells");
  return 0;
}

static const char *line_end_name(const sl_mesh *m, int vertex) {
  for (int f = 0; f < m->n_faces; ++f)
    if (m->face_vertices[2 * f] == vertex && m->face_tag[f] >= 0) return m->boundary_names[m->face_tag[f]];
  return NULL;
}

int sl_scene_line_ends(const sl_mesh *m, int first, int last, const char *model, const char *names[2], sl_diag *d) {
  names[0] = line_end_name(m, first), names[1] = line_end_name(m, last);
  if (!names[0] || !names[1]) return sl_diag_set(d, SL_EBADINPUT, "%s: the line's ends carry no boundary tag", model);
  return 0;
}
