/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tests of the viscosity closures: suspension laws (einstein, batchelor,
 * krieger_dougherty, maron_pierce, eilers, pringle_granular) and
 * viscoplastic laws (bingham, herschel_bulkley, lalli).
 *
 * Expected values are written here with a different arrangement of the
 * algebra than the plugins use (and in long double where cancellation
 * matters), so that a slip in either is caught. */
#include <float.h>
#include <math.h>

#include "closure_test.h"
#include "testing.h"

#define RTOL 1e-12

/* Central difference of output `out` in input `wrt` of a one-input closure
 * family, other inputs at the values given. */
static double fd_phi(sl_tc *t, double phi, double mu_f, double h) {
  double up = sl_tc_eval(t, "viscosity", "phi", phi + h, "mu_f", mu_f, NULL);
  double dn = sl_tc_eval(t, "viscosity", "phi", phi - h, "mu_f", mu_f, NULL);
  return (up - dn) / (2 * h);
}

static double fd_rate(sl_tc *t, double g, double h) {
  double up = sl_tc_eval(t, "viscosity", "shear_rate", g + h, NULL);
  double dn = sl_tc_eval(t, "viscosity", "shear_rate", g - h, NULL);
  return (up - dn) / (2 * h);
}

static double eval_phi(sl_tc *t, double phi, double mu_f) {
  return sl_tc_eval(t, "viscosity", "phi", phi, "mu_f", mu_f, NULL);
}

static double deriv_phi(sl_tc *t, double phi, double mu_f) {
  return sl_tc_deriv(t, "viscosity", "phi", "phi", phi, "mu_f", mu_f, NULL);
}

static double eval_rate(sl_tc *t, double g) { return sl_tc_eval(t, "viscosity", "shear_rate", g, NULL); }

static double deriv_rate(sl_tc *t, double g) {
  return sl_tc_deriv(t, "viscosity", "shear_rate", "shear_rate", g, NULL);
}

/* Refused states of a (phi, mu_f) closure. */
static void check_phi_refused(sl_tc *t, double phi) {
  double v = eval_phi(t, phi, 1e-3);
  CHECK_MSG(sl_tc_status(t) > 0 && isnan(v), "phi = %g: status %d", phi, sl_tc_status(t));
  CHECK(t->err.point == 0 && t->err.msg[0] != '\0');
}

static const double states_phi[][2] = {{0.0, 1e-3}, {0.013, 1e-3}, {0.05, 2.5e-3}, {0.09, 0.3}};

static void test_einstein(void) {
  sl_tc *t = sl_tc_open("viscosity", "einstein", NULL);
  for (size_t i = 0; i < sizeof states_phi / sizeof states_phi[0]; ++i) {
    double phi = states_phi[i][0], mu = states_phi[i][1];
    CHECK_CLOSE(eval_phi(t, phi, mu), mu + 2.5 * mu * phi, RTOL);
    CHECK_CLOSE(deriv_phi(t, phi, mu), 2.5 * mu, RTOL);
  }
  CHECK_CLOSE(eval_phi(t, 0.1, 1e-3), 1.25e-3, RTOL); /* edge of the dilute range is accepted */
  check_phi_refused(t, 0.1000001);
  check_phi_refused(t, -1e-9);
  check_phi_refused(t, NAN);
  eval_phi(t, 0.05, 0.0);
  CHECK(sl_tc_status(t) > 0); /* mu_f below 1e-7 */
  sl_tc_close(t);
  /* another shape: [eta] as a parameter */
  t = sl_tc_open("viscosity", "einstein", "intrinsic_viscosity=4.0", NULL);
  CHECK_CLOSE(eval_phi(t, 0.05, 1e-3), 1.2e-3, RTOL);
  sl_tc_close(t);
}

static void test_batchelor(void) {
  sl_tc *t = sl_tc_open("viscosity", "batchelor", NULL);
  const double phis[] = {0.0, 0.02, 0.1, 0.17};
  for (int i = 0; i < 4; ++i) {
    double phi = phis[i], mu = 1.7e-3;
    CHECK_CLOSE(eval_phi(t, phi, mu), mu * (1 + 2.5 * phi) + 6.2 * mu * phi * phi, RTOL);
    CHECK_CLOSE(deriv_phi(t, phi, mu), 2.5 * mu + 12.4 * mu * phi, RTOL);
  }
  check_phi_refused(t, 0.21);
  check_phi_refused(t, NAN);
  sl_tc_close(t);
  t = sl_tc_open("viscosity", "batchelor", "quadratic=5.2", NULL);
  CHECK_CLOSE(eval_phi(t, 0.1, 1.0), 1.302, RTOL);
  sl_tc_close(t);
}

