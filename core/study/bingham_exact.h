/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Fully developed pressure-driven flow of a Bingham fluid between plates at
 * y = c - H and y = c + H (Bird, Dai & Yarusso 1983, Rev. Chem. Eng. 1:1,
 * section 3.1): driven by G = -dp/dz (any sign), with plastic viscosity
 * mu_p and yield stress tau0, the stress grows linearly from the centre,
 * |tau| = |G| r (r = |y - c|), so the fluid is rigid (a plug) for
 * r < y0 = tau0 / |G| and, outside,
 *   w(r) = sign(G) [ |G| (H^2 - r^2) / (2 mu_p) - tau0 (H - r) / mu_p ],
 * the plug moving at w(y0) = sign(G) |G| (H - y0)^2 / (2 mu_p). No flow when
 * y0 >= H. */
#ifndef SLUICE_VERIFY_BINGHAM_EXACT_H
#define SLUICE_VERIFY_BINGHAM_EXACT_H

#include <math.h>

typedef struct bingham_channel {
  double centre, half_width; /* c, H */
  double G, mu_p, tau0;
} bingham_channel;

static inline double bingham_channel_velocity(const bingham_channel *b, double y) {
  double H = b->half_width, g = fabs(b->G), y0 = g > 0.0 ? b->tau0 / g : INFINITY;
  if (y0 >= H) return 0.0;
  double r = fmin(fabs(y - b->centre), H);
  if (r < y0) r = y0;
  double w = g * (H * H - r * r) / (2.0 * b->mu_p) - b->tau0 * (H - r) / b->mu_p;
  return b->G < 0.0 ? -w : w;
}

#endif
