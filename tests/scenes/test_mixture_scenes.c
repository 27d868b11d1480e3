/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The mixture scenes of configs/, run through the same entry point as
 * `sluice run` and read back from their output files.
 *
 * kynch_settling (1-D batch settling) against the exact Kynch entropy
 * solution (core/study/kynch_exact.h: shocks, the contact shock and
 * fan of non-convex fluxes, the meeting of the fronts):
 *  - Richardson-Zaki with its packing cut-off at phi0 = 0.05, 0.1, 0.2: the
 *    top interface (the written interface height) and the bottom shock fall
 *    and rise at the exact speeds within 1 % on 200 cells;
 *  - Nigam's (1999) flux (eq 2.36), where the sediment forms through a
 *    contact shock and a rarefaction fan: the shock speed within 1 %, and
 *    the fan's profile below it;
 *  - the L1 error of phi falls at first order with refinement (50 to 400
 *    cells; the rate expected with shocks), for both schemes;
 *  - the solids inventory is conserved to round-off at every output and phi
 *    never exceeds phi_max;
 *  - bad input: phi0 above phi_max is refused with the key and the range.
 * migration_couette (shear-induced migration, Phillips et al. 1992) against
 * Nigam's steady state phi gammadot mu^(K_mu/K_c) = const (eq 4.206, solved
 * here by bisection; it reproduces the reference table): |dphi| <= 0.01 in
 * every cell after 1600 revolutions, the swirl within 0.01 of the reference
 * table, and the mean fraction conserved to round-off. migration_poiseuille
 * (a pipe slice periodic along its axis) against eq 4.210 the same way.
 * boycott (a vessel inclined 45 degrees, the scene's 24 x 32 mesh,
 * tests/scenes/boycott_pnk.h): the front falls more than 1.6 times as fast
 * as in an upright vessel, above PNK's z_F; the clear fluid is PNK's
 * production law (with the run's own front) within 5 %; the part not above
 * the front is the Boycott layer's volume (Nigam 4.117) within 30 %, and
 * the front PNK's with that volume counted within 0.03, at t = 0.2 and 0.3;
 * the stream function is zero on all walls. spinup
 * (light particles in a spinning cylinder, slip along the fluid's
 * acceleration, tests/scenes/spinup_asymptotic.h): the asymptotic theory
 * against the reference table, the kinematic shock within 0.03 of it at four
 * heights, the mixture region within 0.02 of the characteristics at z =
 * 0.1. wave_bed (the pseudo-continuum of Lalli, INSEAN): solids
 * conserved and bounded, the soft bed yields and a stiff one does not. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "boycott_pnk.h"
#include "core/io/output.h"
#include "core/io/sample.h"
#include "core/study/kynch_exact.h"
#include "scene_runner.h"
#include "spinup_asymptotic.h"
#include "testing.h"

static char configs[4096];

SCENE_RUNNERS()

static double scalar(const char *file, const char *name, double t) {
  sl_diag d = {{0}};
  double v = NAN, tf;
  int rc = sl_output_read_scalar(file, name, t, &v, &tf, &d);
  CHECK_MSG(rc == 0 && fabs(tf - t) < 1e-9, "%s: %s at t = %g: %s", file, name, t, d.msg);
  return v;
}

/* phi at output time t (cells of the uniform column). */
static int phi_at(const char *file, double t, int n, double *phi) {
  sl_output_field f;
  sl_diag d = {{0}};
  int rc = sl_output_read_field(file, "phi", t, &f, &d);
  CHECK_MSG(rc == 0 && f.n == n && fabs(f.time - t) < 1e-9, "%s: phi at t = %g: %s", file, t, d.msg);
  if (rc) return rc;
  memcpy(phi, f.values, (size_t)n * sizeof *phi);
  sl_output_field_free(&f);
  return 0;
}

/* The scene's column: 0.5 m, 0.1 mm quartz in water, Stokes u_t. */
static const double H = 0.5, phi_max = 0.64;
static double stokes_ut(void) { return (2650.0 - 1000.0) * 9.81 * 1e-8 / (18.0 * 1e-3); }

/* Speed of the level crossing `level` searched from the top (dir = -1) or
 * from the bottom (dir = +1), by a least-squares line through the output
 * times in [ta, tb]. */
static double crossing(const double *phi, int n, double level, int from_bottom) {
  double h = H / n;
  if (from_bottom) {
    for (int i = 0; i + 1 < n; ++i)
      if (phi[i] >= level && phi[i + 1] < level) return (i + 0.5 + (phi[i] - level) / (phi[i] - phi[i + 1])) * h;
  } else {
    for (int i = n - 1; i > 0; --i)
      if (phi[i] < level && phi[i - 1] >= level) return (i - 0.5 + (phi[i - 1] - level) / (phi[i - 1] - phi[i])) * h;
  }
  return NAN;
}

static double slope(const double *t, const double *z, int m) {
  double st = 0, sz = 0, stt = 0, szt = 0;
  for (int i = 0; i < m; ++i) st += t[i], sz += z[i], stt += t[i] * t[i], szt += t[i] * z[i];
  return (m * szt - st * sz) / (m * stt - st * st);
}

/* Runs the column and checks fronts, bounds and conservation; returns the L1
 * error at t = 0.6 t1 through *l1 when asked. */
static void column(const char *label, const kynch *k, const char *closure, const char *const *sets, const char *out,
                   int n, int check_fronts, double *l1) {
  if (run_ok("kynch_settling", closure ? "closure.hindered_settling" : NULL, closure, sets, out)) return;
  enum { NT = 8 };
  double every = k->t1 / 10, tt[NT], ztop[NT], zbot[NT], zint[NT];
  double *phi = malloc((size_t)n * sizeof *phi);
  double worst_mass = 0.0, worst_phi = 0.0;
  for (int j = 0; j < NT; ++j) {
    double t = (j + 2) * every; /* 0.2 .. 0.9 t1: both fronts formed, not yet met */
    if (phi_at(out, t, n, phi)) break;
    tt[j] = t;
    ztop[j] = crossing(phi, n, 0.5 * k->phi0, 0);
    zbot[j] = crossing(phi, n, 0.5 * (k->phi0 + k->phis), 1);
    zint[j] = scalar(out, "interface_height_0", t);
    worst_mass = fmax(worst_mass, fabs(scalar(out, "solids_conservation_error", t)));
    for (int i = 0; i < n; ++i) worst_phi = fmax(worst_phi, phi[i]);
  }
  if (check_fronts) {
    double e_top = -slope(tt, ztop, NT) / k->v0 - 1, e_int = -slope(tt, zint, NT) / k->v0 - 1;
    double e_bot = slope(tt, zbot, NT) / k->sigma - 1;
    printf("  %s: top %.3f%%, written interface %.3f%%, bottom %.3f%% (exact v0 %.5g, sigma %.5g m/s)\n", label,
           100 * e_top, 100 * e_int, 100 * e_bot, k->v0, k->sigma);
    CHECK_MSG(fabs(e_top) < 0.01, "%s: top interface speed off by %.3g", label, e_top);
    CHECK_MSG(fabs(e_int) < 0.01, "%s: written interface height speed off by %.3g", label, e_int);
    CHECK_MSG(fabs(e_bot) < 0.01, "%s: bottom shock speed off by %.3g", label, e_bot);
  }
  CHECK_MSG(worst_mass < 1e-13, "%s: solids conservation error %.3g", label, worst_mass);
  CHECK_MSG(worst_phi <= k->law.c, "%s: phi reached %.17g > phi_max = %g", label, worst_phi, k->law.c);
  if (l1) {
    double t = 6 * every, h = H / n, e = 0.0;
    kx_profile p = kx_at(k, t);
    if (phi_at(out, t, n, phi) == 0)
      for (int i = 0; i < n; ++i) e += fabs(phi[i] * h - kx_integral(k, &p, i * h, (i + 1) * h));
    *l1 = e;
  }
  free(phi);
}

static void set_every(char *buf, size_t n, double every) { snprintf(buf, n, "output.every=%.17g", every); }

static void richardson_zaki(void) {
  const double phis[3] = {0.05, 0.1, 0.2};
  for (int j = 0; j < 3; ++j) {
    kynch k;
    CHECK(kx_init(&k, kx_richardson_zaki(stokes_ut(), 4.65, phi_max), H, phis[j]) == 0);
    char init[64], every[64], end[64], level[64], label[64];
    snprintf(init, sizeof init, "initial.phi=%.17g", phis[j]);
    set_every(every, sizeof every, k.t1 / 10);
    snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
    snprintf(level, sizeof level, "output.interface=%.17g", 0.5 * phis[j]);
    snprintf(label, sizeof label, "Richardson-Zaki phi0 = %.2f", phis[j]);
    const char *sets[] = {init, every, end, level, NULL};
    column(label, &k, NULL, sets, "kynch_rz.h5", 200, 1, NULL);
  }
}

/* The flux truncated at phi_max (packing_cutoff = step): the bottom shock jumps from phi0 straight to phi_max with
 * the speed phi0 u_t (1-phi0)^n / (phi_max - phi0), faster than with the smooth cut-off's sediment. */
static void richardson_zaki_step(void) {
  kynch k;
  CHECK(kx_init(&k, kx_richardson_zaki_step(stokes_ut(), 4.65, phi_max), H, 0.1) == 0);
  char every[64], end[64];
  set_every(every, sizeof every, k.t1 / 10);
  snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
  const char *sets[] = {"closure.hindered_settling.packing_cutoff=step", every, end, "output.interface=0.05", NULL};
  double sigma = 0.1 * stokes_ut() * pow(0.9, 4.65) / (phi_max - 0.1);
  printf("  Richardson-Zaki truncated at phi_max: exact bottom shock %.6g m/s (the formula's %.6g)\n", k.sigma, sigma);
  CHECK_MSG(fabs(k.sigma / sigma - 1.0) < 1e-12, "exact solution's shock %.10g, the jump condition's %.10g", k.sigma,
            sigma);
  column("Richardson-Zaki truncated, phi0 = 0.10", &k, NULL, sets, "kynch_rz_step.h5", 200, 1, NULL);
}

static void nigam_fan(void) {
  kynch k;
  CHECK(kx_init(&k, kx_nigam(stokes_ut(), 2.5, 0.68), H, 0.1) == 0);
  /* Kynch's construction for Nigam's flux (eq 2.36): phi* = 0.5299, shock 0.12289 u_t, fronts meet at 1.3496 H / u_t */
  CHECK_MSG(fabs(k.phis - 0.5299) < 1e-4, "phi* %.6f", k.phis);
  CHECK_MSG(fabs(k.sigma / stokes_ut() - 0.12289) < 1e-5, "shock speed %.6f u_t", k.sigma / stokes_ut());
  CHECK_MSG(fabs(k.t1 * stokes_ut() / H - 1.3496) < 1e-4, "meeting time %.6f H/u_t", k.t1 * stokes_ut() / H);
  CHECK(k.bottom == KX_CONTACT);
  char every[64], end[64];
  set_every(every, sizeof every, k.t1 / 10);
  snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
  const char *sets[] = {every, end, "solid.phi_max=0.68", NULL};
  static const char nigam[] = "[closure.hindered_settling]\nmodel = nigam\nphi_max = 0.68\n";
  enum { N = 200 };
  column("Nigam flux phi0 = 0.10", &k, nigam, sets, "kynch_nigam.h5", N, 1, NULL);
  /* the fan between the sediment (phi_max at the floor only) and the contact shock */
  double t = 0.6 * k.t1, phi[N], h = H / N, worst = 0.0;
  kx_profile p = kx_at(&k, t);
  if (phi_at("kynch_nigam.h5", t, N, phi)) return;
  for (int i = 0; i < N; ++i) {
    double z = (i + 0.5) * h;
    if (z < 0.2 * k.sigma * t || z > 0.8 * k.sigma * t) continue; /* inside the fan, away from its ends */
    worst = fmax(worst, fabs(phi[i] - kx_integral(&k, &p, i * h, (i + 1) * h) / h));
  }
  printf("  Nigam fan at t = %.4g s: max |phi - exact| = %.3g over its middle 60 %%\n", t, worst);
  CHECK_MSG(worst < 0.02, "fan profile off by %.3g", worst);
}

/* L1 error at 0.6 t1 on 50 .. 400 cells, first and second order. The
 * bottom of a Richardson-Zaki column with its cut-off is a contact shock
 * (tangent to F on its upper side) above a fan: a front that characteristics
 * run along is smeared like a linear discontinuity, over O(h^(p/(p+1)))
 * for a scheme of order p (Harten 1977, Comm. Pure Appl. Math. 30:611), so
 * the L1 rate lies between 1/2 (order 1) or 2/3 (order 2) and the 1 of the
 * compressive top shock. */
static void refinement(void) {
  kynch k;
  CHECK(kx_init(&k, kx_richardson_zaki(stokes_ut(), 4.65, phi_max), H, 0.1) == 0);
  CHECK(k.bottom == KX_CONTACT);
  double e[2][4], rate[2];
  for (int order = 1; order <= 2; ++order) {
    for (int j = 0; j < 4; ++j) {
      int n = 50 << j;
      char cells[64], ord[64], every[64], end[64];
      snprintf(cells, sizeof cells, "mesh.cells=%d", n);
      snprintf(ord, sizeof ord, "transport.order=%d", order);
      set_every(every, sizeof every, k.t1 / 10);
      snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
      const char *sets[] = {cells, ord, every, end, NULL};
      column("refinement", &k, NULL, sets, "kynch_l1.h5", n, 0, &e[order - 1][j]);
    }
    double *x = e[order - 1];
    rate[order - 1] = log(x[0] / x[3]) / log(8.0);
    printf("  order %d: L1 errors %.3g %.3g %.3g %.3g (m), observed rate %.2f\n", order, x[0], x[1], x[2], x[3],
           rate[order - 1]);
  }
  CHECK_MSG(rate[0] > 0.45 && rate[0] < 1.05, "first-order L1 rate %.3g", rate[0]);
  CHECK_MSG(rate[1] > 0.6 && rate[1] < 1.1, "second-order L1 rate %.3g", rate[1]);
  for (int j = 0; j < 4; ++j) CHECK_MSG(e[1][j] < 0.6 * e[0][j], "MUSCL no better than Godunov on %d cells", 50 << j);
}

/* ---- shear-induced migration, wide-gap Couette ------------------------------ */

/* Nigam (1999) eq 4.206 (section 4.5): the steady phi(r) with
 * phi_w at the inner wall R_i, exponent 1.82 (K_mu/K_c - 1). */
static const double Ri = 0.2689, am = 0.68, mig_exp = 1.82 * (0.62 / 0.41 - 1.0);

/* phi / phi_w = geometry [(1 - phi/am) / (1 - phi_w/am)]^e: geometry (r/R_i)^2 in the Couette gap (eq
 * 4.206), 1/r in the pipe (eq 4.210). */
static double steady_phi(double geometry, double aw) {
  double lo = 0.0, hi = am, c = aw * geometry / pow(1 - aw / am, mig_exp);
  for (int it = 0; it < 200; ++it) { /* f(a) = a - c (1 - a/am)^e: increasing, f(0) < 0 < f(am) */
    double a = 0.5 * (lo + hi);
    if (a - c * pow(1 - a / am, mig_exp) < 0) lo = a;
    else hi = a;
  }
  return 0.5 * (lo + hi);
}

static double couette_phi(double r, double aw) { return steady_phi((r / Ri) * (r / Ri), aw); }
static double pipe_phi(double r, double aw) { return steady_phi(1.0 / r, aw); }

/* The area mean int phi r dr / int r dr over the gap (Gauss-Legendre, 64 panels of 4 points). */
static double couette_mean(double aw) {
  static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  double s = 0.0, h = (1.0 - Ri) / 64;
  for (int p = 0; p < 64; ++p)
    for (int k = 0; k < 4; ++k) {
      double r = Ri + h * (p + 0.5 + 0.5 * gx[k]);
      s += 0.5 * h * gw[k] * couette_phi(r, aw) * r;
    }
  return s / (0.5 * (1.0 - Ri * Ri));
}

static void migration_couette(void) {
  /* the inner-wall fraction that holds the mean 0.55 (by bisection: 0.28326) */
  double lo = 0.05, hi = 0.55;
  for (int it = 0; it < 80; ++it) {
    double aw = 0.5 * (lo + hi);
    if (couette_mean(aw) < 0.55) lo = aw;
    else hi = aw;
  }
  double aw = 0.5 * (lo + hi);
  CHECK_MSG(fabs(aw - 0.28326) < 2e-5, "phi_w = %.6f", aw);
  /* the reference table (eq 4.206 with phi_w = 0.283) */
  static const double tr[8] = {0.30, 0.40, 0.50, 0.60, 0.70, 0.80, 0.90, 1.00};
  static const double tphi[8] = {0.3208, 0.4208, 0.4907, 0.5385, 0.5716, 0.5951, 0.6120, 0.6246};
  static const double tv[8] = {0.7115, 0.2620, 0.1087, 0.0491, 0.0231, 0.0105, 0.0039, 0.0};
  for (int i = 0; i < 8; ++i)
    CHECK_MSG(fabs(couette_phi(tr[i], 0.283) - tphi[i]) < 1e-4, "exact phi(%g) = %.5f, table %.4f", tr[i],
              couette_phi(tr[i], 0.283), tphi[i]);
  const char *out = "migration_couette.h5";
  if (run_ok("migration_couette", NULL, NULL, NULL, out)) return;
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "phi", INFINITY, &f, &d) || sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return;
  }
  /* cells are one radial row: the r-centroid of cell c from its nodes' r range */
  double worst = 0.0, where = 0.0;
  for (int c = 0; c < f.n; ++c) {
    double r0 = INFINITY, r1 = -INFINITY;
    for (int k = 0; k < m.nodes_per_cell; ++k) {
      double r = m.coords[(size_t)3 * m.cells[(size_t)c * m.nodes_per_cell + k]];
      r0 = fmin(r0, r), r1 = fmax(r1, r);
    }
    double rc = 2.0 / 3.0 * (r1 * r1 * r1 - r0 * r0 * r0) / (r1 * r1 - r0 * r0);
    double e = fabs(f.values[c] - couette_phi(rc, aw));
    if (e > worst) worst = e, where = rc;
  }
  printf("  migration_couette: max |phi - steady state| = %.4f (at r = %.3f), %d cells, t = %g\n", worst, where, f.n,
         f.time);
  CHECK_MSG(worst <= 0.01, "steady phi off by %.4f at r = %.3f", worst, where);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", f.time)) < 1e-12, "mean phi not conserved");
  /* the swirl against the reference table (Nigam's tolerance 0.01 of the wall speed) */
  double xy[16], v[8];
  for (int i = 0; i < 8; ++i) xy[2 * i] = tr[i] < 1.0 ? tr[i] : 1.0, xy[2 * i + 1] = 0.0625;
  sl_sample s;
  if (sl_sample_points(out, "u_theta", INFINITY, 8, xy, &s, &d) == 0) {
    double wv = 0.0;
    for (int i = 0; i < 8; ++i) v[i] = s.values[(size_t)i * s.components], wv = fmax(wv, fabs(v[i] - tv[i]));
    printf("  migration_couette: max |v - table| = %.4f of the wall speed\n", wv);
    CHECK_MSG(wv <= 0.01, "swirl off by %.4f", wv);
    sl_sample_free(&s);
  } else {
    CHECK_MSG(0, "%s", d.msg);
  }
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
}

