/* The checkpoint and the provenance of a two_fluid run, the same for the 1-D
 * column and the 2-D model (two_fluid_impl.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/scene/output.h"
#include "core/models/two_fluid/two_fluid_impl.h"

static const char *const STATE_NAMES[5] = {"phi", "velocity_solid", "velocity_fluid", "pressure", "solids_book"};

int tf_checkpoint_write(sl_output *out, const tf_state *s, double t, double dt, long step, sl_diag *d) {
  double book[2] = {s->inventory0, s->outflow};
  sl_checkpoint_array a[5] = {{"phi", s->n_cells, s->phi}, {"velocity_solid", s->n_faces, s->us},
                              {"velocity_fluid", s->n_faces, s->uf}, {"pressure", s->n_cells, s->p},
                              {"solids_book", 2, book}}; /* the names of STATE_NAMES */
  sl_checkpoint_array a6[6] = {a[0], a[1], a[2], a[3], a[4], {"theta", s->n_cells, s->theta}};
  sl_checkpoint ck = {.time = t, .dt = dt, .step = step, .n_arrays = s->theta ? 6 : 5, .arrays = s->theta ? a6 : a};
  ck.n_ints = 1;
  snprintf(ck.int_names[0], SL_CHECKPOINT_NAME_MAX, "rejected");
  ck.ints[0] = s->rejected;
  return sl_output_write_checkpoint(out, &ck, d);
}

int tf_checkpoint_restore(const char *path, const char *model, tf_state *s, double *t, double *dt, long *step,
                          sl_diag *d) {
  sl_checkpoint ck;
  int rc = sl_checkpoint_read(path, &ck, d);
  if (rc) return rc;
  double *dst[4] = {s->phi, s->us, s->uf, s->p};
  int64_t len[5] = {s->n_cells, s->n_faces, s->n_faces, s->n_cells, 2};
  for (int k = 0; k < 5 && !rc; ++k) {
    const sl_checkpoint_array *a = sl_checkpoint_find(&ck, STATE_NAMES[k]);
    if (!a || a->n != len[k])
      rc = sl_diag_set(d, SL_EBADINPUT, "restart: %s holds no %s '%s' of %lld values", path, model, STATE_NAMES[k],
                       (long long)len[k]);
    else if (k < 4) memcpy(dst[k], a->data, (size_t)a->n * sizeof(double));
    else s->inventory0 = a->data[0], s->outflow = a->data[1];
  }
  if (!rc && s->theta) {
    const sl_checkpoint_array *a = sl_checkpoint_find(&ck, "theta");
    if (!a || a->n != s->n_cells)
      rc = sl_diag_set(d, SL_EBADINPUT, "restart: %s holds no %s 'theta' of %lld values", path, model,
                       (long long)s->n_cells);
    else memcpy(s->theta, a->data, (size_t)a->n * sizeof(double));
  }
  *t = ck.time, *dt = ck.dt, *step = (long)ck.step;
  if (!rc && ck.n_ints > 0) s->rejected = (long)ck.ints[0];
  sl_checkpoint_free(&ck);
  return rc;
}

int tf_write_provenance(sl_output *out, const sl_ini *ini, const sl_ns_run_opts *o, const tf_column *c,
                        const sl_closure *const *extra, const char *const *extra_roles, int n_extra,
                        char params[][1024], sl_diag *d) {
  char *ini_text = sl_ini_to_string(ini);
  sl_provenance_closure pc[2 + TF_MAX_EXTRA_CLOSURES];
  sl_provenance pv = {.sluice_version = o->sluice_version ? o->sluice_version : "unknown", .ini_text = ini_text,
                      .closures = pc};
  const sl_closure *cl[2 + TF_MAX_EXTRA_CLOSURES] = {c->drag.c, c->ps.c};
  const char *roles[2 + TF_MAX_EXTRA_CLOSURES] = {"closure.drag", "closure.solids_pressure"};
  for (int k = 0; k < n_extra && k < TF_MAX_EXTRA_CLOSURES; ++k) cl[2 + k] = extra[k], roles[2 + k] = extra_roles[k];
  for (int k = 0; k < 2 + n_extra && k < 2 + TF_MAX_EXTRA_CLOSURES; ++k)
    if (cl[k]) pc[pv.n_closures++] = sl_scene_closure_provenance(cl[k], roles[k], params[k], sizeof params[k]);
  int rc = sl_output_write_provenance(out, &pv, d);
  free(ini_text);
  return rc;
}
