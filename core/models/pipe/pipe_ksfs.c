/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Krampa's (2009) model C's solids turbulence (pipe.h, `[pipe] solids_turbulence = transported`): the solids'
 * turbulent kinetic energy k_s = <u_s'.u_s'>/2 and the fluid-particle covariance k_fs = <u_f'.u_s'> from their
 * transport equations, Krampa's eqs 5.20 and 5.23 in the form of Simonin (1996, VKI LS 1996-02) and Peirano &
 * Leckner (1998, Prog. Energy Combust. Sci. 24:259; their q_p^2 and q_fp), fully developed (no convection), per
 * unit volume, m = c_s rho_s:
 *
 *   0 = (1/r) d/dr(r m (K_st + K_sc) dk_s/dr) + m nu_s (du_s/dr)^2 - K (2 k_s - k_fs) - m (1 - e^2)/(3 t_c) k_s  (5.20)
 *   0 = (1/r) d/dr(r m (nu_fs/sigma) dk_fs/dr) + 2 m nu_fs (du_f/dr)(du_s/dr)
 *       - K [(1 + S) k_fs - 2 k - 2 S k_s] - m k_fs/t_fs                                                    (5.23)
 *
 * K = m/t_p the drag coefficient (eq 4.58), S = c_s rho_s/(c_f rho_f), t_fs the crossing-trajectory interaction
 * time (eq 4.61), t_c the collision time (eq 5.19), nu_s = nu_st + nu_sc Peirano & Leckner's viscosity (eqs
 * 5.15-5.19, pipe_peirano.c), K_st and K_sc their diffusivities (eqs 5.21-5.22), nu_fs = k_fs t_fs/3 (5.23's
 * mu_kfs/rho_s), sigma = [pipe] covariance_schmidt (Krampa gives none). Corrections to the text as printed:
 *  - 5.20's drag term: Krampa prints (2 m/t_fs)(2 k_s - k_fs); Peirano & Leckner and Simonin have (m/t_p)(2 k_s -
 *    k_fs) = K (2 k_s - k_fs) (digest section 2.6: t_p, not t_fs; and the factor 1: the drag's power into the
 *    solids' fluctuations is K <u_s'.(u_f' - u_s')> = K (k_fs - 2 k_s), so that the fluid's and the solids'
 *    exchanges, K (k_fs - 2 k) of eq 4.80 and this, add to the dissipation -K <|u_f' - u_s'|^2> <= 0; with the
 *    factor 2 they could create energy);
 *  - 5.20's diffusion lacks rho_s (K_st, K_sc are kinematic; the left side is c_s rho_s U k_s);
 *  - 5.20's production -T_s:grad U_s has the printed sign of eq 5.10 (digest erratum 7): with T_s the effective
 *    solids stress of eq 1.5 (+mu_s (grad U + grad U^T)) the production is +T_s:grad U_s = mu_s (du_s/dr)^2 here;
 *  - 5.24 with its trace (digest): -rho_s <u_fi' u_sj'> = rho_s nu_fs (dU_fi/dx_j + dU_sj/dx_i) - (1/3) rho_s k_fs
 *    delta_ij, so that in the pipe (z along, r across; the traces vanish) <u_fz' u_sr'> = -nu_fs du_f/dr and
 *    <u_fr' u_sz'> = -nu_fs du_s/dr, and the two production terms of 5.23 are each m nu_fs (du_f/dr)(du_s/dr).
 * Limits: without gradients and collisions (e = 1) the pair is Tchen's equilibrium for heavy particles, k_s =
 * k_fs/2, k_fs = 2 k t_fs/(t_fs + t_p) (S cancels), what solids_turbulence = equilibrium takes (pipe_peirano.c);
 * with collisions k_s falls below k_fs/2. Fine particles (t_p -> 0) follow the fluid: k_fs -> 2k, and 5.23's
 * production -> 2 nu_t (du/dr)^2, twice the fluid's P_k (tests/models/test_pipe_ksfs.c).
 *
 * Walls: the axis has no flux; at the wall k_fs has none (Krampa gives no condition), k_s none either unless the
 * solids' wall closure gives a theta_flux (Johnson & Jackson 1987, Krampa eq 4.93, his model C's wall), taken at
 * theta = (2/3) k_s (the isotropic relation his section 5.1.3 assumes; digest erratum 12). The granular
 * temperature field theta is (2/3) k_s, which the solids' wall closures see.
 *
 * Numerics: both on the shared cell scalar (core/fv/cell_scalar.h), steady, the coefficients (nu_s, K_st, K_sc,
 * nu_fs, t_c, t_fs, K) of the iterate; the collisional dissipation Newton-linearised and bounded as the granular
 * temperature's (core/models/granular.h: sl_theta_local, sl_theta_bounded); the drag's coupling of the pair by
 * Gauss-Seidel sweeps within an iteration; under-relaxed as the velocities. In the developing pipe both gain the
 * solids' axial and radial convection of m k (pipe_march.c). */
