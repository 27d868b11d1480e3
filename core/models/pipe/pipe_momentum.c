/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's axial momentum (pipe.h): u_f and u_s in the cells and the
 * pressure gradient G in one bordered linear system, the viscosities, the
 * drag and the wall coefficients of the last iterate:
 *   sum_faces a (u_i - u_nb) + A_w a_w u_i + K V (u_i - u_other) + c V G = c rho g_z V   (each phase)
 * with the drag K(s)(u_f - u_s) linearised about the last slip (Newton in the drag alone),
 *   sum_cells V (c_f u_f + c_s u_s) = V_bulk sum_cells V                                   (the flow rate)
 * or, with [pipe] pressure_gradient, G = -(the given -dP/dz) in its place (the flow rate then follows);
 * a = the face's mean of the cells' effective viscosities times area over
 * distance, a_w the wall's tau_w/u of the wall cell (the wall function or the
 * solids' wall condition), per radian and unit length. One sparse direct
 * solve (KLU) of 2n + 1 unknowns. And the velocities' radial gradients on each cell's faces, which the
 * turbulence's and the solids' production terms take. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"

int pipe_momentum_init(pipe *p, sl_diag *d) {
  const int n = p->n, N = 2 * n + 1;
  int32_t *el = malloc((size_t)5 * (size_t)(n - 1) * sizeof *el);
  p->rhs = calloc((size_t)N, sizeof(double)), p->x = calloc((size_t)N, sizeof(double));
  if (!el || !p->rhs || !p->x) {
    free(el);
    return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  }
  for (int i = 0; i + 1 < n; ++i) {
    int32_t *e = el + 5 * i;
    e[0] = 2 * i, e[1] = 2 * i + 1, e[2] = 2 * i + 2, e[3] = 2 * i + 3, e[4] = 2 * n;
  }
  int rc = sl_csr_build_uniform(&p->A, N, n - 1, 5, el, d);
  free(el);
  if (!rc) rc = sl_linsolve_create(&p->ls, "klu", d);
  return rc;
}

static void add(sl_csr *A, int i, int j, double v) { A->values[sl_csr_find(A, i, j)] += v; }

int pipe_momentum_solve(pipe *p, sl_diag *d) {
  const int n = p->n, iG = 2 * n;
  const sl_fv_grid *g = &p->g;
  sl_csr *A = &p->A;
  double *b = p->rhs, *muf = p->buf[0];
  sl_csr_zero(A);
  memset(b, 0, (size_t)(2 * n + 1) * sizeof *b);
  for (int i = 0; i < n; ++i) muf[i] = (1.0 - p->phi[i]) * (p->mu_f + p->mu_t[i]);
  /* the faces between cells */
  for (int i = 0; i + 1 < n; ++i) {
    int f = i + 1;
    double gd = g->area[f] / g->dist[f];
    double a = 0.5 * (muf[i] + muf[i + 1]) * gd;
    add(A, 2 * i, 2 * i, a), add(A, 2 * i, 2 * i + 2, -a);
    add(A, 2 * i + 2, 2 * i + 2, a), add(A, 2 * i + 2, 2 * i, -a);
    if (p->two_phase) {
      double bs = 0.5 * (p->mu_s[i] + p->mu_s[i + 1]) * gd;
      add(A, 2 * i + 1, 2 * i + 1, bs), add(A, 2 * i + 1, 2 * i + 3, -bs);
      add(A, 2 * i + 3, 2 * i + 3, bs), add(A, 2 * i + 3, 2 * i + 1, -bs);
    }
  }
  /* the wall */
  const double Aw = g->area[n];
  add(A, 2 * (n - 1), 2 * (n - 1), p->a_fw * Aw);
  if (p->two_phase) add(A, 2 * n - 1, 2 * n - 1, p->a_sw * Aw);
  /* the cells: drag, the pressure gradient, gravity; the flow rate */
  double Vsum = 0.0;
  for (int i = 0; i < n; ++i) {
    double V = g->vol[i], cs = p->two_phase ? p->phi[i] : 0.0, cf = 1.0 - cs;
    int f = 2 * i, s = 2 * i + 1;
    add(A, f, iG, cf * V), b[f] = cf * p->rho_f * p->gz * V;
    if (p->two_phase) {
      /* the drag K(s)(u_f - u_s) about the last slip s0: Kd (u_f - u_s) + (K - Kd) s0 */
      double KV = p->Kd[i] * V, F0 = (p->K[i] - p->Kd[i]) * p->slip0[i] * V;
      add(A, f, f, KV), add(A, f, s, -KV), b[f] -= F0;
      add(A, s, s, KV), add(A, s, f, -KV);
      add(A, s, iG, cs * V), b[s] = cs * p->rho_s * p->gz * V + F0;
    } else { /* no solids: u_s follows u_f */
      double a = muf[i] * g->area[i + 1] / g->dist[i + 1] + 1e-300;
      add(A, s, s, a), add(A, s, f, -a);
    }
    if (!p->cfg->pressure_gradient.n) add(A, iG, f, cf * V), add(A, iG, s, cs * V);
    Vsum += V;
  }
  if (p->march.on) pipe_march_momentum(p, A, b); /* the developing pipe's convection (pipe_march.c) */
  if (p->cfg->pressure_gradient.n) add(A, iG, iG, 1.0), b[iG] = -p->cfg->pressure_gradient.v[0]; /* G held */
  else b[iG] = p->cfg->bulk_velocity * Vsum;
  sl_csr_touch(A);
  int rc = sl_linsolve_solve(p->ls, A, b, p->x, d);
  if (rc) return sl_diag_prefix(d, rc, "pipe: the momentum solve");
  const double w = p->relax;
  for (int i = 0; i < n; ++i) {
    p->uf[i] += w * (p->x[2 * i] - p->uf[i]);
    p->us[i] += w * (p->x[2 * i + 1] - p->us[i]);
  }
  p->G += w * (p->x[iG] - p->G);
  if (p->two_phase) p->tau_sw = p->a_sw * p->us[n - 1];
  return 0;
}

/* The mixture's bulk velocity carried, (1/A) int (c_f u_f + c_s u_s) dA: the given one, or with [pipe]
   pressure_gradient what the state carries. */
double pipe_bulk_velocity(const pipe *p) {
  if (!p->cfg->pressure_gradient.n) return p->cfg->bulk_velocity;
  double q = 0.0, A = 0.0;
  for (int i = 0; i < p->n; ++i) {
    const double cs = p->two_phase ? p->phi[i] : 0.0;
    q += p->g.vol[i] * ((1.0 - cs) * p->uf[i] + cs * p->us[i]), A += p->g.vol[i];
  }
  return q / A;
}

/* du/dr on each cell's inner (gw) and outer (ge) face: zero at the axis, `wall` on the wall face (NaN: the
   wall cell's inner face's). */
void pipe_face_gradients(const pipe *p, const double *u, double wall, double *gw, double *ge) {
  const sl_fv_grid *g = &p->g;
  const int n = p->n;
  for (int i = 0; i < n; ++i) {
    gw[i] = i > 0 ? (u[i] - u[i - 1]) / (g->xc[i] - g->xc[i - 1]) : 0.0;
    ge[i] = i + 1 < n ? (u[i + 1] - u[i]) / (g->xc[i + 1] - g->xc[i]) : isnan(wall) ? gw[i] : wall;
  }
}
