/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The mixture model: the solids fraction riding on the flow (see
 * mixture.h). */
#include "core/models/mixture/mixture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/assembly/hydrostatic.h"
#include "core/config/expr.h"
#include "core/fe/field.h"
#include "core/fv/face_flux.h"
#include "core/models/mixture/inflow.h"
#include "core/models/navier_stokes/flow.h"
#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"
#include "core/plugin/point_eval.h"
#include "core/scene/keys.h"
#include "core/transport/migration.h"
#include "core/transport/transport.h"

/* The model's own keys ([initial] phi, [mixture], [transport]). */
typedef struct mixture_config {
  sl_flow_config flow; /* first: the flow's keys address it from the config's start */
  sl_scene_expr phi;
  int slip_acceleration, relative_flux_stress;
  double reference_acceleration, diffusivity;
  long order, table_points;
  int limiter;
  double cfl;
  const char *inventory_regions;  /* [output]: mesh regions whose solids inventory is written */
  sl_scene_exprs inventory_where; /* [output]: regions as expressions of x, y (a cell counts where > 0) */
} mixture_config;

enum { MAX_LEVELS = 8, MAX_INVENTORIES = 8 };

/* The quantities the mixture model gives its closures. */
enum { Q_PHI, Q_SHEAR_RATE, Q_D_P, Q_SPHERICITY, Q_RHO_S, Q_RHO_F, Q_MU_F, Q_GRAVITY, Q_D_VESSEL, Q_N };
static const char *const quantity_names[Q_N] = {"phi",   "shear_rate", "d_p",     "sphericity", "rho_s",
                                                "rho_f", "mu_f",       "gravity", "d_vessel"};

/* The hindered-settling closure as the transport's batch callback: phi
 * varies, every other input is fixed by the scene. */
typedef struct settling {
  sl_closure *c; /* the scene's; NULL: no settling */
  sl_point_closure pc;
} settling;

typedef struct mixture {
  const unsigned char *closed; /* the flow's curved slip walls (sl_flow_closed): no flux through their faces */
  sl_scene *sc;
  const mixture_config *cfg;
  sl_flow *flow_model; /* the flow it rides on */
  double rho_solid;
  const double *extra_stress; /* the flow's extra stress (node_stress), NULL without relative_flux_stress */
  const sl_th_space *th;
  const sl_mesh *m;
  int axi;
  double rho_f, mu_f, phi_max;
  double g[2], g_ref, omega, centre[2];
  settling st;
  int slip_acceleration;        /* [mixture]: the slip follows g - Dj/Dt */
  double *acc;                  /* [2 n_cells] Dj/Dt (+ Coriolis) at the cell points (zero before the first step) */
  int relative_flux_stress;     /* [mixture]: the momentum carries -div(rho_f j_R j_R / (phi (1 - phi))) */
  double *cell_stress;          /* [3 n_cells] its entries 00, 11, 01 per cell of the trial state */
  double *settle_speed;         /* [n_cells] u_settle(phi) of the cells (scratch) */
  double *node_stress;          /* [6 pressure dofs] of the current state: the flow's extra stress */
  double *node_weight;          /* [pressure dofs] 1 / the cell volume around the node */
  double *b_face;               /* [2 n_faces] the body-force direction per face */
  double *cell_drag, *grad_phi; /* [4 n_cells], [2 n_cells]: the buoyancy's response to the step's velocity */
  sl_hydrostatic *hs;           /* the layers whose hydrostatic part of the buoyancy the pressure carries, or NULL */
  double *buoy_phi, *p_hydro;   /* [n_cells] phi less that part, [pressure dofs] its pressure */
  int periodic_along_g;         /* a periodic pair repeats along gravity */
  int unchanged;                /* the last accepted step left phi bitwise as it was */
  int no_load;                  /* the remainder of the hydrostatic split is at round-off: the flow is not loaded */
  sl_transport_opts topts;
  sl_transport *tr;
  sl_mixture_inflow *inflow_bc; /* phi of the inflow along boundaries or in time (inflow.h), or NULL */
  sl_face_flux *ff;
  double *phi, *trial, *q, *w; /* cells, cells, faces, faces */
  double *phi_flow, *q_pred;   /* [n_cells] the phi of the flow's viscosity and density (prepare), [n_faces] */
  double *q_acc;               /* [n_faces] the conservative fluxes of the last accepted step */
  int n_inv;                   /* regions whose solids inventory is written ([output] inventory_*) */
  char inv_name[MAX_INVENTORIES][96];
  unsigned char *inv_mask; /* [n_inv * n_cells]: the cell is in region k */
  double *inv_phi;         /* [n_cells] scratch: phi in the region, 0 elsewhere */
  unsigned fields;         /* bit k: field_names[k] is written */
  double inventory0, inflow, trial_inflow;
  double inventory;   /* of the current state */
  double cpu_coupled; /* CPU seconds in the transport steps */
  double book[2];     /* inventory0 and inflow as checkpointed */
  long substeps, fallbacks, trial_substeps, trial_fallbacks, advances;
  double max_raw_div, trial_raw_div, max_div;
  double flux_floor; /* the settling flux scale max |w_f| max |F|: the divergence is measured against it too */
  double area_max;   /* the largest face area */
  int n_levels;
  double level[MAX_LEVELS];
  /* shear-induced migration (optional) */
  const sl_flow_opts *flow;
  sl_closure *mig_c, *visc_c; /* [closure.migration]; [closure.viscosity] as mu(phi) (the scene's) */
  sl_point_closure mig, visc;
  sl_migration *mg;
  double *shear; /* [n_cells] */
  char params[2048];
} mixture;

/* ---- the settling closure ------------------------------------------------- */

static int settling_fn(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  settling *s = user;
  if (!s->c) {
    for (int i = 0; i < n; ++i) u[i] = du[i] = 0.0;
    return 0;
  }
  const double *values[Q_N] = {phi};
  sl_point_request rq = {"settling_velocity", u, du, "phi"};
  int rc = sl_point_eval(&s->pc, n, values, &rq, 1, d);
  return rc ? sl_diag_prefix(d, SL_EBADINPUT, "settling flux") : 0;
}

