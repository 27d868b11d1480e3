/* The mixture scenes of configs/, run through the same entry point as
 * `sluice run` and read back from their output files.
 *
 * kynch_settling (1-D batch settling) against the exact Kynch entropy
 * solution (tests/transport/kynch_exact.h: shocks, the contact shock and
 * fan of non-convex fluxes, the meeting of the fronts):
 *  - Richardson-Zaki with its packing cut-off at phi0 = 0.05, 0.1, 0.2: the
 *    top interface (the written interface height) and the bottom shock fall
 *    and rise at the exact speeds within 1 % on 200 cells;
 *  - Nigam's flux (seed 002, digest 4.6), where the sediment forms through a
 *    contact shock and a rarefaction fan: the shock speed within 1 %, and
 *    the fan's profile below it;
 *  - the L1 error of phi falls at first order with refinement (50 to 400
 *    cells; the rate expected with shocks), for both schemes;
 *  - the solids inventory is conserved to round-off at every output and phi
 *    never exceeds phi_max;
 *  - bad input: phi0 above phi_max is refused with the key and the range. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/scene_schema.h"
#include "core/io/output.h"
#include "core/models/mixture.h"
#include "core/plugin/closure_ini.h"
#include "testing.h"
#include "transport/kynch_exact.h"

static char configs[4096];

/* Runs configs/<scene>.ini, its section [replace_section] replaced by the
 * text `replacement` when both are given, with the overrides `sets`. */
static int run_scene(const char *scene, const char *replace_section, const char *replacement, const char *const *sets,
                     const char *out, sl_diag *d) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s.ini", configs, scene);
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  int rc;
  if (replace_section) {
    FILE *f = fopen(path, "rb");
    static char text[1 << 16], edited[1 << 16];
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f) fclose(f);
    text[n] = '\0';
    char head[128];
    snprintf(head, sizeof head, "[%s]", replace_section);
    char *a = strstr(text, head), *b = a ? strstr(a + 1, "\n[") : NULL;
    if (!a) return sl_diag_set(d, SL_EBADINPUT, "%s: no section %s", path, head);
    snprintf(edited, sizeof edited, "%.*s%s%s", (int)(a - text), text, replacement, b ? b : "");
    rc = sl_ini_parse_string(edited, strlen(edited), path, &ini, d);
  } else {
    rc = sl_ini_parse_file(path, &ini, d);
  }
  for (int i = 0; sets && sets[i] && !rc; ++i) rc = sl_ini_apply_override(ini, sets[i], d);
  if (!rc) rc = sl_scene_validate(ini, d);
  if (!rc) rc = sl_registry_create(&reg, NULL, 0, d);
  if (!rc) rc = sl_registry_scan(reg, d);
  sl_ns_result r;
  sl_ns_run_opts o = {.scene_path = path, .output = out, .sluice_version = "test"};
  if (!rc) rc = sl_mixture_run(ini, reg, &o, &r, d);
  sl_registry_destroy(reg);
  sl_ini_free(ini);
  return rc;
}

static int run_ok(const char *scene, const char *section, const char *replacement, const char *const *sets,
                  const char *out) {
  sl_diag d = {{0}};
  int rc = run_scene(scene, section, replacement, sets, out, &d);
  CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);
  return rc;
}

static double scalar(const char *file, const char *name, double t) {
  sl_diag d = {{0}};
  double v = NAN, tf;
  int rc = sl_output_read_scalar(file, name, t, &v, &tf, &d);
  CHECK_MSG(rc == 0 && fabs(tf - t) < 1e-9, "%s: %s at t = %g: %s", file, name, t, d.msg);
  return v;
}

/* phi at output time t (cells of the uniform column). */
static int phi_at(const char *file, double t, int n, double *phi) {
  sl_output_field f;
  sl_diag d = {{0}};
  int rc = sl_output_read_field(file, "phi", t, &f, &d);
  CHECK_MSG(rc == 0 && f.n == n && fabs(f.time - t) < 1e-9, "%s: phi at t = %g: %s", file, t, d.msg);
  if (rc) return rc;
  memcpy(phi, f.values, (size_t)n * sizeof *phi);
  sl_output_field_free(&f);
  return 0;
}

/* The scene's column: 0.5 m, 0.1 mm quartz in water, Stokes u_t. */
static const double H = 0.5, phi_max = 0.64;
static double stokes_ut(void) { return (2650.0 - 1000.0) * 9.81 * 1e-8 / (18.0 * 1e-3); }

/* Speed of the level crossing `level` searched from the top (dir = -1) or
 * from the bottom (dir = +1), by a least-squares line through the output
 * times in [ta, tb]. */
