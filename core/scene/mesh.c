/* The mesh a scene's [mesh] section describes (see scene_mesh.h). */
#include "core/scene/mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const generators = "interval|rectangle|annulus|inclined_box|gmsh";

/* "geometric:1.5", "symmetric:2" or a bare ratio (geometric). */
static int grading(const sl_ini *ini, const char *key, sl_grading *g, sl_diag *d) {
  const char *s;
  int rc = sl_ini_get_string(ini, "mesh", key, 0, "", &s, d);
  if (rc || !*s) return rc;
  const sl_ini_entry *e = sl_ini_find(ini, "mesh", key);
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

static int range(const sl_ini *ini, const char *key, double v[2], sl_diag *d) {
  int n = 0, rc = sl_ini_get_real_list(ini, "mesh", key, 1, v, 2, &n, d);
  if (rc) return rc;
  const sl_ini_entry *e = sl_ini_find(ini, "mesh", key);
  if (n != 2 || !(v[1] > v[0]))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] %s: expected two increasing numbers, e.g. %s = 0, 1", e->file,
                       e->line, key, key);
  return 0;
}

static int cells(const sl_ini *ini, int want, int n[2], sl_diag *d) {
  double v[2];
  int k = 0, rc = sl_ini_get_real_list(ini, "mesh", "cells", 1, v, 2, &k, d);
  if (rc) return rc;
  const sl_ini_entry *e = sl_ini_find(ini, "mesh", "cells");
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

int sl_scene_mesh(const sl_ini *ini, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  int gen, rc = sl_ini_get_choice(ini, "mesh", "generator", 1, 0, generators, &gen, d);
  if (rc) return rc;
  sl_grid_opts o = {0};
  int type = 0, diag = 0;
  if ((rc = sl_ini_get_choice(ini, "mesh", "cell_type", 0, 0, "quad|tri", &type, d))) return rc;
  if ((rc = sl_ini_get_choice(ini, "mesh", "diagonal", 0, 0, "right|left|union_jack", &diag, d))) return rc;
  o.cell_type = type ? SL_CELL_TRI3 : SL_CELL_QUAD4;
  o.diagonal = (sl_diagonal)diag;
  if ((rc = grading(ini, "grading_x", &o.grade_x, d)) || (rc = grading(ini, "grading_y", &o.grade_y, d))) return rc;
  double x[2], y[2];
  int n[2];
  switch (gen) {
    case 0: /* interval */
      if ((rc = range(ini, "x", x, d)) || (rc = cells(ini, 1, n, d))) return rc;
      return sl_mesh_interval(x[0], x[1], n[0], &o.grade_x, out, d);
    case 1: /* rectangle */
      if ((rc = range(ini, "x", x, d)) || (rc = range(ini, "y", y, d)) || (rc = cells(ini, 2, n, d))) return rc;
      double shear;
      if ((rc = sl_ini_get_real(ini, "mesh", "shear", 0, 0.0, -10.0, 10.0, &shear, d))) return rc;
      if ((rc = sl_mesh_rectangle(x[0], x[1], y[0], y[1], n[0], n[1], &o, out, d))) return rc;
      /* a parallelogram: x moves by shear (y - y0); the map has determinant 1, so cells keep their orientation */
      for (int v = 0; v < (*out)->n_vertices && shear != 0.0; ++v)
        (*out)->xy[2 * v] += shear * ((*out)->xy[2 * v + 1] - y[0]);
      return 0;
    case 2: /* annulus: (r, z) box */
      if ((rc = range(ini, "r", x, d)) || (rc = range(ini, "z", y, d)) || (rc = cells(ini, 2, n, d))) return rc;
      if (x[0] < 0.0) {
        const sl_ini_entry *e = sl_ini_find(ini, "mesh", "r");
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [mesh] r: the inner radius %g is negative", e->file, e->line, x[0]);
      }
      return sl_mesh_annulus(x[0], x[1], y[0], y[1], n[0], n[1], &o, out, d);
    case 3: { /* inclined box */
      double origin[2] = {0, 0}, angle = 0.0, width, height;
      int k = 0;
      if ((rc = sl_ini_get_real_list(ini, "mesh", "origin", 0, origin, 2, &k, d))) return rc;
      if ((rc = sl_ini_get_real(ini, "mesh", "width", 1, 0, 1e-12, 1e12, &width, d))) return rc;
      if ((rc = sl_ini_get_real(ini, "mesh", "height", 1, 0, 1e-12, 1e12, &height, d))) return rc;
      if ((rc = sl_ini_get_real(ini, "mesh", "angle", 0, 0.0, -7.0, 7.0, &angle, d))) return rc;
      if ((rc = cells(ini, 2, n, d))) return rc;
      return sl_mesh_inclined_box(origin[0], origin[1], width, height, angle, n[0], n[1], &o, out, d);
    }
    default: { /* gmsh, relative to the scene file */
      const char *file;
      if ((rc = sl_ini_get_string(ini, "mesh", "file", 1, "", &file, d))) return rc;
      const sl_ini_entry *e = sl_ini_find(ini, "mesh", "file");
      char *path = sl_ini_path_relative(e->file, file);
      if (!path) return sl_diag_set(d, SL_EFAILED, "mesh: out of memory");
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
    return sl_diag_set(d, SL_EFAILED, "mesh: out of memory");
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

int sl_scene_line_ends(const sl_ini *ini, const sl_mesh *m, int first, int last, const char *model,
                       const char *names[2], sl_diag *d) {
  names[0] = line_end_name(m, first), names[1] = line_end_name(m, last);
  if (!names[0] || !names[1]) return sl_diag_set(d, SL_EBADINPUT, "%s: the line's ends carry no boundary tag", model);
  for (int s = 0; s < ini->n_sections; ++s) {
    const sl_ini_section *sec = &ini->sections[s];
    if (strncmp(sec->name, "boundary.", 9) != 0) continue;
    const char *b = sec->name + 9;
    if (strcmp(b, names[0]) != 0 && strcmp(b, names[1]) != 0) {
      const char *sug = sl_suggest(b, names, 2);
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: the mesh has no boundary '%s'%s%s%s (its ends: %s, %s)",
                         sec->file, sec->line, sec->name, b, sug ? "; did you mean '" : "", sug ? sug : "",
                         sug ? "'?" : "", names[0], names[1]);
    }
  }
  return 0;
}
