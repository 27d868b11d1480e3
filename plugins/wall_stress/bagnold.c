/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Bagnold (1954) solids wall shear stress, in the form used for slurry pipe
 * walls by Shook & Bartosik (1994) and Krampa (2009) eqs 2.7-2.9:
 *   macro-viscous  (N < 40):   tau_w = k_v mu_f lambda^1.5 (dU/dy)_w,      k_v = 2.25
 *   grain-inertia  (N > 450):  tau_w = k_i rho_s (lambda d_p)^2 (dU/dy)_w^2, k_i = 0.013
 *   Bagnold number N = rho_s lambda^0.5 d_p^2 (dU/dy)_w / mu_f
 *   linear concentration lambda = 1 / ((phi_max/phi)^(1/3) - 1)
 * Bagnold (1954) Proc. R. Soc. Lond. A 225:49-63 (shear stress T = 2.2-2.25
 * lambda^1.5 eta dU/dy and T = 0.013 sigma (lambda D)^2 (dU/dy)^2 for his wax
 * spheres; maximum static concentration C_0 = 0.74). Krampa (2009) p. 22
 * states the two coefficients the wrong way round ("K_i and K_v ... 2.25 and
 * 0.013 respectively"): k_v = 2.25, k_i = 0.013.
 *
 * Wall shear rate: a wall function, (dU/dy)_w = slip_wall / wall_distance,
 * the tangential solids velocity at the first node off the wall over its
 * distance from the wall (Krampa computes the solids gradient at the wall
 * node; Shook & Bartosik assumed it equal to the liquid's).
 *
 * regime = auto chooses by N: macro-viscous for N <= 40, grain-inertia for
 * N >= 450, and in Bagnold's transition 40 < N < 450 the geometric
 * interpolation in ln N,
 *   tau_w = tau_mv^(1 - w) tau_gi^w,   w = ln(N/40) / ln(450/40),
 * which is continuous (C0) at both ends with a kink there (the two laws cross
 * at N = k_v/k_i = 173, inside the transition). regime = macro_viscous or
 * grain_inertia imposes one law everywhere.
 *
 * lambda is continued by its tangent line above phi_max - delta
 * (linear_concentration.h), so tau_w stays finite for phi >= phi_max. phi is
 * not differentiable: d lambda/d phi ~ phi^(-2/3) is unbounded at phi = 0.
 * tau_w is the magnitude of the stress the wall exerts on the solids,
 * opposing the slip. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "wall_stress/linear_concentration.h"

typedef struct bagnold_params {
  double k_v, k_i, phi_max, delta;
  int32_t regime; /* 0 auto, 1 grain_inertia, 2 macro_viscous */
} bagnold_params;

enum { REGIME_AUTO, REGIME_GRAIN_INERTIA, REGIME_MACRO_VISCOUS };
#define N_VISCOUS 40.0
#define N_INERTIAL 450.0

enum { IN_SLIP_WALL, IN_PHI, IN_RHO_S, IN_MU_F, IN_D_P, IN_WALL_DISTANCE, N_IN };
enum { OUT_TAU_W, OUT_BAGNOLD_NUMBER, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(bagnold_params, k_v, 2.25, 0.0, 100.0, "1", "macro-viscous coefficient (Bagnold 1954: 2.25)"),
    SL_PARAM_REAL_OF(bagnold_params, k_i, 0.013, 0.0, 10.0, "1", "grain-inertia coefficient (Bagnold 1954: 0.013)"),
    SL_PARAM_REAL_OF(bagnold_params, phi_max, 0.74, 0.3, 0.74, "1",
                     "maximum static concentration in lambda (Bagnold 1954: 0.74; Krampa 2009: 0.63)"),
    SL_PARAM_REAL_OF(bagnold_params, delta, 0.01, 1e-4, 0.1, "1",
                     "lambda is continued by its tangent line above phi_max - delta (C1, finite)"),
    SL_PARAM_ENUM_OF(bagnold_params, regime, REGIME_AUTO, "auto|grain_inertia|macro_viscous",
                     "auto: by the Bagnold number (< 40 macro-viscous, > 450 grain-inertia, log blend between)"),
};

static const sl_field_desc inputs[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential solids speed at the first node off the wall"},
    {"phi", "1", 0, 0.3, 0.0, 0.74, "solids volume fraction at the wall node"},
    {"rho_s", "kg m^-3", 0, 2650.0, 1.0, 1e5, "solid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 5e-4, 1e-8, 1.0, "particle diameter"},
    {"wall_distance", "m", 0, 1e-3, 1e-9, 10.0, "distance of the wall node from the wall"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "solids wall shear stress (magnitude, opposing the slip)"},
    {"bagnold_number", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "Bagnold number rho_s lambda^0.5 d_p^2 (dU/dy)_w / mu_f"},
};

/* lambda = 1 at phi = phi_max/8 = 0.0925 (default phi_max 0.74). With
 * rho_s = 2650, d_p = 1e-3, mu_f = 1e-3, wall_distance = 1e-3:
 * slip 1e-3 m/s gives dU/dy = 1 s^-1 and N = 2.65 (macro-viscous);
 * slip 1 m/s gives dU/dy = 1000 s^-1 and N = 2650 (grain-inertia). */
static const double check_mv[N_IN] = {1e-3, 0.74 / 8.0, 2650.0, 1e-3, 1e-3, 1e-3};
static const double check_gi[N_IN] = {1.0, 0.74 / 8.0, 2650.0, 1e-3, 1e-3, 1e-3};
static const sl_check_point checks[] = {
    {check_mv, OUT_TAU_W, 2.25e-3, 1e-12,
     "Bagnold (1954) macro-viscous 2.25 lambda^1.5 mu dU/dy with lambda = 1, mu = 1e-3, dU/dy = 1"},
    {check_mv, OUT_BAGNOLD_NUMBER, 2.65, 1e-12, "Bagnold (1954) N = sigma lambda^0.5 D^2 (dU/dy)/eta, hand-evaluated"},
    {check_gi, OUT_TAU_W, 0.013 * 2650.0, 1e-12,
     "Bagnold (1954) grain-inertia 0.013 sigma (lambda D)^2 (dU/dy)^2 with lambda = 1, D = 1e-3, dU/dy = 1000"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const bagnold_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *u = a->in[IN_SLIP_WALL], *phi = a->in[IN_PHI], *rho = a->in[IN_RHO_S], *mu = a->in[IN_MU_F],
               *dp = a->in[IN_D_P], *h = a->in[IN_WALL_DISTANCE];
  double *tau = a->out[OUT_TAU_W], *bn = a->out[OUT_BAGNOLD_NUMBER];
  double *dtau = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL);
  double *dbn = bn ? sl_dout(a, N_IN, OUT_BAGNOLD_NUMBER, IN_SLIP_WALL) : NULL;
  const double ln_span = log(N_INERTIAL / N_VISCOUS);
  for (int32_t q = 0; q < a->Q; ++q) {
    double lam = ws_lambda(phi[q], p->phi_max, p->delta);
    double sl = sqrt(lam), ld = lam * dp[q];
    double gd = u[q] / h[q];
    double n_per_gd = rho[q] * sl * dp[q] * dp[q] / mu[q]; /* N / (dU/dy) */
    double N = n_per_gd * gd;
    double mv_per_gd = p->k_v * mu[q] * lam * sl;  /* tau_mv / (dU/dy) */
    double gi_per_gd2 = p->k_i * rho[q] * ld * ld; /* tau_gi / (dU/dy)^2 */
    int regime = p->regime;
    if (regime == REGIME_AUTO)
      regime = N <= N_VISCOUS ? REGIME_MACRO_VISCOUS : N >= N_INERTIAL ? REGIME_GRAIN_INERTIA : -1;
    double t, dt_dgd;
    if (regime == REGIME_MACRO_VISCOUS) {
      t = mv_per_gd * gd;
      dt_dgd = mv_per_gd;
    } else if (regime == REGIME_GRAIN_INERTIA) {
      t = gi_per_gd2 * gd * gd;
      dt_dgd = 2.0 * gi_per_gd2 * gd;
    } else { /* transition: N > 40, so gd > 0 and lambda > 0 */
      double t_mv = mv_per_gd * gd, t_gi = gi_per_gd2 * gd * gd;
      double w = log(N / N_VISCOUS) / ln_span, lr = log(t_gi / t_mv);
      t = exp((1.0 - w) * log(t_mv) + w * log(t_gi));
      /* d ln t / d ln gd = (1 - w) + 2 w + ln(t_gi/t_mv) dw/d ln gd */
      dt_dgd = t / gd * (1.0 + w + lr / ln_span);
    }
    tau[q] = t;
    if (dtau) dtau[q] = dt_dgd / h[q];
    gr_set(bn, q, N);
    gr_set(dbn, q, n_per_gd / h[q]);
  }
  return SL_OK;
}

static const sl_closure_desc bagnold = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "bagnold",
    .version = "1.0.0",
    .summary = "Bagnold (1954) solids wall shear stress, macro-viscous / grain-inertia by the Bagnold number",
    .formula =
        "gd = slip_wall / wall_distance, lambda = 1/((phi_max/phi)^(1/3) - 1) (tangent line above phi_max - delta)\n"
        "N = rho_s lambda^0.5 d_p^2 gd / mu_f\n"
        "macro-viscous: tau_w = k_v mu_f lambda^1.5 gd; grain-inertia: tau_w = k_i rho_s (lambda d_p)^2 gd^2\n"
        "auto: macro-viscous N <= 40, grain-inertia N >= 450, tau_mv^(1-w) tau_gi^w with "
        "w = ln(N/40)/ln(450/40) between",
    .reference =
        "Bagnold (1954) Proc. R. Soc. Lond. A 225:49; Shook & Bartosik (1994) Powder Technol. 81:117; "
        "Krampa (2009) eqs 2.7-2.9 (K_i, K_v swapped in the text)",
    .validity =
        "neutrally buoyant or slightly heavy spheres sheared in a Newtonian liquid; N < 40 macro-viscous, "
        "N > 450 grain-inertia; auto mode is C0 with kinks at N = 40 and 450; 0 <= phi <= 0.74 (lambda "
        "continued above phi_max - delta); wall_distance > 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(bagnold_params),
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

static const sl_closure_desc *const all[] = {&bagnold};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
