/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The navier_stokes scenes of configs/, run through the same entry point as
 * `sluice run` and read back from their output files:
 *  - cavity_re100: Ghia, Ghia & Shin (1982) centreline stations, and mesh
 *    independence of the profile (n = 24 vs 32);
 *  - cavity_stokes: observed convergence of the centreline minimum (n = 8,
 *    16, 32) and a single solve for the linear problem;
 *  - bingham_channel: the exact Bingham plug flow; the regularisation error
 *    of the centre velocity falls linearly with eps (measured error/eps
 *    ~0.25 = y0); the unyielded cells sit inside the exact plug |y| < 0.25;
 *  - viscometer: the exact Couette and annular Poiseuille profiles to 1e-6;
 *  - bingham_cavity: rigid zones appear and the solution converges as the
 *    regularisation tightens;
 *  - the Bingham cavity at Bn = 20 (configs/bench): loose intermediate
 *    continuation stages and loose damped corrections reach the plain
 *    continuation's solution with fewer factorisations;
 *  - a transient scene (1-D diffusion of w = sin(pi y) e^{-pi^2 t}): BDF1 and
 *    BDF2 observed orders in time, and a run stopped after 5 steps and
 *    restarted from its checkpoint reproduces the uninterrupted run bit for bit;
 *  - the split step ([flow] scheme = projection) on a transient manufactured Stokes flow: orders in time 2 in
 *    the velocity and at least 3/2 in the pressure, the monolithic step's 2 in both;
 *  - a fixed-step constant-coefficient run factorises its matrix once and
 *    assembles it once (later steps assemble the right-hand side only), also
 *    with a time-dependent lid, and then reaches the steady Stokes cavity;
 *    restarted, it gives the uninterrupted run's state bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/io/sample.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];

/* Runs configs/<scene>.ini with overrides into out; returns the code. */
static int run_scene(const char *scene, const char *const *sets, const char *out, const char *restart,
                     sluice_summary *res) {
  sl_diag d = {{0}};
  scene_request q = {.configs = configs, .scene = scene, .sets = sets, .out = out, .restart = restart};
  int rc = scene_run(&q, res, &d);
  CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);
  return rc;
}

/* Component c of `field` at n points. */
static int sample(const char *file, const char *field, int c, int n, const double *xy, double *v) {
  sl_sample s;
  sl_diag d = {{0}};
  int rc = sl_sample_points(file, field, INFINITY, n, xy, &s, &d);
  CHECK_MSG(rc == 0, "%s: %s", file, d.msg);
  if (rc) return rc;
  for (int i = 0; i < n; ++i) v[i] = s.values[(size_t)i * s.components + c];
  sl_sample_free(&s);
  return 0;
}

/* ---- lid-driven cavity ---------------------------------------------------- */

/* Ghia, Ghia & Shin (1982), Table I, Re = 100: u on x = 1/2. */
static const double ghia_y[17] = {1.0000, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5000,
                                  0.4531, 0.2813, 0.1719, 0.1016, 0.0703, 0.0625, 0.0547, 0.0000};
static const double ghia_u[17] = {1.00000,  0.84123,  0.78871,  0.73722,  0.68717,  0.23151,
                                  0.00332,  -0.13641, -0.20581, -0.21090, -0.15662, -0.10150,
                                  -0.06434, -0.04775, -0.04192, -0.03717, 0.00000};

