/* SPDX-License-Identifier: GPL-2.0-or-later */
/* How the cost of each phase of a run grows with the number of cells: the
 * scenes of configs/ at increasing mesh sizes, each run in-process (the
 * engine `sluice run` uses) in a child process of its own, and per phase the
 * time of one operation:
 *
 *   assembly        the assembly's wall time over the assemblies done
 *                   (matrix and right-hand side, or right-hand side only);
 *   factorisation   the numeric factorisations' wall time over their number
 *                   (the one symbolic analysis of a run is left out);
 *   solve           the back-substitutions' wall time over their number;
 *   transport       the solids transport's CPU time (face fluxes and the
 *                   finite-volume update of phi) over its sub-steps.
 *
 * Each phase's time is the fastest of --repeat R runs (default 3). The growth
 * exponent p of time ~ cells^p is the least-squares slope of log time
 * against log cells over the sizes run; the exponents between successive
 * sizes are written too.
 *
 * The scenes (every size the same steps, so that the counts match):
 *   cavity_stokes    steady Stokes, Q2/Q1 on n x n cells, n = 16..128: one
 *                    assembly, factorisation and solve;
 *   kynch_settling   1-D mixture (MUSCL transport), 250..4000 cells, 100
 *                    steps of 0.004 s: short enough for one transport
 *                    sub-step a step on every mesh (CFL);
 *   boycott          2-D mixture (Navier-Stokes at Re 1000 and MUSCL
 *                    transport), 12 x 16 .. 48 x 64 cells, 10 steps of 1e-3 s.
 *
 *   bench_cost_scaling [SOURCE_DIR] [--repeat R] [--csv PATH] [--svg PATH]
 *                      [--max-cells N] [--scene NAME]...
 *
 * CSV on stdout (and in --csv PATH) with '#' lines for the machine and the
 * fitted exponents; progress on stderr; --svg PATH writes time per operation
 * against cells, one panel per scene (core/study/chart.h). --max-cells N leaves out
 * the larger meshes; --scene NAME runs only the scenes named. The exit status
 * is 1 when a run failed. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include "bench_child.h"
#include "bench_machine.h"
#include "core/study/chart.h"
#include "sluice/sluice.h"

enum { MAX_SIZES = 8, MAX_SETS = 6, N_PHASES = 4, N_SCENES = 3 };
enum { PHASE_ASSEMBLY, PHASE_FACTORISATION, PHASE_SOLVE, PHASE_TRANSPORT };

static const char *const phase_names[N_PHASES] = {"assembly", "factorisation", "solve", "transport"};

typedef struct scene_spec {
  const char *name;
  const char *what;           /* for the CSV */
  const char *title;          /* of its panel */
  const char *sets[MAX_SETS]; /* overrides of every run, NULL-terminated */
  int n_sizes;
  int nx[MAX_SIZES], ny[MAX_SIZES]; /* ny 0: a 1-D mesh */
  int has_transport;
} scene_spec;

static const scene_spec scenes[N_SCENES] = {
    {"cavity_stokes",
     "steady Stokes cavity, Q2/Q1",
     "cavity_stokes: 2-D Stokes, steady",
     {NULL},
     4,
     {16, 32, 64, 128},
     {16, 32, 64, 128},
     0},
    {"kynch_settling",
     "1-D batch settling, mixture model, MUSCL, 100 steps",
     "kynch_settling: 1-D mixture, 100 steps",
     {"time.end=0.4", "time.dt=0.004", "output.every=0.4", NULL},
     5,
     {250, 500, 1000, 2000, 4000},
     {0},
     1},
    {"boycott",
     "2-D Boycott settling, mixture model, 10 steps",
     "boycott: 2-D mixture, 10 steps",
     {"time.end=0.01", "time.dt=1e-3", "time.adaptive=false", "output.every=0.01", NULL},
     3,
     {12, 24, 48},
     {16, 32, 64},
     1},
};

typedef struct run_result {
  int ok;
  char err[2100];
  double cpu, wall;                                     /* of the run, s */
  double assembly, symbolic, numeric, solve, transport; /* totals, s */
  long assemblies, symbolics, numerics, solves, substeps, steps;
} run_result;

