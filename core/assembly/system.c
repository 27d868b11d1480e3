/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Element-by-element systems and Dirichlet constraints. */
#include "core/assembly/system.h"

#include <stdlib.h>
#include <string.h>

#include "core/solve/linsolve.h"

int sl_system_init(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                   sl_diag *d) {
  memset(s, 0, sizeof *s);
  s->n_dofs = n_dofs, s->n_elem = n_elem, s->dofs_per_elem = dofs_per_elem, s->elem_dofs = elem_dofs;
  int32_t *ptr = malloc(((size_t)n_elem + 1) * sizeof *ptr);
  s->b = calloc((size_t)n_dofs, sizeof *s->b);
  if (!ptr || !s->b) {
    free(ptr);
    sl_system_free(s);
    return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for a system of %d dofs", (int)n_dofs);
  }
  s->elem_begin = 0, s->elem_end = n_elem;
  for (int32_t e = 0; e <= n_elem; ++e) ptr[e] = e * dofs_per_elem;
  int rc = sl_csr_build_uniform(&s->A, n_dofs, n_elem, dofs_per_elem, elem_dofs, d);
  if (!rc) rc = sl_csr_elem_map_build(&s->map, &s->A, n_elem, ptr, elem_dofs, NULL, NULL, d);
  free(ptr);
  if (rc) sl_system_free(s);
  return rc;
}

int sl_system_init_kept(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                        const unsigned char *keep, sl_diag *d) {
  if (!keep) return sl_system_init(s, n_dofs, n_elem, dofs_per_elem, elem_dofs, d);
  memset(s, 0, sizeof *s);
  s->n_dofs = n_dofs, s->n_elem = n_elem, s->dofs_per_elem = dofs_per_elem, s->elem_dofs = elem_dofs;
  const int dpe = dofs_per_elem;
  int64_t n_kept = 0;
  for (int k = 0; k < dpe * dpe; ++k) n_kept += keep[k] != 0;
  /* the pattern: one piece per element row, the row's dof against its kept columns */
  size_t n_rows = (size_t)n_elem * dpe;
  int32_t *rptr = malloc((n_rows + 1) * sizeof *rptr), *cptr = malloc((n_rows + 1) * sizeof *cptr);
  int32_t *cols = malloc(((size_t)n_elem * n_kept + 1) * sizeof *cols);
  s->b = calloc((size_t)n_dofs, sizeof *s->b);
  int rc = 0;
  if (!rptr || !cptr || !cols || !s->b || n_rows > INT32_MAX || (int64_t)n_elem * n_kept > INT32_MAX)
    rc = sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for a system of %d dofs", (int)n_dofs);
  s->elem_begin = 0, s->elem_end = n_elem;
  if (!rc) {
    int32_t at = 0;
    for (size_t r = 0; r <= n_rows; ++r) rptr[r] = (int32_t)r;
    for (int32_t e = 0; e < n_elem; ++e)
      for (int a = 0; a < dpe; ++a) {
        cptr[(size_t)e * dpe + a] = at;
        for (int b = 0; b < dpe; ++b)
          if (keep[a * dpe + b]) cols[at++] = elem_dofs[(size_t)e * dpe + b];
      }
    cptr[n_rows] = at;
    rc = sl_csr_build(&s->A, n_dofs, n_dofs, (int32_t)n_rows, rptr, elem_dofs, cptr, cols, d);
  }
  free(rptr), free(cptr), free(cols);
  if (!rc) rc = sl_csr_elem_map_build_kept(&s->map, &s->A, n_elem, dpe, elem_dofs, keep, d);
  if (rc) sl_system_free(s);
  return rc;
}

void sl_system_free(sl_system *s) {
  sl_linsolve_rows_free(&s->rows);
  free(s->rows.owned);
  free(s->rows.global);
  free(s->rows.local);
  sl_csr_free(&s->A);
  sl_csr_elem_map_free(&s->map);
  free(s->b);
  free(s->elem_local);
  memset(s, 0, sizeof *s);
}

void sl_system_zero(sl_system *s) {
  sl_csr_zero(&s->A);
  memset(s->b, 0, (size_t)s->n_dofs * sizeof *s->b);
}

