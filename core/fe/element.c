/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lagrange bases on the reference cells, written out per element: each is
 * a handful of products, clearer as formulas than as a generic tensor code. */
#include "core/fe/element.h"

#include <stddef.h>

/* ---- line [-1, 1] -------------------------------------------------------- */

static void line_p1(const double xi[2], double *phi, double (*dphi)[2]) {
  double x = xi[0];
  if (phi) phi[0] = 0.5 * (1.0 - x), phi[1] = 0.5 * (1.0 + x);
  if (dphi) dphi[0][0] = -0.5, dphi[1][0] = 0.5, dphi[0][1] = dphi[1][1] = 0.0;
}

static void line_p2(const double xi[2], double *phi, double (*dphi)[2]) {
  double x = xi[0];
  if (phi) phi[0] = 0.5 * x * (x - 1.0), phi[1] = 0.5 * x * (x + 1.0), phi[2] = 1.0 - x * x;
  if (dphi) {
    dphi[0][0] = x - 0.5, dphi[1][0] = x + 0.5, dphi[2][0] = -2.0 * x;
    dphi[0][1] = dphi[1][1] = dphi[2][1] = 0.0;
  }
}

/* ---- triangle (0,0), (1,0), (0,1) ---------------------------------------- */

static void tri_p1(const double xi[2], double *phi, double (*dphi)[2]) {
  if (phi) phi[0] = 1.0 - xi[0] - xi[1], phi[1] = xi[0], phi[2] = xi[1];
  if (dphi) {
    dphi[0][0] = -1.0, dphi[0][1] = -1.0;
    dphi[1][0] = 1.0, dphi[1][1] = 0.0;
    dphi[2][0] = 0.0, dphi[2][1] = 1.0;
  }
}

/* In barycentric coordinates l0 = 1 - x - y, l1 = x, l2 = y: vertices
 * l_i (2 l_i - 1), edge (i, j) midpoints 4 l_i l_j. */
static void tri_p2(const double xi[2], double *phi, double (*dphi)[2]) {
  double l0 = 1.0 - xi[0] - xi[1], l1 = xi[0], l2 = xi[1];
  if (phi) {
    phi[0] = l0 * (2.0 * l0 - 1.0), phi[1] = l1 * (2.0 * l1 - 1.0), phi[2] = l2 * (2.0 * l2 - 1.0);
    phi[3] = 4.0 * l0 * l1, phi[4] = 4.0 * l1 * l2, phi[5] = 4.0 * l2 * l0;
  }
  if (dphi) {
    /* dl0 = (-1, -1), dl1 = (1, 0), dl2 = (0, 1) */
    double a = 4.0 * l0 - 1.0;
    dphi[0][0] = -a, dphi[0][1] = -a;
    dphi[1][0] = 4.0 * l1 - 1.0, dphi[1][1] = 0.0;
    dphi[2][0] = 0.0, dphi[2][1] = 4.0 * l2 - 1.0;
    dphi[3][0] = 4.0 * (l0 - l1), dphi[3][1] = -4.0 * l1;
    dphi[4][0] = 4.0 * l2, dphi[4][1] = 4.0 * l1;
    dphi[5][0] = -4.0 * l2, dphi[5][1] = 4.0 * (l0 - l2);
  }
}

/* ---- quadrilateral [-1, 1]^2 --------------------------------------------- */

/* Tensor products of the 1-D bases; ix/iy pick the 1-D factor of each node
 * (0: at -1, 1: at +1, 2: the midpoint for Q2). */
static void tensor(int n, const int (*ij)[2], const double *fx, const double *dfx, const double *fy, const double *dfy,
                   double *phi, double (*dphi)[2]) {
  for (int k = 0; k < n; ++k) {
    int i = ij[k][0], j = ij[k][1];
    if (phi) phi[k] = fx[i] * fy[j];
    if (dphi) dphi[k][0] = dfx[i] * fy[j], dphi[k][1] = fx[i] * dfy[j];
  }
}

static const int q1_ij[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
static const int q2_ij[9][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {1, 2}, {2, 1}, {0, 2}, {2, 2}};

static void quad_q1(const double xi[2], double *phi, double (*dphi)[2]) {
  double fx[2], fy[2], dfx[2][2], dfy[2][2];
  line_p1((double[2]){xi[0], 0.0}, fx, dfx);
  line_p1((double[2]){xi[1], 0.0}, fy, dfy);
  double gx[2] = {dfx[0][0], dfx[1][0]}, gy[2] = {dfy[0][0], dfy[1][0]};
  tensor(4, q1_ij, fx, gx, fy, gy, phi, dphi);
}

static void quad_q2(const double xi[2], double *phi, double (*dphi)[2]) {
  double fx[3], fy[3], dfx[3][2], dfy[3][2];
  line_p2((double[2]){xi[0], 0.0}, fx, dfx);
  line_p2((double[2]){xi[1], 0.0}, fy, dfy);
  double gx[3] = {dfx[0][0], dfx[1][0], dfx[2][0]}, gy[3] = {dfy[0][0], dfy[1][0], dfy[2][0]};
  tensor(9, q2_ij, fx, gx, fy, gy, phi, dphi);
}

/* ---- table ---------------------------------------------------------------- */

static const double line_p1_nodes[2][2] = {{-1, 0}, {1, 0}};
static const double line_p2_nodes[3][2] = {{-1, 0}, {1, 0}, {0, 0}};
static const double tri_p1_nodes[3][2] = {{0, 0}, {1, 0}, {0, 1}};
static const double tri_p2_nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
static const double quad_q1_nodes[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
static const double quad_q2_nodes[9][2] = {{-1, -1}, {1, -1}, {1, 1},  {-1, 1}, {0, -1},
                                           {1, 0},   {0, 1},  {-1, 0}, {0, 0}};

static const sl_element elements[] = {
    {"P1", SL_CELL_LINE2, 1, 1, 2, line_p1_nodes, line_p1}, {"P2", SL_CELL_LINE2, 2, 1, 3, line_p2_nodes, line_p2},
    {"P1", SL_CELL_TRI3, 1, 2, 3, tri_p1_nodes, tri_p1},    {"P2", SL_CELL_TRI3, 2, 2, 6, tri_p2_nodes, tri_p2},
    {"Q1", SL_CELL_QUAD4, 1, 2, 4, quad_q1_nodes, quad_q1}, {"Q2", SL_CELL_QUAD4, 2, 2, 9, quad_q2_nodes, quad_q2},
};

const sl_element *sl_element_lagrange(sl_cell_type cell, int order) {
  for (size_t k = 0; k < sizeof elements / sizeof elements[0]; ++k)
    if (elements[k].cell == cell && elements[k].order == order) return &elements[k];
  return NULL;
}
