/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The shear-induced migration problems of Nigam (1999) section 4.5 on the
 * transport: the Phillips et al. (1992)
 * closure with mu(phi) = (1 - phi/0.68)^(-1.82), K_c = 0.41, K_mu = 0.62,
 * their exact steady states (the implicit relations 4.206 and 4.210, solved
 * by safeguarded Newton), and a radial-line run to steady state with the
 * shear rate of the flow at every outer step. */
#ifndef SLUICE_TESTS_MIGRATION_EXACT_H
#define SLUICE_TESTS_MIGRATION_EXACT_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mesh/mesh.h"
#include "core/transport/migration.h"
#include "core/transport/transport.h"

#define MX_PHI_M 0.68
#define MX_EXPO 1.82 /* mu = (1 - phi/phi_m)^(-1.82): 2.6765 * 0.68 */
#define MX_KC 0.41
#define MX_KMU 0.62

typedef struct mx_params {
  double a2; /* particle radius squared, in the scaled lengths */
  double kc, kmu;
} mx_params;

static inline double mx_mu(double phi) { return pow(1 - phi / MX_PHI_M, -MX_EXPO); }

/* No settling (neutrally buoyant). */
static inline int mx_no_settling(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  (void)user, (void)phi, (void)d;
  for (int i = 0; i < n; ++i) u[i] = du[i] = 0;
  return 0;
}

/* The Phillips et al. closure in the convention of plugins/migration/phillips.c. */
static inline int mx_coef(void *user, int n, const double *phi, const double *g, double *dc, double *dmu, sl_diag *d) {
  const mx_params *p = user;
  (void)d;
  for (int i = 0; i < n; ++i) {
    dc[i] = p->kc * p->a2 * phi[i];
    dmu[i] = p->kmu * p->a2 * g[i] * phi[i] * phi[i];
  }
  return 0;
}

static inline int mx_lnmu(void *user, int n, const double *phi, double *L, double *dL, sl_diag *d) {
  (void)user;
  for (int i = 0; i < n; ++i) {
    if (!(phi[i] >= 0 && phi[i] < MX_PHI_M)) return sl_diag_set(d, SL_EBADINPUT, "phi = %.17g", phi[i]);
    L[i] = -MX_EXPO * log1p(-phi[i] / MX_PHI_M);
    dL[i] = MX_EXPO / (MX_PHI_M - phi[i]);
  }
  return 0;
}

/* ---- exact steady states ------------------------------------------------------------ */

/* The steady state of a no-flux problem: phi g mu^(K_mu/K_c) = const (Nigam
 * eq 4.199). With g = C r^p / mu (Couette p = -2, Poiseuille p = 1):
 *   ln phi - e ln(1 - phi/phi_m) = ln phi_w - e ln(1 - phi_w/phi_m) - p ln(r / r_w),
 * e = 1.82 (K_mu/K_c - 1) (4.206, 4.210). The left side increases from -inf
 * to +inf on (0, phi_m): safeguarded Newton. */
typedef struct mx_exact {
  double p, r_w, phi_w, e;
} mx_exact;

static inline double mx_solve(double rhs, double e) {
  double lo = 0, hi = MX_PHI_M, x = 0.5 * MX_PHI_M;
  for (int it = 0; it < 200; ++it) {
    double f = log(x) - e * log1p(-x / MX_PHI_M) - rhs;
    if (f > 0) hi = x;
    else lo = x;
    double fp = 1 / x + e / (MX_PHI_M - x), xn = x - f / fp;
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
    if (fabs(xn - x) <= 1e-16 * x || hi - lo <= 1e-16) return xn;
    x = xn;
  }
  return x;
}

static inline double mx_phi(const mx_exact *x, double r) {
  if (r <= 0) return MX_PHI_M; /* Poiseuille axis */
  double rhs = log(x->phi_w) - x->e * log1p(-x->phi_w / MX_PHI_M) - x->p * log(r / x->r_w);
  return mx_solve(rhs, x->e);
}

