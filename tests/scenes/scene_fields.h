/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Reading a scene test's output back: a field at a time (all its
 * components) and a scalar, a failure counted as a failed check. */
#ifndef SLUICE_TESTS_SCENES_SCENE_FIELDS_H
#define SLUICE_TESTS_SCENES_SCENE_FIELDS_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "testing.h"

/* Field `name` of `file` at the output nearest t (INFINITY: the last), n
 * entities of its stored components each (1 or 3); its time in *t_found
 * (may be NULL). NULL on failure. The caller frees. */
static inline double *field_at(const char *file, const char *name, double t, int *n, double *t_found) {
  sl_output_field f;
  sl_diag d = {{0}};
  if (sl_output_read_field(file, name, t, &f, &d)) {
    CHECK_MSG(0, "%s: %s: %s", file, name, d.msg);
    return NULL;
  }
  size_t count = (size_t)f.n * (size_t)f.components;
  double *v = malloc(count * sizeof *v);
  if (v) memcpy(v, f.values, count * sizeof *v);
  *n = (int)f.n;
  if (t_found) *t_found = f.time;
  sl_output_field_free(&f);
  return v;
}

/* Scalar `name` of `file` at the output nearest t. */
static inline double scalar(const char *file, const char *name, double t) {
  sl_diag d = {{0}};
  double v = NAN, tf;
  int rc = sl_output_read_scalar(file, name, t, &v, &tf, &d);
  CHECK_MSG(rc == 0, "%s: %s: %s", file, name, d.msg);
  return v;
}

#endif
