/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Stokes drag of isolated spheres, as the momentum-exchange coefficient K
 * with F_s = K (u_f - u_s) (architecture.md section 4).
 *
 * Stokes (1851), Trans. Camb. Phil. Soc. 9:8: the drag on one sphere in
 * creeping flow is 3 pi mu_f d u. With phi / (pi d^3 / 6) spheres per unit
 * volume:
 *   K = 18 mu_f phi / d^2,   d = sphericity d_p.
 * No hindrance and no inertia: the dilute, Re -> 0 limit that every other
 * drag closure here must reproduce (Schiller-Naumann, Wen-Yu and Gidaspow
 * exactly; Di Felice and Syamlal-O'Brien to the Dallavalle factor 0.96). */
#include <math.h>
#include <sluice/closure.h>

#include "drag/sphere_drag.h"

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.01, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s| (K does not depend on it)"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density (K does not depend on it)"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-4, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* 3 pi mu d u per sphere, exact: phi = 0.1, mu = 1e-3, d = 1e-4 -> 18e-3 / 1e-8 * 0.1 = 1.8e5. */
static const double check_in_0[N_IN] = {0.1, 0.0, 1000.0, 1e-3, 1e-4, 1.0};
/* d_p = 2e-4 with sphericity 0.5 is the same d = 1e-4 (slip does not matter). */
static const double check_in_1[N_IN] = {0.1, 0.3, 1000.0, 1e-3, 2e-4, 0.5};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 1.8e5, 1e-14, "Stokes (1851) drag 3 pi mu d u per sphere, exact"},
    {check_in_1, OUT_K, 1.8e5, 1e-14, "Stokes (1851), exact, with d = sphericity d_p (Gidaspow 1994)"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  (void)state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F], *dp = a->in[IN_D_P], *psi = a->in[IN_SPHERICITY];
  double *K = a->out[OUT_K];
  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  for (int32_t q = 0; q < a->Q; ++q) {
    int rc = sl_check_inputs(inputs, N_IN, a, q, -1);
    if (rc) return rc;
    double d = psi[q] * dp[q];
    double k1 = 18.0 * mu[q] / (d * d);
    K[q] = k1 * phi[q];
    if (dK_dphi) dK_dphi[q] = k1;
    if (dK_dslip) dK_dslip[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc stokes = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "stokes",
    .version = "1.0.0",
    .summary = "Stokes (1851) drag of isolated spheres, creeping flow",
    .formula = "K = 18 mu_f phi / d^2,  d = sphericity d_p",
    .reference = "Stokes (1851) Trans. Camb. Phil. Soc. 9:8; per unit volume as in Gidaspow (1994) ch. 5",
    .validity =
        "dilute suspensions (phi -> 0) at particle Reynolds number rho_f |slip| d / mu_f << 1; no "
        "hindrance: K/phi is the single-sphere drag at any phi <= 0.74",
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

static const sl_closure_desc *const all[] = {&stokes};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
