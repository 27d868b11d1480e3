/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The fluid's k-epsilon turbulence of the pipe model and its wall function
 * (pipe.h): the coefficients from [closure.turbulence], the wall cell from
 * [closure.wall_stress.fluid], and one pseudo-time step of each equation on
 * the shared cell-scalar solver (core/fv/cell_scalar.h):
 *   c_f rho (k - k*)/dtau = (1/r) d/dr(r c_f (mu + mu_t/sigma_k) dk/dr) + c_f P_k - c_f rho eps
 *   c_f rho (e - e*)/dtau = (1/r) d/dr(r c_f (mu + mu_t/sigma_e) de/dr) + c_f C_e1 (e/k) P_k - c_f C_e2 rho e^2/k
 * (Krampa 2009 eqs 4.82-4.83 without modulation), P_k = mu_t (du_f/dr)^2, the
 * destruction implicit in k and e with its coefficient lagged, the local
 * pseudo-step dtau = pseudo_step k/eps. The wall cell holds k = u_tau^2/sqrt(C_mu)
 * and eps = u_tau^3/(kappa y) (Krampa 2009 eqs 4.85-4.86). In the developing pipe the march's axial and radial
 * convection join both equations (pipe_march.c).
 *
 * `[closure.turbulence_modulation] model = simonin` adds the particles' modulation of Krampa's model C (eqs
 * 4.80-4.83, Simonin 1996): per unit volume, c_f rho_f Pi_kf = A (k_fs - 2 k) in the k equation and C_eps3 (eps/k)
 * times it in the epsilon equation, A and C_eps3 the closure's (Simonin's A: K the drag coefficient, c_s rho_s/t_p,
 * eq 4.58; here K stands for A). The drift parts, the slip times the drift velocity (eqs 4.80-4.81) and the drift
 * work A nu_t grad(c_f) . (u_f - u_s) (eq 4.82), vanish in the fully developed pipe (axial slip, radial
 * gradients); the developing pipe adds them (pipe_march_drift_work), with C_eps3 (eps/k) times them in epsilon. k_fs is Tchen's equilibrium 2 k eta/(1 + eta), eta = t_fs/t_p, with the crossing-trajectory
 * t_fs of eq 4.61 (as [closure.turbulent_dispersion] model = simonin, pipe_solids.c), where model C transports it (eq 5.23), so that
 * K (k_fs - 2k) = -2 K k/(1 + eta) <= 0: an attenuation, vanishing for fine particles (eta -> infinity). Both
 * terms enter as implicit sinks. With `[pipe] solids_turbulence = transported` k_fs is model C's transported one
 * (pipe_ksfs.c, eq 5.23): K k_fs enters as a source (and C_eps3 (eps/k) K k_fs in epsilon), 2 K k (2 C_eps3 K eps)
 * as the sinks, so that k_fs above 2 k feeds the fluid's turbulence. Printed as is, eq 4.80 carries a c_f on the 2 k and eq 4.83 a minus sign
 * before C_eps3; the dimensionally consistent form of Simonin's model (Elghobashi & Abou-Arab 1983's sign in
 * the epsilon equation: the same as in k) is used here. */
#include <math.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"

int pipe_turbulence_coefficients(pipe *p, sl_diag *d) {
  const double *v[PQ_N] = {0};
  v[PQ_K] = p->k, v[PQ_EPS] = p->eps;
  double *cmu = p->buf[0];
  sl_point_request rq[6] = {{"mu_t", p->mu_t, NULL, NULL},         {"mu_t_k", p->mu_tk, NULL, NULL},
                            {"mu_t_eps", p->mu_te, NULL, NULL},    {"eps_production", p->eps_prod, NULL, NULL},
                            {"eps_sink", p->eps_sink, NULL, NULL}, {"c_mu", cmu, NULL, NULL}};
  int rc = sl_point_eval(&p->turb, p->n, v, rq, 6, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.turbulence]");
  p->c_mu = cmu[0];
  return 0;
}

int pipe_wall_function(pipe *p, sl_diag *d) {
  const int w = p->n - 1;
  double U = fabs(p->uf[w]), tau, dtau, ut, yp, kw, ew;
  const double *v[PQ_N] = {0};
  v[PQ_SLIP_WALL] = &U;
  sl_point_request rq[5] = {{"tau_w", &tau, &dtau, "slip_wall"},
                            {"u_tau", &ut, NULL, NULL},
                            {"y_plus", &yp, NULL, NULL},
                            {"k_wall", &kw, NULL, NULL},
                            {"epsilon_wall", &ew, NULL, NULL}};
  int rc = sl_point_eval(&p->wallf, 1, v, rq, 5, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.wall_stress.fluid]");
  p->tau_fw = (p->uf[w] >= 0.0 ? 1.0 : -1.0) * tau;
  p->u_tau = ut, p->y_plus = yp, p->k_wall = kw, p->eps_wall = ew;
  p->a_fw = U > 0.0 ? tau / U : dtau; /* tau_w = a u_p: the wall's coefficient in the momentum row */
  return 0;
}

/* The wall cell holds p->dirichlet: a diagonal that swamps the row (pipe_impl.h). */
int pipe_hold_wall(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  (void)d;
  pipe *p = user;
  if (c != p->n - 1) return 0;
  double big = 1e12 * (*diag + 1.0);
  *diag += big, *rhs += big * p->dirichlet;
  return 0;
}

