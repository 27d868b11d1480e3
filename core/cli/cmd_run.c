/* sluice run SCENE.ini: parse and validate a scene, resolve its closures,
 * and run it (models navier_stokes, mixture and two_fluid). */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/config/ini.h"
#include "core/config/scene_schema.h"
#include "core/cli/progress.h"
#include "core/mesh/mesh.h"
#include "core/models/mixture.h"
#include "core/models/scene_mesh.h"
#include "core/models/navier_stokes.h"
#include "core/models/two_fluid.h"
#include "core/plugin/closure_ini.h"
#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"

static const char run_usage[] =
    "usage: sluice run SCENE.ini [--set section.key=value]... [--print-config] [-o OUT.h5]\n"
    "                            [--restart FILE.h5] [--check] [--profile]\n"
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
    "  --profile        after the summary, what the run did and skipped: assemblies,\n"
    "                   factorisations (and reuses), closure calls and points per\n"
    "                   closure with their time, the plugin libraries loaded, the\n"
    "                   output written, and the CPU time of each phase\n"
    "A progress line is drawn when stderr is a terminal (SLUICE_PROGRESS=0/1\n"
    "forces it off/on); the run ends with a one-line summary. Ctrl-C stops after\n"
    "the current step and saves it. Exit status: 0 done, 1 the run failed (the\n"
    "last good state is saved), 2 bad input.\n"
    "Models: navier_stokes, mixture and two_fluid (1-D columns and shear layers,\n"
    "geometry = line; 2-D, geometry = planar | axisymmetric).";

static volatile sig_atomic_t interrupted;
static void on_sigint(int sig) {
  (void)sig;
  interrupted = 1;
}

static void monitor(void *user, double t, double dt, long step, int nl) {
  sl_progress_update(user, t, dt, step, nl);
}

static double percent(double part, double whole) { return whole > 0 ? 100.0 * part / whole : 0.0; }

/* `--profile`: what the run did and what it skipped, and where the CPU time
 * went (every line starts with "sluice: profile:"). */
static void print_profile(FILE *f, const sl_ns_result *res, const sl_registry *reg, double cpu_total) {
  const char *p = "sluice: profile:";
  if (res->matrix_assemblies + res->residual_assemblies > 0)
    fprintf(f, "%s assemblies: %ld matrix, %ld right-hand-side only (%.3g s)\n", p, res->matrix_assemblies,
            res->residual_assemblies, res->assembly);
  const sl_linsolve_stats *ls = &res->linear;
  if (ls->n_symbolic + ls->n_numeric + ls->n_solves > 0)
    fprintf(f, "%s factorisations: %ld symbolic (%.3g s), %ld numeric (%.3g s; %ld of them refactorisations), %ld "
               "skipped (matrix unchanged); %ld solves (%.3g s)\n",
            p, ls->n_symbolic, ls->t_symbolic, ls->n_numeric, ls->t_numeric, ls->n_refactor, ls->n_numeric_skipped,
            ls->n_solves, ls->t_solve);
  if (ls->n_numeric > 0) {
    fprintf(f, "%s numeric factorisations by reason:", p);
    for (int k = 0, first = 1; k < SL_REFACTOR_N; ++k)
      if (ls->refactor_reason[k] > 0)
        fprintf(f, "%s %s %ld", first ? "" : ",", sl_refactor_reason_name(k), ls->refactor_reason[k]), first = 0;
    fputc('\n', f);
  }
  if (ls->n_reused + ls->n_krylov_failed > 0)
    fprintf(f,
            "%s factorisation reuse: %ld of %ld solves by FGMRES with an older factorisation, %.1f iterations a solve "
            "(at most %d), %ld attempts refactorised; %.3g s in FGMRES\n",
            p, ls->n_reused, ls->n_solves,
            (double)ls->n_krylov_iterations / (double)(ls->n_reused + ls->n_krylov_failed),
            ls->krylov_max, ls->n_krylov_failed, ls->t_krylov);
  if (res->roundoff_accepted > 0)
    fprintf(f, "%s %ld nonlinear solve%s ended with the residual at round-off\n", p, res->roundoff_accepted,
            res->roundoff_accepted == 1 ? "" : "s");
  /* closures: per descriptor that had an instance */
  double closure_seconds = 0.0;
  int n_closures = 0;
  for (int i = 0; i < reg->n_libraries; ++i) {
    const sl_library *lib = reg->libraries[i];
    const char *base = strrchr(lib->path, '/');
    for (int32_t k = 0; k < lib->n_closures; ++k) {
      const sl_closure_usage *u = &lib->usage[k];
      if (u->instances == 0) continue;
      char label[128];
      sl_closure_label(lib->closures[k], label, sizeof label);
      fprintf(f, "%s closure %s (%s): %ld instance%s, %llu batched call%s, %llu points (%.1f per call), %.3g s\n", p,
              label, base ? base + 1 : lib->path, u->instances, u->instances == 1 ? "" : "s", u->calls,
              u->calls == 1 ? "" : "s", u->points, u->calls ? (double)u->points / (double)u->calls : 0.0, u->seconds);
      closure_seconds += u->seconds;
      ++n_closures;
    }
  }
  if (n_closures == 0) fprintf(f, "%s closures: none evaluated\n", p);
  fprintf(f, "%s plugins: %d of %d libraries on the search path loaded (%ld dlopen)", p, reg->n_libraries,
          sl_registry_files_on_path(reg), reg->n_dlopen);
  for (int i = 0; i < reg->n_libraries; ++i) {
    const char *base = strrchr(reg->libraries[i]->path, '/');
    fprintf(f, "%s%s", i ? ", " : ": ", base ? base + 1 : reg->libraries[i]->path);
  }
  fputc('\n', f);
  if (res->output_times > 0)
    fprintf(f, "%s output: %ld output times, %ld datasets, %.3g MB of field values\n", p, res->output_times,
            res->output_datasets, res->output_bytes / 1e6);
  double known = res->cpu_setup + res->cpu_flow + res->cpu_coupled + res->cpu_output;
  if (known > 0 && cpu_total > 0) {
    double other = cpu_total > known ? cpu_total - known : 0.0;
    fprintf(f, "%s CPU %.3g s: set-up %.3g s (%.0f %%), flow solves %.3g s (%.0f %%)", p, cpu_total, res->cpu_setup,
            percent(res->cpu_setup, cpu_total), res->cpu_flow, percent(res->cpu_flow, cpu_total));
    if (res->cpu_coupled > 0)
      fprintf(f, ", solids transport %.3g s (%.0f %%)", res->cpu_coupled, percent(res->cpu_coupled, cpu_total));
    fprintf(f, ", output %.3g s (%.0f %%), other %.3g s (%.0f %%)\n", res->cpu_output,
            percent(res->cpu_output, cpu_total), other, percent(other, cpu_total));
  }
  if (n_closures > 0)
    fprintf(f, "%s closure calls took %.3g s, %.2g %% of the run's CPU time (wall clock inside the calls)\n", p,
            closure_seconds, percent(closure_seconds, cpu_total));
}

