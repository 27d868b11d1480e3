/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The liquefaction add-on of the 1-D two-fluid column (liquefaction.h). */
#include "core/models/two_fluid/liquefaction.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/base_record.h"

struct tf_liquefaction {
  int n, top;         /* cells; the deposit is cells 0..top-1, faces 0..top */
  tf_base_record rec; /* n == 0: no shaking */
  double start;       /* the record's t = 0 in run time */
  double k2max, g0_const, tan_phi, xi, omega_d, eta_res, liquefied_ratio, phi_min, nbar_drop, nbar_min;
  int solid_mass;                        /* 1: rho_s (as printed), 0: the mixture density */
  double *nbar, *nbar0, *ps0, *ps, *dps; /* [n] */
  double *w, *v, *w_new, *v_new;         /* [n+1] faces: displacement and velocity relative to the base */
  double *gam, *gam_rev, *path, *dir, *amp, *inc, *epsv, *nbar_new; /* [n] shear history */
  double *rho, *a, *b, *tau0, *lo, *di, *up, *rhs;                  /* [n+1] work: density, tau coefficients */
  double *nbar_ref; /* [n] nbar as the deposit was built (before a drop), for its height */
  double ps_floor;  /* cells with p_s0 below it (the partly filled surface cell) have no ratio */
  double *ph, *p0;  /* [n] the hydrostatic pressure; the fluid pressure at t = 0 */
  int nbar_min_given;
  tf_closure dens; /* [closure.densification], c NULL: none */
  double z_surface0, h_deposit, inventory_fluid0;
  long reversals;
  double ru_max, ru_max_depth, t_onset, onset_depth;
  /* the run's history, step by step */
  int surface_cell; /* the topmost deposit cell with p_s0 above ps_floor */
  double ru_surface_max, ru_base_max, thick_onset, thick_shaking_max, base_peak, base_peak_time;
};

/* The quantities the model gives [closure.densification]. */
static const char *const dens_names[] = {"nbar", "strain_amplitude", "strain_increment", "strain_total",
                                         "volumetric_strain"};

int tfl_wanted(const sl_scene *sc, const tf_column *c) {
  return (c->ps.c && sl_point_has_input(&c->ps.pc, "nbar")) || sl_scene_has_section(sc, "shaking") ||
         sl_scene_has_section(sc, "deposit") || sl_scene_closure(sc, "densification") != NULL;
}

static double *vec(size_t n) { return calloc(n, sizeof(double)); }

