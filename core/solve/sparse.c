/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/solve/sparse.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

/* Pattern ids are unique across the process, so a solver can tell "same
 * pattern" from "same pointer, rebuilt pattern". */
static atomic_uint_fast64_t next_pattern_id = 1;

static uint64_t new_pattern_id(void) { return (uint64_t)atomic_fetch_add(&next_pattern_id, 1); }

void sl_csr_free(sl_csr *A) {
  if (!A) return;
  free(A->row_ptr);
  free(A->col_idx);
  free(A->values);
  memset(A, 0, sizeof *A);
}

static int cmp_i32(const void *a, const void *b) {
  int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
  return (x > y) - (x < y);
}

static void sort_i32(int32_t *v, int32_t n) {
  if (n > 32) {
    qsort(v, (size_t)n, sizeof *v, cmp_i32);
    return;
  }
  for (int32_t i = 1; i < n; ++i) { /* rows are short: insertion sort wins */
    int32_t x = v[i], j = i - 1;
    while (j >= 0 && v[j] > x) {
      v[j + 1] = v[j];
      --j;
    }
    v[j + 1] = x;
  }
}

/* Checks every dof index and that the element pointers are non-decreasing. */
static int check_elements(int32_t n, int32_t n_elem, const int32_t *ptr, const int32_t *dofs, const char *what,
                          sl_diag *d) {
  if (ptr[0] < 0) return sl_diag_set(d, SL_EBADINPUT, "sparsity: %s pointer of element 0 is negative", what);
  for (int32_t e = 0; e < n_elem; ++e) {
    if (ptr[e + 1] < ptr[e])
      return sl_diag_set(d, SL_EBADINPUT, "sparsity: %s pointers decrease at element %d", what, (int)e);
    for (int32_t k = ptr[e]; k < ptr[e + 1]; ++k)
      if (dofs[k] >= n)
        return sl_diag_set(d, SL_EBADINPUT, "sparsity: element %d has %s index %d, outside [0, %d)", (int)e, what,
                           (int)dofs[k], (int)n);
  }
  return 0;
}

