/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Sampling of output files: fields that the cell's basis reproduces exactly
 * (biquadratic on rectangular Q9 cells, quadratic on distorted Q9 and on P2
 * triangles and Edge_3 lines, linear on distorted Q1, on P1 triangles and on
 * Polyline lines), read back at points
 * along lines to 1e-12; cell fields; points outside the mesh (beyond the
 * box and in a notch); curved (isoparametric) Q9 and P2 cells of an annulus
 * sector, a linear field read back just inside the curved wall; time
 * selection and its errors; the file listing;
 * the Edge_3 topology in the writer and reader.
 *
 * `io_sample --write-fixtures DIR` only writes the files the CLI tests
 * sample (DIR/sample_2d.h5, DIR/sample_1d.h5). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/io/sample.h"
#include "io_util.h"
#include "testing.h"

#define TOL 1e-12

/* |a - b| <= TOL (1 + |b|): exact up to rounding. */
#define CHECK_EXACT(a, b)                                                                                    \
  do {                                                                                                       \
    double a_ = (a), b_ = (b);                                                                               \
    CHECK_MSG(fabs(a_ - b_) <= TOL * (1.0 + fabs(b_)), "%s = %.17g, expected %.17g (diff %.3g)", #a, a_, b_, \
              fabs(a_ - b_));                                                                                \
  } while (0)

/* ---- building meshes --------------------------------------------------- */

typedef struct mesh {
  int dim, nv, nc, npc;
  double xy[2 * 1024]; /* dim-strided, as sl_output_write_mesh takes them */
  int32_t cells[9 * 512];
  const char *topology;
} mesh;

/* Biquadratic Q9 grid on the tensor product of the corner coordinates
 * xs[0..nx] x ys[0..ny]; midpoints halfway. */
static void q9_grid(mesh *m, const double *xs, int nx, const double *ys, int ny) {
  int NX = 2 * nx + 1, NY = 2 * ny + 1;
  m->dim = 2, m->nv = NX * NY, m->nc = nx * ny, m->npc = 9, m->topology = "Quadrilateral_9";
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      double x = i % 2 ? 0.5 * (xs[i / 2] + xs[i / 2 + 1]) : xs[i / 2];
      double y = j % 2 ? 0.5 * (ys[j / 2] + ys[j / 2 + 1]) : ys[j / 2];
      m->xy[2 * (j * NX + i)] = x, m->xy[2 * (j * NX + i) + 1] = y;
    }
  /* corners counter-clockwise, midpoints of 0-1, 1-2, 2-3, 3-0, centre */
  static const int di[9] = {0, 2, 2, 0, 1, 2, 1, 0, 1}, dj[9] = {0, 0, 2, 2, 0, 1, 2, 1, 1};
  for (int b = 0; b < ny; ++b)
    for (int a = 0; a < nx; ++a)
      for (int k = 0; k < 9; ++k) m->cells[9 * (b * nx + a) + k] = (2 * b + dj[k]) * NX + 2 * a + di[k];
}

/* Moves the Q9 grid's interior corners by (dx, dy) * pattern and puts the
 * midpoints and centres where the bilinear map of the corners has them. */
static void q9_distort(mesh *m, int nx, int ny, double dx, double dy) {
  int NX = 2 * nx + 1;
  for (int j = 2; j < 2 * ny; j += 2)
    for (int i = 2; i < 2 * nx; i += 2) {
      double s = ((i / 2 + j / 2) % 2) ? 1.0 : -0.7;
      m->xy[2 * (j * NX + i)] += s * dx, m->xy[2 * (j * NX + i) + 1] += s * dy;
    }
  for (int c = 0; c < m->nc; ++c) {
    const int32_t *q = m->cells + 9 * c;
    for (int e = 0; e < 4; ++e)
      for (int k = 0; k < 2; ++k) m->xy[2 * q[4 + e] + k] = 0.5 * (m->xy[2 * q[e] + k] + m->xy[2 * q[(e + 1) % 4] + k]);
    for (int k = 0; k < 2; ++k)
      m->xy[2 * q[8] + k] =
          0.25 * (m->xy[2 * q[0] + k] + m->xy[2 * q[1] + k] + m->xy[2 * q[2] + k] + m->xy[2 * q[3] + k]);
  }
}

