/* SPDX-License-Identifier: GPL-2.0-or-later */
/* configs/liquefaction.ini: a sand deposit built by settling in the 1-D
 * two-fluid column, shaken at its base by the synthetic 6 s record, run to
 * 3 minutes (Pringle 2001, thesis sections 5.4-5.5). Checked:
 * - the deposit at rest: the discrete effective-stress balance face by face,
 *   the pore pressure hydrostatic but for the weight of the surface cell's
 *   solids, which the column's scheme holds on the fluid; the total vertical
 *   stress p + p_s of the base cell against the weight of the column above
 *   it; solids and fluid conserved to round-off over settling, shaking and
 *   consolidation;
 * - the undrained load transfer: a uniform drop of nbar at t = 0 puts
 *   1 - exp(-dnbar/(A phi)) of each cell's p_s0 on the fluid (Pringle's eq
 *   4.30 at fixed phi); the onset criterion (excess = 0.95 p_s0) is reached
 *   at the drop dnbar = A phi ln 20 the law predicts;
 * - the base case (0.8 mm): onset (ratio >= 0.95) first at an intermediate
 *   depth, neither at the surface nor at the base; the liquefied zone grows
 *   after onset; settlement of the order of 3 % of the depth; a small excess
 *   left at the base at 3 minutes; no step cut;
 * - configs/terzaghi_consolidation.ini: the degree of consolidation (from
 *   the solids inventory) and the base excess pore pressure against
 *   Terzaghi's series, first order in h (the drained surface is resolved to
 *   a cell);
 * - the horizontal equation: the steady response of a uniform linear
 *   elastic layer to a harmonic base, second order in h;
 * - 0.08 mm: a thicker liquefied zone at 6 s; configs/liquefaction_gravel.ini (8 mm, K2max from the gravel range):
 *   the pore pressure ratio below 0.95 everywhere at all times;
 * - the settlement during the shaking within the drainage bound of the surface layer (Ergun 1952), and the base
 *   excess after the shaking within the maximum at its end (no densification after it: maximum principle), and
 *   only the bottom layers able to carry the base's peak;
 * - free vibration: a linear elastic column's period against 4H/V_s and its logarithmic decrement against 2 pi
 *   zeta of the stated damping, none without it (the integrator does not damp); the base case's free vibration
 *   after the shaking against the discrete column's fundamental and the stated damping. */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench/png_check.h"
#include "core/study/chart.h"
#include "scene_fields.h"
#include "scene_runner.h"
#include "testing.h"

static char configs[4096];
SCENE_RUNNERS()

static const double g = 9.81, rho_s = 2650.0, rho_f = 1000.0, A = 0.015;

/* The Terzaghi deposit at rest (no drop): the discrete effective-stress balance p_s(i-1) - p_s(i) = h phi_{i-1}
 * (rho_s - rho_f) g at every face inside the deposit (two_fluid_plane_step.c: a face takes its gravity-side cell's
 * phi), and the pore pressure hydrostatic but for the surface cell, whose solids the column holds on the fluid
 * (its face to the clear water carries them by drag; the scheme's surface cell, docs/liquefaction.md): a
 * uniform static excess equal to their buoyant weight. */
static void at_rest(void) {
  const char *sets[] = {"deposit.nbar_drop=0", "time.end=0.1", "output.every=0.1", NULL};
  if (run_ok("terzaghi_consolidation", NULL, NULL, sets, "test_liquefaction_rest.h5")) return;
  int n;
  double *phi = field_at("test_liquefaction_rest.h5", "phi", INFINITY, &n, NULL);
  double *ps = field_at("test_liquefaction_rest.h5", "solids_pressure", INFINITY, &n, NULL);
  double *p = field_at("test_liquefaction_rest.h5", "pressure", INFINITY, &n, NULL);
  if (!phi || !ps || !p) return;
  const double h = 12.0 / n, dr = (rho_s - rho_f) * g;
  int top = 0;
  while (top < n && phi[top] > 0.3) ++top;
  double worst = 0.0;
  for (int i = 1; i < top - 1; ++i) worst = fmax(worst, fabs(ps[i - 1] - ps[i] - h * phi[i - 1] * dr) / ps[0]);
  double excess = scalar("test_liquefaction_rest.h5", "base_static_excess_pressure", INFINITY);
  double held = h * phi[top - 1] * dr, hydro_top = p[n - 1];
  printf(
      "  at rest: effective-stress balance at every face within %.2e of p_s(base) = %.1f Pa; static excess %.2f Pa "
      "= the surface cell's buoyant weight %.2f Pa (%.2e); top pressure %.3g Pa\n",
      worst, ps[0], excess, held, fabs(excess - held) / held, hydro_top);
  CHECK_MSG(worst < 1e-6, "effective-stress balance off by %g", worst);
  CHECK_MSG(fabs(excess - held) < 1e-3 * held, "static excess %g, surface cell %g", excess, held);
  free(phi), free(ps), free(p);
}

static void at_rest_and_conservation(const char *out) {
  int n;
  double *phi = field_at(out, "phi", 0.0, &n, NULL), *p = field_at(out, "pressure", 0.0, &n, NULL);
  double *ps = field_at(out, "solids_pressure", 0.0, &n, NULL);
  if (!phi || !p || !ps) return;
  const double h = 17.0 / n;
  double w = 0.5 * h * (phi[0] * rho_s + (1.0 - phi[0]) * rho_f) * g;
  for (int i = 1; i < n; ++i) w += h * (phi[i] * rho_s + (1.0 - phi[i]) * rho_f) * g;
  double total = p[0] + ps[0], err = (total - w) / w;
  printf("  at rest: base cell p + p_s = %.1f Pa, weight above %.1f Pa (%.2e); p_s %.1f Pa\n", total, w, err, ps[0]);
  CHECK_MSG(fabs(err) < 5e-3, "total vertical stress off the weight by %.3g", err); /* 68 cells: 4.3e-3 */
  double es = scalar(out, "solids_conservation_error", INFINITY),
         ef = scalar(out, "fluid_conservation_error", INFINITY);
  printf("  conservation at 186 s: solids %.2e, fluid %.2e\n", es, ef);
  CHECK_MSG(fabs(es) < 1e-13 && fabs(ef) < 1e-13, "conservation %g %g", es, ef);
  free(phi), free(p), free(ps);
}

