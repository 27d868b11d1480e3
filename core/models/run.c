/* A run of a scene (run.h). */
#include "core/models/run.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "core/time/loop.h"

static double cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int sl_model_scene(sl_ini *ini, const sl_registry *reg, int create_closures, int build_mesh,
                   const sl_model_entry **entry, sl_scene **sc, sl_diag *d) {
  *sc = NULL;
  int rc = sl_model_select(ini, entry, d);
  if (rc) return rc;
  int n;
  const sl_schema *const *all = sl_model_schemas(&n);
  sl_scene_opts so = {.registry = reg, .create_closures = create_closures, .build_mesh = build_mesh, .schemas = all,
                      .n_schemas = n};
  return sl_scene_build(ini, (*entry)->schema, &so, sc, d);
}

void sl_run_output_opts(const sl_run_opts *o, char *dir, size_t cap, sl_output_opts *oo) {
  /* the scene's folder: where a path from the scene file may write (besides the working folder) */
  const char *slash = o->scene_path ? strrchr(o->scene_path, '/') : NULL;
  if (slash)
    snprintf(dir, cap, "%.*s", slash == o->scene_path ? 1 : (int)(slash - o->scene_path), o->scene_path);
  else
    snprintf(dir, cap, ".");
  *oo = (sl_output_opts){.from_scene = o->output == NULL, .scene_dir = dir, .overwrite = o->overwrite,
                         .protect = o->scene_path};
}

int sl_model_run(sl_ini *ini, const sl_registry *reg, const sl_run_opts *o, sl_run_result *res, sl_diag *d) {
  memset(res, 0, sizeof *res);
  double c_setup = cpu();
  const sl_model_entry *entry = NULL;
  sl_scene *sc = NULL;
  void *self = NULL;
  sl_model_info info = {0};
  sl_time_loop loop;
  int have_loop = 0, have_ck = 0;
  sl_checkpoint ck = {0};
  sl_output *out = NULL;
  sl_scene_provenance pv = {0};
  int rc = sl_model_scene(ini, reg, 1, 1, &entry, &sc, d);
  const sl_model_ops *ops = entry ? entry->ops : NULL;
  if (!rc) rc = ops->setup(&self, sc, &info, d);
  if (!rc && !(rc = sl_time_loop_init(&loop, &info, &sc->time, d))) have_loop = 1;
  /* a restart is checked against the scene before anything is written */
  if (!rc && o->restart) {
    if (!(rc = sl_checkpoint_read(o->restart, &ck, d))) have_ck = 1;
    if (!rc && ops->restore) rc = ops->restore(self, &ck, d);
    if (!rc) rc = sl_time_loop_restore(&loop, &ck, d);
  }
  if (!rc) {
    sl_scene_output_path(sc, o->output, o->scene_path, res->output_path, sizeof res->output_path);
    sl_output_opts oo;
    char dir[4096];
    sl_run_output_opts(o, dir, sizeof dir, &oo);
    oo.protect_more = (const char *const *)ini->files, oo.n_protect_more = ini->n_files;
    rc = sl_output_open_opts(&out, res->output_path, &oo, d);
  }
  if (!rc) rc = ops->write_mesh(self, out, d);
  if (!rc) rc = sl_scene_provenance_make(sc, o->sluice_version, &pv, d);
  if (!rc) rc = sl_output_write_provenance(out, &pv.pv, d);
  res->cpu_setup = cpu() - c_setup;
  if (!rc) rc = sl_time_loop_run(&loop, ops, self, out, o, res, d);
  if (self && ops->stats) ops->stats(self, res, &res->model);
  if (info.integrator == SL_INTEGRATE_BDF && res->model.has_linear) {
    res->factorisation = res->model.linear.t_symbolic + res->model.linear.t_numeric;
    res->solve = res->model.linear.t_solve;
  }
  if (res->model.stop_reason[0] && sc && sc->time.scheme == SL_SCHEME_STEADY && info.has_steady)
    memcpy(res->stop_reason, res->model.stop_reason, sizeof res->stop_reason);
  if (out) {
    sl_output_stats(out, &res->output_times, &res->output_datasets, &res->output_bytes);
    if (rc) { /* before the first complete output time, what was there stays */
      if (!sl_output_abort(out)) res->output_path[0] = '\0';
    } else
      rc = sl_output_close(out, d);
  } else {
    res->output_path[0] = '\0';
  }
  sl_scene_provenance_free(&pv);
  if (have_ck) sl_checkpoint_free(&ck);
  if (have_loop) sl_time_loop_free(&loop);
  if (self) ops->destroy(self);
  sl_scene_free(sc);
  return rc;
}
