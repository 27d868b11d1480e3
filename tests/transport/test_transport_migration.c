/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The shear-induced migration flux (migration.h) and the transport's extra
 * flux hook:
 *  - the two-point face flux against the continuum flux
 *    N = -D_c d(g phi)/dx - D_mu d(ln mu)/dx at the faces, for smooth phi
 *    and g: second order, planar and on an axisymmetric radial line;
 *  - the stable step is sharp: an Euler step of dt_stable empties the
 *    limiting cell exactly (phi = 0.3 between empty cells), 1 % more
 *    overshoots below 0; no flux between empty cells, none for uniform phi
 *    and g;
 *  - the bounds limiter of the extra flux (a synthetic flux far too large
 *    for the step): phi stays in [0, phi_max), each stage closes at most
 *    half the gap to phi_max, mass to round-off, the scalings are counted;
 *  - failures: a failing or non-finite extra flux, a dt_stable <= 0, an
 *    infinite ln mu (phi at phi_max), a negative shear rate; phi is left as
 *    it was;
 *  - migration across periodic pairs: a frozen shear rate g = 1 + 0.5
 *    sin(2 pi x) on a periodic interval and on a periodic 2-D box: the
 *    steady state phi g mu^(K_mu/K_c) = const (Nigam eq 4.199) at second
 *    order; every row of the box equals the interval run;
 *  - axisymmetric 2-D: an annulus periodic in z reaches, column by column,
 *    the radial line's steady state (migration with g = 1/r^2; the annulus
 *    takes more sub-steps: its z faces count in the stable step). */
#include "migration_exact.h"
#include "testing.h"
#include "transport/transport_testing.h"

static sl_transport *open_t(const sl_mesh *m, int order, sl_transport_geometry geo) {
  sl_diag d;
  sl_transport *t;
  sl_transport_opts o = {.phi_max = MX_PHI_M, .order = order, .geometry = geo, .settling = mx_no_settling};
  if (sl_transport_create(m, &o, &t, &d)) mx_die("transport", &d);
  return t;
}

static sl_migration *open_mg(sl_transport *t, mx_params *p) {
  sl_diag d;
  sl_migration *mg;
  sl_migration_opts mo = {.coef = mx_coef, .coef_user = p, .ln_mu = mx_lnmu};
  if (sl_migration_create(t, &mo, &mg, &d)) mx_die("migration", &d);
  return mg;
}

/* ---- the face flux against the continuum flux -------------------------------------------- */

static double f_phi(double x) { return 0.35 + 0.15 * sin(2.5 * x); }
static double f_dphi(double x) { return 0.375 * cos(2.5 * x); }
static double f_g(double x) { return 1 + x * x; }
static double f_dg(double x) { return 2 * x; }

static void test_flux_accuracy(void) {
  mx_params p = {1e-2, MX_KC, MX_KMU};
  for (int axi = 0; axi <= 1; ++axi) {
    double err[3];
    for (int l = 0; l < 3; ++l) {
      int N = 20 << l;
      sl_diag d;
      sl_mesh *m;
      if (sl_mesh_interval(0.2, 1.2, N, NULL, &m, &d)) mx_die("mesh", &d);
      sl_transport *t = open_t(m, 2, axi ? SL_TRANSPORT_AXISYMMETRIC : SL_TRANSPORT_PLANAR);
      sl_migration *mg = open_mg(t, &p);
      const double *xc = sl_transport_cell_points(t), *xf = sl_transport_face_points(t);
      const double *A = sl_transport_face_areas(t);
      double *phi = alloc(N), *g = alloc(N), *flux = alloc(m->n_faces), dt;
      for (int c = 0; c < N; ++c) phi[c] = f_phi(xc[2 * c]), g[c] = f_g(xc[2 * c]);
      CHECK(sl_migration_set_shear_rate(mg, g, &d) == 0);
      CHECK(sl_migration_flux(mg, phi, flux, &dt, &d) == 0);
      err[l] = 0;
      for (int f = 0; f < m->n_faces; ++f) {
        if (m->face_cells[2 * f + 1] < 0) {
          CHECK(flux[f] == 0); /* walls carry none */
          continue;
        }
        double x = xf[2 * f], ph = f_phi(x), gg = f_g(x), n = sl_transport_cell_points(t)[0] < x ? 1 : -1;
        double dgphi = f_dg(x) * ph + gg * f_dphi(x), dlnmu = MX_EXPO / (MX_PHI_M - ph) * f_dphi(x);
        double N_exact = -(MX_KC * p.a2 * ph * dgphi + MX_KMU * p.a2 * gg * ph * ph * dlnmu);
        double nx[2];
        sl_mesh_face_normal(m, f, nx);
        (void)n;
        err[l] = fmax(err[l], fabs(flux[f] / A[f] - N_exact * nx[0]));
      }
      free(phi), free(g), free(flux);
      sl_migration_destroy(mg);
      sl_transport_destroy(t);
      sl_mesh_destroy(m);
    }
    double o1 = log2(err[0] / err[1]), o2 = log2(err[1] / err[2]);
    printf("%s face flux against the continuum flux: max error %.2e, %.2e, %.2e (N = 20, 40, 80), orders %.2f, %.2f\n",
           axi ? "axisymmetric" : "planar", err[0], err[1], err[2], o1, o2);
    CHECK_MSG(o1 > 1.9 && o2 > 1.9, "orders %.2f %.2f", o1, o2);
  }
}

