/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Incompressible flow of a generalized-Newtonian fluid on Taylor–Hood
 * pairs: the residual and its Jacobian (Newton) or its Oseen/Picard
 * linearisation, for
 *
 *   rho (du/dt + (u.grad)u + 2 Omega x u) - div(2 mu(gamma) D(u)) + grad p = f - div T,
 *   div u = 0,             gamma = sqrt(2 D(u):D(u)) (the shear rate),
 *
 * with T an optional given stress (the mixture model's relative-flux
 * stress), in 2-D planar, axisymmetric (r, z) and 1-D geometry.
 *
 * Velocity components (th->n_comp): the dim in-plane ones, plus optionally
 * one normal to the plane (n_comp == dim + 1): in a planar scene the
 * out-of-plane velocity w(x, y) of a fully developed flow (a pipe or channel
 * cross-section); in an axisymmetric one the swirl u_theta(r, z). Nothing
 * varies along the out-of-plane direction. All tensors are built in the
 * orthonormal frame (e_0, e_1, e_2) = (x, y, out of plane), or (r, z, theta)
 * axisymmetric, where the velocity gradient of an axisymmetric field gains
 * the hoop entries  G_theta,theta = u_r / r  and  G_r,theta = -u_theta / r
 * (Bird, Stewart & Lightfoot, Transport Phenomena, 2nd ed. 2002, appendix
 * A.7, the components of grad v in cylindrical coordinates, d/dtheta = 0). With them the convective
 * term G u holds the centrifugal -u_theta^2/r and Coriolis u_r u_theta/r
 * accelerations, D(u) the hoop strain u_r/r, and tr G = div u the 1/r term
 * of the axisymmetric divergence.
 *
 * Time derivatives come from the integrator as du/dt ~ mass_coef u + history
 * (BDF: mass_coef = alpha_0 / dt, history = sum_k alpha_k u^{n+1-k} / dt).
 *
 * The viscosity callback writes TWO numbers per quadrature point: mu and
 * d mu / d gamma, so that regularised yield-stress laws get a consistent
 * Jacobian. It sees the shear rate of the current iterate in
 * batch->shear_rate and is called once per batch of quadrature points. */
#ifndef SLUICE_ASSEMBLY_FLOW_H
#define SLUICE_ASSEMBLY_FLOW_H

#include "core/assembly/operators.h"

typedef enum sl_flow_linearisation {
  SL_FLOW_RESIDUAL = 0, /* b = -R(u) only; the matrix is not touched */
  SL_FLOW_NEWTON,       /* A = dR/du, b = -R(u) */
  SL_FLOW_PICARD,       /* A = the Oseen operator with frozen mu and advecting velocity */
  SL_FLOW_LOAD          /* b = the part of -R that does not depend on u (the history term, the body force
                           with the centrifugal one, the extra stress); the matrix is not touched, u is not
                           read, the viscosity not evaluated. For a problem linear in u with A = dR/du:
                           -R(u) = b - A u */
} sl_flow_linearisation;

