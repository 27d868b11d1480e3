/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's set-up, steady solve, output and summary (pipe.h). */
#include "core/models/pipe/pipe.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"

/* The geometric ratio sl_mesh_graded_points takes (h_last/h_first, the last cell at the
   wall) for n cells over R with the wall cell w: t = h_{i}/h_{i+1} solves sum_{i<n} t^i = R/w (bisection in
   log t; t = 1 is the uniform grid). */
static double wall_grading(double R, double w, int n) {
  double target = R / w, lo = -50.0, hi = 20.0 / n;
  if (fabs(target - n) < 1e-12 * n) return 1.0;
  for (int it = 0; it < 200; ++it) {
    double m = 0.5 * (lo + hi), t = exp(m), s = 0.0, p = 1.0;
    for (int i = 0; i < n && s <= target; ++i) s += p, p *= t;
    if (s > target) hi = m;
    else lo = m;
  }
  double t = exp(0.5 * (lo + hi));
  return pow(t, -(double)(n - 1));
}

static void release(pipe *p) {
  if (!p) return;
  release(p->other);
  double **a[] = {&p->uf,    &p->us,        &p->phi,      &p->k,        &p->eps, &p->theta, &p->mu_t,
                  &p->mu_tk, &p->mu_te,     &p->eps_prod, &p->eps_sink, &p->K,   &p->mu_s,  &p->rhs,
                  &p->x,     &p->face_flux, &p->Kd,       &p->slip0,    &p->ks,  &p->kfs,   &p->eps_s};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) free(*a[i]);
  for (int i = 0; i < PIPE_NBUF; ++i) free(p->buf[i]);
  sl_point_closure *pc[] = {&p->turb, &p->wallf, &p->drag, &p->gran, &p->psol, &p->walls, &p->lift, &p->disp, &p->modu};
  for (size_t i = 0; i < sizeof pc / sizeof pc[0]; ++i) sl_point_release(pc[i]);
  pipe_march_release(p);
  sl_cell_scalar_free(&p->cs);
  sl_csr_free(&p->A);
  sl_linsolve_destroy(p->ls);
  sl_fv_grid_free(&p->g);
  sl_tensor_grid_free(&p->tg);
  sl_mesh_destroy(p->mesh);
  free(p);
}

/* Churchill (1977), the Fanning friction factor of a smooth pipe (Krampa 2009 eqs 2.12-2.13 with k = 0). */
static double churchill(double Re) {
  double A = pow(-2.457 * log(pow(7.0 / Re, 0.9)), 16.0), B = pow(37530.0 / Re, 16.0);
  return 2.0 * pow(pow(8.0 / Re, 12.0) + pow(A + B, -1.5), 1.0 / 12.0);
}

static int build_grid(pipe *p, sl_diag *d) {
  const pipe_config *c = p->cfg;
  int n = p->n;
  double w = sl_scene_given(p->sc, &c->wall_cell) ? c->wall_cell : p->R / n;
  char at[400], at2[400];
  if (sl_scene_given(p->sc, &c->wall_y_plus)) {
    if (sl_scene_given(p->sc, &c->wall_cell))
      return sl_diag_set(d, SL_EBADINPUT, "%s and %s: give one of the two",
                         sl_scene_where(p->sc, &c->wall_cell, at, sizeof at),
                         sl_scene_where(p->sc, &c->wall_y_plus, at2, sizeof at2));
    double V = c->bulk_velocity, nu = p->mu_f / p->rho_f, ut = V * sqrt(0.5 * churchill(V * c->diameter / nu));
    w = 2.0 * c->wall_y_plus * nu / ut;
  }
  if (w > 0.5 * p->R)
    return sl_diag_set(d, SL_EBADINPUT, "%s = %g: the wall cell must be at most half the radius, %g",
                       sl_scene_where(p->sc, &c->wall_cell, at, sizeof at), w, 0.5 * p->R);
  sl_grid_opts o = {.cell_type = SL_CELL_QUAD4, .grade_x = {SL_GRADE_GEOMETRIC, wall_grading(p->R, w, n)}};
  if (o.grade_x.ratio == 1.0) o.grade_x.kind = SL_GRADE_UNIFORM;
  int rc = sl_mesh_rectangle(0.0, p->R, 0.0, 0.1 * p->R, n, 1, &o, &p->mesh, d);
  if (!rc) rc = sl_tensor_grid_from_mesh(p->mesh, &p->tg, d);
  const int periodic[2] = {0, 1};
  if (!rc) rc = sl_fv_grid_build(&p->g, &p->tg, 1, periodic, d);
  return rc;
}

