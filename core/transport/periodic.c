/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Periodic boundary pairs: the faces of two mesh boundaries that match by a
 * translation are joined into interior faces between their cells (see
 * sl_transport_set_periodic in transport.h). The geometric match is the
 * mesh's (sl_mesh_periodic_match), the one the finite-element spaces use,
 * so the transport and the velocity pair the same faces. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/transport/transport_impl.h"

int sl_transport_set_periodic(sl_transport *t, int a, int b, sl_diag *d) {
  const sl_mesh *m = t->m;
  if (a < 0 || a >= m->n_boundaries || b < 0 || b >= m->n_boundaries)
    return sl_diag_set(d, SL_EBADINPUT, "transport: periodic pair (%d, %d): the mesh has boundaries 0 .. %d", a, b,
                       m->n_boundaries - 1);
  const char *na = m->boundary_names[a], *nb = m->boundary_names[b];
  if (a == b) return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' cannot be periodic with itself", na);
  for (int k = 0; k < 2; ++k) {
    int bb = k ? b : a;
    if (t->bc_type[bb] == SL_TRANSPORT_PERIODIC_)
      return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' is already periodic", m->boundary_names[bb]);
  }
  sl_mesh_periodic pm;
  int rc = sl_mesh_periodic_match(m, na, nb, &pm, d);
  if (rc) return sl_diag_prefix(d, rc, "transport");
  const double *s = pm.shift; /* b = a + s */
  if (t->o.geometry == SL_TRANSPORT_AXISYMMETRIC && s[0] != 0.0) {
    rc = sl_diag_set(d, SL_EBADINPUT,
                     "transport: periodic boundaries '%s' and '%s' are translated by (%g, %g): in an axisymmetric "
                     "geometry a periodic pair must be translated along z only",
                     na, nb, s[0], s[1]);
    goto done;
  }
  for (int i = 0; i < pm.n_faces; ++i) { /* the two faces' cells must lie on either side of the seam */
    int fa = pm.face_pairs[2 * i], fb = pm.face_pairs[2 * i + 1];
    const double *n_a = t->normal + 2 * fa, *n_b = t->normal + 2 * fb;
    const double *ca = t->xc + 2 * m->face_cells[2 * fa], *cb = t->xc + 2 * m->face_cells[2 * fb];
    double dn = (cb[0] - s[0] - ca[0]) * n_a[0] + (cb[1] - s[1] - ca[1]) * n_a[1];
    if (!(n_a[0] * n_b[0] + n_a[1] * n_b[1] < 0 && dn > 0)) {
      double xa[2];
      sl_mesh_face_centroid(m, fa, xa);
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "transport: periodic boundaries '%s' and '%s': face %d of '%s' at (%.9g, %.9g) and its "
                       "translate, face %d of '%s', do not face each other (their cells lie on the same side)",
                       na, nb, fa, na, xa[0], xa[1], fb, nb);
      goto done;
    }
  }
  if (!t->partner) {
    t->partner = malloc((size_t)m->n_faces * sizeof *t->partner);
    t->pshift = calloc(2 * (size_t)m->n_faces, sizeof *t->pshift);
    if (!t->partner || !t->pshift) {
      free(t->partner), free(t->pshift);
      t->partner = NULL, t->pshift = NULL;
      rc = sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
      goto done;
    }
    for (int f = 0; f < m->n_faces; ++f) t->partner[f] = -1;
  }
  for (int i = 0; i < pm.n_faces; ++i) {
    int fa = pm.face_pairs[2 * i], fb = pm.face_pairs[2 * i + 1];
    t->partner[fa] = fb, t->partner[fb] = fa;
    t->fkind[fa] = SL_FACE_PERIODIC, t->fkind[fb] = SL_FACE_PERIODIC_IMAGE;
    t->pshift[2 * fa] = -s[0], t->pshift[2 * fa + 1] = -s[1];
    t->pshift[2 * fb] = s[0], t->pshift[2 * fb + 1] = s[1];
  }
  t->bc_type[a] = t->bc_type[b] = SL_TRANSPORT_PERIODIC_;
  t->bc_phi[a] = t->bc_phi[b] = 0;
  sl_transport_build_lsq(t);
done:
  sl_mesh_periodic_free(&pm);
  return rc;
}

int sl_transport_set_periodic_named(sl_transport *t, const char *a, const char *b, sl_diag *d) {
  int ia, ib, rc;
  if ((rc = sl_mesh_boundary_id(t->m, a, &ia, d)) || (rc = sl_mesh_boundary_id(t->m, b, &ib, d)))
    return sl_diag_prefix(d, rc, "transport: periodic pair");
  return sl_transport_set_periodic(t, ia, ib, d);
}

int sl_transport_periodic_shift(const sl_transport *t, int b, double s[2], sl_diag *d) {
  const sl_mesh *m = t->m;
  if (b < 0 || b >= m->n_boundaries || t->bc_type[b] != SL_TRANSPORT_PERIODIC_)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary %d is not periodic", b);
  int f = m->bface[m->bface_start[b]];
  double sign = t->fkind[f] == SL_FACE_PERIODIC ? -1 : 1;
  s[0] = sign * t->pshift[2 * f], s[1] = sign * t->pshift[2 * f + 1];
  return 0;
}