#include <math.h>
#include <string.h>

#include "core/models/granular.h"
#include "core/models/pipe/pipe_impl.h"

/* The eddy-particle interaction time with the crossing-trajectory effect (Krampa 2009 eq 4.61; Csanady 1963):
   t_fs = C_mu (3k/(2 eps)) [1 + C_beta 3 |u_f - u_s|^2/(2k)]^(-1/2). */
double pipe_tfs(const pipe *p, int i) {
  double k = p->k[i], s2 = (p->uf[i] - p->us[i]) * (p->uf[i] - p->us[i]);
  return p->c_mu * 1.5 * k / p->eps[i] / sqrt(1.0 + p->cfg->crossing_trajectory * 1.5 * s2 / k);
}

/* Tchen's equilibrium for heavy particles (Simonin 1996): k_fs = 2 k eta/(1 + eta), k_s = k_fs/2, eta = t_fs/t_p. */
void pipe_ksfs_equilibrium(const pipe *p, int i, double *ks, double *kfs) {
  double tp = p->phi[i] * p->rho_s / p->K[i], eta = pipe_tfs(p, i) / tp;
  *kfs = isinf(eta) ? 2.0 * p->k[i] : 2.0 * p->k[i] * eta / (1.0 + eta), *ks = 0.5 * *kfs; /* t_p = 0: tracers */
}

double pipe_kfs(const pipe *p, int i) {
  if (p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED) return p->kfs[i];
  double ks, kfs;
  pipe_ksfs_equilibrium(p, i, &ks, &kfs);
  return kfs;
}

/* The point of Peirano & Leckner's closures at cell i (pipe_peirano.c): the transported k_s and k_fs, or none. */
pipe_pl_point pipe_pl_point_at(const pipe *p, int i) {
  double s = p->uf[i] - p->us[i];
  const int tr = p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED;
  return (pipe_pl_point){.phi = p->phi[i],
                         .k = p->k[i],
                         .eps = p->eps[i],
                         .slip2 = s * s,
                         .K = p->K[i],
                         .rho_s = p->rho_s,
                         .d_p = p->d_p,
                         .phi_max = p->phi_max,
                         .restitution = p->cfg->restitution,
                         .c_mu = p->c_mu,
                         .c_beta = p->cfg->crossing_trajectory,
                         .given = tr,
                         .ks = tr ? p->ks[i] : 0.0,
                         .kfs = tr ? p->kfs[i] : 0.0};
}

static void set_theta(pipe *p) {
  for (int i = 0; i < p->n; ++i) p->theta[i] = fmax(2.0 * p->ks[i] / 3.0, SL_THETA_FLOOR);
}

void pipe_ksfs_start(pipe *p) {
  for (int i = 0; i < p->n; ++i) pipe_ksfs_equilibrium(p, i, &p->ks[i], &p->kfs[i]);
  set_theta(p);
  p->ksfs_started = 1;
}

/* The wall's energy flux into k_s (the solids' wall closure's theta_flux at theta = (2/3) k_s): with q(theta) ~ q
   - c (theta - theta_it) and theta = (2/3) k_s, the row gains A (q + (2/3) c k_s,it) and A (2/3) c. */
static int ks_wall(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  pipe *p = user;
  if (c != p->n - 1 || !p->ks_wall_energy) return 0;
  double q, ci, ks = fmax(p->ks[c], SL_THETA_FLOOR);
  int rc = pipe_theta_wall_flux(p, 2.0 * ks / 3.0, &q, &ci, d);
  if (rc) return rc;
  sl_theta_wall_row(p->g.area[p->n], q, 2.0 * ci / 3.0, ks, rhs, diag);
  return 0;
}

/* One steady solve of k_s or k_fs (s_iter the iterate), with the developing pipe's convection (pipe_march.c:
   s_up the last station's). */
static int solve(pipe *p, sl_cell_scalar_terms *t, const double *s_iter, const double *s_up, double *out, sl_diag *d) {
  t->dt = 1e30, t->s_old = s_iter;
  if (p->march.on) {
    pipe_march_ksfs(p, s_iter, s_up);
    t->dt = 1.0, t->cap = p->march.cap, t->s_old = p->march.s_old, t->flux = p->march.rs;
  }
  return sl_cell_scalar_solve(&p->cs, t, out, d);
}

