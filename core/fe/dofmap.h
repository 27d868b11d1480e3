/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Degrees-of-freedom maps for continuous Lagrange spaces, and the combined
 * numbering of Taylor–Hood velocity/pressure pairs.
 *
 * Numbering of a scalar space (one dof per node, without periodic pairs):
 *  - order 1: the mesh vertices, dof v = vertex v;
 *  - order 2 in 2-D: vertices, then one per mesh face (dof n_vertices + f,
 *    at the face midpoint), then for Q2 one per cell (dof n_vertices +
 *    n_faces + c, at the image of the reference centre: the vertex average);
 *  - order 2 in 1-D: vertices, then one per cell (n_vertices + c, midpoint).
 * cell_dofs lists each cell's dofs in the element's basis order
 * (core/fe/element.h), ready for assembly.
 *
 * Taylor–Hood (velocity order 2, pressure order 1; Q2/Q1, P2/P1, and P2/P1
 * on the line). Velocity components are BLOCKED: component c of velocity
 * node i is unknown c * n_vel + i, pressure node j is p_offset + j with
 * p_offset = n_comp * n_vel. Blocked, so that each component is a plain
 * contiguous array (boundary conditions, output, norms take a pointer); the
 * direct solvers reorder for fill themselves, so interleaving buys nothing.
 * Each cell's combined dof list is [u_0 basis..., u_1 basis..., p basis...].
 *
 * Periodic pairs. A pair names two mesh boundaries that are translates of
 * each other (sl_mesh_periodic_match): the nodes of the second, `partner`,
 * are identified with those of the first, `boundary`. The map then has two
 * numberings:
 *  - NODES, geometric and un-identified: exactly the numbering above
 *    (n_nodes, cell_nodes, node_xy). Write meshes and node fields with it.
 *  - DOFS, what assembly, sparsity, constraints and solves see (n_dofs,
 *    cell_dofs, xy): one dof per class of identified nodes. node_dof maps
 *    node -> dof. Dofs are numbered in the order of their first node, so
 *    vertex dofs still come first; a dof's coordinates are those of its
 *    representative node, the one of its class on no partner boundary
 *    (lowest index) -- a "master" position, so interpolating a periodic
 *    function is consistent.
 * Several pairs identify transitively: the four corners of a doubly
 * periodic box are one dof. Without pairs the two numberings coincide
 * (cell_nodes == cell_dofs and node_xy == xy are the same arrays; node_dof
 * is the identity). Geometry (Jacobians, quadrature points, point location)
 * always comes from the mesh, so assembly on the identified dofs is the
 * periodic problem. Code that takes a cell's geometry from the map (edge
 * normals, lengths, r at the nodes) must read node_xy[cell_nodes[..]], not
 * xy[cell_dofs[..]]: across the seam a dof's xy is on the other side. */
#ifndef SLUICE_FE_DOFMAP_H
#define SLUICE_FE_DOFMAP_H

#include <stdint.h>

#include "core/fe/element.h"
#include "core/mesh/mesh.h"
#include "core/util/diag.h"

typedef struct sl_dofmap {
  const sl_mesh *mesh; /* not owned: must outlive the map */
  const sl_element *element;
  int32_t n_dofs;
  int dofs_per_cell;
  int32_t *cell_dofs; /* [n_cells * dofs_per_cell], element basis order */
  double *xy;         /* [2 * n_dofs] dof coordinates (periodic: the representative node's) */
  /* The geometric numbering (see above); the same as the dofs without
   * periodic pairs. */
  int32_t n_nodes;
  int32_t *cell_nodes; /* [n_cells * dofs_per_cell] */
  double *node_xy;     /* [2 * n_nodes] */
  int32_t *node_dof;   /* [n_nodes]: the dof of each node */
  int n_periodic;      /* periodic pairs applied */
} sl_dofmap;

/* Two boundaries made one: `partner`'s nodes take the dofs of `boundary`'s
 * (scene syntax: [boundary.<boundary>] type = periodic, partner = <partner>). */
typedef struct sl_periodic_pair {
  const char *boundary;
  const char *partner;
} sl_periodic_pair;

/* Continuous Lagrange space of order 1 or 2 on the mesh. Returns 0,
 * SL_EBADINPUT (order) or SL_EFAILED (out of memory). */
int sl_dofmap_create(const sl_mesh *mesh, int order, sl_dofmap **out, sl_diag *d);
/* The same with periodic pairs (n_pairs == 0: sl_dofmap_create). Besides the
 * errors of sl_mesh_periodic_match: SL_EBADINPUT when a boundary is the
 * partner of two pairs, or the pairs form a cycle (a -> b, b -> a). */
int sl_dofmap_create_periodic(const sl_mesh *mesh, int order, const sl_periodic_pair *pairs, int n_pairs,
                              sl_dofmap **out, sl_diag *d);
void sl_dofmap_destroy(sl_dofmap *dm);

/* The dofs on the named boundary (its faces' vertices, plus the face
 * midpoints for order 2), ascending and unique. *dofs is malloc'ed (NULL
 * when *n == 0): the caller frees it. An unknown name is SL_EBADINPUT with a
 * did-you-mean. With periodic pairs these are the dofs of the boundary's
 * nodes: a wall finds its corner with a periodic boundary even where that
 * node's dof is represented by a node of another wall (the corner (L, 0) of
 * "bottom" with "left"/"right" periodic is the dof at (0, 0)), and a
 * partner boundary's list is that of its pair's first boundary. */
int sl_dofmap_boundary_dofs(const sl_dofmap *dm, const char *boundary, int32_t **dofs, int32_t *n, sl_diag *d);

/* u_nodes[i * stride] = u[node_dof[i]] for every node: a dof vector spread
 * over the geometric nodes, for output on node_xy / cell_nodes. */
void sl_dofmap_dofs_to_nodes(const sl_dofmap *dm, const double *u, double *u_nodes, int stride);

typedef struct sl_th_space {
  const sl_mesh *mesh; /* not owned */
  sl_dofmap *vel;      /* owned: order 2, one component */
  sl_dofmap *pres;     /* owned: order 1 */
  int n_comp;          /* velocity components (the mesh dimension; 3 with swirl) */
  int32_t n_vel;       /* velocity dofs per component = vel->n_dofs (periodic: < vel->n_nodes) */
  int32_t p_offset;    /* n_comp * n_vel */
  int32_t n_dofs;      /* n_comp * n_vel + pres->n_dofs */
  int dofs_per_cell;   /* n_comp * vel->dofs_per_cell + pres->dofs_per_cell */
  int32_t *cell_dofs;  /* [n_cells * dofs_per_cell], combined numbering */
} sl_th_space;

/* n_comp in [dim, 3]. */
int sl_th_create(const sl_mesh *mesh, int n_comp, sl_th_space **out, sl_diag *d);
/* The same with periodic pairs, applied to the velocity (order 2) and the
 * pressure (order 1) maps alike: vel and pres carry both numberings, and
 * cell_dofs is built from their dofs, so assembly, sparsity, constraints
 * and solves need nothing else. Errors as sl_dofmap_create_periodic. */
int sl_th_create_periodic(const sl_mesh *mesh, int n_comp, const sl_periodic_pair *pairs, int n_pairs,
                          sl_th_space **out, sl_diag *d);
void sl_th_destroy(sl_th_space *th);

static inline int32_t sl_th_vel_dof(const sl_th_space *th, int comp, int32_t node) { return comp * th->n_vel + node; }
static inline int32_t sl_th_pres_dof(const sl_th_space *th, int32_t node) { return th->p_offset + node; }

#endif
