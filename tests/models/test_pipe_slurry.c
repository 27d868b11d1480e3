/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid pipe (core/models/pipe) with solids, on configs/vertical_pipe.ini
 * (Krampa 2009, Chapter 3 experiments: 0.5 mm glass beads, 25 %, V = 3.02 m/s):
 *  - what the discrete equations hold exactly: the bulk velocity, the solids
 *    inventory, and the mixture's momentum, -dP/dz = 4 (tau_fw + tau_sw)/D -
 *    rho_m g_z (Krampa 2009 eq 2.1; the faces' stresses telescope, the drag
 *    cancels), in up-flow and down-flow;
 *  - without a radial force on the solids (no kinetic theory, no solids
 *    pressure) turbulent dispersion alone leaves phi uniform, exactly;
 *  - then, with uniform phi and the solids' eddy viscosity rho_s nu_t
 *    (sigma = 1), u_s = u_f - s with a uniform slip solves both momentum
 *    equations away from the wall (the molecular viscosity aside): the drag
 *    carries the particles' excess weight in the pressure gradient,
 *      K s = -c_s (rho_s - rho_f) G / rho_f / (1 + c_s rho_s/(c_f rho_f)),
 *    checked at the axis with Stokes drag (K = 18 mu phi/d^2) within 1 %;
 *  - with the kinetic theory's pressure (Lun et al. 1984; kinetic_pressure =
 *    true), the granular temperature is highest at the wall and its pressure
 *    drives solids from the wall: phi at the wall below the mean; with
 *    Simonin's dispersivity (t_fs k_fs/3: the crossing trajectories shorten
 *    t_fs and the particles' inertia lowers k_fs below 2k, so D_fs < nu_t for
 *    0.5 mm beads) the depletion is deeper; [closure.turbulent_dispersion] model = gradient at Schmidt number 1
 *    is the scene without the section bit for bit, and at 0.5 it holds more solids at the wall;
 *  - no-slip solids without the kinetic theory: the solids' eddy viscosity
 *    is bridged across the wall cell by the fluid's wall function, so
 *    tau_sw/tau_fw = (c_s rho_s/(sigma rho_f)) u_s/u_f of the wall cell, to
 *    the steady solve's tolerance (1e-8);
 *  - the L-probe (Krampa 2009 section 3.4): the mean solids velocity at V = 4 m/s
 *    within 10 % of 3.91 m/s, the slip at the axis the Ergun uniform-slip solution; at V = 2 m/s every
 *    closure that could move the slip keeps the mean within 2.5 % (the miss is the V term), and the
 *    model gives 1.55 m/s at V = 1.58;
 *  - stability: 2.4 mm sand at 30 % (up-flow at 3.02 m/s, down-flow at 1
 *    m/s) and 0.5 mm beads at phi_max - 0.01 = 0.62 (up at 2 m/s, down at 1
 *    m/s) converge, with a finite state and the mixture's momentum held;
 *    and, with the kinetic pressure, converge or stop naming the field and radius;
 *  - the transported granular temperature with the kinetic pressure: converged where the local balance is
 *    not, momentum and inventory held, the wall depleted, second order in the radial cells;
 *  - Simonin's modulation (model C's fluid side) lowers k in every cell, and the fluid's wall stress;
 *  - a solids fraction above phi_max - 0.01 is refused before the run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "pipe_testing.h"
#include "sluice/sluice.h"
#include "testing.h"

static char scene[8192];

static int load_scene(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/configs/vertical_pipe.ini", src ? src : ".");
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(scene, 1, sizeof scene - 1, f) : 0;
  if (f) fclose(f);
  scene[n] = '\0';
  CHECK_MSG(n > 0, "cannot read %s", path);
  return n > 0 ? 0 : 1;
}

/* The scene with one section's text replaced (NULL: as it is). */
static int run(const char *section, const char *replacement, const char *const *sets, const char *out,
               sluice_error *e) {
  static char text[16384];
  if (section) {
    char head[64];
    snprintf(head, sizeof head, "[%s]", section);
    char *a = strstr(scene, head), *b = a ? strstr(a + 1, "\n[") : NULL;
    if (!a) return snprintf(e->msg, sizeof e->msg, "no %s", head), 2;
    snprintf(text, sizeof text, "%.*s%s%s", (int)(a - scene), scene, replacement, b ? b : "");
  } else {
    snprintf(text, sizeof text, "%s", scene);
  }
  sluice *s = NULL;
  sluice_open_opts oo = {.sets = sets};
  sluice_run_opts ro = {.output = out, .version = "test"};
  sluice_summary sum;
  int rc = sluice_open_text(text, strlen(text), "vertical_pipe.ini", &oo, &s, e);
  if (!rc) rc = sluice_run(s, &ro, &sum, e);
  sluice_close(s);
  return rc;
}