/* One section of the pipe with gravity gz along its flow. */
static int pipe_create(sl_scene *sc, double gz, pipe **out, sl_diag *d) {
  *out = NULL;
  pipe *p = calloc(1, sizeof *p);
  if (!p) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  p->sc = sc, p->cfg = sc->config;
  const pipe_config *c = p->cfg;
  char at[400];
  p->n = (int)c->cells, p->R = 0.5 * c->diameter, p->gz = gz;
  p->phi_target = c->solids_fraction;
  p->rho_f = sc->fluid.density, p->mu_f = sc->fluid.viscosity;
  p->rho_s = sc->solid.density, p->d_p = sc->solid.diameter, p->phi_max = sc->solid.phi_max;
  p->two_phase = c->solids_fraction > 0.0;
  int rc = 0;
  if (p->two_phase && c->solids_fraction > p->phi_max - 0.01)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s = %g: at most [solid] phi_max - 0.01 = %g",
                     sl_scene_where(sc, &c->solids_fraction, at, sizeof at), c->solids_fraction, p->phi_max - 0.01);
  if (!rc && p->two_phase && !sl_scene_closure(sc, "drag"))
    rc = sl_diag_set(d, SL_EBADINPUT, "%s = %g: a slurry needs [closure.drag] (e.g. model = gidaspow)",
                     sl_scene_where(sc, &c->solids_fraction, at, sizeof at), c->solids_fraction);
  if (!rc && c->solids_wall == PIPE_WALL_STRESS && !sl_scene_closure(sc, "wall_stress.solids"))
    rc = sl_diag_set(d, SL_EBADINPUT, "%s = wall_stress needs [closure.wall_stress.solids]",
                     sl_scene_where(sc, &c->solids_wall, at, sizeof at));
  if (!rc && c->solids_wall != PIPE_WALL_STRESS && sl_scene_closure(sc, "wall_stress.solids"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "[closure.wall_stress.solids] is read with [pipe] solids_wall = wall_stress "
                     "only; did you mean solids_wall = wall_stress?");
  if (!rc && c->solids_viscosity == PIPE_SOLIDS_VISCOSITY_PEIRANO_LECKNER && sl_scene_closure(sc, "granular"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s = peirano_leckner is Krampa's model C, whose collisional viscosity replaces the kinetic "
                     "theory's: remove [closure.granular]",
                     sl_scene_where(sc, &c->solids_viscosity, at, sizeof at));
  if (!rc && c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED &&
      c->solids_viscosity != PIPE_SOLIDS_VISCOSITY_PEIRANO_LECKNER)
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s = transported carries the k_s and k_fs of Krampa's model C, whose solids viscosity they set: "
                     "did you mean to add [pipe] solids_viscosity = peirano_leckner?",
                     sl_scene_where(sc, &c->solids_turbulence, at, sizeof at));
  if (!rc && c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED && !p->two_phase)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s = transported needs solids: [pipe] solids_fraction > 0",
                     sl_scene_where(sc, &c->solids_turbulence, at, sizeof at));
  if (!rc && c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_K_EPSILON &&
      (c->solids_viscosity != PIPE_SOLIDS_VISCOSITY_EDDY || !p->two_phase || c->length > 0.0))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s = k_epsilon is the solids' k_s-eps_s of Krampa's models A and B, which replaces the solids' "
                     "eddy viscosity: it needs solids ([pipe] solids_fraction > 0), [pipe] solids_viscosity = eddy and "
                     "the fully developed pipe (no [pipe] length); with solids_viscosity = peirano_leckner the choices "
                     "are equilibrium or transported",
                     sl_scene_where(sc, &c->solids_turbulence, at, sizeof at));
  if (!rc && c->wall_normal_stress == PIPE_NORMAL_CONTACT_KINETIC && !sl_scene_closure(sc, "granular"))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s = contact_kinetic adds the kinetic theory's pressure: the scene has no [closure.granular] "
                     "(allowed without it: contact)",
                     sl_scene_where(sc, &c->wall_normal_stress, at, sizeof at));
  if (!rc && c->pressure_gradient.n && c->length > 0.0)
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s: the developing pipe carries its inlet's flow rate, station by station: remove [pipe] "
                     "length or pressure_gradient",
                     sl_scene_where(sc, &c->pressure_gradient, at, sizeof at));
  if (!rc && c->loop && (c->pressure_gradient.n || c->length > 0.0))
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s = true: the loop's two sections share one bulk velocity and are fully developed: remove "
                     "[pipe] %s",
                     sl_scene_where(sc, &c->loop, at, sizeof at),
                     c->pressure_gradient.n ? "pressure_gradient" : "length");
  if (!rc) rc = build_grid(p, d);
  const int n = p->n;
  if (!rc) {
    double **a[] = {&p->uf,       &p->us,       &p->phi, &p->k,    &p->eps, &p->theta, &p->mu_t, &p->mu_tk, &p->mu_te,
                    &p->eps_prod, &p->eps_sink, &p->K,   &p->mu_s, &p->Kd,  &p->slip0, &p->ks,   &p->kfs,   &p->eps_s};
    for (size_t i = 0; i < sizeof a / sizeof a[0] && !rc; ++i)
      if (!(*a[i] = calloc((size_t)n, sizeof(double)))) rc = sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
    for (int i = 0; i < PIPE_NBUF && !rc; ++i)
      if (!(p->buf[i] = calloc((size_t)n, sizeof(double)))) rc = sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  }
  if (!rc && !(p->face_flux = calloc((size_t)p->g.nf, sizeof(double))))
    rc = sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  if (!rc) rc = pipe_closures_bind(p, d);
  if (!rc) rc = sl_cell_scalar_init(&p->cs, &p->g, d);
  if (!rc) rc = pipe_momentum_init(p, d);
  if (!rc && sl_scene_given(sc, &c->length)) rc = pipe_march_setup(p, d);
  if (rc) {
    release(p);
    return rc;
  }
  /* the initial state: the 1/7 power law, a turbulence intensity of 5 %, a mixing length of 0.07 D */
  const double V = c->bulk_velocity, k0 = 1.5 * (0.05 * V) * (0.05 * V), l0 = 0.07 * c->diameter;
  for (int i = 0; i < n; ++i) {
    double r = p->g.xc[i];
    p->uf[i] = p->us[i] = V * (60.0 / 49.0) * pow(1.0 - r / p->R, 1.0 / 7.0);
    p->k[i] = k0, p->eps[i] = pow(0.09, 0.75) * pow(k0, 1.5) / l0;
    p->phi[i] = c->solids_fraction, p->theta[i] = 1e-4;
  }
  *out = p;
  return 0;
}

