/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The 2-D mixture model keeps a suspension at rest where nothing moves it,
 * and settles like the 1-D column where only settling does.
 *
 *  - Hydrostatic suspensions (no settling closure): uniform phi, a stable
 *    linear stratification and a step, in the upright box 0.1 m x 1 m (4 x
 *    20 cells, 4 x 8 in the sanitizer build: quadrilaterals, "/" triangles, quadrilaterals and triangles
 *    graded towards the walls, lid and floor; dt = 10 s, where the internal
 *    waves' N dt reaches 9) and in the Boycott vessel (configs/boycott.ini,
 *    45-degree walls, its wall grading, 12 x 16 cells (6 x 8), quadrilaterals and "/"
 *    triangles; dt = 0.01, N dt up to 3): max |j| at every tenth of 100 steps below 1e-12
 *    of the settling speed scale (2.198 mm/s in the box, u_t = 1 in the
 *    vessel), every step solved ([solver] skip_known = false); as a run
 *    goes, all 100 solves are skipped (at rest under no load) and j = 0.
 *    Before the buoyancy was split and made implicit in the step's velocity
 *    the box's step grew to 4e-4 m/s and the vessel's triangles carried
 *    1e-3 with the linear stratification.
 *  - The upright box settling (tests/scenes/mixture_box.h: Vesilind's law,
 *    phi0 = 0.1, exact Kynch solution with j = 0) on 4 x 50, 100, 200 cells
 *    (25, 50) against the 1-D column of as many at t = 570 s: the L1
 *    error of phi within 20 % of the column's on every mesh and falling at
 *    its rate (within 0.1), max |j| below 1e-12 of the settling speed, every
 *    step solved; the run that skips the known solves ends at the same L1
 *    (within 1e-9). The density contrasts 0.01 (1006 in 996 kg m^-3) and 1
 *    (2000) both run to the end so, the latter also with convection and
 *    adaptive BDF2 steps.
 *  - Every step's flow solved, the box at rest assembles no matrix and
 *    factorises nothing (its residual is at round-off); a box whose phi
 *    varies across it moves and solves every step. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mixture_box.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];
static int quick; /* SLUICE_SKIP_LONG (the sanitizer build): smaller meshes, the same checks */

/* The largest |j| of a run over all its outputs. */
static double worst_speed(const char *out) {
  double worst = NAN;
  box_speed(out, INFINITY, &worst);
  return worst;
}

static const char *const strata[3][2] = {
    {"uniform", "0.1"}, {"linear", "0.05 + 0.1 * (1 - y)"}, {"step", "y < 0.5 ? 0.1 : 0"}};

static void hydrostatic_box(void) {
  static const char *const meshes[4][2] = {
      {"quadrilaterals", ""},
      {"triangles", "cell_type = tri\ndiagonal = right"},
      {"graded quadrilaterals", "grading_x = symmetric:2\ngrading_y = symmetric:3"},
      {"graded triangles", "cell_type = tri\ndiagonal = right\ngrading_x = symmetric:2\ngrading_y = symmetric:3"}};
  for (int m = 0; m < 4; ++m)
    for (int k = 0; k < 3; ++k) {
      /* every step solved: the discretisation itself; then as a run does it, skipping what is known */
      box_scene s = {.n = quick ? 8 : 20,
                     .mesh_extra = meshes[m][1],
                     .rho_s = 1006.0,
                     .phi = strata[k][1],
                     .settling = 0,
                     .end = 1000.0,
                     .dt = 10.0,
                     .every = 100.0,
                     .solve_every_step = 1};
      sl_diag d = {{0}};
      sluice_summary res, skip;
      int rc = box_run(&s, "balance_box.h5", &res, &d);
      CHECK_MSG(rc == 0, "box, %s, %s: %s", meshes[m][0], strata[k][0], d.msg);
      if (rc) continue;
      double v = worst_speed("balance_box.h5");
      s.solve_every_step = 0;
      rc = box_run(&s, "balance_box_skip.h5", &skip, &d);
      CHECK_MSG(rc == 0, "box, %s, %s: %s", meshes[m][0], strata[k][0], d.msg);
      double vs = rc ? NAN : worst_speed("balance_box_skip.h5");
      printf(
          "  box at rest, %-21s %-7s: max |j| over 100 steps %.2e m/s (%.1e of the settling speed); %ld of 100 "
          "flow solves skipped where known: %.2e m/s\n",
          meshes[m][0], strata[k][0], v, v / box_ut, skip.solves_skipped, vs);
      CHECK_MSG(res.steps == 100 && res.solves_skipped == 0 && v <= 1e-12 * box_ut, "box, %s, %s: |j| = %.3g m/s",
                meshes[m][0], strata[k][0], v);
      CHECK_MSG(skip.solves_skipped == 100 && vs == 0.0, "box, %s, %s: %ld solves skipped, |j| = %.3g m/s",
                meshes[m][0], strata[k][0], skip.solves_skipped, vs);
    }
}

