/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The stream function of conservative face fluxes (stream_function.h). */
#include "core/fv/stream_function.h"

#include "core/solve/dense.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sl_stream_graph_free(sl_stream_graph *g) {
  free(g->start), free(g->face), free(g->queue), free(g->seen);
  memset(g, 0, sizeof *g);
}

int sl_stream_graph_build(sl_stream_graph *g, const sl_mesh *m) {
  int nv = m->n_vertices, nf = m->n_faces;
  g->start = calloc((size_t)nv + 1, sizeof *g->start);
  g->face = malloc((size_t)2 * nf * sizeof *g->face);
  g->queue = malloc((size_t)nv * sizeof *g->queue);
  g->seen = malloc((size_t)nv);
  if (!g->start || !g->face || !g->queue || !g->seen) return -1;
  for (int f = 0; f < nf; ++f) g->start[m->face_vertices[2 * f] + 1]++, g->start[m->face_vertices[2 * f + 1] + 1]++;
  for (int v = 0; v < nv; ++v) g->start[v + 1] += g->start[v];
  int *fill = g->queue; /* scratch */
  memcpy(fill, g->start, (size_t)nv * sizeof *fill);
  for (int f = 0; f < nf; ++f)
    g->face[fill[m->face_vertices[2 * f]]++] = f, g->face[fill[m->face_vertices[2 * f + 1]]++] = f;
  return 0;
}

void sl_stream_function(const sl_mesh *m, sl_stream_graph *g, const double *q, double *psi) {
  int head = 0, tail = 0;
  memset(g->seen, 0, (size_t)m->n_vertices);
  psi[0] = 0.0, g->seen[0] = 1, g->queue[tail++] = 0;
  while (head < tail) {
    int v = g->queue[head++];
    for (int k = g->start[v]; k < g->start[v + 1]; ++k) {
      int f = g->face[k], a = m->face_vertices[2 * f], b = m->face_vertices[2 * f + 1];
      int other = a == v ? b : a;
      if (g->seen[other]) continue;
      psi[other] = a == v ? psi[v] + q[f] : psi[v] - q[f];
      g->seen[other] = 1, g->queue[tail++] = other;
    }
  }
}

void sl_stream_function_nodes(const sl_th_space *th, sl_stream_graph *g, const double *q, double *psi,
                              double *node_psi) {
  const sl_mesh *m = th->mesh;
  sl_stream_function(m, g, q, psi);
  int nb = th->vel->dofs_per_cell, nvc = m->nv_per_cell;
  for (int c = 0; c < m->n_cells; ++c) {
    const int32_t *vd = th->vel->cell_nodes + (size_t)c * nb;
    const int *cv = m->cell_vertices + (size_t)c * nvc;
    for (int k = 0; k < nb; ++k) {
      double v = 0.0;
      if (k < nvc) {
        v = psi[cv[k]];
      } else if (k - nvc < nvc) {
        v = 0.5 * (psi[cv[k - nvc]] + psi[cv[(k - nvc + 1) % nvc]]);
      } else {
        for (int j = 0; j < nvc; ++j) v += psi[cv[j]] / nvc;
      }
      node_psi[vd[k]] = v;
    }
  }
}

#define CENTRE_PATCH 64 /* vertices of the cells around one vertex, at most */

int sl_stream_centre(const sl_mesh *m, const double *psi, double centre[2], double *value) {
  if (m->n_vertices < 1) return -1;
  int v0 = 0;
  for (int v = 1; v < m->n_vertices; ++v)
    if (fabs(psi[v]) > fabs(psi[v0])) v0 = v;
  const double *x0 = m->xy + 2 * v0;
  centre[0] = x0[0], centre[1] = x0[1], *value = psi[v0];
  /* the patch: the vertices of the cells that hold v0 */
  int patch[CENTRE_PATCH], np = 0, nv = m->nv_per_cell;
  for (int c = 0; c < m->n_cells; ++c) {
    const int *cv = m->cell_vertices + (size_t)nv * c;
    int has = 0;
    for (int k = 0; k < nv; ++k) has |= cv[k] == v0;
    if (!has) continue;
    for (int k = 0; k < nv; ++k) {
      int seen = 0;
      for (int i = 0; i < np; ++i) seen |= patch[i] == cv[k];
      if (!seen && np < CENTRE_PATCH) patch[np++] = cv[k];
    }
  }
  if (np < 6) return 0;
  double h = 0.0;
  for (int i = 0; i < np; ++i) h = fmax(h, hypot(m->xy[2 * patch[i]] - x0[0], m->xy[2 * patch[i] + 1] - x0[1]));
  /* the normal equations of the fit in X = (x - x0)/h, Y = (y - y0)/h */
  double N[36] = {0}, r[6] = {0};
  for (int i = 0; i < np; ++i) {
    double X = (m->xy[2 * patch[i]] - x0[0]) / h, Y = (m->xy[2 * patch[i] + 1] - x0[1]) / h;
    double basis[6] = {1.0, X, Y, X * X, X * Y, Y * Y};
    for (int a = 0; a < 6; ++a) {
      r[a] += basis[a] * psi[patch[i]];
      for (int b = 0; b < 6; ++b) N[6 * a + b] += basis[a] * basis[b];
    }
  }
  double k[6];
  if (sl_dense_solve(6, N, r, k, 1e-12)) return 0;
  double hxx = 2.0 * k[3], hxy = k[4], hyy = 2.0 * k[5], det = hxx * hyy - hxy * hxy;
  double s = psi[v0] < 0.0 ? -1.0 : 1.0; /* a maximum of s psi: s H negative definite */
  if (!(det > 0.0) || !(s * hxx < 0.0)) return 0;
  double X = -(hyy * k[1] - hxy * k[2]) / det, Y = -(hxx * k[2] - hxy * k[1]) / det;
  if (!(hypot(X, Y) <= 1.0)) return 0;
  centre[0] = x0[0] + h * X, centre[1] = x0[1] + h * Y;
  *value = k[0] + k[1] * X + k[2] * Y + k[3] * X * X + k[4] * X * Y + k[5] * Y * Y;
  return 1;
}
