/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Work-precision of the 1-D two-fluid model (core/models/two_fluid*.c) on
 * configs/fluidized_bed.ini and configs/fluidization_step.ini (Pringle 2001, section 4.6.1),
 * over mesh refinement (the scene's dt) and time-step refinement (100
 * cells):
 *
 *  - final: the largest |porosity - n_eq| over the bed's cells (the
 *    distributor cell and the two at the top aside) at the end of the run,
 *    n_eq the drag law's equilibrium porosity: for fluidized_bed
 *    (richardson_zaki_consistent, U = 10 mm/s) Richardson & Zaki's
 *    (U/u_t)^(1/4.65), u_t = (rho_s - rho_f) g d^2/(18 mu) (Stokes); for
 *    fluidization_step the thesis's 0.716 (Pringle 2001, section 4.6.1);
 *  - transient: the L1 distance (m) between the phi profile at t = 10 s
 *    and that of the sweep's finest run (the finest mesh, cell averages
 *    summed over the coarse cells, or the smallest dt), which measures the
 *    discretisation error of the transient itself.
 *
 * CPU time is process time spent in the run (sluice_run), the best of
 * --repeat R (default 3) for runs under 2 s.
 *
 *   bench_two_fluid_work_precision [SOURCE_DIR] [--csv PATH] [--svg PATH] [--repeat R]
 *
 * CSV on stdout (and in --csv PATH) with '#' lines for the references and
 * the machine; progress on stderr; --svg PATH writes error against CPU time
 * (core/study/chart.h). The exit status is 1 when a run failed. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_machine.h"
#include "core/io/output.h"
#include "core/study/chart.h"
#include "sluice/sluice.h"

enum { N_SCENES = 2, N_SWEEP = 6, MAX_CELLS = 400 };

static const double T_PROBE = 10.0;

typedef struct scene_spec {
  const char *name;
  double n_eq; /* equilibrium porosity of the final state */
  const char *n_eq_source;
  int cells[N_SWEEP];  /* mesh sweep at the scene's dt */
  double dts[N_SWEEP]; /* time-step sweep at 100 cells */
  const char *extra;   /* an override for every run, or NULL */
} scene_spec;

typedef struct run_result {
  int ok, cells;
  double dt, cpu, final_error, transient_l1;
  long steps;
  double profile[MAX_CELLS]; /* phi at T_PROBE, column order */
  char err[2100];
} run_result;

static double cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0.0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* phi at the output nearest t, cells in column order (the interval generator numbers them upwards). */
static int read_phi(const char *file, double t, double *phi, int n, sl_diag *d) {
  sl_output_field f;
  int rc = sl_output_read_field(file, "phi", t, &f, d);
  if (rc) return rc;
  if (f.n != n) rc = sl_diag_set(d, SL_EFAILED, "%s: %lld cells, expected %d", file, (long long)f.n, n);
  else memcpy(phi, f.values, (size_t)n * sizeof *phi);
  sl_output_field_free(&f);
  return rc;
}

static int run_once(const char *src, const scene_spec *s, int cells, double dt, run_result *r) {
  char path[4096], file[128], set[3][96];
  snprintf(path, sizeof path, "%s/configs/%s.ini", src, s->name);
  snprintf(file, sizeof file, "/tmp/sluice_bench_two_fluid_%ld.h5", (long)getpid());
  snprintf(set[0], sizeof set[0], "mesh.cells=%d", cells);
  snprintf(set[1], sizeof set[1], "time.dt=%.17g", dt);
  snprintf(set[2], sizeof set[2], "output.every=%.17g", T_PROBE);
  sl_diag d = {0};
  const char *sets[5] = {set[0], set[1], set[2], s->extra, NULL};
  sluice *sc = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets, .scan_all = 1};
  int rc = sluice_open(path, &oo, &sc, &e);
  sluice_summary res;
  sluice_run_opts o = {.scene_path = path, .output = file, .version = "bench"};
  if (!rc) {
    double c0 = cpu_seconds();
    rc = sluice_run(sc, &o, &res, &e);
    r->cpu = cpu_seconds() - c0;
    r->steps = res.steps;
  }
  if (rc) sl_diag_set(&d, rc, "%s", e.msg);
  sluice_close(sc);
  double last[MAX_CELLS];
  if (!rc) rc = read_phi(file, T_PROBE, r->profile, cells, &d);
  if (!rc) rc = read_phi(file, INFINITY, last, cells, &d);
  remove(file);
  if (rc) {
    snprintf(r->err, sizeof r->err, "%s", d.msg);
    return rc;
  }
  int top = -1;
  for (int i = 0; i < cells; ++i)
    if (last[i] > 1e-9) top = i;
  r->final_error = 0.0;
  for (int i = 1; i < top - 1; ++i) r->final_error = fmax(r->final_error, fabs(1.0 - last[i] - s->n_eq));
  r->ok = 1, r->cells = cells, r->dt = dt;
  return 0;
}

