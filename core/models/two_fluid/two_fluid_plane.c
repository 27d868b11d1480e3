/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid model on 2-D planar and axisymmetric rectangles (two_fluid.h
 * has the 1-D column; the staggered scheme is in two_fluid_plane_step.c).
 * The mesh must be a tensor grid of axis-aligned quadrilaterals (the
 * rectangle and annulus generators, graded or not).
 *
 * Boundaries ([boundary.NAME] type):
 *   wall    u.n = 0 for both phases; along it the fluid sticks to the
 *           wall's speed `velocity` (an expression of x, y, t and case,
 *           along +x for a bottom or top wall, +y for a left or right one;
 *           default 0); the solids
 *           solids = no_slip (default) | free_slip | wall_stress
 *           (the last: the stress of [closure.wall_stress] against their
 *           slip, two_fluid_plane_solids.c)
 *   slip    u.n = 0, both phases free-slip
 *   axis    the symmetry axis of an axisymmetric scene (r = 0)
 *   inlet   velocity = the superficial fluid velocity entering (m/s, along
 *           the inward normal), an expression of x, y, t and case; the
 *           solids are held (u_s = 0), or enter with it at the superficial
 *           velocity solids_flux (an expression of x, y, t and case, >= 0);
 *           tangential velocities 0
 *   outlet  pressure (default 0); velocities free (zero normal gradient),
 *           solids leave where they are carried out
 *   periodic both opposite sides (left and right, or bottom and top; an
 *           axisymmetric scene: bottom and top only) are this type: what
 *           leaves one enters the other; no mean pressure gradient along it
 *
 *           (with [two_fluid] swirl, axisymmetric: angular_velocity, its
 *           rotation about the axis in rad/s; two_fluid_plane_swirl.c)
 *
 * [body] box = x0, x1, y0, y1 removes the cells inside a box (a rotor's tip,
 * a step): its faces are no-slip walls, turning at its angular_velocity
 * with swirl (two_fluid_plane_body.c). [two_fluid] centrifugal adds the
 * swirl's centrifugal force to the radial momentum (two_fluid_plane_step.c).
 *
 * Output: cell fields phi, velocity_solid, velocity_fluid, pressure,
 * solids_pressure, theta (with [closure.granular]), swirl_fluid and
 * swirl_solid (u_theta, with [two_fluid] swirl); scalars
 * solids_inventory, solids_conservation_error and, per wall NAME,
 * wall_shear_stress_fluid_NAME and wall_shear_stress_solid_NAME (the mean
 * stress each phase exerts on the wall along its positive direction) and
 * wall_slip_NAME (the mean solids slip there), and bagnold_number_NAME
 * where the wall closure gives it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/models/two_fluid/two_fluid.h"
#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/scene/solver.h"

enum { F_PHI = 1, F_US = 2, F_UF = 4, F_P = 8, F_PS = 16, F_THETA = 32, F_SWF = 64, F_SWS = 128 };

typedef struct tfp_run {
  const sl_scene *sc;
  const tf_config *cfg;
  const sl_mesh *mesh;
  tfp_model m;
  tfp_boundary *b;    /* [n_boundaries]: the scene's */
  tfp_boundary *ball; /* with a [body]: the scene's and the body's wall (m.b) */
  int has_inlet, has_outlet;
  double steady_tol, inventory0, outflow;
  long substeps, iterations, advances;
  int fields;
  double *cellbuf; /* [2 n_cells] output scratch in mesh cell order */
  const char *linear;
  char steady_text[96];
  tf_state ck;
} tfp_run;

/* ---- scene ------------------------------------------------------------------- */

