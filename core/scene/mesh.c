/* The mesh a scene's [mesh] section describes (see mesh.h). */
#include "core/scene/mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/scene/scene.h"

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
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s = %s: expected geometric:RATIO or symmetric:RATIO",
                         e->file, e->line, key, s);
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
      return sl_mesh_interval(x[0], x[1], n[0], &o.grade_x, out, d);
    case 1: /* rectangle */
      if ((rc = range(sc, &c->x, "x", x, d)) || (rc = range(sc, &c->y, "y", y, d)) || (rc = cells(sc, 2, n, d)))
        return rc;
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
      return sl_mesh_annulus(x[0], x[1], y[0], y[1], n[0], n[1], &o, out, d);
    case 3: { /* inclined box */
      double origin[2] = {c->origin.n > 0 ? c->origin.v[0] : 0.0, c->origin.n > 1 ? c->origin.v[1] : 0.0};
      if (!sl_scene_given(sc, &c->width)) return missing(sc, "width", d);
      if (!sl_scene_given(sc, &c->height)) return missing(sc, "height", d);
      if ((rc = cells(sc, 2, n, d))) return rc;
      return sl_mesh_inclined_box(origin[0], origin[1], c->width, c->height, c->angle, n[0], n[1], &o, out, d);
    }
    default: { /* gmsh, relative to the scene file */
      const sl_src *e = sl_scene_src(sc, &c->file);
      if (!e) return missing(sc, "file", d);
      char *path = sl_ini_path_relative(e->file, c->file);
      if (!path) return sl_diag_set(d, SL_ENOMEM, "mesh: out of memory");
      rc = sl_mesh_read_gmsh(path, out, d);
      free(path);
      return rc;
    }
  }
}

int sl_scene_line_chain(const sl_mesh *m, int *vertex, int *cell, sl_diag *d) {
  if (m->dim != 1) return sl_diag_set(d, SL_EBADINPUT, "the mesh is %d-D; a 1-D mesh (geometry = line) is needed", m->dim);
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
