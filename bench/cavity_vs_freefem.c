/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The Stokes cavity against FreeFEM: error of the centreline profile against
 * CPU time for sluice (Q2/Q1, read from the CSV of
 * bench_cavity_work_precision --profile-ref) and for FreeFEM (P2/P1 on the
 * same number of unknowns, bench/freefem/cavity_stokes.edp, run here), on
 * one plot.
 *
 * FreeFEM is for comparison only, not a dependency (Debian: freefem++). Each
 * FreeFEM run is its own process; its CPU time is the script's clock() from
 * the mesh to the solution (FreeFEM's start-up and the sampling excluded,
 * as sluice's cpu_s excludes process start-up), its peak memory the child's
 * ru_maxrss.
 *
 * The error is that of u(1/2, y_k) against a reference profile u_ref(y_k) at
 * the points of the reference file (`sluice sample` CSV, columns y and
 * velocity_0; default bench/freefem/cavity_centreline_ref.csv, how it was
 * made is in its header): the max-norm over the points and the L2 norm over
 * 0 <= y <= 1 (trapezoid rule over the points). FreeFEM samples the very
 * points the reference file lists (passed to the script in a points file);
 * sluice's CSV must come from the same reference file. |min u - u*| (u* =
 * -0.207755897 by default) is kept as a secondary column: below about 1e-6
 * the computed minimum crosses u* and that error is not monotone in n.
 *
 *   bench_cavity_vs_freefem SOURCE_DIR [--sluice-csv PATH] [--sluice-bench EXE]
 *       [--profile-ref FILE] [--reference U*] [--repeat R] [--csv PATH]
 *       [--svg PATH] [n ...]                  (default n: 8 16 32 64 128)
 *   bench_cavity_vs_freefem --replot CSV --svg PATH
 *
 * The sluice CSV defaults to SOURCE_DIR/bench/results/cavity_vs_freefem.sluice.csv.
 * With --sluice-bench EXE (bench_cavity_work_precision) the sluice runs are
 * made here instead and the CSV is written, not read: R rounds, each running
 * every mesh once in sluice (both solvers) and then in FreeFEM, each code
 * keeping its least CPU time per mesh. On a machine shared with other jobs
 * the load drifts over minutes; interleaving gives both codes the same
 * drift, where running one code's meshes after the other's does not.
 * CSV on stdout (and in --csv PATH): code, solver, n, unknowns, err_max,
 * err_l2, min_u, min_err, cpu_s, peak_rss_mb; then, for each FreeFEM run and
 * each sluice solver, the CPU time sluice needs for the same error, by
 * linear interpolation of log(cpu) against log(error) between the two sluice
 * meshes whose errors bracket FreeFEM's. --svg PATH draws the errors against
 * cells per side (with the observed order) and against CPU time;
 * --replot CSV draws it from a CSV this program wrote, running nothing.
 * Exit status 1 when a run failed, 2 on bad usage or a CSV it cannot read. */
#define _DEFAULT_SOURCE /* wait4, getloadavg */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <unistd.h>

#include "bench_csv.h"
#include "centreline_profile.h"
#include "core/study/chart.h"
#include "core/study/child.h"

enum { MAX_RUNS = 64, MAX_N = 16, MAX_SOLVERS = 3 };

typedef struct point {
  char code[16], solver[16];
  int n;
  long unknowns;
  double umin, min_err, err_max, err_l2, cpu, mb;
  char raw[1024]; /* sluice: its line of the work-precision CSV */
} point;

/* FreeFEM's lines: "RESULT n unknowns umin cpu" and "P i u" per profile point. */
typedef struct freefem_output {
  const centreline_profile *ref;
  double *u;
  int got, n_u;
  double umin, cpu;
  long unknowns;
} freefem_output;

static void freefem_line(void *user, const char *line) {
  freefem_output *fo = user;
  int nn = 0, i;
  double v;
  if (sscanf(line, "RESULT %d %ld %lf %lf", &nn, &fo->unknowns, &fo->umin, &fo->cpu) == 4) fo->got = 1;
  else if (sscanf(line, "P %d %lf", &i, &v) == 2 && i == fo->n_u && fo->n_u < fo->ref->n) fo->u[fo->n_u++] = v;
}

/* Runs FreeFem++ on the script for n cells per side (fastest of repeat),
 * sampling u at the points of `points` (the reference's y). */
