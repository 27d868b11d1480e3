/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The evaluate loop shared by the two kinetic-theory closures (lun.c,
 * gidaspow.c): same inputs, outputs and parameters, different shear
 * viscosity and conductivity (kinetic.h). Header-only, static, no state. */
#ifndef SLUICE_PLUGINS_GRANULAR_KT_CLOSURE_H
#define SLUICE_PLUGINS_GRANULAR_KT_CLOSURE_H

#include <math.h>
#include <sluice/closure.h>
#include <stddef.h>

#include "granular/inputs.h"
#include "granular/kinetic.h"

typedef struct kt_params {
  double e;       /* particle-particle restitution coefficient */
  double phi_max; /* maximum packing */
  double delta;   /* g0 is continued linearly above phi_max - delta */
  int32_t radial; /* KT_G0_* */
} kt_params;

enum { KT_IN_PHI, KT_IN_THETA, KT_IN_RHO_S, KT_IN_D_P, KT_N_IN };
enum { KT_OUT_G0, KT_OUT_P_S, KT_OUT_MU_S, KT_OUT_LAMBDA_S, KT_OUT_KAPPA, KT_OUT_GAMMA, KT_N_OUT };

#define KT_PARAMS(default_radial)                                                                     \
  {                                                                                                   \
    SL_PARAM_REAL_OF(kt_params, e, 0.9, 0.0, 1.0, "1", "particle-particle restitution coefficient"),  \
        SL_PARAM_REAL_OF(kt_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing fraction in g0"), \
        SL_PARAM_REAL_OF(kt_params, delta, 0.01, 1e-4, 0.1, "1",                                      \
                         "g0 is continued by its tangent line above phi_max - delta (C1, finite)"),   \
        SL_PARAM_ENUM_OF(kt_params, radial, default_radial, KT_G0_CHOICES, KT_G0_HELP),               \
  }

#define KT_INPUTS                                                                                               \
  {                                                                                                             \
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.74, "solids volume fraction (g0 continued above phi_max - delta)"}, \
        {"theta", "m^2 s^-2", SL_FIELD_DIFF, 1e-3, 1e-12, 1e4, "granular temperature"},                         \
        {"rho_s", "kg m^-3", 0, 2650.0, 1.0, 1e5, "solid density"},                                             \
        {"d_p", "m", 0, 5e-4, 1e-8, 1.0, "particle diameter"},                                                  \
  }

/* Units: kappa kg m^-1 s^-1 (q = -kappa grad theta); gamma kg m^-1 s^-3. */
#define KT_OUTPUTS                                                                                   \
  {                                                                                                  \
    {"g0", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "radial distribution function at contact"},              \
        {"p_s", "Pa", SL_FIELD_OPTIONAL, 0, 0, 0, "solids (kinetic + collisional) pressure"},        \
        {"mu_s", "Pa s", SL_FIELD_OPTIONAL, 0, 0, 0, "solids shear viscosity (phase total)"},        \
        {"lambda_s", "Pa s", SL_FIELD_OPTIONAL, 0, 0, 0, "solids bulk viscosity (times div u_s I)"}, \
        {"kappa", "kg m^-1 s^-1", SL_FIELD_OPTIONAL, 0, 0, 0, "granular-energy conductivity"},       \
        {"gamma", "kg m^-1 s^-3", SL_FIELD_OPTIONAL, 0, 0, 0, "collisional dissipation rate"},       \
  }

static inline int kt_evaluate(int variant, const kt_params *p, const sl_field_desc *in, const sl_eval_args *a) {
  int rc = gr_check_inputs(a, in, KT_N_IN);
  if (rc) return rc;
  const double *phi = a->in[KT_IN_PHI], *theta = a->in[KT_IN_THETA], *rho = a->in[KT_IN_RHO_S], *dp = a->in[KT_IN_D_P];
  double *out[KT_N_OUT], *dphi[KT_N_OUT], *dth[KT_N_OUT];
  for (int k = 0; k < KT_N_OUT; ++k) {
    out[k] = a->out[k];
    dphi[k] = out[k] ? sl_dout(a, KT_N_IN, k, KT_IN_PHI) : NULL;
    dth[k] = out[k] ? sl_dout(a, KT_N_IN, k, KT_IN_THETA) : NULL;
  }
  const double e = p->e, ep = 1.0 + e;
  const double c_lambda = (4.0 / 3.0) * ep / KT_SQRT_PI;    /* lambda_s / (rho d sqrt(theta) phi^2 g0) */
  const double c_gamma = 12.0 * (1.0 - e * e) / KT_SQRT_PI; /* gamma d / (rho theta^1.5 phi^2 g0) */
  for (int32_t q = 0; q < a->Q; ++q) {
    double f = phi[q], th = theta[q], st = sqrt(th);
    double dg, g = kt_g0(p->radial, f, p->phi_max, p->delta, &dg);
    double s = rho[q] * dp[q] * st;                          /* rho_s d_p sqrt(theta) */
    double f2g = f * f * g, df2g = 2.0 * f * g + f * f * dg; /* phi^2 g0 and its total phi-derivative */

    gr_set(out[KT_OUT_G0], q, g);
    gr_set(dphi[KT_OUT_G0], q, dg);
    gr_set(dth[KT_OUT_G0], q, 0.0);

    if (out[KT_OUT_P_S]) {
      double A = 2.0 * ep, r = rho[q];
      out[KT_OUT_P_S][q] = r * f * th * (1.0 + A * f * g);
      gr_set(dphi[KT_OUT_P_S], q, r * th * (1.0 + A * (2.0 * f * g + f * f * dg)));
      gr_set(dth[KT_OUT_P_S], q, r * f * (1.0 + A * f * g));
    }
    if (out[KT_OUT_MU_S]) {
      double fp, fg, sh = kt_mu_shape(variant, e, f, g, &fp, &fg);
      out[KT_OUT_MU_S][q] = s * sh;
      gr_set(dphi[KT_OUT_MU_S], q, s * (fp + fg * dg));
      gr_set(dth[KT_OUT_MU_S], q, 0.5 * rho[q] * dp[q] * sh / st);
    }
    if (out[KT_OUT_LAMBDA_S]) {
      out[KT_OUT_LAMBDA_S][q] = c_lambda * s * f2g;
      gr_set(dphi[KT_OUT_LAMBDA_S], q, c_lambda * s * df2g);
      gr_set(dth[KT_OUT_LAMBDA_S], q, 0.5 * c_lambda * rho[q] * dp[q] * f2g / st);
    }
    if (out[KT_OUT_KAPPA]) {
      double fp, fg, sh = kt_kappa_shape(variant, e, f, g, &fp, &fg);
      out[KT_OUT_KAPPA][q] = s * sh;
      gr_set(dphi[KT_OUT_KAPPA], q, s * (fp + fg * dg));
      gr_set(dth[KT_OUT_KAPPA], q, 0.5 * rho[q] * dp[q] * sh / st);
    }
    if (out[KT_OUT_GAMMA]) {
      double c = c_gamma * rho[q] / dp[q]; /* gamma = c theta^1.5 phi^2 g0 */
      out[KT_OUT_GAMMA][q] = c * th * st * f2g;
      gr_set(dphi[KT_OUT_GAMMA], q, c * th * st * df2g);
      gr_set(dth[KT_OUT_GAMMA], q, 1.5 * c * st * f2g);
    }
  }
  return SL_OK;
}

#endif
