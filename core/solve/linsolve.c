/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/solve/linsolve.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/util/blas.h"

struct sl_linsolve {
  const sl_linsolve_ops *ops;
  void *backend;
  /* what the current factorisation was computed from */
  int have_symbolic, have_numeric, force_numeric;
  uint64_t pattern_id, values_gen;
  const sl_csr *matrix;
  const double *values;
  int32_t n;
  double *work;     /* copy of b for in-place solves */
  double *factored; /* copy of the values last factorised: a re-assembled but
                       unchanged matrix (a constant operator) is not refactorised */
  int32_t n_factored;
  /* for a checkpoint (sl_linsolve_history): the values the pivots in hand were chosen for (the last fresh
     factorisation; a refactorisation keeps its pivots), whether the factorisation in hand is a refactorisation,
     whether the last matrix was divided among ranks */
  double *pivoted;
  int32_t n_pivoted;
  int refactored, distributed;
  double *history; /* sl_linsolve_history's array */
  double *pending; /* sl_linsolve_restore_history's, rebuilt at the next factorisation or solve */
  int64_t n_pending;
  sl_linsolve_stats st;
  /* factorisation reuse */
  sl_linsolve_reuse reuse;
  int reason;        /* of the next numeric factorisation, when set by the reuse path (else -1) */
  int refactor_next; /* the last reuse was slow: refactorise at the next solve */
  int fresh_pending; /* sl_linsolve_drop_numeric was called (see settle_fresh) */
  int numeric_since_symbolic;
  sl_krylov kry;
  double *kry_b; /* copy of b for in-place solves through FGMRES */
  /* sl_linsolve_set_fallback: the solver that takes over from a singular factorisation, once */
  const sl_linsolve_ops *fallback;
  int fallback_ordering;
  char fallback_note[400];
};

static const sl_linsolve_reuse reuse_defaults = {.enabled = 1, .max_iterations = 20, .slow_iterations = 7};

static const char *const reason_names[SL_REFACTOR_N] = {"first",      "pattern", "direct",    "forced", "iterations",
                                                        "stagnation", "slow",    "breakdown", "fresh"};

const char *sl_refactor_reason_name(int reason) {
  return reason >= 0 && reason < SL_REFACTOR_N ? reason_names[reason] : "unknown";
}

static const char *const solver_names[] = {"umfpack", "klu", "cholmod", "petsc"};
static const sl_linsolve_ops *const solver_ops[] = {&sl_linsolve_umfpack_ops, &sl_linsolve_klu_ops,
                                                    &sl_linsolve_cholmod_ops, &sl_linsolve_petsc_ops};

#ifndef SLUICE_WITH_PETSC
static int no_petsc(void **backend, sl_diag *d) {
  *backend = NULL;
  return sl_diag_set(d, SL_EBADINPUT,
                     "linear solver petsc: this sluice was built without PETSc (configure with "
                     "-DSLUICE_WITH_PETSC=ON; Debian: libpetsc-real-dev)");
}
static void no_destroy(void *backend) { (void)backend; }
const sl_linsolve_ops sl_linsolve_petsc_ops = {.name = "petsc", .create = no_petsc, .destroy = no_destroy};
int sl_linsolve_petsc_options(const char *options, sl_diag *d) {
  if (!options || !*options) return 0;
  return no_petsc(&(void *){NULL}, d);
}
int sl_linsolve_petsc_scene_options(const char *options, sl_diag *d) { return sl_linsolve_petsc_options(options, d); }
int sl_linsolve_ranks(int *rank, int *size, sl_diag *d) {
  (void)d;
  const char *r = getenv("OMPI_COMM_WORLD_RANK"), *n = getenv("OMPI_COMM_WORLD_SIZE");
  if (!n) r = getenv("PMI_RANK"), n = getenv("PMI_SIZE");
  *rank = r ? atoi(r) : 0;
  *size = n && atoi(n) > 0 ? atoi(n) : 1;
  return 0;
}
int sl_linsolve_agree(int rc) { return rc; }
int sl_linsolve_sum_ordered(double *x, int n, sl_diag *d) {
  (void)x, (void)n, (void)d;
  return 0;
}
int sl_linsolve_rows_complete(sl_rows *rows, sl_csr *A, double *b, int matrix, sl_diag *d) {
  (void)rows, (void)A, (void)b, (void)matrix;
  return sl_diag_set(d, SL_EFAILED, "a system divided among ranks needs a build with PETSc");
}
int sl_linsolve_partition(int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs, int32_t n_dofs, int ranks,
                          int32_t *part, sl_diag *d) {
  (void)n_elem, (void)dofs_per_elem, (void)elem_dofs, (void)n_dofs, (void)ranks, (void)part;
  return sl_diag_set(d, SL_EFAILED, "a system divided among ranks needs a build with PETSc");
}
void sl_linsolve_rows_free(sl_rows *rows) { (void)rows; }
void sl_linsolve_rows_stats(sl_rows_stats *st) { memset(st, 0, sizeof *st); }
void sl_linsolve_rows_profile(int on) { (void)on; }
#endif
enum { N_SOLVERS = (int)(sizeof solver_names / sizeof solver_names[0]) };
/* sl_linsolve_names lists what this build can run; petsc is last and named even without it for a clear error. */
#ifdef SLUICE_WITH_PETSC
enum { N_BUILT = N_SOLVERS };
#else
enum { N_BUILT = N_SOLVERS - 1 };
#endif