/* ---- the Boycott effect -------------------------------------------------------- */

/* The scene's vessel: 45 degrees, L = 0.5, phi0 = 0.1, Nigam's hindrance with
 * Krieger K = 2.5, alpha_m = 0.68, Re / Lambda = 1e3 / 1e5. */
static const boycott_vessel boycott_scene = {0.78539816339744831, 0.5, 0.1, 0.68, 2.5, 1e-2};

/* The clear fluid in the vessel: each cell's volume times 1 - phi/phi0
 * where phi < phi0 (partly clear cells count in part). */
static double clear_volume(const char *out, double t, double phi0) {
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "phi", t, &f, &d) || sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return NAN;
  }
  double v = 0.0;
  for (int c = 0; c < m.n_cells; ++c) {
    const int32_t *q = m.cells + (size_t)c * m.nodes_per_cell; /* the corners first, counter-clockwise */
    double area = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double *p0 = m.coords + 3 * (size_t)q[k], *p1 = m.coords + 3 * (size_t)q[(k + 1) % 4];
      area += 0.5 * (p0[0] * p1[1] - p1[0] * p0[1]);
    }
    if (f.values[c] < phi0) v += fabs(area) * (1 - f.values[c] / phi0);
  }
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
  return v;
}

static void boycott(void) {
  const boycott_vessel *v = &boycott_scene;
  /* the theory against the reference table (A, PNK's front, the sediment at t = 0.3) */
  CHECK_MSG(fabs(boycott_A(v) - 0.618084) < 1e-6 && fabs(boycott_pnk_front(v, 0.3) - 0.6062) < 1e-4 &&
                fabs(boycott_sediment(v, 0.3) - 0.0320) < 1e-4,
            "A %.6f, z_F(0.3) %.4f, S_s(0.3) %.4f", boycott_A(v), boycott_pnk_front(v, 0.3), boycott_sediment(v, 0.3));
  const char *out = "boycott.h5";
  const char *sets[] = {"time.end=0.3", NULL}; /* the scene's 24 x 32 mesh, walls refined */
  if (run_ok("boycott", NULL, NULL, sets, out)) return;
  const double A = boycott_A(v);
  /* the uniform suspension fills the vessel: the interface at its top */
  CHECK_MSG(fabs(scalar(out, "interface_height_0", 0.0) - 1.0) < 1e-12, "interface at t = 0: %.6f",
            scalar(out, "interface_height_0", 0.0));
  double z_prev = 1.0, produced = 0.0, worst_prod = 0.0, worst_layer = 0.0, worst_volume = 0.0, t = 0.3, z = NAN;
  for (int k = 1; k <= 3; ++k) {
    double tk = 0.1 * k;
    z = scalar(out, "interface_height_0", tk);
    /* PNK's production law with the run's own front (trapezoidal rule over the outputs) */
    produced += 0.05 * (boycott_production_rate(v, z_prev, tk - 0.1) + boycott_production_rate(v, z, tk));
    double clear = clear_volume(out, tk, v->alpha0), z_layer = boycott_front_with_layer(v, tk, 2000);
    double pnk = boycott_pnk_front(v, tk);
    /* the clear fluid not above the front, against the layer of (4.117) up to the run's front */
    double layer = clear - boycott_width(v) * (1 - z), layer_theory = boycott_layer_volume(v, z, tk);
    printf(
        "  boycott: t = %.1f: z_F = %.4f, PNK %.4f (lag %.4f), PNK with the layer's volume %.4f; clear fluid %.4f, "
        "produced by PNK's law %.4f (ratio %.3f); in the layer %.4f, (4.117) %.4f (ratio %.3f)\n",
        tk, z, pnk, z - pnk, z_layer, clear, produced, clear / produced, layer, layer_theory, layer / layer_theory);
    CHECK_MSG(z > pnk, "the front %.4f below PNK's %.4f at t = %.1f", z, pnk, tk); /* the layer's volume */
    worst_prod = fmax(worst_prod, fabs(clear / produced - 1));
    if (k >= 2) { /* the layer formed: its transit time along the wall is about 0.17 */
      worst_layer = fmax(worst_layer, fabs(z - z_layer));
      worst_volume = fmax(worst_volume, fabs(layer / layer_theory - 1));
    }
    z_prev = z;
  }
  double enhancement = (1 - z) / (A * t);
  printf(
      "  boycott: descent x%.2f of an upright vessel's (PNK x%.2f); clear fluid within %.3f of PNK's production; "
      "the layer's volume within %.3f of (4.117); front within %.4f of PNK with the layer\n",
      enhancement, (1 - boycott_pnk_front(v, t)) / (A * t), worst_prod, worst_volume, worst_layer);
  /* the front falls much faster than in an upright vessel */
  CHECK_MSG(enhancement > 1.6, "Boycott enhancement x%.2f", enhancement);
  /* PNK's production, A times the interface's horizontal projection: 0.970-0.976 of it (0.975-0.982 on 48 x 64) */
  CHECK_MSG(worst_prod <= 0.05, "clear fluid off PNK's production by %.3f", worst_prod);
  /* the rest of the clear fluid is in the Boycott layer: 0.89 and 0.95 of (4.117)'s volume at t = 0.2 and 0.3
     (0.91, 1.08 on 48 x 64); that profile is expected within +-30 % */
  CHECK_MSG(worst_volume <= 0.3, "the layer's volume off (4.117) by %.3f", worst_volume);
  /* so the front is PNK's with the layer: within 0.001 and 0.016 (0.003, 0.027 on 48 x 64), where the layer's +-30 %
     is 0.036 and 0.026 of front; PNK's own z_F lags by 0.06-0.10 */
  CHECK_MSG(worst_layer <= 0.03, "front off PNK with the layer by %.4f", worst_layer);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", t)) < 1e-13, "solids not conserved");
  /* the stream function of the conservative fluxes: zero on every wall of the closed vessel */
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "stream_function", t, &f, &d) || sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return;
  }
  double wall_max = 0.0, all_max = 0.0, w = sqrt(0.5);
  for (int32_t i = 0; i < f.n; ++i) {
    double x = m.coords[3 * i], y = m.coords[3 * i + 1], psi = fabs(f.values[i]);
    int on_wall = fabs(y) < 1e-12 || fabs(y - 1) < 1e-12 || fabs(x - y) < 1e-12 || fabs(x - y - w) < 1e-12;
    all_max = fmax(all_max, psi);
    if (on_wall) wall_max = fmax(wall_max, psi);
  }
  printf("  boycott: stream function max %.4f inside, %.2g on the walls\n", all_max, wall_max);
  CHECK_MSG(all_max > 0.01 && wall_max < 1e-12 * all_max + 1e-15, "stream function %.3g on walls, %.3g max", wall_max,
            all_max);
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
}

