/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids' k_s-eps_s of Krampa's (2009) models A and B (`[pipe] solids_turbulence = k_epsilon`, pipe.h): the
 * solids-phase turbulence of CFX-4.4's baseline two-phase model, "a k-epsilon type two-equation model similar to
 * that of the fluid-phase" with "the default model constants of the k-epsilon turbulence model in ANSYS CFX-4.4,
 * given in Table 4.1" (Krampa 2009 section 5.1.1; model B solves the same pair, section 5.1.2), and without the
 * modulation ("the last term in equations (4.82) and (4.83) does not appear", section 5.1.1; digest section 1.4:
 * in models A and B no source or sink couples the phases' turbulence). Eqs 4.82-4.83 written for the solids, fully
 * developed (the drift terms vanish: axial slip, radial gradients), one pseudo-time step of each on the shared
 * cell-scalar solver (core/fv/cell_scalar.h) as the fluid's (pipe_turbulence.c):
 *   c_s rho_s (k_s - k_s*)/dtau = (1/r) d/dr(r (mu_sl + c_s mu_st/sigma_k) dk_s/dr) + c_s P_s - c_s rho_s eps_s
 *   c_s rho_s (e_s - e_s*)/dtau = (1/r) d/dr(r (mu_sl + c_s mu_st/sigma_e) de_s/dr) + c_s C_e1 (e_s/k_s) P_s
 *                                 - c_s C_e2 rho_s e_s^2/k_s
 *   mu_st = C_mu rho_s k_s^2/eps_s,   P_s = mu_st (du_s/dr)^2,
 * mu_sl the constant solids viscosity ([solid] viscosity: model A's 1e-8 Pa s), taken as the solids' momentum
 * takes it, not weighted by c_s (pipe_solids.c: mu_s = c_s mu_st + mu_sl), where eq 4.82 has c_f mu_f. The constants are the fluid's
 * [closure.turbulence] (model = k_epsilon: Table 4.1, C_mu 0.09, C_e1 1.44, C_e2 1.92, sigma_k 1.0, sigma_e 1.3),
 * the closure evaluated at (k_s, eps_s, rho_s): one set of constants for both phases, as CFX-4's. The solids'
 * stress is the phase's c_s mu_st (Krampa eq 4.70: rho_s c_s <u_s'' u_s''> = 2 mu_st S_s - (2/3) rho_s c_s k_s I,
 * mu_st there per unit c_s), which replaces the dispersed phase's zero-equation c_s rho_s nu_t/sigma in mu_s
 * (pipe_solids.c); model B adds the kinetic theory's collisional viscosity of theta beside it (his "small-scale"
 * fluctuations, T_s; the "large-scale" ones are k_s).
 *
 * Wall: the thesis states a wall function for the liquid only (section 4.5.1, eqs 4.84-4.86); here the solids'
 * wall cell holds the same log-law values as the fluid's, k_s = u_tau^2/sqrt(C_mu) and eps_s = u_tau^3/(kappa y)
 * (eqs 4.85-4.86, the fluid's u_tau): CFX-4's phase-weighted k-epsilon applies its one wall function to each
 * phase. Then the solids' eddy viscosity at the wall cell is the log layer's nu_t times rho_s, the one the solids'
 * wall bridge of pipe_solids.c takes (c_s rho_s nu_t/sigma with sigma = 1). The axis has no flux.
 *
 * Limit (tests/models/test_pipe_kseps_solid.c): tracer particles of the fluid's density (rho_s = rho_f, mu_sl =
 * c_s mu_f, d_p -> 0: u_s = u_f, c_s uniform) make the pair, and the solids' momentum, the fluid's times c_s/c_f
 * with the same wall values, so k_s = k and eps_s = eps. Both start from the fluid's k, eps at the first
 * call. The fully developed pipe only: the developing pipe has no solids k_s-eps_s (pipe.c says so). */
#include <math.h>

#include "core/models/pipe/pipe_impl.h"

/* the least solids fraction the pair is weighted with (a cell the radial balance empties keeps its rows) */
#define KSEPS_PHI_FLOOR 1e-6

/* The solids' eddy viscosity c_s mu_st = C_mu rho_s c_s k_s^2/eps_s plus the constant solids viscosity, into mu_s
   (pipe_solids.c: with solids_turbulence = k_epsilon in place of the zero-equation model's). */
