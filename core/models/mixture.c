/* The mixture model: the solids fraction coupled to the flow (see
 * mixture.h). */
#include "core/models/mixture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/hydrostatic.h"
#include "core/config/expr.h"
#include "core/fe/field.h"
#include "core/models/face_flux.h"
#include "core/models/stream_function.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"
#include "core/transport/migration.h"
#include "core/transport/transport.h"

enum { MAX_LEVELS = 8, MAX_IN = 32 };

/* A closure evaluated in batch with some inputs varying (per point) and the
 * others fixed by the scene; one output and its derivatives. */
typedef struct bound_closure {
  sl_closure *c;
  double fixed[MAX_IN];
  double *buf;
  int cap;
} bound_closure;

/* Evaluates output `out` at n points; var[i] != NULL supplies input i per
 * point, the others take fixed[i]. dvar (may be NULL) gets d out / d input
 * `wrt`. */
static int bound_eval(bound_closure *b, int n, const double *const *var, int out, double *value, int wrt, double *dvar,
                      sl_diag *d) {
  const sl_closure_desc *c = b->c->desc;
  int n_in = c->n_in, n_out = c->n_out;
  int need = n * (2 * n_in + n_out);
  if (need > b->cap) {
    double *nb = realloc(b->buf, (size_t)need * sizeof *nb);
    if (!nb) return sl_diag_set(d, SL_EFAILED, "closure %s: out of memory", c->name);
    b->buf = nb, b->cap = need;
  }
  const double *in[MAX_IN];
  double *outs[MAX_IN] = {0}, *dout[MAX_IN * MAX_IN] = {0}, *w = b->buf;
  for (int i = 0; i < n_in; ++i) {
    if (var[i]) {
      in[i] = var[i];
      continue;
    }
    for (int k = 0; k < n; ++k) w[k] = b->fixed[i];
    in[i] = w, w += n;
  }
  for (int k = 0; k < n_out; ++k)
    if (k == out || !(c->out[k].flags & SL_FIELD_OPTIONAL)) outs[k] = w, w += n;
  if (dvar)
    for (int i = 0; i < n_in; ++i) /* a slot for every differentiable input of the asked output (ABI) */
      if (c->in[i].flags & SL_FIELD_DIFF) dout[out * n_in + i] = w, w += n;
  sl_error err;
  sl_eval_args a = {.Q = n, .in = in, .out = outs, .dout = dout, .err = &err};
  int rc = sl_closure_evaluate(b->c, &a);
  if (rc) {
    char label[128], where[64] = "";
    sl_closure_label(c, label, sizeof label);
    for (int i = 0; i < n_in; ++i)
      if (var[i] && err.point >= 0 && err.point < n) {
        snprintf(where, sizeof where, " at %s = %g", c->in[i].name, var[i][err.point]);
        break;
      }
    return sl_diag_set(d, SL_EFAILED, "closure %s %s%s: %s", label, rc > 0 ? "is outside its validity" : "failed", where,
                       err.msg);
  }
  memcpy(value, outs[out], (size_t)n * sizeof *value);
  if (dvar) memcpy(dvar, dout[out * n_in + wrt], (size_t)n * sizeof *dvar);
  return 0;
}

/* The hindered-settling closure as the transport's batch callback: phi
 * varies, every other input is fixed by the scene. */
typedef struct settling {
  bound_closure b; /* b.c NULL: no settling */
  int in_phi, out_u;
} settling;

typedef struct mixture {
  const sl_ini *ini;
  const sl_registry *reg;
  sl_ns_coupling cpl;
  const sl_th_space *th;
  const sl_mesh *m;
  int axi;
  double rho_f, mu_f, phi_max;
  double g[2], g_ref, omega, centre[2];
  settling st;
  int slip_acceleration; /* [mixture]: the slip follows g - Dj/Dt */
  double *acc;           /* [2 n_cells] Dj/Dt (+ Coriolis) at the cell points (zero before the first step) */
  int relative_flux_stress; /* [mixture]: the momentum carries -div(rho_f j_R j_R / (phi (1 - phi))) */
  double *cell_stress;      /* [3 n_cells] its entries 00, 11, 01 per cell of the trial state */
  double *settle_speed;     /* [n_cells] u_settle(phi) of the cells (scratch) */
  double *node_stress;      /* [6 pressure dofs] of the current state: the flow's extra stress */
  double *node_weight;      /* [pressure dofs] 1 / the cell volume around the node */
  double *b_face;        /* [2 n_faces] the body-force direction per face */
  double *cell_drag, *grad_phi; /* [4 n_cells], [2 n_cells]: the buoyancy's response to the step's velocity */
  sl_hydrostatic *hs;           /* the layers whose hydrostatic part of the buoyancy the pressure carries, or NULL */
  double *buoy_phi, *p_hydro;   /* [n_cells] phi less that part, [pressure dofs] its pressure */
  int periodic_along_g;         /* a periodic pair repeats along gravity */
  int unchanged;                /* the last accepted step left phi bitwise as it was */
  int no_load;                  /* the remainder of the hydrostatic split is at round-off: the flow is not loaded */
  sl_transport_opts topts;
  sl_transport *tr;
  sl_face_flux *ff;
  double *phi, *trial, *q, *w; /* cells, cells, faces, faces */
  double *q_acc;               /* [n_faces] the conservative fluxes of the last accepted step */
  double *psi, *node_psi;      /* [n_vertices], [velocity nodes]: the stream function (2-D) */
  sl_stream_graph pg;
  unsigned fields; /* bit k: field_names[k] is written */
  double inventory0, inflow, trial_inflow;
  double inventory; /* of the current state: the summary needs it after the mesh is gone */
  double book[2]; /* inventory0 and inflow as checkpointed */
  long substeps, fallbacks, trial_substeps, trial_fallbacks, advances;
  double max_raw_div, trial_raw_div, max_div;
  double flux_floor; /* the settling flux scale max |w_f| max |F|: the divergence is measured against it too */
  double area_max;   /* the largest face area */
  int n_levels;
  double level[MAX_LEVELS];
  /* shear-induced migration (optional) */
  const sl_flow_opts *flow;
  bound_closure mig, visc; /* [closure.migration]; [closure.viscosity] as mu(phi) */
  int mig_phi, mig_shear, mig_dc, mig_dmu, visc_phi, visc_out;
  sl_migration *mg;
  double *shear;           /* [n_cells] */
  char params[2048];
} mixture;

