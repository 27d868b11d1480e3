/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The 2-D two-fluid model (staggered grid, planar and axisymmetric), run
 * through the same entry point as `sluice run` and read back from its
 * output files.
 *
 * One column: a 2-D grid one cell wide reproduces the 1-D column of the
 * fluidisation step of Pringle (2001, section 4.6.1) (the same face scheme) cell by cell, to
 * within what the 2-D model adds (fluid viscous stress, the inertia of
 * both phases written separately) during the transient, and to 1e-6 at
 * the end.
 * fluidized_bed_2d: a bed under a uniform inflow ends homogeneous at the
 * Richardson-Zaki porosity U = u_t (1 - phi)^4.65 (Richardson & Zaki
 * 1954) to 1e-3, planar and axisymmetric, every column alike.
 * settled_bed_2d: a suspension settling in a closed box comes to rest with
 * every column equal to the 1-D column (itself checked against the closed
 * form), the columns alike while it settles at steps of 2 s.
 * Clear fluid through a channel and a pipe with the exact inlet profile:
 * the pressure gradient of plane Poiseuille flow, 12 mu U / H^2, and of
 * Hagen-Poiseuille flow, 8 mu U / R^2; the error falls at second order.
 * A bed blown out of the box: bounded and conserving at every output, no
 * solids left. A run continued from its checkpoint ends where the
 * uninterrupted one does to round-off (not bit for bit: the continued run's
 * first LU chooses its pivots afresh, the other reuses earlier ones). Bad
 * input exits 2 naming the problem. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096], local[4096];
static int quick; /* SLUICE_SKIP_LONG (the sanitizer build): a shorter Pringle (2001) step, the planar bed only, no
                      blow-out */

SCENE_RUNNERS()

/* ---- one column against the 1-D model ------------------------------------------ */

static void one_column(void) {
  const char *end = quick ? "time.end=10" : "time.end=60";
  const char *sets1[] = {end, "time.dt=0.01", "output.every=1", NULL};
  const char *sets2[] = {end,
                         "time.dt=0.01",
                         "output.every=1",
                         "mesh.x=0,0.01",
                         "mesh.cells=1,100",
                         "initial.porosity=y < 0.5 ? 0.65 : 1",
                         "boundary.bottom.velocity=t <= 0 ? 0.0077783 : 0.0115101",
                         "two_fluid.steady_tolerance=0",
                         NULL};
  if (run_ok("fluidization_step", NULL, NULL, sets1, "tf2_col1.h5") ||
      run_ok("fluidized_bed_2d", "closure.drag", "[closure.drag]\nmodel = pringle\n", sets2, "tf2_col2.h5"))
    return;
  double worst = 0.0, last = 0.0, t_end = quick ? 10.0 : 60.0;
  for (int s = 1; s <= (int)t_end; ++s) {
    int n1 = 0, n2 = 0;
    double *a = field_at("tf2_col1.h5", "phi", s, &n1, NULL), *b = field_at("tf2_col2.h5", "phi", s, &n2, NULL);
    if (!a || !b || n1 != n2) {
      CHECK_MSG(0, "one column: %d and %d cells", n1, n2);
      free(a), free(b);
      return;
    }
    last = 0.0;
    for (int i = 0; i < n1; ++i) last = fmax(last, fabs(a[i] - b[i]));
    worst = fmax(worst, last);
    free(a), free(b);
  }
  printf(
      "  one column (1 x 100) against the 1-D column, Pringle (2001) step to t = %g s: "
      "max |dphi| %.2e over the outputs, "
      "%.2e at the end\n",
      t_end, worst, last);
  CHECK_MSG(worst <= 5e-4, "one column: phi differs from the 1-D column by %.3g", worst);
  if (!quick) CHECK_MSG(last <= 1e-6, "one column: %.3g apart at the end", last);
  CHECK_MSG(fabs(scalar("tf2_col2.h5", "solids_conservation_error", t_end)) < 1e-12, "one column: not conserved");
}

/* ---- fluidized_bed_2d --------------------------------------------------------------- */

