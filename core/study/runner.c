/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A study's runs in child processes (see runner.h). */
#include "core/study/runner.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/models/run.h"
#include "core/study/child.h"

const char *sl_bench_status_name(sl_bench_status s) {
  static const char *const names[] = {"ok", "failed", "bad_input", "crashed", "timeout", "interrupted", "not_run"};
  return s >= SL_RUN_OK && s <= SL_RUN_NOT_RUN ? names[s] : "unknown";
}

/* What the child sends back. */
typedef struct record {
  int rc;
  long steps, rejected, nonlinear;
  double t_reached;
  char msg[1024];
} record;

static double monotonic(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_MONOTONIC, &ts)) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu_now(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The first line of a message, control characters made blanks. */
static void one_line(char *dst, size_t n, const char *src) {
  size_t k = 0;
  for (; src[k] && src[k] != '\n' && k + 1 < n; ++k) dst[k] = (unsigned char)src[k] < 0x20 ? ' ' : src[k];
  dst[k] = '\0';
}

static void write_all(int fd, const void *p, size_t n) {
  const char *c = p;
  while (n > 0) {
    ssize_t w = write(fd, c, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return;
    c += w, n -= (size_t)w;
  }
}

int sl_bench_run_here(sl_ini *ini, const sl_registry *reg, const sl_bench_run_opts *o, int result_fd) {
  record rec;
  memset(&rec, 0, sizeof rec);
  sl_diag d = {{0}};
  sl_run_result res;
  memset(&res, 0, sizeof res);
  double w0 = monotonic(), c0 = cpu_now();
  sl_run_opts ro = {
      .scene_path = o->scene_path, .output = o->output, .sluice_version = o->sluice_version, .interrupt = o->interrupt};
  int rc = sl_model_run(ini, reg, &ro, &res, &d);
  if (o->summary && rc != SL_EBADINPUT) o->summary(stderr, &res, monotonic() - w0, cpu_now() - c0);
  if (rc) fprintf(stderr, "%s\n", d.msg);
  rec.rc = rc, rec.steps = res.steps, rec.rejected = res.rejected_steps, rec.nonlinear = res.nonlinear_iterations;
  rec.t_reached = res.t_reached;
  if (rc) one_line(rec.msg, sizeof rec.msg, d.msg);
  fflush(stdout), fflush(stderr);
  if (result_fd >= 0) write_all(result_fd, &rec, sizeof rec);
  return rc == 0 ? 0 : rc == SL_EBADINPUT ? 2 : 1;
}

void sl_bench_send_failure(int result_fd, int rc, const char *msg) {
  record rec;
  memset(&rec, 0, sizeof rec);
  rec.rc = rc;
  rec.t_reached = NAN;
  one_line(rec.msg, sizeof rec.msg, msg);
  if (result_fd >= 0) write_all(result_fd, &rec, sizeof rec);
}

int sl_bench_run(const sl_bench_run_opts *o, sl_bench_run_result *r) {
  memset(r, 0, sizeof *r);
  r->status = SL_RUN_NOT_RUN;
  r->cpu = r->wall = r->peak_rss_mb = r->t_reached = NAN;
  record rec;
  sl_child_opts co = {.argv = o->argv,
                      .result = &rec,
                      .result_size = sizeof rec,
                      .result_fd = SL_BENCH_RESULT_FD,
                      .out = o->log,
                      .err = o->log,
                      .timeout = o->timeout,
                      .interrupt = o->interrupt};
  sl_child_result cr;
  if (sl_child_run(&co, &cr)) {
    snprintf(r->message, sizeof r->message, "%s", cr.message);
    return -1;
  }
  r->wall = cr.wall, r->cpu = cr.cpu, r->peak_rss_mb = cr.peak_rss_mb;
  r->exit_code = cr.exit_code, r->signal_number = cr.signal_number;
  if (cr.timed_out) {
    r->status = SL_RUN_TIMEOUT;
    snprintf(r->message, sizeof r->message, "killed after %.0f s, the study's timeout ([study] timeout)", o->timeout);
  } else if (!cr.got_result) {
    r->status = SL_RUN_CRASHED;
    if (r->signal_number)
      snprintf(r->message, sizeof r->message, "killed by signal %d (%s)", r->signal_number,
               strsignal(r->signal_number));
    else snprintf(r->message, sizeof r->message, "exited with status %d without a result", r->exit_code);
  } else {
    r->steps = rec.steps, r->rejected_steps = rec.rejected, r->nonlinear_iterations = rec.nonlinear;
    r->t_reached = rec.t_reached;
    rec.msg[sizeof rec.msg - 1] = '\0';
    snprintf(r->message, sizeof r->message, "%s", rec.msg);
    r->status = rec.rc == 0                     ? SL_RUN_OK
                : rec.rc == SL_EBADINPUT        ? SL_RUN_BAD_INPUT
                : o->interrupt && *o->interrupt ? SL_RUN_INTERRUPTED
                                                : SL_RUN_FAILED;
    int expected = rec.rc == 0 ? 0 : rec.rc == SL_EBADINPUT ? 2 : 1;
    if (r->signal_number || r->exit_code != expected) { /* e.g. a sanitizer's report at exit */
      r->status = SL_RUN_CRASHED;
      snprintf(r->message, sizeof r->message, "%s with status %d after its run (see its log)%s%.900s",
               r->signal_number ? "killed" : "exited", r->signal_number ? r->signal_number : r->exit_code,
               rec.msg[0] ? ": " : "", rec.msg);
    }
  }
  return 0;
}
