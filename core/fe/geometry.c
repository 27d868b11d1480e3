/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Isoparametric geometry: x(xi) = sum_k x_k N_k(xi) with the P1/Q1 basis
 * N of the cell through its vertices, or the P2/Q2 basis through its
 * geometric nodes (sl_mesh_cell_nodes) when the mesh has second-order
 * geometry. */
#include "core/fe/geometry.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sl_fe_values_init(sl_fe_values *fv, const sl_mesh *mesh, int n_spaces, const sl_element *const *spaces,
                      int quad_degree, int axisymmetric, sl_diag *d) {
  memset(fv, 0, sizeof *fv);
  if (n_spaces < 1 || n_spaces > SL_FE_MAX_SPACES)
    return sl_diag_set(d, SL_EBADINPUT, "fe values: %d spaces (1..%d supported)", n_spaces, SL_FE_MAX_SPACES);
  for (int s = 0; s < n_spaces; ++s)
    if (!spaces[s] || spaces[s]->cell != mesh->cell_type)
      return sl_diag_set(d, SL_EBADINPUT, "fe values: space %d is not an element on %s cells", s,
                         sl_cell_type_name(mesh->cell_type));
  int rc = sl_quadrature_for(mesh->cell_type, quad_degree, &fv->quad, d);
  if (rc) return rc;
  fv->mesh = mesh, fv->axisymmetric = axisymmetric, fv->n_spaces = n_spaces, fv->cell = -1;
  fv->geom = sl_fe_geometry_element(mesh);
  for (int q = 0; q < fv->quad.n; ++q) {
    fv->geom->eval(fv->quad.xi[q], fv->geom_phi[q], fv->geom_dphi[q]);
    for (int s = 0; s < n_spaces; ++s) {
      fv->space[s] = spaces[s];
      spaces[s]->eval(fv->quad.xi[q], fv->phi[s][q], fv->dphi_ref[s][q]);
    }
  }
  return 0;
}

int sl_fe_values_create(sl_fe_values **out, const sl_mesh *mesh, int n_spaces, const sl_element *const *spaces,
                        int quad_degree, int axisymmetric, sl_diag *d) {
  *out = malloc(sizeof **out);
  if (!*out) return sl_diag_set(d, SL_ENOMEM, "fe values: out of memory");
  int rc = sl_fe_values_init(*out, mesh, n_spaces, spaces, quad_degree, axisymmetric, d);
  if (rc) free(*out), *out = NULL;
  return rc;
}

void sl_fe_values_destroy(sl_fe_values *fv) { free(fv); }

const sl_element *sl_fe_geometry_element(const sl_mesh *mesh) {
  return sl_element_lagrange(mesh->cell_type, mesh->geom_order == 2 ? 2 : 1);
}

void sl_fe_values_map_points(const sl_fe_values *fv, int c, double (*x)[2]) {
  double p[SL_ELEMENT_MAX_BASIS][2];
  int n = sl_mesh_cell_nodes(fv->mesh, c, p);
  for (int q = 0; q < fv->quad.n; ++q) {
    x[q][0] = x[q][1] = 0.0;
    for (int k = 0; k < n; ++k) x[q][0] += fv->geom_phi[q][k] * p[k][0], x[q][1] += fv->geom_phi[q][k] * p[k][1];
  }
}

void sl_fe_map_point(const sl_mesh *mesh, int c, const double xi[2], double x[2]) {
  double N[SL_ELEMENT_MAX_BASIS], p[SL_ELEMENT_MAX_BASIS][2];
  int n = sl_mesh_cell_nodes(mesh, c, p);
  sl_fe_geometry_element(mesh)->eval(xi, N, NULL);
  x[0] = x[1] = 0.0;
  for (int k = 0; k < n; ++k) x[0] += N[k] * p[k][0], x[1] += N[k] * p[k][1];
}

