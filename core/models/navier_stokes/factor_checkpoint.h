/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A linear solver's kept factorisation in a checkpoint (sl_linsolve_history): a restart rebuilds it, so that a
 * run stopped anywhere (by max_steps as at an output) goes on bit for bit as the uninterrupted one. */
#ifndef SLUICE_MODELS_NAVIER_STOKES_FACTOR_CHECKPOINT_H
#define SLUICE_MODELS_NAVIER_STOKES_FACTOR_CHECKPOINT_H

#include "core/io/output.h"
#include "core/solve/linsolve.h"

/* The array `name` holding ls's factorisation in a[0] (1 returned), or, where a restart cannot rebuild it (no
 * max room, an iterative backend, a matrix divided among ranks), none (0 returned) and the factorisation
 * dropped, so that the run goes on afresh as its restart will. */
int sl_factor_checkpoint(sl_linsolve *ls, const char *name, sl_checkpoint_array *a, int max);
/* The array `name` of ck, when there is one, for ls's next factorisation (sl_linsolve_restore_history);
 * none: ls starts afresh (a checkpoint of an older build, or one that had nothing to keep). */
int sl_factor_restore(sl_linsolve *ls, const char *name, const sl_checkpoint *ck, sl_diag *d);

#endif
