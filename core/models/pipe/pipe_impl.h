/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's state, shared by its files (pipe.h). */
#ifndef SLUICE_MODELS_PIPE_IMPL_H
#define SLUICE_MODELS_PIPE_IMPL_H

#include "core/fv/cell_scalar.h"
#include "core/fv/grid.h"
#include "core/io/output.h"
#include "core/mesh/mesh.h"
#include "core/mesh/tensor_grid.h"
#include "core/plugin/point_eval.h"
#include "core/scene/scene.h"
#include "core/solve/linsolve.h"
#include "core/solve/sparse.h"

enum { PIPE_NO_SLIP = 0, PIPE_FREE_SLIP, PIPE_WALL_STRESS };
enum { PIPE_THETA_ALGEBRAIC = 0, PIPE_THETA_TRANSPORT };
enum { PIPE_NORMAL_CONTACT = 0, PIPE_NORMAL_CONTACT_KINETIC };
enum { PIPE_SOLIDS_VISCOSITY_EDDY = 0, PIPE_SOLIDS_VISCOSITY_PEIRANO_LECKNER };
enum { PIPE_SOLIDS_TURBULENCE_EQUILIBRIUM = 0, PIPE_SOLIDS_TURBULENCE_TRANSPORTED, PIPE_SOLIDS_TURBULENCE_K_EPSILON };
/* the pipe's scratch and saved-state arrays of n cells (pipe.buf) */
#define PIPE_NBUF 18

typedef struct pipe_config {
  double diameter, bulk_velocity, solids_fraction, wall_cell, wall_y_plus;
  long cells, iterations;
  double tolerance, relaxation, pseudo_step;
  int solids_wall, kinetic_pressure;
  int wall_normal_stress; /* PIPE_NORMAL_*: what the solids' wall closure's normal_stress is */
  double solids_schmidt, crossing_trajectory;
  int granular_temperature; /* PIPE_THETA_* */
  int solids_viscosity;     /* PIPE_SOLIDS_VISCOSITY_* */
  double restitution;       /* e of solids_viscosity = peirano_leckner */
  int solids_turbulence;    /* PIPE_SOLIDS_TURBULENCE_*: model C's k_s and k_fs from Tchen's equilibrium or transported,
                            or models A and B's solids k_s-eps_s (pipe_kseps_solid.c) */
  double covariance_schmidt; /* sigma_kfs of the k_fs diffusion (eq 5.23) */
  /* the developing pipe (pipe_march.c): length 0 for the fully developed one */
  double length, inlet_intensity, inlet_length_scale;
  long axial_cells;
  sl_reals pressure_gradient; /* -dP/dz held in place of the bulk velocity (n = 0: the bulk velocity drives) */
  int loop;                   /* the loop's up- and down-flow sections sharing one solids inventory (pipe_loop.c) */
} pipe_config;

/* The host's quantities the closures bind to. */
enum {
  PQ_PHI,
  PQ_SLIP,
  PQ_K,
  PQ_EPS,
  PQ_THETA,
  PQ_SHEAR,
  PQ_RHO_F,
  PQ_MU_F,
  PQ_RHO_S,
  PQ_D_P,
  PQ_SPHERICITY,
  PQ_SLIP_WALL,
  PQ_WALL_DISTANCE,
  PQ_D_VESSEL,
  PQ_GRAVITY,
  PQ_NORMAL_STRESS,
  PQ_NU_T, /* mu_t/rho_f */
  PQ_T_FS, /* the eddy-particle interaction time (pipe_tfs) */
  PQ_K_FS, /* the fluid-particle covariance (pipe_kfs) */
  PQ_DRAG, /* the drag's K */
  PQ_N
};
extern const char *const pipe_quantity_names[PQ_N];

/* The developing pipe (`[pipe] length`, pipe_march.c): the stations along z, the last station's state, the
   radial volume fluxes of the phases through the row's faces, and every station's fields. */
/* the output fields (the schema's: pipe_schema.c) */
#define PIPE_NFIELDS 10

