/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Bartosik (1996) modified Bagnold wall shear stress for coarse-particle
 * slurries in vertical pipes (Krampa 2009 eq 2.10, "B96"):
 *   tau_w = (8.3018e7 / Re_f^2.317) D^2 rho_s d_p^2 lambda^1.5 (dU/dy)_w^2,
 *   Re_f = rho_f V D / mu_f,   lambda = 1 / ((phi_max/phi)^(1/3) - 1).
 * Bartosik (1996) J. Hydrol. Hydromech. 44(1):49-58, building on Shook &
 * Bartosik (1994) Powder Technol. 81:117. What it adds to Bagnold's
 * grain-inertia law k_i rho_s (lambda d_p)^2 (dU/dy)^2 (bagnold.c): the
 * constant k_i lambda^0.5 is replaced by a factor that falls with the liquid
 * Reynolds number of the pipe flow and grows with the pipe diameter, fitted
 * to vertical-pipe head losses; the stress stays quadratic in the shear rate
 * and there is no macro-viscous branch. The correlation is dimensional:
 * 8.3018e7 carries m^-2 with D in metres (SI assumed; the thesis states no
 * units). Matousek (2002) found it under-predicts the solids contribution
 * for medium and coarse sand in a 150 mm pipe.
 *
 * Re_f is the bulk (pipe) Reynolds number of the liquid, Re = D V rho_L/mu_L
 * (Krampa p. 24). The bulk velocity V is not a local field the host supplies
 * (no input name for it), so it is the parameter bulk_velocity; rho_f, mu_f
 * and D = d_vessel are inputs. Wall shear rate: (dU/dy)_w = slip_wall /
 * wall_distance (wall function, as in bagnold.c; Bartosik took the liquid
 * gradient, assumed equal to the solids', Krampa the solids' own).
 * lambda is continued by its tangent line above phi_max - delta. */
#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "wall_stress/linear_concentration.h"

typedef struct bartosik_params {
  double coefficient, exponent, bulk_velocity, phi_max, delta;
} bartosik_params;

