/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The granular temperature's shared physics (core/models/granular.h), on
 * the kinetic law mu_s = mu0 sqrt(theta), gamma = g0 theta^1.5 (the form of
 * Lun et al. 1984 at fixed phi):
 *
 *  - the algebraic theta: without the drag's sink the balance mu0 gd^2
 *    sqrt(theta) = g0 theta^1.5 gives theta = mu0 gd^2 / g0 exactly; with it
 *    (X theta) the quadratic in sqrt(theta), whose root satisfies the
 *    balance to round-off; d ln sqrt(theta) / d ln gd is 1 without the sink
 *    and equals the centred difference of the root with it;
 *  - the bisection for any closure (the pipe's local balance) finds the
 *    same root to 1e-13;
 *  - the linearised pointwise terms: src - sink theta is the balance's net
 *    source mu_s gd^2 - gamma - X theta at the iterate, the sink is
 *    dgamma/dtheta + X, the capacity (3/2) rho_s phi with phi at least 1e-6;
 *  - the walls' flux: only a falling q(theta) is implicit, and the row's
 *    linearisation reproduces q at the iterate;
 *  - the bound: at most a fivefold fall, at least the floor. */
#include <math.h>
#include <stdio.h>

#include "core/models/granular.h"
#include "testing.h"

typedef struct law {
  double mu0, g0;
} law;

static int law_eval(void *user, const double *th, double *mu, double *gam, sl_diag *d) {
  (void)d;
  const law *l = user;
  mu[0] = l->mu0 * sqrt(th[0]), gam[0] = l->g0 * pow(th[0], 1.5);
  return 0;
}

static void algebraic(void) {
  const law l = {0.0123, 4.56e3}; /* Pa s (m/s)^-1 and kg m^-1 s^-3 (m/s)^-3: theta of order 1e-4 - 1e-1 */
  const double gd[3] = {10.0, 100.0, 1000.0}, X[2] = {0.0, 1.7e2};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 2; ++b) {
      double dlog, A = l.mu0 * gd[a] * gd[a], th = sl_theta_algebraic(A, l.g0, X[b], &dlog);
      double res = A * sqrt(th) - l.g0 * pow(th, 1.5) - X[b] * th;
      CHECK_MSG(fabs(res) < 1e-13 * A * sqrt(th), "gd %g, X %g: balance residual %.2e of the production", gd[a], X[b],
                res / (A * sqrt(th)));
      if (b == 0) {
        CHECK_CLOSE(th, A / l.g0, 1e-15);
        CHECK_CLOSE(dlog, 1.0, 1e-14);
      } else { /* the slope against the root's centred difference in ln gd */
        double h = 1e-4, up = sl_theta_algebraic(A * exp(2.0 * h), l.g0, X[b], NULL);
        double dn = sl_theta_algebraic(A * exp(-2.0 * h), l.g0, X[b], NULL);
        double fd = (0.5 * log(up) - 0.5 * log(dn)) / (2.0 * h);
        CHECK_MSG(fabs(dlog - fd) < 1e-7 && dlog > 1.0 && dlog < 2.0,
                  "gd %g: d ln sqrt(theta)/d ln gd %.10f, "
                  "difference %.10f",
                  gd[a], dlog, fd);
      }
      /* the bisection of any closure: the same root */
      double lo, hi, mu, gam, tb;
      law lc = l;
      int rc = sl_theta_balance(1, &gd[a], &X[b], law_eval, &lc, &lo, &hi, &mu, &gam, &tb, NULL);
      CHECK(rc == 0);
      CHECK_MSG(fabs(tb - th) < 1e-13 * th, "gd %g, X %g: bisection %.15e, quadratic %.15e", gd[a], X[b], tb, th);
      printf("gd = %g 1/s, X = %g: theta %.12e m2/s2 (bisection %.2e apart), d ln sqrt(theta)/d ln gd %.6f\n", gd[a],
             X[b], th, fabs(tb - th) / th, dlog);
    }
  /* no dissipation: the floor */
  CHECK(sl_theta_algebraic(1.0, 0.0, 0.0, NULL) == SL_THETA_FLOOR);
}

static void terms(void) {
  const law l = {0.0123, 4.56e3};
  const double rho_s = 2500.0, phi[2] = {0.3, 0.0}, gd[2] = {100.0, 50.0}, th[2] = {2e-3, 5e-4}, X[2] = {170.0, 0.0};
  double mu[2], gam[2], dgam[2], cap[2], src[2], sink[2];
  for (int i = 0; i < 2; ++i)
    mu[i] = l.mu0 * sqrt(th[i]), gam[i] = l.g0 * pow(th[i], 1.5), dgam[i] = 1.5 * l.g0 * sqrt(th[i]);
  sl_theta_terms(2, rho_s, phi, mu, gd, gam, dgam, X, th, cap, src, sink);
  for (int i = 0; i < 2; ++i) {
    double P = mu[i] * gd[i] * gd[i], net = P - gam[i] - X[i] * th[i];
    CHECK_MSG(fabs(src[i] - sink[i] * th[i] - net) < 1e-14 * (P + gam[i] + X[i] * th[i]),
              "point %d: src - sink theta %.15e, net source %.15e", i, src[i] - sink[i] * th[i], net);
    CHECK_CLOSE(sink[i], dgam[i] + X[i], 1e-15);
    CHECK_CLOSE(cap[i], 1.5 * rho_s * fmax(phi[i], 1e-6), 1e-15);
  }
  /* a negative dgamma/dtheta is not made implicit (the diagonal stays positive) */
  double c1, s1, k1;
  sl_theta_local(rho_s, 0.3, 1.0, 2.0, -5.0, 3.0, 0.1, &c1, &s1, &k1);
  CHECK(k1 == 3.0 && s1 == 1.0 - 2.0);
  /* in place: gam as src, X as sink */
  double g2[1] = {gam[0]}, x2[1] = {X[0]}, c2[1];
  sl_theta_terms(1, rho_s, phi, mu, gd, g2, dgam, x2, th, c2, g2, x2);
  CHECK(g2[0] == src[0] && x2[0] == sink[0] && c2[0] == cap[0]);
}

static void walls(void) {
  CHECK(sl_theta_wall_implicit(-2.5) == 2.5);
  CHECK(sl_theta_wall_implicit(4.0) == 0.0);
  /* the row's linear flux A (q + c theta_it) - A c theta is A q at theta = theta_it */
  double rhs = 1.0, diag = 2.0, A = 0.3, q = -0.7, c = sl_theta_wall_implicit(-1.9), it = 0.04;
  sl_theta_wall_row(A, q, c, it, &rhs, &diag);
  CHECK_CLOSE((rhs - 1.0) - (diag - 2.0) * it, A * q, 1e-14);
  CHECK_CLOSE(diag - 2.0, A * 1.9, 1e-14);
}

static void bound(void) {
  CHECK(sl_theta_bounded(-1.0, 1.0) == 0.2);
  CHECK(sl_theta_bounded(0.5, 1.0) == 0.5);
  CHECK(sl_theta_bounded(-1.0, 0.0) == SL_THETA_FLOOR);
}

int main(void) {
  algebraic();
  terms();
  walls();
  bound();
  return sl_test_summary();
}