/* The r-centroid of each of the first n cells (the first row of a radial mesh), from the output file's nodes,
 * and their widths when `width` is given. */
static int radial_centroids(const char *out, int n, double *rc, double *width) {
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return -1;
  }
  for (int c = 0; c < n && c < m.n_cells; ++c) {
    double r0 = INFINITY, r1 = -INFINITY;
    for (int k = 0; k < m.nodes_per_cell; ++k) {
      double r = m.coords[(size_t)3 * m.cells[(size_t)c * m.nodes_per_cell + k]];
      r0 = fmin(r0, r), r1 = fmax(r1, r);
    }
    rc[c] = 2.0 / 3.0 * (r1 * r1 * r1 - r0 * r0 * r0) / (r1 * r1 - r0 * r0);
    if (width) width[c] = r1 - r0;
  }
  sl_output_mesh_free(&m);
  return 0;
}

/* Pipe flow, periodic along the axis: Nigam's steady state for r >= 0.2
 * (looser at the axis, where phi -> phi_max with an infinite slope), the
 * velocity against the reference table within 1 %, the mean conserved. */
static void migration_poiseuille(void) {
  double lo = 0.05, hi = 0.40; /* phi_w for the mean 2 int phi r dr = 0.40 (by bisection: 0.31825) */
  for (int it = 0; it < 80; ++it) {
    double aw = 0.5 * (lo + hi), sum = 0.0;
    for (int k = 0; k < 4000; ++k) {
      double r = (k + 0.5) / 4000;
      sum += 2 * pipe_phi(r, aw) * r / 4000;
    }
    if (sum < 0.40) lo = aw;
    else hi = aw;
  }
  double aw = 0.5 * (lo + hi);
  CHECK_MSG(fabs(aw - 0.31825) < 5e-5, "pipe phi_w = %.6f", aw);
  static const double tr[6] = {0.2, 0.4, 0.6, 0.8, 0.9, 1.0},
                      tphi[6] = {0.5615, 0.4727, 0.4072, 0.3572, 0.3365, 0.3180};
  static const double tw[6] = {0.9957, 0.9488, 0.8004, 0.4979, 0.2756, 0.0};
  for (int i = 0; i < 6; ++i)
    CHECK_MSG(fabs(pipe_phi(tr[i], 0.318) - tphi[i]) < 2e-4, "exact pipe phi(%g) = %.5f, table %.4f", tr[i],
              pipe_phi(tr[i], 0.318), tphi[i]);
  const char *out = "migration_poiseuille.h5";
  if (run_ok("migration_poiseuille", NULL, NULL, NULL, out)) return;
  sl_output_field f;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "phi", INFINITY, &f, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return;
  }
  double *rc = malloc((size_t)f.n * sizeof *rc), worst = 0.0, where = 0.0, axis = 0.0;
  if (rc && radial_centroids(out, f.n, rc, NULL) == 0)
    for (int c = 0; c < f.n; ++c) {
      double e = fabs(f.values[c] - pipe_phi(rc[c], aw));
      if (rc[c] >= 0.2 && e > worst) worst = e, where = rc[c];
      if (rc[c] < 0.2) axis = fmax(axis, e);
    }
  printf("  migration_poiseuille: max |phi - steady state| = %.4f for r >= 0.2 (at r = %.3f), %.4f nearer the axis\n",
         worst, where, axis);
  CHECK_MSG(worst <= 0.01, "steady phi off by %.4f at r = %.3f", worst, where);
  CHECK_MSG(axis <= 0.03, "steady phi off by %.4f near the axis", axis);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", f.time)) < 1e-12, "mean phi not conserved");
  double xy[14] = {0, 0.05}, w[7];
  for (int i = 0; i < 6; ++i) xy[2 * i + 2] = tr[i], xy[2 * i + 3] = 0.05;
  sl_sample smp;
  if (sl_sample_points(out, "velocity", INFINITY, 7, xy, &smp, &d) == 0) {
    double ww = 0.0;
    for (int i = 0; i < 7; ++i) w[i] = smp.values[(size_t)i * smp.components + 1];
    for (int i = 0; i < 6; ++i) ww = fmax(ww, fabs(w[i + 1] / w[0] - tw[i]));
    printf("  migration_poiseuille: max |w/w(0) - table| = %.4f\n", ww);
    CHECK_MSG(ww <= 0.01, "velocity profile off by %.4f", ww);
    sl_sample_free(&smp);
  } else {
    CHECK_MSG(0, "%s", d.msg);
  }
  free(rc);
  sl_output_field_free(&f);
}

