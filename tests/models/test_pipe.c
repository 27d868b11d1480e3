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
 *  - a wall cell wider than half the radius is refused before anything runs. */
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

int main(void) {
  if (load_scene()) return sl_test_summary();
  friction_factors();
  log_law();
  grid();
  up_and_down();
  bad_wall_cell();
  return sl_test_summary();
}