typedef struct sl_flow_opts {
  int axisymmetric;   /* x is r; needs r >= 0 */
  sl_coef density;    /* rho > 0, kg m^-3 */
  sl_qp_fn viscosity; /* out[2 i] = mu, out[2 i + 1] = d mu / d gamma; NULL: viscosity_value */
  void *viscosity_user;
  double viscosity_value;
  int convection; /* assemble rho (u.grad) u */
  double omega;   /* frame rotation (rad/s) about e_2 (planar: the axis through rotation_centre;
                            axisymmetric: the symmetry axis); adds Coriolis and centrifugal forces */
  double rotation_centre[2];
  /* The density rho_0 whose centrifugal force the pressure takes: the body force is (rho - rho_0) Omega^2 r and
   * the pressure solved for is p - P_ref, P_ref = rho_0 Omega^2 |r|^2 / 2 (the caller adds P_ref back where it
   * writes the pressure and gives natural boundaries the traction P_ref n). A quadratic P_ref is not in the
   * pressure space: taking it out keeps its discretisation error, O(h^2) rho_0 Omega^2, out of a rapidly
   * rotating flow driven by rho - rho_0 alone. 0: the full rho Omega^2 r. */
  double centrifugal_density;
  sl_qp_fn body_force; /* f (N m^-3), n_comp per point in the velocity's components; NULL: none */
  void *body_force_user;
  /* A given symmetric stress T (Pa) in the momentum as -div T, weakly b += int T : grad(v) (natural form: a
   * traction boundary prescribes (sigma - T) n); right-hand side only. Given in the pressure space (continuous,
   * order 1), 6 values per pressure dof: the entries 00, 11, 22, 01, 02, 12 in the frame (e_0, e_1, e_2)
   * (axisymmetric: r, z, theta). There the pressure can balance it exactly: a T = -p I + const of that space
   * leaves the velocity at rest. NULL: none. */
  const double *extra_stress;
  /* A linear momentum sink per cell: the momentum gains + K u (a force -K u), K constant in each cell, its 2 x 2
   * in-plane entries K_00, K_01, K_10, K_11 (kg m^-3 s^-1, the frame axes e_0, e_1; a 1-D mesh reads K_00 only),
   * assembled into the matrix and the residual; not symmetric in general. The mixture model's buoyancy over the
   * step comes so (its linearised change with the velocity that transports phi). NULL: none. */
  const double *cell_drag;
  double mass_coef;      /* 0: steady */
  const double *history; /* combined numbering (velocity part read); NULL: zero */
  int quad_degree;       /* 0: 5 planar (exact for the Q2 convective term on affine cells), 7 axisymmetric */
  /* The momentum equations alone (a split step's velocity solve): the system has the velocity dofs only
   * (th->p_offset of them, per cell the th->n_comp * th->vel->dofs_per_cell velocity dofs that lead
   * th->cell_dofs), its matrix the velocity block of the matrix the full assembly gives, b the momentum rows
   * of its -R(u) (u in the combined numbering: the pressure of u enters them); no continuity rows, no
   * pressure columns. 0: the whole system. */
  int velocity_block;
} sl_flow_opts;

/* Assembles at the iterate u (combined numbering, th->n_dofs): b = -R(u) and,
 * unless lin == SL_FLOW_RESIDUAL, the matrix. The system must come from th
 * and be zeroed by the caller (this function adds). Returns 0 or an SL_E*
 * code: a coefficient callback's code passes through with its message. */
int sl_assemble_flow(sl_system *s, const sl_th_space *th, const double *u, const sl_flow_opts *o,
                     sl_flow_linearisation lin, sl_diag *d);

/* Checks that the options fit the space (components, geometry, rotation):
 * the messages a scene set-up should give before assembling. */
int sl_flow_check_geometry(const sl_th_space *th, const sl_flow_opts *o, sl_diag *d);

/* Natural (traction) boundary condition: b += int_G t.v ds (r ds
 * axisymmetric) over the named boundary, t = (sigma - p I) n the traction
 * the outside exerts, n_comp values per point from the callback, which
 * sees the outward normals in batch->normal (an open outlet: t = 0, i.e.
 * nothing to assemble; a prescribed pressure p0: t = -p0 n). Faces are
 * integrated with 3 Gauss points (exact for quadratic t on straight edges). */
int sl_assemble_flow_traction(sl_system *s, const sl_th_space *th, const char *boundary, sl_qp_fn traction, void *user,
                              int axisymmetric, sl_diag *d);

/* Per-cell averages over the quadrature points of the shear rate and the
 * viscosity, and the fraction of points where the stress mu gamma exceeds
 * yield_stress (the `yielded` field; pass yield_stress <= 0 to get 1
 * everywhere). Any output may be NULL. */
int sl_flow_cell_diagnostics(const sl_th_space *th, const double *u, const sl_flow_opts *o, double yield_stress,
                             double *shear_rate, double *viscosity, double *yielded, sl_diag *d);

#endif
