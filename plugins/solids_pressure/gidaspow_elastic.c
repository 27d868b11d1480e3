/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Solids pressure from the Gidaspow "solids elastic modulus" (Bouillard,
 * Lyczkowski & Gidaspow 1989; Gidaspow 1994):
 *   G(phi) = dp_s/dphi = G0 exp(C (phi - phi_max)),
 * used in two-fluid models to keep the solids fraction below packing. The
 * closure returns the pressure, the integral of G from phi = 0:
 *   p_s = (G0/C) [exp(C (phi - phi_max)) - exp(-C phi_max)],
 * so that p_s(0) = 0 and dp_s/dphi = G exactly (the zero is a choice: the
 * second term is e^-374 with the defaults, i.e. p_s = (G0/C) e^{C(phi-phi_max)}
 * to all digits for phi of practical interest).
 * Constants: G0 = 1 Pa, C = 600, phi_max = 1 - 0.376 = 0.624 (compaction
 * gas fraction 0.376), as commonly quoted for Bouillard et al. (1989). Other
 * sets are in use (e.g. the power-of-ten fits G = 10^(a eps_g + b) of
 * Gidaspow & Ettehadieh 1983); all three constants are parameters. The
 * law has no validity edge below phi = 0.74 other than overflow. */
#include <float.h>
#include <math.h>
#include <sluice/closure.h>

typedef struct gidaspow_elastic_params {
  double modulus_ref; /* G0, Pa */
  double compaction;  /* C */
  double phi_max;     /* where G = G0 */
} gidaspow_elastic_params;

enum { IN_PHI, N_IN };
enum { OUT_P_S, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(gidaspow_elastic_params, modulus_ref, 1.0, 1e-12, 1e12, "Pa", "reference modulus G0 = G(phi_max)"),
    SL_PARAM_REAL_OF(gidaspow_elastic_params, compaction, 600.0, 1.0, 1e4, "1", "compaction modulus C"),
    SL_PARAM_REAL_OF(gidaspow_elastic_params, phi_max, 0.624, 0.3, 0.74, "1",
                     "solids fraction where G = G0 (1 - compaction gas fraction 0.376)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.6, 0.0, 0.74, "solids volume fraction"},
};

static const sl_field_desc outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "solids pressure, integral of G from phi = 0 (dp_s/dphi = G)"},
};

/* No tabulated value in the project's sources: at phi = phi_max the
 * pressure is exactly (G0/C)(1 - e^{-C phi_max}) = 1/600 Pa to all digits. */
static const double check_in_0[N_IN] = {0.624};
static const sl_check_point checks[] = {
    {check_in_0, OUT_P_S, 1.0 / 600.0, 1e-13, "exact: p_s(phi_max) = (G0/C)(1 - exp(-C phi_max)) = 1/600 Pa"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const gidaspow_elastic_params *p = state;
  const double *phi = a->in[IN_PHI];
  double *ps = a->out[OUT_P_S];
  double *dps_dphi = sl_dout(a, N_IN, OUT_P_S, IN_PHI);
  const double C = p->compaction, g0 = p->modulus_ref;
  const double base = exp(-C * p->phi_max); /* e^{-C phi_max}; may underflow to 0 */
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.74]", phi[q]);
    double e = exp(C * (phi[q] - p->phi_max)); /* G / G0 */
    double x = C * phi[q];
    /* e - base = base (e^x - 1): the expm1 form keeps the relative accuracy
     * near phi = 0; the plain difference where base underflows or e^x would
     * overflow. */
    double v = (base > DBL_MIN && x < 700.0) ? g0 / C * base * expm1(x) : g0 / C * (e - base);
    double dv = g0 * e;
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g: p_s overflows (C = %g, phi_max = %g)", phi[q], C,
                     p->phi_max);
    ps[q] = v;
    if (dps_dphi) dps_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc gidaspow_elastic = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = "gidaspow_elastic",
    .version = "1.0.0",
    .summary = "Solids pressure integrated from the Gidaspow elastic modulus G0 exp(C (phi - phi_max))",
    .formula =
        "G = dp_s/dphi = G0 exp(C (phi - phi_max)),  G0 = 1 Pa, C = 600, phi_max = 0.624\n"
        "p_s = (G0/C) [exp(C (phi - phi_max)) - exp(-C phi_max)]  (p_s(0) = 0)",
    .reference =
        "Bouillard, Lyczkowski & Gidaspow (1989) AIChE J. 35:908; Gidaspow (1994) Multiphase Flow and "
        "Fluidization, Academic Press",
    .validity =
        "0 <= phi <= 0.74; an empirical stabilising modulus, not a constitutive law of the packed bed; "
        "constants fitted for gas-fluidised beds",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(gidaspow_elastic_params),
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

static const sl_closure_desc *const all[] = {&gidaspow_elastic};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
