/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Free slip on boundaries of any shape (curved walls): no flow through the
 * wall, u.n = 0, and no tangential stress, for the Taylor-Hood velocity.
 *
 * Each velocity node of the boundaries gets a normal n_i, and its two in-plane
 * momentum rows of the assembled Newton (or Picard) system are replaced by
 *
 *   the constraint row     n_i . du = 0                 (right-hand side 0),
 *   the tangential row     t_i . (row_x, row_y)         (right-hand side t_i . b),
 *
 * t_i = n_i turned by 90 degrees: a local rotation of the node's velocity
 * into (n, t) with u_n fixed (Engelman, Sani & Gresho 1982, Int. J. Numer.
 * Meth. Fluids 2:225), written without rotating the columns: the iterate
 * holds u_n = 0 (sl_slip_impose), so the columns of u_n multiply zero and
 * only the rows change. The tangential row is the momentum equation tested
 * with t_i phi_i, whose boundary term, the tangential traction, the weak
 * form leaves zero (the flow's viscous term is 2 mu D(u) : D(v),
 * core/assembly/flow.h, whose natural condition is (sigma n) . t = 0, the
 * zero-stress condition with its curvature term, not du_t/dn = 0). Other
 * components (a swirl, an out-of-plane velocity) stay free, as on a
 * straight slip wall.
 *
 * The normal is the mass-conserving one of Engelman et al. (1982, eq 14):
 * n_i proportional to int_G phi_i n w ds over the boundary faces (w = r
 * axisymmetric, else 1; along curved faces of a second-order mesh with
 * their own normal). With it sum_i u_i . int phi_i n w ds, the discrete
 * flux int_G u.n w ds through the walls, vanishes to round-off: no fluid is
 * lost through a polygonal or curved wall. On straight edges of Q2/P2 the
 * vertex weights are L/6 and the midpoint's 2L/3, so a vertex's normal is
 * the length-weighted mean of its two edges' normals and a midpoint's the
 * edge's own.
 *
 * Nodes the boundary shares with other conditions:
 *  - both in-plane components already fixed (a wall or inflow, which win
 *    corners): left as they are;
 *  - a corner, where the unit normals of the slip faces (this boundary's,
 *    a straight slip's or an axis's) at the node differ by more than
 *    SL_SLIP_CORNER_DEGREES: no flow through either face means u = 0 there,
 *    and the in-plane components not yet fixed are fixed to 0;
 *  - one component fixed (a smooth join with a straight slip wall or the
 *    axis): the straight condition is kept.
 * Everything else is rotated. */
#ifndef SLUICE_ASSEMBLY_SLIP_H
#define SLUICE_ASSEMBLY_SLIP_H

#include "core/assembly/system.h"

/* A turn of the wall's normal larger than this between two faces at a node is a corner. */
#define SL_SLIP_CORNER_DEGREES 45.0

typedef struct sl_slip {
  int32_t n;      /* rotated nodes */
  int32_t *row_n; /* [n]: the dof whose row becomes n . du = 0 (the component along which n is largest) */
  int32_t *row_t; /* [n]: the dof whose row becomes the tangential momentum */
  int32_t *dof_x; /* [n]: the node's component-0 and component-1 dofs */
  int32_t *dof_y;
  double *normal;    /* [2 n]: unit normals */
  double *tangent;   /* [2 n]: unit tangents, signed so that the row_t component is positive */
  int32_t n_corners; /* nodes whose in-plane velocity was fixed to 0 (corners) */
} sl_slip;

/* The slip nodes of the boundaries slip_ids[0 .. n_slip) of th's mesh (mesh boundary indices).
 * other_ids[0 .. n_other): straight slip walls and the axis, whose faces count for the corner test only.
 * bc holds the Dirichlet constraints of every other condition (applied before); corners are fixed in it.
 * axisymmetric: r-weighted normals. Returns 0, SL_EBADINPUT (a 1-D mesh, fewer than 2 components) or
 * SL_ENOMEM. */
int sl_slip_create(sl_slip *s, const sl_th_space *th, const int *slip_ids, int n_slip, const int *other_ids,
                   int n_other, int axisymmetric, sl_constraints *bc, sl_diag *d);
void sl_slip_free(sl_slip *s);

/* u . n_i = 0 at every slip node: u_i -= (u_i . n_i) n_i (the tangential part unchanged). */
void sl_slip_impose(const sl_slip *s, double *u);

/* The rows of the slip nodes in A (may be NULL: b only) and b: the constraint row n . du = 0 with b = 0,
 * the tangential row t . (row_x, row_y) with b = t . (b_x, b_y). The rows of a node's two components must
 * have the same pattern (they do for every Taylor-Hood system, whose cells hold all components of a node);
 * SL_EFAILED otherwise. A must not be distributed over ranks. */
int sl_slip_rows(const sl_slip *s, sl_csr *A, double *b, sl_diag *d);

/* b = 0 in the constraint rows. */
void sl_slip_zero_normal(const sl_slip *s, double *b);

/* The discrete flux int_G u.n w ds through the slip faces of the velocity u (combined numbering), and the
 * scale int_G |u| w ds it is measured against: for tests (0 to round-off). */
void sl_slip_flux(const sl_th_space *th, const int *slip_ids, int n_slip, int axisymmetric, const double *u,
                  double *flux, double *scale);

#endif
