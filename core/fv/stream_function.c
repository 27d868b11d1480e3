/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The stream function of conservative face fluxes (stream_function.h). */
#include "core/fv/stream_function.h"

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
  for (int f = 0; f < nf; ++f) g->face[fill[m->face_vertices[2 * f]]++] = f, g->face[fill[m->face_vertices[2 * f + 1]]++] = f;
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
