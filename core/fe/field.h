/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Finite-element functions given by a dof map and a coefficient vector:
 * evaluation at a point, integrals and error norms against an exact
 * solution (verification). */
#ifndef SLUICE_FE_FIELD_H
#define SLUICE_FE_FIELD_H

#include "core/fe/dofmap.h"
#include "core/util/diag.h"

/* Exact solution at x: value and gradient (grad may be NULL when only the
 * value is wanted). */
typedef void (*sl_exact_fn)(void *user, const double x[2], double *value, double grad[2]);

/* The L2 norm of u_h - u and the H1 seminorm of u_h - u (either output may
 * be NULL), with the cheapest rule exact to quad_degree; axisymmetric norms
 * weight by r (without 2 pi). u has dm->n_dofs entries. */
int sl_fe_error_norms(const sl_dofmap *dm, const double *u, sl_exact_fn exact, void *user, int axisymmetric,
                      int quad_degree, double *l2, double *h1_semi, sl_diag *d);

/* The integral of u_h and the measure of the domain (either may be NULL). */
int sl_fe_integrate(const sl_dofmap *dm, const double *u, int axisymmetric, double *integral, double *measure,
                    sl_diag *d);

/* The cell containing x and the reference coordinates of x in it; searches
 * all cells (starting at *cell when it is a valid index: pass the previous
 * answer for points along a line). Returns 0, or SL_EBADINPUT when x lies
 * in no cell (tolerance 1e-10 in reference coordinates). */
int sl_fe_locate(const sl_mesh *mesh, const double x[2], int *cell, double xi[2], sl_diag *d);

/* Value and physical gradient (grad may be NULL) of u_h at reference point
 * xi of cell c. */
void sl_fe_eval(const sl_dofmap *dm, const double *u, int c, const double xi[2], double *value, double grad[2]);

/* u[i] = g(node i) for every dof: the nodal interpolant. */
void sl_fe_interpolate(const sl_dofmap *dm, sl_exact_fn g, void *user, double *u);

#endif