typedef struct pipe_march {
  int on, nz, j;
  double h; /* from the last station (the inlet for the first) to this */
  double *uf_up, *us_up, *phi_up, *k_up, *eps_up, *theta_up; /* [n] the last station's state */
  double *ks_up, *kfs_up;                                    /* [n] model C's transported k_s, k_fs there */
  double *ff, *fs, *rff, *rfs, *rs;     /* [nf] the phases' radial volume fluxes, rho_f ff, 1.5 rho_s fs, rho_s fs */
  double *cap, *s_old;                  /* [n] a march step's storage and start for k or epsilon */
  double *field[PIPE_NFIELDS];          /* [n nz] every station's fields (the schema's order) */
  double *G, *tau_fw, *tau_sw, *y_plus; /* [nz] */
  double pressure_drop;                 /* p(0) - p(L) */
  long iterations, worst_station_iterations;
  sl_mesh *mesh;
  sl_tensor_grid tg;
  sl_fv_grid g;
} pipe_march;

typedef struct pipe {
  const sl_scene *sc;
  const pipe_config *cfg;
  sl_mesh *mesh;
  sl_tensor_grid tg;
  sl_fv_grid g;
  int n;        /* radial cells */
  double R, gz; /* radius, gravity along the flow */
  double rho_f, mu_f, rho_s, d_p, phi_max;
  int two_phase;
  /* state (cells) */
  double *uf, *us, *phi, *k, *eps, *theta;
  double *ks, *kfs; /* model C's solids turbulent energy and fluid-particle covariance (pipe_ksfs.c) */
  int ksfs_started;
  double *eps_s; /* models A and B's solids dissipation, with k_s (pipe_kseps_solid.c) */
  int kseps_started;
  double G;          /* dP/dz */
  double phi_target; /* the section-mean solids fraction the radial balance holds: [pipe] solids_fraction, or the
                       loop's share for this section (pipe_loop.c) */
  /* coefficients (cells) */
  double *mu_t, *mu_tk, *mu_te, *eps_prod, *eps_sink, *K, *mu_s;
  double *Kd, *slip0; /* d(K s)/ds at the last slip, and that slip u_f - u_s (the drag's Newton linearisation) */
  double c_mu;
  /* wall */
  double tau_fw, tau_sw, u_tau, y_plus, k_wall, eps_wall, a_fw, a_sw;
  double u_wall;   /* the solids' slip speed at the wall the solids' wall closure saw last */
  double inv_slip; /* 1/lambda_slip of the solids' wall closure at the wall cell (0: none or free slip) */
  double p_wall;   /* the solids' normal stress on the wall: their pressures at the wall cell (pipe_solids.c) */
  /* closures */
  sl_point_closure turb, wallf, drag, gran, psol, walls, lift;
  int have_lift;               /* [closure.lift]: the shear lift in the radial solids balance (pipe_solids.c) */
  sl_point_closure disp, modu; /* [closure.turbulent_dispersion] (pipe_solids.c), [closure.turbulence_modulation] */
  int have_disp, have_modu;    /* (pipe_turbulence.c) */
  int have_gran, have_psol, have_walls, walls_at_node, walls_normal, wall_energy, ks_wall_energy;
  /* solvers */
  sl_cell_scalar cs;
  sl_csr A;
  sl_linsolve *ls;
  double *face_flux;                /* [nf] */
  double *rhs, *x, *buf[PIPE_NBUF]; /* buf[0..7], [14..17] scratch, [8..13] the steady solve's last state */
  double dirichlet;                 /* the value the wall cell's k or epsilon is held at (the cell-scalar hook's) */
  long iterations;
  double change;
  double relax;             /* the under-relaxation in use: [pipe] relaxation, halved where the iteration stalls */
  const char *change_field; /* the field and the cell (-1: none) of the last iteration's largest change */
  int change_cell;
  int converged, warned_yplus;
  char stop_reason[256];
  pipe_march march;
  struct pipe *other;        /* [pipe] loop: the section of the other direction (its own state and closures) */
  long loop_iterations;      /* the loop's updates of the sections' shares */
  double loop_flux_mismatch; /* the sections' solids fluxes' last relative difference */
} pipe;

