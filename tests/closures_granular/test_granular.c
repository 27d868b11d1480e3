/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tests of the granular closures: kinetic theory (lun, gidaspow), the
 * equilibrium granular temperature (algebraic_theta) and the frictional
 * stress (schaeffer, johnson_jackson_frictional).
 *
 * Every law is re-written here in a different arrangement of the algebra
 * (Lun's g1 + g2 and g3 + g4 groups as printed by Krampa 2009 eqs 5.4-5.6 and
 * 5.12-5.13 with the misprints corrected, Gidaspow's viscosity and
 * conductivity expanded term by term, the radial distributions in the sum /
 * exponential / 1 + lambda forms) and compared to 1e-12. Then: dilute
 * limits, g0 -> 1, the C1 continuation near packing, the CFX-10 polynomial
 * constants of Krampa eq 6.2, production = dissipation at the algebraic
 * equilibrium temperature, the Coulomb limit in radians, and refusals. */
#include <float.h>
#include <math.h>

#include "closure_test.h"
#include "tc_extra.h"
#include "testing.h"

static const double PI = 3.14159265358979323846;

/* ---- independent radial distribution functions ------------------------ */

enum { CS, LS, MA, GID, SJ, N_RADIAL };
static const char *const radial_name[N_RADIAL] = {"carnahan_starling", "lun_savage", "ma_ahmadi", "gidaspow",
                                                  "sinclair_jackson"};

/* g0 of the uncontinued law and its derivative, arranged differently from
 * plugins/granular/kinetic.h. */
static double g0_ref(int r, double phi, double pm, double *dg) {
  switch (r) {
    case CS: {
      double n = 1.0 - phi;
      *dg = 1.0 / (n * n) + 1.5 / (n * n) + 3.0 * phi / (n * n * n) + phi / (n * n * n) +
            1.5 * phi * phi / (n * n * n * n);
      return 1.0 / n + 1.5 * phi / (n * n) + 0.5 * phi * phi / (n * n * n);
    }
    case LS: {
      double g = exp(-2.5 * pm * log1p(-phi / pm));
      *dg = 2.5 * g * pm / (pm - phi);
      return g;
    }
    case MA: {
      double N = 1.0 + 2.5 * phi + 4.5904 * phi * phi + 4.515439 * phi * phi * phi;
      double dN = 2.5 + 2.0 * 4.5904 * phi + 3.0 * 4.515439 * phi * phi;
      double pm3 = pm * pm * pm, p3 = phi * phi * phi;
      double g = N * exp(-0.67802 * log((pm3 - p3) / pm3));
      *dg = g * (dN / N + 0.67802 * 3.0 * phi * phi / (pm3 - p3));
      return g;
    }
    default: {
      double c = r == GID ? 0.6 : 1.0;
      double lam = 1.0 / (pow(pm / phi, 1.0 / 3.0) - 1.0); /* Bagnold's linear concentration */
      double x = pow(phi / pm, 1.0 / 3.0);
      *dg = c / ((1.0 - x) * (1.0 - x)) * pow(phi, -2.0 / 3.0) * pow(pm, -1.0 / 3.0) / 3.0;
      return c * (1.0 + lam);
    }
  }
}

/* ---- independent kinetic-theory coefficients --------------------------- */

typedef struct kt_ref {
  double p_s, mu_s, lambda_s, kappa, gamma;
} kt_ref;

static kt_ref gidaspow_ref(double e, double phi, double g, double th, double rho, double d) {
  double sp = sqrt(PI), s = rho * d * sqrt(th);
  kt_ref r;
  r.p_s = rho * phi * th + 2.0 * (1.0 + e) * rho * phi * phi * g * th;
  /* the square of Gidaspow's kinetic term expanded (as OpenFOAM writes it) */
  r.mu_s = s * (0.8 * phi * phi * g * (1.0 + e) / sp + sp * phi * phi * g * (1.0 + e) / 15.0 + sp * phi / 6.0 +
                10.0 * sp / (96.0 * (1.0 + e) * g));
  r.kappa = s * (2.0 * phi * phi * g * (1.0 + e) / sp + (9.0 / 16.0) * sp * g * (1.0 + e) * phi * phi +
                 (15.0 / 16.0) * sp * phi + (25.0 / 64.0) * sp / ((1.0 + e) * g));
  r.lambda_s = (4.0 / 3.0) * phi * phi * rho * d * g * (1.0 + e) * sqrt(th / PI);
  r.gamma = 12.0 * (1.0 - e * e) * g * rho * phi * phi * pow(th, 1.5) / (d * sp);
  return r;
}

