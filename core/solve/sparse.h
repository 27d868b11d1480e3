/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Compressed sparse row matrices for assembly and the direct solvers.
 *
 * The pattern is built once from element connectivity (sorted, unique column
 * indices per row); assembly then only adds into existing entries. Every
 * function here that changes values bumps `values_gen`, which the linear
 * solvers compare to decide whether a new numeric factorisation is needed.
 * Code that writes A->values directly must call sl_csr_touch() afterwards. */
#ifndef SLUICE_SOLVE_SPARSE_H
#define SLUICE_SOLVE_SPARSE_H

#include <stddef.h>
#include <stdint.h>

#include "core/util/diag.h"

/* How a matrix's rows are divided among the ranks of a run (mpirun; core/assembly/system.h builds it): each
 * row is complete on the one rank that owns it (owned[i] != 0) and zero on the others. global[i] is row i's
 * index in the ranks' numbering, in which every rank's rows are contiguous, [begin, end) here, in the order of
 * local[0 .. end - begin) (rows of this rank in increasing sluice order). `exchange` is the linear solver's
 * (PETSc's matrix and vector the ranks add their parts into, sl_linsolve_rows_complete). */
typedef struct sl_rows {
  int32_t n;
  unsigned char *owned; /* [n] */
  int32_t *global;      /* [n] */
  int32_t *local;       /* [end - begin] */
  int32_t begin, end;
  void *exchange;
} sl_rows;

typedef struct sl_csr {
  int32_t n_rows, n_cols;
  int32_t nnz;
  int32_t *row_ptr;    /* n_rows + 1 */
  int32_t *col_idx;    /* nnz, strictly increasing within each row */
  double *values;      /* nnz */
  uint64_t pattern_id; /* unique in the process; new for every pattern built */
  uint64_t values_gen; /* incremented whenever values change */
  /* Several ranks: the rows this rank holds complete (the others are another rank's and zero here). NULL: every
   * row (one rank). Borrowed. */
  const sl_rows *rows;
} sl_csr;

/* Build the pattern from element connectivity. Element e couples the rows
 * row_dofs[row_ptr_e[e] .. row_ptr_e[e+1]) with the columns
 * col_dofs[col_ptr_e[e] .. col_ptr_e[e+1]); pass col_ptr_e = col_dofs = NULL
 * for the usual square case where the columns are the rows. Negative dof
 * indices are skipped (constrained or absent dofs). Values start at zero.
 * `A` must be zero-initialised or freed. Returns 0, SL_EBADINPUT (index out
 * of range) or SL_EFAILED (out of memory, more than INT32_MAX entries). */
int sl_csr_build(sl_csr *A, int32_t n_rows, int32_t n_cols, int32_t n_elem, const int32_t *row_ptr_e,
                 const int32_t *row_dofs, const int32_t *col_ptr_e, const int32_t *col_dofs, sl_diag *d);

/* Convenience: n_elem elements with a fixed number of dofs each (square). */
int sl_csr_build_uniform(sl_csr *A, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                         sl_diag *d);

void sl_csr_free(sl_csr *A);

/* Values to zero (pattern kept). */
void sl_csr_zero(sl_csr *A);
/* Tell the solvers the values changed after writing A->values directly. */
static inline void sl_csr_touch(sl_csr *A) { ++A->values_gen; }

/* Index of entry (i, j) in col_idx/values, or -1 when not in the pattern. */
int32_t sl_csr_find(const sl_csr *A, int32_t i, int32_t j);

/* A(rows[a], cols[b]) += Ke[a * n_c + b] (row-major element matrix) by a
 * binary search in each row. Negative indices are skipped. Returns 0, or
 * SL_EBADINPUT when an entry is not in the pattern (nothing is added then:
 * the check runs first). */
int sl_csr_add_element(sl_csr *A, int n_r, const int32_t *rows, int n_c, const int32_t *cols, const double *Ke,
                       sl_diag *d);

/* Precomputed positions: for each element the nnz index of every (a, b) pair
 * (-1 for skipped dofs), so the hot assembly loop does no searching. Built
 * against one pattern; adding through it into another pattern is refused. */
typedef struct sl_csr_elem_map {
  int32_t n_elem;
  int64_t *offset; /* n_elem + 1, into pos */
  int32_t *pos;    /* sum over e of n_r(e) * n_c(e) */
  uint64_t pattern_id;
  int distinct; /* no element holds a position twice (no dof twice in an element): the add loads a group of
                   entries before it stores them */
} sl_csr_elem_map;

