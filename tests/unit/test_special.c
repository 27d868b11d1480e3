/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The Bessel functions of the expression language (core/config/special.c)
 * against published values:
 *  - J0, J1, Y0, Y1 at x = 1, 2, 5, 10 against the 10-digit values of
 *    Abramowitz & Stegun (1964) Table 9.1, and their first zeros against
 *    Table 9.5 (j_{0,1}, j_{1,1}, y_{0,1});
 *  - J_{1/2} against A&S 10.1.11 (sqrt(2/(pi x)) sin x, its zeros at k pi)
 *    and against J_{1/2} = sqrt(x/2) (J0 + ...) being a solution of Bessel's
 *    equation of order 1/2 (a second-difference residual);
 *  - int_0^x J0 against the Neumann series of A&S 11.1.2, 2 sum_k J_{2k+1}(x)
 *    (the library's jn: an independent route), at x = 0.5 ... 40;
 *  - int_0^x J0 and int_0^x Y0 differentiated numerically give J0 and Y0
 *    (across the series/quadrature switch at x = 8), int_0^x Y0 near 0 is
 *    its two leading terms, and int_0^x J0 at
 *    x = 1 is A&S Table 11.1's 0.9197304101;
 *  - through the expression language: the names, their arity, NaN outside
 *    the domain, constant folding. */
#include <math.h>
#include <stdio.h>

#include "core/config/expr.h"
#include "core/config/special.h"
#include "testing.h"

static const double PI = 3.14159265358979323846;

static void table_9_1(void) {
  /* A&S Table 9.1: x, J0, J1, Y0, Y1 (10 decimals) */
  static const double t[4][5] = {
      {1.0, 0.7651976866, 0.4400505857, 0.0882569642, -0.7812128213},
      {2.0, 0.2238907791, 0.5767248078, 0.5103756726, -0.1070324315},
      {5.0, -0.1775967713, -0.3275791376, -0.3085176252, 0.1478631434},
      {10.0, -0.2459357645, 0.0434727462, 0.0556711673, 0.2490154242},
  };
  double worst = 0.0;
  for (int i = 0; i < 4; ++i) {
    double x = t[i][0];
    double v[4] = {sl_bessel_j0(x), sl_bessel_j1(x), sl_bessel_y0(x), sl_bessel_y1(x)};
    for (int k = 0; k < 4; ++k) {
      double e = fabs(v[k] - t[i][k + 1]);
      worst = fmax(worst, e);
      CHECK_MSG(e < 6e-11, "x = %g, function %d: %.12f against A&S %.10f", x, k, v[k], t[i][k + 1]);
    }
  }
  /* A&S Table 9.5: the first zeros */
  CHECK(fabs(sl_bessel_j0(2.4048255577)) < 1e-10);
  CHECK(fabs(sl_bessel_j1(3.8317059702)) < 1e-10);
  CHECK(fabs(sl_bessel_y0(0.8935769663)) < 1e-10);
  CHECK(sl_bessel_jn(0, 2.0) == sl_bessel_j0(2.0) && sl_bessel_jn(1, 2.0) == sl_bessel_j1(2.0));
  CHECK(fabs(sl_bessel_yn(1, 5.0) - 0.1478631434) < 6e-11);
  printf("A&S Table 9.1: largest difference %.2e (10 decimals given)\n", worst);
}

static void half_order(void) {
  /* zeros at k pi (A&S 10.1.11) and J_{1/2}(pi/2) = sqrt(4 / pi^2) = 2/pi */
  for (int k = 1; k <= 5; ++k) CHECK(fabs(sl_bessel_jhalf(k * PI)) < 1e-15);
  CHECK(fabs(sl_bessel_jhalf(PI / 2) - 2.0 / PI) < 1e-15);
  /* Bessel's equation of order 1/2: x^2 y'' + x y' + (x^2 - 1/4) y = 0, central differences */
  double worst = 0.0, h = 1e-4;
  for (double x = 0.3; x < 12.0; x += 0.37) {
    double ym = sl_bessel_jhalf(x - h), y = sl_bessel_jhalf(x), yp = sl_bessel_jhalf(x + h);
    double res = x * x * (yp - 2 * y + ym) / (h * h) + x * (yp - ym) / (2 * h) + (x * x - 0.25) * y;
    worst = fmax(worst, fabs(res) / (x * x));
  }
  CHECK_MSG(worst < 1e-6, "Bessel's equation of order 1/2: residual %.2e", worst);
  CHECK(sl_bessel_jhalf(0.0) == 0.0 && isnan(sl_bessel_jhalf(-1.0)));
}

static void integrals(void) {
  /* A&S 11.1.2: int_0^x J0 = 2 sum_{k >= 0} J_{2k+1}(x) */
  double worst = 0.0;
  static const double xs[] = {0.5, 1.0, 2.0, 3.14159, 5.0, 7.9, 8.0, 8.1, 10.0, 17.3, 25.0, 40.0};
  for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i) {
    double x = xs[i], s = 0.0;
    for (int k = 0; k < 200; ++k) s += 2.0 * sl_bessel_jn(2 * k + 1, x);
    double v = sl_bessel_int_j0(x), e = fabs(v - s);
    worst = fmax(worst, e);
    CHECK_MSG(e < 1e-13, "int_0^%g J0 = %.16f, Neumann series %.16f", x, v, s);
  }
  printf("int J0 against A&S 11.1.2: largest difference %.2e\n", worst);
  CHECK(fabs(sl_bessel_int_j0(1.0) - 0.9197304101) < 6e-11); /* A&S Table 11.1 */
  CHECK(sl_bessel_int_j0(-2.0) == -sl_bessel_int_j0(2.0));
  /* derivatives (fourth-order differences) against the library's J0 and Y0 */
  double dj = 0.0, dy = 0.0, h = 1e-3;
  for (double x = 0.2; x < 30.0; x += 0.29) {
    double gj = (-sl_bessel_int_j0(x + 2 * h) + 8 * sl_bessel_int_j0(x + h) - 8 * sl_bessel_int_j0(x - h) +
                 sl_bessel_int_j0(x - 2 * h)) /
                (12 * h);
    double gy = (-sl_bessel_int_y0(x + 2 * h) + 8 * sl_bessel_int_y0(x + h) - 8 * sl_bessel_int_y0(x - h) +
                 sl_bessel_int_y0(x - 2 * h)) /
                (12 * h);
    dj = fmax(dj, fabs(gj - sl_bessel_j0(x)));
    dy = fmax(dy, fabs(gy - sl_bessel_y0(x)));
  }
  /* the difference formula's own error is h^4 f^(5) / 30 ~ 3e-14 here (more near 0 for Y0's log) */
  CHECK_MSG(dj < 1e-9 && dy < 1e-8, "d/dx int J0 - J0: %.2e, d/dx int Y0 - Y0: %.2e", dj, dy);
  printf("derivatives of the integrals: J0 %.2e, Y0 %.2e\n", dj, dy);
  /* continuity across the switch at 8 */
  CHECK(fabs(sl_bessel_int_y0(8.0 + 1e-12) - sl_bessel_int_y0(8.0)) < 1e-11);
  /* int_0^x Y0 = (2/pi) x [(L - 1) - x^2/12 (L - 1 - 1/3 - 1)] + O(x^5 ln x) near 0, L = ln(x/2) + gamma (A&S
     9.1.13 integrated by hand) */
  double x = 1e-3, L = log(x / 2) + 0.5772156649015329;
  double lead = 2.0 / PI * x * ((L - 1.0) - x * x / 12.0 * (L - 1.0 - 1.0 / 3.0));
  CHECK_MSG(fabs(sl_bessel_int_y0(x) - lead) < 1e-14 * fabs(lead), "int_0^%g Y0 = %.17g, leading terms %.17g", x,
            sl_bessel_int_y0(x), lead);
  CHECK(sl_bessel_int_y0(0.0) == 0.0 && isnan(sl_bessel_int_y0(-1.0)) && isnan(sl_bessel_int_j0(1e6)));
}