static int run_freefem(const char *script, const char *points, const centreline_profile *ref, int n, int repeat,
                       point *p) {
  static double u[CENTRELINE_MAX_POINTS];
  memset(p, 0, sizeof *p);
  snprintf(p->code, sizeof p->code, "freefem"), snprintf(p->solver, sizeof p->solver, "umfpack");
  p->n = n, p->cpu = INFINITY;
  for (int k = 0; k < repeat; ++k) {
    char arg[32];
    snprintf(arg, sizeof arg, "%d", n);
    char *argv[] = {"FreeFem++", "-nw", "-v", "0", (char *)script, arg, (char *)points, NULL};
    freefem_output fo = {.ref = ref, .u = u};
    sl_child_opts co = {.argv = argv, .result_fd = -1, .line = freefem_line, .line_user = &fo};
    sl_child_result cr;
    if (sl_child_run(&co, &cr)) return fprintf(stderr, "FreeFem++: %s\n", cr.message), -1;
    if (cr.signal_number || cr.exit_code != 0 || !fo.got || fo.n_u != ref->n) {
      fprintf(stderr, "FreeFem++ %s %d failed (status %d%s, %d of %d profile points)\n", script, n, cr.exit_code,
              cr.exit_code == 127 ? ": is it installed? Debian: apt-get install freefem++" : "", fo.n_u, ref->n);
      return -1;
    }
    p->unknowns = fo.unknowns, p->umin = fo.umin;
    centreline_profile_error(ref, u, &p->err_max, &p->err_l2);
    if (fo.cpu < p->cpu) p->cpu = fo.cpu;
    if (cr.peak_rss_mb > p->mb) p->mb = cr.peak_rss_mb;
  }
  if (!isfinite(p->err_max) || !isfinite(p->err_l2)) return fprintf(stderr, "FreeFEM n = %d: NaN in profile\n", n), -1;
  return 0;
}

/* The steady runs of bench_cavity_work_precision's CSV (made with
 * --profile-ref); its "# machine:" line into machine, and the number of
 * profile points of its "# profile reference:" line into *n_prof. */
static int read_sluice(const char *path, point *pts, int max, char *machine, size_t cap, int *n_prof, char *pre,
                       size_t pre_cap) {
  FILE *f = fopen(path, "r");
  if (!f)
    return fprintf(stderr, "%s: %s (run bench_cavity_work_precision --profile-ref FILE --csv first)\n", path,
                   strerror(errno)),
           -1;
  enum { NC = 8 };
  char line[4096], header[4096] = "";
  int n = 0, c[NC];
  static const char *const names[NC] = {"solver", "n",           "unknowns",     "umin",
                                        "cpu_s",  "peak_rss_mb", "prof_max_err", "prof_l2_err"};
  *n_prof = 0;
  if (pre) pre[0] = '\0';
  while (fgets(line, sizeof line, f)) {
    if (pre && (line[0] == '#' || !header[0]) && strlen(pre) + strlen(line) < pre_cap) strcat(pre, line);
    if (line[0] == '#') {
      if (!strncmp(line, "# machine: ", 11)) snprintf(machine, cap, "%.*s", (int)strcspn(line + 11, "\n"), line + 11);
      const char *r = strstr(line, "# profile reference: ");
      if (r && (r = strstr(r, ", ")) != NULL) *n_prof = atoi(r + 2);
      continue;
    }
    if (!header[0]) {
      snprintf(header, sizeof header, "%s", line);
      int bad = 0;
      for (int k = 0; k < NC; ++k) bad |= (c[k] = bench_csv_column(header, names[k])) < 0;
      if (bad) {
        fclose(f);
        return fprintf(stderr, "%s: not a bench_cavity_work_precision CSV with profile errors\n", path), -1;
      }
      continue;
    }
    if (n == max) break;
    point *p = &pts[n];
    char buf[64];
    memset(p, 0, sizeof *p);
    snprintf(p->code, sizeof p->code, "sluice");
    size_t len = strlen(line);
    if (len >= sizeof p->raw) {
      fclose(f);
      return fprintf(stderr, "%s: a line longer than %zu characters\n", path, sizeof p->raw - 1), -1;
    }
    memcpy(p->raw, line, len + 1);
    bench_csv_field(line, c[0], p->solver, sizeof p->solver);
    bench_csv_field(line, c[1], buf, sizeof buf), p->n = atoi(buf);
    bench_csv_field(line, c[2], buf, sizeof buf), p->unknowns = atol(buf);
    bench_csv_field(line, c[3], buf, sizeof buf), p->umin = buf[0] ? strtod(buf, NULL) : NAN;
    bench_csv_field(line, c[4], buf, sizeof buf), p->cpu = strtod(buf, NULL);
    bench_csv_field(line, c[5], buf, sizeof buf), p->mb = strtod(buf, NULL);
    bench_csv_field(line, c[6], buf, sizeof buf), p->err_max = buf[0] ? strtod(buf, NULL) : NAN;
    bench_csv_field(line, c[7], buf, sizeof buf), p->err_l2 = buf[0] ? strtod(buf, NULL) : NAN;
    /* a failed run has no time; a run without a reference profile no profile error */
    if (p->n > 0 && isfinite(p->umin) && p->cpu > 0 && isfinite(p->err_max) && isfinite(p->err_l2)) ++n;
  }
  fclose(f);
  return n;
}