int sl_csr_build(sl_csr *A, int32_t n_rows, int32_t n_cols, int32_t n_elem, const int32_t *row_ptr_e,
                 const int32_t *row_dofs, const int32_t *col_ptr_e, const int32_t *col_dofs, sl_diag *d) {
  memset(A, 0, sizeof *A);
  if (n_rows < 0 || n_cols < 0 || n_elem < 0)
    return sl_diag_set(d, SL_EBADINPUT, "sparsity: negative size (rows %d, columns %d, elements %d)", (int)n_rows,
                       (int)n_cols, (int)n_elem);
  if (!col_ptr_e || !col_dofs) {
    col_ptr_e = row_ptr_e;
    col_dofs = row_dofs;
    if (n_cols != n_rows)
      return sl_diag_set(d, SL_EBADINPUT, "sparsity: square pattern requested but %d rows and %d columns", (int)n_rows,
                         (int)n_cols);
  }
  int rc = check_elements(n_rows, n_elem, row_ptr_e, row_dofs, "row", d);
  if (!rc && col_dofs != row_dofs) rc = check_elements(n_cols, n_elem, col_ptr_e, col_dofs, "column", d);
  if (rc) return rc;

  /* Which elements touch each row: a CSR of the row -> element incidence. */
  int32_t *rel_ptr = calloc((size_t)n_rows + 1, sizeof *rel_ptr);
  int32_t *marker = malloc(((size_t)n_cols + 1) * sizeof *marker);
  int32_t *rel = NULL;
  int64_t *cnt = NULL;
  if (!rel_ptr || !marker) goto oom;
  for (int32_t e = 0; e < n_elem; ++e)
    for (int32_t k = row_ptr_e[e]; k < row_ptr_e[e + 1]; ++k)
      if (row_dofs[k] >= 0) ++rel_ptr[row_dofs[k] + 1];
  for (int32_t r = 0; r < n_rows; ++r) rel_ptr[r + 1] += rel_ptr[r];
  rel = malloc(((size_t)rel_ptr[n_rows] + 1) * sizeof *rel);
  if (!rel) goto oom;
  for (int32_t e = 0; e < n_elem; ++e)
    for (int32_t k = row_ptr_e[e]; k < row_ptr_e[e + 1]; ++k)
      if (row_dofs[k] >= 0) rel[rel_ptr[row_dofs[k]]++] = e;
  for (int32_t r = n_rows; r > 0; --r) rel_ptr[r] = rel_ptr[r - 1]; /* undo the shift of the fill */
  rel_ptr[0] = 0;

  /* Pass 1 counts the distinct columns of each row (marker = last row seen),
   * pass 2 fills them; both touch each (row, element) pair once. */
  for (int32_t c = 0; c < n_cols; ++c) marker[c] = -1;
  cnt = malloc(((size_t)n_rows + 1) * sizeof *cnt);
  if (!cnt) goto oom;
  cnt[0] = 0;
  for (int32_t r = 0; r < n_rows; ++r) {
    int64_t m = 0;
    for (int32_t q = rel_ptr[r]; q < rel_ptr[r + 1]; ++q) {
      int32_t e = rel[q];
      for (int32_t k = col_ptr_e[e]; k < col_ptr_e[e + 1]; ++k) {
        int32_t c = col_dofs[k];
        if (c >= 0 && marker[c] != r) {
          marker[c] = r;
          ++m;
        }
      }
    }
    cnt[r + 1] = cnt[r] + m;
    if (cnt[r + 1] > INT32_MAX) {
      free(rel_ptr), free(marker), free(rel), free(cnt);
      return sl_diag_set(d, SL_EFAILED, "sparsity: more than %d nonzeros (32-bit indices)", (int)INT32_MAX);
    }
  }
  A->n_rows = n_rows;
  A->n_cols = n_cols;
  A->nnz = (int32_t)cnt[n_rows];
  A->row_ptr = malloc(((size_t)n_rows + 1) * sizeof *A->row_ptr);
  A->col_idx = malloc(((size_t)A->nnz + 1) * sizeof *A->col_idx);
  A->values = calloc((size_t)A->nnz + 1, sizeof *A->values);
  if (!A->row_ptr || !A->col_idx || !A->values) goto oom;
  for (int32_t r = 0; r <= n_rows; ++r) A->row_ptr[r] = (int32_t)cnt[r];
  for (int32_t c = 0; c < n_cols; ++c) marker[c] = -1;
  for (int32_t r = 0; r < n_rows; ++r) {
    int32_t *out = A->col_idx + A->row_ptr[r], m = 0;
    for (int32_t q = rel_ptr[r]; q < rel_ptr[r + 1]; ++q) {
      int32_t e = rel[q];
      for (int32_t k = col_ptr_e[e]; k < col_ptr_e[e + 1]; ++k) {
        int32_t c = col_dofs[k];
        if (c >= 0 && marker[c] != r) {
          marker[c] = r;
          out[m++] = c;
        }
      }
    }
    sort_i32(out, m);
  }
  free(rel_ptr), free(marker), free(rel), free(cnt);
  A->pattern_id = new_pattern_id();
  A->values_gen = 1;
  return 0;
oom:
  free(rel_ptr), free(marker), free(rel), free(cnt);
  sl_csr_free(A);
  return sl_diag_set(d, SL_ENOMEM, "sparsity: out of memory (%d rows, %d elements)", (int)n_rows, (int)n_elem);
}

int sl_csr_build_uniform(sl_csr *A, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                         sl_diag *d) {
  if (n_elem < 0 || dofs_per_elem < 0 || (int64_t)n_elem * dofs_per_elem > INT32_MAX) {
    memset(A, 0, sizeof *A);
    return sl_diag_set(d, SL_EBADINPUT, "sparsity: bad element count %d x %d", (int)n_elem, dofs_per_elem);
  }
  int32_t *ptr = malloc(((size_t)n_elem + 1) * sizeof *ptr);
  if (!ptr) {
    memset(A, 0, sizeof *A);
    return sl_diag_set(d, SL_ENOMEM, "sparsity: out of memory");
  }
  for (int32_t e = 0; e <= n_elem; ++e) ptr[e] = e * dofs_per_elem;
  int rc = sl_csr_build(A, n_dofs, n_dofs, n_elem, ptr, elem_dofs, NULL, NULL, d);
  free(ptr);
  return rc;
}

void sl_csr_zero(sl_csr *A) {
  if (A->nnz > 0) memset(A->values, 0, (size_t)A->nnz * sizeof *A->values);
  ++A->values_gen;
}

