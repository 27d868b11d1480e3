/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What a study measures in one run's output file ([measure] of the study):
 *  - a field sampled at evenly spaced points of a line (core/io/sample.h;
 *    on a 1-D mesh the whole mesh when no line is given), or at the
 *    positions of a reference file, optionally reduced to its minimum or
 *    maximum along the line (refined by golden-section search between the
 *    samples);
 *  - with exact = kynch, the cell averages of phi over the whole column;
 *    with exact = fluidized_bed, phi in the cells of the bed at rest;
 *  - an output scalar at one output time, or at each time of a reference.
 * The result is one number or a profile: positions (arc length from the
 * line's start, or times), quadrature weights that sum to 1 (trapezoidal
 * rule, or cell lengths over the column's), values, and the reference
 * values at the same positions when there are any. The error of a profile
 * is a norm of the difference with these weights:
 *   l1 = sum w |e|,  l2 = sqrt(sum w e^2),  max = max |e|,
 * i.e. the mean and root-mean-square difference over the line. */
#ifndef SLUICE_BENCH_MEASURE_H
#define SLUICE_BENCH_MEASURE_H

#include "core/study/exact.h"
#include "core/study/study.h"

typedef struct sl_bench_measured {
  double time;    /* the output time measured (NaN for a scalar against reference times) */
  int is_profile; /* 0: one number, `scalar` */
  double scalar;
  int n;
  double *s, *w, *v, *ref; /* ref NULL when nothing to compare with */
  double line[4];          /* the line sampled (x0, y0, x1, y1), for labels */
} sl_bench_measured;

/* Measures one output file. exact: the run's exact solution (NULL unless
 * the study measures against one). Returns 0; SL_EBADINPUT when the output
 * does not hold what [measure] asks (an unknown field or scalar, a time
 * that is not an output time, a line outside the mesh): a mistake of the
 * study, not of the run; SL_EFAILED when the file cannot be read. */
int sl_bench_measure(const sl_study *st, const sl_bench_exact *exact, const char *h5, sl_bench_measured *m, sl_diag *d);
void sl_bench_measured_free(sl_bench_measured *m);

/* The norm of a - b with weights w over n points. */
double sl_bench_norm(sl_study_norm norm, int n, const double *w, const double *a, const double *b);

#endif
