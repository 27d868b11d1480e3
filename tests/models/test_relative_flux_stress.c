/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The stress of the relative motion, -div[rho_f j_R j_R / (phi (1 - phi))]
 * (Nigam 1999 eq 2.16; [mixture] relative_flux_stress):
 *
 *  - its weak form: the flow's extra stress T, given in the pressure space,
 *    assembles int T : grad(v) (r dr dz axisymmetric, hoop entries
 *    included), which for every test function that vanishes on the boundary
 *    equals the body force -div T (Bird, Stewart & Lightfoot 2002, appendix
 *    A.7, the divergence of a symmetric tensor in cylindrical coordinates):
 *    compared for linear T on planar quadrilaterals and triangles, a line and
 *    an axisymmetric annulus, where both integrals are exact, to round-off;
 *  - a settling column at rest (1-D, planar, axisymmetric) with a suspension
 *    of phi = 0.2 below clear fluid: the stress is balanced by the pressure
 *    alone, so the velocity stays zero to round-off with and without it,
 *    and the pressure of the run with it differs from the run without by
 *    -T_h + const at every node, T_h the stress in the pressure space (the
 *    volume-weighted cell mean at each vertex), i.e. by exactly
 *    tau = rho_f phi u^2 / (1 - phi) between the suspension and the clear
 *    fluid, u the hindered settling velocity u_t (1 - phi)^n (1 - phi /
 *    phi_max) (Richardson & Zaki 1954 with its packing cut-off), u_t Stokes'
 *    (rho_s - rho_f) g d^2 / (18 mu);
 *  - a restarted run continues bit for bit: with the slip along g - Dj/Dt
 *    the stress depends on the last step's acceleration, which the
 *    checkpoint keeps (a tilted column, which moves);
 *  - the option without a settling closure is refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/flow.h"
#include "core/io/output.h"
#include "core/mesh/mesh.h"
#include "core/models/mixture/mixture.h"
#include "core/plugin/closure_ini.h"
#include "sluice/sluice.h"
#include "testing.h"

/* ---- the weak form against the divergence ------------------------------------ */

/* T(x) = A + B x + C y per entry (00, 11, 22, 01, 02, 12 of the frame). */
static const double coef_a[6] = {0.7, -0.4, 0.3, 0.25, -0.6, 0.45};
static const double coef_b[6] = {1.3, 0.2, -0.9, -0.5, 0.8, 0.35};
static const double coef_c[6] = {-0.3, 1.1, 0.6, 0.9, -0.2, -0.75};

typedef struct divergence_case {
  int dim, n_comp, axisymmetric;
} divergence_case;

/* f = -div T in the velocity's components: planar the plain divergence
 * (1-D: dT_00/dx alone); axisymmetric (r, z, theta)
 *   (div T)_r = dT_rr/dr + dT_rz/dz + (T_rr - T_tt)/r,
 *   (div T)_z = dT_rz/dr + dT_zz/dz + T_rz/r,
 *   (div T)_t = dT_rt/dr + dT_zt/dz + 2 T_rt/r   (BSL 2002, eq A.7-2, symmetric T). */
static int minus_divergence(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const divergence_case *k = user;
  (void)d;
  for (int q = 0; q < b->n; ++q) {
    double x = b->x[q][0], y = b->x[q][1], T[6];
    for (int e = 0; e < 6; ++e) T[e] = coef_a[e] + coef_b[e] * x + coef_c[e] * y;
    double div[3] = {coef_b[0] + coef_c[3], coef_b[3] + coef_c[1], coef_b[4] + coef_c[5]};
    if (k->dim == 1) div[0] = coef_b[0];
    if (k->axisymmetric) div[0] += (T[0] - T[2]) / x, div[1] += T[3] / x, div[2] += 2.0 * T[4] / x;
    for (int c = 0; c < k->n_comp; ++c) out[k->n_comp * q + c] = -div[c];
  }
  return 0;
}

