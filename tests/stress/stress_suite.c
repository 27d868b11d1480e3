/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Numerical stability under stress: the scenes of configs/ pushed to their
 * limits (particle diameter 1 um to 10 mm, density ratio 1.01 to 10, phi0
 * up to phi_max - 1e-3, Bingham number up to 1e4, time steps from small to
 * ten times the explicit stability limit) through the mixture,
 * navier_stokes and two_fluid models (the column and the shear layer). Every case must either run to its end
 * (or to its steady state) with every value of every output field finite
 * and phi in [0, phi_max], or stop cleanly: SL_EFAILED, a message saying
 * why, and the last good state (output and checkpoint, at the time reached)
 * readable. Never a crash, never a NaN in a file.
 *
 *   stress_suite            the reduced set (the test run)
 *   stress_suite --full     every case, and a Markdown table of outcomes on stdout
 *   stress_suite NAME...    the cases named
 * SLUICE_SKIP_LONG=1 (sanitizer builds) skips the long cases; when that
 * leaves nothing, the program exits 77 (skipped).
 *
 * Each case runs in a child process, so a crash is reported with the case's
 * name instead of ending the suite. Scales used below: Stokes' terminal
 * velocity u_t = (rho_s - rho_f) g d^2 / (18 mu_f), the cell size h, the
 * particle relaxation time tau_p = rho_s d^2 / (18 mu_f); the explicit limit
 * of the solids transport is h / u_t (the mixture sub-cycles within it), of
 * the drag tau_p (the two-fluid model is implicit in both). */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "stress/case_runner.h"
#include "testing.h"

enum { REDUCED = 1, LONG = 2 }; /* in the test run; skipped under SLUICE_SKIP_LONG */
enum { MAX_SETS = 12 };

typedef struct stress_case {
  const char *name;
  const char *scene;
  const char *params; /* for the table */
  double phi_max;     /* bound of the phi field (0: the scene has none) */
  int flags;
  const char *sets[MAX_SETS];
} stress_case;

/* kynch_settling: 0.5 m column, 200 cells (h = 2.5 mm), water, sand 2650,
 * d = 0.1 mm: u_t = 8.99 mm/s, h/u_t = 0.28 s. */
/* boycott: units H = U = rho_f = 1, u_t = 1 given; 8 x 12 (reduced) or
 * 12 x 16 cells, h ~ 0.06: h/u_t ~ 0.06. */
/* fluidized_bed: 1 m, 100 cells (h = 1 cm), 0.3 mm sand 2600 in water,
 * U = 10 mm/s: tau_p = 13 ms, transport limit h/U ~ 1 s.
 * settled_bed: 0.5 m, 100 cells (h = 5 mm), 50 um beads 2500: u_t = 2.0
 * mm/s, h/u_t = 2.5 s, tau_p = 0.35 ms. */