/* (1 - phi/pm)^(-k pm) written as exp(-k pm log1p(-phi/pm)), in long double. */
static double kd_ref(double phi, double mu, double k, double pm) {
  return (double)((long double)mu * expl(-(long double)k * pm * log1pl(-(long double)phi / pm)));
}

static void test_krieger_dougherty(void) {
  sl_tc *t = sl_tc_open("viscosity", "krieger_dougherty", NULL);
  const double phis[] = {0.0, 0.1, 0.3, 0.55, 0.67};
  for (int i = 0; i < 5; ++i) {
    double phi = phis[i], mu = 1e-3;
    CHECK_CLOSE(eval_phi(t, phi, mu), kd_ref(phi, mu, 2.5, 0.68), RTOL);
    /* d/dphi = mu k (1 - phi/pm)^(-k pm - 1) */
    double d = mu * 2.5 * pow(1 - phi / 0.68, -2.5 * 0.68 - 1);
    CHECK_CLOSE(deriv_phi(t, phi, mu), d, 1e-11);
  }
  /* Nigam (1999) eq 2.18 (K = 2.5, alpha_m = 0.68), 5 significant figures. */
  const double tab[][2] = {{0.05, 1.1386}, {0.10, 1.3105}, {0.20, 1.8078}, {0.30, 2.6893},
                           {0.40, 4.5196}, {0.50, 9.5786}, {0.60, 38.020}, {0.65, 201.45}};
  for (int i = 0; i < 8; ++i) CHECK_CLOSE(eval_phi(t, tab[i][0], 1.0), tab[i][1], 5e-5);
  /* Divergence at phi_max: recoverable code at and beyond it, large just below. */
  check_phi_refused(t, 0.68);
  check_phi_refused(t, 0.7);
  check_phi_refused(t, NAN);
  check_phi_refused(t, -0.01);
  double near = eval_phi(t, 0.68 - 1e-6, 1.0);
  CHECK(sl_tc_status(t) == 0 && near > 1e9 && isfinite(near));
  sl_tc_close(t);
  /* Nigam section 4.5 parameters, [eta] phi_max = 1.82; phi_max as a parameter. */
  t = sl_tc_open("viscosity", "krieger_dougherty", "intrinsic_viscosity=2.6765", NULL);
  CHECK_CLOSE(eval_phi(t, 0.4, 1.0), kd_ref(0.4, 1.0, 2.6765, 0.68), RTOL);
  CHECK_CLOSE(eval_phi(t, 0.4, 1.0), pow(1 - 0.4 / 0.68, -1.82002), RTOL);
  sl_tc_close(t);
  t = sl_tc_open("viscosity", "krieger_dougherty", "phi_max=0.6", NULL);
  check_phi_refused(t, 0.6);
  CHECK_CLOSE(eval_phi(t, 0.59, 1.0), kd_ref(0.59, 1.0, 2.5, 0.6), RTOL);
  sl_tc_close(t);
  t = sl_tc_open("viscosity", "krieger_dougherty", "phi_max=0.74", NULL);
  CHECK_CLOSE(eval_phi(t, 0.7, 1.0), kd_ref(0.7, 1.0, 2.5, 0.74), RTOL); /* above the declared 0.68: accepted */
  sl_tc_close(t);
}

static void test_maron_pierce(void) {
  sl_tc *t = sl_tc_open("viscosity", "maron_pierce", NULL);
  const double phis[] = {0.0, 0.2, 0.34, 0.6};
  for (int i = 0; i < 4; ++i) {
    double phi = phis[i], mu = 2e-3, pm = 0.68;
    CHECK_CLOSE(eval_phi(t, phi, mu), mu * pm * pm / ((pm - phi) * (pm - phi)), RTOL);
    CHECK_CLOSE(deriv_phi(t, phi, mu), 2 * mu * pm * pm / ((pm - phi) * (pm - phi) * (pm - phi)), RTOL);
  }
  CHECK_CLOSE(eval_phi(t, 0.34, 1.0), 4.0, RTOL);
  check_phi_refused(t, 0.68);
  check_phi_refused(t, NAN);
  sl_tc_close(t);
}