static int pipe_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  const pipe_config *c = sc->config;
  double gz = sc->flow.gravity.n ? sc->flow.gravity.v[0] : -9.81;
  pipe *p;
  int rc = pipe_create(sc, gz, &p, d);
  if (rc) return rc;
  if (c->loop && (rc = pipe_create(sc, -gz, &p->other, d))) {
    release(p);
    return rc;
  }
  *info = (sl_model_info){
      .integrator = SL_INTEGRATE_BDF, .n = p->n, .n_err = p->n, .u = p->uf, .has_steady = 1, .state_name = "velocity"};
  *self = p;
  return 0;
}

/* max |a - b| / max |b|, and the cell of the largest |a - b| in *at. */
static double rel_change(const double *a, const double *b, int n, int *at) {
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    if (fabs(a[i] - b[i]) > num) num = fabs(a[i] - b[i]), *at = i;
    den = fmax(den, fabs(b[i]));
  }
  return den > 0.0 ? num / den : num;
}

/* Outer iterations of the momentum (u_f, u_s, G), the turbulence and the solids fraction, each with the others'
   last values, until one changes them all by less than the tolerance (p->converged), or [pipe] iterations: the
   fully developed pipe's steady solve, and each station of the developing pipe's march (pipe_march.c). */
int pipe_converge(pipe *p, sl_diag *d) {
  const pipe_config *c = p->cfg;
  const int n = p->n;
  double *old[6] = {p->buf[8], p->buf[9], p->buf[10], p->buf[11], p->buf[12], p->buf[13]};
  const int ksfs = p->two_phase && c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED;
  const int kseps = p->two_phase && c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_K_EPSILON; /* models A, B */
  double *second = kseps ? p->eps_s : p->kfs; /* the solids' second turbulence field */
  int rc = 0;
  p->converged = 0;
  /* A stalled iteration (a limit cycle between the solids fraction, theta and the turbulence: 2.4 mm sand at
     30 % with the transported theta) is damped: when a window of iterations has not halved the change, the
     under-relaxation is halved (to 0.05 at least). The converged state does not depend on it. */
  const long window = 200;
  double window_change = INFINITY;
  p->relax = c->relaxation;
  for (long it = 1; it <= c->iterations && !rc; ++it) {
    memcpy(old[0], p->uf, (size_t)n * sizeof(double)), memcpy(old[1], p->k, (size_t)n * sizeof(double));
    memcpy(old[2], p->eps, (size_t)n * sizeof(double)), memcpy(old[3], p->phi, (size_t)n * sizeof(double));
    memcpy(old[4], p->ks, (size_t)n * sizeof(double)), memcpy(old[5], second, (size_t)n * sizeof(double));
    double G_old = p->G;
    if (p->march.on) pipe_march_fluxes(p);
    if (!rc) rc = pipe_turbulence_coefficients(p, d);
    if (!rc) rc = pipe_wall_function(p, d);
    if (!rc && p->two_phase) rc = pipe_solids_coefficients(p, d);
    if (!rc) rc = pipe_momentum_solve(p, d);
    if (!rc) rc = pipe_turbulence_update(p, d);
    if (!rc && ksfs) rc = pipe_ksfs_update(p, d);
    if (!rc && kseps) rc = pipe_kseps_update(p, d);
    if (!rc && p->two_phase) rc = pipe_solids_update(p, d);
    p->iterations = it;
    if (rc) break;
    static const char *const names[7] = {"u_f", "k", "epsilon", "phi", "k_s", "k_fs", "dP/dz"};
    const double *now[6] = {p->uf, p->k, p->eps, p->phi, p->ks, second};
    double ch = 0.0;
    for (int k = 0; k < (ksfs || kseps ? 6 : p->two_phase ? 4 : 3); ++k) {
      int at = 0;
      double chk = rel_change(now[k], old[k], n, &at);
      if (chk > ch) ch = chk, p->change_field = k == 5 && kseps ? "eps_s" : names[k], p->change_cell = at;
    }
    double cG = fabs(p->G - G_old) / fmax(fabs(p->G), 1e-300);
    if (cG > ch) ch = cG, p->change_field = names[6], p->change_cell = -1;
    p->change = ch;
    for (int i = 0; i < n; ++i)
      if (!isfinite(p->uf[i]) || !isfinite(p->us[i]) || !isfinite(p->k[i]) || !isfinite(p->eps[i]) ||
          !isfinite(p->phi[i]))
        rc = sl_diag_set(d, SL_EFAILED, "pipe: the solution is not finite at r = %g after %ld iterations", p->g.xc[i],
                         it);
    if (!rc && it > 2 && ch < c->tolerance) {
      p->converged = 1;
      break;
    }
    if (it % window == 0) {
      if (ch > 0.5 * window_change && p->relax > 0.05) p->relax = fmax(0.5 * p->relax, 0.05);
      window_change = ch;
    }
  }
  return rc;
}

