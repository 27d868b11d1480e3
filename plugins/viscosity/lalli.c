/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lalli (INSEAN, undated; work funded 1991-93) density-dependent
 * regularised Bingham viscosity for a liquid carrying a large amount of
 * suspended solids, treated as one pseudo-continuum of variable density rho:
 *   mu = mu0(rho) + (1/2) tau0(rho) (S_II + eta)^(-1/2),   S_II = (1/2) S_ij S_ij,
 * Lalli, "Numerical solution of continuous model for fluid-particle flows"
 * (INSEAN), eq 0.10, the regularisation of the Bingham law eq 0.9
 * (mu = mu0 + (1/2) tau0 S_II^(-1/2) where yielded). With the host's
 * shear_rate = sqrt(2 S_ij S_ij), S_II = shear_rate^2/4, so the unregularised
 * law is the usual mu0 + tau0/shear_rate and the regularised one is the
 * Bercovier-Engelman form mu0 + tau0/sqrt(shear_rate^2 + 4 eta) (Lalli cites
 * Bercovier & Engelman 1980).
 *
 * The paper gives NO functional form for mu0(rho) and tau0(rho): only that
 * the viscosity follows the concentration in dilute regions (Happel &
 * Brenner) and that a yield stress appears beyond a threshold
 * concentration, and, for its wave/sand-bed example (Fig. 5), the
 * dimensionless contrasts drho0/rho0 = 0.25, dmu0/mu0 = 10, tau0 = 10,
 * eta = 1e-4. This closure therefore uses the simplest forms consistent
 * with that description, in s = (rho - rho_0)/delta_rho in [0, 1]:
 *   mu0(rho)  = mu_0 + delta_mu s                                  (linear)
 *   tau0(rho) = yield_stress max(0, (s - yield_onset)/(1 - yield_onset))
 * with defaults mirroring Fig. 5 in SI (rho_0 = 1000, delta_rho = 250,
 * mu_0 = 1e-3, delta_mu = 1e-2, yield_stress = 10 Pa, eta = 1e-4 s^-2).
 * tau0 has a kink at s = yield_onset: d/d density there is the derivative
 * from above (with the default onset 0, the only side inside the range).
 * Densities outside [rho_0, rho_0 + delta_rho] are refused (recoverable). */
#include <math.h>
#include <sluice/closure.h>

typedef struct lalli_params {
  double rho_0;        /* clear-fluid density */
  double delta_rho;    /* density range up to the dense limit */
  double mu_0;         /* viscosity at rho_0 */
  double delta_mu;     /* viscosity increase over the range */
  double yield_stress; /* tau0 at rho_0 + delta_rho */
  double yield_onset;  /* s at which tau0 starts */
  double eta;          /* regularisation, s^-2 */
} lalli_params;

enum { IN_SHEAR_RATE, IN_DENSITY, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(lalli_params, rho_0, 1000.0, 1e-3, 1e5, "kg m^-3", "density of the clear fluid (s = 0)"),
    SL_PARAM_REAL_OF(lalli_params, delta_rho, 250.0, 1e-6, 1e5, "kg m^-3",
                     "density range to the dense limit (Lalli Fig. 5: 0.25 rho_0)"),
    SL_PARAM_REAL_OF(lalli_params, mu_0, 1e-3, 1e-7, 1e5, "Pa s", "Newtonian viscosity mu0 at rho_0"),
    SL_PARAM_REAL_OF(lalli_params, delta_mu, 1e-2, 0.0, 1e8, "Pa s",
                     "increase of mu0 over the density range, linear in density (Lalli Fig. 5: 10 mu_0)"),
    SL_PARAM_REAL_OF(lalli_params, yield_stress, 10.0, 0.0, 1e8, "Pa", "yield stress tau0 at rho_0 + delta_rho"),
    SL_PARAM_REAL_OF(lalli_params, yield_onset, 0.0, 0.0, 0.99, "1",
                     "fraction s of the density range beyond which tau0 rises linearly from 0"),
    SL_PARAM_REAL_OF(lalli_params, eta, 1e-4, 1e-12, 1e12, "s^-2",
                     "regularisation added to S_II = shear_rate^2/4 (Lalli eq 0.10)"),
};

/* The declared density range is that of the default parameters; the closure
 * accepts rho_0 <= density <= rho_0 + delta_rho. */
