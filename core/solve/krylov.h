/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Restarted flexible GMRES, FGMRES(m), right-preconditioned (Saad 1993,
 * SIAM J. Sci. Comput. 14(2):461-469; Saad 2003, Iterative Methods for
 * Sparse Linear Systems, 2nd ed., Algorithm 9.6).
 *
 * Right preconditioning minimises the true residual b - A x over the Krylov
 * space of A M^-1, so the stopping test is on the residual the caller sees;
 * the flexible form keeps the preconditioned vectors z_j = M^-1 v_j, so the
 * solution update needs no further preconditioner application, and M may
 * vary between iterations. Arnoldi by modified Gram-Schmidt, the small
 * least-squares problem by Givens rotations.
 *
 * The iteration stops when |b - A x|_2 <= rtol |b|_2 (the recurrence's
 * estimate, confirmed by a computed residual at the end), when it has used
 * max_iterations, or, with `predict`, as soon as the mean reduction per
 * iteration so far says the budget cannot reach the tolerance: a solve that
 * will fail stops early rather than at the end of its budget. */
#ifndef SLUICE_SOLVE_KRYLOV_H
#define SLUICE_SOLVE_KRYLOV_H

#include <stdint.h>

#include "core/util/diag.h"

/* y = op(x); x and y do not overlap. Returns 0 or an SL_E* code with d set. */
typedef int (*sl_krylov_apply_fn)(void *user, const double *x, double *y, sl_diag *d);

typedef struct sl_krylov_opts {
  double rtol;        /* relative to |b|_2; default 1e-10 */
  int restart;        /* Krylov space dimension m; default 30 (at most the workspace's) */
  int max_iterations; /* in all cycles; default 100 */
  int predict;        /* stop once the mean rate so far cannot reach rtol within max_iterations */
  /* converged when the cycle's residual estimate |g_j| reaches rtol |b| in the first cycle, without the product
   * that recomputes b - A x (the estimate is that residual's norm in exact arithmetic: Saad 2003, Iterative
   * Methods for Sparse Linear Systems, 2nd ed., Proposition 6.9 for GMRES, and for FGMRES with its kept Z,
   * section 9.4.1); result.residual is then the estimate */
  int trust_estimate;
} sl_krylov_opts;

typedef enum sl_krylov_status {
  SL_KRYLOV_CONVERGED = 0,
  SL_KRYLOV_MAX_ITERATIONS, /* the budget used without reaching rtol */
  SL_KRYLOV_STAGNATED,      /* stopped early: the rate cannot reach rtol in the budget (or no decrease at all) */
} sl_krylov_status;

typedef struct sl_krylov_result {
  sl_krylov_status status;
  int iterations; /* operator applications inside the Arnoldi process (= preconditioner applications) */
  int restarts;
  double residual0, residual; /* |b - A x0|_2 and the computed |b - A x|_2 at the end */
  double rate;                /* mean residual reduction per iteration, (residual / residual0)^(1/iterations) */
} sl_krylov_result;

/* Workspace for systems of n unknowns and spaces of dimension up to m. */
typedef struct sl_krylov {
  int32_t n;
  int m;
  double *V, *Z; /* (m + 1) x n and m x n */
  double *H;     /* (m + 1) x m, column-major */
  double *cs, *sn, *g, *y;
  double *r; /* n: the computed residual */
} sl_krylov;

int sl_krylov_init(sl_krylov *k, int32_t n, int m, sl_diag *d);
void sl_krylov_free(sl_krylov *k);

/* Solves A x = b with the preconditioner M (M(v) ~ A^-1 v; NULL: none)
 * from the initial guess in x. Returns 0 with res->status saying whether it
 * converged, or the first error of an operator (x is then unusable). */
int sl_fgmres(sl_krylov *k, sl_krylov_apply_fn A, void *A_user, sl_krylov_apply_fn M, void *M_user, const double *b,
              double *x, const sl_krylov_opts *opts, sl_krylov_result *res, sl_diag *d);

#endif
