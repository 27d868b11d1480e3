/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Stokes on Taylor–Hood pairs: the symmetric-gradient viscous term with a
 * batched viscosity, the pressure–divergence coupling and the body force. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/batch.h"
#include "core/assembly/operators.h"
#include "core/fe/geometry.h"

#define MAX_COMP 2
#define MAX_ELEM_DOFS (MAX_COMP * SL_ELEMENT_MAX_BASIS + 4)

typedef struct stokes_work {
  sl_fe_values *fv; /* space 0: velocity (order 2), space 1: pressure (order 1) */
  sl_asm_batch batch;
  double *mu, *force; /* per batch point (force: n_comp per point) */
  double Ke[MAX_ELEM_DOFS * MAX_ELEM_DOFS], be[MAX_ELEM_DOFS];
} stokes_work;

static void work_free(stokes_work *w) {
  sl_fe_values_destroy(w->fv);
  sl_asm_batch_free(&w->batch);
  free(w->mu), free(w->force);
  free(w);
}

static int work_create(stokes_work **out, const sl_th_space *th, const sl_stokes_opts *o, int with_shear, sl_diag *d) {
  stokes_work *w = calloc(1, sizeof *w);
  if (!w) return sl_diag_set(d, SL_ENOMEM, "stokes: out of memory");
  const sl_element *spaces[2] = {th->vel->element, th->pres->element};
  int rc = sl_fe_values_create(&w->fv, th->mesh, 2, spaces, o->quad_degree > 0 ? o->quad_degree : 4, 0, d);
  if (!rc) rc = sl_asm_batch_init(&w->batch, w->fv->quad.n, with_shear, d);
  if (!rc) {
    size_t cap = (size_t)SL_ASSEMBLY_BATCH_CELLS * w->fv->quad.n;
    w->mu = malloc(cap * sizeof *w->mu), w->force = malloc(cap * th->n_comp * sizeof *w->force);
    if (!w->mu || !w->force) rc = sl_diag_set(d, SL_ENOMEM, "stokes: out of memory");
  }
  if (rc) {
    work_free(w);
    return rc;
  }
  *out = w;
  return 0;
}

/* sqrt(2 D:D) at the quadrature points of the current cell. */
static void shear_rates(const sl_fe_values *fv, const sl_th_space *th, const double *u, int c, double *out) {
  int nb = th->vel->dofs_per_cell, dim = th->mesh->dim;
  const int32_t *vd = th->vel->cell_dofs + (size_t)c * nb;
  for (int q = 0; q < fv->quad.n; ++q) {
    double G[2][2] = {{0, 0}, {0, 0}}; /* G[a][j] = d u_a / d x_j */
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < nb; ++b) {
        double ub = u[sl_th_vel_dof(th, a, vd[b])];
        G[a][0] += ub * fv->grad[0][q][b][0], G[a][1] += ub * fv->grad[0][q][b][1];
      }
    double dd = 0.0;
    for (int a = 0; a < dim; ++a)
      for (int j = 0; j < dim; ++j) {
        double D = 0.5 * (G[a][j] + G[j][a]);
        dd += D * D;
      }
    out[q] = sqrt(2.0 * dd);
  }
}

static int gather_points(stokes_work *w, const sl_th_space *th, const double *u, int first, int n, sl_diag *d) {
  sl_asm_batch *b = &w->batch;
  b->first = first, b->n_cells = n;
  for (int i = 0; i < n; ++i) {
    size_t at = (size_t)i * b->nq;
    for (int q = 0; q < b->nq; ++q) b->cell[at + q] = first + i;
    if (!b->shear_rate) {
      sl_fe_values_map_points(w->fv, first + i, b->x + at);
      continue;
    }
    int rc = sl_fe_values_reinit(w->fv, first + i, d);
    if (rc) return rc;
    memcpy(b->x + at, w->fv->x, (size_t)b->nq * sizeof *b->x);
    shear_rates(w->fv, th, u, first + i, b->shear_rate + at);
  }
  return 0;
}

/* Element matrix [A B^T; B 0] and load of the current cell, in the combined
 * local order [u_0 basis, u_1 basis, p basis]. */
