/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A sparse matrix assembled as (row, column, value) triplets, in whatever
 * order and with repeats, then summed into CSR. The pattern is built the
 * first time and kept: while an assembly emits the same sequence of (row,
 * column) pairs (checked, not assumed) the values go straight to their
 * stored positions, so a fixed stencil pays for the pattern once. */
#ifndef SLUICE_SOLVE_TRIPLETS_H
#define SLUICE_SOLVE_TRIPLETS_H

#include <stdint.h>

#include "core/solve/sparse.h"
#include "core/util/diag.h"

typedef struct sl_triplets {
  int32_t n, cap;
  int32_t *row, *col;
  double *val;
  /* the sequence the pattern was built from, and each triplet's position in it */
  int32_t n_pattern;
  int32_t *prow, *pcol, *pos;
} sl_triplets;

/* Starts an assembly (the pattern is kept). */
static inline void sl_triplets_clear(sl_triplets *t) { t->n = 0; }
/* Adds A(row, col) += v; a negative row or column is skipped (a given
 * value). Returns 0, or -1 when out of memory. */
int sl_triplets_add(sl_triplets *t, int32_t row, int32_t col, double v);
/* Sums the triplets into A (n x n): the pattern built when the sequence
 * differs from the last one's, then the values in the triplets' order. */
int sl_triplets_to_csr(sl_triplets *t, sl_csr *A, int32_t n, sl_diag *d);
void sl_triplets_free(sl_triplets *t);

#endif
