/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Navier partial slip for the solids phase with the slip lengths of Ding &
 * Gidaspow (1990) and Ding & Lyczkowski (1992): the slip condition of
 * Eldighidy et al. (1977), u_s|w = lambda_slip (du_s/dn)|w, written as the
 * wall shear stress that closes it,
 *   tau_w = mu_eff slip_wall / lambda_slip = mu_eff slip_wall * inverse_slip_length,
 * Krampa (2009) eqs 4.87-4.91 (conditions "DG90" and "DL92"):
 *   navier_slip_ding_gidaspow    lambda_slip = d_p / phi^(1/3)
 *     (the mean distance between particle centres: phi (4 pi/3)(lambda/2)^3 = (pi/6) d_p^3)
 *   navier_slip_ding_lyczkowski  lambda_slip = (sqrt(3 pi)/24) d_p / (phi g0)
 *     (kinetic theory; g0 by default Lun & Savage with phi_max = 0.63, eq 4.91)
 *
 * Which viscosity: the slip condition is on the solids velocity, so the
 * stress it transmits is the solids-phase effective viscosity times the wall
 * gradient. The host supplies no solids viscosity field (no input name), so
 * mu_eff is a parameter (default 0.25 Pa s, Krampa's constant solids viscosity
 * of model A); the optional output inverse_slip_length = 1/lambda_slip lets
 * the host impose the Robin condition mu_s du_s/dn = (mu_s/lambda_slip) u_s
 * with its own mu_s instead. 1/lambda_slip is returned rather than
 * lambda_slip because it is finite at phi = 0 (free slip: 0).
 *
 * Check against Krampa (2009) Tables 5.3-5.4 (3.4 mm PVC, slip length from
 * the wall-node concentration c_sw): DG90 reproduces the tabulated lambda;
 * DL92 matches within about 5 % at 10 % solids and not
 * at 20-40 % (the thesis's routine used a smaller g0 than eqs 4.90-4.91 give).
 * tau_w is the magnitude of the stress on the solids, opposing the slip. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "granular/kinetic.h"

typedef struct ns_params {
  double mu_eff, phi_max, delta;
  int32_t radial;
} ns_params;

enum { IN_SLIP_WALL, IN_PHI, IN_D_P, N_IN };
enum { OUT_TAU_W, OUT_INVERSE_SLIP_LENGTH, N_OUT };

#define NS_MU_EFF_PARAM                                                                             \
  SL_PARAM_REAL_OF(ns_params, mu_eff, 0.25, 0.0, 1e5, "Pa s",                                       \
                   "solids effective viscosity that multiplies the wall gradient (Krampa model A: " \
                   "0.25 or 1e-8 Pa s)")

static const sl_param_desc params_dg[] = {NS_MU_EFF_PARAM};
static const sl_param_desc params_dl[] = {
    NS_MU_EFF_PARAM,
    SL_PARAM_REAL_OF(ns_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing in g0 (Krampa 2009: 0.63)"),
    SL_PARAM_REAL_OF(ns_params, delta, 0.01, 1e-4, 0.1, "1",
                     "g0 is continued by its tangent line above phi_max - delta"),
    SL_PARAM_ENUM_OF(ns_params, radial, KT_G0_LUN_SAVAGE, KT_G0_CHOICES, KT_G0_HELP),
};

/* phi is not differentiable for ding_gidaspow: d(phi^(1/3))/dphi is unbounded at 0. */
static const sl_field_desc inputs_dg[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential slip speed of the solids at the wall"},
    {"phi", "1", 0, 0.1, 0.0, 0.74, "solids volume fraction at the wall node"},
    {"d_p", "m", 0, 3.4e-3, 1e-8, 1.0, "particle diameter"},
};
static const sl_field_desc inputs_dl[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential slip speed of the solids at the wall"},
    {"phi", "1", SL_FIELD_DIFF, 0.1, 0.0, 0.74, "solids volume fraction at the wall node"},
    {"d_p", "m", 0, 3.4e-3, 1e-8, 1.0, "particle diameter"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "solids wall shear stress (magnitude, opposing the slip)"},
    {"inverse_slip_length", "m^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "1/lambda_slip (0: free slip)"},
};

/* Krampa (2009) Table 5.3 row DG90-1: c_sw = 0.022, lambda = 0.012 m; Table
 * 5.4 row 10%-1: c_sw = 0.023, lambda = 0.0187 m; d_p = 3.4 mm. */
static const double check_dg[N_IN] = {1.57, 0.022, 3.4e-3};
static const double check_dl[N_IN] = {1.57, 0.023, 3.4e-3};
static const double check_dl_exact[N_IN] = {1.0, 0.3, 1e-3};
static const sl_check_point checks_dg[] = {
    {check_dg, OUT_INVERSE_SLIP_LENGTH, 1.0 / 0.012, 0.05,
     "Krampa (2009) Table 5.3, DG90, c_sw = 0.022: lambda_slip = 0.012 m (2 significant figures)"},
};
static const sl_check_point checks_dl[] = {
    {check_dl, OUT_INVERSE_SLIP_LENGTH, 1.0 / 0.0187, 0.06,
     "Krampa (2009) Table 5.4, DL92 10 %, c_sw = 0.023: lambda_slip = 0.0187 m (the thesis's routine is ~5 % "
     "off eq 4.90)"},
    {check_dl_exact, OUT_INVERSE_SLIP_LENGTH, 6493.799012768399, 1e-12,
     "eq 4.90-4.91 at phi = 0.3, d_p = 1 mm: 24 phi g0/(sqrt(3 pi) d_p), g0 = (1 - 0.3/0.63)^-1.575, "
     "evaluated independently (Python)"},
};

static int evaluate_common(const ns_params *p, int dl, const sl_field_desc *in, const sl_eval_args *a) {
  int rc = gr_check_inputs(a, in, N_IN);
  if (rc) return rc;
  const double *u = a->in[IN_SLIP_WALL], *phi = a->in[IN_PHI], *dp = a->in[IN_D_P];
  double *tau = a->out[OUT_TAU_W], *il = a->out[OUT_INVERSE_SLIP_LENGTH];
  double *dtau_du = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL);
  double *dtau_dphi = dl ? sl_dout(a, N_IN, OUT_TAU_W, IN_PHI) : NULL;
  double *dil_du = il ? sl_dout(a, N_IN, OUT_INVERSE_SLIP_LENGTH, IN_SLIP_WALL) : NULL;
  double *dil_dphi = il && dl ? sl_dout(a, N_IN, OUT_INVERSE_SLIP_LENGTH, IN_PHI) : NULL;
  const double c_dl = 24.0 / sqrt(3.0 * KT_PI);
  for (int32_t q = 0; q < a->Q; ++q) {
    double inv, dinv = 0.0; /* 1/lambda_slip and its phi-derivative */
    if (dl) {
      double dg, g = kt_g0(p->radial, phi[q], p->phi_max, p->delta, &dg);
      inv = c_dl * phi[q] * g / dp[q];
      dinv = c_dl * (g + phi[q] * dg) / dp[q];
    } else {
      inv = cbrt(phi[q]) / dp[q];
    }
    tau[q] = p->mu_eff * u[q] * inv;
    gr_set(dtau_du, q, p->mu_eff * inv);
    gr_set(dtau_dphi, q, p->mu_eff * u[q] * dinv);
    gr_set(il, q, inv);
    gr_set(dil_du, q, 0.0);
    gr_set(dil_dphi, q, dinv);
  }
  return SL_OK;
}

static int evaluate_dg(const void *state, const sl_eval_args *a) { return evaluate_common(state, 0, inputs_dg, a); }
static int evaluate_dl(const void *state, const sl_eval_args *a) { return evaluate_common(state, 1, inputs_dl, a); }

static const sl_closure_desc ding_gidaspow = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "navier_slip_ding_gidaspow",
    .version = "1.0.0",
    .summary = "Navier partial slip of the solids, slip length = mean particle spacing (Ding & Gidaspow 1990)",
    .formula =
        "lambda_slip = d_p / phi^(1/3); tau_w = mu_eff slip_wall / lambda_slip; "
        "inverse_slip_length = phi^(1/3) / d_p",
    .reference = "Ding & Gidaspow (1990) AIChE J 36:523; Eldighidy et al. (1977); Krampa (2009) eqs 4.87-4.89",
    .validity = "solids partial slip at a wall; 0 <= phi <= 0.74 (free slip at phi = 0); mu_eff is a parameter",
    .n_params = SL_COUNT_OF(params_dg),
    .params = params_dg,
    .params_size = sizeof(ns_params),
    .n_in = N_IN,
    .in = inputs_dg,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks_dg),
    .checks = checks_dg,
    .create = NULL,
    .evaluate = evaluate_dg,
    .destroy = NULL,
};

