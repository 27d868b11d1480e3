/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Settling in a vessel whose side walls lean at gamma from the vertical
 * (the Boycott effect): the kinematic theory of Ponder, Nakamura & Kuroda
 * (PNK) and its correction for the clear-fluid layer under the
 * downward-facing wall (Nigam 1999, section 4.2).
 * Lengths in units of the vessel's height, time in units of H / u_t.
 *
 * The vessel is a parallelogram of horizontal width w = L / cos(gamma)
 * (L its perpendicular width). Clear fluid is produced at the hindered
 * settling velocity A = (1 - alpha0)^2 / mu(alpha0) times the horizontal
 * projection of the whole mixture / clear-fluid interface: the horizontal
 * front z_F and the interface under the downward-facing wall from the
 * sediment's top S_s up to the front (4.74-4.76),
 *
 *   dV/dt = A (w + (z_F - S_s) tan(gamma)).                               (P)
 *
 * PNK put all of V above the front, V = w (1 - z_F) (without the sediment,
 * as in 4.77-4.79):  z_F(t) = (1 + 1/C) e^(-A C t) - 1/C,  C = sin(gamma)/L.
 *
 * Part of V is the layer that carries it up the wall, which PNK leave out
 * (Nigam's reason for his front's lag). With the layer's thickness from the
 * quartic-profile solution (4.117), measured from the sediment
 * (xi -> xi - S_s / cos(gamma)),
 *
 *   delta(xi) = (Re/Lambda)^(1/2) A sin(gamma) (320 xi / (81 cos(gamma)))^(1/2),
 *
 * the layer up to the front holds V_l = (2/3) delta(xi_F) xi_F, xi_F =
 * (z_F - S_s) / cos(gamma), and the front follows from w (1 - z_F) + V_l =
 * V with V from (P). The layer is taken quasi-steady: it fills first (the
 * front stays at the top while V < V_l(1)), so the correction is meant for
 * times past the layer's formation (about a transit time along the wall).
 *
 * The sediment's top rises as S_s = (alpha0/alpha_m)(1 - alpha0)^2 (1 -
 * alpha0/alpha_m)^(K alpha_m - 1) t (4.128; Krieger mu with exponent K
 * alpha_m). */
#ifndef SLUICE_VERIFY_BOYCOTT_PNK_H
#define SLUICE_VERIFY_BOYCOTT_PNK_H

#include <math.h>

typedef struct boycott_vessel {
  double gamma;           /* wall angle from the vertical, rad */
  double L;               /* perpendicular width */
  double alpha0, alpha_m; /* the suspension's fraction, packing */
  double K;               /* Krieger's intrinsic viscosity: mu = (1 - alpha/alpha_m)^(-K alpha_m) */
  double re_over_lambda;  /* Re / Lambda (Nigam 4.70) */
} boycott_vessel;

static inline double boycott_A(const boycott_vessel *v) {
  double mu = pow(1 - v->alpha0 / v->alpha_m, -v->K * v->alpha_m);
  return (1 - v->alpha0) * (1 - v->alpha0) / mu;
}

static inline double boycott_width(const boycott_vessel *v) { return v->L / cos(v->gamma); }

/* PNK's front (4.79), z_F(0) = 1. */
static inline double boycott_pnk_front(const boycott_vessel *v, double t) {
  double C = sin(v->gamma) / v->L;
  return (1 + 1 / C) * exp(-boycott_A(v) * C * t) - 1 / C;
}

/* The sediment's top (4.128). */
static inline double boycott_sediment(const boycott_vessel *v, double t) {
  double r = v->alpha0 / v->alpha_m;
  return r * (1 - v->alpha0) * (1 - v->alpha0) * pow(1 - r, v->K * v->alpha_m - 1) * t;
}

/* Clear fluid produced per unit time (P) with the front at z. */
static inline double boycott_production_rate(const boycott_vessel *v, double z, double t) {
  return boycott_A(v) * (boycott_width(v) + (z - boycott_sediment(v, t)) * tan(v->gamma));
}

/* The layer's volume below the front at z (4.117, integrated along the wall). */
static inline double boycott_layer_volume(const boycott_vessel *v, double z, double t) {
  double xi = (z - boycott_sediment(v, t)) / cos(v->gamma);
  if (xi <= 0) return 0;
  double k = sqrt(v->re_over_lambda) * boycott_A(v) * sin(v->gamma) * sqrt(320.0 / (81.0 * cos(v->gamma)));
  return 2.0 / 3.0 * k * xi * sqrt(xi);
}

/* The front that holds the clear-fluid volume V at time t: w (1 - z) +
 * V_l(z) = V, decreasing in z, by bisection; the top while the layer alone
 * takes V. */
static inline double boycott_front_of_volume(const boycott_vessel *v, double V, double t) {
  if (boycott_layer_volume(v, 1.0, t) >= V) return 1.0;
  double w = boycott_width(v), lo = boycott_sediment(v, t), hi = 1.0;
  for (int it = 0; it < 80; ++it) {
    double m = 0.5 * (lo + hi);
    if (w * (1 - m) + boycott_layer_volume(v, m, t) > V) lo = m;
    else hi = m;
  }
  return 0.5 * (lo + hi);
}

/* The front with the layer's volume counted: (P) integrated by the midpoint
 * rule in n steps. */
static inline double boycott_front_with_layer(const boycott_vessel *v, double t_end, int n) {
  double h = t_end / n, V = 0.0, z = 1.0;
  for (int i = 0; i < n; ++i) {
    double t = i * h;
    double z_half = boycott_front_of_volume(v, V + 0.5 * h * boycott_production_rate(v, z, t), t + 0.5 * h);
    V += h * boycott_production_rate(v, z_half, t + 0.5 * h);
    z = boycott_front_of_volume(v, V, t + h);
  }
  return z;
}

#endif