/* One point of model C's solids viscosity (pipe_peirano.c). */
typedef struct pipe_pl_point {
  double phi, k, eps, slip2, K;            /* the solids fraction, the fluid's k and epsilon, slip^2, the drag */
  double rho_s, d_p, phi_max, restitution; /* the particles */
  double c_mu, c_beta;                     /* C_mu, the crossing-trajectory C_beta of t_fs */
  int given;                               /* 1: ks and kfs below (transported); 0: Tchen's equilibrium */
  double ks, kfs;
} pipe_pl_point;
double pipe_peirano_leckner(const pipe_pl_point *q, double *nu_st);
double pipe_peirano_leckner_diffusivity(const pipe_pl_point *q, double *K_st);
double pipe_peirano_leckner_collision_rate(const pipe_pl_point *q);

int pipe_closures_bind(pipe *p, sl_diag *d);
int pipe_turbulence_coefficients(pipe *p, sl_diag *d);
int pipe_wall_function(pipe *p, sl_diag *d);
int pipe_turbulence_update(pipe *p, sl_diag *d);
/* The cell-scalar boundary hook (core/fv/cell_scalar.h) that holds the wall cell at p->dirichlet: the k and
   epsilon equations' wall-function values, the fluid's and the solids'. */
int pipe_hold_wall(void *user, int c, double *rhs, double *diag, sl_diag *d);
int pipe_momentum_init(pipe *p, sl_diag *d);
int pipe_momentum_solve(pipe *p, sl_diag *d);
int pipe_solids_coefficients(pipe *p, sl_diag *d);
int pipe_solids_update(pipe *p, sl_diag *d);
/* the largest jump of [closure.drag]'s K within 1e-3 of a cell's slip or phi (0, -1, NULL: none; scratch buf[0..7]) */
int pipe_drag_jump(pipe *p, double *jump, int *cell, const char **across, sl_diag *d);
/* the solids' turbulent dispersivity D_t in every cell ([closure.turbulent_dispersion]; scratch buf[14..16]) */
int pipe_turbulent_dispersivity(pipe *p, double *Dt, sl_diag *d);
int pipe_theta_transport(pipe *p, const double *gd, sl_diag *d);
int pipe_theta_wall_flux(pipe *p, double theta, double *q, double *c_implicit, sl_diag *d);
void pipe_face_gradients(const pipe *p, const double *u, double wall, double *gw, double *ge);
double pipe_bulk_velocity(const pipe *p);
/* model C's k_s and k_fs (pipe_ksfs.c) */
double pipe_tfs(const pipe *p, int i);
void pipe_ksfs_equilibrium(const pipe *p, int i, double *ks, double *kfs);
double pipe_kfs(const pipe *p, int i);
pipe_pl_point pipe_pl_point_at(const pipe *p, int i);
void pipe_ksfs_start(pipe *p);
int pipe_ksfs_update(pipe *p, sl_diag *d);
/* models A and B's solids k_s-eps_s (pipe_kseps_solid.c) */
void pipe_kseps_viscosity(pipe *p);
int pipe_kseps_update(pipe *p, sl_diag *d);
int pipe_converge(pipe *p, sl_diag *d);
/* the loop (pipe_loop.c) */
int pipe_loop_solve(pipe *p, sl_diag *d);
double pipe_solids_flux(const pipe *p);
/* the developing pipe (pipe_march.c) */
int pipe_march_setup(pipe *p, sl_diag *d);
void pipe_march_release(pipe *p);
void pipe_march_fluxes(pipe *p);
void pipe_march_momentum(const pipe *p, sl_csr *A, double *b);
void pipe_march_scalar(pipe *p, const double *cap_pseudo, const double *s_iter, const double *s_up);
void pipe_march_solids(pipe *p, double *cap, double *flux);
void pipe_march_theta(pipe *p, const double *cap_pseudo);
void pipe_march_ksfs(pipe *p, const double *s_iter, const double *s_up);
void pipe_march_drift_work(const pipe *p, const double *A, const double *Dt, double *W);
const double *pipe_march_drag_fraction(const pipe *p, double *phi_arg);
void pipe_march_drag(pipe *p, const double *phi_arg, double *dK);
int pipe_march_solve(pipe *p, sl_diag *d);
int pipe_march_write(pipe *p, sl_output *out, unsigned mask, sl_diag *d);

#endif
