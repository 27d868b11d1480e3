/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid scenes of configs/ (1-D columns), run through the same
 * entry point as `sluice run` and read back from their output files.
 *
 * fluidized_bed: a bed fluidised at superficial velocity U ends homogeneous
 * at the porosity where the drag carries the buoyant weight,
 * K(phi, s) s = phi (1 - phi) (rho_s - rho_f) g with s = U/(1 - phi)
 * (Pringle 2001, eq 4.20 at steady state). For each drag closure that equilibrium is
 * found here by bisection on the closure's own published formula (not by
 * calling the closure): Richardson & Zaki (1954) U = u_t (1-phi)^4.65 for
 * richardson_zaki_consistent, Wen & Yu (1966) as written by Gidaspow
 * (1994), Di Felice (1994). Every bed cell must be within 1e-3 of it, for
 * three U each.
 * settled_bed: a bed at rest under its own weight against the closed-form
 * profile of Pringle's exponential solids pressure (Pringle 2001,
 * eq 4.30), compared as cell averages; the error falls at first order with h.
 * fluidization_step (Pringle 2001 section 4.6.1, if present): 0.30 mm sand, porosity 0.65
 * stepped to 0.716 with the consistent drag (Ergun / Wen-Yu
 * consistent with Rowe's C_D, drag/pringle): the final porosity within
 * 0.005 of 0.716, the overshoot at most 0.02, the same with half the cells
 * and half the step, with a tenth of the steps, and with second-order transport.
 * settling_illite (Pringle 2001 section 5.2): the hindered-settling speed, the constant-
 * porosity zone, the growing sediment, and the bed at rest against the
 * closed form.
 * slis_step (Pringle 2001 section 5.1): the twelve velocity steps of Table 5.2, the time
 * to the new steady state against the experiment and the kinematic-wave
 * reference (eqs 5.1-5.8), spreading expansions and bounded contraction fronts.
 * Stability: 10 um particles with steps 1000 times their relaxation time
 * (the settling front still falls at the hindered-settling speed), a bed
 * packing up to phi_max with no solids pressure at large steps, and beds
 * blown out of the column: bounded, conservative, no NaN; a NaN inflow stops
 * the run at once. A run continued from its checkpoint ends bit for bit
 * where the uninterrupted one does. Bad input exits 2 with the location. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];
static int quick; /* SLUICE_SKIP_LONG (the sanitizer build): no refined runs */

SCENE_RUNNERS()

static const double g = 9.81;

/* ---- equilibria of the drag laws, from their published formulas --------------- */

typedef struct bed {
  double rho_f, mu_f, rho_s, d;
} bed;

/* Schiller & Naumann (1933): C_D Re / 24. */
static double sn_factor(double re) { return re < 1000.0 ? 1.0 + 0.15 * pow(re, 0.687) : 0.44 * re / 24.0; }

/* K / phi at porosity e and slip s. */
typedef double (*k_over_phi)(const bed *b, double e, double s);

/* Richardson-Zaki-consistent with Stokes' u_t: K = 18 mu/d^2 phi e^(2-4.65). */
static double k_rz(const bed *b, double e, double s) {
  (void)s;
  return 18.0 * b->mu_f / (b->d * b->d) * pow(e, 2.0 - 4.65);
}
/* Wen & Yu (1966) as written by Gidaspow (1994, eq 5.64): K = (3/4) C_D phi e rho |s| e^-2.65 / d,
 * C_D = 24/Re (1 + 0.15 Re^0.687), Re = e rho |s| d / mu. */
static double k_wen_yu(const bed *b, double e, double s) {
  double re = e * b->rho_f * s * b->d / b->mu_f;
  return 18.0 * b->mu_f / (b->d * b->d) * pow(e, -2.65) * sn_factor(re);
}
/* Di Felice (1994), Int. J. Multiphase Flow 20:153, eqs 7-9: K = (3/4) C_D0 rho phi e^(2-beta) |s| / d,
 * C_D0 = (0.63 + 4.8/sqrt(Re))^2, beta = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2), Re = e rho |s| d/mu. */
static double k_di_felice(const bed *b, double e, double s) {
  double re = e * b->rho_f * s * b->d / b->mu_f;
  double cd = pow(0.63 + 4.8 / sqrt(re), 2.0), beta = 3.7 - 0.65 * exp(-pow(1.5 - log10(re), 2.0) / 2.0);
  return 0.75 * cd * b->rho_f * pow(e, 2.0 - beta) * s / b->d;
}
/* Pringle (2001) dilute law, Wen-Yu-consistent with Rowe's C_D (eqs 3.24-3.25, 4.20):
 * K = (3/4) C_D rho phi e^-2.65 |s| / d, C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), Re = rho |s| d / mu. */
static double k_pringle_dilute(const bed *b, double e, double s) {
  double re = b->rho_f * s * b->d / b->mu_f;
  return 18.0 * b->mu_f / (b->d * b->d) * pow(e, -2.65) * sn_factor(re);
}

/* Pringle's drag as drag/pringle evaluates it by default, from the published formulas: Ergun (1952) as
 * Pringle (2001) eq 3.12 prints it below porosity 0.6, K = 150 phi^2 mu/(e d^2) + 1.75 phi rho |s|/(e d),
 * and the Wen-Yu-consistent law with Rowe's C_D at and above (k_pringle_dilute). */
static double k_pringle(const bed *b, double e, double s) {
  if (e < 0.6) return 150.0 * (1.0 - e) * b->mu_f / (e * b->d * b->d) + 1.75 * b->rho_f * s / (e * b->d);
  return k_pringle_dilute(b, e, s);
}

/* The porosity where K s = phi e (rho_s - rho_f) g, s = U/e (bisection; K/phi s - e drho g grows as e
 * falls). */
static double equilibrium_porosity(const bed *b, k_over_phi k, double U) {
  double lo = 0.36, hi = 1.0 - 1e-12;
  for (int it = 0; it < 200; ++it) {
    double e = 0.5 * (lo + hi), s = U / e;
    double r = k(b, e, s) * s - e * (b->rho_s - b->rho_f) * g;
    if (r > 0.0) lo = e;
    else hi = e;
  }
  return 0.5 * (lo + hi);
}

/* The superficial velocity in equilibrium at porosity e. */
static double equilibrium_velocity(const bed *b, k_over_phi k, double e) {
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    double U = 0.5 * (lo + hi), s = U / e;
    if (k(b, e, s) * s < e * (b->rho_s - b->rho_f) * g) lo = U;
    else hi = U;
  }
  return 0.5 * (lo + hi);
}

/* The bed: the cells below the topmost one holding solids (which is partly filled). */
static int bed_top(const double *phi, int n) {
  int top = -1;
  for (int i = 0; i < n; ++i)
    if (phi[i] > 1e-9) top = i;
  return top;
}

/* ---- fluidized_bed ---------------------------------------------------------------- */

