/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Pringle's (2001) artificial neural network for the reference porosity nbar
 * of a sand under cyclic shear: 3 inputs, one hidden layer of 3 logistic
 * nodes, 1 logistic output, min-max scaling of inputs and output (thesis
 * section 3.3.2 and Appendix 3; trained with EasyNN on VELACS undrained
 * cyclic triaxial data):
 *   xbar_i = (x_i - x_i,min)/(x_i,max - x_i,min)
 *   V_j = 1/(1 + exp(-(sum_i xbar_i W^h_ij + b^h_j)))
 *   Y = 1/(1 + exp(-(sum_j V_j W^o_j + b^o))),  nbar_new = Y (Y_max - Y_min) + Y_min.
 * The weights default to those printed in the thesis; its normalisation
 * ranges were not printed, so the defaults of the eight range parameters
 * are placeholders a user must replace with the ranges the weights belong
 * to. Two ambiguities of the print are parameters: the input order (the
 * thesis lists [increment, log total, nbar] in the text and [log total,
 * increment, nbar] in the appendix) and which index of W^h is the row
 * (printed v_j = xbar_i W^h_ij: the row is the input). The logarithm is
 * base 10 (not stated). With no shear in the step (strain_increment = 0)
 * nbar is returned unchanged: the network was trained on shearing only. */
#include <math.h>
#include <sluice/closure.h>

typedef struct ann_params {
  double wh11, wh12, wh13, wh21, wh22, wh23, wh31, wh32, wh33;
  double bh1, bh2, bh3;
  double wo1, wo2, wo3, bo;
  double log_total_min, log_total_max, increment_min, increment_max, nbar_min, nbar_max, out_min, out_max;
  int32_t order; /* 0: log total, increment, nbar; 1: increment, log total, nbar */
  int32_t rows;  /* 0: W^h rows are the inputs; 1: the hidden nodes */
} ann_params;

enum { IN_NBAR, IN_INC, IN_TOTAL, N_IN };
enum { OUT_NBAR, N_OUT };

#define W(m, v, text) SL_PARAM_REAL_OF(ann_params, m, v, -1e3, 1e3, "1", text)
static const sl_param_desc params[] = {
    W(wh11, -1.159932, "W^h (1,1), Pringle (2001) Appendix 3"),
    W(wh12, -2.163154, "W^h (1,2)"),
    W(wh13, 8.074500, "W^h (1,3)"),
    W(wh21, -1.153477, "W^h (2,1)"),
    W(wh22, -2.234670, "W^h (2,2)"),
    W(wh23, 7.259948, "W^h (2,3)"),
    W(wh31, 1.555892, "W^h (3,1)"),
    W(wh32, -5.063079, "W^h (3,2)"),
    W(wh33, 8.430298, "W^h (3,3)"),
    W(bh1, -6.2368, "b^h_1"),
    W(bh2, -5.4514, "b^h_2"),
    W(bh3, 0.6681, "b^h_3"),
    W(wo1, 3.256640, "W^o_1"),
    W(wo2, 2.570816, "W^o_2"),
    W(wo3, 2.172821, "W^o_3"),
    W(bo, 1.8695, "b^o"),
    SL_PARAM_REAL_OF(ann_params, log_total_min, -6.0, -20.0, 5.0, "1",
                     "log10 of the total shear strain scaled to 0 (not printed in the thesis: supply yours)"),
    SL_PARAM_REAL_OF(ann_params, log_total_max, 0.0, -20.0, 5.0, "1", "log10 of the total shear strain scaled to 1"),
    SL_PARAM_REAL_OF(ann_params, increment_min, 0.0, 0.0, 1.0, "1", "the strain increment scaled to 0"),
    SL_PARAM_REAL_OF(ann_params, increment_max, 1e-3, 0.0, 1.0, "1", "the strain increment scaled to 1"),
    SL_PARAM_REAL_OF(ann_params, nbar_min, 0.35, 0.01, 0.99, "1", "the input nbar scaled to 0"),
    SL_PARAM_REAL_OF(ann_params, nbar_max, 0.50, 0.01, 0.99, "1", "the input nbar scaled to 1"),
    SL_PARAM_REAL_OF(ann_params, out_min, 0.35, 0.01, 0.99, "1", "the output nbar at Y = 0"),
    SL_PARAM_REAL_OF(ann_params, out_max, 0.50, 0.01, 0.99, "1", "the output nbar at Y = 1"),
    SL_PARAM_ENUM_OF(ann_params, order, 0, "log_total_first|increment_first",
                     "input order: Appendix 3 (log total, increment, nbar) or the text (increment, log total, nbar)"),
    SL_PARAM_ENUM_OF(ann_params, rows, 0, "inputs|hidden", "the row index of the printed W^h"),
};
#undef W

