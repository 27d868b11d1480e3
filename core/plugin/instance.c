/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/instance.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/config/ini.h"
#include "core/plugin/guard.h"
#include "core/plugin/kinds.h"
#include "core/plugin/validate.h"

#define SL_HOST_VERSION (0 * 10000 + 1 * 100 + 0)

/* ---- host services handed to closures ---- */

static void host_log(void *host, int level, const char *fmt, ...) {
  (void)host;
  static const char *const names[] = {"error", "warning", "info", "debug"};
  if (level < SL_LOG_ERROR || level > SL_LOG_INFO) return; /* debug output is dropped */
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "closure %s: ", names[level]);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
}

static void *host_alloc(void *host, size_t bytes) {
  (void)host;
  size_t rounded = (bytes + 63) / 64 * 64;
  void *p = aligned_alloc(64, rounded ? rounded : 64);
  if (p) memset(p, 0, rounded ? rounded : 64);
  return p;
}

static void host_free(void *host, void *p) {
  (void)host;
  free(p);
}

/* ---- parameters ---- */

int sl_params_new(const sl_closure_desc *desc, void **params, sl_diag *d) {
  *params = host_alloc(NULL, desc->params_size ? desc->params_size : 1);
  if (!*params) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  for (int32_t i = 0; i < desc->n_params; ++i) {
    const sl_param_desc *p = &desc->params[i];
    char *at = (char *)*params + p->offset;
    if (p->type == SL_PARAM_REAL) {
      double v = p->def;
      memcpy(at, &v, sizeof v);
    } else {
      int32_t v = (int32_t)p->def;
      memcpy(at, &v, sizeof v);
    }
  }
  return 0;
}

void sl_params_free(void *params) { free(params); }

int sl_params_find(const sl_closure_desc *desc, const char *key) {
  for (int32_t i = 0; i < desc->n_params; ++i)
    if (strcmp(desc->params[i].name, key) == 0) return (int)i;
  return -1;
}

/* Index of `value` among "a|b|c", or -1. */
static int choice_index(const char *choices, const char *value, char *list, size_t n) {
  int idx = 0, found = -1;
  size_t len = strlen(value);
  snprintf(list, n, "%s", choices);
  for (char *c = list; *c; ++c)
    if (*c == '|') *c = ' ';
  for (const char *s = choices; *s; ++idx) {
    const char *bar = strchr(s, '|');
    size_t l = bar ? (size_t)(bar - s) : strlen(s);
    if (l == len && strncmp(s, value, l) == 0) found = idx;
    s += l + (bar ? 1 : 0);
    if (!bar) break;
  }
  return found;
}

int sl_params_set(const sl_closure_desc *desc, void *params, const char *key, const char *value, sl_diag *d) {
  return sl_params_set_with(desc, params, key, value, NULL, d);
}

