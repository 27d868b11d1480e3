/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The flow operator's linearisations against its residual, on random
 * iterates, for every geometry: planar (2 and 3 components), triangles,
 * axisymmetric with swirl (off and on the axis), 1-D with an out-of-plane
 * component; with convection, a rotating frame, a time-derivative term,
 * variable density and a shear-thinning viscosity or a Newtonian one (the
 * element's fast paths):
 *  - Newton: J v equals the central difference of R along v to 1e-7;
 *  - Picard: R(u) - R(0) = J_P(u) u exactly (to round-off), since every
 *    term is the frozen-coefficient operator applied to u;
 *  - Newtonian without convection the two linearisations coincide. */
#include <stdint.h>

#include "core/assembly/flow.h"
#include "fe_study.h"
#include "testing.h"

static uint64_t rng = 88172645463325252ull;
static double uniform(void) {
  rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
  return (double)(rng >> 11) / 9007199254740992.0 * 2.0 - 1.0;
}

/* mu = 0.3 + 1/(1 + gamma^2) + 0.1 x: shear-thinning, strongly nonlinear near gamma = 1. */
static int shear_thinning(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) {
    double g = b->shear_rate[i], q = 1.0 + g * g;
    out[2 * i] = 0.3 + 1.0 / q + 0.1 * b->x[i][0];
    out[2 * i + 1] = -2.0 * g / (q * q);
  }
  return 0;
}