static void weak_form_case(const char *name, sl_mesh *m, int n_comp, int axisymmetric) {
  sl_diag d = {{0}};
  sl_th_space *th = NULL;
  sl_system s;
  if (sl_th_create(m, n_comp, &th, &d) ||
      sl_system_init(&s, th->n_dofs, m->n_cells, th->dofs_per_cell, th->cell_dofs, &d)) {
    CHECK_MSG(0, "%s: %s", name, d.msg);
    sl_th_destroy(th);
    return;
  }
  int32_t n = th->n_dofs, np = th->pres->n_dofs;
  double *u = calloc((size_t)n, sizeof *u), *b_stress = malloc((size_t)n * sizeof *b_stress);
  double *T = malloc((size_t)6 * np * sizeof *T);
  if (!u || !b_stress || !T) {
    CHECK_MSG(0, "%s: out of memory", name);
  } else {
    for (int32_t i = 0; i < np; ++i) /* linear in x, y: the pressure space holds it exactly */
      for (int e = 0; e < 6; ++e)
        T[6 * i + e] = coef_a[e] + coef_b[e] * th->pres->xy[2 * i] + coef_c[e] * th->pres->xy[2 * i + 1];
    divergence_case k = {m->dim, n_comp, axisymmetric};
    sl_flow_opts o = {.axisymmetric = axisymmetric, .density = {NULL, NULL, 1.0}, .viscosity_value = 1.0};
    o.extra_stress = T;
    sl_system_zero(&s);
    int rc = sl_assemble_flow(&s, th, u, &o, SL_FLOW_RESIDUAL, &d);
    memcpy(b_stress, s.b, (size_t)n * sizeof *b_stress);
    o.extra_stress = NULL, o.body_force = minus_divergence, o.body_force_user = &k;
    sl_system_zero(&s);
    if (!rc) rc = sl_assemble_flow(&s, th, u, &o, SL_FLOW_RESIDUAL, &d);
    CHECK_MSG(rc == 0, "%s: %s", name, d.msg);
    /* velocity dofs off the boundary (the weak form adds T n there) and every pressure row */
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int v = 0; v < m->n_vertices; ++v) {
      xmin = fmin(xmin, m->xy[2 * v]), xmax = fmax(xmax, m->xy[2 * v]);
      ymin = fmin(ymin, m->xy[2 * v + 1]), ymax = fmax(ymax, m->xy[2 * v + 1]);
    }
    double diff = 0.0, scale = 0.0;
    int compared = 0;
    for (int c = 0; c < n_comp; ++c)
      for (int32_t i = 0; i < th->n_vel; ++i) {
        double x = th->vel->xy[2 * i], y = th->vel->xy[2 * i + 1];
        int inside = x > xmin + 1e-12 && x < xmax - 1e-12 && (m->dim == 1 || (y > ymin + 1e-12 && y < ymax - 1e-12));
        if (!inside) continue;
        int32_t k2 = sl_th_vel_dof(th, c, i);
        diff = fmax(diff, fabs(b_stress[k2] - s.b[k2])), scale = fmax(scale, fabs(s.b[k2]));
        ++compared;
      }
    for (int32_t i = th->p_offset; i < n; ++i) diff = fmax(diff, fabs(b_stress[i]) + fabs(s.b[i]));
    printf("%-36s int T : grad v against -int div T . v at %d interior dofs: %.2e of %.2e\n", name, compared, diff,
           scale);
    CHECK_MSG(compared > 0 && scale > 0.01, "%s: nothing compared", name);
    CHECK_MSG(diff <= 1e-13 * scale, "%s: the weak stress differs from its divergence by %.3g (scale %.3g)", name, diff,
              scale);
  }
  free(u), free(b_stress), free(T);
  sl_system_free(&s);
  sl_th_destroy(th);
}

