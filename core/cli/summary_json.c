/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The run's summary as JSON (summary_json.h). */
#include "core/cli/summary_json.h"

#include <math.h>
#include <stdio.h>

/* A JSON string: quotes, backslashes and control characters escaped, other
 * bytes (UTF-8) as they are. */
static void str(FILE *f, const char *s) {
  fputc('"', f);
  for (const unsigned char *c = (const unsigned char *)(s ? s : ""); *c; ++c) {
    if (*c == '"' || *c == '\\') fprintf(f, "\\%c", *c);
    else if (*c == '\n') fputs("\\n", f);
    else if (*c == '\t') fputs("\\t", f);
    else if (*c < 0x20) fprintf(f, "\\u%04x", *c);
    else fputc(*c, f);
  }
  fputc('"', f);
}

/* JSON has no NaN or infinity: null. */
static void num(FILE *f, double v) {
  if (isfinite(v)) fprintf(f, "%.17g", v);
  else fputs("null", f);
}

static void key(FILE *f, const char *k) {
  fputs(",\n  ", f);
  str(f, k);
  fputs(": ", f);
}

int sl_summary_json_write(const char *path, const char *scene, const char *model, int exit_code, const char *message,
                          const sluice_summary *m, double wall_seconds, double cpu_seconds) {
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  const char *status = exit_code == 0 ? "done" : exit_code == 2 ? "bad input" : "failed";
  fputs("{\n  \"status\": ", f);
  str(f, status);
  key(f, "exit_code"), fprintf(f, "%d", exit_code);
  key(f, "message"), str(f, exit_code ? message : "");
  key(f, "scene"), str(f, scene);
  key(f, "model"), str(f, model);
  if (m) {
    key(f, "output"), str(f, m->output_path);
    key(f, "steps"), fprintf(f, "%ld", m->steps);
    key(f, "rejected_steps"), fprintf(f, "%ld", m->rejected_steps);
    key(f, "nonlinear_iterations"), fprintf(f, "%ld", m->nonlinear_iterations);
    key(f, "t_start"), num(f, m->t_start);
    key(f, "t_end"), num(f, m->t_end);
    key(f, "t_reached"), num(f, m->t_reached);
    key(f, "step_limit"), str(f, m->step_limit ? m->step_limit : "");
    key(f, "stop_reason"), str(f, m->stop_reason);
    key(f, "coupling_summary"), str(f, m->coupling_summary);
    key(f, "linear_summary"), str(f, m->linear_summary);
    key(f, "converged"), fputs(m->converged ? "true" : "false", f);
    key(f, "correction"), num(f, m->correction);
    key(f, "residual0"), num(f, m->residual0);
    key(f, "residual"), num(f, m->residual);
    key(f, "matrix_assemblies"), fprintf(f, "%ld", m->matrix_assemblies);
    key(f, "residual_assemblies"), fprintf(f, "%ld", m->residual_assemblies);
    key(f, "output_times"), fprintf(f, "%ld", m->output_times);
    key(f, "output_datasets"), fprintf(f, "%ld", m->output_datasets);
    key(f, "output_bytes"), num(f, m->output_bytes);
    key(f, "wall_seconds"), num(f, wall_seconds);
    key(f, "cpu_seconds"), num(f, cpu_seconds);
    key(f, "wall_seconds_by_phase");
    fputs("{\"assembly\": ", f), num(f, m->assembly);
    fputs(", \"factorisation\": ", f), num(f, m->factorisation);
    fputs(", \"solve\": ", f), num(f, m->solve);
    fputs(", \"output\": ", f), num(f, m->output);
    fputs("}", f);
    key(f, "cpu_seconds_by_phase");
    fputs("{\"setup\": ", f), num(f, m->cpu_setup);
    fputs(", \"flow\": ", f), num(f, m->cpu_flow);
    fputs(", \"coupled\": ", f), num(f, m->cpu_coupled);
    fputs(", \"output\": ", f), num(f, m->cpu_output);
    fputs("}", f);
  }
  fputs("\n}\n", f);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return -1;
  return 0;
}
