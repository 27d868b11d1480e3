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

#include "core/study/chart.h"
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
  const char *planar[] = {"mesh.cells=4,20",         "boundary.right.type=slip",         "scene.geometry=planar",
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
  printf(
      "  profile (10 x 20, no-slip wall): steady at t = %.1f s; z > 0.1 m: mean porosity %.5f (1-D %.5f), core "
      "%.5f, wall band %.5f, phi in [%.5f, %.5f]; conservation error %.1e\n",
      tf, 1.0 - mean, 1.0 - phi_eq, 1.0 - core, 1.0 - wall, lo, hi, err);
  CHECK_MSG(tf < 299.0, "profile: not steady by the end");
  CHECK_MSG(fabs(err) < 1e-12, "profile: solids not conserved (%.3g)", err);
  CHECK_MSG(fabs(mean - phi_eq) <= 1e-4, "profile: mean phi %.6f off the 1-D %.6f", mean, phi_eq);
  CHECK_MSG(hi - lo <= 1e-3, "profile: a radial contrast of %.3g in phi", hi - lo);
  free(phi);
}

/* dispersed: configs/lscfb_riser_dispersed.ini, the no-slip riser with the turbulent dispersion of the solids
 * ([closure.turbulent_dispersion] model = gradient) and the turbophoretic drift (two_fluid_plane_dispersion.c), on
 * 12 x 20 cells graded geometrically to the wall (the last cell 0.05 times the first: 24.8 mm at the axis, 1.24 mm
 * at the wall, y+ = 3.5). Across the developed rows (z > 0.1 m) the wall cell must be denser than the axis cell by
 * more than the laminar model's whole contrast (1e-3 in porosity, scenes_riser_profile), the r dr mean porosity must
 * stay at the 1-D balance within 2e-4 (the solids the drift gathers in the wall's slow layer are few; measured
 * 5e-5), solids conserved to round-off. The radial profile at z = 0.15 m is drawn (riser_porosity.svg/.png,
 * docs/riser.md). */
