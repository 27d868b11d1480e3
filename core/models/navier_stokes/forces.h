/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The force of the fluid on a boundary where the velocity is prescribed (a
 * wall, an inflow, a body in the flow), from the residual of the discrete
 * momentum equation: with v_i the finite-element function that is e_i at
 * the velocity nodes of the boundary and 0 at every other node,
 *
 *   F_i = -R(u, p; v_i) = -sum over those nodes of R_i,
 *
 * R the weak momentum residual (sl_assemble_flow) before the Dirichlet rows
 * are replaced. For the exact solution this is the surface integral
 * int (sigma n_body)_i dS of the stress on the body; for the discrete one it
 * converges at the rate of the energy error squared, faster than the
 * surface integral of the discrete stress (Giles, Larson, Levenstam & Suli
 * 1997; John 2004, eq. (5), the volume formulation used for the DFG
 * benchmark of Schafer & Turek 1996). Nodes a boundary shares with another
 * (a corner) count for both.
 *
 * Planar: N per unit depth (m). Axisymmetric: the force on the surface of
 * revolution, 2 pi times the (r, z) integral; only its z component is not
 * zero by symmetry. */
#ifndef SLUICE_MODELS_NAVIER_STOKES_FORCES_H
#define SLUICE_MODELS_NAVIER_STOKES_FORCES_H

#include "core/models/navier_stokes/flow_problem.h"

/* The force on every boundary b with want[b] set, into F[n_comp * b + i]
 * (n_comp = th->n_comp); others are left as they are. The residual is
 * assembled into p->sys.b (its previous contents are lost; the matrix is
 * not touched), with the problem's options and tractions as they stand:
 * call it right after a solve, with the step's mass coefficient and
 * history still set. work: n_vel bytes. */
int sl_flow_forces(sl_flow_problem *p, const double *u, const unsigned char *want, unsigned char *work, double *F,
                   sl_diag *d);

#endif
