/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The loader against deliberately broken closure libraries: every defect
 * gives a clear message naming the file, never a crash. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/ini.h"
#include "core/plugin/battery.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/instance.h"
#include "testing.h"

static const char *dir;

static const char *lib_path(const char *name) {
  static char path[4096];
  snprintf(path, sizeof path, "%s/%s.so", dir, name);
  return path;
}

/* Loading `name` alone fails with exit code 2 and a message holding `expect`. */
static void expect_refused(const char *name, const char *expect) {
  sl_registry *r;
  sl_diag d;
  CHECK(sl_registry_create(&r, NULL, 0, &d) == 0);
  d.msg[0] = '\0';
  int rc = sl_registry_add_library(r, lib_path(name), NULL, &d);
  CHECK_MSG(rc == SL_EBADINPUT, "%s: rc %d", name, rc);
  CHECK_CONTAINS(d.msg, expect);
  CHECK_CONTAINS(d.msg, lib_path(name));
  CHECK(r->n_entries == 0);
  sl_registry_destroy(r);
}

static sl_battery_result battery_on(const char *name) {
  sl_registry *r;
  sl_diag d;
  sl_battery_result res = {0, 0, 0, NULL, NULL};
  sl_library *lib;
  if (sl_registry_create(&r, NULL, 0, &d) || sl_registry_add_library(r, lib_path(name), &lib, &d)) {
    fprintf(stderr, "%s\n", d.msg);
    res.failed = -1;
    return res;
  }
  for (int i = 0; i < r->n_entries; ++i)
    if (r->entries[i].library == lib) sl_battery_run(&r->entries[i], NULL, &res);
  sl_registry_destroy(r);
  return res;
}

static sl_closure *open_toy(sl_registry *r, const char *lib, const char *name) {
  const sl_closure_entry *e;
  sl_diag d;
  void *params;
  sl_closure *c = NULL;
  if (sl_registry_add_library(r, lib_path(lib), NULL, &d) ||
      sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, name, lib_path(lib), &e, &d) ||
      sl_params_new(e->desc, &params, &d) || sl_closure_create(e, params, &c, &d))
    fprintf(stderr, "open %s: %s\n", lib, d.msg);
  return c;
}

static int eval3(sl_closure *c, const double phi[3], double out[3], sl_error *err) {
  const double *in[1] = {phi};
  double *outp[1] = {out};
  sl_eval_args a = {.Q = 3, .in = in, .out = outp, .err = err};
  return sl_closure_evaluate(c, &a);
}

