/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice run SCENE.ini: parse and validate a scene, resolve its closures,
 * and run it (models navier_stokes, mixture and two_fluid). */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/cli/cli.h"
#include "core/cli/progress.h"
#include "core/cli/summary_json.h"
#include "core/plugin/guard.h"
#include "core/plugin/isolate.h"
#include "core/solve/linsolve.h"
#include "sluice/sluice.h"

static const char run_usage[] =
    "usage: sluice run SCENE.ini [--set section.key=value]... [--print-config] [-o OUT.h5]\n"
    "                            [--restart FILE.h5] [--check] [--profile] [--monitor]\n"
    "                            [--overwrite] [--summary-json FILE] [--petsc \"PETSC OPTIONS\"]\n"
    "                            [--allow-plugin-path] [--closure-time-limit SECONDS]\n"
    "Reads a scene, applies the --set overrides, checks every section and key\n"
    "(unknown ones are errors with a suggestion), loads and validates each\n"
    "[closure.<kind>] against the closure's own schema, and runs it.\n"
    "  --print-config   print the resolved configuration (includes flattened,\n"
    "                   overrides applied) and stop\n"
    "  --check          validate the scene and its closures, build the mesh and\n"
    "                   print its report (where the cells are smallest and\n"
    "                   largest, angles), and stop\n"
    "  -o OUT.h5        output file (default: [output] file, else SCENE.h5)\n"
    "  --restart F.h5   continue from the last checkpoint in F.h5\n"
    "  --overwrite      the output may replace files sluice did not write (without\n"
    "                   it such a file is refused, exit 2; the scene file never)\n"
    "  --summary-json F what the run did (status, steps, times, output) as JSON in F\n"
    "  --profile        after the summary, what the run did and skipped: assemblies,\n"
    "                   factorisations (and reuses), closure calls and points per\n"
    "                   closure with their time, the plugin libraries loaded, the\n"
    "                   output written, and the CPU time of each phase; under\n"
    "                   mpirun the rows rank 0 owns and the time their exchange\n"
    "                   takes (the ranks then meet before each exchange)\n"
    "  --petsc \"OPTS\"   PETSc options for [solver] linear = petsc, over the scene's\n"
    "                   [solver.petsc] (PETSC_OPTIONS over both), as \"-ksp_monitor\",\n"
    "                   \"-log_view\" or \"-pc_type lu\"\n"
    "  --monitor        every nonlinear iteration on a line of its own: the time\n"
    "                   (or the continuation stage), its relative correction, the\n"
    "                   residual and the residual against its terms' scale\n"
    "  --allow-plugin-path  load closure libraries from the folders the scene's\n"
    "                   [plugins] path names (refused without it: docs/trust-plugins.md)\n"
    "  --closure-time-limit S  stop a closure call that has not returned after S\n"
    "                   seconds (the run fails naming it; default: no limit)\n"
    "--check and --print-config run closure library code only in a child process.\n"
    "Progress: on a terminal a line redrawn in place; otherwise (a log) a line\n"
    "every 10 s (SLUICE_PROGRESS_EVERY=seconds; SLUICE_PROGRESS=0 off, 1 in place,\n"
    "lines the log lines). The run ends with a one-line summary (CPU and wall\n"
    "time, the wall time of each phase). A steady solve shows its Newton\n"
    "iterations and continuation stages instead (a line each in a log).\n"
    "Ctrl-C (SIGINT) or SIGTERM stops after the current step (a steady solve\n"
    "after its iteration), saves it and closes the file; further signals until\n"
    "then are ignored. Exit status: 0 done, 1 the run failed (the last accepted\n"
    "state is saved; the message says its time), 2 bad input (found before any\n"
    "file is opened), 130 and 143 stopped by SIGINT and SIGTERM (state saved).\n"
    "Models: navier_stokes, mixture and two_fluid (1-D columns and shear layers,\n"
    "geometry = line; 2-D, geometry = planar | axisymmetric).";

/* SIGINT and SIGTERM: the first one's number; the run stops after its step
 * (a steady solve after its iteration), saves and closes the output. The
 * handlers stay installed until the output is closed, so that a second
 * signal during the save is ignored (counted) instead of killing the process
 * with a half-written file; the exit status is then 128 + the signal's
 * number (130, 143), the shell's convention for a process a signal ended. */
static volatile sig_atomic_t interrupted, signals_seen;
static void on_signal(int sig) {
  if (!interrupted) interrupted = sig;
  signals_seen = signals_seen + 1;
  sl_guard_interrupt(sig); /* inside a closure call (a looping one): leave it */
}

