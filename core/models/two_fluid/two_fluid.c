/* The 1-D two-fluid model (see two_fluid.h): the scene, the time loop and
 * the output. One step is core/models/two_fluid_step.c. */
#include "core/models/two_fluid/two_fluid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/scene/mesh.h"
#include "core/scene/output.h"
#include "core/models/two_fluid/shear_layer.h"
#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/kinds.h"
#include "core/time/fixed_step.h"

enum { F_PHI = 1, F_US = 2, F_UF = 4, F_P = 8 };
enum { TF_MAX_LEVELS = 8 };
static const char *const field_names[] = {"phi", "velocity_solid", "velocity_fluid", "pressure"};

typedef struct tf_run {
  sl_ini *ini;
  sl_ns_result *res;
  sl_mesh *mesh;
  tf_column c;
  int *face_vertex; /* [n+1] */
  int *cell_of;     /* [n]: the mesh cell of column cell i */
  double *node;     /* [n_vertices] scratch for node fields */
  sl_output *out;
  int fields;
  double inventory0, outflow;
  double steady_tol;
  long substeps, iterations, advances;
  char params[2][1024];
  char inlet_where[400]; /* file:line: [section] key of the inlet's value */
  double level[TF_MAX_LEVELS]; /* [output] interface */
  int n_levels;
} tf_run;

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* ---- the column from the mesh ------------------------------------------------ */

static int column_from_mesh(tf_run *r, sl_diag *d) {
  const sl_mesh *m = r->mesh;
  tf_column *c = &r->c;
  if (m->dim != 1)
    return sl_diag_set(d, SL_EBADINPUT, "[scene] model = two_fluid, geometry = line: the mesh must be 1-D (a 2-D "
                                        "mesh takes geometry = planar or axisymmetric)");
  int n = m->n_cells;
  c->n = n;
  r->cell_of = malloc((size_t)n * sizeof *r->cell_of);
  r->face_vertex = malloc((size_t)(n + 1) * sizeof *r->face_vertex);
  if (!r->cell_of || !r->face_vertex) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  int rc = sl_scene_line_chain(m, r->face_vertex, r->cell_of, d);
  if (rc) return sl_diag_prefix(d, rc, "two_fluid");
  c->h = malloc((size_t)n * sizeof *c->h), c->xc = malloc((size_t)n * sizeof *c->xc);
  c->xf = malloc((size_t)(n + 1) * sizeof *c->xf), c->dual = malloc((size_t)(n + 1) * sizeof *c->dual);
  if (!c->h || !c->xc || !c->xf || !c->dual) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  for (int k = 0; k <= n; ++k) c->xf[k] = m->xy[2 * r->face_vertex[k]];
  for (int i = 0; i < n; ++i) c->h[i] = c->xf[i + 1] - c->xf[i], c->xc[i] = 0.5 * (c->xf[i] + c->xf[i + 1]);
  c->dual[0] = 0.5 * c->h[0], c->dual[n] = 0.5 * c->h[n - 1];
  for (int k = 1; k < n; ++k) c->dual[k] = 0.5 * (c->h[k - 1] + c->h[k]);
  return 0;
}

