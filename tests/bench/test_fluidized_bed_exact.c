/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The equilibrium porosity of a liquid-fluidised bed (exact = fluidized_bed
 * of sluice bench):
 *  - core/study/fluidized_bed_exact.h with Richardson & Zaki's drag, whose
 *    balance K s = phi (1 - phi) (rho_s - rho_f) g, s = U / (1 - phi), has
 *    the closed form porosity = (U / u_t)^(1/n) (Richardson & Zaki 1954);
 *    below the minimum fluidisation velocity and above u_t there is no bed;
 *  - the exact solution of a study of configs/fluidized_bed.ini, set up from
 *    each run's scene as sluice bench builds it, its drag closure
 *    (richardson_zaki_consistent, u_t from Stokes' law) evaluated through
 *    the plugin: the same closed form with u_t =
 *    (rho_s - rho_f) g d^2 / (18 mu) = 78.4 mm/s for the scene's sand and
 *    water, at three U; Wen-Yu's and Di Felice's porosities at U = 10 mm/s
 *    as the two-fluid scene tests find them from the published laws (docs/verification.md,
 *    two-fluid scenes: 0.6815 and 0.6758);
 *  - the part compared: the cells below the top of the bed at rest that holds
 *    the run's inventory;
 *  - scenes the solution does not cover are refused with the reason. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/study/exact.h"
#include "core/study/fluidized_bed_exact.h"
#include "core/study/study.h"
#include "testing.h"

static char configs[4096];

/* ---- the header, with Richardson-Zaki's drag in closed form ---- */

typedef struct rz_drag {
  double u_t, n, weight_per_phi; /* weight_per_phi = (rho_s - rho_f) g */
} rz_drag;

/* K = (rho_s - rho_f) g phi / (u_t (1 - phi)^(n - 2)): the drag for which a bed at rest obeys U = u_t (1 - phi)^n. */
static int rz_K(void *user, double phi, double slip, double *K) {
  (void)slip;
  const rz_drag *r = user;
  *K = r->weight_per_phi * phi / (r->u_t * pow(1.0 - phi, r->n - 2.0));
  return 0;
}

static int refusing_K(void *user, double phi, double slip, double *K) {
  (void)user, (void)phi, (void)slip;
  *K = NAN;
  return 1;
}

static void header_closed_form(void) {
  const double drho_g = (2600.0 - 998.2) * 9.81;
  rz_drag r = {.u_t = 0.0784, .n = 4.65, .weight_per_phi = drho_g};
  fb_bed bed = {.rho_f = 998.2, .rho_s = 2600.0, .g = 9.81, .phi_max = 0.64};
  const double Us[] = {0.001, 0.006, 0.010, 0.014, 0.05, 0.078};
  for (size_t k = 0; k < sizeof Us / sizeof Us[0]; ++k) {
    bed.U = Us[k];
    double e = NAN;
    fb_status st = fb_equilibrium_porosity(&bed, rz_K, &r, &e);
    double closed = pow(Us[k] / r.u_t, 1.0 / r.n);
    CHECK_MSG(st == FB_OK && fabs(e - closed) <= 1e-13, "U = %g: porosity %.15f, (U/u_t)^(1/n) = %.15f (status %d)",
              Us[k], e, closed, (int)st);
  }
  /* minimum fluidisation: U_mf = u_t (1 - phi_max)^n = 0.67 mm/s; terminal velocity u_t */
  bed.U = 0.5 * r.u_t * pow(1.0 - bed.phi_max, r.n);
  double e = 0.0;
  CHECK(fb_equilibrium_porosity(&bed, rz_K, &r, &e) == FB_PACKED && isnan(e));
  bed.U = 1.01 * r.u_t;
  CHECK(fb_equilibrium_porosity(&bed, rz_K, &r, &e) == FB_BLOWN_OUT && isnan(e));
  bed.U = 0.01;
  CHECK(fb_equilibrium_porosity(&bed, refusing_K, NULL, &e) == FB_DRAG_FAILED && isnan(e));
}

/* ---- the study's exact solution, from the scene and its plugin ---- */

/* A study of configs/SCENE.ini measured against exact = fluidized_bed, with
 * the sections `sweep` (variants): each variant's run scene as sluice bench
 * builds it, and its exact solution. */
typedef struct bed_study {
  sl_study *study;
  char msg[2048];
} bed_study;

static int bed_study_load(bed_study *b, const char *scene, const char *sweep) {
  char text[8192];
  snprintf(text, sizeof text, "[study]\nscene = %s/%s.ini\n%s[measure]\nexact = fluidized_bed\n", configs, scene,
           sweep);
  FILE *f = fopen("fluidized_bed_exact.ini", "w");
  CHECK(f != NULL);
  if (!f) return -1;
  fputs(text, f);
  fclose(f);
  sl_diag d = {{0}};
  b->study = NULL;
  int rc = sl_study_load("fluidized_bed_exact.ini", &b->study, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  return rc;
}

/* Variant v's porosity, or the refusal's status with the message in b->msg. */
static int bed_porosity(bed_study *b, const sl_registry *reg, int v, double *porosity, double span[2]) {
  sl_diag d = {{0}};
  sl_ini *ini = NULL;
  sl_bench_exact *e = NULL;
  int rc = sl_study_run_ini(b->study, v, 0, &ini, &d);
  if (!rc) rc = sl_bench_exact_create("fluidized_bed", ini, reg, &e, &d);
  *porosity = NAN;
  b->msg[0] = '\0';
  if (rc) snprintf(b->msg, sizeof b->msg, "%s", d.msg);
  else {
    double x = 0.1, phi = NAN;
    sl_bench_exact_values(e, 0.0, 1, &x, &phi);
    *porosity = 1.0 - phi;
    if (span) { /* 10 cells of 0.1 m holding 0.012 m of solids: the bed's top at 0.012 / phi */
      double xa[10], xb[10], held[10];
      for (int c = 0; c < 10; ++c) xa[c] = 0.1 * c, xb[c] = 0.1 * (c + 1), held[c] = c < 3 ? 0.04 : 0.0;
      sl_bench_exact_compared_span(e, 10, xa, xb, held, &span[0], &span[1]);
    }
  }
  sl_bench_exact_free(e);
  sl_ini_free(ini);
  return rc;
}

static void scene_closed_form(const sl_registry *reg) {
  /* the scene: sand 2600 kg/m3, 0.3 mm, in water 998.2 kg/m3, 1.002e-3 Pa s; Richardson-Zaki n = 4.65 */
  const double u_t = (2600.0 - 998.2) * 9.81 * 3e-4 * 3e-4 / (18.0 * 1.002e-3);
  CHECK_MSG(fabs(u_t - 0.0784) < 1e-4, "Stokes u_t = %.6f m/s", u_t);
  bed_study b;
  if (bed_study_load(&b, "fluidized_bed", "[variants.boundary.left]\nvelocity = 0.006, 0.010, 0.014\n")) return;
  const double Us[] = {0.006, 0.010, 0.014};
  for (int k = 0; k < 3; ++k) {
    double e, span[2];
    int rc = bed_porosity(&b, reg, k, &e, span);
    double closed = pow(Us[k] / u_t, 1.0 / 4.65);
    printf("fluidized_bed, richardson_zaki_consistent, U = %g m/s: porosity %.12f, (U/u_t)^(1/4.65) = %.12f\n", Us[k],
           e, closed);
    CHECK_MSG(rc == 0, "%s", b.msg);
    CHECK_MSG(fabs(e - closed) <= 1e-12, "porosity %.15f, closed form %.15f", e, closed);
    CHECK_MSG(span[0] == 0.0 && fabs(span[1] - 0.012 / (1.0 - closed)) < 1e-12, "compared %g to %g, the top at %g",
              span[0], span[1], 0.012 / (1.0 - closed));
  }
  sl_study_free(b.study);
  /* other drag laws: their own equilibria (tests/scenes/test_two_fluid_scenes.c, from the published laws) */
  if (bed_study_load(&b, "fluidized_bed", "[variants.closure.drag]\nmodel = wen_yu, di_felice\n")) return;
  const char *labels[] = {"wen_yu", "di_felice"};
  const double published[] = {0.6815, 0.6758};
  for (int k = 0; k < 2; ++k) {
    double e;
    int rc = bed_porosity(&b, reg, k, &e, NULL);
    printf("fluidized_bed, %s, U = 0.01 m/s: porosity %.6f (published law: %.4f)\n", labels[k], e, published[k]);
    CHECK_MSG(rc == 0, "%s: %s", labels[k], b.msg);
    CHECK_MSG(fabs(e - published[k]) < 6e-5, "%s: porosity %.6f", labels[k], e);
  }
  sl_study_free(b.study);
}

static void refusals(const sl_registry *reg) {
  bed_study b;
  double e;
  if (bed_study_load(&b, "fluidized_bed", "[variants.boundary.left]\nvelocity = 0.1 | 0.0005 | 0.01 + 0.001 * t\n"))
    return;
  static const char *const why[] = {"above the terminal velocity", "below the minimum fluidisation velocity",
                                    "needs a constant inflow"};
  for (int k = 0; k < 3; ++k) {
    CHECK(bed_porosity(&b, reg, k, &e, NULL) == SL_EBADINPUT);
    CHECK_CONTAINS(b.msg, why[k]);
  }
  sl_study_free(b.study);
  if (bed_study_load(&b, "kynch_settling", "")) return;
  CHECK(bed_porosity(&b, reg, 0, &e, NULL) == SL_EBADINPUT);
  CHECK_CONTAINS(b.msg, "needs a two-fluid scene");
  sl_study_free(b.study);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  if (!src) {
    fprintf(stderr, "set SLUICE_SOURCE_DIR\n");
    return 1;
  }
  snprintf(configs, sizeof configs, "%s/configs", src);
  header_closed_form();
  sl_registry *reg = NULL;
  sl_diag d = {{0}};
  int rc = sl_registry_create(&reg, NULL, 0, &d);
  if (!rc) rc = sl_registry_scan(reg, &d);
  CHECK_MSG(rc == 0, "plugin registry: %s", d.msg);
  if (!rc) {
    scene_closed_form(reg);
    refusals(reg);
  }
  sl_registry_destroy(reg);
  return sl_test_summary();
}
