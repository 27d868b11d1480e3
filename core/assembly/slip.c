/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Free slip on boundaries of any shape (slip.h). */
#include "core/assembly/slip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/fe/geometry.h"
#include "core/fe/quadrature.h"

#define FACE_POINTS 3 /* Gauss points along a face: exact for phi n w ds (degree 5 at most, second-order geometry) */

/* The trace of a P2/Q2 velocity on a face at s in [0, 1]: the basis of its nodes at s = 0, 1/2, 1
 * (Lagrange on the reference edge). */
static void face_basis(double s, double phi[3]) {
  phi[0] = (1.0 - s) * (1.0 - 2.0 * s), phi[1] = 4.0 * s * (1.0 - s), phi[2] = s * (2.0 * s - 1.0);
}

/* The dofs of the three velocity nodes of boundary face f (s = 0, 1/2, 1), its cell and local index. */
static void face_nodes(const sl_th_space *th, int f, int32_t node[3], int *cell, int *local) {
  const sl_mesh *m = th->mesh;
  int c = m->face_cells[2 * f], k = m->face_local[2 * f], nv = m->nv_per_cell, nb = th->vel->dofs_per_cell;
  const int32_t *cd = th->vel->cell_dofs + (size_t)c * nb;
  node[0] = cd[k], node[1] = cd[nv + k], node[2] = cd[(k + 1) % nv];
  *cell = c, *local = k;
}

void sl_slip_free(sl_slip *s) {
  free(s->row_n), free(s->row_t), free(s->dof_x), free(s->dof_y), free(s->normal), free(s->tangent);
  memset(s, 0, sizeof *s);
}