static int boundaries(tfp_run *r, sl_diag *d) {
  const sl_mesh *mesh = r->mesh;
  r->b = r->sc->boundaries;
  for (int k = 0; k < mesh->n_boundaries; ++k) {
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", mesh->boundary_names[k]);
    const tfp_boundary *b = &r->b[k];
    if (b->type == TFP_AXIS && !r->m.axi)
      return sl_diag_set(d, SL_EBADINPUT, "[%s] type = axis: only an axisymmetric scene has an axis", sec);
    if (b->type == TFP_INLET) {
      if (!b->velocity.e)
        return sl_diag_set(d, SL_EBADINPUT,
                           "[%s] velocity: an inlet needs the superficial fluid velocity entering "
                           "(m/s), an expression of x, y, t and case",
                           sec);
      r->has_inlet = 1;
      /* the solids entering: finite and not negative at the inlet's face centres at t = 0 (later times: the step
         checks) */
      const sl_tensor_grid *g = &r->m.grid;
      for (int side = 0; b->solids_flux.e && side < 4; ++side)
        for (int s = 0; s < (side < 2 ? g->ny : g->nx); ++s) {
          if (g->side_tag[side][s] != k) continue;
          double x = side < 2 ? g->xf[side == SL_SIDE_LEFT ? 0 : g->nx] : 0.5 * (g->xf[s] + g->xf[s + 1]);
          double y = side < 2 ? 0.5 * (g->yf[s] + g->yf[s + 1]) : g->yf[side == SL_SIDE_BOTTOM ? 0 : g->ny];
          double v[4] = {x, y, 0.0, r->m.c.case_index}, J = sl_expr_eval(b->solids_flux.e, v);
          if (isfinite(J) && J >= 0.0) continue;
          const sl_src *src = sl_scene_src(r->sc, &b->solids_flux);
          return sl_diag_set(d, SL_EBADINPUT,
                             "%s:%d: [%s] solids_flux = %g at (%g, %g), t = 0: it must be finite "
                             "and not negative (m/s)",
                             src ? src->file : "?", src ? src->line : 0, sec, J, x, y);
        }
    }
    if (b->type == TFP_OUTLET) r->has_outlet = 1;
  }
  /* periodic sides come in opposite pairs, each wholly periodic */
  const sl_tensor_grid *gp = &r->m.grid;
  for (int dir = 0; dir < 2; ++dir) {
    int n = dir == 0 ? gp->ny : gp->nx, count[2] = {0, 0};
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < n; ++k) count[side] += r->b[gp->side_tag[2 * dir + side][k]].type == TFP_PERIODIC;
    if (count[0] == 0 && count[1] == 0) continue;
    static const char *const pair[2] = {"left and right", "bottom and top"};
    if (count[0] != n || count[1] != n)
      return sl_diag_set(d, SL_EBADINPUT,
                         "type = periodic: the %s sides must both be periodic, wholly (%d of %d and "
                         "%d of %d faces are)",
                         pair[dir], count[0], n, count[1], n);
    if (dir == 0 && r->m.axi)
      return sl_diag_set(d, SL_EBADINPUT,
                         "type = periodic: an axisymmetric scene is periodic along its axis only "
                         "(bottom and top)");
    if ((dir == 0 ? gp->nx : gp->ny) < 2)
      return sl_diag_set(d, SL_EBADINPUT, "type = periodic: the %s sides need at least 2 cells between them",
                         pair[dir]);
    r->m.fv.periodic[dir] = 1;
  }
  if (r->has_inlet && !r->has_outlet)
    return sl_diag_set(d, SL_EBADINPUT, "two_fluid: an inlet needs an outlet (type = outlet) for the flow to leave");
  /* an axisymmetric grid that reaches r = 0 has its axis there; an axis elsewhere is refused */
  const sl_tensor_grid *g = &r->m.grid;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < (side < 2 ? g->ny : g->nx); ++k) {
      int tag = g->side_tag[side][k];
      int on_axis = r->m.axi && side == SL_SIDE_LEFT && g->xf[0] == 0.0;
      if (r->b[tag].type == TFP_PERIODIC && !on_axis) continue;
      if (on_axis != (r->b[tag].type == TFP_AXIS))
        return sl_diag_set(d, SL_EBADINPUT, "[boundary.%s] type%s: %s", mesh->boundary_names[tag],
                           on_axis ? "" : " = axis",
                           on_axis ? "the boundary at r = 0 of an axisymmetric scene is its axis (type = axis)"
                                   : "only the boundary at r = 0 of an axisymmetric scene is an axis");
    }
  return 0;
}