static kt_ref lun_ref(double e, double phi, double g, double th, double rho, double d) {
  double eta = 0.5 * (1.0 + e), sp = sqrt(PI), st = sqrt(th);
  kt_ref r;
  r.p_s = rho * phi * th * (1.0 + 4.0 * eta * phi * g);
  /* Krampa (2009) eqs 5.4-5.6: mu = mu_dil (g1 + g2) */
  double mu_dil = 5.0 * sp / 96.0 * d * rho * st;
  double br = 1.0 + 1.6 * eta * (3.0 * eta - 2.0) * phi * g;
  double g1 = br / (eta * (2.0 - eta) * g);
  double g2 = 8.0 * phi / (5.0 * (2.0 - eta)) * br + 768.0 / (25.0 * PI) * eta * phi * phi * g;
  r.mu_s = mu_dil * (g1 + g2);
  /* eqs 5.11-5.13 with g4 corrected (phi factor, no 1/g0; a misprint in Krampa 2009) */
  double w = 41.0 - 33.0 * eta, bk = 1.0 + 2.4 * eta * eta * (4.0 * eta - 3.0) * phi * g;
  double g3 = 8.0 / (eta * w * g) * bk;
  double g4 = 96.0 * phi / (5.0 * w) * (bk + 16.0 / (15.0 * PI) * eta * w * phi * g);
  r.kappa = 25.0 * sp / 128.0 * d * rho * st * (g3 + g4);
  r.lambda_s = (8.0 / 3.0) * eta * phi * phi * rho * d * g * sqrt(th / PI);
  r.gamma = 48.0 / sp * eta * (1.0 - eta) * rho * phi * phi * g * th * st / d;
  return r;
}

static double kt_eval(sl_tc *t, const char *out, double phi, double th, double rho, double d) {
  return sl_tc_eval(t, out, "phi", phi, "theta", th, "rho_s", rho, "d_p", d, NULL);
}
static double kt_deriv(sl_tc *t, const char *out, const char *wrt, double phi, double th, double rho, double d) {
  return sl_tc_deriv(t, out, wrt, "phi", phi, "theta", th, "rho_s", rho, "d_p", d, NULL);
}

/* Central difference of a kt output in phi or theta, step h (relative for theta). */
static double kt_fd(sl_tc *t, const char *out, int wrt_theta, double phi, double th, double rho, double d, double h) {
  if (wrt_theta) return (kt_eval(t, out, phi, th + h, rho, d) - kt_eval(t, out, phi, th - h, rho, d)) / (2.0 * h);
  return (kt_eval(t, out, phi + h, th, rho, d) - kt_eval(t, out, phi - h, th, rho, d)) / (2.0 * h);
}

static const char *const kt_outputs[] = {"g0", "p_s", "mu_s", "lambda_s", "kappa", "gamma"};

static void test_kinetic_values(void) {
  const double states[][4] = {
      {0.05, 1e-3, 2650.0, 5e-4}, {0.3, 2e-2, 2500.0, 1e-3}, {0.5, 5e-4, 1400.0, 3.4e-3}, {0.61, 1e-1, 1050.0, 2e-4}};
  const double es[] = {0.9, 0.6, 1.0};
  for (int variant = 0; variant < 2; ++variant) {
    const char *name = variant ? "gidaspow" : "lun";
    for (int r = 0; r < N_RADIAL; ++r)
      for (size_t ie = 0; ie < sizeof es / sizeof es[0]; ++ie) {
        char pr[64], pe[64];
        snprintf(pr, sizeof pr, "radial=%s", radial_name[r]);
        snprintf(pe, sizeof pe, "e=%.17g", es[ie]);
        sl_tc *t = sl_tc_open("granular", name, pr, pe, NULL);
        for (size_t s = 0; s < sizeof states / sizeof states[0]; ++s) {
          double phi = states[s][0], th = states[s][1], rho = states[s][2], d = states[s][3], dg;
          double g = g0_ref(r, phi, 0.63, &dg); /* phi <= 0.62 = phi_c: no continuation */
          kt_ref ref = variant ? gidaspow_ref(es[ie], phi, g, th, rho, d) : lun_ref(es[ie], phi, g, th, rho, d);
          CHECK_CLOSE(kt_eval(t, "g0", phi, th, rho, d), g, 1e-12);
          CHECK_CLOSE(kt_eval(t, "p_s", phi, th, rho, d), ref.p_s, 1e-12);
          CHECK_CLOSE(kt_eval(t, "mu_s", phi, th, rho, d), ref.mu_s, 1e-12);
          CHECK_CLOSE(kt_eval(t, "lambda_s", phi, th, rho, d), ref.lambda_s, 1e-12);
          CHECK_CLOSE(kt_eval(t, "kappa", phi, th, rho, d), ref.kappa, 1e-12);
          if (es[ie] < 1.0) CHECK_CLOSE(kt_eval(t, "gamma", phi, th, rho, d), ref.gamma, 1e-12);
          else CHECK(kt_eval(t, "gamma", phi, th, rho, d) == 0.0); /* elastic: no dissipation */
          CHECK_CLOSE(kt_deriv(t, "g0", "phi", phi, th, rho, d), dg, 1e-11);
        }
        sl_tc_close(t);
      }
  }
}

