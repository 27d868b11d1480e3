/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Finite-element operators assembled into an sl_system: scalar diffusion
 * (Poisson) and Stokes on Taylor–Hood pairs.
 *
 * Coefficients are evaluated in batches: the assembler gathers the
 * quadrature points of up to SL_ASSEMBLY_BATCH_CELLS cells and calls the
 * coefficient once per batch, the way closures are called (architecture
 * section 6). A coefficient with fn == NULL is the constant `value`, and a
 * constant zero term is skipped, not assembled.
 *
 * The operators ADD into the system (call sl_system_zero first), so terms
 * of one equation can be assembled by several calls. */
#ifndef SLUICE_ASSEMBLY_OPERATORS_H
#define SLUICE_ASSEMBLY_OPERATORS_H

#include <stdint.h>

#include "core/assembly/system.h"
#include "core/fe/dofmap.h"
#include "core/util/diag.h"

#define SL_ASSEMBLY_BATCH_CELLS 64

/* What a coefficient sees: n quadrature points of several cells. */
typedef struct sl_qp_batch {
  int n;
  const double (*x)[2];      /* [n] physical coordinates (r, z when axisymmetric) */
  const int32_t *cell;       /* [n] the cell of each point */
  const double *shear_rate;  /* [n] sqrt(2 D(u):D(u)) of the velocity the
                               caller passed (Stokes), else NULL */
  const double (*normal)[2]; /* [n] outward unit normal on boundary batches, else NULL */
} sl_qp_batch;

/* Writes `out` for all points of the batch: out[i] for a scalar, out[k * i
 * + c] for a k-vector (body forces). Returns 0 or an SL_E* code with d set
 * (e.g. a closure outside its validity); the assembler stops and passes it
 * on. Non-finite outputs are refused by the assembler. */
typedef int (*sl_qp_fn)(void *user, const sl_qp_batch *batch, double *out, sl_diag *d);

typedef struct sl_coef {
  sl_qp_fn fn; /* NULL: the constant `value` */
  void *user;
  double value;
} sl_coef;

/* ---- diffusion: -div(k grad u) = f -------------------------------------- */

typedef struct sl_diffusion_opts {
  sl_coef diffusivity; /* k > 0 */
  sl_coef source;      /* f */
  int axisymmetric;    /* weight by r: -(1/r) d/dr(r k du/dr) - d/dz(k du/dz) = f */
  int quad_degree;     /* 0: 2 * order (+1 axisymmetric) */
  /* A constant 2 x 2 matrix T (row-major, not necessarily symmetric): A += int k grad(v).T grad(u), the
   * anisotropic operator -div(k T grad u) with the conormal T grad u . n as its natural boundary flux.
   * NULL: the identity. */
  const double *tensor;
} sl_diffusion_opts;

/* A += int k grad(u).grad(v), b += int f v over the cells of dm; the system
 * must have been initialised from dm (sl_system_init with dm->cell_dofs). */
int sl_assemble_diffusion(sl_system *s, const sl_dofmap *dm, const sl_diffusion_opts *o, sl_diag *d);

/* ---- Stokes: -div(2 mu D(u)) + grad p = f, div u = 0 --------------------- */

typedef struct sl_stokes_opts {
  sl_coef viscosity;   /* mu > 0 (Pa s) */
  sl_qp_fn body_force; /* f, out[n_comp * i + c]; NULL: none */
  void *body_force_user;
  const double *velocity; /* optional: the velocity (combined numbering)
                                whose shear rate the viscosity sees */
  int quad_degree;        /* 0: 4 */
} sl_stokes_opts;

/* The symmetric saddle-point system
 *   [ A  B^T ] [u]   [F]     A = int 2 mu D(u):D(v),  B = -int q div u,
 *   [ B  0   ] [p] = [0]     F = int f.v,
 * on the Taylor–Hood space th, planar, n_comp == dim. The system must have
 * been initialised from th (th->n_dofs, th->cell_dofs). */
int sl_assemble_stokes(sl_system *s, const sl_th_space *th, const sl_stokes_opts *o, sl_diag *d);

/* Pressure datum for enclosed flows (velocity prescribed on the whole
 * boundary, p defined up to a constant): fixes pressure node 0 to zero.
 * Chosen over a zero-mean Lagrange multiplier, which would add a dense row
 * and column to the sparse factorisation; shift afterwards with
 * sl_stokes_zero_mean_pressure when a mean-free pressure is wanted. */
void sl_stokes_fix_pressure_datum(sl_constraints *bc, const sl_th_space *th);
/* Subtracts the mean (integral / area) of the pressure in x. */
int sl_stokes_zero_mean_pressure(const sl_th_space *th, double *x, sl_diag *d);

#endif
