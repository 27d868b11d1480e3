/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Transport set-up: options, flux table, geometry (planar and r-weighted),
 * least-squares matrices, boundary types, helpers for the settling
 * coefficients. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/transport/transport_impl.h"

void sl_transport_destroy(sl_transport *t) {
  if (!t) return;
  sl_settling_table_free(&t->tab);
  free(t->vol);
  free(t->area);
  free(t->normal);
  free(t->xf);
  free(t->xc);
  free(t->lsq);
  free(t->vnb_start);
  free(t->vnb);
  free(t->bc_type);
  free(t->bc_phi);
  free(t->face_phi);
  free(t->bres), free(t->bres1), free(t->bstep);
  free(t->fkind);
  free(t->partner);
  free(t->pshift);
  free(t->xflux);
  free(t->xflux2);
  free(t->xin);
  free(t->xout);
  free(t->xadv);
  free(t->res);
  free(t->cur);
  free(t->stage);
  free(t->grad);
  free(t->sens);
  free(t);
}

/* int r dA and int (x, y) r dA of cell c: a fan of triangles from vertex 0
 * (cells are convex), each integrated by the edge-midpoint rule, exact for
 * the quadratic integrands x r and y r. */
static void axisym_cell(const sl_mesh *m, int c, double *vol, double cen[2]) {
  const int *cv = m->cell_vertices + (size_t)c * m->nv_per_cell;
  const double *p0 = m->xy + 2 * cv[0];
  double sv = 0, sx = 0, sy = 0;
  for (int k = 1; k + 1 < m->nv_per_cell; ++k) {
    const double *a = m->xy + 2 * cv[k], *b = m->xy + 2 * cv[k + 1];
    double area = 0.5 * ((a[0] - p0[0]) * (b[1] - p0[1]) - (a[1] - p0[1]) * (b[0] - p0[0]));
    const double *pa[3] = {p0, a, b};
    for (int e = 0; e < 3; ++e) {
      const double *u = pa[e], *v = pa[(e + 1) % 3];
      double mx = 0.5 * (u[0] + v[0]), my = 0.5 * (u[1] + v[1]);
      sv += area / 3 * mx;
      sx += area / 3 * mx * mx;
      sy += area / 3 * my * mx;
    }
  }
  *vol = sv;
  cen[0] = sx / sv;
  cen[1] = sy / sv;
}

static int build_geometry(sl_transport *t, sl_diag *d) {
  const sl_mesh *m = t->m;
  int axi = t->o.geometry == SL_TRANSPORT_AXISYMMETRIC;
  if (axi)
    for (int v = 0; v < m->n_vertices; ++v)
      if (m->xy[2 * v] < 0)
        return sl_diag_set(d, SL_EBADINPUT, "transport: axisymmetric mesh with r = x = %g < 0 at vertex %d",
                           m->xy[2 * v], v);
  for (int c = 0; c < m->n_cells; ++c) {
    const int *cv = m->cell_vertices + (size_t)c * m->nv_per_cell;
    if (!axi) {
      t->vol[c] = sl_mesh_cell_area(m, c);
      sl_mesh_cell_centroid(m, c, t->xc + 2 * c);
    } else if (m->dim == 1) {
      double x0 = m->xy[2 * cv[0]], x1 = m->xy[2 * cv[1]];
      t->vol[c] = 0.5 * (x1 - x0) * (x1 + x0);
      /* int x^2 dx / int x dx = (2/3)(x0^2 + x0 x1 + x1^2) / (x0 + x1) */
      t->xc[2 * c] = 2.0 / 3.0 * (x0 * x0 + x0 * x1 + x1 * x1) / (x0 + x1);
      t->xc[2 * c + 1] = 0;
    } else {
      axisym_cell(m, c, &t->vol[c], t->xc + 2 * c);
    }
    if (!(t->vol[c] > 0)) return sl_diag_set(d, SL_EBADINPUT, "transport: cell %d has volume %g", c, t->vol[c]);
  }
  for (int f = 0; f < m->n_faces; ++f) {
    sl_mesh_face_normal(m, f, t->normal + 2 * f);
    sl_mesh_face_centroid(m, f, t->xf + 2 * f);
    double len = sl_mesh_face_length(m, f);
    if (!axi) {
      t->area[f] = len;
    } else if (m->dim == 1) {
      t->area[f] = t->xf[2 * f];
    } else {
      /* int r ds on the straight edge a -> b, and the r-weighted point:
       * int_0^1 (a + s e)(r_a + s dr) ds = a r_a + (a dr + e r_a) / 2 + e dr / 3. */
      const double *a = m->xy + 2 * m->face_vertices[2 * f], *b = m->xy + 2 * m->face_vertices[2 * f + 1];
      double ra = a[0], dr = b[0] - a[0], ey = b[1] - a[1];
      double mean_r = ra + 0.5 * dr;
      t->area[f] = len * mean_r;
      if (mean_r > 0) {
        t->xf[2 * f] = (ra * ra + ra * dr + dr * dr / 3) / mean_r;
        t->xf[2 * f + 1] = (a[1] * ra + 0.5 * (a[1] * dr + ey * ra) + ey * dr / 3) / mean_r;
      }
    }
    t->fkind[f] = m->face_cells[2 * f + 1] >= 0 ? SL_FACE_INTERIOR : SL_FACE_WALL;
  }
  sl_transport_build_lsq(t);
  return 0;
}

