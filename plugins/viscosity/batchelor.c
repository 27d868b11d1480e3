/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Batchelor (1977) viscosity of a semi-dilute suspension of rigid spheres,
 *   mu = mu_f (1 + 2.5 phi + 6.2 phi^2),
 * Batchelor (1977) J. Fluid Mech. 83:97 (the result stated in the abstract,
 * for a steady pure straining motion with Brownian motion dominant). For
 * non-Brownian spheres values from 5.2 to 7.6 are quoted, after Batchelor &
 * Green (1972) J. Fluid Mech. 56:401; the coefficient is therefore a
 * parameter. First order: the Einstein limit 1 + 2.5 phi. */
#include <math.h>
#include <sluice/closure.h>

typedef struct batchelor_params {
  double intrinsic_viscosity; /* 2.5 */
  double quadratic;           /* 6.2 */
} batchelor_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(batchelor_params, intrinsic_viscosity, 2.5, 0.0, 100.0, "1",
                     "first-order (Einstein) coefficient [eta], 2.5 for spheres"),
    SL_PARAM_REAL_OF(
        batchelor_params, quadratic, 6.2, 0.0, 100.0, "1",
        "second-order coefficient: 6.2 (Batchelor 1977, Brownian); 5.2-7.6 quoted for non-Brownian spheres"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.05, 0.0, 0.2, "solids volume fraction (semi-dilute: phi <= 0.2)"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity of the suspension"},
};

/* 1 + 0.25 + 6.2 * 0.01 = 1.312 at phi = 0.1. */
static const double check_in_0[N_IN] = {0.1, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 1.312e-3, 1e-14,
     "Batchelor (1977) abstract: 1 + 2.5 phi + 6.2 phi^2 at phi = 0.1, exact"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const batchelor_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside the semi-dilute range [0, 0.2] of batchelor", phi[q]);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    double c1 = p->intrinsic_viscosity, c2 = p->quadratic;
    visc[q] = mu[q] * (1.0 + phi[q] * (c1 + c2 * phi[q]));
    if (dvisc_dphi) dvisc_dphi[q] = mu[q] * (c1 + 2.0 * c2 * phi[q]);
  }
  return SL_OK;
}

static const sl_closure_desc batchelor = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "batchelor",
    .version = "1.0.0",
    .summary = "Batchelor (1977) O(phi^2) suspension viscosity",
    .formula = "viscosity = mu_f (1 + [eta] phi + c2 phi^2),  [eta] = 2.5, c2 = quadratic = 6.2",
    .reference = "Batchelor (1977) J. Fluid Mech. 83:97 (abstract); Batchelor & Green (1972) J. Fluid Mech. 56:401",
    .validity =
        "semi-dilute suspensions of rigid spheres, pair interactions only: 0 <= phi <= 0.2 "
        "(accurate below about 0.1)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(batchelor_params),
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

static const sl_closure_desc *const all[] = {&batchelor};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