static double clock_s(clockid_t id) {
  struct timespec ts;
  if (clock_gettime(id, &ts)) return NAN;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long cells_of(const scene_spec *s, int k) { return s->ny[k] ? (long)s->nx[k] * s->ny[k] : s->nx[k]; }

static void mesh_text(const scene_spec *s, int k, char *buf, size_t len) {
  if (s->ny[k]) snprintf(buf, len, "%d x %d", s->nx[k], s->ny[k]);
  else snprintf(buf, len, "%d", s->nx[k]);
}

/* ---- one run, in the child ---------------------------------------------------------- */

static int run(const char *src, const scene_spec *s, int k, run_result *r) {
  memset(r, 0, sizeof *r);
  char path[4096], file[128], set[96];
  snprintf(path, sizeof path, "%s/configs/%s.ini", src, s->name);
  snprintf(file, sizeof file, "/tmp/sluice_bench_cost_%ld.h5", (long)getpid());
  if (s->ny[k]) snprintf(set, sizeof set, "mesh.cells=%d,%d", s->nx[k], s->ny[k]);
  else snprintf(set, sizeof set, "mesh.cells=%d", s->nx[k]);
  const char *sets[20];
  int n_sets = 0;
  sets[n_sets++] = set;
  for (int j = 0; s->sets[j] && n_sets < 18; ++j) sets[n_sets++] = s->sets[j];
  sets[n_sets] = NULL;
  sluice *sc = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets, .scan_all = 1};
  int rc = sluice_open(path, &oo, &sc, &e);
  sluice_summary res;
  memset(&res, 0, sizeof res);
  sluice_run_opts o = {.scene_path = path, .output = file, .version = "bench"};
  if (!rc) {
    double c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID), w0 = clock_s(CLOCK_MONOTONIC);
    rc = sluice_run(sc, &o, &res, &e);
    r->cpu = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0, r->wall = clock_s(CLOCK_MONOTONIC) - w0;
  }
  if (!rc) {
    r->assembly = res.assembly, r->assemblies = res.matrix_assemblies + res.residual_assemblies;
    r->symbolic = res.linear.t_symbolic, r->symbolics = res.linear.n_symbolic;
    r->numeric = res.linear.t_numeric, r->numerics = res.linear.n_numeric;
    r->solve = res.linear.t_solve, r->solves = res.linear.n_solves;
    r->transport = res.cpu_coupled, r->steps = res.steps;
    /* the mixture's summary: "solids: N transport sub-steps (...)" (core/models/mixture/mixture.c) */
    const char *sub = strstr(res.coupling_summary, "solids: ");
    if (s->has_transport && (!sub || sscanf(sub, "solids: %ld transport sub-steps", &r->substeps) != 1))
      rc = 1, snprintf(e.msg, sizeof e.msg, "no transport sub-step count in '%s'", res.coupling_summary);
  }
  if (rc) snprintf(r->err, sizeof r->err, "%s", e.msg);
  r->ok = !rc;
  bench_remove_output(file);
  sluice_close(sc);
  return rc;
}

typedef struct child_args {
  const char *src;
  const scene_spec *s;
  int k;
} child_args;

static void child_run(void *arg, void *result) {
  const child_args *a = arg;
  run(a->src, a->s, a->k, result);
}

/* One run in a child process (its memory and clocks its own). */
static int run_child(const char *src, const scene_spec *s, int k, run_result *r) {
  child_args a = {src, s, k};
  char why[sizeof r->err];
  if (bench_in_child(child_run, &a, r, sizeof *r, why, sizeof why)) {
    snprintf(r->err, sizeof r->err, "%s", why);
    return -1;
  }
  return r->ok ? 0 : -1;
}

/* ---- the table ------------------------------------------------------------------------ */

typedef struct point {
  int ok;
  long cells, steps, assemblies, numerics, solves, substeps;
  double cpu;              /* the fastest run's CPU time */
  double per_op[N_PHASES]; /* each phase's fastest time per operation (NaN: not in this scene) */
  double symbolic;         /* the fastest symbolic analysis, s */
} point;

