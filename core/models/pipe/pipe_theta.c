/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's transported granular temperature (`[pipe] granular_temperature = transport`, pipe.h):
 * the steady granular energy balance of Krampa (2009) eq 5.10 in the standard form of his section 2.5 (his
 * printed signs corrected; the fluid-particle correlation neglected, as he did), fully developed, so with no
 * convection:
 *   0 = (1/r) d/dr(r kappa dtheta/dr) + mu_s gdot_s^2 - gamma - 3 K theta
 * (Gidaspow 1994 eq 9.?; the two-fluid model's form, core/models/two_fluid), kappa, mu_s and gamma of
 * [closure.granular]. Where the local balance (pipe_solids.c) takes theta cell by cell, this one carries it
 * over the conduction length sqrt(kappa/(3 K)), of millimetres in the dilute wall layer of 0.5 mm beads, longer
 * than the wall cells there. Newton in the dissipation gamma(theta); mu_s, kappa and K of the last iterate (the
 * production's theta^1/2 lagged). The axis has no flux; the wall is adiabatic unless the solids' wall closure
 * gives theta_flux (Johnson & Jackson 1987, Krampa eq 4.93), then its flux enters the wall cell, its
 * theta-derivative implicit where it is a sink. The pointwise terms, the wall's linearisation and the bound
 * (theta falls at most fivefold an iteration and stays above the closure's floor) are every model's
 * (core/models/granular.h); the solve is the shared cell scalar's (core/fv/cell_scalar.h). */
#include <math.h>

#include "core/models/granular.h"
#include "core/models/pipe/pipe_impl.h"

/* The solids' wall closure's energy flux q into the solids at the wall cell's granular temperature theta, and
   the implicit part c = max(-dq/dtheta, 0) of its linearisation (core/models/granular.h); model C's k_s
   (pipe_ksfs.c) takes it at theta = (2/3) k_s. */
int pipe_theta_wall_flux(pipe *p, double theta, double *q, double *c_implicit, sl_diag *d) {
  const int c = p->n - 1;
  double uw = p->u_wall, ph = p->phi[c], th = fmax(theta, SL_THETA_FLOOR), dq;
  const double *v[PQ_N] = {0};
  v[PQ_SLIP_WALL] = &uw, v[PQ_PHI] = &ph, v[PQ_THETA] = &th;
  sl_point_request rq = {"theta_flux", q, &dq, "theta"};
  int rc = sl_point_eval(&p->walls, 1, v, &rq, 1, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.wall_stress.solids] theta_flux");
  *c_implicit = sl_theta_wall_implicit(dq);
  return 0;
}

static int wall_energy(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  pipe *p = user;
  if (c != p->n - 1 || !p->wall_energy) return 0;
  double th = fmax(p->theta[c], SL_THETA_FLOOR), q, ci;
  int rc = pipe_theta_wall_flux(p, th, &q, &ci, d);
  if (rc) return rc;
  sl_theta_wall_row(p->g.area[p->n], q, ci, th, rhs, diag);
  return 0;
}

int pipe_theta_transport(pipe *p, const double *gd, sl_diag *d) {
  const int n = p->n;
  double *sink = p->buf[1], *cap = p->buf[2], *x = p->buf[3], *mu = p->buf[5], *kap = p->buf[6], *src = p->buf[7];
  for (int i = 0; i < n; ++i) p->theta[i] = fmax(p->theta[i], SL_THETA_FLOOR);
  const double *v[PQ_N] = {0};
  v[PQ_PHI] = p->phi, v[PQ_THETA] = p->theta;
  sl_point_request rq[3] = {{"mu_s", mu, NULL, NULL}, {"kappa", kap, NULL, NULL}, {"gamma", src, x, "theta"}};
  int rc = sl_point_eval(&p->gran, n, v, rq, 3, d);
  if (rc) return sl_diag_prefix(d, rc, "[closure.granular]");
  for (int i = 0; i < n; ++i) sink[i] = sl_theta_exchange(1, p->K[i]);
  sl_theta_terms(n, p->rho_s, p->phi, mu, gd, src, x, sink, p->theta, cap, src, sink);
  /* steady: a pseudo-step far beyond the slowest of the sinks' times */
  sl_cell_scalar_terms t = {.dt = 1e30,
                            .cap = cap,
                            .s_old = p->theta,
                            .k = kap,
                            .source = src,
                            .sink = sink,
                            .boundary = p->wall_energy ? wall_energy : NULL,
                            .boundary_user = p};
  if (p->march.on) { /* the developing pipe's convection (pipe_march.c) */
    pipe_march_theta(p, cap);
    t.dt = 1.0, t.cap = p->march.cap, t.s_old = p->march.s_old, t.flux = p->march.rfs;
  }
  if ((rc = sl_cell_scalar_solve(&p->cs, &t, x, d))) return sl_diag_prefix(d, rc, "pipe: the granular temperature");
  const double w = p->iterations > 0 ? p->relax : 1.0; /* under-relaxed as the velocities */
  for (int i = 0; i < n; ++i) {
    if (!isfinite(x[i]))
      return sl_diag_set(d, SL_EFAILED, "pipe: the granular temperature is not finite at r = %g", p->g.xc[i]);
    double th = sl_theta_bounded(x[i], p->theta[i]);
    p->theta[i] = fmax(p->theta[i] + w * (th - p->theta[i]), SL_THETA_FLOOR);
  }
  return 0;
}
