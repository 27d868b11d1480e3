/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The 2-D two-fluid model's second-order solids transport ([two_fluid]
 * order = 2: MUSCL, van Leer 1979, minmod or MC limited, in Heun's stages),
 * run through the same entry point as `sluice run` and read back from its
 * output files.
 *
 * One column: the fluidisation step of Pringle (2001, section 4.6.1) in a 2-D column one cell wide
 * (y-faces) and in a row one cell high with gravity along -x (x-faces)
 * follows the 1-D column at the same order and limiter to within what the
 * 2-D model adds (fluid viscous stress, the inertia of both phases written
 * separately), as test_two_fluid_2d.c checks at order 1; and what order 2
 * changes against order 1 is the same in both models to 1/600 of itself.
 * A smooth pulse of solids carried by a uniform flow, phi(x, t) = phi0(x -
 * U t), towards +x, towards -x and round a periodic channel, on 50 to 800
 * cells, uniform and graded: the L1 error falls at first order with order 1,
 * at second with order 2, and is 10 times smaller or more at order 2.
 * Bounds and conservation at order 2: a dense suspension packing with no
 * solids pressure (the packing limiter alone stops it, at phi_max exactly)
 * and a bed blown out of its box: 0 <= phi <= phi_max at every output,
 * solids conserved to round-off with the outflow counted.
 *
 * With an argument, only that part: one_column, pulse, packing, blow_out.
 * SLUICE_SKIP_LONG (the sanitizer build): the step of Pringle (2001) section 4.6.1 to 10 s, no blow-out. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/io/output.h"
#include "core/mesh/mesh.h"
#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096], local[4096];
static int quick; /* SLUICE_SKIP_LONG (the sanitizer build): a shorter Pringle (2001) step, no blow-out */

SCENE_RUNNERS()

static const char *const limiters[2] = {"minmod", "mc"};

/* ---- one column against the 1-D model ------------------------------------------ */

/* The largest over the outputs 1..t_end s, and the one at the end, of |(a - a0) - (b - b0)| of phi (a0, b0 may
 * be NULL: 0), the files' cells alike. 0, or 1 if unreadable. */
static int phi_apart(const char *fa, const char *fa0, const char *fb, const char *fb0, int t_end, double *worst,
                     double *last) {
  *worst = 0.0, *last = 0.0;
  for (int s = 1; s <= t_end; ++s) {
    const char *files[4] = {fa, fa0, fb, fb0};
    double *v[4] = {NULL, NULL, NULL, NULL};
    int n[4] = {0, 0, 0, 0}, ok = 1;
    for (int k = 0; k < 4; ++k)
      if (files[k]) {
        v[k] = field_at(files[k], "phi", s, &n[k], NULL);
        ok = ok && v[k] && n[k] == n[0];
      }
    for (int i = 0; ok && i < n[0]; ++i) {
      double da = v[0][i] - (v[1] ? v[1][i] : 0.0), db = v[2][i] - (v[3] ? v[3][i] : 0.0);
      *last = i ? fmax(*last, fabs(da - db)) : fabs(da - db);
    }
    *worst = fmax(*worst, *last);
    for (int k = 0; k < 4; ++k) free(v[k]);
    if (!ok) {
      CHECK_MSG(0, "%s, %s: unreadable, or %d and %d cells", fa, fb, n[0], n[2]);
      return 1;
    }
  }
  return 0;
}

/* The step of Pringle (2001) section 4.6.1 (porosity 0.65 -> 0.716, 100 cells, dt = 0.01 s) in the 1-D column, in a
 * 2-D column one cell wide (moving phi across y-faces) and in a 2-D row one cell high with gravity along -x
 * (column_x.ini: x-faces).
 * The name of each 2-D form's output, or NULL (a failed check) when it did not run. */