const char *sl_linsolve_default_name(int32_t n) {
  const char *blas = sl_blas_description();
  int reference = !strncmp(blas, "reference", 9) || !strncmp(blas, "none", 4);
  return n < SL_LINSOLVE_KLU_MAX_UNKNOWNS || reference ? "klu" : "umfpack";
}

const char *sl_linsolve_default_name_once(int32_t n) {
  const char *blas = sl_blas_description();
  int reference = !strncmp(blas, "reference", 9) || !strncmp(blas, "none", 4);
  return n < SL_LINSOLVE_ONCE_UMFPACK_MIN || reference ? "klu" : "umfpack";
}

int sl_linsolve_built(const char *name) {
  for (int i = 0; name && i < N_BUILT; ++i)
    if (strcmp(name, solver_names[i]) == 0) return 1;
  return 0;
}

const char *const *sl_linsolve_names(int *n) {
  if (n) *n = N_BUILT;
  return solver_names;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int sl_linsolve_create_ops(sl_linsolve **ls, const sl_linsolve_ops *ops, sl_diag *d) {
  *ls = NULL;
  sl_linsolve *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", ops->name);
  s->ops = ops;
  s->reuse = reuse_defaults;
  s->reason = -1;
  int rc = ops->create(&s->backend, d);
  if (rc) {
    free(s);
    return rc;
  }
  *ls = s;
  return 0;
}

int sl_linsolve_create(sl_linsolve **ls, const char *name, sl_diag *d) {
  *ls = NULL;
  if (!name || !*name) name = solver_names[0];
  for (int i = 0; i < N_SOLVERS; ++i)
    if (strcmp(name, solver_names[i]) == 0) return sl_linsolve_create_ops(ls, solver_ops[i], d);
  const char *hint = sl_suggest(name, solver_names, N_SOLVERS);
  if (hint)
    return sl_diag_set(d, SL_EBADINPUT,
                       "unknown linear solver '%s' (did you mean '%s'?); known: umfpack, klu, cholmod, petsc", name,
                       hint);
  return sl_diag_set(d, SL_EBADINPUT, "unknown linear solver '%s'; known: umfpack, klu, cholmod, petsc", name);
}

void sl_linsolve_destroy(sl_linsolve *ls) {
  if (!ls) return;
  ls->ops->destroy(ls->backend);
  free(ls->work);
  free(ls->factored);
  free(ls->pivoted), free(ls->history), free(ls->pending);
  sl_krylov_free(&ls->kry);
  free(ls->kry_b);
  free(ls);
}

int sl_linsolve_set_fallback(sl_linsolve *ls, const char *name, int ordering, sl_diag *d) {
  for (int i = 0; i < N_BUILT; ++i)
    if (strcmp(name, solver_names[i]) == 0) {
      ls->fallback = solver_ops[i];
      ls->fallback_ordering = ordering;
      return 0;
    }
  return sl_diag_set(d, SL_EBADINPUT, "unknown linear solver '%s' to fall back on", name);
}

const char *sl_linsolve_fallback_note(const sl_linsolve *ls) { return ls->fallback_note; }

/* The current backend found A singular: the fallback's backend replaces it. */
static int take_over(sl_linsolve *ls, sl_diag *d) {
  const sl_linsolve_ops *next = ls->fallback;
  ls->fallback = NULL; /* once */
  double pivot_ratio = ls->st.rcond;
  void *backend = NULL;
  int rc = next->create(&backend, d);
  if (!rc && ls->fallback_ordering != SL_ORDERING_AUTO && next->set_ordering)
    rc = next->set_ordering(backend, ls->fallback_ordering, d);
  if (rc) {
    if (backend) next->destroy(backend);
    return rc;
  }
  snprintf(ls->fallback_note, sizeof ls->fallback_note,
           "%s found the matrix numerically singular (pivot ratio "
           "%.3g): %s took over",
           ls->ops->name, pivot_ratio, next->name);
  ls->ops->destroy(ls->backend);
  ls->ops = next, ls->backend = backend;
  ls->have_symbolic = ls->have_numeric = 0;
  ls->st.singular = 0;
  ls->st.ordering = NULL;
  return 0;
}

int sl_linsolve_set_ordering(sl_linsolve *ls, const char *name, sl_diag *d) {
  static const char *const names[] = {"auto", "amd", "colamd", "metis"};
  int o = -1;
  for (int i = 0; i < 4; ++i)
    if (strcmp(name, names[i]) == 0) o = i;
  if (o < 0) {
    const char *hint = sl_suggest(name, names, 4);
    return sl_diag_set(d, SL_EBADINPUT, "unknown ordering '%s'%s%s%s; known: auto, amd, colamd, metis", name,
                       hint ? " (did you mean '" : "", hint ? hint : "", hint ? "'?)" : "");
  }
  if (!ls->ops->set_ordering)
    return sl_diag_set(d, SL_EBADINPUT, "the %s solver chooses its own ordering (only klu takes one)", ls->ops->name);
  int rc = ls->ops->set_ordering(ls->backend, o, d);
  if (!rc) ls->have_symbolic = ls->have_numeric = 0; /* analysed again at the next factorisation */
  return rc;
}

void sl_linsolve_values_changed(sl_linsolve *ls) { ls->force_numeric = 1; }

void sl_linsolve_drop_numeric(sl_linsolve *ls) {
  if (ls && ls->have_symbolic) ls->fresh_pending = 1;
}

/* After sl_linsolve_drop_numeric, at the next factorisation or solve: start
 * as a new solver would, unless the factorisation in hand is what a new
 * solver would compute for A (A's values bitwise those factorised, the
 * first numeric factorisation after the analysis of those same values: a
 * constant operator then stays factorised once). */
static void settle_fresh(sl_linsolve *ls, const sl_csr *A) {
  if (!ls->fresh_pending) return;
  ls->fresh_pending = 0;
  int same = ls->have_numeric && ls->numeric_since_symbolic == 1 && ls->pattern_id == A->pattern_id &&
             ls->n == A->n_rows && ls->factored && ls->n_factored == A->nnz &&
             memcmp(ls->factored, A->values, (size_t)A->nnz * sizeof *A->values) == 0;
  ls->refactor_next = 0;
  if (same) return;
  ls->have_symbolic = ls->have_numeric = 0;
  ls->reason = SL_REFACTOR_FRESH;
}
int64_t sl_linsolve_history(sl_linsolve *ls, const double **out) {
  *out = NULL;
  if (!ls || !ls->have_numeric || ls->ops->solve_rtol || ls->distributed || !ls->factored || !ls->pivoted ||
      ls->n_pivoted != ls->n_factored || ls->pending)
    return 0;
  int32_t nnz = ls->n_factored;
  int64_t n = SL_LINSOLVE_HISTORY_HEAD + (int64_t)nnz * (ls->refactored ? 2 : 1);
  double *h = realloc(ls->history, (size_t)n * sizeof *h);
  if (!h) return 0;
  ls->history = h;
  h[0] = 1.0, h[1] = ls->refactored, h[2] = ls->refactor_next, h[3] = ls->numeric_since_symbolic, h[4] = nnz;
  memcpy(h + SL_LINSOLVE_HISTORY_HEAD, ls->pivoted, (size_t)nnz * sizeof *h);
  if (ls->refactored) memcpy(h + SL_LINSOLVE_HISTORY_HEAD + nnz, ls->factored, (size_t)nnz * sizeof *h);
  *out = h;
  return n;
}

int sl_linsolve_restore_history(sl_linsolve *ls, const double *h, int64_t n, sl_diag *d) {
  int64_t nnz = n >= SL_LINSOLVE_HISTORY_HEAD ? (int64_t)h[4] : -1;
  if (nnz < 1 || h[0] != 1.0 || (h[1] != 0.0 && h[1] != 1.0) || n != SL_LINSOLVE_HISTORY_HEAD + nnz * (h[1] ? 2 : 1))
    return sl_diag_set(d, SL_EBADINPUT, "checkpoint: the %s factorisation's state (%lld values) is not one",
                       ls->ops->name, (long long)n);
  double *p = malloc((size_t)n * sizeof *p);
  if (!p) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", ls->ops->name);
  memcpy(p, h, (size_t)n * sizeof *p);
  free(ls->pending);
  ls->pending = p, ls->n_pending = n;
  return 0;
}

/* A checkpoint's factorisation (sl_linsolve_restore_history), rebuilt for A's pattern: the analysis, the fresh
 * factorisation of the values the pivots were chosen for, and with the same pivots the kept values' (KLU's
 * refactorisation), as in the run that wrote it. */
static int rebuild_pending(sl_linsolve *ls, const sl_csr *A, sl_diag *d) {
  if (!ls->pending) return 0;
  double *h = ls->pending;
  ls->pending = NULL;
  int32_t nnz = (int32_t)h[4];
  int refactored = h[1] != 0.0;
  /* a restart on another number of ranks or with another solver cannot rebuild the same factorisation: it
     starts from a fresh one, as a run whose checkpoint holds none (equal to the solver tolerance, not bitwise) */
  if (nnz != A->nnz || A->rows || ls->ops->solve_rtol) {
    free(h);
    return 0;
  }
  sl_csr T = *A;
  T.values = h + SL_LINSOLVE_HISTORY_HEAD;
  ls->have_symbolic = ls->have_numeric = 0;
  ls->fresh_pending = 0;
  double t0 = now();
  int rc = ls->ops->symbolic(ls->backend, &T, d);
  ls->st.t_symbolic += now() - t0;
  if (!rc) ++ls->st.n_symbolic;
  for (int k = 0; k < 1 + refactored && !rc; ++k) {
    if (k) T.values = h + SL_LINSOLVE_HISTORY_HEAD + nnz;
    t0 = now();
    rc = ls->ops->numeric(ls->backend, &T, &ls->st, d);
    ls->st.t_numeric += now() - t0;
    if (!rc) ++ls->st.n_numeric, ++ls->st.refactor_reason[SL_REFACTOR_FRESH];
  }
  if (!rc && (!(ls->factored = realloc(ls->factored, (size_t)nnz * sizeof *ls->factored)) ||
              !(ls->pivoted = realloc(ls->pivoted, (size_t)nnz * sizeof *ls->pivoted))))
    rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory", ls->ops->name);
  if (rc) {
    ls->n_factored = ls->factored ? ls->n_factored : 0, ls->n_pivoted = ls->pivoted ? ls->n_pivoted : 0;
    free(h);
    return sl_diag_prefix(d, rc, "restart: rebuilding the checkpoint's factorisation");
  }
  memcpy(ls->pivoted, h + SL_LINSOLVE_HISTORY_HEAD, (size_t)nnz * sizeof *h);
  memcpy(ls->factored, T.values, (size_t)nnz * sizeof *h);
  ls->n_factored = ls->n_pivoted = nnz;
  ls->refactored = refactored, ls->distributed = 0;
  ls->have_symbolic = ls->have_numeric = 1, ls->force_numeric = 0;
  ls->pattern_id = A->pattern_id, ls->n = A->n_rows;
  ls->matrix = NULL, ls->values = NULL; /* A's values are compared with the kept ones, as after any step */
  ls->refactor_next = h[2] != 0.0, ls->numeric_since_symbolic = (int)h[3];
  ls->reason = -1;
  free(h);
  return 0;
}

const char *sl_linsolve_name(const sl_linsolve *ls) { return ls->ops->name; }
const char *sl_linsolve_description(const sl_linsolve *ls) { return ls->ops->description; }
const sl_linsolve_stats *sl_linsolve_get_stats(const sl_linsolve *ls) { return &ls->st; }

void sl_linsolve_summary(const sl_linsolve *ls, char *buf, size_t len) {
  const sl_linsolve_stats *s = &ls->st;
  int k =
      snprintf(buf, len, "%s%s%s%s%s%s: %ld symbolic %.3g s, %ld numeric %.3g s", ls->fallback_note,
               ls->fallback_note[0] ? "; " : "", ls->ops->name, s->ordering ? " (" : "", s->ordering ? s->ordering : "",
               s->ordering ? " ordering)" : "", s->n_symbolic, s->t_symbolic, s->n_numeric, s->t_numeric);
  if (k >= 0 && (size_t)k < len && s->n_numeric_skipped > 0)
    k += snprintf(buf + k, len - (size_t)k, " (%ld skipped: matrix unchanged)", s->n_numeric_skipped);
  if (k >= 0 && (size_t)k < len && s->n_refactor > 0)
    k += snprintf(buf + k, len - (size_t)k, " (%ld refactor, %ld redone)", s->n_refactor, s->n_refactor_redo);
  if (k >= 0 && (size_t)k < len && s->n_reused + s->n_krylov_failed > 0)
    k += snprintf(buf + k, len - (size_t)k, ", %ld reused (FGMRES %.1f iterations a solve, %ld refactorised) %.3g s",
                  s->n_reused, (double)s->n_krylov_iterations / (double)(s->n_reused + s->n_krylov_failed),
                  s->n_krylov_failed, s->t_krylov);
  if (k >= 0 && (size_t)k < len)
    k += snprintf(buf + k, len - (size_t)k, ", %ld solves %.3g s", s->n_solves, s->t_solve);
  if (k >= 0 && (size_t)k < len && ls->ops->describe) {
    char what[160];
    ls->ops->describe(ls->backend, what, sizeof what);
    snprintf(buf + k, len - (size_t)k, " (%s)", what);
  }
}

void sl_linsolve_describe(const sl_linsolve *ls, char *buf, size_t len) {
  if (ls->ops->describe) {
    char what[160];
    ls->ops->describe(ls->backend, what, sizeof what);
    snprintf(buf, len, "%s, %s", ls->ops->name, what);
  } else {
    snprintf(buf, len, "%s, %ld numeric", ls->ops->name, ls->st.n_numeric);
  }
}

int sl_linsolve_set_blocks(sl_linsolve *ls, int32_t split, int transient, sl_diag *d) {
  return ls->ops->set_blocks ? ls->ops->set_blocks(ls->backend, split, transient, d) : 0;
}

int sl_linsolve_set_role(sl_linsolve *ls, int role, sl_diag *d) {
  return ls->ops->set_role ? ls->ops->set_role(ls->backend, role, d) : 0;
}

int sl_linsolve_factor(sl_linsolve *ls, const sl_csr *A, sl_diag *d) {
  const char *name = ls->ops->name;
  if (A->n_rows != A->n_cols)
    return sl_diag_set(d, SL_EBADINPUT, "%s: matrix is %d x %d, not square", name, (int)A->n_rows, (int)A->n_cols);
  if (A->n_rows <= 0 || !A->row_ptr) return sl_diag_set(d, SL_EBADINPUT, "%s: empty matrix", name);

  int rc0 = rebuild_pending(ls, A, d);
  if (rc0) return rc0;
  settle_fresh(ls, A);
  int reason = ls->reason;
  ls->reason = -1;
  if (!ls->have_symbolic || ls->pattern_id != A->pattern_id || ls->n != A->n_rows) {
    if (reason != SL_REFACTOR_FRESH) reason = ls->st.n_numeric == 0 ? SL_REFACTOR_FIRST : SL_REFACTOR_PATTERN;
    ls->have_symbolic = ls->have_numeric = 0;
    double t0 = now();
    int rc = ls->ops->symbolic(ls->backend, A, d);
    ls->st.t_symbolic += now() - t0;
    if (rc) return rc;
    ++ls->st.n_symbolic;
    ls->numeric_since_symbolic = 0;
    ls->have_symbolic = 1;
    ls->pattern_id = A->pattern_id;
    ls->n = A->n_rows;
  }
  int stale = !ls->have_numeric || ls->force_numeric || ls->values_gen != A->values_gen || ls->matrix != A ||
              ls->values != A->values;
  /* rows divided among ranks: each rank sees its own rows, and the numeric step is collective, so the ranks
   * decide together (any rank's new values refactorise on all) */
  if (A->rows) stale = sl_linsolve_agree(stale);
  int same = stale && ls->have_numeric && !ls->force_numeric && ls->n_factored == A->nnz &&
             memcmp(ls->factored, A->values, (size_t)A->nnz * sizeof *A->values) == 0;
  if (A->rows && stale) same = !sl_linsolve_agree(!same);
  if (same) {
    /* same pattern, bitwise the same values: the factorisation still holds */
    ++ls->st.n_numeric_skipped;
    ls->values_gen = A->values_gen, ls->matrix = A, ls->values = A->values;
    stale = 0;
  }
  if (stale) {
    if (reason < 0)
      reason = !ls->have_numeric ? SL_REFACTOR_FIRST : ls->force_numeric ? SL_REFACTOR_FORCED : SL_REFACTOR_DIRECT;
    ls->have_numeric = 0;
    /* A NaN from a closure would otherwise surface as a misleading "singular". */
    int bad = 0;
    for (int32_t i = 0; i < A->n_rows && !bad; ++i)
      for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p)
        if (!isfinite(A->values[p])) {
          bad = sl_diag_set(d, SL_EFAILED, "%s: matrix entry (%d, %d) is not finite (%g)", name, (int)i,
                            (int)A->col_idx[p], A->values[p]);
          break;
        }
    if (A->rows) {
      int all = sl_linsolve_agree(bad);
      if (all && !bad) bad = sl_diag_set(d, all, "%s: a matrix entry on another rank is not finite", name);
    }
    if (bad) return bad;
    double t0 = now();
    ls->st.singular = 0;
    long refactors = ls->st.n_refactor, redone = ls->st.n_refactor_redo;
    int rc = ls->ops->numeric(ls->backend, A, &ls->st, d);
    ls->st.t_numeric += now() - t0;
    if (rc && rc == SL_EFAILED && ls->st.singular && ls->fallback && !(rc = take_over(ls, d))) {
      ls->reason = reason;
      return sl_linsolve_factor(ls, A, d); /* the same matrix, by the solver that took over */
    }
    if (rc) return rc; /* stays without a numeric factorisation: the next call retries */
    ++ls->st.n_numeric;
    ++ls->st.refactor_reason[reason];
    ++ls->numeric_since_symbolic;
    ls->refactor_next = 0;
    ls->have_numeric = 1;
    ls->force_numeric = 0;
    ls->values_gen = A->values_gen;
    ls->matrix = A;
    ls->values = A->values;
    if (ls->n_factored != A->nnz) {
      free(ls->factored);
      ls->factored = malloc((size_t)A->nnz * sizeof *ls->factored);
      ls->n_factored = ls->factored ? A->nnz : 0;
    }
    if (ls->factored) memcpy(ls->factored, A->values, (size_t)A->nnz * sizeof *A->values);
    /* a refactorisation (KLU's) keeps the pivots of the last fresh factorisation: remember whose they are */
    ls->refactored = ls->st.n_refactor > refactors && ls->st.n_refactor_redo == redone;
    ls->distributed = A->rows != NULL;
    /* the pivots' values are kept only for a checkpoint's history (sl_linsolve_history), which an iterative
       backend (solve_rtol: PETSc) or rows divided among ranks never take: a copy of the matrix's values less */
    if (ls->ops->solve_rtol || ls->distributed) {
      free(ls->pivoted);
      ls->pivoted = NULL, ls->n_pivoted = 0;
    } else if (!ls->refactored) {
      if (ls->n_pivoted != A->nnz) {
        free(ls->pivoted);
        ls->pivoted = malloc((size_t)A->nnz * sizeof *ls->pivoted);
        ls->n_pivoted = ls->pivoted ? A->nnz : 0;
      }
      if (ls->pivoted) memcpy(ls->pivoted, A->values, (size_t)A->nnz * sizeof *A->values);
    }
  }
  return 0;
}

