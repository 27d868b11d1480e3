/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The 1-D two-fluid model (see two_fluid.h): the scene, the time loop and
 * the output. One step is two_fluid_step.c (the 2-D model's step on n x 1 cells). */
#include "core/models/two_fluid/two_fluid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/models/two_fluid/liquefaction.h"
#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/plugin/kinds.h"
#include "core/scene/mesh.h"

enum { F_PHI = 1, F_US = 2, F_UF = 4, F_P = 8 };
enum { TF_MAX_LEVELS = 8 };

typedef struct tf_run {
  const sl_scene *sc;
  const tf_config *cfg;
  const sl_mesh *mesh;
  tf_column c;
  int *face_vertex; /* [n+1] */
  int *cell_of;     /* [n]: the mesh cell of column cell i */
  double *node;     /* [n_vertices] scratch for node fields */
  int fields;
  double inventory0, outflow;
  double steady_tol;
  long substeps, iterations, advances;
  char steady_text[96];
  tf_state ck;                 /* the checkpoint's view of the state */
  char inlet_where[400];       /* file:line: [section] key of the inlet's value */
  double level[TF_MAX_LEVELS]; /* [output] interface */
  int n_levels;
  tf_liquefaction *lq; /* the shaken deposit (liquefaction.h), or NULL */
  long settle_steps;   /* [deposit] settle: its steps and time */
  double settle_time, dt_min;
  char lq_summary[256]; /* the add-on's failure after an accepted step, stopping the next */
  int lq_failed;
} tf_run;

/* ---- the column from the mesh ------------------------------------------------ */

static int column_from_mesh(tf_run *r, sl_diag *d) {
  const sl_mesh *m = r->mesh;
  tf_column *c = &r->c;
  if (m->dim != 1)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[scene] model = two_fluid, geometry = line: the mesh must be 1-D (a 2-D "
                       "mesh takes geometry = planar or axisymmetric)");
  int n = m->n_cells;
  c->n = n;
  r->cell_of = malloc((size_t)n * sizeof *r->cell_of);
  r->face_vertex = malloc((size_t)(n + 1) * sizeof *r->face_vertex);
  if (!r->cell_of || !r->face_vertex) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  int rc = sl_scene_line_chain(m, r->face_vertex, r->cell_of, d);
  if (rc) return sl_diag_prefix(d, rc, "two_fluid");
  c->h = malloc((size_t)n * sizeof *c->h), c->xc = malloc((size_t)n * sizeof *c->xc);
  c->xf = malloc((size_t)(n + 1) * sizeof *c->xf), c->dual = malloc((size_t)(n + 1) * sizeof *c->dual);
  if (!c->h || !c->xc || !c->xf || !c->dual) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int k = 0; k <= n; ++k) c->xf[k] = m->xy[2 * r->face_vertex[k]];
  for (int i = 0; i < n; ++i) c->h[i] = c->xf[i + 1] - c->xf[i], c->xc[i] = 0.5 * (c->xf[i] + c->xf[i + 1]);
  c->dual[0] = 0.5 * c->h[0], c->dual[n] = 0.5 * c->h[n - 1];
  for (int k = 1; k < n; ++k) c->dual[k] = 0.5 * (c->h[k - 1] + c->h[k]);
  return 0;
}

