/* The rotating frames of the flow engine against exact solutions:
 *  - frame: plane Poiseuille flow in a frame rotating about the axis normal to
 *    the plane (tests/scenes/rotating_poiseuille.ini): the velocity is the
 *    inertial frame's, the pressure carries the Coriolis and centrifugal
 *    forces exactly, p = -2 x + (x^2 + y^2)/2 - 2 (y - y^3/3); its error at
 *    interior points, and the observed order over three meshes (Q1 pressure:
 *    2 expected);
 *  - ekman: the rotating channel of Greenspan's spectrometer, rotation normal
 *    to the walls (configs/ekman_channel*.ini), against Nigam (1999) eq 4.142
 *    (U = Re W, V = -Im W) and the flux of 4.144 at E1 = 1, 0.01 and 100 (the
 *    Poiseuille limit) to 1e-3 of max|W|, the pressure drop -G ln 2 + the
 *    centrifugal 3/2 to 1e-3 of G ln 2, and the observed order of the
 *    profiles' error at E1 = 1 over three meshes (Q2: 3 or more). */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/sample.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];
SCENE_RUNNERS()

static void set_configs(const char *sub) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/%s", src ? src : ".", sub);
}

/* All components of `field` at n points into v[3 i + c]. */
static int sample(const char *file, const char *field, int n, const double *xy, double *v) {
  sl_sample s;
  sl_diag d = {{0}};
  int rc = sl_sample_points(file, field, INFINITY, n, xy, &s, &d);
  CHECK_MSG(rc == 0, "%s: %s", file, d.msg);
  if (rc) return rc;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) v[3 * i + c] = c < s.components ? s.values[(size_t)i * s.components + c] : 0.0;
  sl_sample_free(&s);
  return 0;
}

/* ---- plane Poiseuille flow in the rotating frame ------------------------------------------------------------ */

static double poiseuille_p(double x, double y) { return -2.0 * x + 0.5 * (x * x + y * y) - 2.0 * (y - y * y * y / 3); }

/* The largest error of p - p(1, 0) and of u at interior points with `cells` per side. */
static int rotating_poiseuille(int cells, double *ep, double *eu) {
  char set[64], out[64];
  snprintf(set, sizeof set, "mesh.cells=%d,%d", cells, cells);
  snprintf(out, sizeof out, "rotating_poiseuille_%d.h5", cells);
  const char *sets[] = {set, NULL};
  if (run_ok("rotating_poiseuille", NULL, NULL, sets, out)) return 1;
  enum { N = 25 };
  double xy[2 * (N + 1)], p[3 * (N + 1)], u[3 * (N + 1)];
  for (int i = 0; i < N; ++i) xy[2 * i] = 0.25 + 1.5 * (i % 5) / 4.0, xy[2 * i + 1] = -0.8 + 1.6 * (i / 5) / 4.0;
  xy[2 * N] = 1.0, xy[2 * N + 1] = 0.0;
  if (sample(out, "pressure", N + 1, xy, p) || sample(out, "velocity", N + 1, xy, u)) return 1;
  *ep = *eu = 0.0;
  for (int i = 0; i < N; ++i) {
    double x = xy[2 * i], y = xy[2 * i + 1];
    double ex = poiseuille_p(x, y) - poiseuille_p(1.0, 0.0);
    *ep = fmax(*ep, fabs(p[3 * i] - p[3 * N] - ex));
    *eu = fmax(*eu, hypot(u[3 * i] - (1.0 - y * y), u[3 * i + 1]));
  }
  return 0;
}

static void frame(void) {
  set_configs("tests/scenes");
  static const int cells[3] = {8, 16, 32};
  double ep[3], eu[3];
  for (int k = 0; k < 3; ++k)
    if (rotating_poiseuille(cells[k], &ep[k], &eu[k])) return;
  double op = log2(ep[1] / ep[2]), ou = log2(eu[1] / eu[2]);
  printf("rotating Poiseuille: pressure error %.2e %.2e %.2e (of the Coriolis pressure 8/3 across), order %.2f;"
         " velocity error %.2e %.2e %.2e, order %.2f\n",
         ep[0], ep[1], ep[2], op, eu[0], eu[1], eu[2], ou);
  /* the Coriolis pressure difference across the channel is 8/3, the centrifugal one along it 2 */
  CHECK_MSG(ep[2] < 1e-3 * 8.0 / 3.0, "pressure error %.2e", ep[2]);
  CHECK_MSG(op > 1.8, "pressure order %.2f", op);
  CHECK_MSG(eu[2] < 1e-4 && (eu[2] < 1e-12 || ou > 2.5), "velocity error %.2e, order %.2f", eu[2], ou);
}

/* ---- the Ekman-Poiseuille channel ---------------------------------------------------------------------------- */

/* Nigam (1999) eq 4.144 with sin(gamma) = 1: the pressure gradient G that carries the flux Q. */
static double ekman_G(double Q, double E1) {
  double a = 1.0 / sqrt(E1);
  return Q * (cosh(2 * a) + cos(2 * a)) / (M_PI * sqrt(E1) * (sinh(2 * a) - sin(2 * a)));
}

