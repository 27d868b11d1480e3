/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Model C's transported k_s and k_fs (core/models/pipe/pipe_ksfs.c: Krampa 2009 eqs 5.20, 5.23 in the form of
 * Simonin 1996 and Peirano & Leckner 1998), `[pipe] solids_turbulence = transported`:
 *  - homogeneous (no shear, uniform state) and without collisional dissipation (e = 1) the transported pair is
 *    Tchen's equilibrium k_fs = 2k t_fs/(t_fs + t_p), k_s = k_fs/2 (what solids_turbulence = equilibrium takes),
 *    to 1e-13, on the pipe's own solver (the shared cell scalar) started away from it;
 *  - homogeneous with collisions (e = 0.9): the local balance of the two equations, K (k_fs - 2 k_s) = m (1 -
 *    e^2)/(3 t_c) k_s and K [2k + 2 S k_s - (1 + S) k_fs] = m k_fs/t_fs, solved here independently by bisection
 *    in k_s (t_c of eq 5.19 written out), to 1e-10;
 *  - fine particles (t_p/t_fs = 1e-6) in a sheared state follow the fluid: k_fs = 2k and k_s = k to 1e-4;
 *  - in the pipe (configs/vertical_pipe.ini as model C: Peirano & Leckner's viscosity, Simonin's modulation and
 *    dispersion, k_s and k_fs transported): converges, the mixture's momentum -dP/dz = 4 tau_w/D + rho_m g to 1e-8,
 *    the manometric gradient at second order in the radial cells (20-160 cells, the wall cell held at y+ = 40:
 *    the observed order of the differences between 1.5 and 2.5), and Tchen's equilibrium gives a lower gradient
 *    than the transport; the shipped configs/vertical_pipe_model_c.ini is the same scene (to 1e-12);
 *  - the developing pipe (k_s and k_fs convected by the solids): its outlet after 32 m (600 D) is the fully
 *    developed pipe at the outlet's in-situ fraction, -dP/dz to 2e-4, tau_fw to 2e-3, u_s at r/R = 0.4, 0.8 to
 *    1e-3 (measured 6e-5, 9e-4, 3e-4, 2e-4); after the thesis's 4 m the outlet is still developing (printed);
 *  - the developing pipe's drift work of the modulation (Krampa eqs 4.80-4.82, pipe_march_drift_work): zero in a
 *    station equal to the last (exactly), its axial and its radial parts against values by hand (1e-12, 1e-10);
 *  - Johnson & Jackson's solids wall (its energy flux into k_s): converges, the mixture's momentum to 1e-8;
 *  - bad input: solids_turbulence = transported without solids_viscosity = peirano_leckner, or a misspelt choice,
 *    is refused with exit status 2 and a suggestion, before any output is written. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/pipe/pipe_impl.h"
#include "pipe_testing.h"
#include "testing.h"

static const double PI = 3.14159265358979323846;

/* A pipe of n radial cells in a given uniform state, the arrays pipe_ksfs_update reads (no scene). */
typedef struct bench {
  pipe p;
  pipe_config cfg;
  sl_mesh *mesh;
  sl_tensor_grid tg;
  double *arr[16];
} bench;

