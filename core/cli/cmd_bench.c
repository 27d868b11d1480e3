/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice bench STUDY.ini: a work-precision study or a closure comparison
 * (core/study/study.h): every run of the study in its own process, each
 * output measured, one CSV row per run and the plot (SVG and PNG). */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/cli/cli.h"
#include "core/cli/progress.h"
#include "core/io/output.h"
#include "core/models/run.h"
#include "core/plugin/closure_ini.h"
#include "core/study/exact.h"
#include "core/study/measure.h"
#include "core/study/report.h"
#include "core/study/runner.h"
#include "core/study/study.h"
#include "core/util/version.h"

static const char bench_usage[] =
    "usage: sluice bench STUDY.ini [-o DIR] [--keep] [--check] [--allow-plugin-path]\n"
    "Runs a study: the study's scene once for every variant and point, each run\n"
    "in its own process; measures each output against an exact solution, a\n"
    "reference file, a value or the finest run (or, for a comparison, takes the\n"
    "quantity itself); and writes\n"
    "  DIR/STUDY.csv          one row per run: status, CPU and wall time, peak\n"
    "                         memory, steps, rejected steps, the quantity, its\n"
    "                         error and observed order, the failure message\n"
    "  DIR/STUDY.svg          error against the points (with the observed order)\n"
    "                         and against CPU time (log-log), one curve per\n"
    "                         variant; a comparison plots the quantity itself\n"
    "  DIR/STUDY.png          the same figure as a raster image\n"
    "  DIR/STUDY_compare.csv  a comparison's quantity, one column per run\n"
    "  -o DIR   where the results go (default: the current folder; created if missing)\n"
    "  --keep   keep each run's output file and log in DIR/STUDY.runs/ (the logs of\n"
    "           failed runs are always kept)\n"
    "  --check  check the study and every run's scene and closures, and stop\n"
    "  --allow-plugin-path  let the scene's [plugins] path name folders of closure\n"
    "           libraries (refused without it: docs/trust-plugins.md)\n"
    "A failed, crashed or timed-out run is recorded and the study goes on. One line\n"
    "per run on stderr. Ctrl-C stops after the current run and writes what is done.\n"
    "Exit status: 0 every run measured, 1 one or more runs failed (see the CSV),\n"
    "2 bad usage or a bad study file. The file format: docs/benchmarks.md.";

static volatile sig_atomic_t interrupted;
static void on_sigint(int sig) {
  (void)sig;
  interrupted = 1;
}

/* The run's summary line in its log, as `sluice run` prints it. */
static void log_summary(FILE *log, const sl_run_result *res, double wall, double cpu) {
  sl_run_summary s = {.steps = res->steps,
                      .rejected_steps = res->rejected_steps,
                      .nonlinear_iterations = res->nonlinear_iterations,
                      .nonlinear_name = res->model.used_picard ? "Newton/Picard" : "Newton",
                      .wall_seconds = wall,
                      .cpu_seconds = cpu,
                      .assembly = res->model.assembly,
                      .factorisation = res->factorisation,
                      .solve = res->solve,
                      .output = res->output,
                      .step_limit = res->step_limit};
  char line[512];
  sl_run_summary_format(&s, line, sizeof line);
  fprintf(log, "%s\n", line);
  if (res->model.coupling_summary[0]) fprintf(log, "sluice: %s\n", res->model.coupling_summary);
}

typedef struct bench {
  sl_study *study;
  sl_registry *reg;
  char **dirs;
  int n_dirs;
  sl_ini **inis;          /* per run, variant by variant */
  sl_bench_exact **exact; /* per run, or NULL */
  sl_bench_table table;
  int allow_plugin_path; /* --allow-plugin-path: the scene's [plugins] path may name folders */
} bench;

static void bench_free(bench *b) {
  int n = b->study ? b->study->n_variants * b->study->n_points : 0;
  for (int i = 0; i < n; ++i) {
    if (b->inis) sl_ini_free(b->inis[i]);
    if (b->exact) sl_bench_exact_free(b->exact[i]);
  }
  free(b->inis), free(b->exact);
  sl_bench_table_free(&b->table);
  sl_registry_destroy(b->reg);
  sl_plugin_dirs_free(b->dirs, b->n_dirs);
  sl_study_free(b->study);
}

