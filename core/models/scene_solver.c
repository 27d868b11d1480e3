/* The sparse direct solver of a scene (scene_solver.h). */
#include "core/models/scene_solver.h"

#include <string.h>

int sl_scene_linsolve(const sl_ini *ini, const char *default_linear, const char *default_ordering, sl_linsolve **ls,
                      const char **name, sl_diag *d) {
  *ls = NULL;
  const char *ordering = NULL, *reuse = NULL;
  int rc = sl_ini_get_string(ini, "solver", "linear", 0, default_linear, name, d);
  if (!rc) rc = sl_ini_get_string(ini, "solver", "ordering", 0, NULL, &ordering, d);
  if (!rc) rc = sl_ini_get_string(ini, "solver", "reuse", 0, "auto", &reuse, d);
  if (!rc) rc = sl_linsolve_create(ls, *name, d);
  if (rc) return rc;
  if ((rc = sl_linsolve_set_reuse_name(*ls, reuse, d))) {
    const sl_ini_entry *r = sl_ini_find(ini, "solver", "reuse");
    sl_linsolve_destroy(*ls);
    *ls = NULL;
    return r ? sl_diag_prefix(d, SL_EBADINPUT, "%s:%d: [solver] reuse", r->file, r->line) : rc;
  }
  const sl_ini_entry *e = sl_ini_find(ini, "solver", "ordering");
  if (!ordering && strcmp(*name, "klu") == 0) ordering = default_ordering;
  if (ordering && (rc = sl_linsolve_set_ordering(*ls, ordering, d))) {
    sl_linsolve_destroy(*ls);
    *ls = NULL;
    return e ? sl_diag_prefix(d, SL_EBADINPUT, "%s:%d: [solver] ordering", e->file, e->line) : rc;
  }
  return 0;
}
