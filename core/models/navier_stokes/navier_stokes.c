/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The navier_stokes model (navier_stokes.h): its schema, and the flow
 * (flow.h) as its ops. The key tables here are the flow's, shared with the
 * mixture model. */
#include "core/models/navier_stokes/navier_stokes.h"

#include <stdlib.h>

#include "core/models/navier_stokes/flow.h"
#include "core/scene/keys.h"
#include "core/scene/solver.h"

#define TABLE(name, keys) const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}

static const sl_key scene_keys[] = {
    {.section = "scene",
     .name = "geometry",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(geometry),
     .def = 1,
     .choices = "line|planar|axisymmetric",
     .help = "a 1-D cross-section, 2-D planar, or axisymmetric (r, z)"},
};
TABLE(sl_flow_keys_scene, scene_keys);

static const sl_key flow_keys[] = {
    {.section = "flow",
     .name = "third_component",
     .type = SL_KEY_BOOL,
     SL_AT_SCENE(flow.third_component),
     .help = "solve the out-of-plane velocity (planar, line: a fully developed flow) or the swirl (axisymmetric)"},
    {.section = "flow",
     .name = "convection",
     .type = SL_KEY_BOOL,
     SL_AT_SCENE(flow.convection),
     .def = 1,
     .help = "include rho (u.grad)u (false: Stokes flow)"},
    {.section = "flow",
     .name = "scheme",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(flow.scheme),
     .def = 2,
     .choices = "monolithic|projection|auto",
     .help = "a transient step: velocity and pressure in one coupled solve, or split (an incremental rotational "
             "pressure-correction step, Guermond, Minev & Shen 2006, with a constant pressure Poisson operator "
             "factorised once, Guermond & Salgado 2009); auto: projection for a transient suspension (solids "
             "riding on the flow) with convection on one rank in a frame at rest without a yield stress, monolithic "
             "otherwise (docs/transient_cost.md)"},
    {.section = "flow",
     .name = "gravity",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(flow.gravity),
     .max_n = 3,
     .units = "m s^-2",
     .help = "gravitational acceleration per velocity component (default none)"},
    {.section = "flow",
     .name = "body_force",
     .type = SL_KEY_EXPRS,
     SL_AT_SCENE(flow.body_force),
     .vars = "x,y,t",
     .units = "N m^-3",
     .help = "body force per unit volume per component, numbers or expressions of x, y, t (e.g. -dp/dz of a fully "
             "developed flow, or a manufactured solution's forcing)"},
    {.section = "flow",
     .name = "rotation",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(flow.rotation),
     .min = -1e6,
     .max = 1e6,
     .units = "rad s^-1",
     .help = "angular velocity of the frame (planar: about rotation_centre; axisymmetric: the "
             "axis): Coriolis and centrifugal forces"},
    {.section = "flow",
     .name = "rotation_centre",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(flow.rotation_centre),
     .max_n = 2,
     .units = "m",
     .def_list = (const double[]){0.0, 0.0},
     .n_def = 2,
     .help = "planar: the rotation axis x, y"},
};
TABLE(sl_flow_keys_flow, flow_keys);

