/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Runs a scene of configs/ with overrides in-process, as `sluice run` does
 * (parse, --set overrides, validation, every [closure.*] section checked,
 * the plugin index that loads only the closures a scene names), through the
 * embedding API (sluice/sluice.h); and reads an output file back to check every value
 * of every field at every output time. Shared by tests/stress and
 * tests/skipping. */
#ifndef SLUICE_TESTS_STRESS_CASE_RUNNER_H
#define SLUICE_TESTS_STRESS_CASE_RUNNER_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/io/sample.h"
#include "sluice/sluice.h"

typedef struct scene_case {
  sluice *s; /* kept after the run: what it loaded and what its closures did */
} scene_case;

static inline void scene_case_close(scene_case *c) {
  sluice_close(c->s);
  memset(c, 0, sizeof *c);
}

/* configs/<scene>.ini with the overrides `sets` (NULL-terminated, may be
 * NULL); timing: closures time their calls (the profile's clock). Its keys
 * and closures are checked (nothing run). */
static inline int scene_case_open(scene_case *c, const char *configs, const char *scene, const char *const *sets,
                                  int timing, sl_diag *d) {
  memset(c, 0, sizeof *c);
  char path[4200];
  snprintf(path, sizeof path, "%s/%s.ini", configs, scene);
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets, .timing = timing};
  double t0, t1;
  int rc = sluice_open(path, &oo, &c->s, &e);
  if (!rc) rc = sluice_time_span(c->s, &t0, &t1, &e);
  if (rc) {
    sl_diag_set(d, rc, "%s", e.msg);
    scene_case_close(c);
  }
  return rc;
}

static inline int scene_case_run(scene_case *c, const char *scene_path, const char *out, sluice_summary *res,
                                 sl_diag *d) {
  sluice_error e = {0, ""};
  sluice_run_opts o = {.scene_path = scene_path, .output = out, .version = "test"};
  int rc = sluice_run(c->s, &o, res, &e);
  if (rc) sl_diag_set(d, rc, "%s", e.msg);
  return rc;
}

/* The libraries a run has loaded whose file name starts with `prefix`. */
static inline int scene_case_loaded(const scene_case *c, const char *prefix) {
  return sluice_plugins_loaded(c->s, prefix);
}

/* The libraries loaded, on the search path, and the dlopen calls so far. */
static inline int scene_case_n_loaded(const scene_case *c) {
  sluice_plugins p;
  sluice_plugin_counts(c->s, &p);
  return p.loaded;
}
static inline int scene_case_on_path(const scene_case *c) {
  sluice_plugins p;
  sluice_plugin_counts(c->s, &p);
  return p.on_path;
}
static inline long scene_case_dlopen(const scene_case *c) {
  sluice_plugins p;
  sluice_plugin_counts(c->s, &p);
  return p.dlopen;
}

/* The usage of closure kind/name over the run, or NULL when never created. */
static inline const sluice_closure_use *scene_case_usage(const scene_case *c, const char *kind, const char *name) {
  static sluice_closure_use u[4];
  static int next;
  sluice_closure_use *x = &u[next++ % 4];
  return sluice_closure_usage(c->s, kind, name, x) ? NULL : x;
}

/* What an output file holds, every value read back. */
typedef struct file_check {
  int n_times;            /* complete output times */
  double t_first, t_last; /* their range */
  int n_fields;           /* distinct fields */
  long n_datasets;        /* (time, field) pairs read */
  long n_values;          /* values checked */
  long n_nonfinite;       /* NaN or infinite values */
  long n_phi_outside;     /* phi values outside [0, phi_max] */
  double phi_min, phi_max_seen;
  int has_phi;
  int checkpoint_ok; /* the last checkpoint reads back, every array finite */
  double checkpoint_time;
  char error[512]; /* a read failure ("" when none) */
} file_check;

/* Reads every field of every complete output time and the last checkpoint.
 * phi (a field named "phi") must lie in [0, phi_max] when phi_max > 0.
 * Returns 0 when the file could be read (the counts say what it holds). */
static inline int check_output_file(const char *path, double phi_max, file_check *fc) {
  memset(fc, 0, sizeof *fc);
  fc->phi_min = INFINITY, fc->phi_max_seen = -INFINITY;
  sl_diag d;
  sl_output_contents ct;
  if (sl_output_read_contents(path, &ct, &d)) {
    snprintf(fc->error, sizeof fc->error, "%.500s", d.msg);
    return 1;
  }
  fc->n_times = ct.n_steps;
  fc->n_fields = ct.n_fields;
  if (ct.n_steps > 0) fc->t_first = ct.times[0], fc->t_last = ct.times[ct.n_steps - 1];
  int rc = 0;
  for (int k = 0; k < ct.n_steps && !rc; ++k) {
    for (int j = 0; j < ct.n_fields && !rc; ++j) {
      sl_output_field f;
      if (sl_output_read_field_at(path, ct.fields[j].name, k, &f, &d)) continue; /* not written at this time */
      fc->n_datasets++;
      int is_phi = strcmp(ct.fields[j].name, "phi") == 0;
      fc->has_phi |= is_phi;
      size_t n = (size_t)f.n * (size_t)f.components;
      for (size_t i = 0; i < n; ++i) {
        double v = f.values[i];
        fc->n_values++;
        if (!isfinite(v)) {
          fc->n_nonfinite++;
          continue;
        }
        if (is_phi) {
          fc->phi_min = fmin(fc->phi_min, v), fc->phi_max_seen = fmax(fc->phi_max_seen, v);
          if (phi_max > 0 && (v < 0.0 || v > phi_max)) fc->n_phi_outside++;
        }
      }
      sl_output_field_free(&f);
    }
  }
  sl_output_contents_free(&ct);
  sl_checkpoint ck;
  if (sl_checkpoint_read(path, &ck, &d) == 0) {
    int finite = 1;
    for (int a = 0; a < ck.n_arrays; ++a)
      for (int64_t i = 0; i < ck.arrays[a].n; ++i) finite &= isfinite(ck.arrays[a].data[i]) != 0;
    fc->checkpoint_ok = finite && isfinite(ck.time);
    fc->checkpoint_time = ck.time;
    sl_checkpoint_free(&ck);
  } else {
    snprintf(fc->error, sizeof fc->error, "checkpoint: %.480s", d.msg);
  }
  return rc;
}

#endif
