/* Periodic boundary pairs: the faces of two mesh boundaries that match by a
 * translation are joined into interior faces between their cells (see
 * sl_transport_set_periodic in transport.h). Matching sorts the second
 * boundary's faces along its longest extent and looks each translated face
 * of the first up by bisection: O(n log n). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/transport/transport_impl.h"

typedef struct keyed {
  double key;
  int face;
} keyed;

static int cmp_keyed(const void *pa, const void *pb) {
  const keyed *a = pa, *b = pb;
  return a->key < b->key ? -1 : a->key > b->key ? 1 : (a->face > b->face) - (a->face < b->face);
}

static double dist2(const double a[2], const double b[2]) {
  double dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

/* Both vertices of face fa, translated by s, on those of fb (either order). */
static int vertices_match(const sl_mesh *m, int fa, int fb, const double s[2], double tol2) {
  if (m->dim == 1) return 1;
  const double *a0 = m->xy + 2 * m->face_vertices[2 * fa], *a1 = m->xy + 2 * m->face_vertices[2 * fa + 1];
  const double *b0 = m->xy + 2 * m->face_vertices[2 * fb], *b1 = m->xy + 2 * m->face_vertices[2 * fb + 1];
  double p0[2] = {a0[0] + s[0], a0[1] + s[1]}, p1[2] = {a1[0] + s[0], a1[1] + s[1]};
  return (dist2(p0, b0) <= tol2 && dist2(p1, b1) <= tol2) || (dist2(p0, b1) <= tol2 && dist2(p1, b0) <= tol2);
}

static int cmp_double(const void *pa, const void *pb) {
  double a = *(const double *)pa, b = *(const double *)pb;
  return (a > b) - (a < b);
}

/* The unused face of b (index into b's faces) whose face point lies within
 * tol of face fa's translated by s (and, with `vertices`, whose vertices
 * do too), or -1. kb: b's faces sorted by their coordinate `axis`. */
static int lookup(const sl_mesh *m, const keyed *kb, int nfb, int b0, int fa, const double s[2], int axis, double tol,
                  int vertices, const char *used) {
  double xa[2], want[2];
  sl_mesh_face_centroid(m, fa, xa);
  want[0] = xa[0] + s[0], want[1] = xa[1] + s[1];
  int l = 0, h = nfb; /* first key >= want - tol */
  while (l < h) {
    int mid = (l + h) / 2;
    if (kb[mid].key < want[axis] - tol) l = mid + 1;
    else h = mid;
  }
  for (int j = l; j < nfb && kb[j].key <= want[axis] + tol; ++j) {
    int ib = kb[j].face, fb = m->bface[b0 + ib];
    double xb[2];
    sl_mesh_face_centroid(m, fb, xb);
    if (used[ib] || dist2(xb, want) > tol * tol || (vertices && !vertices_match(m, fa, fb, s, tol * tol))) continue;
    return ib;
  }
  return -1;
}

