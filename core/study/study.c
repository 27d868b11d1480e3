/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Reading and checking a study file (see study.h). */
#include "core/study/study.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plugin/closure_ini.h"

/* ---- helpers ------------------------------------------------------------------ */

static char *dup_str(const char *s, size_t n) {
  char *p = malloc(n + 1);
  if (!p) return NULL;
  memcpy(p, s, n);
  p[n] = '\0';
  return p;
}

static int oom(sl_diag *d) { return sl_diag_set(d, SL_ENOMEM, "bench: out of memory"); }

static int at_entry(sl_diag *d, const sl_ini_entry *e, const char *section, const char *why) {
  return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: [%s] %s: %s", e->file, e->line, e->col, section, e->key, why);
}

/* Splits a sweep's value into the runs' values: on '|' when it holds one
 * (the runs' values may then hold commas), else on ','. Blanks around each
 * value are dropped; an empty value is an error. */
static int split_values(const sl_ini_entry *e, const char *section, char **out, int cap, int *n, sl_diag *d) {
  const char *v = e->value;
  char sep = strchr(v, '|') ? '|' : ',';
  *n = 0;
  for (const char *p = v;;) {
    const char *q = strchr(p, sep);
    const char *end = q ? q : p + strlen(p);
    const char *a = p, *b = end;
    while (a < b && (*a == ' ' || *a == '\t')) ++a;
    while (b > a && (b[-1] == ' ' || b[-1] == '\t')) --b;
    if (a == b) {
      char why[160];
      snprintf(why, sizeof why, "value %d is empty (values are separated by '%c')", *n + 1, sep);
      return at_entry(d, e, section, why);
    }
    if (*n == cap) {
      char why[96];
      snprintf(why, sizeof why, "more than %d values", cap);
      return at_entry(d, e, section, why);
    }
    if (!(out[(*n)++] = dup_str(a, (size_t)(b - a)))) return oom(d);
    if (!q) break;
    p = q + 1;
  }
  return 0;
}

static int is_prefix(const char *s, const char *prefix) { return strncmp(s, prefix, strlen(prefix)) == 0; }

/* ---- the sweeps ------------------------------------------------------------------ */

typedef struct group {
  const char *prefix; /* "set.", "points.", "variants." */
  sl_study_key *keys;
  int *n_keys;
  int sweep; /* values are lists */
} group;

static int collect(sl_study *s, const group *g, sl_diag *d) {
  for (int i = 0; i < s->ini->n_sections; ++i) {
    const sl_ini_section *sec = &s->ini->sections[i];
    if (!is_prefix(sec->name, g->prefix)) continue;
    for (int j = 0; j < sec->n_entries; ++j) {
      const sl_ini_entry *e = &sec->entries[j];
      if (*g->n_keys == SL_STUDY_MAX_KEYS)
        return at_entry(d, e, sec->name, "too many keys in one kind of section (at most 32)");
      sl_study_key *k = &g->keys[(*g->n_keys)++];
      k->section = sec->name + strlen(g->prefix), k->key = e->key, k->where = e;
      int rc;
      if (g->sweep) {
        if ((rc = split_values(e, sec->name, k->values, SL_STUDY_MAX_VALUES, &k->n_values, d))) return rc;
      } else {
        k->n_values = 1;
        if (!(k->values[0] = dup_str(e->value, strlen(e->value)))) return oom(d);
      }
    }
  }
  return 0;
}

/* The keys of one sweep change together: they need as many values. */
static int sweep_length(const sl_study_key *keys, int n_keys, int *n, sl_diag *d) {
  *n = 1;
  for (int k = 0; k < n_keys; ++k) {
    if (k == 0) {
      *n = keys[0].n_values;
      continue;
    }
    if (keys[k].n_values != *n) {
      const sl_ini_entry *e = keys[k].where;
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d:%d: %s.%s: %d values, but %s.%s (line %d) has %d: the keys of one sweep change "
                         "together, value by value",
                         e->file, e->line, e->col, keys[k].section, keys[k].key, keys[k].n_values, keys[0].section,
                         keys[0].key, keys[0].where->line, *n);
    }
  }
  return 0;
}

