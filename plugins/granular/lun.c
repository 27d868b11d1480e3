/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lun et al. (1984) kinetic theory of granular flow: radial distribution,
 * solids pressure, shear and bulk viscosity, conductivity of granular energy
 * and collisional dissipation, as functions of the solids fraction phi and
 * the granular temperature theta.
 *
 * Lun, Savage, Jeffrey & Chepurniy (1984), J. Fluid Mech. 140:223-256, the
 * constitutive relations of their eqs (4.x) in the continuum form quoted by
 * Krampa (2009) eqs 5.3-5.14 (section 5.1.2), with the
 * misprints of that thesis corrected: the bulk
 * viscosity (5.8) carries phi^2, the dissipation (5.14) is proportional to
 * phi^2 theta^1.5, and the second conductivity group (5.13) carries phi, not
 * 1/g0. With eta = (1 + e)/2 and X = phi g0:
 *   p_s      = rho_s phi theta (1 + 4 eta X)
 *   mu_s     = (5 sqrt(pi)/96) rho_s d_p sqrt(theta)
 *              [ (1 + 8/5 eta X)(1 + 8/5 eta (3 eta - 2) X) / (eta (2 - eta) g0) + 768/(25 pi) eta phi X ]
 *   lambda_s = (8/3) eta phi^2 rho_s d_p g0 sqrt(theta/pi)
 *   kappa    = 75 sqrt(pi) rho_s d_p sqrt(theta) / (48 eta (41 - 33 eta))
 *              [ (1 + 12/5 eta X)(1 + 12/5 eta^2 (4 eta - 3) X) / g0 + 64/(25 pi) (41 - 33 eta) eta^2 phi X ]
 *   gamma    = (48/sqrt(pi)) eta (1 - eta) rho_s phi^2 g0 theta^1.5 / d_p
 *            = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi))
 * The conductivity was cross-checked against the MFiX 2012 theory guide
 * (eqs B8-B10, as coded in OpenFOAM-derived solvers) and a
 * term-by-term reading of (5.11-5.13). g0 is a parameter (kinetic.h), by
 * default Lun & Savage (1986) with phi_max = 0.63 as in Krampa's model B,
 * continued linearly (C1) above phi_max - delta. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/kt_closure.h"

static const sl_param_desc params[] = KT_PARAMS(KT_G0_LUN_SAVAGE);
static const sl_field_desc inputs[] = KT_INPUTS;
static const sl_field_desc outputs[] = KT_OUTPUTS;

/* Defaults: e = 0.9 (eta = 0.95), lun_savage g0 with phi_max = 0.63. */
#define LUN_ETA 0.95
static const double check_dilute[KT_N_IN] = {0.0, 1.0, 1000.0, 1e-3};
static const double check_ideal[KT_N_IN] = {1e-6, 1e-2, 2650.0, 5e-4};
static const sl_check_point checks[] = {
    {check_dilute, KT_OUT_G0, 1.0, 1e-14, "g0 -> 1 as phi -> 0 (Lun & Savage 1986 form), exact"},
    {check_dilute, KT_OUT_MU_S, 5.0 * KT_SQRT_PI / 96.0 / (LUN_ETA * (2.0 - LUN_ETA)), 1e-12,
     "dilute limit of Lun et al. (1984): (5 sqrt(pi)/96) rho d sqrt(theta) / (eta (2 - eta)); "
     "the Chapman-Enskog value for e = 1"},
    {check_dilute, KT_OUT_KAPPA, 75.0 * KT_SQRT_PI / (48.0 * LUN_ETA * (41.0 - 33.0 * LUN_ETA)), 1e-12,
     "dilute limit of Lun et al. (1984): 75 sqrt(pi) rho d sqrt(theta) / (48 eta (41 - 33 eta)); "
     "75 sqrt(pi)/384 for e = 1"},
    {check_ideal, KT_OUT_P_S, 2650.0 * 1e-6 * 1e-2, 1e-5,
     "ideal granular gas limit p_s -> rho_s phi theta at phi = 1e-6 (collisional part 4 eta phi g0 = 3.8e-6)"},
};

static int evaluate(const void *state, const sl_eval_args *a) { return kt_evaluate(KT_LUN, state, inputs, a); }

static const sl_closure_desc lun = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_GRANULAR,
    .name = "lun",
    .version = "1.0.0",
    .summary = "Lun et al. (1984) kinetic theory: g0, p_s, mu_s, lambda_s, kappa, gamma",
    .formula =
        "eta = (1+e)/2, X = phi g0\n"
        "p_s = rho_s phi theta (1 + 2 (1+e) X)\n"
        "mu_s = (5 sqrt(pi)/96) rho_s d_p sqrt(theta) [(1 + 8/5 eta X)(1 + 8/5 eta (3 eta - 2) X)/(eta (2-eta) g0)"
        " + 768/(25 pi) eta phi X]\n"
        "lambda_s = (4/3) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)\n"
        "kappa = 75 sqrt(pi) rho_s d_p sqrt(theta)/(48 eta (41-33 eta)) [(1 + 12/5 eta X)(1 + 12/5 eta^2 (4 eta - 3) "
        "X)/g0"
        " + 64/(25 pi) (41 - 33 eta) eta^2 phi X]\n"
        "gamma = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi))\n"
        "g0: radial (default lun_savage (1 - phi/phi_max)^(-2.5 phi_max)), tangent-line continuation above "
        "phi_max - delta\n"
        "stress: sigma_s = -p_s I + lambda_s div(u_s) I + 2 mu_s (D_s - div(u_s) I/3); q = -kappa grad theta",
    .reference =
        "Lun, Savage, Jeffrey & Chepurniy (1984) J. Fluid Mech. 140:223; Krampa (2009) eqs 5.3-5.14 "
        "(misprints corrected); MFiX 2012 theory guide eqs B4-B10",
    .validity =
        "rapid granular flow, smooth inelastic spheres, e close to 1 (the theory is first order in 1 - e); "
        "0 <= phi <= 0.74 (beyond phi_max - delta g0 is the C1 linear continuation, not physics); "
        "theta >= 1e-12 m^2/s^2 (mu_s, kappa ~ sqrt(theta): their theta-derivatives are infinite at 0)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(kt_params),
    .n_in = KT_N_IN,
    .in = inputs,
    .n_out = KT_N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = NULL,
    .evaluate = evaluate,
    .destroy = NULL,
};

static const sl_closure_desc *const all[] = {&lun};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
