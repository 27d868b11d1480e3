/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/isolate.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

void sl_isolate_say(int fd, const char *fmt, ...) {
  char buf[2048];
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(buf, sizeof buf - 1, fmt, ap);
  va_end(ap);
  if (n < 0) return;
  if ((size_t)n > sizeof buf - 2) n = (int)sizeof buf - 2;
  for (int i = 0; i < n; ++i)
    if (buf[i] == '\n') buf[i] = ' ';
  buf[n++] = '\n';
  for (int at = 0; at < n;) {
    ssize_t w = write(fd, buf + at, (size_t)(n - at));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return;
    at += (int)w;
  }
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int sl_isolate(int (*child)(void *user, int fd), void *user, void (*on_line)(void *line_user, const char *line),
               void *line_user, double quiet_limit, sl_child_outcome *out) {
  memset(out, 0, sizeof *out);
  int p[2];
  if (pipe(p) != 0) return -1;
  fflush(stdout);
  fflush(stderr);
  pid_t pid = fork();
  if (pid < 0) {
    int e = errno;
    close(p[0]), close(p[1]);
    errno = e;
    return -1;
  }
  if (pid == 0) {
    close(p[0]);
    int rc = child(user, p[1]);
    fflush(stdout);
    fflush(stderr);
    close(p[1]);
    _exit(rc & 0xff);
  }
  close(p[1]);
  char line[4096];
  size_t len = 0;
  double last = now();
  for (;;) {
    int timeout_ms = -1;
    if (quiet_limit > 0) {
      double left = quiet_limit - (now() - last);
      if (left <= 0) {
        kill(pid, SIGKILL);
        out->timed_out = 1;
        break;
      }
      timeout_ms = (int)ceil(left * 1e3);
    }
    struct pollfd pf = {.fd = p[0], .events = POLLIN};
    int pr = poll(&pf, 1, timeout_ms);
    if (pr < 0 && errno == EINTR) continue;
    if (pr < 0) break;
    if (pr == 0) continue; /* the limit is checked at the top */
    char buf[1024];
    ssize_t n = read(p[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break; /* the child closed the pipe: it ended */
    last = now();
    for (ssize_t i = 0; i < n; ++i) {
      if (buf[i] == '\n' || len == sizeof line - 1) {
        line[len] = '\0';
        if (on_line) on_line(line_user, line);
        len = 0;
        if (buf[i] == '\n') continue;
      }
      line[len++] = buf[i];
    }
  }
  if (len > 0 && on_line) {
    line[len] = '\0';
    on_line(line_user, line);
  }
  close(p[0]);
  int st = 0;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) return -1;
  if (WIFEXITED(st)) out->exited = 1, out->status = WEXITSTATUS(st);
  else if (WIFSIGNALED(st)) out->signal = WTERMSIG(st);
  if (out->timed_out) out->exited = 0, out->signal = 0;
  return 0;
}