/* The depth-time history of the pore pressure ratio: its first output with ratio >= 0.95 per cell. */
static void base_case(const char *out) {
  double H = scalar(out, "deposit_height", 0.0), t_on = scalar(out, "onset_time", INFINITY);
  double z_on = scalar(out, "onset_depth", INFINITY);
  printf("  base case: deposit %.2f m, onset at t = %.2f s, depth %.3f m (%.2f H)\n", H, t_on, z_on, z_on / H);
  CHECK_MSG(isfinite(t_on) && t_on < 6.0, "no onset during the shaking (%g)", t_on);
  CHECK_MSG(z_on > 0.2 * H && z_on < 0.8 * H, "onset at depth %g of %g: not intermediate", z_on, H);
  /* the surface cell and the base cell never reach 0.95 (the model's step-by-step maxima) */
  double surf = scalar(out, "surface_cell_ratio_max", INFINITY), base = scalar(out, "base_cell_ratio_max", INFINITY);
  double thick_on = scalar(out, "liquefied_thickness_at_onset", INFINITY);
  double thick_max = scalar(out, "liquefied_thickness_max_shaking", INFINITY);
  printf(
      "  largest ratio in the surface cell %.3f, in the base cell %.3f; liquefied %.2f m at onset, %.2f m at most "
      "during shaking\n",
      surf, base, thick_on, thick_max);
  CHECK_MSG(surf < 0.95 && base < 0.95, "surface %g or base %g liquefied", surf, base);
  CHECK_MSG(thick_max > thick_on, "the liquefied zone did not grow after onset (%g -> %g)", thick_on, thick_max);
  double s6 = scalar(out, "settlement", 6.0), s_end = scalar(out, "settlement", INFINITY);
  printf("  settlement %.3f m at 6 s, %.3f m at 186 s (%.2f %% of the depth; thesis: nearly 40 cm, about 3 %%)\n", s6,
         s_end, 100.0 * s_end / H);
  CHECK_MSG(s_end > 0.01 * H && s_end < 0.05 * H, "settlement %g m of %g", s_end, H);
  double peak = scalar(out, "base_excess_pressure_peak", INFINITY);
  double t_peak = scalar(out, "base_excess_pressure_peak_time", INFINITY);
  double left = scalar(out, "base_excess_pressure", INFINITY);
  printf("  base excess pore pressure: peak %.0f Pa at %.1f s, %.0f Pa (%.2f %%) left at 186 s\n", peak, t_peak, left,
         100.0 * left / peak);
  CHECK_MSG(left > 0.0 && left < 0.05 * peak, "base excess at 3 min %g (peak %g)", left, peak);
}

/* configs/liquefaction_gravel.ini (8 mm, K2max = 80 from the gravel range of Seed et al. 1986): the thesis's
 * gravel does not liquefy. The model's step-by-step largest pore pressure ratio over every deposit cell and every
 * step (max_pore_pressure_ratio) stays below the onset ratio 0.95, and no onset is recorded. */
static void variants(const char *base) {
  const char *fine_sets[] = {"solid.diameter=8e-5", "deposit.settle=400000", "deposit.settle_dt=50", NULL};
  if (run_ok("liquefaction", NULL, NULL, fine_sets, "test_liquefaction_fine.h5")) return;
  if (run_ok("liquefaction_gravel", NULL, NULL, NULL, "test_liquefaction_gravel.h5")) return;
  double tb = scalar(base, "liquefied_thickness", 6.0),
         tf = scalar("test_liquefaction_fine.h5", "liquefied_thickness", 6.0);
  const char *gr = "test_liquefaction_gravel.h5";
  double rg = scalar(gr, "max_pore_pressure_ratio", INFINITY),
         zg = scalar(gr, "max_pore_pressure_ratio_depth", INFINITY);
  double tg = scalar(gr, "liquefied_thickness_max_shaking", INFINITY), on = scalar(gr, "onset_time", INFINITY);
  printf(
      "  liquefied at 6 s: 0.8 mm %.2f m, 0.08 mm %.2f m; 8 mm gravel (K2max 80): largest ratio %.3f (at %.2f m "
      "depth), onset %g, P_s below 5 %% of P_s0 over %.2f m (the cell the surface settles into)\n",
      tb, tf, rg, zg, on, tg);
  CHECK_MSG(tf > tb, "0.08 mm liquefied %g m, not more than 0.8 mm's %g m", tf, tb);
  CHECK_MSG(rg < 0.95 && isnan(on), "8 mm gravel liquefies: largest pore pressure ratio %g, onset %g", rg, on);
}

/* Ergun's minimum-fluidisation relative flux q (m/s) of a layer at porosity e under `w` times its solids' buoyant
 * weight, in the model's drag (Pringle 2001 eq 3.12, Ergun 1952 with the printed 1/n on the inertial term; the
 * column's steady bed has K V_r = phi e (rho_s - rho_f) g, plugins/drag/pringle.c), with V_r = q/e:
 *   150 phi mu q / (e^3 d^2) + 1.75 rho_f q^2 / (e^4 d) = w (rho_s - rho_f) g,
 * the positive root of the quadratic. */
static double ergun_umf(double e, double w, double d, double mu) {
  double a = 150.0 * (1.0 - e) * mu / (e * e * e * d * d), b = 1.75 * rho_f / (e * e * e * e * d);
  double c = w * (rho_s - rho_f) * g;
  return 2.0 * c / (a + sqrt(a * a + 4.0 * b * c));
}

/* The settlement during the shaking against the most the 1-D column can drain through its surface layer.
 * Derivation. Both ends of the column are closed and both phases incompressible, so the mixture flux
 * phi v_s + (1 - phi) v_f vanishes at every face and the relative (superficial) flux q = (1 - phi)(v_f - v_s)
 * equals -v_s: the water leaving the deposit upwards is the solids' descent. Integrate the quasi-static solids
 * momentum balance from the free surface (P_s = 0) down to the bottom face of the deposit's top full cell
 * (the highest with phi >= [deposit] phi_min = 0.3): P_s there = (buoyant weight of the solids above) - (drag on
 * them) >= 0. The drag is upward everywhere (the water rises), so the drag on the top full cell alone is at most
 * w times its solids' buoyant weight, w = 1 + (solids of the partly filled cells above)/(its own solids): q in
 * that cell is at most Ergun's minimum-fluidisation flux ergun_umf(e, w) at its porosity e. The surface height
 * (the solids inventory, liquefaction.c surface_height) counts the solids above that cell at the reference
 * fraction 1 - nbar = 0.5 it was built with, and they leave it at most at phi q through its top face, so
 *   d(settlement)/dt <= phi_top ergun_umf(e_top, w) / (1 - nbar).
 * The bound is evaluated at every output of the shaking (0.5 s apart) from the run's own phi, and the largest
 * rate times the 6 s bounds the settlement at 6 s. With w = 1 and e = 0.434 (the top cell at t = 0) Ergun gives
 * 7.7 mm/s for 0.8 mm sand in water (d = 0.8 mm, mu = 1e-3 Pa s, 1000 and 2650 kg/m3), at most 0.046 m of
 * surface descent in 6 s: the thesis's "a little more than half" of about 0.43 m cannot drain in the shaking's 6 s
 * through a surface layer that is not fluidised. Also checked at each output: the solids' descent at the top
 * face of that cell, q, against the bound. */
