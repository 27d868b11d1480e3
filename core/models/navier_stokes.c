/* The navier_stokes model: scene set-up, steady solve with continuation,
 * adaptive BDF time loop, output, checkpoint and restart (see
 * navier_stokes.h). */
#include "core/models/navier_stokes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/config/expr.h"
#include "core/io/output.h"
#include "core/models/flow_problem.h"
#include "core/models/scene_mesh.h"
#include "core/models/scene_output.h"
#include "core/models/scene_solver.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/kinds.h"
#include "core/time/bdf.h"

static double wall(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- expressions: comma lists split at parenthesis depth 0 -------------- */

enum { MAX_COMP = 3 };
static const char *const expr_vars[] = {"x", "y", "t"};

typedef struct expr_vec {
  int n;
  sl_expr *e[MAX_COMP];
} expr_vec;

static void expr_vec_free(expr_vec *v) {
  for (int i = 0; i < v->n; ++i) sl_expr_free(v->e[i]);
  v->n = 0;
}

/* Compiles "a, b, c" from [section] key; a missing key gives n = 0. */
static int expr_vec_get(const sl_ini *ini, const char *section, const char *key, int max, int allow_t, expr_vec *v,
                        sl_diag *d) {
  memset(v, 0, sizeof *v);
  const char *text;
  int rc = sl_ini_get_string(ini, section, key, 0, "", &text, d);
  if (rc || !*text) return rc;
  const sl_ini_entry *e = sl_ini_find(ini, section, key);
  if ((rc = sl_expr_compile_list(text, expr_vars, allow_t ? 3 : 2, max, v->e, &v->n, d)))
    return sl_diag_prefix(d, rc, "%s:%d: [%s] %s", e->file, e->line, section, key);
  return 0;
}

static int expr_vec_uses_t(const expr_vec *v) {
  for (int i = 0; i < v->n; ++i)
    if (sl_expr_uses(v->e[i], 2)) return 1;
  return 0;
}

/* ---- physics: fluid properties, the viscosity closure, forces ------------ */

typedef struct physics {
  int n_comp, dim, axisymmetric;
  double density, viscosity;
  sl_closure *visc; /* NULL: Newtonian */
  int in_shear, in_other[8], n_other;
  double other_value[8];
  int out_visc, has_dmu;
  double yield_stress; /* for `yielded`; 0 when the law has none */
  double *buf;         /* closure inputs/outputs for one batch */
  int cap;
  double gravity[MAX_COMP], body_force[MAX_COMP];
  int has_force;
  const sl_ns_coupling *cpl; /* solids fraction: variable density, buoyancy, phi input; NULL: none */
  int in_phi, in_density;    /* viscosity inputs fed per point (-1: absent) */
} physics;

static void physics_free(physics *ph) {
  sl_closure_destroy(ph->visc);
  free(ph->buf);
  memset(ph, 0, sizeof *ph);
}

/* Viscosity through the closure, once per batch; mu and d mu / d gamma. */
static int viscosity_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  physics *ph = user;
  int n_in = ph->visc->desc->n_in, n_out = ph->visc->desc->n_out;
  int need = b->n * (n_in + n_out + n_in + 1);
  if (need > ph->cap) {
    double *nb = realloc(ph->buf, (size_t)need * sizeof *nb);
    if (!nb) return sl_diag_set(d, SL_EFAILED, "viscosity: out of memory");
    ph->buf = nb, ph->cap = need;
  }
  const double *in[16];
  double *outs[16], *dout[16 * 16];
  double *w = ph->buf;
  const double *phi = ph->cpl ? ph->cpl->cell_phi(ph->cpl->user) : NULL;
  for (int i = 0; i < n_in; ++i) {
    if (i == ph->in_shear) {
      in[i] = b->shear_rate;
      continue;
    }
    if (phi && (i == ph->in_phi || i == ph->in_density)) {
      for (int q = 0; q < b->n; ++q) {
        double f = phi[b->cell[q]];
        w[q] = i == ph->in_phi ? f : ph->density + f * (ph->cpl->rho_solid - ph->density);
      }
      in[i] = w, w += b->n;
      continue;
    }
    for (int k = 0; k < ph->n_other; ++k)
      if (ph->in_other[k] == i)
        for (int q = 0; q < b->n; ++q) w[q] = ph->other_value[k];
    in[i] = w, w += b->n;
  }
  for (int k = 0; k < n_out; ++k) outs[k] = w, w += b->n;
  for (int k = 0; k < n_out * n_in; ++k) dout[k] = NULL;
  if (ph->has_dmu) dout[ph->out_visc * n_in + ph->in_shear] = w, w += b->n;
  for (int i = 0; i < n_in; ++i) /* the ABI asks a slot for every differentiable input once one is asked */
    if (ph->has_dmu && i != ph->in_shear && (ph->visc->desc->in[i].flags & SL_FIELD_DIFF))
      dout[ph->out_visc * n_in + i] = w, w += b->n;
  sl_error err;
  sl_eval_args a = {.Q = b->n, .in = in, .out = outs, .dout = dout, .err = &err};
  int rc = sl_closure_evaluate(ph->visc, &a);
  if (rc) {
    char label[128];
    sl_closure_label(ph->visc->desc, label, sizeof label);
    int q = err.point >= 0 && err.point < b->n ? err.point : 0;
    char extra[64] = "";
    if (phi) snprintf(extra, sizeof extra, ", phi %g", phi[b->cell[q]]);
    return sl_diag_set(d, SL_EFAILED, "closure %s %s at (%g, %g) in cell %d (shear rate %g%s): %s", label,
                       rc > 0 ? "outside its validity" : "failed", b->x[q][0], b->x[q][1], (int)b->cell[q],
                       b->shear_rate[q], extra, err.msg);
  }
  const double *mu = outs[ph->out_visc], *dmu = ph->has_dmu ? dout[ph->out_visc * n_in + ph->in_shear] : NULL;
  for (int q = 0; q < b->n; ++q) out[2 * q] = mu[q], out[2 * q + 1] = dmu ? dmu[q] : 0.0;
  return 0;
}

/* Gravity and the body force. With a solids fraction only the excess
 * density (rho - rho_f) = phi (rho_s - rho_f) is buoyant: rho_f g goes into
 * the (reduced) pressure. */
static int force_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const physics *ph = user;
  (void)d;
  const double *phi = ph->cpl ? ph->cpl->cell_phi(ph->cpl->user) : NULL;
  for (int q = 0; q < b->n; ++q) {
    double rho = phi ? phi[b->cell[q]] * (ph->cpl->rho_solid - ph->density) : ph->density;
    for (int c = 0; c < ph->n_comp; ++c) out[q * ph->n_comp + c] = rho * ph->gravity[c] + ph->body_force[c];
  }
  return 0;
}

/* The mixture density rho_f + phi (rho_s - rho_f) (Nigam 1999 eq 2.1). */
static int density_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const physics *ph = user;
  (void)d;
  const double *phi = ph->cpl->cell_phi(ph->cpl->user);
  for (int q = 0; q < b->n; ++q) out[q] = ph->density + phi[b->cell[q]] * (ph->cpl->rho_solid - ph->density);
  return 0;
}

