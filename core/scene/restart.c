/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A restart checked against the scene of its checkpoint (restart.h). */
#include "core/scene/restart.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "core/config/ini.h"

/* What a restart may change: how far and how finely it steps, what and where it writes, how it solves,
 * where its closures are found. Everything else (the model, the domain and mesh, the materials, the
 * physics, the boundaries, the closures and their parameters, the time scheme) is the checkpoint's. The
 * initial state is the checkpoint's, so [initial] is not read. */
static const char *const may_change[] = {
    "time.end",
    "time.dt",
    "time.dt_min",
    "time.dt_max",
    "time.max_steps",
    "time.tolerance",
    "time.adaptive",
    "time.controller",
    "output.*",
    "solver.linear",
    "solver.reuse",
    "solver.ordering",
    "solver.max_iterations",
    "solver.nonlinear_tolerance",
    "solver.picard_first",
    "solver.skip_known",
    "solver.nonlinear",
    "plugins.*",
    "initial.*",
    "scene.title",
};

const char *sl_restart_may_change(int k) {
  return k >= 0 && k < (int)(sizeof may_change / sizeof *may_change) ? may_change[k] : NULL;
}

static int changeable(const char *section, const char *key) {
  size_t ls = strlen(section);
  for (size_t k = 0; k < sizeof may_change / sizeof *may_change; ++k) {
    const char *m = may_change[k];
    if (strncmp(m, section, ls) != 0 || m[ls] != '.') continue;
    if (strcmp(m + ls + 1, "*") == 0 || strcmp(m + ls + 1, key) == 0) return 1;
  }
  return 0;
}

static const sl_ini_entry *find(const sl_ini *ini, const char *section, const char *key) {
  const sl_ini_entry *found = NULL;
  for (int s = 0; s < ini->n_sections; ++s) {
    const sl_ini_section *sec = &ini->sections[s];
    if (strcmp(sec->name, section) != 0) continue;
    for (int e = 0; e < sec->n_entries; ++e)
      if (strcmp(sec->entries[e].key, key) == 0) found = &sec->entries[e]; /* the last one holds */
  }
  return found;
}

/* The same value: item by item, as numbers where both items are numbers (1e-2 and 0.01 are the same), else as
 * text with the blanks around commas ignored and letters compared without case. */
static int same_value(const char *a, const char *b) {
  char ia[512], ib[512];
  for (;;) {
    size_t na = strcspn(a, ","), nb = strcspn(b, ",");
    if (na >= sizeof ia || nb >= sizeof ib) return strcmp(a, b) == 0;
    memcpy(ia, a, na), ia[na] = '\0';
    memcpy(ib, b, nb), ib[nb] = '\0';
    char *pa = ia, *pb = ib;
    while (isspace((unsigned char)*pa)) ++pa;
    while (isspace((unsigned char)*pb)) ++pb;
    for (char *e = pa + strlen(pa); e > pa && isspace((unsigned char)e[-1]);) *--e = '\0';
    for (char *e = pb + strlen(pb); e > pb && isspace((unsigned char)e[-1]);) *--e = '\0';
    double va, vb;
    char why[8];
    if (sl_parse_real_expr(pa, &va, why, sizeof why) == 0 && sl_parse_real_expr(pb, &vb, why, sizeof why) == 0) {
      if (!(fabs(va - vb) <= 1e-12 * fmax(fabs(va), fabs(vb)))) return 0;
    } else if (strcasecmp(pa, pb) != 0) {
      return 0;
    }
    a += na, b += nb;
    if (!*a || !*b) return !*a && !*b;
    ++a, ++b;
  }
}

/* The value a key has when it is not given: the schema's default for a scene key with a numeric one. */
static int default_text(const sl_schema *schema, const char *section, const char *key, char *buf, size_t cap) {
  const char *sec = strncmp(section, "boundary.", 9) == 0 ? "boundary" : section;
  const sl_key *k = sl_schema_key(schema, sec, key);
  if (!k || k->def_doc) return 0;
  switch (k->type) {
    case SL_KEY_REAL:
    case SL_KEY_INT:
      snprintf(buf, cap, "%.17g", k->def);
      return 1;
    case SL_KEY_BOOL:
      snprintf(buf, cap, "%s", k->def != 0.0 ? "true" : "false");
      return 1;
    case SL_KEY_CHOICE: {
      const char *c = k->choices;
      for (int i = 0; i < (int)k->def && c; ++i) c = strchr(c, '|'), c = c ? c + 1 : NULL;
      if (!c) return 0;
      size_t n = strcspn(c, "|");
      snprintf(buf, cap, "%.*s", (int)n, c);
      return 1;
    }
    case SL_KEY_STRING:
    case SL_KEY_EXPR:
    case SL_KEY_EXPRS:
      if (!k->def_text) return 0;
      snprintf(buf, cap, "%s", k->def_text);
      return 1;
    default:
      return 0;
  }
}

