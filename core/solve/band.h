/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A banded matrix and its LU factorisation with partial pivoting, for the
 * systems whose unknowns, numbered along a line, couple only near
 * neighbours (a staggered grid one cell across: core/fv/grid.h). The
 * storage and the algorithm are LAPACK's dgbtrf/dgbtrs unblocked (dgbtf2;
 * Golub & Van Loan 2013, Matrix Computations, 4th ed., section 4.3.5):
 * A(i, j) for i - kl <= j <= i + ku at ab[kv + i - j + ld j] with kv =
 * kl + ku and ld = 2 kl + ku + 1, the top kl rows left for the fill of the
 * row interchanges (U then has kl + ku superdiagonals). Work and storage
 * O(n kl (kl + ku)): for n = 1200 and kl = ku = 3 some 40 k flops, where a
 * general sparse LU spends its time in the symbolic bookkeeping.
 *
 * sl_band_permutation numbers the rows and columns of a CSR matrix by a
 * key (the position along the line) and measures the bands of the
 * permuted matrix, so that a caller can decide whether the banded form
 * pays and then assemble straight into it. */
#ifndef SLUICE_SOLVE_BAND_H
#define SLUICE_SOLVE_BAND_H

#include <stdint.h>

#include "core/solve/sparse.h"
#include "core/util/diag.h"

typedef struct sl_band {
  int32_t n, kl, ku, ld;
  double *ab;    /* [ld n], column-major band */
  int32_t *ipiv; /* [n]: the row interchanged with row j at step j */
  double *rs;    /* [n]: row i scaled by rs[i] = 1 / max_j |A(i, j)| before the factorisation */
  int32_t ku_lu; /* the superdiagonals of the last factorisation's U (ku, up to kl + ku with interchanges) */
  long n_factor; /* factorisations done */
} sl_band;

/* An n x n band with kl sub- and ku superdiagonals, zero. 0 or SL_ENOMEM. */
int sl_band_init(sl_band *B, int32_t n, int32_t kl, int32_t ku, sl_diag *d);
void sl_band_free(sl_band *B);
void sl_band_zero(sl_band *B);

/* A(i, j) += v; -1 (nothing added) when (i, j) lies outside the bands. */
static inline int sl_band_add(sl_band *B, int32_t i, int32_t j, double v) {
  if (i - j > B->kl || j - i > B->ku || i < 0 || j < 0 || i >= B->n || j >= B->n) return -1;
  B->ab[(int64_t)(B->kl + B->ku + i - j) + (int64_t)B->ld * j] += v;
  return 0;
}

/* LU with partial pivoting in place, of the matrix with each row scaled by its largest |entry| (as KLU scales
 * by default, Davis & Palamadai Natarajan 2010, ACM TOMS 37(3): the pivots are then chosen alike whatever the
 * rows' units; without it the column's continuity rows, of order the face area, lose every pivot to momentum
 * rows of order the drag, and settling_illite's solids velocity came out 1.9e-14 m/s (5e-10 of its size) from
 * KLU's, against 4e-19 m/s between KLU and UMFPACK; scaled, 1.7e-17 m/s). 0, or SL_EFAILED (a zero row, a zero or non-finite pivot: singular). */
int sl_band_factor(sl_band *B, sl_diag *d);
/* x = A^-1 x with the factorisation (its scaling included). */
void sl_band_solve(const sl_band *B, double *x);

/* perm[old] = new: the unknowns sorted by key[old] (ties in their own order); *kl, *ku the bands of A with rows
 * and columns so renumbered. 0 or SL_ENOMEM. */
int sl_band_permutation(const sl_csr *A, const int32_t *key, int32_t *perm, int32_t *kl, int32_t *ku, sl_diag *d);

#endif