static void fluidized_bed(void) {
  /* Richardson-Zaki with u_t from Stokes' law: u_t = drho g d^2 / (18 mu) */
  const double ut = (2600.0 - 998.2) * 9.81 * 3e-4 * 3e-4 / (18.0 * 1.002e-3), U = 0.010;
  const double phi_eq = 1.0 - pow(U / ut, 1.0 / 4.65);
  const char *axi[] = {"scene.geometry=axisymmetric", "boundary.left.type=axis", NULL};
  for (int k = 0; k < (quick ? 1 : 2); ++k) { /* the sanitizer build: planar only */
    const char *out = "tf2_bed.h5";
    if (run_ok("fluidized_bed_2d", NULL, NULL, k ? axi : NULL, out)) continue;
    int n = 0;
    double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
    if (!phi) continue;
    /* 5 x 50 cells, mesh order = grid order for the rectangle generator; the bed is the rows whose cells all
       hold solids, less the top one (cut by the bed's surface) */
    const int nx = 5, ny = n / nx;
    int top = -1;
    for (int j = 0; j < ny; ++j)
      if (phi[j * nx] > 1e-9) top = j;
    double worst = 0.0, lateral = 0.0;
    for (int j = 0; j < top; ++j)
      for (int i = 0; i < nx; ++i) {
        worst = fmax(worst, fabs(phi[j * nx + i] - phi_eq));
        lateral = fmax(lateral, fabs(phi[j * nx + i] - phi[j * nx]));
      }
    printf(
        "  fluidized_bed_2d (%s, 5 x 50): steady at t = %.1f s, porosity %.5f (Richardson-Zaki %.5f), max "
        "|dphi| %.1e over %d rows, columns within %.1e\n",
        k ? "axisymmetric" : "planar", tf, 1.0 - phi[0], 1.0 - phi_eq, worst, top, lateral);
    CHECK_MSG(top >= 10, "a bed of %d rows", top);
    CHECK_MSG(worst <= 1e-3, "porosity off Richardson-Zaki by %.3g", worst);
    CHECK_MSG(lateral <= 1e-5, "the columns differ by %.3g", lateral);
    CHECK_MSG(tf < 599.0, "not steady by the end");
    CHECK_MSG(fabs(scalar(out, "solids_conservation_error", tf)) < 1e-12, "solids not conserved");
    free(phi);
  }
}

/* ---- settled_bed_2d ------------------------------------------------------------------ */

/* The closed box settles to rest; every column then carries its weight as the 1-D column does on the same rows
 * (which test_two_fluid_scenes.c checks against the closed form), at the same time. During the settling the
 * columns stay alike: the smeared top of the suspension, stably stratified, does not overturn at dt = 2 s. */
static void settled_bed(void) {
  const char *sets1[] = {"mesh.cells=50", NULL};
  if (run_ok("settled_bed", NULL, NULL, sets1, "tf2_rest1.h5") ||
      run_ok("settled_bed_2d", NULL, NULL, NULL, "tf2_rest2.h5"))
    return;
  int n1 = 0, n2 = 0;
  double t1 = 0.0, t2 = 0.0, *a = field_at("tf2_rest1.h5", "phi", INFINITY, &n1, &t1);
  double *b = field_at("tf2_rest2.h5", "phi", INFINITY, &n2, &t2);
  double worst = 0.0, lateral = 0.0, flow = 0.0;
  if (a && b && n2 == 4 * n1) {
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < 4; ++i) worst = fmax(worst, fabs(b[4 * j + i] - a[j]));
    /* the columns during the settling (t = 500 s: the sediment growing, the top still falling) */
    int n = 0, nu = 0;
    double *p = field_at("tf2_rest2.h5", "phi", 500.0, &n, NULL),
           *u = field_at("tf2_rest2.h5", "velocity_fluid", 500.0, &nu, NULL);
    for (int j = 0; p && u && j < n1; ++j)
      for (int i = 1; i < 4; ++i) {
        lateral = fmax(lateral, fabs(p[4 * j + i] - p[4 * j + i - 1]));
        flow = fmax(flow, fabs(u[3 * (4 * j + i)])); /* the horizontal fluid velocity */
      }
    free(p), free(u);
  } else {
    CHECK_MSG(0, "settled bed: %d and %d cells", n1, n2);
  }
  printf(
      "  settled_bed_2d (4 x 50, dt = 2 s): at rest at t = %.0f s (1-D: %.0f s), every column within %.1e of the "
      "1-D column; at t = 500 s the columns within %.1e, horizontal fluid velocity below %.1e m/s\n",
      t2, t1, worst, lateral, flow);
  CHECK_MSG(worst <= 1e-6, "settled bed: 2-D off the 1-D column by %.3g", worst);
  CHECK_MSG(lateral <= 1e-6 && flow <= 1e-6, "settled bed: the columns differ by %.3g, horizontal flow %.3g m/s",
            lateral, flow);
  CHECK_MSG(t2 < 19999.0 && fabs(t2 - t1) <= 0.01 * t1, "settled bed: at rest at %g s, 1-D %g s", t2, t1);
  CHECK_MSG(fabs(scalar("tf2_rest2.h5", "solids_conservation_error", t2)) < 1e-12, "settled bed: not conserved");
  free(a), free(b);
}