static int run_best(const char *src, const scene_spec *s, int cells, double dt, int repeat, run_result *r) {
  memset(r, 0, sizeof *r);
  for (int k = 0; k < repeat; ++k) {
    run_result t;
    memset(&t, 0, sizeof t);
    if (run_once(src, s, cells, dt, &t)) {
      *r = t;
      return 1;
    }
    if (k == 0 || t.cpu < r->cpu) *r = t;
    if (t.cpu > 2.0) break;
  }
  return 0;
}

/* L1 distance (m, column of height 1) between a profile on n cells and the reference on m = n k cells. */
static double l1_against(const run_result *a, const run_result *ref) {
  int n = a->cells, m = ref->cells, k = m / n;
  if (k * n != m) return NAN;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    double mean = 0.0;
    for (int j = 0; j < k; ++j) mean += ref->profile[i * k + j] / k;
    s += fabs(a->profile[i] - mean) / n;
  }
  return s;
}

typedef struct table {
  scene_spec spec[N_SCENES];
  run_result mesh[N_SCENES][N_SWEEP], dt[N_SCENES][N_SWEEP];
  char machine[512];
} table;

static void write_csv(FILE *f, const table *t) {
  fprintf(f, "# machine: %s\n", t->machine);
  for (int s = 0; s < N_SCENES; ++s)
    fprintf(f,
            "# %s: final porosity against %.6f (%s); transient: L1 of phi at t = %g s against the sweep's finest "
            "run\n",
            t->spec[s].name, t->spec[s].n_eq, t->spec[s].n_eq_source, T_PROBE);
  fprintf(f, "scene,sweep,cells,dt,steps,cpu_s,final_error,transient_l1\n");
  for (int s = 0; s < N_SCENES; ++s)
    for (int w = 0; w < 2; ++w)
      for (int k = 0; k < N_SWEEP; ++k) {
        const run_result *r = w ? &t->dt[s][k] : &t->mesh[s][k];
        if (!r->ok) continue;
        fprintf(f, "%s,%s,%d,%.6g,%ld,%.4g,%.3e,%.3e\n", t->spec[s].name, w ? "dt" : "mesh", r->cells, r->dt, r->steps,
                r->cpu, r->final_error, r->transient_l1);
      }
}

