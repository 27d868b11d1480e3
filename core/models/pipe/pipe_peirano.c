/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Krampa's (2009) model C solids viscosity (pipe.h, `[pipe] solids_viscosity = peirano_leckner`): the kinetic and
 * collisional viscosity of Peirano & Leckner (1998, Prog. Energy Combust. Sci. 24:259), Krampa's eqs 5.15-5.19,
 * kinematic (the digest's note on eq 5.16: its nu_st, not mu_st, inside the collisional bracket):
 *   nu_s  = nu_st + nu_sc                                                                   (5.15)
 *   nu_sc = (8/5) c_s g0 eta (nu_st + d_p sqrt(2 k_s/(3 pi))),  eta = (1 + e)/2                 (5.16)
 *   nu_st = (2/3) [(t_fs/t_p) k_fs + (1 + c_s g0 A) k_s] [2/t_p + B/t_c]^-1                   (5.17)
 *   A = (2/5)(1 + e)(3e - 1),  B = (1/5)(1 + e)(3 - e)                                        (5.18)
 *   t_c = sqrt(pi)/(24 c_s g0) d_p sqrt(3/(2 k_s))   (the collision time)                     (5.19)
 * with t_fs the eddy-particle interaction time with the crossing-trajectory effect (eq 4.61; Csanady 1963), t_p =
 * c_s rho_s/K (eq 4.58), g0 Lun & Savage's (1 - c_s/C_max)^(-2.5 C_max) (eq 4.91). Model C transports k_s and k_fs
 * (eqs 5.20, 5.23); here both are Tchen's equilibrium for heavy particles, k_fs = 2 k eta_r/(1 + eta_r) and k_s =
 * k eta_r/(1 + eta_r), eta_r = t_fs/t_p (Simonin 1996; the same k_fs as the modulation and dispersion closures'
 * model = simonin), so that the model's solids side is algebraic in k, epsilon and the drag. This pair is what eqs 5.20
 * and 5.23 give without their production, diffusion and collisional terms: 5.20's interaction makes k_s = k_fs/2,
 * and 5.23's, (1/t_p)[(1 + S) k_fs - 2 k - 2 S k_s] + k_fs/t_fs = 0, then k_fs = 2 k t_fs/(t_fs + t_p). Limits (tests/models/
 * test_pipe_peirano.c): fine particles (t_p -> 0) follow the fluid, nu_st -> (2/3) t_fs k = C_mu k^2/eps at zero
 * slip; without collisions (c_s -> 0) nu_s -> (1/3)(t_fs k_fs + t_p k_s), Simonin's dilute form. Written with
 * t_p in the numerator, (2/3)[t_fs k_fs + t_p (1 + c_s g0 A) k_s]/[2 + B t_p/t_c], finite at t_p = 0. With
 * `[pipe] solids_turbulence = transported` the point's k_s and k_fs are the transported ones (pipe_ksfs.c). */
#include <math.h>

#include "core/models/pipe/pipe_impl.h"

/* The point's times and k_s, k_fs: t_fs (eq 4.61), t_p = c_s rho_s/K (eq 4.58), g0 (eq 4.91), 1/t_c (eq 5.19), and
   the given k_s, k_fs (transported) or Tchen's equilibrium. */
typedef struct pl_state {
  double cs, k, e, tfs, tp, ks, kfs, g0, inv_tc;
} pl_state;

static pl_state pl_state_of(const pipe_pl_point *q) {
  const double pi = 3.14159265358979323846;
  pl_state s;
  s.cs = fmin(fmax(q->phi, 0.0), q->phi_max - 0.01), s.k = fmax(q->k, 0.0), s.e = q->restitution;
  s.tfs = q->c_mu * 1.5 * s.k / q->eps / sqrt(1.0 + q->c_beta * 1.5 * q->slip2 / fmax(s.k, 1e-300));
  s.tp = q->K > 0.0 ? s.cs * q->rho_s / q->K : 0.0;
  if (q->given) {
    s.ks = fmax(q->ks, 0.0), s.kfs = fmax(q->kfs, 0.0);
  } else {
    const double er = s.tp > 0.0 ? s.tfs / s.tp : INFINITY;
    const double f = isinf(er) ? 1.0 : er / (1.0 + er);
    s.kfs = 2.0 * s.k * f, s.ks = s.k * f;
  }
  s.g0 = pow(1.0 - s.cs / q->phi_max, -2.5 * q->phi_max);
  s.inv_tc = 24.0 * s.cs * s.g0 * sqrt(2.0 * s.ks / 3.0) / (sqrt(pi) * q->d_p); /* 1/t_c of eq 5.19 */
  return s;
}