/* A scene key set or swept twice. */
static int check_unique(const sl_study *s, sl_diag *d) {
  const sl_study_key *all[3 * SL_STUDY_MAX_KEYS];
  int n = 0;
  for (int k = 0; k < s->n_fixed; ++k) all[n++] = &s->fixed[k];
  for (int k = 0; k < s->n_point_keys; ++k) all[n++] = &s->points[k];
  for (int k = 0; k < s->n_variant_keys; ++k) all[n++] = &s->variants[k];
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < a; ++b)
      if (!strcmp(all[a]->section, all[b]->section) && !strcmp(all[a]->key, all[b]->key)) {
        const sl_ini_entry *e = all[a]->where;
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: %s.%s is also given at line %d: set or sweep a key once",
                           e->file, e->line, e->col, all[a]->section, all[a]->key, all[b]->where->line);
      }
  return 0;
}

void sl_study_describe(const sl_study_key *keys, int n_keys, int index, char *buf, size_t len) {
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < n_keys && used < len; ++k) {
    int w = snprintf(buf + used, len - used, "%s%s = %s", k ? ", " : "", keys[k].key, keys[k].values[index]);
    if (w < 0) break;
    used += (size_t)w;
  }
}

static int names(sl_study *s, const char *section, const sl_study_key *keys, int n_keys, int n, char **out,
                 sl_diag *d) {
  const sl_ini_entry *e = sl_ini_find(s->ini, section, "names");
  if (e) {
    if (!n_keys) {
      char why[160];
      snprintf(why, sizeof why, "there is no sweep to name: add a [%s.<section>] key = v1, v2, ...", section);
      return at_entry(d, e, section, why);
    }
    int m = 0, rc = split_values(e, section, out, SL_STUDY_MAX_VALUES, &m, d);
    if (rc) return rc;
    if (m != n) {
      char why[160];
      snprintf(why, sizeof why, "%d names for %d values of the sweep", m, n);
      return at_entry(d, e, section, why);
    }
    return 0;
  }
  for (int i = 0; i < n; ++i) {
    char buf[512];
    if (n_keys) sl_study_describe(keys, n_keys, i, buf, sizeof buf);
    else snprintf(buf, sizeof buf, "%s", !strcmp(section, "variants") ? "scene" : "run");
    if (!(out[i] = dup_str(buf, strlen(buf)))) return oom(d);
  }
  return 0;
}

/* ---- [measure] ------------------------------------------------------------------ */

static int parse_numbers(const char *s, double *v, int cap) {
  int n = 0;
  char buf[256];
  if (strlen(s) >= sizeof buf) return -1;
  snprintf(buf, sizeof buf, "%s", s);
  for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    while (*tok == ' ' || *tok == '\t') ++tok;
    char *end = tok + strlen(tok);
    while (end > tok && (end[-1] == ' ' || end[-1] == '\t')) *--end = '\0';
    if (n == cap || sl_parse_real(tok, &v[n])) return -1;
    ++n;
  }
  return n;
}

/* "x0:x1" (1-D) or "x0,y0:x1,y1" (2-D), as `sluice sample --line`. */
static int parse_line(const char *s, double line[4], int *dim) {
  const char *colon = strchr(s, ':');
  if (!colon || strchr(colon + 1, ':') || (size_t)(colon - s) >= 128) return -1;
  char a[128];
  snprintf(a, sizeof a, "%.*s", (int)(colon - s), s);
  double p[2], q[2];
  int na = parse_numbers(a, p, 2), nb = parse_numbers(colon + 1, q, 2);
  if (na < 1 || na != nb) return -1;
  *dim = na;
  line[0] = p[0], line[1] = na == 2 ? p[1] : 0.0, line[2] = q[0], line[3] = na == 2 ? q[1] : 0.0;
  return line[0] == line[2] && line[1] == line[3] ? -1 : 0;
}

/* A reference CSV: rows "position or time, value" (more columns are
 * ignored); blank lines and '#' comments skipped; a first row that is not
 * numbers is a header. */
