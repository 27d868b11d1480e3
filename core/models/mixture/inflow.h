/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids fraction of what flows into a mixture scene: the exterior
 * states of the transport's open boundaries from [boundary.N] phi, an
 * expression of x, y and t evaluated at each face point. A constant is one
 * value for the boundary; a profile along it (Nigam 1999 eq 4.148: particles
 * only in part of the channel's entrance) gives every face its own; one of
 * t is evaluated again at the end of every step.
 *
 * Which boundaries let solids through: those where the flow's velocity is
 * free (open, pressure, traction), and velocity boundaries that give phi
 * (an inlet or an outlet with a prescribed velocity: phi = 0 for an outlet,
 * where it is not used). Other velocity boundaries are walls for the
 * solids, whatever their velocity (a moving wall; a rigid lid carrying a
 * wave's orbital velocity, configs/wave_bed.ini). On an open boundary the
 * solids flux is the Godunov flux of q phi + w F(phi) between the boundary
 * cell and the exterior state: the exterior state enters where the flow
 * comes in, the cell's own leaves where it goes out. */
#ifndef SLUICE_MODELS_MIXTURE_INFLOW_H
#define SLUICE_MODELS_MIXTURE_INFLOW_H

#include "core/io/output.h"
#include "core/scene/scene.h"
#include "core/transport/transport.h"

typedef struct sl_mixture_inflow sl_mixture_inflow;

/* Sets the transport's boundaries from the scene: open[b] != 0 for the
 * flow's free boundaries (sl_flow_open). On success *out (NULL when no
 * boundary lets solids through) is updated by sl_mixture_inflow_update. SL_EBADINPUT: a value outside [0, phi_max],
 * with the scene's file:line and the point. */
int sl_mixture_inflow_create(const sl_scene *sc, sl_transport *tr, const unsigned char *open, double phi_max,
                             sl_mixture_inflow **out, sl_diag *d);
/* The exterior states of the boundaries whose phi depends on t, at time t. */
int sl_mixture_inflow_update(sl_mixture_inflow *in, double t, sl_diag *d);
/* The solids through each open boundary: after a successful transport step
 * (its trial amounts), when the step is accepted (added up), and written
 * with an output as solids_through_NAME, the solids volume that entered
 * through boundary NAME since the run started (negative: it left; int r dA
 * per radian when axisymmetric), from the transport's own Godunov fluxes,
 * so that the inventory's change is their sum; checkpointed. */
void sl_mixture_inflow_stepped(sl_mixture_inflow *in);
void sl_mixture_inflow_accept(sl_mixture_inflow *in);
int sl_mixture_inflow_write(const sl_mixture_inflow *in, sl_output *out, int axisymmetric, sl_diag *d);
/* The sums as a checkpoint array "solids_through" into a[0] (max > 0; returns 1, or 0 when none), and back
 * from it (NULL or of another size: a checkpoint without it, counted from 0). */
int sl_mixture_inflow_checkpoint(sl_mixture_inflow *in, sl_checkpoint_array *a, int max);
void sl_mixture_inflow_restore(sl_mixture_inflow *in, const sl_checkpoint_array *a);
void sl_mixture_inflow_destroy(sl_mixture_inflow *in);

#endif
