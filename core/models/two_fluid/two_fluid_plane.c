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
 *           solids are held (u_s = 0); tangential velocities 0
 *   outlet  pressure (default 0); velocities free (zero normal gradient),
 *           solids leave where they are carried out
 *   periodic both opposite sides (left and right, or bottom and top; an
 *           axisymmetric scene: bottom and top only) are this type: what
 *           leaves one enters the other; no mean pressure gradient along it
 *
 * Output: cell fields phi, velocity_solid, velocity_fluid, pressure,
 * solids_pressure, theta (with [closure.granular]); scalars
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

#include "core/scene/mesh.h"
#include "core/scene/output.h"
#include "core/scene/solver.h"
#include "core/models/two_fluid/two_fluid.h"
#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/time/fixed_step.h"

enum { F_PHI = 1, F_US = 2, F_UF = 4, F_P = 8, F_PS = 16, F_THETA = 32 };
static const char *const field_names[] = {"phi",      "velocity_solid",  "velocity_fluid",
                                          "pressure", "solids_pressure", "theta"};

typedef struct tfp_run {
  sl_ini *ini;
  sl_ns_result *res;
  sl_mesh *mesh;
  tfp_model m;
  tfp_boundary *b; /* [n_boundaries] */
  int has_inlet, has_outlet;
  double steady_tol, inventory0, outflow;
  long substeps, iterations, advances;
  sl_output *out;
  int fields;
  double *cellbuf; /* [2 n_cells] output scratch in mesh cell order */
  char params[5][1024];
} tfp_run;

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* ---- scene ------------------------------------------------------------------- */

