/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Blocked cells ([body], core/models/two_fluid/two_fluid_plane_body.c) and
 * the swirl's centrifugal force ([two_fluid] centrifugal) of the 2-D
 * axisymmetric two-fluid model.
 *
 * - annulus: configs/annulus_blocked.ini, the viscometer's gap made by
 *   blocking the rotor in a cylinder that reaches the axis: (a) the gap's
 *   fields equal those of the same scene on the gap's own mesh with the
 *   rotor as its wall (the same discrete equations, to round-off); (b) the
 *   axial profile against the exact annular Poiseuille profile and the swirl
 *   against Couette's (Bird, Stewart & Lightfoot 2002, Examples 2.4-1 and
 *   3.6-3) on 16, 32, 64 cells across the gap, second order.
 * - torque: the same annulus one cell high between slip walls: the torque on the rotor against Couette's exact
 *   torque between coaxial cylinders, second order, and balanced by the vessel's to round-off.
 * - named bodies: the rotor as two [body.NAME] halves equals the single [body] to round-off, torques adding up.
 * - centrifugal: configs/couette_two_phase.ini with centrifugal = true and
 *   neutrally buoyant solids: the radial pressure of the Couette swirl,
 *   dp/dr = rho u_theta^2 / r, integrated exactly,
 *     p(r) = rho (A^2 r^2 / 2 + 2 A B ln r - B^2 / (2 r^2)) + const,
 *   u_theta = A r + B / r, on 16, 32, 64 cells, second order; denser solids
 *   move outwards (and stay uniform without the key).
 * - bad input: [body], [body.NAME] (overlapping, outside the domain, named like a boundary, without a box, an
 *   unknown key) and centrifugal keys refused with file:line.
 * - viscometer_tip (long): configs/viscometer_rotor_tip.ini, the rotor's tip
 *   in the fluidised bed (Pringle 2001 5.6): the porosity below the tip,
 *   with the swirl one-way and two-way. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];

SCENE_RUNNERS()

static const double RI = 0.015, RO = 0.045, OMEGA = 10.0, U = 0.001;

static double couette(double r) { return OMEGA / (RI * RI - RO * RO) * (r * RI * RI - RI * RI * RO * RO / r); }

/* the annular Poiseuille profile's shape; its r dr mean over the gap */
static double poiseuille_shape(double r) { return RO * RO - r * r + (RO * RO - RI * RI) * log(r / RO) / log(RO / RI); }
static double poiseuille_mean(void) {
  double s = 0.0, a = 0.0;
  for (int k = 0; k < 200000; ++k) {
    double r = RI + (k + 0.5) * (RO - RI) / 200000;
    s += r * poiseuille_shape(r), a += r;
  }
  return s / a;
}

/* runs a scene with a section replaced (NULL: none) */
static int run_replaced(const char *scene, const char *section, const char *text, const char *const *sets,
                        const char *out, sl_diag *d) {
  scene_request q = {
      .configs = configs, .scene = scene, .replace_section = section, .replacement = text, .sets = sets, .out = out};
  return scene_run(&q, NULL, d);
}

enum { NY = 20, ROW = 10 };