/* ---- the settling closure ------------------------------------------------- */

static int settling_fn(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  settling *s = user;
  if (!s->b.c) {
    for (int i = 0; i < n; ++i) u[i] = du[i] = 0.0;
    return 0;
  }
  const double *var[MAX_IN] = {0};
  var[s->in_phi] = phi;
  int rc = bound_eval(&s->b, n, var, s->out_u, u, s->in_phi, du, d);
  return rc ? sl_diag_prefix(d, SL_EBADINPUT, "settling flux") : 0;
}

/* Binds the closure's inputs to the scene: phi varies; d_p, sphericity,
 * rho_s from [solid]; rho_f, mu_f from [fluid]; gravity is g_ref; d_vessel
 * infinite (no wall term) unless [solid] vessel_diameter. */
static int settling_setup(mixture *x, sl_diag *d) {
  settling *s = &x->st;
  const sl_ini *ini = x->ini;
  if (!sl_ini_find_section(ini, "closure.hindered_settling")) return 0;
  int rc = sl_closure_from_ini(x->reg, ini, "closure.hindered_settling", &s->b.c, d);
  if (rc) return rc;
  const sl_closure_desc *c = s->b.c->desc;
  const sl_ini_section *sec = sl_ini_find_section(ini, "closure.hindered_settling");
  char label[128];
  sl_closure_label(c, label, sizeof label);
  s->in_phi = sl_closure_input(c, "phi");
  s->out_u = sl_closure_output(c, "settling_velocity");
  if (s->in_phi < 0 || s->out_u < 0 || c->n_in > MAX_IN || c->n_out > MAX_IN)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.hindered_settling] %s does not map phi to a settling_velocity",
                       sec->file, sec->line, label);
  for (int i = 0; i < c->n_in; ++i) {
    const char *name = c->in[i].name;
    double v = 0.0;
    if (i == s->in_phi) continue;
    if (strcmp(name, "d_p") == 0) rc = sl_ini_get_real(ini, "solid", "diameter", 1, 0, 1e-9, 1.0, &v, d);
    else if (strcmp(name, "sphericity") == 0) rc = sl_ini_get_real(ini, "solid", "sphericity", 0, 1.0, 0.01, 1.0, &v, d);
    else if (strcmp(name, "rho_s") == 0) v = x->cpl.rho_solid;
    else if (strcmp(name, "rho_f") == 0) v = x->rho_f;
    else if (strcmp(name, "mu_f") == 0) v = x->mu_f;
    else if (strcmp(name, "gravity") == 0) v = x->g_ref;
    else if (strcmp(name, "d_vessel") == 0) v = HUGE_VAL;
    else
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [closure.hindered_settling] %s needs the input '%s', which the mixture model does not "
                         "provide (it provides phi, d_p, sphericity, rho_s, rho_f, mu_f, gravity, d_vessel)",
                         sec->file, sec->line, label, name);
    if (rc) return sl_diag_prefix(d, rc, "[closure.hindered_settling] %s needs %s", label, name);
    s->b.fixed[i] = v;
  }
  /* phi_max: the closure's packing parameter unless the scene sets [solid] phi_max; both must agree */
  int k = sl_params_find(c, "phi_max");
  const sl_ini_entry *pe = sl_ini_find(ini, "solid", "phi_max");
  if (k >= 0) {
    char buf[64];
    double cv;
    sl_params_format_value(c, s->b.c->params, k, buf, sizeof buf);
    sl_parse_real(buf, &cv);
    if (!pe) x->phi_max = cv;
    else if (fabs(cv - x->phi_max) > 1e-12)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [solid] phi_max = %g but [closure.hindered_settling] %s packs at phi_max = %g: "
                         "set one value (or drop [solid] phi_max)",
                         pe->file, pe->line, x->phi_max, label, cv);
  }
  return 0;
}

/* ---- the body force direction --------------------------------------------- */

/* b = (g + centrifugal) / g_ref at x: the frame's rotation about the axis
 * (axisymmetric: omega^2 r e_r) or about rotation_centre (planar). */
static void body_direction(void *user, const double x[2], double b[2]) {
  const mixture *mx = user;
  double w2 = mx->omega * mx->omega;
  b[0] = mx->g[0], b[1] = mx->g[1];
  if (mx->axi) b[0] += w2 * x[0];
  else if (w2 > 0.0) b[0] += w2 * (x[0] - mx->centre[0]), b[1] += w2 * (x[1] - mx->centre[1]);
  b[0] /= mx->g_ref, b[1] /= mx->g_ref;
}

/* Nigam (1999) eq 2.25 (rotating frame: eq 3.4): the slip is driven by
 * the effective acceleration f - Dj/Dt - 2 Omega x j, so j's acceleration
 * a = dj/dt + (j.grad) j + 2 Omega x j is evaluated at every cell point
 * (axisymmetric: with the centripetal -u_theta^2 / r of the swirl), and a
 * face takes the mean of its cells (its one cell on the boundary). */
static void cell_accelerations(mixture *x, const double *u, const double *dudt) {
  const sl_th_space *th = x->th;
  const sl_mesh *m = x->m;
  const double *xc = sl_transport_cell_points(x->tr);
  double xi[2] = {0.0, 0.0};
  if (m->cell_type == SL_CELL_TRI3) xi[0] = xi[1] = 1.0 / 3.0;
  int dim = m->dim, swirl = x->axi && th->n_comp == 3;
  for (int c = 0; c < m->n_cells; ++c) {
    double v[3] = {0, 0, 0}, g[2][2] = {{0, 0}, {0, 0}}, a[2] = {0, 0}, rate;
    for (int i = 0; i < th->n_comp; ++i) sl_fe_eval(th->vel, u + (size_t)i * th->n_vel, c, xi, &v[i], i < dim ? g[i] : NULL);
    for (int i = 0; i < dim; ++i) {
      sl_fe_eval(th->vel, dudt + (size_t)i * th->n_vel, c, xi, &rate, NULL);
      a[i] = rate + v[0] * g[i][0] + (dim > 1 ? v[1] * g[i][1] : 0.0);
    }
    if (swirl) a[0] -= v[2] * v[2] / xc[2 * c] + 2.0 * x->omega * v[2];
    else if (dim == 2 && !x->axi) a[0] -= 2.0 * x->omega * v[1], a[1] += 2.0 * x->omega * v[0];
    x->acc[2 * c] = a[0], x->acc[2 * c + 1] = a[1];
  }
  for (int f = 0; f < m->n_faces; ++f) {
    const int *fc = m->face_cells + 2 * f;
    double b[2];
    body_direction(x, sl_transport_face_points(x->tr) + 2 * f, b);
    for (int i = 0; i < 2; ++i) {
      double af = fc[1] >= 0 ? 0.5 * (x->acc[2 * fc[0] + i] + x->acc[2 * fc[1] + i]) : x->acc[2 * fc[0] + i];
      x->b_face[2 * f + i] = b[i] - af / x->g_ref;
    }
  }
}