static const stress_case cases[] = {
    /* ---- mixture: batch settling (1-D) ---- */
    {"kynch_d1um",
     "kynch_settling",
     "d = 1 um (u_t = 0.9 um/s), dt = 1 s",
     0.64,
     REDUCED,
     {"solid.diameter=1e-6", NULL}},
    {"kynch_d10mm",
     "kynch_settling",
     "d = 10 mm (Stokes u_t = 90 m/s), dt = 10 h/u_t = 2.8e-4 s",
     0.64,
     REDUCED,
     {"solid.diameter=1e-2", "time.end=0.012", "time.dt=2.8e-4", "output.every=0.004", NULL}},
    {"kynch_rho1.01",
     "kynch_settling",
     "rho_s/rho_f = 1.01, dt = 10 s",
     0.64,
     REDUCED,
     {"solid.density=1010", "time.dt=10", NULL}},
    {"kynch_rho10",
     "kynch_settling",
     "rho_s/rho_f = 10 (u_t = 49 mm/s), dt = 10 h/u_t = 0.51 s",
     0.64,
     REDUCED,
     {"solid.density=10000", "time.end=20", "time.dt=0.51", "output.every=5", NULL}},
    {"kynch_phi0.639", "kynch_settling", "phi0 = 0.639 = phi_max - 1e-3", 0.64, REDUCED, {"initial.phi=0.639", NULL}},
    {"kynch_dt_small",
     "kynch_settling",
     "dt = 0.1 h/u_t = 0.028 s",
     0.64,
     0,
     {"time.dt=0.028", "time.end=20", "output.every=5", NULL}},
    {"kynch_dt_10x", "kynch_settling", "dt = 10 h/u_t = 2.8 s", 0.64, REDUCED, {"time.dt=2.8", NULL}},
    {"kynch_combined",
     "kynch_settling",
     "d = 10 mm, rho_s/rho_f = 10, phi0 = 0.639 (u_t = 490 m/s), dt = 10 h/u_t",
     0.64,
     0,
     {"solid.diameter=1e-2", "solid.density=10000", "initial.phi=0.639", "time.end=2e-3", "time.dt=5.1e-5",
      "output.every=5e-4", NULL}},
    /* ---- mixture: settling in an inclined vessel (2-D) ---- */
    {"boycott_phi0.679",
     "boycott",
     "phi0 = 0.679 = phi_max - 1e-3, 8 x 12 cells, t = 0.02",
     0.68,
     REDUCED | LONG,
     {"mesh.cells=8,12", "time.end=0.02", "output.every=0.01", "initial.phi=0.679", NULL}},
    {"boycott_base",
     "boycott",
     "the scene (rho_s/rho_f = 1.01), 12 x 16 cells, t = 0.05",
     0.68,
     LONG,
     {"mesh.cells=12,16", "time.end=0.05", "output.every=0.025", NULL}},
    {"boycott_rho10",
     "boycott",
     "rho_s/rho_f = 10, 12 x 16 cells, t = 0.05",
     0.68,
     LONG,
     {"mesh.cells=12,16", "time.end=0.05", "output.every=0.025", "solid.density=10", NULL}},
    {"boycott_phi0.679_12x16",
     "boycott",
     "phi0 = 0.679, 12 x 16 cells, t = 0.05",
     0.68,
     LONG,
     {"mesh.cells=12,16", "time.end=0.05", "output.every=0.025", "initial.phi=0.679", NULL}},
    {"boycott_dt_10x",
     "boycott",
     "fixed dt = 0.6 = 10 h/u_t, 8 x 12 cells, t = 0.6",
     0.68,
     LONG,
     {"mesh.cells=8,12", "time.end=0.6", "output.every=0.3", "time.dt=0.6", "time.adaptive=false", NULL}},
    /* ---- navier_stokes: Bingham (Bn = tau0 H / (mu_p U); channel U = G H^2 / (2 mu_p), cavity U = lid) ---- */
    {"channel_Bn1e4",
     "bingham_channel",
     "Bn = 1e4 (tau0 = 5000: rigid), eps = 1e-4",
     0,
     REDUCED,
     {"closure.viscosity.yield_stress=5000", NULL}},
    {"channel_Bn1",
     "bingham_channel",
     "Bn = 1 (tau0 = 0.5: plug half the gap)",
     0,
     0,
     {"closure.viscosity.yield_stress=0.5", NULL}},
    {"channel_Bn100",
     "bingham_channel",
     "Bn = 100 (tau0 = 50: rigid)",
     0,
     0,
     {"closure.viscosity.yield_stress=50", NULL}},
    {"cavity_Bn1e4",
     "bingham_cavity",
     "Bn = 1e4, 16 x 16 cells, continuation in eps",
     0,
     REDUCED | LONG,
     {"closure.viscosity.yield_stress=1e4", "mesh.cells=16,16", NULL}},
    {"cavity_Bn1e4_direct",
     "bingham_cavity",
     "Bn = 1e4, 16 x 16 cells, no continuation",
     0,
     LONG,
     {"closure.viscosity.yield_stress=1e4", "mesh.cells=16,16", "solver.continuation=\"\"", NULL}},
    {"cavity_Bn100_32",
     "bingham_cavity",
     "Bn = 100, 32 x 32 cells",
     0,
     LONG,
     {"closure.viscosity.yield_stress=100", NULL}},
    {"cavity_Bn1e4_32",
     "bingham_cavity",
     "Bn = 1e4, 32 x 32 cells",
     0,
     LONG,
     {"closure.viscosity.yield_stress=1e4", NULL}},
    {"cavity_Bn1e4_bdf1",
     "bingham_cavity",
     "Bn = 1e4, 16 x 16, BDF1 from rest, fixed dt = 0.02 = 10 h^2 rho/(2 mu_p)",
     0,
     LONG,
     {"closure.viscosity.yield_stress=1e4", "mesh.cells=16,16", "solver.continuation=\"\"", "time.scheme=bdf1",
      "time.dt=0.02", "time.end=0.2", "time.adaptive=false", NULL}},
    /* ---- two_fluid: fluidised bed (1-D) ---- */
    {"fluidized_d1um",
     "fluidized_bed",
     "d = 1 um (carried out by U = 10 mm/s)",
     0.64,
     REDUCED,
     {"solid.diameter=1e-6", NULL}},
    {"fluidized_d10mm", "fluidized_bed", "d = 10 mm (not fluidised)", 0.64, REDUCED, {"solid.diameter=1e-2", NULL}},
    {"fluidized_rho1.01", "fluidized_bed", "rho_s/rho_f = 1.01", 0.64, REDUCED, {"solid.density=1008.2", NULL}},
    {"fluidized_rho10", "fluidized_bed", "rho_s/rho_f = 10", 0.64, REDUCED, {"solid.density=9982", NULL}},
    {"fluidized_phi0.639",
     "fluidized_bed",
     "bed at phi0 = 0.639 = phi_max - 1e-3",
     0.64,
     REDUCED,
     {"initial.porosity=x < 0.3 ? 0.361 : 1", NULL}},
    {"fluidized_dt_small",
     "fluidized_bed",
     "dt = 1e-3 s = 0.08 tau_p, t = 5 s",
     0.64,
     REDUCED,
     {"time.dt=1e-3", "time.end=5", "output.every=1", NULL}},
    {"fluidized_dt_10x", "fluidized_bed", "dt = 0.13 s = 10 tau_p", 0.64, REDUCED, {"time.dt=0.13", NULL}},
    {"fluidized_dt_10x_cfl",
     "fluidized_bed",
     "dt = 10 s = 10 h/U, t = 10 s",
     0.64,
     LONG,
     {"time.dt=10", "time.end=10", NULL}},
    /* ---- two_fluid: settling and consolidation in a closed column (1-D) ---- */
    {"settled_d1um",
     "settled_bed",
     "d = 1 um (u_t = 0.8 um/s), dt = 200 s",
     0.64,
     REDUCED,
     {"solid.diameter=1e-6", "time.dt=200", NULL}},
    {"settled_d10mm", "settled_bed", "d = 10 mm, dt = 2 s", 0.64, LONG, {"solid.diameter=1e-2", NULL}},
    {"settled_rho1.01", "settled_bed", "rho_s/rho_f = 1.01", 0.64, REDUCED, {"solid.density=1010", NULL}},
    {"settled_rho10", "settled_bed", "rho_s/rho_f = 10", 0.64, REDUCED, {"solid.density=10000", NULL}},
    {"settled_phi0.639", "settled_bed", "phi0 = 0.639 = phi_max - 1e-3", 0.64, REDUCED, {"initial.phi=0.639", NULL}},
    {"settled_dt_10x", "settled_bed", "dt = 25 s = 10 h/u_t", 0.64, REDUCED, {"time.dt=25", NULL}},
    {"settled_dt_small",
     "settled_bed",
     "dt = 0.1 s, t = 50 s",
     0.64,
     REDUCED,
     {"time.dt=0.1", "time.end=50", "output.every=10", NULL}},
    /* ---- two-fluid shear layer: Bagnold's cell at U = 4 m/s (grain-inertia) ---- */
    {"shear_d1um",
     "shear_cell",
     "d = 1 um (tau_p = 5.6e-8 s), dt = 1 s",
     0.63,
     REDUCED,
     {"solid.diameter=1e-6", "boundary.right.velocity=4", NULL}},
    {"shear_d10mm",
     "shear_cell",
     "d = 10 mm (as wide as the gap: beyond a continuum), dt = 1 s",
     0.63,
     REDUCED,
     {"solid.diameter=1e-2", "boundary.right.velocity=4", NULL}},
    {"shear_rho1.01",
     "shear_cell",
     "rho_s/rho_f = 1.01",
     0.63,
     REDUCED,
     {"solid.density=1010", "boundary.right.velocity=4", NULL}},
    {"shear_rho10",
     "shear_cell",
     "rho_s/rho_f = 10",
     0.63,
     REDUCED,
     {"solid.density=10000", "boundary.right.velocity=4", NULL}},
    {"shear_phi0.629",
     "shear_cell",
     "phi = 0.629 = phi_max - 1e-3",
     0.63,
     REDUCED,
     {"initial.phi=0.629", "boundary.right.velocity=4", NULL}},
    {"shear_dt_large",
     "shear_cell",
     "dt = 100 s (viscous time of the gap 100 s, of a cell 0.06 s)",
     0.63,
     REDUCED,
     {"time.dt=100", "boundary.right.velocity=4", NULL}},
};
enum { N_CASES = (int)(sizeof cases / sizeof cases[0]) };