static void settlement_bound(const char *out) {
  const double d = 8e-4, mu = 1e-3, nbar_ref = 0.5, phi_min = 0.3, T = 6.0;
  double rate_max = 0.0, q_ratio_max = 0.0, umf0 = NAN, e0 = NAN;
  for (int k = 0; k <= 12; ++k) {
    int n, nv;
    double *phi = field_at(out, "phi", 0.5 * k, &n, NULL), *vs = field_at(out, "velocity_solid", 0.5 * k, &nv, NULL);
    if (!phi || !vs || nv != n + 1) {
      CHECK_MSG(0, "settlement bound: fields at %g s", 0.5 * k);
      free(phi), free(vs);
      return;
    }
    int top = n - 1;
    while (top > 0 && phi[top] < phi_min) --top;
    double above = 0.0;
    for (int i = top + 1; i < n; ++i) above += phi[i];
    double e = 1.0 - phi[top], w = 1.0 + above / phi[top], umf = ergun_umf(e, w, d, mu);
    double rate = phi[top] * umf / (1.0 - nbar_ref);
    if (k == 0) umf0 = ergun_umf(e, 1.0, d, mu), e0 = e;
    rate_max = fmax(rate_max, rate);
    double q = -vs[top + 1];
    q_ratio_max = fmax(q_ratio_max, q / umf);
    CHECK_MSG(q <= umf, "t = %g s: the top cell passes %g m/s, above Ergun's %g m/s", 0.5 * k, q, umf);
    free(phi), free(vs);
  }
  double s6 = scalar(out, "settlement", T), s_end = scalar(out, "settlement", INFINITY);
  printf(
      "  settlement during shaking: %.4f m (%.1f %% of %.3f m); Ergun's U_mf of the top layer at t = 0 (porosity "
      "%.3f) %.2f mm/s, %.3f m in 6 s (%.0f %%); bound from the run's state %.2f mm/s, %.3f m; top-face flux at "
      "most %.2f of its bound\n",
      s6, 100.0 * s6 / s_end, s_end, e0, 1e3 * umf0, T * umf0, 100.0 * T * umf0 / s_end, 1e3 * rate_max, T * rate_max,
      q_ratio_max);
  CHECK_MSG(s6 <= T * rate_max, "settlement %g m during the shaking, above the drainage bound %g m", s6, T * rate_max);
}

/* The base pore pressure after the shaking. Once densification has stopped (nbar changes by under 1e-9 in every cell
 * from the end of the shaking on: Byrne's increment for the free vibration that follows, surface amplitude under
 * 1 mm, is all but nothing after the shaking's accumulated volumetric strain), the excess pore pressure obeys a consolidation
 * equation without a source, (1/M) du/dt = d/dz (k/mu du/dz), drained at the surface, impermeable at the base.
 * Its maximum over the deposit cannot grow (maximum principle), so the base excess after the shaking stays at or
 * below the largest excess over the deposit at its end, plus what the remaining change of nbar can put on the fluid
 * undrained (eq 4.30 at fixed phi: P_s0 dnbar / (A phi), with phi >= 0.3 and P_s0 at most the base's): a base peak after the shaking needs a source after it
 * (the thesis: "because the deposit keeps oscillating"). */
static void base_after_shaking(const char *out) {
  int n, n2;
  double *nb6 = field_at(out, "nbar", 6.0, &n, NULL), *nbe = field_at(out, "nbar", INFINITY, &n2, NULL);
  double *u6 = field_at(out, "excess_pressure", 6.0, &n2, NULL);
  if (!nb6 || !nbe || !u6) {
    free(nb6), free(nbe), free(u6);
    return;
  }
  double dn = 0.0, umax = -INFINITY;
  int imax = 0;
  for (int i = 0; i < n; ++i) {
    dn = fmax(dn, fabs(nbe[i] - nb6[i]));
    if (u6[i] > umax) umax = u6[i], imax = i;
  }
  double worst = -INFINITY, t_peak = scalar(out, "base_excess_pressure_peak_time", INFINITY);
  sl_output_scalars all;
  sl_diag d = {{0}};
  if (sl_output_read_scalars(out, &all, &d)) {
    CHECK_MSG(0, "base after shaking: %s", d.msg);
    free(nb6), free(nbe), free(u6);
    return;
  }
  int col = -1;
  for (int j = 0; j < all.n_names; ++j)
    if (strcmp(all.names[j], "base_excess_pressure") == 0) col = j;
  for (int k = 0; k < all.n_times && col >= 0; ++k)
    if (all.times[k] > 6.0 + 1e-9) worst = fmax(worst, all.values[(size_t)k * all.n_names + col]);
  sl_output_scalars_free(&all);
  CHECK_MSG(col >= 0, "no base_excess_pressure");
  printf(
      "  after the shaking: nbar changes by %.1e; largest excess at 6 s %.0f Pa (cell %d); base excess after 6 s at "
      "most %.0f Pa; its peak at %.2f s, %s the shaking\n",
      dn, umax, imax, worst, t_peak, t_peak <= 6.0 ? "during" : "after");
  double src = 0.0, *ps = field_at(out, "solids_pressure", 0.0, &n2, NULL);
  if (ps) src = ps[0] * dn / (A * 0.3), free(ps);
  printf("  after the shaking: the remaining change of nbar can add at most %.1e Pa undrained\n", src);
  /* Where densification after the shaking could still raise the base above its peak U: the excess of a cell never
   * exceeds max_pore_pressure_ratio (below 1: P_s >= 0 and the overburden at a fixed height only falls as the
   * solids settle) times its P_s0, so the cells k* and above, whose P_s0 is below U / ratio, can never carry U. If
   * nothing densifies in cells 0 .. k*-1 after 6 s, the maximum principle on them bounds the base by the larger of
   * their largest excess at 6 s and the most cell k* can carry, ratio x P_s0(k*): the upper layers' load transfer,
   * diffusing down, cannot make a later base peak. */
  double ru_max = scalar(out, "max_pore_pressure_ratio", INFINITY),
         *ps0 = field_at(out, "solids_pressure", 0.0, &n2, NULL);
  double peak = scalar(out, "base_excess_pressure_peak", INFINITY), h = 17.0 / n, ulow = -INFINITY;
  int ks = 0;
  while (ps0 && ks < n && ru_max * ps0[ks] >= peak) ulow = fmax(ulow, u6[ks]), ++ks;
  if (ps0) {
    double bound = fmax(ulow, ru_max * ps0[ks]);
    printf(
        "  after the shaking: excess at most %.3f P_s0 anywhere; only cells below %.2f m above the base (%d, P_s0 > "
        "%.0f Pa) can carry the base peak %.0f Pa; without densification there after 6 s the base stays below %.0f "
        "Pa (their excess at 6 s at most %.0f Pa, cell %d at most %.0f Pa)\n",
        ru_max, ks * h, ks, peak / ru_max, peak, bound, ulow, ks, ru_max * ps0[ks]);
    CHECK_MSG(ru_max < 1.0 && bound < peak, "upper-layer bound %g against the base peak %g", bound, peak);
    free(ps0);
  }
  CHECK_MSG(dn < 1e-9, "nbar changed by %g after the shaking", dn);
  CHECK_MSG(imax == 0, "the largest excess at 6 s is in cell %d, not at the base", imax);
  CHECK_MSG(worst <= umax + src + 1e-9 * umax, "base excess %g after the shaking, above the maximum %g at its end",
            worst, umax);
  free(nb6), free(nbe), free(u6);
}

