/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Newton's method with a backtracking line search and a Picard fallback,
 * over a problem given by one assembly callback.
 *
 * The callback assembles, at the iterate u, the right-hand side b = -R(u)
 * and (unless asked for the residual only) the matrix of the requested
 * linearisation, both with the constrained dofs already eliminated: the
 * iterate satisfies the Dirichlet values, so a constrained row holds the
 * identity and b = 0 there. The correction then solves A du = b.
 *
 * The iteration converges when the correction is small,
 *   max |du_i| <= rtol * max(max |u_i|, scale)   over i < n_check
 * (that last correction is applied; or the next correction, estimated as
 * c r / (1 - r) from the last one c and the residual's contraction r over a
 * full step, is) AND the residual at u is small against
 * the scale the solution's own terms set,
 *   |b|_2 <= rtol_residual * T,  T = |t|_2,  t_i = sum_j |A_ij u_j|
 * over the rows that are equations (not constrained): a residual small only
 * against the first residual (a large load not yet taken up by the pressure) is
 * not convergence. When the residual is at the round-off of those terms,
 * |b|_2 <= SL_NEWTON_ROUNDOFF T, and an iteration no longer reduces it (by
 * half), no iteration can improve it and the solve has converged at
 * round-off (stats.roundoff:
 * the correction then measures noise, e.g. a velocity of round-off size in
 * a vessel at rest). An absolute |b|_2 <= atol also ends it. Each trial step is accepted when the
 * residual norm falls (Armijo, sufficient decrease 1e-4 of the predicted
 * one); otherwise the step is halved, down to min_step. A Newton step that
 * finds no decrease switches to Picard iterations (robust, linearly
 * convergent) for picard_fallback iterations, then back to Newton.
 *
 * The corrections are solved to a relative residual linear_rtol, which lets
 * the linear solver answer with FGMRES preconditioned by an older
 * factorisation (see linsolve.h) instead of factorising every iteration.
 *
 * A linear problem (opts.linear) takes one solve, exact unless linear_rtol
 * is given; the residual it reports is b - A du, computed with the matrix
 * (no second assembly), so A must be the exact operator. A linear time step
 * (predicted) with a load_scale is not solved at all when the residual at u
 * is at the round-off of the terms it is the sum of: u is then as good as
 * a direct solve would give (load_scale below). When A already holds that
 * operator (opts.matrix_current: a constant-coefficient problem re-solved
 * with new data), only b is assembled and A is left untouched, so the
 * solver also keeps its factorisation.
 *
 * SLUICE_NEWTON_TRACE=1 in the environment prints each accepted iteration
 * (step length, correction, residual) on stderr. */
#ifndef SLUICE_SOLVE_NEWTON_H
#define SLUICE_SOLVE_NEWTON_H

#include <signal.h>

#include "core/solve/linsolve.h"
#include "core/solve/sparse.h"
#include "core/util/diag.h"

typedef enum sl_nl_mode { SL_NL_RESIDUAL = 0, SL_NL_NEWTON, SL_NL_PICARD } sl_nl_mode;

/* Assemble at u. A and b are zeroed before the call. */
typedef int (*sl_nl_assemble_fn)(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d);

