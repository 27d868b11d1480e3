/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What Greenspan's centrifugal spectrometer (Nigam 1999, section 4.3) needs
 * of the mixture model, against exact answers:
 *  - inflow: a channel with plug flow whose inflow carries a solids fraction
 *    given as an expression of the channel coordinate
 *    (tests/scenes/inflow_channel.ini, no settling). Steady advection: the
 *    outflow's cells carry the inflow's value at their row's face point to
 *    1e-6, and so differ from the exact cell averages of the profile by
 *    h^2 phi''/24: observed order 2 (1.9 to 2.1) over 8 and 16 rows.
 *    Conservation: with a profile that also grows in t, before the front
 *    reaches the outlet, the inventory equals the solids that entered,
 *    sum over steps dt sum_f A_f u phi(y_f, t_{n+1}), to 1e-12;
 *  - parameters: a scene written with [parameters] (named constants in its
 *    values and expressions) gives bit for bit the result of the same scene
 *    written in numbers;
 *  - spectrometer: configs/spectrometer.ini on the coarse mesh
 *    (tests/scenes/spectrometer_coarse.msh) to t = 1, with and without 20 %
 *    of the inner flux diverted through the slot: the inventory against the
 *    solids through the boundaries to 1e-12, the inflow's solids against eq
 *    4.148 plus the slip along the channel to 1 %, and the thesis's
 *    observations (a sediment on the inclined walls, the efficiency raised
 *    by the diversion, a retrograde swirl in the slot; the thesis found
 *    it weaker with the diversion, this geometry finds it stronger, which
 *    is printed, not asserted);
 *  - spectrometer_steady: the same two runs (the diverted one as
 *    configs/spectrometer_diverted.ini) to t = 2.5: the steady share of the
 *    particles passing to the outer channel, over windows of a through-flow
 *    time, steady to 1e-3, equal to the outer outlet's share to 1e-3, raised
 *    by the diversion; the sediment and the retrograde swirl in both. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/io/sample.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];
SCENE_RUNNERS()

static void set_configs(const char *sub) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/%s", src ? src : ".", sub);
}

static double scalar(const char *file, const char *name, double t) {
  sl_diag d = {{0}};
  double v = NAN, tf;
  int rc = sl_output_read_scalar(file, name, t, &v, &tf, &d);
  CHECK_MSG(rc == 0 && fabs(tf - t) < 1e-9, "%s: %s at t = %g: %s", file, name, t, d.msg);
  return v;
}

/* The cell field phi at n points at time t. */
static int phi_points(const char *file, double t, int n, const double *xy, double *v) {
  sl_sample s;
  sl_diag d = {{0}};
  int rc = sl_sample_points(file, "phi", t, n, xy, &s, &d);
  CHECK_MSG(rc == 0, "%s: %s", file, d.msg);
  if (rc) return rc;
  for (int i = 0; i < n; ++i) v[i] = s.values[i];
  sl_sample_free(&s);
  return 0;
}

/* The inflow profile of inflow_channel.ini and its exact mean over [a, b]. */
static double profile(double y) { return 0.02 + 0.01 * sin(M_PI * y / 2); }
static double profile_mean(double a, double b) {
  return 0.02 - 0.01 * (2 / M_PI) * (cos(M_PI * b / 2) - cos(M_PI * a / 2)) / (b - a);
}

/* Steady outflow on `rows` rows: the largest error against the exact cell
 * means (*e_mean) and against the profile at the row's centre (*e_point). */
