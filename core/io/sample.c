/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Point sampling of output fields: locate each point in the output mesh,
 * then interpolate with the cell's own Lagrange basis (see sample.h).
 * Second-order cells (Edge_3, Triangle_6, Quadrilateral_9) are
 * isoparametric: their geometry is the map of all their nodes, so a cell
 * whose mid-edge nodes lie off the chords (a curved wall) is curved, and a
 * point is located in it by Newton's method on that map. */
#include "core/io/sample.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/fe/element.h"

/* XDMF topology -> reference cell and polynomial order of the node fields. */
static const struct {
  const char *name;
  sl_cell_type cell;
  int order;
} topologies[] = {
    {"Polyline", SL_CELL_LINE2, 1},  {"Edge_3", SL_CELL_LINE2, 2},        {"Triangle", SL_CELL_TRI3, 1},
    {"Triangle_6", SL_CELL_TRI3, 2}, {"Quadrilateral", SL_CELL_QUAD4, 1}, {"Quadrilateral_9", SL_CELL_QUAD4, 2},
};

/* Same tolerance as sl_fe_locate: a point on a face belongs to both cells. */
#define INSIDE_TOL 1e-10

/* Cells binned on a uniform grid by their bounding boxes, so a point is
 * tried against the few cells of its bin, not the whole mesh. */
typedef struct locator {
  const sl_output_mesh *m;
  const sl_element *geo; /* the geometry map: the node fields' basis (isoparametric) */
  const sl_element *fe;  /* the node fields' basis */
  int dim, nv;           /* mesh dimension (1 or 2), corners per cell */
  int ng;                /* nodes of the geometry map per cell */
  double lo[2], hi[2];   /* box of all cells (slightly enlarged) */
  double h[2];           /* bin sizes */
  int nb[2];             /* bins per direction */
  size_t *start;         /* cells of bin b: cells[start[b] .. start[b + 1] - 1] */
  int *cells;
} locator;

static const double *corner(const locator *L, int c, int k) {
  return L->m->coords + 3 * (size_t)L->m->cells[(size_t)c * L->m->nodes_per_cell + k];
}

/* The reference node of the geometry at (a, b), or -1. */
static int ref_node(const locator *L, double a, double b) {
  for (int k = 0; k < L->ng; ++k)
    if (L->geo->nodes[k][0] == a && L->geo->nodes[k][1] == b) return k;
  return -1;
}

/* The Bezier (Bernstein) control point of the quadratic edge through corners
 * a, b and its mid node m: 2 m - (a + b) / 2. The curve lies in the convex
 * hull of a, it and b (Farin 2002, ch. 3). */
static void edge_control(const locator *L, int c, int m, double out[2]) {
  const double *xm = corner(L, c, m);
  const double *ref = L->geo->nodes[m];
  for (int a = 0; a < L->nv; ++a)
    for (int b = a + 1; b < L->nv; ++b) {
      const double *ra = L->geo->nodes[a], *rb = L->geo->nodes[b];
      if (0.5 * (ra[0] + rb[0]) != ref[0] || 0.5 * (ra[1] + rb[1]) != ref[1]) continue;
      const double *xa = corner(L, c, a), *xb = corner(L, c, b);
      for (int i = 0; i < 2; ++i) out[i] = 2.0 * xm[i] - 0.5 * (xa[i] + xb[i]);
      return;
    }
  out[0] = xm[0], out[1] = xm[1];
}

/* Box of cell c, enlarged so that points the inside test accepts are in it:
 * the box of the control points of the map in Bernstein form, which holds
 * the whole (curved) cell. */
