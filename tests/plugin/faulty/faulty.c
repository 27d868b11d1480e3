/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A viscosity closure that misbehaves on request, for the isolation tests
 * (tests/plugin/CMakeLists.txt): mu = mu0, constant (a Newtonian fluid), and
 * from the time `after` on the fault chosen by `fault`:
 *   segv  writes through a null pointer        fpe   divides an integer by 0
 *   loop  never returns                        exit  calls exit(0)
 *   fatal returns SL_ERR_INTERNAL (< 0)         clock logs t and dt once per time level
 * Built with FAULTY_DEFAULT = the index of a fault, it has that fault at its
 * defaults (what `sluice check-closure` runs). FAULTY_CONSTRUCTOR_MARKER: a
 * library constructor that creates the file named by $SLUICE_TEST_MARKER
 * (whether, and in which process, a library's code ran). */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sluice/closure.h>

#ifndef FAULTY_NAME
#define FAULTY_NAME "faulty"
#endif
#ifndef FAULTY_DEFAULT
#define FAULTY_DEFAULT 0
#endif

enum { F_NONE, F_SEGV, F_FPE, F_LOOP, F_EXIT, F_FATAL, F_CLOCK };

typedef struct faulty_params {
  double mu0, after;
  int32_t fault;
} faulty_params;

typedef struct faulty_state {
  faulty_params p;
  const sl_host_api *api;
} faulty_state;

static const sl_param_desc faulty_param_table[] = {
    SL_PARAM_REAL_OF(faulty_params, mu0, 1.0, 1e-6, 1e6, "Pa s", "the viscosity"),
    SL_PARAM_REAL_OF(faulty_params, after, 0.0, 0.0, 1e9, "s", "the fault happens from this time on"),
    SL_PARAM_ENUM_OF(faulty_params, fault, FAULTY_DEFAULT, "none|segv|fpe|loop|exit|fatal|clock", "what goes wrong"),
};
static const sl_field_desc faulty_inputs[] = {
    {"shear_rate", "s^-1", SL_FIELD_DIFF, 1.0, 0.0, 1e12, "shear-rate magnitude"},
};
static const sl_field_desc faulty_outputs[] = {
    {"viscosity", "Pa s", 0, 0, 0, 0, "mu0"},
};

#if defined(FAULTY_CONSTRUCTOR_MARKER)
#include <unistd.h>
/* Which process ran the library's code: the marker file gets its pid. With
 * $SLUICE_TEST_CONSTRUCTOR_CRASH set the constructor crashes instead. */
__attribute__((constructor)) static void mark(void) {
  const char *path = getenv("SLUICE_TEST_MARKER");
  FILE *f = path ? fopen(path, "a") : NULL;
  if (f) fprintf(f, "constructor of %s ran in pid %ld\n", FAULTY_NAME, (long)getpid()), fclose(f);
  if (getenv("SLUICE_TEST_CONSTRUCTOR_CRASH")) raise(SIGSEGV);
}
#endif

static int faulty_create(const sl_host_api *api, const void *params, void **state, sl_error *err) {
  faulty_state *s = api->alloc(api->host, sizeof *s);
  if (!s) return sl_fail(err, SL_ERR_MEM, -1, "out of memory");
  memcpy(&s->p, params, sizeof s->p);
  s->api = api;
  *state = s;
  return SL_OK;
}

static void faulty_destroy(const sl_host_api *api, void *state) { api->free(api->host, state); }

static volatile int zero; /* what the compiler cannot see through */

static int faulty_evaluate(const void *state, const sl_eval_args *args) {
  const faulty_state *s = state;
  int fault = args->t >= s->p.after ? s->p.fault : F_NONE;
  switch (fault) {
    case F_SEGV: {
      volatile int *volatile p = NULL;
      *p = 1;
      break;
    }
    case F_FPE: {
      volatile int one = 1;
      volatile int r = one / zero;
      (void)r;
      break;
    }
    case F_LOOP:
      for (volatile unsigned long i = 1; i != 0; i = i % 1000 + 1) {
      }
      break;
    case F_EXIT:
      exit(0);
    case F_FATAL:
      return sl_fail(args->err, SL_ERR_INTERNAL, 0, "the test closure gives up at t = %g", args->t);
    case F_CLOCK: {
      static double last_t = -1.0;
      if (args->t != last_t) s->api->log(s->api->host, SL_LOG_INFO, "t = %.6g dt = %.6g", args->t, args->dt);
      last_t = args->t;
      break;
    }
    default:
      break;
  }
  double *mu = args->out[0];
  double *dmu = sl_dout(args, 1, 0, 0);
  for (int32_t q = 0; q < args->Q; ++q) {
    const double g = args->in[0][q];
    if (!(g >= 0.0 && g <= 1e12)) return sl_fail(args->err, SL_RECOVERABLE, q, "shear_rate = %g outside [0, 1e12]", g);
    mu[q] = s->p.mu0;
    if (dmu) dmu[q] = 0.0;
  }
  return SL_OK;
}

static const sl_closure_desc faulty = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_VISCOSITY,
    .name = FAULTY_NAME,
    .version = "0.0.1",
    .summary = "test closure with a fault on request",
    .formula = "mu = mu0",
    .reference = "none: a test fixture",
    .validity = "any shear rate",
    .n_params = SL_COUNT_OF(faulty_param_table),
    .params = faulty_param_table,
    .params_size = sizeof(faulty_params),
    .n_in = SL_COUNT_OF(faulty_inputs),
    .in = faulty_inputs,
    .n_out = SL_COUNT_OF(faulty_outputs),
    .out = faulty_outputs,
    .create = faulty_create,
    .evaluate = faulty_evaluate,
    .destroy = faulty_destroy,
};

static const sl_closure_desc *const all[] = {&faulty};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