/* Derivatives against central differences, including the continuation
 * region (phi > phi_c) and over-packed states (phi > phi_max). */
static void test_kinetic_derivatives(void) {
  const double phis[] = {0.02, 0.25, 0.45, 0.6, 0.625, 0.7};
  for (int variant = 0; variant < 2; ++variant)
    for (int r = 0; r < N_RADIAL; ++r) {
      char pr[64];
      snprintf(pr, sizeof pr, "radial=%s", radial_name[r]);
      sl_tc *t = sl_tc_open("granular", variant ? "gidaspow" : "lun", pr, NULL);
      for (size_t i = 0; i < sizeof phis / sizeof phis[0]; ++i) {
        double phi = phis[i], th = 3e-3, rho = 2650.0, d = 5e-4;
        for (size_t k = 0; k < sizeof kt_outputs / sizeof kt_outputs[0]; ++k) {
          double a = kt_deriv(t, kt_outputs[k], "phi", phi, th, rho, d);
          double fd = kt_fd(t, kt_outputs[k], 0, phi, th, rho, d, 1e-6);
          CHECK_CLOSE(a, fd, 1e-6);
          a = kt_deriv(t, kt_outputs[k], "theta", phi, th, rho, d);
          fd = kt_fd(t, kt_outputs[k], 1, phi, th, rho, d, 1e-7 * th);
          if (strcmp(kt_outputs[k], "g0") == 0) CHECK(a == 0.0);
          else CHECK_CLOSE(a, fd, 1e-6);
        }
      }
      sl_tc_close(t);
    }
}

