/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The transport on 2-D planar and axisymmetric meshes, one code path:
 *  - vertical settling on quads, planar and axisymmetric (r-weighted): every
 *    column equals the 1-D run to round-off;
 *  - on triangles (union jack) the row averages follow the exact Kynch
 *    solution about as closely as the 1-D run;
 *  - a cellular mixture flow (face fluxes from a stream function, so
 *    discretely divergence-free) with settling: mass to round-off, 0 <= phi
 *    <= phi_max; without settling a uniform phi stays uniform;
 *  - radial (centrifugal) settling in a 1-D radial line and an annulus,
 *    b = r e_r: the suspension away from the fronts thins as dphi/dt =
 *    -2 phi u(phi) (the divergence of r e_r in cylinders is 2), the annulus
 *    rows equal the radial line. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kynch_run.h"
#include "testing.h"
#include "transport/transport_testing.h"

#define PHI_MAX 0.64

static kx_law law_a;

static sl_transport *open_t(const sl_mesh *m, sl_transport_geometry g, int order) {
  sl_diag d;
  sl_transport *t;
  sl_transport_opts o = {
      .phi_max = PHI_MAX, .order = order, .geometry = g, .settling = kx_settling, .settling_user = &law_a};
  if (sl_transport_create(m, &o, &t, &d)) {
    fprintf(stderr, "transport: %s\n", d.msg);
    exit(1);
  }
  return t;
}

typedef struct totals {
  long substeps;
  int fallbacks;
  double max_phi, min_phi, max_div, clamped;
} totals;

/* Advances phi to time T in outer steps dt; exits on failure. */
static void run(sl_transport *t, const double *q, const double *w, double *phi, double T, double dt, totals *tot) {
  sl_diag d;
  const sl_mesh *m = sl_transport_mesh(t);
  memset(tot, 0, sizeof *tot);
  tot->min_phi = HUGE_VAL;
  for (double time = 0; time < T * (1 - 1e-12);) {
    double h = fmin(dt, T - time);
    sl_transport_stats st;
    if (sl_transport_step(t, h, q, w, phi, &st, &d)) {
      fprintf(stderr, "step at t = %g: %s\n", time, d.msg);
      exit(1);
    }
    time = h == T - time ? T : time + h;
    tot->substeps += st.n_substeps;
    tot->fallbacks += st.n_fallbacks;
    tot->max_div = fmax(tot->max_div, st.max_divergence);
    tot->clamped += st.clamped;
    for (int c = 0; c < m->n_cells; ++c)
      tot->max_phi = fmax(tot->max_phi, phi[c]), tot->min_phi = fmin(tot->min_phi, phi[c]);
  }
}

/* ---- columns ----------------------------------------------------------------- */

static void test_columns(void) {
  const int N = 60, NX = 3;
  kynch k;
  CHECK(kx_init(&k, law_a, 1.0, 0.1) == 0);
  double T = 1.3 * k.t1;
  for (int order = 1; order <= 2; ++order) {
    kr_run r1;
    kr_open(&r1, N, 1.0, 0.1, order, SL_LIMITER_MC, kx_settling, &law_a, PHI_MAX);
    r1.dt_outer = 0.05;
    kr_advance(&r1, T);
    for (int axi = 0; axi <= 1; ++axi) {
      sl_diag d;
      sl_mesh *m;
      int rc = axi ? sl_mesh_annulus(0, 0.3, 0, 1, NX, N, NULL, &m, &d)
                   : sl_mesh_rectangle(0, 0.3, 0, 1, NX, N, NULL, &m, &d);
      CHECK(rc == 0);
      sl_transport *t = open_t(m, axi ? SL_TRANSPORT_AXISYMMETRIC : SL_TRANSPORT_PLANAR, order);
      double *w = alloc(m->n_faces), *phi = alloc(m->n_cells);
      const double down[2] = {0, -1};
      sl_transport_settling_uniform(t, down, w);
      for (int c = 0; c < m->n_cells; ++c) phi[c] = 0.1;
      double m0 = sl_transport_mass(t, phi);
      totals tot;
      run(t, NULL, w, phi, T, 0.05, &tot);
      double worst = 0;
      for (int c = 0; c < m->n_cells; ++c) {
        int row = (int)(sl_transport_cell_points(t)[2 * c + 1] * N);
        worst = fmax(worst, fabs(phi[c] - r1.phi[row]));
      }
      double dm = fabs(sl_transport_mass(t, phi) - m0) / m0;
      printf(
          "%s quads %dx%d, order %d: columns against the 1-D run: max |difference| %.1e, mass error %.1e, "
          "sub-steps %ld (1-D %ld)\n",
          axi ? "axisymmetric" : "planar", NX, N, order, worst, dm, tot.substeps, r1.substeps);
      CHECK(worst < 1e-12 && dm < 1e-13 && tot.substeps == r1.substeps && tot.fallbacks == 0);
      free(w), free(phi);
      sl_transport_destroy(t);
      sl_mesh_destroy(m);
    }
    kr_close(&r1);
  }
}