int sl_linsolve_solve(sl_linsolve *ls, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  int rc = sl_linsolve_factor(ls, A, d);
  if (rc) return rc;
  int32_t n = A->n_rows;
  if (x == b) {
    /* the backends need distinct b and x */
    double *w = realloc(ls->work, (size_t)n * sizeof *w);
    if (!w) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", ls->ops->name);
    ls->work = w;
    memcpy(w, b, (size_t)n * sizeof *w);
    b = w;
  }
  double t0 = now();
  rc = ls->ops->solve(ls->backend, A, b, x, d);
  ls->st.t_solve += now() - t0;
  if (rc) return rc;
  ++ls->st.n_solves;
  for (int32_t i = 0; i < n; ++i)
    if (!isfinite(x[i]))
      return sl_diag_set(d, SL_EFAILED, "%s: solution is not finite (x[%d] = %g; rcond %.3g)", ls->ops->name, (int)i,
                         x[i], ls->st.rcond);
  return 0;
}

void sl_linsolve_set_reuse(sl_linsolve *ls, const sl_linsolve_reuse *policy) {
  ls->reuse = *policy;
  if (ls->reuse.max_iterations <= 0) ls->reuse.max_iterations = reuse_defaults.max_iterations;
  if (ls->reuse.slow_iterations <= 0) ls->reuse.slow_iterations = reuse_defaults.slow_iterations;
  ls->refactor_next = 0;
}

