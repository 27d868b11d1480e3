/* SPDX-License-Identifier: GPL-2.0-or-later */
/* [parameters]: a scene's named constants (parameters.h). */
#include "core/config/parameters.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sl_ini_params {
  char store[SL_EXPR_MAX_CONSTANTS][64]; /* the names (the INI's entries may be edited later) */
  const char *names[SL_EXPR_MAX_CONSTANTS];
  double values[SL_EXPR_MAX_CONSTANTS];
  sl_expr_constants k;
};

static const char *const reserved[] = {"x", "y", "t", "case"};

static int is_identifier(const char *s) {
  if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || *s == '_')) return 0;
  for (++s; *s; ++s)
    if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || (*s >= '0' && *s <= '9') || *s == '_')) return 0;
  return 1;
}

void sl_ini_params_free(struct sl_ini_params *p) { free(p); }

const sl_expr_constants *sl_ini_constants(const sl_ini *ini) {
  return ini && ini->params && ini->params->k.n > 0 ? &ini->params->k : NULL;
}

int sl_ini_parameters(sl_ini *ini, sl_diag *d) {
  sl_ini_params_free(ini->params);
  ini->params = NULL;
  const sl_ini_section *sec = sl_ini_find_section(ini, "parameters");
  if (!sec || sec->n_entries == 0) return 0;
  struct sl_ini_params *p = calloc(1, sizeof *p);
  if (!p) return sl_diag_set(d, SL_ENOMEM, "[parameters]: out of memory");
  p->k.names = p->names, p->k.values = p->values;
  int rc = 0;
  for (int i = 0; i < sec->n_entries && !rc; ++i) {
    sl_ini_entry *e = &sec->entries[i];
    const char *name = e->key;
    int bad = !is_identifier(name) || sl_expr_is_builtin(name) || strlen(name) >= sizeof p->store[0];
    for (size_t r = 0; r < sizeof reserved / sizeof reserved[0]; ++r) bad = bad || strcmp(name, reserved[r]) == 0;
    if (bad) {
      rc = sl_diag_set(
          d, SL_EBADINPUT,
          "%s:%d:%d: [parameters] %s: a parameter's name is an identifier (letters, digits, _; at most 63) that is "
          "not built in (pi, e, sin, ...) nor a variable (x, y, t, case)",
          e->file, e->line, e->col, name);
      break;
    }
    for (int j = 0; j < p->k.n && !rc; ++j)
      if (strcmp(p->names[j], name) == 0)
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: [parameters] %s is given twice", e->file, e->line, e->col, name);
    if (rc) break;
    if (p->k.n == SL_EXPR_MAX_CONSTANTS) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [parameters]: more than %d parameters", e->file, e->line,
                       SL_EXPR_MAX_CONSTANTS);
      break;
    }
    double v;
    char why[300];
    if (sl_parse_real_expr_with(e->value, &p->k, &v, why, sizeof why)) {
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d:%d: [parameters] %s = '%s': expected a number or a constant expression of the "
                       "parameters above it%s%s",
                       e->file, e->line, e->col, name, e->value, why[0] ? ": " : "", why);
      break;
    }
    e->used = 1;
    memcpy(p->store[p->k.n], name, strlen(name) + 1);
    p->names[p->k.n] = p->store[p->k.n], p->values[p->k.n] = v;
    ++p->k.n;
  }
  if (rc) {
    free(p);
    return rc;
  }
  ini->params = p;
  return 0;
}
