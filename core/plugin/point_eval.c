/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/point_eval.h"

#include "core/plugin/guard.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int sl_point_bind(sl_point_closure *pc, sl_closure *c, const char *const *names, int n_names, const char *section,
                  const char *model, sl_diag *d) {
  memset(pc, 0, sizeof *pc);
  pc->c = c, pc->names = names, pc->n_names = n_names, pc->failed_point = -1;
  if (n_names > SL_POINT_MAX_NAMES)
    return sl_diag_set(d, SL_EBADINPUT, "[%s]: more than %d quantities", section, SL_POINT_MAX_NAMES);
  const sl_closure_desc *cd = c->desc;
  char label[128];
  sl_closure_label(cd, label, sizeof label);
  if (cd->n_in > SL_POINT_MAX_IN || cd->n_out > SL_POINT_MAX_IN)
    return sl_diag_set(d, SL_EBADINPUT, "[%s] %s: more than %d inputs or outputs", section, label, SL_POINT_MAX_IN);
  for (int i = 0; i < cd->n_in; ++i) {
    int k = 0;
    while (k < n_names && strcmp(names[k], cd->in[i].name) != 0) ++k;
    if (k == n_names) {
      char list[512];
      size_t at = 0;
      list[0] = '\0';
      for (int j = 0; j < n_names && at < sizeof list; ++j)
        at += (size_t)snprintf(list + at, sizeof list - at, "%s%s", j ? ", " : "", names[j]);
      return sl_diag_set(d, SL_EBADINPUT, "[%s] %s needs the input '%s', which %s does not provide (it provides %s)",
                         section, label, cd->in[i].name, model, list);
    }
    pc->source[i] = k;
  }
  return 0;
}

void sl_point_constant(sl_point_closure *pc, const char *name, double value) {
  for (int k = 0; k < pc->n_names && k < SL_POINT_MAX_NAMES; ++k)
    if (strcmp(pc->names[k], name) == 0) pc->constant[k] = value;
}

int sl_point_differentiates(const sl_point_closure *pc, const char *name) {
  int i = sl_closure_input(pc->c->desc, name);
  return i >= 0 && (pc->c->desc->in[i].flags & SL_FIELD_DIFF) != 0;
}

int sl_point_has_output(const sl_point_closure *pc, const char *name) {
  return sl_closure_output(pc->c->desc, name) >= 0;
}

int sl_point_has_input(const sl_point_closure *pc, const char *name) {
  return sl_closure_input(pc->c->desc, name) >= 0;
}

int sl_point_eval(sl_point_closure *pc, int Q, const double *const *values, const sl_point_request *rq, int n_rq,
                  sl_diag *d) {
  const sl_closure_desc *cd = pc->c->desc;
  const int n_in = cd->n_in, n_out = cd->n_out;
  int out_of[SL_POINT_MAX_IN], wrt_of[SL_POINT_MAX_IN], want_d = 0, n_const = 0;
  char label[128];
  pc->failed_point = -1;
  for (int r = 0; r < n_rq; ++r) {
    out_of[r] = sl_closure_output(cd, rq[r].output);
    wrt_of[r] = rq[r].wrt ? sl_closure_input(cd, rq[r].wrt) : -1;
    if (out_of[r] < 0)
      return sl_diag_set(d, SL_EFAILED, "closure %s gives no output '%s'", sl_closure_label(cd, label, sizeof label),
                         rq[r].output);
    if (rq[r].derivative) want_d = 1;
  }
  for (int i = 0; i < n_in; ++i) n_const += !values[pc->source[i]];
  /* scratch: every non-optional output, plus one derivative slot per
   * (computed output, differentiable input) pair when any is wanted (ABI) */
  size_t need = (size_t)Q * (size_t)(n_const + n_out + (want_d ? n_out * n_in : 0));
  if (need > pc->cap) {
    double *nb = realloc(pc->buf, need * sizeof *nb);
    if (!nb) return sl_diag_set(d, SL_ENOMEM, "closure %s: out of memory", sl_closure_label(cd, label, sizeof label));
    pc->buf = nb, pc->cap = need;
  }
  const double *in[SL_POINT_MAX_IN];
  double *outs[SL_POINT_MAX_IN] = {0}, *dout[SL_POINT_MAX_IN * SL_POINT_MAX_IN] = {0}, *w = pc->buf;
  for (int i = 0; i < n_in; ++i) {
    int k = pc->source[i];
    if (values[k]) {
      in[i] = values[k];
      continue;
    }
    for (int q = 0; q < Q; ++q) w[q] = pc->constant[k];
    in[i] = w, w += Q;
  }
  for (int k = 0; k < n_out; ++k) {
    int asked = 0;
    for (int r = 0; r < n_rq; ++r) asked |= out_of[r] == k;
    if (asked || !(cd->out[k].flags & SL_FIELD_OPTIONAL)) outs[k] = w, w += Q;
  }
  if (want_d)
    for (int k = 0; k < n_out; ++k)
      for (int i = 0; i < n_in && outs[k]; ++i)
        if (cd->in[i].flags & SL_FIELD_DIFF) dout[k * n_in + i] = w, w += Q;
  sl_error err;
  /* the time level being solved and its step, as the time loop set them */
  double t, dt;
  sl_guard_clock(&t, &dt);
  sl_eval_args a = {.Q = Q, .t = t, .dt = dt, .in = in, .out = outs, .dout = want_d ? dout : NULL, .err = &err};
  int rc = sl_closure_evaluate(pc->c, &a);
  if (rc) {
    sl_closure_label(cd, label, sizeof label);
    pc->failed_point = err.point >= 0 && err.point < Q ? err.point : -1;
    char where[512] = "";
    if (err.point >= 0 && err.point < Q) {
      size_t at = (size_t)snprintf(where, sizeof where, " at point %d (", err.point);
      for (int i = 0; i < n_in && at < sizeof where; ++i)
        at += (size_t)snprintf(where + at, sizeof where - at, "%s%s = %g", i ? ", " : "", cd->in[i].name,
                               in[i][err.point]);
      if (at < sizeof where) snprintf(where + at, sizeof where - at, ")");
    }
    return sl_diag_set(d, SL_EFAILED, "closure %s %s%s: %s", label, rc > 0 ? "is outside its validity" : "failed",
                       where, err.msg);
  }
  for (int r = 0; r < n_rq; ++r) {
    memcpy(rq[r].values, outs[out_of[r]], (size_t)Q * sizeof(double));
    if (!rq[r].derivative) continue;
    const double *src = wrt_of[r] >= 0 ? dout[out_of[r] * n_in + wrt_of[r]] : NULL;
    if (src) memcpy(rq[r].derivative, src, (size_t)Q * sizeof(double));
    else memset(rq[r].derivative, 0, (size_t)Q * sizeof(double));
  }
  return 0;
}

void sl_point_release(sl_point_closure *pc) {
  free(pc->buf);
  pc->buf = NULL, pc->cap = 0;
}