static int boundaries(tfp_run *r, sl_diag *d) {
  const sl_mesh *mesh = r->mesh;
  r->b = calloc((size_t)mesh->n_boundaries, sizeof *r->b);
  if (!r->b) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  for (int s = 0; s < r->ini->n_sections; ++s) { /* every [boundary.X] names a mesh boundary */
    const sl_ini_section *sec = &r->ini->sections[s];
    int id;
    if (strncmp(sec->name, "boundary.", 9) == 0 && sl_mesh_boundary_id(mesh, sec->name + 9, &id, d))
      return sl_diag_prefix(d, SL_EBADINPUT, "%s:%d: [%s]", sec->file, sec->line, sec->name);
  }
  for (int k = 0; k < mesh->n_boundaries; ++k) {
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", mesh->boundary_names[k]);
    static const char *const keys[] = {"type", "velocity", "pressure", "solids"};
    int rc = 0;
    if (sl_ini_find_section(r->ini, sec) && (rc = sl_ini_check_keys(r->ini, sec, keys, 4, d))) return rc;
    tfp_boundary *b = &r->b[k];
    if ((rc = sl_ini_get_choice(r->ini, sec, "type", 0, TFP_WALL, "wall|slip|axis|inlet|outlet|periodic", &b->type,
                                d)))
      return rc;
    const sl_ini_entry *ve = sl_ini_find(r->ini, sec, "velocity"), *pe = sl_ini_find(r->ini, sec, "pressure");
    const sl_ini_entry *se = sl_ini_find(r->ini, sec, "solids");
    if (ve && b->type != TFP_INLET && b->type != TFP_WALL)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] velocity: only an inlet (the inflow) or a wall (its speed "
                                          "along itself) takes a velocity", ve->file, ve->line, sec);
    if (pe && b->type != TFP_OUTLET)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] pressure: only an outlet takes a pressure", pe->file,
                         pe->line, sec);
    if (se && b->type != TFP_WALL)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] solids: only a wall takes it (no_slip | free_slip | "
                                          "wall_stress)", se->file, se->line, sec);
    if (b->type == TFP_WALL &&
        (rc = sl_ini_get_choice(r->ini, sec, "solids", 0, TFP_SOLIDS_NO_SLIP, "no_slip|free_slip|wall_stress",
                                &b->solids, d)))
      return rc;
    if (b->type == TFP_WALL && ve) {
      static const char *const vars[] = {"x", "y", "t", "case"};
      if ((rc = sl_expr_compile(ve->value, vars, 4, &b->velocity, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] velocity", ve->file, ve->line, sec);
    }
    if (b->type == TFP_AXIS && !r->m.axi)
      return sl_diag_set(d, SL_EBADINPUT, "[%s] type = axis: only an axisymmetric scene has an axis", sec);
    if (b->type == TFP_INLET) {
      if (!ve)
        return sl_diag_set(d, SL_EBADINPUT, "[%s] velocity: an inlet needs the superficial fluid velocity entering "
                                            "(m/s), an expression of x, y, t and case", sec);
      static const char *const vars[] = {"x", "y", "t", "case"};
      if ((rc = sl_expr_compile(ve->value, vars, 4, &b->velocity, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] velocity", ve->file, ve->line, sec);
      r->has_inlet = 1;
    }
    if (b->type == TFP_OUTLET) {
      if ((rc = sl_ini_get_real(r->ini, sec, "pressure", 0, 0.0, -1e12, 1e12, &b->pressure, d))) return rc;
      r->has_outlet = 1;
    }
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
      return sl_diag_set(d, SL_EBADINPUT, "type = periodic: the %s sides must both be periodic, wholly (%d of %d and "
                                          "%d of %d faces are)", pair[dir], count[0], n, count[1], n);
    if (dir == 0 && r->m.axi)
      return sl_diag_set(d, SL_EBADINPUT, "type = periodic: an axisymmetric scene is periodic along its axis only "
                                          "(bottom and top)");
    if ((dir == 0 ? gp->nx : gp->ny) < 2)
      return sl_diag_set(d, SL_EBADINPUT, "type = periodic: the %s sides need at least 2 cells between them",
                         pair[dir]);
    r->m.periodic[dir] = 1;
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
  static const char *const keys_all[] = {"phi", "porosity", "velocity_fluid", "velocity_solid", "theta"};
  int rc0 = sl_ini_check_keys(r->ini, "initial", keys_all, 5, d);
  if (rc0) return rc0;
  const sl_ini_entry *te = sl_ini_find(r->ini, "initial", "theta");
  if (te && !(r->m.s.granular && !r->m.s.algebraic))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] theta: only a transported granular temperature takes it "
                                        "([closure.granular] with [two_fluid] granular_temperature = transport)",
                       te->file, te->line);
  if (te) { /* theta in the cells, m^2/s^2 (default 1e-6) */
    static const char *const tvars[] = {"x", "y", "case"};
    sl_expr *tx;
    int trc = sl_expr_compile(te->value, tvars, 3, &tx, d);
    if (trc) return sl_diag_prefix(d, trc, "%s:%d: [initial] theta", te->file, te->line);
    for (int c = 0; c < r->m.nc && !trc; ++c) {
      double xy[3] = {r->m.xc[c % r->m.nx], r->m.yc[c / r->m.nx], r->m.c.case_index}, th = sl_expr_eval(tx, xy);
      if (!(th > 0.0 && th < 1e4))
        trc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] theta = %g at (%g, %g): allowed 0 < theta < 1e4 m^2/s^2",
                          te->file, te->line, th, xy[0], xy[1]);
      r->m.s.theta[c] = r->m.s.theta_new[c] = th;
    }
    sl_expr_free(tx);
    if (trc) return trc;
  } else if (r->m.s.granular && !r->m.s.algebraic) {
    for (int c = 0; c < r->m.nc; ++c) r->m.s.theta[c] = r->m.s.theta_new[c] = 1e-6;
  }
  const sl_ini_entry *e = sl_ini_find(r->ini, "initial", "phi"), *en = sl_ini_find(r->ini, "initial", "porosity");
  if (e && en)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] porosity and phi both given: set one", en->file, en->line);
  if (!e && !en)
    return sl_diag_set(d, SL_EBADINPUT, "[initial] phi (or porosity): the two_fluid model needs the initial solids "
                                        "fraction, an expression of x, y and case");
  const sl_ini_entry *use = e ? e : en;
  static const char *const vars[] = {"x", "y", "case"};
  sl_expr *ex;
  int rc = sl_expr_compile(use->value, vars, 3, &ex, d);
  if (rc) return sl_diag_prefix(d, rc, "%s:%d: [initial] %s", use->file, use->line, use->key);
  tfp_model *m = &r->m;
  for (int c = 0; c < m->nc && !rc; ++c) {
    double xy[3] = {m->xc[c % m->nx], m->yc[c / m->nx], m->c.case_index}, v = sl_expr_eval(ex, xy);
    double phi = e ? v : 1.0 - v;
    if (!(phi >= 0.0 && phi <= m->c.phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s = %g at (%g, %g): allowed %s = %g", use->file,
                       use->line, use->key, v, xy[0], xy[1],
                       e ? "0 <= phi <= phi_max" : "1 - phi_max <= porosity <= 1, phi_max", m->c.phi_max);
    m->phi[c] = phi;
  }
  sl_expr_free(ex);
  if (rc) return rc;
  /* the phases' velocities (default at rest): each face takes its normal component at its centre */
  static const char *const keys[2] = {"velocity_fluid", "velocity_solid"};
  for (int phase = 0; phase < 2; ++phase) {
    const sl_ini_entry *ve = sl_ini_find(r->ini, "initial", keys[phase]);
    if (!ve) continue;
    sl_expr *comp[2] = {NULL, NULL};
    int n = 0;
    if ((rc = sl_expr_compile_list(ve->value, vars, 3, 2, comp, &n, d)))
      return sl_diag_prefix(d, rc, "%s:%d: [initial] %s", ve->file, ve->line, ve->key);
    if (n != 2) {
      for (int k = 0; k < n; ++k) sl_expr_free(comp[k]);
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s: two components (along x, along y), expressions of "
                                          "x, y and case; %d given", ve->file, ve->line, ve->key, n);
    }
    double *u = phase ? m->us : m->uf;
    for (int f = 0; f < m->nf; ++f) {
      int dir = f >= m->nfx, i = dir ? (f - m->nfx) % m->nx : f % (m->nx + 1);
      int j = dir ? (f - m->nfx) / m->nx : f / (m->nx + 1);
      double xy[3] = {dir ? m->xc[i] : m->grid.xf[i], dir ? m->grid.yf[j] : m->yc[j], m->c.case_index};
      u[f] = sl_expr_eval(comp[dir], xy);
      if (!isfinite(u[f])) rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s is not finite at (%g, %g)",
                                            ve->file, ve->line, ve->key, xy[0], xy[1]);
    }
    sl_expr_free(comp[0]), sl_expr_free(comp[1]);
    if (rc) return rc;
  }
  return 0;
}

