/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The Ergun and Wen-Yu laws with their derivatives, shared by the closures
 * that use them alone (ergun, wen_yu) or switched (gidaspow, pringle), so each
 * law is written once. Header-only, libm only. K follows F_s = K (u_f - u_s).
 * d is the effective diameter (sphericity x d_p), eps = 1 - phi. */
#ifndef SLUICE_PLUGINS_DENSE_DRAG_LAWS_H
#define SLUICE_PLUGINS_DENSE_DRAG_LAWS_H

#include <math.h>

#include "sphere_drag.h" /* beside this file: also found from bench/ */

/* K and its derivatives with respect to phi and the slip speed. */
typedef struct sl_drag_value {
  double K, K_phi, K_slip;
} sl_drag_value;

/* The validity ranges of the Ergun closure's inputs (ergun.c declares the
 * same ones), written as negated ranges so that NaN inputs fail too. */
static inline int sl_ergun_inputs_ok(double phi, double slip, double rho, double mu, double dp, double psi) {
  return (phi >= 0.0 && phi <= 0.74) && (slip >= 0.0 && slip < HUGE_VAL) && (rho >= 1e-3 && rho <= 1e5) &&
         (mu >= 1e-7 && mu <= 1e5) && (dp >= 1e-8 && dp <= 1.0) && (psi >= 0.01 && psi <= 1.0);
}

/* Ergun (1952) as K (Gidaspow 1994 eq 5.62; Pringle 2001 eq 3.12):
 *   K = c_visc phi^2 mu / (eps d^2) + c_iner g(phi) rho |slip| / d
 * with g = phi (Gidaspow's substitution) or phi/eps (Pringle's printed eq
 * 3.12, inertial_over_eps). Two divisions: the rest are reciprocal products. */
static inline sl_drag_value sl_ergun_law(double phi, double slip, double rho, double mu, double d, double c_visc,
                                         double c_iner, int inertial_over_eps) {
  const double inv_d = 1.0 / d, inv_eps = 1.0 / (1.0 - phi);
  const double visc = c_visc * mu * inv_d * inv_d, iner = c_iner * rho * inv_d;
  const double g = inertial_over_eps ? phi * inv_eps : phi;
  const double dg = inertial_over_eps ? inv_eps * inv_eps : 1.0;
  sl_drag_value v;
  v.K = visc * phi * phi * inv_eps + iner * g * slip;
  v.K_phi = visc * phi * (2.0 - phi) * inv_eps * inv_eps + iner * dg * slip;
  v.K_slip = iner * g;
  return v;
}

/* Wen & Yu (1966) as written by Gidaspow (1994):
 *   K = (3/4) C_D(Re) phi eps rho |slip| eps^-m / d = 18 mu/d^2 phi eps^-m f(Re),
 * f = C_D Re / 24 of Schiller-Naumann, Re = eps rho |slip| d / mu
 * (fluid_fraction_re) or rho |slip| d / mu (interstitial). dK/dslip at
 * slip = 0 is reported as 0 (f' is infinite there; K(0) is the exact
 * Jacobian of the force K slip). */
static inline sl_drag_value sl_wen_yu_law(double phi, double slip, double rho, double mu, double d, double m,
                                          int fluid_fraction_re) {
  const double eps = 1.0 - phi;
  const double k1 = 18.0 * mu / (d * d);
  const double hind = pow(eps, -m);
  double re_df;
  const double re = (fluid_fraction_re ? eps : 1.0) * rho * slip * d / mu;
  const double f = sl_sn_factor(re, &re_df);
  const double df_dphi = fluid_fraction_re ? -re_df / eps : 0.0; /* dRe/dphi = -Re/eps */
  sl_drag_value v;
  v.K = k1 * phi * hind * f;
  v.K_phi = k1 * hind * (f + phi * (m * f / eps + df_dphi));
  v.K_slip = slip > 0.0 ? k1 * phi * hind * re_df / slip : 0.0;
  return v;
}

#endif