static const sl_field_desc inputs[] = {
    {"nbar", "1", 0, 0.45, 0.01, 0.99, "reference porosity of the sand before the step"},
    {"strain_increment", "1", 0, 1e-4, 0.0, 1.0, "|change of shear strain| over the step"},
    {"strain_total", "1", 0, 1e-3, 0.0, 1e3, "accumulated |shear strain| path"},
};

static const sl_field_desc outputs[] = {
    {"nbar_new", "1", 0, 0, 0, 0, "reference porosity after the step"},
};

/* The network by hand (numpy) at the defaults, Appendix-3 order, rows = inputs. */
static const double check_in_0[N_IN] = {0.45, 1e-4, 1e-3};
static const double check_in_1[N_IN] = {0.45, 0.0, 1e-3};
static const sl_check_point checks[] = {
    {check_in_0, OUT_NBAR, 0.49743475470787185, 1e-12,
     "the 3-3-1 network with the printed weights, placeholder ranges, by hand"},
    {check_in_1, OUT_NBAR, 0.45, 1e-15, "no shear in the step: nbar unchanged"},
};

static double logistic(double v) { return 1.0 / (1.0 + exp(-v)); }

static int evaluate(const void *state, const sl_eval_args *a) {
  const ann_params *p = state;
  const double *nbar = a->in[IN_NBAR], *inc = a->in[IN_INC], *tot = a->in[IN_TOTAL];
  double *out = a->out[OUT_NBAR];
  const double wh[3][3] = {{p->wh11, p->wh12, p->wh13}, {p->wh21, p->wh22, p->wh23}, {p->wh31, p->wh32, p->wh33}};
  const double bh[3] = {p->bh1, p->bh2, p->bh3}, wo[3] = {p->wo1, p->wo2, p->wo3};
  if (!(p->log_total_max > p->log_total_min) || !(p->increment_max > p->increment_min) ||
      !(p->nbar_max > p->nbar_min) || !(p->out_max > p->out_min))
    return sl_fail(a->err, SL_ERR_ARG, -1, "each normalisation range needs max > min");
  for (int32_t q = 0; q < a->Q; ++q) {
    for (int i = 0; i < N_IN; ++i) {
      double v = a->in[i][q];
      if (!(v >= inputs[i].valid_min && v <= inputs[i].valid_max))
        return sl_fail(a->err, SL_RECOVERABLE, q, "%s = %g outside [%g, %g]", inputs[i].name, v, inputs[i].valid_min,
                       inputs[i].valid_max);
    }
    if (inc[q] == 0.0) {
      out[q] = nbar[q];
      continue;
    }
    double lt = log10(fmax(tot[q], 1e-300));
    double xl = (lt - p->log_total_min) / (p->log_total_max - p->log_total_min);
    double xi = (inc[q] - p->increment_min) / (p->increment_max - p->increment_min);
    double xn = (nbar[q] - p->nbar_min) / (p->nbar_max - p->nbar_min);
    double x[3] = {xl, xi, xn};
    if (p->order == 1) x[0] = xi, x[1] = xl;
    double y = p->bo;
    for (int j = 0; j < 3; ++j) {
      double v = bh[j];
      for (int i = 0; i < 3; ++i) v += x[i] * (p->rows == 0 ? wh[i][j] : wh[j][i]);
      y += logistic(v) * wo[j];
    }
    double r = logistic(y) * (p->out_max - p->out_min) + p->out_min;
    if (!isfinite(r) || !(r > 0.0 && r < 1.0))
      return sl_fail(a->err, SL_RECOVERABLE, q, "the network gives nbar = %g (check the ranges)", r);
    out[q] = r;
  }
  return SL_OK;
}

static const sl_closure_desc pringle_ann = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DENSIFICATION,
    .name = "pringle_ann",
    .version = "1.0.0",
    .summary = "Pringle (2001) 3-3-1 logistic network for nbar under cyclic shear (weights as printed, ranges yours)",
    .formula =
        "V_j = s(sum_i xbar_i W^h_ij + b^h_j), Y = s(sum_j V_j W^o_j + b^o), s(v) = 1/(1 + e^-v)\n"
        "xbar = min-max scaled (log10 total strain, increment, nbar); nbar_new = Y (max - min) + min",
    .reference =
        "Pringle (2001) PhD thesis, McMaster University, section 3.3.2 and Appendix 3 (weights); VELACS "
        "(1997) training data",
    .validity =
        "only with the normalisation ranges the weights were trained with (not printed in the thesis: the "
        "defaults are placeholders)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(ann_params),
    .n_in = N_IN,
    .in = inputs,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = NULL,
    .evaluate = evaluate,
    .destroy = NULL,
};

static const sl_closure_desc *const all[] = {&pringle_ann};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
