/* Closure evaluation throughput through the plugin ABI against the same law
 * compiled inline, for batch sizes 1 to 4096 (issue: foundation benchmark).
 *   build/bin/bench_closure_throughput [points]     (default 2^22 points)
 * Prints a Markdown table: points per second both ways and the ABI's cost. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"

/* The Ergun law of plugins/drag/ergun.c (gidaspow form, defaults), inline,
 * with the same validity checks and derivative work. */
static int ergun_inline(int32_t Q, const double *const *in, double *K, double *dK_dphi, double *dK_dslip) {
  for (int32_t q = 0; q < Q; ++q) {
    double phi = in[0][q], slip = in[1][q], rho = in[2][q], mu = in[3][q], dp = in[4][q], psi = in[5][q];
    if (!(phi >= 0.0 && phi <= 0.74) || !(slip >= 0.0 && slip < HUGE_VAL) || !(rho >= 1e-3 && rho <= 1e5) ||
        !(mu >= 1e-7 && mu <= 1e5) || !(dp >= 1e-8 && dp <= 1.0) || !(psi >= 0.01 && psi <= 1.0))
      return 1;
    double inv_d = 1.0 / (psi * dp), inv_n = 1.0 / (1.0 - phi);
    double visc = 150.0 * mu * inv_d * inv_d, iner = 1.75 * rho * inv_d;
    K[q] = visc * phi * phi * inv_n + iner * phi * slip;
    dK_dphi[q] = visc * phi * (2.0 - phi) * inv_n * inv_n + iner * slip;
    dK_dslip[q] = iner * phi;
  }
  return 0;
}

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv) {
  long total = argc > 1 ? atol(argv[1]) : 1L << 22;
  sl_registry *r;
  sl_diag d;
  const sl_closure_entry *e;
  void *params;
  sl_closure *c;
  if (sl_registry_create(&r, NULL, 0, &d) || sl_registry_scan(r, &d) ||
      sl_registry_find(r, SL_KIND_DRAG, "ergun", NULL, &e, &d) || sl_params_new(e->desc, &params, &d) ||
      sl_closure_create(e, params, &c, &d)) {
    fprintf(stderr, "bench: %s\n", d.msg);
    return 1;
  }
  enum { MAXQ = 4096, NIN = 6 };
  static double in_data[NIN][MAXQ], out[MAXQ], d0[MAXQ], d1[MAXQ], dK_unused[NIN][MAXQ];
  const double *in[NIN];
  for (int i = 0; i < NIN; ++i) in[i] = in_data[i];
  for (int q = 0; q < MAXQ; ++q) {
    in_data[0][q] = 0.05 + 0.6 * (double)q / MAXQ;
    in_data[1][q] = 1e-3 * (1 + q % 7);
    in_data[2][q] = 1000.0;
    in_data[3][q] = 1e-3;
    in_data[4][q] = 3e-4;
    in_data[5][q] = 1.0;
  }
  double *outp[1] = {out};
  double *doutp[NIN] = {d0, d1, dK_unused[2], dK_unused[3], dK_unused[4], dK_unused[5]};
  doutp[2] = doutp[3] = doutp[4] = doutp[5] = NULL;
  sl_error err;
  printf("| batch Q | inline (points/s) | through the ABI (points/s) | ABI cost |\n|---|---|---|---|\n");
  const int sizes[] = {1, 8, 64, 512, 4096};
  volatile double sink = 0;
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
    int Q = sizes[s];
    long calls = total / Q;
    double best_inline = 1e30, best_abi = 1e30;
    for (int rep = 0; rep < 5; ++rep) { /* best of 5 against noise */
      double t0 = now();
      for (long k = 0; k < calls; ++k) {
        const double *shifted[NIN];
        int off = (int)(k % (MAXQ / Q)) * Q;
        for (int i = 0; i < NIN; ++i) shifted[i] = in[i] + off;
        if (ergun_inline(Q, shifted, out, d0, d1)) return 1;
        sink += out[0];
      }
      double t1 = now();
      for (long k = 0; k < calls; ++k) {
        const double *shifted[NIN];
        int off = (int)(k % (MAXQ / Q)) * Q;
        for (int i = 0; i < NIN; ++i) shifted[i] = in[i] + off;
        sl_eval_args a = {.Q = Q, .in = shifted, .out = outp, .dout = doutp, .err = &err};
        if (sl_closure_evaluate(c, &a)) return 1;
        sink += out[0];
      }
      double t2 = now();
      if (t1 - t0 < best_inline) best_inline = t1 - t0;
      if (t2 - t1 < best_abi) best_abi = t2 - t1;
    }
    double n = (double)calls * Q;
    printf("| %d | %.3g | %.3g | %+.1f %% |\n", Q, n / best_inline, n / best_abi,
           100.0 * (best_abi - best_inline) / best_inline);
  }
  (void)sink;
  sl_closure_destroy(c);
  sl_registry_destroy(r);
  return 0;
}