static void weak_form(void) {
  sl_diag d = {{0}};
  sl_mesh *quad = NULL, *tri = NULL, *ring = NULL, *line = NULL;
  sl_grid_opts t = {.cell_type = SL_CELL_TRI3, .diagonal = SL_DIAGONAL_UNION_JACK};
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 0.8, 4, 3, NULL, &quad, &d) == 0);
  CHECK(sl_mesh_rectangle(0.0, 1.0, 0.0, 0.8, 3, 3, &t, &tri, &d) == 0);
  CHECK(sl_mesh_annulus(0.2, 1.0, 0.0, 1.0, 4, 3, NULL, &ring, &d) == 0);
  CHECK(sl_mesh_interval(0.0, 1.0, 5, NULL, &line, &d) == 0);
  if (quad && tri && ring && line) {
    weak_form_case("planar Q2/Q1, 2 components", quad, 2, 0);
    weak_form_case("planar Q2/Q1, out-of-plane w", quad, 3, 0);
    weak_form_case("planar P2/P1, 2 components", tri, 2, 0);
    weak_form_case("axisymmetric Q2/Q1 with swirl", ring, 3, 1);
    weak_form_case("axisymmetric Q2/Q1 without swirl", ring, 2, 1);
    weak_form_case("1-D P2/P1", line, 1, 0);
  }
  sl_mesh_destroy(quad), sl_mesh_destroy(tri), sl_mesh_destroy(ring), sl_mesh_destroy(line);
}

/* ---- a settling column at rest ------------------------------------------------- */

/* 1 mm spheres, 2650 in 1000 kg m^-3 water; phi = 0.2 below y = 0.5, clear above. */
static const double rho_f = 1000.0, rho_s = 2650.0, mu_f = 1e-3, grav = 9.81, diam = 1e-3;
static const double phi0 = 0.2, rz_n = 4.65, phi_max = 0.64, t_end = 0.01;

static const char *const column_text =
    "[scene]\nmodel = mixture\ngeometry = %s\n"
    "[mesh]\n%s\n"
    "[fluid]\ndensity = 1000\nviscosity = 1e-3\n"
    "[solid]\ndensity = 2650\ndiameter = 1e-3\n"
    "%s"
    "[flow]\ngravity = %s\nconvection = false\n"
    "[initial]\nphi = %s < 0.5 ? 0.2 : 0\n"
    "%s"
    "[transport]\norder = 1\n"
    "[time]\nscheme = bdf1\nend = 0.01\ndt = 0.01\nadaptive = false\n"
    "[output]\nevery = 0.01\n";
static const char *const settling_text =
    "[closure.hindered_settling]\nmodel = richardson_zaki\nn = 4.65\npacking_cutoff = true\nphi_max = 0.64\n";

typedef struct column {
  const char *name, *geometry, *mesh, *gravity, *height, *boundaries;
  double h; /* the cell height */
} column;

static const column columns[3] = {
    {"1-D", "line", "generator = interval\nx = 0, 1\ncells = 20", "-9.81", "x",
     "[boundary.left]\ntype = wall\n[boundary.right]\ntype = wall\n", 0.05},
    {"planar", "planar", "generator = rectangle\nx = 0, 0.4\ny = 0, 1\ncells = 2, 10", "0, -9.81", "y",
     "[boundary.left]\ntype = wall\n[boundary.right]\ntype = wall\n[boundary.bottom]\ntype = wall\n"
     "[boundary.top]\ntype = wall\n",
     0.1},
    {"axisymmetric", "axisymmetric", "generator = rectangle\nx = 0, 0.4\ny = 0, 1\ncells = 2, 10", "0, -9.81", "y",
     "[boundary.left]\ntype = axis\n[boundary.right]\ntype = wall\n[boundary.bottom]\ntype = wall\n"
     "[boundary.top]\ntype = wall\n",
     0.1},
};

