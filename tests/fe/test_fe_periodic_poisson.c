/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Diffusion -div(k grad u) = f on periodic spaces, manufactured solutions,
 * observed orders over n = 8, 16, 32 (L2 p + 1, H1 p, within +-0.2):
 *
 *  channel  [0, 1]^2, periodic in x, u = 0 on the bottom and top:
 *           u = sin(2 pi x + 0.3) y (1 - y),  k = 1 + cos(2 pi x) / 4 + y / 2;
 *  torus    [0, 2] x [0, 1], periodic in x and y, the dof at the origin
 *           pinned to the exact value (u is defined up to a constant):
 *           u = sin(pi x) cos(2 pi y) + cos(pi x + 2 pi y + 0.3) / 2,
 *           k = 1 + cos(pi x) sin(2 pi y) / 4;
 *  ring     [0, 1.5] periodic (1-D), pinned at x = 0:
 *           u = sin(w x) + 0.3 cos(2 w x), w = 2 pi / 1.5, k = 1 + 0.3 sin(w x).
 * On quads (Q1, Q2) and union-jack triangles (P1, P2), and on the line (P1,
 * P2). The periodic solution is checked across the identified side too: the
 * error norms integrate over every cell, including those whose nodes are
 * the partner side's. */
#include "fe_study.h"
#include "testing.h"

typedef enum problem { CHANNEL, TORUS, RING } problem;

typedef struct exact_data {
  problem pb;
} exact_data;

static const double W_ = 2.0 * M_PI / 1.5;

/* u, grad u, lap u, k, grad k at x. */
static void fields(problem pb, const double x[2], double *u, double gu[2], double *lap, double *k, double gk[2]) {
  if (pb == CHANNEL) {
    double t = 2.0 * M_PI * x[0] + 0.3, s = sin(t), c = cos(t), y = x[1], q = y * (1.0 - y);
    *u = s * q;
    gu[0] = 2.0 * M_PI * c * q, gu[1] = s * (1.0 - 2.0 * y);
    *lap = -4.0 * M_PI * M_PI * s * q - 2.0 * s;
    *k = 1.0 + 0.25 * cos(2.0 * M_PI * x[0]) + 0.5 * y;
    gk[0] = -0.5 * M_PI * sin(2.0 * M_PI * x[0]), gk[1] = 0.5;
  } else if (pb == TORUS) {
    double a = M_PI, b = 2.0 * M_PI, th = a * x[0] + b * x[1] + 0.3;
    *u = sin(a * x[0]) * cos(b * x[1]) + 0.5 * cos(th);
    gu[0] = a * cos(a * x[0]) * cos(b * x[1]) - 0.5 * a * sin(th);
    gu[1] = -b * sin(a * x[0]) * sin(b * x[1]) - 0.5 * b * sin(th);
    *lap = -(a * a + b * b) * *u;
    *k = 1.0 + 0.25 * cos(a * x[0]) * sin(b * x[1]);
    gk[0] = -0.25 * a * sin(a * x[0]) * sin(b * x[1]), gk[1] = 0.25 * b * cos(a * x[0]) * cos(b * x[1]);
  } else {
    double s = sin(W_ * x[0]), c = cos(W_ * x[0]);
    *u = s + 0.3 * cos(2.0 * W_ * x[0]);
    gu[0] = W_ * c - 0.6 * W_ * sin(2.0 * W_ * x[0]), gu[1] = 0.0;
    *lap = -W_ * W_ * s - 1.2 * W_ * W_ * cos(2.0 * W_ * x[0]);
    *k = 1.0 + 0.3 * s;
    gk[0] = 0.3 * W_ * c, gk[1] = 0.0;
  }
}

static void exact(void *user, const double x[2], double *v, double g[2]) {
  const exact_data *e = user;
  double gu[2], lap, k, gk[2];
  fields(e->pb, x, v, gu, &lap, &k, gk);
  if (g) g[0] = gu[0], g[1] = gu[1];
}

static int diffusivity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const exact_data *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) {
    double u, gu[2], lap, gk[2];
    fields(e->pb, b->x[i], &u, gu, &lap, &out[i], gk);
  }
  return 0;
}

static int source(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const exact_data *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) {
    double u, gu[2], lap, k, gk[2];
    fields(e->pb, b->x[i], &u, gu, &lap, &k, gk);
    out[i] = -(gk[0] * gu[0] + gk[1] * gu[1] + k * lap);
  }
  return 0;
}

static const sl_periodic_pair PX[] = {{"left", "right"}}, PXY[] = {{"left", "right"}, {"bottom", "top"}};

