/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Small dense systems (dense.h). */
#include "core/solve/dense.h"

#include <math.h>

int sl_dense_solve(int m, double *A, double *b, double *x, double pivot) {
  double big = 0.0;
  for (int i = 0; i < m; ++i) big = fmax(big, A[i * m + i]);
  if (!(big > 0.0)) return -1;
  for (int c = 0; c < m; ++c) {
    int p = c;
    for (int r = c + 1; r < m; ++r)
      if (fabs(A[r * m + c]) > fabs(A[p * m + c])) p = r;
    if (!(fabs(A[p * m + c]) > pivot * big)) return -1;
    if (p != c) {
      for (int k = 0; k < m; ++k) {
        double t = A[c * m + k];
        A[c * m + k] = A[p * m + k], A[p * m + k] = t;
      }
      double t = b[c];
      b[c] = b[p], b[p] = t;
    }
    for (int r = c + 1; r < m; ++r) {
      double l = A[r * m + c] / A[c * m + c];
      for (int k = c; k < m; ++k) A[r * m + k] -= l * A[c * m + k];
      b[r] -= l * b[c];
    }
  }
  for (int r = m - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < m; ++k) s -= A[r * m + k] * x[k];
    x[r] = s / A[r * m + r];
  }
  return 0;
}
