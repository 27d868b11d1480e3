/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Work in a child process (child.h). */
#define _DEFAULT_SOURCE /* wait4(): the one wait that returns the child's own rusage (BSD, in glibc and musl) */
#include "core/study/child.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/io/output.h"

static double monotonic(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_MONOTONIC, &ts)) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
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

/* A descriptor above the ones the child replaces (0, 1, 2 and the result's). */
static int lift(int fd, int above) {
  if (fd > above) return fd;
  int moved = fcntl(fd, F_DUPFD, above + 1);
  close(fd);
  return moved;
}

static void redirect(const char *path, int to) {
  int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) dup2(fd, to), close(fd);
}

static _Noreturn void in_child(const sl_child_opts *o, int res_w, int out_w) {
  if (o->dir && chdir(o->dir) != 0) {
    fprintf(stderr, "cannot enter %s: %s\n", o->dir, strerror(errno));
    _exit(126);
  }
  for (const char *const *e = o->env; e && *e; ++e) {
    const char *eq = strchr(*e, '=');
    char name[256];
    if (!eq || eq == *e || (size_t)(eq - *e) >= sizeof name) _exit(126);
    memcpy(name, *e, (size_t)(eq - *e)), name[eq - *e] = '\0';
    if (setenv(name, eq + 1, 1) != 0) _exit(126);
  }
  if (out_w >= 0) dup2(out_w, STDOUT_FILENO), close(out_w);
  else if (o->out) redirect(o->out, STDOUT_FILENO);
  if (o->err && o->out && out_w < 0 && strcmp(o->err, o->out) == 0) dup2(STDOUT_FILENO, STDERR_FILENO); /* one log */
  else if (o->err) redirect(o->err, STDERR_FILENO);
  if (o->argv) {
    if (res_w >= 0 && o->result_fd >= 0 && res_w != o->result_fd) {
      if (dup2(res_w, o->result_fd) < 0) _exit(127);
      close(res_w);
    }
    if (strchr(o->argv[0], '/')) execv(o->argv[0], o->argv);
    else execvp(o->argv[0], o->argv);
    fprintf(stderr, "cannot run %s: %s\n", o->argv[0], strerror(errno));
    _exit(127);
  }
  void *mine = o->result_size ? calloc(1, o->result_size) : NULL;
  if (o->result_size && !mine) _exit(3);
  o->fn(o->arg, mine);
  if (res_w >= 0) write_all(res_w, mine, o->result_size);
  fflush(NULL);
  _exit(0);
}

/* Reads what is there of fd into the result (res) or into lines (out); closes fd at its end. */
static void drain(int *fd, char *res, size_t size, size_t *got, char *line, size_t *len, size_t cap,
                  const sl_child_opts *o) {
  char buf[4096];
  ssize_t k = read(*fd, buf, sizeof buf);
  if (k < 0 && (errno == EINTR || errno == EAGAIN)) return;
  if (k <= 0) {
    if (line && *len > 0) line[*len] = '\0', o->line(o->line_user, line), *len = 0;
    close(*fd), *fd = -1;
    return;
  }
  for (ssize_t i = 0; i < k; ++i) {
    if (res) {
      if (*got < size) res[(*got)++] = buf[i];
      continue;
    }
    if (buf[i] == '\n' || *len + 1 >= cap) {
      line[*len] = '\0', o->line(o->line_user, line), *len = 0;
      if (buf[i] == '\n') continue;
    }
    line[(*len)++] = buf[i];
  }
}

int sl_child_run(const sl_child_opts *o, sl_child_result *r) {
  memset(r, 0, sizeof *r);
  r->cpu = r->wall = r->peak_rss_mb = NAN;
  if (o->result && o->result_size) memset(o->result, 0, o->result_size);
  int res[2] = {-1, -1}, out[2] = {-1, -1};
  int want_result = o->result && o->result_size && (o->fn || o->result_fd >= 0);
  int top = o->result_fd > 2 ? o->result_fd : 2;
  if ((want_result && pipe(res)) || (o->line && pipe(out))) {
    snprintf(r->message, sizeof r->message, "pipe: %s", strerror(errno));
    return -1;
  }
  if (want_result && (res[1] = lift(res[1], top)) < 0) {
    snprintf(r->message, sizeof r->message, "fcntl: %s", strerror(errno));
    return -1;
  }
  fflush(NULL); /* nothing buffered is written twice */
  double w0 = monotonic();
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(r->message, sizeof r->message, "fork: %s", strerror(errno));
    for (int k = 0; k < 2; ++k) {
      if (res[k] >= 0) close(res[k]);
      if (out[k] >= 0) close(out[k]);
    }
    return -1;
  }
  if (pid == 0) {
    if (res[0] >= 0) close(res[0]);
    if (out[0] >= 0) close(out[0]);
    in_child(o, res[1], out[1]);
  }
  if (res[1] >= 0) close(res[1]);
  if (out[1] >= 0) close(out[1]);
  size_t got = 0, len = 0;
  char line[4096];
  int status = 0, done = 0;
  struct rusage ru;
  memset(&ru, 0, sizeof ru);
  while (!done || res[0] >= 0 || out[0] >= 0) {
    struct pollfd p[2];
    int *which[2], np = 0;
    if (res[0] >= 0) which[np] = &res[0], p[np++] = (struct pollfd){res[0], POLLIN, 0};
    if (out[0] >= 0) which[np] = &out[0], p[np++] = (struct pollfd){out[0], POLLIN, 0};
    if (np && poll(p, (nfds_t)np, 20) > 0) {
      for (int k = 0; k < np; ++k) {
        if (!(p[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
        if (which[k] == &res[0]) drain(&res[0], o->result, o->result_size, &got, NULL, NULL, 0, o);
        else drain(&out[0], NULL, 0, NULL, line, &len, sizeof line, o);
      }
    } else if (!np) {
      struct timespec ts = {0, 5000000};
      nanosleep(&ts, NULL);
    }
    if (!done) {
      pid_t w = wait4(pid, &status, WNOHANG, &ru);
      if (w == pid) done = 1;
      else if (w < 0 && errno != EINTR) {
        snprintf(r->message, sizeof r->message, "wait4: %s", strerror(errno));
        done = 1;
      }
    }
    if (!done && !r->timed_out && o->timeout > 0 && monotonic() - w0 > o->timeout) kill(pid, SIGKILL), r->timed_out = 1;
    if (!done && o->interrupt && *o->interrupt && !r->interrupted) kill(pid, SIGINT), r->interrupted = 1;
  }
  r->wall = monotonic() - w0;
  r->cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
           1e-6 * (double)ru.ru_stime.tv_usec;
  r->peak_rss_mb = (double)ru.ru_maxrss / 1024.0; /* Linux: kilobytes */
  if (WIFEXITED(status)) r->exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r->signal_number = WTERMSIG(status);
  r->got_result = want_result && got == o->result_size;
  if (want_result && !r->got_result) memset(o->result, 0, o->result_size);
  return 0;
}

void sl_child_remove_output(const char *path) { sl_output_remove(path); }
