/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Closure calls isolated inside the sluice process (docs/trust-plugins.md).
 *
 * Every batched call to a closure's evaluate() goes through
 * sl_guard_evaluate, which
 *  - catches SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT raised inside the
 *    call (sigsetjmp around it; the handler jumps back only when the fault
 *    happened inside a closure call, else the previous disposition acts), so
 *    that the call returns SL_ERR_INTERNAL with the signal named;
 *  - stops a call that does not return within the call time limit
 *    (sl_guard_set_call_time_limit; off by default): a one-shot ITIMER_REAL
 *    whose SIGALRM jumps out of the call;
 *  - turns exit() inside a call into _exit(1) with the closure named (an
 *    atexit hook), so that a closure cannot make a failed run exit 0.
 * A closure that crashed or overran is poisoned: it is not called again.
 *
 * A closure's fatal return (< 0), a crash and an overrun are latched
 * (sl_guard_fatal): the time loop stops the run at once with that message
 * instead of cutting the step as it does for a recoverable failure (> 0).
 *
 * The clock: the time level and step of the solve in progress, which the
 * time loop sets and the binder (point_eval.c) passes to every closure as
 * sl_eval_args.t and .dt. */
#ifndef SLUICE_PLUGIN_GUARD_H
#define SLUICE_PLUGIN_GUARD_H

#include <stddef.h>

#include <sluice/closure.h>

/* Calls desc->evaluate(state, args) under the guard. `label` and `role`
 * name the closure in messages ("drag/ergun", "closure.drag"; role may be
 * NULL). *poisoned is set when the call crashed or overran. Returns the
 * closure's code, or SL_ERR_INTERNAL with args->err->msg saying what
 * happened. */
int sl_guard_evaluate(const sl_closure_desc *desc, const void *state, const sl_eval_args *args, const char *label,
                      const char *role, int *poisoned);

/* The time limit of one batched call in seconds (0: none, the default). */
void sl_guard_set_call_time_limit(double seconds);
double sl_guard_call_time_limit(void);

/* The time level being solved and its step (steady: 0, 0). */
void sl_guard_set_clock(double t, double dt);
void sl_guard_clock(double *t, double *dt);

/* Latches a fatal closure failure (the first one is kept). */
void sl_guard_set_fatal(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* 1 when a fatal closure failure is latched; its message into msg. */
int sl_guard_fatal(char *msg, size_t n);
void sl_guard_clear_fatal(void);

/* For a SIGINT/SIGTERM handler: when the signal arrived inside a closure
 * call, leaves the call (it returns SL_ERR_INTERNAL, "interrupted") and does
 * not return; otherwise returns at once. */
void sl_guard_interrupt(int sig);

/* The signal's name: "SIGSEGV". */
const char *sl_signal_name(int sig);

#endif
