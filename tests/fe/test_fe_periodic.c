/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Periodic dof maps and Taylor–Hood spaces: counts, the two numberings
 * (geometric nodes, identified dofs) and the map between them, the
 * representatives' positions, interpolation of periodic functions, boundary
 * dof lists with periodic corners, the constraints built on them, the 1-D
 * and inclined cases, and every refusal with its message. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/operators.h"
#include "core/assembly/system.h"
#include "core/fe/dofmap.h"
#include "core/fe/field.h"
#include "core/fe/geometry.h"
#include "testing.h"

#define LX 2.0
#define LY 1.0

static const sl_periodic_pair PX[] = {{"left", "right"}};
static const sl_periodic_pair PXY[] = {{"left", "right"}, {"bottom", "top"}};

/* Periodic in x (period LX) and y (period LY). */
static void periodic_fn(void *user, const double x[2], double *v, double g[2]) {
  (void)user;
  double a = M_PI, b = 2.0 * M_PI;
  *v = sin(a * x[0] + 0.4) * (1.0 + 0.5 * cos(b * x[1])) + 0.3 * cos(b * x[1] - 0.2);
  if (g)
    g[0] = a * cos(a * x[0] + 0.4) * (1.0 + 0.5 * cos(b * x[1])),
    g[1] = -0.5 * b * sin(a * x[0] + 0.4) * sin(b * x[1]) - 0.3 * b * sin(b * x[1] - 0.2);
}

static int dof_in(const int32_t *list, int32_t n, int32_t dof) {
  for (int32_t k = 0; k < n; ++k)
    if (list[k] == dof) return 1;
  return 0;
}

/* The node at (x, y), or -1. */
static int32_t node_at(const sl_dofmap *dm, double x, double y) {
  for (int32_t i = 0; i < dm->n_nodes; ++i)
    if (fabs(dm->node_xy[2 * i] - x) < 1e-12 && fabs(dm->node_xy[2 * i + 1] - y) < 1e-12) return i;
  return -1;
}

/* Invariants of any (periodic or not) map over the rectangle [0, LX] x [0, LY]. */
static void check_map(const sl_dofmap *dm, int px, int py) {
  const sl_mesh *m = dm->mesh;
  size_t ncd = (size_t)m->n_cells * dm->dofs_per_cell;
  int consistent = 1, geometric = 1, shifted = 1, master_side = 1, vertex_first = 1;
  for (size_t k = 0; k < ncd; ++k) consistent &= dm->cell_dofs[k] == dm->node_dof[dm->cell_nodes[k]];
  for (int c = 0; c < m->n_cells; ++c)
    for (int b = 0; b < dm->dofs_per_cell; ++b) {
      double x[2];
      sl_fe_map_point(m, c, dm->element->nodes[b], x);
      const double *y = dm->node_xy + 2 * (size_t)dm->cell_nodes[(size_t)c * dm->dofs_per_cell + b];
      geometric &= fabs(x[0] - y[0]) + fabs(x[1] - y[1]) < 1e-14;
    }
  int32_t vmax = 0;
  for (int v = 0; v < m->n_vertices; ++v) vmax = dm->node_dof[v] > vmax ? dm->node_dof[v] : vmax;
  /* A node sits at its dof's position plus a multiple of the periods. */
  for (int32_t i = 0; i < dm->n_nodes; ++i) {
    const double *x = dm->node_xy + 2 * (size_t)i, *y = dm->xy + 2 * (size_t)dm->node_dof[i];
    double dx = x[0] - y[0], dy = x[1] - y[1];
    int okx = fabs(dx) < 1e-14 || (px && fabs(dx - LX) < 1e-14);
    int oky = fabs(dy) < 1e-14 || (py && fabs(dy - LY) < 1e-14);
    shifted &= okx && oky;
    if (i >= m->n_vertices && dm->node_dof[i] <= vmax) vertex_first = 0;
  }
  /* Representatives on the first boundary of each pair. */
  for (int32_t j = 0; j < dm->n_dofs; ++j)
    master_side &= (!px || dm->xy[2 * j] < LX - 1e-12) && (!py || dm->xy[2 * j + 1] < LY - 1e-12);
  char *used = calloc((size_t)dm->n_dofs, 1);
  for (int32_t i = 0; i < dm->n_nodes; ++i) used[dm->node_dof[i]] = 1;
  int onto = 1;
  for (int32_t j = 0; j < dm->n_dofs; ++j) onto &= used[j];
  free(used);
  CHECK_MSG(consistent && geometric && shifted && master_side && vertex_first && onto,
            "%s px %d py %d: consistent %d geometric %d shifted %d master side %d vertex dofs first %d onto %d",
            dm->element->name, px, py, consistent, geometric, shifted, master_side, vertex_first, onto);
}

