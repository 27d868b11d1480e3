/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The flow of a scene (flow.h): physics, boundary conditions, solves with
 * continuation, output and checkpoint of the Taylor-Hood flow. */
#include "core/models/navier_stokes/flow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/fe/field.h"
#include "core/fv/face_flux.h"
#include "core/fv/stream_function.h"
#include "core/models/navier_stokes/factor_checkpoint.h"
#include "core/models/navier_stokes/forces.h"
#include "core/models/navier_stokes/projection.h"
#include "core/plugin/kinds.h"
#include "core/plugin/point_eval.h"
#include "core/scene/solver.h"

static double cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

enum { MAX_COMP = 3 };

/* Steady continuation (sl_flow_steady): the relative residual of a stage's first and damped corrections, and
 * the FGMRES budget of a reused factorisation (and the iterations beyond which the next solve refactorises);
 * a KLU refactorisation of the 40 x 40 Bingham cavity costs as much as about 40 FGMRES iterations with the old
 * one (0.18 s against 4.5 ms, `sluice run --profile`). */
#define SL_FLOW_CONTINUATION_DAMPED_RTOL 0.1
#define SL_FLOW_CONTINUATION_FGMRES 40
#define SL_FLOW_CONTINUATION_FGMRES_SLOW 15

/* The Newton tolerance of an adaptive time step, as a fraction of its error tolerance (solve_opts). */
#define SL_FLOW_STEP_NEWTON_FRACTION 1e-3

const char *const sl_flow_field_names[SL_FLOW_N_FIELDS] = {"velocity",  "pressure", "shear_rate",
                                                           "viscosity", "yielded",  "stream_function"};
enum {
  F_VELOCITY = 1,
  F_PRESSURE = 2,
  F_SHEAR = 4,
  F_VISCOSITY = 8,
  F_YIELDED = 16,
  F_STREAM = SL_FLOW_STREAM_FUNCTION
};

/* ---- physics: fluid properties, the viscosity closure, forces ------------ */

/* The quantities the flow gives a viscosity closure; phi and density vary
 * per point when a solids fraction rides on the flow. */
enum { Q_SHEAR_RATE, Q_MU_F, Q_RHO_F, Q_DENSITY, Q_PHI, Q_N };
static const char *const quantity_names[Q_N] = {"shear_rate", "mu_f", "rho_f", "density", "phi"};

typedef struct physics {
  int n_comp, dim, axisymmetric;
  double density, viscosity;
  sl_closure *visc; /* NULL: Newtonian (the scene's) */
  sl_point_closure pc;
  int has_dmu;
  double yield_stress; /* for `yielded`; 0 when the law has none */
  double *buf;         /* phi, density, mu, d mu / d gamma at the points of one batch */
  int cap;
  double gravity[MAX_COMP], body_force[MAX_COMP];
  const sl_expr *force_expr[MAX_COMP]; /* components of the body force that vary (x, y, t); NULL: body_force[c] */
  int force_varies;
  double t; /* the time the body force is evaluated at (the end of the step being solved) */
  int has_force;
  char force_where[400]; /* file:line of [flow] body_force, for messages */
  int riding;            /* a solids fraction rides on the flow: variable density, buoyancy, phi input */
  const sl_flow_rider *rider;
} physics;

static void physics_free(physics *ph) {
  free(ph->buf);
  sl_point_release(&ph->pc);
  memset(ph, 0, sizeof *ph);
}

/* Viscosity through the closure, once per batch; mu and d mu / d gamma. */
static int viscosity_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  physics *ph = user;
  int need = 4 * b->n;
  if (need > ph->cap) {
    double *nb = realloc(ph->buf, (size_t)need * sizeof *nb);
    if (!nb) return sl_diag_set(d, SL_ENOMEM, "viscosity: out of memory");
    ph->buf = nb, ph->cap = need;
  }
  double *phi_q = ph->buf, *rho_q = phi_q + b->n, *mu = rho_q + b->n, *dmu = mu + b->n;
  const double *values[Q_N] = {b->shear_rate, NULL, NULL, NULL, NULL};
  const double *phi = ph->riding ? ph->rider->phi : NULL;
  if (phi) {
    for (int q = 0; q < b->n; ++q) {
      double f = phi[b->cell[q]];
      phi_q[q] = f, rho_q[q] = ph->density + f * (ph->rider->rho_solid - ph->density);
    }
    values[Q_PHI] = phi_q, values[Q_DENSITY] = rho_q;
  }
  sl_point_request rq = {"viscosity", mu, ph->has_dmu ? dmu : NULL, "shear_rate"};
  int rc = sl_point_eval(&ph->pc, b->n, values, &rq, 1, d);
  if (rc) {
    int q = ph->pc.failed_point >= 0 ? ph->pc.failed_point : 0;
    return sl_diag_prefix(d, rc, "at (%g, %g) in cell %d", b->x[q][0], b->x[q][1], (int)b->cell[q]);
  }
  for (int q = 0; q < b->n; ++q) out[2 * q] = mu[q], out[2 * q + 1] = ph->has_dmu ? dmu[q] : 0.0;
  return 0;
}

/* Gravity and the body force. With a solids fraction only the excess
 * density (rho - rho_f) = phi (rho_s - rho_f) is buoyant: rho_f g goes into
 * the (reduced) pressure; so does the part of phi whose pressure the rider
 * carries (buoyant_phi is the rest). */
static int force_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const physics *ph = user;
  const double *phi = ph->riding ? ph->rider->buoyant_phi ? ph->rider->buoyant_phi : ph->rider->phi : NULL;
  for (int q = 0; q < b->n; ++q) {
    double rho = phi ? phi[b->cell[q]] * (ph->rider->rho_solid - ph->density) : ph->density;
    for (int c = 0; c < ph->n_comp; ++c) out[q * ph->n_comp + c] = rho * ph->gravity[c] + ph->body_force[c];
    if (!ph->force_varies) continue;
    double xyt[3] = {b->x[q][0], b->x[q][1], ph->t};
    for (int c = 0; c < ph->n_comp; ++c)
      if (ph->force_expr[c]) {
        double f = sl_expr_eval(ph->force_expr[c], xyt);
        if (!isfinite(f)) /* finite at t = 0 (checked at set-up): the run cannot go on */
          return sl_diag_set(d, SL_EFAILED, "%s: component %d is %g at (%g, %g), t = %.9g: not a finite force",
                             ph->force_where, c + 1, f, xyt[0], xyt[1], xyt[2]);
        out[q * ph->n_comp + c] = rho * ph->gravity[c] + f;
      }
  }
  return 0;
}

/* The mixture density rho_f + phi (rho_s - rho_f) (Nigam 1999 eq 2.1). */
static int density_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const physics *ph = user;
  (void)d;
  const double *phi = ph->rider->phi;
  for (int q = 0; q < b->n; ++q) out[q] = ph->density + phi[b->cell[q]] * (ph->rider->rho_solid - ph->density);
  return 0;
}

/* A vector key of the scene into n_comp components (more given is an error). */
static int vec_get(const sl_scene *sc, const sl_reals *r, int n_comp, double *v, sl_diag *d) {
  if (r->n > n_comp) {
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT, "%s: %d components given, the scene has %d velocity components",
                       sl_scene_where(sc, r, at, sizeof at), r->n, n_comp);
  }
  for (int c = 0; c < MAX_COMP; ++c) v[c] = c < r->n ? r->v[c] : 0.0;
  return 0;
}

static int physics_setup(const sl_scene *sc, int n_comp, int dim, int axi, int riding, double rho_solid, physics *ph,
                         sl_diag *d) {
  memset(ph, 0, sizeof *ph);
  ph->n_comp = n_comp, ph->dim = dim, ph->axisymmetric = axi, ph->riding = riding;
  ph->density = sc->fluid.density, ph->viscosity = sc->fluid.viscosity;
  int rc = vec_get(sc, &sc->flow.gravity, n_comp, ph->gravity, d);
  if (rc) return rc;
  const sl_scene_exprs *bf = &sc->flow.body_force;
  sl_scene_where(sc, bf, ph->force_where, sizeof ph->force_where);
  if (bf->n > n_comp) {
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT, "%s: %d components given, the scene has %d velocity components",
                       sl_scene_where(sc, bf, at, sizeof at), bf->n, n_comp);
  }
  for (int c = 0; c < bf->n; ++c) { /* constant components as numbers: the same arithmetic as before expressions */
    double v;
    if (sl_expr_is_constant(bf->e[c], &v)) ph->body_force[c] = v;
    else ph->force_expr[c] = bf->e[c], ph->force_varies = 1, ph->has_force = 1;
  }
  for (int c = 0; c < MAX_COMP; ++c) ph->has_force |= ph->gravity[c] != 0.0 || ph->body_force[c] != 0.0;
  if (riding && rho_solid == ph->density) { /* neutrally buoyant: gravity acts on nothing */
    ph->has_force = ph->force_varies;
    for (int c = 0; c < MAX_COMP; ++c) ph->has_force |= ph->body_force[c] != 0.0;
  }
  if (!(ph->visc = sl_scene_closure(sc, "viscosity"))) return 0;
  const sl_closure_desc *c = ph->visc->desc;
  char label[128], where[300];
  sl_closure_label(c, label, sizeof label);
  sl_scene_closure_where(sc, "viscosity", where, sizeof where);
  /* the navier_stokes model gives a constant density; a riding solids fraction gives phi and the mixture's */
  int rc2 = sl_point_bind(&ph->pc, ph->visc, quantity_names, riding ? Q_N : Q_PHI, "closure.viscosity",
                          riding ? "the mixture model" : "the navier_stokes model", d);
  if (rc2) return rc2;
  int in_shear = sl_point_has_input(&ph->pc, "shear_rate");
  int varies = in_shear || (riding && (sl_point_has_input(&ph->pc, "phi") || sl_point_has_input(&ph->pc, "density")));
  if (!sl_point_has_output(&ph->pc, "viscosity") || !varies)
    return sl_diag_set(d, SL_EBADINPUT, "%s %s does not map a shear rate%s to a viscosity", where, label,
                       riding ? " or a solids fraction" : "");
  sl_point_constant(&ph->pc, "mu_f", ph->viscosity);
  sl_point_constant(&ph->pc, "rho_f", ph->density);
  sl_point_constant(&ph->pc, "density", ph->density);
  ph->has_dmu = sl_point_differentiates(&ph->pc, "shear_rate");
  int k = sl_params_find(c, "yield_stress");
  if (k >= 0) {
    char buf[64];
    sl_params_format_value(c, ph->visc->params, k, buf, sizeof buf);
    sl_parse_real(buf, &ph->yield_stress);
  }
  return 0;
}

