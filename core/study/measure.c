/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Measuring a run's output (see measure.h). */
#include "core/study/measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/io/sample.h"

static int oom(sl_diag *d) { return sl_diag_set(d, SL_ENOMEM, "measure: out of memory"); }

static int alloc_profile(sl_bench_measured *m, int n, int with_ref, sl_diag *d) {
  m->is_profile = 1, m->n = n;
  m->s = malloc((size_t)n * sizeof *m->s), m->w = malloc((size_t)n * sizeof *m->w);
  m->v = malloc((size_t)n * sizeof *m->v);
  m->ref = with_ref ? malloc((size_t)n * sizeof *m->ref) : NULL;
  if (!m->s || !m->w || !m->v || (with_ref && !m->ref)) return oom(d);
  return 0;
}

void sl_bench_measured_free(sl_bench_measured *m) {
  free(m->s), free(m->w), free(m->v), free(m->ref);
  memset(m, 0, sizeof *m);
}

double sl_bench_norm(sl_study_norm norm, int n, const double *w, const double *a, const double *b) {
  double acc = 0.0;
  for (int i = 0; i < n; ++i) {
    double e = fabs(a[i] - b[i]);
    if (norm == SL_NORM_MAX) acc = fmax(acc, e);
    else if (norm == SL_NORM_L1) acc += w[i] * e;
    else acc += w[i] * e * e;
    if (isnan(e)) return NAN;
  }
  return norm == SL_NORM_L2 ? sqrt(acc) : acc;
}

/* Trapezoidal weights of the positions s, scaled to sum to 1. */
static void trapezoid(int n, const double *s, double *w) {
  if (n == 1) {
    w[0] = 1.0;
    return;
  }
  double span = s[n - 1] - s[0];
  for (int i = 0; i < n; ++i) {
    double lo = i > 0 ? s[i - 1] : s[i], hi = i + 1 < n ? s[i + 1] : s[i];
    w[i] = 0.5 * (hi - lo) / span;
  }
}

/* The output time asked for must be one the run wrote. */
static int check_time(const sl_study_measure *sm, double found, const char *what, sl_diag *d) {
  if (!sm->has_time || fabs(found - sm->time) <= 1e-9 * fmax(1.0, fabs(sm->time))) return 0;
  return sl_diag_set(
      d, SL_EBADINPUT,
      "measure: %s: no output at t = %g (the nearest is t = %g): make it an output time ([set.output] every, "
      "time.end)",
      what, sm->time, found);
}

/* ---- along a line ------------------------------------------------------------- */

typedef struct line {
  double a[2], b[2], length;
} line;

static void line_point(const line *l, double t, double *xy) {
  xy[0] = l->a[0] + t * (l->b[0] - l->a[0]), xy[1] = l->a[1] + t * (l->b[1] - l->a[1]);
}

/* The field's component at n points; points outside the mesh are an error. */
static int sample(const char *h5, const sl_study_measure *sm, double t, int n, const double *xy, double *v,
                  double *time, sl_diag *d) {
  sl_sample s;
  int rc = sl_sample_points(h5, sm->name, t, n, xy, &s, d);
  if (rc) return sl_diag_prefix(d, rc, "measure");
  if (sm->component >= s.components)
    rc = sl_diag_set(d, SL_EBADINPUT, "measure: '%s' has %d component%s, component = %d asked", sm->name, s.components,
                     s.components == 1 ? "" : "s", sm->component);
  else if (s.n_outside > 0) {
    int k = 0;
    while (k < n && !isnan(s.values[(size_t)k * (size_t)s.components])) ++k;
    rc = sl_diag_set(d, SL_EBADINPUT, "measure: %d of %d points of the line lie outside the mesh (the first at %g, %g)",
                     s.n_outside, n, xy[2 * k], xy[2 * k + 1]);
  }
  for (int k = 0; k < n && !rc; ++k) v[k] = s.values[(size_t)k * (size_t)s.components + (size_t)sm->component];
  if (time) *time = s.time;
  sl_sample_free(&s);
  return rc;
}

/* Minimum (sign = 1) or maximum (sign = -1) along the line: the best of the
 * samples, then golden-section search between its neighbours. */