static void test_abi_refusals(void) {
  expect_refused("no_entry", "no symbol sl_closure_entry_v1");
  expect_refused("entry_v2", "built for closure ABI 2");
  expect_refused("wrong_major", "closure ABI 2.0; this sluice speaks ABI 1.0");
  expect_refused("wrong_real_size", "4-byte reals");
  expect_refused("two_with_one_name", "two closures named solids_pressure 'toy'");
  /* Not a shared object at all. */
  FILE *f = fopen("not_a_library.so", "w");
  CHECK(f != NULL);
  if (f) {
    fputs("this is text\n", f);
    fclose(f);
  }
  sl_registry *r;
  sl_diag d;
  CHECK(sl_registry_create(&r, NULL, 0, &d) == 0);
  CHECK(sl_registry_add_library(r, "./not_a_library.so", NULL, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "cannot load");
  CHECK(sl_registry_add_library(r, "./missing_library.so", NULL, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "missing_library.so");
  sl_registry_destroy(r);
}

static void test_scan_keeps_going(void) {
  /* A folder with broken libraries: the good ones are listed, the broken
   * ones recorded with their reason, nothing crashes. */
  sl_registry *r;
  sl_diag d;
  const char *dirs[1] = {dir};
  CHECK(sl_registry_create(&r, dirs, 1, &d) == 0);
  CHECK(sl_registry_scan(r, &d) == 0);
  CHECK_MSG(r->n_problems == 5, "%d problems", r->n_problems);
  int toys = 0;
  for (int i = 0; i < r->n_entries; ++i) toys += strcmp(r->entries[i].desc->name, "toy") == 0;
  CHECK(toys == 4); /* good, returns_nan, recoverable, wrong_derivative */
  /* Two libraries give "twin": an error unless the scene names the library. */
  const sl_closure_entry *e;
  CHECK(sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, "twin", NULL, &e, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "provided by two libraries");
  CHECK_CONTAINS(d.msg, "library = ");
  CHECK(sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, "twin", "twin_b.so", &e, &d) == 0);
  CHECK(e && strstr(e->library->path, "twin_b.so") != NULL);
  CHECK(sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, "twim", "twin_b.so", &e, &d) == SL_EBADINPUT);
  /* "toy" from four libraries is ambiguous too; an unknown name is suggested. */
  CHECK(sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, "toi", NULL, &e, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'toy'");
  sl_registry_destroy(r);
}

static void test_nan_and_recoverable(void) {
  sl_registry *r;
  sl_diag d;
  CHECK(sl_registry_create(&r, NULL, 0, &d) == 0);
  sl_closure *nan_c = open_toy(r, "returns_nan", "toy");
  sl_closure *rec_c = open_toy(r, "recoverable", "toy");
  CHECK(nan_c && rec_c);
  if (nan_c && rec_c) {
    double phi[3] = {0.1, 0.55, 0.2}, out[3];
    sl_error err;
    /* The host refuses a NaN output: recoverable, point named. */
    CHECK(eval3(nan_c, phi, out, &err) == SL_RECOVERABLE);
    CHECK(err.point == 1);
    CHECK_CONTAINS(err.msg, "output 'p_s' is nan");
    double phi2[3] = {0.1, 0.45, 0.5};
    CHECK(eval3(rec_c, phi2, out, &err) == SL_RECOVERABLE);
    CHECK(err.point == 1);
    CHECK_CONTAINS(err.msg, "toy refuses phi = 0.45");
    double ok[3] = {0.1, 0.2, 0.3};
    CHECK(eval3(rec_c, ok, out, &err) == 0);
    CHECK_CLOSE(out[2], 2.0 * 0.3 * 0.3, 1e-15);
    CHECK(rec_c->n_calls == 2 && rec_c->n_points == 6);
    CHECK(sl_registry_libraries_in_use(r) == 2);
  }
  sl_closure_destroy(nan_c);
  sl_closure_destroy(rec_c);
  CHECK(sl_registry_libraries_in_use(r) == 0);
  sl_registry_destroy(r);
}

static void test_battery_verdicts(void) {
  sl_battery_result good = battery_on("good");
  CHECK_MSG(good.failed == 0 && good.passed >= 9, "good: %d passed, %d failed", good.passed, good.failed);
  sl_battery_result nan_r = battery_on("returns_nan");
  CHECK_MSG(nan_r.failed >= 1, "returns_nan: %d failed", nan_r.failed);
  sl_battery_result deriv = battery_on("wrong_derivative");
  CHECK_MSG(deriv.failed == 1, "wrong_derivative: %d failed", deriv.failed);
}

static void test_parameters(void) {
  sl_registry *r;
  sl_diag d;
  CHECK(sl_registry_create(&r, NULL, 0, &d) == 0);
  CHECK(sl_registry_add_library(r, lib_path("good"), NULL, &d) == 0);
  const sl_closure_entry *e;
  CHECK(sl_registry_find(r, SL_KIND_SOLIDS_PRESSURE, "toy", lib_path("good"), &e, &d) == 0);
  void *params;
  CHECK(sl_params_new(e->desc, &params, &d) == 0);
  CHECK(sl_params_set(e->desc, params, "a", "11", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "outside the allowed range [0, 10]");
  CHECK(sl_params_set(e->desc, params, "a", "two", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "not a number");
  CHECK(sl_params_set(e->desc, params, "b", "1", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "has no parameter 'b'");
  CHECK(sl_params_set(e->desc, params, "aa", "1", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'a'");
  CHECK(sl_params_set(e->desc, params, "a", "3.5", &d) == 0);
  char text[64];
  sl_params_format_value(e->desc, params, 0, text, sizeof text);
  CHECK(strcmp(text, "3.5") == 0);
  sl_params_free(params);

  /* Through a scene file: the error names file:line:col of the bad key. */
  FILE *f = fopen("toy_scene.ini", "w");
  CHECK(f != NULL);
  if (f) {
    fprintf(f, "[scene]\nmodel = mixture\n\n[closure.solids_pressure]\nmodel = toy\nlibrary = good.so\na = 20\n");
    fclose(f);
  }
  sl_ini *ini = NULL;
  CHECK(sl_ini_parse_file("toy_scene.ini", &ini, &d) == 0);
  sl_closure *c = NULL;
  if (ini) {
    CHECK(sl_closure_from_ini(r, ini, "closure.solids_pressure", &c, &d) == SL_EBADINPUT);
    CHECK_CONTAINS(d.msg, "toy_scene.ini:7:1");
    CHECK_CONTAINS(d.msg, "outside the allowed range");
    CHECK(sl_ini_apply_override(ini, "closure.solids_pressure.a=4", &d) == 0);
    CHECK(sl_closure_from_ini(r, ini, "closure.solids_pressure", &c, &d) == 0);
    if (c) {
      double phi[3] = {0.1, 0.2, 0.5}, out[3];
      sl_error err;
      CHECK(eval3(c, phi, out, &err) == 0);
      CHECK_CLOSE(out[2], 4.0 * 0.25, 1e-15);
    }
    sl_closure_destroy(c);
    CHECK(sl_ini_apply_override(ini, "closure.solids_pressure.model=toyy", &d) == 0);
    CHECK(sl_closure_from_ini(r, ini, "closure.solids_pressure", &c, &d) == SL_EBADINPUT);
    CHECK_CONTAINS(d.msg, "did you mean 'toy'");
  }
  sl_ini_free(ini);
  sl_registry_destroy(r);
}

/* A descriptor that never went through the loader: its parameter default is
 * outside its own bounds, which the battery's schema check must catch. */
typedef struct bad_params {
  double a;
} bad_params;
static const sl_param_desc bad_param_table[] = {
    {"a", SL_PARAM_REAL, offsetof(bad_params, a), 20.0, 0.0, 10.0, "1", NULL, "default outside [0, 10]"},
};
static const sl_field_desc bad_inputs[] = {{"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.6, "solids fraction"}};
static const sl_field_desc bad_outputs[] = {{"p_s", "Pa", 0, 0, 0, 0, "a phi"}};
static int bad_evaluate(const void *state, const sl_eval_args *args) {
  const bad_params *p = state;
  for (int32_t q = 0; q < args->Q; ++q) {
    if (!(args->in[0][q] >= 0.0 && args->in[0][q] <= 0.6)) return sl_fail(args->err, SL_RECOVERABLE, q, "phi out");
    args->out[0][q] = p->a * args->in[0][q];
    double *dp = sl_dout(args, 1, 0, 0);
    if (dp) dp[q] = p->a;
  }
  return SL_OK;
}
static const sl_closure_desc bad_desc = {SL_CLOSURE_DESC_HEADER,
                                         .kind = SL_KIND_SOLIDS_PRESSURE,
                                         .name = "bad_default",
                                         .version = "0",
                                         .summary = "s",
                                         .formula = "f",
                                         .reference = "r",
                                         .validity = "v",
                                         .n_params = 1,
                                         .params = bad_param_table,
                                         .params_size = sizeof(bad_params),
                                         .n_in = 1,
                                         .in = bad_inputs,
                                         .n_out = 1,
                                         .out = bad_outputs,
                                         .evaluate = bad_evaluate};

static void test_battery_rechecks_schema(void) {
  sl_library lib = {.path = "(in the test program)"};
  sl_closure_entry e = {&bad_desc, &lib};
  sl_battery_result res = {0, 0, 0, NULL, NULL};
  sl_battery_run(&e, NULL, &res);
  CHECK_MSG(res.failed == 1, "bad default: %d failed", res.failed);
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s BROKEN_PLUGIN_DIR\n", argv[0]);
    return 2;
  }
  dir = argv[1];
  test_abi_refusals();
  test_scan_keeps_going();
  test_nan_and_recoverable();
  test_battery_verdicts();
  test_parameters();
  test_battery_rechecks_schema();
  return sl_test_summary();
}
