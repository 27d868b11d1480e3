/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Krampa (2009) Tables C.1-C.7 (configs/data/krampa_2009_tables_c.csv): the
 * measured manometric pressure gradients of 0.5 mm glass beads in the 53.2 mm
 * vertical loop, every row in up-flow and down-flow with the fully developed
 * pipe model (configs/vertical_pipe.ini: k-epsilon and the log law, Gidaspow
 * drag, the solids' eddy viscosity and Lun et al.'s kinetic viscosity, free
 * slip of the solids at the wall), water properties from each row's
 * temperature (density: Kell 1975, J. Chem. Eng. Data 20:97; viscosity:
 * Vogel's equation, mu = 2.414e-5 10^(247.8/(T - 140)) Pa s), the nominal
 * solids fraction as the section mean in both sections.
 *
 * One wall roughness is calibrated on the 5 % table (C.1) alone: the k_s of
 * the log law that minimises the squared relative errors of its average
 * gradients (golden section in log k_s). The 5 % table is the one the thesis
 * says equals water, 12-24 % above a smooth pipe. Then every table is run
 * with it. Two variants of the solids stress, each calibrated on its own:
 * Krampa's model B as configs/vertical_pipe.ini gives it (the solids' eddy
 * viscosity and Lun et al.'s kinetic viscosity; the solids' k_s-eps_s of his
 * model is the dispersed phase's zero-equation model here) and his model A
 * (no kinetic theory; Bouillard's solids pressure, gidaspow_elastic with G0 =
 * 1 Pa, C = 600, phi_max = 0.63; mu_s = 1e-8 Pa s). Asserted for both, with
 * these targets: the
 * calibration's own table has every average within 10 % at V >= 2.5 m/s and
 * 20 % below; in every other table (25-45 %, not used in the fit) up-flow
 * and down-flow are each within 10 % of their difference; every run
 * converges. The averages of the 25-45 % tables are printed (and recorded in
 * docs/pipe.md) rather than asserted: the model misses them at low velocity,
 * by up to 70 % at 45 %, as Krampa's CFX-4 models missed above about 10 %.
 * A third variant, model B in full: the kinetic theory's pressure in the radial balance
 * (kinetic_pressure = true) with the transported granular temperature (granular_temperature = transport),
 * its own roughness from the 5 % table; the same targets on the rows that converge, and at most 2 of
 * its 152 rows stopping (named: a limit cycle of k and phi at the wall, C.3 3.48 m/s down and C.4 3.78 up).
 * Those two stop because their wall cell's fraction has to sit at Gidaspow's drag switch (phi = 0.2: Wen-Yu
 * above c_f = 0.8, Ergun below, K x1.7 there), where the equations have no solution: at 5000 iterations the wall
 * cell's phi is 0.2046 and 0.2009, cycling across it. A fourth variant, model B in full with the drag switch
 * smoothed by the arctan blend of Huilin & Gidaspow (2003, Chem. Eng. Sci. 58:3777; `blend = huilin_gidaspow` of
 * drag/gidaspow) for every row, its own roughness: the same targets, and every one of its 152 runs converges.
 * A fifth, model C (Peirano & Leckner's solids viscosity with Tchen's equilibrium k_s and k_fs, Simonin's
 * modulation and dispersion, no kinetic theory): every run converges (asserted); its errors are printed only
 * (they miss every target above 5 %: the modulation with the equilibrium k_fs removes the core turbulence).
 * Three more: models B, A and B in full (blended) with Saffman's shear lift in the radial balance ([closure.lift]
 * model = saffman_mei, McLaughlin's weak-shear factor, damped at the wall), each calibrated on the 5 % table; the
 * same targets, every run converging, and model B's mean errors as recorded (docs/pipe.md) to 1 point.
 * Two more: models B and B in full (blended drag) with Coulomb's friction of the solids on the wall
 * (wall_stress/coulomb, mu_w = 0.4, not fitted, on the kinetic pressure at the wall cell), each calibrated on the
 * 5 % table; every run converging and each table's mean error as recorded (docs/pipe.md) to 1 point.
 * One more: model B as the loop ([pipe] loop = true: both sections in one run sharing the solids at one solids flux),
 * calibrated on the 5 % table; the same targets, and each table's mean error as recorded (docs/pipe.md) to 1 point.
 * A third part ("slip"): candidates for the loop's missing slip, each as the loop calibrated on the 5 % table (Di
 * Felice's and Richardson-Zaki's drag, n = 3.19, for the beads' Re_t = 40; Saffman's lift; model B in full), with the
 * slip each table's slowest row needs against the model's; asserted: the Richardson-Zaki variant's mean errors as
 * recorded to 1 point with every run converging, and the needed slip at 40-45 % above 3 u_t.
 * A fourth part ("kseps"): Krampa's models A and B with the solids' own k_s-eps_s ([pipe] solids_turbulence =
 * k_epsilon, configs/vertical_pipe_model_a.ini and _model_b.ini): model A calibrated on the 5 % table, model B (the
 * kinetic theory with its pressure and transported theta, Johnson & Jackson's walls) with model A's roughness (its 5 %
 * table lies above the data with the smoothest wall), and model B with free-slip solids; asserted: every run
 * converging, model A's targets as above, and each variant's mean errors as recorded (docs/pipe.md) to 1 point.
 * The program runs in four parts (argument "models": A, B, B in full, C; "variants": the lift, the Coulomb friction
 * and the loop; "slip"; "kseps"; no argument: all), registered as four tests that run side by side.
 * The predictions go to krampa_tables_c_predicted.csv (and _model_a, _model_b_full, _model_b_full_blend,
 * _model_c, _model_b_lift, _model_a_lift, _model_b_full_blend_lift, _model_b_coulomb,
 * _model_b_full_blend_coulomb, _model_b_loop). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "pipe_testing.h"
#include "sluice/sluice.h"
#include "testing.h"

enum { MAX_ROWS = 128 };

/* each part's own output file (the parts run in parallel in one folder) */
static const char *out_h5 = "pipe_krampa.h5";
typedef struct row {
  char table[8];
  double c, q, down, up, t, avg, v;
  double p_up, p_down, us; /* predicted manometric gradients (kPa/m), the up-flow's mean solids velocity */
  double cu, cd;           /* with the loop: the sections' in-situ mean fractions */
} row;

static row rows[MAX_ROWS];
static int n_rows;
static char scene_b[8192], scene_a[8192], scene_bt[8192], scene_btb[8192], scene_c[8192], scene_ct[8192],
    scene_cj[8192], scene_bl[8192 + 64], scene_al[8192 + 64], scene_btbl[8192 + 64], scene_bw[8192 + 128],
    scene_btbw[8192 + 128], scene_ak[8192], scene_bk[8192], scene_bkf[8192];
static const char *scene = scene_b;
static long runs, failures;

static int load(void) {
  static char csv[1 << 16];
  if (sl_test_read_source("configs/vertical_pipe.ini", scene_b, sizeof scene_b) ||
      sl_test_read_source("configs/data/krampa_2009_tables_c.csv", csv, sizeof csv))
    return 1;
  for (char *line = strtok(csv, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#' || strncmp(line, "table", 5) == 0) continue;
    row *r = &rows[n_rows];
    if (n_rows < MAX_ROWS && sscanf(line, "%7[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", r->table, &r->c, &r->q, &r->down,
                                    &r->up, &r->t, &r->avg, &r->v) == 8)
      ++n_rows;
  }
  CHECK_MSG(n_rows == 76, "%d rows read (Tables C.1-C.7 have 76)", n_rows);
  /* model A: the scene without the kinetic theory, Bouillard's solids pressure and a constant solids viscosity */
  char *gran = strstr(scene_b, "\n[closure.granular]");
  CHECK_MSG(gran != NULL, "vertical_pipe.ini has no [closure.granular]");
  if (!gran) return 1;
  snprintf(scene_a, sizeof scene_a,
           "%.*s\n[closure.solids_pressure]\nmodel = gidaspow_elastic\nmodulus_ref = 1\ncompaction = 600\n"
           "phi_max = 0.63\n",
           (int)(gran - scene_b), scene_b);
  /* model B in full: the kinetic theory's pressure in the radial balance, theta transported (conduction) */
  char *kp = strstr(scene_b, "kinetic_pressure = false");
  CHECK_MSG(kp != NULL, "vertical_pipe.ini has no kinetic_pressure = false");
  if (!kp) return 1;
  snprintf(scene_bt, sizeof scene_bt, "%.*skinetic_pressure = true\ngranular_temperature = transport%s",
           (int)(kp - scene_b), scene_b, kp + strlen("kinetic_pressure = false"));
  /* model B in full with the Huilin & Gidaspow (2003) blend of the drag's switch */
  char *dr = strstr(scene_bt, "[closure.drag]\nmodel = gidaspow\n");
  CHECK_MSG(dr != NULL, "vertical_pipe.ini has no [closure.drag] model = gidaspow");
  if (!dr) return 1;
  size_t at = (size_t)(dr - scene_bt) + strlen("[closure.drag]\nmodel = gidaspow\n");
  snprintf(scene_btb, sizeof scene_btb, "%.*sblend = huilin_gidaspow\n%s", (int)at, scene_bt, scene_bt + at);
  /* model C: Peirano & Leckner's solids viscosity with Tchen's k_s and k_fs, Simonin's modulation and dispersion,
     no kinetic theory (its viscosity replaced) */
  const char *simonin =
      "[closure.turbulence_modulation]\nmodel = simonin\n\n[closure.turbulent_dispersion]\nmodel = "
      "simonin\n";
  snprintf(scene_c, sizeof scene_c, "%.*skinetic_pressure = false\nsolids_viscosity = peirano_leckner%.*s\n%s",
           (int)(kp - scene_b), scene_b, (int)(gran - kp - strlen("kinetic_pressure = false")),
           kp + strlen("kinetic_pressure = false"), simonin);
  /* model C with k_s and k_fs transported (Krampa eqs 5.20, 5.23) */
  snprintf(scene_ct, sizeof scene_ct,
           "%.*skinetic_pressure = false\nsolids_viscosity = peirano_leckner\nsolids_turbulence = transported%.*s\n%s",
           (int)(kp - scene_b), scene_b, (int)(gran - kp - strlen("kinetic_pressure = false")),
           kp + strlen("kinetic_pressure = false"), simonin);
  /* model C with k_s and k_fs transported (Krampa eqs 5.20, 5.23) */
  snprintf(scene_ct, sizeof scene_ct,
           "%.*skinetic_pressure = false\nsolids_viscosity = peirano_leckner\nsolids_turbulence = transported%.*s\n%s",
           (int)(kp - scene_b), scene_b, (int)(gran - kp - strlen("kinetic_pressure = false")),
           kp + strlen("kinetic_pressure = false"), simonin);
  /* and with Johnson & Jackson's solids wall (Krampa's model C wall, eqs 4.92-4.93), its energy flux into k_s */
  {
    char *fs = strstr(scene_ct, "solids_wall = free_slip");
    CHECK_MSG(fs != NULL, "vertical_pipe.ini has no solids_wall = free_slip");
    if (!fs) return 1;
    snprintf(scene_cj, sizeof scene_cj,
             "%.*ssolids_wall = wall_stress%s\n[closure.wall_stress.solids]\nmodel = "
             "johnson_jackson\n",
             (int)(fs - scene_ct), scene_ct, fs + strlen("solids_wall = free_slip"));
  }
  /* with Saffman's shear lift (Mei's correction, damped at the wall: [closure.lift] model = saffman_mei) in the
     radial balance: models B, A and B in full (blended drag) */
  const char *lift = "\n[closure.lift]\nmodel = saffman_mei\n";
  snprintf(scene_bl, sizeof scene_bl, "%s%s", scene_b, lift);
  snprintf(scene_al, sizeof scene_al, "%s%s", scene_a, lift);
  snprintf(scene_btbl, sizeof scene_btbl, "%s%s", scene_btb, lift);
  /* with Coulomb's friction of the solids on the wall (wall_stress/coulomb, mu_w = 0.4, sand on steel, not fitted;
     the normal stress the kinetic theory's pressure at the wall cell, [pipe] wall_normal_stress = contact_kinetic:
     the contact pressure alone is zero in these scenes, none has a [closure.solids_pressure] that acts below
     phi = 0.5): models B and B in full (blended drag) */
  const char *coulomb = "\n[closure.wall_stress.solids]\nmodel = coulomb\nmu_w = 0.4\n";
  {
    const char *fs_b = strstr(scene_b, "solids_wall = free_slip"), *fs_t = strstr(scene_btb, "solids_wall = free_slip");
    CHECK_MSG(fs_b && fs_t, "vertical_pipe.ini has no solids_wall = free_slip");
    if (!fs_b || !fs_t) return 1;
    snprintf(scene_bw, sizeof scene_bw, "%.*ssolids_wall = wall_stress\nwall_normal_stress = contact_kinetic%s%s",
             (int)(fs_b - scene_b), scene_b, fs_b + strlen("solids_wall = free_slip"), coulomb);
    snprintf(scene_btbw, sizeof scene_btbw, "%.*ssolids_wall = wall_stress\nwall_normal_stress = contact_kinetic%s%s",
             (int)(fs_t - scene_btb), scene_btb, fs_t + strlen("solids_wall = free_slip"), coulomb);
  }
  /* models A and B with the solids' k_s-eps_s (pipe_kseps_solid.c) */
  if (sl_test_read_source("configs/vertical_pipe_model_a.ini", scene_ak, sizeof scene_ak) ||
      sl_test_read_source("configs/vertical_pipe_model_b.ini", scene_bk, sizeof scene_bk))
    return 1;
  /* model B with free-slip solids in place of Johnson & Jackson's wall: what the wall condition costs */
  {
    char *ws = strstr(scene_bk, "solids_wall = wall_stress"), *jj = strstr(scene_bk, "\n# Johnson & Jackson");
    CHECK_MSG(ws && jj, "vertical_pipe_model_b.ini has no solids_wall = wall_stress or Johnson & Jackson's wall");
    if (!ws || !jj) return 1;
    snprintf(scene_bkf, sizeof scene_bkf, "%.*ssolids_wall = free_slip%.*s\n", (int)(ws - scene_bk), scene_bk,
             (int)(jj - ws - strlen("solids_wall = wall_stress")), ws + strlen("solids_wall = wall_stress"));
  }
  return n_rows == 76 ? 0 : 1;
}

/* Water at T (C): Kell (1975) density, Vogel's viscosity. */
static double water_density(double T) {
  return (999.83952 + 16.945176 * T - 7.9870401e-3 * T * T - 46.170461e-6 * pow(T, 3) + 105.56302e-9 * pow(T, 4) -
          280.54253e-12 * pow(T, 5)) /
         (1.0 + 16.879850e-3 * T);
}
static double water_viscosity(double T) { return 2.414e-5 * pow(10.0, 247.8 / (T + 273.15 - 140.0)); }

/* 1: each row as the loop ([pipe] loop = true), up-flow and down-flow in one run sharing the solids; the last loop
   run's in-situ fractions */
static int loop;
static double loop_cu = NAN, loop_cd = NAN;

/* One row in one direction, or with loop both in one run: the (up-flow section's, with loop) manometric gradient in
   kPa/m, the down-flow section's into *loop_down (may be NULL); NaN when the run fails. */
static double run_row(const row *r, int down, double ks, double *us, double *loop_down) {
  char s[6][80];
  snprintf(s[0], 80, "fluid.density=%.10g", water_density(r->t));
  snprintf(s[1], 80, "fluid.viscosity=%.10g", water_viscosity(r->t));
  snprintf(s[2], 80, "pipe.bulk_velocity=%.10g", r->v);
  snprintf(s[3], 80, "pipe.solids_fraction=%.10g", r->c);
  snprintf(s[4], 80, "flow.gravity=%s", down ? "9.81" : "-9.81");
  snprintf(s[5], 80, "closure.wall_stress.fluid.roughness=%.10g", ks);
  const char *sets[9] = {s[0], s[1], s[2], s[3], s[4], s[5]};
  int k = 6;
  if (scene == scene_a || scene == scene_al) sets[k++] = "solid.viscosity=1e-8";
  if (loop) sets[k++] = "pipe.loop=true";
  sluice_error e = {0, ""};
  ++runs;
  if (pipe_run_text(scene, "vertical_pipe.ini", sets, out_h5, &e)) {
    ++failures;
    printf("  %s V = %.2f %s: %s\n", r->table, r->v, loop ? "loop" : down ? "down" : "up", e.msg);
    if (loop_down) *loop_down = NAN;
    loop_cu = loop_cd = NAN;
    return NAN;
  }
  if (us) *us = pipe_scalar(out_h5, "solids_mean_velocity");
  if (!loop) return 1e-3 * pipe_scalar(out_h5, "manometric_gradient");
  if (loop_down) *loop_down = 1e-3 * pipe_scalar(out_h5, "loop_manometric_gradient_down");
  loop_cu = pipe_scalar(out_h5, "loop_phi_mean_up"), loop_cd = pipe_scalar(out_h5, "loop_phi_mean_down");
  return 1e-3 * pipe_scalar(out_h5, "loop_manometric_gradient_up");
}

static void run_rows(const char *table, double ks) {
  for (int i = 0; i < n_rows; ++i) {
    if (table && strcmp(rows[i].table, table) != 0) continue;
    rows[i].p_up = run_row(&rows[i], 0, ks, &rows[i].us, loop ? &rows[i].p_down : NULL);
    rows[i].cu = loop ? loop_cu : rows[i].c, rows[i].cd = loop ? loop_cd : rows[i].c;
    if (!loop) rows[i].p_down = run_row(&rows[i], 1, ks, NULL, NULL);
  }
}

/* Sum of squared relative errors of the averages of a table. */
static double misfit(const char *table, double ks) {
  run_rows(table, ks);
  double s = 0.0;
  for (int i = 0; i < n_rows; ++i)
    if (strcmp(rows[i].table, table) == 0) {
      double e = 0.5 * (rows[i].p_up + rows[i].p_down) / rows[i].avg - 1.0;
      s += e * e;
    }
  return s;
}

/* Golden section in log10 k_s over [-7, -3.5]. */
static double calibrate(void) {
  const double gr = 0.5 * (sqrt(5.0) - 1.0);
  double a = -7.0, b = -3.5, x1 = b - gr * (b - a), x2 = a + gr * (b - a);
  double f1 = misfit("C.1", pow(10.0, x1)), f2 = misfit("C.1", pow(10.0, x2));
  for (int it = 0; it < 16; ++it) {
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - gr * (b - a), f1 = misfit("C.1", pow(10.0, x1));
    else a = x1, x1 = x2, f1 = f2, x2 = a + gr * (b - a), f2 = misfit("C.1", pow(10.0, x2));
  }
  return pow(10.0, 0.5 * (a + b));
}

typedef struct score {
  int n, n_avg_ok, n_ud_ok, n_failed;
  double mean_avg, worst_avg, worst_ud, mean_up, mean_down;
} score;

static score table_score(const char *table) {
  score s = {0};
  for (int i = 0; i < n_rows; ++i) {
    const row *r = &rows[i];
    if (strcmp(r->table, table) != 0) continue;
    if (!isfinite(r->p_up) || !isfinite(r->p_down)) { /* a run that stopped (named; counted in model()) */
      ++s.n_failed;
      continue;
    }
    double avg = 0.5 * (r->p_up + r->p_down), ea = avg / r->avg - 1.0, diff = r->up - r->down;
    double eu = (r->p_up - r->up) / diff, ed = (r->p_down - r->down) / diff;
    double lim = r->v >= 2.5 ? 0.10 : 0.20;
    ++s.n;
    s.n_avg_ok += fabs(ea) <= lim, s.n_ud_ok += fabs(eu) <= 0.10 && fabs(ed) <= 0.10;
    s.mean_avg += ea / 1.0, s.worst_avg = fabs(ea) > fabs(s.worst_avg) ? ea : s.worst_avg;
    s.worst_ud = fmax(s.worst_ud, fmax(fabs(eu), fabs(ed)));
    s.mean_up += eu, s.mean_down += ed;
  }
  if (s.n) s.mean_avg /= s.n, s.mean_up /= s.n, s.mean_down /= s.n;
  return s;
}

/* Calibrates (or takes the roughness *ks_io when it is positive), runs every row, writes the CSV, prints the
   table; the roughness used into *ks_io, each table's score into out (may be NULL). */
static void model_scored(const char *label, const char *csv, int assert_targets, long max_failures, double *ks_io,
                         score *out) {
  runs = 0, failures = 0;
  double ks = *ks_io > 0.0 ? *ks_io : calibrate();
  if (*ks_io > 0.0) printf("%s: roughness k_s = %.3g m (%.3g um), given\n", label, ks, 1e6 * ks);
  else {
    printf("%s: roughness calibrated on Table C.1 (5 %%) alone: k_s = %.3g m (%.3g um)\n", label, ks, 1e6 * ks);
    CHECK_MSG(ks > 1.1e-7 && ks < 3.0e-4, "k_s = %g m at the end of the search interval", ks);
  }
  *ks_io = ks;
  long fit_runs = runs;
  failures = 0;
  run_rows(NULL, ks);
  printf("%ld runs in the fit, %ld with every row (%ld failed)\n", fit_runs, runs - fit_runs, failures);
  CHECK_MSG(failures <= max_failures, "%ld runs failed (at most %ld)", failures, max_failures);
  FILE *f = fopen(csv, "w");
  if (f) {
    fprintf(f,
            "table,c,v,t,up,down,avg,up_model,down_model,avg_model,avg_error,up_error_of_difference,"
            "down_error_of_difference,solids_mean_velocity_up\n");
    for (int i = 0; i < n_rows; ++i) {
      const row *r = &rows[i];
      double avg = 0.5 * (r->p_up + r->p_down), diff = r->up - r->down;
      fprintf(f, "%s,%.2f,%.2f,%.1f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", r->table, r->c, r->v, r->t,
              r->up, r->down, r->avg, r->p_up, r->p_down, avg, avg / r->avg - 1.0, (r->p_up - r->up) / diff,
              (r->p_down - r->down) / diff, r->us);
    }
    fclose(f);
  }
  printf(
      "| table | C | rows | average: mean error | worst | rows within target | up, down: mean error / (up - down) | "
      "worst | rows within 10 %% |\n|---|---|---|---|---|---|---|---|---|\n");
  const char *tables[7] = {"C.1", "C.2", "C.3", "C.4", "C.5", "C.6", "C.7"};
  const int pct[7] = {5, 25, 30, 35, 40, 45, 45};
  for (int k = 0; k < 7; ++k) {
    score s = table_score(tables[k]);
    if (out) out[k] = s;
    if (s.n_failed) printf("(%s: %d rows not converged, left out)\n", tables[k], s.n_failed);
    printf("| %s | %d %% | %d | %+.1f %% | %+.1f %% | %d of %d | %+.1f %%, %+.1f %% | %.1f %% | %d of %d |\n",
           tables[k], pct[k], s.n, 100.0 * s.mean_avg, 100.0 * s.worst_avg, s.n_avg_ok, s.n, 100.0 * s.mean_up,
           100.0 * s.mean_down, 100.0 * s.worst_ud, s.n_ud_ok, s.n);
    if (!assert_targets) continue;
    if (k == 0) CHECK_MSG(s.n_avg_ok == s.n, "%s: %d of %d averages within the target", tables[k], s.n_avg_ok, s.n);
    else
      CHECK_MSG(s.n_ud_ok == s.n, "%s: %d of %d up and down within 10 %% of their difference", tables[k], s.n_ud_ok,
                s.n);
  }
  /* the L-probe's mean solids velocities, 25 %, up-flow (Krampa 2009 section 3.4): 1.55 m/s at V = 2, 3.91 at V = 4 */
  const double vv[2] = {2.0, 4.0}, meas[2] = {1.55, 3.91};
  for (int k = 0; k < 2; ++k) {
    row r = {.c = 0.25, .t = 22.8, .v = vv[k]};
    double us = NAN;
    run_row(&r, 0, ks, &us, NULL);
    printf("25 %%, up-flow, V = %.0f m/s: mean solids velocity %.3f m/s, L-probe %.2f (%+.1f %%)\n", vv[k], us, meas[k],
           100.0 * (us / meas[k] - 1.0));
  }
}

static void model(const char *label, const char *csv, int assert_targets, long max_failures) {
  double ks = 0.0;
  model_scored(label, csv, assert_targets, max_failures, &ks, NULL);
}

static void models_abc(void);
static void variants_added(void);
static void slip_candidates(void);
static void models_kseps(void);

/* Krampa's models A, B and C (argument "models"), then the lift, the Coulomb friction and the loop added to them
   ("variants"); no argument: both. */
int main(int argc, char **argv) {
  const char *part = argc > 1 ? argv[1] : "all";
  const int all = strcmp(part, "all") == 0, models = all || strcmp(part, "models") == 0,
            variants = all || strcmp(part, "variants") == 0, slip = all || strcmp(part, "slip") == 0,
            kseps = all || strcmp(part, "kseps") == 0;
  CHECK_MSG(models || variants || slip || kseps, "unknown part '%s' (all, models, variants, slip or kseps)", part);
  if ((!models && !variants && !slip && !kseps) || load()) return sl_test_summary();
  if (!all)
    out_h5 = models     ? "pipe_krampa_models.h5"
             : variants ? "pipe_krampa_variants.h5"
             : slip     ? "pipe_krampa_slip.h5"
                        : "pipe_krampa_kseps.h5";
  if (models) models_abc();
  if (variants) variants_added();
  if (slip) slip_candidates();
  if (kseps) models_kseps();
  return sl_test_summary();
}

/* Krampa's models A and B with the solids' k_s-eps_s ([pipe] solids_turbulence = k_epsilon): model A calibrated on
   the 5 % table with its targets asserted as above; model B with model A's roughness, printed; both with every run
   converging and each table's mean error as recorded (docs/pipe.md) to 1 point. */
static void models_kseps(void) {
  scene = scene_ak;
  double ks = 0.0;
  score sa[7], sb[7];
  model_scored("model A, the solids' k_s-eps_s (vertical_pipe_model_a.ini)", "krampa_tables_c_predicted_model_a_kseps.csv",
               1, 0, &ks, sa);
  scene = scene_bk;
  model_scored("model B, the solids' k_s-eps_s (vertical_pipe_model_b.ini), model A's roughness",
               "krampa_tables_c_predicted_model_b_kseps.csv", 0, 0, &ks, sb);
  scene = scene_bkf;
  score sf[7];
  model_scored("model B, the solids' k_s-eps_s, free-slip solids, model A's roughness",
               "krampa_tables_c_predicted_model_b_kseps_free_slip.csv", 0, 0, &ks, sf);
  /* each table's mean error of the average gradient as measured here (docs/pipe.md, "Models A and B with the solids'
     k_s-eps_s"), to 1 point: model A as with the zero-equation solids (its wall friction is the fluid's), model B
     with Johnson & Jackson's wall 2-5 times the data (the wall cell's shear heats theta: tau_sw 3 times tau_fw at
     25 %, 3.02 m/s), model B with free-slip solids 3-8 points above model A */
  const double mean_a[7] = {-1.8, -11.5, -17.7, -21.7, -33.1, -37.9, -28.3};
  const double mean_b[7] = {89.8, 254.1, 281.3, 318.0, 320.7, 376.4, 447.1};
  const double mean_f[7] = {0.6, -8.5, -13.7, -16.3, -26.8, -30.1, -18.8};
  for (int k = 0; k < 7; ++k) {
    CHECK_MSG(fabs(100.0 * sa[k].mean_avg - mean_a[k]) < 1.0, "model A k_s-eps_s, table %d: mean error %.2f %%, recorded %.1f %%",
              k + 1, 100.0 * sa[k].mean_avg, mean_a[k]);
    CHECK_MSG(fabs(100.0 * sb[k].mean_avg - mean_b[k]) < 1.0, "model B k_s-eps_s, table %d: mean error %.2f %%, recorded %.1f %%",
              k + 1, 100.0 * sb[k].mean_avg, mean_b[k]);
    CHECK_MSG(fabs(100.0 * sf[k].mean_avg - mean_f[k]) < 1.0,
              "model B k_s-eps_s free slip, table %d: mean error %.2f %%, recorded %.1f %%", k + 1,
              100.0 * sf[k].mean_avg, mean_f[k]);
  }
}

static void models_abc(void) {
  scene = scene_b;
  model("model B (vertical_pipe.ini: the kinetic viscosity of Lun et al.)", "krampa_tables_c_predicted.csv", 1, 0);
  scene = scene_a;
  model("model A (no kinetic theory: Bouillard's solids pressure, mu_s = 1e-8 Pa s)",
        "krampa_tables_c_predicted_model_a.csv", 1, 0);
  scene = scene_bt;
  model("model B in full (the kinetic pressure in the radial balance, theta transported)",
        "krampa_tables_c_predicted_model_b_full.csv", 1, 2);
  scene = scene_btb;
  model("model B in full, the drag's switch blended (Huilin & Gidaspow 2003)",
        "krampa_tables_c_predicted_model_b_full_blend.csv", 1, 0);
  scene = scene_c;
  model("model C (Peirano & Leckner's solids viscosity, Tchen's k_s and k_fs, Simonin's modulation and dispersion)",
        "krampa_tables_c_predicted_model_c.csv", 0, 0);
  /* model C with k_s and k_fs transported: every run converges; each table's mean error of the average gradient
     as measured here (docs/pipe.md) to 1 point; up and down within 10 % of their difference in every row of the
     40-45 % tables */
  scene = scene_ct;
  double ks_c = 0.0;
  score sc[7];
  model_scored("model C, k_s and k_fs transported (Krampa eqs 5.20, 5.23)",
               "krampa_tables_c_predicted_model_c_transported.csv", 0, 0, &ks_c, sc);
  const double mean_avg[7] = {-4.3, -64.5, -58.6, -48.9, -44.4, -35.8, -25.2};
  for (int k = 0; k < 7; ++k) {
    CHECK_MSG(fabs(100.0 * sc[k].mean_avg - mean_avg[k]) < 1.0,
              "model C transported, table %d: mean error %.2f %%, "
              "recorded %.1f %%",
              k + 1, 100.0 * sc[k].mean_avg, mean_avg[k]);
    if (k >= 4)
      CHECK_MSG(sc[k].n_ud_ok == sc[k].n, "table %d: %d of %d up and down within 10 %%", k + 1, sc[k].n_ud_ok, sc[k].n);
  }
  /* the same with Johnson & Jackson's solids wall (Krampa's model C wall), the roughness above (the 5 % table
     cannot calibrate one: its gradients are above the data with the smoothest wall); printed only */
  scene = scene_cj;
  model_scored("model C transported, Johnson & Jackson's solids wall", "krampa_tables_c_predicted_model_c_jj.csv", 0, 0,
               &ks_c, NULL);
}

static void variants_added(void) {
  /* Saffman's shear lift ([closure.lift] model = saffman_mei, damped at the wall) added to models B, A and B in full
     (blended drag), each calibrated on the 5 % table as before; the same targets asserted as without it */
  scene = scene_bl;
  double ks_bl = 0.0;
  score sl[7];
  model_scored("model B with Saffman-Mei lift", "krampa_tables_c_predicted_model_b_lift.csv", 1, 0, &ks_bl, sl);
  /* each table's mean error of the average gradient as measured here (docs/pipe.md), to 1 point: the lift moves
     model B's by +0.0 to +0.5 points (up-flow and down-flow move in opposite directions) */
  const double mean_bl[7] = {-2.1, -7.1, -11.3, -12.7, -22.4, -25.6, -13.0};
  for (int k = 0; k < 7; ++k)
    CHECK_MSG(fabs(100.0 * sl[k].mean_avg - mean_bl[k]) < 1.0,
              "model B with lift, table %d: mean error %.2f %%, recorded %.1f %%", k + 1, 100.0 * sl[k].mean_avg,
              mean_bl[k]);
  scene = scene_al;
  model("model A with Saffman-Mei lift", "krampa_tables_c_predicted_model_a_lift.csv", 1, 0);
  scene = scene_btbl;
  model("model B in full (blended drag) with Saffman-Mei lift", "krampa_tables_c_predicted_model_b_full_blend_lift.csv",
        1, 0);
  /* Coulomb's wall friction (wall_stress/coulomb, mu_w = 0.4 not fitted) on models B and B in full (blended drag),
     each calibrated on the 5 % table as before: printed, and every run converging */
  scene = scene_bw;
  double ks_bw = 0.0;
  score sw[7];
  model_scored("model B with Coulomb wall friction", "krampa_tables_c_predicted_model_b_coulomb.csv", 0, 0, &ks_bw, sw);
  scene = scene_btbw;
  double ks_btbw = 0.0;
  score stw[7];
  model_scored("model B in full (blended drag) with Coulomb wall friction",
               "krampa_tables_c_predicted_model_b_full_blend_coulomb.csv", 0, 0, &ks_btbw, stw);
  /* each table's mean error of the average gradient as measured here (docs/pipe.md, "Coulomb wall friction"), to 1
     point: the kinetic pressure at the wall grows with V, so the friction raises the high-velocity rows most (model
     B at 45 %, 3.37 m/s up-flow: tau_sw 219 Pa, the average +352 %) and the low-velocity rows, the misses, least */
  const double mean_bw[7] = {-2.1, -4.5, -6.4, -3.9, -8.8, 26.4, 14.7};
  const double mean_btbw[7] = {-2.1, -7.3, -10.8, -11.1, -18.6, -16.4, -1.8};
  for (int k = 0; k < 7; ++k) {
    CHECK_MSG(fabs(100.0 * sw[k].mean_avg - mean_bw[k]) < 1.0,
              "model B with Coulomb friction, table %d: mean error %.2f %%, recorded %.1f %%", k + 1,
              100.0 * sw[k].mean_avg, mean_bw[k]);
    CHECK_MSG(fabs(100.0 * stw[k].mean_avg - mean_btbw[k]) < 1.0,
              "model B in full with Coulomb friction, table %d: mean error %.2f %%, recorded %.1f %%", k + 1,
              100.0 * stw[k].mean_avg, mean_btbw[k]);
  }
  /* the loop ([pipe] loop = true): each row's up-flow and down-flow sections share the solids at one solids flux,
     their mean fraction the nominal (Krampa 2009 section 3.2), each variant calibrated on the 5 % table as before;
     the same targets asserted as in the sections at the nominal fraction, and each table's mean error as recorded
     (docs/pipe.md, "The loop") to 1 point */
  loop = 1;
  scene = scene_b;
  double ks_bo = 0.0;
  score so[7];
  model_scored("model B as the loop", "krampa_tables_c_predicted_model_b_loop.csv", 1, 0, &ks_bo, so);
  const double mean_bo[7] = {-0.5, -6.1, -11.0, -12.8, -22.5, -26.2, -14.5};
  for (int k = 0; k < 7; ++k)
    CHECK_MSG(fabs(100.0 * so[k].mean_avg - mean_bo[k]) < 1.0,
              "model B as the loop, table %d: mean error %.2f %%, recorded %.1f %%", k + 1, 100.0 * so[k].mean_avg,
              mean_bo[k]);
  loop = 0;
}

/* The loop's slip against what the tables need: for each table's slowest row, the model's in-situ difference
   c_u - c_d and the one that would close the measured average with the model's friction unchanged,
     (c_u - c_d)_needed = (c_u - c_d) + 2 ((dP/L)_avg,measured - (dP/L)_avg,model) / ((rho_s - rho_f) g)
   (the loop's average, docs/pipe.md "The loop"), each as the sections' mean slip it takes at one solids flux with a
   uniform fraction, s = (c_u - c_d) V / (2 C (1 - C)) (first order in s / V); and the other reading, the model's
   shares kept: each section's wall stress from its measured gradient (Krampa 2009 eqs 3.6-3.7),
   tau_u = (D/4)((dP/L)_u - (c_u rho_s + (1 - c_u) rho_f - rho_f) g), tau_d = (D/4)((dP/L)_d + (c_d ... ) g), against
   the model's. The needed slips of C.5-C.7 into need (m/s; may be NULL). */
static void slip_report(const char *label, double *need_out) {
  printf(
      "%s: the slowest row of each table\n| table | V (m/s) | c_u - c_d | needed | slip (m/s) | needed | tau_u (Pa) "
      "| from data | tau_d (Pa) | from data |\n|---|---|---|---|---|---|---|---|---|---|\n",
      label);
  const char *tables[7] = {"C.1", "C.2", "C.3", "C.4", "C.5", "C.6", "C.7"};
  for (int k = 0; k < 7; ++k) {
    const row *lo = NULL;
    for (int i = 0; i < n_rows; ++i)
      if (strcmp(rows[i].table, tables[k]) == 0 && isfinite(rows[i].p_up) && isfinite(rows[i].p_down) &&
          (!lo || rows[i].v < lo->v))
        lo = &rows[i];
    if (!lo) continue;
    const double D = 0.0532, drg = (2500.0 - water_density(lo->t)) * 9.81, dc = lo->cu - lo->cd;
    const double need = dc + 2e3 * (lo->avg - 0.5 * (lo->p_up + lo->p_down)) / drg,
                 f = lo->v / (2.0 * lo->c * (1.0 - lo->c));
    const double tu = 0.25 * D * (1e3 * lo->p_up - lo->cu * drg), td = 0.25 * D * (1e3 * lo->p_down + lo->cd * drg);
    const double tu_m = 0.25 * D * (1e3 * lo->up - lo->cu * drg), td_m = 0.25 * D * (1e3 * lo->down + lo->cd * drg);
    printf("| %s | %.2f | %.4f | %.4f | %.4f | %.4f | %.2f | %.2f | %.2f | %.2f |\n", tables[k], lo->v, dc, need,
           dc * f, need * f, tu, tu_m, td, td_m);
    if (need_out && k >= 4) need_out[k - 4] = need * f;
  }
}

/* Candidates for the slip the loop lacks (argument "slip"), each as the loop, calibrated on the 5 % table: Di Felice's
   (1994) drag (Reynolds-dependent voidage exponent, for Krampa's Re_t of about 38) and Richardson & Zaki's with
   their exponent for that Re_t in place of Ergun's / Wen-Yu's; Saffman's lift and the kinetic pressure (the radial
   distribution of the solids). Printed with the slip they give against the slip the tables need. */
static void slip_candidates(void) {
  static char sdf[8192 + 64], srz[8192 + 128];
  const char *dr = strstr(scene_b, "[closure.drag]\nmodel = gidaspow\n");
  CHECK_MSG(dr != NULL, "vertical_pipe.ini has no [closure.drag] model = gidaspow");
  if (!dr) return;
  const size_t at = (size_t)(dr - scene_b), len = strlen("[closure.drag]\nmodel = gidaspow\n");
  snprintf(sdf, sizeof sdf, "%.*s[closure.drag]\nmodel = di_felice\n%s", (int)at, scene_b, scene_b + at + len);
  /* Richardson & Zaki (1954), for 1 < Re_t < 200: n = (4.45 + 18 d/D) Re_t^-0.1; Re_t = 40 (u_t = 0.0755 m/s from
     Schiller-Naumann, water at 22.9 C), d/D = 0.0094: n = 3.19 */
  snprintf(srz, sizeof srz,
           "%.*s[closure.drag]\nmodel = richardson_zaki_consistent\nterminal_velocity = schiller_naumann\nn = 3.19\n%s",
           (int)at, scene_b, scene_b + at + len);
  struct {
    const char *label, *csv, *text;
  } c[] = {
      {"model B as the loop", "krampa_tables_c_predicted_model_b_loop_slip.csv", scene_b},
      {"model B as the loop, Di Felice's drag", "krampa_tables_c_predicted_model_b_loop_di_felice.csv", sdf},
      {"model B as the loop, Richardson-Zaki drag n = 3.19", "krampa_tables_c_predicted_model_b_loop_rz.csv", srz},
      {"model B as the loop with Saffman-Mei lift", "krampa_tables_c_predicted_model_b_loop_lift.csv", scene_bl},
      {"model B in full (blended drag) as the loop", "krampa_tables_c_predicted_model_b_full_blend_loop.csv",
       scene_btb},
  };
  /* the kept variant's (Richardson-Zaki, n = 3.19) mean errors as measured here (docs/pipe.md), to 1 point; every
     one of its runs converges */
  const double mean_rz[7] = {-0.3, -8.3, -13.2, -15.0, -24.0, -26.7, -15.5};
  /* Schiller-Naumann's terminal velocity of one 0.5 mm bead in water at 22-29 C (0.0755 m/s at 22.9 C; within 4 %
     over the tables' temperatures) */
  const double u_t = 0.0755;
  loop = 1;
  for (size_t k = 0; k < sizeof c / sizeof c[0]; ++k) {
    scene = c[k].text;
    double ks = 0.0, need[3] = {0};
    score sc[7];
    model_scored(c[k].label, c[k].csv, 0, c[k].text == srz ? 0 : 1, &ks, sc);
    slip_report(c[k].label, need);
    if (c[k].text == srz)
      for (int j = 0; j < 7; ++j)
        CHECK_MSG(fabs(100.0 * sc[j].mean_avg - mean_rz[j]) < 1.0,
                  "model B as the loop, Richardson-Zaki drag, table %d: mean error %.2f %%, recorded %.1f %%", j + 1,
                  100.0 * sc[j].mean_avg, mean_rz[j]);
    /* the slip that would close the 40-45 % tables' slowest rows exceeds the terminal velocity of one bead (3.3-4.2
       times): more than any drag law gives a homogeneous suspension, whose slip is below u_t */
    if (k == 0)
      for (int j = 0; j < 3; ++j)
        CHECK_MSG(need[j] > 3.0 * u_t, "table C.%d: the slip needed %.3f m/s, not above 3 u_t", j + 5, need[j]);
  }
  loop = 0;
}
