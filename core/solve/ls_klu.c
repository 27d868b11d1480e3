/* SPDX-License-Identifier: GPL-2.0-or-later */
/* KLU backend: LU with BTF and a fill-reducing ordering, and klu_refactor,
 * which reuses the previous pivot order and is much cheaper than a fresh
 * factorisation. As in SUNDIALS' sunlinsol_klu, a refactorisation whose
 * condition estimate has degraded is thrown away and redone from scratch.
 *
 * Ordering: AMD (KLU's default) below KLU_METIS_MIN_UNKNOWNS, METIS nested
 * dissection of the pattern of A + A^T (through CHOLMOD) from there up.
 * Nested dissection suits the 2-D meshes the solver sees (George 1973, SIAM
 * J. Numer. Anal. 10:345: O(n log n) fill on a grid). Measured on the Stokes
 * cavity's Q2/Q1 saddle point (bench_cavity_work_precision, CPU of the whole
 * steady solve): equal at 21 k unknowns, -6 % at 37.5 k, -36 % at 84 k and
 * -35 % at 149 k (24.9 s -> 16.2 s); at 2.5 k-9.5 k the METIS call costs more
 * than it saves. Should METIS fail (a CHOLMOD built without it), AMD. */
#include <cholmod.h>
#include <float.h>
#include <klu.h>
#include <math.h>
#include <stdlib.h>

#include "core/solve/linsolve.h"

_Static_assert(sizeof(int) == sizeof(int32_t), "the klu_ interface takes int indices");

#define STR_(x) #x
#define STR(x) STR_(x)

/* The factors in single precision for a preconditioner's solves (SL_LINSOLVE_ROLE_PRECONDITIONER): KLU's
 * L U + F = R^{-1} S(P, Q) of S = A^T (klu_extract; R = diag(Rs) in the pivot order, F the off-diagonal blocks of
 * the block triangular form), L without its unit diagonal and U without its diagonal (kept inverted, in double)
 * stored as float with int indices, 8 bytes an entry against KLU's 12: the solves stream the factors from memory
 * (0.74 M entries on spinup's velocity blocks), so they cost what the bytes cost. The sums run in double; the
 * factors' rounding, 2^-24 relative, perturbs the preconditioned operator by that much times the factors'
 * growth, which a Krylov iteration on the exact operator absorbs (FGMRES admits any preconditioner; Saad 2003,
 * Iterative Methods for Sparse Linear Systems, 2nd ed., section 9.4.1). */
typedef struct klu_single {
  int n, nblocks;
  int *P, *Q, *R;
  double *Rs, *Uinv, *w;
  int *Lp, *Li, *Up, *Ui, *Fp, *Fi;
  float *Lx, *Ux, *Fx;
} klu_single;

typedef struct klu_state {
  klu_common c;
  klu_symbolic *sym;
  klu_numeric *num;
  int ordering; /* SL_ORDERING_* */
  int role;     /* SL_LINSOLVE_ROLE_*: PRECONDITIONER keeps `single` */
  klu_single single;
  int single_ok; /* `single` holds the last numeric factorisation */
} klu_state;

static const char *klu_status_text(int s) {
  switch (s) {
    case KLU_OK:
      return "ok";
    case KLU_SINGULAR:
      return "matrix is singular";
    case KLU_OUT_OF_MEMORY:
      return "out of memory";
    case KLU_INVALID:
      return "invalid input";
    case KLU_TOO_LARGE:
      return "problem too large";
    default:
      return "unknown status";
  }
}

static int klu_fail(const klu_state *s, const char *stage, int32_t n, sl_diag *d) {
  return sl_diag_set(d, SL_EFAILED, "klu: %s (status %d) in the %s of a %d x %d matrix", klu_status_text(s->c.status),
                     s->c.status, stage, (int)n, (int)n);
}

enum { KLU_METIS_MIN_UNKNOWNS = 30000 };

/* KLU's user ordering (klu_common.user_order): METIS_NodeND on the pattern of
 * the block plus its transpose. Returns 0 on failure, else 1. */