/* The node (by coordinates) shared by the edges of the P2 triangles. */
static int32_t find_or_add(mesh *m, double x, double y) {
  for (int i = 0; i < m->nv; ++i)
    if (m->xy[2 * i] == x && m->xy[2 * i + 1] == y) return i;
  m->xy[2 * m->nv] = x, m->xy[2 * m->nv + 1] = y;
  return m->nv++;
}

/* P2 triangles on the [0,2] x [0,1] grid of 4 x 2 squares, the vertex at
 * (0.5, 0.5) moved; the square at (skip_i, skip_j) is left out (a notch). */
static void tri6_mesh(mesh *m, int skip_i, int skip_j) {
  m->dim = 2, m->nv = 0, m->nc = 0, m->npc = 6, m->topology = "Triangle_6";
  double cx[5][3], cy[5][3];
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 4; ++i) {
      int moved = i == 1 && j == 1;
      cx[i][j] = 0.5 * i - (moved ? 0.04 : 0.0);
      cy[i][j] = 0.5 * j + (moved ? 0.07 : 0.0);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      if (i == skip_i && j == skip_j) continue;
      /* two counter-clockwise triangles per square, diagonals alternating */
      int a[2] = {i, j}, b[2] = {i + 1, j}, c[2] = {i + 1, j + 1}, dd[2] = {i, j + 1};
      int alt = (i + j) % 2;
      const int *t0[3] = {a, b, alt ? dd : c}, *t1[3] = {alt ? b : a, c, dd};
      for (int t = 0; t < 2; ++t) {
        const int *const *v = t ? t1 : t0;
        int32_t *cell = m->cells + 6 * m->nc++;
        for (int k = 0; k < 3; ++k) cell[k] = find_or_add(m, cx[v[k][0]][v[k][1]], cy[v[k][0]][v[k][1]]);
        for (int k = 0; k < 3; ++k) {
          const int *p = v[k], *q = v[(k + 1) % 3];
          double mx = 0.5 * (cx[p[0]][p[1]] + cx[q[0]][q[1]]), my = 0.5 * (cy[p[0]][p[1]] + cy[q[0]][q[1]]);
          cell[3 + k] = find_or_add(m, mx, my);
        }
      }
    }
}

/* Edge_3 cells on the corner points xs[0..n]; cell 1 runs backwards. */
static void edge3_mesh(mesh *m, const double *xs, int n) {
  m->dim = 1, m->nv = 0, m->nc = n, m->npc = 3, m->topology = "Edge_3";
  for (int i = 0; i <= n; ++i) m->xy[m->nv++] = xs[i];
  for (int c = 0; c < n; ++c) {
    m->xy[m->nv] = 0.5 * (xs[c] + xs[c + 1]);
    int32_t *e = m->cells + 3 * c;
    e[0] = c == 1 ? c + 1 : c, e[1] = c == 1 ? c : c + 1, e[2] = m->nv++;
  }
}

/* Second-order cells of the annulus sector 0.5 <= r <= 1, 0 <= theta <= pi/2
 * on nr x nt polar cells, every node (mid-edge ones included) placed at its
 * polar position, so the edges along theta are arcs sampled at three points
 * (curved, isoparametric cells): Q9 (tri = 0) or two P2 triangles a cell. */
static void polar_point(int i, int j, int nr, int nt, double *x, double *y) {
  double r = 0.5 + 0.5 * i / (2.0 * nr), t = 0.5 * M_PI * j / (2.0 * nt);
  *x = r * cos(t), *y = r * sin(t);
}

static void curved_mesh(mesh *m, int nr, int nt, int tri) {
  int NX = 2 * nr + 1, NY = 2 * nt + 1;
  m->dim = 2, m->nv = NX * NY, m->nc = 0, m->npc = tri ? 6 : 9, m->topology = tri ? "Triangle_6" : "Quadrilateral_9";
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) polar_point(i, j, nr, nt, &m->xy[2 * (j * NX + i)], &m->xy[2 * (j * NX + i) + 1]);
  static const int di[9] = {0, 2, 2, 0, 1, 2, 1, 0, 1}, dj[9] = {0, 0, 2, 2, 0, 1, 2, 1, 1};
  /* P2: corners, then the mids of 0-1, 1-2, 2-0 (lattice offsets) */
  static const int ti[2][6] = {{0, 2, 2, 1, 2, 1}, {0, 2, 0, 1, 1, 0}},
                   tj[2][6] = {{0, 0, 2, 0, 1, 1}, {0, 2, 2, 1, 2, 1}};
  for (int b = 0; b < nt; ++b)
    for (int a = 0; a < nr; ++a) {
      if (!tri) {
        for (int k = 0; k < 9; ++k) m->cells[9 * m->nc + k] = (2 * b + dj[k]) * NX + 2 * a + di[k];
        ++m->nc;
        continue;
      }
      for (int t = 0; t < 2; ++t, ++m->nc)
        for (int k = 0; k < 6; ++k) m->cells[6 * m->nc + k] = (2 * b + tj[t][k]) * NX + 2 * a + ti[t][k];
    }
}