/* The steady solve: pipe_converge for the fully developed pipe, the march along z for the developing one. */
static int pipe_steady(void *self, double *u, long *steps, long *its, sl_diag *d) {
  pipe *p = self;
  const pipe_config *c = p->cfg;
  const int n = p->n;
  int rc = p->march.on ? pipe_march_solve(p, d) : p->other ? pipe_loop_solve(p, d) : pipe_converge(p, d);
  /* the last coefficients and wall stresses of the state reached (the loop's: of both sections) */
  for (pipe *q = p; q && !rc; q = q->other) {
    rc = pipe_turbulence_coefficients(q, d);
    if (!rc) rc = pipe_wall_function(q, d);
    if (!rc && q->two_phase) rc = pipe_solids_coefficients(q, d);
  }
  *steps = 1, *its = p->iterations;
  if (u != p->uf) memcpy(u, p->uf, (size_t)n * sizeof(double));
  if (!rc && !p->converged) {
    char where[96] = "";
    if (p->change_field && p->change_cell >= 0)
      snprintf(where, sizeof where, ", most in %s at r/R = %.3f", p->change_field, p->g.xc[p->change_cell] / p->R);
    else if (p->change_field) snprintf(where, sizeof where, ", most in %s", p->change_field);
    /* a discontinuous drag under a cell has no steady state there: say so (pipe_drag_jump) */
    double jump = 0.0;
    int jc = -1;
    const char *across = NULL;
    for (pipe *q = p; q && !rc && jc < 0; q = q->other) rc = pipe_drag_jump(q, &jump, &jc, &across, d);
    if (rc) return rc;
    int w;
    if (jc >= 0)
      w = snprintf(p->stop_reason, sizeof p->stop_reason,
                   "not converged: %ld iterations changed the state by %.3g > tolerance %.3g%s; [closure.drag] K jumps "
                   "%.2g %% within 0.1 %% of the %s at r/R = %.3f: no steady state there",
                   p->iterations, p->change, c->tolerance, where, 100.0 * jump, across, p->g.xc[jc] / p->R);
    else
      w = snprintf(p->stop_reason, sizeof p->stop_reason,
                   "not converged: %ld iterations ([pipe] iterations) changed the state by %.3g > tolerance %.3g%s "
                   "(relaxation %.3g)",
                   p->iterations, p->change, c->tolerance, where, p->relax);
    /* the reason fills the run summary's fixed line (include/sluice/sluice.h): a cut one ends in "..." */
    if (w >= (int)sizeof p->stop_reason) memcpy(p->stop_reason + sizeof p->stop_reason - 4, "...", 4);
    rc = sl_diag_set(d, SL_EFAILED, "pipe: %s", p->stop_reason);
  } else if (!rc) {
    if (p->march.on)
      snprintf(p->stop_reason, sizeof p->stop_reason,
               "converged at each of %d stations along %g m: %ld iterations, at most %ld a station (last change %.2g)",
               p->march.nz, c->length, p->iterations, p->march.worst_station_iterations, p->change);
    else
      snprintf(p->stop_reason, sizeof p->stop_reason, "converged in %ld iterations (change %.2g)", p->iterations,
               p->change);
    if (p->relax < c->relaxation) {
      size_t L = strlen(p->stop_reason);
      snprintf(p->stop_reason + L, sizeof p->stop_reason - L, ", relaxation lowered to %.3g", p->relax);
    }
  }
  if (!rc && (p->y_plus < 30.0 || p->y_plus > 200.0) && !p->warned_yplus) {
    p->warned_yplus = 1;
    fprintf(stderr,
            "sluice: warning: pipe: the wall cell's centre is at y+ = %.3g, outside the wall function's 30-200 (Krampa "
            "2009 section 2.9): set [pipe] wall_cell or wall_y_plus\n",
            p->y_plus);
  }
  if (!rc && p->march.on && !p->warned_yplus) { /* the developing pipe: every station's wall cell */
    double lo = INFINITY, hi = 0.0;
    int at_lo = 0, at_hi = 0;
    for (int j = 0; j < p->march.nz; ++j) {
      if (p->march.y_plus[j] < lo) lo = p->march.y_plus[j], at_lo = j;
      if (p->march.y_plus[j] > hi) hi = p->march.y_plus[j], at_hi = j;
    }
    if (lo < 30.0 || hi > 200.0) {
      p->warned_yplus = 1;
      int j = lo < 30.0 ? at_lo : at_hi;
      fprintf(stderr,
              "sluice: warning: pipe: the wall cell's centre is at y+ = %.3g at z = %g m, outside the wall function's "
              "30-200 (Krampa 2009 section 2.9; y+ %.3g-%.3g along the pipe): set [pipe] wall_cell or wall_y_plus\n",
              lo < 30.0 ? lo : hi, p->march.g.yc[j], lo, hi);
    }
  }
  return rc;
}

