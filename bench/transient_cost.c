/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What a run of the shipped 2-D scenes costs, and what it cost before:
 * CPU seconds, accepted and rejected steps, Newton iterations, numeric
 * factorisations and reused solves, per scene and per variant, the
 * variants interleaved round by round (other jobs on the machine load them
 * alike) and each the fastest of --repeat R rounds.
 *
 * The variants run `sluice run` as a child process (its CPU time from
 * wait4, user + system) and read its summary lines:
 *   after          this build's sluice as it is (the defaults: [flow] scheme = auto);
 *   monolithic     ... with [flow] scheme = monolithic (the coupled step, the default before auto);
 *   umfpack        ... with [solver] linear = umfpack;
 *   klu            ... with [solver] linear = klu;
 *   no reuse       ... with [solver] reuse = never (a factorisation per changed matrix);
 *   projection     ... with [flow] scheme = projection (the split step), and with it at [time] tolerance 2.5e-4;
 *   before         --before BIN: another build (e.g. of the commit before the change), with its defaults;
 *   before, projection  the same with [flow] scheme = projection;
 *   before, ref. BLAS  the same with --reference-blas DIR first on LD_LIBRARY_PATH (Debian's reference
 *                  libblas.so.3, e.g. /usr/lib/x86_64-linux-gnu/blas).
 * The cases: boycott to t = 0.1 and 0.8 (its 24 x 32 mesh), spinup to t = 25
 * on the mesh of its test (48 x 24, nonlinear tolerance 1e-6), the Bingham
 * cavity's continuation (steady), wave_bed as shipped (two wave periods),
 * the Re = 100 cavity (steady Newton), the Stokes cavity on 128 x 128
 * cells (one solve, 149 k unknowns), the migration scenes as shipped, the
 * spectrometer to t = 0.5 and the rotating waves to t = 10; --quick leaves
 * out boycott to 0.8, spinup, wave_bed, the migration scenes, the
 * spectrometer and the rotating waves.
 *
 *   bench_transient_cost [SOURCE_DIR] [--before BIN [--before-label TEXT]] [--reference-blas DIR]
 *                        [--repeat R] [--quick] [--case NAME]... [--variant NAME]...
 *                        [--markdown PATH [--append]] [--title TEXT]
 * The cases marked large (the linear solvers at growing meshes) run only when named by --case; the variants
 * "petsc" and "petsc, mumps" need a build with -DSLUICE_WITH_PETSC=ON (its bench_transient_cost).
 *
 * A markdown table on stdout (and in --markdown PATH, e.g. docs/transient_cost.md): per case and variant the
 * counts, the CPU time and its ratio to the first variant of the case (before, where given); --append adds
 * the table to PATH under a heading of its own (a second run with other cases or repeats). Progress on
 * stderr. The exit status is 1 when a run failed. */
#define _DEFAULT_SOURCE /* mkstemp, setenv, wait4 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_machine.h"
#include "core/study/child.h"

enum { MAX_SETS = 8, MAX_VARIANTS = 8, MAX_CASES = 16 };

typedef struct bench_case {
  const char *name, *scene, *what;
  const char *sets[MAX_SETS];
  int quick;          /* in --quick */
  int iterative_only; /* too large for the direct solvers on this machine: only the petsc variants run it */
  int large;          /* run only when asked for by --case */
} bench_case;