/* Time per operation of each phase of one run. */
static void per_operation(const run_result *r, int has_transport, double out[N_PHASES]) {
  out[PHASE_ASSEMBLY] = r->assemblies > 0 ? r->assembly / (double)r->assemblies : NAN;
  out[PHASE_FACTORISATION] = r->numerics > 0 ? r->numeric / (double)r->numerics : NAN;
  out[PHASE_SOLVE] = r->solves > 0 ? r->solve / (double)r->solves : NAN;
  out[PHASE_TRANSPORT] = has_transport && r->substeps > 0 ? r->transport / (double)r->substeps : NAN;
}

/* R runs of one size: per phase the fastest. The counts must agree between repeats. */
static int measure(const char *src, const scene_spec *s, int k, int repeat, point *pt, char *err, size_t len) {
  memset(pt, 0, sizeof *pt);
  for (int q = 0; q < N_PHASES; ++q) pt->per_op[q] = NAN;
  pt->cells = cells_of(s, k), pt->cpu = pt->symbolic = INFINITY;
  for (int i = 0; i < repeat; ++i) {
    run_result r;
    if (run_child(src, s, k, &r)) {
      snprintf(err, len, "%s", r.err);
      return -1;
    }
    double op[N_PHASES];
    per_operation(&r, s->has_transport, op);
    for (int q = 0; q < N_PHASES; ++q)
      if (isfinite(op[q])) pt->per_op[q] = isfinite(pt->per_op[q]) ? fmin(pt->per_op[q], op[q]) : op[q];
    if (r.symbolics > 0) pt->symbolic = fmin(pt->symbolic, r.symbolic / (double)r.symbolics);
    pt->cpu = fmin(pt->cpu, r.cpu);
    pt->steps = r.steps, pt->assemblies = r.assemblies, pt->numerics = r.numerics, pt->solves = r.solves;
    pt->substeps = r.substeps;
  }
  pt->ok = 1;
  return 0;
}

/* Least-squares slope of log y against log x over the points where both are positive; NaN below two. */
static double fit_exponent(int n, const long *x, const double *y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int m = 0;
  for (int i = 0; i < n; ++i) {
    if (!(x[i] > 0) || !(y[i] > 0) || !isfinite(y[i])) continue;
    double lx = log((double)x[i]), ly = log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++m;
  }
  if (m < 2) return NAN;
  double den = m * sxx - sx * sx;
  return den > 0 ? (m * sxy - sx * sy) / den : NAN;
}

typedef struct scene_table {
  const scene_spec *spec;
  int n; /* sizes run */
  point pts[MAX_SIZES];
  double p[N_PHASES]; /* fitted exponents */
} scene_table;

static void fit_scene(scene_table *t) {
  long x[MAX_SIZES];
  double y[MAX_SIZES];
  for (int q = 0; q < N_PHASES; ++q) {
    int m = 0;
    for (int k = 0; k < t->n; ++k)
      if (t->pts[k].ok) x[m] = t->pts[k].cells, y[m++] = t->pts[k].per_op[q];
    t->p[q] = fit_exponent(m, x, y);
  }
}