/* ---- clear fluid: Poiseuille ------------------------------------------------------- */

/* The pressure gradient between two cell centres 0.01 m apart mid-way along the duct. */
static double duct_gradient(const char *scene, int n_across, int n_along, int axial_y) {
  char cells[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d,%d", axial_y ? n_across : n_along, axial_y ? n_along : n_across);
  const char *sets[] = {cells, NULL};
  const char *out = "tf2_duct.h5";
  sl_diag d = {{0}};
  scene_request q = {.configs = local, .scene = scene, .sets = sets, .out = out};
  if (scene_run(&q, NULL, &d)) {
    CHECK_MSG(0, "%s: %s", scene, d.msg);
    return NAN;
  }
  int n = 0;
  double *p = field_at(out, "pressure", INFINITY, &n, NULL);
  if (!p) return NAN;
  const double L = 0.05, h = L / n_along;
  int a = (int)(0.02 / h + 0.5), b = (int)(0.03 / h + 0.5); /* cells whose centres are 0.01 m apart */
  /* the centreline column (pipe: next to the axis; channel: any row, the pressure is uniform across) */
  double pa = axial_y ? p[a * n_across] : p[a], pb = axial_y ? p[b * n_across] : p[b];
  free(p);
  return (pa - pb) / ((b - a) * h);
}

static void poiseuille(void) {
  const struct {
    const char *scene, *label;
    double exact;
    int axial_y;
  } ducts[] = {{"channel", "plane channel, 12 mu U / H^2", 12e-3 * 0.01 / 1e-4, 0},
               {"pipe", "pipe (axisymmetric), 8 mu U / R^2", 8e-3 * 0.01 / 2.5e-5, 1}};
  for (int k = 0; k < 2; ++k) {
    double e[3];
    for (int r = 0; r < 3; ++r) {
      int across = 8 << r, along = 20 << r;
      e[r] = fabs(duct_gradient(ducts[k].scene, across, along, ducts[k].axial_y) / ducts[k].exact - 1.0);
    }
    double o1 = log2(e[0] / e[1]), o2 = log2(e[1] / e[2]);
    printf(
        "  clear fluid, %s = %.3g Pa/m: relative error %.2e, %.2e, %.2e on 8, 16, 32 cells across (order %.2f, "
        "%.2f)\n",
        ducts[k].label, ducts[k].exact, e[0], e[1], e[2], o1, o2);
    CHECK_MSG(e[2] <= 2e-3, "%s: pressure gradient off by %.3g", ducts[k].scene, e[2]);
    CHECK_MSG(o1 > 1.8 && o2 > 1.8, "%s: order %.2f, %.2f (second expected)", ducts[k].scene, o1, o2);
  }
}

/* ---- stability, restart, bad input ------------------------------------------------------ */

/* The bed blown out of the box by a step to 0.5 m/s (terminal velocity 78 mm/s), at dt = 0.1 s: every output
 * bounded and conserving with the outflow counted, no solids left at the end. */
static void blow_out(void) {
  if (quick) return; /* 15 s of CPU in the normal build (the 1-D blow-outs run in the sanitizer build) */
  const char *sets[] = {"boundary.bottom.velocity=t <= 0 ? 0.01 : 0.5",
                        "time.dt=0.1",
                        "time.end=10",
                        "output.every=1",
                        "two_fluid.steady_tolerance=0",
                        NULL};
  const char *out = "tf2_blow.h5";
  sluice_summary res;
  sl_diag d = {{0}};
  scene_request q = {.configs = configs, .scene = "fluidized_bed_2d", .sets = sets, .out = out};
  int rc = scene_run(&q, &res, &d);
  CHECK_MSG(rc == 0, "blow-out: %s", d.msg);
  if (rc) return;
  int ns = 0, bad = 0;
  double *times = NULL, worst = 0.0;
  if (sl_output_read_times(out, &ns, &times, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  for (int s = 0; s < ns; ++s) {
    int n = 0, nu = 0;
    double *phi = field_at(out, "phi", times[s], &n, NULL), *us = field_at(out, "velocity_solid", times[s], &nu, NULL);
    for (int i = 0; phi && i < n; ++i) bad += !(phi[i] >= 0.0 && phi[i] <= 0.64);
    for (int i = 0; us && i < 3 * nu; ++i) bad += !isfinite(us[i]);
    worst = fmax(worst, fabs(scalar(out, "solids_conservation_error", times[s])));
    free(phi), free(us);
  }
  double left = scalar(out, "solids_inventory", times[ns - 1]);
  printf(
      "  blow-out (2-D, U 0.01 -> 0.5 m/s, dt = 0.1 s): conservation within %.1e, solids left %.1e m^2 of "
      "%.4f; %s\n",
      worst, left, 0.05 * 0.3 * 0.4, res.coupling_summary);
  CHECK_MSG(bad == 0, "blow-out: %d values outside [0, phi_max] or not finite", bad);
  CHECK_MSG(worst < 1e-12, "blow-out: conservation error %.3g", worst);
  CHECK_MSG(left < 1e-9 * 0.006, "blow-out: %.3g m^2 of solids left", left);
  free(times);
}

static void restart(void) {
  const char *full[] = {"time.end=2", "time.dt=0.1", "output.every=1", NULL};
  const char *half[] = {"time.end=1", "time.dt=0.1", "output.every=1", NULL};
  if (run_ok("fluidized_bed_2d", NULL, NULL, full, "tf2_full.h5") ||
      run_ok("fluidized_bed_2d", NULL, NULL, half, "tf2_half.h5"))
    return;
  sl_diag d = {{0}};
  scene_request q = {
      .configs = configs, .scene = "fluidized_bed_2d", .sets = full, .out = "tf2_cont.h5", .restart = "tf2_half.h5"};
  int rc = scene_run(&q, NULL, &d);
  CHECK_MSG(rc == 0, "restart: %s", d.msg);
  const char *fields[4] = {"phi", "velocity_solid", "velocity_fluid", "pressure"};
  for (int f = 0; f < 4 && rc == 0; ++f) {
    int n = 0, m = 0;
    double *a = field_at("tf2_full.h5", fields[f], 2.0, &n, NULL),
           *b = field_at("tf2_cont.h5", fields[f], 2.0, &m, NULL);
    int comp = f == 1 || f == 2 ? 3 : 1;
    double diff = 0.0, size = 0.0;
    for (int i = 0; a && b && n == m && i < n * comp; ++i)
      diff = fmax(diff, fabs(a[i] - b[i])), size = fmax(size, fabs(a[i]));
    printf("  restart: %s within %.1e of the uninterrupted run (largest %.3g)\n", fields[f], diff, size);
    CHECK_MSG(a && b && n == m && diff <= 1e-10 * size, "restart: %s differs by %.3g (largest %.3g)", fields[f], diff,
              size);
    free(a), free(b);
  }
}

static void bad_input(void) {
  struct {
    const char *sets[3];
    const char *expect;
  } cases[] = {
      {{"mesh.cell_type=tri", NULL}, "needs a 2-D mesh of quadrilaterals"},
      {{"scene.geometry=axisymmetric", NULL}, "the boundary at r = 0 of an axisymmetric scene is its axis"},
      {{"boundary.right.type=axis", NULL}, "only an axisymmetric scene has an axis"},
      {{"boundary.top.type=wall", NULL}, "an inlet needs an outlet"},
      {{"solver.ordering=colamdd", NULL}, "did you mean 'colamd'"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene("fluidized_bed_2d", NULL, NULL, cases[k].sets, "tf2_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, cases[k].expect), "%s: rc %d, %s", cases[k].sets[0], rc, d.msg);
  }
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  snprintf(local, sizeof local, "%s/tests/scenes/two_fluid_2d", src ? src : ".");
  quick = getenv("SLUICE_SKIP_LONG") != NULL;
  one_column();
  fluidized_bed();
  settled_bed();
  poiseuille();
  blow_out();
  restart();
  bad_input();
  return sl_test_summary();
}
