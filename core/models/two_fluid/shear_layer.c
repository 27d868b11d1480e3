/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid shear layer (see shear_layer.h): the scene, one implicit
 * step, the time loop and the output. */
#include "core/models/two_fluid/shear_layer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/config/expr.h"
#include "core/fv/cell_scalar.h"
#include "core/fv/grid.h"
#include "core/mesh/tensor_grid.h"
#include "core/models/two_fluid/quantities.h"
#include "core/models/two_fluid/two_fluid.h"
#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/plugin/kinds.h"
#include "core/plugin/point_eval.h"
#include "core/scene/mesh.h"

enum { SOLIDS_NO_SLIP = 0, SOLIDS_FREE_SLIP = 1, SOLIDS_WALL_STRESS = 2 };
enum { F_PHI = 1, F_UF = 2, F_US = 4, F_THETA = 8, F_PS = 16 };
static const char *const field_names[] = {"phi", "velocity_fluid", "velocity_solid", "theta", "solids_pressure"};

#define SH_PI 3.14159265358979323846

typedef struct sh_wall {
  const char *name;
  int node, inner;      /* the wall's vertex and the next one inwards */
  int cell;             /* the wall's cell */
  int solids;           /* SOLIDS_* */
  int wall_function;    /* the wall closure reads wall_distance: slip at `inner` */
  const sl_expr *speed; /* of t (the scene's) */
  double u;             /* the wall's speed now */
  double area;          /* r_w^2 (annular, per radian) or 1: torque or force per unit stress */
  double theta_area;    /* r_w or 1: energy per unit flux */
  /* reported at the last accepted state */
  double tau_f, tau_s, slip, bagnold;
} sh_wall;

typedef struct sh_layer {
  const sl_scene *sc;
  const tf_config *cfg;
  const sl_mesh *mesh;
  int *vertex, *cell_of; /* [n+1], [n] */
  int n, annular;
  /* geometry: x [n+1]; per cell: h, W (volume), gm (momentum conductance); per node: V, a, s */
  double *x, *h, *W, *gm, *V, *a, *s;
  double rho_f, mu_f, rho_s, d_p, sphericity, phi_max, gravity, mu_s_const;
  double *phi, *phin;               /* cells, nodes (held) */
  double *uf, *us, *th;             /* state: velocities at the nodes, theta in the cells (th[n] unused) */
  double *uf1, *us1, *th1;          /* the step's iterate */
  double *uf_old, *us_old, dt_last; /* the state before the last accepted step, and that step */
  double *K, *dK, *slip, *muc, *muk, *kapc, *thc, *gam, *dgam, *work; /* work arrays */
  double *gdc, *rhoc, *mumc; /* cells: solids shear rate, mixture density, mixture viscosity */
  double *blk;               /* per node: lower, diagonal, upper 2x2 blocks and the rhs (STRIDE) */
  double *qv[TF_Q_N];        /* per-point values of constant quantities */
  sl_closure *drag_c, *gran_c, *wall_c, *visc_c;
  sl_point_closure drag, gran, wall, visc;
  sh_wall wall_at[2];
  int granular, algebraic, exchange;
  int max_iterations;
  double tolerance, steady_tol, v_ref;
  long iterations, advances;
  int fields;
  double *node_out, *cell_out;
  double *psc; /* cells: the kinetic theory's solids pressure, when written */
  /* the transported theta: a cell scalar (core/fv/cell_scalar.h) on the layer's cells */
  sl_tensor_grid tg;
  sl_fv_grid fv;
  sl_cell_scalar cs;
  double *thit, *thcap, *thsrc, *thsink, *thx; /* cells */
  char steady_text[96];
} sh_layer;

/* ---- closures at points ----------------------------------------------------------- */

/* Input arrays for Q points: the constants, then the given varying ones. */
static void point_values(sh_layer *L, const double *v[TF_Q_N], const double *phi, const double *slip,
                         const double *theta) {
  for (int k = 0; k < TF_Q_N; ++k) v[k] = L->qv[k];
  if (phi) v[TF_Q_PHI] = phi;
  if (slip) v[TF_Q_SLIP] = slip;
  if (theta) v[TF_Q_THETA] = theta;
}

/* K and dK/dslip at the nodes for the iterate's slip. */
static int eval_drag(sh_layer *L, sl_diag *d) {
  int N = L->n + 1;
  for (int k = 0; k < N; ++k) L->slip[k] = fabs(L->uf1[k] - L->us1[k]);
  const double *v[TF_Q_N];
  point_values(L, v, L->phin, L->slip, NULL);
  sl_point_request rq = {"K", L->K, L->dK, "slip"};
  return sl_point_eval(&L->drag, N, v, &rq, 1, d);
}

/* The solids viscosity in the cells (theta the mean of the cell's nodes). */
/* The solids phase's viscosity in each cell (its stress is mu_s times the
 * shear rate, as for the kinetic theory's phase viscosity): [solid]
 * viscosity, plus the part of the suspension viscosity mu_m of
 * [closure.viscosity] the fluid's (1 - phi) mu_f leaves, so that the two
 * phases moving together carry mu_m (the mapping n mu_f + (1 - n) mu_s =
 * mu_m, a choice made here for what Pringle 2001, eqs 3.36-3.37,
 * leaves unstated, with (1 - n) mu_s the phase's share), 0 where mu_m falls
 * below (1 - phi) mu_f; plus the kinetic theory's. mu_m is evaluated at the
 * solids shear rate of the iterate. */
static int eval_solids_viscosity(sh_layer *L, sl_diag *d) {
  int rc = 0;
  for (int i = 0; i < L->n; ++i) {
    double du = L->a[i + 1] * L->us1[i + 1] - L->a[i] * L->us1[i];
    L->gdc[i] = sqrt(L->gm[i] * du * du / L->W[i]); /* the cell's root-mean-square shear rate */
    L->muc[i] = L->mu_s_const, L->muk[i] = 0.0;
  }
  if (L->visc_c) {
    const double *v[TF_Q_N];
    point_values(L, v, L->phi, NULL, NULL);
    v[TF_Q_SHEAR_RATE] = L->gdc, v[TF_Q_DENSITY] = L->rhoc;
    sl_point_request rq = {"viscosity", L->mumc, NULL, NULL};
    if ((rc = sl_point_eval(&L->visc, L->n, v, &rq, 1, d))) return rc;
    for (int i = 0; i < L->n; ++i) L->muc[i] += fmax(L->mumc[i] - (1.0 - L->phi[i]) * L->mu_f, 0.0);
  }
  if (!L->granular) return 0;
  for (int i = 0; i < L->n; ++i) L->thc[i] = fmax(L->th1[i], SL_THETA_FLOOR);
  const double *v[TF_Q_N];
  point_values(L, v, L->phi, NULL, L->thc);
  v[TF_Q_SHEAR_RATE] = L->gdc, v[TF_Q_DENSITY] = L->rhoc;
  sl_point_request rq = {"mu_s", L->muk, NULL, NULL};
  rc = sl_point_eval(&L->gran, L->n, v, &rq, 1, d);
  for (int i = 0; i < L->n && !rc; ++i) L->muc[i] += L->muk[i];
  return rc;
}

