/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Internals of the 2-D two-fluid model (planar and axisymmetric) shared by
 * two_fluid_plane.c (scene, boundaries, output, time loop) and
 * two_fluid_plane_step.c (one implicit step on the staggered grid).
 *
 * The staggered (MAC) grid of Harlow & Welch (1965; core/fv/grid.h): phi,
 * the pressure p and the solids pressure P_s in the cells; the normal
 * components of the fluid and solids velocities on the faces. The 1-D
 * column is its n x 1 case with column_form (two_fluid_step.c): each face balances the
 * two cells it separates, so a checkerboard of phi drives the face fluxes
 * that relax it (a collocated or Taylor-Hood form averages it away).
 *
 * Faces: x-faces (normal along x) f = i + (nx + 1) j, i = 0..nx, j =
 * 0..ny-1, then y-faces f = nfx + i + nx j, i = 0..nx-1, j = 0..ny. Cell c =
 * i + nx j. A face's "lo" cell is on its minus side, "hi" on its plus side
 * (-1 outside the domain). */
#ifndef SLUICE_MODELS_TWO_FLUID_PLANE_IMPL_H
#define SLUICE_MODELS_TWO_FLUID_PLANE_IMPL_H

#include "core/fv/cell_scalar.h"
#include "core/fv/grid.h"
#include "core/mesh/tensor_grid.h"
#include "core/models/two_fluid/quantities.h"
#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/plugin/point_eval.h"
#include "core/solve/anderson.h"
#include "core/solve/band.h"
#include "core/solve/linsolve.h"
#include "core/solve/triplets.h"

enum { TFP_WALL = 0, TFP_SLIP, TFP_AXIS, TFP_INLET, TFP_OUTLET, TFP_PERIODIC };
/* what a face's normal velocities are */
enum { TFP_FACE_INTERIOR = 0, TFP_FACE_CLOSED, TFP_FACE_INLET, TFP_FACE_OUTLET, TFP_FACE_IMAGE };
/* TFP_FACE_IMAGE: along a periodic direction the last face of each row (i =
 * nx, or j = ny) is the first one seen from the other end; it shares that
 * face's unknowns, cells (lo, hi) and values, and carries no equation or
 * flux of its own. */

/* The most [body.NAME] sections a scene may hold. */
enum { TFP_BODIES_MAX = 16 };

enum { TFP_SOLIDS_NO_SLIP = 0, TFP_SOLIDS_FREE_SLIP, TFP_SOLIDS_WALL_STRESS };

typedef struct tfp_boundary {
  int type;
  int solids;                /* wall: TFP_SOLIDS_* */
  sl_scene_expr velocity;    /* inlet: superficial fluid velocity entering; wall: its own speed along the side (+x along
                             the bottom and top, +y along the left and right); of (x, y, t, case) (e NULL: 0) */
  double pressure;           /* outlet */
  sl_scene_expr solids_flux; /* inlet: the superficial solids velocity entering, of (x, y, t, case) (e NULL: held) */
  double angular_velocity;   /* wall, with [two_fluid] swirl: its rotation about the axis, rad/s */
} tfp_boundary;

/* The solids phase's stress (two_fluid_plane_solids.c): its viscosity in the
 * cells from [solid] viscosity, [closure.viscosity] and [closure.granular]
 * (with the granular temperature theta in the cells), and the wall stress
 * of [closure.wall_stress]. */
typedef struct tfp_solids {
  sl_closure *visc_c, *gran_c, *wall_c; /* the scene's (not owned); NULL: not in the scene */
  sl_point_closure visc, gran, wall;
  int granular, algebraic, exchange, wall_function;
  int kinetic_pressure; /* the granular closure's p_s joins the solids pressure */
  int wall_energy;      /* the wall closure's theta_flux enters the transported theta through the walls */
  double mu_const;      /* [solid] viscosity */
  double *qv[TF_Q_N];   /* the constant quantities, per point (corners: more than cells) */
  /* cells [nc]: the viscosity, its tangent mu_s + gdot dmu_s/dgdot (Newton in the shear rate), the shear rate,
     the mixture density, the drag coefficient (the mean of the faces), the normal part 2 S':S' - 2 S_xy^2 of
     gdot^2; theta of the accepted state and of the iterate */
  double *mu, *mu_t, *gdot, *rho, *Kc, *normal, *theta, *theta_new;
  /* the grid's corners [(nx + 1)(ny + 1)], where the shear stresses act: du/dy + dv/dx of the solids, the
     means of the cells around, the shear rate, theta, the viscosity and its tangent */
  double *shear, *phi_k, *rho_k, *K_k, *gdot_k, *theta_k, *mu_k_corner, *mu_tk;
  double *mum, *mu_k, *kap, *gam, *dgam, *one; /* per-point scratch (corners' size) */
  /* the transported theta (core/fv/cell_scalar.h): its solver, the last iterate's theta, the equation's
     capacity, source and sink per cell, the solution */
  sl_cell_scalar th;
  double *th_old, *th_cap, *th_src, *th_sink, *th_x;
  double last_bagnold; /* the Bagnold number of the last wall-closure call (NAN: the closure gives none) */
  int any;             /* the solids carry a stress (a viscosity at all) */
} tfp_solids;

