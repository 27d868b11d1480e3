/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The standard k-epsilon model of Launder & Spalding (1974), Comput. Methods
 * Appl. Mech. Eng. 3:269, as its pointwise laws: the eddy viscosity and the
 * coefficients of the two transport equations a model solves,
 *
 *   d(rho k)/dt + ... = div((mu + mu_t/sigma_k) grad k) + P_k - rho eps
 *   d(rho eps)/dt + ... = div((mu + mu_t/sigma_eps) grad eps) + C_eps1 (eps/k) P_k - C_eps2 rho eps^2/k
 *   mu_t = C_mu rho k^2 / eps
 *
 * with the constants of Launder & Spalding (1974), which are those of
 * Krampa (2009) Table 4.1 (C_mu 0.09, C_eps1 1.44, C_eps2 1.92, sigma_k 1.0,
 * sigma_eps 1.3). The outputs are what a model multiplies: mu_t, the two
 * turbulent diffusivities mu_t/sigma, the factor C_eps1 eps/k on the
 * production in the epsilon equation and the sink coefficient
 * C_eps2 rho eps/k (times eps: the destruction), and C_mu for the model's
 * wall function. A model that phase-weights the equations (Krampa 2009 eqs
 * 4.82-4.83: c_f times each term) multiplies them by c_f itself. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"

typedef struct ke_params {
  double c_mu, c_eps1, c_eps2, sigma_k, sigma_eps;
} ke_params;

enum { IN_K, IN_EPS, IN_RHO_F, N_IN };
enum { OUT_MU_T, OUT_MU_T_K, OUT_MU_T_EPS, OUT_EPS_PRODUCTION, OUT_EPS_SINK, OUT_C_MU, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(ke_params, c_mu, 0.09, 1e-3, 1.0, "1", "C_mu of the eddy viscosity"),
    SL_PARAM_REAL_OF(ke_params, c_eps1, 1.44, 0.1, 5.0, "1", "C_eps1, on the production in the epsilon equation"),
    SL_PARAM_REAL_OF(ke_params, c_eps2, 1.92, 0.1, 5.0, "1", "C_eps2, on the destruction in the epsilon equation"),
    SL_PARAM_REAL_OF(ke_params, sigma_k, 1.0, 0.1, 10.0, "1", "turbulent Prandtl number of k"),
    SL_PARAM_REAL_OF(ke_params, sigma_eps, 1.3, 0.1, 10.0, "1", "turbulent Prandtl number of epsilon"),
};

