/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The staggered (MAC) finite-volume grid of Harlow & Welch (1965) on a
 * tensor grid (core/mesh/tensor_grid.h), planar or axisymmetric: scalars in
 * the cells, the normal components of vectors on the faces.
 *
 * Cells c = i + nx j. Faces: x-faces (normal along x) f = i + (nx + 1) j,
 * i = 0..nx, j = 0..ny-1, then y-faces f = nfx + i + nx j, i = 0..nx-1,
 * j = 0..ny. A face's lo cell is on its minus side, hi on its plus side (-1
 * outside the domain). Along a periodic direction the faces at i = 0 and
 * i = nx (or j = 0, ny) join the last cell of the row to the first; the one
 * at i = nx (j = ny) is an image of the first, carrying no unknowns of its
 * own. Axisymmetric (x = r): volumes r dr dz and areas r dz or r dr, per
 * radian. The models on it (the 2-D two-fluid model; the cell scalars of
 * core/fv/cell_scalar.h) add their own face types and numbering. */
#ifndef SLUICE_FV_GRID_H
#define SLUICE_FV_GRID_H

#include "core/mesh/tensor_grid.h"

typedef struct sl_fv_grid {
  const sl_tensor_grid *tg; /* the grid lines, the sides' boundary tags (not owned) */
  int nx, ny, nc, nfx, nf;
  int axi;
  int periodic[2];           /* along x, along y */
  double *xc, *yc, *hx, *hy; /* cell centres and sizes along x [nx], y [ny] */
  double *vol;               /* [nc] */
  double *area, *dist;       /* [nf]: face area, centre-to-centre distance (half a cell at a boundary) */
  int *lo, *hi;              /* [nf] */
  int *bound;                /* [nf]: the boundary (mesh tag) of a boundary face, -1 inside or periodic */
  int *image;                /* [nf]: 1 for a periodic image face */
  /* [nc]: the body (0, 1, ...) a blocked cell belongs to, -1 for an open cell; NULL: none blocked
     (sl_fv_grid_block) */
  int *blocked;
} sl_fv_grid;

/* The grid on tg; periodic[dir] joins the two sides across dir. 0 or SL_EFAILED (memory). */
int sl_fv_grid_build(sl_fv_grid *g, const sl_tensor_grid *tg, int axi, const int periodic[2], sl_diag *d);
void sl_fv_grid_free(sl_fv_grid *g);

/* Removes cells from the grid: body[c] >= 0 blocks cell c as part of body
 * body[c] (-1: open). A blocked cell is outside the domain: a face between
 * a blocked and an open cell becomes a boundary face of the open one (its
 * blocked side -1, its distance half the open cell, its boundary
 * tag_base + body), a face with blocked or no cells on both sides is dead
 * (lo = hi = -1, tagged with the body), and sl_fv_neighbour does not cross
 * into a body. After sl_fv_grid_build; not with periodic directions. 0 or
 * SL_ENOMEM. */
int sl_fv_grid_block(sl_fv_grid *g, const int *body, int tag_base, sl_diag *d);

/* 1 for a face with no open cell on either side (inside a body, or on the
 * domain's side of a blocked cell). */
static inline int sl_fv_dead(const sl_fv_grid *g, int f) { return g->blocked && g->lo[f] < 0 && g->hi[f] < 0; }

/* The neighbour of cell c along dir (0: x, 1: y) on its minus (side 0) or
 * plus (side 1) side, wrapping along a periodic direction; -1 outside. */
static inline int sl_fv_neighbour(const sl_fv_grid *g, int c, int dir, int side) {
  int i = c % g->nx, j = c / g->nx, n = dir == 0 ? g->nx : g->ny, k = (dir == 0 ? i : j) + (side ? 1 : -1);
  if (k < 0 || k >= n) {
    if (!g->periodic[dir]) return -1;
    k = (k + n) % n;
  }
  int nb = dir == 0 ? k + g->nx * j : i + g->nx * k;
  return g->blocked && g->blocked[nb] >= 0 ? -1 : nb;
}

/* The face whose unknowns face f shares: f, or for an image face the first
 * face of its periodic row (x-faces) or column (y-faces). */
static inline int sl_fv_primary(const sl_fv_grid *g, int f) {
  if (!g->image[f]) return f;
  return f < g->nfx ? f - g->nx : f - g->nx * g->ny;
}

/* The four faces of cell c: west, east, south, north. */
static inline void sl_fv_cell_faces(const sl_fv_grid *g, int c, int f[4]) {
  int i = c % g->nx, j = c / g->nx;
  f[0] = i + (g->nx + 1) * j, f[1] = f[0] + 1;
  f[2] = g->nfx + i + g->nx * j, f[3] = f[2] + g->nx;
}

#endif
