/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Ergun (1952) drag for dense beds, as the momentum-exchange coefficient K
 * with F_s = K (u_f - u_s) (architecture.md section 4).
 *
 * Ergun (1952), Chem. Eng. Prog. 48:89, pressure drop through a packed bed,
 *   dP/L = 150 (1-n)^2 mu U / (n^3 d^2) + 1.75 (1-n) rho U^2 / (n^3 d),
 * converted to K with U = n |u_f - u_s| and dP/L = K |u_f - u_s| / n
 * (Gidaspow 1994, eq. 5.62; Pringle 2001 eqs 3.9-3.12):
 *   K = 150 phi^2 mu_f / ((1-phi) (psi d_p)^2) + 1.75 phi rho_f |slip| / (psi d_p)
 * with phi = 1 - n the solids fraction and psi the sphericity.
 * Pringle (2001) eq 3.12 prints the inertial term with an extra 1/n; the
 * substitution the thesis states (eqs 3.9-3.11) does not give
 * it. Both forms are offered: `form = gidaspow` (default) or `pringle`. */
#include <math.h>
#include <sluice/closure.h>

#include "drag/dense_drag_laws.h"

typedef struct ergun_params {
  double viscous;  /* 150 */
  double inertial; /* 1.75 */
  int32_t form;    /* 0 gidaspow, 1 pringle_printed */
} ergun_params;

enum { IN_PHI, IN_SLIP, IN_RHO_F, IN_MU_F, IN_D_P, IN_SPHERICITY, N_IN };
enum { OUT_K, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(ergun_params, viscous, 150.0, 0.0, 1e4, "1", "viscous (Blake-Kozeny) constant"),
    SL_PARAM_REAL_OF(ergun_params, inertial, 1.75, 0.0, 100.0, "1", "inertial (Burke-Plummer) constant"),
    SL_PARAM_ENUM_OF(ergun_params, form, 0, "gidaspow|pringle_printed",
                     "gidaspow: 1.75 phi rho |slip|/d; pringle_printed: eq 3.12 with the extra 1/(1-phi)"),
};

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.4, 0.0, 0.74, "solids volume fraction"},
    {"slip", "m s^-1", SL_FIELD_DIFF, 0.01, 0.0, HUGE_VAL, "slip speed |u_f - u_s|"},
    {"rho_f", "kg m^-3", 0, 1000.0, 1e-3, 1e5, "fluid density"},
    {"mu_f", "Pa s", 0, 1e-3, 1e-7, 1e5, "fluid dynamic viscosity"},
    {"d_p", "m", 0, 1e-3, 1e-8, 1.0, "particle diameter"},
    {"sphericity", "1", 0, 1.0, 0.01, 1.0, "particle sphericity (d_p is multiplied by it)"},
};

static const sl_field_desc outputs[] = {
    {"K", "kg m^-3 s^-1", 0, 0, 0, 0, "momentum-exchange coefficient, F_s = K (u_f - u_s)"},
};

/* Stokes limit (slip = 0), mu/d^2 = 1e3: K = 150 phi^2/(1-phi) * 1e3.
 * Pringle (2001) eq 3.12 gives K/(mu/d^2) = 135.0 at n = 0.4 and 75.0 at
 * n = 0.5 in the Stokes limit. */
