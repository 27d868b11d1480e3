/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Single-sphere drag correlations, the terminal velocity of a sphere and the
 * input range check shared by the drag and hindered-settling closures.
 * Header-only (static inline), no state, no link to anything but libm; a
 * closure including it still depends on nothing but <sluice/closure.h>.
 *
 * Schiller & Naumann (1933), Z. Ver. Dtsch. Ing. 77:318; quoted by Rowe
 * (1961), Trans. Inst. Chem. Eng. 39:175, with the Newton-regime value 0.44
 * above Re = 1000 (Pringle 2001 eqs 3.24-3.25; Gidaspow 1994 ch. 5):
 *   C_D = 24/Re (1 + 0.15 Re^0.687)  for Re < 1000,   C_D = 0.44  for Re >= 1000.
 * Rowe's correlation as printed by Pringle is the same function, so the
 * `rowe` and `schiller_naumann` choices of the closures give identical
 * numbers; both names are kept so that a scene can say which source it
 * follows. C_D jumps by +0.39 % at Re = 1000 (0.4383 -> 0.44).
 *
 * Dallavalle (1948), Micromeritics, Pitman: C_D = (0.63 + 4.8/sqrt(Re))^2
 * (used by Di Felice 1994 and Syamlal & O'Brien 1988).
 *
 * Everything is written as C_D Re (finite at Re = 0) and Re d(C_D Re)/dRe
 * (also finite at Re = 0), so that a closure can form dK/dphi at rest
 * without a 0/0. dK/dslip itself is infinite at slip = 0 for these
 * correlations (K ~ K0 + c slip^0.687 or slip^0.5); the closures report 0
 * there, which gives the force F = K slip its exact Jacobian K(0) I. */
#ifndef SLUICE_PLUGINS_SPHERE_DRAG_H
#define SLUICE_PLUGINS_SPHERE_DRAG_H

#include <math.h>
#include <sluice/closure.h>

#define SL_PI 3.14159265358979323846

/* Schiller-Naumann drag factor f = C_D Re / 24 (f = 1 is Stokes drag).
 * *re_df receives Re df/dRe. */
static inline double sl_sn_factor(double re, double *re_df) {
  if (re < 1000.0) {
    double p = pow(re, 0.687);
    *re_df = 0.15 * 0.687 * p;
    return 1.0 + 0.15 * p;
  }
  *re_df = 0.44 * re / 24.0;
  return 0.44 * re / 24.0;
}

/* Dallavalle: G = C_D Re = (0.63 sqrt(Re) + 4.8)^2; *re_dg = Re dG/dRe. */
static inline double sl_dallavalle_cdre(double re, double *re_dg) {
  double s = sqrt(re);
  double b = 0.63 * s + 4.8;
  *re_dg = 0.63 * s * b;
  return b * b;
}

/* Terminal Reynolds number of a sphere with the Schiller-Naumann/Rowe C_D:
 * the root of C_D(Re) Re^2 = (4/3) Ar, Ar = rho_f |rho_s - rho_f| g d^3 / mu^2
 * (the buoyant weight balancing the drag, (3/4) C_D rho_f u^2 / d = |drho| g).
 * For Re < 1000 this is F(Re) = 24 Re + 3.6 Re^1.687 = (4/3) Ar, F convex
 * and increasing: Newton from the larger of two upper bounds (F >= 24 Re and
 * F >= 3.6 Re^1.687) converges monotonically, to 1e-15 relative in a few
 * steps. Above F(1000) the Newton law Re = sqrt((4/3) Ar / 0.44); in the
 * narrow gap where neither branch has a root (the C_D jump at Re = 1000,
 * 438 291 < (4/3) Ar < 440 000) Re = 1000. */
static inline double sl_sn_terminal_re(double ar) {
  double c = 4.0 / 3.0 * ar;
  if (!(c > 0.0)) return 0.0;
  double c1000 = 24.0e3 + 3.6 * pow(1000.0, 1.687);
  if (c >= c1000) {
    double re = sqrt(c / 0.44);
    return re > 1000.0 ? re : 1000.0;
  }
  double x = fmin(c / 24.0, pow(c / 3.6, 1.0 / 1.687));
  for (int it = 0; it < 200; ++it) {
    double p = pow(x, 0.687);
    double dx = (24.0 * x + 3.6 * x * p - c) / (24.0 + 3.6 * 1.687 * p);
    x -= dx;
    if (!(fabs(dx) > 1e-15 * x)) break;
  }
  return x;
}

/* Choices of the `terminal_velocity` parameter. */
enum { SL_UT_GIVEN = 0, SL_UT_STOKES = 1, SL_UT_SCHILLER_NAUMANN = 2, SL_UT_ROWE = 3 };
#define SL_UT_CHOICES "given|stokes|schiller_naumann|rowe"

/* Terminal velocity of one sphere of diameter d, signed: positive along the
 * body force when rho_s > rho_f, negative for buoyant particles, 0 when the
 * densities are equal or g = 0. *re_t receives rho_f |u_t| d / mu. */
static inline double sl_terminal_velocity(int32_t mode, double u_given, double d, double rho_s, double rho_f, double mu,
                                          double g, double *re_t) {
  double drho = rho_s - rho_f, u;
  if (mode == SL_UT_GIVEN) {
    u = u_given;
  } else if (mode == SL_UT_STOKES) {
    u = drho * g * d * d / (18.0 * mu);
  } else {
    double ar = rho_f * fabs(drho) * g * d * d * d / (mu * mu);
    double re = sl_sn_terminal_re(ar);
    u = re * mu / (rho_f * d);
    if (drho < 0.0) u = -u;
  }
  *re_t = rho_f * fabs(u) * d / mu;
  return u;
}

/* Checks inputs first..n-1 of point q against their declared closed ranges
 * [valid_min, valid_max]. NaN fails, and so does an infinite value, except
 * for input `inf_ok` (-1: none), which may be +infinity when its declared
 * upper bound is (a vessel diameter D -> infinity). The first failing input
 * is reported; returns SL_OK or the sl_fail() code. */
static inline int sl_check_inputs_from(const sl_field_desc *f, int32_t first, int32_t n, const sl_eval_args *a,
                                       int32_t q, int32_t inf_ok) {
  for (int32_t i = first; i < n; ++i) {
    double x = a->in[i][q];
    if (!(x >= f[i].valid_min && x <= f[i].valid_max) || (isinf(x) && i != inf_ok))
      return sl_fail(a->err, SL_RECOVERABLE, q, "%s = %g outside its validity range [%g, %g]", f[i].name, x,
                     f[i].valid_min, f[i].valid_max);
  }
  return SL_OK;
}

/* All n inputs of point q. */
static inline int sl_check_inputs(const sl_field_desc *f, int32_t n, const sl_eval_args *a, int32_t q, int32_t inf_ok) {
  return sl_check_inputs_from(f, 0, n, a, q, inf_ok);
}

#endif
