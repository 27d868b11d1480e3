/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A scene skips what it does not need (architecture.md section 6), counted:
 * a constant-coefficient Stokes run factorises and assembles its matrix
 * once; only the closures a scene names are loaded, each created once and
 * evaluated once per quadrature point and assembly (or once in all, for the
 * tabulated settling flux); a steady scene stops at convergence; fields not
 * asked for are neither computed nor written. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stress/case_runner.h"
#include "testing.h"

static char configs[4096];

/* Opens configs/<scene>.ini with overrides, runs it into out; the case stays
 * open (its registry says what was loaded). */
static int run(scene_case *c, const char *scene, const char *const *sets, const char *out, sluice_summary *res) {
  sl_diag d = {{0}};
  char path[4200];
  snprintf(path, sizeof path, "%s/%s.ini", configs, scene);
  int rc = scene_case_open(c, configs, scene, sets, 0, &d);
  if (!rc) {
    rc = scene_case_run(c, path, out, res, &d);
    if (rc) scene_case_close(c);
  }
  CHECK_MSG(rc == 0, "%s: %s", scene, d.msg);
  return rc;
}

/* Constant viscosity, no inertia, fixed steps: one matrix, one
 * factorisation, right-hand sides only after the first step. */
static void test_stokes_factorises_once(void) {
  const char *sets[] = {"mesh.cells=8,8",
                        "time.scheme=bdf1",
                        "time.adaptive=false",
                        "time.dt=0.01",
                        "time.end=0.5",
                        "output.every=0.1",
                        NULL};
  scene_case c;
  sluice_summary r;
  if (run(&c, "cavity_stokes", sets, "skip_stokes.h5", &r)) return;
  const sluice_linear *ls = &r.linear;
  printf(
      "Stokes, %ld BDF1 steps: %ld matrix and %ld right-hand-side assemblies; %ld symbolic, %ld numeric "
      "factorisations, %ld solves\n",
      r.steps, r.matrix_assemblies, r.residual_assemblies, ls->n_symbolic, ls->n_numeric, ls->n_solves);
  CHECK(r.steps == 50);
  CHECK_MSG(r.matrix_assemblies == 1 && r.residual_assemblies == r.steps - 1, "%ld matrix, %ld residual assemblies",
            r.matrix_assemblies, r.residual_assemblies);
  CHECK_MSG(ls->n_symbolic == 1 && ls->n_numeric == 1 && ls->n_solves == r.steps,
            "%ld symbolic, %ld numeric factorisations, %ld solves", ls->n_symbolic, ls->n_numeric, ls->n_solves);
  CHECK_MSG(scene_case_dlopen(&c) == 0 && scene_case_n_loaded(&c) == 0, "a scene without closures loaded %d libraries",
            scene_case_n_loaded(&c));
  scene_case_close(&c);
}

/* Only the named closures are loaded, each once; the settling flux is
 * tabulated once however many steps the run takes. */