static double crossing(const double *phi, int n, double level, int from_bottom) {
  double h = H / n;
  if (from_bottom) {
    for (int i = 0; i + 1 < n; ++i)
      if (phi[i] >= level && phi[i + 1] < level) return (i + 0.5 + (phi[i] - level) / (phi[i] - phi[i + 1])) * h;
  } else {
    for (int i = n - 1; i > 0; --i)
      if (phi[i] < level && phi[i - 1] >= level) return (i - 0.5 + (phi[i - 1] - level) / (phi[i - 1] - phi[i])) * h;
  }
  return NAN;
}

static double slope(const double *t, const double *z, int m) {
  double st = 0, sz = 0, stt = 0, szt = 0;
  for (int i = 0; i < m; ++i) st += t[i], sz += z[i], stt += t[i] * t[i], szt += t[i] * z[i];
  return (m * szt - st * sz) / (m * stt - st * st);
}

/* Runs the column and checks fronts, bounds and conservation; returns the L1
 * error at t = 0.6 t1 through *l1 when asked. */
static void column(const char *label, const kynch *k, const char *closure, const char *const *sets, const char *out,
                   int n, int check_fronts, double *l1) {
  if (run_ok("kynch_settling", closure ? "closure.hindered_settling" : NULL, closure, sets, out)) return;
  enum { NT = 8 };
  double every = k->t1 / 10, tt[NT], ztop[NT], zbot[NT], zint[NT];
  double *phi = malloc((size_t)n * sizeof *phi);
  double worst_mass = 0.0, worst_phi = 0.0;
  for (int j = 0; j < NT; ++j) {
    double t = (j + 2) * every; /* 0.2 .. 0.9 t1: both fronts formed, not yet met */
    if (phi_at(out, t, n, phi)) break;
    tt[j] = t;
    ztop[j] = crossing(phi, n, 0.5 * k->phi0, 0);
    zbot[j] = crossing(phi, n, 0.5 * (k->phi0 + k->phis), 1);
    zint[j] = scalar(out, "interface_height_0", t);
    worst_mass = fmax(worst_mass, fabs(scalar(out, "solids_conservation_error", t)));
    for (int i = 0; i < n; ++i) worst_phi = fmax(worst_phi, phi[i]);
  }
  if (check_fronts) {
    double e_top = -slope(tt, ztop, NT) / k->v0 - 1, e_int = -slope(tt, zint, NT) / k->v0 - 1;
    double e_bot = slope(tt, zbot, NT) / k->sigma - 1;
    printf("  %s: top %.3f%%, written interface %.3f%%, bottom %.3f%% (exact v0 %.5g, sigma %.5g m/s)\n", label,
           100 * e_top, 100 * e_int, 100 * e_bot, k->v0, k->sigma);
    CHECK_MSG(fabs(e_top) < 0.01, "%s: top interface speed off by %.3g", label, e_top);
    CHECK_MSG(fabs(e_int) < 0.01, "%s: written interface height speed off by %.3g", label, e_int);
    CHECK_MSG(fabs(e_bot) < 0.01, "%s: bottom shock speed off by %.3g", label, e_bot);
  }
  CHECK_MSG(worst_mass < 1e-13, "%s: solids conservation error %.3g", label, worst_mass);
  CHECK_MSG(worst_phi <= k->law.c, "%s: phi reached %.17g > phi_max = %g", label, worst_phi, k->law.c);
  if (l1) {
    double t = 6 * every, h = H / n, e = 0.0;
    kx_profile p = kx_at(k, t);
    if (phi_at(out, t, n, phi) == 0)
      for (int i = 0; i < n; ++i) e += fabs(phi[i] * h - kx_integral(k, &p, i * h, (i + 1) * h));
    *l1 = e;
  }
  free(phi);
}

static void set_every(char *buf, size_t n, double every) { snprintf(buf, n, "output.every=%.17g", every); }

static void richardson_zaki(void) {
  const double phis[3] = {0.05, 0.1, 0.2};
  for (int j = 0; j < 3; ++j) {
    kynch k;
    CHECK(kx_init(&k, kx_richardson_zaki(stokes_ut(), 4.65, phi_max), H, phis[j]) == 0);
    char init[64], every[64], end[64], level[64], label[64];
    snprintf(init, sizeof init, "initial.phi=%.17g", phis[j]);
    set_every(every, sizeof every, k.t1 / 10);
    snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
    snprintf(level, sizeof level, "output.interface=%.17g", 0.5 * phis[j]);
    snprintf(label, sizeof label, "Richardson-Zaki phi0 = %.2f", phis[j]);
    const char *sets[] = {init, every, end, level, NULL};
    column(label, &k, NULL, sets, "kynch_rz.h5", 200, 1, NULL);
  }
}

