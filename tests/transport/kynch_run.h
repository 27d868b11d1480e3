/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A 1-D batch-settling run on the transport module, for the Kynch tests and
 * the work-precision benchmark: a column [0, H] of N cells (x is the height,
 * gravity along -x), walls at both ends, phi = phi0 at t = 0, advanced in
 * outer steps of dt_outer (the engine's step) with sub-cycling inside. */
#ifndef SLUICE_TESTS_KYNCH_RUN_H
#define SLUICE_TESTS_KYNCH_RUN_H

#include <stdio.h>
#include <stdlib.h>

#include "core/mesh/mesh.h"
#include "core/study/kynch_exact.h"
#include "core/transport/transport.h"

typedef struct kr_run {
  sl_mesh *m;
  sl_transport *t;
  double *phi, *w;
  int N;
  double H, time, dt_outer, phi_max;
  double mass0;
  double max_phi, min_phi; /* over every outer step */
  long substeps, outer_steps;
  int fallbacks;
} kr_run;

/* settling: the closure callback (NULL: the law's own, kx_settling). Exits
 * on failure: nothing else makes sense in a test. */
static inline void kr_open(kr_run *r, int N, double H, double phi0, int order, sl_transport_limiter lim,
                           sl_settling_fn settling, void *user, double phi_max) {
  sl_diag d;
  *r = (kr_run){0};
  r->N = N, r->H = H, r->dt_outer = 0.01 * H, r->phi_max = phi_max;
  sl_transport_opts o = {
      .phi_max = phi_max, .order = order, .limiter = lim, .settling = settling, .settling_user = user};
  if (sl_mesh_interval(0, H, N, NULL, &r->m, &d) || sl_transport_create(r->m, &o, &r->t, &d)) {
    fprintf(stderr, "kynch run: %s\n", d.msg);
    exit(1);
  }
  r->phi = malloc((size_t)N * sizeof *r->phi);
  r->w = malloc((size_t)r->m->n_faces * sizeof *r->w);
  if (!r->phi || !r->w) {
    fprintf(stderr, "kynch run: out of memory\n");
    exit(1);
  }
  for (int i = 0; i < N; ++i) r->phi[i] = phi0;
  const double down[2] = {-1, 0};
  sl_transport_settling_uniform(r->t, down, r->w);
  r->mass0 = sl_transport_mass(r->t, r->phi);
  r->max_phi = r->min_phi = phi0;
}

static inline void kr_close(kr_run *r) {
  sl_transport_destroy(r->t);
  sl_mesh_destroy(r->m);
  free(r->phi);
  free(r->w);
}

/* Advances to time `t` (outer steps of dt_outer, the last one shorter). */
static inline void kr_advance(kr_run *r, double t) {
  sl_diag d;
  while (r->time < t * (1 - 1e-14)) {
    double dt = t - r->time < r->dt_outer * (1 + 1e-9) ? t - r->time : r->dt_outer;
    sl_transport_stats st;
    if (sl_transport_step(r->t, dt, NULL, r->w, r->phi, &st, &d)) {
      fprintf(stderr, "kynch run: t = %g: %s\n", r->time, d.msg);
      exit(1);
    }
    r->time = dt == t - r->time ? t : r->time + dt;
    r->substeps += st.n_substeps;
    r->fallbacks += st.n_fallbacks;
    ++r->outer_steps;
    for (int i = 0; i < r->N; ++i) {
      if (r->phi[i] > r->max_phi) r->max_phi = r->phi[i];
      if (r->phi[i] < r->min_phi) r->min_phi = r->phi[i];
    }
  }
}

/* sum_i |phi_i - exact cell average| h_i. */
static inline double kr_l1(const kr_run *r, const kynch *k) {
  kx_profile p = kx_at(k, r->time);
  double s = 0;
  for (int i = 0; i < r->N; ++i) {
    double za = r->m->xy[2 * i], zb = r->m->xy[2 * (i + 1)];
    s += fabs(r->phi[i] * (zb - za) - kx_integral(k, &p, za, zb));
  }
  return s;
}

/* Where phi crosses `level` between cell centres, searching from cell
 * `start` upwards (dir = +1) or downwards (-1): linear interpolation. NAN
 * when it does not. */
static inline double kr_crossing(const kr_run *r, int start, int dir, double level) {
  const double *x = r->m->xy;
  for (int i = start; i + dir >= 0 && i + dir < r->N; i += dir) {
    double a = r->phi[i], b = r->phi[i + dir];
    if ((a - level) * (b - level) <= 0 && a != b) {
      double za = 0.5 * (x[2 * i] + x[2 * i + 2]), zb = 0.5 * (x[2 * (i + dir)] + x[2 * (i + dir) + 2]);
      return za + (zb - za) * (level - a) / (b - a);
    }
  }
  return NAN;
}

/* The cell containing height z. */
static inline int kr_cell(const kr_run *r, double z) {
  int i = (int)(z / r->H * r->N);
  return i < 0 ? 0 : i >= r->N ? r->N - 1 : i;
}

#endif