static int read_reference(sl_study_measure *m, const sl_ini_entry *e, sl_diag *d) {
  FILE *f = fopen(m->reference, "r");
  if (!f)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: [measure] reference = %s: cannot open %s: %s", e->file, e->line,
                       e->col, e->value, m->reference, strerror(errno));
  char line[4096];
  int lineno = 0, cap = 0, rows_seen = 0, rc = 0;
  while (fgets(line, sizeof line, f)) {
    ++lineno;
    line[strcspn(line, "\r\n")] = '\0';
    char *p = line;
    while (*p == ' ' || *p == '\t') ++p;
    if (!*p || *p == '#') continue;
    char *c1 = strchr(p, ','), *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
    if (c2) *c2 = '\0';
    double v[2];
    if (parse_numbers(p, v, 2) != 2) {
      if (rows_seen++ == 0) continue; /* the header */
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: expected two numbers 'position or time, value', found '%.80s'",
                       m->reference, lineno, p);
      break;
    }
    ++rows_seen;
    if (m->n_ref == cap) {
      cap = cap ? 2 * cap : 64;
      double *nx = realloc(m->ref_x, (size_t)cap * sizeof *nx);
      if (nx) m->ref_x = nx;
      double *nv = realloc(m->ref_v, (size_t)cap * sizeof *nv);
      if (nv) m->ref_v = nv;
      if (!nx || !nv) {
        rc = oom(d);
        break;
      }
    }
    m->ref_x[m->n_ref] = v[0], m->ref_v[m->n_ref] = v[1];
    if (m->n_ref > 0 && !(v[0] > m->ref_x[m->n_ref - 1])) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: the first column must increase (%g after %g)", m->reference, lineno,
                       v[0], m->ref_x[m->n_ref - 1]);
      break;
    }
    ++m->n_ref;
  }
  if (!rc && ferror(f)) rc = sl_diag_set(d, SL_EBADINPUT, "%s: read error", m->reference);
  fclose(f);
  if (!rc && m->n_ref == 0) rc = sl_diag_set(d, SL_EBADINPUT, "%s: no data rows", m->reference);
  return rc;
}

static const char *const measure_keys[] = {"field", "scalar",    "component", "time",   "line", "n",    "reduce",
                                           "exact", "reference", "value",     "finest", "norm", "label"};

/* An entry that must not be there, with why. */
static int refuse(const sl_ini *ini, const char *key, const char *why, sl_diag *d) {
  const sl_ini_entry *e = sl_ini_find(ini, "measure", key);
  if (!e) return 0;
  return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: [measure] %s: %s", e->file, e->line, e->col, key, why);
}