/* A uniform drop of nbar at t = 0, no shaking: after 0.2 s the excess of each deposit cell against Pringle's
 * undrained transfer 1 - exp(-dnbar/(A phi)); with dnbar = A phi_c ln 20 cell c is at the onset ratio 0.95. */
static void undrained_transfer(const char *base) {
  int n;
  double *phi = field_at(base, "phi", 0.0, &n, NULL);
  if (!phi) return;
  const int c = 20;
  double drop = A * phi[c] * log(20.0);
  char set_drop[128];
  snprintf(set_drop, sizeof set_drop, "deposit.nbar_drop=%.17g", drop);
  /* 0.2 s: long after the solids' drag relaxation rho_s phi / K (about 8 ms), short of drainage below 2.5 m */
  const char *sets[] = {set_drop, "deposit.nbar_min=0.3", "time.end=0.2", "time.dt=1e-3", "output.every=0.2", NULL};
  if (run_ok("liquefaction", "shaking", "[shaking]\nrecord = \"\"\n", sets, "test_liquefaction_drop.h5")) {
    free(phi);
    return;
  }
  double *ru = field_at("test_liquefaction_drop.h5", "pore_pressure_ratio", INFINITY, &n, NULL);
  if (!ru) {
    free(phi);
    return;
  }
  double worst = 0.0;
  for (int i = 2; i <= 40; ++i) worst = fmax(worst, fabs(ru[i] - (1.0 - exp(-drop / (A * phi[i])))));
  printf(
      "  undrained transfer after 0.2 s: cell %d ratio %.5f (onset 0.95 at dnbar = A phi ln 20 = %.5f); largest "
      "deviation from 1 - exp(-dnbar/(A phi)) %.2e\n",
      c, ru[c], drop, worst);
  CHECK_MSG(fabs(ru[c] - 0.95) < 1e-3, "ratio %g at the predicted onset drop", ru[c]);
  CHECK_MSG(worst < 2e-3, "undrained transfer off by %g", worst);
  free(phi), free(ru);
}

/* Terzaghi (1925): u/u0 = sum (2/M) sin(M Z) exp(-M^2 T), U = 1 - sum (2/M^2) exp(-M^2 T), M = pi (2m+1)/2. */
static double terzaghi_u(double Z, double T) {
  double s = 0.0;
  for (int m = 0; m < 2000; ++m) {
    double M = M_PI * (2 * m + 1) / 2.0;
    s += 2.0 / M * sin(M * Z) * exp(-M * M * T);
  }
  return s;
}
static double terzaghi_U(double T) {
  double s = 0.0;
  for (int m = 0; m < 2000; ++m) {
    double M = M_PI * (2 * m + 1) / 2.0;
    s += 2.0 / (M * M) * exp(-M * M * T);
  }
  return 1.0 - s;
}

/* configs/terzaghi_consolidation.ini on `cells`: the largest errors of U and of the base cell's u/u0 over the
 * outputs 0.25 ... 5 s (T = 0.05 ... 1). */
static int terzaghi_run(int cells, double *eU, double *eu) {
  char set_cells[64];
  snprintf(set_cells, sizeof set_cells, "mesh.cells=%d", cells);
  const char *sets[] = {set_cells, NULL};
  if (run_ok("terzaghi_consolidation", NULL, NULL, sets, "test_liquefaction_terzaghi.h5")) return 1;
  /* c_v = M phibar (1 - phi)^3 d^2 / (150 mu phi^3) at phi = phibar = 0.55 (Ergun's viscous drag) */
  const double M = 1e9, phib = 0.55, d_p = 1e-4, mu = 1e-3, H = 10.0, dn = 1e-7;
  const double cv = M * phib * pow(1.0 - phib, 3) * d_p * d_p / (150.0 * mu * pow(phib, 3));
  const double u0 = M * dn / phib, S_inf = H * dn / (phib + dn), h = 12.0 / cells;
  *eU = *eu = 0.0;
  for (int k = 1; k <= 20; ++k) {
    double t = 0.25 * k, T = cv * t / (H * H);
    double S = scalar("test_liquefaction_terzaghi.h5", "settlement", t);
    double ub = scalar("test_liquefaction_terzaghi.h5", "base_excess_pressure", t);
    *eU = fmax(*eU, fabs(S / S_inf - terzaghi_U(T)));
    *eu = fmax(*eu, fabs(ub / u0 - terzaghi_u(1.0 - 0.5 * h / H, T)));
  }
  return 0;
}

static void terzaghi(void) {
  double eU[3], eu[3];
  const int cells[3] = {24, 48, 96};
  for (int k = 0; k < 3; ++k)
    if (terzaghi_run(cells[k], &eU[k], &eu[k])) return;
  for (int k = 0; k < 3; ++k)
    printf("  terzaghi, %3d cells (h = %.3f m): max |U - U_series| %.2e, max |u_base/u0 - series| %.2e\n", cells[k],
           12.0 / cells[k], eU[k], eu[k]);
  double pU = log2(eU[1] / eU[2]), pu = log2(eu[1] / eu[2]);
  printf("  terzaghi: observed order %.2f (U), %.2f (base pore pressure)\n", pU, pu);
  CHECK_MSG(eU[2] < 1.2e-2 && eu[2] < 7e-3, "Terzaghi errors %g %g on 96 cells", eU[2], eu[2]);
  CHECK_MSG(pU > 0.9 && pu > 0.9 && log2(eU[0] / eU[1]) > 0.9, "Terzaghi order %g %g", pU, pu);
}

/* The depth-time map of the pore pressure ratio over the first 30 s (every output, 0.5 s) as a heat-map panel
 * with a colour bar: liquefaction_ratio.svg and .png; and the base excess pore pressure and the settlement over
 * the run as a figure of two panels: liquefaction_history.png and .svg (core/study/chart.h). The PNGs are read
 * back by the PNG checker. */
