/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Pringle (2001) mixture viscosity of a fluidised sand, a modified Mooney
 * (1951) double exponential fitted to Brookfield measurements in a fluidised
 * bed of Barnes sand (three gradings, one fit):
 *   mu_m / mu_l = exp{ exp[ phi / (k1 + k2 phi) ] },  k1 = 1.1721, k2 = -1.7172,
 * Pringle (2001) PhD thesis, McMaster University, eqs 3.36-3.37 (R^2 = 0.9724;
 * eqs 3.36-3.37), with phi = eps_s = 1 - n the solids
 * fraction and mu_l the liquid viscosity (input mu_f).
 * Caveats:
 *  - as phi -> 0 the fit tends to e = 2.718 mu_l, NOT to mu_l: it has no
 *    Einstein limit and must not be used below the measured range (which the
 *    thesis does not state numerically; the figures are lost);
 *  - it diverges at phi = k1/|k2| = 0.6826;
 *  - it holds only in the Newtonian range phi <= 0.5 (above, the measured
 *    mixture is strongly shear-thinning), so phi > 0.5 is refused;
 *  - the constants are for this sand only. */
#include <math.h>
#include <sluice/closure.h>

typedef struct pringle_granular_params {
  double k1; /* 1.1721 */
  double k2; /* -1.7172 */
} pringle_granular_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(pringle_granular_params, k1, 1.1721, 1e-3, 100.0, "1",
                     "fit constant k1 of 1/ln(ln(mu_m/mu_l)) = k1/phi + k2 (Barnes sand: 1.1721)"),
    SL_PARAM_REAL_OF(pringle_granular_params, k2, -1.7172, -100.0, 100.0, "1",
                     "fit constant k2 (Barnes sand: -1.7172); k1 + k2 phi must stay > 0"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.5, "solids volume fraction eps_s = 1 - n (Newtonian range phi <= 0.5)"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "liquid dynamic viscosity mu_l"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "mixture dynamic viscosity mu_m"},
};

/* The correlation (Pringle 2001, eqs 3.36-3.37) to 3 significant figures. */
static const double check_in_0[N_IN] = {0.10, 1e-3};
static const double check_in_1[N_IN] = {0.40, 1e-3};
static const double check_in_2[N_IN] = {0.50, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 3.02e-3, 2e-3, "Pringle (2001) eqs 3.36-3.37: mu_m/mu_l = 3.02 at eps_s = 0.10"},
    {check_in_1, OUT_VISCOSITY, 9.78e-3, 1e-3, "Pringle (2001) eqs 3.36-3.37: mu_m/mu_l = 9.78 at eps_s = 0.40"},
    {check_in_2, OUT_VISCOSITY, 138e-3, 4e-3, "Pringle (2001) eqs 3.36-3.37: mu_m/mu_l = 138 at eps_s = 0.50"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const pringle_granular_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside the Newtonian range [0, 0.5] of pringle_granular",
                     phi[q]);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    double den = p->k1 + p->k2 * phi[q];
    if (!(den > 0.0))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g at or beyond the divergence k1 + k2 phi = 0 (k1 %g, k2 %g)",
                     phi[q], p->k1, p->k2);
    double g = phi[q] / den;
    double eg = exp(g);
    double v = mu[q] * exp(eg);
    /* d/dphi [phi/(k1 + k2 phi)] = k1/(k1 + k2 phi)^2. */
    double dv = v * eg * p->k1 / (den * den);
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g too close to the divergence k1/|k2|: the viscosity overflows",
                     phi[q]);
    visc[q] = v;
    if (dvisc_dphi) dvisc_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc pringle_granular = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "pringle_granular",
    .version = "1.0.0",
    .summary = "Pringle (2001) double-exponential viscosity of fluidised sand",
    .formula =
        "viscosity = mu_f exp(exp(phi / (k1 + k2 phi))),  k1 = 1.1721, k2 = -1.7172\n"
        "(tends to e mu_f, not mu_f, as phi -> 0; diverges at phi = k1/|k2| = 0.6826)",
    .reference = "Pringle (2001) PhD thesis, McMaster University, eqs 3.36-3.37 (modified Mooney 1951 form)",
    .validity =
        "fluidised Barnes sand in water, Newtonian range 0 <= phi <= 0.5; no Einstein limit "
        "(mu -> 2.718 mu_f at phi -> 0): do not use below the measured range",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(pringle_granular_params),
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

static const sl_closure_desc *const all[] = {&pringle_granular};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
