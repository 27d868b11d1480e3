/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The cost of the fully developed pipe model (core/models/pipe) on configs/vertical_pipe.ini (Krampa 2009,
 * 0.5 mm glass beads at 25 %, V = 3.02 m/s, up-flow), against the budget (one row of model B on 40
 * radial cells under 0.5 s of CPU; the 152 runs of Tables C.1-C.7 under a minute) and the thesis's CFX-4
 * figures (50 x 40 cells: 3.3e3 s model A, 3.2e4 s model B, 3.04e4 s model C per case, Krampa section 6):
 *
 *  - row: the CPU time of one run (sluice_open_text + sluice_run, in this process, the best of --repeat R,
 *    default 5) for model A (no kinetic theory; Bouillard's solids pressure), model B as the scene gives it
 *    (the kinetic viscosity, theta of its local balance) and model B in full (the kinetic pressure, theta
 *    transported), with the iterations;
 *  - study: every row of configs/data/krampa_2009_tables_c.csv in up-flow and down-flow (152 runs) with each
 *    variant, sequentially in this process: CPU and wall seconds, the runs that stopped;
 *  - developing: the developing pipe (`[pipe] length = 4`, 50 axial x 40 radial cells, the thesis's grid, marched
 *    along z) of models A, B and B in full on the scene and of Krampa's P1 case (configs/pvc_pipe.ini, D = 0.04 m: the
 *    thesis's own CFX-4 set-up; free slip as shipped and with no-slip solids), the best CPU of --repeat R, and
 *    the thesis's 3.3e3 s (A) and 3.2e4 s (B) over it;
 *  - work-precision: the up-flow manometric gradient of model B in full on 10-320 radial cells (the wall cell
 *    held at y+ = 40), its difference from 640 cells, and the CPU time of each run.
 *
 *   bench_pipe_cost [SOURCE_DIR] [--csv PATH] [--repeat R]
 *
 * CSV on stdout (and in --csv PATH), '#' lines for the machine and the budget. Exit status 1 when a run of the
 * row or work-precision parts failed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_machine.h"
#include "core/io/output.h"
#include "sluice/sluice.h"

static double cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0.0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double wall_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_MONOTONIC, &ts)) return 0.0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static char scene_b[8192], scene_a[8192], scene_bt[8192], out_file[128];

static int read_file(const char *path, char *buf, size_t cap) {
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(buf, 1, cap - 1, f) : 0;
  if (f) fclose(f);
  buf[n] = '\0';
  if (!n) fprintf(stderr, "bench_pipe_cost: cannot read %s\n", path);
  return n > 0 ? 0 : 1;
}

/* The three variants of the scene (as tests/models/test_pipe_krampa.c builds them). */
static int variants(void) {
  char *gran = strstr(scene_b, "\n[closure.granular]"), *kp = strstr(scene_b, "kinetic_pressure = false");
  if (!gran || !kp) {
    fprintf(stderr, "bench_pipe_cost: vertical_pipe.ini has no [closure.granular] or kinetic_pressure = false\n");
    return 1;
  }
  snprintf(scene_a, sizeof scene_a,
           "%.*s\n[closure.solids_pressure]\nmodel = gidaspow_elastic\nmodulus_ref = 1\ncompaction = 600\n"
           "phi_max = 0.63\n",
           (int)(gran - scene_b), scene_b);
  snprintf(scene_bt, sizeof scene_bt, "%.*skinetic_pressure = true\ngranular_temperature = transport%s",
           (int)(kp - scene_b), scene_b, kp + strlen("kinetic_pressure = false"));
  return 0;
}

