/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Deliberately broken closure libraries for the loader tests: each is a
 * small valid closure with one defect, chosen by a macro at compile time. */
#include <math.h>
#include <sluice/closure.h>

typedef struct toy_params {
  double a;
} toy_params;

static const sl_param_desc toy_param_table[] = {
    SL_PARAM_REAL_OF(toy_params, a, 2.0, 0.0, 10.0, "1", "coefficient"),
};
static const sl_field_desc toy_inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.3, 0.0, 0.6, "solids fraction"},
};
static const sl_field_desc toy_outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "toy pressure a phi^2"},
};

/* p_s = a phi^2, the defects below change this where they are about evaluation. */
static int toy_evaluate(const void *state, const sl_eval_args *args) {
  const toy_params *p = state;
  const double *phi = args->in[0];
  double *out = args->out[0];
  double *dphi = sl_dout(args, 1, 0, 0);
  for (int32_t q = 0; q < args->Q; ++q) {
    if (!(phi[q] >= 0.0 && phi[q] <= 0.6))
      return sl_fail(args->err, SL_RECOVERABLE, q, "phi = %g outside [0, 0.6]", phi[q]);
#if defined(TOY_RETURNS_NAN)
    out[q] = phi[q] > 0.5 ? NAN : p->a * phi[q] * phi[q];
#elif defined(TOY_RECOVERABLE_ABOVE)
    if (phi[q] > TOY_RECOVERABLE_ABOVE) return sl_fail(args->err, SL_RECOVERABLE, q, "toy refuses phi = %g", phi[q]);
    out[q] = p->a * phi[q] * phi[q];
#else
    out[q] = p->a * phi[q] * phi[q];
#endif
    if (dphi) {
#if defined(TOY_WRONG_DERIVATIVE)
      dphi[q] = p->a * phi[q]; /* should be 2 a phi */
#else
      dphi[q] = 2.0 * p->a * phi[q];
#endif
    }
  }
  return SL_OK;
}

#ifndef TOY_NAME
#define TOY_NAME "toy"
#endif

static const sl_closure_desc toy = {
    SL_CLOSURE_DESC_HEADER,
#if defined(TOY_ABI_MAJOR)
    .abi_major = TOY_ABI_MAJOR,
#endif
#if defined(TOY_REAL_SIZE)
    .real_size = TOY_REAL_SIZE,
#endif
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = TOY_NAME,
    .version = "0.0.1",
    .summary = "test closure",
    .formula = "p_s = a phi^2",
    .reference = "none: a test fixture",
    .validity = "0 <= phi <= 0.6",
    .n_params = 1,
    .params = toy_param_table,
    .params_size = sizeof(toy_params),
    .n_in = 1,
    .in = toy_inputs,
    .n_out = 1,
    .out = toy_outputs,
    .evaluate = toy_evaluate,
};