static void run_name(const sl_study *s, int v, int p, char *buf, size_t len) {
  if (s->n_variants > 1 && s->n_points > 1) snprintf(buf, len, "%s; %s", s->variant_names[v], s->point_names[p]);
  else if (s->n_points > 1) snprintf(buf, len, "%s", s->point_names[p]);
  else snprintf(buf, len, "%s", s->variant_names[v]);
}

/* Every run's scene valid, its closures resolved, its exact solution set up
 * and its line fitting the geometry, before anything runs. */
static int check_runs(bench *b, sl_diag *d) {
  const sl_study *s = b->study;
  int n = s->n_variants * s->n_points, rc = 0;
  b->inis = calloc((size_t)n, sizeof *b->inis);
  b->exact = calloc((size_t)n, sizeof *b->exact);
  if (!b->inis || !b->exact) return sl_diag_set(d, SL_ENOMEM, "bench: out of memory");
  for (int v = 0; v < s->n_variants && !rc; ++v)
    for (int p = 0; p < s->n_points && !rc; ++p) {
      int i = v * s->n_points + p;
      sl_ini *ini = NULL;
      if ((rc = sl_study_run_ini(s, v, p, &ini, d))) break;
      b->inis[i] = ini;
      if (i == 0) { /* the plugin folders of the scene */
        if ((rc = sl_plugin_dirs_allowed(ini, b->allow_plugin_path, d))) break;
        if ((rc = sl_plugin_dirs_from_ini(ini, &b->dirs, &b->n_dirs, d))) break;
        if ((rc = sl_registry_create(&b->reg, (const char *const *)b->dirs, b->n_dirs, d))) break;
        /* only the libraries that hold the closures named (docs/trust-plugins.md) */
        if ((rc = sl_registry_index(b->reg, d))) break;
      }
      /* the scene as a run would take it: its keys, its closures created */
      const sl_model_entry *entry;
      sl_scene *sc = NULL;
      if ((rc = sl_model_scene(ini, b->reg, 1, 0, &entry, &sc, d))) break;
      int geometry = sc->geometry;
      sl_scene_free(sc);
      const sl_study_measure *sm = &s->m;
      const sl_ini_section *ms = sm->where;
      if (sm->has_line && (sm->line_dim == 1) != (geometry == 0)) {
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [measure] line: the scene is %s: give line = %s", ms->file, ms->line,
                         geometry == 0 ? "1-D" : "2-D", geometry == 0 ? "x0:x1" : "x0,y0:x1,y1");
        break;
      }
      if (!sm->scalar && !sm->has_line && sm->against != SL_AGAINST_EXACT && geometry != 0) {
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [measure] field = %s: the scene is 2-D: give line = x0,y0:x1,y1",
                         ms->file, ms->line, sm->name);
        break;
      }
      if (sm->against == SL_AGAINST_EXACT && (rc = sl_bench_exact_create(sm->exact, ini, b->reg, &b->exact[i], d))) {
        const sl_ini_entry *e = sl_ini_find(s->ini, "measure", "exact");
        rc = sl_diag_prefix(d, rc, "%s:%d:%d: [measure]", e->file, e->line, e->col);
        break;
      }
    }
  return rc;
}

/* mkdir, an existing folder being fine; *created says whether it is new. */
static int make_dir(const char *path, int *created, sl_diag *d) {
  *created = mkdir(path, 0777) == 0;
  if (*created || errno == EEXIST) return 0;
  return sl_diag_set(d, SL_EFAILED, "%s: %s", path, strerror(errno));
}

