/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The integration context: quadrature points, Jacobians and physical basis
 * gradients on one mesh cell at a time.
 *
 * The geometry is isoparametric of the mesh's geom_order: order 1 (affine
 * lines and triangles, bilinear quads) for straight-sided cells, order 2
 * (the P2 / Q2 map through the face and centre nodes, core/mesh/curved.c)
 * for a mesh with second-order geometry, so curved walls are integrated as
 * curves. Up to
 * SL_FE_MAX_SPACES elements of the same cell type are tabulated at the same
 * quadrature points (e.g. velocity and pressure of a Taylor–Hood pair).
 *
 * Axisymmetric (r, z) problems: with `axisymmetric` set, JxW includes the
 * factor r = x of the quadrature point, so sum_q JxW[q] g(x_q) approximates
 * the integral of g r dr dz. The 2 pi of the full revolution is left out: it
 * cancels in the equations; multiply by it for fluxes and volumes. */
#ifndef SLUICE_FE_GEOMETRY_H
#define SLUICE_FE_GEOMETRY_H

#include "core/fe/element.h"
#include "core/fe/quadrature.h"
#include "core/mesh/mesh.h"
#include "core/util/diag.h"

#define SL_FE_MAX_SPACES 2

typedef struct sl_fe_values {
  const sl_mesh *mesh; /* not owned */
  sl_quadrature quad;
  int axisymmetric;
  int n_spaces;
  const sl_element *space[SL_FE_MAX_SPACES];
  const sl_element *geom; /* the geometric map: P1/Q1 of the cell type, P2/Q2 for geom_order 2 */

  /* Tabulated once, on the reference cell. */
  double geom_phi[SL_QUAD_MAX_POINTS][SL_ELEMENT_MAX_BASIS];
  double geom_dphi[SL_QUAD_MAX_POINTS][SL_ELEMENT_MAX_BASIS][2];
  double phi[SL_FE_MAX_SPACES][SL_QUAD_MAX_POINTS][SL_ELEMENT_MAX_BASIS];
  double dphi_ref[SL_FE_MAX_SPACES][SL_QUAD_MAX_POINTS][SL_ELEMENT_MAX_BASIS][2];

  /* Set by sl_fe_values_reinit for the current cell. */
  int cell;
  double x[SL_QUAD_MAX_POINTS][2];    /* physical quadrature points */
  double J[SL_QUAD_MAX_POINTS][2][2]; /* J[q][i][j] = d x_i / d xi_j (1-D: J[q][0][0] only) */
  double detJ[SL_QUAD_MAX_POINTS];
  double JxW[SL_QUAD_MAX_POINTS];                                             /* detJ * w (* r when axisymmetric) */
  double grad[SL_FE_MAX_SPACES][SL_QUAD_MAX_POINTS][SL_ELEMENT_MAX_BASIS][2]; /* J^-T dphi_ref */
} sl_fe_values;

/* Prepares the context for n_spaces (1..SL_FE_MAX_SPACES) elements on the
 * mesh's cell type with the cheapest rule exact to quad_degree. The struct is
 * large (about 60 kB): allocate it on the heap (sl_fe_values_create). */
int sl_fe_values_init(sl_fe_values *fv, const sl_mesh *mesh, int n_spaces, const sl_element *const *spaces,
                      int quad_degree, int axisymmetric, sl_diag *d);
/* Heap-allocating variant of init; free with sl_fe_values_destroy. */
int sl_fe_values_create(sl_fe_values **fv, const sl_mesh *mesh, int n_spaces, const sl_element *const *spaces,
                        int quad_degree, int axisymmetric, sl_diag *d);
void sl_fe_values_destroy(sl_fe_values *fv);

/* Computes the geometry and physical gradients on cell c. Returns 0, or
 * SL_EBADINPUT when the Jacobian is not positive at a quadrature point (an
 * inverted or degenerate cell) or, axisymmetric, a point has r < 0. */
int sl_fe_values_reinit(sl_fe_values *fv, int c, sl_diag *d);
/* The same without the physical gradients (x, J, detJ, JxW only; grad is
 * left as it was): for integrals of basis values alone, e.g. a load. */
int sl_fe_values_reinit_measure(sl_fe_values *fv, int c, sl_diag *d);

/* Physical coordinates of the quadrature points of cell c only (no
 * Jacobians): the cheap pass that gathers points for batched coefficients. */
void sl_fe_values_map_points(const sl_fe_values *fv, int c, double (*x)[2]);

/* Maps the reference point xi of cell c to x. */
void sl_fe_map_point(const sl_mesh *mesh, int c, const double xi[2], double x[2]);

/* The geometric map's element of the mesh (P1/Q1, or P2/Q2 for geom_order 2). */
const sl_element *sl_fe_geometry_element(const sl_mesh *mesh);

/* A point of local face lf of cell c, at s in [0, 1] from the face's first
 * vertex (local vertex lf) to its second (lf + 1): the reference point xi,
 * the physical point x, the outward unit normal n and the length element
 * |dx/ds| (for int_face g ds = int_0^1 g |dx/ds| ds), along the curved
 * face when the mesh has second-order geometry. 2-D only. Any of x, n, ds
 * may be NULL. */
void sl_fe_face_point(const sl_mesh *mesh, int c, int lf, double s, double xi[2], double x[2], double n[2], double *ds);

#endif
