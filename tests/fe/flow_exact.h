/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Manufactured solutions for the flow operator: the body force is the strong
 * form of the equations applied to an exact (u, p), written in the
 * textbook component form and differentiated numerically, so that it shares
 * no code and no tensor algebra with the assembler:
 *
 *  planar:        rho (u.grad)u - div sigma = f - grad p terms as usual,
 *                 (div sigma)_i = d_x sigma_ix + d_y sigma_iy;
 *  axisymmetric:  (u.grad u)_r = u_r d_r u_r + u_z d_z u_r - u_t^2 / r,
 *                 (u.grad u)_z = u_r d_r u_z + u_z d_z u_z,
 *                 (u.grad u)_t = u_r d_r u_t + u_z d_z u_t + u_r u_t / r,
 *                 (div sigma)_r = d_r s_rr + d_z s_rz + (s_rr - s_tt) / r,
 *                 (div sigma)_z = d_r s_rz + d_z s_zz + s_rz / r,
 *                 (div sigma)_t = d_r s_rt + d_z s_zt + 2 s_rt / r,
 *  with D_rr = d_r u_r, D_zz = d_z u_z, D_tt = u_r / r,
 *  D_rz = (d_z u_r + d_r u_z)/2, D_rt = (d_r u_t - u_t / r)/2, D_zt = d_z u_t / 2
 *  (Bird, Stewart & Lightfoot 2002, appendix B.1 and B.2, d/dtheta = 0).
 * Derivatives: fourth-order central differences (step 1e-3, error ~1e-11
 * after nesting), far below the discretisation errors measured. */
#ifndef SLUICE_TESTS_FE_FLOW_EXACT_H
#define SLUICE_TESTS_FE_FLOW_EXACT_H

#include <math.h>

#include "core/assembly/operators.h"

typedef struct flow_exact {
  int axisymmetric;
  int n_comp; /* in-plane 2, or 3 with the out-of-plane/swirl component (index 2) */
  int convection;
  /* u (3 components: x/r, y/z, out-of-plane/theta) and p at (x, y, t) */
  void (*u)(const double x[2], double t, double u[3]);
  double (*p)(const double x[2], double t);
  double (*rho)(const double x[2]);
  /* mu(gamma) and its derivative */
  void (*mu)(double gamma, double *mu, double *dmu);
  double t;          /* time of the evaluation */
  double dudt_scale; /* rho du/dt is added when non-zero: du/dt by differences in t */
} flow_exact;

#define FE_H 1e-3

/* The exact velocity, without the third component when it is not solved for. */
static inline void flow_exact_u(const flow_exact *e, const double x[2], double t, double u[3]) {
  e->u(x, t, u);
  if (e->n_comp < 3) u[2] = 0.0;
}

static inline double fe_d4(double fm2, double fm1, double fp1, double fp2, double h) {
  return (fm2 - 8.0 * fm1 + 8.0 * fp1 - fp2) / (12.0 * h);
}

/* d u_a / d x_j at x, numerically. */
static inline void flow_exact_grad(const flow_exact *e, const double x[2], double G[3][2]) {
  for (int j = 0; j < 2; ++j) {
    double v[4][3];
    const double off[4] = {-2, -1, 1, 2};
    for (int k = 0; k < 4; ++k) {
      double y[2] = {x[0], x[1]};
      y[j] += off[k] * FE_H;
      flow_exact_u(e, y, e->t, v[k]);
    }
    for (int a = 0; a < 3; ++a) G[a][j] = fe_d4(v[0][a], v[1][a], v[2][a], v[3][a], FE_H);
  }
}

/* The stress sigma = 2 mu D - p I, components rr zz tt rz rt zt (or xx yy
 * ww xy xw yw planar), and the strain D in the same order. */