/* ---- the stable step --------------------------------------------------------------------- */

static void test_stable_step(void) {
  mx_params p = {1e-3, MX_KC, MX_KMU};
  sl_diag d;
  sl_mesh *m;
  if (sl_mesh_interval(0, 1, 5, NULL, &m, &d)) mx_die("mesh", &d);
  sl_transport *t = open_t(m, 1, SL_TRANSPORT_PLANAR);
  sl_migration *mg = open_mg(t, &p);
  double phi[5] = {0, 0, 0.3, 0, 0}, g[5] = {2, 2, 2, 2, 2}, flux[6], dt;
  const double *V = sl_transport_volumes(t);
  CHECK(sl_migration_set_shear_rate(mg, g, &d) == 0);
  CHECK(sl_migration_flux(mg, phi, flux, &dt, &d) == 0);
  CHECK(sl_migration_limiting_cell(mg) == 2);
  double over = 0, cell2 = 0, lowest = 0;
  for (int k = 0; k < 2; ++k) {
    double h = k ? 1.01 * dt : dt, res[5] = {0};
    for (int f = 0; f < m->n_faces; ++f) {
      int o = m->face_cells[2 * f], n = m->face_cells[2 * f + 1];
      if (n < 0) continue;
      res[o] -= flux[f], res[n] += flux[f];
    }
    for (int c = 0; c < 5; ++c) {
      double v = phi[c] + h * res[c] / V[c];
      if (k) over = fmin(over, v);
      else lowest = fmin(lowest, v);
      if (c == 2 && !k) cell2 = v;
    }
  }
  int zero_faces = 0;
  for (int f = 0; f < m->n_faces; ++f) {
    int o = m->face_cells[2 * f], n = m->face_cells[2 * f + 1];
    if (n >= 0 && phi[o] == 0 && phi[n] == 0) zero_faces += flux[f] == 0;
  }
  printf(
      "phi = 0.3 between empty cells: dt_stable %.6e; after it the cell holds %.1e (lowest %.1e); after 1.01 "
      "dt_stable %.2e\n",
      dt, cell2, lowest, over);
  CHECK(fabs(cell2) < 1e-15 && lowest >= -1e-15 && over < -1e-3);
  CHECK(zero_faces == 2);
  /* Uniform phi and g: no flux; zero shear: no flux and dt = +inf. */
  double u[5] = {0.4, 0.4, 0.4, 0.4, 0.4};
  CHECK(sl_migration_flux(mg, u, flux, &dt, &d) == 0);
  double fmax_ = 0;
  for (int f = 0; f < m->n_faces; ++f) fmax_ = fmax(fmax_, fabs(flux[f]));
  CHECK_MSG(fmax_ == 0, "uniform state: flux %g", fmax_);
  double g0[5] = {0};
  CHECK(sl_migration_set_shear_rate(mg, g0, &d) == 0);
  CHECK(sl_migration_flux(mg, phi, flux, &dt, &d) == 0 && dt == HUGE_VAL);
  CHECK(sl_migration_limiting_cell(mg) == -1);
  sl_migration_destroy(mg);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
}