static int steady_rows(int rows, double *e_mean, double *e_point) {
  char cells[64], out[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d,%d", 4 * rows, rows);
  snprintf(out, sizeof out, "inflow_steady_%d.h5", rows);
  const char *sets[] = {cells, "output.every=8", NULL};
  if (run_ok("inflow_channel", NULL, NULL, sets, out)) return 1;
  double xy[2 * 64], v[64], h = 2.0 / rows;
  for (int j = 0; j < rows; ++j) xy[2 * j] = 4 - 0.5 * (4.0 / (4 * rows)), xy[2 * j + 1] = -1 + (j + 0.5) * h;
  if (phi_points(out, 8.0, rows, xy, v)) return 1;
  *e_mean = *e_point = 0;
  for (int j = 0; j < rows; ++j) {
    double y0 = -1 + j * h, y1 = y0 + h;
    *e_mean = fmax(*e_mean, fabs(v[j] - profile_mean(y0, y1)));
    *e_point = fmax(*e_point, fabs(v[j] - profile(0.5 * (y0 + y1))));
  }
  return 0;
}

static void inflow(void) {
  set_configs("tests/scenes");
  double em8, ep8, em16, ep16;
  if (steady_rows(8, &em8, &ep8) || steady_rows(16, &em16, &ep16)) return;
  double order = log2(em8 / em16);
  printf(
      "steady outflow: against the cell means %.3e (8 rows), %.3e (16 rows), order %.3f; against the row's "
      "face value %.2e, %.2e\n",
      em8, em16, order, ep8, ep16);
  CHECK_MSG(order > 1.9 && order < 2.1, "order %g", order);
  CHECK_MSG(ep8 < 1e-6 * 0.03 && ep16 < 1e-6 * 0.03, "%g %g", ep8, ep16);

  /* conservation: phi(y, t) = profile(y) (1 + t), to t = 0.5 (the front is still inside) */
  const char *sets[] = {"boundary.left.phi=(0.02 + 0.01 * sin(pi * y / 2)) * (1 + t)", "time.end=0.5",
                        "output.every=0.5", NULL};
  const char *out = "inflow_timed.h5";
  if (run_ok("inflow_channel", NULL, NULL, sets, out)) return;
  double entered = 0, h = 2.0 / 8, dt = 0.1;
  for (int n = 1; n <= 5; ++n)
    for (int j = 0; j < 8; ++j) entered += dt * h * 1.0 * profile(-1 + (j + 0.5) * h) * (1 + n * dt);
  double inv = scalar(out, "solids_inventory", 0.5), inv0 = scalar(out, "solids_inventory", 0.0);
  double xy[16], v[8];
  for (int j = 0; j < 8; ++j) xy[2 * j] = 3.9375, xy[2 * j + 1] = -1 + (j + 0.5) * h;
  if (phi_points(out, 0.5, 8, xy, v)) return;
  double at_outlet = 0;
  for (int j = 0; j < 8; ++j) at_outlet = fmax(at_outlet, v[j]);
  printf("conservation to t = 0.5: inventory %.15g, entered %.15g, relative %.2e; phi at the outlet %g\n", inv - inv0,
         entered, (inv - inv0 - entered) / entered, at_outlet);
  CHECK_MSG(at_outlet == 0.0, "the front reached the outlet: phi = %g there", at_outlet);
  CHECK_MSG(inv0 == 0.0 && fabs(inv - inv0 - entered) < 1e-12 * entered, "%.17g against %.17g", inv - inv0, entered);

  /* bad input: a profile leaving [0, phi_max] somewhere along the boundary is named with the point */
  const char *bad[] = {"boundary.left.phi=0.5 + y", NULL};
  sl_diag d = {{0}};
  int rc = run_scene("inflow_channel", NULL, NULL, bad, "inflow_bad.h5", &d);
  CHECK_MSG(rc == 2 && strstr(d.msg, "[boundary.left] phi") && strstr(d.msg, "phi_max"), "rc %d: %s", rc, d.msg);
}

/* Two runs of tests/scenes/rotating_settling.ini: one in the frame's groups
 * through [parameters] (Ro = U / (Omega R) with U = R = 1, an Ekman number,
 * the terminal velocity in U, the density ratio), one with the dimensional
 * numbers the same operations give, printed to 17 digits. */
static void parameters(void) {
  set_configs("tests/scenes");
  const double Ro = 0.7, E = 0.013, Ut = 0.011, eps = 0.5, phi0 = 0.2;
  const char *grouped[] = {"parameters.Ro=0.7",
                           "parameters.E=0.013",
                           "parameters.Ut=0.011",
                           "parameters.eps=0.5",
                           "parameters.phi0=0.2",
                           "parameters.Omega=1/Ro",
                           "flow.rotation=Omega",
                           "fluid.viscosity=E*Omega",
                           "solid.density=1 + eps",
                           "closure.hindered_settling.u_t=Ut",
                           "mixture.reference_acceleration=Omega^2",
                           "flow.rotation_centre=0*Ro, 0",
                           "initial.phi=phi0 + 0*x",
                           "time.end=1",
                           NULL};
  char v[6][80];
  double Omega = 1 / Ro;
  snprintf(v[0], sizeof v[0], "flow.rotation=%.17g", Omega);
  snprintf(v[1], sizeof v[1], "fluid.viscosity=%.17g", E * Omega);
  snprintf(v[2], sizeof v[2], "solid.density=%.17g", 1 + eps);
  snprintf(v[3], sizeof v[3], "closure.hindered_settling.u_t=%.17g", Ut);
  snprintf(v[4], sizeof v[4], "mixture.reference_acceleration=%.17g", pow(Omega, 2));
  snprintf(v[5], sizeof v[5], "initial.phi=%.17g", phi0);
  const char *numbers[] = {v[0], v[1], v[2], v[3], v[4], v[5], "time.end=1", NULL};
  const char *a = "parameters_grouped.h5", *b = "parameters_numbers.h5";
  if (run_ok("rotating_settling", NULL, NULL, grouped, a) || run_ok("rotating_settling", NULL, NULL, numbers, b))
    return;
  sl_output_field fa, fb, ua, ub;
  sl_diag d = {{0}};
  int rc = sl_output_read_field(a, "phi", 1.0, &fa, &d) || sl_output_read_field(b, "phi", 1.0, &fb, &d) ||
           sl_output_read_field(a, "velocity", 1.0, &ua, &d) || sl_output_read_field(b, "velocity", 1.0, &ub, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  int same = fa.n == fb.n && ua.n == ub.n && fabs(fa.time - 1.0) < 1e-12 &&
             memcmp(fa.values, fb.values, (size_t)fa.n * sizeof(double)) == 0 &&
             memcmp(ua.values, ub.values, (size_t)ua.n * ua.components * sizeof(double)) == 0;
  double moved = 0;
  for (int i = 0; i < fa.n; ++i) moved = fmax(moved, fabs(fa.values[i] - phi0));
  printf("parameters: phi and velocity at t = 1 %s; phi moved by up to %.3e\n", same ? "bit for bit equal" : "DIFFER",
         moved);
  CHECK(same);
  CHECK(moved > 1e-4); /* the runs did something */
  sl_output_field_free(&fa), sl_output_field_free(&fb), sl_output_field_free(&ua), sl_output_field_free(&ub);

  /* bad input: a parameter named like a variable, and an unknown name, are located errors */
  const char *bad1[] = {"parameters.x=1", NULL}, *bad2[] = {"flow.rotation=1/Rho", "parameters.Ro=1", NULL};
  rc = run_scene("rotating_settling", NULL, NULL, bad1, "parameters_bad.h5", &d);
  CHECK_MSG(rc == 2 && strstr(d.msg, "[parameters] x"), "rc %d: %s", rc, d.msg);
  rc = run_scene("rotating_settling", NULL, NULL, bad2, "parameters_bad.h5", &d);
  CHECK_MSG(rc == 2 && strstr(d.msg, "Rho") && strstr(d.msg, "Ro"), "rc %d: %s", rc, d.msg);
}

/* ---- the spectrometer on the coarse mesh ---------------------------------------------------------------------- */

/* configs/spectrometer.geo's geometry: the cone's generator (sin g, -cos g), across it (cos g, sin g). */
static const double SP_Q = 0.195, SP_G = M_PI / 4;
#define SP_DELTA (SP_Q / (4 * M_PI))

typedef struct spectro_run {
  double eff;           /* share of the inflow's solids passing the slot: 1 - (inner outlet + inner inventory's
                           growth) / inflow, over the last output interval */
  double eff_inventory; /* outer_down / (inner_down + outer_down) */
  double in_rate;       /* solids per unit time (per radian) through the inner inlet */
  double conservation;  /* |inventory - sum of solids_through| / inflow, largest over the outputs */
  double swirl;         /* min u_theta over the slot's nodes */
  double wall_phi;      /* largest phi in the cells touching the outer channel's outer wall */
  double lost;          /* solids leaving by the inner outlet over t in [0.5, 1], of the solids entering then */
  /* over the windows [t_end - 0.5, t_end] and [t_end - 1, t_end - 0.5] (0.5: at least the inner channel's
   * through-flow time, 0.42; configs/spectrometer_report.py): */
  double e_window;                /* solids leaving by the outer outlet / by both outlets */
  double growth;                  /* the inventory's growth over the last window / the solids entering then */
  double passing, passing_prev;   /* the efficiency: the share of the solids entering that pass to the outer
                                     channel, 1 - (inner outlet + the inner channel's growth) / entering */
} spectro_run;

/* configs/SCENE.ini to t = end on mesh_file (NULL: the coarse mesh of the tests; else a path under the source
 * tree), with [parameters] divert set when divert is not NULL. */
static int spectrometer_run_scene(const char *scene, const char *mesh_file, const char *divert, const char *end,
                                  const char *out, spectro_run *r) {
  char mesh[4400], dv[64], te[64];
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(mesh, sizeof mesh, "mesh.file=%s/%s", src ? src : ".",
           mesh_file ? mesh_file : "tests/scenes/spectrometer_coarse.msh");
  snprintf(dv, sizeof dv, "parameters.divert=%s", divert ? divert : "");
  snprintf(te, sizeof te, "time.end=%s", end);
  const char *sets[] = {mesh, te, divert ? dv : NULL, NULL};
  set_configs("configs");
  if (run_ok(scene, NULL, NULL, sets, out)) return 1;
  sl_output_scalars sc;
  sl_diag d = {{0}};
  if (sl_output_read_scalars(out, &sc, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  int k_inv = -1, k_in = -1, k_io = -1, k_oo = -1, k_oi = -1, k_id = -1, k_od = -1, k_iu = -1, k_is = -1;
  for (int k = 0; k < sc.n_names; ++k) {
    const char *n = sc.names[k];
    if (!strcmp(n, "solids_inventory")) k_inv = k;
    if (!strcmp(n, "solids_through_inner_inlet")) k_in = k;
    if (!strcmp(n, "solids_through_outer_inlet")) k_oi = k;
    if (!strcmp(n, "solids_through_inner_outlet")) k_io = k;
    if (!strcmp(n, "solids_through_outer_outlet")) k_oo = k;
    if (!strcmp(n, "solids_inventory_inner_down")) k_id = k;
    if (!strcmp(n, "solids_inventory_outer_down")) k_od = k;
    if (!strcmp(n, "solids_inventory_inner_up")) k_iu = k;
    if (!strcmp(n, "solids_inventory_inner_slot")) k_is = k;
  }
  int ok = k_inv >= 0 && k_in >= 0 && k_oi >= 0 && k_io >= 0 && k_oo >= 0 && k_id >= 0 && k_od >= 0 && k_iu >= 0 &&
           k_is >= 0 && sc.n_times >= 3;
  CHECK_MSG(ok, "%s: the scalars are missing", out);
  if (!ok) return sl_output_scalars_free(&sc), 1;
#define V(i, k) sc.values[(size_t)(i)*sc.n_names + (k)]
  int a = sc.n_times - 2, b = sc.n_times - 1;
  double dt = sc.times[b] - sc.times[a];
  double din = V(b, k_in) - V(a, k_in), dio = V(b, k_io) - V(a, k_io);
  double dinner = V(b, k_iu) + V(b, k_is) + V(b, k_id) - V(a, k_iu) - V(a, k_is) - V(a, k_id);
  r->in_rate = din / dt;
  r->eff = 1 - (-dio + dinner) / din;
  r->eff_inventory = V(b, k_od) / (V(b, k_id) + V(b, k_od));
  int h = 0; /* the output at t = 0.5 */
  for (int i = 0; i < sc.n_times; ++i)
    if (fabs(sc.times[i] - 0.5) < fabs(sc.times[h] - 0.5)) h = i;
  r->lost = -(V(b, k_io) - V(h, k_io)) / (V(b, k_in) - V(h, k_in));
  r->conservation = 0;
  for (int i = 0; i < sc.n_times; ++i) {
    double through = V(i, k_in) + V(i, k_oi) + V(i, k_io) + V(i, k_oo);
    r->conservation = fmax(r->conservation, fabs(V(i, k_inv) - through) / V(b, k_in));
  }
  int w1 = 0, w2 = 0; /* the outputs at t_end - 0.5 and t_end - 1 */
  for (int i = 0; i < sc.n_times; ++i) {
    if (fabs(sc.times[i] - (sc.times[b] - 0.5)) < fabs(sc.times[w1] - (sc.times[b] - 0.5))) w1 = i;
    if (fabs(sc.times[i] - (sc.times[b] - 1)) < fabs(sc.times[w2] - (sc.times[b] - 1))) w2 = i;
  }
  double o1 = -(V(b, k_oo) - V(w1, k_oo)), i1 = -(V(b, k_io) - V(w1, k_io));
  double i2 = -(V(w1, k_io) - V(w2, k_io)), in1 = V(b, k_in) - V(w1, k_in);
  double inner1 = V(b, k_iu) + V(b, k_is) + V(b, k_id) - V(w1, k_iu) - V(w1, k_is) - V(w1, k_id);
  r->e_window = o1 / (o1 + i1);
  r->growth = (V(b, k_inv) - V(w1, k_inv)) / in1;
  r->passing = 1 - (i1 + inner1) / in1;
  double in2 = V(w1, k_in) - V(w2, k_in);
  double inner2 = V(w1, k_iu) + V(w1, k_is) + V(w1, k_id) - V(w2, k_iu) - V(w2, k_is) - V(w2, k_id);
  r->passing_prev = 1 - (i2 + inner2) / in2;
  double t_end = sc.times[b];
#undef V
  sl_output_scalars_free(&sc);
  /* the swirl in the slot and the sediment on the outer channel's outer wall, at the last output */
  sl_output_mesh m;
  sl_output_field ut, phi;
  if (sl_output_read_mesh(out, &m, &d) || sl_output_read_field(out, "u_theta", t_end, &ut, &d) ||
      sl_output_read_field(out, "phi", t_end, &phi, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  const double s = sin(SP_G), c = cos(SP_G), xi0 = 1 / s, w = SP_DELTA / 2;
  r->swirl = HUGE_VAL, r->wall_phi = 0;
  for (int v = 0; v < m.n_vertices; ++v) {
    double x = m.coords[3 * v], y = m.coords[3 * v + 1], xi = x * s - y * c, n = x * c + y * s;
    if (n > SP_DELTA - 1e-9 && n < SP_DELTA + w + 1e-9 && xi > xi0 + 11 * SP_DELTA - 1e-9 &&
        xi < xi0 + 13 * SP_DELTA + 1e-9)
      r->swirl = fmin(r->swirl, ut.values[v]);
  }
  for (int e = 0; e < m.n_cells; ++e) {
    int on_wall = 0;
    for (int j = 0; j < m.nodes_per_cell; ++j) {
      int v = m.cells[(size_t)e * m.nodes_per_cell + j];
      on_wall |= fabs(m.coords[3 * v] * c + m.coords[3 * v + 1] * s - (3.5 * SP_DELTA)) < 1e-9;
    }
    if (on_wall) r->wall_phi = fmax(r->wall_phi, phi.values[e]);
  }
  sl_output_mesh_free(&m), sl_output_field_free(&ut), sl_output_field_free(&phi);
  return 0;
}

static int spectrometer_run_on(const char *mesh_file, const char *divert, const char *out, spectro_run *r) {
  return spectrometer_run_scene("spectrometer", mesh_file, divert, "1", out, r);
}

static int spectrometer_run(const char *divert, const char *out, spectro_run *r) {
  return spectrometer_run_on(NULL, divert, out, r);
}

/* Greenspan's spectrometer on the coarse mesh to t = 1 (steady from about t = 0.7): the solids balance of the
 * boundaries to round-off, the inflow's solids flux against (4.148) with the particles' slip along the channel,
 * and the thesis's observations: a sediment on the inclined walls, the efficiency raised by diverting 20 % of the
 * inner flux through the slot, a retrograde swirl in the slot (its change with the diversion is printed). */
static void spectrometer(void) {
  spectro_run b, v;
  if (spectrometer_run("0", "spectrometer_base.h5", &b) || spectrometer_run("0.2", "spectrometer_divert.h5", &v))
    return;
  /* the inflow's solids: alpha_in (int U over zeta < h) K delta = alpha0 Q / (2 pi) by eq 4.148, plus the slip
   * along the channel, u_t r sin(g) F(alpha_in) over the inlet's part zeta < h, r = 1 + delta zeta cos(g) */
  const double alpha_in = 0.038411435, ut = 0.27, s = sin(SP_G), c = cos(SP_G), h = -1.0 / 3;
  double f = pow(1 - alpha_in, 2) * pow(1 - alpha_in / 0.68, 2.5 * 0.68);
  double r2 = 0; /* int_{-1}^{h} r^2 delta dzeta */
  for (int i = 0; i < 2000; ++i) {
    double z = -1 + (h + 1) * (i + 0.5) / 2000, r = 1 + SP_DELTA * z * c;
    r2 += r * r * SP_DELTA * (h + 1) / 2000;
  }
  double expect = 0.01 * SP_Q / (2 * M_PI) + ut * s * alpha_in * f * r2;
  printf(
      "spectrometer (coarse, t = 1): solids in %.5e per unit time (4.148 with the slip: %.5e, %.2f %%); balance "
      "of the boundaries %.1e\n",
      b.in_rate, expect, 100 * (b.in_rate / expect - 1), b.conservation);
  printf(
      "  efficiency (passing the slot) %.1f %% -> %.1f %% diverted (thesis 75-80 -> 90-95); from the inventories "
      "downstream of the slot %.1f %% -> %.1f %%\n",
      100 * b.eff, 100 * v.eff, 100 * b.eff_inventory, 100 * v.eff_inventory);
  printf(
      "  most retrograde u_theta in the slot %.3f -> %.3f diverted (thesis -1.16 -> -1.06); largest phi on the "
      "outer channel's outer wall %.3f (inflow %.4f)\n",
      b.swirl, v.swirl, b.wall_phi, alpha_in);
  CHECK_MSG(b.conservation < 1e-12 && v.conservation < 1e-12, "%g %g", b.conservation, v.conservation);
  CHECK_MSG(fabs(b.in_rate / expect - 1) < 0.01, "%g against %g", b.in_rate, expect);
  CHECK_MSG(b.wall_phi > 1.5 * alpha_in, "no sediment: %g", b.wall_phi);
  CHECK_MSG(v.eff > b.eff, "diverting does not raise the efficiency: %g -> %g", b.eff, v.eff);
  /* retrograde in both; the thesis found it weaker with the diversion (-1.16 -> -1.06), this geometry stronger
   * (docs/rotating.md): the direction is reported, not asserted */
  CHECK_MSG(b.swirl < -0.1 && v.swirl < -0.1, "swirl %g -> %g", b.swirl, v.swirl);
}

/* The design (Nigam 1999, section 4.3, Fig. 4-18): T/Q is chosen so that the kinematic shock leaving the inner
 * channel's inner wall, the last particles, meets the outer wall at the slot's trailing edge; in the design's
 * kinematics (4.150) every particle reaches the slot and none leaves by the inner outlet. The loss by the inner
 * outlet over t in [0.5, 1], on the coarse mesh (6 cells across a channel) and the scene's (12 across), falls
 * toward that: by more than half (measured 26.5 % -> 8.1 %; 2.0 % on 24 across, docs/rotating.md). */
static void spectrometer_mesh(void) {
  spectro_run c6, c12;
  if (spectrometer_run("0", "spectrometer_mesh6.h5", &c6) ||
      spectrometer_run_on("configs/spectrometer.msh", "0", "spectrometer_mesh12.h5", &c12))
    return;
  printf(
      "spectrometer, t = 0.5-1: lost by the inner outlet %.1f %% (6 across), %.1f %% (12 across); the thesis's "
      "inventory measure at t = 1 %.1f %%, %.1f %%; balance %.1e, %.1e\n",
      100 * c6.lost, 100 * c12.lost, 100 * c6.eff_inventory, 100 * c12.eff_inventory, c6.conservation,
      c12.conservation);
  CHECK_MSG(c12.lost < 0.5 * c6.lost && c12.lost > 0, "lost %.4f (6 across), %.4f (12 across)", c6.lost, c12.lost);
  CHECK_MSG(c12.eff_inventory > c6.eff_inventory, "%.4f -> %.4f", c6.eff_inventory, c12.eff_inventory);
  CHECK_MSG(c12.conservation < 1e-12, "%g", c12.conservation);
}

/* The steady efficiency (Nigam 1999, section 4.3: "the steady share of particles passing to the outer channel"),
 * configs/spectrometer.ini and configs/spectrometer_diverted.ini (20 % of the inner channel's flux through the
 * slot) on the coarse mesh to t = 2.5. The efficiency P is the share of the solids entering over the window
 * [2, 2.5] (at least the inner channel's through-flow time, 0.42) that do not leave by the inner outlet nor stay
 * in the inner channel. Steady: P differs from the window before by less than 1e-3, and the whole inventory
 * grows by less than 1e-3 of the solids entering. Then the solids balance makes P the share E of the solids
 * leaving that leave by the outer outlet too (to 1e-3). The diversion raises P and at least halves the loss
 * (measured 72.4 % -> 92.5 %, the thesis 75-80 % -> 90-95 %); a sediment is on
 * the outer channel's outer wall in both runs; the slot's swirl is retrograde in both. The thesis found it weaker
 * with the diversion (lowest contour -1.16 -> -1.06). Here it is stronger, by what the Coriolis force on the
 * outward through-flow gives (docs/rotating.md, "The swirl in the slot"): in the rotating frame the azimuthal
 * momentum balance across the slot, nu v'' = 2 Omega u_r, with the through-flow u_r = cos(g) u_n and u_n the plane
 * Poiseuille profile (3/2) u_s (1 - s^2/b^2) over the slot's half-width b (the azimuthal component of Nigam 1999
 * eq 4.151, (2/Ro) u_r = (1/Re) v'', steady, dilute, advection neglected), v(+-b) = 0, gives at the slot's centre
 *   dv = -(5/4) (Omega cos(g) b^2/nu) u_s,
 * with u_s = divert Q/(2 pi) over the slot's area per radian, int r dxi on its mid-line. The diversion must make the
 * most retrograde value more retrograde by this to a factor 2 (measured -0.102 against -0.093 here). */
static void spectrometer_steady(void) {
  spectro_run b, v;
  if (spectrometer_run_scene("spectrometer", NULL, NULL, "2.5", "spectrometer_steady_base.h5", &b) ||
      spectrometer_run_scene("spectrometer_diverted", NULL, NULL, "2.5", "spectrometer_steady_divert.h5", &v))
    return;
  const double alpha_in = 0.038411435;
  const spectro_run *r[2] = {&b, &v};
  for (int k = 0; k < 2; ++k)
    printf(
        "spectrometer %s (coarse, t = 2.5): P = passing the slot %.3f %% (window before %.3f %%), E = outer outlet "
        "/ both %.3f %%, inventory growth %.1e of the inflow; thesis's inventory measure %.1f %%; swirl in the slot "
        "%.3f; phi on the outer wall %.3f; balance %.1e\n",
        k ? "diverted" : "base", 100 * r[k]->passing, 100 * r[k]->passing_prev, 100 * r[k]->e_window, r[k]->growth,
        100 * r[k]->eff_inventory, r[k]->swirl, r[k]->wall_phi, r[k]->conservation);
  printf("  steady efficiency %.1f %% -> %.1f %% diverted (thesis 75-80 -> 90-95); swirl %.3f -> %.3f (%s)\n",
         100 * b.passing, 100 * v.passing, b.swirl, v.swirl, v.swirl > b.swirl ? "weaker" : "stronger");
  for (int k = 0; k < 2; ++k) {
    CHECK_MSG(fabs(r[k]->passing - r[k]->passing_prev) < 1e-3, "not steady: P %.5f after %.5f", r[k]->passing,
              r[k]->passing_prev);
    CHECK_MSG(fabs(r[k]->growth) < 1e-3, "not steady: the inventory grows by %.2e of the inflow", r[k]->growth);
    CHECK_MSG(fabs(r[k]->passing - r[k]->e_window) < 1e-3, "passing %.5f against E %.5f", r[k]->passing,
              r[k]->e_window);
    CHECK_MSG(r[k]->conservation < 1e-12, "%g", r[k]->conservation);
    CHECK_MSG(r[k]->wall_phi > 1.5 * alpha_in, "no sediment: %g", r[k]->wall_phi);
    CHECK_MSG(r[k]->swirl < -0.1, "no retrograde swirl in the slot: %g", r[k]->swirl);
  }
  CHECK_MSG(v.passing > b.passing, "diverting does not raise the efficiency: %g -> %g", b.passing, v.passing);
  CHECK_MSG(1 - v.passing < 0.5 * (1 - b.passing), "the loss %.4f -> %.4f", 1 - b.passing, 1 - v.passing);
  /* the swirl's change against the Coriolis estimate above (configs/spectrometer.geo: the slot xi0 + [11, 13]
   * delta, b = delta; its mid-line n = 1.25 delta; Omega = 1/Ro, nu = 1/Re) */
  const double s = sin(SP_G), c = cos(SP_G), xa = 1 / s + 11 * SP_DELTA, xb = 1 / s + 13 * SP_DELTA;
  const double area = s * (xb * xb - xa * xa) / 2 + 1.25 * SP_DELTA * c * (xb - xa);
  const double u_s = 0.2 * SP_Q / (2 * M_PI) / area, dv = -1.25 * (1 / 4.22e-4) * c * SP_DELTA * SP_DELTA * 1.06 * u_s;
  printf(
      "  swirl change %.4f with the diversion, the Coriolis force on the through-flow u_s = %.4f: %.4f (ratio %.2f)\n",
      v.swirl - b.swirl, u_s, dv, (v.swirl - b.swirl) / dv);
  CHECK_MSG((v.swirl - b.swirl) / dv > 0.5 && (v.swirl - b.swirl) / dv < 2, "swirl change %.4f against %.4f",
            v.swirl - b.swirl, dv);
}

int main(int argc, char **argv) {
  static const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"inflow", inflow},
               {"parameters", parameters},
               {"spectrometer", spectrometer},
               {"spectrometer_mesh", spectrometer_mesh},
               {"spectrometer_steady", spectrometer_steady}};
  int ran = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 || strcmp(argv[1], parts[k].name) == 0) parts[k].run(), ++ran;
  if (!ran)
    return fprintf(stderr, "unknown part '%s' (inflow, parameters, spectrometer, spectrometer_mesh, spectrometer_steady)\n", argv[1]), 2;
  return sl_test_summary();
}