/* [solid] diameter, which a closure with the input d_p needs. */
static int solid_diameter(const sl_scene *sc, double *v, sl_diag *d) {
  *v = sc->solid.diameter;
  return sl_scene_require(sc, &sc->solid.diameter, d);
}

/* Binds the closure's inputs to the scene: phi varies; d_p, sphericity,
 * rho_s from [solid]; rho_f, mu_f from [fluid]; gravity is g_ref; d_vessel
 * infinite (no wall term) unless [solid] vessel_diameter. */
static int settling_setup(mixture *x, sl_diag *d) {
  settling *s = &x->st;
  const sl_scene *sc = x->sc;
  if (!(s->c = sl_scene_closure(sc, "hindered_settling"))) return 0;
  const sl_closure_desc *c = s->c->desc;
  char label[128], where[300];
  sl_scene_closure_where(sc, "hindered_settling", where, sizeof where);
  sl_closure_label(c, label, sizeof label);
  int rc = sl_point_bind(&s->pc, s->c, quantity_names, Q_N, "closure.hindered_settling", "the mixture model", d);
  if (rc) return rc;
  if (!sl_point_has_input(&s->pc, "phi") || !sl_point_has_output(&s->pc, "settling_velocity") ||
      sl_point_has_input(&s->pc, "shear_rate"))
    return sl_diag_set(d, SL_EBADINPUT, "%s %s does not map phi to a settling_velocity", where, label);
  double dp = 0.0;
  if (sl_point_has_input(&s->pc, "d_p") && (rc = solid_diameter(sc, &dp, d)))
    return sl_diag_prefix(d, rc, "[closure.hindered_settling] %s needs d_p", label);
  double vessel = sc->solid.vessel_diameter > 0.0 ? sc->solid.vessel_diameter : HUGE_VAL;
  const double constants[Q_N] = {0.0, 0.0, dp, sc->solid.sphericity, x->rho_solid, x->rho_f, x->mu_f, x->g_ref, vessel};
  for (int k = Q_D_P; k < Q_N; ++k) sl_point_constant(&s->pc, quantity_names[k], constants[k]);
  /* phi_max: the closure's packing parameter unless the scene sets [solid] phi_max; both must agree */
  int k = sl_params_find(c, "phi_max");
  const sl_src *pe = sl_scene_src(sc, &sc->solid.phi_max);
  if (k >= 0) {
    char buf[64];
    double cv;
    sl_params_format_value(c, s->c->params, k, buf, sizeof buf);
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
    for (int i = 0; i < th->n_comp; ++i)
      sl_fe_eval(th->vel, u + (size_t)i * th->n_vel, c, xi, &v[i], i < dim ? g[i] : NULL);
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
/* The phi whose viscosity and density the flow's step takes: phi at the step's end as the transport moves it with
 * the face fluxes of the step's predicted velocity (the BDF predictor), from the accepted phi. With the accepted
 * phi instead, the flow of a step lags the transport by one step: where the flow follows phi quasi-statically
 * (the spectrometer: viscous and Ekman times of 3e-4 against steps of 1e-2) the new velocity jumped by the
 * response to the last step's change of phi however short the step, its BDF estimate did not fall with the step,
 * and the controller rejected 17.6 % of the steps (docs/transient_cost.md, "Rejected steps of the spectrometer").
 * The buoyancy keeps the accepted phi with its implicit part below (prepare): with the predicted phi in it too
 * (and that part only against the predictor's velocity) the settling box at a density contrast of 1 grew
 * without bound, as the explicit coupling does. Where the transport fails the flow sees the accepted phi. */
static void predict_transport(mixture *x, double dt, const double *u) {
  int nc = x->m->n_cells;
  memcpy(x->phi_flow, x->phi, (size_t)nc * sizeof *x->phi_flow);
  if (!x->ff || !u) return;
  double umax = 0.0;
  for (int32_t i = 0; i < x->th->p_offset; ++i) umax = fmax(umax, fabs(u[i]));
  sl_diag dp;
  if (sl_face_flux_conservative(x->ff, u, fmax(x->flux_floor, 1e-8 * umax * x->area_max), x->q_pred, NULL, &dp))
    return;
  /* with slip_acceleration the settling field is the last step's, which a restart does not keep: advection alone
     there, so that a restarted run goes on bit for bit */
  if (sl_transport_step(x->tr, dt, x->q_pred, x->st.c && !x->slip_acceleration ? x->w : NULL, x->phi_flow, NULL, &dp))
    memcpy(x->phi_flow, x->phi, (size_t)nc * sizeof *x->phi_flow);
}

static int prepare(void *user, double dt, const double *u, sl_diag *d) {
  mixture *x = user;
  (void)d;
  const double *xc = sl_transport_cell_points(x->tr);
  double drho = x->rho_solid - x->rho_f;
  predict_transport(x, dt, u);
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
  double drho = x->rho_solid - x->rho_f;
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
  if (x->rho_solid == x->rho_f || x->periodic_along_g) return 0;
  for (int b = 0; open && b < x->m->n_boundaries; ++b)
    if (open[b]) return 0;
  int rc = sl_hydrostatic_create(x->m, x->g, sl_transport_volumes(x->tr), sl_transport_cell_points(x->tr), &x->hs, d);
  if (rc || !x->hs) return rc;
  x->buoy_phi = malloc((size_t)x->m->n_cells * sizeof *x->buoy_phi);
  x->p_hydro = malloc((size_t)x->th->pres->n_dofs * sizeof *x->p_hydro);
  if (!x->buoy_phi || !x->p_hydro) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
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
 * -div[rho_f j_R j_R / (phi (1 - phi))] (dimensional; Nigam 1999,
 * eqs 2.15-2.16 and 2.31-2.39), the momentum flux of the two phases' motion
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
  const double *values[Q_N] = {phi_cells};
  sl_point_request rq = {"settling_velocity", x->settle_speed, NULL, NULL};
  int rc = sl_point_eval(&x->st.pc, nc, values, &rq, 1, d);
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
  if (!x->st.c)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[mixture] relative_flux_stress = true needs the relative flux of a "
                       "[closure.hindered_settling]; the scene has none");
  const sl_dofmap *pm = x->th->pres;
  int nc = x->m->n_cells, np = pm->dofs_per_cell;
  x->cell_stress = malloc((size_t)3 * nc * sizeof *x->cell_stress);
  x->settle_speed = malloc((size_t)nc * sizeof *x->settle_speed);
  x->node_stress = malloc((size_t)6 * pm->n_dofs * sizeof *x->node_stress);
  x->node_weight = calloc((size_t)pm->n_dofs, sizeof *x->node_weight);
  if (!x->cell_stress || !x->settle_speed || !x->node_stress || !x->node_weight)
    return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  const double *vol = sl_transport_volumes(x->tr);
  for (int c = 0; c < nc; ++c)
    for (int k = 0; k < np; ++k) x->node_weight[pm->cell_dofs[(size_t)c * np + k]] += vol[c];
  for (int32_t i = 0; i < pm->n_dofs; ++i) x->node_weight[i] = x->node_weight[i] > 0.0 ? 1.0 / x->node_weight[i] : 0.0;
  int rc = stress_of(x, x->phi, d);
  if (rc) return rc;
  node_stress_of(x);
  x->extra_stress = x->node_stress;
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

static int migration_coef(void *user, int n, const double *phi, const double *g, double *D_c, double *D_mu,
                          sl_diag *d) {
  mixture *x = user;
  const double *values[Q_N] = {phi, g};
  sl_point_request rq[2] = {{"D_c", D_c, NULL, NULL}, {"D_mu", D_mu, NULL, NULL}};
  return sl_point_eval(&x->mig, n, values, rq, 2, d);
}

static int migration_lnmu(void *user, int n, const double *phi, double *ln_mu, double *dln_mu, sl_diag *d) {
  mixture *x = user;
  const double *values[Q_N] = {phi};
  sl_point_request rq = {"viscosity", ln_mu, dln_mu, "phi"};
  int rc = sl_point_eval(&x->visc, n, values, &rq, 1, d);
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
  const sl_scene *sc = x->sc;
  double eps = x->cfg->diffusivity;
  int rc = 0;
  sl_migration_opts mo = {.diffusivity = eps};
  if (!(x->mig_c = sl_scene_closure(sc, "migration"))) return eps > 0.0 ? create_gradient_flux(x, &mo, d) : 0;
  const sl_closure_desc *c = x->mig_c->desc;
  char label[128], where[300];
  sl_closure_label(c, label, sizeof label);
  sl_scene_closure_where(sc, "migration", where, sizeof where);
  /* it is given phi, the shear rate and d_p */
  if ((rc = sl_point_bind(&x->mig, x->mig_c, quantity_names, Q_D_P + 1, "closure.migration", "the mixture model", d)))
    return rc;
  if (!sl_point_has_input(&x->mig, "phi") || !sl_point_has_input(&x->mig, "shear_rate") ||
      !sl_point_has_output(&x->mig, "D_c") || !sl_point_has_output(&x->mig, "D_mu"))
    return sl_diag_set(d, SL_EBADINPUT, "%s %s does not give D_c and D_mu of phi and shear_rate", where, label);
  if (sl_point_has_input(&x->mig, "d_p")) {
    double dp;
    if ((rc = solid_diameter(sc, &dp, d))) return rc;
    sl_point_constant(&x->mig, "d_p", dp);
  }
  mo.coef = migration_coef, mo.coef_user = x;
  if ((x->visc_c = sl_scene_closure(sc, "viscosity"))) {
    char vs[300];
    sl_scene_closure_where(sc, "viscosity", vs, sizeof vs);
    const sl_closure_desc *v = x->visc_c->desc;
    sl_closure_label(v, label, sizeof label);
    int in_phi = sl_closure_input(v, "phi");
    if (in_phi < 0 || sl_closure_output(v, "viscosity") < 0 || !(v->in[in_phi].flags & SL_FIELD_DIFF))
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s: [closure.migration] needs [closure.viscosity] as a viscosity of phi; "
                         "%s is not",
                         vs, label);
    for (int i = 0; i < v->n_in; ++i) {
      const char *name = v->in[i].name;
      if (strcmp(name, "phi") != 0 && strcmp(name, "mu_f") != 0 && strcmp(name, "rho_f") != 0)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s: [closure.migration] takes mu(phi) from [closure.viscosity], but %s "
                           "also depends on '%s'",
                           vs, label, name);
    }
    if ((rc = sl_point_bind(&x->visc, x->visc_c, quantity_names, Q_N, "closure.viscosity", "the mixture model", d)))
      return rc;
    sl_point_constant(&x->visc, "mu_f", x->mu_f), sl_point_constant(&x->visc, "rho_f", x->rho_f);
    mo.ln_mu = migration_lnmu, mo.ln_mu_user = x;
  }
  x->shear = calloc((size_t)x->m->n_cells, sizeof *x->shear);
  if (!x->shear) return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  return create_gradient_flux(x, &mo, d);
}

