/* SPDX-License-Identifier: GPL-2.0-or-later */
#include <stdio.h>

#include <sluice/closure.h>

#include "core/cli/cli.h"
#include "core/plugin/registry.h"
#include "core/util/blas.h"
#include "core/util/version.h"

int sl_cmd_version(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(
        "usage: sluice version\nPrints the sluice version, the closure ABI, the plugin folder and the BLAS that "
        "UMFPACK and CHOLMOD run on.");
    return 0;
  }
  if (argc > 0) return sl_cli_error(2, "version takes no arguments");
  printf("sluice %s\nclosure ABI %u.%u\nplugin folder %s\nBLAS %s\n", sl_version(), SL_CLOSURE_ABI_MAJOR,
         SL_CLOSURE_ABI_MINOR, sl_registry_default_dir(), sl_blas_description());
  return 0;
}