int sl_params_set_with(const sl_closure_desc *desc, void *params, const char *key, const char *value,
                       const sl_expr_constants *named, sl_diag *d) {
  int i = sl_params_find(desc, key);
  if (i < 0) {
    const char *cands[128];
    int n = 0;
    for (int32_t k = 0; k < desc->n_params && n < 128; ++k) cands[n++] = desc->params[k].name;
    if (n == 0) return sl_diag_set(d, SL_EBADINPUT, "closure '%s' takes no parameters (got '%s')", desc->name, key);
    const char *s = sl_suggest(key, cands, n);
    if (s)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s' has no parameter '%s'; did you mean '%s'?", desc->name, key, s);
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s' has no parameter '%s' (`sluice closure describe %s` lists them)",
                       desc->name, key, desc->name);
  }
  const sl_param_desc *p = &desc->params[i];
  char *at = (char *)params + p->offset;
  switch (p->type) {
    case SL_PARAM_REAL: {
      double v;
      char why[200];
      if (sl_parse_real_expr_with(value, named, &v, why, sizeof why))
        return sl_diag_set(d, SL_EBADINPUT, "%s = '%s' is not a number or a constant expression%s%s", key, value,
                           why[0] ? ": " : "", why);
      if (v < p->min || v > p->max)
        return sl_diag_set(d, SL_EBADINPUT, "%s = %s is outside the allowed range [%g, %g] %s", key, value, p->min,
                           p->max, p->units);
      memcpy(at, &v, sizeof v);
      return 0;
    }
    case SL_PARAM_INT: {
      long v;
      if (sl_parse_long(value, &v)) return sl_diag_set(d, SL_EBADINPUT, "%s = '%s' is not an integer", key, value);
      if (v < p->min || v > p->max)
        return sl_diag_set(d, SL_EBADINPUT, "%s = %s is outside the allowed range [%g, %g]", key, value, p->min,
                           p->max);
      int32_t iv = (int32_t)v;
      memcpy(at, &iv, sizeof iv);
      return 0;
    }
    case SL_PARAM_BOOL: {
      int b;
      if (sl_parse_bool(value, &b))
        return sl_diag_set(d, SL_EBADINPUT, "%s = '%s' is not a boolean (true or false)", key, value);
      int32_t iv = b;
      memcpy(at, &iv, sizeof iv);
      return 0;
    }
    case SL_PARAM_ENUM: {
      char list[512];
      int idx = choice_index(p->choices, value, list, sizeof list);
      if (idx < 0) {
        /* Suggest among the choices. */
        char copy[512];
        const char *cands[32];
        int n = 0;
        snprintf(copy, sizeof copy, "%s", p->choices);
        for (char *save = NULL, *t = strtok_r(copy, "|", &save); t && n < 32; t = strtok_r(NULL, "|", &save))
          cands[n++] = t;
        const char *s = sl_suggest(value, cands, n);
        if (s)
          return sl_diag_set(d, SL_EBADINPUT, "%s = '%s' is not one of: %s; did you mean '%s'?", key, value, list, s);
        return sl_diag_set(d, SL_EBADINPUT, "%s = '%s' is not one of: %s", key, value, list);
      }
      int32_t iv = idx;
      memcpy(at, &iv, sizeof iv);
      return 0;
    }
  }
  return sl_diag_set(d, SL_EBADINPUT, "%s: unsupported parameter type", key);
}

void sl_params_format_value(const sl_closure_desc *desc, const void *params, int i, char *buf, size_t n) {
  const sl_param_desc *p = &desc->params[i];
  const char *at = (const char *)params + p->offset;
  if (p->type == SL_PARAM_REAL) {
    double v;
    memcpy(&v, at, sizeof v);
    /* Shortest text that reads back to the same double; plain notation
     * (150, 0.001) when it is no longer than the exponent form. */
    char best[64];
    snprintf(best, sizeof best, "%.17g", v);
    for (int prec = 1; prec <= 17; ++prec) {
      char tmp[64];
      snprintf(tmp, sizeof tmp, "%.*g", prec, v);
      if (strtod(tmp, NULL) == v) {
        snprintf(best, sizeof best, "%s", tmp);
        break;
      }
    }
    if (strchr(best, 'e') && fabs(v) >= 1e-4 && fabs(v) < 1e15) {
      for (int prec = 0; prec <= 17; ++prec) {
        char tmp[64];
        snprintf(tmp, sizeof tmp, "%.*f", prec, v);
        if (strtod(tmp, NULL) == v) {
          if (strlen(tmp) <= strlen(best) + 2) snprintf(best, sizeof best, "%s", tmp);
          break;
        }
      }
    }
    snprintf(buf, n, "%s", best);
    return;
  }
  int32_t v;
  memcpy(&v, at, sizeof v);
  if (p->type == SL_PARAM_BOOL) {
    snprintf(buf, n, "%s", v ? "true" : "false");
  } else if (p->type == SL_PARAM_ENUM) {
    const char *s = p->choices;
    for (int32_t k = 0; k < v && s; ++k) {
      s = strchr(s, '|');
      if (s) ++s;
    }
    size_t l = s ? strcspn(s, "|") : 0;
    snprintf(buf, n, "%.*s", (int)l, s ? s : "");
  } else {
    snprintf(buf, n, "%d", (int)v);
  }
}

/* ---- instances ---- */

const char *sl_closure_label(const sl_closure_desc *desc, char *buf, size_t n) {
  snprintf(buf, n, "%s/%s", sl_kind_name(desc->kind), desc->name);
  return buf;
}

