/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Wen-Yu drag, as the momentum-exchange coefficient K with
 * F_s = K (u_f - u_s) (architecture.md section 4).
 *
 * Wen & Yu (1966), Chem. Eng. Prog. Symp. Ser. 62(62):100, as written by
 * Gidaspow (1994), Multiphase Flow and Fluidization, ch. 5 (also MFIX
 * DRAG_WEN_YU, OpenFOAM WenYu), eps = 1 - phi the fluid fraction:
 *   K  = (3/4) C_D phi eps rho_f |slip| eps^-2.65 / d,
 *   C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above,
 *   Re = eps rho_f |slip| d / mu_f,      d = sphericity d_p.
 * With f = C_D Re / 24 this is K = 18 mu_f phi eps^-2.65 f(Re) / d^2: the
 * Stokes limit is 18 mu_f phi eps^-2.65 / d^2, which in the steady
 * homogeneous balance K V_r = phi eps (rho_s - rho_f) g gives exactly
 * Richardson-Zaki U = u_t eps^4.65 (in the steady balance of Pringle 2001, eq 4.20).
 *
 * `reynolds = interstitial` forms Re with the slip itself, Re = rho_f |slip|
 * d / mu_f, and drops the eps in front, K = (3/4) C_D(Re) rho_f phi
 * eps^-2.65 |slip| / d: the "Wen-Yu-consistent" form in Pringle's (2001)
 * variables (Rowe's C_D and his eq 3.25 Re). Both agree
 * in the Stokes limit and differ by f(eps Re) vs f(Re) at finite Re.
 * `exponent` replaces 2.65 (Richardson-Zaki n - 2; SedFoam's hExp). */
#include <math.h>
#include <sluice/closure.h>

#include "drag/dense_drag_laws.h"

typedef struct wen_yu_params {
  double exponent;  /* 2.65 */
  int32_t reynolds; /* 0 fluid_fraction (Gidaspow), 1 interstitial (Pringle 2001 eq 3.25) */
} wen_yu_params;

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(wen_yu_params, exponent, 2.65, 0.0, 10.0, "1",
                     "hindrance exponent m in eps^-m (Richardson-Zaki n - 2)"),
    SL_PARAM_ENUM_OF(wen_yu_params, reynolds, 0, "fluid_fraction|interstitial",
                     "fluid_fraction: Re = (1-phi) rho |slip| d/mu and K ~ phi (1-phi)^(1-m) (Gidaspow 1994); "
                     "interstitial: Re = rho |slip| d/mu and K ~ phi (1-phi)^-m (Pringle 2001 eq 3.25)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.1, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* Stokes limit (slip = 0), mu/d^2 = 1e3: the Wen-Yu-consistent K/(mu/d^2)
 * is 13.9 at n = 0.70 and 2.38 at n = 0.90 (n = 1 - phi, the porosity). */
static const double check_in_0[N_IN] = {0.3, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const double check_in_1[N_IN] = {0.1, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 13.9e3, 4e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.70: 13.9 mu/d^2"},
    {check_in_1, OUT_K, 2.38e3, 4e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.90: 2.38 mu/d^2"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const wen_yu_params *p = state;
  const double *phi = a->in[IN_PHI], *slip = a->in[IN_SLIP], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F],
               *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  const double m = p->exponent;
  const int fluid_fraction_re = p->reynolds == 0;
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    const sl_drag_value v = sl_wen_yu_law(phi[q], slip[q], rho[q], mu[q], psi[q] * dp[q], m, fluid_fraction_re);
    K[q] = v.K;
    if (dK_dphi) dK_dphi[q] = v.K_phi;
    if (dK_dslip) dK_dslip[q] = v.K_slip;
  }
  return SL_OK;
}

static const sl_closure_desc wen_yu = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "wen_yu",
    .version = "1.0.0",
    .summary = "Wen-Yu (1966) drag as written by Gidaspow (1994), Richardson-Zaki hindrance eps^-2.65",
    .formula =
        "K = (3/4) C_D phi eps rho_f |slip| eps^-m / d = 18 mu_f phi eps^-m f(Re) / d^2,  eps = 1 - phi,\n"
        "Re = eps rho_f |slip| d / mu_f,  f = C_D Re/24 = 1 + 0.15 Re^0.687 (Re < 1000), 0.44 Re/24 above,\n"
        "m = exponent (2.65), d = sphericity d_p;  reynolds = interstitial: Re = rho_f |slip| d / mu_f,\n"
        "K = (3/4) C_D rho_f phi eps^-m |slip| / d",
    .reference =
        "Wen & Yu (1966) Chem. Eng. Prog. Symp. Ser. 62(62):100; Gidaspow (1994) Multiphase Flow and "
        "Fluidization ch. 5; Pringle (2001) eqs 3.24-3.25, 4.20",
    .validity =
        "dilute to moderately dense suspensions, fluid fraction above about 0.8 (Gidaspow switches to "
        "Ergun below); evaluated for phi <= 0.74; C_D jumps by +0.39 % at Re = 1000; dK/dslip is "
        "reported as 0 at slip = 0 (it grows as slip^-0.313 there)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(wen_yu_params),
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

static const sl_closure_desc *const all[] = {&wen_yu};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