static int vec_get(const sl_ini *ini, const char *sec, const char *key, int n_comp, double *v, sl_diag *d) {
  double buf[MAX_COMP] = {0, 0, 0};
  int n = 0, rc = sl_ini_get_real_list(ini, sec, key, 0, buf, MAX_COMP, &n, d);
  if (rc) return rc;
  if (n > n_comp) {
    const sl_ini_entry *e = sl_ini_find(ini, sec, key);
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] %s: %d components given, the scene has %d velocity components",
                       e->file, e->line, sec, key, n, n_comp);
  }
  for (int c = 0; c < MAX_COMP; ++c) v[c] = c < n ? buf[c] : 0.0;
  return 0;
}

static int physics_setup(const sl_ini *ini, const sl_registry *reg, int n_comp, int dim, int axi,
                         const sl_ns_coupling *cpl, physics *ph, sl_diag *d) {
  memset(ph, 0, sizeof *ph);
  ph->n_comp = n_comp, ph->dim = dim, ph->axisymmetric = axi, ph->cpl = cpl;
  ph->in_phi = ph->in_density = -1;
  int rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, &ph->density, d);
  if (!rc) rc = sl_ini_get_real(ini, "fluid", "viscosity", 0, 1e-3, 1e-7, 1e7, &ph->viscosity, d);
  if (!rc) rc = vec_get(ini, "flow", "gravity", n_comp, ph->gravity, d);
  if (!rc) rc = vec_get(ini, "flow", "body_force", n_comp, ph->body_force, d);
  if (rc) return rc;
  for (int c = 0; c < MAX_COMP; ++c) ph->has_force |= ph->gravity[c] != 0.0 || ph->body_force[c] != 0.0;
  if (cpl && cpl->rho_solid == ph->density) { /* neutrally buoyant: gravity acts on nothing */
    ph->has_force = 0;
    for (int c = 0; c < MAX_COMP; ++c) ph->has_force |= ph->body_force[c] != 0.0;
  }
  if (!sl_ini_find_section(ini, "closure.viscosity")) return 0;
  if ((rc = sl_closure_from_ini(reg, ini, "closure.viscosity", &ph->visc, d))) return rc;
  const sl_closure_desc *c = ph->visc->desc;
  char label[128];
  sl_closure_label(c, label, sizeof label);
  ph->in_shear = sl_closure_input(c, "shear_rate");
  ph->out_visc = sl_closure_output(c, "viscosity");
  const sl_ini_section *sec = sl_ini_find_section(ini, "closure.viscosity");
  if (cpl) {
    ph->in_phi = sl_closure_input(c, "phi");
    ph->in_density = sl_closure_input(c, "density");
  }
  if (ph->out_visc < 0 || (ph->in_shear < 0 && ph->in_phi < 0 && ph->in_density < 0) || c->n_in > 16 ||
      c->n_out > 16)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.viscosity] %s does not map a shear rate%s to a viscosity",
                       sec->file, sec->line, label, cpl ? " or a solids fraction" : "");
  for (int i = 0; i < c->n_in; ++i) {
    if (i == ph->in_shear || i == ph->in_phi || i == ph->in_density) continue;
    const char *name = c->in[i].name;
    double v;
    if (strcmp(name, "mu_f") == 0) v = ph->viscosity;
    else if (strcmp(name, "rho_f") == 0 || (!cpl && strcmp(name, "density") == 0)) v = ph->density;
    else
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [closure.viscosity] %s needs the input '%s', which the %s model does not "
                         "provide (it provides shear_rate, mu_f, rho_f%s)",
                         sec->file, sec->line, label, name, cpl ? "mixture" : "navier_stokes",
                         cpl ? ", phi, density" : "");
    if (ph->n_other == 8) return sl_diag_set(d, SL_EBADINPUT, "%s: too many inputs", label);
    ph->in_other[ph->n_other] = i, ph->other_value[ph->n_other++] = v;
  }
  ph->has_dmu = ph->in_shear >= 0 && (c->in[ph->in_shear].flags & SL_FIELD_DIFF) != 0;
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
  o->density = ph->cpl && ph->cpl->rho_solid != ph->density ? (sl_coef){density_fn, ph, 0.0}
                                                               : (sl_coef){NULL, NULL, ph->density};
  o->viscosity = ph->visc ? viscosity_fn : NULL;
  o->viscosity_user = ph;
  o->viscosity_value = ph->viscosity;
  o->body_force = ph->has_force ? force_fn : NULL;
  o->body_force_user = ph;
  o->extra_stress = ph->cpl ? ph->cpl->extra_stress : NULL;
}

/* ---- boundary conditions ------------------------------------------------- */

typedef enum bc_type { BC_WALL, BC_VELOCITY, BC_SLIP, BC_AXIS, BC_OPEN, BC_PRESSURE, BC_TRACTION, BC_PERIODIC } bc_type;
static const char *const bc_types = "wall|velocity|slip|axis|open|pressure|traction|periodic";

typedef struct bc {
  const char *name; /* the mesh's boundary name */
  bc_type type;
  expr_vec velocity;
  int slip_comp;       /* the velocity component normal to a slip boundary */
  double traction[MAX_COMP]; /* traction; or -p n for pressure (p in traction[0]) */
  int n_comp;
} bc;

typedef struct bc_set {
  int n;
  bc *b;
  int time_dependent;
  int has_natural; /* an open, pressure or traction boundary: no pressure datum */
  int n_pairs;     /* periodic pairs (boundary, partner), each once */
  sl_periodic_pair *pairs;
} bc_set;