static void nigam_fan(void) {
  kynch k;
  CHECK(kx_init(&k, kx_nigam(stokes_ut(), 2.5, 0.68), H, 0.1) == 0);
  /* digest of seed 002, section 4.6: phi* = 0.5299, shock 0.12289 u_t, fronts meet at 1.3496 H / u_t */
  CHECK_MSG(fabs(k.phis - 0.5299) < 1e-4, "phi* %.6f", k.phis);
  CHECK_MSG(fabs(k.sigma / stokes_ut() - 0.12289) < 1e-5, "shock speed %.6f u_t", k.sigma / stokes_ut());
  CHECK_MSG(fabs(k.t1 * stokes_ut() / H - 1.3496) < 1e-4, "meeting time %.6f H/u_t", k.t1 * stokes_ut() / H);
  CHECK(k.bottom == KX_CONTACT);
  char every[64], end[64];
  set_every(every, sizeof every, k.t1 / 10);
  snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
  const char *sets[] = {every, end, "solid.phi_max=0.68", NULL};
  static const char nigam[] = "[closure.hindered_settling]\nmodel = nigam\nphi_max = 0.68\n";
  enum { N = 200 };
  column("Nigam flux phi0 = 0.10", &k, nigam, sets, "kynch_nigam.h5", N, 1, NULL);
  /* the fan between the sediment (phi_max at the floor only) and the contact shock */
  double t = 0.6 * k.t1, phi[N], h = H / N, worst = 0.0;
  kx_profile p = kx_at(&k, t);
  if (phi_at("kynch_nigam.h5", t, N, phi)) return;
  for (int i = 0; i < N; ++i) {
    double z = (i + 0.5) * h;
    if (z < 0.2 * k.sigma * t || z > 0.8 * k.sigma * t) continue; /* inside the fan, away from its ends */
    worst = fmax(worst, fabs(phi[i] - kx_integral(&k, &p, i * h, (i + 1) * h) / h));
  }
  printf("  Nigam fan at t = %.4g s: max |phi - exact| = %.3g over its middle 60 %%\n", t, worst);
  CHECK_MSG(worst < 0.02, "fan profile off by %.3g", worst);
}

/* L1 error at 0.6 t1 on 50 .. 400 cells, first and second order. The
 * bottom of a Richardson-Zaki column with its cut-off is a contact shock
 * (tangent to F on its upper side) above a fan: a front that characteristics
 * run along is smeared like a linear discontinuity, over O(h^(p/(p+1)))
 * for a scheme of order p (Harten 1977, Comm. Pure Appl. Math. 30:611), so
 * the L1 rate lies between 1/2 (order 1) or 2/3 (order 2) and the 1 of the
 * compressive top shock. */
static void refinement(void) {
  kynch k;
  CHECK(kx_init(&k, kx_richardson_zaki(stokes_ut(), 4.65, phi_max), H, 0.1) == 0);
  CHECK(k.bottom == KX_CONTACT);
  double e[2][4], rate[2];
  for (int order = 1; order <= 2; ++order) {
    for (int j = 0; j < 4; ++j) {
      int n = 50 << j;
      char cells[64], ord[64], every[64], end[64];
      snprintf(cells, sizeof cells, "mesh.cells=%d", n);
      snprintf(ord, sizeof ord, "transport.order=%d", order);
      set_every(every, sizeof every, k.t1 / 10);
      snprintf(end, sizeof end, "time.end=%.17g", k.t1 * 0.95);
      const char *sets[] = {cells, ord, every, end, NULL};
      column("refinement", &k, NULL, sets, "kynch_l1.h5", n, 0, &e[order - 1][j]);
    }
    double *x = e[order - 1];
    rate[order - 1] = log(x[0] / x[3]) / log(8.0);
    printf("  order %d: L1 errors %.3g %.3g %.3g %.3g (m), observed rate %.2f\n", order, x[0], x[1], x[2], x[3],
           rate[order - 1]);
  }
  CHECK_MSG(rate[0] > 0.45 && rate[0] < 1.05, "first-order L1 rate %.3g", rate[0]);
  CHECK_MSG(rate[1] > 0.6 && rate[1] < 1.1, "second-order L1 rate %.3g", rate[1]);
  for (int j = 0; j < 4; ++j) CHECK_MSG(e[1][j] < 0.6 * e[0][j], "MUSCL no better than Godunov on %d cells", 50 << j);
}

static void bad_input(void) {
  sl_diag d = {{0}};
  const char *sets[] = {"initial.phi=0.7", NULL};
  int rc = run_scene("kynch_settling", NULL, NULL, sets, "kynch_bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[initial] phi") && strstr(d.msg, "phi_max = 0.64"), "message: %s", d.msg);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  richardson_zaki();
  nigam_fan();
  refinement();
  bad_input();
  return sl_test_summary();
}