static void physics_opts(physics *ph, sl_flow_opts *o) {
  o->axisymmetric = ph->axisymmetric;
  o->density = ph->riding && ph->rider && ph->rider->rho_solid != ph->density ? (sl_coef){density_fn, ph, 0.0}
                                                                              : (sl_coef){NULL, NULL, ph->density};
  o->viscosity = ph->visc ? viscosity_fn : NULL;
  o->viscosity_user = ph;
  o->viscosity_value = ph->viscosity;
  o->body_force = ph->has_force ? force_fn : NULL;
  o->body_force_user = ph;
  o->extra_stress = ph->riding && ph->rider ? ph->rider->extra_stress : NULL;
  o->cell_drag = ph->riding && ph->rider ? ph->rider->cell_drag : NULL;
  o->centrifugal_density = ph->density; /* rho_f Omega^2 r goes into the pressure (sl_flow_opts) */
}

/* P_ref = rho_f Omega^2 |x - c|^2 / 2 (axisymmetric: rho_f Omega^2 r^2 / 2), the pressure of the fluid's
 * centrifugal force, which the solved pressure leaves out (sl_flow_opts centrifugal_density). */
static double centrifugal_pressure(const sl_flow_opts *o, const double *x) {
  double dx = x[0] - (o->axisymmetric ? 0.0 : o->rotation_centre[0]),
         dy = o->axisymmetric ? 0.0 : x[1] - o->rotation_centre[1];
  return 0.5 * o->centrifugal_density * o->omega * o->omega * (dx * dx + dy * dy);
}

/* ---- boundary conditions ------------------------------------------------- */

typedef struct bc {
  const char *name; /* the mesh's boundary name */
  const ns_boundary *in;
  int type;
  int slip_comp;             /* the velocity component normal to a straight slip boundary; -1: curved (slip.h) */
  double traction[MAX_COMP]; /* traction; or -p n for pressure (p in traction[0]) */
  int n_comp;
  const sl_flow_opts *frame; /* a rotating frame: natural boundaries also get P_ref n (centrifugal_pressure) */
} bc;

typedef struct bc_set {
  int n;
  bc *b;
  int time_dependent;
  int has_natural; /* an open, pressure or traction boundary: no pressure datum */
  int n_pairs;     /* periodic pairs (boundary, partner), each once */
  sl_periodic_pair *pairs;
  unsigned char *open;   /* [n]: the velocity is free there */
  unsigned char *curved; /* [n]: a slip boundary not along x or y (its nodes rotated, slip.h); NULL: none */
  const sl_scene *sc;    /* for the location of a value in messages */
} bc_set;

static void bc_set_free(bc_set *s) {
  free(s->b);
  free(s->pairs);
  free(s->open);
  free(s->curved);
  memset(s, 0, sizeof *s);
}

/* The component normal to an axis-aligned boundary, or -1. */
static int aligned_normal(const sl_mesh *m, int id) {
  int comp = -1;
  for (int k = m->bface_start[id]; k < m->bface_start[id + 1]; ++k) {
    double n[2];
    sl_mesh_face_normal(m, m->bface[k], n);
    int c = fabs(n[0]) > 1.0 - 1e-10 ? 0 : fabs(n[1]) > 1.0 - 1e-10 ? 1 : -1;
    if (c < 0 || (comp >= 0 && c != comp)) return -1;
    comp = c;
  }
  return comp;
}

static int expr_uses_t(const sl_scene_exprs *v) {
  for (int i = 0; i < v->n; ++i)
    if (sl_expr_uses(v->e[i], 2)) return 1;
  return 0;
}

static int bc_setup(const sl_scene *sc, int n_comp, int axi, bc_set *s, sl_diag *d) {
  const sl_mesh *m = sc->mesh;
  memset(s, 0, sizeof *s);
  s->b = calloc((size_t)m->n_boundaries + 1, sizeof *s->b);
  s->pairs = calloc((size_t)m->n_boundaries + 1, sizeof *s->pairs);
  s->open = calloc((size_t)m->n_boundaries + 1, 1);
  if (!s->b || !s->pairs || !s->open) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  s->n = m->n_boundaries, s->sc = sc;
  for (int i = 0; i < s->n; ++i) {
    bc *b = &s->b[i];
    b->name = m->boundary_names[i], b->in = sl_scene_boundary(sc, i), b->type = NS_WALL, b->n_comp = n_comp;
  }
  for (int k = 0; k < s->n; ++k) { /* in the file's order: the first of a periodic pair to name the other leads */
    int id = sc->boundary_order[k];
    const sl_src *sec = sl_scene_boundary_section(sc, id);
    if (!sec) continue;
    bc *b = &s->b[id];
    const ns_boundary *in = b->in;
    const char *name = b->name;
    char at[400];
    b->type = in->type;
    if (b->type == NS_VELOCITY) {
      if (in->velocity.n == 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = velocity needs velocity = <%d expressions of x, y, t>",
                           sec->file, sec->line, sec->section, n_comp);
      if (in->velocity.n > n_comp)
        return sl_diag_set(d, SL_EBADINPUT, "%s: %d components given, the scene has %d velocity components",
                           sl_scene_where(sc, &in->velocity, at, sizeof at), in->velocity.n, n_comp);
      /* the values at t = 0 along the boundary, where a bad expression shows before anything is written */
      for (int f = m->bface_start[id]; f < m->bface_start[id + 1]; ++f) {
        const int *fv = m->face_vertices + 2 * m->bface[f];
        for (int e = 0; e < 2 && fv[e] >= 0; ++e) { /* 1-D: one vertex */
          double v[3] = {m->xy[2 * fv[e]], m->xy[2 * fv[e] + 1], 0.0};
          for (int c = 0; c < in->velocity.n; ++c) {
            double u = sl_expr_eval(in->velocity.e[c], v);
            if (!isfinite(u))
              return sl_diag_set(d, SL_EBADINPUT, "%s: component %d is %g at (%g, %g), t = 0: not a finite velocity",
                                 sl_scene_where(sc, &in->velocity, at, sizeof at), c + 1, u, v[0], v[1]);
          }
        }
      }
      s->time_dependent |= expr_uses_t(&in->velocity);
    } else if (b->type == NS_SLIP) {
      /* along x or y: the normal component fixed (as it always was); any other shape: the nodes' velocity
         rotated into (n, t) with u_n fixed (core/assembly/slip.h) */
      if ((b->slip_comp = aligned_normal(m, id)) < 0) {
        if (m->dim != 2)
          return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = slip: '%s' is not a point of a 1-D mesh", sec->file,
                             sec->line, sec->section, name);
        if (!s->curved && !(s->curved = calloc((size_t)s->n + 1, 1))) return sl_diag_set(d, SL_ENOMEM, "out of memory");
        s->curved[id] = 1;
      }
    } else if (b->type == NS_AXIS) {
      if (!axi || aligned_normal(m, id) != 0)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] type = axis needs an axisymmetric scene and a boundary at r = 0", sec->file,
                           sec->line, sec->section);
      for (int f = m->bface_start[id]; f < m->bface_start[id + 1]; ++f) {
        double c[2];
        sl_mesh_face_centroid(m, m->bface[f], c);
        if (fabs(c[0]) > 1e-12)
          return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = axis: the boundary lies at r = %g, not on the axis",
                             sec->file, sec->line, sec->section, c[0]);
      }
    } else if (b->type == NS_PRESSURE) {
      int rc = sl_scene_require(sc, &in->pressure, d);
      if (rc) return rc;
      b->traction[0] = in->pressure;
      s->has_natural = 1;
    } else if (b->type == NS_TRACTION) {
      int rc = vec_get(sc, &in->traction, n_comp, b->traction, d);
      if (rc) return rc;
      s->has_natural = 1;
    } else if (b->type == NS_OPEN) {
      s->has_natural = 1;
    } else if (b->type == NS_PERIODIC) {
      /* the partner is the same boundary translated: its dofs become this boundary's */
      const char *partner = in->partner ? in->partner : "";
      int pid;
      if (!*partner) continue; /* the partner side of a pair named elsewhere: checked below */
      int rc = sl_mesh_boundary_id(m, partner, &pid, d);
      if (rc) return sl_diag_prefix(d, rc, "%s:%d: [%s] partner", sec->file, sec->line, sec->section);
      if (pid == id)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] partner: a boundary cannot be its own partner", sec->file,
                           sec->line, sec->section);
      sl_mesh_periodic pm;
      if ((rc = sl_mesh_periodic_match(m, name, partner, &pm, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] type = periodic", sec->file, sec->line, sec->section);
      double shift_r = pm.shift[0];
      sl_mesh_periodic_free(&pm);
      if (axi && fabs(shift_r) > 0.0)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] type = periodic: an axisymmetric scene repeats along z only, "
                           "and '%s' is '%s' moved by %g in r",
                           sec->file, sec->line, sec->section, partner, name, shift_r);
      s->pairs[s->n_pairs++] = (sl_periodic_pair){m->boundary_names[id], m->boundary_names[pid]};
    }
  }
  /* every periodic boundary belongs to exactly one pair; the partner of a pair is periodic too */
  for (int k = 0; k < s->n_pairs; ++k) {
    int pid = -1;
    sl_diag quiet;
    if (sl_mesh_boundary_id(m, s->pairs[k].partner, &pid, &quiet)) pid = -1;
    for (int j = 0; j < k; ++j)
      if (s->pairs[j].boundary == s->pairs[k].partner && s->pairs[j].partner == s->pairs[k].boundary) {
        s->pairs[k--] = s->pairs[--s->n_pairs]; /* written on both sides: keep one */
        pid = -1;
        break;
      }
    if (pid < 0) continue;
    const sl_src *ps = sl_scene_boundary_section(sc, pid);
    if (ps && s->b[pid].type != NS_PERIODIC)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] is the periodic partner of '%s' and cannot have another type",
                         ps->file, ps->line, ps->section, s->pairs[k].boundary);
    s->b[pid].type = NS_PERIODIC;
  }
  for (int i = 0; i < s->n; ++i) {
    if (s->b[i].type != NS_PERIODIC) continue;
    int paired = 0;
    for (int k = 0; k < s->n_pairs; ++k)
      paired |= strcmp(s->pairs[k].boundary, s->b[i].name) == 0 || strcmp(s->pairs[k].partner, s->b[i].name) == 0;
    if (!paired)
      return sl_diag_set(d, SL_EBADINPUT, "[boundary.%s] type = periodic needs partner = <the matching boundary>",
                         s->b[i].name);
  }
  /* Unnamed boundaries of an axisymmetric mesh called "axis" are the axis. */
  for (int i = 0; i < s->n && axi; ++i)
    if (strcmp(s->b[i].name, "axis") == 0 && !sl_scene_boundary_section(sc, i)) s->b[i].type = NS_AXIS;
  for (int i = 0; i < s->n; ++i) {
    int ty = s->b[i].type;
    s->open[i] = ty == NS_OPEN || ty == NS_PRESSURE || ty == NS_TRACTION;
  }
  return 0;
}

