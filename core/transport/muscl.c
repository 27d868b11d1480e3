/* SPDX-License-Identifier: GPL-2.0-or-later */
/* MUSCL reconstruction (van Leer 1979): a least-squares gradient per cell
 * from its face neighbours, limited so that the value at every face point
 * stays within beta times the distance to the extreme of the cell and its
 * VERTEX neighbours, the cells that share a vertex with it (Barth &
 * Jespersen 1989, AIAA paper 89-0366; beta = 1). The face neighbours alone
 * are too few on triangles: there the face values of a linear function
 * often lie outside their range, the limiter clips smooth data and order 2
 * is lost (L1 orders 0.5 to 1.8 on union-jack triangles); the vertex
 * neighbours' cell points surround the face points, so linear data is left
 * alone (the usual choice for cell-centred schemes: Venkatakrishnan 1995,
 * J. Comput. Phys. 118:120). In 1-D the vertex neighbours are the face
 * neighbours: on a uniform grid the least-squares slope is the central one
 * and this limit is exactly the monotonized-central limiter (van Leer
 * 1977); beta = 1/2 gives minmod. Across a periodic pair the neighbour's
 * cell point is translated next to the face, and the paired boundaries'
 * matching vertices are one vertex for the vertex neighbours.
 *
 * Stage bound. Face values lie within the values of nearby cells, so in
 * [0, phi_max]; in 2-D they are also kept within [2 phi_i - phi_max,
 * 2 phi_i] of their cell i. Then a forward-Euler stage stays in [0, phi_max]:
 * the Godunov flux H(a, b) out of i does not decrease in i's value a (slope
 * at most s_f, the stable step's), does not increase in the other, and
 * H(0, 0) = 0, so phi_i' >= phi_i - h/V_i sum_f s_f a_f >= 0 because
 * h sum_f s_f <= V_i / 2 (order 2's half step); the same against phi_max
 * with divergence-free q. This is the 1-D argument of transport.h face by
 * face: there a_f <= 2 phi_i holds already (the two face values average to
 * phi_i); in 2-D the wider vertex range would otherwise let a near-empty
 * cell send out more than it holds (a stirred, settling suspension then fell
 * back to first order in 2 to 18 % of the sub-steps on triangles,
 * test_transport_muscl.c). It acts only where a face value would differ
 * from phi_i by more than phi_i's distance to 0 or phi_max. */
#include <math.h>
#include <stdlib.h>

#include "core/transport/transport_impl.h"

int sl_transport_periodic_count(const sl_transport *t) {
  int n = 0;
  for (int b = 0; b < t->m->n_boundaries; ++b) n += t->bc_type[b] == SL_TRANSPORT_PERIODIC_;
  return n;
}

static int root(int *up, int v) {
  while (up[v] != v) v = up[v] = up[up[v]];
  return v;
}

/* |a - s - b|^2 */
static double dist2(const double *a, const double *b, const double s[2]) {
  double dx = a[0] - s[0] - b[0], dy = a[1] - s[1] - b[1];
  return dx * dx + dy * dy;
}

/* Vertices are merged into classes (union-find) along periodic pairs, so a
 * corner of a doubly periodic box is one class of four; then the cells of
 * each class are listed, and each cell's neighbours are the union over its
 * vertices' classes. */
int sl_transport_build_vertex_cells(sl_transport *t, sl_diag *d) {
  const sl_mesh *m = t->m;
  const int nc = m->n_cells, nv = m->n_vertices, npc = m->nv_per_cell;
  int *up = malloc((size_t)nv * sizeof *up), *cstart = calloc((size_t)nv + 1, sizeof *cstart);
  int *cls = malloc((size_t)nc * npc * sizeof *cls), *mark = malloc((size_t)nc * sizeof *mark);
  int *start = malloc(((size_t)nc + 1) * sizeof *start), *list = NULL, *nb = NULL;
  if (!up || !cstart || !cls || !mark || !start) goto oom;
  for (int v = 0; v < nv; ++v) up[v] = v;
  if (t->partner)
    for (int f = 0; f < m->n_faces; ++f) {
      if (t->fkind[f] != SL_FACE_PERIODIC) continue;
      /* The partner's vertices are this face's moved by -pshift[f]: pair each with the nearer one. */
      const int *a = m->face_vertices + 2 * f, *b = m->face_vertices + 2 * t->partner[f];
      const double *s = t->pshift + 2 * f, *x = m->xy;
      int k = 0;
      if (m->dim == 2 && dist2(x + 2 * a[0], x + 2 * b[1], s) < dist2(x + 2 * a[0], x + 2 * b[0], s)) k = 1;
      for (int i = 0; i < m->dim; ++i) {
        int ra = root(up, a[i]), rb = root(up, b[i == 0 ? k : 1 - k]);
        if (ra != rb) up[ra] = rb;
      }
    }
  /* Cells of each class (CSR over class roots). */
  for (size_t i = 0; i < (size_t)nc * npc; ++i) cls[i] = root(up, m->cell_vertices[i]), ++cstart[cls[i] + 1];
  for (int v = 0; v < nv; ++v) cstart[v + 1] += cstart[v];
  if (!(list = malloc((size_t)cstart[nv] * sizeof *list))) goto oom;
  for (size_t i = 0; i < (size_t)nc * npc; ++i) list[cstart[cls[i]]++] = (int)(i / npc);
  for (int v = nv; v > 0; --v) cstart[v] = cstart[v - 1];
  cstart[0] = 0;
  /* Each cell's neighbours, once each: counted in pass 0, stored in pass 1. */
  for (int pass = 0; pass < 2; ++pass) {
    for (int c = 0; c < nc; ++c) mark[c] = -1;
    int n = 0;
    for (int c = 0; c < nc; ++c) {
      mark[c] = c;
      if (pass == 0) start[c] = n;
      for (int k = 0; k < npc; ++k) {
        int r = cls[(size_t)c * npc + k];
        for (int i = cstart[r]; i < cstart[r + 1]; ++i) {
          int j = list[i];
          if (mark[j] == c) continue;
          mark[j] = c;
          if (pass == 1) nb[n] = j;
          ++n;
        }
      }
    }
    if (pass == 0) {
      start[nc] = n;
      if (!(nb = malloc((size_t)(n > 0 ? n : 1) * sizeof *nb))) goto oom;
    }
  }
  free(t->vnb_start), free(t->vnb);
  t->vnb_start = start, t->vnb = nb;
  t->vnb_pairs = sl_transport_periodic_count(t);
  free(up), free(cstart), free(cls), free(mark), free(list);
  return 0;
oom:
  free(up), free(cstart), free(cls), free(mark), free(start), free(list), free(nb);
  return sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
}

