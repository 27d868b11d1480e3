/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Generalized-Newtonian Navier–Stokes residual and Jacobian on Taylor–Hood
 * pairs (see flow.h for the equations and the frame conventions).
 *
 * Per batch of cells: pass 1 evaluates the iterate (velocity, gradient
 * tensor, pressure, shear rate) at every quadrature point; the density,
 * viscosity and body-force callbacks are then called once for the batch;
 * pass 2 builds each element's residual and matrix. */
#include "core/assembly/flow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/assembly/batch.h"
#include "core/fe/geometry.h"

#define MAX_COMP 3
#define MAX_VEL (MAX_COMP * SL_ELEMENT_MAX_BASIS)
#define MAX_ELEM_DOFS (MAX_VEL + 4)

/* A clone of the kernel for AVX2 where the compiler can make one (GCC on x86 with ifunc), chosen at load time. The
 * arithmetic is the same in every clone: no reassociation, no contraction (ISO C mode), so the sums are bitwise
 * those of the default build. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__gnu_linux__) && \
    !defined(__SANITIZE_ADDRESS__)
#define SL_AXI_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SL_AXI_CLONES
#endif

/* point_sums: EVAL_QB points a block, tables of EVAL_NQ points. */
#define EVAL_QB 8
#define EVAL_NQ SL_QUAD_MAX_POINTS
_Static_assert(EVAL_NQ % EVAL_QB == 0, "the points' tables hold whole blocks");

/* The iterate at one quadrature point, in the frame (e_0, e_1, e_2). */
typedef struct qp_state {
  double u[3];
  double G[3][3]; /* G[A][B] = d u_A / d x_B, hoop entries included */
  double p;
} qp_state;

/* Symmetric 3x3 tensor: 00, 11, 22, 01, 02, 12. */
typedef struct sym3 {
  double v[6];
} sym3;

static inline double sym_dot(const sym3 *a, const sym3 *b) {
  return a->v[0] * b->v[0] + a->v[1] * b->v[1] + a->v[2] * b->v[2] +
         2.0 * (a->v[3] * b->v[3] + a->v[4] * b->v[4] + a->v[5] * b->v[5]);
}

static inline sym3 sym_part(const double G[3][3]) {
  return (sym3){
      {G[0][0], G[1][1], G[2][2], 0.5 * (G[0][1] + G[1][0]), 0.5 * (G[0][2] + G[2][0]), 0.5 * (G[1][2] + G[2][1])}};
}

/* The axisymmetric fast path's point table: AXI_NB scalar basis functions a row (SL_ELEMENT_MAX_BASIS padded with
 * zeros to a multiple of 4), AXI_NPAIR packed pairs (i <= j) padded to a multiple of 8, AXI_NK mass coefficients. */
#define AXI_NB 12
#define AXI_NPAIR 48
#define AXI_NK 8 /* the c_AB but (z, theta), zero in every axisymmetric case (axi_point) */
_Static_assert(AXI_NB >= SL_ELEMENT_MAX_BASIS && AXI_NB % 4 == 0, "axi_pts rows hold every basis function");
_Static_assert(AXI_NPAIR >= SL_ELEMENT_MAX_BASIS * (SL_ELEMENT_MAX_BASIS + 1) / 2 && AXI_NPAIR % 8 == 0,
               "axi_sums reads the pairs in blocks of 8");

/* What axi_point keeps of each point of the cell, for axi_sums. */
typedef struct axi_pts {
  double g0[SL_QUAD_MAX_POINTS][AXI_NB], g1[SL_QUAD_MAX_POINTS][AXI_NB], h[SL_QUAD_MAX_POINTS][AXI_NB];
  double a[SL_QUAD_MAX_POINTS][AXI_NB];      /* wq rho u.grad(phi_j), 0 without convection */
  double phi[SL_QUAD_MAX_POINTS][AXI_NB];    /* phi_i */
  double wm[SL_QUAD_MAX_POINTS];             /* wq mu */
  double pp[SL_QUAD_MAX_POINTS][AXI_NPAIR];  /* phi_i phi_j, packed by rows of the upper triangle */
  double ck[SL_QUAD_MAX_POINTS][AXI_NK];     /* wq c_AB packed (axi_mass_index), zero beyond (blocks of 4) */
} axi_pts;

/* The sums of the axisymmetric fast path (axi_sums). */
typedef struct axi_acc {
  double X[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS], Y[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS],
      H[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS], S[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS],
      Z[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS], U[SL_ELEMENT_MAX_BASIS * SL_ELEMENT_MAX_BASIS];
  double M[AXI_NK][AXI_NPAIR]; /* packed upper triangles, in the order of ck */
} axi_acc;

/* The place of c_AB among the packed coefficients: row by row, (z, theta) left out (nc = 3: rr rz rt zr zz tr tz
 * tt; nc = 2: rr rz zr zz). */
static inline int axi_mass_index(int nc, int A, int B) { return nc == 3 ? A * 3 + B - (A * 3 + B > 5) : A * 2 + B; }

/* The cell geometry of a batch (sl_fe_values_reinit in batch_pass), kept for the element pass. */
typedef struct geo_cache {
  double *JxW;
  double (*grad)[SL_ELEMENT_MAX_BASIS][2]; /* space 0 (the velocity) */
} geo_cache;

typedef struct flow_work {
  sl_fe_values *fv; /* space 0: velocity, space 1: pressure */
  sl_asm_batch batch;
  qp_state *state; /* per batch point */
  double *rho, *mu, *force;
  int frame[MAX_COMP]; /* frame axis of each velocity component */
  double Ke[MAX_ELEM_DOFS * MAX_ELEM_DOFS], be[MAX_ELEM_DOFS];
  axi_acc acc; /* the axisymmetric fast path's sums over the cell's points */
  axi_pts pts; /* and its point table */
  geo_cache geo;
  int load_only; /* SL_FLOW_LOAD: the iterate and the viscosity are not needed */
  /* the reference basis functions at the points, transposed (point_sums): velocity, pressure; nq4 points, the
     quadrature's padded with zeros to whole blocks */
  double phiT[SL_ELEMENT_MAX_BASIS][SL_QUAD_MAX_POINTS], psiT[SL_ELEMENT_MAX_BASIS][SL_QUAD_MAX_POINTS];
  double gradT[2][SL_ELEMENT_MAX_BASIS][SL_QUAD_MAX_POINTS]; /* the cell's gradients (eval_state), zero padded */
  int nq4;
} flow_work;