typedef struct bc_eval {
  const sl_expr *e;
  double t;
  int bad; /* a value was not finite: the first one and where */
  double bad_v, bad_x[2];
} bc_eval;

static void bc_value(void *user, const double x[2], double *v, double g[2]) {
  bc_eval *b = user;
  double vals[3] = {x[0], x[1], b->t};
  *v = sl_expr_eval(b->e, vals);
  if (!isfinite(*v) && !b->bad) b->bad = 1, b->bad_v = *v, b->bad_x[0] = x[0], b->bad_x[1] = x[1];
  if (g) g[0] = g[1] = 0.0;
}

/* Fixes the Dirichlet dofs at time t: slip and axis first, then prescribed
 * velocities, then walls, so that walls win shared corners. */
static int bc_apply(const bc_set *s, const sl_th_space *th, sl_constraints *con, double t, int datum, sl_diag *d) {
  int rc = 0;
  for (int pass = 0; pass < 3 && !rc; ++pass)
    for (int i = 0; i < s->n && !rc; ++i) {
      const bc *b = &s->b[i];
      if (pass == 0 && b->type == NS_SLIP && b->slip_comp >= 0)
        rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, b->slip_comp, 0), NULL, NULL, 0.0, d);
      if (pass == 0 && b->type == NS_AXIS) {
        rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, 0, 0), NULL, NULL, 0.0, d);
        if (!rc && th->n_comp == 3)
          rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, 2, 0), NULL, NULL, 0.0, d);
      }
      if (pass == 1 && b->type == NS_VELOCITY)
        for (int c = 0; c < th->n_comp && !rc; ++c) {
          if (c >= b->in->velocity.n) {
            rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, d);
            continue;
          }
          bc_eval be = {b->in->velocity.e[c], t, 0, 0.0, {0.0, 0.0}};
          rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, c, 0), bc_value, &be, 0.0, d);
          if (!rc && be.bad) { /* a time-dependent value that stops being finite: the run cannot go on */
            char at[400];
            rc = sl_diag_set(d, SL_EFAILED, "%s: component %d is %g at (%g, %g), t = %.9g: not a finite velocity",
                             sl_scene_where(s->sc, &b->in->velocity, at, sizeof at), c + 1, be.bad_v, be.bad_x[0],
                             be.bad_x[1], t);
          }
        }
      if (pass == 2 && b->type == NS_WALL) /* periodic boundaries carry no condition */
        for (int c = 0; c < th->n_comp && !rc; ++c)
          rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, d);
    }
  if (!rc && datum) sl_stokes_fix_pressure_datum(con, th);
  return rc;
}

static int traction_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const bc *bc_ = user;
  (void)d;
  for (int q = 0; q < b->n; ++q)
    for (int c = 0; c < bc_->n_comp; ++c) {
      double v;
      if (bc_->type == NS_PRESSURE) v = c < 2 ? -bc_->traction[0] * b->normal[q][c] : 0.0;
      else if (bc_->type == NS_OPEN) v = 0.0;
      else v = bc_->traction[c];
      /* the solved pressure is p - P_ref: sigma n = t becomes (sigma - ...) n = t + P_ref n */
      if (bc_->frame && c < 2) v += centrifugal_pressure(bc_->frame, b->x[q]) * b->normal[q][c];
      out[q * bc_->n_comp + c] = v;
    }
  return 0;
}

/* ---- the flow ---------------------------------------------------------------- */

struct sl_flow {
  sl_scene *sc;
  const sl_mesh *mesh;
  sl_th_space *th;
  physics ph;
  bc_set bcs;
  sl_flow_problem prob;
  sl_linsolve *ls;
  sl_slip slip;      /* the curved slip walls' nodes (slip.h; prob.slip points here when there are any) */
  sl_projection *pj; /* [flow] scheme = projection: the split transient step (projection.h); NULL: monolithic */
  sl_newton_opts nopts;
  unsigned fields;
  double *u;    /* the state: velocity and pressure */
  double *work; /* n_vel * 3 */
  double *cellbuf;
  /* the stream function (2-D, when written): from the rider's face fluxes, else from the flow's own */
  sl_stream_graph pg;
  sl_face_flux *ff;
  double *q, *psi, *node_psi;
  int datum;
  int stream_stats; /* [output] stream_function_stats */
  int riding;
  double rho_solid;
  sl_flow_rider rider;
  const char *linear; /* the solver's name */
  /* Solves whose result is known ([solver] skip_known): */
  int column_at_rest; /* a 1-D column between walls: div u = 0 makes u = 0 whatever the load */
  int unforced;       /* walls at rest all round, no body force, no rotation: only the rider loads it */
  int fixed_point;    /* the last accepted solve returned its start and the rider's phi has not changed since */
  int solved, solved_to_start; /* the last step's: solved (not skipped), and its result was its start */
  /* The forces on the boundaries with force = true (forces.h), written with every output: computed after the
   * solve of a step that writes (its mass term and history are then at hand), or at the write from the steady
   * residual (the initial state) */
  unsigned char *force_want, *force_work;
  double *force;
  int force_valid;
  /* what the nonlinear iterations are reported with (sc->hooks): the time solved for, the continuation stage */
  double t_solve;
  long stage, n_stages;
  /* the velocity a transient step may reach: SL_FLOW_GROWTH_FACTOR times the scale the data set, without the
     boundary speeds (measured per step at the constrained dofs); see velocity_scale */
  double u_data;
  const char *u_data_what;
  double accel;      /* the largest acceleration the forces give a fluid at rest, F / rho + |p| / (rho L) */
  double load_scale; /* the 2-norm of the load's own terms, for a linear step's round-off test (velocity_scale) */
  sl_model_stats st;
};

const sl_th_space *sl_flow_space(const sl_flow *f) { return f->th; }
const sl_flow_opts *sl_flow_options(const sl_flow *f) { return &f->prob.opts; }
const unsigned char *sl_flow_open(const sl_flow *f) { return f->bcs.open; }
const unsigned char *sl_flow_closed(const sl_flow *f) { return f->bcs.curved; }
int sl_flow_axisymmetric(const sl_flow *f) { return f->prob.opts.axisymmetric; }
const sl_periodic_pair *sl_flow_periodic(const sl_flow *f, int *n_pairs) {
  *n_pairs = f->bcs.n_pairs;
  return f->bcs.pairs;
}

void sl_flow_ride(sl_flow *f, const sl_flow_rider *r) {
  f->rider = *r;
  f->ph.rider = &f->rider;
  physics_opts(&f->ph, &f->prob.opts);
}

/* ---- output ---------------------------------------------------------------------- */

int sl_flow_write_mesh(sl_flow *f, sl_output *out, sl_diag *d) {
  const sl_th_space *th = f->th;
  static const char *const topo[] = {
      [SL_CELL_LINE2] = "Edge_3", [SL_CELL_TRI3] = "Triangle_6", [SL_CELL_QUAD4] = "Quadrilateral_9"};
  /* the geometric nodes: periodic boundaries keep both sides in the file */
  const double *coords = th->vel->node_xy;
  if (th->mesh->dim == 1) { /* the writer takes n x dim coordinates */
    for (int32_t i = 0; i < th->vel->n_nodes; ++i) f->work[i] = th->vel->node_xy[2 * i];
    coords = f->work;
  }
  return sl_output_write_mesh(out, th->mesh->dim, th->vel->n_nodes, coords, th->mesh->n_cells, th->vel->dofs_per_cell,
                              th->vel->cell_nodes, topo[th->mesh->cell_type], d);
}

/* The forces of u into f->force; steady: without the time derivative. */
static int compute_forces(sl_flow *f, const double *u, int steady, sl_diag *d) {
  double mass = f->prob.opts.mass_coef;
  const double *history = f->prob.opts.history;
  if (steady) f->prob.opts.mass_coef = 0.0, f->prob.opts.history = NULL;
  int rc = sl_flow_forces(&f->prob, u, f->force_want, f->force_work, f->force, d);
  f->prob.opts.mass_coef = mass, f->prob.opts.history = history;
  f->force_valid = rc == 0;
  return rc;
}

static int write_forces(sl_flow *f, sl_output *out, const double *u, sl_diag *d) {
  if (!f->force) return 0;
  int rc = f->force_valid ? 0 : compute_forces(f, u, 1, d);
  const sl_mesh *m = f->mesh;
  const char *axes = f->prob.opts.axisymmetric ? "rz" : "xy";
  for (int b = 0; b < m->n_boundaries && !rc; ++b) {
    if (!f->force_want[b]) continue;
    for (int i = 0; i < m->dim && !rc; ++i) {
      char name[300];
      snprintf(name, sizeof name, "force_%c_%s", axes[i], m->boundary_names[b]);
      /* planar: per metre of depth; axisymmetric: on the whole surface of revolution */
      rc = sl_output_write_scalar_unit(out, name, f->prob.opts.axisymmetric ? "N" : "N/m",
                                       f->force[f->th->n_comp * b + i], d);
    }
  }
  f->force_valid = 0;
  return rc;
}

