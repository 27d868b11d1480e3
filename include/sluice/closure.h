/*
 * sluice closure ABI, version 1.
 *
 * SPDX-License-Identifier: MIT
 *
 * Copyright (c) 2026 the sluice developers.
 *
 * Permission is hereby granted, free of charge, to any person obtaining a copy
 * of this software and associated documentation files (the "Software"), to
 * deal in the Software without restriction, including without limitation the
 * rights to use, copy, modify, merge, publish, distribute, sublicense, and/or
 * sell copies of the Software, and to permit persons to whom the Software is
 * furnished to do so, subject to the following conditions: the above copyright
 * notice and this permission notice shall be included in all copies or
 * substantial portions of the Software. THE SOFTWARE IS PROVIDED "AS IS",
 * WITHOUT WARRANTY OF ANY KIND.
 *
 * This header is the whole interface between sluice and a closure library.
 * A closure that includes only this header is not a derived work of the
 * sluice core (which is GPL-2.0-or-later); closures may carry any licence.
 *
 * A closure is a pointwise constitutive law. Given the local state at a batch
 * of Q points it returns coefficients and, when asked, their derivatives with
 * respect to the inputs it marks differentiable. It never sees the mesh.
 *
 * Rules a closure library follows:
 *  - Export exactly one symbol, sl_closure_entry_v1, returning a static const
 *    array of descriptors (one library may hold several closures).
 *  - No global constructors, no printing, no exit/abort/longjmp.
 *  - Parameters arrive as a validated plain struct described by the schema.
 *  - evaluate() is reentrant: the state is immutable after create().
 *  - Return 0 (ok), > 0 (recoverable: state outside the law's validity; the
 *    host may cut the step) or < 0 (fatal), with the first bad point and a
 *    message in the host-owned sl_error.
 */
#ifndef SLUICE_CLOSURE_H
#define SLUICE_CLOSURE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SL_CLOSURE_ABI_MAJOR 1u
#define SL_CLOSURE_ABI_MINOR 0u
#define SL_CLOSURE_ENTRY_SYMBOL "sl_closure_entry_v1"

#if defined(__GNUC__)
#define SL_EXPORT __attribute__((visibility("default")))
#else
#define SL_EXPORT
#endif

/* Return codes of create() and evaluate(). Explicit values: never renumber. */
enum {
  SL_OK = 0,
  SL_RECOVERABLE = 1,  /* state outside the law's validity (phi >= phi_max, theta < 0, ...) */
  SL_ERR_ARG = -1,     /* inconsistent arguments (a bug in the caller) */
  SL_ERR_MEM = -2,     /* allocation failed */
  SL_ERR_INTERNAL = -3 /* anything else that cannot be retried */
};