/* The wall closure at wall w for the iterate: tau (magnitude) with its
 * slip derivative (theta, of the wall's cell, lagged), and the energy flux
 * q into the layer with dq/dtheta (0 without). */
static int eval_wall(sh_layer *L, sh_wall *w, double *tau, double *dtau, double *q, double *dq, double *bn,
                     sl_diag *d) {
  int ref = w->wall_function ? w->inner : w->node;
  double sl = fabs(L->us1[ref] - w->u), dist = fabs(L->x[w->inner] - L->x[w->node]);
  double phi = L->phin[ref], th = fmax(L->th1[w->cell], SL_THETA_FLOOR);
  double one[TF_Q_N];
  const double *v[TF_Q_N];
  for (int k = 0; k < TF_Q_N; ++k) one[k] = L->qv[k][0], v[k] = &one[k];
  one[TF_Q_PHI] = phi, one[TF_Q_THETA] = th, one[TF_Q_SLIP_WALL] = sl, one[TF_Q_WALL_DISTANCE] = dist,
  one[TF_Q_SLIP] = sl;
  /* one closure call: tau_w with its slip derivative, and the optional outputs the closure gives */
  sl_point_request rq[3] = {{"tau_w", tau, dtau, "slip_wall"}};
  int n_rq = 1;
  *q = *dq = 0.0, *bn = NAN;
  if (sl_point_has_output(&L->wall, "theta_flux")) rq[n_rq++] = (sl_point_request){"theta_flux", q, dq, "theta"};
  if (sl_point_has_output(&L->wall, "bagnold_number"))
    rq[n_rq++] = (sl_point_request){"bagnold_number", bn, NULL, NULL};
  int rc = sl_point_eval(&L->wall, 1, v, rq, n_rq, d);
  if (rc) return sl_diag_prefix(d, rc, "wall '%s'", w->name);
  return 0;
}

/* ---- the coupled system: block-tridiagonal, 2x2 (u_f, u_s) ------------------------- */

/* Block k: lower (the couplings to node k-1), diagonal, upper, each 2x2
 * row-major with entry (row, column) at [2 row + column], and the
 * right-hand side. Rows and columns: F, S. */
enum { F = 0, S = 1, STRIDE = 14 };
#define LOWER(L, k) ((L)->blk + STRIDE * (k))
#define DIAG(L, k) ((L)->blk + STRIDE * (k) + 4)
#define UPPER(L, k) ((L)->blk + STRIDE * (k) + 8)
#define RHS(L, k) ((L)->blk + STRIDE * (k) + 12)

/* X = A^-1 X for a 2x2 block A and m columns of X (2 x 2 layout), by
 * Gaussian elimination with partial pivoting on a copy of A. */
static int block_solve(const double *A, double *X, int m) {
  double a[4];
  memcpy(a, A, sizeof a);
  for (int c = 0; c < 2; ++c) {
    int p = c;
    for (int r = c + 1; r < 2; ++r)
      if (fabs(a[2 * r + c]) > fabs(a[2 * p + c])) p = r;
    if (!(fabs(a[2 * p + c]) > 0.0) || !isfinite(a[2 * p + c])) return -1;
    if (p != c)
      for (int j = 0; j < 2; ++j) {
        double t = a[2 * c + j];
        a[2 * c + j] = a[2 * p + j], a[2 * p + j] = t;
        if (j < m) t = X[2 * c + j], X[2 * c + j] = X[2 * p + j], X[2 * p + j] = t;
      }
    for (int r = c + 1; r < 2; ++r) {
      double f = a[2 * r + c] / a[2 * c + c];
      for (int j = c; j < 2; ++j) a[2 * r + j] -= f * a[2 * c + j];
      for (int j = 0; j < m; ++j) X[2 * r + j] -= f * X[2 * c + j];
    }
  }
  for (int c = 1; c >= 0; --c)
    for (int j = 0; j < m; ++j) {
      double s = X[2 * c + j];
      for (int k = c + 1; k < 2; ++k) s -= a[2 * c + k] * X[2 * k + j];
      X[2 * c + j] = s / a[2 * c + c];
    }
  return 0;
}

/* Block Thomas elimination; the solution replaces the right-hand sides. */
static int block_thomas(sh_layer *L) {
  const int N = L->n + 1;
  for (int k = 1; k < N; ++k) {
    double G[4], g[4] = {0};
    memcpy(G, UPPER(L, k - 1), sizeof G);
    for (int r = 0; r < 2; ++r) g[2 * r] = RHS(L, k - 1)[r];
    if (block_solve(DIAG(L, k - 1), G, 2) || block_solve(DIAG(L, k - 1), g, 1)) return -1;
    double *Lk = LOWER(L, k), *D = DIAG(L, k), *rk = RHS(L, k);
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c)
        for (int j = 0; j < 2; ++j) D[2 * r + c] -= Lk[2 * r + j] * G[2 * j + c];
      for (int j = 0; j < 2; ++j) rk[r] -= Lk[2 * r + j] * g[2 * j];
    }
  }
  for (int k = N - 1; k >= 0; --k) {
    double x[4] = {0};
    for (int r = 0; r < 2; ++r) {
      x[2 * r] = RHS(L, k)[r];
      if (k < N - 1)
        for (int j = 0; j < 2; ++j) x[2 * r] -= UPPER(L, k)[2 * r + j] * RHS(L, k + 1)[j];
    }
    if (block_solve(DIAG(L, k), x, 1)) return -1;
    for (int r = 0; r < 2; ++r) RHS(L, k)[r] = x[2 * r];
  }
  return 0;
}

/* The block holding the coupling of node k's rows to node j's unknowns. */
static double *block_of(sh_layer *L, int k, int j) { return j == k ? DIAG(L, k) : j > k ? UPPER(L, k) : LOWER(L, k); }

/* The cell stress flux G_i = c_i (a_i+1 u_i+1 - a_i u_i): the shear stress
 * times r^2 (annular) of cell i, c_i = mu_i gm_i. */
static double cell_flux(const sh_layer *L, int i, double mu, const double *u) {
  return mu * L->gm[i] * (L->a[i + 1] * u[i + 1] - L->a[i] * u[i]);
}

/* Residual row of phase p (F or S) at node k without walls, with its
 * Jacobian entries: storage, the viscous fluxes of the two cells (their
 * viscosity of the iterate), the drag. */
