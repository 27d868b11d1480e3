/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Flow problems for the nonlinear solver (see flow_problem.h). */
#include "core/models/navier_stokes/flow_problem.h"

#include <stdlib.h>
#include <string.h>

#include "core/solve/linsolve.h"

int sl_flow_problem_init(sl_flow_problem *p, const sl_th_space *th, sl_diag *d) {
  memset(p, 0, sizeof *p);
  p->th = th;
  /* on several ranks (mpirun) each assembles its own block of cells and owns their rows (system.h) */
  int rank = 0, ranks = 1;
  int rc = sl_linsolve_ranks(&rank, &ranks, d);
  if (rc) return rc;
  if (!sl_linsolve_built("petsc")) rank = 0, ranks = 1; /* without PETSc the scene refuses several ranks */
  rc = sl_system_init_ranks(&p->sys, th->n_dofs, th->mesh->n_cells, th->dofs_per_cell, th->cell_dofs, rank, ranks, d);
  if (rc) return rc;
  if ((rc = sl_constraints_init(&p->bc, th->n_dofs, d))) {
    sl_system_free(&p->sys);
    return rc;
  }
  p->opts.density.value = 1.0;
  p->opts.viscosity_value = 1.0;
  return rc;
}

void sl_flow_problem_free(sl_flow_problem *p) {
  sl_system_free(&p->sys);
  sl_constraints_free(&p->bc);
  free(p->fixed);
  memset(p, 0, sizeof *p);
}

/* The constrained dofs into p->fixed; a change of the set drops the kept
 * matrix (its identity rows are those of the old set). */
static int collect_fixed(sl_flow_problem *p, sl_diag *d) {
  int32_t old = p->n_fixed, k = 0;
  int32_t *f = realloc(p->fixed, ((size_t)(p->bc.n_fixed > old ? p->bc.n_fixed : old) + 1) * sizeof *f);
  if (!f) return sl_diag_set(d, SL_ENOMEM, "flow: out of memory");
  p->fixed = f;
  int same = 1;
  for (int32_t i = 0; i < p->bc.n_dofs; ++i)
    if (p->bc.fixed[i]) {
      same &= k < old && f[k] == i; /* f[0 .. old) still holds the previous set */
      f[k++] = i;
    }
  if (!same || k != old) p->matrix.valid = 0;
  p->n_fixed = k;
  return 0;
}

typedef struct sl_flow_matrix_key matrix_key;

/* The inputs of the matrix when it does not depend on the iterate (nor on
 * anything a callback could change); 0 otherwise. Everything else in the
 * options (history, body force, rotation centre) and the tractions enter the
 * right-hand side only. */
static int constant_matrix_key(const sl_flow_opts *o, matrix_key *k) {
  if (o->convection || o->viscosity || o->density.fn || o->cell_drag) return 0;
  *k = (matrix_key){.mass_coef = o->mass_coef,
                    .density = o->density.value,
                    .viscosity = o->viscosity_value,
                    .omega = o->omega,
                    .axisymmetric = o->axisymmetric,
                    .quad_degree = o->quad_degree};
  return 1;
}

/* Whether sys.A still holds the matrix of the current options. */
static int matrix_current(const sl_flow_problem *p) {
  const matrix_key *m = &p->matrix;
  matrix_key k;
  return m->valid && constant_matrix_key(&p->opts, &k) && k.mass_coef == m->mass_coef && k.density == m->density &&
         k.viscosity == m->viscosity && k.omega == m->omega && k.axisymmetric == m->axisymmetric &&
         k.quad_degree == m->quad_degree && p->sys.A.pattern_id == m->pattern_id &&
         p->sys.A.values_gen == m->values_gen;
}

/* The tractions' part of b (they depend on the data only). */
static int add_tractions(sl_flow_problem *p, sl_system *s, sl_diag *d) {
  int rc = 0;
  for (int k = 0; k < p->n_tractions && !rc; ++k)
    rc = sl_assemble_flow_traction(s, p->th, p->traction[k].boundary, p->traction[k].fn, p->traction[k].user,
                                   p->opts.axisymmetric, d);
  return rc;
}

/* b = -R(u) of a problem linear in u whose operator is in A:
 * (the u-independent part) - A u; only the load is assembled, not the
 * element operators. Used after every assembly of such a problem, so that
 * a step's right-hand side is the same sum whether its matrix was kept or
 * assembled afresh (a restarted run reproduces the uninterrupted one). */