/* What a case did, sent from the child that ran it. */
typedef struct outcome {
  int rc;
  char msg[1024];
  char stop_reason[256];
  int converged; /* a steady navier_stokes solve */
  long steps, nonlinear_iterations;
  double t_end, t_reached, cpu;
  file_check fc;
} outcome;

static double cpu_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *configs_dir(void) {
  static char dir[4096];
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(dir, sizeof dir, "%s/configs", src ? src : ".");
  return dir;
}

static void run_in_child(const stress_case *c, outcome *o) {
  memset(o, 0, sizeof *o);
  char out[512], scene_path[4200];
  snprintf(out, sizeof out, "stress_%s.h5", c->name);
  snprintf(scene_path, sizeof scene_path, "%s/%s.ini", configs_dir(), c->scene);
  remove(out);
  scene_case sc;
  sl_diag d = {{0}};
  double c0 = cpu_now();
  o->rc = scene_case_open(&sc, configs_dir(), c->scene, c->sets, 0, &d);
  if (!o->rc) {
    sluice_summary res;
    o->rc = scene_case_run(&sc, scene_path, out, &res, &d);
    o->steps = res.steps, o->t_end = res.t_end, o->t_reached = res.t_reached;
    o->converged = res.converged, o->nonlinear_iterations = res.nonlinear_iterations;
    snprintf(o->stop_reason, sizeof o->stop_reason, "%s", res.stop_reason);
    scene_case_close(&sc);
  }
  o->cpu = cpu_now() - c0;
  snprintf(o->msg, sizeof o->msg, "%.1000s", o->rc ? d.msg : "");
  if (o->rc == 0 || o->rc == SL_EFAILED) check_output_file(out, c->phi_max, &o->fc);
}

