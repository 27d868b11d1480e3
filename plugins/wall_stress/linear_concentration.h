/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Bagnold's linear concentration (Bagnold 1954; Krampa 2009 eq 2.9),
 *   lambda = 1 / ((phi_max/phi)^(1/3) - 1) = x / (1 - x),  x = (phi/phi_max)^(1/3),
 * the ratio of particle diameter to mean gap between neighbours. It diverges
 * at phi_max; above phi_c = phi_max - delta it is replaced by its tangent
 * line (value and slope matched, C1), so it stays finite and increasing for
 * over-packed states. Used by bagnold.c and bartosik.c. Header-only. */
#ifndef SLUICE_PLUGINS_WALL_STRESS_LINEAR_CONCENTRATION_H
#define SLUICE_PLUGINS_WALL_STRESS_LINEAR_CONCENTRATION_H

#include <math.h>

static inline double ws_lambda_raw(double phi, double phi_max, double *dlam) {
  double x = cbrt(phi / phi_max), o = 1.0 - x;
  *dlam = phi > 0 ? x / (3.0 * phi * o * o) : HUGE_VAL; /* only used at phi_c > 0 */
  return x / o;
}

static inline double ws_lambda(double phi, double phi_max, double delta) {
  double d, phi_c = phi_max - delta;
  if (phi <= phi_c) return ws_lambda_raw(phi, phi_max, &d);
  double lam_c = ws_lambda_raw(phi_c, phi_max, &d);
  return lam_c + d * (phi - phi_c);
}

#endif