static int linear_residual(sl_flow_problem *p, const double *u, int u_zero, double *b, sl_diag *d) {
  memset(b, 0, (size_t)p->th->n_dofs * sizeof *b);
  int rc = sl_assemble_flow(&p->sys, p->th, u, &p->opts, SL_FLOW_LOAD, d);
  if (!rc) rc = add_tractions(p, &p->sys, d);
  rc = sl_system_agree(&p->sys, rc, d);
  if (!rc) rc = sl_system_complete(&p->sys, 0, d);
  if (rc) return rc;
  /* A's slip rows are rotated (sl_flow_problem_assemble): so is the load, before A u comes off */
  if (p->slip && (rc = sl_slip_rows(p->slip, NULL, b, d))) return rc;
  if (!u_zero) sl_csr_matvec_add(&p->sys.A, -1.0, u, 1.0, b); /* (A 0 = 0) */
  for (int32_t k = 0; k < p->n_fixed; ++k) b[p->fixed[k]] = 0.0;
  if (p->slip) sl_slip_zero_normal(p->slip, b);
  return 0;
}

/* A problem linear in u (Stokes flow of a Newtonian fluid: the density, a cell's drag and the frame's terms are
 * linear in u) at u = 0 exactly: -R(0) is the load alone, whatever A holds (A 0 = 0), so its residual needs the
 * load's assembly only (a vessel at rest, whose every step starts there). */
static int linear_at_zero(const sl_flow_problem *p, const double *u) {
  if (p->opts.convection || p->opts.viscosity) return 0;
  for (int32_t i = 0; i < p->th->n_dofs; ++i)
    if (u[i] != 0.0) return 0;
  return 1;
}

int sl_flow_problem_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d) {
  sl_flow_problem *p = user;
  static const sl_flow_linearisation lin[] = {SL_FLOW_RESIDUAL, SL_FLOW_NEWTON, SL_FLOW_PICARD};
  if (A != &p->sys.A || b != p->sys.b)
    return sl_diag_set(d, SL_EBADINPUT, "flow: assemble into the problem's own system");
  if (mode == SL_NL_RESIDUAL) {
    int zero = linear_at_zero(p, u);
    if (zero || matrix_current(p)) return linear_residual(p, u, zero, b, d);
  }
  if (mode != SL_NL_RESIDUAL) p->matrix.valid = 0;
  int rc = sl_assemble_flow(&p->sys, p->th, u, &p->opts, lin[mode], d);
  if (!rc) rc = add_tractions(p, &p->sys, d);
  rc = sl_system_agree(&p->sys, rc, d);
  if (!rc) rc = sl_system_complete(&p->sys, mode != SL_NL_RESIDUAL, d);
  if (rc) return rc;
  if (mode == SL_NL_RESIDUAL) {
    for (int32_t k = 0; k < p->n_fixed; ++k) b[p->fixed[k]] = 0.0;
    return p->slip ? sl_slip_rows(p->slip, NULL, b, d) : 0;
  }
  if ((rc = sl_csr_set_dirichlet(A, p->n_fixed, p->fixed, NULL, b, 0, d))) return rc;
  if (p->slip && (rc = sl_slip_rows(p->slip, A, b, d))) return rc;
  matrix_key k;
  if (!constant_matrix_key(&p->opts, &k)) return 0;
  k.valid = 1, k.pattern_id = A->pattern_id, k.values_gen = A->values_gen;
  p->matrix = k;
  return linear_residual(p, u, 0, b, d);
}

int sl_flow_problem_solve(sl_flow_problem *p, double *u, sl_linsolve *ls, const sl_newton_opts *o, sl_newton_stats *st,
                          sl_diag *d) {
  int rc = collect_fixed(p, d);
  if (rc) return rc;
  sl_constraints_impose(&p->bc, u);
  if (p->slip) sl_slip_impose(p->slip, u);
  sl_newton_opts oo = *o;
  if (oo.n_check <= 0) oo.n_check = p->th->p_offset;
  oo.matrix_current = oo.linear && matrix_current(p);
  return sl_newton_solve(&p->sys.A, p->sys.b, p->th->n_dofs, u, sl_flow_problem_assemble, p, ls, &oo, st, d);
}

int sl_flow_problem_linearise_velocity(sl_flow_problem *p, double *u, sl_system *vs, sl_diag *d) {
  int rc = collect_fixed(p, d);
  if (rc) return rc;
  sl_constraints_impose(&p->bc, u);
  if (p->slip) sl_slip_impose(p->slip, u);
  sl_system_zero(vs);
  sl_flow_opts o = p->opts;
  o.velocity_block = 1;
  rc = sl_assemble_flow(vs, p->th, u, &o, SL_FLOW_NEWTON, d);
  if (!rc) rc = add_tractions(p, vs, d); /* a traction's element vector leads with its velocity entries */
  rc = sl_system_agree(vs, rc, d);
  if (!rc) rc = sl_system_complete(vs, 1, d);
  if (rc) return rc;
  /* the constrained velocity dofs: p->fixed is increasing, so they lead it */
  int32_t nv = 0;
  while (nv < p->n_fixed && p->fixed[nv] < p->th->p_offset) ++nv;
  rc = sl_csr_set_dirichlet(&vs->A, nv, p->fixed, NULL, vs->b, 0, d);
  if (!rc && p->slip) rc = sl_slip_rows(p->slip, &vs->A, vs->b, d); /* the velocity dofs lead: the same rows */
  return rc;
}