static const char *t1_2d(int along_x, const char *const *extra, const char *out) {
  const char *sets[16] = {0};
  int n = 0;
  sets[n++] = quick ? "time.end=10" : "time.end=60";
  if (!along_x) {
    const char *col[] = {"time.dt=0.01",
                         "output.every=1",
                         "mesh.x=0,0.01",
                         "mesh.cells=1,100",
                         "initial.porosity=y < 0.5 ? 0.65 : 1",
                         "boundary.bottom.velocity=t <= 0 ? 0.0077783 : 0.0115101",
                         "two_fluid.steady_tolerance=0"};
    for (size_t k = 0; k < sizeof col / sizeof col[0]; ++k) sets[n++] = col[k];
  }
  for (int k = 0; extra && extra[k]; ++k) sets[n++] = extra[k];
  if (along_x) {
    sl_diag d = {{0}};
    scene_request q = {.configs = local, .scene = "column_x", .sets = sets, .out = out};
    int rc = scene_run(&q, NULL, &d);
    CHECK_MSG(rc == 0, "column_x: %s", d.msg);
    return rc ? NULL : out;
  }
  return run_ok("fluidized_bed_2d", "closure.drag", "[closure.drag]\nmodel = pringle\n", sets, out) ? NULL : out;
}

/* Against the 1-D column at the same order and limiter. At order 1 the 1-D and 2-D columns differ by 1.75e-4 at
 * most during the transient (test_two_fluid_2d.c): the 2-D model's fluid viscous stress and its separate phase
 * inertia, not the transport, which is the column's. So at order 2 they must differ by no more (bound 2.5e-4),
 * and, sharper, what order 2 changes against order 1 must be the same in both models up to what those physics
 * differences do to it: measured 1.5e-5 (bound 3e-5), while that change itself is 9e-3 (the front's shape). */
static void one_column(void) {
  const int t_end = quick ? 10 : 60;
  const char *end = quick ? "time.end=10" : "time.end=60";
  const char *o1[] = {end, "time.dt=0.01", "output.every=1", NULL};
  const char *c1_o1 = "tf2t_c1_o1.h5";
  const char *cy_o1 = t1_2d(0, NULL, "tf2t_cy_o1.h5"), *cx_o1 = t1_2d(1, NULL, "tf2t_cx_o1.h5");
  if (run_ok("fluidization_step", NULL, NULL, o1, c1_o1) || !cy_o1 || !cx_o1) return;
  for (int k = 0; k < 2; ++k) {
    char lim[64];
    snprintf(lim, sizeof lim, "two_fluid.limiter=%s", limiters[k]);
    const char *sets1[] = {end, "time.dt=0.01", "output.every=1", "two_fluid.order=2", lim, NULL};
    const char *extra[] = {"two_fluid.order=2", lim, NULL};
    const char *c1 = "tf2t_c1.h5", *cy = t1_2d(0, extra, "tf2t_cy.h5"), *cx = t1_2d(1, extra, "tf2t_cx.h5");
    if (run_ok("fluidization_step", NULL, NULL, sets1, c1) || !cy || !cx) return;
    double wy, ly, wx, lx, dy, dx, change, tmp;
    if (phi_apart(c1, NULL, cy, NULL, t_end, &wy, &ly) || phi_apart(c1, NULL, cx, NULL, t_end, &wx, &lx) ||
        phi_apart(c1, c1_o1, cy, cy_o1, t_end, &dy, &tmp) || phi_apart(c1, c1_o1, cx, cx_o1, t_end, &dx, &tmp) ||
        phi_apart(c1, NULL, c1_o1, NULL, t_end, &change, &tmp))
      return;
    printf(
        "  one column at order 2, %s, against the 1-D column, Pringle (2001) step to t = %d s: "
        "max |dphi| over the outputs "
        "%.2e (1 x 100), %.2e (100 x 1, along x), at the end %.1e, %.1e; the change from order 1 alike within "
        "%.2e, %.2e (the change itself %.2e)\n",
        limiters[k], t_end, wy, wx, ly, lx, dy, dx, change);
    CHECK_MSG(wy <= 2.5e-4 && wx <= 2.5e-4,
              "one column, %s: phi differs from the 1-D column by %.3g, along x by "
              "%.3g",
              limiters[k], wy, wx);
    CHECK_MSG(dy <= 3e-5 && dx <= 3e-5,
              "one column, %s: order 2 changes phi differently from the 1-D column, by "
              "%.3g, along x by %.3g",
              limiters[k], dy, dx);
    CHECK_MSG(change >= 100.0 * fmax(dy, dx), "one column, %s: order 2 changes phi by %.3g only", limiters[k], change);
    if (!quick) CHECK_MSG(ly <= 1e-6 && lx <= 1e-6, "one column, %s: %.3g, %.3g apart at the end", limiters[k], ly, lx);
    CHECK_MSG(fabs(scalar(cy, "solids_conservation_error", t_end)) < 1e-12 &&
                  fabs(scalar(cx, "solids_conservation_error", t_end)) < 1e-12,
              "one column: not conserved");
  }
}