typedef struct run_view {
  sl_progress *prog;
  int steady;  /* no time span: the progress follows the nonlinear iterations */
  int monitor; /* --monitor: every nonlinear iteration on a line */
} run_view;

static void monitor(void *user, double t, double dt, long step, int nl) {
  const run_view *v = user;
  sl_progress_update(v->prog, t, dt, step, nl);
}

static void nonlinear(void *user, const sluice_nonlinear *r) {
  const run_view *v = user;
  if (v->monitor) {
    sl_progress_end(v->prog); /* a line in place would be overwritten */
    char at[96] = "";
    if (!v->steady) snprintf(at, sizeof at, "t = %.9g, ", r->t);
    if (r->n_stages > 0) snprintf(at + strlen(at), sizeof at - strlen(at), "stage %ld of %ld, ", r->stage, r->n_stages);
    fprintf(stderr,
            "sluice: monitor: %s%s %d: relative correction %.3e, residual %.3e (%.3g of its terms' scale %.3e)\n", at,
            r->picard ? "picard" : "newton", r->iteration, r->correction, r->residual,
            r->terms > 0 ? r->residual / r->terms : 0.0, r->terms);
  } else if (v->steady) {
    sl_progress_iteration(v->prog, r->stage, r->n_stages, r->iteration, r->picard, r->correction, r->residual,
                          r->terms);
  }
}

static double percent(double part, double whole) { return whole > 0 ? 100.0 * part / whole : 0.0; }

/* `--profile`: what the run did and what it skipped, and where the CPU time
 * went (every line starts with "sluice: profile:"). */
static void print_profile(FILE *f, const sluice *sc, const sluice_summary *m, double cpu_total) {
  const char *p = "sluice: profile:";
  if (m->matrix_assemblies + m->residual_assemblies > 0)
    fprintf(f, "%s assemblies: %ld matrix, %ld right-hand-side only (%.3g s)\n", p, m->matrix_assemblies,
            m->residual_assemblies, m->assembly);
  const sluice_linear *ls = &m->linear;
  if (ls->n_symbolic + ls->n_numeric + ls->n_solves > 0)
    fprintf(f,
            "%s factorisations: %ld symbolic (%.3g s), %ld numeric (%.3g s; %ld of them refactorisations), %ld "
            "skipped (matrix unchanged); %ld solves (%.3g s)\n",
            p, ls->n_symbolic, ls->t_symbolic, ls->n_numeric, ls->t_numeric, ls->n_refactor, ls->n_numeric_skipped,
            ls->n_solves, ls->t_solve);
  if (ls->n_numeric > 0) {
    fprintf(f, "%s numeric factorisations by reason:", p);
    for (int k = 0, first = 1; k < SLUICE_REFACTOR_REASONS; ++k)
      if (ls->refactor_reason[k] > 0)
        fprintf(f, "%s %s %ld", first ? "" : ",", sluice_refactor_reason_name(k), ls->refactor_reason[k]), first = 0;
    fputc('\n', f);
  }
  if (ls->n_reused + ls->n_krylov_failed > 0)
    fprintf(f,
            "%s factorisation reuse: %ld of %ld solves by FGMRES with an older factorisation, %.1f iterations a solve "
            "(at most %d), %ld attempts refactorised; %.3g s in FGMRES\n",
            p, ls->n_reused, ls->n_solves,
            (double)ls->n_krylov_iterations / (double)(ls->n_reused + ls->n_krylov_failed), ls->krylov_max,
            ls->n_krylov_failed, ls->t_krylov);
  if (m->rejected_by[0] + m->rejected_by[1] + m->rejected_by[2] + m->rejected_by[3] > 0) {
    static const char *const why[4] = {"the BDF error estimate", "the splitting's error estimate",
                                       "the nonlinear solve failed", "the solids transport failed"};
    fprintf(f, "%s rejected steps by reason:", p);
    for (int k = 0, first = 1; k < 4; ++k)
      if (m->rejected_by[k] > 0) fprintf(f, "%s %s %ld", first ? "" : ",", why[k], m->rejected_by[k]), first = 0;
    fputc('\n', f);
  }
  if (m->solves_skipped > 0)
    fprintf(f, "%s %ld flow solve%s skipped (the flow known: at rest, or at a fixed point)\n", p, m->solves_skipped,
            m->solves_skipped == 1 ? "" : "s");
  if (m->roundoff_accepted > 0)
    fprintf(f, "%s %ld nonlinear solve%s ended with the residual at round-off\n", p, m->roundoff_accepted,
            m->roundoff_accepted == 1 ? "" : "s");
  sl_rows_stats rs;
  sl_linsolve_rows_stats(&rs);
  if (rs.ranks > 1)
    fprintf(f,
            "%s rows on %d ranks: this rank owns %ld of %ld rows; its matrix %ld entries, %ld of them in its rows, of "
            "%ld in all; border: %ld of its rows' entries in other ranks' columns, %ld on all ranks; the parts "
            "exchanged in %.3g s (%ld assemblies, %ld with the matrix; before them %.3g s waiting for the other ranks)\n",
            p, rs.ranks, rs.owned_rows, rs.rows, rs.entries_here, rs.owned_entries, rs.all_entries, rs.border_entries,
            rs.all_border, rs.seconds,
            rs.calls, rs.matrix_calls, rs.waiting);
  sluice_print_closure_profile(sc, f, p, cpu_total);
  if (m->output_times > 0)
    fprintf(f, "%s output: %ld output times, %ld datasets, %.3g MB of field values\n", p, m->output_times,
            m->output_datasets, m->output_bytes / 1e6);
  if (m->output_times > 0 && rs.ranks > 1)
    fprintf(f,
            "%s output on %d ranks: this rank wrote %.0f of the %.0f bytes of the file's values (fields, mesh, "
            "checkpoints) in %ld collective transfers\n",
            p, rs.ranks, m->output_bytes_rank, m->output_bytes_all, m->output_collective);
  double known = m->cpu_setup + m->cpu_flow + m->cpu_coupled + m->cpu_output;
  if (known > 0 && cpu_total > 0) {
    double other = cpu_total > known ? cpu_total - known : 0.0;
    fprintf(f, "%s CPU %.3g s: set-up %.3g s (%.0f %%), flow solves %.3g s (%.0f %%)", p, cpu_total, m->cpu_setup,
            percent(m->cpu_setup, cpu_total), m->cpu_flow, percent(m->cpu_flow, cpu_total));
    if (m->cpu_coupled > 0)
      fprintf(f, ", solids transport %.3g s (%.0f %%)", m->cpu_coupled, percent(m->cpu_coupled, cpu_total));
    fprintf(f, ", output %.3g s (%.0f %%), other %.3g s (%.0f %%)\n", m->cpu_output, percent(m->cpu_output, cpu_total),
            other, percent(other, cpu_total));
  }
}

