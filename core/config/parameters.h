/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A scene's named constants: the section
 *
 *   [parameters]
 *   Ro = 4.22e-4          ; Rossby number
 *   Re = 1.06             ; Reynolds number
 *   E  = Ro / Re          ; each value a constant expression of the ones above it
 *
 * makes Ro, Re and E usable in every real value, list of reals, expression
 * and closure parameter of the scene file (`[flow] rotation = 1/Ro`), so a
 * scene can be written in its nondimensional groups with the conversion to
 * dimensional values in the file itself. Names are identifiers that are not
 * built-in (pi, e, sin, ...) nor a scene variable (x, y, t, case); at most
 * SL_EXPR_MAX_CONSTANTS of them. `--set parameters.Re=2` changes one and
 * everything computed from it. */
#ifndef SLUICE_CONFIG_PARAMETERS_H
#define SLUICE_CONFIG_PARAMETERS_H

#include "core/config/expr.h"
#include "core/config/ini.h"

/* Reads [parameters] of ini (in file order, each value evaluated with the
 * ones before it) and keeps them in the ini, where the real getters and
 * sl_ini_constants find them. Called again it reads the section afresh.
 * Returns 0 or SL_EBADINPUT with file:line (a bad name, a repeated one, a
 * value that is not a finite constant expression). */
int sl_ini_parameters(sl_ini *ini, sl_diag *d);
/* The resolved parameters, or NULL before sl_ini_parameters or when none. */
const sl_expr_constants *sl_ini_constants(const sl_ini *ini);
void sl_ini_params_free(struct sl_ini_params *p);

#endif
