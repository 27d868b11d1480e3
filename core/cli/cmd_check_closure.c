/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice check-closure LIB.so: loads a library strictly and runs the
 * conformance battery on each of its closures, in a child process with a
 * time limit (docs/trust-plugins.md): a closure that crashes, hangs or calls
 * exit() is reported by name and the check it was in, and the command
 * itself always finishes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/plugin/battery.h"
#include "core/plugin/guard.h"
#include "core/plugin/isolate.h"

typedef struct job {
  const char *path;
  int quiet;
  int fd;
  const sl_battery_result *res;
} job;

static void say_progress(void *user, const char *label, const char *check) {
  const job *j = user;
  sl_isolate_say(j->fd, "K%d %d %s\t%s", j->res->passed, j->res->failed, label, check);
}

/* In the child: the library's code runs here only. */
static int battery_child(void *user, int fd) {
  job *j = user;
  j->fd = fd;
  setvbuf(stdout, NULL, _IOLBF, 0); /* what was checked survives a crash */
  sl_registry *r;
  sl_diag d;
  /* An empty search path: only the library named is loaded. */
  if (sl_registry_create(&r, NULL, 0, &d)) return sl_cli_error(SL_EFAILED, "%s", d.msg);
  sl_isolate_say(fd, "K0 0 %s\tload", j->path);
  sl_library *lib;
  int rc = sl_registry_add_library(r, j->path, &lib, &d);
  if (rc) {
    sl_registry_destroy(r);
    sl_isolate_say(fd, "E%d", rc);
    return sl_cli_error(rc, "%s", d.msg);
  }
  sl_battery_result res = {0, 0, 0, say_progress, j};
  j->res = &res;
  for (int i = 0; i < r->n_entries; ++i) {
    if (r->entries[i].library != lib) continue;
    sl_battery_run(&r->entries[i], j->quiet ? NULL : stdout, &res);
    fflush(stdout);
  }
  sl_registry_destroy(r);
  sl_isolate_say(fd, "R%d %d", res.passed, res.failed);
  return 0;
}

typedef struct watch {
  char label[256], check[128];
  int passed, failed, finished, load_error;
} watch;

static void on_line(void *user, const char *line) {
  watch *w = user;
  if (line[0] == 'K') {
    const char *tab = strchr(line + 1, '\t');
    int at = 0;
    if (!tab || sscanf(line + 1, "%d %d %n", &w->passed, &w->failed, &at) != 2 || at <= 0) return;
    snprintf(w->label, sizeof w->label, "%.*s", (int)(tab - line - 1 - at), line + 1 + at);
    snprintf(w->check, sizeof w->check, "%s", tab + 1);
  } else if (line[0] == 'R') {
    if (sscanf(line + 1, "%d %d", &w->passed, &w->failed) == 2) w->finished = 1;
  } else if (line[0] == 'E') {
    w->load_error = atoi(line + 1);
  }
}

int sl_cmd_check_closure(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(
        "usage: sluice check-closure LIB.so [--quiet] [--time-limit SECONDS]\n"
        "Loads a closure library and runs the conformance battery on every closure in\n"
        "it: ABI and schema checks, create/destroy, bounds enforced by the host, every\n"
        "output written, batch invariance, derivatives against central differences,\n"
        "inputs outside the declared validity refused with the point named, reference\n"
        "values from the literature, concurrent evaluation.\n"
        "The battery runs in a child process: a closure that crashes (the signal is\n"
        "named), calls exit() or runs one check longer than the time limit (default\n"
        "30 s) fails with its name and the check it was in.\n"
        "Exit status: 0 all passed, 1 a check failed, 2 the library cannot be loaded.");
    return 0;
  }
  const char *path = NULL;
  int quiet = 0;
  double limit = 30.0;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--quiet") == 0) {
      quiet = 1;
    } else if (strcmp(argv[i], "--time-limit") == 0 && i + 1 < argc) {
      char *end;
      limit = strtod(argv[++i], &end);
      if (*end || !(limit > 0) || limit > 1e6)
        return sl_cli_error(SL_EBADINPUT, "check-closure: --time-limit %s: seconds in (0, 1e6] expected", argv[i]);
    } else if (argv[i][0] == '-') {
      return sl_cli_error(SL_EBADINPUT, "check-closure: unknown option or missing value '%s'", argv[i]);
    } else if (!path) {
      path = argv[i];
    } else {
      return sl_cli_error(SL_EBADINPUT, "check-closure: one library at a time");
    }
  }
  if (!path) return sl_cli_error(SL_EBADINPUT, "check-closure: which library? (sluice check-closure LIB.so)");
  job j = {path, quiet, -1, NULL};
  watch w;
  memset(&w, 0, sizeof w);
  sl_child_outcome o;
  if (sl_isolate(battery_child, &j, on_line, &w, limit, &o))
    return sl_cli_error(SL_EFAILED, "check-closure: cannot start the process that runs the battery");
  if (w.load_error) return o.exited ? o.status : w.load_error;
  if (o.exited && o.status == 0 && w.finished) {
    printf("%d passed, %d failed\n", w.passed, w.failed);
    return w.failed ? SL_EFAILED : 0;
  }
  char why[128];
  if (o.timed_out) snprintf(why, sizeof why, "did not finish within the time limit of %g s (stopped)", limit);
  else if (o.signal) snprintf(why, sizeof why, "crashed with %s (signal %d)", sl_signal_name(o.signal), o.signal);
  else snprintf(why, sizeof why, "called exit(%d)", o.status);
  fflush(stdout);
  printf("FAIL %-22s %s: %s\n", w.label[0] ? w.label : path, w.check[0] ? w.check : "load", why);
  printf("%d passed, %d failed (the battery stopped there)\n", w.passed, w.failed + 1);
  return SL_EFAILED;
}