/* ---- the bounds limiter and failures ----------------------------------------------------- */

typedef struct synthetic {
  double F;  /* flux through the faces, from left to right */
  double dt; /* the stable step it claims */
  int mode;  /* 0: fine, 1: fail, 2: NaN, 3: dt = 0 */
  int calls;
} synthetic;

static int synthetic_flux(void *user, const double *phi, double *flux, double *dt, sl_diag *d) {
  synthetic *s = user;
  ++s->calls;
  (void)phi;
  if (s->mode == 1) return sl_diag_set(d, SL_EFAILED, "synthetic failure");
  for (int f = 0; f < 4; ++f) flux[f] = s->mode == 2 && f == 2 ? NAN : s->F;
  *dt = s->mode == 3 ? 0 : s->dt;
  return 0;
}

static void test_limiter(void) {
  sl_diag d;
  sl_mesh *m;
  if (sl_mesh_interval(0, 1, 3, NULL, &m, &d)) mx_die("mesh", &d);
  for (int order = 1; order <= 2; ++order) {
    sl_transport *t = open_t(m, order, SL_TRANSPORT_PLANAR);
    synthetic s = {.F = 1.0, .dt = 1e9};
    CHECK(sl_transport_set_extra_flux(t, synthetic_flux, &s, &d) == 0);
    double phi[3] = {0.5, 0.6, 0.3}, m0 = sl_transport_mass(t, phi), gap1 = MX_PHI_M - phi[2];
    sl_transport_stats st;
    CHECK(sl_transport_step(t, 1.0, NULL, NULL, phi, &st, &d) == 0);
    double m1 = sl_transport_mass(t, phi);
    printf(
        "order %d, synthetic flux 1.0 through 3 cells for dt = 1: phi = (%.6f, %.6f, %.6f), %d sub-steps, "
        "%d faces limited, %.3e held back, mass change %.1e\n",
        order, phi[0], phi[1], phi[2], st.n_substeps, st.n_extra_limited, st.extra_limited, fabs(m1 - m0) / m0);
    CHECK(st.n_substeps == 1 && st.n_extra_limited > 0 && st.extra_limited > 0);
    CHECK(fabs(m1 - m0) <= 1e-15 * m0);
    CHECK(phi[0] >= 0 && phi[1] < MX_PHI_M && phi[2] < MX_PHI_M);
    /* The last cell received: at most half its gap (Euler), or the mean of two such stages (SSP-RK2). */
    CHECK_MSG(phi[2] - 0.3 <= 0.5 * gap1 + 1e-15, "phi[2] = %.17g", phi[2]);
    CHECK(st.dt_extra == 0.9 * 1e9);
    /* Failures leave phi as it was. */
    double keep[3] = {phi[0], phi[1], phi[2]};
    const char *want[4] = {NULL, "synthetic failure", "the extra flux is nan at face 2", "gave a stable step 0"};
    for (int mode = 1; mode <= 3; ++mode) {
      s.mode = mode;
      int rc = sl_transport_step(t, 1.0, NULL, NULL, phi, &st, &d);
      CHECK(rc == SL_EFAILED);
      CHECK_CONTAINS(d.msg, want[mode]);
      CHECK(phi[0] == keep[0] && phi[1] == keep[1] && phi[2] == keep[2]);
    }
    /* Removing the hook: nothing moves. */
    CHECK(sl_transport_set_extra_flux(t, NULL, NULL, &d) == 0);
    CHECK(sl_transport_step(t, 1.0, NULL, NULL, phi, &st, &d) == 0 && phi[1] == keep[1] && st.dt_extra == HUGE_VAL);
    sl_transport_destroy(t);
  }
  sl_mesh_destroy(m);
}