static int boundaries(tf_run *r, sl_diag *d) {
  tf_column *c = &r->c;
  const sl_scene *sc = r->sc;
  const char *names[2];
  int rc = sl_scene_line_ends(r->mesh, r->face_vertex[0], r->face_vertex[c->n], "two_fluid", names, d);
  if (rc) return rc;
  int n_out = 0;
  c->inlet_side = -1;
  for (int side = 0; side < 2; ++side) {
    int id;
    if ((rc = sl_mesh_boundary_id(r->mesh, names[side], &id, d))) return rc;
    const tfc_boundary *b = sl_scene_boundary(sc, id);
    const sl_src *where = sl_scene_boundary_section(sc, id);
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", names[side]);
    c->bc[side] = b->type;
    const sl_src *ve = sl_scene_src(sc, &b->velocity), *ne = sl_scene_src(sc, &b->porosity);
    if (c->bc[side] == TF_INLET) {
      if (c->inlet_side >= 0)
        return sl_diag_set(d, SL_EBADINPUT, "[%s]: a second inlet (1-D: one inlet and one outlet at most)", sec);
      if (!ve == !ne)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s]: an inlet takes either velocity (the superficial fluid "
                           "velocity entering, m/s) or porosity (that of the homogeneous bed the "
                           "inflow holds at rest), an expression of t and case%s",
                           where ? where->file : "(scene)", where ? where->line : 0, sec, ve ? "; not both" : "");
      if (ne && side != (c->below ? 0 : 1))
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] porosity: a bed is held by an inflow from below; this "
                           "inlet is at the top (give its velocity instead)",
                           ne->file, ne->line, sec);
      if (ne && c->rho_s <= c->rho_f)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] porosity: particles no denser than the fluid (%g <= %g "
                           "kg/m3) are not held by an upward flow (give the velocity instead)",
                           ne->file, ne->line, sec, c->rho_s, c->rho_f);
      const sl_src *e = ve ? ve : ne;
      if (ve) c->inlet = b->velocity.e;
      else c->inlet_porosity = b->porosity.e;
      c->inlet_side = side;
      snprintf(r->inlet_where, sizeof r->inlet_where, "%s:%d: [%s] %s", e->file, e->line, sec, e->key);
    }
    if (c->bc[side] == TF_OUTLET) {
      ++n_out;
      c->p_out = b->pressure;
    }
  }
  if (n_out == 2)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[boundary.%s], [boundary.%s]: two outlets leave the 1-D mixture flux "
                       "undetermined; make one an inlet or a wall",
                       names[0], names[1]);
  if (c->inlet_side >= 0 && n_out == 0)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[boundary.%s]: an inlet needs an outlet at the other end (in 1-D the "
                       "mixture flux is the same everywhere)",
                       names[c->inlet_side]);
  return 0;
}

/* [initial] from: phi of the file's last output, in the mesh's cell order. */
static int initial_from_file(tf_run *r, const sl_src *fe, sl_diag *d) {
  tf_column *c = &r->c;
  sl_output_field f;
  int rc = sl_output_read_field(r->cfg->from, "phi", INFINITY, &f, d);
  if (rc) return sl_diag_prefix(d, SL_EBADINPUT, "%s:%d: [initial] from = %s", fe->file, fe->line, r->cfg->from);
  if (f.n != c->n || f.components != 1 || f.centring != SL_CENTRE_CELL)
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s:%d: [initial] from = %s: its phi has %d values, the mesh %d cells (the "
                     "same mesh is needed)",
                     fe->file, fe->line, r->cfg->from, (int)f.n, c->n);
  for (int i = 0; i < c->n && !rc; ++i) {
    double phi = f.values[r->cell_of[i]];
    if (!(phi >= 0.0 && phi <= c->phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] from = %s: phi = %g in cell %d, above phi_max = %g", fe->file,
                       fe->line, r->cfg->from, phi, i, c->phi_max);
    c->phi[i] = phi;
  }
  sl_output_field_free(&f);
  return rc;
}

