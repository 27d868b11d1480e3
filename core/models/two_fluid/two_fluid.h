/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid model (Eulerian-Eulerian, Pringle 2001), 1-D
 * vertical column. Fluid and solids momentum with one pressure p (Pringle
 * 2001, Table 1.1 and eqs 2.27-2.31; Gidaspow 1994 model A), incompressible phases:
 *
 *   d(phi)/dt + d(phi u_s)/dx = 0,   phi u_s + (1 - phi) u_f = j(t),
 *   rho_s phi du_s/dt       = -phi dp/dx - dp_s/dx + K (u_f - u_s) + phi rho_s g,
 *   rho_f (1-phi) du_f/dt   = -(1-phi) dp/dx       - K (u_f - u_s) + (1-phi) rho_f g,
 *
 * K from [closure.drag] (architecture.md section 4: F_s = K (u_f - u_s)),
 * p_s(phi) from [closure.solids_pressure] (none: p_s = 0), the advective
 * momentum terms dropped as in Pringle's finite-element model ("slow
 * flows", thesis chapter 4). In 1-D the mixture continuity fixes the mixture
 * flux j (the inlet's superficial velocity, 0 in a closed column), so the
 * fluid flux follows from the solids flux (Pringle's V = c, eq 4.43), and
 * eliminating dp/dx leaves one equation for u_s:
 *
 *   [rho_s phi + rho_f phi^2/eps] du_s/dt = -dp_s/dx + K s/eps + phi (rho_s - rho_f) g
 *                                           + phi rho_f/eps dj/dt,
 *   s = u_f - u_s = (j - u_s)/eps,  eps = 1 - phi.
 *
 * Its steady homogeneous state is K s = phi eps (rho_s - rho_f) |g|
 * (eq 4.20 at steady state), U = eps s; at rest dp_s/dx = phi (rho_s - rho_f) g
 * (eq 4.30 at rest). The pressure written is p from the fluid equation.
 *
 * Discretisation (two_fluid_step.c: the 2-D model's step, two_fluid_plane_step.c,
 * on n x 1 cells with column_form): phi as cell averages, u_s and u_f at
 * the faces (the mesh vertices); backward Euler, drag implicit
 * (Newton-linearised in the slip), p_s implicit through its derivative
 * (Pringle 2001 eq 4.31's Taylor expansion about the latest iterate), the
 * step iterated to convergence; phi moved conservatively with the new u_s
 * by bounded upwind (or limited second-order) sub-steps: 0 <= phi <= phi_max
 * whatever dt. An optional particle diffusivity D adds -D dphi/dx to the
 * solids flux: the diffusion term of Pringle's generic conservation law
 * (thesis eq 2.11), which his model drops (he puts D at "order 1e-4 m^2/s",
 * thesis chapter 2). Without it the homogeneous bed of this model is unstable
 * (Jackson 1963, Trans. Instn Chem. Engrs 41:13) wherever no solids pressure
 * holds it, and fine meshes resolve the growing waves.
 *
 * Scene sections:
 *   [scene]   model = two_fluid, geometry = line
 *   [mesh]    generator = interval (x is the height when gravity is -x)
 *   [fluid]   density, viscosity
 *   [solid]   density, diameter, sphericity, phi_max (or porosity_max)
 *   [flow]    gravity = g_x (default -9.81)
 *   [closure.drag]             required
 *   [closure.solids_pressure]  optional
 *   [initial] phi (or porosity) = expression of x, y and case
 *   [boundary.NAME] type = wall | inlet | outlet; inlet: velocity = the
 *             superficial fluid velocity entering, or porosity = that of a
 *             homogeneous bed the inflow holds at rest (the drag's
 *             equilibrium; a bottom inlet), expressions of t and case; solids
 *             held; outlet: pressure (default 0), solids leave if carried
 *   [two_fluid] iterations, tolerance, cfl, steady_tolerance, diffusivity,
 *             order (1 upwind, 2 MUSCL), limiter, case (a number the
 *             expressions read)
 *   [time]    end, dt, dt_min, max_steps
 *   [output]  file, every, fields, interface (levels of phi whose heights
 *             are written as interface_height_K)
 * (the keys' defaults, units and ranges: schema.c) */
#ifndef SLUICE_MODELS_TWO_FLUID_H
#define SLUICE_MODELS_TWO_FLUID_H

#include "core/scene/schema.h"
#include "core/time/model.h"

/* The variants of model = two_fluid: the 1-D column (two_fluid.c), the 2-D
 * model (two_fluid_plane.c, geometry = planar | axisymmetric), the shear
 * layer (shear_layer.c, motion = shear). */
extern const sl_schema sl_two_fluid_column_schema, sl_two_fluid_plane_schema, sl_two_fluid_shear_schema;
extern const sl_model_ops sl_two_fluid_column_ops, sl_two_fluid_plane_ops, sl_two_fluid_shear_ops;

#endif