/* The interpolant of a periodic function: the same error as on the plain
 * map (the identified nodes carry equal values), and evaluation next to the
 * partner boundary agrees with the function. */
static void check_interpolation(const sl_dofmap *per, const sl_dofmap *plain) {
  double *u = malloc((size_t)per->n_dofs * sizeof *u), *v = malloc((size_t)plain->n_dofs * sizeof *v);
  double *un = malloc((size_t)per->n_nodes * sizeof *un);
  sl_fe_interpolate(per, periodic_fn, NULL, u);
  sl_fe_interpolate(plain, periodic_fn, NULL, v);
  double l2p = 0, h1p = 0, l2 = 0, h1 = 0;
  int deg = per->mesh->cell_type == SL_CELL_TRI3 ? 5 : 6;
  CHECK(sl_fe_error_norms(per, u, periodic_fn, NULL, 0, deg, &l2p, &h1p, NULL) == 0);
  CHECK(sl_fe_error_norms(plain, v, periodic_fn, NULL, 0, deg, &l2, &h1, NULL) == 0);
  CHECK_MSG(fabs(l2p - l2) <= 1e-12 * l2 && fabs(h1p - h1) <= 1e-12 * h1 && l2 > 0,
            "%s: interpolation error %.15g / %.15g periodic, %.15g / %.15g plain", per->element->name, l2p, h1p, l2,
            h1);
  /* spread to the nodes: exactly the plain interpolant */
  sl_dofmap_dofs_to_nodes(per, u, un, 1);
  double worst = 0.0;
  for (int32_t i = 0; i < per->n_nodes; ++i) worst = fmax(worst, fabs(un[i] - v[i]));
  CHECK_MSG(worst < 1e-14, "%s: node values differ from the plain interpolant by %g", per->element->name, worst);
  /* next to the partner sides, value and gradient as the plain interpolant's */
  int cell = -1;
  double dev = 0.0;
  for (int k = 0; k < 8; ++k) {
    double x[2] = {LX - 1e-3, (k + 0.37) / 8.0 * LY}, xi[2], a, b, ga[2], gb[2];
    if (k >= 4) x[0] = (k - 3.7) / 4.0 * LX, x[1] = LY - 2e-3;
    CHECK(sl_fe_locate(per->mesh, x, &cell, xi, NULL) == 0);
    sl_fe_eval(per, u, cell, xi, &a, ga);
    sl_fe_eval(plain, v, cell, xi, &b, gb);
    dev = fmax(dev, fabs(a - b) + fabs(ga[0] - gb[0]) + fabs(ga[1] - gb[1]));
  }
  CHECK_MSG(dev < 1e-13, "%s: the periodic interpolant near the partner sides differs by %g", per->element->name, dev);
  free(u), free(v), free(un);
}