static const sl_key time_keys[] = {
    {.section = "time",
     .name = "scheme",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(time.scheme),
     .def = 2,
     .choices = "steady|bdf1|bdf2",
     .def_doc = "bdf2; steady when the scene has no [time] section",
     .help = "the steady solve, or BDF of order 1 or 2 (variable step)"},
    {.section = "time",
     .name = "end",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(time.end),
     .min = 0.0,
     .max = 1e12,
     .units = "s",
     .def_doc = "required (transient)",
     .help = "end time"},
    {.section = "time",
     .name = "dt",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(time.dt),
     .min = 1e-15,
     .max = 1e9,
     .units = "s",
     .def_doc = "required (transient)",
     .help = "first (or fixed) step"},
    {.section = "time",
     .name = "tolerance",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(time.tolerance),
     .def = 1e-3,
     .min = 1e-14,
     .max = 1.0,
     .help = "local error tolerance of adaptive steps (relative to the largest velocity)"},
    {.section = "time",
     .name = "adaptive",
     .type = SL_KEY_BOOL,
     SL_AT_SCENE(time.adaptive),
     .def = 1,
     .help = "adapt the step to the local error estimate"},
    {.section = "time",
     .name = "controller",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(time.controller),
     .choices = "h211pi|pi|h211b|elementary",
     .help = "the adaptive step's controller: digital filters of the error estimates (Soderlind 2003; PI: "
             "Gustafsson 1991)"},
    {.section = "time",
     .name = "dt_min",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(time.dt_min),
     .min = 0.0,
     .max = 1e9,
     .units = "s",
     .def_doc = "dt x 1e-6",
     .help = "smallest step before the run gives up"},
    {.section = "time",
     .name = "dt_max",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(time.dt_max),
     .min = 1e-15,
     .max = 1e12,
     .units = "s",
     .def_doc = "end / 10 (adaptive), else dt",
     .help = "largest step"},
    {.section = "time",
     .name = "max_steps",
     .type = SL_KEY_INT,
     SL_AT_SCENE(time.max_steps),
     .def = 1e8,
     .min = 1,
     .max = 1e8,
     .help = "stop (with a checkpoint) after this many steps of this run"},
};
TABLE(sl_flow_keys_time, time_keys);

static const sl_key solver_keys[] = {
    {.section = "solver",
     .name = "linear",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.linear),
     .choices = SL_SCENE_LINEAR_CHOICES,
     .help = "the sparse direct solver (auto: klu below 20 000 unknowns or on the reference BLAS, else umfpack; "
             "a matrix factorised once, the split step's coupled start, umfpack from 10 000)"},
    {.section = "solver",
     .name = "reuse",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.reuse),
     .choices = SL_SCENE_REUSE_CHOICES,
     .help = "Newton's corrections by FGMRES preconditioned with an older factorisation (auto) or a factorisation "
             "per changed matrix (never)"},
    {.section = "solver",
     .name = "ordering",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.ordering),
     .choices = SL_SCENE_ORDERING_CHOICES,
     .help = "klu's fill-reducing ordering (auto: AMD, METIS from 30 000 unknowns)"},
    {.section = "solver",
     .name = "nonlinear",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.nonlinear),
     .choices = "newton|picard",
     .help = "Newton (line search, Picard fallback) or Picard only"},
    {.section = "solver",
     .name = "nonlinear_tolerance",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solver.nonlinear_tolerance),
     .def = 1e-8,
     .min = 1e-16,
     .max = 1.0,
     .def_doc = "1e-8; an adaptive time step: 1e-3 of [time] tolerance when larger",
     .help = "relative tolerance of Newton/Picard on the velocity correction"},
    {.section = "solver",
     .name = "max_iterations",
     .type = SL_KEY_INT,
     SL_AT_SCENE(solver.max_iterations),
     .def = 30,
     .min = 1,
     .max = 1000,
     .help = "nonlinear iterations per step"},
    {.section = "solver",
     .name = "picard_first",
     .type = SL_KEY_INT,
     SL_AT_SCENE(solver.picard_first),
     .min = 0,
     .max = 1000,
     .help = "Picard iterations before Newton (far initial guesses)"},
    {.section = "solver",
     .name = "continuation",
     .type = SL_KEY_STRING,
     SL_AT_SCENE(solver.continuation),
     .def_text = "",
     .help = "steady: approach this section.key's value (a real key or a closure parameter) in stages"},
    {.section = "solver",
     .name = "continuation_from",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solver.continuation_from),
     .min = -1e300,
     .max = 1e300,
     .def_doc = "required with continuation",
     .help = "the first value of the continuation parameter"},
    {.section = "solver",
     .name = "continuation_steps",
     .type = SL_KEY_INT,
     SL_AT_SCENE(solver.continuation_steps),
     .def = 5,
     .min = 1,
     .max = 1000,
     .help = "continuation stages (geometric when both ends are positive)"},
    {.section = "solver",
     .name = "continuation_tolerance",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solver.continuation_tolerance),
     .min = 1e-16,
     .max = 1.0,
     .def_doc = "nonlinear_tolerance",
     .help = "Newton's relative tolerance at the continuation stages before the last (which take "
             "nonlinear_tolerance): a stage only starts the next"},
    {.section = "solver",
     .name = "skip_known",
     .type = SL_KEY_BOOL,
     SL_AT_SCENE(solver.skip_known),
     .def = 1,
     .help = "transient: skip the solves whose result is known (a closed 1-D column's velocity, a vessel at rest "
             "under no load, a flow at a fixed point whose phi did not change)"},
};
TABLE(sl_flow_keys_solver, solver_keys);

