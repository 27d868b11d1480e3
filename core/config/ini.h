/* SPDX-License-Identifier: GPL-2.0-or-later */
/* In-house INI parser: sections, typed look-up, overrides, unknown-key errors.
 *
 * Syntax: `[section]` and dotted `[closure.drag]` headers; `key = value`;
 * comments with ';' or '#', whole-line or trailing (outside quotes); quoted
 * strings "..." with \" and \\ escapes; comma lists; `include = other.ini`
 * (relative to the including file) pulls in another file whose keys the
 * including file may override. Every diagnostic names file:line:column. */
#ifndef SLUICE_CONFIG_INI_H
#define SLUICE_CONFIG_INI_H

#include <stddef.h>
#include <stdio.h>

#include "core/util/diag.h"

typedef struct sl_ini_entry {
  char *key;
  char *value;      /* unquoted, escapes resolved, trailing comment stripped */
  int quoted;       /* the value was a quoted string */
  const char *file; /* owned by the sl_ini */
  int line, col;    /* position of the key (col of value in value_col) */
  int value_col;
  int used; /* set by the typed getters */
} sl_ini_entry;

typedef struct sl_ini_section {
  char *name;
  const char *file;
  int line;
  int n_entries, cap_entries;
  sl_ini_entry *entries;
} sl_ini_section;

typedef struct sl_ini {
  int n_sections, cap_sections;
  sl_ini_section *sections;
  int n_files, cap_files;
  char **files;                 /* every file read, for diagnostics and provenance */
  struct sl_ini_params *params; /* [parameters] once resolved (parameters.h), else NULL */
} sl_ini;

/* Parse a file (and its includes). Returns 0 or SL_EBADINPUT with d set. */
int sl_ini_parse_file(const char *path, sl_ini **out, sl_diag *d);
/* Parse text held in memory; `name` is used in diagnostics and as the base
 * for relative includes. */
int sl_ini_parse_string(const char *text, size_t len, const char *name, sl_ini **out, sl_diag *d);
void sl_ini_free(sl_ini *ini);

/* `section.key=value`, e.g. "closure.drag.model=ergun": the key is the text
 * after the last dot. Creates the section or key when absent. */
int sl_ini_apply_override(sl_ini *ini, const char *assignment, sl_diag *d);

const sl_ini_section *sl_ini_find_section(const sl_ini *ini, const char *section);
sl_ini_entry *sl_ini_find(const sl_ini *ini, const char *section, const char *key);

/* The entry was given by sl_ini_apply_override, not read from a file. */
int sl_ini_entry_from_command_line(const sl_ini_entry *e);

/* Removes the entries of `section` for which keep(entry, ctx) is 0. */
void sl_ini_drop_entries(sl_ini *ini, const char *section, int (*keep)(const sl_ini_entry *, void *), void *ctx);

/* Typed getters. A missing key gives `def` when required == 0, an error when
 * required != 0. Values outside [min, max] are errors naming the range. Each
 * marks the entry used. Return 0 or SL_EBADINPUT. */
int sl_ini_get_real(const sl_ini *ini, const char *section, const char *key, int required, double def, double min,
                    double max, double *out, sl_diag *d);
int sl_ini_get_int(const sl_ini *ini, const char *section, const char *key, int required, long def, long min, long max,
                   long *out, sl_diag *d);
int sl_ini_get_bool(const sl_ini *ini, const char *section, const char *key, int required, int def, int *out,
                    sl_diag *d);
/* The returned string is owned by the sl_ini. */
int sl_ini_get_string(const sl_ini *ini, const char *section, const char *key, int required, const char *def,
                      const char **out, sl_diag *d);
/* choices: "a|b|c"; *out is the index. Unknown values get a did-you-mean. */
int sl_ini_get_choice(const sl_ini *ini, const char *section, const char *key, int required, int def,
                      const char *choices, int *out, sl_diag *d);
/* Comma list of reals; at most `cap` values. */
int sl_ini_get_real_list(const sl_ini *ini, const char *section, const char *key, int required, double *vals, int cap,
                         int *n, sl_diag *d);

/* Number parsing shared with the command line: the whole string must be a
 * finite number. Return 0 on success. */
int sl_parse_real(const char *s, double *out);
/* A real number as a scene may write it: a decimal number, or a constant
 * expression of the expression language (core/config/expr.h: 2*pi, 1/3,
 * sqrt(2)/2, 10^-4) whose value is finite. SL_EBADINPUT with the reason in
 * why (the expression's own error, column in s) otherwise. */
int sl_parse_real_expr(const char *s, double *out, char *why, size_t why_len);
/* The same with named constants (NULL: none): a scene's [parameters]. */
struct sl_expr_constants;
int sl_parse_real_expr_with(const char *s, const struct sl_expr_constants *k, double *out, char *why, size_t why_len);
int sl_parse_long(const char *s, long *out);
int sl_parse_bool(const char *s, int *out);

/* Unknown sections: every section name must be in `known` or start with one
 * of the prefixes in `known_prefixes` (e.g. "closure.", "boundary."). */
int sl_ini_check_sections(const sl_ini *ini, const char *const *known, int n_known, const char *const *known_prefixes,
                          int n_prefixes, sl_diag *d);
/* Unknown keys in one section, with a did-you-mean among `known`. */
int sl_ini_check_keys(const sl_ini *ini, const char *section, const char *const *known, int n_known, sl_diag *d);

/* A path named in the INI file `file`: relative to that file's folder
 * unless absolute (includes, mesh files, a study's scene). Malloc'd; NULL
 * when out of memory. */
char *sl_ini_path_relative(const char *file, const char *rel);

/* The resolved configuration (includes flattened, overrides applied) as INI
 * text, in section order. */
int sl_ini_write(const sl_ini *ini, FILE *f);
/* Same, into a malloc'ed string (for provenance). NULL on allocation failure. */
char *sl_ini_to_string(const sl_ini *ini);

#endif
