/* The physics of a two_fluid scene, read the same way for the 1-D column
 * and the 2-D model: fluid and solid properties, gravity, the closures
 * bound to the model's inputs, and the [two_fluid] numerical keys. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/kinds.h"

static int bind_closure(sl_ini *ini, const tf_column *c, const sl_registry *reg, const char *section, tf_closure *b,
                        int with_slip, const char *output, sl_diag *d) {
  int rc = sl_closure_from_ini(reg, ini, section, &b->c, d);
  if (rc) return rc;
  const sl_closure_desc *cd = b->c->desc;
  const sl_ini_section *sec = sl_ini_find_section(ini, section);
  char label[128];
  sl_closure_label(cd, label, sizeof label);
  b->in_phi = sl_closure_input(cd, "phi");
  b->in_slip = with_slip ? sl_closure_input(cd, "slip") : -1;
  b->out = sl_closure_output(cd, output);
  if (b->in_phi < 0 || (with_slip && b->in_slip < 0) || b->out < 0 || cd->n_in > TF_MAX_IN || cd->n_out > TF_MAX_IN)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s does not give %s of phi%s", sec->file, sec->line, section,
                       label, output, with_slip ? " and slip" : "");
  for (int i = 0; i < cd->n_in; ++i) {
    const char *name = cd->in[i].name;
    double v;
    if (i == b->in_phi || i == b->in_slip) continue;
    if (strcmp(name, "rho_f") == 0) v = c->rho_f;
    else if (strcmp(name, "mu_f") == 0) v = c->mu_f;
    else if (strcmp(name, "rho_s") == 0) v = c->rho_s;
    else if (strcmp(name, "d_p") == 0) v = c->d_p;
    else if (strcmp(name, "sphericity") == 0) v = c->sphericity;
    else if (strcmp(name, "gravity") == 0) v = fabs(c->g);
    else
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [%s] %s needs the input '%s', which the two_fluid model does not provide (it "
                         "provides phi, slip, rho_f, mu_f, rho_s, d_p, sphericity, gravity)",
                         sec->file, sec->line, section, label, name);
    b->fixed[i] = v;
  }
  return 0;
}

int tf_scene_physics(sl_ini *ini, const sl_registry *reg, int dim, tf_column *c, double gravity[2],
                     double *steady_tol, sl_diag *d) {
  int rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, &c->rho_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "fluid", "viscosity", 0, 1e-3, 1e-7, 1e7, &c->mu_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "density", 1, 0, 1e-3, 1e5, &c->rho_s, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "diameter", 1, 0, 1e-9, 1.0, &c->d_p, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "sphericity", 0, 1.0, 0.01, 1.0, &c->sphericity, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "phi_max", 0, 0.64, 0.01, 0.99, &c->phi_max, d);
  if (rc) return rc;
  const sl_ini_entry *pm = sl_ini_find(ini, "solid", "phi_max"), *nm = sl_ini_find(ini, "solid", "porosity_max");
  if (nm) {
    double n_min;
    if ((rc = sl_ini_get_real(ini, "solid", "porosity_max", 0, 0.36, 0.01, 0.99, &n_min, d))) return rc;
    if (pm)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [solid] porosity_max and phi_max both given: set one", nm->file,
                         nm->line);
    c->phi_max = 1.0 - n_min;
  }
  double gl[3] = {-9.81, 0, 0};
  int ng = 0;
  if ((rc = sl_ini_get_real_list(ini, "flow", "gravity", 0, gl, 3, &ng, d))) return rc;
  if (ng > 0 && ng != dim) {
    const sl_ini_entry *e = sl_ini_find(ini, "flow", "gravity");
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [flow] gravity: a %s takes %d component%s, %d given", e->file,
                       e->line, dim == 1 ? "1-D column" : "2-D scene", dim, dim == 1 ? " (along x)" : "s (x, y)", ng);
  }
  if (dim == 1) {
    c->g = ng == 1 ? gl[0] : -9.81;
    c->below = c->g <= 0.0;
  } else {
    gravity[0] = ng ? gl[0] : 0.0, gravity[1] = ng ? gl[1] : -9.81;
    c->g = -hypot(gravity[0], gravity[1]); /* the magnitude, for the closures' input and the velocity scale */
    c->below = 1;
  }
  long it;
  if ((rc = sl_ini_get_int(ini, "two_fluid", "iterations", 0, 50, 1, 1000, &it, d))) return rc;
  c->max_iterations = (int)it;
  if ((rc = sl_ini_get_real(ini, "two_fluid", "tolerance", 0, 1e-9, 1e-15, 1e-2, &c->tolerance, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "two_fluid", "cfl", 0, 0.9, 1e-3, 1.0, &c->cfl, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "two_fluid", "steady_tolerance", 0, 0.0, 0.0, 1.0, steady_tol, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "two_fluid", "diffusivity", 0, 0.0, 0.0, 1e3, &c->diffusivity, d))) return rc;
  long order;
  if ((rc = sl_ini_get_int(ini, "two_fluid", "order", 0, 1, 1, 2, &order, d))) return rc;
  c->order = (int)order;
  if ((rc = sl_ini_get_choice(ini, "two_fluid", "limiter", 0, TF_LIMITER_MINMOD, "minmod|mc", &c->limiter, d)))
    return rc;
  long case_index;
  if ((rc = sl_ini_get_int(ini, "two_fluid", "case", 0, 0, 0, 1000000, &case_index, d))) return rc;
  c->case_index = (double)case_index;
  c->eq_porosity[0] = c->eq_porosity[1] = NAN;
  if (!sl_ini_find_section(ini, "closure.drag"))
    return sl_diag_set(d, SL_EBADINPUT, "[closure.drag]: the two_fluid model needs a drag closure (e.g. model = "
                                        "wen_yu); `sluice closures` lists them");
  if ((rc = bind_closure(ini, c, reg, "closure.drag", &c->drag, 1, "K", d))) return rc;
  if (sl_ini_find_section(ini, "closure.solids_pressure") &&
      (rc = bind_closure(ini, c, reg, "closure.solids_pressure", &c->ps, 0, "p_s", d)))
    return rc;
  for (int s = 0; s < ini->n_sections; ++s) {
    const char *name = ini->sections[s].name;
    if (strncmp(name, "closure.", 8) != 0 || strcmp(name, "closure.drag") == 0 ||
        strcmp(name, "closure.solids_pressure") == 0)
      continue;
    /* the 2-D model's solids stress (two_fluid_plane_solids.c binds them) */
    if (dim == 2 && (strcmp(name, "closure.viscosity") == 0 || strcmp(name, "closure.granular") == 0 ||
                     strcmp(name, "closure.wall_stress") == 0))
      continue;
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: the two_fluid model (motion = column) uses %s",
                       ini->sections[s].file, ini->sections[s].line, name,
                       dim == 1 ? "[closure.drag] and [closure.solids_pressure] only (a solids stress needs a 2-D "
                                  "scene or the shear layer, motion = shear)"
                                : "[closure.drag], [closure.solids_pressure], [closure.viscosity], "
                                  "[closure.granular] and [closure.wall_stress]");
  }
  /* the velocity scale of the convergence test: the Stokes velocity of one particle, or the through-flow */
  double d_eff = c->sphericity * c->d_p;
  c->v_ref = fmax(fabs(c->rho_s - c->rho_f) * fabs(c->g) * d_eff * d_eff / (18.0 * c->mu_f), 1e-12);
  return 0;
}
