/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The keys a model reads from a scene, declared once: section, name, type,
 * default, range, units and help, and where the typed value goes. A model's
 * schema is the list of every key it reads (shared tables of keys that
 * every model reads the same way, plus its own); the scene builder
 * (core/scene/scene.h) fills the model's structs from it, a key outside it
 * is an error, and `sluice model describe` and docs/models/ are written from
 * it. Nothing else holds a default, a unit or a range of a scene key. */
#ifndef SLUICE_SCENE_SCHEMA_H
#define SLUICE_SCENE_SCHEMA_H

#include <stddef.h>
#include <stdio.h>

#include "core/config/expr.h"

typedef enum sl_key_type {
  SL_KEY_REAL,   /* double */
  SL_KEY_INT,    /* long */
  SL_KEY_BOOL,   /* int, 0 or 1 */
  SL_KEY_CHOICE, /* int: the index in `choices` ("a|b|c") */
  SL_KEY_STRING, /* const char * (owned by the scene); "" when not given and no default text */
  SL_KEY_REALS,  /* sl_reals: a comma list of at most max_n numbers, each in [min, max] */
  SL_KEY_EXPR,   /* sl_scene_expr: an expression of the variables in `vars` */
  SL_KEY_EXPRS   /* sl_scene_exprs: a comma list of at most max_n expressions of `vars` */
} sl_key_type;

/* Where a key's value goes: the scene's common part (sl_scene), the
 * model's configuration struct, or the struct of each boundary. */
typedef enum sl_key_target { SL_IN_SCENE = 0, SL_IN_MODEL, SL_IN_BOUNDARY } sl_key_target;

enum { SL_REALS_MAX = 8, SL_EXPRS_MAX = 3 };

typedef struct sl_reals {
  int n;
  double v[SL_REALS_MAX];
} sl_reals;

typedef struct sl_scene_expr {
  sl_expr *e; /* NULL: not given and no default */
  const char *text;
} sl_scene_expr;

typedef struct sl_scene_exprs {
  int n;
  sl_expr *e[SL_EXPRS_MAX];
  const char *text;
} sl_scene_exprs;

enum {
  SL_KEY_REQUIRED = 1u, /* an error when absent */
  SL_KEY_NAMED = 2u,    /* the section may also be given as [section.NAME], once per NAME, with the same keys: the
                           model reads those itself (sl_scene_named_section) */
};

typedef struct sl_key {
  const char *section; /* "fluid"; "boundary" for every [boundary.NAME] */
  const char *name;
  sl_key_type type;
  sl_key_target target;
  size_t offset; /* of the value in its target struct */
  unsigned flags;
  double def;             /* REAL, INT, BOOL (0/1), CHOICE (index) */
  const double *def_list; /* REALS: the default list (n_def values; 0: an empty list) */
  int n_def;
  double min, max;      /* REAL, INT, REALS */
  const char *choices;  /* CHOICE: "a|b|c" */
  const char *vars;     /* EXPR, EXPRS: the variables, "x,y,t" */
  int max_n;            /* REALS, EXPRS: the most values */
  const char *def_text; /* STRING, EXPR, EXPRS: the default value's text (NULL: none) */
  const char *def_doc;  /* the default in words, where the model works it out ("dt x 1e-6"); NULL: the value */
  const char *units;
  const char *help;
  unsigned when_type;   /* boundary keys: bit k allows the key on a boundary of type choice k (0: any type) */
  const char *when_doc; /* those types in words, "an inlet or a wall" (NULL: their names) */
} sl_key;

/* A table of keys (a model lists several). */
typedef struct sl_key_table {
  const sl_key *keys;
  int n;
} sl_key_table;

/* A closure the model takes: [closure.<role>] (a qualifier after a dot,
 * [closure.wall_stress.inner], is the model's to read). */
typedef struct sl_role {
  const char *role; /* "drag", "viscosity", ... (the kind's name) */
  int required;
  const char *help; /* what the model uses it for; with required, what to write */
} sl_role;

/* A condition on the raw INI that picks a model's variant: [section] key
 * has one of the values `values` ("a|b"); an absent key counts as `absent`. */
typedef struct sl_variant_rule {
  const char *section, *key, *values, *absent;
} sl_variant_rule;

/* A key the model no longer reads, refused at its file:line with what replaces it ("[closure.drag] model = ..."). */
typedef struct sl_moved_key {
  const char *section, *name, *instead;
} sl_moved_key;

enum { SL_SCHEMA_MAX_TABLES = 16, SL_SCHEMA_MAX_ROLES = 10, SL_SCHEMA_MAX_RULES = 3 };

typedef struct sl_schema {
  const char *model;   /* the [scene] model value */
  const char *variant; /* NULL, or what tells this variant from the model's others, "motion = shear" */
  const char *title;   /* one line: what the model solves */
  const char *summary; /* a paragraph for the model's page */
  sl_variant_rule when[SL_SCHEMA_MAX_RULES];
  int n_when;
  const sl_key_table *tables[SL_SCHEMA_MAX_TABLES];
  int n_tables;
  sl_role roles[SL_SCHEMA_MAX_ROLES];
  int n_roles;
  size_t config_size;        /* the model's configuration struct */
  size_t boundary_size;      /* the struct of each boundary (0: the model reads no [boundary.NAME]) */
  const char *const *fields; /* the output fields [output] fields may name */
  int n_fields;
  const sl_moved_key *moved; /* keys of earlier versions, refused with what to write instead */
  int n_moved;
} sl_schema;

/* The key [section] name of a schema, or NULL. */
const sl_key *sl_schema_key(const sl_schema *s, const char *section, const char *name);
/* 1 when the schema has keys in the section (boundary sections: "boundary"). */
int sl_schema_has_section(const sl_schema *s, const char *section);
/* The role of [closure.<role>[.qualifier]], or NULL. */
const sl_role *sl_schema_role(const sl_schema *s, const char *role);

/* The default of a key as text ("1000", "(0, -9.81)", "bdf2", "dt x 1e-6",
 * "none"). */
void sl_key_default_text(const sl_key *k, char *buf, size_t len);
/* The key's type and range as text ("real in [1e-3, 1e5]", "one of steady|bdf1|bdf2"). */
void sl_key_range_text(const sl_key *k, char *buf, size_t len);

/* The model's page: its sections and keys with types, defaults, units,
 * ranges and help, its closures and output fields (markdown when
 * `markdown`, else plain text for the terminal). */
void sl_schema_describe(const sl_schema *s, FILE *f, int markdown);

#endif
