/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The sparse direct solver of a scene (solver.h). */
#include "core/scene/solver.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const orderings[] = {"auto", "amd", "colamd", "metis"};
/* [solver] linear's choices after auto, whether or not this build has each */
static const char *const linear_names[] = {"umfpack", "klu", "cholmod", "petsc"};

static const char *const petsc_families[] = {"ksp_", "pc_", "fieldsplit_", "sub_", "mg_", "mat_"};
/* Words of options that write, print, draw, time or run something: never from a scene file. */
static const char *const petsc_refused[] = {
    "view",  "monitor", "log",     "file",   "debug", "dump",   "draw", "history", "python", "malloc", "error",
    "trace", "info",    "options", "viewer", "save",  "output", "test", "memory",  "signal", "stack",  "fp_trap"};

static int petsc_value_ok(const char *v) {
  if (!*v) return 0;
  for (; *v; ++v)
    if (!(((*v | 32) >= 'a' && (*v | 32) <= 'z') || (*v >= '0' && *v <= '9') || strchr("._+-/", *v))) return 0;
  return 1;
}

int sl_scene_petsc_section(const sl_ini_section *sec, char **options, sl_diag *d) {
  free(*options);
  *options = NULL;
  size_t len = 1;
  for (int i = 0; i < sec->n_entries; ++i) len += strlen(sec->entries[i].key) + strlen(sec->entries[i].value) + 3;
  char *out = malloc(len);
  if (!out) return sl_diag_set(d, SL_ENOMEM, "out of memory reading [%s]", sec->name);
  size_t at = 0;
  out[0] = '\0';
  for (int i = 0; i < sec->n_entries; ++i) {
    sl_ini_entry *e = (sl_ini_entry *)&sec->entries[i]; /* marked read here, as the typed getters do */
    const char *k = e->key;
    int family = 0, ok = 1;
    /* the split step's two solvers read their options under a prefix (core/solve/linsolve.h roles) */
    const char *kf = k;
    if (strncmp(kf, "velocity_", 9) == 0) kf += 9;
    else if (strncmp(kf, "poisson_", 8) == 0) kf += 8;
    for (size_t f = 0; f < sizeof petsc_families / sizeof *petsc_families; ++f)
      family |= strncmp(kf, petsc_families[f], strlen(petsc_families[f])) == 0;
    for (const char *c = k; *c && ok; ++c) ok = (*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') || *c == '_';
    const char *refused = NULL;
    for (size_t w = 0; w < sizeof petsc_refused / sizeof *petsc_refused && !refused; ++w)
      if (strstr(k, petsc_refused[w])) refused = petsc_refused[w];
    int rc = 0;
    if (!ok || !family)
      rc = sl_diag_set(
          d, SL_EBADINPUT,
          "%s:%d:%d: error: [%s] %s: not a solver option a scene may set (allowed: PETSc options "
          "starting ksp_, pc_, fieldsplit_, sub_, mg_ or mat_, or those after velocity_ or poisson_, without the "
          "dash)",
          e->file, e->line, e->col, sec->name, k);
    else if (refused)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d:%d: error: [%s] %s: an option that can %s is not taken from a scene file; give it on "
                       "the command line (--petsc \"-%s %s\") or in PETSC_OPTIONS",
                       e->file, e->line, e->col, sec->name, k,
                       strcmp(refused, "debug") == 0 ? "start a program" : "write or print output", k, e->value);
    else if (!petsc_value_ok(e->value))
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d:%d: error: [%s] %s = %s: a value is one word of letters, digits and . _ + - /", e->file,
                       e->line, e->col, sec->name, k, e->value);
    if (rc) {
      free(out);
      return rc;
    }
    e->used = 1;
    at += (size_t)snprintf(out + at, len - at, "%s-%s %s", at ? " " : "", k, e->value);
  }
  *options = out;
  return 0;
}

int sl_scene_linsolve_general(const sl_scene *sc, int32_t n, const char *why, sl_linsolve **ls, const char **name,
                              sl_diag *d) {
  int which = sc->solver.linear;
  if (which > 0 && which <= (int)(sizeof linear_names / sizeof *linear_names) &&
      strcmp(linear_names[which - 1], "cholmod") == 0) {
    *ls = NULL;
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = cholmod: Cholesky needs a symmetric positive definite matrix, and %s; allowed here: auto, "
                       "umfpack, klu, petsc",
                       sl_scene_where(sc, &sc->solver.linear, at, sizeof at), why);
  }
  return sl_scene_linsolve(sc, n, ls, name, d);
}

static int scene_linsolve(const sl_scene *sc, int32_t n, int once, sl_linsolve **ls, const char **name, sl_diag *d);

int sl_scene_linsolve(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d) {
  return scene_linsolve(sc, n, 0, ls, name, d);
}

int sl_scene_linsolve_once(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d) {
  return scene_linsolve(sc, n, 1, ls, name, d);
}

static int scene_linsolve(const sl_scene *sc, int32_t n, int once, sl_linsolve **ls, const char **name, sl_diag *d) {
  *ls = NULL;
  int which = sc->solver.linear; /* 0: auto, else linear_names[which - 1] */
  int n_names = (int)(sizeof linear_names / sizeof *linear_names);
  int rank = 0, ranks = 1;
  int rc = sl_linsolve_ranks(&rank, &ranks, d);
  if (rc) return rc;
  /* auto: PETSc when launched on several ranks (the scene's validation refused a direct solver there) */
  *name = which > 0 && which <= n_names ? linear_names[which - 1]
          : ranks > 1                   ? "petsc"
          : once                        ? sl_linsolve_default_name_once(n)
                                        : sl_linsolve_default_name(n);
  if (strcmp(*name, "petsc") == 0 && (rc = sl_linsolve_petsc_scene_options(sc->solver.petsc_options, d))) return rc;
  if ((rc = sl_linsolve_create(ls, *name, d))) return rc;
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
  /* auto chose UMFPACK: where its crude pivot ratio calls the matrix singular, KLU takes over (once), with the
     ordering the scene gives KLU */
  if (which == 0 && strcmp(*name, "umfpack") == 0 &&
      (rc = sl_linsolve_set_fallback(*ls, "klu",
                                     given ? sc->solver.ordering
                                     : k   ? (int)k->def
                                           : 0,
                                     d))) {
    sl_linsolve_destroy(*ls);
    *ls = NULL;
    return rc;
  }
  return 0;
}
