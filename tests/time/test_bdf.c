/* Variable-step BDF1/BDF2 on scalar linear ODEs y' = lambda (y - g(t)) + g'(t)
 * with the exact solution y = g(t) + (y0 - g(0)) e^{lambda t}:
 *  - observed orders 1 and 2 with constant and with varying steps;
 *  - the Milne estimate against the true local error (ratio -> 1 as h -> 0)
 *    for several step ratios;
 *  - adaptive runs: controlling the local error per step to tol makes the
 *    global error scale as tol^(p/(p+1)) and the step count as
 *    tol^(-1/(p+1)). */
#include <math.h>
#include <stdio.h>

#include "core/time/bdf.h"
#include "testing.h"

static const double lambda = -2.0;
static double g(double t) { return sin(t) + 0.5 * t * t; }
static double dg(double t) { return cos(t) + t; }
static double exact(double t) { return g(t) + (1.0 - g(0.0)) * exp(lambda * t); }

/* The implicit stage: mass y + hist = lambda (y - g) + g' at t, linear in y. */
static double stage(const sl_bdf_step *s, double hist, double t) {
  return (-hist - lambda * g(t) + dg(t)) / (s->mass_coef - lambda);
}

/* Integrates to t_end with steps h * pattern[k % np]; returns the final error. */
static double run_fixed(int order, double h, const double *pattern, int np, double t_end, int *steps) {
  sl_bdf b;
  double y0 = exact(0.0), hist, pred, y = y0;
  if (sl_bdf_init(&b, order, 1, &y0, 0.0, NULL)) return NAN;
  int k = 0;
  while (b.t < t_end - 1e-12) {
    double hk = fmin(h * pattern[k % np], t_end - b.t);
    sl_bdf_step s;
    sl_bdf_prepare(&b, hk, &s, &hist, &pred);
    y = stage(&s, hist, b.t + hk);
    sl_bdf_accept(&b, &s, &y);
    ++k;
  }
  double e = fabs(y - exact(b.t));
  sl_bdf_free(&b);
  if (steps) *steps = k;
  return e;
}

static void orders(void) {
  const double constant[] = {1.0}, varying[] = {1.0, 1.7, 0.6, 1.3};
  const double *patterns[] = {constant, varying};
  const int np[] = {1, 4};
  for (int order = 1; order <= 2; ++order)
    for (int p = 0; p < 2; ++p) {
      double e[4];
      /* BDF2 starts with two BDF1 steps whose O(h^2) error partly cancels
       * BDF2's own at coarse steps: the asymptotic range starts near h = 0.01. */
      for (int k = 0; k < 4; ++k) e[k] = run_fixed(order, 0.01 / (1 << k), patterns[p], np[p], 2.0, NULL);
      for (int k = 0; k < 3; ++k) {
        double rate = log2(e[k] / e[k + 1]);
        printf("BDF%d %s steps: error %.3e -> %.3e, order %.3f\n", order, p ? "varying" : "constant", e[k], e[k + 1],
               rate);
        CHECK_MSG(fabs(rate - order) < 0.1, "BDF%d observed order %.3f", order, rate);
      }
    }
}

/* One step from exact past values at t = 1 with steps hpp, hp, h; returns
 * estimated / true local error. */
static double estimate_ratio(int order, double h, double w, double wp) {
  double hp = h / w, hpp = hp / wp, t = 1.0;
  sl_bdf b;
  double y = exact(t - hp - hpp), hist, pred;
  if (sl_bdf_init(&b, order, 1, &y, t - hp - hpp, NULL)) return NAN;
  const double hs[2] = {hpp, hp};
  for (int k = 0; k < 2; ++k) {
    sl_bdf_step s;
    sl_bdf_prepare(&b, hs[k], &s, &hist, &pred);
    y = exact(b.t + hs[k]); /* exact past values */
    sl_bdf_accept(&b, &s, &y);
  }
  sl_bdf_step s;
  sl_bdf_prepare(&b, h, &s, &hist, &pred);
  y = stage(&s, hist, t + h);
  double est = s.err_factor * (y - pred), err = y - exact(t + h);
  CHECK(s.order == order && s.estimated);
  sl_bdf_free(&b);
  return est / err;
}