static int bench_open(bench *b, int n, double e, double K, double slip, double shear) {
  memset(b, 0, sizeof *b);
  pipe *p = &b->p;
  sl_diag d = {{0}};
  b->cfg = (pipe_config){.restitution = e,
                         .crossing_trajectory = 0.45,
                         .covariance_schmidt = 1.0,
                         .solids_turbulence = PIPE_SOLIDS_TURBULENCE_TRANSPORTED};
  p->cfg = &b->cfg, p->n = n, p->R = 0.0266, p->rho_f = 997.56, p->rho_s = 2500.0, p->d_p = 5e-4;
  p->phi_max = 0.63, p->c_mu = 0.09, p->relax = 1.0, p->iterations = 1, p->two_phase = 1;
  sl_grid_opts o = {.cell_type = SL_CELL_QUAD4, .grade_x = {SL_GRADE_UNIFORM, 1.0}};
  const int periodic[2] = {0, 1};
  int rc = sl_mesh_rectangle(0.0, p->R, 0.0, 0.1 * p->R, n, 1, &o, &b->mesh, &d);
  if (!rc) rc = sl_tensor_grid_from_mesh(b->mesh, &b->tg, &d);
  if (!rc) rc = sl_fv_grid_build(&p->g, &b->tg, 1, periodic, &d);
  if (!rc) rc = sl_cell_scalar_init(&p->cs, &p->g, &d);
  CHECK_MSG(rc == 0, "the bench's grid: %s", d.msg);
  if (rc) return rc;
  double **a[] = {&p->uf, &p->us, &p->phi, &p->k, &p->eps, &p->K, &p->ks, &p->kfs, &p->theta, &p->mu_s};
  for (int i = 0; i < 10; ++i) *a[i] = b->arr[i] = calloc((size_t)n, sizeof(double));
  for (int i = 0; i < PIPE_NBUF; ++i) p->buf[i] = calloc((size_t)n, sizeof(double));
  for (int i = 0; i < n; ++i) {
    double r = p->g.xc[i];
    p->us[i] = 3.0 - shear * r, p->uf[i] = p->us[i] + slip, p->phi[i] = 0.25, p->k[i] = 0.02, p->eps[i] = 0.5;
    p->K[i] = K, p->ks[i] = 1e-3 * (1.0 + i), p->kfs[i] = 0.05; /* started away from the answer */
  }
  return 0;
}

static void bench_close(bench *b) {
  for (int i = 0; i < 10; ++i) free(b->arr[i]);
  for (int i = 0; i < PIPE_NBUF; ++i) free(b->p.buf[i]);
  sl_cell_scalar_free(&b->p.cs);
  sl_fv_grid_free(&b->p.g);
  sl_tensor_grid_free(&b->tg);
  sl_mesh_destroy(b->mesh);
}

/* Iterates the update to a fixed point; the last relative change. */
static double bench_converge(bench *b, int its) {
  pipe *p = &b->p;
  sl_diag d = {{0}};
  double ch = INFINITY;
  for (int it = 0; it < its && ch > 1e-15; ++it) {
    double s0 = p->ks[p->n / 2], f0 = p->kfs[p->n / 2];
    int rc = pipe_ksfs_update(p, &d);
    CHECK_MSG(rc == 0, "pipe_ksfs_update: %s", d.msg);
    if (rc) return NAN;
    ch = fmax(fabs(p->ks[p->n / 2] / s0 - 1.0), fabs(p->kfs[p->n / 2] / f0 - 1.0));
  }
  return ch;
}

/* The local balance with collisions, independently: k_fs(k_s) from the covariance's (linear), then the k_s
   equation's root by bisection. */
static void local_balance(const bench *b, double *ks, double *kfs) {
  const pipe *p = &b->p;
  const double cs = 0.25, m = cs * p->rho_s, K = p->K[0], e = b->cfg.restitution, k = p->k[0];
  const double s2 = (p->uf[0] - p->us[0]) * (p->uf[0] - p->us[0]);
  const double tfs = 0.09 * 1.5 * k / p->eps[0] / sqrt(1.0 + 0.45 * 1.5 * s2 / k); /* eq 4.61 */
  const double S = m / (0.75 * p->rho_f), g0 = pow(1.0 - cs / 0.63, -2.5 * 0.63);  /* eq 4.91 */
  double lo = 1e-12, hi = k, f = 0.0;
  for (int it = 0; it < 200; ++it) {
    double s = 0.5 * (lo + hi);
    f = K * (2.0 * k + 2.0 * S * s) / (K * (1.0 + S) + m / tfs);
    double tc = sqrt(PI) / (24.0 * cs * g0) * p->d_p * sqrt(3.0 / (2.0 * s)); /* eq 5.19 */
    double r = K * (f - 2.0 * s) - m * (1.0 - e * e) / (3.0 * tc) * s;
    if (r > 0.0) lo = s;
    else hi = s;
  }
  *ks = 0.5 * (lo + hi), *kfs = K * (2.0 * k + 2.0 * S * *ks) / (K * (1.0 + S) + m / tfs);
}

