/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Quadrature rules: weights sum to the reference measure, points lie in the
 * cell, and every monomial up to the rule's degree is integrated exactly. */
#include <math.h>

#include "core/fe/quadrature.h"
#include "testing.h"

/* Exact integrals of monomials on the reference cells. */
static double line_moment(int i) { return i % 2 ? 0.0 : 2.0 / (i + 1); }
static double quad_moment(int i, int j) { return line_moment(i) * line_moment(j); }
static double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
/* int_T x^i y^j = i! j! / (i + j + 2)! on the unit reference triangle. */
static double tri_moment(int i, int j) { return factorial(i) * factorial(j) / factorial(i + j + 2); }

static double apply(const sl_quadrature *q, int i, int j) {
  double s = 0.0;
  for (int k = 0; k < q->n; ++k) s += q->w[k] * pow(q->xi[k][0], i) * pow(q->xi[k][1], j);
  return s;
}

static void check_sum_and_inside(const sl_quadrature *q) {
  double s = 0.0;
  int inside = 1, positive = 1;
  for (int k = 0; k < q->n; ++k) {
    s += q->w[k];
    positive &= q->w[k] > 0.0;
    double x = q->xi[k][0], y = q->xi[k][1];
    if (q->cell == SL_CELL_TRI3) inside &= x > 0.0 && y > 0.0 && x + y < 1.0;
    else inside &= fabs(x) < 1.0 && fabs(y) < 1.0;
  }
  CHECK_CLOSE(s, sl_reference_measure(q->cell), 1e-14);
  CHECK(inside);
  CHECK(positive);
}

static void test_gauss_line(void) {
  for (int n = 1; n <= SL_GAUSS_MAX_POINTS; ++n) {
    sl_quadrature q;
    CHECK(sl_quadrature_gauss_line(n, &q, NULL) == 0);
    CHECK(q.n == n && q.degree == 2 * n - 1);
    check_sum_and_inside(&q);
    int worst_ok = 1;
    for (int i = 0; i <= 2 * n - 1; ++i) worst_ok &= fabs(apply(&q, i, 0) - line_moment(i)) < 1e-14;
    CHECK_MSG(worst_ok, "Gauss %d not exact to degree %d", n, 2 * n - 1);
    /* Not exact one degree higher: the degree is sharp. */
    CHECK(fabs(apply(&q, 2 * n, 0) - line_moment(2 * n)) > 1e-6);
  }
  /* Known 2- and 3-point nodes: 1/sqrt(3); sqrt(3/5) with weights 5/9, 8/9. */
  sl_quadrature q;
  sl_quadrature_gauss_line(2, &q, NULL);
  CHECK_CLOSE(q.xi[1][0], 1.0 / sqrt(3.0), 1e-15);
  sl_quadrature_gauss_line(3, &q, NULL);
  CHECK_CLOSE(q.xi[2][0], sqrt(0.6), 1e-15);
  CHECK_CLOSE(q.w[0], 5.0 / 9.0, 1e-15);
  CHECK_CLOSE(q.w[1], 8.0 / 9.0, 1e-15);
}

static void test_gauss_quad(void) {
  for (int n = 1; n <= SL_GAUSS_MAX_POINTS; ++n) {
    sl_quadrature q;
    CHECK(sl_quadrature_gauss_quad(n, &q, NULL) == 0);
    CHECK(q.n == n * n);
    check_sum_and_inside(&q);
    int ok = 1;
    for (int i = 0; i <= 2 * n - 1; ++i)
      for (int j = 0; j <= 2 * n - 1; ++j) ok &= fabs(apply(&q, i, j) - quad_moment(i, j)) < 1e-13;
    CHECK_MSG(ok, "tensor Gauss %d not exact to degree %d per variable", n, 2 * n - 1);
  }
}

static void test_triangle(void) {
  const int expected_points[] = {1, 1, 3, 6, 6, 7};
  for (int deg = 0; deg <= SL_TRI_MAX_DEGREE; ++deg) {
    sl_quadrature q;
    CHECK(sl_quadrature_triangle(deg, &q, NULL) == 0);
    CHECK(q.n == expected_points[deg] && q.degree >= deg);
    check_sum_and_inside(&q);
    double worst = 0.0;
    for (int i = 0; i <= q.degree; ++i)
      for (int j = 0; i + j <= q.degree; ++j) worst = fmax(worst, fabs(apply(&q, i, j) - tri_moment(i, j)));
    CHECK_MSG(worst < 1e-15, "triangle rule of degree %d: worst monomial error %g", q.degree, worst);
    /* Sharp: some monomial of degree + 1 is missed. */
    double miss = 0.0;
    for (int i = 0; i <= q.degree + 1; ++i)
      miss = fmax(miss, fabs(apply(&q, i, q.degree + 1 - i) - tri_moment(i, q.degree + 1 - i)));
    CHECK(miss > 1e-8);
  }
}

static void test_errors_and_selection(void) {
  sl_quadrature q;
  sl_diag d;
  CHECK(sl_quadrature_gauss_line(0, &q, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "Gauss rule with 0 points");
  CHECK(sl_quadrature_gauss_quad(SL_GAUSS_MAX_POINTS + 1, &q, &d) == SL_EBADINPUT);
  CHECK(sl_quadrature_triangle(6, &q, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "degree 6");
  CHECK(sl_quadrature_for(SL_CELL_QUAD4, 4, &q, NULL) == 0 && q.n == 9);
  CHECK(sl_quadrature_for(SL_CELL_LINE2, 5, &q, NULL) == 0 && q.n == 3);
  CHECK(sl_quadrature_for(SL_CELL_TRI3, 3, &q, NULL) == 0 && q.n == 6);
  CHECK(sl_quadrature_for(SL_CELL_TRI3, 0, &q, NULL) == 0 && q.n == 1);
}

int main(void) {
  test_gauss_line();
  test_gauss_quad();
  test_triangle();
  test_errors_and_selection();
  return sl_test_summary();
}