static int initial_phi(mixture *x, sl_diag *d) {
  const sl_src *e = sl_scene_src(x->sc, &x->cfg->phi);
  const sl_expr *ex = x->cfg->phi.e;
  if (!ex) return sl_diag_set(d, SL_EBADINPUT, "[initial] phi: the mixture model needs the initial solids fraction");
  int rc = 0;
  const double *xc = sl_transport_cell_points(x->tr);
  for (int c = 0; c < x->m->n_cells && !rc; ++c) {
    double v = sl_expr_eval(ex, xc + 2 * c);
    if (!(v >= 0.0 && v <= x->phi_max))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] phi = %g at (%g, %g): allowed 0 <= phi <= phi_max = %g",
                       e->file, e->line, v, xc[2 * c], xc[2 * c + 1], x->phi_max);
    x->phi[c] = v;
  }
  return rc;
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
    if (!nf) rc = sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
    else memcpy(nf + 2 * n, pm.face_pairs, (size_t)2 * pm.n_faces * sizeof *nf), fp = nf, n += pm.n_faces;
    sl_mesh_periodic_free(&pm);
  }
  if (!rc) rc = sl_face_flux_create(x->th, x->axi, open, fp, n, &x->ff, d);
  if (!rc) rc = sl_face_flux_close(x->ff, x->closed, d);
  free(fp);
  return rc;
}

