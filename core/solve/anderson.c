/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Anderson acceleration (see anderson.h). */
#include "core/solve/anderson.h"

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

/* Solves the m x m system gram gamma = rhs in place by elimination with
 * partial pivoting; 0 when no pivot falls below ANDERSON_PIVOT of the
 * largest diagonal. */
static int solve_normal(int m, double *A, double *b, double *x) {
  double big = 0.0;
  for (int i = 0; i < m; ++i) big = fmax(big, A[i * m + i]);
  if (!(big > 0.0)) return -1;
  for (int c = 0; c < m; ++c) {
    int p = c;
    for (int r = c + 1; r < m; ++r)
      if (fabs(A[r * m + c]) > fabs(A[p * m + c])) p = r;
    if (!(fabs(A[p * m + c]) > ANDERSON_PIVOT * big)) return -1;
    if (p != c) {
      for (int k = 0; k < m; ++k) {
        double t = A[c * m + k];
        A[c * m + k] = A[p * m + k], A[p * m + k] = t;
      }
      double t = b[c];
      b[c] = b[p], b[p] = t;
    }
    for (int r = c + 1; r < m; ++r) {
      double l = A[r * m + c] / A[c * m + c];
      for (int k = c; k < m; ++k) A[r * m + k] -= l * A[c * m + k];
      b[r] -= l * b[c];
    }
  }
  for (int r = m - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < m; ++k) s -= A[r * m + k] * x[k];
    x[r] = s / A[r * m + r];
  }
  return 0;
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
    if (solve_normal(m, a->gram, a->rhs, a->gamma) == 0) break;
    drop_oldest(a), ++a->dropped;
  }
  for (int p = 0; p < a->count; ++p) {
    const double *Gp = a->dG + (size_t)p * nn, gp = a->gamma[p];
    for (int i = 0; i < n; ++i) g[i] -= gp * Gp[i];
  }
}