static void cell_box(const locator *L, int c, double lo[2], double hi[2]) {
  lo[0] = lo[1] = INFINITY, hi[0] = hi[1] = -INFINITY;
  for (int k = 0; k < L->ng; ++k) {
    double p[2];
    const double *x = corner(L, c, k);
    p[0] = x[0], p[1] = L->dim == 2 ? x[1] : 0.0;
    if (k >= L->nv) {
      const double *r = L->geo->nodes[k];
      if (L->geo->cell == SL_CELL_QUAD4 && r[0] == 0.0 && r[1] == 0.0) {
        /* the centre of Q9: tensor product of the edge conversions,
         * 4 x_11 - x_01 - x_21 - (b_10 + b_12) / 2 */
        int w = ref_node(L, -1, 0), e = ref_node(L, 1, 0), s = ref_node(L, 0, -1), n = ref_node(L, 0, 1);
        if (w >= 0 && e >= 0 && s >= 0 && n >= 0) {
          double bs[2], bn[2];
          edge_control(L, c, s, bs), edge_control(L, c, n, bn);
          const double *xw = corner(L, c, w), *xe = corner(L, c, e);
          for (int i = 0; i < L->dim; ++i) p[i] = 4.0 * x[i] - xw[i] - xe[i] - 0.5 * (bs[i] + bn[i]);
        }
      } else {
        double q[2];
        edge_control(L, c, k, q);
        p[0] = q[0], p[1] = L->dim == 2 ? q[1] : 0.0;
      }
      /* the node itself lies on the cell too */
      for (int i = 0; i < L->dim; ++i) lo[i] = fmin(lo[i], x[i]), hi[i] = fmax(hi[i], x[i]);
    }
    for (int i = 0; i < L->dim; ++i) lo[i] = fmin(lo[i], p[i]), hi[i] = fmax(hi[i], p[i]);
  }
  double ext = hi[0] - lo[0];
  if (L->dim == 2) ext = fmax(ext, hi[1] - lo[1]);
  double e = 1e-8 * ext + 1e-300;
  for (int i = 0; i < L->dim; ++i) lo[i] -= e, hi[i] += e;
  if (L->dim == 1) lo[1] = hi[1] = 0.0;
}

static int bin_of(const locator *L, int i, double x) {
  double b = floor((x - L->lo[i]) / L->h[i]);
  return b < 0 ? 0 : b >= L->nb[i] ? L->nb[i] - 1 : (int)b;
}

static void locator_free(locator *L) {
  free(L->start);
  free(L->cells);
  L->start = NULL;
  L->cells = NULL;
}

static int locator_build(locator *L, const sl_output_mesh *m, const char *path, sl_diag *d) {
  memset(L, 0, sizeof *L);
  L->m = m;
  int t = -1;
  for (int i = 0; i < (int)(sizeof topologies / sizeof topologies[0]); ++i)
    if (strcmp(m->topology, topologies[i].name) == 0) t = i;
  if (t < 0) return sl_diag_set(d, SL_EBADINPUT, "%s: cannot sample a mesh of topology '%s'", path, m->topology);
  L->geo = sl_element_lagrange(topologies[t].cell, topologies[t].order);
  L->fe = L->geo;
  L->dim = L->geo->dim;
  L->nv = sl_element_lagrange(topologies[t].cell, 1)->n_basis;
  L->ng = L->geo->n_basis;
  if (m->nodes_per_cell != L->fe->n_basis)
    return sl_diag_set(d, SL_EBADINPUT, "%s: topology %s has %d nodes per cell, the file has %d", path, m->topology,
                       L->fe->n_basis, m->nodes_per_cell);
  if (m->dim != L->dim)
    return sl_diag_set(d, SL_EBADINPUT, "%s: cannot sample %s cells in a %d-D mesh (only %d-D)", path, m->topology,
                       m->dim, L->dim);
  if (m->n_cells < 1 || m->n_vertices < 1) return sl_diag_set(d, SL_EBADINPUT, "%s: the mesh is empty", path);
  for (size_t k = 0; k < (size_t)m->n_cells * (size_t)m->nodes_per_cell; ++k)
    if (m->cells[k] < 0 || m->cells[k] >= m->n_vertices)
      return sl_diag_set(d, SL_EBADINPUT, "%s: cell %zu refers to node %d, outside [0, %d)", path,
                         k / (size_t)m->nodes_per_cell, (int)m->cells[k], (int)m->n_vertices);

  L->lo[0] = L->lo[1] = INFINITY, L->hi[0] = L->hi[1] = -INFINITY;
  for (int c = 0; c < m->n_cells; ++c) {
    double lo[2], hi[2];
    cell_box(L, c, lo, hi);
    for (int i = 0; i < 2; ++i) L->lo[i] = fmin(L->lo[i], lo[i]), L->hi[i] = fmax(L->hi[i], hi[i]);
  }
  if (!isfinite(L->lo[0] + L->hi[0] + L->lo[1] + L->hi[1]))
    return sl_diag_set(d, SL_EBADINPUT, "%s: the mesh has non-finite coordinates", path);
  /* About one cell per bin, the bins as square as the box allows. */
  double w = L->hi[0] - L->lo[0], hgt = L->hi[1] - L->lo[1], n = m->n_cells;
  double bx = L->dim == 1 ? n : sqrt(n * w / hgt);
  L->nb[0] = bx < 1 ? 1 : bx > n ? (int)n : (int)ceil(bx);
  double by = L->dim == 1 ? 1 : ceil(n / L->nb[0]);
  L->nb[1] = by < 1 ? 1 : by > n ? (int)n : (int)by;
  L->h[0] = w / L->nb[0];
  L->h[1] = L->dim == 1 ? 1.0 : hgt / L->nb[1];

  size_t n_bins = (size_t)L->nb[0] * (size_t)L->nb[1];
  L->start = calloc(n_bins + 1, sizeof *L->start);
  if (!L->start) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory for the point locator", path);
  /* Two passes: count the cells of each bin, then fill. */
  for (int pass = 0; pass < 2; ++pass) {
    for (int c = 0; c < m->n_cells; ++c) {
      double lo[2], hi[2];
      cell_box(L, c, lo, hi);
      int i0 = bin_of(L, 0, lo[0]), i1 = bin_of(L, 0, hi[0]), j0 = bin_of(L, 1, lo[1]), j1 = bin_of(L, 1, hi[1]);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          size_t b = (size_t)j * (size_t)L->nb[0] + (size_t)i;
          if (pass == 0) ++L->start[b + 1];
          else L->cells[L->start[b]++] = c;
        }
    }
    if (pass == 0) {
      for (size_t b = 0; b < n_bins; ++b) L->start[b + 1] += L->start[b];
      L->cells = malloc((L->start[n_bins] + 1) * sizeof *L->cells);
      if (!L->cells) {
        locator_free(L);
        return sl_diag_set(d, SL_ENOMEM, "%s: out of memory for the point locator", path);
      }
    }
  }
  /* The fill pass advanced each start to the next bin's: shift back. */
  for (size_t b = n_bins; b > 0; --b) L->start[b] = L->start[b - 1];
  L->start[0] = 0;
  return 0;
}