static void test_rectangle(sl_cell_type cell, int order) {
  const int nx = 4, ny = 3;
  sl_grid_opts o = {.cell_type = cell, .diagonal = SL_DIAGONAL_UNION_JACK};
  sl_mesh *m = NULL;
  sl_dofmap *plain = NULL, *px = NULL, *pxy = NULL;
  sl_diag d = {{0}};
  CHECK(sl_mesh_rectangle(0.0, LX, 0.0, LY, nx, ny, &o, &m, &d) == 0);
  CHECK(sl_dofmap_create(m, order, &plain, &d) == 0);
  CHECK_MSG(sl_dofmap_create_periodic(m, order, PX, 1, &px, &d) == 0, "%s", d.msg);
  CHECK_MSG(sl_dofmap_create_periodic(m, order, PXY, 2, &pxy, &d) == 0, "%s", d.msg);
  if (!plain || !px || !pxy) goto out;
  int kx = order * nx, ky = order * ny; /* nodes per row minus one */
  CHECK(plain->n_periodic == 0 && px->n_periodic == 1 && pxy->n_periodic == 2);
  CHECK(plain->cell_nodes == plain->cell_dofs && plain->node_xy == plain->xy);
  CHECK(px->n_nodes == plain->n_dofs && pxy->n_nodes == plain->n_dofs);
  CHECK(plain->n_dofs == (kx + 1) * (ky + 1));
  CHECK_MSG(px->n_dofs == kx * (ky + 1), "%s periodic x: %d dofs", px->element->name, (int)px->n_dofs);
  CHECK_MSG(pxy->n_dofs == kx * ky, "%s doubly periodic: %d dofs", pxy->element->name, (int)pxy->n_dofs);
  check_map(plain, 0, 0);
  check_map(px, 1, 0);
  check_map(pxy, 1, 1);
  check_interpolation(px, plain);
  check_interpolation(pxy, plain);

  /* Corners: periodic in x, (LX, 0) is the dof at (0, 0) and still on
   * "bottom"; doubly periodic, the four corners are one dof on all sides. */
  int32_t c00 = node_at(px, 0, 0), cx0 = node_at(px, LX, 0), c0y = node_at(px, 0, LY), cxy = node_at(px, LX, LY);
  CHECK(c00 >= 0 && cx0 >= 0 && c0y >= 0 && cxy >= 0);
  if (c00 < 0 || cx0 < 0 || c0y < 0 || cxy < 0) goto out;
  CHECK(px->node_dof[cx0] == px->node_dof[c00] && px->node_dof[cxy] == px->node_dof[c0y]);
  CHECK(px->node_dof[c00] != px->node_dof[c0y]);
  CHECK(pxy->node_dof[c00] == pxy->node_dof[cx0] && pxy->node_dof[c00] == pxy->node_dof[c0y] &&
        pxy->node_dof[c00] == pxy->node_dof[cxy]);
  CHECK(pxy->xy[2 * pxy->node_dof[cxy]] == 0.0 && pxy->xy[2 * pxy->node_dof[cxy] + 1] == 0.0);
  static const char *const sides[] = {"bottom", "right", "top", "left"};
  int32_t *list[4] = {NULL}, n[4] = {0};
  for (int s = 0; s < 4; ++s) CHECK(sl_dofmap_boundary_dofs(px, sides[s], &list[s], &n[s], &d) == 0);
  CHECK_MSG(n[0] == kx && n[2] == kx && n[1] == ky + 1 && n[3] == ky + 1, "%s periodic x: sides %d %d %d %d",
            px->element->name, (int)n[0], (int)n[1], (int)n[2], (int)n[3]);
  CHECK(dof_in(list[0], n[0], px->node_dof[c00]) && dof_in(list[2], n[2], px->node_dof[cxy]));
  CHECK(n[1] == n[3] && memcmp(list[1], list[3], (size_t)n[1] * sizeof *list[1]) == 0);
  for (int s = 0; s < 4; ++s) free(list[s]), list[s] = NULL;
  for (int s = 0; s < 4; ++s) CHECK(sl_dofmap_boundary_dofs(pxy, sides[s], &list[s], &n[s], &d) == 0);
  for (int s = 0; s < 4; ++s) CHECK(dof_in(list[s], n[s], pxy->node_dof[c00]));
  CHECK(n[0] == kx && n[1] == ky && n[0] == n[2] && n[1] == n[3]);
  CHECK(memcmp(list[0], list[2], (size_t)n[0] * sizeof *list[0]) == 0);
  for (int s = 0; s < 4; ++s) free(list[s]);
out:
  sl_dofmap_destroy(plain);
  sl_dofmap_destroy(px);
  sl_dofmap_destroy(pxy);
  sl_mesh_destroy(m);
}

/* The Taylor–Hood space of a periodic channel: sizes, the combined
 * numbering, wall constraints through the corners and the pressure datum. */