sl_linsolve_reuse sl_linsolve_get_reuse(const sl_linsolve *ls) { return ls->reuse; }

int sl_linsolve_set_reuse_name(sl_linsolve *ls, const char *name, sl_diag *d) {
  static const char *const names[] = {"auto", "never"};
  for (int i = 0; i < 2; ++i)
    if (strcmp(name, names[i]) == 0) {
      sl_linsolve_reuse r = reuse_defaults;
      r.enabled = i == 0;
      sl_linsolve_set_reuse(ls, &r);
      return 0;
    }
  const char *hint = sl_suggest(name, names, 2);
  return sl_diag_set(d, SL_EBADINPUT, "unknown factorisation reuse '%s'%s%s%s; known: auto, never", name,
                     hint ? " (did you mean '" : "", hint ? hint : "", hint ? "'?)" : "");
}

typedef struct reuse_ctx {
  sl_linsolve *ls;
  const sl_csr *A;
  sl_csr factored; /* A's pattern with the values the factorisation was computed from */
} reuse_ctx;

static int apply_matrix(void *user, const double *x, double *y, sl_diag *d) {
  (void)d;
  sl_csr_matvec(((reuse_ctx *)user)->A, x, y);
  return 0;
}

static int apply_factor(void *user, const double *x, double *y, sl_diag *d) {
  reuse_ctx *c = user;
  const sl_linsolve_ops *ops = c->ls->ops;
  return (ops->precond ? ops->precond : ops->solve)(c->ls->backend, &c->factored, x, y, d);
}