/* Runs the sluice bench (bench_cavity_work_precision) for one mesh, both
 * solvers, one repeat, its CSV into csv. */
static int run_sluice_bench(const char *exe, const char *src, const char *prof, double ref, int n, const char *csv) {
  char nbuf[32], rbuf[64];
  snprintf(nbuf, sizeof nbuf, "%d", n), snprintf(rbuf, sizeof rbuf, "%.17g", ref);
  /* its CSV goes to the file; stderr shows progress */
  char *argv[] = {(char *)exe,   (char *)src, "--solvers",     "umfpack,klu", "--repeat", "1",         "--steps", "0",
                  "--reference", rbuf,        "--profile-ref", (char *)prof,  "--csv",    (char *)csv, nbuf,      NULL};
  sl_child_opts co = {.argv = argv, .result_fd = -1, .out = "/dev/null"};
  sl_child_result cr;
  if (sl_child_run(&co, &cr)) return fprintf(stderr, "%s: %s\n", exe, cr.message), -1;
  if (cr.signal_number || cr.exit_code != 0)
    return fprintf(stderr, "%s n = %d failed (status %d, signal %d)\n", exe, n, cr.exit_code, cr.signal_number), -1;
  return 0;
}

typedef enum reach { REACH_INTERP, REACH_COARSEST, REACH_NOT } reach;

typedef struct reach_result {
  reach how;
  double cpu; /* REACH_INTERP: interpolated; REACH_COARSEST: the coarsest run's (an upper bound) */
  int n_lo, n_hi;
} reach_result;

/* The CPU time sluice (runs idx[0..m), ascending n) needs for error e: the
 * first pair of successive meshes whose errors bracket e, log(cpu) linear in
 * log(error) between them. measure 0: max-norm, 1: L2. */
static reach_result time_to_reach(const point *pts, const int *idx, int m, double e, int measure) {
  reach_result r = {REACH_NOT, NAN, 0, 0};
#define ERR(j) (measure ? pts[idx[j]].err_l2 : pts[idx[j]].err_max)
  if (m > 0 && ERR(0) <= e) {
    r.how = REACH_COARSEST, r.cpu = pts[idx[0]].cpu, r.n_lo = r.n_hi = pts[idx[0]].n;
    return r;
  }
  for (int j = 0; j + 1 < m; ++j) {
    double e0 = ERR(j), e1 = ERR(j + 1);
    if (!(e0 > e && e1 <= e)) continue;
    const point *a = &pts[idx[j]], *b = &pts[idx[j + 1]];
    double s = (log(e) - log(e0)) / (log(e1) - log(e0));
    r.how = REACH_INTERP, r.cpu = exp(log(a->cpu) + s * (log(b->cpu) - log(a->cpu)));
    r.n_lo = a->n, r.n_hi = b->n;
    return r;
  }
#undef ERR
  return r;
}

/* the observed order: the least-squares slope over the finest meshes, n = 64..128 in the shipped sweep */
enum { MAX_SERIES = 4, NP = 6, SLOPE_POINTS = 5 };

/* The figure (core/study/chart.h): for the max-norm and the L2 error of the
 * profile, the error against cells per side (one series per code, the
 * solvers giving the same error, with the observed order) and against CPU
 * time (one series per code and solver); the centreline-minimum error and
 * the peak memory. Returns 0, or -1 with the reason on stderr. */
