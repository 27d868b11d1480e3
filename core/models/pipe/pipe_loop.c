/* SPDX-License-Identifier: GPL-2.0-or-later */
/* `[pipe] loop = true`: the recirculating loop of Krampa (2009, section 3.1), an up-flow and a down-flow
 * section at one bulk velocity that share the loop's solids. The solids slip against the fluid (behind it going
 * up, ahead of it going down), so at one solids flux the up-flow section holds more solids than the down-flow
 * one: the loop's nominal fraction C (solids volume over loop volume, Krampa 2009 section 3.2) is the mean of the
 * sections' in-situ fractions, not each one's. The thesis computes its wall stresses with the nominal C in both
 * sections (its eqs 3.6-3.7) and notes that slip raises the up-flow's in-situ fraction at low V (digest section
 * 4.1, "Inputs"; trend (c) of its derived table). With the two sections' in-situ fractions c_u and c_d the
 * average of the manometric gradients is
 *   ((dP/L)_u + (dP/L)_d) / 2 = 2 (tau_u + tau_d) / D + (c_u - c_d) (rho_s - rho_f) g / 2,
 * so the in-situ difference adds to what friction alone gives.
 *
 * The shares: c_u + c_d = 2 C (the two test sections taken as the loop's halves) and equal solids fluxes
 * F = int c_s u_s dA / A in both (the solids' continuity round the loop), solved for c_u by the secant method on
 * F_u - F_d, each evaluation a steady solve of both sections from their last state (pipe_converge). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"

double pipe_solids_flux(const pipe *p) {
  double A = 0.0, F = 0.0;
  for (int i = 0; i < p->n; ++i) A += p->g.vol[i], F += p->g.vol[i] * p->phi[i] * p->us[i];
  return F / A;
}

/* Both sections with this section's share x (the other's 2C - x); the relative difference of their fluxes. */
static int evaluate(pipe *a, double C, double x, double *f, long *its, sl_diag *d) {
  pipe *b = a->other;
  a->phi_target = x, b->phi_target = 2.0 * C - x;
  for (pipe *q = a; q; q = q == a ? b : NULL) {
    int rc = pipe_converge(q, d);
    *its += q->iterations;
    if (rc) return sl_diag_prefix(d, rc, "pipe: the loop's %s section", q->gz < 0.0 ? "up-flow" : "down-flow");
  }
  double Fa = pipe_solids_flux(a), Fb = pipe_solids_flux(b);
  *f = (Fa - Fb) / (0.5 * (fabs(Fa) + fabs(Fb)));
  return 0;
}

int pipe_loop_solve(pipe *a, sl_diag *d) {
  pipe *b = a->other;
  const pipe_config *c = a->cfg;
  const double C = c->solids_fraction, cap = a->phi_max - 0.01, tol = 10.0 * c->tolerance;
  long its = 0;
  double x0 = C, f0 = 0.0, x1, f1 = 0.0;
  a->loop_iterations = 0;
  int rc = evaluate(a, C, x0, &f0, &its, d), ok = a->converged && b->converged;
  if (!a->two_phase || rc || !ok || fabs(f0) <= tol) {
    a->loop_flux_mismatch = a->two_phase ? f0 : 0.0;
    goto done;
  }
  /* the shares that equal the fluxes if the sections' mean solids velocities did not move with them */
  const double lo = fmax(0.0, 2.0 * C - cap), hi = fmin(cap, 2.0 * C);
  double Fa = pipe_solids_flux(a), Fb = pipe_solids_flux(b);
  x1 = fmin(fmax(2.0 * C * Fb / (Fa + Fb), lo), hi);
  for (int k = 0; k < 50; ++k) {
    if ((rc = evaluate(a, C, x1, &f1, &its, d))) break;
    ++a->loop_iterations;
    if (!(ok = a->converged && b->converged) || fabs(f1) <= tol || f1 == f0) break;
    double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1, x1 = fmin(fmax(x2, lo), hi);
  }
  a->loop_flux_mismatch = f1;
done:
  a->iterations = its;
  if (!rc && ok && a->two_phase && fabs(a->loop_flux_mismatch) > tol) {
    a->converged = 0;
    a->change_field = "the sections' solids fluxes", a->change_cell = -1, a->change = fabs(a->loop_flux_mismatch);
  } else if (!rc && !b->converged) {
    a->converged = 0;
    a->change_field = b->change_field, a->change_cell = b->change_cell, a->change = b->change;
  }
  return rc;
}
