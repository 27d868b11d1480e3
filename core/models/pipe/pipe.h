/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The fully developed vertical pipe (`[scene] model = pipe`): turbulent
 * flow of water, or of a slurry by the two-fluid equations, statistically
 * steady and homogeneous along the pipe, so that every field is a function of
 * the radius r alone (Krampa 2009: the
 * streamwise-periodic pipe driven at a given bulk velocity with a fixed solids
 * inventory). The cells of the shared finite-volume layer (core/fv) on an
 * axisymmetric strip of one cell along the axis, graded towards the wall.
 *
 * Axial momentum of each phase (Krampa 2009 eqs 1.4-1.5 with d/dz = 0 but for
 * the pressure gradient G = dP/dz, the same for both phases; z along the
 * flow, g_z the gravity along it: negative in up-flow, positive in down-flow):
 *   0 = -c_f G + (1/r) d/dr(r c_f (mu_f + mu_t) du_f/dr) - K (u_f - u_s) + c_f rho_f g_z
 *   0 = -c_s G + (1/r) d/dr(r mu_s,eff du_s/dr)          + K (u_f - u_s) + c_s rho_s g_z
 * mu_s,eff = c_s rho_s nu_t / sigma_s (the dispersed phase's zero-equation
 * turbulence, Krampa 2009 eq 6.20) + [solid] viscosity + the kinetic theory's
 * mu_s ([closure.granular], granular temperature from its local balance). G is
 * the unknown that makes the mixture's bulk velocity V = (2/R^2) int (c_f u_f +
 * c_s u_s) r dr the given one: one bordered linear system per iteration.
 *
 * Fluid turbulence: k and epsilon of [closure.turbulence] (k_epsilon), phase
 * weighted (Krampa 2009 eqs 4.82-4.83 without the modulation terms, as in his
 * models A and B), with the wall function [closure.wall_stress.fluid]
 * (log_law: Krampa 2009 eqs 4.84-4.86) at the first cell: the wall stress on
 * the fluid, k and epsilon of that cell.
 *
 * Radial solids balance (two-phase): nothing crosses a radius, so the radial
 * momentum of the phases reduces, with the fluid's eliminated, to a zero net
 * radial solids flux: the turbulent dispersion (Burns et al. 2004: F_TD =
 * -K (nu_t/sigma_d)(grad c_s/c_s - grad c_f/c_f)) against the gradient of the
 * solids pressure (p_s(c_s) of [closure.solids_pressure] and the kinetic
 * theory's p_s(c_s, theta)):
 *   c_s v - D c_s' = 0,  D = nu_t/sigma_d + c_s c_f^2 (dp_s/dc_s)/K,
 *   v = -c_f^2 (dp_s/dtheta) theta'/K,
 * solved as a steady conservative cell scalar with no flux at the axis and the
 * wall, which keeps the section-mean solids fraction at the given one.
 *
 * Outputs: fields velocity_fluid, velocity_solid, phi, k, epsilon, mu_t,
 * theta; scalars pressure_gradient (-dP/dz), manometric_gradient (-dP/dz +
 * rho_f g_z: the water hydrostatics removed, Krampa 2009 eqs 3.6-3.7),
 * wall_shear_stress_fluid, wall_shear_stress_solid, i_m = 4 tau_w/(rho_f g D),
 * friction_factor (Fanning, tau_w/(rho_f V^2/2)), reynolds, y_plus (first
 * cell), phi_mean, phi_chord (the diameter-chord average),
 * velocity_solid_04, velocity_solid_08 (at r/R = 0.4 and 0.8), solids_mean_velocity. */
#ifndef SLUICE_MODELS_PIPE_H
#define SLUICE_MODELS_PIPE_H

#include "core/scene/schema.h"
#include "core/time/model.h"

extern const sl_schema sl_pipe_schema;
extern const sl_model_ops sl_pipe_ops;

#endif
