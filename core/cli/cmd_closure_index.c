/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice closure index DIR: writes DIR/closures.index, the file that lets
 * sluice open, for a closure a scene names, only the library that holds it
 * (docs/trust-plugins.md). The libraries' descriptors are read in a child
 * process. */
#include <stdio.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/plugin/registry.h"

const char sl_closure_index_usage[] =
    "usage: sluice closure index DIR\n"
    "Writes DIR/" SL_PLUGIN_INDEX_FILE
    ": which library in DIR holds which closure (kind,\n"
    "name), read from the libraries in a child process. With the index, a look-up\n"
    "opens the one library that holds the closure named and no other; without it\n"
    "sluice reads what the folder's libraries hold (in a child process) at the\n"
    "first look-up. Write it again when the folder's libraries change.";

int sl_cmd_closure_index(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(sl_closure_index_usage);
    return 0;
  }
  if (argc != 1 || argv[0][0] == '-')
    return sl_cli_error(SL_EBADINPUT, "closure index: one folder (sluice closure index DIR)");
  sl_diag d;
  int n = 0, rc = sl_registry_write_index(argv[0], &n, &d);
  if (rc) return sl_cli_error(rc, "closure index: %s", d.msg);
  if (d.msg[0]) fprintf(stderr, "%s\n", d.msg); /* the libraries skipped */
  printf("%s/%s: %d closure%s\n", argv[0], SL_PLUGIN_INDEX_FILE, n, n == 1 ? "" : "s");
  return 0;
}
