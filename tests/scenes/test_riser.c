/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The riser of a liquid-solid circulating fluidised bed (configs/lscfb_riser.ini;
 * Pringle 2001 section 5.3, Table 5.7), the 2-D two-fluid model with solids
 * entering through its inlet ([boundary] solids_flux).
 *
 * uniform: with slip walls nothing varies across the pipe, so the steady
 * state is the uniform transported suspension whose drag carries the
 * buoyant weight, K(phi, slip) slip = phi (1 - phi) (rho_s - rho_f) g with
 * slip = U / (1 - phi) - J / phi (U, J the superficial liquid and solids
 * velocities entering; Wen & Yu 1966 as Gidaspow 1994 eq 5.45 writes K).
 * From a different start (porosity 0.95) every cell ends at that phi to
 * 1e-10, planar and axisymmetric, and the solids entering, leaving and held
 * balance to round-off (a wrong inflow would shift phi by J's error).
 * profile: the scene with its no-slip pipe wall on a coarse grid (10 x 20
 * cells of 10 mm): steady, conserving, the cross-section mean porosity at
 * the 1-D level to 1e-4, and a radial contrast below 1e-3 in phi: the
 * laminar wall layer (sqrt(nu z / U), about 2 mm at z = 0.15 m) is too thin
 * to make a core-annulus profile (docs/riser.md). The scene's own 2 mm grid
 * (100 x 50) costs about 16 s of CPU a step here (about 7 h to steady) and
 * is not run by the test. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];

SCENE_RUNNERS()

/* Table 5.7 and the scene's inflow */
static const double RHO_F = 1000.0, RHO_S = 2460.0, MU_F = 1.75e-3, D_P = 403e-6, G = 9.81;
static const double U_IN = 0.077, J_IN = 10.0 / 2460.0;

/* Wen & Yu (1966) in Gidaspow's (1994) form: K = (3/4) C_D phi eps rho_f |slip| eps^-2.65 / d,
   C_D = 24 / Re (1 + 0.15 Re^0.687), Re = eps rho_f |slip| d / mu_f (Re < 1000 here). */
static double wen_yu(double phi, double slip) {
  double eps = 1.0 - phi, re = eps * RHO_F * slip * D_P / MU_F, cd = 24.0 / re * (1.0 + 0.15 * pow(re, 0.687));
  return 0.75 * cd * phi * eps * RHO_F * slip * pow(eps, -2.65) / D_P;
}

static double balance(double phi) {
  double eps = 1.0 - phi, slip = U_IN / eps - J_IN / phi;
  return wen_yu(phi, slip) * slip - phi * eps * (RHO_S - RHO_F) * G;
}

/* the uniform transported phi: bisection above J / U (where the slip is positive) */
static double phi_uniform(void) {
  double a = 1.01 * J_IN / U_IN, b = 0.5;
  for (int k = 0; k < 200; ++k) {
    double m = 0.5 * (a + b);
    if ((balance(a) < 0.0) == (balance(m) < 0.0)) a = m;
    else b = m;
  }
  return 0.5 * (a + b);
}

static void uniform(void) {
  const double phi_eq = phi_uniform();
  printf("  uniform transported suspension: phi %.13f (porosity %.6f), u_s %.5f m/s, u_f %.5f m/s\n", phi_eq,
         1.0 - phi_eq, J_IN / phi_eq, U_IN / (1.0 - phi_eq));
  const char *planar[] = {"mesh.cells=4,20", "boundary.right.type=slip", "scene.geometry=planar",
                          "boundary.left.type=slip", "two_fluid.steady_tolerance=1e-12", NULL};
  const char *axi[] = {"mesh.cells=4,20", "boundary.right.type=slip", "two_fluid.steady_tolerance=1e-12", NULL};
  for (int k = 0; k < 2; ++k) {
    const char *out = "riser_uniform.h5";
    if (run_ok("lscfb_riser", NULL, NULL, k ? axi : planar, out)) continue;
    int n = 0;
    double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
    if (!phi) continue;
    double worst = 0.0;
    for (int c = 0; c < n; ++c) worst = fmax(worst, fabs(phi[c] - phi_eq));
    double err = scalar(out, "solids_conservation_error", tf);
    printf("  uniform (%s, 4 x 20): steady at t = %.2f s, max |phi - phi_eq| %.1e, conservation error %.1e\n",
           k ? "axisymmetric" : "planar", tf, worst, err);
    CHECK_MSG(n == 80, "%d cells", n);
    CHECK_MSG(worst <= 1e-10, "uniform: phi off the drag balance by %.3g", worst);
    CHECK_MSG(tf < 119.0, "uniform: not steady by the end");
    CHECK_MSG(fabs(err) < 1e-12, "uniform: solids not conserved (%.3g)", err);
    free(phi);
  }
}

