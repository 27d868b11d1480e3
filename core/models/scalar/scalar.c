/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The scalar model (scalar.h). */
#include "core/models/scalar/scalar.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/fv/cell_scalar.h"
#include "core/scene/keys.h"
#include "core/scene/scene.h"

enum { SC_WALL = 0, SC_VALUE, SC_PERIODIC };

typedef struct sc_config {
  double diffusivity;
  sl_scene_exprs velocity; /* of x, y */
  sl_scene_expr source;    /* of x, y, t */
  sl_scene_expr initial;   /* [initial] value, of x, y */
} sc_config;

typedef struct sc_boundary {
  int type;
  sl_scene_expr value; /* of x, y, t */
} sc_boundary;

typedef struct scalar {
  const sl_scene *sc;
  const sc_config *cfg;
  sl_tensor_grid tg;
  sl_fv_grid g;
  sl_cell_scalar cs;
  const sc_boundary *b;
  double *c, *c_new, *flux, *cap, *src; /* cells, cells, faces, cells, cells */
  double t_new;                         /* the time the trial step ends at */
  double *cellbuf;
  double inventory0, inflow, inflow_trial; /* the balance: what the value boundaries let in */
} scalar;

static double eval2(const sl_expr *e, double x, double y, double t) {
  double v[3] = {x, y, t};
  return sl_expr_eval(e, v);
}

/* The face's centre. */
static void face_centre(const sl_fv_grid *g, int f, double *x, double *y) {
  if (f < g->nfx) {
    int i = f % (g->nx + 1), j = f / (g->nx + 1);
    *x = g->tg->xf[i], *y = g->yc[j];
  } else {
    int i = (f - g->nfx) % g->nx, j = (f - g->nfx) / g->nx;
    *x = g->xc[i], *y = g->tg->yf[j];
  }
}

/* The flux through a boundary face of cell c given its value there: diffusion over the half cell, and what
   the velocity carries in (at the boundary value) or out (at the cell's). */
static int boundary_terms(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  scalar *s = user;
  const sl_fv_grid *g = &s->g;
  int cf[4];
  sl_fv_cell_faces(g, c, cf);
  for (int k = 0; k < 4; ++k) {
    int f = cf[k], tag = g->bound[f];
    if (tag < 0 || s->b[tag].type != SC_VALUE) continue;
    double x, y;
    face_centre(g, f, &x, &y);
    double v = eval2(s->b[tag].value.e, x, y, s->t_new);
    if (!isfinite(v))
      return sl_diag_set(d, SL_EFAILED, "the boundary value is not finite (%g) at (%g, %g), t = %g", v, x, y, s->t_new);
    double kd = s->cfg->diffusivity * g->area[f] / g->dist[f];
    double out = (k % 2 ? 1.0 : -1.0) * s->flux[f]; /* along the outward normal */
    *diag += kd + fmax(out, 0.0);
    *rhs += (kd - fmin(out, 0.0)) * v;
  }
  return 0;
}

static double inventory(const scalar *s, const double *c) {
  double m = 0.0;
  for (int k = 0; k < s->g.nc; ++k) m += c[k] * s->g.vol[k];
  return m;
}

/* What entered through the value boundaries over dt with the trial c_new (for the balance). */
static double boundary_inflow(const scalar *s, double dt) {
  const sl_fv_grid *g = &s->g;
  double in = 0.0;
  for (int f = 0; f < g->nf; ++f) {
    int tag = g->bound[f];
    if (tag < 0 || s->b[tag].type != SC_VALUE) continue;
    int c = g->lo[f] >= 0 ? g->lo[f] : g->hi[f], outward = g->lo[f] >= 0 ? 1 : -1;
    double x, y;
    face_centre(g, f, &x, &y);
    double v = eval2(s->b[tag].value.e, x, y, s->t_new), out = outward * s->flux[f];
    double diffusive = s->cfg->diffusivity * g->area[f] / g->dist[f] * (v - s->c_new[c]);
    in += dt * (diffusive - (out > 0.0 ? out * s->c_new[c] : out * v));
  }
  return in;
}

/* ---- ops ------------------------------------------------------------------------------ */