#define B(field) SL_AT_BOUNDARY(ns_boundary, field)
#define ON(t) (1u << (t))
static const sl_key boundary_keys[] = {
    {.section = "boundary",
     .name = "type",
     .type = SL_KEY_CHOICE,
     B(type),
     .choices = NS_BOUNDARY_TYPES,
     .help = "wall (no slip), velocity (given), slip (no normal flow, no shear; along x or y or curved: "
             "docs/verification.md), axis (r = 0), open (no traction), pressure (the normal stress), traction, "
             "periodic (with its partner)"},
    {.section = "boundary",
     .name = "velocity",
     .type = SL_KEY_EXPRS,
     B(velocity),
     .vars = "x,y,t",
     .max_n = 3,
     .units = "m s^-1",
     .when_type = ON(NS_VELOCITY),
     .help = "the velocity, one expression per component"},
    {.section = "boundary",
     .name = "pressure",
     .type = SL_KEY_REAL,
     B(pressure),
     .min = -1e12,
     .max = 1e12,
     .units = "Pa",
     .when_type = ON(NS_PRESSURE),
     .def_doc = "required with type = pressure",
     .help = "the normal stress -p n"},
    {.section = "boundary",
     .name = "traction",
     .type = SL_KEY_REALS,
     B(traction),
     .max_n = 3,
     .units = "Pa",
     .when_type = ON(NS_TRACTION),
     .help = "the traction per component"},
    {.section = "boundary",
     .name = "partner",
     .type = SL_KEY_STRING,
     B(partner),
     .def_text = "",
     .when_type = ON(NS_PERIODIC),
     .help = "the opposite boundary of a periodic pair (on one side of the pair)"},
    {.section = "boundary",
     .name = "force",
     .type = SL_KEY_BOOL,
     B(force),
     .when_type = ON(NS_WALL) | ON(NS_VELOCITY),
     .help = "write the force of the fluid on this boundary with every output, as the scalars force_x_NAME and "
             "force_y_NAME (force_r_, force_z_ axisymmetric; N/m planar, N axisymmetric): minus the momentum "
             "residual on its nodes (John 2004)"},
};
TABLE(sl_flow_keys_boundary, boundary_keys);

static const sl_key initial_keys[] = {
    {.section = "initial",
     .name = "velocity",
     .type = SL_KEY_EXPRS,
     SL_AT_MODEL(sl_flow_config, velocity),
     .vars = "x,y",
     .max_n = 3,
     .units = "m s^-1",
     .help = "the initial velocity, one expression per component "
             "(default at rest)"},
    /* an output key of the flow's own configuration, in this table because both flow models include it */
    {.section = "output",
     .name = "stream_function_stats",
     .type = SL_KEY_BOOL,
     SL_AT_MODEL(sl_flow_config, stream_stats),
     .help = "planar: write the stream function's largest and smallest values (stream_function_max, _min) and the "
             "phase of its first azimuthal mode about rotation_centre, arg int psi e^(i theta) dA "
             "(stream_function_phase, rad), and the centre of the vortex of largest |psi| (its extremum from a "
             "local quadratic fit: stream_function_centre_x, _y, and its angle about rotation_centre, "
             "stream_function_centre_phase), with each output"},
};
TABLE(sl_flow_keys_initial, initial_keys);