/* Parses the scene text, applies the overrides `sets` (NULL-terminated; may
 * be NULL), validates it and runs it through the mixture model into `out`,
 * from the last checkpoint of `restart` (NULL: from the start). */
static int run_text(const char *text, const char *const *sets, const char *out, const char *restart, sl_diag *d) {
  sluice *s = NULL;
  sluice_error e = {0, ""};
  sluice_summary res;
  sluice_open_opts oo = {.sets = sets, .scan_all = 1};
  sluice_run_opts o = {.scene_path = "column.ini", .output = out, .restart = restart, .version = "test"};
  int rc = sluice_open_text(text, strlen(text), "column.ini", &oo, &s, &e);
  if (!rc) rc = sluice_run(s, &o, &res, &e);
  sluice_close(s);
  if (rc) sl_diag_set(d, rc, "%s", e.msg);
  return rc;
}

/* The field `name` at time t (n values of `components` each), or NULL. */
static double *field(const char *out, const char *name, double t, int32_t *n, int *components) {
  sl_output_field f;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, name, t, &f, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return NULL;
  }
  *n = f.n, *components = f.components;
  return f.values; /* the caller frees it */
}

static void column_case(const column *c) {
  char text[2048], outs[2][64];
  snprintf(text, sizeof text, column_text, c->geometry, c->mesh, settling_text, c->gravity, c->height, c->boundaries);
  const char *const with[] = {"mixture.relative_flux_stress=true", NULL};
  const char *const *sets[2] = {NULL, with};
  double *p[2] = {NULL, NULL}, umax = 0.0;
  int32_t np = -1;
  for (int k = 0; k < 2; ++k) {
    sl_diag d = {{0}};
    snprintf(outs[k], sizeof outs[k], "relative_flux_column_%s_%d.h5", c->geometry, k);
    if (run_text(text, sets[k], outs[k], NULL, &d)) {
      CHECK_MSG(0, "%s column: %s", c->name, d.msg);
      free(p[0]);
      return;
    }
    int32_t n, nu;
    int comp, ucomp;
    p[k] = field(outs[k], "pressure", t_end, &n, &comp);
    double *u = field(outs[k], "velocity", t_end, &nu, &ucomp);
    for (int32_t i = 0; u && i < nu * ucomp; ++i) umax = fmax(umax, fabs(u[i]));
    free(u);
    CHECK(np < 0 || n == np);
    np = n;
  }
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (!p[0] || !p[1] || sl_output_read_mesh(outs[1], &m, &d)) {
    CHECK_MSG(0, "%s column: %s", c->name, d.msg);
    free(p[0]), free(p[1]);
    return;
  }
  CHECK(m.n_vertices == np);
  /* the exact stress of the suspension, and the pressure space's T_h: the suspension's tau up to the
     last vertex below the interface at 0.5, the clear fluid's 0 from the first above, linear between
     (the vertex on the interface takes the mean of its cells, tau / 2) */
  double ut = (rho_s - rho_f) * grav * diam * diam / (18.0 * mu_f);
  double us = ut * pow(1.0 - phi0, rz_n) * (1.0 - phi0 / phi_max);
  double tau = rho_f * phi0 * us * us / (1.0 - phi0);
  int up = m.dim == 1 ? 0 : 1;
  double ref = NAN, worst = 0.0, jump_bottom = NAN, jump_top = NAN;
  for (int32_t i = 0; i < np; ++i) {
    double y = m.coords[3 * (size_t)i + up];
    double Th = tau * fmin(1.0, fmax(0.0, (0.5 + c->h - y) / (2.0 * c->h)));
    double rest = p[1][i] - p[0][i] + Th; /* constant where the pressure balances the stress */
    if (isnan(ref)) ref = rest;
    worst = fmax(worst, fabs(rest - ref));
    if (y < 1e-12) jump_bottom = p[1][i] - p[0][i];
    if (y > 1.0 - 1e-12) jump_top = p[1][i] - p[0][i];
  }
  double jump = jump_bottom - jump_top;
  printf(
      "%-12s column: |u| <= %.1e m/s (settling velocity %.4f m/s); p changes by %.10f Pa across the "
      "interface (-tau = %.10f), p - p0 + T_h constant within %.1e Pa\n",
      c->name, umax, us, jump, -tau, worst);
  CHECK_MSG(umax <= 1e-12 * us, "%s column: the stress set the mixture moving: |u| = %.3g", c->name, umax);
  CHECK_MSG(fabs(jump + tau) <= 1e-10 * tau,
            "%s column: the pressure changes by %.12g across the suspension, "
            "-tau = %.12g",
            c->name, jump, -tau);
  CHECK_MSG(worst <= 1e-10 * tau, "%s column: p - p0 + T_h varies by %.3g", c->name, worst);
  sl_output_mesh_free(&m);
  free(p[0]), free(p[1]);
}