static int read_measure(sl_study *s, sl_diag *d) {
  const sl_ini *ini = s->ini;
  sl_study_measure *m = &s->m;
  m->where = sl_ini_find_section(ini, "measure");
  if (!m->where)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: no [measure] section: say what is measured (field = NAME or scalar = NAME, "
                       "and against what: exact, reference, value, finest, or nothing for a comparison)",
                       s->path);
  int rc = sl_ini_check_keys(ini, "measure", measure_keys, (int)(sizeof measure_keys / sizeof measure_keys[0]), d);
  if (rc) return rc;
  /* against what: at most one */
  static const char *const against[] = {"exact", "reference", "value", "finest"};
  const sl_ini_entry *first = NULL;
  for (int k = 0; k < 4; ++k) {
    const sl_ini_entry *e = sl_ini_find(ini, "measure", against[k]);
    if (!e) continue;
    if (k == 3) {
      int on = 0;
      if ((rc = sl_ini_get_bool(ini, "measure", "finest", 0, 0, &on, d))) return rc;
      if (!on) continue;
    }
    if (first)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d:%d: [measure] %s: the error is measured against one thing, and '%s' (line %d) is "
                         "given too",
                         e->file, e->line, e->col, e->key, first->key, first->line);
    first = e;
    m->against = (sl_study_against)(SL_AGAINST_EXACT + k);
  }
  if (m->against == SL_AGAINST_EXACT) {
    enum { KYNCH, BINGHAM, FLUIDIZED_BED };
    static const char *const exact_names[] = {"kynch", "bingham", "fluidized_bed"};
    static const char *const exact_fields[] = {"the cell averages of phi", "velocity component 2, the axial velocity",
                                               "phi in the cells of the bed below its top"};
    int which = 0;
    if ((rc = sl_ini_get_choice(ini, "measure", "exact", 1, 0, "kynch|bingham|fluidized_bed", &which, d))) return rc;
    m->exact = exact_names[which];
    static const char *const fixed_by_exact[] = {"field", "scalar", "component", "reduce"};
    char why[200];
    for (int k = 0; k < 4; ++k) {
      snprintf(why, sizeof why, "exact = %s measures its own field (%s); drop '%s'", m->exact, exact_fields[which],
               fixed_by_exact[k]);
      if ((rc = refuse(ini, fixed_by_exact[k], why, d))) return rc;
    }
    static const char *const by_cells[] = {"line", "n"};
    for (int k = 0; k < 2 && which != BINGHAM; ++k) {
      snprintf(why, sizeof why, "exact = %s compares %s%s; drop '%s'", m->exact, exact_fields[which],
               which == KYNCH ? " over the whole column" : "", by_cells[k]);
      if ((rc = refuse(ini, by_cells[k], why, d))) return rc;
    }
    m->name = which == BINGHAM ? "velocity" : "phi";
    m->component = which == BINGHAM ? 2 : 0;
  } else {
    const sl_ini_entry *f = sl_ini_find(ini, "measure", "field"), *sc = sl_ini_find(ini, "measure", "scalar");
    if (f && sc)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: [measure] scalar: give either field (line %d) or scalar, not both",
                         sc->file, sc->line, sc->col, f->line);
    if (!f && !sc)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [measure]: say what is measured: field = NAME (sampled along line = "
                         "x0,y0:x1,y1) or scalar = NAME (an output scalar such as interface_height_0)",
                         m->where->file, m->where->line);
    m->scalar = sc != NULL;
    if ((rc = sl_ini_get_string(ini, "measure", m->scalar ? "scalar" : "field", 1, NULL, &m->name, d))) return rc;
    if (m->scalar) {
      static const char *const field_only[] = {"component", "line", "n", "reduce"};
      for (int k = 0; k < 4; ++k)
        if ((rc = refuse(ini, field_only[k], "applies to a field, not to a scalar", d))) return rc;
    }
    long comp = 0;
    if ((rc = sl_ini_get_int(ini, "measure", "component", 0, 0, 0, 2, &comp, d))) return rc;
    m->component = (int)comp;
    int red = 0;
    if ((rc = sl_ini_get_choice(ini, "measure", "reduce", 0, 0, "none|min|max", &red, d))) return rc;
    m->reduce = (sl_study_reduce)red;
  }
  const char *line = NULL;
  if ((rc = sl_ini_get_string(ini, "measure", "line", 0, NULL, &line, d))) return rc;
  if (line) {
    const sl_ini_entry *e = sl_ini_find(ini, "measure", "line");
    if (parse_line(line, m->line, &m->line_dim))
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d:%d: [measure] line = %s: expected x0,y0:x1,y1 (2-D) or x0:x1 (1-D), "
                         "two different points",
                         e->file, e->line, e->value_col, line);
    m->has_line = 1;
  }
  long n = 201;
  if ((rc = sl_ini_get_int(ini, "measure", "n", 0, 201, 2, 100000, &n, d))) return rc;
  m->n = (int)n;
  m->has_time = sl_ini_find(ini, "measure", "time") != NULL;
  if ((rc = sl_ini_get_real(ini, "measure", "time", 0, 0.0, -1e300, 1e300, &m->time, d))) return rc;
  int norm = 1;
  m->has_norm = sl_ini_find(ini, "measure", "norm") != NULL;
  if ((rc = sl_ini_get_choice(ini, "measure", "norm", 0, 1, "l1|l2|max", &norm, d))) return rc;
  m->norm = (sl_study_norm)norm;
  if ((rc = sl_ini_get_string(ini, "measure", "label", 0, NULL, &m->label, d))) return rc;

  /* what needs what */
  int one_number = m->scalar ? m->against != SL_AGAINST_REFERENCE : m->reduce != SL_REDUCE_NONE;
  if (m->reduce != SL_REDUCE_NONE && !m->has_line)
    return refuse(ini, "reduce", "the minimum or maximum is taken along a line: give line = x0,y0:x1,y1", d);
  if (m->against == SL_AGAINST_VALUE) {
    if (!one_number)
      return refuse(ini, "value", "compares one number: give scalar = NAME, or a field with reduce = min or max", d);
    if ((rc = sl_ini_get_real(ini, "measure", "value", 1, 0.0, -1e300, 1e300, &m->value, d))) return rc;
  }
  if (m->against == SL_AGAINST_REFERENCE) {
    const char *ref = NULL;
    if ((rc = sl_ini_get_string(ini, "measure", "reference", 1, NULL, &ref, d))) return rc;
    if ((rc = refuse(ini, "reduce", "a reference file holds a profile; compare one number with value = X", d)))
      return rc;
    if (m->scalar && (rc = refuse(ini, "time", "the reference file's first column gives the times", d))) return rc;
    if (!m->scalar && !m->has_line)
      return refuse(ini, "reference", "the reference's positions are along a line: give line = x0,y0:x1,y1 (or x0:x1)",
                    d);
    if (!(m->reference = sl_ini_path_relative(s->path, ref))) return oom(d);
    if ((rc = read_reference(m, sl_ini_find(ini, "measure", "reference"), d))) return rc;
  }
  if (m->has_norm && one_number)
    return refuse(ini, "norm", "the measure is one number: there is no profile to take a norm of", d);
  if (m->against == SL_AGAINST_FINEST && s->n_points < 2)
    return refuse(ini, "finest", "needs a points sweep of two or more values ([points.<section>] key = v1, v2, ...)",
                  d);
  return 0;
}

