/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A run's time settings ([time], and [output] every), as the scene
 * (core/scene) resolves them for the time loops. */
#ifndef SLUICE_TIME_TIME_CONFIG_H
#define SLUICE_TIME_TIME_CONFIG_H

enum { SL_SCHEME_STEADY = 0, SL_SCHEME_BDF1 = 1, SL_SCHEME_BDF2 = 2 };

typedef struct sl_time_config {
  int scheme;       /* SL_SCHEME_* (the fixed-step models: their own implicit step) */
  double end, dt;   /* end time and first (or fixed) step, s */
  double tolerance; /* local error tolerance of adaptive steps */
  int adaptive;
  double dt_min, dt_max; /* resolved by the scene: dt_min defaults to dt 1e-6, dt_max to end/10 (adaptive) or dt */
  long max_steps;        /* steps of this run before it stops with a checkpoint */
  int controller;        /* adaptive BDF: the step controller, sl_bdf_control (core/time/bdf.h) */
  double every;          /* output interval, s (0: the start and the end only) */
} sl_time_config;

#endif