/* Reference coordinates of x in cell c by Newton's method on the geometry
 * map (one step for affine cells; a few for bilinear and curved ones); 1
 * when x lies in the cell. */
static int try_cell(const locator *L, int c, const double x[2], double xi[2]) {
  double X[SL_ELEMENT_MAX_BASIS][2];
  for (int k = 0; k < L->ng; ++k) {
    const double *p = corner(L, c, k);
    X[k][0] = p[0], X[k][1] = L->dim == 2 ? p[1] : 0.0;
  }
  xi[0] = xi[1] = L->geo->cell == SL_CELL_TRI3 ? 1.0 / 3.0 : 0.0;
  int converged = 0;
  for (int it = 0; it < 50 && !converged; ++it) {
    double N[SL_ELEMENT_MAX_BASIS], dN[SL_ELEMENT_MAX_BASIS][2], r[2] = {-x[0], L->dim == 2 ? -x[1] : 0.0};
    double J[2][2] = {{0, 0}, {0, 0}};
    L->geo->eval(xi, N, dN);
    for (int k = 0; k < L->ng; ++k)
      for (int i = 0; i < 2; ++i) {
        r[i] += N[k] * X[k][i];
        for (int j = 0; j < 2; ++j) J[i][j] += X[k][i] * dN[k][j];
      }
    double dxi, deta = 0.0;
    if (L->dim == 1) {
      dxi = r[0] / J[0][0];
    } else {
      double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
      dxi = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
      deta = (-J[1][0] * r[0] + J[0][0] * r[1]) / det;
    }
    if (!isfinite(dxi) || !isfinite(deta)) return 0;
    xi[0] -= dxi, xi[1] -= deta;
    if (fabs(xi[0]) + fabs(xi[1]) > 10.0) return 0; /* far outside: Newton on a curved map may wander */
    converged = fabs(dxi) + fabs(deta) < 1e-13;
  }
  if (!converged) return 0; /* far outside a bilinear cell Newton may wander */
  const double e = INSIDE_TOL;
  switch (L->geo->cell) {
    case SL_CELL_LINE2:
      return fabs(xi[0]) <= 1.0 + e;
    case SL_CELL_TRI3:
      return xi[0] >= -e && xi[1] >= -e && xi[0] + xi[1] <= 1.0 + e;
    case SL_CELL_QUAD4:
      return fabs(xi[0]) <= 1.0 + e && fabs(xi[1]) <= 1.0 + e;
  }
  return 0;
}

/* The cell holding x (trying *hint first, then updating it), or -1. */
static int locate(const locator *L, const double x[2], int *hint, double xi[2]) {
  double p[2] = {x[0], L->dim == 2 ? x[1] : 0.0};
  if (!isfinite(p[0]) || !isfinite(p[1])) return -1;
  for (int i = 0; i < L->dim; ++i)
    if (p[i] < L->lo[i] || p[i] > L->hi[i]) return -1;
  if (*hint >= 0 && try_cell(L, *hint, p, xi)) return *hint;
  size_t b = (size_t)bin_of(L, 1, p[1]) * L->nb[0] + bin_of(L, 0, p[0]);
  for (size_t k = L->start[b]; k < L->start[b + 1]; ++k) {
    int c = L->cells[k];
    if (c != *hint && try_cell(L, c, p, xi)) return *hint = c;
  }
  return -1;
}

