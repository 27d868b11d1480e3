/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Progress line, run summary and clocks (see progress.h). */
#include "core/cli/progress.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

double sl_wall_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double sl_cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- progress line ------------------------------------------------------- */

enum { LINE_MAX_CHARS = 160 };
#define REDRAW_INTERVAL 0.1 /* s: at most 10 redraws per second */
#define RATE_SAMPLE 0.5     /* s: shortest interval a rate is measured over */
#define RATE_MEMORY 5.0     /* s: time constant of the rate's smoothing */
#define LOG_INTERVAL 10.0   /* s: between lines of the log when the output is not a terminal */

void sl_progress_begin(sl_progress *p, FILE *f, double t_start, double t_end) {
  memset(p, 0, sizeof *p);
  p->f = f;
  p->t_start = t_start, p->t_end = t_end;
  p->now = sl_wall_seconds;
  p->last_draw = -INFINITY;
  p->mark_t = p->mark_wall = NAN;
  p->started = NAN;
  const char *env = getenv("SLUICE_PROGRESS"), *every = getenv("SLUICE_PROGRESS_EVERY");
  p->interval = LOG_INTERVAL;
  if (every) {
    char *end;
    double v = strtod(every, &end);
    if (end != every && *end == '\0' && v > 0 && isfinite(v)) p->interval = v;
  }
  if (!f) p->enabled = 0;
  else if (env && strcmp(env, "1") == 0) p->enabled = 1;
  else if (env && strcmp(env, "0") == 0) p->enabled = 0;
  else if (env && strcmp(env, "lines") == 0) p->enabled = p->lines = 1;
  else p->enabled = 1, p->lines = isatty(fileno(f)) != 1;
  if (p->lines) p->last_draw = NAN; /* the first line after one interval */
}

/* "--", "42 s", "3 min 05 s", "2 h 07 min", "3 d 04 h". */
static void format_left(double s, char *buf, size_t len) {
  if (!isfinite(s) || s < 0 || s > 1e9) {
    snprintf(buf, len, "--");
    return;
  }
  long v = lround(s);
  if (v < 60) snprintf(buf, len, "%ld s", v);
  else if (v < 3600) snprintf(buf, len, "%ld min %02ld s", v / 60, v % 60);
  else if (v < 86400) snprintf(buf, len, "%ld h %02ld min", v / 3600, v % 3600 / 60);
  else snprintf(buf, len, "%ld d %02ld h", v / 86400, v % 86400 / 3600);
}

/* The rate is measured over intervals of at least RATE_SAMPLE and smoothed
 * exponentially, so it follows a run whose step size changes. */
static void sample_rate(sl_progress *p, double t, double now) {
  if (isnan(p->mark_wall)) {
    p->mark_t = t, p->mark_wall = now;
    return;
  }
  double dw = now - p->mark_wall;
  if (!(dw >= RATE_SAMPLE)) return;
  double r = (t - p->mark_t) / dw;
  p->rate = p->rate > 0 ? p->rate + (1.0 - exp(-dw / RATE_MEMORY)) * (r - p->rate) : r;
  p->mark_t = t, p->mark_wall = now;
}

/* A line of the log: what the line in place shows, with the wall time spent, on a line of its own. */
static void log_line(sl_progress *p, double t, double dt, long step, int nonlinear_iterations, double now) {
  if (isnan(p->last_draw)) p->last_draw = now;
  if (!(now - p->last_draw >= p->interval)) return;
  p->last_draw = now;
  char left[32], spent[32];
  format_left(now - p->started, spent, sizeof spent);
  double span = p->t_end - p->t_start;
  int ok;
  if (span > 0 && isfinite(span)) {
    format_left(p->rate > 0 ? (p->t_end - t) / p->rate : NAN, left, sizeof left);
    ok = fprintf(p->f, "sluice: t = %.6g of %.6g s (%.1f %%), step %ld, dt %.3g s, %d iterations; %s spent, %s left\n",
                 t, p->t_end, 100.0 * (t - p->t_start) / span, step, dt, nonlinear_iterations, spent, left) >= 0;
  } else {
    ok = fprintf(p->f, "sluice: t = %.6g s, step %ld, dt %.3g s, %d iterations; %s spent\n", t, step, dt,
                 nonlinear_iterations, spent) >= 0;
  }
  if (!ok || fflush(p->f) != 0) p->enabled = 0;
}

void sl_progress_update(sl_progress *p, double t, double dt, long step, int nonlinear_iterations) {
  if (!p->enabled) return;
  double now = p->now();
  if (isnan(p->started)) p->started = now;
  sample_rate(p, t, now);
  if (p->lines) {
    log_line(p, t, dt, step, nonlinear_iterations, now);
    return;
  }
  if (!(now - p->last_draw >= REDRAW_INTERVAL)) return;
  p->last_draw = now;

  char line[LINE_MAX_CHARS], left[32];
  double span = p->t_end - p->t_start;
  int n;
  if (span > 0 && isfinite(span)) {
    format_left(p->rate > 0 ? (p->t_end - t) / p->rate : NAN, left, sizeof left);
    n = snprintf(line, sizeof line, "t %.6g / %.6g s (%.1f %%)  dt %.3g s  step %ld  iter %d  left %s", t, p->t_end,
                 100.0 * (t - p->t_start) / span, dt, step, nonlinear_iterations, left);
  } else { /* no end time to aim at: no fraction, no estimate */
    n = snprintf(line, sizeof line, "t %.6g s  dt %.3g s  step %ld  iter %d", t, dt, step, nonlinear_iterations);
  }
  if (n < 0) return;
  int len = n < (int)sizeof line ? n : (int)sizeof line - 1;
  /* Spaces over what remains of a longer previous line. */
  int ok = fprintf(p->f, "\r%s%*s", line, p->width > len ? p->width - len : 0, "") >= 0 && fflush(p->f) == 0;
  p->width = len;
  if (!ok) p->enabled = 0;
}