static void dispersed(void) {
  const double phi_eq = phi_uniform(), R = 0.1, ratio = 0.05;
  enum { NX = 12, NY = 20 };
  const char *sets[] = {"mesh.cells=12,20", "mesh.grading_x=geometric:0.05", "two_fluid.steady_tolerance=1e-6",
                        "time.end=300", NULL};
  const char *out = "riser_dispersed.h5";
  if (run_ok("lscfb_riser_dispersed", NULL, NULL, sets, out)) return;
  int n = 0;
  double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
  if (!phi) return;
  CHECK_MSG(n == NX * NY, "%d cells", n);
  if (n != NX * NY) {
    free(phi);
    return;
  }
  /* the geometric grading (core/mesh/generate.c): h_i = h_0 q^i, q = ratio^(1/(n - 1)), summing to R */
  double h[NX], rc[NX], xf = 0.0, sum = 0.0, q = pow(ratio, 1.0 / (NX - 1));
  for (int i = 0; i < NX; ++i) h[i] = pow(q, i), sum += h[i];
  for (int i = 0; i < NX; ++i) h[i] *= R / sum, rc[i] = xf + 0.5 * h[i], xf += h[i];
  double mean = 0.0, area = 0.0, axis = 0.0, wall = 0.0, prof[NX] = {0};
  for (int j = NY / 2; j < NY; ++j)
    for (int i = 0; i < NX; ++i) {
      double p = phi[j * NX + i], a = rc[i] * h[i];
      mean += a * p, area += a;
      if (i == 0) axis += p / (NY / 2);
      if (i == NX - 1) wall += p / (NY / 2);
    }
  mean /= area;
  for (int i = 0; i < NX; ++i) prof[i] = 1.0 - phi[(3 * NY / 4) * NX + i]; /* the row at z = 0.15 m */
  double err = scalar(out, "solids_conservation_error", tf);
  printf(
      "  dispersed (12 x 20 graded, no-slip wall): steady at t = %.1f s; z > 0.1 m: mean porosity %.5f (1-D "
      "%.5f, %+.2e), axis cell %.5f, wall cell %.5f (wall - axis %+.2e); conservation error %.1e\n",
      tf, 1.0 - mean, 1.0 - phi_eq, phi_eq - mean, 1.0 - axis, 1.0 - wall, axis - wall, err);
  printf("  dispersed: porosity at z = 0.15 m against r (m):");
  for (int i = 0; i < NX; ++i) printf(" %.4f:%.5f", rc[i], prof[i]);
  printf("\n");
  CHECK_MSG(tf < 299.0, "dispersed: not steady by the end");
  CHECK_MSG(fabs(err) < 1e-12, "dispersed: solids not conserved (%.3g)", err);
  CHECK_MSG(wall - axis > 1e-3,
            "dispersed: the wall cell is not denser than the axis cell by 1e-3 (phi %.6f against "
            "%.6f)",
            wall, axis);
  CHECK_MSG(fabs(mean - phi_eq) <= 2e-4, "dispersed: mean phi %.6f off the 1-D %.6f", mean, phi_eq);
  /* the picture: the developed profile against the uniform suspension of the 1-D balance */
  double rr[NX], eq[2] = {1.0 - phi_eq, 1.0 - phi_eq}, ends[2] = {0.0, 1.0};
  for (int i = 0; i < NX; ++i) rr[i] = rc[i] / R;
  sl_chart_series se[2] = {{.name = "turbophoretic dispersion, 12 x 20 graded", .n = NX, .x = rr, .y = prof},
                           {.name = "1-D balance (laminar model: flat to 1e-4)",
                            .n = 2,
                            .x = ends,
                            .y = eq,
                            .dashed = 1,
                            .marker = SL_CHART_MARK_NONE,
                            .colour = "#7F7F7F"}};
  sl_chart c = {.title = "riser porosity across the pipe at z = 0.15 m",
                .subtitle =
                    "lscfb_riser_dispersed.ini: 403 um glass beads, U = 0.077 m/s, G_{s} = 10 kg/m^{2}/s "
                    "(assumed); steady",
                .xlabel = "r/R (axis 0, wall 1)",
                .ylabel = "porosity 1 \xE2\x88\x92 \xCF\x86",
                .n_series = 2,
                .series = se,
                .legend = SL_LEGEND_BOTTOM_LEFT};
  sl_diag d = {{0}};
  int rc_svg = sl_chart_write_svg("riser_porosity.svg", &c, 640, 400, &d);
  CHECK_MSG(rc_svg == 0, "riser_porosity.svg: %s", d.msg);
  int rc_png = sl_chart_write_png("riser_porosity.png", &c, 640, 400, &d);
  CHECK_MSG(rc_png == 0, "riser_porosity.png: %s", d.msg);
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
  /* the dispersion's keys: one without [closure.turbulence], the closure without k and epsilon, a k that is not
     positive in a cell; [closure.turbulent_dispersion] without [closure.turbulence], and model = simonin, whose
     t_fs and k_fs the 2-D model does not compute */
  struct {
    const char *scene, *sets[3];
    const char *expect;
  } disp[] = {
      {"lscfb_riser",
       {"two_fluid.turbophoresis=true", NULL},
       "turbophoresis: the solids' turbulent dispersion needs [closure.turbulence]"},
      {"lscfb_riser", {"closure.turbulence.model=k_epsilon", NULL}, "[two_fluid] turbulence_k and turbulence_epsilon"},
      {"lscfb_riser_dispersed", {"two_fluid.turbulence_k=x - 0.05", NULL}, "turbulence_k = -0.0"},
      {"lscfb_riser",
       {"closure.turbulent_dispersion.model=gradient", NULL},
       "the solids' turbulent dispersivity is of the fluid's eddy viscosity: it needs [closure.turbulence]"},
      {"lscfb_riser_dispersed",
       {"closure.turbulent_dispersion.model=simonin", NULL},
       "takes t_fs and k_fs, which the 2-D two_fluid model does not compute"},
  };
  for (size_t k = 0; k < sizeof disp / sizeof disp[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene(disp[k].scene, NULL, NULL, disp[k].sets, "riser_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, disp[k].expect), "%s: rc %d, %s", disp[k].sets[0], rc, d.msg);
  }
}

/* argv[1] names one part (uniform, profile, dispersed); none: all. */
int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  int ran = 0;
  if (argc < 2 || strcmp(argv[1], "uniform") == 0) uniform(), bad_input(), ++ran;
  if (argc < 2 || strcmp(argv[1], "profile") == 0) profile(), ++ran;
  if (argc < 2 || strcmp(argv[1], "dispersed") == 0) dispersed(), ++ran;
  if (!ran) return fprintf(stderr, "unknown part '%s' (uniform, profile, dispersed)\n", argv[1]), 2;
  return sl_test_summary();
}
