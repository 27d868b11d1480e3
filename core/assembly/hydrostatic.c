/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The hydrostatic part of a cell-wise buoyancy (see hydrostatic.h). */
#include "core/assembly/hydrostatic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sl_hydrostatic {
  int n_cells, n_layers;
  double up[2], g; /* unit vector along -g, |g| */
  double *level;   /* [n_layers + 1] heights of the level lines, increasing */
  int *layer;      /* [n_cells] */
  double *w, *h;   /* [n_cells] weights, heights of the cell points */
  double *fit;     /* [3 n_layers] a, b, hbar of the last split */
  double *pbase;   /* [n_layers + 1] P at the levels */
  double *work;    /* [2 n_layers] */
};

void sl_hydrostatic_destroy(sl_hydrostatic *h) {
  if (!h) return;
  free(h->level), free(h->layer), free(h->w), free(h->h), free(h->fit), free(h->pbase), free(h->work);
  free(h);
}

int sl_hydrostatic_layers(const sl_hydrostatic *h) { return h->n_layers; }

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* The level of height v: the index of the nearest level, -1 when none is
 * within tol. */
static int level_of(const double *lev, int n, double v, double tol) {
  int lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (lev[mid] <= v) lo = mid;
    else hi = mid;
  }
  int k = fabs(v - lev[lo]) <= fabs(v - lev[hi]) ? lo : hi;
  return fabs(v - lev[k]) <= tol ? k : -1;
}

int sl_hydrostatic_create(const sl_mesh *m, const double g[2], const double *weight, const double *point,
                          sl_hydrostatic **out, sl_diag *d) {
  *out = NULL;
  double gn = m->dim == 1 ? fabs(g[0]) : hypot(g[0], g[1]);
  if (!(gn > 0.0)) return 0;
  sl_hydrostatic *h = calloc(1, sizeof *h);
  int nv = m->n_vertices, nc = m->n_cells, rc = 0, layered = 0;
  double *vh = malloc((size_t)nv * sizeof *vh);
  if (!h || !vh) {
    free(vh), free(h);
    return sl_diag_set(d, SL_EFAILED, "hydrostatic: out of memory");
  }
  h->n_cells = nc, h->g = gn;
  h->up[0] = -g[0] / gn, h->up[1] = m->dim == 1 ? 0.0 : -g[1] / gn;
  for (int v = 0; v < nv; ++v) vh[v] = h->up[0] * m->xy[2 * v] + h->up[1] * m->xy[2 * v + 1];
  qsort(vh, (size_t)nv, sizeof *vh, cmp_double);
  double tol = 1e-9 * (vh[nv - 1] - vh[0]);
  /* clusters of heights within tol: the levels (their means) */
  int nl = 0;
  for (int i = 0, j; i < nv; i = j) {
    double s = 0.0;
    for (j = i; j < nv && vh[j] - vh[i] <= tol; ++j) s += vh[j];
    vh[nl++] = s / (j - i);
  }
  h->n_layers = nl - 1;
  h->level = malloc((size_t)nl * sizeof *h->level);
  h->layer = malloc((size_t)nc * sizeof *h->layer);
  h->w = malloc((size_t)nc * sizeof *h->w);
  h->h = malloc((size_t)nc * sizeof *h->h);
  h->fit = calloc((size_t)3 * (nl > 1 ? nl - 1 : 1), sizeof *h->fit);
  h->pbase = calloc((size_t)nl, sizeof *h->pbase);
  h->work = malloc((size_t)2 * nl * sizeof *h->work);
  if (!h->level || !h->layer || !h->w || !h->h || !h->fit || !h->pbase || !h->work) {
    rc = sl_diag_set(d, SL_EFAILED, "hydrostatic: out of memory");
    goto out;
  }
  memcpy(h->level, vh, (size_t)nl * sizeof *vh);
  layered = nl > 1;
  for (int c = 0; c < nc && layered; ++c) {
    int lo = nl, hi = -1;
    for (int k = 0; k < m->nv_per_cell; ++k) {
      const double *x = m->xy + 2 * m->cell_vertices[(size_t)c * m->nv_per_cell + k];
      int l = level_of(h->level, nl, h->up[0] * x[0] + h->up[1] * x[1], tol);
      if (l < lo) lo = l;
      if (l > hi) hi = l;
    }
    layered = lo >= 0 && hi == lo + 1;
    h->layer[c] = lo;
    h->w[c] = weight[c];
    h->h[c] = h->up[0] * point[2 * c] + h->up[1] * point[2 * c + 1];
  }
out:
  free(vh);
  if (rc || !layered) sl_hydrostatic_destroy(h);
  else *out = h;
  return rc;
}

