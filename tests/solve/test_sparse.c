/* SPDX-License-Identifier: GPL-2.0-or-later */
/* CSR pattern builder, element assembly (searched and mapped), products and
 * Dirichlet rows. */
#include <stdlib.h>

#include "core/solve/linsolve.h"
#include "core/solve/sparse.h"
#include "poisson.h"
#include "testing.h"

static int same_i32(const int32_t *a, const int32_t *b, int n) {
  for (int i = 0; i < n; ++i)
    if (a[i] != b[i]) return 0;
  return 1;
}

/*  2---3      two triangles {0,1,2} and {1,3,2} sharing the edge 1-2
 *  | \ |
 *  0---1 */
static void test_pattern_two_triangles(void) {
  sl_diag d = {{0}};
  const int32_t tri[] = {0, 1, 2, 1, 3, 2};
  sl_csr A = {0};
  CHECK(sl_csr_build_uniform(&A, 4, 2, 3, tri, &d) == 0);
  const int32_t rp[] = {0, 3, 7, 11, 14};
  const int32_t ci[] = {0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 1, 2, 3};
  CHECK(A.n_rows == 4 && A.n_cols == 4 && A.nnz == 14);
  CHECK(same_i32(A.row_ptr, rp, 5));
  CHECK(same_i32(A.col_idx, ci, 14));
  CHECK(A.pattern_id != 0);
  for (int p = 0; p < A.nnz; ++p) CHECK(A.values[p] == 0.0);
  CHECK(sl_csr_find(&A, 0, 3) == -1);
  CHECK(sl_csr_find(&A, 3, 0) == -1);
  CHECK(sl_csr_find(&A, 2, 3) == 10);

  sl_csr B = {0};
  CHECK(sl_csr_build_uniform(&B, 4, 2, 3, tri, &d) == 0);
  CHECK(B.pattern_id != A.pattern_id); /* every build is a new pattern */
  sl_csr_free(&B);
  sl_csr_free(&A);
  CHECK(A.row_ptr == NULL && A.nnz == 0);
}

/* 1-D P2 elements {v0, v1, mid}: 3 elements on 7 dofs, and a constrained dof
 * given as -1 in the middle element. */
