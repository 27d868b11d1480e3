/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tests of the solids_pressure closures pringle_exponential and
 * gidaspow_elastic: values against the formulas written independently,
 * Pringle's (2001) eq 4.30 tabulated, dp_s/dphi, limits and
 * refused states. */
#include <float.h>
#include <math.h>

#include "closure_test.h"
#include "testing.h"

#define RTOL 1e-12

static double ps(sl_tc *t, double phi) { return sl_tc_eval(t, "p_s", "phi", phi, NULL); }
static double dps(sl_tc *t, double phi) { return sl_tc_deriv(t, "p_s", "phi", "phi", phi, NULL); }

static void check_refused(sl_tc *t, double phi) {
  double v = ps(t, phi);
  CHECK_MSG(sl_tc_status(t) > 0 && isnan(v) && t->err.point == 0 && t->err.msg[0], "phi = %g: status %d", phi,
            sl_tc_status(t));
}

/* Pringle (2001) eq 4.30 in porosity form, P = p_ref exp[(1/A)(1 - (1-nbar)/(1-n))],
 * rearranged as p_ref exp[(phi - phibar) / (A phi)], phibar = 1 - nbar. */
static double pringle_ref(double phi, double A, double nbar, double p_ref) {
  double phibar = 1.0 - nbar;
  return p_ref * exp((phi - phibar) / (A * phi));
}

static void test_pringle_values(void) {
  sl_tc *t = sl_tc_open("solids_pressure", "pringle_exponential", NULL);
  const double phis[] = {0.05, 0.3, 0.5, 0.57, 0.7};
  for (int i = 0; i < 5; ++i) {
    double phi = phis[i];
    double v = pringle_ref(phi, 0.015, 0.5, 1.0);
    CHECK_CLOSE(ps(t, phi), v, RTOL);
    /* eq 3.48: dP/dn = -(P/A)(1 - nbar)/(1 - n)^2, and dphi = -dn. */
    double n = 1.0 - phi;
    CHECK_CLOSE(dps(t, phi), (v / 0.015) * 0.5 / ((1 - n) * (1 - n)), RTOL);
  }
  /* Normalisation P_s(nbar) = p_ref and the inverse 1 - n = (1 - nbar)/(1 - A ln P_s). */
  CHECK_CLOSE(ps(t, 0.5), 1.0, RTOL);
  const double phis_inv[] = {0.45, 0.55, 0.62};
  for (int i = 0; i < 3; ++i) {
    double P = ps(t, phis_inv[i]);
    CHECK_CLOSE(0.5 / (1.0 - 0.015 * log(P)), phis_inv[i], 1e-12);
  }
  /* Compaction raises the pressure (the eq 4.30 form; the inverted ratio
   * printed in eqs 3.51/3.54 would make it fall). */
  double prev = -1.0;
  for (int i = 0; i <= 14; ++i) {
    double phi = 0.45 + 0.01 * i, v = ps(t, phi);
    CHECK(v > prev);
    prev = v;
  }
  double inverted = exp((1.0 / 0.015) * (1.0 - 0.6 / 0.5)); /* misprinted form at n = 0.40 */
  CHECK(ps(t, 0.6) > 1e4 && inverted < 1e-5);
  /* Limits and edges: p_s -> 0 with a zero slope as phi -> 0. */
  CHECK(ps(t, 0.0) == 0.0 && sl_tc_status(t) == 0);
  CHECK(dps(t, 0.0) == 0.0);
  CHECK(ps(t, 1e-300) == 0.0 && dps(t, 1e-300) == 0.0);
  CHECK(ps(t, 0.1) < 1e-100);
  CHECK(isfinite(ps(t, 0.74)) && sl_tc_status(t) == 0);
  check_refused(t, 0.7400001);
  check_refused(t, -1e-12);
  check_refused(t, NAN);
  sl_tc_close(t);

  /* p_ref scales the pressure and its derivative. */
  t = sl_tc_open("solids_pressure", "pringle_exponential", "p_ref=1000", NULL);
  CHECK_CLOSE(ps(t, 0.55), 1000.0 * pringle_ref(0.55, 0.015, 0.5, 1.0), RTOL);
  CHECK_CLOSE(dps(t, 0.55), 1000.0 * pringle_ref(0.55, 0.015, 0.5, 1.0) * 0.5 / (0.015 * 0.55 * 0.55), RTOL);
  sl_tc_close(t);

  /* A stiff set overflows at dense packing: refused, never inf. */
  t = sl_tc_open("solids_pressure", "pringle_exponential", "flexibility=1e-4", "nbar=0.99", NULL);
  check_refused(t, 0.7);
  CHECK_CLOSE(ps(t, 1.0 - 0.99), 1.0, RTOL); /* phi = 1 - nbar */
  sl_tc_close(t);
}

/* Pringle (2001) eq 4.30, tabulated for the sand (A = 0.015, nbar = 0.5) and
 * illite (Table 5.4: A = 0.1075, nbar = 0.95) parameters. Tolerance: one unit in the last printed
 * digit (two illite entries, 62.4 for 62.450 and 396 for 395.47, are off by
 * more than half a unit: rounding slips in the table). */
