/* The Stokes cavity against FreeFEM: error of the centreline minimum against
 * CPU time for sluice (Q2/Q1, read from the CSV of
 * bench_cavity_work_precision) and for FreeFEM (P2/P1 on the same number of
 * unknowns, bench/freefem/cavity_stokes.edp, run here), on one plot.
 *
 * FreeFEM is for comparison only, not a dependency (Debian: freefem++). Each
 * FreeFEM run is its own process; its CPU time is the script's clock() from
 * the mesh to the solution (FreeFEM's start-up and the sampling excluded,
 * as sluice's cpu_s excludes process start-up), its peak memory the child's
 * ru_maxrss. The error of both is |min u - u*| against the same u*.
 *
 *   bench_cavity_vs_freefem SOURCE_DIR [--sluice-csv PATH] [--reference U*]
 *       [--repeat R] [--csv PATH] [--svg PATH] [n ...]   (default n: 8 16 32 64 128)
 *
 * The sluice CSV defaults to SOURCE_DIR/bench/results/cavity_work_precision.csv;
 * u* to -0.207755897 (the README's Richardson extrapolation of n = 64, 128,
 * 256). CSV on stdout (and in --csv PATH): code, solver, n, unknowns, min_u,
 * error, cpu_s, peak_rss_mb; then, for each FreeFEM run, the cheapest sluice
 * run at least as accurate. Exit status 1 when a run failed, 2 on bad usage. */
#define _DEFAULT_SOURCE /* wait4 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "svg_plot.h"

enum { MAX_RUNS = 64, MAX_N = 16 };

typedef struct point {
  char code[16], solver[16];
  int n;
  long unknowns;
  double umin, error, cpu, mb;
} point;

/* Runs FreeFem++ on the script for n cells per side (fastest of repeat). */
static int run_freefem(const char *script, int n, int repeat, point *p) {
  memset(p, 0, sizeof *p);
  snprintf(p->code, sizeof p->code, "freefem"), snprintf(p->solver, sizeof p->solver, "umfpack");
  p->n = n, p->cpu = INFINITY;
  for (int k = 0; k < repeat; ++k) {
    int fd[2];
    if (pipe(fd)) return fprintf(stderr, "pipe: %s\n", strerror(errno)), -1;
    pid_t pid = fork();
    if (pid < 0) return fprintf(stderr, "fork: %s\n", strerror(errno)), -1;
    if (pid == 0) {
      char arg[32];
      snprintf(arg, sizeof arg, "%d", n);
      dup2(fd[1], STDOUT_FILENO);
      close(fd[0]), close(fd[1]);
      execlp("FreeFem++", "FreeFem++", "-nw", "-v", "0", script, arg, (char *)NULL);
      fprintf(stderr, "FreeFem++: %s (Debian: apt-get install freefem++)\n", strerror(errno));
      _exit(127);
    }
    close(fd[1]);
    FILE *f = fdopen(fd[0], "r");
    char line[512];
    int got = 0;
    double umin = NAN, cpu = NAN;
    long unknowns = 0;
    int nn = 0;
    while (f && fgets(line, sizeof line, f))
      if (sscanf(line, "RESULT %d %ld %lf %lf", &nn, &unknowns, &umin, &cpu) == 4) got = 1;
    if (f) fclose(f);
    else close(fd[0]);
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) < 0) return fprintf(stderr, "wait4: %s\n", strerror(errno)), -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !got) {
      fprintf(stderr, "FreeFem++ %s %d failed (status %d)\n", script, n, status);
      return -1;
    }
    p->unknowns = unknowns, p->umin = umin;
    if (cpu < p->cpu) p->cpu = cpu;
    double mb = ru.ru_maxrss / 1024.0;
    if (mb > p->mb) p->mb = mb;
  }
  return 0;
}

/* The column of `name` in a CSV header line, or -1. */
static int column(const char *header, const char *name) {
  int k = 0;
  size_t len = strlen(name);
  for (const char *s = header; *s; ++k) {
    const char *e = strpbrk(s, ",\n");
    size_t w = e ? (size_t)(e - s) : strlen(s);
    if (w == len && strncmp(s, name, len) == 0) return k;
    if (!e || *e == '\n') break;
    s = e + 1;
  }
  return -1;
}

/* Field k of a CSV line (no quoting: bench CSVs have none) into buf. */
static void field(const char *line, int k, char *buf, size_t cap) {
  const char *s = line;
  for (int i = 0; i < k && s; ++i) s = strchr(s, ','), s = s ? s + 1 : NULL;
  buf[0] = '\0';
  if (!s) return;
  size_t w = strcspn(s, ",\n");
  snprintf(buf, cap, "%.*s", (int)(w < cap ? w : cap - 1), s);
}