static void test_pattern_skip_and_rect(void) {
  sl_diag d = {{0}};
  const int32_t el[] = {0, 2, 1, 2, -1, 3, 4, 6, 5};
  sl_csr A = {0};
  CHECK(sl_csr_build_uniform(&A, 7, 3, 3, el, &d) == 0);
  const int32_t rp[] = {0, 3, 6, 10, 12, 15, 18, 21};
  const int32_t ci[] = {0, 1, 2, 0, 1, 2, 0, 1, 2, 3, 2, 3, 4, 5, 6, 4, 5, 6, 4, 5, 6};
  CHECK(A.nnz == 21);
  CHECK(same_i32(A.row_ptr, rp, 8));
  CHECK(same_i32(A.col_idx, ci, 21));
  sl_csr_free(&A);

  /* Rectangular: 4 "velocity" rows coupled to 2 "pressure" columns per element. */
  const int32_t rptr[] = {0, 3, 6}, rows[] = {0, 1, 2, 1, 3, 2};
  const int32_t cptr[] = {0, 1, 3}, cols[] = {0, 0, 1};
  CHECK(sl_csr_build(&A, 4, 2, 2, rptr, rows, cptr, cols, &d) == 0);
  const int32_t rp2[] = {0, 1, 3, 5, 7}, ci2[] = {0, 0, 1, 0, 1, 0, 1};
  CHECK(A.n_rows == 4 && A.n_cols == 2 && A.nnz == 7);
  CHECK(same_i32(A.row_ptr, rp2, 5));
  CHECK(same_i32(A.col_idx, ci2, 7));
  sl_csr_free(&A);

  /* Errors name the element and the index. */
  const int32_t bad[] = {0, 1, 9};
  CHECK(sl_csr_build_uniform(&A, 4, 1, 3, bad, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "element 0");
  CHECK_CONTAINS(d.msg, "index 9");
  CHECK(A.row_ptr == NULL);
  CHECK(sl_csr_build(&A, 4, 3, 2, rptr, rows, NULL, NULL, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "square");
}

static void test_assembly_and_matvec(void) {
  sl_diag d = {{0}};
  const int32_t tri[] = {0, 1, 2, 1, 3, 2};
  const double K0[] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, K1[] = {10, 20, 30, 40, 50, 60, 70, 80, 90};
  sl_csr A = {0}, B = {0};
  CHECK(sl_csr_build_uniform(&A, 4, 2, 3, tri, &d) == 0);
  CHECK(sl_csr_build_uniform(&B, 4, 2, 3, tri, &d) == 0);
  uint64_t g = A.values_gen;
  CHECK(sl_csr_add_element(&A, 3, tri, 3, tri, K0, &d) == 0);
  CHECK(sl_csr_add_element(&A, 3, tri + 3, 3, tri + 3, K1, &d) == 0);
  CHECK(A.values_gen > g);

  /* dense reference */
  double D[4][4] = {{0}};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      D[tri[a]][tri[b]] += K0[a * 3 + b];
      D[tri[3 + a]][tri[3 + b]] += K1[a * 3 + b];
    }
  int all = 1;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      int32_t p = sl_csr_find(&A, i, j);
      double v = p >= 0 ? A.values[p] : 0.0;
      if (v != D[i][j]) all = 0;
    }
  CHECK(all);

  /* The same through the precomputed element map gives identical values. */
  sl_csr_elem_map map;
  const int32_t eptr[] = {0, 3, 6};
  CHECK(sl_csr_elem_map_build(&map, &B, 2, eptr, tri, NULL, NULL, &d) == 0);
  g = B.values_gen;
  CHECK(sl_csr_add_element_mapped(&B, &map, 0, K0, &d) == 0);
  CHECK(sl_csr_add_element_mapped(&B, &map, 1, K1, &d) == 0);
  CHECK(sl_csr_add_element_mapped(&B, &map, 2, K1, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "out of range");
  CHECK(sl_csr_add_element_mapped(&A, &map, 0, K0, &d) == SL_EBADINPUT); /* map of B's pattern */
  CHECK_CONTAINS(d.msg, "another sparsity pattern");
  CHECK(B.values_gen > g);
  int same = 1;
  for (int p = 0; p < A.nnz; ++p)
    if (A.values[p] != B.values[p]) same = 0;
  CHECK(same);
  sl_csr_elem_map_free(&map);

  /* matvec and matvec_add against the dense product */
  const double x[] = {1.5, -2.0, 0.25, 3.0};
  double y[4], yr[4], z[4] = {1, 1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    yr[i] = 0;
    for (int j = 0; j < 4; ++j) yr[i] += D[i][j] * x[j];
  }
  sl_csr_matvec(&A, x, y);
  for (int i = 0; i < 4; ++i) CHECK_CLOSE(y[i], yr[i], 1e-15);
  sl_csr_matvec_add(&A, 2.0, x, -1.0, z);
  for (int i = 0; i < 4; ++i) CHECK_CLOSE(z[i], 2.0 * yr[i] - 1.0, 1e-15);

  /* zeroing keeps the pattern and bumps the generation */
  g = A.values_gen;
  sl_csr_zero(&A);
  CHECK(A.values_gen > g && A.nnz == 14);
  double s = 0;
  for (int p = 0; p < A.nnz; ++p) s += A.values[p] * A.values[p];
  CHECK(s == 0.0);

  /* An entry outside the pattern is refused with a message. */
  const int32_t r0 = 0, c3 = 3;
  const double one = 1.0;
  CHECK(sl_csr_add_element(&A, 1, &r0, 1, &c3, &one, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "(0, 3)");
  const int32_t far[] = {0, 3, 1};
  CHECK(sl_csr_elem_map_build(&map, &A, 1, eptr, far, NULL, NULL, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "not in the pattern");
  sl_csr_elem_map_free(&map);
  sl_csr_elem_map_free(&map); /* freeing twice is harmless */
  sl_csr_free(&A);
  sl_csr_free(&B);
}

/* Dirichlet rows on the 1-D Laplacian of 5 points, both variants. */
static void test_dirichlet(void) {
  sl_diag d = {{0}};
  sl_csr A = {0};
  CHECK(poisson_build(&A, 5, 1, 0.0, &d) == 0);
  double b[5] = {1, 1, 1, 1, 1};
  const int32_t rows[] = {0, 4};
  const double vals[] = {2.0, -1.0};
  CHECK(sl_csr_set_dirichlet(&A, 2, rows, vals, b, 0, &d) == 0);
  /* row 0 = e_0, row 4 = e_4; row 1 still couples to column 0 */
  CHECK(A.values[sl_csr_find(&A, 0, 0)] == 1.0 && A.values[sl_csr_find(&A, 0, 1)] == 0.0);
  CHECK(A.values[sl_csr_find(&A, 4, 4)] == 1.0 && A.values[sl_csr_find(&A, 4, 3)] == 0.0);
  CHECK(A.values[sl_csr_find(&A, 1, 0)] == -1.0);
  CHECK(b[0] == 2.0 && b[4] == -1.0 && b[1] == 1.0);

  sl_csr S = {0};
  double bs[5] = {1, 1, 1, 1, 1};
  CHECK(poisson_build(&S, 5, 1, 0.0, &d) == 0);
  CHECK(sl_csr_set_dirichlet(&S, 2, rows, vals, bs, 1, &d) == 0);
  /* columns eliminated: b1 = 1 + 1*2, b3 = 1 + 1*(-1) */
  CHECK(S.values[sl_csr_find(&S, 1, 0)] == 0.0 && S.values[sl_csr_find(&S, 3, 4)] == 0.0);
  CHECK(bs[0] == 2.0 && bs[1] == 3.0 && bs[2] == 1.0 && bs[3] == 0.0 && bs[4] == -1.0);

  /* Both systems give the same solution of -u'' = 1, u0 = 2, u4 = -1:
   * u = 2 - 3 i / 4 + i (4 - i) / 2 on the grid i = 0..4. */
  const double exact[5] = {2.0, 2.75, 2.5, 1.25, -1.0};
  for (int k = 0; k < 3; ++k) {
    const char *name = sl_linsolve_names(NULL)[k];
    sl_linsolve *ls = NULL;
    double x[5];
    CHECK(sl_linsolve_create(&ls, name, &d) == 0);
    if (k < 2) { /* cholmod refuses the nonsymmetric variant (tested elsewhere) */
      CHECK(sl_linsolve_solve(ls, &A, b, x, &d) == 0);
      for (int i = 0; i < 5; ++i) CHECK_CLOSE(x[i], exact[i], 1e-14);
    }
    sl_linsolve_destroy(ls);
    CHECK(sl_linsolve_create(&ls, name, &d) == 0);
    CHECK_MSG(sl_linsolve_solve(ls, &S, bs, x, &d) == 0, "%s: %s", name, d.msg);
    for (int i = 0; i < 5; ++i) CHECK_CLOSE(x[i], exact[i], 1e-14);
    sl_linsolve_destroy(ls);
  }

  /* b may be NULL (Newton Jacobians); a row without diagonal is refused. */
  CHECK(sl_csr_set_dirichlet(&S, 2, rows, NULL, NULL, 1, &d) == 0);
  const int32_t bad = 7;
  CHECK(sl_csr_set_dirichlet(&S, 1, &bad, NULL, NULL, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "row 7");
  sl_csr R = {0};
  const int32_t rptr[] = {0, 1}, r1[] = {1}, cptr[] = {0, 1}, c0[] = {0};
  CHECK(sl_csr_build(&R, 2, 2, 1, rptr, r1, cptr, c0, &d) == 0);
  CHECK(sl_csr_set_dirichlet(&R, 1, r1, NULL, NULL, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no diagonal");
  sl_csr_free(&R);
  sl_csr_free(&A);
  sl_csr_free(&S);
}

int main(void) {
  test_pattern_two_triangles();
  test_pattern_skip_and_rect();
  test_assembly_and_matvec();
  test_dirichlet();
  return sl_test_summary();
}