int sl_slip_create(sl_slip *s, const sl_th_space *th, const int *slip_ids, int n_slip, const int *other_ids,
                   int n_other, int axisymmetric, sl_constraints *bc, sl_diag *d) {
  memset(s, 0, sizeof *s);
  const sl_mesh *m = th->mesh;
  if (m->dim != 2 || th->n_comp < 2)
    return sl_diag_set(d, SL_EBADINPUT, "slip: a curved slip wall needs a 2-D mesh and two in-plane components");
  int32_t nvel = th->n_vel;
  sl_quadrature g;
  int rc = sl_quadrature_gauss_line(FACE_POINTS, &g, d);
  if (rc) return rc;
  /* per velocity dof: int phi n w ds, int phi n ds (the fallback where w = r vanishes), the first face normal
     seen there and the smallest cosine of another face's normal with it, and whether the node is on the wall */
  double *acc = calloc((size_t)4 * nvel + 1, sizeof *acc), *first = calloc((size_t)2 * nvel + 1, sizeof *first);
  double *cmin = malloc(((size_t)nvel + 1) * sizeof *cmin);
  unsigned char *on = calloc((size_t)nvel + 1, 1), *seen = calloc((size_t)nvel + 1, 1);
  if (!acc || !first || !cmin || !on || !seen) {
    rc = sl_diag_set(d, SL_ENOMEM, "slip: out of memory");
    goto out;
  }
  for (int32_t i = 0; i < nvel; ++i) cmin[i] = 1.0;
  for (int set = 0; set < 2; ++set) {
    const int *ids = set == 0 ? slip_ids : other_ids;
    int n_ids = set == 0 ? n_slip : n_other;
    for (int b = 0; b < n_ids; ++b)
      for (int k = m->bface_start[ids[b]]; k < m->bface_start[ids[b] + 1]; ++k) {
        int f = m->bface[k], c, lf;
        int32_t node[3];
        face_nodes(th, f, node, &c, &lf);
        for (int j = 0; j < 3; ++j) { /* the corner test: the face's normal at each of its nodes */
          double n[2];
          sl_fe_face_point(m, c, lf, 0.5 * j, NULL, NULL, n, NULL);
          int32_t i = node[j];
          if (!seen[i]) seen[i] = 1, first[2 * i] = n[0], first[2 * i + 1] = n[1];
          else cmin[i] = fmin(cmin[i], n[0] * first[2 * i] + n[1] * first[2 * i + 1]);
          if (set == 0) on[i] = 1;
        }
        if (set) continue;
        for (int q = 0; q < FACE_POINTS; ++q) {
          double sq = 0.5 * (1.0 + g.xi[q][0]), x[2], n[2], ds, phi[3];
          sl_fe_face_point(m, c, lf, sq, NULL, x, n, &ds);
          face_basis(sq, phi);
          double w = 0.5 * g.w[q] * ds, wr = axisymmetric ? w * x[0] : w;
          for (int j = 0; j < 3; ++j)
            for (int a = 0; a < 2; ++a)
              acc[4 * node[j] + a] += wr * phi[j] * n[a], acc[4 * node[j] + 2 + a] += w * phi[j] * n[a];
        }
      }
  }
  int32_t cap = 0;
  for (int32_t i = 0; i < nvel; ++i) cap += on[i];
  s->row_n = malloc(((size_t)cap + 1) * sizeof *s->row_n), s->row_t = malloc(((size_t)cap + 1) * sizeof *s->row_t);
  s->dof_x = malloc(((size_t)cap + 1) * sizeof *s->dof_x), s->dof_y = malloc(((size_t)cap + 1) * sizeof *s->dof_y);
  s->normal = malloc(((size_t)2 * cap + 1) * sizeof *s->normal);
  s->tangent = malloc(((size_t)2 * cap + 1) * sizeof *s->tangent);
  if (!s->row_n || !s->row_t || !s->dof_x || !s->dof_y || !s->normal || !s->tangent) {
    rc = sl_diag_set(d, SL_ENOMEM, "slip: out of memory");
    goto out;
  }
  const double corner = cos(SL_SLIP_CORNER_DEGREES * M_PI / 180.0);
  for (int32_t i = 0; i < nvel; ++i) {
    if (!on[i]) continue;
    int32_t ix = sl_th_vel_dof(th, 0, i), iy = sl_th_vel_dof(th, 1, i);
    int fixed = bc->fixed[ix] + bc->fixed[iy];
    if (fixed == 2) continue; /* a wall or inflow wins */
    if (cmin[i] < corner) {   /* no flow through two faces that meet at an angle: u = 0 */
      if (!bc->fixed[ix]) sl_constraints_fix(bc, ix, 0.0);
      if (!bc->fixed[iy]) sl_constraints_fix(bc, iy, 0.0);
      ++s->n_corners;
      continue;
    }
    if (fixed) continue; /* a smooth join with a straight slip wall or the axis: that condition stays */
    double *a = acc + 4 * i;
    double len = hypot(a[0], a[1]), nx, ny;
    if (len > 1e-12 * hypot(a[2], a[3])) nx = a[0] / len, ny = a[1] / len;
    else len = hypot(a[2], a[3]), nx = a[2] / len, ny = a[3] / len; /* on the axis, r = 0 */
    int32_t k = s->n++;
    int along_x = fabs(nx) >= fabs(ny);
    s->dof_x[k] = ix, s->dof_y[k] = iy;
    s->row_n[k] = along_x ? ix : iy, s->row_t[k] = along_x ? iy : ix;
    double tx = -ny, ty = nx, sg = (along_x ? ty : tx) < 0.0 ? -1.0 : 1.0;
    s->normal[2 * k] = nx, s->normal[2 * k + 1] = ny;
    s->tangent[2 * k] = sg * tx, s->tangent[2 * k + 1] = sg * ty;
  }
out:
  free(acc), free(first), free(cmin), free(on), free(seen);
  if (rc) sl_slip_free(s);
  return rc;
}

void sl_slip_impose(const sl_slip *s, double *u) {
  for (int32_t k = 0; k < s->n; ++k) {
    const double *n = s->normal + 2 * k;
    double un = u[s->dof_x[k]] * n[0] + u[s->dof_y[k]] * n[1];
    u[s->dof_x[k]] -= un * n[0], u[s->dof_y[k]] -= un * n[1];
  }
}

