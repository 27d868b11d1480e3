/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Poisson with a manufactured solution and a variable coefficient,
 *   -div(k grad u) = f on [0, 1]^2,  u = u_exact on the boundary,
 *   u = sin(a x + 0.3) cos(b y),  k = 1 + x^2 / 2 + y,
 * on quads (Q1, Q2) and triangles (P1, P2), and on the interval (P1, P2).
 * Observed orders over n = 8, 16, 32: L2 p + 1, H1 p, within +-0.2. */
#include "fe_study.h"
#include "testing.h"

static const double A_ = 1.7, B_ = 2.3;

static void exact(void *user, const double x[2], double *v, double g[2]) {
  (void)user;
  double s = sin(A_ * x[0] + 0.3), c = cos(B_ * x[1]);
  *v = s * c;
  if (g) g[0] = A_ * cos(A_ * x[0] + 0.3) * c, g[1] = -B_ * s * sin(B_ * x[1]);
}

static int diffusivity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = 1.0 + 0.5 * b->x[i][0] * b->x[i][0] + b->x[i][1];
  return 0;
}

/* f = -(grad k . grad u + k lap u); in 1-D (y = 0) only the x terms. */
static int source(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  int dim = *(const int *)user;
  (void)d;
  for (int i = 0; i < b->n; ++i) {
    const double *x = b->x[i];
    double u, g[2];
    exact(NULL, x, &u, g);
    double k = 1.0 + 0.5 * x[0] * x[0] + x[1];
    double lap = -(A_ * A_ + (dim == 2 ? B_ * B_ : 0.0)) * u;
    out[i] = -(x[0] * g[0] + (dim == 2 ? g[1] : 0.0) + k * lap);
  }
  return 0;
}

typedef struct study {
  const char *name;
  int dim;
  sl_cell_type cell;
  int order;
} study;

static int make_mesh(const study *s, int n, sl_mesh **m) {
  if (s->dim == 1) return sl_mesh_interval(0.0, 1.0, n, NULL, m, NULL);
  sl_grid_opts o = {.cell_type = s->cell, .diagonal = SL_DIAGONAL_RIGHT};
  return sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, n, n, &o, m, NULL);
}

static void run(const study *s) {
  static const char *const rect[] = {"bottom", "right", "top", "left"}, *const ends[] = {"left", "right"};
  const int sizes[] = {8, 16, 32};
  double l2[3], h1[3];
  int dim = s->dim;
  sl_diffusion_opts o = {.diffusivity = {diffusivity, NULL, 0.0}, .source = {source, &dim, 0.0}};
  for (int k = 0; k < 3; ++k) {
    sl_mesh *m = NULL;
    sl_dofmap *dm = NULL;
    sl_diag d = {{0}};
    int rc = make_mesh(s, sizes[k], &m);
    if (!rc) rc = sl_dofmap_create(m, s->order, &dm, &d);
    double *x = dm ? calloc((size_t)dm->n_dofs, sizeof *x) : NULL;
    if (!rc) rc = solve_diffusion(dm, &o, dim == 2 ? rect : ends, dim == 2 ? 4 : 2, exact, NULL, "umfpack", x, &d);
    if (!rc) rc = sl_fe_error_norms(dm, x, exact, NULL, 0, error_quad_degree(s->cell, s->order), &l2[k], &h1[k], &d);
    CHECK_MSG(rc == 0, "%s n=%d: %s", s->name, sizes[k], d.msg);
    free(x);
    sl_dofmap_destroy(dm);
    sl_mesh_destroy(m);
    if (rc) return;
  }
  printf("%-12s L2 %.3e %.3e %.3e  orders %.3f %.3f | H1 %.3e %.3e %.3e  orders %.3f %.3f\n", s->name, l2[0], l2[1],
         l2[2], observed_order(l2[0], l2[1]), observed_order(l2[1], l2[2]), h1[0], h1[1], h1[2],
         observed_order(h1[0], h1[1]), observed_order(h1[1], h1[2]));
  for (int k = 0; k < 2; ++k) {
    double ol2 = observed_order(l2[k], l2[k + 1]), oh1 = observed_order(h1[k], h1[k + 1]);
    CHECK_MSG(fabs(ol2 - (s->order + 1)) <= 0.2, "%s: L2 order %.3f, expected %d", s->name, ol2, s->order + 1);
    CHECK_MSG(fabs(oh1 - s->order) <= 0.2, "%s: H1 order %.3f, expected %d", s->name, oh1, s->order);
  }
}

int main(void) {
  const study studies[] = {
      {"Q1 quads", 2, SL_CELL_QUAD4, 1},    {"Q2 quads", 2, SL_CELL_QUAD4, 2}, {"P1 triangles", 2, SL_CELL_TRI3, 1},
      {"P2 triangles", 2, SL_CELL_TRI3, 2}, {"P1 line", 1, SL_CELL_LINE2, 1},  {"P2 line", 1, SL_CELL_LINE2, 2},
  };
  for (size_t k = 0; k < sizeof studies / sizeof studies[0]; ++k) run(&studies[k]);
  return sl_test_summary();
}