static void test_dilute_limits(void) {
  /* g0 -> 1 (gidaspow: 3/5) as phi -> 0; the (phi/phi_max)^(1/3) forms carry
   * the 8e-5 of their dilute-end tangent line. */
  for (int r = 0; r < N_RADIAL; ++r) {
    char pr[64];
    snprintf(pr, sizeof pr, "radial=%s", radial_name[r]);
    sl_tc *t = sl_tc_open("granular", "lun", pr, NULL);
    double g_0 = kt_eval(t, "g0", 0.0, 1e-3, 2650.0, 5e-4);
    double limit = r == GID ? 0.6 : 1.0, tol = (r == GID || r == SJ) ? 1e-4 : 1e-15;
    CHECK_CLOSE(g_0, limit, tol);
    CHECK_CLOSE(kt_eval(t, "g0", 1e-9, 1e-3, 2650.0, 5e-4), limit, (r == GID || r == SJ) ? 2e-3 : 1e-8);
    /* the derivative stays finite at phi = 0 */
    CHECK(isfinite(kt_deriv(t, "g0", "phi", 0.0, 1e-3, 2650.0, 5e-4)));
    CHECK(isfinite(kt_deriv(t, "mu_s", "phi", 0.0, 1e-3, 2650.0, 5e-4)));
    CHECK(sl_tc_status(t) == 0);
    sl_tc_close(t);
  }
  /* p_s -> rho_s phi theta: the collisional share 2 (1+e) phi g0 vanishes. */
  for (int variant = 0; variant < 2; ++variant) {
    sl_tc *t = sl_tc_open("granular", variant ? "gidaspow" : "lun", NULL);
    double prev = HUGE_VAL;
    for (double phi = 1e-2; phi >= 1e-8; phi *= 0.1) {
      double ratio = kt_eval(t, "p_s", phi, 0.02, 2650.0, 5e-4) / (2650.0 * phi * 0.02) - 1.0;
      CHECK(ratio > 0.0 && ratio < prev); /* decreases monotonically to 0 */
      CHECK(ratio < 2.0 * (1.0 + 0.9) * phi * 1.05);
      prev = ratio;
    }
    CHECK(prev < 1e-7);
    /* gamma and lambda_s ~ phi^2 g0 (binary collisions) in the dilute limit */
    const char *binary[] = {"gamma", "lambda_s"};
    for (int k = 0; k < 2; ++k) {
      double q1 =
          kt_eval(t, binary[k], 1e-6, 0.02, 2650.0, 5e-4) / (1e-12 * kt_eval(t, "g0", 1e-6, 0.02, 2650.0, 5e-4));
      double q2 =
          kt_eval(t, binary[k], 2e-6, 0.02, 2650.0, 5e-4) / (4e-12 * kt_eval(t, "g0", 2e-6, 0.02, 2650.0, 5e-4));
      CHECK_CLOSE(q1, q2, 1e-12);
    }
    sl_tc_close(t);
  }
  /* Elastic dilute limit: both theories give the Chapman-Enskog values
   * mu = (5 sqrt(pi)/96) rho d sqrt(theta), kappa = (75 sqrt(pi)/384) rho d sqrt(theta). */
  for (int variant = 0; variant < 2; ++variant) {
    sl_tc *t = sl_tc_open("granular", variant ? "gidaspow" : "lun", "e=1", "radial=lun_savage", NULL);
    double s = 2650.0 * 5e-4 * sqrt(0.04);
    CHECK_CLOSE(kt_eval(t, "mu_s", 0.0, 0.04, 2650.0, 5e-4), 5.0 * sqrt(PI) / 96.0 * s, 1e-13);
    CHECK_CLOSE(kt_eval(t, "kappa", 0.0, 0.04, 2650.0, 5e-4), 75.0 * sqrt(PI) / 384.0 * s, 1e-13);
    CHECK(kt_eval(t, "p_s", 0.0, 0.04, 2650.0, 5e-4) == 0.0);
    CHECK(kt_eval(t, "gamma", 0.3, 0.04, 2650.0, 5e-4) == 0.0);
    sl_tc_close(t);
  }
  /* Lun and Gidaspow differ in dense flow (Gidaspow keeps only the leading
   * Enskog terms); they agree to within a factor 2 at phi = 0.4. */
  {
    sl_tc *a = sl_tc_open("granular", "lun", "radial=lun_savage", NULL);
    sl_tc *b = sl_tc_open("granular", "gidaspow", "radial=lun_savage", NULL);
    double ra = kt_eval(a, "mu_s", 0.4, 0.01, 2650.0, 5e-4) / kt_eval(b, "mu_s", 0.4, 0.01, 2650.0, 5e-4);
    CHECK(ra > 0.5 && ra < 2.0);
    CHECK_CLOSE(kt_eval(a, "p_s", 0.4, 0.01, 2650.0, 5e-4), kt_eval(b, "p_s", 0.4, 0.01, 2650.0, 5e-4), 1e-14);
    CHECK_CLOSE(kt_eval(a, "gamma", 0.4, 0.01, 2650.0, 5e-4), kt_eval(b, "gamma", 0.4, 0.01, 2650.0, 5e-4), 1e-14);
    sl_tc_close(a);
    sl_tc_close(b);
  }
}

/* The near-packing continuation: value and slope continuous at
 * phi_c = phi_max - delta (1e-10), and the tangent line of the raw law beyond. */
