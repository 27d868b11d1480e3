/* SPDX-License-Identifier: GPL-2.0-or-later */
/* libFuzzer target for the model layer: the input is a scene file, checked
 * as `sluice run --check` checks it (the INI parsed, the model chosen, every
 * section and key validated against the model's schema, the closures found
 * through the plugin index and created, the mesh built, the model set up),
 * but in this process and under the fuzz limit of fuzz_scene.h. Any input
 * must pass or fail cleanly: no crash, leak or UB under ASan+UBSan, an exit
 * class of 0, 1 or 2, and a message whenever it fails.
 *
 * Closure libraries: only the plugin folder of this build (its closures.index
 * says which library holds which closure; SLUICE_PLUGIN_PATH is ignored), and
 * a scene's [plugins] path is refused as it is without --allow-plugin-path.
 * Run it through tests/fuzz/run_fuzz.sh; tests fuzz_scene_seeds and
 * fuzz_scene_regressions replay the corpora in every build. */
#include "tests/fuzz/fuzz_scene.h"

#include <stdlib.h>
#include <string.h>

#include "core/config/ini.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

/* 1 when the scene (its includes read) has a [mesh] section: only then is
 * the fuzz limit set, since a model without one (pipe) refuses the section. */
static int has_mesh(const uint8_t *data, size_t size, const char *name) {
  sl_ini *ini = NULL;
  sl_diag d;
  if (sl_ini_parse_string((const char *)data, size, name, &ini, &d) != 0) return 0;
  int yes = sl_ini_find_section(ini, "mesh") != NULL;
  sl_ini_free(ini);
  return yes;
}

int sl_fuzz_scene_check(const uint8_t *data, size_t size, const char *name, sluice_error *e) {
  static const char *const limit[] = {"mesh.memory_limit=" SL_FUZZ_SCENE_MEMORY_LIMIT, NULL};
  sluice_open_opts oo = {.sets = has_mesh(data, size, name) ? limit : NULL};
  sluice *s = NULL;
  memset(e, 0, sizeof *e);
  int rc = sluice_open_text((const char *)data, size, name, &oo, &s, e);
  if (!rc) rc = sluice_check(s, NULL, e);
  sluice_close(s);
  return rc;
}

int LLVMFuzzerInitialize(int *argc, char ***argv) {
  (void)argc, (void)argv;
  unsetenv("SLUICE_PLUGIN_PATH"); /* this build's plugins, nothing else */
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  sluice_error e;
  /* "fuzz.ini": relative includes and meshes resolve in the working directory */
  int rc = sl_fuzz_scene_check(data, size, "fuzz.ini", &e);
  if (rc != SLUICE_OK && rc != SLUICE_FAILED && rc != SLUICE_BAD_INPUT) abort();
  if (rc && !e.msg[0]) abort(); /* a failure says why */
  return 0;
}
