/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The mesh of a scene, from its [mesh] section (the keys, their defaults and
 * ranges: core/scene/keys.c):
 *   generator = interval | rectangle | annulus | inclined_box | gmsh
 *   x = x0, x1   y = y0, y1        (interval: x only; rectangle)
 *   r = r0, r1   z = z0, z1        (annulus: the axisymmetric (r, z) box)
 *   origin = x0, y0  width = W  height = H  angle = radians   (inclined_box)
 *   cells = nx, ny                  (one number: the same in both directions)
 *   cell_type = quad | tri   diagonal = right | left | union_jack
 *   grading_x = geometric:RATIO | symmetric:RATIO   grading_y = ...
 *   file = mesh.msh                 (gmsh, relative to the scene file)
 *   split_quads = true              (gmsh: quadrangles become two triangles)
 *   memory_limit = BYTES            (0: the machine's memory)
 * Errors name the file and line of the offending key. */
#ifndef SLUICE_SCENE_MESH_H
#define SLUICE_SCENE_MESH_H

#include "core/mesh/mesh.h"

struct sl_scene;

int sl_scene_mesh_build(const struct sl_scene *sc, sl_mesh **out, sl_diag *d);

/* A 1-D mesh as one chain of cells in order of increasing x: vertex[k]
 * (k = 0..n) is the k-th vertex along the chain and cell[i] (i = 0..n-1)
 * the mesh cell between vertex[i] and vertex[i+1]. SL_EBADINPUT when the
 * mesh is not 1-D or not a single chain. */
int sl_scene_line_chain(const sl_mesh *m, int *vertex, int *cell, sl_diag *d);

/* The boundary names of a 1-D chain's two ends (vertices first and last);
 * SL_EBADINPUT naming `model` when an end carries no tag. */
int sl_scene_line_ends(const sl_mesh *m, int first, int last, const char *model, const char *names[2], sl_diag *d);

#endif
