/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Banded LU with partial pivoting (band.h). */
#include "core/solve/band.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sl_band_init(sl_band *B, int32_t n, int32_t kl, int32_t ku, sl_diag *d) {
  memset(B, 0, sizeof *B);
  B->n = n, B->kl = kl, B->ku = ku, B->ld = 2 * kl + ku + 1;
  B->ab = calloc((size_t)B->ld * (size_t)n, sizeof *B->ab);
  B->ipiv = malloc((size_t)n * sizeof *B->ipiv);
  B->rs = malloc((size_t)n * sizeof *B->rs);
  if (!B->ab || !B->ipiv || !B->rs) {
    sl_band_free(B);
    return sl_diag_set(d, SL_ENOMEM, "banded matrix of %d unknowns: out of memory", (int)n);
  }
  return 0;
}

void sl_band_free(sl_band *B) {
  free(B->ab), free(B->ipiv), free(B->rs);
  memset(B, 0, sizeof *B);
}

void sl_band_zero(sl_band *B) { memset(B->ab, 0, (size_t)B->ld * (size_t)B->n * sizeof *B->ab); }

/* Column j of the band as the factorisation holds it (U's fill in the top kl rows): A(i, j) = col(B, j)[i - j],
 * kl + ku >= j - i >= -kl. */
static inline double *col(const sl_band *B, int32_t j) { return B->ab + (int64_t)B->ld * j + B->kl + B->ku; }

int sl_band_factor(sl_band *B, sl_diag *d) {
  const int32_t n = B->n, kl = B->kl;
  int32_t ju = 0; /* the last column the interchanges so far reach */
  ++B->n_factor, B->ku_lu = B->ku;
  for (int32_t i = 0; i < n; ++i) B->rs[i] = 0.0;
  for (int32_t j = 0; j < n; ++j) { /* the rows' largest entries, column by column */
    const double *cj = col(B, j);
    for (int32_t i = j - B->ku > 0 ? j - B->ku : 0; i <= j + kl && i < n; ++i)
      if (fabs(cj[i - j]) > B->rs[i]) B->rs[i] = fabs(cj[i - j]);
  }
  for (int32_t i = 0; i < n; ++i) {
    if (!(B->rs[i] > 0.0) || !isfinite(B->rs[i]))
      return sl_diag_set(d, SL_EFAILED, "banded LU: row %d of %d is %s", (int)i, (int)n,
                         B->rs[i] > 0.0 ? "not finite" : "zero (the matrix is singular)");
    B->rs[i] = 1.0 / B->rs[i];
  }
  for (int32_t j = 0; j < n; ++j) {
    double *cj = col(B, j);
    for (int32_t i = j - B->ku > 0 ? j - B->ku : 0; i <= j + kl && i < n; ++i) cj[i - j] *= B->rs[i];
  }
  for (int32_t j = 0; j < n; ++j) {
    double *cj = col(B, j);
    int32_t km = kl < n - 1 - j ? kl : n - 1 - j, jp = 0;
    double big = fabs(cj[0]);
    for (int32_t r = 1; r <= km; ++r)
      if (fabs(cj[r]) > big) big = fabs(cj[r]), jp = r;
    B->ipiv[j] = j + jp;
    if (!(big > 0.0) || !isfinite(big))
      return sl_diag_set(d, SL_EFAILED, "banded LU: the matrix is singular (pivot %g in column %d of %d)", big, (int)j,
                         (int)n);
    int32_t reach = j + B->ku + jp < n - 1 ? j + B->ku + jp : n - 1;
    if (reach > ju) ju = reach;
    if (ju - j > B->ku_lu) B->ku_lu = ju - j;
    if (jp)
      for (int32_t c = j; c <= ju; ++c) {
        double *cc = col(B, c) + j - c, t = cc[0]; /* cc[r] = A(j + r, c) */
        cc[0] = cc[jp], cc[jp] = t;
      }
    const double rp = 1.0 / cj[0]; /* dgbtf2 scales the column so; dgbtrs divides by U's diagonal */
    for (int32_t r = 1; r <= km; ++r) cj[r] *= rp;
    for (int32_t c = j + 1; c <= ju; ++c) {
      double *cc = col(B, c) + j - c, t = cc[0];
      if (t != 0.0)
        for (int32_t r = 1; r <= km; ++r) cc[r] -= cj[r] * t;
    }
  }
  return 0;
}

void sl_band_solve(const sl_band *B, double *x) {
  const int32_t n = B->n, kl = B->kl, kv = B->ku_lu;
  for (int32_t i = 0; i < n; ++i) x[i] *= B->rs[i];
  for (int32_t j = 0; j < n - 1; ++j) { /* L, with the interchanges */
    const double *cj = col(B, j);
    int32_t km = kl < n - 1 - j ? kl : n - 1 - j, l = B->ipiv[j];
    if (l != j) {
      double t = x[l];
      x[l] = x[j], x[j] = t;
    }
    const double xj = x[j];
    for (int32_t r = 1; r <= km; ++r) x[j + r] -= cj[r] * xj;
  }
  for (int32_t j = n - 1; j >= 0; --j) { /* U, ku_lu superdiagonals */
    const double *cj = col(B, j), xj = x[j] /= cj[0];
    for (int32_t i = j - kv > 0 ? j - kv : 0; i < j; ++i) x[i] -= cj[i - j] * xj;
  }
}

int sl_band_permutation(const sl_csr *A, const int32_t *key, int32_t *perm, int32_t *kl, int32_t *ku, sl_diag *d) {
  const int32_t n = A->n_rows;
  int32_t kmax = 0;
  for (int32_t i = 0; i < n; ++i) kmax = key[i] > kmax ? key[i] : kmax;
  int32_t *count = calloc((size_t)kmax + 2, sizeof *count);
  if (!count) return sl_diag_set(d, SL_ENOMEM, "banded matrix: out of memory");
  for (int32_t i = 0; i < n; ++i) ++count[key[i] + 1];
  for (int32_t k = 0; k <= kmax; ++k) count[k + 1] += count[k];
  for (int32_t i = 0; i < n; ++i) perm[i] = count[key[i]]++; /* stable counting sort */
  free(count);
  *kl = *ku = 0;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t e = A->row_ptr[i]; e < A->row_ptr[i + 1]; ++e) {
      int32_t off = perm[i] - perm[A->col_idx[e]];
      if (off > *kl) *kl = off;
      if (-off > *ku) *ku = -off;
    }
  return 0;
}