/* The buoyancy over a step, implicit in the velocity j that moves phi: the
 * flow sees (rho_s - rho_f) phi(t + dt) b with phi(t + dt) ~ phi - dt j.grad
 * phi (div j = 0; b the body acceleration, gravity and the frame's
 * centrifugal one), i.e. the force of phi less K j, K = dt (rho_s - rho_f)
 * b grad(phi)^T per cell (the least-squares gradient). With the buoyancy of
 * phi(t) alone the coupling is explicit: internal waves of a stable
 * stratification, frequency N = (|b| (rho_s - rho_f) |grad phi| / rho)^(1/2),
 * then grow by a factor of about (N dt)^2 a step once N dt > 2 (symplectic
 * Euler), from round-off up to several times the settling speed (an
 * upright box, 4 x 50 cells, dt = 10 s: 1e-14 m/s to 9e-6 m/s in 10 steps
 * with settling off). Implicit, they are damped for every dt (backward
 * Euler), as in semi-implicit treatments of internal gravity waves. */
static int prepare(void *user, double dt, sl_diag *d) {
  mixture *x = user;
  (void)d;
  const double *xc = sl_transport_cell_points(x->tr);
  double drho = x->cpl.rho_solid - x->rho_f;
  sl_transport_gradient(x->tr, x->phi, x->grad_phi);
  for (int c = 0; c < x->m->n_cells; ++c) {
    double b[2], *K = x->cell_drag + 4 * (size_t)c, *g = x->grad_phi + 2 * c;
    body_direction(x, xc + 2 * c, b);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) K[2 * i + j] = dt * drho * x->g_ref * b[i] * g[j];
  }
  return 0;
}

/* The buoyancy less its hydrostatic part (core/assembly/hydrostatic.h), for
 * the current phi: the flow's load, and the pressure added to its output. */
static void hydrostatic_update(mixture *x) {
  if (!x->hs) return;
  const sl_dofmap *pm = x->th->pres;
  sl_hydrostatic_split(x->hs, x->phi, x->buoy_phi);
  sl_hydrostatic_pressure(x->hs, pm->n_dofs, pm->xy, x->p_hydro);
  double drho = x->cpl.rho_solid - x->rho_f;
  for (int32_t i = 0; i < pm->n_dofs; ++i) x->p_hydro[i] *= drho;
  /* a remainder within 1e-12 of the largest phi drives nothing beyond round-off */
  double rmax = 0.0, pmax = 0.0;
  for (int c = 0; c < x->m->n_cells; ++c) rmax = fmax(rmax, fabs(x->buoy_phi[c])), pmax = fmax(pmax, x->phi[c]);
  x->no_load = !x->relative_flux_stress && rmax <= 1e-12 * pmax;
}

static int at_rest(void *user) { return ((const mixture *)user)->no_load; }

/* The hydrostatic split where dropping the layers' buoyancy moves nothing:
 * a layered mesh, walls and periodic pairs across gravity only (an open
 * boundary would need the dropped pressure in its traction). */
static int hydrostatic_setup(mixture *x, const unsigned char *open, sl_diag *d) {
  if (x->cpl.rho_solid == x->rho_f || x->periodic_along_g) return 0;
  for (int b = 0; open && b < x->m->n_boundaries; ++b)
    if (open[b]) return 0;
  int rc = sl_hydrostatic_create(x->m, x->g, sl_transport_volumes(x->tr), sl_transport_cell_points(x->tr), &x->hs, d);
  if (rc || !x->hs) return rc;
  x->buoy_phi = malloc((size_t)x->m->n_cells * sizeof *x->buoy_phi);
  x->p_hydro = malloc((size_t)x->th->pres->n_dofs * sizeof *x->p_hydro);
  if (!x->buoy_phi || !x->p_hydro) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  x->cpl.buoyant_phi = x->buoy_phi, x->cpl.pressure_shift = x->p_hydro;
  hydrostatic_update(x);
  return 0;
}

/* The settling flux scale max |w_f| max |F| of the current settling field. */
static void set_flux_floor(mixture *x) {
  double wmax = 0.0;
  for (int f = 0; f < x->m->n_faces; ++f) wmax = fmax(wmax, fabs(x->w[f]));
  x->flux_floor = wmax * sl_transport_table(x->tr)->F_absmax;
}

/* ---- the stress of the relative motion -------------------------------------- */

/* Nigam (1999) eq 2.16 (in 2.19 and 2.31): the mixture momentum carries
 * -div[rho_f j_R j_R / (phi (1 - phi))] (dimensional; digest of seed 002,
 * sections 1.3 and 1.6), the momentum flux of the two phases' motion
 * relative to the volume-averaged j. With the settling flux j_R = phi
 * u_settle(phi) b of the transport (b the slip direction relative to
 * g_ref at the cell point: the body force, minus Dj/Dt with
 * slip_acceleration, as of the step that gave phi), per cell
 *
 *   T = rho_f phi u_settle(phi)^2 / (1 - phi) b b   (= rho_f phi (1 - phi) v_R v_R, v_R = u_settle b / (1 - phi)),
 *
 * finite at phi = 0, zero at phi_max where u_settle vanishes (and taken as
 * zero at phi = 1). The migration and diffusion fluxes are not part of it.
 * Entries 00, 11, 01 per cell into cell_stress. */
