/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Closure evaluation throughput through the plugin ABI against the same law
 * compiled inline, for batch sizes 1 to 4096 (issue: foundation benchmark).
 *   build/bin/bench_closure_throughput [points [reps [Q [inline|abi]]]]
 * points: points per timed block (default 2^20); reps: timed pairs per batch
 * size (default 41). Short blocks and many of them: on a shared machine the
 * best block is then one that nothing else interrupted. A Q (and a path)
 * restricts the run, for `perf record` or `valgrind --tool=callgrind`.
 *
 * Fairness: the inline copy and the closure compute the same law with the same
 * source (drag/dense_drag_laws.h), the same validity checks and the same
 * flags (both at the build type's optimisation; the closure adds only -fPIC
 * and hidden visibility). Both read six separate 64-byte aligned input arrays
 * through pointers, as the host passes them, so the inline copy cannot fold a
 * static input layout into its addressing.
 * One untimed warm-up pair runs first; then the inline and ABI blocks
 * alternate, the order swapping every repetition, so that frequency drift and
 * other jobs on the machine hit both alike. Reported: the best block of each
 * (points/s), the ABI cost from those, and the median and interquartile range
 * of the cost over the back-to-back pairs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../plugins/drag/dense_drag_laws.h"
#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"

/* The Ergun law of plugins/drag/ergun.c (gidaspow form, default constants),
 * inline: the same validity checks and the same derivative work. */
static int ergun_inline(int32_t Q, const double *const *in, double *restrict K, double *restrict dK_dphi,
                        double *restrict dK_dslip) {
  const double *restrict phi_in = in[0], *restrict slip_in = in[1], *restrict rho_in = in[2], *restrict mu_in = in[3],
                         *restrict dp_in = in[4], *restrict psi_in = in[5];
  for (int32_t q = 0; q < Q; ++q) {
    const double phi = phi_in[q], slip = slip_in[q], rho = rho_in[q], mu = mu_in[q], dp = dp_in[q], psi = psi_in[q];
    if (!sl_ergun_inputs_ok(phi, slip, rho, mu, dp, psi)) return 1;
    const sl_drag_value v = sl_ergun_law(phi, slip, rho, mu, psi * dp, 150.0, 1.75, 0);
    K[q] = v.K;
    dK_dphi[q] = v.K_phi;
    dK_dslip[q] = v.K_slip;
  }
  return 0;
}

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { MAXQ = 4096, NIN = 6 };

typedef struct bench {
  const double *in[NIN];
  double *out[1], *dout[NIN];
  sl_closure *c;
  sl_error err;
  double sink;
} bench;

/* One timed block of `calls` batches of Q points, sliding through the inputs. */
static double run_inline(bench *b, int Q, long calls) {
  double t0 = now();
  for (long k = 0; k < calls; ++k) {
    const double *shifted[NIN];
    int off = (int)(k % (MAXQ / Q)) * Q;
    for (int i = 0; i < NIN; ++i) shifted[i] = b->in[i] + off;
    if (ergun_inline(Q, shifted, b->out[0], b->dout[0], b->dout[1])) {
      fprintf(stderr, "bench: inline Ergun refused its inputs\n");
      exit(1);
    }
    b->sink += b->out[0][0];
  }
  return now() - t0;
}

static double run_abi(bench *b, int Q, long calls) {
  double t0 = now();
  for (long k = 0; k < calls; ++k) {
    const double *shifted[NIN];
    int off = (int)(k % (MAXQ / Q)) * Q;
    for (int i = 0; i < NIN; ++i) shifted[i] = b->in[i] + off;
    sl_eval_args a = {.Q = Q, .in = shifted, .out = b->out, .dout = b->dout, .err = &b->err};
    if (sl_closure_evaluate(b->c, &a)) {
      fprintf(stderr, "bench: %s\n", b->err.msg);
      exit(1);
    }
    b->sink += b->out[0][0];
  }
  return now() - t0;
}

static int cmp_double(const void *x, const void *y) {
  double a = *(const double *)x, b = *(const double *)y;
  return (a > b) - (a < b);
}

