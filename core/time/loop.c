/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The steady, adaptive BDF and fixed-step loops (loop.h). */
#include "core/time/loop.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/plugin/guard.h"

static double wall_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

enum { MAX_ARRAYS = 24 };

int sl_time_loop_init(sl_time_loop *L, const sl_model_info *info, const sl_time_config *tc, sl_diag *d) {
  memset(L, 0, sizeof *L);
  L->info = info, L->tc = tc;
  L->h = tc->dt;
  if (info->integrator != SL_INTEGRATE_BDF) return 0;
  sl_bdf_controller_init(&L->ctl, (sl_bdf_control)tc->controller);
  int order = tc->scheme == SL_SCHEME_STEADY ? 1 : tc->scheme;
  return sl_bdf_init(&L->bdf, order, info->n, info->u, 0.0, d);
}

void sl_time_loop_free(sl_time_loop *L) {
  if (L->info && L->info->integrator == SL_INTEGRATE_BDF) sl_bdf_free(&L->bdf);
}

static const char *const history_names[3] = {"u", "u_prev", "u_prev2"};

static long ck_int(const sl_checkpoint *ck, const char *name, long def) {
  for (int k = 0; k < ck->n_ints; ++k)
    if (strcmp(ck->int_names[k], name) == 0) return (long)ck->ints[k];
  return def;
}

int sl_time_loop_restore(sl_time_loop *L, const sl_checkpoint *ck, sl_diag *d) {
  const sl_model_info *info = L->info;
  L->restarted = 1;
  L->rejected = ck_int(ck, "rejected", 0);
  if (info->integrator == SL_INTEGRATE_BDF) {
    int32_t n = info->n;
    long np = L->tc->scheme == SL_SCHEME_STEADY ? 1 : ck_int(ck, "n_past", 1);
    for (int k = 0; k < np && k < 3; ++k) {
      const sl_checkpoint_array *a = sl_checkpoint_find(ck, history_names[k]);
      if (!a || a->n != n)
        return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint's '%s' has %lld values, the scene %d unknowns",
                           history_names[k], a ? (long long)a->n : 0LL, (int)n);
      memcpy(L->bdf.past[k], a->data, (size_t)n * sizeof(double));
    }
    memcpy(info->u, L->bdf.past[0], (size_t)n * sizeof(double));
    if (L->tc->scheme == SL_SCHEME_STEADY) return 0; /* a steady solve starts from the state */
    const sl_checkpoint_array *hp = sl_checkpoint_find(ck, "h_past");
    if (hp && hp->n == 2) L->bdf.h_past[0] = hp->data[0], L->bdf.h_past[1] = hp->data[1];
    const sl_checkpoint_array *sc = sl_checkpoint_find(ck, "step_control"); /* steps go on as the run's did */
    if (sc && sc->n == SL_BDF_CONTROLLER_STATE) sl_bdf_controller_restore(&L->ctl, sc->data);
    L->bdf.n_past = (int)np, L->bdf.t = ck->time;
  }
  L->t = ck->time, L->h = ck->dt, L->step = (long)ck->step;
  return 0;
}

/* The state at t: the model's fields and scalars, then the checkpoint (the
 * model's arrays and the loop's). */