/* ---- spin-up of a light-particle suspension ------------------------------------ */

/* Nigam (1999) section 4.1: the kinematic shock r_s and the mixture-side
 * fraction alpha_s of the asymptotic theory (Amberg & Ungarish 1993;
 * Nigam 1999 eqs 4.57-4.64) at t = 25 (tau = 0.572), heights z; and its
 * radial profile at t = 50, z = 0.225. */
static const double spin_z[4] = {0.10, 0.15, 0.20, 0.225};
static const double spin_rs[4] = {0.8711, 0.8401, 0.8142, 0.7993}, spin_as[4] = {0.186, 0.224, 0.263, 0.288};
static const double spin50_r[10] = {0.3545, 0.3907, 0.4269, 0.4631, 0.4993, 0.5355, 0.5717, 0.6079, 0.6441, 0.6803};
static const double spin50_a[10] = {0.137, 0.173, 0.203, 0.228, 0.249, 0.267, 0.283, 0.297, 0.309, 0.319};

/* The scene's parameters: H = 0.5, E = 1e-4, beta = 0.04, eps = -0.5, phi0 =
 * 0.1, Krieger mu with K = 2.5, alpha_m = 0.68 (configs/spinup.ini). */
static spinup_theory spin_theory(double *tau_per_t) {
  const double H_cyl = 0.5, E = 1e-4, beta = 0.04, eps = -0.5, a0 = 0.1, K = 2.5, alpha_m = 0.68;
  double mu0 = pow(1 - a0 / alpha_m, -K * alpha_m), root = sqrt(mu0 * E);
  *tau_per_t = root / H_cyl;
  spinup_theory s = {kx_nigam(1.0, K, alpha_m), H_cyl * eps * beta / root, H_cyl, a0};
  return s;
}

