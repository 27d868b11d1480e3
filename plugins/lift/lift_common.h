/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What the lift closures share: the inputs' range check, and the near-wall damping of a lift coefficient,
 * Shaver & Podowski (2015, Trans. Am. Nucl. Soc. 112:1368, "Modeling of
 * interfacial forces for bubbly flows in subcooled boiling conditions"), a
 * cubic step in the distance y of the particle's centre from the wall in
 * particle diameters d:
 *   f = 0                              y/d < 1/2 (the particle touches the wall)
 *     = 3 (2y/d - 1)^2 - 2 (2y/d - 1)^3  1/2 <= y/d <= 1
 *     = 1                              y/d > 1,
 * C^1 at both ends, so that the unbounded-shear coefficient does not act on a
 * particle the wall cuts (where Saffman's and Mei's flows do not exist). */
#ifndef SLUICE_PLUGINS_LIFT_COMMON_H
#define SLUICE_PLUGINS_LIFT_COMMON_H

#include <sluice/closure.h>

/* SL_RECOVERABLE with the point named when an input of point q is outside its declared range (or NaN), else 0. */
static inline int lift_check_inputs(const sl_eval_args *a, const sl_field_desc *inputs, int n_in, int32_t q) {
  for (int i = 0; i < n_in; ++i) {
    const double v = a->in[i][q];
    if (!(v >= inputs[i].valid_min && v <= inputs[i].valid_max))
      return sl_fail(a->err, SL_RECOVERABLE, q, "%s = %g outside [%g, %g]", inputs[i].name, v, inputs[i].valid_min,
                     inputs[i].valid_max);
  }
  return 0;
}

static inline double lift_wall_damping(double y, double d) {
  const double x = 2.0 * y / d - 1.0;
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * (3.0 - 2.0 * x);
}

#endif