static int extremum(const char *h5, const sl_study_measure *sm, const line *l, double t, const double *v, int n,
                    double sign, double *out, sl_diag *d) {
  int best = 0;
  for (int k = 1; k < n; ++k)
    if (sign * v[k] < sign * v[best]) best = k;
  const double g = 0.5 * (sqrt(5.0) - 1.0);
  double a = (best > 0 ? best - 1.0 : 0.0) / (n - 1), b = (best + 1 < n ? best + 1.0 : n - 1.0) / (n - 1);
  double c = b - g * (b - a), e = a + g * (b - a), fc = 0.0, fe = 0.0, xy[2]; /* unset when a sample fails */
  line_point(l, c, xy);
  int rc = sample(h5, sm, t, 1, xy, &fc, NULL, d);
  line_point(l, e, xy);
  if (!rc) rc = sample(h5, sm, t, 1, xy, &fe, NULL, d);
  fc *= sign, fe *= sign;
  while (!rc && b - a > 1e-10) {
    if (fc < fe) {
      b = e, e = c, fe = fc, c = b - g * (b - a);
      line_point(l, c, xy);
      rc = sample(h5, sm, t, 1, xy, &fc, NULL, d);
      fc *= sign;
    } else {
      a = c, c = e, fc = fe, e = a + g * (b - a);
      line_point(l, e, xy);
      rc = sample(h5, sm, t, 1, xy, &fe, NULL, d);
      fe *= sign;
    }
  }
  if (rc) return rc;
  *out = sign * fmin(fmin(fc, fe), sign * v[best]);
  return 0;
}

/* The line of the measure; a 1-D mesh without one: the whole mesh. */
static int measure_line(const sl_study_measure *sm, const char *h5, const sl_bench_exact *exact, line *l, sl_diag *d) {
  memset(l, 0, sizeof *l);
  if (sm->has_line) {
    l->a[0] = sm->line[0], l->a[1] = sm->line[1], l->b[0] = sm->line[2], l->b[1] = sm->line[3];
  } else if (exact) {
    sl_bench_exact_domain(exact, &l->a[0], &l->b[0]);
  } else {
    sl_output_mesh mesh;
    int rc = sl_output_read_mesh(h5, &mesh, d);
    if (rc) return sl_diag_prefix(d, rc, "measure");
    if (mesh.dim != 1) {
      sl_output_mesh_free(&mesh);
      return sl_diag_set(d, SL_EBADINPUT, "measure: a 2-D mesh: give [measure] line = x0,y0:x1,y1");
    }
    l->a[0] = INFINITY, l->b[0] = -INFINITY;
    for (int v = 0; v < mesh.n_vertices; ++v)
      l->a[0] = fmin(l->a[0], mesh.coords[3 * v]), l->b[0] = fmax(l->b[0], mesh.coords[3 * v]);
    sl_output_mesh_free(&mesh);
  }
  l->length = hypot(l->b[0] - l->a[0], l->b[1] - l->a[1]);
  return 0;
}

static int measure_field(const sl_study *st, const sl_bench_exact *exact, const char *h5, sl_bench_measured *m,
                         sl_diag *d) {
  const sl_study_measure *sm = &st->m;
  line l;
  int rc = measure_line(sm, h5, exact, &l, d);
  if (rc) return rc;
  int by_reference = sm->against == SL_AGAINST_REFERENCE;
  int n = by_reference ? sm->n_ref : sm->n;
  double *xy = malloc((size_t)n * 2 * sizeof *xy), *v = malloc((size_t)n * sizeof *v);
  if (!xy || !v) {
    free(xy), free(v);
    return oom(d);
  }
  for (int k = 0; k < n; ++k) {
    double t = by_reference ? sm->ref_x[k] / l.length : (double)k / (n - 1);
    line_point(&l, t, xy + 2 * k);
  }
  m->line[0] = l.a[0], m->line[1] = l.a[1], m->line[2] = l.b[0], m->line[3] = l.b[1];
  double t_asked = sm->has_time ? sm->time : INFINITY;
  rc = sample(h5, sm, t_asked, n, xy, v, &m->time, d);
  if (!rc) rc = check_time(sm, m->time, sm->name, d);
  if (!rc && sm->reduce != SL_REDUCE_NONE) {
    m->is_profile = 0;
    rc = extremum(h5, sm, &l, m->time, v, n, sm->reduce == SL_REDUCE_MIN ? 1.0 : -1.0, &m->scalar, d);
  } else if (!rc) {
    int with_ref = exact || by_reference;
    if (!(rc = alloc_profile(m, n, with_ref, d))) {
      for (int k = 0; k < n; ++k) m->s[k] = by_reference ? sm->ref_x[k] : l.length * k / (n - 1), m->v[k] = v[k];
      trapezoid(n, m->s, m->w);
      if (by_reference) memcpy(m->ref, sm->ref_v, (size_t)n * sizeof *m->ref);
      if (exact) {
        double *x = malloc((size_t)n * sizeof *x);
        if (!x) rc = oom(d);
        for (int k = 0; k < n && !rc; ++k) x[k] = xy[2 * k];
        if (!rc) sl_bench_exact_values(exact, m->time, n, x, m->ref);
        free(x);
      }
    }
  }
  free(xy), free(v);
  return rc;
}

/* Cell averages of phi against the exact ones, over the cells of the part
 * of the column the exact solution compares (sl_bench_exact_compared_span:
 * the whole column, or a fluidised bed below its top). */
