/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A linear solver's kept factorisation in a checkpoint (factor_checkpoint.h). */
#include "core/models/navier_stokes/factor_checkpoint.h"

#include <stdio.h>

int sl_factor_checkpoint(sl_linsolve *ls, const char *name, sl_checkpoint_array *a, int max) {
  const double *h = NULL;
  int64_t n = max > 0 ? sl_linsolve_history(ls, &h) : 0;
  if (n <= 0) {
    sl_linsolve_drop_numeric(ls);
    return 0;
  }
  snprintf(a[0].name, sizeof a[0].name, "%s", name);
  a[0].n = n, a[0].data = h;
  return 1;
}

int sl_factor_restore(sl_linsolve *ls, const char *name, const sl_checkpoint *ck, sl_diag *d) {
  const sl_checkpoint_array *a = sl_checkpoint_find(ck, name);
  if (!a) return 0;
  int rc = sl_linsolve_restore_history(ls, a->data, a->n, d);
  return rc ? sl_diag_prefix(d, rc, "%s", name) : 0;
}
