/* The upright settling box (tests/scenes/mixture_box.h): the 2-D mixture
 * model against the exact Kynch solution and the 1-D column, L1 error of phi
 * against CPU time, with the largest mixture speed it generates.
 *
 *   bench_mixture_box ini N [line]        the scene's INI text (4 x N cells, or a column of N)
 *   bench_mixture_box measure FILE T      L1 of phi at T and max |j| (at T, over the run) of an output file
 *   bench_mixture_box study [N_MAX]       N = 50, 100, ... N_MAX (default 400): 4 x N and the column, CSV
 *
 * The study ends at t = T_END (0.8 of the fronts' meeting time, 551 s) with
 * dt = 10 s, output every 10 s; CPU seconds are the process CPU time of
 * each run (in a child process, bench_child.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../tests/scenes/mixture_box.h"
#include "bench_child.h"
#include "bench_machine.h"

static double cpu_seconds(void) {
  struct timespec ts;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts)) return 0;
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct run_arg {
  box_scene s;
  char out[256];
  double t_end;
} run_arg;

typedef struct run_result {
  int rc;
  double cpu, l1, speed, worst;
  long steps;
  char msg[256];
} run_result;

static void run_child(void *arg, void *result) {
  const run_arg *a = arg;
  run_result *r = result;
  kynch k;
  sl_diag d = {{0}};
  sl_ns_result res;
  if (box_exact(&k)) {
    r->rc = -1;
    return;
  }
  double c0 = cpu_seconds();
  r->rc = box_run(&a->s, a->out, &res, &d);
  r->cpu = cpu_seconds() - c0;
  r->steps = res.steps;
  snprintf(r->msg, sizeof r->msg, "%.200s", r->rc ? d.msg : "");
  r->l1 = box_l1(a->out, a->t_end, &k);
  r->speed = box_speed(a->out, a->t_end, &r->worst);
}

int main(int argc, char **argv) {
  kynch k;
  if (box_exact(&k)) return 1;
  const double t_end = 10.0 * floor(0.8 * k.t1 / 10.0);
  if (argc >= 3 && strcmp(argv[1], "ini") == 0) {
    static char text[8192];
    box_scene s = {.n = atoi(argv[2]), .line = argc > 3, .rho_s = 1006.0, .settling = 1, .end = t_end, .dt = 10.0,
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
  if (argc >= 2 && strcmp(argv[1], "study") != 0) {
    fprintf(stderr, "usage: bench_mixture_box ini N [line] | measure FILE T | study [N_MAX]\n");
    return 2;
  }
  int n_max = argc > 2 ? atoi(argv[2]) : 400;
  char machine[256];
  bench_machine_describe(machine, sizeof machine);
  printf("# %s\n# upright box %g x %g m, phi0 = %g, Vesilind u_t = %g m/s, a = %g, phi_max = %g, t = %g s "
         "(fronts meet at %.1f s), dt = 10 s\n",
         machine, box_W, box_H, box_phi0, box_ut, box_a, box_phi_max, t_end, k.t1);
  printf("model,cells_vertical,cells,cpu_s,steps,l1,max_speed_end,max_speed_run\n");
  for (int n = 50; n <= n_max; n *= 2)
    for (int line = 0; line < 2; ++line) {
      run_arg a = {.s = {.n = n, .line = line, .rho_s = 1006.0, .settling = 1, .end = t_end, .dt = 10.0, .every = 10.0},
                   .t_end = t_end};
      snprintf(a.out, sizeof a.out, "bench_box_%s_%d.h5", line ? "1d" : "2d", n);
      run_result r;
      char why[256];
      if (bench_in_child(run_child, &a, &r, sizeof r, why, sizeof why) || r.rc) {
        printf("%s,%d,%d,failed,,,,%s\n", line ? "sluice_1d" : "sluice_2d", n, line ? n : BOX_NX * n,
               r.rc ? r.msg : why);
        continue;
      }
      printf("%s,%d,%d,%.4g,%ld,%.4e,%.3e,%.3e\n", line ? "sluice_1d" : "sluice_2d", n, line ? n : BOX_NX * n, r.cpu,
             r.steps, r.l1, r.speed, r.worst);
      fflush(stdout);
      bench_remove_output(a.out);
    }
  return 0;
}
