/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Small dense systems: Gaussian elimination with partial pivoting, for the
 * normal equations of small least-squares problems (Anderson's mixing
 * weights, core/solve/anderson.h; local polynomial fits). */
#ifndef SLUICE_SOLVE_DENSE_H
#define SLUICE_SOLVE_DENSE_H

/* Solves the m x m system A x = b (A row-major; A and b are overwritten). 0, or -1 when the largest diagonal
 * is not positive or a pivot falls below `pivot` times it (nearly dependent equations). */
int sl_dense_solve(int m, double *A, double *b, double *x, double pivot);

#endif
