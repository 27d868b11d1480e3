/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Structured generators: interval, rectangle, annulus (r, z box), inclined box. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mesh/mesh.h"

/* Keeps vertex and connectivity counts well inside int. */
#define SL_MESH_MAX_CELLS 100000000L

static int check_grading(const sl_grading *g, int n, const char *dir, sl_diag *d) {
  if (!g || g->kind == SL_GRADE_UNIFORM) return 0;
  if (g->kind != SL_GRADE_GEOMETRIC && g->kind != SL_GRADE_SYMMETRIC)
    return sl_diag_set(d, SL_EBADINPUT, "grading along %s: unknown kind %d", dir, (int)g->kind);
  if (!(g->ratio > 0) || !isfinite(g->ratio))
    return sl_diag_set(d, SL_EBADINPUT, "grading along %s: the ratio must be a positive number (got %g)", dir,
                       g->ratio);
  if (g->ratio != 1 && g->kind == SL_GRADE_GEOMETRIC && n < 2)
    return sl_diag_set(d, SL_EBADINPUT, "grading along %s: a geometric grading needs at least 2 cells (got %d)", dir,
                       n);
  if (g->ratio != 1 && g->kind == SL_GRADE_SYMMETRIC && n < 3)
    return sl_diag_set(d, SL_EBADINPUT, "grading along %s: a symmetric grading needs at least 3 cells (got %d)", dir,
                       n);
  return 0;
}

int sl_mesh_graded_points(double a, double b, int n, const sl_grading *g, double *x, sl_diag *d) {
  if (n < 1) return sl_diag_set(d, SL_EBADINPUT, "need at least one cell (got %d)", n);
  if (!isfinite(a) || !isfinite(b) || !(b > a))
    return sl_diag_set(d, SL_EBADINPUT, "empty or invalid range [%g, %g]", a, b);
  int rc = check_grading(g, n, "the range", d);
  if (rc) return rc;
  sl_grading_kind kind = g && g->ratio != 1 ? g->kind : SL_GRADE_UNIFORM;
  if (kind == SL_GRADE_UNIFORM) {
    for (int i = 0; i <= n; ++i) x[i] = a + (b - a) * ((double)i / n);
  } else {
    /* Relative sizes h_i = q^e(i), e(i) = i (geometric) or min(i, n-1-i)
     * (symmetric); x_i = a + (b - a) S_i / S_n with S_i = sum_{k<i} h_k. */
    int emax = kind == SL_GRADE_GEOMETRIC ? n - 1 : (n - 1) / 2;
    double q = pow(g->ratio, 1.0 / emax);
    double sum = 0;
    x[0] = 0;
    for (int i = 0; i < n; ++i) {
      int e = kind == SL_GRADE_GEOMETRIC ? i : (i < n - 1 - i ? i : n - 1 - i);
      sum += pow(q, e);
      x[i + 1] = sum;
    }
    for (int i = 0; i <= n; ++i) x[i] = a + (b - a) * (x[i] / sum);
    if (kind == SL_GRADE_SYMMETRIC) /* exact mirror symmetry */
      for (int i = 0; i < n - i; ++i) x[n - i] = b - (x[i] - a);
  }
  x[0] = a;
  x[n] = b;
  return 0;
}

int sl_mesh_interval(double a, double b, int n, const sl_grading *g, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  if (n < 1 || n > SL_MESH_MAX_CELLS)
    return sl_diag_set(d, SL_EBADINPUT, "interval: the number of cells must be in 1..%ld (got %d)", SL_MESH_MAX_CELLS,
                       n);
  double *xy = calloc(2 * ((size_t)n + 1), sizeof *xy);
  double *x = malloc(((size_t)n + 1) * sizeof *x);
  int *cells = malloc(2 * (size_t)n * sizeof *cells);
  int rc = 0;
  if (!xy || !x || !cells) {
    rc = sl_diag_set(d, SL_ENOMEM, "interval: out of memory for %d cells", n);
    goto done;
  }
  rc = sl_mesh_graded_points(a, b, n, g, x, d);
  if (rc) {
    sl_diag_prefix(d, rc, "interval");
    goto done;
  }
  for (int i = 0; i <= n; ++i) xy[2 * i] = x[i];
  for (int i = 0; i < n; ++i) {
    cells[2 * i] = i;
    cells[2 * i + 1] = i + 1;
  }
  static const char *const names[] = {"left", "right"};
  const int sides[] = {0, n}, tags[] = {0, 1};
  sl_mesh_spec s = {.dim = 1,
                    .cell_type = SL_CELL_LINE2,
                    .n_vertices = n + 1,
                    .xy = xy,
                    .n_cells = n,
                    .cell_vertices = cells,
                    .n_boundaries = 2,
                    .boundary_names = names,
                    .n_sides = 2,
                    .side_vertices = sides,
                    .side_tag = tags};
  rc = sl_mesh_create(&s, out, d);
done:
  free(xy);
  free(x);
  free(cells);
  return rc;
}

