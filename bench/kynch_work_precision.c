/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Work-precision of the solids-fraction transport on Kynch batch settling:
 * L1 error of phi against the exact entropy solution (tests/transport/
 * kynch_exact.h) against CPU time, first order (Godunov) and MUSCL (MC and
 * minmod limiters), 50 to 3200 cells.
 *
 * Case: Richardson–Zaki with a packing cut-off, F = phi (1-phi)^4.65 (1 -
 * phi/0.64), u_t = 1, a column of height 1, phi0 = 0.1, up to t = 0.8 t1
 * (t1 = 1.5556, when the fronts meet): the falling top shock, the rising
 * contact shock phi0 | 0.4075, the fan to phi_max and the sediment are all
 * present. Outer steps of 0.01 (the engine's step), sub-cycled at CFL 0.9.
 *
 *   bench_kynch_work_precision [max_cells]
 *
 * prints CSV: scheme, cells, sub-steps, CPU seconds (best of up to 3 runs,
 * process CPU time), L1 error, observed rate against the previous row. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "../tests/transport/kynch_run.h"

static double cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
  int max_cells = argc > 1 ? atoi(argv[1]) : 3200;
  if (max_cells < 50) {
    fprintf(stderr, "usage: bench_kynch_work_precision [max_cells >= 50]\n");
    return 2;
  }
  kx_law law = kx_richardson_zaki(1.0, 4.65, 0.64);
  kynch k;
  if (kx_init(&k, law, 1.0, 0.1)) return 1;
  const double t_end = 0.8 * k.t1;
  const struct {
    const char *name;
    int order;
    sl_transport_limiter lim;
  } schemes[] = {{"godunov", 1, SL_LIMITER_MC}, {"muscl_mc", 2, SL_LIMITER_MC}, {"muscl_minmod", 2, SL_LIMITER_MINMOD}};
  printf("scheme,cells,substeps,cpu_s,l1_error,rate\n");
  for (int s = 0; s < 3; ++s) {
    double prev = NAN;
    for (int n = 50; n <= max_cells; n *= 2) {
      double best = HUGE_VAL, l1 = NAN;
      long sub = 0;
      for (int rep = 0; rep < 3; ++rep) {
        kr_run r;
        kr_open(&r, n, 1.0, 0.1, schemes[s].order, schemes[s].lim, kx_settling, &law, 0.64);
        double t0 = cpu_seconds();
        kr_advance(&r, t_end);
        double cpu = cpu_seconds() - t0;
        if (cpu < best) best = cpu;
        l1 = kr_l1(&r, &k);
        sub = r.substeps;
        kr_close(&r);
        if (best > 2.0) break; /* long runs: once is enough */
      }
      printf("%s,%d,%ld,%.4g,%.4e,", schemes[s].name, n, sub, best, l1);
      if (isnan(prev)) printf("\n");
      else printf("%.2f\n", log(prev / l1) / log(2.0));
      fflush(stdout);
      prev = l1;
    }
  }
  return 0;
}