static void bc_set_free(bc_set *s) {
  for (int i = 0; i < s->n; ++i) expr_vec_free(&s->b[i].velocity);
  free(s->b);
  free(s->pairs);
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

static int bc_setup(const sl_ini *ini, const sl_mesh *m, int n_comp, int axi, int solids, bc_set *s, sl_diag *d) {
  memset(s, 0, sizeof *s);
  s->b = calloc((size_t)m->n_boundaries, sizeof *s->b);
  s->pairs = calloc((size_t)m->n_boundaries, sizeof *s->pairs);
  if (!s->b || !s->pairs) return sl_diag_set(d, SL_EFAILED, "out of memory");
  s->n = m->n_boundaries;
  for (int i = 0; i < s->n; ++i) s->b[i].name = m->boundary_names[i], s->b[i].type = BC_WALL;
  for (int k = 0; k < ini->n_sections; ++k) {
    const sl_ini_section *sec = &ini->sections[k];
    if (strncmp(sec->name, "boundary.", 9) != 0) continue;
    const char *name = sec->name + 9;
    int id, rc = sl_mesh_boundary_id(m, name, &id, d);
    if (rc) return sl_diag_prefix(d, rc, "%s:%d: [%s]", sec->file, sec->line, sec->name);
    static const char *const keys[] = {"type", "velocity", "pressure", "traction", "partner", "phi"};
    if ((rc = sl_ini_check_keys(ini, sec->name, keys, solids ? 6 : 5, d))) return rc;
    bc *b = &s->b[id];
    int type;
    if ((rc = sl_ini_get_choice(ini, sec->name, "type", 1, 0, bc_types, &type, d))) return rc;
    b->type = (bc_type)type, b->n_comp = n_comp;
    if (b->type == BC_VELOCITY) {
      if ((rc = expr_vec_get(ini, sec->name, "velocity", n_comp, 1, &b->velocity, d))) return rc;
      if (b->velocity.n == 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = velocity needs velocity = <%d expressions of x, y, t>",
                           sec->file, sec->line, sec->name, n_comp);
      s->time_dependent |= expr_vec_uses_t(&b->velocity);
    } else if (b->type == BC_SLIP) {
      if ((b->slip_comp = aligned_normal(m, id)) < 0)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s:%d: [%s] type = slip needs a straight boundary along x or y; '%s' is not (use a "
                           "velocity condition or realign the mesh)",
                           sec->file, sec->line, sec->name, name);
    } else if (b->type == BC_AXIS) {
      if (!axi || aligned_normal(m, id) != 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = axis needs an axisymmetric scene and a boundary at r = 0",
                           sec->file, sec->line, sec->name);
      for (int f = m->bface_start[id]; f < m->bface_start[id + 1]; ++f) {
        double c[2];
        sl_mesh_face_centroid(m, m->bface[f], c);
        if (fabs(c[0]) > 1e-12)
          return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = axis: the boundary lies at r = %g, not on the axis",
                             sec->file, sec->line, sec->name, c[0]);
      }
    } else if (b->type == BC_PRESSURE) {
      if ((rc = sl_ini_get_real(ini, sec->name, "pressure", 1, 0.0, -1e12, 1e12, &b->traction[0], d))) return rc;
      s->has_natural = 1;
    } else if (b->type == BC_TRACTION) {
      if ((rc = vec_get(ini, sec->name, "traction", n_comp, b->traction, d))) return rc;
      s->has_natural = 1;
    } else if (b->type == BC_OPEN) {
      s->has_natural = 1;
    } else if (b->type == BC_PERIODIC) {
      /* the partner is the same boundary translated: its dofs become this boundary's */
      const char *partner;
      int pid;
      if ((rc = sl_ini_get_string(ini, sec->name, "partner", 0, "", &partner, d))) return rc;
      if (!*partner) continue; /* the partner side of a pair named elsewhere: checked below */
      if ((rc = sl_mesh_boundary_id(m, partner, &pid, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] partner", sec->file, sec->line, sec->name);
      if (pid == id)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] partner: a boundary cannot be its own partner", sec->file,
                           sec->line, sec->name);
      sl_mesh_periodic pm;
      if ((rc = sl_mesh_periodic_match(m, name, partner, &pm, d)))
        return sl_diag_prefix(d, rc, "%s:%d: [%s] type = periodic", sec->file, sec->line, sec->name);
      double shift_r = pm.shift[0];
      sl_mesh_periodic_free(&pm);
      if (axi && fabs(shift_r) > 0.0)
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] type = periodic: an axisymmetric scene repeats along z only, "
                                            "and '%s' is '%s' moved by %g in r", sec->file, sec->line, sec->name,
                           partner, name, shift_r);
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
    char psec[300];
    snprintf(psec, sizeof psec, "boundary.%s", s->pairs[k].partner);
    if (sl_ini_find_section(ini, psec) && s->b[pid].type != BC_PERIODIC) {
      const sl_ini_section *ps = sl_ini_find_section(ini, psec);
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [%s] is the periodic partner of '%s' and cannot have another type",
                         ps->file, ps->line, psec, s->pairs[k].boundary);
    }
    s->b[pid].type = BC_PERIODIC;
  }
  for (int i = 0; i < s->n; ++i) {
    if (s->b[i].type != BC_PERIODIC) continue;
    int paired = 0;
    for (int k = 0; k < s->n_pairs; ++k)
      paired |= strcmp(s->pairs[k].boundary, s->b[i].name) == 0 || strcmp(s->pairs[k].partner, s->b[i].name) == 0;
    if (!paired)
      return sl_diag_set(d, SL_EBADINPUT, "[boundary.%s] type = periodic needs partner = <the matching boundary>",
                         s->b[i].name);
  }
  /* Unnamed boundaries of an axisymmetric mesh called "axis" are the axis. */
  for (int i = 0; i < s->n && axi; ++i)
    if (strcmp(s->b[i].name, "axis") == 0 && !sl_ini_find_section(ini, "boundary.axis")) s->b[i].type = BC_AXIS;
  return 0;
}

typedef struct bc_eval {
  const sl_expr *e;
  double t;
} bc_eval;

static void bc_value(void *user, const double x[2], double *v, double g[2]) {
  const bc_eval *b = user;
  double vals[3] = {x[0], x[1], b->t};
  *v = sl_expr_eval(b->e, vals);
  if (g) g[0] = g[1] = 0.0;
}

/* Fixes the Dirichlet dofs at time t: slip and axis first, then prescribed
 * velocities, then walls, so that walls win shared corners. */
static int bc_apply(const bc_set *s, const sl_th_space *th, sl_constraints *con, double t, int datum, sl_diag *d) {
  int rc = 0;
  for (int pass = 0; pass < 3 && !rc; ++pass)
    for (int i = 0; i < s->n && !rc; ++i) {
      const bc *b = &s->b[i];
      if (pass == 0 && b->type == BC_SLIP)
        rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, b->slip_comp, 0), NULL, NULL, 0.0, d);
      if (pass == 0 && b->type == BC_AXIS) {
        rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, 0, 0), NULL, NULL, 0.0, d);
        if (!rc && th->n_comp == 3)
          rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, 2, 0), NULL, NULL, 0.0, d);
      }
      if (pass == 1 && b->type == BC_VELOCITY)
        for (int c = 0; c < th->n_comp && !rc; ++c) {
          if (c >= b->velocity.n) {
            rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, c, 0), NULL, NULL, 0.0, d);
            continue;
          }
          bc_eval be = {b->velocity.e[c], t};
          rc = sl_constraints_fix_boundary(con, th->vel, b->name, sl_th_vel_dof(th, c, 0), bc_value, &be, 0.0, d);
        }
      if (pass == 2 && b->type == BC_WALL) /* periodic boundaries carry no condition */
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
      if (bc_->type == BC_PRESSURE) v = c < 2 ? -bc_->traction[0] * b->normal[q][c] : 0.0;
      else v = bc_->traction[c];
      out[q * bc_->n_comp + c] = v;
    }
  return 0;
}

/* ---- output ---------------------------------------------------------------- */

enum { F_VELOCITY = 1, F_PRESSURE = 2, F_SHEAR = 4, F_VISCOSITY = 8, F_YIELDED = 16, N_FLOW_FIELDS = 5 };
enum { MAX_FIELDS = 16 };
static const char *const field_names[N_FLOW_FIELDS] = {"velocity", "pressure", "shear_rate", "viscosity", "yielded"};

