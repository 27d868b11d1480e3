/*
 * sluice embedding API: open a scene (with overrides), check it, run it with
 * callbacks for progress, and read what the run did. The sluice command, the
 * scene tests and the benchmarks use this header; other programs can too
 * (link libsluice_core; `pkg-config --cflags --libs sluice`).
 *
 * SPDX-License-Identifier: GPL-2.0-or-later
 *
 *   sluice *s;
 *   sluice_error e;
 *   const char *sets[] = {"mesh.cells=32", NULL};
 *   sluice_open_opts oo = {.sets = sets};
 *   if (sluice_open("configs/cavity_re100.ini", &oo, &s, &e)) { fprintf(stderr, "%s\n", e.msg); return e.code; }
 *   sluice_summary sum;
 *   sluice_run_opts ro = {.output = "cavity.h5"};
 *   int rc = sluice_run(s, &ro, &sum, &e);  // 0, 1 (failed; the last good state saved), 2 (bad input)
 *   sluice_close(s);
 *
 * Every function that can fail returns 0 or the exit status a command would
 * have (SLUICE_FAILED 1: the run failed; SLUICE_BAD_INPUT 2: bad input, nothing
 * written) with the message in the error.
 */
#ifndef SLUICE_SLUICE_H
#define SLUICE_SLUICE_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { SLUICE_OK = 0, SLUICE_FAILED = 1, SLUICE_BAD_INPUT = 2 };

typedef struct sluice_error {
  int code;
  char msg[2048];
} sluice_error;

typedef struct sluice sluice; /* an opened scene */

/* This library's version: "0.1.0", with "+g<commit>" when built from git. */
const char *sluice_version(void);

typedef struct sluice_open_opts {
  const char *const *sets; /* "section.key=value" overrides, NULL-terminated (NULL: none) */
  /* Closure libraries: every one on the search path is loaded (scan_all), or only those that hold the closures
   * the scene names (the default). */
  int scan_all;
  int timing; /* time each closure call (what sluice run --profile reports) */
  /* PETSc options for [solver] linear = petsc ("-ksp_monitor -pc_type lu"), over the scene's [solver.petsc];
   * bad input when sluice was built without PETSc (NULL: none) */
  const char *petsc_options;
  /* The scene's [plugins] path names folders of libraries to load: refused (bad input, the key named) unless this
   * is set (sluice run --allow-plugin-path). */
  int allow_plugin_path;
  /* Each batched closure call is stopped after this many seconds (0: no limit), and the run fails naming it. */
  double closure_time_limit;
} sluice_open_opts;

/* The process's rank and the number of ranks it was launched with by mpirun (0 and 1 otherwise). With PETSc,
 * the ranks share the linear solves and every rank keeps the whole state; every rank runs the scene and the
 * ranks write its one output file together (parallel HDF5); rank 0 alone should print.
 * Starts MPI when launched by mpirun; call it before sluice_open. */
int sluice_ranks(int *rank, int *size, sluice_error *e);

/* Reads the scene file (its includes, the overrides) and finds its model:
 * an unreadable file, an unknown model or a bad override is bad input. */
int sluice_open(const char *path, const sluice_open_opts *o, sluice **s, sluice_error *e);
/* The same from text held in memory; `name` stands for the file in messages
 * and is the base of relative paths (includes, meshes). */
int sluice_open_text(const char *text, size_t len, const char *name, const sluice_open_opts *o, sluice **s,
                     sluice_error *e);
void sluice_close(sluice *s);

/* The scene's model, "two_fluid (motion = shear)". */
const char *sluice_model(const sluice *s);
/* The resolved configuration (includes flattened, overrides applied) as INI text. */
int sluice_write_config(const sluice *s, FILE *f, sluice_error *e);

/* Every check a run makes before it writes anything (the keys against the
 * model's schema, the closures created, the mesh built, the model set up),
 * without running. With report, a summary of the closures and the mesh.
 * The closures' code runs in the calling process: `sluice run --check` calls
 * this in a child process (docs/trust-plugins.md). */
int sluice_check(sluice *s, FILE *report, sluice_error *e);
/* The same with a restart's checkpoint read and checked against the scene (restart NULL: none). */
int sluice_check_restart(sluice *s, const char *restart, FILE *report, sluice_error *e);

/* The simulated time the run spans, for a progress display (after sluice_check or sluice_run). */
int sluice_time_span(sluice *s, double *t0, double *t1, sluice_error *e);

/* One nonlinear iteration: the time its step ends at (steady: 0), the continuation stage (0 of 0 without
 * one), the iteration (from 1), whether it is a Picard iteration, its relative correction, the residual at
 * its start and the scale the solution's own terms set for the residual. */
typedef struct sluice_nonlinear {
  double t;
  long stage, n_stages;
  int iteration, picard;
  double correction, residual, terms;
} sluice_nonlinear;