/* The stream function's extremes over the vertices and the phase of its first azimuthal mode about the rotation
 * centre, arg int psi e^(i theta) dA (each cell: the mean of its vertices' psi, its centroid, its area), for
 * patterns that turn, such as Nigam's (1999, section 4.4) travelling waves psi = f(r) + g(r) cos(theta - c t),
 * whose phase is c t exactly. Sluice's psi is the thesis's with the opposite sign (u = psi_y here): the same
 * pattern has the phase shifted by pi. */
static int write_stream_stats(sl_flow *f, sl_output *out, sl_diag *d) {
  const sl_mesh *m = f->mesh;
  const double *psi = f->psi, *c0 = f->prob.opts.rotation_centre;
  double mx = -INFINITY, mn = INFINITY, re = 0.0, im = 0.0;
  for (int v = 0; v < m->n_vertices; ++v) mx = fmax(mx, psi[v]), mn = fmin(mn, psi[v]);
  int nv = m->nv_per_cell;
  for (int c = 0; c < m->n_cells; ++c) {
    const int *cv = m->cell_vertices + (size_t)nv * c;
    double area = 0.0, cx = 0.0, cy = 0.0, pm = 0.0;
    for (int k = 0; k < nv; ++k) { /* the polygon's area and centroid (shoelace) */
      const double *a = m->xy + 2 * cv[k], *b = m->xy + 2 * cv[(k + 1) % nv];
      double cr = (a[0] - c0[0]) * (b[1] - c0[1]) - (b[0] - c0[0]) * (a[1] - c0[1]);
      area += 0.5 * cr;
      cx += cr * (a[0] + b[0] - 2.0 * c0[0]) / 6.0, cy += cr * (a[1] + b[1] - 2.0 * c0[1]) / 6.0;
      pm += psi[cv[k]] / nv;
    }
    if (area == 0.0) continue;
    cx /= area, cy /= area;
    double r = hypot(cx, cy);
    if (r > 0.0) re += pm * area * cx / r, im += pm * area * cy / r;
  }
  /* the vortex's centre: the extremum of largest |psi|, placed below the cell size (sl_stream_centre), and its
     angle about the rotation centre, the phase of the pattern's strongest vortex */
  double xc[2], pc;
  if (sl_stream_centre(m, psi, xc, &pc) < 0) xc[0] = c0[0], xc[1] = c0[1];
  int rc = sl_output_write_scalar_unit(out, "stream_function_max", "m^2/s", mx, d);
  if (!rc) rc = sl_output_write_scalar_unit(out, "stream_function_min", "m^2/s", mn, d);
  if (!rc) rc = sl_output_write_scalar_unit(out, "stream_function_phase", "rad", atan2(im, re), d);
  if (!rc) rc = sl_output_write_scalar_unit(out, "stream_function_centre_x", "m", xc[0], d);
  if (!rc) rc = sl_output_write_scalar_unit(out, "stream_function_centre_y", "m", xc[1], d);
  if (!rc)
    rc =
        sl_output_write_scalar_unit(out, "stream_function_centre_phase", "rad", atan2(xc[1] - c0[1], xc[0] - c0[0]), d);
  return rc;
}

int sl_flow_write(sl_flow *f, sl_output *out, const double *u, sl_diag *d) {
  const sl_th_space *th = f->th;
  int rc = write_forces(f, out, u, d);
  if (f->fields & F_VELOCITY) {
    /* in the frame: in-plane components, then the out-of-plane one as component 2; axisymmetric, the
     * swirl is not a direction of the (r, z) plane: velocity (u_r, u_z, 0) and u_theta beside it */
    int swirl = f->ph.axisymmetric && th->n_comp == 3 && th->mesh->dim == 2;
    memset(f->work, 0, (size_t)th->vel->n_nodes * 3 * sizeof *f->work);
    for (int32_t i = 0; i < th->vel->n_nodes; ++i)
      for (int c = 0; c < th->n_comp - swirl; ++c)
        f->work[3 * i + (c < th->mesh->dim ? c : 2)] = u[sl_th_vel_dof(th, c, th->vel->node_dof[i])];
    rc = sl_output_write_field(out, "velocity", SL_CENTRE_NODE, 3, f->work, d);
    if (!rc && swirl) {
      for (int32_t i = 0; i < th->vel->n_nodes; ++i) f->work[i] = u[sl_th_vel_dof(th, 2, th->vel->node_dof[i])];
      rc = sl_output_write_field(out, "u_theta", SL_CENTRE_NODE, 1, f->work, d);
    }
  }
  if (!rc && (f->fields & F_PRESSURE)) {
    /* P1 pressure at every velocity node: the vertices carry their values,
     * the other nodes the average of their cell's vertices (exact for the
     * linear pressure on edge midpoints and the Q1 cell centre). */
    const double *p = u + th->p_offset;
    const double *shift = f->riding ? f->rider.pressure_shift : NULL;
    const sl_flow_opts *o = &f->prob.opts;
    int frame = o->omega != 0.0 && o->centrifugal_density != 0.0;
    if (shift || frame) { /* the pressure of what the rider kept out of the load, and of the frame's P_ref */
      double *ps = f->work + th->vel->n_nodes;
      for (int32_t i = 0; i < th->pres->n_dofs; ++i)
        ps[i] = p[i] + (shift ? shift[i] : 0.0) + (frame ? centrifugal_pressure(o, th->pres->xy + 2 * i) : 0.0);
      p = ps;
    }
    double mean = 0.0, area = 0.0;
    if (f->datum && sl_fe_integrate(th->pres, p, f->ph.axisymmetric, &mean, &area, NULL) == 0 && area > 0.0)
      mean /= area;
    else mean = 0.0;
    const sl_mesh *m = th->mesh;
    int nb = th->vel->dofs_per_cell, nvc = m->nv_per_cell;
    for (int c = 0; c < m->n_cells; ++c) {
      const int32_t *vd = th->vel->cell_nodes + (size_t)c * nb, *pn = th->pres->node_dof;
      const int *cv = m->cell_vertices + (size_t)c * nvc;
      for (int k = 0; k < nb; ++k) {
        double v;
        if (k < nvc) {
          v = p[pn[cv[k]]];
        } else if (m->dim == 1 || (m->cell_type == SL_CELL_QUAD4 && k == 8)) {
          v = 0.0;
          for (int j = 0; j < nvc; ++j) v += p[pn[cv[j]]];
          v /= nvc;
        } else {
          int e = k - nvc;
          v = 0.5 * (p[pn[cv[e]]] + p[pn[cv[(e + 1) % nvc]]]);
        }
        f->work[vd[k]] = v - mean;
      }
    }
    rc = sl_output_write_field(out, "pressure", SL_CENTRE_NODE, 1, f->work, d);
  }
  if (!rc && (f->fields & (F_SHEAR | F_VISCOSITY | F_YIELDED))) {
    int nc = th->mesh->n_cells;
    double *g = f->cellbuf, *mu = g + nc, *y = mu + nc;
    rc = sl_flow_cell_diagnostics(th, u, &f->prob.opts, f->ph.yield_stress, g, mu, y, d);
    if (!rc && (f->fields & F_SHEAR)) rc = sl_output_write_field(out, "shear_rate", SL_CENTRE_CELL, 1, g, d);
    if (!rc && (f->fields & F_VISCOSITY)) rc = sl_output_write_field(out, "viscosity", SL_CENTRE_CELL, 1, mu, d);
    if (!rc && (f->fields & F_YIELDED)) rc = sl_output_write_field(out, "yielded", SL_CENTRE_CELL, 1, y, d);
  }
  if (!rc && f->psi) {
    const double *q = f->riding ? f->rider.face_flux : f->q;
    if (!f->riding) rc = sl_face_flux_conservative(f->ff, u, 0.0, f->q, NULL, d);
    if (!rc && q) {
      sl_stream_function_nodes(th, &f->pg, q, f->psi, f->node_psi);
      /* Stokes' stream function of the (r, z) plane has the units of a flow rate per radian */
      rc = sl_output_write_field_unit(out, "stream_function", f->ph.axisymmetric ? "m^3/s" : "m^2/s", SL_CENTRE_NODE, 1,
                                      f->node_psi, d);
      if (!rc && f->stream_stats) rc = write_stream_stats(f, out, d);
    }
  }
  return rc;
}

int sl_flow_checkpoint(sl_flow *f, sl_checkpoint_array *a, int max) {
  /* the factorisation in hand, which a restart rebuilds (a run stopped anywhere, by max_steps too, goes on bit
     for bit as the uninterrupted one); where it cannot be, both start afresh */
  int n = sl_factor_checkpoint(f->ls, "linsolve_flow", a, max);
  if (!f->pj) return n;
  return n + sl_projection_checkpoint(f->pj, a + n, max - n);
}

int sl_flow_restore(sl_flow *f, const sl_checkpoint *ck, sl_diag *d) {
  int rc = sl_factor_restore(f->ls, "linsolve_flow", ck, d);
  return !rc && f->pj ? sl_projection_restore(f->pj, ck, d) : rc;
}

/* ---- solves ---------------------------------------------------------------- */

static void report_iteration(void *user, int iteration, int picard, double correction, double residual, double terms) {
  const sl_flow *f = user;
  sl_nl_report r = {.t = f->t_solve,
                    .stage = f->stage,
                    .n_stages = f->n_stages,
                    .iteration = iteration,
                    .picard = picard,
                    .correction = correction,
                    .residual = residual,
                    .terms = terms};
  f->sc->hooks.nonlinear(f->sc->hooks.user, &r);
}