int tfl_create(const sl_scene *sc, const tf_config *cfg, tf_column *c, const int *cell_of, tf_liquefaction **out,
               sl_diag *d) {
  char at[400];
  *out = NULL;
  if (!c->ps.c || !sl_point_has_input(&c->ps.pc, "nbar"))
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: a shaken deposit ([shaking], [deposit], [closure.densification]) needs "
                       "a solids pressure of phi and nbar in [closure.solids_pressure] (e.g. model = "
                       "pringle_state, Pringle 2001 eq 4.30)",
                       sl_scene_closure(sc, "solids_pressure")
                           ? sl_scene_closure_where(sc, "solids_pressure", at, sizeof at)
                           : "[closure.solids_pressure]");
  const sl_src *ne = sl_scene_src(sc, &cfg->nbar);
  const sl_src *fe = cfg->from && cfg->from[0] ? sl_scene_src(sc, &cfg->from) : NULL;
  sl_output_field nf = {0};
  if (!ne && fe && sl_output_read_field(cfg->from, "nbar", INFINITY, &nf, d) == 0 && nf.n != c->n) {
    sl_output_field_free(&nf);
    nf.values = NULL;
  }
  if (!ne && !nf.values)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[initial] nbar: the solids pressure %s takes the reference porosity nbar of "
                       "each cell: give its initial value (an expression of x)%s",
                       c->ps.c->desc->name, fe ? ", or start from a file that has it ([initial] from)" : "");
  tf_liquefaction *L = calloc(1, sizeof *L);
  if (!L) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  const int n = c->n;
  L->n = n;
  double **cells[] = {&L->nbar_ref, &L->nbar, &L->nbar0, &L->ps0, &L->ps,  &L->dps,  &L->gam,
                      &L->gam_rev,  &L->path, &L->dir,   &L->amp, &L->inc, &L->epsv, &L->nbar_new};
  double **faces[] = {&L->w,    &L->v,  &L->w_new, &L->v_new, &L->rho, &L->a,  &L->b,
                      &L->tau0, &L->lo, &L->di,    &L->up,    &L->rhs, &L->ph, &L->p0};
  int rc = 0;
  for (size_t i = 0; i < sizeof cells / sizeof cells[0] && !rc; ++i)
    if (!(*cells[i] = vec((size_t)n))) rc = SL_ENOMEM;
  for (size_t i = 0; i < sizeof faces / sizeof faces[0] && !rc; ++i)
    if (!(*faces[i] = vec((size_t)n + 1))) rc = SL_ENOMEM;
  if (rc) {
    tfl_free(L);
    sl_output_field_free(&nf);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  const tf_lq_config *q = &cfg->lq;
  L->k2max = q->k2max, L->g0_const = q->shear_modulus, L->tan_phi = tan(q->friction_angle * M_PI / 180.0),
  L->xi = q->damping;
  L->omega_d = 2.0 * M_PI * q->damping_frequency, L->eta_res = q->residual_viscosity;
  L->liquefied_ratio = q->liquefied_ratio, L->phi_min = q->deposit_phi, L->nbar_drop = q->nbar_drop;
  L->solid_mass = q->mass == 1, L->start = q->start;
  L->nbar_min_given = sl_scene_given(sc, &q->nbar_min);
  L->nbar_min = L->nbar_min_given ? q->nbar_min : 0.01; /* the default follows the deposit (tfl_start) */
  for (int i = 0; i < n && !rc; ++i) {
    double xy[3] = {c->xc[i], 0.0, c->case_index};
    double v = ne ? sl_expr_eval(cfg->nbar.e, xy) : nf.values[cell_of[i]];
    if (!(v >= L->nbar_min && v < 1.0))
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [initial] %s: nbar = %g at x = %g: allowed %g <= nbar < 1 ([deposit] "
                       "nbar_min)",
                       ne ? ne->file : fe->file, ne ? ne->line : fe->line, ne ? "nbar" : "from", v, c->xc[i],
                       L->nbar_min);
    L->nbar[i] = L->nbar0[i] = v;
  }
  sl_output_field_free(&nf);
  if (!rc && q->record && q->record[0]) {
    const sl_src *re = sl_scene_src(sc, &q->record);
    sl_scene_where(sc, &q->record, at, sizeof at);
    rc = tf_base_record_read(&L->rec, q->record, re ? re->file : NULL, q->units == 0 ? 9.81 : 1.0, q->peak * 9.81, at,
                             d);
  }
  if (!rc && (L->dens.c = sl_scene_closure(sc, "densification"))) {
    rc = sl_point_bind(&L->dens.pc, L->dens.c, dens_names, 5, "closure.densification", "the two_fluid column", d);
    if (!rc && !sl_point_has_output(&L->dens.pc, "nbar_new"))
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: the closure does not give nbar_new",
                       sl_scene_closure_where(sc, "densification", at, sizeof at));
  }
  if (rc) {
    tfl_free(L);
    return rc;
  }
  c->nbar = L->nbar, c->ps.nbar = L->nbar;
  *out = L;
  return 0;
}

/* p_s and dp_s/dphi of the cells' phi and nbar. */
static int solids_pressure(tf_liquefaction *L, tf_column *c, const double *phi, sl_diag *d) {
  int rc = tf_closure_eval(&c->ps, L->n, phi, NULL, L->ps, L->dps, d);
  return rc ? sl_diag_prefix(d, rc, "solids pressure") : 0;
}

/* The deposit's height from its solids inventory: each cell counts its height where the skeleton holds its
 * solids at least at the reference fraction 1 - nbar the deposit was built with, and the height its solids
 * would fill at that fraction where it is looser (a partly emptied surface cell, a settling suspension), so
 * that the surface moves continuously as solids leave the top cells. */
