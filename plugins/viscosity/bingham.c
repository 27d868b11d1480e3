/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Regularised Bingham (1922) viscoplastic viscosity,
 *   tau = tau0 + mu_p shear_rate (yielded),  mu = mu_p + tau0/shear_rate,
 * which is unbounded at shear_rate = 0 and is therefore regularised:
 *   bercovier_engelman  mu = mu_p + tau0 / sqrt(shear_rate^2 + eps^2)
 *                       (Bercovier & Engelman 1980, J. Comput. Phys. 36:313;
 *                        the form used by Lalli 1993, eq 0.10)
 *   papanastasiou       mu = mu_p + tau0 (1 - exp(-m shear_rate)) / shear_rate
 *                       (Papanastasiou 1987, J. Rheol. 31:385), with the exact
 *                       limit mu_p + tau0 m at shear_rate = 0.
 * Both tend to the Bingham law as eps -> 0 or m -> infinity: the error at a
 * fixed shear rate is -tau0 eps^2/(2 shear_rate^3) + O(eps^4) (Bercovier-
 * Engelman) and -tau0 exp(-m shear_rate)/shear_rate (Papanastasiou). The
 * derivative d mu / d shear_rate is returned for a consistent Newton
 * Jacobian. shear_rate = sqrt(2 D:D). */
#include <math.h>
#include <sluice/closure.h>

#include "yield_regularisation.h"

typedef struct bingham_params {
  double plastic_viscosity; /* mu_p */
  double yield_stress;      /* tau0 */
  int32_t regularisation;   /* 0 bercovier_engelman, 1 papanastasiou */
  double eps;               /* s^-1 */
  double m;                 /* s */
} bingham_params;

enum { IN_SHEAR_RATE, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(bingham_params, plastic_viscosity, 0.1, 0.0, 1e8, "Pa s", "plastic viscosity mu_p"),
    SL_PARAM_REAL_OF(bingham_params, yield_stress, 10.0, 0.0, 1e8, "Pa", "yield stress tau0"),
    SL_PARAM_ENUM_OF(bingham_params, regularisation, SL_REG_BERCOVIER_ENGELMAN, SL_REG_CHOICES,
                     "bercovier_engelman: tau0/sqrt(g^2+eps^2); papanastasiou: tau0 (1-exp(-m g))/g"),
    SL_PARAM_REAL_OF(bingham_params, eps, 1e-3, 1e-12, 1e6, "s^-1",
                     "Bercovier-Engelman regularisation shear rate (viscosity at rest mu_p + tau0/eps)"),
    SL_PARAM_REAL_OF(bingham_params, m, 1e3, 1e-6, 1e8, "s",
                     "Papanastasiou exponent m (viscosity at rest mu_p + tau0 m)"),
};

static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 10.0, 0.0, HUGE_VAL, "shear-rate magnitude sqrt(2 D:D)"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "apparent dynamic viscosity"},
};

/* Defaults: mu_p = 0.1, tau0 = 10, Bercovier-Engelman with eps = 1e-3.
 * At rest the regularised law gives mu_p + tau0/eps exactly; at 100 s^-1 it
 * equals the unregularised Bingham law mu_p + tau0/100 = 0.2 to within
 * tau0 eps^2/(2 g^3) = 5e-12 Pa s (relative 2.5e-11). */
static const double check_in_0[N_IN] = {0.0};
static const double check_in_1[N_IN] = {100.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 0.1 + 10.0 / 1e-3, 1e-14,
     "exact: mu_p + tau0/eps at shear_rate = 0 (Bercovier & Engelman 1980)"},
    {check_in_1, OUT_VISCOSITY, 0.2, 1e-10,
     "Bingham (1922) limit mu_p + tau0/shear_rate at 100 s^-1 (regularisation error 2.5e-11)"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const bingham_params *p = state;
  const double *g = a->in[IN_SHEAR_RATE];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dg = sl_dout(a, N_IN, OUT_VISCOSITY, IN_SHEAR_RATE);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(g[q] >= 0.0 && g[q] < HUGE_VAL))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g is not a finite rate >= 0", g[q]);
    double y, dy;
    sl_yield_term(p->regularisation, p->yield_stress, p->eps, p->m, g[q], &y, &dy);
    visc[q] = p->plastic_viscosity + y;
    if (dvisc_dg) dvisc_dg[q] = dy;
  }
  return SL_OK;
}

static const sl_closure_desc bingham = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "bingham",
    .version = "1.0.0",
    .summary = "Regularised Bingham viscoplastic viscosity",
    .formula =
        "bercovier_engelman: viscosity = mu_p + tau0 / sqrt(shear_rate^2 + eps^2)\n"
        "papanastasiou:      viscosity = mu_p + tau0 (1 - exp(-m shear_rate)) / shear_rate  (mu_p + tau0 m at 0)",
    .reference =
        "Bingham (1922) Fluidity and Plasticity; Bercovier & Engelman (1980) J. Comput. Phys. 36:313; "
        "Papanastasiou (1987) J. Rheol. 31:385",
    .validity =
        "shear_rate >= 0; unyielded regions (stress below tau0) are represented as a very viscous fluid, "
        "exact only as eps -> 0 or m -> infinity",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(bingham_params),
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

static const sl_closure_desc *const all[] = {&bingham};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
