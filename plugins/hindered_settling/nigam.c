/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Nigam (1999) hindered settling: the batch-settling velocity of the solids
 * relative to the mixture volume flux, u_t f(phi), so that the Kynch flux is
 * phi u_t f(phi) (architecture.md section 3, `mixture`).
 *
 * Nigam (1999), Numerical Modeling of Suspension Flows, PhD thesis, MIT,
 * eqs 2.20, 2.25 and 2.36: a
 * particle in creeping motion feels the suspension viscosity mu_f mu_r(phi)
 * and the buoyancy of the mixture, (rho_s - rho_mix) = (1 - phi)(rho_s -
 * rho_f); with j_R = phi (1 - phi) v_R the relative flux, the solids move
 * relative to the mixture flux at u_St f(phi) with
 *   f(phi)    = (1 - phi)^2 / mu_r(phi),
 *   mu_r(phi) = (1 - phi/phi_max)^(-K phi_max)           (Krieger, eq 2.18/2.36),
 *   phi_max = 0.68, K = 2.5 (Einstein 1 + 2.5 phi at phi -> 0; the migration runs use K = 2.6765).
 * There is no separate Richardson-Zaki exponent: for small phi,
 * f = 1 - (2 + K) phi, an effective n = 4.5; f is practically (1-phi)^4.65
 * up to phi = 0.3 and vanishes at phi_max, where a sediment forms
 * (phi > phi_max is refused). The thesis uses the Stokes velocity
 * u_St = 2 eps a^2 g / (9 nu_C) = (rho_s - rho_f) g d^2 / (18 mu_f), which
 * is negative (rising) for its buoyant particles.
 *
 * u_t of one particle of diameter d = sphericity d_p, signed (positive along
 * the body force for rho_s > rho_f). `terminal_velocity`:
 *   stokes (default, the thesis)  u_t = (rho_s - rho_f) g d^2 / (18 mu_f);
 *   given                         u_t is the parameter u_t;
 *   schiller_naumann | rowe       (3/4) C_D rho_f u_t^2 / d = |rho_s - rho_f| g, C_D = 24/Re (1 + 0.15 Re^0.687)
 *                                 for Re < 1000, 0.44 above (one correlation, two names); Newton to 1e-15. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

typedef struct nigam_params {
  double phi_max;             /* 0.68 */
  double intrinsic_viscosity; /* K = 2.5 */
  int32_t terminal_velocity;  /* SL_UT_* */
  double u_t;                 /* given terminal velocity */
} nigam_params;

