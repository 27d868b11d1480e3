/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Conservative face fluxes of a Taylor–Hood velocity (see face_flux.h). */
#include "core/fv/face_flux.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sl_face_flux {
  const sl_th_space *th;
  int axisymmetric;
  unsigned char *adjustable; /* [n_faces] */
  unsigned char *closed;     /* [n_faces] or NULL: faces whose flux is zero (sl_face_flux_close) */
  int n_pairs;
  int *pairs; /* [2 n_pairs] periodic face pairs (fa, fb): one face between their owners */
  sl_csr L;   /* cell graph Laplacian over adjustable faces, one cell pinned if closed */
  sl_linsolve *ls;
  int pinned;           /* the pinned cell, -1 when L is regular */
  double *div, *lambda; /* [n_cells] */
};

void sl_face_flux_destroy(sl_face_flux *ff) {
  if (!ff) return;
  sl_csr_free(&ff->L);
  sl_linsolve_destroy(ff->ls);
  free(ff->adjustable);
  free(ff->closed);
  free(ff->pairs);
  free(ff->div);
  free(ff->lambda);
  free(ff);
}

void sl_face_flux_raw(const sl_face_flux *ff, const double *u, double *q) {
  const sl_th_space *th = ff->th;
  const sl_mesh *m = th->mesh;
  const int nb = th->vel->dofs_per_cell, nv = m->nv_per_cell;
  for (int f = 0; f < m->n_faces; ++f) {
    int c = m->face_cells[2 * f], k = m->face_local[2 * f];
    /* values through the dofs, geometry through the nodes (they differ across periodic seams) */
    const int32_t *cd = th->vel->cell_dofs + (size_t)c * nb, *cn = th->vel->cell_nodes + (size_t)c * nb;
    const double *xy = th->vel->node_xy;
    if (m->dim == 1) {
      /* local face 0 is the left end (normal -1), face 1 the right end */
      double un = u[sl_th_vel_dof(th, 0, cd[k])];
      double r = ff->axisymmetric ? xy[2 * cn[k]] : 1.0;
      q[f] = (k == 0 ? -un : un) * r;
      continue;
    }
    int32_t node[3] = {cd[k], cd[nv + k], cd[(k + 1) % nv]}, geo[3] = {cn[k], cn[nv + k], cn[(k + 1) % nv]};
    const double *a = xy + 2 * geo[0], *b = xy + 2 * geo[2];
    /* outward normal of the owner times the length: (dy, -dx) */
    double nx = b[1] - a[1], ny = -(b[0] - a[0]);
    static const double simpson[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
    double s = 0.0;
    for (int j = 0; j < 3; ++j) {
      double un = u[sl_th_vel_dof(th, 0, node[j])] * nx + u[sl_th_vel_dof(th, 1, node[j])] * ny;
      double r = ff->axisymmetric ? xy[2 * geo[j]] : 1.0;
      s += simpson[j] * un * r;
    }
    q[f] = ff->closed && ff->closed[f] ? 0.0 : s;
  }
}

int sl_face_flux_create(const sl_th_space *th, int axisymmetric, const unsigned char *adjustable, const int *pairs,
                        int n_pairs, sl_face_flux **out, sl_diag *d) {
  *out = NULL;
  const sl_mesh *m = th->mesh;
  sl_face_flux *ff = calloc(1, sizeof *ff);
  if (!ff) return sl_diag_set(d, SL_ENOMEM, "face fluxes: out of memory");
  ff->th = th, ff->axisymmetric = axisymmetric, ff->pinned = -1;
  int nc = m->n_cells, nf = m->n_faces, rc = 0;
  ff->adjustable = calloc((size_t)nf, 1);
  ff->div = malloc((size_t)nc * sizeof *ff->div);
  ff->lambda = malloc((size_t)nc * sizeof *ff->lambda);
  /* the pattern: one "element" per interior face coupling its two cells, one per cell for the diagonal */
  int32_t *ptr = malloc((size_t)(nf + nc + n_pairs + 1) * sizeof *ptr);
  int32_t *rows = calloc((size_t)(2 * nf + 2 * n_pairs + nc), sizeof *rows);
  ff->n_pairs = n_pairs;
  ff->pairs = malloc((size_t)(2 * n_pairs + 1) * sizeof *ff->pairs);
  if (!ff->adjustable || !ff->div || !ff->lambda || !ptr || !rows || !ff->pairs) {
    rc = sl_diag_set(d, SL_ENOMEM, "face fluxes: out of memory");
    goto out;
  }
  int open = 0;
  for (int f = 0; f < nf; ++f) {
    int tag = m->face_tag[f];
    ff->adjustable[f] = tag < 0 || (adjustable && adjustable[tag]);
    if (tag >= 0 && ff->adjustable[f]) open = 1;
  }
  if (n_pairs) memcpy(ff->pairs, pairs, (size_t)2 * n_pairs * sizeof *pairs);
  for (int k = 0; k < 2 * n_pairs; ++k) ff->adjustable[pairs[k]] = 0; /* handled as pairs */
  int32_t at = 0, ne = 0;
  ptr[0] = 0;
  for (int c = 0; c < nc; ++c) rows[at++] = c, ptr[++ne] = at;
  for (int f = 0; f < nf; ++f)
    if (m->face_cells[2 * f + 1] >= 0)
      rows[at++] = m->face_cells[2 * f], rows[at++] = m->face_cells[2 * f + 1], ptr[++ne] = at;
  for (int k = 0; k < n_pairs; ++k)
    rows[at++] = m->face_cells[2 * pairs[2 * k]], rows[at++] = m->face_cells[2 * pairs[2 * k + 1]], ptr[++ne] = at;
  if ((rc = sl_csr_build(&ff->L, nc, nc, ne, ptr, rows, NULL, NULL, d))) goto out;
  for (int f = 0; f < nf; ++f) {
    if (!ff->adjustable[f]) continue;
    int a = m->face_cells[2 * f], b = m->face_cells[2 * f + 1];
    ff->L.values[sl_csr_find(&ff->L, a, a)] += 1.0;
    if (b < 0) continue;
    ff->L.values[sl_csr_find(&ff->L, b, b)] += 1.0;
    ff->L.values[sl_csr_find(&ff->L, a, b)] -= 1.0;
    ff->L.values[sl_csr_find(&ff->L, b, a)] -= 1.0;
  }
  for (int k = 0; k < n_pairs; ++k) {
    int a = m->face_cells[2 * pairs[2 * k]], b = m->face_cells[2 * pairs[2 * k + 1]];
    ff->L.values[sl_csr_find(&ff->L, a, a)] += 1.0;
    ff->L.values[sl_csr_find(&ff->L, b, b)] += 1.0;
    ff->L.values[sl_csr_find(&ff->L, a, b)] -= 1.0;
    ff->L.values[sl_csr_find(&ff->L, b, a)] -= 1.0;
  }
  if (!open) {
    /* closed vessel: the constants are the null space; pin cell 0 (symmetrically, for Cholesky) */
    ff->pinned = 0;
    int32_t r0 = 0;
    if ((rc = sl_csr_set_dirichlet(&ff->L, 1, &r0, NULL, NULL, 1, d))) goto out;
  }
  sl_csr_touch(&ff->L);
  if ((rc = sl_linsolve_create(&ff->ls, "cholmod", d))) goto out;
  if ((rc = sl_linsolve_factor(ff->ls, &ff->L, d))) rc = sl_diag_prefix(d, rc, "face fluxes: cell Laplacian");
out:
  free(ptr), free(rows);
  if (rc) sl_face_flux_destroy(ff);
  else *out = ff;
  return rc;
}

int sl_face_flux_close(sl_face_flux *ff, const unsigned char *closed, sl_diag *d) {
  const sl_mesh *m = ff->th->mesh;
  if (!closed || m->dim != 2) return 0;
  if (!ff->closed && !(ff->closed = calloc((size_t)m->n_faces + 1, 1)))
    return sl_diag_set(d, SL_ENOMEM, "face fluxes: out of memory");
  for (int f = 0; f < m->n_faces; ++f) {
    int tag = m->face_tag[f];
    if (tag >= 0 && closed[tag] && !ff->adjustable[f]) ff->closed[f] = 1;
  }
  return 0;
}

int sl_face_flux_conservative(sl_face_flux *ff, const double *u, double floor, double *q, double *raw_divergence,
                              sl_diag *d) {
  const sl_mesh *m = ff->th->mesh;
  int nc = m->n_cells, nf = m->n_faces;
  sl_face_flux_raw(ff, u, q);
  for (int k = 0; k < ff->n_pairs; ++k) { /* one flux from a to b across the seam: the mean of both sides */
    int fa = ff->pairs[2 * k], fb = ff->pairs[2 * k + 1];
    double qp = 0.5 * (q[fa] - q[fb]);
    q[fa] = qp, q[fb] = -qp;
  }
  memset(ff->div, 0, (size_t)nc * sizeof *ff->div);
  memset(ff->lambda, 0, (size_t)nc * sizeof *ff->lambda); /* reused for the through-flow */
  for (int f = 0; f < nf; ++f) {
    int a = m->face_cells[2 * f], b = m->face_cells[2 * f + 1];
    ff->div[a] += q[f], ff->lambda[a] += fabs(q[f]);
    if (b >= 0) ff->div[b] -= q[f], ff->lambda[b] += fabs(q[f]);
  }
  double dmax = 0.0, smax = 0.0;
  for (int c = 0; c < nc; ++c) dmax = fmax(dmax, fabs(ff->div[c])), smax = fmax(smax, ff->lambda[c]);
  if (raw_divergence) *raw_divergence = fmax(smax, floor) > 0.0 ? dmax / fmax(smax, floor) : 0.0;
  if (smax == 0.0) return 0; /* nothing moves */
  if (ff->pinned >= 0) ff->div[ff->pinned] = 0.0;
  int rc = sl_linsolve_solve(ff->ls, &ff->L, ff->div, ff->lambda, d);
  if (rc) return sl_diag_prefix(d, rc, "face fluxes");
  for (int f = 0; f < nf; ++f) {
    if (!ff->adjustable[f]) continue;
    int a = m->face_cells[2 * f], b = m->face_cells[2 * f + 1];
    q[f] -= ff->lambda[a] - (b >= 0 ? ff->lambda[b] : 0.0);
  }
  for (int k = 0; k < ff->n_pairs; ++k) {
    int fa = ff->pairs[2 * k], fb = ff->pairs[2 * k + 1];
    q[fa] -= ff->lambda[m->face_cells[2 * fa]] - ff->lambda[m->face_cells[2 * fb]];
    q[fb] = -q[fa];
  }
  return 0;
}
