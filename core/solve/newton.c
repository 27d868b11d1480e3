/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Newton with line search and Picard fallback (see newton.h). */
#include "core/solve/newton.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double wall(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Rows divided among ranks (A->rows): each rank's sum of squares over its own rows, the other rows being zero
 * here, added over the ranks in rank order, so that every rank gets the same norm and decides the same. */
static double across_ranks(const sl_csr *A, double sum_sq) {
  if (A->rows && sl_linsolve_sum_ordered(&sum_sq, 1, NULL)) return NAN;
  return sqrt(sum_sq);
}

static double norm2(const sl_csr *A, const double *x, int32_t n) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s += x[i] * x[i];
  return across_ranks(A, s);
}

static double norm_inf(const double *x, int32_t n) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s = fmax(s, fabs(x[i]));
  return s;
}

/* The scale the solution's own terms set for the residual: row by row the
 * magnitude of the operator's terms at u, t_i = sum_j |A_ij u_j|, over the
 * rows that are equations (a constrained row, the identity, is left out),
 * and T = |t|_2. A residual is small when it is small against T: a large
 * load the pressure absorbs makes T large only where the pressure gradient
 * is, and the velocity's terms keep their share of it. */
static double term_scale(const sl_csr *A, const double *u) {
  double s = 0.0;
  for (int32_t i = 0; i < A->n_rows; ++i) {
    double t = 0.0;
    int equation = 0;
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) {
      double a = A->values[p];
      if (A->col_idx[p] != i && a != 0.0) equation = 1;
      t += fabs(a * u[A->col_idx[p]]);
    }
    if (equation) s += t * t;
  }
  return across_ranks(A, s);
}

typedef struct nl_ctx {
  sl_csr *A;
  double *b;
  int32_t n;
  sl_nl_assemble_fn fn;
  void *user;
  sl_newton_stats *st;
} nl_ctx;

static int assemble(nl_ctx *c, const double *u, sl_nl_mode mode, sl_diag *d) {
  double t0 = wall();
  if (mode != SL_NL_RESIDUAL) sl_csr_zero(c->A);
  memset(c->b, 0, (size_t)c->n * sizeof *c->b);
  int rc = c->fn(c->user, u, mode, c->A, c->b, d);
  c->st->t_assembly += wall() - t0;
  if (mode == SL_NL_RESIDUAL) ++c->st->residuals;
  else ++c->st->assemblies;
  for (int32_t i = 0; i < c->n && !rc; ++i)
    if (!isfinite(c->b[i]))
      rc = sl_diag_set(d, SL_EFAILED, "nonlinear solve: the residual is not finite (entry %d)", (int)i);
  if (c->A->rows) { /* every rank goes on, or none */
    int all = sl_linsolve_agree(rc);
    if (all && !rc) rc = sl_diag_set(d, all, "nonlinear solve: the assembly failed on another rank");
  }
  return rc;
}

