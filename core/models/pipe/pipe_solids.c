/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids of the pipe model (pipe.h): the drag, the solids viscosity,
 * the granular temperature's local balance, the solids' wall coefficient, and
 * the radial solids balance that sets phi(r).
 *
 * Granular temperature (with [closure.granular]): production by the solids
 * shear against the collisional and the drag's dissipation, conduction and
 * convection dropped (van Wachem et al. 2001's algebraic form; Krampa 2009
 * eq 5.10 in the standard form of section 2.5 with the fluid-particle
 * correlation neglected, as Krampa did):
 *   mu_s(phi, theta) gdot_s^2 = gamma(phi, theta) + 3 K theta,
 * solved in each cell by bisection in log theta (the left side grows as
 * theta^1/2, the right as theta^3/2 and theta).
 *
 * Radial balance: with no mean radial motion, the radial momentum of the
 * fluid, 0 = -c_f dP/dr - F_TD, and of the solids, 0 = -c_s dP/dr - dp_s/dr +
 * F_TD, give F_TD = c_f dp_s/dr; with the turbulent dispersion force of
 * Burns et al. (2004), F_TD = -K (nu_t/sigma_d) phi'/(c_s c_f) (Krampa 2009
 * eq 4.57 with the gradient closure 4.59), this is a zero net radial flux
 *   phi v - D phi' = 0,  D = nu_t/sigma_d + c_s c_f^2 (dp_s/dphi)/K,
 *   v = -c_f^2 (dp_s/dtheta) theta'/K,
 * a cell scalar (core/fv/cell_scalar.h) with no flux through the axis and the
 * wall. The dispersivity is [closure.turbulent_dispersion]'s: model = gradient, nu_t/sigma_d, or
 * model = simonin, Simonin's D_fs = t_fs k_fs/3 (Krampa 2009 eq 4.63, Enwald et al. 1996)
 * with the eddy-particle interaction time seen by a particle crossing the
 * eddies (Csanady 1963; Krampa eq 4.61),
 *   t_fs = C_mu (3k/(2 eps)) [1 + C_beta 3 |u_f - u_s|^2/(2k)]^(-1/2),
 * and the fluid-particle covariance of Tchen's equilibrium for heavy
 * particles, k_fs = 2 k eta/(1 + eta), eta = t_fs/t_p, t_p = c_s rho_s/K
 * (Krampa eq 4.58): fine particles (eta large) disperse as the fluid, D_fs ->
 * C_mu k^2/eps = nu_t; with `[pipe] solids_turbulence = transported` k_fs is model C's transported one
 * (pipe_ksfs.c). The kinetic theory's pressure joins with [pipe] kinetic_pressure:
 * where phi is small its theta grows as 1/phi^2 (the dissipation falls with
 * phi^2, the dilute viscosity does not) and rho_s phi theta with it, so that
 * it drives solids from where they are fewest; in dilute flow (5 %) this runs
 * away near the wall and the steady solve does not converge. The pseudo-time
 * step keeps the section's solids inventory; phi is kept below phi_max - 0.01
 * and the inventory restored to the given mean. In the developing pipe the balance gains the axial convection
 * of the solids and the radial convection by the mixture's volume flux (pipe_march.c), and carries the inlet's
 * solids flux in place of an inventory. */
#include <math.h>
#include <string.h>

#include "core/models/granular.h"
#include "core/models/pipe/pipe_impl.h"

/* |du_s/dr| in the cells, from the face gradients (zero at the axis; the wall face's from the last wall stress
   over the last solids viscosity: called before mu_s is renewed). */
static void solids_shear(const pipe *p, double *gd) {
  const int n = p->n;
  double *gw = p->buf[14], *ge = p->buf[15];
  pipe_face_gradients(p, p->us, -p->a_sw * p->us[n - 1] / fmax(p->mu_s[n - 1], 1e-300), gw, ge);
  for (int i = 0; i < n; ++i) gd[i] = sqrt(0.5 * (gw[i] * gw[i] + ge[i] * ge[i]));
}

