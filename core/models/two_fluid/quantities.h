/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The quantities the two-fluid model's closures are offered (the 2-D model,
 * two_fluid_plane_solids.c, and the shear layer, shear_layer.c), by input
 * name. The granular physics they compute with is shared with the other
 * models (core/models/granular.h). */
#ifndef SLUICE_MODELS_TWO_FLUID_QUANTITIES_H
#define SLUICE_MODELS_TWO_FLUID_QUANTITIES_H

#include "core/models/granular.h"

enum {
  TF_Q_PHI,
  TF_Q_SLIP,
  TF_Q_THETA,
  TF_Q_RHO_F,
  TF_Q_MU_F,
  TF_Q_RHO_S,
  TF_Q_D_P,
  TF_Q_SPHERICITY,
  TF_Q_GRAVITY,
  TF_Q_SLIP_WALL,
  TF_Q_WALL_DISTANCE,
  TF_Q_SHEAR_RATE,
  TF_Q_DENSITY,
  TF_Q_N
};
extern const char *const tf_quantity_names[TF_Q_N];

#endif