static const bench_case cases[] = {
    {"boycott_0.1", "boycott", "boycott to t = 0.1, 24 x 32 cells", {"time.end=0.1", NULL}, 1, 0, 0},
    {"boycott_0.8", "boycott", "boycott to t = 0.8, 24 x 32 cells", {"time.end=0.8", NULL}, 0, 0, 0},
    {"spinup_25",
     "spinup",
     "spinup to t = 25, 48 x 24 cells (its test's)",
     {"time.end=25", "mesh.cells=48,24", "solver.nonlinear_tolerance=1e-6", NULL},
     0,
     0,
     0},
    {"bingham_cavity", "bingham_cavity", "bingham_cavity, steady continuation in eps, 32 x 32 cells", {NULL}, 1, 0, 0},
    {"wave_bed", "wave_bed", "wave_bed as shipped, two wave periods, 32 x 24 cells", {NULL}, 0, 0, 0},
    /* the other shipped 2-D transient scenes of the flow solver (their rejected steps; docs/transient_cost.md) */
    {"migration_couette",
     "migration_couette",
     "migration_couette as shipped (annulus 48 x 1, t = 2700)",
     {NULL},
     0,
     0,
     0},
    {"migration_poiseuille",
     "migration_poiseuille",
     "migration_poiseuille as shipped (annulus 40 x 1, t = 600)",
     {NULL},
     0,
     0,
     0},
    {"spectrometer_0.5", "spectrometer", "spectrometer to t = 0.5 (of 3)", {"time.end=0.5", NULL}, 0, 0, 0},
    {"rotating_waves_10",
     "rotating_waves",
     "rotating_waves to t = 10 (of 150), 3072 cells",
     {"time.end=10", NULL},
     0,
     0,
     0},
    {"cavity_re100", "cavity_re100", "cavity_re100, steady Newton, 32 x 32 cells", {NULL}, 1, 0, 0},
    {"cavity_stokes_128",
     "cavity_stokes",
     "cavity_stokes, one direct solve, 128 x 128 cells",
     {"mesh.cells=128,128", NULL},
     1,
     0,
     0},
    /* the linear solvers at growing meshes (--case), PETSc's against the direct ones */
    {"cavity_stokes_64",
     "cavity_stokes",
     "cavity_stokes, 64 x 64 cells (37 k unknowns)",
     {"mesh.cells=64,64", NULL},
     0,
     0,
     1},
    {"cavity_stokes_256",
     "cavity_stokes",
     "cavity_stokes, 256 x 256 cells (592 k unknowns)",
     {"mesh.cells=256,256", NULL},
     0,
     0,
     1},
    {"cavity_stokes_512",
     "cavity_stokes",
     "cavity_stokes, 512 x 512 cells (2.4 M unknowns)",
     {"mesh.cells=512,512", NULL},
     0,
     1,
     1},
    {"boycott_48x64",
     "boycott",
     "boycott, 50 fixed steps to t = 0.05, 48 x 64 cells",
     {"mesh.cells=48,64", "time.end=0.05", "time.adaptive=false", "output.every=0.05", NULL},
     0,
     0,
     1},
    {"boycott_96x128",
     "boycott",
     "boycott, 50 fixed steps to t = 0.05, 96 x 128 cells",
     {"mesh.cells=96,128", "time.end=0.05", "time.adaptive=false", "output.every=0.05", NULL},
     0,
     0,
     1},
};
enum { N_CASES = (int)(sizeof cases / sizeof cases[0]) };

typedef struct variant {
  const char *name;
  const char *set;   /* an override, or NULL */
  const char *set2;  /* a second one, or NULL */
  const char *petsc; /* --petsc options, or NULL */
  int before;        /* runs --before BIN */
  int ref_blas;      /* with --reference-blas first on LD_LIBRARY_PATH */
} variant;

static const variant variants[] = {
    {"before, ref. BLAS", NULL, NULL, NULL, 1, 1},
    {"before", NULL, NULL, NULL, 1, 0},
    {"before, projection", "flow.scheme=projection", NULL, NULL, 1, 0}, /* --before BIN's split step */
    {"no reuse", "solver.reuse=never", NULL, NULL, 0, 0},
    {"umfpack", "solver.linear=umfpack", NULL, NULL, 0, 0},
    {"klu", "solver.linear=klu", NULL, NULL, 0, 0},
    {"after", NULL, NULL, NULL, 0, 0},
    {"monolithic", "flow.scheme=monolithic", NULL, NULL, 0, 0}, /* the coupled step (the default before auto) */
    /* the split step (core/models/navier_stokes/projection.h), at the scene's tolerance and at a quarter of it */
    {"projection", "flow.scheme=projection", NULL, NULL, 0, 0},
    {"projection, tolerance 2.5e-4", "flow.scheme=projection", "time.tolerance=2.5e-4", NULL, 0, 0},
    /* a build with -DSLUICE_WITH_PETSC=ON: its defaults, and MUMPS (parallel direct) through it */
    {"petsc", "solver.linear=petsc", NULL, NULL, 0, 0},
    {"petsc, mumps", "solver.linear=petsc", NULL, "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps", 0,
     0},
};
enum { N_VARIANTS = (int)(sizeof variants / sizeof variants[0]) };