/* bools written either way: true/false/yes/no/1/0 */
static int same_bool_text(const char *a, const char *b) {
  int x, y;
  return sl_parse_bool(a, &x) == 0 && sl_parse_bool(b, &y) == 0 && x == y;
}

/* One key of `now` against `then` (either may be NULL): 0 when the same or allowed to change. */
static int compare_key(const sl_scene *sc, const char *section, const char *key, const sl_ini_entry *now,
                       const sl_ini_entry *then, const char *ck_path, sl_diag *d) {
  if (changeable(section, key)) return 0;
  char dn[512], dt[512];
  const char *vn = now ? now->value : default_text(sc->schema, section, key, dn, sizeof dn) ? dn : NULL;
  const char *vt = then ? then->value : default_text(sc->schema, section, key, dt, sizeof dt) ? dt : NULL;
  if (vn && vt && (same_value(vn, vt) || same_bool_text(vn, vt))) return 0;
  char where[600];
  if (now && now->file) snprintf(where, sizeof where, "%s:%d: [%s] %s", now->file, now->line, section, key);
  else snprintf(where, sizeof where, "[%s] %s", section, key);
  const char *w =
      "[time] end, dt, dt_min, dt_max, max_steps, tolerance, adaptive, controller; [output]; [solver] "
      "linear, reuse, ordering, max_iterations, nonlinear_tolerance, picard_first, skip_known, nonlinear; "
      "[plugins]; [scene] title";
  return sl_diag_set(d, SL_EBADINPUT,
                     "%s = %s: the checkpoint in %s was run with %s; a restart continues the same scene (what may "
                     "change: %s)",
                     where, vn ? vn : "(not given)", ck_path, vt ? vt : "it not given", w);
}

static int compare_ini(const sl_scene *sc, const sl_ini *now, const sl_ini *then, int now_first, const char *ck_path,
                       sl_diag *d) {
  const sl_ini *a = now_first ? now : then, *b = now_first ? then : now;
  for (int s = 0; s < a->n_sections; ++s) {
    const sl_ini_section *sec = &a->sections[s];
    for (int e = 0; e < sec->n_entries; ++e) {
      const char *key = sec->entries[e].key;
      if (strcmp(key, "include") == 0) continue;
      const sl_ini_entry *ea = find(a, sec->name, key), *eb = find(b, sec->name, key);
      if (ea != &sec->entries[e]) continue; /* a key given twice: its last value, once */
      if (!now_first && eb) continue;       /* the keys both have were compared in the first pass */
      int rc = now_first ? compare_key(sc, sec->name, key, ea, eb, ck_path, d)
                         : compare_key(sc, sec->name, key, eb, ea, ck_path, d);
      if (rc) return rc;
    }
  }
  return 0;
}

int sl_scene_check_restart(const sl_scene *sc, const char *ck_path, double ck_time, sl_diag *d) {
  char *text = NULL;
  sl_diag inner;
  if (sl_output_read_text(ck_path, "/provenance/ini", &text, &inner))
    return sl_diag_set(d, SL_EBADINPUT,
                       "restart: %s has no scene of its run (/provenance/ini), so it cannot be checked against this "
                       "one: %s",
                       ck_path, inner.msg);
  sl_ini *then = NULL;
  int rc = sl_ini_parse_string(text, strlen(text), ck_path, &then, &inner);
  free(text);
  if (rc) return sl_diag_set(d, SL_EBADINPUT, "restart: the scene stored in %s does not parse: %s", ck_path, inner.msg);
  rc = compare_ini(sc, sc->ini, then, 1, ck_path, d);
  if (!rc) rc = compare_ini(sc, sc->ini, then, 0, ck_path, d);
  sl_ini_free(then);
  if (rc) return rc;
  if (sc->time.scheme != SL_SCHEME_STEADY && !(sc->time.end > ck_time + 1e-12 * fmax(1.0, fabs(ck_time)))) {
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT, "%s = %g is not after the checkpoint's time t = %.9g in %s: nothing to run",
                       sl_scene_where(sc, &sc->time.end, at, sizeof at), sc->time.end, ck_time, ck_path);
  }
  return 0;
}