static double eval(const char *text, double x) {
  static const char *const vars[] = {"x"};
  sl_expr *e = NULL;
  sl_diag d = {{0}};
  if (sl_expr_compile(text, vars, 1, &e, &d)) {
    CHECK_MSG(0, "'%s': %s", text, d.msg);
    return NAN;
  }
  double v = sl_expr_eval(e, &x);
  sl_expr_free(e);
  return v;
}

static void language(void) {
  CHECK(eval("j0(x)", 2.0) == sl_bessel_j0(2.0));
  CHECK(eval("j1(x) + y1(x)", 2.0) == sl_bessel_j1(2.0) + sl_bessel_y1(2.0));
  CHECK(eval("y0(x)", 2.0) == sl_bessel_y0(2.0));
  CHECK(eval("jn(3, x)", 2.0) == sl_bessel_jn(3, 2.0) && eval("yn(2, x)", 2.0) == sl_bessel_yn(2, 2.0));
  CHECK(eval("jhalf(x)", 2.0) == sl_bessel_jhalf(2.0));
  CHECK(eval("int_j0(x) - int_y0(x)", 3.0) == sl_bessel_int_j0(3.0) - sl_bessel_int_y0(3.0));
  CHECK(isnan(eval("jn(0.5, x)", 2.0)) && isnan(eval("y0(x)", -1.0)));
  /* folded at compile time to the same value */
  sl_expr *e = NULL;
  sl_diag d = {{0}};
  double v = 0.0;
  CHECK(sl_expr_compile("int_y0(pi)", NULL, 0, &e, &d) == 0 && sl_expr_is_constant(e, &v) && v == sl_bessel_int_y0(PI));
  sl_expr_free(e);
  /* arity errors */
  static const char *const vars[] = {"x"};
  e = NULL;
  CHECK(sl_expr_compile("jn(x)", vars, 1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile("j0(x, 1)", vars, 1, &e, &d) == SL_EBADINPUT && e == NULL);
}

int main(void) {
  table_9_1();
  half_order();
  integrals();
  language();
  return sl_test_summary();
}
