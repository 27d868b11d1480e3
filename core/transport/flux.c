/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Tabulated settling flux and the exact Godunov flux on it (see flux.h). */
#include "core/transport/flux.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void sl_settling_table_free(sl_settling_table *t) {
  if (!t) return;
  free(t->F);
  free(t->D);
  free(t->piece);
  free(t->piece_dir);
  free(t->FD);
  memset(t, 0, sizeof *t);
}

/* Splits the nodes into pieces on which F' (the node values D) is monotone.
 * Differences below a relative 1e-12 are ignored, so round-off in a flat F'
 * does not create pieces. */
static int find_pieces(sl_settling_table *t) {
  int n = t->n, np = 0, last = 0;
  double tiny = 1e-12 * (fabs(t->D_max) + fabs(t->D_min) + (t->D_max - t->D_min));
  t->piece = malloc((size_t)n * sizeof *t->piece);
  t->piece_dir = malloc((size_t)n * sizeof *t->piece_dir);
  if (!t->piece || !t->piece_dir) return SL_EFAILED;
  t->piece[0] = 0;
  for (int k = 0; k + 1 < n; ++k) {
    double dd = t->D[k + 1] - t->D[k];
    int s = dd > tiny ? 1 : dd < -tiny ? -1 : 0;
    if (s == 0) continue;
    if (last == 0) {
      last = s;
    } else if (s != last) {
      t->piece_dir[np] = last;
      t->piece[++np] = k; /* F' has an extremum at node k */
      last = s;
    }
  }
  t->piece_dir[np] = last ? last : 1;
  t->piece[++np] = n - 1;
  t->n_pieces = np;
  return 0;
}

int sl_settling_table_build(sl_settling_table *t, double phi_max, int n, sl_settling_fn fn, void *user, sl_diag *d) {
  memset(t, 0, sizeof *t);
  if (!(phi_max > 0 && phi_max <= 1))
    return sl_diag_set(d, SL_EBADINPUT, "settling table: phi_max = %g is not in (0, 1]", phi_max);
  if (n < 3 || n > 1 << 24) return sl_diag_set(d, SL_EBADINPUT, "settling table: %d nodes (3 .. 2^24)", n);
  if (!fn) return sl_diag_set(d, SL_EBADINPUT, "settling table: no hindered-settling callback");
  t->n = n;
  t->phi_max = phi_max;
  t->dphi = phi_max / (n - 1);
  t->inv_dphi = (n - 1) / phi_max;
  double *phi = malloc((size_t)n * sizeof *phi), *u = malloc((size_t)n * sizeof *u);
  double *du = malloc((size_t)n * sizeof *du);
  t->F = malloc((size_t)n * sizeof *t->F);
  t->D = malloc((size_t)n * sizeof *t->D);
  int rc = 0;
  if (!phi || !u || !du || !t->F || !t->D) {
    rc = sl_diag_set(d, SL_ENOMEM, "settling table: out of memory");
    goto done;
  }
  for (int k = 0; k < n; ++k) phi[k] = k == n - 1 ? phi_max : k * t->dphi;
  if ((rc = fn(user, n, phi, u, du, d))) {
    sl_diag_prefix(d, rc, "settling table");
    goto done;
  }
  double famax = 0, fpos = 0, fneg = 0;
  for (int k = 0; k < n; ++k) {
    t->F[k] = phi[k] * u[k];
    t->D[k] = u[k] + phi[k] * du[k];
    if (!isfinite(t->F[k]) || !isfinite(t->D[k])) {
      rc = sl_diag_set(d, SL_EBADINPUT, "settling table: the closure gave u = %g, du/dphi = %g at phi = %.17g", u[k],
                       du[k], phi[k]);
      goto done;
    }
    famax = famax > fabs(t->F[k]) ? famax : fabs(t->F[k]);
    if (t->F[k] > fpos) fpos = t->F[k];
    if (t->F[k] < fneg) fneg = t->F[k];
  }
  /* One sign: a wall's zero flux is then the Godunov flux against a ghost
   * state 0 or phi_max, which keeps 0 <= phi <= phi_max (transport.h). */
  double tol = 1e-12 * famax;
  if (fpos > tol && fneg < -tol) {
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "settling table: the settling flux phi u changes sign on [0, %g] (from %g to %g); the solids "
                     "must settle one way along the body force",
                     phi_max, fneg, fpos);
    goto done;
  }
  if (fabs(t->F[n - 1]) > tol) {
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "settling table: the settling flux is %g at phi_max = %g, not zero (max |flux| %g): the sediment "
                     "would pack beyond phi_max; use a closure whose settling stops at phi_max (e.g. richardson_zaki "
                     "with packing_cutoff = true and the same phi_max)",
                     t->F[n - 1], phi_max, famax);
    goto done;
  }
  t->sign = fpos > tol ? 1 : fneg < -tol ? -1 : 0;
  for (int k = 0; k < n; ++k)
    if (t->sign * t->F[k] < 0 || t->sign == 0) t->F[k] = 0;
  t->F[n - 1] = 0;
  t->F_absmax = famax;
  t->D_min = t->D_max = t->D[0];
  for (int k = 1; k < n; ++k) {
    if (t->D[k] < t->D_min) t->D_min = t->D[k];
    if (t->D[k] > t->D_max) t->D_max = t->D[k];
  }
  t->FD = malloc(4 * (size_t)(n - 1) * sizeof *t->FD);
  if (!t->FD || find_pieces(t)) {
    rc = sl_diag_set(d, SL_ENOMEM, "settling table: out of memory");
    goto done;
  }
  for (int k = 0; k + 1 < n; ++k) {
    double *e = t->FD + 4 * k;
    e[0] = t->F[k], e[1] = t->dphi * t->D[k], e[2] = t->F[k + 1], e[3] = t->dphi * t->D[k + 1];
  }
