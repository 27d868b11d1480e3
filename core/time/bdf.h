/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Variable-step BDF1/BDF2 for du/dt = F(u) (an index-1 DAE in the flow
 * solver: the pressure has no time derivative), with a predictor, a local
 * error estimate and step-size control.
 *
 * Step h from t_n with previous step hp (omega = h / hp):
 *   BDF1: (u_{n+1} - u_n) / h
 *   BDF2: (a0 u_{n+1} + a1 u_n + a2 u_{n-1}) / h,
 *         a0 = (1 + 2 omega)/(1 + omega), a1 = -(1 + omega), a2 = omega^2/(1 + omega)
 * (Hairer, Norsett & Wanner, Solving ODEs I, 2nd ed. 1993, section III.5,
 * variable-step BDF), written as du/dt ~ mass_coef u_{n+1} + history.
 *
 * Error estimate (Milne's device): the predictor is the extrapolation of the
 * same order through the past solutions, P = u_{n+1} + C_p u^(p+1) with the
 * sign convention below, and the corrector's local error is
 * C_c u^(p+1); for a smooth solution both are known multiples of the same
 * derivative, so
 *   local error ~ C_c / (C_c + C_p) (u_{n+1} - P).
 * Taylor expansion about t_{n+1} gives (derived in bdf.c)
 *   BDF1: C_c = h^2/2,  C_p = h (h + hp)/2                          (u'')
 *   BDF2: C_c = h^3 (1+omega)^2 / (6 omega (1 + 2 omega)),
 *         C_p = h (h + hp)(h + hp + hpp)/6                          (u''')
 * (constant steps: 1/3 and 2/11 of the difference). The first step has no
 * past to extrapolate from and is taken unestimated; the second is BDF1
 * with the linear predictor; BDF2 starts at the third, once the quadratic
 * predictor has three past values. */
#ifndef SLUICE_TIME_BDF_H
#define SLUICE_TIME_BDF_H

#include <stdint.h>

#include "core/util/diag.h"

typedef struct sl_bdf {
  int order_max;    /* 1 or 2 */
  int32_t n;        /* unknowns */
  int n_past;       /* past solutions held (1..3) */
  double t;         /* time of u_n */
  double h_past[2]; /* the last two accepted steps: h_{n-1}, h_{n-2} */
  double *past[3];  /* u_n, u_{n-1}, u_{n-2} */
} sl_bdf;

/* The history starts at u0 at time t0. */
int sl_bdf_init(sl_bdf *b, int order_max, int32_t n, const double *u0, double t0, sl_diag *d);
void sl_bdf_free(sl_bdf *b);

typedef struct sl_bdf_step {
  int order;     /* of the scheme used for this step */
  int estimated; /* whether an error estimate is available */
  double h;
  double mass_coef;  /* du/dt ~ mass_coef u_{n+1} + history */
  double err_factor; /* C_c / (C_c + C_p) */
} sl_bdf_step;

/* Prepares a step of size h: the coefficients, history[n] and the
 * predictor[n] (the initial guess of the nonlinear solve). */
void sl_bdf_prepare(const sl_bdf *b, double h, sl_bdf_step *s, double *history, double *predictor);

/* The scaled error of the step: max over i < n_err of
 *   err_factor |u_i - P_i| / (rtol max(|u|_inf, scale))
 * where the max norm runs over the same entries; accept when <= 1. 0 when
 * the step has no estimate. */
double sl_bdf_error(const sl_bdf_step *s, const double *u, const double *predictor, int32_t n_err, double rtol,
                    double scale);

/* The next step after a step of size h with scaled error err (accepted or
 * not): h * clamp(0.9 err^(-1/(order+1)), shrink_min, grow_max), further
 * limited for BDF2 to omega <= 2 (zero-stable below 1 + sqrt 2). */
double sl_bdf_next_h(const sl_bdf_step *s, double err);

/* The step from t towards a time t_stop it must land on (an output time, the end) with the proposal h: h; or the
 * rest t_stop - t when it is within 1.05 h (*landing = 1); or, adaptive, half the rest when the rest is below 2 h
 * (*landing = 1), so that the approach is two equal steps of at least h / 2 each, not h and a sliver. eps: a step
 * ending within eps of t_stop keeps its length. */
double sl_bdf_landing_step(double t, double h, double t_stop, double eps, int adaptive, int *landing);
/* The proposal after a landing step hh that had the proposal h and the controller's h_next: h, but at most
 * max(h_next, 2 hh), so that the step after a landing is at most twice it (variable-step BDF2 is zero-stable
 * for step ratios below 1 + sqrt(2): Grigorieff 1983, Numer. Math. 42:359). */
double sl_bdf_after_landing(double h, double hh, double h_next);

/* Accepts u as u_{n+1}: shifts the history, t += h. */
void sl_bdf_accept(sl_bdf *b, const sl_bdf_step *s, const double *u);

/* ---- step-size controller ----------------------------------------------------
 *
 * A digital filter on the scaled error estimates (Soderlind 2003, ACM TOMS
 * 29:1, "Digital filters in adaptive time-stepping", the H211 family):
 *   h_{n+1} / h_n = (q / e_n)^(b1/k) (q / e_{n-1})^(b2/k) (h_n / h_{n-1})^(-a2)
 * with e the scaled error of sl_bdf_error (accept when e <= 1), k = order + 1
 * and q the safety factor: the controller aims at q, below the tolerance,
 * so that the error's step-to-step noise does not reject.
 *  - H211PI, b1 = b2 = 1/6 (Soderlind 2003, section 5), the default: a PI
 *    controller whose two equal weights cancel an error that alternates
 *    from step to step (a zero of the filter at z = -1); the mixture scenes'
 *    estimates do (migration_couette's alternate between 0.46 and 0.09 at
 *    the same step, where the PI controller below rejects 19 % of the steps
 *    and H211PI 5 %);
 *  - PI, b1 = 0.7, b2 = -0.4 (Gustafsson 1991, ACM TOMS 17:533): follows a
 *    trend fastest, and damps the elementary controller's oscillation where
 *    the step is set by stability (doubles, is rejected, halves, ...);
 *  - H211b, b1 = b2 = a2 = 1/4: smoother, slower to follow a trend;
 *  - elementary, b1 = 1: h (q/e)^(1/k).
 * Safety q = 0.7. The proposal is limited to [shrink_min, grow_max] of the
 * step, and to no growth right after a rejection. A rejected step (e > 1)
 * is retried elementarily, h (q/e)^(1/k), at least shrink_min and at most
 * 0.9 of its size; a failed nonlinear solve with a quarter of it. The first
 * estimated step, and the first after a rejection or a failure, are
 * elementary (no trend yet). Measured per scene in docs/transient_cost.md.
 *
 * A step rejected again is retried with the exponent its two attempts
 * show, e ~ h^kappa, kappa = log(e1/e2) / log(h1/h2) in [1/2, k], down to
 * a fiftieth of the step: where the history is not smooth (a flow starting
 * from rest, whose past is all zero, so that the relative estimate is
 * err_factor / tol at any h), the error falls like h, not h^k, and the
 * elementary retry would need many rejections to find the step.
 *
 * SLUICE_STEP_TRACE=1 in the environment prints every decision on stderr. */
typedef enum sl_bdf_control {
  SL_BDF_CONTROL_H211PI = 0,
  SL_BDF_CONTROL_PI,
  SL_BDF_CONTROL_H211B,
  SL_BDF_CONTROL_ELEMENTARY
} sl_bdf_control;

typedef struct sl_bdf_controller {
  double b1, b2, a2; /* the filter (see above) */
  double safety;     /* q; default 0.7 */
  double grow_max, shrink_min;
  /* state: the last accepted step's scaled error and step ratio (0: none) */
  double err_prev, ratio_prev;
  int after_reject;      /* the step being taken follows a rejection or a failure */
  double rej_h, rej_err; /* the last rejected attempt of this step (0: none) */
  long accepted, rejected, failed;
} sl_bdf_controller;

/* The filter (see above) and the defaults. */
void sl_bdf_controller_init(sl_bdf_controller *c, sl_bdf_control kind);

/* The state a restart needs to continue as the uninterrupted run does
 * (SL_BDF_CONTROLLER_STATE values). */
enum { SL_BDF_CONTROLLER_STATE = 3 };
void sl_bdf_controller_save(const sl_bdf_controller *c, double *state);
void sl_bdf_controller_restore(sl_bdf_controller *c, const double *state);

/* After an accepted step with scaled error err: the next step. */
double sl_bdf_controller_accept(sl_bdf_controller *c, const sl_bdf_step *s, double err);
/* After a rejected step (err > 1): the step to retry with. */
double sl_bdf_controller_reject(sl_bdf_controller *c, const sl_bdf_step *s, double err);
/* After a failed nonlinear solve: the step to retry with. */
double sl_bdf_controller_fail(sl_bdf_controller *c, const sl_bdf_step *s);

#endif
