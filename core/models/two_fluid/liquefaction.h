/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The liquefaction add-on of the 1-D two-fluid column (Pringle 2001,
 * thesis sections 5.4-5.5, with the closures of chapter 3, eqs 3.38-3.53
 * and 4.30): a sand deposit whose reference porosity nbar is a state of each
 * cell, shaken at its base.
 *
 * - Solids pressure: [closure.solids_pressure] of phi and nbar (e.g.
 *   pringle_state, Pringle's eq 4.30 with nbar an input).
 * - Horizontal equilibrium of the deposit (thesis eq 5.13), in the frame of
 *   the base, which accelerates with the record a_g(t):
 *     rho dv/dt = d tau/dy - rho a_g(t),   gamma = dw/dy,
 *     tau = G0 gamma / (1 + G0 |gamma| / tau_max) + eta dgamma/dt,
 *   the hyperbolic modulus reduction of Hardin & Drnevich (1972, J. Soil
 *   Mech. Found. Div. 98(SM7), eq 7), G/G0 = 1/(1 + |gamma|/gamma_r),
 *   gamma_r = tau_max/G0; the small-strain modulus of Seed & Idriss (1970,
 *   EERC 70-10) in the form Pringle uses from Hosni (thesis eq 3.40),
 *   G0 = 220 K2max sqrt(P_s) kPa with P_s in kPa (K2max 30-70 for sands:
 *   the thesis's "0.4-0.6" is a misprint), tau_max = P_s
 *   tan(friction angle), and a viscous stress eta = 2 xi G0/omega_d +
 *   eta_res (stiffness-proportional damping of ratio xi at omega_d, plus a
 *   residual viscosity of liquefied sand). rho is the mixture density (the
 *   pore fluid moves with the grains horizontally; the thesis prints rho_s).
 *   Newmark's average acceleration (trapezoidal) rule with the secant
 *   modulus of the step's start, base fixed (w = 0), surface free (tau = 0).
 * - Densification: [closure.densification] gives nbar after each step from
 *   the cell's shear history: the amplitude of a half-cycle at a strain
 *   reversal, the step's |dgamma|, the path sum |dgamma| and the drained
 *   volumetric strain eps_vd = 1 - (1 - nbar0)/(1 - nbar).
 * - A deposit built in the model: [deposit] settle lets [initial]'s
 *   suspension settle and consolidate before t = 0 (thesis section 5.4:
 *   the deposit "constructed" by settling).
 * The vertical two-fluid step is the column's (two_fluid_step.c: the 2-D
 * model's step on n x 1 cells) with nbar
 * held over the step; drainage and re-consolidation are its drag and solids
 * pressure. */
#ifndef SLUICE_MODELS_TWO_FLUID_LIQUEFACTION_H
#define SLUICE_MODELS_TWO_FLUID_LIQUEFACTION_H

#include "core/io/output.h"
#include "core/models/two_fluid/two_fluid_impl.h"

typedef struct tf_liquefaction tf_liquefaction;

/* Whether the scene asks for the add-on: a solids pressure of nbar, a
 * [shaking] or [deposit] section, or [closure.densification]. */
int tfl_wanted(const sl_scene *sc, const tf_column *c);
/* The add-on's state from the scene (nbar from [initial] nbar, or from the
 * file of [initial] from when that has it, in the mesh's cell order cell_of;
 * the record; the densification closure bound): c->nbar and c->ps.nbar point
 * into it. Called before the deposit settles. */
int tfl_create(const sl_scene *sc, const tf_config *cfg, tf_column *c, const int *cell_of, tf_liquefaction **out,
               sl_diag *d);
/* After the settling: the state at t = 0 (p_s0, the deposit's cells, its
 * surface) and the [deposit] nbar_drop. */
int tfl_start(tf_liquefaction *L, tf_column *c, sl_diag *d);
/* The horizontal step from t over dt (a trial, into the add-on's *_new). */
int tfl_step(tf_liquefaction *L, tf_column *c, double t, double dt, sl_diag *d);
/* The trial becomes the state; the densification law updates nbar. */
int tfl_accept(tf_liquefaction *L, tf_column *c, double t, double dt, sl_diag *d);
/* The add-on's fields (cells in the mesh's order via cell_of) and scalars. */
int tfl_write(tf_liquefaction *L, tf_column *c, sl_output *out, const int *cell_of, double *cell_scratch,
              unsigned fields, double t, sl_diag *d);
/* One line for the run's summary. */
void tfl_summary(const tf_liquefaction *L, char *buf, size_t len);
void tfl_free(tf_liquefaction *L);

/* The add-on's output fields (bits of the column's field mask). */
enum { TFL_F_NBAR = 16, TFL_F_RATIO = 32, TFL_F_EXCESS = 64, TFL_F_RU = 128, TFL_F_STRAIN = 256, TFL_F_PS = 512 };

#endif
