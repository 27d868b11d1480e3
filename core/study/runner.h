/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One run of a study in a child process (core/study/child.h): the sluice
 * command itself (/proc/self/exe) exec'ed for that one run, so that the
 * child's memory and clocks start from nothing. A crash, a failure or a
 * hang (killed at the timeout) of one run is recorded and the study goes
 * on. The child's stdout and stderr go to a log file; its step counts and
 * message come back through a pipe on file descriptor 3. */
#ifndef SLUICE_BENCH_RUNNER_H
#define SLUICE_BENCH_RUNNER_H

#include <signal.h>
#include <stdio.h>

#include "core/config/ini.h"
#include "core/plugin/registry.h"
#include "core/time/model.h"

typedef enum sl_bench_status {
  SL_RUN_OK,
  SL_RUN_FAILED,      /* the run stopped with exit status 1 (a solve failed, dt below dt_min, ...) */
  SL_RUN_BAD_INPUT,   /* exit status 2 */
  SL_RUN_CRASHED,     /* killed by a signal, or no result */
  SL_RUN_TIMEOUT,     /* killed at the study's timeout */
  SL_RUN_INTERRUPTED, /* Ctrl-C */
  SL_RUN_NOT_RUN
} sl_bench_status;

const char *sl_bench_status_name(sl_bench_status s); /* "ok", "failed", ... */

typedef struct sl_bench_run_result {
  sl_bench_status status;
  int exit_code, signal_number;
  double cpu, wall;   /* seconds: the child's user + system time; wall time from fork to its end */
  double peak_rss_mb; /* ru_maxrss of the child */
  long steps, rejected_steps, nonlinear_iterations;
  double t_reached;
  char message[1024]; /* one line; empty when ok */
} sl_bench_run_result;

enum { SL_BENCH_RESULT_FD = 3 }; /* where the child writes its outcome */

typedef struct sl_bench_run_opts {
  /* for sl_bench_run, in the parent: */
  char *const *argv; /* what the child execs (argv[0] the program): a command that ends in sl_bench_run_here */
  const char *log;   /* the run's stdout and stderr */
  double timeout;    /* wall seconds; then the child is killed */
  volatile sig_atomic_t *interrupt; /* Ctrl-C: the child stops after its step; the parent forwards it, if need be */
  /* for sl_bench_run_here, in the child: */
  const char *scene_path; /* for provenance and messages */
  const char *output;     /* the run's output file */
  const char *sluice_version;
  void (*summary)(FILE *log, const sl_run_result *res, double wall, double cpu); /* the summary line, optional */
} sl_bench_run_opts;

/* Runs one run in a child. Returns 0 with the outcome in r, or -1 when no
 * child could be started (r->message says why). */
int sl_bench_run(const sl_bench_run_opts *o, sl_bench_run_result *r);

/* The run itself, in the child (the exec'd command calls it): runs the
 * scene ini (model from [scene] model) and writes the outcome to result_fd
 * (none when < 0). Returns the exit status: 0, 1 failed, 2 bad input. */
int sl_bench_run_here(sl_ini *ini, const sl_registry *reg, const sl_bench_run_opts *o, int result_fd);
/* A child that could not get as far as running tells the parent so: rc and
 * the message, as the run's outcome. */
void sl_bench_send_failure(int result_fd, int rc, const char *msg);

#endif