static void test_continuation(void) {
  const double pms[] = {0.63, 0.6, 0.74}, deltas[] = {0.01, 0.001, 0.05};
  for (int r = 0; r < N_RADIAL; ++r)
    for (int c = 0; c < 3; ++c) {
      char pr[64], pp[64], pd[64];
      snprintf(pr, sizeof pr, "radial=%s", radial_name[r]);
      snprintf(pp, sizeof pp, "phi_max=%.17g", pms[c]);
      snprintf(pd, sizeof pd, "delta=%.17g", deltas[c]);
      sl_tc *t = sl_tc_open("granular", "gidaspow", pr, pp, pd, NULL);
      double phi_c = pms[c] - deltas[c], right = nextafter(phi_c, 1.0);
      double gl = kt_eval(t, "g0", phi_c, 1e-3, 2650.0, 5e-4), gr = kt_eval(t, "g0", right, 1e-3, 2650.0, 5e-4);
      double sl = kt_deriv(t, "g0", "phi", phi_c, 1e-3, 2650.0, 5e-4);
      double sr = kt_deriv(t, "g0", "phi", right, 1e-3, 2650.0, 5e-4);
      CHECK_CLOSE(gl, gr, 1e-10);
      CHECK_CLOSE(sl, sr, 1e-10);
      /* the raw law's own value and slope at phi_c (independent formulas) */
      double dref, gref = g0_ref(r, phi_c, pms[c], &dref);
      CHECK_CLOSE(gl, gref, 1e-11);
      CHECK_CLOSE(sl, dref, 1e-9);
      /* beyond phi_c: exactly the tangent line, also above phi_max */
      for (double phi = phi_c + 0.01; phi <= 0.74; phi += 0.03) {
        CHECK_CLOSE(kt_eval(t, "g0", phi, 1e-3, 2650.0, 5e-4), gref + dref * (phi - phi_c), 1e-10);
        CHECK_CLOSE(kt_deriv(t, "g0", "phi", phi, 1e-3, 2650.0, 5e-4), dref, 1e-9);
        CHECK(sl_tc_status(t) == 0);
      }
      /* the other outputs stay finite and continuous through phi_c */
      for (size_t k = 1; k < sizeof kt_outputs / sizeof kt_outputs[0]; ++k) {
        double a = kt_eval(t, kt_outputs[k], phi_c, 1e-2, 2650.0, 5e-4),
               b = kt_eval(t, kt_outputs[k], right, 1e-2, 2650.0, 5e-4);
        CHECK_CLOSE(a, b, 1e-10);
        CHECK(isfinite(kt_eval(t, kt_outputs[k], 0.74, 1e-2, 2650.0, 5e-4)));
      }
      sl_tc_close(t);
    }
  /* CFX-10's near-packing polynomial (Krampa 2009 eq 6.2) is the
   * Taylor continuation of the Gidaspow g0 with C_max = 0.6 at C_max - 0.001:
   * C_0 = 1079.4, C_1 = 1.080e6. */
  sl_tc *t = sl_tc_open("granular", "gidaspow", "phi_max=0.6", "delta=0.001", NULL);
  CHECK_CLOSE(kt_eval(t, "g0", 0.599, 1e-3, 2650.0, 5e-4), 1079.4, 5e-5);
  CHECK_CLOSE(kt_deriv(t, "g0", "phi", 0.599, 1e-3, 2650.0, 5e-4), 1.080e6, 5e-4);
  CHECK_CLOSE(kt_eval(t, "g0", 0.6, 1e-3, 2650.0, 5e-4), 1079.4 + 1.080e6 * 0.001, 5e-4);
  sl_tc_close(t);
}

static void test_kinetic_refusals(void) {
  sl_tc *t = sl_tc_open("granular", "lun", NULL);
  kt_eval(t, "p_s", 0.3, 0.0, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) > 0); /* theta = 0: d mu/d theta would be infinite */
  kt_eval(t, "p_s", 0.3, -1e-3, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) > 0);
  kt_eval(t, "p_s", 0.8, 1e-3, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) > 0);
  kt_eval(t, "p_s", -0.01, 1e-3, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) > 0);
  kt_eval(t, "p_s", NAN, 1e-3, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) > 0);
  kt_eval(t, "p_s", 0.3, 1e-3, 2650.0, 0.0);
  CHECK(sl_tc_status(t) > 0);
  kt_eval(t, "p_s", 0.3, 1e-3, 2650.0, 5e-4);
  CHECK(sl_tc_status(t) == 0);
  sl_tc_close(t);
  CHECK(tcx_param_accepted("granular", "lun", "e", "1.1") != 0);
  CHECK(tcx_param_accepted("granular", "gidaspow", "radial", "percus_yevick") != 0);
  CHECK(tcx_param_accepted("granular", "gidaspow", "radial", "ma_ahmadi") == 0);
}

/* ---- algebraic equilibrium temperature ---------------------------------- */

static double at_eval(sl_tc *t, double phi, double gd, double d) {
  return sl_tc_eval(t, "theta", "phi", phi, "shear_rate", gd, "d_p", d, NULL);
}