static double surface_height(tf_liquefaction *L, const tf_column *c) {
  double z = c->xf[0];
  for (int i = 0; i < c->n; ++i) z += c->h[i] * fmin(1.0, c->phi[i] / (1.0 - L->nbar_ref[i]));
  return z;
}

/* The hydrostatic pressure in the cells by the column's own recursion (two_fluid_plane_step.c, column_finish)
 * with dp/dx = rho_f g,
 * into L->ph. */
static void hydrostatic(tf_liquefaction *L, const tf_column *c) {
  const int n = L->n;
  double *ph = L->ph, p_top = c->bc[1] == TF_OUTLET ? c->p_out : 0.0;
  ph[n - 1] = p_top - 0.5 * c->h[n - 1] * c->rho_f * c->g;
  for (int i = n - 2; i >= 0; --i) ph[i] = ph[i + 1] - c->dual[i + 1] * c->rho_f * c->g;
}

int tfl_start(tf_liquefaction *L, tf_column *c, sl_diag *d) {
  if (!c->below)
    return sl_diag_set(d, SL_EBADINPUT, "[flow] gravity: a shaken deposit lies on the base at x0 (gravity < 0)");
  int rc = solids_pressure(L, c, c->phi, d);
  if (rc) return rc;
  memcpy(L->ps0, L->ps, (size_t)L->n * sizeof *L->ps0);
  L->ps_floor = 1e-3 * L->ps0[0];
  L->top = 0;
  while (L->top < L->n && c->phi[L->top] >= L->phi_min) ++L->top;
  if (L->top == 0)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[deposit] phi_min = %g: no deposit at the base at t = 0 (phi = %g in the "
                       "bottom cell)",
                       L->phi_min, c->phi[0]);
  /* The densest reference state densification may reach: by default the one whose P_s at phi_max is twice
   * the deposit's largest P_s, so that a densified cell can carry its overburden again below the
   * packing limit (bisection on nbar, P_s falling as nbar falls). */
  if (!L->nbar_min_given) {
    double lo = 0.01, hi = L->nbar[0], target = 2.0 * L->ps0[0];
    for (int it = 0; it < 60; ++it) {
      double mid = 0.5 * (lo + hi), pm, dpm;
      c->ps.nbar = &mid;
      rc = tf_closure_eval(&c->ps, 1, &c->phi_max, NULL, &pm, &dpm, d);
      c->ps.nbar = L->nbar;
      if (rc) return sl_diag_prefix(d, rc, "[deposit] nbar_min");
      if (pm > target) hi = mid; /* P_s falls with nbar: mid is dense enough to carry the target */
      else lo = mid;
    }
    L->nbar_min = hi;
  }
  memcpy(L->p0, c->p, (size_t)L->n * sizeof *L->p0);
  memcpy(L->nbar_ref, L->nbar, (size_t)L->n * sizeof *L->nbar_ref);
  L->z_surface0 = surface_height(L, c), L->h_deposit = L->z_surface0 - c->xf[0];
  L->inventory_fluid0 = 0.0;
  for (int i = 0; i < c->n; ++i) L->inventory_fluid0 += (1.0 - c->phi[i]) * c->h[i];
  if (L->nbar_drop != 0.0)
    for (int i = 0; i < L->top; ++i) L->nbar[i] = fmax(L->nbar[i] - L->nbar_drop, L->nbar_min);
  for (int i = 0; i < L->n; ++i) L->nbar0[i] = L->nbar[i];
  L->t_onset = NAN, L->onset_depth = NAN, L->thick_onset = NAN;
  L->surface_cell = 0;
  for (int i = 0; i < L->top; ++i)
    if (L->ps0[i] > L->ps_floor) L->surface_cell = i;
  return 0;
}

/* The secant modulus, viscosity and density of cell i at the step's start. */
static void cell_shear(const tf_liquefaction *L, const tf_column *c, int i, double *G, double *eta, double *rho) {
  double ps = fmax(L->ps[i], 0.0);
  /* Seed & Idriss (1970) / Hosni (thesis eq 3.40): G0 [kPa] = 220 K2max sqrt(P_s [kPa]) */
  double G0 = L->g0_const > 0.0 ? L->g0_const : 1e3 * 220.0 * L->k2max * sqrt(ps * 1e-3), tmax = ps * L->tan_phi;
  double g = fabs(L->gam[i]);
  *G = G0 > 0.0 && tmax > 0.0 ? G0 / (1.0 + G0 * g / tmax) : 0.0; /* Hardin & Drnevich (1972) */
  if (L->g0_const > 0.0) *G = G0;                                 /* the verification's linear elastic deposit */
  *eta = 2.0 * L->xi * G0 / L->omega_d + L->eta_res;
  *rho = L->solid_mass ? c->rho_s : c->phi[i] * c->rho_s + (1.0 - c->phi[i]) * c->rho_f;
}