static int write_figure(const char *path, const point *pts, int np, const char *note) {
  static double x[MAX_SERIES][MAX_RUNS], xn[MAX_SERIES][MAX_RUNS], y[4][MAX_SERIES][MAX_RUNS], u[MAX_SERIES][MAX_RUNS];
  static char names[MAX_SERIES][48], codes[MAX_SERIES][48], lab[MAX_SERIES][MAX_RUNS][16];
  static const char *labels[MAX_SERIES][MAX_RUNS];
  static const char *const colour[MAX_SERIES] = {"#1f77b4", "#2ca02c", "#d62728", "#9467bd"};
  sl_chart_series ser[4][MAX_SERIES], by_n[2][MAX_SERIES];
  int ns_ = 0, n_in[MAX_SERIES] = {0}, n_codes = 0;
  for (int i = 0; i < np; ++i) {
    const char *code = strcmp(pts[i].code, "sluice") ? "FreeFEM P2/P1" : "sluice Q2/Q1";
    char name[48];
    snprintf(name, sizeof name, "%s, %s", code, pts[i].solver);
    int s = 0;
    while (s < ns_ && strcmp(names[s], name)) ++s;
    if (s == ns_) {
      if (ns_ == MAX_SERIES) continue;
      snprintf(names[ns_], sizeof names[0], "%s", name), snprintf(codes[ns_++], sizeof codes[0], "%s", code);
    }
    int k = n_in[s]++;
    x[s][k] = pts[i].cpu, xn[s][k] = pts[i].n, u[s][k] = (double)pts[i].unknowns;
    y[0][s][k] = pts[i].err_max, y[1][s][k] = pts[i].err_l2, y[2][s][k] = pts[i].min_err, y[3][s][k] = pts[i].mb;
    snprintf(lab[s][k], sizeof lab[s][k], "%d", pts[i].n);
    labels[s][k] = lab[s][k];
  }
  for (int q = 0; q < 4; ++q)
    for (int s = 0; s < ns_; ++s) {
      int is_ff = strncmp(names[s], "FreeFEM", 7) == 0, is_umf = strstr(names[s], "umfpack") && !is_ff;
      ser[q][s] = (sl_chart_series){.name = names[s],
                                    .n = n_in[s],
                                    .x = q == 3 ? u[s] : x[s],
                                    .y = y[q][s],
                                    .labels = q < 3 && !is_umf ? labels[s] : NULL,
                                    .colour = colour[s],
                                    .marker = (sl_chart_marker)(SL_CHART_MARK_CIRCLE + s),
                                    .dashed = is_umf};
    }
  for (int s = 0; s < ns_; ++s) { /* against the mesh: a code's first solver */
    int first = 1;
    for (int j = 0; j < s; ++j) first &= strcmp(codes[j], codes[s]) != 0;
    if (!first) continue;
    for (int q = 0; q < 2; ++q)
      by_n[q][n_codes] = (sl_chart_series){.name = codes[s],
                                           .n = n_in[s],
                                           .x = xn[s],
                                           .y = y[q][s],
                                           .colour = colour[s],
                                           .marker = (sl_chart_marker)(SL_CHART_MARK_CIRCLE + s),
                                           .slope_points = SLOPE_POINTS,
                                           .slope_format = "order %.2f",
                                           .slope_negate = 1};
    ++n_codes;
  }
  static const char *const ylab[3] = {"max_{k} |u(1/2, y_{k}) \xE2\x88\x92 u_{ref}(y_{k})| (m/s)",
                                      "L_{2} error of u(1/2, y) over y (m/s)",
                                      "|min u \xE2\x88\x92 u*| on x = 1/2 (m/s)"};
  sl_chart panels[NP] = {
      {.title = "max-norm error of u(1/2, y) against the mesh",
       .xlabel = "cells per side n",
       .ylabel = ylab[0],
       .n_series = n_codes,
       .series = by_n[0],
       .legend = SL_LEGEND_TOP_RIGHT},
      {.title = "max-norm error against CPU time",
       .xlabel = "CPU time of the solve (s)",
       .ylabel = ylab[0],
       .n_series = ns_,
       .series = ser[0],
       .legend = SL_LEGEND_TOP_RIGHT},
      {.title = "old measure: centreline minimum (not monotone)",
       .xlabel = "CPU time of the solve (s)",
       .ylabel = ylab[2],
       .n_series = ns_,
       .series = ser[2],
       .legend = SL_LEGEND_BOTTOM_LEFT},
      {.title = "L_{2} error of u(1/2, y) against the mesh",
       .xlabel = "cells per side n",
       .ylabel = ylab[1],
       .n_series = n_codes,
       .series = by_n[1],
       .legend = SL_LEGEND_TOP_RIGHT},
      {.title = "L_{2} error against CPU time",
       .xlabel = "CPU time of the solve (s)",
       .ylabel = ylab[1],
       .n_series = ns_,
       .series = ser[1],
       .legend = SL_LEGEND_TOP_RIGHT},
      {.title = "peak memory",
       .xlabel = "unknowns (velocity and pressure)",
       .ylabel = "peak resident set (MB)",
       .n_series = ns_,
       .series = ser[3],
       .legend = SL_LEGEND_TOP_LEFT},
  };
  for (int q = 0; q < NP; ++q) panels[q].xscale = panels[q].yscale = SL_AXIS_LOG;
  sl_figure fig = {.title = "Stokes cavity: sluice Q2/Q1 and FreeFEM P2/P1",
                   .note = note,
                   .n_panels = NP,
                   .panels = panels,
                   .columns = 3,
                   .panel_width = 480,
                   .panel_height = 360};
  sl_diag d = {{0}};
  if (sl_figure_write(path, &fig, &d)) return fprintf(stderr, "%s\n", d.msg), -1;
  return 0;
}