static int32_t find_in_row(const sl_csr *A, int32_t i, int32_t j) {
  int32_t lo = A->row_ptr[i], hi = A->row_ptr[i + 1] - 1;
  while (lo <= hi) {
    int32_t mid = lo + (hi - lo) / 2, c = A->col_idx[mid];
    if (c == j) return mid;
    if (c < j) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

int32_t sl_csr_find(const sl_csr *A, int32_t i, int32_t j) {
  if (i < 0 || i >= A->n_rows || j < 0 || j >= A->n_cols) return -1;
  return find_in_row(A, i, j);
}

int sl_csr_add_element(sl_csr *A, int n_r, const int32_t *rows, int n_c, const int32_t *cols, const double *Ke,
                       sl_diag *d) {
  for (int a = 0; a < n_r; ++a) {
    int32_t i = rows[a];
    if (i < 0) continue;
    if (i >= A->n_rows) return sl_diag_set(d, SL_EBADINPUT, "assembly: row %d outside [0, %d)", (int)i, (int)A->n_rows);
    for (int b = 0; b < n_c; ++b) {
      int32_t j = cols[b];
      if (j < 0) continue;
      int32_t p = j < A->n_cols ? find_in_row(A, i, j) : -1;
      if (p < 0) {
        ++A->values_gen;
        return sl_diag_set(d, SL_EBADINPUT, "assembly: entry (%d, %d) is not in the sparsity pattern", (int)i, (int)j);
      }
      A->values[p] += Ke[a * n_c + b];
    }
  }
  ++A->values_gen;
  return 0;
}

/* keep: NULL, or (uniform elements of n_keep rows and columns) keep[a * n_keep + b] == 0 for the pairs left out */
static int elem_map_build(sl_csr_elem_map *map, const sl_csr *A, int32_t n_elem, const int32_t *row_ptr_e,
                          const int32_t *row_dofs, const int32_t *col_ptr_e, const int32_t *col_dofs,
                          const unsigned char *keep, int n_keep, sl_diag *d) {
  memset(map, 0, sizeof *map);
  if (!col_ptr_e || !col_dofs) {
    col_ptr_e = row_ptr_e;
    col_dofs = row_dofs;
  }
  map->offset = malloc(((size_t)n_elem + 1) * sizeof *map->offset);
  if (!map->offset) return sl_diag_set(d, SL_ENOMEM, "element map: out of memory");
  map->offset[0] = 0;
  for (int32_t e = 0; e < n_elem; ++e)
    map->offset[e + 1] =
        map->offset[e] + (int64_t)(row_ptr_e[e + 1] - row_ptr_e[e]) * (col_ptr_e[e + 1] - col_ptr_e[e]);
  map->pos = malloc(((size_t)map->offset[n_elem] + 1) * sizeof *map->pos);
  if (!map->pos) {
    sl_csr_elem_map_free(map);
    return sl_diag_set(d, SL_ENOMEM, "element map: out of memory (%lld positions)", (long long)map->offset[n_elem]);
  }
  map->n_elem = n_elem;
  map->pattern_id = A->pattern_id;
  for (int32_t e = 0; e < n_elem; ++e) {
    int32_t *p = map->pos + map->offset[e];
    for (int32_t ka = row_ptr_e[e]; ka < row_ptr_e[e + 1]; ++ka) {
      int32_t i = row_dofs[ka];
      for (int32_t kb = col_ptr_e[e]; kb < col_ptr_e[e + 1]; ++kb) {
        int32_t j = col_dofs[kb];
        int32_t q = -1;
        if (keep && !keep[(ka - row_ptr_e[e]) * n_keep + (kb - col_ptr_e[e])]) j = -1; /* left out of the pattern */
        if (i >= 0 && j >= 0) {
          q = sl_csr_find(A, i, j);
          if (q < 0) {
            sl_csr_elem_map_free(map);
            return sl_diag_set(d, SL_EBADINPUT, "element map: element %d entry (%d, %d) is not in the pattern", (int)e,
                               (int)i, (int)j);
          }
        }
        *p++ = q;
      }
    }
  }
  /* distinct: each element's positions marked with its number, a second mark of one is a repeat */
  int32_t *mark = malloc(((size_t)A->nnz + 1) * sizeof *mark);
  map->distinct = mark != NULL;
  for (int32_t j = 0; mark && j < A->nnz; ++j) mark[j] = -1;
  for (int32_t e = 0; mark && e < n_elem && map->distinct; ++e)
    for (int64_t k = map->offset[e]; k < map->offset[e + 1]; ++k) {
      int32_t q = map->pos[k];
      if (q < 0) continue;
      if (mark[q] == e) {
        map->distinct = 0;
        break;
      }
      mark[q] = e;
    }
  free(mark);
  return 0;
}

int sl_csr_elem_map_build(sl_csr_elem_map *map, const sl_csr *A, int32_t n_elem, const int32_t *row_ptr_e,
                          const int32_t *row_dofs, const int32_t *col_ptr_e, const int32_t *col_dofs, sl_diag *d) {
  return elem_map_build(map, A, n_elem, row_ptr_e, row_dofs, col_ptr_e, col_dofs, NULL, 0, d);
}

int sl_csr_elem_map_build_kept(sl_csr_elem_map *map, const sl_csr *A, int32_t n_elem, int dofs_per_elem,
                               const int32_t *elem_dofs, const unsigned char *keep, sl_diag *d) {
  int32_t *ptr = malloc(((size_t)n_elem + 1) * sizeof *ptr);
  if (!ptr) {
    memset(map, 0, sizeof *map);
    return sl_diag_set(d, SL_ENOMEM, "element map: out of memory");
  }
  for (int32_t e = 0; e <= n_elem; ++e) ptr[e] = e * dofs_per_elem;
  int rc = elem_map_build(map, A, n_elem, ptr, elem_dofs, NULL, NULL, keep, dofs_per_elem, d);
  free(ptr);
  return rc;
}

void sl_csr_elem_map_free(sl_csr_elem_map *map) {
  if (!map) return;
  free(map->offset);
  free(map->pos);
  memset(map, 0, sizeof *map);
}

void sl_csr_matvec(const sl_csr *A, const double *x, double *y) {
  for (int32_t i = 0; i < A->n_rows; ++i) {
    double s = 0.0;
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) s += A->values[p] * x[A->col_idx[p]];
    y[i] = s;
  }
}

void sl_csr_matvec_split(const sl_csr *A, const double *x, double *y) {
  const double *v = A->values;
  const int32_t *c = A->col_idx;
  for (int32_t i = 0; i < A->n_rows; ++i) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int32_t p = A->row_ptr[i], end = A->row_ptr[i + 1];
    for (; p + 3 < end; p += 4) {
      s0 += v[p] * x[c[p]], s1 += v[p + 1] * x[c[p + 1]];
      s2 += v[p + 2] * x[c[p + 2]], s3 += v[p + 3] * x[c[p + 3]];
    }
    for (; p < end; ++p) s0 += v[p] * x[c[p]];
    y[i] = (s0 + s1) + (s2 + s3);
  }
}

