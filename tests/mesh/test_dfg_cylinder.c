/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The DFG benchmark 2D-1 (Schafer & Turek 1996, Re = 20), configs/dfg_2d1.ini
 * on a second-order mesh made by gmsh from configs/dfg_2d1.geo in the test
 * (the committed configs/dfg_2d1.msh when gmsh is not installed):
 *  - drag and lift coefficients from the navier_stokes model's boundary
 *    forces, c = 2 F / (rho U_mean^2 D) = 500 F, and the pressure
 *    difference p(0.15, 0.2) - p(0.25, 0.2), each inside the published
 *    interval: c_D in [5.57, 5.59], c_L in [0.0104, 0.0110],
 *    dp in [0.1172, 0.1176] (Schafer & Turek 1996, Table 3);
 *  - against the reference values computed on fine grids, c_D = 5.57953523384,
 *    c_L = 0.010618948146, dp = 0.11752016697 (John 2004, Table 3), the
 *    curved (isoparametric) mesh's drag is at least 10 times closer than that
 *    of the same mesh with straight sides (gmsh -order 1), whose polygonal
 *    cylinder is smaller than the circle;
 *  - the same geometry in 9-node quadrangles (Q2/Q1) inside the intervals, with linear = auto: UMFPACK
 *    (auto's choice with an optimised BLAS) calls its matrix singular, KLU takes over and the summary says so;
 *  - the forces' normalisation and sign, where they are known exactly: a
 *    channel and a pipe, periodic along the flow and driven by a body force
 *    f, hold the fluid against the walls alone, so the walls carry the whole
 *    load, f L H planar (half on each wall, the Poiseuille wall stress
 *    f H / 2 times L) and f pi R^2 L on the pipe's wall (axisymmetric: the
 *    2 pi of the revolution included). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../scenes/scene_runner.h"
#include "core/io/output.h"
#include "core/io/sample.h"
#include "core/util/blas.h"
#include "testing.h"

static const double CD_REF = 5.57953523384, CL_REF = 0.010618948146, DP_REF = 0.11752016697;

typedef struct dfg {
  double cd, cl, dp;
} dfg;

static int run(const char *configs, const char *mesh, const char *out, dfg *r) {
  char set[4200];
  snprintf(set, sizeof set, "mesh.file=%s", mesh);
  const char *sets[] = {set, NULL};
  scene_request q = {.configs = configs, .scene = "dfg_2d1", .sets = mesh ? sets : NULL, .out = out};
  sl_diag d = {{0}};
  sluice_summary sum;
  int rc = scene_run(&q, &sum, &d);
  CHECK_MSG(rc == 0, "dfg_2d1 (%s): %s", mesh ? mesh : "configs/dfg_2d1.msh", d.msg);
  if (rc) return rc;
  /* quadrangles, linear = auto: with an optimised BLAS auto chooses UMFPACK for this matrix (above 20 000 unknowns), whose
     pivot ratio (2.5e-19) calls this Q2/Q1 matrix singular; KLU takes over and solves it, and the summary says
     so (with the reference BLAS auto chooses KLU at once) */
  if (strstr(mesh ? mesh : "", "quad")) {
    printf("quads, linear = auto: %s\n", sum.linear_summary);
    const char *blas = sl_blas_description();
    int reference = !strncmp(blas, "reference", 9) || !strncmp(blas, "none", 4);
    if (!reference)
      CHECK_MSG(strncmp(sum.linear_summary, "umfpack found the matrix numerically singular (pivot ratio ", 59) == 0 &&
                    strstr(sum.linear_summary, "): klu took over; klu"),
                "quads: %s", sum.linear_summary);
    else CHECK_MSG(strncmp(sum.linear_summary, "klu", 3) == 0, "quads: %s", sum.linear_summary);
  }
  double fx, fy, t;
  rc = sl_output_read_scalar(out, "force_x_cylinder", INFINITY, &fx, &t, &d);
  if (!rc) rc = sl_output_read_scalar(out, "force_y_cylinder", INFINITY, &fy, &t, &d);
  CHECK_MSG(rc == 0, "%s: %s", out, d.msg);
  if (rc) return rc;
  /* rho = 1, U_mean = 2/3 U_m = 0.2, D = 0.1: 2 / (rho U_mean^2 D) = 500 */
  r->cd = 500 * fx, r->cl = 500 * fy;
  const double pts[4] = {0.15, 0.2, 0.25, 0.2};
  sl_sample s;
  rc = sl_sample_points(out, "pressure", INFINITY, 2, pts, &s, &d);
  CHECK_MSG(rc == 0, "%s: %s", out, d.msg);
  if (rc) return rc;
  r->dp = s.values[0] - s.values[s.components];
  sl_sample_free(&s);
  printf("%s: c_D %.6f (ref %.6f), c_L %.6f (ref %.6f), dp %.6f (ref %.6f)\n", mesh ? mesh : "configs/dfg_2d1.msh",
         r->cd, CD_REF, r->cl, CL_REF, r->dp, DP_REF);
  return 0;
}

