/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A benchmark study (`sluice bench STUDY.ini`): a scene, the overrides that
 * make its runs, and what is measured in each run's output.
 *
 *   [study]              scene = FILE (relative to the study file), title, timeout (wall s per run)
 *   [set.<section>]      key = value: an override for every run, as `--set section.key=value`
 *   [points.<section>]   key = v1, v2, ...: the sweep along each curve (mesh sizes, time steps, ...)
 *   [variants.<section>] key = v1, v2, ...: one curve per value (schemes, solvers, closures)
 *   [points], [variants] names = ...: labels (default "key = value")
 *   [measure]            what is measured and against what (sl_study_measure)
 *
 * Several keys in one sweep change together, value by value. A run value
 * holding commas (a vector, an expression) is written with '|' between the
 * runs: `cells = 8, 8 | 16, 16`. Setting `model` of a [closure.*] section to
 * another closure than the scene's drops the scene's parameters of that
 * section (they belong to the other closure); keys the study sets there
 * apply to the new one. Every message names the study file's line. */
#ifndef SLUICE_BENCH_STUDY_H
#define SLUICE_BENCH_STUDY_H

#include "core/config/ini.h"

enum { SL_STUDY_MAX_KEYS = 32, SL_STUDY_MAX_VALUES = 128 };

typedef struct sl_study_key {
  const char *section, *key; /* the scene's section and key ("closure.drag", "model") */
  int n_values;
  char *values[SL_STUDY_MAX_VALUES];
  const sl_ini_entry *where; /* in the study file */
} sl_study_key;

typedef enum sl_study_against {
  SL_AGAINST_NONE,      /* a comparison: the quantity itself, side by side */
  SL_AGAINST_EXACT,     /* an exact solution built into sluice (core/study/exact.h) */
  SL_AGAINST_REFERENCE, /* a CSV of position (or time), value */
  SL_AGAINST_VALUE,     /* one number */
  SL_AGAINST_FINEST     /* the last point of the same variant */
} sl_study_against;

typedef enum sl_study_norm { SL_NORM_L1, SL_NORM_L2, SL_NORM_MAX } sl_study_norm;
typedef enum sl_study_reduce { SL_REDUCE_NONE, SL_REDUCE_MIN, SL_REDUCE_MAX } sl_study_reduce;

typedef struct sl_study_measure {
  int scalar;       /* 1: an output scalar (attribute of an output time); 0: a field */
  const char *name; /* field or scalar name; NULL with an exact solution (it names its field) */
  int component;    /* of a vector field */
  int has_time;
  double time; /* output time measured (default: the last) */
  int has_line, line_dim;
  double line[4]; /* x0, y0, x1, y1 (1-D: y = 0) */
  int n;          /* points along the line */
  sl_study_reduce reduce;
  sl_study_against against;
  const char *exact; /* kynch | bingham | fluidized_bed */
  char *reference;   /* the CSV's path, resolved against the study file */
  int n_ref;
  double *ref_x, *ref_v; /* positions s along the line (field) or times t (scalar), values */
  double value;
  sl_study_norm norm;
  int has_norm;
  const char *label; /* of the quantity (axis titles), or NULL */
  const sl_ini_section *where;
} sl_study_measure;

typedef struct sl_study {
  sl_ini *ini; /* the study file: owns the strings and locations below */
  char *path;
  char *name;  /* the study file's name without folder and ".ini": names the outputs */
  char *scene; /* resolved against the study file's folder */
  const sl_ini_entry *scene_entry;
  const char *title;
  double timeout;
  int n_fixed, n_point_keys, n_variant_keys;
  sl_study_key fixed[SL_STUDY_MAX_KEYS], points[SL_STUDY_MAX_KEYS], variants[SL_STUDY_MAX_KEYS];
  int n_points, n_variants;
  char *point_names[SL_STUDY_MAX_VALUES], *variant_names[SL_STUDY_MAX_VALUES];
  double point_x[SL_STUDY_MAX_VALUES]; /* the first number of the first points key's value (NaN: none) */
  sl_study_measure m;
} sl_study;

/* Reads and checks a study file. Returns 0 or SL_EBADINPUT with d naming
 * file:line, the key, the allowed values and a did-you-mean. */
int sl_study_load(const char *path, sl_study **out, sl_diag *d);
void sl_study_free(sl_study *s);

/* The scene configuration of run (variant, point): the scene with the fixed,
 * point and variant overrides, located at the study's lines. */
int sl_study_run_ini(const sl_study *s, int variant, int point, sl_ini **ini, sl_diag *d);

/* "key = value, key = value" of one run's point or variant values. */
void sl_study_describe(const sl_study_key *keys, int n_keys, int index, char *buf, size_t len);

#endif