/* The blocked annulus against the gap's own mesh, field by field in the gap's cells. */
static void annulus_equivalence(void) {
  const char *sets_b[] = {NULL}, *sets_g[] = {"mesh.x=0.015,0.045", "mesh.cells=16,20", "boundary.left.type=wall",
                                              "boundary.left.angular_velocity=10", NULL};
  sl_diag d = {{0}};
  int rc = run_replaced("annulus_blocked", NULL, NULL, sets_b, "body_blocked.h5", &d);
  CHECK_MSG(rc == 0, "blocked: %s", d.msg);
  rc = run_replaced("annulus_blocked", "body", "", sets_g, "body_gap.h5", &d);
  CHECK_MSG(rc == 0, "gap: %s", d.msg);
  if (rc) return;
  static const char *const names[3] = {"velocity_fluid", "swirl_fluid", "pressure"};
  static const int ncomp[3] = {3, 1, 1};
  for (int k = 0; k < 3; ++k) {
    int nb = 0, ng = 0;
    double *b = field_at("body_blocked.h5", names[k], INFINITY, &nb, NULL);
    double *g = field_at("body_gap.h5", names[k], INFINITY, &ng, NULL);
    CHECK_MSG(b && g && nb == 24 * NY && ng == 16 * NY, "%s: %d, %d cells", names[k], nb, ng);
    if (b && g && nb == 24 * NY && ng == 16 * NY) {
      double diff = 0.0, big = 0.0;
      for (int j = 0; j < NY; ++j)
        for (int i = 0; i < 16; ++i)
          for (int q = 0; q < ncomp[k]; ++q) {
            double vb = b[ncomp[k] * (j * 24 + 8 + i) + q], vg = g[ncomp[k] * (j * 16 + i) + q];
            diff = fmax(diff, fabs(vb - vg)), big = fmax(big, fabs(vg));
          }
      printf("  annulus: %s blocked against the gap's mesh: largest difference %.2e of %.3e\n", names[k], diff, big);
      CHECK_MSG(big > 0.0 && diff <= 1e-10 * big, "%s: difference %.3g of %.3g", names[k], diff, big);
    }
    free(b), free(g);
  }
}

/* the largest errors of u_z (relative to the mean U) and u_theta (to omega r_i) across the gap at z = 0.105 m,
   n cells across the gap */