/* ---- output ---------------------------------------------------------------------------- */

static int pipe_write_mesh(void *self, sl_output *out, sl_diag *d) {
  const pipe *p = self;
  const sl_mesh *m = p->march.on ? p->march.mesh : p->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * m->nv_per_cell * sizeof *cells);
  if (!cells) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  for (int i = 0; i < m->n_cells * m->nv_per_cell; ++i) cells[i] = m->cell_vertices[i];
  int rc = sl_output_write_mesh(out, 2, m->n_vertices, m->xy, m->n_cells, m->nv_per_cell, cells, "Quadrilateral", d);
  free(cells);
  return rc;
}

/* A cell field's value at radius r (linear between the cell centres, constant beyond the outer ones). */
static double at_radius(const pipe *p, const double *f, double r) {
  const double *xc = p->g.xc;
  if (r <= xc[0]) return f[0];
  for (int i = 0; i + 1 < p->n; ++i)
    if (r <= xc[i + 1]) return f[i] + (f[i + 1] - f[i]) * (r - xc[i]) / (xc[i + 1] - xc[i]);
  return f[p->n - 1];
}

static double loop_phi_mean(const pipe *p) {
  double A = 0.0, m = 0.0;
  for (int i = 0; i < p->n; ++i) A += p->g.vol[i], m += p->g.vol[i] * p->phi[i];
  return m / A;
}

