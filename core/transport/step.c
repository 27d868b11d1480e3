/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Face fluxes, the stable step, the bounds limiter of the extra flux, and
 * the sub-cycled explicit update. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/transport/transport_impl.h"

/* Bounds are checked to this absolute slack: round-off only. */
#define BOUND_SLACK 1e-12
/* Values below this are set to zero: the clear liquid above a suspension
 * decays geometrically into subnormal numbers, which are slow. */
#define PHI_TINY 1e-250
/* An extra flux may close at most this fraction of the gap to phi_max of a
 * cell in one stage (transport.h, sl_transport_set_extra_flux). */
#define EXTRA_UP_FRACTION 0.5

/* The cell a flux face leads into from its owner: the neighbour of an
 * interior face, the owner of the paired face of a periodic one, -1 for an
 * open face. Not for walls and periodic images (no flux of their own). */
static inline int flux_neighbour(const sl_transport *t, int f) {
  const int *fc = t->m->face_cells;
  int kind = t->fkind[f];
  return kind == SL_FACE_INTERIOR ? fc[2 * f + 1] : kind == SL_FACE_PERIODIC ? fc[2 * t->partner[f]] : -1;
}

/* The face's q and w: on a periodic pair the mean of its two faces'
 * (transport.h). */
static inline void face_qw(const sl_transport *t, const double *q, const double *w, int f, double *qf, double *wf) {
  if (t->fkind[f] == SL_FACE_PERIODIC) {
    int p = t->partner[f];
    *qf = q ? 0.5 * (q[f] - q[p]) : 0;
    *wf = w ? 0.5 * (w[f] - w[p]) : 0;
  } else {
    *qf = q ? q[f] : 0;
    *wf = w ? w[f] : 0;
  }
}

static inline int has_flux(int kind) { return kind != SL_FACE_WALL && kind != SL_FACE_PERIODIC_IMAGE; }

/* Lipschitz bounds of the Godunov flux of h = q phi + w F in its owner
 * (a_plus) and neighbour (a_minus) argument: the largest positive and
 * negative slopes q + w F' over the table. */
static inline void face_slopes(const sl_transport *t, double q, double w, double *a_plus, double *a_minus) {
  double s1 = w * t->tab.D_max, s2 = w * t->tab.D_min;
  double smax = q + (s1 > s2 ? s1 : s2), smin = q + (s1 > s2 ? s2 : s1);
  *a_plus = smax > 0 ? smax : 0;
  *a_minus = smin < 0 ? -smin : 0;
}

double sl_transport_stable_dt(const sl_transport *t, const double *q, const double *w, int *cell) {
  const sl_mesh *m = t->m;
  double *s = t->sens;
  memset(s, 0, (size_t)m->n_cells * sizeof *s);
  for (int f = 0; f < m->n_faces; ++f) {
    if (!has_flux(t->fkind[f])) continue;
    double ap, am, qf, wf;
    face_qw(t, q, w, f, &qf, &wf);
    face_slopes(t, qf, wf, &ap, &am);
    s[m->face_cells[2 * f]] += ap;
    int n = flux_neighbour(t, f);
    if (n >= 0) s[n] += am;
  }
  double best = HUGE_VAL;
  int arg = -1;
  for (int c = 0; c < m->n_cells; ++c)
    if (s[c] > 0 && t->vol[c] < best * s[c]) best = t->vol[c] / s[c], arg = c;
  if (cell) *cell = arg;
  return arg < 0 ? HUGE_VAL : best * t->o.cfl * (t->o.order == 2 ? 0.5 : 1.0);
}

/* res[c] = -(sum of outward face fluxes) of cell c for the states phi (with
 * the reconstruction in t->grad when `muscl`); returns the flux that entered
 * through open boundaries per unit time. */
