/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The developing pipe (core/models/pipe/pipe_march.c, `[pipe] length`): water from uniform inlet profiles
 * along Krampa's (2009, section 3.1) CFX-4 pipe, D = 0.04 m, L = 4 m, 50 axial x 40 radial cells, marched
 * along z (the boundary-layer approximation), against the fully developed pipe model on the same radial cells
 * (configs/pipe_water.ini):
 *  - at Re = 4e4, 1e5 and 2e5: the outlet's Fanning friction factor within 0.5 % of the fully developed
 *    model's and within 3 % of Churchill (1977); the outlet's u_f profile within 0.5 % of the bulk velocity of
 *    the fully developed one in every cell, k within 5 % of the fully developed axis-to-wall maximum (k
 *    develops the slowest: Pope 2000 section 7.3; measured, not tuned: the largest differences are printed);
 *  - the flow rate held at every station to 1e-9 relative; the inlet's k and epsilon those of Krampa's
 *    command file (TI 0.1, l = 0.007 D) at the first station's axis reached monotonically from the inlet;
 *  - 50 against 200 axial cells: the outlet's f within 0.2 %; the pressure drop on 25-200 axial cells
 *    converging, each doubling's difference 1.4-2.2 times smaller (order 0.5-1.1; measured 1.67, 1.66: order
 *    0.73, below the first order of backward differences for the inlet's jump);
 *  - the centre-line velocity rises from V at the inlet to the fully developed centre-line value: at the
 *    outlet within 1 %;
 *  - slurries, the inlet's solids fraction uniform with u_s = u_f = V, against the fully developed pipe at the
 *    outlet's section-mean (in-situ) fraction: Krampa's P1 (3.4 mm PVC at 10.7 %, 2.25 m/s, free slip) and
 *    0.5 mm glass beads at 25 % with the kinetic theory's pressure (configs/vertical_pipe.ini, D = 53.2 mm, so
 *    4 m is 75 D): -dP/dz within 0.1 %, tau_fw within 0.2 %, phi within 1e-3 in every outlet cell, u_s within
 *    0.5 % of its largest; the solids flux of the inlet carried by every station to 1e-6. Measured (printed):
 *    P1 6e-6, 3.5e-5, 8e-6, 3.6e-5; the beads 3.4e-4, 7.0e-4, 4.3e-4, 1.6e-3, the flow still developing at
 *    75 D (on 8 m the same differences fall to about 1e-6); the beads again with theta transported (model B
 *    in full: theta convected by the solids); P1 with no-slip solids and the kinetic viscosity (pvc_pipe.ini as
 *    shipped, solids_wall = no_slip), which cycled at its first station before the march took the drag's
 *    fraction from the upstream station (core/models/pipe/pipe_march.c, pipe_march_drag): measured 1e-10 (its
 *    outlet in-situ fraction 0.160 for 0.107 delivered: the solids' wall stress, 214 Pa, holds them back), and
 *    P1 with the Ding-Gidaspow, Ding-Lyczkowski and Bartosik solids walls and the kinetic viscosity;
 *  - an inlet intensity out of range is refused before anything is written (exit 2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "pipe_testing.h"
#include "sluice/sluice.h"
#include "testing.h"

static char scene[4096], slurry_text[8192];
static const char *scene_name = "pipe_water.ini";
static const double rho = 998.2, mu = 1.002e-3, D = 0.04;

static int load(const char *name, char *buf, size_t cap) {
  char rel[256];
  snprintf(rel, sizeof rel, "configs/%s", name);
  return sl_test_read_source(rel, buf, cap);
}

static int run_text(const char *text, const char *const *sets, const char *out, sluice_error *e) {
  return pipe_run_text(text, scene_name, sets, out, e);
}

static int run(const char *const *sets, const char *out, sluice_error *e) { return run_text(scene, sets, out, e); }

/* A field with its cells' centres (r, z) and volumes per radian (r dr dz). */
typedef struct {
  int n;
  double *r, *z, *vol, *v;
} cells;

static int read_cells(const char *out, const char *name, cells *c) {
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  memset(c, 0, sizeof *c);
  if (sl_output_read_field(out, name, INFINITY, &f, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  if (sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    sl_output_field_free(&f);
    return 1;
  }
  c->n = f.n;
  c->r = malloc((size_t)f.n * sizeof(double)), c->z = malloc((size_t)f.n * sizeof(double));
  c->vol = malloc((size_t)f.n * sizeof(double)), c->v = malloc((size_t)f.n * sizeof(double));
  for (int k = 0; k < f.n; ++k) {
    double r0 = INFINITY, r1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (int q = 0; q < m.nodes_per_cell; ++q) {
      const double *x = m.coords + 3 * m.cells[k * m.nodes_per_cell + q];
      r0 = fmin(r0, x[0]), r1 = fmax(r1, x[0]), z0 = fmin(z0, x[1]), z1 = fmax(z1, x[1]);
    }
    c->r[k] = 0.5 * (r0 + r1), c->z[k] = 0.5 * (z0 + z1);
    c->vol[k] = c->r[k] * (r1 - r0) * (z1 - z0), c->v[k] = f.values[k];
  }
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
  return 0;
}

static void cells_free(cells *c) { free(c->r), free(c->z), free(c->vol), free(c->v); }

/* The cell of c at radius r in the row at height z (-1: none). */
static int find(const cells *c, double r, double z) {
  for (int k = 0; k < c->n; ++k)
    if (fabs(c->r[k] - r) < 1e-9 && fabs(c->z[k] - z) < 1e-9) return k;
  return -1;
}

static double zmax(const cells *c) {
  double z = -INFINITY;
  for (int k = 0; k < c->n; ++k) z = fmax(z, c->z[k]);
  return z;
}

static double zmin(const cells *c) {
  double z = INFINITY;
  for (int k = 0; k < c->n; ++k) z = fmin(z, c->z[k]);
  return z;
}

/* The sets of a run at Re with the wall cell's centre at y+ = 36 (as tests/models/test_pipe.c). */
static void sets_at(double Re, char s[3][64]) {
  double V = Re * mu / (rho * D), ut = V * sqrt(0.5 * pipe_churchill(Re)), w = 2.0 * 36.0 * mu / (rho * ut);
  snprintf(s[0], 64, "pipe.bulk_velocity=%.10g", V);
  snprintf(s[1], 64, "pipe.wall_cell=%.10g", w);
}

/* max over the outlet's cells of |dev - fd|, the fd row's max |fd|, and the outlet's centre-line value. */
static void outlet_difference(const char *dev, const char *fd, const char *name, double *diff, double *scale,
                              double *axis_dev, double *axis_fd) {
  cells a, b;
  *diff = NAN;
  if (read_cells(dev, name, &a)) return;
  if (read_cells(fd, name, &b)) {
    cells_free(&a);
    return;
  }
  double zo = zmax(&a), dmax = 0.0, smax = 0.0, rmin = INFINITY;
  int matched = 0;
  for (int k = 0; k < b.n; ++k) {
    int q = find(&a, b.r[k], zo);
    if (q < 0) continue;
    ++matched;
    dmax = fmax(dmax, fabs(a.v[q] - b.v[k])), smax = fmax(smax, fabs(b.v[k]));
    if (b.r[k] < rmin) rmin = b.r[k], *axis_dev = a.v[q], *axis_fd = b.v[k];
  }
  CHECK_MSG(matched == b.n, "%s: %d of %d outlet cells on the fully developed pipe's radii", name, matched, b.n);
  *diff = dmax, *scale = smax;
  cells_free(&a), cells_free(&b);
}

static void against_fully_developed(void) {
  const double Re[3] = {4e4, 1e5, 2e5};
  for (int k = 0; k < 3; ++k) {
    char s[3][64];
    sets_at(Re[k], s);
    const char *fd[] = {s[0], s[1], NULL}, *dev[] = {s[0], s[1], "pipe.length=4", NULL};
    sluice_error e = {0, ""};
    if (run(fd, "pdev_fd.h5", &e) || run(dev, "pdev.h5", &e)) {
      CHECK_MSG(0, "Re %g: %s", Re[k], e.msg);
      continue;
    }
    double ff = pipe_scalar("pdev_fd.h5", "friction_factor"), fdv = pipe_scalar("pdev.h5", "friction_factor");
    double fc = pipe_churchill(Re[k]), V = Re[k] * mu / (rho * D);
    double du, su, dk, sk, ua, uf, ka, kf;
    outlet_difference("pdev.h5", "pdev_fd.h5", "velocity_fluid", &du, &su, &ua, &uf);
    outlet_difference("pdev.h5", "pdev_fd.h5", "k", &dk, &sk, &ka, &kf);
    printf(
        "Re %.0e: outlet f %.6f, fully developed %.6f (%+.3f %%), Churchill %.6f (%+.2f %%); "
        "|du_f|/V %.3f %%, |dk|/max k %.2f %%, centre line %.4f against %.4f m/s (%+.3f %%); excess head %.3f; "
        "%g station iterations at most\n",
        Re[k], fdv, ff, 100.0 * (fdv / ff - 1.0), fc, 100.0 * (fdv / fc - 1.0), 100.0 * du / V, 100.0 * dk / sk, ua, uf,
        100.0 * (ua / uf - 1.0), pipe_scalar("pdev.h5", "inlet_excess_head"),
        pipe_scalar("pdev.h5", "station_iterations_max"));
    CHECK_MSG(fabs(fdv / ff - 1.0) < 0.005, "Re %g: outlet f %.6f against the fully developed %.6f", Re[k], fdv, ff);
    CHECK_MSG(fabs(fdv / fc - 1.0) < 0.03, "Re %g: outlet f %.6f against Churchill's %.6f", Re[k], fdv, fc);
    CHECK_MSG(du < 0.005 * V, "Re %g: the outlet's u_f off the fully developed by %.3f %% of V", Re[k], 100.0 * du / V);
    CHECK_MSG(dk < 0.05 * sk, "Re %g: the outlet's k off the fully developed by %.2f %%", Re[k], 100.0 * dk / sk);
    CHECK_MSG(fabs(ua / uf - 1.0) < 0.01, "Re %g: centre line %.5f against %.5f", Re[k], ua, uf);
  }
}

/* The flow rate at every station, the inlet's turbulence at the first station, the centre line's rise. */
static void stations(void) {
  cells u, kk;
  if (read_cells("pdev.h5", "velocity_fluid", &u)) return; /* the last run: Re = 2e5 */
  if (read_cells("pdev.h5", "k", &kk)) {
    cells_free(&u);
    return;
  }
  double V = 2e5 * mu / (rho * D), worst = 0.0, r0 = INFINITY;
  for (int k = 0; k < u.n; ++k) r0 = fmin(r0, u.r[k]);
  int rows = 0;
  for (int k = 0; k < u.n; ++k) { /* each row once, by its axis cell */
    if (u.r[k] > r0 + 1e-12) continue;
    double q = 0.0, a = 0.0;
    for (int j = 0; j < u.n; ++j)
      if (fabs(u.z[j] - u.z[k]) < 1e-9) q += u.vol[j] * u.v[j], a += u.vol[j];
    worst = fmax(worst, fabs(q / (a * V) - 1.0)), ++rows;
  }
  CHECK_MSG(rows == 50, "%d stations", rows);
  printf("flow rate: worst |Q/(V A) - 1| over the stations %.2e\n", worst);
  CHECK_MSG(worst < 1e-9, "the flow rate is off by %.3g", worst);
  /* the first station's centre line k lies between the fully developed axis value and the inlet's 1.5 (0.1 V)^2 */
  double z0 = zmin(&kk), k_in = 1.5 * (0.1 * V) * (0.1 * V), k_first = NAN;
  for (int k = 0; k < kk.n; ++k)
    if (fabs(kk.z[k] - z0) < 1e-9 && kk.r[k] < r0 + 1e-12) k_first = kk.v[k];
  printf("first station (z = %.3f m): centre-line k %.5f, the inlet's %.5f\n", z0, k_first, k_in);
  CHECK_MSG(k_first < k_in && k_first > 0.0, "the first station's k %.5g against the inlet's %.5g", k_first, k_in);
  cells_free(&u), cells_free(&kk);
}

static void axial_cells(void) {
  char s[3][64];
  sets_at(1e5, s);
  const char *a[] = {s[0], s[1], "pipe.length=4", NULL},
             *b[] = {s[0], s[1], "pipe.length=4", "pipe.axial_cells=200", NULL};
  sluice_error e = {0, ""};
  if (run(a, "pdev50.h5", &e) || run(b, "pdev200.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  double f50 = pipe_scalar("pdev50.h5", "friction_factor"), f200 = pipe_scalar("pdev200.h5", "friction_factor");
  double p50 = pipe_scalar("pdev50.h5", "pressure_drop"), p200 = pipe_scalar("pdev200.h5", "pressure_drop");
  printf("50 and 200 axial cells: outlet f %.6f and %.6f (%+.3f %%); pressure drop %.1f and %.1f Pa (%+.3f %%)\n", f50,
         f200, 100.0 * (f50 / f200 - 1.0), p50, p200, 100.0 * (p50 / p200 - 1.0));
  CHECK_MSG(fabs(f50 / f200 - 1.0) < 0.002, "f %.6f on 50 axial cells, %.6f on 200", f50, f200);
  /* the march's convergence in z: the pressure drop on 25, 50, 100, 200 cells; backward differences in z are
     first order for a smooth solution, the inlet's jump (a boundary layer growing from z = 0) lowers it */
  const char *c25[] = {s[0], s[1], "pipe.length=4", "pipe.axial_cells=25", NULL};
  const char *c100[] = {s[0], s[1], "pipe.length=4", "pipe.axial_cells=100", NULL};
  if (run(c25, "pdev25.h5", &e) || run(c100, "pdev100.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  double p25 = pipe_scalar("pdev25.h5", "pressure_drop"), p100 = pipe_scalar("pdev100.h5", "pressure_drop");
  double r1 = (p50 - p25) / (p100 - p50), r2 = (p100 - p50) / (p200 - p100);
  printf(
      "pressure drop on 25/50/100/200 axial cells: %.2f %.2f %.2f %.2f Pa; the differences fall by %.3f and %.3f "
      "(order %.2f, %.2f)\n",
      p25, p50, p100, p200, r1, r2, log2(r1), log2(r2));
  CHECK_MSG(r1 > 1.4 && r1 < 2.2 && r2 > 1.4 && r2 < 2.2, "the march's differences fall by %.3f and %.3f", r1, r2);
}

/* A slurry: the developing pipe at the inlet's solids fraction, then the fully developed pipe at the outlet's
   section-mean fraction (the in-situ one: the slip makes it differ from the delivered); the outlet against it. */
static void slurry(const char *name, const char *const *extra, double tol_grad, double tol_tau, double tol_phi,
                   double tol_us) {
  scene_name = name;
  if (load(name, slurry_text, sizeof slurry_text)) return;
  const char *dev[8] = {"pipe.length=4"}, *fd[8] = {NULL};
  char phi_set[64];
  int n = 1;
  for (int k = 0; extra[k] && n < 6; ++k) dev[n] = extra[k], fd[n - 1] = extra[k], ++n;
  dev[n] = NULL;
  sluice_error e = {0, ""};
  if (run_text(slurry_text, dev, "pdev_s.h5", &e)) {
    CHECK_MSG(0, "%s developing: %s", name, e.msg);
    return;
  }
  double pm = pipe_scalar("pdev_s.h5", "phi_mean");
  snprintf(phi_set, sizeof phi_set, "pipe.solids_fraction=%.17g", pm);
  fd[n - 1] = phi_set, fd[n] = NULL;
  if (run_text(slurry_text, fd, "pdev_sfd.h5", &e)) {
    CHECK_MSG(0, "%s fully developed: %s", name, e.msg);
    return;
  }
  double ga = pipe_scalar("pdev_s.h5", "pressure_gradient"), gb = pipe_scalar("pdev_sfd.h5", "pressure_gradient");
  double ta = pipe_scalar("pdev_s.h5", "wall_shear_stress_fluid"),
         tb = pipe_scalar("pdev_sfd.h5", "wall_shear_stress_fluid");
  double V = pipe_scalar("pdev_s.h5", "velocity_fluid_area_mean");
  double dphi, sphi, dus, sus, a0, b0;
  outlet_difference("pdev_s.h5", "pdev_sfd.h5", "phi", &dphi, &sphi, &a0, &b0);
  outlet_difference("pdev_s.h5", "pdev_sfd.h5", "velocity_solid", &dus, &sus, &a0, &b0);
  /* the solids flux at every station: the inlet's */
  cells ph, us;
  double worst = NAN, inlet = NAN;
  if (!read_cells("pdev_s.h5", "phi", &ph)) {
    if (!read_cells("pdev_s.h5", "velocity_solid", &us)) {
      const char *src = strstr(slurry_text, "solids_fraction = "), *vb = strstr(slurry_text, "bulk_velocity = ");
      inlet = (src ? atof(src + 18) : NAN) * (vb ? atof(vb + 16) : NAN);
      double r0 = INFINITY;
      worst = 0.0;
      for (int k = 0; k < ph.n; ++k) r0 = fmin(r0, ph.r[k]);
      for (int k = 0; k < ph.n; ++k) {
        if (ph.r[k] > r0 + 1e-12) continue;
        double q = 0.0, a = 0.0;
        for (int j = 0; j < ph.n; ++j)
          if (fabs(ph.z[j] - ph.z[k]) < 1e-9) q += ph.vol[j] * ph.v[j] * us.v[j], a += ph.vol[j];
        worst = fmax(worst, fabs(q / (a * inlet) - 1.0));
      }
      cells_free(&us);
    }
    cells_free(&ph);
  }
  printf(
      "%s developing (phi_in %.4g, outlet phi_mean %.5f): -dP/dz %.2f against %.2f Pa/m (%+.4f %%), tau_fw %.4f "
      "against %.4f Pa (%+.4f %%), max |dphi| %.2e (phi up to %.3f), max |du_s| %.4f %% of %.3f m/s; solids flux "
      "off the inlet's by %.2e at worst; %g station iterations at most\n",
      name, strstr(slurry_text, "solids_fraction = ") ? atof(strstr(slurry_text, "solids_fraction = ") + 18) : NAN, pm,
      ga, gb, 100.0 * (ga / gb - 1.0), ta, tb, 100.0 * (ta / tb - 1.0), dphi, sphi, 100.0 * dus / sus, sus, worst,
      pipe_scalar("pdev_s.h5", "station_iterations_max"));
  (void)V;
  CHECK_MSG(fabs(ga / gb - 1.0) < tol_grad, "%s: -dP/dz %.6g against %.6g", name, ga, gb);
  CHECK_MSG(fabs(ta / tb - 1.0) < tol_tau, "%s: tau_fw %.6g against %.6g", name, ta, tb);
  CHECK_MSG(dphi < tol_phi, "%s: phi off by %.3g", name, dphi);
  CHECK_MSG(dus < tol_us * sus, "%s: u_s off by %.3g", name, dus);
  CHECK_MSG(worst < 1e-6, "%s: the solids flux off the inlet's by %.3g", name, worst);
  scene_name = "pipe_water.ini";
}

static void bad_inlet(void) {
  const char *sets[] = {"pipe.length=4", "pipe.inlet_intensity=2", NULL};
  sluice_error e = {0, ""};
  int rc = run(sets, "pdev_bad.h5", &e);
  printf("inlet_intensity = 2: %s\n", e.msg);
  CHECK_MSG(rc == 2 && strstr(e.msg, "inlet_intensity"), "rc %d: %s", rc, e.msg);
  FILE *f = fopen("pdev_bad.h5", "rb");
  CHECK_MSG(f == NULL, "an output was written");
  if (f) fclose(f);
}

/* The shipped configs/pipe_developing.ini (pipe_water.ini included, length = 4) at its outlet against the fully
 * developed pipe_water.ini: the same friction factor within 0.5 %, as against_fully_developed at Re = 1e5. */
static void shipped_scene(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/configs/pipe_developing.ini", src ? src : ".");
  sluice *s = NULL;
  sluice_open_opts oo = {0};
  sluice_run_opts ro = {.output = "pdev_shipped.h5", .version = "test"};
  sluice_summary sum;
  sluice_error e = {0, ""};
  int rc = sluice_open(path, &oo, &s, &e);
  if (!rc) rc = sluice_run(s, &ro, &sum, &e);
  sluice_close(s);
  const char *none[] = {NULL};
  if (!rc) rc = run(none, "pdev_shipped_fd.h5", &e);
  CHECK_MSG(rc == 0, "%s: %s", path, e.msg);
  if (rc) return;
  double fdv = pipe_scalar("pdev_shipped.h5", "friction_factor"),
         ff = pipe_scalar("pdev_shipped_fd.h5", "friction_factor");
  printf("configs/pipe_developing.ini: outlet f %.7f, pipe_water.ini %.7f (%+.4f %%)\n", fdv, ff,
         100.0 * (fdv / ff - 1.0));
  CHECK_MSG(fabs(fdv / ff - 1.0) < 0.005, "shipped developing pipe: outlet f %.7f against %.7f", fdv, ff);
  CHECK_MSG(pipe_scalar("pdev_shipped.h5", "stations") == 50.0, "the shipped scene marches 50 stations");
}

int main(void) {
  if (load("pipe_water.ini", scene, sizeof scene)) return sl_test_summary();
  remove("pdev_bad.h5");
  against_fully_developed();
  stations();
  axial_cells();
  const char *none[] = {NULL}, *kinetic[] = {"pipe.kinetic_pressure=true", NULL};
  /* Krampa's P1 (3.4 mm PVC, 10.7 %, V = 2.25 m/s, free slip: Table 5.3's first row) */
  slurry("pvc_pipe.ini", none, 1e-3, 2e-3, 1e-3, 5e-3);
  /* P1 as shipped with no-slip solids (the kinetic viscosity of [closure.granular] lun): the wall cell's solids
     stop to 0.14 m/s and gather past Gidaspow's drag switch at c_f = 0.8 near the inlet (pipe_march_drag) */
  const char *no_slip[] = {"pipe.solids_wall=no_slip", NULL};
  slurry("pvc_pipe.ini", no_slip, 1e-3, 2e-3, 1e-3, 5e-3);
  /* and with the three solids wall closures of Tables 5.3-5.4 (DG90, DL92, B96), the kinetic viscosity on */
  static const char *const walls[3] = {"closure.wall_stress.solids.model=navier_slip_ding_gidaspow",
                                       "closure.wall_stress.solids.model=navier_slip_ding_lyczkowski",
                                       "closure.wall_stress.solids.model=bartosik"};
  for (int k = 0; k < 3; ++k) {
    const char *wall[] = {"pipe.solids_wall=wall_stress", walls[k], NULL};
    slurry("pvc_pipe.ini", wall, 1e-3, 2e-3, 1e-3, 5e-3);
  }
  /* 0.5 mm glass beads at 25 %, V = 3.02 m/s, with the kinetic theory's pressure (the solids leave the wall) */
  slurry("vertical_pipe.ini", kinetic, 1e-3, 2e-3, 1e-3, 5e-3);
  /* the same with the transported theta (model B in full) */
  const char *full[] = {"pipe.kinetic_pressure=true", "pipe.granular_temperature=transport", NULL};
  slurry("vertical_pipe.ini", full, 1e-3, 2e-3, 1e-3, 5e-3);
  bad_inlet();
  shipped_scene();
  return sl_test_summary();
}