static int initial_state(tfp_run *r, sl_diag *d) {
  const sl_scene *sc = r->sc;
  const tf_config *cfg = r->cfg;
  const sl_src *te = sl_scene_src(sc, &cfg->theta);
  if (te && !(r->m.s.granular && !r->m.s.algebraic))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [initial] theta: only a transported granular temperature takes it "
                       "([closure.granular] with [two_fluid] granular_temperature = transport)",
                       te->file, te->line);
  if (te) { /* theta in the cells, m^2/s^2 (default 1e-6) */
    int trc = 0;
    for (int c = 0; c < r->m.fv.nc && !trc; ++c) {
      double xy[3] = {r->m.fv.xc[c % r->m.fv.nx], r->m.fv.yc[c / r->m.fv.nx], r->m.c.case_index},
             th = sl_expr_eval(cfg->theta.e, xy);
      if (!(th > 0.0 && th < 1e4))
        trc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] theta = %g at (%g, %g): allowed 0 < theta < 1e4 m^2/s^2",
                          te->file, te->line, th, xy[0], xy[1]);
      r->m.s.theta[c] = r->m.s.theta_new[c] = th;
    }
    if (trc) return trc;
  } else if (r->m.s.granular && !r->m.s.algebraic) {
    for (int c = 0; c < r->m.fv.nc; ++c) r->m.s.theta[c] = r->m.s.theta_new[c] = 1e-6;
  }
  const sl_src *e = sl_scene_src(sc, &cfg->phi), *en = sl_scene_src(sc, &cfg->porosity);
  if (e && en)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] porosity and phi both given: set one", en->file, en->line);
  if (!e && !en)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[initial] phi (or porosity): the two_fluid model needs the initial solids "
                       "fraction, an expression of x, y and case");
  const sl_src *use = e ? e : en;
  const sl_expr *ex = e ? cfg->phi.e : cfg->porosity.e;
  int rc = 0;
  tfp_model *m = &r->m;
  for (int c = 0; c < m->fv.nc && !rc; ++c) {
    double xy[3] = {m->fv.xc[c % m->fv.nx], m->fv.yc[c / m->fv.nx], m->c.case_index}, v = sl_expr_eval(ex, xy);
    double phi = e ? v : 1.0 - v;
    if (!(phi >= 0.0 && phi <= m->c.phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s = %g at (%g, %g): allowed %s = %g", use->file, use->line,
                       use->key, v, xy[0], xy[1], e ? "0 <= phi <= phi_max" : "1 - phi_max <= porosity <= 1, phi_max",
                       m->c.phi_max);
    m->phi[c] = tfp_blocked(m, c) ? 0.0 : phi; /* a body's cell holds nothing */
  }
  if (rc) return rc;
  /* the phases' velocities (default at rest): each face takes its normal component at its centre */
  const sl_scene_exprs *vel[2] = {&cfg->velocity_fluid, &cfg->velocity_solid};
  for (int phase = 0; phase < 2; ++phase) {
    const sl_src *ve = sl_scene_src(sc, vel[phase]);
    if (!ve) continue;
    if (vel[phase]->n != 2)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [initial] %s: two components (along x, along y), expressions of "
                         "x, y and case; %d given",
                         ve->file, ve->line, ve->key, vel[phase]->n);
    sl_expr *const *comp = vel[phase]->e;
    double *u = phase ? m->us : m->uf;
    for (int f = 0; f < m->fv.nf; ++f) {
      int dir = f >= m->fv.nfx, i = dir ? (f - m->fv.nfx) % m->fv.nx : f % (m->fv.nx + 1);
      int j = dir ? (f - m->fv.nfx) / m->fv.nx : f / (m->fv.nx + 1);
      double xy[3] = {dir ? m->fv.xc[i] : m->grid.xf[i], dir ? m->grid.yf[j] : m->fv.yc[j], m->c.case_index};
      u[f] = sl_expr_eval(comp[dir], xy);
      if (!isfinite(u[f]))
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s is not finite at (%g, %g)", ve->file, ve->line, ve->key,
                         xy[0], xy[1]);
    }
    if (rc) return rc;
  }
  return 0;
}

/* ---- output, checkpoint, restart --------------------------------------------------- */

static int plane_write_mesh(void *self, sl_output *out, sl_diag *d) {
  tfp_run *r = self;
  const sl_mesh *m = r->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * m->nv_per_cell * sizeof *cells);
  if (!cells) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int i = 0; i < m->n_cells * m->nv_per_cell; ++i) cells[i] = m->cell_vertices[i];
  int rc = sl_output_write_mesh(out, 2, m->n_vertices, m->xy, m->n_cells, m->nv_per_cell, cells, "Quadrilateral", d);
  free(cells);
  return rc;
}

/* A grid-ordered cell field into mesh cell order (components 1 or 2). */
static const double *to_mesh_order(tfp_run *r, const double *a, const double *b) {
  const tfp_model *m = &r->m;
  for (int c = 0; c < m->fv.nc; ++c) {
    int mc = m->grid.mesh_cell[c];
    if (b) r->cellbuf[2 * mc] = a[c], r->cellbuf[2 * mc + 1] = b[c];
    else r->cellbuf[mc] = a[c];
  }
  return r->cellbuf;
}