/* Least-squares gradient matrices sum_j d d^T over the face neighbours
 * (across periodic pairs too, at their translated points). */
void sl_transport_build_lsq(sl_transport *t) {
  const sl_mesh *m = t->m;
  for (int c = 0; c < m->n_cells; ++c) {
    double a = 0, b = 0, e = 0;
    for (int k = 0; k < m->nf_per_cell; ++k) {
      int f = m->cell_faces[(size_t)c * m->nf_per_cell + k];
      double sh[2];
      int j = sl_transport_across(t, f, c, sh);
      if (j < 0) continue;
      double dx = t->xc[2 * j] + sh[0] - t->xc[2 * c], dy = t->xc[2 * j + 1] + sh[1] - t->xc[2 * c + 1];
      a += dx * dx, b += dx * dy, e += dy * dy;
    }
    double *L = t->lsq + 3 * c;
    L[0] = L[1] = L[2] = 0;
    if (m->dim == 1) {
      if (a > 0) L[0] = 1 / a;
    } else {
      double det = a * e - b * b;
      if (det > 1e-10 * (a * e)) /* otherwise the neighbours are collinear: no gradient */
        L[0] = e / det, L[1] = -b / det, L[2] = a / det;
    }
  }
}

int sl_transport_create(const sl_mesh *m, const sl_transport_opts *o, sl_transport **out, sl_diag *d) {
  *out = NULL;
  if (!m || !o) return sl_diag_set(d, SL_EBADINPUT, "transport: no mesh or no options");
  sl_transport_opts r = *o;
  if (r.order == 0) r.order = 2;
  if (r.cfl == 0) r.cfl = 0.9;
  if (r.table_points == 0) r.table_points = 2049;
  if (r.max_substeps == 0) r.max_substeps = 1000000;
  if (r.order != 1 && r.order != 2) return sl_diag_set(d, SL_EBADINPUT, "transport: order %d (1 or 2)", r.order);
  if (!(r.cfl > 0 && r.cfl <= 1)) return sl_diag_set(d, SL_EBADINPUT, "transport: cfl = %g is not in (0, 1]", r.cfl);
  if (r.limiter != SL_LIMITER_MC && r.limiter != SL_LIMITER_MINMOD)
    return sl_diag_set(d, SL_EBADINPUT, "transport: unknown limiter %d", (int)r.limiter);
  if (r.geometry != SL_TRANSPORT_PLANAR && r.geometry != SL_TRANSPORT_AXISYMMETRIC)
    return sl_diag_set(d, SL_EBADINPUT, "transport: unknown geometry %d", (int)r.geometry);
  if (r.max_substeps < 1) return sl_diag_set(d, SL_EBADINPUT, "transport: max_substeps = %d", r.max_substeps);
  sl_transport *t = calloc(1, sizeof *t);
  if (!t) return sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
  t->m = m;
  t->o = r;
  size_t nc = (size_t)m->n_cells, nf = (size_t)m->n_faces, nb = (size_t)m->n_boundaries;
  t->vol = malloc(nc * sizeof *t->vol);
  t->area = malloc(nf * sizeof *t->area);
  t->normal = malloc(2 * nf * sizeof *t->normal);
  t->xf = malloc(2 * nf * sizeof *t->xf);
  t->xc = malloc(2 * nc * sizeof *t->xc);
  t->lsq = malloc(3 * nc * sizeof *t->lsq);
  t->bc_type = calloc(nb + 1, sizeof *t->bc_type);
  t->bc_phi = calloc(nb + 1, sizeof *t->bc_phi);
  t->bres = calloc(nb + 1, sizeof *t->bres);
  t->bres1 = calloc(nb + 1, sizeof *t->bres1);
  t->bstep = calloc(nb + 1, sizeof *t->bstep);
  t->fkind = malloc(nf * sizeof *t->fkind);
  t->res = malloc(nc * sizeof *t->res);
  t->cur = malloc(nc * sizeof *t->cur);
  t->stage = malloc(nc * sizeof *t->stage);
  t->grad = malloc(2 * nc * sizeof *t->grad);
  t->sens = malloc(nc * sizeof *t->sens);
  int rc;
  if (!t->vol || !t->area || !t->normal || !t->xf || !t->xc || !t->lsq || !t->bc_type || !t->bc_phi || !t->fkind ||
      !t->bres || !t->bres1 || !t->bstep || !t->res || !t->cur || !t->stage || !t->grad || !t->sens) {
    rc = sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
    goto fail;
  }
  if ((rc = build_geometry(t, d))) goto fail;
  if (r.order == 2 && (rc = sl_transport_build_vertex_cells(t, d))) goto fail;
  if ((rc = sl_settling_table_build(&t->tab, r.phi_max, r.table_points, r.settling, r.settling_user, d))) {
    sl_diag_prefix(d, rc, "transport");
    goto fail;
  }
  *out = t;
  return 0;
fail:
  sl_transport_destroy(t);
  return rc;
}

