/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Krieger & Dougherty (1959) viscosity of a concentrated suspension,
 *   mu = mu_f (1 - phi/phi_max)^(-[eta] phi_max),
 * Krieger & Dougherty (1959) Trans. Soc. Rheol. 3:137; the form used by
 * Nigam (1999) eq 2.18 with phi_max = 0.68 and [eta] = 2.5 (K = 2.6765 in its migration runs, [eta] phi_max = 1.82).
 * First order: mu_f (1 + [eta] phi), the Einstein limit for [eta] = 2.5.
 * The law diverges at phi = phi_max: phi >= phi_max is refused with the
 * recoverable code so that the host can cut the step. */
#include <math.h>
#include <sluice/closure.h>

typedef struct kd_params {
  double phi_max;             /* 0.68 */
  double intrinsic_viscosity; /* 2.5 */
} kd_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(kd_params, phi_max, 0.68, 0.3, 0.74, "1",
                     "maximum packing fraction, where the viscosity diverges (Nigam 1999: 0.68)"),
    SL_PARAM_REAL_OF(kd_params, intrinsic_viscosity, 2.5, 0.1, 100.0, "1",
                     "intrinsic viscosity [eta]: 2.5 for spheres (Einstein limit)"),
};

/* The declared phi range is that of the default phi_max; the closure accepts
 * 0 <= phi < phi_max for any phi_max (the ABI has no parameter-dependent range). */
static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.68, "solids volume fraction, 0 <= phi < phi_max"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity of the suspension"},
};

/* Nigam (1999) eq 2.18: mu(alpha) for K = 2.5, alpha_m = 0.68, to 5
 * significant figures. */
static const double check_in_0[N_IN] = {0.10, 1e-3};
static const double check_in_1[N_IN] = {0.30, 1e-3};
static const double check_in_2[N_IN] = {0.50, 1e-3};
static const double check_in_3[N_IN] = {0.60, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 1.3105e-3, 1e-4, "Nigam (1999) eq 2.18, K = 2.5: mu = 1.3105 at alpha = 0.10"},
    {check_in_1, OUT_VISCOSITY, 2.6893e-3, 1e-4, "Nigam (1999) eq 2.18, K = 2.5: mu = 2.6893 at alpha = 0.30"},
    {check_in_2, OUT_VISCOSITY, 9.5786e-3, 1e-4, "Nigam (1999) eq 2.18, K = 2.5: mu = 9.5786 at alpha = 0.50"},
    {check_in_3, OUT_VISCOSITY, 38.020e-3, 1e-4, "Nigam (1999) eq 2.18, K = 2.5: mu = 38.020 at alpha = 0.60"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const kd_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  const double expo = p->intrinsic_viscosity * p->phi_max;
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= 0.0 && phi[q] < p->phi_max))
      return sl_fail(a->err, SL_RECOVERABLE, q,
                     "phi = %g outside [0, phi_max = %g): krieger_dougherty diverges at phi_max", phi[q], p->phi_max);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    double x = 1.0 - phi[q] / p->phi_max; /* in (0, 1] */
    double v = mu[q] * pow(x, -expo);
    /* d/dphi x^(-e) = e x^(-e-1) / phi_max, so dmu/dphi = mu [eta] / x. */
    double dv = v * p->intrinsic_viscosity / x;
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %.17g too close to phi_max = %g: the viscosity overflows",
                     phi[q], p->phi_max);
    visc[q] = v;
    if (dvisc_dphi) dvisc_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc krieger_dougherty = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "krieger_dougherty",
    .version = "1.0.0",
    .summary = "Krieger & Dougherty (1959) concentrated-suspension viscosity",
    .formula = "viscosity = mu_f (1 - phi/phi_max)^(-[eta] phi_max),  phi_max = 0.68, [eta] = 2.5",
    .reference = "Krieger & Dougherty (1959) Trans. Soc. Rheol. 3:137; Nigam (1999) MIT PhD thesis eq 2.18",
    .validity = "0 <= phi < phi_max; diverges at phi_max (recoverable code there); Einstein limit for small phi",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(kd_params),
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

static const sl_closure_desc *const all[] = {&krieger_dougherty};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