double pipe_peirano_leckner(const pipe_pl_point *q, double *nu_st) {
  const double pi = 3.14159265358979323846;
  const pl_state s = pl_state_of(q);
  const double cs = s.cs, e = s.e, g0 = s.g0, tp = s.tp, ks = s.ks;
  const double A = 0.4 * (1.0 + e) * (3.0 * e - 1.0), B = 0.2 * (1.0 + e) * (3.0 - e), eta = 0.5 * (1.0 + e);
  const double st = (2.0 / 3.0) * (s.tfs * s.kfs + tp * (1.0 + cs * g0 * A) * ks) / (2.0 + B * tp * s.inv_tc);
  const double sc = 1.6 * cs * g0 * eta * (st + q->d_p * sqrt(2.0 * ks / (3.0 * pi)));
  if (nu_st) *nu_st = st;
  return st + sc;
}

/* The kinetic and collisional diffusivities of k_s (Krampa 2009 eqs 5.21-5.22; Peirano & Leckner 1998; Simonin
 * 1996's K_2^kin and K_2^coll), kinematic:
 *   K_st = [(3/5)(t_fs/t_p) k_fs + (2/3)(1 + c_s g0 C) k_s] [9/(5 t_p) + D/t_c]^-1                       (5.22)
 *   K_sc = c_s g0 (1 + e) ((6/5) K_st + (4/3) d_p sqrt(2 k_s/(3 pi)))                                     (5.21)
 *   C = 3 (1 + e)^2 (2e - 1)/5,  D = (1 + e)(49 - 33e)/100,
 * written with t_p in the numerator as the viscosity is, [(3/5) t_fs k_fs + (2/3) t_p (1 + c_s g0 C) k_s]/[9/5 +
 * D t_p/t_c]. Checks: the collisional part is the kinetic theory's conductivity (2/3) kappa_coll/(c_s rho_s) =
 * (4/3) c_s g0 (1 + e) d_p sqrt(theta/pi) at theta = 2 k_s/3 (Lun et al. 1984); fine particles (t_p -> 0) diffuse
 * as (3/5) t_fs k_fs / (9/5) = (1/3) t_fs k_fs, Simonin's nu_fs of the covariance (eq 5.23's mu_kfs/rho_s). */
double pipe_peirano_leckner_diffusivity(const pipe_pl_point *q, double *K_st) {
  const double pi = 3.14159265358979323846;
  const pl_state s = pl_state_of(q);
  const double cs = s.cs, e = s.e, g0 = s.g0, tp = s.tp, ks = s.ks;
  const double C = 0.6 * (1.0 + e) * (1.0 + e) * (2.0 * e - 1.0), D = (1.0 + e) * (49.0 - 33.0 * e) / 100.0;
  const double st = (0.6 * s.tfs * s.kfs + (2.0 / 3.0) * tp * (1.0 + cs * g0 * C) * ks) / (1.8 + D * tp * s.inv_tc);
  const double sc = cs * g0 * (1.0 + e) * (1.2 * st + (4.0 / 3.0) * q->d_p * sqrt(2.0 * ks / (3.0 * pi)));
  if (K_st) *K_st = st;
  return st + sc;
}

/* 1/t_c of eq 5.19 at the point (with its k_s). */
double pipe_peirano_leckner_collision_rate(const pipe_pl_point *q) { return pl_state_of(q).inv_tc; }