static void progress_line(const sl_bench_row *r, const sl_study *s) {
  const sl_bench_run_result *x = &r->run;
  if (x->status != SL_RUN_OK) {
    fprintf(stderr, "%s", sl_bench_status_name(x->status));
    if (x->signal_number) fprintf(stderr, " (signal %d)", x->signal_number);
    else if (x->status == SL_RUN_FAILED || x->status == SL_RUN_BAD_INPUT) fprintf(stderr, " (exit %d)", x->exit_code);
    fprintf(stderr, " after %.2f s: %s\n", x->wall, x->message);
    return;
  }
  fprintf(stderr, "CPU %.3g s, wall %.3g s, %.0f MB, %ld step%s (%ld rejected)", x->cpu, x->wall, x->peak_rss_mb,
          x->steps, x->steps == 1 ? "" : "s", x->rejected_steps);
  if (!r->measured) fprintf(stderr, "; not measured: %s\n", x->message);
  else if (isfinite(r->error)) fprintf(stderr, "; error %.4g\n", r->error);
  else if (!r->m.is_profile) fprintf(stderr, "; %s = %.10g\n", s->m.name, r->m.scalar);
  else fputc('\n', stderr);
}

static void remove_outputs(const char *h5) { sl_output_remove(h5); }

/* `sluice bench STUDY.ini --run-one V P OUT.h5`: one run of the study, as
 * the study's child process (fork and exec of this command) runs it, with
 * its outcome on file descriptor 3. Not for users: no --help entry. */
static int run_one(const char *path, const char *v_text, const char *p_text, const char *out, int allow_plugin_path) {
  sl_diag d = {{0}};
  sl_study *s = NULL;
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  char **dirs = NULL;
  int n_dirs = 0, code;
  long v = -1, p = -1;
  int rc = sl_study_load(path, &s, &d);
  if (!rc && (sl_parse_long(v_text, &v) || sl_parse_long(p_text, &p) || v < 0 || p < 0 || v >= s->n_variants ||
              p >= s->n_points))
    rc = sl_diag_set(&d, SL_EBADINPUT, "bench --run-one: no run %s, %s in %s", v_text, p_text, path);
  if (!rc) rc = sl_study_run_ini(s, (int)v, (int)p, &ini, &d);
  if (!rc) rc = sl_plugin_dirs_allowed(ini, allow_plugin_path, &d);
  if (!rc) rc = sl_plugin_dirs_from_ini(ini, &dirs, &n_dirs, &d);
  if (!rc) rc = sl_registry_create(&reg, (const char *const *)dirs, n_dirs, &d);
  if (!rc) rc = sl_registry_index(reg, &d);
  if (!rc) {
    const sl_model_entry *entry;
    sl_scene *sc = NULL;
    rc = sl_model_scene(ini, reg, 0, 0, &entry, &sc, &d);
    sl_scene_free(sc);
  }
  if (rc) {
    fprintf(stderr, "sluice: %s\n", d.msg);
    sl_bench_send_failure(SL_BENCH_RESULT_FD, rc, d.msg);
    code = rc == SL_EBADINPUT ? 2 : 1;
  } else {
    void (*old)(int) = signal(SIGINT, on_sigint);
    sl_bench_run_opts o = {.scene_path = s->scene,
                           .output = out,
                           .sluice_version = sl_version(),
                           .interrupt = &interrupted,
                           .summary = log_summary};
    code = sl_bench_run_here(ini, reg, &o, SL_BENCH_RESULT_FD);
    signal(SIGINT, old);
  }
  sl_registry_destroy(reg);
  sl_plugin_dirs_free(dirs, n_dirs);
  sl_ini_free(ini);
  sl_study_free(s);
  return code;
}