static int initial_state(tf_run *r, sl_diag *d) {
  tf_column *c = &r->c;
  const sl_src *e = sl_scene_src(r->sc, &r->cfg->phi), *en = sl_scene_src(r->sc, &r->cfg->porosity);
  const sl_src *fe = r->cfg->from && r->cfg->from[0] ? sl_scene_src(r->sc, &r->cfg->from) : NULL;
  if (fe && (e || en))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] from and %s both given: set one", fe->file, fe->line,
                       e ? "phi" : "porosity");
  if (fe) return initial_from_file(r, fe, d);
  if (e && en)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] porosity and phi both given: set one", en->file, en->line);
  if (!e && !en)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[initial] phi (or porosity): the two_fluid model needs the initial solids "
                       "fraction");
  const sl_src *use = e ? e : en;
  const sl_expr *ex = e ? r->cfg->phi.e : r->cfg->porosity.e;
  int rc = 0;
  for (int i = 0; i < c->n && !rc; ++i) {
    double xy[3] = {c->xc[i], 0.0, c->case_index}, v = sl_expr_eval(ex, xy), phi = e ? v : 1.0 - v;
    if (!(phi >= 0.0 && phi <= c->phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s = %g at x = %g: allowed %s = %g", use->file, use->line,
                       use->key, v, c->xc[i], e ? "0 <= phi <= phi_max" : "1 - phi_max <= porosity <= 1, phi_max",
                       c->phi_max);
    c->phi[i] = phi;
  }
  if (rc || c->ps.c) return rc;
  /* A packed layer (phi = phi_max) without a solids pressure: below minimum fluidisation its weight rests on its
     contacts, which nothing here carries; the drag then takes the whole buoyant weight (the pressure drop
     comes out as the bed's weight instead of Ergun's), the solids move into a bed that cannot compact, and the
     step looks steady at once (issue 25: 2649 Pa for Ergun's 1091 Pa at 0.45 U_mf). Refused. */
  for (int i = 0; i < c->n; ++i)
    if (c->phi[i] >= c->phi_max * (1.0 - 1e-9))
      return sl_diag_set(
          d, SL_EBADINPUT,
          "%s:%d: [initial] %s = %g at x = %g is a packed bed (phi = phi_max = %g), and the scene has no "
          "[closure.solids_pressure]: nothing would carry the bed's contact stress, so below minimum "
          "fluidisation its pressure drop and solids velocity would be wrong; add a solids-pressure "
          "closure (e.g. model = pringle_exponential, Pringle 2001) or start below phi_max",
          use->file, use->line, use->key, e ? c->phi[i] : 1.0 - c->phi[i], c->xc[i], c->phi_max);
  return 0;
}