/* ---- fields and files -------------------------------------------------- */

typedef double (*fn2)(double x, double y);

static double f_biquad(double x, double y) { return (1.0 + 2.0 * x - 3.0 * x * x) * (0.5 - y + 0.25 * y * y); }
static double f_quad(double x, double y) { return 1.0 + x - 2.0 * y + 3.0 * x * x - x * y + 0.5 * y * y; }
static double f_quad2(double x, double y) { return 0.3 - x * x + 2.0 * x * y + y; }
static double f_lin(double x, double y) { return 2.0 - 0.5 * x + 3.0 * y; }
static double f_1d(double x, double y) { return (void)y, 2.0 - x + 4.0 * x * x; }
static double g_lin(double x, double y) { return -1.0 + 4.0 * x - 0.25 * y; }

/* One file: steps at times[k]; "phi" = (k + 1) f at the nodes, "velocity" =
 * (f, g) at the nodes (2 components, stored as 3), "pressure" = 10 k + cell
 * index at the cells; "extra" only in step 1. */
static int write_file(const char *path, const mesh *m, fn2 f, fn2 g, const double *times, int n_steps) {
  sl_diag d = {{0}};
  sl_output *o = NULL;
  double *phi = malloc(sizeof(double) * (size_t)m->nv), *vel = malloc(2 * sizeof(double) * (size_t)m->nv);
  double *pres = malloc(sizeof(double) * (size_t)m->nc);
  int rc = phi && vel && pres ? 0 : SL_EFAILED;
  if (!rc) rc = sl_output_open(&o, path, &d);
  if (!rc) rc = sl_output_write_mesh(o, m->dim, m->nv, m->xy, m->nc, m->npc, m->cells, m->topology, &d);
  for (int k = 0; !rc && k < n_steps; ++k) {
    for (int i = 0; i < m->nv; ++i) {
      double x = m->xy[m->dim * i], y = m->dim == 2 ? m->xy[2 * i + 1] : 0.0;
      phi[i] = (k + 1) * f(x, y);
      vel[2 * i] = f(x, y), vel[2 * i + 1] = g(x, y);
    }
    for (int c = 0; c < m->nc; ++c) pres[c] = 10.0 * k + c;
    rc = sl_output_begin_step(o, times[k], &d);
    if (!rc) rc = sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, phi, &d);
    if (!rc) rc = sl_output_write_field(o, "velocity", SL_CENTRE_NODE, 2, vel, &d);
    if (!rc) rc = sl_output_write_field(o, "pressure", SL_CENTRE_CELL, 1, pres, &d);
    if (!rc && k == 1) rc = sl_output_write_field(o, "extra", SL_CENTRE_CELL, 1, pres, &d);
    if (!rc) rc = sl_output_end_step(o, &d);
  }
  int rc2 = o ? sl_output_close(o, &d) : 0;
  if (rc || rc2) fprintf(stderr, "writing %s: %s\n", path, d.msg);
  free(phi), free(vel), free(pres);
  return rc ? rc : rc2;
}

/* n points from a to b (both included). */
static void line_points(double *xy, int n, double ax, double ay, double bx, double by) {
  for (int i = 0; i < n; ++i) {
    double t = n > 1 ? (double)i / (n - 1) : 0.0;
    xy[2 * i] = ax + t * (bx - ax), xy[2 * i + 1] = ay + t * (by - ay);
  }
}

/* Samples "phi" (and "velocity") along points and compares with step k's
 * exact values; returns the number of points outside. */
