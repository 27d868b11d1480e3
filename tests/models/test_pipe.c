/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The fully developed pipe model (core/models/pipe), water alone, against
 * smooth-pipe turbulence:
 *  - the Fanning friction factor within 3 % of Churchill (1977) for Re =
 *    4e4, 1e5 and 2e5 (Krampa 2009 section 5.1.6.1's criterion), each with
 *    the wall cell at y+ of about 35;
 *  - the log law U+ = ln(E y+)/kappa of the wall function (kappa 0.41,
 *    E 9.793) in the cells of the overlap region (y+ > 30, y < 0.1 R: Pope
 *    2000, Turbulent Flows, section 7.1.4) within 1 % (the shear stress falls
 *    as 1 - y/R across the pipe, so the profile leaves the law outwards);
 *  - 40 and 80 radial cells (the same wall cell) within 1 %;
 *  - up-flow and down-flow: the same wall stress, the manometric gradients
 *    4 tau_w/D both;
 *  - a wall cell wider than half the radius is refused before anything runs;
 *  - driven by a given pressure gradient ([pipe] pressure_gradient): the -dP/dz of a run at V carries V back (to
 *    1e-7, the steady solve's tolerance) with the same f, for water and for configs/vertical_pipe.ini's slurry
 *    (its inventory held); water falling under gravity alone (down-flow, -dP/dz = 0) has the wall stress of its
 *    weight, tau_w = rho g D/4, and f within 3 % of Churchill at the Re it reaches; refused with a length. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "pipe_testing.h"
#include "sluice/sluice.h"
#include "testing.h"

static char scene[4096];

static int load_scene(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/configs/pipe_water.ini", src ? src : ".");
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(scene, 1, sizeof scene - 1, f) : 0;
  if (f) fclose(f);
  scene[n] = '\0';
  CHECK_MSG(n > 0, "cannot read %s", path);
  return n > 0 ? 0 : 1;
}

static int run(const char *const *sets, const char *out, sluice_error *e) {
  return pipe_run_text(scene, "pipe_water.ini", sets, out, e);
}

static const double rho = 998.2, mu = 1.002e-3, D = 0.04;

/* Runs at Re with n cells and the wall cell at y+ ~ 35; returns f (NaN on failure). */
static double friction(double Re, int n, const char *out) {
  double V = Re * mu / (rho * D);
  /* u_tau from Churchill's f, the wall cell's centre at y+ = 36 */
  double ut = V * sqrt(0.5 * pipe_churchill(Re)), w = 2.0 * 36.0 * mu / (rho * ut);
  char s1[64], s2[64], s3[64];
  snprintf(s1, sizeof s1, "pipe.bulk_velocity=%.10g", V);
  snprintf(s2, sizeof s2, "pipe.cells=%d", n);
  snprintf(s3, sizeof s3, "pipe.wall_cell=%.10g", w);
  const char *sets[] = {s1, s2, s3, NULL};
  sluice_error e = {0, ""};
  int rc = run(sets, out, &e);
  CHECK_MSG(rc == 0, "Re %g: %s", Re, e.msg);
  return rc ? NAN : pipe_scalar(out, "friction_factor");
}

static void friction_factors(void) {
  const double Re[3] = {4e4, 1e5, 2e5};
  for (int k = 0; k < 3; ++k) {
    double f = friction(Re[k], 40, "pipe_f.h5"), fc = pipe_churchill(Re[k]), yp = pipe_scalar("pipe_f.h5", "y_plus");
    printf("Re %.0e: f = %.6f, Churchill %.6f (%+.2f %%), y+ %.1f\n", Re[k], f, fc, 100.0 * (f / fc - 1.0), yp);
    CHECK_MSG(fabs(f / fc - 1.0) < 0.03, "Re %g: f %.6f against Churchill's %.6f", Re[k], f, fc);
    CHECK_MSG(yp > 30.0 && yp < 200.0, "y+ %g at the wall cell", yp);
  }
}

static void log_law(void) {
  if (isnan(friction(1e5, 80, "pipe_log.h5"))) return;
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field("pipe_log.h5", "velocity_fluid", INFINITY, &f, &d) ||
      sl_output_read_mesh("pipe_log.h5", &m, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  double ut = sqrt(pipe_scalar("pipe_log.h5", "wall_shear_stress_fluid") / rho), R = 0.5 * D, worst = 0.0;
  int used = 0;
  for (int c = 0; c < f.n; ++c) {
    double r = 0.0;
    for (int k = 0; k < m.nodes_per_cell; ++k) r += m.coords[3 * m.cells[c * m.nodes_per_cell + k]] / m.nodes_per_cell;
    double y = R - r, yp = rho * ut * y / mu;
    if (yp < 30.0 || y > 0.1 * R) continue;
    double up = f.values[c] / ut, law = log(9.793 * yp) / 0.41;
    worst = fmax(worst, fabs(up / law - 1.0)), ++used;
  }
  printf("log law in %d cells of the overlap region (y+ > 30, y < 0.1 R): worst |U+/law - 1| = %.3f %%\n", used,
         100.0 * worst);
  CHECK_MSG(used >= 3, "only %d cells in the log layer", used);
  CHECK_MSG(worst < 0.01, "U+ off the log law by %.3f %%", 100.0 * worst);
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
}

static void grid(void) {
  double f40 = friction(1e5, 40, "pipe_g40.h5"), f80 = friction(1e5, 80, "pipe_g80.h5");
  double p40 = pipe_scalar("pipe_g40.h5", "pressure_gradient"), p80 = pipe_scalar("pipe_g80.h5", "pressure_gradient");
  printf("40 and 80 cells: f %.6f and %.6f (%+.3f %%), -dP/dz %.2f and %.2f Pa/m\n", f40, f80,
         100.0 * (f80 / f40 - 1.0), p40, p80);
  CHECK_MSG(fabs(f80 / f40 - 1.0) < 0.01, "f changes by %.3f %% from 40 to 80 cells", 100.0 * (f80 / f40 - 1.0));
}

static void up_and_down(void) {
  const char *up[] = {"flow.gravity=-9.81", NULL}, *down[] = {"flow.gravity=9.81", NULL};
  sluice_error e = {0, ""};
  if (run(up, "pipe_up.h5", &e) || run(down, "pipe_down.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  double tu = pipe_scalar("pipe_up.h5", "wall_shear_stress_fluid"),
         td = pipe_scalar("pipe_down.h5", "wall_shear_stress_fluid");
  double mu_ = pipe_scalar("pipe_up.h5", "manometric_gradient"),
         md = pipe_scalar("pipe_down.h5", "manometric_gradient");
  double pu = pipe_scalar("pipe_up.h5", "pressure_gradient"), pd = pipe_scalar("pipe_down.h5", "pressure_gradient");
  printf("up-flow: -dP/dz %.3f, manometric %.4f Pa/m; down-flow: %.3f, %.4f; 4 tau_w/D = %.4f\n", pu, mu_, pd, md,
         4.0 * tu / D);
  CHECK_MSG(fabs(tu - td) < 1e-9 * tu, "tau_w up %.12g, down %.12g", tu, td);
  CHECK_MSG(fabs(mu_ - 4.0 * tu / D) < 1e-6 * mu_ && fabs(md - 4.0 * td / D) < 1e-6 * md,
            "the manometric gradients are the wall friction (4 tau_w/D, Krampa 2009 eqs 3.6-3.7)");
  CHECK_MSG(fabs(pu - pd - 2.0 * rho * 9.81) < 1e-6 * pu, "the water's weight apart: %.6g", pu - pd);
}

static void bad_wall_cell(void) {
  const char *sets[] = {"pipe.wall_cell=0.011", NULL};
  sluice_error e = {0, ""};
  int rc = run(sets, "pipe_bad.h5", &e);
  printf("wall_cell = 0.011: %s\n", e.msg);
  CHECK_MSG(rc == 2 && strstr(e.msg, "wall_cell") && strstr(e.msg, "half the radius"), "rc %d: %s", rc, e.msg);
}

/* The pressure gradient given: the inverse of the bulk velocity given. */
static void given_gradient(const char *text, const char *name, const char *out_v, const char *out_g) {
  const char *sets0[] = {NULL};
  sluice_error e = {0, ""};
  int rc = pipe_run_text(text, name, sets0, out_v, &e);
  CHECK_MSG(rc == 0, "%s: %s", name, e.msg);
  if (rc) return;
  const double G = pipe_scalar(out_v, "pressure_gradient"), V = pipe_scalar(out_v, "bulk_velocity");
  const double f = pipe_scalar(out_v, "friction_factor"), phi = pipe_scalar(out_v, "phi_mean");
  char s1[64];
  snprintf(s1, sizeof s1, "pipe.pressure_gradient=%.17g", G);
  const char *sets[] = {s1, NULL};
  rc = pipe_run_text(text, name, sets, out_g, &e);
  CHECK_MSG(rc == 0, "%s with -dP/dz given: %s", name, e.msg);
  if (rc) return;
  const double V1 = pipe_scalar(out_g, "bulk_velocity"), f1 = pipe_scalar(out_g, "friction_factor");
  const double G1 = pipe_scalar(out_g, "pressure_gradient"), phi1 = pipe_scalar(out_g, "phi_mean");
  printf("%s: -dP/dz %.10g Pa/m given carries V = %.10g m/s (%.2e against %.4g), f %.8g (%.2e)\n", name, G, V1,
         V1 / V - 1.0, V, f1, f1 / f - 1.0);
  CHECK_MSG(fabs(V1 / V - 1.0) < 1e-7 && fabs(f1 / f - 1.0) < 1e-7, "%s: V %.12g against %.12g, f %.10g against %.10g",
            name, V1, V, f1, f);
  CHECK_MSG(G1 == G, "%s: -dP/dz %.17g, given %.17g", name, G1, G);
  CHECK_MSG(fabs(phi1 - phi) < 1e-12, "%s: the inventory %.15g against %.15g", name, phi1, phi);
}

static void falling_water(void) {
  const char *sets[] = {"pipe.pressure_gradient=0", "flow.gravity=9.81", NULL};
  sluice_error e = {0, ""};
  int rc = run(sets, "pipe_falling.h5", &e);
  CHECK_MSG(rc == 0, "falling water: %s", e.msg);
  if (rc) return;
  const double tw = pipe_scalar("pipe_falling.h5", "wall_shear_stress_fluid"),
               V = pipe_scalar("pipe_falling.h5", "bulk_velocity");
  const double f = pipe_scalar("pipe_falling.h5", "friction_factor"), fc = pipe_churchill(rho * V * D / mu);
  printf(
      "falling water, -dP/dz = 0: V = %.4f m/s, tau_w %.6g Pa against rho g D/4 %.6g, f %.6f against Churchill %.6f "
      "(%+.2f %%)\n",
      V, tw, rho * 9.81 * D / 4.0, f, fc, 100.0 * (f / fc - 1.0));
  CHECK_MSG(fabs(tw / (rho * 9.81 * D / 4.0) - 1.0) < 1e-6, "tau_w %.9g against %.9g", tw, rho * 9.81 * D / 4.0);
  CHECK_MSG(fabs(f / fc - 1.0) < 0.03, "f %.6f against Churchill's %.6f", f, fc);
  const char *bad[] = {"pipe.pressure_gradient=1000", "pipe.length=4", NULL};
  rc = run(bad, "pipe_bad_g.h5", &e);
  printf("pressure_gradient with length: %d, %s\n", rc, e.msg);
  CHECK_MSG(rc == 2 && strstr(e.msg, "pressure_gradient") && strstr(e.msg, "length"), "rc %d: %s", rc, e.msg);
}

int main(void) {
  if (load_scene()) return sl_test_summary();
  friction_factors();
  log_law();
  grid();
  up_and_down();
  bad_wall_cell();
  given_gradient(scene, "pipe_water.ini", "pipe_gv.h5", "pipe_gg.h5");
  static char slurry[8192];
  if (!sl_test_read_source("configs/vertical_pipe.ini", slurry, sizeof slurry))
    given_gradient(slurry, "vertical_pipe.ini", "pipe_gsv.h5", "pipe_gsg.h5");
  falling_water();
  return sl_test_summary();
}