/* ---- output, checkpoint, restart --------------------------------------------------- */

static int open_output(tfp_run *r, const sl_ns_run_opts *o, sl_diag *d) {
  unsigned mask;
  unsigned all = F_PHI | F_US | F_UF | F_P | (r->m.c.ps.c ? F_PS : 0) | (r->m.s.granular ? F_THETA : 0);
  int rc = sl_scene_output_path(r->ini, o->output, o->scene_path, r->res->output_path, sizeof r->res->output_path, d);
  if (!rc) rc = sl_scene_output_fields(r->ini, field_names, 6, all, &mask, d);
  if (rc) return rc;
  r->fields = (int)mask;
  if ((rc = sl_output_open(&r->out, r->res->output_path, d))) return rc;
  const sl_mesh *m = r->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * m->nv_per_cell * sizeof *cells);
  if (!cells) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  for (int i = 0; i < m->n_cells * m->nv_per_cell; ++i) cells[i] = m->cell_vertices[i];
  rc = sl_output_write_mesh(r->out, 2, m->n_vertices, m->xy, m->n_cells, m->nv_per_cell, cells, "Quadrilateral", d);
  free(cells);
  if (rc) return rc;
  const sl_closure *extra[3] = {r->m.s.visc_c, r->m.s.gran_c, r->m.s.wall_c};
  static const char *const roles[3] = {"closure.viscosity", "closure.granular", "closure.wall_stress"};
  return tf_write_provenance(r->out, r->ini, o, &r->m.c, extra, roles, 3, r->params, d);
}