static void cavity_re100(void) {
  double xy[34], u32[17], u24[17];
  for (int k = 0; k < 17; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = ghia_y[k];
  const char *s24[] = {"mesh.cells=24", NULL};
  if (run_scene("cavity_re100", NULL, "re100_32.h5", NULL, NULL) ||
      run_scene("cavity_re100", s24, "re100_24.h5", NULL, NULL))
    return;
  if (sample("re100_32.h5", "velocity", 0, 17, xy, u32) || sample("re100_24.h5", "velocity", 0, 17, xy, u24)) return;
  double dmax = 0.0, dmean = 0.0, mesh = 0.0;
  for (int k = 0; k < 17; ++k) {
    double dev = fabs(u32[k] - ghia_u[k]);
    dmax = fmax(dmax, dev), dmean += dev / 17.0, mesh = fmax(mesh, fabs(u32[k] - u24[k]));
    printf("Re 100: y = %.4f  u = %+.5f  Ghia %+.5f  deviation %.2e  (n = 24: %+.5f)\n", ghia_y[k], u32[k], ghia_u[k],
           u32[k] - ghia_u[k], u24[k]);
  }
  printf("Re 100: deviation from Ghia et al. max %.2e, mean %.2e; n = 24 vs 32 differ by at most %.2e\n", dmax, dmean,
         mesh);
  /* The profile is mesh-converged to well below its distance from Ghia's
   * table (the mesh change is under a fifth of the largest deviation): what
   * remains is the error of their second-order 129 x 129 solution. */
  CHECK_MSG(mesh < 0.2 * dmax, "Re 100 profile changes by %.3g between n = 24 and 32, not small against %.3g", mesh,
            dmax);
  CHECK_MSG(dmean < 2e-3, "Re 100: mean deviation from Ghia %.3g", dmean);
  CHECK_MSG(dmax < 5.5e-3, "Re 100: max deviation from Ghia %.3g", dmax);
  /* The stream function from the conservative face fluxes: the primary vortex's -0.103423 and the bottom-right
   * secondary vortex's 1.25374e-5 (Ghia, Ghia & Shin 1982, Table III, Re = 100), at the nodes of the 32 x 32 mesh;
   * zero on the walls (a closed cavity) to round-off. */
  sl_output_field psi;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field("re100_32.h5", "stream_function", INFINITY, &psi, &d) ||
      sl_output_read_mesh("re100_32.h5", &m, &d)) {
    CHECK_MSG(0, "re100_32.h5: %s", d.msg);
    return;
  }
  double lo = INFINITY, hi = -INFINITY, wall = 0.0;
  for (int32_t i = 0; i < psi.n; ++i) {
    lo = fmin(lo, psi.values[i]), hi = fmax(hi, psi.values[i]);
    const double *x = m.coords + 3 * (size_t)i;
    if (x[0] == 0.0 || x[0] == 1.0 || x[1] == 0.0 || x[1] == 1.0) wall = fmax(wall, fabs(psi.values[i]));
  }
  printf("Re 100: stream function min %.6f (Ghia -0.103423), max %.4e (Ghia 1.25374e-5), on the walls %.1e\n", lo, hi,
         wall);
  CHECK_MSG(fabs(lo + 0.103423) < 2e-4, "Re 100: primary vortex psi %.6f", lo);
  CHECK_MSG(fabs(hi - 1.25374e-5) < 0.05 * 1.25374e-5, "Re 100: secondary vortex psi %.4e", hi);
  CHECK_MSG(wall < 1e-12, "Re 100: psi on the walls %.2e", wall);
  sl_output_field_free(&psi);
  sl_output_mesh_free(&m);
}

