/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Evaluation, integrals and error norms of finite-element functions. */
#include "core/fe/field.h"

#include <math.h>

#include "core/fe/geometry.h"

/* u_h and its gradient at quadrature point q of the current cell. */
static void value_at(const sl_fe_values *fv, const int32_t *cd, const double *u, int q, double *val, double grad[2]) {
  *val = grad[0] = grad[1] = 0.0;
  for (int b = 0; b < fv->space[0]->n_basis; ++b) {
    double ub = u[cd[b]];
    *val += ub * fv->phi[0][q][b];
    grad[0] += ub * fv->grad[0][q][b][0], grad[1] += ub * fv->grad[0][q][b][1];
  }
}

int sl_fe_error_norms(const sl_dofmap *dm, const double *u, sl_exact_fn exact, void *user, int axisymmetric,
                      int quad_degree, double *l2, double *h1_semi, sl_diag *d) {
  sl_fe_values *fv;
  int rc = sl_fe_values_create(&fv, dm->mesh, 1, &dm->element, quad_degree, axisymmetric, d);
  if (rc) return rc;
  double e0 = 0.0, e1 = 0.0;
  for (int c = 0; c < dm->mesh->n_cells && !rc; ++c) {
    rc = sl_fe_values_reinit(fv, c, d);
    const int32_t *cd = dm->cell_dofs + (size_t)c * dm->dofs_per_cell;
    for (int q = 0; q < fv->quad.n && !rc; ++q) {
      double uh, gh[2], ue, ge[2] = {0.0, 0.0};
      value_at(fv, cd, u, q, &uh, gh);
      exact(user, fv->x[q], &ue, ge);
      double dx = gh[0] - ge[0], dy = dm->mesh->dim == 2 ? gh[1] - ge[1] : 0.0;
      e0 += fv->JxW[q] * (uh - ue) * (uh - ue);
      e1 += fv->JxW[q] * (dx * dx + dy * dy);
    }
  }
  sl_fe_values_destroy(fv);
  if (l2) *l2 = sqrt(e0);
  if (h1_semi) *h1_semi = sqrt(e1);
  return rc;
}

int sl_fe_integrate(const sl_dofmap *dm, const double *u, int axisymmetric, double *integral, double *measure,
                    sl_diag *d) {
  sl_fe_values *fv;
  int rc = sl_fe_values_create(&fv, dm->mesh, 1, &dm->element, 2 * dm->element->order + 1, axisymmetric, d);
  if (rc) return rc;
  double s = 0.0, a = 0.0;
  for (int c = 0; c < dm->mesh->n_cells && !rc; ++c) {
    rc = sl_fe_values_reinit(fv, c, d);
    const int32_t *cd = dm->cell_dofs + (size_t)c * dm->dofs_per_cell;
    for (int q = 0; q < fv->quad.n && !rc; ++q) {
      double uh, gh[2];
      value_at(fv, cd, u, q, &uh, gh);
      s += fv->JxW[q] * uh, a += fv->JxW[q];
    }
  }
  sl_fe_values_destroy(fv);
  if (integral) *integral = s;
  if (measure) *measure = a;
  return rc;
}

/* ---- point location ----------------------------------------------------- */

#define SL_LOCATE_TOL 1e-10

static int inside_reference(sl_cell_type t, const double xi[2]) {
  const double e = SL_LOCATE_TOL;
  switch (t) {
    case SL_CELL_LINE2:
      return xi[0] >= -1.0 - e && xi[0] <= 1.0 + e;
    case SL_CELL_TRI3:
      return xi[0] >= -e && xi[1] >= -e && xi[0] + xi[1] <= 1.0 + e;
    case SL_CELL_QUAD4:
      return fabs(xi[0]) <= 1.0 + e && fabs(xi[1]) <= 1.0 + e;
  }
  return 0;
}

/* Inverse of the geometric map by Newton's method: exact in one step for
 * affine cells, quadratic convergence for bilinear quads. */
