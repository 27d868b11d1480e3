/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The settling flux F(phi) = phi u_settle(phi) tabulated once from a
 * hindered-settling closure, and the exact Godunov flux of the face flux
 * h(phi) = q phi + w F(phi) built on that table.
 *
 * Why a table. The closure is fixed through a run, and the Godunov flux of a
 * non-convex h needs the minimum or maximum of h over [a, b], i.e. the roots
 * of h' = q + w F' inside that interval. With F known only through a batch
 * call, asking the closure at every face and stage would cost a call per
 * face and a root search through the plug-in. Instead F and F' are sampled
 * once at n equidistant nodes on [0, phi_max]; between nodes F is the cubic
 * Hermite interpolant of (F, F') (error <= dphi^4 max|F''''| / 384, about
 * 1e-14 of max|F| for Richardson–Zaki with n = 2049; test_transport_flux
 * measures it). Values at the states themselves ("end values") come from the
 * same interpolant, so the flux is consistent: G(u, u) = h(u) to round-off.
 *
 * Why exact Godunov rather than Engquist–Osher (1981). Both are monotone and have
 * no expansion shocks. Godunov is the least diffusive monotone flux and
 * resolves stationary and sonic shocks (the sediment surface, the tangent
 * "contact" shock of Kynch settling) without the EO smearing. EO would need
 * the integrals of (q + w F')^+ and ^-, whose break points move with q/w
 * face by face, so they cannot be tabulated once; the Godunov minimum needs
 * only the roots of q + w F' = 0, and F' is monotone on a few "pieces" of
 * the table (between inflection points of F), so each piece has at most one
 * root, found by bisection on the table: O(pieces * log n) per face.
 *
 * Sign conventions: a face carries h along its normal; a is the state on
 * the side the normal leaves (the owner), b the state it enters. Godunov
 * (1959) in the min/max form of Osher (1984), SIAM J. Numer. Anal. 21:217:
 *   G(a, b) = min_{a <= u <= b} h(u)  when a <= b,
 *             max_{b <= u <= a} h(u)  when a >  b. */
#ifndef SLUICE_TRANSPORT_FLUX_H
#define SLUICE_TRANSPORT_FLUX_H

#include "core/util/diag.h"

/* The hindered-settling closure as a batch call: for i < n, u[i] is the
 * settling velocity of the solids relative to the mixture volume flux along
 * the body force (m/s, positive along it) at phi[i], and du[i] = du/dphi.
 * Returns 0 or an SL_E* code with d set. */
typedef int (*sl_settling_fn)(void *user, int n, const double *phi, double *u, double *du, sl_diag *d);

typedef struct sl_settling_table {
  int n;          /* nodes, >= 3 */
  double phi_max; /* the table covers [0, phi_max] */
  double dphi, inv_dphi;
  double *F;           /* [n] F = phi u at phi_k = k dphi */
  double *D;           /* [n] F' = u + phi du */
  double D_min, D_max; /* range of F' over the nodes */
  double F_absmax;     /* max |F| */
  int sign;            /* +1: F >= 0 on the table, -1: F <= 0, 0: F == 0 */
  int n_pieces;        /* pieces of the table on which F' is monotone */
  int *piece;          /* [n_pieces + 1] node indices: piece p is [piece[p], piece[p + 1]] */
  int *piece_dir;      /* [n_pieces] +1 where F' increases on the piece, -1 where it decreases */
  double *FD;          /* [4 (n - 1)] F_k, dphi D_k, F_k+1, dphi D_k+1 per interval: one cache line */
} sl_settling_table;

/* Samples the closure at n nodes (one batch call) and checks the flux: finite,
 * of one sign on [0, phi_max] (settling one way; zero is allowed), and zero
 * at phi_max to 1e-12 of max|F| (the sediment packs there: use a closure
 * with a packing cut-off). Tiny values of the wrong sign and F(phi_max) are
 * then set to exactly zero. Returns 0, SL_EBADINPUT (bad arguments or flux)
 * or the callback's code / SL_EFAILED (out of memory). */
int sl_settling_table_build(sl_settling_table *t, double phi_max, int n, sl_settling_fn fn, void *user, sl_diag *d);
void sl_settling_table_free(sl_settling_table *t);

/* F and F' at phi (clamped to [0, phi_max]): the Hermite interpolant and its
 * derivative. */
double sl_settling_F(const sl_settling_table *t, double phi);
double sl_settling_dF(const sl_settling_table *t, double phi);

/* The Godunov flux of h = q phi + w F(phi) for the states a (owner side) and
 * b (neighbour side); see the top of this file. */
double sl_godunov_flux(const sl_settling_table *t, double q, double w, double a, double b);

#endif
