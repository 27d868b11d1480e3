/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Columns of the benchmark programs' CSVs by header name (no quoting: their
 * fields hold no commas), shared by the programs that read their own CSVs
 * back (--replot) or another program's. */
#ifndef SLUICE_BENCH_CSV_H
#define SLUICE_BENCH_CSV_H

#include <stddef.h>

/* The column of `name` in a CSV header line, or -1. */
int bench_csv_column(const char *header, const char *name);

/* Field k of a CSV line into buf (empty when the line has fewer fields). */
void bench_csv_field(const char *line, int k, char *buf, size_t cap);

/* Field k as a number: NaN when it is empty or not a number. */
double bench_csv_number(const char *line, int k);

#endif
