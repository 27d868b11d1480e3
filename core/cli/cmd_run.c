/* sluice run SCENE.ini: parse and validate a scene, resolve its closures.
 * The finite-element engine that would then simulate it is not part of this
 * build yet; `run` says so instead of pretending. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/config/ini.h"
#include "core/config/scene_schema.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/kinds.h"

static const char run_usage[] =
    "usage: sluice run SCENE.ini [--set section.key=value]... [--print-config] [-o OUT.h5]\n"
    "Reads a scene, applies the --set overrides, checks every section and key\n"
    "(unknown ones are errors with a suggestion), and loads and validates each\n"
    "[closure.<kind>] against the closure's own schema.\n"
    "--print-config prints the resolved configuration (includes flattened,\n"
    "overrides applied) and stops.\n"
    "Note: the simulation engine is not built yet. `run` validates the scene and\n"
    "its closures and stops there: nothing is simulated and no output is written.";

int sl_cmd_run(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(run_usage);
    return 0;
  }
  const char *scene = NULL, *out_file = NULL;
  int print_config = 0;
  enum { MAX_SETS = 256 };
  const char *sets[MAX_SETS];
  int n_sets = 0;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
      if (n_sets == MAX_SETS) return sl_cli_error(SL_EBADINPUT, "too many --set options");
      sets[n_sets++] = argv[++i];
    } else if (strncmp(argv[i], "--set=", 6) == 0) {
      if (n_sets == MAX_SETS) return sl_cli_error(SL_EBADINPUT, "too many --set options");
      sets[n_sets++] = argv[i] + 6;
    } else if (strcmp(argv[i], "--print-config") == 0) {
      print_config = 1;
    } else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
      out_file = argv[++i];
    } else if (argv[i][0] == '-') {
      return sl_cli_error(SL_EBADINPUT, "run: unknown option or missing value '%s' (sluice run --help)", argv[i]);
    } else if (!scene) {
      scene = argv[i];
    } else {
      return sl_cli_error(SL_EBADINPUT, "run: one scene at a time ('%s' and '%s')", scene, argv[i]);
    }
  }
  if (!scene) return sl_cli_error(SL_EBADINPUT, "run: which scene?\n%s", run_usage);
  (void)out_file;

  sl_diag d;
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  char **dirs = NULL;
  int n_dirs = 0, rc;
  enum { MAX_CLOSURES = 64 };
  sl_closure *closures[MAX_CLOSURES];
  int n_closures = 0;
  if ((rc = sl_ini_parse_file(scene, &ini, &d))) goto fail;
  for (int i = 0; i < n_sets; ++i)
    if ((rc = sl_ini_apply_override(ini, sets[i], &d))) goto fail;
  if ((rc = sl_scene_validate(ini, &d))) goto fail;
  if ((rc = sl_plugin_dirs_from_ini(ini, &dirs, &n_dirs, &d))) goto fail;
  if ((rc = sl_registry_create(&reg, (const char *const *)dirs, n_dirs, &d))) goto fail;
  if ((rc = sl_registry_scan(reg, &d))) goto fail;
  for (int s = 0; s < ini->n_sections; ++s) {
    const char *name = ini->sections[s].name;
    if (strncmp(name, "closure.", 8) != 0) continue;
    if (n_closures == MAX_CLOSURES) {
      rc = sl_diag_set(&d, SL_EBADINPUT, "%s: more than %d closures", scene, MAX_CLOSURES);
      goto fail;
    }
    if ((rc = sl_closure_from_ini(reg, ini, name, &closures[n_closures], &d))) goto fail;
    n_closures++;
  }
  if (print_config) {
    if (sl_ini_write(ini, stdout)) rc = sl_diag_set(&d, SL_EFAILED, "cannot write the configuration");
  } else {
    printf("%s: scene valid; %d closure%s resolved\n", scene, n_closures, n_closures == 1 ? "" : "s");
    for (int i = 0; i < n_closures; ++i) {
      const sl_closure_desc *c = closures[i]->desc;
      printf("  %-18s %-24s %s (%s)\n", sl_kind_name(c->kind), c->name, c->version, closures[i]->library->path);
    }
    fprintf(stderr, "sluice: the simulation engine is not built yet: nothing was simulated, no output written\n");
  }
fail:
  for (int i = 0; i < n_closures; ++i) sl_closure_destroy(closures[i]);
  sl_registry_destroy(reg);
  sl_plugin_dirs_free(dirs, n_dirs);
  sl_ini_free(ini);
  if (rc) fprintf(stderr, "%s\n", d.msg);
  return rc;
}