enum { IN_PHI, IN_D_P, IN_SPHERICITY, IN_RHO_S, IN_RHO_F, IN_MU_F, IN_GRAVITY, N_IN };
enum { OUT_SETTLING, OUT_HINDRANCE, OUT_TERMINAL, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(nigam_params, phi_max, 0.68, 0.5, 1.0, "1", "maximum packing alpha_m of the Krieger viscosity"),
    SL_PARAM_REAL_OF(nigam_params, intrinsic_viscosity, 2.5, 2.0, 10.0, "1",
                     "intrinsic viscosity K of mu_r = (1 - phi/phi_max)^(-K phi_max); 2.5 is Einstein's"),
    SL_PARAM_ENUM_OF(nigam_params, terminal_velocity, SL_UT_STOKES, SL_UT_CHOICES,
                     "single-particle terminal velocity: given (u_t), stokes (the thesis), schiller_naumann or rowe"),
    SL_PARAM_REAL_OF(nigam_params, u_t, 0.01, -100.0, 100.0, "m s^-1",
                     "terminal velocity when terminal_velocity = given (positive along the body force)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.1, 0.0, 0.68, "solids volume fraction (at most the parameter phi_max)"},
    {"d_p", "m", 0, 1e-4, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
    {"rho_s", "kg m^-3", 0, 2600.0, 1e-3, 1e5, "particle density"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"gravity", "m s^-2", 0, 9.81, 0.0, 1e5, "magnitude of the body force per unit mass"},
};

static const sl_field_desc outputs[] = {
    {"settling_velocity", "m s^-1", 0, 0, 0, 0,
     "u_t f(phi), solids velocity relative to the mixture volume flux, along the body force"},
    {"hindrance", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "f(phi) = (1 - phi)^2 / mu_r(phi)"},
    {"terminal_velocity", "m s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "u_t of one particle"},
};

/* h(alpha) of Nigam (1999) eq 2.36 (K = 2.5, alpha_m = 0.68):
 * 0.6181 at alpha = 0.1, 0.1822 at 0.3; and the Stokes limit at phi = 0. */
static const double check_in_0[N_IN] = {0.1, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81};
static const double check_in_1[N_IN] = {0.3, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81};
static const double check_in_2[N_IN] = {0.0, 1e-4, 1.0, 2600.0, 1000.0, 1e-3, 9.81};
static const sl_check_point checks[] = {
    {check_in_0, OUT_HINDRANCE, 0.6181, 1e-4, "Nigam (1999) eq 2.36, K = 2.5: h(0.1) = 0.6181"},
    {check_in_1, OUT_HINDRANCE, 0.1822, 3e-4, "Nigam (1999) eq 2.36, K = 2.5: h(0.3) = 0.1822"},
    {check_in_2, OUT_SETTLING, 1600.0 * 9.81 * 1e-8 / 18e-3, 1e-14,
     "Stokes velocity U_St = 2 eps a^2 g / (9 nu_C) (Nigam eq 2.25), exact at phi = 0"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const nigam_params *p = state;
  const double *phi = a->in[IN_PHI], *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY], *rho_s = a->in[IN_RHO_S],
               *rho_f = a->in[IN_RHO_F], *mu = a->in[IN_MU_F], *g = a->in[IN_GRAVITY];
  double *vs = a->out[OUT_SETTLING], *hi = a->out[OUT_HINDRANCE], *ut_out = a->out[OUT_TERMINAL];
  double *dvs = sl_dout(a, N_IN, OUT_SETTLING, IN_PHI), *dhi = hi ? sl_dout(a, N_IN, OUT_HINDRANCE, IN_PHI) : NULL,
         *dut = ut_out ? sl_dout(a, N_IN, OUT_TERMINAL, IN_PHI) : NULL;
  const double pm = p->phi_max, e = p->intrinsic_viscosity * p->phi_max; /* K phi_max >= 1 */
  for (int32_t q = 0; q < a->Q; ++q) {
    /* phi is checked against the parameter phi_max; its declared range shows the default. */
    if (!(phi[q] >= 0.0 && phi[q] <= pm))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, phi_max = %g]", phi[q], pm);
    int rc = sl_check_inputs_from(inputs, IN_PHI + 1, N_IN, a, q, -1);
    if (rc) return rc;
    double d = psi[q] * dp[q];
    double re_t;
    double ut = sl_terminal_velocity(p->terminal_velocity, p->u_t, d, rho_s[q], rho_f[q], mu[q], g[q], &re_t);
    double eps = 1.0 - phi[q], c = 1.0 - phi[q] / pm;
    /* f = eps^2 c^e, e = K phi_max; df/dphi = -2 eps c^e - (e/pm) eps^2 c^(e-1). */
    double ce1 = pow(c, e - 1.0);
    double f = eps * eps * c * ce1;
    double f_phi = -eps * ce1 * (2.0 * c + e / pm * eps);
    vs[q] = ut * f;
    if (dvs) dvs[q] = ut * f_phi;
    if (hi) hi[q] = f;
    if (dhi) dhi[q] = f_phi;
    if (ut_out) ut_out[q] = ut;
    if (dut) dut[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc nigam = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_HINDERED_SETTLING,
    .name = "nigam",
    .version = "1.0.0",
    .summary = "Nigam (1999) hindered settling u_t (1-phi)^2 / mu_r(phi), Krieger relative viscosity",
    .formula =
        "settling_velocity = u_t f(phi),  f = (1 - phi)^2 / mu_r,  mu_r = (1 - phi/phi_max)^(-K phi_max),\n"
        "phi_max = 0.68, K = 2.5;  u_t: stokes (rho_s - rho_f) g d^2/(18 mu_f) (default) | given | "
        "schiller_naumann = rowe: (3/4) C_D rho_f u_t^2/d = |rho_s - rho_f| g;  d = sphericity d_p;  "
        "Kynch flux = phi settling_velocity",
    .reference =
        "Nigam (1999) Numerical Modeling of Suspension Flows, PhD thesis, MIT, eqs 2.18, 2.20, 2.25, 2.36; "
        "Krieger & Dougherty (1959) Trans. Soc. Rheol. 3:137",
    .validity =
        "quasi-steady creeping motion of the particles relative to the fluid (particle Re << 1 with the "
        "default Stokes u_t), 0 <= phi <= phi_max (phi > phi_max is refused); f -> 0 at phi_max",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(nigam_params),
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

static const sl_closure_desc *const all[] = {&nigam};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
