/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Internal: the transport object shared by transport.c (set-up, geometry),
 * periodic.c (periodic boundary pairs), muscl.c (reconstruction), step.c
 * (fluxes, sub-cycling) and migration.c (the shear-induced migration flux). */
#ifndef SLUICE_TRANSPORT_TRANSPORT_IMPL_H
#define SLUICE_TRANSPORT_TRANSPORT_IMPL_H

#include "core/transport/transport.h"

/* Face kinds. A periodic pair (fa on the first boundary, fb on the second)
 * is one flux face: fa is SL_FACE_PERIODIC and carries the flux from its
 * owner into the owner of fb; fb is SL_FACE_PERIODIC_IMAGE and is skipped
 * by the flux loops (but still bounds its owner's reconstruction). */
enum { SL_FACE_INTERIOR = 0, SL_FACE_WALL = 1, SL_FACE_OPEN = 2, SL_FACE_PERIODIC = 3, SL_FACE_PERIODIC_IMAGE = 4 };

struct sl_transport {
  const sl_mesh *m;
  sl_transport_opts o; /* defaults resolved */
  sl_settling_table tab;
  double *vol;    /* [n_cells] */
  double *area;   /* [n_faces] */
  double *normal; /* [2 n_faces], out of the owner */
  double *xf;     /* [2 n_faces] face points */
  double *xc;     /* [2 n_cells] cell points (r-weighted centroids when axisymmetric) */
  double *lsq;    /* [3 n_cells] inverse least-squares matrix (xx, xy, yy); zeros: no gradient */
  /* Order 2: the cells that share a vertex with cell c (c excluded), across
   * periodic pairs too, vnb[vnb_start[c] .. vnb_start[c + 1] - 1]: the
   * limiter's range (muscl.c). vnb_pairs: the periodic boundaries linked
   * when it was built (pairs are only ever added, so a count tells). */
  int *vnb_start, *vnb;
  int vnb_pairs;
  int *bc_type;                 /* [n_boundaries] sl_transport_bc, or SL_TRANSPORT_PERIODIC_ (below) */
  double *bc_phi;               /* [n_boundaries] */
  double *bres, *bres1, *bstep; /* [n_boundaries + 1]: solids into each boundary's cells: one residual, its first
                                   stage, the last sl_transport_step (sl_transport_boundary_flow) */
  double *face_phi; /* [n_faces] exterior states per open face (inflow.c), NULL: bc_phi of the face's boundary */
  int *fkind;       /* [n_faces] SL_FACE_* */
  /* Periodic pairs (NULL until the first sl_transport_set_periodic). */
  int *partner;   /* [n_faces] the paired face, -1 for the others */
  double *pshift; /* [2 n_faces] added to the partner's owner's cell point to bring it next to this face */
  /* Extra face flux (sl_transport_set_extra_flux), NULL when none. */
  sl_transport_extra_fn extra;
  void *extra_user;
  double *xflux, *xflux2;    /* [n_faces] the extra flux at the sub-step's start and at its second stage */
  double *xin, *xout, *xadv; /* [n_cells] limiter work: inflow, outflow, the state after advection */
  /* work */
  double *res, *cur, *stage, *grad, *sens;
};

/* bc_type of a boundary that belongs to a periodic pair. */
enum { SL_TRANSPORT_PERIODIC_ = 100 };

/* The cell across face f from its owner (the face's own cell for a boundary
 * face) and the shift to add to that cell's point so that it lies across
 * the face: the other cell and 0 inside, the partner's owner and pshift on
 * a periodic face, -1 on walls and open faces. */
static inline int sl_transport_across(const sl_transport *t, int f, int c, double shift[2]) {
  const int *fc = t->m->face_cells;
  shift[0] = shift[1] = 0;
  if (t->fkind[f] == SL_FACE_INTERIOR) return fc[2 * f] == c ? fc[2 * f + 1] : fc[2 * f];
  if (t->fkind[f] == SL_FACE_PERIODIC || t->fkind[f] == SL_FACE_PERIODIC_IMAGE) {
    shift[0] = t->pshift[2 * f], shift[1] = t->pshift[2 * f + 1];
    return fc[2 * t->partner[f]];
  }
  return -1;
}

/* The least-squares matrices (after the geometry or the pairs changed). */
void sl_transport_build_lsq(sl_transport *t);

/* Builds t->vnb for the current periodic pairs (at creation, and again by
 * the step after a pair was added). Returns 0 or SL_EFAILED (d set). */
int sl_transport_build_vertex_cells(sl_transport *t, sl_diag *d);
/* The number of boundaries in periodic pairs (compare with t->vnb_pairs). */
int sl_transport_periodic_count(const sl_transport *t);

/* Limited gradients of phi into t->grad (order 2; t->vnb current). */
void sl_transport_reconstruct(sl_transport *t, const double *phi);

#endif