static void test_equilibrium_balance(void) {
  const double phis[] = {0.01, 0.1, 0.3, 0.5, 0.6, 0.65}, gds[] = {0.5, 20.0, 400.0};
  const double es[] = {0.9, 0.5, 0.99};
  for (int variant = 0; variant < 2; ++variant)
    for (int r = 0; r < N_RADIAL; ++r)
      for (size_t ie = 0; ie < sizeof es / sizeof es[0]; ++ie) {
        char pv[64], pr[64], pe[64];
        snprintf(pv, sizeof pv, "viscosity=%s", variant ? "gidaspow" : "lun");
        snprintf(pr, sizeof pr, "radial=%s", radial_name[r]);
        snprintf(pe, sizeof pe, "e=%.17g", es[ie]);
        sl_tc *at = sl_tc_open("granular", "algebraic_theta", pv, pr, pe, NULL);
        sl_tc *kt = sl_tc_open("granular", variant ? "gidaspow" : "lun", pr, pe, NULL);
        for (size_t i = 0; i < sizeof phis / sizeof phis[0]; ++i)
          for (size_t j = 0; j < sizeof gds / sizeof gds[0]; ++j) {
            double phi = phis[i], gd = gds[j], d = 7e-4, rho = 2650.0;
            double th = at_eval(at, phi, gd, d);
            CHECK(sl_tc_status(at) == 0 && th > 0.0);
            double mu = kt_eval(kt, "mu_s", phi, th, rho, d), ga = kt_eval(kt, "gamma", phi, th, rho, d);
            CHECK_CLOSE(mu * gd * gd, ga, 1e-12); /* production = dissipation */
            /* and it is the only root: theta/2 produces more than it dissipates */
            double mu2 = kt_eval(kt, "mu_s", phi, 0.5 * th, rho, d), ga2 = kt_eval(kt, "gamma", phi, 0.5 * th, rho, d);
            CHECK(mu2 * gd * gd > ga2);
          }
        sl_tc_close(at);
        sl_tc_close(kt);
      }
  /* scaling: theta ~ shear_rate^2 d_p^2; derivatives against differences */
  sl_tc *t = sl_tc_open("granular", "algebraic_theta", NULL);
  double a = at_eval(t, 0.3, 10.0, 1e-3);
  CHECK_CLOSE(log(at_eval(t, 0.3, 20.0, 1e-3) / a) / log(2.0), 2.0, 1e-12);
  CHECK_CLOSE(log(at_eval(t, 0.3, 10.0, 2e-3) / a) / log(2.0), 2.0, 1e-12);
  CHECK(at_eval(t, 0.3, 0.0, 1e-3) == 0.0);
  const double ps[] = {0.05, 0.3, 0.55, 0.63, 0.7};
  for (size_t i = 0; i < sizeof ps / sizeof ps[0]; ++i) {
    double phi = ps[i], h = 1e-6;
    double fd = (at_eval(t, phi + h, 10.0, 1e-3) - at_eval(t, phi - h, 10.0, 1e-3)) / (2 * h);
    CHECK_CLOSE(sl_tc_deriv(t, "theta", "phi", "phi", phi, "shear_rate", 10.0, "d_p", 1e-3, NULL), fd, 1e-6);
    fd = (at_eval(t, phi, 10.0 + 1e-5, 1e-3) - at_eval(t, phi, 10.0 - 1e-5, 1e-3)) / 2e-5;
    CHECK_CLOSE(sl_tc_deriv(t, "theta", "shear_rate", "phi", phi, "shear_rate", 10.0, "d_p", 1e-3, NULL), fd, 1e-8);
  }
  /* an independent evaluation of the pure-shear root of Krampa (6.19):
   * theta^0.5 = sqrt(4 A_D A_P)/(2 A_D), A_P = mu0 S^2, A_D = 4 E_D/(d sqrt(pi)). */
  {
    double phi = 0.4, gd = 30.0, d = 1e-3, e = 0.9, rho = 2650.0, dg;
    double g = g0_ref(GID, phi, 0.63, &dg);
    kt_ref k = gidaspow_ref(e, phi, g, 1.0, rho, d); /* theta = 1: the T^0.5 prefactors */
    double E_D = 3.0 * (1.0 - e * e) * phi * phi * rho * g, A_D = 4.0 * E_D / (d * sqrt(PI)), A_P = k.mu_s * gd * gd;
    double root = sqrt(4.0 * A_D * A_P) / (2.0 * A_D);
    CHECK_CLOSE(at_eval(t, phi, gd, d), root * root, 1e-12);
  }
  /* refusals: phi below 1e-6 (theta ~ phi^-2 without interphase exchange), e = 1 */
  at_eval(t, 0.0, 10.0, 1e-3);
  CHECK(sl_tc_status(t) > 0);
  at_eval(t, 0.3, -1.0, 1e-3);
  CHECK(sl_tc_status(t) > 0);
  CHECK(tcx_param_accepted("granular", "algebraic_theta", "e", "1") != 0);
  sl_tc_close(t);
}

/* ---- frictional stress ---------------------------------------------------- */