/* --replot: the runs back from a CSV this program wrote (its columns by
 * name; '#' lines give the note: the reference, the machine, how the CPU
 * time was taken), and the figure drawn from them, running nothing.
 * Returns 0, or -1 with file:line on stderr. */
static int replot(const char *csv, const char *path) {
  FILE *f = fopen(csv, "r");
  if (!f) return fprintf(stderr, "%s: %s\n", csv, strerror(errno)), -1;
  enum { CODE, SOLVER, N, UNKNOWNS, EMAX, EL2, MINU, MINERR, CPU, RSS, NC };
  static const char *const names[NC] = {"code",   "solver", "n",       "unknowns", "err_max",
                                        "err_l2", "min_u",  "min_err", "cpu_s",    "peak_rss_mb"};
  static point pts[MAX_RUNS];
  char line[4096], header[4096] = "", ref[1024] = "", machine[1024] = "", cpu[1024] = "";
  int c[NC], np = 0, lineno = 0, bad = 0;
  while (!bad && fgets(line, sizeof line, f)) {
    ++lineno;
    line[strcspn(line, "\r\n")] = '\0';
    if (line[0] == '#') {
      const char *r = strstr(line, "against the reference profile ");
      if (r && !ref[0]) { /* "... profile PATH (N points); ..." */
        r += strlen("against the reference profile ");
        const char *semi = strchr(r, ';'), *end = semi ? semi : r + strlen(r);
        for (const char *q = r; q < end; ++q)
          if (*q == '/') r = q + 1;
        snprintf(ref, sizeof ref, "%.*s", (int)(end - r), r);
      } else if (!strncmp(line, "# machine", 9)) snprintf(machine, sizeof machine, "%.1000s", line + 2);
      else if (!strncmp(line, "# cpu_s: ", 9)) snprintf(cpu, sizeof cpu, "%.1000s", line + 9);
      continue;
    }
    if (!header[0]) {
      snprintf(header, sizeof header, "%s", line);
      for (int k = 0; k < NC; ++k)
        if ((c[k] = bench_csv_column(header, names[k])) < 0)
          fprintf(stderr, "%s:%d: no column %s: not a bench_cavity_vs_freefem CSV\n", csv, lineno, names[k]), bad = 1;
      continue;
    }
    if (np == MAX_RUNS) {
      fprintf(stderr, "%s:%d: more than %d runs\n", csv, lineno, MAX_RUNS);
      bad = 1;
      break;
    }
    point *p = &pts[np];
    memset(p, 0, sizeof *p);
    bench_csv_field(line, c[CODE], p->code, sizeof p->code);
    bench_csv_field(line, c[SOLVER], p->solver, sizeof p->solver);
    double n = bench_csv_number(line, c[N]);
    p->n = (int)n, p->unknowns = (long)bench_csv_number(line, c[UNKNOWNS]);
    p->err_max = bench_csv_number(line, c[EMAX]), p->err_l2 = bench_csv_number(line, c[EL2]);
    p->umin = bench_csv_number(line, c[MINU]), p->min_err = bench_csv_number(line, c[MINERR]);
    p->cpu = bench_csv_number(line, c[CPU]), p->mb = bench_csv_number(line, c[RSS]);
    if ((strcmp(p->code, "sluice") && strcmp(p->code, "freefem")) || !p->solver[0] || !(n >= 1 && n == floor(n)) ||
        !(p->cpu > 0) || !isfinite(p->err_max) || !isfinite(p->err_l2)) {
      fprintf(stderr, "%s:%d: not a row of bench_cavity_vs_freefem's CSV\n", csv, lineno);
      bad = 1;
      break;
    }
    ++np;
  }
  fclose(f);
  if (!bad && !np) fprintf(stderr, "%s: no rows\n", csv), bad = 1;
  if (bad) return -1;
  char note[4096];
  snprintf(note, sizeof note,
           "labels: cells per side; order: least-squares slope of the five finest meshes. Reference u_{ref}: %s.\n"
           "CPU: %s.\n%s.",
           ref[0] ? ref : "not recorded", cpu[0] ? cpu : "not recorded", machine[0] ? machine : "machine not recorded");
  return write_figure(path, pts, np, note);
}