/* The turbulent dispersion of the solids (two_fluid_plane_dispersion.c), with [closure.turbulence]: the cells' k
 * and epsilon (of the scene's expressions) and eddy viscosity, per face its nu_t, the dispersivity of
 * [closure.turbulent_dispersion] there and the turbophoretic drift velocity; their solids flux is added to the
 * transport's. */
typedef struct tfp_dispersion {
  int on, turbophoretic;
  int have_dc;                                        /* [closure.turbulent_dispersion] given (else D = nu_t) */
  sl_closure *c;                                      /* the scene's (not owned) */
  sl_point_closure pc, dc;                            /* [closure.turbulence], [closure.turbulent_dispersion] */
  double *k, *eps, *mu_t, *tau, *slip, *K, *dK, *phi; /* cells [nc] */
  double *D, *v, *nu;                                 /* faces [nf]: m^2/s, m/s along +x or +y, m^2/s */
} tfp_dispersion;

/* The swirl of an axisymmetric scene (two_fluid_plane_swirl.c): both phases' angular velocities in the cells,
 * fluid [0, nc) then solids [nc, 2 nc), of the accepted step and of the trial; their linear system. */
typedef struct tfp_swirl {
  int on;
  double *buf; /* the allocation (om and om_new swap within it) */
  double *om, *om_new;
  double *rhs, *K, *slip; /* [2 nc], [nc], [nc] scratch */
  /* per boundary b (the mesh's, then the bodies'), of the last swirl solved: [5 b + k] the torque about the axis
     that phase k (fluid 0, solids 1) exerts on the wall (N m, the whole circle), [5 b + 2 + k] its mean azimuthal
     shear stress on the wall (Pa), [5 b + 4] the wall's area (m^2); zero on boundaries that are not walls */
  double *torque;
  sl_triplets trip;
  sl_csr A;
  sl_linsolve *ls;
} tfp_swirl;

