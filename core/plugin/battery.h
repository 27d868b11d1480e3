/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The conformance battery (closure-abi.md): what every closure, built-in or
 * third-party, must pass before it is trusted. `sluice check-closure LIB.so`
 * runs it; so do the tests, on every shipped library. */
#ifndef SLUICE_PLUGIN_BATTERY_H
#define SLUICE_PLUGIN_BATTERY_H

#include <stdio.h>

#include "core/plugin/registry.h"

typedef struct sl_battery_result {
  int passed, failed;
  int skipped_points; /* derivative points skipped at switches or validity edges */
  /* Told before each check starts (may be NULL): what `check-closure` names
   * when a closure crashes or hangs in it. */
  void (*progress)(void *user, const char *label, const char *check);
  void *progress_user;
} sl_battery_result;

/* Runs every check on one closure, printing one line per check to `log`
 * (may be NULL), and adds the outcome to *res. */
void sl_battery_run(const sl_closure_entry *entry, FILE *log, sl_battery_result *res);

#endif