/* r-weighted cell averages of the exact profile on [r0, r1]: 8-point
 * Gauss-Legendre on each cell. */
static inline double mx_cell_average(const mx_exact *x, double r0, double r1) {
  static const double gx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double gw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double c = 0.5 * (r0 + r1), h = 0.5 * (r1 - r0), s = 0, v = 0;
  for (int k = 0; k < 4; ++k)
    for (int sg = -1; sg <= 1; sg += 2) {
      double r = c + sg * h * gx[k];
      s += gw[k] * r * mx_phi(x, r);
      v += gw[k] * r;
    }
  return s / v;
}

/* The r-weighted mean of the exact profile over the cells of the mesh. */
static inline double mx_mean(const mx_exact *x, const sl_mesh *m, double *avg) {
  double s = 0, v = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double r0 = m->xy[2 * m->cell_vertices[2 * c]], r1 = m->xy[2 * m->cell_vertices[2 * c + 1]];
    double a = mx_cell_average(x, r0, r1), vol = 0.5 * (r1 * r1 - r0 * r0);
    if (avg) avg[c] = a;
    s += a * vol, v += vol;
  }
  return s / v;
}

/* phi_w such that the exact profile has the mean `mean` on this mesh
 * (bisection: the mean increases with phi_w). */
static inline void mx_fit(mx_exact *x, const sl_mesh *m, double mean) {
  double lo = 1e-6, hi = MX_PHI_M * (1 - 1e-12);
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    x->phi_w = 0.5 * (lo + hi);
    if (mx_mean(x, m, NULL) < mean) lo = x->phi_w;
    else hi = x->phi_w;
  }
  x->phi_w = 0.5 * (lo + hi);
}

/* ---- runs to steady state ---------------------------------------------------------- */

typedef enum mx_flow { MX_COUETTE, MX_POISEUILLE } mx_flow;

typedef struct mx_run {
  mx_flow flow;
  sl_mesh *m;
  sl_transport *t;
  sl_migration *mg;
  mx_params par;
  double *phi, *g, *prev, *flux;
  double r_in, mass0, time;
  long substeps, outer;
  int limited;
  double limited_volume, clamped;
} mx_run;

/* The shear rate of the flow for the current phi, at the cell points.
 * Couette (inner cylinder r_in at speed 1, outer r = 1 at rest): the torque
 * balance (1/r^2) d(r^2 mu g)/dr = 0 gives g = C/(r^2 mu), and
 * v/r = int_r^1 C/(r'^3 mu) dr' with v(r_in) = 1 fixes C (Nigam 1999, eq 4.207),
 * the integral taken cell by cell with mu of the cell. Poiseuille:
 * g = G r/(2 mu) with G = 1. */
static inline void mx_shear(mx_run *r) {
  const sl_mesh *m = r->m;
  const double *xc = sl_transport_cell_points(r->t);
  double C = 1;
  if (r->flow == MX_COUETTE) {
    double I = 0;
    for (int c = 0; c < m->n_cells; ++c) {
      double r0 = m->xy[2 * m->cell_vertices[2 * c]], r1 = m->xy[2 * m->cell_vertices[2 * c + 1]];
      I += 0.5 * (1 / (r0 * r0) - 1 / (r1 * r1)) / mx_mu(r->phi[c]);
    }
    C = 1 / (r->r_in * I);
  }
  for (int c = 0; c < m->n_cells; ++c) {
    double x = xc[2 * c], mu = mx_mu(r->phi[c]);
    r->g[c] = r->flow == MX_COUETTE ? C / (x * x * mu) : 0.5 * x / mu;
  }
}

static inline void mx_die(const char *what, const sl_diag *d) {
  fprintf(stderr, "%s: %s\n", what, d->msg);
  exit(1);
}