typedef struct ns_run {
  const sl_ini *ini;
  sl_mesh *mesh;
  sl_th_space *th;
  physics ph;
  bc_set bcs;
  sl_flow_problem prob;
  sl_linsolve *ls;
  sl_newton_opts nopts;
  sl_output *out;
  int fields;
  double *work; /* n_vel * 3 */
  double *cellbuf;
  sl_ns_result *res;
  int datum;
  const sl_ns_coupling *cpl; /* NULL: single-phase */
  unsigned cpl_fields;       /* the coupled model's fields to write (bit k: cpl->field_names[k]) */
  /* The residual's round-off (see solve): the largest initial residual of
   * the run, and whether a solve has already ended there. */
  double newton_scale[2];
  sl_bdf_controller ctl; /* the adaptive step's controller (core/time/bdf.h) */
} ns_run;

static int write_state(ns_run *r, double t, const double *u, sl_diag *d) {
  double t0 = wall(), c0 = cpu();
  const sl_th_space *th = r->th;
  int rc = sl_output_begin_step(r->out, t, d);
  if (!rc && (r->fields & F_VELOCITY)) {
    /* in the frame: in-plane components, then the out-of-plane/swirl one as component 2 */
    memset(r->work, 0, (size_t)th->vel->n_nodes * 3 * sizeof *r->work);
    for (int32_t i = 0; i < th->vel->n_nodes; ++i)
      for (int c = 0; c < th->n_comp; ++c)
        r->work[3 * i + (c < th->mesh->dim ? c : 2)] = u[sl_th_vel_dof(th, c, th->vel->node_dof[i])];
    rc = sl_output_write_field(r->out, "velocity", SL_CENTRE_NODE, 3, r->work, d);
  }
  if (!rc && (r->fields & F_PRESSURE)) {
    /* P1 pressure at every velocity node: the vertices carry their values,
     * the other nodes the average of their cell's vertices (exact for the
     * linear pressure on edge midpoints and the Q1 cell centre). */
    const double *p = u + th->p_offset;
    double mean = 0.0, area = 0.0;
    if (r->datum && sl_fe_integrate(th->pres, p, r->ph.axisymmetric, &mean, &area, NULL) == 0 && area > 0.0)
      mean /= area;
    else
      mean = 0.0;
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
          int f = k - nvc;
          v = 0.5 * (p[pn[cv[f]]] + p[pn[cv[(f + 1) % nvc]]]);
        }
        r->work[vd[k]] = v - mean;
      }
    }
    rc = sl_output_write_field(r->out, "pressure", SL_CENTRE_NODE, 1, r->work, d);
  }
  if (!rc && (r->fields & (F_SHEAR | F_VISCOSITY | F_YIELDED))) {
    int nc = th->mesh->n_cells;
    double *g = r->cellbuf, *mu = g + nc, *y = mu + nc;
    rc = sl_flow_cell_diagnostics(th, u, &r->prob.opts, r->ph.yield_stress, g, mu, y, d);
    if (!rc && (r->fields & F_SHEAR)) rc = sl_output_write_field(r->out, "shear_rate", SL_CENTRE_CELL, 1, g, d);
    if (!rc && (r->fields & F_VISCOSITY)) rc = sl_output_write_field(r->out, "viscosity", SL_CENTRE_CELL, 1, mu, d);
    if (!rc && (r->fields & F_YIELDED)) rc = sl_output_write_field(r->out, "yielded", SL_CENTRE_CELL, 1, y, d);
  }
  if (!rc && r->cpl) rc = r->cpl->write(r->cpl->user, r->out, d);
  if (!rc) rc = sl_output_end_step(r->out, d);
  r->res->output += wall() - t0;
  r->res->cpu_output += cpu() - c0;
  return rc;
}

/* The state to restart from: the BDF history (a steady run passes a
 * history of its one solution). */
static int write_checkpoint(ns_run *r, const sl_bdf *b, double t, double dt_next, long step, sl_diag *d) {
  double t0 = wall(), c0 = cpu();
  sl_checkpoint_array arr[16];
  int na = 0;
  const char *names[3] = {"u", "u_prev", "u_prev2"};
  for (int k = 0; k < b->n_past; ++k) {
    snprintf(arr[na].name, sizeof arr[na].name, "%s", names[k]);
    arr[na].n = b->n, arr[na].data = b->past[k];
    ++na;
  }
  snprintf(arr[na].name, sizeof arr[na].name, "h_past");
  arr[na].n = 2, arr[na].data = b->h_past, ++na;
  snprintf(arr[na].name, sizeof arr[na].name, "newton_scale"); /* a restart tests convergence as the run did */
  arr[na].n = 2, arr[na].data = r->newton_scale, ++na;
  double ctl[SL_BDF_CONTROLLER_STATE]; /* and controls its steps as the run did */
  sl_bdf_controller_save(&r->ctl, ctl);
  snprintf(arr[na].name, sizeof arr[na].name, "step_control");
  arr[na].n = SL_BDF_CONTROLLER_STATE, arr[na].data = ctl, ++na;
  /* a restart starts with a fresh factorisation: so does the run that goes on, bit for bit the same */
  sl_linsolve_drop_numeric(r->ls);
  if (r->cpl) na += r->cpl->checkpoint(r->cpl->user, arr + na, 16 - na);
  sl_checkpoint ck = {.time = t, .dt = dt_next, .step = step, .n_arrays = na, .arrays = arr};
  ck.n_ints = 2;
  snprintf(ck.int_names[0], SL_CHECKPOINT_NAME_MAX, "n_past");
  ck.ints[0] = b->n_past;
  snprintf(ck.int_names[1], SL_CHECKPOINT_NAME_MAX, "rejected");
  ck.ints[1] = r->res->rejected_steps;
  int rc = sl_output_write_checkpoint(r->out, &ck, d);
  r->res->output += wall() - t0;
  r->res->cpu_output += cpu() - c0;
  return rc;
}

/* [output] fields: the flow's, then the coupled model's. By default the
 * velocity, the pressure, the viscosity closure's diagnostics when there is
 * one, and every field of the coupled model. */
static int output_fields(ns_run *r, sl_diag *d) {
  const char *names[MAX_FIELDS];
  int n = 0, n_cpl = r->cpl ? r->cpl->n_fields : 0;
  if (N_FLOW_FIELDS + n_cpl > MAX_FIELDS)
    return sl_diag_set(d, SL_EFAILED, "output: more than %d field names", MAX_FIELDS);
  for (int k = 0; k < N_FLOW_FIELDS; ++k) names[n++] = field_names[k];
  for (int k = 0; k < n_cpl; ++k) names[n++] = r->cpl->field_names[k];
  unsigned def = F_VELOCITY | F_PRESSURE | (r->ph.visc ? F_SHEAR | F_VISCOSITY | F_YIELDED : 0);
  def |= ((1u << n_cpl) - 1u) << N_FLOW_FIELDS;
  unsigned mask;
  int rc = sl_scene_output_fields(r->ini, names, n, def, &mask, d);
  if (rc) return rc;
  r->fields = (int)(mask & ((1u << N_FLOW_FIELDS) - 1u));
  r->cpl_fields = mask >> N_FLOW_FIELDS;
  return 0;
}

