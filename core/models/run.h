/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A run of a scene, the same for every model: the model picked from the
 * registry, the typed scene built (every input error found before anything
 * is written), the model set up, a restart's checkpoint read and checked,
 * then the output opened (mesh, provenance) and the time loop run. */
#ifndef SLUICE_MODELS_RUN_H
#define SLUICE_MODELS_RUN_H

#include "core/config/ini.h"
#include "core/models/registry.h"
#include "core/plugin/registry.h"
#include "core/scene/scene.h"
#include "core/time/model.h"

/* Runs the scene. Returns 0, SL_EBADINPUT (bad scene: nothing written) or
 * SL_EFAILED (the run failed: the last good state is in the output file and
 * the message says where and why). res is filled in every case. */
int sl_model_run(sl_ini *ini, const sl_registry *reg, const sl_run_opts *o, sl_run_result *res, sl_diag *d);

/* What the run's output may replace (core/io/output.h): a path from the
 * scene file (no o->output) only in the scene's folder (dir, of cap bytes,
 * receives it) or the working folder; the scene file itself never. */
void sl_run_output_opts(const sl_run_opts *o, char *dir, size_t cap, sl_output_opts *oo);

/* The scene of an INI file without running it (`sluice run --check`,
 * --print-config): the model's entry and its typed scene. Closures are
 * created with create_closures, else only found and checked; the mesh is
 * built with build_mesh. Free with sl_scene_free. */
int sl_model_scene(sl_ini *ini, const sl_registry *reg, int create_closures, int build_mesh,
                   const sl_model_entry **entry, sl_scene **sc, sl_diag *d);

/* Every check a run makes before it opens a file (the scene, the model's
 * set-up, a restart's checkpoint against the scene) without running:
 * `sluice run --check`. The scene is returned for its report (free with
 * sl_scene_free). */
int sl_model_check(sl_ini *ini, const sl_registry *reg, const char *restart, const sl_model_entry **entry,
                   sl_scene **sc, sl_diag *d);

#endif
