/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Work-precision of the flow engine on configs/cavity_stokes.ini (Q2/Q1,
 * n x n cells): the minimum of u on the vertical centreline (401 samples
 * refined by golden section) against a converged value u*, versus CPU time,
 * with the split into assembly, factorisation and back-substitution, and the
 * peak memory; for each sparse direct solver asked for (--solvers, default
 * umfpack,klu; "scene" keeps the scene's).
 *
 * u* is the Richardson extrapolation through the three finest meshes,
 *   u* = u_h + (u_h - u_2h) / (r - 1),  r = (u_2h - u_4h) / (u_h - u_2h),
 * when they are successive halvings whose differences shrink (|r| > 1; the
 * formula is exact for errors in geometric progression, r = 2^p, or -2^p
 * when they alternate in sign); otherwise the finest mesh's value.
 * --reference VALUE overrides both.
 *
 * Each mesh runs in its own process (so that each peak resident set, from
 * getrusage ru_maxrss right after the run, is its own), twice:
 *  - the steady Stokes solve of the scene (the work-precision point);
 *  - unless --steps 0: a transient run of the same constant-coefficient
 *    problem, BDF1 with a fixed step (--dt, default 0.01) for K steps
 *    (--steps, default 10), to count numeric factorisations and matrix
 *    assemblies (one each is the target: later steps assemble the
 *    right-hand side only and back-substitute) and to time a step that
 *    reuses the matrix and its factorisation: the
 *    mean over steps 2..K-1 of the wall time between accepted steps and of
 *    the assembly in it (the first factorises; the last is cut to end at K dt
 *    exactly, which in floating point may be a slightly different step and
 *    so a different matrix; the output is written after it).
 *    --transient-max N runs it only for n <= N.
 * --repeat R keeps the fastest of R runs of each, for runs under a minute:
 * the least CPU time for the steady runs (the time plotted), the least wall
 * time for the transient ones (whose step times are wall times).
 *
 * --profile-ref FILE adds a second error measure: the whole centreline
 * profile u(1/2, y_k) against a reference u_ref(y_k) at the points of FILE
 * (the CSV `sluice sample OUT.h5 --field velocity --line 0.5,0:0.5,1 --n N`
 * writes: columns y and velocity_0 by name, '#' lines skipped), as its
 * max-norm over the points and its L2 norm on 0 <= y <= 1 (trapezoid rule
 * over the points). The minimum alone is not monotone in n: below about
 * 1e-6 the computed minimum crosses u* (bench/results/cavity_vs_freefem.csv);
 * the profile error is a norm and has no such crossings.
 *
 *   bench_cavity_work_precision [SOURCE_DIR] [--csv PATH] [--svg PATH]
 *       [--solvers A,B] [--steps K] [--dt DT] [--transient-max N]
 *       [--repeat R] [--reference VALUE] [--profile-ref FILE]
 *       [--set section.key=value ...] [n ...]                               (default n: 8 16 32 64 128 256)
 *
 *   bench_cavity_work_precision --replot CSV --svg PATH
 *
 * CSV on stdout (and in --csv PATH), '#' lines for u*, the observed orders
 * and the machine; progress on stderr. --svg PATH writes the plot (core/study/chart.h):
 * error versus cells per side with the observed order (least-squares slope
 * of the last three meshes), error versus CPU time, peak memory versus
 * unknowns, and per solver the time split versus unknowns. --replot CSV
 * draws it from a CSV this program wrote, running nothing. The exit status
 * is 1 when any run failed, 2 on bad usage or a CSV it cannot read. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include "bench_child.h"
#include "bench_csv.h"
#include "bench_machine.h"
#include "centreline_profile.h"
#include "core/io/sample.h"
#include "core/study/chart.h"
#include "sluice/sluice.h"

enum { MAX_N = 16, MAX_SET = 8, MAX_SOLVERS = 4 };

typedef struct run_result {
  int ok;
  char err[2048 + 64];
  int dofs;
  double umin;      /* steady only */
  double cpu, wall; /* process CPU and wall seconds in sluice_run */
  double assembly;  /* wall seconds (sluice_summary) */
  double t_symbolic, t_numeric, t_solve;
  long n_symbolic, n_numeric, n_skipped, n_solves;
  long matrix_asm, rhs_asm;        /* full and right-hand-side-only assemblies (sluice_summary) */
  long rss_kb;                     /* peak resident set after the run */
  long steps;                      /* transient: accepted steps */
  long step_count;                 /* transient: steps 2..K-1 measured */
  double step_wall, step_assembly; /* transient: their mean wall and assembly seconds */
  double step_wall_max;            /* transient: the longest of them */
  double prof_max, prof_l2;        /* steady, with a reference profile: its max-norm and L2 errors */
} run_result;

typedef struct bench_opts {
  const char *src;
  const char *sets[MAX_SET];
  int n_sets;
  long steps;
  double dt;
  const centreline_profile *prof; /* the reference profile, or NULL */
} bench_opts;

/* Max-norm and L2 norm (trapezoid rule in y) of u(1/2, y_k) - u_ref(y_k) at
 * the reference's points; -1 when a point cannot be sampled. */
static int profile_error(const char *file, const bench_opts *bo, double *emax, double *el2) {
  const centreline_profile *ref = bo->prof;
  double *xy = malloc(2 * (size_t)ref->n * sizeof *xy), *u = malloc((size_t)ref->n * sizeof *u);
  sl_sample s;
  int rc = xy && u ? 0 : -1;
  for (int k = 0; k < ref->n && !rc; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = ref->y[k];
  if (!rc && (rc = sl_sample_points(file, "velocity", INFINITY, ref->n, xy, &s, NULL)) == 0) {
    for (int k = 0; k < ref->n; ++k) u[k] = s.values[3 * k];
    sl_sample_free(&s);
    rc = centreline_profile_error(ref, u, emax, el2);
  }
  free(xy), free(u);
  return rc ? -1 : 0;
}

static double clock_s(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- the centreline minimum -------------------------------------------- */

static double u_at(const char *file, double y) {
  double xy[2] = {0.5, y};
  sl_sample s;
  if (sl_sample_points(file, "velocity", INFINITY, 1, xy, &s, NULL)) return NAN;
  double v = s.values[0];
  sl_sample_free(&s);
  return v;
}

static double centreline_min(const char *file) {
  enum { N = 401 };
  double xy[2 * N];
  for (int k = 0; k < N; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = (double)k / (N - 1);
  sl_sample s;
  if (sl_sample_points(file, "velocity", INFINITY, N, xy, &s, NULL)) return NAN;
  int best = 1;
  for (int k = 1; k < N - 1; ++k)
    if (s.values[3 * k] < s.values[3 * best]) best = k;
  sl_sample_free(&s);
  const double g = 0.5 * (sqrt(5.0) - 1.0);
  double a = (best - 1.0) / (N - 1), b = (best + 1.0) / (N - 1);
  double c = b - g * (b - a), e = a + g * (b - a), fc = u_at(file, c), fe = u_at(file, e);
  while (b - a > 1e-10) {
    if (fc < fe) b = e, e = c, fe = fc, c = b - g * (b - a), fc = u_at(file, c);
    else a = c, c = e, fc = fe, e = a + g * (b - a), fe = u_at(file, e);
  }
  return fmin(fc, fe);
}

/* ---- one run (in a child process) -------------------------------------- */

/* "umfpack: 1 symbolic 0.12 s, 1 numeric 2.71 s (9 skipped: matrix
 * unchanged), 10 solves 0.5 s" (core/solve/linsolve.c) into r. */
static int parse_summary(const char *s, run_result *r) {
  const char *c = strchr(s, ':');
  if (!c || sscanf(c + 1, " %ld symbolic %lf s, %ld numeric %lf s", &r->n_symbolic, &r->t_symbolic, &r->n_numeric,
                   &r->t_numeric) != 4)
    return -1;
  r->n_skipped = 0;
  for (const char *p = strchr(s, '('); p; p = strchr(p + 1, '(')) {
    long k;
    char word[16];
    if (sscanf(p, "(%ld %15[a-z]", &k, word) == 2 && !strcmp(word, "skipped")) r->n_skipped = k;
  }
  const char *v = strrchr(s, ',');
  if (!v || sscanf(v, ", %ld solves %lf s", &r->n_solves, &r->t_solve) != 2) return -1;
  return 0;
}

typedef struct monitor {
  const sluice_summary *res; /* kept up to date by the run before each call */
  run_result *r;
  long last; /* the last step: shortened to end exactly, it may be a new matrix */
  double wall_prev, assembly_prev;
} monitor;

static void on_step(void *user, double t, double dt, long step, int iterations) {
  (void)t, (void)dt, (void)iterations;
  monitor *m = user;
  double now = clock_s(CLOCK_MONOTONIC);
  if (step >= 2 && step < m->last) {
    m->r->step_wall += now - m->wall_prev;
    m->r->step_wall_max = fmax(m->r->step_wall_max, now - m->wall_prev);
    m->r->step_assembly += m->res->assembly - m->assembly_prev;
    ++m->r->step_count;
  }
  m->wall_prev = now, m->assembly_prev = m->res->assembly;
}

static int run(const bench_opts *bo, const char *solver, int n, int transient, run_result *r) {
  memset(r, 0, sizeof *r);
  r->umin = NAN;
  r->dofs = 2 * (2 * n + 1) * (2 * n + 1) + (n + 1) * (n + 1);
  char path[4096], file[128];
  snprintf(path, sizeof path, "%s/configs/cavity_stokes.ini", bo->src);
  snprintf(file, sizeof file, "/tmp/sluice_bench_cavity_%ld_%d.h5", (long)getpid(), n);
  /* the overrides: the mesh, the solver, the bench's own, a fixed-step transient */
  char sets[16][128];
  const char *set_list[20];
  int n_sets = 0;
  snprintf(sets[n_sets++], sizeof sets[0], "mesh.cells=%d", n);
  if (solver) snprintf(sets[n_sets++], sizeof sets[0], "solver.linear=%s", solver);
  for (int k = 0; k < bo->n_sets && n_sets < 10; ++k) snprintf(sets[n_sets++], sizeof sets[0], "%s", bo->sets[k]);
  if (transient) {
    snprintf(sets[n_sets++], sizeof sets[0], "time.scheme=bdf1");
    snprintf(sets[n_sets++], sizeof sets[0], "time.dt=%.17g", bo->dt);
    snprintf(sets[n_sets++], sizeof sets[0], "time.adaptive=false");
    snprintf(sets[n_sets++], sizeof sets[0], "time.end=%.17g", bo->dt * (double)bo->steps);
  }
  for (int k = 0; k < n_sets; ++k) set_list[k] = sets[k];
  set_list[n_sets] = NULL;
  sluice_error e = {0, ""};
  sluice *sc = NULL;
  sluice_open_opts oo = {.sets = set_list};
  int rc = sluice_open(path, &oo, &sc, &e);
  sluice_summary res, live;
  monitor mon = {.res = &live, .r = r, .last = bo->steps};
  sluice_run_opts o = {.scene_path = path,
                       .output = file,
                       .version = "bench",
                       .progress = on_step,
                       .progress_user = &mon,
                       .live = &live};
  if (!rc) {
    double c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID), w0 = clock_s(CLOCK_MONOTONIC);
    mon.wall_prev = w0;
    rc = sluice_run(sc, &o, &res, &e);
    r->cpu = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0, r->wall = clock_s(CLOCK_MONOTONIC) - w0;
    struct rusage ru;
    if (!rc) {
      if (getrusage(RUSAGE_SELF, &ru)) rc = e.code = 1, snprintf(e.msg, sizeof e.msg, "getrusage: %s", strerror(errno));
      else r->rss_kb = ru.ru_maxrss;
    }
  }
  if (!rc) {
    r->assembly = res.assembly, r->steps = res.steps;
    r->matrix_asm = res.matrix_assemblies, r->rhs_asm = res.residual_assemblies;
    if (parse_summary(res.linear_summary, r))
      rc = 1, snprintf(e.msg, sizeof e.msg, "unexpected linear solver summary '%s'", res.linear_summary);
  }
  if (!rc && r->step_count > 0) r->step_wall /= (double)r->step_count, r->step_assembly /= (double)r->step_count;
  if (!rc && !transient && !isfinite(r->umin = centreline_min(file)))
    rc = 1, snprintf(e.msg, sizeof e.msg, "sampling the centreline of %s failed", file);
  if (!rc && !transient && bo->prof && profile_error(file, bo, &r->prof_max, &r->prof_l2))
    rc = 1, snprintf(e.msg, sizeof e.msg, "sampling the centreline profile of %s failed", file);
  if (rc) snprintf(r->err, sizeof r->err, "%s", e.msg);
  r->ok = !rc;
  bench_remove_output(file);
  sluice_close(sc);
  return rc;
}

typedef struct child_args {
  const bench_opts *bo;
  const char *solver;
  int n, transient;
} child_args;

static void child_run(void *arg, void *result) {
  const child_args *a = arg;
  run(a->bo, a->solver, a->n, a->transient, result);
}

/* Runs one mesh in a child process (its memory and clocks its own). */
static int run_child(const bench_opts *bo, const char *solver, int n, int transient, run_result *r) {
  child_args a = {bo, solver, n, transient};
  char why[sizeof r->err];
  if (bench_in_child(child_run, &a, r, sizeof *r, why, sizeof why)) {
    snprintf(r->err, sizeof r->err, "%s", why);
    return -1;
  }
  return r->ok ? 0 : -1;
}

/* Best of `repeat` runs (steady: the least CPU time, the time plotted;
 * transient: the least wall time, as its step times are), repeating only
 * runs that took under a minute. */
static int best_of(const bench_opts *bo, const char *solver, int n, int transient, int repeat, run_result *r) {
  if (run_child(bo, solver, n, transient, r)) return -1;
  for (int k = 1; k < repeat && r->wall < 60.0; ++k) {
    run_result again;
    if (run_child(bo, solver, n, transient, &again)) {
      *r = again;
      return -1;
    }
    if (transient ? again.wall < r->wall : again.cpu < r->cpu) *r = again;
  }
  return 0;
}

/* ---- output ------------------------------------------------------------ */

typedef struct table {
  int nn, ns[MAX_N];
  int nsolv;
  const char *solvers[MAX_SOLVERS]; /* NULL: the scene's */
  run_result st[MAX_SOLVERS][MAX_N], tr[MAX_SOLVERS][MAX_N];
  int have_tr[MAX_SOLVERS][MAX_N];
  double umin[MAX_N]; /* per mesh, from the first solver that ran it */
  double spread;      /* largest difference in min u between solvers on one mesh */
  double ref, err[MAX_N], ratio;
  double fit_order; /* least-squares slope of log e against log n, all meshes but the coarsest */
  int fit_from, fit_to;
  char ref_method[256];
  char machine[512];
  const char *prof_path; /* the reference profile, or NULL */
  int n_prof;
  char solver_buf[MAX_SOLVERS][32]; /* the solvers' names, read back by --replot */
} table;

static const char *solver_name(const table *t, int s) { return t->solvers[s] ? t->solvers[s] : "scene"; }

static void write_csv(FILE *f, const table *t) {
  fprintf(f, "# bench_cavity_work_precision: configs/cavity_stokes.ini, Q2/Q1 on n x n cells\n");
  fprintf(f, "# machine: %s\n", t->machine);
  fprintf(f, "# reference min u* = %.12f: %s\n", t->ref, t->ref_method);
  if (isfinite(t->ratio) && fabs(t->ratio) > 1.0)
    fprintf(f, "#   u* = u_h + (u_h - u_2h) / (r - 1), r = (u_2h - u_4h) / (u_h - u_2h), h the finest\n");
  fprintf(f, "# min u of one mesh differs between solvers by at most %.2g\n", t->spread);
  if (t->prof_path)
    fprintf(f,
            "# profile reference: %s, %d points on x = 1/2; prof_max_err = max_k |u(1/2, y_k) - u_ref(y_k)|, "
            "prof_l2_err = its L2 norm over 0 <= y <= 1 (trapezoid rule over the points)\n",
            t->prof_path, t->n_prof);
  fprintf(f, "# observed order log2(e_n / e_2n) of the error against u*:");
  for (int k = 0; k + 1 < t->nn; ++k)
    if (t->err[k] > 0 && t->err[k + 1] > 0 && t->ns[k + 1] == 2 * t->ns[k])
      fprintf(f, " %d-%d: %.2f", t->ns[k], t->ns[k + 1], log2(t->err[k] / t->err[k + 1]));
  fprintf(f, "\n# least-squares order over n = %d..%d: %.2f\n", t->fit_from, t->fit_to, t->fit_order);
  fprintf(f,
          "# cpu_s: process CPU time of the run; the split (assembly, symbolic, numeric, solve) and wall_s are "
          "wall time; assembly_share = assembly / wall; tr_*: the constant-coefficient BDF1 run, tr_step_s the "
          "mean (tr_step_max_s the longest) of its steps 2..K-1, which reuse the matrix and its factorisation; "
          "tr_n_matrix_asm and tr_n_rhs_asm count its full and right-hand-side-only assemblies\n");
  for (int s = 0; s < t->nsolv; ++s)
    for (int k = 0; k < t->nn; ++k) {
      if (!t->st[s][k].ok) fprintf(f, "# failed: %s, n = %d: %s\n", solver_name(t, s), t->ns[k], t->st[s][k].err);
      else if (t->have_tr[s][k] && !t->tr[s][k].ok)
        fprintf(f, "# failed: %s, n = %d, BDF1 run: %s\n", solver_name(t, s), t->ns[k], t->tr[s][k].err);
    }
  fprintf(f,
          "solver,n,unknowns,umin,error,cpu_s,wall_s,assembly_s,assembly_share,n_symbolic,symbolic_s,n_numeric,"
          "numeric_s,n_solves,solve_s,peak_rss_mb,tr_steps,tr_n_numeric,tr_n_skipped,tr_cpu_s,tr_step_s,"
          "tr_step_max_s,tr_step_assembly_s,tr_assembly_share,tr_peak_rss_mb,tr_n_matrix_asm,tr_n_rhs_asm,"
          "prof_max_err,prof_l2_err\n");
  for (int s = 0; s < t->nsolv; ++s)
    for (int k = 0; k < t->nn; ++k) {
      const run_result *a = &t->st[s][k], *r = &t->tr[s][k];
      fprintf(f, "%s,%d,%d,", solver_name(t, s), t->ns[k], a->dofs);
      if (!a->ok) {
        fprintf(f, ",,,,,,,,,,,,,,,,,,,,,,,,,\n");
        continue;
      }
      fprintf(f, "%.10f,%.3e,%.4g,%.4g,%.4g,%.4f,%ld,%.4g,%ld,%.4g,%ld,%.4g,%.1f,", a->umin, fabs(a->umin - t->ref),
              a->cpu, a->wall, a->assembly, a->assembly / a->wall, a->n_symbolic, a->t_symbolic, a->n_numeric,
              a->t_numeric, a->n_solves, a->t_solve, a->rss_kb / 1024.0);
      if (t->have_tr[s][k] && r->ok)
        fprintf(f, "%ld,%ld,%ld,%.4g,%.4g,%.4g,%.4g,%.4f,%.1f,%ld,%ld,", r->steps, r->n_numeric, r->n_skipped, r->cpu,
                r->step_wall, r->step_wall_max, r->step_assembly, r->step_assembly / r->step_wall, r->rss_kb / 1024.0,
                r->matrix_asm, r->rhs_asm);
      else fprintf(f, ",,,,,,,,,,,");
      if (t->prof_path) fprintf(f, "%.4e,%.4e\n", a->prof_max, a->prof_l2);
      else fprintf(f, ",\n");
    }
}

static const char *const solver_colours[MAX_SOLVERS] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};

static int write_svg(const char *path, const table *t) {
  enum { SPLIT = 6 };
  double cpu[MAX_SOLVERS][MAX_N], err[MAX_SOLVERS][MAX_N], rss[MAX_SOLVERS][MAX_N], dofs[MAX_N];
  double split[MAX_SOLVERS][SPLIT][MAX_N];
  char buf[MAX_N][32];
  const char *labels[MAX_N];
  sl_chart_series s_err[MAX_SOLVERS], s_mem[MAX_SOLVERS], s_split[MAX_SOLVERS][SPLIT], s_order;
  sl_chart panels[3 + MAX_SOLVERS];
  double cells[MAX_N], err_n[MAX_N];
  char titles[MAX_SOLVERS][96];
  static const char *const split_name[SPLIT] = {
      "steady solve, total",   "its factorisation",         "its assembly",
      "its back-substitution", "BDF1 step, factors reused", "assembly in that step"};
  static const char *const split_colour[SPLIT] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#2ca02c"};
  static const sl_chart_marker split_marker[SPLIT] = {SL_CHART_MARK_CIRCLE,   SL_CHART_MARK_SQUARE,
                                                      SL_CHART_MARK_TRIANGLE, SL_CHART_MARK_DIAMOND,
                                                      SL_CHART_MARK_CIRCLE,   SL_CHART_MARK_TRIANGLE};
  for (int k = 0; k < t->nn; ++k) {
    dofs[k] = t->st[0][k].dofs;
    snprintf(buf[k], sizeof buf[k], "n=%d", t->ns[k]);
    labels[k] = buf[k];
  }
  for (int k = 0; k < t->nn; ++k) cells[k] = t->ns[k], err_n[k] = isfinite(t->umin[k]) ? t->err[k] : NAN;
  /* the minimum of one mesh is the same with every solver (to the spread the CSV gives): one series */
  s_order = (sl_chart_series){.name = "all solvers",
                              .n = t->nn,
                              .x = cells,
                              .y = err_n,
                              .colour = "#000000",
                              .marker = SL_CHART_MARK_CIRCLE,
                              .slope_points = 3,
                              .slope_format = "order %.2f",
                              .slope_negate = 1};
  int np = 3; /* a split panel for each solver with a successful run */
  for (int s = 0; s < t->nsolv; ++s) {
    int any_tr = 0, any = 0;
    for (int k = 0; k < t->nn; ++k) {
      const run_result *a = &t->st[s][k], *r = &t->tr[s][k];
      int tr = t->have_tr[s][k] && r->ok;
      any_tr |= tr, any |= a->ok;
      cpu[s][k] = a->ok ? a->cpu : NAN, err[s][k] = a->ok ? fabs(a->umin - t->ref) : NAN;
      rss[s][k] = a->ok ? a->rss_kb / 1024.0 : NAN;
      split[s][0][k] = a->ok ? a->wall : NAN, split[s][1][k] = a->ok ? a->t_symbolic + a->t_numeric : NAN;
      split[s][2][k] = a->ok ? a->assembly : NAN, split[s][3][k] = a->ok ? a->t_solve : NAN;
      split[s][4][k] = tr ? r->step_wall : NAN, split[s][5][k] = tr ? r->step_assembly : NAN;
    }
    const char *c = solver_colours[s % MAX_SOLVERS];
    s_err[s] = (sl_chart_series){.name = solver_name(t, s),
                                 .n = t->nn,
                                 .x = cpu[s],
                                 .y = err[s],
                                 .labels = s == t->nsolv - 1 ? labels : NULL,
                                 .colour = c,
                                 .marker = (sl_chart_marker)(SL_CHART_MARK_CIRCLE + s)};
    s_mem[s] = (sl_chart_series){.name = solver_name(t, s),
                                 .n = t->nn,
                                 .x = dofs,
                                 .y = rss[s],
                                 .labels = s == t->nsolv - 1 ? labels : NULL,
                                 .colour = c,
                                 .marker = (sl_chart_marker)(SL_CHART_MARK_CIRCLE + s)};
    for (int q = 0; q < SPLIT; ++q)
      s_split[s][q] = (sl_chart_series){.name = split_name[q],
                                        .n = t->nn,
                                        .x = dofs,
                                        .y = split[s][q],
                                        .colour = split_colour[q],
                                        .marker = split_marker[q],
                                        .dashed = q >= 4};
    if (!any) continue;
    snprintf(titles[s], sizeof titles[s], "Where the time goes: %s", solver_name(t, s));
    panels[np++] = (sl_chart){.xscale = SL_AXIS_LOG,
                              .yscale = SL_AXIS_LOG,
                              .title = titles[s],
                              .xlabel = "unknowns (velocity and pressure)",
                              .ylabel = "wall time (s)",
                              .n_series = any_tr ? SPLIT : 4,
                              .series = s_split[s],
                              .legend = SL_LEGEND_TOP_LEFT};
  }
  /* the split panels share their axes */
  double lo = INFINITY, hi = -INFINITY;
  for (int s = 0; s < t->nsolv; ++s)
    for (int q = 0; q < SPLIT; ++q)
      for (int k = 0; k < t->nn; ++k)
        if (split[s][q][k] > 0.0) lo = fmin(lo, split[s][q][k]), hi = fmax(hi, split[s][q][k]);
  for (int p = 3; p < np; ++p) {
    panels[p].xspan[0] = dofs[0], panels[p].xspan[1] = dofs[t->nn - 1];
    panels[p].yspan[0] = lo, panels[p].yspan[1] = hi;
  }
  char err_label[128];
  snprintf(err_label, sizeof err_label, "|min u \xE2\x88\x92 u*| on x = 1/2 (m/s)");
  panels[0] = (sl_chart){.xscale = SL_AXIS_LOG,
                         .yscale = SL_AXIS_LOG,
                         .title = "Error against the mesh",
                         .xlabel = "cells per side n (n \xC3\x97 n cells)",
                         .ylabel = err_label,
                         .n_series = 1,
                         .series = &s_order,
                         .legend = SL_LEGEND_NONE};
  panels[1] = (sl_chart){.xscale = SL_AXIS_LOG,
                         .yscale = SL_AXIS_LOG,
                         .title = "Error against CPU time",
                         .xlabel = "CPU time of the steady solve (s)",
                         .ylabel = err_label,
                         .n_series = t->nsolv,
                         .series = s_err,
                         .legend = SL_LEGEND_AUTO};
  panels[2] = (sl_chart){.xscale = SL_AXIS_LOG,
                         .yscale = SL_AXIS_LOG,
                         .title = "Peak memory",
                         .xlabel = "unknowns (velocity and pressure)",
                         .ylabel = "peak resident set (MB)",
                         .n_series = t->nsolv,
                         .series = s_mem,
                         .legend = SL_LEGEND_TOP_LEFT};
  double elo = INFINITY, ehi = -INFINITY; /* the two error panels share their error axis */
  for (int s = 0; s < t->nsolv; ++s)
    for (int k = 0; k < t->nn; ++k)
      if (err[s][k] > 0.0) elo = fmin(elo, err[s][k]), ehi = fmax(ehi, err[s][k]);
  for (int p = 0; p < 2 && elo <= ehi; ++p) panels[p].yspan[0] = elo, panels[p].yspan[1] = ehi;
  char note[4096];
  int at = snprintf(note, sizeof note,
                    "u* = %.8f m/s: %s. Order: least-squares slope of the last three meshes.\n%s. Release build, "
                    "one process per run.",
                    t->ref, t->ref_method, t->machine);
  for (int s = 0; s < t->nsolv; ++s) /* the failed steady runs, one line each */
    for (int k = 0; k < t->nn && at > 0 && (size_t)at < sizeof note; ++k)
      if (!t->st[s][k].ok)
        at += snprintf(note + at, sizeof note - (size_t)at, "\nNot plotted: %s, n = %d failed: %.110s",
                       solver_name(t, s), t->ns[k], t->st[s][k].err);
  sl_figure fig = {.title = "Stokes lid-driven cavity (configs/cavity_stokes.ini), Q2/Q1 on n \xC3\x97 n cells",
                   .note = note,
                   .n_panels = np,
                   .panels = panels,
                   .columns = 3,
                   .panel_width = 480,
                   .panel_height = 360};
  sl_diag d = {{0}};
  if (sl_figure_write(path, &fig, &d)) return fprintf(stderr, "%s\n", d.msg), -1;
  return 0;
}

/* ---- --replot: the table back from a CSV this program wrote ------------ */

/* The figure again from recorded measurements, running nothing: the steady
 * and BDF1 columns the figure plots, by header name (older CSVs lack the
 * later columns), u* and the machine from the '#' lines, the failed runs'
 * reasons from their "# failed:" lines. Returns 0, or -1 with file:line on
 * stderr. */
static int read_csv(const char *path, table *t) {
  FILE *f = fopen(path, "r");
  if (!f) return fprintf(stderr, "%s: %s\n", path, strerror(errno)), -1;
  enum { SOLVER, N, UNKNOWNS, UMIN, CPU, WALL, ASM, SYM, NUM, SOLVE, RSS, TR_STEP, TR_ASM, NC };
  static const char *const names[NC] = {"solver",      "n",          "unknowns",          "umin",      "cpu_s",
                                        "wall_s",      "assembly_s", "symbolic_s",        "numeric_s", "solve_s",
                                        "peak_rss_mb", "tr_step_s",  "tr_step_assembly_s"};
  static char failed[2 * MAX_SOLVERS * MAX_N][sizeof t->st[0][0].err];
  char line[4096], header[4096] = "";
  int c[NC], lineno = 0, n_failed = 0, rows = 0, bad = 0;
  t->ref = NAN;
  while (!bad && fgets(line, sizeof line, f)) {
    ++lineno;
    line[strcspn(line, "\r\n")] = '\0';
    if (line[0] == '#') {
      double r;
      int at = 0;
      if (!strncmp(line, "# machine: ", 11)) snprintf(t->machine, sizeof t->machine, "%.500s", line + 11);
      else if (sscanf(line, "# reference min u* = %lf: %n", &r, &at) == 1 && at > 0)
        t->ref = r, snprintf(t->ref_method, sizeof t->ref_method, "%.250s", line + at);
      else if (!strncmp(line, "# failed: ", 10) && n_failed < (int)(sizeof failed / sizeof failed[0]))
        snprintf(failed[n_failed++], sizeof failed[0], "%.2000s", line + 10);
      continue;
    }
    if (!header[0]) {
      snprintf(header, sizeof header, "%s", line);
      for (int k = 0; k < NC; ++k)
        if ((c[k] = bench_csv_column(header, names[k])) < 0) {
          fprintf(stderr, "%s:%d: no column %s: not a bench_cavity_work_precision CSV\n", path, lineno, names[k]);
          bad = 1;
        }
      continue;
    }
    char solver[32];
    bench_csv_field(line, c[SOLVER], solver, sizeof solver);
    double n = bench_csv_number(line, c[N]), dofs = bench_csv_number(line, c[UNKNOWNS]);
    if (!solver[0] || !(n >= 1 && n <= 4096 && n == floor(n)) || !(dofs > 0)) {
      fprintf(stderr, "%s:%d: not a row of bench_cavity_work_precision's CSV\n", path, lineno);
      bad = 1;
      break;
    }
    int s = 0, k = 0;
    while (s < t->nsolv && strcmp(t->solver_buf[s], solver)) ++s;
    if (s == t->nsolv) {
      if (s == MAX_SOLVERS) {
        fprintf(stderr, "%s:%d: more than %d solvers\n", path, lineno, MAX_SOLVERS);
        bad = 1;
        break;
      }
      snprintf(t->solver_buf[s], sizeof t->solver_buf[s], "%s", solver);
      t->solvers[t->nsolv++] = strcmp(solver, "scene") ? t->solver_buf[s] : NULL;
    }
    while (k < t->nn && t->ns[k] != (int)n) ++k;
    if (k == t->nn) {
      if (k == MAX_N || (k > 0 && t->ns[k - 1] > (int)n)) {
        fprintf(stderr, "%s:%d: n = %d: at most %d meshes, in ascending order\n", path, lineno, (int)n, MAX_N);
        bad = 1;
        break;
      }
      t->ns[t->nn++] = (int)n;
    }
    run_result *a = &t->st[s][k], *r = &t->tr[s][k];
    a->dofs = (int)dofs, a->umin = bench_csv_number(line, c[UMIN]);
    a->ok = isfinite(a->umin);
    if (a->ok) {
      a->cpu = bench_csv_number(line, c[CPU]), a->wall = bench_csv_number(line, c[WALL]);
      a->assembly = bench_csv_number(line, c[ASM]), a->t_symbolic = bench_csv_number(line, c[SYM]);
      a->t_numeric = bench_csv_number(line, c[NUM]), a->t_solve = bench_csv_number(line, c[SOLVE]);
      a->rss_kb = (long)(bench_csv_number(line, c[RSS]) * 1024.0);
      r->step_wall = bench_csv_number(line, c[TR_STEP]), r->step_assembly = bench_csv_number(line, c[TR_ASM]);
      t->have_tr[s][k] = r->ok = isfinite(r->step_wall);
    } else {
      char prefix[64];
      snprintf(prefix, sizeof prefix, "%s, n = %d: ", solver, (int)n);
      snprintf(a->err, sizeof a->err, "no reason recorded");
      for (int j = 0; j < n_failed; ++j)
        if (!strncmp(failed[j], prefix, strlen(prefix)))
          snprintf(a->err, sizeof a->err, "%s", failed[j] + strlen(prefix));
    }
    ++rows;
  }
  fclose(f);
  if (!bad && !rows) fprintf(stderr, "%s: no rows\n", path), bad = 1;
  if (!bad && !isfinite(t->ref)) fprintf(stderr, "%s: no \"# reference min u* = \" line\n", path), bad = 1;
  if (bad) return -1;
  for (int k = 0; k < t->nn; ++k) { /* per mesh, from the first solver that ran it, as a run records it */
    t->umin[k] = NAN;
    for (int s = 0; s < t->nsolv && isnan(t->umin[k]); ++s)
      if (t->st[s][k].ok) t->umin[k] = t->st[s][k].umin;
    t->err[k] = fabs(t->umin[k] - t->ref);
  }
  return 0;
}

/* ---- main -------------------------------------------------------------- */

static int usage(void) {
  fprintf(stderr,
          "usage: bench_cavity_work_precision [SOURCE_DIR] [--csv PATH] [--svg PATH] [--solvers A,B|scene] "
          "[--steps K] [--dt DT] [--transient-max N] [--repeat R] [--reference VALUE] [--profile-ref FILE] "
          "[--set section.key=value ...] [n ...]\n"
          "       bench_cavity_work_precision --replot CSV --svg PATH   (the figure of recorded runs)\n");
  return 2;
}

/* The converged value: Richardson (Aitken) through the three finest meshes
 * when they are successive halvings whose differences shrink. */
static void reference(table *t, double given) {
  int ok[MAX_N], m = 0;
  for (int k = 0; k < t->nn; ++k)
    if (isfinite(t->umin[k])) ok[m++] = k;
  t->ratio = NAN;
  if (isfinite(given)) {
    t->ref = given;
    snprintf(t->ref_method, sizeof t->ref_method, "given with --reference");
    return;
  }
  int a = m >= 3 ? ok[m - 3] : -1, b = m >= 3 ? ok[m - 2] : -1, c = ok[m - 1];
  t->ref = t->umin[c];
  snprintf(t->ref_method, sizeof t->ref_method, "the finest mesh's value (n = %d)", t->ns[c]);
  if (a < 0 || t->ns[b] != 2 * t->ns[a] || t->ns[c] != 2 * t->ns[b]) return;
  double d1 = t->umin[b] - t->umin[a], d2 = t->umin[c] - t->umin[b], r = d1 / d2;
  t->ratio = r;
  if (!isfinite(r) || fabs(r) <= 1.0) {
    snprintf(t->ref_method, sizeof t->ref_method,
             "the finest mesh's value (n = %d; the differences of the three finest do not shrink, ratio %.3g: no "
             "Richardson)",
             t->ns[c], r);
    return;
  }
  t->ref = t->umin[c] + d2 / (r - 1.0);
  snprintf(t->ref_method, sizeof t->ref_method,
           "Richardson extrapolation of n = %d, %d, %d (difference ratio r = %.3f%s, order log2|r| = %.2f)", t->ns[a],
           t->ns[b], t->ns[c], r, r < 0 ? ", alternating" : "", log2(fabs(r)));
}

/* The least-squares slope of log e against log(1/n) over all meshes but the
 * coarsest (pre-asymptotic) with a positive error. */
static void fit_order(table *t) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int m = 0;
  t->fit_order = NAN, t->fit_from = t->fit_to = 0;
  for (int k = 1; k < t->nn; ++k) {
    if (!(t->err[k] > 0.0)) continue;
    double x = log((double)t->ns[k]), y = -log(t->err[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
    if (!t->fit_from) t->fit_from = t->ns[k];
    t->fit_to = t->ns[k];
  }
  if (m >= 2 && sxx * m - sx * sx > 0.0) t->fit_order = (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

int main(int argc, char **argv) {
  bench_opts bo = {.src = ".", .steps = 10, .dt = 0.01};
  const char *csv = NULL, *svg = NULL, *replot = NULL;
  char solvers_arg[256] = "umfpack,klu";
  long transient_max = 1L << 30;
  int repeat = 1;
  double ref_given = NAN;
  static table t;
  int i = 1;
  if (argc > 1 && argv[1][0] != '-' && strspn(argv[1], "0123456789") != strlen(argv[1])) bo.src = argv[i++];
  for (; i < argc; ++i) {
    const char *a = argv[i];
    char *end;
    if (!strcmp(a, "--csv") && i + 1 < argc) csv = argv[++i];
    else if (!strcmp(a, "--svg") && i + 1 < argc) svg = argv[++i];
    else if (!strcmp(a, "--replot") && i + 1 < argc) replot = argv[++i];
    else if (!strcmp(a, "--solvers") && i + 1 < argc) {
      if (strlen(argv[++i]) >= sizeof solvers_arg) return usage();
      snprintf(solvers_arg, sizeof solvers_arg, "%s", argv[i]);
    } else if (!strcmp(a, "--steps") && i + 1 < argc) {
      bo.steps = strtol(argv[++i], &end, 10);
      if (*end || bo.steps < 0 || (bo.steps > 0 && bo.steps < 3)) return fprintf(stderr, "--steps: 0 or >= 3\n"), 2;
    } else if (!strcmp(a, "--dt") && i + 1 < argc) {
      bo.dt = strtod(argv[++i], &end);
      if (*end || !(bo.dt > 0.0) || !isfinite(bo.dt)) return usage();
    } else if (!strcmp(a, "--transient-max") && i + 1 < argc) {
      transient_max = strtol(argv[++i], &end, 10);
      if (*end) return usage();
    } else if (!strcmp(a, "--repeat") && i + 1 < argc) {
      long r = strtol(argv[++i], &end, 10);
      if (*end || r < 1 || r > 100) return usage();
      repeat = (int)r;
    } else if (!strcmp(a, "--reference") && i + 1 < argc) {
      ref_given = strtod(argv[++i], &end);
      if (*end || !isfinite(ref_given)) return usage();
    } else if (!strcmp(a, "--profile-ref") && i + 1 < argc) {
      t.prof_path = argv[++i];
    } else if (!strcmp(a, "--set") && i + 1 < argc) {
      if (bo.n_sets == MAX_SET) return fprintf(stderr, "at most %d --set\n", MAX_SET), 2;
      bo.sets[bo.n_sets++] = argv[++i];
    } else if (a[0] != '-') {
      long n = strtol(a, &end, 10);
      if (*end || n < 1 || n > 4096) return fprintf(stderr, "bad mesh size '%s'\n", a), 2;
      if (t.nn == MAX_N) return fprintf(stderr, "at most %d meshes\n", MAX_N), 2;
      t.ns[t.nn++] = (int)n;
    } else {
      return usage();
    }
  }
  if (replot) {
    if (!svg || t.nn) return usage();
    if (read_csv(replot, &t)) return 2;
    return write_svg(svg, &t) ? 1 : 0;
  }
  for (char *tok = strtok(solvers_arg, ","); tok; tok = strtok(NULL, ",")) {
    if (t.nsolv == MAX_SOLVERS) return fprintf(stderr, "at most %d solvers\n", MAX_SOLVERS), 2;
    t.solvers[t.nsolv++] = strcmp(tok, "scene") ? tok : NULL;
  }
  if (!t.nsolv) return usage();
  if (!t.nn) {
    static const int def[] = {8, 16, 32, 64, 128, 256};
    for (int k = 0; k < 6; ++k) t.ns[t.nn++] = def[k];
  }
  for (int a = 1; a < t.nn; ++a) /* ascending */
    for (int b = a; b > 0 && t.ns[b - 1] > t.ns[b]; --b) {
      int s = t.ns[b];
      t.ns[b] = t.ns[b - 1], t.ns[b - 1] = s;
    }
  bench_machine_describe(t.machine, sizeof t.machine);
  centreline_profile *prof = NULL;
  if (t.prof_path) {
    if (!(prof = malloc(sizeof *prof))) return fprintf(stderr, "out of memory\n"), 1;
    if (centreline_profile_read(t.prof_path, prof)) return free(prof), 2;
    t.n_prof = prof->n, bo.prof = prof;
  }

  int failures = 0;
  for (int s = 0; s < t.nsolv; ++s)
    for (int k = 0; k < t.nn; ++k) {
      int n = t.ns[k];
      run_result *a = &t.st[s][k];
      fprintf(stderr, "%s, n = %d: steady ...", solver_name(&t, s), n);
      if (best_of(&bo, t.solvers[s], n, 0, repeat, a)) {
        fprintf(stderr, " failed: %s\n", a->err);
        ++failures;
        a->dofs = 2 * (2 * n + 1) * (2 * n + 1) + (n + 1) * (n + 1);
        continue;
      }
      fprintf(stderr, " %.3g s CPU, %.0f MB", a->cpu, a->rss_kb / 1024.0);
      if (t.prof_path) fprintf(stderr, ", profile error %.3g (max) %.3g (L2)", a->prof_max, a->prof_l2);
      if (bo.steps > 0 && n <= transient_max) {
        run_result *r = &t.tr[s][k];
        t.have_tr[s][k] = 1;
        fprintf(stderr, "; BDF1 x %ld ...", bo.steps);
        if (best_of(&bo, t.solvers[s], n, 1, repeat, r)) {
          fprintf(stderr, " failed: %s", r->err);
          ++failures;
        } else {
          fprintf(stderr, " %.3g s CPU, %ld numeric factorisation(s), %ld matrix assembl%s", r->cpu, r->n_numeric,
                  r->matrix_asm, r->matrix_asm == 1 ? "y" : "ies");
        }
      }
      fputc('\n', stderr);
    }

  int any = 0;
  for (int k = 0; k < t.nn; ++k) {
    t.umin[k] = NAN;
    for (int s = 0; s < t.nsolv; ++s) {
      if (!t.st[s][k].ok) continue;
      if (isnan(t.umin[k])) t.umin[k] = t.st[s][k].umin, any = 1;
      else t.spread = fmax(t.spread, fabs(t.st[s][k].umin - t.umin[k]));
    }
  }
  if (!any) return fprintf(stderr, "no run succeeded\n"), 1;
  reference(&t, ref_given);
  for (int k = 0; k < t.nn; ++k) t.err[k] = fabs(t.umin[k] - t.ref);
  fit_order(&t);

  write_csv(stdout, &t);
  if (csv) {
    FILE *f = fopen(csv, "w");
    if (!f) return fprintf(stderr, "%s: %s\n", csv, strerror(errno)), 1;
    write_csv(f, &t);
    int werr = ferror(f);
    if (fclose(f) || werr) return fprintf(stderr, "%s: write failed\n", csv), 1;
  }
  if (svg && write_svg(svg, &t)) return 1; /* the reason is on stderr */
  free(prof);
  if (fflush(stdout)) return 1;
  return failures ? 1 : 0;
}
