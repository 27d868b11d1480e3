/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Gidaspow (1994) kinetic theory of granular flow: radial distribution,
 * solids pressure, shear and bulk viscosity, conductivity of granular energy
 * and collisional dissipation, as functions of the solids fraction phi and
 * the granular temperature theta.
 *
 * Gidaspow (1994), "Multiphase Flow and Fluidization", Academic Press,
 * chapter 9 (kinetic theory for dense flows; the dense-gas corrections of
 * Chapman & Cowling applied to inelastic spheres, Ding & Gidaspow 1990):
 *   p_s      = rho_s phi theta (1 + 2 (1+e) phi g0)
 *   mu_s     = (4/5) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)
 *              + 10 sqrt(pi) rho_s d_p sqrt(theta) / (96 (1+e) g0) (1 + (4/5) g0 phi (1+e))^2
 *   lambda_s = (4/3) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)
 *   kappa    = 2 phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)
 *              + 150 sqrt(pi) rho_s d_p sqrt(theta) / (384 (1+e) g0) (1 + (6/5) phi g0 (1+e))^2
 *   gamma    = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi))
 * These are the phase totals of the solids stress (OpenFOAM's
 * kineticTheoryModels write the same laws as a kinematic viscosity divided
 * by phi rho_s). Krampa (2009) quotes the collisional viscosity as eq 6.4
 * with (1+eta) sqrt(theta)/pi printed for (1+e) sqrt(theta/pi)
 * (a misprint; corrected here). g0 is a parameter (kinetic.h), by default Gidaspow's
 * 0.6/(1 - (phi/phi_max)^(1/3)), continued linearly (C1) above
 * phi_max - delta; with phi_max = 0.6 and delta = 0.001 the continuation
 * point and slope reproduce C_0 = 1079 and C_1 = 1.08e6 of CFX-10's
 * near-packing polynomial (Krampa 2009 eq 6.2). */
#include <math.h>
#include <sluice/closure.h>

#include "granular/kt_closure.h"

static const sl_param_desc params[] = KT_PARAMS(KT_G0_GIDASPOW);
static const sl_field_desc inputs[] = KT_INPUTS;
static const sl_field_desc outputs[] = KT_OUTPUTS;

/* Defaults: e = 0.9, gidaspow g0 with phi_max = 0.63. At phi = phi_max/8 the
 * cube root is 1/2 and g0 = 1.2 exactly. */
#define GID_E 0.9
#define GID_PHI8 (0.63 / 8.0)
#define GID_X (GID_PHI8 * 1.2) /* phi g0 at phi_max/8 */
static const double check_dilute[KT_N_IN] = {0.0, 1.0, 1000.0, 1e-3};
static const double check_eighth[KT_N_IN] = {GID_PHI8, 1.0, 1000.0, 1e-3};
static const double check_ideal[KT_N_IN] = {1e-6, 1e-2, 2650.0, 5e-4};
static const sl_check_point checks[] = {
    {check_eighth, KT_OUT_G0, 1.2, 1e-13,
     "Gidaspow (1994) g0 = 0.6/(1 - (phi/phi_max)^(1/3)) = 1.2 at phi = phi_max/8"},
    {check_eighth, KT_OUT_MU_S,
     0.8 * GID_PHI8 *GID_X *(1.0 + GID_E) / KT_SQRT_PI + 10.0 * KT_SQRT_PI / (96.0 * (1.0 + GID_E) * 1.2) *
                                                             (1.0 + 0.8 * GID_X * (1.0 + GID_E)) *
                                                             (1.0 + 0.8 * GID_X * (1.0 + GID_E)),
     1e-12, "Gidaspow (1994) mu_s evaluated by hand at g0 = 1.2 (phi = phi_max/8), rho d sqrt(theta) = 1"},
    {check_dilute, KT_OUT_G0, 0.6, 1e-4,
     "Gidaspow (1994) g0 -> 3/5 as phi -> 0 (the dilute-end tangent line of kinetic.h adds 8e-5)"},
    {check_dilute, KT_OUT_MU_S, 10.0 * KT_SQRT_PI / (96.0 * (1.0 + GID_E) * 0.6), 1e-4,
     "dilute limit of Gidaspow (1994): 10 sqrt(pi) rho d sqrt(theta)/(96 (1+e) g0) with g0 = 3/5"},
    {check_dilute, KT_OUT_KAPPA, 150.0 * KT_SQRT_PI / (384.0 * (1.0 + GID_E) * 0.6), 1e-4,
     "dilute limit of Gidaspow (1994): 150 sqrt(pi) rho d sqrt(theta)/(384 (1+e) g0) with g0 = 3/5"},
    {check_ideal, KT_OUT_P_S, 2650.0 * 1e-6 * 1e-2, 1e-5,
     "ideal granular gas limit p_s -> rho_s phi theta at phi = 1e-6 (collisional part 2 (1+e) phi g0 < 3e-6)"},
};

static int evaluate(const void *state, const sl_eval_args *a) { return kt_evaluate(KT_GIDASPOW, state, inputs, a); }

static const sl_closure_desc gidaspow = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_GRANULAR,
    .name = "gidaspow",
    .version = "1.0.0",
    .summary = "Gidaspow (1994) kinetic theory: g0, p_s, mu_s, lambda_s, kappa, gamma",
    .formula =
        "p_s = rho_s phi theta (1 + 2 (1+e) phi g0)\n"
        "mu_s = (4/5) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi) + 10 sqrt(pi) rho_s d_p sqrt(theta)/(96 (1+e) g0)"
        " (1 + (4/5) g0 phi (1+e))^2\n"
        "lambda_s = (4/3) phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi)\n"
        "kappa = 2 phi^2 rho_s d_p g0 (1+e) sqrt(theta/pi) + 150 sqrt(pi) rho_s d_p sqrt(theta)/(384 (1+e) g0)"
        " (1 + (6/5) phi g0 (1+e))^2\n"
        "gamma = 12 (1 - e^2) g0 rho_s phi^2 theta^1.5 / (d_p sqrt(pi))\n"
        "g0: radial (default gidaspow 0.6/(1 - (phi/phi_max)^(1/3))), tangent-line continuation above "
        "phi_max - delta\n"
        "stress: sigma_s = -p_s I + lambda_s div(u_s) I + 2 mu_s (D_s - div(u_s) I/3); q = -kappa grad theta",
    .reference =
        "Gidaspow (1994) Multiphase Flow and Fluidization, ch. 9; Ding & Gidaspow (1990) AIChE J 36:523; "
        "Krampa (2009) eqs 5.9, 6.4 (misprint corrected), 6.2",
    .validity =
        "rapid granular flow, smooth inelastic spheres, e close to 1; 0 <= phi <= 0.74 (beyond "
        "phi_max - delta g0 is the C1 linear continuation, not physics); the gidaspow g0 tends to 0.6, "
        "not 1, as phi -> 0; theta >= 1e-12 m^2/s^2",
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

static const sl_closure_desc *const all[] = {&gidaspow};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
