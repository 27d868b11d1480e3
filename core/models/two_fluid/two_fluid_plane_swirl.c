/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The swirl of the axisymmetric 2-D two-fluid model ([two_fluid] swirl =
 * true; two_fluid_plane_impl.h): the azimuthal velocities u_theta of both
 * phases in the cells, as the angular velocities Omega = u_theta / r.
 *
 * The theta momentum of phase k (volume fraction alpha_k, viscosity
 * alpha_k mu_k: the model's eps mu_f and its solids viscosity), with the
 * Newtonian stress tau_r_theta = mu r d(u_theta/r)/dr, tau_z_theta = mu
 * du_theta/dz (Bird, Stewart & Lightfoot 2002, Transport Phenomena, Tables
 * B.1 and B.6), multiplied by r, is the conservation of angular momentum
 * r u_theta = r^2 Omega:
 *
 *   d(rho_k alpha_k r^2 Omega_k)/dt + div(rho_k alpha_k u_k r^2 Omega_k)
 *     = div(alpha_k mu_k r^2 grad Omega_k) + K r^2 (Omega_j - Omega_k)
 *
 * (div and grad axisymmetric; the Coriolis term rho u_r u_theta / r is
 * inside the conservative convection). Finite volumes on the cells: the
 * storage at the cell's r^2, the torque through a face alpha mu r_f^2
 * dOmega/dn with r_f the face's radius and alpha mu the mean of its cells,
 * the drag K of the cell (the slip's magnitude with the swirl's), the
 * convection (with [flow] convection only, as the meridional inertia) of
 * the upwind cell's Omega by the phase's mass flux. Both phases in one
 * linear system (2 nc unknowns, KLU; the same pattern every step, zeros
 * where a term is absent), backward Euler, after each converged
 * step at its meridional velocities and phi.
 *
 * Boundaries: a wall holds each phase it holds (no-slip; the solids' free
 * slip carries no torque) at its angular velocity `angular_velocity`
 * (rad/s); an inlet brings no swirl (Omega = 0 on its face); the axis,
 * slip walls, outlets and periodic sides carry no torque; a body's walls
 * ([body], two_fluid_plane_body.c) are walls at its angular_velocity. The
 * swirl is carried along the meridional flow; with [two_fluid] centrifugal
 * it acts back on it through rho alpha u_theta^2 / r in the radial momentum
 * (two_fluid_plane_step.c, at the accepted step's swirl); without, the
 * coupling is one-way.
 *
 * The torque on a wall (a body's, the vessel's): the azimuthal shear stress
 * each phase exerts on it, tau = alpha mu r dOmega/dn (Bird, Stewart &
 * Lightfoot 2002, Table B.1: tau_r_theta = -mu r d(u_theta/r)/dr, the
 * stress on the wall the opposite of the fluid's), taken as the swirl's
 * equation takes it at the wall (the half cell's one-sided difference), and
 * its moment T = integral of r tau dA over the wall (dA = 2 pi r dz on a
 * side, 2 pi r dr on an end). These are the equation's own boundary
 * fluxes: at steady state the torques on all walls add up to zero (the
 * angular momentum the discrete equation conserves). Between coaxial
 * cylinders, the inner one turning at Omega_i, the outer at rest, the
 * exact torque on the inner one is
 *   T = -4 pi mu L Omega_i R_i^2 R_o^2 / (R_o^2 - R_i^2)
 * (2 pi R_i^2 L tau at R_i of Couette's profile; Bird, Stewart & Lightfoot
 * 2002, Example 3.6-3), which tests/scenes/test_body.c checks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"

void tfp_swirl_free(tfp_swirl *w) {
  free(w->buf), free(w->torque);
  sl_triplets_free(&w->trip), sl_csr_free(&w->A);
  if (w->ls) sl_linsolve_destroy(w->ls);
  memset(w, 0, sizeof *w);
}

int tfp_swirl_setup(tfp_model *m, const char *linear, sl_diag *d) {
  tfp_swirl *w = &m->sw;
  const size_t nc = (size_t)m->fv.nc;
  w->on = 1;
  if (!(w->buf = w->om = calloc(8 * nc, sizeof *w->om))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  w->om_new = w->om + 2 * nc, w->rhs = w->om + 4 * nc, w->K = w->om + 6 * nc, w->slip = w->om + 7 * nc;
  if (!(w->torque = calloc(5 * (size_t)m->n_b, sizeof *w->torque)))
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  return sl_linsolve_create(&w->ls, linear, d);
}

/* The phase's viscosity alpha mu in cell c (the model's: eps mu_f; the solids' of tfp_solids_viscosity). */
static double visc(const tfp_model *m, int phase, int c) {
  return phase == 0 ? (1.0 - m->phi_new[c]) * m->c.mu_f : (m->s.any ? m->s.mu[c] : 0.0);
}

/* 1 when the boundary of face f holds phase `phase` at a given angular velocity (*om), 0 when it carries no
   torque. */
static int held(const tfp_model *m, int f, int phase, double *om) {
  int b = m->fv.bound[f];
  *om = 0.0;
  if (b < 0) return 0;
  const tfp_boundary *bd = &m->b[b];
  if (bd->type == TFP_INLET) return 1;
  if (bd->type != TFP_WALL) return 0;
  if (phase == 1 && bd->solids == TFP_SOLIDS_FREE_SLIP) return 0;
  *om = bd->angular_velocity;
  return 1;
}

/* The torques and mean azimuthal stresses of the swirl om_new on the walls (tfp_swirl.torque). */
static void torques(tfp_model *m) {
  tfp_swirl *w = &m->sw;
  const int nc = m->fv.nc, nx = m->fv.nx;
  double *T = w->torque;
  memset(T, 0, 5 * (size_t)m->n_b * sizeof *T);
  for (int f = 0; f < m->fv.nf; ++f) {
    int b = m->fv.bound[f], lo = m->fv.lo[f], hi = m->fv.hi[f], c = lo >= 0 ? lo : hi;
    if (b < 0 || c < 0 || (lo >= 0 && hi >= 0) || m->ftype[f] == TFP_FACE_IMAGE || m->b[b].type != TFP_WALL) continue;
    int dir = f >= m->fv.nfx, i = dir ? (f - m->fv.nfx) % nx : f % (nx + 1);
    double rf = dir ? m->fv.xc[i] : m->grid.xf[i], A = 2.0 * M_PI * m->fv.area[f], om;
    for (int phase = 0; phase < 2; ++phase) {
      if (!held(m, f, phase, &om) || (phase == 1 && !(m->phi_new[c] > 1e-12))) continue;
      double tau = visc(m, phase, c) * rf * (w->om_new[phase * nc + c] - om) / m->fv.dist[f];
      T[5 * b + phase] += A * rf * tau, T[5 * b + 2 + phase] += A * tau;
    }
    T[5 * b + 4] += A;
  }
  for (int b = 0; b < m->n_b; ++b)
    if (T[5 * b + 4] > 0.0) T[5 * b + 2] /= T[5 * b + 4], T[5 * b + 3] /= T[5 * b + 4];
}

int tfp_swirl_step(tfp_model *m, double dt, sl_diag *d) {
  tfp_swirl *w = &m->sw;
  const int nc = m->fv.nc, nf = m->fv.nf, nx = m->fv.nx;
  const double rho[2] = {m->c.rho_f, m->c.rho_s};
  /* the drag of each cell at the slip's magnitude: the meridional slip (the means of the faces) and the swirl's */
  for (int c = 0; c < nc; ++c) {
    int i = c % nx, j = c / nx, fx = i + (nx + 1) * j, fy = m->fv.nfx + i + nx * j;
    double sx = 0.5 * ((m->uf_new[fx] - m->us_new[fx]) + (m->uf_new[fx + 1] - m->us_new[fx + 1]));
    double sy = 0.5 * ((m->uf_new[fy] - m->us_new[fy]) + (m->uf_new[fy + nx] - m->us_new[fy + nx]));
    double st = m->fv.xc[i] * (w->om[c] - w->om[nc + c]);
    w->slip[c] = sqrt(sx * sx + sy * sy + st * st);
    w->om_new[c] = fmax(m->phi_new[c], 1e-6); /* scratch: phi for the drag, floored (K / phi's dilute limit) */
  }
  int rc = tf_closure_eval(&m->c.drag, nc, w->om_new, w->slip, w->K, w->rhs, d);
  if (rc) return sl_diag_prefix(d, rc, "the swirl's drag");
  sl_triplets_clear(&w->trip);
  for (int k = 0; k < 2 * nc; ++k) w->rhs[k] = 0.0;
  for (int c = 0; c < nc && !rc; ++c) {
    double r = m->fv.xc[c % nx], V = m->fv.vol[c], r2V = r * r * V;
    double K = m->phi_new[c] > 1e-12 ? w->K[c] * r2V : 0.0;
    if (tfp_blocked(m, c)) { /* a body's cell turns with it (unused: its faces are the body's walls) */
      rc |= sl_triplets_add(&w->trip, c, c, 1.0), rc |= sl_triplets_add(&w->trip, nc + c, nc + c, 1.0);
      rc |= sl_triplets_add(&w->trip, nc + c, c, -1.0);
      w->rhs[c] = m->b[m->n_b - m->n_bodies + m->fv.blocked[c]].angular_velocity;
      continue;
    }
    for (int phase = 0; phase < 2; ++phase) {
      int row = phase * nc + c;
      double alpha = phase ? m->phi_new[c] : 1.0 - m->phi_new[c];
      double cap = rho[phase] * alpha * r2V / dt;
      /* a cell without solids: their Omega follows the fluid's */
      if (phase == 1 && !(m->phi_new[c] > 1e-12)) {
        rc |= sl_triplets_add(&w->trip, row, row, 1.0), rc |= sl_triplets_add(&w->trip, row, c, -1.0);
        continue;
      }
      rc |= sl_triplets_add(&w->trip, row, row, cap + K);
      rc |= sl_triplets_add(&w->trip, row, (1 - phase) * nc + c, -K);
      w->rhs[row] += cap * w->om[row];
    }
  }
  for (int f = 0; f < nf && !rc; ++f) {
    if (m->ftype[f] == TFP_FACE_IMAGE) continue;
    int lo = m->fv.lo[f], hi = m->fv.hi[f], dir = f >= m->fv.nfx;
    int i = dir ? (f - m->fv.nfx) % nx : f % (nx + 1);
    double rf = dir ? m->fv.xc[i] : m->grid.xf[i], a = m->fv.area[f] * rf * rf / m->fv.dist[f];
    for (int phase = 0; phase < 2; ++phase) {
      const double *u = phase ? m->us_new : m->uf_new;
      if (lo >= 0 && hi >= 0) { /* the same entries every step (the solver keeps the pattern): zeros where none */
        int empty = phase == 1 && !(m->phi_new[lo] > 1e-12 && m->phi_new[hi] > 1e-12);
        double g = empty ? 0.0 : a * 0.5 * (visc(m, phase, lo) + visc(m, phase, hi));
        int rl = phase * nc + lo, rh = phase * nc + hi;
        rc |= sl_triplets_add(&w->trip, rl, rl, g), rc |= sl_triplets_add(&w->trip, rl, rh, -g);
        rc |= sl_triplets_add(&w->trip, rh, rh, g), rc |= sl_triplets_add(&w->trip, rh, rl, -g);
        if (m->convection) { /* the mass flux's angular momentum, of the upwind cell */
          double al = 0.5 * (phase ? m->phi_new[lo] + m->phi_new[hi] : 2.0 - m->phi_new[lo] - m->phi_new[hi]);
          double q = empty ? 0.0 : rho[phase] * al * u[f] * m->fv.area[f] * rf * rf, qp = fmax(q, 0.0),
                 qm = fmin(q, 0.0);
          rc |= sl_triplets_add(&w->trip, rl, rl, qp), rc |= sl_triplets_add(&w->trip, rl, rh, qm);
          rc |= sl_triplets_add(&w->trip, rh, rl, -qp), rc |= sl_triplets_add(&w->trip, rh, rh, -qm);
        }
        continue;
      }
      int c = lo >= 0 ? lo : hi;
      double om;
      if (c < 0) continue;
      int empty = phase == 1 && !(m->phi_new[c] > 1e-12);
      if (held(m, f, phase, &om)) {
        double g = empty ? 0.0 : a * visc(m, phase, c);
        rc |= sl_triplets_add(&w->trip, phase * nc + c, phase * nc + c, g);
        w->rhs[phase * nc + c] += g * om;
      }
      if (m->convection && m->ftype[f] == TFP_FACE_OUTLET) { /* what leaves carries its cell's Omega */
        double al = phase ? m->phi_new[c] : 1.0 - m->phi_new[c];
        double q = empty ? 0.0 : rho[phase] * al * u[f] * m->fv.area[f] * rf * rf * (lo >= 0 ? 1.0 : -1.0);
        rc |= sl_triplets_add(&w->trip, phase * nc + c, phase * nc + c, fmax(q, 0.0));
      }
    }
  }
  if (rc) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory (the swirl's matrix)");
  if ((rc = sl_triplets_to_csr(&w->trip, &w->A, 2 * nc, d))) return rc;
  if ((rc = sl_linsolve_solve(w->ls, &w->A, w->rhs, w->om_new, d))) return sl_diag_prefix(d, rc, "the swirl's solve");
  for (int k = 0; k < 2 * nc; ++k)
    if (!isfinite(w->om_new[k])) return sl_diag_set(d, SL_EFAILED, "the swirl is not finite in cell %d", k % nc);
  torques(m);
  return 0;
}
