/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Quadrature rules: Gauss–Legendre (computed) and symmetric triangle rules
 * (tabulated); sources are cited in quadrature.h. */
#include "core/fe/quadrature.h"

#include <math.h>
#include <string.h>

double sl_reference_measure(sl_cell_type cell) {
  switch (cell) {
    case SL_CELL_LINE2:
      return 2.0;
    case SL_CELL_TRI3:
      return 0.5;
    case SL_CELL_QUAD4:
      return 4.0;
  }
  return 0.0;
}

/* P_n(x) and P_n'(x) by the three-term recurrence. */
static void legendre(int n, double x, double *p, double *dp) {
  double p0 = 1.0, p1 = x;
  if (n == 0) {
    *p = 1.0, *dp = 0.0;
    return;
  }
  for (int k = 2; k <= n; ++k) {
    double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1, p1 = pk;
  }
  *p = p1;
  *dp = n * (x * p1 - p0) / (x * x - 1.0);
}

/* Nodes ascending and weights of the n-point rule on [-1, 1]. */
static void gauss_legendre(int n, double *x, double *w) {
  for (int i = 0; i < (n + 1) / 2; ++i) {
    /* Tricomi's initial guess for the i-th largest root; Newton converges in a few steps. */
    double z = cos(M_PI * (i + 0.75) / (n + 0.5)), p = 0.0, dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      legendre(n, z, &p, &dp);
      double dz = p / dp;
      z -= dz;
      if (fabs(dz) < 1e-16) break;
    }
    legendre(n, z, &p, &dp);
    double wi = 2.0 / ((1.0 - z * z) * dp * dp);
    x[n - 1 - i] = z, x[i] = -z;
    w[n - 1 - i] = w[i] = wi;
  }
  if (n % 2) x[n / 2] = 0.0; /* exactly, not 1e-17 */
}

int sl_quadrature_gauss_line(int n, sl_quadrature *q, sl_diag *d) {
  if (n < 1 || n > SL_GAUSS_MAX_POINTS)
    return sl_diag_set(d, SL_EBADINPUT, "quadrature: Gauss rule with %d points (1..%d supported)", n,
                       SL_GAUSS_MAX_POINTS);
  double x[SL_GAUSS_MAX_POINTS], w[SL_GAUSS_MAX_POINTS];
  gauss_legendre(n, x, w);
  memset(q, 0, sizeof *q);
  q->cell = SL_CELL_LINE2, q->n = n, q->degree = 2 * n - 1;
  for (int i = 0; i < n; ++i) q->xi[i][0] = x[i], q->w[i] = w[i];
  return 0;
}

int sl_quadrature_gauss_quad(int n, sl_quadrature *q, sl_diag *d) {
  if (n < 1 || n > SL_GAUSS_MAX_POINTS)
    return sl_diag_set(d, SL_EBADINPUT, "quadrature: tensor Gauss rule with %d points per direction (1..%d supported)",
                       n, SL_GAUSS_MAX_POINTS);
  double x[SL_GAUSS_MAX_POINTS], w[SL_GAUSS_MAX_POINTS];
  gauss_legendre(n, x, w);
  memset(q, 0, sizeof *q);
  q->cell = SL_CELL_QUAD4, q->n = n * n, q->degree = 2 * n - 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int k = j * n + i;
      q->xi[k][0] = x[i], q->xi[k][1] = x[j], q->w[k] = w[i] * w[j];
    }
  return 0;
}

/* ---- triangle ------------------------------------------------------------ */

/* Adds the orbit of a symmetric point with barycentric coordinates
 * (a, a, 1 - 2a): 1 point when a = 1/3, else 3. w is for a unit-area
 * triangle; the reference triangle has area 1/2. */
static void add_orbit(sl_quadrature *q, double a, double w) {
  double b = 1.0 - 2.0 * a;
  if (a == 1.0 / 3.0) {
    q->xi[q->n][0] = q->xi[q->n][1] = a, q->w[q->n++] = 0.5 * w;
    return;
  }
  const double pts[3][2] = {{a, a}, {b, a}, {a, b}};
  for (int k = 0; k < 3; ++k) q->xi[q->n][0] = pts[k][0], q->xi[q->n][1] = pts[k][1], q->w[q->n++] = 0.5 * w;
}

int sl_quadrature_triangle(int degree, sl_quadrature *q, sl_diag *d) {
  if (degree < 0 || degree > SL_TRI_MAX_DEGREE)
    return sl_diag_set(d, SL_EBADINPUT, "quadrature: no triangle rule of degree %d (0..%d supported)", degree,
                       SL_TRI_MAX_DEGREE);
  memset(q, 0, sizeof *q);
  q->cell = SL_CELL_TRI3;
  if (degree <= 1) {
    q->degree = 1;
    add_orbit(q, 1.0 / 3.0, 1.0);
  } else if (degree == 2) {
    /* Strang & Fix (1973), interior 3-point rule. */
    q->degree = 2;
    add_orbit(q, 1.0 / 6.0, 1.0 / 3.0);
  } else if (degree <= 4) {
    /* Dunavant (1985), degree 4, 6 points. */
    q->degree = 4;
    add_orbit(q, 0.445948490915964886318329253883, 0.223381589678011465695007008433);
    add_orbit(q, 0.091576213509770743459571463402, 0.109951743655321867638326324900);
  } else {
    /* Radon (1948) / Dunavant (1985) degree 5, 7 points, in closed form. */
    double s = sqrt(15.0);
    q->degree = 5;
    add_orbit(q, 1.0 / 3.0, 9.0 / 40.0);
    add_orbit(q, (6.0 - s) / 21.0, (155.0 - s) / 1200.0);
    add_orbit(q, (6.0 + s) / 21.0, (155.0 + s) / 1200.0);
  }
  return 0;
}

int sl_quadrature_for(sl_cell_type cell, int degree, sl_quadrature *q, sl_diag *d) {
  if (degree < 0) degree = 0;
  int n = degree / 2 + 1; /* 2n - 1 >= degree */
  switch (cell) {
    case SL_CELL_LINE2:
      return sl_quadrature_gauss_line(n, q, d);
    case SL_CELL_QUAD4:
      return sl_quadrature_gauss_quad(n, q, d);
    case SL_CELL_TRI3:
      return sl_quadrature_triangle(degree, q, d);
  }
  return sl_diag_set(d, SL_EBADINPUT, "quadrature: unknown cell type %d", (int)cell);
}
