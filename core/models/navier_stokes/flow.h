/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The flow of a scene: incompressible, generalized-Newtonian flow on
 * Taylor-Hood elements, from the typed scene to solves and output. The
 * navier_stokes model is this flow alone; the mixture model rides on it
 * (its solids fraction gives the flow's density, buoyancy and viscosity
 * input phi, and an extra stress).
 *
 * Keys (their defaults, units and ranges: the schemas in navier_stokes.c and
 * core/models/mixture/mixture.c):
 *   [scene]  geometry = line | planar | axisymmetric
 *   [fluid]  density, viscosity (the Newtonian viscosity when no
 *            [closure.viscosity] is given)
 *   [closure.viscosity]  a generalized-Newtonian law of the shear rate
 *   [flow]   third_component, convection, gravity, body_force, rotation,
 *            rotation_centre
 *   [boundary.NAME] type = wall | velocity | slip (straight along x or y:
 *            the normal component fixed; curved: core/assembly/slip.h) | axis | open | pressure
 *            | traction | periodic; velocity = expressions of x, y, t;
 *            pressure; traction; partner; force (wall, velocity: the
 *            boundary force as the output scalars force_x_NAME, force_y_NAME)
 *   [initial] velocity = expressions of x, y
 *   [time]   scheme = steady | bdf1 | bdf2, end, dt, tolerance, adaptive,
 *            dt_min, dt_max, max_steps
 *   [solver] linear, ordering, nonlinear, nonlinear_tolerance,
 *            max_iterations, picard_first, continuation, continuation_from,
 *            continuation_steps
 *   [output] file, every, fields, stream_function_stats (the stream
 *            function's extremes and the phase of its first azimuthal mode) */
#ifndef SLUICE_MODELS_NAVIER_STOKES_FLOW_H
#define SLUICE_MODELS_NAVIER_STOKES_FLOW_H

#include "core/assembly/flow.h"
#include "core/fe/dofmap.h"
#include "core/io/output.h"
#include "core/models/navier_stokes/flow_problem.h"
#include "core/scene/scene.h"
#include "core/solve/linsolve.h"
#include "core/time/model.h"

/* A boundary of the flow, as the scene gives it. */
enum { NS_WALL, NS_VELOCITY, NS_SLIP, NS_AXIS, NS_OPEN, NS_PRESSURE, NS_TRACTION, NS_PERIODIC };
#define NS_BOUNDARY_TYPES "wall|velocity|slip|axis|open|pressure|traction|periodic"

typedef struct ns_boundary {
  int type;
  sl_scene_exprs velocity; /* of x, y, t */
  double pressure;
  sl_reals traction;
  const char *partner;
  sl_scene_expr phi; /* the mixture: the solids fraction of inflow, of x, y, t (core/models/mixture/inflow.h) */
  int force;         /* write the force of the fluid on this boundary (wall, velocity) with every output */
} ns_boundary;

/* The key tables the two models share (navier_stokes.c). */
extern const sl_key_table sl_flow_keys_scene;    /* [scene] geometry */
extern const sl_key_table sl_flow_keys_flow;     /* [flow] */
extern const sl_key_table sl_flow_keys_time;     /* [time] */
extern const sl_key_table sl_flow_keys_solver;   /* [solver] */
extern const sl_key_table sl_flow_keys_boundary; /* [boundary.NAME] */
extern const sl_key_table sl_flow_keys_initial;  /* [initial] velocity */

/* The model's configuration the flow reads ([initial] velocity). */
typedef struct sl_flow_config {
  sl_scene_exprs velocity;
  int stream_stats; /* [output] stream_function_stats */
} sl_flow_config;

typedef struct sl_flow sl_flow;

/* What rides on the flow: a solids fraction per cell (the mixture's; the
 * array stays the rider's and is read at every assembly), its density, and
 * an extra stress in the pressure space (sl_flow_opts extra_stress). */
typedef struct sl_flow_rider {
  double rho_solid;
  const double *phi;
  const double *extra_stress;
  void *user; /* for the hooks below */
  /* A momentum sink per cell (sl_flow_opts cell_drag); before each solve of a step over dt the flow calls
   * prepare (may be NULL) with the step and its predicted velocity, which brings it up to date. NULL: none. */
  const double *cell_drag;
  int (*prepare)(void *user, double dt, const double *u_predicted, sl_diag *d);
  /* The cell values whose buoyancy the flow takes in place of phi's (the part of phi the pressure does not carry,
   * core/assembly/hydrostatic.h), and the pressure of the part left out, per pressure dof, added to the pressure
   * written. NULL: phi, none. */
  const double *buoyant_phi;
  const double *pressure_shift;
  /* Whether the last accepted step left phi bitwise as it was: a flow at a fixed point is then reused (NULL:
   * always solve). */
  int (*unchanged)(void *user);
  /* Whether the rider loads the flow with nothing (its buoyancy all carried by the pressure, to 1e-12 of its
   * scale, and no stress of its own): a flow at rest between walls at rest then stays at rest and is not solved
   * (NULL: never). */
  int (*at_rest)(void *user);
  /* The conservative face fluxes the rider moves phi with (per mesh face), for the stream function; NULL: the
   * flow's own. */
  const double *face_flux;
} sl_flow_rider;

/* The flow's output fields, in [output] fields' order; the rider's follow them. */
enum { SL_FLOW_N_FIELDS = 6, SL_FLOW_STREAM_FUNCTION = 32 };
extern const char *const sl_flow_field_names[SL_FLOW_N_FIELDS];

/* The flow from the scene: mesh, boundaries, space, physics, solver.
 * rider_phi: 1 when a solids fraction will ride on it (its density and
 * phi input are then the rider's). flow_config: the model's [initial]
 * velocity. fields: bits of [output] fields over sl_flow_field_names.
 * info gets the BDF state (the velocity and pressure, initial velocity
 * interpolated). */
int sl_flow_create(sl_scene *sc, const sl_flow_config *flow_config, double rho_solid, unsigned fields, sl_flow **out,
                   sl_model_info *info, sl_diag *d);
void sl_flow_destroy(sl_flow *f);
/* Attaches the rider (after sl_flow_create, before the first solve). */
void sl_flow_ride(sl_flow *f, const sl_flow_rider *r);

const sl_th_space *sl_flow_space(const sl_flow *f);
const sl_flow_opts *sl_flow_options(const sl_flow *f);
/* 1 for the boundaries where the velocity is free (open, pressure, traction), by mesh boundary. */
const unsigned char *sl_flow_open(const sl_flow *f);
/* 1 for the curved slip walls (core/assembly/slip.h), by mesh boundary: no flux through their faces, though
 * each chord's own trace flux is not zero (sl_face_flux_close); NULL: none. */
const unsigned char *sl_flow_closed(const sl_flow *f);
const sl_periodic_pair *sl_flow_periodic(const sl_flow *f, int *n_pairs);
int sl_flow_axisymmetric(const sl_flow *f);

/* The model hooks (core/time/model.h) of the flow alone. */
int sl_flow_step(sl_flow *f, sl_step *s, int *iterations, sl_diag *d);
/* After the loop accepted a step (and the rider its part): whether the flow is at a fixed point. */
void sl_flow_accept(sl_flow *f);
int sl_flow_steady(sl_flow *f, double *u, long *steps, long *iterations, sl_diag *d);
int sl_flow_write_mesh(sl_flow *f, sl_output *out, sl_diag *d);
int sl_flow_write(sl_flow *f, sl_output *out, const double *u, sl_diag *d);
int sl_flow_checkpoint(sl_flow *f, sl_checkpoint_array *a, int max);
int sl_flow_restore(sl_flow *f, const sl_checkpoint *ck, sl_diag *d);
void sl_flow_stats(sl_flow *f, sl_model_stats *st);

#endif