/* mu_s and gamma of [closure.granular] at theta in every cell (sl_theta_balance's closure). */
static int granular_at(void *user, const double *th, double *mu, double *gam, sl_diag *d) {
  pipe *p = user;
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = p->phi, v[PQ_THETA] = th;
  sl_point_request rq[2] = {{"mu_s", mu, NULL, NULL}, {"gamma", gam, NULL, NULL}};
  int rc = sl_point_eval(&p->gran, p->n, v, rq, 2, d);
  return rc ? sl_diag_prefix(d, rc, "[closure.granular]") : 0;
}

/* theta of the local balance in every cell (core/models/granular.h). */
static int granular_theta(pipe *p, const double *gd, sl_diag *d) {
  const int n = p->n;
  double *lo = p->buf[1], *hi = p->buf[2], *th = p->buf[3], *X = p->buf[7], *mu = p->buf[5], *gam = p->buf[6];
  for (int i = 0; i < n; ++i) X[i] = sl_theta_exchange(1, p->K[i]);
  int rc = sl_theta_balance(n, gd, X, granular_at, p, lo, hi, mu, gam, th, d);
  if (rc) return rc;
  const double w = p->iterations > 0 ? p->relax : 1.0; /* under-relaxed as the velocities */
  for (int i = 0; i < n; ++i) p->theta[i] = fmax(p->theta[i] + w * (th[i] - p->theta[i]), SL_THETA_FLOOR);
  return 0;
}

/* The solids' normal stress on the wall, for a wall closure that takes one (`normal_stress`: wall_stress/coulomb),
   at the wall cell: the contact (frictional) pressure of [closure.solids_pressure], p_s(phi), the normal stress
   of Johnson & Jackson's (1987) frictional wall term tau_sn^f tan(phi_w) (Krampa 2009 eq 4.92), whose collisional
   part is wall_stress/johnson_jackson's; with [pipe] wall_normal_stress = contact_kinetic also the kinetic
   theory's p_s(phi, theta) of [closure.granular] (Lun et al. 1984, Krampa 2009 eq 5.9), whether or not [pipe]
   kinetic_pressure puts it in the radial balance. Nothing else presses the solids on the wall of a vertical
   pipe: there is no weight across the section. */
