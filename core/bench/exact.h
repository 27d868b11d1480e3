/* Exact solutions a study measures against (`[measure] exact = NAME`), set
 * up from one run's resolved scene, closures included:
 *
 *  kynch    1-D batch settling in a closed column (Kynch 1952; the entropy
 *           solution of core/verify/kynch_exact.h): cell averages of phi.
 *           The settling flux is the scene's own closure, evaluated through
 *           the plugin: richardson_zaki with its packing cut-off and a given
 *           exponent, or nigam; u_t is the closure's value at phi = 0, and
 *           the law is checked against the closure at several phi.
 *  bingham  fully developed Bingham flow between plates (Bird, Dai &
 *           Yarusso 1983; core/verify/bingham_exact.h): the axial (third)
 *           velocity component; the scene's plastic viscosity and yield
 *           stress, the driving force from [flow] body_force and gravity.
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

/* Point values at x[0..n-1] at time t. */
void sl_bench_exact_values(const sl_bench_exact *e, double t, int n, const double *x, double *v);
/* Averages over the cells [xa[i], xb[i]] at time t. */
void sl_bench_exact_averages(const sl_bench_exact *e, double t, int n, const double *xa, const double *xb, double *v);

#endif