static int plane_write(void *self, sl_output *out, double t, const double *u_state, sl_diag *d) {
  (void)t, (void)u_state;
  tfp_run *r = self;
  tfp_model *m = &r->m;
  int rc = 0;
  if (r->fields & F_PHI) rc = sl_output_write_field(out, "phi", SL_CENTRE_CELL, 1, to_mesh_order(r, m->phi, NULL), d);
  /* velocities at the cell centres: the mean of the two faces of each family */
  double *vx = m->x, *vy = m->x + m->fv.nc; /* scratch between steps */
  for (int phase = 0; phase < 2 && !rc; ++phase) {
    if (!(r->fields & (phase ? F_US : F_UF))) continue;
    const double *u = phase ? m->us : m->uf;
    for (int c = 0; c < m->fv.nc; ++c) {
      int i = c % m->fv.nx, j = c / m->fv.nx, w = i + (m->fv.nx + 1) * j, s = m->fv.nfx + i + m->fv.nx * j;
      vx[c] = 0.5 * (u[w] + u[w + 1]), vy[c] = 0.5 * (u[s] + u[s + m->fv.nx]);
    }
    rc = sl_output_write_field(out, phase ? "velocity_solid" : "velocity_fluid", SL_CENTRE_CELL, 2,
                               to_mesh_order(r, vx, vy), d);
  }
  if (!rc && (r->fields & F_P))
    rc = sl_output_write_field(out, "pressure", SL_CENTRE_CELL, 1, to_mesh_order(r, m->p, NULL), d);
  if (!rc && (r->fields & F_PS) && m->c.ps.c) {
    if ((rc = tf_closure_eval(&m->c.ps, m->fv.nc, m->phi, NULL, vx, NULL, d)) == 0)
      rc = sl_output_write_field(out, "solids_pressure", SL_CENTRE_CELL, 1, to_mesh_order(r, vx, NULL), d);
  }
  if (!rc && (r->fields & F_THETA) && m->s.granular)
    rc = sl_output_write_field(out, "theta", SL_CENTRE_CELL, 1, to_mesh_order(r, m->s.theta, NULL), d);
  for (int phase = 0; phase < 2 && !rc && m->sw.on; ++phase) { /* u_theta = r Omega */
    if (!(r->fields & (phase ? F_SWS : F_SWF))) continue;
    for (int c = 0; c < m->fv.nc; ++c) vx[c] = m->fv.xc[c % m->fv.nx] * m->sw.om[phase * m->fv.nc + c];
    rc = sl_output_write_field(out, phase ? "swirl_solid" : "swirl_fluid", SL_CENTRE_CELL, 1,
                               to_mesh_order(r, vx, NULL), d);
  }
  const int n_mesh_b = m->n_b - m->n_bodies;
  for (int b = 0; b < m->n_b && !rc; ++b) { /* the mesh's walls, then the bodies' */
    if (m->b[b].type != TFP_WALL) continue;
    const char *wall = b < n_mesh_b ? r->mesh->boundary_names[b] : m->body_names[b - n_mesh_b];
    static const char *const what[4] = {"wall_shear_stress_fluid", "wall_shear_stress_solid", "wall_slip",
                                        "bagnold_number"};
    char name[300];
    for (int k = 0; k < 4 && !rc; ++k) {
      if (k == 3 && !(m->b[b].solids == TFP_SOLIDS_WALL_STRESS && sl_point_has_output(&m->s.wall, "bagnold_number")))
        continue;
      snprintf(name, sizeof name, "%s_%s", what[k], wall);
      rc = sl_output_write_scalar(out, name, m->wall_stats[5 * b + k], d);
    }
    /* with the swirl: the torque about the axis each phase exerts on the wall, their sum, and the mean azimuthal
       shear stresses (two_fluid_plane_swirl.c) */
    static const char *const tq[5] = {"torque_fluid", "torque_solid", "wall_shear_stress_theta_fluid",
                                      "wall_shear_stress_theta_solid", "torque"};
    for (int k = 0; k < 5 && !rc && m->sw.on; ++k) {
      const double *T = m->sw.torque + 5 * b;
      snprintf(name, sizeof name, "%s_%s", tq[k], wall);
      rc = sl_output_write_scalar_unit(out, name, k == 2 || k == 3 ? "Pa" : "N m", k == 4 ? T[0] + T[1] : T[k], d);
    }
  }
  double inv = tfp_inventory(m, m->phi);
  /* the solids volume per unit depth (planar) or per radian (axisymmetric) */
  if (!rc) rc = sl_output_write_scalar_unit(out, "solids_inventory", r->m.axi ? "m^3/rad" : "m^2", inv, d);
  if (!rc)
    rc = sl_output_write_scalar(out, "solids_conservation_error",
                                r->inventory0 > 0.0 ? (inv + r->outflow - r->inventory0) / r->inventory0 : 0.0, d);
  return rc;
}

