/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Helpers for closure tests: open a built-in closure by (kind, name) with
 * parameters, evaluate it at single points or batches, read derivatives.
 *
 *   sl_tc *c = sl_tc_open("drag", "ergun", "switch_phi=0.2", NULL);
 *   double K = sl_tc_eval(c, "K", "phi", 0.4, "slip", 0.01, NULL);
 *   double dK = sl_tc_deriv(c, "K", "phi", "phi", 0.4, "slip", 0.01, NULL);
 *   int rc = sl_tc_status(c);  // code of the last evaluation
 *   sl_tc_close(c);
 * Inputs not named take their typical values. */
#ifndef SLUICE_TESTS_CLOSURE_TEST_H
#define SLUICE_TESTS_CLOSURE_TEST_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"

typedef struct sl_tc {
  sl_registry *reg;
  sl_closure *c;
  int last_rc;
  sl_error err;
} sl_tc;

/* NULL-terminated list of "param=value" strings. Aborts the test program
 * with a message when the closure cannot be opened: nothing else makes sense. */
static inline sl_tc *sl_tc_open(const char *kind, const char *name, ...) {
  sl_tc *t = calloc(1, sizeof *t);
  sl_diag d;
  sl_kind k;
  const sl_closure_entry *e;
  void *params;
  if (!t || sl_registry_create(&t->reg, NULL, 0, &d) || sl_registry_scan(t->reg, &d) ||
      sl_kind_from_name(kind, &k, &d) || sl_registry_find(t->reg, k, name, NULL, &e, &d) ||
      sl_params_new(e->desc, &params, &d)) {
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
      fprintf(stderr, "closure %s/%s: bad parameter '%s': %s\n", kind, name, kv, eq ? d.msg : "no '='");
      exit(1);
    }
  }
  va_end(ap);
  if (sl_closure_create(e, params, &t->c, &d)) {
    fprintf(stderr, "cannot create closure %s/%s: %s\n", kind, name, d.msg);
    exit(1);
  }
  return t;
}

static inline void sl_tc_close(sl_tc *t) {
  if (!t) return;
  sl_closure_destroy(t->c);
  sl_registry_destroy(t->reg);
  free(t);
}

/* Evaluates at one point. `out` names the output; `dwrt` (may be NULL) the
 * input to differentiate by. Returns the value or derivative; NAN on error. */
static inline double sl_tc_eval_va(sl_tc *t, const char *out, const char *dwrt, va_list ap) {
  const sl_closure_desc *c = t->c->desc;
  double in_v[32], out_v[32], dout_v[32 * 32];
  const double *in[32];
  double *outp[32], *doutp[32 * 32];
  if (c->n_in > 32 || c->n_out > 32) return NAN;
  for (int32_t i = 0; i < c->n_in; ++i) {
    in_v[i] = c->in[i].typical;
    in[i] = &in_v[i];
  }
  for (const char *name; (name = va_arg(ap, const char *)) != NULL;) {
    double v = va_arg(ap, double);
    int i = sl_closure_input(c, name);
    if (i < 0) {
      fprintf(stderr, "closure %s has no input '%s'\n", c->name, name);
      exit(1);
    }
    in_v[i] = v;
  }
  for (int32_t k = 0; k < c->n_out; ++k) {
    out_v[k] = NAN;
    outp[k] = &out_v[k];
  }
  for (int32_t j = 0; j < c->n_out * c->n_in; ++j) {
    dout_v[j] = NAN;
    doutp[j] = (c->in[j % c->n_in].flags & SL_FIELD_DIFF) ? &dout_v[j] : NULL;
  }
  sl_eval_args a = {.Q = 1, .in = in, .out = outp, .dout = dwrt ? doutp : NULL, .err = &t->err};
  t->last_rc = sl_closure_evaluate(t->c, &a);
  int k = sl_closure_output(c, out);
  if (k < 0) {
    fprintf(stderr, "closure %s has no output '%s'\n", c->name, out);
    exit(1);
  }
  if (t->last_rc != 0) return NAN;
  if (!dwrt) return out_v[k];
  int i = sl_closure_input(c, dwrt);
  if (i < 0 || !doutp[k * c->n_in + i]) {
    fprintf(stderr, "closure %s: input '%s' is not differentiable\n", c->name, dwrt);
    exit(1);
  }
  return dout_v[k * c->n_in + i];
}

/* sl_tc_eval(t, "K", "phi", 0.4, "slip", 0.01, NULL) */
static inline double sl_tc_eval(sl_tc *t, const char *out, ...) {
  va_list ap;
  va_start(ap, out);
  double v = sl_tc_eval_va(t, out, NULL, ap);
  va_end(ap);
  return v;
}

/* sl_tc_deriv(t, "K", "phi", "phi", 0.4, "slip", 0.01, NULL): dK/dphi */
static inline double sl_tc_deriv(sl_tc *t, const char *out, const char *wrt, ...) {
  va_list ap;
  va_start(ap, wrt);
  double v = sl_tc_eval_va(t, out, wrt, ap);
  va_end(ap);
  return v;
}

static inline int sl_tc_status(const sl_tc *t) { return t->last_rc; }

#endif
