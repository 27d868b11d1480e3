/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/closure_ini.h"

#include <stdlib.h>
#include <string.h>

#include "core/config/parameters.h"
#include "core/plugin/kinds.h"

int sl_closure_section_kind(const char *section, sl_kind *kind, sl_diag *d) {
  if (strncmp(section, "closure.", 8) != 0)
    return sl_diag_set(d, SL_EBADINPUT, "[%s] is not a closure section", section);
  char name[128];
  snprintf(name, sizeof name, "%s", section + 8);
  char *dot = strchr(name, '.');
  if (dot) *dot = '\0';
  return sl_kind_from_name(name, kind, d);
}

static int located(sl_diag *d, int rc, const sl_ini_entry *e) {
  if (e && e->file) return sl_diag_prefix(d, rc, "%s:%d:%d: error", e->file, e->line, e->col);
  return rc;
}

/* The closure a section names and its validated parameters (*params owned
 * by the caller). */
static int resolve(const sl_registry *r, const sl_ini *ini, const char *section, const sl_closure_entry **out,
                   void **out_params, sl_diag *d) {
  *out = NULL;
  *out_params = NULL;
  const sl_ini_section *sec = sl_ini_find_section(ini, section);
  if (!sec) return sl_diag_set(d, SL_EBADINPUT, "the scene has no [%s] section", section);
  sl_kind kind;
  int rc = sl_closure_section_kind(section, &kind, d);
  if (rc) return sl_diag_prefix(d, rc, "%s:%d: error", sec->file, sec->line);
  const char *model = NULL, *library = NULL;
  if ((rc = sl_ini_get_string(ini, section, "model", 1, NULL, &model, d))) return rc;
  if ((rc = sl_ini_get_string(ini, section, "library", 0, NULL, &library, d))) return rc;
  const sl_closure_entry *entry;
  rc = sl_registry_find(r, kind, model, library, &entry, d);
  if (rc) return located(d, rc, sl_ini_find(ini, section, "model"));
  void *params;
  if ((rc = sl_params_new(entry->desc, &params, d))) return rc;
  for (int i = 0; i < sec->n_entries; ++i) {
    sl_ini_entry *e = &sec->entries[i];
    if (strcmp(e->key, "model") == 0 || strcmp(e->key, "library") == 0) continue;
    rc = sl_params_set_with(entry->desc, params, e->key, e->value, sl_ini_constants(ini), d);
    if (rc) {
      sl_params_free(params);
      return located(d, rc, e);
    }
    e->used = 1;
  }
  *out = entry;
  *out_params = params;
  return 0;
}

int sl_closure_from_ini(const sl_registry *r, const sl_ini *ini, const char *section, sl_closure **out, sl_diag *d) {
  *out = NULL;
  const sl_closure_entry *entry;
  void *params;
  int rc = resolve(r, ini, section, &entry, &params, d);
  if (rc) return rc;
  rc = sl_closure_create(entry, params, out, d);
  if (rc) return located(d, rc, sl_ini_find(ini, section, "model"));
  snprintf((*out)->role, sizeof(*out)->role, "%s", section);
  return 0;
}

int sl_closure_check_ini(const sl_registry *r, const sl_ini *ini, const char *section, sl_diag *d) {
  const sl_closure_entry *entry;
  void *params;
  int rc = resolve(r, ini, section, &entry, &params, d);
  sl_params_free(params);
  return rc;
}

static int keep_for_new_model(const sl_ini_entry *e, void *ctx) {
  (void)ctx;
  return !strcmp(e->key, "model") || sl_ini_entry_from_command_line(e);
}

void sl_closure_ini_replace_model(sl_ini *ini, const char *section, const char *model) {
  if (strncmp(section, "closure.", 8) != 0) return;
  const sl_ini_entry *old = sl_ini_find(ini, section, "model");
  if (!old || !strcmp(old->value, model)) return;
  sl_ini_drop_entries(ini, section, keep_for_new_model, NULL);
}

