/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Exterior states that vary along an open boundary (transport.h,
 * sl_transport_set_boundary_values): one value per face, read by the
 * Godunov flux in place of the boundary's single phi_outside. */
#include <stdlib.h>

#include "core/transport/transport_impl.h"

double sl_transport_boundary_flow(const sl_transport *t, int b) {
  return b >= 0 && b < t->m->n_boundaries ? t->bstep[b] : 0.0;
}

int sl_transport_set_boundary_values(sl_transport *t, int b, const double *phi_faces, sl_diag *d) {
  const sl_mesh *m = t->m;
  if (b < 0 || b >= m->n_boundaries)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary %d does not exist (the mesh has %d)", b, m->n_boundaries);
  if (t->bc_type[b] != SL_TRANSPORT_OPEN)
    return sl_diag_set(d, SL_EBADINPUT, "transport: boundary '%s' is not open: values along it are not used",
                       m->boundary_names[b]);
  int i0 = m->bface_start[b], i1 = m->bface_start[b + 1];
  for (int i = i0; i < i1; ++i) {
    double v = phi_faces[i - i0];
    if (!(v >= 0 && v <= t->o.phi_max)) {
      const double *x = t->xf + 2 * m->bface[i];
      return sl_diag_set(d, SL_EBADINPUT,
                         "transport: boundary '%s': phi outside = %g at (%g, %g) is not in [0, phi_max = %g]",
                         m->boundary_names[b], v, x[0], x[1], t->o.phi_max);
    }
  }
  if (!t->face_phi) { /* from here on every open face reads its own value */
    if (!(t->face_phi = malloc((size_t)m->n_faces * sizeof *t->face_phi)))
      return sl_diag_set(d, SL_ENOMEM, "transport: out of memory");
    for (int f = 0; f < m->n_faces; ++f) t->face_phi[f] = 0;
    for (int c = 0; c < m->n_boundaries; ++c)
      for (int i = m->bface_start[c]; i < m->bface_start[c + 1]; ++i) t->face_phi[m->bface[i]] = t->bc_phi[c];
  }
  for (int i = i0; i < i1; ++i) t->face_phi[m->bface[i]] = phi_faces[i - i0];
  return 0;
}
