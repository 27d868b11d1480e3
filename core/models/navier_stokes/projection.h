/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The split (pressure-correction) time step of the flow, [flow] scheme = projection: the incremental
 * rotational projection method of Guermond, Minev & Shen (2006, Comput. Methods Appl. Mech. Engrg. 195:6011,
 * section 3.4, the form in the intermediate velocity alone, eqs 3.14-3.16), with the variable-density
 * pressure Poisson equation of Guermond & Salgado (2009, J. Comput. Phys. 228:2834, eqs 3.4-3.6): its
 * operator has the constant coefficient 1/chi, chi = rho_min (the smallest density the flow can take), so
 * that it is assembled and factorised once per run.
 *
 * A BDF step of size h (du/dt ~ m u^{k+1} + history, core/time/bdf.h) from the state (u^k, p^k):
 *  1. the velocity: rho (m u + history) + the momentum terms + grad p# = f at t^{k+1}, the velocity's
 *     boundary conditions, with the pressure predicted
 *        p# = p^k - sum_j c_j phi^{k-j} / m_{k-j}
 *     where history = sum_j c_j u^{k-j} (c_0 = a1 / h, c_1 = a2 / h of the variable-step BDF2; constant
 *     steps give p^k + 4/3 phi^k - 1/3 phi^{k-1}, eq 3.14). This is the history of the projected velocity
 *     u^m = u~^m - grad(phi^m) / (chi m_m) written with the intermediate velocities u~ the state keeps. The
 *     momentum is linearised once about the BDF predictor (Newton's Jacobian: one correction, the error of
 *     the predictor squared) and solved for the velocity alone;
 *  2. the pressure increment: int grad(phi).grad(q) = -chi m int q div u~ (Neumann; phi = 0 on open,
 *     pressure and traction boundaries; with closed boundaries, at the pressure datum);
 *  3. the pressure: p^{k+1} = p^k + phi - mu div u~ (the rotational correction, eq 3.16; div u~ as its
 *     lumped L2 projection onto the pressure space). With a viscosity closure mu varies and the correction
 *     is left out (the standard incremental form, Guermond & Salgado 2009), whose pressure is first order.
 * Expected orders in time (GMS 2006, Theorem 3.1 and section 3.4): velocity 2 in L2, pressure 3/2.
 *
 * The velocity's matrix F is the velocity block of the monolithic Jacobian, assembled alone with the momentum
 * residual (sl_flow_problem_linearise_velocity: no continuity rows, no pressure columns), solved by FGMRES
 * preconditioned with the LU factors of its diagonal blocks (one per component; the couplings between components, the
 * viscous cross terms, convection's Jacobian, the swirl's and the buoyancy's, are left to the Krylov
 * iteration) from an earlier step, refactorised when a solve becomes slow; the Poisson matrix is factorised
 * at the first step and kept.
 *
 * In a rotating frame (sl_flow_opts.omega) the correction step keeps the Coriolis force: chi (m I + C) delta =
 * -grad(phi), an anisotropic Poisson operator int grad(q).(m D) grad(phi), D = (m I + C)^{-1}, refactorised when
 * m changes; the predictor divides by the symmetric part of D, and the kept velocity takes delta's rotated
 * (divergence-free) part, the geostrophic adjustment to the new pressure (projection.c, correction_tensor and
 * rotation_correction). The preconditioner is then F itself (the Coriolis couplings are as strong as the
 * diagonal). */
#ifndef SLUICE_MODELS_NAVIER_STOKES_PROJECTION_H
#define SLUICE_MODELS_NAVIER_STOKES_PROJECTION_H

#include "core/models/navier_stokes/flow_problem.h"
#include "core/solve/linsolve.h"
#include "core/time/model.h"

typedef struct sl_projection sl_projection;

/* The velocity solve's FGMRES budget, and the iterations after which its preconditioner is refactorised. */
enum { SL_PROJECTION_KRYLOV_BUDGET = 30, SL_PROJECTION_SLOW = 10 };
/* The loosest relative residual of the velocity solve (projection.c velocity_solve): two digits of the correction
 * at least. */
#define SL_PROJECTION_RTOL_MAX 1e-2

typedef struct sl_projection_opts {
  double chi;                /* rho_min > 0: the Poisson equation's density */
  double mu_rotational;      /* the viscosity of the rotational correction; 0: the standard incremental form */
  const unsigned char *open; /* [mesh boundaries]: phi = 0 there (open, pressure, traction) */
  int datum;                 /* no open boundary: phi = 0 at the pressure datum (pressure dof 0) */
  /* The velocity block and the Poisson operator assembled by rank `rank` of `ranks` on its own cells and
   * solved by the (iterative, PETSc) velocity and Poisson solvers on their rows; F's diagonal blocks are not
   * used (preconditioner_solver may be NULL). 0: each assembled whole, F by FGMRES with its diagonal blocks. */
  int distributed, rank, ranks;
  /* The viscosity does not change with the shear rate (no closure, or one without d mu / d gamma): the
   * axisymmetric velocity block with swirl then has no (z, theta) block (sl_projection_create). */
  int shear_free;
  /* the projection's from sl_projection_create on, even on failure: F directly (a fallback), the Poisson
   * matrix, F's diagonal blocks (the preconditioner) */
  sl_linsolve *velocity_solver, *poisson_solver, *preconditioner_solver;
} sl_projection_opts;

int sl_projection_create(const sl_flow_problem *prob, const sl_projection_opts *o, sl_projection **out, sl_diag *d);
void sl_projection_destroy(sl_projection *pj);

/* One trial step: u holds the predictor's velocity on entry and (u~^{k+1}, p^{k+1}) on return; state the
 * accepted (u~^k, p^k). linear_rtol: the velocity solve's accuracy, the relative correction of Newton's test
 * (velocity_solve). The problem's options (mass
 * coefficient, history) are the step's; its constraints at t + h. */
int sl_projection_step(sl_projection *pj, sl_flow_problem *prob, const sl_step *s, double *u, double linear_rtol,
                       double *t_assembly, sl_diag *d);
/* Whether the next step needs a consistent pressure first: the run's first step, or the first after a skipped
 * one (no increments in hand). GMS 2006 (section 3.1) start the scheme from the exact initial pressure; here
 * that step is solved monolithic, and sl_projection_started records it as a step with a zero increment. */
int sl_projection_needs_start(const sl_projection *pj);
void sl_projection_started(sl_projection *pj, double mass_coef);
/* The step whose trial was the last sl_projection_step (or none: a step skipped, at rest) was accepted. */
void sl_projection_accept(sl_projection *pj);
/* The next trial is a skipped step (its increment zero). */
void sl_projection_skip(sl_projection *pj);
/* The increment history, the preconditioner's values and the kept factorisations to checkpoint (4-6 arrays)
 * and back, so that a restart goes on as the uninterrupted run; a checkpoint without them (a monolithic run's)
 * starts the split step afresh (its first step monolithic). */
/* The last sl_projection_step's splitting perturbation of the velocity, root mean square over the domain:
 * |grad phi| / (chi m), what the projection would remove from the intermediate velocity it keeps. */
double sl_projection_split_rms(const sl_projection *pj);
int sl_projection_checkpoint(sl_projection *pj, sl_checkpoint_array *a, int max);
int sl_projection_restore(sl_projection *pj, const sl_checkpoint *ck, sl_diag *d);

const sl_linsolve *sl_projection_velocity_solver(const sl_projection *pj);
/* "projection (velocity: ..., pressure Poisson: 1 factorisation, N solves)" */
void sl_projection_summary(const sl_projection *pj, char *buf, size_t cap);

#endif
