/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Shear-induced migration flux for the solids-fraction transport: the
 * diffusive particle flux of Leighton & Acrivos (1987, J. Fluid Mech.
 * 181:415) in the form of Phillips, Armstrong, Brown, Graham & Abbott
 * (1992, Phys. Fluids A 4:30), as used by Nigam (1999, MIT PhD thesis,
 * eqs 2.29-2.30 and section 4.5):
 *
 *   N = -a^2 [ K_c phi^2 grad(g) + (K_c phi g + K_mu phi^2 g mu'(phi)/mu(phi)) grad(phi) ]
 *     = -D_c grad(g phi) - D_mu grad(ln mu),   D_c = K_c a^2 phi,  D_mu = K_mu a^2 g phi^2,
 *
 * g the shear rate, a the particle radius, K_c = 0.41, K_mu = 0.62. The
 * second form is the output convention of the migration closures
 * (plugins/migration/phillips.c): the closure gives D_c and D_mu, the host
 * takes the gradients. This module does not depend on the plug-in layer: it
 * takes callbacks, as the transport takes sl_settling_fn.
 *
 * Discretisation (a two-point flux, conservative: one flux per face, given
 * to both cells). On a face f between cells o (the owner, the normal
 * leaves it) and n, with cell points x_o, x_n (r-weighted centroids when
 * axisymmetric; across a periodic pair x_n translated next to the face):
 *
 *   F_f = -T_f [ D_c,f (g_n phi_n - g_o phi_o) + D_mu,f (ln mu(phi_n) - ln mu(phi_o)) ],
 *   T_f = A_f / ((x_n - x_o) . n_f),
 *
 * A_f the face area of the transport (r-weighted when axisymmetric), D_c,f
 * and D_mu,f the callback's coefficients at the face state (the means of
 * phi and of g of the two cells). This is the two-point flux approximation:
 * consistent where the line between the cell points is normal to the face
 * (rectangles, radial lines, annuli; not on general triangles). Walls,
 * open boundaries and the axis carry no migration flux. It is second order
 * in space: the discrete steady state of a no-flux problem, (g phi)_n -
 * (g phi)_o = -(K_mu/K_c) g_f phi_f (ln mu_n - ln mu_o), is a centred
 * approximation of the exact invariant g phi mu^(K_mu/K_c) = const (Nigam
 * eq 4.199).
 *
 * Stable step and positivity. Writing ln mu_n - ln mu_o = S_f (phi_n -
 * phi_o) (S_f >= 0 the secant slope of ln mu, the mean of d ln mu/dphi of
 * the two cells when they differ by less than 1e-7), the forward-Euler
 * update of cell i is exactly
 *
 *   phi_i' = phi_i [1 - h/V_i sum_f T_f (D_c,f g_i + D_mu,f S_f)] + h/V_i sum_f T_f (D_c,f g_j + D_mu,f S_f) phi_j,
 *
 * with non-negative coefficients of the neighbours j. So phi' >= 0 when
 *   h <= dt_stable = min_i V_i / sum_f T_f (D_c,f g_i + D_mu,f S_f),
 * the step this module reports: the diffusive limit with the effective
 * diffusivity K_c a^2 phi g + K_mu a^2 phi^2 g mu'/mu, in which the drift
 * part -K_c a^2 phi^2 grad(g) enters through g_i in place of the face mean
 * (the drift is "upwinded" by the identity g_n phi_n - g_o phi_o). The
 * flux vanishes at phi = 0 (no outflow from an empty cell). Near phi_max
 * the coefficient S_f ~ mu'/mu diverges, so does the effective
 * diffusivity, and the step shrinks: the transport's bounds limiter
 * (transport.h, sl_transport_set_extra_flux) keeps a cell below phi_max
 * from reaching it through this flux, so ln mu stays finite. (In a flow
 * whose shear rate scales as 1/mu, as in the Couette and Poiseuille
 * problems, g mu'/mu stays bounded and so does the step.)
 *
 * Use:
 *   sl_migration_create(t, &opts, &mg, d);
 *   sl_transport_set_extra_flux(t, sl_migration_flux, mg, d);
 *   each outer step: sl_migration_set_shear_rate(mg, g_cells, d); sl_transport_step(t, ...);
 * The migration object keeps a pointer to the transport (which must outlive
 * it) and must outlive its installation as the transport's extra flux. */
#ifndef SLUICE_TRANSPORT_MIGRATION_H
#define SLUICE_TRANSPORT_MIGRATION_H

#include "core/transport/transport.h"

/* The migration closure in batch: for i < n, D_c[i] = K_c a^2 phi (m^2) and
 * D_mu[i] = K_mu a^2 g phi^2 (m^2/s) at phi[i], shear rate g[i] (1/s); both
 * must be finite and >= 0. Returns 0 or an SL_E* code with d set. */
typedef int (*sl_migration_coef_fn)(void *user, int n, const double *phi, const double *shear_rate, double *D_c,
                                    double *D_mu, sl_diag *d);
/* The suspension viscosity as ln mu(phi) and its derivative mu'/mu in batch
 * (mu in any unit: only differences of ln mu enter). Finite wherever it is
 * asked, i.e. at every cell value; mu'/mu >= 0. */
typedef int (*sl_migration_lnmu_fn)(void *user, int n, const double *phi, double *ln_mu, double *dln_mu, sl_diag *d);

typedef struct sl_migration_opts {
  sl_migration_coef_fn coef; /* NULL: no shear-induced flux (then diffusivity > 0) */
  void *coef_user;
  sl_migration_lnmu_fn ln_mu; /* NULL: no viscosity-gradient flux (D_mu unused) */
  void *ln_mu_user;
  /* A constant Fickian particle diffusivity eps (m^2/s; 0: none), the
   * flux -eps grad(phi) of a pseudo-continuum (Lalli 1993, eq 0.2). It
   * adds T_f eps (phi_o - phi_n) to a face's flux and T_f eps to the
   * coefficients of the stable step above, so positivity and the bounds
   * hold as for the migration flux. */
  double diffusivity;
} sl_migration_opts;

typedef struct sl_migration sl_migration;

/* Returns 0, SL_EBADINPUT (neither a coefficient callback nor a positive
 * diffusivity) or SL_EFAILED. The
 * shear rate starts at zero (no flux). */
int sl_migration_create(const sl_transport *t, const sl_migration_opts *o, sl_migration **out, sl_diag *d);
void sl_migration_destroy(sl_migration *mg);

/* The shear rate per cell (n_cells values, finite and >= 0; copied), held
 * until the next call: set it once per outer step from the velocity. */
int sl_migration_set_shear_rate(sl_migration *mg, const double *g, sl_diag *d);
const double *sl_migration_shear_rate(const sl_migration *mg);

/* The sl_transport_extra_fn: flux[f] as above on the flux faces (0 on the
 * others) and the stable forward-Euler step. `migration` is the
 * sl_migration. Errors: the callbacks' codes (message prefixed), SL_EFAILED
 * for a non-finite or negative coefficient or a non-finite ln mu (the cell
 * is named: a cell at phi_max where mu is infinite), SL_EBADINPUT for a
 * face whose cell points do not lie on both sides of it. */
int sl_migration_flux(void *migration, const double *phi, double *flux, double *dt_stable, sl_diag *d);

/* The cell that set the last dt_stable (-1: no flux). */
int sl_migration_limiting_cell(const sl_migration *mg);

#endif
