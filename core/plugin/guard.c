/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/guard.h"

#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

/* The call in progress on this thread: where to jump back to, and who. */
static _Thread_local sigjmp_buf *volatile call_env;
static _Thread_local const char *volatile call_label;
static _Thread_local const char *volatile call_role;
static _Thread_local volatile sig_atomic_t call_signal;

static double time_limit; /* seconds, 0: none */
static double clock_t_now, clock_dt_now;

static char fatal_msg[1024];
static int fatal_set;

static const int fault_signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
enum { N_FAULTS = (int)(sizeof fault_signals / sizeof fault_signals[0]) };
static struct sigaction old_fault[N_FAULTS], old_alarm;
static volatile int installed;

const char *sl_signal_name(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGBUS:
      return "SIGBUS";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGABRT:
      return "SIGABRT";
    case SIGALRM:
      return "SIGALRM";
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGKILL:
      return "SIGKILL";
    case SIGPIPE:
      return "SIGPIPE";
    case SIGTRAP:
      return "SIGTRAP";
    case SIGXCPU:
      return "SIGXCPU";
    case SIGSYS:
      return "SIGSYS";
    default:
      return "a signal";
  }
}

static void on_fault(int sig, siginfo_t *si, void *uc) {
  (void)uc;
  sigjmp_buf *env = call_env;
  if (env) {
    call_signal = sig;
    siglongjmp(*env, 1);
  }
  /* Not inside a closure call: what would have happened without us. */
  for (int k = 0; k < N_FAULTS; ++k)
    if (fault_signals[k] == sig) sigaction(sig, &old_fault[k], NULL);
  /* A fault of an instruction happens again on return, now under the old
     disposition; a signal someone sent is sent again. */
  if (!si || si->si_code <= 0) raise(sig);
}

static void on_alarm(int sig) {
  (void)sig;
  sigjmp_buf *env = call_env;
  if (env) {
    call_signal = SIGALRM;
    siglongjmp(*env, 1);
  }
}

/* exit() called while a closure call is in progress: the closure did it
 * (closure-abi.md forbids it). The run has not finished: never exit 0. */
static void at_exit(void) {
  if (!call_env) return;
  char msg[512];
  const char *role = call_role;
  int n = snprintf(msg, sizeof msg,
                   "sluice: closure %s%s%s%s called exit() inside its evaluation; the run did not finish "
                   "(exit status 1)\n",
                   call_label ? call_label : "?", role ? " [" : "", role ? role : "", role ? "]" : "");
  fflush(stdout);
  if (n > 0) {
    ssize_t w = write(STDERR_FILENO, msg, (size_t)n < sizeof msg ? (size_t)n : sizeof msg - 1);
    (void)w;
  }
  _exit(1);
}

static void install_once(void) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sigemptyset(&sa.sa_mask);
  /* SA_NODEFER: the jump out of the handler leaves the signal unblocked
     without saving the mask at every call (sigsetjmp(env, 0)). */
  sa.sa_flags = SA_SIGINFO | SA_NODEFER;
  sa.sa_sigaction = on_fault;
  for (int k = 0; k < N_FAULTS; ++k) sigaction(fault_signals[k], &sa, &old_fault[k]);
  atexit(at_exit);
  installed = 1;
}

static void install(void) {
  static pthread_once_t once = PTHREAD_ONCE_INIT;
  pthread_once(&once, install_once);
}

static void install_alarm(void) {
  static int done;
  if (done) return;
  done = 1;
  install();
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_NODEFER;
  sa.sa_handler = on_alarm;
  sigaction(SIGALRM, &sa, &old_alarm);
}

static void arm(double seconds) {
  struct itimerval it;
  memset(&it, 0, sizeof it);
  if (seconds > 0) {
    double whole = floor(seconds);
    it.it_value.tv_sec = (time_t)whole;
    it.it_value.tv_usec = (suseconds_t)((seconds - whole) * 1e6);
    if (it.it_value.tv_sec == 0 && it.it_value.tv_usec == 0) it.it_value.tv_usec = 1;
  }
  setitimer(ITIMER_REAL, &it, NULL);
}

/* Not inlined: sigsetjmp's frame is this one, and its callers stay inlinable. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
int sl_guard_evaluate(const sl_closure_desc *desc, const void *state, const sl_eval_args *args, const char *label,
                      const char *role, int *poisoned) {
  if (!installed) install();
  const double limit = time_limit;
  sigjmp_buf env;
  sigjmp_buf *volatile prev_env = call_env;
  const char *volatile prev_label = call_label, *volatile prev_role = call_role;
  volatile int rc = SL_ERR_INTERNAL;
  if (sigsetjmp(env, 0) == 0) {
    call_label = label, call_role = role, call_signal = 0;
    call_env = &env;
    if (limit > 0) arm(limit);
    rc = desc->evaluate(state, args);
    call_env = prev_env;
    if (limit > 0) arm(0);
  } else {
    call_env = prev_env;
    if (limit > 0) arm(0);
    *poisoned = 1;
    int sig = call_signal;
    if (sig == SIGALRM)
      snprintf(args->err->msg, sizeof args->err->msg,
               "did not return within the call time limit of %g s (a looping closure); stopped", limit);
    else if (sig == SIGINT || sig == SIGTERM)
      snprintf(args->err->msg, sizeof args->err->msg, "interrupted by %s inside its evaluation", sl_signal_name(sig));
    else
      snprintf(args->err->msg, sizeof args->err->msg, "crashed with %s (signal %d) inside its evaluation",
               sl_signal_name(sig), sig);
    args->err->point = -1;
    rc = SL_ERR_INTERNAL;
  }
  call_label = prev_label, call_role = prev_role;
  return rc;
}

void sl_guard_interrupt(int sig) {
  sigjmp_buf *env = call_env;
  if (!env) return;
  /* The handler runs with the signal blocked; the jump does not restore
     the mask (sigsetjmp(env, 0)): unblock it here. */
  sigset_t s;
  sigemptyset(&s);
  sigaddset(&s, sig);
  sigprocmask(SIG_UNBLOCK, &s, NULL);
  call_signal = sig;
  siglongjmp(*env, 1);
}

void sl_guard_set_call_time_limit(double seconds) {
  time_limit = seconds > 0 ? seconds : 0.0;
  if (time_limit > 0) install_alarm();
}

double sl_guard_call_time_limit(void) { return time_limit; }

void sl_guard_set_clock(double t, double dt) { clock_t_now = t, clock_dt_now = dt; }

void sl_guard_clock(double *t, double *dt) { *t = clock_t_now, *dt = clock_dt_now; }

void sl_guard_set_fatal(const char *fmt, ...) {
  if (fatal_set) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(fatal_msg, sizeof fatal_msg, fmt, ap);
  va_end(ap);
  fatal_set = 1;
}

int sl_guard_fatal(char *msg, size_t n) {
  if (!fatal_set) return 0;
  if (msg && n) snprintf(msg, n, "%s", fatal_msg);
  return 1;
}

void sl_guard_clear_fatal(void) { fatal_set = 0, fatal_msg[0] = '\0'; }
