/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Internals of the two-fluid model shared by its variants: the 1-D column
 * (two_fluid.c, one step in two_fluid_step.c), the 2-D model
 * (two_fluid_plane*.c) and the shear layer (shear_layer.c); their schemas
 * (schema.c) and configuration. */
#ifndef SLUICE_MODELS_TWO_FLUID_IMPL_H
#define SLUICE_MODELS_TWO_FLUID_IMPL_H

#include "core/config/expr.h"
#include "core/io/output.h"
#include "core/plugin/instance.h"
#include "core/plugin/point_eval.h"
#include "core/scene/scene.h"
#include "core/time/model.h"
#include "core/util/diag.h"

/* The keys of [shaking] and [deposit]: the column's liquefaction add-on (liquefaction.h). */
typedef struct tf_lq_config {
  const char *record; /* [shaking] */
  int units, mass;
  double peak, start, k2max, shear_modulus, friction_angle, damping, damping_frequency, residual_viscosity;
  double settle, settle_dt, settle_tolerance; /* [deposit] */
  double deposit_phi, liquefied_ratio, nbar_drop, nbar_min;
} tf_lq_config;

/* The keys of the [two_fluid] section and [initial] (each variant reads its part). */
typedef struct tf_config {
  long iterations, order, case_index;
  double tolerance, cfl, steady_tolerance, diffusivity;
  int limiter, motion, cross_section, granular_temperature, interphase_dissipation, acceleration, kinetic_pressure,
      column_form;
  sl_scene_expr phi, porosity, theta;            /* [initial]: the column and the 2-D model (x, y, case) */
  sl_scene_exprs velocity_fluid, velocity_solid; /* [initial]: the 2-D model (two components) */
  sl_scene_expr sh_phi, sh_theta, sh_uf, sh_us;  /* [initial]: the shear layer (of x) */
  sl_scene_expr nbar;                            /* [initial]: the column's reference porosity (liquefaction.h) */
  const char *from;                              /* [initial]: an output file whose last state the column starts from */
  tf_lq_config lq;
  /* [two_fluid] the 2-D model's turbulent dispersion of the solids (two_fluid_plane_dispersion.c): k and epsilon of
     (x, y, case) for [closure.turbulence] (the dispersivity is [closure.turbulent_dispersion]'s), the turbophoretic
     drift on or off */
  sl_scene_expr turb_k, turb_eps;
  int turbophoresis;
  int swirl;       /* [two_fluid] swirl: the 2-D axisymmetric model's azimuthal velocities (two_fluid_plane_swirl.c) */
  int centrifugal; /* [two_fluid] centrifugal: the swirl's rho alpha u_theta^2 / r back on the radial momentum */
  /* [body] (two_fluid_plane_body.c): a solid body of blocked cells, the box x0, x1, y0, y1 it fills, its rotation */
  sl_reals body_box;
  double body_omega;
} tf_config;

/* A boundary of the 1-D column. */
typedef struct tfc_boundary {
  int type;                         /* TF_WALL | TF_INLET | TF_OUTLET */
  sl_scene_expr velocity, porosity; /* inlet: of (t, case) */
  double pressure;                  /* outlet */
} tfc_boundary;

enum { TF_MAX_IN = 32 };
enum { TF_WALL = 0, TF_INLET = 1, TF_OUTLET = 2 };
enum { TF_LIMITER_MINMOD = 0, TF_LIMITER_MC = 1 };

/* A closure of phi (and slip, for drag), the scene's constants bound
 * (core/plugin/point_eval.h); one output and its derivative. */
typedef struct tf_closure {
  sl_closure *c; /* the scene's; NULL: not in the scene */
  sl_point_closure pc;
  const char *out, *wrt; /* "K", "slip"; "p_s", "phi" */
  const double *nbar;    /* the cells' reference porosity for a solids pressure of nbar (liquefaction.h), or NULL */
} tf_closure;