static void work_free(flow_work *w) {
  if (!w) return;
  sl_fe_values_destroy(w->fv);
  sl_asm_batch_free(&w->batch);
  free(w->state), free(w->rho), free(w->mu), free(w->force);
  free(w->geo.JxW), free(w->geo.grad);
  free(w);
}

static int work_create(flow_work **out, const sl_th_space *th, const sl_flow_opts *o, sl_diag *d) {
  flow_work *w = calloc(1, sizeof *w);
  if (!w) return sl_diag_set(d, SL_ENOMEM, "flow: out of memory");
  const sl_element *spaces[2] = {th->vel->element, th->pres->element};
  /* Degree 5 integrates the planar Q2 terms with constant coefficients
   * exactly. The r weight and the hoop terms raise the degree: with 3 x 3
   * Gauss the axisymmetric manufactured solution had 4x the velocity error
   * of 4 x 4 Gauss at n = 8 and irregular observed orders (tests/fe). */
  int degree = o->quad_degree > 0 ? o->quad_degree : o->axisymmetric ? 7 : 5;
  if (th->mesh->cell_type == SL_CELL_TRI3 && degree > SL_TRI_MAX_DEGREE) degree = SL_TRI_MAX_DEGREE;
  int rc = sl_fe_values_create(&w->fv, th->mesh, 2, spaces, degree, o->axisymmetric, d);
  if (!rc) rc = sl_asm_batch_init(&w->batch, w->fv->quad.n, 1, d);
  if (!rc) {
    size_t cap = (size_t)SL_ASSEMBLY_BATCH_CELLS * w->fv->quad.n;
    w->state = malloc(cap * sizeof *w->state);
    w->rho = malloc(cap * sizeof *w->rho);
    w->mu = malloc(2 * cap * sizeof *w->mu);
    w->force = calloc(cap * th->n_comp, sizeof *w->force);
    w->geo.JxW = malloc(cap * sizeof *w->geo.JxW);
    w->geo.grad = malloc(cap * sizeof *w->geo.grad);
    if (!w->state || !w->rho || !w->mu || !w->force || !w->geo.JxW || !w->geo.grad)
      rc = sl_diag_set(d, SL_ENOMEM, "flow: out of memory");
  }
  if (rc) {
    work_free(w);
    return rc;
  }
  for (int a = 0; a < th->n_comp; ++a) w->frame[a] = a < th->mesh->dim ? a : 2;
  int nq = w->fv->quad.n;
  w->nq4 = (nq + EVAL_QB - 1) / EVAL_QB * EVAL_QB;
  for (int b = 0; b < SL_ELEMENT_MAX_BASIS; ++b)
    for (int q = 0; q < w->nq4; ++q) {
      w->phiT[b][q] = q < nq && b < th->vel->dofs_per_cell ? w->fv->phi[0][q][b] : 0.0;
      w->psiT[b][q] = q < nq && b < th->pres->dofs_per_cell ? w->fv->phi[1][q][b] : 0.0;
    }
  *out = w;
  return 0;
}

static int check_input(const sl_system *s, const sl_th_space *th, const sl_flow_opts *o, sl_diag *d) {
  int dim = th->mesh->dim;
  if (th->n_comp < dim || th->n_comp > dim + 1 || th->n_comp > MAX_COMP)
    return sl_diag_set(d, SL_EBADINPUT, "flow: %d velocity components on a %d-D mesh (%d or %d expected)", th->n_comp,
                       dim, dim, dim + 1);
  if (o->axisymmetric && dim != 2)
    return sl_diag_set(d, SL_EBADINPUT, "flow: an axisymmetric scene needs a 2-D (r, z) mesh");
  if (o->omega != 0.0 && dim != 2) return sl_diag_set(d, SL_EBADINPUT, "flow: a rotating frame needs a 2-D mesh");
  if (o->omega != 0.0 && o->axisymmetric && th->n_comp != 3)
    return sl_diag_set(d, SL_EBADINPUT, "flow: a rotating axisymmetric frame needs the swirl component");
  int32_t n_dofs = o->velocity_block ? th->p_offset : th->n_dofs;
  int per_cell = o->velocity_block ? th->n_comp * th->vel->dofs_per_cell : th->dofs_per_cell;
  if (s && (s->n_dofs != n_dofs || s->n_elem != th->mesh->n_cells || s->dofs_per_elem != per_cell))
    return sl_diag_set(d, SL_EBADINPUT, "flow: the system (%d dofs, %d x %d) was not built from this space",
                       (int)s->n_dofs, (int)s->n_elem, s->dofs_per_elem);
  return 0;
}

/* Sums over a cell's basis functions at its points, EVAL_QB points at a time: out[a][q] = sum_b val[a][b]
 * tab[b][q] (tab: a table transposed to points along its rows, nq4 of them, padded), each sum in the order of the
 * basis functions from zero as a loop over b at one point adds it (the same value to the bit), the EVAL_QB points'
 * sums side by side: short vectors instead of one chain of additions per point. */
SL_AXI_CLONES
static void point_sums(int na, int nb, int nq4, const double (*val)[SL_ELEMENT_MAX_BASIS], const double (*tab)[EVAL_NQ],
                       double (*out)[EVAL_NQ]) {
  for (int a = 0; a < na; ++a)
    for (int q0 = 0; q0 < nq4; q0 += EVAL_QB) {
      double s[EVAL_QB] = {0};
      for (int b = 0; b < nb; ++b) {
        double v = val[a][b];
        for (int k = 0; k < EVAL_QB; ++k) s[k] += v * tab[b][q0 + k];
      }
      for (int k = 0; k < EVAL_QB; ++k) out[a][q0 + k] = s[k];
    }
}

