/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The tensor-product structure of an axis-aligned quadrilateral mesh (a
 * rectangle or annulus generator's mesh, graded or not, or a Gmsh file with
 * the same layout), for staggered (MAC) finite-volume schemes.
 *
 * Cells are numbered c = i + nx j (i along x, j along y). The boundary faces
 * of the four sides keep the mesh's tags, so a side may carry several named
 * boundaries (an inlet on part of the bottom). */
#ifndef SLUICE_MESH_TENSOR_GRID_H
#define SLUICE_MESH_TENSOR_GRID_H

#include "core/mesh/mesh.h"

enum { SL_SIDE_LEFT = 0, SL_SIDE_RIGHT = 1, SL_SIDE_BOTTOM = 2, SL_SIDE_TOP = 3 };

typedef struct sl_tensor_grid {
  int nx, ny;
  double *xf, *yf;  /* [nx + 1], [ny + 1]: the grid lines, increasing */
  int *mesh_cell;   /* [nx ny]: the mesh cell of grid cell i + nx j */
  int *side_tag[4]; /* [ny] for left/right, [nx] for bottom/top: the boundary index of each side face */
} sl_tensor_grid;

/* The grid of m. SL_EBADINPUT naming the first cell that breaks the
 * structure (not a quadrilateral mesh, a cell not aligned with x and y, a
 * hole, a missing or repeated cell), SL_EFAILED out of memory. */
int sl_tensor_grid_from_mesh(const sl_mesh *m, sl_tensor_grid *g, sl_diag *d);
void sl_tensor_grid_free(sl_tensor_grid *g);

#endif