void sl_fe_face_point(const sl_mesh *mesh, int c, int lf, double s, double xi[2], double x[2], double n[2],
                      double *ds) {
  const sl_element *p1 = sl_element_lagrange(mesh->cell_type, 1), *g = sl_fe_geometry_element(mesh);
  const double *a = p1->nodes[lf], *b = p1->nodes[(lf + 1) % mesh->nv_per_cell];
  double loc[2] = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])};
  if (xi) xi[0] = loc[0], xi[1] = loc[1];
  double N[SL_ELEMENT_MAX_BASIS], dN[SL_ELEMENT_MAX_BASIS][2], p[SL_ELEMENT_MAX_BASIS][2];
  int np = sl_mesh_cell_nodes(mesh, c, p);
  g->eval(loc, N, dN);
  double X[2] = {0, 0}, T[2] = {0, 0}, e[2] = {b[0] - a[0], b[1] - a[1]};
  for (int k = 0; k < np; ++k)
    for (int i = 0; i < 2; ++i) {
      X[i] += N[k] * p[k][i];
      T[i] += p[k][i] * (dN[k][0] * e[0] + dN[k][1] * e[1]); /* dx/ds along the reference edge */
    }
  double len = hypot(T[0], T[1]);
  if (x) x[0] = X[0], x[1] = X[1];
  /* counter-clockwise cells: the outward normal is the tangent turned clockwise */
  if (n) n[0] = T[1] / len, n[1] = -T[0] / len;
  if (ds) *ds = len;
}

/* J, det J and J^-1 at quadrature point q of cell c. */
static double jacobian(const sl_fe_values *fv, double (*p)[2], int n, int q, double J[2][2], double Jinv[2][2]) {
  const sl_mesh *m = fv->mesh;
  J[0][0] = J[0][1] = J[1][0] = J[1][1] = 0.0;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) J[i][j] += p[k][i] * fv->geom_dphi[q][k][j];
  if (m->dim == 1) {
    J[0][1] = J[1][0] = J[1][1] = 0.0; /* a 1-D mesh lies on the x axis */
    Jinv[0][0] = 1.0 / J[0][0], Jinv[0][1] = Jinv[1][0] = Jinv[1][1] = 0.0;
    return J[0][0];
  }
  double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  Jinv[0][0] = J[1][1] / det, Jinv[0][1] = -J[0][1] / det;
  Jinv[1][0] = -J[1][0] / det, Jinv[1][1] = J[0][0] / det;
  return det;
}

static int reinit(sl_fe_values *fv, int c, int gradients, sl_diag *d) {
  double p[SL_ELEMENT_MAX_BASIS][2];
  int n = sl_mesh_cell_nodes(fv->mesh, c, p);
  fv->cell = c;
  for (int q = 0; q < fv->quad.n; ++q) {
    fv->x[q][0] = fv->x[q][1] = 0.0;
    for (int k = 0; k < n; ++k)
      fv->x[q][0] += fv->geom_phi[q][k] * p[k][0], fv->x[q][1] += fv->geom_phi[q][k] * p[k][1];
  }
  for (int q = 0; q < fv->quad.n; ++q) {
    double Jinv[2][2];
    double det = jacobian(fv, p, n, q, fv->J[q], Jinv);
    if (!(det > 0.0))
      return sl_diag_set(d, SL_EBADINPUT, "fe values: cell %d has Jacobian %g at quadrature point %d", c, det, q);
    fv->detJ[q] = det;
    fv->JxW[q] = det * fv->quad.w[q];
    if (fv->axisymmetric) {
      if (fv->x[q][0] < 0.0)
        return sl_diag_set(d, SL_EBADINPUT, "fe values: axisymmetric cell %d reaches r = %g < 0", c, fv->x[q][0]);
      fv->JxW[q] *= fv->x[q][0];
    }
    if (!gradients) continue;
    /* grad = J^-T dphi_ref: grad_i = sum_j Jinv[j][i] dphi_ref_j */
    for (int s = 0; s < fv->n_spaces; ++s)
      for (int b = 0; b < fv->space[s]->n_basis; ++b) {
        const double *g = fv->dphi_ref[s][q][b];
        fv->grad[s][q][b][0] = Jinv[0][0] * g[0] + Jinv[1][0] * g[1];
        fv->grad[s][q][b][1] = Jinv[0][1] * g[0] + Jinv[1][1] * g[1];
      }
  }
  return 0;
}

int sl_fe_values_reinit(sl_fe_values *fv, int c, sl_diag *d) { return reinit(fv, c, 1, d); }

int sl_fe_values_reinit_measure(sl_fe_values *fv, int c, sl_diag *d) { return reinit(fv, c, 0, d); }