static void usage(void) {
  fputs(
      "usage: bench_cavity_vs_freefem SOURCE_DIR [--sluice-csv PATH] [--sluice-bench EXE] [--profile-ref FILE]\n"
      "                              [--reference U*] [--repeat R] [--csv PATH] [--svg PATH] [n ...]\n"
      "       bench_cavity_vs_freefem --replot CSV --svg PATH   (the figure of recorded runs)\n",
      stderr);
}

int main(int argc, char **argv) {
  const char *src = NULL, *sluice_csv = NULL, *csv = NULL, *svg = NULL, *prof_path = NULL, *sluice_bench = NULL,
             *replot_csv = NULL;
  double ref = -0.207755897;
  int repeat = 1, ns[MAX_N], n_ns = 0;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    int more = i + 1 < argc;
    if (strcmp(a, "--sluice-csv") == 0 && more) sluice_csv = argv[++i];
    else if (strcmp(a, "--profile-ref") == 0 && more) prof_path = argv[++i];
    else if (strcmp(a, "--sluice-bench") == 0 && more) sluice_bench = argv[++i];
    else if (strcmp(a, "--reference") == 0 && more) ref = strtod(argv[++i], NULL);
    else if (strcmp(a, "--repeat") == 0 && more) repeat = atoi(argv[++i]);
    else if (strcmp(a, "--csv") == 0 && more) csv = argv[++i];
    else if (strcmp(a, "--svg") == 0 && more) svg = argv[++i];
    else if (strcmp(a, "--replot") == 0 && more) replot_csv = argv[++i];
    else if (a[0] == '-') return usage(), 2;
    else if (!src) src = a;
    else if (n_ns < MAX_N && atoi(a) > 0) ns[n_ns++] = atoi(a);
    else return usage(), 2;
  }
  if (replot_csv) {
    if (!svg || src) return usage(), 2;
    return replot(replot_csv, svg) ? 2 : 0;
  }
  if (!src || repeat < 1) return usage(), 2;
  if (!n_ns) {
    static const int def[] = {8, 16, 32, 64, 128};
    for (n_ns = 0; n_ns < 5; ++n_ns) ns[n_ns] = def[n_ns];
  }
  char script[4096], sluice_default[4096], prof_default[4096], points[64];
  snprintf(script, sizeof script, "%s/bench/freefem/cavity_stokes.edp", src);
  snprintf(sluice_default, sizeof sluice_default, "%s/bench/results/cavity_vs_freefem.sluice.csv", src);
  snprintf(prof_default, sizeof prof_default, "%s/bench/freefem/cavity_centreline_ref.csv", src);
  if (!prof_path) prof_path = prof_default;
  static centreline_profile pr;
  if (centreline_profile_read(prof_path, &pr)) return 2;

  static point pts[MAX_RUNS], ff[MAX_N], tmp[8];
  static char pre[16384];
  char machine[512] = "not recorded in the sluice CSV", tmp_csv[64];
  int n_prof_sluice = 0, np = 0, failed = 0;
  if (!sluice_csv) sluice_csv = sluice_default;
  snprintf(points, sizeof points, "/tmp/sluice_ff_points_%ld.txt", (long)getpid());
  snprintf(tmp_csv, sizeof tmp_csv, "/tmp/sluice_ff_sluice_%ld.csv", (long)getpid());
  if (!sluice_bench) {
    np = read_sluice(sluice_csv, pts, MAX_RUNS - MAX_N, machine, sizeof machine, &n_prof_sluice, NULL, 0);
    if (np < 0) return 1;
    if (n_prof_sluice != pr.n) {
      fprintf(stderr, "%s: profile errors over %d points, the reference %s has %d: not the same points\n", sluice_csv,
              n_prof_sluice, prof_path, pr.n);
      return 2;
    }
  }

  /* The points for FreeFEM: the reference's y, printed to round-trip. */
  FILE *pf = fopen(points, "w");
  if (!pf) return fprintf(stderr, "%s: %s\n", points, strerror(errno)), 1;
  fprintf(pf, "%d\n", pr.n);
  for (int k = 0; k < pr.n; ++k) fprintf(pf, "%.17g\n", pr.y[k]);
  if (fclose(pf)) return fprintf(stderr, "%s: write failed\n", points), 1;

  /* Without --sluice-bench: the sluice CSV as given, then R FreeFEM runs per
   * mesh. With it: R rounds, each running every mesh once in both codes,
   * sluice then FreeFEM, so that both see the same load drift on a shared
   * machine; each keeps its least CPU time over the rounds. */
  double load[2][1] = {{NAN}, {NAN}};
  if (getloadavg(load[0], 1) != 1) load[0][0] = NAN;
  int ok_ff[MAX_N] = {0};
  int rounds = sluice_bench ? repeat : 1, per_run = sluice_bench ? 1 : repeat;
  double load_lo = load[0][0], load_hi = load[0][0];
  for (int r = 0; r < rounds && !failed; ++r)
    for (int k = 0; k < n_ns && !failed; ++k) {
      double now;
      if (getloadavg(&now, 1) == 1) load_lo = fmin(load_lo, now), load_hi = fmax(load_hi, now);
      if (sluice_bench) {
        fprintf(stderr, "round %d: sluice, n = %d ...", r + 1, ns[k]);
        int m = -1;
        if (!run_sluice_bench(sluice_bench, src, prof_path, ref, ns[k], tmp_csv))
          m = read_sluice(tmp_csv, tmp, 8, machine, sizeof machine, &n_prof_sluice, r == 0 && k == 0 ? pre : NULL,
                          sizeof pre);
        remove(tmp_csv);
        if (m <= 0 || n_prof_sluice != pr.n) {
          failed = 1;
          break;
        }
        for (int j = 0; j < m; ++j) {
          int i = 0;
          while (i < np && !(pts[i].n == tmp[j].n && !strcmp(pts[i].solver, tmp[j].solver))) ++i;
          if (i == np) pts[np++] = tmp[j];
          else if (tmp[j].cpu < pts[i].cpu) pts[i] = tmp[j];
          fprintf(stderr, " %s %.3g s", tmp[j].solver, tmp[j].cpu);
        }
        fputc('\n', stderr);
      }
      fprintf(stderr, "round %d: freefem, n = %d ...", r + 1, ns[k]);
      point one;
      if (run_freefem(script, points, &pr, ns[k], per_run, &one)) {
        failed = 1;
        break;
      }
      fprintf(stderr, " %.3g s CPU, %.0f MB, error %.3g (max) %.3g (L2)\n", one.cpu, one.mb, one.err_max, one.err_l2);
      if (!ok_ff[k] || one.cpu < ff[k].cpu) {
        double mb = ok_ff[k] ? fmax(ff[k].mb, one.mb) : one.mb;
        ff[k] = one, ff[k].mb = mb;
      } else ff[k].mb = fmax(ff[k].mb, one.mb);
      ok_ff[k] = 1;
    }
  if (getloadavg(load[1], 1) != 1) load[1][0] = NAN;
  load_lo = fmin(load_lo, load[1][0]), load_hi = fmax(load_hi, load[1][0]);
  remove(points);
  if (failed) return 1;
  if (sluice_bench && strstr(machine, ", load"))
    *strstr(machine, ", load") = '\0'; /* the last round's: the range is given */
  if (sluice_bench) {                  /* the merged sluice runs, as the work-precision CSV */
    FILE *sf = fopen(sluice_csv, "w");
    if (!sf) return fprintf(stderr, "%s: %s\n", sluice_csv, strerror(errno)), 1;
    fprintf(sf,
            "# fastest of %d rounds interleaved with FreeFEM's runs (bench_cavity_vs_freefem --sluice-bench), "
            "one bench_cavity_work_precision run per mesh and round; the lines below are from its first run\n",
            repeat);
    fputs(pre, sf);
    for (int i = 0; i < np; ++i) fputs(pts[i].raw, sf);
    if (fclose(sf)) return fprintf(stderr, "%s: write failed\n", sluice_csv), 1;
  }
  int first_ff = np;
  for (int k = 0; k < n_ns; ++k) pts[np++] = ff[k];
  for (int i = 0; i < np; ++i) pts[i].min_err = fabs(pts[i].umin - ref);

  /* sluice's runs per solver, ascending n */
  char solvers[MAX_SOLVERS][16];
  int idx[MAX_SOLVERS][MAX_RUNS], m[MAX_SOLVERS] = {0}, n_solv = 0;
  for (int i = 0; i < first_ff; ++i) {
    int s = 0;
    while (s < n_solv && strcmp(solvers[s], pts[i].solver)) ++s;
    if (s == n_solv) {
      if (n_solv == MAX_SOLVERS) continue;
      snprintf(solvers[n_solv++], sizeof solvers[0], "%s", pts[i].solver);
    }
    int j = m[s]++;
    idx[s][j] = i;
    for (; j > 0 && pts[idx[s][j - 1]].n > pts[idx[s][j]].n; --j) {
      int t = idx[s][j];
      idx[s][j] = idx[s][j - 1], idx[s][j - 1] = t;
    }
  }

  FILE *out[2] = {stdout, csv ? fopen(csv, "w") : NULL};
  if (csv && !out[1]) fprintf(stderr, "%s: %s\n", csv, strerror(errno)), failed = 1;
  for (int o = 0; o < 2; ++o) {
    FILE *f = out[o];
    if (!f) continue;
    fprintf(f, "# Stokes cavity, u(1/2, y) against the reference profile %s (%d points); sluice Q2/Q1, FreeFEM P2/P1\n",
            prof_path, pr.n);
    fprintf(f,
            "# err_max = max_k |u(1/2, y_k) - u_ref(y_k)|, err_l2 = its L2 norm over 0 <= y <= 1 (trapezoid "
            "rule over the points); min_err = |min u - u*|, u* = %.9f (secondary: not monotone in n below 1e-6)\n",
            ref);
    if (sluice_bench)
      fprintf(f, "# machine: %s; 1-min load average %.2f-%.2f over the runs (sampled before each mesh)\n", machine,
              load_lo, load_hi);
    else
      fprintf(f, "# machine (sluice runs, %s): %s; FreeFEM runs: load %.2f at start, %.2f at end\n", sluice_csv,
              machine, load[0][0], load[1][0]);
    fprintf(f,
            "# cpu_s: fastest of %d %s; sluice: process CPU time of sl_model_run; FreeFEM: clock() from the mesh "
            "to the solution\n",
            repeat, sluice_bench ? "interleaved rounds (sluice, then FreeFEM, mesh by mesh)" : "repeats");
    fprintf(f, "code,solver,n,unknowns,err_max,err_l2,min_u,min_err,cpu_s,peak_rss_mb\n");
    for (int i = 0; i < np; ++i)
      fprintf(f, "%s,%s,%d,%ld,%.4e,%.4e,%.12f,%.3e,%.4g,%.1f\n", pts[i].code, pts[i].solver, pts[i].n, pts[i].unknowns,
              pts[i].err_max, pts[i].err_l2, pts[i].umin, pts[i].min_err, pts[i].cpu, pts[i].mb);
    /* At equal accuracy: sluice's CPU time for FreeFEM's error, interpolated log-log between its meshes. */
    for (int measure = 0; measure < 2; ++measure)
      for (int i = first_ff; i < np; ++i) {
        double e = measure ? pts[i].err_l2 : pts[i].err_max;
        fprintf(f, "# equal %s error: FreeFEM n = %d: %.3e in %.4g s", measure ? "L2" : "max-norm", pts[i].n, e,
                pts[i].cpu);
        for (int s = 0; s < n_solv; ++s) {
          reach_result r = time_to_reach(pts, idx[s], m[s], e, measure);
          if (r.how == REACH_INTERP)
            fprintf(f, "; sluice %s %.4g s (interpolated between n = %d and %d), %.2fx", solvers[s], r.cpu, r.n_lo,
                    r.n_hi, r.cpu / pts[i].cpu);
          else if (r.how == REACH_COARSEST)
            fprintf(f, "; sluice %s at most %.4g s (its coarsest run, n = %d, is already as accurate), <= %.2fx",
                    solvers[s], r.cpu, r.n_lo, r.cpu / pts[i].cpu);
          else fprintf(f, "; sluice %s: no run that accurate", solvers[s]);
        }
        fputc('\n', f);
      }
  }
  if (out[1] && fclose(out[1])) failed = 1;

  if (svg) {
    char note[8192];
    snprintf(note, sizeof note,
             "labels: cells per side; order: least-squares slope of the five finest meshes. Reference u_{ref}: %d "
             "points of %s.\nCPU: fastest of %d %s; sluice's from bench_cavity_work_precision (process CPU of the "
             "solve), FreeFEM's from mesh to solution.\n%s; %s %.2f-%.2f.",
             pr.n, strrchr(prof_path, '/') ? strrchr(prof_path, '/') + 1 : prof_path, repeat,
             sluice_bench ? "interleaved rounds" : "repeats", machine,
             sluice_bench ? "load over the runs" : "FreeFEM runs at load", sluice_bench ? load_lo : load[0][0],
             sluice_bench ? load_hi : load[1][0]);
    if (write_figure(svg, pts, np, note)) failed = 1;
  }
  return failed;
}
