/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The navier_stokes model: a scene's incompressible, generalized-Newtonian
 * flow (core/models/navier_stokes/flow.h), steady (with continuation) or
 * transient (adaptive BDF1/BDF2). */
#ifndef SLUICE_MODELS_NAVIER_STOKES_H
#define SLUICE_MODELS_NAVIER_STOKES_H

#include "core/scene/schema.h"
#include "core/time/model.h"

extern const sl_schema sl_navier_stokes_schema;
extern const sl_model_ops sl_navier_stokes_ops;

#endif