static int wall_normal_stress(pipe *p, double *pn, sl_diag *d) {
  const int w = p->n - 1;
  double phw = p->phi[w], thw = p->theta[w], ps = 0.0;
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = &phw, v[PQ_THETA] = &thw;
  *pn = 0.0;
  int rc = 0;
  if (p->have_psol) {
    sl_point_request rq = {"p_s", &ps, NULL, NULL};
    if ((rc = sl_point_eval(&p->psol, 1, v, &rq, 1, d))) return sl_diag_prefix(d, rc, "[closure.solids_pressure]");
    *pn += ps;
  }
  if (p->have_gran && p->cfg->wall_normal_stress == PIPE_NORMAL_CONTACT_KINETIC) {
    sl_point_request rq = {"p_s", &ps, NULL, NULL};
    if ((rc = sl_point_eval(&p->gran, 1, v, &rq, 1, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
    *pn += ps;
  }
  *pn = fmax(*pn, 0.0);
  return 0;
}

int pipe_solids_coefficients(pipe *p, sl_diag *d) {
  const int n = p->n;
  double *slip = p->buf[0], *gd = p->buf[4], *dK = p->buf[1];
  for (int i = 0; i < n; ++i) p->slip0[i] = p->uf[i] - p->us[i], slip[i] = fabs(p->slip0[i]);
  const double *v[PQ_N] = {0};
  /* the developing pipe: the drag's fraction from the last station (pipe_march_drag) */
  v[PQ_PHI] = p->march.on ? pipe_march_drag_fraction(p, p->buf[2]) : p->phi, v[PQ_SLIP] = slip;
  sl_point_request rq = {"K", p->K, dK, "slip"};
  int rc = sl_point_eval(&p->drag, n, v, &rq, 1, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.drag]");
  if (p->march.on) pipe_march_drag(p, p->buf[2], dK);
  v[PQ_PHI] = p->phi;
  /* the drag force K(s) s linearised about the last slip: its slope d(K s)/ds = K + s dK/ds (the lagged K alone
     oscillates where K grows with s, K ~ s at high particle Reynolds numbers) */
  for (int i = 0; i < n; ++i) p->Kd[i] = fmax(p->K[i] + slip[i] * dK[i], p->K[i] * 1e-3);
  /* mu_s: the dispersed phase's eddy viscosity, the constant, the kinetic theory's */
  if (p->have_gran) solids_shear(p, gd);
  /* model C's transported k_s and k_fs start from Tchen's equilibrium at the first drag (pipe_ksfs.c) */
  if (p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED && !p->ksfs_started) pipe_ksfs_start(p);
  if (p->cfg->solids_viscosity == PIPE_SOLIDS_VISCOSITY_PEIRANO_LECKNER) /* Krampa's model C (pipe_peirano.c) */
    for (int i = 0; i < n; ++i) {
      pipe_pl_point q = pipe_pl_point_at(p, i);
      p->mu_s[i] = p->phi[i] * p->rho_s * pipe_peirano_leckner(&q, NULL) + p->sc->solid.viscosity;
    }
  else if (p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_K_EPSILON) /* models A, B (pipe_kseps_solid.c) */
    pipe_kseps_viscosity(p);
  else
    for (int i = 0; i < n; ++i)
      p->mu_s[i] = p->phi[i] * p->rho_s * (p->mu_t[i] / p->rho_f) / p->cfg->solids_schmidt + p->sc->solid.viscosity;
  if (p->have_gran) {
    if ((rc = p->cfg->granular_temperature == PIPE_THETA_TRANSPORT ? pipe_theta_transport(p, gd, d)
                                                                   : granular_theta(p, gd, d)))
      return rc;
    double *mu = p->buf[5];
    v[PQ_THETA] = p->theta;
    sl_point_request r2 = {"mu_s", mu, NULL, NULL};
    if ((rc = sl_point_eval(&p->gran, n, v, &r2, 1, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
    for (int i = 0; i < n; ++i) p->mu_s[i] += mu[i];
  }
  /* the solids' wall: tau_sw = a_sw u_s of the wall cell. Across the wall cell the solids' eddy viscosity
     c_s rho_s nu_t/sigma is bridged by the fluid's wall function, as the fluid's own is (nu_t of the log layer,
     the same for both phases but for sigma: tau = (c_s rho_s/(sigma rho_f)) a_fw u_s), the rest of mu_s (the
     constant, the kinetic theory's) linearly (mu/y) */
  const int w = n - 1;
  const double yp = p->R - p->g.xc[w];
  const double turb_w = p->phi[w] * p->rho_s * (p->mu_t[w] / p->rho_f) / p->cfg->solids_schmidt;
  const double a_ns =
      p->phi[w] * p->rho_s / (p->cfg->solids_schmidt * p->rho_f) * p->a_fw + fmax(p->mu_s[w] - turb_w, 0.0) / yp;
  switch (p->cfg->solids_wall) {
    case PIPE_NO_SLIP:
      p->a_sw = a_ns;
      break;
    case PIPE_FREE_SLIP:
      p->a_sw = 0.0;
      break;
    default: {
      /* a wall function (a wall_distance input: Bartosik, Bagnold) takes the wall cell's speed; a slip law
       (Johnson & Jackson, Navier slip) the speed at the wall: the bridge and the law in series, u_w = a_ns u_p/
       (a_ns + a), a_sw = a a_ns/(a_ns + a), a = tau/u_w of the last iterate */
      double U = fabs(p->us[w]), uw = U, tau, dtau;
      if (!p->walls_at_node && p->a_sw > 0.0) {
        double a = p->a_sw < a_ns ? p->a_sw * a_ns / (a_ns - p->a_sw) : 1e12 * a_ns; /* invert a_sw */
        uw = U * a_ns / (a_ns + a);
      }
      const double *vw[PQ_N] = {0};
      double phw = p->phi[w], thw = p->theta[w], gdw = U / yp, pn = 0.0;
      if (p->walls_normal && (rc = wall_normal_stress(p, &pn, d))) return rc;
      p->p_wall = pn;
      vw[PQ_SLIP_WALL] = &uw, vw[PQ_PHI] = &phw, vw[PQ_THETA] = &thw, vw[PQ_SHEAR] = &gdw, vw[PQ_NORMAL_STRESS] = &pn;
      p->u_wall = uw;
      double inv = 0.0;
      sl_point_request rw[2] = {{"tau_w", &tau, &dtau, "slip_wall"}, {"inverse_slip_length", &inv, NULL, NULL}};
      if ((rc = sl_point_eval(&p->walls, 1, vw, rw, sl_point_has_output(&p->walls, "inverse_slip_length") ? 2 : 1, d)))
        return sl_diag_prefix(d, rc, "[closure.wall_stress.solids]");
      p->inv_slip = inv;
      double a = uw > 0.0 ? tau / uw : dtau;
      p->a_sw = p->walls_at_node ? a : a * a_ns / (a_ns + a);
    }
  }
  return 0;
}

/* The shear lift ([closure.lift]) in the radial balance, added to the faces' volume fluxes. The force on the
   solids per unit volume, F_L = C_L rho_f c_s (u_f - u_s) x curl u_f (Drew & Lahey 1979, Int. J. Multiphase Flow
   5:243, eq 41), has for axial velocities u(r) e_z (curl u_f = -(du_f/dr) e_theta, e_z x e_theta = -e_r) the
   radial component
     F_L = c_s rho_f C_L (u_f - u_s) du_f/dr,
   equal and opposite on the fluid. In the radial momenta of the phases (the header's derivation) it joins the
   dispersion, F_TD + F_L = c_f dp_s/dr, so the zero net flux phi v - D phi' = 0 gains the drift
     v_L = c_f F_L/K = c_f rho_f C_L (u_f - u_s) (du_f/dr)/(K/c_s),
   K/c_s the drag per unit volume of solids (finite as c_s -> 0). In up-flow heavy particles lag the fluid
   (u_f - u_s > 0) where du_f/dr < 0: v_L < 0, towards the axis (Saffman 1965: towards the faster fluid), and in
   down-flow they lead it and go to the wall. At the interior faces, with C_L of the face's |du_f/dr| (floored at
   1e-9 s^-1, where C_L du_f/dr vanishes), slip and distance from the wall; nothing crosses the axis or the wall. */
static int lift_flux(pipe *p, double *flux, sl_diag *d) {
  const int n = p->n, m = n - 1;
  const sl_fv_grid *g = &p->g;
  if (m < 1) return 0;
  double *cl = p->buf[6], *sh = p->buf[14], *sl = p->buf[15], *ph = p->buf[16], *yw = p->buf[17];
  for (int f = 1; f < n; ++f) {
    const int i = f - 1;
    sh[i] = fmax(fabs(p->uf[f] - p->uf[i]) / g->dist[f], 1e-9);
    sl[i] = fabs(0.5 * (p->slip0[i] + p->slip0[f]));
    ph[i] = 0.5 * (p->phi[i] + p->phi[f]);
    yw[i] = fmax(p->R - (g->xc[i] + 0.5 * g->hx[i]), 1e-9);
  }
  const double *v[PQ_N] = {0};
  v[PQ_SHEAR] = sh, v[PQ_SLIP] = sl, v[PQ_PHI] = ph, v[PQ_WALL_DISTANCE] = yw;
  sl_point_request rq = {"C_L", cl, NULL, NULL};
  int rc = sl_point_eval(&p->lift, m, v, &rq, 1, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.lift]");
  for (int f = 1; f < n; ++f) {
    const int i = f - 1;
    const double Ks = 0.5 * (p->K[i] / fmax(p->phi[i], 1e-12) + p->K[f] / fmax(p->phi[f], 1e-12));
    const double vl =
        (1.0 - ph[i]) * p->rho_f * cl[i] * 0.5 * (p->slip0[i] + p->slip0[f]) * (p->uf[f] - p->uf[i]) / g->dist[f] / Ks;
    flux[f] += vl * g->area[f];
  }
  return 0;
}

/* The solids' turbulent dispersivity D_t of [closure.turbulent_dispersion] in every cell, from the fluid's nu_t =
   mu_t/rho_f, the eddy-particle interaction time t_fs with the crossing trajectories (Krampa 2009 eq 4.61, pipe_tfs)
   and the fluid-particle covariance k_fs (Tchen's or model C's, pipe_kfs), each computed where the closure takes it;
   without the section the gradient form with Schmidt number 1 (Krampa eq 4.59), D_t = nu_t. Scratch buf[14..16]. */
int pipe_turbulent_dispersivity(pipe *p, double *Dt, sl_diag *d) {
  const int n = p->n;
  double *nu = p->buf[14], *tfs = p->buf[15], *kfs = p->buf[16];
  for (int i = 0; i < n; ++i) nu[i] = p->mu_t[i] / p->rho_f;
  if (!p->have_disp) {
    memcpy(Dt, nu, (size_t)n * sizeof *Dt);
    return 0;
  }
  const int want_t = sl_point_has_input(&p->disp, "t_fs"), want_k = sl_point_has_input(&p->disp, "k_fs");
  for (int i = 0; i < n; ++i) {
    if (want_t) tfs[i] = pipe_tfs(p, i);
    if (want_k) kfs[i] = pipe_kfs(p, i);
  }
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = p->phi, v[PQ_K] = p->k, v[PQ_EPS] = p->eps;
  v[PQ_NU_T] = nu, v[PQ_T_FS] = tfs, v[PQ_K_FS] = kfs, v[PQ_DRAG] = p->K;
  sl_point_request rq = {"D_t", Dt, NULL, NULL};
  int rc = sl_point_eval(&p->disp, n, v, &rq, 1, d);
  return rc ? sl_diag_prefix(d, rc, "[closure.turbulent_dispersion]") : 0;
}

int pipe_solids_update(pipe *p, sl_diag *d) {
  const int n = p->n;
  const sl_fv_grid *g = &p->g;
  double *B = p->buf[0], *Pt = p->buf[1], *D = p->buf[2], *cap = p->buf[3], *s = p->buf[5];
  double *flux = p->face_flux; /* the grid's faces: the row's x-faces 0..n, then the (periodic) z-faces */
  for (int i = 0; i < n; ++i) B[i] = 0.0, Pt[i] = 0.0;
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = p->phi, v[PQ_THETA] = p->theta;
  int rc = 0;
  if (p->have_psol) {
    double *ps = p->buf[4], *dps = p->buf[7];
    sl_point_request rq = {"p_s", ps, dps, "phi"};
    if ((rc = sl_point_eval(&p->psol, n, v, &rq, 1, d))) return sl_diag_prefix(d, rc, "[closure.solids_pressure]");
    for (int i = 0; i < n; ++i) B[i] += dps[i];
  }
  const int kinetic = p->have_gran && p->cfg->kinetic_pressure;
  if (kinetic) {
    double *ps = p->buf[4], *dph = p->buf[7];
    sl_point_request rq[2] = {{"p_s", ps, dph, "phi"}, {"p_s", ps, Pt, "theta"}};
    if ((rc = sl_point_eval(&p->gran, n, v, rq, 2, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
    for (int i = 0; i < n; ++i) B[i] += dph[i];
  }
  double *Dt = p->buf[17];
  if ((rc = pipe_turbulent_dispersivity(p, Dt, d))) return rc;
  double Dmax = 0.0;
  for (int i = 0; i < n; ++i) {
    double cs = p->phi[i], cf = 1.0 - cs;
    D[i] = Dt[i] + cs * cf * cf * B[i] / p->K[i];
    Dmax = fmax(Dmax, D[i]);
    cap[i] = 1.0;
  }
  memset(flux, 0, (size_t)g->nf * sizeof *flux);
  for (int i = 0; i + 1 < n && kinetic; ++i) {
    int f = i + 1;
    double cf = 1.0 - 0.5 * (p->phi[i] + p->phi[i + 1]), K = 0.5 * (p->K[i] + p->K[i + 1]);
    double vr = -cf * cf * 0.5 * (Pt[i] + Pt[i + 1]) * (p->theta[i + 1] - p->theta[i]) / g->dist[f] / K;
    flux[f] = vr * g->area[f];
  }
  if (p->have_lift && (rc = lift_flux(p, flux, d))) return rc;
  sl_cell_scalar_terms t = {.dt = 1e3 * p->R * p->R / fmax(Dmax, 1e-300),
                            .cap = cap,
                            .s_old = p->phi,
                            .k = D,
                            .flux = kinetic || p->have_lift ? flux : NULL};
  if (p->march.on) { /* the developing pipe: the solids' flux marched along z (pipe_march.c) */
    pipe_march_solids(p, cap, flux);
    t.dt = 1.0, t.s_old = p->march.s_old, t.flux = flux;
  }
  rc = sl_cell_scalar_solve(&p->cs, &t, s, d);
  if (rc) return sl_diag_prefix(d, rc, "pipe: the radial solids balance");
  /* bound and restore the inventory (the developing pipe carries its inlet's flux instead: bounded only) */
  double target = p->phi_target, cap_phi = p->phi_max - 0.01;
  for (int pass = 0; pass < (p->march.on ? 1 : 20); ++pass) {
    double m = 0.0, A = 0.0;
    for (int i = 0; i < n; ++i) s[i] = fmin(fmax(s[i], 0.0), cap_phi), m += g->vol[i] * s[i], A += g->vol[i];
    if (p->march.on) break;
    double scale = target * A / m;
    if (fabs(scale - 1.0) < 1e-14) break;
    for (int i = 0; i < n; ++i) s[i] *= scale;
  }
  const double w = p->relax;
  for (int i = 0; i < n; ++i) p->phi[i] += w * (s[i] - p->phi[i]);
  return 0;
}

/* A jump of the drag in a cell of the reached state (pipe.h): K of [closure.drag] at the cell's phi and slip
   scaled by 1 -+ 1e-3, each pair against the trapezoid of its end slopes, which a K continuous and smooth there
   meets to O(1e-6) of K. Where it misses by more than 1e-4 K the closure is discontinuous inside the window (the
   Wen-Yu C_D of Gidaspow's drag, +0.39 % at Re = 1000; its unblended switch at phi = 0.2): a cell whose balance
   falls on the jump has no steady state, and the outer iteration cycles about it. The largest relative jump,
   its cell and the input it is found across ("slip"; else "phi") go to *jump, *cell, *across (0, -1, NULL: none). Scratch
   buf[0..7]. */
int pipe_drag_jump(pipe *p, double *jump, int *cell, const char **across, sl_diag *d) {
  const int n = p->n;
  const double h = 1e-3;
  *jump = 0.0, *cell = -1, *across = NULL;
  if (!p->two_phase || p->march.on) return 0;
  double *ph = p->buf[0], *sl = p->buf[1], *K = p->buf[2], *dK = p->buf[3];
  for (int pass = 0; pass < 2 && *cell < 0; ++pass) { /* across the slip, then (none there) across phi */
    double *lo = p->buf[4 + 2 * pass], *slo = p->buf[5 + 2 * pass];
    for (int side = 0; side < 2; ++side) {
      const double f = side ? 1.0 + h : 1.0 - h;
      for (int i = 0; i < n; ++i) {
        sl[i] = fabs(p->uf[i] - p->us[i]) * (pass == 0 ? f : 1.0);
        ph[i] = p->phi[i] * (pass == 1 ? f : 1.0);
      }
      const double *v[PQ_N] = {0};
      v[PQ_PHI] = ph, v[PQ_SLIP] = sl;
      sl_point_request rq = {"K", K, dK, pass == 0 ? "slip" : "phi"};
      int rc = sl_point_eval(&p->drag, n, v, &rq, 1, d);
      if (rc) return sl_diag_prefix(d, rc, "[closure.drag]");
      for (int i = 0; i < n; ++i) {
        const double x = pass == 0 ? fabs(p->uf[i] - p->us[i]) : p->phi[i];
        if (!side) {
          lo[i] = K[i], slo[i] = dK[i];
          continue;
        }
        const double dk = K[i] - lo[i], pred = 0.5 * (dK[i] + slo[i]) * 2.0 * h * x;
        const double r = fabs(dk - pred) / fmax(0.5 * (K[i] + lo[i]), 1e-300);
        if (x > 0.0 && r > 1e-4 && r > *jump) *jump = r, *cell = i, *across = pass == 0 ? "slip" : "phi";
      }
    }
  }
  return 0;
}
