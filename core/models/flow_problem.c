/* Flow problems for the nonlinear solver (see flow_problem.h). */
#include "core/models/flow_problem.h"

#include <stdlib.h>
#include <string.h>

int sl_flow_problem_init(sl_flow_problem *p, const sl_th_space *th, sl_diag *d) {
  memset(p, 0, sizeof *p);
  p->th = th;
  int rc = sl_system_init(&p->sys, th->n_dofs, th->mesh->n_cells, th->dofs_per_cell, th->cell_dofs, d);
  if (rc) return rc;
  if ((rc = sl_constraints_init(&p->bc, th->n_dofs, d))) sl_system_free(&p->sys);
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

static int collect_fixed(sl_flow_problem *p, sl_diag *d) {
  int32_t *f = realloc(p->fixed, ((size_t)p->bc.n_fixed + 1) * sizeof *f), k = 0;
  if (!f) return sl_diag_set(d, SL_EFAILED, "flow: out of memory");
  p->fixed = f;
  for (int32_t i = 0; i < p->bc.n_dofs; ++i)
    if (p->bc.fixed[i]) f[k++] = i;
  p->n_fixed = k;
  return 0;
}

int sl_flow_problem_assemble(void *user, const double *u, sl_nl_mode mode, sl_csr *A, double *b, sl_diag *d) {
  sl_flow_problem *p = user;
  static const sl_flow_linearisation lin[] = {SL_FLOW_RESIDUAL, SL_FLOW_NEWTON, SL_FLOW_PICARD};
  if (A != &p->sys.A || b != p->sys.b)
    return sl_diag_set(d, SL_EBADINPUT, "flow: assemble into the problem's own system");
  int rc = sl_assemble_flow(&p->sys, p->th, u, &p->opts, lin[mode], d);
  for (int k = 0; k < p->n_tractions && !rc; ++k)
    rc = sl_assemble_flow_traction(&p->sys, p->th, p->traction[k].boundary, p->traction[k].fn, p->traction[k].user,
                                   p->opts.axisymmetric, d);
  if (rc) return rc;
  if (mode == SL_NL_RESIDUAL) {
    for (int32_t k = 0; k < p->n_fixed; ++k) b[p->fixed[k]] = 0.0;
    return 0;
  }
  return sl_csr_set_dirichlet(A, p->n_fixed, p->fixed, NULL, b, 0, d);
}

int sl_flow_problem_solve(sl_flow_problem *p, double *u, sl_linsolve *ls, const sl_newton_opts *o,
                          sl_newton_stats *st, sl_diag *d) {
  int rc = collect_fixed(p, d);
  if (rc) return rc;
  sl_constraints_impose(&p->bc, u);
  sl_newton_opts oo = *o;
  if (oo.n_check <= 0) oo.n_check = p->th->p_offset;
  return sl_newton_solve(&p->sys.A, p->sys.b, p->th->n_dofs, u, sl_flow_problem_assemble, p, ls, &oo, st, d);
}