static double residual(sl_transport *t, const double *q, const double *w, const double *phi, int muscl, double *res) {
  const sl_mesh *m = t->m;
  memset(res, 0, (size_t)m->n_cells * sizeof *res);
  memset(t->bres, 0, (size_t)m->n_boundaries * sizeof *t->bres);
  double inflow = 0;
  for (int f = 0; f < m->n_faces; ++f) {
    int kind = t->fkind[f];
    if (!has_flux(kind)) continue;
    double qf, wf;
    face_qw(t, q, w, f, &qf, &wf);
    if (qf == 0 && wf == 0) continue;
    int o = m->face_cells[2 * f], n = flux_neighbour(t, f);
    const double *x = t->xf + 2 * f;
    double a = phi[o], b;
    if (muscl) a += t->grad[2 * o] * (x[0] - t->xc[2 * o]) + t->grad[2 * o + 1] * (x[1] - t->xc[2 * o + 1]);
    if (n >= 0) {
      /* The neighbour's value at its own face point: the paired face's on a periodic pair. */
      const double *xn = kind == SL_FACE_PERIODIC ? t->xf + 2 * t->partner[f] : x;
      b = phi[n];
      if (muscl) b += t->grad[2 * n] * (xn[0] - t->xc[2 * n]) + t->grad[2 * n + 1] * (xn[1] - t->xc[2 * n + 1]);
    } else {
      b = t->face_phi ? t->face_phi[f] : t->bc_phi[m->face_tag[f]];
    }
    double g = sl_godunov_flux(&t->tab, qf, wf, a, b);
    res[o] -= g;
    if (n >= 0) res[n] += g;
    else inflow -= g, t->bres[m->face_tag[f]] -= g;
  }
  return inflow;
}

/* Adds the extra face fluxes `flux` (out of each face's owner) to res,
 * limited so that phi + h res / V stays in [0, phi_max] and closes at most
 * EXTRA_UP_FRACTION of each cell's gap to phi_max (transport.h). res holds
 * the Godunov residual on entry. Counts the scaled faces and the volume
 * they held back into *n_lim and *v_lim. */
static void add_extra(sl_transport *t, const double *phi, const double *flux, double h, double *res, int *n_lim,
                      double *v_lim) {
  const sl_mesh *m = t->m;
  const double pm = t->o.phi_max;
  double *in = t->xin, *out = t->xout, *pa = t->xadv;
  for (int c = 0; c < m->n_cells; ++c) {
    double v = phi[c] + h * res[c] / t->vol[c];
    pa[c] = v < 0 ? 0 : v > pm ? pm : v;
    in[c] = out[c] = 0;
  }
  for (int f = 0; f < m->n_faces; ++f) {
    if (!has_flux(t->fkind[f])) continue;
    int o = m->face_cells[2 * f], n = flux_neighbour(t, f);
    if (n < 0 || flux[f] == 0) continue;
    double v = h * flux[f];
    if (v > 0) out[o] += v, in[n] += v;
    else out[n] -= v, in[o] -= v;
  }
  /* in / out become the factors that the cell allows on its inflows / outflows. */
  for (int c = 0; c < m->n_cells; ++c) {
    double up = EXTRA_UP_FRACTION * (pm - pa[c]) * t->vol[c], down = pa[c] * t->vol[c];
    in[c] = in[c] > up ? up / in[c] : 1;
    out[c] = out[c] > down ? down / out[c] : 1;
  }
  for (int f = 0; f < m->n_faces; ++f) {
    if (!has_flux(t->fkind[f])) continue;
    int o = m->face_cells[2 * f], n = flux_neighbour(t, f);
    double F = flux[f];
    if (n < 0 || F == 0) continue;
    double k = F > 0 ? fmin(out[o], in[n]) : fmin(out[n], in[o]);
    if (k < 1) {
      ++*n_lim;
      *v_lim += h * fabs(F) * (1 - k);
      F *= k;
    }
    res[o] -= F;
    res[n] += F;
  }
}