static int check_line(const char *path, double t, int k, const double *xy, int n, fn2 f, fn2 g) {
  sl_diag d = {{0}};
  sl_sample s;
  int out = -1;
  CHECK_MSG(sl_sample_points(path, "phi", t, n, xy, &s, &d) == 0, "%s", d.msg);
  CHECK(s.step == k && s.components == 1 && s.n_points == n && s.centring == SL_CENTRE_NODE);
  for (int i = 0; i < s.n_points; ++i)
    if (!isnan(s.values[i])) CHECK_EXACT(s.values[i], (k + 1) * f(xy[2 * i], xy[2 * i + 1]));
  out = s.n_outside;
  sl_sample_free(&s);
  if (!g) return out;
  CHECK_MSG(sl_sample_points(path, "velocity", t, n, xy, &s, &d) == 0, "%s", d.msg);
  CHECK(s.components == 3 && s.n_outside == out);
  for (int i = 0; i < s.n_points; ++i) {
    if (isnan(s.values[3 * i])) continue;
    CHECK_EXACT(s.values[3 * i], f(xy[2 * i], xy[2 * i + 1]));
    CHECK_EXACT(s.values[3 * i + 1], g(xy[2 * i], xy[2 * i + 1]));
    CHECK(s.values[3 * i + 2] == 0.0);
  }
  sl_sample_free(&s);
  return out;
}

static const double three_times[3] = {0.0, 0.5, 1.0};

/* ---- tests ------------------------------------------------------------- */

/* Curved cells: a field linear in x and y, given at the nodes of the
 * isoparametric cells, is reproduced exactly by the interpolant composed
 * with the inverse of the quadratic map, so it reads back to rounding at
 * points just inside the curved outer wall: between the arc's quadratic
 * and the chord, where a straight-sided cell holds no point. */
static void test_curved(void) {
  enum { NR = 2, NT = 3, NS = 7 };
  static const double s_at[NS] = {-0.95, -0.7, -0.3, 0.0, 0.25, 0.6, 0.9};
  for (int tri = 0; tri < 2; ++tri) {
    mesh m;
    curved_mesh(&m, NR, NT, tri);
    const char *path = tri ? "sample_curved_tri6.h5" : "sample_curved_q9.h5";
    CHECK(write_file(path, &m, f_lin, g_lin, three_times, 1) == 0);
    double xy[2 * NT * NS];
    int n = 0, beyond_chord = 0;
    for (int b = 0; b < NT; ++b) {
      double x0, y0, x1, y1, xm, ym;
      polar_point(2 * NR, 2 * b, NR, NT, &x0, &y0);
      polar_point(2 * NR, 2 * b + 2, NR, NT, &x1, &y1);
      polar_point(2 * NR, 2 * b + 1, NR, NT, &xm, &ym);
      for (int k = 0; k < NS; ++k, ++n) {
        /* the outer edge's quadratic through its three nodes, pulled in by 1e-9 */
        double s = s_at[k], N0 = 0.5 * s * (s - 1.0), N1 = 0.5 * s * (s + 1.0), Nm = 1.0 - s * s;
        double px = N0 * x0 + N1 * x1 + Nm * xm, py = N0 * y0 + N1 * y1 + Nm * ym;
        xy[2 * n] = (1.0 - 1e-9) * px, xy[2 * n + 1] = (1.0 - 1e-9) * py;
        /* beyond the chord x0-x1 (counter-clockwise): on its right, away from the origin */
        double cross = (x1 - x0) * (xy[2 * n + 1] - y0) - (y1 - y0) * (xy[2 * n] - x0);
        beyond_chord += cross < -1e-6;
      }
    }
    CHECK_MSG(beyond_chord == n, "%s: %d of %d points beyond the chords", path, beyond_chord, n);
    CHECK_MSG(check_line(path, 0.0, 0, xy, n, f_lin, g_lin) == 0, "%s: points near the curved wall outside", path);
    /* and through the interior, across the curved edges between cells */
    double line[2 * 41];
    line_points(line, 41, 0.7, 0.05, 0.05, 0.7);
    CHECK_MSG(check_line(path, 0.0, 0, line, 41, f_lin, g_lin) == 0, "%s: interior points outside", path);
    remove(path);
  }
}

