/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Coulomb (sliding) friction of the solids on the wall: the wall's shear stress on the solids is a friction
 * coefficient times the solids' normal stress on the wall,
 *   tau_w = mu_w N tanh(slip_wall/slip_scale),
 * the Coulombic contribution of the sliding-bed models (Wilson 1976, "A model for flow in horizontal pipes with a
 * sliding bed", BHRA Hydrotransport 3; Shook & Roco 1991, "Slurry Flow: Principles and Practice", the Coulombic
 * contribution: the bed's wall friction coefficient eta_s times its normal force on the wall), and the frictional
 * term tau_sn^f tan(phi_w) of Johnson & Jackson's (1987, J. Fluid Mech. 176:67) wall condition (Krampa 2009
 * eq 4.92; the digest's section 2.9), which
 * wall_stress/johnson_jackson leaves out. N is the host's `normal_stress`: the solids' pressure at the first node
 * off the wall (the pipe model: [closure.solids_pressure] and the kinetic theory's, docs/pipe.md). The stress
 * does not depend on the slip speed once the solids slide; tanh(slip_wall/slip_scale) is a regularisation of the
 * sign function at rest (it is 1 to the last bit above slip_wall = 19 slip_scale: 1.9 cm/s by default), so that
 * the stress is continuous and differentiable in slip_wall and vanishes with it.
 *
 * mu_w: sliding-friction coefficients of sand on steel in the slurry literature (Shook & Roco 1991) are about
 * 0.3-0.5; 0.4, the middle of that range, is the default, a choice and not a fit.
 * No value is measured for Krampa's glass beads on his stainless test sections. mu_w = 0 is free slip. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"

typedef struct coulomb_params {
  double mu_w, slip_scale;
} coulomb_params;

enum { IN_SLIP_WALL, IN_NORMAL_STRESS, N_IN };
enum { OUT_TAU_W, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(coulomb_params, mu_w, 0.4, 0.0, 2.0, "1",
                     "wall friction coefficient tan(phi_w) (sand on steel 0.3-0.5: Shook & Roco 1991)"),
    SL_PARAM_REAL_OF(coulomb_params, slip_scale, 1e-3, 1e-9, 1.0, "m s^-1",
                     "regularisation of the sign of the slip: tau_w = mu_w N tanh(slip_wall/slip_scale)"),
};

static const sl_field_desc inputs[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential slip speed of the solids at the wall"},
    {"normal_stress", "Pa", SL_FIELD_DIFF, 100.0, 0.0, 1e9, "normal stress of the solids on the wall"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "solids wall shear stress (magnitude, opposing the slip)"},
};

/* Values by hand (Python, double): sliding, tanh(1000) = 1: 0.4 100 = 40 exactly; at slip_wall = slip_scale:
   0.4 100 tanh(1) = 30.463766238230594. */
static const double check_sliding[N_IN] = {1.0, 100.0};
static const double check_scale[N_IN] = {1e-3, 100.0};
static const sl_check_point checks[] = {
    {check_sliding, OUT_TAU_W, 40.0, 1e-15, "Coulomb's law sliding: tau_w = mu_w N (Shook & Roco 1991), exact"},
    {check_scale, OUT_TAU_W, 30.463766238230594, 1e-13,
     "the regularisation at slip_wall = slip_scale: mu_w N tanh(1), hand-evaluated"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const coulomb_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *u = a->in[IN_SLIP_WALL], *N = a->in[IN_NORMAL_STRESS];
  double *tau = a->out[OUT_TAU_W];
  double *dtau_du = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL), *dtau_dN = sl_dout(a, N_IN, OUT_TAU_W, IN_NORMAL_STRESS);
  for (int32_t q = 0; q < a->Q; ++q) {
    const double x = u[q] / p->slip_scale, t = tanh(x), c = x < 20.0 ? 1.0 / cosh(x) : 0.0;
    tau[q] = p->mu_w * N[q] * t;
    gr_set(dtau_du, q, p->mu_w * N[q] * c * c / p->slip_scale);
    gr_set(dtau_dN, q, p->mu_w * t);
  }
  return SL_OK;
}

static const sl_closure_desc coulomb = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "coulomb",
    .version = "1.0.0",
    .summary = "Coulomb sliding friction of the solids on the wall: mu_w times their normal stress",
    .formula =
        "tau_w = mu_w normal_stress tanh(slip_wall/slip_scale)\n"
        "(= mu_w normal_stress to the last bit once slip_wall > 19 slip_scale)",
    .reference =
        "Wilson (1976) BHRA Hydrotransport 3; Shook & Roco (1991) Slurry Flow; Johnson & Jackson (1987) "
        "J. Fluid Mech. 176:67 (the frictional term of Krampa 2009 eq 4.92)",
    .validity =
        "solids in sustained contact with the wall (a sliding bed, a dense layer), slip_wall > 0; the host's "
        "normal_stress is the solids' pressure at the wall node; mu_w a property of the particle and wall "
        "materials (0.3-0.5 for sand on steel)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(coulomb_params),
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

static const sl_closure_desc *const all[] = {&coulomb};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