static void pictures(const char *out) {
  enum { NT = 61 };
  int n;
  double *ru0 = field_at(out, "pore_pressure_ratio", 0.0, &n, NULL);
  if (!ru0) return;
  free(ru0);
  double H = scalar(out, "deposit_height", 0.0), h = 17.0 / n;
  int cells = (int)floor(H / h + 0.5);
  double te[NT + 1], *ze = malloc((size_t)(cells + 1) * sizeof *ze), *map = malloc((size_t)cells * NT * sizeof *map);
  CHECK(ze && map);
  if (!ze || !map) {
    free(ze), free(map);
    return;
  }
  /* output k (t = 0.5 k) in a column centred on its time, the first and last cut at 0 and 30 s */
  for (int k = 0; k <= NT; ++k) te[k] = k == 0 ? 0.0 : k == NT ? 0.5 * (NT - 1) : 0.5 * k - 0.25;
  for (int i = 0; i <= cells; ++i) ze[i] = i * h; /* height above the base */
  for (int k = 0; k < NT; ++k) {
    double *ru = field_at(out, "pore_pressure_ratio", 0.5 * k, &n, NULL);
    for (int i = 0; i < cells; ++i) map[(size_t)i * NT + (size_t)k] = ru && i < n ? ru[i] : NAN;
    free(ru);
  }
  sl_chart_heatmap hm = {.nx = NT,
                         .ny = cells,
                         .x_edges = te,
                         .y_edges = ze,
                         .values = map,
                         .lo = 0.0,
                         .hi = 1.0,
                         .label = "pore pressure ratio (p \xE2\x88\x92 p_{0})/p'_{s0}"};
  sl_chart c = {.xlabel = "time t (s); shaking 0 to 6 s",
                .ylabel = "height above the base z (m)",
                .legend = SL_LEGEND_NONE,
                .heatmap = &hm};
  sl_figure fig = {.title = "liquefaction.ini: 0.8 mm sand, 6 s of shaking",
                   .subtitle = "pore pressure ratio over the deposit, every output (0.5 s)",
                   .n_panels = 1,
                   .panels = &c,
                   .panel_width = 640,
                   .panel_height = 360};
  sl_diag d = {{0}};
  int rc = sl_figure_write_svg("liquefaction_ratio.svg", &fig, &d);
  CHECK_MSG(rc == 0, "liquefaction_ratio.svg: %s", d.msg);
  rc = sl_figure_write_png("liquefaction_ratio.png", &fig, &d);
  CHECK_MSG(rc == 0, "liquefaction_ratio.png: %s", d.msg);
  free(ze), free(map);
  int w, hh;
  unsigned char *rgb = NULL;
  const char *why = png_check_file("liquefaction_ratio.png", &w, &hh, &rgb);
  CHECK_MSG(why == NULL, "liquefaction_ratio.png: %s", why ? why : "");
  free(rgb);
  /* the history chart */
  enum { NH = 94 };
  double t[NH], pb[NH], st[NH];
  for (int k = 0; k < NH; ++k) {
    t[k] = 2.0 * k;
    pb[k] = 1e-3 * scalar(out, "base_excess_pressure", fmin(t[k], 186.0));
    st[k] = 100.0 * scalar(out, "settlement", fmin(t[k], 186.0)); /* cm */
  }
  /* two panels: each quantity on its own axis, in its own unit */
  sl_chart_series se[2] = {
      {.n = NH, .x = t, .y = pb, .marker_every = 8},
      {.n = NH, .x = t, .y = st, .marker_every = 8, .colour = "#D62728", .marker = SL_CHART_MARK_SQUARE}};
  sl_chart panels[2] = {{.title = "base excess pore pressure",
                         .xlabel = "time t (s)",
                         .ylabel = "excess pore pressure u_{e} (kPa)",
                         .n_series = 1,
                         .series = &se[0],
                         .legend = SL_LEGEND_NONE},
                        {.title = "surface settlement",
                         .xlabel = "time t (s)",
                         .ylabel = "settlement (cm)",
                         .n_series = 1,
                         .series = &se[1],
                         .legend = SL_LEGEND_NONE}};
  sl_figure ch = {.title = "liquefaction.ini: 0.8 mm sand, 6 s of shaking",
                  .subtitle = "from the solids inventory and the fluid pressure over its pre-shaking value",
                  .n_panels = 2,
                  .panels = panels,
                  .columns = 2,
                  .panel_width = 400,
                  .panel_height = 320};
  rc = sl_figure_write_svg("liquefaction_history.svg", &ch, &d);
  CHECK_MSG(rc == 0, "liquefaction_history.svg: %s", d.msg);
  rc = sl_figure_write_png("liquefaction_history.png", &ch, &d);
  CHECK_MSG(rc == 0, "liquefaction_history.png: %s", d.msg);
  why = png_check_file("liquefaction_history.png", &w, &hh, &rgb);
  CHECK_MSG(why == NULL, "liquefaction_history.png: %s", why ? why : "");
  free(rgb);
  printf("  pictures: liquefaction_ratio.png (depth-time map), liquefaction_history.png\n");
}

/* The horizontal equation against the exact steady response of a uniform Kelvin-Voigt layer on a harmonic base
 * (the Terzaghi deposit at rest made linear elastic: [shaking] shear_modulus = 1e7 Pa, damping xi = 0.05 at 2 Hz,
 * eta = 2 xi G / omega_d): the base moves with a = a0 sin(omega t), the surface relative to it by
 * w = (a0/omega^2) |1/cos(k* H) - 1|, k* = omega sqrt(rho/(G + i omega eta)) (Kramer 1996, Geotechnical
 * Earthquake Engineering, eq 7.21 with the base's own motion taken out). The amplitude of w over 25-30 s
 * (the start's free vibration decayed by e^-13) by least squares, on 10, 20, 40 cells of the deposit. */
static double harmonic_run(int cells, const char *record) {
  char s_cells[64], s_rec[2400];
  snprintf(s_cells, sizeof s_cells, "mesh.cells=%d", cells);
  snprintf(s_rec, sizeof s_rec, "shaking.record=%s", record);
  const char *sets[] = {s_cells,
                        s_rec,
                        "deposit.nbar_drop=0",
                        "shaking.units=si",
                        "shaking.shear_modulus=1e7",
                        "time.end=30",
                        "time.dt=0.00125",
                        "output.every=0.01",
                        NULL};
  if (run_ok("terzaghi_consolidation", NULL, NULL, sets, "test_liquefaction_harmonic.h5")) return NAN;
  const double om = 2.0 * M_PI, G = 1e7, eta = 2.0 * 0.05 * G / (2.0 * M_PI * 2.0), H = 10.0, a0 = 0.01;
  double ss = 0, sc = 0, cc = 0, ws = 0, wc = 0;
  sl_output_scalars all;
  sl_diag d = {{0}};
  if (sl_output_read_scalars("test_liquefaction_harmonic.h5", &all, &d)) {
    CHECK_MSG(0, "harmonic: %s", d.msg);
    return NAN;
  }
  int col = -1;
  for (int j = 0; j < all.n_names; ++j)
    if (strcmp(all.names[j], "surface_displacement") == 0) col = j;
  for (int k = 0; k < all.n_times && col >= 0; ++k) {
    double t = all.times[k], w = all.values[(size_t)k * all.n_names + col];
    if (t < 25.0 - 1e-9) continue;
    double sn = sin(om * t), cs = cos(om * t);
    ss += sn * sn, sc += sn * cs, cc += cs * cs, ws += w * sn, wc += w * cs;
  }
  sl_output_scalars_free(&all);
  CHECK_MSG(col >= 0, "harmonic: no surface_displacement");
  double det = ss * cc - sc * sc, fs = (ws * cc - wc * sc) / det, fc = (wc * ss - ws * sc) / det;
  /* the mean density of the deposit: phi = 0.55 on average (its solids are conserved) */
  double rho = 0.55 * rho_s + 0.45 * rho_f;
  double complex ks = om * csqrt(rho / (G + I * om * eta));
  double exact = a0 / (om * om) * cabs(1.0 / ccos(ks * H) - 1.0);
  return (hypot(fs, fc) - exact) / exact;
}