typedef struct sl_newton_opts {
  double rtol;          /* on the correction; default 1e-8 */
  double atol;          /* on |b|_2; default 0 (unused) */
  double rtol_residual; /* the residual's tolerance against the terms' scale T; default max(rtol,
                           SL_NEWTON_RTOL_TERMS) */
  double scale;         /* floor of the solution scale in the correction test; default 1e-12 */
  int n_check;          /* entries entering the correction test; 0: all */
  int max_iterations;   /* default 30 */
  int picard_first;     /* Picard iterations before Newton (a far initial guess) */
  int picard_fallback;  /* default 5 */
  int picard_only;      /* never use Newton */
  int linear;           /* the problem is linear: one solve, then the residual b - A du is reported */
  int matrix_current;   /* with linear: A already holds the operator; assemble the residual only */
  double min_step;      /* smallest line-search factor; default 1/64 */
  /* A solve that starts from a good prediction (a time step from the BDF predictor): the estimate of the next
     correction may end it after its first iteration (otherwise after the second at the earliest, a far start's
     first contraction being no guide), and a full step's trial point is assembled residual only, its matrix
     only when one more iteration is needed (the test at the top of the next iteration then takes the terms'
     scale T with the matrix of the previous iterate). */
  int predicted;
  /* The relative residual a correction is solved to at the first iterate and after a shortened step, when
     larger than linear_rtol's (which the iterations after a full step keep): where the line search does not
     take the full step, the linear model is poor and more digits of its solution are wasted ("oversolving",
     Eisenstat & Walker 1996, SIAM J. Sci. Comput. 17:16). A correction with |F + J s| <= eta |F|, eta < 1, is
     still a descent direction of |F|: grad(|F|^2 / 2) . s = F . (F + J s) - |F|^2 <= (eta - 1) |F|^2
     (Eisenstat & Walker 1994, SIAM J. Optim. 4:393), so the backtracking stays globally convergent. It lets an
     older factorisation answer those solves by FGMRES. 0: off. */
  double damped_linear_rtol;
  double linear_rtol; /* each correction's relative residual |b - A du|_2 <= linear_rtol |b|_2, so that
                           the solver may reuse an older factorisation (sl_linsolve_solve_rtol); default
                           SL_NEWTON_LINEAR_RTOL (predicted: at least 1e-2 rtol); negative: direct solves. A
                           linear problem solves directly unless it is given (> 0). */
  /* A linear time step (linear and predicted): the 2-norm of the load's own terms before they cancel (a body
     force F over the domain: about F |Omega| / sqrt(n)). When |b|_2 <= SL_NEWTON_ROUNDOFF (T + load_scale), T the
     operator's terms at u (above), u's normwise backward error |b| / (|A| |u| + |f|) is at round-off (Rigal &
     Gaches 1967, J. ACM 14:543; Higham 2002, Accuracy and Stability of Numerical Algorithms, Thm 7.1), what a
     backward-stable direct solve leaves: u is the solution without a solve (a suspension at rest whose pressure
     carries its weight). The same level bounds a solve's tolerance from below. 0: no such test. */
  double load_scale;
  /* With load_scale: the residual at u is assembled alone first (T then left out of the test, the stricter), the
     matrix only when the test fails and a solve follows: for a step expected at rest (a velocity at round-off). */
  int residual_first;
  /* Called once per iteration before its correction is taken (--monitor): the iteration (from 1), whether
     it is a Picard one, its relative correction, the residual at u and the terms' scale. May be NULL. */
  void (*monitor)(void *user, int iteration, int picard, double correction, double residual, double terms);
  void *monitor_user;
  /* When set (asynchronously, a signal): stop before the next iteration with SL_EFAILED, u the last iterate
     (steady solves; a transient step finishes and the loop stops after it). NULL: none. */
  volatile sig_atomic_t *interrupt;
} sl_newton_opts;

/* The residual's default tolerance against the terms' scale (with rtol, the larger), and the level at which
 * it is at round-off: a sum of terms of size T is exact to a few ulps of T per term (Higham 2002, sec. 4.2),
 * and the assembly adds some tens of terms per entry. */
#define SL_NEWTON_RTOL_TERMS 1e-10
#define SL_NEWTON_ROUNDOFF (256.0 * 2.220446049250313e-16)

/* The default linear_rtol: far below any Newton tolerance, so that the
 * corrections are those of direct solves to every digit the convergence
 * test sees: with forcing term eta, the error of inexact Newton contracts
 * by about eta per iteration on top of Newton's quadratic term (Dembo,
 * Eisenstat & Steihaug 1982, SIAM J. Numer. Anal. 19:400). */
#define SL_NEWTON_LINEAR_RTOL 1e-10

enum { SL_NEWTON_HISTORY = 32 };

typedef struct sl_newton_stats {
  int iterations;        /* linear solves (0: a linear step whose residual was at round-off, solved by u) */
  int picard_iterations; /* of those, Picard */
  int assemblies;        /* full (matrix) assemblies */
  int residuals;         /* residual-only assemblies (line search, a reused matrix) */
  int backtracks;
  double residual0, residual; /* |b|_2 at the start and at the end */
  double correction;          /* the last relative correction */
  double term_scale;          /* T of the last iterate (see above) */
  int roundoff;               /* converged with the residual at the round-off of its terms */
  int estimated; /* correction is the estimate c r / (1 - r) of what is left (c the last one, r the residual's
                                 contraction), below the tolerance, and no further solve was made */
  double history[SL_NEWTON_HISTORY]; /* relative correction of each iteration */
  double t_assembly;                 /* wall seconds in the callback */
} sl_newton_stats;

/* Solves R(u) = 0 starting from u (overwritten with the solution). Returns 0,
 * SL_EFAILED when it does not converge (u then holds the last iterate and
 * the message says how far it got) or a code from the callback or solver. */
int sl_newton_solve(sl_csr *A, double *b, int32_t n, double *u, sl_nl_assemble_fn assemble, void *user, sl_linsolve *ls,
                    const sl_newton_opts *opts, sl_newton_stats *st, sl_diag *d);

#endif