static int annulus_errors(int n, double *ez, double *et) {
  char cells[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d,%d", n + n / 2, NY);
  const char *sets[] = {cells, NULL};
  const char *out = "body_annulus.h5";
  if (run_ok("annulus_blocked", NULL, NULL, sets, out)) return 1;
  int nv = 0, ns = 0, nx = n + n / 2;
  double *u = field_at(out, "velocity_fluid", INFINITY, &nv, NULL),
         *w = field_at(out, "swirl_fluid", INFINITY, &ns, NULL);
  int ok = u && w && nv == nx * NY && ns == nx * NY;
  CHECK_MSG(ok, "annulus: %d, %d cells", nv, ns);
  double C = U / poiseuille_mean();
  *ez = *et = 0.0;
  for (int i = 0; ok && i < n; ++i) {
    int c = ROW * nx + n / 2 + i;
    double r = RI + (i + 0.5) * (RO - RI) / n;
    *ez = fmax(*ez, fabs(u[3 * c + 1] - C * poiseuille_shape(r)) / U);
    *et = fmax(*et, fabs(w[c] - couette(r)) / (OMEGA * RI));
  }
  free(u), free(w);
  return !ok;
}

static void annulus_order(void) {
  double ez[3], et[3];
  for (int l = 0; l < 3; ++l)
    if (annulus_errors(16 << l, &ez[l], &et[l])) return;
  double pz1 = log2(ez[0] / ez[1]), pz2 = log2(ez[1] / ez[2]), pt1 = log2(et[0] / et[1]), pt2 = log2(et[1] / et[2]);
  printf(
      "  annulus by blocking: u_z error %.3e, %.3e, %.3e of the mean (order %.2f, %.2f); u_theta %.3e, %.3e, "
      "%.3e of omega r_i (order %.2f, %.2f) on 16, 32, 64 cells across the gap\n",
      ez[0], ez[1], ez[2], pz1, pz2, et[0], et[1], et[2], pt1, pt2);
  CHECK_MSG(ez[1] < 0.01 && et[1] < 0.01, "annulus: errors %.3g, %.3g on 32 cells", ez[1], et[1]);
  CHECK_MSG(pz1 > 1.8 && pz2 > 1.8, "annulus: u_z order %.2f, %.2f", pz1, pz2);
  CHECK_MSG(pt1 > 1.8 && pt2 > 1.8, "annulus: u_theta order %.2f, %.2f", pt1, pt2);
}

/* The torque on the blocked rotor (two_fluid_plane_swirl.c) against Couette's between coaxial cylinders, the inner
 * one turning at omega, the outer at rest: T = 2 pi r_i^2 L tau(r_i) = -4 pi mu L omega r_i^2 r_o^2 / (r_o^2 -
 * r_i^2) on the rotor (Bird, Stewart & Lightfoot 2002, Example 3.6-3; mu = 1 Pa s, L = 0.2 m), its opposite on the
 * vessel. The scene's bottom and top become slip walls (no torque, no flow through them) on one row of cells, so
 * that the swirl is Couette's at every height; 16, 32, 64 cells across the gap. Asserted: the torque within 0.5 %
 * on 32 cells and second order, the mean azimuthal stress on the rotor's side at order 2 towards tau(r_i), and the
 * torques on rotor and vessel opposite to round-off (the discrete angular momentum is conserved). */
static void annulus_torque(void) {
  const double L = 0.2, MU = 1.0;
  const double T = -4.0 * M_PI * MU * L * OMEGA * RI * RI * RO * RO / (RO * RO - RI * RI),
               tau = T / (2 * M_PI * RI * RI * L);
  double e[3], es[3];
  for (int l = 0; l < 3; ++l) {
    int n = 16 << l;
    char cells[64];
    snprintf(cells, sizeof cells, "mesh.cells=%d,1", n + n / 2);
    const char *sets[] = {cells, "boundary.top.type=slip", NULL};
    const char *out = "body_torque.h5";
    if (run_ok("annulus_blocked", "boundary.bottom", "[boundary.bottom]\ntype = slip\n", sets, out)) return;
    double tb = scalar(out, "torque_body", INFINITY), tv = scalar(out, "torque_right", INFINITY);
    double tf = scalar(out, "torque_fluid_body", INFINITY), ts = scalar(out, "torque_solid_body", INFINITY);
    double sb = scalar(out, "wall_shear_stress_theta_fluid_body", INFINITY);
    e[l] = fabs(tb - T) / fabs(T), es[l] = fabs(sb - tau) / fabs(tau);
    printf(
        "  torque on the blocked rotor, %d cells across the gap: %.6e N m (Couette %.6e, error %.2e), on the "
        "vessel %.6e, mean stress on the rotor %.5f Pa (%.5f)\n",
        n, tb, T, e[l], tv, sb, tau);
    CHECK_MSG(fabs(tb + tv) <= 1e-12 * fabs(T), "torque: rotor %.17g and vessel %.17g do not balance", tb, tv);
    CHECK_MSG(tf == tb && ts == 0.0, "torque: clear fluid, fluid %.17g solids %.17g of %.17g", tf, ts, tb);
  }
  double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]), q1 = log2(es[0] / es[1]), q2 = log2(es[1] / es[2]);
  printf("  torque order %.2f, %.2f; the rotor's mean azimuthal stress order %.2f, %.2f\n", p1, p2, q1, q2);
  CHECK_MSG(e[1] < 5e-3, "torque: error %.3g on 32 cells", e[1]);
  CHECK_MSG(p1 > 1.8 && p2 > 1.8, "torque: order %.2f, %.2f", p1, p2);
  CHECK_MSG(q1 > 1.8 && q2 > 1.8, "torque: the stress's order %.2f, %.2f", q1, q2);
}

/* Couette's pressure: p(r) up to a constant, rho = 1000 */
static double couette_pressure(double r) {
  double A = OMEGA * RI * RI / (RI * RI - RO * RO), B = -OMEGA * RI * RI * RO * RO / (RI * RI - RO * RO);
  return 1000.0 * (A * A * r * r / 2 + 2 * A * B * log(r) - B * B / (2 * r * r));
}

