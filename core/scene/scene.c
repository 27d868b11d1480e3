/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The typed scene: the INI file read once through a model's schema (scene.h). */
#include "core/scene/scene.h"
#include "core/scene/solver.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/parameters.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/kinds.h"
#include "core/scene/mesh.h"

struct sl_scene_src {
  const void *field;
  sl_src src;
};

/* Compiled expressions the scene owns. */
typedef struct expr_list {
  sl_expr **e;
  int n, cap;
} expr_list;

typedef struct builder {
  sl_scene *sc;
  sl_ini *ini;
  expr_list exprs;
  const sl_scene_opts *o;
} builder;

static int oom(sl_diag *d) { return sl_diag_set(d, SL_ENOMEM, "scene: out of memory"); }

static int remember(builder *b, const void *field, const char *section, const sl_ini_entry *e, sl_diag *d) {
  sl_scene *sc = b->sc;
  if (!e) return 0;
  if (sc->n_src == sc->cap_src) {
    int cap = sc->cap_src ? 2 * sc->cap_src : 64;
    struct sl_scene_src *s = realloc(sc->src, (size_t)cap * sizeof *s);
    if (!s) return oom(d);
    sc->src = s, sc->cap_src = cap;
  }
  sc->src[sc->n_src++] = (struct sl_scene_src){field, {e->file, e->line, section, e->key, e->value}};
  return 0;
}

static int own_expr(builder *b, sl_expr *e, sl_diag *d) {
  expr_list *l = &b->exprs;
  if (l->n == l->cap) {
    int cap = l->cap ? 2 * l->cap : 16;
    sl_expr **n = realloc(l->e, (size_t)cap * sizeof *n);
    if (!n) {
      sl_expr_free(e);
      return oom(d);
    }
    l->e = n, l->cap = cap;
  }
  l->e[l->n++] = e;
  return 0;
}

/* "x,y,t" into names[]. */
static int split_vars(const char *vars, char store[][16], const char *names[], int max) {
  int n = 0;
  for (const char *p = vars ? vars : ""; *p && n < max;) {
    size_t len = strcspn(p, ",");
    snprintf(store[n], 16, "%.*s", (int)len, p);
    names[n] = store[n];
    ++n;
    p += len;
    if (*p == ',') ++p;
  }
  return n;
}

static int compile(builder *b, const sl_key *k, const char *section, const sl_ini_entry *e, const char *text,
                   void *slot, sl_diag *d) {
  char store[SL_EXPR_MAX_VARS][16];
  const char *names[SL_EXPR_MAX_VARS];
  int nv = split_vars(k->vars, store, names, SL_EXPR_MAX_VARS), rc;
  if (k->type == SL_KEY_EXPR) {
    sl_scene_expr *x = slot;
    if ((rc = sl_expr_compile_with(text, names, nv, sl_ini_constants(b->ini), &x->e, d)))
      return e ? sl_diag_prefix(d, rc, "%s:%d: [%s] %s", e->file, e->line, section, k->name)
               : sl_diag_prefix(d, rc, "[%s] %s (default '%s')", section, k->name, text);
    x->text = text;
    return own_expr(b, x->e, d);
  }
  sl_scene_exprs *x = slot;
  int max = k->max_n > 0 && k->max_n <= SL_EXPRS_MAX ? k->max_n : SL_EXPRS_MAX;
  if ((rc = sl_expr_compile_list_with(text, names, nv, sl_ini_constants(b->ini), max, x->e, &x->n, d)))
    return e ? sl_diag_prefix(d, rc, "%s:%d: [%s] %s", e->file, e->line, section, k->name)
             : sl_diag_prefix(d, rc, "[%s] %s (default '%s')", section, k->name, text);
  x->text = text;
  for (int i = 0; i < x->n; ++i)
    if ((rc = own_expr(b, x->e[i], d))) {
      for (int j = i + 1; j < x->n; ++j) sl_expr_free(x->e[j]);
      return rc;
    }
  return 0;
}

/* The INI's own copy of a section name (it outlives the builder's buffers). */
static const char *section_name(const sl_ini *ini, const char *section) {
  const sl_ini_section *s = sl_ini_find_section(ini, section);
  return s ? s->name : "";
}

/* Reads one key of [section] into its slot (the INI's getters give the
 * located messages for types and ranges). */
static int fill_key(builder *b, const sl_key *k, const char *section, void *base, sl_diag *d) {
  void *slot = (char *)base + k->offset;
  const sl_ini *ini = b->ini;
  int req = (k->flags & SL_KEY_REQUIRED) != 0, rc = 0;
  const sl_ini_entry *e = sl_ini_find(ini, section, k->name);
  switch (k->type) {
    case SL_KEY_REAL:
      rc = sl_ini_get_real(ini, section, k->name, req, k->def, k->min, k->max, slot, d);
      break;
    case SL_KEY_INT:
      rc = sl_ini_get_int(ini, section, k->name, req, (long)k->def, (long)k->min, (long)k->max, slot, d);
      break;
    case SL_KEY_BOOL:
      rc = sl_ini_get_bool(ini, section, k->name, req, k->def != 0.0, slot, d);
      break;
    case SL_KEY_CHOICE:
      rc = sl_ini_get_choice(ini, section, k->name, req, (int)k->def, k->choices, slot, d);
      break;
    case SL_KEY_STRING:
      rc = sl_ini_get_string(ini, section, k->name, req, k->def_text ? k->def_text : "", slot, d);
      break;
    case SL_KEY_REALS: {
      sl_reals *r = slot;
      int cap = k->max_n > 0 && k->max_n <= SL_REALS_MAX ? k->max_n : SL_REALS_MAX;
      if (!e && !req) {
        r->n = k->n_def;
        for (int i = 0; i < k->n_def; ++i) r->v[i] = k->def_list[i];
        break;
      }
      if ((rc = sl_ini_get_real_list(ini, section, k->name, req, r->v, cap, &r->n, d))) break;
      for (int i = 0; i < r->n && (k->min != 0.0 || k->max != 0.0); ++i)
        if (!(r->v[i] >= k->min && r->v[i] <= k->max))
          rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: item %d (%g) is outside the allowed range [%g, %g]",
                           e->file, e->line, section, k->name, i + 1, r->v[i], k->min, k->max);
      break;
    }
    case SL_KEY_EXPR:
    case SL_KEY_EXPRS: {
      const char *text = NULL;
      if ((rc = sl_ini_get_string(ini, section, k->name, req, "", &text, d))) break;
      if (!*text) { /* an empty value is no value */
        text = k->def_text;
        e = NULL;
      }
      if (text && *text) rc = compile(b, k, section, e, text, slot, d);
      break;
    }
  }
  if (rc) return rc;
  return remember(b, slot, section_name(b->ini, section), e, d);
}

