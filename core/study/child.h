/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Work in a child process, so that its memory and clocks are its own and a
 * crash, a hang or an exit ends only it: either a command is exec'ed (a
 * study's run of the sluice command itself, FreeFEM), or a function is
 * called in the forked child (an in-process benchmark run). The parent waits
 * with wait4(), whose rusage gives the child's CPU time (user + system) and
 * peak resident set; it kills the child at a timeout and forwards an
 * interrupt; it reads what the child sends back (a result struct through a
 * pipe, its stdout line by line) while it runs, so neither side blocks. */
#ifndef SLUICE_STUDY_CHILD_H
#define SLUICE_STUDY_CHILD_H

#include <signal.h>
#include <stddef.h>

typedef struct sl_child_opts {
  /* what the child does: exec argv (argv[0] searched on PATH when it has no '/'), or call fn(arg, result) */
  char *const *argv;
  void (*fn)(void *arg, void *result);
  void *arg;
  /* the result the child sends back: fn's struct, or what an exec'ed child writes to file descriptor
     result_fd (sl_child_result got_result says whether all of it came) */
  void *result;
  size_t result_size;
  int result_fd;
  /* the child's output: stdout and stderr to files (NULL: inherited; "/dev/null" to drop), or stdout line by line
     to `line` (then `out` is not used) */
  const char *out, *err;
  void (*line)(void *user, const char *text);
  void *line_user;
  const char *dir;        /* the child's working directory (NULL: the parent's); paths above are opened after it */
  const char *const *env; /* "NAME=VALUE" settings for the child, NULL-terminated (NULL: none) */
  double timeout;         /* wall seconds (0: none); then the child is killed */
  volatile sig_atomic_t *interrupt; /* when set: SIGINT forwarded to the child, once */
} sl_child_opts;

typedef struct sl_child_result {
  int exit_code, signal_number; /* the child's */
  int timed_out, interrupted;   /* killed at the timeout; an interrupt was forwarded */
  int got_result;               /* the whole result arrived */
  double cpu, wall, peak_rss_mb;
  char message[512]; /* why the child could not be run or waited for ("" otherwise) */
} sl_child_result;

/* Runs the child and waits for it. 0, or -1 when no child could be started
 * or waited for (r->message says why). r->result is zeroed unless all of it
 * arrived. */
int sl_child_run(const sl_child_opts *o, sl_child_result *r);

/* Removes a run's output file (path ends in ".h5") and its XDMF sidecar. */
void sl_child_remove_output(const char *path);

#endif