/* The structured grid shared by the 2-D generators: vertex (i, j) is
 * j (nx + 1) + i; boundaries 0..3 are the sides y = y0, x = x1, y = y1,
 * x = x0 with the given names. `rotate` turns the grid by `angle` about
 * (x0, y0). */
static int grid(const char *who, double x0, double x1, double y0, double y1, int nx, int ny, const sl_grid_opts *o,
                const char *const names[4], int rotate, double angle, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  sl_grid_opts def = {.cell_type = SL_CELL_QUAD4};
  if (!o) o = &def;
  sl_cell_type type = o->cell_type == 0 ? SL_CELL_QUAD4 : o->cell_type;
  if (type != SL_CELL_QUAD4 && type != SL_CELL_TRI3)
    return sl_diag_set(d, SL_EBADINPUT, "%s: cells must be quad4 or tri3", who);
  if (type == SL_CELL_TRI3 && (o->diagonal < SL_DIAGONAL_RIGHT || o->diagonal > SL_DIAGONAL_UNION_JACK))
    return sl_diag_set(d, SL_EBADINPUT, "%s: unknown diagonal option %d", who, (int)o->diagonal);
  if (nx < 1 || ny < 1 || (long)nx * ny > SL_MESH_MAX_CELLS / 2)
    return sl_diag_set(d, SL_EBADINPUT, "%s: the cell counts must be at least 1 and nx * ny at most %ld (got %d x %d)",
                       who, SL_MESH_MAX_CELLS / 2, nx, ny);
  if (!isfinite(x0) || !isfinite(x1) || !(x1 > x0) || !isfinite(y0) || !isfinite(y1) || !(y1 > y0))
    return sl_diag_set(d, SL_EBADINPUT, "%s: empty or invalid box [%g, %g] x [%g, %g]", who, x0, x1, y0, y1);

  const int nvx = nx + 1, nvy = ny + 1;
  const size_t nvert = (size_t)nvx * nvy;
  const int per = type == SL_CELL_QUAD4 ? 1 : 2, nvc = (int)type;
  const int ncell = nx * ny * per, nside = 2 * (nx + ny);
  double *xs = malloc((size_t)nvx * sizeof *xs), *ys = malloc((size_t)nvy * sizeof *ys);
  double *xy = malloc(2 * nvert * sizeof *xy);
  int *cells = malloc((size_t)ncell * nvc * sizeof *cells);
  int *sides = malloc(2 * (size_t)nside * sizeof *sides), *tags = malloc((size_t)nside * sizeof *tags);
  int rc = 0;
  if (!xs || !ys || !xy || !cells || !sides || !tags) {
    rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory for %d x %d cells", who, nx, ny);
    goto done;
  }
  if ((rc = sl_mesh_graded_points(x0, x1, nx, &o->grade_x, xs, d)) ||
      (rc = sl_mesh_graded_points(y0, y1, ny, &o->grade_y, ys, d))) {
    sl_diag_prefix(d, rc, "%s", who);
    goto done;
  }
  const double c = cos(angle), s = sin(angle);
  for (int j = 0; j < nvy; ++j)
    for (int i = 0; i < nvx; ++i) {
      double *p = xy + 2 * ((size_t)j * nvx + i);
      if (rotate) {
        /* Rotation about (x0, y0): [c -s; s c] applied to the offset. */
        double u = xs[i] - x0, v = ys[j] - y0;
        p[0] = x0 + c * u - s * v;
        p[1] = y0 + s * u + c * v;
      } else {
        p[0] = xs[i];
        p[1] = ys[j];
      }
    }
  int *cv = cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int v00 = j * nvx + i, v10 = v00 + 1, v01 = v00 + nvx, v11 = v01 + 1;
      if (type == SL_CELL_QUAD4) {
        cv[0] = v00, cv[1] = v10, cv[2] = v11, cv[3] = v01;
        cv += 4;
        continue;
      }
      int slash = o->diagonal == SL_DIAGONAL_RIGHT || (o->diagonal == SL_DIAGONAL_UNION_JACK && (i + j) % 2 == 0);
      if (slash) { /* diagonal v00 - v11 */
        cv[0] = v00, cv[1] = v10, cv[2] = v11;
        cv[3] = v00, cv[4] = v11, cv[5] = v01;
      } else { /* diagonal v10 - v01 */
        cv[0] = v00, cv[1] = v10, cv[2] = v01;
        cv[3] = v10, cv[4] = v11, cv[5] = v01;
      }
      cv += 6;
    }
  int k = 0;
  for (int i = 0; i < nx; ++i, ++k) { /* bottom */
    sides[2 * k] = i, sides[2 * k + 1] = i + 1, tags[k] = 0;
  }
  for (int j = 0; j < ny; ++j, ++k) { /* right */
    sides[2 * k] = j * nvx + nx, sides[2 * k + 1] = (j + 1) * nvx + nx, tags[k] = 1;
  }
  for (int i = 0; i < nx; ++i, ++k) { /* top */
    sides[2 * k] = ny * nvx + i, sides[2 * k + 1] = ny * nvx + i + 1, tags[k] = 2;
  }
  for (int j = 0; j < ny; ++j, ++k) { /* left */
    sides[2 * k] = j * nvx, sides[2 * k + 1] = (j + 1) * nvx, tags[k] = 3;
  }
  sl_mesh_spec spec = {.dim = 2,
                       .cell_type = type,
                       .n_vertices = (int)nvert,
                       .xy = xy,
                       .n_cells = ncell,
                       .cell_vertices = cells,
                       .n_boundaries = 4,
                       .boundary_names = names,
                       .n_sides = nside,
                       .side_vertices = sides,
                       .side_tag = tags};
  rc = sl_mesh_create(&spec, out, d);
  if (rc) sl_diag_prefix(d, rc, "%s", who);