static void test_eilers(void) {
  sl_tc *t = sl_tc_open("viscosity", "eilers", NULL);
  const double phis[] = {0.0, 0.15, 0.34, 0.62};
  for (int i = 0; i < 4; ++i) {
    double phi = phis[i], mu = 1e-3, pm = 0.68;
    double r = (pm - phi + 1.25 * phi * pm) / (pm - phi);
    CHECK_CLOSE(eval_phi(t, phi, mu), mu * r * r, RTOL);
    /* d/dphi r = 1.25 pm^2/(pm - phi)^2 */
    CHECK_CLOSE(deriv_phi(t, phi, mu), 2 * mu * r * 1.25 * pm * pm / ((pm - phi) * (pm - phi)), RTOL);
  }
  CHECK_CLOSE(eval_phi(t, 0.34, 1.0), 1.85 * 1.85, RTOL);
  check_phi_refused(t, 0.68);
  check_phi_refused(t, NAN);
  sl_tc_close(t);
}

static void test_pringle_granular(void) {
  sl_tc *t = sl_tc_open("viscosity", "pringle_granular", NULL);
  const double k1 = 1.1721, k2 = -1.7172;
  const double phis[] = {0.01, 0.2, 0.35, 0.5};
  for (int i = 0; i < 4; ++i) {
    double phi = phis[i], mu = 1e-3;
    double inner = 1.0 / (k1 / phi + k2); /* = phi/(k1 + k2 phi) */
    CHECK_CLOSE(eval_phi(t, phi, mu), mu * exp(exp(inner)), RTOL);
    double d = mu * exp(exp(inner) + inner) * k1 / ((k1 + k2 * phi) * (k1 + k2 * phi));
    CHECK_CLOSE(deriv_phi(t, phi, mu), d, RTOL);
  }
  /* Pringle (2001) eqs 3.36-3.37, 3 significant figures (half a unit in the
   * last printed digit). 0.55 lies outside the Newtonian range: refused. */
  const double tab[][3] = {{0.01, 2.74, 0.005}, {0.05, 2.85, 0.005}, {0.10, 3.02, 0.005},
                           {0.20, 3.57, 0.005}, {0.30, 4.85, 0.005}, {0.35, 6.33, 0.005},
                           {0.40, 9.78, 0.005}, {0.45, 21.9, 0.05},  {0.50, 138.0, 0.5}};
  for (int i = 0; i < 9; ++i) {
    double v = eval_phi(t, tab[i][0], 1.0);
    CHECK_MSG(fabs(v - tab[i][1]) <= tab[i][2], "pringle_granular(%g) = %g, table %g", tab[i][0], v, tab[i][1]);
  }
  check_phi_refused(t, 0.55);
  check_phi_refused(t, NAN);
  /* No Einstein limit: tends to e mu_f at phi = 0 (documented). */
  CHECK_CLOSE(eval_phi(t, 0.0, 1e-3), exp(1.0) * 1e-3, RTOL);
  CHECK_CLOSE(deriv_phi(t, 0.0, 1e-3), exp(1.0) * 1e-3 / k1, RTOL);
  sl_tc_close(t);
  /* A refit whose divergence k1/|k2| falls inside [0, 0.5]: refused there. */
  t = sl_tc_open("viscosity", "pringle_granular", "k2=-3.0", NULL);
  check_phi_refused(t, 1.1721 / 3.0);
  check_phi_refused(t, 0.45);
  CHECK(sl_tc_status(t) > 0);
  sl_tc_close(t);
}

/* First-order slope (mu/mu_f - 1)/phi of each suspension law at small phi:
 * it must tend to 2.5 (Einstein) with an error O(phi). */
