/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One implicit step of the 1-D two-fluid model (two_fluid.h): the 2-D
 * model's step (two_fluid_plane_step.c) on its grid of n x 1 cells with the
 * column's form (column_form: no fluid viscous stress, the weight's phi the
 * drag's, the fluid inertia and the pressure from the mixture flux), gravity
 * along x and frictionless sides. tests/scenes/test_two_fluid_column_plane.c
 * checks that this is the column's scheme: the face equations written for
 * phi of the cell on the gravity side ("below", the inside cell at the
 * ends) so that a fluidised bed under clear fluid is steady cell by cell,
 * drag implicit (Newton in the slip), p_s implicit through its derivative
 * (Pringle 2001 eq 4.31's Taylor expansion about the latest iterate), the
 * iteration with the bounded transport of phi until the solids velocity
 * changes by less than tolerance x its scale; the drag's phi that of the
 * step's start after 8 iterations (a drag law with a jump in phi, Pringle
 * 2001 section 3.1, can leave the fixed point without a solution).
 *
 * Here: the column's mixture flux j (its inlet's velocity, or the
 * equilibrium velocity of its porosity), the closures of the column, and the
 * column's state carried to and from the n x 1 model at each step. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/scene/solver.h"

/* Faces with (nearly) no solids: the equilibrium of one particle in clear fluid. */
static const double PHI_FLOOR = 1e-6;

int tf_equilibrium_velocity(tf_column *c, double porosity, double *U, sl_diag *d) {
  /* The steady homogeneous state of the solids equation (two_fluid.h) with u_s = 0 and
   * dp_s/dx = 0: K s / eps = phi (rho_s - rho_f) |g| (Pringle 2001, eq 4.20 at steady state: beta V_r = n (1 - n)
   * (rho_s - rho_f) g). K s grows with s for every drag law, so bisection on s between 0 (where
   * K s - weight < 0) and a bound doubled until it is positive finds the one root. */
  const double phi = fmax(1.0 - porosity, PHI_FLOOR), eps = 1.0 - phi;
  const double weight = phi * eps * (c->rho_s - c->rho_f) * fabs(c->g);
  double lo = 0.0, hi = c->v_ref, K, dK, s;
  int rc;
  for (int grow = 0;; ++grow) {
    s = hi;
    if ((rc = tf_closure_eval(&c->drag, 1, &phi, &s, &K, &dK, d))) return rc;
    if (K * hi > weight) break;
    if (grow == 60)
      return sl_diag_set(d, SL_EFAILED, "no superficial velocity below %.3g m/s holds a bed at porosity %g", eps * hi,
                         porosity);
    lo = hi, hi *= 2.0;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    s = 0.5 * (lo + hi);
    if ((rc = tf_closure_eval(&c->drag, 1, &phi, &s, &K, &dK, d))) return rc;
    if (K * s > weight) hi = s;
    else lo = s;
  }
  *U = eps * 0.5 * (lo + hi);
  return 0;
}

int tf_mixture_flux(tf_column *c, double t, double *j, sl_diag *d) {
  *j = 0.0;
  if (!c->inlet && !c->inlet_porosity) return 0;
  const double vars[2] = {t, c->case_index};
  double v;
  if (c->inlet) {
    v = sl_expr_eval(c->inlet, vars);
    if (!isfinite(v))
      return sl_diag_set(d, SL_EFAILED, "the inlet velocity is not a finite number (%g) at t = %g", v, t);
  } else {
    double n = sl_expr_eval(c->inlet_porosity, vars);
    if (!(n > 1.0 - c->phi_max && n <= 1.0))
      return sl_diag_set(d, SL_EFAILED,
                         "the inlet porosity is %g at t = %g: allowed 1 - phi_max < porosity <= 1, "
                         "phi_max = %g",
                         n, t, c->phi_max);
    int k = c->eq_porosity[0] == n ? 0 : c->eq_porosity[1] == n ? 1 : -1;
    if (k < 0) {
      int rc = tf_equilibrium_velocity(c, n, &v, d);
      if (rc) return sl_diag_prefix(d, rc, "the inlet at porosity %g (t = %g)", n, t);
      k = c->eq_next, c->eq_next = 1 - c->eq_next;
      c->eq_porosity[k] = n, c->eq_velocity[k] = v;
    }
    v = c->eq_velocity[k];
  }
  *j = c->inlet_side == 0 ? v : -v;
  return 0;
}

int tf_closure_eval(tf_closure *b, int n, const double *phi, const double *slip, double *value, double *dvalue,
                    sl_diag *d) {
  const double *values[9] = {phi, slip, NULL, NULL, NULL, NULL, NULL, NULL, b->nbar};
  sl_point_request rq = {b->out, value, dvalue, b->wrt};
  return sl_point_eval(&b->pc, n, values, &rq, 1, d);
}

/* ---- the column on the 2-D model's n x 1 grid ---------------------------------------- */