/* The mixture's output fields (after the flow's in [output] fields). */
enum { F_PHI = 1 };

/* The solids fraction on the flow f: the settling closure, the transport,
 * the diagnostics and the initial phi. */
/* The regions of [output] inventory_regions (mesh regions by name, comma-separated) and inventory_where
 * (expressions of x, y: the cells whose centroid gives a positive value), whose solids inventories int phi dV
 * are written as solids_inventory_NAME and solids_inventory_where_K: Greenspan's spectrometer's efficiency is
 * the share of particles found downstream of the slot (Nigam 1999, section 4.3). */
static int inventory_setup(mixture *x, sl_diag *d) {
  const mixture_config *cfg = x->cfg;
  const sl_mesh *m = x->m;
  int nc = m->n_cells, n_names = 0;
  const char *list = cfg->inventory_regions ? cfg->inventory_regions : "";
  for (const char *p = list; *p;) { /* count the names */
    size_t len = strcspn(p, ",");
    n_names += len > strspn(p, " \t") ? 1 : 0;
    p += len + (p[len] == ',');
  }
  int n = n_names + cfg->inventory_where.n;
  if (n == 0) return 0;
  if (n > MAX_INVENTORIES)
    return sl_diag_set(d, SL_EBADINPUT, "[output] inventory_regions and inventory_where: %d regions, at most %d", n,
                       MAX_INVENTORIES);
  x->inv_mask = calloc((size_t)n * nc, 1);
  x->inv_phi = malloc((size_t)nc * sizeof *x->inv_phi);
  if (!x->inv_mask || !x->inv_phi) return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  const sl_src *src = sl_scene_src(x->sc, &cfg->inventory_regions);
  for (const char *p = list; *p;) {
    size_t len = strcspn(p, ",");
    const char *a = p, *b = p + len;
    p += len + (p[len] == ',');
    while (a < b && (*a == ' ' || *a == '\t')) ++a;
    while (b > a && (b[-1] == ' ' || b[-1] == '\t')) --b;
    if (a == b) continue;
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)(b - a), a);
    int r = -1;
    for (int k = 0; k < m->n_regions; ++k)
      if (strcmp(m->region_names[k], name) == 0) r = k;
    if (r < 0) {
      const char *near = m->n_regions ? sl_suggest(name, (const char *const *)m->region_names, m->n_regions) : NULL;
      char where[160] = "[output] inventory_regions";
      if (src) snprintf(where, sizeof where, "%s:%d: [output] inventory_regions", src->file, src->line);
      if (!m->n_regions)
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s: no region '%s': the mesh has no named regions (a Gmsh file's "
                           "physical surfaces; use inventory_where for an expression)",
                           where, name);
      return sl_diag_set(d, SL_EBADINPUT, "%s: no region '%s' in the mesh%s%s%s", where, name,
                         near ? "; did you mean '" : "", near ? near : "", near ? "'?" : "");
    }
    unsigned char *mask = x->inv_mask + (size_t)x->n_inv * nc;
    for (int c = 0; c < nc; ++c) mask[c] = m->cell_region[c] == r;
    snprintf(x->inv_name[x->n_inv++], sizeof x->inv_name[0], "solids_inventory_%s", name);
  }
  const double *xc = sl_transport_cell_points(x->tr);
  for (int k = 0; k < cfg->inventory_where.n; ++k) {
    unsigned char *mask = x->inv_mask + (size_t)x->n_inv * nc;
    for (int c = 0; c < nc; ++c) mask[c] = sl_expr_eval(cfg->inventory_where.e[k], xc + 2 * c) > 0.0;
    snprintf(x->inv_name[x->n_inv++], sizeof x->inv_name[0], "solids_inventory_where_%d", k);
  }
  return 0;
}