static void test_einstein_limit(void) {
  const char *laws[] = {"einstein", "batchelor", "krieger_dougherty", "eilers"};
  for (int l = 0; l < 4; ++l) {
    sl_tc *t = sl_tc_open("viscosity", laws[l], NULL);
    double prev = INFINITY;
    const double hs[] = {1e-2, 1e-3, 1e-4, 1e-5};
    for (int i = 0; i < 4; ++i) {
      double h = hs[i];
      double slope = (eval_phi(t, h, 1e-3) / 1e-3 - 1.0) / h;
      double err = fabs(slope - 2.5);
      CHECK_MSG(err < 20 * h + 1e-9, "%s: slope %.12g at phi = %g", laws[l], slope, h);
      CHECK_MSG(err <= prev + 1e-9, "%s: slope error grows as phi -> 0 (%g after %g)", laws[l], err, prev);
      prev = err;
    }
    CHECK_CLOSE(deriv_phi(t, 0.0, 1e-3), 2.5e-3, RTOL);
    sl_tc_close(t);
  }
  /* Maron-Pierce: slope 2/phi_max, Einstein's only for phi_max = 0.8. */
  sl_tc *t = sl_tc_open("viscosity", "maron_pierce", NULL);
  CHECK_CLOSE(deriv_phi(t, 0.0, 1.0), 2.0 / 0.68, RTOL);
  CHECK(fabs(deriv_phi(t, 0.0, 1.0) - 2.5) > 0.4);
  sl_tc_close(t);
  t = sl_tc_open("viscosity", "maron_pierce", "phi_max=0.8", NULL);
  CHECK_CLOSE(deriv_phi(t, 0.0, 1.0), 2.5, RTOL);
  CHECK(fabs((eval_phi(t, 1e-5, 1.0) - 1.0) / 1e-5 - 2.5) < 1e-4);
  sl_tc_close(t);
  /* Pringle: no Einstein limit at all (mu(0) = e mu_f). */
  t = sl_tc_open("viscosity", "pringle_granular", NULL);
  CHECK(fabs(eval_phi(t, 1e-6, 1.0) - 1.0) > 1.7);
  sl_tc_close(t);
  /* Derivatives agree with central differences for every suspension law. */
  const char *all[] = {"einstein", "batchelor", "krieger_dougherty", "maron_pierce", "eilers", "pringle_granular"};
  for (int l = 0; l < 6; ++l) {
    t = sl_tc_open("viscosity", all[l], NULL);
    double phi = l < 2 ? 0.07 : 0.3;
    CHECK_CLOSE(deriv_phi(t, phi, 1e-3), fd_phi(t, phi, 1e-3, 1e-6), 1e-7);
    sl_tc_close(t);
  }
}

/* ---- viscoplastic laws ---- */

static void check_rate_refused(sl_tc *t, double g) {
  double v = eval_rate(t, g);
  CHECK_MSG(sl_tc_status(t) > 0 && isnan(v), "shear_rate = %g: status %d", g, sl_tc_status(t));
}

static void test_bingham_bercovier(void) {
  const double mu_p = 0.1, tau0 = 10.0, eps = 1e-3;
  sl_tc *t = sl_tc_open("viscosity", "bingham", NULL); /* defaults: bercovier_engelman */
  CHECK_CLOSE(eval_rate(t, 0.0), mu_p + tau0 / eps, RTOL);
  CHECK(deriv_rate(t, 0.0) == 0.0);
  const double gs[] = {1e-4, 2e-3, 0.5, 3.0, 100.0};
  for (int i = 0; i < 5; ++i) {
    double g = gs[i];
    double rg = g * sqrt(1.0 + (eps / g) * (eps / g));
    CHECK_CLOSE(eval_rate(t, g), mu_p + tau0 / rg, RTOL);
    CHECK_CLOSE(deriv_rate(t, g), -tau0 * g / pow(g * g + eps * eps, 1.5), RTOL);
    CHECK_CLOSE(deriv_rate(t, g), fd_rate(t, g, 1e-6 * g), 1e-6);
  }
  check_rate_refused(t, -1e-3);
  check_rate_refused(t, NAN);
  check_rate_refused(t, INFINITY);
  sl_tc_close(t);
  /* Large shear rate: tends to the Bingham law mu_p + tau0/g; the error
   * -tau0 eps^2/(2 g^3) (1 + O(eps^2/g^2)) falls as eps^2 when the
   * regularisation tightens (mu_p = 0 and g = 1 keep rounding below 1e-8
   * of the error). */
  const double g = 1.0;
  double prev = INFINITY;
  const char *eps_set[] = {"eps=0.1", "eps=0.01", "eps=0.001", "eps=0.0001"};
  const double eps_v[] = {0.1, 0.01, 0.001, 0.0001};
  for (int i = 0; i < 4; ++i) {
    t = sl_tc_open("viscosity", "bingham", eps_set[i], "plastic_viscosity=0", NULL);
    double err = eval_rate(t, g) - tau0 / g;
    double model = -tau0 * eps_v[i] * eps_v[i] / (2 * g * g * g);
    CHECK_CLOSE(err, model, eps_v[i] * eps_v[i] / (g * g) + 1e-7); /* relative O(eps^2/g^2) */
    CHECK(fabs(err) < prev / 50);
    prev = fabs(err);
    sl_tc_close(t);
  }
  /* Still far from the rest value at moderate rates: the plastic plateau. */
  t = sl_tc_open("viscosity", "bingham", NULL);
  CHECK_CLOSE(eval_rate(t, 1e6), mu_p + tau0 / 1e6, RTOL);
  sl_tc_close(t);
}

