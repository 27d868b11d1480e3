/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Finite-volume transport of the solids fraction phi on the cells of a mesh:
 *
 *   d/dt int_V phi + sum_faces [ q_f phi + w_f F(phi) ] = 0,   F(phi) = phi u_settle(phi),
 *
 * the drift-flux (mixture) form of Nigam (1999) eqs 2.33-2.34 with the
 * relative flux j_R from a hindered-settling closure (Kynch 1952).
 *
 * What the caller provides, per face f (normal out of face_cells[2f]):
 *  - q[f], the mixture volume flux through the face along its normal,
 *    int j.n dA (m^3/s; per unit depth in 2-D planar; r-weighted, without
 *    the 2 pi, when axisymmetric; m/s in 1-D, where faces have area 1). It
 *    comes from the finite-element velocity; the module does not look at it
 *    otherwise. It must be discretely divergence-free (the fluxes of each
 *    cell sum to zero, wall faces excluded) for the bounds to hold; the step
 *    reports the largest divergence it saw, relative to the flow's scale.
 *  - w[f], the settling coefficient int (b.n) dA, b the body-force direction
 *    times its magnitude relative to the one the closure table was built for
 *    (b = -e_y, |b| = 1, for plain gravity; b = omega^2 r / g e_r in a
 *    centrifuge). sl_transport_settling_uniform / _field compute it. The
 *    settling velocity is taken to scale linearly with |b| (Stokes regime);
 *    for laws nonlinear in g build the table at the representative g.
 * Either array may be NULL (no mixture flux / no settling).
 *
 * Scheme. Cell averages; the exact Godunov flux of h_f(phi) = q_f phi +
 * w_f F(phi) at every face (flux.h: correct for non-convex settling fluxes,
 * no expansion shocks). Order 2: MUSCL (van Leer 1979) with a least-squares
 * gradient and a Barth–Jespersen (1989) limit of the face values to the
 * range of the cells that share a vertex with the cell, across periodic
 * pairs too (the face neighbours alone clip smooth data on triangles: L1
 * orders 0.5 to 1.8 on union-jack meshes, test_transport_muscl.c;
 * Venkatakrishnan 1995), in 1-D the MC limiter, or minmod; SSP-RK2 (Shu &
 * Osher 1988) in time.
 * Explicit, sub-cycled: a call advances one outer step dt (the engine's) in
 * n equal sub-steps, each within the stable step.
 *
 * Stability and bounds. First order is monotone (Crandall & Majda 1980)
 * when, for every cell i,
 *   dt_sub sum_f a_f <= V_i,
 *   a_f = max_phi (q_f + w_f F')^+ at faces i owns, max_phi (q_f + w_f F')^- at faces it neighbours,
 * with max/min F' from the table. Walls carry zero flux, which equals the
 * Godunov flux against a ghost state 0 or phi_max because F has one sign and
 * vanishes at 0 and phi_max; with divergence-free q the scheme then maps
 * [0, phi_max] into itself: the sediment packs to phi_max and no further.
 * MUSCL stages are bounded in 1-D at half that step (the cell average is
 * the mean of its two face values, so a stage is a convex combination of
 * two first-order updates with twice the step; Zhang & Shu 2010, J. Comput.
 * Phys. 229:3091, section 2), so order 2 uses cfl / 2. On 2-D meshes, where that argument
 * does not carry over exactly, a sub-step whose MUSCL result leaves [0,
 * phi_max] (beyond 1e-12) is redone at first order and counted. The
 * limiter also keeps 2-D face values within [2 phi_i - phi_max, 2 phi_i]
 * of their cell's phi_i, which gives the bound face by face (muscl.c), so
 * with divergence-free q that fallback is a guard against round-off.
 *
 * Optional: an extra face flux evaluated from phi at every stage (the
 * shear-induced migration flux, migration.h; sl_transport_set_extra_flux),
 * and periodic boundary pairs (sl_transport_set_periodic).
 *
 * Conservation: each face flux (a periodic pair's and the extra flux
 * included) is computed once and given to both cells, so
 * sum_i V_i phi_i changes only by the flux through open boundaries, exactly
 * up to round-off. Round-off excursions past the bounds (a MUSCL stage on
 * triangles gave -4e-32) are set back to the bound, so that a closure asked
 * at phi never sees phi < 0; the stats report the volume so moved.
 *
 * Geometry: one code path for 1-D, 2-D planar and axisymmetric (x = r):
 * axisymmetric volumes are int r dA and face areas int r ds (exact for
 * straight-sided cells; no 2 pi), a 1-D axisymmetric mesh is a radial line.
 * Faces on the axis have zero area and carry no flux.
 *
 * Ownership: sl_transport keeps a pointer to the mesh (which must outlive
 * it) and owns everything else, work arrays included: step one object from
 * one thread at a time. */
#ifndef SLUICE_TRANSPORT_TRANSPORT_H
#define SLUICE_TRANSPORT_TRANSPORT_H

#include "core/mesh/mesh.h"
#include "core/transport/flux.h"
#include "core/util/diag.h"

typedef enum sl_transport_geometry {
  SL_TRANSPORT_PLANAR = 0,
  SL_TRANSPORT_AXISYMMETRIC /* x is r; the mesh must have x >= 0 */
} sl_transport_geometry;

typedef enum sl_transport_limiter {
  SL_LIMITER_MC = 0, /* Barth–Jespersen: face values within the vertex neighbours' range (1-D: monotonized central) */
  SL_LIMITER_MINMOD  /* half that range (1-D: minmod), more diffusive */
} sl_transport_limiter;

typedef enum sl_transport_bc {
  SL_TRANSPORT_WALL = 0, /* zero total flux (the default on every boundary) */
  SL_TRANSPORT_OPEN      /* Godunov flux against the exterior state phi_outside */
} sl_transport_bc;       /* periodic pairs: sl_transport_set_periodic */

/* An extra solids flux through the faces (the shear-induced migration flux
 * of migration.h, or any other), evaluated from the current cell values at
 * every stage and added to the Godunov flux. The callback fills flux[f]
 * for every face f: the solids volume per unit time through f along its
 * normal, out of face_cells[2f], in the units of q phi (int N.n dA,
 * r-weighted without 2 pi when axisymmetric). Only faces between two cells
 * use it (interior faces, and the first face of each periodic pair: its
 * flux goes into the owner of the paired face); walls and open boundaries
 * carry none. *dt_stable is the largest forward-Euler step for which the
 * flux keeps phi >= 0 and does not oscillate (+infinity when it is zero
 * everywhere); the transport multiplies it by cfl. Returns 0 or an SL_E*
 * code with d set. */
typedef int (*sl_transport_extra_fn)(void *user, const double *phi, double *flux, double *dt_stable, sl_diag *d);

typedef struct sl_transport_opts {
  double phi_max;               /* maximum packing, (0, 1] */
  int order;                    /* 1 (Godunov) or 2 (MUSCL); 0 means 2 */
  sl_transport_limiter limiter; /* order 2 only */
  sl_transport_geometry geometry;
  double cfl;              /* fraction of the stable step, (0, 1]; 0 means 0.9 */
  int table_points;        /* nodes of the flux table; 0 means 2049 */
  int max_substeps;        /* 0 means 1000000; needing more is an error */
  sl_settling_fn settling; /* the hindered-settling closure (required) */
  void *settling_user;
} sl_transport_opts;

typedef struct sl_transport_stats {
  int n_substeps;         /* sub-steps of the last call */
  int n_fallbacks;        /* MUSCL sub-steps redone at first order to stay in bounds */
  double dt_stable;       /* the stable sub-step (cfl included) for this call's q and w */
  int limiting_cell;      /* the cell that sets dt_stable (-1: no flux anywhere) */
  double boundary_inflow; /* solids volume that entered through open boundaries (int r dA units) */
  double max_divergence;  /* max over cells |sum_f q_f| / max over cells sum_f |q_f| (walls
                             excluded): the discrete divergence relative to the flow's scale */
  double clamped;         /* sum |change| V of round-off excursions (< 1e-12) set back to 0 or
                             phi_max, and of values below 1e-250 set to 0: bounds the mass they move */
  /* With an extra flux (sl_transport_set_extra_flux): */
  double dt_extra;      /* the smallest stable step it reported at a sub-step's start, cfl included
                             (+infinity without an extra flux) */
  int n_extra_limited;  /* extra face fluxes scaled down to keep 0 <= phi <= phi_max (bounds limiter) */
  double extra_limited; /* the solids volume those scalings held back (int r dA units) */
} sl_transport_stats;

typedef struct sl_transport sl_transport;

/* Builds the geometry and tabulates the settling flux (one batch call of the
 * closure). Returns 0, SL_EBADINPUT (bad options, axisymmetric mesh with x <
 * 0, a flux that does not vanish at phi_max: see flux.h) or SL_EFAILED. */
int sl_transport_create(const sl_mesh *m, const sl_transport_opts *o, sl_transport **out, sl_diag *d);
void sl_transport_destroy(sl_transport *t);

/* Boundary `b` (a mesh boundary index) becomes a wall or an open boundary
 * with exterior state phi_outside in [0, phi_max]. A boundary of a periodic
 * pair is refused. */
int sl_transport_set_boundary(sl_transport *t, int b, sl_transport_bc type, double phi_outside, sl_diag *d);

/* Exterior states that vary along the open boundary b: phi_faces[i] is the
 * state outside the face m->bface[m->bface_start[b] + i] (one per face of
 * b, each in [0, phi_max]), used by the Godunov flux in place of the
 * boundary's phi_outside until set again (an inflow profile of the channel
 * coordinate, Nigam 1999 eq 4.148, or one that changes in time). Returns 0,
 * or SL_EBADINPUT (no such boundary, not open, a value out of range: the
 * face point is named) with nothing changed. */
int sl_transport_set_boundary_values(sl_transport *t, int b, const double *phi_faces, sl_diag *d);
/* The solids volume that entered through boundary b (negative: left) in the
 * last successful sl_transport_step, in the units of boundary_inflow; the
 * boundaries' values sum to its boundary_inflow. */
double sl_transport_boundary_flow(const sl_transport *t, int b);

/* Periodic pair: the faces of mesh boundaries a and b, which must match by
 * one translation s (x_b = x_a + s), become interior faces between their two
 * cells: Godunov flux, MUSCL reconstruction (the neighbour's cell point
 * taken at x - s or x + s), extra (migration) flux with the translated cell
 * point. The match is the mesh's (sl_mesh_periodic_match, the one the
 * finite-element spaces use): every node of b at a node of a plus s, within
 * 1e-9 of the mesh's bounding-box diagonal, else SL_EBADINPUT naming both
 * boundaries, the unmatched node and where its partner was sought. In an axisymmetric
 * geometry the translation must be along z (s_r = 0). a and b must differ
 * and not already be periodic; an open or wall boundary may be made
 * periodic. Several pairs may be set (a doubly periodic box).
 *
 * The face flux q and settling coefficient w of a pair are the mean of
 * what the caller gives on its two faces, q[fa] and -q[fb] (their normals
 * are opposite): fill both, as a periodic finite-element velocity does. */
int sl_transport_set_periodic(sl_transport *t, int boundary_a, int boundary_b, sl_diag *d);
/* The same with the boundaries' names (sl_mesh_boundary_id's errors). */
int sl_transport_set_periodic_named(sl_transport *t, const char *a, const char *b, sl_diag *d);
/* The translation s of the pair that boundary b belongs to, from its first
 * boundary to its second; returns 0, or SL_EBADINPUT when b is not periodic. */
int sl_transport_periodic_shift(const sl_transport *t, int b, double s[2], sl_diag *d);

/* Installs (fn != NULL) or removes (fn == NULL) the extra face flux; see
 * sl_transport_extra_fn. With one, sl_transport_step chooses each
 * sub-step's length from the state at its start: the largest h <= min(the
 * advective stable step, cfl * the extra flux's dt_stable) that splits the
 * rest of the outer step into equal parts. The second SSP-RK2 stage uses
 * the flux of the stage state at that h.
 *
 * Bounds. The extra flux is limited face by face, conservatively (one
 * factor per face, for both cells), as in flux-corrected transport
 * (Zalesak 1979, J. Comput. Phys. 31:335): in each stage, with phi_a the
 * cell value after the Godunov fluxes alone, the extra inflows of a cell
 * may raise it by at most half of phi_max - phi_a and its extra outflows
 * lower it by at most phi_a. So every stage stays in [0, phi_max] and a
 * cell below phi_max never reaches it through the extra flux (where the
 * migration flux's ln mu would be infinite). A face flux is scaled by the
 * smaller of its sender's and its receiver's factor. Within the stable
 * step a flux like the migration one (positive coefficients: migration.h)
 * needs no limiting at the lower bound; at the upper one it acts only in
 * a transient that drives a cell towards phi_max faster than half the gap
 * per stage. The stats count the scaled faces and the volume held back. */
int sl_transport_set_extra_flux(sl_transport *t, sl_transport_extra_fn fn, void *user, sl_diag *d);

/* Geometry as the scheme sees it: cell volumes, face areas, the cell and
 * face points where the reconstruction is taken (r-weighted centroids when
 * axisymmetric). Arrays of n_cells / n_faces / 2 n_faces / 2 n_cells. */
const double *sl_transport_volumes(const sl_transport *t);
const double *sl_transport_face_areas(const sl_transport *t);
const double *sl_transport_face_points(const sl_transport *t);
const double *sl_transport_cell_points(const sl_transport *t);
const sl_settling_table *sl_transport_table(const sl_transport *t);
const sl_mesh *sl_transport_mesh(const sl_transport *t);

/* w[f] = A_f (b . n_f) for a uniform b (gravity: b = (0, -1) in 2-D, (-1, 0)
 * for a 1-D column whose x is the height). */
void sl_transport_settling_uniform(const sl_transport *t, const double b[2], double *w);
/* w[f] = A_f (b(x_f) . n_f) with b evaluated at the face point. */
void sl_transport_settling_field(const sl_transport *t, void (*b)(void *user, const double x[2], double b[2]),
                                 void *user, double *w);

/* w[f] = A_f (b_f . n_f) for a body-force direction given per face
 * (b[2 f], b[2 f + 1]): an acceleration field that varies in time. */
void sl_transport_settling_faces(const sl_transport *t, const double *b, double *w);

/* The stable explicit sub-step for these fluxes (cfl and the order's factor
 * included): +infinity when nothing moves. *cell (may be NULL) is the cell
 * that sets it, -1 then. */
double sl_transport_stable_dt(const sl_transport *t, const double *q, const double *w, int *cell);

/* Advances phi (n_cells cell averages, in [0, phi_max]) by dt. On failure
 * phi is left as it was: SL_EBADINPUT for a bad dt, non-finite q or w, or
 * phi outside [0, phi_max] on entry (the cell is named); SL_EFAILED when
 * more than max_substeps sub-steps are needed or a first-order sub-step
 * leaves the bounds (face fluxes not divergence-free); the extra flux
 * callback's code (its message prefixed) when it fails or gives a
 * non-finite flux or a dt_stable that is not > 0. st may be NULL. */
int sl_transport_step(sl_transport *t, double dt, const double *q, const double *w, double *phi, sl_transport_stats *st,
                      sl_diag *d);

/* The least-squares gradient of the cell values phi (n_cells) from each
 * cell's face neighbours, across periodic pairs too, unlimited (exact for
 * linear data), into grad[2 n_cells] (1-D: the x component, 0). */
void sl_transport_gradient(const sl_transport *t, const double *phi, double *grad);

/* sum_i V_i phi_i, compensated (Neumaier) so that it measures conservation
 * to round-off. */
double sl_transport_mass(const sl_transport *t, const double *phi);

#endif