/* The liquefied zone: the deposit's full cells (below the current surface) whose p_s fell below
 * liquefied_ratio of p_s0; its top and bottom depths below the initial surface and its thickness. L->ps must
 * hold p_s of the state. */
static double liquefied_zone(tf_liquefaction *L, const tf_column *c, double *ztop, double *zbot) {
  double thick = 0.0, zs = surface_height(L, c);
  *ztop = NAN, *zbot = NAN;
  for (int i = 0; i < L->top; ++i)
    if (L->ps0[i] > L->ps_floor && c->xf[i + 1] <= zs && L->ps[i] < L->liquefied_ratio * L->ps0[i]) {
      double a = L->z_surface0 - c->xf[i + 1], b = L->z_surface0 - c->xf[i];
      if (isnan(*ztop) || a < *ztop) *ztop = a;
      if (isnan(*zbot) || b > *zbot) *zbot = b;
      thick += c->h[i];
    }
  return thick;
}

int tfl_step(tf_liquefaction *L, tf_column *c, double t, double dt, sl_diag *d) {
  const int top = L->top;
  int rc = solids_pressure(L, c, c->phi, d);
  if (rc) return rc;
  /* per cell: tau^{n+1} = a (dv^{n+1}) + b, tau^n = tau0 */
  for (int i = 0; i < top; ++i) {
    double G, eta, rho;
    cell_shear(L, c, i, &G, &eta, &rho);
    double dw = L->w[i + 1] - L->w[i], dv = L->v[i + 1] - L->v[i], h = c->h[i];
    L->rho[i] = rho;
    L->a[i] = (0.5 * G * dt + eta) / h;
    L->b[i] = G / h * (dw + 0.5 * dt * dv);
    L->tau0[i] = G / h * dw + eta / h * dv;
  }
  const double ag = L->rec.n ? tf_base_record_at(&L->rec, t + 0.5 * dt - L->start) : 0.0;
  for (int k = 1; k <= top; ++k) {
    double m = 0.5 * L->rho[k - 1] * c->h[k - 1] + (k < top ? 0.5 * L->rho[k] * c->h[k] : 0.0); /* the face's mass */
    double ak = k < top ? L->a[k] : 0.0, am = L->a[k - 1];
    double bk = k < top ? L->b[k] : 0.0, tk = k < top ? L->tau0[k] : 0.0;
    L->di[k] = m / dt + 0.5 * (ak + am);
    L->up[k] = -0.5 * ak;
    L->lo[k] = k > 1 ? -0.5 * am : 0.0;
    L->rhs[k] = m / dt * L->v[k] + 0.5 * (bk - L->b[k - 1] + tk - L->tau0[k - 1]) - m * ag;
  }
  for (int k = 2; k <= top; ++k) { /* Thomas: the matrix is diagonally dominant */
    double f = L->lo[k] / L->di[k - 1];
    L->di[k] -= f * L->up[k - 1], L->rhs[k] -= f * L->rhs[k - 1];
  }
  L->v_new[0] = 0.0, L->w_new[0] = 0.0;
  for (int k = top; k >= 1; --k) L->v_new[k] = (L->rhs[k] - (k < top ? L->up[k] * L->v_new[k + 1] : 0.0)) / L->di[k];
  for (int k = 1; k <= top; ++k) {
    L->w_new[k] = L->w[k] + 0.5 * dt * (L->v[k] + L->v_new[k]);
    if (!isfinite(L->w_new[k]))
      return sl_diag_set(d, SL_EFAILED, "the horizontal motion of the deposit is not finite at face %d", k);
  }
  return 0;
}