static double worst_rel(const double *a, double ref, int n) {
  double w = 0.0;
  for (int i = 0; i < n; ++i) w = fmax(w, fabs(a[i] / ref - 1.0));
  return w;
}

/* The developing pipe's drift work of the modulation (pipe_march_drift_work: Krampa 2009 eqs 4.80-4.82, W = A g
   (nu_t + D/(c_f c_s)), g = grad(c_f).(U_f - U_s)) on the bench's 20 cells, A = K = 1e4 kg/(m3 s), nu_t = D = 1e-3
   m2/s, the slip u_f - u_s = 0.2 m/s:
   - developed (the station equals the last: phi = phi_up with a radial gradient, the radial fluxes of continuity
     zero): W = 0 in every cell, exactly (the slip is axial, the gradient radial);
   - the axial part: phi 0.25 -> 0.24 over h = 0.04 m, uniform: dphi/dz = -0.25 /m, g = 0.25 x 0.2 = 0.05 /s,
     W = 1e4 x 0.05 x 1e-3 (1 + 1/(0.76 x 0.24)) = 3.2412280701754386 W/m3 in every cell (a source of k);
   - the radial part: phi = 0.3 - 2 r (dphi/dr = -2 /m), phi = phi_up, the faces' radial velocities v_f - v_s =
     0.01 m/s given: g = 2 x 0.01 = 0.02 /s, W = 1e4 x 0.02 x 1e-3 (1 + 1/(c_f c_s)) at an interior cell. */
