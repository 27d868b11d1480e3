/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/battery.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"
#include "core/plugin/validate.h"

enum { N_STATES = 64, N_THREAD_REPEATS = 50 };

typedef struct battery {
  const sl_closure_desc *desc;
  sl_closure *closure;
  FILE *log;
  sl_battery_result *res;
  char label[128];
} battery;

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static void
report(battery *b, int ok, const char *check, const char *fmt, ...) {
  if (ok) b->res->passed++;
  else b->res->failed++;
  if (!b->log) return;
  fprintf(b->log, "%s %-22s %s", ok ? "ok  " : "FAIL", b->label, check);
  if (fmt) {
    va_list ap;
    va_start(ap, fmt);
    fputs(": ", b->log);
    vfprintf(b->log, fmt, ap);
    va_end(ap);
  }
  fputc('\n', b->log);
}

/* Buffers for one batch: inputs, outputs and derivatives, structure of arrays. */
typedef struct batch {
  int32_t Q, n_in, n_out;
  double *in_data, *out_data, *dout_data;
  const double **in;
  double **out, **dout;
} batch;

static void batch_free(batch *bt) {
  free(bt->in_data);
  free(bt->out_data);
  free(bt->dout_data);
  free(bt->in);
  free(bt->out);
  free(bt->dout);
  memset(bt, 0, sizeof *bt);
}

static int batch_alloc(batch *bt, const sl_closure_desc *c, int32_t Q) {
  memset(bt, 0, sizeof *bt);
  bt->Q = Q;
  bt->n_in = c->n_in;
  bt->n_out = c->n_out;
  size_t ni = (size_t)(c->n_in ? c->n_in : 1), no = (size_t)c->n_out;
  bt->in_data = calloc(ni * (size_t)Q, sizeof(double));
  bt->out_data = calloc(no * (size_t)Q, sizeof(double));
  bt->dout_data = calloc(no * ni * (size_t)Q, sizeof(double));
  bt->in = calloc(ni, sizeof *bt->in);
  bt->out = calloc(no, sizeof *bt->out);
  bt->dout = calloc(no * ni, sizeof *bt->dout);
  if (!bt->in_data || !bt->out_data || !bt->dout_data || !bt->in || !bt->out || !bt->dout) {
    batch_free(bt);
    return -1;
  }
  for (int32_t i = 0; i < c->n_in; ++i) bt->in[i] = bt->in_data + (size_t)i * (size_t)Q;
  for (int32_t k = 0; k < c->n_out; ++k) bt->out[k] = bt->out_data + (size_t)k * (size_t)Q;
  for (int32_t k = 0; k < c->n_out; ++k)
    for (int32_t i = 0; i < c->n_in; ++i)
      bt->dout[k * c->n_in + i] =
          (c->in[i].flags & SL_FIELD_DIFF) ? bt->dout_data + ((size_t)k * ni + (size_t)i) * (size_t)Q : NULL;
  return 0;
}

static double *in_mut(batch *bt, int32_t i) { return (double *)bt->in[i]; }

static void fill_nan(batch *bt) {
  size_t ni = (size_t)(bt->n_in ? bt->n_in : 1);
  for (size_t j = 0; j < (size_t)bt->n_out * (size_t)bt->Q; ++j) bt->out_data[j] = NAN;
  for (size_t j = 0; j < (size_t)bt->n_out * ni * (size_t)bt->Q; ++j) bt->dout_data[j] = NAN;
}

static int eval_batch(const battery *b, batch *bt, int derivs, sl_error *err) {
  sl_eval_args a = {
      .Q = bt->Q, .t = 0.0, .dt = 0.0, .in = bt->in, .out = bt->out, .dout = derivs ? bt->dout : NULL, .err = err};
  err->point = -1;
  err->msg[0] = '\0';
  return b->desc->evaluate(b->closure->state, &a);
}

