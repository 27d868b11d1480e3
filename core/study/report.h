/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The results of a study: one row per run, the errors and observed orders,
 * and what is written: a CSV with one row per run, a CSV of the compared
 * quantity side by side (comparisons), and a PNG plot (core/study/chart.h):
 * error against CPU time on log-log axes, one curve per variant, or for a
 * comparison the quantity per variant on linear axes. */
#ifndef SLUICE_BENCH_REPORT_H
#define SLUICE_BENCH_REPORT_H

#include "core/study/measure.h"
#include "core/study/runner.h"
#include "core/study/study.h"

typedef struct sl_bench_row {
  int variant, point;
  sl_bench_run_result run;
  int measured; /* the measure succeeded */
  sl_bench_measured m;
  double error; /* NaN: none (a comparison, or nothing to compare with) */
  double order; /* observed order against the previous point of the variant, NaN: none */
} sl_bench_row;

typedef struct sl_bench_table {
  const sl_study *study;
  int n_rows; /* n_variants x n_points, variant by variant */
  sl_bench_row *rows;
  char exact[512]; /* the exact solution's description, or "" */
} sl_bench_table;

int sl_bench_table_init(sl_bench_table *t, const sl_study *s);
void sl_bench_table_free(sl_bench_table *t);
sl_bench_row *sl_bench_table_row(sl_bench_table *t, int variant, int point);

/* Errors of every measured row (against the exact solution, the reference,
 * the value or the variant's finest run) and the observed orders
 *   p = log(e_prev / e) / |log(x / x_prev)|
 * with x the first number of the first points key (cells, dt, eps, ...). */
void sl_bench_errors(sl_bench_table *t);

/* What is measured, in words ("L1 error of phi at t = 60 against ..."). */
void sl_bench_describe_measure(const sl_bench_table *t, char *buf, size_t len);
/* Label of the measured quantity ("phi", "min velocity[0] along 0.5,0:0.5,1"). */
void sl_bench_quantity_label(const sl_study *s, char *buf, size_t len);

int sl_bench_write_csv(const sl_bench_table *t, const char *path, sl_diag *d);
/* Comparisons: positions (or points) down, one column per run. */
int sl_bench_write_compare_csv(const sl_bench_table *t, const char *path, sl_diag *d);
/* The study's figure (bench_plot.c), as PNG (a path ending in .png) or SVG:
 * error against the first points key (when its values are numbers) with
 * reference slopes labelled with the observed order, beside error against
 * CPU time, log-log, one curve per variant; for a comparison the quantity
 * along the line (or against the points) per run, linear axes. */
int sl_bench_write_plot(const sl_bench_table *t, const char *path, sl_diag *d);

#endif