static int mixture_setup(mixture *x, const sl_flow *fl, unsigned fields, sl_diag *d) {
  const sl_scene *sc = x->sc;
  const mixture_config *cfg = x->cfg;
  const sl_th_space *th = sl_flow_space(fl);
  const unsigned char *open = sl_flow_open(fl);
  int n_pairs = 0;
  const sl_periodic_pair *pairs = sl_flow_periodic(fl, &n_pairs);
  x->fields = fields;
  x->th = th, x->m = th->mesh, x->axi = sl_flow_axisymmetric(fl), x->flow = sl_flow_options(fl);
  x->rho_f = sc->fluid.density, x->mu_f = sc->fluid.viscosity;
  x->slip_acceleration = cfg->slip_acceleration, x->relative_flux_stress = cfg->relative_flux_stress;
  int nc = x->m->n_cells, nf = x->m->n_faces, rc;
  /* body force and its reference magnitude */
  const sl_reals *gl = &sc->flow.gravity, *ce = &sc->flow.rotation_centre;
  x->g[0] = gl->n > 0 ? gl->v[0] : 0.0, x->g[1] = x->m->dim > 1 && gl->n > 1 ? gl->v[1] : 0.0;
  x->omega = sc->flow.rotation;
  x->centre[0] = ce->n > 0 ? ce->v[0] : 0.0, x->centre[1] = ce->n > 1 ? ce->v[1] : 0.0;
  x->g_ref = hypot(x->g[0], x->g[1]);
  if (x->g_ref == 0.0 && x->omega != 0.0) {
    double rmax = 0.0;
    for (int v = 0; v < x->m->n_vertices; ++v) {
      const double *p = x->m->xy + 2 * v;
      rmax = fmax(rmax, x->axi ? p[0] : hypot(p[0] - x->centre[0], p[1] - x->centre[1]));
    }
    x->g_ref = x->omega * x->omega * rmax;
  }
  if (x->slip_acceleration && x->g_ref == 0.0) x->g_ref = 1.0;
  if (sl_scene_given(sc, &cfg->reference_acceleration)) x->g_ref = cfg->reference_acceleration;
  if ((rc = settling_setup(x, d))) return rc;
  if (x->st.c && x->g_ref == 0.0)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[closure.hindered_settling] is set but nothing drives settling: give [flow] "
                       "gravity or rotation, or [mixture] slip_acceleration = true");
  /* the transport */
  x->topts = (sl_transport_opts){.phi_max = x->phi_max,
                                 .order = (int)cfg->order,
                                 .limiter = cfg->limiter ? SL_LIMITER_MINMOD : SL_LIMITER_MC,
                                 .geometry = x->axi ? SL_TRANSPORT_AXISYMMETRIC : SL_TRANSPORT_PLANAR,
                                 .cfl = cfg->cfl,
                                 .table_points = (int)cfg->table_points,
                                 .settling = settling_fn,
                                 .settling_user = &x->st};
  if ((rc = sl_transport_create(x->m, &x->topts, &x->tr, d))) return sl_diag_prefix(d, rc, "solids transport");
  if ((rc = sl_mixture_inflow_create(sc, x->tr, open, x->phi_max, &x->inflow_bc, d))) return rc;
  x->closed = sl_flow_closed(fl);
  if ((rc = periodic_setup(x, open, pairs, n_pairs, d))) return rc;
  const double *area = sl_transport_face_areas(x->tr);
  for (int f = 0; f < nf; ++f) x->area_max = fmax(x->area_max, area[f]);
  x->phi = malloc((size_t)nc * sizeof *x->phi);
  x->trial = malloc((size_t)nc * sizeof *x->trial);
  x->q = malloc((size_t)nf * sizeof *x->q);
  x->w = calloc((size_t)nf, sizeof *x->w);
  x->q_acc = calloc((size_t)nf, sizeof *x->q_acc);
  x->phi_flow = malloc((size_t)nc * sizeof *x->phi_flow);
  x->q_pred = calloc((size_t)nf, sizeof *x->q_pred);
  if (!x->phi || !x->trial || !x->q || !x->w || !x->q_acc || !x->phi_flow || !x->q_pred)
    return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  if (x->slip_acceleration) {
    x->acc = calloc((size_t)2 * nc, sizeof *x->acc);
    x->b_face = malloc((size_t)2 * nf * sizeof *x->b_face);
    if (!x->acc || !x->b_face) return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  }
  if (x->st.c) {
    sl_transport_settling_field(x->tr, body_direction, x, x->w);
    set_flux_floor(x);
  }
  if (x->rho_solid != x->rho_f && (hypot(x->g[0], x->g[1]) > 0.0 || x->omega != 0.0)) {
    x->cell_drag = malloc((size_t)4 * nc * sizeof *x->cell_drag);
    x->grad_phi = malloc((size_t)2 * nc * sizeof *x->grad_phi);
    if (!x->cell_drag || !x->grad_phi) return sl_diag_set(d, SL_EFAILED, "mixture: out of memory");
  }
  if ((rc = migration_setup(x, d))) return rc;
  if ((rc = initial_phi(x, d))) return rc;
  memcpy(x->phi_flow, x->phi, (size_t)nc * sizeof *x->phi_flow);
  x->inventory = x->inventory0 = sl_transport_mass(x->tr, x->phi);
  if ((rc = hydrostatic_setup(x, open, d))) return rc;
  if (x->relative_flux_stress && (rc = stress_setup(x, d))) return rc;
  /* interface levels */
  const sl_src *le = sl_scene_src(sc, &sc->output.interface);
  if (le) {
    x->n_levels = sc->output.interface.n;
    for (int k = 0; k < x->n_levels; ++k) x->level[k] = sc->output.interface.v[k];
    if (x->n_levels > 0 && hypot(x->g[0], x->g[1]) == 0.0)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s:%d: [output] interface: heights are measured against gravity, and the "
                         "scene has none",
                         le->file, le->line);
  }
  return inventory_setup(x, d);
}

static int advance(mixture *x, double t, double dt, const double *u, const double *dudt, sl_diag *d) {
  if (x->st.c && x->slip_acceleration) { /* the slip of this step follows the acceleration at its end */
    cell_accelerations(x, u, dudt);
    sl_transport_settling_faces(x->tr, x->b_face, x->w);
    set_flux_floor(x);
  }
  /* the divergence is measured against the through-flow, or against the settling flux and 1e-8 of the
   * largest speed where the mixture hardly moves across faces (a swirl, a closed column) */
  double umax = 0.0;
  for (int32_t i = 0; i < x->th->p_offset; ++i) umax = fmax(umax, fabs(u[i]));
  int rc =
      sl_face_flux_conservative(x->ff, u, fmax(x->flux_floor, 1e-8 * umax * x->area_max), x->q, &x->trial_raw_div, d);
  if (rc) return rc;
  memcpy(x->trial, x->phi, (size_t)x->m->n_cells * sizeof *x->trial);
  if (x->mig_c) { /* the shear rate of the new velocity drives the migration over the step */
    if ((rc = sl_flow_cell_diagnostics(x->th, u, x->flow, 0.0, x->shear, NULL, NULL, d)) ||
        (rc = sl_migration_set_shear_rate(x->mg, x->shear, d)))
      return rc;
  }
  if ((rc = sl_mixture_inflow_update(x->inflow_bc, t + dt, d))) return rc;
  sl_transport_stats st;
  rc = sl_transport_step(x->tr, dt, x->q, x->st.c ? x->w : NULL, x->trial, &st, d);
  if (rc) return sl_diag_prefix(d, SL_EFAILED, "solids transport from t = %.6g over dt = %.3g", t, dt);
  x->trial_substeps = st.n_substeps, x->trial_fallbacks = st.n_fallbacks;
  x->trial_inflow = st.boundary_inflow;
  sl_mixture_inflow_stepped(x->inflow_bc);
  x->max_div = fmax(x->max_div, st.max_divergence);
  return x->relative_flux_stress ? stress_of(x, x->trial, d) : 0;
}

