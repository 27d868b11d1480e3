/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The sparse direct solver of a scene: [solver] linear (auto: by the number
 * of unknowns and the BLAS, sl_linsolve_default_name), ordering (only for
 * klu; when the scene gives none, the model's default ordering) and reuse
 * (factorisation reuse in Newton's solves: auto | never). */
#ifndef SLUICE_SCENE_SOLVER_H
#define SLUICE_SCENE_SOLVER_H

#include "core/config/ini.h"
#include "core/scene/scene.h"
#include "core/solve/linsolve.h"

#define SL_SCENE_LINEAR_CHOICES "auto|umfpack|klu|cholmod|petsc"
#define SL_SCENE_REUSE_CHOICES "auto|never"
#define SL_SCENE_ORDERING_CHOICES "auto|amd|colamd|metis"

/* [solver.petsc]: PETSc options as keys without the leading dash (ksp_type = fgmres,
 * fieldsplit_u_pc_type = hypre); *options gets "-ksp_type fgmres ...", owned by the caller.
 * A scene file may come from someone else, so it may set only what configures a solve: keys of
 * the solver families (ksp_, pc_, fieldsplit_, sub_, mg_, mat_mumps_, mat_superlu_, mat_) with
 * values of letters, digits and "._+-/"; options that write files, print, or start programs
 * (view, monitor, log, file, debugger, ...) belong to --petsc or PETSC_OPTIONS. */
int sl_scene_petsc_section(const sl_ini_section *sec, char **options, sl_diag *d);

/* For a system of n unknowns; *name: the solver's name (static). */
int sl_scene_linsolve(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d);
/* The same for a matrix factorised once or twice a run and solved a few times (no refactorisations to reuse):
 * auto picks sl_linsolve_default_name_once. */
int sl_scene_linsolve_once(const sl_scene *sc, int32_t n, sl_linsolve **ls, const char **name, sl_diag *d);
/* The same for a matrix that is never symmetric positive definite (`why` says what it is): a solver that needs
 * one (cholmod) is bad input found at set-up, not a failure of every step retried down to dt_min. */
int sl_scene_linsolve_general(const sl_scene *sc, int32_t n, const char *why, sl_linsolve **ls, const char **name,
                              sl_diag *d);

#endif