typedef struct result {
  int ok, steps_known;
  double cpu, peak_mb;
  long steps, rejected, newton, numeric, reused, krylov;
  char linear[32], why[256];
} result;

/* The summary lines of `sluice run` (core/cli/progress.c, cmd_run.c). */
static void parse(const char *text, result *r) {
  const char *p = strstr(text, "sluice: ");
  for (; p; p = strstr(p + 1, "sluice: ")) {
    long a, b, c;
    if (sscanf(p, "sluice: %ld steps (%ld rejected), %ld", &a, &b, &c) == 3 ||
        sscanf(p, "sluice: %ld step (%ld rejected), %ld", &a, &b, &c) == 3) {
      r->steps = a, r->rejected = b, r->newton = c, r->steps_known = 1;
    }
    if (!strncmp(p, "sluice: output ", 15)) {
      const char *q = strchr(p, '(');
      if (q) {
        sscanf(q + 1, "%31[a-z]", r->linear);
        /* "N numeric", "N reused": the count before the word */
        const char *words[2] = {" numeric", " reused"};
        long *into[2] = {&r->numeric, &r->reused};
        for (int w = 0; w < 2; ++w) {
          const char *s = strstr(q, words[w]);
          if (!s) continue;
          while (s > q && s[-1] >= '0' && s[-1] <= '9') --s;
          *into[w] = strtol(s, NULL, 10);
        }
        /* an iterative backend's "(fgmres/fieldsplit, N iterations)" */
        const char *it = strstr(q, " iterations)");
        if (it) {
          while (it > q && it[-1] >= '0' && it[-1] <= '9') --it;
          r->krylov = strtol(it, NULL, 10);
        }
      }
    }
  }
}

/* Runs args[0] with args, stderr and stdout into a temporary file; CPU and peak memory are the child's own. */
static int run(char *const *args, const char *ld_path, result *r) {
  char log[] = "/tmp/sluice_bench_transient_XXXXXX";
  int fd = mkstemp(log);
  if (fd < 0) {
    snprintf(r->why, sizeof r->why, "mkstemp: %s", strerror(errno));
    return -1;
  }
  close(fd);
  char ld[4096];
  const char *old = getenv("LD_LIBRARY_PATH");
  if (ld_path) snprintf(ld, sizeof ld, "LD_LIBRARY_PATH=%s%s%s", ld_path, old ? ":" : "", old ? old : "");
  const char *const env[] = {ld, NULL};
  sl_child_opts co = {.argv = args, .result_fd = -1, .env = ld_path ? env : NULL, .out = log, .err = log};
  sl_child_result cr;
  if (sl_child_run(&co, &cr)) {
    snprintf(r->why, sizeof r->why, "%.200s", cr.message);
    unlink(log);
    return -1;
  }
  r->peak_mb = cr.peak_rss_mb;
  r->cpu = cr.cpu;
  FILE *f = fopen(log, "r");
  char *text = NULL;
  size_t n = 0;
  if (f) {
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    text = calloc((size_t)(len > 0 ? len : 0) + 1, 1);
    if (text && len > 0) n = fread(text, 1, (size_t)len, f);
    fclose(f);
  }
  unlink(log);
  if (text) text[n] = 0;
  r->ok = cr.exit_code == 0 && !cr.signal_number;
  if (text) parse(text, r);
  if (!r->ok) {
    const char *e = text ? strstr(text, "error") : NULL;
    snprintf(r->why, sizeof r->why, "exit status %d%s%.200s", cr.signal_number ? -1 : cr.exit_code, e ? ": " : "",
             e ? e : "");
  } else if (!r->steps_known) {
    r->ok = 0;
    snprintf(r->why, sizeof r->why, "no summary line");
  }
  free(text);
  return r->ok ? 0 : -1;
}