int sl_closure_create(const sl_closure_entry *entry, void *params, sl_closure **out, sl_diag *d) {
  *out = NULL;
  sl_closure *c = calloc(1, sizeof *c);
  if (!c) {
    sl_params_free(params);
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
  }
  c->desc = entry->desc;
  c->library = entry->library;
  c->params = params;
  c->timed = entry->library->timing;
  sl_closure_label(c->desc, c->label, sizeof c->label);
  for (int32_t k = 0; k < entry->library->n_closures; ++k)
    if (entry->library->closures[k] == entry->desc) c->usage_index = (int)k;
  c->api = (sl_host_api){.struct_size = (uint32_t)sizeof(sl_host_api),
                         .host_version = SL_HOST_VERSION,
                         .dim = 0,
                         .log = host_log,
                         .alloc = host_alloc,
                         .free = host_free,
                         .host = NULL};
  if (c->desc->create) {
    sl_error err = {-1, ""};
    int rc = c->desc->create(&c->api, params, &c->state, &err);
    if (rc != 0) {
      char label[128];
      sl_closure_label(c->desc, label, sizeof label);
      sl_params_free(params);
      free(c);
      return sl_diag_set(d, SL_EBADINPUT, "closure %s (%s) refused its parameters: %s", label, entry->library->path,
                         err.msg[0] ? err.msg : "no reason given");
    }
  } else {
    c->state = params;
  }
  entry->library->n_in_use++;
  if (entry->library->usage) entry->library->usage[c->usage_index].instances++;
  *out = c;
  return 0;
}

void sl_closure_destroy(sl_closure *c) {
  if (!c) return;
  if (c->desc->destroy) c->desc->destroy(&c->api, c->state);
  if (c->library) c->library->n_in_use--;
  if (c->library && c->library->usage) {
    sl_closure_usage *u = &c->library->usage[c->usage_index];
    u->calls += c->n_calls, u->points += c->n_points, u->seconds += c->seconds;
  }
  sl_params_free(c->params);
  free(c);
}

/* ---- the output scan ----
 * all_finite(o, Q) is true when o[0..Q) holds only finite values. Their sum is
 * finite then, and it is not when any of them is an infinity or a NaN (both
 * propagate through additions), so one pass of additions, with no comparison
 * and no branch per point, clears the batch. A sum that overflows with every
 * value finite is only a false alarm: the caller then looks point by point
 * and finds nothing. Independent partial sums keep the pass at the load rate
 * rather than at the latency of an addition; with AVX (checked at run time)
 * four 4-wide sums, otherwise four 2-wide (SSE2) ones. The pass sits between
 * the closure's loop and the next batch, so its length in instructions is
 * what the ABI costs per point (bench/closure_throughput.c). Relies on IEEE
 * arithmetic, as isfinite() below does: no -ffast-math for this file. */
#if defined(__GNUC__) && defined(__x86_64__) /* SSE2 is baseline there */
typedef double sl_v2d __attribute__((vector_size(16)));
typedef double sl_v4d __attribute__((vector_size(32)));

/* Unaligned vector loads (the batch may start anywhere in a host array). */
static inline sl_v2d load2(const double *p) {
  sl_v2d v;
  memcpy(&v, p, sizeof v);
  return v;
}
__attribute__((target("avx"))) static inline sl_v4d load4(const double *p) {
  sl_v4d v;
  memcpy(&v, p, sizeof v);
  return v;
}

static int all_finite_sse2(const double *restrict o, int32_t Q) {
  sl_v2d a0 = {0.0, 0.0}, a1 = a0, a2 = a0, a3 = a0;
  int32_t q = 0;
  for (; q + 8 <= Q; q += 8) {
    a0 += load2(o + q);
    a1 += load2(o + q + 2);
    a2 += load2(o + q + 4);
    a3 += load2(o + q + 6);
  }
  double s = 0.0;
  for (; q < Q; ++q) s += o[q];
  const sl_v2d t = (a0 + a1) + (a2 + a3);
  s += t[0] + t[1];
  return s - s == 0.0; /* false for an infinite or NaN sum */
}

__attribute__((target("avx"))) static int all_finite_avx(const double *restrict o, int32_t Q) {
  sl_v4d a0 = {0.0, 0.0, 0.0, 0.0}, a1 = a0, a2 = a0, a3 = a0;
  int32_t q = 0;
  for (; q + 16 <= Q; q += 16) {
    a0 += load4(o + q);
    a1 += load4(o + q + 4);
    a2 += load4(o + q + 8);
    a3 += load4(o + q + 12);
  }
  for (; q + 4 <= Q; q += 4) a0 += load4(o + q);
  double s = 0.0;
  for (; q < Q; ++q) s += o[q];
  const sl_v4d t = (a0 + a1) + (a2 + a3);
  s += (t[0] + t[1]) + (t[2] + t[3]);
  return s - s == 0.0;
}