static double centrifugal_error(int n, double *span) {
  char cells[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d,1", n);
  const char *sets[] = {cells, "two_fluid.centrifugal=true", "solid.density=1000", NULL};
  const char *out = "body_centrifugal.h5";
  if (run_ok("couette_two_phase", NULL, NULL, sets, out)) return NAN;
  int m = 0;
  double *p = field_at(out, "pressure", INFINITY, &m, NULL);
  CHECK_MSG(p && m == n, "%d cells", m);
  if (!p || m != n) {
    free(p);
    return NAN;
  }
  double worst = 0.0, r0 = RI + 0.5 * (RO - RI) / n;
  *span = couette_pressure(RO - 0.5 * (RO - RI) / n) - couette_pressure(r0);
  for (int i = 0; i < n; ++i) {
    double r = RI + (i + 0.5) * (RO - RI) / n;
    worst = fmax(worst, fabs((p[i] - p[0]) - (couette_pressure(r) - couette_pressure(r0))));
  }
  free(p);
  return worst;
}

static void centrifugal_order(void) {
  double e[3], span = 0.0;
  for (int l = 0; l < 3; ++l) e[l] = centrifugal_error(16 << l, &span);
  double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]);
  printf(
      "  centrifugal: Couette's radial pressure, largest error %.3e, %.3e, %.3e Pa on 16, 32, 64 cells (its rise "
      "across the gap %.3f Pa); order %.2f, %.2f\n",
      e[0], e[1], e[2], span, p1, p2);
  CHECK_MSG(e[1] < 0.01 * span, "centrifugal: error %.3g Pa on 32 cells", e[1]);
  CHECK_MSG(p1 > 1.8 && p2 > 1.8, "centrifugal: order %.2f, %.2f", p1, p2);
  /* denser solids (2460 kg/m3) are flung outwards; without the key phi stays uniform */
  for (int on = 0; on < 2; ++on) {
    const char *sets[] = {"mesh.cells=16,1", on ? "two_fluid.centrifugal=true" : NULL, NULL};
    if (run_ok("couette_two_phase", NULL, NULL, sets, "body_centrifuge.h5")) return;
    int m = 0;
    double *phi = field_at("body_centrifuge.h5", "phi", INFINITY, &m, NULL);
    if (!phi || m != 16) {
      CHECK_MSG(0, "%d cells", m);
      free(phi);
      return;
    }
    printf("  centrifugal %s: phi %.6f at the rotor, %.6f at the vessel (0.3 at first)\n", on ? "on" : "off", phi[0],
           phi[15]);
    if (on) CHECK_MSG(phi[15] > phi[0] && phi[0] < 0.3, "centrifuge: phi %.6g, %.6g", phi[0], phi[15]);
    else CHECK_MSG(phi[0] == 0.3 && phi[15] == 0.3, "no centrifugal: phi %.17g, %.17g", phi[0], phi[15]);
    free(phi);
  }
}

/* Named bodies ([body.NAME]): the rotor as two bodies, its lower and upper half, touching at z = 0.1 m: the fields
 * equal the single [body]'s to round-off (the faces between them are dead, as inside one body), and the two
 * halves' torques add up to the whole rotor's. */
static void named_bodies(void) {
  const char *two =
      "[body.lower]\nbox = 0, 0.015, 0, 0.1\nangular_velocity = 10\n\n"
      "[body.upper]\nbox = 0, 0.015, 0.1, 0.2\nangular_velocity = 10\n";
  const char *sets[] = {NULL};
  sl_diag d = {{0}};
  int rc = run_replaced("annulus_blocked", NULL, NULL, sets, "body_one.h5", &d);
  CHECK_MSG(rc == 0, "one body: %s", d.msg);
  if (!rc) rc = run_replaced("annulus_blocked", "body", two, sets, "body_two.h5", &d);
  CHECK_MSG(rc == 0, "two bodies: %s", d.msg);
  if (rc) return;
  static const char *const names[3] = {"velocity_fluid", "swirl_fluid", "pressure"};
  for (int k = 0; k < 3; ++k) {
    int n1 = 0, n2 = 0;
    double *a = field_at("body_one.h5", names[k], INFINITY, &n1, NULL),
           *b = field_at("body_two.h5", names[k], INFINITY, &n2, NULL);
    CHECK_MSG(a && b && n1 == n2 && n1 > 0, "%s: %d, %d cells", names[k], n1, n2);
    double diff = 0.0, big = 0.0;
    int nv = k == 0 ? 3 * n1 : n1;
    for (int i = 0; a && b && n1 == n2 && i < nv; ++i)
      diff = fmax(diff, fabs(a[i] - b[i])), big = fmax(big, fabs(a[i]));
    printf("  named bodies: %s of two bodies against one: largest difference %.2e of %.3e\n", names[k], diff, big);
    CHECK_MSG(big > 0.0 && diff <= 1e-12 * big, "%s: difference %.3g of %.3g", names[k], diff, big);
    free(a), free(b);
  }
  double t1 = scalar("body_one.h5", "torque_body", INFINITY);
  double tl = scalar("body_two.h5", "torque_lower", INFINITY), tu = scalar("body_two.h5", "torque_upper", INFINITY);
  printf("  named bodies: torque %.6e + %.6e = %.6e N m against the single body's %.6e\n", tl, tu, tl + tu, t1);
  CHECK_MSG(fabs(tl + tu - t1) <= 1e-12 * fabs(t1) && tl < 0.0 && tu < 0.0, "torques %.17g + %.17g against %.17g", tl,
            tu, t1);
}