static int metis_order(int n, int *Ap, int *Ai, int *Perm, klu_common *kc) {
  (void)kc;
  cholmod_common cc;
  if (!cholmod_start(&cc)) return 0;
  cc.print = 0; /* failures fall back to AMD quietly */
  cholmod_sparse A = {.nrow = (size_t)n,
                      .ncol = (size_t)n,
                      .nzmax = (size_t)Ap[n],
                      .p = Ap,
                      .i = Ai,
                      .stype = 0,
                      .itype = CHOLMOD_INT,
                      .xtype = CHOLMOD_PATTERN,
                      .dtype = CHOLMOD_DOUBLE,
                      .sorted = 0,
                      .packed = 1};
  cholmod_sparse *At = cholmod_transpose(&A, 0, &cc);
  cholmod_sparse *S = At ? cholmod_add(&A, At, NULL, NULL, 0, 0, &cc) : NULL;
  int ok = 0;
  if (S) {
    S->stype = 1; /* symmetric: METIS reads the upper part */
    ok = cholmod_metis(S, NULL, 0, 1, Perm, &cc);
  }
  cholmod_free_sparse(&At, &cc);
  cholmod_free_sparse(&S, &cc);
  cholmod_finish(&cc);
  return ok ? 1 : 0;
}

static int klu_create_(void **backend, sl_diag *d) {
  klu_state *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "klu: out of memory");
  klu_defaults(&s->c);
  *backend = s;
  return 0;
}

static void single_free(klu_single *f) {
  free(f->P), free(f->Q), free(f->R), free(f->Rs), free(f->Uinv), free(f->w);
  free(f->Lp), free(f->Li), free(f->Up), free(f->Ui), free(f->Fp), free(f->Fi);
  free(f->Lx), free(f->Ux), free(f->Fx);
  *f = (klu_single){0};
}

/* `single` from the last numeric factorisation (klu_single); 0, or SL_ENOMEM / SL_EFAILED with d set. */
static int single_build(klu_state *s, sl_diag *d) {
  klu_single *f = &s->single;
  single_free(f);
  s->single_ok = 0;
  int n = s->sym->n, nb = s->sym->nblocks, lnz = (int)s->num->lnz, unz = (int)s->num->unz, nzoff = s->num->nzoff;
  f->n = n, f->nblocks = nb;
  int *Lp = malloc((size_t)(n + 1) * sizeof *Lp), *Li = malloc((size_t)(lnz + 1) * sizeof *Li);
  int *Up = malloc((size_t)(n + 1) * sizeof *Up), *Ui = malloc((size_t)(unz + 1) * sizeof *Ui);
  double *Lx = malloc((size_t)(lnz + 1) * sizeof *Lx), *Ux = malloc((size_t)(unz + 1) * sizeof *Ux);
  f->Fp = malloc((size_t)(n + 1) * sizeof *f->Fp), f->Fi = malloc((size_t)(nzoff + 1) * sizeof *f->Fi);
  double *Fx = malloc((size_t)(nzoff + 1) * sizeof *Fx);
  f->P = malloc((size_t)n * sizeof *f->P), f->Q = malloc((size_t)n * sizeof *f->Q);
  f->R = malloc((size_t)(nb + 1) * sizeof *f->R), f->Rs = malloc((size_t)n * sizeof *f->Rs);
  f->Uinv = malloc((size_t)n * sizeof *f->Uinv), f->w = malloc((size_t)n * sizeof *f->w);
  f->Lp = malloc((size_t)(n + 1) * sizeof *f->Lp), f->Li = malloc((size_t)(lnz + 1) * sizeof *f->Li);
  f->Up = malloc((size_t)(n + 1) * sizeof *f->Up), f->Ui = malloc((size_t)(unz + 1) * sizeof *f->Ui);
  f->Lx = malloc((size_t)(lnz + 1) * sizeof *f->Lx), f->Ux = malloc((size_t)(unz + 1) * sizeof *f->Ux);
  f->Fx = malloc((size_t)(nzoff + 1) * sizeof *f->Fx);
  int rc = 0;
  if (!Lp || !Li || !Up || !Ui || !Lx || !Ux || !Fx || !f->Fp || !f->Fi || !f->P || !f->Q || !f->R || !f->Rs ||
      !f->Uinv || !f->w || !f->Lp || !f->Li || !f->Up || !f->Ui || !f->Lx || !f->Ux || !f->Fx)
    rc = sl_diag_set(d, SL_ENOMEM, "klu: out of memory");
  if (!rc && !klu_extract(s->num, s->sym, Lp, Li, Lx, Up, Ui, Ux, f->Fp, f->Fi, Fx, f->P, f->Q, f->Rs, f->R, &s->c))
    rc = klu_fail(s, "extraction of the factors", n, d);
  if (!rc) { /* the diagonals out: L's is 1, U's inverted */
    int kl = 0, ku = 0;
    f->Lp[0] = f->Up[0] = 0;
    for (int j = 0; j < n && !rc; ++j) {
      double ujj = 0.0;
      for (int p = Lp[j]; p < Lp[j + 1]; ++p)
        if (Li[p] != j) f->Li[kl] = Li[p], f->Lx[kl++] = (float)Lx[p];
      for (int p = Up[j]; p < Up[j + 1]; ++p) {
        if (Ui[p] == j) ujj = Ux[p];
        else f->Ui[ku] = Ui[p], f->Ux[ku++] = (float)Ux[p];
      }
      if (ujj == 0.0) rc = sl_diag_set(d, SL_EFAILED, "klu: a zero pivot in the factors of a %d x %d matrix", n, n);
      f->Uinv[j] = 1.0 / ujj;
      f->Lp[j + 1] = kl, f->Up[j + 1] = ku;
    }
    for (int p = 0; p < nzoff; ++p) f->Fx[p] = (float)Fx[p];
  }
  free(Lp), free(Li), free(Up), free(Ui), free(Lx), free(Ux), free(Fx);
  if (rc) single_free(f);
  else s->single_ok = 1;
  return rc;
}