static void hydrostatic_boycott(void) {
  static const char *const meshes[2][2] = {{"quadrilaterals", NULL}, {"triangles", "mesh.cell_type=tri"}};
  for (int m = 0; m < 2; ++m)
    for (int k = 0; k < 3; ++k) {
      char phi[128];
      snprintf(phi, sizeof phi, "initial.phi=%s", strata[k][1]);
      /* quadrilaterals: the list ends at meshes[m][1] == NULL */
      const char *sets[] = {quick ? "mesh.cells=6,8" : "mesh.cells=12,16",
                            "time.scheme=bdf1",
                            "time.adaptive=false",
                            "time.dt=0.01",
                            "time.end=1",
                            "output.every=0.1",
                            phi,
                            meshes[m][1],
                            "mesh.diagonal=right",
                            NULL};
      scene_request q = {.configs = configs,
                         .scene = "boycott",
                         .replace_section = "closure.hindered_settling",
                         .replacement = "",
                         .sets = sets,
                         .out = "balance_boycott.h5",
                         .solve_every_step = 1};
      sl_diag d = {{0}};
      int rc = scene_run(&q, NULL, &d);
      CHECK_MSG(rc == 0, "Boycott vessel, %s, %s: %s", meshes[m][0], strata[k][0], d.msg);
      if (rc) continue;
      double v = worst_speed("balance_boycott.h5");
      printf("  Boycott vessel at rest, %-14s %-7s: max |j| over 100 steps %.2e (u_t = 1)\n", meshes[m][0],
             strata[k][0], v);
      CHECK_MSG(v <= 1e-12, "Boycott vessel, %s, %s: |j| = %.3g", meshes[m][0], strata[k][0], v);
    }
}

/* One settling run; its L1 at t = 570 s and max |j| over the run, NAN on failure. */
static double settle(box_scene s, const char *out, const kynch *k, double *speed) {
  sl_diag d = {{0}};
  int rc = box_run(&s, out, NULL, &d);
  CHECK_MSG(rc == 0, "%s: %s", out, d.msg);
  *speed = rc ? NAN : worst_speed(out);
  return rc ? NAN : box_l1(out, 570.0, k);
}