static void test_taylor_hood(sl_cell_type cell) {
  const int nx = 5, ny = 2;
  sl_grid_opts o = {.cell_type = cell, .diagonal = SL_DIAGONAL_RIGHT};
  sl_mesh *m = NULL;
  sl_th_space *th = NULL;
  sl_diag d = {{0}};
  CHECK(sl_mesh_rectangle(0.0, LX, 0.0, LY, nx, ny, &o, &m, &d) == 0);
  CHECK_MSG(sl_th_create_periodic(m, 3, PX, 1, &th, &d) == 0, "%s", d.msg);
  if (!th) {
    sl_mesh_destroy(m);
    return;
  }
  CHECK(th->n_vel == 2 * nx * (2 * ny + 1) && th->pres->n_dofs == nx * (ny + 1));
  CHECK(th->n_dofs == 3 * th->n_vel + th->pres->n_dofs && th->p_offset == 3 * th->n_vel);
  int nbv = th->vel->dofs_per_cell, nbp = th->pres->dofs_per_cell, ok = 1;
  for (int c = 0; c < m->n_cells; ++c) {
    const int32_t *cd = th->cell_dofs + (size_t)c * th->dofs_per_cell;
    for (int comp = 0; comp < 3; ++comp)
      for (int i = 0; i < nbv; ++i)
        ok &= cd[comp * nbv + i] == sl_th_vel_dof(th, comp, th->vel->node_dof[th->vel->cell_nodes[c * nbv + i]]);
    for (int i = 0; i < nbp; ++i)
      ok &= cd[3 * nbv + i] == sl_th_pres_dof(th, th->pres->node_dof[th->pres->cell_nodes[c * nbp + i]]);
  }
  CHECK(ok);
  /* pressure nodes are the vertices, identified the same way as the velocity's */
  ok = 1;
  for (int v = 0; v < m->n_vertices; ++v)
    ok &= th->pres->xy[2 * th->pres->node_dof[v]] == th->vel->xy[2 * th->vel->node_dof[v]] &&
          th->pres->xy[2 * th->pres->node_dof[v] + 1] == th->vel->xy[2 * th->vel->node_dof[v] + 1];
  CHECK(ok);
  /* walls top and bottom: every one of their dofs, corners included */
  sl_constraints bc;
  CHECK(sl_constraints_init(&bc, th->n_dofs, &d) == 0);
  for (int c = 0; c < 3; ++c) {
    CHECK(sl_constraints_fix_boundary(&bc, th->vel, "bottom", sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, &d) == 0);
    CHECK(sl_constraints_fix_boundary(&bc, th->vel, "top", sl_th_vel_dof(th, c, 0), NULL, NULL, 1.0, &d) == 0);
  }
  sl_stokes_fix_pressure_datum(&bc, th);
  CHECK_MSG(bc.n_fixed == 3 * 2 * (2 * nx) + 1, "%d fixed", (int)bc.n_fixed);
  int32_t top_right = node_at(th->vel, LX, LY);
  CHECK(top_right >= 0 && bc.fixed[sl_th_vel_dof(th, 1, th->vel->node_dof[top_right])] &&
        bc.value[sl_th_vel_dof(th, 1, th->vel->node_dof[top_right])] == 1.0);
  CHECK(bc.fixed[th->p_offset] && th->pres->xy[0] == 0.0 && th->pres->xy[1] == 0.0);
  sl_constraints_free(&bc);
  /* the system builds on the identified numbering */
  sl_system s;
  CHECK(sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, &d) == 0);
  sl_system_free(&s);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

static void test_line_and_inclined(void) {
  sl_mesh *m = NULL;
  sl_diag d = {{0}};
  sl_th_space *th = NULL;
  CHECK(sl_mesh_interval(0.0, 3.0, 6, NULL, &m, &d) == 0);
  CHECK_MSG(sl_th_create_periodic(m, 1, PX, 1, &th, &d) == 0, "%s", d.msg);
  if (th) {
    CHECK(th->n_vel == 12 && th->pres->n_dofs == 6 && th->n_dofs == 18);
    CHECK(th->vel->node_dof[6] == th->vel->node_dof[0] && th->pres->node_dof[6] == 0);
    /* the midpoint of the last cell keeps its own dof, numbered after the vertices */
    CHECK(th->vel->node_dof[7 + 5] == 11 && th->vel->xy[2 * 11] == 2.75);
  }
  sl_th_destroy(th);
  sl_mesh_destroy(m);

  /* One cell across the period: the cell's two sides are one. */
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 1, 2, NULL, &m, &d) == 0);
  CHECK_MSG(sl_th_create_periodic(m, 2, PX, 1, &th, &d) == 0, "%s", d.msg);
  if (th) CHECK(th->n_vel == 2 * 5 && th->pres->n_dofs == 3);
  sl_th_destroy(th);
  sl_mesh_destroy(m);

  /* A box inclined by 0.6 rad, periodic along its width W: a function of the
   * coordinate along the width with period W is interpolated as on the
   * plain map. */
  CHECK(sl_mesh_inclined_box(0.3, -0.2, 2.0, 1.0, 0.6, 6, 4, NULL, &m, &d) == 0);
  sl_dofmap *per = NULL, *plain = NULL;
  CHECK_MSG(sl_dofmap_create_periodic(m, 2, PX, 1, &per, &d) == 0, "%s", d.msg);
  CHECK(sl_dofmap_create(m, 2, &plain, &d) == 0);
  if (per && plain) {
    CHECK(per->n_dofs == plain->n_dofs - 9);
    int ok = 1;
    for (int32_t i = 0; i < per->n_nodes; ++i) {
      const double *x = per->node_xy + 2 * i, *y = per->xy + 2 * per->node_dof[i];
      double dx = x[0] - y[0], dy = x[1] - y[1];
      ok &= hypot(dx, dy) < 1e-14 || hypot(dx - 2.0 * cos(0.6), dy - 2.0 * sin(0.6)) < 1e-13;
    }
    CHECK(ok);
  }
  sl_dofmap_destroy(per);
  sl_dofmap_destroy(plain);
  sl_mesh_destroy(m);
}

