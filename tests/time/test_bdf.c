/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Variable-step BDF1/BDF2 on scalar linear ODEs y' = lambda (y - g(t)) + g'(t)
 * with the exact solution y = g(t) + (y0 - g(0)) e^{lambda t}:
 *  - observed orders 1 and 2 with constant and with varying steps;
 *  - the Milne estimate against the true local error (ratio -> 1 as h -> 0)
 *    for several step ratios;
 *  - adaptive runs: controlling the local error per step to tol makes the
 *    global error scale as tol^(p/(p+1)) and the step count as
 *    tol^(-1/(p+1));
 *  - the step controller (sl_bdf_controller): the same scaling with each
 *    filter; on a problem whose step is set by the stability of a lagged
 *    (explicit) stiff term, the filters reject fewer steps than the
 *    elementary controller; a step whose error falls like h (a
 *    non-smooth history) is found in three retries; the saved state
 *    continues the proposals exactly;
 *  - landing on output times (sl_bdf_landing_step, sl_bdf_after_landing):
 *    for any proposal h and distance to the output time, every step of
 *    the approach is at least h/2 (or the whole rest within 1.05 h), the
 *    output time is hit exactly, and the step after the landing is at most
 *    twice the landing step: below BDF2's zero-stability bound 1 + sqrt(2)
 *    on the step ratio (Grigorieff 1983). */
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

/* ---- the step controller ----------------------------------------------------------- */

static const char *const control_names[4] = {"H211PI", "PI", "H211b", "elementary"};

/* Adaptive integration to t_end with the controller; the lagged term -mu (y_n - g(t_n)) is explicit (mu = 0:
 * none). Returns the final error. */
static double run_controlled(sl_bdf_control kind, int order, double tol, double mu, double t_end, int *steps,
                             int *rejected) {
  sl_bdf b;
  double y = exact(0.0), hist, pred;
  if (sl_bdf_init(&b, order, 1, &y, 0.0, NULL)) return NAN;
  sl_bdf_controller c;
  sl_bdf_controller_init(&c, kind);
  double h = 1e-4;
  *steps = *rejected = 0;
  while (b.t < t_end - 1e-12) {
    h = fmin(h, t_end - b.t);
    sl_bdf_step s;
    sl_bdf_prepare(&b, h, &s, &hist, &pred);
    double t = b.t + h, yn = b.past[0][0];
    /* the exact solution of y' = lambda (y - g) + g' - mu (y - g) from y(0) = g(0) is g */
    double ynew = (-hist - lambda * g(t) + dg(t) - mu * (yn - g(b.t))) / (s.mass_coef - lambda);
    if (mu == 0.0) ynew = stage(&s, hist, t);
    double err = sl_bdf_error(&s, &ynew, &pred, 1, tol, 1e-12);
    if (err > 1.0) {
      h = sl_bdf_controller_reject(&c, &s, err);
      ++*rejected;
      continue;
    }
    sl_bdf_accept(&b, &s, &ynew);
    h = sl_bdf_controller_accept(&c, &s, err);
    ++*steps;
  }
  CHECK(c.accepted == *steps && c.rejected == *rejected && c.failed == 0);
  double e = fabs(b.past[0][0] - (mu == 0.0 ? exact(b.t) : g(b.t)));
  sl_bdf_free(&b);
  return e;
}

static void controlled(void) {
  for (int kind = 0; kind < 4; ++kind) {
    double e[3];
    int n[3], rej[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = run_controlled(kind, 2, 1e-4 * pow(0.1, k), 0.0, 3.0, &n[k], &rej[k]);
      printf("BDF2, %s control, tol %.0e: %d steps, %d rejected, final error %.3e\n", control_names[kind],
             1e-4 * pow(0.1, k), n[k], rej[k], e[k]);
      CHECK_MSG(10 * rej[k] <= n[k], "%s: %d rejections in %d steps of a smooth problem", control_names[kind], rej[k],
                n[k]);
      if (k > 0) {
        double growth = (double)n[k] / n[k - 1], expect = pow(10.0, 1.0 / 3.0);
        CHECK_MSG(growth > 0.7 * expect && growth < 1.5 * expect, "%s: step growth %.2f", control_names[kind], growth);
        CHECK(e[k] < e[k - 1]);
      }
    }
    double ratio = e[0] / e[2], expect = pow(100.0, 2.0 / 3.0);
    CHECK_MSG(ratio > expect / 1.3 && ratio < expect * 1.3, "%s: error ratio %.2f over a 100-fold tolerance change",
              control_names[kind], ratio);
  }
  /* A lagged stiff term (mu = 100): stable while h mu stays below about 2, so the step is set by stability,
     where the elementary controller grows the step into instability, is rejected, shrinks, grows again. */
  int n[4], rej[4];
  double e[4];
  for (int kind = 0; kind < 4; ++kind) {
    e[kind] = run_controlled(kind, 2, 1e-4, 100.0, 10.0, &n[kind], &rej[kind]);
    printf("BDF2 with a lagged stiff term, %s control: %d steps, %d rejected (%.0f %%), error %.2e\n",
           control_names[kind], n[kind], rej[kind], 100.0 * rej[kind] / (n[kind] + rej[kind]), e[kind]);
  }
  CHECK_MSG(4 * rej[1] <= 3 * rej[3] && 4 * rej[2] <= 3 * rej[3], "rejections: PI %d, H211b %d, elementary %d", rej[1],
            rej[2], rej[3]);
}