/* The iterate at the quadrature points of the current cell. */
static void eval_state(flow_work *w, const sl_th_space *th, const double *u, int axi, qp_state *st, double *shear) {
  const sl_fe_values *fv = w->fv;
  int c = fv->cell, nb = th->vel->dofs_per_cell, np = th->pres->dofs_per_cell, dim = th->mesh->dim, nc = th->n_comp;
  int nq = fv->quad.n, nq4 = w->nq4;
  const int32_t *vd = th->vel->cell_dofs + (size_t)c * nb, *pd = th->pres->cell_dofs + (size_t)c * np;
  double ul[MAX_COMP][SL_ELEMENT_MAX_BASIS]; /* the cell's velocity values, gathered once */
  for (int a = 0; a < nc; ++a) {
    const double *ua = u + sl_th_vel_dof(th, a, 0);
    for (int b = 0; b < nb; ++b) ul[a][b] = ua[vd[b]];
  }
  double pl[1][SL_ELEMENT_MAX_BASIS];
  for (int k = 0; k < np; ++k) pl[0][k] = u[th->p_offset + pd[k]];
  double(*gt)[SL_ELEMENT_MAX_BASIS][EVAL_NQ] = w->gradT; /* the cell's basis gradients, transposed */
  for (int q = 0; q < nq; ++q)
    for (int b = 0; b < nb; ++b) {
      gt[0][b][q] = fv->grad[0][q][b][0];
      if (dim > 1) gt[1][b][q] = fv->grad[0][q][b][1];
    }
  double U[MAX_COMP][EVAL_NQ], G0[MAX_COMP][EVAL_NQ], G1[MAX_COMP][EVAL_NQ], P[1][EVAL_NQ];
  point_sums(nc, nb, nq4, (const double(*)[SL_ELEMENT_MAX_BASIS])ul, (const double(*)[EVAL_NQ])w->phiT, U);
  point_sums(nc, nb, nq4, (const double(*)[SL_ELEMENT_MAX_BASIS])ul, (const double(*)[EVAL_NQ])gt[0], G0);
  if (dim > 1) point_sums(nc, nb, nq4, (const double(*)[SL_ELEMENT_MAX_BASIS])ul, (const double(*)[EVAL_NQ])gt[1], G1);
  point_sums(1, np, nq4, (const double(*)[SL_ELEMENT_MAX_BASIS])pl, (const double(*)[EVAL_NQ])w->psiT, P);
  for (int q = 0; q < nq; ++q) {
    qp_state *s = &st[q];
    memset(s, 0, sizeof *s);
    for (int a = 0; a < nc; ++a) {
      int A = w->frame[a];
      s->u[A] = U[a][q], s->G[A][0] = G0[a][q];
      if (dim > 1) s->G[A][1] = G1[a][q];
    }
    s->p = P[0][q];
    if (axi) {
      double r = fv->x[q][0];
      s->G[2][2] += s->u[0] / r;
      s->G[0][2] -= s->u[2] / r;
    }
    sym3 D = sym_part(s->G);
    shear[q] = sqrt(2.0 * sym_dot(&D, &D));
  }
}

/* T : grad(phi e_A) for the symmetric T (sym3 order) and the basis function
 * phi with gradient dphi at radius r: its gradient tensor has the row A
 * (grad phi) and, axisymmetric, the hoop entries (theta, theta) = phi / r
 * for A = r and (r, theta) = -phi / r for A = theta (see flow.h). */
