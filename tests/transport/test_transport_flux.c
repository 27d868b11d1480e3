/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Unit tests of the transport module: the tabulated settling flux (Hermite
 * error against the analytic law, its O(dphi^4) fall, the pieces of
 * monotone F'), the Godunov flux against an exact Godunov flux computed from
 * the analytic law (roots of q + w F' to machine precision), its
 * consistency, monotonicity and the wall/ghost identities, the error the
 * table adds to a Kynch solution, the geometry (planar, axisymmetric 2-D and
 * 1-D), the stable step, open-boundary mass accounting, and refused input. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kynch_run.h"
#include "testing.h"

#define PHI_MAX 0.64

/* ---- exact Godunov flux from the analytic law ------------------------------ */

static double h_exact(const kx_law *l, double q, double w, double x) { return q * x + w * kx_F(l, x); }
static double g_exact(const kx_law *l, double q, double w, double x) { return q + w * kx_dF(l, x); }

/* min or max of q x + w F(x) over [lo, hi]: the ends and the root of
 * q + w F' on each side of the inflection point (F' is monotone on each),
 * by bisection to machine precision. */
static double godunov_exact(const kx_law *l, double infl, double q, double w, double a, double b) {
  int want_min = a <= b;
  double lo = want_min ? a : b, hi = want_min ? b : a;
  double best =
      want_min ? fmin(h_exact(l, q, w, lo), h_exact(l, q, w, hi)) : fmax(h_exact(l, q, w, lo), h_exact(l, q, w, hi));
  const double cut[3] = {lo, fmin(fmax(infl, lo), hi), hi};
  for (int p = 0; p < 2; ++p) {
    double u = cut[p], v = cut[p + 1], gu = g_exact(l, q, w, u);
    if (v <= u || (gu > 0) == (g_exact(l, q, w, v) > 0)) continue;
    for (int it = 0; it < 200 && v - u > 1e-17; ++it) {
      double m = 0.5 * (u + v);
      if ((g_exact(l, q, w, m) > 0) == (gu > 0)) u = m;
      else v = m;
    }
    double hv = h_exact(l, q, w, 0.5 * (u + v));
    best = want_min ? fmin(best, hv) : fmax(best, hv);
  }
  if (infl > lo && infl < hi) {
    double hv = h_exact(l, q, w, infl);
    best = want_min ? fmin(best, hv) : fmax(best, hv);
  }
  return best;
}

static double urand(unsigned long long *s) {
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*s >> 11) / 9007199254740992.0;
}

static void build(sl_settling_table *t, kx_law *l, int n) {
  sl_diag d;
  if (sl_settling_table_build(t, l->c, n, kx_settling, l, &d)) {
    fprintf(stderr, "table: %s\n", d.msg);
    exit(1);
  }
}

static void test_table(void) {
  kx_law rz = kx_richardson_zaki(1.0, 4.65, PHI_MAX), ng = kx_nigam(1.0, 2.5, 0.68);
  const int sizes[3] = {129, 513, 2049};
  double err[2][3];
  for (int law = 0; law < 2; ++law) {
    kx_law *l = law ? &ng : &rz;
    for (int s = 0; s < 3; ++s) {
      sl_settling_table t;
      build(&t, l, sizes[s]);
      double e = 0, ed = 0, fmx = 0;
      for (int i = 0; i <= 50000; ++i) {
        double x = l->c * i / 50000.0;
        e = fmax(e, fabs(sl_settling_F(&t, x) - kx_F(l, x)));
        if (x < 0.99 * l->c) ed = fmax(ed, fabs(sl_settling_dF(&t, x) - kx_dF(l, x)));
        fmx = fmax(fmx, kx_F(l, x));
      }
      err[law][s] = e / fmx;
      if (s == 2) {
        printf("table of %d nodes, %s: max |F - F_exact| / max F = %.2e, max |F' - F'_exact| = %.2e, %d pieces\n",
               sizes[s], law ? "Nigam" : "Richardson-Zaki n = 4.65", e / fmx, ed, t.n_pieces);
        CHECK(t.n_pieces == 2);
        /* The piece boundary is the inflection point of F (F' extreme). */
        kynch k;
        CHECK(kx_init(&k, *l, 1.0, 0.1) == 0);
        CHECK_MSG(fabs(t.piece[1] * t.dphi - k.infl) <= t.dphi, "piece boundary %g, inflection %g", t.piece[1] * t.dphi,
                  k.infl);
        CHECK(t.sign == 1 && t.F[0] == 0 && t.F[t.n - 1] == 0);
      }
      sl_settling_table_free(&t);
    }
  }
  /* O(dphi^4) for the smooth law; Nigam's F'' is singular at alpha_m
   * ((1 - phi/alpha_m)^-0.3), which costs accuracy near it only. */
  double r = log(err[0][1] / err[0][2]) / log(4.0);
  printf(
      "Richardson-Zaki table error: %.2e, %.2e, %.2e on 129, 513, 2049 nodes (order %.2f); Nigam %.2e, %.2e, "
      "%.2e\n",
      err[0][0], err[0][1], err[0][2], r, err[1][0], err[1][1], err[1][2]);
  CHECK(r > 3.5);
  CHECK(err[0][2] < 1e-12 && err[1][2] < 1e-7);
}

static void test_godunov(void) {
  kx_law rz = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  sl_settling_table t;
  build(&t, &rz, 2049);
  kynch k;
  CHECK(kx_init(&k, rz, 1.0, 0.1) == 0);
  unsigned long long seed = 42;
  double worst = 0, worst_mono = 0;
  int n_interior = 0;
  for (int i = 0; i < 20000; ++i) {
    double q = i % 3 == 0 ? 0 : 4 * urand(&seed) - 2;
    double w = i % 4 == 0 ? -1 : i % 4 == 1 ? 1 : 6 * urand(&seed) - 3;
    double a = PHI_MAX * urand(&seed), b = i % 5 == 0 ? a + 1e-3 * (urand(&seed) - 0.5) : PHI_MAX * urand(&seed);
    b = fmin(fmax(b, 0), PHI_MAX);
    double g = sl_godunov_flux(&t, q, w, a, b), ge = godunov_exact(&rz, k.infl, q, w, a, b);
    double scale = fabs(q) * PHI_MAX + fabs(w) * t.F_absmax;
    worst = fmax(worst, fabs(g - ge) / scale);
    double ends = a <= b ? fmin(h_exact(&rz, q, w, a), h_exact(&rz, q, w, b))
                         : fmax(h_exact(&rz, q, w, a), h_exact(&rz, q, w, b));
    n_interior += fabs(ge - ends) > 1e-6 * scale;
    /* Monotone: non-decreasing in the owner state, non-increasing in the other. */
    double da = 1e-3 * urand(&seed);
    worst_mono =
        fmax(worst_mono, sl_godunov_flux(&t, q, w, a, b) - sl_godunov_flux(&t, q, w, fmin(a + da, PHI_MAX), b));
    worst_mono =
        fmax(worst_mono, sl_godunov_flux(&t, q, w, a, fmin(b + da, PHI_MAX)) - sl_godunov_flux(&t, q, w, a, b));
    /* Consistent: G(u, u) = h(u) on the table. */
    CHECK(sl_godunov_flux(&t, q, w, a, a) == q * a + w * sl_settling_F(&t, a));
  }
  printf(
      "Godunov flux on the 2049-node table against the exact one: max error %.2e of |q| phi_max + |w| max F "
      "(%d of 20000 with an interior extremum); monotonicity violated by at most %.1e\n",
      worst, n_interior, worst_mono);
  CHECK(worst < 1e-12);
  CHECK(n_interior > 1000);
  CHECK(worst_mono <= 1e-15);
  /* The wall identities behind the bounds: with h = w F, F >= 0 vanishing at
   * 0 and phi_max, the ghost 0 on the side where h would carry solids in and
   * phi_max on the other give zero flux for every state. */
  for (int i = 0; i <= 64; ++i) {
    double u = PHI_MAX * i / 64;
    CHECK(sl_godunov_flux(&t, 0, -1, PHI_MAX, u) == 0 && sl_godunov_flux(&t, 0, -1, u, 0) == 0);
    CHECK(sl_godunov_flux(&t, 0, 1, 0, u) == 0 && sl_godunov_flux(&t, 0, 1, u, PHI_MAX) == 0);
  }
  /* Transonic rarefaction (expansion) from 0.6 (below) to 0.02 (above) with
   * h = +F: a <= b is false... the sonic point F' = 0 is the maximum of F. */
  double xs = 0;
  for (int i = 0; i < 100000; ++i) {
    double x = 0.3 * i / 100000.0;
    if (kx_F(&rz, x) > kx_F(&rz, xs)) xs = x;
  }
  CHECK_CLOSE(sl_godunov_flux(&t, 0, 1, 0.6, 0.02), kx_F(&rz, xs), 1e-9);
  sl_settling_table_free(&t);
}

/* ---- table errors --------------------------------------------------------- */

static int bad_callback(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  int mode = *(const int *)user;
  for (int i = 0; i < n; ++i) {
    u[i] = mode == 0   ? pow(1 - phi[i], 4.65)                   /* no cut-off: F(phi_max) > 0 */
           : mode == 1 ? (0.3 - phi[i]) * (1 - phi[i] / PHI_MAX) /* changes sign */
                       : (phi[i] > 0.5 ? NAN : 1 - phi[i] / PHI_MAX);
    du[i] = 0;
  }
  if (mode == 3) return sl_diag_set(d, SL_EFAILED, "the closure is outside its validity at phi = %g", phi[n - 1]);
  return 0;
}

static void test_table_errors(void) {
  sl_settling_table t;
  sl_diag d;
  int mode = 0;
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, bad_callback, &mode, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "packing_cutoff");
  CHECK(t.F == NULL);
  mode = 1;
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, bad_callback, &mode, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "changes sign");
  mode = 2;
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, bad_callback, &mode, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "u = nan");
  mode = 3;
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, bad_callback, &mode, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "settling table: the closure is outside its validity at phi = 0.64");
  kx_law rz = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  CHECK(sl_settling_table_build(&t, 0, 65, kx_settling, &rz, &d) == SL_EBADINPUT);
  CHECK(sl_settling_table_build(&t, 1.5, 65, kx_settling, &rz, &d) == SL_EBADINPUT);
  CHECK(sl_settling_table_build(&t, PHI_MAX, 2, kx_settling, &rz, &d) == SL_EBADINPUT);
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, NULL, &rz, &d) == SL_EBADINPUT);
  /* Buoyant particles (u < 0) and no settling at all are fine. */
  kx_law up = kx_richardson_zaki(-0.5, 4.65, PHI_MAX), none = kx_richardson_zaki(0.0, 4.65, PHI_MAX);
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, kx_settling, &up, &d) == 0 && t.sign == -1);
  sl_settling_table_free(&t);
  CHECK(sl_settling_table_build(&t, PHI_MAX, 65, kx_settling, &none, &d) == 0 && t.sign == 0);
  CHECK(sl_godunov_flux(&t, 0, 1, 0.1, 0.5) == 0);
  sl_settling_table_free(&t);
}

