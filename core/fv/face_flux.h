/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Conservative face fluxes of a Taylor–Hood velocity for the finite-volume
 * transport of the solids fraction.
 *
 * The transport needs, per mesh face, the volume flux q_f = int_f u.n ds
 * (r ds axisymmetric, no 2 pi) of the mixture velocity, and it stays within
 * [0, phi_max] only when the fluxes of every cell sum to zero. A Taylor–Hood
 * velocity is divergence-free only weakly (against the continuous P1/Q1
 * pressures), not cell by cell, so the raw fluxes carry a small cell
 * divergence (a few per cent of the cell's through-flow on coarse meshes,
 * falling as h^2). This module removes it with the least-squares correction
 *
 *   min sum_f dq_f^2   subject to   sum_{f in i} s_if (q_f + dq_f) = 0 for every cell i,
 *
 * (s_if = +1 where the face normal leaves cell i), whose solution is
 * dq_f = -(lambda_owner - lambda_neighbour), lambda solving the cell graph
 * Laplacian L lambda = div q: a global least-squares flux correction (cf.
 * Cockburn, Gopalakrishnan & Wang 2007, SIAM J. Numer. Anal. 45:1742, who
 * obtain locally conservative fluxes from continuous Galerkin solutions with
 * local patch problems instead). L depends on the mesh only: it is
 * factorised once, each call is one back-substitution.
 *
 * Which faces may change: interior faces and the faces of boundaries where
 * the velocity is not prescribed (open, pressure, traction). Faces on
 * boundaries with a prescribed normal velocity (walls, slip, axis, inflow)
 * keep the flux of the prescribed data. A closed vessel has no adjustable
 * boundary face; L is then singular with the constants as null space and
 * the cell divergences sum to zero exactly (every interior flux enters two
 * cells with opposite signs), so one cell's lambda is pinned.
 *
 * Raw fluxes: the trace of a Q2/P2 velocity on a straight edge is the
 * quadratic through its end and midpoint nodes, so Simpson's rule
 * integrates u.n exactly, and u.n r (cubic) as well: q_f is exact for the
 * discrete velocity. In 1-D a face is a point and q_f = u.n there. */
#ifndef SLUICE_MODELS_FACE_FLUX_H
#define SLUICE_MODELS_FACE_FLUX_H

#include "core/fe/dofmap.h"
#include "core/solve/linsolve.h"
#include "core/util/diag.h"

typedef struct sl_face_flux sl_face_flux;

/* adjustable[b] != 0 for the mesh boundaries b (indices into the mesh's
 * boundary names) whose faces the correction may change; NULL: none.
 * pairs[2k], pairs[2k + 1] are the two faces of a periodic seam (n_pairs of
 * them): one face between their cells, whose flux is the mean of both
 * sides' (q[fb] = -q[fa] on return). */
int sl_face_flux_create(const sl_th_space *th, int axisymmetric, const unsigned char *adjustable, const int *pairs,
                        int n_pairs, sl_face_flux **out, sl_diag *d);
void sl_face_flux_destroy(sl_face_flux *ff);

/* Marks the faces of the boundaries b with closed[b] != 0 (mesh boundary indices; NULL: none) as carrying
 * no flux: their raw flux is 0. For walls whose normal velocity is zero in a sense the trace does not show
 * face by face: a free-slip wall on a curved boundary (core/assembly/slip.h) holds u.n_i = 0 at its nodes with
 * the nodes' normals, so each chord's own flux is small but not zero, and the chords' fluxes sum to zero. */
int sl_face_flux_close(sl_face_flux *ff, const unsigned char *closed, sl_diag *d);

/* The raw fluxes of the velocity u (combined numbering) into q[n_faces]. */
void sl_face_flux_raw(const sl_face_flux *ff, const double *u, double *q);

/* Conservative fluxes of u into q[n_faces]. *raw_divergence (may be NULL)
 * gets max_i |sum_f s_if q_f| / max(max_i sum_f |q_f|, floor) of the raw
 * fluxes: the size of the correction relative to the flow's scale, or to
 * `floor` (e.g. the settling flux) where the flow is at round-off. */
int sl_face_flux_conservative(sl_face_flux *ff, const double *u, double floor, double *q, double *raw_divergence,
                              sl_diag *d);

#endif
