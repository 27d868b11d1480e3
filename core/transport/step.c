/* Face fluxes, the stable step, and the sub-cycled explicit update. */
#include <math.h>
#include <string.h>

#include "core/transport/transport_impl.h"

/* Bounds are checked to this absolute slack: round-off only. */
#define BOUND_SLACK 1e-12
/* Values below this are set to zero: the clear liquid above a suspension
 * decays geometrically into subnormal numbers, which are slow. */
#define PHI_TINY 1e-250

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
    if (t->fkind[f] == SL_FACE_WALL) continue;
    double ap, am;
    face_slopes(t, q ? q[f] : 0, w ? w[f] : 0, &ap, &am);
    s[m->face_cells[2 * f]] += ap;
    if (t->fkind[f] == SL_FACE_INTERIOR) s[m->face_cells[2 * f + 1]] += am;
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
static double residual(sl_transport *t, const double *q, const double *w, const double *phi, int muscl,
                       double *res) {
  const sl_mesh *m = t->m;
  memset(res, 0, (size_t)m->n_cells * sizeof *res);
  double inflow = 0;
  for (int f = 0; f < m->n_faces; ++f) {
    int kind = t->fkind[f];
    if (kind == SL_FACE_WALL) continue;
    int o = m->face_cells[2 * f], n = m->face_cells[2 * f + 1];
    const double *x = t->xf + 2 * f;
    double a = phi[o], b;
    if (muscl) a += t->grad[2 * o] * (x[0] - t->xc[2 * o]) + t->grad[2 * o + 1] * (x[1] - t->xc[2 * o + 1]);
    if (kind == SL_FACE_INTERIOR) {
      b = phi[n];
      if (muscl) b += t->grad[2 * n] * (x[0] - t->xc[2 * n]) + t->grad[2 * n + 1] * (x[1] - t->xc[2 * n + 1]);
    } else {
      b = t->bc_phi[m->face_tag[f]];
    }
    double qf = q ? q[f] : 0, wf = w ? w[f] : 0;
    if (qf == 0 && wf == 0) continue;
    double g = sl_godunov_flux(&t->tab, qf, wf, a, b);
    res[o] -= g;
    if (kind == SL_FACE_INTERIOR) res[n] += g;
    else inflow -= g;
  }
  return inflow;
}

/* out = phi + h res / V. Round-off excursions (within BOUND_SLACK) past 0
 * or phi_max, and values below PHI_TINY, are set to the bound, so that
 * closures asked at phi never see -1e-32; *clamped gets sum |change| V.
 * Returns the first cell further outside (or non-finite), -1 when none. */
static int euler(const sl_transport *t, const double *phi, const double *res, double h, double *out,
                 double *clamped) {
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
      if (t->fkind[f] == SL_FACE_WALL) continue;
      double v = m->face_cells[2 * f] == c ? q[f] : -q[f];
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

int sl_transport_step(sl_transport *t, double dt, const double *q, const double *w, double *phi,
                      sl_transport_stats *st, sl_diag *d) {
  sl_transport_stats local;
  if (!st) st = &local;
  memset(st, 0, sizeof *st);
  st->limiting_cell = -1;
  int rc = check_inputs(t, dt, q, w, phi, d);
  if (rc) return rc;
  const sl_mesh *m = t->m;
  const int nc = m->n_cells;
  st->max_divergence = max_divergence(t, q);
  st->dt_stable = sl_transport_stable_dt(t, q, w, &st->limiting_cell);
  double ns = ceil(dt / st->dt_stable);
  if (ns < 1) ns = 1;
  if (ns > t->o.max_substeps)
    return sl_diag_set(d, SL_EFAILED,
                       "transport: the step %g needs %.0f sub-steps of %g (limit %d), set by cell %d at (%g, %g)", dt,
                       ns, st->dt_stable, t->o.max_substeps, st->limiting_cell, t->xc[2 * st->limiting_cell],
                       t->xc[2 * st->limiting_cell + 1]);
  int n = (int)ns;
  double h = dt / n;
  double *cur = t->cur, *stage = t->stage, *res = t->res;
  memcpy(cur, phi, (size_t)nc * sizeof *cur);
  for (int s = 0; s < n; ++s) {
    int bad = 0;
    if (t->o.order == 2) {
      /* SSP-RK2 (Shu & Osher 1988): u1 = u + h L(u), u_new = (u + u1 + h L(u1)) / 2. */
      sl_transport_reconstruct(t, cur);
      double in1 = residual(t, q, w, cur, 1, res), cl = 0;
      bad = euler(t, cur, res, h, stage, &cl) >= 0;
      if (!bad) {
        sl_transport_reconstruct(t, stage);
        double in2 = residual(t, q, w, stage, 1, res);
        bad = euler(t, stage, res, h, stage, &cl) >= 0;
        if (!bad) { /* the mean of two states in bounds is in bounds */
          for (int c = 0; c < nc; ++c) cur[c] = 0.5 * (cur[c] + stage[c]);
          st->boundary_inflow += 0.5 * h * (in1 + in2);
          st->clamped += 0.5 * cl;
          continue;
        }
      }
      ++st->n_fallbacks;
    }
    double in = residual(t, q, w, cur, 0, res);
    int c = euler(t, cur, res, h, stage, &st->clamped);
    if (c >= 0)
      return sl_diag_set(d, SL_EFAILED,
                         "transport: phi = %.17g in cell %d at (%g, %g) left [0, phi_max = %g] in a first-order "
                         "sub-step (the face fluxes' largest relative divergence is %.3g; they must be divergence-free)",
                         stage[c], c, t->xc[2 * c], t->xc[2 * c + 1], t->o.phi_max, st->max_divergence);
    memcpy(cur, stage, (size_t)nc * sizeof *cur);
    st->boundary_inflow += h * in;
  }
  memcpy(phi, cur, (size_t)nc * sizeof *phi);
  st->n_substeps = n;
  return 0;
}