static inline void mx_open(mx_run *r, mx_flow flow, int N, double a2, double phi0, int order) {
  sl_diag d;
  memset(r, 0, sizeof *r);
  r->flow = flow;
  r->r_in = flow == MX_COUETTE ? 0.2689 : 0;
  r->par = (mx_params){a2, MX_KC, MX_KMU};
  sl_transport_opts o = {
      .phi_max = MX_PHI_M, .order = order, .geometry = SL_TRANSPORT_AXISYMMETRIC, .settling = mx_no_settling};
  sl_migration_opts mo = {.coef = mx_coef, .coef_user = &r->par, .ln_mu = mx_lnmu};
  if (sl_mesh_interval(r->r_in, 1, N, NULL, &r->m, &d)) mx_die("mesh", &d);
  if (sl_transport_create(r->m, &o, &r->t, &d)) mx_die("transport", &d);
  if (sl_migration_create(r->t, &mo, &r->mg, &d)) mx_die("migration", &d);
  if (sl_transport_set_extra_flux(r->t, sl_migration_flux, r->mg, &d)) mx_die("extra flux", &d);
  r->phi = malloc((size_t)N * sizeof *r->phi);
  r->g = malloc((size_t)N * sizeof *r->g);
  r->prev = malloc((size_t)N * sizeof *r->prev);
  r->flux = malloc((size_t)r->m->n_faces * sizeof *r->flux);
  if (!r->phi || !r->g || !r->prev || !r->flux) exit(1);
  for (int c = 0; c < N; ++c) r->phi[c] = phi0;
  r->mass0 = sl_transport_mass(r->t, r->phi);
}

static inline void mx_close(mx_run *r) {
  sl_migration_destroy(r->mg);
  sl_transport_destroy(r->t);
  sl_mesh_destroy(r->m);
  free(r->phi), free(r->g), free(r->prev), free(r->flux);
}

/* Outer steps of `sub` stable sub-steps each, the shear rate set at each
 * from the current phi, until max |dphi/dt| over an outer step is below
 * `tol` or the time reaches t_max. Returns that rate. */
static inline double mx_steady(mx_run *r, int sub, double tol, double t_max) {
  sl_diag d;
  const int N = r->m->n_cells;
  double rate = HUGE_VAL;
  while (r->time < t_max) {
    mx_shear(r);
    if (sl_migration_set_shear_rate(r->mg, r->g, &d)) mx_die("shear rate", &d);
    double dts;
    if (sl_migration_flux(r->mg, r->phi, r->flux, &dts, &d)) mx_die("flux", &d);
    double dt = sub * 0.9 * dts;
    memcpy(r->prev, r->phi, (size_t)N * sizeof *r->phi);
    sl_transport_stats st;
    if (sl_transport_step(r->t, dt, NULL, NULL, r->phi, &st, &d)) mx_die("step", &d);
    r->time += dt;
    r->substeps += st.n_substeps;
    r->limited += st.n_extra_limited;
    r->limited_volume += st.extra_limited;
    r->clamped += st.clamped;
    ++r->outer;
    rate = 0;
    for (int c = 0; c < N; ++c) rate = fmax(rate, fabs(r->phi[c] - r->prev[c]) / dt);
    if (rate < tol) break;
  }
  return rate;
}

/* The cell values interpolated linearly between the cell points at r
 * (extrapolated from the two nearest cells beyond the first or last). */
static inline double mx_interp(const mx_run *r, double x) {
  const double *xc = sl_transport_cell_points(r->t);
  int N = r->m->n_cells, k = 0;
  while (k + 2 < N && xc[2 * (k + 1)] < x) ++k;
  double x0 = xc[2 * k], x1 = xc[2 * (k + 1)];
  return r->phi[k] + (r->phi[k + 1] - r->phi[k]) * (x - x0) / (x1 - x0);
}

/* The r-weighted mean of phi over the mesh. */
static inline double mx_run_mean(const mx_run *r) {
  const double *v = sl_transport_volumes(r->t);
  double V = 0;
  for (int c = 0; c < r->m->n_cells; ++c) V += v[c];
  return sl_transport_mass(r->t, r->phi) / V;
}

#endif