static int open_output(ns_run *r, const sl_ns_run_opts *o, sl_diag *d) {
  int rc = sl_scene_output_path(r->ini, o->output, o->scene_path, r->res->output_path, sizeof r->res->output_path, d);
  if (rc) return rc;
  if ((rc = sl_output_open(&r->out, r->res->output_path, d))) return rc;
  const sl_th_space *th = r->th;
  static const char *const topo[] = {[SL_CELL_LINE2] = "Edge_3", [SL_CELL_TRI3] = "Triangle_6",
                                     [SL_CELL_QUAD4] = "Quadrilateral_9"};
  /* the geometric nodes: periodic boundaries keep both sides in the file */
  const double *coords = th->vel->node_xy;
  if (th->mesh->dim == 1) { /* the writer takes n x dim coordinates */
    for (int32_t i = 0; i < th->vel->n_nodes; ++i) r->work[i] = th->vel->node_xy[2 * i];
    coords = r->work;
  }
  rc = sl_output_write_mesh(r->out, th->mesh->dim, th->vel->n_nodes, coords, th->mesh->n_cells,
                            th->vel->dofs_per_cell, th->vel->cell_nodes, topo[th->mesh->cell_type], d);
  if (rc) return rc;
  /* provenance */
  char *ini_text = sl_ini_to_string(r->ini);
  sl_provenance_closure pc[8] = {{0}};
  char params[2048] = "", cparams[4096] = "";
  sl_provenance pv = {.sluice_version = o->sluice_version ? o->sluice_version : "unknown", .ini_text = ini_text};
  if (r->ph.visc) {
    const sl_closure_desc *c = r->ph.visc->desc;
    size_t at = 0;
    for (int k = 0; k < c->n_params && at < sizeof params; ++k) {
      char v[64];
      sl_params_format_value(c, r->ph.visc->params, k, v, sizeof v);
      at += (size_t)snprintf(params + at, sizeof params - at, "%s = %s\n", c->params[k].name, v);
    }
    pc[pv.n_closures++] = (sl_provenance_closure){"closure.viscosity", sl_kind_name(c->kind), c->name, c->version,
                                                  r->ph.visc->library->path, params};
  }
  if (r->cpl) pv.n_closures += r->cpl->provenance(r->cpl->user, pc + pv.n_closures, 8 - pv.n_closures, cparams, sizeof cparams);
  pv.closures = pc;
  rc = sl_output_write_provenance(r->out, &pv, d);
  free(ini_text);
  return rc;
}

/* ---- solves ---------------------------------------------------------------- */

/* A residual this far below the largest initial residual of the run (its
 * forcing: the lid, the buoyancy) is at round-off. A flow nearly at rest
 * under a large load that the pressure carries (a suspension close to
 * packing) gets there in one iteration, and then no relative test can pass:
 * the corrections are noise and the predictor's residual, the reference of
 * the relative residual test, is already tiny. Such a solve is converged.
 * Ordinary solves pass their own tests first and are not touched; once one
 * has ended at round-off, the later ones stop there (atol). */
#define NEWTON_ROUNDOFF 1e-13

static int solve(ns_run *r, double *u, int *iterations, sl_diag *d) {
  sl_newton_stats st;
  double c0 = cpu();
  double *scale = &r->newton_scale[0], *engaged = &r->newton_scale[1];
  r->nopts.atol = *engaged ? NEWTON_ROUNDOFF * *scale : 0.0;
  int rc = sl_flow_problem_solve(&r->prob, u, r->ls, &r->nopts, &st, d);
  if (isfinite(st.residual0) && st.residual0 > *scale) *scale = st.residual0;
  if (rc == SL_EFAILED && st.iterations > 0 && isfinite(st.residual) && st.residual <= NEWTON_ROUNDOFF * *scale) {
    rc = 0; /* u is the last iterate, whose residual st.residual is */
    *engaged = 1.0;
    r->res->roundoff_accepted++;
  } else if (rc == 0 && r->nopts.atol > 0.0 && st.residual <= r->nopts.atol) {
    r->res->roundoff_accepted++;
  }
  if (iterations) *iterations = st.iterations;
  r->res->correction = st.correction;
  r->res->residual0 = st.residual0, r->res->residual = st.residual;
  r->res->nonlinear_iterations += st.iterations;
  r->res->matrix_assemblies += st.assemblies, r->res->residual_assemblies += st.residuals;
  r->res->assembly += st.t_assembly;
  if (st.picard_iterations) r->res->used_picard = 1;
  r->res->cpu_flow += cpu() - c0;
  return rc;
}

/* Rebuilds the physics after an INI change (continuation). */
static int rebuild_physics(ns_run *r, const sl_registry *reg, sl_diag *d) {
  physics_free(&r->ph);
  int rc = physics_setup(r->ini, reg, r->th->n_comp, r->mesh->dim, r->prob.opts.axisymmetric, r->cpl, &r->ph, d);
  if (rc) return rc;
  int convection = r->prob.opts.convection;
  double omega = r->prob.opts.omega, c0 = r->prob.opts.rotation_centre[0], c1 = r->prob.opts.rotation_centre[1];
  physics_opts(&r->ph, &r->prob.opts);
  r->prob.opts.convection = convection, r->prob.opts.omega = omega;
  r->prob.opts.rotation_centre[0] = c0, r->prob.opts.rotation_centre[1] = c1;
  return 0;
}

static int steady(ns_run *r, sl_ini *ini, const sl_registry *reg, double *u, sl_diag *d) {
  const char *key;
  int rc = sl_ini_get_string(ini, "solver", "continuation", 0, "", &key, d);
  if (rc) return rc;
  if (!*key) {
    int its = 0;
    rc = solve(r, u, &its, d);
    r->res->steps = 1;
    if (rc) return sl_diag_prefix(d, rc, "steady solve");
    r->res->converged = 1;
    if (r->nopts.linear)
      snprintf(r->res->stop_reason, sizeof r->res->stop_reason,
               "steady state solved: a linear problem, one solve (residual %.2g)", r->res->residual);
    else
      snprintf(r->res->stop_reason, sizeof r->res->stop_reason,
               "steady state converged in %d Newton iteration%s (last relative correction %.2g, tolerance %g; "
               "residual %.2g from %.2g)",
               its, its == 1 ? "" : "s", r->res->correction, r->nopts.rtol, r->res->residual, r->res->residual0);
    return 0;
  }
  /* continuation: section.key from continuation_from to its scene value */
  const sl_ini_entry *ce = sl_ini_find(ini, "solver", "continuation");
  char sec[256];
  const char *dot = strrchr(key, '.');
  if (!dot || dot == key || (size_t)(dot - key) >= sizeof sec)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [solver] continuation = %s: expected section.key", ce->file,
                       ce->line, key);
  snprintf(sec, sizeof sec, "%.*s", (int)(dot - key), key);
  char name[128];
  snprintf(name, sizeof name, "%s", dot + 1);
  double target, from;
  long steps;
  if (!sl_ini_find(ini, sec, name))
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [solver] continuation = %s: the scene sets no [%s] %s", ce->file,
                       ce->line, key, sec, name);
  if ((rc = sl_ini_get_real(ini, sec, name, 1, 0, -HUGE_VAL, HUGE_VAL, &target, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "solver", "continuation_from", 1, 0, -HUGE_VAL, HUGE_VAL, &from, d))) return rc;
  if ((rc = sl_ini_get_int(ini, "solver", "continuation_steps", 0, 5, 1, 1000, &steps, d))) return rc;
  int geometric = from > 0 && target > 0;
  for (long k = 0; k <= steps && !rc; ++k) {
    double s = (double)k / (double)steps;
    double v = geometric ? from * pow(target / from, s) : from + (target - from) * s;
    if (k == steps) v = target;
    char assign[512];
    snprintf(assign, sizeof assign, "%s=%.17g", key, v);
    if ((rc = sl_ini_apply_override(ini, assign, d))) break;
    if ((rc = rebuild_physics(r, reg, d))) break;
    int its = 0;
    rc = solve(r, u, &its, d);
    if (rc) rc = sl_diag_prefix(d, rc, "continuation stage %ld of %ld (%s = %g)", k, steps, key, v);
    r->res->steps++;
    if (!rc && k == steps) {
      r->res->converged = 1;
      snprintf(r->res->stop_reason, sizeof r->res->stop_reason,
               "steady state converged at %s = %g, the last of %ld continuation stages, in %d Newton iteration%s "
               "(last relative correction %.2g, tolerance %g; residual %.2g from %.2g)",
               key, v, steps + 1, its, its == 1 ? "" : "s", r->res->correction, r->nopts.rtol, r->res->residual,
               r->res->residual0);
    }
  }
  return rc;
}

