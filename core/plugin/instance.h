/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A closure in use: its validated parameters, its state, and the evaluate
 * wrapper that the rest of the core calls (it counts calls, clears the error
 * record and refuses non-finite outputs so that no NaN passes silently). */
#ifndef SLUICE_PLUGIN_INSTANCE_H
#define SLUICE_PLUGIN_INSTANCE_H

#include <stdio.h>

#include "core/config/expr.h"
#include "core/plugin/registry.h"

typedef struct sl_closure {
  const sl_closure_desc *desc;
  sl_library *library;
  void *params; /* validated parameter struct, owned here */
  void *state;  /* from create(), or params when the closure has no create */
  sl_host_api api;
  unsigned long long n_calls, n_points; /* evaluation counters (profile) */
  double seconds;                       /* inside evaluate, when timed */
  int timed;                            /* from the library's timing switch at creation */
  int usage_index;                      /* this closure's slot in library->usage */
  char role[64];                        /* the scene section it was created from ("closure.drag"), "" when none */
  char label[96];                       /* "kind/name" */
  int poisoned;                         /* it crashed or overran: not called again (guard.h) */
} sl_closure;

/* A parameter struct filled with the schema's defaults (64-byte aligned,
 * zeroed first). Free with sl_params_free. */
int sl_params_new(const sl_closure_desc *desc, void **params, sl_diag *d);
void sl_params_free(void *params);
/* Sets one parameter from text, checking type and bounds; unknown keys get a
 * did-you-mean. The message carries no location: callers prefix it. */
int sl_params_set(const sl_closure_desc *desc, void *params, const char *key, const char *value, sl_diag *d);
/* The same with named constants in real values (a scene's [parameters]; NULL: none). */
int sl_params_set_with(const sl_closure_desc *desc, void *params, const char *key, const char *value,
                       const sl_expr_constants *k, sl_diag *d);
/* Index of a parameter by name, or -1. */
int sl_params_find(const sl_closure_desc *desc, const char *key);
/* The value of parameter i as text ("4.65", "true", "rowe"). */
void sl_params_format_value(const sl_closure_desc *desc, const void *params, int i, char *buf, size_t n);

/* Creates the closure; takes ownership of params (also on failure). Its
 * counters go into library->usage when it is destroyed. */
int sl_closure_create(const sl_closure_entry *entry, void *params, sl_closure **out, sl_diag *d);
void sl_closure_destroy(sl_closure *c);

/* Evaluates one batch. Returns the closure's code: 0, > 0 recoverable (also
 * for a non-finite output, reported as such), < 0 fatal; err names the point.
 * Counts the call and its points (and times it when c->timed). */
int sl_closure_evaluate(sl_closure *c, const sl_eval_args *args);

/* Index of an input or output by name, or -1. */
int sl_closure_input(const sl_closure_desc *desc, const char *name);
int sl_closure_output(const sl_closure_desc *desc, const char *name);

/* "kind/name" for messages (static buffer per call site is not needed: the
 * caller passes one). */
const char *sl_closure_label(const sl_closure_desc *desc, char *buf, size_t n);

#endif
