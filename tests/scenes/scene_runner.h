/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Runs a scene of configs/ as `sluice run` does (parse, overrides,
 * validation, closures, the model), through the embedding API, for the
 * scene tests. */
#ifndef SLUICE_TESTS_SCENES_SCENE_RUNNER_H
#define SLUICE_TESTS_SCENES_SCENE_RUNNER_H

#include <stdio.h>
#include <string.h>

#include "core/util/diag.h"
#include "sluice/sluice.h"

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

static inline int scene_run(const scene_request *q, sluice_summary *res, sl_diag *d) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s.ini", q->configs, q->scene);
  sluice *s = NULL;
  sluice_error e = {0, ""};
  /* solve_every_step: [solver] skip_known = false after the request's own overrides */
  const char *sets[64];
  int n_sets = 0;
  while (q->sets && q->sets[n_sets] && n_sets < 62) sets[n_sets] = q->sets[n_sets], ++n_sets;
  if (q->solve_every_step) sets[n_sets++] = "solver.skip_known=false";
  sets[n_sets] = NULL;
  sluice_open_opts oo = {.sets = sets, .scan_all = 1};
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
    rc = sluice_open_text(edited, strlen(edited), path, &oo, &s, &e);
  } else {
    rc = sluice_open(path, &oo, &s, &e);
  }
  sluice_summary r;
  sluice_run_opts o = {.scene_path = path, .output = q->out, .restart = q->restart, .version = "test"};
  if (!rc) rc = sluice_run(s, &o, res ? res : &r, &e);
  sluice_close(s);
  if (rc) sl_diag_set(d, rc, "%s", e.msg);
  return rc;
}

/* Defines, for a test file with `static char configs[]` and testing.h:
 *   run_scene(scene, replace_section, replacement, sets, out, d): 0 or the error (d set);
 *   run_ok(scene, replace_section, replacement, sets, out): the same, a failure counted as a failed check;
 * (the model is the scene's). */
#define SCENE_RUNNERS()                                                                                       \
  static int run_scene(const char *scene, const char *replace_section, const char *replacement,               \
                       const char *const *sets, const char *out, sl_diag *d) {                                \
    scene_request q = {.configs = configs,                                                                    \
                       .scene = scene,                                                                        \
                       .replace_section = replace_section,                                                    \
                       .replacement = replacement,                                                            \
                       .sets = sets,                                                                          \
                       .out = out};                                                                           \
    return scene_run(&q, NULL, d);                                                                            \
  }                                                                                                           \
  static int run_ok(const char *scene, const char *section, const char *replacement, const char *const *sets, \
                    const char *out) {                                                                        \
    sl_diag d = {{0}};                                                                                        \
    int rc = run_scene(scene, section, replacement, sets, out, &d);                                           \
    CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);                                                               \
    return rc;                                                                                                \
  }

#endif