done:
  free(xs);
  free(ys);
  free(xy);
  free(cells);
  free(sides);
  free(tags);
  return rc;
}

static const char *const rect_names[4] = {"bottom", "right", "top", "left"};

int sl_mesh_rectangle(double x0, double x1, double y0, double y1, int nx, int ny, const sl_grid_opts *o, sl_mesh **out,
                      sl_diag *d) {
  return grid("rectangle", x0, x1, y0, y1, nx, ny, o, rect_names, 0, 0, out, d);
}

int sl_mesh_annulus(double r_in, double r_out, double z0, double z1, int nr, int nz, const sl_grid_opts *o,
                    sl_mesh **out, sl_diag *d) {
  *out = NULL;
  if (!(r_in >= 0)) return sl_diag_set(d, SL_EBADINPUT, "annulus: the inner radius must be >= 0 (got %g)", r_in);
  static const char *const ring[4] = {"bottom", "outer", "top", "inner"};
  static const char *const pipe[4] = {"bottom", "outer", "top", "axis"};
  return grid("annulus", r_in, r_out, z0, z1, nr, nz, o, r_in == 0 ? pipe : ring, 0, 0, out, d);
}

int sl_mesh_inclined_box(double x0, double y0, double width, double height, double angle, int nx, int ny,
                         const sl_grid_opts *o, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  if (!isfinite(angle)) return sl_diag_set(d, SL_EBADINPUT, "inclined box: the angle must be finite");
  if (!(width > 0) || !(height > 0))
    return sl_diag_set(d, SL_EBADINPUT, "inclined box: width and height must be positive (got %g, %g)", width, height);
  return grid("inclined box", x0, x0 + width, y0, y0 + height, nx, ny, o, rect_names, 1, angle, out, d);
}
