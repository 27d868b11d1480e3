/* SPDX-License-Identifier: GPL-2.0-or-later */
/* An implicit cell scalar on the staggered grid (cell_scalar.h). */
#include "core/fv/cell_scalar.h"

#include <stdlib.h>
#include <string.h>

int sl_cell_scalar_init(sl_cell_scalar *cs, const sl_fv_grid *g, sl_diag *d) {
  memset(cs, 0, sizeof *cs);
  cs->g = g;
  const int nc = g->nc;
  /* the pattern: each cell with its east and north neighbours (the element pairs make it symmetric) */
  int32_t *pairs = malloc(4 * (size_t)nc * sizeof *pairs);
  cs->rhs = malloc((size_t)nc * sizeof *cs->rhs);
  if (!pairs || !cs->rhs) {
    free(pairs);
    return sl_diag_set(d, SL_ENOMEM, "cell scalar: out of memory");
  }
  for (int c = 0; c < nc; ++c)
    for (int dir = 0; dir < 2; ++dir)
      pairs[4 * c + 2 * dir] = c, pairs[4 * c + 2 * dir + 1] = sl_fv_neighbour(g, c, dir, 1);
  int rc = sl_csr_build_uniform(&cs->A, nc, 2 * nc, 2, pairs, d);
  free(pairs);
  if (!rc) rc = sl_linsolve_create(&cs->ls, "klu", d);
  return rc;
}

void sl_cell_scalar_free(sl_cell_scalar *cs) {
  sl_csr_free(&cs->A);
  sl_linsolve_destroy(cs->ls);
  free(cs->rhs);
  memset(cs, 0, sizeof *cs);
}

int sl_cell_scalar_solve(sl_cell_scalar *cs, const sl_cell_scalar_terms *t, double *s, sl_diag *d) {
  const sl_fv_grid *g = cs->g;
  sl_csr *A = &cs->A;
  int rc = 0;
  sl_csr_zero(A);
  for (int c = 0; c < g->nc && !rc; ++c) {
    double V = g->vol[c], cap = t->cap[c] * V / t->dt;
    double diag = cap + V * (t->sink ? t->sink[c] : 0.0);
    cs->rhs[c] = cap * t->s_old[c] + V * (t->source ? t->source[c] : 0.0);
    int cf[4];
    sl_fv_cell_faces(g, c, cf);
    for (int dir = 0; dir < 2; ++dir)
      for (int side = 0; side < 2; ++side) {
        int nb = sl_fv_neighbour(g, c, dir, side), f = cf[2 * dir + side];
        if (nb < 0 || nb == c) continue;
        if (t->k) { /* an image face has its first face's area and distance */
          double k = 0.5 * (t->k[c] + t->k[nb]) * g->area[f] / g->dist[f];
          diag += k;
          A->values[sl_csr_find(A, c, nb)] -= k;
        }
        if (t->flux) { /* upwind: what leaves through the face takes this cell's s, what enters the neighbour's */
          double F = t->flux[sl_fv_primary(g, f)], out = side ? F : -F;
          if (out > 0.0) diag += out;
          else A->values[sl_csr_find(A, c, nb)] += out;
        }
      }
    if (t->boundary) rc = t->boundary(t->boundary_user, c, &cs->rhs[c], &diag, d);
    A->values[sl_csr_find(A, c, c)] += diag;
  }
  if (rc) return rc;
  sl_csr_touch(A);
  return sl_linsolve_solve(cs->ls, A, cs->rhs, s, d);
}