typedef struct sluice_run_opts {
  const char *scene_path; /* for the default output name (NULL: the opened file's) */
  const char *output;     /* overrides [output] file (NULL: keep) */
  const char *restart;    /* continue from this file's last checkpoint (NULL: start) */
  const char *version;    /* for provenance (NULL: this library's) */
  /* after every accepted step */
  void (*progress)(void *user, double t, double dt, long step, int nonlinear_iterations);
  void *progress_user;
  volatile sig_atomic_t *interrupt; /* set asynchronously: stop after the step and save */
  struct sluice_summary *live;      /* when not NULL: kept up to date before each progress call */
  /* at every nonlinear iteration (NULL: not called) */
  void (*nonlinear)(void *user, const struct sluice_nonlinear *r);
  void *nonlinear_user;
  int overwrite; /* the output may replace files sluice did not write (never the scene file itself) */
} sluice_run_opts;

/* Why a numeric factorisation was computed: sluice_refactor_reason_name(k) for k < SLUICE_REFACTOR_REASONS
 * ("first", "pattern", "direct", "forced", "iterations", "stagnation", "slow", "breakdown", "fresh"). */
#define SLUICE_REFACTOR_REASONS 9
const char *sluice_refactor_reason_name(int k);

typedef struct sluice_linear {
  long n_symbolic, n_numeric, n_refactor, n_refactor_redo, n_numeric_skipped, n_solves;
  double t_symbolic, t_numeric, t_solve; /* wall seconds */
  /* factorisation reuse: solves by FGMRES with an older factorisation, attempts that ended in a
   * refactorisation, their iterations, the most of one accepted reuse, wall seconds in FGMRES */
  long n_reused, n_krylov_failed, n_krylov_iterations;
  int krylov_max;
  double t_krylov;
  long refactor_reason[SLUICE_REFACTOR_REASONS]; /* numeric factorisations by reason; they sum to n_numeric */
} sluice_linear;

/* What a run did. */
typedef struct sluice_summary {
  long steps, rejected_steps, nonlinear_iterations;
  /* the rejections by reason: the BDF error estimate of the state, the model's own estimate (the splitting's),
     the nonlinear solve failed, the coupled part (the solids transport) failed; this run's, not a restart's */
  long rejected_by[4];
  double t_start, t_end, t_reached;
  double saved_time; /* the time of the last state saved with its checkpoint, when saved_time_valid */
  int saved_time_valid;
  const char *step_limit; /* what limited the step most often, or NULL */
  char output_path[4096];
  char stop_reason[256];      /* why the run ended ("" when it failed: the error says why) */
  char coupling_summary[256]; /* the model's own line, or "" */
  char linear_summary[256];
  long matrix_assemblies, residual_assemblies;
  int used_picard, converged;
  double correction, residual0, residual; /* steady: the last Newton solve */
  long roundoff_accepted;
  long solves_skipped; /* steps whose flow was known without a solve (at rest, or at a fixed point) */
  sluice_linear linear;
  /* seconds: assembly, factorisation, solve (wall), output; CPU of the phases */
  double assembly, factorisation, solve, output;
  double cpu_setup, cpu_flow, cpu_coupled, cpu_output;
  long output_times, output_datasets;
  double output_bytes;
  /* under mpirun every rank writes its block of the file's values: this
   * rank's bytes of them, and in how many collective transfers */
  double output_bytes_rank, output_bytes_all;
  long output_collective;
} sluice_summary;

/* Runs the scene. sum is filled in every case (a failed run's output_path
 * holds its last good state). */
int sluice_run(sluice *s, const sluice_run_opts *o, sluice_summary *sum, sluice_error *e);

/* What a run spent in the closures and which libraries it loaded, as the
 * lines `sluice run --profile` prints (each starting with prefix). */
void sluice_print_closure_profile(const sluice *s, FILE *f, const char *prefix, double cpu_total);

/* The closure libraries: how many the scene has loaded, how many files the
 * search path holds, how many times a library was opened. */
typedef struct sluice_plugins {
  int loaded, on_path;
  long dlopen;
} sluice_plugins;
void sluice_plugin_counts(const sluice *s, sluice_plugins *p);
/* The loaded libraries whose file name starts with prefix. */
int sluice_plugins_loaded(const sluice *s, const char *prefix);

/* What the runs so far did with closure kind/name: 0, or -1 when it was never created. */
typedef struct sluice_closure_use {
  long instances;
  unsigned long long calls, points;
  double seconds; /* inside the calls, when timed */
} sluice_closure_use;
int sluice_closure_usage(const sluice *s, const char *kind, const char *name, sluice_closure_use *u);
/* The closures the runs so far created: their number, and their uses summed into total. */
int sluice_closure_totals(const sluice *s, sluice_closure_use *total);

#ifdef __cplusplus
}
#endif

#endif
