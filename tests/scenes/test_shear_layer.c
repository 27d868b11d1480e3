/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid shear layer (`[two_fluid] motion = shear`): ktgf_shear.ini
 * and shear_cell.ini of configs/, and variants written here, run through
 * the entry point of `sluice run` and read back from their output files.
 *
 * ktgf_shear: homogeneous simple shear. The granular temperature follows
 * the exact solution of (3/2) rho_s phi dtheta/dt = mu_s gdot^2 - gamma with
 * Lun et al.'s (1984) mu_s = mu0 theta^0.5 and gamma = gamma0 theta^1.5
 * (coded here from the formulas, not through the closure) at first order in
 * dt, and settles on the algebraic equilibrium theta = mu0 gdot^2 / gamma0;
 * with the interphase sink 3 K theta (Wen-Yu's K at zero slip) on the root
 * of gamma0 s^2 + 3 K s - mu0 gdot^2 = 0, s = sqrt(theta); the algebraic
 * option gives that balance at once.
 * Annular Couette (a variant): each phase on u = A r + B/r at the nodes to
 * round-off, and the wall stresses and torques of its viscosity.
 * shear_cell: Bagnold's two regimes at the walls, the solids wall stress
 * growing as the speed (N < 40) and as its square (N > 450), and the torque
 * on the inner cylinder balancing the outer one at steady state.
 * Johnson & Jackson walls (a planar variant): the antisymmetry of Couette
 * flow and the balance of the wall forces. Restart bit for bit. Bad input
 * exits 2 with the location. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "kinetic_reference.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];

SCENE_RUNNERS()

static const double PI = 3.14159265358979323846;

static double *node_field(const char *file, const char *name, double t, int *n) {
  sl_output_field f;
  sl_diag d = {{0}};
  if (sl_output_read_field(file, name, t, &f, &d)) {
    CHECK_MSG(0, "%s: %s: %s", file, name, d.msg);
    return NULL;
  }
  double *v = malloc((size_t)f.n * sizeof *v);
  if (v) memcpy(v, f.values, (size_t)f.n * sizeof *v);
  *n = (int)f.n;
  sl_output_field_free(&f);
  return v;
}

static double scalar(const char *file, const char *name, double t) {
  sl_diag d = {{0}};
  double v = NAN, tf;
  int rc = sl_output_read_scalar(file, name, t, &v, &tf, &d);
  CHECK_MSG(rc == 0, "%s: %s: %s", file, name, d.msg);
  return v;
}

/* A scene written to the working folder from text, run as `sluice run`. */
static int run_text(const char *name, const char *text, const char *const *sets, const char *out, const char *restart,
                    sl_diag *d) {
  char path[256];
  snprintf(path, sizeof path, "%s.ini", name);
  FILE *f = fopen(path, "w");
  if (!f) return sl_diag_set(d, SL_EFAILED, "cannot write %s", path);
  fputs(text, f);
  fclose(f);
  scene_request q = {.configs = ".", .scene = name, .sets = sets, .out = out, .restart = restart};
  return scene_run(&q, NULL, d);
}

/* ---- ktgf_shear ------------------------------------------------------------------ */

static const kt_point ktgf = {0.3, 2500.0, 5e-4, 0.9, 0.63};
static const double gdot = 100.0;

static double uniform_theta(const char *file, double t, double *spread) {
  int n = 0;
  double *th = node_field(file, "theta", t, &n), lo = INFINITY, hi = -INFINITY;
  for (int k = 0; th && k < n; ++k) lo = fmin(lo, th[k]), hi = fmax(hi, th[k]);
  free(th);
  *spread = (hi - lo) / hi;
  return hi;
}

static void ktgf_shear(void) {
  double mu0 = mu0_lun(&ktgf), gam0 = gamma0_lun(&ktgf), rho_phi = ktgf.rho_s * ktgf.phi;
  double A = mu0 * gdot * gdot / (3.0 * rho_phi), B = gam0 / (3.0 * rho_phi), se = sqrt(A / B);
  double theta_eq = mu0 * gdot * gdot / gam0;
  /* the transient at t = 0.05 (about 1.4 relaxation times), backward Euler at three steps
   * (from theta_0 = 1e-6 the first steps are stiff: orders settle to 1 from dt = 2.5e-4 down) */
  const double t1 = 0.05;
  double exact = pow(se * tanh(sqrt(A * B) * t1 + atanh(sqrt(1e-6) / se)), 2), err[3];
  const char *dts[3] = {"time.dt=2.5e-4", "time.dt=1.25e-4", "time.dt=6.25e-5"};
  for (int k = 0; k < 3; ++k) {
    const char *sets[] = {dts[k], "time.end=0.05", "output.every=0.05", "two_fluid.steady_tolerance=0", NULL};
    if (run_ok("ktgf_shear", NULL, NULL, sets, "ktgf_t.h5")) return;
    double spread, th = uniform_theta("ktgf_t.h5", t1, &spread);
    err[k] = fabs(th - exact) / exact;
    CHECK_MSG(spread < 1e-10, "theta uniform across the gap: spread %.2e", spread);
    printf("ktgf_shear: %s, theta(0.05) = %.8e, exact %.8e, relative error %.3e\n", dts[k], th, exact, err[k]);
  }
  for (int k = 1; k < 3; ++k) {
    double order = log2(err[k - 1] / err[k]);
    CHECK_MSG(fabs(order - 1.0) < 0.05, "first order in dt: observed %.3f", order);
  }
  CHECK_MSG(err[2] < 4e-4, "dt = 6.25e-5: relative error %.3e", err[2]);
  /* the equilibrium */
  if (run_ok("ktgf_shear", NULL, NULL, NULL, "ktgf.h5")) return;
  double spread, th = uniform_theta("ktgf.h5", INFINITY, &spread);
  printf("ktgf_shear: steady theta %.12e, algebraic equilibrium %.12e\n", th, theta_eq);
  CHECK_CLOSE(th, theta_eq, 1e-8);
  CHECK(spread < 1e-10);
  /* the solids pressure written beside: Lun et al.'s (1984) rho_s phi theta (1 + 2 (1 + e) phi g0) at the
   * equilibrium theta, in every cell */
  int n_ps = 0;
  double *ps = node_field("ktgf.h5", "solids_pressure", INFINITY, &n_ps), worst = 0.0;
  double ps_eq = rho_phi * theta_eq * (1.0 + 2.0 * (1.0 + ktgf.e) * ktgf.phi * g0_lun_savage(&ktgf));
  for (int k = 0; ps && k < n_ps; ++k) worst = fmax(worst, fabs(ps[k] - ps_eq) / ps_eq);
  printf("ktgf_shear: solids pressure %.10g Pa in %d cells (Lun et al. %.10g), largest relative difference %.2e\n",
         ps && n_ps ? ps[0] : NAN, n_ps, ps_eq, worst);
  CHECK_MSG(ps && n_ps == 20 && worst < 1e-8, "solids pressure: %d cells, worst relative difference %.2e", n_ps, worst);
  free(ps);
  /* the solids stress mu_s gdot on the walls, the fluid's (1 - phi) mu_f gdot */
  double tau_s = mu0 * sqrt(theta_eq) * gdot, tau_f = 0.7 * 1.002e-3 * gdot;
  CHECK_CLOSE(scalar("ktgf.h5", "wall_shear_stress_solid_left", INFINITY), tau_s, 1e-7);
  CHECK_CLOSE(scalar("ktgf.h5", "wall_shear_stress_solid_right", INFINITY), -tau_s, 1e-7);
  CHECK_CLOSE(scalar("ktgf.h5", "wall_shear_stress_fluid_left", INFINITY), tau_f, 1e-9);
  /* with the interphase sink 3 K theta */
  const char *with_sink[] = {"two_fluid.interphase_dissipation=true", NULL};
  if (run_ok("ktgf_shear", NULL, NULL, with_sink, "ktgf_k.h5")) return;
  double K = k_wen_yu_zero_slip(ktgf.phi, 1.002e-3, ktgf.d);
  double s = (-3.0 * K + sqrt(9.0 * K * K + 4.0 * gam0 * mu0 * gdot * gdot)) / (2.0 * gam0);
  th = uniform_theta("ktgf_k.h5", INFINITY, &spread);
  printf("ktgf_shear with 3 K theta (K = %.1f): steady theta %.12e, balance %.12e\n", K, th, s * s);
  CHECK_CLOSE(th, s * s, 1e-8);
  /* the algebraic option: the balance after one step */
  const char *alg[] = {"two_fluid.granular_temperature=algebraic", "time.end=1e-3", NULL};
  if (run_ok("ktgf_shear", NULL, NULL, alg, "ktgf_a.h5")) return;
  th = uniform_theta("ktgf_a.h5", INFINITY, &spread);
  CHECK_CLOSE(th, theta_eq, 1e-10);
  CHECK(spread < 1e-10);
}

/* ---- annular Couette ------------------------------------------------------------- */

static const char couette_text[] =
    "[scene]\nmodel = two_fluid\ngeometry = line\n"
    "[mesh]\ngenerator = interval\nx = 0.05, 0.06\ncells = 7\ngrading_x = geometric:1.3\n"
    "[fluid]\ndensity = 1000\nviscosity = 1e-3\n"
    "[solid]\ndensity = 1000\ndiameter = 1e-3\nviscosity = 0.05\n"
    "[closure.drag]\nmodel = wen_yu\n"
    "[two_fluid]\nmotion = shear\ncross_section = annular\ntolerance = 1e-13\n"
    "[initial]\nphi = 0.3\n"
    "[boundary.left]\ntype = wall\nvelocity = 0\n"
    "[boundary.right]\ntype = wall\nvelocity = 0.3\n"
    "[time]\nend = 1e4\ndt = 1e3\n";

static void annular_couette(void) {
  sl_diag d = {{0}};
  int rc = run_text("couette_annulus", couette_text, NULL, "couette.h5", NULL, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  const double ri = 0.05, ro = 0.06, U = 0.3, A = U * ro / (ro * ro - ri * ri), B = -A * ri * ri;
  sl_output_mesh m;
  if (sl_output_read_mesh("couette.h5", &m, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  int n = 0, n2 = 0;
  double *uf = node_field("couette.h5", "velocity_fluid", INFINITY, &n);
  double *us = node_field("couette.h5", "velocity_solid", INFINITY, &n2);
  double worst = 0.0;
  for (int k = 0; uf && us && k < n; ++k) {
    double r = m.coords[3 * k], u = A * r + B / r;
    worst = fmax(worst, fmax(fabs(uf[k] - u), fabs(us[k] - u)) / U);
  }
  printf("annular Couette (7 graded cells): largest nodal error %.2e of the wall speed\n", worst);
  CHECK(worst < 1e-12);
  free(uf), free(us);
  sl_output_mesh_free(&m);
  /* tau = mu r d(u/r)/dr = -2 mu B / r^2; the stress on the inner wall is +tau(ri), on the outer -tau(ro) */
  double muf = 0.7e-3, mus = 0.05;
  CHECK_CLOSE(scalar("couette.h5", "wall_shear_stress_fluid_left", INFINITY), -2.0 * muf * B / (ri * ri), 1e-10);
  CHECK_CLOSE(scalar("couette.h5", "wall_shear_stress_solid_left", INFINITY), -2.0 * mus * B / (ri * ri), 1e-10);
  CHECK_CLOSE(scalar("couette.h5", "wall_shear_stress_fluid_right", INFINITY), 2.0 * muf * B / (ro * ro), 1e-10);
  CHECK_CLOSE(scalar("couette.h5", "torque_left", INFINITY), -4.0 * PI * (muf + mus) * B, 1e-10);
  CHECK_CLOSE(scalar("couette.h5", "torque_right", INFINITY), 4.0 * PI * (muf + mus) * B, 1e-10);
}

/* The solids' share of a suspension viscosity: Krieger & Dougherty (1959)
 * mu_m = mu_f (1 - phi/phi_m)^(-[eta] phi_m), phi_m = 0.68, [eta] = 2.5:
 * the fluid carries (1 - phi) mu_f, the solids phase mu_m - (1 - phi) mu_f. */
static const char couette_kd_text[] =
    "[scene]\nmodel = two_fluid\ngeometry = line\n"
    "[mesh]\ngenerator = interval\nx = 0.05, 0.06\ncells = 5\n"
    "[fluid]\ndensity = 1000\nviscosity = 1e-3\n"
    "[solid]\ndensity = 1000\ndiameter = 1e-3\n"
    "[closure.drag]\nmodel = wen_yu\n"
    "[closure.viscosity]\nmodel = krieger_dougherty\n"
    "[two_fluid]\nmotion = shear\ncross_section = annular\ntolerance = 1e-13\n"
    "[initial]\nphi = 0.45\n"
    "[boundary.left]\ntype = wall\nvelocity = 0\n"
    "[boundary.right]\ntype = wall\nvelocity = 0.3\n"
    "[time]\nend = 1e4\ndt = 1e3\n";

static void couette_viscosity_closure(void) {
  sl_diag d = {{0}};
  int rc = run_text("couette_kd", couette_kd_text, NULL, "couette_kd.h5", NULL, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  const double ri = 0.05, ro = 0.06, U = 0.3, A = U * ro / (ro * ro - ri * ri), B = -A * ri * ri, phi = 0.45;
  double mum = 1e-3 * pow(1.0 - phi / 0.68, -2.5 * 0.68), mus = mum - (1.0 - phi) * 1e-3;
  double ts = scalar("couette_kd.h5", "wall_shear_stress_solid_left", INFINITY);
  double tf = scalar("couette_kd.h5", "wall_shear_stress_fluid_left", INFINITY);
  printf(
      "annular Couette, Krieger-Dougherty at phi = 0.45: mu_m = %.6g Pa s, solids phase mu_s = %.6g Pa s; wall "
      "stresses fluid %.6g, solids %.6g Pa\n",
      mum, mus, tf, ts);
  CHECK_CLOSE(ts, -2.0 * mus * B / (ri * ri), 1e-10);
  CHECK_CLOSE(tf, -2.0 * (1.0 - phi) * 1e-3 * B / (ri * ri), 1e-10);
  CHECK_CLOSE(tf + ts, -2.0 * mum * B / (ri * ri), 1e-10);
}

/* ---- shear_cell: Bagnold's regimes ------------------------------------------------ */

typedef struct cell_result {
  double tau_s, bagnold, torque_in, torque_out;
} cell_result;

static int shear_cell_run(const char *speed, const char *dt, const char *end, cell_result *r) {
  const char *sets[] = {speed, dt, end, NULL};
  if (run_ok("shear_cell", NULL, NULL, sets, "cell.h5")) return -1;
  r->tau_s = scalar("cell.h5", "wall_shear_stress_solid_left", INFINITY);
  r->bagnold = scalar("cell.h5", "bagnold_number_left", INFINITY);
  r->torque_in = scalar("cell.h5", "torque_left", INFINITY);
  r->torque_out = scalar("cell.h5", "torque_right", INFINITY);
  return 0;
}

static void shear_cell(void) {
  const char *speeds[4] = {"boundary.right.velocity=0.01", "boundary.right.velocity=0.02", "boundary.right.velocity=2",
                           "boundary.right.velocity=4"};
  const char *dts[4] = {"time.dt=2", "time.dt=1", "time.dt=0.01", "time.dt=0.005"};
  const char *ends[4] = {"time.end=4000", "time.end=2000", "time.end=40", "time.end=20"};
  cell_result r[4];
  for (int k = 0; k < 4; ++k) {
    if (shear_cell_run(speeds[k], dts[k], ends[k], &r[k])) return;
    printf("shear_cell %s: solids wall stress %.5g Pa, Bagnold number %.4g, torques %.6g, %.6g N m/m\n", speeds[k],
           r[k].tau_s, r[k].bagnold, r[k].torque_in, r[k].torque_out);
    CHECK_MSG(fabs(r[k].torque_in + r[k].torque_out) < 1e-7 * fabs(r[k].torque_in), "torque balance: %.6e %.6e",
              r[k].torque_in, r[k].torque_out);
  }
  double slow = log(r[1].tau_s / r[0].tau_s) / log(2.0), fast = log(r[3].tau_s / r[2].tau_s) / log(2.0);
  printf("shear_cell: solids wall stress ~ U^%.3f at N = %.3g-%.3g, ~ U^%.3f at N = %.4g-%.4g\n", slow, r[0].bagnold,
         r[1].bagnold, fast, r[2].bagnold, r[3].bagnold);
  CHECK(r[0].bagnold < 40.0 && r[1].bagnold < 40.0);
  CHECK(r[2].bagnold > 450.0 && r[3].bagnold > 450.0);
  CHECK_MSG(fabs(slow - 1.0) < 0.02, "macro-viscous: exponent %.4f", slow);
  CHECK_MSG(fabs(fast - 2.0) < 0.06, "grain-inertia: exponent %.4f", fast);
}

/* ---- Johnson & Jackson walls, planar ---------------------------------------------- */

static const char jj_text[] =
    "[scene]\nmodel = two_fluid\ngeometry = line\n"
    "[mesh]\ngenerator = interval\nx = 0, 0.01\ncells = 16\n"
    "[fluid]\ndensity = 998.2\nviscosity = 1.002e-3\n"
    "[solid]\ndensity = 2500\ndiameter = 5e-4\n"
    "[closure.drag]\nmodel = wen_yu\n"
    "[closure.granular]\nmodel = lun\n"
    "[closure.wall_stress]\nmodel = johnson_jackson\nspecularity = 0.1\ne_w = 0.9\n"
    "[two_fluid]\nmotion = shear\ntolerance = 1e-10\nsteady_tolerance = 1e-9\niterations = 100\n"
    "[initial]\nphi = 0.3\ntheta = 1e-4\n"
    "[boundary.left]\ntype = wall\nvelocity = 0\nsolids = wall_stress\n"
    "[boundary.right]\ntype = wall\nvelocity = 1\nsolids = wall_stress\n"
    "[time]\nend = 5000\ndt = 0.5\n";

static void johnson_jackson_walls(void) {
  sl_diag d = {{0}};
  int rc = run_text("jj_couette", jj_text, NULL, "jj.h5", NULL, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  double sl = scalar("jj.h5", "wall_slip_left", INFINITY), sr = scalar("jj.h5", "wall_slip_right", INFINITY);
  double fl = scalar("jj.h5", "wall_shear_stress_fluid_left", INFINITY);
  double fr = scalar("jj.h5", "wall_shear_stress_fluid_right", INFINITY);
  double tl = scalar("jj.h5", "wall_shear_stress_solid_left", INFINITY);
  double tr = scalar("jj.h5", "wall_shear_stress_solid_right", INFINITY);
  printf("Johnson-Jackson walls: solids slip %.6g, %.6g m/s; stresses fluid %.6g, %.6g, solids %.6g, %.6g Pa\n", sl, sr,
         fl, fr, tl, tr);
  CHECK(sl > 0.0 && sl < 1.0);
  CHECK_CLOSE(sr, -sl, 1e-7);
  CHECK_CLOSE(tr, -tl, 1e-7);
  CHECK_MSG(fabs(fl + tl + fr + tr) < 1e-7 * fabs(fl + tl), "force balance: %.3e", fl + tl + fr + tr);
  int n = 0;
  double *th = node_field("jj.h5", "theta", INFINITY, &n);
  for (int k = 0; th && k < n; ++k) CHECK(th[k] > 0.0 && isfinite(th[k]) && fabs(th[k] - th[n - 1 - k]) < 1e-7 * th[k]);
  free(th);
}

/* ---- restart, bad input ----------------------------------------------------------- */

static void restart(void) {
  const char *full[] = {"time.end=6", "time.dt=0.5", "output.every=3", "two_fluid.steady_tolerance=0", NULL};
  const char *half[] = {"time.end=3", "time.dt=0.5", "output.every=3", "two_fluid.steady_tolerance=0", NULL};
  if (run_ok("shear_cell", NULL, NULL, full, "cell_full.h5") || run_ok("shear_cell", NULL, NULL, half, "cell_half.h5"))
    return;
  sl_diag d = {{0}};
  scene_request q = {
      .configs = configs, .scene = "shear_cell", .sets = full, .out = "cell_cont.h5", .restart = "cell_half.h5"};
  int rc = scene_run(&q, NULL, &d);
  CHECK_MSG(rc == 0, "restart: %s", d.msg);
  const char *fields[3] = {"velocity_fluid", "velocity_solid", "theta"};
  for (int f = 0; f < 3 && rc == 0; ++f) {
    int n = 0, m = 0;
    double *a = node_field("cell_full.h5", fields[f], 6.0, &n), *b = node_field("cell_cont.h5", fields[f], 6.0, &m);
    CHECK(a && b && n == m && memcmp(a, b, (size_t)n * sizeof *a) == 0);
    free(a), free(b);
  }
}

static void bad_input(void) {
  sl_diag d = {{0}};
  const char *sets[] = {"two_fluid.cfl=0.5", NULL};
  int rc = run_scene("shear_cell", NULL, NULL, sets, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[two_fluid] cfl") && strstr(d.msg, "motion = column"), "message: %s", d.msg);
  const char *sets2[] = {"boundary.left.solids=wall_stres", NULL};
  rc = run_scene("shear_cell", NULL, NULL, sets2, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[boundary.left] solids = wall_stres") && strstr(d.msg, "did you mean 'wall_stress'"),
            "message: %s", d.msg);
  const char *sets3[] = {"initial.phi=0.7", NULL};
  rc = run_scene("shear_cell", NULL, NULL, sets3, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[initial] phi = 0.7") && strstr(d.msg, "phi_max = 0.63"), "message: %s", d.msg);
  const char *sets4[] = {"two_fluid.cross_section=annular", NULL};
  rc = run_scene("fluidized_bed", NULL, NULL, sets4, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[two_fluid] cross_section") && strstr(d.msg, "motion = shear"), "message: %s", d.msg);
  rc = run_scene("ktgf_shear", "closure.granular", "[closure.granular]\nmodel = schaeffer\n", NULL, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  printf("bad input: %s\n", d.msg);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  ktgf_shear();
  annular_couette();
  couette_viscosity_closure();
  shear_cell();
  johnson_jackson_walls();
  restart();
  bad_input();
  return sl_test_summary();
}
