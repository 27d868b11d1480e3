/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Simonin's (1996, VKI Lecture Series 1996-02) modulation of the fluid's
 * turbulence by the particles, Krampa's (2009) model C (eqs 4.80-4.83): per
 * unit volume the fluid's k equation gains
 *   c_f rho_f Pi_kf = K [k_fs - 2 k + (u_f - u_s) . U_d]     (eq 4.80)
 * with K = c_s rho_s/t_p the drag's coefficient (eq 4.58) and U_d the drift
 * velocity of eq 4.81, and the drift work (K/rho_f) mu_t grad(c_f) . (u_f -
 * u_s) (eq 4.82); the epsilon equation gains C_eps3 (eps/k) times both (eq
 * 4.83, with Elghobashi & Abou-Arab's 1983 sign: the same as in k). The closure
 * gives the exchange coefficient A = K of those brackets and C_eps3 (Krampa
 * Table 4.1: 1.2); the covariance k_fs, the drift velocity and the gradients
 * are the host's. */
#include <sluice/closure.h>

#include "granular/inputs.h"

typedef struct simonin_params {
  double c_eps3;
} simonin_params;

enum { IN_DRAG, N_IN };
enum { OUT_EXCHANGE, OUT_C_EPS3, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(simonin_params, c_eps3, 1.2, 0.0, 10.0, "1",
                     "C_eps3 of the epsilon equation's C_eps3 (eps/k) times the k modulation (Krampa 2009 Table "
                     "4.1: 1.2)"),
};

static const sl_field_desc inputs[] = {
    {"drag_coefficient", "kg m^-3 s^-1", SL_FIELD_DIFF, 1e3, 0.0, 1e12,
     "the drag's K = c_s rho_s/t_p (Krampa 2009 eq 4.58)"},
};

static const sl_field_desc outputs[] = {
    {"exchange", "kg m^-3 s^-1", 0, 0, 0, 0, "the exchange coefficient A of c_f rho_f Pi_kf: K"},
    {"c_eps3", "1", 0, 0, 0, 0, "C_eps3 of the epsilon equation's modulation"},
};

static const double check_in_0[N_IN] = {1500.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_EXCHANGE, 1500.0, 1e-15, "Simonin (1996); Krampa (2009) eq 4.80: A = c_s rho_s/t_p = K"},
    {check_in_0, OUT_C_EPS3, 1.2, 1e-15, "Krampa (2009) Table 4.1: C_eps3 = 1.2"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const simonin_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *K = a->in[IN_DRAG];
  double *dA = sl_dout(a, N_IN, OUT_EXCHANGE, IN_DRAG), *dC = sl_dout(a, N_IN, OUT_C_EPS3, IN_DRAG);
  for (int32_t q = 0; q < a->Q; ++q) {
    a->out[OUT_EXCHANGE][q] = K[q], a->out[OUT_C_EPS3][q] = p->c_eps3;
    gr_set(dA, q, 1.0), gr_set(dC, q, 0.0);
  }
  return SL_OK;
}

static const sl_closure_desc simonin = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_TURBULENCE_MODULATION,
    .name = "simonin",
    .version = "1.0.0",
    .summary = "Simonin's modulation of the fluid's k and epsilon by the drag (Krampa's model C)",
    .formula = "exchange = K (c_f rho_f Pi_kf = exchange [k_fs - 2 k + (u_f - u_s).U_d]), c_eps3 = c_eps3",
    .reference =
        "Simonin (1996) VKI Lecture Series 1996-02; Krampa (2009) eqs 4.80-4.83, Table 4.1; Elghobashi & "
        "Abou-Arab (1983) Phys. Fluids 26:931",
    .validity = "particles smaller than the energetic eddies (the two-fluid averaging); any K >= 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(simonin_params),
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

static const sl_closure_desc *const all[] = {&simonin};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
