/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids' k_s-eps_s of Krampa's (2009) models A and B (core/models/pipe/pipe_kseps_solid.c, `[pipe]
 * solids_turbulence = k_epsilon`):
 *  1. the single-phase limit: particles of the fluid's density with the solids' laminar viscosity c_s mu_f (the
 *     fluid's c_f mu_f per unit fraction), no-slip solids, no solids pressure: the solids' momentum, k_s and eps_s
 *     equations are the fluid's times c_s/c_f with the same wall values, so k_s = k and eps_s = eps but for the
 *     slip the drag leaves. With Gidaspow's (Wen-Yu) drag at small Re_p, K = 18 mu c_s c_f^-1.65/d_p^2 (Stokes),
 *     the slip a wall mismatch leaves falls as d_p^2, and k_s - k with it: asserted, the largest |k_s - k|/max k and
 *     |eps_s - eps|/eps below 1e-4 at d_p = 3 um, and falling by at least 8 (d_p^2: 11.1) from d_p = 10 um to 3 um;
 *  2. positivity: k_s > 0 and eps_s > 0 in every cell of models A and B (configs/vertical_pipe_model_a.ini, _b.ini);
 *  3. the mixture's momentum, -dP/dz = 4 (tau_fw + tau_sw)/D + rho_m g, to 1e-8 (the section's balance: the
 *     solids' eddy viscosity moves stress between the phases, never out of the mixture), models A and B;
 *  4. the mesh: k_s at r/R = 0.5 (model A, 25 %, the wall cell held at y+ = 40) on 20, 40, 80 and 160 radial cells:
 *     the differences' observed orders between 1.5 and 2.5 (the cell-scalar solver is second order);
 *  5. Table C.1's row at 3.05 m/s (5 %, 22.8 C, up-flow, measured 2.327 kPa/m): models A and B converge; model A's
 *     gradient within the 10 % (the thesis's own finding: at 5 % the models follow the data); model B's
 *     printed (Johnson & Jackson's wall heats theta: docs/pipe.md);
 *  6. the key's refusals: a bad value lists the allowed ones; k_epsilon with solids_viscosity = peirano_leckner,
 *     without solids, or in the developing pipe is refused (status 2) before any output. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pipe_testing.h"

static double worst_diff(const profile *a, const profile *b, int relative) {
  double w = 0.0, m = 0.0;
  for (int i = 0; i < a->n; ++i) m = fmax(m, fabs(b->v[i]));
  for (int i = 0; i < a->n; ++i) w = fmax(w, fabs(a->v[i] - b->v[i]) / (relative ? fabs(b->v[i]) : m));
  return w;
}

/* the value of a profile at r (linear between the cell centres) */
static double at_r(const profile *p, double r) {
  for (int i = 0; i + 1 < p->n; ++i)
    if (r <= p->r[i + 1]) return p->v[i] + (p->v[i + 1] - p->v[i]) * (r - p->r[i]) / (p->r[i + 1] - p->r[i]);
  return p->v[p->n - 1];
}

static int run(const char *text, const char *name, const char *const *sets, const char *out) {
  sluice_error e = {0, ""};
  int rc = pipe_run_text(text, name, sets, out, &e);
  CHECK_MSG(rc == 0, "%s: %s", name, e.msg);
  return rc;
}

static void momentum(const char *out, double rho_s, double c, const char *label) {
  const double D = 0.0532, rho_f = 997.56; /* the scenes' water at 22.9 C */
  double P = pipe_scalar(out, "pressure_gradient"), tf = pipe_scalar(out, "wall_shear_stress_fluid"),
         ts = pipe_scalar(out, "wall_shear_stress_solid");
  double bal = 4.0 * (tf + ts) / D + (c * rho_s + (1.0 - c) * rho_f) * 9.81;
  printf("%s: -dP/dz %.6f Pa/m against the mixture's momentum %.6f (%.1e)\n", label, P, bal, P / bal - 1.0);
  CHECK_MSG(fabs(P / bal - 1.0) < 1e-8, "%s: -dP/dz %.9g against 4 tau_w/D + rho_m g %.9g", label, P, bal);
}

int main(void) {
  static char model_a[8192], model_b[8192], limit[8192];
  if (sl_test_read_source("configs/vertical_pipe_model_a.ini", model_a, sizeof model_a) ||
      sl_test_read_source("configs/vertical_pipe_model_b.ini", model_b, sizeof model_b))
    return sl_test_summary();

  /* 1. the single-phase limit: model A's scene without the solids pressure, no-slip solids, rho_s = rho_f */
  {
    char *ps = strstr(model_a, "\n# Bouillard"), *fs = strstr(model_a, "solids_wall = free_slip");
    CHECK_MSG(ps && fs, "vertical_pipe_model_a.ini has no Bouillard pressure or solids_wall = free_slip");
    if (!ps || !fs) return sl_test_summary();
    snprintf(limit, sizeof limit, "%.*ssolids_wall = no_slip%.*s\n", (int)(fs - model_a), model_a,
             (int)(ps - fs - strlen("solids_wall = free_slip")), fs + strlen("solids_wall = free_slip"));
    const double dps[2] = {1e-5, 3e-6};
    double wk[2] = {NAN, NAN}, we[2] = {NAN, NAN};
    for (int j = 0; j < 2; ++j) {
      char dp[64];
      snprintf(dp, sizeof dp, "solid.diameter=%g", dps[j]);
      const char *sets[] = {"solid.density=997.56", dp, "pipe.solids_fraction=0.01", "solid.viscosity=9.347e-6",
                            "pipe.tolerance=1e-11", "pipe.iterations=20000", NULL};
      if (run(limit, "the single-phase limit", sets, "pipe_kseps_limit.h5")) return sl_test_summary();
      profile k, ks, e, es;
      if (read_profile("pipe_kseps_limit.h5", "k", &k) || read_profile("pipe_kseps_limit.h5", "k_s", &ks) ||
          read_profile("pipe_kseps_limit.h5", "epsilon", &e) || read_profile("pipe_kseps_limit.h5", "epsilon_s", &es))
        return sl_test_summary();
      wk[j] = worst_diff(&ks, &k, 0), we[j] = worst_diff(&es, &e, 1);
      printf("d_p = %g m, rho_s = rho_f, c_s = 0.01: max |k_s - k|/max k %.3e, max |eps_s - eps|/eps %.3e\n", dps[j],
             wk[j], we[j]);
    }
    CHECK_MSG(wk[1] < 1e-4 && we[1] < 1e-4, "the single-phase limit: k_s off k by %.2e, eps_s off eps by %.2e", wk[1],
              we[1]);
    CHECK_MSG(wk[0] / wk[1] > 8.0 && we[0] / we[1] > 8.0, "k_s - k fell by %.2f, eps_s - eps by %.2f (d_p^2: 11.1)",
              wk[0] / wk[1], we[0] / we[1]);
  }

  /* 2, 3. positivity and the mixture's momentum, models A and B */
  {
    const char *none[] = {NULL};
    const char *texts[2] = {model_a, model_b}, *names[2] = {"model A", "model B"};
    for (int m = 0; m < 2; ++m) {
      if (run(texts[m], names[m], none, "pipe_kseps_ab.h5")) continue;
      profile ks, es;
      if (read_profile("pipe_kseps_ab.h5", "k_s", &ks) || read_profile("pipe_kseps_ab.h5", "epsilon_s", &es)) continue;
      double lo_k = INFINITY, lo_e = INFINITY;
      for (int i = 0; i < ks.n; ++i) lo_k = fmin(lo_k, ks.v[i]), lo_e = fmin(lo_e, es.v[i]);
      printf("%s (25 %%, 3.02 m/s): k_s %.4g-%.4g m2/s2 (axis %.4g), eps_s from %.4g, %.0f iterations\n", names[m], lo_k,
             ks.v[ks.n - 1], ks.v[0], lo_e, pipe_scalar("pipe_kseps_ab.h5", "iterations"));
      CHECK_MSG(lo_k > 0.0 && lo_e > 0.0, "%s: k_s %.3g, eps_s %.3g", names[m], lo_k, lo_e);
      momentum("pipe_kseps_ab.h5", 2500.0, 0.25, names[m]);
    }
  }

  /* 4. the mesh: k_s at r/R = 0.5, model A */
  {
    const int cells[4] = {20, 40, 80, 160};
    double q[4] = {NAN, NAN, NAN, NAN};
    for (int c = 0; c < 4; ++c) {
      char nc[64];
      snprintf(nc, sizeof nc, "pipe.cells=%d", cells[c]);
      const char *sets[] = {nc, "pipe.tolerance=1e-11", "pipe.iterations=20000", NULL};
      if (run(model_a, "model A", sets, "pipe_kseps_mesh.h5")) return sl_test_summary();
      profile ks;
      if (read_profile("pipe_kseps_mesh.h5", "k_s", &ks)) return sl_test_summary();
      q[c] = at_r(&ks, 0.5 * 0.0266);
      printf("%3d cells: k_s(r/R = 0.5) = %.8f m2/s2\n", cells[c], q[c]);
    }
    double d1 = q[1] - q[0], d2 = q[2] - q[1], d3 = q[3] - q[2];
    double p1 = log2(fabs(d1 / d2)), p2 = log2(fabs(d2 / d3));
    printf("differences %.3e, %.3e, %.3e: observed orders %.2f, %.2f\n", d1, d2, d3, p1, p2);
    CHECK_MSG(p1 > 1.5 && p1 < 2.5 && p2 > 1.5 && p2 < 2.5, "observed orders %.3f, %.3f (second order expected)", p1,
              p2);
  }

  /* 5. Table C.1's row at 3.05 m/s, up-flow: 2.327 kPa/m measured */
  {
    const char *sets[] = {"pipe.solids_fraction=0.05", "pipe.bulk_velocity=3.05", "fluid.density=997.59",
                          "fluid.viscosity=0.00093693", NULL};
    const char *texts[2] = {model_a, model_b}, *names[2] = {"model A", "model B"};
    for (int m = 0; m < 2; ++m) {
      if (run(texts[m], names[m], sets, "pipe_kseps_c1.h5")) continue;
      double G = 1e-3 * pipe_scalar("pipe_kseps_c1.h5", "manometric_gradient");
      printf("%s, Table C.1, 3.05 m/s up-flow: %.4f kPa/m against 2.327 measured (%+.1f %%), %.0f iterations\n",
             names[m], G, 100.0 * (G / 2.327 - 1.0), pipe_scalar("pipe_kseps_c1.h5", "iterations"));
      if (m == 0) CHECK_MSG(fabs(G / 2.327 - 1.0) < 0.10, "model A, C.1 at 3.05 m/s: %.4f kPa/m", G);
    }
  }

  /* 6. refusals, before any output */
  {
    sluice_error e = {0, ""};
    remove("pipe_kseps_bad.h5");
    const char *bad[] = {"pipe.solids_turbulence=k_eps", NULL};
    int rc = pipe_run_text(model_a, "model A", bad, "pipe_kseps_bad.h5", &e);
    CHECK_MSG(rc == 2 && strstr(e.msg, "equilibrium, transported, k_epsilon"), "a bad value: %d %s", rc,
              e.msg);
    const char *pl[] = {"pipe.solids_viscosity=peirano_leckner", NULL};
    rc = pipe_run_text(model_a, "model A", pl, "pipe_kseps_bad.h5", &e);
    CHECK_MSG(rc == 2 && strstr(e.msg, "solids_viscosity = eddy"), "with peirano_leckner: %d %s", rc, e.msg);
    const char *water[] = {"pipe.solids_fraction=0", NULL};
    rc = pipe_run_text(model_a, "model A", water, "pipe_kseps_bad.h5", &e);
    CHECK_MSG(rc == 2 && strstr(e.msg, "solids_fraction > 0"), "without solids: %d %s", rc, e.msg);
    const char *dev[] = {"pipe.length=4", NULL};
    rc = pipe_run_text(model_a, "model A", dev, "pipe_kseps_bad.h5", &e);
    CHECK_MSG(rc == 2 && strstr(e.msg, "length"), "the developing pipe: %d %s", rc, e.msg);
    FILE *f = fopen("pipe_kseps_bad.h5", "rb");
    CHECK_MSG(f == NULL, "a refused scene wrote its output");
    if (f) fclose(f);
  }
  return sl_test_summary();
}
