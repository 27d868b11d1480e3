/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The shear lift on a sphere, Saffman (1965, J. Fluid Mech. 22:385; the
 * constant 6.46 of the corrigendum, 1968, J. Fluid Mech. 31:624) with Mei's
 * (1992, Int. J. Multiphase Flow 18:145, his fit of Dandy & Dwyer 1990) correction for the particle
 * Reynolds number, in the coefficient form of F_L = C_L rho_f phi (u_f - u_s)
 * x curl u_f (per unit volume of particles, the force 6.46 mu a^2 |u_f - u_s|
 * (gdot/nu)^(1/2) over pi d^3/6):
 *   C_L = (3/(2 pi)) 6.46 f / Re_g^(1/2),  Re_g = rho_f gdot d^2/mu_f,
 *   Re_p = rho_f |u_f - u_s| d/mu_f,  beta = Re_g/(2 Re_p) = d gdot/(2 |u_f - u_s|),
 *   f = (1 - 0.3314 beta^(1/2)) exp(-Re_p/10) + 0.3314 beta^(1/2)   Re_p <= 40,
 *   f = 0.0524 (beta Re_p)^(1/2)                                     Re_p > 40,
 * f -> 1 (Saffman) as Re_p -> 0 at a fixed shear: written e + 0.3314 (Re_g/2)^(1/2)
 * (1 - e)/Re_p^(1/2) with e = exp(-Re_p/10), finite at Re_p = 0. The force
 * C_L gdot ~ gdot^(1/2) vanishes at zero shear, where C_L diverges: the closure
 * refuses shear_rate below 1e-9 s^-1. A lagging particle (u_s < u_f along the
 * flow) is pushed towards the faster fluid, a leading one away from it.
 * With correction = mclaughlin, f is instead McLaughlin's (1991, J. Fluid Mech. 224:261) weak-shear factor
 * J(eps)/2.255, eps = Re_g^(1/2)/Re_p, in Mei's (1992) fit
 *   J = 0.6765 {1 + tanh[2.5 (log10 eps + 0.191)]} {0.667 + tanh[6 (eps - 0.32)]},
 * J -> 2.255 (Saffman's) as eps -> inf and -> 0 as eps -> 0: the lift vanishes where the shear is weak
 * against the slip (a pipe's axis), where Saffman's C_L Re_g^(-1/2) would stay singular.
 * wall_damping (default on) multiplies C_L by Shaver & Podowski's (2015) step
 * (lift/lift_common.h): Saffman's and Mei's flows are unbounded, and the
 * wall's own lift on a particle that nearly touches it (Wilson & Sellgren
 * 2003, the repulsion Krampa's review mentions) is not theirs. */
#include <math.h>
#include <sluice/closure.h>

#include "lift/lift_common.h"

typedef struct saffman_mei_params {
  int32_t wall_damping;
  int32_t correction; /* 0 Mei's finite Re_p, 1 McLaughlin's weak shear, 2 none (Saffman's own) */
} saffman_mei_params;

enum { IN_SHEAR_RATE, IN_SLIP, IN_WALL_DISTANCE, IN_RHO_F, IN_MU_F, IN_D_P, N_IN };
enum { OUT_C_L, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_BOOL_OF(saffman_mei_params, wall_damping, 1,
                     "damp C_L to 0 within one particle diameter of the wall (Shaver & Podowski 2015)"),
    SL_PARAM_ENUM_OF(saffman_mei_params, correction, 1, "mei|mclaughlin|none",
                     "Saffman's C_L corrected for a finite Re_p (mei), for a weak shear, Re_g^(1/2)/Re_p small "
                     "(mclaughlin, Mei's fit of McLaughlin's J: well-posed on a pipe's axis), or not (none)"),
};

static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", 0, 100.0, 1e-9, 1e8, "the fluid's shear rate |du_f/dr| (C_L diverges at 0)"},
    {"slip", "m s^-1", 0, 0.02, 0.0, 100.0, "slip speed |u_f - u_s|"},
    {"wall_distance", "m", 0, 1e-3, 1e-9, 10.0, "distance of the point from the wall"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 5e-4, 1e-8, 1.0, "particle diameter"},
};

static const sl_field_desc outputs[] = {
    {"C_L", "1", 0, 0, 0, 0, "lift coefficient of F_L = C_L rho_f phi (u_f - u_s) x curl u_f"},
};

/* Re_g = 25, Re_p = 10 (eps = 0.5), two diameters off the wall, the default correction (McLaughlin's): 3 6.46
   J(0.5)/(2.255 2 pi 5), J(0.5) = 0.6765 (1 + tanh(2.5 (log10 0.5 + 0.191))) (0.667 + tanh(1.08)), by hand */
static const double check_in_0[N_IN] = {100.0, 0.02, 1e-3, 1000.0, 1e-3, 5e-4};
/* no slip (eps infinite): Saffman's own, 3 6.46/(2 pi 5) */
static const double check_in_1[N_IN] = {100.0, 0.0, 1e-3, 1000.0, 1e-3, 5e-4};
/* Re_p = 50, eps = 0.1: McLaughlin's J is slightly negative below eps of about 0.2 (McLaughlin 1991, Fig. 4) */
static const double check_in_2[N_IN] = {100.0, 0.1, 1e-3, 1000.0, 1e-3, 5e-4};
/* the centre half a diameter off the wall: damped to 0 */
static const double check_in_3[N_IN] = {100.0, 0.02, 2.5e-4, 1000.0, 1e-3, 5e-4};
/* Mei's finite-Re_p branch (correction = mei) is checked by tests/models/test_pipe_lift.c (`sluice closure eval`):
   the battery's points take the default parameters */
static const sl_check_point checks[] = {
    {check_in_0, OUT_C_L, 0.1977179433315671, 1e-13, "Saffman (1965, 1968) with McLaughlin's J (Mei 1992), eps = 0.5"},
    {check_in_1, OUT_C_L, 0.6168845594241863, 1e-13, "Saffman (1965, corrigendum 1968): 6.46, the weak-slip limit"},
    {check_in_2, OUT_C_L, -0.0012724946366381633, 1e-11, "McLaughlin (1991) J in Mei's (1992) fit, eps = 0.1"},
    {check_in_3, OUT_C_L, 0.0, 1e-15, "Shaver & Podowski (2015): C_L = 0 at y = d_p/2"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const saffman_mei_params *p = state;
  double *cl = a->out[OUT_C_L];
  for (int32_t q = 0; q < a->Q; ++q) {
    const int rc = lift_check_inputs(a, inputs, N_IN, q);
    if (rc) return rc;
    const double nu = a->in[IN_MU_F][q] / a->in[IN_RHO_F][q], d = a->in[IN_D_P][q];
    const double re_g = a->in[IN_SHEAR_RATE][q] * d * d / nu, re_p = a->in[IN_SLIP][q] * d / nu;
    double f;
    if (p->correction == 2) f = 1.0;
    else if (p->correction == 1) { /* J(eps)/2.255, eps = Re_g^(1/2)/Re_p; J -> 2.255 (Saffman) as eps -> inf */
      const double eps = re_p > 0.0 ? sqrt(re_g) / re_p : HUGE_VAL;
      f = eps == HUGE_VAL
              ? 1.0
              : 0.6765 * (1.0 + tanh(2.5 * (log10(eps) + 0.191))) * (0.667 + tanh(6.0 * (eps - 0.32))) / 2.255;
    } else if (re_p <= 40.0) { /* (1 - alpha) e + alpha = e + alpha (1 - e), alpha (1 - e) -> 0 as Re_p -> 0 */
      const double e = exp(-0.1 * re_p);
      f = e + (re_p > 0.0 ? 0.3314 * sqrt(0.5 * re_g / re_p) * -expm1(-0.1 * re_p) : 0.0);
    } else f = 0.0524 * sqrt(0.5 * re_g);
    const double damp = p->wall_damping ? lift_wall_damping(a->in[IN_WALL_DISTANCE][q], d) : 1.0;
    cl[q] = 3.0 * 6.46 * f / (2.0 * 3.14159265358979323846 * sqrt(re_g)) * damp;
  }
  return SL_OK;
}

static const sl_closure_desc saffman_mei = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_LIFT,
    .name = "saffman_mei",
    .version = "1.0.0",
    .summary =
        "Saffman's (1965) shear lift, corrected for a weak shear (McLaughlin 1991) or a finite Re_p (Mei "
        "1992), damped at the wall",
    .formula =
        "C_L = (3/(2 pi)) 6.46 f / Re_g^(1/2), Re_g = rho_f gdot d^2/mu_f, Re_p = rho_f slip d/mu_f\n"
        "mclaughlin: f = J(eps)/2.255, eps = Re_g^(1/2)/Re_p, J = 0.6765 {1 + tanh[2.5 (log10 eps + 0.191)]} "
        "{0.667 + tanh[6 (eps - 0.32)]}\n"
        "mei: f = (1 - 0.3314 beta^(1/2)) exp(-Re_p/10) + 0.3314 beta^(1/2) (Re_p <= 40), 0.0524 (beta "
        "Re_p)^(1/2) above, beta = Re_g/(2 Re_p)\n"
        "x f_w(y/d_p): 0 below 1/2, 3x^2 - 2x^3 of x = 2y/d_p - 1, 1 above 1 (wall_damping)",
    .reference =
        "Saffman (1965) J. Fluid Mech. 22:385 and (1968) 31:624; McLaughlin (1991) J. Fluid Mech. 224:261; "
        "Mei (1992) Int. J. Multiphase Flow 18:145 (his fits of McLaughlin's J and of Dandy & Dwyer 1990); "
        "Shaver & Podowski (2015) Trans. Am. Nucl. Soc. 112:1368",
    .validity =
        "Saffman: Re_p << Re_g^(1/2) << 1; McLaughlin: Re_p, Re_g << 1 at any eps; Mei's finite-Re_p fit: 0.1 "
        "<= Re_p <= 100, 0.005 <= beta <= 0.4; beyond, an extrapolation",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(saffman_mei_params),
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

static const sl_closure_desc *const all[] = {&saffman_mei};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
