/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Periodic boundary pairs: the translation between two boundaries and
 * their vertex and face correspondence (see mesh.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mesh/mesh.h"

void sl_mesh_periodic_free(sl_mesh_periodic *p) {
  if (!p) return;
  free(p->vertex_pairs);
  free(p->face_pairs);
  memset(p, 0, sizeof *p);
}

static int cmp_int(const void *a, const void *b) {
  int x = *(const int *)a, y = *(const int *)b;
  return (x > y) - (x < y);
}

/* Pairs (first, second) ordered by first. */
static int cmp_pair(const void *a, const void *b) { return cmp_int(a, b); }

/* The distinct vertices of boundary b, ascending; *v is malloc'ed. */
static int boundary_vertices(const sl_mesh *m, int b, int **v, int *n) {
  int f0 = m->bface_start[b], f1 = m->bface_start[b + 1], per = m->dim == 2 ? 2 : 1;
  int *list = malloc(((size_t)(f1 - f0) * per + 1) * sizeof *list), k = 0;
  if (!list) return -1;
  for (int i = f0; i < f1; ++i)
    for (int j = 0; j < per; ++j) list[k++] = m->face_vertices[2 * m->bface[i] + j];
  qsort(list, (size_t)k, sizeof *list, cmp_int);
  int u = 0;
  for (int i = 0; i < k; ++i)
    if (u == 0 || list[i] != list[u - 1]) list[u++] = list[i];
  *v = list, *n = u;
  return 0;
}

static void bbox(const sl_mesh *m, const int *v, int n, double lo[2], double hi[2]) {
  lo[0] = lo[1] = INFINITY, hi[0] = hi[1] = -INFINITY;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c) {
      double x = m->xy[2 * (size_t)v[i] + c];
      lo[c] = fmin(lo[c], x), hi[c] = fmax(hi[c], x);
    }
}

typedef struct keyed {
  double key;
  int v;
} keyed;

static int cmp_keyed(const void *a, const void *b) {
  const keyed *x = a, *y = b;
  return (x->key > y->key) - (x->key < y->key);
}

/* A face of the boundary by its (sorted) vertex pair. */
typedef struct face_key {
  int lo, hi, face;
} face_key;

static int cmp_face_key(const void *a, const void *b) {
  const face_key *x = a, *y = b;
  if (x->lo != y->lo) return (x->lo > y->lo) - (x->lo < y->lo);
  return (x->hi > y->hi) - (x->hi < y->hi);
}

static face_key make_face_key(const sl_mesh *m, int f, const int *image) {
  int a = m->face_vertices[2 * f], b = m->dim == 2 ? m->face_vertices[2 * f + 1] : a;
  if (image) a = image[a], b = image[b];
  face_key k = {a < b ? a : b, a < b ? b : a, f};
  return k;
}

typedef struct match_work {
  int *va, *vb; /* vertices of boundary and partner */
  keyed *sorted;
  char *used;
  int *image; /* [n_vertices]: partner vertex -> boundary vertex, -1 */
  face_key *fa;
} match_work;

static void work_free(match_work *w) {
  free(w->va), free(w->vb), free(w->sorted), free(w->used), free(w->image), free(w->fa);
}

