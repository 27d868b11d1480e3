/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Every model sluice runs, by name: its schema (core/scene/schema.h) and
 * its ops (core/time/model.h). A model with variants (two_fluid) lists one
 * entry per variant; the scene's keys pick one (the schema's `when` rules).
 * Adding a model is a folder under core/models and a line in registry.c. */
#ifndef SLUICE_MODELS_REGISTRY_H
#define SLUICE_MODELS_REGISTRY_H

#include "core/config/ini.h"
#include "core/scene/schema.h"
#include "core/time/model.h"

typedef struct sl_model_entry {
  const sl_schema *schema;
  const sl_model_ops *ops;
} sl_model_entry;

/* All entries, in the registry's order. */
const sl_model_entry *sl_models(int *n);
/* Every entry's schema (for the scene builder's "a key of model X" hints). */
const sl_schema *const *sl_model_schemas(int *n);
/* The entry a scene file asks for (sl_scene_select). */
int sl_model_select(const sl_ini *ini, const sl_model_entry **entry, sl_diag *d);
/* The entry of model `name` and variant `variant` (NULL: the first). */
const sl_model_entry *sl_model_variant(const char *name, const char *variant);

#endif