static const double D = 0.0532, rho_f = 997.56, rho_s = 2500.0, g = 9.81;

static void balances(void) {
  const char *dirs[2] = {"flow.gravity=-9.81", "flow.gravity=9.81"};
  for (int k = 0; k < 2; ++k) {
    const char *sets[] = {dirs[k], NULL};
    sluice_error e = {0, ""};
    if (run(NULL, NULL, sets, "pipe_slurry.h5", &e)) {
      CHECK_MSG(0, "%s: %s", dirs[k], e.msg);
      continue;
    }
    double gz = k ? g : -g, phi = pipe_scalar("pipe_slurry.h5", "phi_mean"), rho_m = phi * rho_s + (1.0 - phi) * rho_f;
    double tau = pipe_scalar("pipe_slurry.h5", "wall_shear_stress_fluid") +
                 pipe_scalar("pipe_slurry.h5", "wall_shear_stress_solid");
    double dp = pipe_scalar("pipe_slurry.h5", "pressure_gradient"), bal = 4.0 * tau / D - rho_m * gz;
    profile pf, ps, pp;
    if (read_profile("pipe_slurry.h5", "velocity_fluid", &pf) ||
        read_profile("pipe_slurry.h5", "velocity_solid", &ps) || read_profile("pipe_slurry.h5", "phi", &pp))
      continue;
    /* the bulk velocity over the cells' areas r dr */
    double q = 0.0, A = 0.0;
    for (int i = 0; i < pf.n; ++i) {
      double w = 0.5 * (pf.hi[i] * pf.hi[i] - pf.lo[i] * pf.lo[i]);
      q += w * ((1.0 - pp.v[i]) * pf.v[i] + pp.v[i] * ps.v[i]), A += w;
    }
    printf("%s: -dP/dz %.4f Pa/m, 4 tau_w/D - rho_m g_z %.4f (%.2e), V %.9f, phi_mean %.12f, manometric %.2f\n",
           k ? "down-flow" : "up-flow", dp, bal, dp / bal - 1.0, q / A, phi,
           pipe_scalar("pipe_slurry.h5", "manometric_gradient"));
    CHECK_MSG(fabs(dp / bal - 1.0) < 1e-6, "the mixture momentum: %.9g against %.9g", dp, bal);
    CHECK_MSG(fabs(q / A - 3.02) < 1e-6, "the bulk velocity %.9g", q / A);
    CHECK_MSG(fabs(phi - 0.25) < 1e-12, "the solids inventory %.15g", phi);
  }
}

