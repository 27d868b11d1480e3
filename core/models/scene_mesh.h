/* The mesh of a scene, from its [mesh] section:
 *   generator = interval | rectangle | annulus | inclined_box | gmsh
 *   x = x0, x1   y = y0, y1        (interval: x only; rectangle)
 *   r = r0, r1   z = z0, z1        (annulus: the axisymmetric (r, z) box)
 *   origin = x0, y0  width = W  height = H  angle = radians   (inclined_box)
 *   cells = nx, ny                  (one number: the same in both directions)
 *   cell_type = quad | tri   diagonal = right | left | union_jack
 *   grading_x = geometric:RATIO | symmetric:RATIO   grading_y = ...
 *   file = mesh.msh                 (gmsh, relative to the scene file)
 * Errors name the file and line of the offending key. */
#ifndef SLUICE_MODELS_SCENE_MESH_H
#define SLUICE_MODELS_SCENE_MESH_H

#include "core/config/ini.h"
#include "core/mesh/mesh.h"

int sl_scene_mesh(const sl_ini *ini, sl_mesh **out, sl_diag *d);

#endif