/* ---- loading ------------------------------------------------------------------ */

int sl_study_load(const char *path, sl_study **out, sl_diag *d) {
  *out = NULL;
  sl_study *s = calloc(1, sizeof *s);
  if (!s) return oom(d);
  int rc = sl_ini_parse_file(path, &s->ini, d);
  if (rc) goto fail;
  if (!(s->path = dup_str(path, strlen(path)))) {
    rc = oom(d);
    goto fail;
  }
  const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
  size_t bl = strlen(base);
  if (bl > 4 && !strcmp(base + bl - 4, ".ini")) bl -= 4;
  if (!(s->name = dup_str(base, bl))) {
    rc = oom(d);
    goto fail;
  }
  static const char *const sections[] = {"study", "measure", "points", "variants"};
  static const char *const prefixes[] = {"set.", "points.", "variants."};
  if ((rc = sl_ini_check_sections(s->ini, sections, 4, prefixes, 3, d))) goto fail;
  static const char *const study_keys[] = {"scene", "title", "timeout"};
  static const char *const sweep_keys[] = {"names"};
  if ((rc = sl_ini_check_keys(s->ini, "study", study_keys, 3, d))) goto fail;
  if ((rc = sl_ini_check_keys(s->ini, "points", sweep_keys, 1, d))) goto fail;
  if ((rc = sl_ini_check_keys(s->ini, "variants", sweep_keys, 1, d))) goto fail;
  if (!sl_ini_find_section(s->ini, "study")) {
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no [study] section: name the scene with [study] scene = FILE.ini", path);
    goto fail;
  }
  const char *scene;
  if ((rc = sl_ini_get_string(s->ini, "study", "scene", 1, NULL, &scene, d))) goto fail;
  s->scene_entry = sl_ini_find(s->ini, "study", "scene");
  if (!(s->scene = sl_ini_path_relative(s->scene_entry->file, scene))) {
    rc = oom(d);
    goto fail;
  }
  if ((rc = sl_ini_get_string(s->ini, "study", "title", 0, NULL, &s->title, d))) goto fail;
  if ((rc = sl_ini_get_real(s->ini, "study", "timeout", 0, 600.0, 1.0, 1e7, &s->timeout, d))) goto fail;

  const group groups[3] = {{"set.", s->fixed, &s->n_fixed, 0},
                           {"points.", s->points, &s->n_point_keys, 1},
                           {"variants.", s->variants, &s->n_variant_keys, 1}};
  for (int g = 0; g < 3; ++g)
    if ((rc = collect(s, &groups[g], d))) goto fail;
  if ((rc = check_unique(s, d))) goto fail;
  if ((rc = sweep_length(s->points, s->n_point_keys, &s->n_points, d))) goto fail;
  if ((rc = sweep_length(s->variants, s->n_variant_keys, &s->n_variants, d))) goto fail;
  if ((rc = names(s, "points", s->points, s->n_point_keys, s->n_points, s->point_names, d))) goto fail;
  if ((rc = names(s, "variants", s->variants, s->n_variant_keys, s->n_variants, s->variant_names, d))) goto fail;
  for (int p = 0; p < s->n_points; ++p) {
    double v[2];
    s->point_x[p] = NAN;
    if (s->n_point_keys && parse_numbers(s->points[0].values[p], v, 2) >= 1) s->point_x[p] = v[0];
  }
  if ((rc = read_measure(s, d))) goto fail;
  *out = s;
  return 0;
fail:
  sl_study_free(s);
  return rc;
}