void pipe_kseps_viscosity(pipe *p) {
  if (!p->kseps_started)
    for (int i = 0; i < p->n; ++i) p->ks[i] = p->k[i], p->eps_s[i] = p->eps[i];
  p->kseps_started = 1;
  for (int i = 0; i < p->n; ++i)
    p->mu_s[i] = p->phi[i] * p->c_mu * p->rho_s * p->ks[i] * p->ks[i] / p->eps_s[i] + p->sc->solid.viscosity;
}

int pipe_kseps_update(pipe *p, sl_diag *d) {
  const int n = p->n;
  if (!p->kseps_started) pipe_kseps_viscosity(p);
  /* scratch: buf[0..7] and [14..17] (the steady solve keeps [8..13]) */
  double *mu = p->buf[0], *mk = p->buf[1], *me = p->buf[2], *ep = p->buf[3], *es = p->buf[4], *rho = p->buf[5];
  double *cap = p->buf[6], *kd = p->buf[7], *src = p->buf[14], *snk = p->buf[15], *P = p->buf[16], *x = p->buf[17];
  for (int i = 0; i < n; ++i) rho[i] = p->rho_s;
  const double *v[PQ_N] = {0};
  v[PQ_K] = p->ks, v[PQ_EPS] = p->eps_s, v[PQ_RHO_F] = rho;
  sl_point_request rq[5] = {{"mu_t", mu, NULL, NULL},
                            {"mu_t_k", mk, NULL, NULL},
                            {"mu_t_eps", me, NULL, NULL},
                            {"eps_production", ep, NULL, NULL},
                            {"eps_sink", es, NULL, NULL}};
  int rc = sl_point_eval(&p->turb, n, v, rq, 5, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.turbulence] at the solids' k_s, eps_s");
  /* P_s from the face gradients of u_s (zero at the axis; the wall cell is held) */
  double *gw = cap, *ge = kd;
  pipe_face_gradients(p, p->us, NAN, gw, ge);
  for (int i = 0; i < n; ++i) P[i] = mu[i] * 0.5 * (gw[i] * gw[i] + ge[i] * ge[i]);
  const double a = p->cfg->pseudo_step, mul = p->sc->solid.viscosity;
  const double rw = p->iterations > 0 ? p->relax : 1.0; /* under-relaxed as the velocities */
  for (int pass = 0; pass < 2; ++pass) {
    const int is_k = pass == 0;
    for (int i = 0; i < n; ++i) {
      const double cs = fmax(p->phi[i], KSEPS_PHI_FLOOR);
      cap[i] = cs * p->rho_s * p->eps_s[i] / (a * p->ks[i]); /* dtau = pseudo_step k_s/eps_s */
      kd[i] = mul + cs * (is_k ? mk[i] : me[i]);
      src[i] = is_k ? cs * P[i] : cs * ep[i] * P[i];
      snk[i] = is_k ? cs * p->rho_s * p->eps_s[i] / p->ks[i] : cs * es[i];
    }
    p->dirichlet = is_k ? p->k_wall : p->eps_wall; /* the wall cell held at the log law's values */
    sl_cell_scalar_terms t = {.dt = 1.0, .cap = cap, .s_old = is_k ? p->ks : p->eps_s, .k = kd, .source = src,
                              .sink = snk, .boundary = pipe_hold_wall, .boundary_user = p};
    if ((rc = sl_cell_scalar_solve(&p->cs, &t, x, d)))
      return sl_diag_prefix(d, rc, is_k ? "pipe: the solids' k_s equation" : "pipe: the solids' eps_s equation");
    /* k_s first, with the eps_s of the step's start in its coefficients; eps_s with the k_s of the step's start */
    double *dst = is_k ? mu : x; /* mu is spent in P: it keeps the new k_s until eps_s is solved */
    for (int i = 0; i < n; ++i) {
      if (!isfinite(x[i]))
        return sl_diag_set(d, SL_EFAILED, "pipe: the solids' %s is not finite at r = %g", is_k ? "k_s" : "eps_s",
                           p->g.xc[i]);
      dst[i] = fmax(x[i], 1e-14);
    }
    if (!is_k)
      for (int i = 0; i < n; ++i) p->ks[i] += rw * (mu[i] - p->ks[i]), p->eps_s[i] += rw * (x[i] - p->eps_s[i]);
  }
  return 0;
}
