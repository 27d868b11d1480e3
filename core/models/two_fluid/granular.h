/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The granular physics of the two-fluid model's solids, once for the 2-D
 * model (two_fluid_plane_solids.c) and the shear layer (shear_layer.c): the
 * quantities their solids closures read, the kinetic-scaling check, the
 * algebraic granular temperature and the pointwise terms of the transported
 * one, (3/2) rho_s phi dtheta/dt = div(kappa grad theta) + mu_k gdot^2 -
 * gamma - 3 K theta (Krampa 2009 eq 5.10 in the standard form, with its
 * printed signs corrected; 3 K theta the drag's sink). Each model discretises the equation on its own grid:
 * the 2-D model in the cells with core/fv/cell_scalar.h, the shear layer at
 * its vertices coupled to the momentum by Newton. */
#ifndef SLUICE_MODELS_TWO_FLUID_GRANULAR_H
#define SLUICE_MODELS_TWO_FLUID_GRANULAR_H

#include "core/plugin/point_eval.h"
#include "core/util/diag.h"

/* The quantities the solids closures are offered, by input name (tf_quantity_names). */
enum { TF_Q_PHI, TF_Q_SLIP, TF_Q_THETA, TF_Q_RHO_F, TF_Q_MU_F, TF_Q_RHO_S, TF_Q_D_P, TF_Q_SPHERICITY, TF_Q_GRAVITY,
       TF_Q_SLIP_WALL, TF_Q_WALL_DISTANCE, TF_Q_SHEAR_RATE, TF_Q_DENSITY, TF_Q_N };
extern const char *const tf_quantity_names[TF_Q_N];

/* m^2/s^2: the kinetic closures' lowest valid theta */
#define TF_THETA_FLOOR 1e-12

/* The kinetic scaling the algebraic theta relies on: mu_s ~ sqrt(theta),
 * gamma ~ theta^1.5 (and p_s ~ theta when with_ps) at fixed phi, checked
 * at theta = 1 and 4 with phi = min(phi_max / 2, 0.3) and the other
 * quantities the first point's of qv. 0, or SL_EBADINPUT naming `where`. */
int tf_granular_check_kinetic(sl_point_closure *gran, double *const *qv, double phi_max, int with_ps,
                              const char *where, sl_diag *d);

/* The algebraic granular temperature of a kinetic closure: production
 * equals dissipation and the drag's sink, mu_s0 gdot^2 sqrt(theta) = gamma0
 * theta^1.5 + C theta (mu_s = mu_s0 sqrt(theta), gamma = gamma0
 * theta^1.5, C = 3 K or 0), a quadratic in sqrt(theta) with A = mu_s0
 * gdot^2, B = gamma0; at least TF_THETA_FLOOR. *dlog (may be NULL):
 * d ln sqrt(theta) / d ln gdot (1 without the sink, up to 2 with it). */
double tf_theta_algebraic(double A, double B, double C, double *dlog);

/* (3/2) rho_s phi: the capacity of the theta equation per unit volume. */
double tf_theta_capacity(double rho_s, double phi);

/* The drag's sink coefficient 3 K (0 when interphase dissipation is off). */
double tf_theta_exchange(int on, double K);

/* An iterate's new theta kept positive: at most a fivefold fall from the
 * last iterate's, and at least TF_THETA_FLOOR. */
double tf_theta_bounded(double theta, double last);

#endif
