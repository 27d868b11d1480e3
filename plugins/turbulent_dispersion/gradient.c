/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The gradient form of the turbulent dispersion of the solids: the turbulent
 * solids flux <c_s'' u_f''> = -(nu_t/sigma) grad(c_s) (Krampa 2009 eq 4.59,
 * Schmidt number 1; the favre-averaged drag of Burns et al. 2004, Proc. 5th
 * Int. Conf. Multiphase Flow, paper 392: F_TD = -K (nu_t/sigma) (grad c_s/c_s
 * - grad c_f/c_f)), as the dispersivity D_t = nu_t/sigma. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/inputs.h"

typedef struct gradient_params {
  double schmidt;
} gradient_params;

enum { IN_NU_T, N_IN };
enum { OUT_D_T, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(gradient_params, schmidt, 1.0, 1e-3, 1e3, "1",
                     "the turbulent Schmidt number sigma of the solids (Krampa 2009 eq 4.59: 1)"),
};

static const sl_field_desc inputs[] = {
    {"nu_t", "m^2 s^-1", SL_FIELD_DIFF, 1e-4, 0.0, 1e6, "the fluid's eddy viscosity mu_t/rho_f"},
};

static const sl_field_desc outputs[] = {
    {"D_t", "m^2 s^-1", 0, 0, 0, 0, "the solids' turbulent dispersivity nu_t/sigma"},
};

static const double check_in_0[N_IN] = {2.5e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_D_T, 2.5e-3, 1e-15, "Krampa (2009) eq 4.59: Schmidt number 1, D_t = nu_t"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const gradient_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *nu = a->in[IN_NU_T];
  double *D = a->out[OUT_D_T], *dD = sl_dout(a, N_IN, OUT_D_T, IN_NU_T);
  for (int32_t q = 0; q < a->Q; ++q) {
    D[q] = nu[q] / p->schmidt;
    gr_set(dD, q, 1.0 / p->schmidt);
  }
  return SL_OK;
}

static const sl_closure_desc gradient = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_TURBULENT_DISPERSION,
    .name = "gradient",
    .version = "1.0.0",
    .summary = "gradient-transport dispersion of the solids by the fluid's eddies, D_t = nu_t/sigma",
    .formula = "D_t = nu_t / schmidt",
    .reference = "Krampa (2009) eq 4.59; Burns et al. (2004) Proc. 5th Int. Conf. Multiphase Flow, paper 392",
    .validity = "solids that follow the fluid's eddies (t_p small against the eddies' time); any nu_t >= 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(gradient_params),
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

static const sl_closure_desc *const all[] = {&gradient};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
