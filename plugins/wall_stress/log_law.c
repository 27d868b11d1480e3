/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The standard wall function of Launder & Spalding (1974), Comput. Methods
 * Appl. Mech. Eng. 3:269, in the form of Krampa (2009) eqs 4.84-4.86: the
 * fluid's speed U at the first node off a smooth wall, at distance y, lies on
 * the log law
 *   U / u_tau = (1/kappa) ln(E y+),  y+ = rho u_tau y / mu,  tau_w = rho u_tau^2,
 * solved for u_tau by Newton; below the crossover y+_c of the log law with
 * the viscous sublayer (y+ = ln(E y+)/kappa, 11.5 for the defaults) the
 * sublayer's U+ = y+ holds, tau_w = mu U / y. The turbulence at the node:
 *   k = u_tau^2 / sqrt(C_mu),  epsilon = u_tau^3 / (kappa y).
 * E = 9.793 (Krampa 2009 eq 4.84, CFX-4's); kappa 0.41 (0.4187 is CFX-4's
 * pairing with E = 9.793). The law holds for y+ of about 30-200 (Krampa
 * 2009 section 2.9); a model warns outside it. A rough wall (sand-grain
 * height k_s = roughness) shifts the law down by
 *   Delta B = (1/kappa) ln(1 + C_s k_s+),  k_s+ = rho u_tau k_s / mu,
 * i.e. E becomes E/(1 + C_s k_s+) (Cebeci & Bradshaw 1977, Momentum Transfer
 * in Boundary Layers, their fully rough form; C_s = 0.5 for uniform sand
 * grains). */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"

typedef struct log_law_params {
  double kappa, e, c_mu, roughness, roughness_constant;
} log_law_params;

enum { IN_SLIP_WALL, IN_WALL_DISTANCE, IN_RHO_F, IN_MU_F, N_IN };
enum { OUT_TAU_W, OUT_U_TAU, OUT_Y_PLUS, OUT_K_WALL, OUT_EPS_WALL, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(log_law_params, kappa, 0.41, 0.3, 0.5, "1", "von Karman constant"),
    SL_PARAM_REAL_OF(log_law_params, e, 9.793, 1.0, 30.0, "1", "E of the smooth-wall log law"),
    SL_PARAM_REAL_OF(log_law_params, c_mu, 0.09, 1e-3, 1.0, "1", "C_mu of the k-epsilon model, in k at the wall node"),
    SL_PARAM_REAL_OF(log_law_params, roughness, 0.0, 0.0, 1.0, "m", "equivalent sand-grain roughness k_s (0: smooth)"),
    SL_PARAM_REAL_OF(log_law_params, roughness_constant, 0.5, 0.0, 10.0, "1",
                     "C_s of the roughness shift ln(1 + C_s k_s+)/kappa"),
};

static const sl_field_desc inputs[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 1e3, "the fluid's speed along the wall at the first node"},
    {"wall_distance", "m", 0, 1e-3, 1e-12, 10.0, "the node's distance from the wall"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "wall shear stress (magnitude, opposing the motion)"},
    {"u_tau", "m s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "friction velocity sqrt(tau_w/rho_f)"},
    {"y_plus", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "the node's distance in wall units"},
    {"k_wall", "m^2 s^-2", SL_FIELD_OPTIONAL, 0, 0, 0, "k at the node, u_tau^2/sqrt(C_mu)"},
    {"epsilon_wall", "m^2 s^-3", SL_FIELD_OPTIONAL, 0, 0, 0, "epsilon at the node, u_tau^3/(kappa y)"},
};

/* u_tau = 0.05 m/s, y = 1 mm in water (rho 1000, mu 1e-3): y+ = 50, U = 0.05 ln(9.793 * 50)/0.41. */
static const double check_log[N_IN] = {0.7553281524593665, 1e-3, 1000.0, 1e-3};
/* in the sublayer: U = 0.01 m/s at y = 0.1 mm, y+ = 1: tau = mu U / y = 0.1 Pa */
static const double check_lam[N_IN] = {0.01, 1e-4, 1000.0, 1e-3};
static const sl_check_point checks[] = {
    {check_log, OUT_TAU_W, 2.5, 1e-10,
     "log law U+ = ln(E y+)/kappa (Launder & Spalding 1974; Krampa 2009 eq 4.84) "
     "at y+ = 50, u_tau = 0.05 m/s, hand-evaluated"},
    {check_log, OUT_Y_PLUS, 50.0, 1e-10, "y+ = rho u_tau y/mu (Krampa 2009 eq 4.84)"},
    {check_log, OUT_K_WALL, 0.0025 / 0.3, 1e-10, "k = u_tau^2/sqrt(C_mu) (Krampa 2009 eq 4.85)"},
    {check_log, OUT_EPS_WALL, 1.25e-4 / 0.41e-3, 1e-10, "epsilon = u_tau^3/(kappa y) (Krampa 2009 eq 4.86)"},
    {check_lam, OUT_TAU_W, 0.1, 1e-12, "viscous sublayer U+ = y+: tau = mu U/y"},
};

