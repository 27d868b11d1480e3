/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solids fraction of the inflow, along the boundary and in time
 * (inflow.h). */
#include "core/models/mixture/inflow.h"

#include <stdio.h>
#include <stdlib.h>

#include "core/config/expr.h"
#include "core/models/navier_stokes/flow.h"

struct sl_mixture_inflow {
  const sl_scene *sc;
  sl_transport *tr;
  double phi_max;
  int n;               /* boundaries with values along them */
  int *b;              /* [n] their mesh indices */
  int *timed;          /* [n] 1: phi depends on t */
  double *v;           /* scratch: one value per face of the longest */
  int n_open;          /* the boundaries solids pass through */
  int *open_b;         /* [n_open] their mesh indices */
  double *trial, *cum; /* [n_open] solids in through each: the last transport step, the accepted ones' sum */
};

/* The values of boundary b's phi at its face points at time t into in->v. */
static int evaluate(sl_mixture_inflow *in, int b, const ns_boundary *nb, double t, sl_diag *d) {
  const sl_mesh *m = in->sc->mesh;
  const double *xf = sl_transport_face_points(in->tr);
  for (int i = m->bface_start[b]; i < m->bface_start[b + 1]; ++i) {
    const double *x = xf + 2 * m->bface[i];
    double at[3] = {x[0], x[1], t}, v = sl_expr_eval(nb->phi.e, at);
    if (!(v >= 0 && v <= in->phi_max)) {
      char where[400];
      return sl_diag_set(d, SL_EBADINPUT, "%s = %g at (%g, %g), t = %g: allowed 0 <= phi <= phi_max = %g",
                         sl_scene_where(in->sc, &nb->phi, where, sizeof where), v, x[0], x[1], t, in->phi_max);
    }
    in->v[i - m->bface_start[b]] = v;
  }
  return 0;
}

int sl_mixture_inflow_create(const sl_scene *sc, sl_transport *tr, const unsigned char *open, double phi_max,
                             sl_mixture_inflow **out, sl_diag *d) {
  *out = NULL;
  const sl_mesh *m = sc->mesh;
  sl_mixture_inflow *in = calloc(1, sizeof *in);
  if (!in) return sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  in->sc = sc, in->tr = tr, in->phi_max = phi_max;
  int longest = 0, rc = 0;
  for (int b = 0; b < m->n_boundaries; ++b)
    if (m->bface_start[b + 1] - m->bface_start[b] > longest) longest = m->bface_start[b + 1] - m->bface_start[b];
  in->b = malloc((size_t)m->n_boundaries * sizeof *in->b);
  in->timed = malloc((size_t)m->n_boundaries * sizeof *in->timed);
  in->v = malloc((size_t)(longest + 1) * sizeof *in->v);
  in->open_b = malloc((size_t)m->n_boundaries * sizeof *in->open_b);
  in->trial = calloc((size_t)m->n_boundaries + 1, sizeof *in->trial);
  in->cum = calloc((size_t)m->n_boundaries + 1, sizeof *in->cum);
  if (!in->b || !in->timed || !in->v || !in->open_b || !in->trial || !in->cum)
    rc = sl_diag_set(d, SL_ENOMEM, "mixture: out of memory");
  for (int b = 0; b < m->n_boundaries && !rc; ++b) {
    const ns_boundary *nb = sl_scene_boundary(sc, b);
    int through = (open && open[b]) || (nb->type == NS_VELOCITY && nb->phi.e);
    if (!through) continue;
    double c = 0.0;
    int constant = !nb->phi.e || sl_expr_is_constant(nb->phi.e, &c);
    if (constant && !(c >= 0 && c <= phi_max)) {
      char where[400];
      rc = sl_diag_set(d, SL_EBADINPUT, "%s = %g is outside the allowed range [0, %g] (phi_max)",
                       sl_scene_where(sc, &nb->phi, where, sizeof where), c, phi_max);
      break;
    }
    if ((rc = sl_transport_set_boundary(tr, b, SL_TRANSPORT_OPEN, constant ? c : 0.0, d))) break;
    in->open_b[in->n_open++] = b;
    if (constant) continue;
    in->b[in->n] = b, in->timed[in->n] = sl_expr_uses(nb->phi.e, 2);
    ++in->n;
    if (!(rc = evaluate(in, b, nb, 0.0, d))) rc = sl_transport_set_boundary_values(tr, b, in->v, d);
  }
  if (rc || in->n_open == 0) {
    sl_mixture_inflow_destroy(in);
    return rc;
  }
  *out = in;
  return 0;
}

int sl_mixture_inflow_update(sl_mixture_inflow *in, double t, sl_diag *d) {
  if (!in) return 0;
  int rc = 0;
  for (int k = 0; k < in->n && !rc; ++k) {
    if (!in->timed[k]) continue;
    const ns_boundary *nb = sl_scene_boundary(in->sc, in->b[k]);
    if (!(rc = evaluate(in, in->b[k], nb, t, d))) rc = sl_transport_set_boundary_values(in->tr, in->b[k], in->v, d);
  }
  return rc;
}

void sl_mixture_inflow_stepped(sl_mixture_inflow *in) {
  for (int k = 0; in && k < in->n_open; ++k) in->trial[k] = sl_transport_boundary_flow(in->tr, in->open_b[k]);
}

void sl_mixture_inflow_accept(sl_mixture_inflow *in) {
  for (int k = 0; in && k < in->n_open; ++k) in->cum[k] += in->trial[k];
}

int sl_mixture_inflow_write(const sl_mixture_inflow *in, sl_output *out, int axisymmetric, sl_diag *d) {
  int rc = 0;
  for (int k = 0; in && k < in->n_open && !rc; ++k) {
    char name[128];
    snprintf(name, sizeof name, "solids_through_%s", in->sc->mesh->boundary_names[in->open_b[k]]);
    rc = sl_output_write_scalar_unit(out, name, axisymmetric ? "m^3/rad" : "m^2", in->cum[k], d);
  }
  return rc;
}

int sl_mixture_inflow_checkpoint(sl_mixture_inflow *in, sl_checkpoint_array *a, int max) {
  if (!in || max < 1) return 0;
  snprintf(a->name, sizeof a->name, "solids_through");
  a->n = in->n_open, a->data = in->cum;
  return 1;
}

void sl_mixture_inflow_restore(sl_mixture_inflow *in, const sl_checkpoint_array *a) {
  if (!in) return;
  for (int k = 0; k < in->n_open; ++k) in->cum[k] = a && a->n == in->n_open ? a->data[k] : 0.0;
}

void sl_mixture_inflow_destroy(sl_mixture_inflow *in) {
  if (!in) return;
  free(in->b), free(in->timed), free(in->v), free(in->open_b), free(in->trial), free(in->cum);
  free(in);
}
