/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Second-order (curved) cell geometry: the quadratic Lagrange map of a
 * 6-node triangle or 9-node quadrangle through its vertices, face nodes and
 * (quads) centre node, x(xi) = sum_k x_k N_k(xi) (the isoparametric map of
 * Ciarlet & Raviart 1972; Zienkiewicz & Taylor, The Finite Element Method,
 * vol. 1, 5th ed. 2000, sec. 8.5 and 9.4). The node order is that of
 * core/fe/element.h, which is also Gmsh's for types 9 and 10. */
#include <math.h>
#include <stdio.h>

#include "core/mesh/mesh.h"

int sl_mesh_cell_nodes(const sl_mesh *m, int c, double (*x)[2]) {
  const int nv = m->nv_per_cell;
  for (int k = 0; k < nv; ++k) {
    const double *p = m->xy + 2 * (size_t)m->cell_vertices[(size_t)c * nv + k];
    x[k][0] = p[0], x[k][1] = p[1];
  }
  if (m->geom_order < 2) return nv;
  for (int k = 0; k < m->nf_per_cell; ++k) {
    const double *p = m->face_mid + 2 * (size_t)m->cell_faces[(size_t)c * m->nf_per_cell + k];
    x[nv + k][0] = p[0], x[nv + k][1] = p[1];
  }
  if (m->cell_type == SL_CELL_TRI3) return 6;
  x[8][0] = m->cell_mid[2 * (size_t)c], x[8][1] = m->cell_mid[2 * (size_t)c + 1];
  return 9;
}

/* Reference gradients of the quadratic basis at xi (the element order). */
static int quadratic_gradients(sl_cell_type t, const double xi[2], double dN[9][2]) {
  if (t == SL_CELL_TRI3) { /* barycentric l0 = 1 - xi - eta, l1 = xi, l2 = eta */
    double l0 = 1 - xi[0] - xi[1], l1 = xi[0], l2 = xi[1];
    dN[0][0] = dN[0][1] = -(4 * l0 - 1);
    dN[1][0] = 4 * l1 - 1, dN[1][1] = 0;
    dN[2][0] = 0, dN[2][1] = 4 * l2 - 1;
    dN[3][0] = 4 * (l0 - l1), dN[3][1] = -4 * l1;
    dN[4][0] = 4 * l2, dN[4][1] = 4 * l1;
    dN[5][0] = -4 * l2, dN[5][1] = 4 * (l0 - l2);
    return 6;
  }
  /* tensor product of the 1-D quadratics at -1, 1, 0 (index 0, 1, 2) */
  static const int ij[9][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {1, 2}, {2, 1}, {0, 2}, {2, 2}};
  double l[2][3], dl[2][3];
  for (int a = 0; a < 2; ++a) {
    double s = xi[a];
    l[a][0] = 0.5 * s * (s - 1), l[a][1] = 0.5 * s * (s + 1), l[a][2] = 1 - s * s;
    dl[a][0] = s - 0.5, dl[a][1] = s + 0.5, dl[a][2] = -2 * s;
  }
  for (int k = 0; k < 9; ++k) {
    dN[k][0] = dl[0][ij[k][0]] * l[1][ij[k][1]];
    dN[k][1] = l[0][ij[k][0]] * dl[1][ij[k][1]];
  }
  return 9;
}

static double det_at(sl_cell_type t, double (*x)[2], const double xi[2]) {
  double dN[9][2], J[2][2] = {{0, 0}, {0, 0}};
  int n = quadratic_gradients(t, xi, dN);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) J[i][j] += x[k][i] * dN[k][j];
  return J[0][0] * J[1][1] - J[0][1] * J[1][0];
}

/* Points where det J is checked: the nodes, and the 3 x 3 Gauss points
 * (quads) or the 7 points of the degree-5 triangle rule's layout. */
static int check_points(sl_cell_type t, double (*xi)[2]) {
  int n = 0;
  if (t == SL_CELL_TRI3) {
    static const double p[][2] = {{0, 0},      {1, 0},           {0, 1},     {0.5, 0},   {0.5, 0.5},
                                  {0, 0.5},    {1. / 3, 1. / 3}, {0.1, 0.1}, {0.8, 0.1}, {0.1, 0.8},
                                  {0.45, 0.1}, {0.45, 0.45},     {0.1, 0.45}};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; ++k) xi[n][0] = p[k][0], xi[n][1] = p[k][1], ++n;
    return n;
  }
  static const double s[] = {-1, -0.7745966692414834, 0, 0.7745966692414834, 1};
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) xi[n][0] = s[a], xi[n][1] = s[b], ++n;
  return n;
}

