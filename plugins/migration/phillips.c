/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Phillips et al. (1992) shear-induced migration: the diffusive particle
 * fluxes of the Leighton & Acrivos (1987) scaling arguments,
 *   N_c  = -K_c  a^2 phi grad(shear_rate phi)            (collisions)
 *   N_mu = -K_mu a^2 shear_rate phi^2 grad(ln mu)         (viscosity gradients)
 * Phillips, Armstrong, Brown, Graham & Abbott (1992) Phys. Fluids A 4:30,
 * with K_c = 0.41, K_mu = 0.62 fitted to Couette data; a is the
 * particle RADIUS (d_p / 2). Nigam (1999) eqs 2.28-2.30 (and
 * section 4.5) use the same flux, expanded with K_gammadot = K_c:
 *   N = -a^2 [K_c phi^2 grad(g) + (K_c phi g + K_mu phi^2 g mu'/mu) grad(phi)].
 *
 * Outputs (what the host multiplies):
 *   D_c  = K_c a^2 phi          m^2        N_c  = -D_c  grad(shear_rate phi)
 *   D_mu = K_mu a^2 shear_rate phi^2  m^2 s^-1   N_mu = -D_mu grad(ln mu)
 * so the migration flux is N = -D_c grad(shear_rate phi) - D_mu grad(ln mu),
 * with mu the suspension viscosity from the viscosity closure (for mu(phi)
 * only, grad(ln mu) = (mu'/mu) grad(phi), mu' its d/dphi). The host takes
 * the gradients; the closure never sees the mesh. */
#include <math.h>
#include <sluice/closure.h>

typedef struct phillips_params {
  double k_c;  /* 0.41 */
  double k_mu; /* 0.62 */
} phillips_params;

enum { IN_PHI, IN_SHEAR_RATE, IN_D_P, N_IN };
enum { OUT_D_C, OUT_D_MU, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(phillips_params, k_c, 0.41, 0.0, 100.0, "1",
                     "collision coefficient K_c (Phillips et al. 1992: 0.41)"),
    SL_PARAM_REAL_OF(phillips_params, k_mu, 0.62, 0.0, 100.0, "1",
                     "viscosity-gradient coefficient K_mu (Phillips et al. 1992: 0.62)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.4, 0.0, 0.74, "solids volume fraction"},
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 10.0, 0.0, HUGE_VAL, "shear-rate magnitude sqrt(2 D:D)"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter (a = d_p/2)"},
};

static const sl_field_desc outputs[] = {
    {"D_c", "m^2", 0, 0, 0, 0, "K_c a^2 phi: N_c = -D_c grad(shear_rate phi)"},
    {"D_mu", "m^2 s^-1", 0, 0, 0, 0, "K_mu a^2 shear_rate phi^2: N_mu = -D_mu grad(ln mu)"},
};

/* The Phillips et al. (1992) constants at a = 1 mm, phi = 0.5, 1 s^-1:
 * D_c = 0.41 * 1e-6 * 0.5, D_mu = 0.62 * 1e-6 * 0.25. */
static const double check_in_0[N_IN] = {0.5, 1.0, 2e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_D_C, 0.41 * 1e-6 * 0.5, 1e-14,
     "Phillips et al. (1992) K_c = 0.41: K_c a^2 phi at a = 1 mm, phi = 0.5"},
    {check_in_0, OUT_D_MU, 0.62 * 1e-6 * 0.25, 1e-14,
     "Phillips et al. (1992) K_mu = 0.62: K_mu a^2 g phi^2 at a = 1 mm, phi = 0.5, g = 1 s^-1"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const phillips_params *p = state;
  const double *phi = a->in[IN_PHI], *g = a->in[IN_SHEAR_RATE], *dp = a->in[IN_D_P];
  double *dc = a->out[OUT_D_C], *dmu = a->out[OUT_D_MU];
  double *ddc_dphi = sl_dout(a, N_IN, OUT_D_C, IN_PHI), *ddc_dg = sl_dout(a, N_IN, OUT_D_C, IN_SHEAR_RATE);
  double *ddmu_dphi = sl_dout(a, N_IN, OUT_D_MU, IN_PHI), *ddmu_dg = sl_dout(a, N_IN, OUT_D_MU, IN_SHEAR_RATE);
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= inputs[IN_PHI].valid_min && phi[q] <= inputs[IN_PHI].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.74]", phi[q]);
    if (!(g[q] >= 0.0 && g[q] < HUGE_VAL))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g is not a finite rate >= 0", g[q]);
    if (!(dp[q] >= inputs[IN_D_P].valid_min && dp[q] <= inputs[IN_D_P].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "d_p = %g outside [1e-8, 1] m", dp[q]);
    double r = 0.5 * dp[q];
    double a2 = r * r;
    dc[q] = p->k_c * a2 * phi[q];
    dmu[q] = p->k_mu * a2 * g[q] * phi[q] * phi[q];
    if (ddc_dphi) ddc_dphi[q] = p->k_c * a2;
    if (ddc_dg) ddc_dg[q] = 0.0;
    if (ddmu_dphi) ddmu_dphi[q] = 2.0 * p->k_mu * a2 * g[q] * phi[q];
    if (ddmu_dg) ddmu_dg[q] = p->k_mu * a2 * phi[q] * phi[q];
  }
  return SL_OK;
}

static const sl_closure_desc phillips = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_MIGRATION,
    .name = "phillips",
    .version = "1.0.0",
    .summary = "Phillips et al. (1992) shear-induced migration flux coefficients",
    .formula =
        "a = d_p/2;  D_c = K_c a^2 phi,  D_mu = K_mu a^2 shear_rate phi^2,  K_c = 0.41, K_mu = 0.62\n"
        "flux N = -D_c grad(shear_rate phi) - D_mu grad(ln mu)  (gradients taken by the host)",
    .reference =
        "Phillips, Armstrong, Brown, Graham & Abbott (1992) Phys. Fluids A 4:30; Leighton & Acrivos (1987) "
        "J. Fluid Mech. 181:415; Nigam (1999) MIT PhD thesis eqs 2.28-2.30",
    .validity =
        "non-Brownian, neutrally buoyant spheres in viscous (Stokes) shear flow; 0 <= phi <= 0.74; "
        "constants fitted to Couette data (Phillips et al. 1992)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(phillips_params),
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

static const sl_closure_desc *const all[] = {&phillips};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
