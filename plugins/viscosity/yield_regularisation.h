/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Regularisations of the yield-stress term tau0/shear_rate shared by the
 * bingham and herschel_bulkley closures (header-only, no state).
 *
 *  Bercovier & Engelman (1980) J. Comput. Phys. 36:313:
 *     tau0 / sqrt(g^2 + eps^2)                 -> tau0/eps at g = 0
 *  Papanastasiou (1987) J. Rheol. 31:385:
 *     tau0 (1 - exp(-m g)) / g = tau0 m f(m g),  f(x) = (1 - e^-x)/x
 *                                              -> tau0 m at g = 0
 * The Papanastasiou term is evaluated without cancellation near g = 0: the
 * value with expm1, its derivative with a Taylor series below m g = 0.25. */
#ifndef SLUICE_PLUGINS_VISCOSITY_YIELD_REGULARISATION_H
#define SLUICE_PLUGINS_VISCOSITY_YIELD_REGULARISATION_H

#include <math.h>

enum { SL_REG_BERCOVIER_ENGELMAN = 0, SL_REG_PAPANASTASIOU = 1 };
#define SL_REG_CHOICES "bercovier_engelman|papanastasiou"

/* f'(x) for f(x) = (1 - exp(-x))/x, by its Taylor series
 * sum_{k>=1} (-1)^k x^(k-1) / ((k+1) (k-1)!) to k = 12: for x < 0.25 the
 * truncation is below 1e-17 relative, where the closed form
 * (x e^-x + expm1(-x))/x^2 would cancel. f'(0) = -1/2. */
static inline double sl_papanastasiou_df_series(double x) {
  static const double c[12] = {-1.0 / 2,      1.0 / 3,       -1.0 / 8,        1.0 / 30,
                               -1.0 / 144,    1.0 / 840,     -1.0 / 5760,     1.0 / 45360,
                               -1.0 / 403200, 1.0 / 3991680, -1.0 / 43545600, 1.0 / 518918400};
  double s = 0.0;
  for (int k = 11; k >= 0; --k) s = s * x + c[k];
  return s;
}

/* Yield term y(g) and dy/dg at shear rate g >= 0 (finite). */
static inline void sl_yield_term(int form, double tau0, double eps, double m, double g, double *y, double *dy) {
  if (form == SL_REG_PAPANASTASIOU) {
    double x = m * g;
    /* y = tau0 (1 - e^-x)/g with expm1 (no cancellation); below x = 1e-5
     * (and at g = 0, where the limit is tau0 m) the series
     * tau0 m (1 - x/2 + x^2/6 - x^3/24), whose truncation is below 1e-21. */
    *y = x < 1e-5 ? tau0 * m * (1.0 - x / 2.0 * (1.0 - x / 3.0 * (1.0 - x / 4.0))) : -tau0 * expm1(-x) / g;
    /* dy/dg = tau0 m^2 f'(x) = tau0 [m e^-x / g + expm1(-x) / g^2]. */
    *dy = x < 0.25 ? tau0 * m * m * sl_papanastasiou_df_series(x) : tau0 * (m * exp(-x) / g + expm1(-x) / (g * g));
  } else {
    double r = hypot(g, eps);
    *y = tau0 / r;
    *dy = -tau0 * (g / r) / (r * r);
  }
}

#endif