static int simulate(sl_ini *ini, const sl_registry *reg, int model, const char *scene, const char *out_file,
                    const char *restart, int profile, sl_diag *d) {
  double t0, t1;
  int rc = sl_ns_time_span(ini, &t0, &t1, d);
  if (rc) return rc;
  sl_progress prog;
  sl_progress_begin(&prog, stderr, t0, t1);
  sl_ns_run_opts o = {.scene_path = scene, .output = out_file, .restart = restart, .sluice_version = SLUICE_VERSION,
                      .monitor = monitor, .monitor_user = &prog, .interrupt = &interrupted};
  sl_ns_result res;
  double w0 = sl_wall_seconds(), c0 = sl_cpu_seconds();
  void (*old)(int) = signal(SIGINT, on_sigint);
  rc = model == 1   ? sl_mixture_run(ini, reg, &o, &res, d)
       : model == 2 ? sl_two_fluid_run(ini, reg, &o, &res, d)
                    : sl_ns_run(ini, reg, &o, &res, d);
  signal(SIGINT, old);
  sl_progress_end(&prog);
  sl_run_summary s = {.steps = res.steps, .rejected_steps = res.rejected_steps,
                      .nonlinear_iterations = res.nonlinear_iterations,
                      .nonlinear_name = res.used_picard ? "Newton/Picard" : "Newton",
                      .wall_seconds = sl_wall_seconds() - w0, .cpu_seconds = sl_cpu_seconds() - c0,
                      .assembly = res.assembly, .factorisation = res.factorisation, .solve = res.solve,
                      .output = res.output, .step_limit = res.step_limit};
  if (rc != SL_EBADINPUT) {
    char line[512];
    sl_run_summary_format(&s, line, sizeof line);
    fprintf(stderr, "%s\n", line);
    if (res.coupling_summary[0]) fprintf(stderr, "sluice: %s\n", res.coupling_summary);
    if (res.output_path[0]) {
      fprintf(stderr, "sluice: output %s (%s", res.output_path, res.linear_summary);
      /* what was skipped shows in the counts: a constant matrix is assembled once */
      if (res.matrix_assemblies + res.residual_assemblies > 0)
        fprintf(stderr, "; assemblies: %ld matrix, %ld right-hand-side only", res.matrix_assemblies,
                res.residual_assemblies);
      fputs(")\n", stderr);
    }
    if (res.stop_reason[0]) fprintf(stderr, "sluice: %s\n", res.stop_reason);
    if (profile) print_profile(stderr, &res, reg, s.cpu_seconds);
  }
  if (rc == SL_EFAILED && res.output_path[0])
    sl_diag_prefix(d, rc, "run failed at t = %g; last state saved in %s", res.t_reached, res.output_path);
  return rc;
}