static int boundaries(tf_run *r, sl_diag *d) {
  tf_column *c = &r->c;
  const char *names[2];
  int rc = sl_scene_line_ends(r->ini, r->mesh, r->face_vertex[0], r->face_vertex[c->n], "two_fluid", names, d);
  if (rc) return rc;
  int n_out = 0;
  c->inlet_side = -1;
  for (int side = 0; side < 2; ++side) {
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", names[side]);
    static const char *const keys[] = {"type", "velocity", "porosity", "pressure"};
    if (sl_ini_find_section(r->ini, sec) && (rc = sl_ini_check_keys(r->ini, sec, keys, 4, d))) return rc;
    if ((rc = sl_ini_get_choice(r->ini, sec, "type", 0, TF_WALL, "wall|inlet|outlet", &c->bc[side], d))) return rc;
    const sl_ini_entry *ve = sl_ini_find(r->ini, sec, "velocity"), *pe = sl_ini_find(r->ini, sec, "pressure");
    const sl_ini_entry *ne = sl_ini_find(r->ini, sec, "porosity");
    if ((ve || ne) && c->bc[side] != TF_INLET)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: only an inlet takes a %s", ve ? ve->file : ne->file,
                         ve ? ve->line : ne->line, sec, ve ? "velocity" : "porosity", ve ? "velocity" : "porosity");
    if (pe && c->bc[side] != TF_OUTLET)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] pressure: only an outlet takes a pressure", pe->file, pe->line,
                         sec);
    if (c->bc[side] == TF_INLET) {
      if (c->inlet_side >= 0)
        return sl_diag_set(d, SL_EBADINPUT, "[%s]: a second inlet (1-D: one inlet and one outlet at most)", sec);
      if (!ve == !ne) {
        const sl_ini_section *where = sl_ini_find_section(r->ini, sec);
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s]: an inlet takes either velocity (the superficial fluid "
                                            "velocity entering, m/s) or porosity (that of the homogeneous bed the "
                                            "inflow holds at rest), an expression of t and case%s",
                           where ? where->file : "(scene)", where ? where->line : 0, sec, ve ? "; not both" : "");
      }
      if (ne && side != (c->below ? 0 : 1))
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] porosity: a bed is held by an inflow from below; this "
                                            "inlet is at the top (give its velocity instead)", ne->file, ne->line,
                           sec);
      if (ne && c->rho_s <= c->rho_f)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] porosity: particles no denser than the fluid (%g <= %g "
                                            "kg/m3) are not held by an upward flow (give the velocity instead)",
                           ne->file, ne->line, sec, c->rho_s, c->rho_f);
      static const char *const vars[] = {"t", "case"};
      const sl_ini_entry *e = ve ? ve : ne;
      if ((rc = sl_expr_compile(e->value, vars, 2, ve ? &c->inlet : &c->inlet_porosity, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] %s", e->file, e->line, sec, e->key);
      c->inlet_side = side;
      snprintf(r->inlet_where, sizeof r->inlet_where, "%s:%d: [%s] %s", e->file, e->line, sec, e->key);
    }
    if (c->bc[side] == TF_OUTLET) {
      ++n_out;
      if ((rc = sl_ini_get_real(r->ini, sec, "pressure", 0, 0.0, -1e12, 1e12, &c->p_out, d))) return rc;
    }
  }
  if (n_out == 2)
    return sl_diag_set(d, SL_EBADINPUT, "[boundary.%s], [boundary.%s]: two outlets leave the 1-D mixture flux "
                                        "undetermined; make one an inlet or a wall", names[0], names[1]);
  if (c->inlet_side >= 0 && n_out == 0)
    return sl_diag_set(d, SL_EBADINPUT, "[boundary.%s]: an inlet needs an outlet at the other end (in 1-D the "
                                        "mixture flux is the same everywhere)", names[c->inlet_side]);
  return 0;
}

static int initial_state(tf_run *r, sl_diag *d) {
  tf_column *c = &r->c;
  const sl_ini_entry *e = sl_ini_find(r->ini, "initial", "phi"), *en = sl_ini_find(r->ini, "initial", "porosity");
  if (e && en)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] porosity and phi both given: set one", en->file, en->line);
  if (!e && !en)
    return sl_diag_set(d, SL_EBADINPUT, "[initial] phi (or porosity): the two_fluid model needs the initial solids "
                                        "fraction");
  const sl_ini_entry *use = e ? e : en;
  static const char *const vars[] = {"x", "y", "case"};
  sl_expr *ex;
  int rc = sl_expr_compile(use->value, vars, 3, &ex, d);
  if (rc) return sl_diag_prefix(d, rc, "%s:%d: [initial] %s", use->file, use->line, use->key);
  for (int i = 0; i < c->n && !rc; ++i) {
    double xy[3] = {c->xc[i], 0.0, c->case_index}, v = sl_expr_eval(ex, xy), phi = e ? v : 1.0 - v;
    if (!(phi >= 0.0 && phi <= c->phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s = %g at x = %g: allowed %s = %g", use->file, use->line,
                       use->key, v, c->xc[i], e ? "0 <= phi <= phi_max" : "1 - phi_max <= porosity <= 1, phi_max",
                       c->phi_max);
    c->phi[i] = phi;
  }
  sl_expr_free(ex);
  return rc;
}

static int allocate(tf_column *c, sl_diag *d) {
  size_t n = (size_t)c->n, f = n + 1;
  double **cells[] = {&c->phi, &c->p, &c->phi_new, &c->p_new, &c->ps_v, &c->ps_d, &c->alpha, &c->slope, &c->stage};
  double **faces[] = {&c->u,  &c->uf,   &c->u_new, &c->uf_new, &c->w,  &c->K,   &c->dK,   &c->phif,
                      &c->slip, &c->lo, &c->di,    &c->up,     &c->rhs, &c->flux, &c->dpdx};
  for (size_t i = 0; i < sizeof cells / sizeof cells[0]; ++i)
    if (!(*cells[i] = calloc(n, sizeof(double)))) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  for (size_t i = 0; i < sizeof faces / sizeof faces[0]; ++i)
    if (!(*faces[i] = calloc(f, sizeof(double)))) return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  return 0;
}

