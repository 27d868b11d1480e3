/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lagrange reference elements: P1/P2 on the line, P1/P2 on the triangle,
 * Q1/Q2 on the quadrilateral (reference cells in core/fe/quadrature.h).
 *
 * Basis (node) order, which the dof maps follow:
 *  - vertices first, in the cell's counter-clockwise vertex order;
 *  - then one node per face for order 2, local face k (joining vertices k
 *    and k + 1) at its midpoint; on the line the P2 midpoint instead;
 *  - then the centre node of Q2.
 * Reference vertices: line -1, 1; triangle (0,0), (1,0), (0,1); quad
 * (-1,-1), (1,-1), (1,1), (-1,1). */
#ifndef SLUICE_FE_ELEMENT_H
#define SLUICE_FE_ELEMENT_H

#include "core/mesh/mesh.h"

#define SL_ELEMENT_MAX_BASIS 9 /* Q2 */

typedef struct sl_element {
  const char *name; /* "P1", "P2", "Q1", "Q2" */
  sl_cell_type cell;
  int order;                /* polynomial order: 1 or 2 */
  int dim;                  /* 1 or 2 */
  int n_basis;              /* basis functions (= nodes) per cell */
  const double (*nodes)[2]; /* [n_basis] reference node coordinates */
  /* Values phi[n_basis] and reference gradients dphi[n_basis][2] (d/dxi,
   * d/deta; d/deta = 0 on the line) at the reference point xi. Either
   * output may be NULL. */
  void (*eval)(const double xi[2], double *phi, double (*dphi)[2]);
} sl_element;

/* The Lagrange element of the given order (1 or 2) on the cell type, or
 * NULL when there is none. The element is static: never freed. */
const sl_element *sl_element_lagrange(sl_cell_type cell, int order);

#endif