static int allocate(tf_column *c, sl_diag *d) {
  size_t n = (size_t)c->n, f = n + 1;
  double **cells[] = {&c->phi, &c->p, &c->phi_new, &c->p_new, &c->alpha};
  double **faces[] = {&c->u, &c->uf, &c->u_new, &c->uf_new};
  for (size_t i = 0; i < sizeof cells / sizeof cells[0]; ++i)
    if (!(*cells[i] = calloc(n, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (size_t i = 0; i < sizeof faces / sizeof faces[0]; ++i)
    if (!(*faces[i] = calloc(f, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  return 0;
}

static void release(tf_run *r) {
  tf_column *c = &r->c;
  double *all[] = {c->h,     c->xc,    c->xf, c->dual, c->phi,   c->p,      c->phi_new,
                   c->p_new, c->alpha, c->u,  c->uf,   c->u_new, c->uf_new, r->node};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) free(all[i]);
  tf_plane_free(c);
  sl_point_release(&c->drag.pc), sl_point_release(&c->ps.pc);
  tfl_free(r->lq);
  free(r->face_vertex), free(r->cell_of);
  free(r);
}

/* ---- output ----------------------------------------------------------------------- */

static double inventory(const tf_column *c) {
  double s = 0.0;
  for (int i = 0; i < c->n; ++i) s += c->phi[i] * c->h[i];
  return s;
}

/* [output] interface: levels of phi in (0, phi_max], against gravity. */
static int interface_levels(tf_run *r, sl_diag *d) {
  const sl_src *le = sl_scene_src(r->sc, &r->sc->output.interface);
  if (!le) return 0;
  r->n_levels = r->sc->output.interface.n;
  for (int k = 0; k < r->n_levels; ++k) {
    r->level[k] = r->sc->output.interface.v[k];
    if (!(r->level[k] > 0.0 && r->level[k] <= r->c.phi_max))
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [output] interface = %g: a level of phi, allowed 0 < level <= "
                         "phi_max = %g",
                         le->file, le->line, r->level[k], r->c.phi_max);
  }
  if (r->n_levels > 0 && r->c.g == 0.0)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [output] interface: heights are measured against gravity, and the "
                       "scene has none",
                       le->file, le->line);
  return 0;
}

static int column_write_mesh(void *self, sl_output *out, sl_diag *d) {
  tf_run *r = self;
  const sl_mesh *m = r->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * 2 * sizeof *cells);
  if (!cells) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int v = 0; v < m->n_vertices; ++v) r->node[v] = m->xy[2 * v];
  for (int e2 = 0; e2 < 2 * m->n_cells; ++e2) cells[e2] = m->cell_vertices[e2];
  int rc = sl_output_write_mesh(out, 1, m->n_vertices, r->node, m->n_cells, 2, cells, "Polyline", d);
  free(cells);
  return rc;
}

/* The height (along -g) where phi first reaches `level` coming down from the
 * top, linear between cell centres (the same measure as the mixture model's
 * interface_height): the top of a bed or of a settling suspension. NAN when
 * phi stays below the level everywhere. */
static double interface_height(const tf_column *c, double level) {
  const double up = c->below ? 1.0 : -1.0;
  double h_above = NAN, p_above = NAN;
  for (int k = 0; k < c->n; ++k) {
    int i = c->below ? c->n - 1 - k : k;
    double p = c->phi[i], h = up * c->xc[i];
    if (p >= level) return isnan(p_above) ? h : h + (h_above - h) * (p - level) / (p - p_above);
    h_above = h, p_above = p;
  }
  return NAN;
}

/* Cell arrays in the mesh's cell order, face arrays at the mesh's vertices. */
static int column_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)u;
  tf_run *r = self;
  tf_column *c = &r->c;
  int rc = 0;
  double *cellv = r->c.alpha; /* scratch of n cells */
  const double *cf[2] = {c->phi, c->p}, *ff[2] = {c->u, c->uf};
  const int cflag[2] = {F_PHI, F_P}, fflag[2] = {F_US, F_UF};
  const char *cname[2] = {"phi", "pressure"}, *fname[2] = {"velocity_solid", "velocity_fluid"};
  for (int k = 0; k < 2 && !rc; ++k) {
    if (!(r->fields & cflag[k])) continue;
    for (int i = 0; i < c->n; ++i) cellv[r->cell_of[i]] = cf[k][i];
    rc = sl_output_write_field(out, cname[k], SL_CENTRE_CELL, 1, cellv, d);
  }
  for (int k = 0; k < 2 && !rc; ++k) {
    if (!(r->fields & fflag[k])) continue;
    for (int f = 0; f <= c->n; ++f) r->node[r->face_vertex[f]] = ff[k][f];
    rc = sl_output_write_field(out, fname[k], SL_CENTRE_NODE, 1, r->node, d);
  }
  double inv = inventory(c);
  if (!rc) rc = sl_output_write_scalar(out, "solids_inventory", inv, d);
  if (!rc)
    rc = sl_output_write_scalar(out, "solids_conservation_error",
                                r->inventory0 > 0.0 ? (inv + r->outflow - r->inventory0) / r->inventory0 : 0.0, d);
  double j = 0.0;
  if (!rc) rc = tf_mixture_flux(c, t, &j, d);
  if (!rc) rc = sl_output_write_scalar(out, "mixture_flux", j, d);
  if (!rc && r->lq) rc = tfl_write(r->lq, c, out, r->cell_of, cellv, (unsigned)r->fields, t, d);
  for (int k = 0; k < r->n_levels && !rc; ++k) {
    char name[64];
    snprintf(name, sizeof name, "interface_height_%d", k);
    rc = sl_output_write_scalar(out, name, interface_height(c, r->level[k]), d);
    snprintf(name, sizeof name, "interface_level_%d", k);
    if (!rc) rc = sl_output_write_scalar(out, name, r->level[k], d);
  }
  return rc;
}

static int column_checkpoint(void *self, sl_checkpoint_array *a, int max) {
  tf_run *r = self;
  r->ck = (tf_state){.phi = r->c.phi,
                     .us = r->c.u,
                     .uf = r->c.uf,
                     .p = r->c.p,
                     .n_cells = r->c.n,
                     .n_faces = r->c.n + 1,
                     .inventory0 = r->inventory0,
                     .outflow = r->outflow};
  return tf_checkpoint_arrays(&r->ck, a, max);
}

static int column_restore(void *self, const sl_checkpoint *ck, sl_diag *d) {
  tf_run *r = self;
  tf_state st = {.phi = r->c.phi, .us = r->c.u, .uf = r->c.uf, .p = r->c.p, .n_cells = r->c.n, .n_faces = r->c.n + 1};
  int rc = tf_checkpoint_restore(ck, "two_fluid", &st, d);
  if (!rc) r->inventory0 = st.inventory0, r->outflow = st.outflow;
  return rc;
}

/* ---- the model's steps (core/time/loop.h) ------------------------------------------------ */

