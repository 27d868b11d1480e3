/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The loop of Krampa's (2009) experiments ([pipe] loop = true, core/models/pipe/pipe_loop.c): an up-flow and a
 * down-flow section at one bulk velocity sharing the solids, on configs/vertical_pipe.ini (0.5 mm beads, model B)
 * at 45 % and 1.24 m/s (Table C.6's slowest row). Asserted:
 * - the shares: the sections' mean fractions average to the nominal 45 % (to round-off) and carry the same solids
 *   flux (to the loop's tolerance, 10 x [pipe] tolerance); the up-flow section holds more (the solids lag the
 *   fluid going up, lead it going down);
 * - the loop's average gradient is friction plus the in-situ difference,
 *   (G_u + G_d)/2 = 2 (tau_u + tau_d)/D + (c_u - c_d)(rho_s - rho_f) g/2, to 1e-6 of the average (each section's
 *   mixture momentum, Krampa 2009 eq 2.1, to the solve's tolerance);
 * - the up-flow section is the single up-flow run at its share (solids_fraction = c_u), to 1e-6;
 * - neutrally buoyant solids (rho_s = rho_f) do not slip by gravity: both shares are the nominal exactly;
 * - with Richardson-Zaki's drag (n = 3.19), dilute (2 %, 1 m/s): the sections' mean slip is u_t (1 - C)^(n - 1), to 1e-4;
 * - loop with length or pressure_gradient is refused (a bad-input error, before any output). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pipe_testing.h"

static char base[8192];

static int run(const char *out, const char *const *sets) {
  sluice_error e = {0, ""};
  int rc = pipe_run_text(base, "vertical_pipe.ini", sets, out, &e);
  CHECK_MSG(rc == 0, "%s: %s", out, e.msg);
  return rc;
}

static void shares_and_balance(void) {
  const char *sets[] = {"pipe.solids_fraction=0.45", "pipe.bulk_velocity=1.24", "pipe.loop=true", NULL};
  if (run("pipe_loop.h5", sets)) return;
  const char *o = "pipe_loop.h5";
  const double cu = pipe_scalar(o, "loop_phi_mean_up"), cd = pipe_scalar(o, "loop_phi_mean_down");
  const double Gu = pipe_scalar(o, "loop_manometric_gradient_up"), Gd = pipe_scalar(o, "loop_manometric_gradient_down");
  const double avg = pipe_scalar(o, "loop_manometric_gradient_average");
  const double tu = pipe_scalar(o, "loop_wall_shear_stress_up"), td = pipe_scalar(o, "loop_wall_shear_stress_down");
  const double mis = pipe_scalar(o, "loop_flux_mismatch");
  const double D = 0.0532, rho_s = 2500.0, rho_f = 997.56, g = 9.81;
  const double friction = 2.0 * (tu + td) / D, insitu = 0.5 * (cu - cd) * (rho_s - rho_f) * g;
  printf("loop at 45 %%, 1.24 m/s: phi up %.6f down %.6f (mean %.15f), flux mismatch %.2e after %g updates\n", cu, cd,
         0.5 * (cu + cd), mis, pipe_scalar(o, "loop_iterations"));
  printf("  manometric up %.2f down %.2f average %.3f Pa/m = friction %.3f + in-situ difference %.3f (%.1f %% of it)\n",
         Gu, Gd, avg, friction, insitu, 100.0 * insitu / avg);
  CHECK_MSG(fabs(0.5 * (cu + cd) - 0.45) < 1e-12, "the shares' mean %.15g, not 0.45", 0.5 * (cu + cd));
  CHECK_MSG(fabs(mis) <= 1e-7, "the sections' solids fluxes differ by %g (relative)", mis);
  CHECK_MSG(cu > cd + 1e-3, "the up-flow section holds %g, the down-flow %g: the up-flow should hold more", cu, cd);
  CHECK_MSG(fabs(avg - 0.5 * (Gu + Gd)) <= 1e-12 * fabs(Gu), "average %.17g against (up + down)/2", avg);
  CHECK_MSG(fabs(avg - friction - insitu) <= 1e-6 * avg, "average %.9g against friction + in-situ %.9g", avg,
            friction + insitu);
  /* the up-flow section against the single up-flow run at its share */
  char share[64];
  snprintf(share, sizeof share, "pipe.solids_fraction=%.17g", cu);
  const char *single[] = {share, "pipe.bulk_velocity=1.24", NULL};
  if (run("pipe_loop_single.h5", single)) return;
  const double Gs = pipe_scalar("pipe_loop_single.h5", "manometric_gradient");
  printf("  single up-flow run at phi = %.6f: manometric %.4f Pa/m (the loop's %.4f)\n", cu, Gs, Gu);
  CHECK_MSG(fabs(Gs - Gu) <= 1e-6 * fabs(Gu), "single run %.9g against the loop's up-flow section %.9g", Gs, Gu);
}

static void neutrally_buoyant(void) {
  const char *sets[] = {"pipe.solids_fraction=0.30", "pipe.bulk_velocity=2", "pipe.loop=true", "solid.density=997.56",
                        NULL};
  if (run("pipe_loop_neutral.h5", sets)) return;
  const double cu = pipe_scalar("pipe_loop_neutral.h5", "loop_phi_mean_up"),
               cd = pipe_scalar("pipe_loop_neutral.h5", "loop_phi_mean_down");
  printf("neutrally buoyant: phi up %.17g down %.17g\n", cu, cd);
  CHECK_MSG(fabs(cu - 0.30) < 1e-12 && fabs(cd - 0.30) < 1e-12, "shares %.17g, %.17g: not the nominal 0.30", cu, cd);
}

/* The Richardson-Zaki-consistent drag (drag/richardson_zaki_consistent, the exponent of Krampa's beads, n = 3.19) in the loop,
   dilute: each section's mean slip from its share and the common solids flux F, s = (V - F)/(1 - c) - F/c (the
   fraction uniform under dispersion alone), against Richardson & Zaki (1954), u_t (1 - C)^(n - 1), the slip of a
   homogeneous suspension with that drag (the interstitial form of U = u_t eps^n). The wall friction's share
   (about 4 tau_w / (D eps rho_f g), 2 % at 1 m/s) has the opposite sign in the two sections, so their mean slip
   meets the homogeneous one to second order. u_t from the Schiller-Naumann balance (3/4) C_D rho_f u_t^2 / d =
   (rho_s - rho_f) g, C_D = 24/Re (1 + 0.15 Re^0.687), by bisection. */
static void richardson_zaki_dilute(void) {
  const double C = 0.02, V = 1.0, n = 3.19;
  char sets_v[3][64];
  snprintf(sets_v[0], 64, "pipe.solids_fraction=%g", C);
  snprintf(sets_v[1], 64, "pipe.bulk_velocity=%g", V);
  snprintf(sets_v[2], 64, "closure.drag.n=%g", n);
  const char *sets[] = {sets_v[0], sets_v[1], "pipe.loop=true", sets_v[2], NULL};
  static char saved[8192];
  memcpy(saved, base, sizeof saved);
  char *dr = strstr(base, "[closure.drag]\nmodel = gidaspow\n");
  CHECK_MSG(dr != NULL, "vertical_pipe.ini has no [closure.drag] model = gidaspow");
  if (!dr) return;
  snprintf(dr, sizeof base - (size_t)(dr - base),
           "[closure.drag]\nmodel = richardson_zaki_consistent\nterminal_velocity = schiller_naumann\n%s",
           saved + (dr - base) + strlen("[closure.drag]\nmodel = gidaspow\n"));
  int rc = run("pipe_loop_rz.h5", sets);
  memcpy(base, saved, sizeof saved);
  if (rc) return;
  const char *o = "pipe_loop_rz.h5";
  const double cu = pipe_scalar(o, "loop_phi_mean_up"), cd = pipe_scalar(o, "loop_phi_mean_down");
  const double F = pipe_scalar(o, "loop_solids_flux");
  const double rho_s = 2500.0, rho_f = 997.56, mu = 0.9347e-3, d = 5e-4, g = 9.81;
  double lo = 1e-6, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    double u = 0.5 * (lo + hi), Re = rho_f * u * d / mu, cd_ = 24.0 / Re * (1.0 + 0.15 * pow(Re, 0.687));
    if (0.75 * cd_ * rho_f * u * u / d > (rho_s - rho_f) * g) hi = u;
    else lo = u;
  }
  const double ut = 0.5 * (lo + hi), s_rz = ut * pow(1.0 - C, n - 1.0);
  const double su = (V - F) / (1.0 - cu) - F / cu, sd = (F - V) / (1.0 - cd) + F / cd;
  printf(
      "Richardson-Zaki drag, %g %%, %g m/s: u_t %.5f m/s, slip up %.6f down %.6f (mean %.6f) against u_t eps^(n-1) "
      "%.6f (%+.3f %%)\n",
      100.0 * C, V, ut, su, sd, 0.5 * (su + sd), s_rz, 100.0 * (0.5 * (su + sd) / s_rz - 1.0));
  CHECK_MSG(fabs(0.5 * (su + sd) / s_rz - 1.0) < 1e-4, "the sections' mean slip %.6g against %.6g", 0.5 * (su + sd),
            s_rz);
  CHECK_MSG(su > 0.0 && sd > 0.0, "slips %g, %g: the solids lag going up and lead going down", su, sd);
}

static void refused(const char *set, const char *key) {
  const char *sets[] = {"pipe.solids_fraction=0.45", "pipe.loop=true", set, NULL};
  sluice_error e = {0, ""};
  int rc = pipe_run_text(base, "vertical_pipe.ini", sets, "pipe_loop_refused.h5", &e);
  printf("loop with %s: %s\n", set, e.msg);
  CHECK_MSG(rc == SLUICE_BAD_INPUT, "loop with %s: code %d, not a bad-input error", set, rc);
  CHECK_MSG(strstr(e.msg, key) != NULL && strstr(e.msg, "loop") != NULL, "the message names neither loop nor %s", key);
  FILE *f = fopen("pipe_loop_refused.h5", "rb");
  CHECK_MSG(f == NULL, "a refused scene wrote its output");
  if (f) fclose(f);
}

int main(void) {
  if (sl_test_read_source("configs/vertical_pipe.ini", base, sizeof base)) return sl_test_summary();
  shares_and_balance();
  neutrally_buoyant();
  richardson_zaki_dilute();
  refused("pipe.length=4", "length");
  refused("pipe.pressure_gradient=8000", "pressure_gradient");
  return sl_test_summary();
}