/* ---- triangles --------------------------------------------------------------- */

static void test_triangles(void) {
  const int N = 80, NX = 4;
  kynch k;
  CHECK(kx_init(&k, law_a, 1.0, 0.1) == 0);
  double T = 0.8 * k.t1;
  for (int order = 1; order <= 2; ++order) {
    kr_run r1;
    kr_open(&r1, N, 1.0, 0.1, order, SL_LIMITER_MC, kx_settling, &law_a, PHI_MAX);
    kr_advance(&r1, T);
    double l1_1d = kr_l1(&r1, &k);
    sl_diag d;
    sl_mesh *m;
    sl_grid_opts go = {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK};
    CHECK(sl_mesh_rectangle(0, 0.2, 0, 1, NX, N, &go, &m, &d) == 0);
    sl_transport *t = open_t(m, SL_TRANSPORT_PLANAR, order);
    double *w = alloc(m->n_faces), *phi = alloc(m->n_cells), row_mass[80] = {0}, row_vol[80] = {0};
    const double down[2] = {0, -1};
    sl_transport_settling_uniform(t, down, w);
    for (int c = 0; c < m->n_cells; ++c) phi[c] = 0.1;
    double m0 = sl_transport_mass(t, phi);
    totals tot;
    run(t, NULL, w, phi, T, 0.01, &tot);
    const double *V = sl_transport_volumes(t);
    for (int c = 0; c < m->n_cells; ++c) {
      int row = (int)(sl_transport_cell_points(t)[2 * c + 1] * N);
      row_mass[row] += V[c] * phi[c], row_vol[row] += V[c];
    }
    kx_profile p = kx_at(&k, T);
    double l1 = 0, spread = 0;
    for (int j = 0; j < N; ++j)
      l1 += fabs(row_mass[j] / row_vol[j] - kx_integral(&k, &p, (double)j / N, (j + 1.0) / N) * N) / N;
    for (int c = 0; c < m->n_cells; ++c) {
      int row = (int)(sl_transport_cell_points(t)[2 * c + 1] * N);
      spread = fmax(spread, fabs(phi[c] - row_mass[row] / row_vol[row]));
    }
    double dm = fabs(sl_transport_mass(t, phi) - m0) / m0;
    printf(
        "triangles (union jack) %dx%dx4, order %d, t = 0.8 t1: row-average L1 %.3e (1-D run %.3e), largest "
        "departure from the row average %.2e, mass error %.1e, phi in [%.2g, %.6f], %d first-order fallbacks in "
        "%ld sub-steps, round-off clamped %.1e\n",
        NX, N, order, l1, l1_1d, spread, dm, tot.min_phi, tot.max_phi, tot.fallbacks, tot.substeps, tot.clamped);
    CHECK(l1 < 1.5 * l1_1d);
    CHECK(dm < 1e-13 && tot.min_phi >= 0 && tot.max_phi <= PHI_MAX);
    free(w), free(phi);
    sl_transport_destroy(t);
    sl_mesh_destroy(m);
    kr_close(&r1);
  }
}

