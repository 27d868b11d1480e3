/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Pringle (2001) drag: Ergun in dense beds, a Richardson-Zaki law with
 * Rowe's C_D in dilute ones, switched hard at porosity 0.6; as the
 * momentum-exchange coefficient K with F_s = K (u_f - u_s)
 * (architecture.md section 4). eps = 1 - phi is the porosity n.
 *
 * Pringle (2001), Finite Element Modelling of Two-Component, Solid-Liquid
 * Mixtures, PhD thesis, McMaster University, section 3.1:
 *   eps < 0.6 (eq 3.12, Ergun 1952):
 *     K = 150 phi^2 mu_f / (eps d^2) + 1.75 phi rho_f |slip| / (eps d)         ergun_form = pringle_printed
 *     (the stated substitution U = eps V_r into eq 3.8 gives 1.75 phi rho_f |slip| / d without the 1/eps:
 *      ergun_form = gidaspow; the substitution of eqs 3.9-3.11 gives no 1/n)
 *   eps >= 0.6, modified Richardson-Zaki (eq 3.32, f'(n) = n^-4.65, eq 3.31):
 *     K = (3/4) C_D rho_f eps^-4.65 [rho_s/(rho_s - rho_f) - eps] |slip| eps^2 / d   dilute = printed_eq_3_32
 *   C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above (Rowe 1961, eq 3.24), Re = rho_f |slip| d / mu_f
 *   (eq 3.25, the interstitial slip), d = sphericity d_p (eq 5.9).
 *
 * CONSISTENCY PROBLEM (eqs 3.32-3.34 against eq 4.20). In the thesis's
 * own momentum equations, which carry the fluid weight, a steady
 * homogeneous bed needs K V_r = phi eps (rho_s - rho_f) g. The printed
 * eq 3.32 was derived instead by balancing the drag against the whole
 * mixture-weight gradient, and inside the momentum equations it gives
 *   U = u_t eps^4.65 (1 - eps)(rho_s - rho_f) / rhobar      (Stokes),
 * not Richardson-Zaki U = u_t eps^4.65: the extra factor is about 0.32 for
 * sand in water at eps = 0.7 and 0.034 for nylon in water at 0.75, where
 * U(eps) even decreases across the switch (a bed that contracts when the
 * flow increases). The printed law also keeps K > 0 in clear fluid
 * (K -> 18 mu_f rho_f / ((rho_s - rho_f) d^2) at phi = 0) and is undefined
 * for rho_s <= rho_f. The form that reproduces Richardson-Zaki, and the
 * DEFAULT here (dilute = wen_yu_consistent), is the Wen-Yu form as written
 * by Gidaspow (1994) with the same C_D and Re:
 *     K = (3/4) C_D rho_f phi eps^-2.65 |slip| / d,    Stokes: 18 mu_f phi eps^-2.65 / d^2.
 * With it and the printed Ergun (the defaults) the inertia-free kinematic
 * reference for Slis et al. (1958), section 5.1, is reproduced.
 *
 * THE SWITCH IS A JUMP. At slip -> 0, K/(mu_f/d^2) goes from 40.0 (Ergun,
 * eps -> 0.6-) to 27.9 (consistent, x 0.70) or to 71.4 (printed eq 3.34
 * for rho_s/rho_f = 2.6, x 1.78) (eq 3.12 against eq 3.34). Pringle
 * used no blending; `switch_fluid_fraction` moves the switch. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/dense_drag_laws.h"

typedef struct pringle_params {
  double switch_fluid_fraction; /* 0.6 */
  int32_t ergun_form;           /* 0 pringle_printed (eq 3.12), 1 gidaspow */
  int32_t dilute;               /* 0 wen_yu_consistent, 1 printed_eq_3_32 */
  double rz_exponent;           /* 4.65, f'(n) = n^-4.65 */
} pringle_params;

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, IN_RHO_S, N_IN };
enum { OUT_K, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(pringle_params, switch_fluid_fraction, 0.6, 0.26, 1.0, "1",
                     "porosity 1-phi at which Ergun (below) hands over to the dilute law (at and above); a jump"),
    SL_PARAM_ENUM_OF(pringle_params, ergun_form, 0, "pringle_printed|gidaspow",
                     "pringle_printed: eq 3.12 with 1.75 phi rho |slip|/((1-phi) d); gidaspow: without the 1/(1-phi)"),
    SL_PARAM_ENUM_OF(pringle_params, dilute, 0, "wen_yu_consistent|printed_eq_3_32",
                     "wen_yu_consistent: (3/4) C_D rho phi (1-phi)^(2-n) |slip|/d, reproduces Richardson-Zaki; "
                     "printed_eq_3_32: as printed, inconsistent (see formula)"),
    SL_PARAM_REAL_OF(pringle_params, rz_exponent, 4.65, 1.0, 10.0, "1",
                     "Richardson-Zaki exponent n of f'(n) = (1-phi)^-n (eq 3.31)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.74, "solids volume fraction (1 - porosity)"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it, eq 5.9)"},
    {"rho_s", "kg m^-3", 0, 2600.0, 1e-3, 1e5, "particle density (used by dilute = printed_eq_3_32 only)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* 1-2. Stokes limit (slip = 0), mu/d^2 = 1e3 (eq 3.12 and
 *      the consistent form): Ergun 135.0 mu/d^2 at n = 0.40, consistent 13.9 at n = 0.70.
 * 3-4. Slis et al. (1958) nylon I (d = 3 mm, 1140 kg/m^3) in water at 20 C
 *      (998.2 kg/m^3, 1.002 mPa s; Table 5.1), the kinematic reference
 *      (printed Ergun + consistent dilute + Rowe C_D): the steady bed has
 *      U = 35.5 mm/s at n = 0.76 and 11.1 mm/s at n = 0.54. At that slip
 *      V_r = U/n the drag balances the buoyant weight, K = n (1-n) drho g / V_r. */
#define SLIS_K(n, U) ((n) * (1.0 - (n)) * (1140.0 - 998.2) * 9.81 * (n) / (U))
static const double check_in_0[N_IN] = {0.6, 0.0, 1000.0, 1e-3, 1e-3, 1.0, 2600.0};
static const double check_in_1[N_IN] = {0.3, 0.0, 1000.0, 1e-3, 1e-3, 1.0, 2600.0};
static const double check_in_2[N_IN] = {0.24, 0.0355 / 0.76, 998.2, 1.002e-3, 3e-3, 1.0, 1140.0};
static const double check_in_3[N_IN] = {0.46, 0.0111 / 0.54, 998.2, 1.002e-3, 3e-3, 1.0, 1140.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 135.0e3, 5e-4, "Pringle (2001) eq 3.12 (Ergun), Stokes limit, n = 0.40: 135.0 mu/d^2"},
    {check_in_1, OUT_K, 13.9e3, 4e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.70: 13.9 mu/d^2"},
    {check_in_2, OUT_K, SLIS_K(0.76, 0.0355), 3e-3,
     "Slis nylon I (Pringle 2001, Table 5.1), equilibrium: U = 35.5 mm/s at n = 0.76 (K V_r = n(1-n) drho g)"},
    {check_in_3, OUT_K, SLIS_K(0.54, 0.0111), 8e-3,
     "Slis nylon I (Pringle 2001, Table 5.1), equilibrium: U = 11.1 mm/s at n = 0.54, eq 3.12 Ergun"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const pringle_params *p = state;
  const double *phi = a->in[IN_PHI], *slip = a->in[IN_SLIP], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F],
               *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY], *rho_s = a->in[IN_RHO_S];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  const double nrz = p->rz_exponent;
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    if (p->dilute == 1 && !(rho_s[q] > rho[q]))
      return sl_fail(a->err, SL_RECOVERABLE, q,
                     "printed eq 3.32 needs rho_s > rho_f (rho_s = %g, rho_f = %g): [rho_s/(rho_s - rho_f) - n] "
                     "is singular or negative",
                     rho_s[q], rho[q]);
    double d = psi[q] * dp[q];
    double eps = 1.0 - phi[q];
    double k1 = mu[q] / (d * d);
    double s = slip[q];
    double k, k_phi, k_s;
    if (eps < p->switch_fluid_fraction) {
      /* Ergun; inertial factor phi/eps (printed eq 3.12, ergun_form 0) or phi (gidaspow). */
      const sl_drag_value e = sl_ergun_law(phi[q], s, rho[q], mu[q], d, 150.0, 1.75, p->ergun_form == 0);
      k = e.K;
      k_phi = e.K_phi;
      k_s = e.K_slip;
    } else {
      /* 18 k1 f(Re) eps^(2-n) X, X = phi (consistent) or rho_s/drho - eps (printed). */
      double re = rho[q] * s * d / mu[q], re_df;
      double f = sl_sn_factor(re, &re_df);
      double h = pow(eps, 2.0 - nrz), h_phi = (nrz - 2.0) * h / eps; /* eps^(2-n) and its phi derivative */
      double X = p->dilute == 0 ? phi[q] : rho_s[q] / (rho_s[q] - rho[q]) - eps;
      k = 18.0 * k1 * f * h * X;
      k_phi = 18.0 * k1 * f * (h_phi * X + h);
      k_s = s > 0.0 ? 18.0 * k1 * h * X * re_df / s : 0.0;
    }
    K[q] = k;
    if (dK_dphi) dK_dphi[q] = k_phi;
    if (dK_dslip) dK_dslip[q] = k_s;
  }
  return SL_OK;
}