static void fluidized_bed(void) {
  const bed b = {998.2, 1.002e-3, 2600.0, 3e-4};
  struct {
    const char *label, *section;
    k_over_phi k;
  } drags[] = {
      {"richardson_zaki_consistent", "[closure.drag]\nmodel = richardson_zaki_consistent\nn = 4.65\n", k_rz},
      {"wen_yu", "[closure.drag]\nmodel = wen_yu\n", k_wen_yu},
      {"di_felice", "[closure.drag]\nmodel = di_felice\n", k_di_felice},
  };
  const double Us[3] = {0.006, 0.010, 0.014};
  /* Richardson-Zaki directly: u_t = drho g d^2 / (18 mu) = 78.4 mm/s (the sand of section 4.6.1) */
  double ut = (b.rho_s - b.rho_f) * g * b.d * b.d / (18.0 * b.mu_f);
  CHECK_MSG(fabs(ut - 0.0784) < 1e-4, "Stokes u_t = %.5f m/s, reference 78.4 mm/s", ut);
  for (int j = 0; j < 3; ++j) CHECK_CLOSE(equilibrium_porosity(&b, k_rz, Us[j]), pow(Us[j] / ut, 1.0 / 4.65), 1e-9);
  for (size_t k = 0; k < sizeof drags / sizeof drags[0]; ++k) {
    for (int j = 0; j < 3; ++j) {
      double e_eq = equilibrium_porosity(&b, drags[k].k, Us[j]), phi_eq = 1.0 - e_eq;
      char vel[64];
      snprintf(vel, sizeof vel, "boundary.left.velocity=%.17g", Us[j]);
      const char *sets[] = {vel, NULL};
      const char *out = "fluidized_bed.h5";
      if (run_ok("fluidized_bed", "closure.drag", drags[k].section, sets, out)) continue;
      int n = 0;
      double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
      if (!phi) continue;
      int top = bed_top(phi, n);
      double worst = 0.0, inv = 0.0;
      for (int i = 0; i < top; ++i) worst = fmax(worst, fabs(phi[i] - phi_eq));
      for (int i = 0; i < n; ++i) inv += phi[i] / n;
      printf(
          "  fluidized_bed %-27s U = %4.1f mm/s: porosity %.5f (own law %.5f), max |dphi| %.1e over %d cells, "
          "steady at t = %.1f s\n",
          drags[k].label, 1e3 * Us[j], 1.0 - phi[0], e_eq, worst, top, tf);
      CHECK_MSG(top >= 20, "%s U = %g: a bed of %d cells only", drags[k].label, Us[j], top);
      CHECK_MSG(worst <= 1e-3, "%s U = %g: porosity off its equilibrium %.5f by %.3g", drags[k].label, Us[j], e_eq,
                worst);
      CHECK_MSG(tf < 599.0, "%s U = %g: not steady by the end", drags[k].label, Us[j]);
      CHECK_MSG(fabs(scalar(out, "solids_conservation_error", tf)) < 1e-12, "solids not conserved");
      CHECK_MSG(fabs(inv - 0.3 * 0.4) < 1e-12, "inventory %.15g", inv);
      free(phi);
    }
  }
}

/* ---- settled_bed -------------------------------------------------------------------- */

/* Pringle's exponential p_s with A, nbar: depth below the bed top where p_s = P (from eq 4.30). */
typedef struct pexp {
  double A, nbar, drho;
} pexp;
static double depth_of(const pexp *p, double P) {
  return P * (1.0 + p->A - p->A * log(P)) / ((1.0 - p->nbar) * p->drho * g);
}
/* p_s at depth z (inverse of depth_of, bisection in log P). */
static double p_at_depth(const pexp *p, double z) {
  if (z <= 0.0) return 0.0;
  double lo = -60.0, hi = 30.0;
  for (int it = 0; it < 200; ++it) {
    double m = 0.5 * (lo + hi);
    if (depth_of(p, exp(m)) < z) lo = m;
    else hi = m;
  }
  return exp(0.5 * (lo + hi));
}

/* The settled bed on n cells against the closed form: max |phi - exact cell average| over the cells more
 * than 2 cm below the exact bed top (near the top phi ~ 1/(1 - A ln(depth)) has an infinite slope, which
 * cell averages resolve only in the mean), the L1 error over all cells, and max |solids volume above a
 * face - exact| over all faces. */
typedef struct rest_case {
  const char *scene;
  const char *const *sets; /* with mesh.cells=n added */
  pexp p;
  double H, S, t_end; /* column height, solids volume per unit area, the run's end */
} rest_case;

static double bed_at_rest_error(const rest_case *rc, int n, double *bottom_phi, double *bottom_exact, double *above_err,
                                double *l1) {
  char cells[64];
  snprintf(cells, sizeof cells, "mesh.cells=%d", n);
  const char *sets[16] = {cells};
  for (int k = 0; rc->sets && rc->sets[k] && k < 14; ++k) sets[k + 1] = rc->sets[k];
  const char *out = "bed_at_rest.h5";
  *bottom_phi = *bottom_exact = *above_err = *l1 = NAN;
  if (run_ok(rc->scene, NULL, NULL, sets, out)) return INFINITY;
  int nn = 0;
  double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &nn, &tf);
  if (!phi || nn != n) {
    free(phi);
    CHECK_MSG(0, "%s: %d cells read", rc->scene, nn);
    return INFINITY;
  }
  const pexp p = rc->p;
  const double H = rc->H, S = rc->S, Pb = p.drho * g * S, top = depth_of(&p, Pb), h = H / n;
  double worst = 0.0, above = 0.0;
  *above_err = 0.0, *l1 = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    /* the solids volume above height z per unit area is p_s(depth)/(drho g) */
    double s0 = p_at_depth(&p, top - i * h) / (p.drho * g), s1 = p_at_depth(&p, top - (i + 1) * h) / (p.drho * g);
    double exact = (s0 - s1) / h;
    above += phi[i] * h;
    *above_err = fmax(*above_err, fabs(above - s0));
    if (i == 0) *bottom_phi = phi[0], *bottom_exact = exact;
    if ((i + 1) * h <= top - 0.02) worst = fmax(worst, fabs(phi[i] - exact));
    *l1 += fabs(phi[i] - exact) * h;
  }
  CHECK_MSG(tf < rc->t_end - 1.0, "%s: not steady by the end", rc->scene);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", tf)) < 1e-12, "%s: solids not conserved", rc->scene);
  free(phi);
  return worst;
}

static double settled_error(int n, double *bottom_phi, double *bottom_exact, double *above_err, double *l1) {
  const rest_case rc = {"settled_bed", NULL, {0.1075, 0.95, 1500.0}, 0.5, 0.05, 20000.0};
  return bed_at_rest_error(&rc, n, bottom_phi, bottom_exact, above_err, l1);
}