static int stress_of(mixture *x, const double *phi_cells, sl_diag *d) {
  int nc = x->m->n_cells;
  const double *var[MAX_IN] = {0};
  var[x->st.in_phi] = phi_cells;
  int rc = bound_eval(&x->st.b, nc, var, x->st.out_u, x->settle_speed, 0, NULL, d);
  if (rc) return sl_diag_prefix(d, rc, "relative-flux stress");
  const double *xc = sl_transport_cell_points(x->tr);
  for (int c = 0; c < nc; ++c) {
    double b[2], phi = phi_cells[c], us = x->settle_speed[c];
    body_direction(x, xc + 2 * c, b);
    if (x->slip_acceleration) b[0] -= x->acc[2 * c] / x->g_ref, b[1] -= x->acc[2 * c + 1] / x->g_ref;
    double tau = phi < 1.0 ? x->rho_f * phi * us * us / (1.0 - phi) : 0.0;
    double *T = x->cell_stress + 3 * (size_t)c;
    T[0] = tau * b[0] * b[0], T[1] = tau * b[1] * b[1], T[2] = tau * b[0] * b[1];
  }
  return 0;
}

/* The flow takes the stress in its pressure space (continuous, order 1;
 * sl_flow_opts extra_stress): at each pressure node the volume-weighted mean
 * of cell_stress over the cells around it. Continuous, the stress of a
 * column at rest is then balanced by the pressure alone, as the buoyancy of
 * the cells' phi is; cell values would put point loads on the faces, which a
 * continuous pressure cannot balance (the velocity would oscillate about
 * every jump of phi). */
static void node_stress_of(mixture *x) {
  const sl_dofmap *pm = x->th->pres;
  const double *vol = sl_transport_volumes(x->tr);
  int np = pm->dofs_per_cell;
  memset(x->node_stress, 0, (size_t)6 * pm->n_dofs * sizeof *x->node_stress);
  for (int c = 0; c < x->m->n_cells; ++c)
    for (int k = 0; k < np; ++k) {
      double *T = x->node_stress + 6 * (size_t)pm->cell_dofs[(size_t)c * np + k];
      const double *Tc = x->cell_stress + 3 * (size_t)c;
      T[0] += vol[c] * Tc[0], T[1] += vol[c] * Tc[1], T[3] += vol[c] * Tc[2];
    }
  for (int32_t i = 0; i < pm->n_dofs; ++i)
    for (int e = 0; e < 6; ++e) x->node_stress[6 * (size_t)i + e] *= x->node_weight[i];
}

/* The node weights of node_stress_of (1 / the volume around each pressure
 * node), the buffers, and the stress of the initial state. */
static int stress_setup(mixture *x, sl_diag *d) {
  if (!x->st.b.c)
    return sl_diag_set(d, SL_EBADINPUT, "[mixture] relative_flux_stress = true needs the relative flux of a "
                                        "[closure.hindered_settling]; the scene has none");
  const sl_dofmap *pm = x->th->pres;
  int nc = x->m->n_cells, np = pm->dofs_per_cell;
  x->cell_stress = malloc((size_t)3 * nc * sizeof *x->cell_stress);
  x->settle_speed = malloc((size_t)nc * sizeof *x->settle_speed);
  x->node_stress = malloc((size_t)6 * pm->n_dofs * sizeof *x->node_stress);
  x->node_weight = calloc((size_t)pm->n_dofs, sizeof *x->node_weight);
  if (!x->cell_stress || !x->settle_speed || !x->node_stress || !x->node_weight)
    return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  const double *vol = sl_transport_volumes(x->tr);
  for (int c = 0; c < nc; ++c)
    for (int k = 0; k < np; ++k) x->node_weight[pm->cell_dofs[(size_t)c * np + k]] += vol[c];
  for (int32_t i = 0; i < pm->n_dofs; ++i) x->node_weight[i] = x->node_weight[i] > 0.0 ? 1.0 / x->node_weight[i] : 0.0;
  int rc = stress_of(x, x->phi, d);
  if (rc) return rc;
  node_stress_of(x);
  x->cpl.extra_stress = x->node_stress;
  return 0;
}

/* ---- diagnostics -------------------------------------------------------------- */

/* The height (along -g) where the slab-averaged phi first reaches `level`
 * coming down from the top: the mixture/clear-fluid interface of a settling
 * column (slabs are the cells in 1-D, sqrt(n_cells) bands of equal height
 * in 2-D), linear between slab centres. When the top slab is already at the
 * level the mixture fills the column: its top (the highest vertex). NAN
 * when phi stays below the level everywhere. */
static double interface_height(const mixture *x, const double *phi, double level) {
  const double *xc = sl_transport_cell_points(x->tr), *vol = sl_transport_volumes(x->tr);
  double gn = hypot(x->g[0], x->g[1]), up[2] = {-x->g[0] / gn, -x->g[1] / gn};
  int nc = x->m->n_cells, nb = x->m->dim == 1 ? nc : (int)ceil(sqrt((double)nc));
  double hmin = INFINITY, hmax = -INFINITY;
  for (int c = 0; c < nc; ++c) {
    double h = up[0] * xc[2 * c] + up[1] * xc[2 * c + 1];
    hmin = fmin(hmin, h), hmax = fmax(hmax, h);
  }
  double *sv = calloc((size_t)nb * 3, sizeof *sv);
  if (!sv) return NAN;
  double *sp = sv + nb, *sh = sp + nb, width = (hmax - hmin) / nb;
  for (int c = 0; c < nc; ++c) {
    double h = up[0] * xc[2 * c] + up[1] * xc[2 * c + 1];
    int k = width > 0.0 ? (int)((h - hmin) / width) : 0;
    k = k < 0 ? 0 : k >= nb ? nb - 1 : k;
    sv[k] += vol[c], sp[k] += vol[c] * phi[c], sh[k] += vol[c] * h;
  }
  double result = NAN, h_above = NAN, p_above = NAN;
  for (int k = nb - 1; k >= 0; --k) {
    if (sv[k] <= 0.0) continue;
    double p = sp[k] / sv[k], h = sh[k] / sv[k];
    if (p >= level) {
      if (isnan(p_above)) {
        result = -INFINITY;
        for (int v = 0; v < x->m->n_vertices; ++v)
          result = fmax(result, up[0] * x->m->xy[2 * v] + up[1] * x->m->xy[2 * v + 1]);
      } else {
        result = h + (h_above - h) * (p - level) / (p - p_above);
      }
      break;
    }
    h_above = h, p_above = p;
  }
  free(sv);
  return result;
}

/* ---- the coupling hooks ----------------------------------------------------- */

/* ---- shear-induced migration ------------------------------------------------- */

