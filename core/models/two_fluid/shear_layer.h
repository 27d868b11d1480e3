/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid shear layer: fluid and solids moving across a 1-D mesh, in
 * the direction perpendicular to it, between two walls (`[two_fluid] motion
 * = shear`). Planar (a Couette gap, x across it) or annular (`cross_section
 * = annular`: x is the radius, the motion is the swirl between coaxial
 * cylinders). The solids fraction is held (nothing moves across the layer);
 * the granular temperature theta is solved when a kinetic-theory closure
 * gives the solids viscosity.
 *
 * Tangential momentum of each phase (Gidaspow 1994, Multiphase Flow and
 * Fluidization, eqs 9.5-9.6 reduced to one velocity component u(x); Krampa
 * 2009 eqs 1.1-1.5), with the shear stress tau = mu du/dx (planar) or
 * tau = mu r d(u/r)/dr (annular):
 *   rho_f (1-phi) du_f/dt = (1/r^m) d(r^m tau_f)/dx - K (u_f - u_s),  mu = (1-phi) mu_f
 *   rho_s phi     du_s/dt = (1/r^m) d(r^m tau_s)/dx + K (u_f - u_s),  mu = mu_s
 * (m = 0 planar, 2 annular), K from [closure.drag]. mu_s, the solids
 * phase's viscosity, is the sum of [solid] viscosity (a constant, default 0:
 * stresses carried through the fluid, such as Bagnold's macro-viscous one),
 * the part mu_m - (1 - phi) mu_f of a suspension viscosity mu_m from
 * [closure.viscosity] (Krieger-Dougherty, Pringle's granular fit, ...; at
 * the solids shear rate) and, with [closure.granular], the kinetic
 * theory's, whose production alone heats the particles: the granular
 * energy balance (Krampa 2009 eq
 * 5.10 in the standard form (section 5.1.2; the printed
 * production and dissipation signs are inverted)
 *   (3/2) rho_s phi dtheta/dt = (1/r^n) d(r^n kappa dtheta/dx)/dx + mu_s gdot^2 - gamma - 3 K theta
 * (n = 0 planar, 1 annular; gdot the solids shear rate; the last term the
 * interphase dissipation with the fluid-particle velocity correlation
 * neglected: -3 beta Theta of Gidaspow 1994, Multiphase Flow and
 * Fluidization, chapter 9, as in the MFIX theory guide, Syamlal, Rogers &
 * O'Brien 1993, DOE/METC-94/1004; Krampa 2009 section 5.1.2 also drops
 * the correlation; off with
 * `interphase_dissipation = false`), or, with `granular_temperature =
 * algebraic`, its local balance mu_s gdot^2 = gamma + 3 K theta
 * (conduction and storage dropped; van Wachem et al. 2001).
 *
 * Walls ([boundary.NAME], both ends): the fluid sticks to the wall's speed
 * `velocity` (an expression of t; annular: the surface speed, omega r); the
 * solids `solids = no_slip | free_slip | wall_stress`, the last taking the
 * stress from [closure.wall_stress]. A wall closure with a wall_distance
 * input (Bagnold, Bartosik) is a wall function: its slip is the solids
 * velocity at the first node off the wall, over that node's distance, and
 * the node's control volume reaches the wall; otherwise (Johnson & Jackson,
 * Navier slip) the slip is the solids velocity at the wall. A closure giving
 * theta_flux sets the granular-energy flux through the wall; without it the
 * wall is adiabatic.
 *
 * Discretisation: u_f and u_s by vertex-centred finite volumes (the P1
 * lumped-mass analogue) at the vertices, phi and theta in the cells: the
 * cells and vertices are the n x 1 staggered grid of core/fv/grid.h
 * (velocities on the faces, scalars in the cells). The annular cell stress
 * uses the exact conductance of the Couette profile, r^2 tau = 2 mu (u/r|_i+1
 * - u/r|_i) / (r_i^-2 - r_i+1^-2), and the cell's viscous production G^2/(mu
 * g), exact for Couette flow in both geometries. Backward Euler; within a
 * step each iteration solves u_f and u_s by Newton (a 2x2
 * block-tridiagonal system) in the drag and the wall stress, the solids
 * viscosity of the iterate's theta, then theta in the cells: transported,
 * by the shared cell scalar (core/fv/cell_scalar.h) with the pointwise
 * terms and the walls' energy flux of every model (core/models/granular.h:
 * Newton in the dissipation; kappa, the drag's sink and the production
 * lagged), the 2-D model's scheme; or algebraic, the local balance at the
 * cell's shear rate. The wall stress sees the theta of its wall's cell.
 *
 * Output: cell fields phi, theta (and solids_pressure), node fields
 * velocity_fluid, velocity_solid;
 * with each output time, per wall NAME, the scalars
 * wall_shear_stress_fluid_NAME and wall_shear_stress_solid_NAME (the
 * stress each phase exerts on the wall, along the motion), wall_slip_NAME
 * (the solids slip the wall condition sees) and, annular, torque_NAME (per
 * metre of height, 2 pi r^2 times the sum of the two stresses); with a
 * closure that gives it, bagnold_number_NAME. */
#ifndef SLUICE_MODELS_SHEAR_LAYER_H
#define SLUICE_MODELS_SHEAR_LAYER_H

#include "core/scene/schema.h"

/* A wall of the layer, as the scene gives it (schema.c). */
typedef struct sh_boundary {
  int type;               /* wall */
  sl_scene_expr velocity; /* the wall's speed, of t */
  int solids;             /* no_slip | free_slip | wall_stress */
} sh_boundary;

#endif