/* A scene written into the working folder and run; the scalar `name` of its output. */
static double periodic_force(const char *scene, const char *text, const char *name) {
  char path[256];
  snprintf(path, sizeof path, "%s.ini", scene);
  FILE *f = fopen(path, "w");
  if (!f) return NAN;
  fputs(text, f);
  fclose(f);
  char out[256];
  snprintf(out, sizeof out, "%s.h5", scene);
  scene_request q = {.configs = ".", .scene = scene, .out = out};
  sl_diag d = {{0}};
  int rc = scene_run(&q, NULL, &d);
  CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);
  double v = NAN, t;
  if (!rc && sl_output_read_scalar(out, name, INFINITY, &v, &t, &d)) CHECK_MSG(0, "%s: %s", out, d.msg);
  return v;
}

static void force_balance(void) {
  const char *channel =
      "[scene]\nmodel = navier_stokes\ngeometry = planar\n"
      "[mesh]\ngenerator = rectangle\nx = 0, 1\ny = 0, 0.5\ncells = 6, 5\n"
      "[fluid]\ndensity = 1\nviscosity = 0.1\n[flow]\nconvection = false\nbody_force = 2, 0\n"
      "[boundary.left]\ntype = periodic\npartner = right\n"
      "[boundary.bottom]\nforce = true\n[boundary.top]\nforce = true\n";
  double fb = periodic_force("force_channel", channel, "force_x_bottom");
  double ft = periodic_force("force_channel", channel, "force_x_top");
  double fy = periodic_force("force_channel", channel, "force_y_bottom");
  printf("channel: force_x bottom %.15g, top %.15g (f L H / 2 = 0.5), force_y bottom %.3g\n", fb, ft, fy);
  CHECK_CLOSE(fb, 0.5, 1e-10);
  CHECK_CLOSE(ft, 0.5, 1e-10);
  CHECK(fabs(fy) < 1e-10);
  const char *pipe =
      "[scene]\nmodel = navier_stokes\ngeometry = axisymmetric\n"
      "[mesh]\ngenerator = annulus\nr = 0, 0.5\nz = 0, 2\ncells = 5, 4\n"
      "[fluid]\ndensity = 1\nviscosity = 0.1\n[flow]\nconvection = false\nbody_force = 0, 3\n"
      "[boundary.bottom]\ntype = periodic\npartner = top\n[boundary.outer]\nforce = true\n";
  double fz = periodic_force("force_pipe", pipe, "force_z_outer");
  const double exact = 3 * acos(-1.0) * 0.25 * 2;
  printf("pipe: force_z outer %.15g (f pi R^2 L = %.15g)\n", fz, exact);
  CHECK_CLOSE(fz, exact, 1e-10);
}