static const sl_closure_desc ding_lyczkowski = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "navier_slip_ding_lyczkowski",
    .version = "1.0.0",
    .summary = "Navier partial slip of the solids, kinetic-theory slip length (Ding & Lyczkowski 1992)",
    .formula =
        "lambda_slip = (sqrt(3 pi)/24) d_p / (phi g0); tau_w = mu_eff slip_wall / lambda_slip; "
        "inverse_slip_length = 24 phi g0 / (sqrt(3 pi) d_p)\n"
        "g0: radial (default lun_savage (1 - phi/phi_max)^(-2.5 phi_max)), tangent line above phi_max - delta",
    .reference = "Ding & Lyczkowski (1992) Powder Technol. 73:127; Krampa (2009) eqs 4.87, 4.90-4.91",
    .validity =
        "solids partial slip at a wall; 0 <= phi <= 0.74 (free slip at phi = 0; g0 continued above "
        "phi_max - delta); mu_eff is a parameter",
    .n_params = SL_COUNT_OF(params_dl),
    .params = params_dl,
    .params_size = sizeof(ns_params),
    .n_in = N_IN,
    .in = inputs_dl,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks_dl),
    .checks = checks_dl,
    .create = NULL,
    .evaluate = evaluate_dl,
    .destroy = NULL,
};

static const sl_closure_desc *const all[] = {&ding_gidaspow, &ding_lyczkowski};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
