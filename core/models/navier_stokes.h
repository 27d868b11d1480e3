/* The navier_stokes model: a scene's incompressible, generalized-Newtonian
 * flow, from the INI file to the output file.
 *
 * Sections read (README "Scenes" has the user's view):
 *   [scene]  geometry = line | planar | axisymmetric
 *   [mesh]   see core/models/scene_mesh.h
 *   [fluid]  density, viscosity (the Newtonian viscosity when no
 *            [closure.viscosity] is given)
 *   [closure.viscosity]  a generalized-Newtonian law of the shear rate
 *   [flow]   third_component, convection, gravity, body_force, rotation,
 *            rotation_centre
 *   [boundary.NAME] type = wall | velocity | slip | axis | open | pressure
 *            | traction; velocity = expressions of x, y, t; pressure; traction
 *   [initial] velocity = expressions of x, y
 *   [time]   scheme = steady | bdf1 | bdf2, end, dt, tolerance, adaptive,
 *            dt_min, dt_max, max_steps
 *   [solver] linear, nonlinear, nonlinear_tolerance, max_iterations,
 *            picard_first, continuation, continuation_from, continuation_steps
 *   [output] file, every, fields
 */
#ifndef SLUICE_MODELS_NAVIER_STOKES_H
#define SLUICE_MODELS_NAVIER_STOKES_H

#include <signal.h>

#include "core/config/ini.h"
#include "core/assembly/flow.h"
#include "core/fe/dofmap.h"
#include "core/io/output.h"
#include "core/plugin/registry.h"
#include "core/solve/linsolve.h"
#include "core/util/diag.h"

/* A model riding on the flow: the mixture model's solids fraction. The flow
 * takes density rho_f + phi (rho_s - rho_f), buoyancy (rho - rho_f) g (the
 * pressure is then the reduced pressure p - rho_f g.x) and the viscosity
 * closure's input `phi` from the coupling's cell values; the coupling
 * advances them after every converged flow step. A step the coupling
 * refuses (SL_EFAILED) is retried smaller, like a failed Newton solve. */
typedef struct sl_ns_coupling {
  void *user;
  double rho_solid;
  /* The coupled model's output fields, named in [output] fields with the
   * flow's (all of them by default). */
  const char *const *field_names;
  int n_fields;
  /* After the velocity space exists; `flow` stays valid through the run
   * (its viscosity gives the shear rate); open[b] != 0 marks boundaries
   * where the velocity is free (open, pressure, traction); pairs are the
   * periodic boundary pairs; bit k of `fields` says field_names[k] is to be
   * written (what is not written need not be computed or allocated). */
  int (*setup)(void *user, const sl_th_space *th, const sl_flow_opts *flow, const unsigned char *open,
               const sl_periodic_pair *pairs, int n_pairs, unsigned fields, sl_diag *d);
  const double *(*cell_phi)(void *user);                 /* the current cell values */
  /* An extra stress T of the coupled model in the flow's momentum, -div T,
   * in the pressure space (sl_flow_opts extra_stress); set by setup and
   * kept current by the coupling through the run; NULL: none. */
  const double *extra_stress;
  /* A momentum sink of the coupled model per cell (sl_flow_opts cell_drag), set by setup; before each attempt of a
   * step over dt the flow calls prepare (may be NULL), which brings it up to date. NULL: none. */
  const double *cell_drag;
  int (*prepare)(void *user, double dt, sl_diag *d);
  /* The cell values whose buoyancy the flow takes in place of cell_phi's (the part of phi the pressure does not
   * carry, core/assembly/hydrostatic.h), and the pressure that part left out carries, per pressure dof, added to
   * the pressure written; set by setup, kept current by the coupling; NULL: cell_phi, none. */
  const double *buoyant_phi;
  const double *pressure_shift;
  /* Whether the last accepted step left what the flow reads of the coupled model (phi) bitwise as it was; the
   * flow then reuses a solve that was at a fixed point (may be NULL: always solve). */
  int (*unchanged)(void *user);
  /* Whether the coupled model loads the flow with nothing (its buoyancy all carried by the pressure, to 1e-12 of
   * its scale, and no stress of its own): a flow at rest between walls at rest then stays at rest and is not solved
   * (may be NULL: never). */
  int (*at_rest)(void *user);
  /* Into a trial state, from the converged velocity u at t + dt and the
   * integrator's time derivative dudt of it (both combined numbering). */
  int (*advance)(void *user, double t, double dt, const double *u, const double *dudt, sl_diag *d);
  void (*accept)(void *user);                            /* the trial becomes current */
  int (*write)(void *user, sl_output *out, sl_diag *d);  /* inside an output step */
  int (*checkpoint)(void *user, sl_checkpoint_array *arrays, int max); /* arrays to save: their count */
  int (*restore)(void *user, const sl_checkpoint *ck, sl_diag *d);
  int (*provenance)(void *user, sl_provenance_closure *c, int max, char *buf, size_t buf_len); /* closures used */
} sl_ns_coupling;