int tfl_accept(tf_liquefaction *L, tf_column *c, double t, double dt, sl_diag *d) {
  const int top = L->top;
  double *sw;
  sw = L->w, L->w = L->w_new, L->w_new = sw;
  sw = L->v, L->v = L->v_new, L->v_new = sw;
  /* the shear history: strain, reversals (the half-cycle's amplitude is half its excursion) */
  for (int i = 0; i < top; ++i) {
    double g = (L->w[i + 1] - L->w[i]) / c->h[i], dg = g - L->gam[i];
    double dir = dg > 0.0 ? 1.0 : dg < 0.0 ? -1.0 : 0.0;
    L->amp[i] = 0.0, L->inc[i] = fabs(dg);
    if (dir != 0.0) {
      if (L->dir[i] != 0.0 && dir != L->dir[i]) {
        L->amp[i] = 0.5 * fabs(L->gam[i] - L->gam_rev[i]);
        L->gam_rev[i] = L->gam[i];
        ++L->reversals;
      }
      L->dir[i] = dir;
    }
    L->path[i] += fabs(dg);
    L->gam[i] = g;
    L->epsv[i] = 1.0 - (1.0 - L->nbar0[i]) / (1.0 - L->nbar[i]);
  }
  if (L->dens.c && top > 0) {
    const double *values[5] = {L->nbar, L->amp, L->inc, L->path, L->epsv};
    sl_point_request rq = {"nbar_new", L->nbar_new, NULL, NULL};
    int rc = sl_point_eval(&L->dens.pc, top, values, &rq, 1, d);
    if (rc) return sl_diag_prefix(d, rc, "densification");
    for (int i = 0; i < top; ++i) L->nbar[i] = fmin(fmax(L->nbar_new[i], L->nbar_min), L->nbar[i]);
  }
  /* onset: the first time the excess pore pressure reaches 0.95 of the initial effective stress */
  hydrostatic(L, c);
  for (int i = 0; i < top; ++i) {
    double ru = L->ps0[i] > L->ps_floor ? (c->p[i] - L->p0[i]) / L->ps0[i] : 0.0;
    if (ru > L->ru_max) L->ru_max = ru, L->ru_max_depth = L->z_surface0 - c->xc[i];
    if (isnan(L->t_onset) && ru >= 0.95) L->t_onset = t + dt, L->onset_depth = L->z_surface0 - c->xc[i];
    if (i == L->surface_cell) L->ru_surface_max = fmax(L->ru_surface_max, ru);
    if (i == 0) L->ru_base_max = fmax(L->ru_base_max, ru);
  }
  if (c->p[0] - L->p0[0] > L->base_peak) L->base_peak = c->p[0] - L->p0[0], L->base_peak_time = t + dt;
  int rc = solids_pressure(L, c, c->phi, d);
  if (rc) return rc;
  double a, b, thick = liquefied_zone(L, c, &a, &b);
  if (!isnan(L->t_onset) && isnan(L->thick_onset)) L->thick_onset = thick;
  if (L->rec.n && t + dt <= L->start + tf_base_record_end(&L->rec) + 1e-9)
    L->thick_shaking_max = fmax(L->thick_shaking_max, thick);
  return 0;
}

