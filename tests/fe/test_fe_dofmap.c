/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Dof maps: counts, node coordinates, continuity (a quadratic is
 * interpolated exactly and the interpolant agrees across cells), boundary
 * dof lists, the Taylor–Hood numbering, and point location/evaluation. */
#include <math.h>
#include <stdlib.h>

#include "core/fe/dofmap.h"
#include "core/fe/field.h"
#include "core/fe/geometry.h"
#include "testing.h"

static void quadratic(void *user, const double x[2], double *v, double g[2]) {
  (void)user;
  *v = 1.0 + 2.0 * x[0] - x[1] + 0.5 * x[0] * x[0] + 0.25 * x[0] * x[1] - 0.75 * x[1] * x[1];
  if (g) g[0] = 2.0 + x[0] + 0.25 * x[1], g[1] = -1.0 + 0.25 * x[0] - 1.5 * x[1];
}

static void linear(void *user, const double x[2], double *v, double g[2]) {
  (void)user;
  *v = 1.0 + 2.0 * x[0] - x[1];
  if (g) g[0] = 2.0, g[1] = -1.0;
}

/* Each cell's nodes are the images of the element's reference nodes. */
static void check_nodes(const sl_dofmap *dm) {
  double worst = 0.0;
  int in_range = 1;
  for (int c = 0; c < dm->mesh->n_cells; ++c)
    for (int b = 0; b < dm->dofs_per_cell; ++b) {
      int32_t i = dm->cell_dofs[(size_t)c * dm->dofs_per_cell + b];
      in_range &= i >= 0 && i < dm->n_dofs;
      if (i < 0 || i >= dm->n_dofs) continue;
      double x[2];
      sl_fe_map_point(dm->mesh, c, dm->element->nodes[b], x);
      worst = fmax(worst, fabs(x[0] - dm->xy[2 * i]) + fabs(x[1] - dm->xy[2 * i + 1]));
    }
  CHECK(in_range);
  CHECK_MSG(worst < 1e-14, "%s: node coordinates differ from the cell map by %g", dm->element->name, worst);
  /* Every dof is used by some cell. */
  char *used = calloc((size_t)dm->n_dofs, 1);
  for (size_t k = 0; k < (size_t)dm->mesh->n_cells * dm->dofs_per_cell; ++k) used[dm->cell_dofs[k]] = 1;
  int all = 1;
  for (int32_t i = 0; i < dm->n_dofs; ++i) all &= used[i];
  CHECK(all);
  free(used);
}

/* The interpolant of a polynomial of the space's order is exact everywhere,
 * including its gradient and at points located by sl_fe_locate. */
static void check_interpolation(const sl_dofmap *dm) {
  sl_exact_fn f = dm->element->order == 2 ? quadratic : linear;
  double *u = malloc((size_t)dm->n_dofs * sizeof *u), l2, h1;
  sl_fe_interpolate(dm, f, NULL, u);
  CHECK(sl_fe_error_norms(dm, u, f, NULL, 0, 4, &l2, &h1, NULL) == 0);
  CHECK_MSG(l2 < 1e-13 && h1 < 1e-12, "%s: interpolation error %g %g", dm->element->name, l2, h1);
  int cell = -1;
  double worst = 0.0;
  for (int k = 0; k < 15; ++k) {
    double x[2] = {0.05 + 0.9 * (0.5 + 0.5 * sin(1.7 * k)),
                   dm->mesh->dim == 2 ? 0.05 + 0.9 * (0.5 + 0.5 * cos(2.3 * k)) : 0.0};
    double xi[2], v, g[2], ve, ge[2];
    CHECK(sl_fe_locate(dm->mesh, x, &cell, xi, NULL) == 0);
    sl_fe_eval(dm, u, cell, xi, &v, g);
    f(NULL, x, &ve, ge);
    worst = fmax(worst, fabs(v - ve) + fabs(g[0] - ge[0]) + (dm->mesh->dim == 2 ? fabs(g[1] - ge[1]) : 0.0));
  }
  CHECK_MSG(worst < 1e-12, "%s: point evaluation off by %g", dm->element->name, worst);
  free(u);
}

