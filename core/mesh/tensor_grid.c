/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The tensor-product structure of an axis-aligned quad mesh (tensor_grid.h). */
#include "core/mesh/tensor_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The distinct values of v[0..n) (stride 2) within tol, sorted, into *out. */
static int grid_lines(const double *xy, int n, double tol, double **out, int *count) {
  double *v = malloc((size_t)n * sizeof *v);
  if (!v) return -1;
  for (int k = 0; k < n; ++k) v[k] = xy[2 * k];
  qsort(v, (size_t)n, sizeof *v, cmp_double);
  int m = 0;
  for (int k = 0; k < n; ++k)
    if (m == 0 || v[k] - v[m - 1] > tol) v[m++] = v[k];
  *out = v, *count = m;
  return 0;
}

/* The index of the grid line x within tol, or -1. */
static int line_index(const double *lines, int n, double x, double tol) {
  int lo = 0, hi = n - 1;
  while (lo <= hi) {
    int mid = (lo + hi) / 2;
    if (fabs(lines[mid] - x) <= tol) return mid;
    if (lines[mid] < x) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

int sl_tensor_grid_from_mesh(const sl_mesh *m, sl_tensor_grid *g, sl_diag *d) {
  memset(g, 0, sizeof *g);
  if (m->dim != 2 || m->cell_type != SL_CELL_QUAD4)
    return sl_diag_set(d, SL_EBADINPUT, "the staggered grid needs a 2-D mesh of quadrilaterals (cell_type = quad)");
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < m->n_vertices; ++v)
    for (int a = 0; a < 2; ++a) lo[a] = fmin(lo[a], m->xy[2 * v + a]), hi[a] = fmax(hi[a], m->xy[2 * v + a]);
  const double tol = 1e-9 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
  double *xs = NULL, *ys = NULL;
  int nxl = 0, nyl = 0;
  if (grid_lines(m->xy, m->n_vertices, tol, &xs, &nxl) || grid_lines(m->xy + 1, m->n_vertices, tol, &ys, &nyl)) {
    free(xs);
    return sl_diag_set(d, SL_ENOMEM, "tensor grid: out of memory");
  }
  g->xf = xs, g->yf = ys, g->nx = nxl - 1, g->ny = nyl - 1;
  const int nx = g->nx, ny = g->ny;
  if (nx < 1 || ny < 1 || (long)nx * ny != m->n_cells) {
    int rc = sl_diag_set(d, SL_EBADINPUT,
                         "the staggered grid needs a mesh whose cells fill a rectangle in rows and "
                         "columns: %d cells on %d x %d grid lines",
                         m->n_cells, nxl, nyl);
    sl_tensor_grid_free(g);
    return rc;
  }
  g->mesh_cell = malloc((size_t)m->n_cells * sizeof *g->mesh_cell);
  for (int s = 0; s < 4; ++s) g->side_tag[s] = malloc((size_t)(s < 2 ? ny : nx) * sizeof(int));
  if (!g->mesh_cell || !g->side_tag[0] || !g->side_tag[1] || !g->side_tag[2] || !g->side_tag[3]) {
    sl_tensor_grid_free(g);
    return sl_diag_set(d, SL_ENOMEM, "tensor grid: out of memory");
  }
  for (int c = 0; c < m->n_cells; ++c) g->mesh_cell[c] = -1;
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k < (s < 2 ? ny : nx); ++k) g->side_tag[s][k] = -1;
  for (int c = 0; c < m->n_cells; ++c) {
    /* the cell's corners: two distinct x lines i, i+1 and two y lines j, j+1 */
    int ix[4], iy[4], imin = nxl, jmin = nyl;
    for (int k = 0; k < 4; ++k) {
      const double *p = m->xy + 2 * m->cell_vertices[4 * c + k];
      ix[k] = line_index(xs, nxl, p[0], tol), iy[k] = line_index(ys, nyl, p[1], tol);
      if (ix[k] < imin) imin = ix[k];
      if (iy[k] < jmin) jmin = iy[k];
    }
    int ok = 1, seen = 0;
    for (int k = 0; k < 4; ++k) {
      int a = ix[k] - imin, b = iy[k] - jmin;
      ok = ok && (a == 0 || a == 1) && (b == 0 || b == 1);
      if (ok) seen |= 1 << (a + 2 * b);
    }
    if (!ok || seen != 15 || g->mesh_cell[imin + nx * jmin] >= 0) {
      sl_tensor_grid_free(g);
      return sl_diag_set(d, SL_EBADINPUT,
                         "the staggered grid needs axis-aligned cells in rows and columns: mesh cell "
                         "%d is not one",
                         c);
    }
    g->mesh_cell[imin + nx * jmin] = c;
  }
  for (int f = 0; f < m->n_faces; ++f) {
    if (m->face_cells[2 * f + 1] >= 0) continue;
    const double *a = m->xy + 2 * m->face_vertices[2 * f], *b = m->xy + 2 * m->face_vertices[2 * f + 1];
    double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]);
    int side = fabs(a[0] - b[0]) <= tol ? (fabs(mx - xs[0]) <= tol ? SL_SIDE_LEFT : SL_SIDE_RIGHT)
                                        : (fabs(my - ys[0]) <= tol ? SL_SIDE_BOTTOM : SL_SIDE_TOP);
    const double *lines = side < 2 ? ys : xs;
    int n = side < 2 ? ny : nx, k = 0;
    double along = side < 2 ? fmin(a[1], b[1]) : fmin(a[0], b[0]);
    k = line_index(lines, n + 1, along, tol);
    double across = side < 2 ? mx : my, edge = side == SL_SIDE_LEFT     ? xs[0]
                                               : side == SL_SIDE_RIGHT  ? xs[nx]
                                               : side == SL_SIDE_BOTTOM ? ys[0]
                                                                        : ys[ny];
    if (k < 0 || k >= n || fabs(across - edge) > tol) {
      sl_tensor_grid_free(g);
      return sl_diag_set(d, SL_EBADINPUT,
                         "the staggered grid needs a rectangle without holes: boundary face %d lies "
                         "inside it",
                         f);
    }
    g->side_tag[side][k] = m->face_tag[f];
  }
  return 0;
}

void sl_tensor_grid_free(sl_tensor_grid *g) {
  free(g->xf), free(g->yf), free(g->mesh_cell);
  for (int s = 0; s < 4; ++s) free(g->side_tag[s]);
  memset(g, 0, sizeof *g);
}
