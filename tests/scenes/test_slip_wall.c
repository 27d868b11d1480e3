/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Free-slip walls on curved boundaries ([boundary.NAME] type = slip on a
 * boundary not along x or y: core/assembly/slip.h) on an annulus
 * R1 = 0.5 < r < R2 = 1 that the test writes as a Gmsh file, with straight
 * (Q4) or curved (Q9, second-order geometry) quadrilaterals:
 *  - normals: the node normals radial (planar), and the discrete flux of a
 *    velocity made tangent zero to round-off, planar and axisymmetric;
 *  - rotation: rigid-body rotation u = (-y, x) between two slip walls is a
 *    transient Stokes flow with no stress anywhere (D(u) = 0): it must stay
 *    so to round-off, with no flow through either wall (u . r/|r| = 0 at
 *    every wall node), on both meshes, monolithic and with the projection
 *    step; bad input: a curved slip wall with linear = petsc (exit 2);
 *  - couette: steady Stokes flow between a no-slip inner wall at rest and a
 *    free-slip outer wall, driven by the azimuthal body force f = (-y, x)
 *    (f_theta = r), mu = 1:
 *      u_theta = -r^3/8 + A r + B/r,  B = -R2^4/8,  A = R1^2/8 + R2^4/(8 R1^2)
 *    (mu (u'' + u'/r - u/r^2) = -r; u(R1) = 0; zero shear stress
 *    r d/dr(u/r) = 0 at R2, the free-slip condition with its curvature
 *    term: a wall with du/dr = 0 instead would give another profile). The
 *    largest nodal velocity error on 32 x 4, 64 x 8, 128 x 16 cells, and its
 *    observed order: at least 1.9 on straight cells (the polygon's O(h^2)
 *    geometry), at least 3.5 on curved cells (measured 2.00, 2.00 and 3.74, 3.86);
 *  - shell: axisymmetric, both spheres of a spherical shell free-slip walls
 *    (curved, meeting the axis at corners), in a frame turning at Omega: the
 *    rigid counter-rotation u_theta = -2 Omega r stays exact to round-off
 *    (velocity, no flux through the spheres, p = rho Omega^2 r^2/2 + const at
 *    the vertices), straight and curved cells, the monolithic step. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/slip.h"
#include "core/io/output.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096] = ".";
SCENE_RUNNERS()

static const double R1 = 0.5, R2 = 1.0;

/* The annulus R1 < r < R2 about (cx, 0) in nt x nr quadrilaterals, Gmsh MSH 2.2 ASCII; order 2: 9-node cells
 * with their nodes on the circles (second-order geometry). Physical groups: the curves "inner" and "outer", the
 * surface "ring". shell: only its half x >= 0 (cx = 0), the meridian of the spherical shell R1 < rho < R2 of an
 * axisymmetric scene (x = r, y = z), the polar angle phi in [-pi/2, pi/2] from the equator, and the curve
 * "axis" (the two segments of r = 0) besides; the surface is "shell". */
static int write_polar(const char *path, int nt, int nr, int order, double cx, int shell) {
  FILE *f = fopen(path, "w");
  if (!f) return 1;
  int o = order, NI = o * nt + (shell ? 1 : 0), NJ = o * nr + 1; /* the lattice of nodes, periodic in I if a ring */
  int surface = shell ? 4 : 3;
  if (shell)
    fprintf(f,
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n1 1 \"inner\"\n1 2 \"outer\"\n1 3 "
            "\"axis\"\n2 4 \"shell\"\n$EndPhysicalNames\n$Nodes\n%d\n",
            NI * NJ);
  else
    fprintf(f,
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 1 \"inner\"\n1 2 \"outer\"\n2 3 "
            "\"ring\"\n$EndPhysicalNames\n$Nodes\n%d\n",
            NI * NJ);
  for (int J = 0; J < NJ; ++J)
    for (int I = 0; I < NI; ++I) {
      double r = R1 + (R2 - R1) * J / (NJ - 1), x, y;
      if (shell) { /* the axis's nodes exactly on x = 0 */
        double ph = -M_PI / 2 + M_PI * I / (NI - 1);
        x = I == 0 || I == NI - 1 ? 0.0 : r * cos(ph), y = I == 0 ? -r : I == NI - 1 ? r : r * sin(ph);
      } else {
        double th = 2 * M_PI * I / NI;
        x = cx + r * cos(th), y = r * sin(th);
      }
      fprintf(f, "%d %.17g %.17g 0\n", 1 + J * NI + I, x, y);
    }
#define ND(I, J) (1 + (J)*NI + ((I) % NI))
  fprintf(f, "$EndNodes\n$Elements\n%d\n", 2 * nt + (shell ? 2 * nr : 0) + nt * nr);
  int e = 0;
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < nt; ++i) {
      int J = side ? NJ - 1 : 0;
      if (order == 1) fprintf(f, "%d 1 2 %d %d %d %d\n", ++e, side + 1, side + 1, ND(i, J), ND(i + 1, J));
      else
        fprintf(f, "%d 8 2 %d %d %d %d %d\n", ++e, side + 1, side + 1, ND(o * i, J), ND(o * i + o, J),
                ND(o * i + 1, J));
    }
  for (int end = 0; shell && end < 2; ++end)
    for (int j = 0; j < nr; ++j) {
      int I = end ? NI - 1 : 0;
      if (order == 1) fprintf(f, "%d 1 2 3 3 %d %d\n", ++e, ND(I, j), ND(I, j + 1));
      else fprintf(f, "%d 8 2 3 3 %d %d %d\n", ++e, ND(I, o * j), ND(I, o * j + o), ND(I, o * j + 1));
    }
  for (int j = 0; j < nr; ++j)
    for (int i = 0; i < nt; ++i) { /* counter-clockwise: outward in r, then on in theta */
      int I = o * i, J = o * j;
      if (order == 1) {
        fprintf(f, "%d 3 2 %d %d %d %d %d %d\n", ++e, surface, surface, ND(I, J), ND(I, J + 1), ND(I + 1, J + 1),
                ND(I + 1, J));
      } else {
        fprintf(f, "%d 10 2 %d %d %d %d %d %d %d %d %d %d %d\n", ++e, surface, surface, ND(I, J), ND(I, J + 2),
                ND(I + 2, J + 2), ND(I + 2, J), ND(I, J + 1), ND(I + 1, J + 2), ND(I + 2, J + 1), ND(I + 1, J),
                ND(I + 1, J + 1));
      }
    }
#undef ND
  fprintf(f, "$EndElements\n");
  return fclose(f) != 0;
}