enum { IN_SLIP_WALL, IN_PHI, IN_RHO_S, IN_RHO_F, IN_MU_F, IN_D_P, IN_D_VESSEL, IN_WALL_DISTANCE, N_IN };
enum { OUT_TAU_W, OUT_REYNOLDS, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(bartosik_params, coefficient, 8.3018e7, 0.0, 1e12, "m^-2", "Bartosik (1996) coefficient"),
    SL_PARAM_REAL_OF(bartosik_params, exponent, 2.317, 0.0, 5.0, "1", "exponent of the liquid Reynolds number"),
    SL_PARAM_REAL_OF(bartosik_params, bulk_velocity, 3.0, 1e-3, 100.0, "m s^-1",
                     "bulk (mean mixture) velocity V of the pipe flow in Re_f = rho_f V D / mu_f"),
    SL_PARAM_REAL_OF(bartosik_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing in lambda"),
    SL_PARAM_REAL_OF(bartosik_params, delta, 0.01, 1e-4, 0.1, "1",
                     "lambda is continued by its tangent line above phi_max - delta (C1, finite)"),
};

static const sl_field_desc inputs[] = {
    {"slip_wall", "m s^-1", SL_FIELD_DIFF, 1.0, 0.0, 100.0, "tangential solids speed at the first node off the wall"},
    {"phi", "1", 0, 0.1, 0.0, 0.74, "solids volume fraction (Shook & Bartosik used the mean concentration)"},
    {"rho_s", "kg m^-3", 0, 1400.0, 1.0, 1e5, "solid density"},
    {"rho_f", "kg m^-3", 0, 998.0, 1e-3, 1e5, "liquid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "liquid dynamic viscosity"},
    {"d_p", "m", 0, 3.4e-3, 1e-8, 1.0, "particle diameter"},
    {"d_vessel", "m", 0, 0.04, 1e-4, 100.0, "pipe diameter D"},
    {"wall_distance", "m", 0, 1e-3, 1e-9, 10.0, "distance of the wall node from the wall"},
};

static const sl_field_desc outputs[] = {
    {"tau_w", "Pa", 0, 0, 0, 0, "solids wall shear stress (magnitude, opposing the slip)"},
    {"reynolds", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "liquid pipe Reynolds number rho_f V D / mu_f"},
};

/* lambda = 1 at phi = phi_max/8; rho_f = 1, mu_f = 1.5, D = 0.5 and V = 3
 * give Re_f = 1; slip 1 m/s over 1e-2 m gives dU/dy = 100 s^-1. */
static const double check_re1[N_IN] = {1.0, 0.63 / 8.0, 1400.0, 1.0, 1.5, 3.4e-3, 0.5, 1e-2};
static const sl_check_point checks[] = {
    {check_re1, OUT_TAU_W, 8.3018e7 * 0.25 * 1400.0 * 3.4e-3 * 3.4e-3 * 1e4, 1e-12,
     "Bartosik (1996), Krampa (2009) eq 2.10 at Re_f = 1, lambda = 1, D = 0.5 m, hand-evaluated"},
    {check_re1, OUT_REYNOLDS, 1.0, 1e-14, "Re = D V rho_L / mu_L (Krampa 2009 p. 24) = 0.5 * 3 * 1 / 1.5"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const bartosik_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *u = a->in[IN_SLIP_WALL], *phi = a->in[IN_PHI], *rs = a->in[IN_RHO_S], *rf = a->in[IN_RHO_F],
               *mu = a->in[IN_MU_F], *dp = a->in[IN_D_P], *D = a->in[IN_D_VESSEL], *h = a->in[IN_WALL_DISTANCE];
  double *tau = a->out[OUT_TAU_W], *re = a->out[OUT_REYNOLDS];
  double *dtau = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL);
  double *dre = re ? sl_dout(a, N_IN, OUT_REYNOLDS, IN_SLIP_WALL) : NULL;
  for (int32_t q = 0; q < a->Q; ++q) {
    double lam = ws_lambda(phi[q], p->phi_max, p->delta);
    double Re = rf[q] * p->bulk_velocity * D[q] / mu[q];
    double c = p->coefficient * pow(Re, -p->exponent) * D[q] * D[q] * rs[q] * dp[q] * dp[q] * lam * sqrt(lam) /
               (h[q] * h[q]); /* tau = c slip^2 */
    tau[q] = c * u[q] * u[q];
    if (dtau) dtau[q] = 2.0 * c * u[q];
    gr_set(re, q, Re);
    gr_set(dre, q, 0.0);
  }
  return SL_OK;
}

static const sl_closure_desc bartosik = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_WALL_STRESS,
    .name = "bartosik",
    .version = "1.0.0",
    .summary = "Bartosik (1996) modified Bagnold (grain-inertia) solids wall shear stress for vertical pipes",
    .formula =
        "gd = slip_wall / wall_distance, lambda = 1/((phi_max/phi)^(1/3) - 1) (tangent line above phi_max - delta)\n"
        "Re_f = rho_f bulk_velocity d_vessel / mu_f\n"
        "tau_w = coefficient Re_f^(-exponent) d_vessel^2 rho_s d_p^2 lambda^1.5 gd^2  (8.3018e7 m^-2, 2.317)",
    .reference =
        "Bartosik (1996) J. Hydrol. Hydromech. 44(1):49; Shook & Bartosik (1994) Powder Technol. 81:117; "
        "Krampa (2009) eq 2.10",
    .validity =
        "turbulent vertical pipe flow of coarse particles (Shook & Bartosik: 1.4-3.4 mm, D = 26-40 mm, "
        "C = 10-45 %, V = 2-7 m/s); dimensional SI correlation; 0 <= phi <= 0.74 (lambda continued above "
        "phi_max - delta); bulk_velocity is a parameter",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(bartosik_params),
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

static const sl_closure_desc *const all[] = {&bartosik};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
