/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Scalar diffusion: A += int k grad v . T grad u (T the identity unless given), b += int f v. */
#include <stdlib.h>
#include <string.h>

#include "core/assembly/batch.h"
#include "core/assembly/operators.h"
#include "core/fe/geometry.h"

typedef struct diffusion_work {
  sl_fe_values *fv;
  sl_asm_batch batch;
  double *k, *f; /* per batch point */
  double Ke[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS], be[SL_ELEMENT_MAX_BASIS];
} diffusion_work;

static void work_free(diffusion_work *w) {
  sl_fe_values_destroy(w->fv);
  sl_asm_batch_free(&w->batch);
  free(w->k), free(w->f);
  free(w);
}

static int work_create(diffusion_work **out, const sl_dofmap *dm, const sl_diffusion_opts *o, sl_diag *d) {
  diffusion_work *w = calloc(1, sizeof *w);
  if (!w) return sl_diag_set(d, SL_ENOMEM, "diffusion: out of memory");
  int degree = o->quad_degree > 0 ? o->quad_degree : 2 * dm->element->order + (o->axisymmetric ? 1 : 0);
  int rc = sl_fe_values_create(&w->fv, dm->mesh, 1, &dm->element, degree, o->axisymmetric, d);
  if (!rc) rc = sl_asm_batch_init(&w->batch, w->fv->quad.n, 0, d);
  if (!rc) {
    size_t cap = (size_t)SL_ASSEMBLY_BATCH_CELLS * w->fv->quad.n;
    w->k = malloc(cap * sizeof *w->k), w->f = malloc(cap * sizeof *w->f);
    if (!w->k || !w->f) rc = sl_diag_set(d, SL_ENOMEM, "diffusion: out of memory");
  }
  if (rc) {
    work_free(w);
    return rc;
  }
  *out = w;
  return 0;
}

/* Quadrature points of cells [first, first + n) into the batch. */
static void gather_points(diffusion_work *w, int first, int n) {
  sl_asm_batch *b = &w->batch;
  b->first = first, b->n_cells = n;
  for (int i = 0; i < n; ++i) {
    sl_fe_values_map_points(w->fv, first + i, b->x + (size_t)i * b->nq);
    for (int q = 0; q < b->nq; ++q) b->cell[(size_t)i * b->nq + q] = first + i;
  }
}

/* Element matrix and vector of the current cell; k and f at its points. */
static void element(diffusion_work *w, int nb, const double *k, const double *f, int with_k, int with_f,
                    const double *T) {
  const sl_fe_values *fv = w->fv;
  memset(w->Ke, 0, sizeof w->Ke);
  memset(w->be, 0, sizeof w->be);
  for (int q = 0; q < fv->quad.n; ++q) {
    const double(*g)[2] = fv->grad[0][q];
    double wk = fv->JxW[q] * (with_k ? k[q] : 0.0), wf = fv->JxW[q] * (with_f ? f[q] : 0.0);
    for (int i = 0; i < nb; ++i) {
      w->be[i] += wf * fv->phi[0][q][i];
      if (!T)
        for (int j = 0; j < nb; ++j) w->Ke[i * nb + j] += wk * (g[i][0] * g[j][0] + g[i][1] * g[j][1]);
      else
        for (int j = 0; j < nb; ++j)
          w->Ke[i * nb + j] +=
              wk * (g[i][0] * (T[0] * g[j][0] + T[1] * g[j][1]) + g[i][1] * (T[2] * g[j][0] + T[3] * g[j][1]));
    }
  }
}

static int check_system(const sl_system *s, const sl_dofmap *dm, sl_diag *d) {
  if (s->n_dofs != dm->n_dofs || s->n_elem != dm->mesh->n_cells || s->dofs_per_elem != dm->dofs_per_cell)
    return sl_diag_set(d, SL_EBADINPUT, "diffusion: the system (%d dofs, %d x %d) was not built from this dof map",
                       (int)s->n_dofs, (int)s->n_elem, s->dofs_per_elem);
  return 0;
}

int sl_assemble_diffusion(sl_system *s, const sl_dofmap *dm, const sl_diffusion_opts *o, sl_diag *d) {
  int rc = check_system(s, dm, d);
  int with_k = !sl_asm_coef_is_zero(&o->diffusivity), with_f = !sl_asm_coef_is_zero(&o->source);
  if (rc || (!with_k && !with_f)) return rc;
  diffusion_work *w = NULL;
  if ((rc = work_create(&w, dm, o, d))) return rc;
  int nc = dm->mesh->n_cells, nb = dm->dofs_per_cell, nq = w->fv->quad.n;
  for (int first = 0; first < nc && !rc; first += SL_ASSEMBLY_BATCH_CELLS) {
    int n = nc - first < SL_ASSEMBLY_BATCH_CELLS ? nc - first : SL_ASSEMBLY_BATCH_CELLS;
    gather_points(w, first, n);
    sl_qp_batch view = sl_asm_batch_view(&w->batch);
    if (with_k) rc = sl_asm_coef_eval(&o->diffusivity, "diffusivity", &view, 1, w->k, d);
    if (!rc && with_f) rc = sl_asm_coef_eval(&o->source, "source", &view, 1, w->f, d);
    for (int i = 0; i < n && !rc; ++i) {
      if ((rc = sl_fe_values_reinit(w->fv, first + i, d))) break;
      element(w, nb, w->k + (size_t)i * nq, w->f + (size_t)i * nq, with_k, with_f, o->tensor);
      rc = sl_system_add_element(s, first + i, with_k ? w->Ke : NULL, with_f ? w->be : NULL, d);
    }
  }
  work_free(w);
  return rc;
}