static int write_state(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, double t, const double *u,
                       double dt_next, const sl_bdf *history, sl_run_result *res, sl_diag *d) {
  double w0 = wall_now(), c0 = cpu_now();
  int rc = sl_output_begin_step(out, t, d);
  if (!rc) rc = ops->write(self, out, t, u, d);
  if (!rc) rc = sl_output_end_step(out, d);
  if (!rc) {
    sl_checkpoint_array arr[MAX_ARRAYS];
    int na = ops->checkpoint ? ops->checkpoint(self, arr, MAX_ARRAYS - 5) : 0;
    double ctl[SL_BDF_CONTROLLER_STATE];
    sl_checkpoint ck = {.time = t, .dt = dt_next, .step = L->step};
    if (history) {
      for (int k = 0; k < history->n_past; ++k) {
        snprintf(arr[na].name, sizeof arr[na].name, "%s", history_names[k]);
        arr[na].n = history->n, arr[na].data = history->past[k];
        ++na;
      }
      snprintf(arr[na].name, sizeof arr[na].name, "h_past");
      arr[na].n = 2, arr[na].data = history->h_past, ++na;
      sl_bdf_controller_save(&L->ctl, ctl);
      snprintf(arr[na].name, sizeof arr[na].name, "step_control");
      arr[na].n = SL_BDF_CONTROLLER_STATE, arr[na].data = ctl, ++na;
      snprintf(ck.int_names[ck.n_ints], SL_CHECKPOINT_NAME_MAX, "n_past");
      ck.ints[ck.n_ints++] = history->n_past;
    }
    snprintf(ck.int_names[ck.n_ints], SL_CHECKPOINT_NAME_MAX, "rejected");
    ck.ints[ck.n_ints++] = L->rejected;
    ck.n_arrays = na, ck.arrays = arr;
    rc = sl_output_write_checkpoint(out, &ck, d);
  }
  if (!rc) res->saved_time = t, res->saved_time_valid = 1;
  res->output += wall_now() - w0;
  res->cpu_output += cpu_now() - c0;
  return rc;
}

/* ---- steady ------------------------------------------------------------------------------ */

static int run_steady(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, sl_run_result *res,
                      sl_diag *d) {
  double *u = L->info->u;
  long steps = 0, its = 0;
  sl_guard_set_clock(0.0, 0.0);
  int rc = ops->steady(self, u, &steps, &its, d);
  char fatal[1024];
  if (sl_guard_fatal(fatal, sizeof fatal)) rc = sl_diag_set(d, SL_EFAILED, "%s", fatal); /* never retried */
  L->step = res->steps = steps;
  res->nonlinear_iterations += its;
  /* the state reached, also when the solve failed: the history of one state */
  sl_diag d2;
  memcpy(L->bdf.past[0], u, (size_t)L->info->n * sizeof *u);
  L->bdf.n_past = 1;
  int wrc = write_state(L, ops, self, out, 0.0, u, 0.0, &L->bdf, res, rc ? &d2 : d);
  if (!rc) rc = wrc;
  return rc;
}

/* ---- adaptive BDF ------------------------------------------------------------------------------- */

static const char *const limits[] = {"error estimate", "nonlinear convergence", "dt_max", "end or output time",
                                     "fixed dt",       "solids transport"};
enum { N_LIMITS = 6 };

