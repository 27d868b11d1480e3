/* SPDX-License-Identifier: GPL-2.0-or-later */
/* libFuzzer target for the expression language (core/config/expr.c). Any
 * input must compile or fail cleanly (no crash, leak or UB under ASan+UBSan,
 * nothing handed out on failure, a "column N:" style message). Programs that
 * compile are evaluated at a few points and must keep these properties:
 *   - a constant program evaluates to its constant whatever the variables;
 *   - a variable that sl_expr_uses() says is unused does not change the value;
 *   - "(text)" has the same value and "-(text)" the negated one (when they
 *     compile; they may only fail on the length, nesting or stack limits).
 * Run: configure with -DSLUICE_FUZZ=ON -DCMAKE_C_COMPILER=clang, build the
 * fuzz_expr target, then e.g.
 *   BUILD/bin/fuzz_expr -max_total_time=60 -max_len=512 -dict=tests/fuzz/expr.dict \
 *     BUILD/fuzz/expr-corpus tests/fuzz/corpus/expr
 * The seed corpus is replayed by the fuzz_expr_corpus_replay test in every build. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/expr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const vars[] = {"x", "y", "t"};
static const double points[][3] = {{0.3, -1.7, 2.5}, {0, -0.0, 1}, {1e300, -1e-300, 7}, {NAN, INFINITY, -2}};
enum { N_POINTS = (int)(sizeof points / sizeof points[0]) };

static int same(double a, double b) {
  if (isnan(a) || isnan(b)) return isnan(a) && isnan(b);
  return a == b && signbit(a) == signbit(b);
}

static int limit_error(const char *msg) {
  return strstr(msg, "too long") || strstr(msg, "nested too deeply") || strstr(msg, "too complex");
}

/* Compiles `fmt` with the text in it and checks its value at every point
 * against f(value of the original). */
static void check_wrapped(const char *fmt, const char *text, size_t len, const sl_expr *orig, int negate) {
  char *w = malloc(len + 8);
  if (!w) return;
  snprintf(w, len + 8, fmt, text);
  sl_expr *e = NULL;
  sl_diag d;
  if (sl_expr_compile(w, vars, 3, &e, &d) != 0) {
    if (e || !limit_error(d.msg)) abort();
  } else {
    for (int p = 0; p < N_POINTS; ++p) {
      double v = sl_expr_eval(orig, points[p]);
      if (!same(sl_expr_eval(e, points[p]), negate ? -v : v)) abort();
    }
    sl_expr_free(e);
  }
  free(w);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char *text = malloc(size + 1);
  if (!text) return 0;
  if (size) memcpy(text, data, size);
  text[size] = '\0';
  size_t len = strlen(text); /* the expression ends at an embedded NUL */

  sl_expr *e = (sl_expr *)&e; /* compile must reset it */
  sl_diag d;
  d.msg[0] = '\0';
  if (sl_expr_compile(text, vars, 3, &e, &d) != 0) {
    if (e) abort(); /* a failed compile must not hand anything out */
    if (strncmp(d.msg, "column ", 7) != 0 && strncmp(d.msg, "empty expression", 16) != 0 &&
        strncmp(d.msg, "expression", 10) != 0)
      abort();
    if (d.msg[0] == 'c' && (size_t)atol(d.msg + 7) > len + 1) abort(); /* a column inside the text (or just after) */
    free(text);
    return 0;
  }
  double c = 0;
  int is_const = sl_expr_is_constant(e, &c);
  for (int p = 0; p < N_POINTS; ++p) {
    double v = sl_expr_eval(e, points[p]);
    if (is_const && !same(v, c)) abort();
    for (int k = 0; k < 3; ++k) {
      if (sl_expr_uses(e, k)) continue;
      double other[3] = {points[p][0], points[p][1], points[p][2]};
      other[k] = 12345.678;
      if (!same(sl_expr_eval(e, other), v)) abort();
    }
  }
  if (is_const && (sl_expr_uses(e, 0) || sl_expr_uses(e, 1) || sl_expr_uses(e, 2))) abort();
  check_wrapped("(%s)", text, len, e, 0);
  check_wrapped("-(%s)", text, len, e, 1);
  sl_expr_free(e);
  free(text);
  return 0;
}