static int migration_coef(void *user, int n, const double *phi, const double *g, double *D_c, double *D_mu, sl_diag *d) {
  mixture *x = user;
  const double *var[MAX_IN] = {0};
  var[x->mig_phi] = phi, var[x->mig_shear] = g;
  int rc = bound_eval(&x->mig, n, var, x->mig_dc, D_c, 0, NULL, d);
  if (!rc) rc = bound_eval(&x->mig, n, var, x->mig_dmu, D_mu, 0, NULL, d);
  return rc;
}

static int migration_lnmu(void *user, int n, const double *phi, double *ln_mu, double *dln_mu, sl_diag *d) {
  mixture *x = user;
  const double *var[MAX_IN] = {0};
  var[x->visc_phi] = phi;
  int rc = bound_eval(&x->visc, n, var, x->visc_out, ln_mu, x->visc_phi, dln_mu, d);
  for (int i = 0; i < n && !rc; ++i) dln_mu[i] /= ln_mu[i], ln_mu[i] = log(ln_mu[i]);
  return rc;
}

/* The gradient fluxes (migration, diffusion) as the transport's extra flux. */
static int create_gradient_flux(mixture *x, const sl_migration_opts *mo, sl_diag *d) {
  int rc = sl_migration_create(x->tr, mo, &x->mg, d);
  return rc ? rc : sl_transport_set_extra_flux(x->tr, sl_migration_flux, x->mg, d);
}

/* [closure.migration] (Phillips et al. 1992) with [closure.viscosity] as
 * mu(phi) for its viscosity-gradient part, and [mixture] diffusivity, the
 * particle diffusivity of a pseudo-continuum (Lalli 1993, eq 0.2). */
static int migration_setup(mixture *x, sl_diag *d) {
  const sl_ini *ini = x->ini;
  const sl_ini_section *sec = sl_ini_find_section(ini, "closure.migration");
  double eps = 0.0;
  int rc = sl_ini_get_real(ini, "mixture", "diffusivity", 0, 0.0, 0.0, 1e6, &eps, d);
  if (rc) return rc;
  sl_migration_opts mo = {.diffusivity = eps};
  if (!sec) return eps > 0.0 ? create_gradient_flux(x, &mo, d) : 0;
  if ((rc = sl_closure_from_ini(x->reg, ini, "closure.migration", &x->mig.c, d))) return rc;
  const sl_closure_desc *c = x->mig.c->desc;
  char label[128];
  sl_closure_label(c, label, sizeof label);
  x->mig_phi = sl_closure_input(c, "phi"), x->mig_shear = sl_closure_input(c, "shear_rate");
  x->mig_dc = sl_closure_output(c, "D_c"), x->mig_dmu = sl_closure_output(c, "D_mu");
  if (x->mig_phi < 0 || x->mig_shear < 0 || x->mig_dc < 0 || x->mig_dmu < 0 || c->n_in > MAX_IN || c->n_out > MAX_IN)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.migration] %s does not give D_c and D_mu of phi and shear_rate",
                       sec->file, sec->line, label);
  for (int i = 0; i < c->n_in; ++i) {
    if (i == x->mig_phi || i == x->mig_shear) continue;
    if (strcmp(c->in[i].name, "d_p") != 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.migration] %s needs the input '%s', which the mixture model "
                                          "does not provide (it provides phi, shear_rate, d_p)",
                         sec->file, sec->line, label, c->in[i].name);
    if ((rc = sl_ini_get_real(ini, "solid", "diameter", 1, 0, 1e-9, 1.0, &x->mig.fixed[i], d))) return rc;
  }
  mo.coef = migration_coef, mo.coef_user = x;
  const sl_ini_section *vs = sl_ini_find_section(ini, "closure.viscosity");
  if (vs) {
    if ((rc = sl_closure_from_ini(x->reg, ini, "closure.viscosity", &x->visc.c, d))) return rc;
    const sl_closure_desc *v = x->visc.c->desc;
    sl_closure_label(v, label, sizeof label);
    x->visc_phi = sl_closure_input(v, "phi"), x->visc_out = sl_closure_output(v, "viscosity");
    if (x->visc_phi < 0 || x->visc_out < 0 || !(v->in[x->visc_phi].flags & SL_FIELD_DIFF) || v->n_in > MAX_IN)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.migration] needs [closure.viscosity] as a viscosity of phi; "
                                          "%s is not", vs->file, vs->line, label);
    for (int i = 0; i < v->n_in; ++i) {
      if (i == x->visc_phi) continue;
      const char *name = v->in[i].name;
      if (strcmp(name, "mu_f") == 0) x->visc.fixed[i] = x->mu_f;
      else if (strcmp(name, "rho_f") == 0) x->visc.fixed[i] = x->rho_f;
      else
        return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [closure.migration] takes mu(phi) from [closure.viscosity], but %s "
                                            "also depends on '%s'", vs->file, vs->line, label, name);
    }
    mo.ln_mu = migration_lnmu, mo.ln_mu_user = x;
  }
  x->shear = calloc((size_t)x->m->n_cells, sizeof *x->shear);
  if (!x->shear) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  return create_gradient_flux(x, &mo, d);
}

static const double *cell_phi(void *user) { return ((mixture *)user)->phi; }

static int initial_phi(mixture *x, sl_diag *d) {
  const sl_ini_entry *e = sl_ini_find(x->ini, "initial", "phi");
  if (!e) return sl_diag_set(d, SL_EBADINPUT, "[initial] phi: the mixture model needs the initial solids fraction");
  static const char *const vars[] = {"x", "y"};
  sl_expr *ex;
  int rc = sl_expr_compile(e->value, vars, 2, &ex, d);
  if (rc) return sl_diag_prefix(d, rc, "%s:%d: [initial] phi", e->file, e->line);
  const double *xc = sl_transport_cell_points(x->tr);
  for (int c = 0; c < x->m->n_cells && !rc; ++c) {
    double v = sl_expr_eval(ex, xc + 2 * c);
    if (!(v >= 0.0 && v <= x->phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] phi = %g at (%g, %g): allowed 0 <= phi <= phi_max = %g",
                       e->file, e->line, v, xc[2 * c], xc[2 * c + 1], x->phi_max);
    x->phi[c] = v;
  }
  sl_expr_free(ex);
  return rc;
}