/* Closure kinds. Each kind is a contract: the inputs a closure of the kind
 * must declare (* : it must return the derivative with respect to it, i.e.
 * mark it SL_FIELD_DIFF), the outputs the models read, in SI units. The
 * models supply the other canonical inputs listed further down when the
 * closure declares them; an input name the host does not know is refused
 * when the library is loaded. For every kind, evaluate() returns
 * SL_RECOVERABLE for an input outside the closure's declared validity range
 * or NaN. The full tables (typical values, ranges supplied, which model
 * reads what) are in the installed documentation, docs/closure-kinds.md
 * (share/doc/sluice/ under the install prefix), and writing one step by step
 * in docs/writing-a-closure.md; `sluice closure kinds` prints them.
 *
 *   kind               required inputs   outputs (required; optional)
 *   drag               phi*, slip*       K [kg m^-3 s^-1], F_s = K (u_f - u_s)
 *   hindered_settling  phi*              settling_velocity [m s^-1], zero at phi_max;
 *                                        hindrance [1], terminal_velocity [m s^-1]
 *   viscosity          (none)            viscosity [Pa s]
 *   solids_pressure    phi*              p_s [Pa]
 *   wall_stress        slip_wall*        tau_w [Pa]; bagnold_number [1],
 *                                        theta_flux [kg s^-3], u_tau [m s^-1], y_plus [1]
 *   granular           phi, theta        at least one of mu_s [Pa s],
 *                                        kappa [kg m^-1 s^-1], gamma [kg m^-1 s^-3],
 *                                        p_s [Pa], g0 [1]
 *   migration          phi               at least one of D_c [m^2], D_mu [m^2 s^-1]
 *   turbulence         k, epsilon        mu_t [Pa s]; mu_t_k, mu_t_eps [Pa s],
 *                                        eps_production [s^-1],
 *                                        eps_sink [kg m^-3 s^-1], c_mu [1]
 *   densification      nbar              nbar_new [1]; volumetric_strain_increment [1]
 *   lift               shear_rate        C_L [1], F_L = C_L rho_f phi (u_f - u_s) x curl u_f
 *   turbulent_dispersion (none)          D_t [m^2 s^-1], the solids' turbulent flux -D_t grad(phi)
 *   turbulence_modulation drag_coefficient exchange [kg m^-3 s^-1], c_eps3 [1]: c_f rho_f Pi_kf =
 *                                        exchange (k_fs - 2 k + drift work)
 *
 * A closure may declare extra named inputs beyond these. */
typedef enum sl_kind {
  SL_KIND_DRAG = 1,
  SL_KIND_HINDERED_SETTLING = 2,
  SL_KIND_VISCOSITY = 3,
  SL_KIND_SOLIDS_PRESSURE = 4,
  SL_KIND_WALL_STRESS = 5,
  SL_KIND_GRANULAR = 6,
  SL_KIND_MIGRATION = 7,
  SL_KIND_TURBULENCE = 8,
  SL_KIND_DENSIFICATION = 9,         /* the reference porosity nbar of a sand under cyclic shear (liquefaction) */
  SL_KIND_LIFT = 10,                 /* the shear-induced lift on the solids (its coefficient C_L) */
  SL_KIND_TURBULENT_DISPERSION = 11, /* the solids' turbulent dispersivity (drift by the fluid's eddies) */
  SL_KIND_TURBULENCE_MODULATION = 12 /* the particles' modulation of the fluid's k and epsilon */
} sl_kind;

/* ---- parameter schema ------------------------------------------------- */

typedef enum sl_param_type {
  SL_PARAM_REAL = 1, /* double */
  SL_PARAM_INT = 2,  /* int32_t */
  SL_PARAM_BOOL = 3, /* int32_t, 0 or 1 */
  SL_PARAM_ENUM = 4  /* int32_t index into the '|'-separated choices */
} sl_param_type;

typedef struct sl_param_desc {
  const char *name; /* INI key, lower_snake_case */
  sl_param_type type;
  size_t offset;       /* offsetof() into the closure's parameter struct */
  double def;          /* default (the choice index for ENUM) */
  double min, max;     /* closed bounds for REAL and INT */
  const char *units;   /* SI: "1", "Pa s", "m", "kg m^-3" */
  const char *choices; /* ENUM only: "stokes|schiller_naumann|rowe" */
  const char *help;    /* one line */
} sl_param_desc;

/* ---- fields (inputs and outputs) -------------------------------------- */

#define SL_FIELD_DIFF 1u     /* input: the closure returns d(outputs)/d(this input) */
#define SL_FIELD_OPTIONAL 2u /* output: the host may pass NULL when it does not need it */

