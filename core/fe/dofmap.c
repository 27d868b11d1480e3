/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Dof numbering for continuous Lagrange spaces and Taylor–Hood pairs. */
#include "core/fe/dofmap.h"

#include <stdlib.h>
#include <string.h>

#include "core/fe/geometry.h"

void sl_dofmap_destroy(sl_dofmap *dm) {
  if (!dm) return;
  if (dm->cell_nodes != dm->cell_dofs) free(dm->cell_nodes);
  if (dm->node_xy != dm->xy) free(dm->node_xy);
  free(dm->cell_dofs);
  free(dm->xy);
  free(dm->node_dof);
  free(dm);
}

/* Node coordinates: the images of the element's reference nodes under the
 * geometric map (vertices copied exactly). Shared nodes get the same value
 * from every cell: the map restricted to a straight face depends only on
 * that face's vertices. */
static void place_nodes(sl_dofmap *dm) {
  const sl_mesh *m = dm->mesh;
  memcpy(dm->node_xy, m->xy, 2 * (size_t)m->n_vertices * sizeof *dm->node_xy);
  for (int32_t c = 0; c < m->n_cells; ++c)
    for (int i = m->nv_per_cell; i < dm->dofs_per_cell; ++i) {
      int32_t node = dm->cell_nodes[(size_t)c * dm->dofs_per_cell + i];
      sl_fe_map_point(m, c, dm->element->nodes[i], dm->node_xy + 2 * (size_t)node);
    }
}

