/* The solids-fraction transport of the 2-D two-fluid model on the staggered
 * grid (two_fluid_plane_impl.h): T(phi^n, u_s) of one step, the column's
 * bounded scheme (two_fluid_step.c) in two dimensions. First-order upwind
 * face fluxes of the face solids velocities, plus the particle diffusivity
 * -D grad phi; sub-stepped within the CFL limit; what enters a cell scaled so
 * that it cannot pass phi_max. Solids never enter from outside (clear fluid
 * at an outlet, held solids at an inlet). */
#include <math.h>
#include <string.h>
#include <time.h>

#include "core/models/two_fluid_plane_impl.h"

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* One forward-Euler stage over ds of the upwind solids fluxes of us (plus
 * the particle diffusivity), with the packing limiter. */
static void transport_stage(tfp_model *m, const double *us, double *phi, double ds, double *out) {
  const double phi_max = m->c.phi_max, D = m->c.diffusivity;
  double *F = m->flux, *alpha = m->alpha, *in = m->inflow;
  memset(in, 0, (size_t)m->nc * sizeof *in);
  for (int f = 0; f < m->nf; ++f) {
    int lo = m->lo[f], hi = m->hi[f];
    double q = m->area[f] * us[f];
    if (m->ftype[f] == TFP_FACE_IMAGE) { /* a periodic seam's second copy: its first carries the flux */
      F[f] = 0.0;
      continue;
    }
    /* nothing enters from outside (clear fluid at an outlet; held solids at an inlet) */
    F[f] = q > 0.0 ? (lo >= 0 ? q * phi[lo] : 0.0) : (hi >= 0 ? q * phi[hi] : 0.0);
    if (D > 0.0 && lo >= 0 && hi >= 0) F[f] -= D * m->area[f] * (phi[hi] - phi[lo]) / m->dist[f];
    if (F[f] > 0.0 && hi >= 0) in[hi] += F[f];
    else if (F[f] < 0.0 && lo >= 0) in[lo] -= F[f];
  }
  for (int c = 0; c < m->nc; ++c)
    alpha[c] = in[c] > 0.0 ? fmin(1.0, fmax(0.0, (phi_max - phi[c]) * m->vol[c] / (ds * in[c]))) : 1.0;
  for (int f = 0; f < m->nf; ++f) {
    int lo = m->lo[f], hi = m->hi[f];
    if (F[f] > 0.0 && hi >= 0) F[f] *= alpha[hi];
    else if (F[f] < 0.0 && lo >= 0) F[f] *= alpha[lo];
    if (hi < 0) *out += ds * F[f];
    if (lo < 0) *out -= ds * F[f];
  }
  for (int f = 0; f < m->nf; ++f) {
    if (m->lo[f] >= 0) phi[m->lo[f]] -= ds / m->vol[m->lo[f]] * F[f];
    if (m->hi[f] >= 0) phi[m->hi[f]] += ds / m->vol[m->hi[f]] * F[f];
  }
  for (int c = 0; c < m->nc; ++c) phi[c] = phi[c] < 0.0 ? 0.0 : phi[c] > phi_max ? phi_max : phi[c]; /* round-off */
}

int tfp_transport(tfp_model *m, const double *us, double dt, double *phi, double *outflow, sl_diag *d) {
  double t0 = cpu_now();
  double *rate = m->inflow, rmax = 0.0;
  memset(rate, 0, (size_t)m->nc * sizeof *rate);
  for (int f = 0; f < m->nf; ++f) {
    int lo = m->lo[f], hi = m->hi[f];
    double q = m->area[f] * us[f];
    if (m->ftype[f] == TFP_FACE_IMAGE) continue;
    double Df = m->c.diffusivity > 0.0 && lo >= 0 && hi >= 0 ? m->c.diffusivity * m->area[f] / m->dist[f] : 0.0;
    if (lo >= 0) rate[lo] += fmax(q, 0.0) + Df;
    if (hi >= 0) rate[hi] += fmax(-q, 0.0) + Df;
  }
  for (int c = 0; c < m->nc; ++c) rmax = fmax(rmax, rate[c] / m->vol[c]);
  double ns = ceil(dt * rmax / m->c.cfl);
  if (!(ns <= 1e7)) return sl_diag_set(d, SL_EFAILED, "solids transport would need %.3g sub-steps", ns);
  /* an iterate far from the last accepted step's speeds is refused (the step is retried smaller) */
  double cap = fmax(1e3, 50.0 * (double)m->accepted_substeps);
  if (m->accepted_substeps > 0 && ns > cap)
    return sl_diag_set(d, SL_EFAILED, "solids transport of this iterate would need %.3g sub-steps, more than 50 "
                                      "times the last step's %ld", ns, m->accepted_substeps);
  long n = ns < 1.0 ? 1 : (long)ns;
  double ds = dt / (double)n, out = 0.0;
  memcpy(phi, m->phi, (size_t)m->nc * sizeof *phi);
  for (long s = 0; s < n; ++s) transport_stage(m, us, phi, ds, &out);
  m->last_substeps = n;
  m->substeps_trial += n;
  *outflow = out;
  m->transport_cpu += cpu_now() - t0;
  return 0;
}