/* out = phi + h res / V. Round-off excursions (within BOUND_SLACK) past 0
 * or phi_max, and values below PHI_TINY, are set to the bound, so that
 * closures asked at phi never see -1e-32; *clamped gets sum |change| V.
 * Returns the first cell further outside (or non-finite), -1 when none. */
static int euler(const sl_transport *t, const double *phi, const double *res, double h, double *out, double *clamped) {
  const double pm = t->o.phi_max;
  double cl = 0;
  int bad = -1;
  for (int c = 0; c < t->m->n_cells; ++c) {
    double v = phi[c] + h * res[c] / t->vol[c];
    if (!(v >= PHI_TINY && v <= pm)) {
      if (v > pm && v <= pm + BOUND_SLACK) cl += (v - pm) * t->vol[c], v = pm;
      else if (v < PHI_TINY && v >= -BOUND_SLACK) cl += fabs(v) * t->vol[c], v = 0;
      else if (bad < 0) bad = c;
    }
    out[c] = v;
  }
  *clamped += cl;
  return bad;
}

/* max_c |sum_f q_f| over the non-wall faces of each cell, relative to the
 * largest sum_f |q_f| of a cell: the flow's own scale, so that round-off in
 * cells with almost no flux does not read as a divergence of 1. */
static double max_divergence(const sl_transport *t, const double *q) {
  const sl_mesh *m = t->m;
  double worst = 0, amax = 0;
  if (!q) return 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double s = 0, a = 0;
    for (int k = 0; k < m->nf_per_cell; ++k) {
      int f = m->cell_faces[(size_t)c * m->nf_per_cell + k];
      int kind = t->fkind[f];
      if (kind == SL_FACE_WALL) continue;
      /* A periodic face (either of the pair) is a boundary face owned by c:
       * its outflow is the pair's mean flux along its own normal. */
      double v = kind == SL_FACE_PERIODIC || kind == SL_FACE_PERIODIC_IMAGE ? 0.5 * (q[f] - q[t->partner[f]])
                 : m->face_cells[2 * f] == c                                ? q[f]
                                                                            : -q[f];
      s += v;
      a += fabs(v);
    }
    if (fabs(s) > worst) worst = fabs(s);
    if (a > amax) amax = a;
  }
  return amax > 0 ? worst / amax : 0;
}

static int check_inputs(const sl_transport *t, double dt, const double *q, const double *w, const double *phi,
                        sl_diag *d) {
  const sl_mesh *m = t->m;
  if (!(dt > 0 && isfinite(dt))) return sl_diag_set(d, SL_EBADINPUT, "transport: time step %g", dt);
  for (int f = 0; f < m->n_faces; ++f)
    if ((q && !isfinite(q[f])) || (w && !isfinite(w[f])))
      return sl_diag_set(d, SL_EBADINPUT, "transport: face %d has flux q = %g, settling coefficient w = %g", f,
                         q ? q[f] : 0.0, w ? w[f] : 0.0);
  for (int c = 0; c < m->n_cells; ++c)
    if (!(phi[c] >= -BOUND_SLACK && phi[c] <= t->o.phi_max + BOUND_SLACK))
      return sl_diag_set(d, SL_EBADINPUT, "transport: phi = %.17g in cell %d at (%g, %g) is not in [0, phi_max = %g]",
                         phi[c], c, t->xc[2 * c], t->xc[2 * c + 1], t->o.phi_max);
  return 0;
}

