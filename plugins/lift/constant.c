/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A constant lift coefficient, F_L = C_L rho_f phi (u_f - u_s) x curl u_f
 * (Drew & Lahey 1979, Int. J. Multiphase Flow 5:243, eq 41; the lift of a
 * sphere in a weak inviscid shear, Auton 1987, J. Fluid Mech. 183:199:
 * C_L = 1/2), optionally damped to 0 at the wall by Shaver & Podowski's
 * (2015) step (lift/lift_common.h). With it the pipe model's radial solids
 * balance has a closed-form check (tests/models/test_pipe_lift.c) and a
 * coefficient of 0 returns the balance without lift. */
#include <math.h>
#include <sluice/closure.h>

#include "lift/lift_common.h"

typedef struct constant_params {
  double coefficient;
  int32_t wall_damping;
} constant_params;

enum { IN_SHEAR_RATE, IN_WALL_DISTANCE, IN_D_P, N_IN };
enum { OUT_C_L, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(constant_params, coefficient, 0.5, -10.0, 10.0, "1",
                     "C_L (Auton 1987: 1/2 for a sphere in a weak inviscid shear; 0: no lift)"),
    SL_PARAM_BOOL_OF(constant_params, wall_damping, 0,
                     "damp C_L to 0 within one particle diameter of the wall (Shaver & Podowski 2015)"),
};

static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", 0, 10.0, 0.0, 1e8, "the fluid's shear rate |du_f/dr| (C_L does not depend on it)"},
    {"wall_distance", "m", 0, 1e-3, 1e-9, 10.0, "distance of the point from the wall"},
    {"d_p", "m", 0, 5e-4, 1e-8, 1.0, "particle diameter"},
};

static const sl_field_desc outputs[] = {
    {"C_L", "1", 0, 0, 0, 0, "lift coefficient of F_L = C_L rho_f phi (u_f - u_s) x curl u_f"},
};

static const double check_in_0[N_IN] = {10.0, 1e-3, 5e-4}; /* two diameters off the wall: undamped */
static const sl_check_point checks[] = {
    {check_in_0, OUT_C_L, 0.5, 1e-15, "Auton (1987): C_L = 1/2 for a sphere in a weak inviscid shear"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const constant_params *p = state;
  double *cl = a->out[OUT_C_L];
  for (int32_t q = 0; q < a->Q; ++q) {
    const int rc = lift_check_inputs(a, inputs, N_IN, q);
    if (rc) return rc;
    cl[q] = p->coefficient * (p->wall_damping ? lift_wall_damping(a->in[IN_WALL_DISTANCE][q], a->in[IN_D_P][q]) : 1.0);
  }
  return SL_OK;
}

static const sl_closure_desc constant = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_LIFT,
    .name = "constant",
    .version = "1.0.0",
    .summary = "a constant lift coefficient C_L (Auton 1987: 1/2), optionally damped at the wall",
    .formula =
        "C_L = coefficient (x f(y/d_p) with wall_damping: 0 below 1/2, 3x^2 - 2x^3 of x = 2y/d_p - 1, 1 "
        "above 1)",
    .reference =
        "Drew & Lahey (1979) Int. J. Multiphase Flow 5:243, eq 41; Auton (1987) J. Fluid Mech. 183:199; "
        "the damping: Shaver & Podowski (2015) Trans. Am. Nucl. Soc. 112:1368",
    .validity = "a weak shear of an inviscid flow (Auton); a prescribed coefficient otherwise",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(constant_params),
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

static const sl_closure_desc *const all[] = {&constant};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
