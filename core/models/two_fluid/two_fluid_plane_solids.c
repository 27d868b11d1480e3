/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids phase's stress in the 2-D two-fluid model
 * (two_fluid_plane_impl.h): its viscosity in the cells and the wall
 * closure's stress along walls with solids = wall_stress.
 *
 * mu_s, the solids phase's viscosity (its stress mu_s grad u_s, as the
 * fluid's is (1 - phi) mu_f grad u_f), is the sum, as in the shear layer
 * (shear_layer.h), of
 *   [solid] viscosity, a constant (default 0);
 *   the part mu_m - (1 - phi) mu_f of a suspension viscosity mu_m of
 *     [closure.viscosity] that the fluid's share leaves (0 where mu_m falls
 *     below it), at the solids shear rate and the mixture density;
 *   the kinetic theory's mu_s(phi, theta) of [closure.granular], with the
 *     granular temperature theta of the cells from its algebraic balance
 *     (`[two_fluid] granular_temperature = algebraic`):
 *       mu_s(theta) gdot^2 = gamma(theta) + 3 K theta
 *     (van Wachem et al. 2001; the drag's sink -3 K theta as in Gidaspow
 *     1994, chapter 9; off with interphase_dissipation = false), a quadratic
 *     in sqrt(theta) for a kinetic closure (mu_s ~ theta^1/2, gamma ~
 *     theta^3/2, checked at set-up); or, with `granular_temperature =
 *     transport`, the theta of its transport equation (tfp_theta_solve).
 * mu_s is evaluated in the cells (for the normal stresses, and theta's
 * output) and at the grid's corners, where the shear stresses act, at the
 * corner's own shear rate (phi, the density and the normal strain the
 * means of its cells). The iteration's matrix takes the tangent viscosity
 * mu_s + gdot dmu_s/dgdot (Newton in the shear rate; the lagged mu_s alone
 * diverges once mu_s grows as gdot or faster, as the kinetic one does), the
 * right-hand side the difference at the iterate; with the corner's own
 * shear rate the tangent of a shear stress is exact (from the cells' mean
 * of four corners it mismatched the stress's dependence on its neighbours
 * and Newton fell to a linear rate of 0.45-0.6).
 * gdot is the solids' shear rate sqrt(2 S':S'), S' the deviator of the
 * strain rate: S_xx, S_yy (and S_thth = u_r / r axisymmetric) at the cell
 * from its faces, S_xy from du/dy + dv/dx at the grid's corners (the mean of
 * the squares of its four), the velocity at a wall that of the wall (no
 * slip), the solids' own there (free slip: no shear) or their slip under the
 * wall stress.
 *
 * The wall closure sets the tangential stress tau_w(slip) the wall exerts on
 * the solids against their slip. A wall function (a closure with a
 * wall_distance input: Bagnold, Bartosik) reads the slip of the face next
 * to the wall, half a cell from it. Otherwise (Johnson & Jackson, Navier
 * slip) the slip is that at the wall itself, found so that the half cell
 * between face and wall carries the same stress: mu_s (u - u_w) / (h/2) =
 * tau_w(u_w - U), by Newton; the face then feels R(u) = tau_w with dR/du =
 * k tau' / (k + tau'), k = mu_s / (h/2). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/solve/linsolve.h"

void tfp_solids_free(tfp_solids *s) {
  double *all[] = {s->mu,     s->mu_t,   s->gdot,   s->rho,    s->Kc,      s->theta,       s->theta_new,
                   s->normal, s->mum,    s->mu_k,   s->kap,    s->gam,     s->one,         s->shear,
                   s->phi_k,  s->rho_k,  s->K_k,    s->gdot_k, s->theta_k, s->mu_k_corner, s->mu_tk,
                   s->dgam,   s->th_old, s->th_cap, s->th_src, s->th_sink, s->th_x};
  sl_cell_scalar_free(&s->th);
  for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) free(all[k]);
  for (int k = 0; k < TF_Q_N; ++k) free(s->qv[k]);
  free(s->visc.buf), free(s->gran.buf), free(s->wall.buf);
}