/* ---- which model a key belongs to, for the messages -------------------------------- */

/* "; it is a key of <variant>" or "; it is read by model = X" when another
 * schema reads it (the model's own variants first). */
static void owner_hint(const builder *b, const char *section, const char *key, char *buf, size_t len) {
  buf[0] = '\0';
  const sl_schema *me = b->sc->schema;
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < b->o->n_schemas; ++i) {
      const sl_schema *s = b->o->schemas[i];
      int sibling = strcmp(s->model, me->model) == 0;
      if (s == me || sibling != (pass == 0)) continue;
      int has = key ? sl_schema_key(s, section, key) != NULL
                    : (strncmp(section, "closure.", 8) == 0 ? sl_schema_role(s, section + 8) != NULL
                                                            : sl_schema_has_section(s, section));
      if (!has) continue;
      if (sibling && s->variant) snprintf(buf, len, "; it is a key of the %s (%s)", s->title, s->variant);
      else
        snprintf(buf, len, "; it is read by model = %s%s%s%s", s->model, s->variant ? " (" : "",
                 s->variant ? s->variant : "", s->variant ? ")" : "");
      return;
    }
}

static const char *model_label(const sl_schema *s, char *buf, size_t len) {
  snprintf(buf, len, "%s%s%s%s", s->title, s->variant ? " (" : "", s->variant ? s->variant : "", s->variant ? ")" : "");
  return buf;
}

/* The schema's key names of one section. */
static int section_keys(const sl_schema *s, const char *section, const char **names, int max) {
  int n = 0;
  for (int t = 0; t < s->n_tables; ++t)
    for (int i = 0; i < s->tables[t]->n && n < max; ++i)
      if (sl_schema_key(s, section, s->tables[t]->keys[i].name) == &s->tables[t]->keys[i])
        names[n++] = s->tables[t]->keys[i].name; /* [section]'s, or its family's for [family.NAME] */
  return n;
}

/* 1 when [section] is [FAMILY.NAME] of a named family of the schema (keys flagged SL_KEY_NAMED) */
static int named_member(const sl_schema *s, const char *section) {
  const char *dot = strchr(section, '.');
  if (!dot || !dot[1]) return 0;
  for (int t = 0; t < s->n_tables; ++t)
    for (int i = 0; i < s->tables[t]->n; ++i) {
      const sl_key *k = &s->tables[t]->keys[i];
      if ((k->flags & SL_KEY_NAMED) && strlen(k->section) == (size_t)(dot - section) &&
          strncmp(k->section, section, (size_t)(dot - section)) == 0)
        return 1;
    }
  return 0;
}

static int check_keys(builder *b, const sl_ini_section *sec, const char *schema_section, sl_diag *d) {
  const sl_schema *s = b->sc->schema;
  for (int i = 0; i < sec->n_entries; ++i) {
    const sl_ini_entry *e = &sec->entries[i];
    if (sl_schema_key(s, schema_section, e->key)) continue;
    char hint[256], label[256];
    for (int m = 0; m < s->n_moved; ++m)
      if (strcmp(s->moved[m].section, schema_section) == 0 && strcmp(s->moved[m].name, e->key) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: error: [%s] %s is no longer a key of the %s: use %s", e->file,
                           e->line, e->col, sec->name, e->key, model_label(s, label, sizeof label),
                           s->moved[m].instead);
    const char *names[128];
    int n = section_keys(s, schema_section, names, 128);
    owner_hint(b, schema_section, e->key, hint, sizeof hint);
    const char *sug = sl_suggest(e->key, names, n);
    char list[900];
    size_t at = 0;
    list[0] = '\0';
    for (int k = 0; k < n && at < sizeof list; ++k)
      at += (size_t)snprintf(list + at, sizeof list - at, "%s%s", k ? ", " : "", names[k]);
    model_label(s, label, sizeof label);
    if (sug && !*hint)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: error: unknown key '%s' in [%s]; did you mean '%s'?", e->file,
                         e->line, e->col, e->key, sec->name, sug);
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: error: [%s] %s: not a key of the %s (its keys: %s)%s", e->file,
                       e->line, e->col, sec->name, e->key, label, n ? list : "none", hint);
  }
  return 0;
}