/* Eq 4.142: W = U - i V. */
static double complex ekman_W(double z, double E1, double G) {
  double complex k = (1.0 - I) / sqrt(E1);
  return I * G / 2.0 * (1.0 - ccosh(k * z) / ccosh(k));
}

typedef struct ekman_result {
  double e_profile; /* max |U - Re W|, |V + Im W| at r = 1.5 over max |W| */
  double e_flux;    /* Q / 0.195 - 1 */
  double e_dp;      /* (p(2, 0) - p(1, 0) - exact) / (G ln 2) */
} ekman_result;

static int ekman(const char *scene, double E1, const char *cells, ekman_result *res) {
  const double Q = 0.195, r = 1.5, G = ekman_G(Q, E1);
  char out[96], set[64];
  snprintf(out, sizeof out, "%s%s.h5", scene, cells ? cells : "");
  snprintf(set, sizeof set, "mesh.cells=%s", cells ? cells : "");
  const char *sets[] = {set, NULL};
  if (run_ok(scene, NULL, NULL, cells ? sets : NULL, out)) return 1;
  enum { N = 401 }; /* Simpson's rule across the channel */
  static double xy[2 * N], v[3 * N];
  for (int i = 0; i < N; ++i) xy[2 * i] = r, xy[2 * i + 1] = -1.0 + 2.0 * i / (N - 1);
  if (sample(out, "velocity", N, xy, v)) return 1;
  double e = 0.0, wmax = 0.0, q = 0.0;
  for (int i = 0; i < N; ++i) {
    double complex W = ekman_W(xy[2 * i + 1], E1, G);
    wmax = fmax(wmax, cabs(W));
    e = fmax(e, fmax(fabs(r * v[3 * i] - creal(W)), fabs(r * v[3 * i + 2] + cimag(W))));
    q += (i == 0 || i == N - 1 ? 1.0 : i % 2 ? 4.0 : 2.0) * v[3 * i];
  }
  q *= 2.0 / (N - 1) / 3.0 * 2.0 * M_PI * r;
  double pxy[4] = {1.0, 0.0, 2.0, 0.0}, p[6];
  if (sample(out, "pressure", 2, pxy, p)) return 1;
  res->e_profile = e / wmax;
  res->e_flux = q / Q - 1.0;
  res->e_dp = (p[3] - p[0] - (-G * log(2.0) + 1.5)) / (G * log(2.0));
  printf("%s (E1 = %g, G = %.6f): profiles %.2e of max|W| = %.4f, flux %.6f (%+.1e), pressure drop %+.1e of G ln 2\n",
         scene, E1, G, res->e_profile, wmax, q, res->e_flux, res->e_dp);
  return 0;
}

static void ekman_channel(void) {
  set_configs("configs");
  static const struct {
    const char *scene;
    double E1;
  } cases[] = {{"ekman_channel", 1.0}, {"ekman_channel_thin", 0.01}, {"ekman_channel_poiseuille", 100.0}};
  for (int k = 0; k < 3; ++k) {
    ekman_result r;
    if (ekman(cases[k].scene, cases[k].E1, NULL, &r)) return;
    CHECK_MSG(r.e_profile < 1e-3 && fabs(r.e_flux) < 1e-3 && fabs(r.e_dp) < 1e-3,
              "%s: profiles %.2e, flux %.2e, pressure drop %.2e", cases[k].scene, r.e_profile, r.e_flux, r.e_dp);
  }
  /* E1 -> infinity: Poiseuille, G -> 3 Q E1 / (4 pi), within O(1/E1^2) */
  double G = ekman_G(0.195, 100.0), Gp = 3.0 * 0.195 * 100.0 / (4.0 * M_PI);
  CHECK_MSG(fabs(G / Gp - 1.0) < 1e-4, "G = %.8f against the Poiseuille %.8f", G, Gp);
  /* the observed order at E1 = 1 */
  static const char *const meshes[3] = {"3,6", "6,12", "12,24"};
  double e[3];
  for (int k = 0; k < 3; ++k) {
    ekman_result r;
    if (ekman("ekman_channel", 1.0, meshes[k], &r)) return;
    e[k] = r.e_profile;
  }
  double o1 = log2(e[0] / e[1]), o2 = log2(e[1] / e[2]);
  printf("ekman_channel: profile error %.2e %.2e %.2e, observed orders %.2f %.2f\n", e[0], e[1], e[2], o1, o2);
  CHECK_MSG(o2 > 2.8, "observed order %.2f (Q2 velocity: 3 or more)", o2);
}

int main(int argc, char **argv) {
  static const struct {
    const char *name;
    void (*run)(void);
  } parts[] = {{"frame", frame}, {"ekman", ekman_channel}};
  int ran = 0;
  for (size_t k = 0; k < sizeof parts / sizeof parts[0]; ++k)
    if (argc < 2 || strcmp(argv[1], parts[k].name) == 0) parts[k].run(), ++ran;
  if (!ran) return fprintf(stderr, "unknown part '%s' (frame, ekman)\n", argv[1]), 2;
  return sl_test_summary();
}