static const sl_closure_desc pringle = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "pringle",
    .version = "1.0.0",
    .summary = "Pringle (2001) drag: Ergun below porosity 0.6, Richardson-Zaki/Rowe above, hard switch",
    .formula =
        "n = 1 - phi (porosity), d = sphericity d_p, Re = rho_f |slip| d / mu_f, C_D = 24/Re (1 + 0.15 Re^0.687) "
        "(Re < 1000), 0.44 above;\n"
        "n < 0.6: K = 150 phi^2 mu_f/(n d^2) + 1.75 phi rho_f |slip|/(n d)  (eq 3.12; ergun_form = gidaspow drops "
        "the 1/n);\n"
        "n >= 0.6, dilute = wen_yu_consistent (default): K = (3/4) C_D rho_f phi n^-2.65 |slip| / d;\n"
        "n >= 0.6, dilute = printed_eq_3_32: K = (3/4) C_D rho_f n^-4.65 [rho_s/(rho_s - rho_f) - n] |slip| n^2 / d.\n"
        "WARNING (Pringle 2001, eqs 3.32 and 4.20): the printed eq 3.32 does NOT reproduce Richardson-Zaki inside the "
        "momentum equations (it balances the mixture-weight gradient, not n x the buoyant weight): a steady bed "
        "gets U = u_t n^4.65 (1-n)(rho_s-rho_f)/rhobar, U(n) can decrease across the switch, and K > 0 at phi = 0. "
        "The wen_yu_consistent form gives U = u_t n^4.65 exactly.\n"
        "The switch at n = 0.6 is a jump: at slip -> 0, 40.0 -> 27.9 mu_f/d^2 (consistent) or 40.0 -> 71.4 "
        "(printed, rho_s/rho_f = 2.6)",
    .reference =
        "Pringle (2001) PhD thesis, McMaster University, eqs 3.12, 3.24-3.25, 3.31-3.34, 5.9; Ergun (1952) "
        "Chem. Eng. Prog. 48:89; Rowe (1961) Trans. Inst. Chem. Eng. 39:175; Slis et al. (1958) as "
        "used in Pringle (2001) section 5.1",
    .validity =
        "liquid-fluidised beds and settling suspensions, porosity 0.26-1 (phi <= 0.74); the printed dense "
        "law was fitted near porosity 0.4; hard switch at porosity 0.6 (a jump in K); dilute = "
        "printed_eq_3_32 needs rho_s > rho_f; dK/dslip is reported as 0 at slip = 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(pringle_params),
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

static const sl_closure_desc *const all[] = {&pringle};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