static double fr_eval(sl_tc *t, const char *out, double phi, double gd) {
  return sl_tc_eval(t, out, "phi", phi, "shear_rate", gd, NULL);
}
static double fr_deriv(sl_tc *t, const char *out, const char *wrt, double phi, double gd) {
  return sl_tc_deriv(t, out, wrt, "phi", phi, "shear_rate", gd, NULL);
}

static double jj_ref(double phi, double fr, double r, double s, double pmin, double pmax) {
  return phi <= pmin ? 0.0 : fr * exp(r * log(phi - pmin) - s * log(pmax - phi));
}

static void test_frictional(void) {
  /* Johnson & Jackson pressure and Coulomb viscosity */
  sl_tc *t = sl_tc_open("granular", "johnson_jackson_frictional", NULL);
  const double sin285 = sin(28.5 * PI / 180.0);
  const double phis[] = {0.3, 0.5, 0.51, 0.55, 0.6, 0.615};
  for (size_t i = 0; i < sizeof phis / sizeof phis[0]; ++i) {
    double phi = phis[i], p = jj_ref(phi, 0.05, 2.0, 5.0, 0.5, 0.63);
    CHECK_CLOSE(fr_eval(t, "p_fr", phi, 3.0), p, 1e-12);
    CHECK_CLOSE(fr_eval(t, "mu_fr", phi, 3.0), p * sin285 / sqrt(9.0 + 1e-8), 1e-12);
    if (phi > 0.5) {
      double fd = (fr_eval(t, "p_fr", phi + 1e-7, 3.0) - fr_eval(t, "p_fr", phi - 1e-7, 3.0)) / 2e-7;
      CHECK_CLOSE(fr_deriv(t, "p_fr", "phi", phi, 3.0), fd, 1e-6);
      fd = (fr_eval(t, "mu_fr", phi, 3.0 + 1e-5) - fr_eval(t, "mu_fr", phi, 3.0 - 1e-5)) / 2e-5;
      CHECK_CLOSE(fr_deriv(t, "mu_fr", "shear_rate", phi, 3.0), fd, 1e-7);
    } else {
      CHECK(fr_eval(t, "p_fr", phi, 3.0) == 0.0 && fr_eval(t, "mu_fr", phi, 3.0) == 0.0);
      CHECK(fr_deriv(t, "p_fr", "phi", phi, 3.0) == 0.0);
    }
  }
  /* C1 at phi_min (r = 2) and at phi_c = 0.62; finite and increasing beyond phi_max */
  CHECK(fabs(fr_deriv(t, "p_fr", "phi", 0.5 + 1e-12, 1.0)) < 1e-6);
  {
    double phi_c = 0.63 - 0.01, right = nextafter(phi_c, 1.0);
    CHECK_CLOSE(fr_eval(t, "p_fr", phi_c, 1.0), fr_eval(t, "p_fr", right, 1.0), 1e-10);
    CHECK_CLOSE(fr_deriv(t, "p_fr", "phi", phi_c, 1.0), fr_deriv(t, "p_fr", "phi", right, 1.0), 1e-10);
    double pc = jj_ref(phi_c, 0.05, 2.0, 5.0, 0.5, 0.63);
    double sc = pc * (2.0 / (phi_c - 0.5) + 5.0 / (0.63 - phi_c));
    CHECK_CLOSE(fr_eval(t, "p_fr", 0.7, 1.0), pc + sc * (0.7 - phi_c), 1e-10);
    CHECK(sl_tc_status(t) == 0);
  }
  /* Coulomb limit: shear stress mu_fr shear_rate -> p_fr sin(phi_f) */
  CHECK_CLOSE(fr_eval(t, "mu_fr", 0.58, 100.0) * 100.0, fr_eval(t, "p_fr", 0.58, 100.0) * sin285, 1e-11);
  /* unsheared: finite, p sin(phi_f)/shear_rate_reg */
  CHECK_CLOSE(fr_eval(t, "mu_fr", 0.58, 0.0), fr_eval(t, "p_fr", 0.58, 0.0) * sin285 / 1e-4, 1e-12);
  fr_eval(t, "p_fr", 0.58, -1.0);
  CHECK(sl_tc_status(t) > 0);
  fr_eval(t, "p_fr", 0.75, 1.0);
  CHECK(sl_tc_status(t) > 0);
  sl_tc_close(t);

  /* Radians: 30 degrees given as 0.5236; 30 itself is refused by the bounds. */
  t = sl_tc_open("granular", "schaeffer", "friction_angle=0.5236", NULL);
  double p = fr_eval(t, "p_fr", 0.6, 2.0);
  CHECK_CLOSE(p, 1e25 * pow(0.1, 10.0), 1e-12);
  CHECK_CLOSE(fr_eval(t, "mu_fr", 0.6, 2.0) * 2.0 / p, 0.5, 1e-5);
  CHECK_CLOSE(fr_eval(t, "mu_fr", 0.6, 2.0) * 2.0 / p, sin(0.5236), 1e-8);
  sl_tc_close(t);
  CHECK(tcx_param_accepted("granular", "schaeffer", "friction_angle", "30") != 0);
  CHECK(tcx_param_accepted("granular", "schaeffer", "friction_angle", "0.5236") == 0);
  CHECK(tcx_param_accepted("granular", "johnson_jackson_frictional", "friction_angle", "28.5") != 0);

  /* Schaeffer: power law by default; 2 sqrt(I_2D) = shear_rate in simple shear */
  t = sl_tc_open("granular", "schaeffer", NULL);
  const double ps[] = {0.45, 0.52, 0.58, 0.65, 0.74};
  for (size_t i = 0; i < sizeof ps / sizeof ps[0]; ++i) {
    double phi = ps[i], pl = phi > 0.5 ? 1e25 * exp(10.0 * log(phi - 0.5)) : 0.0;
    /* simple shear u_x = G y: D_xy = G/2, I_2D = D_xy^2, shear_rate = sqrt(2 D:D) = G */
    double G = 5.0, I2D = 0.25 * G * G;
    CHECK_CLOSE(fr_eval(t, "p_fr", phi, G), pl, 1e-12);
    CHECK_CLOSE(fr_eval(t, "mu_fr", phi, G), pl * 0.5 / (2.0 * sqrt(I2D)), 1e-9);
  }
  sl_tc_close(t);
  t = sl_tc_open("granular", "schaeffer", "pressure=johnson_jackson", NULL);
  CHECK_CLOSE(fr_eval(t, "p_fr", 0.55, 1.0), 38.14697265625, 1e-12);
  sl_tc_close(t);

  /* A parameter set with no frictional range is refused at create. */
  CHECK(tcx_create_rc("granular", "johnson_jackson_frictional", "phi_min=0.625", NULL) != 0);
  CHECK(tcx_create_rc("granular", "johnson_jackson_frictional", "phi_min=0.6", NULL) == 0);
  CHECK(tcx_create_rc("granular", "schaeffer", "phi_min=0.7", NULL) == 0); /* power law: no phi_max */
}

