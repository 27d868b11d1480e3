/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Schiller-Naumann drag of isolated spheres, as the momentum-exchange
 * coefficient K with F_s = K (u_f - u_s) (architecture.md section 4).
 *
 * Schiller & Naumann (1933), Z. Ver. Dtsch. Ing. 77:318, with the Newton
 * value 0.44 above Re = 1000 (Rowe 1961; Pringle 2001 eqs 3.24-3.25):
 *   C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 for Re >= 1000,
 *   Re  = rho_f |slip| d / mu_f,
 *   K   = (3/4) C_D rho_f phi |slip| / d = 18 mu_f phi f(Re) / d^2,  f = C_D Re / 24,
 * with d = sphericity d_p.
 * Decision: NO fluid-fraction factor. K/phi is the drag of one isolated
 * sphere at the slip speed; Re is formed with the slip itself, not with
 * (1-phi) |slip|. This is the dilute law (phi -> 0) that wen_yu and
 * gidaspow reduce to; at finite phi it has no hindrance, so use wen_yu,
 * di_felice or richardson_zaki_consistent for suspensions. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.01, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* 1. Terminal fall of a 3 mm nylon sphere (1140 kg/m^3) in water at 20 C
 *    (998.2 kg/m^3, 1.002 mPa s): u_t = 87.9 mm/s at Re = 263 with Rowe's
 *    C_D (Pringle 2001, eqs 3.24-3.25; Slis et al. 1958). At u_t the drag balances the
 *    buoyant weight, K u_t = phi (rho_s - rho_f) g:
 *    K = 0.01 * 141.8 * 9.81 / 0.0879 = 158.25.
 * 2. Re -> 0: Stokes, 18 mu phi / d^2 exactly. */
static const double check_in_0[N_IN] = {0.01, 0.0879, 998.2, 1.002e-3, 3e-3, 1.0};
static const double check_in_1[N_IN] = {0.2, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 0.01 * 141.8 * 9.81 / 0.0879, 2e-3,
     "Pringle (2001) eqs 3.24-3.25: 3 mm nylon in water, u_t = 87.9 mm/s (Rowe C_D); K u_t = phi drho g"},
    {check_in_1, OUT_K, 3.6e3, 1e-14, "Stokes limit slip = 0: 18 mu phi / d^2, exact"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  (void)state;
  const double *phi = a->in[IN_PHI], *slip = a->in[IN_SLIP], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F],
               *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    double d = psi[q] * dp[q];
    double k1 = 18.0 * mu[q] / (d * d);
    double re = rho[q] * slip[q] * d / mu[q], re_df;
    double f = sl_sn_factor(re, &re_df);
    K[q] = k1 * phi[q] * f;
    if (dK_dphi) dK_dphi[q] = k1 * f;
    /* dRe/dslip = Re/slip; df/dRe is infinite at Re = 0, reported as 0 there. */
    if (dK_dslip) dK_dslip[q] = slip[q] > 0.0 ? k1 * phi[q] * re_df / slip[q] : 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc schiller_naumann = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "schiller_naumann",
    .version = "1.0.0",
    .summary = "Schiller-Naumann (1933) drag of isolated spheres, no fluid-fraction correction",
    .formula =
        "K = (3/4) C_D rho_f phi |slip| / d = 18 mu_f phi f(Re) / d^2,  Re = rho_f |slip| d / mu_f,\n"
        "f = C_D Re/24 = 1 + 0.15 Re^0.687 (Re < 1000), 0.44 Re/24 (Re >= 1000),  d = sphericity d_p;\n"
        "no (1-phi) factor in K or Re: K/phi is the isolated-sphere drag",
    .reference =
        "Schiller & Naumann (1933) Z. Ver. Dtsch. Ing. 77:318; Rowe (1961) Trans. Inst. Chem. Eng. "
        "39:175; Pringle (2001) eqs 3.24-3.25",
    .validity =
        "dilute suspensions (phi -> 0), Re up to about 2e5 (no drag crisis); C_D jumps by +0.39 % at "
        "Re = 1000; dK/dslip ~ slip^-0.313 as slip -> 0 and is reported as 0 at slip = 0",
    .n_params = 0,
    .params = NULL,
    .params_size = 0,
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

static const sl_closure_desc *const all[] = {&schiller_naumann};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