static void write_csv(FILE *f, const scene_table *tables, int n_tables, const char *machine, int repeat) {
  fprintf(f, "# bench_cost_scaling: time per operation of each phase against the number of cells\n");
  fprintf(f, "# machine: %s\n", machine);
  fprintf(f,
          "# each phase's fastest of %d runs; assembly, factorisation (numeric) and solve are wall time per "
          "operation, transport CPU time per transport sub-step\n",
          repeat);
  for (int i = 0; i < n_tables; ++i) {
    const scene_table *t = &tables[i];
    fprintf(f, "# %s (%s): fitted p in time ~ cells^p:", t->spec->name, t->spec->what);
    int fitted = 0;
    for (int q = 0; q < N_PHASES; ++q) fitted |= isfinite(t->p[q]);
    if (!fitted) {
      fprintf(f, " none (fewer than two sizes measured)\n");
      continue;
    }
    for (int q = 0; q < N_PHASES; ++q)
      if (isfinite(t->p[q])) fprintf(f, " %s %.3f", phase_names[q], t->p[q]);
    fprintf(f, "; between sizes:");
    for (int q = 0; q < N_PHASES; ++q) {
      if (!isfinite(t->p[q])) continue;
      fprintf(f, " %s", phase_names[q]);
      for (int k = 1; k < t->n; ++k) {
        const point *a = &t->pts[k - 1], *b = &t->pts[k];
        if (a->ok && b->ok && a->per_op[q] > 0 && b->per_op[q] > 0)
          fprintf(f, " %.2f", log(b->per_op[q] / a->per_op[q]) / log((double)b->cells / (double)a->cells));
      }
    }
    fputc('\n', f);
  }
  fprintf(f,
          "scene,mesh,cells,steps,assemblies,factorisations,solves,transport_substeps,cpu_s,assembly_s,"
          "factorisation_s,solve_s,transport_s,symbolic_s,status\n");
  for (int i = 0; i < n_tables; ++i) {
    const scene_table *t = &tables[i];
    for (int k = 0; k < t->n; ++k) {
      const point *pt = &t->pts[k];
      char mesh[64];
      mesh_text(t->spec, k, mesh, sizeof mesh);
      fprintf(f, "%s,%s,%ld,", t->spec->name, mesh, pt->cells);
      if (!pt->ok) {
        fprintf(f, ",,,,,,,,,,,failed\n"); /* the 11 columns from steps to symbolic_s empty, then the status */
        continue;
      }
      fprintf(f, "%ld,%ld,%ld,%ld,%ld,%.4g", pt->steps, pt->assemblies, pt->numerics, pt->solves, pt->substeps,
              pt->cpu);
      for (int q = 0; q < N_PHASES; ++q) {
        if (isfinite(pt->per_op[q])) fprintf(f, ",%.4e", pt->per_op[q]);
        else fputc(',', f);
      }
      if (isfinite(pt->symbolic)) fprintf(f, ",%.4e,ok\n", pt->symbolic);
      else fprintf(f, ",,ok\n");
    }
  }
}

static int write_svg(const char *path, const scene_table *tables, int n_tables, const char *machine, int repeat) {
  static const char *const colours[N_PHASES] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e"};
  static const sl_chart_marker markers[N_PHASES] = {SL_CHART_MARK_CIRCLE, SL_CHART_MARK_SQUARE, SL_CHART_MARK_TRIANGLE,
                                                    SL_CHART_MARK_DIAMOND};
  sl_chart_series series[N_SCENES][N_PHASES + 1];
  sl_chart panels[N_SCENES];
  double x[N_SCENES][MAX_SIZES], y[N_SCENES][N_PHASES][MAX_SIZES], guide_x[N_SCENES][2], guide_y[N_SCENES][2];
  char names[N_SCENES][N_PHASES][64];
  int np = 0;
  for (int i = 0; i < n_tables && np < N_SCENES; ++i) {
    const scene_table *t = &tables[i];
    int ns = 0;
    for (int k = 0; k < t->n; ++k) x[np][k] = (double)t->pts[k].cells;
    for (int q = 0; q < N_PHASES; ++q) {
      int any = 0;
      for (int k = 0; k < t->n; ++k) {
        y[np][q][k] = t->pts[k].ok ? t->pts[k].per_op[q] : NAN;
        any |= y[np][q][k] > 0.0;
      }
      if (!any) continue;
      if (isfinite(t->p[q])) snprintf(names[np][q], sizeof names[np][q], "%s, p = %.2f", phase_names[q], t->p[q]);
      else snprintf(names[np][q], sizeof names[np][q], "%s", phase_names[q]);
      series[np][ns++] = (sl_chart_series){
          .name = names[np][q], .n = t->n, .x = x[np], .y = y[np][q], .colour = colours[q], .marker = markers[q]};
    }
    /* a slope-1 guide from the first assembly point across the sizes */
    if (t->n >= 2 && isfinite(y[np][PHASE_ASSEMBLY][0]) && isfinite(t->p[PHASE_ASSEMBLY])) {
      guide_x[np][0] = x[np][0], guide_x[np][1] = x[np][t->n - 1];
      guide_y[np][0] = y[np][PHASE_ASSEMBLY][0], guide_y[np][1] = guide_y[np][0] * guide_x[np][1] / guide_x[np][0];
      series[np][ns++] = (sl_chart_series){.name = "\xE2\x88\x9D cells^{1}",
                                           .n = 2,
                                           .x = guide_x[np],
                                           .y = guide_y[np],
                                           .colour = "#7f7f7f",
                                           .marker = SL_CHART_MARK_NONE,
                                           .dashed = 1};
    }
    if (ns == 0) continue; /* no run of this scene succeeded */
    panels[np] = (sl_chart){.xscale = SL_AXIS_LOG,
                            .yscale = SL_AXIS_LOG,
                            .title = t->spec->title,
                            .xlabel = "cells",
                            .ylabel = "time per operation (s)",
                            .n_series = ns,
                            .series = series[np],
                            .legend = SL_LEGEND_AUTO};
    ++np;
  }
  char note[1024];
  snprintf(note, sizeof note,
           "Each phase's fastest of %d runs: assembly, numeric factorisation and back-substitution wall time per "
           "operation, transport CPU time per sub-step.\np: least-squares slope of log time against log cells. "
           "Machine: %s.",
           repeat, machine);
  sl_figure fig = {.title = "Cost per operation against cells (bench_cost_scaling)",
                   .note = note,
                   .n_panels = np,
                   .panels = panels,
                   .columns = np,
                   .panel_width = 440,
                   .panel_height = 380};
  sl_diag d = {{0}};
  if (sl_figure_write(path, &fig, &d)) return fprintf(stderr, "%s\n", d.msg), -1;
  return 0;
}