/* y+_c: where the log law meets U+ = y+ (fixed point of y = ln(E y)/kappa, a contraction for y > 1/kappa). */
static double crossover(const log_law_params *p) {
  double y = 11.0;
  for (int i = 0; i < 60; ++i) y = log(p->e * y) / p->kappa;
  return y;
}

static int evaluate(const void *state, const sl_eval_args *a) {
  const log_law_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *U = a->in[IN_SLIP_WALL], *y = a->in[IN_WALL_DISTANCE], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F];
  double *dtau = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL);
  const double yc = crossover(p);
  for (int32_t q = 0; q < a->Q; ++q) {
    double nu = mu[q] / rho[q], u = U[q], h = y[q];
    double ut = sqrt(nu * u / h), dtau_du = mu[q] / h; /* the sublayer's */
    if (ut * h / nu > yc) {
      /* Newton on F(ut) = ut [ln(E h ut/nu) - ln(1 + C_s k_s ut/nu)] - kappa U from the sublayer's ut (the bracket
         grows with ut: one root), a step never more than to a tenth of ut */
      const double cr = p->roughness_constant * p->roughness / nu;
      double dF = 1.0;
      for (int it = 0; it < 200; ++it) {
        double L = log(p->e * h * ut / nu) - log1p(cr * ut), F = ut * L - p->kappa * u;
        dF = L + 1.0 - cr * ut / (1.0 + cr * ut);
        double next = dF > 0.0 ? ut - F / dF : 0.1 * ut;
        if (next < 0.1 * ut) next = 0.1 * ut;
        double step = ut - next;
        ut = next;
        if (fabs(step) <= 1e-15 * ut) break;
      }
      dF = log(p->e * h * ut / nu) - log1p(cr * ut) + 1.0 - cr * ut / (1.0 + cr * ut); /* kappa dU/dut */
      dtau_du = 2.0 * rho[q] * ut * p->kappa / dF;
    }
    double tau = rho[q] * ut * ut;
    if (!(ut >= 0.0) || !isfinite(tau))
      return sl_fail(a->err, SL_RECOVERABLE, q, "the log law has no root for U = %g", u);
    a->out[OUT_TAU_W][q] = tau;
    gr_set(dtau, q, dtau_du);
    gr_set(a->out[OUT_U_TAU], q, ut);
    gr_set(a->out[OUT_Y_PLUS], q, ut * h / nu);
    gr_set(a->out[OUT_K_WALL], q, ut * ut / sqrt(p->c_mu));
    gr_set(a->out[OUT_EPS_WALL], q, ut * ut * ut / (p->kappa * h));
    double ddu = dtau_du / (2.0 * rho[q] * (ut > 0.0 ? ut : 1.0)); /* d ut / dU */
    if (a->out[OUT_U_TAU]) gr_set(sl_dout(a, N_IN, OUT_U_TAU, IN_SLIP_WALL), q, ddu);
    if (a->out[OUT_Y_PLUS]) gr_set(sl_dout(a, N_IN, OUT_Y_PLUS, IN_SLIP_WALL), q, ddu * h / nu);
    if (a->out[OUT_K_WALL]) gr_set(sl_dout(a, N_IN, OUT_K_WALL, IN_SLIP_WALL), q, 2.0 * ut * ddu / sqrt(p->c_mu));
    if (a->out[OUT_EPS_WALL])
      gr_set(sl_dout(a, N_IN, OUT_EPS_WALL, IN_SLIP_WALL), q, 3.0 * ut * ut * ddu / (p->kappa * h));
  }
  return SL_OK;
}

static const sl_closure_desc log_law = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "log_law",
    .version = "1.0.0",
    .summary =
        "standard wall function (Launder & Spalding 1974): the fluid's wall shear stress from the smooth-wall "
        "log law, with k and epsilon at the wall node",
    .formula =
        "slip_wall/u_tau = ln(e y+/(1 + roughness_constant k_s+))/kappa, y+ = rho_f u_tau wall_distance/mu_f, "
        "k_s+ = rho_f u_tau roughness/mu_f (y+ above the crossover with "
        "U+ = y+; below it tau_w = mu_f slip_wall/wall_distance)\n"
        "tau_w = rho_f u_tau^2, k_wall = u_tau^2/sqrt(c_mu), epsilon_wall = u_tau^3/(kappa wall_distance)",
    .reference =
        "Launder & Spalding (1974) Comput. Methods Appl. Mech. Eng. 3:269; Krampa (2009) eqs 4.84-4.86; "
        "Cebeci & Bradshaw (1977) for the roughness",
    .validity =
        "a smooth wall with the first node in the log layer, y+ of about 30-200 (the sublayer's linear law "
        "below the crossover)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(log_law_params),
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

static const sl_closure_desc *const all[] = {&log_law};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