/* Canonical input names the host knows how to supply (the full list with
 * ranges: docs/closure-kinds.md):
 *   phi         solids volume fraction                  1
 *   slip        |u_f - u_s|, slip speed                  m s^-1
 *   shear_rate  sqrt(2 D:D), shear-rate magnitude        s^-1
 *   theta       granular temperature                     m^2 s^-2
 *   rho_f, mu_f fluid density and dynamic viscosity      kg m^-3, Pa s
 *   rho_s, d_p  solid density and particle diameter      kg m^-3, m
 *   sphericity  particle sphericity                      1
 *   density     local mixture or fluid density           kg m^-3
 *   gravity     magnitude of the effective body force    m s^-2
 *   d_vessel    vessel (pipe, column) diameter           m
 *   wall_distance, slip_wall   distance to and tangential slip at a wall
 *   normal_stress  the solids' normal stress on a wall     Pa
 *   k, epsilon  turbulent kinetic energy and its dissipation rate  m^2 s^-2, m^2 s^-3
 *   nbar        reference porosity of a sand (Pringle 2001 eq 4.30), a state 1
 *   strain_amplitude  shear strain amplitude of the half-cycle ended at a strain
 *               reversal (0 between reversals)             1
 *   strain_increment  |change of shear strain| over the step      1
 *   strain_total      accumulated |shear strain| path             1
 *   volumetric_strain densification strain accumulated so far     1
 * Each input carries a typical value (used by `sluice closure eval` and the
 * conformance battery when no value is given) and its validity range. */
typedef struct sl_field_desc {
  const char *name;
  const char *units;
  uint32_t flags;
  double typical;              /* a representative value, inside [valid_min, valid_max] */
  double valid_min, valid_max; /* inputs: the declared validity range (closed) */
  const char *help;
} sl_field_desc;

/* ---- literature check points (conformance battery, item 7) ----------- */

typedef struct sl_check_point {
  const double *in;   /* one value per input, schema order; parameters at their defaults */
  int32_t out;        /* index of the output checked */
  double expected;    /* published or independently derived value */
  double rtol;        /* relative tolerance of the published figure */
  const char *source; /* where the number comes from */
} sl_check_point;

/* ---- host services ---------------------------------------------------- */

enum { SL_LOG_ERROR = 0, SL_LOG_WARNING = 1, SL_LOG_INFO = 2, SL_LOG_DEBUG = 3 };

typedef struct sl_host_api {
  uint32_t struct_size;
  uint32_t host_version; /* MAJOR*10000 + MINOR*100 + PATCH */
  int32_t dim;           /* spatial dimension of the scene, 0 when none (closure eval) */
  void (*log)(void *host, int level, const char *fmt, ...);
  void *(*alloc)(void *host, size_t bytes); /* zeroed, 64-byte aligned */
  void (*free)(void *host, void *p);
  void *host;
} sl_host_api;

/* Host-owned error record: the first bad point and a message. */
typedef struct sl_error {
  int32_t point; /* index q of the first offending point, -1 when not point-wise */
  char msg[256];
} sl_error;

/* ---- evaluation ------------------------------------------------------- */

/* One call per batch of Q points, structure of arrays.
 *   in[i][q]    value of input i at point q
 *   out[k][q]   output k; out[k] may be NULL only for SL_FIELD_OPTIONAL outputs
 *   dout        NULL when no derivatives are wanted. Otherwise dout[k*n_in + i]
 *               receives d out_k / d in_i for every differentiable input i and
 *               every non-NULL output k; the other slots are NULL.
 *   t, dt       the time level being solved and its step: a step from t0 to
 *               t0 + h evaluates at t = t0 + h, dt = h (its sub-steps and
 *               iterations too); the steady solve, the initial state and
 *               `sluice closure eval` at t = 0, dt = 0
 * All arrays are host-owned, 64-byte aligned, and do not alias. */
typedef struct sl_eval_args {
  int32_t Q;
  double t, dt;
  const double *const *in;
  double *const *out;
  double *const *dout;
  sl_error *err;
} sl_eval_args;

typedef struct sl_closure_desc sl_closure_desc;

struct sl_closure_desc {
  uint32_t struct_size; /* sizeof(sl_closure_desc) as the closure was built */
  uint16_t abi_major, abi_minor;
  uint16_t real_size, index_size; /* sizeof(double), sizeof(int32_t) */