static int density(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  (void)user, (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = 1.0 + 0.5 * b->x[i][0] + 0.25 * b->x[i][1];
  return 0;
}

static int force(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  int nc = *(const int *)user;
  (void)d;
  for (int i = 0; i < b->n; ++i)
    for (int c = 0; c < nc; ++c) out[nc * i + c] = sin(b->x[i][0] + c) * cos(b->x[i][1] - c);
  return 0;
}

static int residual(sl_system *s, const sl_th_space *th, const double *u, const sl_flow_opts *o, double *r) {
  sl_system_zero(s);
  int rc = sl_assemble_flow(s, th, u, o, SL_FLOW_RESIDUAL, NULL);
  for (int32_t i = 0; i < th->n_dofs; ++i) r[i] = -s->b[i];
  return rc;
}

static double rel_diff(const double *a, const double *b, int32_t n) {
  double num = 0.0, den = 0.0;
  for (int32_t i = 0; i < n; ++i) num = fmax(num, fabs(a[i] - b[i])), den = fmax(den, fabs(b[i]));
  return num / den;
}

/* The velocity block alone (a split step's F, Newton) with swirl: its (z, theta) block, the z rows against the
 * theta columns, is zero unless the viscosity changes with the shear rate (the generalized-Newtonian term
 * 4 mu' gamma (Dhat:D(v)) (Dhat:D(dv)) couples every pair of components): the viscous term does not couple theta
 * with (r, z), the convection's hoop terms and the Coriolis force couple theta with r only, Newton's rho G(u) has
 * G_z,theta = 0 (core/models/navier_stokes/projection.c leaves the block out of F's pattern then). A pattern
 * without it (sl_system_init_kept) gives the same F v, to the bit (the terms left out are +0). */
static void check_ztheta(const char *name, const sl_th_space *th, const sl_flow_opts *o, const double *u,
                         const double *v, int newtonian) {
  sl_diag d = {{0}};
  int nc = th->mesh->n_cells, nb = th->vel->dofs_per_cell, nbv = 3 * nb;
  int32_t nv = th->p_offset, nvel = th->n_vel;
  int32_t *vd = malloc((size_t)nc * nbv * sizeof *vd);
  unsigned char *keep = malloc((size_t)nbv * nbv);
  double *y0 = malloc(nv * sizeof *y0), *y1 = malloc(nv * sizeof *y1);
  for (int c = 0; c < nc; ++c)
    for (int k = 0; k < nbv; ++k) vd[c * nbv + k] = th->cell_dofs[(size_t)c * th->dofs_per_cell + k];
  for (int a = 0; a < nbv; ++a)
    for (int b = 0; b < nbv; ++b) keep[a * nbv + b] = !(a / nb == 1 && b / nb == 2);
  sl_flow_opts ov = *o;
  ov.velocity_block = 1;
  sl_system full, kept;
  CHECK(sl_system_init(&full, nv, nc, nbv, vd, &d) == 0);
  CHECK_MSG(sl_system_init_kept(&kept, nv, nc, nbv, vd, keep, &d) == 0, "%s", d.msg);
  sl_system_zero(&full), sl_system_zero(&kept);
  CHECK(sl_assemble_flow(&full, th, u, &ov, SL_FLOW_NEWTON, &d) == 0);
  CHECK_MSG(sl_assemble_flow(&kept, th, u, &ov, SL_FLOW_NEWTON, &d) == 0, "%s", d.msg);
  double zt = 0.0, big = 0.0;
  for (int32_t i = 0; i < nv; ++i)
    for (int32_t p = full.A.row_ptr[i]; p < full.A.row_ptr[i + 1]; ++p) {
      double a = fabs(full.A.values[p]);
      big = fmax(big, a);
      if (i / nvel == 1 && full.A.col_idx[p] / nvel == 2) zt = fmax(zt, a);
    }
  sl_csr_matvec(&full.A, v, y0);
  sl_csr_matvec(&kept.A, v, y1);
  double dy = 0.0;
  for (int32_t i = 0; i < nv; ++i) dy = fmax(dy, fabs(y0[i] - y1[i]));
  printf(
      "%-34s (z, theta) block of F: max %.2e of %.2e; %d of %d entries kept, F v against the full pattern's "
      "%.2e\n",
      name, zt, big, (int)kept.A.nnz, (int)full.A.nnz, dy);
  if (newtonian) {
    CHECK_MSG(zt == 0.0, "%s: the (z, theta) block is %.3g, not zero", name, zt);
    CHECK_MSG(dy == 0.0, "%s: F v without the (z, theta) block differs by %.3g", name, dy);
    CHECK(9 * (full.A.nnz - kept.A.nnz) > full.A.nnz / 2); /* a block of nine (fewer where dofs are fixed) */
  } else {
    CHECK_MSG(zt > 1e-3 * big, "%s: the generalized-Newtonian (z, theta) block is %.3g", name, zt);
  }
  sl_system_free(&full), sl_system_free(&kept);
  free(vd), free(keep), free(y0), free(y1);
}

static void check_case(const char *name, sl_mesh *m, int n_comp, int axisymmetric, int newtonian, int convection,
                       double omega) {
  sl_diag d = {{0}};
  sl_th_space *th = NULL;
  sl_system s;
  int rc = sl_th_create(m, n_comp, &th, &d);
  CHECK_MSG(rc == 0, "%s: %s", name, d.msg);
  if (rc) return;
  int32_t n = th->n_dofs;
  rc = sl_system_init(&s, n, m->n_cells, th->dofs_per_cell, th->cell_dofs, &d);
  CHECK(rc == 0);
  double *u = malloc(n * sizeof *u), *v = malloc(n * sizeof *v), *h = malloc(n * sizeof *h);
  double *rp = malloc(n * sizeof *rp), *rm = malloc(n * sizeof *rm), *Jv = malloc(n * sizeof *Jv);
  double *w = malloc(n * sizeof *w), *z = calloc(n, sizeof *z);
  for (int32_t i = 0; i < n; ++i) u[i] = uniform(), v[i] = uniform(), h[i] = uniform();
  sl_flow_opts o = {.axisymmetric = axisymmetric,
                    .density = {density, NULL, 0.0},
                    .viscosity = newtonian ? NULL : shear_thinning,
                    .viscosity_value = 0.7,
                    .convection = convection,
                    .omega = omega,
                    .rotation_centre = {0.3, 0.1},
                    .body_force = force,
                    .body_force_user = &n_comp,
                    .mass_coef = 3.0,
                    .history = h};
  /* Newton: J v against the central difference of R. */
  sl_system_zero(&s);
  rc = sl_assemble_flow(&s, th, u, &o, SL_FLOW_NEWTON, &d);
  CHECK_MSG(rc == 0, "%s: %s", name, d.msg);
  sl_csr_matvec(&s.A, v, Jv);
  const double eps = 1e-6;
  for (int32_t i = 0; i < n; ++i) w[i] = u[i] + eps * v[i];
  CHECK(residual(&s, th, w, &o, rp) == 0);
  for (int32_t i = 0; i < n; ++i) w[i] = u[i] - eps * v[i];
  CHECK(residual(&s, th, w, &o, rm) == 0);
  for (int32_t i = 0; i < n; ++i) rp[i] = (rp[i] - rm[i]) / (2.0 * eps);
  double e_newton = rel_diff(Jv, rp, n);
  /* Picard: J_P(u) u = R(u) - R(0). */
  sl_system_zero(&s);
  CHECK(sl_assemble_flow(&s, th, u, &o, SL_FLOW_PICARD, &d) == 0);
  sl_csr_matvec(&s.A, u, Jv);
  CHECK(residual(&s, th, u, &o, rp) == 0);
  CHECK(residual(&s, th, z, &o, rm) == 0);
  for (int32_t i = 0; i < n; ++i) rp[i] -= rm[i];
  double e_picard = rel_diff(Jv, rp, n);
  printf("%-34s %6d dofs: Newton J v vs difference %.2e, Picard J_P u vs R(u) - R(0) %.2e\n", name, (int)n, e_newton,
         e_picard);
  CHECK_MSG(e_newton < 1e-7, "%s: Newton Jacobian off by %.3g", name, e_newton);
  CHECK_MSG(e_picard < 1e-12, "%s: Picard operator off by %.3g", name, e_picard);
  if (newtonian && !convection) {
    sl_system_zero(&s);
    CHECK(sl_assemble_flow(&s, th, u, &o, SL_FLOW_NEWTON, &d) == 0);
    sl_csr_matvec(&s.A, v, Jv);
    sl_system_zero(&s);
    CHECK(sl_assemble_flow(&s, th, u, &o, SL_FLOW_PICARD, &d) == 0);
    sl_csr_matvec(&s.A, v, rp);
    CHECK(rel_diff(Jv, rp, n) < 1e-14);
  }
  if (axisymmetric && n_comp == 3) check_ztheta(name, th, &o, u, v, newtonian);
  free(u), free(v), free(h), free(rp), free(rm), free(Jv), free(w), free(z);
  sl_system_free(&s);
  sl_th_destroy(th);
}

int main(void) {
  sl_diag d = {{0}};
  sl_mesh *quad = NULL, *tri = NULL, *ring = NULL, *axis = NULL, *line = NULL;
  sl_grid_opts t = {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK};
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 0.8, 3, 2, NULL, &quad, &d) == 0);
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 0.8, 2, 2, &t, &tri, &d) == 0);
  CHECK(sl_mesh_annulus(0.2, 1.0, 0.0, 1.0, 3, 2, NULL, &ring, &d) == 0);
  CHECK(sl_mesh_annulus(0.0, 1.0, 0.0, 1.0, 2, 2, &t, &axis, &d) == 0);
  CHECK(sl_mesh_interval(0.0, 1.0, 4, NULL, &line, &d) == 0);
  if (!quad || !tri || !ring || !axis || !line) return sl_test_summary();
  check_case("planar Q2/Q1, 2 comp", quad, 2, 0, 0, 1, 0.0);
  check_case("planar Q2/Q1, 2 comp, rotating", quad, 2, 0, 0, 1, 1.3);
  check_case("planar Q2/Q1, out-of-plane w", quad, 3, 0, 0, 1, 0.7);
  check_case("planar P2/P1, 2 comp", tri, 2, 0, 0, 1, 0.0);
  check_case("planar Q2/Q1 Newtonian Stokes", quad, 2, 0, 1, 0, 0.0);
  check_case("axisymmetric Q2/Q1 swirl", ring, 3, 1, 0, 1, 0.0);
  check_case("axisymmetric Q2/Q1 swirl, rotating", ring, 3, 1, 0, 1, 2.0);
  check_case("axisymmetric Q2/Q1 no swirl", ring, 2, 1, 0, 1, 0.0);
  check_case("axisymmetric P2/P1 on the axis", axis, 3, 1, 0, 1, 0.0);
  check_case("axisymmetric Newtonian Stokes", axis, 3, 1, 1, 0, 0.0);
  /* Newtonian with convection: the axisymmetric fast path of the element matrix (core/assembly/flow.c, axi_matrix),
     against the residual's general loop */
  check_case("axisymmetric Newtonian swirl", ring, 3, 1, 1, 1, 0.0);
  check_case("axisymmetric Newtonian swirl, rotating", ring, 3, 1, 1, 1, 2.0);
  check_case("axisymmetric Newtonian no swirl", ring, 2, 1, 1, 1, 0.0);
  check_case("axisymmetric Newtonian P2/P1 on the axis", axis, 3, 1, 1, 1, 0.0);
  check_case("1-D P2/P1 with out-of-plane w", line, 2, 0, 0, 1, 0.0);
  check_case("1-D P2/P1", line, 1, 0, 0, 1, 0.0);
  sl_mesh_destroy(quad), sl_mesh_destroy(tri), sl_mesh_destroy(ring), sl_mesh_destroy(axis), sl_mesh_destroy(line);
  return sl_test_summary();
}
