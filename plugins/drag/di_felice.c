/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Di Felice (1994) drag with a Reynolds-dependent voidage exponent, as the
 * momentum-exchange coefficient K with F_s = K (u_f - u_s)
 * (architecture.md section 4). eps = 1 - phi is the fluid fraction.
 *
 * Di Felice (1994), Int. J. Multiphase Flow 20:153: the force on
 * one particle of a suspension is f(eps) = eps^-beta times the force on an
 * isolated one at the same superficial velocity U = eps |slip|,
 *   F_0 = C_D0 (pi d^2/4) rho_f U^2 / 2,  C_D0 = (0.63 + 4.8 / sqrt(Re))^2   (Dallavalle 1948),
 *   beta = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2),   Re = eps rho_f |slip| d / mu_f.
 * That force excludes the buoyancy of the mixture pressure gradient: at
 * equilibrium it balances eps times the buoyant weight, so beta = 3.7 is
 * Richardson-Zaki n = 4.7 in the viscous regime and n = 2.35 in the Newton
 * regime. With phi / (pi d^3/6) particles per unit volume and K = F/|slip|:
 *   K = (3/4) C_D0 rho_f phi eps^(2-beta) |slip| / d = (3/4) (mu_f/d^2) phi eps^(1-beta) (C_D0 Re),
 * d = sphericity d_p (the form of PhasicFlow DiFeliceGrain and of CFD-DEM
 * "model B" papers, converted to K). C_D0 Re = (0.63 sqrt(Re) + 4.8)^2 is
 * finite at rest: the Re -> 0 limit is K = 17.28 mu_f phi eps^-2.7 / d^2,
 * 0.96 times Stokes drag at phi -> 0 (Dallavalle's 4.8^2 = 23.04, not 24). */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.2, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* 1. Re -> 0 (slip = 0), beta -> 3.7: K = 17.28 (mu/d^2) phi eps^-2.7;
 *    phi = 0.3, mu/d^2 = 1e3: 17.28e3 * 0.3 * 0.7^-2.7.
 * 2. Re = 10^1.5, where beta has its exact minimum 3.05 (eps = 0.8,
 *    mu/d^2 = 1e3, rho d / mu = 1e3): K = 750 phi eps^-2.05 (0.63 10^0.75 + 4.8)^2. */
#define RE_MIN 31.62277660168379332
static const double check_in_0[N_IN] = {0.3, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const double check_in_1[N_IN] = {0.2, RE_MIN / 800.0, 1000.0, 1e-3, 1e-3, 1.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 13580.01609983288, 1e-12,
     "Di Felice (1994) with Dallavalle C_D, exact Re -> 0 limit 17.28 mu phi eps^-2.7 / d^2"},
    {check_in_1, OUT_K, 16495.872124960057, 1e-9,
     "Di Felice (1994) at Re = 10^1.5 where beta = 3.7 - 0.65 = 3.05 exactly (derived)"},
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
    double eps = 1.0 - phi[q];
    double P = 0.75 * mu[q] / (d * d);
    double s = slip[q];
    double re = eps * rho[q] * s * d / mu[q];
    /* beta(Re) and Re dbeta/dRe; the Gaussian in log10 Re vanishes at Re = 0. */
    double beta = 3.7, re_dbeta = 0.0;
    if (re > 0.0) {
      double x = 1.5 - log10(re);
      double g = exp(-0.5 * x * x);
      beta = 3.7 - 0.65 * g;
      re_dbeta = -0.65 * x * g / log(10.0);
    }
    double re_dG;
    double G = sl_dallavalle_cdre(re, &re_dG);
    double lne = log(eps);
    double E = exp((1.0 - beta) * lne); /* eps^(1-beta) */
    K[q] = P * phi[q] * E * G;
    /* Re = eps rho s d / mu: dRe/dphi = -Re/eps, dRe/dslip = Re/slip. */
    double re_dlnKre = -lne * re_dbeta + re_dG / G; /* Re d ln(E G)/dRe at fixed eps */
    if (dK_dphi) dK_dphi[q] = P * E * G * (1.0 - phi[q] / eps * ((1.0 - beta) + re_dlnKre));
    if (dK_dslip) dK_dslip[q] = s > 0.0 ? P * phi[q] * E * G * re_dlnKre / s : 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc di_felice = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "di_felice",
    .version = "1.0.0",
    .summary = "Di Felice (1994) drag: Dallavalle C_D with a Reynolds-dependent voidage exponent",
    .formula =
        "K = (3/4) C_D0 rho_f phi eps^(2-beta) |slip| / d = (3/4) (mu_f/d^2) phi eps^(1-beta) (0.63 sqrt(Re) "
        "+ 4.8)^2,\n"
        "eps = 1 - phi, Re = eps rho_f |slip| d / mu_f, C_D0 = (0.63 + 4.8/sqrt(Re))^2,\n"
        "beta = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2), d = sphericity d_p",
    .reference = "Di Felice (1994) Int. J. Multiphase Flow 20:153; Dallavalle (1948) Micromeritics",
    .validity =
        "fluid fraction 0.4-1 and Re 1e-2 to 1e4 in Di Felice's data; evaluated for phi <= 0.74 and any "
        "Re; phi -> 0 gives 0.96 x Stokes at low Re (Dallavalle C_D); dK/dslip ~ slip^-1/2 as slip -> 0 "
        "and is reported as 0 at slip = 0",
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

static const sl_closure_desc *const all[] = {&di_felice};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