/* Fills cell_nodes in the element's basis order (core/fe/element.h). */
static void number_cells(sl_dofmap *dm) {
  const sl_mesh *m = dm->mesh;
  int nv = m->nv_per_cell, k = dm->dofs_per_cell;
  int32_t cell_base = m->n_vertices + (m->dim == 2 ? m->n_faces : 0);
  for (int32_t c = 0; c < m->n_cells; ++c) {
    int32_t *cd = dm->cell_nodes + (size_t)c * k;
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

static int32_t count_nodes(const sl_mesh *m, const sl_element *e) {
  if (e->order == 1) return m->n_vertices;
  if (m->dim == 1) return m->n_vertices + m->n_cells;
  int has_centre = e->n_basis > m->nv_per_cell + m->nf_per_cell;
  return m->n_vertices + m->n_faces + (has_centre ? m->n_cells : 0);
}

/* ---- periodic identification ----------------------------------------------- */

static int32_t find_root(int32_t *parent, int32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

static void unite(int32_t *parent, int32_t a, int32_t b) {
  a = find_root(parent, a), b = find_root(parent, b);
  if (a < b) parent[b] = a;
  else if (b < a) parent[a] = b;
}

/* The dof numbering from the node numbering and the matched pairs. */
static int identify(sl_dofmap *dm, const sl_mesh_periodic *match, int n_match, sl_diag *d) {
  const sl_mesh *m = dm->mesh;
  int32_t nn = dm->n_nodes;
  int32_t *parent = malloc(((size_t)nn + 1) * sizeof *parent), *rep = malloc(((size_t)nn + 1) * sizeof *rep);
  unsigned char *on_partner = calloc((size_t)nn + 1, 1);
  if (!parent || !rep || !on_partner) {
    free(parent), free(rep), free(on_partner);
    return sl_diag_set(d, SL_ENOMEM, "dof map: out of memory");
  }
  for (int32_t i = 0; i < nn; ++i) parent[i] = i, rep[i] = -1;
  int face_nodes = dm->element->order == 2 && m->dim == 2;
  for (int k = 0; k < n_match; ++k) {
    const sl_mesh_periodic *p = &match[k];
    for (int i = 0; i < p->n_vertices; ++i) {
      unite(parent, p->vertex_pairs[2 * i], p->vertex_pairs[2 * i + 1]);
      on_partner[p->vertex_pairs[2 * i + 1]] = 1;
    }
    for (int i = 0; i < p->n_faces && face_nodes; ++i) {
      int32_t a = m->n_vertices + p->face_pairs[2 * i], b = m->n_vertices + p->face_pairs[2 * i + 1];
      unite(parent, a, b);
      on_partner[b] = 1;
    }
  }
  /* The representative of a class: its lowest node on no partner boundary. */
  for (int32_t i = 0; i < nn; ++i) {
    int32_t r = find_root(parent, i);
    if (!on_partner[i] && rep[r] < 0) rep[r] = i;
  }
  int rc = 0;
  for (int32_t i = 0; i < nn && !rc; ++i)
    if (parent[i] == i && rep[i] < 0)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "periodic pairs: every node identified with (%g, %g) lies on a partner boundary, so none "
                       "keeps the dof (do the pairs form a cycle?)",
                       dm->node_xy[2 * (size_t)i], dm->node_xy[2 * (size_t)i + 1]);
  int32_t n_dofs = 0;
  if (!rc) { /* dofs in the order of their first node */
    for (int32_t i = 0; i < nn; ++i) dm->node_dof[i] = -1;
    for (int32_t i = 0; i < nn; ++i) {
      int32_t r = find_root(parent, i);
      if (dm->node_dof[r] < 0) dm->node_dof[r] = n_dofs++;
      dm->node_dof[i] = dm->node_dof[r];
    }
    dm->n_dofs = n_dofs;
    size_t ncd = (size_t)m->n_cells * dm->dofs_per_cell;
    dm->cell_dofs = malloc((ncd + 1) * sizeof *dm->cell_dofs);
    dm->xy = malloc((2 * (size_t)n_dofs + 1) * sizeof *dm->xy);
    if (!dm->cell_dofs || !dm->xy) rc = sl_diag_set(d, SL_ENOMEM, "dof map: out of memory");
    for (size_t k = 0; k < ncd && !rc; ++k) dm->cell_dofs[k] = dm->node_dof[dm->cell_nodes[k]];
    for (int32_t i = 0; i < nn && !rc; ++i)
      if (parent[i] == i) {
        const double *x = dm->node_xy + 2 * (size_t)rep[i];
        double *y = dm->xy + 2 * (size_t)dm->node_dof[i];
        y[0] = x[0], y[1] = x[1];
      }
  }
  free(parent), free(rep), free(on_partner);
  return rc;
}

static int dofmap_build(const sl_mesh *mesh, int order, const sl_mesh_periodic *match, int n_match, sl_dofmap **out,
                        sl_diag *d) {
  *out = NULL;
  const sl_element *e = sl_element_lagrange(mesh->cell_type, order);
  if (!e)
    return sl_diag_set(d, SL_EBADINPUT, "dof map: no Lagrange element of order %d on %s cells (1 or 2)", order,
                       sl_cell_type_name(mesh->cell_type));
  sl_dofmap *dm = calloc(1, sizeof *dm);
  if (!dm) return sl_diag_set(d, SL_ENOMEM, "dof map: out of memory");
  dm->mesh = mesh, dm->element = e, dm->dofs_per_cell = e->n_basis;
  dm->n_nodes = count_nodes(mesh, e);
  dm->n_periodic = n_match;
  dm->cell_nodes = malloc(((size_t)mesh->n_cells * e->n_basis + 1) * sizeof *dm->cell_nodes);
  dm->node_xy = malloc((2 * (size_t)dm->n_nodes + 1) * sizeof *dm->node_xy);
  dm->node_dof = malloc(((size_t)dm->n_nodes + 1) * sizeof *dm->node_dof);
  if (!dm->cell_nodes || !dm->node_xy || !dm->node_dof) {
    sl_dofmap_destroy(dm);
    return sl_diag_set(d, SL_ENOMEM, "dof map: out of memory");
  }
  number_cells(dm);
  place_nodes(dm);
  if (n_match == 0) {
    dm->n_dofs = dm->n_nodes;
    dm->cell_dofs = dm->cell_nodes, dm->xy = dm->node_xy;
    for (int32_t i = 0; i < dm->n_nodes; ++i) dm->node_dof[i] = i;
  } else {
    int rc = identify(dm, match, n_match, d);
    if (rc) {
      sl_dofmap_destroy(dm);
      return rc;
    }
  }
  *out = dm;
  return 0;
}

int sl_dofmap_create(const sl_mesh *mesh, int order, sl_dofmap **out, sl_diag *d) {
  return dofmap_build(mesh, order, NULL, 0, out, d);
}

static void free_matches(sl_mesh_periodic *match, int n) {
  for (int k = 0; k < n && match; ++k) sl_mesh_periodic_free(&match[k]);
  free(match);
}

/* Matches every pair and checks them as a set. */
static int match_pairs(const sl_mesh *mesh, const sl_periodic_pair *pairs, int n_pairs, sl_mesh_periodic **out,
                       sl_diag *d) {
  *out = NULL;
  if (n_pairs < 0 || (n_pairs > 0 && !pairs))
    return sl_diag_set(d, SL_EBADINPUT, "periodic pairs: %d pairs given%s", n_pairs, pairs ? "" : " without a list");
  if (n_pairs == 0) return 0;
  sl_mesh_periodic *match = calloc((size_t)n_pairs, sizeof *match);
  int *master = malloc(((size_t)mesh->n_boundaries + 1) * sizeof *master);
  if (!match || !master) {
    free(match), free(master);
    return sl_diag_set(d, SL_ENOMEM, "periodic pairs: out of memory");
  }
  int rc = 0;
  for (int k = 0; k < n_pairs && !rc; ++k)
    rc = sl_mesh_periodic_match(mesh, pairs[k].boundary, pairs[k].partner, &match[k], d);
  for (int b = 0; b < mesh->n_boundaries; ++b) master[b] = -1;
  for (int k = 0; k < n_pairs && !rc; ++k) {
    int b = match[k].partner;
    if (master[b] >= 0)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "periodic pairs: boundary '%s' is the partner of two pairs ('%s' / '%s' and '%s' / '%s'); a "
                       "boundary can be identified with one other only",
                       mesh->boundary_names[b], mesh->boundary_names[master[b]], mesh->boundary_names[b],
                       mesh->boundary_names[match[k].boundary], mesh->boundary_names[b]);
    else master[b] = match[k].boundary;
  }
  /* Each boundary has at most one master: follow the links for a cycle. */
  for (int b = 0; b < mesh->n_boundaries && !rc; ++b) {
    int at = master[b];
    for (int steps = 0; at >= 0 && at != b && steps <= n_pairs; ++steps) at = master[at];
    if (at == b)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "periodic pairs form a cycle through boundary '%s' (it is, through the pairs, its own "
                       "partner): list each periodic direction once",
                       mesh->boundary_names[b]);
  }
  free(master);
  if (rc) {
    free_matches(match, n_pairs);
    return rc;
  }
  *out = match;
  return 0;
}

