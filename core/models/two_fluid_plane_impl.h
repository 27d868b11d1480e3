/* Internals of the 2-D two-fluid model (planar and axisymmetric) shared by
 * two_fluid_plane.c (scene, boundaries, output, time loop) and
 * two_fluid_plane_step.c (one implicit step on the staggered grid).
 *
 * The staggered (MAC) grid of Harlow & Welch (1965): phi, the pressure p and
 * the solids pressure P_s in the cells; the normal components of the fluid
 * and solids velocities on the faces. It carries the 1-D column's face
 * scheme (two_fluid_step.c) over to two dimensions: each face balances the
 * two cells it separates, so a checkerboard of phi drives the face fluxes
 * that relax it (a collocated or Taylor-Hood form averages it away).
 *
 * Faces: x-faces (normal along x) f = i + (nx + 1) j, i = 0..nx, j =
 * 0..ny-1, then y-faces f = nfx + i + nx j, i = 0..nx-1, j = 0..ny. Cell c =
 * i + nx j. A face's "lo" cell is on its minus side, "hi" on its plus side
 * (-1 outside the domain). */
#ifndef SLUICE_MODELS_TWO_FLUID_PLANE_IMPL_H
#define SLUICE_MODELS_TWO_FLUID_PLANE_IMPL_H

#include "core/mesh/tensor_grid.h"
#include "core/models/two_fluid_impl.h"
#include "core/solve/linsolve.h"

enum { TFP_WALL = 0, TFP_SLIP, TFP_AXIS, TFP_INLET, TFP_OUTLET };
/* what a face's normal velocities are */
enum { TFP_FACE_INTERIOR = 0, TFP_FACE_CLOSED, TFP_FACE_INLET, TFP_FACE_OUTLET };

typedef struct tfp_boundary {
  int type;
  int solids_slip;   /* wall: the solids slip freely along it */
  sl_expr *velocity; /* inlet: superficial fluid velocity entering, of (x, y, t, case) */
  double pressure;   /* outlet */
} tfp_boundary;

typedef struct tfp_model {
  sl_tensor_grid grid;
  int nx, ny, nc, nfx, nf;
  int axi;
  double g[2];
  double mu_s; /* [solid] viscosity: the solids stress is phi mu_s grad u_s */
  tf_column c; /* the physics, the closures and the numerical keys (its column geometry is unused) */
  const tfp_boundary *b; /* [n_boundaries] */
  /* geometry */
  double *xc, *yc, *hx, *hy;      /* cell centres and sizes along x [nx], y [ny] */
  double *vol;                    /* [nc] (axisymmetric: r dr dz, without 2 pi) */
  double *area, *dist;            /* [nf]: face area (axisymmetric: r ds), centre-to-centre distance (half cells at
                                     the boundary) */
  int *lo, *hi;                   /* [nf] */
  int *ftype, *fbound;            /* [nf]: TFP_FACE_*, the boundary index of a boundary face (-1 inside) */
  int *tan_noslip;                /* [2 nf]: per phase (fluid 0, solids 1), 1 when the boundary along which the
                                     face's velocity runs holds it (no-slip), 0 free */
  /* state: cells phi, p, P_s; faces the fluid and solids velocities (boundary faces hold their values) */
  double *phi, *p, *uf, *us;
  double *phi_new, *p_new, *uf_new, *us_new;
  /* unknown numbering: us_row[f], uf_row[f] (-1: given), p at n_vel + c */
  int *us_row, *uf_row;
  int n_vel, n_unknowns;
  int closed; /* no outlet: the pressure takes its datum in cell 0 */
  /* the step's work arrays */
  double *phf, *phg, *w, *K, *dK, *slip, *sn, *ps, *dps, *flux, *alpha, *inflow, *x, *rhs;
  /* the linear system: triplets, their CSR positions */
  int n_trip, cap_trip;
  int32_t *trow, *tcol, *tpos;
  int32_t *prow, *pcol; /* the triplet sequence the pattern was built from */
  int phi_frozen;       /* this iteration takes the face phi from the step's start */
  double *tval;
  sl_csr A;
  int pattern_built;
  sl_linsolve *ls;
  /* counters of the trial step */
  double outflow_trial, transport_cpu;
  long substeps_trial, accepted_substeps, last_substeps;
  int iterations_trial;
  char where[256]; /* where the last failure happened */
} tfp_model;

/* The grid geometry, face types and unknown numbering from the grid and the
 * boundaries. 0 or SL_EFAILED (memory). */
int tfp_setup(tfp_model *m, sl_diag *d);
void tfp_free(tfp_model *m);

/* The inlet faces' fluid velocities at t (with the inside cells' phi). */
int tfp_boundary_values(tfp_model *m, double t, const double *phi, sl_diag *d);

/* One backward-Euler step from the state at t over dt into the *_new
 * arrays. 0, or SL_EFAILED with the reason (the caller retries smaller). */
int tfp_step(tfp_model *m, double t, double dt, sl_diag *d);

/* phi = T(phi^n, us) over dt (two_fluid_plane_transport.c): the solids
 * leaving through the boundary are added to *outflow. 0, or SL_EFAILED when
 * the sub-steps needed are too many (the caller retries smaller). */
int tfp_transport(tfp_model *m, const double *us, double dt, double *phi, double *outflow, sl_diag *d);

/* The solids volume (per radian when axisymmetric) in the domain. */
double tfp_inventory(const tfp_model *m, const double *phi);

#endif
