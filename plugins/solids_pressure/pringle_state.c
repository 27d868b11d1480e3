/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Pringle (2001) solid ("granular component") pressure with its reference
 * porosity a state variable of the sand:
 *   P_s = p_ref exp[ (1/A) (1 - (1 - nbar)/(1 - n)) ],   n = 1 - phi,
 * Pringle (2001) PhD thesis, McMaster University, eq 4.30 (the derivation is
 * eqs 3.41-3.50; eqs 3.51/3.54 print the ratio inverted). nbar is "a state
 * variable": the same grains may sit at different porosities under the same
 * confining pressure (thesis section 3.3); a densification law
 * ([closure.densification]) lowers it under cyclic shear. This is the law of
 * solids_pressure/pringle_exponential with nbar an input instead of a
 * parameter:
 *   dP_s/dphi = P_s (1 - nbar) / (A phi^2).
 * Lowering nbar at fixed phi lowers P_s: the undrained load transfer to the
 * fluid that is liquefaction (thesis Figure 3.14). */
#include <math.h>
#include <sluice/closure.h>

typedef struct pringle_state_params {
  double flexibility; /* A */
  double p_ref;       /* P_s at n = nbar */
} pringle_state_params;

enum { IN_PHI, IN_NBAR, N_IN };
enum { OUT_P_S, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(pringle_state_params, flexibility, 0.015, 1e-4, 10.0, "1",
                     "flexibility A, -d eps_v/dP_s = A/P_s (thesis Figs 3.12-3.13: 0.015; illite: 0.1075)"),
    SL_PARAM_REAL_OF(pringle_state_params, p_ref, 1.0, 1e-12, 1e12, "Pa",
                     "P_s at n = nbar (the thesis normalises it to 1, in Pa)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.55, 0.0, 0.74, "solids volume fraction, 1 - porosity"},
    {"nbar", "1", 0, 0.5, 0.01, 0.99, "reference porosity, where P_s = p_ref (a state of the sand)"},
};

static const sl_field_desc outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "solid (granular component) pressure"},
};

/* Pringle (2001) eq 4.30 with A = 0.015, nbar = 0.5, to 3 significant figures. */
static const double check_in_0[N_IN] = {0.55, 0.5};  /* n = 0.45, A = 0.015 */
static const double check_in_1[N_IN] = {0.60, 0.5};  /* n = 0.40 */
static const double check_in_2[N_IN] = {0.50, 0.5};  /* n = nbar */
static const double check_in_3[N_IN] = {0.70, 0.75}; /* phi/(1 - nbar) = 2.8: exp((1 - 1/2.8)/0.015) */
static const sl_check_point checks[] = {
    {check_in_0, OUT_P_S, 429.0, 2e-3, "Pringle (2001) eq 4.30, A = 0.015, nbar = 0.5: P_s = 429 at n = 0.45"},
    {check_in_1, OUT_P_S, 6.69e4, 2e-3, "Pringle (2001) eq 4.30, A = 0.015, nbar = 0.5: P_s = 6.69e4 at n = 0.40"},
    {check_in_2, OUT_P_S, 1.0, 1e-14, "Pringle (2001) eq 3.50 normalisation: P_s(nbar) = 1, exact"},
    {check_in_3, OUT_P_S, 4.0984595e18, 1e-7, "eq 4.30 at n = 0.3, nbar = 0.75: exp((1 - 0.25/0.7)/0.015), by hand"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const pringle_state_params *p = state;
  const double *phi = a->in[IN_PHI], *nbar = a->in[IN_NBAR];
  double *ps = a->out[OUT_P_S];
  double *dps_dphi = sl_dout(a, N_IN, OUT_P_S, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.74]", phi[q]);
    if (!(nbar[q] >= inputs[IN_NBAR].valid_min && nbar[q] <= inputs[IN_NBAR].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "nbar = %g outside [0.01, 0.99]", nbar[q]);
    const double rbar = 1.0 - nbar[q]; /* reference solids fraction */
    double v = 0.0, dv = 0.0;
    if (phi[q] > 0.0) {
      v = p->p_ref * exp((1.0 - rbar / phi[q]) / p->flexibility);
      dv = v > 0.0 ? v * rbar / (p->flexibility * phi[q] * phi[q]) : 0.0; /* v underflows before phi^2 */
    }
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g: p_s overflows (A = %g, nbar = %g)", phi[q], p->flexibility,
                     nbar[q]);
    ps[q] = v;
    if (dps_dphi) dps_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc pringle_state = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = "pringle_state",
    .version = "1.0.0",
    .summary = "Pringle (2001) exponential solid pressure with the reference porosity nbar a state of the sand",
    .formula =
        "p_s = p_ref exp[(1/A) (1 - (1 - nbar)/(1 - n))],  n = 1 - phi,  A = flexibility = 0.015\n"
        "dp_s/dphi = p_s (1 - nbar) / (A phi^2)",
    .reference = "Pringle (2001) PhD thesis, McMaster University, eq 4.30 (eqs 3.51/3.54 print the ratio inverted)",
    .validity =
        "0 <= phi <= 0.74, 0.01 <= nbar <= 0.99; p_s -> 0 as phi -> 0; nbar is supplied by the model (a "
        "state that [closure.densification] evolves)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(pringle_state_params),
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

static const sl_closure_desc *const all[] = {&pringle_state};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