/* ---- the order of the transport: a smooth pulse ----------------------------------------- */

/* pulse.ini: phi0 = A exp(-((x - c) / w)^2) carried at U for t (towards +x); backwards, the inlet at the right,
 * from 1 - c; pulse_periodic.ini: from 1/2 once round the periodic channel, for 1 / U. */
static const double P_A = 0.1, P_C = 0.4, P_W = 0.1, P_U = 0.1, P_T = 3.0;
enum { FORWARD, BACKWARD, PERIODIC };

/* The exact mean of phi over [a, b] at the end. */
static double pulse_mean(double a, double b, int way) {
  double c = way == FORWARD ? P_C + P_U * P_T : way == BACKWARD ? 1.0 - P_C - P_U * P_T : 0.5;
  return P_A * P_W * sqrt(M_PI) / 2.0 * (erf((b - c) / P_W) - erf((a - c) / P_W)) / (b - a);
}

/* The L1 error of phi at the end on n cells (grading: NULL uniform, else geometric with that ratio), relative to
 * the pulse's integral; NAN on failure. */
static double pulse_error(int n, int order, int limiter, const char *grading, int way) {
  char cells[64], ord[64], lim[64], grad[64], init[128];
  snprintf(cells, sizeof cells, "mesh.cells=%d,1", n);
  snprintf(ord, sizeof ord, "two_fluid.order=%d", order);
  snprintf(lim, sizeof lim, "two_fluid.limiter=%s", limiters[limiter]);
  snprintf(grad, sizeof grad, "mesh.grading_x=geometric:%s", grading ? grading : "1");
  snprintf(init, sizeof init, "initial.phi=%g * exp(-((x - %g) / %g) * ((x - %g) / %g))", P_A, 1.0 - P_C, P_W,
           1.0 - P_C, P_W);
  const char *sets[] = {
      cells, ord, lim, grad, way == BACKWARD ? init : NULL, "boundary.right.type=inlet", "boundary.right.velocity=0.1",
      NULL};
  const char *out = "tf2t_pulse.h5";
  sl_diag d = {{0}};
  scene_request q = {.configs = local, .scene = way == PERIODIC ? "pulse_periodic" : "pulse", .sets = sets, .out = out};
  if (way == BACKWARD) q.replace_section = "boundary.left", q.replacement = "[boundary.left]\ntype = outlet\n";
  if (scene_run(&q, NULL, &d)) {
    CHECK_MSG(0, "pulse: %s", d.msg);
    return NAN;
  }
  double *x = malloc((size_t)(n + 1) * sizeof *x);
  sl_grading g = {.kind = SL_GRADE_GEOMETRIC, .ratio = grading ? atof(grading) : 1.0};
  int m = 0;
  double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &m, &tf), t_end = way == PERIODIC ? 1.0 / P_U : P_T;
  if (!x || !phi || m != n || sl_mesh_graded_points(0.0, 1.0, n, &g, x, &d) || fabs(tf - t_end) > 1e-9) {
    CHECK_MSG(0, "pulse: %d cells read, t = %g", m, tf);
    free(x), free(phi);
    return NAN;
  }
  double err = 0.0;
  for (int i = 0; i < n; ++i) err += (x[i + 1] - x[i]) * fabs(phi[i] - pulse_mean(x[i], x[i + 1], way));
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", tf)) < 1e-12, "pulse: not conserved");
  free(x), free(phi);
  return err / (P_A * P_W * sqrt(M_PI));
}

/* The pulse on 50, 100, 200, 400, 800 cells, uniform and graded geometrically 1:3 (the slopes then use the
 * actual centre distances), carried towards +x, towards -x (the upwind cell then the face's hi cell) and once
 * round the periodic channel (through the seam; graded, the cells' sizes jump 3:1 there), at order 1 and at
 * order 2 with either limiter. Upwind's numerical diffusion U h (1 - nu) / 2 makes its error first order
 * (measured 0.89 to 0.98 on the finest pair, still rising; bound 0.8). MUSCL is second order but where the
 * limiter clips the slope, at the pulse's peak and feet: a few cells of first-order error O(h) each, O(h^2) in
 * L1, which shows as an observed order still rising towards 2 (measured 1.87 to 1.99); bound 1.8. On 800 cells
 * the order-2 error is 15 to 80 times the smaller; bound 10. */
