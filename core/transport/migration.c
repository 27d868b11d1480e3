/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The shear-induced migration flux (Phillips et al. 1992; Nigam 1999 eqs
 * 2.29-2.30): two-point face fluxes and the stable explicit step. See
 * migration.h for the formulas and the positivity argument. */
#include "core/transport/migration.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/transport/transport_impl.h"

/* Below this difference of phi the secant slope of ln mu is taken as the
 * mean of the two derivatives (cancellation). */
#define SECANT_MIN 1e-7

struct sl_migration {
  const sl_transport *t;
  sl_migration_opts o;
  double *g;                  /* [n_cells] shear rate */
  int *fface;                 /* [n_faces] the flux faces, packed */
  double *pf, *gf, *dc, *dmu; /* [n_faces] face states and coefficients, packed */
  double *lnmu, *dlnmu, *sum; /* [n_cells] */
  int limit_cell;
};

void sl_migration_destroy(sl_migration *mg) {
  if (!mg) return;
  free(mg->g);
  free(mg->fface);
  free(mg->pf);
  free(mg->gf);
  free(mg->dc);
  free(mg->dmu);
  free(mg->lnmu);
  free(mg->dlnmu);
  free(mg->sum);
  free(mg);
}

int sl_migration_create(const sl_transport *t, const sl_migration_opts *o, sl_migration **out, sl_diag *d) {
  *out = NULL;
  if (!t || !o || (!o->coef && !(o->diffusivity > 0.0)) || !(o->diffusivity >= 0.0 && isfinite(o->diffusivity)))
    return sl_diag_set(d, SL_EBADINPUT,
                       "migration: no transport, or neither a coefficient callback nor a finite "
                       "diffusivity > 0");
  sl_migration *mg = calloc(1, sizeof *mg);
  if (!mg) return sl_diag_set(d, SL_ENOMEM, "migration: out of memory");
  size_t nc = (size_t)t->m->n_cells, nf = (size_t)t->m->n_faces + 1;
  mg->t = t;
  mg->o = *o;
  mg->limit_cell = -1;
  mg->g = calloc(nc, sizeof *mg->g);
  mg->fface = malloc(nf * sizeof *mg->fface);
  mg->pf = malloc(nf * sizeof *mg->pf);
  mg->gf = malloc(nf * sizeof *mg->gf);
  mg->dc = malloc(nf * sizeof *mg->dc);
  mg->dmu = malloc(nf * sizeof *mg->dmu);
  mg->lnmu = calloc(nc, sizeof *mg->lnmu);
  mg->dlnmu = calloc(nc, sizeof *mg->dlnmu);
  mg->sum = malloc(nc * sizeof *mg->sum);
  if (!mg->g || !mg->fface || !mg->pf || !mg->gf || !mg->dc || !mg->dmu || !mg->lnmu || !mg->dlnmu || !mg->sum) {
    sl_migration_destroy(mg);
    return sl_diag_set(d, SL_ENOMEM, "migration: out of memory");
  }
  *out = mg;
  return 0;
}

int sl_migration_set_shear_rate(sl_migration *mg, const double *g, sl_diag *d) {
  const sl_transport *t = mg->t;
  for (int c = 0; c < t->m->n_cells; ++c)
    if (!(g[c] >= 0 && isfinite(g[c])))
      return sl_diag_set(d, SL_EBADINPUT, "migration: shear rate %g in cell %d at (%g, %g) (finite, >= 0)", g[c], c,
                         t->xc[2 * c], t->xc[2 * c + 1]);
  memcpy(mg->g, g, (size_t)t->m->n_cells * sizeof *mg->g);
  return 0;
}

const double *sl_migration_shear_rate(const sl_migration *mg) { return mg->g; }
int sl_migration_limiting_cell(const sl_migration *mg) { return mg->limit_cell; }