static const sl_field_desc inputs[] = {
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 1.0, 0.0, HUGE_VAL, "shear-rate magnitude sqrt(2 D:D) = 2 sqrt(S_II)"},
    {"density", "kg m^-3", SL_FIELD_DIFF, 1125.0, 1000.0, 1250.0, "mixture density, in [rho_0, rho_0 + delta_rho]"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "apparent dynamic viscosity"},
};

/* No number in the paper (its results are figures). Exact values of eq 0.10
 * with the defaults: clear fluid mu_0; dense limit at rest
 * mu_0 + delta_mu + tau0 / (2 sqrt(eta)) = 0.011 + 500. */
static const double check_in_0[N_IN] = {1.0, 1000.0};
static const double check_in_1[N_IN] = {0.0, 1250.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 1e-3, 1e-14, "exact: clear fluid (tau0 = 0) gives mu0(rho_0) = mu_0"},
    {check_in_1, OUT_VISCOSITY, 500.011, 1e-13, "exact: Lalli eq 0.10 at S_II = 0, mu0 + tau0/(2 sqrt(eta))"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const lalli_params *p = state;
  const double *g = a->in[IN_SHEAR_RATE], *rho = a->in[IN_DENSITY];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dg = sl_dout(a, N_IN, OUT_VISCOSITY, IN_SHEAR_RATE);
  double *dvisc_drho = sl_dout(a, N_IN, OUT_VISCOSITY, IN_DENSITY);
  const double rho_1 = p->rho_0 + p->delta_rho;
  const double ramp = p->yield_stress / (1.0 - p->yield_onset); /* d tau0 / d s above the onset */
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(g[q] >= 0.0 && g[q] < HUGE_VAL))
      return sl_fail(a->err, SL_RECOVERABLE, q, "shear_rate = %g is not a finite rate >= 0", g[q]);
    if (!(rho[q] >= p->rho_0 && rho[q] <= rho_1))
      return sl_fail(a->err, SL_RECOVERABLE, q, "density = %g outside [rho_0, rho_0 + delta_rho] = [%g, %g]", rho[q],
                     p->rho_0, rho_1);
    double s = (rho[q] - p->rho_0) / p->delta_rho;
    if (s > 1.0) s = 1.0;            /* rounding of rho_0 + delta_rho */
    int above = s >= p->yield_onset; /* at the onset: the derivative from above */
    double mu0 = p->mu_0 + p->delta_mu * s;
    double tau0 = above ? ramp * (s - p->yield_onset) : 0.0;
    double sii = 0.25 * g[q] * g[q] + p->eta; /* S_II + eta */
    double root = sqrt(sii);
    visc[q] = mu0 + 0.5 * tau0 / root;
    /* d/dg (S_II + eta)^(-1/2) = -(1/2) (S_II + eta)^(-3/2) g/2. */
    if (dvisc_dg) dvisc_dg[q] = -0.125 * tau0 * g[q] / (sii * root);
    if (dvisc_drho) dvisc_drho[q] = (p->delta_mu + (above ? 0.5 * ramp / root : 0.0)) / p->delta_rho;
  }
  return SL_OK;
}

static const sl_closure_desc lalli = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "lalli",
    .version = "1.0.0",
    .summary = "Lalli density-dependent regularised Bingham viscosity",
    .formula =
        "viscosity = mu0(rho) + (1/2) tau0(rho) / sqrt(S_II + eta),  S_II = shear_rate^2 / 4\n"
        "s = (rho - rho_0)/delta_rho,  mu0 = mu_0 + delta_mu s,\n"
        "tau0 = yield_stress max(0, (s - yield_onset)/(1 - yield_onset))",
    .reference =
        "Lalli, Numerical solution of continuous model for fluid-particle flows, INSEAN (1991-93 research plan), "
        "eqs 0.8-0.10; "
        "Bercovier & Engelman (1980) J. Comput. Phys. 36:313",
    .validity =
        "rho_0 <= density <= rho_0 + delta_rho, shear_rate >= 0; mu0(rho) and tau0(rho) are linear "
        "choices (the paper gives no forms); kink in d/d density at yield_onset",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(lalli_params),
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

static const sl_closure_desc *const all[] = {&lalli};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