int sl_mesh_periodic_match(const sl_mesh *m, const char *boundary, const char *partner, sl_mesh_periodic *out,
                           sl_diag *d) {
  memset(out, 0, sizeof *out);
  const char *an = boundary ? boundary : "(null)", *bn = partner ? partner : "(null)";
  if (!boundary || !partner)
    return sl_diag_set(d, SL_EBADINPUT, "periodic pair '%s' / '%s': both boundary names are needed", an, bn);
  int a, b, rc = sl_mesh_boundary_id(m, boundary, &a, d);
  if (!rc) rc = sl_mesh_boundary_id(m, partner, &b, d);
  if (rc) return sl_diag_prefix(d, rc, "periodic pair '%s' / '%s'", an, bn);
  if (a == b)
    return sl_diag_set(d, SL_EBADINPUT, "periodic pair '%s' / '%s': a boundary cannot be its own partner", an, bn);
  int nfa = m->bface_start[a + 1] - m->bface_start[a], nfb = m->bface_start[b + 1] - m->bface_start[b];
  if (nfa == 0 || nfb == 0)
    return sl_diag_set(d, SL_EBADINPUT, "periodic pair '%s' / '%s': boundary '%s' has no faces", an, bn,
                       nfa == 0 ? an : bn);
  match_work w = {0};
  int na, nb;
  if (boundary_vertices(m, a, &w.va, &na) || boundary_vertices(m, b, &w.vb, &nb)) {
    work_free(&w);
    return sl_diag_set(d, SL_ENOMEM, "periodic pair '%s' / '%s': out of memory", an, bn);
  }
  if (na != nb || nfa != nfb) {
    work_free(&w);
    return sl_diag_set(d, SL_EBADINPUT,
                       "periodic pair '%s' / '%s': '%s' has %d nodes and %d faces, '%s' %d nodes and %d faces; "
                       "periodic boundaries must match node for node",
                       an, bn, an, na, nfa, bn, nb, nfb);
  }
  /* Tolerance from the size of the whole mesh. */
  double mlo[2] = {INFINITY, INFINITY}, mhi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < m->n_vertices; ++v)
    for (int c = 0; c < 2; ++c) mlo[c] = fmin(mlo[c], m->xy[2 * v + c]), mhi[c] = fmax(mhi[c], m->xy[2 * v + c]);
  double tol = SL_MESH_PERIODIC_TOL * hypot(mhi[0] - mlo[0], mhi[1] - mlo[1]);
  double alo[2], ahi[2], blo[2], bhi[2];
  bbox(m, w.va, na, alo, ahi);
  bbox(m, w.vb, nb, blo, bhi);
  double shift[2] = {blo[0] - alo[0], blo[1] - alo[1]};
  int same_extent =
      fabs((ahi[0] - alo[0]) - (bhi[0] - blo[0])) <= tol && fabs((ahi[1] - alo[1]) - (bhi[1] - blo[1])) <= tol;
  if (same_extent && fabs(shift[0]) <= tol && fabs(shift[1]) <= tol) {
    work_free(&w);
    return sl_diag_set(d, SL_EBADINPUT, "periodic pair '%s' / '%s': the two boundaries coincide (no translation)", an,
                       bn);
  }
  /* The boundary's vertices sorted along its longer extent; each partner
   * vertex looks for x - shift in a window of +-tol. */
  int axis = ahi[1] - alo[1] > ahi[0] - alo[0] ? 1 : 0;
  w.sorted = malloc((size_t)na * sizeof *w.sorted);
  w.used = calloc((size_t)na, 1);
  w.image = malloc((size_t)m->n_vertices * sizeof *w.image);
  out->vertex_pairs = malloc(2 * (size_t)na * sizeof *out->vertex_pairs);
  out->face_pairs = malloc(2 * (size_t)nfa * sizeof *out->face_pairs);
  w.fa = malloc((size_t)nfa * sizeof *w.fa);
  if (!w.sorted || !w.used || !w.image || !out->vertex_pairs || !out->face_pairs || !w.fa) {
    work_free(&w);
    sl_mesh_periodic_free(out);
    return sl_diag_set(d, SL_ENOMEM, "periodic pair '%s' / '%s': out of memory", an, bn);
  }
  for (int i = 0; i < na; ++i) w.sorted[i] = (keyed){m->xy[2 * (size_t)w.va[i] + axis], w.va[i]};
  qsort(w.sorted, (size_t)na, sizeof *w.sorted, cmp_keyed);
  for (int v = 0; v < m->n_vertices; ++v) w.image[v] = -1;
  for (int i = 0; i < nb; ++i) {
    const double *x = m->xy + 2 * (size_t)w.vb[i];
    double want[2] = {x[0] - shift[0], x[1] - shift[1]};
    int lo = 0, hi = na; /* first sorted entry with key >= want - tol */
    while (lo < hi) {
      int mid = lo + (hi - lo) / 2;
      if (w.sorted[mid].key < want[axis] - tol) lo = mid + 1;
      else hi = mid;
    }
    int found = -1;
    for (int k = lo; k < na && w.sorted[k].key <= want[axis] + tol; ++k) {
      const double *y = m->xy + 2 * (size_t)w.sorted[k].v;
      if (!w.used[k] && fabs(y[0] - want[0]) <= tol && fabs(y[1] - want[1]) <= tol) {
        found = k;
        break;
      }
    }
    if (found < 0) {
      int r;
      if (!same_extent)
        r = sl_diag_set(d, SL_EBADINPUT,
                        "periodic pair '%s' / '%s': the boundaries are not translates of each other ('%s' spans "
                        "%.12g x %.12g, '%s' %.12g x %.12g; only a translation is supported, not a rotation or "
                        "reflection): the node (%.12g, %.12g) of '%s' has no partner on '%s'",
                        an, bn, an, ahi[0] - alo[0], ahi[1] - alo[1], bn, bhi[0] - blo[0], bhi[1] - blo[1], x[0], x[1],
                        bn, an);
      else
        r = sl_diag_set(d, SL_EBADINPUT,
                        "periodic pair '%s' / '%s': the node (%.12g, %.12g) of '%s' has no partner on '%s' at "
                        "(%.12g, %.12g) (translation (%.12g, %.12g), tolerance %.3g)",
                        an, bn, x[0], x[1], bn, an, want[0], want[1], shift[0], shift[1], tol);
      work_free(&w);
      sl_mesh_periodic_free(out);
      return r;
    }
    w.used[found] = 1;
    w.image[w.vb[i]] = w.sorted[found].v;
    out->vertex_pairs[2 * i] = w.sorted[found].v, out->vertex_pairs[2 * i + 1] = w.vb[i];
  }
  qsort(out->vertex_pairs, (size_t)na, 2 * sizeof *out->vertex_pairs, cmp_pair);
  /* Faces: the image of each partner face's vertices is a face of the boundary. */
  for (int i = 0; i < nfa; ++i) w.fa[i] = make_face_key(m, m->bface[m->bface_start[a] + i], NULL);
  qsort(w.fa, (size_t)nfa, sizeof *w.fa, cmp_face_key);
  for (int i = 0; i < nfb; ++i) {
    int f = m->bface[m->bface_start[b] + i];
    face_key k = make_face_key(m, f, w.image);
    const face_key *hit = bsearch(&k, w.fa, (size_t)nfa, sizeof *w.fa, cmp_face_key);
    if (!hit) {
      double c[2];
      sl_mesh_face_centroid(m, f, c);
      int r = sl_diag_set(d, SL_EBADINPUT,
                          "periodic pair '%s' / '%s': the face of '%s' centred at (%.12g, %.12g) has no partner face "
                          "on '%s' (its nodes match, the edges between them do not)",
                          an, bn, bn, c[0], c[1], an);
      work_free(&w);
      sl_mesh_periodic_free(out);
      return r;
    }
    out->face_pairs[2 * i] = hit->face, out->face_pairs[2 * i + 1] = f;
  }
  qsort(out->face_pairs, (size_t)nfa, 2 * sizeof *out->face_pairs, cmp_pair);
  work_free(&w);
  out->boundary = a, out->partner = b;
  out->shift[0] = shift[0], out->shift[1] = shift[1];
  out->n_vertices = na, out->n_faces = nfa;
  return 0;
}