/* The asymptotic solution written here (tests/scenes/spinup_asymptotic.h)
 * against an independently integrated reference table (the characteristics and
 * shock equations, eqs 4.57-4.64, with 400-800 characteristics). */
static void spinup_theory_table(void) {
  double tau_per_t;
  spinup_theory s = spin_theory(&tau_per_t);
  CHECK_MSG(fabs(s.kappa + 0.8735) < 1e-4 && fabs(tau_per_t - 0.022896) < 1e-6, "kappa %.5f, tau/t %.6f", s.kappa,
            tau_per_t);
  double worst = 0.0;
  for (int k = 0; k < 4; ++k) /* alpha_s = alpha on the theory's characteristics at r_s */
    worst = fmax(worst, fabs(spinup_alpha(&s, spin_rs[k], spin_z[k], 25 * tau_per_t) - spin_as[k]));
  for (int i = 0; i < 10; ++i)
    worst = fmax(worst, fabs(spinup_alpha(&s, spin50_r[i], 0.225, 50 * tau_per_t) - spin50_a[i]));
  printf("  spinup: the characteristics give the reference alpha_s and t = 50 profile within %.1e\n", worst);
  CHECK_MSG(worst <= 1e-3, "asymptotic alpha off the reference table by %.2e", worst); /* the table's 3 decimals */
  CHECK(spinup_alpha(&s, 0.5, 0.225, 25 * tau_per_t) == 0.1); /* the non-rotating core, r < e^-tau = 0.564 */
}