static void bad_input(void) {
  /* the [body] section replaced in the scene file (its errors name the file's line) */
  struct {
    const char *body, *expect;
  } cases[] = {
      {"[body]\nbox = 0, 0.015, 0\n", "annulus_blocked.ini:63: [body] box = 0, 0.015, 0: four numbers"},
      {"[body]\nbox = 0, 0.016, 0, 0.2\nangular_velocity = 10\n",
       "annulus_blocked.ini:63: [body] box: x1 = 0.016 is "
       "not on a grid line"},
      {"[body]\nbox = 0, 0.045, 0, 0.2\n", "annulus_blocked.ini:63: [body] box: it holds all of the mesh's"},
      {"[body]\nangular_velocity = 10\n", "annulus_blocked.ini:63: [body] angular_velocity: the body needs its box"},
      {"[body.a]\nbox = 0, 0.015, 0, 0.1\n[body.b]\nbox = 0.0075, 0.015, 0.05, 0.2\n",
       "annulus_blocked.ini:65: [body.b] box = 0.0075, 0.015, 0.05, 0.2: overlaps"},
      {"[body.a]\nbox = 0, 0.015, 0, 0.3\n",
       "annulus_blocked.ini:63: [body.a] box = 0, 0.015, 0, 0.3: outside the "
       "domain"},
      {"[body.right]\nbox = 0, 0.015, 0, 0.1\n", "annulus_blocked.ini:62: [body.right]: the name of a boundary"},
      {"[body.a]\nangular_velocity = 10\n", "annulus_blocked.ini:62: [body.a]: the body needs its box"},
      {"[body.a]\nbox = 0, 0.015, 0, 0.1\nradius = 3\n",
       "annulus_blocked.ini:64:1: error: [body.a] radius: not a key of the 2-D model (motion = column, "
       "geometry = planar | axisymmetric) (its keys: box, angular_velocity)"},
  };
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene("annulus_blocked", "body", cases[k].body, NULL, "body_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, cases[k].expect), "%s: rc %d, %s", cases[k].body, rc, d.msg);
  }
  struct {
    const char *scene, *sets[3], *expect;
  } sets[] = {
      {"annulus_blocked",
       {"two_fluid.swirl=false", NULL},
       "[body] angular_velocity: only with [two_fluid] swirl = true"},
      {"fluidized_bed_2d", {"two_fluid.centrifugal=true", NULL}, "[two_fluid] centrifugal: only with swirl = true"},
  };
  for (size_t k = 0; k < sizeof sets / sizeof sets[0]; ++k) {
    sl_diag d = {{0}};
    int rc = run_scene(sets[k].scene, NULL, NULL, sets[k].sets, "body_bad.h5", &d);
    CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, sets[k].expect), "%s: rc %d, %s", sets[k].sets[0], rc, d.msg);
  }
}

/* configs/viscometer_rotor_tip.ini on 9 x 20 cells (5 mm), the swirl one-way (to its steady state) and two-way
 * (to t = 50 s): the porosity directly below the tip (the row under z = 30 mm: the axis cell, the mean of the
 * three under the rotor) against Pringle's (2001 5.6, digest 4.8) n ~ 1 there, the sand dropping out where the
 * fluid is slow. The one-way run shows it (the axis cell's porosity above 0.95), reaches the scene's steady
 * criterion (largest dphi/dt below 1e-5 per s) before its end with under 10 % of its steps rejected, and the
 * mixture holds the rotor back (a negative torque on it); the two-way run's porosity is printed (its centrifugal
 * pumping under the tip keeps the sand up there); solids conserved in both. */
