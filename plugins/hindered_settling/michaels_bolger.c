/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Michaels-Bolger hindered settling: the batch-settling velocity of the
 * solids relative to the mixture volume flux, u_t f(phi), so that the Kynch
 * flux is phi u_t f(phi) (architecture.md section 3, `mixture`).
 *
 * Michaels & Bolger (1962), Ind. Eng. Chem. Fundam. 1:24, for flocculated
 * suspensions: Richardson-Zaki with the volume fraction of the aggregates,
 * phi / phi_max, in place of phi,
 *   f(phi) = (1 - phi/phi_max)^k,   k = 4.65 (the Richardson-Zaki viscous exponent),
 * where 1/phi_max is the aggregate volume per unit solids volume, so that
 * settling stops at phi_max (the form used with k = 4.65 by PDAC and
 * IMEX-SfloW2D; OpenFOAM's MichaelsBolger relative-velocity model adds a
 * constant a0 to it). phi > phi_max is refused.
 *
 * u_t, the terminal velocity of one particle (or floc) of diameter
 * d = sphericity d_p, is signed: positive along the body force for
 * rho_s > rho_f. `terminal_velocity`:
 *   given                      u_t is the parameter u_t;
 *   stokes                     u_t = (rho_s - rho_f) g d^2 / (18 mu_f);
 *   schiller_naumann | rowe    (3/4) C_D rho_f u_t^2 / d = |rho_s - rho_f| g, C_D = 24/Re (1 + 0.15 Re^0.687)
 *                              for Re < 1000, 0.44 above (one correlation, two names); Newton to 1e-15. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

typedef struct mb_params {
  double phi_max;            /* 0.64 */
  double k;                  /* 4.65 */
  int32_t terminal_velocity; /* SL_UT_* */
  double u_t;                /* given terminal velocity */
} mb_params;

enum { IN_PHI, IN_D_P, IN_SPHERICITY, IN_RHO_S, IN_RHO_F, IN_MU_F, IN_GRAVITY, N_IN };
enum { OUT_SETTLING, OUT_HINDRANCE, OUT_TERMINAL, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(mb_params, phi_max, 0.64, 0.01, 1.0, "1",
                     "solids fraction at which the aggregates fill space and settling stops"),
    SL_PARAM_REAL_OF(mb_params, k, 4.65, 1.0, 20.0, "1", "exponent k of (1 - phi/phi_max)^k"),
    SL_PARAM_ENUM_OF(mb_params, terminal_velocity, SL_UT_STOKES, SL_UT_CHOICES,
                     "single-particle terminal velocity: given (u_t), stokes, schiller_naumann or rowe (the same C_D)"),
    SL_PARAM_REAL_OF(mb_params, u_t, 0.01, -100.0, 100.0, "m s^-1",
                     "terminal velocity when terminal_velocity = given (positive along the body force)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.1, 0.0, 0.64, "solids volume fraction (at most the parameter phi_max)"},
    {"d_p", "m", 0, 1e-4, 1e-8, 1.0, "particle (floc) diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
    {"rho_s", "kg m^-3", 0, 2600.0, 1e-3, 1e5, "particle (floc) density"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"gravity", "m s^-2", 0, 9.81, 0.0, 1e5, "magnitude of the body force per unit mass"},
};

static const sl_field_desc outputs[] = {
    {"settling_velocity", "m s^-1", 0, 0, 0, 0,
     "u_t f(phi), solids velocity relative to the mixture volume flux, along the body force"},
    {"hindrance", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "f(phi) = (1 - phi/phi_max)^k"},
    {"terminal_velocity", "m s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "u_t of one particle"},
};

/* 1. phi = 0: Stokes terminal velocity, exact. 2. phi = phi_max: f = 0 exactly. */
static const double check_in_0[N_IN] = {0.0, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81};
static const double check_in_1[N_IN] = {0.64, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81};
static const sl_check_point checks[] = {
    {check_in_0, OUT_SETTLING, 1600.0 * 9.81 * 1e-8 / 18e-3, 1e-14,
     "Stokes (1851) terminal velocity (rho_s - rho_f) g d^2 / (18 mu), exact at phi = 0"},
    {check_in_1, OUT_HINDRANCE, 0.0, 0.0, "Michaels & Bolger (1962): settling stops at phi_max, f = 0 exactly"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const mb_params *p = state;
  const double *phi = a->in[IN_PHI], *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY], *rho_s = a->in[IN_RHO_S],
               *rho_f = a->in[IN_RHO_F], *mu = a->in[IN_MU_F], *g = a->in[IN_GRAVITY];
  double *vs = a->out[OUT_SETTLING], *hi = a->out[OUT_HINDRANCE], *ut_out = a->out[OUT_TERMINAL];
  double *dvs = sl_dout(a, N_IN, OUT_SETTLING, IN_PHI), *dhi = hi ? sl_dout(a, N_IN, OUT_HINDRANCE, IN_PHI) : NULL,
         *dut = ut_out ? sl_dout(a, N_IN, OUT_TERMINAL, IN_PHI) : NULL;
  for (int32_t q = 0; q < a->Q; ++q) {
    /* phi is checked against the parameter phi_max; its declared range shows the default. */
    if (!(phi[q] >= 0.0 && phi[q] <= p->phi_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, phi_max = %g]", phi[q], p->phi_max);
    int rc = sl_check_inputs_from(inputs, IN_PHI + 1, N_IN, a, q, -1);
    if (rc) return rc;
    double d = psi[q] * dp[q];
    double re_t;
    double ut = sl_terminal_velocity(p->terminal_velocity, p->u_t, d, rho_s[q], rho_f[q], mu[q], g[q], &re_t);
    double c = 1.0 - phi[q] / p->phi_max;
    double f = pow(c, p->k), f_phi = -p->k * pow(c, p->k - 1.0) / p->phi_max;
    vs[q] = ut * f;
    if (dvs) dvs[q] = ut * f_phi;
    if (hi) hi[q] = f;
    if (dhi) dhi[q] = f_phi;
    if (ut_out) ut_out[q] = ut;
    if (dut) dut[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc michaels_bolger = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_HINDERED_SETTLING,
    .name = "michaels_bolger",
    .version = "1.0.0",
    .summary = "Michaels-Bolger (1962) hindered settling u_t (1 - phi/phi_max)^k",
    .formula =
        "settling_velocity = u_t f(phi),  f = (1 - phi/phi_max)^k,  k = 4.65, phi_max = 0.64;\n"
        "u_t: given | stokes (rho_s - rho_f) g d^2/(18 mu_f) | schiller_naumann = rowe: (3/4) C_D rho_f u_t^2/d "
        "= |rho_s - rho_f| g;  d = sphericity d_p;  Kynch flux = phi settling_velocity",
    .reference =
        "Michaels & Bolger (1962) Ind. Eng. Chem. Fundam. 1:24; Richardson & Zaki (1954) Trans. Inst. Chem. "
        "Eng. 32:35 (k = 4.65)",
    .validity =
        "flocculated suspensions below the gel point, 0 <= phi <= phi_max (phi > phi_max is refused); "
        "phi_max is the reciprocal aggregate volume ratio, a fitted property of the suspension",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(mb_params),
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

static const sl_closure_desc *const all[] = {&michaels_bolger};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
