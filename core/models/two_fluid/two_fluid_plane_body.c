/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A solid body inside the 2-D two-fluid model's domain ([body];
 * two_fluid_plane_impl.h): a rotor's tip, a step in a channel.
 *
 *   [body]
 *   box = x0, x1, y0, y1      ; r and z when axisymmetric, m
 *   angular_velocity = 10     ; with [two_fluid] swirl, rad/s
 *
 * The cells whose centres lie in the box are blocked (core/fv/grid.h,
 * sl_fv_grid_block): they leave the domain, and each face between a
 * blocked and an open cell is a wall of the open one, at rest in the
 * meridional plane (u.n = 0, both phases no-slip along it at half a
 * cell, as the domain's walls: two_fluid_plane_step.c), turning at
 * angular_velocity about the axis (two_fluid_plane_swirl.c). The body is
 * made of whole cells: each edge of the box inside the domain must lie on
 * a grid line, and the box inside the domain. A blocked cell keeps phi = 0
 * and p = 0 (unused), its swirl the body's Omega. Not with periodic sides,
 * column_form or a transported granular temperature (not verified there).
 *
 * Several bodies: [body.NAME] sections with the same keys (and [body] as
 * the body named `body`), up to TFP_BODIES_MAX; they may touch (the faces
 * between them are dead), not overlap; NAME names the body's output
 * scalars and may not be a boundary of the mesh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"

/* 1 when v is within a millionth of a cell of a grid line, or outside (lo, hi). */
static int on_line(double v, const double *lines, int n) {
  if (v <= lines[0] || v >= lines[n]) return 1;
  for (int k = 0; k <= n; ++k) {
    double h = lines[k < n ? k + 1 : n] - lines[k < n ? k : n - 1];
    if (fabs(v - lines[k]) <= 1e-6 * h) return 1;
  }
  return 0;
}

/* One body's box (v, its text `what` for messages), checked against the grid, its cells marked `k` in cells[]
 * (overlapping an earlier body's: an error naming it). */
static int body_cells(tfp_model *m, int k, const double *v, int nv, const char *where, const char *what, int *cells,
                      sl_diag *d) {
  if (nv != 4 || !(v[0] < v[1]) || !(v[2] < v[3]))
    return sl_diag_set(d, SL_EBADINPUT, "%s box = %s: four numbers x0, x1, y0, y1 with x0 < x1 and y0 < y1 (m)", where,
                       what);
  const sl_tensor_grid *g = &m->grid;
  const double ex = 1e-9 * (g->xf[g->nx] - g->xf[0]), ey = 1e-9 * (g->yf[g->ny] - g->yf[0]);
  if (v[0] < g->xf[0] - ex || v[1] > g->xf[g->nx] + ex || v[2] < g->yf[0] - ey || v[3] > g->yf[g->ny] + ey)
    return sl_diag_set(d, SL_EBADINPUT, "%s box = %s: outside the domain (allowed: x in [%g, %g], y in [%g, %g] m)",
                       where, what, g->xf[0], g->xf[g->nx], g->yf[0], g->yf[g->ny]);
  const double *lines[4] = {g->xf, g->xf, g->yf, g->yf};
  const int nl[4] = {g->nx, g->nx, g->ny, g->ny};
  static const char *const edge[4] = {"x0", "x1", "y0", "y1"};
  for (int e = 0; e < 4; ++e)
    if (!on_line(v[e], lines[e], nl[e]))
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s box: %s = %g is not on a grid line of the mesh (the body is made of "
                         "whole cells)",
                         where, edge[e], v[e]);
  const int nc = g->nx * g->ny;
  int n_in = 0;
  for (int c = 0; c < nc; ++c) {
    int i = c % g->nx, j = c / g->nx;
    double x = 0.5 * (g->xf[i] + g->xf[i + 1]), y = 0.5 * (g->yf[j] + g->yf[j + 1]);
    if (!(x > v[0] && x < v[1] && y > v[2] && y < v[3])) continue;
    if (cells[c] >= 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s box = %s: overlaps %s (at (%g, %g); bodies may touch, not overlap)",
                         where, what, m->body_where[cells[c]], x, y);
    cells[c] = k, ++n_in;
  }
  int all = 1;
  for (int c = 0; c < nc && all; ++c) all = cells[c] >= 0;
  if (n_in == 0 || all)
    return sl_diag_set(d, SL_EBADINPUT, "%s box: it holds %s of the mesh's %d cells (allowed: some, not all)", where,
                       n_in ? "all" : "none", nc);
  m->body_r1[k] = v[1];
  return 0;
}

int tfp_body_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, const tfp_boundary *mesh_b, int n_mesh_b,
                  tfp_boundary **all, sl_diag *d) {
  *all = NULL;
  const sl_src *box = sl_scene_src(sc, &cfg->body_box), *om = sl_scene_src(sc, &cfg->body_omega);
  if (om && !box)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [body] angular_velocity: the body needs its box (box = x0, x1, y0, "
                       "y1)",
                       om->file, om->line);
  int n = box ? 1 : 0;
  const char *name;
  sl_src sec;
  while (sl_scene_named(sc, "body", n - (box ? 1 : 0), &name, &sec)) ++n;
  if (!n) return 0;
  if (n > TFP_BODIES_MAX) {
    sl_scene_named(sc, "body", TFP_BODIES_MAX - (box ? 1 : 0), &name, &sec);
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: at most %d bodies in a scene", sec.file, sec.line, sec.section,
                       TFP_BODIES_MAX);
  }
  const int nc = m->grid.nx * m->grid.ny;
  int *cells = malloc((size_t)nc * sizeof *cells);
  tfp_boundary *b = calloc((size_t)(n_mesh_b + n), sizeof *b);
  if (!cells || !b) {
    free(cells), free(b);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  for (int c = 0; c < nc; ++c) cells[c] = -1;
  memcpy(b, mesh_b, (size_t)n_mesh_b * sizeof *b);
  int rc = 0;
  for (int k = 0; k < n && !rc; ++k) {
    double v[4] = {0}, omega = 0.0;
    int nv = 0, has_omega = 0;
    char what[256];
    if (box && k == 0) { /* [body] */
      snprintf(m->body_names[k], sizeof m->body_names[k], "body");
      snprintf(m->body_where[k], sizeof m->body_where[k], "%s:%d: [body]", box->file, box->line);
      memcpy(v, cfg->body_box.v, sizeof v), nv = cfg->body_box.n, omega = cfg->body_omega, has_omega = om != NULL;
      snprintf(what, sizeof what, "%s", box->value);
    } else { /* [body.NAME]: its keys were checked against [body]'s (the scene's named family) */
      int j = k - (box ? 1 : 0);
      sl_scene_named(sc, "body", j, &name, &sec);
      snprintf(m->body_names[k], sizeof m->body_names[k], "%s", name);
      snprintf(m->body_where[k], sizeof m->body_where[k], "%s:%d: [%s]", sec.file, sec.line, sec.section);
      for (int q = 0; q < n_mesh_b && !rc; ++q)
        if (strcmp(sc->mesh->boundary_names[q], name) == 0)
          rc = sl_diag_set(d, SL_EBADINPUT,
                           "%s: the name of a boundary of the mesh (the output's scalars name "
                           "both): choose another",
                           m->body_where[k]);
      for (int q = box ? 1 : 0; q < k && !rc; ++q)
        if (strcmp(m->body_names[q], name) == 0)
          rc = sl_diag_set(d, SL_EBADINPUT, "%s: a second body named %s", m->body_where[k], name);
      sl_src eb, eo;
      int no = 0;
      if (!rc) rc = sl_scene_named_reals(sc, "body", j, "box", v, 4, &nv, &eb, d);
      if (!rc && !eb.file)
        rc = sl_diag_set(d, SL_EBADINPUT, "%s: the body needs its box (box = x0, x1, y0, y1)", m->body_where[k]);
      if (!rc) {
        snprintf(m->body_where[k], sizeof m->body_where[k], "%s:%d: [%s]", eb.file, eb.line, sec.section);
        snprintf(what, sizeof what, "%s", eb.value);
        rc = sl_scene_named_reals(sc, "body", j, "angular_velocity", &omega, 1, &no, &eo, d);
      }
      if (!rc && eo.file) {
        has_omega = 1;
        if (!cfg->swirl)
          rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] angular_velocity: only with [two_fluid] swirl = true", eo.file,
                           eo.line, sec.section);
      }
    }
    if (!rc && has_omega && !cfg->swirl && k == 0 && box)
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] angular_velocity: only with [two_fluid] swirl = true", om->file,
                       om->line);
    if (!rc && (m->fv.periodic[0] || m->fv.periodic[1] || cfg->column_form))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: not with periodic sides or [two_fluid] column_form", m->body_where[k]);
    if (!rc) rc = body_cells(m, k, v, nv, m->body_where[k], what, cells, d);
    b[n_mesh_b + k] = (tfp_boundary){.type = TFP_WALL, .solids = TFP_SOLIDS_NO_SLIP, .angular_velocity = omega};
  }
  if (rc) {
    free(cells), free(b);
    return rc;
  }
  m->body_cells = cells, m->n_bodies = n;
  m->b = b, m->n_b = n_mesh_b + n;
  *all = b;
  return 0;
}
