/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The staggered grid's geometry and topology (grid.h). */
#include "core/fv/grid.h"

#include <stdlib.h>
#include <string.h>

int sl_fv_grid_build(sl_fv_grid *m, const sl_tensor_grid *g, int axi, const int periodic[2], sl_diag *d) {
  memset(m, 0, sizeof *m);
  const int nx = g->nx, ny = g->ny;
  m->tg = g, m->axi = axi, m->periodic[0] = periodic[0], m->periodic[1] = periodic[1];
  m->nx = nx, m->ny = ny, m->nc = nx * ny, m->nfx = (nx + 1) * ny, m->nf = m->nfx + nx * (ny + 1);
  const size_t nc = (size_t)m->nc, nf = (size_t)m->nf;
  struct {
    double **p;
    size_t n;
  } a[] = {{&m->xc, nx}, {&m->yc, ny}, {&m->hx, nx}, {&m->hy, ny}, {&m->vol, nc}, {&m->area, nf}, {&m->dist, nf}};
  for (size_t k = 0; k < sizeof a / sizeof a[0]; ++k)
    if (!(*a[k].p = calloc(a[k].n, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "grid: out of memory");
  int **ia[] = {&m->lo, &m->hi, &m->bound, &m->image};
  for (size_t k = 0; k < sizeof ia / sizeof ia[0]; ++k)
    if (!(*ia[k] = calloc(nf, sizeof(int)))) return sl_diag_set(d, SL_ENOMEM, "grid: out of memory");
  for (int i = 0; i < nx; ++i) m->hx[i] = g->xf[i + 1] - g->xf[i], m->xc[i] = 0.5 * (g->xf[i] + g->xf[i + 1]);
  for (int j = 0; j < ny; ++j) m->hy[j] = g->yf[j + 1] - g->yf[j], m->yc[j] = 0.5 * (g->yf[j] + g->yf[j + 1]);
  for (int c = 0; c < m->nc; ++c) {
    int i = c % nx, j = c / nx;
    m->vol[c] = m->hx[i] * m->hy[j] * (axi ? m->xc[i] : 1.0);
  }
  for (int f = 0; f < m->nf; ++f) {
    int side = -1, k = 0, image = 0;
    if (f < m->nfx) {
      int i = f % (nx + 1), j = f / (nx + 1);
      m->lo[f] = i > 0 ? i - 1 + nx * j : -1, m->hi[f] = i < nx ? i + nx * j : -1;
      m->area[f] = m->hy[j] * (axi ? g->xf[i] : 1.0);
      m->dist[f] = i == 0 ? 0.5 * m->hx[0] : i == nx ? 0.5 * m->hx[nx - 1] : m->xc[i] - m->xc[i - 1];
      if (m->periodic[0] && (i == 0 || i == nx)) { /* between the last cell of the row and the first */
        m->lo[f] = nx - 1 + nx * j, m->hi[f] = nx * j, m->dist[f] = 0.5 * (m->hx[0] + m->hx[nx - 1]);
        image = i == nx;
      } else if (i == 0 || i == nx) side = i == 0 ? SL_SIDE_LEFT : SL_SIDE_RIGHT, k = j;
    } else {
      int i = (f - m->nfx) % nx, j = (f - m->nfx) / nx;
      m->lo[f] = j > 0 ? i + nx * (j - 1) : -1, m->hi[f] = j < ny ? i + nx * j : -1;
      m->area[f] = m->hx[i] * (axi ? m->xc[i] : 1.0);
      m->dist[f] = j == 0 ? 0.5 * m->hy[0] : j == ny ? 0.5 * m->hy[ny - 1] : m->yc[j] - m->yc[j - 1];
      if (m->periodic[1] && (j == 0 || j == ny)) {
        m->lo[f] = i + nx * (ny - 1), m->hi[f] = i, m->dist[f] = 0.5 * (m->hy[0] + m->hy[ny - 1]);
        image = j == ny;
      } else if (j == 0 || j == ny) side = j == 0 ? SL_SIDE_BOTTOM : SL_SIDE_TOP, k = i;
    }
    m->bound[f] = side >= 0 ? g->side_tag[side][k] : -1;
    m->image[f] = image;
  }
  return 0;
}

int sl_fv_grid_block(sl_fv_grid *m, const int *body, int tag_base, sl_diag *d) {
  if (!(m->blocked = malloc((size_t)m->nc * sizeof *m->blocked)))
    return sl_diag_set(d, SL_ENOMEM, "grid: out of memory");
  memcpy(m->blocked, body, (size_t)m->nc * sizeof *body);
  for (int f = 0; f < m->nf; ++f) {
    int lo = m->lo[f], hi = m->hi[f], blo = lo >= 0 ? body[lo] : -1, bhi = hi >= 0 ? body[hi] : -1;
    if (blo < 0 && bhi < 0) continue;
    int dir = f >= m->nfx;
    if (blo >= 0) m->lo[f] = -1;
    if (bhi >= 0) m->hi[f] = -1;
    m->bound[f] = tag_base + (blo >= 0 ? blo : bhi);
    int open = m->lo[f] >= 0 ? m->lo[f] : m->hi[f];
    if (open >= 0) m->dist[f] = 0.5 * (dir == 0 ? m->hx[open % m->nx] : m->hy[open / m->nx]);
  }
  return 0;
}

void sl_fv_grid_free(sl_fv_grid *m) {
  double *all[] = {m->xc, m->yc, m->hx, m->hy, m->vol, m->area, m->dist};
  for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) free(all[k]);
  int *ia[] = {m->lo, m->hi, m->bound, m->image, m->blocked};
  for (size_t k = 0; k < sizeof ia / sizeof ia[0]; ++k) free(ia[k]);
  memset(m, 0, sizeof *m);
}
