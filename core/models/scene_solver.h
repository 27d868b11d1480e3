/* The sparse direct solver of a scene, from its [solver] section:
 *   linear   = umfpack | klu | cholmod      (default: the model's)
 *   ordering = auto | amd | colamd | metis  (klu only; default: the model's)
 *   reuse    = auto | never                 (factorisation reuse in Newton's solves, see linsolve.h)
 * Errors name the file and line of the offending key. */
#ifndef SLUICE_MODELS_SCENE_SOLVER_H
#define SLUICE_MODELS_SCENE_SOLVER_H

#include "core/config/ini.h"
#include "core/solve/linsolve.h"

/* *name points into the scene (or is default_linear). default_ordering
 * applies when the solver is klu and the scene names no ordering. */
int sl_scene_linsolve(const sl_ini *ini, const char *default_linear, const char *default_ordering, sl_linsolve **ls,
                      const char **name, sl_diag *d);

#endif
