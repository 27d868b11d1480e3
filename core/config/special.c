/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Bessel functions and the integrals of J0 and Y0 (special.h). */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* j0, j1, jn, y0, y1, yn of <math.h> */
#endif
#include "core/config/special.h"

#include <math.h>

static const double PI = 3.14159265358979323846, EULER_GAMMA = 0.57721566490153286061;

double sl_bessel_j0(double x) { return j0(x); }
double sl_bessel_j1(double x) { return j1(x); }
double sl_bessel_y0(double x) { return x < 0.0 ? NAN : y0(x); }
double sl_bessel_y1(double x) { return x < 0.0 ? NAN : y1(x); }

static int integer_order(double n) { return n == floor(n) && fabs(n) <= 10000.0; }

double sl_bessel_jn(double n, double x) { return integer_order(n) ? jn((int)n, x) : NAN; }
double sl_bessel_yn(double n, double x) { return integer_order(n) && !(x < 0.0) ? yn((int)n, x) : NAN; }

/* Abramowitz & Stegun (1964) 10.1.1 and 10.1.11: J_{1/2}(x) = sqrt(2 x / pi) j_0(x), j_0(x) = sin(x) / x. */
double sl_bessel_jhalf(double x) {
  if (!(x >= 0.0)) return NAN;
  if (x == 0.0) return 0.0;
  return sqrt(2.0 / (PI * x)) * sin(x);
}

/* The series part, 0 <= x <= SERIES_MAX: with c_k = (-1)^k (x^2/4)^k / (k!)^2 (A&S 9.1.12, J0 = sum c_k),
 *   int_0^x J0 = sum_k x c_k / (2k + 1),
 * and with A&S 9.1.13, Y0 = (2/pi) sum_k c_k [ln(x/2) + gamma - H_k] (H_k the harmonic numbers, H_0 = 0), term by
 * term with int_0^x t^2k ln(t/2) dt = x^(2k+1) / (2k + 1) [ln(x/2) - 1/(2k + 1)],
 *   int_0^x Y0 = (2/pi) sum_k x c_k / (2k + 1) [ln(x/2) + gamma - H_k - 1/(2k + 1)].
 * The largest term at x = 8 is about 1e2 times the sum: 1e-14 relative. */
enum { SERIES_MAX = 8 };
static void series(double x, double *ij0, double *iy0) {
  double q = 0.25 * x * x, c = 1.0, H = 0.0, L = log(0.5 * x) + EULER_GAMMA;
  double sj = 0.0, sy = 0.0;
  for (int k = 0; k < 200; ++k) {
    if (k > 0) c *= -q / ((double)k * (double)k), H += 1.0 / k;
    double t = x * c / (2.0 * k + 1.0);
    sj += t;
    sy += t * (L - H - 1.0 / (2.0 * k + 1.0));
    if (k > q && fabs(t) * (1.0 + fabs(L) + H) < 1e-18 * (fabs(sj) + fabs(sy))) break;
  }
  *ij0 = sj;
  *iy0 = 2.0 / PI * sy;
}

/* 16-point Gauss-Legendre nodes and weights on [-1, 1], by Newton's method on P_16 from the Chebyshev-like
 * initial guesses (Press et al., Numerical Recipes, 2nd ed. 1992, section 4.5, gauleg). */
enum { GL_N = 16 };
static void gauss_legendre(double *xg, double *wg) {
  for (int i = 0; i < (GL_N + 1) / 2; ++i) {
    double z = cos(PI * (i + 0.75) / (GL_N + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = 0.0;
      for (int j = 1; j <= GL_N; ++j) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
      }
      dp = GL_N * (z * p0 - p1) / (z * z - 1.0);
      double dz = p0 / dp;
      z -= dz;
      if (fabs(dz) < 1e-16) break;
    }
    xg[i] = -z, xg[GL_N - 1 - i] = z;
    wg[i] = wg[GL_N - 1 - i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

/* int_a^b f for SERIES_MAX <= a < b, f smooth there: panels of width at most 1. */
static double panels(double (*f)(double), double a, double b) {
  double xg[GL_N], wg[GL_N], s = 0.0;
  gauss_legendre(xg, wg);
  long n = (long)ceil(b - a);
  double h = (b - a) / (double)n;
  for (long p = 0; p < n; ++p) {
    double m = a + (p + 0.5) * h, part = 0.0;
    for (int i = 0; i < GL_N; ++i) part += wg[i] * f(m + 0.5 * h * xg[i]);
    s += 0.5 * h * part;
  }
  return s;
}

/* Beyond this the panels cost too much (16 evaluations per unit of x): NaN. */
static const double INT_MAX_X = 1e5;

double sl_bessel_int_j0(double x) {
  if (isnan(x)) return x;
  if (x < 0.0) return -sl_bessel_int_j0(-x);
  if (x > INT_MAX_X) return NAN;
  double ij, iy;
  series(x < SERIES_MAX ? x : SERIES_MAX, &ij, &iy);
  return x <= SERIES_MAX ? ij : ij + panels(sl_bessel_j0, SERIES_MAX, x);
}

double sl_bessel_int_y0(double x) {
  if (!(x >= 0.0) || x > INT_MAX_X) return NAN;
  if (x == 0.0) return 0.0;
  double ij, iy;
  series(x < SERIES_MAX ? x : SERIES_MAX, &ij, &iy);
  return x <= SERIES_MAX ? iy : iy + panels(sl_bessel_y0, SERIES_MAX, x);
}