static int run_bdf(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, const sl_run_opts *o,
                   sl_run_result *res, sl_diag *d) {
  const sl_time_config *tc = L->tc;
  const sl_model_info *info = L->info;
  sl_bdf *b = &L->bdf;
  int32_t n = info->n;
  int rc = 0;
  double *hist = malloc((size_t)n * sizeof *hist), *pred = malloc((size_t)n * sizeof *pred);
  double *trial = malloc((size_t)n * sizeof *trial), *rate = ops->complete ? malloc((size_t)n * sizeof *rate) : NULL;
  if (!hist || !pred || !trial || (ops->complete && !rate)) {
    rc = sl_diag_set(d, SL_ENOMEM, "out of memory for %d unknowns", (int)n);
    goto out;
  }
  double h = L->h;
  long step = L->step;
  int next_out = 1;
  if (L->restarted) {
    if (tc->every > 0) next_out = (int)floor(b->t / tc->every + 1e-9) + 1;
  } else if ((rc = write_state(L, ops, self, out, 0.0, b->past[0], h, b, res, d))) {
    goto out;
  }
  res->t_start = b->t;
  long limit_count[N_LIMITS] = {0};
  const double eps_t = 1e-12 * fmax(1.0, tc->end);
  long steps_here = 0;
  while (b->t < tc->end - eps_t) {
    if (o->interrupt && *o->interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "interrupted at t = %.6g after %ld steps", b->t, step);
      break;
    }
    if (steps_here >= tc->max_steps) break;
    int limit = tc->adaptive ? 0 : 4;
    double hh = h;
    /* land on the end and on every output time (a step within 5 % of one is stretched to it) */
    double t_stop = tc->end;
    if (tc->every > 0 && next_out * tc->every < t_stop) t_stop = next_out * tc->every;
    /* a step that ends there up to round-off keeps its length, so that a constant-coefficient matrix stays
       bitwise the same and is not factorised again */
    int landing;
    hh = sl_bdf_landing_step(b->t, hh, t_stop, eps_t, tc->adaptive, &landing);
    if (landing) limit = 3;
    sl_bdf_step s;
    sl_bdf_prepare(b, hh, &s, hist, pred);
    memcpy(trial, pred, (size_t)n * sizeof *trial);
    int writes = tc->every > 0 ? b->t + hh >= next_out * tc->every - eps_t : 0;
    writes |= b->t + hh >= tc->end - eps_t || steps_here + 1 >= tc->max_steps;
    sl_step st = {.t = b->t,
                  .dt = hh,
                  .mass_coef = s.mass_coef,
                  .history = hist,
                  .predictor = pred,
                  .u = trial,
                  .state = b->past[0],
                  .writes = writes};
    sl_diag dn;
    sl_guard_set_clock(b->t + hh, hh); /* the closures see the time level being solved */
    int its = 0, nrc = ops->step(self, &st, &its, &dn);
    res->nonlinear_iterations += its;
    double err = 0.0;
    if (nrc == 0 && tc->adaptive)
      err = fmax(sl_bdf_error(&s, trial, pred, info->n_err, tc->tolerance, 1e-12), st.error);
    if (nrc == 0 && tc->adaptive && s.estimated && getenv("SLUICE_STEP_TRACE")) {
      int32_t im = 0; /* where the BDF estimate is largest: the unknown, its value and its prediction */
      for (int32_t i = 1; i < info->n_err; ++i)
        if (fabs(trial[i] - pred[i]) > fabs(trial[im] - pred[im])) im = i;
      fprintf(stderr, "  t %.6g: BDF estimate largest at unknown %d of %d: %.4g predicted %.4g; model estimate %.3g\n",
              b->t, (int)im, (int)info->n_err, trial[im], pred[im], st.error);
    }
    int coupled_failed = 0;
    if (nrc == 0 && err <= 1.0 && ops->complete) {
      for (int32_t i = 0; i < n; ++i) rate[i] = s.mass_coef * trial[i] + hist[i]; /* the BDF du/dt at t + hh */
      st.dudt = rate;
      coupled_failed = (nrc = ops->complete(self, &st, &dn)) != 0;
    }
    char fatal[1024];
    if (sl_guard_fatal(fatal, sizeof fatal)) { /* a closure's fatal failure is not retried with a smaller step */
      rc = sl_diag_set(d, SL_EFAILED, "at t = %.6g: %s", b->t, fatal);
      break;
    }
    if (nrc != 0 || err > 1.0) {
      L->rejected++;
      h = nrc ? sl_bdf_controller_fail(&L->ctl, &s) : sl_bdf_controller_reject(&L->ctl, &s, err);
      limit_count[coupled_failed ? 5 : nrc ? 1 : 0]++;
      res->rejected_by[coupled_failed ? 3 : nrc ? 2 : err == st.error && st.error > 1.0 ? 1 : 0]++;
      if (nrc < 0) {
        rc = sl_diag_set(d, -nrc, "%s", dn.msg);
        break;
      }
      if (h < tc->dt_min) {
        double umax = 0.0; /* a state growing without bound shows here */
        for (int32_t i = 0; i < info->n_err; ++i) umax = fmax(umax, fabs(b->past[0][i]));
        rc = sl_diag_set(d, SL_EFAILED,
                         "step rejected at t = %.6g down to dt = %.3g < dt_min = %.3g: %s (largest %s of the last "
                         "accepted step %.3g)",
                         b->t, h, tc->dt_min, nrc ? dn.msg : "the error estimate stays above the tolerance",
                         info->state_name ? info->state_name : "value", umax);
        break;
      }
      continue;
    }
    sl_bdf_accept(b, &s, trial);
    if (fabs(b->t - t_stop) <= eps_t) b->t = t_stop; /* on the output time or the end exactly, as above */
    if (ops->accept) {
      int steady = 0;
      ops->accept(self, &st, &steady);
    }
    ++step, ++steps_here;
    L->step = step;
    double h_next = tc->adaptive ? sl_bdf_controller_accept(&L->ctl, &s, err) : tc->dt;
    if (h_next > tc->dt_max) h_next = tc->dt_max, limit = 2;
    if (limit != 3) h = h_next; /* a step shortened to hit the end keeps the proposal, */
    else if (tc->adaptive) h = sl_bdf_after_landing(h, hh, h_next); /* up to twice the step it took */
    limit_count[limit]++;
    if (o->monitor) {
      if (ops->stats) ops->stats(self, res, &res->model); /* what a monitor may read of the run so far */
      o->monitor(o->monitor_user, b->t, hh, step, its);
    }
    int due = tc->every > 0 ? b->t >= next_out * tc->every - eps_t : 0;
    int last = b->t >= tc->end - eps_t || steps_here >= tc->max_steps;
    if (due || last) {
      while (tc->every > 0 && b->t >= next_out * tc->every - eps_t) ++next_out;
      if ((rc = write_state(L, ops, self, out, b->t, b->past[0], h, b, res, d))) break;
    }
  }
  L->h = h;
  res->steps = step;
  res->t_reached = b->t;
  if (!rc && b->t >= tc->end - eps_t)
    snprintf(res->stop_reason, sizeof res->stop_reason, "reached the end time t = %g", tc->end);
  else if (!rc)
    snprintf(res->stop_reason, sizeof res->stop_reason,
             "stopped after max_steps = %ld steps at t = %.6g, before the end time %g (checkpoint saved)",
             tc->max_steps, b->t, tc->end);
  long best = 0;
  for (int k = 0; k < N_LIMITS; ++k)
    if (limit_count[k] > best) best = limit_count[k], res->step_limit = limits[k];
  if ((rc == SL_EFAILED || rc == SL_ENOMEM) && !(res->saved_time_valid && res->saved_time == b->t)) {
    sl_diag d2; /* keep the last accepted state (unless it is the one just written) */
    write_state(L, ops, self, out, b->t, b->past[0], h, b, res, &d2);
  }