done:
  free(phi);
  free(u);
  free(du);
  if (rc) sl_settling_table_free(t);
  return rc;
}

/* Node interval of phi (clamped) and the local coordinate s in [0, 1]. */
static inline int locate(const sl_settling_table *t, double *phi, double *s) {
  double x = *phi < 0 ? 0 : *phi > t->phi_max ? t->phi_max : *phi;
  int k = (int)(x * t->inv_dphi);
  if (k > t->n - 2) k = t->n - 2;
  if (k < 0) k = 0;
  *phi = x;
  *s = (x - k * t->dphi) * t->inv_dphi;
  return k;
}

/* The Hermite interpolant; inlined into the Godunov flux, its hot path. */
static inline double hermite_F(const sl_settling_table *t, double phi) {
  double s;
  int k = locate(t, &phi, &s);
  const double *e = t->FD + 4 * k;
  double r = 1 - s;
  /* Cubic Hermite basis (1 + 2s)(1-s)^2, s(1-s)^2, s^2(3 - 2s), -s^2(1-s). */
  double v = (1 + 2 * s) * r * r * e[0] + s * s * (3 - 2 * s) * e[2] + s * r * (r * e[1] - s * e[3]);
  /* Keep the sign of the table (the bounds argument needs it). */
  return t->sign * v < 0 ? 0 : v;
}

double sl_settling_F(const sl_settling_table *t, double phi) { return hermite_F(t, phi); }

double sl_settling_dF(const sl_settling_table *t, double phi) {
  double s;
  int k = locate(t, &phi, &s);
  return 6 * s * (1 - s) * (t->F[k + 1] - t->F[k]) * t->inv_dphi + (1 - s) * (1 - 3 * s) * t->D[k] +
         s * (3 * s - 2) * t->D[k + 1];
}

/* The stationary point of h = q phi + w F on the nodes ka..kb of one piece,
 * where g = q + w F' is monotone and changes sign between ka and kb (node
 * values): bisection over the nodes, then the root of the linear
 * interpolant of g in the last node interval. The root is off by
 * O(dphi^2), so h there by O(dphi^4): h is stationary at the root. */
static double stationary_point(const sl_settling_table *t, double q, double w, int ka, int kb) {
  double ga = q + w * t->D[ka];
  while (kb - ka > 1) {
    int mid = (ka + kb) / 2;
    double gm = q + w * t->D[mid];
    if ((gm <= 0) == (ga <= 0)) ka = mid, ga = gm;
    else kb = mid;
  }
  double gb = q + w * t->D[kb];
  double s = ga == gb ? 0.5 : ga / (ga - gb);
  return (ka + s) * t->dphi;
}

double sl_godunov_flux(const sl_settling_table *t, double q, double w, double a, double b) {
  const double pm = t->phi_max;
  a = a < 0 ? 0 : a > pm ? pm : a;
  b = b < 0 ? 0 : b > pm ? pm : b;
  int want_min = a <= b;
  double lo = want_min ? a : b, hi = want_min ? b : a;
  double hlo = q * lo + w * hermite_F(t, lo), hhi = q * hi + w * hermite_F(t, hi);
  double best = want_min ? (hlo < hhi ? hlo : hhi) : (hlo > hhi ? hlo : hhi);
  if (lo == hi || w == 0 || t->sign == 0) return best;
  /* Nodes bracketing [lo, hi]. */
  int klo = (int)(lo * t->inv_dphi), khi = (int)ceil(hi * t->inv_dphi);
  if (khi > t->n - 1) khi = t->n - 1;
  for (int p = 0; p < t->n_pieces; ++p) {
    int pa = t->piece[p], pb = t->piece[p + 1];
    if (pb <= klo) continue;
    if (pa >= khi) break;
    double xa = pa * t->dphi;
    if (xa > lo && xa < hi) { /* a piece boundary inside: a node value, exact */
      double hv = q * xa + w * t->F[pa];
      if (want_min ? hv < best : hv > best) best = hv;
    }
    /* h' = q + w F' is monotone here; an interior minimum needs it
     * increasing (h convex), an interior maximum decreasing. */
    int increasing = (w > 0) == (t->piece_dir[p] > 0);
    if (increasing != want_min) continue;
    int ka = pa > klo ? pa : klo, kb = pb < khi ? pb : khi;
    double ga = q + w * t->D[ka], gb = q + w * t->D[kb];
    if ((ga > 0 && gb > 0) || (ga < 0 && gb < 0)) continue;
    double r = stationary_point(t, q, w, ka, kb);
    if (!(r > lo && r < hi)) continue; /* outside: the end values cover it */
    double hv = q * r + w * hermite_F(t, r);
    if (want_min ? hv < best : hv > best) best = hv;
  }
  return best;
}
