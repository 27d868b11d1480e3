/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The embedding API (include/sluice/sluice.h) over the core. */
#include "sluice/sluice.h"

#include <stdlib.h>
#include <string.h>

#include "core/config/ini.h"
#include "core/models/run.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/guard.h"
#include "core/plugin/kinds.h"
#include "core/solve/linsolve.h"
#include "core/time/loop.h"
#include "core/util/version.h"

const char *sluice_version(void) { return sl_version(); }

_Static_assert(SLUICE_REFACTOR_REASONS == SL_REFACTOR_N, "sluice_linear.refactor_reason has a slot per reason");
const char *sluice_refactor_reason_name(int k) { return sl_refactor_reason_name(k); }

struct sluice {
  sl_ini *ini;
  sl_registry *reg;
  char **dirs;
  int n_dirs;
  char *path;
  const sl_model_entry *entry;
  sl_scene *scene; /* of sluice_check or sluice_time_span (keys only) */
  int scene_full;  /* built with its closures and mesh */
  char model[256];
};

static int fail(sluice_error *e, int code, const char *msg) {
  if (e) {
    e->code = code;
    snprintf(e->msg, sizeof e->msg, "%s", msg);
  }
  return code;
}

static int from_diag(sluice_error *e, int code, const sl_diag *d) {
  return code ? fail(e, sl_exit_status(code), d->msg) : 0;
}

static int finish_open(sluice *s, const sluice_open_opts *o, sluice_error *e) {
  sl_diag d;
  int rc = 0;
  for (int i = 0; o && o->sets && o->sets[i] && !rc; ++i) rc = sl_closure_ini_apply_override(s->ini, o->sets[i], &d);
  if (!rc) rc = sl_plugin_dirs_allowed(s->ini, o && o->allow_plugin_path, &d);
  if (!rc) rc = sl_plugin_dirs_from_ini(s->ini, &s->dirs, &s->n_dirs, &d);
  if (!rc) sl_guard_set_call_time_limit(o ? o->closure_time_limit : 0.0);
  if (!rc) rc = sl_registry_create(&s->reg, (const char *const *)s->dirs, s->n_dirs, &d);
  /* only the libraries of the closures the scene names are loaded, unless asked */
  if (!rc) rc = o && o->scan_all ? sl_registry_scan(s->reg, &d) : sl_registry_index(s->reg, &d);
  if (!rc && o && o->timing) sl_registry_set_timing(s->reg, 1);
  if (!rc && o && o->petsc_options) rc = sl_linsolve_petsc_options(o->petsc_options, &d);
  if (!rc) rc = sl_model_select(s->ini, &s->entry, &d);
  if (!rc) {
    const sl_schema *sc = s->entry->schema;
    snprintf(s->model, sizeof s->model, "%s%s%s%s", sc->model, sc->variant ? " (" : "", sc->variant ? sc->variant : "",
             sc->variant ? ")" : "");
  }
  return from_diag(e, rc, &d);
}

static sluice *create(const char *path, sluice_error *e) {
  sluice *s = calloc(1, sizeof *s);
  if (s) s->path = strdup(path ? path : "scene");
  if (!s || !s->path) {
    free(s);
    fail(e, SLUICE_FAILED, "sluice: out of memory");
    return NULL;
  }
  return s;
}

int sluice_ranks(int *rank, int *size, sluice_error *e) {
  sl_diag d;
  int rc = sl_linsolve_ranks(rank, size, &d);
  return rc ? from_diag(e, rc, &d) : 0;
}

int sluice_open(const char *path, const sluice_open_opts *o, sluice **out, sluice_error *e) {
  *out = NULL;
  sluice *s = create(path, e);
  if (!s) return SLUICE_FAILED;
  sl_diag d;
  int rc = sl_ini_parse_file(path, &s->ini, &d);
  if (rc) rc = from_diag(e, rc, &d);
  else rc = finish_open(s, o, e);
  if (rc) sluice_close(s);
  else *out = s;
  return rc;
}

