/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice model list | describe NAME: the models, their variants, and each
 * one's sections, keys, defaults, units and ranges, from its schema. */
#include <stdio.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/models/registry.h"

static const char model_usage[] =
    "usage: sluice model list\n"
    "       sluice model describe NAME [--variant V] [--markdown]\n"
    "       sluice model describe --all --markdown\n"
    "list: every model and its variants, one line each.\n"
    "describe: the sections and keys a model reads, with type, default, units and\n"
    "range, its closures and its output fields (all variants unless --variant).\n"
    "--markdown writes the page docs/models/NAME.md holds.";

static void describe(const char *name, const char *variant, int markdown) {
  int n;
  const sl_model_entry *all = sl_models(&n);
  int first = 1;
  for (int i = 0; i < n; ++i) {
    const sl_schema *s = all[i].schema;
    if (strcmp(s->model, name) != 0) continue;
    if (variant && (!s->variant || strcmp(s->variant, variant) != 0)) continue;
    if (!first) fputs(markdown ? "\n" : "\n\n", stdout);
    sl_schema_describe(s, stdout, markdown);
    first = 0;
  }
}

int sl_cmd_model(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv) || argc < 1) {
    puts(model_usage);
    return argc < 1 ? 2 : 0;
  }
  int n;
  const sl_model_entry *all = sl_models(&n);
  if (strcmp(argv[0], "list") == 0) {
    for (int i = 0; i < n; ++i) {
      const sl_schema *s = all[i].schema;
      printf("%-14s %-52s %s\n", s->model, s->variant ? s->variant : "", s->title);
    }
    return 0;
  }
  if (strcmp(argv[0], "describe") != 0) {
    static const char *const verbs[] = {"list", "describe"};
    const char *hint = sl_suggest(argv[0], verbs, 2);
    return sl_cli_error(2, "model: unknown subcommand '%s'%s%s%s\n%s", argv[0], hint ? " (did you mean '" : "",
                        hint ? hint : "", hint ? "'?)" : "", model_usage);
  }
  const char *name = NULL, *variant = NULL;
  int markdown = 0, every = 0;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--markdown") == 0) markdown = 1;
    else if (strcmp(argv[i], "--all") == 0) every = 1;
    else if (strcmp(argv[i], "--variant") == 0 && i + 1 < argc) variant = argv[++i];
    else if (argv[i][0] == '-') return sl_cli_error(2, "model describe: unknown option '%s'", argv[i]);
    else name = argv[i];
  }
  if (every) {
    for (int i = 0; i < n; ++i) {
      int seen = 0;
      for (int j = 0; j < i && !seen; ++j) seen = strcmp(all[j].schema->model, all[i].schema->model) == 0;
      if (seen) continue;
      if (i) fputs("\n", stdout);
      describe(all[i].schema->model, NULL, markdown);
    }
    return 0;
  }
  if (!name) return sl_cli_error(2, "model describe: which model?\n%s", model_usage);
  const char *names[16];
  int n_names = 0, found = 0;
  for (int i = 0; i < n; ++i) {
    found |= strcmp(all[i].schema->model, name) == 0 &&
             (!variant || (all[i].schema->variant && strcmp(all[i].schema->variant, variant) == 0));
    int seen = 0;
    for (int j = 0; j < n_names && !seen; ++j) seen = strcmp(names[j], all[i].schema->model) == 0;
    if (!seen && n_names < 16) names[n_names++] = all[i].schema->model;
  }
  if (!found) {
    const char *hint = sl_suggest(name, names, n_names);
    return sl_cli_error(2, "model describe: no model '%s'%s%s%s%s (sluice model list)", name,
                        variant ? " with that variant" : "", hint ? "; did you mean '" : "", hint ? hint : "",
                        hint ? "'?" : "");
  }
  describe(name, variant, markdown);
  return 0;
}