/* 64-byte aligned, as the host's arrays are. */
static double *array(void) {
  double *p = aligned_alloc(64, MAXQ * sizeof(double));
  if (!p) exit(1);
  memset(p, 0, MAXQ * sizeof(double));
  return p;
}

int main(int argc, char **argv) {
  long total = argc > 1 ? atol(argv[1]) : 1L << 20;
  int reps = argc > 2 ? atoi(argv[2]) : 41;
  int only_q = argc > 3 ? atoi(argv[3]) : 0;
  const char *only_path = argc > 4 ? argv[4] : "";
  if (total < 1 || reps < 1 || reps > 1000) {
    fprintf(stderr, "usage: bench_closure_throughput [points [reps [Q [inline|abi]]]]\n");
    return 2;
  }
  sl_registry *r;
  sl_diag d;
  const sl_closure_entry *e;
  void *params;
  bench b = {.sink = 0.0};
  if (sl_registry_create(&r, NULL, 0, &d) || sl_registry_scan(r, &d) ||
      sl_registry_find(r, SL_KIND_DRAG, "ergun", NULL, &e, &d) || sl_params_new(e->desc, &params, &d) ||
      sl_closure_create(e, params, &b.c, &d)) {
    fprintf(stderr, "bench: %s\n", d.msg);
    return 1;
  }
  double *in_data[NIN];
  for (int i = 0; i < NIN; ++i) b.in[i] = in_data[i] = array();
  for (int q = 0; q < MAXQ; ++q) {
    in_data[0][q] = 0.05 + 0.6 * (double)q / MAXQ;
    in_data[1][q] = 1e-3 * (1 + q % 7);
    in_data[2][q] = 1000.0;
    in_data[3][q] = 1e-3;
    in_data[4][q] = 3e-4;
    in_data[5][q] = 1.0;
  }
  b.out[0] = array();
  for (int i = 0; i < NIN; ++i) b.dout[i] = NULL;
  b.dout[0] = array(); /* dK/dphi */
  b.dout[1] = array(); /* dK/dslip */

  printf(
      "| batch Q | inline (points/s) | through the ABI (points/s) | ABI cost (best of %d) | ABI cost, pairs: "
      "median [IQR] |\n|---|---|---|---|---|\n",
      reps);
  const int sizes[] = {1, 8, 64, 512, 4096};
  for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
    int Q = sizes[s];
    if (only_q && Q != only_q) continue;
    long calls = total / Q > 0 ? total / Q : 1;
    if (!strcmp(only_path, "inline") || !strcmp(only_path, "abi")) { /* one path only, for perf */
      for (int rep = 0; rep < reps; ++rep) {
        if (only_path[0] == 'i') run_inline(&b, Q, calls);
        else run_abi(&b, Q, calls);
      }
      continue;
    }
    double best_inline = 1e30, best_abi = 1e30, cost[1000];
    run_inline(&b, Q, calls); /* warm-up: caches, branch predictors, clock */
    run_abi(&b, Q, calls);
    for (int rep = 0; rep < reps; ++rep) {
      double ti, ta;
      if (rep % 2 == 0) {
        ti = run_inline(&b, Q, calls);
        ta = run_abi(&b, Q, calls);
      } else {
        ta = run_abi(&b, Q, calls);
        ti = run_inline(&b, Q, calls);
      }
      if (ti < best_inline) best_inline = ti;
      if (ta < best_abi) best_abi = ta;
      cost[rep] = 100.0 * (ta - ti) / ti;
    }
    qsort(cost, (size_t)reps, sizeof cost[0], cmp_double);
    double n = (double)calls * Q;
    printf("| %d | %.3g | %.3g | %+.1f %% | %+.1f %% [%+.1f, %+.1f] |\n", Q, n / best_inline, n / best_abi,
           100.0 * (best_abi - best_inline) / best_inline, cost[reps / 2], cost[reps / 4], cost[(3 * reps) / 4]);
    fflush(stdout);
  }
  if (b.sink == 42.0) puts(""); /* keeps the results alive */
  sl_closure_destroy(b.c);
  sl_registry_destroy(r);
  for (int i = 0; i < NIN; ++i) free(in_data[i]);
  free(b.out[0]);
  free(b.dout[0]);
  free(b.dout[1]);
  return 0;
}