/* The steady runs of bench_cavity_work_precision's CSV. */
static int read_sluice(const char *path, point *pts, int max) {
  FILE *f = fopen(path, "r");
  if (!f) return fprintf(stderr, "%s: %s (run bench_cavity_work_precision --csv first)\n", path, strerror(errno)), -1;
  char line[4096], header[4096] = "";
  int n = 0, c[5] = {-1, -1, -1, -1, -1};
  static const char *const names[5] = {"solver", "n", "unknowns", "umin", "cpu_s"};
  int c_mb = -1;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    if (!header[0]) {
      snprintf(header, sizeof header, "%s", line);
      for (int k = 0; k < 5; ++k) c[k] = column(header, names[k]);
      c_mb = column(header, "peak_rss_mb");
      if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[3] < 0 || c[4] < 0) {
        fclose(f);
        return fprintf(stderr, "%s: not a bench_cavity_work_precision CSV\n", path), -1;
      }
      continue;
    }
    if (n == max) break;
    point *p = &pts[n];
    char buf[64];
    memset(p, 0, sizeof *p);
    snprintf(p->code, sizeof p->code, "sluice");
    field(line, c[0], p->solver, sizeof p->solver);
    field(line, c[1], buf, sizeof buf), p->n = atoi(buf);
    field(line, c[2], buf, sizeof buf), p->unknowns = atol(buf);
    field(line, c[3], buf, sizeof buf), p->umin = strtod(buf, NULL);
    field(line, c[4], buf, sizeof buf), p->cpu = strtod(buf, NULL);
    if (c_mb >= 0) field(line, c_mb, buf, sizeof buf), p->mb = strtod(buf, NULL);
    if (p->n > 0 && isfinite(p->umin) && p->cpu > 0) ++n; /* a failed run has no time */
  }
  fclose(f);
  return n;
}

static void usage(void) {
  fputs("usage: bench_cavity_vs_freefem SOURCE_DIR [--sluice-csv PATH] [--reference U*] [--repeat R]\n"
        "                              [--csv PATH] [--svg PATH] [n ...]\n",
        stderr);
}