static int column_step(void *self, sl_step *s, int *iterations, sl_diag *d) {
  tf_run *r = self;
  if (r->lq_failed) return sl_diag_set(d, SL_EFAILED, "%s", r->lq_summary), -SL_EFAILED;
  int rc = r->lq ? tfl_step(r->lq, &r->c, s->t, s->dt, d) : 0;
  if (!rc) rc = tf_step(&r->c, s->t, s->dt, d);
  *iterations = r->c.iterations_trial;
  r->iterations += r->c.iterations_trial;
  return rc == 0 ? 0 : r->c.fatal ? -SL_EFAILED : sl_step_code(rc);
}

static void swap_state(tf_run *r, double dt, int *steady);

static void column_accept(void *self, const sl_step *s, int *steady) {
  tf_run *r = self;
  swap_state(r, s->dt, steady);
  r->dt_min = r->dt_min > 0.0 ? fmin(r->dt_min, s->dt) : s->dt;
  if (r->lq) {
    sl_diag d;
    if (tfl_accept(r->lq, &r->c, s->t, s->dt, &d))
      r->lq_failed = 1, snprintf(r->lq_summary, sizeof r->lq_summary, "%.200s", d.msg);
  }
}

static void swap_state(tf_run *r, double dt, int *steady) {
  tf_column *c = &r->c;
  double rate = 0.0;
  for (int i = 0; i < c->n; ++i) rate = fmax(rate, fabs(c->phi_new[i] - c->phi[i]) / dt);
  double *sw;
  sw = c->phi, c->phi = c->phi_new, c->phi_new = sw;
  sw = c->u, c->u = c->u_new, c->u_new = sw;
  sw = c->uf, c->uf = c->uf_new, c->uf_new = sw;
  sw = c->p, c->p = c->p_new, c->p_new = sw;
  r->outflow += c->outflow_trial;
  r->substeps += c->substeps_trial, ++r->advances;
  c->accepted_substeps = c->last_substeps;
  *steady = r->steady_tol > 0.0 && rate < r->steady_tol;
}

/* [deposit] settle: the column's own steps from [initial]'s state until it is at rest, before t = 0 (Pringle
 * 2001 section 5.4 builds his deposit by settling it out of suspension). A failed step is retried at a quarter
 * of its length and grown back, as the run's steps are. */
static int settle(tf_run *r, sl_diag *d) {
  const tf_lq_config *q = &r->cfg->lq;
  double t = 0.0, h = q->settle_dt;
  int steady = 0;
  const double save_tol = r->steady_tol;
  r->steady_tol = q->settle_tolerance;
  while (t < q->settle && !steady) {
    double hh = fmin(h, q->settle - t);
    int rc = tf_step(&r->c, t, hh, d);
    if (rc) {
      if (r->c.fatal || hh < 1e-6 * q->settle_dt) {
        r->steady_tol = save_tol;
        return sl_diag_prefix(d, rc == SL_EFAILED ? SL_EBADINPUT : rc, "[deposit] settle at t = %g before the run", t);
      }
      h = 0.25 * hh;
      continue;
    }
    swap_state(r, hh, &steady);
    t += hh, ++r->settle_steps;
    if (h < q->settle_dt) h = fmin(q->settle_dt, 2.0 * h);
  }
  r->steady_tol = save_tol;
  r->settle_time = t;
  /* the run starts from rest: the velocities of the settled state */
  r->outflow = 0.0, r->substeps = 0, r->advances = 0, r->iterations = 0;
  return 0;
}