typedef struct tfp_model {
  sl_tensor_grid grid;
  sl_fv_grid fv; /* its staggered grid: cells, faces, neighbours, periodic images, geometry */
  int axi;
  int convection; /* [flow] convection: the phases' rho alpha (u . grad) u */
  double g[2];
  tfp_solids s;
  tfp_dispersion disp;   /* zero: none */
  tfp_swirl sw;          /* zero: none */
  tf_column c;           /* the physics, the closures and the numerical keys (its column geometry is unused) */
  const tfp_boundary *b; /* [n_b]: the mesh's boundaries, then the bodies' walls */
  int n_b;
  /* [body] (two_fluid_plane_body.c): n_bodies solid bodies whose cells are blocked (core/fv/grid.h), their walls
     the boundaries n_b - n_bodies ... n_b - 1; body_cells [nc] the body of each cell (-1 open), given before
     tfp_setup (which hands it to the grid, then frees it) */
  int n_bodies;
  int *body_cells;
  char body_names[TFP_BODIES_MAX][64];  /* [n_bodies]: "body" for [body], NAME for [body.NAME] (output scalars) */
  char body_where[TFP_BODIES_MAX][320]; /* [n_bodies]: "FILE:LINE: [body.NAME]", for messages */
  double body_r1[TFP_BODIES_MAX];       /* [n_bodies]: the body's outer radius inside the domain (x1) */
  int centrifugal; /* [two_fluid] centrifugal: rho alpha u_theta^2 / r of the swirl in the radial momentum */
  /* per boundary b, of the last converged step (walls): [5 b] the fluid's and [5 b + 1] the solids' mean shear
     stress on it, [5 b + 2] the mean solids slip, [5 b + 3] the mean Bagnold number of the wall closure (NAN:
     none), [5 b + 4] the length (or area per radian) averaged over */
  double *wall_stats;
  int *ftype;             /* [nf]: TFP_FACE_* */
  int *open_face, n_open; /* the faces a flux can cross (not closed, not an image), ascending */
  int *tan_noslip;        /* [4 nf]: per phase (fluid 0, solids 1) and end (minus 0, plus 1) of the face
                                     across its family, 1 when a boundary there holds the phase (no-slip) */
  int *end_wall;          /* [2 nf]: per end, the wall (boundary index) along which the face runs, -1 none */
  double *end_u;          /* [2 nf]: that wall's speed along the face's direction */
  double *end_us;         /* [2 nf]: the solids velocity at that wall (its slip under a wall stress) */
  double *js;             /* [nf]: an inlet face's given solids volume flux per area, along +x or +y */
  /* state: cells phi, p, P_s; faces the fluid and solids velocities (boundary faces hold their values) */
  double *phi, *p, *uf, *us;
  double *phi_new, *p_new, *uf_new, *us_new;
  /* unknown numbering: us_row[f], uf_row[f] (-1: given), p at n_vel + c */
  int *us_row, *uf_row;
  int n_vel, n_unknowns;
  int closed; /* no outlet: the pressure takes its datum in cell `datum` (0, or the first open cell) */
  int datum;
  /* [two_fluid] column_form: a grid one cell across along direction col_dir takes the 1-D column's equations
     (two_fluid.h; two_fluid_plane_step.c): col_n cells, col_face[k] (k = 0..col_n) its faces upwards along
     col_dir; col_j the mixture flux along +col_dir of the accepted state and col_j_new of the trial; col_uf0 the
     accepted fluid velocities (the inlet's before its new value) */
  int column, col_dir, col_n;
  int *col_face;
  double col_j, col_j_new, *col_uf0;
  int col_inlet_given; /* the inlet's superficial velocity is col_inlet (inward), not its expression: the 1-D
                          column's inlet, which may be an equilibrium (two_fluid_step.c) */
  double col_inlet;
  /* the step's work arrays */
  double *phf, *phg, *w, *K, *dK, *slip, *sn, *ps, *dps, *flux, *alpha, *inflow, *x, *rhs;
  /* the linear system: its triplets (the pattern kept) */
  sl_triplets trip;
  int phi_frozen;  /* this iteration takes the face phi from the step's start */
  int sink_frozen; /* this iteration keeps the drag coefficient of the granular sink 3 K theta */
  sl_csr A;
  sl_linsolve *ls;
  /* the fast path of a grid one cell across (two_fluid_plane_step.c, band_start): with band_allowed (the
     caller's: [solver] linear = auto) the unknowns numbered along the grid (band_of[row]) make a banded matrix,
     assembled straight into `band` and solved by banded LU instead of the general sparse factorisation;
     band_on once the first system's bands were found narrow; band_miss an entry outside them (back to the
     general path for good) */
  int band_allowed, band_on, band_miss;
  sl_band band;
  int32_t *band_of;
  double *band_x;
  /* Anderson acceleration of the step's iteration (two_fluid_plane_step.c): its state, the iterate x and the
     map's value g over [us (nf), uf (nf), theta (nc), the walls' solids velocities end_us (2 nf), phi (nc)], and
     their scales */
  int accelerate;
  sl_anderson acc;
  double *acc_x, *acc_g, *acc_scale;
  /* counters of the trial step */
  double outflow_trial, transport_cpu;
  long substeps_trial, accepted_substeps, last_substeps;
  int iterations_trial;
  char where[256]; /* where the last failure happened */
} tfp_model;

/* A blocked cell (inside a body), a dead face (no open cell on either side). */
static inline int tfp_blocked(const tfp_model *m, int c) { return m->fv.blocked && m->fv.blocked[c] >= 0; }
static inline int tfp_dead(const tfp_model *m, int f) { return sl_fv_dead(&m->fv, f); }

/* The grid's neighbour and image-face maps (core/fv/grid.h). */
static inline int tfp_neighbour(const tfp_model *m, int c, int dir, int side) {
  return sl_fv_neighbour(&m->fv, c, dir, side);
}
static inline int tfp_primary(const tfp_model *m, int f) { return sl_fv_primary(&m->fv, f); }

/* The grid geometry, face types and unknown numbering from the grid and the
 * boundaries. 0 or SL_EFAILED (memory). */
int tfp_setup(tfp_model *m, sl_diag *d);
void tfp_free(tfp_model *m);

/* The inlet faces' fluid velocities at t (with the inside cells' phi), the walls' speeds. */
int tfp_boundary_values(tfp_model *m, double t, const double *phi, sl_diag *d);

/* One backward-Euler step from the state at t over dt into the *_new
 * arrays. 0, or SL_EFAILED with the reason (the caller retries smaller). */
int tfp_step(tfp_model *m, double t, double dt, sl_diag *d);