void sl_study_free(sl_study *s) {
  if (!s) return;
  sl_study_key *groups[3] = {s->fixed, s->points, s->variants};
  int counts[3] = {s->n_fixed, s->n_point_keys, s->n_variant_keys};
  for (int g = 0; g < 3; ++g)
    for (int k = 0; k < counts[g]; ++k)
      for (int i = 0; i < groups[g][k].n_values; ++i) free(groups[g][k].values[i]);
  for (int i = 0; i < SL_STUDY_MAX_VALUES; ++i) free(s->point_names[i]), free(s->variant_names[i]);
  free(s->m.reference);
  free(s->m.ref_x);
  free(s->m.ref_v);
  free(s->scene);
  free(s->name);
  free(s->path);
  sl_ini_free(s->ini);
  free(s);
}

/* ---- one run's configuration -------------------------------------------------------- */

static sl_ini_section *find_section(sl_ini *ini, const char *name) {
  for (int i = 0; i < ini->n_sections; ++i)
    if (!strcmp(ini->sections[i].name, name)) return &ini->sections[i];
  return NULL;
}

static int apply(sl_ini *ini, const sl_study_key *k, const char *value, sl_diag *d) {
  if (!strcmp(k->key, "model")) sl_closure_ini_replace_model(ini, k->section, value);
  int had_section = find_section(ini, k->section) != NULL;
  size_t len = strlen(k->section) + strlen(k->key) + strlen(value) + 3;
  char *a = malloc(len);
  if (!a) return oom(d);
  snprintf(a, len, "%s.%s=%s", k->section, k->key, value);
  int rc = sl_ini_apply_override(ini, a, d);
  free(a);
  const sl_ini_entry *w = k->where;
  if (rc) return sl_diag_prefix(d, rc, "%s:%d:%d: %s.%s", w->file, w->line, w->col, k->section, k->key);
  /* messages about this key name the study's line, not the command line */
  sl_ini_section *sec = find_section(ini, k->section);
  if (sec && !had_section) sec->file = w->file, sec->line = w->line;
  sl_ini_entry *e = sl_ini_find(ini, k->section, k->key);
  if (e) e->file = w->file, e->line = w->line, e->col = w->col, e->value_col = w->value_col;
  return 0;
}

int sl_study_run_ini(const sl_study *s, int variant, int point, sl_ini **out, sl_diag *d) {
  sl_ini *ini = NULL;
  int rc = sl_ini_parse_file(s->scene, &ini, d);
  if (rc) {
    const sl_ini_entry *e = s->scene_entry;
    return sl_diag_prefix(d, rc, "%s:%d:%d: [study] scene = %s", e->file, e->line, e->value_col, e->value);
  }
  const sl_study_key *groups[3] = {s->fixed, s->points, s->variants};
  int counts[3] = {s->n_fixed, s->n_point_keys, s->n_variant_keys}, index[3] = {0, point, variant};
  /* closure models first: a model change drops the old closure's parameters, not the study's */
  for (int pass = 0; pass < 2 && !rc; ++pass)
    for (int g = 0; g < 3 && !rc; ++g)
      for (int k = 0; k < counts[g] && !rc; ++k) {
        const sl_study_key *key = &groups[g][k];
        int is_model = is_prefix(key->section, "closure.") && !strcmp(key->key, "model");
        if (is_model == (pass == 0)) rc = apply(ini, key, key->values[index[g]], d);
      }
  if (rc) {
    sl_ini_free(ini);
    return rc;
  }
  *out = ini;
  return 0;
}