static double stress_contraction(const sym3 *T, int A, double phi, const double *dphi, int dim, int axi, double r) {
  static const int at[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  double s = 0.0;
  for (int j = 0; j < dim; ++j) s += T->v[at[A][j]] * dphi[j];
  if (axi && A == 0) s += T->v[2] * phi / r;
  if (axi && A == 2) s -= T->v[4] * phi / r;
  return s;
}

/* One trial/test function phi_i e_a at a quadrature point. */
typedef struct basis_vec {
  sym3 D;       /* D(phi e_a) */
  double div;   /* div(phi e_a) */
  double Tu[3]; /* G(phi e_a) u: the advected part of the linearised convection */
  double phi;
  int A; /* frame axis */
} basis_vec;

/* The matrix of one quadrature point, planar with two components and no Coriolis term nor shear-rate dependent
 * viscosity, per pair of scalar basis functions (i, j) for the four component pairs (A, B) at once: with
 * D(phi e_A) = (e_A grad(phi)^T + grad(phi) e_A^T) / 2,
 *   2 mu D(phi_i e_A) : D(phi_j e_B) = mu (delta_AB grad(phi_i).grad(phi_j) + d_B phi_i d_A phi_j),
 * the mass rho mass_coef, the cell's sink K and Newton's rho G(u) all phi_i c_AB phi_j, and Picard's
 * convection rho phi_i (u.grad phi_j) delta_AB. The same terms as the general loop of element(), a quarter of
 * its operations (its per-(A, i) loops repeat each scalar product for every component pair). */
static void planar_matrix(double *Ke, int n, int nb, double wq, const double *phi, const double (*grad)[2],
                          const double *psi, int np, double rq, double mq, double mass_coef, const double *K,
                          const qp_state *s, int convection, int newton) {
  double c[2][2], a[SL_ELEMENT_MAX_BASIS];
  for (int A = 0; A < 2; ++A)
    for (int B = 0; B < 2; ++B)
      c[A][B] =
          (A == B ? rq * mass_coef : 0.0) + (K ? K[2 * A + B] : 0.0) + (convection && newton ? rq * s->G[A][B] : 0.0);
  for (int j = 0; j < nb; ++j) a[j] = convection ? wq * rq * (s->u[0] * grad[j][0] + s->u[1] * grad[j][1]) : 0.0;
  double wm = wq * mq;
  int nv = 2 * nb;
  for (int i = 0; i < nb; ++i) {
    double *r0 = Ke + (size_t)i * n, *r1 = Ke + (size_t)(nb + i) * n; /* the rows (0, i) and (1, i) */
    double wpi = wq * phi[i], gi0 = wm * grad[i][0], gi1 = wm * grad[i][1];
    for (int j = 0; j < nb; ++j) {
      double g0 = grad[j][0], g1 = grad[j][1], pp = wpi * phi[j];
      double diag = gi0 * g0 + gi1 * g1 + phi[i] * a[j];
      r0[j] += diag + gi0 * g0 + pp * c[0][0];      /* (0, i), (0, j): d_0 phi_i d_0 phi_j */
      r0[nb + j] += gi1 * g0 + pp * c[0][1];        /* (0, i), (1, j): d_1 phi_i d_0 phi_j */
      r1[j] += gi0 * g1 + pp * c[1][0];             /* (1, i), (0, j): d_0 phi_i d_1 phi_j */
      r1[nb + j] += diag + gi1 * g1 + pp * c[1][1]; /* (1, i), (1, j) */
    }
    for (int k = 0; k < np; ++k) { /* -psi_k div(phi_i e_A), and its transpose */
      double b0 = -wq * psi[k] * grad[i][0], b1 = -wq * psi[k] * grad[i][1];
      r0[nv + k] += b0, r1[nv + k] += b1;
      Ke[(size_t)(nv + k) * n + i] += b0, Ke[(size_t)(nv + k) * n + nb + i] += b1;
    }
  }
}

/* The axisymmetric matrix without a shear-rate dependent viscosity (frame axes r = 0, z = 1, theta = 2, the swirl
 * if nc = 3), per pair of scalar basis functions (i, j) for all component pairs at once. With g = grad(phi) in
 * (r, z), h = phi / r and the hoop entries of flow.h (grad(phi e_r) has (theta, theta) = h, grad(phi e_theta) has
 * (r, theta) = -h), the viscous term 2 mu D(phi_i e_A) : D(phi_j e_B) is
 *   (r, r): mu (g_i.g_j + d_r phi_i d_r phi_j + 2 h_i h_j),    (r, z): mu d_z phi_i d_r phi_j,
 *   (z, z): mu (g_i.g_j + d_z phi_i d_z phi_j),                (z, r): mu d_r phi_i d_z phi_j,
 *   (theta, theta): mu (g_i.g_j + h_i h_j - d_r phi_i h_j - h_i d_r phi_j),  zero between theta and (r, z)
 * (Batchelor 1967, Appendix 2, the rate of strain in cylindrical coordinates: e_rr = d_r u_r, e_thth = u_r / r,
 * e_rth = r d_r(u_th / r) / 2, axisymmetric); Picard's convection G(phi_j e_B) u tested with phi_i e_A is
 * delta_AB u.grad(phi_j) plus, from the hoop entries, (theta, r) u_theta h_j and (r, theta) -u_theta h_j
 * (Batchelor's (u.grad u)_r = ... - u_th^2 / r, (u.grad u)_th = ... + u_r u_th / r, linearised); mass, Coriolis
 * rho C, the cell's sink K (in-plane) and Newton's rho G(u) are phi_i c_AB phi_j. div(phi e_r) = d_r phi + h,
 * div(phi e_z) = d_z phi, div(phi e_theta) = 0. The same terms as the general loop of element().
 *
 * Every block is a combination of a few scalar matrices summed over the cell's points: the symmetric
 * X = sum mu w d_r phi_i d_r phi_j, Y (d_z, d_z), H (h, h), S (d_r phi_i h_j + h_i d_r phi_j) and the
 * c_AB-weighted masses M_AB (upper triangles only), the unsymmetric Z (d_z phi_i d_r phi_j) and the convection
 * U (phi_i u.grad phi_j): (r, r) = 2X + Y + 2H + U + M_rr, (z, z) = X + 2Y + U + M_zz, (theta, theta) = X + Y +
 * H - S + U + M_thth, (r, z) = Z + M_rz, (z, r) = Z^T + M_zr, the swirl's other pairs M_AB alone (axi_accumulate
 * per point, axi_finish per cell): 750 products a point where the row updates per point took 1800. */

/* One point of the cell into the point table (axi_sums adds them up); the pressure columns and rows (np of them)
 * straight into Ke. */
static void axi_point(axi_pts *restrict P, int q, double *Ke, int n, int nc, int nb, double wq, double r,
                      const double *phi, const double (*grad)[2], const double *psi, int np, double rq, double mq,
                      double mass_coef, const double *K, const double C[3][3], const qp_state *s, int convection,
                      int newton) {
  double c[3][3], *restrict h = P->h[q];
  double rinv = 1.0 / r;
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B)
      c[A][B] = (A == B ? rq * mass_coef : 0.0) + (K && A < 2 && B < 2 ? K[2 * A + B] : 0.0) + rq * C[A][B] +
                (convection && newton ? rq * s->G[A][B] : 0.0);
  if (convection) c[2][0] += rq * s->u[2] * rinv, c[0][2] -= rq * s->u[2] * rinv;
  for (int j = 0; j < nb; ++j) {
    P->a[q][j] = convection ? wq * rq * (s->u[0] * grad[j][0] + s->u[1] * grad[j][1]) : 0.0;
    h[j] = phi[j] * rinv, P->g0[q][j] = grad[j][0], P->g1[q][j] = grad[j][1], P->phi[q][j] = phi[j];
  }
  P->wm[q] = wq * mq;
  /* c_z,theta is zero: no Coriolis term there (the frame's C couples r and theta), no hoop entry of Picard's
     convection (those are (r, theta) and (theta, r)), the sink in-plane, and G_z,theta = d u_z / d theta = 0 */
  for (int A = 0; A < nc; ++A)
    for (int B = 0; B < nc; ++B)
      if (!(A == 1 && B == 2)) P->ck[q][axi_mass_index(nc, A, B)] = wq * c[A][B];
  int npair = 0, nv = nc * nb;
  for (int i = 0; i < nb; ++i)
    for (int j = i; j < nb; ++j) P->pp[q][npair++] = phi[i] * phi[j];
  for (int i = 0; i < nb; ++i)
    for (int k = 0; k < np; ++k) { /* -psi_k div(phi_i e_A), and its transpose; div(phi e_theta) = 0 */
      double b0 = -wq * psi[k] * (grad[i][0] + h[i]), b1 = -wq * psi[k] * grad[i][1];
      Ke[(size_t)i * n + nv + k] += b0, Ke[(size_t)(nb + i) * n + nv + k] += b1;
      Ke[(size_t)(nv + k) * n + i] += b0, Ke[(size_t)(nv + k) * n + nb + i] += b1;
    }
}

/* Rows [i0, i1) of the symmetric sums X, Y, H and S from column j0 on (j0 <= i0 a multiple of 4, a constant where
 * inlined): the upper triangles that axi_finish reads, and the columns of their block below it. */
static inline void axi_sym_rows(axi_acc *restrict acc, const axi_pts *restrict P, int nq, int nb, int i0, int i1,
                                int j0) {
  for (int i = i0; i < i1 && i < nb; ++i) {
    double x[AXI_NB] = {0}, y[AXI_NB] = {0}, hh[AXI_NB] = {0}, sv[AXI_NB] = {0};
    for (int q = 0; q < nq; ++q) {
      double wm = P->wm[q], gi0 = wm * P->g0[q][i], gi1 = wm * P->g1[q][i], hi = wm * P->h[q][i];
      for (int j = j0; j < AXI_NB; ++j) {
        x[j] += gi0 * P->g0[q][j], y[j] += gi1 * P->g1[q][j], hh[j] += hi * P->h[q][j];
        sv[j] += gi0 * P->h[q][j] + hi * P->g0[q][j];
      }
    }
    for (int j = j0; j < nb; ++j)
      acc->X[i * nb + j] = x[j], acc->Y[i * nb + j] = y[j], acc->H[i * nb + j] = hh[j], acc->S[i * nb + j] = sv[j];
  }
}

/* The sums of axi_acc over the cell's nq points, point by point in the order of the points as the per-point
 * updates added them, each sum held in registers over the points and stored once: X, Y, H, S (the upper
 * triangles, rows in blocks of 4 from their block's diagonal on), Z, U (full), and the masses M_k = sum_q ck_k(q)
 * pp(q) in blocks of 8 pairs and 4 coefficients. */