static void viscometer_tip(void) {
  enum { NX = 9, NZ = 20, TIP = 6 }; /* the tip at row 6 (z = 30 mm); the rotor r < 15 mm: columns 0-2 */
  for (int two_way = 0; two_way < 2; ++two_way) {
    const char *out = "viscometer_rotor_tip.h5";
    const char *sets[] = {"mesh.cells=9,20", two_way ? "two_fluid.centrifugal=true" : NULL,
                          two_way ? "time.end=50" : NULL, NULL};
    scene_request q = {.configs = configs, .scene = "viscometer_rotor_tip", .sets = sets, .out = out};
    sluice_summary res;
    sl_diag d = {{0}};
    int rc = scene_run(&q, &res, &d);
    CHECK_MSG(rc == 0, "viscometer_rotor_tip: %s", d.msg);
    if (rc) return;
    double rejected = res.steps + res.rejected_steps > 0
                          ? (double)res.rejected_steps / (double)(res.steps + res.rejected_steps)
                          : 1.0;
    double T = scalar(out, "torque_body", INFINITY), Tf = scalar(out, "torque_fluid_body", INFINITY);
    printf(
        "  viscometer with the rotor's tip (9 x 20, swirl %s): %s; %ld steps, %ld rejected (%.1f %%); torque on "
        "the rotor %.4e N m (fluid %.4e)\n",
        two_way ? "two-way" : "one-way", res.stop_reason, res.steps, res.rejected_steps, 100.0 * rejected, T, Tf);
    if (!two_way) {
      CHECK_MSG(strstr(res.stop_reason, "steady") != NULL, "viscometer_tip (one-way): not steady (%s)",
                res.stop_reason);
      CHECK_MSG(rejected < 0.1, "viscometer_tip (one-way): %.3g of the steps rejected", rejected);
      CHECK_MSG(T < 0.0 && Tf < 0.0, "viscometer_tip (one-way): torque %.3g, fluid's %.3g", T, Tf);
    }
    int n = 0;
    double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
    CHECK_MSG(phi && n == NX * NZ, "%d cells", n);
    if (!phi || n != NX * NZ) {
      free(phi);
      return;
    }
    const double *row = phi + (TIP - 1) * NX;
    double axis = 1.0 - row[0], under = 1.0 - (row[0] + row[1] + row[2]) / 3.0, beside = 0.0, bed = 0.0;
    for (int i = 3; i < NX; ++i) beside += (1.0 - row[i]) / (NX - 3);
    for (int i = 0; i < NX; ++i) bed += (1.0 - phi[i]) / NX;
    double err = scalar(out, "solids_conservation_error", tf);
    printf(
        "  viscometer with the rotor's tip (9 x 20, swirl %s): t = %.1f s; porosity directly below the tip %.4f "
        "at the axis, %.4f under the rotor; beside it in the gap %.4f; at the distributor %.4f; conservation "
        "%.1e\n",
        two_way ? "two-way" : "one-way", tf, axis, under, beside, bed, err);
    CHECK_MSG(fabs(err) < 1e-12, "viscometer_tip: solids not conserved (%.3g)", err);
    if (!two_way) CHECK_MSG(axis > 0.95, "viscometer_tip (one-way): porosity below the tip %.4f", axis);
    free(phi);
  }
}

/* argv[1] names one part (annulus, centrifugal, viscometer_tip); none: annulus, centrifugal, bad input. */
int main(int argc, char **argv) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  const char *part = argc > 1 ? argv[1] : "";
  if (strcmp(part, "viscometer_tip") == 0) viscometer_tip();
  else if (strcmp(part, "annulus") == 0) annulus_equivalence(), annulus_order(), annulus_torque(), named_bodies();
  else if (strcmp(part, "centrifugal") == 0) centrifugal_order();
  else if (strcmp(part, "bad_input") == 0) bad_input();
  else if (*part) return fprintf(stderr, "unknown part '%s'\n", part), 2;
  else annulus_equivalence(), annulus_order(), annulus_torque(), named_bodies(), centrifugal_order(), bad_input();
  return sl_test_summary();
}