static double phase_row(sh_layer *L, int p, int k, const double *mu, const double *u, const double *old, double rho,
                        double frac, double dt, double drag) {
  double *D = DIAG(L, k), mass = rho * frac * L->V[k] / dt;
  double r = mass * (u[k] - old[k]) + (p == F ? 1.0 : -1.0) * L->V[k] * drag;
  D[2 * p + p] += mass;
  for (int side = 0; side < 2; ++side) {
    int i = side == 0 ? k : k - 1; /* the cell to the right, to the left */
    if (i < 0 || i >= L->n) continue;
    double sgn = side == 0 ? -1.0 : 1.0; /* -G_k + G_k-1 */
    double c = mu[i] * L->gm[i] / L->s[k], G = cell_flux(L, i, mu[i], u);
    r += sgn * G / L->s[k];
    block_of(L, k, i)[2 * p + p] -= sgn * c * L->a[i];
    block_of(L, k, i + 1)[2 * p + p] += sgn * c * L->a[i + 1];
  }
  return r;
}

/* One Newton update of (u_f, u_s), theta and the viscosities of the
 * iterate held. du: the largest change. */
static int newton_update(sh_layer *L, double dt, double *du, sl_diag *d) {
  const int N = L->n + 1;
  int rc = eval_drag(L, d);
  if (rc) return rc;
  memset(L->blk, 0, (size_t)N * STRIDE * sizeof(double));
  double *muf = L->work; /* [n] fluid viscosity (1 - phi) mu_f */
  for (int i = 0; i < L->n; ++i) muf[i] = (1.0 - L->phi[i]) * L->mu_f;
  for (int k = 0; k < N; ++k) {
    double w = L->uf1[k] - L->us1[k], drag = L->K[k] * w;
    double kn = L->K[k] + L->dK[k] * fabs(w); /* d(K(|w|) w)/dw */
    double rf = phase_row(L, F, k, muf, L->uf1, L->uf, L->rho_f, 1.0 - L->phin[k], dt, drag);
    double rs = phase_row(L, S, k, L->muc, L->us1, L->us, L->rho_s, L->phin[k], dt, drag);
    double *D = DIAG(L, k);
    D[2 * F + F] += L->V[k] * kn, D[2 * F + S] -= L->V[k] * kn;
    D[2 * S + F] -= L->V[k] * kn, D[2 * S + S] += L->V[k] * kn;
    RHS(L, k)[F] = -rf, RHS(L, k)[S] = -rs;
  }
  for (int side = 0; side < 2; ++side) {
    sh_wall *w = &L->wall_at[side];
    int k = w->node, j = w->inner;
    double *D = DIAG(L, k), *Lo = LOWER(L, k), *Up = UPPER(L, k);
    /* the fluid sticks to the wall */
    for (int c = 0; c < 2; ++c) D[2 * F + c] = Lo[2 * F + c] = Up[2 * F + c] = 0.0;
    D[2 * F + F] = 1.0, RHS(L, k)[F] = w->u - L->uf1[k];
    if (w->solids == SOLIDS_NO_SLIP) {
      for (int c = 0; c < 2; ++c) D[2 * S + c] = Lo[2 * S + c] = Up[2 * S + c] = 0.0;
      D[2 * S + S] = 1.0, RHS(L, k)[S] = w->u - L->us1[k];
    } else if (w->solids == SOLIDS_WALL_STRESS) {
      double tau, dtau, q, dq, bn;
      if ((rc = eval_wall(L, w, &tau, &dtau, &q, &dq, &bn, d))) return rc;
      int ref = w->wall_function ? j : k;
      double slip = L->us1[ref] - w->u, sg = slip > 0 ? 1.0 : slip < 0 ? -1.0 : 0.0;
      if (w->wall_function) {
        /* the inner node's control volume reaches the wall: add the wall
         * node's solids row to it, then tie the wall node's solids to it */
        double scale = L->s[k] / L->s[j], *to_k = block_of(L, j, k), *to_j = DIAG(L, j), *off = block_of(L, k, j);
        for (int c = 0; c < 2; ++c) to_k[2 * S + c] += scale * D[2 * S + c], to_j[2 * S + c] += scale * off[2 * S + c];
        RHS(L, j)[S] += scale * RHS(L, k)[S];
        double fj = w->area / L->s[j];
        RHS(L, j)[S] -= fj * tau * sg;
        to_j[2 * S + S] += fj * dtau;
        for (int c = 0; c < 2; ++c) D[2 * S + c] = Lo[2 * S + c] = Up[2 * S + c] = 0.0;
        D[2 * S + S] = 1.0, off[2 * S + S] = -1.0, RHS(L, k)[S] = L->us1[j] - L->us1[k];
      } else {
        double f = w->area / L->s[k]; /* the wall's stress in this row's units */
        RHS(L, k)[S] -= f * tau * sg;
        D[2 * S + S] += f * dtau;
      }
    }
  }
  if (block_thomas(L))
    return sl_diag_set(d, SL_EFAILED, "the shear layer's system is singular (no drag, no viscosity?)");
  double mu = 0.0;
  for (int k = 0; k < N; ++k) {
    double *x = RHS(L, k);
    if (!isfinite(x[F]) || !isfinite(x[S])) return sl_diag_set(d, SL_EFAILED, "non-finite update at x = %g", L->x[k]);
    L->uf1[k] += x[F], L->us1[k] += x[S];
    mu = fmax(mu, fmax(fabs(x[F]), fabs(x[S])));
  }
  *du = mu;
  return 0;
}

/* ---- the granular temperature ------------------------------------------------------ */

/* The walls' granular-energy flux into their cells (sl_cell_scalar_terms boundary): the wall closure's
   theta_flux at the wall, linearised as every model does (core/models/granular.h). */
static int wall_energy(void *user, int c, double *rhs, double *diag, sl_diag *d) {
  sh_layer *L = user;
  for (int side = 0; side < 2; ++side) {
    sh_wall *w = &L->wall_at[side];
    if (w->cell != c || w->solids != SOLIDS_WALL_STRESS) continue;
    double tau, dtau, q, dq, bn;
    int rc = eval_wall(L, w, &tau, &dtau, &q, &dq, &bn, d);
    if (rc) return rc;
    sl_theta_wall_row(w->theta_area, q, sl_theta_wall_implicit(dq), L->thit[c], rhs, diag);
  }
  return 0;
}

/* The cells' shear rate of the iterate's solids velocities, and K there (the mean of the nodes'). */
static void cell_shear(sh_layer *L) {
  for (int i = 0; i < L->n; ++i) {
    double du = L->a[i + 1] * L->us1[i + 1] - L->a[i] * L->us1[i];
    L->gdc[i] = sqrt(L->gm[i] * du * du / L->W[i]); /* the cell's root-mean-square shear rate */
    L->thsink[i] = sl_theta_exchange(L->exchange, 0.5 * (L->K[i] + L->K[i + 1]));
  }
}

/* Transported theta in the cells, after the velocities of the iterate: the
 * shared cell scalar (core/fv/cell_scalar.h) with every model's pointwise
 * terms (sl_theta_terms), as the 2-D model's (two_fluid_plane_solids.c);
 * the walls with solids = wall_stress pass the wall closure's theta_flux,
 * the others are adiabatic. dmax: the largest change. */