int tfl_write(tf_liquefaction *L, tf_column *c, sl_output *out, const int *cell_of, double *cell, unsigned fields,
              double t, sl_diag *d) {
  const int n = L->n, top = L->top;
  int rc = solids_pressure(L, c, c->phi, d);
  if (rc) return rc;
  hydrostatic(L, c);
  const double *ph = L->ph;
  double base_excess = c->p[0] - L->p0[0];
  struct {
    unsigned flag;
    const char *name;
  } f[] = {{TFL_F_NBAR, "nbar"},
           {TFL_F_RATIO, "stress_ratio"},
           {TFL_F_EXCESS, "excess_pressure"},
           {TFL_F_RU, "pore_pressure_ratio"},
           {TFL_F_STRAIN, "shear_strain"},
           {TFL_F_PS, "solids_pressure"}};
  for (size_t k = 0; k < sizeof f / sizeof f[0] && !rc; ++k) {
    if (!(fields & f[k].flag)) continue;
    for (int i = 0; i < n; ++i) {
      double v = 0.0, ratio = L->ps0[i] > L->ps_floor ? L->ps[i] / L->ps0[i] : 1.0;
      switch (f[k].flag) {
        case TFL_F_NBAR:
          v = L->nbar[i];
          break;
        case TFL_F_RATIO:
          v = i < top ? ratio : 1.0;
          break;
        case TFL_F_EXCESS:
          v = c->p[i] - L->p0[i];
          break;
        case TFL_F_RU:
          v = i < top && L->ps0[i] > L->ps_floor ? (c->p[i] - L->p0[i]) / L->ps0[i] : 0.0;
          break;
        case TFL_F_STRAIN:
          v = L->gam[i];
          break;
        default:
          v = L->ps[i];
          break;
      }
      cell[cell_of[i]] = v;
    }
    rc = sl_output_write_field(out, f[k].name, SL_CENTRE_CELL, 1, cell, d);
  }
  /* the liquefied zone: deposit cells whose p_s fell below liquefied_ratio of p_s0 */
  double ztop, zbot, thick = liquefied_zone(L, c, &ztop, &zbot), zs = surface_height(L, c);
  double fluid = 0.0;
  for (int i = 0; i < n; ++i) fluid += (1.0 - c->phi[i]) * c->h[i];
  double ag = L->rec.n ? tf_base_record_at(&L->rec, t - L->start) : 0.0;
  const struct {
    const char *name;
    double v;
  } s[] = {{"settlement", L->z_surface0 - zs},
           {"deposit_height", L->h_deposit},
           {"base_excess_pressure", base_excess},
           {"base_static_excess_pressure", L->p0[0] - ph[0]},
           {"nbar_min", L->nbar_min},
           {"base_pore_pressure_ratio", L->ps0[0] > 0.0 ? base_excess / L->ps0[0] : 0.0},
           {"liquefied_depth_top", ztop},
           {"liquefied_depth_bottom", zbot},
           {"liquefied_thickness", thick},
           {"max_pore_pressure_ratio", L->ru_max},
           {"max_pore_pressure_ratio_depth", L->ru_max_depth},
           {"onset_time", L->t_onset},
           {"liquefied_thickness_at_onset", L->thick_onset},
           {"liquefied_thickness_max_shaking", L->thick_shaking_max},
           {"surface_cell_ratio_max", L->ru_surface_max},
           {"base_cell_ratio_max", L->ru_base_max},
           {"base_excess_pressure_peak", L->base_peak},
           {"base_excess_pressure_peak_time", L->base_peak_time},
           {"onset_depth", L->onset_depth},
           {"base_acceleration", ag},
           {"surface_displacement", L->w[top]},
           {"fluid_conservation_error",
            L->inventory_fluid0 > 0.0 ? (fluid - L->inventory_fluid0) / L->inventory_fluid0 : 0.0}};
  for (size_t k = 0; k < sizeof s / sizeof s[0] && !rc; ++k) rc = sl_output_write_scalar(out, s[k].name, s[k].v, d);
  return rc;
}

void tfl_summary(const tf_liquefaction *L, char *buf, size_t len) {
  snprintf(buf, len,
           "deposit of %d cells (%.4g m), %ld strain reversals, largest pore pressure ratio %.3f at depth "
           "%.3g m, onset (ratio 0.95) at t = %.4g s, depth %.4g m",
           L->top, L->h_deposit, L->reversals, L->ru_max, L->ru_max_depth, L->t_onset, L->onset_depth);
}

void tfl_free(tf_liquefaction *L) {
  if (!L) return;
  double *all[] = {L->nbar_ref, L->nbar, L->nbar0, L->ps0,      L->ps, L->dps, L->gam,   L->gam_rev, L->path, L->dir,
                   L->amp,      L->inc,  L->epsv,  L->nbar_new, L->w,  L->v,   L->w_new, L->v_new,   L->rho,  L->a,
                   L->b,        L->tau0, L->lo,    L->di,       L->up, L->rhs, L->ph,    L->p0};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i) free(all[i]);
  tf_base_record_free(&L->rec);
  if (L->dens.c) sl_point_release(&L->dens.pc);
  free(L);
}
