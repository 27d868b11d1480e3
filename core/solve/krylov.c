/* SPDX-License-Identifier: GPL-2.0-or-later */
/* FGMRES(m) (see krylov.h), after Saad 2003, Algorithm 9.6. */
#include "core/solve/krylov.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int sl_krylov_init(sl_krylov *k, int32_t n, int m, sl_diag *d) {
  memset(k, 0, sizeof *k);
  if (n <= 0 || m <= 0) return sl_diag_set(d, SL_EBADINPUT, "krylov: %d unknowns, space of dimension %d", (int)n, m);
  size_t nn = (size_t)n, mm = (size_t)m;
  k->V = malloc((mm + 1) * nn * sizeof *k->V);
  k->Z = malloc(mm * nn * sizeof *k->Z);
  k->H = calloc((mm + 1) * mm, sizeof *k->H);
  k->cs = malloc(mm * sizeof *k->cs), k->sn = malloc(mm * sizeof *k->sn);
  k->g = malloc((mm + 1) * sizeof *k->g), k->y = malloc(mm * sizeof *k->y);
  k->r = malloc(nn * sizeof *k->r);
  if (!k->V || !k->Z || !k->H || !k->cs || !k->sn || !k->g || !k->y || !k->r) {
    sl_krylov_free(k);
    return sl_diag_set(d, SL_EFAILED, "krylov: out of memory for %d unknowns x %d vectors", (int)n, 2 * m + 1);
  }
  k->n = n, k->m = m;
  return 0;
}

void sl_krylov_free(sl_krylov *k) {
  free(k->V), free(k->Z), free(k->H), free(k->cs), free(k->sn), free(k->g), free(k->y), free(k->r);
  memset(k, 0, sizeof *k);
}

static double dot(const double *x, const double *y, int32_t n) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s += x[i] * y[i];
  return s;
}