static int theta_transport(sh_layer *L, double dt, double *dmax, sl_diag *d) {
  const int n = L->n;
  int rc;
  if (!L->cs.ls && (rc = sl_cell_scalar_init(&L->cs, &L->fv, d)))
    return sl_diag_prefix(d, rc, "the granular temperature's system");
  cell_shear(L);
  for (int i = 0; i < n; ++i) L->thit[i] = fmax(L->th1[i], SL_THETA_FLOOR);
  const double *v[TF_Q_N];
  point_values(L, v, L->phi, NULL, L->thit);
  v[TF_Q_SHEAR_RATE] = L->gdc, v[TF_Q_DENSITY] = L->rhoc;
  sl_point_request rq[3] = {
      {"mu_s", L->muk, NULL, NULL}, {"kappa", L->kapc, NULL, NULL}, {"gamma", L->gam, L->dgam, "theta"}};
  if ((rc = sl_point_eval(&L->gran, n, v, rq, 3, d))) return sl_diag_prefix(d, rc, "[closure.granular]");
  sl_theta_terms(n, L->rho_s, L->phi, L->muk, L->gdc, L->gam, L->dgam, L->thsink, L->thit, L->thcap, L->thsrc,
                 L->thsink);
  sl_cell_scalar_terms t = {.dt = dt,
                            .cap = L->thcap,
                            .s_old = L->th,
                            .k = L->kapc,
                            .source = L->thsrc,
                            .sink = L->thsink,
                            .boundary = L->wall_c ? wall_energy : NULL,
                            .boundary_user = L};
  if ((rc = sl_cell_scalar_solve(&L->cs, &t, L->thx, d)))
    return sl_diag_prefix(d, rc, "the granular temperature's solve");
  double m = 0.0;
  for (int i = 0; i < n; ++i) {
    if (!isfinite(L->thx[i]))
      return sl_diag_set(d, SL_EFAILED, "the granular temperature is not finite at x = %g",
                         0.5 * (L->x[i] + L->x[i + 1]));
    double th = sl_theta_bounded(L->thx[i], L->thit[i]); /* at most a fivefold fall per iteration */
    m = fmax(m, fabs(th - L->th1[i]));
    L->th1[i] = th;
  }
  *dmax = m;
  return 0;
}

/* Algebraic theta in the cells (sl_theta_algebraic: the kinetic closures'
 * quadratic, checked at set-up), at the cells' shear rate. */
static int theta_algebraic(sh_layer *L, double *dmax, sl_diag *d) {
  int n = L->n;
  double *one = L->work, *mu0 = L->gam, *g0 = L->dgam;
  for (int i = 0; i < n; ++i) one[i] = 1.0;
  const double *v[TF_Q_N];
  point_values(L, v, L->phi, NULL, one);
  sl_point_request rq[2] = {{"mu_s", mu0, NULL, NULL}, {"gamma", g0, NULL, NULL}};
  int rc = sl_point_eval(&L->gran, n, v, rq, 2, d);
  if (rc) return rc;
  cell_shear(L);
  double m = 0.0;
  for (int i = 0; i < n; ++i) {
    double th = sl_theta_algebraic(mu0[i] * L->gdc[i] * L->gdc[i], g0[i], L->thsink[i], NULL);
    m = fmax(m, fabs(th - L->th1[i]));
    L->th1[i] = th;
  }
  *dmax = m;
  return 0;
}

/* ---- one step ---------------------------------------------------------------------- */

static int layer_step(sh_layer *L, double t, double dt, int *iterations, sl_diag *d) {
  int N = L->n + 1;
  memcpy(L->uf1, L->uf, (size_t)N * sizeof(double));
  memcpy(L->us1, L->us, (size_t)N * sizeof(double));
  memcpy(L->th1, L->th, (size_t)N * sizeof(double));
  for (int side = 0; side < 2; ++side) {
    double tv = t + dt;
    L->wall_at[side].u = sl_expr_eval(L->wall_at[side].speed, &tv);
    if (!isfinite(L->wall_at[side].u))
      return sl_diag_set(d, SL_EFAILED, "wall '%s': its velocity is not finite at t = %g", L->wall_at[side].name, tv);
  }
  double v_scale = L->v_ref;
  for (int side = 0; side < 2; ++side) v_scale = fmax(v_scale, fabs(L->wall_at[side].u));
  for (int it = 1; it <= L->max_iterations; ++it) {
    double du = 0.0, dth = 0.0;
    int rc = eval_solids_viscosity(L, d);
    if (!rc) rc = newton_update(L, dt, &du, d);
    if (!rc && L->granular) rc = L->algebraic ? theta_algebraic(L, &dth, d) : theta_transport(L, dt, &dth, d);
    if (rc) return rc;
    double th_scale = SL_THETA_FLOOR;
    for (int k = 0; k < N; ++k) th_scale = fmax(th_scale, L->th1[k]);
    *iterations = it;
    if (du <= L->tolerance * v_scale && dth <= L->tolerance * th_scale) return 0;
  }
  return sl_diag_set(d, SL_EFAILED, "the implicit step did not converge in %d iterations ([two_fluid] iterations)",
                     L->max_iterations);
}

/* ---- wall stresses of the accepted state ------------------------------------------- */

/* The stress each phase exerts on wall w along +u: the reaction of the
 * wall node's row (its storage, drag and the flux from inside), or the wall
 * closure's stress. dt: the step that led to the state (0 at t = 0: no
 * storage term). */
static int wall_report(sh_layer *L, sh_wall *w, const double *uf_old, const double *us_old, double dt, sl_diag *d) {
  int k = w->node, i = w->inner > k ? k : k - 1; /* the wall cell */
  double sign_in = w->inner > k ? 1.0 : -1.0;    /* flux from inside enters the wall node with this sign */
  double wv = L->uf1[k] - L->us1[k], drag = L->K[k] * wv;
  double store_f = dt > 0 ? L->rho_f * (1.0 - L->phin[k]) * L->V[k] * (L->uf1[k] - uf_old[k]) / dt : 0.0;
  double muf = (1.0 - L->phi[i]) * L->mu_f;
  /* force of the wall on the fluid (row units times s_k) */
  double on_fluid = L->s[k] * (store_f + L->V[k] * drag) - sign_in * cell_flux(L, i, muf, L->uf1);
  w->tau_f = -on_fluid / w->area;
  w->slip = 0.0, w->bagnold = NAN, w->tau_s = 0.0;
  if (w->solids == SOLIDS_NO_SLIP) {
    double store_s = dt > 0 ? L->rho_s * L->phin[k] * L->V[k] * (L->us1[k] - us_old[k]) / dt : 0.0;
    double on_solids = L->s[k] * (store_s - L->V[k] * drag) - sign_in * cell_flux(L, i, L->muc[i], L->us1);
    w->tau_s = -on_solids / w->area;
  } else if (w->solids == SOLIDS_WALL_STRESS) {
    double tau, dtau, q, dq, bn;
    int rc = eval_wall(L, w, &tau, &dtau, &q, &dq, &bn, d);
    if (rc) return rc;
    int ref = w->wall_function ? w->inner : k;
    w->slip = L->us1[ref] - w->u;
    w->tau_s = w->slip > 0 ? tau : w->slip < 0 ? -tau : 0.0;
    w->bagnold = bn;
  } else {
    w->slip = L->us1[k] - w->u;
  }
  return 0;
}

