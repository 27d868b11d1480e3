/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The key tables shared by every model (keys.h). */
#include "core/scene/keys.h"

#include "core/scene/scene.h"

#define TABLE(name, keys) const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}

static const sl_key scene_keys[] = {
    {.section = "scene", .name = "model", .type = SL_KEY_STRING, SL_AT_SCENE(model), .flags = SL_KEY_REQUIRED,
     .help = "the physical model (`sluice model list`)"},
    {.section = "scene", .name = "title", .type = SL_KEY_STRING, SL_AT_SCENE(title), .help = "a one-line title"},
};
TABLE(sl_keys_scene, scene_keys);

static const sl_key mesh_keys[] = {
    {.section = "mesh", .name = "generator", .type = SL_KEY_CHOICE, SL_AT_SCENE(mesh_config.generator),
     .flags = SL_KEY_REQUIRED, .choices = "interval|rectangle|annulus|inclined_box|gmsh", .help = "how the mesh is made"},
    {.section = "mesh", .name = "x", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.x), .max_n = 2, .units = "m",
     .help = "x0, x1 (interval, rectangle)"},
    {.section = "mesh", .name = "y", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.y), .max_n = 2, .units = "m",
     .help = "y0, y1 (rectangle)"},
    {.section = "mesh", .name = "shear", .type = SL_KEY_REAL, SL_AT_SCENE(mesh_config.shear), .min = -10.0, .max = 10.0,
     .help = "rectangle: x moves by shear (y - y0), a parallelogram"},
    {.section = "mesh", .name = "r", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.r), .max_n = 2, .units = "m",
     .help = "r0, r1 (annulus)"},
    {.section = "mesh", .name = "z", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.z), .max_n = 2, .units = "m",
     .help = "z0, z1 (annulus)"},
    {.section = "mesh", .name = "origin", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.origin), .max_n = 2,
     .units = "m", .def_list = (const double[]){0.0, 0.0}, .n_def = 2, .help = "lower-left corner (inclined_box)"},
    {.section = "mesh", .name = "width", .type = SL_KEY_REAL, SL_AT_SCENE(mesh_config.width), .min = 1e-12,
     .max = 1e12, .units = "m", .def_doc = "required with inclined_box", .help = "inclined_box width"},
    {.section = "mesh", .name = "height", .type = SL_KEY_REAL, SL_AT_SCENE(mesh_config.height), .min = 1e-12,
     .max = 1e12, .units = "m", .def_doc = "required with inclined_box", .help = "inclined_box height"},
    {.section = "mesh", .name = "angle", .type = SL_KEY_REAL, SL_AT_SCENE(mesh_config.angle), .min = -7.0, .max = 7.0,
     .units = "rad", .help = "inclined_box rotation (counter-clockwise about the origin)"},
    {.section = "mesh", .name = "cells", .type = SL_KEY_REALS, SL_AT_SCENE(mesh_config.cells), .max_n = 2,
     .help = "cells per direction: n, or nx, ny"},
    {.section = "mesh", .name = "cell_type", .type = SL_KEY_CHOICE, SL_AT_SCENE(mesh_config.cell_type),
     .choices = "quad|tri", .help = "quadrilaterals or triangles"},
    {.section = "mesh", .name = "diagonal", .type = SL_KEY_CHOICE, SL_AT_SCENE(mesh_config.diagonal),
     .choices = "right|left|union_jack", .help = "how quads are split into triangles (right: \"/\")"},
    {.section = "mesh", .name = "grading_x", .type = SL_KEY_STRING, SL_AT_SCENE(mesh_config.grading_x),
     .help = "geometric:RATIO (each cell RATIO times the last, along +x) or symmetric:RATIO (h_middle / h_end: "
             "above 1 refines both ends)"},
    {.section = "mesh", .name = "grading_y", .type = SL_KEY_STRING, SL_AT_SCENE(mesh_config.grading_y),
     .help = "the same along y (z)"},
    {.section = "mesh", .name = "file", .type = SL_KEY_STRING, SL_AT_SCENE(mesh_config.file),
     .help = "gmsh: the mesh file (MSH 2.2 ASCII, 4.1 ASCII or binary; order 1 or 2), relative to the scene"},
    {.section = "mesh", .name = "memory_limit", .type = SL_KEY_REAL, SL_AT_SCENE(mesh_config.memory_limit), .min = 0.0,
     .max = 1e18, .units = "B", .def_doc = "the machine's memory (MemTotal in /proc/meminfo)",
     .help = "refuse a mesh whose run needs more (estimated before anything is allocated: at least 16 kB a cell in "
             "2-D, 1 kB in 1-D)"},
    {.section = "mesh", .name = "split_quads", .type = SL_KEY_BOOL, SL_AT_SCENE(mesh_config.split_quads),
     .help = "gmsh: split each quadrangle into two triangles along its shorter diagonal (a mesh of triangles and "
             "quadrangles then runs on P2/P1)"},
};
TABLE(sl_keys_mesh, mesh_keys);

