/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Anderson acceleration of a fixed-point iteration x <- G(x).
 *
 * Walker & Ni (2011), SIAM J. Numer. Anal. 49:1715, "Anderson
 * acceleration for fixed-point iterations", Algorithm AA with depth m in
 * its "type II" form: with f_k = G(x_k) - x_k and the differences
 * dF_j = f_{j+1} - f_j, dG_j = G(x_{j+1}) - G(x_j) of the last m
 * iterations, gamma minimises |W (f_k - dF gamma)|_2 and the next iterate
 * is x_{k+1} = G(x_k) - dG gamma. W is a diagonal weight (the inverse
 * scale of each unknown), so that unknowns of different units (a velocity
 * and a granular temperature) weigh alike. A segregated iteration that
 * converges linearly (one field solved after the other, each holding the
 * other fixed) typically turns superlinear: Anderson with depth m is a
 * multisecant quasi-Newton method (Fang & Saad 2009).
 *
 * The least-squares problem is solved by its m x m normal equations
 * (Gaussian elimination with partial pivoting); when those are
 * ill-conditioned (columns nearly dependent) the oldest differences are
 * dropped until they are not, and with none left the step is the plain
 * fixed-point one. */
#ifndef SLUICE_SOLVE_ANDERSON_H
#define SLUICE_SOLVE_ANDERSON_H

#include "core/util/diag.h"

typedef struct sl_anderson {
  int n, depth;    /* unknowns; the most differences kept */
  int count;       /* differences held now (<= depth) */
  int have_prev;   /* f and G of the previous iterate are held */
  double *dF, *dG; /* [depth][n], oldest first */
  double *f_prev, *g_prev;
  double *f; /* work: f_k */
  double gram[64], rhs[8], gamma[8];
  int dropped; /* differences dropped for conditioning since the last reset (a diagnostic) */
} sl_anderson;

enum { SL_ANDERSON_MAX_DEPTH = 8 };

/* Allocates for n unknowns and depth 1..SL_ANDERSON_MAX_DEPTH. */
int sl_anderson_init(sl_anderson *a, int n, int depth, sl_diag *d);
void sl_anderson_free(sl_anderson *a);

/* Forgets the history (a new step, or the fixed-point map changed). */
void sl_anderson_reset(sl_anderson *a);

/* x: the iterate the map was applied to; g: G(x) on entry, the accelerated
 * next iterate on return; scale: each unknown's scale (> 0), its weight the
 * inverse. */
void sl_anderson_apply(sl_anderson *a, const double *x, double *g, const double *scale);

#endif