/* ---- the time loop ---------------------------------------------------------- */

typedef struct time_cfg {
  int scheme; /* 0 steady, 1 bdf1, 2 bdf2 */
  double end, dt, tol, dt_min, dt_max, every;
  int adaptive;
  long max_steps;
} time_cfg;

static int time_config(const sl_ini *ini, time_cfg *tc, sl_diag *d) {
  memset(tc, 0, sizeof *tc);
  int rc = sl_ini_get_choice(ini, "time", "scheme", 0, 2, "steady|bdf1|bdf2", &tc->scheme, d);
  if (rc) return rc;
  if (!sl_ini_find_section(ini, "time")) tc->scheme = 0;
  if (tc->scheme == 0) return 0;
  if ((rc = sl_ini_get_real(ini, "time", "end", 1, 0, 0, 1e12, &tc->end, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "time", "dt", 1, 0, 1e-15, 1e9, &tc->dt, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "time", "tolerance", 0, 1e-3, 1e-14, 1, &tc->tol, d))) return rc;
  if ((rc = sl_ini_get_bool(ini, "time", "adaptive", 0, 1, &tc->adaptive, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "time", "dt_min", 0, tc->dt * 1e-6, 0, 1e9, &tc->dt_min, d))) return rc;
  /* A fixed step is what was asked for; an adaptive one is capped at a tenth of the run by default. */
  double dt_max = tc->adaptive && tc->end > 0 ? tc->end / 10 : tc->dt;
  if ((rc = sl_ini_get_real(ini, "time", "dt_max", 0, dt_max, 1e-15, 1e12, &tc->dt_max, d))) return rc;
  if ((rc = sl_ini_get_int(ini, "time", "max_steps", 0, 100000000L, 1, 100000000L, &tc->max_steps, d))) return rc;
  if ((rc = sl_ini_get_real(ini, "output", "every", 0, 0.0, 0.0, 1e12, &tc->every, d))) return rc;
  return 0;
}

int sl_ns_time_span(const sl_ini *ini, double *t0, double *t1, sl_diag *d) {
  time_cfg tc;
  int rc = time_config(ini, &tc, d);
  *t0 = 0.0, *t1 = tc.scheme ? tc.end : 0.0;
  return rc;
}

static const char *const limits[] = {"error estimate", "nonlinear convergence", "dt_max",
                                     "end or output time", "fixed dt",            "solids transport"};
enum { N_LIMITS = 6 };

