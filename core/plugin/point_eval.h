/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The one binder of a host's quantities to a closure's inputs. A closure
 * is evaluated at a batch of points whose inputs the host supplies by name:
 * the binding maps each of the closure's inputs to one of the host's named
 * quantities, once; an evaluation fills the outputs asked for and,
 * optionally, their derivatives with respect to one input. A quantity the
 * host holds constant (a material property) is given once with
 * sl_point_constant and passed as NULL in the values of an evaluation.
 *
 *   static const char *const names[] = {"phi", "theta", "rho_s", "d_p"};
 *   sl_point_closure pc;
 *   sl_point_bind(&pc, closure, names, 4, "closure.granular", "the shear layer", d);
 *   sl_point_constant(&pc, "rho_s", 2650.0), sl_point_constant(&pc, "d_p", 1e-3);
 *   const double *values[4] = {phi, theta, NULL, NULL};      // each [Q]
 *   sl_point_request rq[1] = {{"mu_s", mu, dmu_dtheta, "theta"}};
 *   sl_point_eval(&pc, Q, values, rq, 1, d);
 */
#ifndef SLUICE_PLUGIN_POINT_EVAL_H
#define SLUICE_PLUGIN_POINT_EVAL_H

#include "core/plugin/instance.h"
#include "core/util/diag.h"

enum { SL_POINT_MAX_IN = 32, SL_POINT_MAX_NAMES = 32 };

typedef struct sl_point_closure {
  sl_closure *c;               /* not owned */
  int source[SL_POINT_MAX_IN]; /* the host quantity of each closure input */
  const char *const *names;    /* the host's quantity names (the binding's) */
  int n_names;
  double constant[SL_POINT_MAX_NAMES]; /* the value of a quantity passed as NULL */
  int failed_point; /* the point of the last failed evaluation (-1: none), for the caller's context */
  double *buf;
  size_t cap;
} sl_point_closure;

/* One output wanted: its values (n points), and optionally its derivative
 * with respect to the input `wrt` (NULL: none). The derivative is 0 where
 * the closure does not differentiate that input (or has no such input).
 * The same output may be asked twice with different `wrt`: one call to the
 * closure serves every request. */
typedef struct sl_point_request {
  const char *output;
  double *values;
  double *derivative;
  const char *wrt;
} sl_point_request;

/* Binds c's inputs to the host's quantities by name. SL_EBADINPUT names the
 * closure, the section and the missing input, and lists what `model`
 * provides. */
int sl_point_bind(sl_point_closure *pc, sl_closure *c, const char *const *names, int n_names, const char *section,
                  const char *model, sl_diag *d);
/* The value of quantity `name` wherever an evaluation passes it as NULL. */
void sl_point_constant(sl_point_closure *pc, const char *name, double value);

/* 1 when the closure gives the output `name`. */
int sl_point_has_output(const sl_point_closure *pc, const char *name);
/* 1 when the closure has the input `name`. */
int sl_point_has_input(const sl_point_closure *pc, const char *name);
/* 1 when the closure's input `name` exists and is differentiable. */
int sl_point_differentiates(const sl_point_closure *pc, const char *name);

/* Evaluates Q points; values[k] is the host quantity k at every point (the
 * order of the binding's names), NULL for a constant. SL_EFAILED with the
 * closure's message and the offending point's inputs when it fails or
 * leaves its validity (pc->failed_point is that point). */
int sl_point_eval(sl_point_closure *pc, int Q, const double *const *values, const sl_point_request *rq, int n_rq,
                  sl_diag *d);

void sl_point_release(sl_point_closure *pc);

#endif
