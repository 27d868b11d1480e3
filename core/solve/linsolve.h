/* Direct sparse linear solvers behind one ops table (SUNDIALS style), one
 * backend per SuiteSparse package: "umfpack" (default, general LU), "klu"
 * (LU with cheap refactorisation) and "cholmod" (symmetric positive definite).
 *
 * The solver remembers the pattern and the values generation of the matrix it
 * factorised: the symbolic analysis runs once per pattern, the numeric
 * factorisation only when the values changed (or the caller says so). A
 * matrix re-assembled with bitwise the same values (a constant operator of a
 * linear problem) is recognised by comparison with a copy of the factorised
 * values and not factorised again. */
#ifndef SLUICE_SOLVE_LINSOLVE_H
#define SLUICE_SOLVE_LINSOLVE_H

#include <stdint.h>

#include "core/solve/sparse.h"
#include "core/util/diag.h"

typedef struct sl_linsolve_stats {
  long n_symbolic;      /* symbolic analyses (orderings) */
  long n_numeric;       /* numeric factorisations, refactorisations included */
  long n_refactor;      /* of those, klu_refactor reusing the old pivots */
  long n_refactor_redo; /* klu_refactor results thrown away for a fresh klu_factor (rcond degraded) */
  long n_numeric_skipped; /* re-assembled matrices found bitwise unchanged: not refactorised */
  long n_solves;
  double t_symbolic, t_numeric, t_solve; /* wall-clock seconds */
  double rcond;                          /* last reciprocal condition estimate (backend's own, crude) */
  const char *ordering; /* the last fill-reducing ordering, where the backend says ("amd", "metis"), else NULL */
} sl_linsolve_stats;

/* A backend. Every function returns 0 or an SL_E* code with d set. The
 * matrix is sluice's CSR; the SuiteSparse LU backends read it as the CSC of
 * A^T and solve the transposed system, so no copy is made. */
typedef struct sl_linsolve_ops {
  const char *name;
  const char *description;
  int (*create)(void **backend, sl_diag *d);
  /* Once per pattern; drops any previous factorisation. */
  int (*symbolic)(void *backend, const sl_csr *A, sl_diag *d);
  /* After symbolic; may reuse pivots from a previous numeric call. */
  int (*numeric)(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d);
  /* x = A^-1 b with the last numeric factorisation; x and b do not overlap. */
  int (*solve)(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d);
  void (*destroy)(void *backend);
  /* Optional: the fill-reducing ordering of later symbolic analyses
   * (SL_ORDERING_*); NULL when the backend chooses its own. */
  int (*set_ordering)(void *backend, int ordering, sl_diag *d);
} sl_linsolve_ops;

/* Fill-reducing orderings a backend may be told to use. AUTO is the
 * backend's default (KLU: AMD below 30 000 unknowns, METIS above). COLAMD
 * orders the columns for LU with partial pivoting (Davis et al. 2004, ACM
 * TOMS 30(3)); it suits matrices whose zero diagonal forces off-diagonal
 * pivots (a saddle point with its pressure rows), where a symmetric ordering
 * of A + A^T predicts the fill badly. */
enum { SL_ORDERING_AUTO = 0, SL_ORDERING_AMD, SL_ORDERING_COLAMD, SL_ORDERING_METIS };

extern const sl_linsolve_ops sl_linsolve_umfpack_ops;
extern const sl_linsolve_ops sl_linsolve_klu_ops;
extern const sl_linsolve_ops sl_linsolve_cholmod_ops;

typedef struct sl_linsolve sl_linsolve;

/* By name: "umfpack" | "klu" | "cholmod"; NULL or "" gives "umfpack".
 * Unknown names: SL_EBADINPUT with a did-you-mean. */
int sl_linsolve_create(sl_linsolve **ls, const char *name, sl_diag *d);
int sl_linsolve_create_ops(sl_linsolve **ls, const sl_linsolve_ops *ops, sl_diag *d);
void sl_linsolve_destroy(sl_linsolve *ls);

/* The names accepted by sl_linsolve_create, for help text. */
const char *const *sl_linsolve_names(int *n);

/* Factorise as needed: symbolic when A's pattern differs from the last one,
 * numeric when A's values generation (or A itself) differs, or after
 * sl_linsolve_values_changed. Returns 0, SL_EBADINPUT (not square, empty) or
 * SL_EFAILED (singular, not positive definite, out of memory). */
int sl_linsolve_factor(sl_linsolve *ls, const sl_csr *A, sl_diag *d);
/* Factorise as needed, then x = A^-1 b. x may be b (solved in place). A
 * non-finite solution is SL_EFAILED. */
int sl_linsolve_solve(sl_linsolve *ls, const sl_csr *A, const double *b, double *x, sl_diag *d);
/* Force a numeric factorisation at the next solve (values written without
 * sl_csr_touch). */
void sl_linsolve_values_changed(sl_linsolve *ls);

/* The ordering by name ("auto" | "amd" | "colamd" | "metis"), for the next
 * symbolic analysis. SL_EBADINPUT for an unknown name (with a did-you-mean)
 * or a backend that takes no ordering (umfpack, cholmod). */
int sl_linsolve_set_ordering(sl_linsolve *ls, const char *name, sl_diag *d);

const char *sl_linsolve_name(const sl_linsolve *ls);
/* e.g. "UMFPACK V5.7.9 (Oct 20, 2019): multifrontal LU, ..." for provenance. */
const char *sl_linsolve_description(const sl_linsolve *ls);
const sl_linsolve_stats *sl_linsolve_get_stats(const sl_linsolve *ls);
/* One line for the run summary, e.g.
 * "umfpack: 1 symbolic 0.012 s, 3 numeric 0.150 s, 40 solves 0.020 s". */
void sl_linsolve_summary(const sl_linsolve *ls, char *buf, size_t len);

#endif