static void profile(void) {
  const double phi_eq = phi_uniform();
  const int nx = 10, ny = 20;
  const char *sets[] = {"mesh.cells=10,20", "two_fluid.steady_tolerance=1e-7", "time.end=300", NULL};
  const char *out = "riser_profile.h5";
  if (run_ok("lscfb_riser", NULL, NULL, sets, out)) return;
  int n = 0;
  double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
  if (!phi) return;
  CHECK_MSG(n == nx * ny, "%d cells", n);
  if (n != nx * ny) {
    free(phi);
    return;
  }
  /* the developed rows (z = 0.1 .. 0.2 m): cross-section means weighted by r dr (uniform cells, r_i = (i + 1/2) h),
     the core (r < 0.5 R) and the wall band (r > 0.8 R) */
  double mean = 0.0, area = 0.0, core = 0.0, a_core = 0.0, wall = 0.0, a_wall = 0.0, hi = 0.0, lo = 1.0;
  for (int j = ny / 2; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double r = i + 0.5, p = phi[j * nx + i];
      mean += r * p, area += r;
      if (r < 0.5 * nx) core += r * p, a_core += r;
      if (r > 0.8 * nx) wall += r * p, a_wall += r;
      hi = fmax(hi, p), lo = fmin(lo, p);
    }
  mean /= area, core /= a_core, wall /= a_wall;
  double err = scalar(out, "solids_conservation_error", tf);
  printf("  profile (10 x 20, no-slip wall): steady at t = %.1f s; z > 0.1 m: mean porosity %.5f (1-D %.5f), core "
         "%.5f, wall band %.5f, phi in [%.5f, %.5f]; conservation error %.1e\n",
         tf, 1.0 - mean, 1.0 - phi_eq, 1.0 - core, 1.0 - wall, lo, hi, err);
  CHECK_MSG(tf < 299.0, "profile: not steady by the end");
  CHECK_MSG(fabs(err) < 1e-12, "profile: solids not conserved (%.3g)", err);
  CHECK_MSG(fabs(mean - phi_eq) <= 1e-4, "profile: mean phi %.6f off the 1-D %.6f", mean, phi_eq);
  CHECK_MSG(hi - lo <= 1e-3, "profile: a radial contrast of %.3g in phi", hi - lo);
  free(phi);
}

static void bad_input(void) {
  struct {
    const char *sets[3];
    const char *expect;
  } cases[] = {
      {{"boundary.right.solids_flux=0.001", NULL}, "solids_flux"},
      {{"boundary.bottom.solids_flux=-0.001", NULL}, "solids_flux = -0.001 at (0.001, 0), t = 0: it must be finite"},
      {{"boundary.bottom.solids_flux=x < 0.05 ? 0.004 : -1", NULL}, "must be finite and not negative"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene("lscfb_riser", NULL, NULL, cases[k].sets, "riser_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, cases[k].expect), "%s: rc %d, %s", cases[k].sets[0], rc, d.msg);
  }
}

/* argv[1] names one part (uniform, profile); none: all. */
int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  int ran = 0;
  if (argc < 2 || strcmp(argv[1], "uniform") == 0) uniform(), bad_input(), ++ran;
  if (argc < 2 || strcmp(argv[1], "profile") == 0) profile(), ++ran;
  if (!ran) return fprintf(stderr, "unknown part '%s' (uniform, profile)\n", argv[1]), 2;
  return sl_test_summary();
}
