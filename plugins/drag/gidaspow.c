/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Gidaspow drag: Ergun in dense beds, Wen-Yu in dilute suspensions, as the
 * momentum-exchange coefficient K with F_s = K (u_f - u_s)
 * (architecture.md section 4). eps = 1 - phi is the fluid fraction.
 *
 * Gidaspow (1994), Multiphase Flow and Fluidization, eq 5.62 and ch. 5
 * (also Ding & Gidaspow 1990, AIChE J. 36:523; MFIX DRAG_GIDASPOW):
 *   eps <  0.8:  K_E  = 150 phi^2 mu_f / (eps d^2) + 1.75 phi rho_f |slip| / d      (Ergun 1952)
 *   eps >= 0.8:  K_WY = (3/4) C_D phi eps rho_f |slip| eps^-2.65 / d                 (Wen & Yu 1966)
 *                C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), 0.44 above, Re = eps rho_f |slip| d / mu_f
 * d = sphericity d_p. The switch is a jump: at slip -> 0, K/(mu/d^2) falls
 * from 7.50 (Ergun) to 6.50 (Wen-Yu) as eps crosses 0.8 upwards (-13 %);
 * at finite slip the jump changes size and sign (the OpenFOAM
 * GidaspowErgunWenYu jump of peer-codes-survey section 4 item 5).
 *
 * `blend = huilin_gidaspow` replaces the switch by the smooth arctan blend
 * of Huilin & Gidaspow (2003), Chem. Eng. Sci. 58:3777 (also MFIX
 * GIDASPOW_BLEND, after Lathouwers & Bellan 2000):
 *   w = arctan(s (eps - 0.8)) / pi + 1/2,  s = 150 x 1.75 = 262.5,
 *   K = (1 - w) K_E + w K_WY,
 * continuous and differentiable everywhere, equal to (K_E + K_WY)/2 at the
 * switch; the blend weight is within 1 % of 0 or 1 only 0.12 away from it. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/dense_drag_laws.h"

typedef struct gidaspow_params {
  double switch_fluid_fraction; /* 0.8 */
  int32_t blend;                /* 0 none (hard switch), 1 huilin_gidaspow */
  double blend_steepness;       /* 262.5 */
} gidaspow_params;

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(gidaspow_params, switch_fluid_fraction, 0.8, 0.26, 1.0, "1",
                     "fluid fraction 1-phi at which Ergun (below) hands over to Wen-Yu (at and above)"),
    SL_PARAM_ENUM_OF(gidaspow_params, blend, 0, "none|huilin_gidaspow",
                     "none: hard switch with a jump (Gidaspow 1994); huilin_gidaspow: arctan blend (2003)"),
    SL_PARAM_REAL_OF(gidaspow_params, blend_steepness, 262.5, 1.0, 1e5, "1",
                     "s in w = arctan(s (1-phi - switch))/pi + 1/2 (150 x 1.75 in Huilin & Gidaspow 2003)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.4, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* Stokes limit (slip = 0), mu/d^2 = 1e3 (Pringle 2001, eq 3.12; Gidaspow 1994):
 * Ergun 135.0 mu/d^2 at n = 0.40 (dense side) and Wen-Yu-consistent 2.38
 * mu/d^2 at n = 0.90 (dilute side). */
static const double check_in_0[N_IN] = {0.6, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const double check_in_1[N_IN] = {0.1, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 135.0e3, 5e-4, "Pringle (2001) eq 3.12 (Ergun), Stokes limit, n = 0.40: 135.0 mu/d^2"},
    {check_in_1, OUT_K, 2.38e3, 4e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.90: 2.38 mu/d^2"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const gidaspow_params *p = state;
  const double *phi = a->in[IN_PHI], *slip = a->in[IN_SLIP], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F],
               *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  const double sw = p->switch_fluid_fraction, st = p->blend_steepness;
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    const double d = psi[q] * dp[q], eps = 1.0 - phi[q];
    const sl_drag_value e = sl_ergun_law(phi[q], slip[q], rho[q], mu[q], d, 150.0, 1.75, 0);
    const sl_drag_value y = sl_wen_yu_law(phi[q], slip[q], rho[q], mu[q], d, 2.65, 1);
    double w, w_phi;
    if (p->blend == 1) {
      double x = st * (eps - sw);
      w = atan(x) / SL_PI + 0.5;
      w_phi = -st / (SL_PI * (1.0 + x * x));
    } else {
      w = eps < sw ? 0.0 : 1.0;
      w_phi = 0.0;
    }
    K[q] = (1.0 - w) * e.K + w * y.K;
    if (dK_dphi) dK_dphi[q] = (1.0 - w) * e.K_phi + w * y.K_phi + w_phi * (y.K - e.K);
    if (dK_dslip) dK_dslip[q] = (1.0 - w) * e.K_slip + w * y.K_slip;
  }
  return SL_OK;
}

static const sl_closure_desc gidaspow = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "gidaspow",
    .version = "1.0.0",
    .summary = "Gidaspow (1994) drag: Ergun below fluid fraction 0.8, Wen-Yu above; optional arctan blend",
    .formula =
        "eps = 1 - phi, d = sphericity d_p;\n"
        "K_E  = 150 phi^2 mu_f / (eps d^2) + 1.75 phi rho_f |slip| / d;\n"
        "K_WY = (3/4) C_D phi eps rho_f |slip| eps^-2.65 / d, C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), "
        "0.44 above, Re = eps rho_f |slip| d / mu_f;\n"
        "blend = none: K = K_E for eps < 0.8, K_WY for eps >= 0.8 (a jump: 7.50 -> 6.50 mu_f/d^2 at "
        "slip = 0);\n"
        "blend = huilin_gidaspow: K = (1-w) K_E + w K_WY, w = arctan(262.5 (eps - 0.8))/pi + 1/2 (smooth)",
    .reference =
        "Gidaspow (1994) Multiphase Flow and Fluidization eq 5.62 (Ergun) and ch. 5 (Wen-Yu); Ding & Gidaspow (1990) "
        "AIChE J. "
        "36:523; Huilin & Gidaspow (2003) Chem. Eng. Sci. 58:3777 (blend)",
    .validity =
        "fluidised beds and suspensions, phi <= 0.74; K jumps at fluid fraction 0.8 unless blended "
        "(at slip -> 0 by -13 %); C_D jumps by +0.39 % at Re = 1000; dK/dslip is reported as 0 at "
        "slip = 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(gidaspow_params),
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

static const sl_closure_desc *const all[] = {&gidaspow};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