static void test_only_named_closures(void) {
  const char *sets[] = {"transport.table_points=1025", "time.end=40", NULL};
  scene_case c;
  sluice_summary r;
  if (run(&c, "kynch_settling", sets, "skip_kynch.h5", &r)) return;
  int on_path = scene_case_on_path(&c);
  printf("kynch_settling: %d of %d libraries loaded, %ld dlopen\n", scene_case_n_loaded(&c), on_path,
         scene_case_dlopen(&c));
  CHECK_MSG(on_path > 20, "only %d closure libraries on the search path", on_path);
  CHECK_MSG(scene_case_n_loaded(&c) == 1 && scene_case_dlopen(&c) == 1 &&
                scene_case_loaded(&c, "hindered_settling_richardson_zaki.so") == 1,
            "%d libraries loaded, %ld dlopen", scene_case_n_loaded(&c), scene_case_dlopen(&c));
  CHECK(scene_case_loaded(&c, "drag_") == 0 && scene_case_loaded(&c, "viscosity_") == 0);
  const sluice_closure_use *u = scene_case_usage(&c, "hindered_settling", "richardson_zaki");
  CHECK_MSG(u && u->instances == 1 && u->calls == 1 && u->points == 1025,
            "settling closure: %ld instances, %llu calls, %llu points over %ld steps", u ? u->instances : 0,
            u ? u->calls : 0ULL, u ? u->points : 0ULL, r.steps);
  CHECK(r.steps == 40);
  scene_case_close(&c);

  /* the mixture with a phi-dependent viscosity: two libraries, nothing else */
  const char *bsets[] = {"mesh.cells=4,6", "time.end=2e-3", "output.every=0", NULL};
  if (run(&c, "boycott", bsets, "skip_boycott.h5", &r)) return;
  CHECK_MSG(scene_case_n_loaded(&c) == 2 && scene_case_dlopen(&c) == 2 &&
                scene_case_loaded(&c, "hindered_settling_nigam.so") &&
                scene_case_loaded(&c, "viscosity_krieger_dougherty.so"),
            "boycott: %d libraries loaded", scene_case_n_loaded(&c));
  const sluice_closure_use *v = scene_case_usage(&c, "viscosity", "krieger_dougherty");
  CHECK(v && v->instances == 1);
  scene_case_close(&c);

  /* two_fluid: the drag and the solids pressure */
  const char *fsets[] = {"time.end=1", NULL};
  if (run(&c, "fluidized_bed", fsets, "skip_fluidized.h5", &r)) return;
  CHECK_MSG(scene_case_n_loaded(&c) == 2 && scene_case_loaded(&c, "drag_richardson_zaki_consistent.so") &&
                scene_case_loaded(&c, "solids_pressure_pringle_exponential.so"),
            "fluidized_bed: %d libraries loaded", scene_case_n_loaded(&c));
  const sluice_closure_use *k = scene_case_usage(&c, "drag", "richardson_zaki_consistent");
  CHECK(k && k->instances == 1 && k->calls > 0);
  scene_case_close(&c);
}

/* The viscosity closure is evaluated exactly once per quadrature point of
 * every assembly pass (matrix, residual, and the output's cell
 * diagnostics), and created once per continuation stage. */
static void test_closure_calls_per_assembly(void) {
  const char *sets[] = {"solver.continuation_steps=4", NULL};
  scene_case c;
  sluice_summary r;
  if (run(&c, "bingham_channel", sets, "skip_channel.h5", &r)) return;
  const sluice_closure_use *u = scene_case_usage(&c, "viscosity", "bingham");
  if (!u) {
    CHECK_MSG(0, "bingham_channel: the viscosity closure was never created");
    scene_case_close(&c);
    return;
  }
  long passes = r.matrix_assemblies + r.residual_assemblies + r.output_times; /* every output has the diagnostics */
  long cells = 200;
  unsigned long long per_pass = u->points / (unsigned long long)passes;
  printf(
      "bingham_channel: %llu points in %llu calls over %ld assembly passes (%llu points per cell and pass), %ld "
      "instances\n",
      u->points, u->calls, passes, per_pass / (unsigned long long)cells, u->instances);
  CHECK_MSG(u->points % (unsigned long long)passes == 0 && per_pass % (unsigned long long)cells == 0,
            "%llu points over %ld passes of %ld cells", u->points, passes, cells);
  /* the scene's own closure (provenance), then one per stage: eps changes */
  CHECK_MSG(u->instances == 6 && r.steps == 5, "%ld viscosity instances for %ld continuation stages", u->instances,
            r.steps);
  CHECK(r.output_times == 1);
  scene_case_close(&c);
}

/* Steady scenes stop at convergence: one solve, few iterations, and the
 * result says converged. */
