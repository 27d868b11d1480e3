/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Pringle (2001) solid ("granular component") pressure of a saturated sand,
 * from a logarithmic compressibility -d eps_v / dP_s = A / P_s:
 *   P_s = p_ref exp[ (1/A) (1 - (1 - nbar)/(1 - n)) ],   n = 1 - phi (porosity),
 * Pringle (2001) PhD thesis, McMaster University, eq 4.30 (consistent with
 * the derivation eqs 3.41-3.50), with A the
 * "flexibility" and nbar the reference porosity at which P_s = p_ref.
 * MISPRINT: eqs 3.51 and 3.54 print the ratio inverted,
 * exp[(1/A)(1 - (1-n)/(1-nbar))], which would make P_s fall under
 * compaction; the eq 4.30 form is used here. The thesis normalises
 * P_s(nbar) = 1 with units implied Pa: p_ref = 1 Pa by default.
 * In terms of phi = 1 - n:  P_s = p_ref exp[(1 - (1 - nbar)/phi) / A],
 *   dP_s/dphi = P_s (1 - nbar) / (A phi^2)   (= -dP_s/dn, eq 3.48).
 * P_s -> 0 as phi -> 0 (exactly 0 at phi = 0, with a zero derivative). */
#include <math.h>
#include <sluice/closure.h>

typedef struct pringle_exp_params {
  double flexibility; /* A */
  double nbar;        /* reference porosity */
  double p_ref;       /* P_s at n = nbar */
} pringle_exp_params;

enum { IN_PHI, N_IN };
enum { OUT_P_S, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(pringle_exp_params, flexibility, 0.015, 1e-4, 10.0, "1",
                     "flexibility A, -d eps_v/dP_s = A/P_s (thesis Figs 3.12-3.13: 0.015; illite: 0.1075)"),
    SL_PARAM_REAL_OF(pringle_exp_params, nbar, 0.5, 0.01, 0.99, "1",
                     "reference porosity nbar where P_s = p_ref (Figs 3.12-3.13: 0.5; illite: 0.95)"),
    SL_PARAM_REAL_OF(pringle_exp_params, p_ref, 1.0, 1e-12, 1e12, "Pa",
                     "P_s at n = nbar (the thesis normalises it to 1, in Pa)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.55, 0.0, 0.74, "solids volume fraction, 1 - porosity"},
};

static const sl_field_desc outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "solid (granular component) pressure"},
};

/* Eq 4.30 with A = 0.015, nbar = 0.5 (the values of Pringle's Figs 3.12-3.13),
 * to 3 significant figures. */
static const double check_in_0[N_IN] = {0.55}; /* n = 0.45 */
static const double check_in_1[N_IN] = {0.60}; /* n = 0.40 */
static const double check_in_2[N_IN] = {0.50}; /* n = nbar */
static const sl_check_point checks[] = {
    {check_in_0, OUT_P_S, 429.0, 2e-3, "Pringle (2001) eq 4.30, A = 0.015, nbar = 0.5: P_s = 429 at n = 0.45"},
    {check_in_1, OUT_P_S, 6.69e4, 2e-3, "Pringle (2001) eq 4.30, A = 0.015, nbar = 0.5: P_s = 6.69e4 at n = 0.40"},
    {check_in_2, OUT_P_S, 1.0, 1e-14, "Pringle (2001) eq 3.50 normalisation: P_s(nbar) = 1, exact"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const pringle_exp_params *p = state;
  const double *phi = a->in[IN_PHI];
  double *ps = a->out[OUT_P_S];
  double *dps_dphi = sl_dout(a, N_IN, OUT_P_S, IN_PHI);
  const double rbar = 1.0 - p->nbar; /* reference solids fraction */
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.74]", phi[q]);
    double v = 0.0, dv = 0.0;
    if (phi[q] > 0.0) {
      v = p->p_ref * exp((1.0 - rbar / phi[q]) / p->flexibility);
      /* v underflows to 0 long before phi^2 does: no 0 * inf. */
      dv = v > 0.0 ? v * rbar / (p->flexibility * phi[q] * phi[q]) : 0.0;
    }
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g: p_s overflows (A = %g, nbar = %g)", phi[q], p->flexibility,
                     p->nbar);
    ps[q] = v;
    if (dps_dphi) dps_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc pringle_exponential = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = "pringle_exponential",
    .version = "1.0.0",
    .summary = "Pringle (2001) exponential solid pressure of a saturated granular bed",
    .formula =
        "p_s = p_ref exp[(1/A) (1 - (1 - nbar)/(1 - n))],  n = 1 - phi,  A = flexibility = 0.015, nbar = 0.5\n"
        "dp_s/dphi = p_s (1 - nbar) / (A phi^2)",
    .reference = "Pringle (2001) PhD thesis, McMaster University, eq 4.30 (eqs 3.51/3.54 print the ratio inverted)",
    .validity =
        "0 <= phi <= 0.74; p_s -> 0 as phi -> 0; calibrated for sand (A = 0.015, nbar = 0.5) and illite "
        "(A = 0.1075, nbar = 0.95); nbar is a state variable in the thesis, a constant here",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(pringle_exp_params),
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

static const sl_closure_desc *const all[] = {&pringle_exponential};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