static const sl_key fluid_keys[] = {
    {.section = "fluid", .name = "density", .type = SL_KEY_REAL, SL_AT_SCENE(fluid.density), .def = 1000.0,
     .min = 1e-3, .max = 1e5, .units = "kg m^-3", .help = "fluid density"},
    {.section = "fluid", .name = "viscosity", .type = SL_KEY_REAL, SL_AT_SCENE(fluid.viscosity), .def = 1e-3,
     .min = 1e-7, .max = 1e7, .units = "Pa s", .help = "fluid dynamic viscosity"},
};
TABLE(sl_keys_fluid, fluid_keys);

static const sl_key time_step_keys[] = {
    {.section = "time", .name = "end", .type = SL_KEY_REAL, SL_AT_SCENE(time.end), .flags = SL_KEY_REQUIRED,
     .min = 0.0, .max = 1e12, .units = "s", .help = "end time"},
    {.section = "time", .name = "dt", .type = SL_KEY_REAL, SL_AT_SCENE(time.dt), .flags = SL_KEY_REQUIRED,
     .min = 1e-15, .max = 1e9, .units = "s", .help = "the step (a failed step is retried at a quarter of its length "
                                                    "and grown back by doubling)"},
    {.section = "time", .name = "dt_min", .type = SL_KEY_REAL, SL_AT_SCENE(time.dt_min), .min = 0.0, .max = 1e9,
     .units = "s", .def_doc = "dt x 1e-6", .help = "smallest step before the run gives up"},
    {.section = "time", .name = "max_steps", .type = SL_KEY_INT, SL_AT_SCENE(time.max_steps), .def = 1e8, .min = 1,
     .max = 1e8, .help = "stop (with a checkpoint) after this many steps of this run"},
};
TABLE(sl_keys_time_steps, time_step_keys);

static const sl_key output_keys[] = {
    {.section = "output", .name = "file", .type = SL_KEY_STRING, SL_AT_SCENE(output.file),
     .def_text = "", .help = "HDF5 output file (default: the scene's name with .h5, in the working folder)"},
    {.section = "output", .name = "every", .type = SL_KEY_REAL, SL_AT_SCENE(time.every), .min = 0.0, .max = 1e12,
     .units = "s", .help = "output interval (0: the start and the end only)"},
    {.section = "output", .name = "fields", .type = SL_KEY_STRING, SL_AT_SCENE(output.fields),
     .def_text = "", .help = "fields to write, comma-separated (default: all of the model's)"},
};
TABLE(sl_keys_output, output_keys);

static const sl_key plugin_keys[] = {
    {.section = "plugins", .name = "path", .type = SL_KEY_STRING, SL_AT_SCENE(plugins_path),
     .help = "folders searched first for closure libraries, comma-separated, relative to the scene"},
};
TABLE(sl_keys_plugins, plugin_keys);
