/* Runs a scene of configs/ through a model's entry point, as `sluice run`
 * does (parse, overrides, validation, closure registry), for the scene
 * tests. */
#ifndef SLUICE_TESTS_SCENES_SCENE_RUNNER_H
#define SLUICE_TESTS_SCENES_SCENE_RUNNER_H

#include <stdio.h>
#include <string.h>

#include "core/config/scene_schema.h"
#include "core/models/navier_stokes.h"
#include "core/plugin/closure_ini.h"

typedef int (*scene_model_run)(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res,
                               sl_diag *d);

typedef struct scene_request {
  const char *configs;         /* folder of the scene files */
  const char *scene;           /* configs/<scene>.ini */
  const char *replace_section; /* with replacement: this section's text is replaced (NULL: none) */
  const char *replacement;
  const char *const *sets; /* section.key=value overrides, NULL-terminated (may be NULL) */
  const char *out;         /* output file */
  const char *restart;     /* checkpoint to continue from (NULL: start) */
  int solve_every_step;    /* solve the flow even where its result is known */
} scene_request;

static inline int scene_run(const scene_request *q, scene_model_run run, sl_ns_result *res, sl_diag *d) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s.ini", q->configs, q->scene);
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  int rc;
  if (q->replace_section) {
    static char text[1 << 16], edited[1 << 16];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f) fclose(f);
    text[n] = '\0';
    char head[128];
    snprintf(head, sizeof head, "[%s]", q->replace_section);
    char *a = strstr(text, head), *b = a ? strstr(a + 1, "\n[") : NULL;
    if (!a) return sl_diag_set(d, SL_EBADINPUT, "%s: no section %s", path, head);
    snprintf(edited, sizeof edited, "%.*s%s%s", (int)(a - text), text, q->replacement, b ? b : "");
    rc = sl_ini_parse_string(edited, strlen(edited), path, &ini, d);
  } else {
    rc = sl_ini_parse_file(path, &ini, d);
  }
  for (int i = 0; q->sets && q->sets[i] && !rc; ++i) rc = sl_ini_apply_override(ini, q->sets[i], d);
  if (!rc) rc = sl_scene_validate(ini, d);
  if (!rc) rc = sl_registry_create(&reg, NULL, 0, d);
  if (!rc) rc = sl_registry_scan(reg, d);
  sl_ns_result r;
  sl_ns_run_opts o = {.scene_path = path, .output = q->out, .restart = q->restart, .sluice_version = "test",
                      .solve_every_step = q->solve_every_step};
  if (!rc) rc = run(ini, reg, &o, res ? res : &r, d);
  sl_registry_destroy(reg);
  sl_ini_free(ini);
  return rc;
}

/* Defines, for a test file with `static char configs[]` and testing.h:
 *   run_scene(scene, replace_section, replacement, sets, out, d): 0 or the error (d set);
 *   run_ok(scene, replace_section, replacement, sets, out): the same, a failure counted as a failed check;
 * both with the model entry point `model`. */
#define SCENE_RUNNERS(model)                                                                                          \
  static int run_scene(const char *scene, const char *replace_section, const char *replacement,                      \
                       const char *const *sets, const char *out, sl_diag *d) {                                        \
    scene_request q = {.configs = configs, .scene = scene, .replace_section = replace_section,                        \
                       .replacement = replacement, .sets = sets, .out = out};                                         \
    return scene_run(&q, model, NULL, d);                                                                             \
  }                                                                                                                   \
  static int run_ok(const char *scene, const char *section, const char *replacement, const char *const *sets,        \
                    const char *out) {                                                                                \
    sl_diag d = {{0}};                                                                                                \
    int rc = run_scene(scene, section, replacement, sets, out, &d);                                                   \
    CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);                                                                       \
    return rc;                                                                                                        \
  }

#endif
