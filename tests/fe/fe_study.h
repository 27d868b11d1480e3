/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Helpers shared by the fe verification studies: observed orders, error
 * quadrature degrees, a diffusion solve on a dof map. */
#ifndef SLUICE_TESTS_FE_STUDY_H
#define SLUICE_TESTS_FE_STUDY_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/assembly/operators.h"
#include "core/assembly/system.h"
#include "core/fe/field.h"
#include "core/solve/linsolve.h"

/* log2 of successive error ratios: the observed order per halving. */
static inline double observed_order(double coarse, double fine) { return log(coarse / fine) / log(2.0); }

/* A rule exact well beyond the discretisation, for error norms. */
static inline int error_quad_degree(sl_cell_type t, int order) { return t == SL_CELL_TRI3 ? 5 : 2 * order + 2; }

/* Assembles -div(k grad u) = f with u = g on the listed boundaries and
 * solves; x has dm->n_dofs entries. Returns 0 or the failing code. */
static inline int solve_diffusion(const sl_dofmap *dm, const sl_diffusion_opts *o, const char *const *boundaries,
                                  int n_boundaries, sl_exact_fn g, void *g_user, const char *solver, double *x,
                                  sl_diag *d) {
  sl_system s;
  sl_constraints bc;
  sl_linsolve *ls = NULL;
  int rc = sl_system_init(&s, dm->n_dofs, dm->mesh->n_cells, dm->dofs_per_cell, dm->cell_dofs, d);
  if (rc) return rc;
  if ((rc = sl_constraints_init(&bc, dm->n_dofs, d))) {
    sl_system_free(&s);
    return rc;
  }
  rc = sl_assemble_diffusion(&s, dm, o, d);
  for (int k = 0; k < n_boundaries && !rc; ++k)
    rc = sl_constraints_fix_boundary(&bc, dm, boundaries[k], 0, g, g_user, 0.0, d);
  if (!rc) rc = sl_constraints_apply(&bc, &s, 1, d);
  if (!rc) rc = sl_linsolve_create(&ls, solver, d);
  if (!rc) rc = sl_linsolve_solve(ls, &s.A, s.b, x, d);
  sl_linsolve_destroy(ls);
  sl_constraints_free(&bc);
  sl_system_free(&s);
  return rc;
}

#endif
