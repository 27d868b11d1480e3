/* SPDX-License-Identifier: MIT */
/* An out-of-tree closure: a power-law (Ostwald-de Waele) fluid,
 *   viscosity = consistency * shear_rate^(n - 1),
 * with the shear rate floored at `min_shear_rate` so the viscosity stays
 * finite at rest. Build it against an installed sluice (see CMakeLists.txt),
 * put the folder on SLUICE_PLUGIN_PATH, and use it by name:
 *   [closure.viscosity]
 *   model = my_power_law
 *   consistency = 0.5
 *   n = 0.6 */
#include <math.h>
#include <sluice/closure.h>

typedef struct power_law_params {
  double consistency;    /* Pa s^n */
  double n;              /* flow index */
  double min_shear_rate; /* s^-1 */
} power_law_params;

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(power_law_params, consistency, 1.0, 0.0, 1e6, "Pa s^n", "consistency index"),
    SL_PARAM_REAL_OF(power_law_params, n, 0.5, 0.05, 2.0, "1", "flow index: < 1 shear-thinning"),
    SL_PARAM_REAL_OF(power_law_params, min_shear_rate, 1e-3, 1e-12, 1.0, "s^-1", "shear rate floor"),
};

static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 1.0, 0.0, 1e8, "shear-rate magnitude"},
};
static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity"},
};

/* consistency 1, n 0.5, shear rate 4: 1 * 4^-0.5 = 0.5 exactly. */
static const double check_in[] = {4.0};
static const sl_check_point checks[] = {{check_in, 0, 0.5, 1e-14, "exact: 4^-0.5"}};

static int evaluate(const void *state, const sl_eval_args *a) {
  const power_law_params *p = state;
  const double *g = a->in[0];
  double *mu = a->out[0];
  double *dmu = sl_dout(a, 1, 0, 0);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(g[q] >= 0.0 && g[q] <= 1e8))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g outside [0, 1e8]", g[q]);
    double gf = g[q] > p->min_shear_rate ? g[q] : p->min_shear_rate;
    mu[q] = p->consistency * pow(gf, p->n - 1.0);
    if (dmu) dmu[q] = g[q] > p->min_shear_rate ? (p->n - 1.0) * mu[q] / gf : 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc power_law = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "my_power_law",
    .version = "1.0.0",
    .summary = "power-law fluid (example of an out-of-tree closure)",
    .formula = "viscosity = consistency * max(shear_rate, min_shear_rate)^(n - 1)",
    .reference = "Ostwald (1925); de Waele (1923)",
    .validity = "0 <= shear_rate <= 1e8 s^-1",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(power_law_params),
    .n_in = SL_COUNT_OF(inputs),
    .in = inputs,
    .n_out = SL_COUNT_OF(outputs),
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .evaluate = evaluate,
};

static const sl_closure_desc *const all[] = {&power_law};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