/* The planar column tilted (gravity 0.3 off the vertical), so that it
 * overturns, with the slip along g - Dj/Dt: three steps in one run against
 * two and a restart for the third. */
static void restart(void) {
  char text[2048];
  const column *c = &columns[1];
  snprintf(text, sizeof text, column_text, c->geometry, c->mesh, settling_text, "3, -9.81", c->height, c->boundaries);
  const char *const whole[] = {"mixture.relative_flux_stress=true", "mixture.slip_acceleration=true", "time.end=0.03",
                               NULL};
  const char *const first[] = {"mixture.relative_flux_stress=true", "mixture.slip_acceleration=true", "time.end=0.02",
                               NULL};
  const char *outs[3] = {"relative_flux_whole.h5", "relative_flux_first.h5", "relative_flux_second.h5"};
  sl_diag d = {{0}};
  if (run_text(text, whole, outs[0], NULL, &d) || run_text(text, first, outs[1], NULL, &d) ||
      run_text(text, whole, outs[2], outs[1], &d)) {
    CHECK_MSG(0, "restart: %s", d.msg);
    return;
  }
  static const char *const names[3] = {"phi", "velocity", "pressure"};
  double moved = 0.0;
  for (int k = 0; k < 3; ++k) {
    int32_t na = 0, nb = 0;
    int ca = 0, cb = 0;
    double *a = field(outs[0], names[k], 0.03, &na, &ca), *b = field(outs[2], names[k], 0.03, &nb, &cb);
    double diff = 0.0;
    CHECK(a && b && na == nb && ca == cb);
    for (int32_t i = 0; a && b && na == nb && ca == cb && i < na * ca; ++i) {
      diff = fmax(diff, fabs(a[i] - b[i]));
      if (k == 1) moved = fmax(moved, fabs(a[i]));
    }
    printf("restart: %s of the restarted run differs by %.1e from the uninterrupted one\n", names[k], diff);
    CHECK_MSG(diff == 0.0, "restart: %s differs by %.3g", names[k], diff);
    free(a), free(b);
  }
  printf("restart: the tilted column moves at up to %.2e m/s\n", moved);
  CHECK_MSG(moved > 1e-6, "restart: the tilted column should move: |u| = %.3g", moved);
}

static void needs_settling(void) {
  char text[2048];
  const column *c = &columns[0];
  snprintf(text, sizeof text, column_text, c->geometry, c->mesh, "", c->gravity, c->height, c->boundaries);
  sl_diag d = {{0}};
  const char *const sets[] = {"mixture.relative_flux_stress=true", NULL};
  int rc = run_text(text, sets, "relative_flux_refused.h5", NULL, &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "relative_flux_stress") && strstr(d.msg, "hindered_settling"), "message: %s", d.msg);
}

int main(void) {
  weak_form();
  for (int k = 0; k < 3; ++k) column_case(&columns[k]);
  restart();
  needs_settling();
  return sl_test_summary();
}
