/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A restart checked against the scene of its checkpoint: the scene the
 * checkpoint's run was made with (its provenance, /provenance/ini) and the
 * scene of the restart must agree on everything but what a continuation
 * may change (sl_restart_may_change): the model, the domain and the mesh,
 * the materials, the physics, every boundary, every closure and its
 * parameters, and the time scheme. Values are compared as numbers where
 * they are numbers (1e-2 = 0.01) and a key not given counts as its schema
 * default. The end time must lie after the checkpoint's time. Found before
 * any file is opened: SL_EBADINPUT with file:line of the changed key, the
 * checkpoint's value and what may change. */
#ifndef SLUICE_SCENE_RESTART_H
#define SLUICE_SCENE_RESTART_H

#include "core/scene/scene.h"

int sl_scene_check_restart(const sl_scene *sc, const char *ck_path, double ck_time, sl_diag *d);
/* The k-th key a restart may change, "section.key" or "section.*" (NULL past the last). */
const char *sl_restart_may_change(int k);

#endif
