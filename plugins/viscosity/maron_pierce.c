/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Maron & Pierce (1956) viscosity of a concentrated suspension,
 *   mu = mu_f (1 - phi/phi_max)^(-2),
 * Maron & Pierce (1956) J. Colloid Sci. 11:80 (the form given by the
 * Ree-Eyring analysis with a fitted maximum packing); the Krieger-Dougherty
 * law with [eta] phi_max = 2. Its first-order slope is 2/phi_max, which is the
 * Einstein 2.5 only for phi_max = 0.8: with the default phi_max = 0.68 the
 * dilute limit is mu_f (1 + 2.94 phi), not Einstein's. The law diverges at
 * phi = phi_max (recoverable code there). */
#include <math.h>
#include <sluice/closure.h>

typedef struct maron_pierce_params {
  double phi_max; /* 0.68 */
} maron_pierce_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(maron_pierce_params, phi_max, 0.68, 0.3, 0.8, "1",
                     "maximum packing fraction (fitted; 0.8 gives the Einstein slope 2.5)"),
};

/* Declared phi range: that of the default phi_max; 0 <= phi < phi_max is accepted. */
static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.68, "solids volume fraction, 0 <= phi < phi_max"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity of the suspension"},
};

/* No tabulated value in the project's sources: at phi = phi_max / 2 the
 * relative viscosity is exactly (1/2)^-2 = 4. */
static const double check_in_0[N_IN] = {0.34, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 4e-3, 1e-13, "exact: mu_f (1 - 1/2)^-2 = 4 mu_f at phi = phi_max/2 = 0.34"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const maron_pierce_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= 0.0 && phi[q] < p->phi_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, phi_max = %g): maron_pierce diverges at phi_max",
                     phi[q], p->phi_max);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    double x = 1.0 - phi[q] / p->phi_max; /* in (0, 1] */
    double v = mu[q] / (x * x);
    double dv = 2.0 * v / (x * p->phi_max);
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %.17g too close to phi_max = %g: the viscosity overflows",
                     phi[q], p->phi_max);
    visc[q] = v;
    if (dvisc_dphi) dvisc_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc maron_pierce = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "maron_pierce",
    .version = "1.0.0",
    .summary = "Maron & Pierce (1956) concentrated-suspension viscosity",
    .formula = "viscosity = mu_f (1 - phi/phi_max)^-2,  phi_max = 0.68",
    .reference = "Maron & Pierce (1956) J. Colloid Sci. 11:80",
    .validity =
        "0 <= phi < phi_max; diverges at phi_max (recoverable code there); dilute slope 2/phi_max "
        "(Einstein's 2.5 only when phi_max = 0.8)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(maron_pierce_params),
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

static const sl_closure_desc *const all[] = {&maron_pierce};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