static void settled_bed(void) {
  const pexp p = {0.1075, 0.95, 1500.0};
  /* a sand example (eq 4.30): S = 6 m, drho = 1650, A = 0.015, nbar = 0.5: P_b 97 kPa, n_bottom 0.396 */
  const pexp sand = {0.015, 0.5, 1650.0};
  double Pb = sand.drho * g * 6.0;
  CHECK_MSG(fabs(Pb - 97.1e3) < 100.0, "sand P_b = %g", Pb);
  CHECK_MSG(fabs(1.0 - (1.0 - sand.nbar) / (1.0 - sand.A * log(Pb)) - 0.396) < 5e-4, "sand n_bottom");
  double Pb2 = p.drho * g * 0.05;
  printf("  settled_bed: closed form p_s(bottom) = %.1f Pa, porosity %.4f, bed %.4f m deep\n", Pb2,
         1.0 - (1.0 - p.nbar) / (1.0 - p.A * log(Pb2)), depth_of(&p, Pb2));
  double b1, x1, b2, x2, a1, a2, l1, l2;
  double e1 = settled_error(100, &b1, &x1, &a1, &l1);
  printf(
      "  settled_bed, 100 cells: max |phi - closed-form cell average| = %.2e below the top 2 cm, L1 %.2e m; "
      "bottom cell %.5f vs %.5f; solids above a face within %.2e m (of 0.05 m)\n",
      e1, l1, b1, x1, a1);
  CHECK_MSG(e1 <= 1e-3, "settled bed off the closed form by %.4f (100 cells; tolerance 0.005)", e1);
  CHECK_MSG(a1 <= 2e-4, "solids above a face off by %.3g m", a1);
  if (quick) return; /* the refined run */
  double e2 = settled_error(200, &b2, &x2, &a2, &l2);
  printf("  settled_bed, 200 cells: %.2e, L1 %.2e m, solids above a face within %.2e m\n", e2, l2, a2);
  CHECK_MSG(l2 <= 0.5 * l1, "settled bed L1 error %.3g -> %.3g with h/2", l1, l2);
  CHECK_MSG(e2 <= 0.6 * e1, "settled bed error %.3g -> %.3g with h/2: not converging", e1, e2);
  CHECK_MSG(a2 <= 0.6 * a1, "solids above a face off by %.3g -> %.3g m with h/2", a1, a2);
}

/* ---- fluidization_step (Pringle 2001 section 4.6.1) ------------------------------------------- */

typedef struct step_result {
  double final_porosity, overshoot, t_cross;
} step_result;

/* Runs the step with `cells` and `dt`: the bed's mean porosity at the end (the distributor cell and the top
 * two aside), the most any bed cell's porosity exceeded that at any output, and the time at which the
 * porosity at x = 0.3 m crossed halfway from 0.65 to 0.716 (linear between outputs). */