/* Papanastasiou reference in long double: mu_p + tau0 (1 - e^-mg)/g. */
static double papa_ref(double mu_p, double tau0, double m, double g) {
  long double x = (long double)m * g;
  return (double)(mu_p + (long double)tau0 * m * (-expm1l(-x)) / x);
}

static void test_bingham_papanastasiou(void) {
  const double mu_p = 0.1, tau0 = 10.0, m = 1e3;
  sl_tc *t = sl_tc_open("viscosity", "bingham", "regularisation=papanastasiou", NULL);
  /* Exact limit at rest, and the slope there: d/dg = -tau0 m^2 / 2. */
  CHECK_CLOSE(eval_rate(t, 0.0), mu_p + tau0 * m, RTOL);
  CHECK_CLOSE(deriv_rate(t, 0.0), -tau0 * m * m / 2, RTOL);
  /* Near 0: the series tau0 m (1 - x/2 + x^2/6 - x^3/24), x = m g. */
  const double tiny[] = {1e-300, 1e-15, 1e-12, 1e-9, 1e-8};
  for (int i = 0; i < 5; ++i) {
    double x = m * tiny[i];
    double v = mu_p + tau0 * m * (1 - x / 2 + x * x / 6 - x * x * x / 24);
    CHECK_CLOSE(eval_rate(t, tiny[i]), v, RTOL);
    CHECK_CLOSE(deriv_rate(t, tiny[i]), tau0 * m * m * (-0.5 + x / 3 - x * x / 8), RTOL);
  }
  /* Away from 0 (both sides of the 1e-5 and 0.25 switches in x). */
  const double gs[] = {9e-9, 1.1e-8, 1e-5, 2.4e-4, 2.6e-4, 1e-3, 5e-3, 0.05, 3.0};
  for (int i = 0; i < 9; ++i) {
    double g = gs[i];
    CHECK_CLOSE(eval_rate(t, g), papa_ref(mu_p, tau0, m, g), RTOL);
    long double x = (long double)m * g, e = expl(-x);
    double d = (double)((long double)tau0 * (x * e - 1 + e) / ((long double)g * g));
    CHECK_CLOSE(deriv_rate(t, g), d, x > 1e-3L ? 1e-10 : 1e-5); /* the long double reference cancels at small x */
    if (g >= 1e-6) CHECK_CLOSE(deriv_rate(t, g), fd_rate(t, g, 1e-4 * g), 1e-6);
  }
  /* Continuity of the derivative across the series switch at x = 0.25. */
  double lo = deriv_rate(t, 0.25e-3 * (1 - 1e-12)), hi = deriv_rate(t, 0.25e-3 * (1 + 1e-12));
  CHECK_CLOSE(lo, hi, 1e-11);
  check_rate_refused(t, -1.0);
  check_rate_refused(t, NAN);
  sl_tc_close(t);
  /* Large shear rate: the error is exactly -tau0 exp(-m g)/g, so it vanishes
   * exponentially as m grows. */
  const char *m_set[] = {"m=0.5", "m=1", "m=2", "m=5"};
  const double m_v[] = {0.5, 1, 2, 5};
  const double g = 3.0;
  for (int i = 0; i < 4; ++i) {
    t = sl_tc_open("viscosity", "bingham", "regularisation=papanastasiou", m_set[i], NULL);
    double err = eval_rate(t, g) - (mu_p + tau0 / g);
    CHECK_CLOSE(err, -tau0 * exp(-m_v[i] * g) / g, 1e-9);
    sl_tc_close(t);
  }
  t = sl_tc_open("viscosity", "bingham", "regularisation=papanastasiou", NULL);
  CHECK_CLOSE(eval_rate(t, 0.1), mu_p + tau0 / 0.1, RTOL); /* e^-100: the Bingham law to all digits */
  sl_tc_close(t);
}