/* ---- set-up ------------------------------------------------------------------------ */

static int geometry(sh_layer *L, sl_diag *d) {
  const sl_mesh *m = L->mesh;
  int n = L->n = m->n_cells;
  L->vertex = malloc((size_t)(n + 1) * sizeof *L->vertex), L->cell_of = malloc((size_t)n * sizeof *L->cell_of);
  if (!L->vertex || !L->cell_of) return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  int rc = sl_scene_line_chain(m, L->vertex, L->cell_of, d);
  if (rc) return sl_diag_prefix(d, rc, "two_fluid (motion = shear)");
  size_t N = (size_t)n + 1;
  double **nodes[] = {&L->uf_old, &L->us_old, &L->x,   &L->V,    &L->a,    &L->s,       &L->phin,
                      &L->uf,     &L->us,     &L->th,  &L->uf1,  &L->us1,  &L->th1,     &L->K,
                      &L->dK,     &L->slip,   &L->gam, &L->dgam, &L->work, &L->node_out};
  double **cells[] = {&L->h,   &L->W,    &L->gm,   &L->phi,  &L->muc,   &L->muk,   &L->kapc,   &L->thc, &L->cell_out,
                      &L->gdc, &L->rhoc, &L->mumc, &L->thit, &L->thcap, &L->thsrc, &L->thsink, &L->thx};
  for (size_t k = 0; k < sizeof nodes / sizeof nodes[0]; ++k)
    if (!(*nodes[k] = calloc(N, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  for (size_t k = 0; k < sizeof cells / sizeof cells[0]; ++k)
    if (!(*cells[k] = calloc((size_t)n, sizeof(double))))
      return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  for (int k = 0; k < TF_Q_N; ++k)
    if (!(L->qv[k] = calloc(N, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  if (!(L->blk = calloc(N * STRIDE, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  for (size_t k = 0; k < N; ++k) L->x[k] = m->xy[2 * L->vertex[k]];
  if (L->annular && !(L->x[0] > 0.0)) {
    char at[400];
    return sl_diag_set(d, SL_EBADINPUT, "%s = annular: x is the radius and must be > 0 (the mesh starts at x = %g)",
                       sl_scene_where(L->sc, &L->cfg->cross_section, at, sizeof at), L->x[0]);
  }
  for (int i = 0; i < n; ++i) {
    double x0 = L->x[i], x1 = L->x[i + 1], xm = 0.5 * (x0 + x1);
    L->h[i] = x1 - x0;
    if (L->annular) {
      L->W[i] = 0.5 * (x1 * x1 - x0 * x0);
      L->gm[i] = 2.0 / (1.0 / (x0 * x0) - 1.0 / (x1 * x1)); /* r^2 tau = 2 mu d(u/r) / d(r^-2) */
      L->V[i] += 0.5 * (xm * xm - x0 * x0), L->V[i + 1] += 0.5 * (x1 * x1 - xm * xm);
    } else {
      L->W[i] = L->h[i], L->gm[i] = 1.0 / L->h[i];
      L->V[i] += 0.5 * L->h[i], L->V[i + 1] += 0.5 * L->h[i];
    }
  }
  for (size_t k = 0; k < N; ++k) L->a[k] = L->annular ? 1.0 / L->x[k] : 1.0, L->s[k] = L->annular ? L->x[k] : 1.0;
  /* the cells as an n x 1 staggered grid (planar, or axisymmetric with x the radius) for the cell scalar */
  sl_tensor_grid *tg = &L->tg;
  tg->nx = n, tg->ny = 1;
  tg->xf = malloc(N * sizeof *tg->xf), tg->yf = malloc(2 * sizeof *tg->yf);
  tg->mesh_cell = malloc((size_t)n * sizeof *tg->mesh_cell);
  for (int s = 0; s < 4; ++s) tg->side_tag[s] = malloc((size_t)(s < 2 ? 1 : n) * sizeof(int));
  if (!tg->xf || !tg->yf || !tg->mesh_cell || !tg->side_tag[0] || !tg->side_tag[1] || !tg->side_tag[2] ||
      !tg->side_tag[3])
    return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  memcpy(tg->xf, L->x, N * sizeof *tg->xf);
  tg->yf[0] = 0.0, tg->yf[1] = 1.0;
  for (int i = 0; i < n; ++i) tg->mesh_cell[i] = L->cell_of[i], tg->side_tag[2][i] = tg->side_tag[3][i] = -1;
  tg->side_tag[0][0] = tg->side_tag[1][0] = -1;
  const int periodic[2] = {0, 0};
  return sl_fv_grid_build(&L->fv, tg, L->annular, periodic, d);
}

static int physics(sh_layer *L, sl_diag *d) {
  const sl_scene *sc = L->sc;
  const tf_config *cfg = L->cfg;
  int rc = 0;
  L->rho_f = sc->fluid.density, L->mu_f = sc->fluid.viscosity;
  L->rho_s = sc->solid.density, L->d_p = sc->solid.diameter, L->sphericity = sc->solid.sphericity;
  L->phi_max = sc->solid.phi_max, L->mu_s_const = sc->solid.viscosity;
  const sl_reals *gl = &sc->flow.gravity;
  double g0 = gl->n > 0 ? gl->v[0] : 0.0, g1 = gl->n > 1 ? gl->v[1] : 0.0, g2 = gl->n > 2 ? gl->v[2] : 0.0;
  L->gravity = sl_scene_given(sc, gl) && gl->n ? sqrt(g0 * g0 + g1 * g1 + g2 * g2) : 9.81;
  L->max_iterations = (int)cfg->iterations;
  L->tolerance = cfg->tolerance, L->steady_tol = cfg->steady_tolerance;
  L->algebraic = cfg->granular_temperature, L->exchange = cfg->interphase_dissipation;
  const char *model = "the two_fluid shear layer";
  L->drag_c = sl_scene_closure(sc, "drag");
  if ((rc = sl_point_bind(&L->drag, L->drag_c, tf_quantity_names, TF_Q_N, "closure.drag", model, d))) return rc;
  if (sl_point_has_input(&L->drag, "shear_rate"))
    return sl_diag_set(d, SL_EBADINPUT, "[closure.drag]: the shear layer gives a drag closure no shear_rate");
  if (!sl_point_has_output(&L->drag, "K") || !sl_point_has_input(&L->drag, "slip"))
    return sl_diag_set(d, SL_EBADINPUT, "[closure.drag]: the closure gives no K of slip");
  L->gran_c = sl_scene_closure(sc, "granular");
  L->granular = L->gran_c != NULL;
  const sl_src *gt = sl_scene_src(sc, &cfg->granular_temperature);
  if (!L->granular && gt)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s:%d: [two_fluid] granular_temperature: needs [closure.granular] (a "
                       "kinetic theory, e.g. model = lun)",
                       gt->file, gt->line);
  if (L->granular) {
    if ((rc = sl_point_bind(&L->gran, L->gran_c, tf_quantity_names, TF_Q_N, "closure.granular", model, d))) return rc;
    if ((rc = sl_granular_require(&L->gran, 1, "the shear layer", d))) return rc;
  }
  if ((L->visc_c = sl_scene_closure(sc, "viscosity"))) {
    if ((rc = sl_point_bind(&L->visc, L->visc_c, tf_quantity_names, TF_Q_N, "closure.viscosity", model, d))) return rc;
    if (!sl_point_has_output(&L->visc, "viscosity"))
      return sl_diag_set(d, SL_EBADINPUT, "[closure.viscosity]: the closure gives no viscosity");
  }
  if ((L->wall_c = sl_scene_closure(sc, "wall_stress"))) {
    if ((rc = sl_point_bind(&L->wall, L->wall_c, tf_quantity_names, TF_Q_N, "closure.wall_stress", model, d)))
      return rc;
    if (sl_point_has_input(&L->wall, "shear_rate"))
      return sl_diag_set(d, SL_EBADINPUT,
                         "[closure.wall_stress]: the shear layer gives a wall closure no shear_rate "
                         "(its slip_wall and wall_distance give the wall's shear rate)");
  }
  for (int k = 0; k <= L->n; ++k) {
    L->qv[TF_Q_RHO_F][k] = L->rho_f, L->qv[TF_Q_MU_F][k] = L->mu_f, L->qv[TF_Q_RHO_S][k] = L->rho_s;
    L->qv[TF_Q_D_P][k] = L->d_p, L->qv[TF_Q_SPHERICITY][k] = L->sphericity, L->qv[TF_Q_GRAVITY][k] = L->gravity;
  }
  return 0;
}

static int walls(sh_layer *L, sl_diag *d) {
  const char *names[2];
  int rc = sl_scene_line_ends(L->mesh, L->vertex[0], L->vertex[L->n], "two_fluid shear layer", names, d);
  if (rc) return rc;
  int any_stress = 0;
  for (int side = 0; side < 2; ++side) {
    sh_wall *w = &L->wall_at[side];
    int id;
    if ((rc = sl_mesh_boundary_id(L->mesh, names[side], &id, d))) return rc;
    const sh_boundary *b = sl_scene_boundary(L->sc, id);
    char sec[300];
    snprintf(sec, sizeof sec, "boundary.%s", names[side]);
    w->name = names[side];
    w->node = side == 0 ? 0 : L->n;
    w->inner = side == 0 ? 1 : L->n - 1;
    w->cell = side == 0 ? 0 : L->n - 1;
    w->area = L->annular ? L->x[w->node] * L->x[w->node] : 1.0;
    w->theta_area = L->annular ? L->x[w->node] : 1.0;
    w->solids = b->solids;
    w->speed = b->velocity.e;
    if (w->solids == SOLIDS_WALL_STRESS) {
      any_stress = 1;
      if (!L->wall_c) {
        char at[400];
        return sl_diag_set(d, SL_EBADINPUT,
                           "%s = wall_stress needs [closure.wall_stress] (e.g. model = bagnold or "
                           "johnson_jackson)",
                           sl_scene_where(L->sc, &b->solids, at, sizeof at));
      }
      w->wall_function = sl_point_has_input(&L->wall, "wall_distance");
      if (w->wall_function && L->n < 2)
        return sl_diag_set(d, SL_EBADINPUT, "[%s]: a wall function needs at least two cells", sec);
    }
  }
  if (L->wall_c && !any_stress)
    return sl_diag_set(d, SL_EBADINPUT,
                       "[closure.wall_stress]: no wall uses it (set solids = wall_stress in a "
                       "[boundary.NAME])");
  if (L->wall_c && L->wall_at[0].wall_function && L->n < 3)
    return sl_diag_set(d, SL_EBADINPUT, "two_fluid shear layer: wall functions at both walls need at least 3 cells");
  return 0;
}

static int initial_state(sh_layer *L, sl_diag *d) {
  const tf_config *cfg = L->cfg;
  const sl_src *pe = sl_scene_src(L->sc, &cfg->sh_phi);
  if (!pe) return sl_diag_set(d, SL_EBADINPUT, "[initial] phi: the shear layer needs the solids fraction (held)");
  const sl_src *te = sl_scene_src(L->sc, &cfg->sh_theta);
  if (te && !L->granular)
    return sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] theta: needs [closure.granular]", te->file, te->line);
  const sl_scene_expr *ex[4] = {&cfg->sh_phi, &cfg->sh_theta, &cfg->sh_uf, &cfg->sh_us};
  const char *names[4] = {"phi", "theta", "velocity_fluid", "velocity_solid"};
  int rc = 0;
  for (int f = 0; f < 4 && !rc; ++f) {
    const sl_src *es = sl_scene_src(L->sc, ex[f]);
    const char *file = es ? es->file : "(default)";
    int line = es ? es->line : 0;
    if (f == 0) {
      for (int i = 0; i < L->n && !rc; ++i) {
        double xc = 0.5 * (L->x[i] + L->x[i + 1]), v = sl_expr_eval(ex[f]->e, &xc);
        if (!(v > 0.0 && v <= L->phi_max))
          rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] phi = %g at x = %g: allowed 0 < phi <= phi_max = %g",
                           pe->file, pe->line, v, xc, L->phi_max);
        L->phi[i] = v;
      }
    } else if (f == 1) { /* theta in the cells */
      for (int i = 0; i < L->n && !rc; ++i) {
        double xc = 0.5 * (L->x[i] + L->x[i + 1]), v = sl_expr_eval(ex[f]->e, &xc);
        if (!(v > 0.0))
          rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] theta = %g at x = %g: allowed theta > 0", file, line, v,
                           xc);
        L->th[i] = v;
      }
    } else {
      double *dst = f == 2 ? L->uf : L->us;
      for (int k = 0; k <= L->n && !rc; ++k) {
        double v = sl_expr_eval(ex[f]->e, &L->x[k]);
        if (!isfinite(v))
          rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: [initial] %s = %g at x = %g: allowed a finite value", file, line,
                           names[f], v, L->x[k]);
        dst[k] = v;
      }
    }
  }
  if (rc) return rc;
  /* phi at the nodes: the volume-weighted mean of the node's half cells */
  for (int k = 0; k <= L->n; ++k) {
    double num = 0.0, den = 0.0;
    for (int i = k - 1; i <= k; ++i) {
      if (i < 0 || i >= L->n) continue;
      double half = L->annular ? 0.5 * fabs(L->x[k] * L->x[k] - pow(0.5 * (L->x[i] + L->x[i + 1]), 2)) : 0.5 * L->h[i];
      num += half * L->phi[i], den += half;
    }
    L->phin[k] = num / den;
  }
  for (int i = 0; i < L->n; ++i) L->rhoc[i] = L->rho_f * (1.0 - L->phi[i]) + L->rho_s * L->phi[i];
  for (int k = 0; k <= L->n; ++k) L->qv[TF_Q_DENSITY][k] = L->rho_f * (1.0 - L->phin[k]) + L->rho_s * L->phin[k];
  if (!L->granular)
    for (int k = 0; k <= L->n; ++k) L->th[k] = 0.0;
  for (int side = 0; side < 2; ++side) {
    double t0 = 0.0;
    sh_wall *w = &L->wall_at[side];
    w->u = sl_expr_eval(w->speed, &t0);
    L->v_ref = fmax(L->v_ref, fabs(w->u));
  }
  /* the scale of the velocity test: the walls, else the initial velocities */
  for (int k = 0; k <= L->n; ++k) L->v_ref = fmax(L->v_ref, fmax(fabs(L->uf[k]), fabs(L->us[k])));
  if (L->v_ref == 0.0) L->v_ref = 1e-12;
  return 0;
}

/* ---- output ------------------------------------------------------------------------ */

static int layer_write_mesh(void *self, sl_output *out, sl_diag *d) {
  sh_layer *L = self;
  const sl_mesh *m = L->mesh;
  int32_t *cells = malloc((size_t)m->n_cells * 2 * sizeof *cells);
  double *coords = malloc((size_t)m->n_vertices * sizeof *coords);
  if (!cells || !coords) {
    free(cells), free(coords);
    return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  }
  for (int v = 0; v < m->n_vertices; ++v) coords[v] = m->xy[2 * v];
  for (int e = 0; e < 2 * m->n_cells; ++e) cells[e] = m->cell_vertices[e];
  int rc = sl_output_write_mesh(out, 1, m->n_vertices, coords, m->n_cells, 2, cells, "Polyline", d);
  free(cells), free(coords);
  return rc;
}

static int write_state(sh_layer *L, sl_output *out, sl_diag *d) {
  int rc = 0;
  if (L->fields & F_PHI) {
    for (int i = 0; i < L->n; ++i) L->cell_out[L->cell_of[i]] = L->phi[i];
    rc = sl_output_write_field(out, "phi", SL_CENTRE_CELL, 1, L->cell_out, d);
  }
  const double *nf[2] = {L->uf, L->us};
  const int flag[2] = {F_UF, F_US};
  for (int f = 0; f < 2 && !rc; ++f) {
    if (!(L->fields & flag[f])) continue;
    for (int k = 0; k <= L->n; ++k) L->node_out[L->vertex[k]] = nf[f][k];
    rc = sl_output_write_field(out, field_names[f + 1], SL_CENTRE_NODE, 1, L->node_out, d);
  }
  if (!rc && (L->fields & F_THETA)) {
    for (int i = 0; i < L->n; ++i) L->cell_out[L->cell_of[i]] = L->th[i];
    rc = sl_output_write_field(out, "theta", SL_CENTRE_CELL, 1, L->cell_out, d);
  }
  if (!rc && (L->fields & F_PS)) { /* p_s(phi, theta) of [closure.granular] */
    for (int i = 0; i < L->n; ++i) L->thc[i] = fmax(L->th[i], SL_THETA_FLOOR);
    const double *v[TF_Q_N];
    point_values(L, v, L->phi, NULL, L->thc);
    v[TF_Q_SHEAR_RATE] = L->gdc, v[TF_Q_DENSITY] = L->rhoc;
    sl_point_request rq = {"p_s", L->psc, NULL, NULL};
    rc = sl_point_eval(&L->gran, L->n, v, &rq, 1, d);
    for (int i = 0; i < L->n && !rc; ++i) L->cell_out[L->cell_of[i]] = L->psc[i];
    if (!rc) rc = sl_output_write_field(out, "solids_pressure", SL_CENTRE_CELL, 1, L->cell_out, d);
  }
  for (int side = 0; side < 2 && !rc; ++side) {
    const sh_wall *w = &L->wall_at[side];
    char name[300];
    snprintf(name, sizeof name, "wall_shear_stress_fluid_%s", w->name);
    rc = sl_output_write_scalar(out, name, w->tau_f, d);
    snprintf(name, sizeof name, "wall_shear_stress_solid_%s", w->name);
    if (!rc) rc = sl_output_write_scalar(out, name, w->tau_s, d);
    snprintf(name, sizeof name, "wall_slip_%s", w->name);
    if (!rc) rc = sl_output_write_scalar(out, name, w->slip, d);
    if (!rc && L->annular) {
      snprintf(name, sizeof name, "torque_%s", w->name);
      rc = sl_output_write_scalar(out, name, 2.0 * SH_PI * w->area * (w->tau_f + w->tau_s), d);
    }
    if (!rc && w->solids == SOLIDS_WALL_STRESS && sl_point_has_output(&L->wall, "bagnold_number")) {
      snprintf(name, sizeof name, "bagnold_number_%s", w->name);
      rc = sl_output_write_scalar(out, name, w->bagnold, d);
    }
  }
  return rc;
}

static int layer_checkpoint(void *self, sl_checkpoint_array *a, int max) {
  sh_layer *L = self;
  if (max < 3) return 0;
  const char *names[3] = {"velocity_fluid", "velocity_solid", "theta"};
  const double *data[3] = {L->uf, L->us, L->th};
  for (int k = 0; k < 3; ++k) {
    snprintf(a[k].name, sizeof a[k].name, "%s", names[k]);
    a[k].n = k == 2 ? L->n : L->n + 1, a[k].data = data[k]; /* theta in the cells */
  }
  return 3;
}

static int layer_restore(void *self, const sl_checkpoint *ck, sl_diag *d) {
  sh_layer *L = self;
  const char *names[3] = {"velocity_fluid", "velocity_solid", "theta"};
  double *dst[3] = {L->uf, L->us, L->th};
  for (int k = 0; k < 3; ++k) {
    const sl_checkpoint_array *a = sl_checkpoint_find(ck, names[k]);
    int n = k == 2 ? L->n : L->n + 1;
    if (!a || a->n != n)
      return sl_diag_set(d, SL_EBADINPUT, "restart: the checkpoint holds no shear-layer '%s' of %d values", names[k],
                         n);
    memcpy(dst[k], a->data, (size_t)a->n * sizeof(double));
  }
  return 0;
}

/* The reported wall quantities of the state in (uf, us, th). */
static int report_walls(sh_layer *L, const double *uf_old, const double *us_old, double dt, sl_diag *d) {
  int N = L->n + 1;
  memcpy(L->uf1, L->uf, (size_t)N * sizeof(double));
  memcpy(L->us1, L->us, (size_t)N * sizeof(double));
  memcpy(L->th1, L->th, (size_t)N * sizeof(double));
  int rc = eval_solids_viscosity(L, d);
  if (!rc) rc = eval_drag(L, d);
  for (int side = 0; side < 2 && !rc; ++side) rc = wall_report(L, &L->wall_at[side], uf_old, us_old, dt, d);
  return rc;
}

/* ---- the model's steps (core/time/loop.h) ------------------------------------------------ */

static int layer_trial(void *self, sl_step *s, int *iterations, sl_diag *d) {
  sh_layer *L = self;
  int rc = layer_step(L, s->t, s->dt, iterations, d);
  L->iterations += *iterations;
  return sl_step_code(rc);
}

static void layer_accept(void *self, const sl_step *s, int *steady) {
  sh_layer *L = self;
  const int N = L->n + 1;
  double dt = s->dt, rate_u = 0.0, rate_t = 0.0, th_max = SL_THETA_FLOOR, v_scale = L->v_ref;
  for (int k = 0; k < N; ++k) {
    rate_u = fmax(rate_u, fmax(fabs(L->uf1[k] - L->uf[k]), fabs(L->us1[k] - L->us[k])));
    rate_t = fmax(rate_t, fabs(L->th1[k] - L->th[k]));
    th_max = fmax(th_max, L->th1[k]);
  }
  for (int side = 0; side < 2; ++side) v_scale = fmax(v_scale, fabs(L->wall_at[side].u));
  rate_u /= dt * v_scale, rate_t /= dt * th_max;
  memcpy(L->uf_old, L->uf, (size_t)N * sizeof(double));
  memcpy(L->us_old, L->us, (size_t)N * sizeof(double));
  memcpy(L->uf, L->uf1, (size_t)N * sizeof(double));
  memcpy(L->us, L->us1, (size_t)N * sizeof(double));
  memcpy(L->th, L->th1, (size_t)N * sizeof(double));
  L->dt_last = dt;
  ++L->advances;
  *steady = L->steady_tol > 0.0 && rate_u < L->steady_tol && (!L->granular || rate_t < L->steady_tol);
}

static int layer_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)t, (void)u;
  sh_layer *L = self;
  int rc = report_walls(L, L->uf_old, L->us_old, L->dt_last, d);
  return rc ? rc : write_state(L, out, d);
}

static void release(sh_layer *L) {
  double *all[] = {L->uf_old,   L->us_old, L->x,    L->h,     L->W,     L->gm,     L->V,    L->a,
                   L->s,        L->phi,    L->phin, L->uf,    L->us,    L->th,     L->uf1,  L->us1,
                   L->th1,      L->K,      L->dK,   L->slip,  L->muc,   L->muk,    L->kapc, L->thc,
                   L->gdc,      L->rhoc,   L->mumc, L->gam,   L->dgam,  L->work,   L->blk,  L->node_out,
                   L->cell_out, L->psc,    L->thit, L->thcap, L->thsrc, L->thsink, L->thx};
  for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) free(all[k]);
  for (int k = 0; k < TF_Q_N; ++k) free(L->qv[k]);
  sl_point_release(&L->drag), sl_point_release(&L->gran), sl_point_release(&L->wall), sl_point_release(&L->visc);
  sl_cell_scalar_free(&L->cs), sl_fv_grid_free(&L->fv), sl_tensor_grid_free(&L->tg);
  free(L->vertex), free(L->cell_of);
  free(L);
}

