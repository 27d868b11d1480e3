/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Shared pieces of the kinetic theory of granular flow (KTGF), used by the
 * granular closures (lun, gidaspow, algebraic_theta) and by the wall_stress
 * closures that need a radial distribution function (johnson_jackson,
 * navier_slip_ding_lyczkowski). Header-only: static inline functions, no
 * state, nothing exported; each closure library gets its own copy.
 *
 * 1. Radial distribution function at contact, g0(phi), with dg0/dphi:
 *      carnahan_starling  (1 - phi/2) / (1 - phi)^3               Carnahan & Starling (1969)
 *      lun_savage         (1 - phi/phi_max)^(-2.5 phi_max)         Lun & Savage (1986) Acta Mech 63:15; Krampa eq 4.91
 *      ma_ahmadi          (1 + 2.5 phi + 4.5904 phi^2 + 4.515439 phi^3)
 *                         / (1 - (phi/phi_max)^3)^0.67802          Ma & Ahmadi (1986) J Chem Phys 84:3449
 *      gidaspow           (3/5) / (1 - (phi/phi_max)^(1/3))         Gidaspow (1994) "Multiphase flow and
 *                                                                   fluidization", the CFX-10 form (Krampa 6.2)
 *      sinclair_jackson   1 / (1 - (phi/phi_max)^(1/3))             Bagnold (1954) / Ogawa et al. (1980) /
 *                                                                   Sinclair & Jackson (1989)
 *    The gidaspow form tends to 3/5, not 1, as phi -> 0 (a known property of
 *    that fit); sinclair_jackson is the same law without the 3/5 and tends to 1.
 *
 *    Near packing every form is replaced by its tangent line beyond
 *    phi_c = phi_max - delta:
 *      g0(phi) = g0(phi_c) + g0'(phi_c) (phi - phi_c),   phi > phi_c,
 *    so g0 is C1 (value and slope match at phi_c), finite and increasing for
 *    all phi, including phi >= phi_max (over-packed states the solver must be
 *    able to recover from). CFX-10 uses a cubic Taylor polynomial above
 *    phi_max - 0.001 instead (Krampa 2009 eq 6.2); the linear form is the
 *    minimal C1 choice and never turns over.
 *
 *    The two (phi/phi_max)^(1/3) forms have an infinite slope at phi = 0. Below
 *    phi_floor = 1e-12 they are replaced by their tangent line at phi_floor,
 *    which keeps dg0/dphi finite at phi = 0 and changes g0(0) by 8e-5
 *    relative (g0(0) = c (1 + 7.8e-5) with c = 3/5 or 1).
 *
 * 2. Kinetic-theory transport coefficients, written as ("shape" functions of
 *    phi and g0) x (dimensional scale). With eta = (1 + e)/2, X = phi g0:
 *    solids pressure (both)   p_s      = rho_s phi theta (1 + 2 (1+e) phi g0)
 *    bulk viscosity (both)    lambda_s = (4/3) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)
 *    dissipation (both)       gamma    = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi))
 *    shear viscosity, Gidaspow (1994):
 *      mu_s = rho_s d_p sqrt(theta) [ (4/5)(1+e) phi^2 g0 / sqrt(pi)
 *                                   + (10 sqrt(pi)/96) (1 + (4/5)(1+e) X)^2 / ((1+e) g0) ]
 *    conductivity, Gidaspow (1994):
 *      kappa = rho_s d_p sqrt(theta) [ 2 (1+e) phi^2 g0 / sqrt(pi)
 *                                    + (150 sqrt(pi)/384) (1 + (6/5)(1+e) X)^2 / ((1+e) g0) ]
 *    shear viscosity, Lun et al. (1984):
 *      mu_s = (5 sqrt(pi)/96) rho_s d_p sqrt(theta)
 *             [ (1 + (8/5) eta X)(1 + (8/5) eta (3 eta - 2) X) / (eta (2 - eta) g0)
 *               + (768/(25 pi)) eta phi^2 g0 ]
 *    conductivity, Lun et al. (1984):
 *      kappa = 75 sqrt(pi) rho_s d_p sqrt(theta) / (48 eta (41 - 33 eta))
 *              [ (1 + (12/5) eta X)(1 + (12/5) eta^2 (4 eta - 3) X) / g0
 *                + (64/(25 pi)) (41 - 33 eta) eta^2 phi^2 g0 ]
 *    All coefficients are the phase totals that enter the solids stress
 *      sigma_s = -p_s I + lambda_s (div u_s) I + 2 mu_s (D_s - (1/3)(div u_s) I)
 *    (not to be multiplied by phi again), and the granular-energy flux
 *    q = -kappa grad theta. Krampa (2009) prints several of these with
 *    misprints: (5.8) lacks phi^2, (5.14) lacks
 *    phi theta^0.5, (5.13) has g0 where phi belongs; the forms above are the
 *    corrected ones (cross-checked against MFiX's Lun et al. coefficients,
 *    eqs B8-B10 of the MFiX 2012 theory guide, and Gidaspow's book). */
#ifndef SLUICE_PLUGINS_GRANULAR_KINETIC_H
#define SLUICE_PLUGINS_GRANULAR_KINETIC_H

#include <math.h>

enum {
  KT_G0_CARNAHAN_STARLING = 0,
  KT_G0_LUN_SAVAGE = 1,
  KT_G0_MA_AHMADI = 2,
  KT_G0_GIDASPOW = 3,
  KT_G0_SINCLAIR_JACKSON = 4
};
#define KT_G0_CHOICES "carnahan_starling|lun_savage|ma_ahmadi|gidaspow|sinclair_jackson"
#define KT_G0_HELP                                                                                    \
  "radial distribution g0: carnahan_starling, lun_savage (1-phi/phi_max)^(-2.5 phi_max), ma_ahmadi, " \
  "gidaspow 0.6/(1-(phi/phi_max)^(1/3)), sinclair_jackson 1/(1-(phi/phi_max)^(1/3))"

#define KT_SQRT_PI 1.7724538509055160273
#define KT_PI 3.14159265358979323846
#define KT_PHI_FLOOR 1e-12

/* g0 and dg0/dphi of the uncontinued law, for 0 <= phi <= phi_c < phi_max. */
static inline double kt_g0_raw(int model, double phi, double phi_max, double *dg) {
  switch (model) {
    case KT_G0_CARNAHAN_STARLING: {
      double n = 1.0 - phi, n3 = n * n * n;
      *dg = (2.5 - phi) / (n3 * n);
      return (1.0 - 0.5 * phi) / n3;
    }
    case KT_G0_LUN_SAVAGE: {
      double r = 1.0 - phi / phi_max;
      double g = pow(r, -2.5 * phi_max);
      *dg = 2.5 * g / r;
      return g;
    }
    case KT_G0_MA_AHMADI: {
      double num = 1.0 + phi * (2.5 + phi * (4.5904 + phi * 4.515439));
      double dnum = 2.5 + phi * (9.1808 + phi * 13.546317);
      double y = phi / phi_max, s = 1.0 - y * y * y;
      double g = num / pow(s, 0.67802);
      *dg = g * (dnum / num + 0.67802 * 3.0 * y * y / (phi_max * s));
      return g;
    }
    default: { /* gidaspow (c = 3/5) and sinclair_jackson (c = 1) */
      double c = model == KT_G0_GIDASPOW ? 0.6 : 1.0;
      if (phi < KT_PHI_FLOOR) { /* tangent line at the floor: finite slope at phi = 0 */
        double xf = cbrt(KT_PHI_FLOOR / phi_max), of = 1.0 - xf;
        double slope = c * xf / (3.0 * KT_PHI_FLOOR * of * of);
        *dg = slope;
        return c / of + slope * (phi - KT_PHI_FLOOR);
      }
      double x = cbrt(phi / phi_max), o = 1.0 - x;
      *dg = c * x / (3.0 * phi * o * o);
      return c / o;
    }
  }
}

/* g0 with the C1 linear continuation above phi_c = phi_max - delta. */
static inline double kt_g0(int model, double phi, double phi_max, double delta, double *dg) {
  double phi_c = phi_max - delta;
  if (phi <= phi_c) return kt_g0_raw(model, phi, phi_max, dg);
  double slope, g_c = kt_g0_raw(model, phi_c, phi_max, &slope);
  *dg = slope;
  return g_c + slope * (phi - phi_c);
}

/* A "pair" shape (1 + a X)(1 + b X) / g with X = phi g, and its partial
 * derivatives at fixed g and at fixed phi. */
static inline double kt_pair(double a, double b, double phi, double g, double *d_phi, double *d_g) {
  double X = phi * g;
  *d_phi = a * (1.0 + b * X) + b * (1.0 + a * X);
  *d_g = (a * b * X * X - 1.0) / (g * g);
  return (1.0 + a * X) * (1.0 + b * X) / g;
}

enum { KT_LUN = 0, KT_GIDASPOW = 1 };

/* Shape of the shear viscosity: mu_s = rho_s d_p sqrt(theta) * f(phi, g0),
 * with the partial derivatives of f at fixed g0 and at fixed phi. */
static inline double kt_mu_shape(int variant, double e, double phi, double g, double *f_phi, double *f_g) {
  double dp, dg, s;
  if (variant == KT_GIDASPOW) {
    double a1 = 0.8 * (1.0 + e) / KT_SQRT_PI, a2 = 10.0 * KT_SQRT_PI / (96.0 * (1.0 + e)), b = 0.8 * (1.0 + e);
    s = kt_pair(b, b, phi, g, &dp, &dg);
    *f_phi = 2.0 * a1 * phi * g + a2 * dp;
    *f_g = a1 * phi * phi + a2 * dg;
    return a1 * phi * phi * g + a2 * s;
  }
  double eta = 0.5 * (1.0 + e);
  double c0 = 5.0 * KT_SQRT_PI / 96.0, k1 = c0 / (eta * (2.0 - eta)), q = c0 * 768.0 * eta / (25.0 * KT_PI);
  s = kt_pair(1.6 * eta, 1.6 * eta * (3.0 * eta - 2.0), phi, g, &dp, &dg);
  *f_phi = k1 * dp + 2.0 * q * phi * g;
  *f_g = k1 * dg + q * phi * phi;
  return k1 * s + q * phi * phi * g;
}

/* Shape of the conductivity: kappa = rho_s d_p sqrt(theta) * f(phi, g0). */
static inline double kt_kappa_shape(int variant, double e, double phi, double g, double *f_phi, double *f_g) {
  double dp, dg, s;
  if (variant == KT_GIDASPOW) {
    double a1 = 2.0 * (1.0 + e) / KT_SQRT_PI, a2 = 150.0 * KT_SQRT_PI / (384.0 * (1.0 + e)), b = 1.2 * (1.0 + e);
    s = kt_pair(b, b, phi, g, &dp, &dg);
    *f_phi = 2.0 * a1 * phi * g + a2 * dp;
    *f_g = a1 * phi * phi + a2 * dg;
    return a1 * phi * phi * g + a2 * s;
  }
  double eta = 0.5 * (1.0 + e), w = 41.0 - 33.0 * eta;
  double k1 = 75.0 * KT_SQRT_PI / (48.0 * eta * w), q = k1 * 64.0 * w * eta * eta / (25.0 * KT_PI);
  s = kt_pair(2.4 * eta, 2.4 * eta * eta * (4.0 * eta - 3.0), phi, g, &dp, &dg);
  *f_phi = k1 * dp + 2.0 * q * phi * g;
  *f_g = k1 * dg + q * phi * phi;
  return k1 * s + q * phi * phi * g;
}

#endif
