/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Eilers (1941) viscosity of a concentrated suspension,
 *   mu = mu_f [1 + (0.5 [eta]) phi / (1 - phi/phi_max)]^2,  0.5 [eta] = 1.25,
 * Eilers (1941) Kolloid-Z. 97:313, in the form with the intrinsic viscosity
 * written out (e.g. Stickel & Powell 2005, Annu. Rev. Fluid Mech. 37:129):
 * the constant 1.25 is half of [eta] = 2.5, so that the square expands to
 * 1 + 2.5 phi + O(phi^2), the Einstein limit. phi_max was fitted by Eilers to
 * his emulsion data; it is a parameter here, defaulting to the 0.68
 * used for Krieger-Dougherty. Diverges at phi = phi_max (recoverable code). */
#include <math.h>
#include <sluice/closure.h>

typedef struct eilers_params {
  double phi_max;             /* 0.68 */
  double intrinsic_viscosity; /* 2.5: the Eilers constant is half of it, 1.25 */
} eilers_params;

enum { IN_PHI, IN_MU_F, N_IN };
enum { OUT_VISCOSITY, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(eilers_params, phi_max, 0.68, 0.3, 0.8, "1",
                     "maximum packing fraction, where the viscosity diverges"),
    SL_PARAM_REAL_OF(eilers_params, intrinsic_viscosity, 2.5, 0.1, 100.0, "1",
                     "intrinsic viscosity [eta]; the Eilers constant is [eta]/2 = 1.25"),
};

/* Declared phi range: that of the default phi_max; 0 <= phi < phi_max is accepted. */
static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.68, "solids volume fraction, 0 <= phi < phi_max"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
};

static const sl_field_desc outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "effective dynamic viscosity of the suspension"},
};

/* No tabulated value in the project's sources: at phi = phi_max/2 the
 * relative viscosity is exactly (1 + 1.25 phi_max)^2 = 1.85^2 = 3.4225. */
static const double check_in_0[N_IN] = {0.34, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_VISCOSITY, 3.4225e-3, 1e-13, "exact: mu_f (1 + 1.25 phi_max)^2 at phi = phi_max/2 = 0.34"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const eilers_params *p = state;
  const double *phi = a->in[IN_PHI], *mu = a->in[IN_MU_F];
  double *visc = a->out[OUT_VISCOSITY];
  double *dvisc_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);
  const double c = 0.5 * p->intrinsic_viscosity;
  for (int32_t q = 0; q < a->Q; ++q) {
    if (!(phi[q] >= 0.0 && phi[q] < p->phi_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, phi_max = %g): eilers diverges at phi_max",
                     phi[q], p->phi_max);
    if (!(mu[q] >= inputs[IN_MU_F].valid_min && mu[q] <= inputs[IN_MU_F].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "mu_f = %g outside [1e-7, 1e5] Pa s", mu[q]);
    double x = 1.0 - phi[q] / p->phi_max; /* in (0, 1] */
    double u = 1.0 + c * phi[q] / x;
    double v = mu[q] * u * u;
    /* d/dphi [phi / x] = 1/x^2. */
    double dv = 2.0 * mu[q] * u * c / (x * x);
    if (!isfinite(v) || !isfinite(dv))
      return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %.17g too close to phi_max = %g: the viscosity overflows",
                     phi[q], p->phi_max);
    visc[q] = v;
    if (dvisc_dphi) dvisc_dphi[q] = dv;
  }
  return SL_OK;
}

static const sl_closure_desc eilers = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = "eilers",
    .version = "1.0.0",
    .summary = "Eilers (1941) concentrated-suspension viscosity",
    .formula = "viscosity = mu_f [1 + ([eta]/2) phi / (1 - phi/phi_max)]^2,  [eta]/2 = 1.25, phi_max = 0.68",
    .reference =
        "Eilers (1941) Kolloid-Z. 97:313; form with [eta] as in Stickel & Powell (2005) Annu. Rev. Fluid "
        "Mech. 37:129",
    .validity = "0 <= phi < phi_max; diverges at phi_max (recoverable code there); Einstein limit for small phi",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(eilers_params),
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

static const sl_closure_desc *const all[] = {&eilers};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