static void release(tf_run *r) {
  tf_column *c = &r->c;
  double *all[] = {c->slope, c->stage, c->h, c->xc, c->xf, c->dual, c->phi, c->p, c->phi_new, c->p_new, c->ps_v,
                   c->ps_d,  c->alpha, c->u,   c->uf,     c->u_new, c->uf_new, c->w,     c->K,       c->dK,
                   c->phif,  c->slip, c->lo,   c->di,     c->up,    c->rhs,  c->flux,  c->dpdx,    c->drag.buf,
                   c->ps.buf, r->node};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) free(all[i]);
  sl_closure_destroy(c->drag.c);
  sl_closure_destroy(c->ps.c);
  sl_expr_free(c->inlet);
  sl_expr_free(c->inlet_porosity);
  free(r->face_vertex), free(r->cell_of);
  sl_mesh_destroy(r->mesh);
}

/* ---- output ----------------------------------------------------------------------- */

static double inventory(const tf_column *c) {
  double s = 0.0;
  for (int i = 0; i < c->n; ++i) s += c->phi[i] * c->h[i];
  return s;
}

static int open_output(tf_run *r, const sl_ns_run_opts *o, sl_diag *d) {
  unsigned mask;
  const sl_ini_entry *le = sl_ini_find(r->ini, "output", "interface");
  if (le) {
    int rc = sl_ini_get_real_list(r->ini, "output", "interface", 0, r->level, TF_MAX_LEVELS, &r->n_levels, d);
    if (rc) return rc;
    for (int k = 0; k < r->n_levels; ++k)
      if (!(r->level[k] > 0.0 && r->level[k] <= r->c.phi_max))
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [output] interface = %g: a level of phi, allowed 0 < level <= "
                                            "phi_max = %g", le->file, le->line, r->level[k], r->c.phi_max);
    if (r->n_levels > 0 && r->c.g == 0.0)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [output] interface: heights are measured against gravity, and the "
                                          "scene has none", le->file, le->line);
  }
  int rc = sl_scene_output_path(r->ini, o->output, o->scene_path, r->res->output_path, sizeof r->res->output_path, d);
  if (!rc) rc = sl_scene_output_fields(r->ini, field_names, 4, F_PHI | F_US | F_UF | F_P, &mask, d);
  if (rc) return rc;
  r->fields = (int)mask;
  if ((rc = sl_output_open(&r->out, r->res->output_path, d))) return rc;
  const sl_mesh *m = r->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * 2 * sizeof *cells);
  r->node = calloc((size_t)m->n_vertices, sizeof *r->node);
  if (!cells || !r->node) {
    free(cells);
    return sl_diag_set(d, SL_EFAILED, "two_fluid: out of memory");
  }
  for (int v = 0; v < m->n_vertices; ++v) r->node[v] = m->xy[2 * v];
  for (int e2 = 0; e2 < 2 * m->n_cells; ++e2) cells[e2] = m->cell_vertices[e2];
  rc = sl_output_write_mesh(r->out, 1, m->n_vertices, r->node, m->n_cells, 2, cells, "Polyline", d);
  free(cells);
  if (rc) return rc;
  return tf_write_provenance(r->out, r->ini, o, &r->c, NULL, NULL, 0, r->params, d);
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
static int write_state(tf_run *r, double t, sl_diag *d) {
  double t0 = cpu_now();
  tf_column *c = &r->c;
  int rc = sl_output_begin_step(r->out, t, d);
  double *cellv = r->c.alpha; /* scratch of n cells */
  const double *cf[2] = {c->phi, c->p}, *ff[2] = {c->u, c->uf};
  const int cflag[2] = {F_PHI, F_P}, fflag[2] = {F_US, F_UF};
  const char *cname[2] = {"phi", "pressure"}, *fname[2] = {"velocity_solid", "velocity_fluid"};
  for (int k = 0; k < 2 && !rc; ++k) {
    if (!(r->fields & cflag[k])) continue;
    for (int i = 0; i < c->n; ++i) cellv[r->cell_of[i]] = cf[k][i];
    rc = sl_output_write_field(r->out, cname[k], SL_CENTRE_CELL, 1, cellv, d);
  }
  for (int k = 0; k < 2 && !rc; ++k) {
    if (!(r->fields & fflag[k])) continue;
    for (int f = 0; f <= c->n; ++f) r->node[r->face_vertex[f]] = ff[k][f];
    rc = sl_output_write_field(r->out, fname[k], SL_CENTRE_NODE, 1, r->node, d);
  }
  double inv = inventory(c);
  if (!rc) rc = sl_output_write_scalar(r->out, "solids_inventory", inv, d);
  if (!rc)
    rc = sl_output_write_scalar(r->out, "solids_conservation_error",
                                r->inventory0 > 0.0 ? (inv + r->outflow - r->inventory0) / r->inventory0 : 0.0, d);
  double j = 0.0;
  if (!rc) rc = tf_mixture_flux(c, t, &j, d);
  if (!rc) rc = sl_output_write_scalar(r->out, "mixture_flux", j, d);
  for (int k = 0; k < r->n_levels && !rc; ++k) {
    char name[64];
    snprintf(name, sizeof name, "interface_height_%d", k);
    rc = sl_output_write_scalar(r->out, name, interface_height(c, r->level[k]), d);
    snprintf(name, sizeof name, "interface_level_%d", k);
    if (!rc) rc = sl_output_write_scalar(r->out, name, r->level[k], d);
  }
  if (!rc) rc = sl_output_end_step(r->out, d);
  r->res->output += cpu_now() - t0;
  return rc;
}