/* ---- cellular flow ------------------------------------------------------------- */

/* q_f = psi(b) - psi(a) along the face a -> b (the owner's counter-clockwise
 * order): int u.n ds for u = (psi_y, -psi_x), so each cell's fluxes sum to
 * zero up to round-off, and psi = 0 on the walls. */
static void cellular_fluxes(const sl_mesh *m, double U, double *q) {
  for (int f = 0; f < m->n_faces; ++f) {
    const double *a = m->xy + 2 * m->face_vertices[2 * f], *b = m->xy + 2 * m->face_vertices[2 * f + 1];
    double pa = U / M_PI * sin(M_PI * a[0]) * sin(M_PI * a[1]), pb = U / M_PI * sin(M_PI * b[0]) * sin(M_PI * b[1]);
    q[f] = pb - pa;
  }
}

static void test_cellular(void) {
  for (int tri = 0; tri <= 1; ++tri)
    for (int order = 1; order <= 2; ++order) {
      sl_diag d;
      sl_mesh *m;
      sl_grid_opts go = {.cell_type = tri ? SL_CELL_TRI3 : SL_CELL_QUAD4, .diagonal = SL_DIAGONAL_RIGHT};
      CHECK(sl_mesh_rectangle(0, 1, 0, 1, 32, 32, &go, &m, &d) == 0);
      sl_transport *t = open_t(m, SL_TRANSPORT_PLANAR, order);
      double *w = alloc(m->n_faces), *q = alloc(m->n_faces), *phi = alloc(m->n_cells);
      const double down[2] = {0, -1};
      sl_transport_settling_uniform(t, down, w);
      cellular_fluxes(m, 2.0, q);
      /* Without settling a uniform phi stays uniform. */
      for (int c = 0; c < m->n_cells; ++c) phi[c] = 0.2;
      totals tot;
      run(t, q, NULL, phi, 0.5, 0.05, &tot);
      double dev = 0;
      for (int c = 0; c < m->n_cells; ++c) dev = fmax(dev, fabs(phi[c] - 0.2));
      CHECK_MSG(dev < 1e-13, "uniform phi in the cellular flow drifts by %g", dev);
      /* With settling: a blob of suspension stirred and settling. */
      for (int c = 0; c < m->n_cells; ++c) {
        const double *x = sl_transport_cell_points(t) + 2 * c;
        phi[c] = hypot(x[0] - 0.5, x[1] - 0.6) < 0.3 ? 0.3 : 0.02;
      }
      double m0 = sl_transport_mass(t, phi);
      run(t, q, w, phi, 3.0, 0.05, &tot);
      double dm = fabs(sl_transport_mass(t, phi) - m0) / m0;
      double bottom = 0;
      for (int c = 0; c < m->n_cells; ++c) bottom = fmax(bottom, phi[c]);
      printf(
          "cellular flow + settling, %s 32x32, order %d, t = 3: mass error %.1e, phi in [%.2g, %.6f], largest "
          "relative divergence of q %.1e, uniform phi without settling kept to %.1e, %d fallbacks in %ld "
          "sub-steps, round-off clamped %.1e\n",
          tri ? "triangles" : "quads", order, dm, tot.min_phi, tot.max_phi, tot.max_div, dev, tot.fallbacks,
          tot.substeps, tot.clamped);
      CHECK(dm < 1e-13 && tot.min_phi >= 0 && tot.max_phi <= PHI_MAX && tot.max_div < 1e-15 &&
            tot.clamped < 1e-15 * m0);
      CHECK(bottom > 0.3); /* a sediment forms where the flow lets it */
      free(w), free(q), free(phi);
      sl_transport_destroy(t);
      sl_mesh_destroy(m);
    }
}