/* A steady solve stops at an interrupt between its iterations; a transient step is finished first. */
static int solve_opts(sl_flow *f, double *u, int *iterations, int steady, sl_diag *d) {
  sl_newton_stats st;
  double c0 = cpu();
  sl_newton_opts o = f->nopts;
  if (f->sc->hooks.nonlinear) o.monitor = report_iteration, o.monitor_user = f;
  if (steady) o.interrupt = f->sc->hooks.interrupt;
  /* A time step starts from the BDF predictor: its first contraction may end it (sl_newton_opts predicted).
     An adaptive step is accurate to [time] tolerance of the largest velocity: without a [solver]
     nonlinear_tolerance of the scene's, its iterations stop at 1e-3 of that, as an integrator's Newton
     iteration stops at a fraction of the local error test (CVODE's 0.1: Hindmarsh et al. 2005, ACM TOMS 31:363,
     sec. 2.1), not at a steady solve's 1e-8. */
  if (!steady) {
    const sl_scene *sc = f->sc;
    o.predicted = 1;
    o.load_scale = f->load_scale;
    /* a linear step from a velocity at the round-off of the speed the data set (a vessel at rest, whose
       velocity the round-off test keeps at the predictor's) assembles its residual alone first (newton.h) */
    if (o.linear && f->u_data > 0.0) {
      double umax = 0.0;
      for (int32_t i = 0; i < f->th->p_offset; ++i) umax = fmax(umax, fabs(u[i]));
      o.residual_first = umax <= SL_NEWTON_ROUNDOFF * f->u_data;
    }
    if (sc->time.adaptive && !sl_scene_given(sc, &sc->solver.nonlinear_tolerance))
      o.rtol = fmax(o.rtol, SL_FLOW_STEP_NEWTON_FRACTION * sc->time.tolerance);
  }
  int rc = sl_flow_problem_solve(&f->prob, u, f->ls, &o, &st, d);
  if (rc == 0 && st.roundoff) f->st.roundoff_accepted++;
  if (iterations) *iterations = st.iterations;
  f->st.correction = st.correction;
  f->st.roundoff = st.roundoff, f->st.term_scale = st.term_scale, f->st.estimated = st.estimated;
  f->st.residual0 = st.residual0, f->st.residual = st.residual;
  f->st.matrix_assemblies += st.assemblies, f->st.residual_assemblies += st.residuals;
  f->st.assembly += st.t_assembly;
  if (st.picard_iterations) f->st.used_picard = 1;
  f->st.cpu_flow += cpu() - c0;
  return rc;
}

static int solve(sl_flow *f, double *u, int *iterations, sl_diag *d) { return solve_opts(f, u, iterations, 0, d); }

/* A transient step split into a velocity and a pressure Poisson solve (projection.h). Its one linear solve
 * stops at the relative residual of the Newton tolerance an adaptive step's monolithic solve would use
 * (solve_opts): its error is then below what Newton's last correction leaves (boycott to t = 0.3: 1e-8
 * instead gave 9.8 FGMRES iterations a solve against 8.1 and moved the interface height by 1e-10). */
static int split_step(sl_flow *f, sl_step *s, int *iterations, sl_diag *d) {
  if (sl_projection_needs_start(f->pj)) {
    int rc = solve_opts(f, s->u, iterations, 0, d);
    if (rc == 0) sl_projection_started(f->pj, s->mass_coef);
    return rc;
  }
  double c0 = cpu();
  const sl_scene *sc = f->sc;
  double rtol = f->nopts.rtol;
  if (sc->time.adaptive && !sl_scene_given(sc, &sc->solver.nonlinear_tolerance))
    rtol = fmax(rtol, SL_FLOW_STEP_NEWTON_FRACTION * sc->time.tolerance);
  double t_asm = 0.0;
  int rc = sl_projection_step(f->pj, &f->prob, s, s->u, rtol, &t_asm, d);
  if (rc == 0 && sc->time.adaptive) {
    /* The splitting's perturbation of the step's velocity against the tolerance, as the BDF estimate's
       (sl_bdf_error: of the largest velocity): the step controller does not see it in the BDF estimate of the
       intermediate velocity, and without it spinup at its tolerance took steps of up to dt_max = 0.5 and put the
       shock 0.044 off the theory (0.021 with it, 0.018 with dt_max = 0.125 and no such estimate). */
    double size = 0.0;
    for (int32_t i = 0; i < f->th->p_offset; ++i) size = fmax(size, fabs(s->u[i]));
    s->error = sl_projection_split_rms(f->pj) / (sc->time.tolerance * fmax(size, 1e-12));
  }
  f->st.matrix_assemblies++;
  f->st.assembly += t_asm;
  if (iterations) *iterations = 1;
  f->st.cpu_flow += cpu() - c0;
  return rc;
}

static int force_depends_on_t(const physics *ph) {
  for (int c = 0; c < MAX_COMP; ++c)
    if (ph->force_expr[c] && sl_expr_uses(ph->force_expr[c], 2)) return 1;
  return 0;
}

/* A transient step whose velocity grows without bound is rejected and the run stops: |u| above
 * SL_FLOW_GROWTH_FACTOR times the largest speed the data set, the boundary speeds at the step's end (the
 * constrained dofs), the initial velocity, the free-fall speed sqrt(2 F L / rho) of the body force and the
 * buoyancy F over the domain's size L, the Bernoulli speed sqrt(2 |p| / rho) of a given pressure or traction and
 * the frame's |omega| L, and the speed those forces give a fluid from rest over the time t run (F t / rho: a
 * periodic channel accelerates without a length to bound it). A flow the data drive does not leave these by two
 * orders of magnitude (a lid-driven
 * cavity stays below its lid's speed at any Re; a 10:1 contraction speeds its inflow up tenfold); an unstable
 * time integration or an unresolved flow does (issue 25: |u| 1.9e5 under a lid of 1). */
#define SL_FLOW_GROWTH_FACTOR 100.0

static int check_growth(const sl_flow *f, const double *u, double t, sl_diag *d) {
  const sl_flow_problem *p = &f->prob;
  int32_t nv = f->th->p_offset;
  double u_bc = 0.0, umax = 0.0;
  for (int32_t k = 0; k < p->n_fixed; ++k)
    if (p->fixed[k] < nv) u_bc = fmax(u_bc, fabs(u[p->fixed[k]]));
  int32_t at = 0;
  for (int32_t i = 0; i < nv; ++i)
    if (fabs(u[i]) > umax || !(fabs(u[i]) <= umax)) {
      umax = fabs(u[i]), at = i;
      if (!isfinite(umax)) break;
    }
  double u_acc = f->accel * t; /* a periodic channel's forcing accelerates for as long as the run lasts */
  double scale = fmax(fmax(u_bc, f->u_data), u_acc), bound = SL_FLOW_GROWTH_FACTOR * scale;
  if (scale > 0.0 && umax <= bound) return 0;
  if (scale == 0.0 && umax == 0.0) return 0;    /* nothing drives it, nothing moves */
  if (scale == 0.0 && isfinite(umax)) return 0; /* no scale to judge by (round-off of a vessel at rest) */
  return sl_diag_set(d, SL_EFAILED,
                     "the velocity grew without bound in the step to t = %.6g: |u| = %.3g (unknown %d) exceeds %g "
                     "times the speed the data set, %.3g (%s); the step is rejected (a smaller dt, a finer mesh or "
                     "a viscosity closure may resolve the flow)",
                     t, umax, (int)at, SL_FLOW_GROWTH_FACTOR, scale,
                     u_acc >= fmax(u_bc, f->u_data) ? "the forces' acceleration over the time run"
                     : u_bc >= f->u_data            ? "the boundary speed"
                                                    : f->u_data_what);
}

int sl_flow_step(sl_flow *f, sl_step *s, int *iterations, sl_diag *d) {
  f->prob.opts.mass_coef = s->mass_coef;
  f->prob.opts.history = s->history;
  int rc;
  if (f->bcs.time_dependent && (rc = bc_apply(&f->bcs, f->th, &f->prob.bc, s->t + s->dt, f->datum, d))) return -rc;
  size_t bytes = (size_t)f->th->n_dofs * sizeof *s->u;
  f->solved = 0;
  f->force_valid = 0;
  f->ph.t = f->t_solve = s->t + s->dt;
  /* Skip what is known: a vessel at rest under no load stays at rest; a closed column's velocity is 0 and its
     pressure is needed only when written; a flow at a fixed point whose phi has not changed gives itself again. */
  if (f->sc->solver.skip_known && s->state) {
    const sl_flow_rider *r = &f->rider;
    int rest = f->riding && f->unforced && r->at_rest && r->at_rest(r->user);
    for (int32_t i = 0; i < f->th->p_offset && rest; ++i) rest = s->state[i] == 0.0;
    if (rest) { /* zero velocity and (reduced) pressure */
      memset(s->u, 0, bytes);
      f->st.solves_skipped++;
      if (f->pj) sl_projection_skip(f->pj);
      return 0;
    }
    if ((f->column_at_rest && !(s->writes && (f->fields & F_PRESSURE))) ||
        (f->fixed_point && !f->bcs.time_dependent && !force_depends_on_t(&f->ph))) {
      memcpy(s->u, s->state, bytes);
      f->st.solves_skipped++;
      if (f->pj) sl_projection_skip(f->pj);
      return 0;
    }
  }
  if (f->riding && f->rider.prepare && (rc = f->rider.prepare(f->rider.user, s->dt, s->u, d))) return sl_step_code(rc);
  rc = f->pj ? split_step(f, s, iterations, d) : solve(f, s->u, iterations, d);
  if (rc == 0 && (rc = check_growth(f, s->u, s->t + s->dt, d))) return -rc;
  f->solved = 1;
  if (rc == 0 && f->force && s->writes && (rc = compute_forces(f, s->u, 0, d))) return -rc;
  if (rc == 0 && f->column_at_rest) memset(s->u, 0, (size_t)f->th->p_offset * sizeof *s->u);
  f->solved_to_start = rc == 0 && s->state && memcmp(s->u, s->state, bytes) == 0;
  return sl_step_code(rc);
}

void sl_flow_accept(sl_flow *f) {
  if (f->pj) sl_projection_accept(f->pj);
  if (f->solved) f->fixed_point = f->solved_to_start;
  if (f->riding && !(f->rider.unchanged && f->rider.unchanged(f->rider.user))) f->fixed_point = 0;
}

