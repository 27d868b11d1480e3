/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The time loops that serve every model (core/time/model.h): the steady
 * solve, the adaptive BDF1/BDF2 loop and the fixed-step loop, with the same
 * output and checkpoint timing for all of them:
 *  - steps land exactly on the output times and the end (a step within 5 %
 *    of one is stretched to it);
 *  - the state is written with a checkpoint at t = 0, at every output time,
 *    at the end, at max_steps and at a steady state; a run that fails writes
 *    the last good state before it stops;
 *  - a restart continues from a checkpoint's state, time, step and history,
 *    bit for bit where the uninterrupted run would be;
 *  - an interrupt (Ctrl-C) stops after the current step and saves it.
 * The BDF loop adapts the step to the local error estimate (core/time/bdf.h)
 * within [dt_min, dt_max]; the fixed-step loop retries a failed step at a
 * quarter of its length and grows it back by doubling up to dt. */
#ifndef SLUICE_TIME_LOOP_H
#define SLUICE_TIME_LOOP_H

#include "core/time/bdf.h"
#include "core/time/model.h"
#include "core/time/time_config.h"

typedef struct sl_time_loop {
  const sl_model_info *info;
  const sl_time_config *tc;
  sl_bdf bdf;            /* BDF: the history (also the steady solve's one state) */
  sl_bdf_controller ctl; /* BDF: the adaptive step's controller */
  double t, h;
  long step, rejected;
  int restarted;
} sl_time_loop;

/* After the model's setup (info holds its initial state). */
int sl_time_loop_init(sl_time_loop *L, const sl_model_info *info, const sl_time_config *tc, sl_diag *d);
/* The loop's part of a checkpoint: time, step, the rejected count and the
 * BDF history; SL_EBADINPUT when it does not fit the model's state. */
int sl_time_loop_restore(sl_time_loop *L, const sl_checkpoint *ck, sl_diag *d);
/* Runs to the end (or the steady state, max_steps, an interrupt or a
 * failure), writing into out. 0, SL_EFAILED (the last good state written,
 * the message says where and why) or SL_EBADINPUT. */
int sl_time_loop_run(sl_time_loop *L, const sl_model_ops *ops, void *self, sl_output *out, const sl_run_opts *o,
                     sl_run_result *res, sl_diag *d);
void sl_time_loop_free(sl_time_loop *L);

/* The simulated span a scene's run covers (for the progress display). */
static inline void sl_time_span(const sl_time_config *tc, double *t0, double *t1) {
  *t0 = 0.0, *t1 = tc->scheme == SL_SCHEME_STEADY ? 0.0 : tc->end;
}

#endif
