/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The swirl of the axisymmetric 2-D two-fluid model ([two_fluid] swirl,
 * core/models/two_fluid/two_fluid_plane_swirl.c) against the exact Couette
 * profile of configs/couette_two_phase.ini,
 *   u_theta = omega/(r_i^2 - r_o^2) (r r_i^2 - r_i^2 r_o^2 / r),
 * which both phases of a uniform suspension follow (Bird, Stewart &
 * Lightfoot 2002, Example 3.6-3): the largest error at the cell centres on
 * 16, 32, 64 cells across the gap, second order (observed order > 1.8 and
 * below 1 % of omega r_i on 32 cells), with viscous solids that the walls
 * hold and with inviscid solids ([solid] viscosity = 0: the drag alone
 * turns them, to the fluid's Omega at steady state). (Viscous solids that
 * slip at the walls are not a case: their zero wall torque is not
 * Couette's, and they leave it in a layer sqrt(mu_s / K) thick.) Bad input:
 * swirl in a planar scene, angular_velocity without swirl. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];

SCENE_RUNNERS()

static const double RI = 0.015, RO = 0.045, OMEGA = 10.0;

static double couette(double r) { return OMEGA / (RI * RI - RO * RO) * (r * RI * RI - RI * RI * RO * RO / r); }

/* the largest error of both phases' swirl at the cell centres on n cells across (uniform) */
static double run_error(int n, int inviscid) {
  char cells[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d,1", n);
  const char *sets[] = {cells, inviscid ? "solid.viscosity=0" : NULL, NULL};
  const char *out = "swirl_couette.h5";
  if (run_ok("couette_two_phase", NULL, NULL, sets, out)) return NAN;
  double worst = 0.0;
  for (int phase = 0; phase < 2; ++phase) {
    int m = 0;
    double *u = field_at(out, phase ? "swirl_solid" : "swirl_fluid", INFINITY, &m, NULL);
    if (!u) return NAN;
    CHECK_MSG(m == n, "%d cells", m);
    for (int i = 0; i < m && m == n; ++i) worst = fmax(worst, fabs(u[i] - couette(RI + (i + 0.5) * (RO - RI) / n)));
    free(u);
  }
  return worst;
}

static void couette_order(void) {
  const char *kinds[2] = {"viscous solids held at the walls", "inviscid solids"};
  for (int k = 0; k < 2; ++k) {
    double e[3];
    for (int l = 0; l < 3; ++l) e[l] = run_error(16 << l, k);
    double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]);
    printf("  couette (%s): max error %.3e, %.3e, %.3e m/s on 16, 32, 64 cells (omega r_i %.2f); order %.2f, %.2f\n",
           kinds[k], e[0], e[1], e[2], OMEGA * RI, p1, p2);
    CHECK_MSG(e[1] < 0.01 * OMEGA * RI, "couette (%s): error %.3g on 32 cells", kinds[k], e[1]);
    CHECK_MSG(p1 > 1.8 && p2 > 1.8, "couette (%s): order %.2f, %.2f", kinds[k], p1, p2);
  }
}

static void bad_input(void) {
  struct {
    const char *sets[3];
    const char *expect;
  } cases[] = {
      {{"scene.geometry=planar", NULL}, "swirl: only an axisymmetric scene has a swirl"},
      {{"two_fluid.swirl=false", NULL}, "angular_velocity: only with [two_fluid] swirl = true"},
      {{"boundary.right.solids=wall_stress", "closure.wall_stress.model=bagnold"}, "swirl takes walls"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene("couette_two_phase", NULL, NULL, cases[k].sets, "swirl_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, cases[k].expect), "%s: rc %d, %s", cases[k].sets[0], rc, d.msg);
  }
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  couette_order();
  bad_input();
  return sl_test_summary();
}
