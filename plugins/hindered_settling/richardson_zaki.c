/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Richardson-Zaki hindered settling: the batch-settling velocity of the
 * solids relative to the mixture volume flux, u_t f(phi), so that the Kynch
 * flux is phi u_t f(phi) (architecture.md section 3, `mixture`).
 *
 * Richardson & Zaki (1954), Trans. Inst. Chem. Eng. 32:35:
 *   f(phi) = (1 - phi)^n,
 * n given, or from their correlation with the terminal Reynolds number
 * Re_t = rho_f |u_t| d / mu_f and the wall term d/D (D = d_vessel, may be
 * +infinity):
 *   Re_t < 0.2        n = 4.65 + 19.5 d/D
 *   0.2 <= Re_t < 1   n = (4.35 + 17.5 d/D) Re_t^-0.03
 *   1 <= Re_t < 200   n = (4.45 + 18 d/D) Re_t^-0.1
 *   200 <= Re_t < 500 n = 4.45 Re_t^-0.1
 *   Re_t >= 500       n = 2.39
 * (n jumps at the range limits, e.g. 4.65 -> 4.56 at Re_t = 0.2; this does
 * not touch d/dphi), or from Garside & Al-Dibouni (1977), Ind. Eng. Chem.
 * Process Des. Dev. 16:206: n = (5.1 + 0.27 Re_t^0.9) / (1 + 0.1 Re_t^0.9),
 * smooth from 5.1 (Re_t -> 0) to 2.7 (Re_t -> infinity).
 * Optional packing cut-off (not in Richardson & Zaki), so that the flux
 * vanishes at phi_max and a sediment forms without a separate sediment
 * model; phi > phi_max is then refused:
 *   packing_cutoff = true:  f = (1-phi)^n (1 - phi/phi_max) (multiplicative);
 *   packing_cutoff = step:  f = (1-phi)^n below phi_max and 0 at phi_max (a
 *                           flux truncated at the maximum concentration,
 *                           which Kynch's (1952) theory admits).
 *
 * u_t, the terminal velocity of one particle (d = sphericity d_p), is
 * signed: positive along the body force for rho_s > rho_f, negative for
 * buoyant particles. `terminal_velocity`:
 *   given                      u_t is the parameter u_t;
 *   stokes                     u_t = (rho_s - rho_f) g d^2 / (18 mu_f);
 *   schiller_naumann | rowe    (3/4) C_D rho_f u_t^2 / d = |rho_s - rho_f| g with C_D = 24/Re (1 + 0.15
 *                              Re^0.687) for Re < 1000, 0.44 above (Rowe 1961 as printed in Pringle 2001
 *                              eqs 3.24-3.25 is the same correlation); Newton iteration to 1e-15. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

typedef struct rz_params {
  int32_t exponent;          /* 0 given, 1 richardson_zaki_1954, 2 garside_al_dibouni_1977 */
  double n;                  /* 4.65 */
  int32_t packing_cutoff;    /* 0 none, 1 multiplicative, 2 step */
  double phi_max;            /* 0.64 */
  int32_t terminal_velocity; /* SL_UT_* */
  double u_t;                /* given terminal velocity */
} rz_params;

enum { IN_PHI, IN_D_P, IN_SPHERICITY, IN_RHO_S, IN_RHO_F, IN_MU_F, IN_GRAVITY, IN_D_VESSEL, N_IN };
enum { OUT_SETTLING, OUT_HINDRANCE, OUT_TERMINAL, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_ENUM_OF(rz_params, exponent, 0, "given|richardson_zaki_1954|garside_al_dibouni_1977",
                     "where n comes from: the parameter n, the Richardson-Zaki (1954) Re_t and d/D correlation, or "
                     "Garside & Al-Dibouni (1977)"),
    SL_PARAM_REAL_OF(rz_params, n, 4.65, 1.0, 20.0, "1", "Richardson-Zaki exponent when exponent = given"),
    SL_PARAM_ENUM_OF(rz_params, packing_cutoff, 0, "false|true|step",
                     "settling stops at phi_max: true multiplies by (1 - phi/phi_max), step drops to 0 there"),
    SL_PARAM_REAL_OF(rz_params, phi_max, 0.64, 0.3, 1.0, "1", "maximum packing fraction of the packing cut-off"),
    SL_PARAM_ENUM_OF(rz_params, terminal_velocity, SL_UT_STOKES, SL_UT_CHOICES,
                     "single-particle terminal velocity: given (u_t), stokes, schiller_naumann or rowe (the same C_D)"),
    SL_PARAM_REAL_OF(rz_params, u_t, 0.01, -100.0, 100.0, "m s^-1",
                     "terminal velocity when terminal_velocity = given (positive along the body force)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.1, 0.0, 1.0, "solids volume fraction"},
    {"d_p", "m", 0, 1e-4, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
    {"rho_s", "kg m^-3", 0, 2600.0, 1e-3, 1e5, "particle density"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"gravity", "m s^-2", 0, 9.81, 0.0, 1e5, "magnitude of the body force per unit mass"},
    {"d_vessel", "m", 0, 0.1, 1e-6, HUGE_VAL, "vessel diameter D of the wall term d/D (may be infinite)"},
};

static const sl_field_desc outputs[] = {
    {"settling_velocity", "m s^-1", 0, 0, 0, 0,
     "u_t f(phi), solids velocity relative to the mixture volume flux, along the body force"},
    {"hindrance", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "f(phi) = (1 - phi)^n"},
    {"terminal_velocity", "m s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "u_t of one particle"},
};

/* 1. phi = 0: Stokes terminal velocity, exact: 1600 * 9.81 * 1e-8 / 18e-3.
 * 2. (1 - 0.2)^4.65 = 0.3543 (Richardson & Zaki 1954). */
static const double check_in_0[N_IN] = {0.0, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81, 0.1};
static const double check_in_1[N_IN] = {0.2, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81, 0.1};
static const sl_check_point checks[] = {
    {check_in_0, OUT_SETTLING, 1600.0 * 9.81 * 1e-8 / 18e-3, 1e-14,
     "Stokes (1851) terminal velocity (rho_s - rho_f) g d^2 / (18 mu), exact at phi = 0"},
    {check_in_1, OUT_HINDRANCE, 0.3543, 2e-4, "Richardson & Zaki (1954): (1-0.2)^4.65 = 0.3543"},
};

/* Richardson & Zaki (1954) exponent from Re_t and d/D. */
static double rz1954_exponent(double re, double dD) {
  if (re < 0.2) return 4.65 + 19.5 * dD;
  if (re < 1.0) return (4.35 + 17.5 * dD) * pow(re, -0.03);
  if (re < 200.0) return (4.45 + 18.0 * dD) * pow(re, -0.1);
  if (re < 500.0) return 4.45 * pow(re, -0.1);
  return 2.39;
}

static int evaluate(const void *state, const sl_eval_args *a) {
  const rz_params *p = state;
  const double *phi = a->in[IN_PHI], *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY], *rho_s = a->in[IN_RHO_S],
               *rho_f = a->in[IN_RHO_F], *mu = a->in[IN_MU_F], *g = a->in[IN_GRAVITY], *dv = a->in[IN_D_VESSEL];
  double *vs = a->out[OUT_SETTLING], *hi = a->out[OUT_HINDRANCE], *ut_out = a->out[OUT_TERMINAL];
  double *dvs = sl_dout(a, N_IN, OUT_SETTLING, IN_PHI), *dhi = hi ? sl_dout(a, N_IN, OUT_HINDRANCE, IN_PHI) : NULL,
         *dut = ut_out ? sl_dout(a, N_IN, OUT_TERMINAL, IN_PHI) : NULL;
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, IN_D_VESSEL);
    if (rc) return rc;
    if (p->packing_cutoff && phi[q] > p->phi_max)
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g above phi_max = %g of the packing cut-off", phi[q],
                     p->phi_max);
    double d = psi[q] * dp[q];
    double re_t;
    double ut = sl_terminal_velocity(p->terminal_velocity, p->u_t, d, rho_s[q], rho_f[q], mu[q], g[q], &re_t);
    double n = p->n;
    if (p->exponent == 1) {
      if (!(d <= dv[q]))
        return sl_fail(a->err, SL_RECOVERABLE, q, "particle diameter %g exceeds the vessel diameter %g", d, dv[q]);
      n = rz1954_exponent(re_t, d / dv[q]);
    } else if (p->exponent == 2) {
      double r = pow(re_t, 0.9);
      n = (5.1 + 0.27 * r) / (1.0 + 0.1 * r);
    }
    double eps = 1.0 - phi[q];
    double f = pow(eps, n), f_phi = -n * pow(eps, n - 1.0);
    if (p->packing_cutoff == 1) {
      double c = 1.0 - phi[q] / p->phi_max;
      f_phi = f_phi * c - f / p->phi_max;
      f *= c;
    } else if (p->packing_cutoff == 2 && phi[q] >= p->phi_max) {
      f = f_phi = 0.0;
    }
    vs[q] = ut * f;
    if (dvs) dvs[q] = ut * f_phi;
    if (hi) hi[q] = f;
    if (dhi) dhi[q] = f_phi;
    if (ut_out) ut_out[q] = ut;
    if (dut) dut[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc richardson_zaki = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_HINDERED_SETTLING,
    .name = "richardson_zaki",
    .version = "1.0.0",
    .summary = "Richardson-Zaki (1954) hindered settling u_t (1-phi)^n, n given or from Re_t",
    .formula =
        "settling_velocity = u_t f(phi),  f = (1 - phi)^n  [x (1 - phi/phi_max) with packing_cutoff = true; 0 at "
        "phi_max with packing_cutoff = step];\n"
        "n given, or Richardson-Zaki (1954): 4.65 + 19.5 d/D (Re_t < 0.2), (4.35 + 17.5 d/D) Re_t^-0.03 (< 1), "
        "(4.45 + 18 d/D) Re_t^-0.1 (< 200), 4.45 Re_t^-0.1 (< 500), 2.39 (>= 500);\n"
        "or Garside & Al-Dibouni (1977): n = (5.1 + 0.27 Re_t^0.9)/(1 + 0.1 Re_t^0.9);  Re_t = rho_f |u_t| "
        "d / mu_f;\n"
        "u_t: given | stokes (rho_s - rho_f) g d^2/(18 mu_f) | schiller_naumann = rowe: (3/4) C_D rho_f u_t^2/d "
        "= |rho_s - rho_f| g;  d = sphericity d_p;  Kynch flux = phi settling_velocity",
    .reference =
        "Richardson & Zaki (1954) Trans. Inst. Chem. Eng. 32:35; Garside & Al-Dibouni (1977) Ind. Eng. "
        "Chem. Process Des. Dev. 16:206; Schiller & Naumann (1933); Rowe (1961); Pringle (2001) eqs "
        "3.24-3.25",
    .validity =
        "monodisperse non-flocculated suspensions, 0 <= phi <= 1 (the data cover phi up to about 0.5; "
        "phi <= phi_max with the packing cut-off); the 1954 correlation jumps at its Re_t limits and its "
        "wall term was fitted for d/D up to about 0.1 (d > D is refused); C_D of the terminal velocity "
        "jumps by +0.39 % at Re = 1000 and ignores the drag crisis",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(rz_params),
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

static const sl_closure_desc *const all[] = {&richardson_zaki};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