/* One run: 0 or the sluice error; the CPU seconds, the iterations and the manometric gradient. */
static int run(const char *scene, const char *const *sets_in, double *cpu, double *its, double *grad, char *why,
               size_t len) {
  const char *sets[16];
  int n = 0;
  for (; sets_in[n] && n < 14; ++n) sets[n] = sets_in[n];
  if (scene == scene_a) sets[n++] = "solid.viscosity=1e-8"; /* model A's constant solids viscosity */
  sets[n] = NULL;
  sluice *s = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets};
  sluice_run_opts ro = {.output = out_file, .version = "bench"};
  sluice_summary sum;
  double t0 = cpu_seconds();
  int rc = sluice_open_text(scene, strlen(scene), "vertical_pipe.ini", &oo, &s, &e);
  if (!rc) rc = sluice_run(s, &ro, &sum, &e);
  sluice_close(s);
  *cpu = cpu_seconds() - t0;
  *its = *grad = NAN;
  if (rc) {
    snprintf(why, len, "%s", e.msg);
    return rc;
  }
  sl_diag d = {{0}};
  double t;
  if (sl_output_read_scalar(out_file, "iterations", INFINITY, its, &t, &d) ||
      sl_output_read_scalar(out_file, "manometric_gradient", INFINITY, grad, &t, &d)) {
    snprintf(why, len, "%s", d.msg);
    return 1;
  }
  return 0;
}