/* A grid-ordered cell field into mesh cell order (components 1 or 2). */
static const double *to_mesh_order(tfp_run *r, const double *a, const double *b) {
  const tfp_model *m = &r->m;
  for (int c = 0; c < m->nc; ++c) {
    int mc = m->grid.mesh_cell[c];
    if (b) r->cellbuf[2 * mc] = a[c], r->cellbuf[2 * mc + 1] = b[c];
    else r->cellbuf[mc] = a[c];
  }
  return r->cellbuf;
}

static int write_state(tfp_run *r, double t, sl_diag *d) {
  double t0 = cpu_now();
  tfp_model *m = &r->m;
  int rc = sl_output_begin_step(r->out, t, d);
  if (!rc && (r->fields & F_PHI))
    rc = sl_output_write_field(r->out, "phi", SL_CENTRE_CELL, 1, to_mesh_order(r, m->phi, NULL), d);
  /* velocities at the cell centres: the mean of the two faces of each family */
  double *vx = m->x, *vy = m->x + m->nc; /* scratch between steps */
  for (int phase = 0; phase < 2 && !rc; ++phase) {
    if (!(r->fields & (phase ? F_US : F_UF))) continue;
    const double *u = phase ? m->us : m->uf;
    for (int c = 0; c < m->nc; ++c) {
      int i = c % m->nx, j = c / m->nx, w = i + (m->nx + 1) * j, s = m->nfx + i + m->nx * j;
      vx[c] = 0.5 * (u[w] + u[w + 1]), vy[c] = 0.5 * (u[s] + u[s + m->nx]);
    }
    rc = sl_output_write_field(r->out, phase ? "velocity_solid" : "velocity_fluid", SL_CENTRE_CELL, 2,
                               to_mesh_order(r, vx, vy), d);
  }
  if (!rc && (r->fields & F_P))
    rc = sl_output_write_field(r->out, "pressure", SL_CENTRE_CELL, 1, to_mesh_order(r, m->p, NULL), d);
  if (!rc && (r->fields & F_PS) && m->c.ps.c) {
    if ((rc = tf_closure_eval(&m->c.ps, m->nc, m->phi, NULL, vx, NULL, d)) == 0)
      rc = sl_output_write_field(r->out, "solids_pressure", SL_CENTRE_CELL, 1, to_mesh_order(r, vx, NULL), d);
  }
  if (!rc && (r->fields & F_THETA) && m->s.granular)
    rc = sl_output_write_field(r->out, "theta", SL_CENTRE_CELL, 1, to_mesh_order(r, m->s.theta, NULL), d);
  for (int b = 0; b < m->n_b && !rc; ++b) {
    if (r->b[b].type != TFP_WALL) continue;
    static const char *const what[4] = {"wall_shear_stress_fluid", "wall_shear_stress_solid", "wall_slip",
                                        "bagnold_number"};
    for (int k = 0; k < 4 && !rc; ++k) {
      if (k == 3 && !(r->b[b].solids == TFP_SOLIDS_WALL_STRESS && sl_point_has_output(&m->s.wall, "bagnold_number")))
        continue;
      char name[300];
      snprintf(name, sizeof name, "%s_%s", what[k], r->mesh->boundary_names[b]);
      rc = sl_output_write_scalar(r->out, name, m->wall_stats[5 * b + k], d);
    }
  }
  double inv = tfp_inventory(m, m->phi);
  if (!rc) rc = sl_output_write_scalar(r->out, "solids_inventory", inv, d);
  if (!rc)
    rc = sl_output_write_scalar(r->out, "solids_conservation_error",
                                r->inventory0 > 0.0 ? (inv + r->outflow - r->inventory0) / r->inventory0 : 0.0, d);
  if (!rc) rc = sl_output_end_step(r->out, d);
  r->res->output += cpu_now() - t0;
  return rc;
}