int main(int argc, char **argv) {
  const char *src = NULL, *sluice_csv = NULL, *csv = NULL, *svg = NULL;
  double ref = -0.207755897;
  int repeat = 1, ns[MAX_N], n_ns = 0;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    int more = i + 1 < argc;
    if (strcmp(a, "--sluice-csv") == 0 && more) sluice_csv = argv[++i];
    else if (strcmp(a, "--reference") == 0 && more) ref = strtod(argv[++i], NULL);
    else if (strcmp(a, "--repeat") == 0 && more) repeat = atoi(argv[++i]);
    else if (strcmp(a, "--csv") == 0 && more) csv = argv[++i];
    else if (strcmp(a, "--svg") == 0 && more) svg = argv[++i];
    else if (a[0] == '-') return usage(), 2;
    else if (!src) src = a;
    else if (n_ns < MAX_N && atoi(a) > 0) ns[n_ns++] = atoi(a);
    else return usage(), 2;
  }
  if (!src || repeat < 1) return usage(), 2;
  if (!n_ns) {
    static const int def[] = {8, 16, 32, 64, 128};
    for (n_ns = 0; n_ns < 5; ++n_ns) ns[n_ns] = def[n_ns];
  }
  char script[4096], sluice_default[4096];
  snprintf(script, sizeof script, "%s/bench/freefem/cavity_stokes.edp", src);
  snprintf(sluice_default, sizeof sluice_default, "%s/bench/results/cavity_work_precision.csv", src);
  point pts[MAX_RUNS];
  int np = read_sluice(sluice_csv ? sluice_csv : sluice_default, pts, MAX_RUNS - MAX_N);
  if (np < 0) return 1;
  int failed = 0, first_ff = np;
  for (int k = 0; k < n_ns; ++k) {
    fprintf(stderr, "freefem, n = %d ...", ns[k]);
    if (run_freefem(script, ns[k], repeat, &pts[np])) {
      failed = 1;
      continue;
    }
    fprintf(stderr, " %.3g s CPU, %.0f MB\n", pts[np].cpu, pts[np].mb);
    ++np;
  }
  for (int i = 0; i < np; ++i) pts[i].error = fabs(pts[i].umin - ref);

  FILE *out[2] = {stdout, csv ? fopen(csv, "w") : NULL};
  if (csv && !out[1]) fprintf(stderr, "%s: %s\n", csv, strerror(errno)), failed = 1;
  for (int o = 0; o < 2; ++o) {
    FILE *f = out[o];
    if (!f) continue;
    fprintf(f, "# Stokes cavity, min u on x = 1/2 against u* = %.9f; sluice Q2/Q1, FreeFEM P2/P1\n", ref);
    fprintf(f, "code,solver,n,unknowns,min_u,error,cpu_s,peak_rss_mb\n");
    for (int i = 0; i < np; ++i)
      fprintf(f, "%s,%s,%d,%ld,%.12f,%.3e,%.4g,%.1f\n", pts[i].code, pts[i].solver, pts[i].n, pts[i].unknowns,
              pts[i].umin, pts[i].error, pts[i].cpu, pts[i].mb);
    /* At equal accuracy: the cheapest sluice run with an error no larger than FreeFEM's. */
    for (int i = first_ff; i < np; ++i) {
      int best = -1;
      for (int j = 0; j < first_ff; ++j)
        if (pts[j].error <= pts[i].error && (best < 0 || pts[j].cpu < pts[best].cpu)) best = j;
      if (best >= 0)
        fprintf(f, "# FreeFEM n = %d: error %.2e in %.3g s; sluice %s n = %d: %.2e in %.3g s (%.2fx the time)\n",
                pts[i].n, pts[i].error, pts[i].cpu, pts[best].solver, pts[best].n, pts[best].error, pts[best].cpu,
                pts[best].cpu / pts[i].cpu);
      else
        fprintf(f, "# FreeFEM n = %d: error %.2e in %.3g s; no sluice run that accurate\n", pts[i].n, pts[i].error,
                pts[i].cpu);
    }
  }
  if (out[1] && fclose(out[1])) failed = 1;

  if (svg) {
    /* One series per code and solver, in mesh order. */
    enum { MAX_SERIES = 4 };
    static double x[MAX_SERIES][MAX_RUNS], y[MAX_SERIES][MAX_RUNS], u[MAX_SERIES][MAX_RUNS], m[MAX_SERIES][MAX_RUNS];
    static char names[MAX_SERIES][48], lab[MAX_SERIES][MAX_RUNS][16];
    static const char *labels[MAX_SERIES][MAX_RUNS];
    svgp_series err[MAX_SERIES], mem[MAX_SERIES];
    int ns_ = 0;
    for (int i = 0; i < np; ++i) {
      char name[48];
      snprintf(name, sizeof name, "%s %s", strcmp(pts[i].code, "sluice") ? "FreeFEM P2/P1," : "sluice Q2/Q1,",
               pts[i].solver);
      int s = 0;
      while (s < ns_ && strcmp(names[s], name)) ++s;
      if (s == ns_) {
        if (ns_ == MAX_SERIES) continue;
        snprintf(names[ns_++], sizeof names[0], "%s", name);
        err[s] = (svgp_series){.name = names[s], .marker = (svgp_marker)s, .dashed = s == 2};
        err[s].x = x[s], err[s].y = y[s], err[s].labels = labels[s];
      }
      int k = err[s].n++;
      x[s][k] = pts[i].cpu, y[s][k] = pts[i].error, u[s][k] = (double)pts[i].unknowns, m[s][k] = pts[i].mb;
      snprintf(lab[s][k], sizeof lab[s][k], "%d", pts[i].n);
      labels[s][k] = lab[s][k];
    }
    for (int s = 0; s < ns_; ++s) {
      mem[s] = err[s];
      mem[s].x = u[s], mem[s].y = m[s], mem[s].labels = NULL;
    }
    svgp_panel panels[2] = {
        {.title = "error against CPU time", .xlabel = "CPU s", .ylabel = "|min u - u*|", .n_series = ns_,
         .series = err, .legend = SVGP_TOP_RIGHT},
        {.title = "peak memory", .xlabel = "unknowns", .ylabel = "MB", .n_series = ns_, .series = mem,
         .legend = SVGP_TOP_LEFT},
    };
    svgp_figure fig = {.title = "Stokes cavity: sluice and FreeFEM",
                       .note = "labels: cells per side; sluice's CPU from bench_cavity_work_precision, FreeFEM's "
                               "from mesh to solution",
                       .n_panels = 2,
                       .panels = panels};
    if (svgp_write(svg, &fig)) fprintf(stderr, "%s: %s\n", svg, strerror(errno)), failed = 1;
  }
  return failed;
}