/* Every section is the schema's, a boundary or a closure of one of its roles. */
static int check_sections(builder *b, sl_diag *d) {
  const sl_schema *s = b->sc->schema;
  const sl_ini *ini = b->ini;
  char label[256], hint[256];
  model_label(s, label, sizeof label);
  for (int i = 0; i < ini->n_sections; ++i) {
    const sl_ini_section *sec = &ini->sections[i];
    if (strcmp(sec->name, "plugins") == 0 || strcmp(sec->name, "parameters") == 0) continue;
    if (strcmp(sec->name, "solver.petsc") == 0 && sl_schema_key(s, "solver", "linear")) {
      int rc = sl_scene_petsc_section(sec, &b->sc->solver.petsc_options, d);
      if (rc) return rc;
      continue;
    }
    if (strncmp(sec->name, "boundary.", 9) == 0 && sec->name[9]) {
      if (!s->boundary_size)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: the %s takes no boundary conditions", sec->file, sec->line,
                           sec->name, label);
      continue;
    }
    if (strncmp(sec->name, "closure.", 8) == 0 && sec->name[8]) {
      char role[128];
      snprintf(role, sizeof role, "%s", sec->name + 8);
      if (sl_schema_role(s, role)) continue;
      char list[600];
      size_t at = 0;
      list[0] = '\0';
      for (int r = 0; r < s->n_roles && at < sizeof list; ++r)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s[closure.%s]", r ? ", " : "", s->roles[r].role);
      owner_hint(b, sec->name, NULL, hint, sizeof hint);
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: the %s uses %s%s", sec->file, sec->line, sec->name, label,
                         s->n_roles ? list : "no closures", hint);
    }
    if (sl_schema_has_section(s, sec->name)) continue;
    const char *names[64];
    int n = 0;
    for (int t = 0; t < s->n_tables; ++t)
      for (int k = 0; k < s->tables[t]->n; ++k) {
        const char *x = s->tables[t]->keys[k].section;
        int seen = strcmp(x, "boundary") == 0;
        for (int j = 0; j < n && !seen; ++j) seen = strcmp(names[j], x) == 0;
        if (!seen && n < 64) names[n++] = x;
      }
    const char *sug = sl_suggest(sec->name, names, n);
    owner_hint(b, sec->name, NULL, hint, sizeof hint);
    if (sug)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d:1: error: unknown section [%s]; did you mean [%s]?%s", sec->file,
                         sec->line, sec->name, sug, hint);
    if (!*hint && strchr(sec->name, '.')) { /* a misspelt prefix: [clousre.drag] */
      static const char *const prefixes[] = {"closure.", "boundary."};
      char head[70];
      size_t hl = (size_t)(strchr(sec->name, '.') - sec->name) + 1;
      if (hl < sizeof head) {
        snprintf(head, sizeof head, "%.*s", (int)hl, sec->name);
        const char *p = sl_suggest(head, prefixes, 2);
        if (p)
          return sl_diag_set(d, SL_EBADINPUT, "%s:%d:1: error: unknown section [%s]; did you mean [%s%s]?", sec->file,
                             sec->line, sec->name, p, strchr(sec->name, '.') + 1);
      }
    }
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d:1: error: unknown section [%s]: the %s does not read it%s", sec->file,
                       sec->line, sec->name, label, hint);
  }
  return 0;
}

/* ---- the common sections' computed defaults ------------------------------------------ */

static int resolve_time(builder *b, sl_diag *d) {
  sl_scene *sc = b->sc;
  sl_time_config *t = &sc->time;
  const sl_schema *s = sc->schema;
  const sl_key *scheme = sl_schema_key(s, "time", "scheme");
  if (scheme && !sl_scene_has_section(sc, "time")) t->scheme = SL_SCHEME_STEADY;
  if (!scheme) t->scheme = SL_SCHEME_BDF1; /* a model's own implicit steps */
  if (t->scheme != SL_SCHEME_STEADY) {
    /* end and dt: required for a transient run */
    static const char *const req[2] = {"end", "dt"};
    for (int k = 0; k < 2; ++k) {
      const sl_key *key = sl_schema_key(s, "time", req[k]);
      if (!key || (key->flags & SL_KEY_REQUIRED)) continue;
      double v;
      int rc = sl_ini_get_real(b->ini, "time", req[k], 1, 0.0, key->min, key->max, &v, d);
      if (rc) return rc;
    }
  }
  if (!sl_scene_given(sc, &t->dt_min)) t->dt_min = t->dt * 1e-6;
  if (!sl_scene_given(sc, &t->dt_max)) t->dt_max = t->adaptive && t->end > 0 ? t->end / 10 : t->dt;
  if (t->scheme == SL_SCHEME_STEADY) return 0;
  /* the step's bounds agree with each other, and the output interval with them */
  char a[400], c[400];
  if (sl_scene_given(sc, &t->dt_min) && t->dt_min > t->dt)
    return sl_diag_set(d, SL_EBADINPUT, "%s = %g is larger than %s = %g: the first step would be below the smallest",
                       sl_scene_where(sc, &t->dt_min, a, sizeof a), t->dt_min, sl_scene_where(sc, &t->dt, c, sizeof c),
                       t->dt);
  if (sl_scene_given(sc, &t->dt_max) && t->dt_max < t->dt_min)
    return sl_diag_set(d, SL_EBADINPUT, "%s = %g is smaller than %s = %g: no step fits between them",
                       sl_scene_where(sc, &t->dt_max, a, sizeof a), t->dt_max,
                       sl_scene_where(sc, &t->dt_min, c, sizeof c), t->dt_min);
  if (t->every > 0 && t->every < t->dt_min)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = %g is below %s = %g: the steps that land on every output time would be shorter than the "
                       "smallest step the run allows",
                       sl_scene_where(sc, &t->every, a, sizeof a), t->every,
                       sl_scene_where(sc, &t->dt_min, c, sizeof c), t->dt_min);
  if (t->every > 0 && t->end / t->every > SL_SCENE_OUTPUT_TIMES_MAX)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = %g would write %.3g output times before the end t = %g (at most %g, each a full set of "
                       "fields and a checkpoint): allowed every >= end / %g = %g",
                       sl_scene_where(sc, &t->every, a, sizeof a), t->every, t->end / t->every, t->end,
                       (double)SL_SCENE_OUTPUT_TIMES_MAX, (double)SL_SCENE_OUTPUT_TIMES_MAX,
                       t->end / SL_SCENE_OUTPUT_TIMES_MAX);
  return 0;
}

