/* SPDX-License-Identifier: GPL-2.0-or-later */
/* `sluice run --summary-json FILE`: what the run did, as one JSON object
 * (the numbers of the summary line and more), for scripts such as the
 * Python package in python/. Keys: docs/output.md. */
#ifndef SLUICE_CLI_SUMMARY_JSON_H
#define SLUICE_CLI_SUMMARY_JSON_H

#include "sluice/sluice.h"

/* Writes FILE (replacing it). m and the times may be NULL when the run
 * never started (bad input): then only the status, the exit code and the
 * message are written. Returns 0 or -1 with errno. */
int sl_summary_json_write(const char *path, const char *scene, const char *model, int exit_code, const char *message,
                          const sluice_summary *m, double wall_seconds, double cpu_seconds);

#endif
