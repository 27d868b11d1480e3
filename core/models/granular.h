/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The granular temperature's physics, once for every model that carries a
 * solids phase with [closure.granular]: the 2-D two-fluid model
 * (two_fluid/two_fluid_plane_solids.c), the two-fluid shear layer
 * (two_fluid/shear_layer.c) and the pipe (pipe/pipe_solids.c,
 * pipe/pipe_theta.c). The balance is Krampa (2009) eq 5.10 in the standard
 * form of his section 2.5 (his printed signs corrected; the fluid-particle
 * correlation neglected):
 *
 *   (3/2) rho_s phi dtheta/dt = div(kappa grad theta) + mu_s gdot^2 - gamma - 3 K theta,
 *
 * 3 K theta the drag's sink (Gidaspow 1994, ch. 9), kappa, mu_s and gamma of
 * the closure. Here: the kinetic-scaling check, the algebraic theta (the
 * local balance without conduction: the quadratic of a kinetic closure, or
 * bisection for any closure), the equation's pointwise terms linearised the
 * one way every model uses (Newton in the dissipation, the production and
 * kappa lagged, the drag's sink implicit), the walls' energy flux linearised
 * (Johnson & Jackson 1987: only its sink part implicit) and the positivity
 * bound of an iterate. Each model discretises the conduction on its own grid:
 * the cell-centred ones (2-D model, pipe) with core/fv/cell_scalar.h, the
 * shear layer at its vertices coupled to the momentum by Newton. */
#ifndef SLUICE_MODELS_GRANULAR_H
#define SLUICE_MODELS_GRANULAR_H

#include "core/plugin/point_eval.h"
#include "core/util/diag.h"

/* m^2/s^2: the kinetic closures' lowest valid theta */
#define SL_THETA_FLOOR 1e-12

/* The outputs a model needs of [closure.granular]: mu_s and gamma, and
 * kappa unless with_kappa is 0. 0, or SL_EBADINPUT naming `who` (e.g. "the
 * 2-D model") and the first output missing. */
int sl_granular_require(const sl_point_closure *gran, int with_kappa, const char *who, sl_diag *d);

/* The kinetic scaling the algebraic theta relies on: mu_s ~ sqrt(theta),
 * gamma ~ theta^1.5 (and p_s ~ theta when with_ps) at fixed phi, checked
 * at theta = 1 and 4 with phi = min(phi_max / 2, 0.3) and the other
 * quantities the first point's of qv (nq quantities, phi at iphi, theta at
 * itheta, as bound to the closure). 0, or SL_EBADINPUT naming `where`. */
int sl_granular_check_kinetic(sl_point_closure *gran, int nq, double *const *qv, int iphi, int itheta, double phi_max,
                              int with_ps, const char *where, sl_diag *d);

/* The algebraic granular temperature of a kinetic closure: production
 * equals dissipation and the drag's sink, mu_s0 gdot^2 sqrt(theta) = gamma0
 * theta^1.5 + C theta (mu_s = mu_s0 sqrt(theta), gamma = gamma0
 * theta^1.5, C = 3 K or 0), a quadratic in sqrt(theta) with A = mu_s0
 * gdot^2, B = gamma0; at least SL_THETA_FLOOR. *dlog (may be NULL):
 * d ln sqrt(theta) / d ln gdot (1 without the sink, up to 2 with it). */
double sl_theta_algebraic(double A, double B, double C, double *dlog);

/* mu_s(theta) and gamma(theta) at n points (sl_theta_balance's closure). */
typedef int (*sl_theta_eval_fn)(void *user, const double *theta, double *mu_s, double *gamma, sl_diag *d);

/* The algebraic granular temperature of any closure: mu_s(theta) gd^2 =
 * gamma(theta) + X theta at n points, by 60 bisections in ln theta over
 * [SL_THETA_FLOOR, 100] m^2/s^2 (the left side grows as theta^1/2 for the
 * kinetic theories, the right as theta^3/2 and theta). X [n]: the sinks'
 * coefficients (sl_theta_exchange). lo, hi, mu, gam: scratch [n]; th [n]:
 * the root (the last interval's geometric centre). 0, or eval's error. */
int sl_theta_balance(int n, const double *gd, const double *X, sl_theta_eval_fn eval, void *user, double *lo,
                     double *hi, double *mu, double *gam, double *th, sl_diag *d);

/* (3/2) rho_s phi: the capacity of the theta equation per unit volume. */
double sl_theta_capacity(double rho_s, double phi);

/* The drag's sink coefficient 3 K (0 when interphase dissipation is off). */
double sl_theta_exchange(int on, double K);

/* The theta equation's pointwise terms at one point, per unit volume, as
 * cap dtheta/dt = (conduction) + src - sink theta, linearised about the
 * iterate th: cap = (3/2) rho_s max(phi, 1e-6); src = mu_s gd^2 - gamma +
 * g' th, sink = g' + X, g' = max(dgamma/dtheta, 0) (Newton in the
 * dissipation; the production's theta^1/2, whose derivative is unbounded at
 * theta = 0, lagged). P = mu_s gd^2 the production, X the drag's sink
 * coefficient (sl_theta_exchange). */
void sl_theta_local(double rho_s, double phi, double P, double gam, double dgam, double X, double th, double *cap,
                    double *src, double *sink);

/* The same at n points, P = mu_s gd gd of each. gam may be src and X may be
 * sink (in place). */
void sl_theta_terms(int n, double rho_s, const double *phi, const double *mu_s, const double *gd, const double *gam,
                    const double *dgam, const double *X, const double *th, double *cap, double *src, double *sink);

/* The walls' energy flux q(theta) into the solids (a wall closure's
 * theta_flux, e.g. Johnson & Jackson 1987), linearised about the iterate:
 * q(theta) ~ q - c (theta - theta_it), c = max(-dq/dtheta, 0) the sink part
 * only (the slip's heating goes as theta^1/2, its derivative unbounded at
 * theta = 0). */
static inline double sl_theta_wall_implicit(double dq) { return dq < 0.0 ? -dq : 0.0; }

/* Area A of such a flux added to a row of the theta equation in the form
 * diag theta = rhs (a cell's): rhs += A (q + c theta_it), diag += A c. */
static inline void sl_theta_wall_row(double A, double q, double c, double theta_it, double *rhs, double *diag) {
  *rhs += A * (q + c * theta_it);
  *diag += A * c;
}

/* An iterate's new theta kept positive: at most a fivefold fall from the
 * last iterate's, and at least SL_THETA_FLOOR. */
double sl_theta_bounded(double theta, double last);

#endif