void sl_progress_iteration(sl_progress *p, long stage, long n_stages, int iteration, int picard, double correction,
                           double residual, double terms) {
  if (!p->enabled) return;
  double now = p->now();
  if (isnan(p->started)) p->started = now;
  char line[LINE_MAX_CHARS], st[64] = "", spent[32];
  if (n_stages > 0) snprintf(st, sizeof st, "stage %ld of %ld, ", stage, n_stages);
  format_left(now - p->started, spent, sizeof spent);
  int n =
      snprintf(line, sizeof line, "steady: %s%s iteration %d: correction %.3g, residual %.3g (%.3g of its terms)", st,
               picard ? "Picard" : "Newton", iteration, correction, residual, terms > 0 ? residual / terms : 0.0);
  if (n < 0) return;
  int ok;
  if (p->lines) {
    ok = fprintf(p->f, "sluice: %s; %s spent\n", line, spent) >= 0 && fflush(p->f) == 0;
  } else {
    if (!(now - p->last_draw >= REDRAW_INTERVAL)) return;
    p->last_draw = now;
    int len = n < (int)sizeof line ? n : (int)sizeof line - 1;
    ok = fprintf(p->f, "\r%s%*s", line, p->width > len ? p->width - len : 0, "") >= 0 && fflush(p->f) == 0;
    p->width = len;
  }
  if (!ok) p->enabled = 0;
}

void sl_progress_end(sl_progress *p) {
  if (p->enabled && !p->lines && p->width > 0) {
    if (fprintf(p->f, "\r%*s\r", p->width, "") < 0 || fflush(p->f) != 0) p->enabled = 0;
  }
  p->width = 0;
  p->enabled = 0;
}

/* ---- run summary --------------------------------------------------------- */

typedef struct out {
  char *buf;
  size_t len, used; /* used <= len - 1: always terminated */
} out;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void
put(out *o, const char *fmt, ...) {
  if (o->used + 1 >= o->len) return;
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(o->buf + o->used, o->len - o->used, fmt, ap);
  va_end(ap);
  if (n < 0) return;
  o->used = o->used + (size_t)n < o->len ? o->used + (size_t)n : o->len - 1;
}

/* A caller's string, with line breaks and other control characters made
 * blanks: the summary stays one line. */
static void put_text(out *o, const char *s) {
  for (; *s && o->used + 1 < o->len; ++s) {
    o->buf[o->used++] = (unsigned char)*s < 0x20 || *s == 0x7f ? ' ' : *s;
    o->buf[o->used] = '\0';
  }
}

static double nonneg(double v) { return v > 0 && isfinite(v) ? v : 0.0; }

/* Whole percentages of v[0..n-1] adding up to 100: floors, then the points
 * left over go to the largest remainders. */
static void percentages(const double *v, int n, double total, int *pct) {
  int sum = 0;
  double rem[8];
  for (int i = 0; i < n; ++i) {
    double x = 100.0 * v[i] / total;
    pct[i] = (int)floor(x);
    rem[i] = x - pct[i];
    sum += pct[i];
  }
  for (int k = 0; k < n && sum < 100; ++k, ++sum) {
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (rem[i] > rem[best]) best = i;
    ++pct[best];
    rem[best] = -1.0;
  }
}

void sl_run_summary_format(const sl_run_summary *s, char *buf, size_t len) {
  if (!buf || len == 0) return;
  buf[0] = '\0';
  out o = {buf, len, 0};
  const char *nl = s->nonlinear_name ? s->nonlinear_name : "nonlinear";
  put(&o, "sluice: %ld step%s (%ld rejected), %ld ", s->steps, s->steps == 1 ? "" : "s", s->rejected_steps,
      s->nonlinear_iterations);
  put_text(&o, nl);
  put(&o, " iteration%s; CPU %.1f s, wall %.1f s", s->nonlinear_iterations == 1 ? "" : "s", nonneg(s->cpu_seconds),
      nonneg(s->wall_seconds));

  /* the phases are timed by the wall clock: their shares are of the wall time */
  static const char *const names[5] = {"assembly", "factorisation", "solve", "output", "other"};
  double v[5] = {nonneg(s->assembly), nonneg(s->factorisation), nonneg(s->solve), nonneg(s->output), 0.0};
  double parts = v[0] + v[1] + v[2] + v[3];
  v[4] = nonneg(s->wall_seconds) > parts ? nonneg(s->wall_seconds) - parts : 0.0;
  double total = parts + v[4]; /* the wall total, or the parts' sum if the clocks disagree */
  if (total > 0) {
    int pct[5];
    percentages(v, 5, total, pct);
    for (int i = 0; i < 5; ++i) put(&o, "%s%s %.1f s (%d %%)", i ? ", " : " (wall: ", names[i], v[i], pct[i]);
    put(&o, ")");
  }
  if (s->step_limit && *s->step_limit) {
    put(&o, "; step limited by ");
    put_text(&o, s->step_limit);
  }
}