static int simulate(sluice *sc, const char *scene, const char *out_file, const char *restart, int profile,
                    int show_iterations, int overwrite, const char *summary_json, sluice_error *e) {
  double t0, t1;
  int rc = sluice_time_span(sc, &t0, &t1, e);
  if (rc) {
    if (summary_json && sl_summary_json_write(summary_json, scene, sluice_model(sc), rc, e->msg, NULL, 0.0, 0.0))
      fprintf(stderr, "sluice: cannot write the summary '%s'\n", summary_json);
    return rc;
  }
  sl_progress prog;
  sl_progress_begin(&prog, stderr, t0, t1);
  run_view view = {.prog = &prog, .steady = !(t1 > t0), .monitor = show_iterations};
  sluice_run_opts o = {.scene_path = scene,
                       .output = out_file,
                       .restart = restart,
                       .progress = monitor,
                       .progress_user = &view,
                       .interrupt = &interrupted,
                       .nonlinear = view.monitor || view.steady ? nonlinear : NULL,
                       .nonlinear_user = &view,
                       .overwrite = overwrite};
  sluice_summary m;
  double w0 = sl_wall_seconds(), c0 = sl_cpu_seconds();
  struct sigaction sa, old_int, old_term;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  rc = sluice_run(sc, &o, &m, e);
  /* the output is closed: from here a signal acts as it did before the run */
  sigaction(SIGINT, &old_int, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  sl_progress_end(&prog);
  sl_run_summary s = {.steps = m.steps,
                      .rejected_steps = m.rejected_steps,
                      .nonlinear_iterations = m.nonlinear_iterations,
                      .nonlinear_name = m.used_picard ? "Newton/Picard" : "Newton",
                      .wall_seconds = sl_wall_seconds() - w0,
                      .cpu_seconds = sl_cpu_seconds() - c0,
                      .assembly = m.assembly,
                      .factorisation = m.factorisation,
                      .solve = m.solve,
                      .output = m.output,
                      .step_limit = m.step_limit};
  if (rc != SLUICE_BAD_INPUT) {
    char line[512];
    sl_run_summary_format(&s, line, sizeof line);
    fprintf(stderr, "%s\n", line);
    if (m.coupling_summary[0]) fprintf(stderr, "sluice: %s\n", m.coupling_summary);
    if (m.output_path[0]) {
      fprintf(stderr, "sluice: output %s (%s", m.output_path, m.linear_summary);
      /* what was skipped shows in the counts: a constant matrix is assembled once */
      if (m.matrix_assemblies + m.residual_assemblies > 0)
        fprintf(stderr, "; assemblies: %ld matrix, %ld right-hand-side only", m.matrix_assemblies,
                m.residual_assemblies);
      fputs(")\n", stderr);
    }
    if (m.stop_reason[0]) fprintf(stderr, "sluice: %s\n", m.stop_reason);
    if (profile) print_profile(stderr, sc, &m, s.cpu_seconds);
  }
  if (rc == SLUICE_FAILED && interrupted) {
    char msg[sizeof e->msg];
    const char *name = interrupted == SIGTERM ? "SIGTERM" : "SIGINT";
    if (m.output_path[0] && m.saved_time_valid)
      snprintf(msg, sizeof msg, "sluice: %s: stopped at t = %.9g; the state at t = %.9g is saved in %.900s (%.600s)",
               name, m.t_reached, m.saved_time, m.output_path, e->msg);
    else snprintf(msg, sizeof msg, "sluice: %s: stopped (%.1000s)", name, e->msg);
    if (signals_seen > 1)
      snprintf(msg + strlen(msg), sizeof msg - strlen(msg), " (%d more signal%s ignored until the file was closed)",
               (int)signals_seen - 1, signals_seen > 2 ? "s" : "");
    memcpy(e->msg, msg, sizeof msg);
    return 128 + (int)interrupted;
  }
  if (rc == SLUICE_FAILED && m.output_path[0]) {
    char msg[sizeof e->msg];
    if (m.saved_time_valid && !(t1 > t0)) /* steady: the model's message says which state */
      snprintf(msg, sizeof msg, "run failed; its state is saved in %.900s: %.1000s", m.output_path, e->msg);
    else if (m.saved_time_valid)
      snprintf(msg, sizeof msg,
               "run failed at t = %.9g; the last accepted state, t = %.9g, is saved in %.900s: %.1000s", m.t_reached,
               m.saved_time, m.output_path, e->msg);
    else
      snprintf(msg, sizeof msg, "run failed at t = %.9g; nothing could be saved in %.900s: %.1000s", m.t_reached,
               m.output_path, e->msg);
    memcpy(e->msg, msg, sizeof msg);
  }
  if (summary_json &&
      sl_summary_json_write(summary_json, scene, sluice_model(sc), rc, e->msg, &m, s.wall_seconds, s.cpu_seconds))
    fprintf(stderr, "sluice: cannot write the summary '%s'\n", summary_json);
  return rc;
}

/* --check and --print-config: closure library code (constructors, create())
 * runs in a child process, never in this one; the child prints the report. */
typedef struct check_job {
  sluice *sc;
  int print_config;
  const char *restart; /* --check: a restart's checkpoint is checked against the scene too */
} check_job;

static int check_in_child(void *user, int fd) {
  (void)fd;
  check_job *j = user;
  sluice_error e = {0, ""};
  int rc;
  if (j->print_config) {
    double t0, t1; /* the keys and the closures are checked first (bad input: exit 2, nothing printed) */
    if (!(rc = sluice_time_span(j->sc, &t0, &t1, &e))) rc = sluice_write_config(j->sc, stdout, &e);
  } else {
    rc = sluice_check_restart(j->sc, j->restart, stdout, &e);
  }
  if (rc) fprintf(stderr, "%s\n", e.msg);
  return rc;
}

static int check_isolated(sluice *sc, int print_config, const char *restart, const char *scene, sluice_error *e) {
  check_job j = {sc, print_config, restart};
  sl_child_outcome o;
  if (sl_isolate(check_in_child, &j, NULL, NULL, 0.0, &o)) {
    snprintf(e->msg, sizeof e->msg, "sluice: cannot start the checking process");
    return SLUICE_FAILED;
  }
  if (o.exited) {
    e->msg[0] = '\0'; /* the child said it */
    return o.status;
  }
  snprintf(e->msg, sizeof e->msg,
           "sluice: %s: %s stopped by %s while checking the scene (closure library code runs in a child process "
           "under %s; nothing was loaded into sluice)",
           scene, print_config ? "--print-config" : "--check", sl_signal_name(o.signal),
           print_config ? "--print-config" : "--check");
  return SLUICE_FAILED;
}

int sl_cmd_run(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(run_usage);
    return 0;
  }
  const char *scene = NULL, *out_file = NULL, *restart = NULL, *summary_json = NULL, *petsc = NULL;
  int print_config = 0, check_only = 0, profile = 0, show_iterations = 0, allow_plugin_path = 0, overwrite = 0;
  double closure_time_limit = 0.0;
  enum { MAX_SETS = 256 };
  const char *sets[MAX_SETS];
  int n_sets = 0;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
      if (n_sets == MAX_SETS) return sl_cli_error(SL_EBADINPUT, "too many --set options");
      sets[n_sets++] = argv[++i];
    } else if (strncmp(argv[i], "--set=", 6) == 0) {
      if (n_sets == MAX_SETS) return sl_cli_error(SL_EBADINPUT, "too many --set options");
      sets[n_sets++] = argv[i] + 6;
    } else if (strcmp(argv[i], "--print-config") == 0) {
      print_config = 1;
    } else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
      out_file = argv[++i];
    } else if (strcmp(argv[i], "--restart") == 0 && i + 1 < argc) {
      restart = argv[++i];
    } else if (strcmp(argv[i], "--check") == 0) {
      check_only = 1;
    } else if (strcmp(argv[i], "--profile") == 0) {
      profile = 1;
      sl_linsolve_rows_profile(1);
    } else if (strcmp(argv[i], "--overwrite") == 0) {
      overwrite = 1;
    } else if (strcmp(argv[i], "--summary-json") == 0 && i + 1 < argc) {
      summary_json = argv[++i];
    } else if (strcmp(argv[i], "--petsc") == 0 && i + 1 < argc) {
      petsc = argv[++i];
    } else if (strncmp(argv[i], "--petsc=", 8) == 0) {
      petsc = argv[i] + 8;
    } else if (strcmp(argv[i], "--monitor") == 0) {
      show_iterations = 1;
    } else if (strcmp(argv[i], "--allow-plugin-path") == 0) {
      allow_plugin_path = 1;
    } else if (strcmp(argv[i], "--closure-time-limit") == 0 && i + 1 < argc) {
      char *end;
      closure_time_limit = strtod(argv[++i], &end);
      if (*end || !(closure_time_limit > 0) || closure_time_limit > 1e6)
        return sl_cli_error(SL_EBADINPUT, "run: --closure-time-limit %s: seconds in (0, 1e6] expected", argv[i]);
    } else if (argv[i][0] == '-') {
      return sl_cli_error(SL_EBADINPUT, "run: unknown option or missing value '%s' (sluice run --help)", argv[i]);
    } else if (!scene) {
      scene = argv[i];
    } else {
      return sl_cli_error(SL_EBADINPUT, "run: one scene at a time ('%s' and '%s')", scene, argv[i]);
    }
  }
  if (!scene) return sl_cli_error(SL_EBADINPUT, "run: which scene?\n%s", run_usage);

  sluice *sc = NULL;
  sluice_error e = {0, ""};
  /* under mpirun the ranks share the linear solves and write the one output file together (sl_model_run); rank 0
     prints, the others print nothing */
  int rank = 0, ranks = 1;
  if (sluice_ranks(&rank, &ranks, &e)) return sl_cli_error(e.code, "%s", e.msg);
  if (rank > 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))) return 1;
  const char *set_list[MAX_SETS + 1];
  for (int i = 0; i < n_sets; ++i) set_list[i] = sets[i];
  set_list[n_sets] = NULL;
  sluice_open_opts oo = {.sets = set_list,
                         .timing = profile,
                         .petsc_options = petsc,
                         .allow_plugin_path = allow_plugin_path,
                         .closure_time_limit = closure_time_limit};
  int rc = sluice_open(scene, &oo, &sc, &e);
  if (!rc && (print_config || check_only)) {
    rc = check_isolated(sc, print_config, restart, scene, &e);
  } else if (!rc) {
    rc =
        simulate(sc, scene, out_file, restart, profile, show_iterations, overwrite, rank > 0 ? NULL : summary_json, &e);
    summary_json = NULL; /* written */
  }
  if (summary_json && !print_config && !check_only && rc &&
      sl_summary_json_write(summary_json, scene, sc ? sluice_model(sc) : "", rc, e.msg, NULL, 0.0, 0.0))
    fprintf(stderr, "sluice: cannot write the summary '%s'\n", summary_json);
  sluice_close(sc);
  if (rc && e.msg[0]) fprintf(stderr, "%s\n", e.msg);
  return rc;
}