SL_AXI_CLONES
static void axi_sums(axi_acc *restrict acc, const axi_pts *restrict P, int nq, int nc, int nb) {
  _Static_assert(AXI_NB == 12, "axi_sums takes the rows in three blocks of 4");
  axi_sym_rows(acc, P, nq, nb, 0, 4, 0);
  axi_sym_rows(acc, P, nq, nb, 4, 8, 4);
  axi_sym_rows(acc, P, nq, nb, 8, 12, 8);
  for (int i = 0; i < nb; ++i) {
    double z[AXI_NB] = {0}, u[AXI_NB] = {0};
    for (int q = 0; q < nq; ++q) {
      double gi1 = P->wm[q] * P->g1[q][i], pi = P->phi[q][i];
      for (int j = 0; j < AXI_NB; ++j) z[j] += gi1 * P->g0[q][j], u[j] += pi * P->a[q][j];
    }
    for (int j = 0; j < nb; ++j) acc->Z[i * nb + j] = z[j], acc->U[i * nb + j] = u[j];
  }
  int npair = nb * (nb + 1) / 2, nk = nc == 3 ? 8 : 4;
  for (int e0 = 0; e0 < npair; e0 += 8)
    for (int k0 = 0; k0 < nk; k0 += 4) {
      double m0[8] = {0}, m1[8] = {0}, m2[8] = {0}, m3[8] = {0};
      for (int q = 0; q < nq; ++q) {
        const double *pp = P->pp[q] + e0, c0 = P->ck[q][k0], c1 = P->ck[q][k0 + 1], c2 = P->ck[q][k0 + 2],
                     c3 = P->ck[q][k0 + 3];
        for (int e = 0; e < 8; ++e) m0[e] += c0 * pp[e], m1[e] += c1 * pp[e], m2[e] += c2 * pp[e], m3[e] += c3 * pp[e];
      }
      for (int e = 0; e < 8; ++e)
        acc->M[k0][e0 + e] = m0[e], acc->M[k0 + 1][e0 + e] = m1[e], acc->M[k0 + 2][e0 + e] = m2[e],
                        acc->M[k0 + 3][e0 + e] = m3[e];
    }
}

/* The cell's velocity blocks from the sums (axi_acc), added to Ke. */
static void axi_finish(const axi_acc *acc, double *Ke, int n, int nc, int nb) {
  for (int i = 0; i < nb; ++i) {
    double *r0 = Ke + (size_t)i * n, *r1 = Ke + (size_t)(nb + i) * n, *r2 = nc == 3 ? Ke + (size_t)(2 * nb + i) * n : NULL;
    for (int j = 0; j < nb; ++j) {
      int lo = i <= j ? i : j, hi = i <= j ? j : i;
      int ij = lo * nb + hi;                              /* the upper triangle's entry of a symmetric sum */
      int e = lo * nb - lo * (lo - 1) / 2 + (hi - lo); /* the same, packed (the masses) */
      double X = acc->X[ij], Y = acc->Y[ij], H = acc->H[ij], U = acc->U[i * nb + j];
      r0[j] += 2.0 * X + Y + 2.0 * H + U + acc->M[0][e];
      r0[nb + j] += acc->Z[i * nb + j] + acc->M[1][e];
      r1[j] += acc->Z[j * nb + i] + acc->M[axi_mass_index(nc, 1, 0)][e];
      r1[nb + j] += X + 2.0 * Y + U + acc->M[axi_mass_index(nc, 1, 1)][e];
      if (nc == 3) { /* (z, theta): zero (axi_point) */
        r0[2 * nb + j] += acc->M[axi_mass_index(3, 0, 2)][e];
        r2[j] += acc->M[axi_mass_index(3, 2, 0)][e], r2[nb + j] += acc->M[axi_mass_index(3, 2, 1)][e];
        r2[2 * nb + j] += X + Y + H - acc->S[ij] + U + acc->M[axi_mass_index(3, 2, 2)][e];
      }
    }
  }
}