static inline void flow_exact_stress(const flow_exact *e, const double x[2], double s[6], double *gamma_out) {
  double u[3], G[3][2];
  flow_exact_u(e, x, e->t, u);
  flow_exact_grad(e, x, G);
  double D[6];
  D[0] = G[0][0], D[1] = G[1][1];
  D[3] = 0.5 * (G[0][1] + G[1][0]);
  if (e->axisymmetric) {
    double r = x[0];
    D[2] = u[0] / r;
    D[4] = 0.5 * (G[2][0] - u[2] / r);
    D[5] = 0.5 * G[2][1];
  } else {
    D[2] = 0.0, D[4] = 0.5 * G[2][0], D[5] = 0.5 * G[2][1];
  }
  double dd = D[0] * D[0] + D[1] * D[1] + D[2] * D[2] + 2.0 * (D[3] * D[3] + D[4] * D[4] + D[5] * D[5]);
  double gamma = sqrt(2.0 * dd), mu, dmu;
  e->mu(gamma, &mu, &dmu);
  double p = e->p(x, e->t);
  for (int k = 0; k < 6; ++k) s[k] = 2.0 * mu * D[k];
  s[0] -= p, s[1] -= p, s[2] -= p;
  if (gamma_out) *gamma_out = gamma;
}

/* The body force f (n_comp components) that makes (u, p) exact. */
static inline void flow_exact_force(const flow_exact *e, const double x[2], double *f) {
  double u[3], G[3][2], s[6], ds[2][6];
  flow_exact_u(e, x, e->t, u);
  flow_exact_grad(e, x, G);
  flow_exact_stress(e, x, s, NULL);
  for (int j = 0; j < 2; ++j) {
    double v[4][6];
    const double off[4] = {-2, -1, 1, 2};
    for (int k = 0; k < 4; ++k) {
      double y[2] = {x[0], x[1]};
      y[j] += off[k] * FE_H;
      flow_exact_stress(e, y, v[k], NULL);
    }
    for (int c = 0; c < 6; ++c) ds[j][c] = fe_d4(v[0][c], v[1][c], v[2][c], v[3][c], FE_H);
  }
  /* stress components: 0 rr, 1 zz, 2 tt, 3 rz, 4 rt, 5 zt */
  double div[3], conv[3];
  div[0] = ds[0][0] + ds[1][3];
  div[1] = ds[0][3] + ds[1][1];
  div[2] = ds[0][4] + ds[1][5];
  for (int a = 0; a < 3; ++a) conv[a] = u[0] * G[a][0] + u[1] * G[a][1];
  if (e->axisymmetric) {
    double r = x[0];
    div[0] += (s[0] - s[2]) / r;
    div[1] += s[3] / r;
    div[2] += 2.0 * s[4] / r;
    conv[0] -= u[2] * u[2] / r;
    conv[2] += u[0] * u[2] / r;
  }
  double rho = e->rho(x), dudt[3] = {0, 0, 0};
  if (e->dudt_scale != 0.0) {
    double v[4][3];
    const double off[4] = {-2, -1, 1, 2};
    for (int k = 0; k < 4; ++k) flow_exact_u(e, x, e->t + off[k] * FE_H, v[k]);
    for (int a = 0; a < 3; ++a) dudt[a] = fe_d4(v[0][a], v[1][a], v[2][a], v[3][a], FE_H);
  }
  int map[3] = {0, 1, 2};
  for (int c = 0; c < e->n_comp; ++c) {
    int a = map[c];
    f[c] = rho * (dudt[a] + (e->convection ? conv[a] : 0.0)) - div[a];
  }
}

/* sl_qp_fn adapters */
static inline int flow_exact_force_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const flow_exact *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) flow_exact_force(e, b->x[i], out + (size_t)e->n_comp * i);
  return 0;
}

/* The traction sigma.n on a boundary (normal from the batch). */
static inline int flow_exact_traction_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const flow_exact *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) {
    double s[6];
    flow_exact_stress(e, b->x[i], s, NULL);
    const double *n = b->normal[i];
    /* in-plane rows of sigma: (0,0) (0,1); (1,0) (1,1); out-of-plane row (2,0) (2,1) */
    double t[3] = {s[0] * n[0] + s[3] * n[1], s[3] * n[0] + s[1] * n[1], s[4] * n[0] + s[5] * n[1]};
    for (int c = 0; c < e->n_comp; ++c) out[e->n_comp * i + c] = t[c];
  }
  return 0;
}

static inline int flow_exact_rho_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const flow_exact *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) out[i] = e->rho(b->x[i]);
  return 0;
}

static inline int flow_exact_mu_fn(void *user, const sl_qp_batch *b, double *out, sl_diag *d) {
  const flow_exact *e = user;
  (void)d;
  for (int i = 0; i < b->n; ++i) e->mu(b->shear_rate[i], &out[2 * i], &out[2 * i + 1]);
  return 0;
}

#endif