static void settling_box(void) {
  kynch k;
  if (box_exact(&k, 0) != 0) {
    CHECK_MSG(0, "the box's Kynch solution");
    return;
  }
  double e2[3], e1[3], v, v1;
  int nj = quick ? 2 : 3, n0 = quick ? 25 : 50;
  for (int j = 0; j < nj; ++j) {
    int n = n0 << j;
    box_scene s = {
        .n = n, .rho_s = 1006.0, .settling = 1, .end = 570.0, .dt = 10.0, .every = 190.0, .solve_every_step = 1};
    e2[j] = settle(s, "balance_settle_2d.h5", &k, &v);
    CHECK_MSG(v <= 1e-12 * box_ut, "4 x %d: |j| = %.3g m/s", n, v);
    s.solve_every_step = 0; /* as a run goes: at rest under no load, no solve */
    double e_skip = settle(s, "balance_settle_2d.h5", &k, &v1);
    s.line = 1;
    e1[j] = settle(s, "balance_settle_1d.h5", &k, &v1);
    printf(
        "  settling box 4 x %d: L1 %.4e (%.4e without the known solves), the column of %d %.4e (ratio %.4f), "
        "max |j| over the run %.2e m/s\n",
        n, e2[j], e_skip, n, e1[j], e2[j] / e1[j], v);
    CHECK_MSG(fabs(e_skip - e2[j]) <= 1e-9 * e2[j], "4 x %d: L1 %.10g with every solve, %.10g without", n, e2[j],
              e_skip);
    CHECK_MSG(fabs(e2[j] / e1[j] - 1.0) <= 0.2, "4 x %d: L1 %.4g, the column's %.4g", n, e2[j], e1[j]);
  }
  double span = (nj - 1) * log(2.0), r2 = log(e2[0] / e2[nj - 1]) / span, r1 = log(e1[0] / e1[nj - 1]) / span;
  printf("  settling box: L1 rate %.3f over %d .. %d vertical cells, the column's %.3f\n", r2, n0, n0 << (nj - 1), r1);
  CHECK_MSG(fabs(r2 - r1) <= 0.1 && r1 > 0.6, "L1 rates: box %.3g, column %.3g", r2, r1);
  /* density contrast 1: Stokes flow with fixed steps, and convection with adaptive BDF2 */
  for (int c = 0; c < 2; ++c) {
    box_scene s = {.n = n0,
                   .rho_s = 2000.0,
                   .settling = 1,
                   .end = 570.0,
                   .dt = 10.0,
                   .every = 190.0,
                   .convection = c,
                   .solve_every_step = 1};
    sl_diag d = {{0}};
    sluice_summary res;
    int rc = box_run(&s, "balance_contrast1.h5", &res, &d);
    CHECK_MSG(rc == 0, "density contrast 1%s: %s", c ? " with convection" : "", d.msg);
    if (rc) continue;
    double l1 = box_l1("balance_contrast1.h5", 570.0, &k);
    v = worst_speed("balance_contrast1.h5");
    printf("  density contrast 1%s: %ld steps (%ld rejected), L1 %.4e (the column's %.4e), max |j| %.2e m/s\n",
           c ? ", convection, adaptive BDF2" : ", Stokes flow", res.steps, res.rejected_steps, l1, e1[0], v);
    CHECK_MSG(res.t_reached >= 570.0 - 1e-9 && v <= 1e-12 * box_ut, "density contrast 1: |j| = %.3g m/s", v);
    CHECK_MSG(fabs(l1 / e1[0] - 1.0) <= 0.2, "density contrast 1: L1 %.4g, the column's %.4g", l1, e1[0]);
  }
}

/* A linear step whose residual at the predictor is at the round-off of its load's terms is not solved
 * (core/solve/newton.h load_scale; the monolithic step's): the box at rest with every step's flow solved assembles the load alone, never
 * a matrix, factorises nothing and stays at j = 0 exactly; a box whose phi varies across it (0.12 left of the
 * middle, 0.08 right) moves, and every one of its steps assembles its matrix and solves. */
static void roundoff_steps(void) {
  box_scene s = {.n = quick ? 8 : 20,
                 .rho_s = 1006.0,
                 .settling = 1,
                 .end = 100.0,
                 .dt = 10.0,
                 .every = 100.0,
                 .solve_every_step = 1,
                 .monolithic = 1};
  sl_diag d = {{0}};
  sluice_summary res;
  int rc = box_run(&s, "balance_roundoff.h5", &res, &d);
  CHECK_MSG(rc == 0, "box at rest: %s", d.msg);
  double v = rc ? NAN : worst_speed("balance_roundoff.h5");
  if (!rc)
    printf("  settling box, every step's flow: %ld steps, %ld matrix and %ld load assemblies, max |j| %.2e m/s; %s\n",
           res.steps, res.matrix_assemblies, res.residual_assemblies, v, res.linear_summary);
  CHECK_MSG(!rc && res.steps == 10 && res.matrix_assemblies == 0 && res.residual_assemblies == 10 && v == 0.0,
            "box at rest: %ld matrix assemblies, |j| %.3g", res.matrix_assemblies, v);
  if (!rc) CHECK_CONTAINS(res.linear_summary, " 0 numeric");
  s.phi = "x < 0.05 ? 0.12 : 0.08";
  rc = box_run(&s, "balance_moving.h5", &res, &d);
  CHECK_MSG(rc == 0, "moving box: %s", d.msg);
  v = rc ? NAN : worst_speed("balance_moving.h5");
  if (!rc)
    printf("  box with phi varying across it: %ld steps, %ld matrix assemblies, max |j| %.2e m/s; %s\n", res.steps,
           res.matrix_assemblies, v, res.linear_summary);
  CHECK_MSG(!rc && res.matrix_assemblies == res.steps && v > 1e-3 * box_ut,
            "moving box: %ld matrix assemblies in %ld "
            "steps, |j| %.3g",
            res.matrix_assemblies, res.steps, v);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  quick = getenv("SLUICE_SKIP_LONG") != NULL;
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  hydrostatic_box();
  hydrostatic_boycott();
  settling_box();
  roundoff_steps();
  return sl_test_summary();
}
