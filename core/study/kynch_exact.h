/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The exact entropy solution of 1-D batch settling (Kynch 1952) in a closed
 * column 0 <= z <= H (z up), phi(z, 0) = phi0:
 *
 *   phi_t - (F(phi))_z = 0,   F(phi) = u_t phi (1 - phi)^p (1 - phi/c)^m exp(-k phi),   F(0) = F(c) = 0,
 *
 * which covers Richardson & Zaki (1954) with a packing cut-off (p = n, m = 1,
 * c = phi_max), Nigam (1999) eqs 2.20/2.36 (p = 2, m = K alpha_m, c =
 * alpha_m) and Vesilind (1968), 10^(-a phi) = exp(-a ln(10) phi), with its
 * smooth cut-off (p = 0, m = 1) or a step one (m = 0 and F(c) = 0 alone:
 * `step`, a flux that drops to zero at c). F is concave then convex (one
 * inflection point, checked).
 *
 * Construction (Kynch 1952, Trans. Faraday Soc. 48:166; Bustos, Concha, Bürger
 * & Tory 1999, "Sedimentation and Thickening"): the walls act as the states 0
 * above and c below.
 *  - Top: 0 | phi0 is one shock falling at v0 = F(phi0)/phi0 when the chord
 *    from 0 to phi0 lies below F (checked).
 *  - Bottom: the lower convex hull of F on [phi0, c]. With phi0 below the
 *    inflection, the chord from phi0 either reaches c (one shock rising at
 *    F(phi0)/(c - phi0)) or touches F at phi* where F'(phi*) = (F(phi*) -
 *    F(phi0))/(phi* - phi0): a shock phi0 | phi* rising at -F'(phi*) (a
 *    contact: it moves with the characteristics of its lower side), then a
 *    rarefaction fan z/t = -F'(phi) for phi from phi* to c, then the sediment
 *    phi = c below z = -F'(c) t. With phi0 past the inflection the bottom is
 *    a fan from phi0. With a step at c the hull reaches (c, 0) along the
 *    tangent from it, touching F at phi_e (F'(phi_e) (c - phi_e) + F(phi_e) =
 *    0): the fan ends at phi_e, over the sediment's contact shock rising at
 *    -F'(phi_e) (one shock phi0 | c when the tangent from phi0 touches past
 *    phi_e).
 *  - The fronts meet at t1 = H / (v0 + sigma). After that (fan cases) the
 *    interface 0 | phi descends through the fan: dz/dt = -F(phi)/phi with z =
 *    -F'(phi) t, i.e. d ln t / d phi = F''(phi) / (F(phi)/phi - F'(phi)),
 *    integrated by quadrature, until phi = c (phi_e with a step) at t2
 *    (infinite when F'(c) = 0); then the sediment phi0 H / c high is at rest.
 * Cell averages are exact: over the fan, int phi dz = -t [phi F' - F]. */
#ifndef SLUICE_VERIFY_KYNCH_EXACT_H
#define SLUICE_VERIFY_KYNCH_EXACT_H

#include <math.h>
#include <stdio.h>

#include "core/util/diag.h"

typedef struct kx_law {
  double u_t, p, c, m;
  double k; /* exp(-k phi); 0: none */
  int step; /* F(c) = 0 by a step (m = 0) */
} kx_law;

static inline kx_law kx_richardson_zaki(double u_t, double n, double phi_max) {
  kx_law l = {u_t, n, phi_max, 1.0, 0.0, 0};
  return l;
}

/* The same with the flux truncated at phi_max (a step to zero there) instead of the factor (1 - phi/phi_max). */
static inline kx_law kx_richardson_zaki_step(double u_t, double n, double phi_max) {
  kx_law l = {u_t, n, phi_max, 0.0, 0.0, 1};
  return l;
}

static inline kx_law kx_nigam(double u_t, double K, double alpha_m) {
  kx_law l = {u_t, 2.0, alpha_m, K * alpha_m, 0.0, 0};
  return l;
}

/* Vesilind (1968): u_t 10^(-a phi), with the smooth cut-off (1 - phi/c) or the step one at c. */
static inline kx_law kx_vesilind(double u_t, double a, double c, int step) {
  kx_law l = {u_t, 0.0, c, step ? 0.0 : 1.0, a * 2.302585092994045684, step};
  return l;
}

/* F = u_t phi A B, A = (1 - phi)^p, B = (1 - phi/c)^m exp(-k phi) (the smooth
 * F of a step law below c). */
static inline void kx_parts(const kx_law *l, double x, double *A, double *A1, double *A2, double *B, double *B1,
                            double *B2) {
  double e = 1 - x, r = 1 - x / l->c;
  if (r < 0) r = 0;
  *A = pow(e, l->p), *A1 = -l->p * pow(e, l->p - 1), *A2 = l->p * (l->p - 1) * pow(e, l->p - 2);
  double C = pow(r, l->m);
  double C1 = l->m == 0 ? 0.0 : -l->m / l->c * (l->m == 1 ? 1.0 : pow(r, l->m - 1));
  double C2 = l->m == 0 || l->m == 1 ? 0.0 : l->m * (l->m - 1) / (l->c * l->c) * pow(r, l->m - 2);
  double E = exp(-l->k * x), k = l->k;
  *B = C * E, *B1 = (C1 - k * C) * E, *B2 = (C2 - 2 * k * C1 + k * k * C) * E;
}

static inline double kx_F(const kx_law *l, double x) {
  double A, A1, A2, B, B1, B2;
  if (l->step && x >= l->c) return 0.0;
  kx_parts(l, x, &A, &A1, &A2, &B, &B1, &B2);
  return l->u_t * x * A * B;
}

static inline double kx_dF(const kx_law *l, double x) {
  double A, A1, A2, B, B1, B2;
  kx_parts(l, x, &A, &A1, &A2, &B, &B1, &B2);
  return l->u_t * (A * B + x * (A1 * B + A * B1));
}

static inline double kx_d2F(const kx_law *l, double x) {
  double A, A1, A2, B, B1, B2;
  kx_parts(l, x, &A, &A1, &A2, &B, &B1, &B2);
  return l->u_t * (2 * (A1 * B + A * B1) + x * (A2 * B + 2 * A1 * B1 + A * B2));
}

/* The settling callback of core/transport/flux.h for this law: u = F/phi. */
static inline int kx_settling(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  const kx_law *l = user;
  (void)d;
  for (int i = 0; i < n; ++i) {
    double A, A1, A2, B, B1, B2;
    kx_parts(l, phi[i], &A, &A1, &A2, &B, &B1, &B2);
    int cut = l->step && phi[i] >= l->c;
    u[i] = cut ? 0.0 : l->u_t * A * B;
    du[i] = cut ? 0.0 : l->u_t * (A1 * B + A * B1);
  }
  return 0;
}

enum { KX_SHOCK, KX_CONTACT, KX_FAN };
#define KX_NT 400

typedef struct kynch {
  kx_law law;
  double H, phi0;
  double infl;    /* inflection point of F */
  double v0;      /* speed of the top interface (downwards) */
  int bottom;     /* KX_SHOCK, KX_CONTACT or KX_FAN */
  double phis;    /* phi*: upper state of the fan (c for a single shock, phi0 for a fan from phi0) */
  double phie;    /* the fan's lower end: c, or phi_e with a step (c for a single shock) */
  double sigma;   /* speed of the top of the bottom structure (upwards) */
  double sed;     /* -F'(phie): the top of the phi = c layer rises at this speed (fan cases) */
  double t1, z1;  /* the fronts meet */
  double t2;      /* the interface reaches the sediment; at rest afterwards (INFINITY: never) */
  double z_final; /* phi0 H / c */
  /* ln(t/t1) at the interface as a function of its state phi: nodes graded
   * towards c and the cumulative integral (fan cases). */
  double lt_x[KX_NT + 1], lt_v[KX_NT + 1];
} kynch;

/* phi in [lo, c] with F'(phi) = s, F' increasing there (the convex part). */
static inline double kx_inv_dF(const kx_law *l, double lo, double s) {
  double a = lo, b = l->c;
  if (s <= kx_dF(l, a)) return a;
  if (s >= kx_dF(l, b)) return b;
  for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
    double mid = 0.5 * (a + b);
    if (kx_dF(l, mid) < s) a = mid;
    else b = mid;
  }
  return 0.5 * (a + b);
}

/* Gauss-Legendre, 8 points, on [a, b]. */
static inline double kx_gl8(double (*f)(const kx_law *, double), const kx_law *l, double a, double b) {
  static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double h = 0.5 * (b - a), mid = 0.5 * (a + b), s = 0;
  for (int i = 0; i < 4; ++i) s += w[i] * (f(l, mid - h * x[i]) + f(l, mid + h * x[i]));
  return s * h;
}

static inline double kx_interface_rate(const kx_law *l, double x) {
  return kx_d2F(l, x) / (kx_F(l, x) / x - kx_dF(l, x));
}

/* The table of ln(t/t1) against the interface state: nodes from phi* to
 * within 1e-13 of c, geometric in the distance to c (the integrand grows
 * like 1/(c - phi) when F'(c) = 0), 8-point Gauss-Legendre per panel. */
static inline void kx_log_time_table(kynch *k) {
  double c = k->phie, da = c - k->phis, db = 1e-13 * k->law.c;
  k->lt_x[0] = k->phis, k->lt_v[0] = 0;
  for (int j = 1; j <= KX_NT; ++j) {
    k->lt_x[j] = c - da * pow(db / da, (double)j / KX_NT);
    k->lt_v[j] = k->lt_v[j - 1] + kx_gl8(kx_interface_rate, &k->law, k->lt_x[j - 1], k->lt_x[j]);
  }
}

/* Sets up the solution; returns 0, or -1 (with a message on stderr) when the
 * flux or phi0 is outside what this construction covers. */
static inline int kx_init(kynch *k, kx_law law, double H, double phi0) {
  const kx_law *l = &k->law;
  k->law = law, k->H = H, k->phi0 = phi0;
  /* The inflection: F'' changes sign once on (0, c). */
  int n_sign = 0;
  double prev = kx_d2F(l, 1e-9), xa = 0;
  for (int i = 1; i < 4000; ++i) {
    double x = law.c * i / 4000.0, v = kx_d2F(l, x);
    if ((v > 0) != (prev > 0)) ++n_sign, xa = law.c * (i - 1) / 4000.0;
    prev = v;
  }
  if (n_sign != 1 || kx_d2F(l, 1e-9) >= 0) {
    fprintf(stderr, "kynch: F is not concave-then-convex (%d sign changes of F'')\n", n_sign);
    return -1;
  }
  double a = xa, b = xa + law.c / 4000.0;
  for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
    double mid = 0.5 * (a + b);
    if (kx_d2F(l, mid) < 0) a = mid;
    else b = mid;
  }
  k->infl = 0.5 * (a + b);
  double F0 = kx_F(l, phi0);
  k->v0 = F0 / phi0;
  for (int i = 1; i < 2000; ++i) { /* the top is one shock: F above the chord from 0 */
    double x = phi0 * i / 2000.0;
    if (kx_F(l, x) < k->v0 * x * (1 - 1e-12)) {
      fprintf(stderr, "kynch: phi0 = %g: the top is not a single shock\n", phi0);
      return -1;
    }
  }
  /* the fan's lower end: c, or with a step the tangency from (c, 0), where t(x) = F'(x)(c - x) + F(x)
     increases from t(infl) through 0 (none when t(infl) >= 0: the sediment is reached by one shock) */
  k->phie = law.c;
  if (law.step) {
    k->phie = k->infl;
    if (kx_dF(l, k->infl) * (law.c - k->infl) + kx_F(l, k->infl) < 0) {
      a = k->infl, b = law.c;
      for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
        double mid = 0.5 * (a + b);
        if (kx_dF(l, mid) * (law.c - mid) + kx_F(l, mid) < 0) a = mid;
        else b = mid;
      }
      k->phie = 0.5 * (a + b);
    }
  }
  k->sed = -kx_dF(l, k->phie);
  if (k->sed < 1e-14 * law.u_t) k->sed = 0;
  if (phi0 >= k->infl && phi0 < k->phie) {
    k->bottom = KX_FAN, k->phis = phi0, k->sigma = -kx_dF(l, phi0);
    if (!(k->sigma > 0)) {
      fprintf(stderr, "kynch: phi0 = %g: the fan does not rise\n", phi0);
      return -1;
    }
  } else {
    /* g(x) = F'(x)(x - phi0) - (F(x) - F0) < 0 on the concave part, increasing on the convex one: the tangent
       from phi0 touches F where g = 0, if before the fan's end; otherwise one shock to c */
    double ge = kx_dF(l, k->phie) * (k->phie - phi0) - (kx_F(l, k->phie) - F0);
    if (phi0 >= k->infl || ge <= 0) {
      k->bottom = KX_SHOCK, k->phis = k->phie = law.c, k->sigma = F0 / (law.c - phi0);
    } else {
      a = k->infl, b = k->phie;
      for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
        double mid = 0.5 * (a + b);
        if (kx_dF(l, mid) * (mid - phi0) - (kx_F(l, mid) - F0) < 0) a = mid;
        else b = mid;
      }
      k->bottom = KX_CONTACT, k->phis = 0.5 * (a + b), k->sigma = -kx_dF(l, k->phis);
    }
  }
  k->t1 = H / (k->v0 + k->sigma);
  k->z1 = k->sigma * k->t1;
  k->z_final = phi0 * H / law.c;
  if (k->bottom == KX_SHOCK) {
    k->t2 = k->t1;
    return 0;
  }
  kx_log_time_table(k);
  k->t2 = k->sed == 0 ? INFINITY : k->t1 * exp(k->lt_v[KX_NT]);
  return 0;
}