/* scheme: the [flow] scheme override (NULL: the scene's). */
static void spinup(const char *scheme) {
  if (!scheme) spinup_theory_table();
  const char *out = scheme ? "spinup_split.h5" : "spinup.h5";
  enum { N = 48 }; /* the cells along r (the scene's grading refines them towards the wall) */
  const char *sets[] = {"time.end=25", "mesh.cells=48,24", "solver.nonlinear_tolerance=1e-6", scheme, NULL};
  if (run_ok("spinup", NULL, NULL, sets, out)) return;
  const double t = 25.0;
  double tau_per_t, rc[N], h[N];
  spinup_theory th = spin_theory(&tau_per_t);
  const double tau = t * tau_per_t, r_front = exp(-tau);
  static double xy[2 * N];
  sl_diag d = {{0}};
  if (radial_centroids(out, N, rc, h)) return; /* the first row of cells: the columns' centroids and widths */
  double worst = 0.0, worst_a = 0.0, near_lid = 0.0;
  for (int k = 0; k < 4; ++k) {
    /* phi at the cells' centroids, from the wall inwards */
    for (int i = 0; i < N; ++i) xy[2 * i] = rc[N - 1 - i], xy[2 * i + 1] = spin_z[k];
    sl_sample smp;
    if (sl_sample_points(out, "phi", t, N, xy, &smp, &d)) {
      CHECK_MSG(0, "%s", d.msg);
      return;
    }
    /* the shock: coming in from the clear fluid at the wall, where phi first reaches alpha_s / 2
       (linear between cell centres) */
    double rs = NAN, amax = 0.0;
    for (int i = 1; i < N && isnan(rs); ++i)
      if (smp.values[i] >= 0.5 * spin_as[k]) {
        double p0 = smp.values[i - 1], p1 = smp.values[i];
        rs = xy[2 * (i - 1)] + (xy[2 * i] - xy[2 * (i - 1)]) * (0.5 * spin_as[k] - p0) / (p1 - p0);
      }
    for (int i = 0; i < N; ++i) amax = fmax(amax, smp.values[i]);
    /* the mixture region against the characteristics, between the viscously smeared spin-up front (2 (mu E
       t)^(1/2) = 0.076 wide) and three cells inside the shock */
    double dev = 0.0;
    for (int i = 0; i < N; ++i) {
      double r = xy[2 * i];
      if (r < r_front + 0.08 || r > spin_rs[k] - 3 * h[N - 1 - i]) continue;
      dev = fmax(dev, fabs(smp.values[i] - spinup_alpha(&th, r, spin_z[k], tau)));
    }
    sl_sample_free(&smp);
    printf(
        "  spinup: t = %g, z = %.3f (left the lid at t = %.1f): shock at r = %.4f (theory %.4f), largest phi %.3f "
        "(mixture side %.3f), mixture region within %.3f of the characteristics\n",
        t, spin_z[k], spinup_departure(&th, spin_z[k], tau) / tau_per_t, rs, spin_rs[k], amax, spin_as[k], dev);
    worst = fmax(worst, fabs(rs - spin_rs[k]));
    if (!isnan(rs)) worst_a = fmax(worst_a, fabs(amax - spin_as[k]));
    if (k == 0) near_lid = dev;
    CHECK_MSG(!isnan(rs), "no shock at z = %g", spin_z[k]);
  }
  printf("  spinup: shock position within %.4f of the theory, mixture-side phi within %.3f\n", worst, worst_a);
  CHECK_MSG(worst <= 0.03, "shock off the theory by %.4f", worst); /* 2-3 cells of the 128 x 64 grid */
  /* 0.02 for alpha in the mixture region, where the theory's lid layers had formed when the fluid left
     them (z = 0.1: t = 11.5, some two revolutions) */
  CHECK_MSG(near_lid <= 0.02, "mixture region at z = 0.1 off the characteristics by %.3f", near_lid);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", t)) < 1e-13, "solids not conserved");
}