int sluice_open_text(const char *text, size_t len, const char *name, const sluice_open_opts *o, sluice **out,
                     sluice_error *e) {
  *out = NULL;
  sluice *s = create(name, e);
  if (!s) return SLUICE_FAILED;
  sl_diag d;
  int rc = sl_ini_parse_string(text, len, name, &s->ini, &d);
  if (rc) rc = from_diag(e, rc, &d);
  else rc = finish_open(s, o, e);
  if (rc) sluice_close(s);
  else *out = s;
  return rc;
}

void sluice_close(sluice *s) {
  if (!s) return;
  sl_scene_free(s->scene);
  sl_registry_destroy(s->reg);
  sl_plugin_dirs_free(s->dirs, s->n_dirs);
  sl_ini_free(s->ini);
  free(s->path);
  free(s);
}

const char *sluice_model(const sluice *s) { return s->model; }

int sluice_write_config(const sluice *s, FILE *f, sluice_error *e) {
  return sl_ini_write(s->ini, f) ? fail(e, SLUICE_FAILED, "cannot write the configuration") : 0;
}

/* The scene's keys (and closures found and checked), for a time span or --print-config. */
static int keys_scene(sluice *s, sluice_error *e) {
  if (s->scene) return 0;
  sl_diag d;
  const sl_model_entry *entry;
  return from_diag(e, sl_model_scene(s->ini, s->reg, 0, 0, &entry, &s->scene, &d), &d);
}

int sluice_time_span(sluice *s, double *t0, double *t1, sluice_error *e) {
  int rc = keys_scene(s, e);
  if (!rc) sl_time_span(&s->scene->time, t0, t1);
  return rc;
}

int sluice_check(sluice *s, FILE *report, sluice_error *e) { return sluice_check_restart(s, NULL, report, e); }

int sluice_check_restart(sluice *s, const char *restart, FILE *report, sluice_error *e) {
  sl_diag d;
  const sl_model_entry *entry;
  sl_scene_free(s->scene), s->scene = NULL;
  /* every check a run makes before it writes anything: the model's own set-up and a restart too */
  int rc = sl_model_check(s->ini, s->reg, restart, &entry, &s->scene, &d);
  if (rc) return from_diag(e, rc, &d);
  s->scene_full = 1;
  /* where [output] file may write (the folder rule; whether an existing
   * file may be replaced is decided by the run, which knows -o and --overwrite) */
  char out[4096], dir[4096];
  sl_scene_output_path(s->scene, NULL, s->path, out, sizeof out);
  sl_run_opts ro = {.scene_path = s->path, .overwrite = 1};
  sl_output_opts oo;
  sl_run_output_opts(&ro, dir, sizeof dir, &oo);
  oo.protect_more = (const char *const *)s->ini->files, oo.n_protect_more = s->ini->n_files;
  if ((rc = sl_output_check_path(out, &oo, &d))) {
    const sl_src *at = sl_scene_src(s->scene, &s->scene->output.file); /* the line that named the file */
    if (rc == SL_EBADINPUT && at) sl_diag_prefix(&d, rc, "%s:%d", at->file, at->line);
    return from_diag(e, rc, &d);
  }
  if (!report) return 0;
  const sl_schema *schema = entry->schema;
  int n_closures = 0;
  for (int r = 0; r < schema->n_roles; ++r) n_closures += s->scene->closures[r] != NULL;
  fprintf(report, "%s: scene valid; %d closure%s resolved\n", s->path, n_closures, n_closures == 1 ? "" : "s");
  for (int r = 0; r < schema->n_roles; ++r) {
    const sl_closure *cl = s->scene->closures[r];
    if (!cl) continue;
    const sl_closure_desc *c = cl->desc;
    fprintf(report, "  %-21s %-24s %s (%s)\n", sl_kind_name(c->kind), c->name, c->version, cl->library->path);
  }
  /* the mesh's report says where the cells are finest */
  if (s->scene->mesh) sl_mesh_print_report(s->scene->mesh, report);
  return 0;
}

