/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Coulomb's friction of the solids on the pipe's wall ([pipe] solids_wall = wall_stress, [closure.wall_stress.solids]
 * model = coulomb: tau_sw = mu_w N; core/models/pipe/pipe_solids.c supplies N, the solids' pressures at the wall
 * cell), on configs/vertical_pipe.ini (0.5 mm beads, Krampa's model B) at 2.49 m/s:
 * - at 45 % (Table C.6) mu_w = 0 with the kinetic pressure on the wall ([pipe] wall_normal_stress =
 *   contact_kinetic), and mu_w = 0.4 with the contact pressure alone (the default; the scene has none), are the
 *   free-slip run of vertical_pipe.ini, bit for bit (manometric gradient, phi, u_s);
 * - contact_kinetic, mu_w = 0.4: in a converged run the reported solids wall stress is mu_w times the reported
 *   normal stress (to the solve's tolerance), and that normal stress is Lun et al.'s (1984) kinetic pressure
 *   rho_s phi theta (1 + 2 (1+e) phi g0) (Krampa 2009 eq 5.9; g0 of Lun & Savage, (1 - phi/0.63)^(-2.5 x 0.63))
 *   evaluated here from the run's own phi and theta of the wall cell; the mixture's momentum,
 *   -dP/dz = 4 (tau_fw + tau_sw)/D - rho_m g_z (Krampa 2009 eq 2.1), up and down;
 * - with Johnson & Jackson's (1987) frictional pressure as [closure.solids_pressure]: at 45 % (uniform phi, below
 *   its phi_min = 0.5) nothing moves; at 55 % the normal stress is Fr (phi - 0.5)^2/(0.63 - phi)^5 (Fr = 0.05 Pa)
 *   of the run's wall-cell phi, tau_sw = mu_w N, and the mixture's momentum holds. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pipe_testing.h"

static char base[8192];

static int run_at(const char *fraction, const char *wall, const char *extra, const char *gravity, const char *out,
                  const char *set) {
  static char text[12288];
  const char *fs = strstr(base, "solids_wall = free_slip");
  CHECK_MSG(fs != NULL, "vertical_pipe.ini has no solids_wall = free_slip");
  if (!fs) return 1;
  snprintf(text, sizeof text, "%.*ssolids_wall = %s%s\n%s", (int)(fs - base), base, wall ? "wall_stress" : "free_slip",
           fs + strlen("solids_wall = free_slip"), extra ? extra : "");
  if (wall) snprintf(text + strlen(text), sizeof text - strlen(text), "\n%s", wall);
  const char *sets[] = {fraction, "pipe.bulk_velocity=2.49", gravity, set, NULL};
  sluice_error e = {0, ""};
  int rc = pipe_run_text(text, "vertical_pipe.ini", sets, out, &e);
  CHECK_MSG(rc == 0, "%s: %s", out, e.msg);
  return rc;
}

/* at 45 %; kinetic: [pipe] wall_normal_stress = contact_kinetic */
static int run(const char *wall, const char *extra, const char *gravity, const char *out, int kinetic) {
  return run_at("pipe.solids_fraction=0.45", wall, extra, gravity, out,
                kinetic ? "pipe.wall_normal_stress=contact_kinetic" : NULL);
}

static double max_diff(const profile *a, const profile *b) {
  double m = a->n == b->n ? 0.0 : INFINITY;
  for (int i = 0; i < a->n && i < b->n; ++i) m = fmax(m, fabs(a->v[i] - b->v[i]));
  return m;
}

/* The run of `wall` (and `extra`) against free slip: the same, bit for bit. */
static void as_free_slip(const char *label, const char *wall, int kinetic, const char *out) {
  if (run(wall, NULL, "flow.gravity=-9.81", out, kinetic)) return;
  const double g0 = pipe_scalar("pipe_coulomb_free.h5", "manometric_gradient"), g1 = pipe_scalar(out, "manometric_gradient");
  profile a, b, c, e;
  if (read_profile("pipe_coulomb_free.h5", "phi", &a) || read_profile(out, "phi", &b) ||
      read_profile("pipe_coulomb_free.h5", "velocity_solid", &c) || read_profile(out, "velocity_solid", &e))
    return;
  printf("%s: manometric gradient %.17g, free slip %.17g; phi differs by %g, u_s by %g; N %g Pa\n", label, g1, g0,
         max_diff(&a, &b), max_diff(&c, &e), pipe_scalar(out, "wall_normal_stress_solid"));
  CHECK_MSG(g1 == g0, "%s: %.17g against free slip %.17g", label, g1, g0);
  CHECK_MSG(max_diff(&a, &b) == 0.0 && max_diff(&c, &e) == 0.0, "%s: the profiles differ", label);
  CHECK_MSG(pipe_scalar(out, "wall_shear_stress_solid") == 0.0, "%s: tau_sw != 0", label);
}

static void zero_friction(void) {
  if (run(NULL, NULL, "flow.gravity=-9.81", "pipe_coulomb_free.h5", 0)) return;
  as_free_slip("mu_w = 0, contact_kinetic", "[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0\n", 1,
               "pipe_coulomb_zero.h5");
  as_free_slip("mu_w = 0.4, contact (none in the scene)", "[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n",
               0, "pipe_coulomb_contact.h5");
  CHECK_MSG(pipe_scalar("pipe_coulomb_zero.h5", "wall_normal_stress_solid") > 0.0, "contact_kinetic: N = 0");
}

/* The mixture's momentum of a run: -dP/dz against 4 (tau_fw + tau_sw)/D - rho_m g_z. */
static void momentum(const char *out, double gz) {
  const double D = 0.0532, rho_s = 2500.0, rho_f = 997.56;
  const double tau = pipe_scalar(out, "wall_shear_stress_solid") + pipe_scalar(out, "wall_shear_stress_fluid");
  const double phi = pipe_scalar(out, "phi_mean"), rho_m = phi * rho_s + (1.0 - phi) * rho_f;
  const double dp = pipe_scalar(out, "pressure_gradient"), bal = 4.0 * tau / D - rho_m * gz;
  printf("  %s: -dP/dz %.6f, 4 tau_w/D - rho_m g_z %.6f\n", out, dp, bal);
  CHECK_MSG(fabs(dp / bal - 1.0) < 1e-6, "the mixture momentum: %.9g against %.9g", dp, bal);
}

/* Lun et al.'s pressure with e = 0.9 and Lun & Savage's g0 (phi_max 0.63), independently of the closure's code. */
static double lun_pressure(double phi, double theta) {
  const double rho_s = 2500.0, e = 0.9, g0 = pow(1.0 - phi / 0.63, -2.5 * 0.63);
  return rho_s * phi * theta * (1.0 + 2.0 * (1.0 + e) * phi * g0);
}

static void friction(const char *gravity, const char *out) {
  const double mu_w = 0.4;
  if (run("[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n", NULL, gravity, out, 1)) return;
  const double tau_s = pipe_scalar(out, "wall_shear_stress_solid"), N = pipe_scalar(out, "wall_normal_stress_solid");
  const double phi_w = pipe_scalar(out, "phi_wall");
  profile th;
  if (read_profile(out, "theta", &th)) return;
  const double p_lun = lun_pressure(phi_w, th.v[th.n - 1]);
  printf("%s, contact_kinetic: tau_sw %.9g Pa, mu_w N %.9g (N %.6g Pa; Lun's p_s at the wall cell %.6g)\n", gravity,
         tau_s, mu_w * N, N, p_lun);
  CHECK_MSG(N > 0.0 && tau_s > 0.0, "the friction acts: N %g, tau_sw %g", N, tau_s);
  CHECK_MSG(fabs(tau_s / (mu_w * N) - 1.0) < 1e-6, "tau_sw %.12g against mu_w N %.12g", tau_s, mu_w * N);
  CHECK_MSG(fabs(N / p_lun - 1.0) < 1e-12, "N %.15g against Lun's pressure %.15g", N, p_lun);
  momentum(out, strstr(gravity, "-") ? -9.81 : 9.81);
}

/* Johnson & Jackson's frictional pressure as the contact pressure at 55 %: N of the run's wall-cell phi. */
static void contact_dense(void) {
  const char *w = "[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n";
  const char *jj = "[closure.solids_pressure]\nmodel = johnson_jackson_frictional\n";
  if (run_at("pipe.solids_fraction=0.55", w, jj, "flow.gravity=-9.81", "pipe_coulomb_dense.h5", NULL)) return;
  const char *out = "pipe_coulomb_dense.h5";
  const double tau_s = pipe_scalar(out, "wall_shear_stress_solid"), N = pipe_scalar(out, "wall_normal_stress_solid");
  const double phi_w = pipe_scalar(out, "phi_wall"), p_jj = 0.05 * pow(phi_w - 0.5, 2.0) / pow(0.63 - phi_w, 5.0);
  printf("55 %%, contact: phi_wall %.6f, N %.9g Pa against Fr (phi - 0.5)^2/(0.63 - phi)^5 = %.9g; tau_sw %.9g, mu_w N "
         "%.9g\n",
         phi_w, N, p_jj, tau_s, 0.4 * N);
  CHECK_MSG(phi_w > 0.5 && phi_w < 0.62, "phi_wall %g", phi_w);
  CHECK_MSG(fabs(N / p_jj - 1.0) < 1e-12, "N %.15g against Johnson & Jackson's %.15g", N, p_jj);
  CHECK_MSG(fabs(tau_s / (0.4 * N) - 1.0) < 1e-6, "tau_sw %.12g against mu_w N %.12g", tau_s, 0.4 * N);
  momentum(out, -9.81);
}

/* Johnson & Jackson's frictional pressure below its phi_min changes nothing. */
static void frictional_dilute(void) {
  const char *w = "[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n";
  if (run(w, "[closure.solids_pressure]\nmodel = johnson_jackson_frictional\n", "flow.gravity=-9.81",
          "pipe_coulomb_jj.h5", 1))
    return;
  const double a = pipe_scalar("pipe_coulomb_jj.h5", "manometric_gradient");
  const double b = pipe_scalar("pipe_coulomb_up.h5", "manometric_gradient");
  const double na = pipe_scalar("pipe_coulomb_jj.h5", "wall_normal_stress_solid");
  const double nb = pipe_scalar("pipe_coulomb_up.h5", "wall_normal_stress_solid");
  printf("with the frictional pressure at phi 0.45: manometric %.17g against %.17g, N %.17g against %.17g\n", a, b, na,
         nb);
  CHECK_MSG(a == b && na == nb, "the frictional pressure below phi_min moved the run");
}

int main(void) {
  if (sl_test_read_source("configs/vertical_pipe.ini", base, sizeof base)) return sl_test_summary();
  zero_friction();
  friction("flow.gravity=-9.81", "pipe_coulomb_up.h5");
  friction("flow.gravity=9.81", "pipe_coulomb_down.h5");
  frictional_dilute();
  contact_dense();
  return sl_test_summary();
}