int sl_transport_set_boundary(sl_transport *t, int b, sl_transport_bc type, double phi_outside, sl_diag *d) {
  const sl_mesh *m = t->m;
  if (b < 0 || b >= m->n_boundaries)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary %d does not exist (the mesh has %d)", b, m->n_boundaries);
  if (t->bc_type[b] == SL_TRANSPORT_PERIODIC_)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' is periodic; it cannot become a %s",
                       m->boundary_names[b], type == SL_TRANSPORT_OPEN ? "open boundary" : "wall");
  if (type != SL_TRANSPORT_WALL && type != SL_TRANSPORT_OPEN)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s': unknown type %d", m->boundary_names[b], (int)type);
  if (type == SL_TRANSPORT_OPEN && !(phi_outside >= 0 && phi_outside <= t->o.phi_max))
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s': phi outside = %g is not in [0, phi_max = %g]",
                       m->boundary_names[b], phi_outside, t->o.phi_max);
  t->bc_type[b] = (int)type;
  t->bc_phi[b] = type == SL_TRANSPORT_OPEN ? phi_outside : 0;
  for (int i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) {
    t->fkind[m->bface[i]] = type == SL_TRANSPORT_OPEN ? SL_FACE_OPEN : SL_FACE_WALL;
    if (t->face_phi) t->face_phi[m->bface[i]] = t->bc_phi[b];
  }
  return 0;
}

const double *sl_transport_volumes(const sl_transport *t) { return t->vol; }
const double *sl_transport_face_areas(const sl_transport *t) { return t->area; }
const double *sl_transport_face_points(const sl_transport *t) { return t->xf; }
const double *sl_transport_cell_points(const sl_transport *t) { return t->xc; }
const sl_settling_table *sl_transport_table(const sl_transport *t) { return &t->tab; }
const sl_mesh *sl_transport_mesh(const sl_transport *t) { return t->m; }

void sl_transport_settling_uniform(const sl_transport *t, const double b[2], double *w) {
  for (int f = 0; f < t->m->n_faces; ++f) w[f] = t->area[f] * (b[0] * t->normal[2 * f] + b[1] * t->normal[2 * f + 1]);
}

void sl_transport_settling_field(const sl_transport *t, void (*b)(void *user, const double x[2], double b[2]),
                                 void *user, double *w) {
  for (int f = 0; f < t->m->n_faces; ++f) {
    double v[2] = {0, 0};
    b(user, t->xf + 2 * f, v);
    w[f] = t->area[f] * (v[0] * t->normal[2 * f] + v[1] * t->normal[2 * f + 1]);
  }
}

void sl_transport_settling_faces(const sl_transport *t, const double *b, double *w) {
  for (int f = 0; f < t->m->n_faces; ++f)
    w[f] = t->area[f] * (b[2 * f] * t->normal[2 * f] + b[2 * f + 1] * t->normal[2 * f + 1]);
}

double sl_transport_mass(const sl_transport *t, const double *phi) {
  double s = 0, c = 0;
  for (int i = 0; i < t->m->n_cells; ++i) {
    double v = t->vol[i] * phi[i], u = s + v;
    c += fabs(s) >= fabs(v) ? (s - u) + v : (v - u) + s;
    s = u;
  }
  return s + c;
}
