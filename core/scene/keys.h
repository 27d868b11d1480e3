/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Key tables every model reads the same way (a model's schema lists them
 * beside its own). */
#ifndef SLUICE_SCENE_KEYS_H
#define SLUICE_SCENE_KEYS_H

#include "core/scene/schema.h"

extern const sl_key_table sl_keys_scene;      /* [scene] model, title */
extern const sl_key_table sl_keys_mesh;       /* [mesh] */
extern const sl_key_table sl_keys_fluid;      /* [fluid] density, viscosity */
extern const sl_key_table sl_keys_time_steps; /* [time] end, dt (required), dt_min, max_steps: a model's own steps */
extern const sl_key_table sl_keys_output;     /* [output] file, every, fields */
extern const sl_key_table sl_keys_plugins;    /* [plugins] path */

#endif