/* sum_{p in [p0, p1)} v_p w_{i_p} in four partial sums (sl_csr_matvec_split): four chains of additions, not
 * one, so that a column runs at the memory's speed rather than the adder's latency */
static inline double gather(const float *v, const int *i, int p0, int p1, const double *w) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  int p = p0;
  for (; p + 3 < p1; p += 4) {
    s0 += (double)v[p] * w[i[p]], s1 += (double)v[p + 1] * w[i[p + 1]];
    s2 += (double)v[p + 2] * w[i[p + 2]], s3 += (double)v[p + 3] * w[i[p + 3]];
  }
  for (; p < p1; ++p) s0 += (double)v[p] * w[i[p]];
  return (s0 + s1) + (s2 + s3);
}

/* A x = b, i.e. S^T x = b with S(P, Q) = R (L U + F): (L U + F)^T w = b(Q), x(P) = w / Rs (klu_single). (L U +
 * F)^T is block lower triangular: block by block, the off-diagonal blocks' columns first, then U^T forward and
 * L^T backward, each a gather over one column of the factor. */
static void single_solve(const klu_single *f, const double *b, double *x) {
  double *w = f->w;
  for (int j = 0; j < f->n; ++j) w[j] = b[f->Q[j]];
  for (int k = 0; k < f->nblocks; ++k) {
    int j0 = f->R[k], j1 = f->R[k + 1];
    for (int j = j0; j < j1; ++j) {
      double t = w[j] - gather(f->Fx, f->Fi, f->Fp[j], f->Fp[j + 1], w);
      w[j] = (t - gather(f->Ux, f->Ui, f->Up[j], f->Up[j + 1], w)) * f->Uinv[j];
    }
    for (int j = j1 - 1; j >= j0; --j) {
      w[j] -= gather(f->Lx, f->Li, f->Lp[j], f->Lp[j + 1], w);
    }
  }
  for (int i = 0; i < f->n; ++i) x[f->P[i]] = w[i] / f->Rs[i];
}

static void klu_drop(klu_state *s) {
  single_free(&s->single);
  s->single_ok = 0;
  if (s->num) klu_free_numeric(&s->num, &s->c);
  if (s->sym) klu_free_symbolic(&s->sym, &s->c);
  s->num = NULL;
  s->sym = NULL;
}

/* KLU's prototypes lack const although it does not modify the matrix. */
#define AP(A) ((int *)(A)->row_ptr)
#define AI(A) ((int *)(A)->col_idx)
#define AX(A) ((double *)(A)->values)

static int klu_symbolic_(void *backend, const sl_csr *A, sl_diag *d) {
  klu_state *s = backend;
  klu_drop(s);
  /* KLU's codes: 0 AMD, 1 COLAMD, 3 the user's (METIS) */
  switch (s->ordering) {
    case SL_ORDERING_AMD:
      s->c.ordering = 0;
      break;
    case SL_ORDERING_COLAMD:
      s->c.ordering = 1;
      break;
    case SL_ORDERING_METIS:
      s->c.ordering = 3;
      break;
    default:
      s->c.ordering = A->n_rows >= KLU_METIS_MIN_UNKNOWNS ? 3 : 0;
  }
  s->c.user_order = metis_order;
  s->sym = klu_analyze(A->n_rows, AP(A), AI(A), &s->c);
  if (!s->sym && s->c.ordering == 3) { /* METIS failed: AMD */
    s->c.ordering = 0;
    s->sym = klu_analyze(A->n_rows, AP(A), AI(A), &s->c);
  }
  if (!s->sym) return klu_fail(s, "symbolic analysis", A->n_rows, d);
  return 0;
}

