/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What a run shows while it runs and when it ends: a one-line progress
 * display redrawn in place, the one-line run summary, and the clocks to time
 * the run with. */
#ifndef SLUICE_CLI_PROGRESS_H
#define SLUICE_CLI_PROGRESS_H

#include <stddef.h>
#include <stdio.h>

/* Seconds, NaN when the clock cannot be read. */
double sl_wall_seconds(void); /* monotonic, arbitrary origin */
double sl_cpu_seconds(void);  /* CPU time of the process, all its threads */

typedef struct sl_progress {
  FILE *f;
  int enabled;
  double t_start, t_end;    /* simulated time span of the run */
  double (*now)(void);      /* the wall clock: sl_wall_seconds; tests may replace it */
  double last_draw;         /* wall time of the last redraw */
  double rate;              /* simulated seconds per wall second, smoothed; 0 until known */
  double mark_t, mark_wall; /* simulated and wall time where the current rate sample began */
  int width;                /* characters of the line on screen, to blank them */
  int lines;                /* one line per interval (a log, not a terminal) instead of a line redrawn in place */
  double interval;          /* seconds between lines of the log */
  double started;           /* wall time of the first update */
} sl_progress;

/* On a terminal, a line redrawn in place; otherwise (a log file, a pipe) one
 * line every 10 s of wall time (SLUICE_PROGRESS_EVERY=seconds). SLUICE_PROGRESS=0
 * turns it off, =1 forces the line in place, =lines the log lines. */
void sl_progress_begin(sl_progress *p, FILE *f, double t_start, double t_end);
/* After each step: redraws the line with '\r', at most 10 times per wall
 * second. Shows t, dt, the step, the nonlinear iterations of that step and
 * the wall time left (from the simulated-time rate; "--" until known). A
 * write error disables the display; the run goes on. */
void sl_progress_update(sl_progress *p, double t, double dt, long step, int nonlinear_iterations);
/* A nonlinear iteration of a steady solve (a run with no time span): on a
 * terminal the line in place, otherwise one line per iteration, with the
 * continuation stage when there are stages (n_stages > 0). */
void sl_progress_iteration(sl_progress *p, long stage, long n_stages, int iteration, int picard, double correction,
                           double residual, double terms);
/* Clears the line (call before printing anything else). */
void sl_progress_end(sl_progress *p);

typedef struct sl_run_summary {
  long steps; /* accepted steps */
  long rejected_steps;
  long nonlinear_iterations;        /* all steps, rejected ones included */
  const char *nonlinear_name;       /* e.g. "Newton", "Picard"; NULL: "nonlinear" */
  double wall_seconds, cpu_seconds; /* the whole run */
  /* wall seconds per phase; the rest of wall_seconds is reported as "other" */
  double assembly, factorisation, solve, output;
  const char *step_limit; /* what limited the step most often, or NULL */
} sl_run_summary;

/* One line, no newline, e.g. "sluice: 120 steps (3 rejected), 410 Newton
 * iterations; CPU 12.3 s, wall 12.5 s (wall: assembly 1.2 s (10 %), ...,
 * other 0.6 s (5 %)); step limited by error estimate": the phases are
 * wall-clock times, their percentages of the wall time, rounded so that
 * they add up to 100. Truncated to fit len. */
void sl_run_summary_format(const sl_run_summary *s, char *buf, size_t len);

#endif