static void release(scalar *s) {
  free(s->c), free(s->c_new), free(s->flux), free(s->cap), free(s->src), free(s->cellbuf);
  sl_cell_scalar_free(&s->cs);
  sl_fv_grid_free(&s->g);
  sl_tensor_grid_free(&s->tg);
  free(s);
}

static int sc_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  scalar *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "scalar: out of memory");
  s->sc = sc, s->cfg = sc->config, s->b = sc->boundaries;
  const sl_mesh *m = sc->mesh;
  char at[400];
  int rc = m->dim == 2 ? 0 : sl_diag_set(d, SL_EBADINPUT, "[mesh]: the scalar model needs a 2-D mesh");
  if (!rc && (rc = sl_tensor_grid_from_mesh(m, &s->tg, d)))
    rc = sl_diag_prefix(d, rc, "[mesh] (the scalar model's grid)");
  /* periodic sides come in opposite pairs */
  int periodic[2] = {0, 0};
  for (int dir = 0; dir < 2 && !rc; ++dir) {
    int n = dir == 0 ? s->tg.ny : s->tg.nx, count[2] = {0, 0};
    for (int side = 0; side < 2; ++side)
      for (int k = 0; k < n; ++k) count[side] += s->b[s->tg.side_tag[2 * dir + side][k]].type == SC_PERIODIC;
    if (count[0] == 0 && count[1] == 0) continue;
    if (count[0] != n || count[1] != n)
      rc = sl_diag_set(d, SL_EBADINPUT, "type = periodic: the %s sides must both be periodic, wholly",
                       dir ? "bottom and top" : "left and right");
    periodic[dir] = 1;
  }
  for (int k = 0; k < m->n_boundaries && !rc; ++k)
    if (s->b[k].type == SC_VALUE && !s->b[k].value.e)
      rc = sl_diag_set(d, SL_EBADINPUT, "[boundary.%s] type = value needs value = <an expression of x, y, t>",
                       m->boundary_names[k]);
  if (!rc) rc = sl_fv_grid_build(&s->g, &s->tg, sc->geometry == 2, periodic, d);
  if (!rc && s->cfg->velocity.n != 0 && s->cfg->velocity.n != 2)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: two components (along x, along y), %d given",
                     sl_scene_where(sc, &s->cfg->velocity, at, sizeof at), s->cfg->velocity.n);
  if (!rc && !s->cfg->initial.e) rc = sl_scene_require(sc, &s->cfg->initial, d);
  const int nc = s->g.nc, nf = s->g.nf;
  if (!rc) {
    s->c = malloc((size_t)nc * sizeof *s->c), s->c_new = malloc((size_t)nc * sizeof *s->c_new);
    s->flux = calloc((size_t)nf, sizeof *s->flux), s->cap = malloc((size_t)nc * sizeof *s->cap);
    s->src = calloc((size_t)nc, sizeof *s->src), s->cellbuf = malloc((size_t)nc * sizeof *s->cellbuf);
    if (!s->c || !s->c_new || !s->flux || !s->cap || !s->src || !s->cellbuf)
      rc = sl_diag_set(d, SL_ENOMEM, "scalar: out of memory");
  }
  if (!rc) rc = sl_cell_scalar_init(&s->cs, &s->g, d);
  /* the velocity's normal component at each face centre, times its area: the volume flux */
  for (int f = 0; f < nf && !rc && s->cfg->velocity.n == 2; ++f) {
    double x, y;
    face_centre(&s->g, f, &x, &y);
    double un = eval2(s->cfg->velocity.e[f >= s->g.nfx], x, y, 0.0);
    if (!isfinite(un))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s is not finite at (%g, %g)",
                       sl_scene_where(sc, &s->cfg->velocity, at, sizeof at), x, y);
    s->flux[f] = un * s->g.area[f];
  }
  /* the boundary values at the start, where a bad expression shows (a value the run meets later stops it) */
  for (int f = 0; f < nf && !rc; ++f) {
    int tag = s->g.bound[f];
    if (tag < 0 || s->b[tag].type != SC_VALUE) continue;
    double x, y;
    face_centre(&s->g, f, &x, &y);
    double v = eval2(s->b[tag].value.e, x, y, 0.0);
    if (!isfinite(v))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s = %g at (%g, %g), t = 0: not a finite value",
                       sl_scene_where(sc, &s->b[tag].value, at, sizeof at), v, x, y);
  }
  for (int c = 0; c < nc && !rc; ++c) {
    double v = eval2(s->cfg->initial.e, s->g.xc[c % s->g.nx], s->g.yc[c / s->g.nx], 0.0);
    if (!isfinite(v))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s is not finite at (%g, %g)",
                       sl_scene_where(sc, &s->cfg->initial, at, sizeof at), s->g.xc[c % s->g.nx], s->g.yc[c / s->g.nx]);
    s->c[c] = v, s->cap[c] = 1.0;
  }
  if (rc) {
    release(s);
    return rc;
  }
  s->inventory0 = inventory(s, s->c);
  *info = (sl_model_info){.integrator = SL_INTEGRATE_FIXED, .steady_text = ""};
  *self = s;
  return 0;
}

