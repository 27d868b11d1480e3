/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A base acceleration record (an earthquake's or a synthetic one): a
 * two-column CSV of time (s) and acceleration, read once, interpolated
 * linearly, zero outside its time span. */
#ifndef SLUICE_MODELS_TWO_FLUID_BASE_RECORD_H
#define SLUICE_MODELS_TWO_FLUID_BASE_RECORD_H

#include "core/util/diag.h"

typedef struct tf_base_record {
  int n;
  double *t, *a; /* [n], a in m s^-2 after scaling */
  double peak;   /* max |a|, m s^-2 */
} tf_base_record;

/* Reads `path` (relative paths from the directory of `scene_file`): lines of
 * "time, acceleration" (comma, semicolon, tab or blanks between them);
 * blank lines, lines starting with '#' and one header line that is not two
 * numbers are skipped. `to_si` multiplies the accelerations (9.81 for a
 * record in g), then, when peak > 0, they are scaled so that the largest
 * |a| is `peak` (m s^-2). Times must increase strictly. 0, or SL_EBADINPUT
 * naming file:line of the bad row (where: the key's "file:line: [s] key"). */
int tf_base_record_read(tf_base_record *r, const char *path, const char *scene_file, double to_si, double peak,
                        const char *where, sl_diag *d);
/* a(t): linear between samples, 0 before the first and after the last. */
double tf_base_record_at(const tf_base_record *r, double t);
/* The record's last time. */
double tf_base_record_end(const tf_base_record *r);
void tf_base_record_free(tf_base_record *r);

#endif
