/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Checks shared by the mesh tests: topology, normals, areas, lengths. */
#ifndef SLUICE_TESTS_MESH_CHECKS_H
#define SLUICE_TESTS_MESH_CHECKS_H

#include <math.h>
#include <stdlib.h>

#include "core/mesh/mesh.h"
#include "testing.h"

/* Compensated (Kahan) sum, so the area checks test the mesh, not the sum. */
typedef struct ksum {
  double s, c;
} ksum;
static inline void ksum_add(ksum *k, double x) {
  double y = x - k->c, t = k->s + y;
  k->c = (t - k->s) - y;
  k->s = t;
}

static inline double total_area(const sl_mesh *m) {
  ksum k = {0, 0};
  for (int c = 0; c < m->n_cells; ++c) ksum_add(&k, sl_mesh_cell_area(m, c));
  return k.s;
}

/* Total length of the faces of boundary `name` (the number of points in 1-D). */
static inline double boundary_length(const sl_mesh *m, const char *name) {
  int id;
  sl_diag d;
  if (sl_mesh_boundary_id(m, name, &id, &d)) return -1;
  ksum k = {0, 0};
  for (int i = m->bface_start[id]; i < m->bface_start[id + 1]; ++i) ksum_add(&k, sl_mesh_face_length(m, m->bface[i]));
  return k.s;
}

static inline int boundary_count(const sl_mesh *m, const char *name) {
  int id;
  sl_diag d;
  if (sl_mesh_boundary_id(m, name, &id, &d)) return -1;
  return m->bface_start[id + 1] - m->bface_start[id];
}

/* Outward normal of local face k of cell c computed from the cell itself. */
static inline void cell_face_normal(const sl_mesh *m, int c, int k, double n[2]) {
  const int *cv = m->cell_vertices + c * m->nv_per_cell;
  if (m->dim == 1) {
    n[0] = k == 0 ? -1 : 1;
    n[1] = 0;
    return;
  }
  const double *a = m->xy + 2 * cv[k], *b = m->xy + 2 * cv[(k + 1) % m->nv_per_cell];
  double dx = b[0] - a[0], dy = b[1] - a[1], l = hypot(dx, dy);
  n[0] = dy / l;
  n[1] = -dx / l;
}

/* Everything that must hold for any valid mesh: consistent cell/face maps,
 * two cells with opposite normals on interior faces, outward normals on the
 * boundary, closed cells (sum of n L over a cell's faces = 0), boundary
 * tags exactly on boundary faces, bface lists matching face_tag. */
static inline void check_mesh_invariants(const sl_mesh *m) {
  int bad_map = 0, bad_normal = 0, bad_out = 0, bad_tag = 0, nb = 0;
  for (int f = 0; f < m->n_faces; ++f) {
    double n[2], nc[2], fc[2], cc[2];
    sl_mesh_face_normal(m, f, n);
    sl_mesh_face_centroid(m, f, fc);
    for (int s = 0; s < 2; ++s) {
      int c = m->face_cells[2 * f + s], k = m->face_local[2 * f + s];
      if (c < 0) {
        if (s == 0 || k != -1) ++bad_map;
        continue;
      }
      if (k < 0 || k >= m->nf_per_cell || m->cell_faces[c * m->nf_per_cell + k] != f) ++bad_map;
      cell_face_normal(m, c, k, nc);
      double sign = s == 0 ? 1 : -1; /* the neighbour sees the opposite normal */
      if (fabs(nc[0] - sign * n[0]) > 1e-14 || fabs(nc[1] - sign * n[1]) > 1e-14) ++bad_normal;
      /* Outward: from the cell's centroid towards the face. */
      sl_mesh_cell_centroid(m, c, cc);
      if (sign * ((fc[0] - cc[0]) * n[0] + (fc[1] - cc[1]) * n[1]) <= 0) ++bad_out;
    }
    int boundary = m->face_cells[2 * f + 1] < 0;
    nb += boundary;
    if (boundary != (m->face_tag[f] >= 0)) ++bad_tag;
  }
  CHECK(bad_map == 0);
  CHECK(bad_normal == 0);
  CHECK(bad_out == 0);
  CHECK(bad_tag == 0);
  CHECK(nb == m->n_boundary_faces);
  CHECK(m->bface_start[m->n_boundaries] == m->n_boundary_faces);
  int bad_list = 0;
  for (int b = 0; b < m->n_boundaries; ++b)
    for (int i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i)
      if (m->face_tag[m->bface[i]] != b || (i > m->bface_start[b] && m->bface[i] <= m->bface[i - 1])) ++bad_list;
  CHECK(bad_list == 0);
  /* Closed cells: the face normals weighted by lengths sum to zero. */
  double worst = 0;
  for (int c = 0; c < m->n_cells; ++c) {
    double sx = 0, sy = 0, scale = 0;
    for (int k = 0; k < m->nf_per_cell; ++k) {
      int f = m->cell_faces[c * m->nf_per_cell + k];
      double n[2], l = sl_mesh_face_length(m, f), sign = m->face_cells[2 * f] == c ? 1 : -1;
      sl_mesh_face_normal(m, f, n);
      sx += sign * n[0] * l;
      sy += sign * n[1] * l;
      scale += l;
    }
    double r = hypot(sx, sy) / scale;
    if (r > worst) worst = r;
  }
  CHECK_MSG(worst < 1e-14, "cells not closed: %g", worst);
}

/* Euler characteristic of a simply connected 2-D mesh: V - E + F = 1. */
static inline int euler(const sl_mesh *m) { return m->n_vertices - m->n_faces + m->n_cells; }

#endif
