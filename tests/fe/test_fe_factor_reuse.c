/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Constant operators are factorised once: repeated solves with the same
 * assembled matrix do one symbolic and one numeric factorisation
 * (sl_linsolve_get_stats), and re-assembling the same operator is
 * recognised as unchanged (no second numeric factorisation). Poisson (Q1,
 * cholmod and umfpack) and Stokes (P2/P1, umfpack and klu). */
#include "fe_study.h"
#include "testing.h"

static int sin_source(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = sin(3.0 * b->x[i][0]) + b->x[i][1];
  return 0;
}

static int gravity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[2 * i] = b->x[i][1], out[2 * i + 1] = -9.81 * (1.0 + b->x[i][0]);
  return 0;
}

typedef struct problem {
  sl_system s;
  sl_constraints bc;
} problem;

/* Assemble and constrain: Poisson on dm (th NULL) or Stokes on th. */
static int assemble(problem *p, const sl_dofmap *dm, const sl_th_space *th, sl_diag *d) {
  static const char *const walls[] = {"bottom", "right", "top", "left"};
  sl_system_zero(&p->s);
  int rc;
  if (th) {
    sl_stokes_opts o = {.viscosity = {NULL, NULL, 2.0}, .body_force = gravity};
    rc = sl_assemble_stokes(&p->s, th, &o, d);
    sl_stokes_fix_pressure_datum(&p->bc, th);
    for (int w = 0; w < 4 && !rc; ++w)
      for (int c = 0; c < 2 && !rc; ++c)
        rc = sl_constraints_fix_boundary(&p->bc, th->vel, walls[w], sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, d);
  } else {
    sl_diffusion_opts o = {.diffusivity = {NULL, NULL, 1.5}, .source = {sin_source, NULL, 0.0}};
    rc = sl_assemble_diffusion(&p->s, dm, &o, d);
    for (int w = 0; w < 4 && !rc; ++w) rc = sl_constraints_fix_boundary(&p->bc, dm, walls[w], 0, NULL, NULL, 0.0, d);
  }
  return rc ? rc : sl_constraints_apply(&p->bc, &p->s, 1, d);
}

static void run(const char *solver, const sl_dofmap *dm, const sl_th_space *th) {
  int32_t n = th ? th->n_dofs : dm->n_dofs;
  const sl_mesh *m = th ? th->mesh : dm->mesh;
  problem p;
  sl_linsolve *ls = NULL;
  sl_diag d = {{0}};
  double *x1 = calloc((size_t)n, sizeof *x1), *x2 = calloc((size_t)n, sizeof *x2), *b2 = calloc((size_t)n, sizeof *b2);
  int rc = sl_system_init(&p.s, n, m->n_cells, th ? th->dofs_per_cell : dm->dofs_per_cell,
                          th ? th->cell_dofs : dm->cell_dofs, &d);
  if (!rc) rc = sl_constraints_init(&p.bc, n, &d);
  if (!rc) rc = assemble(&p, dm, th, &d);
  if (!rc) rc = sl_linsolve_create(&ls, solver, &d);
  if (!rc) rc = sl_linsolve_solve(ls, &p.s.A, p.s.b, x1, &d);
  /* Four more right-hand sides, the matrix untouched: x(k b) = k x(b). */
  double worst = 0.0;
  for (int k = 2; k <= 5 && !rc; ++k) {
    for (int32_t i = 0; i < n; ++i) b2[i] = k * p.s.b[i];
    rc = sl_linsolve_solve(ls, &p.s.A, b2, x2, &d);
    for (int32_t i = 0; i < n && !rc; ++i) worst = fmax(worst, fabs(x2[i] - k * x1[i]));
  }
  CHECK_MSG(rc == 0, "%s: %s", solver, d.msg);
  if (rc) goto done;
  const sl_linsolve_stats *st = sl_linsolve_get_stats(ls);
  printf("%-8s %s, %d dofs: %ld symbolic, %ld numeric, %ld solves\n", solver, th ? "Stokes P2/P1" : "Poisson Q1",
         (int)n, st->n_symbolic, st->n_numeric, st->n_solves);
  CHECK(st->n_symbolic == 1 && st->n_numeric == 1 && st->n_solves == 5);
  double scale = 0.0;
  for (int32_t i = 0; i < n; ++i) scale = fmax(scale, fabs(x1[i]));
  CHECK_MSG(scale > 0.0 && worst <= 1e-10 * 5.0 * scale, "%s: solves with k b differ from k x by %g", solver, worst);
  /* Re-assembled, bitwise the same operator (a constant-coefficient run):
   * recognised, no second numeric factorisation. */
  if ((rc = assemble(&p, dm, th, &d)) == 0) rc = sl_linsolve_solve(ls, &p.s.A, p.s.b, x2, &d);
  CHECK_MSG(rc == 0, "%s: %s", solver, d.msg);
  CHECK(st->n_symbolic == 1 && st->n_numeric == 1 && st->n_numeric_skipped == 1 && st->n_solves == 6);
  worst = 0.0;
  for (int32_t i = 0; i < n; ++i) worst = fmax(worst, fabs(x2[i] - x1[i]));
  CHECK(worst <= 1e-10 * scale);
done:
  sl_linsolve_destroy(ls);
  sl_constraints_free(&p.bc);
  sl_system_free(&p.s);
  free(x1), free(x2), free(b2);
}

int main(void) {
  sl_mesh *quads, *tris;
  sl_dofmap *q1;
  sl_th_space *th;
  sl_grid_opts o = {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK};
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 32, 32, NULL, &quads, NULL) == 0);
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 16, 16, &o, &tris, NULL) == 0);
  CHECK(sl_dofmap_create(quads, 1, &q1, NULL) == 0);
  CHECK(sl_th_create(tris, 2, &th, NULL) == 0);
  run("cholmod", q1, NULL);
  run("umfpack", q1, NULL);
  run("umfpack", NULL, th);
  run("klu", NULL, th);
  sl_th_destroy(th);
  sl_dofmap_destroy(q1);
  sl_mesh_destroy(tris);
  sl_mesh_destroy(quads);
  return sl_test_summary();
}