static tf_state plane_state(tfp_run *r) {
  tfp_model *m = &r->m;
  return (tf_state){.phi = m->phi,
                    .us = m->us,
                    .uf = m->uf,
                    .p = m->p,
                    .n_cells = m->fv.nc,
                    .n_faces = m->fv.nf,
                    .theta = m->s.granular && !m->s.algebraic ? m->s.theta : NULL,
                    .inventory0 = r->inventory0,
                    .outflow = r->outflow};
}

static int plane_checkpoint(void *self, sl_checkpoint_array *a, int max) {
  tfp_run *r = self;
  r->ck = plane_state(r);
  return tf_checkpoint_arrays(&r->ck, a, max);
}

static int plane_restore(void *self, const sl_checkpoint *ck, sl_diag *d) {
  tfp_run *r = self;
  tf_state st = plane_state(r);
  if (r->m.sw.on)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[two_fluid] swirl: a checkpoint does not hold the swirl; run the scene "
                       "from its start");
  int rc = tf_checkpoint_restore(ck, "2-D two_fluid (the same grid)", &st, d);
  if (!rc && st.theta) memcpy(r->m.s.theta_new, r->m.s.theta, (size_t)r->m.fv.nc * sizeof *r->m.s.theta);
  if (!rc) r->inventory0 = st.inventory0, r->outflow = st.outflow;
  if (!rc && r->m.column) tfp_column_restored(&r->m);
  return rc;
}

/* ---- the time loop ------------------------------------------------------------------ */

static int plane_step(void *self, sl_step *s, int *iterations, sl_diag *d) {
  tfp_run *r = self;
  int rc = tfp_step(&r->m, s->t, s->dt, d);
  *iterations = r->m.iterations_trial;
  r->iterations += r->m.iterations_trial;
  return sl_step_code(rc);
}

static void plane_accept(void *self, const sl_step *s, int *steady) {
  tfp_run *r = self;
  tfp_model *m = &r->m;
  double rate = 0.0, *sw, dt = s->dt;
  for (int c = 0; c < m->fv.nc; ++c) rate = fmax(rate, fabs(m->phi_new[c] - m->phi[c]) / dt);
  sw = m->phi, m->phi = m->phi_new, m->phi_new = sw;
  sw = m->p, m->p = m->p_new, m->p_new = sw;
  sw = m->us, m->us = m->us_new, m->us_new = sw;
  sw = m->uf, m->uf = m->uf_new, m->uf_new = sw;
  if (m->s.granular) memcpy(m->s.theta, m->s.theta_new, (size_t)m->fv.nc * sizeof *m->s.theta);
  if (m->sw.on) sw = m->sw.om, m->sw.om = m->sw.om_new, m->sw.om_new = sw;
  r->outflow += m->outflow_trial;
  r->substeps += m->substeps_trial, ++r->advances;
  m->accepted_substeps = m->last_substeps;
  m->col_j = m->col_j_new;
  *steady = r->steady_tol > 0.0 && rate < r->steady_tol;
}

/* [two_fluid] swirl: axisymmetric only, no wall-stress solids (their slip along theta is not modelled); a wall's
   angular_velocity only with it. */
