/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice closures: every closure on the search path, by kind. */
#include <stdio.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/plugin/kinds.h"

int sl_cmd_closures(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(
        "usage: sluice closures\n"
        "Lists every closure found on the plugin search path: kind, name, version,\n"
        "library and a one-line summary. Libraries that cannot be used are named on\n"
        "stderr with the reason.");
    return 0;
  }
  if (argc > 0)
    return sl_cli_error(2, "closures takes no arguments (did you mean `sluice closure describe %s`?)", argv[0]);
  sl_registry *r;
  int rc = sl_cli_registry(&r, 1);
  if (rc) return rc;
  printf("%-21s %-28s %-8s %-40s %s\n", "kind", "name", "version", "summary", "library");
  for (int k = SL_KIND_FIRST; k <= SL_KIND_LAST; ++k) {
    for (int i = 0; i < r->n_entries; ++i) {
      const sl_closure_entry *e = &r->entries[i];
      if ((int)e->desc->kind != k) continue;
      const char *base = strrchr(e->library->path, '/');
      printf("%-21s %-28s %-8s %-40s %s\n", sl_kind_name(e->desc->kind), e->desc->name, e->desc->version,
             e->desc->summary, base ? base + 1 : e->library->path);
    }
  }
  /* Two libraries with one (kind, name): say so, a scene must choose. */
  for (int i = 0; i < r->n_entries; ++i)
    for (int j = i + 1; j < r->n_entries; ++j)
      if (r->entries[i].desc->kind == r->entries[j].desc->kind &&
          strcmp(r->entries[i].desc->name, r->entries[j].desc->name) == 0)
        fprintf(stderr, "sluice: warning: %s closure '%s' is provided by both %s and %s\n",
                sl_kind_name(r->entries[i].desc->kind), r->entries[i].desc->name, r->entries[i].library->path,
                r->entries[j].library->path);
  sl_registry_destroy(r);
  return 0;
}
