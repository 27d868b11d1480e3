/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Validity check shared by the granular and wall_stress closures: every
 * input against its declared closed range [valid_min, valid_max], point by
 * point so that the first bad point is the one named, written as a negated
 * range so that NaN fails too. Header-only, static inline, no state. */
#ifndef SLUICE_PLUGINS_GRANULAR_INPUTS_H
#define SLUICE_PLUGINS_GRANULAR_INPUTS_H

#include <sluice/closure.h>

static inline int gr_check_inputs(const sl_eval_args *a, const sl_field_desc *in, int32_t n_in) {
  for (int32_t q = 0; q < a->Q; ++q)
    for (int32_t i = 0; i < n_in; ++i) {
      double x = a->in[i][q];
      if (!(x >= in[i].valid_min && x <= in[i].valid_max))
        return sl_fail(a->err, SL_RECOVERABLE, q, "%s = %g outside its validity range [%g, %g]", in[i].name, x,
                       in[i].valid_min, in[i].valid_max);
    }
  return SL_OK;
}

/* Writes v when the slot exists (optional outputs and their derivatives). */
static inline void gr_set(double *p, int32_t q, double v) {
  if (p) p[q] = v;
}

#endif