static void element(flow_work *w, const sl_th_space *th, const sl_flow_opts *o, sl_flow_linearisation lin,
                    const qp_state *st, const double *shear, const double *rho, const double *mu, const double *force,
                    const double (*X)[2], const double *JxW, const double (*GR)[SL_ELEMENT_MAX_BASIS][2]) {
  const sl_fe_values *fv = w->fv; /* the reference tabulation; the cell's geometry is X, JxW and GR */
  int c = fv->cell, nc = th->n_comp, nb = th->vel->dofs_per_cell, np = th->pres->dofs_per_cell;
  /* npc: the pressure dofs the element's rows and columns hold (none for the velocity block alone) */
  int npc = o->velocity_block ? 0 : np;
  int dim = th->mesh->dim, nv = nc * nb, n = nv + npc, axi = o->axisymmetric, planar2 = !axi && nc == 2 && dim == 2;
  const int32_t *vd = th->vel->cell_dofs + (size_t)c * nb;
  int matrix = lin == SL_FLOW_NEWTON || lin == SL_FLOW_PICARD, newton = lin == SL_FLOW_NEWTON;
  if (matrix) memset(w->Ke, 0, (size_t)n * n * sizeof *w->Ke);
  memset(w->be, 0, (size_t)n * sizeof *w->be);
  /* Coriolis 2 Omega x u = C u in the frame (Omega along e_2 planar, along the axis e_1 = z axisymmetric). */
  double C[3][3] = {{0}};
  const double *K = o->cell_drag ? o->cell_drag + 4 * (size_t)c : NULL;
  if (o->omega != 0.0) {
    if (axi) C[0][2] = -2.0 * o->omega, C[2][0] = 2.0 * o->omega;
    else C[0][1] = -2.0 * o->omega, C[1][0] = 2.0 * o->omega;
  }
  double hl[MAX_COMP][SL_ELEMENT_MAX_BASIS]; /* the cell's history values, gathered once */
  if (o->history)
    for (int a = 0; a < nc; ++a) {
      const double *ha = o->history + sl_th_vel_dof(th, a, 0);
      for (int b = 0; b < nb; ++b) hl[a][b] = ha[vd[b]];
    }
  double hq[MAX_COMP][EVAL_NQ]; /* the history at the points */
  if (o->history)
    point_sums(nc, nb, w->nq4, (const double(*)[SL_ELEMENT_MAX_BASIS])hl, (const double(*)[EVAL_NQ])w->phiT, hq);
  basis_vec bv[MAX_VEL];
  int acc_used = 0;
  unsigned char fast_at[SL_QUAD_MAX_POINTS] = {0}; /* the points in the fast path's table */
  for (int q = 0; q < fv->quad.n; ++q) {
    const qp_state *s = &st[q];
    double wq = JxW[q], r = X[q][0], rq = rho[q];
    /* du/dt ~ mass_coef u + history, in the frame. */
    double hist[3] = {0, 0, 0};
    if (o->history)
      for (int a = 0; a < nc; ++a) hist[w->frame[a]] = hq[a][q];
    /* Body force in the frame, centrifugal included. */
    double f[3] = {0, 0, 0};
    for (int a = 0; a < nc; ++a) f[w->frame[a]] += force[q * nc + a];
    if (o->omega != 0.0) {
      double w2 = (rq - o->centrifugal_density) * o->omega * o->omega;
      if (axi) f[0] += w2 * r;
      else f[0] += w2 * (X[q][0] - o->rotation_centre[0]), f[1] += w2 * (X[q][1] - o->rotation_centre[1]);
    }
    if (o->extra_stress) { /* -div T, weakly + int T : grad(v); T interpolated in the pressure space */
      sym3 T = {{0}};
      const int32_t *pd = th->pres->cell_dofs + (size_t)c * np;
      for (int k = 0; k < np; ++k)
        for (int e = 0; e < 6; ++e) T.v[e] += o->extra_stress[6 * (size_t)pd[k] + e] * fv->phi[1][q][k];
      for (int a = 0; a < nc; ++a)
        for (int i = 0; i < nb; ++i)
          w->be[a * nb + i] += wq * stress_contraction(&T, w->frame[a], fv->phi[0][q][i], GR[q][i], dim, axi, r);
    }
    if (lin == SL_FLOW_LOAD) { /* the u-independent part of the momentum residual only */
      for (int a = 0; a < nc; ++a) {
        int A = w->frame[a];
        double g = wq * (rq * hist[A] - f[A]);
        for (int i = 0; i < nb; ++i) w->be[a * nb + i] -= g * fv->phi[0][q][i];
      }
      continue;
    }
    double mq = mu[2 * q], dmq = mu[2 * q + 1], gam = shear[q];
    sym3 Du = sym_part(s->G);
    double divu = s->G[0][0] + s->G[1][1] + s->G[2][2];
    /* Strong-form momentum terms tested against phi_i e_A: rho (du/dt + G u + C u) - f. */
    double m[3];
    for (int A = 0; A < 3; ++A) {
      double conv = 0.0, cor = 0.0;
      for (int B = 0; B < 3; ++B) conv += s->G[A][B] * s->u[B], cor += C[A][B] * s->u[B];
      m[A] = rq * (o->mass_coef * s->u[A] + hist[A] + (o->convection ? conv : 0.0) + cor) - f[A];
    }
    if (K) /* the cell's momentum sink K u (in-plane axes) */
      for (int A = 0; A < dim; ++A)
        for (int B = 0; B < dim; ++B) m[A] += K[2 * A + B] * s->u[B];
    /* The fast paths below (planar_matrix, axi_matrix) take the matrix of this point from the scalar basis
       functions; the general loop needs the basis vectors' advected parts Tu. */
    int gen_newtonian = newton && dmq != 0.0 && gam > 0.0;
    int fast = matrix && !gen_newtonian && w->frame[0] == 0 && w->frame[1] == 1 &&
               ((planar2 && o->omega == 0.0) || (axi && (nc == 2 || w->frame[2] == 2)));
    /* The residual of the fast paths' cases from the scalar basis functions (the same arithmetic as the basis
       vectors' below: D(phi e_r) has 00 = d_r phi, 11 = 0, 22 = phi / r, 01 = d_z phi / 2; D(phi e_z) 11 = d_z phi,
       01 = d_r phi / 2; D(phi e_theta) 02 = (d_r phi - phi / r) / 2, 12 = d_z phi / 2, div 0). */
    int fast_res = w->frame[0] == 0 && w->frame[1] == 1 && (axi ? nc == 2 || w->frame[2] == 2 : planar2);
    if (fast_res) {
      const double *ph = fv->phi[0][q];
      const double(*gr)[2] = (const double(*)[2])GR[q];
      double hv[SL_ELEMENT_MAX_BASIS]; /* phi / r, in a loop of its own (the divisions vectorised) */
      for (int i = 0; i < nb; ++i) hv[i] = axi ? ph[i] / r : 0.0;
      for (int i = 0; i < nb; ++i) {
        double g0 = gr[i][0], g1 = gr[i][1], hh = hv[i];
        double sd0 = axi ? (Du.v[0] * g0 + Du.v[2] * hh) + 2.0 * (Du.v[3] * (0.5 * g1))
                         : Du.v[0] * g0 + 2.0 * (Du.v[3] * (0.5 * g1));
        double sd1 = Du.v[1] * g1 + 2.0 * (Du.v[3] * (0.5 * g0));
        w->be[i] -= wq * (m[0] * ph[i] + 2.0 * mq * sd0 - s->p * (axi ? g0 + hh : g0));
        w->be[nb + i] -= wq * (m[1] * ph[i] + 2.0 * mq * sd1 - s->p * g1);
        if (nc == 3) {
          double sd2 = 2.0 * (Du.v[4] * (0.5 * (-hh + g0)) + Du.v[5] * (0.5 * g1));
          w->be[2 * nb + i] -= wq * (m[2] * ph[i] + 2.0 * mq * sd2);
        }
      }
    }
    /* The basis vectors of this point: for the general loop and its residual. */
    if (!fast_res || (matrix && !fast)) {
      for (int a = 0; a < nc; ++a)
        for (int i = 0; i < nb; ++i) {
          basis_vec *v = &bv[a * nb + i];
          double T[3][3] = {{0}};
          int A = w->frame[a];
          double ph = fv->phi[0][q][i];
          for (int j = 0; j < dim; ++j) T[A][j] = GR[q][i][j];
          if (axi && A == 0) T[2][2] = ph / r;
          if (axi && A == 2) T[0][2] = -ph / r;
          v->D = sym_part(T);
          v->div = T[0][0] + T[1][1] + T[2][2];
          if (o->convection && matrix && !fast)
            for (int B = 0; B < 3; ++B) v->Tu[B] = T[B][0] * s->u[0] + T[B][1] * s->u[1] + T[B][2] * s->u[2];
          v->phi = ph;
          v->A = A;
        }
    }
    if (!fast_res) /* Residual. */
      for (int k = 0; k < nv; ++k) {
        const basis_vec *v = &bv[k];
        w->be[k] -= wq * (m[v->A] * v->phi + 2.0 * mq * sym_dot(&Du, &v->D) - s->p * v->div);
      }
    const double *psi = fv->phi[1][q];
    for (int k = 0; k < npc; ++k) w->be[nv + k] -= wq * (-psi[k] * divu);
    if (!matrix) continue;
    /* The generalized-Newtonian part of the Jacobian: 4 mu' gamma (Dhat:D(v)) (Dhat:D(dv)), Dhat = D(u)/gamma. */
    double s_ia[MAX_VEL];
    double visc2 = 0.0;
    if (gen_newtonian) {
      visc2 = 4.0 * dmq * gam;
      for (int k = 0; k < nv; ++k) s_ia[k] = sym_dot(&Du, &bv[k].D) / gam;
    }
    if (fast && planar2) {
      planar_matrix(w->Ke, n, nb, wq, fv->phi[0][q], (const double(*)[2])GR[q], psi, npc, rq, mq, o->mass_coef, K, s,
                    o->convection, newton);
      continue;
    }
    if (fast) {
      axi_point(&w->pts, q, w->Ke, n, nc, nb, wq, r, fv->phi[0][q], (const double(*)[2])GR[q], psi, npc, rq, mq,
                o->mass_coef, K, (const double(*)[3])C, s, o->convection, newton);
      acc_used = 1, fast_at[q] = 1;
      continue;
    }
    double rm = rq * o->mass_coef, w2mu = 2.0 * wq * mq;
    for (int ki = 0; ki < nv; ++ki) {
      const basis_vec *vi = &bv[ki];
      double *row = w->Ke + (size_t)ki * n;
      double wphi = wq * vi->phi, wsi = visc2 != 0.0 ? wq * visc2 * s_ia[ki] : 0.0;
      /* The symmetric part (viscous, generalized-Newtonian, mass), once per pair and mirrored. Planar with two
         components, D(phi e_a) has only its 00, 11 and 01 entries. */
      for (int kj = ki; kj < nv; ++kj) {
        const basis_vec *vj = &bv[kj];
        double dd = planar2 ? vi->D.v[0] * vj->D.v[0] + vi->D.v[1] * vj->D.v[1] + 2.0 * vi->D.v[3] * vj->D.v[3]
                            : sym_dot(&vi->D, &vj->D);
        double val = w2mu * dd;
        if (wsi != 0.0) val += wsi * s_ia[kj];
        if (vi->A == vj->A) val += wphi * rm * vj->phi; /* rho mass_coef, tested with phi_i e_A */
        row[kj] += val;
        if (kj != ki) w->Ke[(size_t)kj * n + ki] += val;
      }
      if (o->omega != 0.0) /* rho C, antisymmetric */
        for (int kj = 0; kj < nv; ++kj) row[kj] += wphi * rq * C[vi->A][bv[kj].A] * bv[kj].phi;
      if (K && vi->A < dim) /* the cell's momentum sink K (in-plane axes; not symmetric) */
        for (int kj = 0; kj < nv; ++kj)
          if (bv[kj].A < dim) row[kj] += wphi * K[2 * vi->A + bv[kj].A] * bv[kj].phi;
      for (int k = 0; k < npc; ++k) {
        double bval = -wq * psi[k] * vi->div;
        row[nv + k] += bval;
        w->Ke[(size_t)(nv + k) * n + ki] += bval;
      }
    }
    if (o->convection) {
      /* Picard (Oseen): rho G(dv) u, i.e. u.grad of the new velocity; Newton adds rho G(u) dv. */
      for (int ki = 0; ki < nv; ++ki) {
        const basis_vec *vi = &bv[ki];
        double *row = w->Ke + (size_t)ki * n;
        double wr = wq * rq * vi->phi;
        for (int kj = 0; kj < nv; ++kj) {
          const basis_vec *vj = &bv[kj];
          double val = vj->Tu[vi->A];
          if (newton) val += s->G[vi->A][vj->A] * vj->phi;
          row[kj] += wr * val;
        }
      }
    }
  }
  if (acc_used) {
    /* a point of the general loop (a shear-rate dependent viscosity there) adds zeros to the sums, as if skipped */
    for (int q = 0; q < fv->quad.n; ++q)
      if (!fast_at[q]) {
        axi_pts *P = &w->pts;
        P->wm[q] = 0.0;
        memset(P->phi[q], 0, sizeof P->phi[q]), memset(P->a[q], 0, sizeof P->a[q]);
        memset(P->g0[q], 0, sizeof P->g0[q]), memset(P->g1[q], 0, sizeof P->g1[q]), memset(P->h[q], 0, sizeof P->h[q]);
        memset(P->ck[q], 0, sizeof P->ck[q]), memset(P->pp[q], 0, sizeof P->pp[q]);
      }
    axi_sums(&w->acc, &w->pts, fv->quad.n, nc, nb);
    axi_finish(&w->acc, w->Ke, n, nc, nb);
  }
}

