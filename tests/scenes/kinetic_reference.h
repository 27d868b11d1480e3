/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lun et al.'s (1984) kinetic theory at theta = 1 and Wen & Yu's drag at
 * zero slip, coded from the formulas (lun.c's comment) rather than through
 * the closures, for the scene tests of the shear layer and the 2-D model:
 * mu_s = mu0 theta^0.5, gamma = gamma0 theta^1.5. */
#ifndef SLUICE_TESTS_SCENES_KINETIC_REFERENCE_H
#define SLUICE_TESTS_SCENES_KINETIC_REFERENCE_H

#include <math.h>

typedef struct kt_point {
  double phi, rho_s, d, e, phi_max;
} kt_point;

static inline double g0_lun_savage(const kt_point *p) { return pow(1.0 - p->phi / p->phi_max, -2.5 * p->phi_max); }

static inline double mu0_lun(const kt_point *p) {
  const double pi = 3.14159265358979323846;
  double eta = 0.5 * (1.0 + p->e), g0 = g0_lun_savage(p), X = p->phi * g0;
  return 5.0 * sqrt(pi) / 96.0 * p->rho_s * p->d *
         ((1.0 + 1.6 * eta * X) * (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * X) / (eta * (2.0 - eta) * g0) +
          768.0 / (25.0 * pi) * eta * p->phi * X);
}

static inline double gamma0_lun(const kt_point *p) {
  const double pi = 3.14159265358979323846;
  return 12.0 * (1.0 - p->e * p->e) * g0_lun_savage(p) * p->rho_s * p->phi * p->phi / (p->d * sqrt(pi));
}

/* Wen & Yu (1966) as written by Gidaspow (1994) at zero slip: the Stokes
 * limit of C_D = 24/Re (1 + 0.15 Re^0.687), Re = eps rho_f d s / mu. */
static inline double k_wen_yu_zero_slip(double phi, double mu, double d) {
  return 18.0 * mu * phi * pow(1.0 - phi, -2.65) / (d * d);
}

#endif