static int column_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  tf_run *r = calloc(1, sizeof *r);
  if (!r) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  r->sc = sc, r->cfg = sc->config, r->mesh = sc->mesh;
  unsigned mask = 0; /* unset when an earlier step fails */
  int rc = column_from_mesh(r, d);
  if (!rc) rc = tf_scene_physics(sc, r->cfg, 1, &r->c, NULL, &r->steady_tol, d);
  int shaken = !rc && tfl_wanted(sc, &r->c);
  if (!rc)
    rc = sl_scene_output_fields(
        sc,
        F_PHI | F_US | F_UF | F_P |
            (shaken ? TFL_F_NBAR | TFL_F_RATIO | TFL_F_EXCESS | TFL_F_RU | TFL_F_STRAIN | TFL_F_PS : 0),
        &mask, d);
  r->fields = (int)mask;
  if (!rc) rc = boundaries(r, d);
  if (!rc) rc = allocate(&r->c, d);
  if (!rc) rc = initial_state(r, d);
  if (!rc) { /* the initial fluid velocity and a consistent u_s = 0 */
    tf_column *c = &r->c;
    double j = 0.0;
    if (tf_mixture_flux(c, 0.0, &j, d)) rc = sl_diag_prefix(d, SL_EBADINPUT, "%s", r->inlet_where);
    for (int k = 0; k <= c->n && !rc; ++k) {
      int cell = k == 0 ? 0 : k == c->n ? c->n - 1 : (c->below ? k - 1 : k);
      c->uf[k] = j / (1.0 - c->phi[cell]);
    }
    c->v_ref = fmax(c->v_ref, fabs(j));
  }
  if (!rc && shaken) rc = tfl_create(sc, r->cfg, &r->c, r->cell_of, &r->lq, d);
  if (!rc) rc = tf_plane_create(&r->c, sc, r->cfg, d);
  /* settling the deposit is a time integration: a run's, not --check's (bounded like any run only by its end) */
  if (!rc && r->cfg->lq.settle > 0.0 && !sc->hooks.checking) rc = settle(r, d);
  if (!rc && r->lq) rc = tfl_start(r->lq, &r->c, d);
  if (!rc) rc = interface_levels(r, d);
  if (!rc && !(r->node = calloc((size_t)r->mesh->n_vertices, sizeof *r->node)))
    rc = sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  if (rc) {
    release(r);
    return rc;
  }
  r->inventory0 = inventory(&r->c); /* a restart reads it from the checkpoint */
  snprintf(r->steady_text, sizeof r->steady_text, "(largest dphi/dt below %g per s)", r->steady_tol);
  *info = (sl_model_info){.integrator = SL_INTEGRATE_FIXED, .steady_text = r->steady_text};
  *self = r;
  return 0;
}

static void column_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  tf_run *r = self;
  /* profile phases: the implicit steps less their transport, the transport */
  st->cpu_coupled = r->c.transport_cpu, st->cpu_flow = fmax(res->solve - r->c.transport_cpu, 0.0);
  if (r->advances) {
    double base = r->inventory0, err = base > 0.0 ? (inventory(&r->c) + r->outflow - base) / base : 0.0;
    double pmax = 0.0;
    for (int i = 0; i < r->c.n; ++i) pmax = fmax(pmax, r->c.phi[i]);
    snprintf(st->coupling_summary, sizeof st->coupling_summary,
             "two_fluid: %.1f iterations and %.1f transport sub-steps per step, solids conservation error %.1e, "
             "outflow %.3g m, max phi %.4f (phi_max %.4g)",
             (double)r->iterations / (double)r->advances, (double)r->substeps / (double)r->advances, err, r->outflow,
             pmax, r->c.phi_max);
  }
  if (r->lq) {
    char line[256];
    tfl_summary(r->lq, line, sizeof line);
    size_t at = strlen(st->coupling_summary);
    snprintf(st->coupling_summary + at, sizeof st->coupling_summary - at,
             "; settled %.4g s in %ld steps before t = 0; "
             "smallest dt %.3g s; %s",
             r->settle_time, r->settle_steps, r->dt_min, line);
  }
  const tfp_model *m = r->c.plane;
  if (m && m->ls) {
    st->linear = tfp_linear_stats(m), st->has_linear = 1;
    snprintf(st->linear_summary, sizeof st->linear_summary, "%s, %d unknowns (the staggered grid's %d x 1 cells)",
             tfp_linear_name(m, r->c.linear), m->n_unknowns, r->c.n);
  }
}

static void column_destroy(void *self) { release(self); }

const sl_model_ops sl_two_fluid_column_ops = {.setup = column_setup,
                                              .step = column_step,
                                              .accept = column_accept,
                                              .write_mesh = column_write_mesh,
                                              .write = column_write,
                                              .checkpoint = column_checkpoint,
                                              .restore = column_restore,
                                              .stats = column_stats,
                                              .destroy = column_destroy};