static int sc_step(void *self, sl_step *st, int *iterations, sl_diag *d) {
  scalar *s = self;
  s->t_new = st->t + st->dt;
  *iterations = 1;
  if (s->cfg->source.e)
    for (int c = 0; c < s->g.nc; ++c)
      s->src[c] = eval2(s->cfg->source.e, s->g.xc[c % s->g.nx], s->g.yc[c / s->g.nx], s->t_new);
  double *k = NULL;
  if (s->cfg->diffusivity > 0.0) { /* the cells' diffusivity: the scene's constant */
    k = s->cellbuf;
    for (int c = 0; c < s->g.nc; ++c) k[c] = s->cfg->diffusivity;
  }
  sl_cell_scalar_terms t = {.dt = st->dt,
                            .cap = s->cap,
                            .s_old = s->c,
                            .k = k,
                            .source = s->src,
                            .flux = s->cfg->velocity.n ? s->flux : NULL,
                            .boundary = boundary_terms,
                            .boundary_user = s};
  int rc = sl_cell_scalar_solve(&s->cs, &t, s->c_new, d);
  if (rc) return -rc; /* a direct solve of a fixed stencil does not get better with a smaller step */
  double source = 0.0;
  for (int c = 0; c < s->g.nc; ++c) {
    if (!isfinite(s->c_new[c])) {
      sl_diag_set(d, SL_EFAILED, "the scalar is not finite in cell %d", c);
      return SL_STEP_RETRY;
    }
    source += s->src[c] * s->g.vol[c];
  }
  s->inflow_trial = boundary_inflow(s, st->dt) + st->dt * source;
  return 0;
}

static void sc_accept(void *self, const sl_step *st, int *steady) {
  (void)st, (void)steady;
  scalar *s = self;
  double *w = s->c;
  s->c = s->c_new, s->c_new = w;
  s->inflow += s->inflow_trial;
}

static int sc_write_mesh(void *self, sl_output *out, sl_diag *d) {
  const sl_mesh *m = ((scalar *)self)->sc->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * m->nv_per_cell * sizeof *cells);
  if (!cells) return sl_diag_set(d, SL_ENOMEM, "scalar: out of memory");
  for (int i = 0; i < m->n_cells * m->nv_per_cell; ++i) cells[i] = m->cell_vertices[i];
  int rc = sl_output_write_mesh(out, 2, m->n_vertices, m->xy, m->n_cells, m->nv_per_cell, cells, "Quadrilateral", d);
  free(cells);
  return rc;
}

static int sc_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)t, (void)u;
  scalar *s = self;
  for (int c = 0; c < s->g.nc; ++c) s->cellbuf[s->tg.mesh_cell[c]] = s->c[c];
  int rc = sl_output_write_field(out, "value", SL_CENTRE_CELL, 1, s->cellbuf, d);
  double inv = inventory(s, s->c), base = fmax(fabs(s->inventory0) + fabs(s->inflow), 1e-300);
  if (!rc) rc = sl_output_write_scalar(out, "inventory", inv, d);
  if (!rc) rc = sl_output_write_scalar(out, "balance_error", (inv - s->inventory0 - s->inflow) / base, d);
  return rc;
}