int sl_transport_set_periodic(sl_transport *t, int a, int b, sl_diag *d) {
  const sl_mesh *m = t->m;
  if (a < 0 || a >= m->n_boundaries || b < 0 || b >= m->n_boundaries)
    return sl_diag_set(d, SL_EBADINPUT, "transport: periodic pair (%d, %d): the mesh has boundaries 0 .. %d", a, b,
                       m->n_boundaries - 1);
  const char *na = m->boundary_names[a], *nb = m->boundary_names[b];
  if (a == b) return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' cannot be periodic with itself", na);
  for (int k = 0; k < 2; ++k) {
    int bb = k ? b : a;
    if (t->bc_type[bb] == SL_TRANSPORT_PERIODIC_)
      return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' is already periodic", m->boundary_names[bb]);
  }
  int a0 = m->bface_start[a], nfa = m->bface_start[a + 1] - a0;
  int b0 = m->bface_start[b], nfb = m->bface_start[b + 1] - b0;
  if (nfa == 0 || nfa != nfb)
    return sl_diag_set(d, SL_EBADINPUT,
                       "transport: periodic boundaries '%s' and '%s' have %d and %d faces: they cannot be paired", na,
                       nb, nfa, nfb);
  /* Tolerance: 1e-9 of the bounding-box diagonal. */
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (int v = 0; v < m->n_vertices; ++v)
    for (int k = 0; k < 2; ++k) lo[k] = fmin(lo[k], m->xy[2 * v + k]), hi[k] = fmax(hi[k], m->xy[2 * v + k]);
  double extent = hypot(hi[0] - lo[0], hi[1] - lo[1]), tol = 1e-9 * extent;
  /* The translation: difference of the length-weighted mean face points. */
  double ma[2] = {0, 0}, mb[2] = {0, 0}, la = 0, lb = 0;
  for (int i = 0; i < nfa; ++i) {
    double x[2], len;
    int f = m->bface[a0 + i];
    sl_mesh_face_centroid(m, f, x);
    len = sl_mesh_face_length(m, f);
    ma[0] += len * x[0], ma[1] += len * x[1], la += len;
    f = m->bface[b0 + i];
    sl_mesh_face_centroid(m, f, x);
    len = sl_mesh_face_length(m, f);
    mb[0] += len * x[0], mb[1] += len * x[1], lb += len;
  }
  double s[2] = {mb[0] / lb - ma[0] / la, mb[1] / lb - ma[1] / la};
  if (t->o.geometry == SL_TRANSPORT_AXISYMMETRIC && fabs(s[0]) > tol)
    return sl_diag_set(d, SL_EBADINPUT,
                       "transport: periodic boundaries '%s' and '%s' are translated by (%g, %g): in an axisymmetric "
                       "geometry a periodic pair must be translated along z only",
                       na, nb, s[0], s[1]);
  if (hypot(s[0], s[1]) <= tol)
    return sl_diag_set(d, SL_EBADINPUT, "transport: periodic boundaries '%s' and '%s' are not translated apart", na,
                       nb);
  /* Sort b's faces along b's longest extent. */
  keyed *kb = malloc((size_t)nfb * sizeof *kb);
  int *match = malloc((size_t)nfa * sizeof *match);
  char *used = calloc((size_t)nfb, 1);
  int rc = 0;
  if (!kb || !match || !used) {
    rc = sl_diag_set(d, SL_EFAILED, "transport: out of memory");
    goto done;
  }
  double blo[2] = {HUGE_VAL, HUGE_VAL}, bhi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (int i = 0; i < nfb; ++i) {
    double x[2];
    sl_mesh_face_centroid(m, m->bface[b0 + i], x);
    for (int k = 0; k < 2; ++k) blo[k] = fmin(blo[k], x[k]), bhi[k] = fmax(bhi[k], x[k]);
  }
  int axis = bhi[1] - blo[1] > bhi[0] - blo[0];
  for (int i = 0; i < nfb; ++i) {
    double x[2];
    sl_mesh_face_centroid(m, m->bface[b0 + i], x);
    kb[i].key = x[axis];
    kb[i].face = i;
  }
  qsort(kb, (size_t)nfb, sizeof *kb, cmp_keyed);
  /* A first, loose pass (a quarter of the smallest face) refines s to the
   * median of the matched differences, so that one bad face does not move
   * the translation of all the others; then the strict pass. */
  double hmin = HUGE_VAL;
  for (int i = 0; i < nfa; ++i) hmin = fmin(hmin, sl_mesh_face_length(m, m->bface[a0 + i]));
  double loose = m->dim == 1 ? 0.25 * extent : 0.25 * hmin;
  int nd = 0;
  double *dx = malloc(2 * (size_t)nfa * sizeof *dx);
  if (!dx) {
    rc = sl_diag_set(d, SL_EFAILED, "transport: out of memory");
    goto done;
  }
  for (int i = 0; i < nfa; ++i) {
    double xa[2], xb[2];
    int ib = lookup(m, kb, nfb, b0, m->bface[a0 + i], s, axis, loose, 0, used);
    if (ib < 0) continue;
    sl_mesh_face_centroid(m, m->bface[a0 + i], xa);
    sl_mesh_face_centroid(m, m->bface[b0 + ib], xb);
    dx[nd] = xb[0] - xa[0], dx[nfa + nd] = xb[1] - xa[1];
    ++nd;
  }
  if (nd > 0) {
    qsort(dx, (size_t)nd, sizeof *dx, cmp_double);
    qsort(dx + nfa, (size_t)nd, sizeof *dx, cmp_double);
    s[0] = dx[nd / 2], s[1] = dx[nfa + nd / 2];
  }
  free(dx);
  for (int i = 0; i < nfa; ++i) {
    int fa = m->bface[a0 + i];
    double xa[2], want[2];
    sl_mesh_face_centroid(m, fa, xa);
    want[0] = xa[0] + s[0], want[1] = xa[1] + s[1];
    match[i] = lookup(m, kb, nfb, b0, fa, s, axis, tol, 1, used);
    if (match[i] >= 0) used[match[i]] = 1;
    if (match[i] < 0) {
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "transport: periodic boundaries '%s' and '%s': face %d of '%s' at (%.9g, %.9g) has no partner "
                       "on '%s' at (%.9g, %.9g) (translation (%.9g, %.9g), tolerance %.3g)",
                       na, nb, fa, na, xa[0], xa[1], nb, want[0], want[1], s[0], s[1], tol);
      goto done;
    }
    int fb = m->bface[b0 + match[i]];
    const double *n_a = t->normal + 2 * fa, *n_b = t->normal + 2 * fb;
    const double *ca = t->xc + 2 * m->face_cells[2 * fa], *cb = t->xc + 2 * m->face_cells[2 * fb];
    double dn = (cb[0] - s[0] - ca[0]) * n_a[0] + (cb[1] - s[1] - ca[1]) * n_a[1];
    if (!(n_a[0] * n_b[0] + n_a[1] * n_b[1] < 0 && dn > 0)) {
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "transport: periodic boundaries '%s' and '%s': face %d of '%s' at (%.9g, %.9g) and its "
                       "translate, face %d of '%s', do not face each other (their cells lie on the same side)",
                       na, nb, fa, na, xa[0], xa[1], fb, nb);
      goto done;
    }
  }
  if (!t->partner) {
    t->partner = malloc((size_t)m->n_faces * sizeof *t->partner);
    t->pshift = calloc(2 * (size_t)m->n_faces, sizeof *t->pshift);
    if (!t->partner || !t->pshift) {
      free(t->partner), free(t->pshift);
      t->partner = NULL, t->pshift = NULL;
      rc = sl_diag_set(d, SL_EFAILED, "transport: out of memory");
      goto done;
    }
    for (int f = 0; f < m->n_faces; ++f) t->partner[f] = -1;
  }
  for (int i = 0; i < nfa; ++i) {
    int fa = m->bface[a0 + i], fb = m->bface[b0 + match[i]];
    t->partner[fa] = fb, t->partner[fb] = fa;
    t->fkind[fa] = SL_FACE_PERIODIC, t->fkind[fb] = SL_FACE_PERIODIC_IMAGE;
    t->pshift[2 * fa] = -s[0], t->pshift[2 * fa + 1] = -s[1];
    t->pshift[2 * fb] = s[0], t->pshift[2 * fb + 1] = s[1];
  }
  t->bc_type[a] = t->bc_type[b] = SL_TRANSPORT_PERIODIC_;
  t->bc_phi[a] = t->bc_phi[b] = 0;
  sl_transport_build_lsq(t);
done:
  free(kb);
  free(match);
  free(used);
  return rc;
}

int sl_transport_set_periodic_named(sl_transport *t, const char *a, const char *b, sl_diag *d) {
  int ia, ib, rc;
  if ((rc = sl_mesh_boundary_id(t->m, a, &ia, d)) || (rc = sl_mesh_boundary_id(t->m, b, &ib, d)))
    return sl_diag_prefix(d, rc, "transport: periodic pair");
  return sl_transport_set_periodic(t, ia, ib, d);
}

int sl_transport_periodic_shift(const sl_transport *t, int b, double s[2], sl_diag *d) {
  const sl_mesh *m = t->m;
  if (b < 0 || b >= m->n_boundaries || t->bc_type[b] != SL_TRANSPORT_PERIODIC_)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary %d is not periodic", b);
  int f = m->bface[m->bface_start[b]];
  double sign = t->fkind[f] == SL_FACE_PERIODIC ? -1 : 1;
  s[0] = sign * t->pshift[2 * f], s[1] = sign * t->pshift[2 * f + 1];
  return 0;
}