/* Rebuilds the physics after a change of the scene (continuation). */
static int rebuild_physics(sl_flow *f, sl_diag *d) {
  physics_free(&f->ph);
  int rc =
      physics_setup(f->sc, f->th->n_comp, f->mesh->dim, f->prob.opts.axisymmetric, f->riding, f->rho_solid, &f->ph, d);
  if (rc) return rc;
  if (f->riding) f->ph.rider = &f->rider;
  int convection = f->prob.opts.convection;
  double omega = f->prob.opts.omega, c0 = f->prob.opts.rotation_centre[0], c1 = f->prob.opts.rotation_centre[1];
  physics_opts(&f->ph, &f->prob.opts);
  f->prob.opts.convection = convection, f->prob.opts.omega = omega;
  f->prob.opts.rotation_centre[0] = c0, f->prob.opts.rotation_centre[1] = c1;
  return 0;
}

/* How the last solve converged, in words that agree with the numbers: the
 * last correction against the tolerance, the residual against its terms'
 * scale; or the residual at round-off (the correction then measures noise). */
/* A one-line reason longer than its buffer ends in "..." rather than mid-word without notice. */
static void mark_cut(char *line, size_t cap) {
  if (cap > 4) memcpy(line + cap - 4, "...", 4);
}

static const char *converged_text(const sl_flow *f, char *buf, size_t cap) {
  const sl_model_stats *r = &f->st;
  double rel = r->term_scale > 0 ? r->residual / r->term_scale : 0.0;
  if (r->roundoff)
    snprintf(buf, cap, "residual %.2g from %.2g: at the round-off of its terms' scale %.2g, the corrections noise",
             r->residual, r->residual0, r->term_scale);
  else
    snprintf(buf, cap, "relative correction %.2g%s <= tolerance %g; residual %.2g from %.2g, %.2g of its terms' scale",
             r->correction, r->estimated ? " (the next one's, estimated)" : "", f->nopts.rtol, r->residual,
             r->residual0, rel);
  return buf;
}

static int diag_append(sl_diag *d, int rc, const char *tail) {
  char msg[sizeof d->msg];
  memcpy(msg, d->msg, sizeof msg);
  return sl_diag_set(d, rc, "%.1700s%s", msg, tail);
}

int sl_flow_steady(sl_flow *f, double *u, long *steps, long *iterations, sl_diag *d) {
  char tb[240];
  const sl_solver_config *sv = &f->sc->solver;
  sl_model_stats *r = &f->st;
  const char *key = sv->continuation ? sv->continuation : "";
  int rc = 0;
  *steps = 0, *iterations = 0;
  f->t_solve = 0.0, f->stage = f->n_stages = 0;
  if (!*key) {
    int its = 0;
    rc = solve_opts(f, u, &its, 1, d);
    *steps = 1, *iterations = its;
    if (rc) {
      sl_diag_prefix(d, rc, "steady solve");
      return diag_append(d, rc, "; the state saved is the last Newton iterate, not a solution");
    }
    f->force_valid = 0;
    r->converged = 1;
    if (f->nopts.linear)
      snprintf(r->stop_reason, sizeof r->stop_reason,
               "steady state solved: a linear problem, one solve (residual %.2g)", r->residual);
    else if (snprintf(r->stop_reason, sizeof r->stop_reason, "steady state converged in %d Newton iteration%s (%s)",
                      its, its == 1 ? "" : "s", converged_text(f, tb, sizeof tb)) >= (int)sizeof r->stop_reason)
      mark_cut(r->stop_reason, sizeof r->stop_reason);
    return 0;
  }
  /* continuation: section.key from continuation_from to its scene value (checked at set-up); a stage that
     fails leaves the state of the last converged one */
  double target, from = sv->continuation_from;
  long n_stages = sv->continuation_steps;
  if ((rc = sl_scene_get_real(f->sc, key, &target, d))) return rc;
  size_t bytes = (size_t)f->th->n_dofs * sizeof *u;
  double *good = malloc(bytes), v_good = NAN;
  if (!good) return sl_diag_set(d, SL_ENOMEM, "continuation: out of memory");
  int geometric = from > 0 && target > 0;
  f->n_stages = n_stages + 1;
  /* A stage's first and damped Newton corrections to a relative residual of SL_FLOW_CONTINUATION_DAMPED_RTOL
     (newton.h damped_linear_rtol), and a larger FGMRES budget for the older factorisation: the damped iterations
     at the start of a stage are then mostly answered by FGMRES instead of a factorisation each (the Bingham
     cavity at Bn = 20 on 16 x 16 cells, every stage to 1e-9: 39 factorisations with direct solves, 9 with this;
     test scenes_flow_bingham_continuation, docs/benchmarks.md). */
  sl_linsolve_reuse reuse = sl_linsolve_get_reuse(f->ls), wide = reuse;
  if (wide.enabled)
    wide.max_iterations = SL_FLOW_CONTINUATION_FGMRES, wide.slow_iterations = SL_FLOW_CONTINUATION_FGMRES_SLOW;
  sl_linsolve_set_reuse(f->ls, &wide);
  double damped = f->nopts.damped_linear_rtol;
  f->nopts.damped_linear_rtol = SL_FLOW_CONTINUATION_DAMPED_RTOL;
  for (long k = 0; k <= n_stages && !rc; ++k) {
    double s = (double)k / (double)n_stages;
    double v = geometric ? from * pow(target / from, s) : from + (target - from) * s;
    if (k == n_stages) v = target;
    f->stage = k + 1;
    if (f->sc->hooks.interrupt && *f->sc->hooks.interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "interrupted before continuation stage %ld of %ld (%s = %g)", k + 1, n_stages + 1,
                       key, v);
      break;
    }
    if ((rc = sl_scene_set_real(f->sc, key, v, d))) break;
    if ((rc = rebuild_physics(f, d))) break;
    int its = 0;
    double rtol = f->nopts.rtol;
    if (k < n_stages && sv->continuation_tolerance > 0) f->nopts.rtol = fmax(rtol, sv->continuation_tolerance);
    rc = solve_opts(f, u, &its, 1, d);
    f->nopts.rtol = rtol;
    *iterations += its;
    if (rc) rc = sl_diag_prefix(d, rc, "continuation stage %ld of %ld (%s = %g)", k + 1, n_stages + 1, key, v);
    (*steps)++;
    if (!rc) memcpy(good, u, bytes), v_good = v;
    if (!rc && k == n_stages) {
      r->converged = 1;
      if (snprintf(
              r->stop_reason, sizeof r->stop_reason,
              "steady state converged at %s = %g, the last of %ld continuation stages, in %d Newton iteration%s (%s)",
              key, v, n_stages + 1, its, its == 1 ? "" : "s",
              converged_text(f, tb, sizeof tb)) >= (int)sizeof r->stop_reason)
        mark_cut(r->stop_reason, sizeof r->stop_reason);
    }
  }
  f->nopts.damped_linear_rtol = damped;
  sl_linsolve_set_reuse(f->ls, &reuse);
  if (rc && isfinite(v_good)) {
    memcpy(u, good, bytes);
    char tail[300];
    snprintf(tail, sizeof tail, "; the state saved is the last converged stage's, %s = %g", key, v_good);
    diag_append(d, rc, tail);
  } else if (rc) {
    diag_append(d, rc, "; the state saved is the last Newton iterate, not a solution");
  }
  free(good);
  return rc;
}

void sl_flow_stats(sl_flow *f, sl_model_stats *st) {
  *st = f->st;
  if (f->pj) { /* the transient steps' solves are the velocity's */
    st->linear = *sl_linsolve_get_stats(sl_projection_velocity_solver(f->pj));
    st->has_linear = 1;
    sl_projection_summary(f->pj, st->linear_summary, sizeof st->linear_summary);
  } else if (f->ls) {
    st->linear = *sl_linsolve_get_stats(f->ls);
    st->has_linear = 1;
    sl_linsolve_summary(f->ls, st->linear_summary, sizeof st->linear_summary);
  }
}

/* ---- set-up and teardown ---------------------------------------------------- */

/* A body force that is not finite somewhere at t = 0 is bad input, found before the output opens (at the
 * vertices: where a log or a division would fail first). */
static int check_body_force(const sl_scene *sc, const physics *ph, sl_diag *d) {
  if (!ph->force_varies) return 0;
  const sl_mesh *m = sc->mesh;
  for (int v = 0; v < m->n_vertices; ++v) {
    double xyt[3] = {m->xy[2 * v], m->xy[2 * v + 1], 0.0};
    for (int c = 0; c < ph->n_comp; ++c) {
      double f = ph->force_expr[c] ? sl_expr_eval(ph->force_expr[c], xyt) : 0.0;
      if (!isfinite(f)) {
        char at[400];
        return sl_diag_set(d, SL_EBADINPUT, "%s: component %d is %g at (%g, %g), t = 0",
                           sl_scene_where(sc, &sc->flow.body_force, at, sizeof at), c + 1, f, xyt[0], xyt[1]);
      }
    }
  }
  return 0;
}

/* The stream function's storage (2-D, when written). Without a rider the fluxes are the flow's own, made
 * conservative cell by cell (core/fv/face_flux.h); a periodic pair would make psi multivalued there. */
static int stream_setup(sl_flow *f, sl_diag *d) {
  const sl_mesh *m = f->mesh;
  if (!(f->fields & F_STREAM) || m->dim != 2) return 0;
  if (!f->riding && f->bcs.n_pairs > 0)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[output] fields = stream_function: not with periodic boundaries (the "
                       "stream function would not be periodic)");
  f->psi = malloc((size_t)m->n_vertices * sizeof *f->psi);
  f->node_psi = malloc((size_t)f->th->vel->n_nodes * sizeof *f->node_psi);
  if (!f->riding) f->q = malloc((size_t)m->n_faces * sizeof *f->q);
  if (!f->psi || !f->node_psi || (!f->riding && !f->q) || sl_stream_graph_build(&f->pg, m))
    return sl_diag_set(d, SL_ENOMEM, "stream function: out of memory");
  if (f->riding) return 0;
  int rc = sl_face_flux_create(f->th, f->prob.opts.axisymmetric, f->bcs.open, NULL, 0, &f->ff, d);
  return rc ? rc : sl_face_flux_close(f->ff, f->bcs.curved, d);
}