static void harmonic(void) {
  char cwd[2048], path[2300];
  if (!getcwd(cwd, sizeof cwd)) return;
  snprintf(path, sizeof path, "%s/test_liquefaction_harmonic.csv", cwd);
  FILE *f = fopen(path, "w");
  if (!f) return;
  fprintf(f, "time_s,acceleration_m_s2\n");
  for (int i = 0; i <= 30000; ++i) fprintf(f, "%.3f,%.12e\n", 1e-3 * i, 0.01 * sin(2.0 * M_PI * 1e-3 * i));
  fclose(f);
  double e[3];
  const int cells[3] = {12, 24, 48};
  for (int k = 0; k < 3; ++k) e[k] = harmonic_run(cells[k], path);
  printf(
      "  harmonic base, uniform layer: surface amplitude error %.2e / %.2e / %.2e on 10 / 20 / 40 cells, order "
      "%.2f, %.2f\n",
      e[0], e[1], e[2], log2(fabs(e[0] / e[1])), log2(fabs(e[1] / e[2])));
  CHECK_MSG(fabs(e[2]) < 1e-4 && fabs(e[1]) < 3e-4, "harmonic response off by %g, %g", e[1], e[2]);
  CHECK_MSG(log2(fabs(e[0] / e[1])) > 1.8, "harmonic response order %g", log2(fabs(e[0] / e[1])));
}