typedef struct ns_config {
  sl_flow_config flow; /* first: the flow's keys address it from the config's start */
} ns_config;

const sl_schema sl_navier_stokes_schema = {
    .model = "navier_stokes",
    .title = "incompressible generalized-Newtonian flow",
    .summary =
        "Taylor-Hood elements (Q2/Q1, P2/P1), planar, axisymmetric with swirl, or a 1-D cross-section with its "
        "out-of-plane velocity; a viscosity closure of the shear rate (Bingham, Herschel-Bulkley, ...), a "
        "rotating frame, periodic boundaries; Newton with line search and Picard fallback, continuation; steady "
        "or adaptive BDF1/BDF2.",
    .tables = {&sl_keys_scene, &sl_flow_keys_scene, &sl_keys_mesh, &sl_keys_fluid, &sl_flow_keys_flow,
               &sl_flow_keys_time, &sl_flow_keys_solver, &sl_keys_output, &sl_keys_plugins, &sl_flow_keys_boundary,
               &sl_flow_keys_initial},
    .n_tables = 11,
    .config_size = sizeof(ns_config),
    .boundary_size = sizeof(ns_boundary),
    .roles = {{"viscosity", 0, "a generalized-Newtonian viscosity of the shear rate (none: [fluid] viscosity)"}},
    .n_roles = 1,
    .fields = sl_flow_field_names,
    .n_fields = SL_FLOW_N_FIELDS,
};

/* ---- ops: the flow alone ------------------------------------------------------------ */

static int ns_setup(void **self, sl_scene *sc, sl_model_info *info, sl_diag *d) {
  unsigned mask;
  unsigned def = 1u | 2u | (sl_scene_closure(sc, "viscosity") ? 4u | 8u | 16u : 0u);
  int rc = sl_scene_output_fields(sc, def, &mask, d);
  if (rc) return rc;
  const ns_config *cfg = sc->config;
  sl_flow *f;
  if ((rc = sl_flow_create(sc, &cfg->flow, -1.0, mask, &f, info, d))) return rc;
  *self = f;
  return 0;
}

static int ns_step(void *self, sl_step *s, int *iterations, sl_diag *d) { return sl_flow_step(self, s, iterations, d); }
static void ns_accept(void *self, const sl_step *s, int *steady) {
  (void)s, (void)steady;
  sl_flow_accept(self);
}
static int ns_steady(void *self, double *u, long *steps, long *its, sl_diag *d) {
  return sl_flow_steady(self, u, steps, its, d);
}
static int ns_write_mesh(void *self, sl_output *out, sl_diag *d) { return sl_flow_write_mesh(self, out, d); }
static int ns_write(void *self, sl_output *out, double t, const double *u, sl_diag *d) {
  (void)t;
  return sl_flow_write(self, out, u, d);
}
static int ns_checkpoint(void *self, sl_checkpoint_array *a, int max) { return sl_flow_checkpoint(self, a, max); }
static int ns_restore(void *self, const sl_checkpoint *ck, sl_diag *d) { return sl_flow_restore(self, ck, d); }
static void ns_stats(void *self, const sl_run_result *res, sl_model_stats *st) {
  (void)res;
  sl_flow_stats(self, st);
}
static void ns_destroy(void *self) { sl_flow_destroy(self); }

const sl_model_ops sl_navier_stokes_ops = {.setup = ns_setup,
                                           .step = ns_step,
                                           .accept = ns_accept,
                                           .steady = ns_steady,
                                           .write_mesh = ns_write_mesh,
                                           .write = ns_write,
                                           .checkpoint = ns_checkpoint,
                                           .restore = ns_restore,
                                           .stats = ns_stats,
                                           .destroy = ns_destroy};
