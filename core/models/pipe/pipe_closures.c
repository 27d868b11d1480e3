/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's closures, bound once to its quantities (pipe.h). */
#include <math.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"

const char *const pipe_quantity_names[PQ_N] = {
    "phi",     "slip",          "k",    "epsilon",    "theta",     "shear_rate",      "rho_f",
    "mu_f",    "rho_s",         "d_p",  "sphericity", "slip_wall", "wall_distance",   "d_vessel",
    "gravity", "normal_stress", "nu_t", "t_fs",       "k_fs",      "drag_coefficient"};

static const char *const model_name = "the pipe model";

static void constants(pipe *p, sl_point_closure *pc) {
  const sl_scene *sc = p->sc;
  sl_point_constant(pc, "rho_f", p->rho_f), sl_point_constant(pc, "mu_f", p->mu_f);
  sl_point_constant(pc, "rho_s", p->rho_s), sl_point_constant(pc, "d_p", p->d_p);
  sl_point_constant(pc, "sphericity", sc->solid.sphericity), sl_point_constant(pc, "d_vessel", p->cfg->diameter);
  sl_point_constant(pc, "gravity", fabs(p->gz)), sl_point_constant(pc, "wall_distance", p->R - p->g.xc[p->n - 1]);
}

static int bind(pipe *p, sl_point_closure *pc, const char *role, int *have, sl_diag *d) {
  sl_closure *c = sl_scene_closure(p->sc, role);
  if (have) *have = c != NULL;
  if (!c) return 0;
  char sec[64];
  snprintf(sec, sizeof sec, "closure.%s", role);
  int rc = sl_point_bind(pc, c, pipe_quantity_names, PQ_N, sec, model_name, d);
  if (!rc) constants(p, pc);
  return rc;
}

int pipe_closures_bind(pipe *p, sl_diag *d) {
  int rc = bind(p, &p->turb, "turbulence", NULL, d);
  if (!rc && !sl_point_has_output(&p->turb, "mu_t_k"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "[closure.turbulence]: the pipe model needs a k-epsilon closure (outputs mu_t, "
                     "mu_t_k, mu_t_eps, eps_production, eps_sink, c_mu): model = k_epsilon");
  const char *need[] = {"mu_t_eps", "eps_production", "eps_sink", "c_mu"};
  for (int i = 0; i < 4 && !rc; ++i)
    if (!sl_point_has_output(&p->turb, need[i]))
      rc = sl_diag_set(d, SL_EBADINPUT, "[closure.turbulence]: the closure gives no %s (model = k_epsilon does)",
                       need[i]);
  if (!rc) rc = bind(p, &p->wallf, "wall_stress.fluid", NULL, d);
  if (!rc && !sl_point_has_output(&p->wallf, "u_tau"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "[closure.wall_stress.fluid]: the fluid's wall function must give u_tau, "
                     "y_plus, k_wall and epsilon_wall (model = log_law)");
  if (!rc) rc = bind(p, &p->drag, "drag", NULL, d);
  if (!rc) rc = bind(p, &p->gran, "granular", &p->have_gran, d);
  if (!rc && p->have_gran) {
    const char *g[] = {"mu_s", "gamma", "p_s"};
    for (int i = 0; i < 3 && !rc; ++i)
      if (!sl_point_has_output(&p->gran, g[i]))
        rc = sl_diag_set(d, SL_EBADINPUT,
                         "[closure.granular]: the pipe model needs mu_s, gamma and p_s of the "
                         "kinetic theory (model = lun or gidaspow); the closure gives no %s",
                         g[i]);
  }
  if (!rc && p->have_gran && p->cfg->granular_temperature == PIPE_THETA_TRANSPORT &&
      !sl_point_has_output(&p->gran, "kappa"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "[closure.granular]: [pipe] granular_temperature = transport needs the conductivity kappa "
                     "(model = lun or gidaspow)");
  if (!rc) rc = bind(p, &p->psol, "solids_pressure", &p->have_psol, d);
  if (!rc) rc = bind(p, &p->walls, "wall_stress.solids", &p->have_walls, d);
  if (!rc) rc = bind(p, &p->lift, "lift", &p->have_lift, d);
  if (!rc) rc = bind(p, &p->disp, "turbulent_dispersion", &p->have_disp, d);
  if (!rc) rc = bind(p, &p->modu, "turbulence_modulation", &p->have_modu, d);
  if (!rc && p->have_walls) p->walls_at_node = sl_point_has_input(&p->walls, "wall_distance");
  if (!rc && p->have_walls) p->walls_normal = sl_point_has_input(&p->walls, "normal_stress");
  if (!rc && p->have_walls && p->have_gran && p->cfg->granular_temperature == PIPE_THETA_TRANSPORT)
    p->wall_energy = sl_point_has_output(&p->walls, "theta_flux");
  if (!rc && p->have_walls && p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED)
    p->ks_wall_energy = sl_point_has_output(&p->walls, "theta_flux"); /* at theta = (2/3) k_s (pipe_ksfs.c) */
  return rc;
}
