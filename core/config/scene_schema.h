/* The keys a scene may hold, section by section, with their types and
 * ranges: the single table behind unknown-key errors, typed validation and
 * the scene documentation. The engine's sections grow here as it does. */
#ifndef SLUICE_CONFIG_SCENE_SCHEMA_H
#define SLUICE_CONFIG_SCENE_SCHEMA_H

#include "core/config/ini.h"

typedef enum sl_key_type { SL_KEY_REAL, SL_KEY_INT, SL_KEY_BOOL, SL_KEY_STRING, SL_KEY_CHOICE, SL_KEY_LIST } sl_key_type;

typedef struct sl_key_spec {
  const char *name;
  sl_key_type type;
  int required;
  double min, max;     /* REAL and INT */
  const char *choices; /* CHOICE: "a|b|c" */
  const char *help;
} sl_key_spec;

typedef struct sl_section_spec {
  const char *name;     /* "time", or a prefix ending in '.' ("boundary.") */
  int open;             /* keys not checked yet (the engine that reads them is not built) */
  const sl_key_spec *keys;
  int n_keys;
} sl_section_spec;

const sl_section_spec *sl_scene_sections(int *n);

/* Checks sections and keys (unknown ones with a did-you-mean), and the type
 * and range of every value the schema knows. Closure sections are checked
 * separately against the closure's own schema. */
int sl_scene_validate(const sl_ini *ini, sl_diag *d);

#endif