static void evaluate(const locator *L, const sl_output_field *f, int c, const double xi[2], double *out) {
  const int nc = f->components;
  if (f->centring == SL_CENTRE_CELL) {
    for (int k = 0; k < nc; ++k) out[k] = f->values[(size_t)c * nc + k];
    return;
  }
  double phi[SL_ELEMENT_MAX_BASIS];
  L->fe->eval(xi, phi, NULL);
  const int32_t *nodes = L->m->cells + (size_t)c * L->m->nodes_per_cell;
  for (int k = 0; k < nc; ++k) {
    double v = 0.0;
    for (int b = 0; b < L->fe->n_basis; ++b) v += phi[b] * f->values[(size_t)nodes[b] * nc + k];
    out[k] = v;
  }
}

/* A finite t must lie within the output times (to rounding). */
static int check_time(const char *path, const char *field, double t, const double *times, int n,
                      const sl_output_field *f, sl_diag *d) {
  double t0 = INFINITY, t1 = -INFINITY;
  for (int i = 0; i < n; ++i) t0 = fmin(t0, times[i]), t1 = fmax(t1, times[i]);
  double tol = 1e-9 * fmax(t1 - t0, fmax(fabs(t0), fabs(t1)));
  if (t >= t0 - tol && t <= t1 + tol) return 0;
  return sl_diag_set(d, SL_EBADINPUT,
                     "%s: time %.10g is outside the output times [%.10g, %.10g] (%d step%s); the nearest output of "
                     "'%s' is t = %.10g (step %d)",
                     path, t, t0, t1, n, n == 1 ? "" : "s", field, f->time, f->step);
}

int sl_sample_points(const char *path, const char *field, double t, int n_points, const double *xy, sl_sample *s,
                     sl_diag *d) {
  memset(s, 0, sizeof *s);
  if (n_points < 0 || (n_points > 0 && !xy)) return sl_diag_set(d, SL_EBADINPUT, "%s: no points to sample", path);
  if (isnan(t)) return sl_diag_set(d, SL_EBADINPUT, "%s: requested time is NaN", path);
  int n_steps = 0;
  double *times = NULL;
  sl_output_field f;
  sl_output_mesh m;
  locator L;
  memset(&f, 0, sizeof f);
  memset(&m, 0, sizeof m);
  memset(&L, 0, sizeof L);
  int rc = sl_output_read_times(path, &n_steps, &times, d);
  if (!rc) rc = sl_output_read_field(path, field, t, &f, d);
  if (!rc && isfinite(t)) rc = check_time(path, field, t, times, n_steps, &f, d);
  if (!rc) rc = sl_output_read_mesh(path, &m, d);
  if (!rc) rc = locator_build(&L, &m, path, d);
  if (!rc) {
    int32_t want = f.centring == SL_CENTRE_NODE ? m.n_vertices : m.n_cells;
    if (f.n != want || f.components < 1)
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' at step %d has %d values of %d components; the mesh has %d %s",
                       path, field, f.step, (int)f.n, f.components, (int)want,
                       f.centring == SL_CENTRE_NODE ? "nodes" : "cells");
  }
  if (!rc) {
    s->values = malloc(((size_t)n_points * (size_t)f.components + 1) * sizeof *s->values);
    if (!s->values) rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory for %d sample points", path, n_points);
  }
  if (!rc) {
    s->step = f.step;
    s->time = f.time;
    s->centring = f.centring;
    s->dim = L.dim;
    s->components = f.components;
    s->n_points = n_points;
    int hint = -1; /* consecutive points (a line) mostly share a cell */
    for (int i = 0; i < n_points; ++i) {
      double xi[2], *out = s->values + (size_t)i * f.components;
      int c = locate(&L, xy + 2 * (size_t)i, &hint, xi);
      if (c >= 0) {
        evaluate(&L, &f, c, xi, out);
      } else {
        for (int k = 0; k < f.components; ++k) out[k] = NAN;
        ++s->n_outside;
      }
    }
  }
  locator_free(&L);
  sl_output_mesh_free(&m);
  sl_output_field_free(&f);
  free(times);
  if (rc) sl_sample_free(s);
  return rc;
}

void sl_sample_free(sl_sample *s) {
  if (!s) return;
  free(s->values);
  memset(s, 0, sizeof *s);
}