int sl_system_add_element(sl_system *s, int32_t e, const double *Ke, const double *be, sl_diag *d) {
  if (s->distributed && (e < 0 || e >= s->n_elem || s->elem_local[e] < 0)) return 0; /* another rank's */
  if (Ke) {
    int rc = sl_csr_add_element_mapped(&s->A, &s->map, s->distributed ? s->elem_local[e] : e, Ke, d);
    if (rc) return rc;
  }
  if (be) {
    const int32_t *dofs = s->elem_dofs + (size_t)e * s->dofs_per_elem;
    for (int a = 0; a < s->dofs_per_elem; ++a)
      if (dofs[a] >= 0) s->b[dofs[a]] += be[a];
  }
  return 0;
}

void sl_system_partition(int32_t n_elem, int rank, int ranks, int32_t *begin, int32_t *end) {
  if (ranks < 1) ranks = 1, rank = 0;
  *begin = (int32_t)((int64_t)n_elem * rank / ranks);
  *end = (int32_t)((int64_t)n_elem * (rank + 1) / ranks);
}

/* Row ownership and the ranks' numbering (see system.h): owner[i] is the rank (part[e]) of the lowest-numbered
 * element e holding dof i; a dof of no element goes to the last rank. */
static int build_rows(sl_system *s, const int32_t *part, int rank, int ranks, sl_diag *d) {
  int32_t n = s->n_dofs;
  sl_rows *r = &s->rows;
  int32_t *owner = malloc((size_t)n * sizeof *owner), *count = calloc((size_t)ranks + 1, sizeof *count);
  r->owned = calloc((size_t)n, 1);
  r->global = malloc((size_t)n * sizeof *r->global);
  if (!owner || !count || !r->owned || !r->global) {
    free(owner), free(count);
    return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for the rows of %d dofs", (int)n);
  }
  for (int32_t i = 0; i < n; ++i) owner[i] = -1;
  for (int64_t k = 0; k < (int64_t)s->n_elem * s->dofs_per_elem; ++k) {
    int32_t i = s->elem_dofs[k];
    if (i >= 0 && i < n && owner[i] < 0) owner[i] = part[k / s->dofs_per_elem];
  }
  for (int32_t i = 0; i < n; ++i) {
    if (owner[i] < 0) owner[i] = ranks - 1;
    ++count[owner[i] + 1];
  }
  for (int q = 0; q < ranks; ++q) count[q + 1] += count[q]; /* count[q]: the first row of rank q */
  r->n = n, r->begin = count[rank], r->end = count[rank + 1];
  r->local = malloc(((size_t)(r->end - r->begin) + 1) * sizeof *r->local);
  int rc = 0;
  if (!r->local) rc = sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for the rows of %d dofs", (int)n);
  for (int32_t i = 0; i < n && !rc; ++i) {
    int32_t g = count[owner[i]]++;
    r->global[i] = g;
    if (owner[i] == rank) r->owned[i] = 1, r->local[g - r->begin] = i;
  }
  free(owner), free(count);
  return rc;
}

