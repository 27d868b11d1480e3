/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Closure kinds: their names and contracts (docs/closure-kinds.md is generated from them),
 * and the dictionary of input names the host knows how to supply. */
#ifndef SLUICE_PLUGIN_KINDS_H
#define SLUICE_PLUGIN_KINDS_H

#include <sluice/closure.h>

#include "core/util/diag.h"

#define SL_KIND_FIRST SL_KIND_DRAG
#define SL_KIND_LAST SL_KIND_TURBULENCE_MODULATION

/* "drag", "hindered_settling", ...; NULL for an unknown kind. */
const char *sl_kind_name(sl_kind kind);
/* Kind from its name, with a did-you-mean on failure. */
int sl_kind_from_name(const char *name, sl_kind *kind, sl_diag *d);
/* All kind names, for suggestions and listings. */
const char *const *sl_kind_names(int *n);

/* Is `name` in the host's dictionary of input fields? */
int sl_input_is_known(const char *name);
const char *const *sl_input_names(int *n);

/* One entry of the host's dictionary of inputs: what it is, its SI units,
 * a representative value and the range the host can supply. */
typedef struct sl_input_info {
  const char *name, *units, *meaning;
  double typical, min, max;
} sl_input_info;
/* The entry of `name`, NULL when the host does not know it. */
const sl_input_info *sl_input_find(const char *name);

/* What a closure of one kind gives the models: the output's name, units,
 * meaning and whether the kind's contract requires it (else a model reads
 * it when present, or needs it in some configurations, as `note` says). */
typedef struct sl_kind_output {
  const char *name, *units, *meaning;
  int required;
} sl_kind_output;

enum { SL_KIND_MAX_INPUTS = 8, SL_KIND_MAX_OUTPUTS = 6 };

/* A kind's contract as a closure author reads it. */
typedef struct sl_kind_info {
  const char *summary;                         /* what a closure of the kind is */
  const char *required[SL_KIND_MAX_INPUTS];    /* inputs every closure of the kind declares */
  unsigned diff_mask;                          /* bit i: required[i] must be differentiable */
  const char *usual[SL_KIND_MAX_INPUTS];       /* further inputs the models supply for the kind */
  sl_kind_output outputs[SL_KIND_MAX_OUTPUTS]; /* the outputs the models read */
  int any_output;                              /* outputs are free (at least one) */
  const char *range_checks;                    /* what evaluate() must refuse */
  const char *used_by;                         /* the models that read it, and how */
} sl_kind_info;
/* NULL for an unknown kind. */
const sl_kind_info *sl_kind_info_of(sl_kind kind);

/* Checks a descriptor against its kind's contract: required inputs present
 * (and differentiable where the contract says so), required outputs present.
 * Returns 0 or SL_EBADINPUT with a message naming what is missing. */
int sl_kind_check_contract(const sl_closure_desc *desc, sl_diag *d);

#endif