static int layer_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  sh_layer *L = calloc(1, sizeof *L);
  if (!L) return sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  L->sc = sc, L->cfg = sc->config, L->mesh = sc->mesh, L->annular = L->cfg->cross_section;
  int rc = 0;
  if (sc->geometry != 0) {
    char at[400];
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "%s: the shear layer (motion = shear) is 1-D (geometry = line; cross_section = "
                     "annular for coaxial cylinders)",
                     sl_scene_where(sc, &sc->geometry, at, sizeof at));
  }
  if (!rc) rc = geometry(L, d);
  if (!rc) rc = physics(L, d);
  if (!rc && L->granular && L->algebraic) {
    char at[400];
    rc = sl_granular_check_kinetic(&L->gran, TF_Q_N, L->qv, TF_Q_PHI, TF_Q_THETA, L->phi_max, 0,
                                   sl_scene_where(L->sc, &L->cfg->granular_temperature, at, sizeof at), d);
  }
  if (!rc) rc = walls(L, d);
  if (!rc) rc = initial_state(L, d);
  unsigned mask = 0;
  int has_ps = L->granular && sl_point_has_output(&L->gran, "p_s");
  if (!rc)
    rc =
        sl_scene_output_fields(sc, F_PHI | F_UF | F_US | (L->granular ? F_THETA : 0u) | (has_ps ? F_PS : 0u), &mask, d);
  if (!rc && (mask & F_THETA) && !L->granular) {
    char at[400];
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: theta needs [closure.granular]",
                     sl_scene_where(sc, &sc->output.fields, at, sizeof at));
  }
  if (!rc && (mask & F_PS) && !has_ps) {
    char at[400];
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: solids_pressure needs a [closure.granular] with the output p_s",
                     sl_scene_where(sc, &sc->output.fields, at, sizeof at));
  }
  if (!rc && (mask & F_PS) && !(L->psc = malloc((size_t)L->n * sizeof *L->psc)))
    rc = sl_diag_set(d, SL_ENOMEM, "shear layer: out of memory");
  L->fields = (int)mask;
  if (rc) {
    release(L);
    return rc;
  }
  L->dt_last = 0.0; /* no storage term in the wall reactions of the starting state */
  snprintf(L->steady_text, sizeof L->steady_text, "(relative rates below %g per s)", L->steady_tol);
  *info = (sl_model_info){.integrator = SL_INTEGRATE_FIXED, .steady_text = L->steady_text};
  *self = L;
  return 0;
}