int sl_linsolve_solve_rtol(sl_linsolve *ls, const sl_csr *A, const double *b, double *x, double rtol, sl_diag *d) {
  if (ls->ops->solve_rtol && rtol > 0.0) { /* an iterative backend: its own preconditioner, the caller's tolerance */
    int rc = sl_linsolve_factor(ls, A, d);
    if (rc) return rc;
    if (x == b) {
      double *w = realloc(ls->work, (size_t)A->n_rows * sizeof *w);
      if (!w) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", ls->ops->name);
      ls->work = w;
      memcpy(w, b, (size_t)A->n_rows * sizeof *w);
      b = w;
    }
    double t0 = now();
    rc = ls->ops->solve_rtol(ls->backend, A, b, x, rtol, d);
    ls->st.t_solve += now() - t0;
    if (!rc) ++ls->st.n_solves;
    return rc;
  }
  if (A->n_rows == A->n_cols && A->row_ptr) {
    int rc0 = rebuild_pending(ls, A, d);
    if (rc0) return rc0;
    settle_fresh(ls, A);
  }
  if (!(rtol > 0.0) || !ls->reuse.enabled || !ls->have_symbolic || !ls->have_numeric || ls->force_numeric ||
      ls->pattern_id != A->pattern_id || ls->n != A->n_rows || A->n_rows != A->n_cols || !ls->factored ||
      ls->n_factored != A->nnz)
    return sl_linsolve_solve(ls, A, b, x, d);
  int current = ls->values_gen == A->values_gen && ls->matrix == A && ls->values == A->values;
  if (current || memcmp(ls->factored, A->values, (size_t)A->nnz * sizeof *A->values) == 0)
    return sl_linsolve_solve(ls, A, b, x, d); /* the factorisation is that of A: direct */
  if (ls->refactor_next) {
    ls->reason = SL_REFACTOR_SLOW;
    return sl_linsolve_solve(ls, A, b, x, d);
  }
  int32_t n = A->n_rows;
  int m = ls->reuse.max_iterations;
  if (ls->kry.n != n || ls->kry.m < m) {
    sl_krylov_free(&ls->kry);
    free(ls->kry_b);
    ls->kry_b = NULL;
    int rc = sl_krylov_init(&ls->kry, n, m, d);
    if (!rc && !(ls->kry_b = malloc((size_t)n * sizeof *ls->kry_b)))
      rc = sl_diag_set(d, SL_EFAILED, "%s: out of memory", ls->ops->name);
    if (rc) {
      sl_krylov_free(&ls->kry);
      return rc;
    }
  }
  if (x == b) {
    memcpy(ls->kry_b, b, (size_t)n * sizeof *b);
    b = ls->kry_b;
  }
  reuse_ctx c = {ls, A, *A};
  c.factored.values = ls->factored;
  for (int32_t i = 0; i < n; ++i) x[i] = 0.0;
  sl_krylov_opts ko = {.rtol = rtol, .restart = m, .max_iterations = m, .predict = 1};
  sl_krylov_result kr;
  sl_diag dk;
  double t0 = now();
  int rc = sl_fgmres(&ls->kry, apply_matrix, &c, apply_factor, &c, b, x, &ko, &kr, &dk);
  ls->st.t_krylov += now() - t0;
  ls->st.t_solve += now() - t0;
  ls->st.n_krylov_iterations += kr.iterations;
  if (!rc && kr.status == SL_KRYLOV_CONVERGED) {
    for (int32_t i = 0; i < n; ++i)
      if (!isfinite(x[i])) rc = SL_EFAILED;
    if (!rc) {
      ++ls->st.n_reused, ++ls->st.n_solves;
      if (kr.iterations > ls->st.krylov_max) ls->st.krylov_max = kr.iterations;
      if (kr.iterations > ls->reuse.slow_iterations) ls->refactor_next = 1;
      return 0;
    }
  }
  /* the old factorisation is too far from A (or FGMRES broke down): factorise A and solve directly */
  ++ls->st.n_krylov_failed;
  ls->reason = rc                                 ? SL_REFACTOR_BREAKDOWN
               : kr.status == SL_KRYLOV_STAGNATED ? SL_REFACTOR_STAGNATION
                                                  : SL_REFACTOR_ITERATIONS;
  return sl_linsolve_solve(ls, A, b, x, d);
}