static int initial_velocity(const sl_scene *sc, const sl_flow_config *fc, const sl_th_space *th, double *u,
                            sl_diag *d) {
  const sl_scene_exprs *v = &fc->velocity;
  if (v->n > th->n_comp) {
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT, "%s: %d components given, the scene has %d velocity components",
                       sl_scene_where(sc, v, at, sizeof at), v->n, th->n_comp);
  }
  for (int c = 0; c < v->n; ++c) {
    bc_eval be = {v->e[c], 0.0, 0, 0.0, {0.0, 0.0}};
    sl_fe_interpolate(th->vel, bc_value, &be, u + sl_th_vel_dof(th, c, 0));
    /* evaluated once, here: a value that is not finite is bad input, found before anything is written */
    for (int32_t i = 0; i < th->vel->n_nodes; ++i) {
      double ui = u[sl_th_vel_dof(th, c, th->vel->node_dof[i])];
      if (!isfinite(ui)) {
        char at[400];
        return sl_diag_set(d, SL_EBADINPUT, "%s: component %d is %g at (%g, %g): not a finite velocity",
                           sl_scene_where(sc, v, at, sizeof at), c + 1, ui, th->vel->node_xy[2 * i],
                           th->vel->node_xy[2 * i + 1]);
      }
    }
  }
  return 0;
}

/* The speed the data set besides the boundary speeds (check_growth): the initial velocity, the free fall
 * of the body force and buoyancy over the domain, the Bernoulli speed of given pressures, the frame's. */
static void velocity_scale(sl_flow *f) {
  const sl_mesh *m = f->mesh;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int v = 0; v < m->n_vertices; ++v)
    for (int k = 0; k < 2; ++k) lo[k] = fmin(lo[k], m->xy[2 * v + k]), hi[k] = fmax(hi[k], m->xy[2 * v + k]);
  double L = hypot(hi[0] - lo[0], m->dim > 1 ? hi[1] - lo[1] : 0.0);
  const physics *ph = &f->ph;
  double rho = ph->density > 0 ? ph->density : 1.0;
  /* buoyancy: the whole density without solids (the pressure carries it, but it is what a wrong pressure
     would accelerate); with solids the contrast */
  double rho_g = f->riding ? fabs(f->rho_solid - ph->density) : ph->density;
  double F = 0.0, g = 0.0;
  for (int c = 0; c < MAX_COMP; ++c) g += ph->gravity[c] * ph->gravity[c], F = fmax(F, fabs(ph->body_force[c]));
  for (int v = 0; v < m->n_vertices && ph->force_varies; ++v) {
    double xyt[3] = {m->xy[2 * v], m->xy[2 * v + 1], 0.0};
    for (int c = 0; c < ph->n_comp; ++c)
      if (ph->force_expr[c]) F = fmax(F, fabs(sl_expr_eval(ph->force_expr[c], xyt)));
  }
  F += rho_g * sqrt(g);
  double u0 = 0.0, p = 0.0;
  for (int32_t i = 0; i < f->th->p_offset; ++i) u0 = fmax(u0, fabs(f->u[i]));
  for (int i = 0; i < f->bcs.n; ++i)
    for (int c = 0; c < MAX_COMP; ++c) p = fmax(p, fabs(f->bcs.b[i].traction[c]));
  double cand[4] = {u0, sqrt(2.0 * F * L / rho), sqrt(2.0 * p / rho), fabs(f->prob.opts.omega) * L};
  static const char *const what[4] = {"the initial velocity", "the free fall of the body force and buoyancy",
                                      "the Bernoulli speed of the given pressure", "the frame's rotation"};
  f->accel = F / rho + (L > 0 ? p / (rho * L) : 0.0);
  /* The load's own terms, |f_i| <= F int |psi_i| over the velocity basis: the domain's measure (weighted by r when
     axisymmetric, as the quadrature is) shared among the n velocity unknowns, |f|_2 ~ F |Omega| / sqrt(n), and
     the tractions' p L on the boundary alike (sl_newton_opts load_scale: a linear step whose residual is at the
     round-off of these is not solved). */
  double measure = 0.0;
  for (int c = 0; c < m->n_cells; ++c) {
    double x[2] = {1.0, 0.0};
    if (f->prob.opts.axisymmetric) sl_mesh_cell_centroid(m, c, x);
    measure += sl_mesh_cell_area(m, c) * fabs(x[0]);
  }
  double r_max = f->prob.opts.axisymmetric ? fmax(fabs(lo[0]), fabs(hi[0])) : 1.0;
  f->load_scale = (F * measure + p * L * r_max) / sqrt(fmax(1.0, (double)f->th->p_offset));
  f->u_data = 0.0, f->u_data_what = what[0];
  for (int k = 0; k < 4; ++k)
    if (cand[k] > f->u_data) f->u_data = cand[k], f->u_data_what = what[k];
}

/* [solver] continuation names a real value the flow can vary, and its start. */
static int check_continuation(const sl_scene *sc, sl_diag *d) {
  const sl_solver_config *sv = &sc->solver;
  if (!sv->continuation || !*sv->continuation) return 0;
  char at[400];
  double v;
  sl_diag inner;
  if (sl_scene_get_real(sc, sv->continuation, &v, &inner))
    return sl_diag_set(d, SL_EBADINPUT, "%s = %s: %s", sl_scene_where(sc, &sv->continuation, at, sizeof at),
                       sv->continuation, inner.msg);
  if (!sl_scene_given(sc, &sv->continuation_from))
    return sl_diag_set(d, SL_EBADINPUT, "%s: continuation needs continuation_from = <the first value>",
                       sl_scene_where(sc, &sv->continuation, at, sizeof at));
  return 0;
}

/* The curved slip walls (slip.h): their nodes after the other conditions are fixed (walls win corners; a
 * corner between slip faces is fixed to rest). The rotated rows are combined on one rank with a matrix
 * sluice assembles whole: not under mpirun, not with PETSc (its field split reads the velocity rows as they
 * were). */
static int slip_setup(sl_flow *f, sl_diag *d) {
  const bc_set *s = &f->bcs;
  if (!s->curved) return 0;
  int *ids = malloc(2 * ((size_t)s->n + 1) * sizeof *ids), n_slip = 0, n_other = 0, rc;
  if (!ids) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  int *other = ids + s->n + 1;
  const char *name = "";
  for (int i = 0; i < s->n; ++i) {
    if (s->curved[i]) ids[n_slip++] = i, name = n_slip == 1 ? s->b[i].name : name;
    else if (s->b[i].type == NS_SLIP || s->b[i].type == NS_AXIS) other[n_other++] = i;
  }
  int rank = 0, ranks = 1;
  char at[400];
  const sl_src *sec = NULL;
  for (int i = 0; i < s->n && !sec; ++i)
    if (s->curved[i]) sec = sl_scene_boundary_section(f->sc, i);
  snprintf(at, sizeof at, "%s:%d: [%s] type = slip", sec ? sec->file : "?", sec ? sec->line : 0,
           sec ? sec->section : name);
  if ((rc = sl_linsolve_ranks(&rank, &ranks, d))) goto out;
  if (ranks > 1 && sl_linsolve_built("petsc")) {
    rc = sl_diag_set(d, SL_EBADINPUT, "%s on a curved boundary ('%s') runs on one rank (this run has %d)", at, name,
                     ranks);
    goto out;
  }
  if (f->linear && strcmp(f->linear, "petsc") == 0) {
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s on a curved boundary ('%s') needs a direct solver: [solver] linear = auto, "
                     "umfpack or klu, not petsc",
                     at, name);
    goto out;
  }
  rc = sl_slip_create(&f->slip, f->th, ids, n_slip, other, n_other, f->prob.opts.axisymmetric, &f->prob.bc, d);
  if (!rc) f->prob.slip = &f->slip;
out:
  free(ids);
  return rc;
}

/* [flow] scheme = projection: the split step's solvers and operators (a transient scene only). chi, the
 * Poisson equation's density, is the smallest the flow can take (Guermond & Salgado 2009, chi <= rho): the
 * fluid's, or with solids riding on it the lighter of fluid and solid. */
static int projection_setup(sl_flow *f, sl_diag *d) {
  const sl_scene *sc = f->sc;
  int rank = 0, ranks = 1, rc0 = sl_linsolve_ranks(&rank, &ranks, d);
  if (rc0) return rc0;
  /* auto (the default, docs/transient_cost.md "The default scheme", measured): the split step for a transient
     suspension (solids riding on the flow) in a frame at rest and without a yield stress, on any number of
     ranks, where it costs 0.3-0.4 of the monolithic step at the scenes' accuracy; the monolithic step otherwise:
     the rotating waves' split step is unstable by t = 7.8 with a no-slip wall at Omega dt = 10, the Bingham
     bed's steps fall to 1e-5 under the splitting error of a 1e5 viscosity contrast, and the plain fluid's scenes keep their
     second-order pressure. A linear (Stokes) step stays monolithic too: one solve a step, none where the
     load is at round-off (the box at rest 0.065 s against the split step's 0.61 s; boycott with convection off
     to t = 0.2, 2.2 s against 1.9 s). */
  int linear = !sc->flow.convection && !f->ph.visc;
  if (sc->flow.scheme == 2 && (sc->time.scheme == SL_SCHEME_STEADY || !f->riding || sc->flow.rotation != 0.0 ||
                               f->ph.yield_stress > 0.0 || linear))
    return 0;
  if (sc->flow.scheme == 0) return 0;
  char at[400];
  if (sc->time.scheme == SL_SCHEME_STEADY)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s = projection: a split time step needs a transient [time] scheme "
                       "(bdf1 or bdf2); a steady scene is solved monolithic",
                       sl_scene_where(sc, &sc->flow.scheme, at, sizeof at));
  sl_projection_opts o = {.chi = f->riding ? fmin(f->ph.density, f->rho_solid) : f->ph.density,
                          .mu_rotational = f->ph.visc ? 0.0 : f->ph.viscosity,
                          .open = f->bcs.open,
                          .datum = f->datum,
                          .rank = rank,
                          .ranks = ranks,
                          .shear_free = !(f->ph.visc && f->ph.has_dmu)};
  const char *name;
  int rc = sl_scene_linsolve_general(sc, f->th->p_offset, "the split step's velocity matrix is nonsymmetric",
                                     &o.velocity_solver, &name, d);
  if (rc) return rc;
  /* PETSc (under mpirun, or chosen): both operators assembled on the ranks' cells and solved on their rows by
     Krylov solvers with the roles' defaults (linsolve.h); otherwise F's diagonal blocks precondition FGMRES */
  o.distributed = strcmp(name, "petsc") == 0;
  if ((rc = sl_scene_linsolve_general(sc, f->th->pres->n_dofs, "", &o.poisson_solver, &name, d)) ||
      (!o.distributed &&
       (rc = sl_scene_linsolve_general(sc, f->th->p_offset, "", &o.preconditioner_solver, &name, d)))) {
    sl_linsolve_destroy(o.velocity_solver), sl_linsolve_destroy(o.poisson_solver);
    return rc;
  }
  /* F's diagonal blocks only precondition FGMRES on F itself: their factors in single precision (linsolve.h) */
  if (!o.distributed &&
      (rc = sl_linsolve_set_role(o.preconditioner_solver, SL_LINSOLVE_ROLE_PRECONDITIONER, d))) {
    sl_linsolve_destroy(o.velocity_solver), sl_linsolve_destroy(o.poisson_solver);
    sl_linsolve_destroy(o.preconditioner_solver);
    return rc;
  }
  if (o.distributed &&
      ((rc = sl_linsolve_set_role(o.velocity_solver, SL_LINSOLVE_ROLE_VELOCITY, d)) ||
       (rc = sl_linsolve_set_role(o.poisson_solver,
                                  sc->flow.rotation != 0.0 ? SL_LINSOLVE_ROLE_POISSON_NONSYM : SL_LINSOLVE_ROLE_POISSON,
                                  d)))) {
    sl_linsolve_destroy(o.velocity_solver), sl_linsolve_destroy(o.poisson_solver);
    return rc;
  }
  return sl_projection_create(&f->prob, &o, &f->pj, d);
}