/* Runs a case in a child; returns 0, or describes a crash in why. */
static int run_case(const stress_case *c, outcome *o, char *why, size_t len) {
  int fd[2];
  if (pipe(fd) != 0) {
    snprintf(why, len, "pipe: %s", strerror(errno));
    return 1;
  }
  fflush(NULL);
  pid_t pid = fork();
  if (pid < 0) {
    snprintf(why, len, "fork: %s", strerror(errno));
    close(fd[0]), close(fd[1]);
    return 1;
  }
  if (pid == 0) {
    close(fd[0]);
    outcome *mine = malloc(sizeof *mine);
    int ok = mine != NULL;
    if (ok) {
      run_in_child(c, mine);
      const char *p = (const char *)mine;
      for (size_t left = sizeof *mine; left > 0 && ok;) {
        ssize_t k = write(fd[1], p, left);
        if (k <= 0) ok = 0;
        else p += k, left -= (size_t)k;
      }
    }
    free(mine);
    close(fd[1]);
    exit(ok ? 0 : 3); /* exit(), not _exit(): the leak checker runs in the child */
  }
  close(fd[1]);
  size_t got = 0;
  char *p = (char *)o;
  for (ssize_t k; got < sizeof *o && (k = read(fd[0], p + got, sizeof *o - got)) > 0;) got += (size_t)k;
  close(fd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    snprintf(why, len, "crashed: signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
    return 1;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    snprintf(why, len, "the case's process exited with status %d", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return 1;
  }
  if (got != sizeof *o) {
    snprintf(why, len, "no outcome from the case's process");
    return 1;
  }
  return 0;
}

/* One line of text for the table: no '|' or line breaks. */
static void table_text(const char *in, char *out, size_t len, size_t max_chars) {
  size_t k = 0;
  for (; *in && k + 1 < len && k < max_chars; ++in) out[k++] = *in == '|' ? '/' : (*in == '\n' ? ' ' : *in);
  if (*in && k >= 3 && k >= max_chars) memcpy(out + k - 3, "...", 3);
  out[k] = '\0';
}

static void describe(const outcome *o, char *buf, size_t len) {
  char text[400];
  if (o->rc == 0) {
    if (o->converged) {
      snprintf(buf, len, "completed: steady state converged (%ld Newton iterations in all)", o->nonlinear_iterations);
    } else if (o->stop_reason[0]) {
      table_text(o->stop_reason, text, sizeof text, 120);
      snprintf(buf, len, "completed: %s", text);
    } else if (o->t_reached < o->t_end * (1 - 1e-12)) {
      snprintf(buf, len, "completed: steady at t = %.4g s", o->t_reached);
    } else {
      snprintf(buf, len, "completed: reached the end time t = %g", o->t_end);
    }
  } else {
    table_text(o->msg, text, sizeof text, 240);
    snprintf(buf, len, "stopped cleanly at t = %.4g: %s", o->t_reached, text);
  }
}

/* The checks of one case's outcome. */
static void check_outcome(const stress_case *c, const outcome *o) {
  const file_check *fc = &o->fc;
  CHECK_MSG(o->rc == 0 || o->rc == SL_EFAILED, "%s: neither completed nor stopped cleanly (code %d): %s", c->name,
            o->rc, o->msg);
  if (o->rc != 0 && o->rc != SL_EFAILED) return;
  CHECK_MSG(fc->error[0] == '\0', "%s: the output does not read back: %s", c->name, fc->error);
  CHECK_MSG(fc->n_times >= 1 && fc->n_datasets >= fc->n_times, "%s: %d output times, %ld datasets", c->name,
            fc->n_times, fc->n_datasets);
  CHECK_MSG(fc->n_nonfinite == 0, "%s: %ld of %ld output values are NaN or infinite", c->name, fc->n_nonfinite,
            fc->n_values);
  if (c->phi_max > 0) {
    CHECK_MSG(fc->has_phi, "%s: no phi field in the output", c->name);
    CHECK_MSG(fc->n_phi_outside == 0, "%s: %ld phi values outside [0, %g] (range %.17g .. %.17g)", c->name,
              fc->n_phi_outside, c->phi_max, fc->phi_min, fc->phi_max_seen);
  }
  CHECK_MSG(fc->checkpoint_ok, "%s: the last checkpoint is missing or not finite", c->name);
  /* the last state in the file is the state the run ended in */
  double tol = 1e-9 * fmax(1.0, fabs(o->t_reached));
  CHECK_MSG(fabs(fc->t_last - o->t_reached) <= tol && fabs(fc->checkpoint_time - o->t_reached) <= tol,
            "%s: the run ended at t = %.17g, its last output is at %.17g, its checkpoint at %.17g", c->name,
            o->t_reached, fc->t_last, fc->checkpoint_time);
  if (o->rc == SL_EFAILED) CHECK_MSG(strlen(o->msg) > 20, "%s: stopped without a reason: '%s'", c->name, o->msg);
}

int main(int argc, char **argv) {
  int full = 0, n_named = 0;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--full") == 0) {
      full = 1;
      continue;
    }
    int known = 0;
    for (int k = 0; k < N_CASES; ++k) known |= strcmp(argv[i], cases[k].name) == 0;
    if (!known) {
      fprintf(stderr, "stress_suite: no case '%s' (the cases:", argv[i]);
      for (int k = 0; k < N_CASES; ++k) fprintf(stderr, " %s", cases[k].name);
      fprintf(stderr, ")\n");
      return 2;
    }
    ++n_named;
  }
  const char *skip_env = getenv("SLUICE_SKIP_LONG");
  int skip_long = skip_env && *skip_env && strcmp(skip_env, "0") != 0;
  int n_run = 0, n_skipped = 0;
  if (full) {
    printf("| case | parameters | outcome | steps | max phi | CPU s |\n");
    printf("|---|---|---|---|---|---|\n");
  }
  for (int k = 0; k < N_CASES; ++k) {
    const stress_case *c = &cases[k];
    int wanted = full || (n_named == 0 && (c->flags & REDUCED));
    for (int i = 1; i < argc; ++i) wanted |= strcmp(argv[i], c->name) == 0;
    if (!wanted) continue;
    if (skip_long && (c->flags & LONG)) {
      fprintf(stderr, "stress: %s skipped (SLUICE_SKIP_LONG)\n", c->name);
      ++n_skipped;
      continue;
    }
    outcome o;
    char crash[256];
    if (run_case(c, &o, crash, sizeof crash)) {
      CHECK_MSG(0, "%s: %s", c->name, crash);
      if (full) printf("| %s | %s | **%s** | | | |\n", c->name, c->params, crash);
      continue;
    }
    ++n_run;
    check_outcome(c, &o);
    char text[600];
    describe(&o, text, sizeof text);
    char phi[32] = "-";
    if (c->phi_max > 0 && o.fc.has_phi) snprintf(phi, sizeof phi, "%.4f", o.fc.phi_max_seen);
    fprintf(stderr, "stress: %-24s %s; %ld steps, max phi %s, CPU %.2f s\n", c->name, text, o.steps, phi, o.cpu);
    if (full) printf("| %s | %s | %s | %ld | %s | %.2f |\n", c->name, c->params, text, o.steps, phi, o.cpu);
    fflush(stdout);
  }
  if (n_run == 0 && n_skipped > 0) {
    printf("all %d cases skipped (SLUICE_SKIP_LONG)\n", n_skipped);
    return 77;
  }
  return sl_test_summary();
}