out:
  free(hist), free(pred), free(trial), free(rate);
  return rc;
}

/* ---- fixed steps ------------------------------------------------------------------------------------ */

static double clock_cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

static int run_fixed(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, const sl_run_opts *o,
                     sl_run_result *res, sl_diag *d) {
  const sl_time_config *tc = L->tc;
  double end = tc->end, dt_cfg = tc->dt, every = tc->every;
  double t = L->t, h = L->h;
  long step = L->step, steps_here = 0;
  int rc = 0;
  if (!L->restarted && (rc = write_state(L, ops, self, out, 0.0, NULL, h, NULL, res, d))) return rc;
  res->t_start = t;
  int next_out = every > 0 ? (int)floor(t / every + 1e-9) + 1 : 0;
  const double eps_t = 1e-12 * fmax(1.0, end);
  int steady = 0;
  long n_cut = 0;
  while (t < end - eps_t && !steady && steps_here < tc->max_steps) {
    if (o->interrupt && *o->interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "interrupted at t = %.6g after %ld steps", t, step);
      break;
    }
    /* land on the next output time, without a sliver of a step before it */
    double t_stop = end;
    if (every > 0 && next_out * every < t_stop) t_stop = next_out * every;
    double hh = h;
    if (fabs(t + hh - t_stop) > eps_t && (t + hh > t_stop || t + 1.05 * hh > t_stop)) hh = t_stop - t;
    double c0 = clock_cpu();
    sl_diag ds;
    int writes = every > 0 ? t + hh >= next_out * every - eps_t : 0;
    writes |= t + hh >= end - eps_t || steps_here + 1 >= tc->max_steps;
    sl_step st = {.t = t, .dt = hh, .writes = writes};
    sl_guard_set_clock(t + hh, hh);
    int its = 0, src = ops->step(self, &st, &its, &ds);
    res->solve += clock_cpu() - c0;
    res->nonlinear_iterations += its;
    char fatal[1024];
    if (sl_guard_fatal(fatal, sizeof fatal)) { /* not retried with a smaller step */
      rc = sl_diag_set(d, SL_EFAILED, "at t = %.6g: %s", t, fatal);
      break;
    }
    if (src < 0) {
      rc = sl_diag_set(d, -src, "at t = %.6g: %s", t, ds.msg);
      break;
    }
    if (src) {
      L->rejected++, ++n_cut, res->rejected_by[2]++;
      h = 0.25 * hh;
      if (h < tc->dt_min) {
        rc = sl_diag_set(d, SL_EFAILED, "step rejected at t = %.6g down to dt = %.3g < dt_min = %.3g: %s", t, h,
                         tc->dt_min, ds.msg);
        break;
      }
      continue;
    }
    if (ops->accept) ops->accept(self, &st, &steady);
    /* a step that ends on an output time or the end up to round-off ends there exactly: the times written are
       the scene's (60, not 59.99999999999663 after 1200 steps of 0.05) */
    t = fabs(t + hh - t_stop) <= eps_t ? t_stop : t + hh;
    ++step, ++steps_here;
    L->t = t, L->step = step;
    if (h < dt_cfg) h = fmin(dt_cfg, 2.0 * h);
    if (o->monitor) {
      if (ops->stats) ops->stats(self, res, &res->model);
      o->monitor(o->monitor_user, t, hh, step, its);
    }
    int due = every > 0 ? t >= next_out * every - eps_t : 0;
    if (due || steady || t >= end - eps_t || steps_here >= tc->max_steps) {
      while (every > 0 && t >= next_out * every - eps_t) ++next_out;
      if ((rc = write_state(L, ops, self, out, t, NULL, h, NULL, res, d))) break;
    }
  }
  L->h = h;
  res->steps = step;
  res->t_reached = t;
  res->step_limit = n_cut ? "convergence of the implicit step" : "fixed dt";
  if (!rc && steady)
    snprintf(res->stop_reason, sizeof res->stop_reason, "steady at t = %.6g %s", t,
             L->info->steady_text ? L->info->steady_text : "");
  else if (!rc && t >= end - eps_t)
    snprintf(res->stop_reason, sizeof res->stop_reason, "reached the end time t = %g", end);
  else if (!rc)
    snprintf(res->stop_reason, sizeof res->stop_reason,
             "stopped after max_steps = %ld steps at t = %.6g, before the end time %g (checkpoint saved)",
             tc->max_steps, t, end);
  if ((rc == SL_EFAILED || rc == SL_ENOMEM) && !(res->saved_time_valid && res->saved_time == t)) {
    sl_diag d2; /* keep the last accepted state (unless it is the one just written) */
    write_state(L, ops, self, out, t, NULL, h, NULL, res, &d2);
  }
  return rc;
}

int sl_time_loop_run(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, const sl_run_opts *o,
                     sl_run_result *res, sl_diag *d) {
  res->rejected_steps = L->rejected;
  sl_guard_clear_fatal();
  sl_guard_set_clock(L->info->integrator == SL_INTEGRATE_BDF ? L->bdf.t : L->t, 0.0); /* until the first step */
  int rc;
  if (L->tc->scheme == SL_SCHEME_STEADY && L->info->has_steady) rc = run_steady(L, ops, self, out, res, d);
  else if (L->info->integrator == SL_INTEGRATE_BDF) rc = run_bdf(L, ops, self, out, o, res, d);
  else rc = run_fixed(L, ops, self, out, o, res, d);
  res->rejected_steps = L->rejected;
  res->t_end = L->tc->end;
  return rc;
}