int sl_closure_ini_apply_override(sl_ini *ini, const char *assignment, sl_diag *d) {
  /* section.key=value, the key after the last dot (as sl_ini_apply_override reads it) */
  const char *eq = assignment ? strchr(assignment, '=') : NULL;
  if (eq) {
    const char *ls = assignment, *le = eq, *vs = eq + 1;
    while (ls < le && (*ls == ' ' || *ls == '\t')) ++ls;
    while (le > ls && (le[-1] == ' ' || le[-1] == '\t')) --le;
    while (*vs == ' ' || *vs == '\t') ++vs;
    size_t vlen = strlen(vs);
    while (vlen && (vs[vlen - 1] == ' ' || vs[vlen - 1] == '\t')) --vlen;
    const char *dot = NULL;
    for (const char *q = ls; q < le; ++q)
      if (*q == '.') dot = q;
    char section[256], model[256];
    if (dot && le - dot - 1 == 5 && !memcmp(dot + 1, "model", 5) && (size_t)(dot - ls) < sizeof section &&
        vlen < sizeof model && (vlen == 0 || vs[0] != '"')) {
      memcpy(section, ls, (size_t)(dot - ls));
      section[dot - ls] = '\0';
      memcpy(model, vs, vlen);
      model[vlen] = '\0';
      sl_closure_ini_replace_model(ini, section, model);
    }
  }
  return sl_ini_apply_override(ini, assignment, d);
}

int sl_plugin_dirs_allowed(const sl_ini *ini, int allow, sl_diag *d) {
  const sl_ini_entry *e = sl_ini_find(ini, "plugins", "path");
  if (!e || allow) return 0;
  return sl_diag_set(d, SL_EBADINPUT,
                     "%s:%d: error: [plugins] path = %s: a scene may not make sluice load closure libraries from a "
                     "folder it names (their code would run with your rights); closures are loaded from the plugin "
                     "path (SLUICE_PLUGIN_PATH and sluice's own folder). If you trust the libraries in that folder, "
                     "run with --allow-plugin-path",
                     e->file ? e->file : "scene", e->line, e->value);
}

int sl_plugin_dirs_from_ini(const sl_ini *ini, char ***dirs, int *n, sl_diag *d) {
  *dirs = NULL;
  *n = 0;
  sl_ini_entry *e = sl_ini_find(ini, "plugins", "path");
  if (!e) return 0;
  e->used = 1;
  int cap = 1;
  for (const char *c = e->value; *c; ++c) cap += *c == ',';
  char **out = calloc((size_t)cap, sizeof *out);
  if (!out) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  /* Relative folders are taken from the folder of the file that names them. */
  const char *slash = e->file ? strrchr(e->file, '/') : NULL;
  int base_len = slash ? (int)(slash - e->file) : 0;
  int k = 0;
  for (const char *t = e->value; *t && k < cap;) {
    while (*t == ' ' || *t == '\t' || *t == ',') ++t;
    size_t len = strcspn(t, ",");
    while (len > 0 && (t[len - 1] == ' ' || t[len - 1] == '\t')) --len;
    if (len > 0) {
      size_t sz = len + (size_t)base_len + 2;
      if (!(out[k] = malloc(sz))) {
        sl_plugin_dirs_free(out, k);
        return sl_diag_set(d, SL_ENOMEM, "out of memory");
      }
      if (t[0] == '/' || base_len == 0) snprintf(out[k], sz, "%.*s", (int)len, t);
      else snprintf(out[k], sz, "%.*s/%.*s", base_len, e->file, (int)len, t);
      ++k;
    }
    t += strcspn(t, ",");
  }
  *dirs = out;
  *n = k;
  return 0;
}

void sl_plugin_dirs_free(char **dirs, int n) {
  for (int i = 0; i < n; ++i) free(dirs[i]);
  free(dirs);
}