/* file in the working folder, as an absolute path (the scene resolves relative ones against configs/). */
static int getcwd_path(char *buf, size_t n, const char *file) {
  char cwd[4096];
  if (!getcwd(cwd, sizeof cwd)) return 0;
  snprintf(buf, n, "%s/%s", cwd, file);
  return 1;
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  char configs[4096];
  snprintf(configs, sizeof configs, "%s/configs", src ? src : "..");
  int have_gmsh = system("gmsh --version > /dev/null 2>&1") == 0;
  const char *curved = NULL;
  char cmd[8400];
  if (have_gmsh) {
    snprintf(cmd, sizeof cmd, "gmsh -2 -order 2 -format msh41 %s/dfg_2d1.geo -o dfg_p2.msh > dfg_p2.log 2>&1", configs);
    CHECK_MSG(system(cmd) == 0, "gmsh failed: see dfg_p2.log");
    curved = "dfg_p2.msh";
  } else {
    printf(
        "gmsh is not installed (Debian: apt-get install gmsh): the committed configs/dfg_2d1.msh is used and the "
        "straight-sided comparison is skipped\n");
  }
  char mesh[4200] = "";
  if (curved) {
    if (!getcwd_path(mesh, sizeof mesh, curved)) snprintf(mesh, sizeof mesh, "%s", curved);
  }
  force_balance();
  dfg a;
  if (run(configs, curved ? mesh : NULL, "dfg_p2.h5", &a)) return sl_test_summary();
  CHECK_MSG(a.cd >= 5.57 && a.cd <= 5.59, "c_D %.6f outside [5.57, 5.59]", a.cd);
  CHECK_MSG(a.cl >= 0.0104 && a.cl <= 0.0110, "c_L %.6f outside [0.0104, 0.0110]", a.cl);
  CHECK_MSG(a.dp >= 0.1172 && a.dp <= 0.1176, "dp %.6f outside [0.1172, 0.1176]", a.dp);
  if (have_gmsh) { /* the same geometry in 9-node quadrangles (Q2/Q1), all recombined */
    FILE *f = fopen("dfg_quad.geo", "w");
    if (f) {
      fprintf(f, "Merge \"%s/dfg_2d1.geo\";\nMesh.RecombineAll = 1;\nMesh.SubdivisionAlgorithm = 1;\n", configs);
      fclose(f);
    }
    CHECK_MSG(system("gmsh -2 -order 2 -format msh41 dfg_quad.geo -o dfg_quad.msh > dfg_quad.log 2>&1") == 0,
              "gmsh failed: see dfg_quad.log");
    dfg q;
    if (!getcwd_path(mesh, sizeof mesh, "dfg_quad.msh")) snprintf(mesh, sizeof mesh, "dfg_quad.msh");
    if (run(configs, mesh, "dfg_quad.h5", &q) == 0) {
      CHECK_MSG(q.cd >= 5.57 && q.cd <= 5.59, "quads: c_D %.6f outside [5.57, 5.59]", q.cd);
      CHECK_MSG(q.cl >= 0.0104 && q.cl <= 0.0110, "quads: c_L %.6f outside [0.0104, 0.0110]", q.cl);
      CHECK_MSG(q.dp >= 0.1172 && q.dp <= 0.1176, "quads: dp %.6f outside [0.1172, 0.1176]", q.dp);
    }
  }
  if (have_gmsh) {
    snprintf(cmd, sizeof cmd, "gmsh -2 -order 1 -format msh41 %s/dfg_2d1.geo -o dfg_p1.msh > dfg_p1.log 2>&1", configs);
    CHECK_MSG(system(cmd) == 0, "gmsh failed: see dfg_p1.log");
    dfg b;
    if (!getcwd_path(mesh, sizeof mesh, "dfg_p1.msh")) snprintf(mesh, sizeof mesh, "dfg_p1.msh");
    if (run(configs, mesh, "dfg_p1.h5", &b) == 0)
      CHECK_MSG(fabs(a.cd - CD_REF) * 10 < fabs(b.cd - CD_REF),
                "c_D error: curved %.2e, straight %.2e (the curved mesh should be 10 times closer)",
                fabs(a.cd - CD_REF), fabs(b.cd - CD_REF));
  }
  return sl_test_summary();
}