static void inverse_map(const sl_mesh *m, int c, const double x[2], double xi[2]) {
  const sl_element *g = sl_fe_geometry_element(m);
  double P[SL_ELEMENT_MAX_BASIS][2];
  int np = sl_mesh_cell_nodes(m, c, P);
  xi[0] = xi[1] = m->cell_type == SL_CELL_TRI3 ? 1.0 / 3.0 : 0.0;
  for (int it = 0; it < 20; ++it) {
    double N[SL_ELEMENT_MAX_BASIS], dN[SL_ELEMENT_MAX_BASIS][2], r[2] = {-x[0], -x[1]}, J[2][2] = {{0, 0}, {0, 0}};
    g->eval(xi, N, dN);
    for (int k = 0; k < np; ++k) {
      const double *p = P[k];
      for (int i = 0; i < 2; ++i) {
        r[i] += N[k] * p[i];
        for (int j = 0; j < 2; ++j) J[i][j] += p[i] * dN[k][j];
      }
    }
    double dxi, deta = 0.0;
    if (m->dim == 1) {
      dxi = r[0] / J[0][0];
    } else {
      double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      dxi = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
      deta = (-J[1][0] * r[0] + J[0][0] * r[1]) / det;
    }
    xi[0] -= dxi, xi[1] -= deta;
    if (fabs(dxi) + fabs(deta) < 1e-14) break;
  }
}

static int try_cell(const sl_mesh *m, int c, const double x[2], double xi[2]) {
  inverse_map(m, c, x, xi);
  return inside_reference(m->cell_type, xi);
}

int sl_fe_locate(const sl_mesh *mesh, const double x[2], int *cell, double xi[2], sl_diag *d) {
  if (*cell >= 0 && *cell < mesh->n_cells && try_cell(mesh, *cell, x, xi)) return 0;
  for (int c = 0; c < mesh->n_cells; ++c)
    if (try_cell(mesh, c, x, xi)) {
      *cell = c;
      return 0;
    }
  *cell = -1;
  return sl_diag_set(d, SL_EBADINPUT, "fe locate: the point (%g, %g) lies in no cell of the mesh", x[0], x[1]);
}

void sl_fe_eval(const sl_dofmap *dm, const double *u, int c, const double xi[2], double *value, double grad[2]) {
  const sl_mesh *m = dm->mesh;
  double phi[SL_ELEMENT_MAX_BASIS], dphi[SL_ELEMENT_MAX_BASIS][2];
  dm->element->eval(xi, phi, dphi);
  const int32_t *cd = dm->cell_dofs + (size_t)c * dm->dofs_per_cell;
  double v = 0.0, gr[2] = {0.0, 0.0};
  for (int b = 0; b < dm->dofs_per_cell; ++b) {
    v += u[cd[b]] * phi[b];
    gr[0] += u[cd[b]] * dphi[b][0], gr[1] += u[cd[b]] * dphi[b][1];
  }
  *value = v;
  if (!grad) return;
  /* Physical gradient: J^-T times the reference gradient. */
  double N[SL_ELEMENT_MAX_BASIS], dN[SL_ELEMENT_MAX_BASIS][2], J[2][2] = {{0, 0}, {0, 0}}, P[SL_ELEMENT_MAX_BASIS][2];
  int np = sl_mesh_cell_nodes(m, c, P);
  sl_fe_geometry_element(m)->eval(xi, N, dN);
  for (int k = 0; k < np; ++k) {
    const double *p = P[k];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) J[i][j] += p[i] * dN[k][j];
  }
  if (m->dim == 1) {
    grad[0] = gr[0] / J[0][0], grad[1] = 0.0;
    return;
  }
  double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  grad[0] = (J[1][1] * gr[0] - J[1][0] * gr[1]) / det;
  grad[1] = (-J[0][1] * gr[0] + J[0][0] * gr[1]) / det;
}

void sl_fe_interpolate(const sl_dofmap *dm, sl_exact_fn g, void *user, double *u) {
  for (int32_t i = 0; i < dm->n_dofs; ++i) g(user, dm->xy + 2 * (size_t)i, &u[i], NULL);
}