static void drift_work(void) {
  bench b;
  if (bench_open(&b, 20, 0.9, 1e4, 0.2, 5.0)) return;
  pipe *p = &b.p;
  pipe_march *m = &p->march;
  const int n = p->n, nf = p->g.nf;
  double *buf[10];
  for (int k = 0; k < 10; ++k) buf[k] = calloc((size_t)(nf > n ? nf : n), sizeof(double));
  double *A = buf[0], *Dt = buf[1], *W = buf[2];
  p->mu_t = buf[3], m->phi_up = buf[4], m->uf_up = buf[5], m->us_up = buf[6], m->ff = buf[7], m->fs = buf[8];
  m->rff = m->rfs = m->rs = buf[9];
  m->on = 1, m->h = 0.04;
  for (int i = 0; i < n; ++i) A[i] = 1e4, Dt[i] = 1e-3, p->mu_t[i] = 1e-3 * p->rho_f;
  /* developed */
  for (int i = 0; i < n; ++i) {
    p->phi[i] = 0.3 - 2.0 * p->g.xc[i];
    m->phi_up[i] = p->phi[i], m->uf_up[i] = p->uf[i], m->us_up[i] = p->us[i];
  }
  pipe_march_fluxes(p);
  pipe_march_drift_work(p, A, Dt, W);
  double wmax = 0.0;
  for (int i = 0; i < n; ++i) wmax = fmax(wmax, fabs(W[i]));
  printf("drift work, the station equal to the last (dphi/dr = -2 /m): max |W| = %.3g W/m3\n", wmax);
  CHECK_MSG(wmax == 0.0, "the developed station's drift work %.3g is not 0", wmax);
  /* the axial part */
  for (int i = 0; i < n; ++i) p->phi[i] = 0.24, m->phi_up[i] = 0.25, p->us[i] = 3.0, p->uf[i] = 3.2;
  for (int i = 0; i < n; ++i) m->uf_up[i] = p->uf[i], m->us_up[i] = p->us[i];
  pipe_march_fluxes(p);
  pipe_march_drift_work(p, A, Dt, W);
  const double wz = 3.2412280701754386;
  double ez = 0.0;
  for (int i = 0; i < n; ++i) ez = fmax(ez, fabs(W[i] / wz - 1.0));
  printf("drift work, phi 0.25 -> 0.24 over 0.04 m: W = %.16g W/m3 (by hand %.16g, worst %.1e)\n", W[n / 2], wz, ez);
  CHECK_MSG(ez < 1e-12, "the axial drift work %.16g against %.16g by hand (%.2e)", W[n / 2], wz, ez);
  /* the radial part */
  for (int i = 0; i < n; ++i) {
    p->phi[i] = 0.3 - 2.0 * p->g.xc[i];
    m->phi_up[i] = p->phi[i];
  }
  for (int f = 1; f < n; ++f) {
    const double pf = 0.5 * (p->phi[f - 1] + p->phi[f]), a = p->g.area[f];
    m->ff[f] = 0.03 * (1.0 - pf) * a, m->fs[f] = 0.02 * pf * a; /* v_f = 0.03, v_s = 0.02 m/s */
  }
  m->ff[0] = m->fs[0] = m->ff[n] = m->fs[n] = 0.0;
  pipe_march_drift_work(p, A, Dt, W);
  const int c = n / 2;
  const double cs = p->phi[c], wr = 1e4 * 0.02 * 1e-3 * (1.0 + 1.0 / ((1.0 - cs) * cs)), er = fabs(W[c] / wr - 1.0);
  printf("drift work, dphi/dr = -2 /m, v_f - v_s = 0.01 m/s: W = %.12g W/m3 at r = %.4g m (by hand %.12g, %.1e)\n",
         W[c], p->g.xc[c], wr, er);
  CHECK_MSG(er < 1e-10, "the radial drift work %.12g against %.12g by hand (%.2e)", W[c], wr, er);
  p->mu_t = NULL;
  for (int k = 0; k < 10; ++k) free(buf[k]);
  memset(m, 0, sizeof *m);
  bench_close(&b);
}

