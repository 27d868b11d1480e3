/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The physics of a two_fluid scene, read the same way for the 1-D column
 * and the 2-D model: fluid and solid properties, gravity, the closures
 * bound to the model's inputs, and the [two_fluid] numerical keys. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/plugin/kinds.h"

/* The quantities the two_fluid model gives its drag and solids-pressure closures. */
static const char *const quantities[] = {"phi", "slip",       "rho_f",   "mu_f", "rho_s",
                                         "d_p", "sphericity", "gravity", "nbar"};

static int bind_closure(const sl_scene *sc, const tf_column *c, const char *role, tf_closure *b, int with_slip,
                        const char *output, sl_diag *d) {
  b->c = sl_scene_closure(sc, role);
  char section[64];
  snprintf(section, sizeof section, "closure.%s", role);
  int rc = sl_point_bind(&b->pc, b->c, quantities, 9, section, "the two_fluid model", d);
  if (rc) return rc;
  char label[128], where[300];
  sl_closure_label(b->c->desc, label, sizeof label);
  sl_scene_closure_where(sc, role, where, sizeof where);
  if (!sl_point_has_input(&b->pc, "phi") || (with_slip && !sl_point_has_input(&b->pc, "slip")) ||
      !sl_point_has_output(&b->pc, output) || (!with_slip && sl_point_has_input(&b->pc, "slip")))
    return sl_diag_set(d, SL_EBADINPUT, "%s %s does not give %s of phi%s", where, label, output,
                       with_slip ? " and slip" : "");
  b->out = output, b->wrt = with_slip ? "slip" : "phi";
  const double values[8] = {0.0, 0.0, c->rho_f, c->mu_f, c->rho_s, c->d_p, c->sphericity, fabs(c->g)};
  for (int k = 2; k < 8; ++k) sl_point_constant(&b->pc, quantities[k], values[k]);
  sl_point_constant(&b->pc, "nbar", NAN); /* a model that does not hold nbar per cell (liquefaction.h) refuses it */
  return 0;
}

int tf_scene_physics(const sl_scene *sc, const tf_config *cfg, int dim, tf_column *c, double gravity[2],
                     double *steady_tol, sl_diag *d) {
  int rc = 0;
  char at[400];
  c->rho_f = sc->fluid.density, c->mu_f = sc->fluid.viscosity;
  c->rho_s = sc->solid.density, c->d_p = sc->solid.diameter, c->sphericity = sc->solid.sphericity;
  c->phi_max = sc->solid.phi_max;
  if (sl_scene_given(sc, &sc->solid.porosity_max)) {
    if (sl_scene_given(sc, &sc->solid.phi_max))
      return sl_diag_set(d, SL_EBADINPUT, "%s and phi_max both given: set one",
                         sl_scene_where(sc, &sc->solid.porosity_max, at, sizeof at));
    c->phi_max = 1.0 - sc->solid.porosity_max;
  }
  const sl_reals *gl = &sc->flow.gravity;
  int ng = sl_scene_given(sc, gl) ? gl->n : 0;
  if (ng > 0 && ng != dim)
    return sl_diag_set(d, SL_EBADINPUT, "%s: a %s takes %d component%s, %d given",
                       sl_scene_where(sc, gl, at, sizeof at), dim == 1 ? "1-D column" : "2-D scene", dim,
                       dim == 1 ? " (along x)" : "s (x, y)", ng);
  if (dim == 1) {
    c->g = ng == 1 ? gl->v[0] : -9.81;
    c->below = c->g <= 0.0;
  } else {
    gravity[0] = ng ? gl->v[0] : 0.0, gravity[1] = ng ? gl->v[1] : -9.81;
    c->g = -hypot(gravity[0], gravity[1]); /* the magnitude, for the closures' input and the velocity scale */
    c->below = 1;
  }
  c->max_iterations = (int)cfg->iterations;
  c->tolerance = cfg->tolerance, c->cfl = cfg->cfl, *steady_tol = cfg->steady_tolerance;
  c->diffusivity = cfg->diffusivity;
  c->order = (int)cfg->order, c->limiter = cfg->limiter;
  c->case_index = (double)cfg->case_index;
  c->eq_porosity[0] = c->eq_porosity[1] = NAN;
  if ((rc = bind_closure(sc, c, "drag", &c->drag, 1, "K", d))) return rc;
  if (sl_scene_closure(sc, "solids_pressure") && (rc = bind_closure(sc, c, "solids_pressure", &c->ps, 0, "p_s", d)))
    return rc;
  if (dim == 2 && c->ps.c && sl_point_has_input(&c->ps.pc, "nbar"))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: %s takes the reference porosity nbar of each cell, which only the 1-D "
                       "column holds (geometry = line, [initial] nbar)",
                       sl_scene_closure_where(sc, "solids_pressure", at, sizeof at), c->ps.c->desc->name);
  /* the velocity scale of the convergence test: the Stokes velocity of one particle, or the through-flow */
  double d_eff = c->sphericity * c->d_p;
  c->v_ref = fmax(fabs(c->rho_s - c->rho_f) * fabs(c->g) * d_eff * d_eff / (18.0 * c->mu_f), 1e-12);
  return 0;
}