int pipe_ksfs_update(pipe *p, sl_diag *d) {
  const int n = p->n;
  const double e = p->cfg->restitution, sigma = p->cfg->covariance_schmidt;
  /* scratch: buf[0..7] and [14..17] (the steady solve keeps [8..13]) */
  double *gfw = p->buf[0], *gfe = p->buf[1], *gsw = p->buf[2], *gse = p->buf[3];
  double *cap = p->buf[4], *src = p->buf[5], *snk = p->buf[6], *x = p->buf[7];
  double *dks = p->buf[14], *dfs = p->buf[15], *afs = p->buf[16], *ms = p->buf[17];
  pipe_face_gradients(p, p->uf, NAN, gfw, gfe);
  pipe_face_gradients(p, p->us, -p->a_sw * p->us[n - 1] / fmax(p->mu_s[n - 1], 1e-300), gsw, gse);
  /* the pointwise coefficients of the iterate; the k_s equation's production and collisional dissipation
     (Newton) into src, snk; the k_fs equation's production per unit k_fs into afs */
  for (int i = 0; i < n; ++i) {
    pipe_pl_point q = pipe_pl_point_at(p, i);
    const double m = p->rho_s * fmax(p->phi[i], 1e-6), tfs = pipe_tfs(p, i), K = p->K[i];
    const double nu_s = pipe_peirano_leckner(&q, NULL), inv_tc = pipe_peirano_leckner_collision_rate(&q);
    dks[i] = m * pipe_peirano_leckner_diffusivity(&q, NULL);
    dfs[i] = m * fmax(p->kfs[i], 0.0) * tfs / (3.0 * sigma);
    afs[i] = (2.0 / 3.0) * m * tfs * 0.5 * (gfw[i] * gsw[i] + gfe[i] * gse[i]);
    ms[i] = m;
    const double P = m * nu_s * 0.5 * (gsw[i] * gsw[i] + gse[i] * gse[i]);
    /* m (1 - e^2)/(3 t_c) k_s, 1/t_c ~ sqrt(k_s): d/dk_s = 1.5 times it over k_s */
    const double ks = fmax(p->ks[i], SL_THETA_FLOOR), gam = m * (1.0 - e * e) / 3.0 * inv_tc * ks;
    sl_theta_local(p->rho_s, p->phi[i], P, gam, 1.5 * gam / ks, 2.0 * K, ks, &cap[i], &src[i], &snk[i]);
    cap[i] = m;
  }
  /* the face gradients are spent once afs and P are formed: their arrays take the sweeps' */
  double *s_new = x, *f_new = gfw, *srcf = gfe, *snkf = gsw, *srcs = gse;
  memcpy(s_new, p->ks, (size_t)n * sizeof(double)), memcpy(f_new, p->kfs, (size_t)n * sizeof(double));
  int rc = 0;
  /* the drag couples the pair (K k_fs in k_s's, 2 K S k_s in k_fs's): Gauss-Seidel sweeps, each k_s then k_fs */
  for (int sweep = 0; sweep < 3 && !rc; ++sweep) {
    for (int i = 0; i < n; ++i) srcs[i] = src[i] + p->K[i] * fmax(f_new[i], 0.0);
    sl_cell_scalar_terms t = {.cap = cap,
                              .k = dks,
                              .source = srcs,
                              .sink = snk,
                              .boundary = p->ks_wall_energy ? ks_wall : NULL,
                              .boundary_user = p};
    if ((rc = solve(p, &t, p->ks, p->march.ks_up, s_new, d))) return sl_diag_prefix(d, rc, "pipe: the k_s equation");
    for (int i = 0; i < n; ++i) {
      const double K = p->K[i], S = ms[i] / ((1.0 - p->phi[i]) * p->rho_f), tfs = pipe_tfs(p, i);
      srcf[i] = K * (2.0 * p->k[i] + 2.0 * S * fmax(s_new[i], 0.0)) + fmax(afs[i], 0.0) * fmax(p->kfs[i], 0.0);
      snkf[i] = K * (1.0 + S) + ms[i] / tfs + fmax(-afs[i], 0.0);
    }
    t = (sl_cell_scalar_terms){.cap = cap, .k = dfs, .source = srcf, .sink = snkf};
    if ((rc = solve(p, &t, p->kfs, p->march.kfs_up, f_new, d))) return sl_diag_prefix(d, rc, "pipe: the k_fs equation");
  }
  const double w = p->iterations > 0 ? p->relax : 1.0; /* under-relaxed as the velocities */
  for (int i = 0; i < n; ++i) {
    if (!isfinite(s_new[i]) || !isfinite(f_new[i]))
      return sl_diag_set(d, SL_EFAILED, "pipe: k_s or k_fs is not finite at r = %g", p->g.xc[i]);
    double a = sl_theta_bounded(s_new[i], p->ks[i]), b = sl_theta_bounded(f_new[i], p->kfs[i]);
    p->ks[i] = fmax(p->ks[i] + w * (a - p->ks[i]), SL_THETA_FLOOR);
    p->kfs[i] = fmax(p->kfs[i] + w * (b - p->kfs[i]), SL_THETA_FLOOR);
  }
  set_theta(p);
  return 0;
}