int sl_mesh_check_curved(const sl_mesh *m, const char *source, const int *cell_line, sl_diag *d) {
  if (m->geom_order < 2) return 0;
  double xi[32][2];
  int np = check_points(m->cell_type, xi);
  for (int c = 0; c < m->n_cells; ++c) {
    double x[9][2];
    int n = sl_mesh_cell_nodes(m, c, x);
    /* the scale of det J: the straight cell's area (twice, for triangles in the reference (0,1) square) */
    double a = fabs(sl_mesh_cell_area(m, c)) * (m->cell_type == SL_CELL_TRI3 ? 2.0 : 0.25);
    for (int q = 0; q < np; ++q) {
      double det = det_at(m->cell_type, x, xi[q]);
      if (det > 1e-8 * a) continue;
      char at[600], nodes[700];
      size_t used = 0;
      nodes[0] = '\0';
      for (int k = 0; k < n && used < sizeof nodes; ++k) {
        int w = snprintf(nodes + used, sizeof nodes - used, "%s(%.10g, %.10g)", k ? ", " : "", x[k][0], x[k][1]);
        if (w < 0) break;
        used += (size_t)w;
      }
      if (source && cell_line) snprintf(at, sizeof at, "%s:%d: ", source, cell_line[c]);
      else if (source) snprintf(at, sizeof at, "%s: ", source);
      else at[0] = '\0';
      return sl_diag_set(d, SL_EBADINPUT,
                         "%scell %d folds under its second-order map: det J = %.3g at the reference point (%g, %g) "
                         "(its face nodes lie too far from the straight edges for its size; refine the mesh near "
                         "the curved boundary): nodes %s",
                         at, c, det, xi[q][0], xi[q][1], nodes);
    }
  }
  return 0;
}

void sl_mesh_face_point(const sl_mesh *m, int f, double s, double x[2], double t[2]) {
  const double *a = m->xy + 2 * (size_t)m->face_vertices[2 * f], *b = m->xy + 2 * (size_t)m->face_vertices[2 * f + 1];
  if (m->geom_order < 2) {
    for (int i = 0; i < 2; ++i) {
      x[i] = a[i] + s * (b[i] - a[i]);
      if (t) t[i] = b[i] - a[i];
    }
    return;
  }
  /* the quadratic through a (s = 0), the face node (s = 1/2) and b (s = 1) */
  const double *c = m->face_mid + 2 * (size_t)f;
  double na = (1 - s) * (1 - 2 * s), nc = 4 * s * (1 - s), nb = s * (2 * s - 1);
  double da = 4 * s - 3, dc = 4 - 8 * s, db = 4 * s - 1;
  for (int i = 0; i < 2; ++i) {
    x[i] = na * a[i] + nc * c[i] + nb * b[i];
    if (t) t[i] = da * a[i] + dc * c[i] + db * b[i];
  }
}

double sl_mesh_face_arc_length(const sl_mesh *m, int f) {
  if (m->dim == 1 || m->geom_order < 2) return sl_mesh_face_length(m, f);
  /* Gauss-Legendre, 5 points on [0, 1] */
  static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
  double len = 0;
  for (int q = 0; q < 5; ++q) {
    double x[2], t[2];
    sl_mesh_face_point(m, f, 0.5 * (1 + gx[q]), x, t);
    len += 0.5 * gw[q] * hypot(t[0], t[1]);
  }
  return len;
}

double sl_mesh_cell_curved_area(const sl_mesh *m, int c) {
  if (m->dim == 1 || m->geom_order < 2) return sl_mesh_cell_area(m, c);
  double x[9][2];
  sl_mesh_cell_nodes(m, c, x);
  double area = 0;
  if (m->cell_type == SL_CELL_TRI3) {
    /* det J of the P2 map is quadratic: the 3-point rule at the edge midpoints is exact (Strang & Fix 1973) */
    static const double p[3][2] = {{0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    for (int q = 0; q < 3; ++q) area += det_at(m->cell_type, x, p[q]) / 6.0;
    return area;
  }
  /* det J of the Q2 map has degree 3 in each variable: 2 x 2 Gauss is exact */
  const double g = 0.5773502691896258;
  for (int a = -1; a <= 1; a += 2)
    for (int b = -1; b <= 1; b += 2) area += det_at(m->cell_type, x, (const double[2]){a * g, b * g});
  return area;
}