/* [closure.turbulence_modulation]'s exchange coefficient A (Simonin: the drag's K) and C_eps3 in every cell. */
static int modulation_coefficients(pipe *p, double *A, double *c3, sl_diag *d) {
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = p->phi, v[PQ_K] = p->k, v[PQ_EPS] = p->eps, v[PQ_DRAG] = p->K;
  sl_point_request rq[2] = {{"exchange", A, NULL, NULL}, {"c_eps3", c3, NULL, NULL}};
  int rc = sl_point_eval(&p->modu, p->n, v, rq, 2, d);
  return rc ? sl_diag_prefix(d, rc, "[closure.turbulence_modulation]") : 0;
}

int pipe_turbulence_update(pipe *p, sl_diag *d) {
  const int n = p->n;
  double *P = p->buf[0], *cap = p->buf[1], *kd = p->buf[2], *src = p->buf[3], *snk = p->buf[4], *s = p->buf[5];
  /* P_k from the face gradients of u_f (zero at the axis; the wall cell is held) */
  double *gw = p->buf[14], *ge = p->buf[15];
  pipe_face_gradients(p, p->uf, NAN, gw, ge);
  for (int i = 0; i < n; ++i) P[i] = p->mu_t[i] * 0.5 * (gw[i] * gw[i] + ge[i] * ge[i]);
  const double a = p->cfg->pseudo_step;
  sl_cell_scalar_terms t = {
      .dt = 1.0, .cap = cap, .k = kd, .source = src, .sink = snk, .boundary = pipe_hold_wall, .boundary_user = p};
  /* the modulation K (k_fs - 2k): with Tchen's k_fs the sink 2 K/(1 + eta) of k (0 without); with the transported
     k_fs (pipe_ksfs.c) the sink 2 K and the source K k_fs (modk) */
  double *mod = p->buf[6], *modk = p->buf[16], *A = p->buf[7], *c3 = p->buf[17];
  const int transported = p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED;
  const int modulated = p->two_phase && p->have_modu;
  int rc = modulated ? modulation_coefficients(p, A, c3, d) : 0;
  if (rc) return rc;
  /* the developing pipe's drift work W (pipe_march.c; zero in the fully developed pipe), its part of either sign
     into the source and the implicit sink, which the epsilon equation takes times C_eps3 (eps/k) as the rest */
  double *W = p->buf[1], *Dt = p->buf[2];
  const int drift = modulated && p->march.on;
  if (drift && (rc = pipe_turbulent_dispersivity(p, Dt, d))) return rc;
  if (drift) pipe_march_drift_work(p, A, Dt, W);
  for (int i = 0; i < n; ++i) {
    mod[i] = 0.0, modk[i] = 0.0;
    if (!modulated) c3[i] = 0.0;
    if (!modulated || !(p->K[i] > 0.0)) continue;
    if (transported) {
      mod[i] = 2.0 * A[i], modk[i] = A[i] * p->kfs[i];
      continue;
    }
    double tp = fmax(p->phi[i], 1e-12) * p->rho_s / p->K[i];
    mod[i] = 2.0 * A[i] / (1.0 + pipe_tfs(p, i) / tp);
  }
  for (int i = 0; i < n && drift; ++i) {
    if (W[i] > 0.0) modk[i] += W[i];
    else mod[i] -= W[i] / p->k[i];
  }
  /* k */
  for (int i = 0; i < n; ++i) {
    double cf = 1.0 - p->phi[i];
    cap[i] = cf * p->rho_f * p->eps[i] / (a * p->k[i]);
    kd[i] = cf * (p->mu_f + p->mu_tk[i]);
    src[i] = cf * P[i] + modk[i];
    snk[i] = cf * p->rho_f * p->eps[i] / p->k[i] + mod[i];
  }
  t.s_old = p->k, p->dirichlet = p->k_wall;
  if (p->march.on) { /* the developing pipe's convection (pipe_march.c) */
    pipe_march_scalar(p, cap, p->k, p->march.k_up);
    t.cap = p->march.cap, t.s_old = p->march.s_old, t.flux = p->march.rff;
  }
  rc = sl_cell_scalar_solve(&p->cs, &t, s, d);
  if (rc) return sl_diag_prefix(d, rc, "pipe: the k equation");
  /* epsilon, with the k of the step's start in its coefficients */
  for (int i = 0; i < n; ++i) {
    double cf = 1.0 - p->phi[i];
    kd[i] = cf * (p->mu_f + p->mu_te[i]);
    src[i] = cf * p->eps_prod[i] * P[i] + c3[i] * modk[i] * p->eps[i] / p->k[i];
    snk[i] = cf * p->eps_sink[i] + c3[i] * mod[i];
  }
  t.s_old = p->eps, p->dirichlet = p->eps_wall;
  if (p->march.on) {
    pipe_march_scalar(p, cap, p->eps, p->march.eps_up);
    t.s_old = p->march.s_old;
  }
  double *e = P; /* P is in src already */
  rc = sl_cell_scalar_solve(&p->cs, &t, e, d);
  if (rc) return sl_diag_prefix(d, rc, "pipe: the epsilon equation");
  for (int i = 0; i < n; ++i) {
    p->k[i] = fmax(s[i], 1e-14);
    p->eps[i] = fmax(e[i], 1e-14);
  }
  return 0;
}