int tfp_solids_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, sl_diag *d) {
  tfp_solids *s = &m->s;
  const size_t nc = (size_t)m->fv.nc, nk = (size_t)(m->fv.nx + 1) * (size_t)(m->fv.ny + 1); /* nk > nc */
  double **a[] = {&s->mu,     &s->mu_t,   &s->gdot,   &s->rho,    &s->Kc,      &s->theta,       &s->theta_new,
                  &s->normal, &s->mum,    &s->mu_k,   &s->kap,    &s->gam,     &s->one,         &s->shear,
                  &s->phi_k,  &s->rho_k,  &s->K_k,    &s->gdot_k, &s->theta_k, &s->mu_k_corner, &s->mu_tk,
                  &s->dgam,   &s->th_old, &s->th_cap, &s->th_src, &s->th_sink, &s->th_x};
  for (size_t k = 0; k < sizeof a / sizeof a[0]; ++k)
    if (!(*a[k] = calloc(nk, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int k = 0; k < TF_Q_N; ++k)
    if (!(s->qv[k] = calloc(nk, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (size_t c = 0; c < nk; ++c) {
    s->qv[TF_Q_RHO_F][c] = m->c.rho_f, s->qv[TF_Q_MU_F][c] = m->c.mu_f, s->qv[TF_Q_RHO_S][c] = m->c.rho_s;
    s->qv[TF_Q_D_P][c] = m->c.d_p, s->qv[TF_Q_SPHERICITY][c] = m->c.sphericity;
    s->qv[TF_Q_GRAVITY][c] = fabs(m->c.g), s->one[c] = 1.0;
  }
  s->mu_const = sc->solid.viscosity;
  int rc = 0;
  char at[400];
  const char *model = "the 2-D two_fluid model";
  if ((s->visc_c = sl_scene_closure(sc, "viscosity"))) {
    if ((rc = sl_point_bind(&s->visc, s->visc_c, tf_quantity_names, TF_Q_N, "closure.viscosity", model, d))) return rc;
    if (!sl_point_has_output(&s->visc, "viscosity"))
      return sl_diag_set(d, SL_EBADINPUT, "[closure.viscosity]: the closure gives no viscosity");
  }
  s->gran_c = sl_scene_closure(sc, "granular");
  s->granular = s->gran_c != NULL;
  const sl_src *gt = sl_scene_src(sc, &cfg->granular_temperature);
  if (!s->granular && gt)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [two_fluid] granular_temperature: needs [closure.granular] (a "
                       "kinetic theory, e.g. model = lun)",
                       gt->file, gt->line);
  if (s->granular) {
    s->algebraic = cfg->granular_temperature;
    s->exchange = cfg->interphase_dissipation;
    if ((rc = sl_point_bind(&s->gran, s->gran_c, tf_quantity_names, TF_Q_N, "closure.granular", model, d))) return rc;
    if ((rc = sl_granular_require(&s->gran, !s->algebraic, "the 2-D model", d))) return rc;
    /* the kinetic pressure by default with a transported theta only: the algebraic theta follows the shear rate
       at once, as (gdot d)^2, and from an impulsive start (kinetic_shear, bagnold_shear) its pressure in the
       walls' cells kept the iteration from converging at any time step */
    int has_ps = sl_point_has_output(&s->gran, "p_s");
    s->kinetic_pressure = sl_scene_given(sc, &cfg->kinetic_pressure) ? cfg->kinetic_pressure : has_ps && !s->algebraic;
    if (s->kinetic_pressure && !has_ps)
      return sl_diag_set(d, SL_EBADINPUT, "%s = true: [closure.granular] gives no p_s",
                         sl_scene_where(sc, &cfg->kinetic_pressure, at, sizeof at));
    if (s->algebraic) {
      char gt_at[400];
      if ((rc = sl_granular_check_kinetic(&s->gran, TF_Q_N, s->qv, TF_Q_PHI, TF_Q_THETA, m->c.phi_max,
                                          s->kinetic_pressure,
                                          sl_scene_where(sc, &cfg->granular_temperature, gt_at, sizeof gt_at), d)))
        return rc;
    }
  } else {
    const void *keys[] = {&cfg->interphase_dissipation, &cfg->kinetic_pressure};
    for (int k = 0; k < 2; ++k)
      if (sl_scene_given(sc, keys[k]))
        return sl_diag_set(d, SL_EBADINPUT, "%s: needs [closure.granular]", sl_scene_where(sc, keys[k], at, sizeof at));
  }
  /* Anderson acceleration: the default with a kinetic theory (see tfp_step) */
  m->accelerate = sl_scene_given(sc, &cfg->acceleration) ? cfg->acceleration : s->granular;
  int any_stress = 0;
  for (int f = 0; f < 2 * m->fv.nf; ++f)
    any_stress |= m->end_wall[f] >= 0 && m->b[m->end_wall[f]].solids == TFP_SOLIDS_WALL_STRESS;
  if ((s->wall_c = sl_scene_closure(sc, "wall_stress"))) {
    if ((rc = sl_point_bind(&s->wall, s->wall_c, tf_quantity_names, TF_Q_N, "closure.wall_stress", model, d)))
      return rc;
    if (!sl_point_has_output(&s->wall, "tau_w"))
      return sl_diag_set(d, SL_EBADINPUT, "[closure.wall_stress]: the closure gives no tau_w");
    if (sl_point_has_input(&s->wall, "shear_rate"))
      return sl_diag_set(d, SL_EBADINPUT,
                         "[closure.wall_stress]: the 2-D model gives a wall closure no shear_rate "
                         "(its slip_wall and wall_distance give the wall's shear rate)");
    s->wall_function = sl_point_has_input(&s->wall, "wall_distance");
    s->wall_energy = s->granular && !s->algebraic && sl_point_has_output(&s->wall, "theta_flux");
    if (!any_stress)
      return sl_diag_set(d, SL_EBADINPUT,
                         "[closure.wall_stress]: no wall uses it (set solids = wall_stress in a "
                         "[boundary.NAME] of type wall)");
  } else if (any_stress) {
    return sl_diag_set(d, SL_EBADINPUT,
                       "solids = wall_stress needs [closure.wall_stress] (e.g. model = bagnold or "
                       "johnson_jackson)");
  }
  s->any = s->mu_const > 0.0 || s->visc_c || s->granular || any_stress;
  for (size_t c = 0; c < nc; ++c) s->theta[c] = s->theta_new[c] = SL_THETA_FLOOR;
  for (size_t k = 0; k < nk; ++k) s->theta_k[k] = SL_THETA_FLOOR;
  return 0;
}

/* The solids velocity along the wall at face f's end: the wall's (no
 * slip), their slip under a wall stress, or the face's own (free slip: no
 * shear). */
static double wall_solids(const tfp_model *m, int f, int end, double u_face) {
  f = tfp_primary(m, f); /* an image face's wall state is its first face's */
  int e = 2 * f + end, b = m->end_wall[e];
  if (m->tan_noslip[4 * f + 2 + end] || (b >= 0 && m->b[b].solids == TFP_SOLIDS_WALL_STRESS)) return m->end_us[e];
  return u_face;
}

/* du/dy + dv/dx of the solids at every corner of the grid. */
static void corner_shear(tfp_model *m, const double *us) {
  const int nx = m->fv.nx, ny = m->fv.ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double g = 0.0;
      /* du/dy from the x-faces (i, j-1) and (i, j) */
      {
        int below = j - 1, above = j, fa, fb;
        if (m->fv.periodic[1]) below = (below + ny) % ny, above = above % ny;
        double ua, ub, gap;
        /* a body's wall: a dead face on one side (both: a corner inside the body, no shear) */
        int dead_b = below >= 0 && tfp_dead(m, i + (nx + 1) * below),
            dead_a = above < ny && tfp_dead(m, i + (nx + 1) * above);
        if ((dead_a || above >= ny) && (dead_b || below < 0) && (dead_a || dead_b)) ua = ub = 0.0, gap = 1.0;
        else if (dead_b) {
          fa = i + (nx + 1) * above;
          ua = us[fa], ub = wall_solids(m, fa, 0, ua), gap = 0.5 * m->fv.hy[above];
        } else if (dead_a) {
          fb = i + (nx + 1) * below;
          ub = us[fb], ua = wall_solids(m, fb, 1, ub), gap = 0.5 * m->fv.hy[below];
        } else if (below >= 0 && above < ny) {
          fa = i + (nx + 1) * above, fb = i + (nx + 1) * below;
          ua = us[fa], ub = us[fb], gap = 0.5 * (m->fv.hy[above] + m->fv.hy[below]);
        } else if (below < 0) { /* the bottom */
          fa = i + (nx + 1) * above;
          ua = us[fa], ub = wall_solids(m, fa, 0, ua);
          gap = 0.5 * m->fv.hy[above];
        } else { /* the top */
          fb = i + (nx + 1) * below;
          ub = us[fb], ua = wall_solids(m, fb, 1, ub);
          gap = 0.5 * m->fv.hy[below];
        }
        g += (ua - ub) / gap;
      }
      /* dv/dx from the y-faces (i-1, j) and (i, j) */
      {
        int left = i - 1, right = i, fa, fb;
        if (m->fv.periodic[0]) left = (left + nx) % nx, right = right % nx;
        double ua, ub, gap;
        int dead_l = left >= 0 && tfp_dead(m, m->fv.nfx + left + nx * j),
            dead_r = right < nx && tfp_dead(m, m->fv.nfx + right + nx * j);
        if ((dead_l || left < 0) && (dead_r || right >= nx) && (dead_l || dead_r)) ua = ub = 0.0, gap = 1.0;
        else if (dead_l) {
          fa = m->fv.nfx + right + nx * j;
          ua = us[fa], ub = wall_solids(m, fa, 0, ua), gap = 0.5 * m->fv.hx[right];
        } else if (dead_r) {
          fb = m->fv.nfx + left + nx * j;
          ub = us[fb], ua = wall_solids(m, fb, 1, ub), gap = 0.5 * m->fv.hx[left];
        } else if (left >= 0 && right < nx) {
          fa = m->fv.nfx + right + nx * j, fb = m->fv.nfx + left + nx * j;
          ua = us[fa], ub = us[fb], gap = 0.5 * (m->fv.hx[right] + m->fv.hx[left]);
        } else if (left < 0) {
          fa = m->fv.nfx + right + nx * j;
          ua = us[fa], ub = wall_solids(m, fa, 0, ua);
          gap = 0.5 * m->fv.hx[right];
        } else {
          fb = m->fv.nfx + left + nx * j;
          ub = us[fb], ua = wall_solids(m, fb, 1, ub);
          gap = 0.5 * m->fv.hx[left];
        }
        g += (ua - ub) / gap;
      }
      m->s.shear[i + (nx + 1) * j] = g;
    }
}

/* The solids shear rate of every cell, sqrt(2 S':S'). */
static void shear_rate(tfp_model *m, const double *us) {
  const int nx = m->fv.nx;
  corner_shear(m, us);
  for (int c = 0; c < m->fv.nc; ++c) {
    int i = c % nx, j = c / nx, cf[4];
    int fw = i + (nx + 1) * j, fs = m->fv.nfx + i + nx * j;
    cf[0] = fw, cf[1] = fw + 1, cf[2] = fs, cf[3] = fs + nx;
    double sxx = (us[cf[1]] - us[cf[0]]) / m->fv.hx[i], syy = (us[cf[3]] - us[cf[2]]) / m->fv.hy[j];
    double stt = m->axi ? 0.5 * (us[cf[0]] + us[cf[1]]) / m->fv.xc[i] : 0.0;
    if (m->axi) sxx = (m->grid.xf[i + 1] * us[cf[1]] - m->grid.xf[i] * us[cf[0]]) / (m->fv.xc[i] * m->fv.hx[i]) - stt;
    double sxy2 = 0.0; /* the mean square of S_xy = (du/dy + dv/dx)/2 over the four corners */
    for (int q = 0; q < 4; ++q) {
      double g = m->s.shear[(i + (q & 1)) + (nx + 1) * (j + (q >> 1))];
      sxy2 += 0.25 * 0.25 * g * g;
    }
    double tr = sxx + syy + stt;
    m->s.normal[c] = 2.0 * (sxx * sxx + syy * syy + stt * stt - tr * tr / 3.0);
    m->s.gdot[c] = sqrt(fmax(m->s.normal[c] + 4.0 * sxy2, 0.0));
  }
}

/* The cells around corner (i, j) of the grid (wrapping along a periodic
 * direction), their number: the open ones (a corner inside a body: all). */
static int corner_cells(const tfp_model *m, int i, int j, int cells[4]) {
  int n = 0, open = 0;
  for (int dj = -1; dj <= 0; ++dj)
    for (int di = -1; di <= 0; ++di) {
      int ci = i + di, cj = j + dj;
      if (m->fv.periodic[0]) ci = (ci + m->fv.nx) % m->fv.nx;
      if (m->fv.periodic[1]) cj = (cj + m->fv.ny) % m->fv.ny;
      if (ci >= 0 && ci < m->fv.nx && cj >= 0 && cj < m->fv.ny) cells[n++] = ci + m->fv.nx * cj;
    }
  for (int q = 0; q < n; ++q)
    if (!tfp_blocked(m, cells[q])) cells[open++] = cells[q];
  return open ? open : n;
}

/* mu_s and its tangent mu_s + gdot dmu_s/dgdot at N points from phi, the
 * shear rate, the mixture density and the drag coefficient there, with the
 * algebraic theta of the kinetic theory: mu_s0 gdot^2 sqrt(theta) = gamma0
 * theta^1.5 + 3 K theta (mu_s = mu_s0 sqrt(theta), gamma = gamma0
 * theta^1.5). The viscosity closure's own shear dependence is lagged (a
 * shear-thinning law converges so). */
static int solids_mu_points(tfp_model *m, int N, const double *phi, const double *gdot, const double *rho,
                            const double *K, double *theta, double *mu, double *mu_t, sl_diag *d) {
  tfp_solids *s = &m->s;
  const double *v[TF_Q_N];
  int rc;
  for (int k = 0; k < TF_Q_N; ++k) v[k] = s->qv[k];
  v[TF_Q_PHI] = phi, v[TF_Q_SHEAR_RATE] = gdot, v[TF_Q_DENSITY] = rho, v[TF_Q_THETA] = theta;
  for (int q = 0; q < N; ++q) mu[q] = s->mu_const;
  if (s->granular && !s->algebraic) { /* theta given: the kinetic viscosity at it, no shear dependence of its own */
    sl_point_request rq = {"mu_s", s->mu_k, NULL, NULL};
    for (int q = 0; q < N; ++q) s->kap[q] = 0.0;
    if ((rc = sl_point_eval(&s->gran, N, v, &rq, 1, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
  } else if (s->granular) {
    v[TF_Q_THETA] = s->one;
    sl_point_request rq[2] = {{"mu_s", s->mu_k, NULL, NULL}, {"gamma", s->gam, NULL, NULL}};
    if ((rc = sl_point_eval(&s->gran, N, v, rq, 2, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
    v[TF_Q_THETA] = theta;
    for (int q = 0; q < N; ++q) {
      /* kap: d ln sqrt(theta) / d ln gdot */
      theta[q] = sl_theta_algebraic(s->mu_k[q] * gdot[q] * gdot[q], s->gam[q], sl_theta_exchange(s->exchange, K[q]),
                                    &s->kap[q]);
      s->mu_k[q] *= sqrt(theta[q]);
    }
  }
  if (s->visc_c) {
    sl_point_request rq = {"viscosity", s->mum, NULL, NULL};
    if ((rc = sl_point_eval(&s->visc, N, v, &rq, 1, d))) return sl_diag_prefix(d, rc, "[closure.viscosity]");
    for (int q = 0; q < N; ++q) mu[q] += fmax(s->mum[q] - (1.0 - phi[q]) * m->c.mu_f, 0.0);
  }
  /* the stress mu_s(gdot) gdot grows as mu_s + gdot dmu_s/dgdot, the kinetic part as (1 + n) mu_k */
  for (int q = 0; q < N; ++q) {
    double mk = s->granular ? s->mu_k[q] : 0.0;
    mu_t[q] = mu[q] + (1.0 + s->kap[q]) * mk;
    mu[q] += mk;
    if (!isfinite(mu[q]) || mu[q] < 0.0)
      return sl_diag_set(d, SL_EFAILED, "the solids viscosity is %g (phi %g, shear rate %g 1/s)", mu[q], phi[q],
                         gdot[q]);
  }
  return 0;
}

int tfp_solids_viscosity(tfp_model *m, const double *us, const double *phi, sl_diag *d) {
  tfp_solids *s = &m->s;
  if (!s->any) return 0;
  const int nx = m->fv.nx, ny = m->fv.ny, nk = (nx + 1) * (ny + 1);
  shear_rate(m, us);
  for (int c = 0; c < m->fv.nc; ++c) {
    int i = c % nx, j = c / nx, fw = i + (nx + 1) * j, fs = m->fv.nfx + i + nx * j;
    s->rho[c] = (1.0 - phi[c]) * m->c.rho_f + phi[c] * m->c.rho_s;
    /* the sink's K, once the iteration is close: a drag law of |slip| (Wen & Yu's Re^0.687) is not smooth at
       the zero slip of a sheared suspension, and its round-off kept the iteration from converging */
    if (!m->sink_frozen) s->Kc[c] = 0.25 * (m->K[fw] + m->K[fw + 1] + m->K[fs] + m->K[fs + nx]);
  }
  /* the corners, where the shear stresses act: the means of their cells, their own shear */
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      int k = i + (nx + 1) * j, cells[4], n = corner_cells(m, i, j, cells);
      double ph = 0.0, rho = 0.0, K = 0.0, nrm = 0.0, sh = s->shear[k];
      for (int q = 0; q < n; ++q) {
        int c = cells[q];
        ph += phi[c] / n, rho += s->rho[c] / n, K += s->Kc[c] / n, nrm += s->normal[c] / n;
      }
      s->phi_k[k] = ph, s->rho_k[k] = rho, s->gdot_k[k] = sqrt(fmax(sh * sh + nrm, 0.0));
      if (!m->sink_frozen) s->K_k[k] = K;
      if (s->granular && !s->algebraic) { /* a transported theta: the mean of the cells' */
        double th = 0.0;
        for (int q = 0; q < n; ++q) th += s->theta_new[cells[q]] / n;
        s->theta_k[k] = th;
      }
    }
  int rc = solids_mu_points(m, m->fv.nc, phi, s->gdot, s->rho, s->Kc, s->theta_new, s->mu, s->mu_t, d);
  if (rc) return sl_diag_prefix(d, rc, "cells");
  if ((rc = solids_mu_points(m, nk, s->phi_k, s->gdot_k, s->rho_k, s->K_k, s->theta_k, s->mu_k_corner, s->mu_tk, d)))
    return sl_diag_prefix(d, rc, "grid corners");
  return 0;
}

/* The granular energy entering cell c through the walls with solids =
 * wall_stress on its sides (cf its four faces), per the wall closure's
 * theta_flux q(phi, theta, slip) (Johnson & Jackson 1987: the slip's
 * heating less the inelastic wall collisions' loss), linearised as every
 * model does (sl_theta_wall_row, core/models/granular.h: its sink part
 * implicit). The slip is that at
 * the wall of the two faces along it (their mean flux), phi and theta the
 * cell's. */
static int wall_energy(tfp_model *m, int c, const int cf[4], double *rhs, double *diag, sl_diag *d) {
  tfp_solids *s = &m->s;
  for (int dir = 0; dir < 2; ++dir)
    for (int side = 0; side < 2; ++side) {
      if (tfp_neighbour(m, c, dir, side) >= 0) continue;
      double q_sum = 0.0, c_sum = 0.0;
      int n = 0;
      for (int t = 0; t < 2; ++t) { /* the faces along the wall: x-faces along a bottom or top, y-faces along a side */
        int ft = tfp_primary(m, cf[2 * (1 - dir) + t]), e = 2 * ft + side, b = m->end_wall[e];
        if (b < 0 || m->b[b].solids != TFP_SOLIDS_WALL_STRESS) continue;
        double one[TF_Q_N], q, dq;
        const double *v[TF_Q_N];
        for (int k = 0; k < TF_Q_N; ++k) one[k] = s->qv[k][0], v[k] = &one[k];
        one[TF_Q_PHI] = m->phi_new[c], one[TF_Q_THETA] = s->th_old[c];
        one[TF_Q_SLIP_WALL] = one[TF_Q_SLIP] = fabs(m->end_us[e] - m->end_u[e]);
        one[TF_Q_WALL_DISTANCE] = 0.5 * (dir ? m->fv.hy[c / m->fv.nx] : m->fv.hx[c % m->fv.nx]);
        one[TF_Q_SHEAR_RATE] = s->gdot[c], one[TF_Q_DENSITY] = s->rho[c];
        sl_point_request rq = {"theta_flux", &q, &dq, "theta"};
        int rc = sl_point_eval(&s->wall, 1, v, &rq, 1, d);
        if (rc)
          return sl_diag_prefix(d, rc, "[closure.wall_stress] theta_flux in cell (%d, %d)", c % m->fv.nx, c / m->fv.nx);
        q_sum += q, c_sum += sl_theta_wall_implicit(dq), ++n;
      }
      if (!n) continue;
      sl_theta_wall_row(m->fv.area[cf[2 * dir + side]] / n, q_sum, c_sum, s->th_old[c], rhs, diag);
    }
  return 0;
}

/* The transported granular temperature (`granular_temperature = transport`)
 * of the iterate, cell by cell, with the pointwise terms shared by every
 * model (sl_theta_terms, core/models/granular.h; Krampa 2009 eq 5.10):
 *   (3/2) rho_s phi dtheta/dt = div(kappa grad theta) + mu_k gdot^2 - gamma - 3 K theta,
 * mu_k the kinetic viscosity, backward Euler on core/fv/cell_scalar.h.
 * Newton in the dissipation gamma(theta); kappa, mu_k and K from the last
 * iterate; the shear rate of the velocities just solved. The
 * walls with solids = wall_stress pass the wall closure's theta_flux
 * (wall_energy), the others are adiabatic; there is no convection of theta
 * (the model's momentum has none either). *change: the largest change of
 * theta. */
/* The walls' energy flux into cell c's equation (sl_cell_scalar_terms boundary). */
static int wall_energy_of(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  tfp_model *m = user;
  int cf[4];
  sl_fv_cell_faces(&m->fv, c, cf);
  return wall_energy(m, c, cf, rhs, diag, d);
}

int tfp_theta_solve(tfp_model *m, double dt, double *change, sl_diag *d) {
  tfp_solids *s = &m->s;
  const int nc = m->fv.nc;
  int rc;
  if (!s->th.ls && (rc = sl_cell_scalar_init(&s->th, &m->fv, d)))
    return sl_diag_prefix(d, rc, "the granular temperature's system");
  shear_rate(m, m->us_new);
  for (int c = 0; c < nc; ++c) s->th_old[c] = fmax(s->theta_new[c], SL_THETA_FLOOR);
  const double *v[TF_Q_N];
  for (int k = 0; k < TF_Q_N; ++k) v[k] = s->qv[k];
  v[TF_Q_PHI] = m->phi_new, v[TF_Q_THETA] = s->th_old, v[TF_Q_SHEAR_RATE] = s->gdot, v[TF_Q_DENSITY] = s->rho;
  sl_point_request rq[3] = {
      {"mu_s", s->mu_k, NULL, NULL}, {"kappa", s->kap, NULL, NULL}, {"gamma", s->gam, s->dgam, "theta"}};
  if ((rc = sl_point_eval(&s->gran, nc, v, rq, 3, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
  for (int c = 0; c < nc; ++c) s->th_sink[c] = sl_theta_exchange(s->exchange, s->Kc[c]);
  sl_theta_terms(nc, m->c.rho_s, m->phi_new, s->mu_k, s->gdot, s->gam, s->dgam, s->th_sink, s->th_old, s->th_cap,
                 s->th_src, s->th_sink);
  sl_cell_scalar_terms terms = {.dt = dt,
                                .cap = s->th_cap,
                                .s_old = s->theta,
                                .k = s->kap,
                                .source = s->th_src,
                                .sink = s->th_sink,
                                .boundary = s->wall_energy ? wall_energy_of : NULL,
                                .boundary_user = m};
  if ((rc = sl_cell_scalar_solve(&s->th, &terms, s->th_x, d)))
    return sl_diag_prefix(d, rc, "the granular temperature's solve");
  double ch = 0.0;
  for (int c = 0; c < nc; ++c) {
    if (!isfinite(s->th_x[c]))
      return sl_diag_set(d, SL_EFAILED, "the granular temperature is not finite in cell (%d, %d)", c % m->fv.nx,
                         c / m->fv.nx);
    /* theta stays positive: at most a fivefold fall per iteration */
    double th = sl_theta_bounded(s->th_x[c], s->th_old[c]);
    ch = fmax(ch, fabs(th - s->th_old[c]));
    s->theta_new[c] = th;
  }
  *change = ch;
  return 0;
}

int tfp_solids_pressure(tfp_model *m, const double *phi, double *ps, double *dps, sl_diag *d) {
  tfp_solids *s = &m->s;
  if (!s->granular || !s->kinetic_pressure) return 0;
  const double *v[TF_Q_N];
  for (int k = 0; k < TF_Q_N; ++k) v[k] = s->qv[k];
  for (int c = 0; c < m->fv.nc; ++c) s->th_old[c] = fmax(s->theta_new[c], SL_THETA_FLOOR);
  /* the algebraic theta of an iterate may leave the closure's range (a wall started impulsively shears its
     cell at U / (h/2)): p_s ~ theta is evaluated at theta = 1 and scaled (checked at set-up) */
  v[TF_Q_PHI] = phi, v[TF_Q_THETA] = s->algebraic ? s->one : s->th_old;
  v[TF_Q_SHEAR_RATE] = s->gdot, v[TF_Q_DENSITY] = s->rho;
  sl_point_request rq = {"p_s", s->mum, s->gam, "phi"};
  int rc = sl_point_eval(&s->gran, m->fv.nc, v, &rq, 1, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.granular] p_s");
  for (int c = 0; c < m->fv.nc; ++c) {
    double scale = s->algebraic ? s->th_old[c] : 1.0;
    ps[c] += scale * s->mum[c], dps[c] += scale * s->gam[c];
  }
  return 0;
}

/* tau_w and d tau_w / d slip at one point. */
/* tau_w and d tau_w / d slip at face f, phi given; theta, the shear rate and
 * the density the means of the face's two cells (one cell's would bias the
 * wall along the face's direction). */
static int wall_tau(tfp_model *m, int f, double phi, double slip, double dist, double *tau, double *dtau, sl_diag *d) {
  tfp_solids *s = &m->s;
  double one[TF_Q_N], th = 0.0, gd = 0.0, rho = 0.0;
  int n = 0;
  for (int side = 0; side < 2; ++side) {
    int c = side ? m->fv.hi[f] : m->fv.lo[f];
    if (c >= 0) th += s->theta_new[c], gd += s->gdot[c], rho += s->rho[c], ++n;
  }
  const double *v[TF_Q_N];
  for (int k = 0; k < TF_Q_N; ++k) one[k] = s->qv[k][0], v[k] = &one[k];
  one[TF_Q_PHI] = phi, one[TF_Q_THETA] = fmax(th / n, SL_THETA_FLOOR), one[TF_Q_SLIP_WALL] = slip;
  one[TF_Q_SLIP] = slip, one[TF_Q_WALL_DISTANCE] = dist, one[TF_Q_SHEAR_RATE] = gd / n;
  one[TF_Q_DENSITY] = rho / n;
  sl_point_request rq[2] = {{"tau_w", tau, dtau, "slip_wall"}, {"bagnold_number", &s->last_bagnold, NULL, NULL}};
  s->last_bagnold = NAN;
  return sl_point_eval(&s->wall, 1, v, rq, sl_point_has_output(&s->wall, "bagnold_number") ? 2 : 1, d);
}

int tfp_solids_wall(tfp_model *m, int f, int end, double mu, double h, double *R0, double *dR, sl_diag *d) {
  int e = 2 * f + end;
  double U = m->end_u[e], u = m->us_new[f], phi = m->phf[f], tau, dtau;
  int rc;
  if (m->s.wall_function || mu <= 0.0) { /* the slip of the face, half a cell from the wall */
    double sl = u - U, sg = sl > 0.0 ? 1.0 : sl < 0.0 ? -1.0 : 0.0;
    if ((rc = wall_tau(m, f, phi, fabs(sl), 0.5 * h, &tau, &dtau, d))) goto failed;
    *R0 = tau * sg, *dR = fmax(dtau, 0.0);
    m->end_us[e] = u;
    return 0;
  }
  /* the slip at the wall: k (u - u_w) = tau_w(u_w - U) sign, by Newton from the last one */
  double k = mu / (0.5 * h), uw = m->end_us[e];
  if (!isfinite(uw) || (uw - U) * (u - U) < 0.0 || fabs(uw - U) > fabs(u - U)) uw = U + 0.5 * (u - U);
  for (int it = 0; it < 50; ++it) {
    double sl = uw - U, sg = sl > 0.0 ? 1.0 : sl < 0.0 ? -1.0 : 0.0;
    if ((rc = wall_tau(m, f, phi, fabs(sl), 0.5 * h, &tau, &dtau, d))) goto failed;
    double g = k * (u - uw) - tau * sg, dg = -k - fmax(dtau, 0.0);
    double next = uw - g / dg;
    /* between the wall's speed and the face's: the stress has the slip's sign and is below k |u - U| */
    double lo = fmin(U, u), hi = fmax(U, u);
    next = fmin(fmax(next, lo), hi);
    double change = fabs(next - uw);
    uw = next;
    if (change <= 1e-14 * fmax(fabs(u - U), 1e-300)) break;
  }
  {
    double sl = uw - U, sg = sl > 0.0 ? 1.0 : sl < 0.0 ? -1.0 : 0.0;
    if ((rc = wall_tau(m, f, phi, fabs(sl), 0.5 * h, &tau, &dtau, d))) goto failed;
    m->end_us[e] = uw;
    *R0 = tau * sg;
    dtau = fmax(dtau, 0.0);
    *dR = k * dtau / (k + dtau);
  }
  return 0;
failed:
  return sl_diag_prefix(d, rc, "[closure.wall_stress] at (%g, %g)",
                        f < m->fv.nfx ? m->grid.xf[f % (m->fv.nx + 1)] : m->fv.xc[(f - m->fv.nfx) % m->fv.nx],
                        f < m->fv.nfx ? m->fv.yc[f / (m->fv.nx + 1)] : m->grid.yf[(f - m->fv.nfx) / m->fv.nx]);
}
