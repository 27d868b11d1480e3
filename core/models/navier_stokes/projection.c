/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The projection step of the flow (projection.h). */
#include "core/models/navier_stokes/projection.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/assembly/operators.h"
#include "core/models/navier_stokes/factor_checkpoint.h"
#include "core/solve/krylov.h"

static double wall(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

struct sl_projection {
  const sl_th_space *th;
  sl_projection_opts o;
  int32_t nv, np;
  /* the velocity block of the monolithic matrix and the momentum residual, assembled alone
   * (sl_flow_problem_linearise_velocity) */
  sl_system vsys;
  int32_t *vel_cell_dofs;
  sl_linsolve *ls_v; /* F directly: the fallback */
  /* The preconditioner of F: its diagonal blocks, one per velocity component (the couplings between components
   * dropped), factorised when a solve becomes slow and kept meanwhile (P's values are F's of that step). */
  sl_csr P;
  int32_t *comp_dofs, *pmap; /* the per-component element dofs; [P.nnz] indices into F's values */
  sl_linsolve *ls_P;
  sl_krylov kry;
  int refresh; /* copy F into P (and so refactorise) at the next solve */
  long krylov_solves, krylov_iterations, refreshes, direct_solves;
  /* the divergence: B = -int q div(v) (pressure rows, velocity columns), and the lumped pressure mass */
  sl_csr B;
  double *mass;
  /* the Poisson operator, constrained, factorised once */
  sl_system psys;
  sl_constraints pbc;
  int32_t n_pfixed, *pfixed;
  sl_linsolve *ls_p;
  long poisson_solves;
  double volume; /* sum of the lumped pressure mass: the domain's area (volume per radian) */
  double split_rms;
  double dnorm; /* |x|_2 of the last velocity correction */
  double h_now, h_last; /* the step being solved; the step of the last velocity correction (x), 0: none */
  /* The frame's rotation (flow.h omega): the correction step keeps the Coriolis force, so that its Poisson
   * operator depends on the step's mass coefficient (assembled for m_poisson) and the kept velocity takes the
   * correction's rotated part (rotation_correction). */
  double omega;
  int axi;
  double m_poisson;
  double *grad, *vmass; /* [nv]: B^T phi; [velocity nodes]: the lumped velocity mass int N_a */
  /* the increments of the last two accepted steps and their mass coefficients; the trial's */
  int n_hist;
  double m_hist[2];
  double *phi_hist[2];
  double *phi_trial, m_trial;
  int trial; /* 1: a solved trial, 0: skipped, -1: none */
  double *rhs, *x, *div;
  double head[6]; /* the checkpoint's [n_hist, m^k, m^{k-1}, refresh, dnorm, h_last] */
};

/* B = -int q div(v): the continuity rows of a Stokes assembly (they depend on the geometry alone). */
static int build_divergence(sl_projection *pj, const sl_flow_problem *prob, sl_diag *d) {
  const sl_th_space *th = pj->th;
  sl_system s;
  int rc = sl_system_init(&s, th->n_dofs, th->mesh->n_cells, th->dofs_per_cell, th->cell_dofs, d);
  if (rc) return rc;
  sl_flow_opts o = {.axisymmetric = prob->opts.axisymmetric,
                    .density = {NULL, NULL, 1.0},
                    .viscosity_value = 1.0,
                    .quad_degree = prob->opts.quad_degree};
  double *zero = calloc((size_t)th->n_dofs, sizeof *zero);
  if (!zero) rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  if (!rc) rc = sl_assemble_flow(&s, th, zero, &o, SL_FLOW_NEWTON, d);
  if (!rc) rc = sl_system_complete(&s, 1, d);
  free(zero);
  int32_t nv = pj->nv, np = pj->np, nnz = 0;
  const sl_csr *A = &s.A;
  if (!rc) {
    for (int32_t i = 0; i < np; ++i)
      for (int32_t k = A->row_ptr[nv + i]; k < A->row_ptr[nv + i + 1]; ++k) nnz += A->col_idx[k] < nv;
    pj->B.n_rows = np, pj->B.n_cols = nv, pj->B.nnz = nnz;
    pj->B.row_ptr = malloc((size_t)(np + 1) * sizeof *pj->B.row_ptr);
    pj->B.col_idx = malloc((size_t)(nnz + 1) * sizeof *pj->B.col_idx);
    pj->B.values = malloc((size_t)(nnz + 1) * sizeof *pj->B.values);
    if (!pj->B.row_ptr || !pj->B.col_idx || !pj->B.values) rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  }
  if (!rc) {
    int32_t j = 0;
    pj->B.row_ptr[0] = 0;
    for (int32_t i = 0; i < np; ++i) {
      for (int32_t k = A->row_ptr[nv + i]; k < A->row_ptr[nv + i + 1]; ++k)
        if (A->col_idx[k] < nv) pj->B.col_idx[j] = A->col_idx[k], pj->B.values[j++] = A->values[k];
      pj->B.row_ptr[i + 1] = j;
    }
  }
  sl_system_free(&s);
  return rc;
}

/* The correction step with the frame's Coriolis force C (core/assembly/flow.c: C u = 2 Omega x u, planar
 * C_01 = -2 Omega, C_10 = 2 Omega; axisymmetric the same between r and theta): chi (m I + C) delta = -grad phi,
 * so delta = -D grad(phi) / chi with D = (m I + C)^{-1}, on the coupled pair [[m, 2 Omega], [-2 Omega, m]] / (m^2
 * + 4 Omega^2) and 1/m on the other component. Without it (C left to the velocity step alone) the increment's
 * rotated part J grad(phi) / (chi m), divergence-free, is not seen: at Omega / m >> 1 the pressure moves by (m /
 * 2 Omega)^2 of what the geostrophic balance asks and a rotating flow freezes. The correction step is GMS 2006's
 * eq 3.15 with the momentum's other local term linear in u, C, kept beside the mass term (derived here; checks:
 * Omega = 0 gives eq 3.15 itself, D's inverse is (m I + C) (J^2 = -I), and the inviscid rotating wave turns as the
 * monolithic step's, docs/transient_cost.md). The weak Poisson operator's antisymmetric part int grad(q).J
 * grad(phi) is a boundary term only (div J grad(phi) = 0): it gives the oblique condition (D grad(phi)).n = 0,
 * the correction's no-flux wall. D's in-plane 2 x 2 part times m, T = m P D P^T (P: the components that grad(phi)
 * has): planar the full pair, T = [[m^2, 2 Omega m], [-2 Omega m, m^2]] / (m^2 + 4 Omega^2); axisymmetric (grad phi = (d_r, d_z, 0))
 * T = diag(m^2 / (m^2 + 4 Omega^2), 1). Omega = 0: the identity. */
static void correction_tensor(const sl_projection *pj, double m, double T[4]) {
  double w = 2.0 * pj->omega, q = m * m / (m * m + w * w);
  if (pj->axi) T[0] = q, T[1] = T[2] = 0.0, T[3] = 1.0;
  else T[0] = T[3] = q, T[1] = w * m / (m * m + w * w), T[2] = -T[1];
}

/* The Poisson matrix int grad(q).T grad(phi) (r-weighted axisymmetric; T of correction_tensor at the mass
 * coefficient m, the identity without rotation) with its Dirichlet nodes; b the lumped mass int q. */
static int poisson_matrix(sl_projection *pj, int axisymmetric, double m, sl_diag *d) {
  sl_system_zero(&pj->psys);
  double T[4];
  correction_tensor(pj, m, T);
  sl_diffusion_opts o = {.diffusivity = {NULL, NULL, 1.0},
                         .source = {NULL, NULL, 1.0},
                         .axisymmetric = axisymmetric,
                         .tensor = pj->omega != 0.0 ? T : NULL};
  int rc = sl_assemble_diffusion(&pj->psys, pj->th->pres, &o, d);
  if (!rc) rc = sl_system_complete(&pj->psys, 1, d);
  if (!rc && pj->pfixed) rc = sl_csr_set_dirichlet(&pj->psys.A, pj->n_pfixed, pj->pfixed, NULL, NULL, 1, d);
  if (!rc) sl_csr_touch(&pj->psys.A);
  pj->m_poisson = m;
  return rc;
}

/* The Poisson operator (poisson_matrix; without rotation assembled and factorised once) and the lumped mass
 * int q (the same weight). */
static int build_poisson(sl_projection *pj, const sl_flow_problem *prob, sl_diag *d) {
  const sl_dofmap *pm = pj->th->pres;
  const sl_mesh *m = pj->th->mesh;
  int rc = sl_system_init_ranks(&pj->psys, pm->n_dofs, m->n_cells, pm->dofs_per_cell, pm->cell_dofs, pj->o.rank,
                                pj->o.ranks, d);
  if (rc) return rc;
  if ((rc = poisson_matrix(pj, prob->opts.axisymmetric, 1.0, d))) return rc;
  memcpy(pj->mass, pj->psys.b, (size_t)pj->np * sizeof *pj->mass);
  /* distributed, each rank holds its own rows of b (zeros elsewhere): the ranks' sum is the whole lumped mass,
   * bitwise the same on every rank */
  if (pj->psys.distributed && (rc = sl_linsolve_sum_ordered(pj->mass, pj->np, d))) return rc;
  for (int32_t i = 0; i < pj->np; ++i) pj->volume += pj->mass[i];
  if ((rc = sl_constraints_init(&pj->pbc, pm->n_dofs, d))) return rc;
  int any = 0;
  for (int b = 0; b < m->n_boundaries && !rc; ++b)
    if (pj->o.open && pj->o.open[b]) {
      rc = sl_constraints_fix_boundary(&pj->pbc, pm, m->boundary_names[b], 0, NULL, NULL, 0.0, d);
      any = 1;
    }
  if (rc) return rc;
  if (!any) sl_constraints_fix(&pj->pbc, 0, 0.0); /* the datum: phi, like p, up to a constant */
  pj->pfixed = malloc(((size_t)pj->pbc.n_fixed + 1) * sizeof *pj->pfixed);
  if (!pj->pfixed) return sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  for (int32_t i = 0; i < pm->n_dofs; ++i)
    if (pj->pbc.fixed[i]) pj->pfixed[pj->n_pfixed++] = i;
  return sl_csr_set_dirichlet(&pj->psys.A, pj->n_pfixed, pj->pfixed, NULL, NULL, 1, d);
}

/* The lumped mass int N_a of the velocity nodes (r-weighted axisymmetric), all positive on Q2 cells that are not
 * too distorted (row sums of the tensor-product Lagrange mass: 1/36, 4/36, 16/36 of an affine cell). */
static int velocity_mass(sl_projection *pj, int axisymmetric, sl_diag *d) {
  const sl_dofmap *vm = pj->th->vel;
  sl_system s;
  int rc = sl_system_init(&s, vm->n_dofs, vm->mesh->n_cells, vm->dofs_per_cell, vm->cell_dofs, d);
  if (rc) return rc;
  sl_system_zero(&s);
  sl_diffusion_opts o = {.diffusivity = {NULL, NULL, 0.0}, .source = {NULL, NULL, 1.0}, .axisymmetric = axisymmetric};
  if (!(rc = sl_assemble_diffusion(&s, vm, &o, d))) rc = sl_system_complete(&s, 1, d);
  /* an axis node's r-weighted mass is 0, in floating point a round-off of either sign (curved cells) */
  double largest = 0.0;
  for (int32_t i = 0; i < vm->n_dofs && !rc; ++i) largest = fmax(largest, fabs(s.b[i]));
  for (int32_t i = 0; i < vm->n_dofs && !rc; ++i) {
    if (axisymmetric && fabs(s.b[i]) <= 64.0 * DBL_EPSILON * largest) s.b[i] = 0.0;
    pj->vmass[i] = s.b[i];
    if (!(s.b[i] > 0.0) && !(axisymmetric && s.b[i] == 0.0))
      rc = sl_diag_set(d, SL_EFAILED, "projection: the lumped velocity mass of node %d is %g (a distorted cell)",
                       (int)i, s.b[i]);
    if (pj->vmass[i] == 0.0) pj->vmass[i] = 1.0; /* on the axis: its (r-weighted) gradient is 0 too */
  }
  sl_system_free(&s);
  return rc;
}

int sl_projection_create(const sl_flow_problem *prob, const sl_projection_opts *o, sl_projection **out, sl_diag *d) {
  *out = NULL;
  if (!(o->chi > 0.0)) {
    sl_linsolve_destroy(o->velocity_solver), sl_linsolve_destroy(o->poisson_solver);
    sl_linsolve_destroy(o->preconditioner_solver);
    return sl_diag_set(d, SL_EBADINPUT, "projection: the smallest density %g is not positive", o->chi);
  }
  sl_projection *pj = calloc(1, sizeof *pj);
  if (!pj) {
    sl_linsolve_destroy(o->velocity_solver), sl_linsolve_destroy(o->poisson_solver);
    sl_linsolve_destroy(o->preconditioner_solver);
    return sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  }
  pj->ls_v = o->velocity_solver, pj->ls_p = o->poisson_solver, pj->ls_P = o->preconditioner_solver;
  pj->refresh = 1;
  const sl_th_space *th = prob->th;
  pj->th = th, pj->o = *o, pj->nv = th->p_offset, pj->np = th->pres->n_dofs, pj->trial = -1;
  pj->omega = prob->opts.omega, pj->axi = prob->opts.axisymmetric;
  int nc = th->mesh->n_cells, nbv = th->n_comp * th->vel->dofs_per_cell;
  pj->vel_cell_dofs = malloc((size_t)nc * nbv * sizeof *pj->vel_cell_dofs);
  pj->mass = malloc((size_t)pj->np * sizeof *pj->mass);
  pj->phi_hist[0] = calloc((size_t)pj->np, sizeof(double));
  pj->phi_hist[1] = calloc((size_t)pj->np, sizeof(double));
  pj->phi_trial = calloc((size_t)pj->np, sizeof(double));
  pj->rhs = malloc((size_t)(pj->nv > pj->np ? pj->nv : pj->np) * sizeof *pj->rhs);
  pj->x = malloc((size_t)(pj->nv > pj->np ? pj->nv : pj->np) * sizeof *pj->x);
  pj->div = malloc((size_t)pj->np * sizeof *pj->div);
  pj->grad = malloc((size_t)pj->nv * sizeof *pj->grad);
  pj->vmass = malloc((size_t)th->vel->n_dofs * sizeof *pj->vmass);
  int rc = 0;
  if (!pj->vel_cell_dofs || !pj->mass || !pj->phi_hist[0] || !pj->phi_hist[1] || !pj->phi_trial || !pj->rhs || !pj->x ||
      !pj->div || !pj->grad || !pj->vmass)
    rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  /* each cell's velocity dofs lead its combined list (core/fe/dofmap.h) */
  for (int c = 0; c < nc && !rc; ++c)
    memcpy(pj->vel_cell_dofs + (size_t)c * nbv, th->cell_dofs + (size_t)c * th->dofs_per_cell,
           (size_t)nbv * sizeof *pj->vel_cell_dofs);
  /* The (z, theta) block of F (the z rows, the theta columns) is zero in an axisymmetric scene with swirl whose
     viscosity does not change with the shear rate: the viscous term does not couple theta with (r, z) (Batchelor
     1967, Appendix 2; axi_matrix in core/assembly/flow.c), Picard's convection couples theta with r alone (the
     hoop entries), the Coriolis force too (r and theta), the cell's sink is in-plane, and Newton's rho G(u) has
     G_z,theta = d u_z / d theta = 0 (axisymmetric). Only the generalized-Newtonian term 4 mu' gamma (Dhat:D(v))
     (Dhat:D(dv)) fills it. It is left out of F's pattern: 1/9 of F's entries, of the scatter and of each FGMRES
     product. Kept: on several ranks, in a rotating frame (P is F itself there), and with curved slip walls
     (their rotated r and z rows share one pattern). Test fe_flow_jacobian checks that the block is zero. */
  unsigned char *keep = NULL;
  if (!rc && !o->distributed && pj->axi && th->n_comp == 3 && o->shear_free && pj->omega == 0.0 && !prob->slip) {
    int nb = th->vel->dofs_per_cell;
    if (!(keep = malloc((size_t)nbv * nbv))) rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
    for (int a = 0; a < nbv && keep; ++a)
      for (int b = 0; b < nbv; ++b) keep[a * nbv + b] = !(a / nb == 1 && b / nb == 2);
  }
  if (!rc) {
    if (!o->distributed) rc = sl_system_init_kept(&pj->vsys, pj->nv, nc, nbv, pj->vel_cell_dofs, keep, d);
    else rc = sl_system_init_ranks(&pj->vsys, pj->nv, nc, nbv, pj->vel_cell_dofs, o->rank, o->ranks, d);
  }
  free(keep);
  int ncomp = th->n_comp, nb = th->vel->dofs_per_cell;
  /* distributed, F is solved without its diagonal blocks: no P, no map into F, no FGMRES workspace */
  if (!rc && !o->distributed && !(pj->comp_dofs = malloc((size_t)nc * nbv * sizeof *pj->comp_dofs)))
    rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  /* In a rotating frame the Coriolis force couples the components as strongly as the mass term holds each (2
   * Omega against m = 1.5 / dt: 13 times at Omega dt = 10), and the diagonal blocks are no preconditioner
   * there (FGMRES fails and F is solved directly at every step): P is then F itself, kept as long as it works. */
  if (!rc && !o->distributed) { /* element (cell, component): that component's dofs of the cell; rotating, the cell's */
    memcpy(pj->comp_dofs, pj->vel_cell_dofs, (size_t)nc * nbv * sizeof *pj->comp_dofs);
    rc = pj->omega != 0.0 ? sl_csr_build_uniform(&pj->P, pj->nv, nc, nbv, pj->comp_dofs, d)
                          : sl_csr_build_uniform(&pj->P, pj->nv, nc * ncomp, nb, pj->comp_dofs, d);
  }
  if (!rc && !o->distributed && !(pj->pmap = malloc(((size_t)pj->P.nnz + 1) * sizeof *pj->pmap)))
    rc = sl_diag_set(d, SL_ENOMEM, "projection: out of memory");
  if (!rc && !o->distributed) { /* P's entries among F's (the same rows, fewer columns) */
    const sl_csr *F = &pj->vsys.A, *P = &pj->P;
    for (int32_t i = 0; i < pj->nv && !rc; ++i) {
      int32_t k = F->row_ptr[i], end = F->row_ptr[i + 1];
      for (int32_t j = P->row_ptr[i]; j < P->row_ptr[i + 1]; ++j) {
        while (k < end && F->col_idx[k] < P->col_idx[j]) ++k;
        if (k == end || F->col_idx[k] != P->col_idx[j]) {
          rc = sl_diag_set(d, SL_EFAILED, "projection: a diagonal block's entry is not in the velocity block");
          break;
        }
        pj->pmap[j] = k;
      }
    }
  }
  if (!rc && !o->distributed) rc = sl_krylov_init(&pj->kry, pj->nv, SL_PROJECTION_KRYLOV_BUDGET, d);
  if (!rc) rc = build_divergence(pj, prob, d);
  if (!rc) rc = build_poisson(pj, prob, d);
  if (!rc && pj->omega != 0.0) rc = velocity_mass(pj, prob->opts.axisymmetric, d);
  if (rc) {
    sl_projection_destroy(pj);
    return rc;
  }
  *out = pj;
  return 0;
}

void sl_projection_destroy(sl_projection *pj) {
  if (!pj) return;
  sl_linsolve_destroy(pj->ls_v), sl_linsolve_destroy(pj->ls_p), sl_linsolve_destroy(pj->ls_P);
  sl_csr_free(&pj->P);
  sl_krylov_free(&pj->kry);
  free(pj->comp_dofs), free(pj->pmap);
  sl_system_free(&pj->vsys), sl_system_free(&pj->psys);
  sl_constraints_free(&pj->pbc);
  sl_csr_free(&pj->B);
  free(pj->vel_cell_dofs), free(pj->mass), free(pj->pfixed);
  free(pj->phi_hist[0]), free(pj->phi_hist[1]), free(pj->phi_trial);
  free(pj->rhs), free(pj->x), free(pj->div), free(pj->grad), free(pj->vmass);
  free(pj);
}

static int apply_F(void *user, const double *x, double *y, sl_diag *d) {
  (void)d;
  sl_csr_matvec_split(user, x, y);
  return 0;
}

static int apply_P(void *user, const double *x, double *y, sl_diag *d) {
  sl_projection *pj = user;
  return sl_linsolve_solve(pj->ls_P, &pj->P, x, y, d);
}

/* F x = b: FGMRES preconditioned by the diagonal blocks of an earlier F
 * (block Jacobi: Saad 2003, Iterative Methods for Sparse Linear Systems, 2nd ed., chapter 12), the blocks refactorised after a solve that needed more than
 * SL_PROJECTION_SLOW iterations or failed; a solve that fails with fresh blocks is solved directly.
 * The stopping test is Newton's on the step's velocity (rtol: the relative correction a monolithic step's Newton
 * stops at): x is the one correction from the predictor u, so its error, about eps |x| after a residual reduction
 * eps (Kelley 1995, Iterative Methods for Linear and Nonlinear Equations, Lemma 1.1.1, for a preconditioned
 * operator of condition near 1), is held to rtol |u|: eps = rtol |u| / |x|, |x| the last solve's (the steps' corrections vary
 * slowly), between rtol (the relative residual used before) and SL_PROJECTION_RTOL_MAX. On spinup the
 * corrections are 1e-4 to 1e-2 of |u|, and a solve takes 5.4 FGMRES iterations instead of 9.2.
 * The iteration starts from the last solve's correction scaled by (h / h_last)^3: the correction is the BDF2
 * predictor's error, the local error of order h^3 (Hairer, Norsett & Wanner 1993, section III.7: the difference of
 * predictor and corrector estimates the local error), and the steps' corrections vary slowly; the stopping test
 * is relative to |b| (krylov.h), so the start's share of x is iterations saved (spinup 5.4 -> 4.5 a solve). */
static int velocity_solve(sl_projection *pj, sl_csr *F, const double *b, double rtol, const double *u, sl_diag *d) {
  double *x = pj->x;
  double un = 0.0;
  for (int32_t i = 0; i < pj->nv; ++i) un += u[i] * u[i];
  un = sqrt(un);
  double eps = rtol;
  if (pj->dnorm > 0.0 && un > 0.0) eps = fmin(SL_PROJECTION_RTOL_MAX, fmax(rtol, rtol * un / pj->dnorm));
  if (pj->o.distributed) { /* the iterative velocity solver on the ranks' rows, x gathered on every rank */
    int rc = sl_linsolve_solve_rtol(pj->ls_v, F, b, x, eps, d);
    if (rc) return rc;
    double xn = 0.0;
    for (int32_t i = 0; i < pj->nv; ++i) xn += x[i] * x[i];
    pj->dnorm = sqrt(xn), pj->h_last = pj->h_now;
    pj->krylov_solves++;
    return 0;
  }
  for (int attempt = 0; attempt < 2; ++attempt) {
    int fresh = pj->refresh;
    if (pj->refresh) {
      for (int32_t j = 0; j < pj->P.nnz; ++j) pj->P.values[j] = F->values[pj->pmap[j]];
      sl_csr_touch(&pj->P);
      pj->refresh = 0, pj->refreshes++;
    }
    if (attempt == 0 && pj->h_last > 0.0 && pj->h_now > 0.0) {
      double f = pow(pj->h_now / pj->h_last, 3.0);
      for (int32_t i = 0; i < pj->nv; ++i) x[i] *= f;
    } else {
      memset(x, 0, (size_t)pj->nv * sizeof *x);
    }
    sl_krylov_opts ko = {.rtol = eps,
                         .restart = SL_PROJECTION_KRYLOV_BUDGET,
                         .max_iterations = SL_PROJECTION_KRYLOV_BUDGET,
                         .predict = 1,
                         .trust_estimate = 1}; /* no product for the last residual: only x and the count are used */
    sl_krylov_result kr;
    sl_diag dk = {{0}};
    int rc = sl_fgmres(&pj->kry, apply_F, F, apply_P, pj, b, x, &ko, &kr, &dk);
    pj->krylov_iterations += kr.iterations;
    if (rc == 0 && kr.status == SL_KRYLOV_CONVERGED) {
      double xn = 0.0;
      for (int32_t i = 0; i < pj->nv; ++i) xn += x[i] * x[i];
      pj->dnorm = sqrt(xn);
      pj->h_last = pj->h_now;
      pj->krylov_solves++;
      if (kr.iterations > SL_PROJECTION_SLOW) pj->refresh = 1;
      return 0;
    }
    pj->refresh = 1;
    if (fresh) break; /* fresh blocks did not do: F itself */
  }
  pj->direct_solves++;
  int rc = sl_linsolve_solve(pj->ls_v, F, b, x, d);
  pj->h_last = rc ? 0.0 : pj->h_now;
  return rc;
}

/* Rotating: the symmetric part of D (correction_tensor) on the gradient, m / (m^2 + 4 Omega^2), written as 1 / m'
 * with m' = m + 4 Omega^2 / m, the mass coefficient the predictor divides by (m without rotation). */
static double sym_mass(const sl_projection *pj, double m) { return m + 4.0 * pj->omega * pj->omega / m; }

/* The pressure predictor's increments: p# = p^k + sum_j w_j phi^{k-j} (projection.h). The BDF2 coefficients
 * follow from m h = a0 = (1 + 2 w)/(1 + w) (core/time/bdf.h): w = (a0 - 1)/(2 - a0); BDF1 has a0 = 1. */
static void predictor_weights(const sl_projection *pj, double m, double h, double w[2]) {
  double a0 = m * h;
  w[0] = w[1] = 0.0;
  if (pj->n_hist == 0) return;
  if (fabs(a0 - 1.0) < 1e-12 || pj->n_hist < 2) { /* BDF1 (or a first history): c_0 = -1/h */
    w[0] = 1.0 / (h * pj->m_hist[0]);
    if (pj->omega != 0.0) w[0] = 1.0 / (h * sym_mass(pj, pj->m_hist[0]));
    return;
  }
  double om = (a0 - 1.0) / (2.0 - a0);
  double c0 = -(1.0 + om) / h, c1 = om * om / ((1.0 + om) * h);
  w[0] = -c0 / pj->m_hist[0], w[1] = -c1 / pj->m_hist[1];
  if (pj->omega != 0.0) w[0] = -c0 / sym_mass(pj, pj->m_hist[0]), w[1] = -c1 / sym_mass(pj, pj->m_hist[1]);
}

/* In a rotating frame the kept velocity takes the rotated part of the correction: with the Coriolis force in
 * the correction step the projected velocity is u = u~ + delta, delta = -D grad(phi) / chi (correction_tensor),
 * D = [[m, 2 Omega], [-2 Omega, m]] / (m^2 + 4 Omega^2) on the coupled pair. Its symmetric part -(m / (m^2 + 4
 * Omega^2)) grad(phi) / chi, a gradient, is what the scheme leaves in u~ and the predictor's pressure carries
 * (predictor_weights with sym_mass, as GMS 2006 eq 3.14 does with 1/m); the antisymmetric part -(2 Omega / (m^2 +
 * 4 Omega^2)) J^T grad(phi) / chi, divergence-free, is the geostrophic adjustment of the velocity to the new
 * pressure, which no pressure predictor can carry: left out, the kept velocity trails the pressure by a step (the
 * inviscid wave lost c dt of its phase at the first split step, 0.0033 rad). Carrying the full -(D - I/m) part in
 * the kept velocity instead (a gradient as large as the increment itself) diverged within three steps at Omega
 * dt = 10. It is added to u~ at the velocity nodes, grad(phi) there the lumped L2 projection (B^T phi)_a / int N_a
 * (B^T phi = int v . grad(phi), the weak gradient the pressure acts through), the constraints imposed after. */
static void rotation_correction(sl_projection *pj, sl_flow_problem *prob, double m, double *u) {
  const int32_t nv = pj->nv, nvel = pj->th->vel->n_dofs;
  memset(pj->grad, 0, (size_t)nv * sizeof *pj->grad);
  const sl_csr *B = &pj->B;
  for (int32_t i = 0; i < B->n_rows; ++i)
    for (int32_t k = B->row_ptr[i]; k < B->row_ptr[i + 1]; ++k)
      pj->grad[B->col_idx[k]] += B->values[k] * pj->phi_trial[i];
  const int a = 0, b = pj->axi ? 2 : 1; /* the coupled pair (axisymmetric: r and theta, grad(phi)_theta = 0) */
  const double w = 2.0 * pj->omega, off = w / (m * m + w * w) / pj->o.chi;
  const double *ga = pj->grad + (size_t)a * nvel, *gb = pj->grad + (size_t)b * nvel;
  for (int32_t i = 0; i < nvel; ++i) { /* delta_J = -off J^T grad(phi): (-off g_b, off g_a) */
    double gai = ga[i] / pj->vmass[i], gbi = pj->axi ? 0.0 : gb[i] / pj->vmass[i];
    u[(size_t)a * nvel + i] -= off * gbi;
    u[(size_t)b * nvel + i] += off * gai;
  }
  sl_constraints_impose(&prob->bc, u);
  if (prob->slip) sl_slip_impose(prob->slip, u);
}

int sl_projection_step(sl_projection *pj, sl_flow_problem *prob, const sl_step *s, double *u, double linear_rtol,
                       double *t_assembly, sl_diag *d) {
  const int32_t nv = pj->nv, np = pj->np;
  double m = s->mass_coef, w[2];
  predictor_weights(pj, m, s->dt, w);
  /* the iterate: the predictor's velocity, the predicted pressure */
  double *p = u + nv;
  const double *pk = s->state ? s->state + nv : p;
  for (int32_t i = 0; i < np; ++i) p[i] = pk[i] + w[0] * pj->phi_hist[0][i] + w[1] * pj->phi_hist[1][i];
  double t0 = wall();
  int rc = sl_flow_problem_linearise_velocity(prob, u, &pj->vsys, d);
  if (t_assembly) *t_assembly += wall() - t0;
  if (rc) return rc;
  sl_csr *F = &pj->vsys.A;
  pj->h_now = s->dt;
  if ((rc = velocity_solve(pj, F, pj->vsys.b, linear_rtol, u, d)))
    return sl_diag_prefix(d, rc, "projection: the velocity solve");
  for (int32_t i = 0; i < nv; ++i) u[i] += pj->x[i];
  /* the increment: int grad(phi).grad(q) = chi m (B u~)_q */
  sl_csr_matvec(&pj->B, u, pj->div);
  double f = pj->o.chi * m;
  for (int32_t i = 0; i < np; ++i) pj->rhs[i] = f * pj->div[i];
  for (int32_t k = 0; k < pj->n_pfixed; ++k) pj->rhs[pj->pfixed[k]] = 0.0;
  if (pj->omega != 0.0 && m != pj->m_poisson) { /* the rotating correction's operator at this m, factorised afresh */
    if ((rc = poisson_matrix(pj, pj->axi, m, d))) return rc;
    sl_linsolve_drop_numeric(pj->ls_p);
  }
  if ((rc = sl_linsolve_solve(pj->ls_p, &pj->psys.A, pj->rhs, pj->phi_trial, d)))
    return sl_diag_prefix(d, rc, "projection: the pressure Poisson solve");
  if (pj->omega != 0.0) rotation_correction(pj, prob, m, u);
  pj->poisson_solves++;
  /* The splitting's part of the step: the end-of-step solenoidal velocity is u~ - grad(phi) / (chi m) (GMS 2006,
     eq 3.15, Guermond & Salgado 2009's chi), the intermediate u~ is kept, so the step's velocity carries
     delta = grad(phi) / (chi m). Its root mean square: |grad phi|^2 = phi . K phi = chi m phi . (B u~) (the
     Poisson equation; phi = 0 on its Dirichlet nodes), so |delta|^2 = phi . (B u~) / (chi m). */
  double g = 0.0;
  for (int32_t i = 0; i < np; ++i) g += pj->phi_trial[i] * pj->div[i];
  pj->split_rms = pj->volume > 0.0 && g > 0.0 ? sqrt(g / (f * pj->volume)) : 0.0;
  /* Rotating (correction_tensor, rotation_correction): the kept velocity leaves out delta's symmetric part
     -(m / (m^2 + 4 Omega^2)) grad(phi) / chi, and phi . K phi = chi m phi . (B u~) with K's symmetric part m^2 /
     (m^2 + 4 Omega^2) of the Laplacian, planar: |delta_sym|^2 = m^2 / (m^2 + 4 Omega^2) of the above; axisymmetric
     (the z part 1/m) the above bounds it. */
  if (pj->omega != 0.0 && !pj->axi) pj->split_rms /= sqrt(1.0 + 4.0 * pj->omega * pj->omega / (m * m));
  /* p^{k+1} = p^k + phi - mu div u~, div u~ ~ -(B u~) / mass (lumped) */
  double mu = pj->o.mu_rotational;
  for (int32_t i = 0; i < np; ++i) p[i] = pk[i] + pj->phi_trial[i] + (mu > 0.0 ? mu * pj->div[i] / pj->mass[i] : 0.0);
  if (pj->o.datum) { /* the pressure datum stays 0, as the monolithic solve's */
    double p0 = p[0];
    for (int32_t i = 0; i < np; ++i) p[i] -= p0;
  }
  pj->m_trial = m, pj->trial = 1;
  return 0;
}

int sl_projection_needs_start(const sl_projection *pj) { return pj->n_hist == 0; }

double sl_projection_split_rms(const sl_projection *pj) { return pj->split_rms; }

void sl_projection_started(sl_projection *pj, double mass_coef) {
  memset(pj->phi_trial, 0, (size_t)pj->np * sizeof *pj->phi_trial);
  pj->m_trial = mass_coef, pj->trial = 1;
}

void sl_projection_skip(sl_projection *pj) {
  memset(pj->phi_trial, 0, (size_t)pj->np * sizeof *pj->phi_trial);
  pj->trial = 0;
}

void sl_projection_accept(sl_projection *pj) {
  if (pj->trial < 0) return;
  if (pj->trial == 0) { /* a skipped step: no increment, and the history restarts */
    pj->n_hist = 0;
    memset(pj->phi_hist[0], 0, (size_t)pj->np * sizeof(double));
    memset(pj->phi_hist[1], 0, (size_t)pj->np * sizeof(double));
    pj->trial = -1;
    return;
  }
  double *old = pj->phi_hist[1];
  pj->phi_hist[1] = pj->phi_hist[0], pj->m_hist[1] = pj->m_hist[0];
  pj->phi_hist[0] = pj->phi_trial, pj->m_hist[0] = pj->m_trial;
  pj->phi_trial = old;
  if (pj->n_hist < 2) pj->n_hist++;
  pj->trial = -1;
}

int sl_projection_checkpoint(sl_projection *pj, sl_checkpoint_array *a, int max) {
  if (max < 7) return 0;
  /* [n_hist, m^k, m^{k-1}, refresh, the last correction's norm and step], the two increments, the preconditioner's
     values and the last correction (the next solve's start) */
  double *head = pj->head;
  head[0] = pj->n_hist, head[1] = pj->m_hist[0], head[2] = pj->m_hist[1], head[3] = pj->refresh;
  head[4] = pj->dnorm, head[5] = pj->h_last;
  snprintf(a[0].name, sizeof a[0].name, "projection_history"), a[0].n = 6, a[0].data = head;
  snprintf(a[1].name, sizeof a[1].name, "projection_phi"), a[1].n = pj->np, a[1].data = pj->phi_hist[0];
  snprintf(a[2].name, sizeof a[2].name, "projection_phi_prev"), a[2].n = pj->np, a[2].data = pj->phi_hist[1];
  /* the blocks' and the fallback's factorisations, which a restart rebuilds (the Poisson operator's, factorised
     once, it computes afresh as the run did); distributed, no blocks */
  snprintf(a[3].name, sizeof a[3].name, "projection_correction"), a[3].n = pj->nv, a[3].data = pj->x;
  int n = 4;
  if (!pj->o.distributed)
    snprintf(a[n].name, sizeof a[n].name, "projection_blocks"), a[n].n = pj->P.nnz, a[n++].data = pj->P.values;
  if (pj->ls_P) n += sl_factor_checkpoint(pj->ls_P, "linsolve_projection_blocks", a + n, max - n);
  n += sl_factor_checkpoint(pj->ls_v, "linsolve_projection_velocity", a + n, max - n);
  return n;
}

int sl_projection_restore(sl_projection *pj, const sl_checkpoint *ck, sl_diag *d) {
  const sl_checkpoint_array *h = sl_checkpoint_find(ck, "projection_history");
  const sl_checkpoint_array *a = sl_checkpoint_find(ck, "projection_phi");
  const sl_checkpoint_array *b = sl_checkpoint_find(ck, "projection_phi_prev");
  const sl_checkpoint_array *P = sl_checkpoint_find(ck, "projection_blocks");
  if (!h && !a && !b && !P) return 0;
  /* the blocks are not needed distributed, and a distributed run's checkpoint has none: they are formed at the
     next solve */
  if (pj->o.distributed) P = NULL;
  if (!h || !a || !b || (h->n < 4 || h->n > 6) || a->n != pj->np || b->n != pj->np || (P && P->n != pj->P.nnz))
    return sl_diag_set(d, SL_EBADINPUT,
                       "checkpoint: the projection's pressure increments do not fit the mesh "
                       "(%lld pressure values, the scene has %d)",
                       a ? (long long)a->n : 0LL, (int)pj->np);
  pj->n_hist = (int)h->data[0], pj->m_hist[0] = h->data[1], pj->m_hist[1] = h->data[2];
  pj->refresh = h->data[3] != 0.0;
  pj->dnorm = h->n >= 5 ? h->data[4] : 0.0; /* an older checkpoint's: the first solve to rtol itself */
  /* the last correction, the next solve's start (an older checkpoint's: none, the solve starts from 0) */
  const sl_checkpoint_array *x = sl_checkpoint_find(ck, "projection_correction");
  pj->h_last = 0.0;
  if (h->n == 6 && x && x->n == pj->nv) {
    pj->h_last = h->data[5];
    memcpy(pj->x, x->data, (size_t)pj->nv * sizeof(double));
  }
  if (P) {
    memcpy(pj->P.values, P->data, (size_t)pj->P.nnz * sizeof(double));
    sl_csr_touch(&pj->P);
  } else {
    pj->refresh = 1;
  }
  memcpy(pj->phi_hist[0], a->data, (size_t)pj->np * sizeof(double));
  memcpy(pj->phi_hist[1], b->data, (size_t)pj->np * sizeof(double));
  int rc = pj->ls_P ? sl_factor_restore(pj->ls_P, "linsolve_projection_blocks", ck, d) : 0;
  return rc ? rc : sl_factor_restore(pj->ls_v, "linsolve_projection_velocity", ck, d);
}

const sl_linsolve *sl_projection_velocity_solver(const sl_projection *pj) {
  return pj->o.distributed ? pj->ls_v : pj->ls_P;
}

void sl_projection_summary(const sl_projection *pj, char *buf, size_t cap) {
  const sl_linsolve_stats *ps = sl_linsolve_get_stats(pj->ls_p);
  long n = pj->krylov_solves + pj->direct_solves;
  if (pj->o.distributed) {
    char v[160], p[160];
    sl_linsolve_describe(pj->ls_v, v, sizeof v);
    sl_linsolve_describe(pj->ls_p, p, sizeof p);
    snprintf(buf, cap, "projection: velocity %ld solves (%s); pressure Poisson %ld solves (%s)", n, v,
             pj->poisson_solves, p);
    return;
  }
  snprintf(buf, cap,
           "projection: velocity %ld solves, %ld reused (FGMRES with its diagonal blocks' factors, %.1f iterations a "
           "solve), %ld numeric (the blocks), %ld direct; pressure Poisson %ld factorisation%s, %ld solves",
           n, pj->krylov_solves, pj->krylov_solves ? (double)pj->krylov_iterations / pj->krylov_solves : 0.0,
           pj->refreshes, pj->direct_solves, ps->n_numeric, ps->n_numeric == 1 ? "" : "s", pj->poisson_solves);
}