static tf_state plane_state(tfp_run *r) {
  tfp_model *m = &r->m;
  return (tf_state){.phi = m->phi, .us = m->us, .uf = m->uf, .p = m->p, .n_cells = m->nc, .n_faces = m->nf,
                    .theta = m->s.granular && !m->s.algebraic ? m->s.theta : NULL,
                    .inventory0 = r->inventory0, .outflow = r->outflow, .rejected = r->res->rejected_steps};
}

static int write_checkpoint(tfp_run *r, double t, double dt, long step_no, sl_diag *d) {
  tf_state st = plane_state(r);
  return tf_checkpoint_write(r->out, &st, t, dt, step_no, d);
}

static int plane_restore(void *user, const char *path, double *t, double *dt, long *step_no, sl_diag *d) {
  tfp_run *r = user;
  tf_state st = plane_state(r);
  int rc = tf_checkpoint_restore(path, "2-D two_fluid (the same grid)", &st, t, dt, step_no, d);
  if (!rc && st.theta) memcpy(r->m.s.theta_new, r->m.s.theta, (size_t)r->m.nc * sizeof *r->m.s.theta);
  r->inventory0 = st.inventory0, r->outflow = st.outflow, r->res->rejected_steps = st.rejected;
  return rc;
}

/* ---- the time loop ------------------------------------------------------------------ */

static int plane_step(void *user, double t, double dt, int *iterations, int *fatal, sl_diag *d) {
  tfp_run *r = user;
  int rc = tfp_step(&r->m, t, dt, d);
  *iterations = r->m.iterations_trial, *fatal = 0;
  r->iterations += r->m.iterations_trial;
  return rc;
}

static void plane_accept(void *user, double dt, int *steady) {
  tfp_run *r = user;
  tfp_model *m = &r->m;
  double rate = 0.0, *sw;
  for (int c = 0; c < m->nc; ++c) rate = fmax(rate, fabs(m->phi_new[c] - m->phi[c]) / dt);
  sw = m->phi, m->phi = m->phi_new, m->phi_new = sw;
  sw = m->p, m->p = m->p_new, m->p_new = sw;
  sw = m->us, m->us = m->us_new, m->us_new = sw;
  sw = m->uf, m->uf = m->uf_new, m->uf_new = sw;
  if (m->s.granular) memcpy(m->s.theta, m->s.theta_new, (size_t)m->nc * sizeof *m->s.theta);
  r->outflow += m->outflow_trial;
  r->substeps += m->substeps_trial, ++r->advances;
  m->accepted_substeps = m->last_substeps;
  *steady = r->steady_tol > 0.0 && rate < r->steady_tol;
}

static int plane_write(void *user, double t, double dt_next, long step_no, sl_diag *d) {
  tfp_run *r = user;
  int rc = write_state(r, t, d);
  return rc ? rc : write_checkpoint(r, t, dt_next, step_no, d);
}

static void release(tfp_run *r) {
  free(r->cellbuf), free(r->m.c.drag.buf), free(r->m.c.ps.buf);
  if (r->b)
    for (int k = 0; k < r->mesh->n_boundaries; ++k) sl_expr_free(r->b[k].velocity);
  free(r->b);
  sl_closure_destroy(r->m.c.drag.c);
  sl_closure_destroy(r->m.c.ps.c);
  tfp_free(&r->m);
  sl_mesh_destroy(r->mesh);
}