static double centreline_min(const char *file) {
  enum { N = 401 };
  double xy[2 * N], u[N];
  for (int k = 0; k < N; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = (double)k / (N - 1);
  if (sample(file, "velocity", 0, N, xy, u)) return NAN;
  double m = INFINITY;
  for (int k = 0; k < N; ++k) m = fmin(m, u[k]);
  return m;
}

/* As bench/bingham_vs_freefem.c measures it: the least of 2001 samples of u(1/2, y), refined by the vertex of
 * the parabola through it and its neighbours. */
static double centreline_min_fine(const char *file) {
  enum { N = 2001 };
  static double xy[2 * N], u[N];
  for (int k = 0; k < N; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = (double)k / (N - 1);
  if (sample(file, "velocity", 0, N, xy, u)) return NAN;
  int k = 1;
  for (int j = 1; j < N - 1; ++j)
    if (u[j] < u[k]) k = j;
  double a = u[k - 1], b = u[k], c = u[k + 1], den = a - 2.0 * b + c;
  return den > 0.0 ? b - (a - c) * (a - c) / (8.0 * den) : b;
}

static void cavity_stokes(void) {
  const int ns[3] = {8, 16, 32};
  double m[3];
  for (int k = 0; k < 3; ++k) {
    char set[64], out[64];
    snprintf(set, sizeof set, "mesh.cells=%d", ns[k]);
    snprintf(out, sizeof out, "stokes_%d.h5", ns[k]);
    const char *sets[] = {set, NULL};
    sluice_summary res;
    if (run_scene("cavity_stokes", sets, out, NULL, &res)) return;
    CHECK_MSG(res.nonlinear_iterations == 1, "Stokes cavity: %ld solves for a linear problem",
              res.nonlinear_iterations);
    CHECK_MSG(res.matrix_assemblies == 1 && res.residual_assemblies == 0,
              "Stokes cavity: %ld matrix and %ld residual assemblies for one linear solve", res.matrix_assemblies,
              res.residual_assemblies);
    m[k] = centreline_min(out);
    printf("Stokes cavity n = %2d: min u on x = 1/2 (401 samples) %.6f\n", ns[k], m[k]);
  }
  double ratio = fabs(m[1] - m[0]) / fabs(m[2] - m[1]);
  printf("Stokes cavity: successive differences %.2e, %.2e (ratio %.1f)\n", fabs(m[1] - m[0]), fabs(m[2] - m[1]),
         ratio);
  CHECK(fabs(m[2] - m[1]) < fabs(m[1] - m[0]));
  CHECK(m[2] < -0.20 && m[2] > -0.215);
}

/* ---- Bingham channel ---------------------------------------------------------- */

static double bingham_exact(double y) {
  const double y0 = 0.25;
  y = fabs(y);
  return y < y0 ? 0.5 * (1.0 - y0) * (1.0 - y0) : 0.5 * (1.0 - y * y) - 0.25 * (1.0 - y);
}

static void bingham_channel(void) {
  const double eps[2] = {1e-3, 1e-4};
  double err_c[2];
  enum { N = 81 };
  for (int k = 0; k < 2; ++k) {
    char set[64], out[64];
    snprintf(set, sizeof set, "closure.viscosity.eps=%g", eps[k]);
    snprintf(out, sizeof out, "bingham_channel_%d.h5", k);
    const char *sets[] = {set, NULL};
    if (run_scene("bingham_channel", sets, out, NULL, NULL)) return;
    double xy[2 * N], w[N], emax = 0.0;
    for (int i = 0; i < N; ++i) xy[2 * i] = -1.0 + 2.0 * i / (N - 1), xy[2 * i + 1] = 0.0;
    if (sample(out, "velocity", 2, N, xy, w)) return;
    for (int i = 0; i < N; ++i) emax = fmax(emax, fabs(w[i] - bingham_exact(xy[2 * i])));
    err_c[k] = fabs(w[N / 2] - bingham_exact(0.0));
    printf("Bingham channel eps = %g: centre velocity %.8f (exact 0.28125, error %.3e), max error %.3e\n", eps[k],
           w[N / 2], err_c[k], emax);
    CHECK_MSG(emax <= 1.05 * err_c[k], "Bingham channel: the largest error %.3g is not the plug's %.3g", emax,
              err_c[k]);
    /* The unyielded cells lie in the exact plug |y| < 0.25, and fill it but for the cells at its edges. */
    sl_output_field f;
    sl_diag d = {{0}};
    if (sl_output_read_field(out, "yielded", INFINITY, &f, &d)) {
      CHECK_MSG(0, "%s", d.msg);
      continue;
    }
    int inside = 0, outside = 0, n_cells = f.n;
    for (int c = 0; c < n_cells; ++c) {
      double yc = -1.0 + 2.0 * (c + 0.5) / n_cells;
      if (f.values[c] < 0.5) {
        if (fabs(yc) < 0.25) ++inside;
        else ++outside;
      }
    }
    int plug_cells = (int)(0.5 / (2.0 / n_cells));
    printf("Bingham channel eps = %g: %d unyielded cells inside the exact plug (of %d), %d outside\n", eps[k], inside,
           plug_cells, outside);
    CHECK(outside == 0 && inside >= plug_cells - 2);
    sl_output_field_free(&f);
  }
  double rate = log10(err_c[0] / err_c[1]);
  printf("Bingham channel: regularisation error of the plug velocity falls as eps^%.3f (Bercovier-Engelman: eps^1)\n",
         rate);
  CHECK_MSG(fabs(rate - 1.0) < 0.05, "regularisation rate %.3f", rate);
  CHECK_CLOSE(err_c[1] / eps[1], 0.25, 0.05); /* ~ y0 eps: the plug creeps at the regularised rate */
}

/* ---- viscometer ---------------------------------------------------------------- */

static void viscometer(void) {
  if (run_scene("viscometer", NULL, "viscometer.h5", NULL, NULL)) return;
  const double ri = 0.015, ro = 0.045, omega = 10.0, G = 1000.0, mu = 1.0;
  const double uz_peak = 0.1152; /* the profile's maximum, near r = 0.0288 */
  /* at vertices of mid-height (48 Q2 cells across the gap) */
  enum { N = 47 };
  double xy[2 * N], uz[N], ut[N], ur[N], ez_max = 0.0, et_max = 0.0, ur_max = 0.0;
  for (int i = 0; i < N; ++i) xy[2 * i] = ri + (ro - ri) * (i + 1) / (N + 1), xy[2 * i + 1] = 0.05;
  if (sample("viscometer.h5", "velocity", 0, N, xy, ur) || sample("viscometer.h5", "velocity", 1, N, xy, uz) ||
      sample("viscometer.h5", "u_theta", 0, N, xy, ut))
    return;
  for (int i = 0; i < N; ++i) {
    double r = xy[2 * i];
    double et = omega / (ri * ri - ro * ro) * (r * ri * ri - ri * ri * ro * ro / r);
    double ez = G / (4.0 * mu) * (ro * ro - r * r + (ro * ro - ri * ri) * log(r / ro) / log(ro / ri));
    et_max = fmax(et_max, fabs(ut[i] - et) / (omega * ri));
    ez_max = fmax(ez_max, fabs(uz[i] - ez) / uz_peak);
    ur_max = fmax(ur_max, fabs(ur[i]) / (omega * ri));
  }
  printf("viscometer: swirl error %.2e of omega r_i, axial error %.2e of its peak, radial velocity %.2e of omega r_i\n",
         et_max, ez_max, ur_max);
  CHECK(et_max < 1e-6 && ez_max < 1e-6 && ur_max < 1e-6);
}

/* ---- Bingham cavity ------------------------------------------------------------- */

static void bingham_cavity(void) {
  const double eps[3] = {1e-1, 1e-2, 1e-3};
  double uc[3];
  for (int k = 0; k < 3; ++k) {
    char set[64], out[64];
    snprintf(set, sizeof set, "closure.viscosity.eps=%g", eps[k]);
    snprintf(out, sizeof out, "bingham_cavity_%d.h5", k);
    const char *sets[] = {"mesh.cells=16", set, "solver.continuation_steps=3", NULL};
    if (run_scene("bingham_cavity", sets, out, NULL, NULL)) return;
    double xy[2] = {0.5, 0.75};
    if (sample(out, "velocity", 0, 1, xy, &uc[k])) return;
    sl_output_field f;
    sl_diag d = {{0}};
    if (sl_output_read_field(out, "yielded", INFINITY, &f, &d)) {
      CHECK_MSG(0, "%s", d.msg);
      return;
    }
    int rigid = 0;
    for (int c = 0; c < f.n; ++c) rigid += f.values[c] < 0.5;
    printf("Bingham cavity eps = %g: u(0.5, 0.75) = %.6f, %d of %d cells unyielded\n", eps[k], uc[k], rigid, (int)f.n);
    if (k == 2) CHECK_MSG(rigid > f.n / 20 && rigid < f.n * 19 / 20, "%d of %d cells rigid", rigid, (int)f.n);
    sl_output_field_free(&f);
  }
  printf("Bingham cavity: change of u(0.5, 0.75) per decade of eps: %.2e, %.2e\n", fabs(uc[1] - uc[0]),
         fabs(uc[2] - uc[1]));
  CHECK(fabs(uc[2] - uc[1]) < 0.5 * fabs(uc[1] - uc[0]));
}

/* ---- Bingham cavity at Bn = 20: the continuation's cost --------------------------------------- */

/* configs/bench/bingham_cavity_bn20.ini (Papanastasiou m = 1000 by continuation from m = 1) on 16 x 16 cells,
 * three ways: (a) every stage to Newton's 1e-9 and every correction by a direct solve ([solver] reuse = never),
 * the plain Newton continuation; (b) every stage to 1e-9 with the defaults (a stage's first and damped
 * corrections to a relative residual of 0.1, answered by FGMRES with an older factorisation where it can);
 * (c) the scene as given, the stages before the last to 1e-3 (continuation_tolerance). All three converge to
 * the same discrete solution, within what the last stage's tolerance leaves (1e-9 of max |u| = 1, the
 * corrections contracting quadratically): the centreline minimum agrees to 1e-8 and equals the value of
 * the plain continuation before either change, -0.13231193 (docs/benchmarks.md, n = 16); (b) and (c) take
 * fewer numeric factorisations than (a), and (c) fewer Newton iterations than (b). */
static void bingham_bn20_continuation(void) {
  static const char *const way[3][3] = {{"solver.continuation_tolerance=1e-9", "solver.reuse=never", NULL},
                                        {"solver.continuation_tolerance=1e-9", NULL, NULL},
                                        {NULL, NULL, NULL}};
  static const char *const name[3] = {"direct, every stage to 1e-9", "defaults, every stage to 1e-9",
                                      "the scene (stages to 1e-3)"};
  double umin[3];
  long newton[3], fact[3];
  for (int k = 0; k < 3; ++k) {
    const char *sets[5] = {"mesh.cells=16", "output.fields=velocity", way[k][0], way[k][1], NULL};
    char out[64];
    snprintf(out, sizeof out, "bingham_bn20_way%d.h5", k);
    sluice_summary res;
    if (run_scene("bench/bingham_cavity_bn20", sets, out, NULL, &res)) return;
    umin[k] = centreline_min_fine(out);
    newton[k] = res.nonlinear_iterations, fact[k] = res.linear.n_numeric;
    printf("Bingham Bn = 20, 16 x 16, %s: u_min %.10f, %ld Newton iterations, %ld factorisations\n", name[k], umin[k],
           newton[k], fact[k]);
  }
  for (int k = 0; k < 3; ++k) {
    CHECK_MSG(fabs(umin[k] - umin[0]) < 1e-8, "%s: u_min %.10f, direct %.10f", name[k], umin[k], umin[0]);
    CHECK_MSG(fabs(umin[k] + 0.13231193) < 1e-8, "%s: u_min %.10f, not -0.13231193", name[k], umin[k]);
  }
  CHECK_MSG(fact[1] < fact[0] && fact[2] < fact[0], "factorisations %ld, %ld, %ld", fact[0], fact[1], fact[2]);
  CHECK_MSG(newton[2] < newton[1], "Newton iterations %ld (stages to 1e-3) against %ld", newton[2], newton[1]);
}

/* ---- transient: orders in time, restart --------------------------------------------- */

static double diffusion_error(const char *scheme, double dt, const char *out) {
  char s1[64], s2[64];
  snprintf(s1, sizeof s1, "time.scheme=%s", scheme);
  snprintf(s2, sizeof s2, "time.dt=%g", dt);
  const char *sets[] = {s1, s2, "time.adaptive=false", NULL};
  if (run_scene("diffusion_1d", sets, out, NULL, NULL)) return NAN;
  enum { N = 21 };
  double xy[2 * N], w[N], e = 0.0;
  for (int i = 0; i < N; ++i) xy[2 * i] = (double)i / (N - 1), xy[2 * i + 1] = 0.0;
  if (sample(out, "velocity", 2, N, xy, w)) return NAN;
  for (int i = 0; i < N; ++i) e = fmax(e, fabs(w[i] - sin(M_PI * xy[2 * i]) * exp(-M_PI * M_PI * 0.2)));
  return e;
}

static void time_orders(void) {
  const char *schemes[2] = {"bdf1", "bdf2"};
  for (int s = 0; s < 2; ++s) {
    double e[3];
    for (int k = 0; k < 3; ++k) e[k] = diffusion_error(schemes[s], 0.02 / (1 << k), "diffusion.h5");
    for (int k = 0; k < 2; ++k) {
      double order = log2(e[k] / e[k + 1]);
      printf("diffusion, %s: error %.3e -> %.3e, order in time %.3f\n", schemes[s], e[k], e[k + 1], order);
      CHECK_MSG(fabs(order - (s + 1)) < 0.12, "%s order %.3f", schemes[s], order);
    }
  }
}

static int read_velocity(const char *file, sl_output_field *f) {
  sl_diag d = {{0}};
  int rc = sl_output_read_field(file, "velocity", INFINITY, f, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  return rc;
}

/* A constant-coefficient run with a fixed step: BDF1 with dt = 0.01 to
 * t = 0.1, where the accumulated time reaches the end 1e-17 short of a
 * whole step. Every step's matrix is the same, so it is factorised once
 * (the last step is not shortened by round-off into a new matrix). */
static void single_factorisation(void) {
  const char *sets[] = {"time.scheme=bdf1", "time.adaptive=false", "time.dt=0.01",
                        "time.end=0.1",     "output.every=0",      NULL};
  sluice_summary res;
  if (run_scene("diffusion_1d", sets, "one_factor.h5", NULL, &res)) return;
  printf("constant coefficients: %ld steps, %ld matrix assemblies, %ld right-hand sides, %s\n", res.steps,
         res.matrix_assemblies, res.residual_assemblies, res.linear_summary);
  CHECK(res.steps == 10);
  CHECK_CONTAINS(res.linear_summary, " 1 numeric");
  CHECK_MSG(res.matrix_assemblies == 1 && res.residual_assemblies == 9, "%ld matrix, %ld residual-only assemblies",
            res.matrix_assemblies, res.residual_assemblies);
}

/* The Stokes cavity (n = 8) from rest, BDF1 with dt = 0.05 to t = 3, the
 * lid ramped up to 1 by t = 1: one matrix assembly and one factorisation
 * (the lid's values enter the right-hand side only), and the end state is
 * the steady solution (stokes_8.h5 from cavity_stokes) to 1e-9; the slowest
 * mode decays by about 1 / (1 + 2 pi^2 dt) per step. */
static void constant_coefficient_steps(void) {
  const char *sets[] = {"mesh.cells=8",
                        "time.scheme=bdf1",
                        "time.adaptive=false",
                        "time.dt=0.05",
                        "time.end=3",
                        "output.every=0",
                        "boundary.top.velocity=min(1, t), 0",
                        NULL};
  sluice_summary res;
  if (run_scene("cavity_stokes", sets, "stokes_8_steps.h5", NULL, &res)) return;
  printf("Stokes cavity, ramped lid: %ld steps, %ld matrix assemblies, %ld right-hand sides, %s\n", res.steps,
         res.matrix_assemblies, res.residual_assemblies, res.linear_summary);
  CHECK(res.steps == 60);
  CHECK_CONTAINS(res.linear_summary, " 1 numeric");
  CHECK_MSG(res.matrix_assemblies == 1 && res.residual_assemblies == 59, "%ld matrix, %ld residual-only assemblies",
            res.matrix_assemblies, res.residual_assemblies);
  sl_output_field a, b;
  if (read_velocity("stokes_8_steps.h5", &a)) return;
  if (read_velocity("stokes_8.h5", &b) == 0) {
    double e = a.n == b.n ? 0.0 : INFINITY;
    for (long i = 0; a.n == b.n && i < (long)a.n * a.components; ++i) e = fmax(e, fabs(a.values[i] - b.values[i]));
    printf("Stokes cavity, ramped lid: max |u(3) - u_steady| = %.2e\n", e);
    CHECK_MSG(e < 1e-9, "the transient run ends %.3g from the steady solution", e);
    sl_output_field_free(&b);
  }
  sl_output_field_free(&a);
  /* Restarted after 4 of 10 BDF2 steps, the run assembles its matrix afresh where the uninterrupted one kept it:
     the end states agree bit for bit. */
  const char *whole[] = {"mesh.cells=8",
                         "time.scheme=bdf2",
                         "time.adaptive=false",
                         "time.dt=0.05",
                         "time.end=0.5",
                         "output.every=0",
                         "boundary.top.velocity=min(1, 4*t), 0",
                         NULL};
  const char *part[] = {"mesh.cells=8",
                        "time.scheme=bdf2",
                        "time.adaptive=false",
                        "time.dt=0.05",
                        "time.end=0.5",
                        "output.every=0",
                        "boundary.top.velocity=min(1, 4*t), 0",
                        "time.max_steps=4",
                        NULL};
  sluice_summary r1, r2, r3;
  if (run_scene("cavity_stokes", whole, "kept_whole.h5", NULL, &r1) ||
      run_scene("cavity_stokes", part, "kept_first.h5", NULL, &r2) ||
      run_scene("cavity_stokes", whole, "kept_second.h5", "kept_first.h5", &r3))
    return;
  /* BDF2 starts with a BDF1 step: two mass coefficients, two matrices; the restart assembles one more */
  CHECK_MSG(r1.steps == 10 && r1.matrix_assemblies == 2 && r3.steps == 10 && r3.matrix_assemblies == 1,
            "%ld steps, %ld matrix assemblies; restarted: %ld steps, %ld matrix assemblies", r1.steps,
            r1.matrix_assemblies, r3.steps, r3.matrix_assemblies);
  if (read_velocity("kept_whole.h5", &a)) return;
  if (read_velocity("kept_second.h5", &b) == 0) {
    CHECK_MSG(
        a.n == b.n && a.time == b.time && memcmp(a.values, b.values, (size_t)a.n * a.components * sizeof(double)) == 0,
        "the restarted run differs from the uninterrupted one");
    sl_output_field_free(&b);
  }
  sl_output_field_free(&a);
}

static void restart(void) {
  sluice_summary a, b, c;
  const char *full[] = {"time.adaptive=true", NULL};
  const char *part[] = {"time.adaptive=true", "time.max_steps=5", NULL};
  if (run_scene("diffusion_1d", full, "whole.h5", NULL, &a) || run_scene("diffusion_1d", part, "first.h5", NULL, &b) ||
      run_scene("diffusion_1d", full, "second.h5", "first.h5", &c))
    return;
  printf("restart: uninterrupted %ld steps to t = %g; interrupted after %ld steps at t = %g, restarted to step %ld\n",
         a.steps, a.t_reached, b.steps, b.t_reached, c.steps);
  CHECK(b.steps == 5 && b.t_reached < a.t_reached && c.steps == a.steps);
  sl_output_field fa, fc;
  if (read_velocity("whole.h5", &fa)) return;
  if (read_velocity("second.h5", &fc) == 0) {
    CHECK(fa.n == fc.n && fa.time == fc.time);
    CHECK_MSG(fa.n == fc.n && memcmp(fa.values, fc.values, (size_t)fa.n * fa.components * sizeof(double)) == 0,
              "the restarted run differs from the uninterrupted one");
    sl_output_field_free(&fc);
  }
  sl_output_field_free(&fa);
}

static void set_configs(const char *sub);

/* A nonlinear transient run (the Re = 100 cavity started from rest, adaptive BDF2), whose Newton solves reuse
 * factorisations: stopped at an output time and restarted from its checkpoint there, it ends bit for bit where the
 * uninterrupted run does (the checkpoint holds the kept factorisation, which the restart rebuilds), with the same
 * steps (the controller's state carries over). */
static void restart_reuse(void) {
  set_configs("configs");
  const char *full[] = {"mesh.cells=8,8",     "time.scheme=bdf2", "time.dt=0.01",     "time.end=0.4",
                        "time.adaptive=true", "time.dt_max=0.02", "output.every=0.1", NULL};
  const char *part[] = {"mesh.cells=8,8",     "time.scheme=bdf2", "time.dt=0.01",     "time.end=0.2",
                        "time.adaptive=true", "time.dt_max=0.02", "output.every=0.1", NULL};
  sluice_summary a, b, c;
  int rc = run_scene("cavity_re100", full, "reuse_whole.h5", NULL, &a) ||
           run_scene("cavity_re100", part, "reuse_first.h5", NULL, &b) ||
           run_scene("cavity_re100", full, "reuse_second.h5", "reuse_first.h5", &c);
  set_configs("tests/scenes");
  if (rc) return;
  printf(
      "restart with reuse: uninterrupted %ld steps (%ld rejected), %ld reused solves of %ld; stopped at t = %g "
      "after %ld steps, restarted: %ld steps (%ld rejected)\n",
      a.steps, a.rejected_steps, a.linear.n_reused, a.linear.n_solves, b.t_reached, b.steps, c.steps, c.rejected_steps);
  CHECK(a.linear.n_reused > 0 && b.steps < a.steps && c.steps == a.steps && c.rejected_steps == a.rejected_steps);
  sl_output_field fa, fc;
  if (read_velocity("reuse_whole.h5", &fa)) return;
  if (read_velocity("reuse_second.h5", &fc) == 0) {
    CHECK_MSG(fa.n == fc.n && fa.time == fc.time &&
                  memcmp(fa.values, fc.values, (size_t)fa.n * fa.components * sizeof(double)) == 0,
              "the restarted run differs from the uninterrupted one");
    sl_output_field_free(&fc);
  }
  sl_output_field_free(&fa);
}

static void set_configs(const char *sub) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/%s", src ? src : ".", sub);
}

/* ---- a manufactured solution from the command line ------------------------------------------ */

/* configs/mms_stokes.ini: the exact u, v, p of its comment, held by a body force written as expressions of x and
 * y. On 8, 16, 32 cells the root-mean-square error over a 50 x 50 grid of points (a midpoint rule for the L2
 * norm) falls at order 3 in the velocity (Q2, within 0.25) and at least 2 in the pressure (Q1; 3.0 then 2.25
 * here, still superconvergent on the coarse meshes). */
static void mms_stokes(void) {
  set_configs("configs");
  enum { NG = 50, NP = NG * NG };
  static double xy[2 * NP], ue[NP], ve[NP], pe[NP], u[NP], v[NP], p[NP];
  for (int i = 0; i < NG; ++i)
    for (int j = 0; j < NG; ++j) {
      double x = (i + 0.5) / NG, y = (j + 0.5) / NG;
      int k = NG * i + j;
      xy[2 * k] = x, xy[2 * k + 1] = y;
      ue[k] = M_PI * pow(sin(M_PI * x), 2) * sin(2 * M_PI * y);
      ve[k] = -M_PI * sin(2 * M_PI * x) * pow(sin(M_PI * y), 2);
      pe[k] = cos(M_PI * x) * cos(M_PI * y);
    }
  double eu[3], ep[3];
  const int ns[3] = {8, 16, 32};
  for (int m = 0; m < 3; ++m) {
    char cells[64], out[64];
    snprintf(cells, sizeof cells, "mesh.cells=%d,%d", ns[m], ns[m]);
    snprintf(out, sizeof out, "mms_stokes_%d.h5", ns[m]);
    const char *sets[] = {cells, NULL};
    if (run_scene("mms_stokes", sets, out, NULL, NULL) || sample(out, "velocity", 0, NP, xy, u) ||
        sample(out, "velocity", 1, NP, xy, v) || sample(out, "pressure", 0, NP, xy, p))
      return;
    double su = 0.0, sp = 0.0;
    for (int k = 0; k < NP; ++k) {
      su += (u[k] - ue[k]) * (u[k] - ue[k]) + (v[k] - ve[k]) * (v[k] - ve[k]);
      sp += (p[k] - pe[k]) * (p[k] - pe[k]);
    }
    eu[m] = sqrt(su / NP), ep[m] = sqrt(sp / NP);
  }
  double ou = log2(eu[1] / eu[2]), op = log2(ep[1] / ep[2]);
  printf(
      "mms_stokes: L2 velocity error %.3e, %.3e, %.3e (orders %.2f, %.2f), pressure %.3e, %.3e, %.3e (orders "
      "%.2f, %.2f)\n",
      eu[0], eu[1], eu[2], log2(eu[0] / eu[1]), ou, ep[0], ep[1], ep[2], log2(ep[0] / ep[1]), op);
  CHECK_MSG(fabs(ou - 3.0) < 0.25, "velocity order %.2f", ou);
  CHECK_MSG(op > 1.8, "pressure order %.2f (at least 2 expected)", op);
}

/* ---- the split step: orders in time ------------------------------------------------------- */

/* tests/scenes/mms_stokes_transient.ini to t = 1 with fixed steps 0.1 / 2^k: the root-mean-square difference
 * over a 40 x 40 grid of points from a monolithic run with dt = 1/2000 on the same mesh (the time-continuous
 * solution of the spatial discretisation to about 1e-7, below every difference measured). The incremental
 * rotational scheme (Guermond, Minev & Shen 2006, Theorem 3.1 and section 3.4) converges at order 2 in the
 * velocity (L2) and 3/2 in the pressure; the monolithic BDF2 at order 2 in both. */
static int split_fields(const char *out, int n, const double *xy, double *u, double *v, double *p) {
  return sample(out, "velocity", 0, n, xy, u) || sample(out, "velocity", 1, n, xy, v) ||
         sample(out, "pressure", 0, n, xy, p);
}

static void projection_restart(void);

static void projection_orders(void) {
  set_configs("tests/scenes");
  enum { NG = 40, NP = NG * NG, NK = 5 };
  static double xy[2 * NP], ur[NP], vr[NP], pr[NP], u[NP], v[NP], p[NP];
  for (int i = 0; i < NG; ++i)
    for (int j = 0; j < NG; ++j) xy[2 * (NG * i + j)] = (i + 0.5) / NG, xy[2 * (NG * i + j) + 1] = (j + 0.5) / NG;
  const char *ref_sets[] = {"time.dt=0.0005", NULL};
  if (run_scene("mms_stokes_transient", ref_sets, "split_ref.h5", NULL, NULL) ||
      split_fields("split_ref.h5", NP, xy, ur, vr, pr))
    return;
  static const char *const schemes[2] = {"monolithic", "projection"};
  for (int s = 0; s < 2; ++s) {
    double eu[NK], ep[NK];
    for (int k = 0; k < NK; ++k) {
      char sc[64], dt[64];
      snprintf(sc, sizeof sc, "flow.scheme=%s", schemes[s]);
      snprintf(dt, sizeof dt, "time.dt=%.17g", 0.1 / (1 << k));
      const char *sets[] = {sc, dt, NULL};
      if (run_scene("mms_stokes_transient", sets, "split.h5", NULL, NULL) || split_fields("split.h5", NP, xy, u, v, p))
        return;
      double su = 0.0, sp = 0.0;
      for (int i = 0; i < NP; ++i) {
        su += (u[i] - ur[i]) * (u[i] - ur[i]) + (v[i] - vr[i]) * (v[i] - vr[i]);
        sp += (p[i] - pr[i]) * (p[i] - pr[i]);
      }
      eu[k] = sqrt(su / NP), ep[k] = sqrt(sp / NP);
    }
    for (int k = 0; k + 1 < NK; ++k)
      printf("%s: dt %.4g -> %.4g: velocity %.3e -> %.3e (order %.2f), pressure %.3e -> %.3e (order %.2f)\n",
             schemes[s], 0.1 / (1 << k), 0.1 / (2 << k), eu[k], eu[k + 1], log2(eu[k] / eu[k + 1]), ep[k], ep[k + 1],
             log2(ep[k] / ep[k + 1]));
    double ou = log2(eu[NK - 2] / eu[NK - 1]), op = log2(ep[NK - 2] / ep[NK - 1]);
    CHECK_MSG(fabs(ou - 2.0) < 0.25, "%s: velocity order %.2f (2 expected)", schemes[s], ou);
    if (s == 0) CHECK_MSG(fabs(op - 2.0) < 0.25, "monolithic: pressure order %.2f (2 expected)", op);
    else CHECK_MSG(op > 1.3, "projection: pressure order %.2f (3/2 expected)", op);
  }
  projection_restart();
}

/* The split step with adaptive steps, stopped after 6 steps and restarted from its checkpoint, ends bit for bit
 * where the uninterrupted run does (the increments, the pressure predictor's weights and the preconditioner's
 * values are in the checkpoint). */
static void projection_restart(void) {
  const char *full[] = {"flow.scheme=projection", "time.adaptive=true", "time.tolerance=1e-4", "time.dt=0.01", NULL};
  const char *part[] = {"flow.scheme=projection", "time.adaptive=true", "time.tolerance=1e-4",
                        "time.dt=0.01",           "time.max_steps=6",   NULL};
  sluice_summary a, b, c;
  if (run_scene("mms_stokes_transient", full, "split_whole.h5", NULL, &a) ||
      run_scene("mms_stokes_transient", part, "split_first.h5", NULL, &b) ||
      run_scene("mms_stokes_transient", full, "split_second.h5", "split_first.h5", &c))
    return;
  printf("projection restart: uninterrupted %ld steps; interrupted after %ld at t = %g, restarted to step %ld\n",
         a.steps, b.steps, b.t_reached, c.steps);
  CHECK(b.steps == 6 && c.steps == a.steps);
  static const char *const fields[2] = {"velocity", "pressure"};
  for (int k = 0; k < 2; ++k) {
    sl_output_field fa, fc;
    sl_diag d = {{0}};
    if (sl_output_read_field("split_whole.h5", fields[k], INFINITY, &fa, &d)) {
      CHECK_MSG(0, "%s", d.msg);
      return;
    }
    if (sl_output_read_field("split_second.h5", fields[k], INFINITY, &fc, &d) == 0) {
      CHECK_MSG(fa.n == fc.n && fa.time == fc.time &&
                    memcmp(fa.values, fc.values, (size_t)fa.n * fa.components * sizeof(double)) == 0,
                "the restarted split run's %s differs from the uninterrupted one's", fields[k]);
      sl_output_field_free(&fc);
    } else {
      CHECK_MSG(0, "%s", d.msg);
    }
    sl_output_field_free(&fa);
  }
}

static void cavities(void) {
  set_configs("configs");
  cavity_re100();
  cavity_stokes();
  constant_coefficient_steps(); /* reads cavity_stokes's stokes_8.h5 */
}

static void bingham_and_viscometer(void) {
  set_configs("configs");
  bingham_channel();
  viscometer();
  bingham_cavity();
}

static void continuation_cost(void) {
  set_configs("configs");
  bingham_bn20_continuation();
}

static void time_stepping(void) {
  set_configs("tests/scenes");
  time_orders();
  single_factorisation();
  restart();
  restart_reuse();
}

/* argv[1] names one part (its own ctest entry, so that the parts run in
 * parallel); none: all. */
int main(int argc, char **argv) {
  static const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"cavity", cavities},
               {"bingham", bingham_and_viscometer},
               {"continuation", continuation_cost},
               {"time", time_stepping},
               {"mms", mms_stokes},
               {"projection", projection_orders}};
  int ran = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 || strcmp(argv[1], parts[k].name) == 0) parts[k].run(), ++ran;
  if (!ran)
    return fprintf(stderr, "unknown part '%s' (cavity, bingham, continuation, time, mms, projection)\n", argv[1]), 2;
  return sl_test_summary();
}