int sl_transport_set_extra_flux(sl_transport *t, sl_transport_extra_fn fn, void *user, sl_diag *d) {
  if (fn && !t->xflux) {
    size_t nc = (size_t)t->m->n_cells, nf = (size_t)t->m->n_faces;
    t->xflux = calloc(nf, sizeof *t->xflux);
    t->xflux2 = calloc(nf, sizeof *t->xflux2);
    t->xin = malloc(nc * sizeof *t->xin);
    t->xout = malloc(nc * sizeof *t->xout);
    t->xadv = malloc(nc * sizeof *t->xadv);
    if (!t->xflux || !t->xflux2 || !t->xin || !t->xout || !t->xadv) {
      free(t->xflux), free(t->xflux2), free(t->xin), free(t->xout), free(t->xadv);
      t->xflux = t->xflux2 = t->xin = t->xout = t->xadv = NULL;
      t->extra = NULL;
      return sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
    }
  }
  t->extra = fn;
  t->extra_user = fn ? user : NULL;
  return 0;
}

/* The extra flux at phi, checked: finite on every flux face, dt_stable > 0. */
static int eval_extra(sl_transport *t, const double *phi, double *flux, double *dt_stable, sl_diag *d) {
  const sl_mesh *m = t->m;
  *dt_stable = HUGE_VAL;
  int rc = t->extra(t->extra_user, phi, flux, dt_stable, d);
  if (rc) return sl_diag_prefix(d, rc, "transport: extra flux");
  if (!(*dt_stable > 0))
    return sl_diag_set(d, SL_EFAILED, "transport: the extra flux gave a stable step %g (it must be > 0)", *dt_stable);
  for (int f = 0; f < m->n_faces; ++f)
    if (has_flux(t->fkind[f]) && t->fkind[f] != SL_FACE_OPEN && !isfinite(flux[f]))
      return sl_diag_set(d, SL_EFAILED, "transport: the extra flux is %g at face %d at (%g, %g)", flux[f], f,
                         t->xf[2 * f], t->xf[2 * f + 1]);
  return 0;
}

/* One sub-step of length h from t->cur (in place), SSP-RK2 or Euler; with
 * an extra flux its value at t->cur is in t->xflux. */
static int substep(sl_transport *t, const double *q, const double *w, double h, sl_transport_stats *st, sl_diag *d) {
  const int nc = t->m->n_cells;
  double *cur = t->cur, *stage = t->stage, *res = t->res;
  if (t->o.order == 2) {
    /* SSP-RK2 (Shu & Osher 1988): u1 = u + h L(u), u_new = (u + u1 + h L(u1)) / 2. */
    int nl = 0, bad;
    double vl = 0, cl = 0;
    sl_transport_reconstruct(t, cur);
    double in1 = residual(t, q, w, cur, 1, res);
    memcpy(t->bres1, t->bres, (size_t)t->m->n_boundaries * sizeof *t->bres1);
    if (t->extra) add_extra(t, cur, t->xflux, h, res, &nl, &vl);
    bad = euler(t, cur, res, h, stage, &cl) >= 0;
    if (!bad) {
      if (t->extra) {
        double dts;
        int rc = eval_extra(t, stage, t->xflux2, &dts, d);
        if (rc) return rc;
      }
      sl_transport_reconstruct(t, stage);
      double in2 = residual(t, q, w, stage, 1, res);
      if (t->extra) add_extra(t, stage, t->xflux2, h, res, &nl, &vl);
      bad = euler(t, stage, res, h, stage, &cl) >= 0;
      if (!bad) { /* the mean of two states in bounds is in bounds */
        for (int c = 0; c < nc; ++c) cur[c] = 0.5 * (cur[c] + stage[c]);
        st->boundary_inflow += 0.5 * h * (in1 + in2);
        for (int b = 0; b < t->m->n_boundaries; ++b) t->bstep[b] += 0.5 * h * (t->bres1[b] + t->bres[b]);
        st->clamped += 0.5 * cl;
        st->n_extra_limited += nl;
        st->extra_limited += 0.5 * vl;
        return 0;
      }
    }
    ++st->n_fallbacks;
  }
  double in = residual(t, q, w, cur, 0, res);
  if (t->extra) add_extra(t, cur, t->xflux, h, res, &st->n_extra_limited, &st->extra_limited);
  int c = euler(t, cur, res, h, stage, &st->clamped);
  if (c >= 0)
    return sl_diag_set(d, SL_EFAILED,
                       "transport: phi = %.17g in cell %d at (%g, %g) left [0, phi_max = %g] in a first-order "
                       "sub-step (the face fluxes' largest relative divergence is %.3g; they must be divergence-free)",
                       stage[c], c, t->xc[2 * c], t->xc[2 * c + 1], t->o.phi_max, st->max_divergence);
  memcpy(cur, stage, (size_t)nc * sizeof *cur);
  st->boundary_inflow += h * in;
  for (int b = 0; b < t->m->n_boundaries; ++b) t->bstep[b] += h * t->bres[b];
  return 0;
}