static int swirl_setup(tfp_run *r, sl_diag *d) {
  const sl_scene *sc = r->sc;
  char at[400];
  for (int k = 0; k < r->mesh->n_boundaries; ++k) {
    const sl_src *src = sl_scene_src(sc, &r->b[k].angular_velocity);
    if (src && !r->cfg->swirl)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [boundary.%s] angular_velocity: only with [two_fluid] swirl = true",
                         src->file, src->line, r->mesh->boundary_names[k]);
    if (r->cfg->swirl && r->b[k].type == TFP_WALL && r->b[k].solids == TFP_SOLIDS_WALL_STRESS)
      return sl_diag_set(d, SL_EBADINPUT,
                         "[boundary.%s] solids = wall_stress: [two_fluid] swirl takes walls that "
                         "hold the solids or let them slip (no_slip, free_slip)",
                         r->mesh->boundary_names[k]);
  }
  if (r->cfg->centrifugal && !r->cfg->swirl)
    return sl_diag_set(d, SL_EBADINPUT, "%s: [two_fluid] centrifugal: only with swirl = true",
                       sl_scene_where(sc, &r->cfg->centrifugal, at, sizeof at));
  r->m.centrifugal = r->cfg->centrifugal;
  if (!r->cfg->swirl) return 0;
  if (r->m.centrifugal) { /* the velocity scale of the step's convergence: at least the fastest wall's swirl
                             (a round-off meridional flow has none of its own to compare with) */
    const sl_tensor_grid *g = &r->m.grid;
    for (int side = 0; side < 4; ++side)
      for (int k = 0; k < (side < 2 ? g->ny : g->nx); ++k) {
        const tfp_boundary *b = &r->m.b[g->side_tag[side][k]];
        double rw = side == SL_SIDE_LEFT ? g->xf[0] : side == SL_SIDE_RIGHT ? g->xf[g->nx] : g->xf[k + 1];
        if (b->type == TFP_WALL) r->m.c.v_ref = fmax(r->m.c.v_ref, fabs(b->angular_velocity) * rw);
      }
    for (int k = 0; k < r->m.n_bodies; ++k) /* each body's outer radius */
      r->m.c.v_ref = fmax(r->m.c.v_ref, fabs(r->m.b[r->m.n_b - r->m.n_bodies + k].angular_velocity) * r->m.body_r1[k]);
  }
  if (!r->m.axi)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: [two_fluid] swirl: only an axisymmetric scene has a swirl "
                       "([scene] geometry = axisymmetric)",
                       sl_scene_where(sc, &r->cfg->swirl, at, sizeof at));
  if (r->cfg->column_form)
    return sl_diag_set(d, SL_EBADINPUT, "%s: [two_fluid] swirl: not with column_form",
                       sl_scene_where(sc, &r->cfg->swirl, at, sizeof at));
  return tfp_swirl_setup(&r->m, r->linear, d);
}

static void release(tfp_run *r) {
  free(r->cellbuf);
  free(r->ball), free(r->m.body_cells);
  sl_point_release(&r->m.c.drag.pc), sl_point_release(&r->m.c.ps.pc);
  tfp_dispersion_free(&r->m.disp);
  tfp_swirl_free(&r->m.sw);
  tfp_free(&r->m);
  free(r);
}

