/* SPDX-License-Identifier: GPL-2.0-or-later */
/* An implicit scalar in the cells of the staggered grid (core/fv/grid.h):
 * one backward-Euler step of
 *
 *   c ds/dt + div(F s) - div(k grad s) = S - D s,   D >= 0,
 *
 * by finite volumes: the storage c V (s - s_old) / dt, the convective flux
 * through each face F_f s of the upwind cell (F the volume flux along +x or
 * +y, given), the diffusive flux between two cells with the mean of their k
 * over the centres' distance, the source S and the sink D s implicit (a
 * sink keeps the matrix an M-matrix: with upwind convection the scheme is
 * bounded at any step). A boundary face carries no flux unless the caller's
 * per-cell hook adds one (a wall's flux, a given value). Periodic
 * directions join the rows as the grid does. The pattern (each cell with
 * its neighbours) is built once, each step's matrix solved directly (KLU).
 * The granular temperature of the 2-D two-fluid model, the shear layer
 * (its n x 1 cells) and the pipe is one (core/models/granular.h gives its
 * terms); the pipe's k, epsilon and radial solids balance are more. */
#ifndef SLUICE_FV_CELL_SCALAR_H
#define SLUICE_FV_CELL_SCALAR_H

#include "core/fv/grid.h"
#include "core/solve/linsolve.h"

typedef struct sl_cell_scalar {
  const sl_fv_grid *g;
  sl_csr A;
  sl_linsolve *ls;
  double *rhs;
} sl_cell_scalar;

typedef struct sl_cell_scalar_terms {
  double dt;
  const double *cap;    /* [nc] c, per unit volume */
  const double *s_old;  /* [nc] at the step's start */
  const double *k;      /* [nc] the diffusivity of each cell (NULL: none) */
  const double *source; /* [nc] S, per unit volume (NULL: none) */
  const double *sink;   /* [nc] D >= 0, per unit volume (NULL: none) */
  const double *flux;   /* [nf] the volume flux through each face (NULL: no convection) */
  /* A cell's boundary terms, added to its equation after the rest (NULL: none). */
  int (*boundary)(void *user, int c, double *rhs, double *diag, sl_diag *d);
  void *boundary_user;
} sl_cell_scalar_terms;

int sl_cell_scalar_init(sl_cell_scalar *cs, const sl_fv_grid *g, sl_diag *d);
/* The step's s into s (the caller bounds it as its physics needs). 0, or
 * SL_EFAILED (the solve failed; s is untouched). */
int sl_cell_scalar_solve(sl_cell_scalar *cs, const sl_cell_scalar_terms *t, double *s, sl_diag *d);
void sl_cell_scalar_free(sl_cell_scalar *cs);

#endif