int sl_two_fluid_plane_run(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res,
                           sl_diag *d) {
  memset(res, 0, sizeof *res);
  tfp_run r = {.ini = ini, .res = res};
  double c0 = cpu_now();
  int geometry = 0;
  const char *linear = "klu";
  int rc = sl_ini_get_choice(ini, "scene", "geometry", 0, 0, "line|planar|axisymmetric", &geometry, d);
  r.m.axi = geometry == 2;
  if (!rc) rc = sl_scene_mesh(ini, &r.mesh, d);
  if (!rc && r.mesh->dim != 2)
    rc = sl_diag_set(d, SL_EBADINPUT, "[scene] geometry = %s needs a 2-D mesh", r.m.axi ? "axisymmetric" : "planar");
  if (!rc && (rc = sl_tensor_grid_from_mesh(r.mesh, &r.m.grid, d)))
    rc = sl_diag_prefix(d, rc, "[mesh] (the 2-D two_fluid model's staggered grid)");
  if (!rc) rc = tf_scene_physics(ini, reg, 2, &r.m.c, r.m.g, &r.steady_tol, d);
  if (!rc) rc = boundaries(&r, d);
  r.m.b = r.b;
  if (!rc) r.m.n_b = r.mesh->n_boundaries;
  if (!rc) rc = tfp_setup(&r.m, d);
  if (!rc) rc = tfp_solids_bind(&r.m, ini, reg, d);
  /* the phases' convective acceleration, off by default as in the 1-D column (which has none) */
  if (!rc) rc = sl_ini_get_bool(ini, "flow", "convection", 0, 0, &r.m.convection, d);
  if (!rc && !(r.cellbuf = calloc(2 * (size_t)r.m.nc, sizeof *r.cellbuf)))
    rc = sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  if (!rc) rc = initial_state(&r, d);
  if (!rc) rc = sl_scene_linsolve(ini, "klu", "colamd", &r.m.ls, &linear, d);
  if (!rc) { /* the velocity scale: the Stokes velocity, or the largest inflow at t = 0 */
    for (int k = 0; k < r.mesh->n_boundaries; ++k) {
      if (r.b[k].type != TFP_INLET) continue;
      const sl_tensor_grid *g = &r.m.grid;
      for (int i = 0; i <= g->nx; ++i)
        for (int j = 0; j <= g->ny; ++j) {
          double v[4] = {g->xf[i], g->yf[j], 0.0, r.m.c.case_index}, U = fabs(sl_expr_eval(r.b[k].velocity, v));
          if (isfinite(U)) r.m.c.v_ref = fmax(r.m.c.v_ref, U);
        }
    }
  }
  if (!rc) rc = tfp_boundary_values(&r.m, 0.0, r.m.phi, d);
  if (!rc) rc = open_output(&r, o, d);
  res->cpu_setup = cpu_now() - c0;
  if (!rc) {
    char steady_text[96];
    snprintf(steady_text, sizeof steady_text, "(largest dphi/dt below %g per s)", r.steady_tol);
    sl_fixed_step_model fm = {.user = &r, .step = plane_step, .accept = plane_accept, .write = plane_write,
                              .restore = plane_restore, .steady_text = steady_text};
    r.inventory0 = tfp_inventory(&r.m, r.m.phi); /* a restart reads it from the checkpoint */
    rc = sl_fixed_step_run(ini, &fm, o, res, d);
  }
  res->cpu_coupled = r.m.transport_cpu, res->cpu_flow = fmax(res->solve - r.m.transport_cpu, 0.0);
  res->cpu_output = res->output;
  if (r.m.ls) res->linear = *sl_linsolve_get_stats(r.m.ls);
  if (r.out) {
    sl_output_stats(r.out, &res->output_times, &res->output_datasets, &res->output_bytes);
    sl_diag d2;
    int crc = sl_output_close(r.out, rc ? &d2 : d);
    if (!rc) rc = crc;
  }
  if (r.advances) {
    double base = r.inventory0, err = base > 0.0 ? (tfp_inventory(&r.m, r.m.phi) + r.outflow - base) / base : 0.0;
    double pmax = 0.0;
    for (int c = 0; c < r.m.nc; ++c) pmax = fmax(pmax, r.m.phi[c]);
    snprintf(res->coupling_summary, sizeof res->coupling_summary,
             "two_fluid (2-D staggered, %d x %d): %.1f iterations and %.1f transport sub-steps per step, solids "
             "conservation error %.1e, max phi %.4f (phi_max %.4g)",
             r.m.nx, r.m.ny, (double)r.iterations / (double)r.advances, (double)r.substeps / (double)r.advances, err,
             pmax, r.m.c.phi_max);
  }
  if (r.m.ls) snprintf(res->linear_summary, sizeof res->linear_summary, "%s, %d unknowns", linear, r.m.n_unknowns);
  release(&r);
  return rc;
}
