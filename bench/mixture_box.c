/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The upright settling box (tests/scenes/mixture_box.h) of the 2-D mixture
 * model: the L1 error of phi against the exact Kynch solution against CPU
 * time, with the largest mixture speed of each run, and OpenFOAM's
 * driftFluxFoam on the same meshes (Debian package openfoam: a comparison,
 * never a dependency; the case is written by bench/driftflux/box_case.sh).
 *
 *   bench_mixture_box ini N [line]        the scene's INI text (4 x N cells, or a column of N)
 *   bench_mixture_box measure FILE T      L1 of phi at T and max |j| (at T, over the run) of an output file
 *   bench_mixture_box study [N_MAX]       4 x N and the column of N, N = 50 .. N_MAX (400): the smooth cut-off
 *   bench_mixture_box foam SOURCE_DIR [N_MAX] [ROUNDS]
 *                                         4 x N, N = 50 .. N_MAX (400), sluice and driftFluxFoam interleaved in
 *                                         ROUNDS rounds (2; the fastest CPU time of each kept): the step cut-off
 *
 * study: Vesilind's law with the smooth cut-off (the tests' case), t = 570 s
 * (0.8 of the fronts' meeting time), dt = 10 s.
 * foam: the law both codes have, 10^(-a phi) held at phi_max (sluice's
 * packing_cutoff = step; driftFluxFoam's simple model bounded by alphaMax),
 * a = 4, phi_max = 1,
 * t = 720 s (0.8 of the fronts' meeting time 905 s). sluice: dt = 10 s,
 * Stokes flow, as a run goes (the flow known at rest is not solved:
 * `sluice`), with every step solved by the monolithic step (`sluice_every_solve`), and so with
 * the split step ([flow] scheme = projection: `sluice_every_solve_projection`).
 * driftFluxFoam: the largest of 10, 5, 2, 1, 0.5, 0.25, 0.1 s with which its
 * run ends bounded, and 1/2, 1/4, 1/8 of it (its error falls with the
 * step), the alpha equation sub-cycled to a drift Courant number of 0.5 (its
 * explicit MULES step), PIMPLE with two pressure correctors; the mixture velocity it reports is the mass average. CPU
 * seconds: the process CPU time of each run (a child process: bench_child.h;
 * driftFluxFoam's from its rusage, blockMesh not counted). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "../tests/scenes/mixture_box.h"
#include "bench_child.h"
#include "bench_machine.h"
#include "core/study/child.h"

static double cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* foam: a = 4, held at 1 (the default alphaMax): the flux drops from 2.2e-7 u_t to 0 there, so that the drop costs
 * sluice's explicit transport no sub-steps */
static const double t_smooth = 570.0, t_step = 720.0, foam_a = 4.0, foam_phi_max = 1.0;

typedef struct run_arg {
  box_scene s;
  char out[256];
  double t_end;
  int step; /* the step cut-off */
} run_arg;

typedef struct run_result {
  int rc;
  double cpu, l1, speed, worst;
  long steps, solves_skipped;
  char msg[256];
} run_result;

static void run_child(void *arg, void *result) {
  const run_arg *a = arg;
  run_result *r = result;
  kynch k;
  sl_diag d = {{0}};
  sluice_summary res;
  memset(&res, 0, sizeof res);
  if (a->step ? kx_init(&k, kx_vesilind(box_ut, foam_a, foam_phi_max, 1), box_H, box_phi0) : box_exact(&k, 0)) {
    r->rc = -1;
    return;
  }
  double c0 = cpu_seconds();
  r->rc = box_run(&a->s, a->out, &res, &d);
  r->cpu = cpu_seconds() - c0;
  r->steps = res.steps, r->solves_skipped = res.solves_skipped;
  snprintf(r->msg, sizeof r->msg, "%.200s", r->rc ? d.msg : "");
  r->l1 = box_l1(a->out, a->t_end, &k);
  r->speed = box_speed(a->out, a->t_end, &r->worst);
}

/* One sluice run in a child process (every: 1 solve the flow at every step, also where it is known; 2 the same with
 * the split step, [flow] scheme = projection); 0 or -1 (why in r->msg). */
static int box_timed_run(int n, int line, int step, int every, run_result *r) {
  run_arg a = {.s = {.n = n,
                     .line = line,
                     .rho_s = 1006.0,
                     .settling = step ? 2 : 1,
                     .dt = 10.0,
                     .a = step ? foam_a : 0.0,
                     .phi_max = step ? foam_phi_max : 0.0,
                     .solve_every_step = every > 0,
                     .projection = every > 1,
                     .monolithic = every == 1},
               .t_end = step ? t_step : t_smooth,
               .step = step};
  a.s.end = a.s.every = a.t_end;
  snprintf(a.out, sizeof a.out, "bench_box_%s_%d.h5", line ? "1d" : "2d", n);
  char why[256];
  int rc = bench_in_child(run_child, &a, r, sizeof *r, why, sizeof why);
  if (rc) snprintf(r->msg, sizeof r->msg, "%.200s", why);
  bench_remove_output(a.out);
  return rc || r->rc ? -1 : 0;
}

/* ---- driftFluxFoam ------------------------------------------------------------ */

/* The n x comp numbers of an OpenFOAM ASCII field's internalField into v (malloc'ed); its count, or -1. */
static int foam_read(const char *path, int comp, double **v) {
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  static char buf[1 << 16];
  int n = -1, got = 0;
  *v = NULL;
  while (fgets(buf, sizeof buf, f))
    if (strncmp(buf, "internalField", 13) == 0) break;
  if (!feof(f) && strstr(buf, "nonuniform")) {
    if (fscanf(f, "%d", &n) == 1 && n > 0 && (*v = malloc((size_t)n * comp * sizeof **v))) {
      int c;
      while (got < n * comp && (c = fgetc(f)) != EOF) {
        if (c == '(' || c == ')' || c == ' ' || c == '\n' || c == '\t' || c == '\r') continue;
        ungetc(c, f);
        if (fscanf(f, "%lf", &(*v)[got]) != 1) break;
        ++got;
      }
    }
  }
  fclose(f);
  if (n < 0 || got != n * comp) {
    free(*v), *v = NULL;
    return -1;
  }
  return n;
}

typedef struct foam_result {
  double cpu, l1, speed, alpha_max, dt;
  char msg[256];
} foam_result;

/* Writes, meshes and runs the case in dir with steps dt; 0 or -1 (why in r->msg). */
static int foam_run(const char *src, const char *dir, int n, double dt, foam_result *r, const kynch *k) {
  char cmd[8192];
  double h = box_H / n, drift = box_ut * dt / h;
  int sub = (int)ceil(drift / 0.5);
  r->dt = dt;
  snprintf(cmd, sizeof cmd,
           "rm -rf '%s' && sh '%s/bench/driftflux/box_case.sh' '%s' %d %g %d %g %g %g && cd '%s' && "
           "WM_PROJECT_DIR=/usr/share/openfoam blockMesh > blockMesh.log 2>&1",
           dir, src, dir, n, dt, sub, t_step, foam_a, foam_phi_max, dir);
  if (system(cmd) != 0) {
    snprintf(r->msg, sizeof r->msg, "the case or blockMesh failed (%.100s)", dir);
    return -1;
  }
  char *const argv[] = {"driftFluxFoam", NULL};
  const char *const env[] = {"WM_PROJECT_DIR=/usr/share/openfoam", NULL};
  sl_child_opts co = {
      .argv = argv, .result_fd = -1, .dir = dir, .env = env, .out = "driftFluxFoam.log", .err = "driftFluxFoam.log"};
  sl_child_result cr;
  if (sl_child_run(&co, &cr) || cr.exit_code != 0 || cr.signal_number) {
    snprintf(r->msg, sizeof r->msg, "driftFluxFoam failed (exit %d, signal %d%s%.60s; %.100s/driftFluxFoam.log)",
             cr.exit_code, cr.signal_number, cr.message[0] ? ", " : "", cr.message, dir);
    return -1;
  }
  r->cpu = cr.cpu; /* the child's own user + system time, from wait4 */
  char path[4096];
  double *a = NULL, *u = NULL;
  snprintf(path, sizeof path, "%s/%g/alpha.sludge", dir, t_step);
  int na = foam_read(path, 1, &a);
  snprintf(path, sizeof path, "%s/%g/U", dir, t_step);
  int nu = foam_read(path, 3, &u);
  if (na != BOX_NX * n || nu != na) {
    free(a), free(u);
    snprintf(r->msg, sizeof r->msg, "%.100s: no fields at t = %g", dir, t_step);
    return -1;
  }
  /* blockMesh numbers the cells x first: row j holds cells 4 j .. 4 j + 3 */
  kx_profile p = kx_at(k, t_step);
  r->l1 = r->speed = r->alpha_max = 0.0;
  for (int j = 0; j < n; ++j) {
    double exact = kx_integral(k, &p, j * h, (j + 1) * h);
    for (int i = 0; i < BOX_NX; ++i) {
      int c = BOX_NX * j + i;
      r->l1 += fabs(a[c] * h - exact) / BOX_NX;
      r->alpha_max = fmax(r->alpha_max, a[c]);
      for (int e = 0; e < 3; ++e) r->speed = fmax(r->speed, fabs(u[3 * c + e]));
    }
  }
  free(a), free(u);
  if (!(r->alpha_max <= foam_phi_max + 0.01) || !isfinite(r->l1)) {
    snprintf(r->msg, sizeof r->msg, "dt = %g: alpha up to %g", dt, r->alpha_max);
    return -1;
  }
  return 0;
}

/* The largest of these steps with which driftFluxFoam ends with bounded fields (it diverges with larger ones:
 * its buoyancy is explicit too); 0 when none. */
static const double foam_dts[] = {10.0, 5.0, 2.0, 1.0, 0.5, 0.25, 0.1};

static double foam_stable_dt(const char *src, const char *dir, int n, const kynch *k) {
  for (size_t i = 0; i < sizeof foam_dts / sizeof foam_dts[0]; ++i) {
    foam_result f;
    if (foam_run(src, dir, n, foam_dts[i], &f, k) == 0) return foam_dts[i];
    fprintf(stderr, " [dt = %g: %s]", foam_dts[i], f.msg);
  }
  return 0.0;
}

static int foam_study(const char *src, int n_max, int rounds) {
  kynch k;
  if (kx_init(&k, kx_vesilind(box_ut, foam_a, foam_phi_max, 1), box_H, box_phi0)) return 1;
  enum { MAX_N = 8, N_DT = 4 }; /* driftFluxFoam at its largest stable step and 1/2, 1/4, 1/8 of it */
  int ns[MAX_N], nn = 0;
  for (int n = 50; n <= n_max && nn < MAX_N; n *= 2) ns[nn++] = n;
  run_result best_s[MAX_N][3]; /* skipping the known solves, solving every step, and so split */
  static const char *const names[3] = {"sluice", "sluice_every_solve", "sluice_every_solve_projection"};
  foam_result best_f[MAX_N][N_DT];
  int ok_s[MAX_N][3] = {{0}}, ok_f[MAX_N][N_DT] = {{0}};
  double dts[MAX_N];
  for (int i = 0; i < nn; ++i) {
    char dir[256];
    snprintf(dir, sizeof dir, "bench_box_foam_%d", ns[i]);
    fprintf(stderr, "driftFluxFoam 4 x %d: the largest stable step ...", ns[i]);
    dts[i] = foam_stable_dt(src, dir, ns[i], &k);
    fprintf(stderr, " %g s\n", dts[i]);
  }
  char machine[256];
  bench_machine_describe(machine, sizeof machine);
  for (int r = 0; r < rounds; ++r)
    for (int i = 0; i < nn; ++i) {
      fprintf(stderr, "round %d: sluice 4 x %d ...", r + 1, ns[i]);
      for (int e = 0; e < 3; ++e) {
        run_result s;
        if (box_timed_run(ns[i], 0, 1, e, &s) == 0 && (!ok_s[i][e] || s.cpu < best_s[i][e].cpu))
          best_s[i][e] = s, ok_s[i][e] = 1;
      }
      char dir[256];
      snprintf(dir, sizeof dir, "bench_box_foam_%d", ns[i]);
      for (int j = 0; j < N_DT && dts[i] > 0.0; ++j) {
        foam_result f;
        double dt = dts[i] / (1 << j);
        fprintf(stderr, " driftFluxFoam dt = %g ...", dt);
        if (foam_run(src, dir, ns[i], dt, &f, &k) == 0) {
          if (!ok_f[i][j] || f.cpu < best_f[i][j].cpu) best_f[i][j] = f, ok_f[i][j] = 1;
        } else {
          fprintf(stderr, " %s", f.msg);
        }
      }
      fprintf(stderr, "\n");
    }
  printf(
      "# %s\n# upright box %g x %g m, 4 x N cells, phi0 = %g, u_t 10^(-%g phi) held at phi_max = %g, u_t = %g m/s, "
      "t = %g s; fastest of %d interleaved rounds\n",
      machine, box_W, box_H, box_phi0, foam_a, foam_phi_max, box_ut, t_step, rounds);
  printf("code,cells_vertical,cells,dt_s,cpu_s,l1,max_speed,max_phi\n");
  for (int i = 0; i < nn; ++i) {
    for (int e = 0; e < 3; ++e)
      if (ok_s[i][e])
        printf("%s,%d,%d,10,%.4g,%.4e,%.3e,\n", names[e], ns[i], BOX_NX * ns[i], best_s[i][e].cpu, best_s[i][e].l1,
               best_s[i][e].worst);
    for (int j = 0; j < N_DT; ++j)
      if (ok_f[i][j])
        printf("driftFluxFoam,%d,%d,%g,%.4g,%.4e,%.3e,%.6f\n", ns[i], BOX_NX * ns[i], best_f[i][j].dt, best_f[i][j].cpu,
               best_f[i][j].l1, best_f[i][j].speed, best_f[i][j].alpha_max);
  }
  return 0;
}

int main(int argc, char **argv) {
  kynch k;
  if (box_exact(&k, 0)) return 1;
  if (argc >= 3 && strcmp(argv[1], "ini") == 0) {
    static char text[8192];
    box_scene s = {.n = atoi(argv[2]),
                   .line = argc > 3,
                   .rho_s = 1006.0,
                   .settling = 1,
                   .end = t_smooth,
                   .dt = 10.0,
                   .every = 10.0};
    box_text(&s, text, sizeof text);
    fputs(text, stdout);
    return 0;
  }
  if (argc >= 4 && strcmp(argv[1], "measure") == 0) {
    double t = atof(argv[3]), worst = NAN;
    double l1 = box_l1(argv[2], t, &k), v = box_speed(argv[2], t, &worst);
    printf("%s: t = %g: L1 %.4e, max |j| %.3e (over the run %.3e)\n", argv[2], t, l1, v, worst);
    return isnan(l1);
  }
  if (argc >= 3 && strcmp(argv[1], "foam") == 0)
    return foam_study(argv[2], argc > 3 ? atoi(argv[3]) : 400, argc > 4 ? atoi(argv[4]) : 2);
  if (argc >= 2 && strcmp(argv[1], "study") != 0) {
    fprintf(stderr,
            "usage: bench_mixture_box ini N [line] | measure FILE T | study [N_MAX] | foam SOURCE_DIR [N_MAX] "
            "[ROUNDS]\n");
    return 2;
  }
  int n_max = argc > 2 ? atoi(argv[2]) : 400;
  char machine[256];
  bench_machine_describe(machine, sizeof machine);
  printf(
      "# %s\n# upright box %g x %g m, phi0 = %g, Vesilind u_t = %g m/s, a = %g, phi_max = %g, t = %g s "
      "(fronts meet at %.1f s), dt = 10 s\n",
      machine, box_W, box_H, box_phi0, box_ut, box_a, box_phi_max, t_smooth, k.t1);
  printf("model,cells_vertical,cells,cpu_s,steps,solves_skipped,l1,max_speed_run\n");
  for (int n = 50; n <= n_max; n *= 2)
    for (int line = 0; line < 2; ++line) {
      run_result r;
      const char *model = line ? "sluice_1d" : "sluice_2d";
      if (box_timed_run(n, line, 0, 0, &r)) {
        printf("%s,%d,%d,failed,,,,,%s\n", model, n, line ? n : BOX_NX * n, r.msg);
        continue;
      }
      printf("%s,%d,%d,%.4g,%ld,%ld,%.4e,%.3e\n", model, n, line ? n : BOX_NX * n, r.cpu, r.steps, r.solves_skipped,
             r.l1, r.worst);
      fflush(stdout);
    }
  return 0;
}