static int klu_fresh_factor(klu_state *s, const sl_csr *A, sl_diag *d) {
  if (s->num) klu_free_numeric(&s->num, &s->c);
  s->num = klu_factor(AP(A), AI(A), AX(A), s->sym, &s->c);
  if (!s->num || s->c.status != KLU_OK) {
    if (s->num) klu_free_numeric(&s->num, &s->c);
    s->num = NULL;
    return klu_fail(s, "numeric factorisation", A->n_rows, d);
  }
  return 0;
}

static int klu_numeric_(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d) {
  klu_state *s = backend;
  /* eps^(2/3), the threshold SUNDIALS uses for the cheap and the accurate estimate */
  const double tiny = pow(DBL_EPSILON, 2.0 / 3.0);
  int rc;
  if (s->num) {
    ++st->n_refactor;
    int ok = klu_refactor(AP(A), AI(A), AX(A), s->sym, s->num, &s->c);
    int redo = !ok; /* e.g. a zero pivot in the old order: the matrix may still be regular */
    if (ok && klu_rcond(s->sym, s->num, &s->c) && s->c.rcond < tiny) {
      if (!klu_condest(AP(A), AX(A), s->sym, s->num, &s->c) || s->c.condest > 1.0 / tiny) redo = 1;
    }
    if (redo) {
      ++st->n_refactor_redo;
      rc = klu_fresh_factor(s, A, d);
      if (rc) return rc;
    }
  } else {
    rc = klu_fresh_factor(s, A, d);
    if (rc) return rc;
  }
  s->single_ok = 0;
  if (s->role == SL_LINSOLVE_ROLE_PRECONDITIONER && (rc = single_build(s, d))) return rc;
  st->ordering = s->sym->ordering == 3 ? "metis" : s->sym->ordering == 1 ? "colamd" : "amd";
  if (!klu_rcond(s->sym, s->num, &s->c)) return klu_fail(s, "condition estimate", A->n_rows, d);
  st->rcond = s->c.rcond;
  if (!(s->c.rcond >= DBL_EPSILON)) {
    klu_free_numeric(&s->num, &s->c);
    s->num = NULL;
    st->singular = 1;
    return sl_diag_set(d, SL_EFAILED,
                       "klu: matrix is numerically singular (pivot ratio %.3g) in the numeric factorisation of a %d x "
                       "%d matrix",
                       st->rcond, (int)A->n_rows, (int)A->n_rows);
  }
  return 0;
}

static int klu_solve_(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  klu_state *s = backend;
  if (s->single_ok) {
    single_solve(&s->single, b, x);
    return 0;
  }
  for (int32_t i = 0; i < A->n_rows; ++i) x[i] = b[i];
  /* KLU factored A^T (our CSR read as CSC): the transposed solve gives A x = b. */
  if (!klu_tsolve(s->sym, s->num, A->n_rows, 1, x, &s->c)) return klu_fail(s, "solve", A->n_rows, d);
  return 0;
}

static void klu_destroy_(void *backend) {
  klu_state *s = backend;
  if (!s) return;
  klu_drop(s);
  free(s);
}

static int klu_set_ordering_(void *backend, int ordering, sl_diag *d) {
  (void)d;
  ((klu_state *)backend)->ordering = ordering;
  return 0;
}

static int klu_set_role_(void *backend, int role, sl_diag *d) {
  (void)d;
  ((klu_state *)backend)->role = role;
  return 0;
}

const sl_linsolve_ops sl_linsolve_klu_ops = {
    .name = "klu",
    .description = "KLU " STR(KLU_MAIN_VERSION) "." STR(KLU_SUB_VERSION) "." STR(
        KLU_SUBSUB_VERSION) ": LU with cheap refactorisation, general square matrices",
    .create = klu_create_,
    .symbolic = klu_symbolic_,
    .numeric = klu_numeric_,
    .solve = klu_solve_,
    .destroy = klu_destroy_,
    .set_ordering = klu_set_ordering_,
    .set_role = klu_set_role_,
};
