/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The upright settling box of the mixture model's scene tests and of
 * bench/mixture_box.c: a closed vessel W wide and H high (0.1 m x 1 m), nx x
 * ny cells (ny = n, nx = 4; or a 1-D column of n cells), a uniform
 * suspension phi0 = 0.1 of 1006 kg m^-3 particles in 996 kg m^-3 water
 * (density contrast 0.01) settling by Vesilind's law u_t 10^(-a phi) (1 -
 * phi/phi_max), u_t = 2.198 mm/s, a = 2, phi_max = 0.64, Stokes flow (no
 * convection) with fixed steps: the exact solution is Kynch's
 * (core/study/kynch_exact.h) with j = 0, and the L1 error of phi against
 * it. */
#ifndef SLUICE_TESTS_SCENES_MIXTURE_BOX_H
#define SLUICE_TESTS_SCENES_MIXTURE_BOX_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/study/kynch_exact.h"
#include "core/util/diag.h"
#include "sluice/sluice.h"

enum { BOX_NX = 4 };
static const double box_W = 0.1, box_H = 1.0, box_phi0 = 0.1, box_ut = 2.198e-3, box_a = 2.0, box_phi_max = 0.64;

typedef struct box_scene {
  int n;                  /* cells along the height */
  int line;               /* a 1-D column of n cells instead of 4 x n */
  const char *mesh_extra; /* more [mesh] lines ("cell_type = tri", a grading), or NULL */
  double rho_s;           /* particle density (996 kg m^-3 water) */
  const char *phi;        /* [initial] phi, NULL: phi0 */
  int settling;           /* 0: no [closure.hindered_settling]; 2: the step cut-off at phi_max */
  double a, phi_max;      /* the law's a and phi_max; 0: box_a, box_phi_max */
  double end, dt, every;
  int convection;       /* [flow] convection = true, with adaptive BDF2 steps (else Stokes flow, fixed BDF1) */
  int solve_every_step; /* solve the flow even where its result is known ([solver] skip_known = false) */
  int projection;       /* [flow] scheme = projection (the split step) */
  int monolithic;       /* [flow] scheme = monolithic (else the default, auto: the split step for this box) */
  const char *extra;    /* more sections at the end, or NULL */
} box_scene;

/* The scene's INI text into buf. */
static inline void box_text(const box_scene *s, char *buf, size_t len) {
  char mesh[512], phi[256], closure[512];
  double a = s->a > 0.0 ? s->a : box_a, phi_max = s->phi_max > 0.0 ? s->phi_max : box_phi_max;
  if (s->line) snprintf(mesh, sizeof mesh, "generator = interval\nx = 0, %g\ncells = %d\n", box_H, s->n);
  else
    snprintf(mesh, sizeof mesh, "generator = rectangle\nx = 0, %g\ny = 0, %g\ncells = %d, %d\n%s\n", box_W, box_H,
             BOX_NX, s->n, s->mesh_extra ? s->mesh_extra : "");
  snprintf(phi, sizeof phi, "%s", s->phi ? s->phi : "0.1");
  snprintf(closure, sizeof closure,
           "[closure.hindered_settling]\nmodel = vesilind\na = %g\npacking_cutoff = %s\nphi_max = %g\n"
           "terminal_velocity = given\nu_t = %.17g\n",
           a, s->settling == 2 ? "step" : "smooth", phi_max, box_ut);
  snprintf(buf, len,
           "[scene]\nmodel = mixture\ngeometry = %s\n[mesh]\n%s"
           "[fluid]\ndensity = 996\nviscosity = 1e-3\n[solid]\ndensity = %.17g\ndiameter = 1e-4\nphi_max = %g\n%s"
           "[flow]\ngravity = %s\nconvection = %s\n[initial]\nphi = %s\n"
           "[boundary.left]\ntype = wall\n[boundary.right]\ntype = wall\n%s"
           "[transport]\norder = 2\n"
           "[time]\nscheme = %s\nend = %.17g\ndt = %.17g\nadaptive = %s\n[output]\nevery = %.17g\n%s",
           s->line ? "line" : "planar", mesh, s->rho_s, phi_max, s->settling ? closure : "",
           s->line ? "-9.81" : "0, -9.81", s->convection ? "true" : "false", phi,
           s->line ? "" : "[boundary.bottom]\ntype = wall\n[boundary.top]\ntype = wall\n",
           s->convection ? "bdf2" : "bdf1", s->end, s->dt, s->convection ? "true" : "false", s->every,
           s->extra ? s->extra : "");
}