int main(int argc, char **argv) {
  const char *src = ".", *csv = NULL;
  int repeat = 5;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else src = argv[i];
  }
  if (repeat < 1) repeat = 1;
  snprintf(out_file, sizeof out_file, "/tmp/sluice_bench_pipe_%ld.h5", (long)getpid());
  char path[4096];
  static char table[1 << 16];
  snprintf(path, sizeof path, "%s/configs/vertical_pipe.ini", src);
  if (read_file(path, scene_b, sizeof scene_b) || variants()) return 2;
  snprintf(path, sizeof path, "%s/configs/data/krampa_2009_tables_c.csv", src);
  if (read_file(path, table, sizeof table)) return 2;
  FILE *out[2] = {stdout, csv ? fopen(csv, "w") : NULL};
  char machine[512];
  bench_machine_describe(machine, sizeof machine);
  int failed = 0;
  const char *names[3] = {"model_a", "model_b", "model_b_full"};
  const char *scenes[3] = {scene_a, scene_b, scene_bt};
  char line[4][512];
  int nl = 0;
  /* row */
  for (int v = 0; v < 3; ++v) {
    double best = INFINITY, its = NAN, grad = NAN, cpu;
    char why[2100] = "";
    for (int r = 0; r < repeat; ++r) {
      const char *sets[] = {NULL};
      if (run(scenes[v], sets, &cpu, &its, &grad, why, sizeof why)) {
        fprintf(stderr, "row %s: %s\n", names[v], why);
        failed = 1;
        break;
      }
      best = fmin(best, cpu);
    }
    snprintf(line[nl++], sizeof line[0], "row,%s,40,%.0f,%.6f,%.3f", names[v], its, best, grad);
  }
  /* the developing pipe: Krampa's CFX-4 set-up, 4 m on 50 axial x 40 radial cells, marched along z */
  static char scene_p1[8192];
  snprintf(path, sizeof path, "%s/configs/pvc_pipe.ini", src);
  if (read_file(path, scene_p1, sizeof scene_p1)) return 2;
  const char *dnames[5] = {"model_a", "model_b", "model_b_full", "pvc_p1_model_b", "pvc_p1_model_b_no_slip"};
  const char *dscenes[5] = {scene_a, scene_b, scene_bt, scene_p1, scene_p1};
  char dline[5][512];
  for (int v = 0; v < 5; ++v) {
    double best = INFINITY, its = NAN, grad = NAN, cpu;
    char why[2100] = "";
    for (int r = 0; r < repeat; ++r) {
      const char *sets[] = {"pipe.length=4", "pipe.axial_cells=50", v == 4 ? "pipe.solids_wall=no_slip" : NULL, NULL};
      if (run(dscenes[v], sets, &cpu, &its, &grad, why, sizeof why)) {
        fprintf(stderr, "developing %s: %s\n", dnames[v], why);
        failed = 1;
        break;
      }
      best = fmin(best, cpu);
    }
    snprintf(dline[v], sizeof dline[0], "developing,%s,50x40,%.0f,%.6f,%.3f,%.3g,%.3g", dnames[v], its, best, grad,
             3.3e3 / best, 3.2e4 / best);
  }
  /* study */
  char study[3][256];
  for (int v = 0; v < 3; ++v) {
    static char copy[1 << 16];
    memcpy(copy, table, sizeof copy);
    long runs = 0, stopped = 0;
    double c0 = cpu_seconds(), w0 = wall_seconds(), its_sum = 0.0;
    for (char *l = strtok(copy, "\n"); l; l = strtok(NULL, "\n")) {
      char tab[8];
      double c, q, dn, up, T, avg, V;
      if (l[0] == '#' || sscanf(l, "%7[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", tab, &c, &q, &dn, &up, &T, &avg, &V) != 8)
        continue;
      /* water at T: Kell (1975) density, Vogel's viscosity (as the test) */
      double rho = (999.83952 + 16.945176 * T - 7.9870401e-3 * T * T - 46.170461e-6 * pow(T, 3) +
                    105.56302e-9 * pow(T, 4) - 280.54253e-12 * pow(T, 5)) /
                   (1.0 + 16.879850e-3 * T);
      double mu = 2.414e-5 * pow(10.0, 247.8 / (T + 273.15 - 140.0));
      for (int down = 0; down < 2; ++down) {
        char s[5][80];
        snprintf(s[0], 80, "fluid.density=%.10g", rho), snprintf(s[1], 80, "fluid.viscosity=%.10g", mu);
        snprintf(s[2], 80, "pipe.bulk_velocity=%.10g", V), snprintf(s[3], 80, "pipe.solids_fraction=%.10g", c);
        snprintf(s[4], 80, "flow.gravity=%s", down ? "9.81" : "-9.81");
        const char *sets[] = {s[0], s[1], s[2], s[3], s[4], NULL};
        double cpu, its, grad;
        char why[2100];
        ++runs;
        if (run(scenes[v], sets, &cpu, &its, &grad, why, sizeof why)) ++stopped;
        else its_sum += its;
      }
    }
    snprintf(study[v], sizeof study[v], "study,%s,%ld,%ld,%.3f,%.3f,%.1f", names[v], runs, stopped, cpu_seconds() - c0,
             wall_seconds() - w0, its_sum / (double)(runs - stopped));
  }
  /* work-precision, model B in full */
  const int cells[7] = {10, 20, 40, 80, 160, 320, 640};
  double g[7], c[7], it[7];
  for (int k = 0; k < 7; ++k) {
    char s[64], why[2100];
    snprintf(s, sizeof s, "pipe.cells=%d", cells[k]);
    const char *sets[] = {s, NULL};
    if (run(scene_bt, sets, &c[k], &it[k], &g[k], why, sizeof why)) {
      fprintf(stderr, "work-precision %d cells: %s\n", cells[k], why);
      failed = 1;
    }
  }
  for (int f = 0; f < 2; ++f) {
    if (!out[f]) continue;
    fprintf(out[f], "# bench_pipe_cost: configs/vertical_pipe.ini (Krampa 2009 E1, 25 %%, 3.02 m/s, up-flow)\n");
    fprintf(out[f], "# machine: %s\n", machine);
    fprintf(out[f],
            "# budget: a row of model B on 40 cells < 0.5 s CPU; the 152 runs < 60 s; CFX-4 (Krampa 2009 "
            "section 6): 3.3e3 s (A), 3.2e4 s (B), 3.04e4 s (C) per case on 50 x 40 cells\n");
    fprintf(out[f], "part,variant,cells,iterations,cpu_s,manometric_Pa_per_m\n");
    for (int k = 0; k < nl; ++k) fprintf(out[f], "%s\n", line[k]);
    fprintf(out[f], "part,variant,cells,iterations,cpu_s,manometric_Pa_per_m,cfx4_model_a_ratio,cfx4_model_b_ratio\n");
    for (int k = 0; k < 5; ++k) fprintf(out[f], "%s\n", dline[k]);
    fprintf(out[f], "part,variant,runs,stopped,cpu_s,wall_s,mean_iterations\n");
    for (int v = 0; v < 3; ++v) fprintf(out[f], "%s\n", study[v]);
    fprintf(out[f], "part,variant,cells,iterations,cpu_s,manometric_Pa_per_m,difference_from_640\n");
    for (int k = 0; k < 7; ++k)
      fprintf(out[f], "work_precision,model_b_full,%d,%.0f,%.6f,%.4f,%.3e\n", cells[k], it[k], c[k], g[k],
              g[k] / g[6] - 1.0);
  }
  if (out[1]) fclose(out[1]);
  remove(out_file);
  char xmf[160];
  snprintf(xmf, sizeof xmf, "%.*s.xmf", (int)strlen(out_file) - 3, out_file);
  remove(xmf);
  return failed;
}