int sl_cmd_run(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(run_usage);
    return 0;
  }
  const char *scene = NULL, *out_file = NULL, *restart = NULL;
  int print_config = 0, check_only = 0, profile = 0;
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
    } else if (argv[i][0] == '-') {
      return sl_cli_error(SL_EBADINPUT, "run: unknown option or missing value '%s' (sluice run --help)", argv[i]);
    } else if (!scene) {
      scene = argv[i];
    } else {
      return sl_cli_error(SL_EBADINPUT, "run: one scene at a time ('%s' and '%s')", scene, argv[i]);
    }
  }
  if (!scene) return sl_cli_error(SL_EBADINPUT, "run: which scene?\n%s", run_usage);

  sl_diag d;
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  char **dirs = NULL;
  int n_dirs = 0, rc;
  enum { MAX_CLOSURES = 64 };
  sl_closure *closures[MAX_CLOSURES];
  int n_closures = 0;
  if ((rc = sl_ini_parse_file(scene, &ini, &d))) goto fail;
  for (int i = 0; i < n_sets; ++i)
    if ((rc = sl_ini_apply_override(ini, sets[i], &d))) goto fail;
  if ((rc = sl_scene_validate(ini, &d))) goto fail;
  if ((rc = sl_plugin_dirs_from_ini(ini, &dirs, &n_dirs, &d))) goto fail;
  /* Only the libraries of the closures the scene names are loaded. */
  if ((rc = sl_registry_create(&reg, (const char *const *)dirs, n_dirs, &d))) goto fail;
  if ((rc = sl_registry_index(reg, &d))) goto fail;
  if (profile) sl_registry_set_timing(reg, 1);
  int model = 0;
  if ((rc = sl_ini_get_choice(ini, "scene", "model", !print_config, 0, "navier_stokes|mixture|two_fluid", &model, &d)))
    goto fail;
  /* Every closure section is checked here (bad input: exit 2, nothing
   * written); a run leaves creating them to the model, once. */
  for (int s = 0; s < ini->n_sections; ++s) {
    const char *name = ini->sections[s].name;
    if (strncmp(name, "closure.", 8) != 0) continue;
    if (!check_only || print_config) {
      if ((rc = sl_closure_check_ini(reg, ini, name, &d))) goto fail;
      continue;
    }
    if (n_closures == MAX_CLOSURES) {
      rc = sl_diag_set(&d, SL_EBADINPUT, "%s: more than %d closures", scene, MAX_CLOSURES);
      goto fail;
    }
    if ((rc = sl_closure_from_ini(reg, ini, name, &closures[n_closures], &d))) goto fail;
    n_closures++;
  }
  if (print_config) {
    if (sl_ini_write(ini, stdout)) rc = sl_diag_set(&d, SL_EFAILED, "cannot write the configuration");
    goto fail;
  }
  if (check_only) {
    printf("%s: scene valid; %d closure%s resolved\n", scene, n_closures, n_closures == 1 ? "" : "s");
    for (int i = 0; i < n_closures; ++i) {
      const sl_closure_desc *c = closures[i]->desc;
      printf("  %-18s %-24s %s (%s)\n", sl_kind_name(c->kind), c->name, c->version, closures[i]->library->path);
    }
    /* the mesh is built and checked too, and its report says where the cells are finest */
    if (sl_ini_find_section(ini, "mesh")) {
      sl_mesh *m = NULL;
      if ((rc = sl_scene_mesh(ini, &m, &d))) goto fail;
      sl_mesh_print_report(m, stdout);
      sl_mesh_destroy(m);
    }
    goto fail;
  }
  rc = simulate(ini, reg, model, scene, out_file, restart, profile, &d);
fail:
  for (int i = 0; i < n_closures; ++i) sl_closure_destroy(closures[i]);
  sl_registry_destroy(reg);
  sl_plugin_dirs_free(dirs, n_dirs);
  sl_ini_free(ini);
  if (rc) fprintf(stderr, "%s\n", d.msg);
  return rc;
}