/* Pairs listed the other way round: the right and top sides keep the dofs,
 * whatever the node numbering (their nodes are numbered last). */
static void test_reversed(void) {
  sl_mesh *m = NULL;
  sl_dofmap *dm = NULL;
  sl_diag d = {{0}};
  const sl_periodic_pair rev[] = {{"right", "left"}, {"top", "bottom"}};
  CHECK(sl_mesh_rectangle(0.0, LX, 0.0, LY, 3, 2, NULL, &m, &d) == 0);
  CHECK_MSG(sl_dofmap_create_periodic(m, 2, rev, 2, &dm, &d) == 0, "%s", d.msg);
  if (dm) {
    int ok = 1;
    for (int32_t j = 0; j < dm->n_dofs; ++j) ok &= dm->xy[2 * j] > 1e-12 && dm->xy[2 * j + 1] > 1e-12;
    CHECK(ok);
    CHECK(dm->n_dofs == 6 * 4);
    int32_t c = node_at(dm, 0.0, 0.0);
    CHECK(c >= 0 && dm->xy[2 * dm->node_dof[c]] == LX && dm->xy[2 * dm->node_dof[c] + 1] == LY);
  }
  sl_dofmap_destroy(dm);
  sl_mesh_destroy(m);
}

static void expect_error(const sl_mesh *m, const sl_periodic_pair *pairs, int n, const char *const *needles, int k) {
  sl_th_space *th = (sl_th_space *)&th; /* must be reset */
  sl_diag d = {{0}};
  int rc = sl_th_create_periodic(m, 2, pairs, n, &th, &d);
  CHECK_MSG(rc == SL_EBADINPUT && th == NULL, "rc %d: %s", rc, d.msg);
  for (int i = 0; i < k; ++i) CHECK_CONTAINS(d.msg, needles[i]);
  printf("  %s\n", d.msg);
  if (rc == 0) sl_th_destroy(th);
}

static void test_errors(void) {
  sl_mesh *m = NULL;
  sl_diag d = {{0}};
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 3, NULL, &m, &d) == 0);
  expect_error(m, (const sl_periodic_pair[]){{"left", "rihgt"}}, 1,
               (const char *[]){"periodic pair 'left' / 'rihgt'", "did you mean \"right\""}, 2);
  expect_error(m, (const sl_periodic_pair[]){{"left", "bottom"}}, 1,
               (const char *[]){"'left' has 4 nodes", "'bottom' 5 nodes"}, 2);
  expect_error(m, (const sl_periodic_pair[]){{"left", "right"}, {"left", "right"}}, 2,
               (const char *[]){"'right' is the partner of two pairs"}, 1);
  expect_error(m, (const sl_periodic_pair[]){{"left", "right"}, {"right", "left"}}, 2,
               (const char *[]){"cycle through boundary 'right'"}, 1);
  expect_error(m, PX, -1, (const char *[]){"-1 pairs"}, 1);
  expect_error(m, NULL, 1, (const char *[]){"without a list"}, 1);
  sl_mesh_destroy(m);
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 3, 3, NULL, &m, &d) == 0);
  expect_error(m, (const sl_periodic_pair[]){{"bottom", "left"}}, 1, (const char *[]){"not translates", "rotation"}, 2);
  sl_mesh_destroy(m);
  /* a node of the top moved along it: named with its partner's place */
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 4, 2, NULL, &m, &d) == 0);
  for (int v = 0; v < m->n_vertices; ++v)
    if (m->xy[2 * v] == 0.25 && m->xy[2 * v + 1] == 1.0) m->xy[2 * v] = 0.2;
  expect_error(
      m, PXY, 2,
      (const char *[]){"'bottom' / 'top'", "the node (0.2, 1) of 'top' has no partner on 'bottom' at (0.2, 0)"}, 2);
  sl_mesh_destroy(m);
}

int main(void) {
  test_rectangle(SL_CELL_QUAD4, 1);
  test_rectangle(SL_CELL_QUAD4, 2);
  test_rectangle(SL_CELL_TRI3, 1);
  test_rectangle(SL_CELL_TRI3, 2);
  test_taylor_hood(SL_CELL_QUAD4);
  test_taylor_hood(SL_CELL_TRI3);
  test_line_and_inclined();
  test_reversed();
  test_errors();
  return sl_test_summary();
}