int sl_transport_step(sl_transport *t, double dt, const double *q, const double *w, double *phi, sl_transport_stats *st,
                      sl_diag *d) {
  sl_transport_stats local;
  if (!st) st = &local;
  memset(st, 0, sizeof *st);
  memset(t->bstep, 0, (size_t)t->m->n_boundaries * sizeof *t->bstep);
  st->limiting_cell = -1;
  st->dt_extra = HUGE_VAL;
  int rc = check_inputs(t, dt, q, w, phi, d);
  if (rc) return rc;
  const sl_mesh *m = t->m;
  const int nc = m->n_cells;
  /* A periodic pair added since the limiter's neighbours were listed joins them. */
  if (t->o.order == 2 && t->vnb_pairs != sl_transport_periodic_count(t) && (rc = sl_transport_build_vertex_cells(t, d)))
    return rc;
  st->max_divergence = max_divergence(t, q);
  st->dt_stable = sl_transport_stable_dt(t, q, w, &st->limiting_cell);
  memcpy(t->cur, phi, (size_t)nc * sizeof *t->cur);
  if (!t->extra) {
    /* n equal sub-steps within the stable one. */
    double ns = ceil(dt / st->dt_stable);
    if (ns < 1) ns = 1;
    if (ns > t->o.max_substeps)
      return sl_diag_set(d, SL_EFAILED,
                         "transport: the step %g needs %.0f sub-steps of %g (limit %d), set by cell %d at (%g, %g)", dt,
                         ns, st->dt_stable, t->o.max_substeps, st->limiting_cell, t->xc[2 * st->limiting_cell],
                         t->xc[2 * st->limiting_cell + 1]);
    int n = (int)ns;
    double h = dt / n;
    for (int s = 0; s < n; ++s)
      if ((rc = substep(t, q, w, h, st, d))) return rc;
    st->n_substeps = n;
  } else {
    /* Each sub-step from the state at its start: the extra flux's stable
     * step changes with phi. */
    double elapsed = 0;
    for (int count = 0;; ++count) {
      double dte;
      if ((rc = eval_extra(t, t->cur, t->xflux, &dte, d))) return rc;
      dte *= t->o.cfl;
      if (dte < st->dt_extra) st->dt_extra = dte;
      double rem = dt - elapsed, hc = fmin(st->dt_stable, dte);
      double nr = ceil(rem / hc);
      if (!(nr >= 1)) nr = 1;
      if (nr > (double)t->o.max_substeps - count)
        return sl_diag_set(d, SL_EFAILED,
                           "transport: the step %g needs more than %d sub-steps: after %d, the rest %g needs %.0f "
                           "of %g (advective stable step %g, extra flux's %g)",
                           dt, t->o.max_substeps, count, rem, nr, hc, st->dt_stable, dte);
      double h = nr == 1 ? rem : rem / nr;
      if ((rc = substep(t, q, w, h, st, d))) return rc;
      if (nr == 1) {
        st->n_substeps = count + 1;
        break;
      }
      elapsed += h;
    }
  }
  memcpy(phi, t->cur, (size_t)nc * sizeof *phi);
  return 0;
}