static int solve(const sl_dofmap *dm, exact_data *e, double *x, sl_diag *d) {
  sl_system s;
  sl_constraints bc;
  sl_linsolve *ls = NULL;
  int rc = sl_system_init(&s, dm->n_dofs, dm->mesh->n_cells, dm->dofs_per_cell, dm->cell_dofs, d);
  if (rc) return rc;
  if ((rc = sl_constraints_init(&bc, dm->n_dofs, d))) {
    sl_system_free(&s);
    return rc;
  }
  sl_diffusion_opts o = {.diffusivity = {diffusivity, e, 0.0}, .source = {source, e, 0.0}};
  rc = sl_assemble_diffusion(&s, dm, &o, d);
  if (e->pb == CHANNEL) {
    if (!rc) rc = sl_constraints_fix_boundary(&bc, dm, "bottom", 0, exact, e, 0.0, d);
    if (!rc) rc = sl_constraints_fix_boundary(&bc, dm, "top", 0, exact, e, 0.0, d);
  } else { /* pin the dof at the origin */
    double v;
    exact(e, dm->xy, &v, NULL);
    sl_constraints_fix(&bc, 0, v);
  }
  if (!rc) rc = sl_constraints_apply(&bc, &s, 1, d);
  if (!rc) rc = sl_linsolve_create(&ls, "umfpack", d);
  if (!rc) rc = sl_linsolve_solve(ls, &s.A, s.b, x, d);
  sl_linsolve_destroy(ls);
  sl_constraints_free(&bc);
  sl_system_free(&s);
  return rc;
}

typedef struct study {
  const char *name;
  problem pb;
  sl_cell_type cell;
  int order;
} study;

static void run(const study *s) {
  const int sizes[] = {8, 16, 32};
  double l2[3], h1[3];
  exact_data e = {s->pb};
  for (int k = 0; k < 3; ++k) {
    int n = sizes[k];
    sl_mesh *m = NULL;
    sl_dofmap *dm = NULL;
    sl_diag d = {{0}};
    sl_grid_opts go = {.cell_type = s->cell, .diagonal = SL_DIAGONAL_UNION_JACK};
    int rc = s->pb == RING    ? sl_mesh_interval(0.0, 1.5, n, NULL, &m, &d)
             : s->pb == TORUS ? sl_mesh_rectangle(0.0, 2.0, 0.0, 1.0, 2 * n, n, &go, &m, &d)
                              : sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, n, n, &go, &m, &d);
    if (!rc) rc = sl_dofmap_create_periodic(m, s->order, s->pb == TORUS ? PXY : PX, s->pb == TORUS ? 2 : 1, &dm, &d);
    double *x = dm ? calloc((size_t)dm->n_dofs, sizeof *x) : NULL;
    if (!rc) rc = solve(dm, &e, x, &d);
    if (!rc) rc = sl_fe_error_norms(dm, x, exact, &e, 0, error_quad_degree(s->cell, s->order), &l2[k], &h1[k], &d);
    CHECK_MSG(rc == 0, "%s n=%d: %s", s->name, n, d.msg);
    if (!rc && k == 0) { /* the identified numbering was used: fewer dofs than nodes */
      int32_t lost = s->pb == RING    ? 1
                     : s->pb == TORUS ? (2 * n * s->order + 1) + (n * s->order + 1) - 1
                                      : n * s->order + 1;
      CHECK_MSG(dm->n_nodes - dm->n_dofs == lost, "%s: %d nodes, %d dofs", s->name, (int)dm->n_nodes, (int)dm->n_dofs);
    }
    free(x);
    sl_dofmap_destroy(dm);
    sl_mesh_destroy(m);
    if (rc) return;
  }
  printf("%-22s L2 %.3e %.3e %.3e  orders %.3f %.3f | H1 %.3e %.3e %.3e  orders %.3f %.3f\n", s->name, l2[0], l2[1],
         l2[2], observed_order(l2[0], l2[1]), observed_order(l2[1], l2[2]), h1[0], h1[1], h1[2],
         observed_order(h1[0], h1[1]), observed_order(h1[1], h1[2]));
  for (int k = 0; k < 2; ++k) {
    double ol2 = observed_order(l2[k], l2[k + 1]), oh1 = observed_order(h1[k], h1[k + 1]);
    CHECK_MSG(fabs(ol2 - (s->order + 1)) <= 0.2, "%s: L2 order %.3f, expected %d", s->name, ol2, s->order + 1);
    CHECK_MSG(fabs(oh1 - s->order) <= 0.2, "%s: H1 order %.3f, expected %d", s->name, oh1, s->order);
  }
  /* the size of the error at n = 32: a wrong identification (a seam) would
   * leave an O(1) H1 error that does not converge */
  CHECK_MSG(h1[2] < (s->order == 2 ? 2e-2 : 0.5), "%s: H1 error %.3e at n = 32", s->name, h1[2]);
}

int main(void) {
  const study studies[] = {
      {"channel Q2", CHANNEL, SL_CELL_QUAD4, 2},      {"channel P2", CHANNEL, SL_CELL_TRI3, 2},
      {"channel Q1", CHANNEL, SL_CELL_QUAD4, 1},      {"channel P1", CHANNEL, SL_CELL_TRI3, 1},
      {"torus Q2 (pinned)", TORUS, SL_CELL_QUAD4, 2}, {"torus P2 (pinned)", TORUS, SL_CELL_TRI3, 2},
      {"torus Q1 (pinned)", TORUS, SL_CELL_QUAD4, 1}, {"ring P2 (pinned)", RING, SL_CELL_LINE2, 2},
      {"ring P1 (pinned)", RING, SL_CELL_LINE2, 1},
  };
  for (size_t k = 0; k < sizeof studies / sizeof studies[0]; ++k) run(&studies[k]);
  return sl_test_summary();
}