/* Evaluates the iterate over a batch of cells and calls the coefficients. */
static int batch_pass(flow_work *w, const sl_th_space *th, const double *u, const sl_flow_opts *o, int first, int n,
                      sl_diag *d) {
  sl_asm_batch *b = &w->batch;
  b->first = first, b->n_cells = n;
  int nq = b->nq, rc = 0;
  for (int i = 0; i < n && !rc; ++i) {
    size_t at = (size_t)i * nq;
    for (int q = 0; q < nq; ++q) b->cell[at + q] = first + i;
    if (w->load_only) { /* the points alone, for the coefficients */
      sl_fe_values_map_points(w->fv, first + i, b->x + at);
      memset(b->shear_rate + at, 0, (size_t)nq * sizeof *b->shear_rate);
      continue;
    }
    if ((rc = sl_fe_values_reinit(w->fv, first + i, d))) break;
    memcpy(b->x + at, w->fv->x, (size_t)nq * sizeof *b->x);
    /* the geometry the element pass needs (the points are b->x), kept so that it does not compute it again */
    memcpy(w->geo.JxW + at, w->fv->JxW, (size_t)nq * sizeof *w->geo.JxW);
    memcpy(w->geo.grad + at, w->fv->grad[0], (size_t)nq * sizeof *w->geo.grad);
    eval_state(w, th, u, o->axisymmetric, w->state + at, b->shear_rate + at);
  }
  if (rc) return rc;
  sl_qp_batch view = sl_asm_batch_view(b);
  if ((rc = sl_asm_coef_eval(&o->density, "density", &view, 1, w->rho, d))) return rc;
  for (int k = 0; k < view.n; ++k)
    if (!(w->rho[k] > 0.0))
      return sl_diag_set(d, SL_EFAILED, "flow: density %g at (%g, %g) in cell %d is not positive", w->rho[k],
                         view.x[k][0], view.x[k][1], (int)view.cell[k]);
  sl_coef visc = {o->viscosity, o->viscosity_user, 0.0};
  if (w->load_only) {
    for (int k = 0; k < view.n; ++k) w->mu[2 * k] = 1.0, w->mu[2 * k + 1] = 0.0; /* not used */
  } else if (o->viscosity) {
    if ((rc = sl_asm_coef_eval(&visc, "viscosity", &view, 2, w->mu, d))) return rc;
  } else {
    for (int k = 0; k < view.n; ++k) w->mu[2 * k] = o->viscosity_value, w->mu[2 * k + 1] = 0.0;
  }
  for (int k = 0; k < view.n; ++k)
    if (!(w->mu[2 * k] > 0.0))
      return sl_diag_set(d, SL_EFAILED, "flow: viscosity %g at (%g, %g) in cell %d (shear rate %g) is not positive",
                         w->mu[2 * k], view.x[k][0], view.x[k][1], (int)view.cell[k], view.shear_rate[k]);
  if (o->body_force) {
    sl_coef force = {o->body_force, o->body_force_user, 0.0};
    if ((rc = sl_asm_coef_eval(&force, "body force", &view, th->n_comp, w->force, d))) return rc;
  }
  return 0;
}

