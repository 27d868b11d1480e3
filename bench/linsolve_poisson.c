/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Timings, not a test (speed is never asserted): the backends on the 2-D
 * 5-point Poisson matrix, and element assembly by binary search against the
 * precomputed element map on P1 and P2 triangle meshes.
 *   solve_bench [N]     (N x N grid, default 256) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "core/solve/linsolve.h"
#include "core/solve/sparse.h"
#include "poisson.h"

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int bench_solvers(int N) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  if (poisson_build(&A, N, N, 0.0, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
  int32_t n = A.n_rows;
  double *xe = malloc((size_t)n * sizeof *xe), *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
  for (int32_t i = 0; i < n; ++i) xe[i] = sin(0.37 * i) + 1.0;
  sl_csr_matvec(&A, xe, b);
  printf("2-D Poisson %dx%d: n = %d, nnz = %d\n", N, N, (int)n, (int)A.nnz);
  printf("%-8s %12s %12s %12s %12s %10s %10s\n", "solver", "symbolic s", "numeric1 s", "numeric2 s", "solve s", "err",
         "rcond");
  for (int k = 0; k < 3; ++k) {
    sl_linsolve *ls = NULL;
    const char *name = sl_linsolve_names(NULL)[k];
    if (sl_linsolve_create(&ls, name, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
    const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
    if (sl_linsolve_solve(ls, &A, b, x, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
    double tn1 = st->t_numeric;
    sl_csr_touch(&A); /* same values, but a second numeric (KLU: refactor) */
    for (int r = 0; r < 10; ++r)
      if (sl_linsolve_solve(ls, &A, b, x, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
    double e = 0;
    for (int32_t i = 0; i < n; ++i) e = fmax(e, fabs(x[i] - xe[i]));
    printf("%-8s %12.4f %12.4f %12.4f %12.5f %10.2e %10.2e\n", name, st->t_symbolic, tn1, st->t_numeric - tn1,
           st->t_solve / (double)st->n_solves, e, st->rcond);
    sl_linsolve_destroy(ls);
  }
  sl_csr_free(&A);
  free(xe), free(b), free(x);
  return 0;
}

/* Triangles of an N x N square grid, P1 (3 dofs) or P2 (6 dofs, with the
 * dofs of the (2N+1)^2 refined grid). */
static int bench_assembly(int N, int p2) {
  sl_diag d = {{0}};
  int nd = p2 ? 6 : 3, M = p2 ? 2 * N + 1 : N + 1;
  int32_t n_elem = 2 * N * N, n_dof = M * M;
  int32_t *el = malloc((size_t)n_elem * nd * sizeof *el);
  int32_t *ptr = malloc(((size_t)n_elem + 1) * sizeof *ptr);
  for (int j = 0, e = 0; j < N; ++j)
    for (int i = 0; i < N; ++i, e += 2) {
      int s = p2 ? 2 : 1;
#define V(a, b) ((int32_t)((j * s + (b)) * M + i * s + (a)))
      int32_t *t0 = el + (size_t)e * nd, *t1 = t0 + nd;
      if (p2) {
        const int32_t a[6] = {V(0, 0), V(2, 0), V(0, 2), V(1, 0), V(1, 1), V(0, 1)};
        const int32_t c[6] = {V(2, 0), V(2, 2), V(0, 2), V(2, 1), V(1, 2), V(1, 1)};
        for (int q = 0; q < 6; ++q) t0[q] = a[q], t1[q] = c[q];
      } else {
        t0[0] = V(0, 0), t0[1] = V(1, 0), t0[2] = V(0, 1);
        t1[0] = V(1, 0), t1[1] = V(1, 1), t1[2] = V(0, 1);
      }
#undef V
    }
  for (int32_t e = 0; e <= n_elem; ++e) ptr[e] = e * nd;
  double Ke[36];
  for (int q = 0; q < nd * nd; ++q) Ke[q] = 1.0 + 0.01 * q;

  sl_csr A = {0};
  double t0 = now();
  if (sl_csr_build(&A, n_dof, n_dof, n_elem, ptr, el, NULL, NULL, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
  double t_build = now() - t0;
  sl_csr_elem_map map;
  t0 = now();
  if (sl_csr_elem_map_build(&map, &A, n_elem, ptr, el, NULL, NULL, &d)) return fprintf(stderr, "%s\n", d.msg), 1;
  double t_map = now() - t0;
  const int reps = 10;
  t0 = now();
  for (int r = 0; r < reps; ++r) {
    sl_csr_zero(&A);
    for (int32_t e = 0; e < n_elem; ++e)
      sl_csr_add_element(&A, nd, el + (size_t)e * nd, nd, el + (size_t)e * nd, Ke, &d);
  }
  double t_search = (now() - t0) / reps;
  double sum1 = 0;
  for (int32_t p = 0; p < A.nnz; ++p) sum1 += A.values[p];
  t0 = now();
  for (int r = 0; r < reps; ++r) {
    sl_csr_zero(&A);
    for (int32_t e = 0; e < n_elem; ++e) sl_csr_add_element_mapped(&A, &map, e, Ke, &d);
  }
  double t_mapped = (now() - t0) / reps;
  double sum2 = 0;
  for (int32_t p = 0; p < A.nnz; ++p) sum2 += A.values[p];
  printf(
      "P%d triangles %dx%d: %d elements, %d dofs, nnz %d: pattern %.4f s, map %.4f s (%.1f MB); "
      "assembly per pass: search %.4f s, mapped %.4f s (x%.1f)%s\n",
      p2 ? 2 : 1, N, N, (int)n_elem, (int)n_dof, (int)A.nnz, t_build, t_map, (double)map.offset[n_elem] * 4.0 / 1e6,
      t_search, t_mapped, t_search / t_mapped, sum1 == sum2 ? "" : " MISMATCH");
  sl_csr_elem_map_free(&map);
  sl_csr_free(&A);
  free(el), free(ptr);
  return 0;
}

int main(int argc, char **argv) {
  int N = argc > 1 ? atoi(argv[1]) : 256;
  if (N < 2) N = 256;
  int rc = bench_solvers(N);
  rc |= bench_assembly(N, 0);
  rc |= bench_assembly(N, 1);
  return rc;
}