/* The state just below the top interface after the meeting: ln(t/t1) =
 * int_phis^phi rate; the table's panel, then safeguarded Newton in it. */
static inline double kx_interface_phi(const kynch *k, double t) {
  double target = log(t / k->t1);
  if (target >= k->lt_v[KX_NT]) return k->phie;
  int lo = 0, hi = KX_NT;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (k->lt_v[mid] <= target) lo = mid;
    else hi = mid;
  }
  double a = k->lt_x[lo], b = k->lt_x[hi], x = 0.5 * (a + b);
  for (int it = 0; it < 60; ++it) {
    double g = k->lt_v[lo] + kx_gl8(kx_interface_rate, &k->law, k->lt_x[lo], x) - target;
    if (g < 0) a = x;
    else b = x;
    double xn = x - g / kx_interface_rate(&k->law, x);
    if (!(xn > a && xn < b)) xn = 0.5 * (a + b);
    if (fabs(xn - x) < 1e-16) break;
    x = xn;
  }
  return x;
}

/* The solution at time t as up to four regions [z[i], z[i+1]], each constant
 * (val[i]) or a fan (fan[i] != 0). Returns the number of regions. */
typedef struct kx_profile {
  int n;
  double z[5], val[4];
  int fan[4];
  double t;
} kx_profile;

