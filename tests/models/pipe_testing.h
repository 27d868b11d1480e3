/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What the pipe model's tests share: a scene run from its text, a scalar of
 * the output, Churchill's friction factor. */
#ifndef SLUICE_TESTS_PIPE_TESTING_H
#define SLUICE_TESTS_PIPE_TESTING_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/io/output.h"
#include "sluice/sluice.h"
#include "testing.h"

/* Runs the scene `text` (named `name` in messages) with the overrides into out; 0 or the error code, e says why. */
static inline int pipe_run_text(const char *text, const char *name, const char *const *sets, const char *out,
                                sluice_error *e) {
  sluice *s = NULL;
  sluice_open_opts oo = {.sets = sets};
  sluice_run_opts ro = {.output = out, .version = "test"};
  sluice_summary sum;
  int rc = sluice_open_text(text, strlen(text), name, &oo, &s, e);
  if (!rc) rc = sluice_run(s, &ro, &sum, e);
  sluice_close(s);
  return rc;
}

/* The output's last value of the scalar `name` (a failed check and NaN if it has none). */
static inline double pipe_scalar(const char *out, const char *name) {
  double v = NAN, t;
  sl_diag d = {{0}};
  int rc = sl_output_read_scalar(out, name, INFINITY, &v, &t, &d);
  CHECK_MSG(rc == 0, "%s: %s", out, d.msg);
  return v;
}

/* configs/vertical_pipe.ini into text, and the same without its [closure.granular] (Krampa's model C replaces the
   kinetic theory) into cut; 0, or 1 after a failed check. */
static inline int pipe_vertical_without_granular(char *text, size_t tcap, char *cut, size_t ccap) {
  if (sl_test_read_source("configs/vertical_pipe.ini", text, tcap)) return 1;
  char *gran = strstr(text, "\n[closure.granular]");
  CHECK_MSG(gran != NULL, "vertical_pipe.ini has no [closure.granular]");
  if (!gran) return 1;
  snprintf(cut, ccap, "%.*s\n", (int)(gran - text), text);
  return 0;
}

/* A cell field with the cells' radii, sorted from the axis out (n cells). */
typedef struct profile {
  int n;
  double r[512], v[512], lo[512], hi[512]; /* centre, faces, value */
} profile;

static inline int read_profile(const char *out, const char *name, profile *p) {
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, name, INFINITY, &f, &d) || sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  p->n = f.n < 512 ? f.n : 512;
  for (int c = 0; c < p->n; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < m.nodes_per_cell; ++k) {
      double x = m.coords[3 * m.cells[c * m.nodes_per_cell + k]];
      lo = fmin(lo, x), hi = fmax(hi, x);
    }
    p->r[c] = 0.5 * (lo + hi), p->lo[c] = lo, p->hi[c] = hi, p->v[c] = f.values[c];
  }
  for (int i = 1; i < p->n; ++i) /* insertion sort by r */
    for (int j = i; j > 0 && p->r[j] < p->r[j - 1]; --j) {
      double *a[4] = {p->r, p->v, p->lo, p->hi};
      for (int k = 0; k < 4; ++k) {
        double t = a[k][j];
        a[k][j] = a[k][j - 1], a[k][j - 1] = t;
      }
    }
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
  return 0;
}

/* Churchill (1977), Fanning, smooth (Krampa 2009 eqs 2.12-2.13 with k = 0). */
static inline double pipe_churchill(double Re) {
  double A = pow(-2.457 * log(pow(7.0 / Re, 0.9)), 16.0), B = pow(37530.0 / Re, 16.0);
  return 2.0 * pow(pow(8.0 / Re, 12.0) + pow(A + B, -1.5), 1.0 / 12.0);
}

#endif