/* ---- boundaries ------------------------------------------------------------------------ */

static int fill_boundaries(builder *b, sl_diag *d) {
  sl_scene *sc = b->sc;
  const sl_schema *s = sc->schema;
  const sl_mesh *m = sc->mesh;
  for (int i = 0; i < b->ini->n_sections; ++i) { /* every [boundary.X] names a boundary of the mesh */
    const sl_ini_section *sec = &b->ini->sections[i];
    int id;
    if (strncmp(sec->name, "boundary.", 9) != 0) continue;
    int rc = sl_mesh_boundary_id(m, sec->name + 9, &id, d);
    if (rc) return sl_diag_prefix(d, rc, "%s:%d: [%s]", sec->file, sec->line, sec->name);
    if ((rc = check_keys(b, sec, "boundary", d))) return rc;
  }
  sc->n_boundaries = m->n_boundaries;
  sc->boundaries = calloc((size_t)(m->n_boundaries > 0 ? m->n_boundaries : 1), s->boundary_size);
  sc->boundary_src = calloc((size_t)(m->n_boundaries > 0 ? m->n_boundaries : 1), sizeof *sc->boundary_src);
  if (!sc->boundaries || !sc->boundary_src) return oom(d);
  if (!(sc->boundary_order = calloc((size_t)(m->n_boundaries > 0 ? m->n_boundaries : 1), sizeof *sc->boundary_order)))
    return oom(d);
  int n_order = 0;
  for (int i = 0; i < b->ini->n_sections; ++i) {
    const sl_ini_section *sec = &b->ini->sections[i];
    int id;
    sl_diag quiet;
    if (strncmp(sec->name, "boundary.", 9) == 0 && sl_mesh_boundary_id(m, sec->name + 9, &id, &quiet) == 0)
      sc->boundary_order[n_order++] = id;
  }
  for (int i = 0; i < m->n_boundaries; ++i) {
    char name[300];
    snprintf(name, sizeof name, "boundary.%s", m->boundary_names[i]);
    if (!sl_ini_find_section(b->ini, name)) sc->boundary_order[n_order++] = i;
  }
  const sl_key *type = sl_schema_key(s, "boundary", "type");
  for (int i = 0; i < m->n_boundaries; ++i) {
    char name[300];
    snprintf(name, sizeof name, "boundary.%s", m->boundary_names[i]);
    void *base = sl_scene_boundary(sc, i);
    const sl_ini_section *bs = sl_ini_find_section(b->ini, name);
    if (bs) sc->boundary_src[i] = (sl_src){bs->file, bs->line, bs->name, NULL, NULL};
    for (int t = 0; t < s->n_tables; ++t)
      for (int k = 0; k < s->tables[t]->n; ++k) {
        const sl_key *key = &s->tables[t]->keys[k];
        if (strcmp(key->section, "boundary") != 0) continue;
        int rc = fill_key(b, key, name, base, d);
        if (rc) return rc;
      }
    if (!type) continue;
    int ty = *(const int *)((const char *)base + type->offset);
    for (int t = 0; t < s->n_tables; ++t)
      for (int k = 0; k < s->tables[t]->n; ++k) {
        const sl_key *key = &s->tables[t]->keys[k];
        if (strcmp(key->section, "boundary") != 0 || !key->when_type || (key->when_type & (1u << ty))) continue;
        const sl_ini_entry *e = sl_ini_find(b->ini, name, key->name);
        if (!e) continue;
        char allowed[256], tname[64];
        size_t at = 0;
        allowed[0] = '\0';
        const char *p = type->choices;
        for (int c = 0; *p; ++c) {
          size_t len = strcspn(p, "|");
          if (key->when_type & (1u << c))
            at += (size_t)snprintf(allowed + at, sizeof allowed - at, "%s%.*s", at ? " or " : "", (int)len, p);
          if (c == ty) snprintf(tname, sizeof tname, "%.*s", (int)len, p);
          p += len;
          if (*p) ++p;
        }
        if (key->when_doc)
          return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: only %s takes it (this one is type = %s)", e->file,
                             e->line, name, key->name, key->when_doc, tname);
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] %s: only a boundary of type = %s takes it (this one is type = %s)", e->file,
                           e->line, name, key->name, allowed, tname);
      }
  }
  return 0;
}

/* ---- closures ----------------------------------------------------------------------------- */

static int resolve_closures(builder *b, sl_diag *d) {
  sl_scene *sc = b->sc;
  const sl_schema *s = sc->schema;
  char label[256];
  model_label(s, label, sizeof label);
  for (int r = 0; r < s->n_roles; ++r) {
    char sec[160];
    snprintf(sec, sizeof sec, "closure.%s", s->roles[r].role);
    const sl_ini_section *is = sl_ini_find_section(b->ini, sec);
    if (!is) {
      if (s->roles[r].required)
        return sl_diag_set(d, SL_EBADINPUT, "[%s]: the %s needs it: %s; `sluice closures` lists them", sec, label,
                           s->roles[r].help);
      continue;
    }
    sc->closure_sections[r] = is->name;
    if (!b->o->registry) continue;
    int rc = b->o->create_closures ? sl_closure_from_ini(b->o->registry, b->ini, sec, &sc->closures[r], d)
                                   : sl_closure_check_ini(b->o->registry, b->ini, sec, d);
    if (rc) return rc;
  }
  return 0;
}