int sl_migration_flux(void *migration, const double *phi, double *flux, double *dt_stable, sl_diag *d) {
  sl_migration *mg = migration;
  const sl_transport *t = mg->t;
  const sl_mesh *m = t->m;
  const int nc = m->n_cells;
  const double *g = mg->g;
  int nff = 0, rc;
  *dt_stable = HUGE_VAL;
  mg->limit_cell = -1;
  /* The flux faces (interior, and the first face of each periodic pair)
   * and their states. */
  for (int f = 0; f < m->n_faces; ++f) {
    flux[f] = 0;
    int kind = t->fkind[f];
    if (kind != SL_FACE_INTERIOR && kind != SL_FACE_PERIODIC) continue;
    double sh[2];
    int o = m->face_cells[2 * f], n = sl_transport_across(t, f, o, sh);
    mg->fface[nff] = f;
    mg->pf[nff] = 0.5 * (phi[o] + phi[n]);
    mg->gf[nff] = 0.5 * (g[o] + g[n]);
    ++nff;
  }
  if (nff == 0) return 0;
  if (!mg->o.coef) {
    memset(mg->dc, 0, (size_t)nff * sizeof *mg->dc);
    memset(mg->dmu, 0, (size_t)nff * sizeof *mg->dmu);
  } else if ((rc = mg->o.coef(mg->o.coef_user, nff, mg->pf, mg->gf, mg->dc, mg->dmu, d))) {
    return sl_diag_prefix(d, rc, "migration: the coefficients D_c, D_mu");
  }
  if (mg->o.ln_mu && mg->o.coef) {
    if ((rc = mg->o.ln_mu(mg->o.ln_mu_user, nc, phi, mg->lnmu, mg->dlnmu, d)))
      return sl_diag_prefix(d, rc, "migration: ln mu");
    for (int c = 0; c < nc; ++c)
      if (!isfinite(mg->lnmu[c]) || !isfinite(mg->dlnmu[c]))
        return sl_diag_set(d, SL_EFAILED,
                           "migration: ln mu = %g, d ln mu/dphi = %g at phi = %.17g in cell %d at (%g, %g): the "
                           "viscosity must be finite where phi is (phi_max of the transport below the viscosity's "
                           "maximum packing, or a cell that packed to phi_max)",
                           mg->lnmu[c], mg->dlnmu[c], phi[c], c, t->xc[2 * c], t->xc[2 * c + 1]);
  }
  double *sum = mg->sum;
  memset(sum, 0, (size_t)nc * sizeof *sum);
  const int use_mu = mg->o.ln_mu != NULL && mg->o.coef != NULL;
  const double eps = mg->o.diffusivity;
  const double *L = mg->lnmu, *dL = mg->dlnmu;
  for (int k = 0; k < nff; ++k) {
    int f = mg->fface[k];
    double dc = mg->dc[k], dmu = use_mu ? mg->dmu[k] : 0, sh[2];
    int o = m->face_cells[2 * f], n = sl_transport_across(t, f, o, sh);
    if (!(dc >= 0 && isfinite(dc) && dmu >= 0 && isfinite(dmu)))
      return sl_diag_set(d, SL_EFAILED,
                         "migration: the coefficients are D_c = %g, D_mu = %g at phi = %g, shear rate %g (face %d at "
                         "(%g, %g)): they must be finite and >= 0",
                         dc, dmu, mg->pf[k], mg->gf[k], f, t->xf[2 * f], t->xf[2 * f + 1]);
    const double *xo = t->xc + 2 * o, *xn = t->xc + 2 * n, *nrm = t->normal + 2 * f;
    double dn = (xn[0] + sh[0] - xo[0]) * nrm[0] + (xn[1] + sh[1] - xo[1]) * nrm[1];
    if (!(dn > 0))
      return sl_diag_set(d, SL_EBADINPUT,
                         "migration: face %d at (%g, %g): the points of its cells %d and %d do not lie on both sides "
                         "of it (normal distance %g)",
                         f, t->xf[2 * f], t->xf[2 * f + 1], o, n, dn);
    double T = t->area[f] / dn;
    double dphi = phi[n] - phi[o], dlnmu = use_mu ? L[n] - L[o] : 0;
    flux[f] = -T * (dc * (g[n] * phi[n] - g[o] * phi[o]) + dmu * dlnmu + eps * dphi);
    double S = 0;
    if (use_mu) {
      S = fabs(dphi) > SECANT_MIN ? dlnmu / dphi : 0.5 * (dL[o] + dL[n]);
      if (S < 0) S = 0;
    }
    sum[o] += T * (dc * g[o] + dmu * S + eps);
    sum[n] += T * (dc * g[n] + dmu * S + eps);
  }
  double best = HUGE_VAL;
  for (int c = 0; c < nc; ++c)
    if (sum[c] > 0 && t->vol[c] < best * sum[c]) best = t->vol[c] / sum[c], mg->limit_cell = c;
  *dt_stable = best;
  return 0;
}
