/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Shared pieces of the frictional (quasi-static, Coulomb) solids stress
 * closures schaeffer.c and johnson_jackson_frictional.c: the frictional
 * pressure laws, the Coulomb viscosity and the evaluate loop.
 * Header-only, static, no state.
 *
 * Frictional pressure p_fr(phi), zero at and below phi_min:
 *   power_law        p_coefficient (phi - phi_min)^p_exponent
 *                    (Schaeffer 1987 as implemented by Syamlal, Rogers &
 *                    O'Brien 1993, MFIX: 1e25 Pa, exponent 10)
 *   johnson_jackson  fr (phi - phi_min)^r / (phi_max - phi)^s
 *                    (Johnson & Jackson 1987 J Fluid Mech 176:67, eq 2.x;
 *                    Fr = 0.05 Pa, r = 2, s = 5 for their glass beads),
 *                    continued by its tangent line above phi_c = phi_max - delta
 *                    so that it stays finite and C1 at and beyond packing
 *                    (OpenFOAM's max(phi_max - phi, delta) is only C0).
 *
 * Coulomb viscosity: in a yielding (plastic) state the deviatoric stress has
 * the magnitude p_fr sin(friction_angle); with the host's shear rate
 * shear_rate = sqrt(2 D:D) this is
 *   mu_fr = p_fr sin(friction_angle) / sqrt(shear_rate^2 + shear_rate_reg^2).
 * Schaeffer's p sin(phi_f)/(2 sqrt(I_2D)), with I_2D = (1/2) D':D' the
 * second invariant of the deviatoric strain rate (MFiX, Fluent, OpenFOAM), and
 * Johnson & Jackson's sqrt(2) p sin(phi_f) S/|S| both reduce to
 * p sin(phi_f)/shear_rate when D is traceless (the host should pass
 * sqrt(2 D':D') for a compressible solids velocity). In simple shear the
 * shear stress is then mu_fr shear_rate = p_fr sin(friction_angle), the
 * Coulomb limit. shear_rate_reg (default 1e-4 s^-1) keeps mu_fr finite in
 * unsheared regions (peer codes add a "small" or cap mu_fr instead).
 *
 * The friction angle is in RADIANS (architecture.md section 4): SedFoam
 * shipped degrees where radians were meant (SedFoam PR #52) and OpenFOAM-dev
 * converts from degrees internally; its bounds [0, pi/2] reject a value
 * given in degrees (30 is refused; 30 degrees is 0.5236). */
#ifndef SLUICE_PLUGINS_GRANULAR_FRICTIONAL_H
#define SLUICE_PLUGINS_GRANULAR_FRICTIONAL_H

#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>
#include <string.h>

#include "granular/inputs.h"

enum { FR_POWER_LAW = 0, FR_JOHNSON_JACKSON = 1 };

typedef struct fr_params {
  double friction_angle; /* rad */
  double phi_min, phi_max, delta;
  double fr, r, s;                  /* Johnson-Jackson pressure */
  double p_coefficient, p_exponent; /* power-law pressure (schaeffer only) */
  double shear_rate_reg;            /* s^-1 */
  int32_t pressure;                 /* FR_* (schaeffer only; johnson_jackson_frictional forces FR_JOHNSON_JACKSON) */
} fr_params;

enum { FR_IN_PHI, FR_IN_THETA, FR_IN_SHEAR_RATE, FR_N_IN };
enum { FR_OUT_P_FR, FR_OUT_MU_FR, FR_N_OUT };

#define FR_INPUTS                                                                                     \
  {                                                                                                   \
    {"phi", "1", SL_FIELD_DIFF, 0.58, 0.0, 0.74, "solids volume fraction"},                           \
        {"theta",                                                                                     \
         "m^2 s^-2",                                                                                  \
         0,                                                                                           \
         1e-3,                                                                                        \
         0.0,                                                                                         \
         1e4,                                                                                         \
         "granular temperature: required by the granular kind contract, not used by this closure"},   \
        {"shear_rate", "s^-1", SL_FIELD_DIFF, 1.0, 0.0, 1e6, "shear rate sqrt(2 D:D) of the solids"}, \
  }

#define FR_OUTPUTS                                                                                    \
  {                                                                                                   \
    {"p_fr", "Pa", SL_FIELD_OPTIONAL, 0, 0, 0, "frictional pressure (added to the solids pressure)"}, \
        {"mu_fr", "Pa s", SL_FIELD_OPTIONAL, 0, 0, 0, "frictional (Coulomb) shear viscosity"},        \
  }

/* The parameters of the Johnson-Jackson pressure (granular/johnson_jackson_frictional, and
   solids_pressure/johnson_jackson_frictional where p_fr is the solids pressure p_s). */
#define FR_JJ_PRESSURE_PARAMS                                                                                      \
  SL_PARAM_REAL_OF(fr_params, fr, 0.05, 0.0, 1e8, "Pa", "coefficient Fr"),                                         \
      SL_PARAM_REAL_OF(fr_params, r, 2.0, 1.0, 10.0, "1",                                                          \
                       "exponent of (phi - phi_min); r > 1 makes p_fr C1 at phi_min"),                             \
      SL_PARAM_REAL_OF(fr_params, s, 5.0, 0.0, 10.0, "1", "exponent of (phi_max - phi)"),                          \
      SL_PARAM_REAL_OF(fr_params, phi_min, 0.5, 0.0, 0.74, "1", "solids fraction where friction starts"),          \
      SL_PARAM_REAL_OF(fr_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing"),                               \
      SL_PARAM_REAL_OF(fr_params, delta, 0.01, 1e-4, 0.1, "1",                                                     \
                       "p_fr is continued by its tangent line above phi_max - delta (C1, finite)")

/* Johnson-Jackson pressure without continuation, phi_min < phi < phi_max. */
static inline double fr_jj_raw(const fr_params *p, double phi, double *dp) {
  double a = phi - p->phi_min, b = p->phi_max - phi;
  double ar = pow(a, p->r), bs = pow(b, p->s);
  *dp = p->fr * (p->r * pow(a, p->r - 1.0) / bs + p->s * ar / (bs * b));
  return p->fr * ar / bs;
}

static inline double fr_pressure(const fr_params *p, int model, double phi, double *dp) {
  if (!(phi > p->phi_min)) {
    *dp = 0.0;
    return 0.0;
  }
  if (model == FR_POWER_LAW) {
    double a = phi - p->phi_min;
    *dp = p->p_coefficient * p->p_exponent * pow(a, p->p_exponent - 1.0);
    return p->p_coefficient * pow(a, p->p_exponent);
  }
  double phi_c = p->phi_max - p->delta;
  if (phi <= phi_c) return fr_jj_raw(p, phi, dp);
  double slope, p_c = fr_jj_raw(p, phi_c, &slope);
  *dp = slope;
  return p_c + slope * (phi - phi_c);
}

/* create(): copies the parameters and checks what the bounds cannot. */
static inline int fr_create(const sl_host_api *api, const void *params, void **state, sl_error *err, int model) {
  const fr_params *p = params;
  if (model == FR_JOHNSON_JACKSON && !(p->phi_min < p->phi_max - p->delta))
    return sl_fail(err, SL_ERR_ARG, -1, "phi_min = %g must be below phi_max - delta = %g", p->phi_min,
                   p->phi_max - p->delta);
  fr_params *s = api->alloc(api->host, sizeof *s);
  if (!s) return sl_fail(err, SL_ERR_MEM, -1, "out of memory");
  memcpy(s, p, sizeof *s);
  *state = s;
  return SL_OK;
}

static inline void fr_destroy(const sl_host_api *api, void *state) { api->free(api->host, state); }

static inline int fr_evaluate(const fr_params *p, int model, const sl_field_desc *in, const sl_eval_args *a) {
  int rc = gr_check_inputs(a, in, FR_N_IN);
  if (rc) return rc;
  const double *phi = a->in[FR_IN_PHI], *gd = a->in[FR_IN_SHEAR_RATE];
  double *pf = a->out[FR_OUT_P_FR], *mu = a->out[FR_OUT_MU_FR];
  double *dp_dphi = pf ? sl_dout(a, FR_N_IN, FR_OUT_P_FR, FR_IN_PHI) : NULL;
  double *dp_dgd = pf ? sl_dout(a, FR_N_IN, FR_OUT_P_FR, FR_IN_SHEAR_RATE) : NULL;
  double *dmu_dphi = mu ? sl_dout(a, FR_N_IN, FR_OUT_MU_FR, FR_IN_PHI) : NULL;
  double *dmu_dgd = mu ? sl_dout(a, FR_N_IN, FR_OUT_MU_FR, FR_IN_SHEAR_RATE) : NULL;
  const double sf = sin(p->friction_angle), reg2 = p->shear_rate_reg * p->shear_rate_reg;
  for (int32_t q = 0; q < a->Q; ++q) {
    double dp, pr = fr_pressure(p, model, phi[q], &dp);
    gr_set(pf, q, pr);
    gr_set(dp_dphi, q, dp);
    gr_set(dp_dgd, q, 0.0);
    if (mu) {
      double S = sqrt(gd[q] * gd[q] + reg2);
      mu[q] = pr * sf / S;
      gr_set(dmu_dphi, q, dp * sf / S);
      gr_set(dmu_dgd, q, -pr * sf * gd[q] / (S * S * S));
    }
  }
  return SL_OK;
}

#endif