static void element(stokes_work *w, int nc, int nb, int np, const double *mu, const double *f, int with_f) {
  const sl_fe_values *fv = w->fv;
  int n = nc * nb + np;
  memset(w->Ke, 0, (size_t)n * n * sizeof *w->Ke);
  memset(w->be, 0, (size_t)n * sizeof *w->be);
  for (int q = 0; q < fv->quad.n; ++q) {
    const double(*g)[2] = fv->grad[0][q];
    const double *psi = fv->phi[1][q], *phi = fv->phi[0][q];
    double wm = fv->JxW[q] * mu[q];
    /* 2 D(phi_j e_b) : D(phi_i e_a) = delta_ab grad phi_i . grad phi_j + d_b phi_i d_a phi_j */
    for (int i = 0; i < nb; ++i)
      for (int j = 0; j < nb; ++j) {
        double gg = g[i][0] * g[j][0] + g[i][1] * g[j][1];
        for (int a = 0; a < nc; ++a)
          for (int b = 0; b < nc; ++b)
            w->Ke[(a * nb + i) * n + b * nb + j] += wm * ((a == b ? gg : 0.0) + g[i][b] * g[j][a]);
      }
    /* B = -int psi_k div u */
    for (int k = 0; k < np; ++k)
      for (int j = 0; j < nb; ++j)
        for (int b = 0; b < nc; ++b) {
          double v = -fv->JxW[q] * psi[k] * g[j][b];
          w->Ke[(nc * nb + k) * n + b * nb + j] += v;
          w->Ke[(b * nb + j) * n + nc * nb + k] += v;
        }
    if (with_f)
      for (int a = 0; a < nc; ++a)
        for (int i = 0; i < nb; ++i) w->be[a * nb + i] += fv->JxW[q] * f[q * nc + a] * phi[i];
  }
}

static int check_input(const sl_system *s, const sl_th_space *th, sl_diag *d) {
  if (th->n_comp != th->mesh->dim || th->n_comp > MAX_COMP)
    return sl_diag_set(d, SL_EBADINPUT, "stokes: %d velocity components on a %d-D mesh (planar Stokes needs %d)",
                       th->n_comp, th->mesh->dim, th->mesh->dim);
  if (s->n_dofs != th->n_dofs || s->n_elem != th->mesh->n_cells || s->dofs_per_elem != th->dofs_per_cell)
    return sl_diag_set(d, SL_EBADINPUT, "stokes: the system (%d dofs, %d x %d) was not built from this space",
                       (int)s->n_dofs, (int)s->n_elem, s->dofs_per_elem);
  return 0;
}

int sl_assemble_stokes(sl_system *s, const sl_th_space *th, const sl_stokes_opts *o, sl_diag *d) {
  int rc = check_input(s, th, d);
  if (rc) return rc;
  stokes_work *w = NULL;
  int with_shear = o->velocity && o->viscosity.fn, with_f = o->body_force != NULL;
  if ((rc = work_create(&w, th, o, with_shear, d))) return rc;
  sl_coef force = {o->body_force, o->body_force_user, 0.0};
  int ncell = th->mesh->n_cells, nc = th->n_comp, nb = th->vel->dofs_per_cell, np = th->pres->dofs_per_cell;
  int nq = w->fv->quad.n;
  for (int first = 0; first < ncell && !rc; first += SL_ASSEMBLY_BATCH_CELLS) {
    int n = ncell - first < SL_ASSEMBLY_BATCH_CELLS ? ncell - first : SL_ASSEMBLY_BATCH_CELLS;
    if ((rc = gather_points(w, th, o->velocity, first, n, d))) break;
    sl_qp_batch view = sl_asm_batch_view(&w->batch);
    rc = sl_asm_coef_eval(&o->viscosity, "viscosity", &view, 1, w->mu, d);
    if (!rc && with_f) rc = sl_asm_coef_eval(&force, "body force", &view, nc, w->force, d);
    for (int i = 0; i < n && !rc; ++i) {
      if ((rc = sl_fe_values_reinit(w->fv, first + i, d))) break;
      element(w, nc, nb, np, w->mu + (size_t)i * nq, w->force + (size_t)i * nq * nc, with_f);
      rc = sl_system_add_element(s, first + i, w->Ke, with_f ? w->be : NULL, d);
    }
  }
  work_free(w);
  return rc;
}

void sl_stokes_fix_pressure_datum(sl_constraints *bc, const sl_th_space *th) {
  sl_constraints_fix(bc, sl_th_pres_dof(th, 0), 0.0);
}

int sl_stokes_zero_mean_pressure(const sl_th_space *th, double *x, sl_diag *d) {
  double integral, area;
  double *p = x + th->p_offset;
  int rc = sl_fe_integrate(th->pres, p, 0, &integral, &area, d);
  if (rc) return rc;
  double mean = integral / area;
  for (int32_t i = 0; i < th->pres->n_dofs; ++i) p[i] -= mean;
  return 0;
}
