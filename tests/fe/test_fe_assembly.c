/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Assembly unit checks: operator identities (constants and rigid motions in
 * the kernel, symmetry, load sums), skipped zero terms, batched callbacks
 * (shear rate input, errors and NaN refused), Dirichlet constraints, input
 * checks, and the 1-D Stokes path. */
#include "fe_study.h"
#include "testing.h"

static int is_symmetric(const sl_csr *A, double tol) {
  for (int32_t i = 0; i < A->n_rows; ++i)
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) {
      int32_t q = sl_csr_find(A, A->col_idx[p], i);
      if (q < 0 || fabs(A->values[p] - A->values[q]) > tol) return 0;
    }
  return 1;
}

static double max_abs(const double *v, int32_t n) {
  double m = 0.0;
  for (int32_t i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  return m;
}

static int variable_k(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = 1.0 + b->x[i][0] * b->x[i][1];
  return 0;
}

static void test_diffusion_identities(sl_cell_type cell, int order) {
  sl_grid_opts go = {.cell_type = cell};
  sl_mesh *m;
  sl_dofmap *dm;
  sl_system s;
  CHECK(sl_mesh_rectangle(1.0, 3.0, 0.0, 1.0, 5, 3, &go, &m, NULL) == 0);
  CHECK(sl_dofmap_create(m, order, &dm, NULL) == 0);
  CHECK(sl_system_init(&s, dm->n_dofs, m->n_cells, dm->dofs_per_cell, dm->cell_dofs, NULL) == 0);
  for (int axi = 0; axi <= 1; ++axi) {
    sl_system_zero(&s);
    sl_diffusion_opts o = {.diffusivity = {variable_k, NULL, 0.0}, .source = {NULL, NULL, 2.0}, .axisymmetric = axi};
    CHECK(sl_assemble_diffusion(&s, dm, &o, NULL) == 0);
    double *one = malloc((size_t)dm->n_dofs * sizeof *one), *y = malloc((size_t)dm->n_dofs * sizeof *y), sum = 0.0;
    for (int32_t i = 0; i < dm->n_dofs; ++i) one[i] = 1.0, sum += s.b[i];
    sl_csr_matvec(&s.A, one, y);
    CHECK_MSG(max_abs(y, dm->n_dofs) < 1e-12, "A 1 = %g", max_abs(y, dm->n_dofs)); /* constants in the kernel */
    CHECK(is_symmetric(&s.A, 1e-14));
    CHECK_CLOSE(sum, axi ? 8.0 : 4.0, 1e-13); /* int 2 dA = 4; int 2 r dr dz = (9 - 1) = 8 */
    free(one), free(y);
  }
  /* A zero source is not assembled; with a zero diffusivity too, nothing is. */
  sl_system_zero(&s);
  uint64_t gen = s.A.values_gen;
  sl_diffusion_opts none = {.diffusivity = {NULL, NULL, 0.0}, .source = {NULL, NULL, 0.0}};
  CHECK(sl_assemble_diffusion(&s, dm, &none, NULL) == 0 && s.A.values_gen == gen);
  sl_diffusion_opts k_only = {.diffusivity = {NULL, NULL, 1.0}};
  CHECK(sl_assemble_diffusion(&s, dm, &k_only, NULL) == 0 && max_abs(s.b, s.n_dofs) == 0.0);
  sl_system_free(&s);
  sl_dofmap_destroy(dm);
  sl_mesh_destroy(m);
}

/* Rigid motions u = (1, 0), (0, 1), (-y, x) have D(u) = 0: A u = 0. */
static void rigid(void *user, const double x[2], double *v, double g[2]) {
  int k = *(const int *)user;
  (void)g;
  if (k < 2) *v = k == 0 ? 1.0 : 0.0;
  else if (k == 2) *v = -x[1]; /* x component of the rotation */
  else *v = x[0];              /* its y component */
}

static void test_stokes_identities(sl_cell_type cell) {
  sl_grid_opts go = {.cell_type = cell, .diagonal = SL_DIAGONAL_LEFT};
  sl_mesh *m;
  sl_th_space *th;
  sl_system s;
  CHECK(sl_mesh_inclined_box(0.3, 0.1, 1.5, 1.0, 0.4, 4, 3, &go, &m, NULL) == 0);
  CHECK(sl_th_create(m, 2, &th, NULL) == 0);
  CHECK(sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, NULL) == 0);
  sl_stokes_opts o = {.viscosity = {variable_k, NULL, 0.0}};
  CHECK(sl_assemble_stokes(&s, th, &o, NULL) == 0);
  CHECK(is_symmetric(&s.A, 1e-13));
  double *u = calloc((size_t)th->n_dofs, sizeof *u), *y = malloc((size_t)th->n_dofs * sizeof *y);
  const int motions[3][2] = {{0, 1}, {1, 0}, {2, 3}}; /* (x comp, y comp) selectors */
  for (int k = 0; k < 3; ++k) {
    sl_fe_interpolate(th->vel, rigid, (void *)&motions[k][0], u);
    sl_fe_interpolate(th->vel, rigid, (void *)&motions[k][1], u + th->n_vel);
    sl_csr_matvec(&s.A, u, y);
    CHECK_MSG(max_abs(y, th->p_offset) < 1e-12, "rigid motion %d: |A u| = %g", k, max_abs(y, th->p_offset));
    /* Divergence-free: the pressure rows of B u vanish too. */
    CHECK(max_abs(y + th->p_offset, th->pres->n_dofs) < 1e-12);
  }
  /* u = (x, 0): div u = 1, so sum_k (B u)_k = -area. */
  for (int32_t i = 0; i < th->n_vel; ++i) u[i] = th->vel->xy[2 * i], u[th->n_vel + i] = 0.0;
  sl_csr_matvec(&s.A, u, y);
  double sum = 0.0;
  for (int32_t k = 0; k < th->pres->n_dofs; ++k) sum += y[th->p_offset + k];
  CHECK_CLOSE(sum, -1.5, 1e-12);
  free(u), free(y);
  sl_system_free(&s);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

/* ---- callbacks --------------------------------------------------------- */

typedef struct probe {
  int mode; /* 0: record shear rates, 1: fail, 2: NaN */
  double min_rate, max_rate;
} probe;

static int probing_viscosity(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  probe *p = user;
  if (p->mode == 1) return sl_diag_set(d, SL_EFAILED, "outside my validity at phi = 0.7");
  for (int i = 0; i < b->n; ++i) {
    out[i] = p->mode == 2 && i == 3 ? NAN : 1.0;
    if (b->shear_rate)
      p->min_rate = fmin(p->min_rate, b->shear_rate[i]), p->max_rate = fmax(p->max_rate, b->shear_rate[i]);
  }
  return 0;
}

static void test_callbacks(void) {
  sl_mesh *m;
  sl_th_space *th;
  sl_system s;
  sl_diag d;
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 3, 3, NULL, &m, NULL) == 0);
  CHECK(sl_th_create(m, 2, &th, NULL) == 0);
  CHECK(sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, NULL) == 0);
  /* Simple shear u = (2 y, 0): shear rate sqrt(2 D:D) = 2 everywhere. */
  double *u = calloc((size_t)th->n_dofs, sizeof *u);
  for (int32_t i = 0; i < th->n_vel; ++i) u[i] = 2.0 * th->vel->xy[2 * i + 1];
  probe p = {0, INFINITY, -INFINITY};
  sl_stokes_opts o = {.viscosity = {probing_viscosity, &p, 0.0}, .velocity = u};
  CHECK(sl_assemble_stokes(&s, th, &o, NULL) == 0);
  CHECK_CLOSE(p.min_rate, 2.0, 1e-12);
  CHECK_CLOSE(p.max_rate, 2.0, 1e-12);
  p.mode = 1;
  CHECK(sl_assemble_stokes(&s, th, &o, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "assembly: viscosity: outside my validity");
  p.mode = 2;
  CHECK(sl_assemble_stokes(&s, th, &o, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "viscosity is nan at (");
  /* Inputs that do not fit. */
  sl_th_space *swirl;
  CHECK(sl_th_create(m, 3, &swirl, NULL) == 0);
  CHECK(sl_assemble_stokes(&s, swirl, &o, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "3 velocity components");
  sl_th_destroy(swirl);
  sl_diffusion_opts dopt = {.diffusivity = {NULL, NULL, 1.0}};
  CHECK(sl_assemble_diffusion(&s, th->pres, &dopt, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "not built from this dof map");
  free(u);
  sl_system_free(&s);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

/* ---- constraints ------------------------------------------------------- */

static void test_constraints(void) {
  sl_mesh *m;
  sl_dofmap *dm;
  sl_system s;
  sl_constraints bc;
  sl_diag d;
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 1.0, 2, 2, NULL, &m, NULL) == 0);
  CHECK(sl_dofmap_create(m, 2, &dm, NULL) == 0);
  CHECK(sl_system_init(&s, dm->n_dofs, m->n_cells, dm->dofs_per_cell, dm->cell_dofs, NULL) == 0);
  CHECK(sl_constraints_init(&bc, dm->n_dofs, NULL) == 0);
  CHECK(sl_constraints_fix_boundary(&bc, dm, "top", 0, NULL, NULL, 1.0, NULL) == 0);
  CHECK(bc.n_fixed == 5);
  CHECK(sl_constraints_fix_boundary(&bc, dm, "left", 0, NULL, NULL, 0.0, NULL) == 0);
  CHECK(bc.n_fixed == 9); /* the top-left corner is shared */
  int32_t corner = -1;
  for (int32_t i = 0; i < dm->n_dofs; ++i)
    if (dm->xy[2 * i] == 0.0 && dm->xy[2 * i + 1] == 1.0) corner = i;
  CHECK(corner >= 0 && bc.value[corner] == 0.0); /* the later call wins */
  double *u = calloc((size_t)dm->n_dofs, sizeof *u);
  sl_constraints_impose(&bc, u);
  double top_mid = 0.0;
  for (int32_t i = 0; i < dm->n_dofs; ++i)
    if (dm->xy[2 * i] == 0.5 && dm->xy[2 * i + 1] == 1.0) top_mid = u[i];
  CHECK(top_mid == 1.0);
  /* Applied to a Laplacian: the solution holds the values exactly. */
  sl_diffusion_opts o = {.diffusivity = {NULL, NULL, 1.0}};
  CHECK(sl_assemble_diffusion(&s, dm, &o, NULL) == 0);
  CHECK(sl_constraints_fix_boundary(&bc, dm, "bottom", 0, NULL, NULL, 0.0, NULL) == 0);
  CHECK(sl_constraints_fix_boundary(&bc, dm, "right", 0, NULL, NULL, 0.0, NULL) == 0);
  CHECK(sl_constraints_apply(&bc, &s, 1, NULL) == 0);
  CHECK(is_symmetric(&s.A, 0.0));
  sl_linsolve *ls;
  CHECK(sl_linsolve_create(&ls, "cholmod", NULL) == 0);
  CHECK(sl_linsolve_solve(ls, &s.A, s.b, u, NULL) == 0);
  int held = 1;
  for (int32_t i = 0; i < dm->n_dofs; ++i)
    if (bc.fixed[i]) held &= u[i] == bc.value[i];
  CHECK(held);
  sl_linsolve_destroy(ls);
  CHECK(sl_constraints_fix_boundary(&bc, dm, "lid", 0, NULL, NULL, 1.0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "lid");
  CHECK(sl_constraints_fix_boundary(&bc, dm, "top", 3, NULL, NULL, 1.0, &d) == SL_EBADINPUT);
  sl_constraints small;
  CHECK(sl_constraints_init(&small, 3, NULL) == 0);
  CHECK(sl_constraints_apply(&small, &s, 1, &d) == SL_EBADINPUT);
  sl_constraints_free(&small);
  free(u);
  sl_constraints_free(&bc);
  sl_system_free(&s);
  sl_dofmap_destroy(dm);
  sl_mesh_destroy(m);
}

/* ---- 1-D Stokes -------------------------------------------------------- */

/* A column: u = 0 at both ends of [0, 2], body force f = 3. div u = 0
 * forces u = 0, and the pressure balances the force: p = 3 (x - 1) with
 * zero mean, linear, so the P1 pressure is exact. */
static int column_force(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = 3.0;
  return 0;
}

static void test_stokes_1d(void) {
  sl_mesh *m;
  sl_th_space *th;
  sl_system s;
  sl_constraints bc;
  sl_linsolve *ls;
  CHECK(sl_mesh_interval(0.0, 2.0, 6, NULL, &m, NULL) == 0);
  CHECK(sl_th_create(m, 1, &th, NULL) == 0);
  CHECK(th->dofs_per_cell == 3 + 2);
  CHECK(sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, NULL) == 0);
  CHECK(sl_constraints_init(&bc, th->n_dofs, NULL) == 0);
  sl_stokes_opts o = {.viscosity = {NULL, NULL, 0.5}, .body_force = column_force};
  CHECK(sl_assemble_stokes(&s, th, &o, NULL) == 0);
  CHECK(sl_constraints_fix_boundary(&bc, th->vel, "left", 0, NULL, NULL, 0.0, NULL) == 0);
  CHECK(sl_constraints_fix_boundary(&bc, th->vel, "right", 0, NULL, NULL, 0.0, NULL) == 0);
  sl_stokes_fix_pressure_datum(&bc, th);
  CHECK(sl_constraints_apply(&bc, &s, 1, NULL) == 0);
  double *x = calloc((size_t)th->n_dofs, sizeof *x);
  CHECK(sl_linsolve_create(&ls, "umfpack", NULL) == 0);
  CHECK(sl_linsolve_solve(ls, &s.A, s.b, x, NULL) == 0);
  CHECK(sl_stokes_zero_mean_pressure(th, x, NULL) == 0);
  CHECK(max_abs(x, th->p_offset) < 1e-12);
  double worst = 0.0; /* p = 3 (x - 1): linear, so exact */
  for (int32_t i = 0; i < th->pres->n_dofs; ++i)
    worst = fmax(worst, fabs(x[th->p_offset + i] - 3.0 * (th->pres->xy[2 * i] - 1.0)));
  CHECK_MSG(worst < 1e-11, "1-D Stokes pressure off by %g", worst);
  sl_linsolve_destroy(ls);
  free(x);
  sl_constraints_free(&bc);
  sl_system_free(&s);
  sl_th_destroy(th);
  sl_mesh_destroy(m);
}

int main(void) {
  test_diffusion_identities(SL_CELL_QUAD4, 1);
  test_diffusion_identities(SL_CELL_QUAD4, 2);
  test_diffusion_identities(SL_CELL_TRI3, 1);
  test_diffusion_identities(SL_CELL_TRI3, 2);
  test_stokes_identities(SL_CELL_QUAD4);
  test_stokes_identities(SL_CELL_TRI3);
  test_callbacks();
  test_constraints();
  test_stokes_1d();
  return sl_test_summary();
}
