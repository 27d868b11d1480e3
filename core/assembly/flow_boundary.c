/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Boundary integrals of the flow equations: prescribed tractions. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/batch.h"
#include "core/assembly/flow.h"
#include "core/fe/geometry.h"
#include "core/fe/quadrature.h"

#define FACE_POINTS 3

int sl_assemble_flow_traction(sl_system *s, const sl_th_space *th, const char *boundary, sl_qp_fn traction, void *user,
                              int axisymmetric, sl_diag *d) {
  const sl_mesh *m = th->mesh;
  int b_id, rc = sl_mesh_boundary_id(m, boundary, &b_id, d);
  if (rc) return rc;
  int nf = m->bface_start[b_id + 1] - m->bface_start[b_id];
  int npf = m->dim == 1 ? 1 : FACE_POINTS, np = nf * npf, nc = th->n_comp, nb = th->vel->dofs_per_cell;
  sl_quadrature g;
  if ((rc = sl_quadrature_gauss_line(FACE_POINTS, &g, d))) return rc;
  double(*x)[2] = malloc((size_t)np * sizeof *x), (*nrm)[2] = malloc((size_t)np * sizeof *nrm);
  double(*xi)[2] = malloc((size_t)np * sizeof *xi), *w = malloc((size_t)np * sizeof *w);
  int32_t *cell = malloc((size_t)np * sizeof *cell);
  double *t = malloc((size_t)np * nc * sizeof *t);
  if (!x || !nrm || !xi || !w || !cell || !t) {
    rc = sl_diag_set(d, SL_ENOMEM, "traction: out of memory");
    goto out;
  }
  const sl_element *p1 = sl_element_lagrange(m->cell_type, 1);
  for (int k = 0; k < nf; ++k) {
    int f = m->bface[m->bface_start[b_id] + k], c = m->face_cells[2 * f], lf = m->face_local[2 * f];
    double n[2], len = sl_mesh_face_length(m, f);
    sl_mesh_face_normal(m, f, n);
    for (int q = 0; q < npf; ++q) {
      int i = k * npf + q;
      if (m->dim == 1) {
        xi[i][0] = p1->nodes[lf][0], xi[i][1] = 0.0, w[i] = 1.0;
      } else if (m->geom_order == 2) { /* along the curved face: its own normal and length element */
        double ds;
        sl_fe_face_point(m, c, lf, 0.5 * (1.0 + g.xi[q][0]), xi[i], x[i], n, &ds);
        w[i] = 0.5 * g.w[q] * ds;
      } else {
        const double *a = p1->nodes[lf], *bb = p1->nodes[(lf + 1) % m->nv_per_cell];
        double sq = 0.5 * (1.0 + g.xi[q][0]); /* [-1, 1] -> [0, 1] along the edge */
        xi[i][0] = a[0] + sq * (bb[0] - a[0]), xi[i][1] = a[1] + sq * (bb[1] - a[1]);
        w[i] = 0.5 * g.w[q] * len;
      }
      sl_fe_map_point(m, c, xi[i], x[i]);
      if (axisymmetric) w[i] *= x[i][0];
      nrm[i][0] = n[0], nrm[i][1] = n[1], cell[i] = c;
    }
  }
  sl_qp_batch view = {.n = np, .x = (const double(*)[2])x, .cell = cell, .normal = (const double(*)[2])nrm};
  sl_coef cf = {traction, user, 0.0};
  if ((rc = sl_asm_coef_eval(&cf, "traction", &view, nc, t, d))) goto out;
  double be[3 * SL_ELEMENT_MAX_BASIS + 4], phi[SL_ELEMENT_MAX_BASIS];
  int ndof = th->dofs_per_cell;
  for (int k = 0; k < nf && !rc; ++k) {
    memset(be, 0, (size_t)ndof * sizeof *be);
    for (int q = 0; q < npf; ++q) {
      int i = k * npf + q;
      th->vel->element->eval(xi[i], phi, NULL);
      for (int a = 0; a < nc; ++a)
        for (int j = 0; j < nb; ++j) be[a * nb + j] += w[i] * t[(size_t)i * nc + a] * phi[j];
    }
    rc = sl_system_add_element(s, cell[k * npf], NULL, be, d);
  }
out:
  free(x), free(nrm), free(xi), free(w), free(cell), free(t);
  return rc;
}
