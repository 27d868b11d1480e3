/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice: simulation of solid-liquid mixtures with pluggable closures. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/io/output.h"
#include "core/util/diag.h"

static const char usage[] =
    "usage: sluice <command> [options]\n"
    "\n"
    "commands:\n"
    "  run SCENE.ini [--set section.key=value]... [--print-config] [-o OUT.h5]\n"
    "                                  run a scene (--check: validate it and stop)\n"
    "  model list | describe NAME      the models, and the sections and keys each reads\n"
    "  closures                        list every closure found (kind, name, version, library)\n"
    "  closure describe NAME|--all     schema, units, ranges, reference, an INI stanza\n"
    "  closure eval NAME --at SPEC     evaluate a closure without a mesh (CSV)\n"
    "  closure kinds [KIND]            the closure kinds and their contracts (inputs, outputs, units)\n"
    "  closure new KIND NAME [-o DIR]  write a closure template (NAME.c, CMakeLists.txt) to fill in\n"
    "  closure index DIR               write DIR/closures.index (which library holds which closure)\n"
    "  check-closure LIB.so            run the conformance battery on a closure library\n"
    "  sample OUT.h5 --field F --line x0,y0:x1,y1 [--n N] [--time T]\n"
    "                                  a field of an output file along a line (CSV);\n"
    "                                  --point x,y for one point, --list for the contents\n"
    "  bench STUDY.ini [-o DIR]        a work-precision study or a closure comparison:\n"
    "                                  every run in its own process; CSV, SVG, PNG\n"
    "  version                         print the version\n"
    "\n"
    "Each command takes --help. Closures are searched in SLUICE_PLUGIN_PATH\n"
    "(colon-separated), then sluice's own plugin folder; the folders a scene's\n"
    "[plugins] path names come first only with run --allow-plugin-path.\n"
    "Exit status: 0 success, 1 the run failed, 2 bad usage or bad input.\n";

int sl_cli_error(int code, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fputs("sluice: ", stderr);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return code;
}

int sl_cli_wants_help(int argc, char **argv) {
  for (int i = 0; i < argc; ++i)
    if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) return 1;
  return 0;
}

int sl_cli_registry(sl_registry **r, int warn) {
  sl_diag d;
  if (sl_registry_create(r, NULL, 0, &d) || sl_registry_scan(*r, &d)) {
    sl_registry_destroy(*r);
    *r = NULL;
    return sl_cli_error(SL_EFAILED, "%s", d.msg);
  }
  if (warn)
    for (int i = 0; i < (*r)->n_problems; ++i) fprintf(stderr, "sluice: warning: skipped %s\n", (*r)->problems[i]);
  return 0;
}

typedef struct command {
  const char *name;
  int (*run)(int argc, char **argv);
} command;

static const command commands[] = {
    {"run", sl_cmd_run},         {"closures", sl_cmd_closures},
    {"closure", sl_cmd_closure}, {"check-closure", sl_cmd_check_closure},
    {"version", sl_cmd_version}, {"sample", sl_cmd_sample},
    {"bench", sl_cmd_bench},     {"model", sl_cmd_model},
};

int main(int argc, char **argv) {
  sl_io_process_start();
  if (argc < 2) {
    fputs(usage, stderr);
    return SL_EBADINPUT;
  }
  const char *name = argv[1];
  if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0 || strcmp(name, "help") == 0) {
    fputs(usage, stdout);
    return 0;
  }
  if (strcmp(name, "--version") == 0) name = "version";
  const char *names[sizeof commands / sizeof commands[0]];
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i) {
    names[i] = commands[i].name;
    if (strcmp(name, commands[i].name) == 0) return sl_exit_status(commands[i].run(argc - 2, argv + 2));
  }
  const char *s = sl_suggest(name, names, (int)(sizeof names / sizeof names[0]));
  if (s) return sl_cli_error(SL_EBADINPUT, "unknown command '%s'; did you mean '%s'? (sluice --help)", name, s);
  return sl_cli_error(SL_EBADINPUT, "unknown command '%s' (sluice --help lists the commands)", name);
}