/* ---- the table's share of a Kynch error ----------------------------------- */

static void test_table_in_solution(void) {
  kx_law law = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  kynch k;
  CHECK(kx_init(&k, law, 1.0, 0.1) == 0);
  const int sizes[4] = {129, 513, 2049, 8193};
  double *phi[4];
  double l1_exact = 0;
  for (int s = 0; s < 4; ++s) {
    kr_run r;
    sl_diag d;
    sl_transport_opts o = {
        .phi_max = PHI_MAX, .order = 2, .table_points = sizes[s], .settling = kx_settling, .settling_user = &law};
    r = (kr_run){0};
    kr_open(&r, 200, 1.0, 0.1, 2, SL_LIMITER_MC, kx_settling, &law, PHI_MAX);
    sl_transport_destroy(r.t);
    if (sl_transport_create(r.m, &o, &r.t, &d)) {
      fprintf(stderr, "%s\n", d.msg);
      exit(1);
    }
    kr_advance(&r, 0.8 * k.t1);
    if (s == 3) l1_exact = kr_l1(&r, &k);
    phi[s] = malloc(200 * sizeof(double));
    memcpy(phi[s], r.phi, 200 * sizeof(double));
    kr_close(&r);
  }
  double diff[3];
  for (int s = 0; s < 3; ++s) {
    diff[s] = 0;
    for (int i = 0; i < 200; ++i) diff[s] += fabs(phi[s][i] - phi[3][i]) / 200;
  }
  printf(
      "Kynch case A, MUSCL, 200 cells, t = 0.8 t1: L1 change from the table (129, 513, 2049 nodes against 8193): "
      "%.2e, %.2e, %.2e; the discretisation error is %.2e\n",
      diff[0], diff[1], diff[2], l1_exact);
  CHECK(diff[2] < 1e-10 * l1_exact / 1e-3 && diff[2] < 1e-9);
  for (int s = 0; s < 4; ++s) free(phi[s]);
}