static void summarise(const sl_run_result *res, sluice_summary *sum) {
  const sl_model_stats *m = &res->model;
  sum->steps = res->steps, sum->rejected_steps = res->rejected_steps;
  for (int k = 0; k < 4; ++k) sum->rejected_by[k] = res->rejected_by[k];
  sum->nonlinear_iterations = res->nonlinear_iterations;
  sum->t_start = res->t_start, sum->t_end = res->t_end, sum->t_reached = res->t_reached;
  sum->saved_time = res->saved_time, sum->saved_time_valid = res->saved_time_valid;
  sum->step_limit = res->step_limit;
  memcpy(sum->output_path, res->output_path, sizeof sum->output_path);
  memcpy(sum->stop_reason, res->stop_reason, sizeof sum->stop_reason);
  memcpy(sum->coupling_summary, m->coupling_summary, sizeof sum->coupling_summary);
  memcpy(sum->linear_summary, m->linear_summary, sizeof sum->linear_summary);
  sum->matrix_assemblies = m->matrix_assemblies, sum->residual_assemblies = m->residual_assemblies;
  sum->used_picard = m->used_picard, sum->converged = m->converged;
  sum->correction = m->correction, sum->residual0 = m->residual0, sum->residual = m->residual;
  sum->roundoff_accepted = m->roundoff_accepted;
  sum->solves_skipped = m->solves_skipped;
  const sl_linsolve_stats *ls = &m->linear;
  sum->linear = (sluice_linear){.n_symbolic = ls->n_symbolic,
                                .n_numeric = ls->n_numeric,
                                .n_refactor = ls->n_refactor,
                                .n_refactor_redo = ls->n_refactor_redo,
                                .n_numeric_skipped = ls->n_numeric_skipped,
                                .n_solves = ls->n_solves,
                                .t_symbolic = ls->t_symbolic,
                                .t_numeric = ls->t_numeric,
                                .t_solve = ls->t_solve,
                                .n_reused = ls->n_reused,
                                .n_krylov_failed = ls->n_krylov_failed,
                                .n_krylov_iterations = ls->n_krylov_iterations,
                                .krylov_max = ls->krylov_max,
                                .t_krylov = ls->t_krylov};
  for (int k = 0; k < SLUICE_REFACTOR_REASONS; ++k) sum->linear.refactor_reason[k] = ls->refactor_reason[k];
  sum->assembly = m->assembly, sum->factorisation = res->factorisation, sum->solve = res->solve;
  sum->output = res->output;
  sum->cpu_setup = res->cpu_setup, sum->cpu_flow = m->cpu_flow, sum->cpu_coupled = m->cpu_coupled;
  sum->cpu_output = res->cpu_output;
  sum->output_times = res->output_times, sum->output_datasets = res->output_datasets;
  sum->output_bytes = res->output_bytes;
  sum->output_bytes_rank = res->output_bytes_rank, sum->output_bytes_all = res->output_bytes_all;
  sum->output_collective = res->output_collective;
}

/* The run's progress call, with the live summary brought up to date first. */
typedef struct progress_relay {
  const sluice_run_opts *o;
  const sl_run_result *res;
} progress_relay;

static void relay(void *user, double t, double dt, long step, int its) {
  const progress_relay *r = user;
  if (r->o->live) summarise(r->res, r->o->live);
  if (r->o->progress) r->o->progress(r->o->progress_user, t, dt, step, its);
}

static void relay_nonlinear(void *user, const sl_nl_report *r) {
  const sluice_run_opts *o = user;
  sluice_nonlinear n = {.t = r->t,
                        .stage = r->stage,
                        .n_stages = r->n_stages,
                        .iteration = r->iteration,
                        .picard = r->picard,
                        .correction = r->correction,
                        .residual = r->residual,
                        .terms = r->terms};
  o->nonlinear(o->nonlinear_user, &n);
}

int sluice_run(sluice *s, const sluice_run_opts *o, sluice_summary *sum, sluice_error *e) {
  memset(sum, 0, sizeof *sum);
  sl_scene_free(s->scene), s->scene = NULL; /* the run builds its own */
  sl_run_result res;
  progress_relay rl = {o, &res};
  sl_run_opts ro = {.scene_path = o && o->scene_path ? o->scene_path : s->path,
                    .output = o ? o->output : NULL,
                    .restart = o ? o->restart : NULL,
                    .sluice_version = o && o->version ? o->version : sl_version(),
                    .monitor = o && (o->progress || o->live) ? relay : NULL,
                    .monitor_user = &rl,
                    .interrupt = o ? o->interrupt : NULL,
                    .nonlinear = o && o->nonlinear ? relay_nonlinear : NULL,
                    .nonlinear_user = (void *)o,
                    .overwrite = o ? o->overwrite : 0};
  sl_diag d;
  int rc = sl_model_run(s->ini, s->reg, &ro, &res, &d);
  summarise(&res, sum);
  return from_diag(e, rc, &d);
}

