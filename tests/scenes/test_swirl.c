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

/* configs/viscometer_two_phase.ini (Pringle 2001 section 5.6, geometry assumed): the rotor turning in the
 * fluidised bed. The developed axial profile of the fluid across the gap in the bed's middle (z = 31 mm) against
 * the single-phase annular Poiseuille profile of the same gap, u = r_o^2 - r^2 + (r_o^2 - r_i^2) ln(r/r_o) /
 * ln(r_o/r_i) up to a factor (digest 4.2's derived solution), whose peak is 1.50 times its mean (2 in a pipe):
 * the drag of the bed flattens it, to a peak within 2 % of the mean interstitial velocity; the superficial
 * fluid flux r dr-averaged across the gap equals the inflow's 2 mm/s to 1e-6 relative (continuity); the bed
 * is fluidised (0 < phi < phi_max) below its surface and the rotor's swirl reaches the vessel wall falling. */
static void viscometer(void) {
  enum { NX = 12, NY = 40, ROW = 12 };
  const char *out = "viscometer_two_phase.h5";
  if (run_ok("viscometer_two_phase", NULL, NULL, NULL, out)) return;
  int n = 0, nv = 0, ns = 0;
  double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
  double *uf = field_at(out, "velocity_fluid", INFINITY, &nv, NULL),
         *sw = field_at(out, "swirl_fluid", INFINITY, &ns, NULL);
  CHECK_MSG(n == NX * NY && nv == NX * NY && ns == NX * NY, "%d, %d, %d cells", n, nv, ns);
  if (!phi || !uf || !sw || n != NX * NY || nv != NX * NY || ns != NX * NY) {
    free(phi), free(uf), free(sw);
    return;
  }
  /* the velocity field's stored components: 3 (x, y and a zero third) */
  const int nc3 = 3;
  const double h = (RO - RI) / NX, U = 0.002;
  double mean = 0.0, peak = 0.0, flux = 0.0, area = 0.0, pmean = 0.0, ppeak = 0.0, parea = 0.0;
  for (int i = 0; i < NX; ++i) {
    int c = ROW * NX + i;
    double r = RI + (i + 0.5) * h, u = uf[nc3 * c + 1], eps = 1.0 - phi[c];
    mean += r * u, area += r, peak = fmax(peak, u), flux += r * eps * u;
  }
  mean /= area, flux /= area;
  /* the single-phase profile's peak over its mean, on a fine quadrature (r dr) */
  for (int k = 0; k < 20000; ++k) {
    double r = RI + (k + 0.5) * (RO - RI) / 20000,
           u = RO * RO - r * r + (RO * RO - RI * RI) * log(r / RO) / log(RO / RI);
    pmean += r * u, parea += r, ppeak = fmax(ppeak, u);
  }
  pmean /= parea;
  double bed_lo = 1.0, bed_hi = 0.0;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < NX; ++i) bed_lo = fmin(bed_lo, phi[j * NX + i]), bed_hi = fmax(bed_hi, phi[j * NX + i]);
  double sw_in = sw[ROW * NX], sw_out = sw[ROW * NX + NX - 1];
  double err = scalar(out, "solids_conservation_error", tf);
  printf(
      "  viscometer (12 x 40): steady at t = %.2f s; bed phi %.4f-%.4f below z = 50 mm; at z = 31 mm the fluid's "
      "peak/mean %.4f (single-phase annular Poiseuille %.4f, pipe 2), superficial flux %.7f m/s (inflow %.4f); "
      "swirl %.4f m/s at the rotor's cell, %.2e at the vessel's; conservation %.1e\n",
      tf, bed_lo, bed_hi, peak / mean, ppeak / pmean, flux, U, sw_in, sw_out, err);
  CHECK_MSG(tf < 199.0, "viscometer: not steady by the end");
  CHECK_MSG(fabs(ppeak / pmean - 1.5) < 0.02, "annular Poiseuille peak/mean %.4f", ppeak / pmean);
  CHECK_MSG(peak / mean < 1.02, "viscometer: the bed's fluid profile peak/mean %.4f is not flat", peak / mean);
  CHECK_MSG(fabs(flux - U) < 1e-6 * U, "viscometer: superficial flux %.9g against %.9g", flux, U);
  CHECK_MSG(bed_lo > 0.3 && bed_hi < 0.6, "viscometer: the bed is not fluidised (phi %.4f-%.4f)", bed_lo, bed_hi);
  CHECK_MSG(sw_in > sw_out && sw_out >= 0.0, "viscometer: swirl %.4g at the rotor, %.4g at the wall", sw_in, sw_out);
  CHECK_MSG(fabs(err) < 1e-12, "viscometer: solids not conserved (%.3g)", err);
  free(phi), free(uf), free(sw);
}

/* argv[1] names one part (couette, viscometer); none: couette and the bad input. */
int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  if (argc > 1 && strcmp(argv[1], "viscometer") == 0) viscometer();
  else if (argc > 1 && strcmp(argv[1], "couette") != 0) return fprintf(stderr, "unknown part '%s'\n", argv[1]), 2;
  else couette_order(), bad_input();
  return sl_test_summary();
}