/* The time series of a scalar over the outputs in [t0, t1]: *t and *v malloc'ed, the count returned (-1: none). */
static int scalar_series(const char *out, const char *name, double t0, double t1, double **t, double **v) {
  sl_output_scalars all;
  sl_diag d = {{0}};
  *t = *v = NULL;
  if (sl_output_read_scalars(out, &all, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return -1;
  }
  int col = -1, m = 0;
  for (int j = 0; j < all.n_names; ++j)
    if (strcmp(all.names[j], name) == 0) col = j;
  *t = malloc((size_t)all.n_times * sizeof **t), *v = malloc((size_t)all.n_times * sizeof **v);
  for (int k = 0; k < all.n_times && col >= 0 && *t && *v; ++k)
    if (all.times[k] >= t0 - 1e-9 && all.times[k] <= t1 + 1e-9)
      (*t)[m] = all.times[k], (*v)[m++] = all.values[(size_t)k * all.n_names + col];
  sl_output_scalars_free(&all);
  CHECK_MSG(col >= 0 && *t && *v, "%s: no %s", out, name);
  if (col < 0 || !*t || !*v) {
    free(*t), free(*v), *t = *v = NULL;
    return -1;
  }
  return m;
}

/* A free vibration sampled at (t, w): its extrema (each by the parabola through the sample and its neighbours),
 * the period as twice the mean spacing of successive extrema, and the logarithmic decrement per cycle,
 * -2 x the least-squares slope of ln |e_k - e_(k+1)| (successive peak-to-peak excursions, so that a static offset
 * drops out) against k. Returns the number of extrema (period and decrement NAN below 4). */
static int free_vibration_fit(const double *t, const double *w, int n, double *period, double *decrement,
                              double *amp_first) {
  enum { MAXE = 400 };
  double te[MAXE], we[MAXE];
  int m = 0;
  for (int k = 1; k + 1 < n && m < MAXE; ++k) {
    double a = w[k - 1], b = w[k], c = w[k + 1];
    if (!((b > a && b >= c) || (b < a && b <= c))) continue;
    double den = a - 2.0 * b + c, x = den != 0.0 ? 0.5 * (a - c) / den : 0.0; /* the vertex, in samples */
    te[m] = t[k] + x * (t[k + 1] - t[k]), we[m++] = b - 0.25 * (a - c) * x;
  }
  *period = *decrement = *amp_first = NAN;
  if (m < 4) return m;
  *period = 2.0 * (te[m - 1] - te[0]) / (m - 1);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int q = m - 1;
  for (int k = 0; k < q; ++k) {
    double y = log(fabs(we[k] - we[k + 1]));
    sx += k, sy += y, sxx += (double)k * k, sxy += k * y;
  }
  *decrement = -2.0 * (q * sxy - sx * sy) / (q * sxx - sx * sx);
  *amp_first = 0.5 * fabs(we[0] - we[1]);
  return m;
}

/* The free vibration of a linear elastic column (the Terzaghi deposit at rest, [shaking] shear_modulus = 1e7 Pa,
 * 40 cells over its 10 m, the scene's dt = 0.01 s) after one cycle of base motion at its natural frequency.
 * Exact (a uniform Kelvin-Voigt layer, fixed base, free surface; Kramer 1996, Geotechnical Earthquake Engineering,
 * section 7.2.1): the fundamental mode has omega_1 = (pi/2H) V_s, V_s = sqrt(G/rho), an undamped period
 * T_0 = 4H/V_s, and under the stiffness-proportional viscosity eta = 2 xi G/omega_d the damping ratio
 * zeta = eta omega_1/(2G) = xi omega_1/omega_d, so a damped period T_0/sqrt(1 - zeta^2) and a logarithmic
 * decrement 2 pi zeta/sqrt(1 - zeta^2). Newmark's average acceleration rule conserves a linear system's energy
 * (Hughes 1987, The Finite Element Method, section 9.1.2: spectral radius 1 at every step), so without the
 * viscosity the decrement is 0 (an implicit Euler step would give about pi omega dt = 0.36 per cycle here) and
 * its period error is (omega dt)^2/12 = 1.1e-3. Checked: period within 1 % of 4H/V_s (damped), decrement
 * within 3 % of 2 pi zeta, and below 1e-3 without damping. */
static void free_vibration_elastic(void) {
  char cwd[2048], path[2300], s_rec[2400];
  if (!getcwd(cwd, sizeof cwd)) return;
  const double G = 1e7, rho = 0.55 * rho_s + 0.45 * rho_f, H = 10.0, Vs = sqrt(G / rho), T0 = 4.0 * H / Vs;
  snprintf(path, sizeof path, "%s/test_liquefaction_pulse.csv", cwd);
  FILE *f = fopen(path, "w");
  if (!f) return;
  fprintf(f, "time_s,acceleration_m_s2\n"); /* one cycle at 1/T0, then still */
  for (int i = 0; i <= 200; ++i) fprintf(f, "%.6f,%.12e\n", T0 * i / 200.0, 0.01 * sin(2.0 * M_PI * i / 200.0));
  fclose(f);
  snprintf(s_rec, sizeof s_rec, "shaking.record=%s", path);
  const double xis[2] = {0.05, 0.0};
  for (int k = 0; k < 2; ++k) {
    char s_xi[64];
    snprintf(s_xi, sizeof s_xi, "shaking.damping=%g", xis[k]);
    const char *sets[] = {"mesh.cells=48",
                          s_rec,
                          s_xi,
                          "deposit.nbar_drop=0",
                          "shaking.units=si",
                          "shaking.shear_modulus=1e7",
                          "time.end=10",
                          "time.dt=0.01",
                          "output.every=0.01",
                          NULL};
    if (run_ok("terzaghi_consolidation", NULL, NULL, sets, "test_liquefaction_free.h5")) return;
    double *t, *w, T, delta, a1;
    int n = scalar_series("test_liquefaction_free.h5", "surface_displacement", 2.0, 10.0, &t, &w);
    if (n < 0) return;
    int m = free_vibration_fit(t, w, n, &T, &delta, &a1);
    free(t), free(w);
    double zeta = xis[k] * (2.0 * M_PI / T0) / (2.0 * M_PI * 2.0), Td = T0 / sqrt(1.0 - zeta * zeta);
    double dex = 2.0 * M_PI * zeta / sqrt(1.0 - zeta * zeta);
    printf(
        "  free vibration of an elastic column (xi = %.2f at 2 Hz): %d extrema over 2-10 s, period %.4f s against "
        "4H/V_s = %.4f s (damped %.4f, %+.2e), logarithmic decrement %.4f per cycle against 2 pi zeta = %.4f "
        "(zeta = %.4f)\n",
        xis[k], m, T, T0, Td, T / Td - 1.0, delta, dex, zeta);
    CHECK_MSG(m >= 20 && fabs(T / Td - 1.0) < 1e-2, "elastic column: period %g against %g (%d extrema)", T, Td, m);
    if (xis[k] > 0.0) CHECK_MSG(fabs(delta / dex - 1.0) < 0.03, "elastic column: decrement %g against %g", delta, dex);
    else CHECK_MSG(fabs(delta) < 1e-3, "elastic column without damping: decrement %g (the integrator damps)", delta);
  }
}

/* The fundamental period of the discrete deposit column at an output: the lumped face masses (half of each
 * neighbouring cell's mixture density times its height) and the cells' small-strain moduli G0 = 220 K2max
 * sqrt(P_s) kPa (Seed & Idriss 1970, as liquefaction.c), base face fixed, surface free; omega^2 the smallest
 * eigenvalue of K w = omega^2 M w by inverse iteration (K tridiagonal, Thomas), 2 pi/omega returned. */
static double column_period(const double *phi, const double *ps, int top, double h, double k2max) {
  double *G = malloc((size_t)top * sizeof *G), *m = malloc((size_t)(top + 1) * sizeof *m);
  double *x = malloc((size_t)(top + 1) * sizeof *x), *y = malloc((size_t)(top + 1) * sizeof *y);
  double *c = malloc((size_t)(top + 1) * sizeof *c), om2 = NAN;
  if (!G || !m || !x || !y || !c) goto done;
  for (int i = 0; i < top; ++i) G[i] = 1e3 * 220.0 * k2max * sqrt(fmax(ps[i], 0.0) * 1e-3) / h;
  for (int k = 1; k <= top; ++k) {
    double r0 = phi[k - 1] * rho_s + (1.0 - phi[k - 1]) * rho_f,
           r1 = k < top ? phi[k] * rho_s + (1.0 - phi[k]) * rho_f : 0.0;
    m[k] = 0.5 * h * (r0 + r1), x[k] = (double)k / top;
  }
  for (int it = 0; it < 200; ++it) {
    for (int k = 1; k <= top; ++k) y[k] = m[k] * x[k];
    /* K: diagonal G[k-1] + G[k] (k < top), off-diagonal -G[k] */
    double cp = 0.0;
    for (int k = 1; k <= top; ++k) {
      double dk = G[k - 1] + (k < top ? G[k] : 0.0), lo = k > 1 ? -G[k - 1] : 0.0, den = dk - lo * cp;
      c[k] = k < top ? -G[k] / den : 0.0;
      y[k] = (y[k] - lo * (k > 1 ? y[k - 1] : 0.0)) / den;
      cp = c[k];
    }
    for (int k = top - 1; k >= 1; --k) y[k] -= c[k] * y[k + 1];
    double num = 0.0, den = 0.0, nx = 0.0;
    for (int k = 1; k <= top; ++k) num += x[k] * m[k] * x[k], den += x[k] * m[k] * y[k], nx = fmax(nx, fabs(y[k]));
    om2 = num / den; /* Rayleigh quotient estimate x'Mx / x'M K^-1 M x */
    for (int k = 1; k <= top; ++k) x[k] = y[k] / nx;
  }
done:
  free(G), free(m), free(x), free(y), free(c);
  return 2.0 * M_PI / sqrt(om2);
}

/* The base case keeps oscillating after the record stops at 6 s: its free vibration, read from the surface
 * displacement relative to the base at every 0.01 s to 16 s. Its period against the discrete column's
 * fundamental (column_period) at 12 s, and its decay against the stated damping: the viscosity
 * eta = 2 xi G0/omega_d is proportional to the small-strain stiffness, so every mode of the small-strain
 * deposit has zeta = xi omega/omega_d (Rayleigh damping with its stiffness term only; Chopra 2012, Dynamics of
 * Structures, eq 11.4.5), here measured at the free vibration's own frequency. The shear strain amplitude of
 * each cell over 6-7 s, and the half-cycle increment Byrne's law gives it after the shaking's accumulated
 * volumetric strain, are printed (docs/liquefaction.md). */
static void scene_oscillation(void) {
  const char *out = "test_liquefaction_osc.h5";
  const char *sets[] = {"time.end=16", "output.every=0.01", "output.fields=phi,solids_pressure,shear_strain,nbar",
                        NULL};
  if (run_ok("liquefaction", NULL, NULL, sets, out)) return;
  double *t, *w, T, delta, a1, T2, delta2, a2;
  int n = scalar_series(out, "surface_displacement", 6.0, 15.0, &t, &w), j9 = 0, j75 = 0;
  if (n < 0) return;
  while (j9 < n && t[j9] < 9.0 - 1e-9) ++j9;
  while (j75 < n && t[j75] < 7.5 + 1e-9) ++j75;
  int m = free_vibration_fit(t + j9, w + j9, n - j9, &T, &delta, &a1);
  int m2 = free_vibration_fit(t, w, j75, &T2, &delta2, &a2);
  free(t), free(w);
  const double xi = 0.05, fd = 2.0, k2max = 30.0;
  double zeta = xi * (1.0 / T) / fd, dex = 2.0 * M_PI * zeta / sqrt(1.0 - zeta * zeta);
  int nc;
  double *phi0 = field_at(out, "phi", 0.0, &nc, NULL), *phi = field_at(out, "phi", 12.0, &nc, NULL);
  double *ps = field_at(out, "solids_pressure", 12.0, &nc, NULL);
  if (!phi0 || !phi || !ps) {
    free(phi0), free(phi), free(ps);
    return;
  }
  int top = 0;
  while (top < nc && phi0[top] >= 0.3) ++top;
  double h = 17.0 / nc, Tc = column_period(phi, ps, top, h, k2max), trav = 0.0;
  for (int i = 0; i < top; ++i) {
    double G0 = 1e3 * 220.0 * k2max * sqrt(fmax(ps[i], 0.0) * 1e-3), r = phi[i] * rho_s + (1.0 - phi[i]) * rho_f;
    trav += h / sqrt(G0 / r);
  }
  printf(
      "  after the shaking: the surface moves %.2e m relative to the base over 6-7.5 s (%d extrema, period %.3f s, "
      "decrement %.3f); over 9-15 s %.2e m at first, period %.4f s (%d extrema), decrement %.4f per cycle against "
      "2 pi zeta = %.4f (zeta = xi f/f_d = %.4f); the column's fundamental at 12 s %.4f s (%+.2e), 4 x travel time "
      "%.4f s\n",
      a2, m2, T2, delta2, a1, T, m, delta, dex, zeta, Tc, T / Tc - 1.0, 4.0 * trav);
  /* the strain amplitude per cell over 6-7 s and Byrne's half-cycle increment after the shaking */
  double *gmax = calloc((size_t)top, sizeof *gmax), *gmin = calloc((size_t)top, sizeof *gmin);
  double *nb = field_at(out, "nbar", 6.0, &nc, NULL);
  const double C1 = 7600.0 * pow(15.0, -2.5), C2 = 0.4 / C1, nbar_min = scalar(out, "nbar_min", 6.0);
  for (int k = 0; k <= 20 && gmax && gmin; ++k) { /* every 0.05 s: a tenth of the period */
    double *gs = field_at(out, "shear_strain", 6.0 + 0.05 * k, &nc, NULL);
    for (int i = 0; i < top && gs; ++i) {
      gmax[i] = k ? fmax(gmax[i], gs[i]) : gs[i], gmin[i] = k ? fmin(gmin[i], gs[i]) : gs[i];
    }
    free(gs);
  }
  double worst_free = 0.0, gbig = 0.0;
  int ibig = 0;
  for (int i = 0; i < top && gmax && gmin && nb; ++i) {
    double amp = 0.5 * (gmax[i] - gmin[i]), e = 100.0 * (1.0 - 0.5 / (1.0 - nb[i])), gp = 100.0 * amp;
    double inc = gp > 0.0 ? gp * C1 * exp(-C2 * e / gp) : 0.0; /* percent, Byrne (1991) */
    if (amp > gbig) gbig = amp, ibig = i;
    if (nb[i] > nbar_min + 1e-12) worst_free = fmax(worst_free, inc);
    if (i % 10 == 0 || i == top - 1)
      printf(
          "    cell %2d (%.2f m deep): strain amplitude %.2e over 6-7 s, eps_vd %.2f %%, C2 eps_vd/gamma %.1f, "
          "Byrne's half-cycle increment %.1e %%%s\n",
          i, scalar(out, "deposit_height", 0.0) - (i + 0.5) * h, amp, e, C2 * e / gp, inc,
          nb[i] <= nbar_min + 1e-12 ? " (at nbar_min)" : "");
  }
  printf("    largest strain amplitude %.2e in cell %d; largest Byrne increment of a cell above nbar_min %.1e %%\n",
         gbig, ibig, worst_free);
  free(gmax), free(gmin), free(nb);
  CHECK_MSG(m >= 20, "the deposit does not keep oscillating after the shaking (%d extrema over 9-15 s)", m);
  /* measured: +0.7 % and +0.9 %; the secant modulus at the window's strains (under 1e-4) against G0, and the
   * deposit stiffening as it drains (the period falls from 0.59 s at 6-7.5 s to 0.49 s), account for them */
  CHECK_MSG(fabs(T / Tc - 1.0) < 0.03, "free vibration period %g against the column's %g", T, Tc);
  CHECK_MSG(fabs(delta / dex - 1.0) < 0.05, "free vibration decrement %g against the stated damping's %g", delta, dex);
  free(phi0), free(phi), free(ps);
}
/* [initial] from: a run starting from another's last state has it as its state at t = 0, bit for bit (phi and
 * nbar; the deposit is not settled again). */
static void from_file(void) {
  char cwd[2048], repl[2400];
  if (!getcwd(cwd, sizeof cwd)) return;
  const char *first[] = {"time.end=1", "output.every=1", NULL};
  if (run_ok("liquefaction", NULL, NULL, first, "test_liquefaction_first.h5")) return;
  snprintf(repl, sizeof repl, "[initial]\nfrom = %s/test_liquefaction_first.h5\n", cwd);
  const char *second[] = {"time.end=0.5", "output.every=0.5", "deposit.settle=0", NULL};
  if (run_ok("liquefaction", "initial", repl, second, "test_liquefaction_second.h5")) return;
  int n1, n2, same = 1;
  const char *names[2] = {"phi", "nbar"};
  for (int k = 0; k < 2; ++k) {
    double *a = field_at("test_liquefaction_first.h5", names[k], INFINITY, &n1, NULL);
    double *b = field_at("test_liquefaction_second.h5", names[k], 0.0, &n2, NULL);
    if (a && b && n1 == n2)
      for (int i = 0; i < n1; ++i) same &= a[i] == b[i];
    else same = 0;
    free(a), free(b);
  }
  printf("  [initial] from: the second run starts bit for bit from the first's last phi and nbar: %s\n",
         same ? "yes" : "no");
  CHECK_MSG(same, "[initial] from did not reproduce the file's state");
}

/* Bad input: refused before any output, with the location and what is allowed. */
static void expect_refusal(const char *scene, const char *section, const char *replacement, const char *const *sets,
                           const char *needle) {
  sl_diag d = {{0}};
  int rc = run_scene(scene, section, replacement, sets, "test_liquefaction_bad.h5", &d);
  CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, needle), "expected a refusal naming '%s', got %d: %s", needle, rc,
            d.msg);
}

