/* A fixed-step time loop for the implicit 1-D models: steps of [time] dt
 * that land exactly on the output times, a failed step retried at a
 * quarter of its length and grown back by doubling, output and checkpoint
 * at every output time, at a steady state, at the end and at max_steps,
 * and, when a run fails, the last good state saved before it stops.
 *
 *   [time]   end (required), dt (required), dt_min (default dt 1e-6),
 *            max_steps (this many steps of this run, then a checkpoint)
 *   [output] every (0: the start and the end only)
 *
 * The model supplies one trial step, its acceptance (which says whether
 * the state is steady), the writing of a state (fields and checkpoint) and
 * the restore from a checkpoint. */
#ifndef SLUICE_TIME_FIXED_STEP_H
#define SLUICE_TIME_FIXED_STEP_H

#include "core/config/ini.h"
#include "core/models/navier_stokes/navier_stokes.h"

typedef struct sl_fixed_step_model {
  void *user;
  /* A trial step from t over dt: 0, or SL_EFAILED with *fatal = 1 when a
   * smaller step cannot cure the failure (the step is then not retried). */
  int (*step)(void *user, double t, double dt, int *iterations, int *fatal, sl_diag *d);
  /* Makes the trial the state; *steady = 1 when the run has reached a
   * steady state. */
  void (*accept)(void *user, double dt, int *steady);
  /* Writes the state at t (output and checkpoint; dt_next and step go into
   * the checkpoint). */
  int (*write)(void *user, double t, double dt_next, long step, sl_diag *d);
  /* Reads the state, t, the next dt and the step count from a checkpoint. */
  int (*restore)(void *user, const char *path, double *t, double *dt, long *step, sl_diag *d);
  /* The text after "steady at t = T " in the stop reason, e.g. "(largest
   * dphi/dt below 1e-07 per s)". */
  const char *steady_text;
} sl_fixed_step_model;

/* Runs the loop; fills res's steps, rejected steps, nonlinear iterations,
 * times, solve seconds (the steps' CPU time), step limit and stop reason.
 * Returns 0, SL_EBADINPUT ([time] or [output]) or SL_EFAILED (the last good
 * state written, the message says where and why). */
int sl_fixed_step_run(const sl_ini *ini, const sl_fixed_step_model *m, const sl_ns_run_opts *o, sl_ns_result *res,
                      sl_diag *d);

#endif