static int write_svg(const char *path, const table *t) {
  static double x[N_SCENES][4][N_SWEEP], y[N_SCENES][4][N_SWEEP];
  static char lab[N_SCENES][4][N_SWEEP][32];
  static const char *labp[N_SCENES][4][N_SWEEP];
  sl_chart_series ser[N_SCENES][4];
  sl_chart panels[N_SCENES];
  static const char *names[4] = {"mesh: final porosity", "mesh: profile at 10 s", "dt: final porosity",
                                 "dt: profile at 10 s"};
  static const char *colours[4] = {"#1f77b4", "#1f77b4", "#d62728", "#d62728"};
  static char titles[N_SCENES][128];
  for (int s = 0; s < N_SCENES; ++s) {
    for (int q = 0; q < 4; ++q) {
      int m = 0;
      for (int k = 0; k < N_SWEEP; ++k) {
        const run_result *r = q < 2 ? &t->mesh[s][k] : &t->dt[s][k];
        if (!r->ok) continue;
        x[s][q][m] = r->cpu, y[s][q][m] = q % 2 ? r->transient_l1 : r->final_error;
        if (q < 2) snprintf(lab[s][q][m], sizeof lab[s][q][m], "%d", r->cells);
        else snprintf(lab[s][q][m], sizeof lab[s][q][m], "%g s", r->dt);
        labp[s][q][m] = q % 2 ? lab[s][q][m] : NULL;
        ++m;
      }
      ser[s][q] = (sl_chart_series){.name = names[q],
                                    .n = m,
                                    .x = x[s][q],
                                    .y = y[s][q],
                                    .labels = labp[s][q],
                                    .colour = colours[q],
                                    .marker = q < 2 ? SL_CHART_MARK_CIRCLE : SL_CHART_MARK_SQUARE,
                                    .dashed = q % 2 == 0};
    }
    snprintf(titles[s], sizeof titles[s], "%s", t->spec[s].name);
    panels[s] = (sl_chart){.xscale = SL_AXIS_LOG,
                           .yscale = SL_AXIS_LOG,
                           .title = titles[s],
                           .xlabel = "CPU time of the run (s)",
                           .ylabel = "final porosity error; L_{1} error in \xCF\x86 at 10 s (m)",
                           .n_series = 4,
                           .series = ser[s],
                           .legend = SL_LEGEND_AUTO,
                           .yspan = {s == 0 ? 0.0 : 1e-10, s == 0 ? 0.0 : 1e-1}}; /* room for the legend */
  }
  char note[1024];
  snprintf(
      note, sizeof note,
      "Mesh sweeps at the scene's dt, dt sweeps at 100 cells; profile errors against the sweep's finest run.\n"
      "Final: max |porosity \xE2\x88\x92 equilibrium| over the bed at the end (the discrete steady state is the drag's "
      "equilibrium: this is the stopping tolerance).\n%s.",
      t->machine);
  sl_figure fig = {.title = "1-D two-fluid model: error against CPU time",
                   .note = note,
                   .n_panels = N_SCENES,
                   .panels = panels,
                   .columns = N_SCENES,
                   .panel_width = 520,
                   .panel_height = 440};
  sl_diag d = {{0}};
  if (sl_figure_write(path, &fig, &d)) return fprintf(stderr, "%s\n", d.msg), -1;
  return 0;
}

/* The table back from a CSV this program wrote (--replot): the figure again
 * from recorded measurements, without running anything. Returns 0 or -1. */
static int read_csv(const char *path, table *t) {
  FILE *f = fopen(path, "r");
  if (!f) return fprintf(stderr, "%s: %s\n", path, strerror(errno)), -1;
  char line[4096];
  int rows = 0, lineno = 0, bad = 0;
  while (fgets(line, sizeof line, f)) {
    ++lineno;
    if (!strncmp(line, "# machine: ", 11)) {
      snprintf(t->machine, sizeof t->machine, "%.*s", (int)strcspn(line + 11, "\n"), line + 11);
      continue;
    }
    if (line[0] == '#' || !strncmp(line, "scene,", 6)) continue;
    char scene[64], sweep[8];
    run_result r = {.ok = 1};
    if (sscanf(line, "%63[^,],%7[^,],%d,%lf,%ld,%lf,%lf,%lf", scene, sweep, &r.cells, &r.dt, &r.steps, &r.cpu,
               &r.final_error, &r.transient_l1) != 8) {
      fprintf(stderr, "%s:%d: not a row of this program's CSV\n", path, lineno);
      bad = 1;
      break;
    }
    int placed = 0;
    for (int s = 0; s < N_SCENES && !placed; ++s) {
      if (strcmp(scene, t->spec[s].name)) continue;
      int dt_sweep = !strcmp(sweep, "dt");
      for (int k = 0; k < N_SWEEP && !placed; ++k)
        if (dt_sweep ? fabs(t->spec[s].dts[k] - r.dt) <= 1e-9 * r.dt : t->spec[s].cells[k] == r.cells) {
          (dt_sweep ? t->dt[s] : t->mesh[s])[k] = r;
          placed = 1;
        }
    }
    if (!placed) {
      fprintf(stderr, "%s:%d: %s, %s sweep, %d cells, dt %g is not one of this program's runs\n", path, lineno, scene,
              sweep, r.cells, r.dt);
      bad = 1;
      break;
    }
    ++rows;
  }
  fclose(f);
  if (!bad && rows == 0) fprintf(stderr, "%s: no rows\n", path), bad = 1;
  return bad ? -1 : 0;
}

