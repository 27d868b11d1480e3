/* sluice check-closure LIB.so: loads a library strictly and runs the
 * conformance battery on each of its closures. */
#include <stdio.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/plugin/battery.h"

int sl_cmd_check_closure(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts("usage: sluice check-closure LIB.so [--quiet]\n"
         "Loads a closure library and runs the conformance battery on every closure in\n"
         "it: ABI and schema checks, create/destroy, bounds enforced by the host, every\n"
         "output written, batch invariance, derivatives against central differences,\n"
         "inputs outside the declared validity refused with the point named, reference\n"
         "values from the literature, concurrent evaluation.\n"
         "Exit status: 0 all passed, 1 a check failed, 2 the library cannot be loaded.");
    return 0;
  }
  const char *path = NULL;
  int quiet = 0;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--quiet") == 0) quiet = 1;
    else if (argv[i][0] == '-') return sl_cli_error(SL_EBADINPUT, "check-closure: unknown option '%s'", argv[i]);
    else if (!path) path = argv[i];
    else return sl_cli_error(SL_EBADINPUT, "check-closure: one library at a time");
  }
  if (!path) return sl_cli_error(SL_EBADINPUT, "check-closure: which library? (sluice check-closure LIB.so)");
  sl_registry *r;
  sl_diag d;
  /* An empty search path: only the library named is loaded. */
  if (sl_registry_create(&r, NULL, 0, &d)) return sl_cli_error(SL_EFAILED, "%s", d.msg);
  sl_library *lib;
  int rc = sl_registry_add_library(r, path, &lib, &d);
  if (rc) {
    sl_registry_destroy(r);
    return sl_cli_error(rc, "%s", d.msg);
  }
  sl_battery_result res = {0, 0, 0};
  for (int i = 0; i < r->n_entries; ++i) {
    if (r->entries[i].library != lib) continue;
    sl_battery_run(&r->entries[i], quiet ? NULL : stdout, &res);
  }
  printf("%d passed, %d failed\n", res.passed, res.failed);
  sl_registry_destroy(r);
  return res.failed ? SL_EFAILED : 0;
}