/* The least-squares gradient of phi over the face neighbours (periodic
 * ones translated next to the face), unlimited. */
static void lsq_gradient(const sl_transport *t, const double *phi, int c, double g[2]) {
  const sl_mesh *m = t->m;
  const int nfc = m->nf_per_cell;
  const double *L = t->lsq + 3 * c, *xc = t->xc + 2 * c;
  double rx = 0, ry = 0, pc = phi[c];
  g[0] = g[1] = 0;
  if (L[0] == 0 && L[2] == 0) return;
  for (int k = 0; k < nfc; ++k) {
    int f = m->cell_faces[(size_t)c * nfc + k];
    double sh[2];
    int j = sl_transport_across(t, f, c, sh);
    if (j < 0) continue;
    double dp = phi[j] - pc;
    rx += (t->xc[2 * j] + sh[0] - xc[0]) * dp;
    ry += (t->xc[2 * j + 1] + sh[1] - xc[1]) * dp;
  }
  g[0] = L[0] * rx + L[1] * ry, g[1] = L[1] * rx + L[2] * ry;
}

void sl_transport_gradient(const sl_transport *t, const double *phi, double *grad) {
  for (int c = 0; c < t->m->n_cells; ++c) lsq_gradient(t, phi, c, grad + 2 * c);
}

void sl_transport_reconstruct(sl_transport *t, const double *phi) {
  const sl_mesh *m = t->m;
  const int nfc = m->nf_per_cell;
  const double beta = t->o.limiter == SL_LIMITER_MINMOD ? 0.5 : 1.0;
  for (int c = 0; c < m->n_cells; ++c) {
    const double *xc = t->xc + 2 * c;
    double *g = t->grad + 2 * c, gl[2];
    lsq_gradient(t, phi, c, gl);
    g[0] = g[1] = 0;
    double gx = gl[0], gy = gl[1], pc = phi[c], lo = pc, hi = pc;
    if (gx == 0 && gy == 0) continue;
    for (int k = 0; k < nfc; ++k) {
      int f = m->cell_faces[(size_t)c * nfc + k];
      double sh[2];
      int j = sl_transport_across(t, f, c, sh);
      if (j < 0) continue;
      if (phi[j] < lo) lo = phi[j];
      if (phi[j] > hi) hi = phi[j];
    }
    double dv[4], dmax = 0, dmin = 0; /* face value - cell value (nf_per_cell <= 4) */
    for (int k = 0; k < nfc; ++k) {
      int f = m->cell_faces[(size_t)c * nfc + k];
      dv[k] = gx * (t->xf[2 * f] - xc[0]) + gy * (t->xf[2 * f + 1] - xc[1]);
      if (dv[k] > dmax) dmax = dv[k];
      if (dv[k] < dmin) dmin = dv[k];
    }
    /* The face neighbours are vertex neighbours: only when their range
     * would limit is the wider one needed (the common case skips it). */
    if (dmax > beta * (hi - pc) || dmin < beta * (lo - pc))
      for (int i = t->vnb_start[c]; i < t->vnb_start[c + 1]; ++i) {
        double p = phi[t->vnb[i]];
        if (p < lo) lo = p;
        if (p > hi) hi = p;
      }
    double alpha = 1, up = beta * (hi - pc), down = beta * (lo - pc); /* up >= 0 >= down */
    if (m->dim == 2) { /* the stage bound (top of the file); in 1-D it always holds */
      if (up > pc) up = pc;
      if (down < pc - t->o.phi_max) down = pc - t->o.phi_max;
    }
    for (int k = 0; k < nfc; ++k) {
      if (dv[k] > 0 && alpha * dv[k] > up) alpha = up / dv[k];
      else if (dv[k] < 0 && alpha * dv[k] < down) alpha = down / dv[k];
    }
    g[0] = alpha * gx;
    g[1] = alpha * gy;
  }
}