static int sc_checkpoint(void *self, sl_checkpoint_array *a, int max) {
  scalar *s = self;
  if (max < 2) return 0;
  snprintf(a[0].name, sizeof a[0].name, "value");
  a[0].n = s->g.nc, a[0].data = s->c;
  snprintf(a[1].name, sizeof a[1].name, "inflow");
  a[1].n = 1, a[1].data = &s->inflow;
  return 2;
}

static int sc_restore(void *self, const sl_checkpoint *ck, sl_diag *d) {
  scalar *s = self;
  const sl_checkpoint_array *a = sl_checkpoint_find(ck, "value"), *in = sl_checkpoint_find(ck, "inflow");
  if (!a || a->n != s->g.nc || !in || in->n != 1)
    return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no scalar of %d cells", s->g.nc);
  memcpy(s->c, a->data, (size_t)a->n * sizeof *s->c);
  s->inflow = in->data[0];
  return 0;
}

static void sc_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  scalar *s = self;
  st->cpu_flow = res->solve;
  if (s->cs.ls) st->linear = *sl_linsolve_get_stats(s->cs.ls), st->has_linear = 1;
  snprintf(st->linear_summary, sizeof st->linear_summary, "klu, %d cells", s->g.nc);
}

static void sc_destroy(void *self) { release(self); }

const sl_model_ops sl_scalar_ops = {.setup = sc_setup,
                                    .step = sc_step,
                                    .accept = sc_accept,
                                    .write_mesh = sc_write_mesh,
                                    .write = sc_write,
                                    .checkpoint = sc_checkpoint,
                                    .restore = sc_restore,
                                    .stats = sc_stats,
                                    .destroy = sc_destroy};

/* ---- the schema --------------------------------------------------------------------- */

#define TABLE(name, keys) static const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}
#define C(field) SL_AT_MODEL(sc_config, field)

static const sl_key scalar_keys[] = {
    {.section = "scene",
     .name = "geometry",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(geometry),
     .def = 1,
     .choices = "line|planar|axisymmetric",
     .help = "planar, or axisymmetric (x is r)"},
    {.section = "scalar",
     .name = "diffusivity",
     .type = SL_KEY_REAL,
     C(diffusivity),
     .min = 0.0,
     .max = 1e6,
     .units = "m^2 s^-1",
     .help = "D"},
    {.section = "scalar",
     .name = "velocity",
     .type = SL_KEY_EXPRS,
     C(velocity),
     .vars = "x,y",
     .max_n = 2,
     .units = "m s^-1",
     .help = "the carrying velocity, two components (default at rest)"},
    {.section = "scalar",
     .name = "source",
     .type = SL_KEY_EXPR,
     C(source),
     .vars = "x,y,t",
     .help = "S, per unit volume and time"},
    {.section = "initial",
     .name = "value",
     .type = SL_KEY_EXPR,
     C(initial),
     .vars = "x,y",
     .def_doc = "required",
     .help = "the initial value at the cell centres"},
    {.section = "boundary",
     .name = "type",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(sc_boundary, type),
     .choices = "wall|value|periodic",
     .help = "wall (no flux), value (given), periodic (both opposite sides)"},
    {.section = "boundary",
     .name = "value",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(sc_boundary, value),
     .vars = "x,y,t",
     .when_type = 1u << SC_VALUE,
     .help = "the value at the boundary"},
};
TABLE(sc_keys, scalar_keys);

static const char *const scalar_fields[] = {"value"};

const sl_schema sl_scalar_schema = {
    .model = "scalar",
    .title = "passive scalar",
    .summary =
        "A scalar carried by a given velocity, diffusing, with a source, on the staggered finite-volume grid "
        "of a rectangle: backward Euler, upwind convection, central diffusion; walls, given values, periodic "
        "sides. The smallest model on the shared layers (core/fv).",
    .tables = {&sl_keys_scene, &sl_keys_mesh, &sl_keys_time_steps, &sl_keys_output, &sl_keys_plugins, &sc_keys},
    .n_tables = 6,
    .config_size = sizeof(sc_config),
    .boundary_size = sizeof(sc_boundary),
    .fields = scalar_fields,
    .n_fields = 1,
};