static tf_state column_state(tf_run *r) {
  return (tf_state){.phi = r->c.phi, .us = r->c.u, .uf = r->c.uf, .p = r->c.p, .n_cells = r->c.n,
                    .n_faces = r->c.n + 1, .inventory0 = r->inventory0, .outflow = r->outflow,
                    .rejected = r->res->rejected_steps};
}

static int write_checkpoint(tf_run *r, double t, double dt, long step, sl_diag *d) {
  tf_state st = column_state(r);
  return tf_checkpoint_write(r->out, &st, t, dt, step, d);
}

static int restore(tf_run *r, const char *path, double *t, double *dt, long *step, sl_diag *d) {
  tf_state st = column_state(r);
  int rc = tf_checkpoint_restore(path, "two_fluid", &st, t, dt, step, d);
  r->inventory0 = st.inventory0, r->outflow = st.outflow, r->res->rejected_steps = st.rejected;
  return rc;
}

/* ---- the time loop (core/time/fixed_step) ------------------------------------------------ */

static int column_step(void *user, double t, double dt, int *iterations, int *fatal, sl_diag *d) {
  tf_run *r = user;
  int rc = tf_step(&r->c, t, dt, d);
  *iterations = r->c.iterations_trial, *fatal = r->c.fatal;
  r->iterations += r->c.iterations_trial;
  return rc;
}

