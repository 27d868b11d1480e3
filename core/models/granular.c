/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The granular temperature's physics (granular.h). */
#include "core/models/granular.h"

#include <math.h>

int sl_granular_require(const sl_point_closure *gran, int with_kappa, const char *who, sl_diag *d) {
  static const char *const need[] = {"mu_s", "gamma", "kappa"};
  for (int k = 0; k < (with_kappa ? 3 : 2); ++k)
    if (!sl_point_has_output(gran, need[k]))
      return sl_diag_set(d, SL_EBADINPUT,
                         "[closure.granular]: %s needs mu_s, gamma%s of (phi, theta); this closure "
                         "gives no %s",
                         who, with_kappa ? " and kappa" : "", need[k]);
  return 0;
}

#define MAX_Q 32

int sl_granular_check_kinetic(sl_point_closure *gran, int nq, double *const *qv, int iphi, int itheta, double phi_max,
                              int with_ps, const char *where, sl_diag *d) {
  if (nq > MAX_Q) return sl_diag_set(d, SL_EFAILED, "the kinetic-scaling check: %d quantities, at most %d", nq, MAX_Q);
  double th[2] = {1.0, 4.0}, ph[2], mu[2], g[2], ps[2] = {1.0, 4.0}, pair[MAX_Q][2];
  ph[0] = ph[1] = fmin(0.5 * phi_max, 0.3);
  const double *v[MAX_Q];
  for (int k = 0; k < nq; ++k) pair[k][0] = pair[k][1] = qv[k][0], v[k] = pair[k];
  v[iphi] = ph, v[itheta] = th;
  sl_point_request rq[3] = {{"mu_s", mu, NULL, NULL}, {"gamma", g, NULL, NULL}, {"p_s", ps, NULL, NULL}};
  int rc = sl_point_eval(gran, 2, v, rq, with_ps ? 3 : 2, d);
  if (rc) return rc;
  if (fabs(mu[1] / mu[0] - 2.0) > 1e-9 || fabs(g[1] / g[0] - 8.0) > 1e-9 || fabs(ps[1] / ps[0] - 4.0) > 1e-9)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = algebraic needs a kinetic closure (mu_s ~ theta^0.5, gamma ~ "
                       "theta^1.5%s); [closure.granular] is not one (use transport)",
                       where, with_ps ? ", p_s ~ theta" : "");
  return 0;
}

double sl_theta_algebraic(double A, double B, double C, double *dlog) {
  double sq = 0.0, k = 0.0;
  if (B > 0.0) {
    double root = sqrt(C * C + 4.0 * A * B);
    sq = (-C + root) / (2.0 * B);
    if (sq > 0.0) k = 2.0 * A / (sq * root);
  }
  if (dlog) *dlog = k;
  return fmax(sq * sq, SL_THETA_FLOOR);
}

int sl_theta_balance(int n, const double *gd, const double *X, sl_theta_eval_fn eval, void *user, double *lo,
                     double *hi, double *mu, double *gam, double *th, sl_diag *d) {
  for (int i = 0; i < n; ++i) lo[i] = log(SL_THETA_FLOOR), hi[i] = log(1e2);
  for (int it = 0; it < 60; ++it) {
    for (int i = 0; i < n; ++i) th[i] = fmax(exp(0.5 * (lo[i] + hi[i])), SL_THETA_FLOOR);
    int rc = eval(user, th, mu, gam, d);
    if (rc) return rc;
    for (int i = 0; i < n; ++i) {
      double excess = mu[i] * gd[i] * gd[i] - gam[i] - X[i] * th[i];
      if (excess > 0.0) lo[i] = 0.5 * (lo[i] + hi[i]);
      else hi[i] = 0.5 * (lo[i] + hi[i]);
    }
  }
  for (int i = 0; i < n; ++i) th[i] = exp(0.5 * (lo[i] + hi[i]));
  return 0;
}

double sl_theta_capacity(double rho_s, double phi) { return 1.5 * rho_s * phi; }

double sl_theta_exchange(int on, double K) { return on ? 3.0 * K : 0.0; }

void sl_theta_local(double rho_s, double phi, double P, double gam, double dgam, double X, double th, double *cap,
                    double *src, double *sink) {
  double dg = fmax(dgam, 0.0);
  *cap = sl_theta_capacity(rho_s, fmax(phi, 1e-6));
  *sink = dg + X;
  *src = P - gam + dg * th;
}

void sl_theta_terms(int n, double rho_s, const double *phi, const double *mu_s, const double *gd, const double *gam,
                    const double *dgam, const double *X, const double *th, double *cap, double *src, double *sink) {
  for (int i = 0; i < n; ++i) /* by value: gam may be src, X may be sink */
    sl_theta_local(rho_s, phi[i], mu_s[i] * gd[i] * gd[i], gam[i], dgam[i], X[i], th[i], &cap[i], &src[i], &sink[i]);
}

double sl_theta_bounded(double theta, double last) { return fmax(theta, fmax(0.2 * last, SL_THETA_FLOOR)); }
