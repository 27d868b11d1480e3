#include "core/scene/output.h"

#include <stdio.h>
#include <string.h>

#include "core/plugin/kinds.h"
#include "core/util/diag.h"

int sl_scene_output_path(const sl_ini *ini, const char *override, const char *scene_path, char *path, size_t cap,
                         sl_diag *d) {
  const char *file;
  int rc = sl_ini_get_string(ini, "output", "file", 0, "", &file, d);
  if (rc) return rc;
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
  return 0;
}

int sl_scene_output_fields(const sl_ini *ini, const char *const *names, int n_names, unsigned default_mask,
                           unsigned *mask, sl_diag *d) {
  const char *list;
  int rc = sl_ini_get_string(ini, "output", "fields", 0, "", &list, d);
  if (rc) return rc;
  *mask = *list ? 0 : default_mask;
  const sl_ini_entry *e = sl_ini_find(ini, "output", "fields");
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
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [output] fields: unknown field '%s'%s%s%s (known: %s)", e->file,
                         e->line, name, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "", known);
    }
    *mask |= 1u << found;
    p = q;
  }
  return 0;
}

sl_provenance_closure sl_scene_closure_provenance(const sl_closure *cl, const char *role, char *buf, size_t len) {
  const sl_closure_desc *c = cl->desc;
  size_t at = 0;
  if (len) buf[0] = '\0';
  for (int k = 0; k < c->n_params && at < len; ++k) {
    char v[64];
    sl_params_format_value(c, cl->params, k, v, sizeof v);
    at += (size_t)snprintf(buf + at, len - at, "%s = %s\n", c->params[k].name, v);
  }
  return (sl_provenance_closure){role, sl_kind_name(c->kind), c->name, c->version, cl->library->path, buf};
}
