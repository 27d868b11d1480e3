/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Variable-step BDF1/BDF2 with Milne error estimates (see bdf.h).
 *
 * Error constants, expanding about t_{n+1} (h = t_{n+1} - t_n, hp, hpp the
 * previous steps), for a smooth solution u:
 *  - corrector: the numerical u_{n+1} from exact past values differs from
 *    u(t_{n+1}) by -tau/a0, tau the residual of the exact solution in the
 *    scheme; for BDF2 tau = -(u'''/6)(a1 h^3 + a2 (h + hp)^3) = -(u'''/6) h^3
 *    (1 + omega)/omega, so the error is +u''' h^3 (1+omega)^2/(6 omega (1+2 omega));
 *    for BDF1 it is +u'' h^2/2;
 *  - predictor: the extrapolating polynomial through the past values misses
 *    u(t_{n+1}) by u^(p+1)/(p+1)! times the product of the distances to the
 *    interpolation nodes, P = u(t_{n+1}) - C_p u^(p+1).
 * Hence u_{n+1} - P = (C_c + C_p) u^(p+1) and the corrector's error is
 * C_c/(C_c + C_p) of that difference. tests/time checks the estimate
 * against the true local error. */
#include "core/time/bdf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int sl_bdf_init(sl_bdf *b, int order_max, int32_t n, const double *u0, double t0, sl_diag *d) {
  memset(b, 0, sizeof *b);
  if (order_max < 1 || order_max > 2) return sl_diag_set(d, SL_EBADINPUT, "bdf: order %d (1 or 2)", order_max);
  for (int k = 0; k < 3; ++k)
    if (!(b->past[k] = malloc((size_t)n * sizeof(double)))) {
      sl_bdf_free(b);
      return sl_diag_set(d, SL_ENOMEM, "bdf: out of memory for %d unknowns", (int)n);
    }
  memcpy(b->past[0], u0, (size_t)n * sizeof(double));
  b->order_max = order_max, b->n = n, b->n_past = 1, b->t = t0;
  return 0;
}

void sl_bdf_free(sl_bdf *b) {
  for (int k = 0; k < 3; ++k) free(b->past[k]);
  memset(b, 0, sizeof *b);
}

void sl_bdf_prepare(const sl_bdf *b, double h, sl_bdf_step *s, double *history, double *predictor) {
  const double *u0 = b->past[0], *u1 = b->past[1], *u2 = b->past[2];
  double hp = b->h_past[0], hpp = b->h_past[1];
  memset(s, 0, sizeof *s);
  s->h = h;
  s->order = b->order_max == 2 && b->n_past >= 3 ? 2 : 1;
  if (s->order == 1) {
    s->mass_coef = 1.0 / h;
    for (int32_t i = 0; i < b->n; ++i) history[i] = -u0[i] / h;
    if (b->n_past >= 2) {
      /* linear extrapolation through (t_{n-1}, u1), (t_n, u0) */
      double r = h / hp;
      for (int32_t i = 0; i < b->n; ++i) predictor[i] = u0[i] + r * (u0[i] - u1[i]);
      double cc = 0.5 * h * h, cp = 0.5 * h * (h + hp);
      s->estimated = 1, s->err_factor = cc / (cc + cp);
    } else {
      memcpy(predictor, u0, (size_t)b->n * sizeof *predictor);
    }
    return;
  }
  double w = h / hp;
  double a0 = (1.0 + 2.0 * w) / (1.0 + w), a1 = -(1.0 + w), a2 = w * w / (1.0 + w);
  s->mass_coef = a0 / h;
  for (int32_t i = 0; i < b->n; ++i) history[i] = (a1 * u0[i] + a2 * u1[i]) / h;
  /* Quadratic extrapolation (Lagrange) through t_{n-2}, t_{n-1}, t_n to
   * t_{n+1}, with times relative to t_n: 0, -hp, -(hp + hpp). */
  double t0 = 0.0, t1 = -hp, t2 = -(hp + hpp), x = h;
  double l0 = (x - t1) * (x - t2) / ((t0 - t1) * (t0 - t2));
  double l1 = (x - t0) * (x - t2) / ((t1 - t0) * (t1 - t2));
  double l2 = (x - t0) * (x - t1) / ((t2 - t0) * (t2 - t1));
  for (int32_t i = 0; i < b->n; ++i) predictor[i] = l0 * u0[i] + l1 * u1[i] + l2 * u2[i];
  double cc = h * h * h * (1.0 + w) * (1.0 + w) / (6.0 * w * (1.0 + 2.0 * w));
  double cp = h * (h + hp) * (h + hp + hpp) / 6.0;
  s->estimated = 1, s->err_factor = cc / (cc + cp);
}

double sl_bdf_error(const sl_bdf_step *s, const double *u, const double *predictor, int32_t n_err, double rtol,
                    double scale) {
  if (!s->estimated) return 0.0;
  double diff = 0.0, size = 0.0;
  for (int32_t i = 0; i < n_err; ++i) {
    diff = fmax(diff, fabs(u[i] - predictor[i]));
    size = fmax(size, fabs(u[i]));
  }
  return s->err_factor * diff / (rtol * fmax(size, scale));
}

double sl_bdf_next_h(const sl_bdf_step *s, double err) {
  const double shrink_min = 0.2, grow_max = s->order == 2 ? 2.0 : 2.5;
  if (!(err > 0.0)) return s->h * grow_max;
  double f = 0.9 * pow(err, -1.0 / (s->order + 1));
  if (!isfinite(f)) f = shrink_min;
  return s->h * fmin(grow_max, fmax(shrink_min, f));
}

double sl_bdf_landing_step(double t, double h, double t_stop, double eps, int adaptive, int *landing) {
  *landing = 0;
  if (fabs(t + h - t_stop) <= eps) return h;
  if (t + 1.05 * h > t_stop) return *landing = 1, t_stop - t;
  /* the step after a sliver returned to the proposal at up to 7 (diverted: 13) times it and its estimate rejected it
     (the spectrometer to t = 3: 38 of its 83 rejections, in 23 of 46 episodes, followed a landing;
     docs/transient_cost.md, "Rejected steps of the spectrometer") */
  if (adaptive && t + 2.0 * h > t_stop + eps) return *landing = 1, 0.5 * (t_stop - t);
  return h;
}

double sl_bdf_after_landing(double h, double hh, double h_next) { return fmin(h, fmax(h_next, 2.0 * hh)); }

void sl_bdf_accept(sl_bdf *b, const sl_bdf_step *s, const double *u) {
  double *oldest = b->past[2];
  b->past[2] = b->past[1], b->past[1] = b->past[0], b->past[0] = oldest;
  memcpy(b->past[0], u, (size_t)b->n * sizeof *u);
  b->h_past[1] = b->h_past[0], b->h_past[0] = s->h;
  b->t += s->h;
  if (b->n_past < 3) ++b->n_past;
}

/* ---- step-size controller (see bdf.h) ----------------------------------------- */

void sl_bdf_controller_init(sl_bdf_controller *c, sl_bdf_control kind) {
  memset(c, 0, sizeof *c);
  c->safety = 0.7, c->grow_max = 2.0, c->shrink_min = 0.2;
  switch (kind) {
    case SL_BDF_CONTROL_ELEMENTARY:
      c->b1 = 1.0;
      break;
    case SL_BDF_CONTROL_PI:
      c->b1 = 0.7, c->b2 = -0.4;
      break; /* Gustafsson 1991 */
    case SL_BDF_CONTROL_H211B:
      c->b1 = c->b2 = c->a2 = 0.25;
      break; /* Soderlind 2003, H211b with b = 4 */
    default:
      c->b1 = c->b2 = 1.0 / 6.0; /* Soderlind 2003, H211PI */
  }
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

double sl_bdf_controller_accept(sl_bdf_controller *c, const sl_bdf_step *s, double err) {
  ++c->accepted;
  double k = s->order + 1, q = c->safety;
  double grow = c->after_reject ? 1.0 : c->grow_max;
  /* an unestimated step (the first) or an error at round-off: grow as allowed */
  double e = err > 1e-10 ? err : 1e-10;
  double ratio;
  if (!s->estimated) {
    ratio = grow;
  } else if (c->err_prev > 0.0 && !c->after_reject) {
    ratio = pow(q / e, c->b1 / k) * pow(q / c->err_prev, c->b2 / k);
    if (c->a2 != 0.0 && c->ratio_prev > 0.0) ratio *= pow(c->ratio_prev, -c->a2);
  } else {
    ratio = pow(q / e, 1.0 / k);
  }
  if (!isfinite(ratio)) ratio = grow;
  ratio = clampd(ratio, c->shrink_min, grow);
  if (getenv("SLUICE_STEP_TRACE"))
    fprintf(stderr, "  step %ld: BDF%d h %.4g, error %.3g: accepted, next h %.4g\n", c->accepted, s->order, s->h,
            s->estimated ? err : NAN, s->h * ratio);
  c->err_prev = s->estimated ? e : 0.0;
  c->ratio_prev = ratio;
  c->after_reject = 0;
  c->rej_h = c->rej_err = 0.0;
  return s->h * ratio;
}

double sl_bdf_controller_reject(sl_bdf_controller *c, const sl_bdf_step *s, double err) {
  ++c->rejected;
  c->after_reject = 1;
  double k = s->order + 1, lo = c->shrink_min;
  if (c->rej_h > s->h && c->rej_err > err) { /* rejected again: the exponent the two attempts show */
    double kappa = log(c->rej_err / err) / log(c->rej_h / s->h);
    if (isfinite(kappa)) k = clampd(kappa, 0.5, k), lo = 0.02;
  }
  c->rej_h = s->h, c->rej_err = err;
  double f = pow(c->safety / err, 1.0 / k);
  if (!isfinite(f)) f = lo;
  f = clampd(f, lo, 0.9);
  if (getenv("SLUICE_STEP_TRACE"))
    fprintf(stderr, "  step %ld: BDF%d h %.4g, error %.3g: rejected, retry with h %.4g\n", c->accepted + 1, s->order,
            s->h, err, s->h * f);
  return s->h * f;
}

double sl_bdf_controller_fail(sl_bdf_controller *c, const sl_bdf_step *s) {
  ++c->failed;
  c->after_reject = 1;
  c->rej_h = c->rej_err = 0.0;
  if (getenv("SLUICE_STEP_TRACE"))
    fprintf(stderr, "  step %ld: BDF%d h %.4g: the nonlinear solve failed, retry with h %.4g\n", c->accepted + 1,
            s->order, s->h, 0.25 * s->h);
  return 0.25 * s->h;
}

void sl_bdf_controller_save(const sl_bdf_controller *c, double *state) {
  state[0] = c->err_prev, state[1] = c->ratio_prev, state[2] = c->after_reject;
}

void sl_bdf_controller_restore(sl_bdf_controller *c, const double *state) {
  c->err_prev = state[0], c->ratio_prev = state[1], c->after_reject = state[2] != 0.0;
}