/* ---- which schema ------------------------------------------------------------------------------ */

/* value is one of "a|b|c". */
static int one_of(const char *value, const char *list) {
  size_t n = strlen(value);
  for (const char *p = list; *p;) {
    size_t len = strcspn(p, "|");
    if (len == n && strncmp(p, value, n) == 0) return 1;
    p += len;
    if (*p) ++p;
  }
  return 0;
}

static int rules_match(const sl_ini *ini, const sl_schema *s) {
  for (int r = 0; r < s->n_when; ++r) {
    const sl_variant_rule *w = &s->when[r];
    const sl_ini_entry *e = sl_ini_find(ini, w->section, w->key);
    if (!one_of(e ? e->value : w->absent, w->values)) return 0;
  }
  return 1;
}

int sl_scene_select(const sl_ini *ini, const sl_schema *const *schemas, int n, int *index, sl_diag *d) {
  char names[512];
  size_t at = 0;
  names[0] = '\0';
  for (int i = 0; i < n; ++i) {
    int seen = 0;
    for (int j = 0; j < i && !seen; ++j) seen = strcmp(schemas[j]->model, schemas[i]->model) == 0;
    if (!seen) at += (size_t)snprintf(names + at, sizeof names - at, "%s%s", at ? "|" : "", schemas[i]->model);
  }
  int choice;
  int rc = sl_ini_get_choice(ini, "scene", "model", 1, 0, names, &choice, d);
  if (rc) return rc;
  const char *model = sl_ini_find(ini, "scene", "model")->value;
  *index = -1;
  for (int i = 0; i < n; ++i) {
    if (strcmp(schemas[i]->model, model) != 0) continue;
    if (*index < 0) *index = i;
    if (rules_match(ini, schemas[i])) {
      *index = i;
      break;
    }
  }
  return 0;
}

/* ---- the build ------------------------------------------------------------------------------- */

static void *target_base(sl_scene *sc, const sl_key *k) {
  return k->target == SL_IN_SCENE ? (void *)sc : k->target == SL_IN_MODEL ? sc->config : NULL;
}

/* [output] file = "" names no file: refused rather than taken as the default. */
static int check_output_file(const sl_scene *sc, sl_diag *d) {
  const sl_src *e = sl_scene_src(sc, &sc->output.file);
  if (!e || (sc->output.file && *sc->output.file)) return 0;
  return sl_diag_set(d, SL_EBADINPUT,
                     "%s:%d: error: [output] file = \"\": the file name is empty; name the output file (e.g. file = "
                     "result.h5) or leave the key out for the default (the scene's name with .h5, in the working "
                     "folder)",
                     e->file, e->line);
}

int sl_scene_build(sl_ini *ini, const sl_schema *schema, const sl_scene_opts *o, sl_scene **out, sl_diag *d) {
  *out = NULL;
  sl_scene *sc = calloc(1, sizeof *sc);
  if (!sc) return oom(d);
  sc->schema = schema, sc->ini = ini, sc->registry = o->registry;
  builder b = {.sc = sc, .ini = ini, .o = o};
  int rc = 0;
  if (!(sc->config = calloc(1, schema->config_size ? schema->config_size : 1))) rc = oom(d);
  if (!rc) rc = sl_ini_parameters(ini, d); /* [parameters]: named constants of every value below */
  if (!rc) rc = check_sections(&b, d);
  for (int i = 0; i < ini->n_sections && !rc; ++i) {
    const sl_ini_section *sec = &ini->sections[i];
    if (strncmp(sec->name, "boundary.", 9) == 0 || strncmp(sec->name, "closure.", 8) == 0) continue;
    if (strcmp(sec->name, "parameters") == 0) continue;
    if (strcmp(sec->name, "solver.petsc") == 0) continue; /* checked with the sections */
    rc = check_keys(&b, sec, sec->name, d);
  }
  /* the values the file gives first (their types and ranges), then the closures, then what the file leaves to
     the defaults (a missing required key last) */
  for (int pass = 0; pass < 2 && !rc; ++pass) {
    if (pass == 1) rc = resolve_closures(&b, d);
    for (int t = 0; t < schema->n_tables && !rc; ++t)
      for (int k = 0; k < schema->tables[t]->n && !rc; ++k) {
        const sl_key *key = &schema->tables[t]->keys[k];
        if (key->target == SL_IN_BOUNDARY || (sl_ini_find(ini, key->section, key->name) != NULL) != (pass == 0))
          continue;
        rc = fill_key(&b, key, key->section, target_base(sc, key), d);
      }
  }
  if (!rc) rc = resolve_time(&b, d);
  if (!rc) rc = check_output_file(sc, d);
  if (!rc && sc->solver.linear == 4 && !sl_linsolve_built("petsc")) { /* SL_SCENE_LINEAR_CHOICES */
    char at[400];
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s: this sluice was built without PETSc (configure with -DSLUICE_WITH_PETSC=ON; "
                     "Debian: libpetsc-real-dev); this build has umfpack, klu and cholmod",
                     sl_scene_where(sc, &sc->solver.linear, at, sizeof at));
  }
  int rank = 0, ranks = 1;
  if (!rc) rc = sl_linsolve_ranks(&rank, &ranks, d);
  if (!rc && ranks > 1) { /* several ranks share the linear solves (PETSc), each keeps the whole state */
    char at[400];
    if (!sl_linsolve_built("petsc"))
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "launched on %d ranks (mpirun), but this sluice was built without PETSc and MPI: it runs on "
                       "one (configure with -DSLUICE_WITH_PETSC=ON to run on several)",
                       ranks);
    else if (!sl_schema_key(schema, "solver", "linear"))
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "launched on %d ranks (mpirun): the %s cannot run on several ranks yet; run "
                       "it on one",
                       ranks, schema->title);
    else if (sl_scene_given(sc, &sc->solver.linear) && sc->solver.linear != 4)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "%s: launched on %d ranks (mpirun), the linear solves must be PETSc's (linear = petsc or "
                       "auto); the direct solvers run on one rank",
                       sl_scene_where(sc, &sc->solver.linear, at, sizeof at), ranks);
  }
  if (!rc && o->build_mesh && sl_schema_has_section(schema, "mesh")) rc = sl_scene_mesh_build(sc, &sc->mesh, d);
  if (!rc && o->build_mesh && schema->boundary_size) rc = fill_boundaries(&b, d);
  /* every entry outside the closures' sections is read by now */
  for (int i = 0; i < ini->n_sections && !rc && o->build_mesh; ++i) {
    const sl_ini_section *sec = &ini->sections[i];
    if (strncmp(sec->name, "closure.", 8) == 0 || strcmp(sec->name, "plugins") == 0) continue;
    if (named_member(schema, sec->name)) continue; /* the model reads it (sl_scene_named_section), keys checked */
    for (int k = 0; k < sec->n_entries && !rc; ++k)
      if (!sec->entries[k].used)
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: not read by the model (a key of no part of it)",
                         sec->entries[k].file, sec->entries[k].line, sec->name, sec->entries[k].key);
  }
  /* the scene owns the compiled expressions: keep the list in the src table's tail */
  sc->exprs = b.exprs.e, sc->n_exprs = b.exprs.n;
  if (rc) {
    sl_scene_free(sc);
    return rc;
  }
  *out = sc;
  return 0;
}