static int unchanged(void *user) { return ((const mixture *)user)->unchanged; }

static void accept(mixture *x) {
  x->unchanged = memcmp(x->phi, x->trial, (size_t)x->m->n_cells * sizeof *x->phi) == 0;
  memcpy(x->phi, x->trial, (size_t)x->m->n_cells * sizeof *x->phi);
  memcpy(x->phi_flow, x->phi, (size_t)x->m->n_cells * sizeof *x->phi_flow);
  memcpy(x->q_acc, x->q, (size_t)x->m->n_faces * sizeof *x->q_acc);
  x->inflow += x->trial_inflow;
  sl_mixture_inflow_accept(x->inflow_bc);
  x->inventory = sl_transport_mass(x->tr, x->phi);
  x->substeps += x->trial_substeps, x->fallbacks += x->trial_fallbacks, ++x->advances;
  x->max_raw_div = fmax(x->max_raw_div, x->trial_raw_div);
  if (x->relative_flux_stress) node_stress_of(x);
  hydrostatic_update(x);
}

static int write(mixture *x, sl_output *out, sl_diag *d) {
  int rc = x->fields & F_PHI ? sl_output_write_field(out, "phi", SL_CENTRE_CELL, 1, x->phi, d) : 0;
  double inv = sl_transport_mass(x->tr, x->phi);
  double err = x->inventory0 + x->inflow > 0.0 ? (inv - x->inventory0 - x->inflow) / (x->inventory0 + x->inflow) : 0.0;
  /* the solids volume per unit depth (planar) or per radian (axisymmetric) */
  if (!rc) rc = sl_output_write_scalar_unit(out, "solids_inventory", x->axi ? "m^3/rad" : "m^2", inv, d);
  if (!rc) rc = sl_output_write_scalar(out, "solids_conservation_error", err, d);
  if (!rc) rc = sl_mixture_inflow_write(x->inflow_bc, out, x->axi, d);
  for (int k = 0; k < x->n_inv && !rc; ++k) {
    const unsigned char *mask = x->inv_mask + (size_t)k * x->m->n_cells;
    for (int c = 0; c < x->m->n_cells; ++c) x->inv_phi[c] = mask[c] ? x->phi[c] : 0.0;
    rc = sl_output_write_scalar_unit(out, x->inv_name[k], x->axi ? "m^3/rad" : "m^2",
                                     sl_transport_mass(x->tr, x->inv_phi), d);
  }
  for (int k = 0; k < x->n_levels && !rc; ++k) {
    char name[64];
    snprintf(name, sizeof name, "interface_height_%d", k);
    rc = sl_output_write_scalar(out, name, interface_height(x, x->phi, x->level[k]), d);
    snprintf(name, sizeof name, "interface_level_%d", k);
    if (!rc) rc = sl_output_write_scalar(out, name, x->level[k], d);
  }
  return rc;
}

static int checkpoint(mixture *x, sl_checkpoint_array *a, int max) {
  if (max < 2) return 0;
  snprintf(a[0].name, sizeof a[0].name, "phi");
  a[0].n = x->m->n_cells, a[0].data = x->phi;
  x->book[0] = x->inventory0, x->book[1] = x->inflow;
  snprintf(a[1].name, sizeof a[1].name, "solids_book");
  a[1].n = 2, a[1].data = x->book;
  int n = 2 + sl_mixture_inflow_checkpoint(x->inflow_bc, a + 2, max - 2);
  if (!x->relative_flux_stress || max < n + 1) return n;
  /* it holds the slip direction of the last step, which phi alone does not give */
  snprintf(a[n].name, sizeof a[n].name, "relative_flux_stress");
  a[n].n = 6 * (int64_t)x->th->pres->n_dofs, a[n].data = x->node_stress;
  return n + 1;
}

static int restore(mixture *x, const sl_checkpoint *ck, sl_diag *d) {
  const sl_checkpoint_array *p = sl_checkpoint_find(ck, "phi"), *b = sl_checkpoint_find(ck, "solids_book");
  if (!p || p->n != x->m->n_cells || !b || b->n != 2)
    return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no solids fraction of %d cells", x->m->n_cells);
  memcpy(x->phi, p->data, (size_t)p->n * sizeof *x->phi);
  memcpy(x->phi_flow, x->phi, (size_t)p->n * sizeof *x->phi_flow);
  x->inventory0 = b->data[0], x->inflow = b->data[1];
  sl_mixture_inflow_restore(x->inflow_bc, sl_checkpoint_find(ck, "solids_through"));
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

static void mixture_free(mixture *x) {
  sl_transport_destroy(x->tr);
  sl_mixture_inflow_destroy(x->inflow_bc);
  sl_face_flux_destroy(x->ff);
  free(x->phi), free(x->trial), free(x->q), free(x->w), free(x->q_acc), free(x->acc), free(x->b_face);
  free(x->phi_flow), free(x->q_pred);
  free(x->cell_stress), free(x->settle_speed), free(x->node_stress), free(x->node_weight);
  free(x->cell_drag), free(x->grad_phi), free(x->buoy_phi), free(x->p_hydro);
  sl_hydrostatic_destroy(x->hs);
  sl_point_release(&x->st.pc);
  sl_migration_destroy(x->mg);
  free(x->shear);
  free(x->inv_mask), free(x->inv_phi);
  sl_point_release(&x->mig), sl_point_release(&x->visc);
  sl_flow_destroy(x->flow_model);
  free(x);
}

/* ---- the schema ------------------------------------------------------------------------ */

#define TABLE(name, keys) static const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}
#define M(field) SL_AT_MODEL(mixture_config, field)

static const sl_key solid_keys[] = {
    {.section = "solid",
     .name = "density",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.density),
     .flags = SL_KEY_REQUIRED,
     .min = 1e-3,
     .max = 1e5,
     .units = "kg m^-3",
     .help = "particle density"},
    {.section = "solid",
     .name = "diameter",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.diameter),
     .min = 1e-9,
     .max = 1.0,
     .units = "m",
     .def_doc = "required by closures with the input d_p",
     .help = "particle diameter"},
    {.section = "solid",
     .name = "phi_max",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.phi_max),
     .def = 0.64,
     .min = 0.01,
     .max = 1.0,
     .def_doc = "the settling closure's phi_max, else 0.64",
     .help = "maximum packing fraction"},
    {.section = "solid",
     .name = "sphericity",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.sphericity),
     .def = 1.0,
     .min = 0.01,
     .max = 1.0,
     .help = "particle sphericity"},
    {.section = "solid",
     .name = "vessel_diameter",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.vessel_diameter),
     .min = 1e-6,
     .max = 1e6,
     .units = "m",
     .def_doc = "none (no wall term)",
     .help = "the vessel (column, pipe) diameter D a settling law's wall term d/D uses (Richardson & Zaki 1954)"},
};
TABLE(mixture_solid_keys, solid_keys);

