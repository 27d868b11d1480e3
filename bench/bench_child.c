/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The benchmarks' runs in a child process (bench_child.h), on the study's child runner (core/study/child.h). */
#include "bench_child.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "core/study/child.h"

int bench_in_child(void (*fn)(void *arg, void *result), void *arg, void *result, size_t size, char *why, size_t len) {
  sl_child_opts o = {.fn = fn, .arg = arg, .result = result, .result_size = size, .result_fd = -1};
  sl_child_result r;
  if (sl_child_run(&o, &r)) {
    snprintf(why, len, "%s", r.message);
    return -1;
  }
  if (!r.got_result) {
    if (r.signal_number)
      snprintf(why, len, "the child was killed by signal %d%s", r.signal_number,
               r.signal_number == SIGKILL ? " (out of memory?)" : "");
    else snprintf(why, len, "the child exited with status %d without a result", r.exit_code);
    return -1;
  }
  return 0;
}

void bench_remove_output(const char *path) { sl_child_remove_output(path); }
