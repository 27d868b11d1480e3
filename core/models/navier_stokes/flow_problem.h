/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A discrete incompressible-flow problem ready for the nonlinear solver:
 * the Taylor–Hood space, its system, the Dirichlet constraints and the flow
 * operator's options, with the assembly callback of core/solve/newton.h.
 *
 *   sl_flow_problem_init(&p, th, d);
 *   sl_constraints_fix_boundary(&p.bc, ...); ...   (velocity values)
 *   p.opts = ...;                                   (physics)
 *   sl_flow_problem_solve(&p, u, ls, &newton_opts, &stats, d);
 *
 * Constrained dofs hold their prescribed values in the iterate; their rows
 * become identity rows with a zero right-hand side, so corrections vanish
 * there.
 *
 * A problem whose matrix does not depend on the iterate (no convection, no
 * viscosity or density callback) keeps its assembled matrix between solves:
 * while the matrix inputs (mass coefficient, density, viscosity, rotation,
 * geometry, quadrature, the set of constrained dofs) stay the same and
 * nothing else wrote to sys.A, a linear solve (newton opts.linear) assembles
 * the right-hand side only, and the linear solver keeps its factorisation.
 * Time-dependent data (history, body force, tractions, constraint values)
 * enter the right-hand side alone. */
#ifndef SLUICE_MODELS_FLOW_PROBLEM_H
#define SLUICE_MODELS_FLOW_PROBLEM_H

#include "core/assembly/flow.h"
#include "core/assembly/slip.h"
#include "core/assembly/system.h"
#include "core/solve/newton.h"

enum { SL_FLOW_MAX_TRACTIONS = 16 };

typedef struct sl_flow_traction {
  const char *boundary; /* borrowed */
  sl_qp_fn fn;
  void *user;
} sl_flow_traction;

typedef struct sl_flow_problem {
  const sl_th_space *th; /* not owned */
  sl_system sys;
  sl_constraints bc;
  sl_flow_opts opts;
  int n_tractions; /* prescribed tractions (sl_assemble_flow_traction) */
  sl_flow_traction traction[SL_FLOW_MAX_TRACTIONS];
  /* Free-slip nodes on curved walls (slip.h), rotated after the constraints: their rows become n . du = 0 and
   * the tangential momentum, and the iterate keeps u . n = 0. NULL: none (the straight slip walls are
   * constraints). Not owned. */
  const sl_slip *slip;
  int32_t n_fixed; /* the constrained dofs, collected at solve time */
  int32_t *fixed;
  /* What the matrix in sys.A was assembled from, when it does not depend on
   * the iterate (valid != 0); see sl_flow_problem_solve. */
  struct sl_flow_matrix_key {
    int valid;
    uint64_t pattern_id, values_gen; /* sys.A as left by that assembly */
    double mass_coef, density, viscosity, omega;
    int axisymmetric, quad_degree;
  } matrix;
} sl_flow_problem;

int sl_flow_problem_init(sl_flow_problem *p, const sl_th_space *th, sl_diag *d);
void sl_flow_problem_free(sl_flow_problem *p);

/* The sl_nl_assemble_fn of the problem (user = the problem). */
int sl_flow_problem_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d);

/* Imposes the constraint values on u, then solves with Newton/Picard. The
 * correction test runs over the velocity dofs. With o->linear and the
 * matrix of the previous solve still current (see above), only the
 * right-hand side is assembled (st->assemblies == 0); the problem sets
 * o->matrix_current itself. */
int sl_flow_problem_solve(sl_flow_problem *p, double *u, sl_linsolve *ls, const sl_newton_opts *o, sl_newton_stats *st,
                          sl_diag *d);

/* Imposes the constraint values on u, then assembles the momentum equations alone at u into vs, a system of
 * the velocity dofs (sl_flow_opts.velocity_block; a split step's linearisation, projection.h): Newton's
 * velocity block and the momentum rows of b = -R(u), the constrained velocity rows identity rows with b = 0;
 * the velocity rows and columns of the monolithic Newton system, without its continuity rows and pressure
 * columns. p->sys is not touched. */
int sl_flow_problem_linearise_velocity(sl_flow_problem *p, double *u, sl_system *vs, sl_diag *d);

#endif