static const sl_key mixture_keys[] = {
    {.section = "mixture",
     .name = "slip_acceleration",
     .type = SL_KEY_BOOL,
     M(slip_acceleration),
     .help = "the slip follows g - Dj/Dt (Nigam 1999 eq 2.25), not only gravity and the frame's centrifugal force"},
    {.section = "mixture",
     .name = "reference_acceleration",
     .type = SL_KEY_REAL,
     M(reference_acceleration),
     .min = 1e-12,
     .max = 1e12,
     .units = "m s^-2",
     .def_doc = "|g|, else the frame's largest centrifugal acceleration, else 1",
     .help = "the acceleration the settling closure is evaluated at"},
    {.section = "mixture",
     .name = "diffusivity",
     .type = SL_KEY_REAL,
     M(diffusivity),
     .min = 0.0,
     .max = 1e6,
     .units = "m^2 s^-1",
     .help = "particle diffusivity eps: the flux -eps grad(phi) (Lalli 1993)"},
    {.section = "mixture",
     .name = "relative_flux_stress",
     .type = SL_KEY_BOOL,
     M(relative_flux_stress),
     .help = "the momentum carries the stress rho_f j_R j_R / (phi (1 - phi)) of the settling flux (Nigam 1999 eq "
             "2.16)"},
};
TABLE(mixture_model_keys, mixture_keys);

static const sl_key transport_keys[] = {
    {.section = "transport",
     .name = "order",
     .type = SL_KEY_INT,
     M(order),
     .def = 2,
     .min = 1,
     .max = 2,
     .help = "1: Godunov, 2: MUSCL (second order)"},
    {.section = "transport",
     .name = "limiter",
     .type = SL_KEY_CHOICE,
     M(limiter),
     .choices = "mc|minmod",
     .help = "the slope limiter of order 2"},
    {.section = "transport",
     .name = "cfl",
     .type = SL_KEY_REAL,
     M(cfl),
     .def = 0.9,
     .min = 1e-3,
     .max = 1.0,
     .help = "fraction of the stable explicit sub-step"},
    {.section = "transport",
     .name = "table_points",
     .type = SL_KEY_INT,
     M(table_points),
     .def = 2049,
     .min = 17,
     .max = 1000001,
     .help = "nodes of the settling-flux table"},
};
TABLE(mixture_transport_keys, transport_keys);

static const sl_key extra_keys[] = {
    {.section = "initial",
     .name = "phi",
     .type = SL_KEY_EXPR,
     M(phi),
     .vars = "x,y",
     .flags = SL_KEY_REQUIRED,
     .help = "the initial solids fraction at the cell centroids"},
    {.section = "output",
     .name = "interface",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(output.interface),
     .max_n = SL_REALS_MAX,
     .min = 0.0,
     .max = 1.0,
     .help = "levels of phi whose heights (along -g) are written as interface_height_K"},
    {.section = "output",
     .name = "inventory_regions",
     .type = SL_KEY_STRING,
     M(inventory_regions),
     .def_text = "",
     .help = "mesh regions (Gmsh physical surfaces, comma-separated) whose solids volume int phi dV is written "
             "as solids_inventory_NAME"},
    {.section = "output",
     .name = "inventory_where",
     .type = SL_KEY_EXPRS,
     M(inventory_where),
     .vars = "x,y",
     .max_n = 3,
     .help = "regions as expressions of x, y (a cell counts where its centroid gives > 0), their solids "
             "volume written as solids_inventory_where_K"},
    {.section = "boundary",
     .name = "phi",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(ns_boundary, phi),
     .vars = "x,y,t",
     .when_type = (1u << NS_OPEN) | (1u << NS_PRESSURE) | (1u << NS_TRACTION) | (1u << NS_VELOCITY),
     .def_doc = "0",
     .help = "the solids fraction of what flows in, an expression of x, y, t along the boundary (in [0, phi_max]); "
             "a velocity boundary lets solids through only when it gives phi"},
};
TABLE(mixture_extra_keys, extra_keys);

static const char *const mixture_fields[] = {"velocity", "pressure",        "shear_rate", "viscosity",
                                             "yielded",  "stream_function", "phi"};

