/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The asymptotic particle fraction of a light-particle suspension spun up
 * from rest in a closed cylinder (Amberg & Ungarish 1993; Nigam 1999,
 * section 4.1, eqs 4.51-4.61), in the interior's
 * spun-up region e^-tau < r < r_s, for small Ekman number.
 *
 * Spin-up time tau = (mu(alpha0) E)^(1/2) t / H. Wedemeyer's interior swirl
 * (4.54) puts the front at r_f = e^-tau. Fluid leaves the lid layers with
 * alpha0 at a radius r0 in (e^-tau0, 1] and time tau0, then moves along the
 * characteristics (4.57-4.61), F(alpha) = alpha (1 - alpha)^2 / mu(alpha):
 *
 *   dr/dtau     = [(r^2 - 1) e^-2tau + kappa F'(alpha) (r^2 - e^-2tau)^2 / (r^2 (1 - e^-2tau))] / (r (1 - e^-2tau))
 *   dalpha/dtau = -2 kappa F(alpha) (1 - e^-4tau / r^4) / (1 - e^-2tau)^2
 *   1 - e^-2tau0 = (1 - 2 z / H) (1 - e^-2tau)        (the height z reached at tau)
 *
 * kappa = H eps beta / (mu(alpha0) E)^(1/2) is the centrifugal separation
 * speed's coefficient in tau units (-0.8735 for the thesis's parameters,
 * computed from the primitive parameters). The characteristics' end radius grows with r0, so
 * alpha(r) is found by bisection on r0 (Nigam's algorithm, 4.64), each
 * characteristic integrated by classical RK4 (the right-hand side is smooth
 * for tau0 > 0). */
#ifndef SLUICE_VERIFY_SPINUP_ASYMPTOTIC_H
#define SLUICE_VERIFY_SPINUP_ASYMPTOTIC_H

#include <math.h>

#include "core/study/kynch_exact.h"

typedef struct spinup_theory {
  kx_law flux; /* F(alpha) = alpha (1 - alpha)^2 (1 - alpha/alpha_m)^(K alpha_m): kx_nigam(1, K, alpha_m) */
  double kappa, H, alpha0;
} spinup_theory;

static inline void spinup_rhs(const spinup_theory *s, double tau, double r, double a, double *dr, double *da) {
  double e2 = exp(-2 * tau), g = 1 - e2, r2 = r * r;
  *dr = ((r2 - 1) * e2 + s->kappa * kx_dF(&s->flux, a) * (r2 - e2) * (r2 - e2) / (r2 * g)) / (r * g);
  *da = -2 * s->kappa * kx_F(&s->flux, a) * (1 - e2 * e2 / (r2 * r2)) / (g * g);
}

/* The characteristic leaving the lid at radius r0 and time tau0, followed to
 * tau in n RK4 steps: its radius and fraction there. */
static inline void spinup_characteristic(const spinup_theory *s, double tau0, double r0, double tau, int n, double *r,
                                         double *alpha) {
  double h = (tau - tau0) / n, x = r0, a = s->alpha0;
  for (int i = 0; i < n; ++i) {
    double t = tau0 + i * h, k1r, k1a, k2r, k2a, k3r, k3a, k4r, k4a;
    spinup_rhs(s, t, x, a, &k1r, &k1a);
    spinup_rhs(s, t + h / 2, x + h / 2 * k1r, a + h / 2 * k1a, &k2r, &k2a);
    spinup_rhs(s, t + h / 2, x + h / 2 * k2r, a + h / 2 * k2a, &k3r, &k3a);
    spinup_rhs(s, t + h, x + h * k3r, a + h * k3a, &k4r, &k4a);
    x += h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
    a += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
  }
  *r = x, *alpha = a;
}

/* The time tau0 at which the fluid at height z (0 < z < H/2) at tau left the
 * lid. */
static inline double spinup_departure(const spinup_theory *s, double z, double tau) {
  return -0.5 * log(1 - (1 - 2 * z / s->H) * (1 - exp(-2 * tau)));
}

/* alpha at radius r and height z at time tau: alpha0 in the non-rotating
 * core (r <= e^-tau), NAN beyond the characteristic from the wall. (That
 * characteristic ends outside r = 1: the shock, not the wall, bounds the
 * mixture region.) */
static inline double spinup_alpha(const spinup_theory *s, double r, double z, double tau) {
  if (r <= exp(-tau)) return s->alpha0;
  double tau0 = spinup_departure(s, z, tau), lo = exp(-tau0), hi = 1.0, re, a;
  const int steps = 2000;
  spinup_characteristic(s, tau0, hi, tau, steps, &re, &a);
  if (r > re) return NAN;
  for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
    double mid = 0.5 * (lo + hi);
    spinup_characteristic(s, tau0, mid, tau, steps, &re, &a);
    if (re < r) lo = mid;
    else hi = mid;
  }
  spinup_characteristic(s, tau0, 0.5 * (lo + hi), tau, steps, &re, &a);
  return a;
}

#endif