/* Same element description as sl_csr_build (NULL columns: square). `map` is
 * overwritten: free an old map first. Costs 4 bytes per element-matrix entry;
 * assembly through it is about 5x faster than the searched add (see the
 * solve_bench program). */
int sl_csr_elem_map_build(sl_csr_elem_map *map, const sl_csr *A, int32_t n_elem, const int32_t *row_ptr_e,
                          const int32_t *row_dofs, const int32_t *col_ptr_e, const int32_t *col_dofs, sl_diag *d);
/* The map of n_elem elements of dofs_per_elem dofs each (square) whose local pairs (a, b) with keep[a *
 * dofs_per_elem + b] == 0 are not in A's pattern: their positions are -1, and the mapped add drops those
 * entries of Ke (which the caller knows to be zero). Every other pair must be in the pattern. */
int sl_csr_elem_map_build_kept(sl_csr_elem_map *map, const sl_csr *A, int32_t n_elem, int dofs_per_elem,
                               const int32_t *elem_dofs, const unsigned char *keep, sl_diag *d);
void sl_csr_elem_map_free(sl_csr_elem_map *map);
/* A += Ke of element e (row-major, the element's own row/column order).
 * Returns 0, or SL_EBADINPUT when the map was built for another pattern or e
 * is out of range. */
static inline int sl_csr_add_element_mapped(sl_csr *A, const sl_csr_elem_map *map, int32_t e, const double *Ke,
                                            sl_diag *d) {
  if (map->pattern_id != A->pattern_id || e < 0 || e >= map->n_elem)
    return sl_diag_set(d, SL_EBADINPUT, "assembly: element map %s (element %d of %d)",
                       map->pattern_id != A->pattern_id ? "belongs to another sparsity pattern" : "out of range",
                       (int)e, (int)map->n_elem);
  const int32_t *p = map->pos + map->offset[e];
  int64_t k = map->offset[e + 1] - map->offset[e], q = 0;
  if (map->distinct) { /* four entries loaded, then stored: no store waits on the next load (the positions differ) */
    double sink[4] = {0}, *v = A->values;
    for (; q + 4 <= k; q += 4) {
      double *d0 = p[q] >= 0 ? v + p[q] : sink, *d1 = p[q + 1] >= 0 ? v + p[q + 1] : sink + 1;
      double *d2 = p[q + 2] >= 0 ? v + p[q + 2] : sink + 2, *d3 = p[q + 3] >= 0 ? v + p[q + 3] : sink + 3;
      double v0 = *d0 + Ke[q], v1 = *d1 + Ke[q + 1], v2 = *d2 + Ke[q + 2], v3 = *d3 + Ke[q + 3];
      *d0 = v0, *d1 = v1, *d2 = v2, *d3 = v3;
    }
  }
  for (; q < k; ++q)
    if (p[q] >= 0) A->values[p[q]] += Ke[q];
  ++A->values_gen;
  return 0;
}

/* y = A x (x has n_cols entries, y has n_rows; they must not overlap). */
void sl_csr_matvec(const sl_csr *A, const double *x, double *y);
/* y = A x with each row's sum in four partial sums (entries p mod 4), added at the end: the sum's additions four
 * chains instead of one, so the product runs at the memory's speed, not the adder's latency; the result is
 * sl_csr_matvec's up to round-off (another order of the same additions), not bitwise. */
void sl_csr_matvec_split(const sl_csr *A, const double *x, double *y);
/* y = alpha A x + beta y. */
void sl_csr_matvec_add(const sl_csr *A, double alpha, const double *x, double beta, double *y);

/* Dirichlet conditions u[rows[k]] = vals[k] (vals NULL: all zero). Each row
 * becomes the identity row and b[rows[k]] = vals[k] (b may be NULL, e.g. for
 * a Newton Jacobian). With `symmetric`, the columns are eliminated as well:
 * b[i] -= A(i, r) vals[r] and A(i, r) = 0 for the other rows, keeping a
 * symmetric matrix symmetric (needed for cholmod). Every Dirichlet row must
 * have its diagonal entry in the pattern. A matrix whose rows are divided among ranks (A->rows) changes only
 * the rows this rank owns. Returns 0 or SL_EBADINPUT. */
int sl_csr_set_dirichlet(sl_csr *A, int32_t n, const int32_t *rows, const double *vals, double *b, int symmetric,
                         sl_diag *d);

#endif