int sl_slip_rows(const sl_slip *s, sl_csr *A, double *b, sl_diag *d) {
  if (A && A->rows)
    return sl_diag_set(d, SL_EBADINPUT, "slip: a curved slip wall is not supported on a distributed matrix");
  for (int32_t k = 0; k < s->n; ++k) {
    int32_t rx = s->dof_x[k], ry = s->dof_y[k];
    const double *n = s->normal + 2 * k, *t = s->tangent + 2 * k;
    int t_is_x = s->row_t[k] == rx;
    if (A) {
      int32_t px = A->row_ptr[rx], py = A->row_ptr[ry], len = A->row_ptr[rx + 1] - px;
      if (A->row_ptr[ry + 1] - py != len)
        return sl_diag_set(d, SL_EFAILED, "slip: the rows of dofs %d and %d differ in pattern", (int)rx, (int)ry);
      /* the constraint row with a positive diagonal, scaled as the momentum row it replaces (its diagonal's
         size), so that a solver's pivoting sees rows of one scale */
      double sg = (t_is_x ? n[1] : n[0]) < 0.0 ? -1.0 : 1.0, scale = 0.0;
      int32_t rn = s->row_n[k], pn = A->row_ptr[rn];
      for (int32_t p = 0; p < len; ++p)
        if (A->col_idx[pn + p] == rn) scale = fabs(A->values[pn + p]);
      if (!(scale > 0.0) || !isfinite(scale)) scale = 1.0;
      sg *= scale;
      for (int32_t p = 0; p < len; ++p) {
        int32_t col = A->col_idx[px + p];
        if (A->col_idx[py + p] != col)
          return sl_diag_set(d, SL_EFAILED, "slip: the rows of dofs %d and %d differ in pattern", (int)rx, (int)ry);
        double vt = t[0] * A->values[px + p] + t[1] * A->values[py + p];
        double vn = col == rx ? sg * n[0] : col == ry ? sg * n[1] : 0.0;
        A->values[px + p] = t_is_x ? vt : vn;
        A->values[py + p] = t_is_x ? vn : vt;
      }
    }
    double bt = t[0] * b[rx] + t[1] * b[ry];
    b[s->row_t[k]] = bt, b[s->row_n[k]] = 0.0;
  }
  if (A && s->n) ++A->values_gen;
  return 0;
}

void sl_slip_zero_normal(const sl_slip *s, double *b) {
  for (int32_t k = 0; k < s->n; ++k) b[s->row_n[k]] = 0.0;
}

void sl_slip_flux(const sl_th_space *th, const int *slip_ids, int n_slip, int axisymmetric, const double *u,
                  double *flux, double *scale) {
  const sl_mesh *m = th->mesh;
  sl_quadrature g;
  sl_diag quiet;
  *flux = *scale = 0.0;
  if (m->dim != 2 || th->n_comp < 2 || sl_quadrature_gauss_line(FACE_POINTS, &g, &quiet)) return;
  for (int b = 0; b < n_slip; ++b)
    for (int k = m->bface_start[slip_ids[b]]; k < m->bface_start[slip_ids[b] + 1]; ++k) {
      int c, lf;
      int32_t node[3];
      face_nodes(th, m->bface[k], node, &c, &lf);
      for (int q = 0; q < FACE_POINTS; ++q) {
        double sq = 0.5 * (1.0 + g.xi[q][0]), x[2], n[2], ds, phi[3], v[2] = {0.0, 0.0};
        sl_fe_face_point(m, c, lf, sq, NULL, x, n, &ds);
        face_basis(sq, phi);
        for (int j = 0; j < 3; ++j)
          for (int a = 0; a < 2; ++a) v[a] += phi[j] * u[sl_th_vel_dof(th, a, node[j])];
        double w = 0.5 * g.w[q] * ds * (axisymmetric ? x[0] : 1.0);
        *flux += w * (v[0] * n[0] + v[1] * n[1]), *scale += w * hypot(v[0], v[1]);
      }
    }
}