static int fluidization_step_run(int cells, double dt, int order, step_result *res) {
  char c1[64], c2[64];
  snprintf(c1, sizeof c1, "mesh.cells=%d", cells);
  snprintf(c2, sizeof c2, "time.dt=%.17g", dt);
  const char *sets[] = {c1, c2, "two_fluid.order=2", "two_fluid.limiter=mc", NULL};
  if (order == 1) sets[2] = NULL; /* the scene's default */
  const char *out = "fluidization_step.h5";
  if (run_ok("fluidization_step", NULL, NULL, sets, out)) return 1;
  int n = 0, ns = 0;
  double *times = NULL;
  sl_diag d = {{0}};
  if (sl_output_read_times(out, &ns, &times, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return 1;
  }
  double tf, *phi = field_at(out, "phi", INFINITY, &n, &tf);
  if (!phi) {
    free(times);
    return 1;
  }
  int top = bed_top(phi, n), m = 0, i_probe = (int)(0.3 * n); /* the cell just above x = 0.3 */
  double sum = 0.0;
  for (int i = 1; i < top - 1; ++i) sum += 1.0 - phi[i], ++m;
  res->final_porosity = m ? sum / m : NAN;
  double hi = 0.0, level = 0.5 * (0.65 + 0.716), prev = 0.65, t_prev = 0.0;
  res->t_cross = NAN;
  for (int s = 0; s < ns; ++s) {
    int nn;
    double *p = field_at(out, "phi", times[s], &nn, NULL);
    if (!p) break;
    int top_s = bed_top(p, nn), lim = top_s < top ? top_s : top;
    for (int i = 1; i < lim - 1; ++i) hi = fmax(hi, 1.0 - p[i]);
    double e = 1.0 - p[i_probe];
    if (isnan(res->t_cross) && e >= level && s > 0)
      res->t_cross = t_prev + (times[s] - t_prev) * (level - prev) / (e - prev);
    prev = e, t_prev = times[s];
    free(p);
  }
  res->overshoot = hi - res->final_porosity;
  free(phi), free(times);
  return 0;
}

static void fluidization_step(void) {
  /* the steady velocities (eq 4.20 with Ergun + Wen-Yu-consistent with Rowe's C_D):
   * 7.78 mm/s at porosity 0.65, 11.51 at 0.716; the scene's inlet uses these */
  const bed b = {998.2, 1.002e-3, 2600.0, 3e-4};
  double U0 = equilibrium_velocity(&b, k_pringle_dilute, 0.65), U1 = equilibrium_velocity(&b, k_pringle_dilute, 0.716);
  CHECK_MSG(fabs(U0 - 7.78e-3) < 0.01e-3 && fabs(U1 - 11.51e-3) < 0.01e-3, "U(0.65) = %.5f, U(0.716) = %.5f", U0, U1);
  CHECK_MSG(fabs(U0 - 0.0077783) < 1e-7 && fabs(U1 - 0.0115101) < 1e-7, "the scene's U0, U1 are not %.7f, %.7f", U0,
            U1);
  /* the last run: second-order (MUSCL, MC-limited) transport, which shows no overshoot either */
  step_result r[4];
  const int cells[4] = {100, 200, 100, 100}, order[4] = {1, 1, 1, 2};
  const double dts[4] = {0.01, 0.005, 0.1, 0.01};
  const int n_runs = quick ? 1 : 4;
  for (int k = 0; k < n_runs; ++k)
    if (fluidization_step_run(cells[k], dts[k], order[k], &r[k])) return;
  for (int k = 0; k < n_runs; ++k) {
    printf(
        "  fluidization_step %d cells, dt %.3g s, order %d: final porosity %.4f, overshoot %.4f, front at x = 0.3 "
        "m at t = %.2f s\n",
        cells[k], dts[k], order[k], r[k].final_porosity, r[k].overshoot, r[k].t_cross);
    CHECK_MSG(fabs(r[k].final_porosity - 0.716) <= 0.005, "final porosity %.4f, Pringle (2001): 0.716 +- 0.005",
              r[k].final_porosity);
    CHECK_MSG(r[k].overshoot <= 0.02, "overshoot %.4f > 0.02", r[k].overshoot);
    CHECK_MSG(fabs(r[k].t_cross - r[0].t_cross) <= 0.05 * r[0].t_cross,
              "front time %.3g vs %.3g: not mesh/dt independent within 5 %%", r[k].t_cross, r[0].t_cross);
  }
}

/* ---- settling_illite (Pringle 2001 section 5.2) --------------------------------------------------- */

/* Pringle (2001) section 5.2 as configs/settling_illite.ini sets it up (its header lists what had to be assumed). The
 * thesis's measured profiles are lost with its figures, so its error metric (12.4 / 8.0 / 17.2 % at 90 /
 * 180 / 300 s) cannot be recomputed; what follows from Table 5.4 is checked:
 * - the suspension settles at the hindered-settling speed of the drag's equilibrium, 3.5e-5 m/s for
 *   d' = 5.5 um at porosity 0.95 (Richardson-Zaki with Stokes' u_t: a scale check), measured
 *   as the solids missing from the upper half of the column, which over phi0 is the fall of the top;
 * - between the top and the sediment the porosity stays at its initial value (thesis eqs 5.10-5.12);
 * - the sediment grows at the bottom;
 * - run on to rest, the consolidated bed against the closed form of Pringle's p_s (eq 4.30) within
 *   0.005 in porosity, compared as cell averages; its bottom porosity is the 0.870 the column
 *   height was chosen for. */
static void settling_illite(void) {
  const bed b = {870.0, 0.586e-3, 2460.0, 0.088 * 62.5e-6};
  const double phi0 = 0.05, H = 0.4, n_cells = 64;
  double ut = (b.rho_s - b.rho_f) * g * b.d * b.d / (18.0 * b.mu_f);
  double v = equilibrium_velocity(&b, k_pringle, 1.0 - phi0);
  CHECK_MSG(fabs(ut - 4.47e-5) < 0.01e-5, "illite u_t %.4g m/s, reference 4.47e-5", ut);
  CHECK_MSG(fabs(v - 3.5e-5) < 0.05e-5 && fabs(v / (ut * pow(1.0 - phi0, 4.65)) - 1.0) < 1e-3,
            "illite hindered settling %.4g m/s, reference 3.5e-5, Richardson-Zaki %.4g", v, ut * pow(1.0 - phi0, 4.65));
  const char *out = "settling_illite.h5";
  if (run_ok("settling_illite", NULL, NULL, NULL, out)) return;
  const double times[3] = {90, 180, 300};
  double bottom_prev = phi0;
  for (int k = 0; k < 3; ++k) {
    int n = 0;
    double tf = 0.0, *phi = field_at(out, "phi", times[k], &n, &tf);
    if (!phi) return;
    double missing = 0.0, zone = 0.0, lo = 1.0, hi = 0.0;
    for (int i = n / 2; i < n; ++i) missing += (phi0 - phi[i]) * H / n;
    for (int i = n / 4; i < 3 * n / 4; ++i) zone = fmax(zone, fabs(phi[i] - phi0));
    for (int i = 0; i < n; ++i) lo = fmin(lo, 1.0 - phi[i]), hi = fmax(hi, 1.0 - phi[i]);
    double fall = missing / phi0;
    printf(
        "  settling_illite t = %3.0f s: the top has fallen %.2f mm (hindered settling %.2f mm, %+.2f %%), "
        "porosity %.4f (bottom) to %.4f, constant zone within %.1e of 0.95, level of phi = 0.025 at %.4f m\n",
        tf, 1e3 * fall, 1e3 * v * tf, 100 * (fall / (v * tf) - 1.0), lo, hi, zone,
        scalar(out, "interface_height_0", tf));
    CHECK_MSG(n == n_cells && fabs(tf - times[k]) < 1e-9, "illite: output at %g s", times[k]);
    CHECK_MSG(fabs(fall / (v * tf) - 1.0) < 0.01, "illite: the top fell %.4g m by %g s, hindered settling %.4g", fall,
              tf, v * tf);
    CHECK_MSG(zone < 1e-4, "illite: the middle half of the column left porosity 0.95 by %.2g at %g s", zone, tf);
    CHECK_MSG(phi[0] > bottom_prev, "illite: the sediment does not grow (bottom phi %.4f at %g s)", phi[0], tf);
    bottom_prev = phi[0];
    free(phi);
  }
  /* on to rest: steps of 20 s (the drag is implicit), stopped when max |dphi/dt| < 1e-10 per s */
  const char *rest_sets[] = {"time.dt=20", "time.end=400000", "output.every=100000", "two_fluid.steady_tolerance=1e-10",
                             NULL};
  const rest_case rc = {"settling_illite", rest_sets, {0.1075, 0.95, b.rho_s - b.rho_f}, H, phi0 * H, 400000.0};
  double bp, bx, above, l1;
  double worst = bed_at_rest_error(&rc, (int)n_cells, &bp, &bx, &above, &l1);
  printf(
      "  settling_illite at rest: max |porosity - closed-form cell average| %.2e below the top 2 cm, L1 %.2e m; "
      "bottom cell %.4f vs %.4f; solids above a face within %.2e m (of 0.02 m)\n",
      worst, l1, 1.0 - bp, 1.0 - bx, above);
  CHECK_MSG(worst <= 0.005, "illite at rest: off the closed form by %.4f (tolerance 0.005)", worst);
  CHECK_MSG(fabs((1.0 - bx) - 0.870) < 0.001, "illite: the closed form's bottom porosity %.4f, not 0.870", 1.0 - bx);
}

/* ---- slis_step (Pringle 2001 section 5.1) ------------------------------------------------------ */

/* Table 5.2 of Pringle (2001) and the inertia-free kinematic-wave reference (eqs 5.1-5.8)
 * (same drag, free surface, 2.5 mm Godunov): U0, U1 in mm/s, t95 and t99 of the level change (0: not
 * resolved there), the single-shock contraction time t_c (0: an expansion). */
typedef struct slis_case {
  double d, n0, n1, t_exp, t_fea, U0, U1, t95_kin, t99_kin, t_c;
  int switch_crossed;     /* the change crosses drag/pringle's jump at porosity 0.6 (eq 3.12 vs 3.34) */
  int matches_experiment; /* see slis_step() */
} slis_case;
static const slis_case slis[12] = {
    {3e-3, 0.54, 0.76, 15, 13.8, 11.1, 35.5, 11.3, 13.2, 0, 1, 1},
    {3e-3, 0.68, 0.80, 19, 18, 24.4, 42.1, 10.3, 12.5, 0, 0, 0},
    {4e-3, 0.53, 0.83, 17, 16, 13.4, 61.4, 13.7, 17.1, 0, 1, 1},
    {4e-3, 0.62, 0.73, 9, 7.2, 23.4, 40.3, 6.9, 8.1, 0, 0, 1},
    {5e-3, 0.66, 0.85, 18, 15, 35.2, 80.3, 10.2, 12.2, 0, 0, 0},
    {5e-3, 0.72, 0.78, 10, 11, 46.8, 60.7, 5.5, 6.2, 0, 0, 0},
    {3e-3, 0.63, 0.54, 9.3, 5.6, 18.9, 11.1, 9.1, 11.1, 6.94, 1, 1},
    {3e-3, 0.73, 0.53, 10, 7.4, 31.0, 10.6, 5.8, 7.3, 5.74, 1, 1},
    {4e-3, 0.70, 0.61, 6.8, 4.9, 35.0, 22.2, 4.8, 0, 4.94, 0, 1},
    {4e-3, 0.67, 0.57, 6.0, 4.3, 30.3, 15.9, 6.5, 8.4, 4.43, 1, 1},
    {5e-3, 0.69, 0.64, 5.2, 4.0, 40.7, 31.8, 4.1, 0, 4.29, 0, 1},
    {5e-3, 0.80, 0.73, 11, 7.3, 65.9, 48.9, 4.0, 4.5, 4.19, 0, 0},
};

/* The kinematic (drift-flux) solids flux of a bed of porosity e = 1 - phi through which the mixture flux j
 * passes, the slip in local equilibrium: F = phi (j - U_eq(e)) (Slis et al. 1958, thesis eqs 5.1-5.8). */
static double kinematic_flux(const bed *b, double j, double phi) {
  return phi * (j - equilibrium_velocity(b, k_pringle, 1.0 - phi));
}

/* The 10-90 % width of the travelling wave that a kinematic shock from phi1 (below) to phi0 (above)
 * becomes with a particle diffusivity D: D dphi/dx = F(phi) - F(phi0) - s (phi - phi0), s the shock speed
 * (the viscous profile of a conservation law; e.g. LeVeque 2002, Finite Volume Methods, section 11.14),
 * integrated dx = D dphi / G(phi) by the midpoint rule. */
static double travelling_wave_width(const bed *b, double j, double phi0, double phi1, double D) {
  const double F0 = kinematic_flux(b, j, phi0), s = (kinematic_flux(b, j, phi1) - F0) / (phi1 - phi0);
  const double pa = phi1 + 0.1 * (phi0 - phi1), pb = phi1 + 0.9 * (phi0 - phi1);
  const int m = 400;
  double x = 0.0;
  for (int i = 0; i < m; ++i) {
    double p = pa + (pb - pa) * (i + 0.5) / m;
    x += D * (pb - pa) / m / (kinematic_flux(b, j, p) - F0 - s * (p - phi0));
  }
  return fabs(x);
}

/* Where phi first crosses `level` going up from the bottom (linear between cell centres of a uniform
 * column of height 1), rising or falling; NAN if it does not. */
static double first_crossing(const double *phi, int n, double level, int rising) {
  for (int i = 1; i < n; ++i) {
    double a = phi[i - 1], b = phi[i];
    if ((rising && a < level && b >= level) || (!rising && a > level && b <= level))
      return (i - 0.5 + (level - a) / (b - a)) / n;
  }
  return NAN;
}

/* The width (m) of the front between the new bed (phi1, at the bottom) and the old (phi0): the distance
 * between the first crossings of phi1 + 0.1 (phi0 - phi1) and phi1 + 0.9 (phi0 - phi1) from the bottom. */
static double front_width(const char *file, double t, double phi0, double phi1) {
  int n = 0;
  double *phi = field_at(file, "phi", t, &n, NULL);
  if (!phi) return NAN;
  int rising = phi0 > phi1;
  double w = first_crossing(phi, n, phi1 + 0.9 * (phi0 - phi1), rising) -
             first_crossing(phi, n, phi1 + 0.1 * (phi0 - phi1), rising);
  free(phi);
  return w;
}

typedef struct slis_result {
  double U0, U1, H0, H1, t95, t99, width[3]; /* widths at t = 1, 2, 3 s */
} slis_result;

/* The time after which the level H stays within (1 - q) |H_end - H_0| of H_end, linear between outputs. */
static double settle_time(const double *t, const double *H, int m, double q) {
  double band = (1.0 - q) * fabs(H[m - 1] - H[0]);
  for (int k = m - 2; k >= 0; --k) {
    double a = fabs(H[k] - H[m - 1]);
    if (a > band) {
      double b = fabs(H[k + 1] - H[m - 1]);
      return t[k] + (t[k + 1] - t[k]) * (a - band) / (a - b);
    }
  }
  return 0.0;
}

/* Runs case k (1-12) of configs/slis_step.ini with the extra override `extra` (or NULL). */
static int slis_run(int k, const char *extra, slis_result *r) {
  const slis_case *c = &slis[k - 1];
  char cs[64], ds[64];
  snprintf(cs, sizeof cs, "two_fluid.case=%d", k);
  snprintf(ds, sizeof ds, "solid.diameter=%.17g", c->d);
  const char *sets[] = {cs, ds, extra, NULL};
  const char *out = "slis_step.h5";
  if (run_ok("slis_step", NULL, NULL, sets, out)) return 1;
  int m = 0;
  double *t = NULL;
  sl_diag d = {{0}};
  if (sl_output_read_times(out, &m, &t, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return 1;
  }
  double *H = malloc((size_t)m * sizeof *H);
  if (!H) {
    free(t);
    return 1;
  }
  for (int i = 0; i < m; ++i) H[i] = scalar(out, "interface_height_0", t[i]);
  r->U0 = scalar(out, "mixture_flux", 0.0), r->U1 = scalar(out, "mixture_flux", t[m - 1]);
  r->H0 = H[0], r->H1 = H[m - 1];
  r->t95 = settle_time(t, H, m, 0.95), r->t99 = settle_time(t, H, m, 0.99);
  for (int i = 0; i < 3; ++i) r->width[i] = front_width(out, 1.0 + i, 1.0 - c->n0, 1.0 - c->n1);
  CHECK_MSG(fabs(scalar(out, "solids_conservation_error", t[m - 1])) < 1e-12, "slis case %d: solids not conserved", k);
  /* settled: within 1 % of the final level for the last 5 s at least (a bed top whose smoothed profile
   * passes the drag's jump at porosity 0.6 keeps a small flicker there, so max |dphi/dt| need not fall
   * to the scene's steady_tolerance) */
  CHECK_MSG(r->t99 < t[m - 1] - 5.0 || t[m - 1] < 39.9, "slis case %d: the level has not settled by %g s", k, t[m - 1]);
  free(H), free(t);
  return 0;
}

/* Pringle (2001) section 5.1: the twelve Slis et al. (1958) velocity steps of Table 5.2, as configs/slis_step.ini sets
 * them (its header says what is assumed). Checked:
 * - the inflows, from the drag law's equilibrium at n0 and n1, against the test's own bisection on the
 *   published formulas and the reference table (to its 0.1 mm/s);
 * - the final level against that of a sharp bed top by solids conservation, H0 (1 - n0)/(1 - n1): at it
 *   or up to 1 cm above (the level is read where phi = 0.075, in the diffusive tail over the bed);
 * - t_1 = t99 of the level change against the inertia-free kinematic-wave reference with the same
 *   drag (t95 where its t99 was not resolved), within 20 % (inertia and viscous terms add delay);
 * - t_1 against the experiment within the bands the thesis itself achieved (Table 5.2): 20 % for
 *   expansions, 40 % for contractions. Four cases miss them: the expansions II 0.68 -> 0.80 and III
 *   0.66 -> 0.85, 0.72 -> 0.78 and the contraction III 0.80 -> 0.73, where the experiment is 35-60 %
 *   slower than both this model and the kinematic theory (which agree within 15 %); for those the test
 *   asserts only that direction. The thesis's finite elements came closer there (18, 15, 11, 7.3 s);
 *   no drag printed in the thesis would explain it (eqs 3.12-3.34).
 * - the fronts: an expansion's widens (the width at 3 s at least 1.5 times that at 1 s); a contraction
 *   that does not cross the drag switch stays a shock: never wider than the travelling wave of the
 *   kinematic flux with the scene's particle diffusivity (plus two cells), and without that diffusivity
 *   (case 11) a few cells wide and not widening. */
static void slis_step(void) {
  const double D = 1e-4, h = 1.0 / 400;
  int first = 1, last = 12;
  for (int k = first; k <= last; ++k) {
    if (quick && k != 1 && k != 8 && k != 12) continue;
    const slis_case *c = &slis[k - 1];
    const bed b = {998.2, 1.002e-3, 1140.0, c->d};
    double U0 = equilibrium_velocity(&b, k_pringle, c->n0), U1 = equilibrium_velocity(&b, k_pringle, c->n1);
    CHECK_MSG(fabs(1e3 * U0 - c->U0) <= 0.05 + 1e-9 && fabs(1e3 * U1 - c->U1) <= 0.05 + 1e-9,
              "slis case %d: U0, U1 = %.3f, %.3f mm/s, reference %.1f, %.1f", k, 1e3 * U0, 1e3 * U1, c->U0, c->U1);
    slis_result r;
    if (slis_run(k, NULL, &r)) continue;
    const int expansion = c->n1 > c->n0;
    double H_exact = 0.275 * (1.0 - c->n0) / (1.0 - c->n1);
    double dev_exp = (r.t99 - c->t_exp) / c->t_exp, dev_kin = r.t99 / c->t99_kin - 1.0;
    double dev95 = r.t95 / c->t95_kin - 1.0;
    char kin[64] = "kin n/r";
    if (c->t99_kin > 0) snprintf(kin, sizeof kin, "kin %.1f, %+.0f %%", c->t99_kin, 100 * dev_kin);
    printf(
        "  slis %2d %s %.2f -> %.2f: U %.2f -> %.2f mm/s, level %.4f -> %.4f m (sharp: %.4f), t95 %.2f s (kin %.1f, "
        "%+.0f %%), t_1 = t99 %.2f s (%s; exp %.1f, %+.0f %%; thesis FE %.1f); front %.1f, %.1f, %.1f cells "
        "at 1, 2, 3 s\n",
        k, expansion ? "exp" : "con", c->n0, c->n1, 1e3 * r.U0, 1e3 * r.U1, r.H0, r.H1, H_exact, r.t95, c->t95_kin,
        100 * dev95, r.t99, kin, c->t_exp, 100 * dev_exp, c->t_fea, r.width[0] / h, r.width[1] / h, r.width[2] / h);
    CHECK_MSG(fabs(r.U0 - U0) <= 1e-9 * U0 && fabs(r.U1 - U1) <= 1e-9 * U1,
              "slis case %d: inflow %.9g, %.9g vs %.9g, %.9g", k, r.U0, r.U1, U0, U1);
    /* the level reads phi = 0.075 in the bed top's diffusive tail: above the sharp interface, by millimetres */
    CHECK_MSG(r.H1 >= H_exact - h && r.H1 <= H_exact + 0.01, "slis case %d: final level %.4f m, sharp %.4f", k, r.H1,
              H_exact);
    CHECK_MSG(fabs(dev95) <= 0.2, "slis case %d: t95 %.2f s, kinematic %.1f", k, r.t95, c->t95_kin);
    if (c->t99_kin > 0)
      CHECK_MSG(fabs(dev_kin) <= 0.2, "slis case %d: t99 %.2f s, kinematic %.1f", k, r.t99, c->t99_kin);
    if (c->matches_experiment)
      CHECK_MSG(fabs(dev_exp) <= (expansion ? 0.2 : 0.4), "slis case %d: t_1 %.2f s, experiment %.1f", k, r.t99,
                c->t_exp);
    else CHECK_MSG(r.t99 < c->t_exp, "slis case %d: t_1 %.2f s, experiment %.1f", k, r.t99, c->t_exp);
    if (expansion) {
      CHECK_MSG(r.width[2] >= 1.5 * r.width[0], "slis case %d: expansion front %.1f -> %.1f cells from 1 to 3 s", k,
                r.width[0] / h, r.width[2] / h);
    } else if (!c->switch_crossed) {
      double w_tw = travelling_wave_width(&b, U1, 1.0 - c->n0, 1.0 - c->n1, D);
      printf("  slis %2d: the contraction's travelling wave with D = %g m2/s is %.1f cells wide\n", k, D, w_tw / h);
      for (int i = 0; i < 3; ++i)
        CHECK_MSG(r.width[i] <= w_tw + 2 * h,
                  "slis case %d: contraction front %.1f cells at %d s, travelling wave %.1f", k, r.width[i] / h, i + 1,
                  w_tw / h);
    }
  }
  /* without the particle diffusivity the contraction is the kinematic shock of the model itself */
  slis_result r0;
  if (!quick && slis_run(11, "two_fluid.diffusivity=0", &r0) == 0) {
    printf("  slis 11 without diffusivity: front %.1f, %.1f, %.1f cells at 1, 2, 3 s, t99 %.2f s\n", r0.width[0] / h,
           r0.width[1] / h, r0.width[2] / h, r0.t99);
    CHECK_MSG(r0.width[2] <= 8 * h && r0.width[2] - r0.width[0] <= 2 * h,
              "slis case 11 (D = 0): contraction front %.1f -> %.1f cells from 1 to 3 s", r0.width[0] / h,
              r0.width[2] / h);
  }
}

/* ---- stability ---------------------------------------------------------------------- */

/* 10 um sand (relaxation time rho_s d^2/(18 mu) = 14 us) settling in a 1 cm column (fluidized_bed with no
 * inflow) with dt = 1000 relaxation times: bounded, conservative, and the top of the suspension falls at
 * the Richardson-Zaki speed u_t (1 - phi0)^4.65 of the richardson_zaki_consistent drag. */
static void stiff_fine_particles(void) {
  const double d = 1e-5, rho_s = 2600, rho_f = 998.2, mu = 1.002e-3, phi0 = 0.1, H = 0.01;
  const int n = 100;
  double tau = rho_s * d * d / (18 * mu), ut = (rho_s - rho_f) * g * d * d / (18 * mu);
  double v = ut * pow(1 - phi0, 4.65), t_end = 0.3 * H / v;
  char dt[64], end[64], every[64];
  snprintf(dt, sizeof dt, "time.dt=%.17g", 1000 * tau);
  snprintf(end, sizeof end, "time.end=%.17g", t_end);
  snprintf(every, sizeof every, "output.every=%.17g", t_end / 5);
  const char *sets[] = {"solid.diameter=1e-5",
                        "mesh.x=0,0.01",
                        "mesh.cells=100",
                        "initial.porosity=0.9",
                        "boundary.left.velocity=0",
                        "two_fluid.steady_tolerance=0",
                        dt,
                        end,
                        every,
                        NULL};
  const char *out = "stiff_fine.h5";
  if (run_ok("fluidized_bed", NULL, NULL, sets, out)) return;
  double ts[6], zs[6], worst_phi = 0.0, worst_mass = 0.0;
  for (int s = 0; s <= 5; ++s) {
    int nn = 0;
    double tf = 0.0, *phi = field_at(out, "phi", s * t_end / 5, &nn, &tf);
    if (!phi || nn != n) {
      free(phi);
      return;
    }
    ts[s] = tf, zs[s] = NAN;
    for (int i = n - 1; i > 0 && isnan(zs[s]); --i) /* the top of the suspension: where phi crosses phi0/2 */
      if (phi[i] < 0.5 * phi0 && phi[i - 1] >= 0.5 * phi0)
        zs[s] = (i - 0.5 + (phi[i - 1] - 0.5 * phi0) / (phi[i - 1] - phi[i])) * H / n;
    for (int i = 0; i < n; ++i) {
      CHECK_MSG(isfinite(phi[i]) && phi[i] >= 0.0, "phi[%d] = %g", i, phi[i]);
      worst_phi = fmax(worst_phi, phi[i]);
    }
    worst_mass = fmax(worst_mass, fabs(scalar(out, "solids_conservation_error", tf)));
    free(phi);
  }
  /* the speed over the last four outputs (the first one is the initial state, no front yet) */
  double st = 0, sz = 0, stt = 0, szt = 0;
  for (int s = 2; s <= 5; ++s) st += ts[s], sz += zs[s], stt += ts[s] * ts[s], szt += ts[s] * zs[s];
  double speed = -(4 * szt - st * sz) / (4 * stt - st * st);
  printf(
      "  stiff: 10 um particles, dt = 1000 tau_p = %.3g s: the suspension top falls at %.4g m/s, Richardson-Zaki "
      "%.4g (%+.2f %%); max phi %.4f, conservation %.1e\n",
      1000 * tau, speed, v, 100 * (speed / v - 1), worst_phi, worst_mass);
  CHECK_MSG(fabs(speed / v - 1) < 0.01, "settling front speed %.4g, Richardson-Zaki %.4g", speed, v);
  CHECK_MSG(worst_phi <= 0.64, "phi %.17g above phi_max", worst_phi);
  CHECK_MSG(worst_mass < 1e-12, "solids conservation error %.3g", worst_mass);
}

/* A dense suspension (phi = 0.5) settling with no solids pressure at all, in steps of 20 s: nothing but the
 * transport's limiter stops the packing, which ends at phi_max exactly, the bed S / phi_max high. Also with
 * the stiff Gidaspow elastic modulus (p_s grows by e^600 per unit phi, its own phi_max 0.62 below the
 * limiter's 0.64) for 400 s at the same steps: the implicit step then often needs retrying smaller, which is
 * slow (13 s of CPU to 4000 s), so the test stops early. */
static void packing(void) {
  const char *sets[] = {
      "initial.phi=0.5", "time.dt=20", "time.end=4000", "output.every=4000", "two_fluid.steady_tolerance=0", NULL};
  const char *sets_short[] = {
      "initial.phi=0.5", "time.dt=20", "time.end=400", "output.every=400", "two_fluid.steady_tolerance=0", NULL};
  const char *out = "packing.h5";
  for (int k = 0; k < 2; ++k) {
    const char *ps = k == 0 ? "" : "[closure.solids_pressure]\nmodel = gidaspow_elastic\nphi_max = 0.62\n";
    sl_diag d = {{0}};
    int rc = run_scene("settled_bed", "closure.solids_pressure", ps, k == 0 ? sets : sets_short, out, &d);
    CHECK_MSG(rc == 0 || (rc == SL_EFAILED && strlen(d.msg) > 0), "packing: rc %d: %s", rc, d.msg);
    if (rc) printf("  packing (%s): stopped cleanly: %s\n", k ? "gidaspow_elastic" : "no p_s", d.msg);
    int n = 0;
    double tf = 0.0, *phi = field_at(out, "phi", INFINITY, &n, &tf);
    if (!phi) continue;
    double top = 0.0, worst = 0.0;
    int bad = 0;
    for (int i = 0; i < n; ++i) {
      bad += !(isfinite(phi[i]) && phi[i] >= 0.0 && phi[i] <= 0.64);
      worst = fmax(worst, phi[i]);
      top += phi[i] * 0.5 / n;
    }
    double err = scalar(out, "solids_conservation_error", tf);
    int full = 0;
    for (int i = 0; i < n; ++i) full += phi[i] >= 0.64 - 1e-12;
    printf("  packing (%s): t = %g s, max phi %.6f, %.4f m of solids, %d cells at phi_max, conservation %.1e\n",
           k ? "gidaspow_elastic" : "no p_s", tf, worst, top, full, err);
    CHECK_MSG(bad == 0, "packing: %d cells outside [0, phi_max] or not finite", bad);
    CHECK_MSG(fabs(err) < 1e-12, "packing: conservation error %.3g", err);
    if (k == 0 && rc == 0) {
      /* S = 0.25 m of solids: 0.25 / 0.64 = 0.3906 m of packed bed, 78.1 cells of 5 mm */
      CHECK_MSG(full == 78, "packing: %d cells at phi_max, expected 78", full);
    }
    free(phi);
  }
}

/* Every output of `out` bounded (0 <= phi <= phi_max, finite velocities) and conserving the solids with the
 * outflow counted; the solids volume per unit area left at the end in *left. 0, or 1 if unreadable. */
static int bounded_and_conserved(const char *out, const char *label, double *left) {
  int ns = 0;
  double *times = NULL;
  sl_diag d = {{0}};
  if (sl_output_read_times(out, &ns, &times, &d)) {
    CHECK_MSG(0, "%s: %s", label, d.msg);
    return 1;
  }
  int bad = 0;
  double worst = 0.0, inv = NAN;
  for (int s = 0; s < ns; ++s) {
    int n = 0, nu = 0;
    double *phi = field_at(out, "phi", times[s], &n, NULL), *us = field_at(out, "velocity_solid", times[s], &nu, NULL);
    if (!phi || !us) {
      free(phi), free(us);
      bad = 1;
      break;
    }
    for (int i = 0; i < n; ++i) bad += !(phi[i] >= 0.0 && phi[i] <= 0.64);
    for (int i = 0; i < nu; ++i) bad += !isfinite(us[i]);
    worst = fmax(worst, fabs(scalar(out, "solids_conservation_error", times[s])));
    inv = scalar(out, "solids_inventory", times[s]);
    free(phi), free(us);
  }
  CHECK_MSG(bad == 0, "%s: %d values outside [0, phi_max] or not finite", label, bad);
  CHECK_MSG(worst < 1e-12, "%s: solids conservation error %.3g (outflow counted)", label, worst);
  *left = inv;
  free(times);
  return 0;
}

/* A step of the inflow far past the particles' terminal velocity blows the bed out of the column through
 * the outlet: the sand of Pringle (2001) section 4.6.1 (terminal velocity 42 mm/s with Rowe's C_D) stepped to
 * 0.5 m/s, at dt = 0.01 s and at dt = 1 s, and to 50 m/s at dt = 1 s (1.6e4 transport sub-steps a step); Slis's 3 mm
 * nylon (terminal 88 mm/s) stepped to 0.5 m/s. Every output bounded and conserving with the outflow counted;
 * at the end no solids left (0.175 m of sand, 0.1265 m of nylon, went out). An inflow that turns into
 * NaN stops the run at once, naming the inlet and the time, the last good state saved and finite. */
static void blow_out(void) {
  const struct {
    const char *scene, *velocity, *dt, *end;
    double solids;
  } runs[] = {
      {"fluidization_step", "boundary.left.velocity=t <= 0 ? 0.0077783 : 0.5", "time.dt=0.01", "time.end=10", 0.175},
      {"fluidization_step", "boundary.left.velocity=t <= 0 ? 0.0077783 : 0.5", "time.dt=1", "time.end=10", 0.175},
      {"fluidization_step", "boundary.left.velocity=t <= 0 ? 0.0077783 : 50", "time.dt=1", "time.end=4", 0.175},
      {"slis_step", NULL, "time.dt=0.01", "time.end=10", 0.275 * 0.46},
  };
  const char *out = "blow_out.h5";
  for (size_t k = 0; k < sizeof runs / sizeof runs[0]; ++k) {
    const char *sets[] = {runs[k].dt,
                          runs[k].end,
                          "output.every=1",
                          "output.fields=phi,velocity_solid",
                          "two_fluid.steady_tolerance=0",
                          runs[k].velocity,
                          NULL};
    const char *inlet = "[boundary.left]\ntype = inlet\nvelocity = t <= 0 ? 0.0111 : 0.5\n";
    sluice_summary res;
    sl_diag d = {{0}};
    scene_request q = {.configs = configs,
                       .scene = runs[k].scene,
                       .replace_section = runs[k].velocity ? NULL : "boundary.left",
                       .replacement = inlet,
                       .sets = sets,
                       .out = out};
    int rc = scene_run(&q, &res, &d);
    CHECK_MSG(rc == 0, "blow-out %s %s: %s", runs[k].scene, runs[k].dt, d.msg);
    double left = NAN;
    if (rc || bounded_and_conserved(out, runs[k].scene, &left)) continue;
    printf("  blow-out %s, %s, %s: solids left %.1e m of %.4f; %s\n", runs[k].scene,
           runs[k].velocity ? runs[k].velocity + 23 : "nylon to 0.5 m/s", runs[k].dt, left, runs[k].solids,
           res.coupling_summary);
    CHECK_MSG(left < 1e-9 * runs[k].solids, "blow-out %s: %.3g m of solids left in the column", runs[k].scene, left);
  }
  const char *nan_sets[] = {"boundary.left.velocity=t <= 0 ? 0.0077783 : t > 2 ? log(-1) : 0.5", "time.dt=0.1",
                            "time.end=10", "output.every=1", NULL};
  sl_diag d = {{0}};
  int rc = run_scene("fluidization_step", NULL, NULL, nan_sets, out, &d);
  printf("  blow-out with a NaN inflow from t = 2: %s\n", d.msg);
  CHECK_MSG(rc == SL_EFAILED && strstr(d.msg, "inlet velocity is not a finite number") && strstr(d.msg, "t = 2"),
            "NaN inflow: rc %d, %s", rc, d.msg);
  double left;
  bounded_and_conserved(out, "NaN inflow", &left);
}

/* A column run continued from its checkpoint ends bit for bit where the
 * uninterrupted run does (phi, both velocities, the pressure). */
static void restart(void) {
  const char *full[] = {"time.end=2", "time.dt=0.05", "output.every=1", NULL};
  const char *half[] = {"time.end=1", "time.dt=0.05", "output.every=1", NULL};
  if (run_ok("fluidization_step", NULL, NULL, full, "tf_full.h5") ||
      run_ok("fluidization_step", NULL, NULL, half, "tf_half.h5"))
    return;
  sl_diag d = {{0}};
  scene_request q = {
      .configs = configs, .scene = "fluidization_step", .sets = full, .out = "tf_cont.h5", .restart = "tf_half.h5"};
  int rc = scene_run(&q, NULL, &d);
  CHECK_MSG(rc == 0, "restart: %s", d.msg);
  const char *fields[4] = {"phi", "velocity_solid", "velocity_fluid", "pressure"};
  for (int f = 0; f < 4 && rc == 0; ++f) {
    int n = 0, m = 0;
    double *a = field_at("tf_full.h5", fields[f], 2.0, &n, NULL), *b = field_at("tf_cont.h5", fields[f], 2.0, &m, NULL);
    CHECK_MSG(a && b && n == m && memcmp(a, b, (size_t)n * sizeof *a) == 0, "restart: %s differs", fields[f]);
    free(a), free(b);
  }
}

static void bad_input(void) {
  sl_diag d = {{0}};
  const char *sets[] = {"scene.geometry=planar", NULL};
  int rc = run_scene("settled_bed", NULL, NULL, sets, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[scene] geometry = planar needs a 2-D mesh"), "message: %s", d.msg);
  const char *sets2[] = {"initial.phi=0.7", NULL};
  rc = run_scene("settled_bed", NULL, NULL, sets2, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, ":0: [initial] phi = 0.7 at x = 0.0025") && strstr(d.msg, "phi_max = 0.64"), "message: %s",
            d.msg);
  const char *sets3[] = {"boundary.left.type=inlet", "boundary.left.velocity=0.01", NULL};
  rc = run_scene("settled_bed", NULL, NULL, sets3, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "needs an outlet"), "message: %s", d.msg);
  /* the inlet: velocity or porosity, one of them; a porosity holds a bed only in (1 - phi_max, 1] */
  const char *sets4[] = {"boundary.left.velocity=0.01", NULL};
  rc = run_scene("slis_step", NULL, NULL, sets4, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "slis_step.ini:") && strstr(d.msg, "[boundary.left]") && strstr(d.msg, "not both"),
            "message: %s", d.msg);
  rc = run_scene("fluidization_step", "boundary.left", "[boundary.left]\ntype = inlet\nporosity = 0.3\n", NULL,
                 "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "fluidization_step.ini:") && strstr(d.msg, "[boundary.left] porosity") &&
                strstr(d.msg, "inlet porosity is 0.3 at t = 0") && strstr(d.msg, "phi_max = 0.64"),
            "message: %s", d.msg);
  const char *sets5[] = {"two_fluid.case=13", NULL};
  rc = run_scene("slis_step", NULL, NULL, sets5, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[initial] porosity = -1"), "message: %s", d.msg);
  const char *sets6[] = {"output.interface=0.9", NULL};
  rc = run_scene("settling_illite", NULL, NULL, sets6, "bad.h5", &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strstr(d.msg, "[output] interface = 0.9") && strstr(d.msg, "phi_max = 0.64"), "message: %s", d.msg);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  quick = getenv("SLUICE_SKIP_LONG") != NULL;
  fluidized_bed();
  settled_bed();
  fluidization_step();
  settling_illite();
  slis_step();
  stiff_fine_particles();
  packing();
  blow_out();
  restart();
  bad_input();
  return sl_test_summary();
}
