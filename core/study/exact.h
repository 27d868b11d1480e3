/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Exact solutions a study measures against (`[measure] exact = NAME`), set
 * up from one run's resolved scene, closures included:
 *
 *  kynch    1-D batch settling in a closed column (Kynch 1952; the entropy
 *           solution of core/study/kynch_exact.h): cell averages of phi.
 *           The settling flux is the scene's own closure, evaluated through
 *           the plugin: richardson_zaki with its packing cut-off and a given
 *           exponent, or nigam; u_t is the closure's value at phi = 0, and
 *           the law is checked against the closure at several phi.
 *  bingham  fully developed Bingham flow between plates (Bird, Dai &
 *           Yarusso 1983; core/study/bingham_exact.h): the axial (third)
 *           velocity component; the scene's plastic viscosity and yield
 *           stress, the driving force from [flow] body_force and gravity.
 *  fluidized_bed  the homogeneous liquid-fluidised bed at rest (Richardson &
 *           Zaki 1954; core/study/fluidized_bed_exact.h): a 1-D two_fluid
 *           column fed at the bottom ([boundary.left] an inlet of constant
 *           velocity U, [boundary.right] an outlet) holds its solids at the
 *           porosity where the scene's own drag closure (evaluated through
 *           the plugin, its inputs bound as the two_fluid model binds them)
 *           carries their buoyant weight. The solids pressure and particle
 *           diffusivity do not act on a uniform bed. phi is compared cell by
 *           cell over the bed at rest: the cells wholly below its top, at the
 *           height that holds the run's solids inventory at the equilibrium
 *           phi (the cell the top cuts is left out).
 *
 * A scene outside what a solution covers is refused with the reason. */
#ifndef SLUICE_BENCH_EXACT_H
#define SLUICE_BENCH_EXACT_H

#include "core/config/ini.h"
#include "core/plugin/registry.h"

typedef struct sl_bench_exact sl_bench_exact;

int sl_bench_exact_create(const char *name, const sl_ini *ini, const sl_registry *reg, sl_bench_exact **out,
                          sl_diag *d);
void sl_bench_exact_free(sl_bench_exact *e);

/* One line: which solution, with its parameters. */
const char *sl_bench_exact_describe(const sl_bench_exact *e);
/* 1: compared as cell averages (sl_bench_exact_averages); 0: point values. */
int sl_bench_exact_cell_averages(const sl_bench_exact *e);
/* The 1-D domain [x0, x1] of the solution. */
void sl_bench_exact_domain(const sl_bench_exact *e, double *x0, double *x1);

/* The part [lo, hi] of the domain compared, given a run's cell values v
 * over the cells [xa[c], xb[c]] (n cells, the whole column): the domain
 * itself, or for fluidized_bed the bed at rest that holds the run's solids
 * inventory (sum of v h) at the equilibrium phi. */
void sl_bench_exact_compared_span(const sl_bench_exact *e, int n, const double *xa, const double *xb, const double *v,
                                  double *lo, double *hi);

/* Point values at x[0..n-1] at time t. */
void sl_bench_exact_values(const sl_bench_exact *e, double t, int n, const double *x, double *v);
/* Averages over the cells [xa[i], xb[i]] at time t. */
void sl_bench_exact_averages(const sl_bench_exact *e, double t, int n, const double *xa, const double *xb, double *v);

#endif
