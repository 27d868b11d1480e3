/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What a model gives the time loops: one ops table (in the spirit of
 * SUNDIALS' ops tables and PETSc's XXXSetType: a NULL hook means the
 * default, usually "nothing to do"), and what a run reports.
 *
 * A model is one of two kinds, told by its setup (sl_model_info):
 *  - integrated by the loop (SL_INTEGRATE_BDF): the model's state is a
 *    vector the loop integrates with variable-step BDF1/BDF2 (core/time/bdf.h):
 *    the loop keeps the history, predicts, estimates the local error and
 *    adapts the step; the model solves one implicit step given the BDF
 *    coefficients (sl_step), and may advance a coupled part after the error
 *    test has passed (`complete`);
 *  - self-integrated (SL_INTEGRATE_FIXED): the model takes a whole implicit
 *    step of dt itself; the loop lands on output times, retries a failed step
 *    at a quarter of its length and grows it back.
 * Both get the same output and checkpoint timing, restart, progress,
 * interruption, the stop reason and the summary.
 *
 * Codes: step and complete return 0, SL_STEP_RETRY (> 0: retry smaller) or a
 * negative fatal code, -SL_EFAILED or -SL_EBADINPUT (stop; the run exits
 * with the code's absolute value). Every other hook returns 0 or an SL_E*
 * code. Out of memory is fatal, never a reason for a smaller step. */
#ifndef SLUICE_TIME_MODEL_H
#define SLUICE_TIME_MODEL_H

#include <signal.h>
#include <stdint.h>

#include "core/io/output.h"
#include "core/solve/linsolve.h"
#include "core/util/diag.h"

struct sl_scene;
struct sl_nl_report;
struct sl_run_result;

enum { SL_STEP_RETRY = 1 };

/* A step's code from a solve's: a failed solve is retried smaller (SL_EFAILED), anything else (bad input, out
 * of memory) stops the run. */
static inline int sl_step_code(int rc) { return rc == 0 ? 0 : rc == SL_EFAILED ? SL_STEP_RETRY : -rc; }
enum { SL_INTEGRATE_FIXED = 0, SL_INTEGRATE_BDF = 1 };

/* What a model's setup tells the loop. */
typedef struct sl_model_info {
  int integrator; /* SL_INTEGRATE_* */
  int32_t n;      /* BDF: the unknowns the loop integrates */
  int32_t n_err;  /* BDF: the leading entries the error estimate measures (the rest: algebraic) */
  double *u;      /* BDF: the model's state vector, holding the initial state (the loop writes into it) */
  int has_steady; /* the model has a steady solve ([time] scheme = steady) */
  int time_dependent_boundaries; /* BDF: the boundary values change with t (the model re-applies them per step) */
  const char *steady_text;       /* FIXED: the text after "steady at t = T " in the stop reason */
  const char *state_name;        /* BDF: what the measured entries are, for messages ("velocity") */
} sl_model_info;

/* One step from t over dt. With SL_INTEGRATE_BDF also the BDF step: du/dt
 * at t + dt is mass_coef u + history[], the initial guess u[] holds the
 * predictor on entry and the solution on return. */
typedef struct sl_step {
  double t, dt;
  double mass_coef;
  const double *history;
  const double *predictor;
  double *u;
  const double *dudt;  /* for `complete`: the BDF du/dt at t + dt */
  const double *state; /* BDF: the last accepted state (at t) */
  int writes;          /* the state after this step is written (an output time, the end, the step limit) */
  /* set by the step: an error of its own beside the BDF estimate, scaled as sl_bdf_error (the step is accepted when
     both are <= 1; 0: none). The split flow step's splitting error (core/models/navier_stokes/projection.h). */
  double error;
} sl_step;

/* The counts a model adds to the summary and the profile. */
typedef struct sl_model_stats {
  long matrix_assemblies, residual_assemblies; /* full (matrix and right-hand side) and right-hand-side-only */
  int used_picard;
  double assembly;          /* wall seconds in assembly */
  sl_linsolve_stats linear; /* the main linear solver's counts */
  int has_linear;
  double cpu_flow, cpu_coupled; /* CPU seconds in the main solves and in the coupled part (transport) */
  long roundoff_accepted;
  long solves_skipped; /* steps whose result was known without a solve */
  int converged;       /* steady: the (last) solve converged */
  double correction, residual0, residual;
  double term_scale;          /* the last solve's residual scale set by its terms (core/solve/newton.h) */
  int roundoff;               /* the last solve converged with its residual at the round-off of its terms */
  int estimated;              /* its correction is the estimate of the next one (core/solve/newton.h) */
  char coupling_summary[256]; /* the model's own one line, or "" */
  char linear_summary[256];
  char stop_reason[256]; /* a steady solve's: set by the model */
} sl_model_stats;

typedef struct sl_model_ops {
  /* Builds the model from the typed scene (the scene may be changed by a
   * continuation: it is the model's to vary). Allocates the state, sets the
   * initial state, checks what the schema cannot (nothing is written yet). */
  int (*setup)(void **self, struct sl_scene *sc, sl_model_info *info, sl_diag *d);
  /* One trial step (see the codes above); *iterations: its nonlinear iterations. */
  int (*step)(void *self, sl_step *s, int *iterations, sl_diag *d);
  /* BDF: after the error estimate accepted the step's u: the coupled part
   * (the mixture's transport). NULL: none. */
  int (*complete)(void *self, const sl_step *s, sl_diag *d);
  /* The trial becomes the state; *steady = 1 when the run has reached a
   * steady state (FIXED). NULL: nothing to do. */
  void (*accept)(void *self, const sl_step *s, int *steady);
  /* The steady solve (has_steady): u on entry the initial state, on return
   * the solution; *steps the solves taken, *iterations their nonlinear iterations. */
  int (*steady)(void *self, double *u, long *steps, long *iterations, sl_diag *d);
  /* The mesh as the model's fields live on it (once, after the output opens). */
  int (*write_mesh)(void *self, sl_output *out, sl_diag *d);
  /* The fields and scalars of the state at t (inside an output step; u: the
   * BDF state, NULL for FIXED). */
  int (*write)(void *self, sl_output *out, double t, const double *u, sl_diag *d);
  /* The model's arrays to checkpoint (besides the loop's): their count (at most max). NULL: none. */
  int (*checkpoint)(void *self, sl_checkpoint_array *a, int max);
  /* From a checkpoint, before the output opens: a checkpoint that does not
   * fit the scene is SL_EBADINPUT. NULL: nothing beyond the loop's state. */
  int (*restore)(void *self, const sl_checkpoint *ck, sl_diag *d);
  /* After the run (also a failed one): the model's counts and summary lines
   * (res: what the loop measured). */
  void (*stats)(void *self, const struct sl_run_result *res, sl_model_stats *st);
  void (*destroy)(void *self);
} sl_model_ops;

/* How a run is driven from outside. */
typedef struct sl_run_opts {
  const char *scene_path;     /* for the default output name */
  const char *output;         /* overrides [output] file; NULL: keep */
  const char *restart;        /* continue from this file's last checkpoint; NULL: start */
  const char *sluice_version; /* for provenance */
  /* Called after every accepted step (progress display); may be NULL. */
  void (*monitor)(void *user, double t, double dt, long step, int nonlinear_iterations);
  void *monitor_user;
  volatile sig_atomic_t *interrupt; /* set asynchronously (Ctrl-C, SIGTERM): stop after the step, save */
  /* Called at every nonlinear iteration (core/scene/scene.h's sl_nl_report); may be NULL. */
  void (*nonlinear)(void *user, const struct sl_nl_report *r);
  void *nonlinear_user;
  int overwrite; /* the output may replace files sluice did not write */
  int checking;  /* validation only (run --check): no time integration in set-up */
} sl_run_opts;

/* What a run did. */
typedef struct sl_run_result {
  long steps, rejected_steps, nonlinear_iterations;
  /* this run's rejections: the BDF estimate of the state, the model's estimate (sl_step error), the nonlinear
     solve failed, the coupled part (complete) failed */
  long rejected_by[4];
  double t_start, t_end, t_reached;
  double saved_time; /* the time of the last state written with its checkpoint (saved_time_valid) */
  int saved_time_valid;
  const char *step_limit; /* what limited the step most often (static string) or NULL */
  char output_path[4096];
  char stop_reason[256]; /* why the run ended, one line ("" when it failed: the error says why) */
  /* seconds: the solves (BDF: the linear solver's wall clock; FIXED: the
   * steps' CPU), the factorisations (BDF), output (wall); CPU of the set-up
   * and the output */
  double solve, factorisation, output, cpu_setup, cpu_output;
  long output_times, output_datasets;
  double output_bytes;
  /* of the values, what this rank wrote, in how many collective transfers (mpirun) */
  double output_bytes_rank, output_bytes_all;
  long output_collective;
  sl_model_stats model;
} sl_run_result;

#endif
