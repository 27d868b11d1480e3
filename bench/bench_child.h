/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A benchmark run in a child process, so that its peak memory and its
 * clocks are its own and a crash ends only that run: the child calls
 * fn(arg, result) and sends the result struct back through a pipe. */
#ifndef SLUICE_BENCH_CHILD_H
#define SLUICE_BENCH_CHILD_H

#include <stddef.h>

/* Returns 0 when the child delivered its whole result (size bytes into
 * result), else -1 with the reason in why[len] (a failed fork or pipe, a
 * signal, an exit without a result) and result zeroed. */
int bench_in_child(void (*fn)(void *arg, void *result), void *arg, void *result, size_t size, char *why, size_t len);

/* Removes a run's output file (path ends in ".h5") and its XDMF sidecar. */
void bench_remove_output(const char *path);

#endif