static void test_herschel_bulkley(void) {
  const double K = 1.0, n = 0.5, tau0 = 10.0, eps = 1e-3, m = 1e3;
  sl_tc *t = sl_tc_open("viscosity", "herschel_bulkley", NULL);
  CHECK_CLOSE(eval_rate(t, 0.0), tau0 / eps + K / sqrt(eps), RTOL);
  const double gs[] = {1e-4, 0.02, 1.0, 50.0};
  for (int i = 0; i < 4; ++i) {
    double g = gs[i], r2 = g * g + eps * eps;
    CHECK_CLOSE(eval_rate(t, g), (tau0 + K * pow(r2, n / 2)) / sqrt(r2), RTOL);
    double d = -tau0 * g / pow(r2, 1.5) + K * (n - 1) * g * pow(r2, (n - 3) / 2);
    CHECK_CLOSE(deriv_rate(t, g), d, RTOL);
    CHECK_CLOSE(deriv_rate(t, g), fd_rate(t, g, 1e-6 * g), 1e-6);
  }
  /* Large shear rate: the unregularised tau0/g + K g^(n-1). */
  CHECK_CLOSE(eval_rate(t, 1e3), tau0 / 1e3 + K / sqrt(1e3), 1e-11);
  check_rate_refused(t, -1.0);
  check_rate_refused(t, NAN);
  sl_tc_close(t);

  t = sl_tc_open("viscosity", "herschel_bulkley", "regularisation=papanastasiou", NULL);
  CHECK_CLOSE(eval_rate(t, 0.0), tau0 * m + K / sqrt(eps), RTOL);
  const double gp[] = {1e-9, 1e-4, 0.02, 2.0};
  for (int i = 0; i < 4; ++i) {
    double g = gp[i];
    double v = papa_ref(0.0, tau0, m, g) + K * pow(g * g + eps * eps, (n - 1) / 2);
    CHECK_CLOSE(eval_rate(t, g), v, RTOL);
    CHECK_CLOSE(deriv_rate(t, g), fd_rate(t, g, 1e-4 * g), 1e-6);
  }
  sl_tc_close(t);

  /* Shear-thickening n = 2: K r behaves like a growing viscosity. */
  t = sl_tc_open("viscosity", "herschel_bulkley", "flow_index=2", "yield_stress=0", NULL);
  CHECK_CLOSE(eval_rate(t, 4.0), K * hypot(4.0, eps), RTOL);
  sl_tc_close(t);

  /* n = 1 reduces exactly to bingham with mu_p = K, for both regularisations. */
  const char *forms[] = {"regularisation=bercovier_engelman", "regularisation=papanastasiou"};
  for (int f = 0; f < 2; ++f) {
    sl_tc *hb = sl_tc_open("viscosity", "herschel_bulkley", "flow_index=1", "consistency=0.3", forms[f], NULL);
    sl_tc *bi = sl_tc_open("viscosity", "bingham", "plastic_viscosity=0.3", forms[f], NULL);
    const double gb[] = {0.0, 1e-6, 0.7, 40.0};
    for (int i = 0; i < 4; ++i) {
      CHECK_CLOSE(eval_rate(hb, gb[i]), eval_rate(bi, gb[i]), 1e-14);
      CHECK_CLOSE(deriv_rate(hb, gb[i]), deriv_rate(bi, gb[i]), 1e-14);
    }
    sl_tc_close(hb);
    sl_tc_close(bi);
  }
}

static double lalli_eval(sl_tc *t, double g, double rho) {
  return sl_tc_eval(t, "viscosity", "shear_rate", g, "density", rho, NULL);
}

static double lalli_d(sl_tc *t, const char *wrt, double g, double rho) {
  return sl_tc_deriv(t, "viscosity", wrt, "shear_rate", g, "density", rho, NULL);
}