static void pulse_orders(void) {
  enum { NG = 5, NR = 14 };
  const struct {
    int order, limiter;
    const char *grading;
    int way;
  } runs[NR] = {{1, 0, NULL, FORWARD}, {2, 0, NULL, FORWARD}, {2, 1, NULL, FORWARD},  {1, 0, "3", FORWARD},
                {2, 0, "3", FORWARD},  {2, 1, "3", FORWARD},  {1, 0, NULL, BACKWARD}, {2, 0, NULL, BACKWARD},
                {1, 0, "3", BACKWARD}, {2, 1, "3", BACKWARD}, {1, 0, NULL, PERIODIC}, {2, 1, NULL, PERIODIC},
                {1, 0, "3", PERIODIC}, {2, 1, "3", PERIODIC}};
  static const char *const ways[] = {"towards +x", "towards -x", "periodic"};
  double e[NR][NG];
  for (int r = 0; r < NR; ++r) {
    for (int k = 0; k < NG; ++k)
      e[r][k] = pulse_error(50 << k, runs[r].order, runs[r].limiter, runs[r].grading, runs[r].way);
    char label[96], errs[128] = "", ords[128] = "";
    snprintf(label, sizeof label, "order %d%s%s, %s, %s", runs[r].order, runs[r].order == 2 ? " " : "",
             runs[r].order == 2 ? limiters[runs[r].limiter] : "", runs[r].grading ? "graded 1:3" : "uniform",
             ways[runs[r].way]);
    for (int k = 0; k < NG; ++k) {
      size_t l = strlen(errs);
      snprintf(errs + l, sizeof errs - l, "%s%.2e", k ? ", " : "", e[r][k]);
      if (k) {
        l = strlen(ords);
        snprintf(ords + l, sizeof ords - l, "%s%.2f", k > 1 ? ", " : "", log2(e[r][k - 1] / e[r][k]));
      }
    }
    printf("  pulse, %s: relative L1 error %s on 50..%d cells (orders %s)\n", label, errs, 50 << (NG - 1), ords);
  }
  const int f = NG - 1; /* the finest grid */
  for (int r = 0; r < NR; ++r) {
    double o = log2(e[r][f - 1] / e[r][f]);
    if (runs[r].order == 1) {
      CHECK_MSG(o > 0.8 && o < 1.15, "pulse, order 1 (%s): observed order %.2f", ways[runs[r].way], o);
      continue;
    }
    CHECK_MSG(o > 1.8, "pulse, order 2 (%s, %s): observed order %.2f", limiters[runs[r].limiter], ways[runs[r].way], o);
    for (int q = 0; q < NR; ++q) /* against order 1 on the same grid, the same way */
      if (runs[q].order == 1 && runs[q].way == runs[r].way && (runs[q].grading != NULL) == (runs[r].grading != NULL))
        CHECK_MSG(e[r][f] * 10.0 < e[q][f], "pulse, order 2 (%s): error %.3g, order 1 %.3g", ways[runs[r].way], e[r][f],
                  e[q][f]);
  }
}

/* ---- bounds and conservation at order 2 -------------------------------------------------- */

/* Every output of `out` bounded (0 <= phi <= phi_max, finite solids velocities); the largest conservation
 * error over the outputs in *worst, the largest phi in *pmax, the cells at phi_max at the end in *full. */
static int bounded(const char *out, const char *label, double *worst, double *pmax, int *full, double *left) {
  int ns = 0, bad = 0;
  double *times = NULL;
  sl_diag d = {{0}};
  if (sl_output_read_times(out, &ns, &times, &d)) {
    CHECK_MSG(0, "%s: %s", label, d.msg);
    return 1;
  }
  *worst = 0.0, *pmax = 0.0, *full = 0;
  for (int s = 0; s < ns; ++s) {
    int n = 0, nu = 0;
    double *phi = field_at(out, "phi", times[s], &n, NULL);
    double *us = field_at(out, "velocity_solid", times[s], &nu, NULL);
    for (int i = 0; phi && i < n; ++i) {
      bad += !(phi[i] >= 0.0 && phi[i] <= 0.64);
      *pmax = fmax(*pmax, phi[i]);
      if (s == ns - 1) *full += phi[i] >= 0.64 - 1e-12;
    }
    for (int i = 0; us && i < 3 * nu; ++i) bad += !isfinite(us[i]);
    *worst = fmax(*worst, fabs(scalar(out, "solids_conservation_error", times[s])));
    free(phi), free(us);
  }
  *left = scalar(out, "solids_inventory", times[ns - 1]);
  free(times);
  CHECK_MSG(bad == 0, "%s: %d values outside [0, phi_max] or not finite", label, bad);
  CHECK_MSG(*worst < 1e-12, "%s: conservation error %.3g", label, *worst);
  return 0;
}