/* ---- a gravity wave over a Bingham bed (Lalli, INSEAN) -------------------------- */

/* The mean of `yielded` over the bed's cells (y < 0.15, below its smeared
 * surface at 0.2) at time t, and the extreme phi of the whole field. */
static double bed_yielded(const char *out, double t, double *phi_lo, double *phi_hi) {
  sl_output_field y, p;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "yielded", t, &y, &d) || sl_output_read_field(out, "phi", t, &p, &d) ||
      sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return NAN;
  }
  double sum = 0.0;
  int n = 0;
  *phi_lo = INFINITY, *phi_hi = -INFINITY;
  for (int c = 0; c < m.n_cells; ++c) {
    double yc = 0.0;
    for (int k = 0; k < m.nodes_per_cell; ++k)
      yc += m.coords[(size_t)3 * m.cells[(size_t)c * m.nodes_per_cell + k] + 1];
    if (yc / m.nodes_per_cell < 0.15) sum += y.values[c], ++n;
    *phi_lo = fmin(*phi_lo, p.values[c]), *phi_hi = fmax(*phi_hi, p.values[c]);
  }
  sl_output_field_free(&y), sl_output_field_free(&p), sl_output_mesh_free(&m);
  return n ? sum / n : NAN;
}

/* wave_bed on a coarse mesh over a twelfth of a period. The scene's bed
 * (Bingham number 10 on the viscous stress scale) yields under the wave's
 * pressure gradient, a fluid-mud layer; with the yield stress raised to
 * 0.2 (of rho U0^2 = 0.0227: far above every stress of the wave) the same
 * bed stays rigid. Solids conserved and 0 <= phi <= 1 in both. */
static void wave_bed(void) {
  static const char *const soft[] = {"mesh.cells=16,12", "time.end=0.5", "output.every=0.5", NULL};
  static const char *const rigid[] = {"mesh.cells=16,12", "time.end=0.5", "output.every=0.5",
                                      "closure.viscosity.yield_stress=0.2", NULL};
  const char *const *sets[2] = {soft, rigid};
  const char *outs[2] = {"wave_bed_soft.h5", "wave_bed_rigid.h5"};
  double yielded[2];
  for (int k = 0; k < 2; ++k) {
    if (run_ok("wave_bed", NULL, NULL, sets[k], outs[k])) return;
    double lo, hi;
    yielded[k] = bed_yielded(outs[k], 0.5, &lo, &hi);
    double err = scalar(outs[k], "solids_conservation_error", 0.5);
    printf("  wave_bed (%s bed): yielded fraction of the bed %.3f, phi in [%.3g, %.15g], conservation error %.1e\n",
           k ? "rigid" : "soft", yielded[k], lo, hi, err);
    CHECK_MSG(lo >= 0.0 && hi <= 1.0, "phi outside [0, 1]: [%g, %g]", lo, hi);
    CHECK_MSG(fabs(err) < 1e-13, "solids not conserved: %g", err);
  }
  CHECK_MSG(yielded[0] > 0.9, "the scene's bed should yield under the wave: %.3f", yielded[0]);
  CHECK_MSG(yielded[1] == 0.0, "a bed with a yield stress above the wave's stresses flows: %.3f", yielded[1]);
}

static void bad_input(void) {
  sl_diag d = {{0}};
  const char *sets[] = {"initial.phi=0.7", NULL};
  int rc = run_scene("kynch_settling", NULL, NULL, sets, "kynch_bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[initial] phi") && strstr(d.msg, "phi_max = 0.64"), "message: %s", d.msg);
}

static void kynch_part(void) {
  richardson_zaki();
  richardson_zaki_step();
  nigam_fan();
  refinement();
  bad_input();
}

static void migration(void) {
  migration_couette();
  migration_poiseuille();
}

static void boycott_part(void) {
  if (getenv("SLUICE_SKIP_LONG")) exit(77); /* 100 s; skipped in the sanitizer build (ctest's SKIP_RETURN_CODE) */
  boycott();
}

static void spinup_part(void) {
  if (getenv("SLUICE_SKIP_LONG")) exit(77); /* 110 s; skipped in the sanitizer build */
  spinup(NULL);
}

/* The same measures and bounds with the split step at the scene's tolerance: its step control sees the
 * splitting error (docs/transient_cost.md; without it the shock was 0.044 off). */
static void spinup_split_part(void) {
  if (getenv("SLUICE_SKIP_LONG")) exit(77);
  spinup("flow.scheme=projection");
}

/* argv[1] names one part (its own ctest entry, so that the parts run in
 * parallel); none: all but spinup. */