void sl_csr_matvec_add(const sl_csr *A, double alpha, const double *x, double beta, double *y) {
  for (int32_t i = 0; i < A->n_rows; ++i) {
    double s = 0.0;
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) s += A->values[p] * x[A->col_idx[p]];
    /* beta == 0 must not propagate NaN from an uninitialised y */
    y[i] = beta == 0.0 ? alpha * s : alpha * s + beta * y[i];
  }
}

int sl_csr_set_dirichlet(sl_csr *A, int32_t n, const int32_t *rows, const double *vals, double *b, int symmetric,
                         sl_diag *d) {
  if (A->n_rows != A->n_cols)
    return sl_diag_set(d, SL_EBADINPUT, "dirichlet: matrix is %d x %d, not square", (int)A->n_rows, (int)A->n_cols);
  /* which[r] = k + 1 for the last k naming row r, 0 otherwise */
  int32_t *which = calloc((size_t)A->n_rows + 1, sizeof *which);
  if (!which) return sl_diag_set(d, SL_ENOMEM, "dirichlet: out of memory");
  for (int32_t k = 0; k < n; ++k) {
    int32_t r = rows[k];
    if (r < 0 || r >= A->n_rows) {
      free(which);
      return sl_diag_set(d, SL_EBADINPUT, "dirichlet: row %d outside [0, %d)", (int)r, (int)A->n_rows);
    }
    /* another rank's row: its column is eliminated here, the row there */
    if ((!A->rows || A->rows->owned[r]) && find_in_row(A, r, r) < 0) {
      free(which);
      return sl_diag_set(d, SL_EBADINPUT, "dirichlet: row %d has no diagonal entry in the pattern", (int)r);
    }
    which[r] = k + 1;
  }
  if (symmetric) {
    /* Move the known values to the right-hand side before the rows vanish. */
    for (int32_t i = 0; i < A->n_rows; ++i) {
      if (which[i]) continue;
      for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) {
        int32_t k = which[A->col_idx[p]];
        if (!k) continue;
        if (b && vals) b[i] -= A->values[p] * vals[k - 1];
        A->values[p] = 0.0;
      }
    }
  }
  for (int32_t r = 0; r < A->n_rows; ++r) {
    if (!which[r] || (A->rows && !A->rows->owned[r])) continue;
    for (int32_t p = A->row_ptr[r]; p < A->row_ptr[r + 1]; ++p) A->values[p] = A->col_idx[p] == r ? 1.0 : 0.0;
    if (b) b[r] = vals ? vals[which[r] - 1] : 0.0;
  }
  free(which);
  ++A->values_gen;
  return 0;
}