static void dispersion_alone(void) {
  /* Stokes drag, 0.1 mm: no kinetic theory, so no radial force on the solids */
  const char *sets[] = {"solid.diameter=1e-4", "closure.drag.model=stokes", NULL};
  sluice_error e = {0, ""};
  if (run("closure.granular", "", sets, "pipe_disp.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  profile pf, ps, pp;
  if (read_profile("pipe_disp.h5", "phi", &pp) || read_profile("pipe_disp.h5", "velocity_fluid", &pf) ||
      read_profile("pipe_disp.h5", "velocity_solid", &ps))
    return;
  double dev = 0.0;
  for (int i = 0; i < pp.n; ++i) dev = fmax(dev, fabs(pp.v[i] - 0.25));
  double G = -pipe_scalar("pipe_disp.h5", "pressure_gradient"), cs = 0.25, cf = 0.75, mu = 0.9347e-3, d = 1e-4;
  double K = 18.0 * mu * cs / (d * d), s = -cs * (rho_s - rho_f) * G / rho_f / (1.0 + cs * rho_s / (cf * rho_f)) / K;
  double s_axis = pf.v[0] - ps.v[0];
  printf(
      "dispersion alone: max |phi - 0.25| = %.2e; slip at the axis %.6f m/s, uniform-slip solution %.6f (%+.3f %%)\n",
      dev, s_axis, s, 100.0 * (s_axis / s - 1.0));
  CHECK_MSG(dev < 1e-12, "phi is not uniform: %.3e", dev);
  CHECK_MSG(fabs(s_axis / s - 1.0) < 0.01, "slip %.6g against %.6g", s_axis, s);
}

static void kinetic_theory(void) {
  const char *sets[] = {"pipe.kinetic_pressure=true", NULL};
  sluice_error e = {0, ""};
  if (run(NULL, NULL, sets, "pipe_kt.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  profile pp, pt;
  if (read_profile("pipe_kt.h5", "phi", &pp) || read_profile("pipe_kt.h5", "theta", &pt)) return;
  int n = pp.n;
  printf("kinetic theory: phi axis %.4f, wall cell %.4f; theta axis %.3e, wall cell %.3e m^2/s^2\n", pp.v[0],
         pp.v[n - 1], pt.v[0], pt.v[n - 1]);
  CHECK_MSG(pt.v[n - 1] > 10.0 * pt.v[0], "theta is not highest at the wall");
  CHECK_MSG(pp.v[n - 1] < 0.25 && pp.v[0] > 0.25, "the solids are not driven from the wall");
  const char *sim[] = {"pipe.kinetic_pressure=true", "closure.turbulent_dispersion.model=simonin", NULL};
  profile ps;
  if (run(NULL, NULL, sim, "pipe_kt_simonin.h5", &e) || read_profile("pipe_kt_simonin.h5", "phi", &ps)) {
    CHECK_MSG(0, "simonin: %s", e.msg);
    return;
  }
  printf("with Simonin's dispersivity: phi axis %.4f, wall cell %.4f\n", ps.v[0], ps.v[n - 1]);
  CHECK_MSG(ps.v[n - 1] < pp.v[n - 1], "Simonin's dispersion: phi at the wall %.4f, gradient form %.4f", ps.v[n - 1],
            pp.v[n - 1]);
  /* [closure.turbulent_dispersion] model = gradient at its default Schmidt number 1 is the scene without the
     section, bit for bit; at 0.5 the dispersion doubles and holds more solids at the wall against the kinetic
     pressure */
  const char *g1[] = {"pipe.kinetic_pressure=true", "closure.turbulent_dispersion.model=gradient", NULL};
  const char *g05[] = {"pipe.kinetic_pressure=true", "closure.turbulent_dispersion.model=gradient",
                       "closure.turbulent_dispersion.schmidt=0.5", NULL};
  profile pg, ph;
  if (run(NULL, NULL, g1, "pipe_kt_gradient.h5", &e) || read_profile("pipe_kt_gradient.h5", "phi", &pg) ||
      run(NULL, NULL, g05, "pipe_kt_gradient05.h5", &e) || read_profile("pipe_kt_gradient05.h5", "phi", &ph)) {
    CHECK_MSG(0, "gradient: %s", e.msg);
    return;
  }
  int same = pg.n == n;
  for (int i = 0; i < n && same; ++i) same = pg.v[i] == pp.v[i];
  printf("gradient dispersion: Schmidt 1 the default bit for bit: %s; Schmidt 0.5: phi wall cell %.4f (1: %.4f)\n",
         same ? "yes" : "no", ph.v[n - 1], pp.v[n - 1]);
  CHECK_MSG(same, "model = gradient with schmidt = 1 is not the scene without [closure.turbulent_dispersion]");
  CHECK_MSG(ph.v[n - 1] > pp.v[n - 1], "Schmidt 0.5: phi at the wall %.4f, at 1 %.4f", ph.v[n - 1], pp.v[n - 1]);
}

static void no_slip_bridge(void) {
  const char *sets[] = {"pipe.solids_wall=no_slip", NULL};
  sluice_error e = {0, ""};
  if (run("closure.granular", "", sets, "pipe_ns.h5", &e)) {
    CHECK_MSG(0, "%s", e.msg);
    return;
  }
  profile pf, ps, pp;
  if (read_profile("pipe_ns.h5", "velocity_fluid", &pf) || read_profile("pipe_ns.h5", "velocity_solid", &ps) ||
      read_profile("pipe_ns.h5", "phi", &pp))
    return;
  int w = pf.n - 1;
  double tf = pipe_scalar("pipe_ns.h5", "wall_shear_stress_fluid"),
         ts = pipe_scalar("pipe_ns.h5", "wall_shear_stress_solid");
  double ratio = pp.v[w] * rho_s / rho_f * ps.v[w] / pf.v[w];
  printf("no-slip solids: tau_fw %.4f Pa, tau_sw %.4f Pa, ratio %.6f against (c_s rho_s/rho_f) u_s/u_f %.6f\n", tf, ts,
         ts / tf, ratio);
  CHECK_MSG(fabs(ts / tf / ratio - 1.0) < 1e-7, "tau_sw/tau_fw %.9g against %.9g", ts / tf, ratio);
}

/* Krampa (2009) section 3.4, the L-probe (0.5 mm beads, 25 %, up-flow): the mean solids velocity of the measured
   profiles, U_us = 1.55 m/s at V = 2 m/s and 3.91 m/s at V = 4 m/s; the target is 10 %. The model's area mean of
   u_s(r) (as the profile's mean) meets it at 4 m/s and misses it at 2 m/s: with phi uniform (kinetic_pressure =
   false) the slip is uniform away from the wall and equals the uniform-slip solution with the Ergun branch of the
   drag (c_f = 0.75 < 0.8), K(s) s = -c_s c_f (rho_s - rho_f) G/(c_s rho_s + c_f rho_f), K = 150 c_s^2 mu/(c_f d^2)
   + 1.75 c_s rho_f s/d: a quadratic in s, solved here, checked at the axis. So u_s,mean = V - c_f s (the wall
   layer, where the free-slip solids outrun the fluid, lowers the mean slip by 12-15 %), and the
   probe's 1.55 m/s would need a mean slip (V - U_us)/c_f = 0.6 m/s, a drag on the beads many times their
   buoyant weight (printed); the pressure data of Table C.2 (C_est 0.251 at 1.99 m/s, eq 3.11) do not show the
   hold-up such a slip would give (0.25 V/U_us = 0.32). */
static void lprobe(void) {
  static const double V[2] = {2.0, 4.0}, target[2] = {1.55, 3.91};
  const double cs = 0.25, cf = 0.75, mu = 0.9347e-3, d = 5e-4;
  for (int k = 0; k < 2; ++k) {
    char sv[64];
    snprintf(sv, sizeof sv, "pipe.bulk_velocity=%g", V[k]);
    const char *sets[] = {sv, "flow.gravity=-9.81", NULL};
    sluice_error e = {0, ""};
    if (run(NULL, NULL, sets, "pipe_lprobe.h5", &e)) {
      CHECK_MSG(0, "V = %g: %s", V[k], e.msg);
      continue;
    }
    profile pf, ps;
    if (read_profile("pipe_lprobe.h5", "velocity_fluid", &pf) || read_profile("pipe_lprobe.h5", "velocity_solid", &ps))
      continue;
    double s_axis = pf.v[0] - ps.v[0];
    double us = pipe_scalar("pipe_lprobe.h5", "velocity_solid_area_mean");
    double uf = pipe_scalar("pipe_lprobe.h5", "velocity_fluid_area_mean");
    double G = -pipe_scalar("pipe_lprobe.h5", "pressure_gradient");
    double F = -cs * cf * (rho_s - rho_f) * G / (cs * rho_s + cf * rho_f);
    double a = 1.75 * cs * rho_f / d, b = 150.0 * cs * cs * mu / (cf * d * d);
    double s = (-b + sqrt(b * b + 4.0 * a * F)) / (2.0 * a), s_probe = (V[k] - target[k]) / cf;
    double F_probe = (a * s_probe + b) * s_probe;
    printf(
        "L-probe V = %g m/s: mean u_s %.4f m/s against %.2f measured (%+.1f %%); slip at the axis %.5f m/s, "
        "uniform-slip solution %.5f (%+.2f %%), mean slip %.5f; the measured mean needs slip %.3f m/s, drag %.1f "
        "times the model's\n",
        V[k], us, target[k], 100.0 * (us / target[k] - 1.0), s_axis, s, 100.0 * (s_axis / s - 1.0), uf - us, s_probe,
        F_probe / F);
    /* the bulk velocity from the two means: c_f uf + c_s us = V with phi uniform */
    CHECK_MSG(fabs(cf * uf + cs * us - V[k]) < 1e-9, "V = %g: c_f uf + c_s us = %.12g", V[k], cf * uf + cs * us);
    CHECK_MSG(fabs(s_axis / s - 1.0) < 0.01, "V = %g: slip at the axis %.6g against %.6g", V[k], s_axis, s);
    if (k == 1) CHECK_MSG(fabs(us / target[k] - 1.0) < 0.10, "V = 4: u_s %.4g against 3.91 (10 %%)", us);
    if (k == 0) CHECK_MSG(us / target[k] - 1.0 > 0.2, "V = 2: u_s %.4g, the model's miss changed", us);
  }
}

/* Why V = 2 misses (issue 21, measured): with phi held, the continuity of the mixture makes the section-mean solids
   velocity V - c_f <slip>, and the slip term is set by the drag against the beads' buoyant weight. Every closure
   that could change the slip or the profile: the drag law (Wen-Yu, Di Felice, Syamlal-O'Brien for Gidaspow's
   Ergun branch), the kinetic pressure with the transported theta (model B in full), Simonin's dispersion,
   Simonin's modulation (model C's fluid side), no-slip solids. Asserted: each gives the mean within 2.5 % of
   the scene's (measured -1.6 to +0.6 %), so each misses 1.55 by more than +20 %: the miss is the V term, not a
   closure's. And the model gives 1.55 m/s at V = 1.58 m/s (within 1 %; measured +0.3 %): the probe's profile
   is what the model gives some 20 % below the stated V (the thesis's captions disagree on it, digest
   erratum 15). */
static void lprobe_terms(void) {
  static const char *const variants[][3] = {{"closure.drag.model=wen_yu", NULL, NULL},
                                            {"closure.drag.model=di_felice", NULL, NULL},
                                            {"closure.drag.model=syamlal_obrien", NULL, NULL},
                                            {"pipe.kinetic_pressure=true", "pipe.granular_temperature=transport", NULL},
                                            {"closure.turbulent_dispersion.model=simonin", NULL, NULL},
                                            {"closure.turbulence_modulation.model=simonin", NULL, NULL},
                                            {"pipe.solids_wall=no_slip", NULL, NULL}};
  const char *base_sets[] = {"pipe.bulk_velocity=2", "flow.gravity=-9.81", NULL};
  sluice_error e = {0, ""};
  if (run(NULL, NULL, base_sets, "pipe_lprobe_terms.h5", &e)) {
    CHECK_MSG(0, "V = 2: %s", e.msg);
    return;
  }
  double base = pipe_scalar("pipe_lprobe_terms.h5", "velocity_solid_area_mean");
  double uf = pipe_scalar("pipe_lprobe_terms.h5", "velocity_fluid_area_mean");
  printf("L-probe V = 2: mean u_s %.4f m/s = V - c_f <slip>, c_f <slip> = %.4f m/s; the probe's 1.55 needs %.3f\n",
         base, 2.0 - base, 2.0 - 1.55);
  CHECK_MSG(fabs(0.75 * uf + 0.25 * base - 2.0) < 1e-9, "c_f uf + c_s us = %.12g", 0.75 * uf + 0.25 * base);
  for (size_t k = 0; k < sizeof variants / sizeof variants[0]; ++k) {
    const char *sets[6] = {"pipe.bulk_velocity=2", "flow.gravity=-9.81", variants[k][0], variants[k][1], NULL};
    if (run(NULL, NULL, sets, "pipe_lprobe_terms.h5", &e)) {
      CHECK_MSG(0, "V = 2, %s: %s", variants[k][0], e.msg);
      continue;
    }
    double us = pipe_scalar("pipe_lprobe_terms.h5", "velocity_solid_area_mean");
    printf("  %s%s%s: mean u_s %.4f m/s (%+.2f %% of the scene's, %+.1f %% of 1.55)\n", variants[k][0],
           variants[k][1] ? ", " : "", variants[k][1] ? variants[k][1] : "", us, 100.0 * (us / base - 1.0),
           100.0 * (us / 1.55 - 1.0));
    CHECK_MSG(fabs(us / base - 1.0) < 0.025, "%s: mean u_s %.4f against the scene's %.4f", variants[k][0], us, base);
  }
  const char *low[] = {"pipe.bulk_velocity=1.58", "flow.gravity=-9.81", NULL};
  if (run(NULL, NULL, low, "pipe_lprobe_terms.h5", &e)) {
    CHECK_MSG(0, "V = 1.58: %s", e.msg);
    return;
  }
  double us = pipe_scalar("pipe_lprobe_terms.h5", "velocity_solid_area_mean");
  printf("  V = 1.58 m/s: mean u_s %.4f m/s (%+.2f %% of 1.55)\n", us, 100.0 * (us / 1.55 - 1.0));
  CHECK_MSG(fabs(us / 1.55 - 1.0) < 0.01, "V = 1.58: mean u_s %.4f against 1.55", us);
}

static void stability(void) {
  static const struct {
    const char *name, *sets[6];
    double gz, rho_s;
  } cases[4] = {
      {"2.4 mm sand, 30 %, up, 3.02 m/s",
       {"solid.diameter=2.4e-3", "solid.density=2650", "pipe.solids_fraction=0.3", "flow.gravity=-9.81", NULL},
       -9.81,
       2650.0},
      {"2.4 mm sand, 30 %, down, 1 m/s",
       {"solid.diameter=2.4e-3", "solid.density=2650", "pipe.solids_fraction=0.3", "flow.gravity=9.81",
        "pipe.bulk_velocity=1", NULL},
       9.81,
       2650.0},
      {"0.5 mm, 62 %, up, 2 m/s",
       {"pipe.solids_fraction=0.62", "pipe.bulk_velocity=2", "flow.gravity=-9.81", NULL},
       -9.81,
       2500.0},
      {"0.5 mm, 62 %, down, 1 m/s",
       {"pipe.solids_fraction=0.62", "pipe.bulk_velocity=1", "flow.gravity=9.81", NULL},
       9.81,
       2500.0}};
  for (int k = 0; k < 4; ++k) {
    sluice_error e = {0, ""};
    if (run(NULL, NULL, cases[k].sets, "pipe_stab.h5", &e)) {
      CHECK_MSG(0, "%s: %s", cases[k].name, e.msg);
      continue;
    }
    double it = pipe_scalar("pipe_stab.h5", "iterations"), dp = pipe_scalar("pipe_stab.h5", "pressure_gradient");
    double phi = pipe_scalar("pipe_stab.h5", "phi_mean"), rho_m = phi * cases[k].rho_s + (1.0 - phi) * rho_f;
    double tau =
        pipe_scalar("pipe_stab.h5", "wall_shear_stress_fluid") + pipe_scalar("pipe_stab.h5", "wall_shear_stress_solid");
    double bal = 4.0 * tau / D - rho_m * cases[k].gz;
    printf("%s: converged in %.0f iterations, -dP/dz %.2f Pa/m (balance %.1e)\n", cases[k].name, it, dp,
           dp / bal - 1.0);
    CHECK_MSG(isfinite(dp) && fabs(dp / bal - 1.0) < 1e-6, "%s: -dP/dz %g against %g", cases[k].name, dp, bal);
  }
}

/* The stability cases with the kinetic theory's pressure in the radial balance (kinetic_pressure = true, Krampa's
   model B in full): each converges or stops with a named reason ("not converged", the field and the radius of the
   largest change), and the state it saves is finite. At 45 % (0.5 mm, up-flow, 5 m/s) it stops: the granular
   temperature's local balance makes p_s fall with phi in the wall layer (docs/pipe.md); with the transported
   theta every case converges, that one too. */
static void stability_kinetic(void) {
  static const struct {
    const char *name, *sets[7];
    int converges;
  } cases[5] = {
      {"2.4 mm sand, 30 %, up, 3.02 m/s",
       {"solid.diameter=2.4e-3", "solid.density=2650", "pipe.solids_fraction=0.3", "flow.gravity=-9.81",
        "pipe.kinetic_pressure=true", NULL},
       1},
      {"2.4 mm sand, 30 %, down, 1 m/s",
       {"solid.diameter=2.4e-3", "solid.density=2650", "pipe.solids_fraction=0.3", "flow.gravity=9.81",
        "pipe.bulk_velocity=1", "pipe.kinetic_pressure=true", NULL},
       1},
      {"0.5 mm, 62 %, up, 2 m/s",
       {"pipe.solids_fraction=0.62", "pipe.bulk_velocity=2", "flow.gravity=-9.81", "pipe.kinetic_pressure=true", NULL},
       1},
      {"0.5 mm, 62 %, down, 1 m/s",
       {"pipe.solids_fraction=0.62", "pipe.bulk_velocity=1", "flow.gravity=9.81", "pipe.kinetic_pressure=true", NULL},
       1},
      {"0.5 mm, 45 %, up, 5 m/s",
       {"pipe.solids_fraction=0.45", "pipe.bulk_velocity=5", "flow.gravity=-9.81", "pipe.kinetic_pressure=true",
        "pipe.iterations=1000", NULL},
       0}};
  for (int q = 0; q < 10; ++q) {
    /* q < 5: theta of its local balance; q >= 5: transported (every case converges, the 45 % one too) */
    const int k = q % 5, transport = q >= 5;
    const char *sets[9];
    int ns = 0;
    for (; cases[k].sets[ns]; ++ns) sets[ns] = cases[k].sets[ns];
    if (transport) sets[ns++] = "pipe.granular_temperature=transport";
    sets[ns] = NULL;
    sluice_error e = {0, ""};
    int rc = run(NULL, NULL, sets, "pipe_stab_kt.h5", &e);
    profile pp, pt;
    int finite = !read_profile("pipe_stab_kt.h5", "phi", &pp) && !read_profile("pipe_stab_kt.h5", "theta", &pt);
    for (int i = 0; finite && i < pp.n; ++i) finite = isfinite(pp.v[i]) && isfinite(pt.v[i]);
    printf("kinetic pressure, theta %s, %s: %s\n", transport ? "transported" : "local", cases[k].name,
           rc ? e.msg : "converged");
    CHECK_MSG(finite, "%s: the saved state is not finite", cases[k].name);
    if (cases[k].converges || transport) CHECK_MSG(rc == 0, "%s: %s", cases[k].name, e.msg);
    else
      CHECK_MSG(rc != 0 && strstr(e.msg, "not converged") && strstr(e.msg, "most in ") && strstr(e.msg, "at r/R = "),
                "%s: rc %d, %s", cases[k].name, rc, e.msg);
  }
}

/* The transported granular temperature (granular_temperature = transport) with the kinetic pressure: the cases
   where the local balance does not converge (dilute, or fast: its theta ~ 1/phi^2 makes p_s fall with phi in the
   wall layer) converge, hold the mixture's momentum and the inventory, and deplete the wall; the manometric
   gradient converges at second order in the radial cells (20, 40, 80, 160 with the same wall cell: the
   differences fall by more than 2.5 a doubling). */
static void theta_transport(void) {
  static const struct {
    const char *name, *sets[5];
    double phi, gz;
  } cases[4] = {{"5 %, up, 3.02 m/s", {"pipe.solids_fraction=0.05", "flow.gravity=-9.81", NULL}, 0.05, -9.81},
                {"5 %, down, 5 m/s",
                 {"pipe.solids_fraction=0.05", "flow.gravity=9.81", "pipe.bulk_velocity=5", NULL},
                 0.05,
                 9.81},
                {"25 %, up, 5 m/s",
                 {"pipe.solids_fraction=0.25", "flow.gravity=-9.81", "pipe.bulk_velocity=5", NULL},
                 0.25,
                 -9.81},
                {"45 %, up, 5 m/s",
                 {"pipe.solids_fraction=0.45", "flow.gravity=-9.81", "pipe.bulk_velocity=5", NULL},
                 0.45,
                 -9.81}};
  for (int k = 0; k < 4; ++k) {
    const char *sets[8] = {"pipe.kinetic_pressure=true", "pipe.granular_temperature=transport"};
    for (int j = 0; cases[k].sets[j]; ++j) sets[2 + j] = cases[k].sets[j];
    sluice_error e = {0, ""};
    if (run(NULL, NULL, sets, "pipe_tt.h5", &e)) {
      CHECK_MSG(0, "transported theta, %s: %s", cases[k].name, e.msg);
      continue;
    }
    double phi = pipe_scalar("pipe_tt.h5", "phi_mean"), rho_m = phi * rho_s + (1.0 - phi) * rho_f;
    double tau =
        pipe_scalar("pipe_tt.h5", "wall_shear_stress_fluid") + pipe_scalar("pipe_tt.h5", "wall_shear_stress_solid");
    double dp = pipe_scalar("pipe_tt.h5", "pressure_gradient"), bal = 4.0 * tau / D - rho_m * cases[k].gz;
    double pw = pipe_scalar("pipe_tt.h5", "phi_wall");
    printf("transported theta, %s: %.0f iterations, phi_wall %.4f (mean %.2f), manometric %.2f Pa/m (balance %.1e)\n",
           cases[k].name, pipe_scalar("pipe_tt.h5", "iterations"), pw, cases[k].phi,
           pipe_scalar("pipe_tt.h5", "manometric_gradient"), dp / bal - 1.0);
    CHECK_MSG(fabs(dp / bal - 1.0) < 1e-6, "%s: -dP/dz %.9g against %.9g", cases[k].name, dp, bal);
    CHECK_MSG(fabs(phi - cases[k].phi) < 1e-12, "%s: inventory %.15g", cases[k].name, phi);
    CHECK_MSG(pw < cases[k].phi, "%s: phi_wall %.4g not below the mean", cases[k].name, pw);
  }
  for (int c = 0; c < 2; ++c) {
    double m[4];
    const char *cells[4] = {"pipe.cells=20", "pipe.cells=40", "pipe.cells=80", "pipe.cells=160"};
    for (int k = 0; k < 4; ++k) {
      const char *sets[] = {"pipe.kinetic_pressure=true", "pipe.granular_temperature=transport", cells[k],
                            c ? "pipe.solids_fraction=0.25" : "pipe.solids_fraction=0.05", NULL};
      sluice_error e = {0, ""};
      m[k] = run(NULL, NULL, sets, "pipe_tt.h5", &e) ? NAN : pipe_scalar("pipe_tt.h5", "manometric_gradient");
      CHECK_MSG(isfinite(m[k]), "%s: %s", cells[k], e.msg);
    }
    double r1 = (m[1] - m[0]) / (m[2] - m[1]), r2 = (m[2] - m[1]) / (m[3] - m[2]);
    printf("transported theta, %s: manometric %.3f, %.3f, %.3f, %.3f Pa/m on 20-160 cells; ratios %.2f, %.2f\n",
           c ? "25 %" : "5 %", m[0], m[1], m[2], m[3], r1, r2);
    CHECK_MSG(r1 > 2.5 && r2 > 2.5, "the differences fall by %.3g and %.3g a doubling", r1, r2);
  }
}

/* Simonin's modulation of the fluid's turbulence ([closure.turbulence_modulation] model = simonin, Krampa 2009
   model C's fluid side with Tchen's equilibrium k_fs): K (k_fs - 2k) = -2 K k/(1 + eta) <= 0 is an attenuation, so
   k falls in every cell and the fluid's wall stress with it (0.5 mm beads at 25 %: tau_fw 22.55 -> 6.09 Pa,
   printed); model = none is the scene without the section, bit for bit. */
static void modulation(void) {
  const char *none[] = {"closure.turbulence_modulation.model=none", NULL},
             *sim[] = {"closure.turbulence_modulation.model=simonin", NULL};
  sluice_error e = {0, ""};
  profile k0, k1, kd;
  if (run(NULL, NULL, NULL, "pipe_mod0.h5", &e) || read_profile("pipe_mod0.h5", "k", &kd) ||
      run(NULL, NULL, none, "pipe_mod1.h5", &e) || read_profile("pipe_mod1.h5", "k", &k0) ||
      run(NULL, NULL, sim, "pipe_mod2.h5", &e) || read_profile("pipe_mod2.h5", "k", &k1)) {
    CHECK_MSG(0, "modulation: %s", e.msg);
    return;
  }
  int same = 1, lower = 1;
  for (int i = 0; i < k0.n; ++i) same &= k0.v[i] == kd.v[i], lower &= k1.v[i] < k0.v[i];
  double t0 = pipe_scalar("pipe_mod1.h5", "wall_shear_stress_fluid"),
         t1 = pipe_scalar("pipe_mod2.h5", "wall_shear_stress_fluid");
  printf("modulation: k on the axis %.4g -> %.4g m2/s2, tau_fw %.4f -> %.4f Pa, manometric %.1f -> %.1f Pa/m\n",
         k0.v[0], k1.v[0], t0, t1, pipe_scalar("pipe_mod1.h5", "manometric_gradient"),
         pipe_scalar("pipe_mod2.h5", "manometric_gradient"));
  CHECK_MSG(same, "modulation = none is not the default");
  CHECK_MSG(lower, "the modulation does not lower k in every cell");
  CHECK_MSG(t1 < t0, "tau_fw %.6g with the modulation, %.6g without", t1, t0);
}

static void refused(void) {
  const char *sets[] = {"pipe.solids_fraction=0.625", NULL};
  sluice_error e = {0, ""};
  int rc = run(NULL, NULL, sets, "pipe_bad.h5", &e);
  printf("solids_fraction = 0.625: %s\n", e.msg);
  CHECK_MSG(rc == 2 && strstr(e.msg, "solids_fraction") && strstr(e.msg, "phi_max - 0.01"), "rc %d: %s", rc, e.msg);
}

int main(void) {
  if (load_scene()) return sl_test_summary();
  balances();
  dispersion_alone();
  kinetic_theory();
  no_slip_bridge();
  lprobe();
  lprobe_terms();
  stability();
  stability_kinetic();
  theta_transport();
  modulation();
  refused();
  return sl_test_summary();
}