static const sl_field_desc inputs[] = {
    {"k", "m^2 s^-2", SL_FIELD_DIFF, 1e-2, 1e-30, 1e6, "turbulent kinetic energy"},
    {"epsilon", "m^2 s^-3", SL_FIELD_DIFF, 1e-1, 1e-30, 1e9, "its dissipation rate"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
};

static const sl_field_desc outputs[] = {
    {"mu_t", "Pa s", 0, 0, 0, 0, "eddy viscosity C_mu rho k^2/eps"},
    {"mu_t_k", "Pa s", SL_FIELD_OPTIONAL, 0, 0, 0, "turbulent diffusivity of k, mu_t/sigma_k"},
    {"mu_t_eps", "Pa s", SL_FIELD_OPTIONAL, 0, 0, 0, "turbulent diffusivity of epsilon, mu_t/sigma_eps"},
    {"eps_production", "s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "C_eps1 eps/k: the epsilon source per unit P_k"},
    {"eps_sink", "kg m^-3 s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "C_eps2 rho eps/k: the destruction over eps"},
    {"c_mu", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "C_mu (for the wall function's k and epsilon)"},
};

/* k = 1, eps = 0.09, rho = 1: mu_t = 0.09 * 1 / 0.09 = 1 exactly; eps_sink = 1.92 * 0.09. */
static const double check_unit[N_IN] = {1.0, 0.09, 1.0};
static const double check_water[N_IN] = {0.02, 0.5, 998.0};
static const sl_check_point checks[] = {
    {check_unit, OUT_MU_T, 1.0, 1e-14, "Launder & Spalding (1974): C_mu rho k^2/eps = 0.09 * 1/0.09"},
    {check_unit, OUT_EPS_SINK, 1.92 * 0.09, 1e-14, "Launder & Spalding (1974): C_eps2 rho eps/k"},
    {check_water, OUT_MU_T_EPS, 0.09 * 998.0 * 4e-4 / 0.5 / 1.3, 1e-14,
     "Launder & Spalding (1974) with sigma_eps = 1.3 (Krampa 2009 Table 4.1), hand-evaluated"},
    {check_water, OUT_EPS_PRODUCTION, 1.44 * 0.5 / 0.02, 1e-14, "C_eps1 eps/k, Krampa (2009) eq 4.83"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const ke_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *k = a->in[IN_K], *e = a->in[IN_EPS], *rho = a->in[IN_RHO_F];
  const double inv_sig[3] = {1.0, 1.0 / p->sigma_k, 1.0 / p->sigma_eps};
  for (int32_t q = 0; q < a->Q; ++q) {
    double mu = p->c_mu * rho[q] * k[q] * k[q] / e[q];
    double dk = 2.0 * mu / k[q], de = -mu / e[q];
    for (int o = OUT_MU_T; o <= OUT_MU_T_EPS; ++o) {
      gr_set(a->out[o], q, mu * inv_sig[o]);
      if (a->out[o]) {
        gr_set(sl_dout(a, N_IN, o, IN_K), q, dk * inv_sig[o]);
        gr_set(sl_dout(a, N_IN, o, IN_EPS), q, de * inv_sig[o]);
      }
    }
    if (a->out[OUT_EPS_PRODUCTION]) {
      a->out[OUT_EPS_PRODUCTION][q] = p->c_eps1 * e[q] / k[q];
      gr_set(sl_dout(a, N_IN, OUT_EPS_PRODUCTION, IN_K), q, -p->c_eps1 * e[q] / (k[q] * k[q]));
      gr_set(sl_dout(a, N_IN, OUT_EPS_PRODUCTION, IN_EPS), q, p->c_eps1 / k[q]);
    }
    if (a->out[OUT_EPS_SINK]) {
      a->out[OUT_EPS_SINK][q] = p->c_eps2 * rho[q] * e[q] / k[q];
      gr_set(sl_dout(a, N_IN, OUT_EPS_SINK, IN_K), q, -p->c_eps2 * rho[q] * e[q] / (k[q] * k[q]));
      gr_set(sl_dout(a, N_IN, OUT_EPS_SINK, IN_EPS), q, p->c_eps2 * rho[q] / k[q]);
    }
    if (a->out[OUT_C_MU]) {
      a->out[OUT_C_MU][q] = p->c_mu;
      gr_set(sl_dout(a, N_IN, OUT_C_MU, IN_K), q, 0.0);
      gr_set(sl_dout(a, N_IN, OUT_C_MU, IN_EPS), q, 0.0);
    }
  }
  return SL_OK;
}

static const sl_closure_desc k_epsilon = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_TURBULENCE,
    .name = "k_epsilon",
    .version = "1.0.0",
    .summary =
        "standard k-epsilon model (Launder & Spalding 1974): eddy viscosity and the coefficients of the k and "
        "epsilon equations",
    .formula =
        "mu_t = c_mu rho_f k^2/epsilon, mu_t_k = mu_t/sigma_k, mu_t_eps = mu_t/sigma_eps\n"
        "eps_production = c_eps1 epsilon/k (times P_k), eps_sink = c_eps2 rho_f epsilon/k (times epsilon)",
    .reference =
        "Launder & Spalding (1974) Comput. Methods Appl. Mech. Eng. 3:269; Krampa (2009) eqs 4.74-4.83, "
        "Table 4.1",
    .validity =
        "fully turbulent flow away from walls (high Reynolds number form: a model bridges the wall with a "
        "wall function); k > 0, epsilon > 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(ke_params),
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

static const sl_closure_desc *const all[] = {&k_epsilon};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