static int measure_cells(const sl_study *st, const sl_bench_exact *exact, const char *h5, sl_bench_measured *m,
                         sl_diag *d) {
  const sl_study_measure *sm = &st->m;
  sl_output_field f;
  sl_output_mesh mesh;
  int rc = sl_output_read_field(h5, sm->name, sm->has_time ? sm->time : INFINITY, &f, d);
  if (rc) return sl_diag_prefix(d, rc, "measure");
  if ((rc = sl_output_read_mesh(h5, &mesh, d))) {
    sl_output_field_free(&f);
    return sl_diag_prefix(d, rc, "measure");
  }
  m->time = f.time;
  rc = check_time(sm, f.time, sm->name, d);
  if (!rc && (f.centring != SL_CENTRE_CELL || f.n != mesh.n_cells || mesh.dim != 1 || f.components != 1))
    rc = sl_diag_set(d, SL_EBADINPUT, "measure: '%s' is not a scalar cell field of a 1-D mesh", sm->name);
  int n = rc ? 0 : (int)f.n;
  double *xa = NULL, *xb = NULL, x0 = 0.0, x1 = 0.0, lo = 0.0, hi = 0.0;
  if (!rc) {
    xa = malloc((size_t)n * sizeof *xa), xb = malloc((size_t)n * sizeof *xb);
    if (!xa || !xb) rc = oom(d);
  }
  for (int c = 0; c < n && !rc; ++c) {
    double a = INFINITY, b = -INFINITY;
    for (int k = 0; k < mesh.nodes_per_cell; ++k) {
      double x = mesh.coords[3 * (size_t)mesh.cells[(size_t)c * (size_t)mesh.nodes_per_cell + (size_t)k]];
      a = fmin(a, x), b = fmax(b, x);
    }
    xa[c] = a, xb[c] = b;
  }
  int used = 0;
  if (!rc) {
    sl_bench_exact_domain(exact, &x0, &x1);
    sl_bench_exact_compared_span(exact, n, xa, xb, f.values, &lo, &hi);
    const double slack = 1e-12 * (x1 - x0);
    for (int c = 0; c < n; ++c) /* the cells inside [lo, hi], moved to the front */
      if (xa[c] >= lo - slack && xb[c] <= hi + slack)
        xa[used] = xa[c], xb[used] = xb[c], f.values[used++] = f.values[c];
    if (used == 0)
      rc = sl_diag_set(d, SL_EFAILED, "measure: no whole cell of the mesh lies in the part compared, %g to %g", lo, hi);
  }
  if (!rc && !(rc = alloc_profile(m, used, 1, d))) {
    m->line[0] = lo, m->line[2] = hi;
    double length = 0.0;
    for (int c = 0; c < used; ++c) length += xb[c] - xa[c];
    for (int c = 0; c < used; ++c)
      m->s[c] = 0.5 * (xa[c] + xb[c]) - x0, m->w[c] = (xb[c] - xa[c]) / length, m->v[c] = f.values[c];
    sl_bench_exact_averages(exact, m->time, used, xa, xb, m->ref);
  }
  free(xa), free(xb);
  sl_output_field_free(&f);
  sl_output_mesh_free(&mesh);
  return rc;
}

static int measure_scalar(const sl_study *st, const char *h5, sl_bench_measured *m, sl_diag *d) {
  const sl_study_measure *sm = &st->m;
  double tf;
  if (sm->against != SL_AGAINST_REFERENCE) {
    int rc = sl_output_read_scalar(h5, sm->name, sm->has_time ? sm->time : INFINITY, &m->scalar, &tf, d);
    if (rc) return sl_diag_prefix(d, rc, "measure");
    m->time = tf;
    return check_time(sm, tf, sm->name, d);
  }
  int rc = alloc_profile(m, sm->n_ref, 1, d);
  m->time = NAN;
  for (int k = 0; k < sm->n_ref && !rc; ++k) {
    rc = sl_output_read_scalar(h5, sm->name, sm->ref_x[k], &m->v[k], &tf, d);
    if (rc) return sl_diag_prefix(d, rc, "measure");
    if (fabs(tf - sm->ref_x[k]) > 1e-9 * fmax(1.0, fabs(sm->ref_x[k])))
      return sl_diag_set(d, SL_EBADINPUT,
                         "measure: %s: no output at the reference's t = %g (the nearest is t = %g): make the reference "
                         "times output times",
                         sm->name, sm->ref_x[k], tf);
    m->s[k] = sm->ref_x[k], m->ref[k] = sm->ref_v[k];
  }
  if (!rc) trapezoid(sm->n_ref, m->s, m->w);
  return rc;
}

int sl_bench_measure(const sl_study *st, const sl_bench_exact *exact, const char *h5, sl_bench_measured *m,
                     sl_diag *d) {
  memset(m, 0, sizeof *m);
  m->time = NAN, m->scalar = NAN;
  int rc;
  if (st->m.scalar) rc = measure_scalar(st, h5, m, d);
  else if (exact && sl_bench_exact_cell_averages(exact)) rc = measure_cells(st, exact, h5, m, d);
  else rc = measure_field(st, exact, h5, m, d);
  if (rc) sl_bench_measured_free(m);
  return rc;
}
