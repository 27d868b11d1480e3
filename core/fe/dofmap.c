/* Dof numbering for continuous Lagrange spaces and Taylor–Hood pairs. */
#include "core/fe/dofmap.h"

#include <stdlib.h>
#include <string.h>

#include "core/fe/geometry.h"

void sl_dofmap_destroy(sl_dofmap *dm) {
  if (!dm) return;
  free(dm->cell_dofs);
  free(dm->xy);
  free(dm);
}

/* Node coordinates: the images of the element's reference nodes under the
 * geometric map (vertices copied exactly). Shared nodes get the same value
 * from every cell: the map restricted to a straight face depends only on
 * that face's vertices. */
static void place_nodes(sl_dofmap *dm) {
  const sl_mesh *m = dm->mesh;
  memcpy(dm->xy, m->xy, 2 * (size_t)m->n_vertices * sizeof *dm->xy);
  for (int32_t c = 0; c < m->n_cells; ++c)
    for (int i = m->nv_per_cell; i < dm->dofs_per_cell; ++i) {
      int32_t node = dm->cell_dofs[(size_t)c * dm->dofs_per_cell + i];
      sl_fe_map_point(m, c, dm->element->nodes[i], dm->xy + 2 * (size_t)node);
    }
}

/* Fills cell_dofs in the element's basis order (core/fe/element.h). */
static void number_cells(sl_dofmap *dm) {
  const sl_mesh *m = dm->mesh;
  int nv = m->nv_per_cell, k = dm->dofs_per_cell;
  int32_t cell_base = m->n_vertices + (m->dim == 2 ? m->n_faces : 0);
  for (int32_t c = 0; c < m->n_cells; ++c) {
    int32_t *cd = dm->cell_dofs + (size_t)c * k;
    for (int i = 0; i < nv; ++i) cd[i] = m->cell_vertices[(size_t)c * nv + i];
    if (dm->element->order == 1) continue;
    if (m->dim == 1) {
      cd[2] = m->n_vertices + c;
      continue;
    }
    for (int f = 0; f < m->nf_per_cell; ++f) cd[nv + f] = m->n_vertices + m->cell_faces[(size_t)c * m->nf_per_cell + f];
    if (k > nv + m->nf_per_cell) cd[k - 1] = cell_base + c; /* Q2 centre */
  }
}

static int32_t count_dofs(const sl_mesh *m, const sl_element *e) {
  if (e->order == 1) return m->n_vertices;
  if (m->dim == 1) return m->n_vertices + m->n_cells;
  int has_centre = e->n_basis > m->nv_per_cell + m->nf_per_cell;
  return m->n_vertices + m->n_faces + (has_centre ? m->n_cells : 0);
}

int sl_dofmap_create(const sl_mesh *mesh, int order, sl_dofmap **out, sl_diag *d) {
  *out = NULL;
  const sl_element *e = sl_element_lagrange(mesh->cell_type, order);
  if (!e)
    return sl_diag_set(d, SL_EBADINPUT, "dof map: no Lagrange element of order %d on %s cells (1 or 2)", order,
                       sl_cell_type_name(mesh->cell_type));
  sl_dofmap *dm = calloc(1, sizeof *dm);
  if (!dm) return sl_diag_set(d, SL_EFAILED, "dof map: out of memory");
  dm->mesh = mesh, dm->element = e, dm->dofs_per_cell = e->n_basis;
  dm->n_dofs = count_dofs(mesh, e);
  dm->cell_dofs = malloc((size_t)mesh->n_cells * e->n_basis * sizeof *dm->cell_dofs);
  dm->xy = malloc(2 * (size_t)dm->n_dofs * sizeof *dm->xy);
  if (!dm->cell_dofs || !dm->xy) {
    sl_dofmap_destroy(dm);
    return sl_diag_set(d, SL_EFAILED, "dof map: out of memory");
  }
  number_cells(dm);
  place_nodes(dm);
  *out = dm;
  return 0;
}