int sl_dofmap_create_periodic(const sl_mesh *mesh, int order, const sl_periodic_pair *pairs, int n_pairs,
                              sl_dofmap **out, sl_diag *d) {
  *out = NULL;
  sl_mesh_periodic *match;
  int rc = match_pairs(mesh, pairs, n_pairs, &match, d);
  if (rc) return rc;
  rc = dofmap_build(mesh, order, match, n_pairs, out, d);
  free_matches(match, n_pairs);
  return rc;
}

void sl_dofmap_dofs_to_nodes(const sl_dofmap *dm, const double *u, double *u_nodes, int stride) {
  for (int32_t i = 0; i < dm->n_nodes; ++i) u_nodes[(size_t)i * stride] = u[dm->node_dof[i]];
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
  if (!list) return sl_diag_set(d, SL_ENOMEM, "dof map: out of memory");
  for (int32_t i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) {
    int f = m->bface[i];
    list[k++] = dm->node_dof[m->face_vertices[2 * f]];
    if (m->dim == 1) continue;
    list[k++] = dm->node_dof[m->face_vertices[2 * f + 1]];
    if (dm->element->order == 2) list[k++] = dm->node_dof[m->n_vertices + f];
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
  return sl_th_create_periodic(mesh, n_comp, NULL, 0, out, d);
}

int sl_th_create_periodic(const sl_mesh *mesh, int n_comp, const sl_periodic_pair *pairs, int n_pairs,
                          sl_th_space **out, sl_diag *d) {
  *out = NULL;
  if (n_comp < mesh->dim || n_comp > 3)
    return sl_diag_set(d, SL_EBADINPUT, "Taylor-Hood: %d velocity components on a %d-D mesh (%d..3)", n_comp, mesh->dim,
                       mesh->dim);
  sl_mesh_periodic *match;
  int rc = match_pairs(mesh, pairs, n_pairs, &match, d);
  if (rc) return rc;
  sl_th_space *th = calloc(1, sizeof *th);
  if (!th) {
    free_matches(match, n_pairs);
    return sl_diag_set(d, SL_ENOMEM, "Taylor-Hood: out of memory");
  }
  th->mesh = mesh, th->n_comp = n_comp;
  rc = dofmap_build(mesh, 2, match, n_pairs, &th->vel, d);
  if (!rc) rc = dofmap_build(mesh, 1, match, n_pairs, &th->pres, d);
  free_matches(match, n_pairs);
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
    return sl_diag_set(d, SL_ENOMEM, "Taylor-Hood: out of memory");
  }
  number_th_cells(th);
  *out = th;
  return 0;
}