void sl_scene_free(sl_scene *sc) {
  if (!sc) return;
  free(sc->solver.petsc_options);
  for (int i = 0; i < sc->n_exprs; ++i) sl_expr_free(sc->exprs[i]);
  free(sc->exprs);
  for (int r = 0; r < SL_SCHEMA_MAX_ROLES; ++r) sl_closure_destroy(sc->closures[r]);
  sl_mesh_destroy(sc->mesh);
  free(sc->boundaries);
  free(sc->boundary_src);
  free(sc->boundary_order);
  free(sc->config);
  free(sc->src);
  free(sc);
}

/* ---- look-ups ----------------------------------------------------------------------------------- */

const sl_src *sl_scene_src(const sl_scene *sc, const void *field) {
  for (int i = 0; i < sc->n_src; ++i)
    if (sc->src[i].field == field) return &sc->src[i].src;
  return NULL;
}

/* The key whose slot is `field`, with its section name, for messages about a default. */
static const sl_key *key_of(const sl_scene *sc, const void *field, char *section, size_t len) {
  const sl_schema *s = sc->schema;
  for (int t = 0; t < s->n_tables; ++t)
    for (int k = 0; k < s->tables[t]->n; ++k) {
      const sl_key *key = &s->tables[t]->keys[k];
      if (key->target == SL_IN_BOUNDARY) {
        for (int i = 0; i < sc->n_boundaries; ++i)
          if ((const char *)sl_scene_boundary(sc, i) + key->offset == (const char *)field) {
            snprintf(section, len, "boundary.%s", sc->mesh->boundary_names[i]);
            return key;
          }
        continue;
      }
      const char *base = key->target == SL_IN_SCENE ? (const char *)sc : (const char *)sc->config;
      if (base + key->offset == (const char *)field) {
        snprintf(section, len, "%s", key->section);
        return key;
      }
    }
  return NULL;
}

const char *sl_scene_where(const sl_scene *sc, const void *field, char *buf, size_t len) {
  const sl_src *e = sl_scene_src(sc, field);
  char section[300] = "?";
  const sl_key *k = key_of(sc, field, section, sizeof section);
  if (e) {
    snprintf(buf, len, "%s:%d: [%s] %s", e->file, e->line, e->section, e->key);
  } else {
    snprintf(buf, len, "[%s] %s", section, k ? k->name : "?");
  }
  return buf;
}

int sl_scene_require(const sl_scene *sc, const void *field, sl_diag *d) {
  if (sl_scene_given(sc, field)) return 0;
  char section[300] = "?";
  const sl_key *k = key_of(sc, field, section, sizeof section);
  const char *key = k ? k->name : "?";
  const sl_ini_section *s = sl_ini_find_section(sc->ini, section);
  if (s)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d:1: error: [%s] is missing the required key '%s'", s->file, s->line,
                       section, key);
  const char *root = sc->ini->n_files > 0 ? sc->ini->files[0] : "<configuration>";
  return sl_diag_set(d, SL_EBADINPUT, "%s: error: missing section [%s] (it needs the key '%s')", root, section, key);
}

int sl_scene_has_section(const sl_scene *sc, const char *section) {
  return sl_ini_find_section(sc->ini, section) != NULL;
}

static const sl_ini_section *named_section(const sl_scene *sc, const char *family, int i) {
  size_t n = strlen(family);
  for (int k = 0; k < sc->ini->n_sections; ++k) {
    const sl_ini_section *sec = &sc->ini->sections[k];
    if (strncmp(sec->name, family, n) == 0 && sec->name[n] == '.' && sec->name[n + 1] && i-- == 0) return sec;
  }
  return NULL;
}

int sl_scene_named(const sl_scene *sc, const char *family, int i, const char **name, sl_src *where) {
  const sl_ini_section *sec = named_section(sc, family, i);
  if (!sec) return 0;
  *name = sec->name + strlen(family) + 1;
  *where = (sl_src){.file = sec->file, .line = sec->line, .section = sec->name};
  return 1;
}

