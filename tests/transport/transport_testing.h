/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Helpers shared by the transport tests: a zero settling closure (pure
 * advection), a fatal-error exit and a checked allocation. */
#ifndef SLUICE_TESTS_TRANSPORT_TESTING_H
#define SLUICE_TESTS_TRANSPORT_TESTING_H

#include <stdio.h>
#include <stdlib.h>

#include "core/util/diag.h"

/* Settling velocity and its derivative 0 for every phi: advection by q only. */
static inline int no_settling(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  (void)user, (void)phi, (void)d;
  for (int i = 0; i < n; ++i) u[i] = du[i] = 0;
  return 0;
}

static inline void die(const char *what, const sl_diag *d) {
  fprintf(stderr, "%s: %s\n", what, d->msg);
  exit(1);
}

static inline double *alloc(int n) {
  double *p = malloc((size_t)n * sizeof *p);
  if (!p) exit(1);
  return p;
}

#endif