/* ---- geometry ------------------------------------------------------------- */

static sl_transport *open_t(const sl_mesh *m, sl_transport_geometry g, int order, kx_law *law) {
  sl_diag d;
  sl_transport *t;
  sl_transport_opts o = {
      .phi_max = PHI_MAX, .order = order, .geometry = g, .settling = kx_settling, .settling_user = law};
  if (sl_transport_create(m, &o, &t, &d)) {
    fprintf(stderr, "transport: %s\n", d.msg);
    exit(1);
  }
  return t;
}

static void test_geometry(void) {
  kx_law law = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  sl_diag d;
  sl_mesh *m;
  /* Axisymmetric quads on [0.5, 1.5] x [0, 2]: V = (ro^2 - ri^2)/2 hz, A = L r on faces of constant r,
   * (ro^2 - ri^2)/2 on faces of constant z; r-weighted centroid 2/3 (ro^3 - ri^3)/(ro^2 - ri^2). */
  CHECK(sl_mesh_annulus(0.5, 1.5, 0, 2, 4, 5, NULL, &m, &d) == 0);
  sl_transport *t = open_t(m, SL_TRANSPORT_AXISYMMETRIC, 2, &law);
  const double *V = sl_transport_volumes(t), *A = sl_transport_face_areas(t), *xc = sl_transport_cell_points(t);
  double sum = 0, worst = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double ri = 1e9, ro = -1e9, zmin = 1e9, zmax = -1e9;
    for (int k = 0; k < 4; ++k) {
      const double *p = m->xy + 2 * m->cell_vertices[4 * c + k];
      ri = fmin(ri, p[0]), ro = fmax(ro, p[0]), zmin = fmin(zmin, p[1]), zmax = fmax(zmax, p[1]);
    }
    worst = fmax(worst, fabs(V[c] - 0.5 * (ro * ro - ri * ri) * (zmax - zmin)));
    worst = fmax(worst, fabs(xc[2 * c] - 2.0 / 3.0 * (ro * ro * ro - ri * ri * ri) / (ro * ro - ri * ri)));
    worst = fmax(worst, fabs(xc[2 * c + 1] - 0.5 * (zmin + zmax)));
    sum += V[c];
  }
  for (int f = 0; f < m->n_faces; ++f) {
    const double *a = m->xy + 2 * m->face_vertices[2 * f], *b = m->xy + 2 * m->face_vertices[2 * f + 1];
    double expect = a[0] == b[0] ? fabs(b[1] - a[1]) * a[0] : 0.5 * fabs(b[0] * b[0] - a[0] * a[0]);
    worst = fmax(worst, fabs(A[f] - expect));
  }
  CHECK_MSG(worst < 1e-14 && fabs(sum - 0.5 * (1.5 * 1.5 - 0.25) * 2) < 1e-14, "axisymmetric quads: %g, sum %g", worst,
            sum);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
  /* Triangles reaching the axis: the same total, and axis faces carry no area. */
  sl_grid_opts go = {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK};
  CHECK(sl_mesh_annulus(0, 1.5, 0, 2, 5, 4, &go, &m, &d) == 0);
  t = open_t(m, SL_TRANSPORT_AXISYMMETRIC, 2, &law);
  V = sl_transport_volumes(t), A = sl_transport_face_areas(t);
  sum = 0;
  for (int c = 0; c < m->n_cells; ++c) sum += V[c];
  int axis;
  CHECK(sl_mesh_boundary_id(m, "axis", &axis, &d) == 0);
  double axis_area = 0;
  for (int i = m->bface_start[axis]; i < m->bface_start[axis + 1]; ++i) axis_area += A[m->bface[i]];
  CHECK_CLOSE(sum, 0.5 * 1.5 * 1.5 * 2, 1e-14);
  CHECK(axis_area == 0);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
  /* 1-D radial line: V = (x1^2 - x0^2)/2, A = x at the face. */
  CHECK(sl_mesh_interval(0.25, 1, 3, NULL, &m, &d) == 0);
  t = open_t(m, SL_TRANSPORT_AXISYMMETRIC, 2, &law);
  V = sl_transport_volumes(t), A = sl_transport_face_areas(t);
  CHECK_CLOSE(V[0], 0.5 * (0.5 * 0.5 - 0.25 * 0.25), 1e-15);
  for (int f = 0; f < m->n_faces; ++f) CHECK(A[f] == sl_transport_face_points(t)[2 * f]);
  sl_transport_destroy(t);
  /* Planar: the mesh's own measures. */
  t = open_t(m, SL_TRANSPORT_PLANAR, 2, &law);
  CHECK(sl_transport_volumes(t)[1] == sl_mesh_cell_area(m, 1) && sl_transport_face_areas(t)[0] == 1);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
  /* An axisymmetric mesh must have r >= 0. */
  CHECK(sl_mesh_interval(-1, 1, 4, NULL, &m, &d) == 0);
  sl_transport_opts o = {
      .phi_max = PHI_MAX, .geometry = SL_TRANSPORT_AXISYMMETRIC, .settling = kx_settling, .settling_user = &law};
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT && t == NULL);
  CHECK_CONTAINS(d.msg, "r = x = -1 < 0");
  sl_mesh_destroy(m);
}