int sl_scene_named_reals(const sl_scene *sc, const char *family, int i, const char *key, double *v, int max, int *n,
                         sl_src *where, sl_diag *d) {
  const sl_ini_section *sec = named_section(sc, family, i);
  const sl_key *k = sl_schema_key(sc->schema, family, key);
  *n = 0, *where = (sl_src){0};
  if (!sec || !k || !(k->flags & SL_KEY_NAMED))
    return sl_diag_set(d, SL_EFAILED, "[%s.*] %s: not a key of a named family", family, key);
  sl_ini_entry *e = sl_ini_find(sc->ini, sec->name, key);
  if (!e) return 0;
  *where = (sl_src){.file = e->file, .line = e->line, .section = sec->name, .key = key, .value = e->value};
  if (k->type == SL_KEY_REAL) {
    int rc = sl_ini_get_real(sc->ini, sec->name, key, 1, 0.0, k->min, k->max, v, d);
    if (!rc) *n = 1;
    return rc;
  }
  if (k->type != SL_KEY_REALS) return sl_diag_set(d, SL_EFAILED, "[%s] %s: not a number key", sec->name, key);
  int cap = k->max_n > 0 && k->max_n < max ? k->max_n : max;
  int rc = sl_ini_get_real_list(sc->ini, sec->name, key, 1, v, cap, n, d);
  for (int q = 0; q < *n && !rc; ++q)
    if (!(v[q] >= k->min && v[q] <= k->max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: %g is outside [%g, %g]", e->file, e->line, sec->name, key,
                       v[q], k->min, k->max);
  return rc;
}

const sl_src *sl_scene_boundary_section(const sl_scene *sc, int i) {
  return sc->boundary_src && sc->boundary_src[i].file ? &sc->boundary_src[i] : NULL;
}

static int role_index(const sl_scene *sc, const char *role) {
  for (int r = 0; r < sc->schema->n_roles; ++r)
    if (strcmp(sc->schema->roles[r].role, role) == 0) return r;
  return -1;
}

sl_closure *sl_scene_closure(const sl_scene *sc, const char *role) {
  int r = role_index(sc, role);
  return r >= 0 ? sc->closures[r] : NULL;
}

const char *sl_scene_closure_where(const sl_scene *sc, const char *role, char *buf, size_t len) {
  char sec[160];
  snprintf(sec, sizeof sec, "closure.%s", role);
  const sl_ini_section *s = sl_ini_find_section(sc->ini, sec);
  if (s) snprintf(buf, len, "%s:%d: [%s]", s->file, s->line, sec);
  else snprintf(buf, len, "[%s]", sec);
  return buf;
}

/* ---- output ------------------------------------------------------------------------------------- */

int sl_scene_output_fields(const sl_scene *sc, unsigned default_mask, unsigned *mask, sl_diag *d) {
  const char *list = sc->output.fields ? sc->output.fields : "";
  const char *const *names = sc->schema->fields;
  int n_names = sc->schema->n_fields;
  *mask = *list ? 0 : default_mask;
  const sl_src *e = sl_scene_src(sc, &sc->output.fields);
  for (const char *p = list; *p;) {
    while (*p == ' ' || *p == ',') ++p;
    const char *q = p;
    while (*q && *q != ',' && *q != ' ') ++q;
    if (q == p) break;
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(q - p), p);
    int found = -1;
    for (int k = 0; k < n_names; ++k)
      if (strcmp(name, names[k]) == 0) found = k;
    if (found < 0) {
      char known[512];
      size_t n = 0;
      known[0] = '\0';
      for (int k = 0; k < n_names && n < sizeof known; ++k)
        n += (size_t)snprintf(known + n, sizeof known - n, "%s%s", k ? ", " : "", names[k]);
      const char *s = sl_suggest(name, names, n_names);
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [output] fields: unknown field '%s'%s%s%s (known: %s)",
                         e ? e->file : "?", e ? e->line : 0, name, s ? "; did you mean '" : "", s ? s : "",
                         s ? "'?" : "", known);
    }
    *mask |= 1u << found;
    p = q;
  }
  return 0;
}

void sl_scene_output_path(const sl_scene *sc, const char *override, const char *scene_path, char *path, size_t cap) {
  const char *file = sc->output.file ? sc->output.file : "";
  if (override) {
    snprintf(path, cap, "%s", override);
  } else if (*file) {
    snprintf(path, cap, "%s", file);
  } else {
    const char *base = scene_path ? strrchr(scene_path, '/') : NULL;
    base = base ? base + 1 : scene_path ? scene_path : "sluice";
    const char *dot = strrchr(base, '.');
    snprintf(path, cap, "%.*s.h5", dot ? (int)(dot - base) : (int)strlen(base), base);
  }
}

/* ---- provenance ----------------------------------------------------------------------------------- */

int sl_scene_provenance_make(const sl_scene *sc, const char *sluice_version, sl_scene_provenance *p, sl_diag *d) {
  memset(p, 0, sizeof *p);
  if (!(p->ini_text = sl_ini_to_string(sc->ini))) return oom(d);
  p->pv.sluice_version = sluice_version ? sluice_version : "unknown";
  p->pv.ini_text = p->ini_text;
  p->pv.closures = p->closures;
  for (int r = 0; r < sc->schema->n_roles; ++r) {
    const sl_closure *cl = sc->closures[r];
    if (!cl) continue;
    const sl_closure_desc *c = cl->desc;
    char *buf = p->params[p->pv.n_closures];
    size_t at = 0, len = sizeof p->params[0];
    buf[0] = '\0';
    for (int k = 0; k < c->n_params && at < len; ++k) {
      char v[64];
      sl_params_format_value(c, cl->params, k, v, sizeof v);
      at += (size_t)snprintf(buf + at, len - at, "%s = %s\n", c->params[k].name, v);
    }
    p->closures[p->pv.n_closures++] = (sl_provenance_closure){
        sc->closure_sections[r], sl_kind_name(c->kind), c->name, c->version, cl->library->path, buf};
  }
  return 0;
}

