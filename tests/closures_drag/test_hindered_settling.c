/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tests of the hindered_settling closures richardson_zaki, michaels_bolger,
 * nigam and vesilind: the terminal velocity (Stokes formula; the Schiller-Naumann /
 * Rowe force balance to 1e-14 and Pringle's (2001) values for nylon spheres),
 * the Richardson-Zaki (1954) and Garside & Al-Dibouni (1977) exponents at
 * published Re_t, f -> 1 as phi -> 0, Nigam's (1999) h(alpha) and Kynch flux
 * maximum for Nigam's law, derivatives against central differences, and
 * refused states. */
#include <float.h>
#include <math.h>

#include "closure_test.h"
#include "testing.h"

#define RTOL 1e-12

/* A hindered-settling state (d_vessel is only an input of richardson_zaki). */
typedef struct hs {
  double phi, d_p, psi, rho_s, rho_f, mu_f, g, D;
} hs;

static hs H(double phi, double d_p, double rho_s, double rho_f, double mu_f) {
  hs s = {phi, d_p, 1.0, rho_s, rho_f, mu_f, 9.81, INFINITY};
  return s;
}

static double ev(sl_tc *t, const char *out, hs s) {
  if (sl_closure_input(t->c->desc, "d_vessel") >= 0)
    return sl_tc_eval(t, out, "phi", s.phi, "d_p", s.d_p, "sphericity", s.psi, "rho_s", s.rho_s, "rho_f", s.rho_f,
                      "mu_f", s.mu_f, "gravity", s.g, "d_vessel", s.D, NULL);
  return sl_tc_eval(t, out, "phi", s.phi, "d_p", s.d_p, "sphericity", s.psi, "rho_s", s.rho_s, "rho_f", s.rho_f, "mu_f",
                    s.mu_f, "gravity", s.g, NULL);
}

static double dev(sl_tc *t, const char *out, hs s) {
  if (sl_closure_input(t->c->desc, "d_vessel") >= 0)
    return sl_tc_deriv(t, out, "phi", "phi", s.phi, "d_p", s.d_p, "sphericity", s.psi, "rho_s", s.rho_s, "rho_f",
                       s.rho_f, "mu_f", s.mu_f, "gravity", s.g, "d_vessel", s.D, NULL);
  return sl_tc_deriv(t, out, "phi", "phi", s.phi, "d_p", s.d_p, "sphericity", s.psi, "rho_s", s.rho_s, "rho_f", s.rho_f,
                     "mu_f", s.mu_f, "gravity", s.g, NULL);
}

static double vs(sl_tc *t, hs s) { return ev(t, "settling_velocity", s); }
static double fh(sl_tc *t, hs s) { return ev(t, "hindrance", s); }
static double ut(sl_tc *t, hs s) { return ev(t, "terminal_velocity", s); }

/* d(settling)/dphi and d(hindrance)/dphi against central differences; d(u_t)/dphi = 0. */
static void check_derivs(sl_tc *t, hs s) {
  const char *outs[] = {"settling_velocity", "hindrance"};
  double h = 1e-6 * fmax(s.phi, 1e-3);
  if (s.phi - h < 0.0) return; /* phi = 0 is an edge: its slope is tested on its own */
  for (int k = 0; k < 2; ++k) {
    hs a = s, b = s;
    a.phi += h, b.phi -= h;
    double fd = (ev(t, outs[k], a) - ev(t, outs[k], b)) / (2.0 * h);
    double an = dev(t, outs[k], s);
    CHECK_MSG(fabs(an - fd) <= 1e-6 * fabs(fd) + 1e-9 * fabs(ev(t, outs[k], s)) / fmax(s.phi, 1e-3),
              "%s: d%s/dphi at phi %g: closure %.12g, central difference %.12g", t->c->desc->name, outs[k], s.phi, an,
              fd);
  }
  CHECK(dev(t, "terminal_velocity", s) == 0.0);
}

static void check_refused(sl_tc *t, hs s) {
  double v = vs(t, s);
  CHECK_MSG(sl_tc_status(t) > 0 && isnan(v) && t->err.point == 0 && t->err.msg[0], "%s: phi %g status %d",
            t->c->desc->name, s.phi, sl_tc_status(t));
}

static void check_common_refusals(sl_tc *t) {
  hs s = H(0.1, 1e-4, 2600.0, 1000.0, 1e-3), b;
  b = s, b.phi = -1e-12, check_refused(t, b);
  b = s, b.phi = NAN, check_refused(t, b);
  b = s, b.phi = 1.5, check_refused(t, b);
  b = s, b.d_p = 0.0, check_refused(t, b);
  b = s, b.rho_s = NAN, check_refused(t, b);
  b = s, b.mu_f = -1e-3, check_refused(t, b);
  b = s, b.g = -9.81, check_refused(t, b);
  b = s, b.g = INFINITY, check_refused(t, b);
  b = s, b.psi = 0.0, check_refused(t, b);
  double ok = vs(t, s);
  CHECK(sl_tc_status(t) == 0 && isfinite(ok));
}

/* ---- terminal velocity -------------------------------------------------- */

static double cd_sn(double re) { return re < 1000.0 ? 24.0 / re * (1.0 + 0.15 * pow(re, 0.687)) : 0.44; }

static double stokes_ut(hs s) {
  double d = s.psi * s.d_p;
  return (s.rho_s - s.rho_f) * s.g * d * d / (18.0 * s.mu_f);
}

static void test_terminal_velocity(void) {
  sl_tc *st = sl_tc_open("hindered_settling", "richardson_zaki", NULL);
  sl_tc *sn = sl_tc_open("hindered_settling", "richardson_zaki", "terminal_velocity=schiller_naumann", NULL);
  sl_tc *rw = sl_tc_open("hindered_settling", "richardson_zaki", "terminal_velocity=rowe", NULL);
  sl_tc *gv = sl_tc_open("hindered_settling", "richardson_zaki", "terminal_velocity=given", "u_t=0.0123", NULL);
  /* Stokes: 2 (rho_s - rho_f) g a^2 / (9 mu), signed (buoyant particles rise). */
  const hs stk[] = {H(0.0, 1e-4, 2600.0, 1000.0, 1e-3), H(0.0, 62.5e-6, 2460.0, 870.0, 5.86e-4),
                    H(0.0, 2e-5, 500.0, 1000.0, 1e-3), H(0.0, 1e-6, 2600.0, 1.2, 1.8e-5)};
  for (int i = 0; i < 4; ++i) {
    hs s = stk[i];
    double a = s.d_p / 2.0;
    CHECK_CLOSE(vs(st, s), 2.0 * (s.rho_s - s.rho_f) * s.g * a * a / (9.0 * s.mu_f), RTOL);
    CHECK_CLOSE(ut(st, s), stokes_ut(s), RTOL);
  }
  hs s = H(0.0, 62.5e-6, 2460.0, 870.0, 5.86e-4);
  s.psi = 0.088; /* Pringle's illite, d' = 5.5 um: 4.47e-5 m/s (Pringle 2001, Table 5.4, eq 5.9) */
  CHECK_CLOSE(vs(st, s), 4.47e-5, 2e-3);
  CHECK(vs(st, H(0.0, 2e-5, 500.0, 1000.0, 1e-3)) < 0.0);
  /* Schiller-Naumann / Rowe: the force balance (3/4) C_D rho_f u^2 / d = |drho| g holds to 1e-14
   * over Stokes, intermediate and Newton regimes; rowe is the same correlation. */
  const double dps[] = {1e-7, 1e-5, 1e-4, 5e-4, 1e-3, 3e-3, 5e-3, 1e-2, 5e-2, 0.3};
  for (int i = 0; i < 10; ++i) {
    hs z = H(0.0, dps[i], 2650.0, 998.2, 1.002e-3);
    double u = ut(sn, z), re = z.rho_f * u * z.d_p / z.mu_f;
    double lhs = 0.75 * cd_sn(re) * z.rho_f * u * u / z.d_p, rhs = (z.rho_s - z.rho_f) * z.g;
    if (fabs(re - 1000.0) > 1e-9) CHECK_CLOSE(lhs, rhs, 1e-14);
    CHECK(u > 0.0 && u <= stokes_ut(z) * (1.0 + 1e-15));
    CHECK(ut(rw, z) == u);
    CHECK(vs(sn, z) == u);
  }
  /* Re -> 0: Stokes, to the Schiller-Naumann correction 0.15 Re^0.687 (1e-7 here). */
  hs tiny = H(0.0, 1e-7, 2650.0, 998.2, 1.002e-3);
  CHECK_CLOSE(ut(sn, tiny), stokes_ut(tiny), 2e-7);
  /* Buoyant particles: the same speed, upwards; equal densities or g = 0: no settling. */
  hs up = H(0.0, 1e-3, 998.2 - 500.0, 998.2, 1.002e-3), down = H(0.0, 1e-3, 998.2 + 500.0, 998.2, 1.002e-3);
  CHECK_CLOSE(ut(sn, up), -ut(sn, down), RTOL);
  hs eq = H(0.0, 1e-3, 998.2, 998.2, 1.002e-3);
  CHECK(ut(sn, eq) == 0.0 && sl_tc_status(sn) == 0);
  eq.rho_s = 2650.0, eq.g = 0.0;
  CHECK(ut(sn, eq) == 0.0 && sl_tc_status(sn) == 0);
  /* The C_D jump at Re = 1000: in the gap where no root exists u_t sits at Re_t = 1000 exactly, and
   * u_t stays monotonic in d. */
  double prev = 0.0;
  for (int i = 0; i <= 400; ++i) {
    hs z = H(0.0, 2e-3 * pow(10.0, i / 400.0), 2650.0, 998.2, 1.002e-3);
    double u = ut(sn, z);
    CHECK(u >= prev);
    prev = u;
  }
  /* Slis et al. (1958) nylon (Pringle 2001, Table 5.1) in 20 C water, 3/4/5 mm: 87.9 mm/s (Re 263), 112.6 (449),
   * 135.8 (677). */
  const double dn[] = {3e-3, 4e-3, 5e-3}, un[] = {0.0879, 0.1126, 0.1358}, ren[] = {263.0, 449.0, 677.0};
  for (int i = 0; i < 3; ++i) {
    hs z = H(0.0, dn[i], 1140.0, 998.2, 1.002e-3);
    double u = ut(rw, z);
    CHECK_CLOSE(u, un[i], 6e-4);
    CHECK_CLOSE(998.2 * u * dn[i] / 1.002e-3, ren[i], 2e-3);
  }
  /* Given u_t. */
  CHECK_CLOSE(vs(gv, H(0.0, 1e-4, 2600.0, 1000.0, 1e-3)), 0.0123, RTOL);
  CHECK_CLOSE(vs(gv, H(0.3, 1e-4, 2600.0, 1000.0, 1e-3)), 0.0123 * pow(0.7, 4.65), RTOL);
  sl_tc_close(st);
  sl_tc_close(sn);
  sl_tc_close(rw);
  sl_tc_close(gv);
}

/* ---- Richardson-Zaki ----------------------------------------------------- */

/* n from the hindrance output: f = (1-phi)^n. */
static double exponent_of(sl_tc *t, hs s) { return log(fh(t, s)) / log(1.0 - s.phi); }

/* Given u_t sets Re_t = rho_f u_t d / mu_f = u_t / 1e-3 with rho_f 1000, mu_f 1e-3, d 1e-3. */
static sl_tc *rz_at_re(const char *exponent, double re_t) {
  char u[64], e[96];
  snprintf(u, sizeof u, "u_t=%.17g", re_t * 1e-3);
  snprintf(e, sizeof e, "exponent=%s", exponent);
  return sl_tc_open("hindered_settling", "richardson_zaki", "terminal_velocity=given", u, e, NULL);
}

static void test_richardson_zaki(void) {
  sl_tc *t = sl_tc_open("hindered_settling", "richardson_zaki", NULL);
  /* Values against u_t (1-phi)^n at several states; f -> 1 as phi -> 0; Richardson & Zaki (1954). */
  const double phis[] = {0.0, 1e-9, 0.05, 0.2, 0.45, 0.7, 1.0};
  for (int i = 0; i < 7; ++i) {
    hs s = H(phis[i], 1e-4, 2600.0, 1000.0, 1e-3);
    double u0 = 1600.0 * 9.81 * 1e-8 / 18e-3;
    CHECK_CLOSE(vs(t, s), u0 * exp(4.65 * log1p(-s.phi)), RTOL);
    if (phis[i] < 1.0) check_derivs(t, s);
  }
  CHECK_CLOSE(fh(t, H(1e-9, 1e-4, 2600.0, 1000.0, 1e-3)), 1.0, 1e-8);
  const double a_tab[] = {0.05, 0.10, 0.20, 0.30, 0.40, 0.50, 0.60, 0.65};
  const double rz_tab[] = {0.7878, 0.6127, 0.3543, 0.1904, 0.0930, 0.0398, 0.0141, 0.0076};
  for (int i = 0; i < 8; ++i)
    CHECK_CLOSE(fh(t, H(a_tab[i], 1e-4, 2600.0, 1000.0, 1e-3)), rz_tab[i], 0.00005 / rz_tab[i] + 1e-9);
  /* n given. */
  sl_tc *t24 = sl_tc_open("hindered_settling", "richardson_zaki", "n=2.39", NULL);
  CHECK_CLOSE(exponent_of(t24, H(0.3, 1e-4, 2600.0, 1000.0, 1e-3)), 2.39, 1e-12);
  sl_tc_close(t24);
  /* Richardson & Zaki (1954) correlation at published Re_t. */
  struct {
    double re, D, n;
  } rz[] = {
      {0.1, INFINITY, 4.65},
      {0.1, 0.1, 4.65 + 19.5 * 0.01},
      {0.5, INFINITY, 4.35 * pow(0.5, -0.03)},
      {0.5, 0.05, (4.35 + 17.5 * 0.02) * pow(0.5, -0.03)},
      {50.0, INFINITY, 4.45 * pow(50.0, -0.1)},
      {50.0, 0.1, (4.45 + 18.0 * 0.01) * pow(50.0, -0.1)},
      {300.0, 0.1, 4.45 * pow(300.0, -0.1)},
      {1000.0, 0.01, 2.39},
      {1e5, INFINITY, 2.39},
  };
  for (size_t i = 0; i < sizeof rz / sizeof rz[0]; ++i) {
    sl_tc *c = rz_at_re("richardson_zaki_1954", rz[i].re);
    hs s = H(0.25, 1e-3, 2600.0, 1000.0, 1e-3);
    s.D = rz[i].D;
    CHECK_CLOSE(exponent_of(c, s), rz[i].n, 1e-12);
    check_derivs(c, s);
    sl_tc_close(c);
  }
  /* Low Re, no wall: the classical 4.65; the documented jumps at Re_t = 0.2 and 500. */
  {
    sl_tc *a = rz_at_re("richardson_zaki_1954", 0.2 * (1 - 1e-12)), *b = rz_at_re("richardson_zaki_1954", 0.2);
    hs s = H(0.25, 1e-3, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(exponent_of(a, s), 4.65, 1e-12);
    CHECK_CLOSE(exponent_of(b, s), 4.35 * pow(0.2, -0.03), 1e-12);
    sl_tc_close(a);
    sl_tc_close(b);
    a = rz_at_re("richardson_zaki_1954", 500.0 * (1 - 1e-12));
    CHECK_CLOSE(exponent_of(a, s), 4.45 * pow(500.0, -0.1), 1e-9);
    sl_tc_close(a);
  }
  /* Re_t from the terminal velocity itself: 0.1 mm sand in water, Stokes, Re_t = 0.87 -> n = 4.37. */
  {
    sl_tc *c = sl_tc_open("hindered_settling", "richardson_zaki", "exponent=richardson_zaki_1954", NULL);
    hs s = H(0.3, 1e-4, 2600.0, 1000.0, 1e-3);
    double u = 1600.0 * 9.81 * 1e-8 / 18e-3, re = 1000.0 * u * 1e-4 / 1e-3;
    CHECK_CLOSE(exponent_of(c, s), 4.35 * pow(re, -0.03), 1e-12);
    /* a particle wider than the vessel is refused; D = infinity is allowed */
    s.D = 5e-5, check_refused(c, s);
    s.D = INFINITY;
    CHECK(isfinite(vs(c, s)) && sl_tc_status(c) == 0);
    sl_tc_close(c);
  }
  /* Garside & Al-Dibouni (1977): (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9; n -> 5.1 and 2.7 at the ends. */
  const double ga_re[] = {1e-6, 0.2, 1.0, 10.0, 100.0, 1e3, 1e5};
  for (int i = 0; i < 7; ++i) {
    sl_tc *c = rz_at_re("garside_al_dibouni_1977", ga_re[i]);
    hs s = H(0.25, 1e-3, 2600.0, 1000.0, 1e-3);
    double n = exponent_of(c, s);
    CHECK_CLOSE((5.1 - n) / (n - 2.7), 0.1 * pow(ga_re[i], 0.9), 1e-9);
    if (i == 0) CHECK_CLOSE(n, 5.1, 1e-5);
    if (i == 2) CHECK_CLOSE(n, 5.37 / 1.1, 1e-12);
    if (i == 6) CHECK_CLOSE(n, 2.7, 1e-3);
    sl_tc_close(c);
  }
  /* Packing cut-off: f = (1-phi)^n (1 - phi/phi_max), 0 at phi_max, refused above. */
  sl_tc *pc = sl_tc_open("hindered_settling", "richardson_zaki", "packing_cutoff=true", "phi_max=0.6", NULL);
  const double pphi[] = {0.0, 0.1, 0.35, 0.59};
  for (int i = 0; i < 4; ++i) {
    hs s = H(pphi[i], 1e-4, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(fh(pc, s), pow(1.0 - pphi[i], 4.65) * (0.6 - pphi[i]) / 0.6, RTOL);
    check_derivs(pc, s);
  }
  CHECK(fh(pc, H(0.6, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0 && sl_tc_status(pc) == 0);
  check_refused(pc, H(0.6000001, 1e-4, 2600.0, 1000.0, 1e-3));
  sl_tc_close(pc);
  check_common_refusals(t);
  hs b = H(0.1, 1e-4, 2600.0, 1000.0, 1e-3);
  b.D = 0.0, check_refused(t, b);
  b.D = NAN, check_refused(t, b);
  sl_tc_close(t);
}

/* ---- Michaels-Bolger ----------------------------------------------------- */

static void test_michaels_bolger(void) {
  sl_tc *t = sl_tc_open("hindered_settling", "michaels_bolger", NULL);
  sl_tc *t2 = sl_tc_open("hindered_settling", "michaels_bolger", "phi_max=0.2", "k=5.1", "terminal_velocity=given",
                         "u_t=3e-4", NULL);
  const double phis[] = {0.0, 1e-9, 0.1, 0.32, 0.6, 0.64};
  for (int i = 0; i < 6; ++i) {
    hs s = H(phis[i], 1e-4, 2600.0, 1000.0, 1e-3);
    double u0 = 1600.0 * 9.81 * 1e-8 / 18e-3;
    /* aggregate fraction phi_A = phi / phi_max in Richardson-Zaki's (1 - phi_A)^4.65 */
    double phiA = phis[i] * (1.0 / 0.64);
    CHECK_CLOSE(vs(t, s), u0 * exp(4.65 * log(1.0 - phiA)), 1e-11);
    if (phis[i] < 0.64) check_derivs(t, s);
  }
  CHECK_CLOSE(fh(t, H(1e-9, 1e-4, 2600.0, 1000.0, 1e-3)), 1.0, 1e-8);
  CHECK(fh(t, H(0.64, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0);
  const double phis2[] = {0.0, 0.05, 0.15, 0.2};
  for (int i = 0; i < 4; ++i) {
    hs s = H(phis2[i], 1e-4, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(vs(t2, s), 3e-4 * pow(1.0 - 5.0 * phis2[i], 5.1), 1e-11);
    if (phis2[i] < 0.2) check_derivs(t2, s);
  }
  /* Above phi_max (the parameter, not the declared default) is refused. */
  check_refused(t, H(0.6400001, 1e-4, 2600.0, 1000.0, 1e-3));
  check_refused(t2, H(0.21, 1e-4, 2600.0, 1000.0, 1e-3));
  sl_tc *t7 = sl_tc_open("hindered_settling", "michaels_bolger", "phi_max=0.7", NULL);
  CHECK_CLOSE(fh(t7, H(0.66, 1e-4, 2600.0, 1000.0, 1e-3)), pow(0.04 / 0.7, 4.65), 1e-11);
  sl_tc_close(t7);
  check_common_refusals(t);
  sl_tc_close(t);
  sl_tc_close(t2);
}

/* ---- Nigam ------------------------------------------------------------------ */

/* h = (1 - alpha)^2 / mu(alpha), mu = (1 - alpha/alpha_m)^(-K alpha_m) (Nigam eqs 2.25, 2.36). */
static double nigam_ref(double a, double am, double K) {
  double mu = pow(1.0 - a / am, -K * am);
  return (1.0 - a) * (1.0 - a) / mu;
}

static void test_nigam(void) {
  sl_tc *t = sl_tc_open("hindered_settling", "nigam", NULL);
  const double phis[] = {0.0, 0.05, 0.2, 0.4, 0.6, 0.67};
  for (int i = 0; i < 6; ++i) {
    hs s = H(phis[i], 1e-4, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(vs(t, s), stokes_ut(s) * nigam_ref(phis[i], 0.68, 2.5), 1e-11);
    check_derivs(t, s);
  }
  /* Nigam (1999) eqs 2.18 and 2.36: mu and h at K = 2.5, alpha_m = 0.68. */
  const double a_tab[] = {0.05, 0.10, 0.20, 0.30, 0.40, 0.50, 0.60, 0.65};
  const double h_tab[] = {0.7926, 0.6181, 0.3540, 0.1822, 0.0797, 0.0261, 0.0042, 0.0006};
  for (int i = 0; i < 8; ++i)
    CHECK_CLOSE(fh(t, H(a_tab[i], 1e-4, 2600.0, 1000.0, 1e-3)), h_tab[i], 0.00005 / h_tab[i] + 1e-9);
  /* f -> 1 as phi -> 0 with slope -(2 + K) (an effective Richardson-Zaki n = 4.5); 0 at alpha_m. */
  CHECK_CLOSE(fh(t, H(0.0, 1e-4, 2600.0, 1000.0, 1e-3)), 1.0, RTOL);
  CHECK_CLOSE(dev(t, "hindrance", H(0.0, 1e-4, 2600.0, 1000.0, 1e-3)), -4.5, RTOL);
  CHECK(fh(t, H(0.68, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0 && sl_tc_status(t) == 0);
  CHECK(dev(t, "hindrance", H(0.68, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0);
  /* Kynch flux F = alpha h(alpha) (U_St = 1): maximum 0.07183 at alpha = 0.1732 (K = 2.5) and
   * 0.06938 at 0.1679 (K = 2.6765) (from Nigam 1999, eq 2.36). */
  const char *kp[] = {"intrinsic_viscosity=2.5", "intrinsic_viscosity=2.6765"};
  const double amax[] = {0.1732, 0.1679}, fmax_[] = {0.07183, 0.06938};
  for (int k = 0; k < 2; ++k) {
    sl_tc *c = sl_tc_open("hindered_settling", "nigam", kp[k], "terminal_velocity=given", "u_t=1", NULL);
    double lo = 0.05, hi = 0.35;
    for (int it = 0; it < 200; ++it) { /* bisection on dF/dalpha = h + alpha h' = 0 */
      double m = 0.5 * (lo + hi);
      hs s = H(m, 1e-4, 2600.0, 1000.0, 1e-3);
      if (vs(c, s) + m * dev(c, "settling_velocity", s) > 0.0) lo = m;
      else hi = m;
    }
    double a = 0.5 * (lo + hi);
    CHECK_CLOSE(a, amax[k], 0.00005 / amax[k]);
    CHECK_CLOSE(a * vs(c, H(a, 1e-4, 2600.0, 1000.0, 1e-3)), fmax_[k], 0.000005 / fmax_[k]);
    sl_tc_close(c);
  }
  /* Top-interface speed of the alpha_0 = 0.1 batch test = h(0.1) = 0.61808 (Kynch, Nigam's eq 2.36). */
  CHECK_CLOSE(fh(t, H(0.1, 1e-4, 2600.0, 1000.0, 1e-3)), 0.61808, 1e-5);
  /* Buoyant particles (the thesis's light mixtures) rise: u_St < 0. */
  CHECK(vs(t, H(0.1, 1e-4, 900.0, 1000.0, 1e-3)) < 0.0);
  /* Another packing and K; phi above phi_max refused. */
  sl_tc *c = sl_tc_open("hindered_settling", "nigam", "phi_max=0.6", "intrinsic_viscosity=3", NULL);
  CHECK_CLOSE(fh(c, H(0.3, 1e-4, 2600.0, 1000.0, 1e-3)), nigam_ref(0.3, 0.6, 3.0), 1e-12);
  check_derivs(c, H(0.3, 1e-4, 2600.0, 1000.0, 1e-3));
  check_refused(c, H(0.61, 1e-4, 2600.0, 1000.0, 1e-3));
  sl_tc_close(c);
  check_refused(t, H(0.6800001, 1e-4, 2600.0, 1000.0, 1e-3));
  check_common_refusals(t);
  sl_tc_close(t);
}

/* ---- Vesilind ------------------------------------------------------------------ */

/* u_t 10^(-a phi) with the smooth cut-off (1 - phi/phi_max) or the step to 0 at phi_max. */
static void test_vesilind(void) {
  sl_tc *t = sl_tc_open("hindered_settling", "vesilind", NULL);
  sl_tc *st = sl_tc_open("hindered_settling", "vesilind", "packing_cutoff=step", "a=3", "phi_max=0.5",
                         "terminal_velocity=given", "u_t=2.198e-3", NULL);
  const double phis[] = {0.0, 1e-9, 0.1, 0.32, 0.6, 0.64};
  double u0 = 1600.0 * 9.81 * 1e-8 / 18e-3;
  for (int i = 0; i < 6; ++i) {
    hs s = H(phis[i], 1e-4, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(vs(t, s), u0 * exp(-2.0 * log(10.0) * phis[i]) * (1.0 - phis[i] / 0.64), 1e-12);
    if (phis[i] < 0.64) check_derivs(t, s);
  }
  CHECK(fh(t, H(0.64, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0 && sl_tc_status(t) == 0);
  /* the step: 10^(-3 phi) up to phi_max, exactly 0 there */
  const double phis2[] = {0.0, 0.1, 0.3, 0.4999};
  for (int i = 0; i < 4; ++i) {
    hs s = H(phis2[i], 1e-4, 2600.0, 1000.0, 1e-3);
    CHECK_CLOSE(vs(st, s), 2.198e-3 * pow(10.0, -3.0 * phis2[i]), 1e-12);
    check_derivs(st, s);
  }
  CHECK(vs(st, H(0.5, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0 &&
        dev(st, "settling_velocity", H(0.5, 1e-4, 2600.0, 1000.0, 1e-3)) == 0.0);
  check_refused(t, H(0.6400001, 1e-4, 2600.0, 1000.0, 1e-3));
  check_refused(st, H(0.51, 1e-4, 2600.0, 1000.0, 1e-3));
  check_common_refusals(t);
  sl_tc_close(t);
  sl_tc_close(st);
}

/* Optional outputs may be left out: evaluate with only settling_velocity. */
static void test_optional_outputs(void) {
  const char *names[] = {"richardson_zaki", "michaels_bolger", "nigam", "vesilind"};
  for (int i = 0; i < 4; ++i) {
    sl_tc *t = sl_tc_open("hindered_settling", names[i], NULL);
    const sl_closure_desc *c = t->c->desc;
    double in_v[16], v = NAN, dv = NAN;
    const double *in[16];
    for (int32_t j = 0; j < c->n_in; ++j) in_v[j] = c->in[j].typical, in[j] = &in_v[j];
    double *out[3] = {&v, NULL, NULL};
    double *dout[3 * 16] = {0};
    dout[0 * c->n_in + sl_closure_input(c, "phi")] = &dv;
    sl_error err;
    sl_eval_args a = {.Q = 1, .in = in, .out = out, .dout = dout, .err = &err};
    CHECK(sl_closure_evaluate(t->c, &a) == 0 && isfinite(v) && isfinite(dv));
    CHECK_CLOSE(v, vs(t, H(c->in[0].typical, 1e-4, 2600.0, 1000.0, 1e-3)), 0.0);
    sl_tc_close(t);
  }
}

int main(void) {
  test_terminal_velocity();
  test_richardson_zaki();
  test_michaels_bolger();
  test_nigam();
  test_vesilind();
  test_optional_outputs();
  return sl_test_summary();
}