/* Open boundaries let solids in with [boundary.N] phi (default 0). */
static int transport_boundaries(mixture *x, const unsigned char *open, sl_diag *d) {
  for (int b = 0; b < x->m->n_boundaries; ++b) {
    if (!open || !open[b]) continue;
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", x->m->boundary_names[b]);
    double v;
    int rc = sl_ini_get_real(x->ini, sec, "phi", 0, 0.0, 0.0, x->phi_max, &v, d);
    if (!rc) rc = sl_transport_set_boundary(x->tr, b, SL_TRANSPORT_OPEN, v, d);
    if (rc) return rc;
  }
  return 0;
}

/* Periodic pairs: the transport pairs the faces itself; the face fluxes get
 * the same pairs from the mesh's match. */
static int periodic_setup(mixture *x, const unsigned char *open, const sl_periodic_pair *pairs, int n_pairs,
                          sl_diag *d) {
  int rc = 0, n = 0, *fp = NULL;
  for (int k = 0; k < n_pairs && !rc; ++k) {
    sl_mesh_periodic pm;
    if ((rc = sl_transport_set_periodic_named(x->tr, pairs[k].boundary, pairs[k].partner, d))) break;
    if ((rc = sl_mesh_periodic_match(x->m, pairs[k].boundary, pairs[k].partner, &pm, d))) break;
    double along = pm.shift[0] * x->g[0] + pm.shift[1] * x->g[1];
    if (fabs(along) > 1e-9 * hypot(pm.shift[0], pm.shift[1]) * hypot(x->g[0], x->g[1])) x->periodic_along_g = 1;
    int *nf = realloc(fp, (size_t)2 * (n + pm.n_faces) * sizeof *nf);
    if (!nf) rc = sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
    else memcpy(nf + 2 * n, pm.face_pairs, (size_t)2 * pm.n_faces * sizeof *nf), fp = nf, n += pm.n_faces;
    sl_mesh_periodic_free(&pm);
  }
  if (!rc) rc = sl_face_flux_create(x->th, x->axi, open, fp, n, &x->ff, d);
  free(fp);
  return rc;
}

/* The mixture's output fields (after the flow's in [output] fields). */
enum { F_PHI = 1, F_STREAM = 2 };
static const char *const field_names[] = {"phi", "stream_function"};

static int setup(void *user, const sl_th_space *th, const sl_flow_opts *flow, const unsigned char *open,
                 const sl_periodic_pair *pairs, int n_pairs, unsigned fields, sl_diag *d) {
  mixture *x = user;
  x->fields = fields;
  x->th = th, x->m = th->mesh, x->axi = flow->axisymmetric, x->flow = flow;
  int nc = x->m->n_cells, nf = x->m->n_faces, rc;
  /* body force and its reference magnitude */
  double gl[3] = {0, 0, 0};
  int ng = 0;
  if ((rc = sl_ini_get_real_list(x->ini, "flow", "gravity", 0, gl, 3, &ng, d))) return rc;
  x->g[0] = gl[0], x->g[1] = x->m->dim > 1 ? gl[1] : 0.0;
  if ((rc = sl_ini_get_real(x->ini, "flow", "rotation", 0, 0.0, -1e6, 1e6, &x->omega, d))) return rc;
  int nk = 0;
  if ((rc = sl_ini_get_real_list(x->ini, "flow", "rotation_centre", 0, x->centre, 2, &nk, d))) return rc;
  x->g_ref = hypot(x->g[0], x->g[1]);
  if (x->g_ref == 0.0 && x->omega != 0.0) {
    double rmax = 0.0;
    for (int v = 0; v < x->m->n_vertices; ++v) {
      const double *p = x->m->xy + 2 * v;
      rmax = fmax(rmax, x->axi ? p[0] : hypot(p[0] - x->centre[0], p[1] - x->centre[1]));
    }
    x->g_ref = x->omega * x->omega * rmax;
  }
  if ((rc = sl_ini_get_bool(x->ini, "mixture", "slip_acceleration", 0, 0, &x->slip_acceleration, d))) return rc;
  if (x->slip_acceleration && x->g_ref == 0.0) x->g_ref = 1.0;
  if ((rc = sl_ini_get_real(x->ini, "mixture", "reference_acceleration", 0, x->g_ref, 1e-12, 1e12, &x->g_ref, d)))
    return rc;
  if ((rc = settling_setup(x, d))) return rc;
  if (x->st.b.c && x->g_ref == 0.0)
    return sl_diag_set(d, SL_EBADINPUT, "[closure.hindered_settling] is set but nothing drives settling: give [flow] "
                                        "gravity or rotation, or [mixture] slip_acceleration = true");
  /* the transport */
  long order = 2, table = 0;
  int lim = 0;
  double cfl = 0.9;
  if ((rc = sl_ini_get_int(x->ini, "transport", "order", 0, 2, 1, 2, &order, d))) return rc;
  if ((rc = sl_ini_get_choice(x->ini, "transport", "limiter", 0, 0, "mc|minmod", &lim, d))) return rc;
  if ((rc = sl_ini_get_real(x->ini, "transport", "cfl", 0, 0.9, 1e-3, 1.0, &cfl, d))) return rc;
  if ((rc = sl_ini_get_int(x->ini, "transport", "table_points", 0, 2049, 17, 1000001, &table, d))) return rc;
  x->topts = (sl_transport_opts){.phi_max = x->phi_max,
                                 .order = (int)order,
                                 .limiter = lim ? SL_LIMITER_MINMOD : SL_LIMITER_MC,
                                 .geometry = x->axi ? SL_TRANSPORT_AXISYMMETRIC : SL_TRANSPORT_PLANAR,
                                 .cfl = cfl,
                                 .table_points = (int)table,
                                 .settling = settling_fn,
                                 .settling_user = &x->st};
  if ((rc = sl_transport_create(x->m, &x->topts, &x->tr, d))) return sl_diag_prefix(d, rc, "solids transport");
  if ((rc = transport_boundaries(x, open, d))) return rc;
  if ((rc = periodic_setup(x, open, pairs, n_pairs, d))) return rc;
  const double *area = sl_transport_face_areas(x->tr);
  for (int f = 0; f < nf; ++f) x->area_max = fmax(x->area_max, area[f]);
  x->phi = malloc((size_t)nc * sizeof *x->phi);
  x->trial = malloc((size_t)nc * sizeof *x->trial);
  x->q = malloc((size_t)nf * sizeof *x->q);
  x->w = calloc((size_t)nf, sizeof *x->w);
  x->q_acc = calloc((size_t)nf, sizeof *x->q_acc);
  if (!x->phi || !x->trial || !x->q || !x->w || !x->q_acc) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  if (x->m->dim == 2 && (x->fields & F_STREAM)) {
    x->psi = malloc((size_t)x->m->n_vertices * sizeof *x->psi);
    x->node_psi = malloc((size_t)th->vel->n_nodes * sizeof *x->node_psi);
    if (!x->psi || !x->node_psi || sl_stream_graph_build(&x->pg, x->m))
      return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  }
  if (x->slip_acceleration) {
    x->acc = calloc((size_t)2 * nc, sizeof *x->acc);
    x->b_face = malloc((size_t)2 * nf * sizeof *x->b_face);
    if (!x->acc || !x->b_face) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  }
  if (x->st.b.c) {
    sl_transport_settling_field(x->tr, body_direction, x, x->w);
    set_flux_floor(x);
  }
  if (x->cpl.rho_solid != x->rho_f && (hypot(x->g[0], x->g[1]) > 0.0 || x->omega != 0.0)) {
    x->cell_drag = malloc((size_t)4 * nc * sizeof *x->cell_drag);
    x->grad_phi = malloc((size_t)2 * nc * sizeof *x->grad_phi);
    if (!x->cell_drag || !x->grad_phi) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
    x->cpl.cell_drag = x->cell_drag, x->cpl.prepare = prepare;
  }
  if ((rc = migration_setup(x, d))) return rc;
  if ((rc = initial_phi(x, d))) return rc;
  x->inventory = x->inventory0 = sl_transport_mass(x->tr, x->phi);
  if ((rc = hydrostatic_setup(x, open, d))) return rc;
  if (x->relative_flux_stress && (rc = stress_setup(x, d))) return rc;
  /* interface levels */
  const sl_ini_entry *le = sl_ini_find(x->ini, "output", "interface");
  if (le) {
    if ((rc = sl_ini_get_real_list(x->ini, "output", "interface", 0, x->level, MAX_LEVELS, &x->n_levels, d))) return rc;
    if (x->n_levels > 0 && hypot(x->g[0], x->g[1]) == 0.0)
      return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [output] interface: heights are measured against gravity, and the "
                                          "scene has none", le->file, le->line);
  }
  return 0;
}

