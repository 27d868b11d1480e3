/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The mixture (drift-flux) model: the flow of core/models/navier_stokes/flow.h in
 * the volume-averaged velocity j (div j = 0), carrying a solids fraction phi
 * that moves with j plus the hindered-settling flux (Nigam 1999, eqs
 * 2.31-2.36):
 *
 *   rho(phi) (dj/dt + j.grad j) = -grad p + div(2 mu D(j)) + (rho(phi) - rho_f) g,
 *   div j = 0,   dphi/dt + div(phi j + j_R) = 0,   j_R = phi u_settle(phi) b,
 *
 * rho = rho_f + phi (rho_s - rho_f), mu from [closure.viscosity] (inputs
 * phi, shear_rate, density, mu_f), u_settle from
 * [closure.hindered_settling] along b, the body force per unit mass
 * relative to its magnitude g_ref: gravity, plus the centrifugal
 * acceleration in a rotating frame ([flow] rotation), minus Dj/Dt with
 * [mixture] slip_acceleration (Nigam eq 2.25). Optional ([mixture]
 * relative_flux_stress): the stress of the relative motion,
 * -div[rho_f j_R j_R / (phi (1 - phi))] on the right of the momentum
 * (Nigam eq 2.16). Dropped against Nigam (2.31): the epsilon-acceleration
 * terms (his conclusion, for them and the j_R j_R stress: no effect seen in
 * his simulations).
 *
 * Time splitting: every step solves the flow with phi frozen at t_n, then
 * moves phi from t_n to t_n + dt by the finite-volume transport
 * (core/transport) with conservative face fluxes of the new velocity
 * (core/fv/face_flux.h), sub-cycled within its CFL limit. A transport
 * step that fails rejects the whole step, which is retried smaller.
 *
 * Scene sections beyond navier_stokes.h's:
 *   [solid]      density, diameter, phi_max, sphericity
 *   [closure.hindered_settling]   the settling law (none: no settling)
 *   [mixture]    slip_acceleration, reference_acceleration, diffusivity,
 *                relative_flux_stress
 *   [initial]    phi = expression of x, y (cell centroids)
 *   [boundary.N] phi = the solids fraction of inflow, an expression of x, y, t
 *                (open boundaries, and velocity boundaries that give it: inflow.h)
 *   [transport]  order = 1|2, limiter = mc|minmod, cfl
 *   [output]     interface = levels of phi whose heights are reported
 * Output: the cell field phi and, per output time, the attributes
 * solids_inventory, solids_conservation_error and interface_height_<k>. */
#ifndef SLUICE_MODELS_MIXTURE_H
#define SLUICE_MODELS_MIXTURE_H

#include "core/scene/schema.h"
#include "core/time/model.h"

extern const sl_schema sl_mixture_schema;
extern const sl_model_ops sl_mixture_ops;

#endif
