/* MUSCL reconstruction (van Leer 1979): a least-squares gradient per cell
 * from its face neighbours, limited so that the value at every face point
 * stays within beta times the distance to the extreme of the cell and its
 * neighbours (Barth & Jespersen 1989, AIAA paper 89-0366; beta = 1). On a
 * uniform 1-D grid the least-squares slope is the central one and this limit
 * is exactly the monotonized-central limiter (van Leer 1977); beta = 1/2
 * gives minmod. Face values inside the neighbours' range are what the
 * bound argument of transport.h needs. Across a periodic pair the
 * neighbour's cell point is translated next to the face. */
#include <math.h>

#include "core/transport/transport_impl.h"

void sl_transport_reconstruct(sl_transport *t, const double *phi) {
  const sl_mesh *m = t->m;
  const int nfc = m->nf_per_cell;
  const double beta = t->o.limiter == SL_LIMITER_MINMOD ? 0.5 : 1.0;
  for (int c = 0; c < m->n_cells; ++c) {
    const double *L = t->lsq + 3 * c, *xc = t->xc + 2 * c;
    double *g = t->grad + 2 * c;
    g[0] = g[1] = 0;
    if (L[0] == 0 && L[2] == 0) continue;
    double rx = 0, ry = 0, pc = phi[c], lo = pc, hi = pc;
    for (int k = 0; k < nfc; ++k) {
      int f = m->cell_faces[(size_t)c * nfc + k];
      double sh[2];
      int j = sl_transport_across(t, f, c, sh);
      if (j < 0) continue;
      double dp = phi[j] - pc;
      rx += (t->xc[2 * j] + sh[0] - xc[0]) * dp;
      ry += (t->xc[2 * j + 1] + sh[1] - xc[1]) * dp;
      if (phi[j] < lo) lo = phi[j];
      if (phi[j] > hi) hi = phi[j];
    }
    double gx = L[0] * rx + L[1] * ry, gy = L[1] * rx + L[2] * ry;
    if (gx == 0 && gy == 0) continue;
    double alpha = 1, up = beta * (hi - pc), down = beta * (lo - pc); /* up >= 0 >= down */
    for (int k = 0; k < nfc; ++k) {
      int f = m->cell_faces[(size_t)c * nfc + k];
      double dv = gx * (t->xf[2 * f] - xc[0]) + gy * (t->xf[2 * f + 1] - xc[1]);
      if (dv > 0 && alpha * dv > up) alpha = up / dv;
      else if (dv < 0 && alpha * dv < down) alpha = down / dv;
    }
    g[0] = alpha * gx;
    g[1] = alpha * gy;
  }
}
