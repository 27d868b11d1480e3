/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The base acceleration record of a shaken column (base_record.h). */
#include "core/models/two_fluid/base_record.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int two_numbers(const char *s, double *x, double *y) {
  char *end;
  errno = 0;
  *x = strtod(s, &end);
  if (end == s || errno) return 0;
  s = end;
  while (*s == ' ' || *s == '\t' || *s == ',' || *s == ';') ++s;
  const char *b = s;
  *y = strtod(b, &end);
  if (end == b || errno) return 0;
  for (s = end; *s; ++s)
    if (*s != ' ' && *s != '\t' && *s != '\r' && *s != '\n' && *s != ',' && *s != ';') return 0;
  return isfinite(*x) && isfinite(*y);
}

int tf_base_record_read(tf_base_record *r, const char *path, const char *scene_file, double to_si, double peak,
                        const char *where, sl_diag *d) {
  memset(r, 0, sizeof *r);
  char full[4096];
  if (path[0] != '/' && scene_file && strrchr(scene_file, '/')) {
    int len = (int)(strrchr(scene_file, '/') - scene_file);
    snprintf(full, sizeof full, "%.*s/%s", len, scene_file, path);
  } else {
    snprintf(full, sizeof full, "%s", path);
  }
  FILE *f = fopen(full, "r");
  if (!f) return sl_diag_set(d, SL_EBADINPUT, "%s: cannot open the base record '%s': %s", where, full, strerror(errno));
  char line[1024];
  int cap = 0, lineno = 0, skipped_header = 0, rc = 0;
  while (!rc && fgets(line, sizeof line, f)) {
    ++lineno;
    const char *s = line;
    while (*s == ' ' || *s == '\t') ++s;
    if (*s == '#' || *s == '\n' || *s == '\r' || *s == 0) continue;
    double x, y;
    if (!two_numbers(s, &x, &y)) {
      if (r->n == 0 && !skipped_header) {
        skipped_header = 1;
        continue;
      }
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: the base record needs two numbers per row (time in s, acceleration)",
                       full, lineno);
      break;
    }
    if (r->n > 0 && !(x > r->t[r->n - 1])) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: time %g does not follow %g: the record's times must increase", full,
                       lineno, x, r->t[r->n - 1]);
      break;
    }
    if (r->n == cap) {
      cap = cap ? 2 * cap : 1024;
      double *t = realloc(r->t, (size_t)cap * sizeof *t), *a = t ? realloc(r->a, (size_t)cap * sizeof *a) : NULL;
      if (t) r->t = t;
      if (!t || !a) {
        rc = sl_diag_set(d, SL_ENOMEM, "base record: out of memory");
        break;
      }
      r->a = a;
    }
    r->t[r->n] = x, r->a[r->n] = y * to_si, ++r->n;
  }
  fclose(f);
  if (!rc && r->n < 2)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: the base record '%s' has %d rows (at least 2)", where, full, r->n);
  if (!rc) {
    double m = 0.0;
    for (int i = 0; i < r->n; ++i) m = fmax(m, fabs(r->a[i]));
    if (peak > 0.0) {
      if (m == 0.0)
        rc = sl_diag_set(d, SL_EBADINPUT, "%s: the base record '%s' is all zeros: it cannot be scaled", where, full);
      for (int i = 0; i < r->n && !rc; ++i) r->a[i] *= peak / m;
      m = peak;
    }
    r->peak = m;
  }
  if (rc) tf_base_record_free(r);
  return rc;
}

double tf_base_record_at(const tf_base_record *r, double t) {
  if (r->n < 2 || t < r->t[0] || t > r->t[r->n - 1]) return 0.0;
  int lo = 0, hi = r->n - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (r->t[mid] <= t) lo = mid;
    else hi = mid;
  }
  double w = (t - r->t[lo]) / (r->t[hi] - r->t[lo]);
  return r->a[lo] + w * (r->a[hi] - r->a[lo]);
}

double tf_base_record_end(const tf_base_record *r) { return r->n ? r->t[r->n - 1] : 0.0; }

void tf_base_record_free(tf_base_record *r) {
  free(r->t), free(r->a);
  r->t = r->a = NULL, r->n = 0;
}
