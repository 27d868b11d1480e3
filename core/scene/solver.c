/* The sparse direct solver of a scene (solver.h). */
#include "core/scene/solver.h"

#include <string.h>

static const char *const orderings[] = {"auto", "amd", "colamd", "metis"};

int sl_scene_linsolve_general(const sl_scene *sc, int32_t n, const char *why, sl_linsolve **ls, const char **name,
                              sl_diag *d) {
  int n_names = 0;
  const char *const *names = sl_linsolve_names(&n_names);
  int which = sc->solver.linear;
  if (which > 0 && which <= n_names && strcmp(names[which - 1], "cholmod") == 0) {
    *ls = NULL;
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = cholmod: Cholesky needs a symmetric positive definite matrix, and %s; allowed here: auto, "
                       "umfpack, klu%s",
                       sl_scene_where(sc, &sc->solver.linear, at, sizeof at), why,
                       strstr(SL_SCENE_LINEAR_CHOICES, "petsc") ? ", petsc" : "");
  }
  return sl_scene_linsolve(sc, n, ls, name, d);
}

int sl_scene_linsolve(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d) {
  *ls = NULL;
  int n_names = 0;
  const char *const *names = sl_linsolve_names(&n_names);
  int which = sc->solver.linear; /* 0: auto, else names[which - 1] */
  *name = which > 0 && which <= n_names ? names[which - 1] : sl_linsolve_default_name(n);
  int rc = sl_linsolve_create(ls, *name, d);
  if (rc) return rc;
  if (sc->solver.reuse && (rc = sl_linsolve_set_reuse_name(*ls, "never", d))) {
    sl_linsolve_destroy(*ls);
    *ls = NULL;
    return rc;
  }
  const sl_key *k = sl_schema_key(sc->schema, "solver", "ordering");
  int given = sl_scene_given(sc, &sc->solver.ordering);
  int ordering = given ? sc->solver.ordering : (k && strcmp(*name, "klu") == 0 ? (int)k->def : 0);
  if ((given || ordering != 0) && (rc = sl_linsolve_set_ordering(*ls, orderings[ordering], d))) {
    sl_linsolve_destroy(*ls);
    *ls = NULL;
    char at[400];
    return given ? sl_diag_prefix(d, SL_EBADINPUT, "%s", sl_scene_where(sc, &sc->solver.ordering, at, sizeof at)) : rc;
  }
  return 0;
}