static void layer_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  sh_layer *L = self;
  st->cpu_flow = res->solve; /* profile phases */
  if (L->advances) {
    double thm = 0.0;
    for (int k = 0; k <= L->n; ++k) thm = fmax(thm, L->th[k]);
    snprintf(st->coupling_summary, sizeof st->coupling_summary,
             "two_fluid shear layer (%s): %.1f iterations per step; solids wall stresses %.4g Pa (%s), %.4g Pa "
             "(%s); max theta %.3g m2/s2",
             L->annular ? "annular" : "planar", (double)L->iterations / (double)L->advances, L->wall_at[0].tau_s,
             L->wall_at[0].name ? L->wall_at[0].name : "-", L->wall_at[1].tau_s,
             L->wall_at[1].name ? L->wall_at[1].name : "-", thm);
  }
  snprintf(st->linear_summary, sizeof st->linear_summary, "2x2 block-tridiagonal, %d nodes%s", L->n + 1,
           L->granular && !L->algebraic ? "; theta: cell scalar" : "");
}

static void layer_destroy(void *self) { release(self); }

const sl_model_ops sl_two_fluid_shear_ops = {.setup = layer_setup,
                                             .step = layer_trial,
                                             .accept = layer_accept,
                                             .write_mesh = layer_write_mesh,
                                             .write = layer_write,
                                             .checkpoint = layer_checkpoint,
                                             .restore = layer_restore,
                                             .stats = layer_stats,
                                             .destroy = layer_destroy};
