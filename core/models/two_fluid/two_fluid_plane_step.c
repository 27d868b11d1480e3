/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One implicit step of the 2-D two-fluid model on the staggered grid
 * (two_fluid_plane_impl.h). The equations are those of the 1-D column
 * (two_fluid.h) with the pressure kept as an unknown, per unit volume:
 *
 *   phi rho_s du_s/dt = -phi grad p - grad P_s + F + phi rho_s g + div(mu_s grad u_s)
 *   eps rho_f du_f/dt = -eps grad p - F + eps rho_f g + div(eps mu_f grad u_f)
 *   div(phi u_s + eps u_f) = 0,      eps = 1 - phi,
 *   dphi/dt + div(phi u_s) = 0,
 *
 * F = K(phi, |s|) s the drag on the solids, s = u_f - u_s (Pringle 2001,
 * eq 3.10), in the Stokes regime (no convective terms,
 * as the column) and with the Laplacian form of the viscous stresses; mu_s
 * the solids phase's viscosity (two_fluid_plane_solids.c).
 *
 * Each face carries the normal components of both momentum equations,
 * written with phi_f of the cell on its gravity side (the mean of its two
 * cells for faces along gravity's normal) and multiplied by its dual volume
 * A_f L_f; each cell the continuity of the mixture's volume flux. Iteration
 * k (phi^0 = T(phi^n, u_s^n)), as in the column:
 *   drag  Newton-linearised in the normal slip, the tangential slip (the
 *         mean of the four nearest transverse faces) of the iterate;
 *   P_s   P_s(phi^k) + P_s'(phi^k) dphi(delta u_s), dphi_c = -(dt/V_c)
 *         sum_f sigma A_f w_f delta u_s,f with w the upwind phi^k (Pringle
 *         2001 eq 4.31, Newton on the transported phi);
 *   then one sparse solve for (u_s, u_f, p) and phi^(k+1) = T(phi^n, u_s),
 * until the velocities change by less than tolerance x the velocity scale.
 * T is the column's bounded transport (two_fluid_plane_transport.c): upwind
 * or MUSCL face fluxes, sub-stepped within the CFL limit, what enters a cell
 * scaled so that it cannot pass phi_max (the Newton terms' w stays the
 * first-order upwind phi: it only shapes the Jacobian). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"

/* Nearly empty faces still get a solids equation: that of one particle in
 * clear fluid (every term of it is proportional to phi). */
static const double PHI_FLOOR = 1e-6;
/* After this many iterations the face phi of drag and momentum is that of the
 * step's start (as in the column, for drag laws with a jump in phi). */
enum { FREEZE_PHI_AFTER = 8 };
/* The weight's phi (phi_g) stays implicit, Newton-coupled to the transport, for longer: a stratified
 * suspension overturns when its weight lags (N dt > 1), but a bed blown out at many cells a step can leave
 * the iteration without a fixed point, and after this many iterations it too takes the step's start. */
enum { FREEZE_WEIGHT_AFTER = 20 };
/* Differences kept by the Anderson acceleration of the iteration (see acceleration_start). */
enum { ANDERSON_DEPTH = 5 };

/* ---- geometry --------------------------------------------------------------- */

static int face_dir(const tfp_model *m, int f) { return f >= m->fv.nfx; }

/* The four faces of cell c (west, east, south, north) and the sign of the
 * outward normal along each face's axis. */
static void cell_faces(const tfp_model *m, int c, int f[4]) { sl_fv_cell_faces(&m->fv, c, f); }
static const double SIGMA[4] = {-1.0, 1.0, -1.0, 1.0};

int tfp_setup(tfp_model *m, sl_diag *d) {
  const sl_tensor_grid *g = &m->grid;
  const int nx = g->nx, ny = g->ny;
  int periodic[2] = {m->fv.periodic[0], m->fv.periodic[1]}; /* the boundaries' */
  int rc = sl_fv_grid_build(&m->fv, g, m->axi, periodic, d);
  if (rc) return rc;
  if (m->body_cells) { /* the bodies' cells leave the grid; their faces are the bodies' walls */
    rc = sl_fv_grid_block(&m->fv, m->body_cells, m->n_b - m->n_bodies, d);
    free(m->body_cells), m->body_cells = NULL;
    if (rc) return rc;
  }
  const size_t nc = (size_t)m->fv.nc, nf = (size_t)m->fv.nf;
  struct {
    double **p;
    size_t n;
  } a[] = {{&m->phi, nc},        {&m->p, nc},           {&m->uf, nf},     {&m->us, nf},    {&m->phi_new, nc},
           {&m->p_new, nc},      {&m->uf_new, nf},      {&m->us_new, nf}, {&m->phf, nf},   {&m->phg, nf},
           {&m->w, nf},          {&m->K, nf},           {&m->dK, nf},     {&m->slip, nf},  {&m->sn, nf},
           {&m->ps, nc},         {&m->dps, nc},         {&m->flux, nf},   {&m->alpha, nc}, {&m->inflow, nc},
           {&m->x, 2 * nf + nc}, {&m->rhs, 2 * nf + nc}};
  for (size_t k = 0; k < sizeof a / sizeof a[0]; ++k)
    if (!(*a[k].p = calloc(a[k].n, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  int **ia[] = {&m->ftype, &m->us_row, &m->uf_row, &m->open_face};
  for (size_t k = 0; k < sizeof ia / sizeof ia[0]; ++k)
    if (!(*ia[k] = calloc(nf, sizeof(int)))) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  if (!(m->wall_stats = calloc(5 * (size_t)m->n_b, sizeof(double))) || !(m->tan_noslip = calloc(4 * nf, sizeof(int))) ||
      !(m->end_wall = calloc(2 * nf, sizeof(int))) || !(m->end_u = calloc(2 * nf, sizeof(double))) ||
      !(m->end_us = calloc(2 * nf, sizeof(double))) || !(m->js = calloc(nf, sizeof(double))))
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int f = 0; f < m->fv.nf; ++f) {
    if (m->fv.image[f]) m->ftype[f] = TFP_FACE_IMAGE;
    else if (m->fv.bound[f] < 0) m->ftype[f] = TFP_FACE_INTERIOR;
    else if (m->fv.area[f] == 0.0) m->ftype[f] = TFP_FACE_CLOSED; /* on the axis */
    else {
      int t = m->b[m->fv.bound[f]].type;
      m->ftype[f] = t == TFP_INLET ? TFP_FACE_INLET : t == TFP_OUTLET ? TFP_FACE_OUTLET : TFP_FACE_CLOSED;
    }
  }
  for (int f = 0; f < m->fv.nf; ++f)
    if (m->ftype[f] != TFP_FACE_IMAGE && m->ftype[f] != TFP_FACE_CLOSED) m->open_face[m->n_open++] = f;
  /* the tangential conditions: a face touching a side at one of its ends (x-faces: bottom, top; y-faces:
     left, right) takes the side faces that meet there; no-slip when one of them holds the phase; a wall there
     gives its speed and, for the solids, its stress */
  for (int f = 0; f < 2 * m->fv.nf; ++f) m->end_wall[f] = -1;
  for (int f = 0; f < m->fv.nf; ++f) {
    int dir = face_dir(m, f), along = dir == 0 ? f % (nx + 1) : (f - m->fv.nfx) / nx;
    int across = dir == 0 ? f / (nx + 1) : (f - m->fv.nfx) % nx, n_along = dir == 0 ? nx : ny;
    int n_across = dir == 0 ? ny : nx;
    if (m->fv.periodic[1 - dir]) continue; /* no side across the face's family */
    for (int end = 0; end < 2; ++end) {
      if (across != (end == 0 ? 0 : n_across - 1)) continue;
      int side = dir == 0 ? (end == 0 ? SL_SIDE_BOTTOM : SL_SIDE_TOP) : (end == 0 ? SL_SIDE_LEFT : SL_SIDE_RIGHT);
      for (int s = along - 1; s <= along; ++s) {
        if (s < 0 || s >= n_along) continue;
        int tag = g->side_tag[side][s];
        const tfp_boundary *b = &m->b[tag];
        int fluid = b->type == TFP_WALL || b->type == TFP_INLET;
        int solids = (b->type == TFP_WALL && b->solids == TFP_SOLIDS_NO_SLIP) || b->type == TFP_INLET;
        m->tan_noslip[4 * f + 2 * 0 + end] |= fluid;
        m->tan_noslip[4 * f + 2 * 1 + end] |= solids;
        if (b->type == TFP_WALL && m->end_wall[2 * f + end] < 0) m->end_wall[2 * f + end] = tag;
      }
    }
  }
  /* a body's wall at a face's end: the face of its family across is dead (inside the body or on the domain's
     side of it); the body holds the fluid, the solids as its walls' `solids` says */
  for (int f = 0; f < m->fv.nf && m->fv.blocked; ++f) {
    if (tfp_dead(m, f)) continue;
    int dir = face_dir(m, f), along = dir == 0 ? f % (nx + 1) : (f - m->fv.nfx) / nx;
    int across = dir == 0 ? f / (nx + 1) : (f - m->fv.nfx) % nx, n_across = dir == 0 ? ny : nx;
    for (int end = 0; end < 2; ++end) {
      int to = across + (end ? 1 : -1);
      if (to < 0 || to >= n_across) continue;
      int nb = dir == 0 ? along + (nx + 1) * to : m->fv.nfx + to + nx * along, tag = m->fv.bound[nb];
      if (!tfp_dead(m, nb) || tag < m->n_b - m->n_bodies) continue;
      m->tan_noslip[4 * f + end] = 1;
      m->tan_noslip[4 * f + 2 + end] |= m->b[tag].solids == TFP_SOLIDS_NO_SLIP;
      if (m->end_wall[2 * f + end] < 0) m->end_wall[2 * f + end] = tag;
    }
  }
  m->closed = 1;
  for (int f = 0; f < m->fv.nf; ++f) m->closed = m->closed && m->ftype[f] != TFP_FACE_OUTLET;
  m->datum = 0; /* a closed vessel's pressure datum: the first open cell */
  while (m->datum < m->fv.nc - 1 && tfp_blocked(m, m->datum)) ++m->datum;
  int n = 0;
  for (int f = 0; f < m->fv.nf; ++f) {
    if (m->ftype[f] == TFP_FACE_IMAGE) { /* the first face of its row or column: already numbered */
      int first = tfp_primary(m, f);
      m->us_row[f] = m->us_row[first], m->uf_row[f] = m->uf_row[first];
      continue;
    }
    int active = m->ftype[f] == TFP_FACE_INTERIOR || m->ftype[f] == TFP_FACE_OUTLET;
    m->us_row[f] = active ? n++ : -1;
    m->uf_row[f] = active ? n++ : -1;
  }
  m->n_vel = n, m->n_unknowns = n + m->fv.nc;
  return 0;
}

void tfp_free(tfp_model *m) {
  double *all[] = {m->phi, m->p,          m->uf,    m->us,     m->phi_new,   m->p_new,  m->uf_new, m->us_new,
                   m->phf, m->phg,        m->w,     m->K,      m->dK,        m->slip,   m->sn,     m->ps,
                   m->dps, m->flux,       m->alpha, m->inflow, m->x,         m->rhs,    m->end_u,  m->end_us,
                   m->js,  m->wall_stats, m->acc_x, m->acc_g,  m->acc_scale, m->col_uf0};
  for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) free(all[k]);
  int *ia[] = {m->ftype, m->us_row, m->uf_row, m->tan_noslip, m->end_wall, m->col_face, m->open_face};
  for (size_t k = 0; k < sizeof ia / sizeof ia[0]; ++k) free(ia[k]);
  sl_csr_free(&m->A);
  sl_triplets_free(&m->trip);
  sl_band_free(&m->band);
  free(m->band_of), free(m->band_x);
  sl_linsolve_destroy(m->ls);
  sl_fv_grid_free(&m->fv);
  sl_tensor_grid_free(&m->grid);
  tfp_solids_free(&m->s);
  if (m->acc.n) sl_anderson_free(&m->acc);
}

double tfp_inventory(const tfp_model *m, const double *phi) {
  double s = 0.0;
  for (int c = 0; c < m->fv.nc; ++c) s += phi[c] * m->fv.vol[c];
  return s;
}

/* The inlet faces' superficial velocity (along +x or +y) is eps u_f with u_s
 * = 0; u_f takes eps of the inside cell. With solids_flux the solids enter
 * too: their volume flux phi u_s per area is given (js), u_s = js / phi of
 * the inside cell. The walls' own speeds at the ends
 * of the faces that run along them. */
int tfp_boundary_values(tfp_model *m, double t, const double *phi, sl_diag *d) {
  const double *xf = m->grid.xf, *yf = m->grid.yf;
  for (int f = 0; f < m->fv.nf; ++f) {
    int dir = face_dir(m, f);
    for (int end = 0; end < 2; ++end) {
      int b = m->end_wall[2 * f + end];
      if (b < 0) continue;
      /* the corner at the face's end (on a side of the grid or a body's wall) */
      double x = dir == 0 ? xf[f % (m->fv.nx + 1)] : xf[(f - m->fv.nfx) % m->fv.nx + end];
      double y = dir == 0 ? yf[f / (m->fv.nx + 1) + end] : yf[(f - m->fv.nfx) / m->fv.nx];
      double v[4] = {x, y, t, m->c.case_index};
      double U = m->b[b].velocity.e ? sl_expr_eval(m->b[b].velocity.e, v) : 0.0;
      if (!isfinite(U))
        return sl_diag_set(d, SL_EFAILED, "a wall's velocity is not a finite number (%g) at (%g, %g), t = %g", U, x, y,
                           t);
      m->end_u[2 * f + end] = U;
      if (m->b[b].solids == TFP_SOLIDS_NO_SLIP) m->end_us[2 * f + end] = U;
    }
    if (m->ftype[f] == TFP_FACE_CLOSED) m->uf[f] = m->us[f] = 0.0;
    if (m->ftype[f] != TFP_FACE_INLET) continue;
    int inside = m->fv.lo[f] >= 0 ? m->fv.lo[f] : m->fv.hi[f];
    double x = dir == 0 ? xf[f % (m->fv.nx + 1)] : m->fv.xc[(f - m->fv.nfx) % m->fv.nx];
    double y = dir == 0 ? m->fv.yc[f / (m->fv.nx + 1)] : yf[(f - m->fv.nfx) / m->fv.nx];
    double v[4] = {x, y, t, m->c.case_index};
    double U = m->col_inlet_given ? m->col_inlet : sl_expr_eval(m->b[m->fv.bound[f]].velocity.e, v);
    if (!isfinite(U))
      return sl_diag_set(d, SL_EFAILED, "the inlet velocity is not a finite number (%g) at (%g, %g), t = %g", U, x, y,
                         t);
    double inward = m->fv.lo[f] < 0 ? 1.0 : -1.0;
    double J = 0.0;
    const sl_scene_expr *je = &m->b[m->fv.bound[f]].solids_flux;
    if (je->e && !(isfinite(J = sl_expr_eval(je->e, v)) && J >= 0.0))
      return sl_diag_set(d, SL_EFAILED,
                         "the inlet's solids flux is %g at (%g, %g), t = %g: it must be finite and "
                         "not negative",
                         J, x, y, t);
    m->js[f] = inward * J;
    m->us[f] = phi[inside] > PHI_FLOOR ? m->js[f] / phi[inside] : 0.0;
    m->uf[f] = inward * U / (1.0 - phi[inside]);
  }
  return 0;
}

/* ---- the linear system ------------------------------------------------------------ */

/* A(row, col) += v: into the triplets, or on the fast path straight into the band (a given value, row or col
 * negative, skipped as the triplets skip it; an entry outside the bands sends the step back to the general
 * path). */
static inline int add(tfp_model *m, int row, int col, double v) {
  if (!m->band_on) return sl_triplets_add(&m->trip, row, col, v);
  if (row >= 0 && col >= 0 && sl_band_add(&m->band, m->band_of[row], m->band_of[col], v)) m->band_miss = 1;
  return 0;
}

/* The face's phi in its momentum equations and its continuity flux: the
 * cell on gravity's side of it, the mean of its two cells when gravity runs
 * along it, the inside cell at the boundary. */
static double face_phi(const tfp_model *m, const double *phi, int f) {
  int lo = m->fv.lo[f], hi = m->fv.hi[f];
  double v;
  if (lo < 0 && hi < 0) return PHI_FLOOR; /* a dead face (inside a body): unused */
  if (lo < 0 || hi < 0) v = phi[lo < 0 ? hi : lo];
  else {
    double gd = m->g[face_dir(m, f)];
    /* the column without gravity takes the cell below (two_fluid.h) */
    v = gd < 0.0 || (gd == 0.0 && m->column) ? phi[lo] : gd > 0.0 ? phi[hi] : 0.5 * (phi[lo] + phi[hi]);
  }
  return fmax(v, PHI_FLOOR);
}

/* The phase's viscosity at a cell (phase 0 fluid: eps mu_f; 1 solids: that of tfp_solids_viscosity), and its
 * tangent (the solids' stress grows faster than mu_s with the shear rate). */
static double phase_mu(const tfp_model *m, int phase, const double *phi, int c) {
  return phase == 0 ? (1.0 - phi[c]) * m->c.mu_f : m->s.mu[c];
}
static double phase_mu_t(const tfp_model *m, int phase, const double *phi, int c) {
  return phase == 0 ? (1.0 - phi[c]) * m->c.mu_f : m->s.mu_t[c];
}

/* A viscous flux k (u_row - u_nb) into row, Newton-linearised with the tangent kt at the iterate un (u_nb
 * given when nb has no row: `fixed`). */
static int flux_term(tfp_model *m, int row, int nb_row, double fixed, double k, double kt, double u0, double unb0) {
  int rc = add(m, row, row, kt);
  if (nb_row >= 0) rc |= add(m, row, nb_row, -kt);
  else m->rhs[row] += kt * fixed, unb0 = fixed;
  m->rhs[row] += (kt - k) * (u0 - unb0);
  return rc;
}

/* -div(mu grad u) of the phase's normal velocity at face f, times the dual
 * volume (the Laplacian of the face-velocity grid, five points; the
 * axisymmetric hoop term mu u_r / r^2 for x-faces), added to row. Along a
 * wall the phase sticks to the wall's speed, slips freely, or (solids) feels
 * the wall closure's stress. */
static int viscous(tfp_model *m, int phase, int f, int row, const double *phi, sl_diag *d) {
  const int nx = m->fv.nx, ny = m->fv.ny, dir = face_dir(m, f);
  const int *rows = phase ? m->us_row : m->uf_row;
  const double *u = phase ? m->us : m->uf, *un = phase ? m->us_new : m->uf_new;
  const double *xf = m->grid.xf;
  int i, j;
  if (dir == 0) i = f % (nx + 1), j = f / (nx + 1);
  else i = (f - m->fv.nfx) % nx, j = (f - m->fv.nfx) / nx;
  int rc = 0;
  /* along the normal: through the cells lo and hi to their far faces of the same family */
  for (int side = 0; side < 2; ++side) {
    int c = side ? m->fv.hi[f] : m->fv.lo[f];
    if (c < 0) continue; /* an outlet: zero normal gradient */
    int ci = c % nx, cj = c / nx, cf[4];
    cell_faces(m, c, cf);
    int nb = cf[2 * dir + side];
    double across =
        dir == 0 ? m->fv.hy[cj] * (m->axi ? m->fv.xc[ci] : 1.0) : m->fv.hx[ci] * (m->axi ? m->fv.xc[ci] : 1.0);
    double h = dir == 0 ? m->fv.hx[ci] : m->fv.hy[cj];
    double k = phase_mu(m, phase, phi, c) * across / h, kt = phase_mu_t(m, phase, phi, c) * across / h;
    rc |= flux_term(m, row, rows[nb], u[nb], k, kt, un[f], un[nb]);
  }
  /* across: to the faces of the same family in the neighbouring rows (x-faces) or columns (y-faces) */
  int n_across = dir == 0 ? ny : nx, a = dir == 0 ? j : i;
  const double *hs = dir == 0 ? m->fv.hy : m->fv.hx;
  for (int end = 0; end < 2; ++end) {
    int to = end ? a + 1 : a - 1;
    int wall = to < 0 || to >= n_across;
    if (wall && m->fv.periodic[1 - dir]) to = (to + n_across) % n_across, wall = 0;
    if (!wall && m->fv.blocked) wall = tfp_dead(m, dir == 0 ? i + (nx + 1) * to : m->fv.nfx + to + nx * j); /* a body */
    /* the corner's radius and the dual length of the face */
    double r_corner = dir == 0 ? xf[i] : xf[end ? i + 1 : i];
    double across = m->fv.dist[f] * (m->axi ? r_corner : 1.0);
    /* the viscosity at the corner: the mean of the cells around it */
    double mu = 0.0, mut = 0.0;
    if (phase == 1) { /* the solids' viscosity at the corner's own shear rate */
      int k = dir == 0 ? i + (nx + 1) * (j + end) : (i + end) + (nx + 1) * j;
      mu = m->s.mu_k_corner[k], mut = m->s.mu_tk[k];
    } else { /* the fluid's: the mean of the cells around the corner */
      int nmu = 0;
      for (int s = 0; s < 2; ++s) {
        int c = s ? m->fv.hi[f] : m->fv.lo[f];
        if (c < 0) continue;
        mu += phase_mu(m, phase, phi, c), ++nmu;
        int cn = tfp_neighbour(m, c, 1 - dir, end);
        if (cn >= 0) mu += phase_mu(m, phase, phi, cn), ++nmu;
      }
      mu /= nmu, mut = mu;
    }
    if (wall) {
      double h = hs[a];
      int e = 2 * f + end;
      if (m->tan_noslip[4 * f + 2 * phase + end]) { /* the wall at half a cell, moving at its speed */
        rc |= flux_term(m, row, -1, m->end_u[e], mu * across / (0.5 * h), mut * across / (0.5 * h), un[f], 0.0);
      } else if (phase == 1 && m->end_wall[e] >= 0 && m->b[m->end_wall[e]].solids == TFP_SOLIDS_WALL_STRESS) {
        double R0, dR;
        int wrc = tfp_solids_wall(m, f, end, mu, h, &R0, &dR, d);
        if (wrc) return wrc;
        rc |= add(m, row, row, across * dR);
        m->rhs[row] += across * (dR * m->us_new[f] - R0);
      }
      continue; /* free slip: no stress */
    }
    int nb = dir == 0 ? i + (nx + 1) * to : m->fv.nfx + to + nx * j;
    const double *cs = dir == 0 ? m->fv.yc : m->fv.xc; /* the centres' distance, half cells across a periodic seam */
    double gap = to == a + (end ? 1 : -1) ? fabs(cs[to] - cs[a]) : 0.5 * (hs[a] + hs[to]);
    rc |= flux_term(m, row, rows[nb], u[nb], mu * across / gap, mut * across / gap, un[f], un[nb]);
  }
  if (dir == 0 && m->axi) { /* mu u_r / r^2 over the dual volume */
    double mu = 0.0;
    int nmu = 0;
    if (m->fv.lo[f] >= 0) mu += phase_mu(m, phase, phi, m->fv.lo[f]), ++nmu;
    if (m->fv.hi[f] >= 0) mu += phase_mu(m, phase, phi, m->fv.hi[f]), ++nmu;
    rc |= add(m, row, row, mu / nmu * m->fv.area[f] * m->fv.dist[f] / (xf[i] * xf[i]));
  }
  if (rc) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  return 0;
}

/* The weights of a b du/ds at a point between neighbours at distances h[0]
 * behind and h[1] ahead: central, or upwind (the neighbour the flow comes
 * from); w[0], w[1] the neighbours', w[2] the point's own. */
static void difference_weights(double ab, const double h[2], int upwind, double w[3]) {
  if (!upwind) w[0] = -ab / (h[0] + h[1]), w[1] = -w[0], w[2] = 0.0;
  else if (ab >= 0.0) w[0] = -ab / h[0], w[1] = 0.0, w[2] = ab / h[0];
  else w[0] = 0.0, w[1] = ab / h[1], w[2] = -ab / h[1];
}

/* rho alpha (a . grad) u of the phase's normal velocity u at face f, times
 * its dual volume (rho_alpha_V), added to row: the advective form, a the
 * phase's velocity of the last iterate (Picard), its tangential component
 * the mean of the four faces of the other family around f; differences
 * between the neighbouring faces of f's family (one-sided at an outlet), a
 * wall's velocity half a cell off (its speed where the phase sticks, the
 * solids' slip velocity under a wall stress, f's own where the phase slips
 * freely). Axisymmetric, without swirl, the form is the same. The fluid's
 * differences are central (second order); the solids' are upwind: their
 * velocity jumps at a bed's surface, and central differences there
 * oscillated, lifted solids into the freeboard and blew fluidized_bed_2d's
 * first step up (solids at 400 m/s by its 9th iteration). */
static int convection(tfp_model *m, int phase, int f, int row, double rho_alpha_V, int upwind) {
  const int nx = m->fv.nx, ny = m->fv.ny, dir = face_dir(m, f);
  const int *rows = phase ? m->us_row : m->uf_row;
  const double *un = phase ? m->us_new : m->uf_new;
  const int lo = m->fv.lo[f], hi = m->fv.hi[f];
  int rc = 0;
/* an entry coef u_g of face g: its unknown, or its given value */
#define TERM(g, coef) ((rows[g] >= 0) ? add(m, row, rows[g], (coef)) : (m->rhs[row] -= (coef)*un[g], 0))
  /* along the normal: the same family's faces beyond the cells lo and hi */
  {
    int nb[2] = {-1, -1};
    double h[2] = {0.0, 0.0};
    for (int side = 0; side < 2; ++side) {
      int c = side ? hi : lo;
      if (c < 0) continue;
      int cf[4];
      cell_faces(m, c, cf);
      nb[side] = cf[2 * dir + side], h[side] = dir == 0 ? m->fv.hx[c % nx] : m->fv.hy[c / nx];
    }
    double an = un[f];
    if (nb[0] >= 0 && nb[1] >= 0) {
      double w[3];
      difference_weights(rho_alpha_V * an, h, upwind, w);
      rc |= TERM(nb[0], w[0]), rc |= TERM(nb[1], w[1]), rc |= add(m, row, row, w[2]);
    } else { /* an outlet: one-sided, into the vessel */
      int in = nb[0] >= 0 ? 0 : 1;
      double k = rho_alpha_V * an / h[in] * (in ? 1.0 : -1.0);
      rc |= TERM(nb[in], k), rc |= add(m, row, row, -k);
    }
  }
  /* across: the tangential velocity, and the same family's faces in the neighbouring rows (x-faces) or columns */
  {
    double at = 0.0;
    int nt = 0;
    for (int side = 0; side < 2; ++side) {
      int c = side ? hi : lo;
      if (c < 0) continue;
      int cf[4];
      cell_faces(m, c, cf);
      at += un[cf[2 * (1 - dir)]] + un[cf[2 * (1 - dir) + 1]], nt += 2;
    }
    at /= nt;
    int i, j;
    if (dir == 0) i = f % (nx + 1), j = f / (nx + 1);
    else i = (f - m->fv.nfx) % nx, j = (f - m->fv.nfx) / nx;
    int n_across = dir == 0 ? ny : nx, a = dir == 0 ? j : i;
    const double *hs = dir == 0 ? m->fv.hy : m->fv.hx, *cs = dir == 0 ? m->fv.yc : m->fv.xc;
    int g[2];
    double dist[2], wall_value[2];
    for (int end = 0; end < 2; ++end) {
      int to = end ? a + 1 : a - 1;
      g[end] = -1;
      int body = to >= 0 && to < n_across && m->fv.blocked &&
                 tfp_dead(m, dir == 0 ? i + (nx + 1) * to : m->fv.nfx + to + nx * j);
      if (to < 0 || to >= n_across || body) {
        if (m->fv.periodic[1 - dir]) to = (to + n_across) % n_across;
        else { /* a wall (or an open side, or a body's wall) half a cell off */ int e = 2 * f + end;
          dist[end] = 0.5 * hs[a];
          if (m->tan_noslip[4 * f + 2 * phase + end]) wall_value[end] = m->end_u[e];
          else if (phase == 1 && m->end_wall[e] >= 0 && m->b[m->end_wall[e]].solids == TFP_SOLIDS_WALL_STRESS)
            wall_value[end] = m->end_us[2 * tfp_primary(m, f) + end];
          else g[end] = f; /* free slip: no gradient across */
          continue;
        }
      }
      g[end] = dir == 0 ? i + (nx + 1) * to : m->fv.nfx + to + nx * j;
      dist[end] = to == a + (end ? 1 : -1) ? fabs(cs[to] - cs[a]) : 0.5 * (hs[a] + hs[to]);
    }
    double w[3];
    difference_weights(rho_alpha_V * at, dist, upwind, w);
    rc |= add(m, row, row, w[2]);
    for (int end = 0; end < 2; ++end) {
      if (g[end] >= 0) rc |= TERM(g[end], w[end]);
      else m->rhs[row] -= w[end] * wall_value[end];
    }
  }
#undef TERM
  return rc;
}

/* Drag and solids pressure at the iterate: K, dK/d|s| and the normal slip at
 * every face, P_s and dP_s/dphi in the cells. */
static int closures(tfp_model *m, const double *phi_drag, const double *phi, sl_diag *d) {
  /* the faces with momentum equations: all, or the column's (contiguous; the others are closed) */
  const int fa = m->column ? m->col_face[0] : 0, fb = m->column ? m->col_face[m->col_n] + 1 : m->fv.nf;
  for (int f = fa; f < fb; ++f) {
    m->phf[f] = face_phi(m, phi_drag, f);
    /* the weight's phi: implicit, Newton-coupled (below); the column's is the drag's */
    m->phg[f] = m->column ? m->phf[f] : face_phi(m, m->phi_frozen ? m->phi : phi, f);
    /* the transverse slip: the mean over the faces of the other family around f */
    double st = 0.0;
    int n = 0;
    for (int s = 0; s < 2; ++s) {
      int c = s ? m->fv.hi[f] : m->fv.lo[f];
      if (c < 0) continue;
      int cf[4];
      cell_faces(m, c, cf);
      int a = face_dir(m, f) == 0 ? 2 : 0;
      st += (m->uf_new[cf[a]] - m->us_new[cf[a]]) + (m->uf_new[cf[a + 1]] - m->us_new[cf[a + 1]]), n += 2;
    }
    m->sn[f] = m->uf_new[f] - m->us_new[f];
    if (n) st /= n; /* a dead face (inside a body): none */
    m->slip[f] = hypot(m->sn[f], st);
  }
  int rc = tf_closure_eval(&m->c.drag, fb - fa, m->phf + fa, m->slip + fa, m->K + fa, m->dK + fa, d);
  if (rc) return sl_diag_prefix(d, rc, "drag");
  for (int f = fa; f < fb; ++f)
    if (!isfinite(m->K[f]) || m->K[f] < 0.0 || !isfinite(m->dK[f]))
      return sl_diag_set(d, SL_EFAILED, "[closure.drag] gave K = %g (dK/dslip = %g) at face %d, phi = %g, slip %g m/s",
                         m->K[f], m->dK[f], f, m->phf[f], m->slip[f]);
  if (m->c.ps.c) {
    if ((rc = tf_closure_eval(&m->c.ps, m->fv.nc, phi, NULL, m->ps, m->dps, d)))
      return sl_diag_prefix(d, rc, "solids pressure");
  } else {
    memset(m->ps, 0, (size_t)m->fv.nc * sizeof *m->ps), memset(m->dps, 0, (size_t)m->fv.nc * sizeof *m->dps);
  }
  if ((rc = tfp_solids_pressure(m, phi, m->ps, m->dps, d))) return rc; /* the kinetic theory's, added */
  for (int c = 0; c < m->fv.nc; ++c) m->dps[c] = fmax(m->dps[c], 0.0); /* a softening law would be unstable */
  for (int f = 0; f < m->fv.nf; ++f) {                                 /* the transport's upwind phi of the iterate */
    double lo = m->fv.lo[f] >= 0 ? phi[m->fv.lo[f]] : 0.0, hi = m->fv.hi[f] >= 0 ? phi[m->fv.hi[f]] : 0.0;
    m->w[f] = m->us_new[f] > 0.0 ? lo : m->us_new[f] < 0.0 ? hi : fmax(lo, hi);
  }
  return 0;
}

/* The linearised system at the iterate (us_new, uf_new, phi) into triplets and rhs. */
static int assemble(tfp_model *m, double dt, sl_diag *d) {
  const double rho_s = m->c.rho_s, rho_f = m->c.rho_f;
  const int P = m->n_vel;
  int rc = 0;
  if (m->band_on) sl_band_zero(&m->band), m->band_miss = 0;
  else sl_triplets_clear(&m->trip);
  memset(m->rhs, 0, (size_t)m->n_unknowns * sizeof *m->rhs);
  for (int f = 0; f < m->fv.nf; ++f) {
    int rs = m->us_row[f], rf = m->uf_row[f];
    if (rs < 0 || m->ftype[f] == TFP_FACE_IMAGE) continue;
    const int lo = m->fv.lo[f], hi = m->fv.hi[f], dir = face_dir(m, f);
    const double ph = m->phf[f], eps = 1.0 - ph, A = m->fv.area[f], V = A * m->fv.dist[f], gd = m->g[dir];
    const double K = m->K[f], s = m->sn[f];
    double Keff = K + (m->slip[f] > 0.0 ? m->dK[f] * s * s / m->slip[f] : 0.0);
    Keff = fmax(Keff, 0.0);
    const double p_out = (lo < 0 || hi < 0) ? m->b[m->fv.bound[f]].pressure : 0.0;
    /* the weight and the pressure gradient share the iterate's phi_g (never frozen) */
    const double pg = m->phg[f], eg = 1.0 - pg;
    /* the body force per unit mass of each phase along the face's normal: gravity, and with [two_fluid]
       centrifugal on a radial face the swirl's u_theta^2 / r = Omega^2 r of the accepted step (Bird, Stewart &
       Lightfoot 2002, Table B.6, the r-component's rho u_theta^2 / r), Omega the mean of the face's cells */
    double gs = gd, gf = gd;
    if (m->centrifugal && dir == 0) {
      double om[2] = {0.0, 0.0}, rr = m->grid.xf[f % (m->fv.nx + 1)];
      for (int phase = 0; phase < 2; ++phase) {
        int n = 0;
        for (int side = 0; side < 2; ++side) {
          int c = side ? hi : lo;
          if (c >= 0) om[phase] += m->sw.om[phase * m->fv.nc + c], ++n;
        }
        om[phase] /= n;
      }
      gf += om[0] * om[0] * rr, gs += om[1] * om[1] * rr;
    }
    /* solids */
    rc |= add(m, rs, rs, V * (ph * rho_s / dt + Keff));
    rc |= add(m, rs, rf, -V * Keff);
    m->rhs[rs] += V * (ph * rho_s * m->us[f] / dt + pg * rho_s * gs - (Keff - K) * s);
    /* fluid */
    rc |= add(m, rf, rf, V * (eps * rho_f / dt + Keff));
    rc |= add(m, rf, rs, -V * Keff);
    /* the column's fluid inertia is that of its mixture flux j: with u_f = (j - phi u_s)/eps at the face's phi
       of the iterate, the old u_f is (j_old - phi u_s,old)/eps (two_fluid.h eliminates p so) */
    const double uf_old = m->column ? (m->col_j - ph * m->us[f]) / eps : m->uf[f];
    m->rhs[rf] += V * (eps * rho_f * uf_old / dt + eg * rho_f * gf + (Keff - K) * s);
    /* the pressure gradient, A (p_hi - p_lo), p_out outside */
    for (int side = 0; side < 2; ++side) {
      int c = side ? hi : lo;
      double sg = side ? 1.0 : -1.0;
      if (c >= 0) rc |= add(m, rs, P + c, sg * A * pg), rc |= add(m, rf, P + c, sg * A * eg);
      else m->rhs[rs] -= sg * A * pg * p_out, m->rhs[rf] -= sg * A * eg * p_out;
    }
    /* Newton in phi_g: its change with the solids velocities, dphi_c = -(dt/V_c) sum sigma A w delta u_s of the
       cell(s) it is read from, moves weight against the pressure gradient between the phases: + (rho_s g -
       dp/dn) on the solids, - (rho_f g - dp/dn) on the fluid. Without it the weight lags the transport, and
       a stratified suspension (the smeared top of a settling one) overturns once N dt exceeds about 1, N the
       buoyancy frequency. */
    if (!m->column) { /* emitted for every face (zero where phi_g is floored), so that the pattern stays the same;
                         the column's weight takes the drag's phi, with nothing to linearise */
      double gradp = lo >= 0 && hi >= 0 ? (m->p_new[hi] - m->p_new[lo]) / m->fv.dist[f]
                     : lo < 0           ? (m->p_new[hi] - p_out) / m->fv.dist[f]
                                        : (p_out - m->p_new[lo]) / m->fv.dist[f];
      double Ss = pg > PHI_FLOOR ? V * (rho_s * gs - gradp) : 0.0,
             Sf = pg > PHI_FLOOR ? -V * (rho_f * gf - gradp) : 0.0;
      int src[2] = {-1, -1};
      double wt[2] = {1.0, 0.0};
      if (lo < 0 || hi < 0) src[0] = lo < 0 ? hi : lo;
      else if (gd != 0.0) src[0] = gd < 0.0 ? lo : hi;
      else src[0] = lo, src[1] = hi, wt[0] = wt[1] = 0.5;
      int cols[8], nc = 0;
      double dphi[8];
      for (int q = 0; q < 2; ++q) {
        int c = src[q];
        if (c < 0) continue;
        int cf[4];
        cell_faces(m, c, cf);
        /* one Euler step's dphi over-predicts the sub-stepped transport beyond a Courant number of 1 (a bed
           blown out at 0.5 m/s): the derivative is scaled back steeply by it */
        double courant = 0.0;
        for (int k = 0; k < 4; ++k) courant += 0.5 * dt * fabs(m->fv.area[cf[k]] * m->us_new[cf[k]]) / m->fv.vol[c];
        double damp = pow(fmax(1.0, courant), -4.0);
        for (int k = 0; k < 4; ++k)
          if (m->us_row[cf[k]] >= 0)
            cols[nc] = cf[k],
            dphi[nc++] = damp * wt[q] * (-(dt / m->fv.vol[c]) * SIGMA[k] * m->fv.area[cf[k]] * m->w[cf[k]]);
      }
      /* Dilute faces: the weight's sensitivity, drho g per unit phi, does not fall with phi as the row's inertia
         and drag do, and would take the row over (a bed blown out leaves such faces): the term is kept to half
         the row's diagonal. */
      double big = 0.0, diag = V * (ph * rho_s / dt + Keff), scale = 1.0;
      for (int q = 0; q < nc; ++q) big = fmax(big, fabs(Ss * dphi[q]));
      if (big > 0.5 * diag) scale = 0.5 * diag / big;
      if (m->phi_frozen) scale = 0.0; /* phi_g is the step's start: nothing to linearise */
      for (int q = 0; q < nc; ++q) {
        double ds = scale * dphi[q];
        rc |= add(m, rs, m->us_row[cols[q]], -Ss * ds);
        rc |= add(m, rf, m->us_row[cols[q]], -Sf * ds);
        m->rhs[rs] -= Ss * ds * m->us_new[cols[q]];
        m->rhs[rf] -= Sf * ds * m->us_new[cols[q]];
      }
    }
    /* the solids pressure gradient, linearised in the solids velocities of both cells' faces (P_s = 0 outside) */
    for (int side = 0; side < 2; ++side) {
      int c = side ? hi : lo;
      if (c < 0) continue;
      double sg = side ? 1.0 : -1.0;
      m->rhs[rs] -= sg * A * m->ps[c];
      int cf[4];
      cell_faces(m, c, cf);
      for (int k = 0; k < 4; ++k) {
        int gface = cf[k];
        if (m->us_row[gface] < 0) continue;
        double coef = sg * A * m->dps[c] * (-(dt / m->fv.vol[c]) * SIGMA[k] * m->fv.area[gface] * m->w[gface]);
        rc |= add(m, rs, m->us_row[gface], coef);
        m->rhs[rs] += coef * m->us_new[gface];
      }
    }
    if (m->convection) {
      rc |= convection(m, 0, f, rf, V * eps * rho_f, 0);
      rc |= convection(m, 1, f, rs, V * ph * rho_s, 1);
    }
    if (rc) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
    if (!m->column && (rc = viscous(m, 0, f, rf, m->phi_new, d))) return rc; /* the column has no fluid stress */
    if (m->s.any && (rc = viscous(m, 1, f, rs, m->phi_new, d))) return rc;
  }
  /* continuity: the mixture's volume flux out of each cell; in a closed vessel cell 0 holds the datum p = 0 */
  for (int c = 0; c < m->fv.nc; ++c) {
    int row = P + c;
    if ((m->closed && c == m->datum) || tfp_blocked(m, c)) { /* the datum p = 0; a body's cell: p = 0, unused */
      rc |= add(m, row, row, 1.0);
      continue;
    }
    rc |= add(m, row, row, 0.0);
    int cf[4];
    cell_faces(m, c, cf);
    for (int k = 0; k < 4; ++k) {
      int f = cf[k];
      double A = SIGMA[k] * m->fv.area[f], ph = m->phf[f];
      if (m->us_row[f] >= 0) {
        rc |= add(m, row, m->us_row[f], A * ph);
        rc |= add(m, row, m->uf_row[f], A * (1.0 - ph));
      } else if (m->ftype[f] == TFP_FACE_INLET) { /* eps u_f of the inside cell: the given superficial velocity */
        int in = m->fv.lo[f] >= 0 ? m->fv.lo[f] : m->fv.hi[f];
        m->rhs[row] -= A * ((1.0 - m->phi[in]) * m->uf[f] + m->js[f]);
      }
    }
  }
  if (rc) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  return 0;
}

/* The mean shear stress of each phase on every wall and the solids slip
 * there, at the converged iterate: the stress the phase exerts on the wall
 * along the wall's positive direction. */
static int wall_stresses(tfp_model *m, sl_diag *d) {
  double *w = m->wall_stats;
  memset(w, 0, 5 * (size_t)m->n_b * sizeof *w);
  for (int f = 0; f < m->fv.nf; ++f)
    for (int end = 0; end < 2; ++end) {
      int e = 2 * f + end, b = m->end_wall[e];
      if (b < 0 || m->ftype[f] != TFP_FACE_INTERIOR) continue;
      int dir = face_dir(m, f), a = dir == 0 ? f / (m->fv.nx + 1) : (f - m->fv.nfx) % m->fv.nx;
      double h = dir == 0 ? m->fv.hy[a] : m->fv.hx[a];
      double r = m->axi ? (dir == 0 ? m->grid.xf[f % (m->fv.nx + 1)] : m->grid.xf[a + end]) : 1.0;
      double len = m->fv.dist[f] * r, U = m->end_u[e], muf = 0.0, bn = NAN;
      int n = 0;
      for (int s = 0; s < 2; ++s) {
        int c = s ? m->fv.hi[f] : m->fv.lo[f];
        if (c >= 0) muf += (1.0 - m->phi_new[c]) * m->c.mu_f, ++n;
      }
      muf /= n;
      /* the solids' viscosity of the wall corner, as the momentum equation took it */
      int i = dir == 0 ? f % (m->fv.nx + 1) : (f - m->fv.nfx) % m->fv.nx,
          j = dir == 0 ? f / (m->fv.nx + 1) : (f - m->fv.nfx) / m->fv.nx;
      double mus = m->s.mu_k_corner[dir == 0 ? i + (m->fv.nx + 1) * (j + end) : (i + end) + (m->fv.nx + 1) * j];
      double tf = muf * (m->uf_new[f] - U) / (0.5 * h), ts = 0.0, slip = 0.0;
      if (m->b[b].solids == TFP_SOLIDS_NO_SLIP) ts = mus * (m->us_new[f] - U) / (0.5 * h);
      else if (m->b[b].solids == TFP_SOLIDS_WALL_STRESS) {
        double R0, dR;
        int rc = tfp_solids_wall(m, f, end, mus, h, &R0, &dR, d);
        if (rc) return rc;
        ts = R0, slip = m->end_us[e] - U, bn = m->s.last_bagnold;
      } else slip = m->us_new[f] - U;
      w[5 * b] += len * tf, w[5 * b + 1] += len * ts, w[5 * b + 2] += len * slip, w[5 * b + 3] += len * bn;
      w[5 * b + 4] += len;
    }
  for (int b = 0; b < m->n_b; ++b)
    if (w[5 * b + 4] > 0.0)
      for (int k = 0; k < 4; ++k) w[5 * b + k] /= w[5 * b + 4];
  return 0;
}

/* ---- the 1-D column as the grid's one-cell-wide case ------------------------------------ */

/* The column's mixture flux along +col_dir at the inlet's current value (tfp_boundary_values, with the step's
 * starting phi of its cell), 0 without an inlet. */
static double column_flux(const tfp_model *m) {
  for (int e = 0; e < 2; ++e) {
    int f = m->col_face[e ? m->col_n : 0];
    if (m->ftype[f] != TFP_FACE_INLET) continue;
    int in = m->fv.lo[f] >= 0 ? m->fv.lo[f] : m->fv.hi[f];
    return (1.0 - m->phi[in]) * m->uf[f];
  }
  return 0.0;
}

int tfp_column_start(tfp_model *m, int fluid_given, const char *where, sl_diag *d) {
  const int nx = m->fv.nx, ny = m->fv.ny, dir = ny > 1 ? 1 : 0, n = dir ? ny : nx;
  if ((dir ? nx : ny) != 1 || n < 2)
    return sl_diag_set(d, SL_EBADINPUT, "%s: the column's form needs a grid one cell across (%d x %d cells)", where, nx,
                       ny);
  if (m->g[1 - dir] != 0.0 || m->fv.periodic[dir] || m->axi || m->s.any || m->convection || m->accelerate)
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: the column's form needs gravity along the column (%s), no periodic ends, "
                       "a planar scene, no solids stress, no [flow] convection and no acceleration",
                       where, dir ? "along y" : "along x");
  m->column = 1, m->col_dir = dir, m->col_n = n;
  if (!(m->col_face = malloc((size_t)(n + 1) * sizeof *m->col_face)) ||
      !(m->col_uf0 = calloc((size_t)m->fv.nf, sizeof *m->col_uf0)))
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  for (int k = 0; k <= n; ++k) m->col_face[k] = dir ? m->fv.nfx + k : k;
  m->col_j = column_flux(m);
  if (!fluid_given) /* the column's start: the fluid carries the inflow through every cell, u_s = 0 */
    for (int k = 0; k <= n; ++k) {
      int cell = k == 0 ? 0 : k == n ? n - 1 : (m->g[dir] <= 0.0 ? k - 1 : k);
      m->uf[m->col_face[k]] = m->col_j / (1.0 - m->phi[cell]);
    }
  return 0;
}

void tfp_column_restored(tfp_model *m) {
  /* the faces hold u_f = (j - phi u_s)/eps; an end face has u_s = 0 unless it is an outlet */
  int f = m->col_face[0];
  double ph = face_phi(m, m->phi, f);
  m->col_j = ph * m->us[f] + (1.0 - ph) * m->uf[f];
}

/* The converged column step's fluid velocity and pressure at the step's final phi, as the 1-D column gives them
 * (two_fluid.h): u_f = (j - phi u_s)/eps at every face, and dp/dx from the fluid momentum,
 * dp/dx = rho_f g - K s/eps - rho_f du_f/dt, s = (j - u_s)/eps, summed from the outlet (or from p = 0 at the
 * top of a closed column) over the centres' distances. */
static int column_finish(tfp_model *m, double dt, sl_diag *d) {
  const int n = m->col_n;
  const double j = column_flux(m), g = m->g[m->col_dir], rho_f = m->c.rho_f;
  double *ph = m->phg, *slip = m->sn, *K = m->K, *dK = m->dK, *dpdx = m->flux;
  for (int k = 0; k <= n; ++k) {
    int f = m->col_face[k];
    ph[k] = face_phi(m, m->phi_new, f);
    slip[k] = fabs(j - m->us_new[f]) / (1.0 - ph[k]);
  }
  int rc = tf_closure_eval(&m->c.drag, n + 1, ph, slip, K, dK, d);
  if (rc) return sl_diag_prefix(d, rc, "drag");
  for (int k = 0; k <= n; ++k) {
    int f = m->col_face[k];
    double eps = 1.0 - ph[k], s = (j - m->us_new[f]) / eps;
    m->uf_new[f] = (j - ph[k] * m->us_new[f]) / eps;
    dpdx[k] = rho_f * g - K[k] * s / eps - rho_f * (m->uf_new[f] - m->col_uf0[f]) / dt;
  }
  const int f0 = m->col_face[0], f1 = m->col_face[n];
  const int out0 = m->ftype[f0] == TFP_FACE_OUTLET, out1 = m->ftype[f1] == TFP_FACE_OUTLET;
  const double *L = m->fv.dist; /* half cells at the ends, centre to centre inside */
  if (out0 && !out1) {
    m->p_new[0] = m->b[m->fv.bound[f0]].pressure + L[f0] * dpdx[0];
    for (int i = 1; i < n; ++i) m->p_new[i] = m->p_new[i - 1] + L[m->col_face[i]] * dpdx[i];
  } else {
    m->p_new[n - 1] = (out1 ? m->b[m->fv.bound[f1]].pressure : 0.0) - L[f1] * dpdx[n];
    for (int i = n - 2; i >= 0; --i) m->p_new[i] = m->p_new[i + 1] - L[m->col_face[i + 1]] * dpdx[i + 1];
  }
  for (int i = 0; i < n; ++i)
    if (!isfinite(m->p_new[i])) return sl_diag_set(d, SL_EFAILED, "the pressure is not finite in cell %d", i);
  m->col_j_new = j;
  return 0;
}

/* ---- the fast path of a grid one cell across ------------------------------------------- */

/* Bands wider than this go the general way (the banded LU's work grows as n kl (kl + ku)). */
enum { BAND_MAX = 16 };

/* Once, at the first system (in m->A): on a grid one cell across, not periodic along it, the unknowns numbered
 * along the grid, each face's before the cell beyond it (the faces across the grid and the pressure with their
 * cell), make a banded matrix; the column's has kl = ku = 3 (a face's momentum couples the pressures of its two
 * cells and, through P_s's Newton term, the faces of both; a cell's continuity its two faces). Bands at most
 * BAND_MAX wide turn the fast path on, with this system copied into the band. */
static int band_start(tfp_model *m, sl_diag *d) {
  m->band_allowed = 0; /* decided once */
  const int nx = m->fv.nx, ny = m->fv.ny, dir = ny == 1 ? 0 : 1, n = m->n_unknowns;
  if ((nx != 1 && ny != 1) || m->fv.periodic[dir]) return 0;
  int32_t *key = malloc((size_t)n * sizeof *key), kl = 0, ku = 0;
  if (!key || !(m->band_of = malloc((size_t)n * sizeof *m->band_of)) ||
      !(m->band_x = malloc((size_t)n * sizeof *m->band_x))) {
    free(key);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  for (int f = 0; f < m->fv.nf; ++f) {
    if (m->us_row[f] < 0 || m->ftype[f] == TFP_FACE_IMAGE) continue;
    int fd = face_dir(m, f), i = fd == 0 ? f % (nx + 1) : (f - m->fv.nfx) % nx;
    int j = fd == 0 ? f / (nx + 1) : (f - m->fv.nfx) / nx, along = dir == 0 ? i : j;
    key[m->us_row[f]] = key[m->uf_row[f]] = fd == dir ? 2 * along : 2 * along + 1;
  }
  for (int c = 0; c < m->fv.nc; ++c) key[m->n_vel + c] = 2 * (dir == 0 ? c % nx : c / nx) + 1;
  int rc = sl_band_permutation(&m->A, key, m->band_of, &kl, &ku, d);
  free(key);
  if (rc || kl > BAND_MAX || ku > BAND_MAX) return rc;
  if ((rc = sl_band_init(&m->band, n, kl, ku, d))) return rc;
  for (int r = 0; r < n; ++r)
    for (int32_t e = m->A.row_ptr[r]; e < m->A.row_ptr[r + 1]; ++e)
      sl_band_add(&m->band, m->band_of[r], m->band_of[m->A.col_idx[e]], m->A.values[e]);
  m->band_on = 1;
  return 0;
}

/* x = A^-1 rhs by banded LU, in the band's numbering. */
static int band_solve(tfp_model *m, sl_diag *d) {
  const int n = m->n_unknowns;
  for (int r = 0; r < n; ++r) m->band_x[m->band_of[r]] = m->rhs[r];
  int rc = sl_band_factor(&m->band, d);
  if (rc) return rc;
  sl_band_solve(&m->band, m->band_x);
  for (int r = 0; r < n; ++r) m->x[r] = m->band_x[m->band_of[r]];
  return 0;
}

const char *tfp_linear_name(const tfp_model *m, const char *general) {
  return m->band_on ? "banded LU (a grid one cell across)" : general;
}

sl_linsolve_stats tfp_linear_stats(const tfp_model *m) {
  sl_linsolve_stats st = *sl_linsolve_get_stats(m->ls);
  if (m->band_on) { /* the band's factorisations and solves (the general solver's, none, or before it took over) */
    st.n_numeric += m->band.n_factor, st.n_solves += m->band.n_factor;
    st.refactor_reason[SL_REFACTOR_DIRECT] += m->band.n_factor;
  }
  return st;
}

/* ---- one step ------------------------------------------------------------------------ */

/* Anderson acceleration of the iteration (`[two_fluid] acceleration`,
 * default anderson with a kinetic theory). Parts of the step are lagged
 * by one iteration: a transported theta is solved after the velocities,
 * holding them; the wall's slip under a wall stress is found in the
 * assembly from the last iterate's viscosity; an algebraic theta follows
 * the last shear rate. That iteration converged linearly at best (Johnson
 * & Jackson's planar shear with the transported theta: a rate of 0.7, theta
 * oscillating, 52 iterations a step and half the steps rejected) or fell
 * into a cycle (the same with the algebraic theta, and Navier slip with
 * Lun's theory: no step from rest). The map iterate -> next iterate is
 * accelerated over all it carries from one iteration to the next, [us, uf,
 * theta, the walls' slip velocities, phi], each scaled by its magnitude;
 * phi so accelerated is an affine combination of transported fields (its
 * inventory kept), and a converged step ends on the map's own value. */
static int acceleration_start(tfp_model *m, sl_diag *d) {
  const int n = 4 * m->fv.nf + 2 * m->fv.nc;
  if (!m->acc.n) {
    int rc = sl_anderson_init(&m->acc, n, ANDERSON_DEPTH, d);
    if (rc) return rc;
    m->acc_x = malloc((size_t)n * sizeof *m->acc_x), m->acc_g = malloc((size_t)n * sizeof *m->acc_g);
    m->acc_scale = malloc((size_t)n * sizeof *m->acc_scale);
    if (!m->acc_x || !m->acc_g || !m->acc_scale) return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  sl_anderson_reset(&m->acc);
  return 0;
}

static void pack(const tfp_model *m, double *v) {
  const size_t nf = (size_t)m->fv.nf;
  memcpy(v, m->us_new, nf * sizeof *v), memcpy(v + nf, m->uf_new, nf * sizeof *v);
  memcpy(v + 2 * nf, m->s.theta_new, (size_t)m->fv.nc * sizeof *v);
  memcpy(v + 2 * nf + (size_t)m->fv.nc, m->end_us, 2 * nf * sizeof *v);
  memcpy(v + 4 * nf + (size_t)m->fv.nc, m->phi_new, (size_t)m->fv.nc * sizeof *v);
}

/* The iterate the map starts from; a new map (the iteration's frozen
 * coefficients change at FREEZE_*_AFTER) starts a new history. */
static void acceleration_save(tfp_model *m, int it) {
  if (it == FREEZE_PHI_AFTER + 1 || it == FREEZE_WEIGHT_AFTER + 1) sl_anderson_reset(&m->acc);
  pack(m, m->acc_x);
}

static void acceleration_apply(tfp_model *m, double v_scale, double th_scale) {
  const int nf = m->fv.nf, nc = m->fv.nc;
  pack(m, m->acc_g);
  for (int k = 0; k < 2 * nf; ++k) m->acc_scale[k] = v_scale;
  for (int c = 0; c < nc; ++c) m->acc_scale[2 * nf + c] = th_scale > 0.0 ? th_scale : 1.0;
  for (int k = 0; k < 2 * nf; ++k) m->acc_scale[2 * nf + nc + k] = v_scale;
  for (int c = 0; c < nc; ++c) m->acc_scale[4 * nf + nc + c] = m->c.phi_max;
  sl_anderson_apply(&m->acc, m->acc_x, m->acc_g, m->acc_scale);
  for (int f = 0; f < nf; ++f)
    if (m->us_row[f] >= 0) m->us_new[f] = m->acc_g[f], m->uf_new[f] = m->acc_g[nf + f];
  /* theta stays positive: at most a fivefold fall from the map's value (core/models/granular.h) */
  for (int c = 0; c < nc; ++c) m->s.theta_new[c] = sl_theta_bounded(m->acc_g[2 * nf + c], m->s.theta_new[c]);
  memcpy(m->end_us, m->acc_g + 2 * nf + nc, 2 * (size_t)nf * sizeof *m->end_us);
  /* phi, an affine combination of transported fields (its inventory kept), is what the next iteration's
     closures and weight read; that iteration's transport then replaces it */
  for (int c = 0; c < nc; ++c) m->phi_new[c] = fmin(fmax(m->acc_g[4 * nf + nc + c], 0.0), m->c.phi_max);
}

int tfp_step(tfp_model *m, double t, double dt, sl_diag *d) {
  const int nf = m->fv.nf, nc = m->fv.nc;
  if (m->column) memcpy(m->col_uf0, m->uf, (size_t)nf * sizeof *m->uf);
  int rc = tfp_boundary_values(m, t + dt, m->phi, d);
  if (rc) return rc;
  memcpy(m->us_new, m->us, (size_t)nf * sizeof *m->us);
  memcpy(m->uf_new, m->uf, (size_t)nf * sizeof *m->uf);
  memcpy(m->p_new, m->p, (size_t)nc * sizeof *m->p);
  if (m->s.granular && !m->s.algebraic) memcpy(m->s.theta_new, m->s.theta, (size_t)nc * sizeof *m->s.theta);
  m->substeps_trial = 0, m->iterations_trial = 0;
  double out = 0.0, change = 0.0, umax = 0.0;
  if ((rc = tfp_transport(m, m->us_new, dt, m->phi_new, &out, d))) return rc;
  const int accelerate = m->accelerate;
  if (accelerate && (rc = acceleration_start(m, d))) return rc;
  for (int it = 1; it <= m->c.max_iterations; ++it) {
    m->iterations_trial = it;
    if (accelerate) acceleration_save(m, it);
    m->phi_frozen = it > FREEZE_WEIGHT_AFTER;
    m->sink_frozen = it > FREEZE_PHI_AFTER;
    if ((rc = closures(m, it > FREEZE_PHI_AFTER ? m->phi : m->phi_new, m->phi_new, d))) return rc;
    if ((rc = tfp_solids_viscosity(m, m->us_new, m->phi_new, d))) return rc;
    if ((rc = assemble(m, dt, d))) return rc;
    if (m->band_on && m->band_miss) { /* not banded after all: the general path for good */
      m->band_on = m->band_allowed = 0;
      if ((rc = assemble(m, dt, d))) return rc;
    }
    if (!m->band_on) {
      if ((rc = sl_triplets_to_csr(&m->trip, &m->A, m->n_unknowns, d))) return rc;
      if (m->band_allowed && (rc = band_start(m, d))) return rc;
    }
    rc = m->band_on ? band_solve(m, d) : sl_linsolve_solve(m->ls, &m->A, m->rhs, m->x, d);
    if (rc) return sl_diag_prefix(d, rc, "the coupled solve");
    change = 0.0, umax = 0.0;
    for (int f = 0; f < nf; ++f) {
      if (m->us_row[f] < 0) continue;
      double us = m->x[m->us_row[f]], uf = m->x[m->uf_row[f]];
      if (m->column) { /* the column's measure: the solids velocity (the fluid's follows from j) */
        change = fmax(change, fabs(us - m->us_new[f])), umax = fmax(umax, fabs(us));
      } else {
        change = fmax(change, fmax(fabs(us - m->us_new[f]), fabs(uf - m->uf_new[f])));
        umax = fmax(umax, fmax(fabs(us), fabs(uf)));
      }
      m->us_new[f] = us, m->uf_new[f] = uf;
    }
    for (int c = 0; c < nc; ++c) m->p_new[c] = m->x[m->n_vel + c];
    if (!isfinite(change) || !isfinite(umax))
      return sl_diag_set(d, SL_EFAILED, "the coupled solve gave a non-finite velocity (iteration %d)", it);
    if ((rc = tfp_transport(m, m->us_new, dt, m->phi_new, &out, d))) return rc;
    double dth = 0.0, th_scale = 0.0;
    if (m->s.granular && !m->s.algebraic) {
      if ((rc = tfp_theta_solve(m, dt, &dth, d))) return rc;
      for (int c = 0; c < nc; ++c) th_scale = fmax(th_scale, m->s.theta_new[c]);
    }
    int converged = change <= m->c.tolerance * fmax(m->c.v_ref, umax) && dth <= m->c.tolerance * th_scale;
    if (!converged && accelerate) {
      acceleration_apply(m, fmax(m->c.v_ref, umax), th_scale);
    }
    if (converged) {
      m->outflow_trial = out;
      if ((rc = wall_stresses(m, d))) return rc;
      if (m->column) return column_finish(m, dt, d);
      /* the inlet's u_f with the new phi of its cell */
      for (int f = 0; f < nf; ++f)
        if (m->ftype[f] == TFP_FACE_INLET) {
          int in = m->fv.lo[f] >= 0 ? m->fv.lo[f] : m->fv.hi[f];
          m->uf_new[f] = m->uf[f] * (1.0 - m->phi[in]) / (1.0 - m->phi_new[in]);
          m->us_new[f] = m->phi_new[in] > PHI_FLOOR ? m->js[f] / m->phi_new[in] : 0.0;
        }
      if (m->sw.on) return tfp_swirl_step(m, dt, d); /* two_fluid_plane_swirl.c */
      return 0;
    }
  }
  return sl_diag_set(d, SL_EFAILED,
                     "the implicit step did not converge in %d iterations (last velocity change "
                     "%.3g m/s, tolerance %.3g)",
                     m->c.max_iterations, change, m->c.tolerance * fmax(m->c.v_ref, umax));
}