int tf_plane_create(tf_column *c, const sl_scene *sc, const tf_config *cfg, sl_diag *d) {
  const int n = c->n;
  tfp_model *m = calloc(1, sizeof *m);
  tfp_boundary *b = calloc(3, sizeof *b);
  c->plane = m;
  if (!m || !b) {
    free(b);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  /* the ends (boundary 0 at x0, 1 at x1) and the frictionless sides (2) */
  for (int side = 0; side < 2; ++side) {
    b[side].type = c->bc[side] == TF_INLET ? TFP_INLET : c->bc[side] == TF_OUTLET ? TFP_OUTLET : TFP_WALL;
    b[side].pressure = c->bc[side] == TF_OUTLET ? c->p_out : 0.0;
    b[side].solids = TFP_SOLIDS_FREE_SLIP;
  }
  b[2].type = TFP_SLIP;
  m->b = b, m->n_b = 3;
  m->c = *c; /* the physics and the numerical keys; the closures stay the column's (tf_step lends them) */
  m->g[0] = c->g, m->g[1] = 0.0;
  sl_tensor_grid *g = &m->grid;
  g->nx = n, g->ny = 1;
  g->xf = malloc((size_t)(n + 1) * sizeof *g->xf), g->yf = malloc(2 * sizeof *g->yf);
  g->mesh_cell = malloc((size_t)n * sizeof *g->mesh_cell);
  for (int k = 0; k < 4; ++k) g->side_tag[k] = malloc((size_t)(k < 2 ? 1 : n) * sizeof *g->side_tag[k]);
  if (!g->xf || !g->yf || !g->mesh_cell || !g->side_tag[0] || !g->side_tag[1] || !g->side_tag[2] || !g->side_tag[3])
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  memcpy(g->xf, c->xf, (size_t)(n + 1) * sizeof *g->xf);
  g->yf[0] = 0.0, g->yf[1] = 1.0;
  for (int i = 0; i < n; ++i) g->mesh_cell[i] = i, g->side_tag[SL_SIDE_BOTTOM][i] = g->side_tag[SL_SIDE_TOP][i] = 2;
  g->side_tag[SL_SIDE_LEFT][0] = 0, g->side_tag[SL_SIDE_RIGHT][0] = 1;
  int rc = tfp_setup(m, d);
  if (!rc) rc = tfp_solids_bind(m, sc, cfg, d);
  if (!rc)
    rc = sl_scene_linsolve_general(sc, m->n_unknowns, "the coupled two-fluid matrix is nonsymmetric", &m->ls,
                                   &c->linear, d);
  m->band_allowed = sc->solver.linear == 0 && !rc && strcmp(c->linear, "petsc") != 0; /* auto: the fast path */
  m->col_inlet_given = 1, m->col_inlet = 0.0;
  if (!rc) rc = tfp_column_start(m, 1, "[scene] geometry = line (the column)", d);
  return rc;
}

void tf_plane_free(tf_column *c) {
  tfp_model *m = c->plane;
  if (!m) return;
  free((void *)m->b);
  tfp_free(m);
  free(m);
  c->plane = NULL;
}

int tf_step(tf_column *c, double t, double dt, sl_diag *d) {
  tfp_model *m = c->plane;
  const int n = c->n;
  double j0, j1;
  int rc = tf_mixture_flux(c, t, &j0, d);
  if (!rc) rc = tf_mixture_flux(c, t + dt, &j1, d);
  c->fatal = rc != 0;
  if (rc) return rc;
  /* the column's state, its mixture flux at t, its inlet's at t + dt (inwards), and its closures (lent) */
  memcpy(m->phi, c->phi, (size_t)n * sizeof *c->phi), memcpy(m->p, c->p, (size_t)n * sizeof *c->p);
  for (int k = 0; k <= n; ++k) m->us[m->col_face[k]] = c->u[k], m->uf[m->col_face[k]] = c->uf[k];
  m->col_j = j0, m->col_inlet = c->inlet_side == 1 ? -j1 : j1;
  m->accepted_substeps = c->accepted_substeps;
  m->c.drag = c->drag, m->c.ps = c->ps, m->c.v_ref = c->v_ref;
  const double cpu = m->transport_cpu;
  rc = tfp_step(m, t, dt, d);
  c->drag = m->c.drag, c->ps = m->c.ps; /* their buffers may have grown */
  c->transport_cpu += m->transport_cpu - cpu;
  c->iterations_trial = m->iterations_trial, c->substeps_trial = m->substeps_trial;
  c->last_substeps = m->last_substeps;
  if (rc) return rc;
  memcpy(c->phi_new, m->phi_new, (size_t)n * sizeof *c->phi), memcpy(c->p_new, m->p_new, (size_t)n * sizeof *c->p);
  for (int k = 0; k <= n; ++k) c->u_new[k] = m->us_new[m->col_face[k]], c->uf_new[k] = m->uf_new[m->col_face[k]];
  c->outflow_trial = m->outflow_trial;
  return 0;
}
