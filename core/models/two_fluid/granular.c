/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid model's granular physics (granular.h). */
#include "core/models/two_fluid/granular.h"

#include <math.h>

const char *const tf_quantity_names[TF_Q_N] = {"phi",     "slip",      "theta",         "rho_f",      "mu_f",
                                               "rho_s",   "d_p",       "sphericity",    "gravity",    "slip_wall",
                                               "wall_distance", "shear_rate", "density"};

int tf_granular_check_kinetic(sl_point_closure *gran, double *const *qv, double phi_max, int with_ps,
                              const char *where, sl_diag *d) {
  double th[2] = {1.0, 4.0}, ph[2], mu[2], g[2], ps[2] = {1.0, 4.0}, pair[TF_Q_N][2];
  ph[0] = ph[1] = fmin(0.5 * phi_max, 0.3);
  const double *v[TF_Q_N];
  for (int k = 0; k < TF_Q_N; ++k) pair[k][0] = pair[k][1] = qv[k][0], v[k] = pair[k];
  v[TF_Q_PHI] = ph, v[TF_Q_THETA] = th;
  sl_point_request rq[3] = {{"mu_s", mu, NULL, NULL}, {"gamma", g, NULL, NULL}, {"p_s", ps, NULL, NULL}};
  int rc = sl_point_eval(gran, 2, v, rq, with_ps ? 3 : 2, d);
  if (rc) return rc;
  if (fabs(mu[1] / mu[0] - 2.0) > 1e-9 || fabs(g[1] / g[0] - 8.0) > 1e-9 || fabs(ps[1] / ps[0] - 4.0) > 1e-9)
    return sl_diag_set(d, SL_EBADINPUT, "%s = algebraic needs a kinetic closure (mu_s ~ theta^0.5, gamma ~ "
                                        "theta^1.5%s); [closure.granular] is not one (use transport)",
                       where, with_ps ? ", p_s ~ theta" : "");
  return 0;
}

double tf_theta_algebraic(double A, double B, double C, double *dlog) {
  double sq = 0.0, k = 0.0;
  if (B > 0.0) {
    double root = sqrt(C * C + 4.0 * A * B);
    sq = (-C + root) / (2.0 * B);
    if (sq > 0.0) k = 2.0 * A / (sq * root);
  }
  if (dlog) *dlog = k;
  return fmax(sq * sq, TF_THETA_FLOOR);
}

double tf_theta_capacity(double rho_s, double phi) { return 1.5 * rho_s * phi; }

double tf_theta_exchange(int on, double K) { return on ? 3.0 * K : 0.0; }

double tf_theta_bounded(double theta, double last) { return fmax(theta, fmax(0.2 * last, TF_THETA_FLOOR)); }