static void test_q9_rectangles(void) {
  static mesh m;
  const double xs[4] = {0.0, 0.3, 0.45, 1.0}, ys[3] = {-1.0, 0.5, 2.0};
  q9_grid(&m, xs, 3, ys, 2);
  CHECK(write_file("sample_q9.h5", &m, f_biquad, f_quad, three_times, 3) == 0);
  enum { N = 41 };
  double xy[2 * N];
  /* the diagonal (corners included), a cell edge, an off-grid line */
  line_points(xy, N, 0.0, -1.0, 1.0, 2.0);
  CHECK(check_line("sample_q9.h5", INFINITY, 2, xy, N, f_biquad, f_quad) == 0);
  line_points(xy, N, 0.0, 0.5, 1.0, 0.5);
  CHECK(check_line("sample_q9.h5", 0.0, 0, xy, N, f_biquad, f_quad) == 0);
  line_points(xy, N, 0.9, -0.95, 0.05, 1.7);
  CHECK(check_line("sample_q9.h5", 0.5, 1, xy, N, f_biquad, f_quad) == 0);

  /* the cell field at the cell centres: cell c holds 10 k + c */
  double centres[2 * 6];
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 3; ++a)
      centres[2 * (3 * b + a)] = 0.5 * (xs[a] + xs[a + 1]), centres[2 * (3 * b + a) + 1] = 0.5 * (ys[b] + ys[b + 1]);
  sl_diag d = {{0}};
  sl_sample s;
  CHECK_MSG(sl_sample_points("sample_q9.h5", "pressure", 0.5, 6, centres, &s, &d) == 0, "%s", d.msg);
  CHECK(s.centring == SL_CENTRE_CELL && s.components == 1 && s.n_outside == 0);
  for (int c = 0; c < 6 && s.values; ++c) CHECK(s.values[c] == 10.0 + c);
  sl_sample_free(&s);
}

static void test_q9_distorted(void) {
  static mesh m;
  const double xs[4] = {0.0, 1.0, 2.0, 3.0}, ys[4] = {0.0, 1.0, 2.0, 3.0};
  q9_grid(&m, xs, 3, ys, 3);
  q9_distort(&m, 3, 3, 0.21, -0.17);
  CHECK(write_file("sample_q9d.h5", &m, f_quad, f_quad2, three_times, 1) == 0);
  enum { N = 57 };
  double xy[2 * N];
  line_points(xy, N, 0.01, 0.02, 2.99, 2.9);
  CHECK(check_line("sample_q9d.h5", 0.0, 0, xy, N, f_quad, f_quad2) == 0);
  line_points(xy, N, 3.0, 0.1, 0.0, 2.3);
  CHECK(check_line("sample_q9d.h5", 0.0, 0, xy, N, f_quad, f_quad2) == 0);
}

static void test_tri6(void) {
  static mesh m;
  tri6_mesh(&m, 2, 1); /* notch: the square [1, 1.5] x [0.5, 1] is missing */
  CHECK(m.nc == 14);
  CHECK(write_file("sample_t6.h5", &m, f_quad, f_quad2, three_times, 2) == 0);
  enum { N = 33 };
  double xy[2 * N];
  line_points(xy, N, 0.0, 0.0, 2.0, 0.5);
  CHECK(check_line("sample_t6.h5", 0.5, 1, xy, N, f_quad, f_quad2) == 0);
  line_points(xy, N, 0.0, 1.0, 1.0, 0.0);
  CHECK(check_line("sample_t6.h5", 0.0, 0, xy, N, f_quad, f_quad2) == 0);
  line_points(xy, N, 0.0, 0.25, 2.0, 0.25);
  CHECK(check_line("sample_t6.h5", 0.0, 0, xy, N, f_quad, f_quad2) == 0);
  /* across the notch and beyond the box: x = -0.5 .. 2.5 at y = 0.8 in steps
   * of 3/32; inside the mesh for x in [0, 1] and [1.5, 2] */
  line_points(xy, N, -0.5, 0.8, 2.5, 0.8);
  int expect = 0;
  for (int i = 0; i < N; ++i) {
    double x = xy[2 * i];
    expect += !((x >= 0.0 && x <= 1.0) || (x >= 1.5 && x <= 2.0));
  }
  CHECK(expect == 17);
  CHECK(check_line("sample_t6.h5", 0.5, 1, xy, N, f_quad, f_quad2) == expect);
  sl_diag d = {{0}};
  sl_sample s;
  const double notch[2] = {1.25, 0.75}, edge[2] = {1.0, 0.75};
  CHECK(sl_sample_points("sample_t6.h5", "phi", 0.0, 1, notch, &s, &d) == 0 && s.n_outside == 1 && isnan(s.values[0]));
  sl_sample_free(&s);
  CHECK(sl_sample_points("sample_t6.h5", "phi", 0.0, 1, edge, &s, &d) == 0 && s.n_outside == 0);
  if (s.values) CHECK_EXACT(s.values[0], f_quad(1.0, 0.75));
  sl_sample_free(&s);
}

