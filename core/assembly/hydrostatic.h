/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The hydrostatic part of a buoyancy rho'(x) g with rho' given per cell,
 * taken out of the flow's load so that a stratification at rest loads it
 * with nothing.
 *
 * A Taylor–Hood pressure balances rho' g exactly only when rho' g is the
 * gradient of a function of its own space, i.e. when rho' is constant in
 * each layer of cells between two levels of the height along -g (a Q1 or P1
 * pressure is then linear in the height in each layer). Cell values of a
 * smooth phi(y) on triangles are not (a cell's value is its point's, and the
 * two triangles of a quadrilateral have their points at different heights),
 * and even where the balance is exact the load rho' g has to be cancelled by
 * the pressure to round-off of the solve: a box at rest then moves at 1e-11
 * of its settling speed.
 *
 * The split (a reference state subtracted before the pressure gradient, as
 * in atmospheric and ocean models: Gary 1973, J. Atmos. Sci. 30:223;
 * Mellor, Ezer & Oey 1994, J. Atmos. Oceanic Technol. 11:1126): per layer L
 * the least-squares line
 *
 *   rho_L(h) = a_L + b_L (h - hbar_L)
 *
 * through the cells' values against the height h of their points (weights:
 * the cell volumes; b_L = 0 when the points share one height), and
 *
 *   rho' g = rho_ref(h) g + (rho' - rho_ref(h)) g,   rho_ref = rho_L in layer L.
 *
 * rho_ref(h) g is the gradient of the hydrostatic pressure P(h), dP/dh =
 * -|g| rho_ref(h): in a vessel whose walls carry no flux it moves nothing
 * and only adds P to the pressure, so the flow is loaded with the
 * remainder rho'_c - rho_L(h_c) per cell alone, and P is added to the
 * pressure it gives. The remainder is the departure from the layer's line:
 * zero for any rho' that is constant in each layer (a step, any phi(y) on
 * quadrilaterals) and for any rho' linear in the height (on triangles too),
 * so such states load the flow with exact zeros; what drives motion is the
 * horizontal variation within layers, the baroclinic part of the buoyancy.
 *
 * Needs a layered mesh: the heights of the vertices take a set of levels
 * (within 1e-9 of the mesh's height range) such that every cell has its
 * vertices on two consecutive levels (rectangles, sheared, graded, split
 * into triangles; a 1-D column, where every cell is a layer and the
 * remainder is zero). sl_hydrostatic_create reports other meshes (and a
 * zero g) by leaving *out NULL. The caller also decides whether dropping
 * rho_ref g is right: it is where the boundaries are walls or periodic
 * across g (an open boundary would need P in its traction). */
#ifndef SLUICE_ASSEMBLY_HYDROSTATIC_H
#define SLUICE_ASSEMBLY_HYDROSTATIC_H

#include "core/mesh/mesh.h"
#include "core/util/diag.h"

typedef struct sl_hydrostatic sl_hydrostatic;

/* The layers of mesh m under gravity g (2 components; 1-D: g[0] along x).
 * weight[c] and point[2c], [2c + 1] are the cells' volumes and points (the
 * points where the cell values are taken; r-weighted when axisymmetric).
 * *out = NULL (and 0 returned) when m is not layered along g or g = 0. The
 * arrays are copied. */
int sl_hydrostatic_create(const sl_mesh *m, const double g[2], const double *weight, const double *point,
                          sl_hydrostatic **out, sl_diag *d);
void sl_hydrostatic_destroy(sl_hydrostatic *h);

/* The number of layers. */
int sl_hydrostatic_layers(const sl_hydrostatic *h);

/* Fits the layers' lines to rho (n_cells values) and writes the remainder
 * rho[c] - rho_ref(h_c) into remainder (may be rho). */
void sl_hydrostatic_split(sl_hydrostatic *h, const double *rho, double *remainder);

/* The hydrostatic pressure of the last split's rho_ref under g, zero at the
 * lowest level, at n points xy (2 n values) into p. */
void sl_hydrostatic_pressure(const sl_hydrostatic *h, int n, const double *xy, double *p);

#endif
