/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Coulomb's friction of the solids on the pipe's wall ([pipe] solids_wall = wall_stress, [closure.wall_stress.solids]
 * model = coulomb: tau_sw = mu_w N; core/models/pipe/pipe_solids.c supplies N, the solids' pressures at the wall
 * cell), on configs/vertical_pipe.ini (0.5 mm beads, Krampa's model B) at 45 % and 2.49 m/s (Table C.6):
 * - mu_w = 0 is the free-slip run of vertical_pipe.ini, bit for bit (manometric gradient, phi, u_s);
 * - in a converged run the reported solids wall stress is mu_w times the reported normal stress (to the solve's
 *   tolerance), and that normal stress is Lun et al.'s (1984) kinetic pressure rho_s phi theta (1 + 2 (1+e) phi g0)
 *   (Krampa 2009 eq 5.9; g0 of Lun & Savage, (1 - phi/0.63)^(-2.5 x 0.63)) evaluated here from the run's own
 *   phi and theta of the wall cell;
 * - with Johnson & Jackson's (1987) frictional pressure as [closure.solids_pressure] the normal stress gains
 *   Fr (phi - 0.5)^2/(0.63 - phi)^5, zero at this phi (uniform 0.45 < phi_min = 0.5): the run is the one without it;
 * - the mixture's momentum, -dP/dz = 4 (tau_fw + tau_sw)/D - rho_m g_z (Krampa 2009 eq 2.1), up and down. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pipe_testing.h"

static char base[8192];

static int run(const char *wall, const char *extra, const char *gravity, const char *out) {
  static char text[12288];
  const char *fs = strstr(base, "solids_wall = free_slip");
  CHECK_MSG(fs != NULL, "vertical_pipe.ini has no solids_wall = free_slip");
  if (!fs) return 1;
  snprintf(text, sizeof text, "%.*ssolids_wall = %s%s\n%s", (int)(fs - base), base, wall ? "wall_stress" : "free_slip",
           fs + strlen("solids_wall = free_slip"), extra ? extra : "");
  if (wall) snprintf(text + strlen(text), sizeof text - strlen(text), "\n%s", wall);
  const char *sets[] = {"pipe.solids_fraction=0.45", "pipe.bulk_velocity=2.49", gravity, NULL};
  sluice_error e = {0, ""};
  int rc = pipe_run_text(text, "vertical_pipe.ini", sets, out, &e);
  CHECK_MSG(rc == 0, "%s: %s", out, e.msg);
  return rc;
}

static double max_diff(const profile *a, const profile *b) {
  double m = a->n == b->n ? 0.0 : INFINITY;
  for (int i = 0; i < a->n && i < b->n; ++i) m = fmax(m, fabs(a->v[i] - b->v[i]));
  return m;
}

/* mu_w = 0 is free slip, exactly. */
static void zero_friction(void) {
  if (run(NULL, NULL, "flow.gravity=-9.81", "pipe_coulomb_free.h5") ||
      run("[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0\n", NULL, "flow.gravity=-9.81",
          "pipe_coulomb_zero.h5"))
    return;
  const double g0 = pipe_scalar("pipe_coulomb_free.h5", "manometric_gradient");
  const double g1 = pipe_scalar("pipe_coulomb_zero.h5", "manometric_gradient");
  profile a, b, c, e;
  if (read_profile("pipe_coulomb_free.h5", "phi", &a) || read_profile("pipe_coulomb_zero.h5", "phi", &b) ||
      read_profile("pipe_coulomb_free.h5", "velocity_solid", &c) ||
      read_profile("pipe_coulomb_zero.h5", "velocity_solid", &e))
    return;
  printf("mu_w = 0: manometric gradient %.17g, free slip %.17g; phi differs by %g, u_s by %g\n", g1, g0,
         max_diff(&a, &b), max_diff(&c, &e));
  CHECK_MSG(g1 == g0, "mu_w = 0: %.17g against free slip %.17g", g1, g0);
  CHECK_MSG(max_diff(&a, &b) == 0.0 && max_diff(&c, &e) == 0.0, "mu_w = 0: the profiles differ");
  CHECK_MSG(pipe_scalar("pipe_coulomb_zero.h5", "wall_shear_stress_solid") == 0.0, "mu_w = 0: tau_sw != 0");
}

/* Lun et al.'s pressure with e = 0.9 and Lun & Savage's g0 (phi_max 0.63), independently of the closure's code. */
static double lun_pressure(double phi, double theta) {
  const double rho_s = 2500.0, e = 0.9, g0 = pow(1.0 - phi / 0.63, -2.5 * 0.63);
  return rho_s * phi * theta * (1.0 + 2.0 * (1.0 + e) * phi * g0);
}

static void friction(const char *gravity, const char *out) {
  const double mu_w = 0.4, D = 0.0532, rho_s = 2500.0, rho_f = 997.56;
  if (run("[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n", NULL, gravity, out)) return;
  const double tau_s = pipe_scalar(out, "wall_shear_stress_solid"), N = pipe_scalar(out, "wall_normal_stress_solid");
  const double tau_f = pipe_scalar(out, "wall_shear_stress_fluid"), phi_w = pipe_scalar(out, "phi_wall");
  profile th;
  if (read_profile(out, "theta", &th)) return;
  const double p_lun = lun_pressure(phi_w, th.v[th.n - 1]);
  const double gz = strstr(gravity, "-") ? -9.81 : 9.81, phi = pipe_scalar(out, "phi_mean");
  const double rho_m = phi * rho_s + (1.0 - phi) * rho_f, dp = pipe_scalar(out, "pressure_gradient");
  const double bal = 4.0 * (tau_f + tau_s) / D - rho_m * gz;
  printf("%s: tau_sw %.9g Pa, mu_w N %.9g (N %.6g Pa; Lun's p_s at the wall cell %.6g), tau_fw %.6g; -dP/dz %.6f, "
         "4 tau_w/D - rho_m g_z %.6f\n",
         gravity, tau_s, mu_w * N, N, p_lun, tau_f, dp, bal);
  CHECK_MSG(N > 0.0 && tau_s > 0.0, "the friction acts: N %g, tau_sw %g", N, tau_s);
  CHECK_MSG(fabs(tau_s / (mu_w * N) - 1.0) < 1e-6, "tau_sw %.12g against mu_w N %.12g", tau_s, mu_w * N);
  CHECK_MSG(fabs(N / p_lun - 1.0) < 1e-12, "N %.15g against Lun's pressure %.15g", N, p_lun);
  CHECK_MSG(fabs(dp / bal - 1.0) < 1e-6, "the mixture momentum: %.9g against %.9g", dp, bal);
}

/* Johnson & Jackson's frictional pressure below its phi_min changes nothing. */
static void frictional_dilute(void) {
  const char *w = "[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n";
  if (run(w, "[closure.solids_pressure]\nmodel = johnson_jackson_frictional\n", "flow.gravity=-9.81",
          "pipe_coulomb_jj.h5"))
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
  return sl_test_summary();
}