static void test_steady_stops(void) {
  const char *sets[] = {"mesh.cells=16,16", NULL};
  scene_case c;
  sluice_summary r;
  if (run(&c, "cavity_re100", sets, "skip_re100.h5", &r)) return;
  printf("cavity_re100: %ld step, %ld Newton iterations: %s\n", r.steps, r.nonlinear_iterations, r.stop_reason);
  CHECK_MSG(r.converged && r.steps == 1 && r.nonlinear_iterations >= 2 && r.nonlinear_iterations <= 10,
            "converged %d, %ld steps, %ld iterations", r.converged, r.steps, r.nonlinear_iterations);
  /* Newton's own tests (cavity_re100: nonlinear_tolerance = 1e-10, the residual reduced by 1e10) */
  CHECK_MSG(r.correction <= 1e-10 || r.residual <= 1e-10 * r.residual0,
            "last relative correction %g, residual %g from %g: not converged", r.correction, r.residual, r.residual0);
  CHECK_CONTAINS(r.stop_reason, "converged");
  CHECK(r.output_times == 1);
  scene_case_close(&c);

  /* a transient two-fluid column stops when steady: far fewer steps than end/dt */
  if (run(&c, "fluidized_bed", NULL, "skip_fluidized_steady.h5", &r)) return;
  file_check fc;
  check_output_file("skip_fluidized_steady.h5", 0.64, &fc);
  printf("fluidized_bed: steady at t = %g after %ld steps (end %g)\n", r.t_reached, r.steps, r.t_end);
  CHECK_MSG(r.t_reached < 0.5 * r.t_end && r.steps < 0.5 * r.t_end / 0.05,
            "fluidized_bed: ran to t = %g (end %g) in %ld steps", r.t_reached, r.t_end, r.steps);
  CHECK_MSG(fc.t_last == r.t_reached && fc.checkpoint_time == r.t_reached, "last output %g, checkpoint %g, stop %g",
            fc.t_last, fc.checkpoint_time, r.t_reached);
  scene_case_close(&c);
}

/* Fields not asked for are not written (nor computed: the counters of what
 * was written match the file). */
static void test_unused_fields(void) {
  const char *sets[] = {"mesh.cells=8,8", "output.fields=velocity", NULL};
  scene_case c;
  sluice_summary r;
  if (run(&c, "cavity_stokes", sets, "skip_fields.h5", &r)) return;
  scene_case_close(&c);
  sl_output_contents ct;
  sl_output_mesh m;
  sl_diag d;
  if (sl_output_read_contents("skip_fields.h5", &ct, &d) || sl_output_read_mesh("skip_fields.h5", &m, &d)) {
    CHECK_MSG(0, "skip_fields.h5: %s", d.msg);
    return;
  }
  CHECK_MSG(ct.n_fields == 1 && strcmp(ct.fields[0].name, "velocity") == 0, "%d fields, the first '%s'", ct.n_fields,
            ct.n_fields ? ct.fields[0].name : "");
  CHECK(r.output_datasets == r.output_times && r.output_times == ct.n_steps);
  CHECK_MSG(r.output_bytes == (double)ct.n_steps * m.n_vertices * 3 * sizeof(double), "%g bytes written for %d nodes",
            r.output_bytes, (int)m.n_vertices);
  sl_output_contents_free(&ct);
  sl_output_mesh_free(&m);

  /* no viscosity closure: by default no shear_rate, viscosity or yielded */
  const char *dsets[] = {"mesh.cells=8,8", "output.fields=\"\"", NULL};
  if (run(&c, "cavity_re100", dsets, "skip_default_fields.h5", &r)) return;
  scene_case_close(&c);
  if (sl_output_read_contents("skip_default_fields.h5", &ct, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  CHECK_MSG(
      ct.n_fields == 2 && strcmp(ct.fields[0].name, "pressure") == 0 && strcmp(ct.fields[1].name, "velocity") == 0,
      "%d fields written without a viscosity closure", ct.n_fields);
  sl_output_contents_free(&ct);

  /* a mixture asked for velocity and phi: no pressure, no stream function */
  const char *msets[] = {"mesh.cells=4,6", "time.end=2e-3", "output.every=0", "output.fields=velocity, phi", NULL};
  if (run(&c, "boycott", msets, "skip_mixture_fields.h5", &r)) return;
  scene_case_close(&c);
  if (sl_output_read_contents("skip_mixture_fields.h5", &ct, &d)) {
    CHECK_MSG(0, "%s", d.msg);
    return;
  }
  CHECK_MSG(ct.n_fields == 2 && strcmp(ct.fields[0].name, "phi") == 0 && strcmp(ct.fields[1].name, "velocity") == 0,
            "%d fields written for 'velocity, phi'", ct.n_fields);
  CHECK(r.output_datasets == 2 * r.output_times);
  sl_output_contents_free(&ct);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  snprintf(configs, sizeof configs, "%s/configs", src ? src : ".");
  test_stokes_factorises_once();
  test_only_named_closures();
  test_closure_calls_per_assembly();
  test_steady_stops();
  test_unused_fields();
  return sl_test_summary();
}
