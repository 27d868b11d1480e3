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
 * a grid line. A blocked cell keeps phi = 0 and p = 0 (unused), its swirl
 * the body's Omega. Not with periodic sides, column_form or a transported
 * granular temperature (not verified there). */
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

int tfp_body_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, const tfp_boundary *mesh_b, int n_mesh_b,
                  tfp_boundary **all, sl_diag *d) {
  *all = NULL;
  const sl_src *box = sl_scene_src(sc, &cfg->body_box), *om = sl_scene_src(sc, &cfg->body_omega);
  if (om && !box)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] angular_velocity: the body needs its box (box = x0, x1, y0, "
                                        "y1)", om->file, om->line);
  if (om && !cfg->swirl)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] angular_velocity: only with [two_fluid] swirl = true",
                       om->file, om->line);
  if (!box) return 0;
  const double *v = cfg->body_box.v;
  if (cfg->body_box.n != 4 || !(v[0] < v[1]) || !(v[2] < v[3]))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] box = %s: four numbers x0, x1, y0, y1 with x0 < x1 and "
                                        "y0 < y1 (m)", box->file, box->line, box->value);
  if (m->fv.periodic[0] || m->fv.periodic[1] || cfg->column_form)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body]: not with periodic sides or [two_fluid] column_form",
                       box->file, box->line);
  const sl_tensor_grid *g = &m->grid;
  const double *lines[4] = {g->xf, g->xf, g->yf, g->yf};
  const int nl[4] = {g->nx, g->nx, g->ny, g->ny};
  static const char *const edge[4] = {"x0", "x1", "y0", "y1"};
  for (int k = 0; k < 4; ++k)
    if (!on_line(v[k], lines[k], nl[k]))
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] box: %s = %g is not on a grid line of the mesh (the body "
                                          "is made of whole cells)", box->file, box->line, edge[k], v[k]);
  const int nc = g->nx * g->ny;
  int *cells = malloc((size_t)nc * sizeof *cells), n_in = 0;
  tfp_boundary *b = calloc((size_t)n_mesh_b + 1, sizeof *b);
  if (!cells || !b) {
    free(cells), free(b);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  for (int c = 0; c < nc; ++c) {
    int i = c % g->nx, j = c / g->nx;
    double x = 0.5 * (g->xf[i] + g->xf[i + 1]), y = 0.5 * (g->yf[j] + g->yf[j + 1]);
    cells[c] = x > v[0] && x < v[1] && y > v[2] && y < v[3] ? 0 : -1;
    n_in += cells[c] == 0;
  }
  if (n_in == 0 || n_in == nc) {
    free(cells), free(b);
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [body] box: it holds %s of the mesh's %d cells (allowed: some, not "
                                        "all)", box->file, box->line, n_in ? "all" : "none", nc);
  }
  memcpy(b, mesh_b, (size_t)n_mesh_b * sizeof *b);
  b[n_mesh_b] = (tfp_boundary){.type = TFP_WALL, .solids = TFP_SOLIDS_NO_SLIP, .angular_velocity = cfg->body_omega};
  m->body_cells = cells, m->n_bodies = 1;
  snprintf(m->body_names[0], sizeof m->body_names[0], "body");
  m->b = b, m->n_b = n_mesh_b + 1;
  *all = b;
  return 0;
}
