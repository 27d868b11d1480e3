/* The sparse direct solver of a scene: [solver] linear (auto: by the number
 * of unknowns and the BLAS, sl_linsolve_default_name), ordering (only for
 * klu; when the scene gives none, the model's default ordering) and reuse
 * (factorisation reuse in Newton's solves: auto | never). */
#ifndef SLUICE_SCENE_SOLVER_H
#define SLUICE_SCENE_SOLVER_H

#include "core/scene/scene.h"
#include "core/solve/linsolve.h"

#define SL_SCENE_LINEAR_CHOICES "auto|umfpack|klu|cholmod|petsc"
#define SL_SCENE_REUSE_CHOICES "auto|never"
#define SL_SCENE_ORDERING_CHOICES "auto|amd|colamd|metis"

/* For a system of n unknowns; *name: the solver's name (static). */
int sl_scene_linsolve(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d);
/* The same for a matrix that is never symmetric positive definite (`why` says what it is): a solver that needs
 * one (cholmod) is bad input found at set-up, not a failure of every step retried down to dt_min. */
int sl_scene_linsolve_general(const sl_scene *sc, int32_t n, const char *why, sl_linsolve **ls, const char **name,
                              sl_diag *d);

#endif
