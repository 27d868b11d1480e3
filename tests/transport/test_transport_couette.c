/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Shear-induced migration in a wide-gap Couette cell (Phillips et al. 1992;
 * Nigam 1999 section 4.5), on a 1-D
 * axisymmetric radial line r in [0.2689, 1] (lengths scaled by the outer
 * radius), inner cylinder at speed 1, neutrally buoyant, K_c = 0.41,
 * K_mu = 0.62, mu = (1 - phi/0.68)^(-1.82), a^2 = 2.029e-4, uniform phi =
 * 0.55 at t = 0; the shear rate g = C/(r^2 mu(phi)) from the torque balance
 * at every outer step, C from the inner wall speed (eq 4.207). Run to a
 * steady state (max |dphi/dt| < 1e-10) on 16, 32 and 64 cells, then:
 *  - against the reference table of the steady profile (Nigam 1999, eq 4.206): |dphi| <= 0.01 from
 *    32 cells on;
 *  - against the exact steady state (eq 4.206, Newton, with the phi_w that
 *    gives the same mean), r-weighted cell averages: errors fall at second
 *    order with the cell size;
 *  - the mean of phi is conserved to 1e-12 relative;
 *  - the velocity v(r) = r int_r^1 C/(r'^3 mu) dr' of the steady state
 *    against the table's (within 0.01 of the wall speed);
 *  - order 2 (SSP-RK2 sub-steps) reaches the same steady state as order 1.
 * The steady state does not depend on a^2 or the speed (they scale time),
 * nor does the number of sub-steps to reach it. */
#include "migration_exact.h"
#include "testing.h"

#define R_IN 0.2689
#define A2 2.029e-4
#define PHI0 0.55
#define TOL_RATE 1e-10

static const double tab_r[] = {0.2689, 0.30, 0.35, 0.40, 0.45, 0.50, 0.60, 0.70, 0.80, 0.90, 1.00};
static const double tab_phi[] = {0.2830, 0.3208, 0.3750, 0.4208, 0.4590, 0.4907,
                                 0.5385, 0.5716, 0.5951, 0.6120, 0.6246};
static const double tab_v[] = {1.0000, 0.7115, 0.4245, 0.2620, 0.1666, 0.1087, 0.0491, 0.0231, 0.0105, 0.0039, 0};
#define NTAB ((int)(sizeof tab_r / sizeof tab_r[0]))

/* v(x) = x int_x^1 C/(r^3 mu) dr with mu piecewise constant on the cells
 * and C such that v(R_IN) = 1. */
static double couette_v(const mx_run *r, double x) {
  const sl_mesh *m = r->m;
  double I = 0, Ix = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double r0 = m->xy[2 * m->cell_vertices[2 * c]], r1 = m->xy[2 * m->cell_vertices[2 * c + 1]];
    double mu = mx_mu(r->phi[c]);
    I += 0.5 * (1 / (r0 * r0) - 1 / (r1 * r1)) / mu;
    double a = fmax(r0, x);
    if (a < r1) Ix += 0.5 * (1 / (a * a) - 1 / (r1 * r1)) / mu;
  }
  return x * Ix / (R_IN * I);
}

typedef struct level {
  int N;
  double err_max, err_l1, tab_err, v_err, mass_err, phi_w;
} level;