static int transient(ns_run *r, const time_cfg *tc, const sl_ns_run_opts *o, double *u, const sl_checkpoint *ck,
                     sl_diag *d) {
  sl_bdf b;
  int32_t n = r->th->n_dofs;
  int rc = sl_bdf_init(&b, tc->scheme, n, u, 0.0, d);
  if (rc) return rc;
  sl_bdf_controller_init(&r->ctl, SL_BDF_CONTROL_H211PI);
  double *hist = malloc((size_t)n * sizeof *hist), *pred = malloc((size_t)n * sizeof *pred);
  double *trial = malloc((size_t)n * sizeof *trial), *rate = malloc((size_t)n * sizeof *rate);
  if (!hist || !pred || !trial || !rate) {
    rc = sl_diag_set(d, SL_EFAILED, "out of memory");
    goto out;
  }
  double h = tc->dt;
  long step = 0;
  int next_out = 1;
  if (ck) {
    /* restore the history exactly */
    const char *names[3] = {"u", "u_prev", "u_prev2"};
    long np = ck->n_ints > 0 ? (long)ck->ints[0] : 1;
    for (int k = 0; k < np && k < 3; ++k) {
      const sl_checkpoint_array *a = sl_checkpoint_find(ck, names[k]);
      if (!a || a->n != n) {
        rc = sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint's '%s' has %lld values, the scene %d unknowns",
                         names[k], a ? (long long)a->n : 0LL, (int)n);
        goto out;
      }
      memcpy(b.past[k], a->data, (size_t)n * sizeof(double));
    }
    const sl_checkpoint_array *hp = sl_checkpoint_find(ck, "h_past");
    if (hp && hp->n == 2) b.h_past[0] = hp->data[0], b.h_past[1] = hp->data[1];
    const sl_checkpoint_array *ns = sl_checkpoint_find(ck, "newton_scale");
    if (ns && ns->n == 2) r->newton_scale[0] = ns->data[0], r->newton_scale[1] = ns->data[1];
    const sl_checkpoint_array *sc = sl_checkpoint_find(ck, "step_control");
    if (sc && sc->n == SL_BDF_CONTROLLER_STATE) sl_bdf_controller_restore(&r->ctl, sc->data);
    b.n_past = (int)np, b.t = ck->time;
    h = ck->dt, step = (long)ck->step;
    if (ck->n_ints > 1) r->res->rejected_steps = (long)ck->ints[1];
    memcpy(u, b.past[0], (size_t)n * sizeof *u);
    if (tc->every > 0) next_out = (int)floor(b.t / tc->every + 1e-9) + 1;
  } else if ((rc = write_state(r, 0.0, u, d)) || (rc = write_checkpoint(r, &b, 0.0, h, 0, d))) {
    goto out;
  }
  r->res->t_start = b.t;
  long limit_count[N_LIMITS] = {0};
  const double eps_t = 1e-12 * fmax(1.0, tc->end);
  long steps_here = 0;
  while (b.t < tc->end - eps_t) {
    if (o->interrupt && *o->interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "interrupted at t = %.6g after %ld steps", b.t, step);
      break;
    }
    if (steps_here >= tc->max_steps) break;
    int limit = tc->adaptive ? 0 : 4;
    double hh = h;
    /* land on the end and on every output time (a step within 5 % of one is stretched to it) */
    double t_stop = tc->end;
    if (tc->every > 0 && next_out * tc->every < t_stop) t_stop = next_out * tc->every;
    /* a step that ends there up to round-off keeps its length, so that a constant-coefficient matrix stays
       bitwise the same and is not factorised again */
    if (fabs(b.t + hh - t_stop) > eps_t && (b.t + hh > t_stop || b.t + 1.05 * hh > t_stop))
      hh = t_stop - b.t, limit = 3;
    sl_bdf_step s;
    sl_bdf_prepare(&b, hh, &s, hist, pred);
    r->prob.opts.mass_coef = s.mass_coef;
    r->prob.opts.history = hist;
    if (r->bcs.time_dependent && (rc = bc_apply(&r->bcs, r->th, &r->prob.bc, b.t + hh, r->datum, d))) break;
    memcpy(trial, pred, (size_t)n * sizeof *trial);
    sl_diag dn;
    int its = 0, nrc = solve(r, trial, &its, &dn);
    double err = 0.0;
    if (nrc == 0 && tc->adaptive) err = sl_bdf_error(&s, trial, pred, r->th->p_offset, tc->tol, 1e-12);
    int coupled_failed = 0;
    if (nrc == 0 && err <= 1.0 && r->cpl) {
      for (int32_t i = 0; i < n; ++i) rate[i] = s.mass_coef * trial[i] + hist[i]; /* the BDF du/dt at t + hh */
      double c0 = cpu();
      coupled_failed = (nrc = r->cpl->advance(r->cpl->user, b.t, hh, trial, rate, &dn)) != 0;
      r->res->cpu_coupled += cpu() - c0;
    }
    if (nrc != 0 || err > 1.0) {
      r->res->rejected_steps++;
      h = nrc ? sl_bdf_controller_fail(&r->ctl, &s) : sl_bdf_controller_reject(&r->ctl, &s, err);
      limit_count[coupled_failed ? 5 : nrc ? 1 : 0]++;
      if (nrc && nrc != SL_EFAILED) {
        rc = sl_diag_set(d, nrc, "%s", dn.msg);
        break;
      }
      if (h < tc->dt_min) {
        double umax = 0.0; /* a velocity growing without bound shows here */
        for (int32_t i = 0; i < r->th->p_offset; ++i) umax = fmax(umax, fabs(b.past[0][i]));
        rc = sl_diag_set(d, SL_EFAILED,
                         "step rejected at t = %.6g down to dt = %.3g < dt_min = %.3g: %s (largest velocity of the last "
                         "accepted step %.3g)",
                         b.t, h, tc->dt_min, nrc ? dn.msg : "the error estimate stays above the tolerance", umax);
        break;
      }
      continue;
    }
    sl_bdf_accept(&b, &s, trial);
    if (r->cpl) r->cpl->accept(r->cpl->user);
    ++step, ++steps_here;
    double h_next = tc->adaptive ? sl_bdf_controller_accept(&r->ctl, &s, err) : tc->dt;
    if (h_next > tc->dt_max) h_next = tc->dt_max, limit = 2;
    if (limit != 3) h = h_next; /* a step shortened to hit the end keeps the proposal */
    limit_count[limit]++;
    if (o->monitor) o->monitor(o->monitor_user, b.t, hh, step, its);
    int due = tc->every > 0 ? b.t >= next_out * tc->every - eps_t : 0;
    int last = b.t >= tc->end - eps_t || steps_here >= tc->max_steps;
    if (due || last) {
      while (tc->every > 0 && b.t >= next_out * tc->every - eps_t) ++next_out;
      if ((rc = write_state(r, b.t, b.past[0], d)) || (rc = write_checkpoint(r, &b, b.t, h, step, d))) break;
    }
  }
  r->res->steps = step;
  r->res->t_reached = b.t;
  if (!rc && b.t >= tc->end - eps_t)
    snprintf(r->res->stop_reason, sizeof r->res->stop_reason, "reached the end time t = %g", tc->end);
  else if (!rc)
    snprintf(r->res->stop_reason, sizeof r->res->stop_reason,
             "stopped after max_steps = %ld steps at t = %.6g, before the end time %g (checkpoint saved)",
             tc->max_steps, b.t, tc->end);
  long best = 0;
  for (int k = 0; k < N_LIMITS; ++k)
    if (limit_count[k] > best) best = limit_count[k], r->res->step_limit = limits[k];
  if (rc == SL_EFAILED) {
    /* keep the last good state */
    sl_diag d2;
    if (write_state(r, b.t, b.past[0], &d2) == 0) write_checkpoint(r, &b, b.t, h, step, &d2);
  }
out:
  free(hist), free(pred), free(trial), free(rate);
  sl_bdf_free(&b);
  return rc;
}

/* ---- set-up and teardown ---------------------------------------------------- */

static int initial_velocity(const sl_ini *ini, const sl_th_space *th, double *u, sl_diag *d) {
  expr_vec v;
  int rc = expr_vec_get(ini, "initial", "velocity", th->n_comp, 0, &v, d);
  if (rc) return rc;
  for (int c = 0; c < v.n; ++c) {
    bc_eval be = {v.e[c], 0.0};
    sl_fe_interpolate(th->vel, bc_value, &be, u + sl_th_vel_dof(th, c, 0));
  }
  expr_vec_free(&v);
  return 0;
}