static int all_finite(const double *restrict o, int32_t Q) {
  if (Q >= 16 && __builtin_cpu_supports("avx")) return all_finite_avx(o, Q);
  return all_finite_sse2(o, Q);
}
#else
static int all_finite(const double *restrict o, int32_t Q) {
  double acc[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  int32_t q = 0;
  for (; q + 8 <= Q; q += 8)
    for (int j = 0; j < 8; ++j) acc[j] += o[q + j];
  for (; q < Q; ++q) acc[0] += o[q];
  const double s = ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
  return s - s == 0.0;
}
#endif

static double monotonic_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Inlined into both paths of sl_closure_evaluate: the untimed call costs
 * what it did before the profile's clock existed. */
#if defined(__GNUC__)
#define SL_EVAL_INLINE __attribute__((always_inline)) static inline
#else
#define SL_EVAL_INLINE static inline
#endif

/* The call and the host's scan of its outputs. */
SL_EVAL_INLINE int evaluate_checked(sl_closure *c, const sl_eval_args *a) {
  a->err->point = -1;
  a->err->msg[0] = '\0';
  const sl_closure_desc *desc = c->desc;
  if (c->poisoned) {
    snprintf(a->err->msg, sizeof a->err->msg, "not called again after it crashed or overran");
    return SL_ERR_INTERNAL;
  }
  int rc = sl_guard_evaluate(desc, c->state, a, c->label, c->role[0] ? c->role : NULL, &c->poisoned);
  if (rc != 0) {
    if (!a->err->msg[0]) snprintf(a->err->msg, sizeof a->err->msg, "returned %d without a message", rc);
    /* fatal (< 0): the run stops at once, the closure named (guard.h) */
    if (rc < 0)
      sl_guard_set_fatal("closure %s%s%s%s failed (fatal, code %d): %s", c->label, c->role[0] ? " [" : "", c->role,
                         c->role[0] ? "]" : "", rc, a->err->msg);
    return rc;
  }
  /* No silent NaN: a non-finite output is the closure's failure, recoverable.
   * The point-by-point search runs only when the batch test says so. */
  for (int32_t k = 0; k < desc->n_out; ++k) {
    const double *o = a->out[k];
    if (!o || all_finite(o, a->Q)) continue;
    for (int32_t q = 0; q < a->Q; ++q) {
      if (!isfinite(o[q])) {
        a->err->point = q;
        snprintf(a->err->msg, sizeof a->err->msg, "output '%s' is %g at point %d", desc->out[k].name, o[q], (int)q);
        return SL_RECOVERABLE;
      }
    }
  }
  /* nor in the derivatives a Newton solve takes */
  for (int32_t k = 0; k < desc->n_out && a->dout; ++k)
    for (int32_t i = 0; i < desc->n_in; ++i) {
      const double *o = a->dout[k * desc->n_in + i];
      if (!o || all_finite(o, a->Q)) continue;
      for (int32_t q = 0; q < a->Q; ++q)
        if (!isfinite(o[q])) {
          a->err->point = q;
          snprintf(a->err->msg, sizeof a->err->msg, "derivative of '%s' by '%s' is %g at point %d", desc->out[k].name,
                   desc->in[i].name, o[q], (int)q);
          return SL_RECOVERABLE;
        }
    }
  return 0;
}

int sl_closure_evaluate(sl_closure *c, const sl_eval_args *a) {
  c->n_calls++;
  c->n_points += (unsigned long long)a->Q;
  if (!c->timed) return evaluate_checked(c, a);
  double t0 = monotonic_seconds();
  int rc = evaluate_checked(c, a);
  c->seconds += monotonic_seconds() - t0;
  return rc;
}

int sl_closure_input(const sl_closure_desc *desc, const char *name) {
  for (int32_t i = 0; i < desc->n_in; ++i)
    if (strcmp(desc->in[i].name, name) == 0) return (int)i;
  return -1;
}

int sl_closure_output(const sl_closure_desc *desc, const char *name) {
  for (int32_t i = 0; i < desc->n_out; ++i)
    if (strcmp(desc->out[i].name, name) == 0) return (int)i;
  return -1;
}