/* The tables back from a CSV this program wrote (--replot): the figure again
 * from recorded measurements, running nothing. Returns 0 or -1. */
static int read_csv(const char *path, scene_table *tables, int *n_tables, char *machine, size_t mlen, int *repeat) {
  FILE *f = fopen(path, "r");
  if (!f) return fprintf(stderr, "%s: %s\n", path, strerror(errno)), -1;
  char line[4096];
  int lineno = 0, bad = 0;
  *n_tables = 0;
  while (!bad && fgets(line, sizeof line, f)) {
    ++lineno;
    line[strcspn(line, "\r\n")] = '\0';
    if (!strncmp(line, "# machine: ", 11)) snprintf(machine, mlen, "%.400s", line + 11);
    const char *fastest = strstr(line, "fastest of ");
    if (line[0] == '#' && fastest) *repeat = atoi(fastest + 11);
    if (line[0] == '#' || !strncmp(line, "scene,", 6)) continue;
    /* scene,mesh,cells, then steps .. symbolic_s (11 fields, empty when failed), status */
    char *field[16];
    int n = 0;
    for (char *q = line; n < 16;) {
      field[n++] = q;
      char *comma = strchr(q, ',');
      if (!comma) break;
      *comma = '\0', q = comma + 1;
    }
    int spec = -1;
    for (int i = 0; n == 15 && i < N_SCENES; ++i)
      if (!strcmp(field[0], scenes[i].name)) spec = i;
    if (spec < 0) {
      fprintf(stderr, "%s:%d: not a row of this program's CSV\n", path, lineno);
      bad = 1;
      break;
    }
    scene_table *t = NULL;
    for (int i = 0; i < *n_tables; ++i)
      if (tables[i].spec == &scenes[spec]) t = &tables[i];
    if (!t) {
      t = &tables[(*n_tables)++];
      memset(t, 0, sizeof *t);
      t->spec = &scenes[spec];
    }
    if (t->n == MAX_SIZES) {
      fprintf(stderr, "%s:%d: more sizes than this program runs\n", path, lineno);
      bad = 1;
      break;
    }
    point *pt = &t->pts[t->n++];
    pt->cells = atol(field[2]);
    pt->ok = !strcmp(field[14], "ok");
    pt->cpu = pt->ok ? atof(field[8]) : NAN;
    for (int q = 0; q < N_PHASES; ++q) pt->per_op[q] = pt->ok && field[9 + q][0] ? atof(field[9 + q]) : NAN;
    pt->symbolic = pt->ok && field[13][0] ? atof(field[13]) : NAN;
  }
  fclose(f);
  if (!bad && *n_tables == 0) fprintf(stderr, "%s: no rows\n", path), bad = 1;
  for (int i = 0; !bad && i < *n_tables; ++i) fit_scene(&tables[i]);
  return bad ? -1 : 0;
}