static void estimates(void) {
  const double ws[][2] = {{1.0, 1.0}, {2.0, 0.5}, {0.5, 1.5}, {1.8, 1.8}};
  for (int order = 1; order <= 2; ++order)
    for (int k = 0; k < 4; ++k) {
      double coarse = estimate_ratio(order, 2e-2, ws[k][0], ws[k][1]);
      double fine = estimate_ratio(order, 2e-3, ws[k][0], ws[k][1]);
      printf("BDF%d omega %.1f, %.1f: estimate / true local error %.4f (h = 2e-2), %.5f (h = 2e-3)\n", order, ws[k][0],
             ws[k][1], coarse, fine);
      CHECK_MSG(fabs(fine - 1.0) < 0.02, "BDF%d estimate ratio %.4f", order, fine);
      CHECK(fabs(fine - 1.0) < fabs(coarse - 1.0) + 1e-3);
    }
}

/* Adaptive integration to t = 3 with tolerance tol; returns the final error. */
static double run_adaptive(int order, double tol, int *steps, int *rejected) {
  sl_bdf b;
  double y = exact(0.0), hist, pred;
  if (sl_bdf_init(&b, order, 1, &y, 0.0, NULL)) return NAN;
  double h = 1e-4, t_end = 3.0;
  *steps = *rejected = 0;
  while (b.t < t_end - 1e-14) {
    h = fmin(h, t_end - b.t);
    sl_bdf_step s;
    sl_bdf_prepare(&b, h, &s, &hist, &pred);
    double yn = stage(&s, hist, b.t + h);
    double err = sl_bdf_error(&s, &yn, &pred, 1, tol, 1e-12);
    double h_next = sl_bdf_next_h(&s, err);
    if (err > 1.0) {
      ++*rejected;
    } else {
      sl_bdf_accept(&b, &s, &yn);
      y = yn;
      ++*steps;
    }
    h = h_next;
  }
  double e = fabs(y - exact(b.t));
  sl_bdf_free(&b);
  return e;
}

static void adaptive(void) {
  for (int order = 1; order <= 2; ++order) {
    double e_prev = 0.0, e_first = 0.0;
    int n_prev = 0;
    for (int k = 0; k < 3; ++k) {
      double tol = 1e-3 * pow(0.1, k);
      int n = 0, rej = 0;
      double e = run_adaptive(order, tol, &n, &rej);
      printf("BDF%d adaptive tol %.0e: %d steps, %d rejected, final error %.3e\n", order, tol, n, rej, e);
      if (k == 0) e_first = e;
      if (k == 2) {
        double ratio = e_first / e, expect = pow(100.0, (double)order / (order + 1));
        printf("BDF%d adaptive: error ratio over a 100-fold tolerance change %.2f (tol^(p/(p+1)): %.2f)\n", order,
               ratio, expect);
        CHECK_MSG(ratio > expect / 1.3 && ratio < expect * 1.3, "BDF%d error ratio %.2f, %.2f expected", order, ratio,
                  expect);
      }
      if (k > 0) {
        /* a tenth of the tolerance costs 10^(1/(p+1)) times the steps */
        double growth = (double)n / n_prev, expect = pow(10.0, 1.0 / (order + 1));
        CHECK_MSG(growth > 0.7 * expect && growth < 1.5 * expect, "BDF%d step growth %.2f (about %.2f expected)", order,
                  growth, expect);
        CHECK(e < e_prev);
      }
      e_prev = e, n_prev = n;
    }
  }
}

int main(void) {
  orders();
  estimates();
  adaptive();
  return sl_test_summary();
}
