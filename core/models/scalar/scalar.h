/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The scalar model: a passive scalar carried by a given velocity field,
 * diffusing, with a source, on the staggered finite-volume grid of a
 * rectangle (core/fv: its cells and the implicit cell-scalar solver):
 *
 *   dc/dt + div(u c) - div(D grad c) = S(x, y, t),
 *
 * u(x, y) and S given as expressions, D constant; backward Euler, upwind
 * convection (bounded, conservative), central diffusion. A boundary is a
 * wall (no flux), a given value (an expression of x, y, t, at the face), or
 * periodic with its opposite side. It is the smallest model on the shared
 * layers: its folder and one registry line give it the scene's validation,
 * the time loop, output, checkpoints and restart, progress and the profile. */
#ifndef SLUICE_MODELS_SCALAR_H
#define SLUICE_MODELS_SCALAR_H

#include "core/scene/schema.h"
#include "core/time/model.h"

extern const sl_schema sl_scalar_schema;
extern const sl_model_ops sl_scalar_ops;

#endif