int sl_cmd_bench(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(bench_usage);
    return 0;
  }
  const char *path = NULL, *dir = ".";
  int keep = 0, check_only = 0, allow_plugin_path = 0;
  if ((argc == 5 || (argc == 6 && !strcmp(argv[5], "--allow-plugin-path"))) && !strcmp(argv[1], "--run-one"))
    return run_one(argv[0], argv[2], argv[3], argv[4], argc == 6);
  for (int i = 0; i < argc; ++i) {
    if (!strcmp(argv[i], "-o") && i + 1 < argc) dir = argv[++i];
    else if (!strcmp(argv[i], "--allow-plugin-path")) allow_plugin_path = 1;
    else if (!strcmp(argv[i], "--keep")) keep = 1;
    else if (!strcmp(argv[i], "--check")) check_only = 1;
    else if (argv[i][0] == '-')
      return sl_cli_error(SL_EBADINPUT, "bench: unknown option or missing value '%s' (sluice bench --help)", argv[i]);
    else if (!path) path = argv[i];
    else return sl_cli_error(SL_EBADINPUT, "bench: one study at a time ('%s' and '%s')", path, argv[i]);
  }
  if (!path) return sl_cli_error(SL_EBADINPUT, "bench: which study?\n%s", bench_usage);

  bench b;
  memset(&b, 0, sizeof b);
  b.allow_plugin_path = allow_plugin_path;
  sl_diag d = {{0}};
  int rc = sl_study_load(path, &b.study, &d);
  if (!rc) rc = check_runs(&b, &d);
  if (rc) {
    bench_free(&b);
    return sl_cli_error(rc, "%s", d.msg);
  }
  const sl_study *s = b.study;
  int n_runs = s->n_variants * s->n_points;
  if (sl_bench_table_init(&b.table, s)) {
    bench_free(&b);
    return sl_cli_error(SL_EFAILED, "bench: out of memory");
  }
  if (b.exact[0]) snprintf(b.table.exact, sizeof b.table.exact, "%s", sl_bench_exact_describe(b.exact[0]));
  char what[2048];
  sl_bench_describe_measure(&b.table, what, sizeof what);
  fprintf(stderr, "sluice: bench %s: %s, %d variant%s x %d point%s = %d run%s\nsluice: measure: %s\n", path, s->scene,
          s->n_variants, s->n_variants == 1 ? "" : "s", s->n_points, s->n_points == 1 ? "" : "s", n_runs,
          n_runs == 1 ? "" : "s", what);
  if (b.table.exact[0]) fprintf(stderr, "sluice: %s\n", b.table.exact);
  if (check_only) {
    printf("%s: study valid; %d run%s, every scene valid and its closures resolved\n", path, n_runs,
           n_runs == 1 ? "" : "s");
    bench_free(&b);
    return 0;
  }

  char runs_dir[4096], file[4300], log[4300];
  snprintf(runs_dir, sizeof runs_dir, "%s/%s.runs", dir, s->name);
  int new_dir = 0, new_runs_dir = 0;
  if ((rc = make_dir(dir, &new_dir, &d)) || (rc = make_dir(runs_dir, &new_runs_dir, &d))) {
    bench_free(&b);
    return sl_cli_error(rc, "bench: %s", d.msg);
  }
  void (*old)(int) = signal(SIGINT, on_sigint);
  int not_ok = 0, kept_logs = 0, stop = 0;
  for (int v = 0; v < s->n_variants && !stop; ++v)
    for (int p = 0; p < s->n_points && !stop; ++p) {
      int i = v * s->n_points + p;
      sl_bench_row *row = sl_bench_table_row(&b.table, v, p);
      char name[600];
      run_name(s, v, p, name, sizeof name);
      snprintf(file, sizeof file, "%s/v%02d_p%02d.h5", runs_dir, v + 1, p + 1);
      snprintf(log, sizeof log, "%s/v%02d_p%02d.log", runs_dir, v + 1, p + 1);
      fprintf(stderr, "sluice: [%*d/%d] %s: ", n_runs >= 10 ? 2 : 1, i + 1, n_runs, name);
      /* the child execs this command for the one run: its memory and clocks are its own */
      char v_text[16], p_text[16];
      snprintf(v_text, sizeof v_text, "%d", v), snprintf(p_text, sizeof p_text, "%d", p);
      char *child_argv[] = {"/proc/self/exe",
                            "bench",
                            (char *)path,
                            "--run-one",
                            v_text,
                            p_text,
                            file,
                            allow_plugin_path ? "--allow-plugin-path" : NULL,
                            NULL};
      sl_bench_run_opts o = {.argv = child_argv, .log = log, .timeout = s->timeout, .interrupt = &interrupted};
      if (sl_bench_run(&o, &row->run)) {
        fprintf(stderr, "cannot start: %s\n", row->run.message);
        rc = SL_EFAILED;
        stop = 1;
        break;
      }
      if (row->run.status == SL_RUN_OK) {
        int mrc = sl_bench_measure(s, b.exact[i], file, &row->m, &d);
        row->measured = mrc == 0;
        if (mrc) snprintf(row->run.message, sizeof row->run.message, "%.1000s", d.msg);
        if (mrc == SL_EBADINPUT) { /* the study asks for something the output does not hold: every run would say so */
          fprintf(stderr, "measure failed\n");
          const sl_ini_section *ms = s->m.where;
          char why[sizeof d.msg];
          snprintf(why, sizeof why, "%s", strncmp(d.msg, "measure: ", 9) ? d.msg : d.msg + 9);
          sl_diag_set(&d, SL_EBADINPUT, "%s:%d: [measure] %.1900s", ms->file, ms->line, why);
          if (!keep) remove_outputs(file), remove(log);
          rc = SL_EBADINPUT;
          stop = 1;
          break;
        }
        sl_bench_errors(&b.table);
      }
      progress_line(row, s);
      int ok = row->run.status == SL_RUN_OK && row->measured;
      not_ok += !ok;
      if (!keep) remove_outputs(file);
      if (ok && !keep) remove(log);
      else kept_logs = 1;
      if (interrupted) {
        fprintf(stderr, "sluice: interrupted: the study stops here; writing what is done\n");
        stop = 1;
      }
    }
  signal(SIGINT, old);
  if (rc == SL_EBADINPUT || rc == SL_EFAILED) { /* nothing written but the logs of failed runs */
    if (!kept_logs && !keep) rmdir(runs_dir);
    if (new_dir) rmdir(dir); /* only when empty */
    int code = rc;
    if (rc == SL_EBADINPUT) fprintf(stderr, "sluice: %s\n", d.msg);
    bench_free(&b);
    return code;
  }
  sl_bench_errors(&b.table);
  char csv[4300], png[4300], svg[4300], compare[4300];
  snprintf(csv, sizeof csv, "%s/%s.csv", dir, s->name);
  snprintf(png, sizeof png, "%s/%s.png", dir, s->name);
  snprintf(svg, sizeof svg, "%s/%s.svg", dir, s->name);
  snprintf(compare, sizeof compare, "%s/%s_compare.csv", dir, s->name);
  int comparison = s->m.against == SL_AGAINST_NONE;
  if (!(rc = sl_bench_write_csv(&b.table, csv, &d)) && !(rc = sl_bench_write_plot(&b.table, svg, &d)) &&
      !(rc = sl_bench_write_plot(&b.table, png, &d)) && comparison)
    rc = sl_bench_write_compare_csv(&b.table, compare, &d);
  if (!rc) {
    /* the observed orders, variant by variant */
    for (int v = 0; v < s->n_variants && !comparison && s->n_points > 1; ++v) {
      fprintf(stderr, "sluice: %s: error", s->variant_names[v]);
      for (int p = 0; p < s->n_points; ++p) fprintf(stderr, " %.3g", sl_bench_table_row(&b.table, v, p)->error);
      fprintf(stderr, "; order");
      for (int p = 1; p < s->n_points; ++p) fprintf(stderr, " %.2f", sl_bench_table_row(&b.table, v, p)->order);
      fputc('\n', stderr);
    }
    int measured = 0;
    for (int i = 0; i < n_runs; ++i) measured += b.table.rows[i].measured;
    fprintf(stderr, "sluice: wrote %s, %s, %s%s%s (%d of %d runs measured)\n", csv, svg, png, comparison ? ", " : "",
            comparison ? compare : "", measured, n_runs);
    if (kept_logs && !keep) fprintf(stderr, "sluice: the logs of the failed runs are in %s\n", runs_dir);
  }
  if (!kept_logs && !keep) rmdir(runs_dir);
  bench_free(&b);
  if (rc) return sl_cli_error(rc, "bench: %s", d.msg);
  return not_ok || interrupted ? SL_EFAILED : 0;
}