int sl_system_init_ranks(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                         int rank, int ranks, sl_diag *d) {
  if (ranks <= 1) return sl_system_init(s, n_dofs, n_elem, dofs_per_elem, elem_dofs, d);
  memset(s, 0, sizeof *s);
  s->n_dofs = n_dofs, s->n_elem = n_elem, s->dofs_per_elem = dofs_per_elem, s->elem_dofs = elem_dofs;
  s->distributed = 1;
  s->b = calloc((size_t)n_dofs, sizeof *s->b);
  s->elem_local = malloc(((size_t)n_elem + 1) * sizeof *s->elem_local);
  int32_t *part = malloc(((size_t)n_elem + 1) * sizeof *part), *size = calloc((size_t)ranks, sizeof *size);
  if (!s->b || !s->elem_local || !part || !size) {
    free(part), free(size);
    sl_system_free(s);
    return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for a system of %d dofs", (int)n_dofs);
  }
  int rc = sl_linsolve_partition(n_elem, dofs_per_elem, elem_dofs, n_dofs, ranks, part, d);
  for (int32_t e = 0; e < n_elem && !rc; ++e) {
    if (part[e] < 0 || part[e] >= ranks)
      rc = sl_diag_set(d, SL_EFAILED, "assembly: cell %d's part %d is not a rank of %d", (int)e, (int)part[e], ranks);
    else
      ++size[part[e]];
  }
  int empty = 0;
  for (int q = 0; q < ranks && !rc; ++q) empty |= size[q] == 0;
  if (empty) /* a part left empty (a mesh of few cells): the blocks of the numbering instead */
    for (int q = 0; q < ranks; ++q) {
      int32_t e0, e1;
      sl_system_partition(n_elem, q, ranks, &e0, &e1);
      for (int32_t e = e0; e < e1; ++e) part[e] = q;
    }
  free(size);
  if (!rc) rc = build_rows(s, part, rank, ranks, d);
  if (rc) {
    free(part);
    sl_system_free(s);
    return rc;
  }
  /* this rank's elements, in increasing order, and the range holding them */
  int32_t n_own = 0;
  s->elem_begin = n_elem, s->elem_end = 0;
  for (int32_t e = 0; e < n_elem; ++e) {
    s->elem_local[e] = part[e] == rank ? n_own++ : -1;
    if (part[e] == rank) {
      if (e < s->elem_begin) s->elem_begin = e;
      s->elem_end = e + 1;
    }
  }
  if (n_own == 0) s->elem_begin = s->elem_end = 0;
  free(part);
  /* The pattern: the own elements' rows and columns, and the rows this rank owns of the other ranks' elements
   * that touch them (so that an owned row has its complete pattern here); other rows of those are skipped. */
  const int dpe = dofs_per_elem;
  int32_t n_ghost = 0;
  for (int32_t e = 0; e < n_elem; ++e) {
    if (s->elem_local[e] >= 0) continue;
    for (int a = 0; a < dpe; ++a) {
      int32_t i = elem_dofs[(size_t)e * dpe + a];
      if (i >= 0 && i < n_dofs && s->rows.owned[i]) {
        ++n_ghost;
        break;
      }
    }
  }
  int32_t m = n_own + n_ghost;
  int32_t *ptr = malloc(((size_t)m + 1) * sizeof *ptr);
  int32_t *row_dofs = malloc(((size_t)m * dpe + 1) * sizeof *row_dofs);
  int32_t *col_dofs = malloc(((size_t)m * dpe + 1) * sizeof *col_dofs);
  if (!ptr || !row_dofs || !col_dofs) {
    free(ptr), free(row_dofs), free(col_dofs);
    sl_system_free(s);
    return sl_diag_set(d, SL_ENOMEM, "assembly: out of memory for a system of %d dofs", (int)n_dofs);
  }
  for (int32_t e = 0; e <= m; ++e) ptr[e] = e * dpe;
  for (int32_t e = 0; e < n_elem; ++e)
    if (s->elem_local[e] >= 0)
      memcpy(row_dofs + (size_t)s->elem_local[e] * dpe, elem_dofs + (size_t)e * dpe, (size_t)dpe * sizeof *row_dofs);
  memcpy(col_dofs, row_dofs, (size_t)n_own * dpe * sizeof *col_dofs);
  int32_t k = n_own;
  for (int32_t e = 0; e < n_elem; ++e) {
    if (s->elem_local[e] >= 0) continue;
    const int32_t *dofs = elem_dofs + (size_t)e * dpe;
    int touches = 0;
    for (int a = 0; a < dpe; ++a) touches |= dofs[a] >= 0 && dofs[a] < n_dofs && s->rows.owned[dofs[a]];
    if (!touches) continue;
    for (int a = 0; a < dpe; ++a) {
      int own = dofs[a] >= 0 && dofs[a] < n_dofs && s->rows.owned[dofs[a]];
      row_dofs[(size_t)k * dpe + a] = own ? dofs[a] : -1;
      col_dofs[(size_t)k * dpe + a] = dofs[a];
    }
    ++k;
  }
  rc = sl_csr_build(&s->A, n_dofs, n_dofs, m, ptr, row_dofs, ptr, col_dofs, d);
  free(col_dofs);
  if (!rc) rc = sl_csr_elem_map_build(&s->map, &s->A, n_own, ptr, row_dofs, NULL, NULL, d);
  free(ptr), free(row_dofs);
  if (rc) {
    sl_system_free(s);
    return rc;
  }
  s->A.rows = &s->rows;
  return 0;
}