void sl_scene_provenance_free(sl_scene_provenance *p) {
  free(p->ini_text);
  p->ini_text = NULL;
}

/* ---- continuation ---------------------------------------------------------------------------------- */

/* "section.key" into its parts. */
static int split_key(const char *key, char *section, size_t slen, char *name, size_t nlen) {
  const char *dot = strrchr(key, '.');
  if (!dot || dot == key || !dot[1] || (size_t)(dot - key) >= slen) return -1;
  snprintf(section, slen, "%.*s", (int)(dot - key), key);
  snprintf(name, nlen, "%s", dot + 1);
  return 0;
}

int sl_scene_get_real(const sl_scene *sc, const char *key, double *v, sl_diag *d) {
  char section[160], name[128];
  if (split_key(key, section, sizeof section, name, sizeof name))
    return sl_diag_set(d, SL_EBADINPUT, "'%s': expected section.key", key);
  if (strncmp(section, "closure.", 8) == 0) {
    const sl_closure *cl = sl_scene_closure(sc, section + 8);
    int k = cl ? sl_params_find(cl->desc, name) : -1;
    if (k < 0 || cl->desc->params[k].type != SL_PARAM_REAL)
      return sl_diag_set(d, SL_EBADINPUT, "'%s': %s", key,
                         !cl ? "the scene has no such closure" : "the closure has no real parameter of that name");
    char buf[64];
    sl_params_format_value(cl->desc, cl->params, k, buf, sizeof buf);
    if (!sl_ini_find(sc->ini, section, name))
      return sl_diag_set(d, SL_EBADINPUT, "'%s': the scene sets no [%s] %s", key, section, name);
    return sl_parse_real(buf, v) ? sl_diag_set(d, SL_EBADINPUT, "'%s': not a number (%s)", key, buf) : 0;
  }
  const sl_key *k = sl_schema_key(sc->schema, section, name);
  if (!k || k->type != SL_KEY_REAL || k->target == SL_IN_BOUNDARY)
    return sl_diag_set(d, SL_EBADINPUT, "'%s': not a real key of the model", key);
  if (!sl_ini_find(sc->ini, section, name))
    return sl_diag_set(d, SL_EBADINPUT, "'%s': the scene sets no [%s] %s", key, section, name);
  const char *base = k->target == SL_IN_SCENE ? (const char *)sc : (const char *)sc->config;
  *v = *(const double *)(base + k->offset);
  return 0;
}

int sl_scene_set_real(sl_scene *sc, const char *key, double v, sl_diag *d) {
  double old;
  int rc = sl_scene_get_real(sc, key, &old, d);
  if (rc) return rc;
  char assign[512], section[160], name[128];
  split_key(key, section, sizeof section, name, sizeof name);
  snprintf(assign, sizeof assign, "%s=%.17g", key, v);
  if ((rc = sl_ini_apply_override(sc->ini, assign, d))) return rc;
  if (strncmp(section, "closure.", 8) == 0) {
    int r = role_index(sc, section + 8);
    sl_closure *fresh = NULL;
    if ((rc = sl_closure_from_ini(sc->registry, sc->ini, section, &fresh, d))) return rc;
    sl_closure_destroy(sc->closures[r]);
    sc->closures[r] = fresh;
    return 0;
  }
  const sl_key *k = sl_schema_key(sc->schema, section, name);
  char *base = k->target == SL_IN_SCENE ? (char *)sc : (char *)sc->config;
  return sl_ini_get_real(sc->ini, section, name, 1, 0.0, k->min, k->max, (double *)(base + k->offset), d);
}

/* A model's bad-input message that names a section or key ("[boundary.top] velocity: ...", "[closure.drag]: ...")
 * but not where it is gets the file:line of that key, else of the section (the last one given). */
int sl_scene_locate(const sl_scene *sc, int rc, sl_diag *d) {
  const sl_ini *ini = sc->ini;
  if (rc != SL_EBADINPUT || d->msg[0] != '[') return rc;
  const char *close = strchr(d->msg, ']');
  if (!close || close - d->msg > 200) return rc;
  char section[256], key[128] = "";
  memcpy(section, d->msg + 1, (size_t)(close - d->msg - 1));
  section[close - d->msg - 1] = '\0';
  const char *k = close + 1;
  if (*k == ' ') {
    size_t n = 0;
    for (++k; (isalnum((unsigned char)k[n]) || k[n] == '_') && n + 1 < sizeof key; ++n) key[n] = k[n];
    key[n] = '\0';
  }
  const char *file = NULL;
  int line = 0;
  for (int i = 0; i < ini->n_sections; ++i) {
    const sl_ini_section *sec = &ini->sections[i];
    if (strcmp(sec->name, section) != 0) continue;
    if (!key[0] || !file) file = sec->file, line = sec->line;
    for (int e = 0; e < sec->n_entries && key[0]; ++e)
      if (strcmp(sec->entries[e].key, key) == 0) file = sec->entries[e].file, line = sec->entries[e].line;
  }
  if (!file) return rc;
  char msg[sizeof d->msg];
  memcpy(msg, d->msg, sizeof msg);
  return sl_diag_set(d, rc, "%s:%d: %.1900s", file, line, msg);
}