static const double check_in_0[N_IN] = {0.6, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const double check_in_1[N_IN] = {0.5, 0.0, 1000.0, 1e-3, 1e-3, 1.0};
static const sl_check_point checks[] = {
    {check_in_0, OUT_K, 135.0e3, 5e-4, "Pringle (2001) eq 3.12 (Ergun), Stokes limit, n = 0.40: 135.0 mu/d^2"},
    {check_in_1, OUT_K, 75.0e3, 5e-4, "Pringle (2001) eq 3.12 (Ergun), Stokes limit, n = 0.50: 75.0 mu/d^2"},
};

/* Names the first offending input at point q (the cold path of the loop). */
static int refuse(const sl_eval_args *a, int32_t q) {
  const double phi = a->in[IN_PHI][q], slip = a->in[IN_SLIP][q], rho = a->in[IN_RHO_F][q], mu = a->in[IN_MU_F][q],
               dp = a->in[IN_D_P][q], psi = a->in[IN_SPHERICITY][q];
  /* Written as negated ranges so that NaN inputs fail too. */
  if (!(phi >= 0.0 && phi <= 0.74)) return sl_fail(a->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.74]", phi);
  if (!(slip >= 0.0 && slip < HUGE_VAL))
    return sl_fail(a->err, SL_RECOVERABLE, q, "slip = %g is not a finite speed >= 0", slip);
  return sl_fail(a->err, SL_RECOVERABLE, q,
                 "fluid or particle property outside its range (rho_f %g, mu_f %g, d_p %g, sphericity %g)", rho, mu, dp,
                 psi);
}

#if defined(__GNUC__)
#define ERGUN_SPECIALISED static inline __attribute__((always_inline))
#else
#define ERGUN_SPECIALISED static inline
#endif

/* The loop, specialised below on the form and on which derivatives are asked
 * for (constant arguments), so that none of those tests stays inside it: the
 * loop then matches the law written inline for one case. */
ERGUN_SPECIALISED int ergun_loop(const ergun_params *p, const sl_eval_args *a, const int pringle_form,
                                 const int want_dphi, const int want_dslip) {
  /* The host guarantees the arrays do not alias (closure.h): say so, so the
   * compiler keeps inputs and parameters in registers across the stores. */
  const double *restrict phi_in = a->in[IN_PHI], *restrict slip_in = a->in[IN_SLIP], *restrict rho_in = a->in[IN_RHO_F],
                         *restrict mu_in = a->in[IN_MU_F], *restrict dp_in = a->in[IN_D_P],
                         *restrict psi_in = a->in[IN_SPHERICITY];
  double *restrict K = a->out[OUT_K];
  double *restrict dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *restrict dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);
  const double c_visc = p->viscous, c_iner = p->inertial;
  const int32_t Q = a->Q;
  for (int32_t q = 0; q < Q; ++q) {
    const double phi = phi_in[q], slip = slip_in[q], rho = rho_in[q], mu = mu_in[q], dp = dp_in[q], psi = psi_in[q];
    if (!sl_ergun_inputs_ok(phi, slip, rho, mu, dp, psi)) return refuse(a, q);
    const sl_drag_value v = sl_ergun_law(phi, slip, rho, mu, psi * dp, c_visc, c_iner, pringle_form);
    K[q] = v.K;
    if (want_dphi) dK_dphi[q] = v.K_phi;
    if (want_dslip) dK_dslip[q] = v.K_slip;
  }
  return SL_OK;
}

static int evaluate(const void *state, const sl_eval_args *a) {
  const ergun_params *p = state;
  const int pringle = p->form != 0;
  const int dphi = sl_dout(a, N_IN, OUT_K, IN_PHI) != NULL, dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP) != NULL;
  if (dphi && dslip) return pringle ? ergun_loop(p, a, 1, 1, 1) : ergun_loop(p, a, 0, 1, 1);
  if (!dphi && !dslip) return pringle ? ergun_loop(p, a, 1, 0, 0) : ergun_loop(p, a, 0, 0, 0);
  return ergun_loop(p, a, pringle, dphi, dslip); /* one derivative: rare */
}

static const sl_closure_desc ergun = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DRAG,
    .name = "ergun",
    .version = "1.0.0",
    .summary = "Ergun (1952) packed-bed drag",
    .formula =
        "K = viscous phi^2 mu_f / ((1-phi) d^2) + inertial phi rho_f |slip| / d,  d = sphericity d_p\n"
        "(pringle_printed: inertial term divided by (1-phi))",
    .reference = "Ergun (1952) Chem. Eng. Prog. 48:89; Gidaspow (1994) eq 5.62; Pringle (2001) eq 3.12",
    .validity = "dense beds, fluid fraction below about 0.8 (phi > 0.2); phi <= 0.74",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(ergun_params),
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

static const sl_closure_desc *const all[] = {&ergun};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