/* A step whose error goes as 400 (h / 2e-3): the retries with the observed exponent find it in three; the
 * elementary retry (h^(1/2) for BDF1, at least a fifth of the step) would take six. */
static void retry_exponent(void) {
  sl_bdf_controller c;
  sl_bdf_controller_init(&c, SL_BDF_CONTROL_PI);
  sl_bdf_step s = {.order = 1, .estimated = 1, .h = 2e-3};
  int tries = 0;
  double err;
  while ((err = 400.0 * s.h / 2e-3) > 1.0 && tries < 20) s.h = sl_bdf_controller_reject(&c, &s, err), ++tries;
  int elementary = 0;
  for (double h = 2e-3; 400.0 * h / 2e-3 > 1.0 && elementary < 20; ++elementary)
    h *= fmin(0.9, fmax(0.2, pow(0.8 / (400.0 * h / 2e-3), 0.5)));
  printf("retries of a step whose error falls like h: %d (elementary: %d), accepted at h = %.3g, error %.3f\n", tries,
         elementary, s.h, err);
  CHECK(tries == 3 && elementary == 6 && err > 0.1);
  /* after the rejections: no growth; an unestimated step grows by grow_max */
  CHECK(sl_bdf_controller_accept(&c, &s, err) <= s.h);
  sl_bdf_step first = {.order = 1, .estimated = 0, .h = 1e-3};
  CHECK(sl_bdf_controller_accept(&c, &first, 0.0) == c.grow_max * first.h);
  CHECK(sl_bdf_controller_fail(&c, &first) == 0.25 * first.h && c.failed == 1);
}

/* The saved state continues the proposals exactly (a restart). */
static void controller_state(void) {
  sl_bdf_controller a, b;
  sl_bdf_controller_init(&a, SL_BDF_CONTROL_H211B);
  sl_bdf_step s = {.order = 2, .estimated = 1, .h = 0.01};
  const double errs[] = {0.3, 0.5, 0.2, 1.7, 0.6, 0.4, 0.45};
  double state[SL_BDF_CONTROLLER_STATE], ha = 0.0, hb = 0.0;
  for (int k = 0; k < 7; ++k) {
    if (k == 4) {
      sl_bdf_controller_save(&a, state);
      sl_bdf_controller_init(&b, SL_BDF_CONTROL_H211B);
      sl_bdf_controller_restore(&b, state);
    }
    sl_bdf_step sb = s;
    ha = errs[k] > 1.0 ? sl_bdf_controller_reject(&a, &s, errs[k]) : sl_bdf_controller_accept(&a, &s, errs[k]);
    if (k >= 4) {
      hb = errs[k] > 1.0 ? sl_bdf_controller_reject(&b, &sb, errs[k]) : sl_bdf_controller_accept(&b, &sb, errs[k]);
      CHECK_MSG(ha == hb, "step %d: %.17g, restored %.17g", k, ha, hb);
    }
    s.h = ha;
  }
}

static void landing(void) {
  int bad_short = 0, bad_ratio = 0, bad_hit = 0, cases = 0;
  double worst = 0.0;
  for (int a = 1; a <= 400; ++a)  /* distance to the output time, in units of the proposal h = 0.01 */
    for (int g = 0; g < 3; ++g) { /* the controller's proposal after a landing: shrink, keep, grow */
      const double h0 = 0.01, eps = 1e-12, t_stop = 1.0, rest = 0.0137 * a * h0;
      double t = t_stop - rest, h = h0, last = 0.0;
      int steps = 0;
      while (t < t_stop - eps && steps < 100) {
        int land;
        double hh = sl_bdf_landing_step(t, h, t_stop, eps, 1, &land);
        if (hh < 0.5 * h - 1e-15 && !(land && hh == t_stop - t && hh <= 1.05 * h)) ++bad_short;
        t = fabs(t + hh - t_stop) <= eps ? t_stop : t + hh;
        if (land) h = sl_bdf_after_landing(h, hh, (0.5 + 0.75 * g) * hh);
        last = hh, ++steps;
      }
      if (t != t_stop) ++bad_hit;
      if (h > 2.0 * last * (1 + 1e-12) && last < h0) ++bad_ratio;
      worst = fmax(worst, h / last);
      ++cases;
    }
  printf("landing: %d approaches, the step after the landing at most %.3f times it\n", cases, worst);
  CHECK(bad_short == 0 && bad_hit == 0 && bad_ratio == 0);
  CHECK(worst <= 2.0 + 1e-12 && worst < 1.0 + sqrt(2.0));
}

int main(void) {
  orders();
  estimates();
  adaptive();
  controlled();
  retry_exponent();
  controller_state();
  landing();
  return sl_test_summary();
}