/* ln mu that is infinite at phi_max (the module must catch it). */
static int lnmu_inf(void *user, int n, const double *phi, double *L, double *dL, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < n; ++i) {
    L[i] = -MX_EXPO * log1p(-phi[i] / MX_PHI_M);
    dL[i] = MX_EXPO / (MX_PHI_M - phi[i]);
  }
  return 0;
}

static void test_failures(void) {
  mx_params p = {1e-3, MX_KC, MX_KMU};
  sl_diag d;
  sl_mesh *m;
  if (sl_mesh_interval(0, 1, 4, NULL, &m, &d)) mx_die("mesh", &d);
  sl_transport *t = open_t(m, 2, SL_TRANSPORT_PLANAR);
  sl_migration *mg;
  sl_migration_opts mo = {.coef = mx_coef, .coef_user = &p, .ln_mu = lnmu_inf};
  CHECK(sl_migration_create(t, &mo, &mg, &d) == 0);
  CHECK(sl_transport_set_extra_flux(t, sl_migration_flux, mg, &d) == 0);
  double g[4] = {1, 1, -1, 1};
  CHECK(sl_migration_set_shear_rate(mg, g, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "shear rate -1 in cell 2");
  g[2] = 1;
  CHECK(sl_migration_set_shear_rate(mg, g, &d) == 0);
  double phi[4] = {0.3, 0.4, MX_PHI_M, 0.5};
  int rc = sl_transport_step(t, 0.1, NULL, NULL, phi, NULL, &d);
  printf("phi at phi_max: %s\n", d.msg);
  CHECK(rc == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "ln mu = inf");
  CHECK_CONTAINS(d.msg, "in cell 2");
  CHECK(phi[2] == MX_PHI_M && phi[0] == 0.3);
  /* The closure's own refusal is passed on, prefixed. */
  sl_migration_destroy(mg);
  mo.ln_mu = mx_lnmu;
  CHECK(sl_migration_create(t, &mo, &mg, &d) == 0);
  CHECK(sl_transport_set_extra_flux(t, sl_migration_flux, mg, &d) == 0);
  CHECK(sl_migration_set_shear_rate(mg, g, &d) == 0);
  rc = sl_transport_step(t, 0.1, NULL, NULL, phi, NULL, &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "transport: extra flux: migration: ln mu: phi = 0.68");
  sl_migration_opts none = {0};
  sl_migration *bad;
  CHECK(sl_migration_create(t, &none, &bad, &d) == SL_EBADINPUT && bad == NULL);
  sl_migration_destroy(mg);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
}

/* ---- periodic: frozen shear rate, steady state ------------------------------------------ */

static double per_g(double x) { return 1 + 0.5 * sin(2 * M_PI * x); }

/* The exact steady state with frozen g: ln phi - 1.82 (K_mu/K_c) ln(1 - phi/phi_m) = K - ln g(x);
 * planar cell averages over [x0, x1] by 8-point Gauss. */
static double per_exact_avg(double K, double x0, double x1) {
  static const double gx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double gw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double c = 0.5 * (x0 + x1), h = 0.5 * (x1 - x0), s = 0;
  for (int k = 0; k < 4; ++k)
    for (int sg = -1; sg <= 1; sg += 2)
      s += gw[k] * mx_solve(K - log(per_g(c + sg * h * gx[k])), MX_EXPO * MX_KMU / MX_KC);
  return s / 2;
}

/* Runs the interval (box == 0) or the box [0, 1] x [0, 0.2] (N x 1 quads: its walls carry nothing, so it takes
 * the interval's sub-steps) to steady state; returns the max error
 * against the exact cell averages; phi1 (N values, the interval's) is compared with the rows of the box. */
static double per_run(int N, int box, double *phi1, double *row_diff, double *mass_err) {
  mx_params p = {1e-3, MX_KC, MX_KMU};
  sl_diag d;
  sl_mesh *m;
  int rc = box ? sl_mesh_rectangle(0, 1, 0, 0.2, N, 1, NULL, &m, &d) : sl_mesh_interval(0, 1, N, NULL, &m, &d);
  if (rc) mx_die("mesh", &d);
  sl_transport *t = open_t(m, 1, SL_TRANSPORT_PLANAR);
  if (sl_transport_set_periodic_named(t, "left", "right", &d)) mx_die("periodic", &d);
  sl_migration *mg = open_mg(t, &p);
  if (sl_transport_set_extra_flux(t, sl_migration_flux, mg, &d)) mx_die("extra", &d);
  const int nc = m->n_cells;
  const double *xc = sl_transport_cell_points(t);
  double *phi = alloc(nc), *g = alloc(nc), *prev = alloc(nc), *flux = alloc(m->n_faces);
  for (int c = 0; c < nc; ++c) phi[c] = 0.4, g[c] = per_g(xc[2 * c]);
  if (sl_migration_set_shear_rate(mg, g, &d)) mx_die("shear", &d);
  double m0 = sl_transport_mass(t, phi), dts, rate = HUGE_VAL;
  if (sl_migration_flux(mg, phi, flux, &dts, &d)) mx_die("flux", &d);
  long steps = 0;
  while (rate > 1e-10) {
    double dt = 20 * dts;
    memcpy(prev, phi, (size_t)nc * sizeof *phi);
    sl_transport_stats st;
    if (sl_transport_step(t, dt, NULL, NULL, phi, &st, &d)) mx_die("step", &d);
    steps += st.n_substeps;
    rate = 0;
    for (int c = 0; c < nc; ++c) rate = fmax(rate, fabs(phi[c] - prev[c]) / dt);
  }
  *mass_err = fabs(sl_transport_mass(t, phi) - m0) / m0;
  /* The exact constant K for the same mean (bisection: the mean increases with K). */
  double lo = -10, hi = 10, mean = m0 / (box ? 0.2 : 1.0);
  for (int it = 0; it < 100; ++it) {
    double K = 0.5 * (lo + hi), s = 0;
    for (int i = 0; i < N; ++i) s += per_exact_avg(K, (double)i / N, (double)(i + 1) / N);
    if (s / N < mean) lo = K;
    else hi = K;
  }
  double K = 0.5 * (lo + hi), err = 0;
  *row_diff = 0;
  for (int c = 0; c < nc; ++c) {
    int i = (int)(xc[2 * c] * N);
    err = fmax(err, fabs(phi[c] - per_exact_avg(K, (double)i / N, (double)(i + 1) / N)));
    if (box) *row_diff = fmax(*row_diff, fabs(phi[c] - phi1[i]));
    else phi1[c] = phi[c];
  }
  printf(
      "periodic %s, N = %d, frozen g = 1 + 0.5 sin(2 pi x): steady after %ld sub-steps, max |error| %.2e, mass "
      "change %.1e%s",
      box ? "box (N x 1 quads)" : "interval", N, steps, err, *mass_err, box ? "" : "\n");
  if (box) printf(", rows against the interval %.1e\n", *row_diff);
  free(phi), free(g), free(prev), free(flux);
  sl_migration_destroy(mg);
  sl_transport_destroy(t);
  sl_mesh_destroy(m);
  return err;
}

static void test_periodic_migration(void) {
  double e[2], rd, me;
  for (int l = 0; l < 2; ++l) {
    int N = 32 << l;
    double *phi1 = alloc(N);
    e[l] = per_run(N, 0, phi1, &rd, &me);
    CHECK(me < 1e-13);
    double eb = per_run(N, 1, phi1, &rd, &me);
    CHECK(me < 1e-13);
    CHECK_MSG(rd < 1e-13, "the box differs from the interval by %.2e", rd);
    CHECK_MSG(fabs(eb - e[l]) < 1e-13, "box error %.3e, interval %.3e", eb, e[l]);
    free(phi1);
  }
  double o = log2(e[0] / e[1]);
  printf("periodic migration: observed order %.2f\n", o);
  CHECK_MSG(o > 1.8 && e[1] < 1e-3, "order %.2f, error %.2e", o, e[1]);
}

/* ---- axisymmetric 2-D against the radial line -------------------------------------------- */

static void test_annulus(void) {
  mx_params p = {1e-3, MX_KC, MX_KMU};
  const int NR = 16;
  sl_diag d;
  sl_mesh *m1, *m2;
  if (sl_mesh_interval(0.3, 1, NR, NULL, &m1, &d) || sl_mesh_annulus(0.3, 1, 0, 0.1, NR, 3, NULL, &m2, &d))
    mx_die("mesh", &d);
  sl_transport *t1 = open_t(m1, 2, SL_TRANSPORT_AXISYMMETRIC), *t2 = open_t(m2, 2, SL_TRANSPORT_AXISYMMETRIC);
  if (sl_transport_set_periodic_named(t2, "bottom", "top", &d)) mx_die("periodic", &d);
  sl_migration *g1 = open_mg(t1, &p), *g2 = open_mg(t2, &p);
  if (sl_transport_set_extra_flux(t1, sl_migration_flux, g1, &d) ||
      sl_transport_set_extra_flux(t2, sl_migration_flux, g2, &d))
    mx_die("extra", &d);
  double *p1 = alloc(m1->n_cells), *p2 = alloc(m2->n_cells), *s1 = alloc(m1->n_cells), *s2 = alloc(m2->n_cells);
  const double *x1 = sl_transport_cell_points(t1), *x2 = sl_transport_cell_points(t2);
  for (int c = 0; c < m1->n_cells; ++c) p1[c] = 0.45, s1[c] = 1 / (x1[2 * c] * x1[2 * c]);
  for (int c = 0; c < m2->n_cells; ++c) p2[c] = 0.45, s2[c] = 1 / (x2[2 * c] * x2[2 * c]);
  CHECK(sl_migration_set_shear_rate(g1, s1, &d) == 0 && sl_migration_set_shear_rate(g2, s2, &d) == 0);
  double m0 = sl_transport_mass(t2, p2);
  long n1 = 0, n2 = 0;
  double *q1 = alloc(m1->n_cells), *q2 = alloc(m2->n_cells), rate = HUGE_VAL;
  while (rate > 1e-11) {
    sl_transport_stats a, b;
    memcpy(q1, p1, (size_t)m1->n_cells * sizeof *p1);
    memcpy(q2, p2, (size_t)m2->n_cells * sizeof *p2);
    CHECK(sl_transport_step(t1, 100, NULL, NULL, p1, &a, &d) == 0);
    CHECK(sl_transport_step(t2, 100, NULL, NULL, p2, &b, &d) == 0);
    n1 += a.n_substeps, n2 += b.n_substeps;
    rate = 0;
    for (int c = 0; c < m1->n_cells; ++c) rate = fmax(rate, fabs(p1[c] - q1[c]) / 100);
    for (int c = 0; c < m2->n_cells; ++c) rate = fmax(rate, fabs(p2[c] - q2[c]) / 100);
  }
  double diff = 0, moved = 0;
  for (int c = 0; c < m2->n_cells; ++c) {
    int i = (int)((x2[2 * c] - 0.3) / 0.7 * NR);
    diff = fmax(diff, fabs(p2[c] - p1[i]));
  }
  for (int c = 0; c < m1->n_cells; ++c) moved = fmax(moved, fabs(p1[c] - 0.45));
  double me = fabs(sl_transport_mass(t2, p2) - m0) / m0;
  printf(
      "annulus %dx3 periodic in z against the radial line, g = 1/r^2, steady state: phi moved up to %.3f, columns "
      "differ by %.1e, sub-steps %ld / %ld, mass change %.1e\n",
      NR, moved, diff, n2, n1, me);
  CHECK(moved > 0.05 && diff < 1e-9 && me < 1e-13);
  free(q1), free(q2);
  free(p1), free(p2), free(s1), free(s2);
  sl_migration_destroy(g1), sl_migration_destroy(g2);
  sl_transport_destroy(t1), sl_transport_destroy(t2);
  sl_mesh_destroy(m1), sl_mesh_destroy(m2);
}

int main(void) {
  test_flux_accuracy();
  test_stable_step();
  test_limiter();
  test_failures();
  test_periodic_migration();
  test_annulus();
  return sl_test_summary();
}
