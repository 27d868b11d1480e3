/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Quadrature rules on the reference cells.
 *
 * Reference cells (shared with core/fe/element.h):
 *  - line:     [-1, 1]                      (length 2)
 *  - quad:     [-1, 1] x [-1, 1]            (area 4)
 *  - triangle: (0, 0), (1, 0), (0, 1)       (area 1/2)
 * Weights sum to the reference measure. Points are stored as (xi, eta);
 * eta is 0 on the line.
 *
 * Rules
 *  - Gauss–Legendre on the line, n = 1..SL_GAUSS_MAX_POINTS points, exact
 *    to degree 2n - 1; nodes by Newton's method on P_n, weights
 *    2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun 1964, 25.4.29).
 *  - Tensor Gauss–Legendre on the quad, n x n points, exact to degree
 *    2n - 1 in each variable.
 *  - Symmetric rules on the triangle, all weights positive, points inside:
 *    degree 1 (centroid, 1 point), degree 2 (Strang & Fix 1973, 3 interior
 *    points), degree 4 (Dunavant 1985, 6 points), degree 5 (Radon 1948,
 *    as tabulated by Dunavant 1985, 7 points).
 *    D. A. Dunavant, High degree efficient symmetrical Gaussian quadrature
 *    rules for the triangle, Int. J. Numer. Meth. Eng. 21 (1985) 1129–1148. */
#ifndef SLUICE_FE_QUADRATURE_H
#define SLUICE_FE_QUADRATURE_H

#include "core/mesh/mesh.h"
#include "core/util/diag.h"

#define SL_QUAD_MAX_POINTS 64 /* 8 x 8 Gauss on the quad */
#define SL_GAUSS_MAX_POINTS 8 /* per direction */
#define SL_TRI_MAX_DEGREE 5

typedef struct sl_quadrature {
  sl_cell_type cell;
  int n;      /* number of points */
  int degree; /* exact for polynomials of total degree <= degree (per variable on the quad) */
  double xi[SL_QUAD_MAX_POINTS][2];
  double w[SL_QUAD_MAX_POINTS];
} sl_quadrature;

/* n-point Gauss–Legendre rule on [-1, 1]. */
int sl_quadrature_gauss_line(int n, sl_quadrature *q, sl_diag *d);
/* n x n tensor Gauss–Legendre rule on [-1, 1]^2. */
int sl_quadrature_gauss_quad(int n, sl_quadrature *q, sl_diag *d);
/* The cheapest tabulated symmetric triangle rule exact to at least `degree`
 * (0..SL_TRI_MAX_DEGREE). */
int sl_quadrature_triangle(int degree, sl_quadrature *q, sl_diag *d);
/* The cheapest rule above for the cell type that integrates polynomials of
 * the given degree exactly (degree >= 0). */
int sl_quadrature_for(sl_cell_type cell, int degree, sl_quadrature *q, sl_diag *d);
/* Measure of the reference cell: 2, 1/2 or 4. */
double sl_reference_measure(sl_cell_type cell);

#endif
