/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The turbulent dispersion of the solids in the 2-D two-fluid model
 * (two_fluid_plane_impl.h), with [closure.turbulence]: a lateral mechanism
 * the laminar equations lack. The flow itself stays laminar; the scene
 * states the fluid's turbulence as k(x, y) and epsilon(x, y) (`[two_fluid]
 * turbulence_k`, `turbulence_epsilon`), the turbulence closure (the pipe
 * model's kind, e.g. model = k_epsilon: mu_t = C_mu rho_f k^2/eps, Launder
 * & Spalding 1974) gives the eddy viscosity, and the solids flux gains
 *
 *   J = -D_t grad phi
 *     with D_t the dispersivity of [closure.turbulent_dispersion] (the pipe
 *     model's kind, as pipe_solids.c) at nu_t = mu_t / rho_f: model =
 *     gradient, D_t = nu_t / sigma (Burns et al. 2004's turbulent
 *     dispersion force in the gradient closure of Krampa 2009 eq 4.59);
 *     without the section D_t = nu_t, the gradient form with sigma = 1;
 *   and with [two_fluid] turbophoresis the drift -phi tau_p grad <v'^2>
 *     with <v'^2> = 2 k / 3 (isotropy) and the particle relaxation time
 *     tau_p = phi rho_s / K of the drag (Krampa 2009 eq 4.58, as pipe.h):
 *     the drift of particles down the gradient of the turbulent intensity
 *     (turbophoresis: Caporaloni, Tampieri, Trombetti & Vittori 1975,
 *     J. Atmos. Sci. 32:565; Reeks 1983, J. Aerosol Sci. 14:729), the
 *     particle flux of Young & Leeming (1997, J. Fluid Mech. 340:129, eq 13
 *     with the Brownian term dropped and the particle diffusivity taken as
 *     the fluid's). Near a wall k falls to 0 across the viscous sublayer, so
 *     the drift carries particles to the wall, where the dispersion that
 *     would return them vanishes with nu_t. The drift is not a diffusivity,
 *     so it is the model's switch and not the closure's.
 *
 * Both are face fluxes of the cells' values: the face's nu_t the harmonic
 * mean of the two cells' (the closure evaluated at it) and tau_p the
 * arithmetic mean, grad the difference over the centres' distance, the
 * drift taking the upwind cell's phi. No flux crosses a boundary face. The
 * eddy viscosity follows phi when the closure reads it; tau_p follows phi
 * and the slip of the iterate. The 2-D model computes neither the
 * eddy-particle interaction time t_fs nor the fluid-particle covariance
 * k_fs: a dispersion closure that takes them (model = simonin) is refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"

enum { DQ_K, DQ_EPS, DQ_RHO_F, DQ_MU_F, DQ_PHI, DQ_N };
static const char *const dq_names[DQ_N] = {"k", "epsilon", "rho_f", "mu_f", "phi"};
/* what the 2-D model gives [closure.turbulent_dispersion], at the faces */
enum { DD_NU_T, DD_RHO_F, DD_N };
static const char *const dd_names[DD_N] = {"nu_t", "rho_f"};

void tfp_dispersion_free(tfp_dispersion *p) {
  sl_point_release(&p->pc), sl_point_release(&p->dc);
  free(p->k), free(p->D);
  memset(p, 0, sizeof *p);
}

/* The scene's k or epsilon in every cell, checked against (0, hi]. */
static int cell_values(const tfp_model *m, const sl_scene *sc, const sl_scene_expr *ex, double hi, double *v,
                       sl_diag *d) {
  const sl_src *s = sl_scene_src(sc, ex);
  for (int c = 0; c < m->fv.nc; ++c) {
    double xy[3] = {m->fv.xc[c % m->fv.nx], m->fv.yc[c / m->fv.nx], m->c.case_index};
    v[c] = sl_expr_eval(ex->e, xy);
    if (!(v[c] > 0.0 && v[c] <= hi))
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [two_fluid] %s = %g at (%g, %g): allowed 0 < %s <= %g", s->file,
                         s->line, s->key, v[c], xy[0], xy[1], s->key, hi);
  }
  return 0;
}

/* [closure.turbulent_dispersion] bound at the faces' nu_t and rho_f; a closure that takes the solids' turbulence
   (t_fs, k_fs: model = simonin) is refused, naming what the 2-D model lacks. */
static int bind_dispersivity(tfp_dispersion *p, const sl_scene *sc, const tfp_model *m, sl_diag *d) {
  char at[400], label[128], lacks[64] = "";
  sl_closure *c = sl_scene_closure(sc, "turbulent_dispersion");
  if (!c) return 0;
  sl_scene_closure_where(sc, "turbulent_dispersion", at, sizeof at);
  const char *solids_turbulence[] = {"t_fs", "k_fs"};
  for (int k = 0; k < 2; ++k)
    if (sl_closure_input(c->desc, solids_turbulence[k]) >= 0)
      snprintf(lacks + strlen(lacks), sizeof lacks - strlen(lacks), "%s%s", lacks[0] ? " and " : "",
               solids_turbulence[k]);
  if (lacks[0])
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: %s takes %s, which the 2-D two_fluid model does not compute (t_fs the eddy-particle "
                       "interaction time, k_fs the fluid-particle covariance: the scene states only the fluid's k and "
                       "epsilon); use model = gradient",
                       at, sl_closure_label(c->desc, label, sizeof label), lacks);
  int rc = sl_point_bind(&p->dc, c, dd_names, DD_N, "closure.turbulent_dispersion", "two_fluid (2-D)", d);
  if (rc) return rc;
  if (!sl_point_has_output(&p->dc, "D_t")) return sl_diag_set(d, SL_EBADINPUT, "%s: the closure gives no D_t", at);
  sl_point_constant(&p->dc, "rho_f", m->c.rho_f);
  p->have_dc = 1;
  return 0;
}

int tfp_dispersion_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, sl_diag *d) {
  tfp_dispersion *p = &m->disp;
  sl_closure *c = sl_scene_closure(sc, "turbulence");
  const void *keys[3] = {&cfg->turb_k, &cfg->turb_eps, &cfg->turbophoresis};
  char at[400];
  if (!c) {
    for (int k = 0; k < 3; ++k)
      if (sl_scene_given(sc, keys[k])) {
        const sl_src *s = sl_scene_src(sc, keys[k]);
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [two_fluid] %s: the solids' turbulent dispersion needs "
                           "[closure.turbulence] (e.g. model = k_epsilon)",
                           s->file, s->line, s->key);
      }
    if (sl_scene_closure(sc, "turbulent_dispersion"))
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s: the solids' turbulent dispersivity is of the fluid's eddy viscosity: it needs "
                         "[closure.turbulence] (e.g. model = k_epsilon)",
                         sl_scene_closure_where(sc, "turbulent_dispersion", at, sizeof at));
    return 0;
  }
  if (!sl_scene_given(sc, &cfg->turb_k) || !sl_scene_given(sc, &cfg->turb_eps))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: [closure.turbulence] disperses the solids with the fluid's turbulence, "
                       "which the scene states: [two_fluid] turbulence_k and turbulence_epsilon "
                       "(expressions of x, y and case, m^2/s^2 and m^2/s^3)",
                       sl_scene_closure_where(sc, "turbulence", at, sizeof at));
  sl_scene_closure_where(sc, "turbulence", at, sizeof at);
  const size_t nc = (size_t)m->fv.nc, nf = (size_t)m->fv.nf;
  p->c = c, p->on = 1, p->turbophoretic = cfg->turbophoresis;
  if (!(p->k = malloc(8 * nc * sizeof *p->k)) || !(p->D = malloc(3 * nf * sizeof *p->D)))
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  p->eps = p->k + nc, p->mu_t = p->k + 2 * nc, p->tau = p->k + 3 * nc, p->slip = p->k + 4 * nc;
  p->K = p->k + 5 * nc, p->dK = p->k + 6 * nc, p->phi = p->k + 7 * nc, p->v = p->D + nf, p->nu = p->D + 2 * nf;
  int rc = cell_values(m, sc, &cfg->turb_k, 1e6, p->k, d);
  if (!rc) rc = cell_values(m, sc, &cfg->turb_eps, 1e9, p->eps, d);
  if (!rc) rc = sl_point_bind(&p->pc, c, dq_names, DQ_N, "closure.turbulence", "two_fluid (2-D)", d);
  if (rc) return rc;
  if (!sl_point_has_output(&p->pc, "mu_t")) return sl_diag_set(d, SL_EBADINPUT, "%s: the closure gives no mu_t", at);
  sl_point_constant(&p->pc, "rho_f", m->c.rho_f), sl_point_constant(&p->pc, "mu_f", m->c.mu_f);
  return bind_dispersivity(p, sc, m, d);
}

int tfp_dispersion_update(tfp_model *m, const double *phi, const double *uf, const double *us, sl_diag *d) {
  tfp_dispersion *p = &m->disp;
  const int nc = m->fv.nc, nf = m->fv.nf, nx = m->fv.nx;
  const double *v[DQ_N] = {p->k, p->eps, NULL, NULL, phi};
  sl_point_request rq = {"mu_t", p->mu_t, NULL, NULL};
  int rc = sl_point_eval(&p->pc, nc, v, &rq, 1, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.turbulence]");
  if (p->turbophoretic) {
    /* the slip's magnitude in each cell from the means of its faces' normal slips, the drag at it (phi floored so
       that K / phi keeps its dilute limit) */
    for (int c = 0; c < nc; ++c) {
      int i = c % nx, j = c / nx, fx = i + (nx + 1) * j, fy = m->fv.nfx + i + nx * j;
      double sx = 0.5 * ((uf[fx] - us[fx]) + (uf[fx + 1] - us[fx + 1]));
      double sy = 0.5 * ((uf[fy] - us[fy]) + (uf[fy + nx] - us[fy + nx]));
      p->slip[c] = hypot(sx, sy), p->phi[c] = fmax(phi[c], 1e-6);
    }
    if ((rc = tf_closure_eval(&m->c.drag, nc, p->phi, p->slip, p->K, p->dK, d)))
      return sl_diag_prefix(d, rc, "the turbophoretic drift's drag");
    for (int c = 0; c < nc; ++c) {
      p->tau[c] = p->K[c] > 0.0 ? p->phi[c] * m->c.rho_s / p->K[c] : 0.0;
      if (!isfinite(p->tau[c]))
        return sl_diag_set(d, SL_EFAILED, "the particle relaxation time in cell %d is not finite", c);
    }
  }
  for (int f = 0; f < nf; ++f) {
    int lo = m->fv.lo[f], hi = m->fv.hi[f];
    p->nu[f] = p->v[f] = 0.0;
    if (lo < 0 || hi < 0 || m->ftype[f] == TFP_FACE_IMAGE) continue;
    /* the harmonic mean of the cells' eddy viscosities: two resistances in series (Patankar 1980, Numerical Heat
       Transfer and Fluid Flow, eq 4.9), so that a wall cell's small nu_t is not hidden by its neighbour's */
    double a = p->mu_t[lo], b = p->mu_t[hi];
    p->nu[f] = (a + b > 0.0 ? 2.0 * a * b / (a + b) : 0.0) / m->c.rho_f;
    if (p->turbophoretic)
      p->v[f] = -0.5 * (p->tau[lo] + p->tau[hi]) * (2.0 / 3.0) * (p->k[hi] - p->k[lo]) / m->fv.dist[f];
  }
  /* the dispersivity of the faces' nu_t; without [closure.turbulent_dispersion] nu_t itself (Schmidt number 1,
     Krampa 2009 eq 4.59, as the pipe model) */
  if (!p->have_dc) {
    memcpy(p->D, p->nu, (size_t)nf * sizeof *p->D);
    return 0;
  }
  const double *dv[DD_N] = {p->nu, NULL};
  sl_point_request dr = {"D_t", p->D, NULL, NULL};
  if ((rc = sl_point_eval(&p->dc, nf, dv, &dr, 1, d))) return sl_diag_prefix(d, rc, "[closure.turbulent_dispersion]");
  for (int f = 0; f < nf; ++f) /* boundary and image faces carry no flux, whatever the closure gives at nu_t = 0 */
    if (m->fv.lo[f] < 0 || m->fv.hi[f] < 0 || m->ftype[f] == TFP_FACE_IMAGE) p->D[f] = 0.0;
  return 0;
}