/* ---- radial settling ----------------------------------------------------------- */

static void radial(void *user, const double x[2], double b[2]) {
  (void)user;
  b[0] = x[0], b[1] = 0;
}

/* dphi/dt = -2 phi u(phi) by RK4. */
static double plateau_exact(double phi, double T) {
  const int n = 20000;
  double h = T / n;
  for (int i = 0; i < n; ++i) {
    double k1 = -2 * kx_F(&law_a, phi), k2 = -2 * kx_F(&law_a, phi + h / 2 * k1);
    double k3 = -2 * kx_F(&law_a, phi + h / 2 * k2), k4 = -2 * kx_F(&law_a, phi + h * k3);
    phi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return phi;
}

static void test_radial(void) {
  const int N = 64;
  const double T = 0.15, r0 = 0.2, r1 = 1.0;
  double exact = plateau_exact(0.1, T);
  for (int order = 1; order <= 2; ++order) {
    sl_diag d;
    sl_mesh *m1, *m2;
    CHECK(sl_mesh_interval(r0, r1, N, NULL, &m1, &d) == 0);
    CHECK(sl_mesh_annulus(r0, r1, 0, 0.1, N, 2, NULL, &m2, &d) == 0);
    sl_transport *t1 = open_t(m1, SL_TRANSPORT_AXISYMMETRIC, order), *t2 = open_t(m2, SL_TRANSPORT_AXISYMMETRIC, order);
    double *w1 = alloc(m1->n_faces), *w2 = alloc(m2->n_faces), *p1 = alloc(N), *p2 = alloc(m2->n_cells);
    sl_transport_settling_field(t1, radial, NULL, w1);
    sl_transport_settling_field(t2, radial, NULL, w2);
    for (int c = 0; c < N; ++c) p1[c] = 0.1;
    for (int c = 0; c < m2->n_cells; ++c) p2[c] = 0.1;
    double m10 = sl_transport_mass(t1, p1), m20 = sl_transport_mass(t2, p2);
    totals tot1, tot2;
    run(t1, NULL, w1, p1, T, 0.01, &tot1);
    run(t2, NULL, w2, p2, T, 0.01, &tot2);
    double mid = p1[N / 2], e = fabs(mid / exact - 1), worst = 0;
    for (int c = 0; c < m2->n_cells; ++c) {
      int col = (int)((sl_transport_cell_points(t2)[2 * c] - r0) / (r1 - r0) * N);
      worst = fmax(worst, fabs(p2[c] - p1[col]));
    }
    double dm1 = fabs(sl_transport_mass(t1, p1) - m10) / m10, dm2 = fabs(sl_transport_mass(t2, p2) - m20) / m20;
    printf(
        "radial settling b = r e_r, order %d, t = %g: plateau phi %.8f, exact (dphi/dt = -2 phi u) %.8f, "
        "error %.1e; annulus rows against the radial line %.1e; mass errors %.1e, %.1e; outer cell %.5f\n",
        order, T, mid, exact, e, worst, dm1, dm2, p1[N - 1]);
    CHECK(e < (order == 1 ? 2e-3 : 1e-5));
    CHECK(worst < 1e-12 && dm1 < 1e-13 && dm2 < 1e-13);
    CHECK(tot1.max_phi <= PHI_MAX && tot1.min_phi >= 0 && p1[N - 1] > 0.3);
    free(w1), free(w2), free(p1), free(p2);
    sl_transport_destroy(t1);
    sl_transport_destroy(t2);
    sl_mesh_destroy(m1);
    sl_mesh_destroy(m2);
  }
}

int main(void) {
  law_a = kx_richardson_zaki(1.0, 4.65, PHI_MAX);
  test_columns();
  test_triangles();
  test_cellular();
  test_radial();
  return sl_test_summary();
}
