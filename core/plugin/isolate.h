/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Closure library code run in a child process (docs/trust-plugins.md): what
 * it does there (a constructor, a crash, a hang, exit()) cannot touch the
 * sluice process, which reads what the child reports and how it ended. */
#ifndef SLUICE_PLUGIN_ISOLATE_H
#define SLUICE_PLUGIN_ISOLATE_H

typedef struct sl_child_outcome {
  int exited; /* the child returned or called exit(): status is its exit status */
  int status;
  int signal;    /* the child was killed by this signal (0: none) */
  int timed_out; /* it sent nothing for longer than the limit and was killed */
} sl_child_outcome;

/* Forks; the child runs child(user, fd) with fd the write end of a pipe to
 * the parent, then _exit()s with its return value (no atexit handler of the
 * parent runs in the child). The parent passes each line the child writes
 * (without its newline) to on_line (may be NULL), and kills the child when
 * it has written nothing for `quiet_limit` seconds (0: no limit). Returns 0
 * when the child was started and waited for (the outcome in *out), -1 when
 * it could not be started (errno). */
int sl_isolate(int (*child)(void *user, int fd), void *user, void (*on_line)(void *line_user, const char *line),
               void *line_user, double quiet_limit, sl_child_outcome *out);

/* Writes one line (a newline added) to the pipe of sl_isolate's child. */
void sl_isolate_say(int fd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