static void test_edge3(void) {
  static mesh m;
  const double xs[4] = {0.0, 0.1, 0.35, 1.0};
  edge3_mesh(&m, xs, 3);
  CHECK(write_file("sample_e3.h5", &m, f_1d, f_1d, three_times, 3) == 0);
  char *x = slurp("sample_e3.xmf");
  CHECK(x && strstr(x, "TopologyType=\"Edge_3\" NumberOfElements=\"3\">"));
  free(x);
  int st = xmllint_status("sample_e3.xmf");
  if (st != -2) CHECK(st == 0);
  sl_diag d = {{0}};
  sl_output_mesh om;
  CHECK(sl_output_read_mesh("sample_e3.h5", &om, &d) == 0);
  CHECK(strcmp(om.topology, "Edge_3") == 0 && om.dim == 1 && om.nodes_per_cell == 3 && om.n_cells == 3 &&
        om.n_vertices == 7 && om.cells[3] == 2 && om.cells[5] == 5 && om.coords[3 * 5] == 0.5 * (xs[1] + xs[2]));
  sl_output_mesh_free(&om);

  enum { N = 23 };
  double xy[2 * N];
  line_points(xy, N, -0.1, 0.0, 1.1, 0.0);         /* the ends lie outside */
  for (int i = 0; i < N; ++i) xy[2 * i + 1] = 7.0; /* y is ignored in 1-D */
  int out = check_line("sample_e3.h5", 1.0, 2, xy, N, f_1d, f_1d);
  int expect = 0;
  for (int i = 0; i < N; ++i) expect += xy[2 * i] < 0.0 || xy[2 * i] > 1.0;
  CHECK(out == expect && expect == 4);

  /* the writer wants 3 nodes per Edge_3 cell */
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "sample_e3_bad.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 1, 3, xs, 1, 2, m.cells, "Edge_3", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "Edge_3 has 3 nodes per cell, not 2");
  CHECK(sl_output_write_mesh(o, 1, 3, xs, 1, 3, m.cells, "Edge3", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'Edge_3'");
  CHECK(sl_output_close(o, &d) == 0);
}

/* Q1 on a distorted 40 x 30 grid with a linear field: many cells per query,
 * points scattered inside and outside the rectangle [0, 4] x [0, 3]. */
static void test_locator_many_cells(void) {
  enum { NX = 40, NY = 30 };
  static double xy[2 * (NX + 1) * (NY + 1)];
  static int32_t q[4 * NX * NY];
  for (int j = 0; j <= NY; ++j)
    for (int i = 0; i <= NX; ++i) {
      int interior = i > 0 && i < NX && j > 0 && j < NY;
      xy[2 * (j * (NX + 1) + i)] = 0.1 * i + (interior ? 0.03 * sin(1.7 * i + j) : 0.0);
      xy[2 * (j * (NX + 1) + i) + 1] = 0.1 * j + (interior ? 0.03 * cos(0.9 * i - 2.1 * j) : 0.0);
    }
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      int32_t *c = q + 4 * (j * NX + i), v = j * (NX + 1) + i;
      c[0] = v, c[1] = v + 1, c[2] = v + NX + 2, c[3] = v + NX + 1;
    }
  sl_diag d = {{0}};
  sl_output *o = NULL;
  double phi[(NX + 1) * (NY + 1)];
  for (int v = 0; v < (NX + 1) * (NY + 1); ++v) phi[v] = f_lin(xy[2 * v], xy[2 * v + 1]);
  CHECK(sl_output_open(&o, "sample_q4.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, (NX + 1) * (NY + 1), xy, NX * NY, 4, q, "Quadrilateral", &d) == 0);
  CHECK(sl_output_begin_step(o, 2.0, &d) == 0);
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, phi, &d) == 0);
  CHECK(sl_output_end_step(o, &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  enum { N = 2000 };
  static double pts[2 * N];
  unsigned r = 12345u;
  int expect = 0;
  for (int i = 0; i < N; ++i) {
    r = r * 1103515245u + 12345u;
    pts[2 * i] = -0.5 + 5.0 * ((r >> 8) & 0xffff) / 65535.0;
    r = r * 1103515245u + 12345u;
    pts[2 * i + 1] = -0.5 + 4.0 * ((r >> 8) & 0xffff) / 65535.0;
    expect += pts[2 * i] < 0.0 || pts[2 * i] > 4.0 || pts[2 * i + 1] < 0.0 || pts[2 * i + 1] > 3.0;
  }
  sl_sample s;
  CHECK_MSG(sl_sample_points("sample_q4.h5", "phi", 2.0, N, pts, &s, &d) == 0, "%s", d.msg);
  CHECK_MSG(s.n_outside == expect, "%d outside, expected %d", s.n_outside, expect);
  int bad = 0;
  for (int i = 0; i < N && s.values; ++i) {
    int outside = pts[2 * i] < 0.0 || pts[2 * i] > 4.0 || pts[2 * i + 1] < 0.0 || pts[2 * i + 1] > 3.0;
    double e = f_lin(pts[2 * i], pts[2 * i + 1]);
    if (outside ? !isnan(s.values[i]) : !(fabs(s.values[i] - e) <= TOL * (1.0 + fabs(e)))) ++bad;
  }
  CHECK_MSG(bad == 0, "%d of %d points wrong", bad, N);
  sl_sample_free(&s);
}

/* The linear cells: two triangles and a 1-D Polyline, linear fields. */
static void test_linear_cells(void) {
  static mesh m;
  const double sq[8] = {0, 0, 2, 0, 2, 1, 0.5, 1.2};
  const int32_t tri[6] = {0, 1, 2, 0, 2, 3};
  m.dim = 2, m.nv = 4, m.nc = 2, m.npc = 3, m.topology = "Triangle";
  memcpy(m.xy, sq, sizeof sq);
  memcpy(m.cells, tri, sizeof tri);
  CHECK(write_file("sample_t3.h5", &m, f_lin, f_lin, three_times, 1) == 0);
  enum { N = 21 };
  double xy[2 * N];
  line_points(xy, N, 0.0, 0.0, 2.0, 1.0); /* along the shared edge */
  CHECK(check_line("sample_t3.h5", 0.0, 0, xy, N, f_lin, f_lin) == 0);
  line_points(xy, N, 0.3, 0.5, 1.9, 0.5);
  CHECK(check_line("sample_t3.h5", 0.0, 0, xy, N, f_lin, f_lin) == 0);

  const double xs[4] = {0.0, 0.7, 0.2, 1.0}; /* unordered vertices */
  const int32_t seg[6] = {0, 2, 1, 2, 3, 1};
  m.dim = 1, m.nv = 4, m.nc = 3, m.npc = 2, m.topology = "Polyline";
  memcpy(m.xy, xs, sizeof xs);
  memcpy(m.cells, seg, sizeof seg);
  CHECK(write_file("sample_l2.h5", &m, f_lin, f_lin, three_times, 1) == 0);
  line_points(xy, N, 0.0, 0.0, 1.0, 0.0);
  CHECK(check_line("sample_l2.h5", 0.0, 0, xy, N, f_lin, f_lin) == 0);
}

static void test_times_and_errors(void) {
  sl_diag d = {{0}};
  sl_sample s;
  const double p[2] = {0.3, 0.5};
  /* nearest step; the earlier one on a tie; infinities take the ends */
  const struct {
    double t;
    int step;
  } cases[] = {{0.6, 1}, {0.25, 0}, {0.76, 2}, {1.0 + 1e-12, 2}, {-INFINITY, 0}, {INFINITY, 2}, {-1e-12, 0}};
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    CHECK_MSG(sl_sample_points("sample_q9.h5", "phi", cases[i].t, 1, p, &s, &d) == 0, "%s", d.msg);
    CHECK_MSG(s.step == cases[i].step && s.time == three_times[cases[i].step], "t = %g: step %d", cases[i].t, s.step);
    if (s.values) CHECK_EXACT(s.values[0], (cases[i].step + 1) * f_biquad(0.3, 0.5));
    sl_sample_free(&s);
  }
  CHECK(sl_sample_points("sample_q9.h5", "phi", 2.0, 1, p, &s, &d) == SL_EBADINPUT && !s.values);
  CHECK_CONTAINS(d.msg, "time 2 is outside the output times [0, 1] (3 steps)");
  CHECK_CONTAINS(d.msg, "nearest output of 'phi' is t = 1 (step 2)");
  CHECK(sl_sample_points("sample_q9.h5", "phi", -0.5, 1, p, &s, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "t = 0 (step 0)");
  /* a field held by step 1 only: the range is the file's, the step its own */
  const double in_cell0[2] = {0.1, 0.0};
  CHECK(sl_sample_points("sample_q9.h5", "extra", 0.0, 1, in_cell0, &s, &d) == 0 && s.step == 1 && s.values &&
        s.values[0] == 10.0);
  sl_sample_free(&s);
  CHECK(sl_sample_points("sample_q9.h5", "ph", 0.0, 1, p, &s, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'phi'");
  CHECK(sl_sample_points("sample_q9.h5", "phi", NAN, 1, p, &s, &d) == SL_EBADINPUT);
  CHECK(sl_sample_points("no_such_file.h5", "phi", 0.0, 1, p, &s, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no_such_file.h5");
  /* no points: an empty answer */
  CHECK(sl_sample_points("sample_q9.h5", "velocity", 0.0, 0, NULL, &s, &d) == 0 && s.n_points == 0 &&
        s.components == 3);
  sl_sample_free(&s);

  /* a Polyline in the plane is no 1-D mesh */
  const double xy[6] = {0, 0, 1, 1, 2, 0};
  const int32_t seg[4] = {0, 1, 1, 2};
  const double u[3] = {1, 2, 3};
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "sample_curve.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, 3, xy, 2, 2, seg, "Polyline", &d) == 0);
  CHECK(sl_output_begin_step(o, 0.0, &d) == 0);
  CHECK(sl_output_write_field(o, "u", SL_CENTRE_NODE, 1, u, &d) == 0);
  CHECK(sl_output_end_step(o, &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  CHECK(sl_sample_points("sample_curve.h5", "u", 0.0, 1, p, &s, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "cannot sample Polyline cells in a 2-D mesh");
}

static void test_contents(void) {
  sl_diag d = {{0}};
  sl_output_contents c;
  CHECK_MSG(sl_output_read_contents("sample_q9.h5", &c, &d) == 0, "%s", d.msg);
  CHECK(c.n_steps == 3 && c.times[0] == 0.0 && c.times[1] == 0.5 && c.times[2] == 1.0);
  CHECK(c.n_fields == 4);
  if (c.n_fields == 4) {
    const char *names[4] = {"extra", "phi", "pressure", "velocity"};
    for (int i = 0; i < 4; ++i) CHECK(strcmp(c.fields[i].name, names[i]) == 0);
    CHECK(c.fields[0].n_steps == 1 && c.fields[0].t_first == 0.5 && c.fields[0].t_last == 0.5);
    CHECK(c.fields[1].n_steps == 3 && c.fields[1].t_first == 0.0 && c.fields[1].t_last == 1.0);
    CHECK(c.fields[1].centring == SL_CENTRE_NODE && c.fields[1].components == 1);
    CHECK(c.fields[2].centring == SL_CENTRE_CELL && c.fields[3].components == 3);
  }
  sl_output_contents_free(&c);
  CHECK(sl_output_read_contents("no_such_file.h5", &c, &d) == SL_EBADINPUT && c.times == NULL);
}

/* Files for the CLI tests (tests/cli/CMakeLists.txt): a unit square of 2 x 2
 * Q9 cells with phi = (k + 1)(x + 2 y), velocity (x + 2 y, x - y), pressure
 * 10 k + cell at t = 0, 0.5, 1; [0, 2] in two Edge_3 cells with phi = x^2 at
 * t = 0. */
static double f_cli(double x, double y) { return x + 2.0 * y; }
static double g_cli(double x, double y) { return x - y; }
static double f_cli_1d(double x, double y) { return (void)y, x * x; }

static int write_fixtures(const char *dir) {
  static mesh m;
  char path[1024];
  const double xs[3] = {0.0, 0.5, 1.0}, x1[3] = {0.0, 1.0, 2.0};
  q9_grid(&m, xs, 2, xs, 2);
  snprintf(path, sizeof path, "%s/sample_2d.h5", dir);
  if (write_file(path, &m, f_cli, g_cli, three_times, 3)) return 1;
  edge3_mesh(&m, x1, 2);
  snprintf(path, sizeof path, "%s/sample_1d.h5", dir);
  if (write_file(path, &m, f_cli_1d, f_cli_1d, three_times, 1)) return 1;
  return 0;
}

int main(int argc, char **argv) {
  if (argc == 3 && strcmp(argv[1], "--write-fixtures") == 0) return write_fixtures(argv[2]);
  test_q9_rectangles();
  test_q9_distorted();
  test_tri6();
  test_edge3();
  test_curved();
  test_locator_many_cells();
  test_linear_cells();
  test_times_and_errors();
  test_contents();
  return sl_test_summary();
}
