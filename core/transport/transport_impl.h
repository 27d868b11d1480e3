/* Internal: the transport object shared by transport.c (set-up, geometry),
 * muscl.c (reconstruction) and step.c (fluxes, sub-cycling). */
#ifndef SLUICE_TRANSPORT_TRANSPORT_IMPL_H
#define SLUICE_TRANSPORT_TRANSPORT_IMPL_H

#include "core/transport/transport.h"

enum { SL_FACE_INTERIOR = 0, SL_FACE_WALL = 1, SL_FACE_OPEN = 2 };

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
  int *bc_type;   /* [n_boundaries] sl_transport_bc */
  double *bc_phi; /* [n_boundaries] */
  int *fkind;     /* [n_faces] SL_FACE_* */
  /* work */
  double *res, *cur, *stage, *grad, *sens;
};

/* Limited gradients of phi into t->grad (order 2). */
void sl_transport_reconstruct(sl_transport *t, const double *phi);

#endif