static int advance(void *user, double t, double dt, const double *u, const double *dudt, sl_diag *d) {
  mixture *x = user;
  if (x->st.b.c && x->slip_acceleration) { /* the slip of this step follows the acceleration at its end */
    cell_accelerations(x, u, dudt);
    sl_transport_settling_faces(x->tr, x->b_face, x->w);
    set_flux_floor(x);
  }
  /* the divergence is measured against the through-flow, or against the settling flux and 1e-8 of the
   * largest speed where the mixture hardly moves across faces (a swirl, a closed column) */
  double umax = 0.0;
  for (int32_t i = 0; i < x->th->p_offset; ++i) umax = fmax(umax, fabs(u[i]));
  int rc = sl_face_flux_conservative(x->ff, u, fmax(x->flux_floor, 1e-8 * umax * x->area_max), x->q, &x->trial_raw_div, d);
  if (rc) return rc;
  memcpy(x->trial, x->phi, (size_t)x->m->n_cells * sizeof *x->trial);
  if (x->mig.c) { /* the shear rate of the new velocity drives the migration over the step */
    if ((rc = sl_flow_cell_diagnostics(x->th, u, x->flow, 0.0, x->shear, NULL, NULL, d)) ||
        (rc = sl_migration_set_shear_rate(x->mg, x->shear, d)))
      return rc;
  }
  sl_transport_stats st;
  rc = sl_transport_step(x->tr, dt, x->q, x->st.b.c ? x->w : NULL, x->trial, &st, d);
  if (rc) return sl_diag_prefix(d, SL_EFAILED, "solids transport from t = %.6g over dt = %.3g", t, dt);
  x->trial_substeps = st.n_substeps, x->trial_fallbacks = st.n_fallbacks;
  x->trial_inflow = st.boundary_inflow;
  x->max_div = fmax(x->max_div, st.max_divergence);
  return x->relative_flux_stress ? stress_of(x, x->trial, d) : 0;
}

static int unchanged(void *user) { return ((const mixture *)user)->unchanged; }

static void accept(void *user) {
  mixture *x = user;
  x->unchanged = memcmp(x->phi, x->trial, (size_t)x->m->n_cells * sizeof *x->phi) == 0;
  memcpy(x->phi, x->trial, (size_t)x->m->n_cells * sizeof *x->phi);
  memcpy(x->q_acc, x->q, (size_t)x->m->n_faces * sizeof *x->q_acc);
  x->inflow += x->trial_inflow;
  x->inventory = sl_transport_mass(x->tr, x->phi);
  x->substeps += x->trial_substeps, x->fallbacks += x->trial_fallbacks, ++x->advances;
  x->max_raw_div = fmax(x->max_raw_div, x->trial_raw_div);
  if (x->relative_flux_stress) node_stress_of(x);
  hydrostatic_update(x);
}

static int write(void *user, sl_output *out, sl_diag *d) {
  mixture *x = user;
  int rc = x->fields & F_PHI ? sl_output_write_field(out, "phi", SL_CENTRE_CELL, 1, x->phi, d) : 0;
  if (!rc && x->psi) {
    /* at the velocity nodes: vertices as computed, edge and centre nodes the mean of their cell's vertices
       (exact on edge midpoints for psi linear along the edge) */
    sl_stream_function(x->m, &x->pg, x->q_acc, x->psi);
    const sl_mesh *m = x->m;
    int nb = x->th->vel->dofs_per_cell, nvc = m->nv_per_cell;
    for (int c = 0; c < m->n_cells; ++c) {
      const int32_t *vd = x->th->vel->cell_nodes + (size_t)c * nb;
      const int *cv = m->cell_vertices + (size_t)c * nvc;
      for (int k = 0; k < nb; ++k) {
        double v = 0.0;
        if (k < nvc) {
          v = x->psi[cv[k]];
        } else if (k - nvc < nvc) {
          v = 0.5 * (x->psi[cv[k - nvc]] + x->psi[cv[(k - nvc + 1) % nvc]]);
        } else {
          for (int j = 0; j < nvc; ++j) v += x->psi[cv[j]] / nvc;
        }
        x->node_psi[vd[k]] = v;
      }
    }
    rc = sl_output_write_field(out, "stream_function", SL_CENTRE_NODE, 1, x->node_psi, d);
  }
  double inv = sl_transport_mass(x->tr, x->phi);
  double err = x->inventory0 + x->inflow > 0.0 ? (inv - x->inventory0 - x->inflow) / (x->inventory0 + x->inflow) : 0.0;
  if (!rc) rc = sl_output_write_scalar(out, "solids_inventory", inv, d);
  if (!rc) rc = sl_output_write_scalar(out, "solids_conservation_error", err, d);
  for (int k = 0; k < x->n_levels && !rc; ++k) {
    char name[64];
    snprintf(name, sizeof name, "interface_height_%d", k);
    rc = sl_output_write_scalar(out, name, interface_height(x, x->phi, x->level[k]), d);
    snprintf(name, sizeof name, "interface_level_%d", k);
    if (!rc) rc = sl_output_write_scalar(out, name, x->level[k], d);
  }
  return rc;
}