/* What to do with each batch once the iterate and the coefficients are known. */
typedef int (*batch_fn)(flow_work *w, const sl_th_space *th, const sl_flow_opts *o, int first, int n, void *user,
                        sl_diag *d);

/* Runs fn over the mesh, batch by batch (see batch_pass). */
static int for_each_batch(const sl_th_space *th, const double *u, const sl_flow_opts *o, const sl_system *s,
                          int load_only, batch_fn fn, void *user, sl_diag *d) {
  int rc = check_input(s, th, o, d);
  if (rc) return rc;
  flow_work *w = NULL;
  if ((rc = work_create(&w, th, o, d))) return rc;
  w->load_only = load_only;
  /* a system assembled on several ranks: this rank's cells only (their closures alone are called here) */
  int32_t c0 = 0, c1 = th->mesh->n_cells;
  for (int32_t at = 0; at < th->mesh->n_cells && c0 < c1 && !rc; at = c1) {
    if (s) sl_system_next_run(s, at, &c0, &c1); /* the next run of this rank's cells */
    for (int first = c0; first < c1 && !rc; first += SL_ASSEMBLY_BATCH_CELLS) {
      int n = c1 - first < SL_ASSEMBLY_BATCH_CELLS ? c1 - first : SL_ASSEMBLY_BATCH_CELLS;
      if (!(rc = batch_pass(w, th, u, o, first, n, d))) rc = fn(w, th, o, first, n, user, d);
    }
  }
  work_free(w);
  return rc;
}

typedef struct assemble_ctx {
  sl_system *s;
  sl_flow_linearisation lin;
} assemble_ctx;

static int assemble_batch(flow_work *w, const sl_th_space *th, const sl_flow_opts *o, int first, int n, void *user,
                          sl_diag *d) {
  const assemble_ctx *a = user;
  int nq = w->fv->quad.n, rc = 0;
  for (int i = 0; i < n && !rc; ++i) {
    size_t at = (size_t)i * nq;
    sl_fe_values *fv = w->fv;
    const double(*X)[2] = w->batch.x + at, *JxW = w->geo.JxW + at;
    const double(*GR)[SL_ELEMENT_MAX_BASIS][2] = (const double(*)[SL_ELEMENT_MAX_BASIS][2])(w->geo.grad + at);
    if (w->load_only) { /* the load pass needs the basis gradients for the extra stress only */
      rc = o->extra_stress ? sl_fe_values_reinit(fv, first + i, d) : sl_fe_values_reinit_measure(fv, first + i, d);
      if (rc) break;
      X = (const double(*)[2])fv->x, JxW = fv->JxW, GR = (const double(*)[SL_ELEMENT_MAX_BASIS][2])fv->grad[0];
    } else { /* the geometry batch_pass computed */
      fv->cell = first + i;
    }
    element(w, th, o, a->lin, w->state + at, w->batch.shear_rate + at, w->rho + at, w->mu + 2 * at,
            w->force + at * th->n_comp, X, JxW, GR);
    int matrix = a->lin == SL_FLOW_NEWTON || a->lin == SL_FLOW_PICARD;
    rc = sl_system_add_element(a->s, first + i, matrix ? w->Ke : NULL, w->be, d);
  }
  return rc;
}

int sl_assemble_flow(sl_system *s, const sl_th_space *th, const double *u, const sl_flow_opts *o,
                     sl_flow_linearisation lin, sl_diag *d) {
  assemble_ctx a = {s, lin};
  return for_each_batch(th, u, o, s, lin == SL_FLOW_LOAD, assemble_batch, &a, d);
}

int sl_flow_check_geometry(const sl_th_space *th, const sl_flow_opts *o, sl_diag *d) {
  return check_input(NULL, th, o, d);
}

typedef struct diag_ctx {
  double yield_stress;
  double *shear_rate, *viscosity, *yielded;
} diag_ctx;

static int diagnostics_batch(flow_work *w, const sl_th_space *th, const sl_flow_opts *o, int first, int n, void *user,
                             sl_diag *d) {
  const diag_ctx *c = user;
  int nq = w->fv->quad.n;
  (void)th, (void)o, (void)d;
  for (int i = 0; i < n; ++i) {
    double sg = 0.0, sm = 0.0, sy = 0.0;
    for (int q = 0; q < nq; ++q) {
      size_t k = (size_t)i * nq + q;
      double g = w->batch.shear_rate[k], mu = w->mu[2 * k];
      sg += g, sm += mu, sy += mu * g > c->yield_stress ? 1.0 : 0.0;
    }
    if (c->shear_rate) c->shear_rate[first + i] = sg / nq;
    if (c->viscosity) c->viscosity[first + i] = sm / nq;
    if (c->yielded) c->yielded[first + i] = sy / nq;
  }
  return 0;
}

int sl_flow_cell_diagnostics(const sl_th_space *th, const double *u, const sl_flow_opts *o, double yield_stress,
                             double *shear_rate, double *viscosity, double *yielded, sl_diag *d) {
  diag_ctx c = {yield_stress, shear_rate, viscosity, yielded};
  return for_each_batch(th, u, o, NULL, 0, diagnostics_batch, &c, d);
}
