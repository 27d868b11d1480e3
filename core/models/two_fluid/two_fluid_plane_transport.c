/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids-fraction transport of the 2-D two-fluid model on the staggered
 * grid (two_fluid_plane_impl.h): T(phi^n, u_s) of one step, bounded and
 * conservative (the 1-D column's too: its n x 1 case). Face fluxes of the
 * face solids velocities with the upwind cell's phi (order 1) or its limited
 * linear reconstruction along the face's normal (order 2: MUSCL, van Leer
 * 1979, in Heun's two stages), plus the particle diffusivity -D grad phi;
 * sub-stepped within the CFL limit (halved at order 2); what enters a cell
 * scaled so that it cannot pass phi_max. Solids enter from outside only
 * through an inlet with a solids flux (its given js; clear fluid at an
 * outlet, held solids at any other inlet). With [closure.turbulence] the
 * turbulent dispersion's face fluxes join (two_fluid_plane_dispersion.c). The image faces of a
 * periodic row carry nothing: the row's first face carries its flux; nor
 * do closed faces (walls, the axis): the loops skip both (open_face). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/models/two_fluid/two_fluid_plane_impl.h"

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* Order 2's work for one call of tfp_transport: the geometry of the
 * reconstruction once, then per stage the limited half increments. */
typedef struct muscl {
  int *nb;       /* [4 nc]: cell c's neighbour along dir on side s at 4 c + 2 dir + s (c itself outside) */
  double *g;     /* [6 nc]: its factors gl, gr, gc along dir at 6 c + 3 dir (0 next to the boundary) */
  double *half;  /* [2 nc]: half the limited increment across cell c along dir at 2 c + dir */
  double *stage; /* [nc]: Heun's intermediate stage */
} muscl;

/* The limited linear reconstruction phi_c + s (x - x_c) of a cell of size h
 * puts phi_c -+ delta on its two faces along x, delta = s h / 2. With the
 * differences dl = phi_c - phi_l, dr = phi_r - phi_c to the neighbours at
 * their actual centre distances (h + h_l) / 2, (h + h_r) / 2:
 *   minmod (Roe 1986): s = minmod(dl / dm, dr / dp), delta = minmod(gl dl, gr dr);
 *   monotonised central (van Leer 1977): s = minmod(central difference, 2 dl / h, 2 dr / h),
 *     delta = minmod(gc (dl + dr), dl, dr);
 * gl = h / (h + h_l), gr = h / (h + h_r), gc = h / (2 h + h_l + h_r) (Sweby 1984; LeVeque 2002, Finite Volume
 * Methods, section 6.12). On a uniform grid that is the slope of the one-sided differences per metre; on a graded one the
 * MC bound 2 dphi / h with the cell's own size keeps each face value between the cell's phi and its neighbour's
 * (the uniform grid's 2 dphi / dx would not), hence within [0, phi_max] and [0, 2 phi_c]. Next to the boundary
 * the slope is 0 (first order there, and nothing enters through a wall). */
static int muscl_setup(const tfp_model *m, muscl *w) {
  const int nc = m->fv.nc;
  w->nb = malloc(4 * (size_t)nc * sizeof *w->nb);
  w->g = malloc(9 * (size_t)nc * sizeof *w->g);
  if (!w->nb || !w->g) return -1;
  w->half = w->g + 6 * nc, w->stage = w->g + 8 * nc;
  for (int c = 0; c < nc; ++c)
    for (int dir = 0; dir < 2; ++dir) {
      int l = tfp_neighbour(m, c, dir, 0), r = tfp_neighbour(m, c, dir, 1);
      const double *size = dir == 0 ? m->fv.hx : m->fv.hy;
      int at = dir == 0 ? c % m->fv.nx : c / m->fv.nx; /* the cell's index along dir */
      double *g = w->g + 6 * c + 3 * dir;
      w->nb[4 * c + 2 * dir] = l < 0 ? c : l, w->nb[4 * c + 2 * dir + 1] = r < 0 ? c : r;
      if (l < 0 || r < 0) {
        g[0] = g[1] = g[2] = 0.0;
        continue;
      }
      double h = size[at], hl = size[dir == 0 ? l % m->fv.nx : l / m->fv.nx],
             hr = size[dir == 0 ? r % m->fv.nx : r / m->fv.nx];
      g[0] = h / (h + hl), g[1] = h / (h + hr), g[2] = h / (2.0 * h + hl + hr);
    }
  return 0;
}

static void muscl_free(muscl *w) { free(w->nb), free(w->g); }

/* The limited half increments of phi in every cell along x and y. */
static void muscl_increments(const tfp_model *m, const muscl *w, const double *phi) {
  const int mc = m->c.limiter == TF_LIMITER_MC;
  for (int k = 0; k < 2 * m->fv.nc; ++k) { /* k = 2 c + dir */
    int c = k >> 1;
    const double *g = w->g + 3 * k;
    double dl = phi[c] - phi[w->nb[2 * k]], dr = phi[w->nb[2 * k + 1]] - phi[c], a;
    if (dl * dr <= 0.0) { /* an extremum, or the boundary (its neighbour is the cell itself) */
      w->half[k] = 0.0;
      continue;
    }
    if (mc) a = fmin(fabs(g[2] * (dl + dr)), fmin(fabs(dl), fabs(dr)));
    else a = fmin(fabs(g[0] * dl), fabs(g[1] * dr));
    w->half[k] = copysign(a, dl);
  }
}

/* One forward-Euler stage over ds from phi into next (next may be phi) of
 * the upwind solids fluxes of us (order 2: with the reconstruction of w)
 * plus the particle diffusivity, with the packing limiter. */
static void transport_stage(tfp_model *m, const double *us, const double *phi, double ds, double *next, const muscl *w,
                            double *out) {
  const double phi_max = m->c.phi_max, D = m->c.diffusivity;
  double *F = m->flux, *alpha = m->alpha, *in = m->inflow;
  if (w) muscl_increments(m, w, phi);
  memset(in, 0, (size_t)m->fv.nc * sizeof *in);
  for (int k = 0; k < m->n_open; ++k) {
    const int f = m->open_face[k];
    F[f] = 0.0;
    int lo = m->fv.lo[f], hi = m->fv.hi[f], dir = f >= m->fv.nfx;
    double q = m->fv.area[f] * us[f];
    /* nothing enters from outside (clear fluid at an outlet; held solids at an inlet) */
    if (q > 0.0 && lo >= 0) F[f] = q * (w ? phi[lo] + w->half[2 * lo + dir] : phi[lo]);
    else if (q < 0.0 && hi >= 0) F[f] = q * (w ? phi[hi] - w->half[2 * hi + dir] : phi[hi]);
    if (m->ftype[f] == TFP_FACE_INLET) F[f] = m->fv.area[f] * m->js[f]; /* the given inflow (0: held) */
    if (D > 0.0 && lo >= 0 && hi >= 0) F[f] -= D * m->fv.area[f] * (phi[hi] - phi[lo]) / m->fv.dist[f];
    if (m->disp.on && lo >= 0 && hi >= 0) { /* the turbulent dispersion (two_fluid_plane_dispersion.c) */
      double a = m->fv.area[f], vd = m->disp.v[f];
      F[f] += a * vd * (vd > 0.0 ? phi[lo] : phi[hi]) - a * m->disp.D[f] * (phi[hi] - phi[lo]) / m->fv.dist[f];
    }
    if (F[f] > 0.0 && hi >= 0) in[hi] += F[f];
    else if (F[f] < 0.0 && lo >= 0) in[lo] -= F[f];
  }
  /* what leaves a cell is bounded by the CFL condition (phi stays >= 0); what enters is scaled here */
  for (int c = 0; c < m->fv.nc; ++c)
    alpha[c] = in[c] > 0.0 ? fmin(1.0, fmax(0.0, (phi_max - phi[c]) * m->fv.vol[c] / (ds * in[c]))) : 1.0;
  for (int k = 0; k < m->n_open; ++k) {
    const int f = m->open_face[k], lo = m->fv.lo[f], hi = m->fv.hi[f];
    if (F[f] > 0.0 && hi >= 0) F[f] *= alpha[hi];
    else if (F[f] < 0.0 && lo >= 0) F[f] *= alpha[lo];
    if (hi < 0) *out += ds * F[f];
    if (lo < 0) *out -= ds * F[f];
  }
  if (next != phi) memcpy(next, phi, (size_t)m->fv.nc * sizeof *next);
  for (int k = 0; k < m->n_open; ++k) {
    const int f = m->open_face[k];
    if (m->fv.lo[f] >= 0) next[m->fv.lo[f]] -= ds / m->fv.vol[m->fv.lo[f]] * F[f];
    if (m->fv.hi[f] >= 0) next[m->fv.hi[f]] += ds / m->fv.vol[m->fv.hi[f]] * F[f];
  }
  for (int c = 0; c < m->fv.nc; ++c) /* round-off only */
    next[c] = next[c] < 0.0 ? 0.0 : next[c] > phi_max ? phi_max : next[c];
}

int tfp_transport(tfp_model *m, const double *us, double dt, double *phi, double *outflow, sl_diag *d) {
  double t0 = cpu_now();
  double *rate = m->inflow, rmax = 0.0;
  if (m->disp.on) {
    int rc = tfp_dispersion_update(m, m->phi, m->uf_new, us, d);
    if (rc) return rc;
  }
  memset(rate, 0, (size_t)m->fv.nc * sizeof *rate);
  for (int k = 0; k < m->n_open; ++k) {
    const int f = m->open_face[k], lo = m->fv.lo[f], hi = m->fv.hi[f];
    double q = m->fv.area[f] * us[f];
    double Df = m->c.diffusivity > 0.0 && lo >= 0 && hi >= 0 ? m->c.diffusivity * m->fv.area[f] / m->fv.dist[f] : 0.0;
    if (m->disp.on && lo >= 0 && hi >= 0) Df += m->fv.area[f] * (m->disp.D[f] / m->fv.dist[f] + fabs(m->disp.v[f]));
    if (lo >= 0) rate[lo] += fmax(q, 0.0) + Df;
    if (hi >= 0) rate[hi] += fmax(-q, 0.0) + Df;
  }
  for (int c = 0; c < m->fv.nc; ++c) rmax = fmax(rmax, rate[c] / m->fv.vol[c]);
  /* a limited second-order stage is positive at half the first-order step (a face value may be up to twice the
     cell's mean) */
  const int order2 = m->c.order == 2;
  double ns = ceil(dt * rmax / (order2 ? 0.5 * m->c.cfl : m->c.cfl));
  if (!(ns <= 1e7)) return sl_diag_set(d, SL_EFAILED, "solids transport would need %.3g sub-steps", ns);
  /* an iterate far from the last accepted step's speeds is refused (the step is retried smaller) */
  double cap = fmax(1e3, 50.0 * (double)m->accepted_substeps);
  if (m->accepted_substeps > 0 && ns > cap)
    return sl_diag_set(d, SL_EFAILED,
                       "solids transport of this iterate would need %.3g sub-steps, more than 50 "
                       "times the last step's %ld",
                       ns, m->accepted_substeps);
  long n = ns < 1.0 ? 1 : (long)ns;
  double ds = dt / (double)n, out = 0.0;
  muscl w = {0};
  if (order2 && muscl_setup(m, &w)) {
    muscl_free(&w);
    return sl_diag_set(d, SL_ENOMEM, "two_fluid: out of memory");
  }
  memcpy(phi, m->phi, (size_t)m->fv.nc * sizeof *phi);
  for (long s = 0; s < n; ++s) {
    if (!order2) {
      transport_stage(m, us, phi, ds, phi, NULL, &out);
      continue;
    }
    /* Heun's method, the two-stage strong-stability-preserving Runge-Kutta scheme (Shu & Osher 1988, eq 2.15):
       the mean of the start and two Euler stages, so bounds and conservation carry over */
    double o1 = 0.0, o2 = 0.0;
    transport_stage(m, us, phi, ds, w.stage, &w, &o1);
    transport_stage(m, us, w.stage, ds, w.stage, &w, &o2);
    for (int c = 0; c < m->fv.nc; ++c) phi[c] = 0.5 * (phi[c] + w.stage[c]);
    out += 0.5 * (o1 + o2);
  }
  muscl_free(&w);
  m->last_substeps = n;
  m->substeps_trial += n;
  *outflow = out;
  m->transport_cpu += cpu_now() - t0;
  return 0;
}
