/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Helpers for the granular and wall-stress tests on top of closure_test.h:
 * whether a closure accepts a parameter value and whether it can be created,
 * a one-point evaluation with every output requested, and a Richardson-
 * checked central difference. */
#ifndef SLUICE_TESTS_CLOSURES_GRANULAR_TC_EXTRA_H
#define SLUICE_TESTS_CLOSURES_GRANULAR_TC_EXTRA_H

#include <stdarg.h>

#include "closure_test.h"

/* 0 when (kind, name) accepts key = value through the host's schema check. */
static inline int tcx_param_accepted(const char *kind, const char *name, const char *key, const char *value) {
  sl_registry *reg;
  sl_diag d;
  sl_kind k;
  const sl_closure_entry *e;
  void *params;
  if (sl_registry_create(&reg, NULL, 0, &d) || sl_registry_scan(reg, &d) || sl_kind_from_name(kind, &k, &d) ||
      sl_registry_find(reg, k, name, NULL, &e, &d) || sl_params_new(e->desc, &params, &d)) {
    fprintf(stderr, "cannot open closure %s/%s: %s\n", kind, name, d.msg);
    exit(1);
  }
  int rc = sl_params_set(e->desc, params, key, value, &d);
  sl_params_free(params);
  sl_registry_destroy(reg);
  return rc;
}

/* 0 when (kind, name) can be created with the NULL-terminated "key=value" list. */
static inline int tcx_create_rc(const char *kind, const char *name, ...) {
  sl_registry *reg;
  sl_diag d;
  sl_kind k;
  const sl_closure_entry *e;
  void *params;
  if (sl_registry_create(&reg, NULL, 0, &d) || sl_registry_scan(reg, &d) || sl_kind_from_name(kind, &k, &d) ||
      sl_registry_find(reg, k, name, NULL, &e, &d) || sl_params_new(e->desc, &params, &d)) {
    fprintf(stderr, "cannot open closure %s/%s: %s\n", kind, name, d.msg);
    exit(1);
  }
  va_list ap;
  va_start(ap, name);
  for (const char *kv; (kv = va_arg(ap, const char *)) != NULL;) {
    char key[128];
    const char *eq = strchr(kv, '=');
    snprintf(key, sizeof key, "%.*s", eq ? (int)(eq - kv) : 0, kv);
    if (!eq || sl_params_set(e->desc, params, key, eq + 1, &d)) {
      fprintf(stderr, "bad parameter '%s'\n", kv);
      exit(1);
    }
  }
  va_end(ap);
  sl_closure *c = NULL;
  int rc = sl_closure_create(e, params, &c, &d); /* takes params */
  sl_closure_destroy(c);
  sl_registry_destroy(reg);
  return rc;
}

/* Evaluates with only output `out` requested (every other optional output
 * NULL, and their derivative slots NULL), at the closure's typical inputs
 * except those named in the NULL-terminated (name, value) list. Returns the
 * value; *rc receives the code; *dv (may be NULL) d out / d wrt. */
static inline double tcx_eval_only(sl_tc *t, const char *out, const char *wrt, double *dv, int *rc, ...) {
  const sl_closure_desc *c = t->c->desc;
  double in_v[32], out_v[32], dout_v[32 * 32];
  const double *in[32];
  double *outp[32], *doutp[32 * 32];
  for (int32_t i = 0; i < c->n_in; ++i) {
    in_v[i] = c->in[i].typical;
    in[i] = &in_v[i];
  }
  va_list ap;
  va_start(ap, rc);
  for (const char *name; (name = va_arg(ap, const char *)) != NULL;) {
    double v = va_arg(ap, double);
    in_v[sl_closure_input(c, name)] = v;
  }
  va_end(ap);
  int k = sl_closure_output(c, out);
  for (int32_t j = 0; j < c->n_out; ++j) outp[j] = j == k ? &out_v[j] : NULL;
  for (int32_t j = 0; j < c->n_out * c->n_in; ++j) {
    dout_v[j] = NAN;
    doutp[j] = (j / c->n_in == k && (c->in[j % c->n_in].flags & SL_FIELD_DIFF)) ? &dout_v[j] : NULL;
  }
  out_v[k] = NAN;
  sl_eval_args a = {.Q = 1, .in = in, .out = outp, .dout = doutp, .err = &t->err};
  *rc = sl_closure_evaluate(t->c, &a);
  if (dv) *dv = dout_v[k * c->n_in + sl_closure_input(c, wrt)];
  return out_v[k];
}

#endif