static void column_accept(void *user, double dt, int *steady) {
  tf_run *r = user;
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

static int column_write(void *user, double t, double dt_next, long step, sl_diag *d) {
  tf_run *r = user;
  int rc = write_state(r, t, d);
  return rc ? rc : write_checkpoint(r, t, dt_next, step, d);
}

static int column_restore(void *user, const char *path, double *t, double *dt, long *step, sl_diag *d) {
  return restore(user, path, t, dt, step, d);
}

static int time_loop(tf_run *r, const sl_ns_run_opts *o, sl_diag *d) {
  char steady_text[96];
  snprintf(steady_text, sizeof steady_text, "(largest dphi/dt below %g per s)", r->steady_tol);
  sl_fixed_step_model m = {.user = r, .step = column_step, .accept = column_accept, .write = column_write,
                           .restore = column_restore, .steady_text = steady_text};
  r->inventory0 = inventory(&r->c); /* a restart reads it from the checkpoint */
  return sl_fixed_step_run(r->ini, &m, o, r->res, d);
}

int sl_two_fluid_run(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res, sl_diag *d) {
  int motion = 0;
  int rc = sl_ini_get_choice(ini, "two_fluid", "motion", 0, 0, "column|shear", &motion, d);
  if (rc) return rc;
  if (motion == 1) {
    int geometry = 0;
    if ((rc = sl_ini_get_choice(ini, "scene", "geometry", 0, 0, "line|planar|axisymmetric", &geometry, d))) return rc;
    if (geometry != 0) {
      const sl_ini_entry *e = sl_ini_find(ini, "scene", "geometry");
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [scene] geometry = %s: the shear layer (motion = shear) is 1-D "
                                          "(geometry = line; cross_section = annular for coaxial cylinders)",
                         e->file, e->line, e->value);
    }
    static const char *const plane_only[] = {"kinetic_pressure", "acceleration"};
    for (int k = 0; k < 2; ++k) {
      const sl_ini_entry *kp = sl_ini_find(ini, "two_fluid", plane_only[k]);
      if (kp)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [two_fluid] %s: a key of the 2-D model (not of the shear layer)",
                           kp->file, kp->line, kp->key);
    }
    return sl_shear_layer_run(ini, reg, o, res, d);
  }
  int geometry = 0;
  rc = sl_ini_get_choice(ini, "scene", "geometry", 0, 0, "line|planar|axisymmetric", &geometry, d);
  if (rc) return rc;
  /* the column has no solids stress; the 2-D model takes its granular keys */
  static const char *const not_column[] = {"cross_section", "granular_temperature", "interphase_dissipation",
                                           "kinetic_pressure", "acceleration"};
  static const char *const owner[] = {"the shear layer (motion = shear)",
                                      "the shear layer (motion = shear) or a 2-D scene with [closure.granular]",
                                      "the shear layer (motion = shear) or a 2-D scene with [closure.granular]",
                                      "a 2-D scene with [closure.granular]", "a 2-D scene"};
  for (size_t k = 0; k < (geometry != 0 ? 1 : sizeof not_column / sizeof not_column[0]); ++k) {
    const sl_ini_entry *e = sl_ini_find(ini, "two_fluid", not_column[k]);
    if (e) return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [two_fluid] %s: a key of %s", e->file, e->line, e->key, owner[k]);
  }
  if (geometry != 0) return sl_two_fluid_plane_run(ini, reg, o, res, d);
  int convection = 0;
  if ((rc = sl_ini_get_bool(ini, "flow", "convection", 0, 0, &convection, d))) return rc;
  if (convection) {
    const sl_ini_entry *cv = sl_ini_find(ini, "flow", "convection");
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [flow] convection: the 1-D column has no convective acceleration "
                                        "(the 2-D model takes it: geometry = planar or axisymmetric)",
                       cv->file, cv->line);
  }
  memset(res, 0, sizeof *res);
  tf_run r = {.ini = ini, .res = res};
  double c0 = cpu_now();
  if (!rc) rc = sl_scene_mesh(ini, &r.mesh, d);
  if (!rc) rc = column_from_mesh(&r, d);
  if (!rc) rc = tf_scene_physics(r.ini, reg, 1, &r.c, NULL, &r.steady_tol, d);
  if (!rc) rc = boundaries(&r, d);
  if (!rc) rc = allocate(&r.c, d);
  if (!rc) rc = initial_state(&r, d);
  if (!rc) { /* the initial fluid velocity and a consistent u_s = 0 */
    tf_column *c = &r.c;
    double j = 0.0;
    if (tf_mixture_flux(c, 0.0, &j, d)) rc = sl_diag_prefix(d, SL_EBADINPUT, "%s", r.inlet_where);
    for (int k = 0; k <= c->n && !rc; ++k) {
      int cell = k == 0 ? 0 : k == c->n ? c->n - 1 : (c->below ? k - 1 : k);
      c->uf[k] = j / (1.0 - c->phi[cell]);
    }
    c->v_ref = fmax(c->v_ref, fabs(j));
  }
  if (!rc) rc = open_output(&r, o, d);
  res->cpu_setup = cpu_now() - c0;
  if (!rc) rc = time_loop(&r, o, d);
  /* profile phases: the implicit steps less their transport, the transport, the output */
  res->cpu_coupled = r.c.transport_cpu, res->cpu_flow = fmax(res->solve - r.c.transport_cpu, 0.0);
  res->cpu_output = res->output;
  if (r.out) {
    sl_output_stats(r.out, &res->output_times, &res->output_datasets, &res->output_bytes);
    sl_diag d2;
    int crc = sl_output_close(r.out, rc ? &d2 : d);
    if (!rc) rc = crc;
  }
  if (r.advances) {
    double base = r.inventory0, err = base > 0.0 ? (inventory(&r.c) + r.outflow - base) / base : 0.0;
    double pmax = 0.0;
    for (int i = 0; i < r.c.n; ++i) pmax = fmax(pmax, r.c.phi[i]);
    snprintf(res->coupling_summary, sizeof res->coupling_summary,
             "two_fluid: %.1f iterations and %.1f transport sub-steps per step, solids conservation error %.1e, "
             "outflow %.3g m, max phi %.4f (phi_max %.4g)",
             (double)r.iterations / (double)r.advances, (double)r.substeps / (double)r.advances, err, r.outflow, pmax,
             r.c.phi_max);
  }
  snprintf(res->linear_summary, sizeof res->linear_summary, "tridiagonal, %d faces", r.c.n + 1);
  release(&r);
  return rc;
}
