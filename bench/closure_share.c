/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The share of a run spent inside closure calls: runs scenes of configs/
 * in-process as `sluice run` does, with the closures timing each batched
 * call (the clock of `sluice run --profile`), and prints per scene the run's
 * wall and CPU time, the calls, points and wall time inside the calls
 * (the closure's loop and the host's check of its outputs), and their share
 * of the run. The same scene also runs with the timing off: the difference
 * bounds what the two clock reads per call add.
 *
 *   bench_closure_share [--source DIR] [--repeat R] [SCENE [--set section.key=value]...]...
 *
 * Default scenes: bingham_cavity (a viscosity closure at every quadrature
 * point of every Newton assembly), boycott on 12 x 16 cells to t = 0.1 (a
 * phi-dependent viscosity and the tabulated settling flux) and
 * fluidized_bed (the two-fluid model's drag and solids pressure on a 1-D
 * column, where the linear algebra is cheapest). Each run is repeated R
 * times (default 3); the fastest run (wall) of each kind is kept. A Markdown
 * table on stdout; progress on stderr. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/util/diag.h"
#include "sluice/sluice.h"

enum { MAX_SCENES = 16, MAX_SETS = 16 };

typedef struct scene_spec {
  const char *name;
  const char *sets[MAX_SETS + 1];
  int n_sets;
} scene_spec;

typedef struct measured {
  double wall, cpu;       /* the whole run, set-up included */
  double closure_seconds; /* inside the calls (timed runs) */
  unsigned long long calls, points;
  int n_closures;
} measured;

static double clock_of(clockid_t id) {
  struct timespec ts;
  clock_gettime(id, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int run_once(const char *configs, const scene_spec *s, int timing, measured *m, sl_diag *d) {
  memset(m, 0, sizeof *m);
  char path[4200], out[512];
  snprintf(path, sizeof path, "%s/%s.ini", configs, s->name);
  snprintf(out, sizeof out, "closure_share_%s.h5", s->name);
  double w0 = clock_of(CLOCK_MONOTONIC), c0 = clock_of(CLOCK_PROCESS_CPUTIME_ID);
  const char *sets[MAX_SETS + 1];
  for (int i = 0; i < s->n_sets; ++i) sets[i] = s->sets[i];
  sets[s->n_sets] = NULL;
  sluice *sc = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets, .timing = timing};
  int rc = sluice_open(path, &oo, &sc, &e);
  if (!rc) {
    sluice_summary res;
    sluice_run_opts o = {.scene_path = path, .output = out, .version = "bench"};
    rc = sluice_run(sc, &o, &res, &e);
  }
  m->wall = clock_of(CLOCK_MONOTONIC) - w0, m->cpu = clock_of(CLOCK_PROCESS_CPUTIME_ID) - c0;
  if (sc) {
    sluice_closure_use total;
    m->n_closures = sluice_closure_totals(sc, &total);
    m->calls = total.calls, m->points = total.points, m->closure_seconds = total.seconds;
  }
  if (rc) sl_diag_set(d, rc, "%s", e.msg);
  sluice_close(sc);
  remove(out);
  return rc;
}

int main(int argc, char **argv) {
  const char *source = getenv("SLUICE_SOURCE_DIR");
  int repeat = 3, n_scenes = 0;
  scene_spec scenes[MAX_SCENES];
  memset(scenes, 0, sizeof scenes);
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--source") == 0 && i + 1 < argc) {
      source = argv[++i];
    } else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = atoi(argv[++i]);
      if (repeat < 1) {
        fprintf(stderr, "bench_closure_share: --repeat takes a whole number from 1, not '%s'\n", argv[i]);
        return 2;
      }
    } else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
      if (n_scenes == 0 || scenes[n_scenes - 1].n_sets == MAX_SETS) {
        fprintf(stderr, "bench_closure_share: --set %s: give the scene first, at most %d --set each\n", argv[i + 1],
                MAX_SETS);
        return 2;
      }
      scene_spec *s = &scenes[n_scenes - 1];
      s->sets[s->n_sets++] = argv[++i];
    } else if (argv[i][0] == '-') {
      fprintf(stderr,
              "usage: bench_closure_share [--source DIR] [--repeat R] [SCENE [--set section.key=value]...]...\n");
      return 2;
    } else if (n_scenes == MAX_SCENES) {
      fprintf(stderr, "bench_closure_share: at most %d scenes\n", MAX_SCENES);
      return 2;
    } else {
      scenes[n_scenes++].name = argv[i];
    }
  }
  if (n_scenes == 0) {
    scenes[0] = (scene_spec){.name = "bingham_cavity"};
    scenes[1] = (scene_spec){.name = "boycott", .sets = {"mesh.cells=12,16", "time.end=0.1"}, .n_sets = 2};
    scenes[2] = (scene_spec){.name = "fluidized_bed"};
    n_scenes = 3;
  }
  char configs[4096];
  snprintf(configs, sizeof configs, "%s/configs", source ? source : ".");
  printf(
      "| scene | closures | calls | points per call | run wall s (CPU s), timed | inside the calls, wall s | "
      "share of the run's wall time | run wall s, timing off |\n");
  printf("|---|---|---|---|---|---|---|---|\n");
  int failed = 0;
  for (int k = 0; k < n_scenes; ++k) {
    const scene_spec *s = &scenes[k];
    measured best_timed = {0}, best_plain = {0};
    for (int r = 0; r < repeat; ++r)
      for (int timing = 1; timing >= 0; --timing) { /* alternate, so both see the same load */
        measured m;
        sl_diag d = {{0}};
        if (run_once(configs, s, timing, &m, &d)) {
          fprintf(stderr, "bench_closure_share: %s: %s\n", s->name, d.msg);
          failed = 1;
          r = repeat;
          break;
        }
        measured *best = timing ? &best_timed : &best_plain;
        if (r == 0 || m.wall < best->wall) *best = m;
        fprintf(stderr, "%s run %d, timing %s: wall %.3f s, CPU %.3f s, inside closures %.4f s\n", s->name, r + 1,
                timing ? "on" : "off", m.wall, m.cpu, m.closure_seconds);
      }
    if (failed) break;
    char label[256] = "";
    size_t at = (size_t)snprintf(label, sizeof label, "%s", s->name);
    for (int i = 0; i < s->n_sets && at < sizeof label; ++i)
      at += (size_t)snprintf(label + at, sizeof label - at, " %s", s->sets[i]);
    printf("| %s | %d | %llu | %.0f | %.3f (%.3f) | %.4f | %.2f %% | %.3f |\n", label, best_timed.n_closures,
           best_timed.calls, best_timed.calls ? (double)best_timed.points / (double)best_timed.calls : 0.0,
           best_timed.wall, best_timed.cpu, best_timed.closure_seconds,
           100.0 * best_timed.closure_seconds / best_timed.wall, best_plain.wall);
    fflush(stdout);
  }
  return failed;
}