/* Deterministic pseudo-random numbers in [0, 1). */
static double lcg(unsigned long long *s) {
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

/* A state inside the declared validity range, away from its edges: linear
 * in narrow ranges, logarithmic around the typical value in wide ones. */
static double sample_input(const sl_field_desc *f, unsigned long long *seed) {
  double lo = f->valid_min, hi = f->valid_max, u = lcg(seed);
  if (isfinite(lo) && isfinite(hi) && (lo <= 0 || hi / lo <= 100) && hi - lo < 1e3 * fabs(f->typical) + 1e3) {
    double w = hi - lo;
    return lo + w * (0.05 + 0.9 * u);
  }
  /* Wide range: a decade either side of the typical value, kept inside. */
  double t = f->typical;
  double v = t == 0 ? (isfinite(hi) ? lo + 0.5 * (hi - lo) * u : u) : t * pow(10.0, 2.0 * u - 1.0);
  if (v <= lo) v = lo + 0.5 * (t - lo) * (0.1 + 0.9 * u);
  if (v >= hi) v = hi - 0.5 * (hi - t) * (0.1 + 0.9 * u);
  return v;
}

static void fill_states(const sl_closure_desc *c, batch *bt) {
  unsigned long long seed = 0x5eedULL;
  for (int32_t q = 0; q < bt->Q; ++q)
    for (int32_t i = 0; i < c->n_in; ++i) in_mut(bt, i)[q] = q == 0 ? c->in[i].typical : sample_input(&c->in[i], &seed);
}

static void describe_point(const sl_closure_desc *c, const batch *bt, int32_t q, char *buf, size_t n) {
  size_t used = 0;
  buf[0] = '\0';
  for (int32_t i = 0; i < c->n_in && used < n; ++i)
    used += (size_t)snprintf(buf + used, n - used, "%s%s=%.6g", i ? " " : "", c->in[i].name, bt->in[i][q]);
}

/* 1. Schema sanity was enforced at load; 2. create/destroy and host bounds. */
static void check_schema_and_bounds(battery *b) {
  const sl_closure_desc *c = b->desc;
  sl_diag d;
  /* Loading validated it already; the battery does not rely on how the
   * entry was obtained. */
  int schema_ok = sl_validate_descriptor(c, &d) == 0;
  if (schema_ok)
    report(b, 1, "schema", "%d parameters, %d inputs, %d outputs", (int)c->n_params, (int)c->n_in, (int)c->n_out);
  else report(b, 0, "schema", "%s", d.msg);
  void *params = NULL;
  int refused_all = 1, tried = 0;
  char what[160] = "";
  if (sl_params_new(c, &params, &d) == 0) {
    for (int32_t i = 0; i < c->n_params; ++i) {
      const sl_param_desc *p = &c->params[i];
      if (p->type != SL_PARAM_REAL && p->type != SL_PARAM_INT) continue;
      double outside[2] = {p->max + fmax(1.0, fabs(p->max)), p->min - fmax(1.0, fabs(p->min))};
      for (int s = 0; s < 2; ++s) {
        if (!isfinite(outside[s]) || fabs(outside[s]) > 1e300) continue;
        char text[64];
        snprintf(text, sizeof text, p->type == SL_PARAM_INT ? "%.0f" : "%.17g", outside[s]);
        ++tried;
        if (sl_params_set(c, params, p->name, text, &d) == 0) {
          refused_all = 0;
          snprintf(what, sizeof what, "%s = %s was accepted", p->name, text);
        }
      }
    }
    sl_params_free(params);
  }
  if (refused_all) report(b, 1, "bounds", "%d out-of-range values refused", tried);
  else report(b, 0, "bounds", "%s", what);
}

/* 3. Every output written, with and without derivatives. */
static void check_outputs_written(battery *b, batch *bt) {
  for (int derivs = 0; derivs < 2; ++derivs) {
    fill_states(b->desc, bt);
    fill_nan(bt);
    sl_error err;
    int rc = eval_batch(b, bt, derivs, &err);
    if (rc != 0) {
      report(b, 0, derivs ? "outputs written (derivatives)" : "outputs written",
             "evaluate returned %d inside the validity range (point %d: %s)", rc, (int)err.point, err.msg);
      continue;
    }
    int ok = 1;
    char where[512] = "";
    for (int32_t k = 0; k < bt->n_out && ok; ++k)
      for (int32_t q = 0; q < bt->Q && ok; ++q)
        if (!isfinite(bt->out[k][q])) {
          ok = 0;
          char pt[300];
          describe_point(b->desc, bt, q, pt, sizeof pt);
          snprintf(where, sizeof where, "output '%s' not finite at %s", b->desc->out[k].name, pt);
        }
    if (derivs)
      for (int32_t j = 0; j < bt->n_out * bt->n_in && ok; ++j)
        if (bt->dout[j])
          for (int32_t q = 0; q < bt->Q && ok; ++q)
            if (!isfinite(bt->dout[j][q])) {
              ok = 0;
              snprintf(where, sizeof where, "d%s/d%s not written or not finite at point %d",
                       b->desc->out[j / bt->n_in].name, b->desc->in[j % bt->n_in].name, (int)q);
            }
    const char *check = derivs ? "outputs written (derivatives)" : "outputs written";
    if (ok) report(b, 1, check, "%d states", (int)bt->Q);
    else report(b, 0, check, "%s", where);
  }
}

/* 4. Q = 1 repeated equals one call with Q = N, bit for bit. */
static void check_batch_invariance(battery *b, batch *bt) {
  fill_states(b->desc, bt);
  sl_error err;
  if (eval_batch(b, bt, 1, &err) != 0) {
    report(b, 0, "batch invariance", "evaluate failed: %s", err.msg);
    return;
  }
  batch one;
  if (batch_alloc(&one, b->desc, 1)) {
    report(b, 0, "batch invariance", "out of memory");
    return;
  }
  int ok = 1;
  for (int32_t q = 0; q < bt->Q && ok; ++q) {
    for (int32_t i = 0; i < bt->n_in; ++i) in_mut(&one, i)[0] = bt->in[i][q];
    if (eval_batch(b, &one, 1, &err) != 0) ok = 0;
    for (int32_t k = 0; k < bt->n_out && ok; ++k)
      if (memcmp(&one.out[k][0], &bt->out[k][q], sizeof(double)) != 0) ok = 0;
    for (int32_t j = 0; j < bt->n_out * bt->n_in && ok; ++j)
      if (one.dout[j] && memcmp(&one.dout[j][0], &bt->dout[j][q], sizeof(double)) != 0) ok = 0;
    if (!ok) report(b, 0, "batch invariance", "point %d differs between Q = 1 and Q = %d", (int)q, (int)bt->Q);
  }
  if (ok) report(b, 1, "batch invariance", "Q = 1 x %d equals Q = %d bit for bit", (int)bt->Q, (int)bt->Q);
  batch_free(&one);
}

/* 5. Derivatives against central differences, Richardson-checked so that
 * points at a switch (a kink or a documented jump) are skipped, not failed. */
static void check_derivatives(battery *b, batch *bt) {
  const sl_closure_desc *c = b->desc;
  int n_diff = 0;
  for (int32_t i = 0; i < c->n_in; ++i) n_diff += (c->in[i].flags & SL_FIELD_DIFF) != 0;
  if (n_diff == 0) {
    report(b, 1, "derivatives", "no differentiable inputs");
    return;
  }
  fill_states(c, bt);
  sl_error err;
  if (eval_batch(b, bt, 1, &err) != 0) {
    report(b, 0, "derivatives", "evaluate failed: %s", err.msg);
    return;
  }
  batch st; /* 4 perturbed copies of one point: x+h, x-h, x+h/2, x-h/2 */
  if (batch_alloc(&st, c, 4)) {
    report(b, 0, "derivatives", "out of memory");
    return;
  }
  int checked = 0, skipped = 0, ok = 1;
  double worst = 0;
  char msg[600] = "";
  for (int32_t q = 0; q < bt->Q && ok; ++q) {
    for (int32_t i = 0; i < c->n_in && ok; ++i) {
      if (!(c->in[i].flags & SL_FIELD_DIFF)) continue;
      double x = bt->in[i][q];
      double scale = fabs(c->in[i].typical) > 0 ? fabs(c->in[i].typical) : 1.0;
      double h = 1e-5 * fmax(fabs(x), 1e-2 * scale);
      if (x - 2 * h < c->in[i].valid_min || x + 2 * h > c->in[i].valid_max) {
        ++skipped;
        continue;
      }
      for (int32_t j = 0; j < c->n_in; ++j)
        for (int s = 0; s < 4; ++s) in_mut(&st, j)[s] = bt->in[j][q];
      in_mut(&st, i)[0] = x + h;
      in_mut(&st, i)[1] = x - h;
      in_mut(&st, i)[2] = x + h / 2;
      in_mut(&st, i)[3] = x - h / 2;
      if (eval_batch(b, &st, 0, &err) != 0) {
        ++skipped; /* the stencil crossed an edge of validity */
        continue;
      }
      for (int32_t k = 0; k < c->n_out && ok; ++k) {
        double fd1 = (st.out[k][0] - st.out[k][1]) / (2 * h);
        double fd2 = (st.out[k][2] - st.out[k][3]) / h;
        double a = bt->dout[k * c->n_in + i][q];
        /* Round-off in the differences: a few ulps of the values over h. */
        double fmag = fmax(fmax(fabs(st.out[k][0]), fabs(st.out[k][1])), fabs(bt->out[k][q]));
        double noise = 64.0 * DBL_EPSILON * fmag / h + 1e-300;
        /* A kink or jump inside the stencil: the two differences disagree. */
        if (fabs(fd1 - fd2) > 1e-4 * fabs(fd2) + 2.0 * noise) {
          ++skipped;
          continue;
        }
        double rel = fabs(a - fd2) / fmax(fmax(fabs(a), fabs(fd2)), 1e5 * noise);
        if (rel > worst) worst = rel;
        ++checked;
        if (rel > 1e-5) {
          ok = 0;
          char pt[300];
          describe_point(c, bt, q, pt, sizeof pt);
          snprintf(msg, sizeof msg, "d%s/d%s at %s: closure %.10g, central difference %.10g (relative error %.2e)",
                   c->out[k].name, c->in[i].name, pt, a, fd2, rel);
        }
      }
    }
  }
  batch_free(&st);
  b->res->skipped_points += skipped;
  if (ok && checked == 0) {
    report(b, 0, "derivatives", "no point could be checked (%d skipped)", skipped);
    return;
  }
  if (ok)
    report(b, 1, "derivatives", "%d checks, worst relative error %.1e, %d skipped at switches or edges", checked, worst,
           skipped);
  else report(b, 0, "derivatives", "%s", msg);
}

/* 6. Inputs outside the declared validity: the recoverable code naming the
 * point, never a silent NaN. */
static void check_out_of_range(battery *b) {
  const sl_closure_desc *c = b->desc;
  batch bt;
  if (batch_alloc(&bt, c, 3)) {
    report(b, 0, "outside validity", "out of memory");
    return;
  }
  int tried = 0, ok = 1;
  char msg[400] = "";
  for (int32_t i = 0; i < c->n_in && ok; ++i) {
    double bad[3] = {NAN, c->in[i].valid_max + fmax(1.0, fabs(c->in[i].valid_max)),
                     c->in[i].valid_min - fmax(1.0, fabs(c->in[i].valid_min))};
    for (int s = 0; s < 3 && ok; ++s) {
      if (s > 0 && (!isfinite(bad[s]) || fabs(bad[s]) > 1e300)) continue;
      for (int32_t j = 0; j < c->n_in; ++j)
        for (int q = 0; q < 3; ++q) in_mut(&bt, j)[q] = c->in[j].typical;
      in_mut(&bt, i)[1] = bad[s];
      fill_nan(&bt);
      sl_error err;
      int rc = eval_batch(b, &bt, 1, &err);
      ++tried;
      if (rc <= 0 || err.point != 1 || !err.msg[0]) {
        ok = 0;
        snprintf(msg, sizeof msg, "%s = %g at point 1: returned %d, point %d, message '%s'", c->in[i].name, bad[s], rc,
                 (int)err.point, err.msg);
      }
    }
  }
  batch_free(&bt);
  if (ok) report(b, 1, "outside validity", "%d bad inputs refused with the point named", tried);
  else report(b, 0, "outside validity", "%s", msg);
}

/* 7. Reference values from the literature. */
static void check_reference_values(battery *b) {
  const sl_closure_desc *c = b->desc;
  if (c->n_checks == 0) {
    report(b, 1, "reference values", "none declared");
    return;
  }
  batch bt;
  if (batch_alloc(&bt, c, 1)) {
    report(b, 0, "reference values", "out of memory");
    return;
  }
  int ok = 1;
  char msg[600] = "";
  double worst = 0;
  for (int32_t n = 0; n < c->n_checks && ok; ++n) {
    const sl_check_point *cp = &c->checks[n];
    for (int32_t i = 0; i < c->n_in; ++i) in_mut(&bt, i)[0] = cp->in[i];
    sl_error err;
    int rc = eval_batch(b, &bt, 0, &err);
    double got = bt.out[cp->out][0];
    double rel = fabs(got - cp->expected) / fmax(fabs(cp->expected), 1e-300);
    if (rel > worst) worst = rel;
    if (rc != 0 || !(rel <= cp->rtol)) {
      ok = 0;
      snprintf(msg, sizeof msg, "%s = %.10g, expected %.10g +- %g relative (%s)", c->out[cp->out].name, got,
               cp->expected, cp->rtol, cp->source);
    }
  }
  batch_free(&bt);
  if (ok) report(b, 1, "reference values", "%d values, worst relative deviation %.1e", (int)c->n_checks, worst);
  else report(b, 0, "reference values", "%s", msg);
}

/* 8. Concurrent evaluate calls on one state. */
typedef struct thread_job {
  const battery *b;
  batch bt;
  int failed;
} thread_job;

static void *thread_main(void *arg) {
  thread_job *job = arg;
  sl_error err;
  for (int r = 0; r < N_THREAD_REPEATS; ++r)
    if (eval_batch(job->b, &job->bt, 1, &err) != 0) job->failed = 1;
  return NULL;
}

static void check_concurrency(battery *b, batch *ref) {
  fill_states(b->desc, ref);
  sl_error err;
  if (eval_batch(b, ref, 1, &err) != 0) {
    report(b, 0, "concurrent evaluation", "evaluate failed: %s", err.msg);
    return;
  }
  thread_job jobs[2];
  memset(jobs, 0, sizeof jobs);
  pthread_t th[2];
  int started = 0, ok = 1;
  for (int t = 0; t < 2; ++t) {
    jobs[t].b = b;
    if (batch_alloc(&jobs[t].bt, b->desc, ref->Q)) {
      ok = 0;
      break;
    }
    fill_states(b->desc, &jobs[t].bt);
  }
  for (int t = 0; t < 2 && ok; ++t) {
    if (pthread_create(&th[t], NULL, thread_main, &jobs[t]) != 0) ok = 0;
    else ++started;
  }
  for (int t = 0; t < started; ++t) pthread_join(th[t], NULL);
  for (int t = 0; t < 2 && ok; ++t) {
    if (jobs[t].failed) ok = 0;
    for (int32_t k = 0; k < ref->n_out && ok; ++k)
      if (memcmp(jobs[t].bt.out[k], ref->out[k], (size_t)ref->Q * sizeof(double)) != 0) ok = 0;
  }
  for (int t = 0; t < 2; ++t) batch_free(&jobs[t].bt);
  if (ok) report(b, 1, "concurrent evaluation", "2 threads x %d calls agree with the serial result", N_THREAD_REPEATS);
  else
    report(b, 0, "concurrent evaluation", "results differ between 2 threads x %d calls and the serial result",
           N_THREAD_REPEATS);
}

void sl_battery_run(const sl_closure_entry *entry, FILE *log, sl_battery_result *res) {
  battery b = {.desc = entry->desc, .log = log, .res = res};
  sl_closure_label(entry->desc, b.label, sizeof b.label);
  void *params;
  sl_diag d;
#define SL_STARTING(what) \
  if (res->progress) res->progress(res->progress_user, b.label, what)
  SL_STARTING("create with defaults");
  if (sl_params_new(entry->desc, &params, &d) || sl_closure_create(entry, params, &b.closure, &d)) {
    report(&b, 0, "create with defaults", "%s", d.msg);
    return;
  }
  report(&b, 1, "create with defaults", NULL);
  batch bt;
  if (batch_alloc(&bt, entry->desc, N_STATES)) {
    report(&b, 0, "allocation", "out of memory");
    sl_closure_destroy(b.closure);
    return;
  }
  SL_STARTING("schema and bounds");
  check_schema_and_bounds(&b);
  SL_STARTING("outputs written");
  check_outputs_written(&b, &bt);
  SL_STARTING("batch invariance");
  check_batch_invariance(&b, &bt);
  SL_STARTING("derivatives");
  check_derivatives(&b, &bt);
  SL_STARTING("out of range");
  check_out_of_range(&b);
  SL_STARTING("reference values");
  check_reference_values(&b);
  SL_STARTING("concurrency");
  check_concurrency(&b, &bt);
  batch_free(&bt);
  SL_STARTING("destroy");
  sl_closure_destroy(b.closure);
#undef SL_STARTING
}
