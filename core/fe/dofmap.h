/* Degrees-of-freedom maps for continuous Lagrange spaces, and the combined
 * numbering of Taylor–Hood velocity/pressure pairs.
 *
 * Numbering of a scalar space (one dof per node):
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
 * Each cell's combined dof list is [u_0 basis..., u_1 basis..., p basis...]. */
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
  double *xy;         /* [2 * n_dofs] node coordinates */
} sl_dofmap;

/* Continuous Lagrange space of order 1 or 2 on the mesh. Returns 0,
 * SL_EBADINPUT (order) or SL_EFAILED (out of memory). */
int sl_dofmap_create(const sl_mesh *mesh, int order, sl_dofmap **out, sl_diag *d);
void sl_dofmap_destroy(sl_dofmap *dm);

/* The dofs on the named boundary (its faces' vertices, plus the face
 * midpoints for order 2), ascending and unique. *dofs is malloc'ed (NULL
 * when *n == 0): the caller frees it. An unknown name is SL_EBADINPUT with a
 * did-you-mean. */
int sl_dofmap_boundary_dofs(const sl_dofmap *dm, const char *boundary, int32_t **dofs, int32_t *n, sl_diag *d);

typedef struct sl_th_space {
  const sl_mesh *mesh; /* not owned */
  sl_dofmap *vel;      /* owned: order 2, one component */
  sl_dofmap *pres;     /* owned: order 1 */
  int n_comp;          /* velocity components (the mesh dimension; 3 with swirl) */
  int32_t n_vel;       /* velocity nodes = vel->n_dofs */
  int32_t p_offset;    /* n_comp * n_vel */
  int32_t n_dofs;      /* n_comp * n_vel + pres->n_dofs */
  int dofs_per_cell;   /* n_comp * vel->dofs_per_cell + pres->dofs_per_cell */
  int32_t *cell_dofs;  /* [n_cells * dofs_per_cell], combined numbering */
} sl_th_space;

/* n_comp in [dim, 3]. */
int sl_th_create(const sl_mesh *mesh, int n_comp, sl_th_space **out, sl_diag *d);
void sl_th_destroy(sl_th_space *th);

static inline int32_t sl_th_vel_dof(const sl_th_space *th, int comp, int32_t node) {
  return comp * th->n_vel + node;
}
static inline int32_t sl_th_pres_dof(const sl_th_space *th, int32_t node) { return th->p_offset + node; }

#endif