void sl_hydrostatic_split(sl_hydrostatic *h, const double *rho, double *remainder) {
  int nl = h->n_layers;
  double *f = h->fit;
  memset(f, 0, (size_t)3 * nl * sizeof *f);
  /* per layer: sum w, sum w h, sum w rho (the means), then the slope about the mean height */
  double *sw = h->work, *ref = h->work + nl; /* the sums about a value of the layer: exact for a uniform one */
  memset(sw, 0, (size_t)nl * sizeof *sw);
  for (int c = h->n_cells - 1; c >= 0; --c) ref[h->layer[c]] = rho[c];
  for (int c = 0; c < h->n_cells; ++c) {
    double *L = f + 3 * h->layer[c];
    sw[h->layer[c]] += h->w[c], L[0] += h->w[c] * (rho[c] - ref[h->layer[c]]), L[2] += h->w[c] * h->h[c];
  }
  for (int l = 0; l < nl; ++l) f[3 * l] = ref[l] + f[3 * l] / sw[l], f[3 * l + 2] /= sw[l];
  double *shh = ref; /* sum w (h - hbar)^2; f[3 l + 1] gathers sum w (h - hbar)(rho - a) */
  memset(shh, 0, (size_t)nl * sizeof *shh);
  for (int c = 0; c < h->n_cells; ++c) {
    double *L = f + 3 * h->layer[c], dh = h->h[c] - L[2];
    shh[h->layer[c]] += h->w[c] * dh * dh, L[1] += h->w[c] * dh * (rho[c] - L[0]);
  }
  for (int l = 0; l < nl; ++l) {
    /* points at one height (within 1e-10 of the layer's thickness): a constant */
    double t = h->level[l + 1] - h->level[l];
    f[3 * l + 1] = shh[l] > 1e-20 * t * t * sw[l] ? f[3 * l + 1] / shh[l] : 0.0;
  }
  for (int c = 0; c < h->n_cells; ++c) {
    const double *L = f + 3 * h->layer[c];
    remainder[c] = rho[c] - (L[0] + L[1] * (h->h[c] - L[2]));
  }
  /* P at the levels: dP/dh = -|g| rho_ref(h), exact for the lines */
  h->pbase[0] = 0.0;
  for (int l = 0; l < nl; ++l) {
    const double *L = f + 3 * l;
    double lo = h->level[l] - L[2], hi = h->level[l + 1] - L[2];
    h->pbase[l + 1] = h->pbase[l] - h->g * (L[0] * (hi - lo) + 0.5 * L[1] * (hi * hi - lo * lo));
  }
}

void sl_hydrostatic_pressure(const sl_hydrostatic *h, int n, const double *xy, double *p) {
  int nl = h->n_layers;
  for (int i = 0; i < n; ++i) {
    double v = h->up[0] * xy[2 * i] + h->up[1] * xy[2 * i + 1];
    int lo = 0, hi = nl;
    while (hi - lo > 1) {
      int mid = (lo + hi) / 2;
      if (h->level[mid] <= v) lo = mid;
      else hi = mid;
    }
    const double *L = h->fit + 3 * lo;
    double a = h->level[lo] - L[2], b = v - L[2];
    p[i] = h->pbase[lo] - h->g * (L[0] * (b - a) + 0.5 * L[1] * (b * b - a * a));
  }
}