/* [solid] vessel_diameter reaches the settling law: Richardson & Zaki's (1954) exponent for 0.2 <= Re_t < 1 is
 * n = (4.35 + 17.5 d/D) Re_t^-0.03, and the top interface of kynch_settling falls at u_t (1 - phi0)^n (1 -
 * phi0/phi_max) until the sediment meets it. With D = 0.01 m (d/D = 0.01) against an unbounded vessel the fall
 * after 40 s shrinks by (1 - phi0)^(17.5 * 0.01 * Re_t^-0.03), Re_t from Stokes' u_t: 0.98167. */
static void vessel_wall_term(void) {
  const char *unbounded[] = {"closure.hindered_settling.exponent=richardson_zaki_1954", "time.end=40", NULL};
  const char *narrow[] = {"closure.hindered_settling.exponent=richardson_zaki_1954", "time.end=40",
                          "solid.vessel_diameter=0.01", NULL};
  if (run_ok("kynch_settling", NULL, NULL, unbounded, "vessel_unbounded.h5") ||
      run_ok("kynch_settling", NULL, NULL, narrow, "vessel_narrow.h5"))
    return;
  double h0, h1, t0, t1;
  sl_diag d = {{0}};
  if (sl_output_read_scalar("vessel_unbounded.h5", "interface_height_0", 40.0, &h0, &t0, &d) ||
      sl_output_read_scalar("vessel_narrow.h5", "interface_height_0", 40.0, &h1, &t1, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  double u_t = (2650.0 - 1000.0) * 9.81 * 1e-8 / (18.0 * 1e-3), re = 1000.0 * u_t * 1e-4 / 1e-3;
  double expected = pow(0.9, 17.5 * 0.01 * pow(re, -0.03)), got = (0.5 - h1) / (0.5 - h0);
  printf(
      "vessel wall term: fall in 40 s %.6f m (unbounded), %.6f m (D = 0.01 m): ratio %.5f, Richardson-Zaki "
      "%.5f\n",
      0.5 - h0, 0.5 - h1, got, expected);
  CHECK_MSG(t0 == 40.0 && t1 == 40.0 && fabs(got / expected - 1.0) < 0.003, "ratio %.5f, expected %.5f", got, expected);
}

/* Boycott's vessel stopped by max_steps between output times and restarted from that checkpoint ends bit for bit
 * where the uninterrupted run does, in every field, with the same steps: the checkpoint holds the kept
 * factorisations (the values their pivots were chosen for and the refactorised ones), which the restart rebuilds,
 * so that the factorisation-reusing FGMRES goes on as in the uninterrupted run. Both flow schemes; the
 * scene's own mesh, to t = 0.03 (the stop at step 25 lies inside the start-up transient, where the matrix moves
 * fastest and the reuse refactorises most). */
static void restart_bitwise(void) {
  static const char *const schemes[2] = {"flow.scheme=monolithic", "flow.scheme=projection"};
  static const char *const fields[3] = {"velocity", "pressure", "phi"};
  for (int k = 0; k < 2; ++k) {
    const char *full[] = {schemes[k], "time.end=0.03", NULL};
    const char *part[] = {schemes[k], "time.end=0.03", "time.max_steps=25", NULL};
    char out[3][64];
    for (int i = 0; i < 3; ++i) snprintf(out[i], sizeof out[i], "restart_%d_%d.h5", k, i);
    scene_request q[3] = {{.configs = configs, .scene = "boycott", .sets = full, .out = out[0]},
                          {.configs = configs, .scene = "boycott", .sets = part, .out = out[1]},
                          {.configs = configs, .scene = "boycott", .sets = full, .out = out[2], .restart = out[1]}};
    sluice_summary r[3];
    sl_diag d = {{0}};
    int rc = 0;
    for (int i = 0; i < 3 && !rc; ++i) rc = scene_run(&q[i], &r[i], &d);
    CHECK_MSG(rc == 0, "%s: %s", schemes[k], d.msg);
    if (rc) continue;
    printf(
        "boycott restart, %s: uninterrupted %ld steps (%ld rejected), %ld of %ld solves reused; stopped at t = "
        "%.6g after %ld steps, restarted: %ld steps (%ld rejected)\n",
        schemes[k], r[0].steps, r[0].rejected_steps, r[0].linear.n_reused, r[0].linear.n_solves, r[1].t_reached,
        r[1].steps, r[2].steps, r[2].rejected_steps);
    CHECK(r[1].steps == 25 && r[1].t_reached < 0.03 && r[2].steps == r[0].steps &&
          r[2].rejected_steps == r[0].rejected_steps);
    if (k == 0) CHECK_MSG(r[0].linear.n_reused > 0, "no reused factorisation: the test would not test the restart");
    for (int f = 0; f < 3; ++f) {
      sl_output_field a, b;
      if (sl_output_read_field(out[0], fields[f], INFINITY, &a, &d)) {
        CHECK_MSG(0, "%s", d.msg);
        continue;
      }
      if (sl_output_read_field(out[2], fields[f], INFINITY, &b, &d) == 0) {
        long diff = a.n == b.n ? 0 : -1;
        for (long i = 0; a.n == b.n && i < (long)a.n * a.components; ++i) diff += a.values[i] != b.values[i];
        CHECK_MSG(a.time == b.time && diff == 0,
                  "%s: the restarted run's %s differs from the uninterrupted one's "
                  "in %ld values (t = %g and %g)",
                  schemes[k], fields[f], diff, a.time, b.time);
        sl_output_field_free(&b);
      } else {
        CHECK_MSG(0, "%s", d.msg);
      }
      sl_output_field_free(&a);
    }
  }
}

int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  static const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"kynch", kynch_part},        {"migration", migration},    {"wave_bed", wave_bed},
               {"boycott", boycott_part},    {"spinup", spinup_part},     {"spinup_split", spinup_split_part},
               {"vessel", vessel_wall_term}, {"restart", restart_bitwise}};
  int ran = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 ? strncmp(parts[k].name, "spinup", 6) != 0 : strcmp(argv[1], parts[k].name) == 0)
      parts[k].run(), ++ran;
  if (!ran)
    return fprintf(stderr,
                   "unknown part '%s' (kynch, migration, wave_bed, boycott, spinup, spinup_split, vessel, restart)\n",
                   argv[1]),
           2;
  return sl_test_summary();
}