int main(int argc, char **argv) {
  const char *src = SLUICE_SOURCE_DIR, *before = NULL, *before_label = NULL, *ref_blas = NULL, *markdown = NULL,
             *title = "Benchmarks: the cost of the 2-D scenes";
  int repeat = 2, quick = 0, append = 0, n_case_sel = 0, n_var_sel = 0;
  const char *case_sel[MAX_CASES], *var_sel[MAX_VARIANTS];
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--before") && i + 1 < argc) before = argv[++i];
    else if (!strcmp(argv[i], "--before-label") && i + 1 < argc) before_label = argv[++i];
    else if (!strcmp(argv[i], "--reference-blas") && i + 1 < argc) ref_blas = argv[++i];
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--markdown") && i + 1 < argc) markdown = argv[++i];
    else if (!strcmp(argv[i], "--title") && i + 1 < argc) title = argv[++i];
    else if (!strcmp(argv[i], "--quick")) quick = 1;
    else if (!strcmp(argv[i], "--append")) append = 1;
    else if (!strcmp(argv[i], "--case") && i + 1 < argc && n_case_sel < MAX_CASES) case_sel[n_case_sel++] = argv[++i];
    else if (!strcmp(argv[i], "--variant") && i + 1 < argc && n_var_sel < MAX_VARIANTS)
      var_sel[n_var_sel++] = argv[++i];
    else if (argv[i][0] != '-') src = argv[i];
    else {
      fprintf(stderr,
              "usage: bench_transient_cost [SOURCE_DIR] [--before BIN [--before-label TEXT]] "
              "[--reference-blas DIR] [--repeat R] [--quick] [--case NAME]... [--variant NAME]... "
              "[--markdown PATH [--append]] [--title TEXT]\n");
      return 2;
    }
  }
  if (repeat < 1) repeat = 1;
  char self[4096];
  snprintf(self, sizeof self, "%s", SLUICE_EXECUTABLE);
  int use_case[N_CASES], use_var[N_VARIANTS];
  for (int c = 0; c < N_CASES; ++c) {
    use_case[c] = n_case_sel == 0 ? (!quick || cases[c].quick) && !cases[c].large : 0;
    for (int k = 0; k < n_case_sel; ++k) use_case[c] |= !strcmp(case_sel[k], cases[c].name);
  }
  for (int v = 0; v < N_VARIANTS; ++v) {
    use_var[v] = n_var_sel == 0;
    for (int k = 0; k < n_var_sel; ++k) use_var[v] |= !strcmp(var_sel[k], variants[v].name);
    if (variants[v].before && !before) use_var[v] = 0;
    if (variants[v].ref_blas && !ref_blas) use_var[v] = 0;
  }
  static result best[N_CASES][N_VARIANTS];
  int failed = 0;
  char out[256];
  snprintf(out, sizeof out, "/tmp/sluice_bench_transient_%ld.h5", (long)getpid());
  for (int round = 0; round < repeat; ++round)
    for (int c = 0; c < N_CASES; ++c) {
      if (!use_case[c]) continue;
      for (int v = 0; v < N_VARIANTS; ++v) {
        if (!use_var[v] || (cases[c].iterative_only && strcmp(variants[v].name, "petsc") != 0)) continue;
        char scene[4096];
        snprintf(scene, sizeof scene, "%s/configs/%s.ini", src, cases[c].scene);
        char *args[4 + 2 * MAX_SETS + 6];
        int na = 0;
        args[na++] = (char *)(variants[v].before ? before : self);
        args[na++] = "run";
        args[na++] = scene;
        for (int k = 0; cases[c].sets[k]; ++k) args[na++] = "--set", args[na++] = (char *)cases[c].sets[k];
        if (variants[v].set) args[na++] = "--set", args[na++] = (char *)variants[v].set;
        if (variants[v].set2) args[na++] = "--set", args[na++] = (char *)variants[v].set2;
        if (variants[v].petsc) args[na++] = "--petsc", args[na++] = (char *)variants[v].petsc;
        args[na++] = "-o", args[na++] = out;
        args[na] = NULL;
        result r = {0};
        fprintf(stderr, "round %d: %s, %s ... ", round + 1, cases[c].name, variants[v].name);
        int rc = run(args, variants[v].ref_blas ? ref_blas : NULL, &r);
        char xmf[300];
        snprintf(xmf, sizeof xmf, "%.*s.xmf", (int)strlen(out) - 3, out);
        remove(out), remove(xmf);
        if (rc) {
          fprintf(stderr, "failed: %s\n", r.why);
          ++failed;
          continue;
        }
        fprintf(stderr, "%.2f s CPU, %.0f MB, %ld steps (%ld rejected), %ld Newton, %ld numeric, %ld reused\n", r.cpu,
                r.peak_mb, r.steps, r.rejected, r.newton, r.numeric, r.reused);
        result *b = &best[c][v];
        if (!b->ok || r.cpu < b->cpu) *b = r;
      }
    }
  char machine[512];
  bench_machine_describe(machine, sizeof machine);
  FILE *md = markdown ? fopen(markdown, append ? "a" : "w") : NULL;
  if (markdown && !md) fprintf(stderr, "cannot write %s: %s\n", markdown, strerror(errno));
  FILE *sinks[2] = {stdout, md};
  for (int s = 0; s < 2; ++s) {
    FILE *f = sinks[s];
    if (!f) continue;
    if (f == md && append) fprintf(f, "\n## A further run\n\n");
    else fprintf(f, "# %s\n\n", title);
    fprintf(f,
            "Written by `bench_transient_cost` (bench/transient_cost.c). %s; each time the fastest of %d "
            "interleaved round%s, CPU seconds of the whole `sluice run` (user + system). \"before\" is `%s`%s.\n\n",
            machine, repeat, repeat == 1 ? "" : "s",
            before_label ? before_label
            : before     ? before
                         : "(not run)",
            ref_blas ? ", \"ref. BLAS\" the same with the reference BLAS first on LD_LIBRARY_PATH" : "");
    fprintf(f,
            "| case | variant | solver | CPU s | ratio | peak MB | steps | rejected | rejected %% | Newton | numeric "
            "factorisations | reused solves | Krylov iterations |\n"
            "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int c = 0; c < N_CASES; ++c) {
      if (!use_case[c]) continue;
      double ref = NAN;
      for (int v = 0; v < N_VARIANTS && isnan(ref); ++v)
        if (use_var[v] && best[c][v].ok) ref = best[c][v].cpu;
      for (int v = 0; v < N_VARIANTS; ++v) {
        const result *r = &best[c][v];
        if (!use_var[v] || (cases[c].iterative_only && strcmp(variants[v].name, "petsc") != 0)) continue;
        if (!r->ok) {
          fprintf(f, "| %s | %s | | failed | | | | | | | | | |\n", cases[c].what, variants[v].name);
          continue;
        }
        long att = r->steps + r->rejected;
        fprintf(f, "| %s | %s | %s | %.2f | %.2f | %.0f | %ld | %ld | %.1f | %ld | %ld | %ld | %ld |\n", cases[c].what,
                variants[v].name, r->linear, r->cpu, ref / r->cpu, r->peak_mb, r->steps, r->rejected,
                att > 0 ? 100.0 * (double)r->rejected / (double)att : 0.0, r->newton, r->numeric, r->reused, r->krylov);
      }
    }
    fprintf(f,
            "\n\"ratio\" is the first variant's CPU time over the row's (how many times faster); \"peak MB\" the "
            "run's largest resident set (wait4's ru_maxrss). \"rejected %%\" "
            "is of all attempted steps. \"Newton\" counts the linear solves of the nonlinear iterations; "
            "\"reused solves\" those answered by FGMRES with an older factorisation (core/solve/linsolve.h).\n");
  }
  if (md) fclose(md);
  return failed ? 1 : 0;
}