static int checkpoint(void *user, sl_checkpoint_array *a, int max) {
  mixture *x = user;
  if (max < 2) return 0;
  snprintf(a[0].name, sizeof a[0].name, "phi");
  a[0].n = x->m->n_cells, a[0].data = x->phi;
  x->book[0] = x->inventory0, x->book[1] = x->inflow;
  snprintf(a[1].name, sizeof a[1].name, "solids_book");
  a[1].n = 2, a[1].data = x->book;
  if (!x->relative_flux_stress || max < 3) return 2;
  /* it holds the slip direction of the last step, which phi alone does not give */
  snprintf(a[2].name, sizeof a[2].name, "relative_flux_stress");
  a[2].n = 6 * (int64_t)x->th->pres->n_dofs, a[2].data = x->node_stress;
  return 3;
}

static int restore(void *user, const sl_checkpoint *ck, sl_diag *d) {
  mixture *x = user;
  const sl_checkpoint_array *p = sl_checkpoint_find(ck, "phi"), *b = sl_checkpoint_find(ck, "solids_book");
  if (!p || p->n != x->m->n_cells || !b || b->n != 2)
    return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no solids fraction of %d cells", x->m->n_cells);
  memcpy(x->phi, p->data, (size_t)p->n * sizeof *x->phi);
  x->inventory0 = b->data[0], x->inflow = b->data[1];
  x->inventory = sl_transport_mass(x->tr, x->phi);
  hydrostatic_update(x);
  if (!x->relative_flux_stress) return 0;
  const sl_checkpoint_array *s = sl_checkpoint_find(ck, "relative_flux_stress");
  if (s && s->n == 6 * (int64_t)x->th->pres->n_dofs) {
    memcpy(x->node_stress, s->data, (size_t)s->n * sizeof *x->node_stress);
    return 0;
  }
  int rc = stress_of(x, x->phi, d); /* saved without it: from phi */
  if (!rc) node_stress_of(x);
  return rc;
}

static int provenance(void *user, sl_provenance_closure *pc, int max, char *buf, size_t len) {
  mixture *x = user;
  if (!x->st.b.c || max < 1) return 0;
  const sl_closure_desc *c = x->st.b.c->desc;
  size_t at = 0;
  buf[0] = '\0';
  for (int k = 0; k < c->n_params && at < len; ++k) {
    char v[64];
    sl_params_format_value(c, x->st.b.c->params, k, v, sizeof v);
    at += (size_t)snprintf(buf + at, len - at, "%s = %s\n", c->params[k].name, v);
  }
  pc[0] = (sl_provenance_closure){"closure.hindered_settling", sl_kind_name(c->kind), c->name, c->version,
                                  x->st.b.c->library->path, buf};
  return 1;
}

int sl_mixture_run(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res, sl_diag *d) {
  mixture x = {.ini = ini, .reg = reg, .phi_max = 0.64};
  int rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, &x.rho_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "fluid", "viscosity", 0, 1e-3, 1e-7, 1e7, &x.mu_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "density", 1, 0, 1e-3, 1e5, &x.cpl.rho_solid, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "phi_max", 0, 0.64, 0.01, 1.0, &x.phi_max, d);
  if (rc) return rc;
  x.cpl.user = &x;
  x.cpl.field_names = field_names, x.cpl.n_fields = (int)(sizeof field_names / sizeof field_names[0]);
  x.cpl.setup = setup, x.cpl.cell_phi = cell_phi, x.cpl.advance = advance, x.cpl.accept = accept;
  x.cpl.unchanged = unchanged, x.cpl.at_rest = at_rest;
  x.cpl.write = write, x.cpl.checkpoint = checkpoint, x.cpl.restore = restore, x.cpl.provenance = provenance;
  if ((rc = sl_ini_get_bool(ini, "mixture", "relative_flux_stress", 0, 0, &x.relative_flux_stress, d))) return rc;
  sl_ns_run_opts oo = *o;
  oo.coupling = &x.cpl;
  rc = sl_ns_run(ini, reg, &oo, res, d);
  if (x.tr) { /* the mesh is gone now: only what the run kept */
    double inv = x.inventory, base = x.inventory0 + x.inflow;
    snprintf(res->coupling_summary, sizeof res->coupling_summary,
             "solids: %ld transport sub-steps (%.1f per step, %ld at first order), conservation error %.1e, "
             "raw face-flux divergence up to %.1e",
             x.substeps, x.advances ? (double)x.substeps / (double)x.advances : 0.0, x.fallbacks,
             base > 0.0 ? (inv - base) / base : 0.0, x.max_raw_div);
  }
  sl_transport_destroy(x.tr);
  sl_face_flux_destroy(x.ff);
  free(x.phi), free(x.trial), free(x.q), free(x.w), free(x.q_acc), free(x.acc), free(x.b_face), free(x.psi), free(x.node_psi);
  free(x.cell_stress), free(x.settle_speed), free(x.node_stress), free(x.node_weight);
  free(x.cell_drag), free(x.grad_phi), free(x.buoy_phi), free(x.p_hydro);
  sl_hydrostatic_destroy(x.hs);
  sl_stream_graph_free(&x.pg);
  free(x.st.b.buf);
  sl_closure_destroy(x.st.b.c);
  sl_migration_destroy(x.mg);
  free(x.shear);
  free(x.mig.buf), free(x.visc.buf);
  sl_closure_destroy(x.mig.c);
  sl_closure_destroy(x.visc.c);
  return rc;
}
