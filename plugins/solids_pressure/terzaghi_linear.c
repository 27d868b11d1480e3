/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A linear solids pressure of the volumetric strain from a reference
 * state, Terzaghi's (1925) soil of constant compressibility m_v = 1/M:
 *   p_s = M max(0, 1 - (1 - nbar)/phi),   n = 1 - phi,
 * the volumetric strain 1 - phibar/phi of the skeleton from the solids
 * fraction phibar = 1 - nbar at which it carries nothing (no tension). The
 * small-strain limit of Pringle's (2001) eq 4.30 about a state of pressure
 * p: eq 4.30 gives dP_s = (P_s/A) d(1 - phibar/phi), so M = p/A there.
 * With it the consolidation coefficient c_v = M phibar (1 - phi)^2/(phi K)
 * of the two-fluid column is constant for a nearly uniform deposit, and
 * Terzaghi's series solution is exact for the linearised problem (the
 * verification of configs/terzaghi_consolidation.ini).
 *   dp_s/dphi = M (1 - nbar)/phi^2 (phi > 1 - nbar), 0 below. */
#include <math.h>
#include <sluice/closure.h>

typedef struct terzaghi_params {
  double modulus; /* M */
} terzaghi_params;

enum { IN_PHI, IN_NBAR, N_IN };
enum { OUT_P_S, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(terzaghi_params, modulus, 1e7, 1.0, 1e12, "Pa", "constrained modulus M = 1/m_v"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.56, 0.0, 0.99, "solids volume fraction, 1 - porosity"},
    {"nbar", "1", 0, 0.45, 0.01, 0.99, "the porosity at which the skeleton carries nothing"},
};

static const sl_field_desc outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "solids (effective) pressure"},
};

static const double check_in_0[N_IN] = {0.55, 0.45}; /* unloaded */
static const double check_in_1[N_IN] = {0.56, 0.45}; /* 1 - 0.55/0.56 = 1/56 */
static const double check_in_2[N_IN] = {0.50, 0.45}; /* looser than the reference: no tension */
static const sl_check_point checks[] = {
    {check_in_0, OUT_P_S, 0.0, 1e-15, "phi = 1 - nbar: p_s = 0"},
    {check_in_1, OUT_P_S, 1e7 / 56.0, 1e-14, "p_s = M (1 - 0.55/0.56) = 1e7/56, by hand"},
    {check_in_2, OUT_P_S, 0.0, 1e-15, "phi < 1 - nbar: p_s = 0"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const terzaghi_params *p = state;
  const double *phi = a->in[IN_PHI], *nbar = a->in[IN_NBAR];
  double *ps = a->out[OUT_P_S];
  double *d = sl_dout(a, N_IN, OUT_P_S, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.99]", phi[q]);
    if (!(nbar[q] >= inputs[IN_NBAR].valid_min && nbar[q] <= inputs[IN_NBAR].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "nbar = %g outside [0.01, 0.99]", nbar[q]);
    double rbar = 1.0 - nbar[q], e = phi[q] > rbar ? 1.0 - rbar / phi[q] : 0.0;
    ps[q] = p->modulus * e;
    if (d) d[q] = phi[q] > rbar ? p->modulus * rbar / (phi[q] * phi[q]) : 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc terzaghi_linear = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = "terzaghi_linear",
    .version = "1.0.0",
    .summary = "Terzaghi's (1925) linear skeleton: p_s = M x volumetric strain from phibar = 1 - nbar, no tension",
    .formula = "p_s = M max(0, 1 - (1 - nbar)/phi)\ndp_s/dphi = M (1 - nbar)/phi^2 for phi > 1 - nbar, else 0",
    .reference =
        "Terzaghi (1925) Erdbaumechanik, Deuticke, Vienna (constant m_v); the small-strain limit of Pringle "
        "(2001) eq 4.30, M = P_s/A",
    .validity = "small strains (a linear skeleton); 0 <= phi <= 0.99, 0.01 <= nbar <= 0.99",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(terzaghi_params),
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

static const sl_closure_desc *const all[] = {&terzaghi_linear};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