static void test_pringle_tables(void) {
  sl_tc *t = sl_tc_open("solids_pressure", "pringle_exponential", NULL);
  const double sand[][3] = {{0.55, 6.1e-4, 0.1e-4}, {0.52, 0.062, 0.001}, {0.50, 1.0, 1e-12},   {0.49, 3.70, 0.01},
                            {0.48, 13.0, 0.1},      {0.47, 43.5, 0.1},    {0.46, 140.0, 1.0},   {0.45, 429.0, 1.0},
                            {0.44, 1265.0, 1.0},    {0.42, 9852.0, 1.0},  {0.40, 6.69e4, 100.0}};
  for (size_t i = 0; i < sizeof sand / sizeof sand[0]; ++i) {
    double v = ps(t, 1.0 - sand[i][0]);
    CHECK_MSG(fabs(v - sand[i][1]) <= sand[i][2], "sand n = %g: p_s = %.6g, table %g", sand[i][0], v, sand[i][1]);
  }
  /* the check points of the tables above, to their printed precision */
  CHECK_CLOSE(ps(t, 0.55), 429.0, 2e-3);
  CHECK_CLOSE(ps(t, 0.60), 6.69e4, 2e-3);
  sl_tc_close(t);

  t = sl_tc_open("solids_pressure", "pringle_exponential", "flexibility=0.1075", "nbar=0.95", NULL);
  const double illite[][3] = {{0.97, 0.0020, 0.0001}, {0.95, 1.0, 1e-12}, {0.94, 4.71, 0.01}, {0.93, 14.3, 0.1},
                              {0.92, 32.7, 0.1},      {0.91, 62.4, 0.1},  {0.90, 105.0, 1.0}, {0.89, 160.0, 1.0},
                              {0.88, 227.0, 1.0},     {0.87, 306.0, 1.0}, {0.86, 396.0, 1.0}, {0.85, 494.0, 1.0}};
  for (size_t i = 0; i < sizeof illite / sizeof illite[0]; ++i) {
    double v = ps(t, 1.0 - illite[i][0]);
    CHECK_MSG(fabs(v - illite[i][1]) <= illite[i][2], "illite n = %g: p_s = %.6g, table %g", illite[i][0], v,
              illite[i][1]);
  }
  CHECK_CLOSE(ps(t, 0.10), 105.0, 5e-3);
  for (int i = 0; i < 3; ++i) {
    double phi = 0.04 + 0.05 * i;
    CHECK_CLOSE(ps(t, phi), pringle_ref(phi, 0.1075, 0.95, 1.0), RTOL);
  }
  sl_tc_close(t);
}

/* Gidaspow elastic: p_s = (G0/C) e^{-C pm} (e^{C phi} - 1), in long double. */
static double gidaspow_ref(double phi, double G0, double C, double pm) {
  long double c = C;
  return (double)((long double)G0 / c * expl(-c * pm) * expm1l(c * phi));
}

static void test_gidaspow_elastic(void) {
  sl_tc *t = sl_tc_open("solids_pressure", "gidaspow_elastic", NULL);
  const double G0 = 1.0, C = 600.0, pm = 0.624;
  const double phis[] = {1e-6, 0.2, 0.55, 0.624, 0.66, 0.74};
  for (int i = 0; i < 6; ++i) {
    double phi = phis[i];
    CHECK_CLOSE(ps(t, phi), gidaspow_ref(phi, G0, C, pm), RTOL);
    /* dp_s/dphi is the modulus G = G0 exp(C (phi - phi_max)) */
    CHECK_CLOSE(dps(t, phi), G0 * exp(C * phi) / exp(C * pm), 1e-12);
  }
  CHECK(ps(t, 0.0) == 0.0 && sl_tc_status(t) == 0);
  CHECK_CLOSE(dps(t, 0.0), exp(-C * pm), RTOL);
  CHECK_CLOSE(ps(t, pm), G0 / C, RTOL);
  CHECK_CLOSE(dps(t, pm), G0, RTOL);
  /* Consistency: p_s(b) - p_s(a) = integral of G (composite Simpson, 20000
   * panels: quadrature error about 4e-11 relative for C = 600). */
  double a = 0.55, b = 0.66, sum = 0.0;
  int nseg = 20000;
  for (int k = 0; k <= nseg; ++k) {
    double w = (k == 0 || k == nseg) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += w * dps(t, a + (b - a) * k / nseg);
  }
  double integral = sum * (b - a) / (3.0 * nseg);
  CHECK_CLOSE(ps(t, b) - ps(t, a), integral, 1e-9);
  /* and against central differences */
  for (int i = 1; i < 5; ++i) {
    double phi = phis[i], h = 1e-7;
    CHECK_CLOSE(dps(t, phi), (ps(t, phi + h) - ps(t, phi - h)) / (2 * h), 1e-6);
  }
  check_refused(t, 0.75);
  check_refused(t, -0.01);
  check_refused(t, NAN);
  sl_tc_close(t);

  /* Parameters: G0 scales, phi_max shifts; an overflowing set is refused. */
  t = sl_tc_open("solids_pressure", "gidaspow_elastic", "modulus_ref=5", "phi_max=0.6", "compaction=500", NULL);
  CHECK_CLOSE(ps(t, 0.63), gidaspow_ref(0.63, 5.0, 500.0, 0.6), RTOL);
  CHECK_CLOSE(dps(t, 0.63), 5.0 * exp(500.0 * 0.03), RTOL);
  sl_tc_close(t);
  t = sl_tc_open("solids_pressure", "gidaspow_elastic", "compaction=10000", "phi_max=0.3", NULL);
  check_refused(t, 0.74);
  /* e^{-C phi_max} = e^-3000 underflows: the plain difference form, still exact. */
  CHECK_CLOSE(ps(t, 0.32), (double)(expl(10000.0L * (0.32L - 0.3L)) / 10000.0L), 1e-12);
  sl_tc_close(t);
}

int main(void) {
  test_pringle_values();
  test_pringle_tables();
  test_gidaspow_elastic();
  return sl_test_summary();
}