/* Runs the scene into `out`; res (may be NULL) gets the run's result. */
static inline int box_run(const box_scene *s, const char *out, sluice_summary *res, sl_diag *d) {
  static char text[8192];
  box_text(s, text, sizeof text);
  const char *sets[3] = {NULL, NULL, NULL};
  int n_sets = 0;
  if (s->solve_every_step) sets[n_sets++] = "solver.skip_known=false";
  if (s->projection) sets[n_sets++] = "flow.scheme=projection";
  else if (s->monolithic) sets[n_sets++] = "flow.scheme=monolithic";
  sluice_open_opts oo = {.sets = n_sets ? sets : NULL};
  sluice *sc = NULL;
  sluice_error e = {0, ""};
  sluice_summary r;
  sluice_run_opts o = {.scene_path = "box.ini", .output = out, .version = "test"};
  int rc = sluice_open_text(text, strlen(text), "box.ini", &oo, &sc, &e);
  if (!rc) rc = sluice_run(sc, &o, res ? res : &r, &e);
  sluice_close(sc);
  if (rc) sl_diag_set(d, rc, "%s", e.msg);
  return rc;
}

/* The law's exact solution (step: the step cut-off). */
static inline int box_exact(kynch *k, int step) {
  return kx_init(k, kx_vesilind(box_ut, box_a, box_phi_max, step), box_H, box_phi0);
}

/* The L1 error of phi at output time t, per unit width: sum over cells of
 * |phi_c - the exact mean over c| times the cell's area, over W (1-D: the
 * cell length), cells' heights from the output mesh (quadrilaterals with
 * horizontal sides, or a line). NAN when the file cannot be read. */
static inline double box_l1(const char *out, double t, const kynch *k) {
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "phi", t, &f, &d)) return NAN;
  if (sl_output_read_mesh(out, &m, &d)) {
    sl_output_field_free(&f);
    return NAN;
  }
  kx_profile p = kx_at(k, f.time);
  int up = m.dim == 1 ? 0 : 1;
  double e = 0.0;
  for (int32_t c = 0; c < m.n_cells; ++c) {
    double lo = INFINITY, hi = -INFINITY, xl = INFINITY, xh = -INFINITY;
    for (int j = 0; j < m.nodes_per_cell; ++j) {
      const double *x = m.coords + 3 * (size_t)m.cells[(size_t)c * m.nodes_per_cell + j];
      lo = fmin(lo, x[up]), hi = fmax(hi, x[up]);
      xl = fmin(xl, x[0]), xh = fmax(xh, x[0]);
    }
    double width = m.dim == 1 ? 1.0 : (xh - xl) / box_W;
    e += width * fabs(f.values[c] * (hi - lo) - kx_integral(k, &p, lo, hi));
  }
  sl_output_field_free(&f);
  sl_output_mesh_free(&m);
  return e;
}

/* max |j| (any component, any node) at the output nearest t (INFINITY: the last), and the largest over all
 * outputs into *worst (may be NULL). */
static inline double box_speed(const char *out, double t, double *worst) {
  sl_diag d = {{0}};
  int n = 0;
  double *times = NULL, at = NAN;
  if (sl_output_read_times(out, &n, &times, &d)) return NAN;
  if (worst) *worst = 0.0;
  for (int i = 0; i < n; ++i) {
    sl_output_field f;
    if (sl_output_read_field(out, "velocity", times[i], &f, &d)) continue;
    double v = 0.0;
    for (int32_t k = 0; k < f.n * f.components; ++k) v = fmax(v, fabs(f.values[k]));
    if (worst) *worst = fmax(*worst, v);
    if (i == n - 1 || (isfinite(t) && fabs(times[i] - t) < 1e-9 * fmax(1.0, fabs(t)))) at = v;
    sl_output_field_free(&f);
    if (isfinite(t) && fabs(times[i] - t) < 1e-9 * fmax(1.0, fabs(t))) break;
  }
  free(times);
  return at;
}

#endif
