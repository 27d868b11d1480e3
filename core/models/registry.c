/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The models sluice runs (registry.h). */
#include "core/models/registry.h"

#include <string.h>

#include "core/models/mixture/mixture.h"
#include "core/models/navier_stokes/navier_stokes.h"
#include "core/models/pipe/pipe.h"
#include "core/models/scalar/scalar.h"
#include "core/models/two_fluid/two_fluid.h"
#include "core/scene/scene.h"

static const sl_model_entry entries[] = {
    {&sl_navier_stokes_schema, &sl_navier_stokes_ops},
    {&sl_mixture_schema, &sl_mixture_ops},
    {&sl_two_fluid_column_schema, &sl_two_fluid_column_ops},
    {&sl_two_fluid_plane_schema, &sl_two_fluid_plane_ops},
    {&sl_two_fluid_shear_schema, &sl_two_fluid_shear_ops},
    {&sl_scalar_schema, &sl_scalar_ops},
    {&sl_pipe_schema, &sl_pipe_ops},
};
enum { N_ENTRIES = (int)(sizeof entries / sizeof entries[0]) };

const sl_model_entry *sl_models(int *n) {
  *n = N_ENTRIES;
  return entries;
}

const sl_schema *const *sl_model_schemas(int *n) {
  static const sl_schema *list[N_ENTRIES];
  for (int i = 0; i < N_ENTRIES; ++i) list[i] = entries[i].schema;
  *n = N_ENTRIES;
  return list;
}

int sl_model_select(const sl_ini *ini, const sl_model_entry **entry, sl_diag *d) {
  int n, k;
  const sl_schema *const *all = sl_model_schemas(&n);
  int rc = sl_scene_select(ini, all, n, &k, d);
  *entry = rc ? NULL : &entries[k];
  return rc;
}

const sl_model_entry *sl_model_variant(const char *name, const char *variant) {
  for (int i = 0; i < N_ENTRIES; ++i) {
    const sl_schema *s = entries[i].schema;
    if (strcmp(s->model, name) == 0 && (!variant || (s->variant && strcmp(s->variant, variant) == 0)))
      return &entries[i];
  }
  return NULL;
}
