/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Anderson acceleration (see anderson.h). */
#include "core/solve/anderson.h"

#include "core/solve/dense.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Differences whose normal equations pivot below this fraction of the
 * largest diagonal are nearly dependent: the oldest is dropped. */
static const double ANDERSON_PIVOT = 1e-13;

int sl_anderson_init(sl_anderson *a, int n, int depth, sl_diag *d) {
  memset(a, 0, sizeof *a);
  if (n <= 0 || depth < 1 || depth > SL_ANDERSON_MAX_DEPTH)
    return sl_diag_set(d, SL_EFAILED, "Anderson acceleration: %d unknowns, depth %d (1..%d)", n, depth,
                       SL_ANDERSON_MAX_DEPTH);
  a->n = n, a->depth = depth;
  size_t nn = (size_t)n;
  a->dF = malloc((size_t)depth * nn * sizeof *a->dF);
  a->dG = malloc((size_t)depth * nn * sizeof *a->dG);
  a->f_prev = malloc(nn * sizeof *a->f_prev);
  a->g_prev = malloc(nn * sizeof *a->g_prev);
  a->f = malloc(nn * sizeof *a->f);
  if (!a->dF || !a->dG || !a->f_prev || !a->g_prev || !a->f) {
    sl_anderson_free(a);
    return sl_diag_set(d, SL_ENOMEM, "Anderson acceleration: out of memory");
  }
  return 0;
}

void sl_anderson_free(sl_anderson *a) {
  free(a->dF), free(a->dG), free(a->f_prev), free(a->g_prev), free(a->f);
  memset(a, 0, sizeof *a);
}

void sl_anderson_reset(sl_anderson *a) { a->count = 0, a->have_prev = 0, a->dropped = 0; }

static void drop_oldest(sl_anderson *a) {
  size_t nn = (size_t)a->n;
  memmove(a->dF, a->dF + nn, (size_t)(a->count - 1) * nn * sizeof *a->dF);
  memmove(a->dG, a->dG + nn, (size_t)(a->count - 1) * nn * sizeof *a->dG);
  --a->count;
}

void sl_anderson_apply(sl_anderson *a, const double *x, double *g, const double *scale) {
  const int n = a->n;
  const size_t nn = (size_t)n;
  for (int i = 0; i < n; ++i) a->f[i] = (g[i] - x[i]) / scale[i];
  if (a->have_prev) {
    if (a->count == a->depth) drop_oldest(a);
    double *dF = a->dF + (size_t)a->count * nn, *dG = a->dG + (size_t)a->count * nn;
    for (int i = 0; i < n; ++i) dF[i] = a->f[i] - a->f_prev[i], dG[i] = g[i] - a->g_prev[i];
    ++a->count;
  }
  memcpy(a->f_prev, a->f, nn * sizeof *a->f);
  memcpy(a->g_prev, g, nn * sizeof *g);
  a->have_prev = 1;
  while (a->count > 0) {
    const int m = a->count;
    for (int p = 0; p < m; ++p) {
      const double *Fp = a->dF + (size_t)p * nn;
      double r = 0.0;
      for (int i = 0; i < n; ++i) r += Fp[i] * a->f[i];
      a->rhs[p] = r;
      for (int q = 0; q <= p; ++q) {
        const double *Fq = a->dF + (size_t)q * nn;
        double s = 0.0;
        for (int i = 0; i < n; ++i) s += Fp[i] * Fq[i];
        a->gram[p * m + q] = a->gram[q * m + p] = s;
      }
    }
    if (sl_dense_solve(m, a->gram, a->rhs, a->gamma, ANDERSON_PIVOT) == 0) break;
    drop_oldest(a), ++a->dropped;
  }
  for (int p = 0; p < a->count; ++p) {
    const double *Gp = a->dG + (size_t)p * nn, gp = a->gamma[p];
    for (int i = 0; i < n; ++i) g[i] -= gp * Gp[i];
  }
}