static inline void kx_region(kx_profile *p, double zhi, double val, int fan) {
  double zlo = p->z[p->n];
  if (zhi <= zlo) return;
  p->val[p->n] = val, p->fan[p->n] = fan;
  p->z[++p->n] = zhi;
}

static inline kx_profile kx_at(const kynch *k, double t) {
  kx_profile p = {0, {0}, {0}, {0}, t};
  const double c = k->law.c, H = k->H;
  if (t <= k->t1) {
    double top = H - k->v0 * t;
    if (k->bottom == KX_SHOCK) {
      kx_region(&p, k->sigma * t, c, 0);
    } else {
      kx_region(&p, k->sed * t, c, 0);
      kx_region(&p, k->sigma * t, 0, 1);
    }
    kx_region(&p, top, k->phi0, 0);
    kx_region(&p, H, 0, 0);
  } else if (t >= k->t2) {
    kx_region(&p, k->z_final, c, 0);
    kx_region(&p, H, 0, 0);
  } else {
    double phiI = kx_interface_phi(k, t);
    kx_region(&p, k->sed * t, c, 0);
    kx_region(&p, -kx_dF(&k->law, phiI) * t, 0, 1);
    kx_region(&p, H, 0, 0);
  }
  return p;
}

static inline double kx_fan_phi(const kynch *k, double z, double t) { return kx_inv_dF(&k->law, k->phis, -z / t); }

static inline double kx_value(const kynch *k, const kx_profile *p, double z) {
  for (int i = 0; i < p->n; ++i)
    if (z <= p->z[i + 1] || i == p->n - 1) return p->fan[i] ? kx_fan_phi(k, z, p->t) : p->val[i];
  return 0;
}

/* int_za^zb phi dz. */
static inline double kx_integral(const kynch *k, const kx_profile *p, double za, double zb) {
  double s = 0;
  for (int i = 0; i < p->n; ++i) {
    double a = fmax(za, p->z[i]), b = fmin(zb, p->z[i + 1]);
    if (b <= a) continue;
    if (!p->fan[i]) {
      s += p->val[i] * (b - a);
    } else {
      double pa = kx_fan_phi(k, a, p->t), pb = kx_fan_phi(k, b, p->t);
      s += -p->t * ((pb * kx_dF(&k->law, pb) - kx_F(&k->law, pb)) - (pa * kx_dF(&k->law, pa) - kx_F(&k->law, pa)));
    }
  }
  return s;
}

#endif
