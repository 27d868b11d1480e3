/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Einstein (1906, 1911) viscosity of a dilute suspension of rigid spheres,
 *   mu = mu_f (1 + 2.5 phi),
 * Einstein (1906) Ann. Phys. 19:289, with the arithmetic error corrected in
 * Einstein (1911) Ann. Phys. 34:591 (the coefficient 2.5). It is the first
 * term of every suspension law in this folder (the "Einstein limit"); the
 * coefficient is the intrinsic viscosity [eta] of spheres, exposed as a
 * parameter for other particle shapes. Valid only for dilute suspensions:
 * the declared range stops at phi = 0.1, beyond which particle interactions
 * (Batchelor 1977, Krieger-Dougherty) matter. */
#include <math.h>
#include <sluice/closure.h>

typedef struct einstein_params {
  double intrinsic_viscosity; /* [eta] = 2.5 for spheres */
} einstein_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(einstein_params, intrinsic_viscosity, 2.5, 0.0, 100.0, "1",
                     "intrinsic viscosity [eta]: 2.5 for rigid spheres (Einstein 1911)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.02, 0.0, 0.1, "solids volume fraction (dilute: phi <= 0.1)"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity of the suspension"},
};

/* The law itself at a round point: 1 + 2.5 * 0.05 = 1.125. */
static const double check_in_0[N_IN] = {0.05, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 1.125e-3, 1e-14, "Einstein (1911): mu_f (1 + 2.5 phi) at phi = 0.05, exact"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const einstein_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    /* Written as negated ranges so that NaN inputs fail too. */
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside the dilute range [0, 0.1] of einstein", phi[q]);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    visc[q] = mu[q] * (1.0 + p->intrinsic_viscosity * phi[q]);
    if (dvisc_dphi) dvisc_dphi[q] = mu[q] * p->intrinsic_viscosity;
  }
  return SL_OK;
}

static const sl_closure_desc einstein = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "einstein",
    .version = "1.0.0",
    .summary = "Einstein (1906, 1911) dilute-suspension viscosity",
    .formula = "viscosity = mu_f (1 + [eta] phi),  [eta] = intrinsic_viscosity = 2.5 for spheres",
    .reference = "Einstein (1906) Ann. Phys. 19:289; Einstein (1911) Ann. Phys. 34:591 (corrected coefficient 2.5)",
    .validity =
        "dilute suspensions of rigid spheres, no interactions: 0 <= phi <= 0.1 (accurate below about 0.02-0.05)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(einstein_params),
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

static const sl_closure_desc *const all[] = {&einstein};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
