/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The sluice command: one file per subcommand. Each returns the process exit
 * status (0 ok, 1 the run failed, 2 bad usage or input). */
#ifndef SLUICE_CLI_CLI_H
#define SLUICE_CLI_CLI_H

#include "core/plugin/registry.h"

int sl_cmd_version(int argc, char **argv);
int sl_cmd_closures(int argc, char **argv);
int sl_cmd_closure(int argc, char **argv); /* describe | eval */
int sl_cmd_check_closure(int argc, char **argv);
int sl_cmd_run(int argc, char **argv);
int sl_cmd_sample(int argc, char **argv);
int sl_cmd_bench(int argc, char **argv);
int sl_cmd_model(int argc, char **argv); /* list | describe */

/* A registry with every library of the search path loaded. Libraries that
 * could not be used are reported on stderr when `warn` is set. */
int sl_cli_registry(sl_registry **r, int warn);

/* "--help" or "-h" among the arguments. */
int sl_cli_wants_help(int argc, char **argv);

/* Prints "sluice: <msg>" to stderr and returns `code`. */
int sl_cli_error(int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* sluice closure index DIR (cmd_closure_index.c) */
int sl_cmd_closure_index(int argc, char **argv);
extern const char sl_closure_index_usage[];
/* sluice closure kinds [KIND] [--markdown] (cmd_closure_kinds.c) */
int sl_cmd_closure_kinds(int argc, char **argv);
extern const char sl_closure_kinds_usage[];
/* sluice closure new KIND NAME [-o DIR] (cmd_closure_new.c) */
int sl_cmd_closure_new(int argc, char **argv);
extern const char sl_closure_new_usage[];

#endif