int sl_flow_create(sl_scene *sc, const sl_flow_config *fc, double rho_solid, unsigned fields, sl_flow **out,
                   sl_model_info *info, sl_diag *d) {
  *out = NULL;
  sl_flow *f = calloc(1, sizeof *f);
  if (!f) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  f->sc = sc, f->mesh = sc->mesh, f->fields = fields, f->stream_stats = fc->stream_stats;
  f->riding = rho_solid >= 0.0, f->rho_solid = rho_solid;
  int geometry = sc->geometry, third = sc->flow.third_component, rc;
  int dim = f->mesh->dim, axi = geometry == 2;
  if ((geometry == 0) != (dim == 1)) {
    rc = sl_diag_set(d, SL_EBADINPUT, "[scene] geometry = %s but the mesh is %d-D",
                     geometry == 0   ? "line"
                     : geometry == 1 ? "planar"
                                     : "axisymmetric",
                     dim);
    goto fail;
  }
  if ((rc = check_continuation(sc, d))) goto fail;
  if ((rc = bc_setup(sc, dim + (third ? 1 : 0), axi, &f->bcs, d))) goto fail;
  if ((rc = sl_th_create_periodic(f->mesh, dim + (third ? 1 : 0), f->bcs.pairs, f->bcs.n_pairs, &f->th, d))) goto fail;
  if ((rc = physics_setup(sc, f->th->n_comp, dim, axi, f->riding, rho_solid, &f->ph, d))) goto fail;
  if ((rc = sl_flow_problem_init(&f->prob, f->th, d))) goto fail;
  physics_opts(&f->ph, &f->prob.opts);
  f->prob.opts.convection = sc->flow.convection;
  f->prob.opts.omega = sc->flow.rotation;
  const sl_reals *ce = &sc->flow.rotation_centre;
  f->prob.opts.rotation_centre[0] = ce->n > 0 ? ce->v[0] : 0.0,
  f->prob.opts.rotation_centre[1] = ce->n > 1 ? ce->v[1] : 0.0;
  if ((rc = sl_flow_check_geometry(f->th, &f->prob.opts, d))) goto fail;
  f->datum = !f->bcs.has_natural;
  f->column_at_rest = dim == 1 && f->th->n_comp == 1 && f->bcs.n > 0;
  f->unforced = f->prob.opts.omega == 0.0;
  for (int c = 0; c < MAX_COMP; ++c) f->unforced &= f->ph.body_force[c] == 0.0 && !f->ph.force_expr[c];
  for (int i = 0; i < f->bcs.n; ++i) {
    int ty = f->bcs.b[i].type;
    f->column_at_rest &= ty == NS_WALL;
    f->unforced &= ty == NS_WALL || ty == NS_SLIP || ty == NS_AXIS || ty == NS_PERIODIC;
  }
  for (int i = 0; i < f->bcs.n; ++i) {
    int ty = f->bcs.b[i].type;
    f->bcs.b[i].frame = f->prob.opts.omega != 0.0 && f->prob.opts.centrifugal_density != 0.0 ? &f->prob.opts : NULL;
    if (ty == NS_PRESSURE || ty == NS_TRACTION || (ty == NS_OPEN && f->bcs.b[i].frame)) {
      if (f->prob.n_tractions == SL_FLOW_MAX_TRACTIONS) break;
      f->prob.traction[f->prob.n_tractions++] = (sl_flow_traction){f->bcs.b[i].name, traction_fn, &f->bcs.b[i]};
    }
  }
  if ((rc = bc_apply(&f->bcs, f->th, &f->prob.bc, 0.0, f->datum, d))) goto fail;
  if ((rc = sl_scene_linsolve_general(sc, f->th->n_dofs,
                                      "the flow's matrix couples velocity and pressure (a saddle point: symmetric "
                                      "indefinite without convection, nonsymmetric with it)",
                                      &f->ls, &f->linear, d)))
    goto fail;
  /* velocity, then pressure */
  if ((rc = sl_linsolve_set_blocks(f->ls, f->th->p_offset, sc->time.scheme != SL_SCHEME_STEADY, d))) goto fail;
  if ((rc = slip_setup(f, d))) goto fail;
  f->nopts = (sl_newton_opts){.rtol = sc->solver.nonlinear_tolerance,
                              .max_iterations = (int)sc->solver.max_iterations,
                              .picard_only = sc->solver.nonlinear == 1,
                              .picard_first = (int)sc->solver.picard_first,
                              .linear = !sc->flow.convection && !f->ph.visc,
                              .scale = 1e-12};
  f->u = calloc((size_t)f->th->n_dofs, sizeof *f->u);
  f->work = malloc((size_t)f->th->vel->n_nodes * 3 * sizeof *f->work);
  /* the cell diagnostics only when written */
  int cell_fields = (f->fields & (F_SHEAR | F_VISCOSITY | F_YIELDED)) != 0;
  if (cell_fields) f->cellbuf = malloc((size_t)f->mesh->n_cells * 3 * sizeof *f->cellbuf);
  if (!f->u || !f->work || (cell_fields && !f->cellbuf)) {
    rc = sl_diag_set(d, SL_ENOMEM, "out of memory for %d unknowns", (int)f->th->n_dofs);
    goto fail;
  }
  if ((rc = stream_setup(f, d))) goto fail;
  if (dim == 2) { /* the forces on the boundaries that ask for them ([boundary.NAME] force = true) */
    int any = 0;
    f->force_want = calloc((size_t)f->bcs.n + 1, 1);
    for (int i = 0; i < f->bcs.n && f->force_want; ++i)
      any |= f->force_want[i] =
          (f->bcs.b[i].type == NS_WALL || f->bcs.b[i].type == NS_VELOCITY) && f->bcs.b[i].in->force;
    f->force = calloc((size_t)f->th->n_comp * (f->bcs.n + 1), sizeof *f->force);
    f->force_work = malloc((size_t)f->th->n_vel + 1);
    if (!f->force_want || !f->force || !f->force_work) {
      rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
      goto fail;
    }
    if (!any)
      free(f->force_want), free(f->force), free(f->force_work), f->force_want = f->force_work = NULL, f->force = NULL;
  }
  if ((rc = check_body_force(sc, &f->ph, d))) goto fail;
  if ((rc = projection_setup(f, d))) goto fail;
  /* The split step solves the coupled system only to start (its first step, and the first after a skipped one):
     a factorisation or two a run and no refactorisations, where the solver for a matrix factorised once wins
     (sl_linsolve_default_name_once: spinup's start 0.27 s against 0.37 s) */
  if (f->pj && sc->solver.linear == 0 && strcmp(f->linear, "petsc") != 0 &&
      strcmp(f->linear, sl_linsolve_default_name_once(f->th->n_dofs)) != 0) {
    sl_linsolve_destroy(f->ls);
    f->ls = NULL;
    if ((rc = sl_scene_linsolve_once(sc, f->th->n_dofs, &f->ls, &f->linear, d))) goto fail;
    if ((rc = sl_linsolve_set_blocks(f->ls, f->th->p_offset, 1, d))) goto fail;
  }
  if ((rc = initial_velocity(sc, fc, f->th, f->u, d))) goto fail;
  velocity_scale(f);
  *info = (sl_model_info){.integrator = SL_INTEGRATE_BDF,
                          .n = f->th->n_dofs,
                          .n_err = f->th->p_offset,
                          .u = f->u,
                          .has_steady = 1,
                          .state_name = "velocity"};
  *out = f;
  return 0;
fail:
  sl_flow_destroy(f);
  return rc;
}

void sl_flow_destroy(sl_flow *f) {
  if (!f) return;
  free(f->u), free(f->work), free(f->cellbuf);
  free(f->q), free(f->psi), free(f->node_psi);
  free(f->force_want), free(f->force_work), free(f->force);
  sl_stream_graph_free(&f->pg);
  sl_face_flux_destroy(f->ff);
  sl_linsolve_destroy(f->ls);
  sl_projection_destroy(f->pj);
  sl_flow_problem_free(&f->prob);
  sl_slip_free(&f->slip);
  bc_set_free(&f->bcs);
  physics_free(&f->ph);
  sl_th_destroy(f->th);
  free(f);
}