int main(void) {
  bench b;
  drift_work();
  /* 1. homogeneous, e = 1: Tchen's equilibrium */
  if (!bench_open(&b, 20, 1.0, 8.0e4, 0.04, 0.0)) {
    double ch = bench_converge(&b, 400), ks, kfs;
    pipe_ksfs_equilibrium(&b.p, 0, &ks, &kfs);
    double eks = worst_rel(b.p.ks, ks, 20), ekfs = worst_rel(b.p.kfs, kfs, 20);
    printf("homogeneous, e = 1: k_s %.15g (Tchen %.15g, %.1e), k_fs %.15g (%.15g, %.1e); last change %.1e\n", b.p.ks[0],
           ks, eks, b.p.kfs[0], kfs, ekfs, ch);
    CHECK_MSG(eks < 1e-13 && ekfs < 1e-13, "Tchen's equilibrium: k_s off by %.2e, k_fs by %.2e", eks, ekfs);
    bench_close(&b);
  }
  /* 2. homogeneous, e = 0.9: the local balance with the collisional dissipation */
  if (!bench_open(&b, 20, 0.9, 8.0e4, 0.04, 0.0)) {
    double ch = bench_converge(&b, 400), ks, kfs, ks_t, kfs_t;
    local_balance(&b, &ks, &kfs);
    pipe_ksfs_equilibrium(&b.p, 0, &ks_t, &kfs_t);
    double eks = worst_rel(b.p.ks, ks, 20), ekfs = worst_rel(b.p.kfs, kfs, 20);
    printf(
        "homogeneous, e = 0.9: k_s %.12g (local balance %.12g, %.1e; Tchen's %.6g), k_fs %.12g (%.12g, %.1e); "
        "last change %.1e\n",
        b.p.ks[0], ks, eks, ks_t, b.p.kfs[0], kfs, ekfs, ch);
    CHECK_MSG(eks < 1e-10 && ekfs < 1e-10, "the local balance: k_s off by %.2e, k_fs by %.2e", eks, ekfs);
    CHECK_MSG(ks < 0.5 * kfs, "the collisions leave k_s %.6g >= k_fs/2 = %.6g", ks, 0.5 * kfs);
    bench_close(&b);
  }
  /* 3. fine particles in shear: t_p = c_s rho_s/K = 1e-6 t_fs */
  {
    const double tfs = 0.09 * 1.5 * 0.02 / 0.5, K = 0.25 * 2500.0 / (1e-6 * tfs);
    if (!bench_open(&b, 20, 0.9, K, 0.0, 20.0)) {
      bench_converge(&b, 400);
      double eks = worst_rel(b.p.ks, 0.02, 20), ekfs = worst_rel(b.p.kfs, 0.04, 20);
      printf("fine particles (t_p/t_fs = 1e-6), shear 20 1/s: k_s/k - 1 %.1e, k_fs/(2k) - 1 %.1e\n", eks, ekfs);
      CHECK_MSG(eks < 1e-4 && ekfs < 1e-4, "tracers: k_s off k by %.2e, k_fs off 2k by %.2e", eks, ekfs);
      bench_close(&b);
    }
  }

  /* 4. the pipe: vertical_pipe.ini as model C, transported */
  static char text[8192], model_c[8192];
  if (pipe_vertical_without_granular(text, sizeof text, model_c, sizeof model_c)) return sl_test_summary();
  sluice_error err = {0, ""};
  const double rho_f = 997.56, rho_m = 0.25 * 2500.0 + 0.75 * rho_f;
  double G[4] = {0}, Geq = NAN;
  const int cells[4] = {20, 40, 80, 160};
  for (int c = 0; c < 4; ++c) {
    char nc[64];
    snprintf(nc, sizeof nc, "pipe.cells=%d", cells[c]);
    const char *sets[] = {"pipe.solids_viscosity=peirano_leckner",
                          "closure.turbulence_modulation.model=simonin",
                          "closure.turbulent_dispersion.model=simonin",
                          "pipe.solids_turbulence=transported",
                          nc,
                          NULL};
    int rc = pipe_run_text(model_c, "vertical_pipe.ini", sets, "pipe_ksfs.h5", &err);
    CHECK_MSG(rc == 0, "model C transported on %d cells: %s", cells[c], err.msg);
    if (rc) return sl_test_summary();
    G[c] = pipe_scalar("pipe_ksfs.h5", "manometric_gradient");
    double P = pipe_scalar("pipe_ksfs.h5", "pressure_gradient"),
           tf = pipe_scalar("pipe_ksfs.h5", "wall_shear_stress_fluid");
    double ts = pipe_scalar("pipe_ksfs.h5", "wall_shear_stress_solid"), bal = 4.0 * (tf + ts) / 0.0532 + rho_m * 9.81;
    printf(
        "%3d cells: manometric gradient %.4f Pa/m, -dP/dz %.4f against the mixture's momentum %.4f (%.1e), "
        "%.0f iterations\n",
        cells[c], G[c], P, bal, P / bal - 1.0, pipe_scalar("pipe_ksfs.h5", "iterations"));
    CHECK_MSG(fabs(P / bal - 1.0) < 1e-8, "-dP/dz %.9g against 4 tau_w/D + rho_m g %.9g", P, bal);
    if (c == 1) {
      const char *eq[] = {"pipe.solids_viscosity=peirano_leckner", "closure.turbulence_modulation.model=simonin",
                          "closure.turbulent_dispersion.model=simonin", NULL};
      rc = pipe_run_text(model_c, "vertical_pipe.ini", eq, "pipe_ksfs_eq.h5", &err);
      CHECK_MSG(rc == 0, "model C with Tchen's k_s, k_fs: %s", err.msg);
      if (!rc) Geq = pipe_scalar("pipe_ksfs_eq.h5", "manometric_gradient");
    }
  }
  /* the shipped configs/vertical_pipe_model_c.ini is this scene on 40 cells */
  {
    static char shipped[8192];
    const char *none[] = {NULL};
    if (!sl_test_read_source("configs/vertical_pipe_model_c.ini", shipped, sizeof shipped)) {
      int rc = pipe_run_text(shipped, "vertical_pipe_model_c.ini", none, "pipe_ksfs_shipped.h5", &err);
      CHECK_MSG(rc == 0, "configs/vertical_pipe_model_c.ini: %s", err.msg);
      double Gs = rc ? NAN : pipe_scalar("pipe_ksfs_shipped.h5", "manometric_gradient");
      printf("configs/vertical_pipe_model_c.ini: %.6f Pa/m (the built scene %.6f)\n", Gs, G[1]);
      CHECK_MSG(fabs(Gs / G[1] - 1.0) < 1e-12, "the shipped scene %.12g against %.12g", Gs, G[1]);
    }
  }
  double d1 = G[1] - G[0], d2 = G[2] - G[1], d3 = G[3] - G[2];
  double p1 = log2(fabs(d1 / d2)), p2 = log2(fabs(d2 / d3));
  printf("differences %.4g, %.4g, %.4g Pa/m: observed orders %.2f, %.2f; 40 against 160 cells %.2e\n", d1, d2, d3, p1,
         p2, G[1] / G[3] - 1.0);
  CHECK_MSG(p1 > 1.5 && p1 < 2.5 && p2 > 1.5 && p2 < 2.5, "observed orders %.3f, %.3f (second order expected)", p1, p2);
  printf("40 cells: Tchen's equilibrium %.4f Pa/m, transported %.4f (measured 5524, Table C.2)\n", Geq, G[1]);
  CHECK_MSG(Geq < G[1], "the transport (%.6g) did not raise the gradient of Tchen's equilibrium (%.6g)", G[1], Geq);

  /* 5. the developing pipe (pipe_march.c: k_s and k_fs convected by the solids) at its outlet against the fully
     developed pipe at the outlet's in-situ fraction. Model C's core has laminarised (k on the axis 1e-4 of model
     B's), so the flow develops slowly: 4 m (75 D, the thesis's CFX-4 pipe) is printed, 32 m (600 D) asserted */
  const char *base[] = {"pipe.solids_viscosity=peirano_leckner", "closure.turbulence_modulation.model=simonin",
                        "closure.turbulent_dispersion.model=simonin", "pipe.solids_turbulence=transported"};
  const char *lens[2] = {"pipe.length=4", "pipe.length=32"};
  for (int c = 0; c < 2; ++c) {
    const char *dev[] = {base[0], base[1], base[2], base[3], lens[c], "pipe.axial_cells=100", NULL};
    int rc = pipe_run_text(model_c, "vertical_pipe.ini", dev, "pipe_ksfs_dev.h5", &err);
    CHECK_MSG(rc == 0, "model C transported, developing (%s): %s", lens[c], err.msg);
    if (rc) break;
    char phi_set[64];
    snprintf(phi_set, sizeof phi_set, "pipe.solids_fraction=%.17g", pipe_scalar("pipe_ksfs_dev.h5", "phi_mean"));
    const char *fd[] = {base[0], base[1], base[2], base[3], phi_set, NULL};
    rc = pipe_run_text(model_c, "vertical_pipe.ini", fd, "pipe_ksfs_fd.h5", &err);
    CHECK_MSG(rc == 0, "model C transported at the outlet's fraction: %s", err.msg);
    if (rc) break;
    static const char *const q[4] = {"pressure_gradient", "wall_shear_stress_fluid", "velocity_solid_04",
                                     "velocity_solid_08"};
    static const double tol[4] = {2e-4, 2e-3, 1e-3, 1e-3};
    printf("developing, %s (outlet phi_mean %.6f):", lens[c], pipe_scalar("pipe_ksfs_dev.h5", "phi_mean"));
    for (int k = 0; k < 4; ++k) {
      double va = pipe_scalar("pipe_ksfs_dev.h5", q[k]), vb = pipe_scalar("pipe_ksfs_fd.h5", q[k]);
      printf(" %s %.6g against %.6g (%+.2e)", q[k], va, vb, va / vb - 1.0);
      if (c == 1) CHECK_MSG(fabs(va / vb - 1.0) < tol[k], "32 m outlet: %s %.8g against %.8g", q[k], va, vb);
    }
    printf("\n");
  }

  /* 6. Johnson & Jackson's solids wall (Krampa's model C wall): its energy flux into k_s at theta = (2/3) k_s;
     the mixture's momentum with the solids' wall stress */
  {
    static char jj[8192 + 64];
    int len = snprintf(jj, sizeof jj, "%s[closure.wall_stress.solids]\nmodel = johnson_jackson\n", model_c);
    CHECK_MSG(len > 0 && (size_t)len < sizeof jj, "the Johnson-Jackson scene does not fit (%d)", len);
    const char *sets[] = {base[0], base[1], base[2], base[3], "pipe.solids_wall=wall_stress", NULL};
    int rc = pipe_run_text(jj, "vertical_pipe.ini", sets, "pipe_ksfs_jj.h5", &err);
    CHECK_MSG(rc == 0, "model C transported, Johnson-Jackson walls: %s", err.msg);
    if (!rc) {
      double P = pipe_scalar("pipe_ksfs_jj.h5", "pressure_gradient");
      double tf = pipe_scalar("pipe_ksfs_jj.h5", "wall_shear_stress_fluid");
      double ts = pipe_scalar("pipe_ksfs_jj.h5", "wall_shear_stress_solid"),
             bal = 4.0 * (tf + ts) / 0.0532 + rho_m * 9.81;
      printf(
          "Johnson-Jackson walls: manometric %.2f Pa/m (measured 5524), tau_fw %.3f, tau_sw %.3f Pa; -dP/dz against "
          "the mixture's momentum %.1e\n",
          pipe_scalar("pipe_ksfs_jj.h5", "manometric_gradient"), tf, ts, P / bal - 1.0);
      CHECK_MSG(fabs(P / bal - 1.0) < 1e-8, "-dP/dz %.9g against %.9g", P, bal);
      CHECK_MSG(ts > 0.0, "tau_sw %.6g: the wall holds no solids", ts);
    }
  }

  /* 7. bad input, refused before any output */
  remove("pipe_ksfs_bad.h5");
  const char *bad1[] = {"pipe.solids_turbulence=transported", NULL};
  int rc = pipe_run_text(model_c, "vertical_pipe.ini", bad1, "pipe_ksfs_bad.h5", &err);
  printf("transported without peirano_leckner: %d, %s\n", rc, err.msg);
  CHECK_MSG(rc == 2 && strstr(err.msg, "did you mean") && strstr(err.msg, "peirano_leckner"), "rc %d: %s", rc, err.msg);
  const char *bad2[] = {"pipe.solids_viscosity=peirano_leckner", "pipe.solids_turbulence=transport", NULL};
  rc = pipe_run_text(model_c, "vertical_pipe.ini", bad2, "pipe_ksfs_bad.h5", &err);
  printf("solids_turbulence = transport: %d, %s\n", rc, err.msg);
  CHECK_MSG(rc == 2 && strstr(err.msg, "transported"), "rc %d: %s", rc, err.msg);
  FILE *f = fopen("pipe_ksfs_bad.h5", "rb");
  CHECK_MSG(f == NULL, "a refused scene wrote its output");
  if (f) fclose(f);
  return sl_test_summary();
}
