/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The drag that reproduces Richardson-Zaki exactly inside the two-fluid
 * momentum equations, as the momentum-exchange coefficient K with
 * F_s = K (u_f - u_s) (architecture.md section 4). eps = 1 - phi.
 *
 * Steady homogeneous fluidisation or sedimentation (uniform eps, no
 * acceleration, solids pressure constant): the mixture equation gives
 * dp/dy = -rhobar g, the fluid equation eps dp/dy = -eps rho_f g - K V_r,
 * so  K V_r = phi eps (rho_s - rho_f) g,  with superficial U = eps V_r
 * (the steady balance of Pringle 2001, eq 4.20). Richardson & Zaki (1954), Trans.
 * Inst. Chem. Eng. 32:35, U = u_t eps^n, holds exactly when
 *   K = phi eps^(2-n) (rho_s - rho_f) g / u_t = phi eps^(2-n) k_t,
 * k_t = |rho_s - rho_f| g / |u_t| the drag per unit particle volume and
 * unit velocity of one sphere at its terminal velocity:
 *   terminal_velocity = stokes:  k_t = 18 mu_f / d^2 (no density needed;
 *                                n = 4.65 is then the Wen-Yu/Gidaspow Stokes
 *                                limit 18 mu_f phi eps^-2.65 / d^2),
 *   schiller_naumann | rowe:     u_t from the force balance with C_D =
 *                                24/Re (1 + 0.15 Re^0.687), 0.44 above
 *                                Re = 1000 (Newton iteration, 1e-15), and
 *                                k_t = |drho| g / |u_t| (18 mu_f/d^2 when
 *                                drho g = 0, its limit),
 *   given:                       k_t = |drho| g / u_t with u_t a parameter
 *                                (K = 0 when drho g = 0).
 * d = sphericity d_p. K does not depend on the slip: it is the secant drag
 * through the Richardson-Zaki equilibrium point of each eps, exact there,
 * an extrapolation at other slips (Pringle 2001, section 3.1.2(iii)).
 * Buoyant particles (rho_s < rho_f) use |rho_s - rho_f|: they rise with
 * the same law. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

typedef struct rzc_params {
  double n;                  /* 4.65 */
  int32_t terminal_velocity; /* SL_UT_* */
  double u_t;                /* given terminal velocity */
} rzc_params;

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, IN_RHO_S, IN_GRAVITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(rzc_params, n, 4.65, 1.0, 10.0, "1", "Richardson-Zaki exponent in U = u_t (1-phi)^n"),
    SL_PARAM_ENUM_OF(rzc_params, terminal_velocity, SL_UT_STOKES, SL_UT_CHOICES,
                     "single-particle terminal velocity: given (u_t), stokes, schiller_naumann or rowe (the same "
                     "C_D, Pringle eq 3.24)"),
    SL_PARAM_REAL_OF(rzc_params, u_t, 0.01, 1e-12, 100.0, "m s^-1",
                     "terminal velocity of one particle, used when terminal_velocity = given"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s| (K does not depend on it)"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
    {"rho_s", "kg m^-3", 0, 2600.0, 1e-3, 1e5, "particle density"},
    {"gravity", "m s^-2", 0, 9.81, 0.0, 1e5, "magnitude of the body force per unit mass"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* Stokes u_t, n = 4.65, mu/d^2 = 1e3, rho_s 2600 / rho_f 1000: the Wen-Yu-consistent
 * K/(mu/d^2) is 13.9 at porosity 0.70 and 6.50 at 0.80. */
static const double check_in_0[N_IN] = {0.3, 0.01, 1000.0, 1e-3, 1e-3, 1.0, 2600.0, 9.81};
static const double check_in_1[N_IN] = {0.2, 0.01, 1000.0, 1e-3, 1e-3, 1.0, 2600.0, 9.81};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 13.9e3, 4e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.70: 13.9 mu/d^2"},
    {check_in_1, OUT_K, 6.50e3, 1e-3, "Wen-Yu-consistent (Gidaspow 1994), Stokes limit, n = 0.80: 6.50 mu/d^2"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const rzc_params *p = state;
  const double *phi = a->in[IN_PHI], *rho = a->in[IN_RHO_F], *mu = a->in[IN_MU_F], *dp = a->in[IN_D_P],
               *psi = a->in[IN_SPHERICITY], *rho_s = a->in[IN_RHO_S], *g = a->in[IN_GRAVITY];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  const double n = p->n;
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    double d = psi[q] * dp[q];
    double eps = 1.0 - phi[q];
    double buoyant = fabs(rho_s[q] - rho[q]) * g[q];
    double kt;
    if (p->terminal_velocity == SL_UT_STOKES) {
      kt = 18.0 * mu[q] / (d * d);
    } else if (p->terminal_velocity == SL_UT_GIVEN) {
      kt = buoyant / p->u_t;
    } else {
      double re_t;
      double ut = fabs(sl_terminal_velocity(p->terminal_velocity, p->u_t, d, rho_s[q], rho[q], mu[q], g[q], &re_t));
      kt = ut > 0.0 ? buoyant / ut : 18.0 * mu[q] / (d * d);
    }
    double h = pow(eps, 2.0 - n); /* eps^(2-n) */
    K[q] = kt * phi[q] * h;
    if (dK_dphi) dK_dphi[q] = kt * h * (1.0 - phi[q] * (2.0 - n) / eps);
    if (dK_dslip) dK_dslip[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc richardson_zaki_consistent = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "richardson_zaki_consistent",
    .version = "1.0.0",
    .summary = "drag that makes a homogeneous bed obey Richardson-Zaki U = u_t (1-phi)^n exactly",
    .formula =
        "K = phi eps^(2-n) |rho_s - rho_f| g / |u_t|,  eps = 1 - phi  (from K V_r = phi eps drho g, U = eps V_r "
        "= u_t eps^n);\n"
        "stokes: |drho| g/|u_t| = 18 mu_f / d^2;  schiller_naumann/rowe: u_t from (3/4) C_D rho_f u_t^2/d = "
        "|drho| g;  given: u_t a parameter;  d = sphericity d_p",
    .reference =
        "Richardson & Zaki (1954) Trans. Inst. Chem. Eng. 32:35; Pringle (2001) eq 4.20 "
        "(steady balance); Gidaspow (1994) ch. 5 (Stokes limit of Wen-Yu)",
    .validity =
        "homogeneous suspensions and fluidised beds near their Richardson-Zaki equilibrium, phi <= 0.74; "
        "K does not depend on the slip, so transients away from equilibrium are an extrapolation; "
        "K = 0 for terminal_velocity = given when rho_s = rho_f or g = 0",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(rzc_params),
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

static const sl_closure_desc *const all[] = {&richardson_zaki_consistent};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