static void test_lalli(void) {
  /* Defaults: rho_0 1000, delta_rho 250, mu_0 1e-3, delta_mu 1e-2, tau0 10 at
   * the dense end, onset 0, eta 1e-4. Equivalent form: mu0 + tau0/sqrt(g^2 + 4 eta). */
  sl_tc *t = sl_tc_open("viscosity", "lalli", NULL);
  const double st[][2] = {{0.0, 1000.0}, {0.0, 1250.0}, {0.3, 1100.0}, {7.0, 1180.0}, {1e-3, 1249.0}};
  for (int i = 0; i < 5; ++i) {
    double g = st[i][0], rho = st[i][1];
    double frac = (rho - 1000.0) / 250.0;
    double mu0 = 1e-3 * (1 - frac) + 1.1e-2 * frac, tau0 = 10.0 * frac;
    double root = sqrt(g * g + 4e-4);
    CHECK_CLOSE(lalli_eval(t, g, rho), mu0 + tau0 / root, RTOL);
    CHECK_CLOSE(lalli_d(t, "shear_rate", g, rho), -tau0 * g / (root * root * root), RTOL);
    CHECK_CLOSE(lalli_d(t, "density", g, rho), (1e-2 + 10.0 / root) / 250.0, RTOL);
  }
  CHECK_CLOSE(lalli_eval(t, 0.0, 1250.0), 500.011, RTOL);
  /* The unregularised Bingham limit at large shear rate. */
  CHECK_CLOSE(lalli_eval(t, 1e3, 1250.0), 1.1e-2 + 10.0 / 1e3, 1e-9);
  /* Density outside [rho_0, rho_0 + delta_rho] and bad rates: refused. */
  lalli_eval(t, 1.0, 999.0);
  CHECK(sl_tc_status(t) > 0 && t->err.msg[0]);
  lalli_eval(t, 1.0, 1250.001);
  CHECK(sl_tc_status(t) > 0);
  lalli_eval(t, 1.0, NAN);
  CHECK(sl_tc_status(t) > 0);
  lalli_eval(t, -1.0, 1100.0);
  CHECK(sl_tc_status(t) > 0);
  sl_tc_close(t);

  /* Yield onset at half the density range: Newtonian below, with a kink in
   * d/d density at the onset (the documented one-sided derivative). */
  t = sl_tc_open("viscosity", "lalli", "yield_onset=0.5", NULL);
  double g = 2.0, root = sqrt(g * g + 4e-4);
  double below = lalli_eval(t, g, 1124.0), at = lalli_eval(t, g, 1125.0);
  CHECK_CLOSE(below, 1e-3 + 1e-2 * 124.0 / 250.0, RTOL);
  CHECK_CLOSE(at, 1e-3 + 1e-2 * 0.5, RTOL); /* continuous: tau0 = 0 at the onset */
  CHECK(lalli_d(t, "shear_rate", g, 1124.0) == 0.0);
  CHECK_CLOSE(lalli_d(t, "density", g, 1124.0), 1e-2 / 250.0, RTOL);
  CHECK_CLOSE(lalli_d(t, "density", g, 1126.0), (1e-2 + 20.0 / root) / 250.0, RTOL);
  CHECK_CLOSE(lalli_d(t, "density", g, 1125.0), (1e-2 + 20.0 / root) / 250.0, RTOL); /* from above at the kink */
  CHECK_CLOSE(lalli_eval(t, g, 1200.0), 1e-3 + 1e-2 * 0.8 + 10.0 * 0.6 / root, RTOL);
  sl_tc_close(t);

  /* With constant mu0, the dense limit is the Bercovier-Engelman Bingham law
   * with eps = 2 sqrt(eta). */
  t = sl_tc_open("viscosity", "lalli", "delta_mu=0", "mu_0=0.1", "eta=0.25", NULL);
  sl_tc *b = sl_tc_open("viscosity", "bingham", "eps=1.0", NULL);
  const double gb[] = {0.0, 0.5, 3.0};
  for (int i = 0; i < 3; ++i) {
    CHECK_CLOSE(lalli_eval(t, gb[i], 1250.0), eval_rate(b, gb[i]), 1e-14);
    CHECK_CLOSE(lalli_d(t, "shear_rate", gb[i], 1250.0), deriv_rate(b, gb[i]), 1e-14);
  }
  sl_tc_close(b);
  sl_tc_close(t);

  /* Another fluid density: the accepted range follows the parameters. */
  t = sl_tc_open("viscosity", "lalli", "rho_0=998", NULL);
  CHECK_CLOSE(lalli_eval(t, 1.0, 998.0), 1e-3, RTOL);
  lalli_eval(t, 1.0, 1248.5);
  CHECK(sl_tc_status(t) > 0);
  sl_tc_close(t);
}

int main(void) {
  test_einstein();
  test_batchelor();
  test_krieger_dougherty();
  test_maron_pierce();
  test_eilers();
  test_pringle_granular();
  test_einstein_limit();
  test_bingham_bercovier();
  test_bingham_papanastasiou();
  test_herschel_bulkley();
  test_lalli();
  return sl_test_summary();
}
