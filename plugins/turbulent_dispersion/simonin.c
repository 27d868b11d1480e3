/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Simonin's turbulent dispersion of the solids: the dispersivity of the
 * fluid-particle turbulence, isotropic, D_fs = t_fs k_fs/3 (Krampa 2009 eq
 * 4.63; Enwald, Peirano & Almstedt 1996, Int. J. Multiphase Flow 22:21; Deutsch
 * & Simonin 1991), with t_fs the eddy-particle interaction time the host
 * computes with the crossing-trajectory effect (Krampa eq 4.61, Csanady 1963:
 * t_fs = C_mu (3k/(2 eps)) [1 + C_beta 3 |u_f - u_s|^2/(2k)]^(-1/2)) and k_fs
 * = <u_f'.u_s'> the fluid-particle covariance (Tchen's equilibrium or
 * transported: the host's). Fine particles at zero slip (t_fs = C_mu 3k/(2 eps),
 * k_fs = 2k) disperse as the fluid: D_fs = C_mu k^2/eps = nu_t, the check
 * point below. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/inputs.h"

enum { IN_T_FS, IN_K_FS, N_IN };
enum { OUT_D_T, N_OUT };

static const sl_field_desc inputs[] = {
    {"t_fs", "s", SL_FIELD_DIFF, 1e-2, 0.0, 1e9, "the eddy-particle interaction time (crossing trajectories)"},
    {"k_fs", "m^2 s^-2", SL_FIELD_DIFF, 1e-2, 0.0, 1e6, "the fluid-particle velocity covariance <u_f'.u_s'>"},
};

static const sl_field_desc outputs[] = {
    {"D_t", "m^2 s^-1", 0, 0, 0, 0, "the solids' turbulent dispersivity t_fs k_fs/3"},
};

/* k = 0.02 m2/s2, eps = 0.5 m2/s3, no slip: t_fs = 0.09 * 1.5 * 0.02/0.5 = 5.4e-3 s, k_fs = 2k = 0.04:
   D = 0.09 * 0.02^2/0.5 = 7.2e-5 m2/s = nu_t */
static const double check_in_0[N_IN] = {5.4e-3, 0.04};
static const sl_check_point checks[] = {
    {check_in_0, OUT_D_T, 7.2e-5, 1e-14,
     "Krampa (2009) eqs 4.61, 4.63: tracers at zero slip (k_fs = 2k) disperse as nu_t = C_mu k^2/eps"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  (void)state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *t = a->in[IN_T_FS], *kfs = a->in[IN_K_FS];
  double *D = a->out[OUT_D_T];
  double *dt = sl_dout(a, N_IN, OUT_D_T, IN_T_FS), *dk = sl_dout(a, N_IN, OUT_D_T, IN_K_FS);
  for (int32_t q = 0; q < a->Q; ++q) {
    D[q] = t[q] * kfs[q] / 3.0;
    gr_set(dt, q, kfs[q] / 3.0);
    gr_set(dk, q, t[q] / 3.0);
  }
  return SL_OK;
}

static const sl_closure_desc simonin = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_TURBULENT_DISPERSION,
    .name = "simonin",
    .version = "1.0.0",
    .summary = "Simonin's dispersion by the fluid-particle turbulence, D_t = t_fs k_fs/3",
    .formula = "D_t = t_fs k_fs / 3 (t_fs with the crossing-trajectory effect, k_fs = <u_f'.u_s'>: the host's)",
    .reference =
        "Krampa (2009) eqs 4.60-4.63; Enwald, Peirano & Almstedt (1996) Int. J. Multiphase Flow 22:21; "
        "Csanady (1963) J. Atmos. Sci. 20:201",
    .validity = "isotropic fluid-particle turbulence (the trace of D_fs,ij); t_fs >= 0, k_fs >= 0",
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

static const sl_closure_desc *const all[] = {&simonin};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
