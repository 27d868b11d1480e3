/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tests of the migration closure phillips: the Phillips et al. (1992)
 * constants, the a = d_p/2 convention, derivatives, refused states, and the
 * zero-flux steady state phi shear_rate mu^(K_mu/K_c) = const (Nigam 1999
 * eq 4.199, section 4.5) assembled the way a host would,
 * N = -D_c grad(shear_rate phi) - D_mu grad(ln mu), with the viscosity from
 * krieger_dougherty. */
#include <math.h>

#include "closure_test.h"
#include "testing.h"

#define RTOL 1e-12

static double out(sl_tc *t, const char *name, double phi, double g, double dp) {
  return sl_tc_eval(t, name, "phi", phi, "shear_rate", g, "d_p", dp, NULL);
}

static double dout(sl_tc *t, const char *name, const char *wrt, double phi, double g, double dp) {
  return sl_tc_deriv(t, name, wrt, "phi", phi, "shear_rate", g, "d_p", dp, NULL);
}

static void check_refused(sl_tc *t, double phi, double g, double dp) {
  double v = out(t, "D_c", phi, g, dp);
  CHECK_MSG(sl_tc_status(t) > 0 && isnan(v) && t->err.msg[0], "phi %g, shear_rate %g, d_p %g: status %d", phi, g, dp,
            sl_tc_status(t));
}

static void test_constants(void) {
  sl_tc *t = sl_tc_open("migration", "phillips", NULL);
  const double st[][3] = {
      {0.0, 0.0, 1e-3}, {0.1, 3.0, 2e-4}, {0.4, 10.0, 1e-3}, {0.55, 250.0, 5e-5}, {0.74, 1.0, 0.02}};
  for (int i = 0; i < 5; ++i) {
    double phi = st[i][0], g = st[i][1], dp = st[i][2];
    double a2 = dp * dp / 4.0; /* a = d_p / 2: the RADIUS */
    CHECK_CLOSE(out(t, "D_c", phi, g, dp), 0.41 * phi * a2, RTOL);
    CHECK_CLOSE(out(t, "D_mu", phi, g, dp), 0.62 * g * phi * phi * a2, RTOL);
    CHECK_CLOSE(dout(t, "D_c", "phi", phi, g, dp), 0.41 * a2, RTOL);
    CHECK(dout(t, "D_c", "shear_rate", phi, g, dp) == 0.0);
    CHECK_CLOSE(dout(t, "D_mu", "phi", phi, g, dp), 1.24 * g * phi * a2, RTOL);
    CHECK_CLOSE(dout(t, "D_mu", "shear_rate", phi, g, dp), 0.62 * phi * phi * a2, RTOL);
  }
  /* The constants themselves: D_c/(a^2 phi) = K_c, D_mu/(a^2 g phi^2) = K_mu. */
  CHECK_CLOSE(out(t, "D_c", 0.5, 2.0, 2.0e-3) / (1e-6 * 0.5), 0.41, RTOL);
  CHECK_CLOSE(out(t, "D_mu", 0.5, 2.0, 2.0e-3) / (1e-6 * 2.0 * 0.25), 0.62, RTOL);
  /* K_mu/K_c = 1.512..., the exponent ratio of Nigam eq 4.200. */
  CHECK_CLOSE(out(t, "D_mu", 0.3, 1.0, 1e-3) / (out(t, "D_c", 0.3, 1.0, 1e-3) * 0.3), 0.62 / 0.41, RTOL);
  check_refused(t, 0.75, 1.0, 1e-3);
  check_refused(t, -0.01, 1.0, 1e-3);
  check_refused(t, NAN, 1.0, 1e-3);
  check_refused(t, 0.3, -1.0, 1e-3);
  check_refused(t, 0.3, INFINITY, 1e-3);
  check_refused(t, 0.3, 1.0, 0.0);
  check_refused(t, 0.3, 1.0, NAN);
  sl_tc_close(t);
  t = sl_tc_open("migration", "phillips", "k_c=0.5", "k_mu=0.75", NULL);
  CHECK_CLOSE(out(t, "D_c", 0.2, 1.0, 2e-3), 0.5 * 0.2 * 1e-6, RTOL);
  CHECK_CLOSE(out(t, "D_mu", 0.2, 3.0, 2e-3), 0.75 * 3.0 * 0.04 * 1e-6, RTOL);
  sl_tc_close(t);
}

/* 1-D profile phi(r) with the Nigam steady shear rate
 * g(r) = C / (phi mu(phi)^(K_mu/K_c)): the host-assembled flux vanishes. */
static void test_zero_flux_state(void) {
  sl_tc *mig = sl_tc_open("migration", "phillips", NULL);
  sl_tc *vis = sl_tc_open("viscosity", "krieger_dougherty", "intrinsic_viscosity=2.6765", NULL);
  const double dp = 1e-3, ratio = 0.62 / 0.41, h = 1e-5;
  for (int k = 0; k < 3; ++k) {
    double r0 = 0.2 + 0.3 * k;
    double phi_r[3], g_r[3], lnmu_r[3];
    for (int s = 0; s < 3; ++s) {
      double r = r0 + (s - 1) * h;
      double phi = 0.25 + 0.3 * r * r; /* any smooth profile below phi_max */
      double mu = sl_tc_eval(vis, "viscosity", "phi", phi, "mu_f", 1e-3, NULL);
      phi_r[s] = phi;
      lnmu_r[s] = log(mu);
      g_r[s] = 5.0 / (phi * pow(mu, ratio));
    }
    double grad_gphi = (g_r[2] * phi_r[2] - g_r[0] * phi_r[0]) / (2 * h);
    double grad_lnmu = (lnmu_r[2] - lnmu_r[0]) / (2 * h);
    double Dc = out(mig, "D_c", phi_r[1], g_r[1], dp), Dmu = out(mig, "D_mu", phi_r[1], g_r[1], dp);
    double Nc = -Dc * grad_gphi, Nmu = -Dmu * grad_lnmu;
    CHECK(sl_tc_status(mig) == 0 && fabs(Nc) > 0);
    CHECK_MSG(fabs(Nc + Nmu) <= 1e-7 * fabs(Nc), "r = %g: N_c %g, N_mu %g", r0, Nc, Nmu);
    /* A uniform shear rate instead would drive particles: flux non-zero. */
    double grad_phi = (phi_r[2] - phi_r[0]) / (2 * h);
    double N_uniform = -Dc * g_r[1] * grad_phi - Dmu * grad_lnmu;
    CHECK(fabs(N_uniform) > 0.1 * fabs(Nc));
  }
  sl_tc_close(vis);
  sl_tc_close(mig);
}

int main(void) {
  test_constants();
  test_zero_flux_state();
  return sl_test_summary();
}
