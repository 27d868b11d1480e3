/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Algebraic (local-equilibrium) granular temperature in homogeneous simple
 * shear: production by the shear stress equals collisional dissipation,
 *   mu_s(phi, theta) shear_rate^2 = gamma(phi, theta),
 * with convection, conduction and interphase exchange neglected. Because
 * mu_s = rho_s d_p sqrt(theta) f_mu(phi, g0) and
 * gamma = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi)), the balance
 * is linear in theta:
 *   theta = sqrt(pi) d_p^2 f_mu(phi, g0) shear_rate^2 / (12 (1 - e^2) g0 phi^2).
 * rho_s cancels (it is therefore not an input).
 *
 * This is the pure-shear (div u_s = 0) reduction of the algebraic
 * equilibrium model of Syamlal, Rogers & O'Brien (1993, MFIX documentation,
 * DOE/METC-94/1004) and van Wachem et al. (2001, AIChE J 47:1035), as used by
 * ANSYS CFX-10: Krampa (2009) eqs 6.8-6.19, whose quadratic (6.13) reduces
 * with D = 0 to theta = mu_s^(0) S^2 d_s sqrt(pi)/(4 E_D), E_D = 3 (1 - e^2)
 * phi^2 rho_s g0 (section 6.2; (6.17) misprints sqrt(pi) as pi). Here
 * shear_rate = sqrt(2 D:D), so the production 2 mu_s D:D = mu_s shear_rate^2.
 *
 * f_mu and g0 are exactly those of the granular closures `gidaspow` and
 * `lun` (kinetic.h): with the same viscosity, radial, e, phi_max and delta,
 * the closures' own mu_s(theta_eq) shear_rate^2 equals their gamma(theta_eq)
 * to rounding. Without interphase exchange theta grows like phi^-2 in dilute
 * flow (CFX caps it; no cap here), hence phi >= 1e-6. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "granular/kinetic.h"

typedef struct at_params {
  double e;
  double phi_max;
  double delta;
  int32_t viscosity; /* KT_LUN or KT_GIDASPOW */
  int32_t radial;
} at_params;

enum { IN_PHI, IN_THETA, IN_SHEAR_RATE, IN_D_P, N_IN };
enum { OUT_THETA, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(at_params, e, 0.9, 0.0, 0.9999, "1",
                     "particle-particle restitution coefficient (< 1: no equilibrium for elastic spheres)"),
    SL_PARAM_REAL_OF(at_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing fraction in g0"),
    SL_PARAM_REAL_OF(at_params, delta, 0.01, 1e-4, 0.1, "1",
                     "g0 is continued by its tangent line above phi_max - delta"),
    SL_PARAM_ENUM_OF(at_params, viscosity, 1, "lun|gidaspow",
                     "shear viscosity producing granular energy: that of granular/lun or granular/gidaspow"),
    SL_PARAM_ENUM_OF(at_params, radial, KT_G0_GIDASPOW, KT_G0_CHOICES, KT_G0_HELP),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 1e-6, 0.74, "solids volume fraction"},
    {"theta", "m^2 s^-2", 0, 1e-3, 0.0, 1e4,
     "granular temperature: required by the granular kind contract, not used (this closure computes it)"},
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 10.0, 0.0, 1e6, "shear rate sqrt(2 D:D) of the solids"},
    {"d_p", "m", 0, 5e-4, 1e-8, 1.0, "particle diameter"},
};

static const sl_field_desc outputs[] = {
    {"theta", "m^2 s^-2", 0, 0, 0, 0, "equilibrium granular temperature"},
};

/* Defaults: gidaspow viscosity and g0, e = 0.9, phi_max = 0.63. At
 * phi = phi_max/8, g0 = 1.2 exactly; d_p = 1e-3, shear_rate = 10. */
#define AT_E 0.9
#define AT_PHI (0.63 / 8.0)
#define AT_X (AT_PHI * 1.2)
#define AT_FMU                                                                                         \
  (0.8 * AT_PHI * AT_X * (1.0 + AT_E) / KT_SQRT_PI + 10.0 * KT_SQRT_PI / (96.0 * (1.0 + AT_E) * 1.2) * \
                                                         (1.0 + 0.8 * AT_X * (1.0 + AT_E)) *           \
                                                         (1.0 + 0.8 * AT_X * (1.0 + AT_E)))
static const double check_in[N_IN] = {AT_PHI, 0.0, 10.0, 1e-3};
static const sl_check_point checks[] = {
    {check_in, OUT_THETA, KT_SQRT_PI * 1e-6 * AT_FMU * 100.0 / (12.0 * (1.0 - AT_E * AT_E) * 1.2 * AT_PHI * AT_PHI),
     1e-12,
     "Krampa (2009) eq 6.19 with div u = 0: theta = mu_s0 S^2 d sqrt(pi)/(4 E_D), Gidaspow mu_s, "
     "g0 = 1.2 at phi = phi_max/8, hand-evaluated"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const at_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *phi = a->in[IN_PHI], *gd = a->in[IN_SHEAR_RATE], *dp = a->in[IN_D_P];
  double *th = a->out[OUT_THETA];
  double *dth_dphi = sl_dout(a, N_IN, OUT_THETA, IN_PHI), *dth_dgd = sl_dout(a, N_IN, OUT_THETA, IN_SHEAR_RATE);
  const double c = KT_SQRT_PI / (12.0 * (1.0 - p->e * p->e));
  for (int32_t q = 0; q < a->Q; ++q) {
    double f = phi[q];
    double dg, g = kt_g0(p->radial, f, p->phi_max, p->delta, &dg);
    double fp, fg, fmu = kt_mu_shape(p->viscosity, p->e, f, g, &fp, &fg);
    double K = c * dp[q] * dp[q] * fmu / (g * f * f); /* theta = K shear_rate^2 */
    th[q] = K * gd[q] * gd[q];
    if (dth_dphi) dth_dphi[q] = th[q] * ((fp + fg * dg) / fmu - dg / g - 2.0 / f);
    if (dth_dgd) dth_dgd[q] = 2.0 * K * gd[q];
  }
  return SL_OK;
}

static const sl_closure_desc algebraic_theta = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_GRANULAR,
    .name = "algebraic_theta",
    .version = "1.0.0",
    .summary = "equilibrium granular temperature of homogeneous simple shear (production = dissipation)",
    .formula =
        "mu_s(theta) shear_rate^2 = gamma(theta), mu_s = rho_s d_p sqrt(theta) f_mu(phi, g0):\n"
        "theta = sqrt(pi) d_p^2 f_mu(phi, g0) shear_rate^2 / (12 (1 - e^2) g0 phi^2)\n"
        "f_mu, g0: those of granular/gidaspow (default) or granular/lun with the same parameters",
    .reference =
        "Syamlal, Rogers & O'Brien (1993) MFIX documentation; van Wachem et al. (2001) AIChE J 47:1035; "
        "Krampa (2009) eqs 6.8-6.19 (ANSYS CFX-10 algebraic equilibrium model), div u_s = 0",
    .validity =
        "homogeneous simple shear, local equilibrium (no convection, conduction or interphase exchange); "
        "e < 1; 1e-6 <= phi <= 0.74; theta grows like phi^-2 in dilute flow (no cap); the theta input is "
        "not used",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(at_params),
    .n_in = N_IN,
    .in = inputs,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = NULL,
    .evaluate = evaluate,
    .destroy = NULL,
};

static const sl_closure_desc *const all[] = {&algebraic_theta};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