/* settled_bed_2d one column wide (1 x 50) at phi = 0.5 with no solids pressure, steps of 20 s to 4000 s (the
 * 1-D column's packing case of test_two_fluid_scenes.c): only the packing limiter stops the sediment, which ends
 * at phi_max exactly, S / phi_max high: 0.25 / 0.64 = 0.39 m, 39 of the 50 rows of 1 cm. (4 columns with their
 * no-slip walls take minutes at either order: the packed sediment's iterates need thousands of sub-steps.) */
static void packing(void) {
  for (int k = 0; k < 2; ++k) {
    char lim[64];
    snprintf(lim, sizeof lim, "two_fluid.limiter=%s", limiters[k]);
    const char *sets[] = {"mesh.cells=1,50",
                          "initial.phi=0.5",
                          "time.dt=20",
                          "time.end=4000",
                          "output.every=20",
                          "two_fluid.steady_tolerance=0",
                          "two_fluid.order=2",
                          lim,
                          NULL};
    const char *out = "tf2t_pack.h5";
    if (run_ok("settled_bed_2d", "closure.solids_pressure", "", sets, out)) continue;
    double worst, pmax, left;
    int full;
    if (bounded(out, "packing", &worst, &pmax, &full, &left)) continue;
    printf(
        "  packing (settled_bed_2d 1 x 50, phi 0.5, no p_s, order 2, %s): max phi %.15f, %d cells at phi_max, "
        "conservation within %.1e over the outputs\n",
        limiters[k], pmax, full, worst);
    CHECK_MSG(full == 39, "packing, %s: %d cells at phi_max, expected 39", limiters[k], full);
  }
}

/* The bed of fluidized_bed_2d (5 x 50) blown out of the box by a step to 0.5 m/s (terminal velocity 78 mm/s),
 * order 2 with MC, to 5 s: bounded and conserving at every output with the outflow counted, no solids left. At
 * dt = 0.02 s (5 s of CPU; at test_two_fluid_2d.c's 0.1 s the emptying cells' iterates need ~10^4 sub-steps, a
 * minute and a half at order 2). */
static void blow_out(void) {
  if (quick) return;
  const char *sets[] = {"boundary.bottom.velocity=t <= 0 ? 0.01 : 0.5",
                        "time.dt=0.02",
                        "time.end=5",
                        "output.every=0.5",
                        "two_fluid.steady_tolerance=0",
                        "two_fluid.order=2",
                        "two_fluid.limiter=mc",
                        NULL};
  const char *out = "tf2t_blow.h5";
  sluice_summary res;
  sl_diag d = {{0}};
  scene_request q = {.configs = configs, .scene = "fluidized_bed_2d", .sets = sets, .out = out};
  int rc = scene_run(&q, &res, &d);
  CHECK_MSG(rc == 0, "blow-out: %s", d.msg);
  if (rc) return;
  double worst, pmax, left;
  int full;
  if (bounded(out, "blow-out", &worst, &pmax, &full, &left)) return;
  printf(
      "  blow-out (order 2, mc, U 0.01 -> 0.5 m/s, dt = 0.02 s): conservation within %.1e, max phi %.4f, solids "
      "left %.1e m^2 of %.4f; %s\n",
      worst, pmax, left, 0.05 * 0.3 * 0.4, res.coupling_summary);
  CHECK_MSG(left < 1e-9 * 0.006, "blow-out: %.3g m^2 of solids left", left);
}

int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  snprintf(local, sizeof local, "%s/tests/scenes/two_fluid_2d", src ? src : ".");
  quick = getenv("SLUICE_SKIP_LONG") != NULL;
  const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"one_column", one_column}, {"pulse", pulse_orders}, {"packing", packing}, {"blow_out", blow_out}};
  clock_t c0 = clock();
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 || strcmp(argv[1], parts[k].name) == 0) parts[k].run();
  printf("  CPU %.1f s\n", (double)(clock() - c0) / CLOCKS_PER_SEC);
  return sl_test_summary();
}