static int plane_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  tfp_run *r = calloc(1, sizeof *r);
  if (!r) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  r->sc = sc, r->cfg = sc->config, r->mesh = sc->mesh, r->linear = "klu";
  r->m.axi = sc->geometry == 2;
  int rc = 0;
  if (r->mesh->dim != 2)
    rc = sl_diag_set(d, SL_EBADINPUT, "[scene] geometry = %s needs a 2-D mesh", r->m.axi ? "axisymmetric" : "planar");
  if (!rc && (rc = sl_tensor_grid_from_mesh(r->mesh, &r->m.grid, d)))
    rc = sl_diag_prefix(d, rc, "[mesh] (the 2-D two_fluid model's staggered grid)");
  if (!rc) rc = tf_scene_physics(sc, r->cfg, 2, &r->m.c, r->m.g, &r->steady_tol, d);
  if (!rc) rc = boundaries(r, d);
  r->m.b = r->b;
  if (!rc) r->m.n_b = r->mesh->n_boundaries;
  if (!rc) rc = tfp_body_bind(&r->m, sc, r->cfg, r->b, r->mesh->n_boundaries, &r->ball, d);
  if (!rc) rc = tfp_setup(&r->m, d);
  if (!rc) rc = tfp_solids_bind(&r->m, sc, r->cfg, d);
  if (!rc && r->m.n_bodies && r->m.s.granular && !r->m.s.algebraic)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: not with a transported granular temperature", r->m.body_where[0]);
  if (!rc) rc = tfp_dispersion_bind(&r->m, sc, r->cfg, d);
  /* the phases' convective acceleration, off by default as in the 1-D column (which has none) */
  r->m.convection = sc->flow.convection;
  if (!rc && !(r->cellbuf = calloc(2 * (size_t)r->m.fv.nc, sizeof *r->cellbuf)))
    rc = sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  if (!rc) rc = initial_state(r, d);
  if (!rc)
    rc = sl_scene_linsolve_general(sc, r->m.n_unknowns,
                                   "the coupled two-fluid matrix (both phases' velocities and the pressure) is "
                                   "nonsymmetric",
                                   &r->m.ls, &r->linear, d);
  if (!rc) r->m.band_allowed = sc->solver.linear == 0 && strcmp(r->linear, "petsc") != 0; /* auto: the fast path */
  if (!rc) { /* the velocity scale: the Stokes velocity, or the largest inflow at t = 0 */
    for (int k = 0; k < r->mesh->n_boundaries; ++k) {
      if (r->b[k].type != TFP_INLET) continue;
      const sl_tensor_grid *g = &r->m.grid;
      for (int i = 0; i <= g->nx; ++i)
        for (int j = 0; j <= g->ny; ++j) {
          double v[4] = {g->xf[i], g->yf[j], 0.0, r->m.c.case_index}, U = fabs(sl_expr_eval(r->b[k].velocity.e, v));
          if (isfinite(U)) r->m.c.v_ref = fmax(r->m.c.v_ref, U);
        }
    }
  }
  if (!rc) rc = swirl_setup(r, d);
  if (!rc) rc = tfp_boundary_values(&r->m, 0.0, r->m.phi, d);
  if (!rc && r->cfg->column_form) {
    char at[400];
    rc = tfp_column_start(&r->m, sl_scene_src(sc, &r->cfg->velocity_fluid) != NULL,
                          sl_scene_where(sc, &r->cfg->column_form, at, sizeof at), d);
  }
  unsigned mask = 0;
  unsigned all = F_PHI | F_US | F_UF | F_P | (r->m.c.ps.c ? F_PS : 0) | (r->m.s.granular ? F_THETA : 0) |
                 (r->m.sw.on ? F_SWF | F_SWS : 0);
  if (!rc) rc = sl_scene_output_fields(sc, all, &mask, d);
  r->fields = (int)mask;
  if (rc) {
    release(r);
    return rc;
  }
  r->inventory0 = tfp_inventory(&r->m, r->m.phi); /* a restart reads it from the checkpoint */
  snprintf(r->steady_text, sizeof r->steady_text, "(largest dphi/dt below %g per s)", r->steady_tol);
  *info = (sl_model_info){.integrator = SL_INTEGRATE_FIXED, .steady_text = r->steady_text};
  *self = r;
  return 0;
}

static void plane_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  tfp_run *r = self;
  st->cpu_coupled = r->m.transport_cpu, st->cpu_flow = fmax(res->solve - r->m.transport_cpu, 0.0);
  if (r->m.ls) st->linear = tfp_linear_stats(&r->m), st->has_linear = 1;
  if (r->advances) {
    double base = r->inventory0, err = base > 0.0 ? (tfp_inventory(&r->m, r->m.phi) + r->outflow - base) / base : 0.0;
    double pmax = 0.0;
    for (int c = 0; c < r->m.fv.nc; ++c) pmax = fmax(pmax, r->m.phi[c]);
    snprintf(st->coupling_summary, sizeof st->coupling_summary,
             "two_fluid (2-D staggered, %d x %d): %.1f iterations and %.1f transport sub-steps per step, solids "
             "conservation error %.1e, max phi %.4f (phi_max %.4g)",
             r->m.fv.nx, r->m.fv.ny, (double)r->iterations / (double)r->advances,
             (double)r->substeps / (double)r->advances, err, pmax, r->m.c.phi_max);
  }
  if (r->m.ls)
    snprintf(st->linear_summary, sizeof st->linear_summary, "%s, %d unknowns", tfp_linear_name(&r->m, r->linear),
             r->m.n_unknowns);
}

static void plane_destroy(void *self) { release(self); }

const sl_model_ops sl_two_fluid_plane_ops = {.setup = plane_setup,
                                             .step = plane_step,
                                             .accept = plane_accept,
                                             .write_mesh = plane_write_mesh,
                                             .write = plane_write,
                                             .checkpoint = plane_checkpoint,
                                             .restore = plane_restore,
                                             .stats = plane_stats,
                                             .destroy = plane_destroy};