void sl_system_elements(const sl_system *s, int32_t *begin, int32_t *end) {
  *begin = s->distributed ? s->elem_begin : 0;
  *end = s->distributed ? s->elem_end : s->n_elem;
}

void sl_system_next_run(const sl_system *s, int32_t from, int32_t *begin, int32_t *end) {
  int32_t n = s->distributed ? s->elem_end : s->n_elem, e = from < 0 ? 0 : from;
  while (s->distributed && e < n && s->elem_local[e] < 0) ++e;
  *begin = e;
  while (s->distributed && e < n && s->elem_local[e] >= 0) ++e;
  *end = s->distributed ? e : n;
  if (*begin > *end) *begin = *end;
}

int sl_system_complete(sl_system *s, int matrix, sl_diag *d) {
  if (!s->distributed) return 0;
  return sl_linsolve_rows_complete(&s->rows, &s->A, s->b, matrix, d);
}

int sl_system_agree(const sl_system *s, int rc, sl_diag *d) {
  if (!s->distributed) return rc;
  int all = sl_linsolve_agree(rc);
  if (all && !rc) return sl_diag_set(d, all, "another rank's assembly failed (its message is on that rank)");
  return rc ? rc : all;
}

/* ---- constraints --------------------------------------------------------- */

int sl_constraints_init(sl_constraints *bc, int32_t n_dofs, sl_diag *d) {
  memset(bc, 0, sizeof *bc);
  bc->fixed = calloc((size_t)n_dofs, 1);
  bc->value = calloc((size_t)n_dofs, sizeof *bc->value);
  if (!bc->fixed || !bc->value) {
    sl_constraints_free(bc);
    return sl_diag_set(d, SL_ENOMEM, "constraints: out of memory");
  }
  bc->n_dofs = n_dofs;
  return 0;
}

void sl_constraints_free(sl_constraints *bc) {
  free(bc->fixed);
  free(bc->value);
  memset(bc, 0, sizeof *bc);
}

void sl_constraints_fix(sl_constraints *bc, int32_t i, double v) {
  if (!bc->fixed[i]) ++bc->n_fixed;
  bc->fixed[i] = 1, bc->value[i] = v;
}

int sl_constraints_fix_boundary(sl_constraints *bc, const sl_dofmap *dm, const char *boundary, int32_t offset,
                                sl_exact_fn g, void *user, double value, sl_diag *d) {
  if (offset < 0 || offset + dm->n_dofs > bc->n_dofs)
    return sl_diag_set(d, SL_EBADINPUT, "constraints: block offset %d does not fit %d dofs", (int)offset,
                       (int)bc->n_dofs);
  int32_t *dofs, n;
  int rc = sl_dofmap_boundary_dofs(dm, boundary, &dofs, &n, d);
  if (rc) return rc;
  for (int32_t k = 0; k < n; ++k) {
    double v = value;
    if (g) g(user, dm->xy + 2 * (size_t)dofs[k], &v, NULL);
    sl_constraints_fix(bc, offset + dofs[k], v);
  }
  free(dofs);
  return 0;
}

int sl_constraints_apply(const sl_constraints *bc, sl_system *s, int symmetric, sl_diag *d) {
  if (bc->n_dofs != s->n_dofs)
    return sl_diag_set(d, SL_EBADINPUT, "constraints: %d dofs, the system has %d", (int)bc->n_dofs, (int)s->n_dofs);
  if (bc->n_fixed == 0) return 0;
  int32_t *rows = malloc((size_t)bc->n_fixed * sizeof *rows), k = 0;
  double *vals = malloc((size_t)bc->n_fixed * sizeof *vals);
  if (!rows || !vals) {
    free(rows), free(vals);
    return sl_diag_set(d, SL_ENOMEM, "constraints: out of memory");
  }
  for (int32_t i = 0; i < bc->n_dofs; ++i)
    if (bc->fixed[i]) rows[k] = i, vals[k++] = bc->value[i];
  int rc = sl_csr_set_dirichlet(&s->A, k, rows, vals, s->b, symmetric, d);
  free(rows), free(vals);
  return rc;
}

void sl_constraints_impose(const sl_constraints *bc, double *u) {
  for (int32_t i = 0; i < bc->n_dofs; ++i)
    if (bc->fixed[i]) u[i] = bc->value[i];
}