static int cmp_int32(const void *a, const void *b) {
  int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
  return (x > y) - (x < y);
}

int sl_dofmap_boundary_dofs(const sl_dofmap *dm, const char *boundary, int32_t **dofs, int32_t *n, sl_diag *d) {
  const sl_mesh *m = dm->mesh;
  *dofs = NULL, *n = 0;
  int b;
  int rc = sl_mesh_boundary_id(m, boundary, &b, d);
  if (rc) return rc;
  int32_t nf = m->bface_start[b + 1] - m->bface_start[b];
  if (nf == 0) return 0;
  int32_t *list = malloc(3 * (size_t)nf * sizeof *list), k = 0;
  if (!list) return sl_diag_set(d, SL_EFAILED, "dof map: out of memory");
  for (int32_t i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) {
    int f = m->bface[i];
    list[k++] = m->face_vertices[2 * f];
    if (m->dim == 1) continue;
    list[k++] = m->face_vertices[2 * f + 1];
    if (dm->element->order == 2) list[k++] = m->n_vertices + f;
  }
  qsort(list, (size_t)k, sizeof *list, cmp_int32);
  int32_t u = 0;
  for (int32_t i = 0; i < k; ++i)
    if (u == 0 || list[i] != list[u - 1]) list[u++] = list[i];
  *dofs = list, *n = u;
  return 0;
}

/* ---- Taylor–Hood ---------------------------------------------------------- */

void sl_th_destroy(sl_th_space *th) {
  if (!th) return;
  sl_dofmap_destroy(th->vel);
  sl_dofmap_destroy(th->pres);
  free(th->cell_dofs);
  free(th);
}

static void number_th_cells(sl_th_space *th) {
  int nbv = th->vel->dofs_per_cell, nbp = th->pres->dofs_per_cell, k = th->dofs_per_cell;
  for (int32_t c = 0; c < th->mesh->n_cells; ++c) {
    int32_t *cd = th->cell_dofs + (size_t)c * k;
    const int32_t *v = th->vel->cell_dofs + (size_t)c * nbv, *p = th->pres->cell_dofs + (size_t)c * nbp;
    for (int comp = 0; comp < th->n_comp; ++comp)
      for (int i = 0; i < nbv; ++i) cd[comp * nbv + i] = sl_th_vel_dof(th, comp, v[i]);
    for (int i = 0; i < nbp; ++i) cd[th->n_comp * nbv + i] = sl_th_pres_dof(th, p[i]);
  }
}

int sl_th_create(const sl_mesh *mesh, int n_comp, sl_th_space **out, sl_diag *d) {
  *out = NULL;
  if (n_comp < mesh->dim || n_comp > 3)
    return sl_diag_set(d, SL_EBADINPUT, "Taylor-Hood: %d velocity components on a %d-D mesh (%d..3)", n_comp,
                       mesh->dim, mesh->dim);
  sl_th_space *th = calloc(1, sizeof *th);
  if (!th) return sl_diag_set(d, SL_EFAILED, "Taylor-Hood: out of memory");
  th->mesh = mesh, th->n_comp = n_comp;
  int rc = sl_dofmap_create(mesh, 2, &th->vel, d);
  if (!rc) rc = sl_dofmap_create(mesh, 1, &th->pres, d);
  if (rc) {
    sl_th_destroy(th);
    return rc;
  }
  th->n_vel = th->vel->n_dofs;
  th->p_offset = n_comp * th->n_vel;
  th->n_dofs = th->p_offset + th->pres->n_dofs;
  th->dofs_per_cell = n_comp * th->vel->dofs_per_cell + th->pres->dofs_per_cell;
  th->cell_dofs = malloc((size_t)mesh->n_cells * th->dofs_per_cell * sizeof *th->cell_dofs);
  if (!th->cell_dofs) {
    sl_th_destroy(th);
    return sl_diag_set(d, SL_EFAILED, "Taylor-Hood: out of memory");
  }
  number_th_cells(th);
  *out = th;
  return 0;
}
