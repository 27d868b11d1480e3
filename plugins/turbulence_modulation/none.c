/* SPDX-License-Identifier: GPL-2.0-or-later */
/* No modulation of the fluid's turbulence by the particles: the phase-weighted
 * single-phase k-epsilon of Krampa's (2009) models A and B ("no additional
 * source or sink terms are present in the phasic turbulent transport
 * equations", his section 5.1; digest section 1.4). The exchange coefficient
 * and C_eps3 are zero, so that every modulation and drift-work term vanishes. */
#include <sluice/closure.h>

#include "granular/inputs.h"

enum { IN_DRAG, N_IN };
enum { OUT_EXCHANGE, OUT_C_EPS3, N_OUT };

static const sl_field_desc inputs[] = {
    {"drag_coefficient", "kg m^-3 s^-1", 0, 1e3, 0.0, 1e12, "the drag's K (does not enter)"},
};

static const sl_field_desc outputs[] = {
    {"exchange", "kg m^-3 s^-1", 0, 0, 0, 0, "the exchange coefficient A of c_f rho_f Pi_kf: 0"},
    {"c_eps3", "1", 0, 0, 0, 0, "C_eps3 of the epsilon equation's modulation: 0"},
};

static const double check_in_0[N_IN] = {1500.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_EXCHANGE, 0.0, 1e-15, "Krampa (2009) models A and B: no modulation terms"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  (void)state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  for (int32_t q = 0; q < a->Q; ++q) a->out[OUT_EXCHANGE][q] = 0.0, a->out[OUT_C_EPS3][q] = 0.0;
  return SL_OK;
}

static const sl_closure_desc none = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_TURBULENCE_MODULATION,
    .name = "none",
    .version = "1.0.0",
    .summary = "no modulation of the fluid's turbulence by the particles (Krampa's models A and B)",
    .formula = "exchange = 0, c_eps3 = 0",
    .reference = "Krampa (2009) section 5.1 (models A and B)",
    .validity = "dilute or fine suspensions whose particles leave the fluid's turbulence as it is",
    .n_params = 0,
    .params = NULL,
    .params_size = 0,
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

static const sl_closure_desc *const all[] = {&none};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