static double percent(double part, double whole) { return whole > 0 ? 100.0 * part / whole : 0.0; }

void sluice_print_closure_profile(const sluice *s, FILE *f, const char *p, double cpu_total) {
  const sl_registry *reg = s->reg;
  double closure_seconds = 0.0;
  int n_closures = 0;
  for (int i = 0; i < reg->n_libraries; ++i) {
    const sl_library *lib = reg->libraries[i];
    const char *base = strrchr(lib->path, '/');
    for (int32_t k = 0; k < lib->n_closures; ++k) {
      const sl_closure_usage *u = &lib->usage[k];
      if (u->instances == 0) continue;
      char label[128];
      sl_closure_label(lib->closures[k], label, sizeof label);
      fprintf(f, "%s closure %s (%s): %ld instance%s, %llu batched call%s, %llu points (%.1f per call), %.3g s\n", p,
              label, base ? base + 1 : lib->path, u->instances, u->instances == 1 ? "" : "s", u->calls,
              u->calls == 1 ? "" : "s", u->points, u->calls ? (double)u->points / (double)u->calls : 0.0, u->seconds);
      closure_seconds += u->seconds;
      ++n_closures;
    }
  }
  if (n_closures == 0) fprintf(f, "%s closures: none evaluated\n", p);
  fprintf(f, "%s plugins: %d of %d libraries on the search path loaded (%ld dlopen)", p, reg->n_libraries,
          sl_registry_files_on_path(reg), reg->n_dlopen);
  for (int i = 0; i < reg->n_libraries; ++i) {
    const char *base = strrchr(reg->libraries[i]->path, '/');
    fprintf(f, "%s%s", i ? ", " : ": ", base ? base + 1 : reg->libraries[i]->path);
  }
  fputc('\n', f);
  if (n_closures > 0)
    fprintf(f, "%s closure calls took %.3g s, %.2g %% of the run's CPU time (wall clock inside the calls)\n", p,
            closure_seconds, percent(closure_seconds, cpu_total));
}

void sluice_plugin_counts(const sluice *s, sluice_plugins *p) {
  p->loaded = s->reg->n_libraries, p->on_path = sl_registry_files_on_path(s->reg), p->dlopen = s->reg->n_dlopen;
}

int sluice_plugins_loaded(const sluice *s, const char *prefix) {
  int n = 0;
  for (int i = 0; i < s->reg->n_libraries; ++i) {
    const char *path = s->reg->libraries[i]->path, *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    n += strncmp(base, prefix, strlen(prefix)) == 0;
  }
  return n;
}

int sluice_closure_usage(const sluice *s, const char *kind, const char *name, sluice_closure_use *u) {
  memset(u, 0, sizeof *u);
  char label[128];
  snprintf(label, sizeof label, "%s/%s", kind, name);
  for (int i = 0; i < s->reg->n_libraries; ++i) {
    const sl_library *lib = s->reg->libraries[i];
    for (int32_t k = 0; k < lib->n_closures; ++k) {
      char have[128];
      sl_closure_label(lib->closures[k], have, sizeof have);
      if (strcmp(label, have) != 0 || lib->usage[k].instances == 0) continue;
      const sl_closure_usage *x = &lib->usage[k];
      *u = (sluice_closure_use){x->instances, x->calls, x->points, x->seconds};
      return 0;
    }
  }
  return -1;
}

int sluice_closure_totals(const sluice *s, sluice_closure_use *total) {
  memset(total, 0, sizeof *total);
  int n = 0;
  for (int i = 0; i < s->reg->n_libraries; ++i)
    for (int32_t k = 0; k < s->reg->libraries[i]->n_closures; ++k) {
      const sl_closure_usage *u = &s->reg->libraries[i]->usage[k];
      if (u->instances == 0) continue;
      ++n;
      total->instances += u->instances, total->calls += u->calls, total->points += u->points;
      total->seconds += u->seconds;
    }
  return n;
}