/* r = b - A x; returns |r|_2 (x all zero: r = b without applying A). */
static int residual(sl_krylov_apply_fn A, void *user, const double *b, const double *x, double *r, int32_t n,
                    double *norm, sl_diag *d) {
  int zero = 1;
  for (int32_t i = 0; i < n && zero; ++i) zero = x[i] == 0.0;
  if (zero) {
    memcpy(r, b, (size_t)n * sizeof *r);
  } else {
    int rc = A(user, x, r, d);
    if (rc) return rc;
    for (int32_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
  }
  *norm = sqrt(dot(r, r, n));
  return 0;
}

int sl_fgmres(sl_krylov *k, sl_krylov_apply_fn A, void *A_user, sl_krylov_apply_fn M, void *M_user, const double *b,
              double *x, const sl_krylov_opts *opts, sl_krylov_result *res, sl_diag *d) {
  const int32_t n = k->n;
  const size_t nn = (size_t)n;
  double rtol = opts && opts->rtol > 0 ? opts->rtol : 1e-10;
  int m = opts && opts->restart > 0 ? opts->restart : 30;
  if (m > k->m) m = k->m;
  int max_it = opts && opts->max_iterations > 0 ? opts->max_iterations : 100;
  int predict = opts ? opts->predict : 0, trust = opts ? opts->trust_estimate : 0;
  memset(res, 0, sizeof *res);

  double bnorm = sqrt(dot(b, b, n)), beta;
  int rc = residual(A, A_user, b, x, k->r, n, &beta, d);
  if (rc) return rc;
  res->residual0 = res->residual = beta;
  res->rate = 0.0;
  if (!isfinite(beta)) return sl_diag_set(d, SL_EFAILED, "krylov: the initial residual is not finite");
  const double target = rtol * bnorm;
  if (beta <= target) return 0; /* b = 0 with x = 0, or a guess already good enough */

  int total = 0, stagnated = 0;
  double *V = k->V, *Z = k->Z, *H = k->H, *g = k->g;
  for (;;) {
    for (int32_t i = 0; i < n; ++i) V[i] = k->r[i] / beta;
    memset(g, 0, ((size_t)m + 1) * sizeof *g);
    g[0] = beta;
    int j = 0, done = 0, reached = 0;
    while (j < m && total < max_it && !done) {
      double *v = V + (size_t)j * nn, *z = Z + (size_t)j * nn, *w = V + (size_t)(j + 1) * nn;
      if (M) {
        if ((rc = M(M_user, v, z, d))) return rc;
      } else {
        memcpy(z, v, nn * sizeof *z);
      }
      if ((rc = A(A_user, z, w, d))) return rc;
      double *h = H + (size_t)j * ((size_t)m + 1); /* column j */
      double wnorm0 = sqrt(dot(w, w, n));
      for (int i = 0; i <= j; ++i) { /* modified Gram-Schmidt */
        const double *vi = V + (size_t)i * nn;
        double hij = dot(w, vi, n);
        h[i] = hij;
        for (int32_t q = 0; q < n; ++q) w[q] -= hij * vi[q];
      }
      double hn = sqrt(dot(w, w, n));
      if (!isfinite(hn) || !isfinite(wnorm0))
        return sl_diag_set(d, SL_EFAILED, "krylov: the Arnoldi vector %d is not finite", total + 1);
      /* a new direction at round-off of A z: the space holds the solution ("happy breakdown") */
      int breakdown = !(hn > 16.0 * DBL_EPSILON * wnorm0);
      h[j + 1] = hn;
      if (!breakdown)
        for (int32_t q = 0; q < n; ++q) w[q] /= hn;
      /* the previous rotations on column j, then the one that zeroes h[j + 1] */
      for (int i = 0; i < j; ++i) {
        double t = k->cs[i] * h[i] + k->sn[i] * h[i + 1];
        h[i + 1] = -k->sn[i] * h[i] + k->cs[i] * h[i + 1];
        h[i] = t;
      }
      double den = hypot(h[j], h[j + 1]);
      if (den == 0.0)
        return sl_diag_set(d, SL_EFAILED, "krylov: singular Hessenberg matrix at iteration %d", total + 1);
      k->cs[j] = h[j] / den, k->sn[j] = h[j + 1] / den;
      h[j] = den, h[j + 1] = 0.0;
      g[j + 1] = -k->sn[j] * g[j];
      g[j] = k->cs[j] * g[j];
      ++j, ++total;
      double est = fabs(g[j]);
      if (est <= target || breakdown) {
        done = 1, reached = est <= target;
      } else if (predict && total >= 3) {
        double rate = pow(est / res->residual0, 1.0 / total);
        if (!(rate < 1.0) || total + log(target / est) / log(rate) > max_it) done = stagnated = 1;
      }
    }
    /* y = H^-1 g (upper triangular j x j), x += Z y */
    for (int i = j - 1; i >= 0; --i) {
      double s = g[i];
      for (int l = i + 1; l < j; ++l) s -= H[(size_t)l * ((size_t)m + 1) + (size_t)i] * k->y[l];
      k->y[i] = s / H[(size_t)i * ((size_t)m + 1) + (size_t)i];
    }
    for (int l = 0; l < j; ++l) {
      const double *zl = Z + (size_t)l * nn;
      double yl = k->y[l];
      for (int32_t q = 0; q < n; ++q) x[q] += yl * zl[q];
    }
    if (trust && reached && res->restarts == 0) {
      res->iterations = total;
      res->residual = fabs(g[j]);
      res->rate = total > 0 && res->residual0 > 0 ? pow(res->residual / res->residual0, 1.0 / total) : 0.0;
      res->status = SL_KRYLOV_CONVERGED;
      return 0;
    }
    if ((rc = residual(A, A_user, b, x, k->r, n, &beta, d))) return rc;
    res->iterations = total;
    res->residual = beta;
    res->rate = total > 0 && res->residual0 > 0 ? pow(beta / res->residual0, 1.0 / total) : 0.0;
    if (!isfinite(beta)) return sl_diag_set(d, SL_EFAILED, "krylov: the residual is not finite");
    if (beta <= target) {
      res->status = SL_KRYLOV_CONVERGED;
      return 0;
    }
    if (stagnated) {
      res->status = SL_KRYLOV_STAGNATED;
      return 0;
    }
    if (total >= max_it) {
      res->status = SL_KRYLOV_MAX_ITERATIONS;
      return 0;
    }
    ++res->restarts;
  }
}