static int pipe_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)t, (void)u;
  pipe *p = self;
  const pipe_config *c = p->cfg;
  const int n = p->n;
  unsigned mask;
  /* k_s and k_fs by default when transported; asked for with Tchen's, they are its equilibrium (pipe_ksfs.c) */
  const int tr = c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED;
  const int ke = c->solids_turbulence == PIPE_SOLIDS_TURBULENCE_K_EPSILON; /* k_s and eps_s (pipe_kseps_solid.c) */
  int rc = sl_scene_output_fields(p->sc, tr ? 0x1ffu : ke ? 0x2ffu : 0x7fu, &mask, d);
  if (!rc && !tr && !ke && p->two_phase && !p->march.on)
    for (int i = 0; i < n; ++i) pipe_ksfs_equilibrium(p, i, &p->ks[i], &p->kfs[i]);
  const double *fields[PIPE_NFIELDS] = {p->uf, p->us, p->phi, p->k, p->eps, p->mu_t, p->theta, p->ks, p->kfs, p->eps_s};
  if (!rc && p->march.on) rc = pipe_march_write(p, out, mask, d), mask = 0; /* its 2-D fields */
  for (int k = 0; k < PIPE_NFIELDS && !rc; ++k) {
    if (!(mask >> k & 1u)) continue;
    double *v = p->buf[0];
    for (int i = 0; i < n; ++i) v[p->tg.mesh_cell[i]] = fields[k][i];
    rc = sl_output_write_field(out, sl_pipe_schema.fields[k], SL_CENTRE_CELL, 1, v, d);
  }
  /* section means (area-weighted) and the chord average along a diameter (length-weighted) */
  double A = 0.0, phim = 0.0, chord = 0.0, flux_s = 0.0, usm = 0.0, ufm = 0.0;
  for (int i = 0; i < n; ++i) {
    A += p->g.vol[i], phim += p->g.vol[i] * p->phi[i], chord += p->g.hx[i] * p->phi[i];
    flux_s += p->g.vol[i] * p->phi[i] * p->us[i];
    usm += p->g.vol[i] * p->us[i], ufm += p->g.vol[i] * p->uf[i];
  }
  double tau = p->tau_fw + p->tau_sw, V = pipe_bulk_velocity(p), g = fabs(p->gz) > 0 ? fabs(p->gz) : 9.81;
  struct {
    const char *name;
    double v;
  } s[] = {{"pressure_gradient", -p->G},
           {"bulk_velocity", V},
           {"manometric_gradient", -p->G + p->rho_f * p->gz},
           {"wall_shear_stress_fluid", p->tau_fw},
           {"wall_shear_stress_solid", p->tau_sw},
           {"i_m", 4.0 * tau / (p->rho_f * g * c->diameter)},
           {"friction_factor", tau / (0.5 * p->rho_f * V * V)},
           {"reynolds", p->rho_f * V * c->diameter / p->mu_f},
           {"y_plus", p->y_plus},
           {"phi_mean", phim / A},
           {"phi_chord", chord / p->R},
           {"solids_mean_velocity", phim > 0.0 ? flux_s / phim : 0.0},
           {"velocity_solid_04", at_radius(p, p->us, 0.4 * p->R)},
           {"velocity_solid_08", at_radius(p, p->us, 0.8 * p->R)},
           {"velocity_solid_area_mean", usm / A},
           {"velocity_fluid_area_mean", ufm / A},
           {"phi_wall", p->phi[n - 1]},
           {"velocity_solid_wall", p->us[n - 1]},
           {"slip_length", p->inv_slip > 0.0 ? 1.0 / p->inv_slip : 0.0},
           {"wall_normal_stress_solid", p->p_wall},
           {"iterations", (double)p->iterations}};
  for (size_t k = 0; k < sizeof s / sizeof s[0] && !rc; ++k) rc = sl_output_write_scalar(out, s[k].name, s[k].v, d);
  if (!rc && p->other) { /* the loop (pipe_loop.c): both sections' in-situ fractions and manometric gradients */
    const pipe *up = p->gz < 0.0 ? p : p->other, *dn = p->gz < 0.0 ? p->other : p;
    double mu = -up->G + up->rho_f * up->gz, md = -dn->G + dn->rho_f * dn->gz;
    struct {
      const char *name;
      double v;
    } l[] = {{"loop_phi_mean_up", loop_phi_mean(up)},
             {"loop_phi_mean_down", loop_phi_mean(dn)},
             {"loop_manometric_gradient_up", mu},
             {"loop_manometric_gradient_down", md},
             {"loop_manometric_gradient_average", 0.5 * (mu + md)},
             {"loop_wall_shear_stress_up", up->tau_fw + up->tau_sw},
             {"loop_wall_shear_stress_down", dn->tau_fw + dn->tau_sw},
             {"loop_solids_flux", pipe_solids_flux(p)},
             {"loop_flux_mismatch", p->loop_flux_mismatch},
             {"loop_iterations", (double)p->loop_iterations}};
    for (size_t k = 0; k < sizeof l / sizeof l[0] && !rc; ++k) rc = sl_output_write_scalar(out, l[k].name, l[k].v, d);
  }
  return rc;
}