const sl_schema sl_mixture_schema = {
    .model = "mixture",
    .title = "drift-flux mixture model",
    .summary =
        "The flow in the volume-averaged velocity j (div j = 0) with the mixture's density and viscosity, "
        "carrying a solids fraction phi moved by j plus a hindered-settling flux (Nigam 1999, eqs 2.31-2.36), "
        "shear-induced migration (Phillips et al. 1992) and a particle diffusivity; bounded, conservative "
        "finite-volume transport with face fluxes from the flow; the slip along the fluid's acceleration in "
        "a rotating frame.",
    .tables = {&sl_keys_scene, &sl_flow_keys_scene, &sl_keys_mesh, &sl_keys_fluid, &mixture_solid_keys,
               &sl_flow_keys_flow, &sl_flow_keys_time, &sl_flow_keys_solver, &sl_keys_output, &sl_keys_plugins,
               &sl_flow_keys_boundary, &sl_flow_keys_initial, &mixture_extra_keys, &mixture_model_keys,
               &mixture_transport_keys},
    .n_tables = 15,
    .roles = {{"viscosity", 0, "the suspension's viscosity of phi and the shear rate (none: [fluid] viscosity)"},
              {"hindered_settling", 0, "the settling velocity of phi (none: no settling)"},
              {"migration", 0, "shear-induced migration, D_c and D_mu of phi and the shear rate"}},
    .n_roles = 3,
    .config_size = sizeof(mixture_config),
    .boundary_size = sizeof(ns_boundary),
    .fields = mixture_fields,
    .n_fields = 7,
};

/* ---- ops: the flow and the solids fraction ------------------------------------------------ */

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int mx_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  if (sc->time.scheme == SL_SCHEME_STEADY)
    return sl_diag_set(d, SL_EBADINPUT, "[time] scheme = steady: the mixture model is transient (bdf1 or bdf2)");
  mixture *x = calloc(1, sizeof *x);
  if (!x) return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  x->sc = sc, x->cfg = sc->config, x->rho_solid = sc->solid.density, x->phi_max = sc->solid.phi_max;
  unsigned mask, def = 1u | 2u | (sl_scene_closure(sc, "viscosity") ? 4u | 8u | 16u : 0u) | SL_FLOW_STREAM_FUNCTION |
                       (1u << SL_FLOW_N_FIELDS);
  int rc = sl_scene_output_fields(sc, def, &mask, d);
  if (!rc)
    rc = sl_flow_create(sc, &x->cfg->flow, x->rho_solid, mask & ((1u << SL_FLOW_N_FIELDS) - 1u), &x->flow_model, info,
                        d);
  if (!rc) rc = mixture_setup(x, x->flow_model, mask >> SL_FLOW_N_FIELDS, d);
  /* the initial velocity's fluxes until the first step: the stream function written at t = 0 is [initial]
     velocity's */
  if (!rc && x->ff) rc = sl_face_flux_conservative(x->ff, info->u, 0.0, x->q_acc, NULL, d);
  if (rc) {
    mixture_free(x);
    return rc;
  }
  sl_flow_rider rider = {.rho_solid = x->rho_solid,
                         .phi = x->phi_flow,
                         .extra_stress = x->extra_stress,
                         .user = x,
                         .cell_drag = x->cell_drag,
                         .prepare = x->cell_drag ? prepare : NULL,
                         .buoyant_phi = x->hs ? x->buoy_phi : x->phi, /* the accepted phi (predict_transport) */
                         .pressure_shift = x->hs ? x->p_hydro : NULL,
                         .face_flux = x->q_acc,
                         .unchanged = unchanged,
                         .at_rest = at_rest};
  sl_flow_ride(x->flow_model, &rider);
  info->has_steady = 0;
  *self = x;
  return 0;
}

static int mx_step(void *self, sl_step *s, int *iterations, sl_diag *d) {
  mixture *x = self;
  return sl_flow_step(x->flow_model, s, iterations, d);
}

/* After the flow's step passed its error test: phi over the step. A failed transport rejects the step. */
static int mx_complete(void *self, const sl_step *s, sl_diag *d) {
  mixture *x = self;
  double c0 = cpu_now();
  int rc = advance(x, s->t, s->dt, s->u, s->dudt, d);
  x->cpu_coupled += cpu_now() - c0;
  return sl_step_code(rc);
}

static void mx_accept(void *self, const sl_step *s, int *steady) {
  (void)s, (void)steady;
  mixture *x = self;
  accept(x);
  sl_flow_accept(x->flow_model);
}

static int mx_write_mesh(void *self, sl_output *out, sl_diag *d) {
  return sl_flow_write_mesh(((mixture *)self)->flow_model, out, d);
}

static int mx_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)t;
  mixture *x = self;
  int rc = sl_flow_write(x->flow_model, out, u, d);
  return rc ? rc : write(x, out, d);
}

static int mx_checkpoint(void *self, sl_checkpoint_array *a, int max) {
  mixture *x = self;
  int n = sl_flow_checkpoint(x->flow_model, a, max);
  return n + checkpoint(x, a + n, max - n);
}

static int mx_restore(void *self, const sl_checkpoint *ck, sl_diag *d) {
  mixture *x = self;
  int rc = sl_flow_restore(x->flow_model, ck, d);
  return rc ? rc : restore(x, ck, d);
}

static void mx_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  (void)res;
  mixture *x = self;
  sl_flow_stats(x->flow_model, st);
  st->cpu_coupled = x->cpu_coupled;
  if (x->tr) {
    double inv = x->inventory, base = x->inventory0 + x->inflow;
    snprintf(st->coupling_summary, sizeof st->coupling_summary,
             "solids: %ld transport sub-steps (%.1f per step, %ld at first order), conservation error %.1e, "
             "raw face-flux divergence up to %.1e",
             x->substeps, x->advances ? (double)x->substeps / (double)x->advances : 0.0, x->fallbacks,
             base > 0.0 ? (inv - base) / base : 0.0, x->max_raw_div);
  }
}

static void mx_destroy(void *self) { mixture_free(self); }

const sl_model_ops sl_mixture_ops = {.setup = mx_setup,
                                     .step = mx_step,
                                     .complete = mx_complete,
                                     .accept = mx_accept,
                                     .write_mesh = mx_write_mesh,
                                     .write = mx_write,
                                     .checkpoint = mx_checkpoint,
                                     .restore = mx_restore,
                                     .stats = mx_stats,
                                     .destroy = mx_destroy};
