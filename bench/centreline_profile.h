/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The cavity's reference centreline profile (bench/freefem/cavity_centreline_ref.csv)
 * and the error of a profile sampled at its points, shared by
 * bench_cavity_work_precision and bench_cavity_vs_freefem. */
#ifndef SLUICE_BENCH_CENTRELINE_PROFILE_H
#define SLUICE_BENCH_CENTRELINE_PROFILE_H

enum { CENTRELINE_MAX_POINTS = 2049 };

typedef struct centreline_profile {
  int n;
  double y[CENTRELINE_MAX_POINTS], u[CENTRELINE_MAX_POINTS];
} centreline_profile;

/* Columns y and velocity_0 of a `sluice sample` CSV (by name; '#' lines
 * skipped), y ascending, 2 to CENTRELINE_MAX_POINTS rows. 0, or -1 with a
 * message on stderr. */
int centreline_profile_read(const char *path, centreline_profile *p);

/* Max-norm and L2 norm (trapezoid rule in y) of u[k] - ref->u[k]; -1 when
 * a value is not finite (the norms are then NaN), else 0. */
int centreline_profile_error(const centreline_profile *ref, const double *u, double *emax, double *el2);

#endif