/* ---- stable step, sub-steps, refused input -------------------------------- */

static void test_step(void) {
  kx_law law = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  sl_diag d;
  sl_mesh *m;
  CHECK(sl_mesh_interval(0, 1, 50, NULL, &m, &d) == 0);
  for (int order = 1; order <= 2; ++order) {
    sl_transport *t = open_t(m, SL_TRANSPORT_PLANAR, order, &law);
    const sl_settling_table *tab = sl_transport_table(t);
    double w[51], phi[50];
    const double down[2] = {-1, 0};
    sl_transport_settling_uniform(t, down, w);
    CHECK(w[0] == 1 && w[1] == -1 && w[50] == -1); /* the left end's normal points down */
    int cell;
    double dt = sl_transport_stable_dt(t, NULL, w, &cell);
    /* Interior cell: F' at its upper face up to -D_min, at its lower face D_max. */
    double expect = 0.9 * (order == 2 ? 0.5 : 1) * 0.02 / (tab->D_max - tab->D_min);
    CHECK_CLOSE(dt, expect, 1e-14);
    CHECK(cell > 0 && cell < 49);
    CHECK(sl_transport_stable_dt(t, NULL, NULL, &cell) == HUGE_VAL && cell == -1);
    for (int i = 0; i < 50; ++i) phi[i] = 0.1;
    sl_transport_stats st;
    CHECK(sl_transport_step(t, 10.5 * expect, NULL, w, phi, &st, &d) == 0);
    CHECK(st.n_substeps == 11 && st.n_fallbacks == 0 && st.dt_stable == dt && st.max_divergence == 0);
    /* Refused input leaves phi as it was. */
    double keep[50];
    memcpy(keep, phi, sizeof keep);
    CHECK(sl_transport_step(t, 0, NULL, w, phi, &st, &d) == SL_EBADINPUT);
    CHECK(sl_transport_step(t, NAN, NULL, w, phi, &st, &d) == SL_EBADINPUT);
    w[7] = NAN;
    CHECK(sl_transport_step(t, 0.01, NULL, w, phi, &st, &d) == SL_EBADINPUT);
    CHECK_CONTAINS(d.msg, "face 7");
    w[7] = -1;
    phi[3] = 0.7;
    CHECK(sl_transport_step(t, 0.01, NULL, w, phi, &st, &d) == SL_EBADINPUT);
    CHECK_CONTAINS(d.msg, "cell 3");
    phi[3] = keep[3];
    CHECK(sl_transport_step(t, 1e7, NULL, w, phi, &st, &d) == SL_EFAILED);
    CHECK_CONTAINS(d.msg, "sub-steps");
    /* Face fluxes that are not divergence-free (a sink of mixture in cell
     * 20): the first-order sub-step leaves the bounds and the step fails. */
    double q[51] = {0};
    q[20] = 5, q[21] = -5;
    int rc = 0;
    for (int s = 0; s < 200 && !rc; ++s) rc = sl_transport_step(t, 0.05, q, w, phi, &st, &d);
    CHECK(rc == SL_EFAILED && st.max_divergence == 1);
    CHECK_CONTAINS(d.msg, "divergence");
    for (int i = 0; i < 50; ++i) CHECK(phi[i] >= 0 && phi[i] <= PHI_MAX);
    sl_transport_destroy(t);
  }
  /* Bad options and boundaries. */
  sl_transport *t;
  sl_transport_opts o = {.phi_max = PHI_MAX, .settling = kx_settling, .settling_user = &law};
  o.order = 3;
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT && t == NULL);
  o.order = 1, o.cfl = 1.5;
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT);
  o.cfl = 0, o.limiter = (sl_transport_limiter)9;
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT);
  o.limiter = SL_LIMITER_MC, o.geometry = (sl_transport_geometry)7;
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT);
  o.geometry = SL_TRANSPORT_PLANAR, o.phi_max = 0;
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "transport: settling table: phi_max = 0");
  o.phi_max = PHI_MAX;
  CHECK(sl_transport_create(m, &o, &t, &d) == 0);
  CHECK(sl_transport_set_boundary(t, 2, SL_TRANSPORT_WALL, 0, &d) == SL_EBADINPUT);
  CHECK(sl_transport_set_boundary(t, 0, (sl_transport_bc)5, 0, &d) == SL_EBADINPUT);
  CHECK(sl_transport_set_boundary(t, 0, SL_TRANSPORT_OPEN, 0.9, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'left'");
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
}

/* A fluidised column: mixture flowing up at q = 0.3 through an open bottom
 * (feed phi = 0.2) and an open top; the solids volume changes by exactly
 * what the step reports as boundary inflow. */
static void test_open_boundaries(void) {
  kx_law law = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  sl_diag d;
  sl_mesh *m;
  CHECK(sl_mesh_interval(0, 1, 80, NULL, &m, &d) == 0);
  for (int order = 1; order <= 2; ++order) {
    sl_transport *t = open_t(m, SL_TRANSPORT_PLANAR, order, &law);
    CHECK(sl_transport_set_boundary(t, 0, SL_TRANSPORT_OPEN, 0.2, &d) == 0);
    CHECK(sl_transport_set_boundary(t, 1, SL_TRANSPORT_OPEN, 0.0, &d) == 0);
    double w[81], q[81], phi[80];
    const double down[2] = {-1, 0};
    sl_transport_settling_uniform(t, down, w);
    for (int f = 0; f < 81; ++f) q[f] = 0.3 * -w[f]; /* j = +0.3 e_x: q = A (j . n) = -0.3 w */
    for (int i = 0; i < 80; ++i) phi[i] = i < 40 ? 0.05 : 0;
    double m0 = sl_transport_mass(t, phi), inflow = 0, worst = 0;
    for (int s = 0; s < 100; ++s) {
      sl_transport_stats st;
      CHECK(sl_transport_step(t, 0.02, q, w, phi, &st, &d) == 0);
      inflow += st.boundary_inflow;
      worst = fmax(worst, fabs(sl_transport_mass(t, phi) - (m0 + inflow)));
      CHECK(st.max_divergence < 1e-15);
    }
    printf(
        "open column, order %d: solids volume %.6f after 2 s (from %.6f), balance with the reported inflow "
        "off by %.1e\n",
        order, sl_transport_mass(t, phi), m0, worst);
    CHECK(worst < 1e-15 && inflow > 0);
    sl_transport_destroy(t);
  }
  sl_mesh_destroy(m);
}

int main(void) {
  test_table();
  test_godunov();
  test_table_errors();
  test_table_in_solution();
  test_geometry();
  test_step();
  test_open_boundaries();
  return sl_test_summary();
}