/* Optional outputs: any subset may be requested; the others are NULL. */
static void test_optional_outputs(void) {
  const char *names[] = {"lun", "gidaspow"};
  for (int v = 0; v < 2; ++v) {
    sl_tc *t = sl_tc_open("granular", names[v], NULL);
    for (size_t k = 0; k < sizeof kt_outputs / sizeof kt_outputs[0]; ++k) {
      int rc;
      double dv, val = tcx_eval_only(t, kt_outputs[k], "phi", &dv, &rc, "phi", 0.45, "theta", 0.02, NULL);
      CHECK(rc == 0);
      CHECK(val == kt_eval(t, kt_outputs[k], 0.45, 0.02, 2650.0, 5e-4));
      CHECK(dv == kt_deriv(t, kt_outputs[k], "phi", 0.45, 0.02, 2650.0, 5e-4));
    }
    sl_tc_close(t);
  }
  const char *fr[] = {"schaeffer", "johnson_jackson_frictional"}, *fo[] = {"p_fr", "mu_fr"};
  for (int v = 0; v < 2; ++v) {
    sl_tc *t = sl_tc_open("granular", fr[v], NULL);
    for (int k = 0; k < 2; ++k) {
      int rc;
      double dv, val = tcx_eval_only(t, fo[k], "shear_rate", &dv, &rc, "phi", 0.56, "shear_rate", 2.0, NULL);
      CHECK(rc == 0);
      CHECK(val == fr_eval(t, fo[k], 0.56, 2.0));
      CHECK(dv == fr_deriv(t, fo[k], "shear_rate", 0.56, 2.0));
    }
    sl_tc_close(t);
  }
}

int main(void) {
  test_kinetic_values();
  test_kinetic_derivatives();
  test_dilute_limits();
  test_continuation();
  test_kinetic_refusals();
  test_equilibrium_balance();
  test_frictional();
  test_optional_outputs();
  return sl_test_summary();
}