static void test_rectangle(sl_cell_type t, int order, int32_t expected_dofs, int32_t expected_bottom) {
  sl_grid_opts o = {.cell_type = t, .diagonal = SL_DIAGONAL_UNION_JACK, .grade_y = {SL_GRADE_SYMMETRIC, 2.0}};
  sl_mesh *m;
  sl_dofmap *dm;
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 3, &o, &m, NULL) == 0);
  CHECK(sl_dofmap_create(m, order, &dm, NULL) == 0);
  CHECK_MSG(dm->n_dofs == expected_dofs, "%s: %d dofs, expected %d", dm->element->name, (int)dm->n_dofs,
            (int)expected_dofs);
  check_nodes(dm);
  check_interpolation(dm);
  int32_t *bd, nb;
  CHECK(sl_dofmap_boundary_dofs(dm, "bottom", &bd, &nb, NULL) == 0);
  CHECK(nb == expected_bottom);
  int on_bottom = 1, sorted = 1;
  for (int32_t k = 0; k < nb; ++k) {
    on_bottom &= dm->xy[2 * bd[k] + 1] == 0.0;
    if (k) sorted &= bd[k] > bd[k - 1];
  }
  CHECK(on_bottom && sorted);
  free(bd);
  sl_diag d;
  CHECK(sl_dofmap_boundary_dofs(dm, "botom", &bd, &nb, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "bottom");
  sl_dofmap_destroy(dm);
  sl_mesh_destroy(m);
}

static void test_interval(void) {
  sl_mesh *m;
  sl_dofmap *dm;
  CHECK(sl_mesh_interval(0.0, 1.0, 5, NULL, &m, NULL) == 0);
  for (int order = 1; order <= 2; ++order) {
    CHECK(sl_dofmap_create(m, order, &dm, NULL) == 0);
    CHECK(dm->n_dofs == (order == 1 ? 6 : 11));
    check_nodes(dm);
    check_interpolation(dm);
    int32_t *bd, nb;
    CHECK(sl_dofmap_boundary_dofs(dm, "right", &bd, &nb, NULL) == 0);
    CHECK(nb == 1 && dm->xy[2 * bd[0]] == 1.0);
    free(bd);
    sl_dofmap_destroy(dm);
  }
  sl_diag d;
  CHECK(sl_dofmap_create(m, 3, &dm, &d) == SL_EBADINPUT && dm == NULL);
  CHECK_CONTAINS(d.msg, "order 3");
  sl_mesh_destroy(m);
}

static void test_taylor_hood(sl_cell_type t) {
  sl_grid_opts o = {.cell_type = t};
  sl_mesh *m;
  sl_th_space *th;
  CHECK(sl_mesh_rectangle(0.0, 2.0, 0.0, 1.0, 4, 2, &o, &m, NULL) == 0);
  CHECK(sl_th_create(m, 2, &th, NULL) == 0);
  int32_t nv = 9 * 5, np = 5 * 3;
  CHECK(th->n_vel == nv && th->pres->n_dofs == np);
  CHECK(th->p_offset == 2 * nv && th->n_dofs == 2 * nv + np);
  int nbv = th->vel->dofs_per_cell;
  CHECK(th->dofs_per_cell == 2 * nbv + th->pres->dofs_per_cell);
  int ok = 1;
  for (int c = 0; c < m->n_cells; ++c) {
    const int32_t *cd = th->cell_dofs + (size_t)c * th->dofs_per_cell;
    const int32_t *v = th->vel->cell_dofs + (size_t)c * nbv,
                  *p = th->pres->cell_dofs + (size_t)c * th->pres->dofs_per_cell;
    for (int b = 0; b < nbv; ++b) ok &= cd[b] == v[b] && cd[nbv + b] == nv + v[b];
    for (int b = 0; b < th->pres->dofs_per_cell; ++b) ok &= cd[2 * nbv + b] == 2 * nv + p[b];
  }
  CHECK(ok);
  sl_th_destroy(th);
  sl_diag d;
  CHECK(sl_th_create(m, 1, &th, &d) == SL_EBADINPUT && th == NULL);
  CHECK(sl_th_create(m, 3, &th, NULL) == 0 && th->p_offset == 3 * nv); /* swirl */
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

static void test_locate_outside(void) {
  sl_mesh *m;
  sl_diag d;
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 2, 2, NULL, &m, NULL) == 0);
  int cell = -1;
  double xi[2];
  CHECK(sl_fe_locate(m, (double[2]){1.5, 0.5}, &cell, xi, &d) == SL_EBADINPUT && cell == -1);
  CHECK_CONTAINS(d.msg, "no cell");
  CHECK(sl_fe_locate(m, (double[2]){1.0, 1.0}, &cell, xi, NULL) == 0); /* a corner: on the boundary counts */
  sl_mesh_destroy(m);
}

int main(void) {
  /* 4 x 3 grid: 20 vertices, quads 12 cells 31 faces, triangles 24 cells 43 faces. */
  test_rectangle(SL_CELL_QUAD4, 1, 20, 5);
  test_rectangle(SL_CELL_QUAD4, 2, 9 * 7, 9);
  test_rectangle(SL_CELL_TRI3, 1, 20, 5);
  test_rectangle(SL_CELL_TRI3, 2, 9 * 7, 9);
  test_interval();
  test_taylor_hood(SL_CELL_QUAD4);
  test_taylor_hood(SL_CELL_TRI3);
  test_locate_outside();
  return sl_test_summary();
}