int sl_ns_run(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res, sl_diag *d) {
  memset(res, 0, sizeof *res);
  double c_setup = cpu();
  ns_run r = {.ini = ini, .res = res, .cpl = o->coupling};
  double *u = NULL;
  sl_checkpoint ck = {0};
  int have_ck = 0;
  int geometry, third = 0, convection = 1, nonlinear = 0, picard_first = 0;
  long max_it;
  double tol, omega = 0.0, centre[2] = {0, 0};
  time_cfg tc;
  const char *linear;
  int rc = sl_ini_get_choice(ini, "scene", "geometry", 0, 1, "line|planar|axisymmetric", &geometry, d);
  if (!rc) rc = sl_ini_get_bool(ini, "flow", "third_component", 0, 0, &third, d);
  if (!rc) rc = sl_ini_get_bool(ini, "flow", "convection", 0, 1, &convection, d);
  if (!rc) rc = sl_ini_get_real(ini, "flow", "rotation", 0, 0.0, -1e6, 1e6, &omega, d);
  if (!rc) {
    int k = 0;
    rc = sl_ini_get_real_list(ini, "flow", "rotation_centre", 0, centre, 2, &k, d);
  }
  if (!rc) rc = sl_ini_get_string(ini, "solver", "linear", 0, "umfpack", &linear, d);
  if (!rc) rc = sl_ini_get_choice(ini, "solver", "nonlinear", 0, 0, "newton|picard", &nonlinear, d);
  if (!rc) rc = sl_ini_get_real(ini, "solver", "nonlinear_tolerance", 0, 1e-8, 1e-16, 1.0, &tol, d);
  if (!rc) rc = sl_ini_get_int(ini, "solver", "max_iterations", 0, 30, 1, 1000, &max_it, d);
  if (!rc) {
    long pf = 0;
    rc = sl_ini_get_int(ini, "solver", "picard_first", 0, 0, 0, 1000, &pf, d);
    picard_first = (int)pf;
  }
  if (!rc) rc = time_config(ini, &tc, d);
  if (!rc) rc = sl_scene_mesh(ini, &r.mesh, d);
  if (rc) goto out;
  int dim = r.mesh->dim, axi = geometry == 2;
  if ((geometry == 0) != (dim == 1)) {
    rc = sl_diag_set(d, SL_EBADINPUT, "[scene] geometry = %s but the mesh is %d-D",
                     geometry == 0 ? "line" : geometry == 1 ? "planar" : "axisymmetric", dim);
    goto out;
  }
  if ((rc = bc_setup(ini, r.mesh, dim + (third ? 1 : 0), axi, r.cpl != NULL, &r.bcs, d))) goto out;
  if ((rc = sl_th_create_periodic(r.mesh, dim + (third ? 1 : 0), r.bcs.pairs, r.bcs.n_pairs, &r.th, d))) goto out;
  if ((rc = physics_setup(ini, reg, r.th->n_comp, dim, axi, r.cpl, &r.ph, d))) goto out;
  if ((rc = sl_flow_problem_init(&r.prob, r.th, d))) goto out;
  physics_opts(&r.ph, &r.prob.opts);
  r.prob.opts.convection = convection;
  r.prob.opts.omega = omega;
  r.prob.opts.rotation_centre[0] = centre[0], r.prob.opts.rotation_centre[1] = centre[1];
  if ((rc = sl_flow_check_geometry(r.th, &r.prob.opts, d))) goto out;
  if ((rc = output_fields(&r, d))) goto out;
  if (r.cpl) {
    if (tc.scheme == 0) {
      rc = sl_diag_set(d, SL_EBADINPUT, "[time] scheme = steady: the mixture model is transient (bdf1 or bdf2)");
      goto out;
    }
    /* bcs.b[i] is the mesh's boundary i */
    unsigned char *open = calloc((size_t)r.bcs.n + 1, 1);
    if (!open) {
      rc = sl_diag_set(d, SL_EFAILED, "out of memory");
      goto out;
    }
    for (int i = 0; i < r.bcs.n; ++i) {
      bc_type ty = r.bcs.b[i].type;
      open[i] = ty == BC_OPEN || ty == BC_PRESSURE || ty == BC_TRACTION;
    }
    rc = r.cpl->setup(r.cpl->user, r.th, &r.prob.opts, open, r.bcs.pairs, r.bcs.n_pairs, r.cpl_fields, d);
    free(open);
    if (rc) goto out;
    r.prob.opts.extra_stress = r.cpl->extra_stress; /* allocated by the set-up */
  }
  r.datum = !r.bcs.has_natural;
  for (int i = 0; i < r.bcs.n; ++i)
    if (r.bcs.b[i].type == BC_PRESSURE || r.bcs.b[i].type == BC_TRACTION) {
      if (r.prob.n_tractions == SL_FLOW_MAX_TRACTIONS) break;
      r.prob.traction[r.prob.n_tractions++] = (sl_flow_traction){r.bcs.b[i].name, traction_fn, &r.bcs.b[i]};
    }
  if ((rc = bc_apply(&r.bcs, r.th, &r.prob.bc, 0.0, r.datum, d))) goto out;
  if ((rc = sl_scene_linsolve(ini, sl_linsolve_default_name(r.th->n_dofs), NULL, &r.ls, &linear, d))) goto out;
  r.nopts = (sl_newton_opts){.rtol = tol,
                             .max_iterations = (int)max_it,
                             .picard_only = nonlinear == 1,
                             .picard_first = picard_first,
                             .linear = !convection && !r.ph.visc,
                             .scale = 1e-12,
                             .rtol_residual = 1e-10};
  u = calloc((size_t)r.th->n_dofs, sizeof *u);
  r.work = malloc((size_t)r.th->vel->n_nodes * 3 * sizeof *r.work);
  /* the cell diagnostics only when written */
  int cell_fields = (r.fields & (F_SHEAR | F_VISCOSITY | F_YIELDED)) != 0;
  if (cell_fields) r.cellbuf = malloc((size_t)r.mesh->n_cells * 3 * sizeof *r.cellbuf);
  if (!u || !r.work || (cell_fields && !r.cellbuf)) {
    rc = sl_diag_set(d, SL_EFAILED, "out of memory for %d unknowns", (int)r.th->n_dofs);
    goto out;
  }
  if ((rc = initial_velocity(ini, r.th, u, d))) goto out;
  if (o->restart) {
    if ((rc = sl_checkpoint_read(o->restart, &ck, d))) goto out;
    have_ck = 1;
    if (tc.scheme == 0) {
      const sl_checkpoint_array *a = sl_checkpoint_find(&ck, "u");
      if (!a || a->n != r.th->n_dofs) {
        rc = sl_diag_set(d, SL_EBADINPUT, "restart: %s holds no state of %d unknowns", o->restart, (int)r.th->n_dofs);
        goto out;
      }
      memcpy(u, a->data, (size_t)a->n * sizeof *u); /* a steady solve starts from it */
    }
    if (r.cpl && (rc = r.cpl->restore(r.cpl->user, &ck, d))) goto out;
  }
  if ((rc = open_output(&r, o, d))) goto out;
  res->cpu_setup = cpu() - c_setup;
  if (tc.scheme == 0) {
    rc = steady(&r, ini, reg, u, d);
    sl_diag d2;
    int wrc = write_state(&r, 0.0, u, rc ? &d2 : d);
    sl_bdf one;
    if (!wrc && !(wrc = sl_bdf_init(&one, 1, r.th->n_dofs, u, 0.0, rc ? &d2 : d))) {
      wrc = write_checkpoint(&r, &one, 0.0, 0.0, res->steps, rc ? &d2 : d);
      sl_bdf_free(&one);
    }
    if (!rc) rc = wrc;
  } else {
    rc = transient(&r, &tc, o, u, have_ck ? &ck : NULL, d);
  }
  res->t_end = tc.end;
out:
  if (r.ls) {
    const sl_linsolve_stats *st = sl_linsolve_get_stats(r.ls);
    res->linear = *st;
    res->factorisation = st->t_symbolic + st->t_numeric, res->solve = st->t_solve;
    sl_linsolve_summary(r.ls, res->linear_summary, sizeof res->linear_summary);
  }
  if (r.out) {
    sl_output_stats(r.out, &res->output_times, &res->output_datasets, &res->output_bytes);
    sl_diag d2;
    int crc = sl_output_close(r.out, rc ? &d2 : d);
    if (!rc) rc = crc;
  }
  if (have_ck) sl_checkpoint_free(&ck);
  free(u), free(r.work), free(r.cellbuf);
  sl_linsolve_destroy(r.ls);
  sl_flow_problem_free(&r.prob);
  bc_set_free(&r.bcs);
  physics_free(&r.ph);
  sl_th_destroy(r.th);
  sl_mesh_destroy(r.mesh);
  return rc;
}
