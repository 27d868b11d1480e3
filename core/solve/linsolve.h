/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Direct sparse linear solvers behind one ops table (SUNDIALS style), one
 * backend per SuiteSparse package: "umfpack" (general multifrontal LU), "klu"
 * (LU with cheap refactorisation) and "cholmod" (symmetric positive definite);
 * the scenes' default by size and BLAS, sl_linsolve_default_name.
 *
 * The solver remembers the pattern and the values generation of the matrix it
 * factorised: the symbolic analysis runs once per pattern, the numeric
 * factorisation only when the values changed (or the caller says so). A
 * matrix re-assembled with bitwise the same values (a constant operator of a
 * linear problem) is recognised by comparison with a copy of the factorised
 * values and not factorised again.
 *
 * Factorisation reuse (sl_linsolve_solve_rtol): a caller that can take an
 * approximate solution, to a relative residual rtol (Newton's corrections),
 * gets one from FGMRES (core/solve/krylov.h) preconditioned with the last
 * factorisation when only the matrix values changed since it was computed:
 * a slowly varying matrix (a Newton Jacobian, one time step to the next)
 * is then factorised a few times per run instead of at every solve. The
 * solve is refactorised and done directly when FGMRES does not reach rtol
 * within its budget or its rate says it will not (the preconditioner has
 * drifted too far), and at the next solve after one that needed more than
 * slow_iterations. Why each factorisation was computed is counted. */
#ifndef SLUICE_SOLVE_LINSOLVE_H
#define SLUICE_SOLVE_LINSOLVE_H

#include <stdint.h>

#include "core/solve/krylov.h"
#include "core/solve/sparse.h"
#include "core/util/diag.h"

/* Why a numeric factorisation was computed (sl_linsolve_stats.refactor_reason). */
typedef enum sl_refactor_reason {
  SL_REFACTOR_FIRST = 0,  /* no factorisation yet, or the last one failed */
  SL_REFACTOR_PATTERN,    /* a new sparsity pattern or ordering */
  SL_REFACTOR_DIRECT,     /* new values and a direct solve: reuse off, an exact solve asked for, sl_linsolve_factor */
  SL_REFACTOR_FORCED,     /* sl_linsolve_values_changed */
  SL_REFACTOR_ITERATIONS, /* FGMRES with the old factorisation used its budget without converging */
  SL_REFACTOR_STAGNATION, /* its convergence rate could not reach the tolerance within the budget */
  SL_REFACTOR_SLOW,       /* the previous reuse needed more than slow_iterations */
  SL_REFACTOR_BREAKDOWN,  /* FGMRES failed (a vector not finite) */
  SL_REFACTOR_FRESH,      /* after sl_linsolve_drop_numeric (a checkpoint) */
  SL_REFACTOR_N
} sl_refactor_reason;

/* "first", "pattern", "direct", "forced", "iterations", "stagnation", "slow", "breakdown", "fresh" */
const char *sl_refactor_reason_name(int reason);

typedef struct sl_linsolve_stats {
  long n_symbolic;                       /* symbolic analyses (orderings) */
  long n_numeric;                        /* numeric factorisations, refactorisations included */
  long n_refactor;                       /* of those, klu_refactor reusing the old pivots */
  long n_refactor_redo;                  /* klu_refactor results thrown away for a fresh klu_factor (rcond degraded) */
  long n_numeric_skipped;                /* re-assembled matrices found bitwise unchanged: not refactorised */
  long n_solves;                         /* systems solved, reused ones included (t_solve: FGMRES included) */
  double t_symbolic, t_numeric, t_solve; /* wall-clock seconds */
  double rcond;                          /* last reciprocal condition estimate (backend's own, crude) */
  const char *ordering; /* the last fill-reducing ordering, where the backend says ("amd", "metis"), else NULL */
  /* factorisation reuse (sl_linsolve_solve_rtol) */
  long n_reused;                       /* solves answered by FGMRES with an older factorisation */
  long n_krylov_failed;                /* FGMRES attempts that ended in a refactorisation */
  long n_krylov_iterations;            /* FGMRES iterations in all, failed attempts included */
  int krylov_max;                      /* most iterations of one accepted reuse */
  long refactor_reason[SL_REFACTOR_N]; /* numeric factorisations by reason; they sum to n_numeric */
  double t_krylov; /* of t_solve, the wall-clock seconds in FGMRES (its preconditioner solves, failed attempts) */
  int singular;    /* the last numeric factorisation failed because the backend found the matrix numerically singular */
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
  /* Optional: as solve, for a preconditioner application (A holds the
   * factorised values): no iterative refinement. NULL: solve. */
  int (*precond)(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d);
  /* Optional, an iterative backend: x to a relative residual rtol (solve: to the backend's own tight one);
   * sl_linsolve_solve_rtol then calls it instead of reusing an older factorisation. */
  int (*solve_rtol)(void *backend, const sl_csr *A, const double *b, double *x, double rtol, sl_diag *d);
  /* Optional: the unknowns [0, split) and [split, n) are the two fields of a saddle point (velocity, pressure);
   * transient: the velocity block holds a time derivative's mass term. */
  int (*set_blocks)(void *backend, int32_t split, int transient, sl_diag *d);
  /* Optional: what the backend does, for the run's summary ("fgmres/fieldsplit, 120 iterations"). */
  void (*describe)(void *backend, char *buf, size_t len);
  /* Optional: the system's role among a run's several (sl_linsolve_set_role). */
  int (*set_role)(void *backend, int role, sl_diag *d);
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
/* With SLUICE_WITH_PETSC: PETSc's KSP on one rank (core/solve/ls_petsc.c); without, its create says how to
 * build it. */
extern const sl_linsolve_ops sl_linsolve_petsc_ops;
/* PETSc options as on a PETSc command line ("-ksp_type gmres -pc_type ilu"). The user's (the command line's
 * --petsc) win over a scene's ([solver.petsc]); PETSC_OPTIONS in the environment wins over both. Each call
 * replaces that level's options for the solvers created afterwards. SL_EBADINPUT without PETSc. */
int sl_linsolve_petsc_options(const char *options, sl_diag *d);
int sl_linsolve_petsc_scene_options(const char *options, sl_diag *d);
/* This process's rank and the number of ranks it was launched with (mpirun sets OMPI_COMM_WORLD_SIZE or
 * PMI_SIZE). With PETSc and a launcher, MPI starts here (through PETSc); without PETSc, *size is the
 * launcher's so that a caller can refuse to run the same scene N times. */
int sl_linsolve_ranks(int *rank, int *size, sl_diag *d);
/* On several ranks: the largest of every rank's rc (0 when all are 0), so that a step one rank alone can fail
 * (a closure out of range on one rank's points) is failed by all; on one rank (or without PETSc) rc itself. */
int sl_linsolve_agree(int rc);
/* On several ranks: x[0..n) becomes the sum over the ranks of their x, added in rank order on every rank so
 * that every rank gets bitwise the same sums (Newton's norms of a system whose rows are divided among the ranks:
 * identical numbers, identical decisions); n is small (an MPI_Allgather of n values a rank). Nothing on one
 * rank. */
int sl_linsolve_sum_ordered(double *x, int n, sl_diag *d);
/* A system whose rows are divided among the ranks (core/assembly/system.h): A and b hold this rank's part of
 * every row it touches; afterwards each rank holds the rows it owns complete and zeros elsewhere. The parts are
 * added with PETSc's MatSetValues and VecSetValues (ADD_VALUES), a row another rank owns travelling there
 * through PETSc's stash in MatAssemblyBegin/End, into a matrix and a vector kept in rows->exchange; A's values
 * only with `matrix` (then A is touched). Collective. SL_EFAILED without PETSc. */
int sl_linsolve_rows_complete(sl_rows *rows, sl_csr *A, double *b, int matrix, sl_diag *d);
/* The cells' partition among `ranks` ranks (the number launched): part[e] is the rank of element e, on every
 * rank the same. The cells' graph (two elements are neighbours when they share an unknown, the edge weighted by
 * how many) is partitioned by PETSc's MatPartitioning, PT-Scotch by default (Debian's PETSc has no ParMETIS;
 * -mat_partitioning_type chooses another), so that the cut, the border the ranks exchange, is small.
 * Collective. SL_EFAILED without PETSc. */
int sl_linsolve_partition(int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs, int32_t n_dofs, int ranks,
                          int32_t *part, sl_diag *d);
/* Frees rows->exchange. */
void sl_linsolve_rows_free(sl_rows *rows);
/* What sl_linsolve_rows_complete did in this process (the last pattern's sizes): all zero on one rank. */
typedef struct sl_rows_stats {
  double seconds;           /* wall seconds in sl_linsolve_rows_complete */
  double waiting;           /* with sl_linsolve_rows_profile: of those, before them, waiting for the other ranks */
  long calls, matrix_calls; /* its calls, those with the matrix among them */
  int ranks;
  long rows, owned_rows; /* the system's rows, this rank's */
  long entries_here;     /* this rank's matrix: the entries of the rows its elements touch */
  long owned_entries;    /* of those, in its own rows */
  long all_entries;      /* the owned entries of every rank: the whole matrix's entries */
  long border_entries;   /* of the owned entries, those in a column another rank owns (the off-rank block) */
  long all_border;       /* the border entries of every rank */
} sl_rows_stats;
void sl_linsolve_rows_stats(sl_rows_stats *st);
/* On (`sluice run --profile`): the ranks meet (MPI_Barrier) before each sl_linsolve_rows_complete, so that its
 * time is the exchange's own and the time a rank waited for a slower one is counted apart (stats.waiting). */
void sl_linsolve_rows_profile(int on);

typedef struct sl_linsolve sl_linsolve;

/* By name: "umfpack" | "klu" | "cholmod" | "petsc"; NULL or "" gives "umfpack".
 * Unknown names: SL_EBADINPUT with a did-you-mean. */
int sl_linsolve_create(sl_linsolve **ls, const char *name, sl_diag *d);
int sl_linsolve_create_ops(sl_linsolve **ls, const sl_linsolve_ops *ops, sl_diag *d);
void sl_linsolve_destroy(sl_linsolve *ls);
/* Once: when a numeric factorisation fails because this solver finds the matrix numerically singular
 * (stats.singular), the solver `name` (with the ordering SL_ORDERING_* where it takes one) takes over for
 * the rest of the run and factorises the same matrix; the summary says so. For a choice made on the
 * user's behalf (linear = auto): UMFPACK's pivot ratio, min |U_ii| / max |U_ii| of the scaled matrix, is a
 * crude condition estimate that calls some well-posed saddle points singular (the DFG cylinder in Q2/Q1
 * quadrangles, 2.5e-19) that KLU factorises with a condition estimate far above the epsilon. */
int sl_linsolve_set_fallback(sl_linsolve *ls, const char *name, int ordering, sl_diag *d);
/* The fallback taken, for a log ("umfpack found the matrix numerically singular (pivot ratio 2.5e-19): klu
 * took over"), or "" when none; sl_linsolve_summary starts with it. */
const char *sl_linsolve_fallback_note(const sl_linsolve *ls);

/* The default solver for n unknowns, chosen by measurement (bench_transient_cost,
 * docs/transient_cost.md): "klu" below SL_LINSOLVE_KLU_MAX_UNKNOWNS, where its
 * cheaper refactorisations and back-substitutions win (the 2-D scenes with
 * factorisation reuse: 13-25 % less CPU than UMFPACK), and at every size
 * when the process runs on the reference BLAS (UMFPACK then takes 3-4 times
 * longer); "umfpack" from there with an optimised BLAS, whose supernodal
 * kernels win the large factorisations (the Stokes cavity on 128 x 128
 * cells, 149 k unknowns: 6.9 s against KLU's 10.5 s; equal at 28 k). */
enum { SL_LINSOLVE_KLU_MAX_UNKNOWNS = 20000 };
const char *sl_linsolve_default_name(int32_t n);
/* The default for a matrix factorised once or twice a run, whose few solves follow one factorisation each (the
 * split step's coupled start, core/models/navier_stokes/flow.c): "umfpack" with an optimised BLAS from
 * SL_LINSOLVE_ONCE_UMFPACK_MIN unknowns on, "klu" below it and on the reference BLAS. KLU's cheaper
 * refactorisations are not used there, and UMFPACK's supernodal factorisation is faster on the larger matrices:
 * spinup's start (15 484 unknowns, one factorisation and an FGMRES solve with it) 0.27 s of CPU against KLU's
 * 0.37 s for the whole one-step run; boycott's (7 195) 0.03-0.05 s either way (docs/transient_cost.md). */
enum { SL_LINSOLVE_ONCE_UMFPACK_MIN = 10000 };
const char *sl_linsolve_default_name_once(int32_t n);

/* The names accepted by sl_linsolve_create, for help text. */
const char *const *sl_linsolve_names(int *n);
/* 1 when this build has the solver `name`. */
int sl_linsolve_built(const char *name);

/* Factorise as needed: symbolic when A's pattern differs from the last one,
 * numeric when A's values generation (or A itself) differs, or after
 * sl_linsolve_values_changed. Returns 0, SL_EBADINPUT (not square, empty) or
 * SL_EFAILED (singular, not positive definite, out of memory). */
int sl_linsolve_factor(sl_linsolve *ls, const sl_csr *A, sl_diag *d);
/* Factorise as needed, then x = A^-1 b. x may be b (solved in place). A
 * non-finite solution is SL_EFAILED. */
int sl_linsolve_solve(sl_linsolve *ls, const sl_csr *A, const double *b, double *x, sl_diag *d);
/* The system is a saddle point whose first `split` unknowns are one field (the velocity) and the rest the
 * other (the pressure), from a transient step (a mass term in the velocity block) or a steady one: a backend
 * that can use it (PETSc's field split, whose Schur preconditioner depends on it) does; the direct ones
 * ignore it. */
int sl_linsolve_set_blocks(sl_linsolve *ls, int32_t split, int transient, sl_diag *d);

/* What a system is among the several of one run, for an iterative backend's defaults and options (the direct
 * backends ignore it). PETSc: the solver reads its options under the role's prefix (-velocity_ksp_type,
 * -poisson_pc_type ...), and its defaults are the role's: the split step's velocity block (nonsymmetric, its
 * mass term dominant) GMRES with ILU(0), block Jacobi with ILU(0) on each rank's rows on several ranks; its
 * pressure Poisson operator (symmetric positive definite) CG with BoomerAMG (GAMG without hypre); the rotating
 * frame's Poisson operator (nonsymmetric) GMRES with BoomerAMG. */
enum {
  SL_LINSOLVE_ROLE_ANY = 0,
  SL_LINSOLVE_ROLE_VELOCITY,      /* prefix "velocity_" */
  SL_LINSOLVE_ROLE_POISSON,       /* prefix "poisson_", symmetric positive definite */
  SL_LINSOLVE_ROLE_POISSON_NONSYM, /* prefix "poisson_", nonsymmetric */
  SL_LINSOLVE_ROLE_PRECONDITIONER  /* a Krylov solver's preconditioner: KLU solves with its factors in single
                                      precision (core/solve/ls_klu.c) */
};
int sl_linsolve_set_role(sl_linsolve *ls, int role, sl_diag *d);

/* Force a numeric factorisation at the next solve (values written without
 * sl_csr_touch). */
void sl_linsolve_values_changed(sl_linsolve *ls);

/* The next factorisation or solve starts as a new solver would (analysis
 * and factorisation afresh, no reuse pending), unless the factorisation in
 * hand is exactly what a new solver would compute for that matrix (the
 * first after the analysis of the same values: a constant operator stays
 * factorised once). A run restarted from a checkpoint starts with a new
 * solver; the run that writes the checkpoint calls this, so that both go
 * on bit for bit the same (reuse and KLU's refactorisation depend on what
 * came before). */
void sl_linsolve_drop_numeric(sl_linsolve *ls);

/* The factorisation in hand as a checkpoint holds it, so that a restarted run rebuilds the very factorisation
 * the uninterrupted run goes on with and both go on bit for bit the same (the reuse path's FGMRES and KLU's
 * refactorisation, which keeps the pivots of an earlier factorisation, depend on what came before): the state
 * [have a factorisation, refactorised, refactorise at the next solve, factorisations since the analysis,
 * nonzeros] then the values the pivots were chosen for and, when the factorisation in hand is a
 * refactorisation, the values it was computed from. *out points into ls (valid until its next factorisation
 * or destruction); the length is 0 when there is nothing a restart can rebuild that way (no factorisation, an
 * iterative backend, a matrix divided among ranks): the caller then drops the factorisation
 * (sl_linsolve_drop_numeric). */
enum { SL_LINSOLVE_HISTORY_HEAD = 5 };
int64_t sl_linsolve_history(sl_linsolve *ls, const double **out);
/* From a checkpoint's array (sl_linsolve_history): the next factorisation or solve analyses its matrix,
 * factorises the values the pivots were chosen for, refactorises the kept values with those pivots and goes on
 * as the run that wrote it. SL_EBADINPUT when the array is not such a state. */
int sl_linsolve_restore_history(sl_linsolve *ls, const double *h, int64_t n, sl_diag *d);

/* x with |b - A x|_2 <= rtol |b|_2: when only A's values changed since the
 * last factorisation and reuse is on, by FGMRES preconditioned with that
 * factorisation; otherwise (rtol <= 0, reuse off, a new pattern, no
 * factorisation yet, FGMRES failing) as sl_linsolve_solve. */
int sl_linsolve_solve_rtol(sl_linsolve *ls, const sl_csr *A, const double *b, double *x, double rtol, sl_diag *d);

/* The reuse policy. On by default (it only acts in sl_linsolve_solve_rtol). */
typedef struct sl_linsolve_reuse {
  int enabled;
  int max_iterations;  /* FGMRES budget of one solve (no restart); default 20 */
  int slow_iterations; /* a reuse needing more refactorises at the next solve; default 7 */
} sl_linsolve_reuse;
void sl_linsolve_set_reuse(sl_linsolve *ls, const sl_linsolve_reuse *policy);
sl_linsolve_reuse sl_linsolve_get_reuse(const sl_linsolve *ls);
/* "auto" (the defaults) | "never"; SL_EBADINPUT with a did-you-mean otherwise. */
int sl_linsolve_set_reuse_name(sl_linsolve *ls, const char *name, sl_diag *d);

/* The ordering by name ("auto" | "amd" | "colamd" | "metis"), for the next
 * symbolic analysis. SL_EBADINPUT for an unknown name (with a did-you-mean)
 * or a backend that takes no ordering (umfpack, cholmod). */
int sl_linsolve_set_ordering(sl_linsolve *ls, const char *name, sl_diag *d);

const char *sl_linsolve_name(const sl_linsolve *ls);
/* e.g. "UMFPACK V5.7.9 (Oct 20, 2019): multifrontal LU, ..." for provenance. */
const char *sl_linsolve_description(const sl_linsolve *ls);
const sl_linsolve_stats *sl_linsolve_get_stats(const sl_linsolve *ls);
/* One line for the run summary, e.g.
 * "umfpack: 1 symbolic 0.012 s, 3 numeric 0.150 s, 40 solves 0.020 s" or
 * "klu (amd ordering): 1 symbolic ..., 13 numeric ..., 159 reused (FGMRES
 * 7.5 iterations a solve, 0 refactorised) ..., 172 solves ...". */
void sl_linsolve_summary(const sl_linsolve *ls, char *buf, size_t len);
/* Shorter: the backend and what it did ("petsc, gmres/bjacobi, 637 iterations, 2 ranks"; a direct backend's
 * numeric factorisations). */
void sl_linsolve_describe(const sl_linsolve *ls, char *buf, size_t len);

#endif