static void pipe_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  (void)res;
  pipe *p = self;
  st->converged = p->converged;
  st->correction = p->change;
  memcpy(st->stop_reason, p->stop_reason, sizeof st->stop_reason);
  if (p->ls) st->linear = *sl_linsolve_get_stats(p->ls), st->has_linear = 1;
  double tau = p->tau_fw + p->tau_sw, V = pipe_bulk_velocity(p);
  snprintf(st->coupling_summary, sizeof st->coupling_summary,
           "pipe: -dP/dz %.6g Pa/m (manometric %.6g), tau_w %.4g Pa (fluid %.4g, solids %.4g), f %.5g, y+ %.3g", -p->G,
           -p->G + p->rho_f * p->gz, tau, p->tau_fw, p->tau_sw, tau / (0.5 * p->rho_f * V * V), p->y_plus);
  if (p->other) {
    const pipe *u = p->gz < 0.0 ? p : p->other, *w = p->gz < 0.0 ? p->other : p;
    double mu = -u->G + u->rho_f * u->gz, md = -w->G + w->rho_f * w->gz;
    size_t L = strlen(st->coupling_summary);
    snprintf(st->coupling_summary + L, sizeof st->coupling_summary - L,
             "; loop: manometric up %.6g, down %.6g, average %.6g Pa/m, phi up %.4f, down %.4f", mu, md,
             0.5 * (mu + md), loop_phi_mean(u), loop_phi_mean(w));
  }
  snprintf(st->linear_summary, sizeof st->linear_summary, "klu, %d radial cells", p->n);
}

static void pipe_destroy(void *self) { release(self); }

const sl_model_ops sl_pipe_ops = {.setup = pipe_setup,
                                  .steady = pipe_steady,
                                  .write_mesh = pipe_write_mesh,
                                  .write = pipe_write,
                                  .stats = pipe_stats,
                                  .destroy = pipe_destroy};