int sl_newton_solve(sl_csr *A, double *b, int32_t n, double *u, sl_nl_assemble_fn fn, void *user, sl_linsolve *ls,
                    const sl_newton_opts *opts, sl_newton_stats *st, sl_diag *d) {
  sl_newton_opts o = *opts;
  if (!(o.rtol > 0)) o.rtol = 1e-8;
  if (!(o.scale > 0)) o.scale = 1e-12;
  if (o.max_iterations <= 0) o.max_iterations = 30;
  if (o.picard_fallback <= 0) o.picard_fallback = 5;
  if (!(o.min_step > 0)) o.min_step = 1.0 / 64.0;
  /* A linear problem's one solve is exact (its residual b - A du is computed, not solved for), unless the caller
     asks for a tolerance: a linear time step's matrix that moves with the solution (the mixture's density and
     implicit buoyancy) leaves the kept factorisation no preconditioner (FGMRES stagnated in 77 of 79 steps of a
     moving Stokes mixture, docs/transient_cost.md), so the default stays direct. */
  double linear_rtol = o.linear_rtol < 0 || (o.linear && !(o.linear_rtol > 0)) ? 0.0
                       : o.linear_rtol > 0                                     ? o.linear_rtol
                                                                               : SL_NEWTON_LINEAR_RTOL;
  /* A time step's corrections from its predictor: to 1e-2 of the Newton tolerance (the residual's contraction,
     which the convergence estimate reads, then holds the linear solve's error too: Dembo, Eisenstat & Steihaug
     1982); fewer FGMRES iterations and refactorisations, the same steps */
  if (o.predicted && !o.linear && !(o.linear_rtol != 0.0)) linear_rtol = fmax(linear_rtol, 1e-2 * o.rtol);
  /* a linear step with a load scale: not solved when its residual is at round-off; with residual_first that
     residual is assembled alone, the matrix only when a solve follows */
  int floor_test = o.linear && o.predicted && o.load_scale > 0;
  int residual_first = floor_test && o.residual_first && !o.matrix_current;
  int32_t n_check = o.n_check > 0 && o.n_check <= n ? o.n_check : n;
  memset(st, 0, sizeof *st);
  nl_ctx c = {A, b, n, fn, user, st};

  double *du = malloc((size_t)n * sizeof *du), *trial = malloc((size_t)n * sizeof *trial);
  if (!du || !trial) {
    free(du), free(trial);
    return sl_diag_set(d, SL_ENOMEM, "nonlinear solve: out of memory for %d unknowns", (int)n);
  }
  int picard_left = o.picard_only ? o.max_iterations : o.picard_first;
  sl_nl_mode mode = picard_left > 0 ? SL_NL_PICARD : SL_NL_NEWTON;
  /* A linear operator already in A: b only, and A keeps its values generation (no refactorisation). */
  int rc = assemble(&c, u, o.linear && (o.matrix_current || residual_first) ? SL_NL_RESIDUAL : mode, d);
  double res = rc ? NAN : norm2(A, b, n);
  st->residual0 = st->residual = res;
  int converged = 0;
  double res_prev = INFINITY;
  int last_full = 0; /* the last iteration took its full step */
  /* predicted: u was assembled residual only; its matrix comes before the next solve */
  int need_matrix = residual_first;
  int first_estimate = o.predicted ? 1 : 2; /* the first iteration whose contraction may end the solve */
  double rtol_terms = o.rtol_residual > 0 ? o.rtol_residual : fmax(o.rtol, SL_NEWTON_RTOL_TERMS);
  while (!rc && !converged) {
    /* A is the matrix at u here (assembled with b, or current and b computed with it), or with need_matrix that
       of the previous iterate, which gives T as a scale all the same */
    /* (a linear step's residual assembled alone: A is not u's matrix, and its terms are left out of the round-off
       test, which is then the stricter) */
    double T = residual_first && need_matrix ? 0.0 : term_scale(A, u);
    st->term_scale = T;
    if (o.atol > 0 && res <= o.atol) {
      converged = 1;
      break;
    }
    /* a linear step whose residual at u is at the round-off of its terms: u's backward error is a direct
       solve's (load_scale in newton.h), and a solve would only add noise */
    double round_floor = floor_test ? SL_NEWTON_ROUNDOFF * (T + o.load_scale) : 0.0;
    if (floor_test && res <= round_floor) {
      if (getenv("SLUICE_NEWTON_TRACE"))
        fprintf(stderr, "  linear: residual %.3e at round-off (<= %.3e of the terms' scales %.3e + %.3e): not solved\n",
                res, round_floor, T, o.load_scale);
      converged = 1, st->roundoff = 1;
      break;
    }
    /* the correction the next iteration would make, from the last one and the residual's decrease (error
       and residual contract alike near the solution, Kelley 1995, Iterative Methods for Linear and Nonlinear
       Equations, ch. 5): below the tolerance at a residual small against its terms, the solve is done
       without one more solve to measure it */
    if (!o.linear && st->iterations >= first_estimate && last_full && res <= rtol_terms * T && res_prev > 0) {
      /* with a contraction r per iteration the error left after this iterate is the next correction summed
         over the rest, c r / (1 - r): for Newton r is tiny, for Picard it need not be */
      double r = res / res_prev, next = r < 1.0 ? st->correction * r / (1.0 - r) : INFINITY;
      if (next <= o.rtol) {
        st->correction = next, st->estimated = 1;
        converged = 1;
        break;
      }
    }
    /* the residual at the round-off of its own terms and no longer falling: no iteration can make it
       smaller, and the corrections are noise (a flow at rest whose pressure carries the load) */
    if (!o.linear && st->iterations > 1 && res > 0.5 * res_prev && res <= SL_NEWTON_ROUNDOFF * T) {
      converged = 1, st->roundoff = 1;
      break;
    }
    res_prev = res;
    if (st->iterations == o.max_iterations) break;
    if (need_matrix) { /* the matrix at u (b again, the same sum) */
      need_matrix = 0;
      if ((rc = assemble(&c, u, mode, d))) break;
      res = norm2(A, b, n);
      res_prev = res;
      if (floor_test)
        st->term_scale = term_scale(A, u), round_floor = SL_NEWTON_ROUNDOFF * (st->term_scale + o.load_scale);
    }
    if (o.interrupt && *o.interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "nonlinear solve: interrupted after %d iterations (residual %.3g from %.3g)",
                       st->iterations, res, st->residual0);
      break;
    }
    /* The same absolute accuracy for every correction, |b - A du| <= linear_rtol |b0| (at most 1e-4 of |b|):
       a later correction, of a residual already reduced, needs fewer digits of its own (the forcing term
       follows the residual's decrease, Eisenstat & Walker 1996, SIAM J. Sci. Comput. 17:16). */
    double eta = linear_rtol;
    if (eta > 0.0 && res > 0.0) eta = fmin(1e-4, fmax(linear_rtol, linear_rtol * st->residual0 / res));
    if (eta > 0.0 && !last_full && o.damped_linear_rtol > eta && o.damped_linear_rtol < 1.0)
      eta = o.damped_linear_rtol; /* the first iterate, or one a shortened step reached (newton.h) */
    /* no digit below the round-off of the terms (a linear step's floor): |b - A du| <= floor is a direct solve's */
    if (eta > 0.0 && round_floor > 0.0 && res > 0.0) eta = fmax(eta, fmin(1e-4, round_floor / res));
    if ((rc = sl_linsolve_solve_rtol(ls, A, b, du, eta, d))) break;
    ++st->iterations;
    if (mode == SL_NL_PICARD) ++st->picard_iterations;
    st->correction = norm_inf(du, n_check) / fmax(norm_inf(u, n_check), o.scale);
    if (st->iterations <= SL_NEWTON_HISTORY) st->history[st->iterations - 1] = st->correction;
    if (getenv("SLUICE_NEWTON_TRACE"))
      fprintf(stderr, "  %s %2d: correction %.3e, residual %.3e (%.3g of the terms' scale %.3e)\n",
              mode == SL_NL_PICARD ? "picard" : "newton", st->iterations, st->correction, res, T > 0 ? res / T : 0.0,
              T);
    if (o.monitor) o.monitor(o.monitor_user, st->iterations, mode == SL_NL_PICARD, st->correction, res, T);
    if (o.linear || (st->correction <= o.rtol && res <= rtol_terms * T)) {
      /* Linear, or a correction at the tolerance at a residual small
       * against its terms: take it and stop (a line search at round-off
       * level would only see noise). A small correction at a residual that
       * is not small (a load the pressure has not yet taken up) goes on. */
      for (int32_t i = 0; i < n; ++i) u[i] += du[i];
      if (o.linear) {
        /* R is affine, so -R(u + du) = b - A du: no second assembly. */
        sl_csr_matvec_add(A, -1.0, du, 1.0, b);
        st->residual = norm2(A, b, n);
      }
      converged = 1;
      break;
    }
    /* Line search: the full step first, assembled completely so that an
     * accepted full step needs no second assembly. */
    double lambda = 1.0, trial_res = INFINITY;
    sl_nl_mode next = mode;
    if (mode == SL_NL_PICARD && --picard_left <= 0 && !o.picard_only) next = SL_NL_NEWTON;
    int accepted = 0, full = 1;
    for (;;) {
      for (int32_t i = 0; i < n; ++i) trial[i] = u[i] + lambda * du[i];
      if ((rc = assemble(&c, trial, full && !o.predicted ? next : SL_NL_RESIDUAL, d))) {
        /* A closure outside its range at the trial point: shorten the step. */
        if (rc != SL_EFAILED || lambda * 0.5 < o.min_step) break;
        rc = 0;
        trial_res = INFINITY;
      } else {
        trial_res = norm2(A, b, n);
      }
      /* A Picard step is a fixed-point step: accept it unless it blows up. */
      if (trial_res <= (1.0 - 1e-4 * lambda) * res || (mode == SL_NL_PICARD && trial_res <= 10.0 * res)) {
        accepted = 1;
        break;
      }
      if (lambda * 0.5 < o.min_step) break;
      lambda *= 0.5, full = 0;
      ++st->backtracks;
    }
    if (rc) break;
    if (!accepted) {
      if (st->iterations > 1 && res <= SL_NEWTON_ROUNDOFF * T) {
        /* no decrease from a residual already at the round-off of its terms: u is the solution */
        if ((!full || o.predicted) && (rc = assemble(&c, u, mode, d))) break;
        converged = 1, st->roundoff = 1;
        break;
      }
      if (mode == SL_NL_NEWTON && !o.picard_only) {
        /* No decrease along the Newton direction: fall back to Picard at u. */
        mode = SL_NL_PICARD, picard_left = o.picard_fallback;
        rc = assemble(&c, u, mode, d);
        continue;
      }
      rc = sl_diag_set(d, SL_EFAILED,
                       "nonlinear solve: no decrease of the residual along the %s step (residual %.3g, started at "
                       "%.3g, %d iterations)",
                       mode == SL_NL_PICARD ? "Picard" : "Newton", res, st->residual0, st->iterations);
      break;
    }
    memcpy(u, trial, (size_t)n * sizeof *u);
    last_full = lambda == 1.0;
    if (getenv("SLUICE_NEWTON_TRACE")) fprintf(stderr, "      step %.3g, residual -> %.3e\n", lambda, trial_res);
    res = trial_res;
    st->residual = res;
    if (!full) rc = assemble(&c, u, next, d); /* the matrix at the accepted point */
    else if (o.predicted) need_matrix = 1;    /* ... when the next iteration needs it */
    mode = next;
  }
  free(du), free(trial);
  if (rc) return rc;
  if (!converged)
    return sl_diag_set(d, SL_EFAILED,
                       "nonlinear solve: not converged in %d iterations (relative correction %.3g, tolerance %.3g; "
                       "residual %.3g from %.3g, %.3g of its terms' scale, tolerance %.3g)",
                       st->iterations, st->correction, o.rtol, res, st->residual0,
                       st->term_scale > 0 ? res / st->term_scale : 0.0, rtol_terms);
  return 0;
}