/* ---- main ----------------------------------------------------------------------------- */

static int usage(void) {
  fprintf(stderr,
          "usage: bench_cost_scaling [SOURCE_DIR] [--repeat R] [--csv PATH] [--svg PATH] [--max-cells N] "
          "[--scene NAME]...\n"
          "       bench_cost_scaling --replot CSV --svg PATH   (the figure of recorded runs)\n");
  return 2;
}

int main(int argc, char **argv) {
  const char *src = ".", *csv = NULL, *svg = NULL, *replot = NULL;
  const char *only[N_SCENES];
  int n_only = 0, repeat = 3;
  long max_cells = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else if (!strcmp(argv[i], "--svg") && i + 1 < argc) svg = argv[++i];
    else if (!strcmp(argv[i], "--replot") && i + 1 < argc) replot = argv[++i];
    else if (!strcmp(argv[i], "--max-cells") && i + 1 < argc) max_cells = atol(argv[++i]);
    else if (!strcmp(argv[i], "--scene") && i + 1 < argc && n_only < N_SCENES) only[n_only++] = argv[++i];
    else if (argv[i][0] == '-') return usage();
    else src = argv[i];
  }
  if (repeat < 1) return usage();
  char machine[512];
  scene_table tables[N_SCENES];
  if (replot) {
    int n_read = 0;
    if (!svg) return usage();
    if (read_csv(replot, tables, &n_read, machine, sizeof machine, &repeat)) return 2;
    return write_svg(svg, tables, n_read, machine, repeat) ? 1 : 0;
  }
  bench_machine_describe(machine, sizeof machine);
  int n_tables = 0, failed = 0;
  for (int i = 0; i < N_SCENES; ++i) {
    int wanted = n_only == 0;
    for (int j = 0; j < n_only; ++j) wanted |= !strcmp(only[j], scenes[i].name);
    if (!wanted) continue;
    scene_table *t = &tables[n_tables++];
    memset(t, 0, sizeof *t);
    t->spec = &scenes[i];
    for (int k = 0; k < scenes[i].n_sizes; ++k) {
      if (max_cells > 0 && cells_of(&scenes[i], k) > max_cells) break;
      char mesh[64], err[2200];
      mesh_text(&scenes[i], k, mesh, sizeof mesh);
      fprintf(stderr, "%s, %s cells: ", scenes[i].name, mesh);
      point *pt = &t->pts[t->n++];
      if (measure(src, &scenes[i], k, repeat, pt, err, sizeof err)) {
        fprintf(stderr, "failed: %s\n", err);
        failed = 1;
        continue;
      }
      fprintf(stderr, "CPU %.3g s; per operation: assembly %.3g s, factorisation %.3g s, solve %.3g s", pt->cpu,
              pt->per_op[PHASE_ASSEMBLY], pt->per_op[PHASE_FACTORISATION], pt->per_op[PHASE_SOLVE]);
      if (scenes[i].has_transport)
        fprintf(stderr, ", transport %.3g s (%ld sub-steps)", pt->per_op[PHASE_TRANSPORT], pt->substeps);
      fputc('\n', stderr);
    }
    fit_scene(t);
  }
  write_csv(stdout, tables, n_tables, machine, repeat);
  if (csv) {
    FILE *f = fopen(csv, "w");
    if (!f) {
      fprintf(stderr, "%s: %s\n", csv, strerror(errno));
      return 1;
    }
    write_csv(f, tables, n_tables, machine, repeat);
    if (fclose(f)) {
      fprintf(stderr, "%s: write failed\n", csv);
      return 1;
    }
  }
  if (svg && write_svg(svg, tables, n_tables, machine, repeat)) return 1; /* the reason is on stderr */
  return failed;
}
