/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Johnson & Jackson (1987) partial-slip wall condition for the solids phase:
 * the shear stress transmitted by particle-wall collisions and the
 * granular-energy flux through the wall,
 *   tau_w      = (pi/6) sqrt(3) specularity (phi/phi_max) rho_s g0 sqrt(theta) u_slip
 *   theta_flux = (pi/6) sqrt(3) (phi/phi_max) rho_s g0 sqrt(theta)
 *                [ specularity u_slip^2 - (3/2)(1 - e_w^2) theta ]
 * Johnson & Jackson (1987) J. Fluid Mech. 176:67-93; Krampa (2009) eqs
 * 4.92-4.93, which carry the 1/C_max factor, as do the
 * forms of MFiX (calc_grbdry.f, BC_JJ_PS) and Fluent; the factor phi/phi_max
 * is the areal density of particles next to the wall relative to packing.
 * The frictional wall term tau_sn^f tan(phi_w) of (4.92) is not included
 * (it needs the frictional normal stress at the wall; add it in the host if
 * frictional stress is active). specularity = 0 gives free slip, 1 a rough
 * wall; no value is given by Krampa (2009); peer-code examples
 * use 0.01-0.6.
 *
 * theta_flux is -kappa d(theta)/dn with n the unit normal pointing from the
 * wall into the flow: positive when slip generates more granular energy than
 * inelastic wall collisions dissipate (the wall heats the particles).
 * tau_w is the magnitude of the stress on the solids, opposing the slip, and
 * is linear in the slip speed. g0 is a parameter (kinetic.h), by default
 * Lun & Savage with phi_max = 0.63 (Krampa's model B), continued linearly
 * above phi_max - delta. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "granular/kinetic.h"

typedef struct jjw_params {
  double specularity, e_w, phi_max, delta;
  int32_t radial;
} jjw_params;

enum { IN_SLIP_WALL, IN_PHI, IN_THETA, IN_RHO_S, N_IN };
enum { OUT_TAU_W, OUT_THETA_FLUX, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(jjw_params, specularity, 0.5, 0.0, 1.0, "1",
                     "specularity coefficient: 0 specular (free slip) to 1 diffuse (rough wall)"),
    SL_PARAM_REAL_OF(jjw_params, e_w, 0.9, 0.0, 1.0, "1", "particle-wall restitution coefficient"),
    SL_PARAM_REAL_OF(jjw_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing (in phi/phi_max and g0)"),
    SL_PARAM_REAL_OF(jjw_params, delta, 0.01, 1e-4, 0.1, "1",
                     "g0 is continued by its tangent line above phi_max - delta"),
    SL_PARAM_ENUM_OF(jjw_params, radial, KT_G0_LUN_SAVAGE, KT_G0_CHOICES, KT_G0_HELP),
};

static const sl_field_desc inputs[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential slip speed of the solids at the wall"},
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.74, "solids volume fraction at the wall"},
    {"theta", "m^2 s^-2", SL_FIELD_DIFF, 1e-3, 1e-12, 1e4, "granular temperature at the wall"},
    {"rho_s", "kg m^-3", 0, 2650.0, 1.0, 1e5, "solid density"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "solids wall shear stress (magnitude, opposing the slip)"},
    {"theta_flux", "kg s^-3", SL_FIELD_OPTIONAL, 0, 0, 0,
     "granular-energy flux from the wall into the flow, -kappa dtheta/dn (n into the flow)"},
};

/* Defaults (specularity 0.5, e_w 0.9, lun_savage g0 with phi_max 0.63) at
 * slip 1 m/s, phi 0.3, theta 0.01, rho_s 2650: g0 = (1 - 0.3/0.63)^-1.575 =
 * 2.76886581908435; values evaluated independently (Python, double). */
static const double check_in[N_IN] = {1.0, 0.3, 0.01, 2650.0};
static const sl_check_point checks[] = {
    {check_in, OUT_TAU_W, 158.43741327509986, 1e-12,
     "Johnson & Jackson (1987) / Krampa (2009) eq 4.92 without the friction term, hand-evaluated"},
    {check_in, OUT_THETA_FLUX, 157.5343200194318, 1e-12,
     "Johnson & Jackson (1987) / Krampa (2009) eq 4.93, hand-evaluated"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const jjw_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *u = a->in[IN_SLIP_WALL], *phi = a->in[IN_PHI], *th = a->in[IN_THETA], *rho = a->in[IN_RHO_S];
  double *tau = a->out[OUT_TAU_W], *fl = a->out[OUT_THETA_FLUX];
  double *dtau_du = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL), *dtau_dphi = sl_dout(a, N_IN, OUT_TAU_W, IN_PHI),
         *dtau_dth = sl_dout(a, N_IN, OUT_TAU_W, IN_THETA);
  double *dfl_du = fl ? sl_dout(a, N_IN, OUT_THETA_FLUX, IN_SLIP_WALL) : NULL,
         *dfl_dphi = fl ? sl_dout(a, N_IN, OUT_THETA_FLUX, IN_PHI) : NULL,
         *dfl_dth = fl ? sl_dout(a, N_IN, OUT_THETA_FLUX, IN_THETA) : NULL;
  const double c0 = KT_PI * sqrt(3.0) / (6.0 * p->phi_max), sp = p->specularity;
  const double diss = 1.5 * (1.0 - p->e_w * p->e_w);
  for (int32_t q = 0; q < a->Q; ++q) {
    double dg, g = kt_g0(p->radial, phi[q], p->phi_max, p->delta, &dg);
    double st = sqrt(th[q]);
    double A = c0 * phi[q] * g * rho[q] * st; /* collision factor */
    double dA_dphi = c0 * (g + phi[q] * dg) * rho[q] * st;
    double dA_dth = 0.5 * c0 * phi[q] * g * rho[q] / st;
    tau[q] = sp * A * u[q];
    gr_set(dtau_du, q, sp * A);
    gr_set(dtau_dphi, q, sp * dA_dphi * u[q]);
    gr_set(dtau_dth, q, sp * dA_dth * u[q]);
    if (fl) {
      double br = sp * u[q] * u[q] - diss * th[q];
      fl[q] = A * br;
      gr_set(dfl_du, q, 2.0 * sp * A * u[q]);
      gr_set(dfl_dphi, q, dA_dphi * br);
      gr_set(dfl_dth, q, dA_dth * br - A * diss);
    }
  }
  return SL_OK;
}

static const sl_closure_desc johnson_jackson = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "johnson_jackson",
    .version = "1.0.0",
    .summary = "Johnson & Jackson (1987) partial-slip solids wall stress and granular-energy wall flux",
    .formula =
        "A = (pi/6) sqrt(3) (phi/phi_max) rho_s g0 sqrt(theta)\n"
        "tau_w = specularity A slip_wall\n"
        "theta_flux = A [specularity slip_wall^2 - (3/2)(1 - e_w^2) theta]\n"
        "g0: radial (default lun_savage), tangent-line continuation above phi_max - delta",
    .reference = "Johnson & Jackson (1987) J. Fluid Mech. 176:67; Krampa (2009) eqs 4.92-4.93",
    .validity =
        "collisional (rapid) granular flow at a flat wall; the Coulomb friction term of JJ (1987) is not "
        "included; 0 <= phi <= 0.74 (g0 continued above phi_max - delta); theta >= 1e-12 m^2/s^2",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(jjw_params),
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

static const sl_closure_desc *const all[] = {&johnson_jackson};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