typedef struct tf_column {
  /* geometry: cells 0..n-1 upwards in x, face k between cells k-1 and k */
  int n;
  double *h, *xc, *xf, *dual; /* [n], [n], [n+1], [n+1] (dual: centre to centre, half cells at the ends) */
  int below;                  /* 1: the gravity side of face k is cell k-1 (g <= 0); 0: cell k */
  /* physics */
  double rho_f, mu_f, rho_s, d_p, sphericity, g, phi_max;
  double v_ref;        /* velocity scale: |j| or the Stokes velocity */
  tf_closure drag, ps; /* the scene's closures (not owned); ps.c NULL: no solids pressure */
  /* boundaries: [0] at x0, [1] at x1 */
  int bc[2];
  const sl_expr *inlet;          /* superficial fluid velocity entering, of (t, case) (the scene's) */
  const sl_expr *inlet_porosity; /* or the porosity of a bed the inflow holds in equilibrium, of (t, case) */
  int inlet_side;
  double case_index;                     /* [two_fluid] case, a variable of the scene's expressions */
  double eq_porosity[2], eq_velocity[2]; /* the last two equilibria found (a step alternates between two) */
  int eq_next;
  double p_out;
  /* numerics */
  int max_iterations;
  double tolerance, cfl;
  double diffusivity; /* particle diffusivity D: the extra solids flux -D dphi/dx, m^2/s */
  int order, limiter; /* transport: 1 upwind, 2 MUSCL with TF_LIMITER_* */
  /* state: cells phi, p; faces u (solids), uf (fluid) */
  double *phi, *u, *uf, *p;
  double *nbar; /* [n] the reference porosity of each cell (liquefaction.h), or NULL */
  /* the step's trial; scratch of n cells */
  double *phi_new, *u_new, *uf_new, *p_new;
  double *alpha;
  struct tfp_model *plane; /* the n x 1 grid of the 2-D model the step runs on (two_fluid_step.c) */
  const char *linear;      /* its sparse solver's name */
  double outflow_trial;    /* solids volume per unit area that left during the trial */
  int fatal;               /* the trial failed for a reason a smaller step cannot cure (the inlet's value) */
  long substeps_trial;
  double transport_cpu;   /* CPU seconds in the solids transport over the run (profile) */
  long last_substeps;     /* of the last transport call */
  long accepted_substeps; /* of the last accepted step's transport (0: none yet) */
  int iterations_trial;
} tf_column;

/* The mixture flux j (along +x) at time t: the inlet's velocity, or the
 * equilibrium velocity of its porosity (tf_equilibrium_velocity). 0, or
 * SL_EFAILED (a porosity outside (1 - phi_max, 1], a non-finite value, the
 * drag closure failing) with d set. */
int tf_mixture_flux(tf_column *c, double t, double *j, sl_diag *d);

/* The superficial velocity U that holds a homogeneous bed of the given
 * porosity at rest: the drag carries the buoyant weight,
 * K(phi, s) s = phi (1 - phi) (rho_s - rho_f) |g|, U = (1 - phi) s. */
int tf_equilibrium_velocity(tf_column *c, double porosity, double *U, sl_diag *d);

/* The column's step runs on the 2-D model's n x 1 grid (two_fluid_step.c):
 * built once the column's physics, boundaries, state and closures are set
 * (0, or an error with d set; tf_plane_free releases it in any case). */
int tf_plane_create(tf_column *c, const sl_scene *sc, const tf_config *cfg, sl_diag *d);
void tf_plane_free(tf_column *c);

/* One backward-Euler step from (phi, u) at t over dt into the *_new arrays.
 * 0, or SL_EFAILED with the reason (no convergence, a closure outside its
 * validity, a non-finite value): the caller retries smaller. */
int tf_step(tf_column *c, double t, double dt, sl_diag *d);

/* The scene's physics into c (two_fluid_scene.c): [fluid], [solid], [flow]
 * gravity (dim components; 2-D: into gravity[], default (0, -9.81), and
 * c->g = -|g|), the [two_fluid] numerical keys, and [closure.drag] and the
 * optional [closure.solids_pressure] bound to the model's inputs. 0 or
 * SL_EBADINPUT with file:line. */
int tf_scene_physics(const sl_scene *sc, const tf_config *cfg, int dim, tf_column *c, double gravity[2],
                     double *steady_tol, sl_diag *d);

/* A run's state as its checkpoint holds it: phi and p in n_cells cells, the
 * solids and fluid velocities on n_faces faces, and the solids bookkeeping
 * (two_fluid_io.c). */
typedef struct tf_state {
  double *phi, *us, *uf, *p;
  double *theta; /* [n_cells] a transported granular temperature, or NULL */
  int64_t n_cells, n_faces;
  double inventory0, outflow;
  double book[2]; /* inventory0 and outflow as checkpointed */
} tf_state;

/* The state's arrays for a checkpoint (their count, at most max). */
int tf_checkpoint_arrays(tf_state *s, sl_checkpoint_array *a, int max);
/* From a checkpoint into s's arrays (their lengths must match: SL_EBADINPUT
 * naming the array and the model otherwise) and its bookkeeping. */
int tf_checkpoint_restore(const sl_checkpoint *ck, const char *model, tf_state *s, sl_diag *d);

/* K and dK/dslip at n faces (phi, slip given); p_s and dp_s/dphi at n cells. */
int tf_closure_eval(tf_closure *b, int n, const double *phi, const double *slip, double *value, double *dvalue,
                    sl_diag *d);

#endif
