/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Boundary forces from the momentum residual (forces.h). */
#include "core/models/navier_stokes/forces.h"

#include <math.h>
#include <string.h>

#include "core/solve/linsolve.h"

int sl_flow_forces(sl_flow_problem *p, const double *u, const unsigned char *want, unsigned char *work, double *F,
                   sl_diag *d) {
  const sl_th_space *th = p->th;
  const sl_mesh *m = th->mesh;
  double *b = p->sys.b;
  memset(b, 0, (size_t)th->n_dofs * sizeof *b);
  int rc = sl_assemble_flow(&p->sys, th, u, &p->opts, SL_FLOW_RESIDUAL, d); /* b = -R(u) */
  for (int k = 0; k < p->n_tractions && !rc; ++k)
    rc = sl_assemble_flow_traction(&p->sys, th, p->traction[k].boundary, p->traction[k].fn, p->traction[k].user,
                                   p->opts.axisymmetric, d);
  rc = sl_system_agree(&p->sys, rc, d);
  if (!rc) rc = sl_system_complete(&p->sys, 0, d); /* several ranks: each holds its own rows of b */
  if (rc) return sl_diag_prefix(d, rc, "boundary forces");
  const sl_dofmap *vel = th->vel;
  const int nv = m->nv_per_cell, nb = vel->dofs_per_cell;
  const double scale = p->opts.axisymmetric ? 2.0 * acos(-1.0) : 1.0;
  for (int bd = 0; bd < m->n_boundaries; ++bd) {
    if (!want[bd]) continue;
    memset(work, 0, (size_t)th->n_vel);
    double f[3] = {0, 0, 0};
    for (int k = m->bface_start[bd]; k < m->bface_start[bd + 1]; ++k) {
      int face = m->bface[k], c = m->face_cells[2 * face], lf = m->face_local[2 * face];
      /* the face's velocity nodes: its vertices and (2-D) its face node, in the element order of core/fe */
      int local[3] = {lf, m->dim == 1 ? -1 : (lf + 1) % nv, m->dim == 1 ? -1 : nv + lf};
      for (int j = 0; j < 3; ++j) {
        if (local[j] < 0 || local[j] >= nb) continue;
        int32_t dof = vel->cell_dofs[(size_t)c * nb + local[j]];
        if (work[dof]) continue;
        work[dof] = 1;
        for (int i = 0; i < th->n_comp; ++i) f[i] += b[sl_th_vel_dof(th, i, dof)];
      }
    }
    /* b = -R: the force on the body, -R(v_i), is the sum of b */
    for (int i = 0; i < th->n_comp; ++i) F[th->n_comp * bd + i] = scale * f[i];
  }
  /* several ranks: each summed the rows it owns (b is zero in the others) */
  for (int bd = 0; bd < m->n_boundaries && p->sys.distributed; ++bd)
    if (want[bd] && (rc = sl_linsolve_sum_ordered(F + th->n_comp * bd, th->n_comp, d)))
      return sl_diag_prefix(d, rc, "boundary forces");
  return 0;
}