/* phi = T(phi^n, us) over dt (two_fluid_plane_transport.c): the solids
 * leaving through the boundary are added to *outflow. 0, or SL_EFAILED when
 * the sub-steps needed are too many (the caller retries smaller). */
int tfp_transport(tfp_model *m, const double *us, double dt, double *phi, double *outflow, sl_diag *d);

/* The solids stress closures of the scene bound, the keys read
 * ([two_fluid] granular_temperature, interphase_dissipation, kinetic_pressure,
 * acceleration); after tfp_setup. 0, SL_EBADINPUT or SL_EFAILED. */
int tfp_solids_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, sl_diag *d);
void tfp_solids_free(tfp_solids *s);

/* The solids viscosity of every cell at the iterate (us, phi, theta_new),
 * with the algebraic theta first when so chosen. */
int tfp_solids_viscosity(tfp_model *m, const double *us, const double *phi, sl_diag *d);

/* One solve of the transported granular temperature of the iterate
 * (theta_new), from the accepted theta over dt; *change its largest change.
 * Only with granular_temperature = transport. */
int tfp_theta_solve(tfp_model *m, double dt, double *change, sl_diag *d);

/* Adds the kinetic theory's solids pressure (kinetic and collisional, at
 * the cells' theta of the iterate) and its phi derivative to ps, dps. */
int tfp_solids_pressure(tfp_model *m, const double *phi, double *ps, double *dps, sl_diag *d);

/* The wall's resistance to the solids at face f's end `end` (a wall with
 * solids = wall_stress), per unit wall area, as R0 + dR (u - u0) in the
 * face velocity u near u0 = us[f]; mu the solids viscosity of the half cell
 * next to the wall, h its width. Updates end_us. */
int tfp_solids_wall(tfp_model *m, int f, int end, double mu, double h, double *R0, double *dR, sl_diag *d);

/* [two_fluid] column_form (two_fluid_plane_step.c): checks the grid is one cell across with gravity along it, and
 * starts the fluid with the inlet's mixture flux, as the column does. After tfp_setup and the initial state;
 * `where` names the key for errors. 0, SL_EBADINPUT or SL_ENOMEM. */
int tfp_column_start(tfp_model *m, int fluid_given, const char *where, sl_diag *d);
/* The column's mixture flux from a restored state. */
void tfp_column_restored(tfp_model *m);

/* The linear solver's name and counters, the fast path's when it is on (band_start). */
const char *tfp_linear_name(const tfp_model *m, const char *general);
sl_linsolve_stats tfp_linear_stats(const tfp_model *m);

/* [closure.turbulence], [closure.turbulent_dispersion] and the [two_fluid] dispersion keys bound
 * (two_fluid_plane_dispersion.c): nothing when the scene has none; SL_EBADINPUT with file:line for a key or
 * [closure.turbulent_dispersion] without [closure.turbulence], a dispersion closure taking t_fs or k_fs, or k,
 * epsilon outside (0, 1e6], (0, 1e9] at a cell. After tfp_setup. */
int tfp_dispersion_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, sl_diag *d);
/* The faces' D and v at the solids fraction phi and the iterate's velocities (uf, us). 0 or SL_EFAILED. */
int tfp_dispersion_update(tfp_model *m, const double *phi, const double *uf, const double *us, sl_diag *d);
void tfp_dispersion_free(tfp_dispersion *p);

/* [two_fluid] swirl: its arrays and solver (`linear` names it). 0 or SL_ENOMEM. */
int tfp_swirl_setup(tfp_model *m, const char *linear, sl_diag *d);
/* The trial's swirl (om_new) over dt at the converged step's velocities and phi. 0 or SL_EFAILED. */
int tfp_swirl_step(tfp_model *m, double dt, sl_diag *d);
void tfp_swirl_free(tfp_swirl *w);

/* [body] bound (two_fluid_plane_body.c): nothing without a box; else its cells (m->body_cells, for tfp_setup) and
 * the boundaries with the body's wall after the mesh's n_mesh_b (*all, the caller's to free; m->b, m->n_b point to
 * it). After the grid and the boundaries' periodic sides, before tfp_setup. 0, SL_EBADINPUT (file:line) or
 * SL_ENOMEM. */
int tfp_body_bind(tfp_model *m, const sl_scene *sc, const tf_config *cfg, const tfp_boundary *mesh_b, int n_mesh_b,
                  tfp_boundary **all, sl_diag *d);

/* The solids volume (per radian when axisymmetric) in the domain. */
double tfp_inventory(const tfp_model *m, const double *phi);

#endif
