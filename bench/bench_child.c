#include "bench_child.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int bench_in_child(void (*fn)(void *arg, void *result), void *arg, void *result, size_t size, char *why, size_t len) {
  memset(result, 0, size);
  int fd[2];
  if (pipe(fd)) {
    snprintf(why, len, "pipe: %s", strerror(errno));
    return -1;
  }
  fflush(NULL);
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(why, len, "fork: %s", strerror(errno));
    close(fd[0]), close(fd[1]);
    return -1;
  }
  if (pid == 0) {
    close(fd[0]);
    void *mine = calloc(1, size);
    if (!mine) _exit(3);
    fn(arg, mine);
    const char *p = mine;
    size_t left = size;
    while (left > 0) {
      ssize_t w = write(fd[1], p, left);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) _exit(2);
      p += w, left -= (size_t)w;
    }
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  char *p = result;
  size_t got = 0;
  while (got < size) {
    ssize_t k = read(fd[0], p + got, size - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    got += (size_t)k;
  }
  close(fd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      snprintf(why, len, "waitpid: %s", strerror(errno));
      return -1;
    }
  if (got != size) {
    memset(result, 0, size);
    if (WIFSIGNALED(status))
      snprintf(why, len, "the child was killed by signal %d%s", WTERMSIG(status),
               WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
    else snprintf(why, len, "the child exited with status %d without a result", WEXITSTATUS(status));
    return -1;
  }
  return 0;
}

void bench_remove_output(const char *path) {
  char xmf[4096];
  size_t len = strlen(path);
  remove(path);
  if (len < 3 || len >= sizeof xmf || strcmp(path + len - 3, ".h5") != 0) return;
  memcpy(xmf, path, len - 3);
  memcpy(xmf + len - 3, ".xmf", 5);
  remove(xmf);
}