  sl_kind kind;
  const char *name;      /* lower_snake_case, unique within the kind */
  const char *version;   /* of this closure, "1.0.0" */
  const char *summary;   /* one line */
  const char *formula;   /* plain text, may span lines */
  const char *reference; /* author, year, equation */
  const char *validity;  /* plain-text statement of where the law holds */

  int32_t n_params;
  const sl_param_desc *params;
  size_t params_size; /* sizeof the parameter struct */

  int32_t n_in;
  const sl_field_desc *in;
  int32_t n_out;
  const sl_field_desc *out;

  int32_t n_checks;
  const sl_check_point *checks;

  /* create() may be NULL: the state is then the validated parameter struct
   * itself, owned by the host and alive as long as the closure. */
  int (*create)(const sl_host_api *api, const void *params, void **state, sl_error *err);
  int (*evaluate)(const void *state, const sl_eval_args *args);
  void (*destroy)(const sl_host_api *api, void *state); /* may be NULL when create is */

  /* ABI 1.x appends fields below this line only. */
};

typedef const sl_closure_desc *const *(*sl_closure_entry_fn)(int32_t *count);

/* The one symbol a closure library defines and exports. */
SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count);

/* ---- helpers for closure authors (header-only, no link to the core) ---- */

/* Fills the version fields of a descriptor: SL_CLOSURE_DESC_HEADER, */
#define SL_CLOSURE_DESC_HEADER                                                         \
  .struct_size = (uint32_t)sizeof(sl_closure_desc), .abi_major = SL_CLOSURE_ABI_MAJOR, \
  .abi_minor = SL_CLOSURE_ABI_MINOR, .real_size = (uint16_t)sizeof(double), .index_size = (uint16_t)sizeof(int32_t)

#define SL_COUNT_OF(a) ((int32_t)(sizeof(a) / sizeof((a)[0])))

/* A real parameter of struct S, member m. */
#define SL_PARAM_REAL_OF(S, m, dflt, lo, hi, unit, text)                                                  \
  {                                                                                                       \
    .name = #m, .type = SL_PARAM_REAL, .offset = offsetof(S, m), .def = (dflt), .min = (lo), .max = (hi), \
    .units = (unit), .choices = NULL, .help = (text)                                                      \
  }
#define SL_PARAM_ENUM_OF(S, m, dflt, list, text)                                                                 \
  {                                                                                                              \
    .name = #m, .type = SL_PARAM_ENUM, .offset = offsetof(S, m), .def = (dflt), .min = 0, .max = 0, .units = "", \
    .choices = (list), .help = (text)                                                                            \
  }
#define SL_PARAM_BOOL_OF(S, m, dflt, text)                                                                       \
  {                                                                                                              \
    .name = #m, .type = SL_PARAM_BOOL, .offset = offsetof(S, m), .def = (dflt), .min = 0, .max = 1, .units = "", \
    .choices = NULL, .help = (text)                                                                              \
  }
#define SL_PARAM_INT_OF(S, m, dflt, lo, hi, text)                                                                      \
  {                                                                                                                    \
    .name = #m, .type = SL_PARAM_INT, .offset = offsetof(S, m), .def = (dflt), .min = (lo), .max = (hi), .units = "1", \
    .choices = NULL, .help = (text)                                                                                    \
  }

/* Records the first bad point and a message; returns `code` for `return`. */
static inline int sl_fail(sl_error *err, int code, int32_t point, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static inline int sl_fail(sl_error *err, int code, int32_t point, const char *fmt, ...) {
  if (err) {
    va_list ap;
    va_start(ap, fmt);
    err->point = point;
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
  }
  return code;
}

/* Slot of d out_k / d in_i, or NULL when not requested. */
static inline double *sl_dout(const sl_eval_args *a, int32_t n_in, int32_t k, int32_t i) {
  return a->dout ? a->dout[k * n_in + i] : NULL;
}

#ifdef __cplusplus
}
#endif
#endif /* SLUICE_CLOSURE_H */
