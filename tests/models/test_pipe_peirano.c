/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Model C's solids viscosity (core/models/pipe/pipe_peirano.c: Peirano & Leckner 1998, Krampa 2009 eqs 5.15-5.19,
 * Tchen's equilibrium k_s and k_fs) against its exact limits and the printed formulas:
 *  - fine particles (t_p -> 0, the drag K large) at zero slip follow the fluid: nu_st = (2/3) t_fs k = C_mu k^2/eps
 *    (the fluid's eddy viscosity), to 1e-9 at t_p/t_fs = 1e-12;
 *  - without collisions (c_s -> 0): nu_s = (1/3)(t_fs k_fs + t_p k_s), Simonin's dilute form, to 1e-9;
 *  - at a dense state (c_s = 0.3, e = 0.9) the value of eqs 5.15-5.19 written out here term by term with the
 *    printed t_p in the denominators (1/t_p, t_fs/t_p), to 1e-12;
 *  - the crossing-trajectory effect lowers it: t_fs falls as (1 + C_beta 3 s^2/(2k))^(-1/2) (eq 4.61);
 *  - in the pipe, vertical_pipe.ini without [closure.granular] and solids_viscosity = peirano_leckner converges
 *    with the mixture's momentum held; with [closure.granular] the scene is refused (exit 2). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"
#include "pipe_testing.h"
#include "testing.h"

static const double PI = 3.14159265358979323846;

int main(void) {
  pipe_pl_point q = {.phi = 1e-12,
                     .k = 0.02,
                     .eps = 0.5,
                     .slip2 = 0.0,
                     .K = 1e30,
                     .rho_s = 2500.0,
                     .d_p = 5e-4,
                     .phi_max = 0.63,
                     .restitution = 0.9,
                     .c_mu = 0.09,
                     .c_beta = 0.45};
  /* fine particles: t_p = c_s rho_s/K -> 0 */
  q.phi = 1e-6, q.K = q.phi * q.rho_s / 1e-12;
  double st, nu = pipe_peirano_leckner(&q, &st), nut = q.c_mu * q.k * q.k / q.eps;
  printf("fine particles: nu_st %.12g against C_mu k^2/eps %.12g (%.2e)\n", st, nut, st / nut - 1.0);
  CHECK_MSG(fabs(st / nut - 1.0) < 1e-9, "nu_st %.12g against %.12g", st, nut);
  CHECK_MSG(fabs(nu / nut - 1.0) < 1e-5, "nu_s %.12g against %.12g (c_s = 1e-6)", nu, nut);
  /* dilute: no collisions; t_p of 0.5 mm beads, K = 150 phi^2 mu/((1-phi) d^2) + ... taken as given */
  q.phi = 1e-13, q.K = q.phi * q.rho_s / 0.05; /* t_p = 0.05 s; the collisions are O(c_s) */
  double tfs = q.c_mu * 1.5 * q.k / q.eps, tp = 0.05, er = tfs / tp;
  double kfs = 2.0 * q.k * er / (1.0 + er), ks = q.k * er / (1.0 + er), dil = (tfs * kfs + tp * ks) / 3.0;
  nu = pipe_peirano_leckner(&q, &st);
  printf("dilute: nu_s %.12g against (1/3)(t_fs k_fs + t_p k_s) %.12g (%.2e)\n", nu, dil, nu / dil - 1.0);
  CHECK_MSG(fabs(nu / dil - 1.0) < 1e-9, "dilute nu_s %.12g against %.12g", nu, dil);
  /* dense: the printed eqs 5.15-5.19 term by term */
  q.phi = 0.3, q.K = 2.0e5, q.slip2 = 0.04 * 0.04;
  const double e = q.restitution, cs = q.phi, d = q.d_p;
  tfs = q.c_mu * 1.5 * q.k / q.eps / sqrt(1.0 + q.c_beta * 1.5 * q.slip2 / q.k), tp = cs * q.rho_s / q.K;
  er = tfs / tp, kfs = 2.0 * q.k * er / (1.0 + er), ks = q.k * er / (1.0 + er);
  double g0 = pow(1.0 - cs / q.phi_max, -2.5 * q.phi_max);                                        /* 4.91 */
  double A = 0.4 * (1.0 + e) * (3.0 * e - 1.0), B = 0.2 * (1.0 + e) * (3.0 - e);                  /* 5.18 */
  double tc = sqrt(PI) / (24.0 * cs * g0) * d * sqrt(3.0 / (2.0 * ks));                           /* 5.19 */
  double nst = (2.0 / 3.0) * ((tfs / tp) * kfs + (1.0 + cs * g0 * A) * ks) / (2.0 / tp + B / tc); /* 5.17 / rho_s */
  double nsc = (8.0 / 5.0) * cs * g0 * 0.5 * (1.0 + e) * (nst + d * sqrt(2.0 * ks / (3.0 * PI))); /* 5.16 */
  nu = pipe_peirano_leckner(&q, &st);
  printf("dense (c_s 0.3): nu_s %.12g m2/s (kinetic %.6g, collisional %.6g), eqs 5.15-5.19 %.12g (%.2e)\n", nu, st,
         nu - st, nst + nsc, nu / (nst + nsc) - 1.0);
  CHECK_MSG(fabs(nu / (nst + nsc) - 1.0) < 1e-12, "dense nu_s %.15g against %.15g", nu, nst + nsc);
  CHECK_MSG(fabs(st / nst - 1.0) < 1e-12, "dense nu_st %.15g against %.15g", st, nst);
  /* the crossing trajectories */
  double nu0 = nu;
  q.slip2 = 0.5 * 0.5;
  nu = pipe_peirano_leckner(&q, NULL);
  printf("slip 0.04 -> 0.5 m/s: nu_s %.6g -> %.6g\n", nu0, nu);
  CHECK_MSG(nu < nu0, "the crossing trajectories raised nu_s: %.6g -> %.6g", nu0, nu);

  /* in the pipe: model C's solids viscosity on vertical_pipe.ini without the kinetic theory */
  static char text[8192], model_c[8192];
  if (pipe_vertical_without_granular(text, sizeof text, model_c, sizeof model_c)) return sl_test_summary();
  const char *sets[] = {"pipe.solids_viscosity=peirano_leckner", NULL};
  sluice_error err = {0, ""};
  int rc = pipe_run_text(model_c, "vertical_pipe.ini", sets, "pipe_pl.h5", &err);
  CHECK_MSG(rc == 0, "model C's solids viscosity: %s", err.msg);
  if (!rc) {
    double G = pipe_scalar("pipe_pl.h5", "pressure_gradient"),
           tf = pipe_scalar("pipe_pl.h5", "wall_shear_stress_fluid");
    double ts = pipe_scalar("pipe_pl.h5", "wall_shear_stress_solid"), rho_f = 997.56,
           rho_m = 0.25 * 2500.0 + 0.75 * rho_f;
    double bal = 4.0 * (tf + ts) / 0.0532 + rho_m * 9.81;
    printf(
        "vertical_pipe.ini, solids_viscosity = peirano_leckner: -dP/dz %.3f Pa/m, the mixture's momentum %.3f "
        "(%.2e)\n",
        G, bal, G / bal - 1.0);
    CHECK_MSG(fabs(G / bal - 1.0) < 1e-8, "-dP/dz %.9g against 4 tau_w/D + rho_m g %.9g", G, bal);
  }
  rc = pipe_run_text(text, "vertical_pipe.ini", sets, "pipe_pl_bad.h5", &err);
  printf("with [closure.granular]: %d, %s\n", rc, err.msg);
  CHECK_MSG(rc == 2 && strstr(err.msg, "peirano_leckner"), "rc %d: %s", rc, err.msg);
  return sl_test_summary();
}