static void bad_input(void) {
  char cwd[2048], path[2300], set[2400];
  if (!getcwd(cwd, sizeof cwd)) return;
  const char *k2[] = {"shaking.k2max=0.5", NULL};
  expect_refusal("liquefaction", NULL, NULL, k2, "k2max");
  expect_refusal("liquefaction", "initial", "[initial]\nphi = 0.45\n", NULL, "[initial] nbar");
  const char *missing[] = {"shaking.record=no_such_record.csv", NULL};
  expect_refusal("liquefaction", NULL, NULL, missing, "cannot open the base record");
  snprintf(path, sizeof path, "%s/test_liquefaction_backwards.csv", cwd);
  FILE *f = fopen(path, "w");
  if (!f) return;
  fprintf(f, "time,a\n0,0\n0.1,0.01\n0.1,0.02\n");
  fclose(f);
  snprintf(set, sizeof set, "shaking.record=%s", path);
  const char *back[] = {set, NULL};
  expect_refusal("liquefaction", NULL, NULL, back, "test_liquefaction_backwards.csv:4: time 0.1 does not follow");
  expect_refusal("fluidized_bed_2d", "closure.solids_pressure", "[closure.solids_pressure]\nmodel = pringle_state\n",
                 NULL, "only the 1-D column");
  printf("  bad input refused: k2max 0.5, no [initial] nbar, a missing record, a record going back, nbar in 2-D\n");
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  const char *out = "test_liquefaction.h5";
  if (run_ok("liquefaction", NULL, NULL, NULL, out)) return sl_test_summary();
  at_rest_and_conservation(out);
  base_case(out);
  undrained_transfer(out);
  terzaghi();
  at_rest();
  variants(out);
  settlement_bound(out);
  base_after_shaking(out);
  pictures(out);
  harmonic();
  free_vibration_elastic();
  scene_oscillation();
  from_file();
  bad_input();
  return sl_test_summary();
}
