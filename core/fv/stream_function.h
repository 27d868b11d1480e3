/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The stream function at the vertices from the conservative face fluxes:
 * psi(b) - psi(a) = q_f across the face from a to b (its vertices in the
 * owner's counter-clockwise order), psi = 0 at vertex 0. This is psi with
 * u = d psi/dy, v = -d psi/dx in the plane, and the Stokes stream function
 * (r-weighted fluxes, per radian) when axisymmetric. Well defined because
 * the fluxes of every cell sum to zero (and the mesh is connected): a
 * breadth-first walk over the vertex-face graph visits each vertex once. */
#ifndef SLUICE_FV_STREAM_FUNCTION_H
#define SLUICE_FV_STREAM_FUNCTION_H

#include "core/fe/dofmap.h"
#include "core/mesh/mesh.h"

typedef struct sl_stream_graph {
  int *start, *face; /* vertex -> its faces (CSR) */
  int *queue;
  unsigned char *seen;
} sl_stream_graph;

/* The vertex-face graph of a 2-D mesh; 0 or -1 (out of memory: free it). */
int sl_stream_graph_build(sl_stream_graph *g, const sl_mesh *m);
void sl_stream_graph_free(sl_stream_graph *g);

/* psi[n_vertices] from the face fluxes q[n_faces]. */
void sl_stream_function(const sl_mesh *m, sl_stream_graph *g, const double *q, double *psi);

/* The same at the velocity nodes of th (node_psi[th->vel->n_nodes]), as the output writes node fields: the
 * vertices as computed, edge and centre nodes the mean of their cell's vertices (exact on edge midpoints for psi
 * linear along the edge). psi[n_vertices] is the scratch (and the vertex values). */
void sl_stream_function_nodes(const sl_th_space *th, sl_stream_graph *g, const double *q, double *psi,
                              double *node_psi);

/* The centre of the vortex: the extremum of largest |psi| over the vertices (psi[n_vertices]), placed below the
 * cell size by a least-squares quadratic fit, psi ~ a + b X + c Y + d X^2 + e X Y + f Y^2, to the vertices of the
 * cells that share the extremal vertex (a 3 x 3 stencil on a quadrilateral grid; Savitzky & Golay 1964 in 2-D:
 * exact for a quadratic psi), and the fit's stationary point, grad = 0: [2d e; e 2f] (X, Y) = -(b, c). On a
 * smooth psi the point converges at third order in h to the true extremum (measured 3.0 on quadrilaterals and
 * triangles, tests/scenes/test_rotating_scenes.c), against O(h) for the vertex. Falls back to the vertex where
 * the fit is not an extremum of the same sign (its Hessian not definite) or the point leaves the patch.
 * centre[2], *value: the fit's value there (the vertex's on the fallback). Returns 1 if refined by the fit, 0 on
 * the fallback, -1 on an empty mesh. */
int sl_stream_centre(const sl_mesh *m, const double *psi, double centre[2], double *value);

#endif