static int usage(void) {
  fprintf(stderr,
          "usage: bench_two_fluid_work_precision [SOURCE_DIR] [--csv PATH] [--svg PATH] [--repeat R]\n"
          "       bench_two_fluid_work_precision --replot CSV --svg PATH   (the figure of recorded runs)\n");
  return 2;
}

int main(int argc, char **argv) {
  const char *src = ".", *csv = NULL, *svg = NULL, *replot = NULL;
  int repeat = 3;
  for (int a = 1; a < argc; ++a) {
    if (!strcmp(argv[a], "--csv") && a + 1 < argc) csv = argv[++a];
    else if (!strcmp(argv[a], "--svg") && a + 1 < argc) svg = argv[++a];
    else if (!strcmp(argv[a], "--replot") && a + 1 < argc) replot = argv[++a];
    else if (!strcmp(argv[a], "--repeat") && a + 1 < argc) {
      repeat = atoi(argv[++a]);
      if (repeat < 1 || repeat > 100) return usage();
    } else if (argv[a][0] != '-') src = argv[a];
    else return usage();
  }
  static table t;
  /* Richardson & Zaki (1954) with Stokes' u_t for fluidized_bed's 0.3 mm sand in water at 10 mm/s */
  const double ut = (2600.0 - 998.2) * 9.81 * 3e-4 * 3e-4 / (18.0 * 1.002e-3);
  t.spec[0] = (scene_spec){"fluidized_bed",
                           pow(0.010 / ut, 1.0 / 4.65),
                           "Richardson-Zaki, the drag's own law",
                           {25, 50, 100, 200, 400, 0},
                           {0.8, 0.4, 0.2, 0.1, 0.05, 0.025},
                           NULL};
  t.spec[1] = (scene_spec){"fluidization_step",
                           0.716,
                           "Pringle 2001, section 4.6.1",
                           {25, 50, 100, 200, 400, 0},
                           {0.16, 0.08, 0.04, 0.02, 0.01, 0.005},
                           NULL};
  if (replot) {
    if (!svg) return usage();
    if (read_csv(replot, &t)) return 2;
    return write_svg(svg, &t) ? 1 : 0;
  }
  bench_machine_describe(t.machine, sizeof t.machine);
  int failures = 0;
  for (int s = 0; s < N_SCENES; ++s) {
    const scene_spec *sp = &t.spec[s];
    double dt_scene = sp == &t.spec[0] ? 0.05 : 0.01; /* the scenes' own steps */
    for (int w = 0; w < 2; ++w) {
      run_result *row = w ? t.dt[s] : t.mesh[s];
      int last = -1;
      for (int k = 0; k < N_SWEEP; ++k) {
        int cells = w ? 100 : sp->cells[k];
        double dt = w ? sp->dts[k] : dt_scene;
        if (cells <= 0) continue;
        fprintf(stderr, "%s, %d cells, dt %g ...", sp->name, cells, dt);
        if (run_best(src, sp, cells, dt, repeat, &row[k])) {
          fprintf(stderr, " failed: %s\n", row[k].err);
          ++failures;
          continue;
        }
        fprintf(stderr, " %.3g s CPU, final error %.2e\n", row[k].cpu, row[k].final_error);
        last = k;
      }
      for (int k = 0; k < N_SWEEP && last >= 0; ++k)
        if (row[k].ok) row[k].transient_l1 = k == last ? NAN : l1_against(&row[k], &row[last]);
    }
  }
  write_csv(stdout, &t);
  if (csv) {
    FILE *f = fopen(csv, "w");
    if (!f) return fprintf(stderr, "%s: %s\n", csv, strerror(errno)), 1;
    write_csv(f, &t);
    int werr = ferror(f);
    if (fclose(f) || werr) return fprintf(stderr, "%s: write failed\n", csv), 1;
  }
  if (svg && write_svg(svg, &t)) return 1; /* the reason is on stderr */
  if (fflush(stdout)) return 1;
  return failures ? 1 : 0;
}
