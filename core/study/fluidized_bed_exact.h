/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The porosity of a homogeneous liquid-fluidised bed at rest: fluid passes
 * upwards at superficial velocity U through particles that do not move, so
 * the drag on the solids carries their buoyant weight,
 *
 *   K(phi, s) s = phi (1 - phi) (rho_s - rho_f) |g|,   s = U / (1 - phi),
 *
 * with K the interphase momentum exchange coefficient (F_s = K (u_f - u_s))
 * and s the interstitial slip: the solids momentum balance of the two-fluid
 * model with the solids at rest and no solids-pressure gradient (Pringle
 * 2001, eq 4.20 at steady state: beta V_r = n (1 - n) (rho_s - rho_f) g, n the porosity
 * there). With the drag K = (rho_s - rho_f) |g| phi / (u_t (1 - phi)^(n - 2))
 * it is Richardson & Zaki's law U = u_t (1 - phi)^n, n their exponent (1954,
 * Trans. Inst. Chem. Eng. 32:35).
 *
 * Divided by phi, the balance reads
 *   r(e) = (K / phi)(1 - e, U / e) U / e - e (rho_s - rho_f) |g| = 0
 * in the porosity e = 1 - phi. For the drag laws in use K / phi grows with
 * phi and with the slip, so r falls as e rises and has one root between the
 * packed bed (e = 1 - phi_max) and a single particle (e = 1): a bed exists
 * when U lies between the minimum fluidisation velocity (r > 0 at the packed
 * end) and the terminal velocity (r < 0 at e = 1). The root is found by
 * bisection, to round-off. */
#ifndef SLUICE_VERIFY_FLUIDIZED_BED_EXACT_H
#define SLUICE_VERIFY_FLUIDIZED_BED_EXACT_H

#include <math.h>

/* K at one (phi, slip) into *K; 0, or nonzero when the drag cannot be
 * evaluated there (the bisection stops with that status). */
typedef int (*fb_drag_fn)(void *user, double phi, double slip, double *K);

typedef struct fb_bed {
  double rho_f, rho_s; /* kg/m^3 */
  double g;            /* |g|, m/s^2 */
  double U;            /* superficial fluid velocity through the bed, m/s */
  double phi_max;      /* the packed bed's solids fraction */
} fb_bed;

typedef enum fb_status {
  FB_OK = 0,
  FB_PACKED = 1,    /* U is at or below the minimum fluidisation velocity: r(1 - phi_max) <= 0 */
  FB_BLOWN_OUT = 2, /* U is at or above the terminal velocity: r(1) >= 0 */
  FB_DRAG_FAILED = 3
} fb_status;

/* r(e) of the comment above; *r NaN when the drag fails. */
static inline int fb_residual(const fb_bed *b, fb_drag_fn drag, void *user, double e, double *r) {
  double phi = 1.0 - e, slip = b->U / e, K = NAN;
  /* at e = 1 (phi = 0) K / phi is the single particle's drag: its limit, taken at phi = 1e-9 */
  const double phi_eval = phi > 1e-9 ? phi : 1e-9;
  if (drag(user, phi_eval, slip, &K) || !isfinite(K)) {
    *r = NAN;
    return FB_DRAG_FAILED;
  }
  *r = K / phi_eval * slip - e * (b->rho_s - b->rho_f) * b->g;
  return FB_OK;
}

/* The bed's porosity e into *porosity; FB_OK, or why there is no bed. */
static inline fb_status fb_equilibrium_porosity(const fb_bed *b, fb_drag_fn drag, void *user, double *porosity) {
  double lo = 1.0 - b->phi_max, hi = 1.0, r_lo, r_hi;
  *porosity = NAN;
  if (fb_residual(b, drag, user, lo, &r_lo) || fb_residual(b, drag, user, hi, &r_hi)) return FB_DRAG_FAILED;
  if (!(r_lo > 0.0)) return FB_PACKED;
  if (!(r_hi < 0.0)) return FB_BLOWN_OUT;
  for (int it = 0; it < 200 && hi - lo > 4e-16; ++it) {
    double e = 0.5 * (lo + hi), r;
    if (fb_residual(b, drag, user, e, &r)) return FB_DRAG_FAILED;
    if (r > 0.0) lo = e;
    else hi = e;
  }
  *porosity = 0.5 * (lo + hi);
  return FB_OK;
}

#endif
