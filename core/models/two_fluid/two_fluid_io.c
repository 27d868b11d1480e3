/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The checkpoint of a two_fluid run, the same for the 1-D column and the
 * 2-D model (two_fluid_impl.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_impl.h"

static const char *const STATE_NAMES[5] = {"phi", "velocity_solid", "velocity_fluid", "pressure", "solids_book"};

int tf_checkpoint_arrays(tf_state *s, sl_checkpoint_array *a, int max) {
  if (max < 6) return 0;
  s->book[0] = s->inventory0, s->book[1] = s->outflow;
  const double *data[5] = {s->phi, s->us, s->uf, s->p, s->book};
  int64_t len[5] = {s->n_cells, s->n_faces, s->n_faces, s->n_cells, 2};
  for (int k = 0; k < 5; ++k) {
    snprintf(a[k].name, sizeof a[k].name, "%s", STATE_NAMES[k]);
    a[k].n = len[k], a[k].data = data[k];
  }
  if (!s->theta) return 5;
  snprintf(a[5].name, sizeof a[5].name, "theta");
  a[5].n = s->n_cells, a[5].data = s->theta;
  return 6;
}

int tf_checkpoint_restore(const sl_checkpoint *ck, const char *model, tf_state *s, sl_diag *d) {
  double *dst[4] = {s->phi, s->us, s->uf, s->p};
  int64_t len[5] = {s->n_cells, s->n_faces, s->n_faces, s->n_cells, 2};
  for (int k = 0; k < 5; ++k) {
    const sl_checkpoint_array *a = sl_checkpoint_find(ck, STATE_NAMES[k]);
    if (!a || a->n != len[k])
      return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no %s '%s' of %lld values", model,
                         STATE_NAMES[k], (long long)len[k]);
    if (k < 4) memcpy(dst[k], a->data, (size_t)a->n * sizeof(double));
    else s->inventory0 = a->data[0], s->outflow = a->data[1];
  }
  if (s->theta) {
    const sl_checkpoint_array *a = sl_checkpoint_find(ck, "theta");
    if (!a || a->n != s->n_cells)
      return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no %s 'theta' of %lld values", model,
                         (long long)s->n_cells);
    memcpy(s->theta, a->data, (size_t)a->n * sizeof(double));
  }
  return 0;
}
