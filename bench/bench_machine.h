/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The machine a benchmark ran on, for its CSV header: CPU model, cores and
 * the load average when it started (other jobs inflate the times). */
#ifndef SLUICE_BENCH_MACHINE_H
#define SLUICE_BENCH_MACHINE_H

#include <stddef.h>

void bench_machine_describe(char *buf, size_t len);

#endif