typedef struct sl_ns_run_opts {
  const char *scene_path;     /* for the default output name */
  const char *output;         /* overrides [output] file; NULL: keep */
  const char *restart;        /* continue from this file's last checkpoint; NULL: start */
  const char *sluice_version; /* for provenance */
  /* Called after every accepted step (progress display); may be NULL. */
  void (*monitor)(void *user, double t, double dt, long step, int nonlinear_iterations);
  void *monitor_user;
  volatile sig_atomic_t *interrupt; /* set asynchronously (Ctrl-C): stop after the step, save */
  const sl_ns_coupling *coupling;   /* NULL: single-phase flow */
  int solve_every_step;             /* solve the flow even where its result is known (verification) */
} sl_ns_run_opts;

typedef struct sl_ns_result {
  long steps, rejected_steps, nonlinear_iterations;
  long matrix_assemblies, residual_assemblies; /* full (matrix and right-hand side) and right-hand-side-only */
  int used_picard;
  double t_start, t_end, t_reached;
  /* wall seconds (assembly from the nonlinear solver, factorisation and
   * solve from the linear solver's clocks) */
  double assembly, factorisation, solve, output;
  const char *step_limit;   /* what limited the step most often (static string) or NULL */
  char output_path[4096];
  char linear_summary[256];
  char coupling_summary[256]; /* the coupled model's one line, or "" */
  /* What was done and skipped (the profile of `sluice run`); models that do
   * not fill these leave them zero. */
  sl_linsolve_stats linear;  /* the flow's linear solver: symbolic and numeric factorisations, reuses */
  int converged;             /* steady: the (last) solve converged */
  double correction;         /* steady: its last relative Newton correction */
  double residual0, residual; /* steady: |b|_2 at the start and at the end of that solve */
  long roundoff_accepted;    /* solves accepted with their residual at round-off (see navier_stokes.c) */
  long solves_skipped;       /* steps whose flow was known without a solve (a closed column at rest, a vessel at
                                rest under no load, a flow at a fixed point whose coupled phi did not change) */
  char stop_reason[256];     /* why the run ended, one line ("" when it failed: the error says why) */
  /* CPU seconds: set-up (mesh, spaces, closures, output file), the flow's
   * solves, the coupled model's steps (the mixture's transport), output */
  double cpu_setup, cpu_flow, cpu_coupled, cpu_output;
  long output_times, output_datasets; /* written: output times, datasets (fields) over all of them */
  double output_bytes;                /* of field data */
} sl_ns_result;

/* The simulated time span the run will cover (for the progress display). */
int sl_ns_time_span(const sl_ini *ini, double *t0, double *t1, sl_diag *d);

/* Runs the scene. Returns 0, SL_EBADINPUT (bad scene: nothing written) or
 * SL_EFAILED (the run failed: the last good state is in the output file and
 * the message says where and why). */
int sl_ns_run(sl_ini *ini, const sl_registry *reg, const sl_ns_run_opts *o, sl_ns_result *res, sl_diag *d);

#endif