static int write_annulus_at(const char *path, int nt, int nr, int order, double cx) {
  return write_polar(path, nt, nr, order, cx, 0);
}

static int write_annulus(const char *path, int nt, int nr, int order) {
  return write_annulus_at(path, nt, nr, order, 0.0);
}

static int write_text(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  if (!f) return 1;
  fputs(text, f);
  return fclose(f) != 0;
}

/* The largest |u - exact| over the velocity nodes of the output at time t, against the largest |exact|, and the
 * largest |u . r/|r|| at the wall nodes (r = R1 or R2 to 1e-9). */
static int node_errors(const char *out, double t, void (*exact)(double, double, double *), double *err, double *scale,
                       double *normal) {
  sl_output_mesh m;
  sl_output_field fu;
  sl_diag d = {{0}};
  if (sl_output_read_mesh(out, &m, &d) || sl_output_read_field(out, "velocity", t, &fu, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  *err = *scale = *normal = 0.0;
  for (int32_t i = 0; i < m.n_vertices; ++i) {
    double x = m.coords[3 * i], y = m.coords[3 * i + 1], ue[2], r = hypot(x, y);
    const double *u = fu.values + 3 * (size_t)i;
    exact(x, y, ue);
    *err = fmax(*err, hypot(u[0] - ue[0], u[1] - ue[1]));
    *scale = fmax(*scale, hypot(ue[0], ue[1]));
    if (fabs(r - R1) < 1e-9 || fabs(r - R2) < 1e-9) *normal = fmax(*normal, fabs(u[0] * x + u[1] * y) / r);
  }
  sl_output_mesh_free(&m);
  sl_output_field_free(&fu);
  return 0;
}

static void rigid(double x, double y, double *u) { u[0] = -y, u[1] = x; }

static const char *const ROTATION_INI =
    "; rigid-body rotation between two free-slip walls (tests/scenes/test_slip_wall.c)\n"
    "[scene]\nmodel = navier_stokes\ngeometry = planar\n"
    "[mesh]\ngenerator = gmsh\nfile = slip_annulus.msh\n"
    "[fluid]\ndensity = 1\nviscosity = 0.1\n"
    "[flow]\nconvection = false\n"
    "[initial]\nvelocity = -y, x\n"
    "[boundary.inner]\ntype = slip\n[boundary.outer]\ntype = slip\n"
    "[time]\nscheme = bdf2\nend = 1\ndt = 0.125\nadaptive = false\n"
    "[output]\nfields = velocity, pressure\n";

static void rotation(void) {
  if (write_text("slip_rotation.ini", ROTATION_INI)) {
    CHECK_MSG(0, "cannot write slip_rotation.ini");
    return;
  }
  for (int order = 1; order <= 2; ++order)
    for (int scheme = 0; scheme < 2; ++scheme) {
      if (write_annulus("slip_annulus.msh", 32, 4, order)) {
        CHECK_MSG(0, "cannot write the mesh");
        return;
      }
      const char *sets[] = {scheme ? "flow.scheme=projection" : "flow.scheme=monolithic", NULL};
      if (run_ok("slip_rotation", NULL, NULL, sets, "slip_rotation.h5")) return;
      double e, s, un;
      if (node_errors("slip_rotation.h5", 1.0, rigid, &e, &s, &un)) return;
      printf(
          "rigid rotation, %s cells, %s, t = 1: largest velocity error %.2e of %.3f, largest u.n at the walls "
          "%.2e\n",
          order == 1 ? "straight" : "curved", scheme ? "projection" : "monolithic", e, s, un);
      CHECK_MSG(e < 1e-12 * s && un < 1e-12 * s, "error %.3e, u.n %.3e", e, un);
    }
  /* PETSc's field split reads the rows as assembled: refused, before anything is written */
  const char *bad[] = {"solver.linear=petsc", NULL};
  sl_diag d = {{0}};
  remove("slip_rotation_bad.h5");
  int rc = run_scene("slip_rotation", NULL, NULL, bad, "slip_rotation_bad.h5", &d);
  FILE *f = fopen("slip_rotation_bad.h5", "rb");
  CHECK_MSG(rc == SL_EBADINPUT && !f, "rc %d: %s", rc, d.msg);
  if (f) fclose(f);
  printf("linear = petsc: %s\n", d.msg);
}

static double couette_u(double r) {
  double B = -pow(R2, 4) / 8, A = R1 * R1 / 8 + pow(R2, 4) / (8 * R1 * R1);
  return -r * r * r / 8 + A * r + B / r;
}

static void couette(double x, double y, double *u) {
  double r = hypot(x, y), ut = couette_u(r);
  u[0] = -ut * y / r, u[1] = ut * x / r;
}

static const char *const COUETTE_INI =
    "; Stokes flow between a wall at rest (r = 0.5) and a free-slip wall (r = 1) driven by f_theta = r\n"
    "; (tests/scenes/test_slip_wall.c: u_theta = -r^3/8 + A r + B/r)\n"
    "[scene]\nmodel = navier_stokes\ngeometry = planar\n"
    "[mesh]\ngenerator = gmsh\nfile = slip_couette.msh\n"
    "[fluid]\ndensity = 1\nviscosity = 1\n"
    "[flow]\nconvection = false\nbody_force = -y, x\n"
    "[boundary.inner]\ntype = wall\n[boundary.outer]\ntype = slip\n"
    "[time]\nscheme = steady\n"
    "[output]\nfields = velocity\n";

static void couette_order(void) {
  if (write_text("slip_couette.ini", COUETTE_INI)) {
    CHECK_MSG(0, "cannot write slip_couette.ini");
    return;
  }
  printf("exact: u_theta(R2) = %.6f\n", couette_u(R2));
  for (int order = 1; order <= 2; ++order) {
    double e[3], s = 0.0, un = 0.0;
    for (int k = 0; k < 3; ++k) {
      int nt = 32 << k, nr = 4 << k;
      if (write_annulus("slip_couette.msh", nt, nr, order)) {
        CHECK_MSG(0, "cannot write the mesh");
        return;
      }
      if (run_ok("slip_couette", NULL, NULL, NULL, "slip_couette.h5")) return;
      if (node_errors("slip_couette.h5", 0.0, couette, &e[k], &s, &un)) return;
      printf("couette, %s cells, %d x %d: largest nodal error %.3e (of %.4f), largest u.n at the walls %.1e%s\n",
             order == 1 ? "straight" : "curved", nt, nr, e[k], s, un, k ? "" : "");
      if (k) printf("  observed order %.3f\n", log2(e[k - 1] / e[k]));
      CHECK_MSG(un < 1e-12 * s, "u.n %.3e at the walls", un);
    }
    double p1 = log2(e[0] / e[1]), p2 = log2(e[1] / e[2]), want = order == 1 ? 1.9 : 3.5;
    CHECK_MSG(p1 > want && p2 > want, "%s cells: orders %.3f, %.3f (want > %.1f)", order == 1 ? "straight" : "curved",
              p1, p2, want);
    CHECK_MSG(e[2] < (order == 1 ? 1e-3 : 1e-5) * s, "finest error %.3e", e[2]);
  }
}

/* The node normals of slip.h on both circles of the annulus: planar, the vertex and midpoint normals are radial
 * (the boundary's nodes are evenly spaced: each node's two faces mirror each other), on straight and curved
 * cells; and for any velocity made tangent by sl_slip_impose the discrete flux int u.n w ds through the walls is
 * zero to round-off, planar (w = 1) and axisymmetric (w = r, the annulus centred at r = 3), while the same
 * velocity before imposing has a flux of its own size. */
static void normals(void) {
  for (int axi = 0; axi < 2; ++axi)
    for (int order = 1; order <= 2; ++order) {
      double cx = axi ? 3.0 : 0.0;
      if (write_annulus_at("slip_normals.msh", 24, 3, order, cx)) {
        CHECK_MSG(0, "cannot write the mesh");
        return;
      }
      sl_diag d = {{0}};
      sl_mesh *m = NULL;
      sl_th_space *th = NULL;
      sl_constraints bc = {0};
      sl_slip sl = {0};
      int ids[2];
      double *u = NULL;
      if (sl_mesh_read_gmsh("slip_normals.msh", &m, &d) || sl_th_create(m, 2, &th, &d) ||
          sl_mesh_boundary_id(m, "inner", &ids[0], &d) || sl_mesh_boundary_id(m, "outer", &ids[1], &d) ||
          sl_constraints_init(&bc, th->n_dofs, &d) || sl_slip_create(&sl, th, ids, 2, NULL, 0, axi, &bc, &d) ||
          !(u = malloc((size_t)th->n_dofs * sizeof *u))) {
        CHECK_MSG(0, "%s", d.msg);
        goto next;
      }
      double worst = 0.0;
      for (int32_t k = 0; k < sl.n; ++k) {
        int32_t i = sl.dof_x[k];
        double x = th->vel->xy[2 * i] - cx, y = th->vel->xy[2 * i + 1], r = hypot(x, y);
        double sg = r > 0.75 ? 1.0 : -1.0; /* outward: away from the centre on the outer circle */
        worst = fmax(worst, hypot(sl.normal[2 * k] - sg * x / r, sl.normal[2 * k + 1] - sg * y / r));
      }
      unsigned seed = 12345u;
      for (int32_t i = 0; i < th->n_dofs; ++i)
        seed = seed * 1103515245u + 12345u, u[i] = (seed >> 8) / 16777216.0 - 0.5;
      double f0, s0, f1, s1;
      sl_slip_flux(th, ids, 2, axi, u, &f0, &s0);
      sl_slip_impose(&sl, u);
      sl_slip_flux(th, ids, 2, axi, u, &f1, &s1);
      printf(
          "normals, %s, %s cells: %d wall nodes rotated, %d corners, largest |n - radial| %.2e; flux of a random "
          "velocity %.3e (of %.3f), made tangent %.2e (of %.3f)\n",
          axi ? "axisymmetric" : "planar", order == 1 ? "straight" : "curved", (int)sl.n, (int)sl.n_corners, worst, f0,
          s0, f1, s1);
      CHECK(sl.n == 2 * 24 * 2 && sl.n_corners == 0);
      if (!axi) CHECK_MSG(worst < 1e-12, "normal off radial by %.3e", worst);
      CHECK_MSG(fabs(f1) < 1e-14 * s1 && fabs(f0) > 1e-3 * s0, "flux %.3e of %.3e (before: %.3e)", f1, s1, f0);
    next:
      free(u);
      sl_slip_free(&sl);
      sl_constraints_free(&bc);
      sl_th_destroy(th);
      sl_mesh_destroy(m);
    }
}

/* ---- an axisymmetric vessel with curved free-slip walls --------------------------------------------------------- */

/* The frame turns at OMEGA about the axis; the fluid turns rigidly at -OMEGA in the inertial frame, u_theta =
 * -2 OMEGA r in the frame's terms (u = (Omega_fluid - Omega) k x r). Then the frame's Coriolis force on the swirl,
 * -2 Omega u_theta e_r = 4 Omega^2 r e_r, and the swirl's own centripetal term, u_theta^2/r = 4 Omega^2 r, cancel
 * pointwise (Greenspan 1968, The Theory of Rotating Fluids, section 1.2: the momentum equation in a frame turning
 * at Omega), the frame's centrifugal force is the pressure rho Omega^2 r^2/2 that sluice takes exactly
 * (docs/rotating.md), and D(u) = 0: u with p = rho Omega^2 r^2/2 + const is an exact steady flow of the
 * Navier-Stokes equations in the frame, whatever the vessel's shape, if its walls neither hold the swirl nor let
 * fluid through: free slip. u_theta is linear in r, in the Q2 space also on curved (isoparametric) cells. */
static const double SHELL_OMEGA = 2.0;
enum { SHELL_NT = 24, SHELL_NR = 4 };

static const char *const SHELL_INI =
    "; rigid rotation in a spherical shell with free-slip walls, axisymmetric, rotating frame\n"
    "; (tests/scenes/test_slip_wall.c: u_theta = -2 Omega r, u_r = u_z = 0)\n"
    "[scene]\nmodel = navier_stokes\ngeometry = axisymmetric\n"
    "[mesh]\ngenerator = gmsh\nfile = slip_shell.msh\n"
    "[fluid]\ndensity = 1.5\nviscosity = 0.1\n"
    "[flow]\nthird_component = true\nconvection = true\nrotation = 2\n"
    "[initial]\nvelocity = 0, 0, -4*x\n"
    "[boundary.inner]\ntype = slip\n[boundary.outer]\ntype = slip\n[boundary.axis]\ntype = axis\n"
    "[time]\nscheme = bdf2\nend = 1\ndt = 0.125\nadaptive = false\n"
    "[output]\nfields = velocity, pressure\n";

/* The largest |u - exact| over the output's nodes at t = 1 (u_r, u_z and u_theta), against 2 Omega R2, the
 * largest |u . n| on the spheres, and the spread of p - rho Omega^2 r^2/2 over the mesh's vertices, against
 * rho Omega^2 R2^2. */
static int shell_errors(const char *out, double *eu, double *un, double *ep) {
  sl_output_mesh m;
  sl_output_field fu, ft, fp;
  sl_diag d = {{0}};
  if (sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return 1;
  }
  if (sl_output_read_field(out, "velocity", 1.0, &fu, &d) || sl_output_read_field(out, "u_theta", 1.0, &ft, &d) ||
      sl_output_read_field(out, "pressure", 1.0, &fp, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    sl_output_mesh_free(&m);
    return 1;
  }
  double pmin = INFINITY, pmax = -INFINITY, w = 2 * SHELL_OMEGA * R2;
  *eu = *un = 0.0;
  for (int32_t i = 0; i < m.n_vertices; ++i) {
    double x = m.coords[3 * i], y = m.coords[3 * i + 1], rho = hypot(x, y);
    const double *u = fu.values + 3 * (size_t)i;
    *eu = fmax(*eu, fmax(hypot(u[0], u[1]), fabs(ft.values[i] + 2 * SHELL_OMEGA * x)) / w);
    if (fabs(rho - R1) < 1e-9 || fabs(rho - R2) < 1e-9) *un = fmax(*un, fabs(u[0] * x + u[1] * y) / rho / w);
    /* the pressure at the mesh's vertices (the output's other nodes carry the mean of their cell's vertices) */
    double a = (rho - R1) * SHELL_NR / (R2 - R1), b = (atan2(y, x) + M_PI / 2) * SHELL_NT / M_PI;
    if (fabs(a - round(a)) > 1e-6 || fabs(b - round(b)) > 1e-6) continue;
    double p = fp.values[i] - 1.5 * SHELL_OMEGA * SHELL_OMEGA * x * x / 2;
    pmin = fmin(pmin, p), pmax = fmax(pmax, p);
  }
  *ep = (pmax - pmin) / (1.5 * SHELL_OMEGA * SHELL_OMEGA * R2 * R2);
  sl_output_mesh_free(&m);
  sl_output_field_free(&fu);
  sl_output_field_free(&ft);
  sl_output_field_free(&fp);
  return 0;
}

/* Rigid rotation in an axisymmetric spherical shell with curved free-slip walls (both spheres), in the frame
 * turning at Omega: it stays exact to round-off (velocity, no flow through the spheres, the pressure) on straight
 * and curved cells, monolithic and split. With the outer sphere a no-slip wall the same start
 * spins down: the check can fail. */
static void shell(void) {
  if (write_text("slip_shell.ini", SHELL_INI)) {
    CHECK_MSG(0, "cannot write slip_shell.ini");
    return;
  }
  /* both steps: the split step takes the axis nodes' r-weighted mass, 0 only to round-off (-8e-22), as 0 */
  for (int order = 1; order <= 2; ++order)
    for (int scheme = 0; scheme < 2; ++scheme) {
      if (write_polar("slip_shell.msh", SHELL_NT, SHELL_NR, order, 0.0, 1)) {
        CHECK_MSG(0, "cannot write the mesh");
        return;
      }
      const char *sets[] = {scheme ? "flow.scheme=projection" : "flow.scheme=monolithic", NULL};
      if (run_ok("slip_shell", NULL, NULL, sets, "slip_shell.h5")) return;
      double eu, un, ep;
      if (shell_errors("slip_shell.h5", &eu, &un, &ep)) return;
      printf(
          "rigid rotation in a spherical shell, axisymmetric, %s cells, %s, t = 1: velocity error %.2e of "
          "2 Omega R, u.n on the spheres %.2e, pressure spread %.2e of rho Omega^2 R^2\n",
          order == 1 ? "straight" : "curved", scheme ? "projection" : "monolithic", eu, un, ep);
      CHECK_MSG(eu < 1e-12 && un < 1e-12 && ep < 1e-12, "error %.3e, u.n %.3e, pressure %.3e", eu, un, ep);
    }
  const char *wall[] = {"flow.scheme=monolithic", NULL};
  if (run_ok("slip_shell", "boundary.outer", "[boundary.outer]\ntype = wall\n", wall, "slip_shell_wall.h5")) return;
  double eu, un, ep;
  if (shell_errors("slip_shell_wall.h5", &eu, &un, &ep)) return;
  printf("the same with a no-slip outer sphere: velocity error %.2e, pressure spread %.2e\n", eu, ep);
  CHECK_MSG(eu > 1e-2, "a no-slip outer sphere left the rotation (error %.2e)", eu);
}

int main(int argc, char **argv) {
  static const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"rotation", rotation}, {"couette", couette_order}, {"normals", normals}, {"shell", shell}};
  int ran = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 || strcmp(argv[1], parts[k].name) == 0) parts[k].run(), ++ran;
  if (!ran) return fprintf(stderr, "unknown part '%s' (rotation, couette, normals, shell)\n", argv[1]), 2;
  return sl_test_summary();
}