static void run_level(level *L, int order, double *phi_out) {
  mx_run r;
  mx_open(&r, MX_COUETTE, L->N, A2, PHI0, order);
  double rate = mx_steady(&r, 10, TOL_RATE, 1e6);
  CHECK_MSG(rate < TOL_RATE, "N = %d: no steady state (rate %g at t = %g)", L->N, rate, r.time);
  double mean = mx_run_mean(&r);
  L->mass_err = fabs(sl_transport_mass(r.t, r.phi) - r.mass0) / r.mass0;
  /* Exact steady state with the same mean. */
  mx_exact x = {.p = -2, .r_w = R_IN, .e = MX_EXPO * (MX_KMU / MX_KC - 1)};
  mx_fit(&x, r.m, mean);
  L->phi_w = x.phi_w;
  double *avg = malloc((size_t)L->N * sizeof *avg);
  if (!avg) exit(1);
  mx_mean(&x, r.m, avg);
  const double *vol = sl_transport_volumes(r.t);
  double V = 0;
  L->err_max = L->err_l1 = 0;
  for (int c = 0; c < L->N; ++c) {
    double e = fabs(r.phi[c] - avg[c]);
    L->err_max = fmax(L->err_max, e);
    L->err_l1 += e * vol[c], V += vol[c];
  }
  L->err_l1 /= V;
  L->tab_err = L->v_err = 0;
  for (int k = 0; k < NTAB; ++k) {
    L->tab_err = fmax(L->tab_err, fabs(mx_interp(&r, tab_r[k]) - tab_phi[k]));
    L->v_err = fmax(L->v_err, fabs(couette_v(&r, tab_r[k]) - tab_v[k]));
  }
  printf(
      "N = %3d, order %d: steady at t = %.0f after %ld sub-steps (%ld outer), phi in [%.4f, %.4f]; exact "
      "(phi_w = %.5f): max |error| %.2e, mean |error| %.2e; reference table: max |dphi| %.2e, max |dv| %.2e; "
      "mean %.15f, relative change %.1e; limited faces %d, clamped %.1e\n",
      L->N, order, r.time, r.substeps, r.outer, r.phi[0], r.phi[L->N - 1], x.phi_w, L->err_max, L->err_l1, L->tab_err,
      L->v_err, mean, L->mass_err, r.limited, r.clamped);
  if (phi_out) memcpy(phi_out, r.phi, (size_t)L->N * sizeof *phi_out);
  free(avg);
  mx_close(&r);
}

int main(void) {
  level lv[3] = {{.N = 16}, {.N = 32}, {.N = 64}};
  double phi1[16], phi2[16];
  for (int i = 0; i < 3; ++i) run_level(&lv[i], 1, i == 0 ? phi1 : NULL);
  for (int i = 0; i < 3; ++i) {
    CHECK_MSG(lv[i].mass_err <= 1e-12, "N = %d: mean changed by %.2e relative", lv[i].N, lv[i].mass_err);
    /* The exact mean 0.55 fits phi_w = 0.28326 (found by bisection). */
    CHECK_MSG(fabs(lv[i].phi_w - 0.28326) < 5e-5, "N = %d: phi_w = %.6f", lv[i].N, lv[i].phi_w);
  }
  double o_max1 = log2(lv[0].err_max / lv[1].err_max), o_max2 = log2(lv[1].err_max / lv[2].err_max);
  double o_l11 = log2(lv[0].err_l1 / lv[1].err_l1), o_l12 = log2(lv[1].err_l1 / lv[2].err_l1);
  printf("observed orders against the exact steady state: max %.2f, %.2f; mean %.2f, %.2f\n", o_max1, o_max2, o_l11,
         o_l12);
  CHECK_MSG(o_max1 > 1.7 && o_max2 > 1.7 && o_l11 > 1.7 && o_l12 > 1.7, "orders %.2f %.2f %.2f %.2f", o_max1, o_max2,
            o_l11, o_l12);
  CHECK_MSG(lv[2].err_max < 1e-3, "N = 64: max error %.2e against the exact steady state", lv[2].err_max);
  /* The reference table: |dphi| <= 0.01 (its tolerance), v within 0.01 of the wall speed, from 32 cells on (16
   * cells miss it at the inner wall by a few 1e-3). */
  for (int i = 1; i < 3; ++i) {
    CHECK_MSG(lv[i].tab_err <= 0.01, "N = %d: max |dphi| %.3e against the reference table", lv[i].N, lv[i].tab_err);
    CHECK_MSG(lv[i].v_err <= 0.01, "N = %d: max |dv| %.3e against the reference table", lv[i].N, lv[i].v_err);
  }
  /* The finest level is within 2e-3 of the table (what remains is the table's phi_w = 0.283, rounded, and the
   * interpolation to the walls). */
  CHECK_MSG(lv[2].tab_err <= 2e-3, "N = 64: max |dphi| %.3e against the reference table", lv[2].tab_err);
  /* Order 2 (SSP-RK2 sub-steps, no reconstruction is involved without an advective flux): the same steady state. */
  level l2 = {.N = 16};
  run_level(&l2, 2, phi2);
  double diff = 0;
  for (int c = 0; c < 16; ++c) diff = fmax(diff, fabs(phi1[c] - phi2[c]));
  printf("N = 16: order 2 against order 1 steady states: max |difference| %.2e\n", diff);
  CHECK_MSG(diff < 1e-6, "order 1 and 2 steady states differ by %.2e", diff);
  return sl_test_summary();
}
