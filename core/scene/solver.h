/* The sparse direct solver of a scene: [solver] linear and ordering (the
 * ordering only for klu; when the scene gives none, the model's default
 * ordering). */
#ifndef SLUICE_SCENE_SOLVER_H
#define SLUICE_SCENE_SOLVER_H

#include "core/scene/scene.h"
#include "core/solve/linsolve.h"

#define SL_SCENE_LINEAR_CHOICES "umfpack|klu|cholmod"
#define SL_SCENE_ORDERING_CHOICES "auto|amd|colamd|metis"

/* *name: the solver's name (static). */
int sl_scene_linsolve(const sl_scene *sc, sl_linsolve **ls, const char **name, sl_diag *d);

#endif
