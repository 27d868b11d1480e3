/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Regularised Herschel & Bulkley (1926) viscoplastic viscosity,
 *   tau = tau0 + K shear_rate^n (yielded),  mu = tau0/shear_rate + K shear_rate^(n-1),
 * Herschel & Bulkley (1926) Kolloid-Z. 39:291. Regularised with the same
 * options as the bingham closure (yield_regularisation.h):
 *   bercovier_engelman  mu = tau0 / r + K r^(n-1),             r = sqrt(shear_rate^2 + eps^2)
 *                       i.e. (tau0 + K r^n)/r, the Bercovier & Engelman (1980) form
 *   papanastasiou       mu = tau0 (1 - exp(-m shear_rate))/shear_rate + K r^(n-1)
 *                       (the Papanastasiou-regularised Herschel-Bulkley law,
 *                        e.g. Mitsoulis 2007, Rheology Reviews 135)
 * In both forms the power-law part uses r, so that it stays bounded at rest
 * for shear-thinning n < 1 (K eps^(n-1) at shear_rate = 0); for n = 1 it is
 * exactly K and the closure reduces to bingham with mu_p = K. The derivative
 * d mu / d shear_rate is returned for a consistent Newton Jacobian. */
#include <math.h>
#include <sluice/closure.h>

#include "yield_regularisation.h"

typedef struct herschel_bulkley_params {
  double consistency;     /* K, Pa s^n */
  double flow_index;      /* n */
  double yield_stress;    /* tau0 */
  int32_t regularisation; /* 0 bercovier_engelman, 1 papanastasiou */
  double eps;             /* s^-1 */
  double m;               /* s */
} herschel_bulkley_params;

enum { IN_SHEAR_RATE, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(herschel_bulkley_params, consistency, 1.0, 0.0, 1e8, "Pa s^n", "consistency K"),
    SL_PARAM_REAL_OF(herschel_bulkley_params, flow_index, 0.5, 0.05, 3.0, "1",
                     "flow index n (< 1 shear-thinning, 1 Bingham, > 1 shear-thickening)"),
    SL_PARAM_REAL_OF(herschel_bulkley_params, yield_stress, 10.0, 0.0, 1e8, "Pa", "yield stress tau0"),
    SL_PARAM_ENUM_OF(herschel_bulkley_params, regularisation, SL_REG_BERCOVIER_ENGELMAN, SL_REG_CHOICES,
                     "bercovier_engelman: tau0/sqrt(g^2+eps^2); papanastasiou: tau0 (1-exp(-m g))/g"),
    SL_PARAM_REAL_OF(herschel_bulkley_params, eps, 1e-3, 1e-12, 1e6, "s^-1",
                     "regularisation shear rate: yield term (bercovier_engelman) and power-law term (both forms)"),
    SL_PARAM_REAL_OF(herschel_bulkley_params, m, 1e3, 1e-6, 1e8, "s", "Papanastasiou exponent m"),
};

static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 10.0, 0.0, HUGE_VAL, "shear-rate magnitude sqrt(2 D:D)"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "apparent dynamic viscosity"},
};

/* Defaults K = 1, n = 0.5, tau0 = 10, Bercovier-Engelman eps = 1e-3.
 * At rest: tau0/eps + K eps^(n-1) = 1e4 + 1e-3^-0.5 exactly. At 100 s^-1
 * the unregularised law gives tau0/100 + 100^-0.5 = 0.2, which the
 * regularised one matches to 4e-11 relative. */
static const double check_in_0[N_IN] = {0.0};
static const double check_in_1[N_IN] = {100.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 10031.622776601684, 1e-14,
     "exact: tau0/eps + K eps^(n-1) at shear_rate = 0 (Bercovier & Engelman form)"},
    {check_in_1, OUT_VISCOSITY, 0.2, 1e-10,
     "Herschel & Bulkley (1926) limit tau0/g + K g^(n-1) at 100 s^-1 (regularisation error 4e-11)"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const herschel_bulkley_params *p = state;
  const double *g = a->in[IN_SHEAR_RATE];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dg = sl_dout(a, N_IN, OUT_VISCOSITY, IN_SHEAR_RATE);
  const double n = p->flow_index;
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(g[q] >= 0.0 && g[q] < HUGE_VAL))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g is not a finite rate >= 0", g[q]);
    double y, dy;
    sl_yield_term(p->regularisation, p->yield_stress, p->eps, p->m, g[q], &y, &dy);
    double r = hypot(g[q], p->eps);
    double pl = p->consistency * pow(r, n - 1.0);
    /* d/dg r^(n-1) = (n-1) r^(n-2) g/r. */
    double dpl = (n - 1.0) * pl * (g[q] / r) / r;
    double v = y + pl, dv = dy + dpl;
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g: the power-law term K r^(n-1) overflows", g[q]);
    visc[q] = v;
    if (dvisc_dg) dvisc_dg[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc herschel_bulkley = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "herschel_bulkley",
    .version = "1.0.0",
    .summary = "Regularised Herschel-Bulkley viscoplastic viscosity",
    .formula =
        "r = sqrt(shear_rate^2 + eps^2)\n"
        "bercovier_engelman: viscosity = tau0 / r + K r^(n-1)\n"
        "papanastasiou:      viscosity = tau0 (1 - exp(-m shear_rate)) / shear_rate + K r^(n-1)  "
        "(tau0 m + K eps^(n-1) at 0)",
    .reference =
        "Herschel & Bulkley (1926) Kolloid-Z. 39:291; Bercovier & Engelman (1980) J. Comput. Phys. 36:313; "
        "Papanastasiou (1987) J. Rheol. 31:385",
    .validity =
        "shear_rate >= 0; unyielded regions are represented as a very viscous fluid, exact only as "
        "eps -> 0 (and m -> infinity)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(herschel_bulkley_params),
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

static const sl_closure_desc *const all[] = {&herschel_bulkley};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
