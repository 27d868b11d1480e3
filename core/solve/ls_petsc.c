/* SPDX-License-Identifier: GPL-2.0-or-later */
/* PETSc backend (built with -DSLUICE_WITH_PETSC=ON): a KSP solve of sluice's
 * CSR matrix, on one rank. The matrix is copied into a sequential AIJ matrix
 * of the same pattern; "numeric" hands the new values to the KSP, whose
 * preconditioner is set up again at the next solve.
 *
 * Defaults (every one can be changed with PETSc's own options, from
 * PETSC_OPTIONS, `sluice run --petsc "..."` or a scene's [solver.petsc]):
 *  - a saddle point (the flow: velocity unknowns first, then the pressure;
 *    sl_linsolve_set_blocks) is solved by FGMRES with a Schur-complement
 *    field split (Murphy, Golub & Wathen 2000; Elman, Silvester & Wathen
 *    2014, ch. 9): the velocity block by one V-cycle of hypre's BoomerAMG
 *    (GAMG where PETSc has no hypre), the Schur complement by the
 *    "selfp" approximation A11 - A10 diag(A00)^-1 A01 and Jacobi, upper
 *    triangular factorisation;
 *  - the split step's velocity block and Poisson operator (sl_linsolve_set_role) by GMRES with ILU(0)
 *    (block Jacobi on several ranks) and CG with BoomerAMG, under the options prefixes -velocity_, -poisson_;
 *  - any other system by GMRES(30) with ILU(0), right-preconditioned.
 * The tolerance is on the true residual, |b - A x| <= rtol |b| (right
 * preconditioning): 1e-10 for a solve that must be exact to Newton's eye,
 * the caller's for an inexact Newton correction. A solve that does not
 * converge is SL_EFAILED with PETSc's reason. */
#include <petscksp.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/solve/linsolve.h"

_Static_assert(sizeof(PetscInt) == sizeof(int32_t), "PETSc built with 32-bit indices, as sluice's CSR");
_Static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc built with real double scalars");

enum { PETSC_EXACT_MAX_IT = 10000 };
#define PETSC_EXACT_RTOL 1e-10

typedef struct rows_exchange {
  Mat M;               /* the owned rows, complete after MatAssemblyEnd */
  Vec v;               /* the owned entries of b */
  uint64_t pattern_id; /* of the sluice matrix M was preallocated for */
  PetscInt *cols;      /* one row's columns in the ranks' numbering */
  int32_t n_cols;
} rows_exchange;

typedef struct petsc_state {
  Mat A;
  KSP ksp;
  Vec b, x;            /* this rank's rows */
  Vec x_all;           /* every rank: the whole solution (several ranks) */
  VecScatter to_all;   /* x -> x_all */
  int32_t r0, r1;      /* the rows this rank owns: [r0, r1) */
  int size;            /* ranks in PETSC_COMM_WORLD */
  int32_t n, split;    /* split > 0: unknowns [0, split) and [split, n) are a saddle point's two fields */
  int transient;       /* the velocity block has a mass term */
  int configured;      /* the KSP has its type and options */
  int user_tolerances; /* -ksp_rtol or -ksp_max_it given: they replace the exact solve's */
  long iterations;
  int role;            /* SL_LINSOLVE_ROLE_*: the options prefix and the defaults (sl_linsolve_set_role) */
  const sl_rows *rows; /* the matrix's rows are divided among the ranks (A->rows): this rank's own rows only */
  rows_exchange map;   /* a row's columns in the ranks' numbering (its cols buffer) */
} petsc_state;

static int petsc_started;

/* The option levels, lowest first: a scene's, the user's (--petsc), the environment's (PETSC_OPTIONS, also read
 * by PetscInitialize). They are inserted in that order before a solver is configured, so a higher level wins. */
static char *scene_options, *user_options;

static void petsc_finish(void) {
  if (petsc_started) PetscFinalize();
  petsc_started = 0;
  free(scene_options);
  free(user_options);
  scene_options = user_options = NULL;
}

static int petsc_start(sl_diag *d);

int sl_linsolve_ranks(int *rank, int *size, sl_diag *d) {
  *rank = 0, *size = 1;
  if (!petsc_started && !getenv("OMPI_COMM_WORLD_SIZE") && !getenv("PMI_SIZE")) return 0; /* not launched */
  int rc = petsc_start(d);
  if (rc) return rc;
  PetscMPIInt r = 0, n = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  MPI_Comm_size(PETSC_COMM_WORLD, &n);
  *rank = r, *size = n;
  return 0;
}

int sl_linsolve_agree(int rc) {
  PetscMPIInt n = 1;
  if (!petsc_started || MPI_Comm_size(PETSC_COMM_WORLD, &n) || n == 1) return rc;
  int all = rc;
  if (MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD)) return rc ? rc : SL_EFAILED;
  return all;
}

static int petsc_fail(PetscErrorCode e, const char *what, sl_diag *d) {
  const char *text = NULL;
  PetscErrorMessage(e, &text, NULL);
  return sl_diag_set(d, SL_EFAILED, "petsc: %s failed (error %d: %s)", what, (int)e, text ? text : "unknown");
}

#define TRY(call, what)                       \
  do {                                        \
    PetscErrorCode e_ = (call);               \
    if (e_) return petsc_fail(e_, (what), d); \
  } while (0)

int sl_linsolve_sum_ordered(double *x, int n, sl_diag *d) {
  PetscMPIInt size = 1, rank = 0;
  if (!petsc_started || MPI_Comm_size(PETSC_COMM_WORLD, &size) || size == 1 || n <= 0) return 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  double *all = malloc((size_t)size * (size_t)n * sizeof *all);
  if (!all) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  if (MPI_Allgather(x, n, MPI_DOUBLE, all, n, MPI_DOUBLE, PETSC_COMM_WORLD)) {
    free(all);
    return sl_diag_set(d, SL_EFAILED, "petsc: gathering the ranks' partial sums failed");
  }
  for (int k = 0; k < n; ++k) {
    double sum = 0.0;
    for (PetscMPIInt q = 0; q < size; ++q) sum += all[(size_t)q * n + k]; /* rank order, the same everywhere */
    x[k] = sum;
  }
  free(all);
  return 0;
}

/* ---- a system whose rows are divided among the ranks ------------------------------------------------------ */

static sl_rows_stats rows_stats;

static int rows_profile;

void sl_linsolve_rows_stats(sl_rows_stats *st) { *st = rows_stats; }
void sl_linsolve_rows_profile(int on) { rows_profile = on; }

static double wall_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void sl_linsolve_rows_free(sl_rows *rows) {
  rows_exchange *x = rows->exchange;
  if (!x) return;
  if (petsc_started) {
    if (x->M) MatDestroy(&x->M);
    if (x->v) VecDestroy(&x->v);
  }
  free(x->cols);
  free(x);
  rows->exchange = NULL;
}

/* Row i's columns in the ranks' numbering, into a buffer of the longest row. */
static PetscInt *global_cols(rows_exchange *x, const sl_rows *rows, const sl_csr *A, int32_t i) {
  int32_t k0 = A->row_ptr[i], nc = A->row_ptr[i + 1] - k0;
  for (int32_t k = 0; k < nc; ++k) x->cols[k] = rows->global[A->col_idx[k0 + k]];
  return x->cols;
}

/* A distributed AIJ matrix of the owned rows of A (their complete pattern), preallocated exactly: the diagonal
 * block's and the off-diagonal block's entries of each owned row. */
static int create_owned_matrix(const sl_rows *rows, const sl_csr *A, Mat *M, sl_diag *d) {
  int32_t nloc = rows->end - rows->begin;
  PetscInt *dn = malloc(((size_t)nloc + 1) * sizeof *dn), *on = malloc(((size_t)nloc + 1) * sizeof *on);
  if (!dn || !on) {
    free(dn), free(on);
    return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  }
  for (int32_t k = 0; k < nloc; ++k) {
    int32_t i = rows->local[k];
    dn[k] = on[k] = 0;
    for (int32_t p = A->row_ptr[i]; p < A->row_ptr[i + 1]; ++p) {
      int32_t g = rows->global[A->col_idx[p]];
      if (g >= rows->begin && g < rows->end) ++dn[k];
      else ++on[k];
    }
  }
  PetscErrorCode e = MatCreate(PETSC_COMM_WORLD, M);
  if (!e) e = MatSetSizes(*M, nloc, nloc, A->n_rows, A->n_cols);
  if (!e) e = MatSetType(*M, MATMPIAIJ);
  if (!e) e = MatMPIAIJSetPreallocation(*M, 0, dn, 0, on);
  if (!e) e = MatSetOption(*M, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE);
  free(dn), free(on);
  if (e) return petsc_fail(e, "creating the distributed matrix", d);
  return 0;
}

static int rows_prepare(rows_exchange *x, const sl_rows *rows, const sl_csr *A, sl_diag *d) {
  int32_t longest = 1;
  for (int32_t i = 0; i < A->n_rows; ++i)
    if (A->row_ptr[i + 1] - A->row_ptr[i] > longest) longest = A->row_ptr[i + 1] - A->row_ptr[i];
  if (longest > x->n_cols) {
    PetscInt *c = realloc(x->cols, (size_t)longest * sizeof *c);
    if (!c) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
    x->cols = c, x->n_cols = longest;
  }
  if (x->M) MatDestroy(&x->M);
  int rc = create_owned_matrix(rows, A, &x->M, d);
  if (rc) return rc;
  x->pattern_id = A->pattern_id;
  sl_rows_stats *st = &rows_stats;
  PetscMPIInt size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  st->ranks = size, st->rows = rows->n, st->owned_rows = rows->end - rows->begin, st->entries_here = A->nnz;
  st->owned_entries = st->border_entries = 0;
  for (int32_t k = 0; k < rows->end - rows->begin; ++k)
    for (int32_t p = A->row_ptr[rows->local[k]]; p < A->row_ptr[rows->local[k] + 1]; ++p) {
      int32_t g = rows->global[A->col_idx[p]];
      ++st->owned_entries;
      st->border_entries += g < rows->begin || g >= rows->end;
    }
  long mine[2] = {st->owned_entries, st->border_entries}, all[2];
  if (MPI_Allreduce(mine, all, 2, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD))
    return sl_diag_set(d, SL_EFAILED, "petsc: counting the matrix's entries over the ranks failed");
  st->all_entries = all[0], st->all_border = all[1];
  return 0;
}

int sl_linsolve_rows_complete(sl_rows *rows, sl_csr *A, double *b, int matrix, sl_diag *d) {
  int rc = petsc_start(d);
  if (rc) return rc;
  double t0 = wall_now();
  if (rows_profile) {
    if (MPI_Barrier(PETSC_COMM_WORLD)) return sl_diag_set(d, SL_EFAILED, "petsc: MPI_Barrier failed");
    double t1 = wall_now();
    rows_stats.waiting += t1 - t0;
    t0 = t1;
  }
  rows_exchange *x = rows->exchange;
  if (!x) {
    if (!(x = calloc(1, sizeof *x))) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
    rows->exchange = x;
  }
  int32_t nloc = rows->end - rows->begin;
  if (matrix) {
    if (!x->M || x->pattern_id != A->pattern_id) {
      if ((rc = rows_prepare(x, rows, A, d))) return rc;
    } else {
      TRY(MatZeroEntries(x->M), "MatZeroEntries");
    }
    /* every row this rank's elements touched: its own rows stay here, the others go to their owners */
    for (int32_t i = 0; i < A->n_rows; ++i) {
      int32_t k0 = A->row_ptr[i], nc = A->row_ptr[i + 1] - k0;
      if (nc == 0) continue;
      PetscInt g = rows->global[i];
      TRY(MatSetValues(x->M, 1, &g, nc, global_cols(x, rows, A, i), A->values + k0, ADD_VALUES), "MatSetValues");
    }
    TRY(MatAssemblyBegin(x->M, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    TRY(MatAssemblyEnd(x->M, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    /* the owned rows back, complete; the others zero (another rank holds them) */
    for (int32_t i = 0; i < A->n_rows; ++i) {
      int32_t k0 = A->row_ptr[i], nc = A->row_ptr[i + 1] - k0;
      if (nc == 0) continue;
      if (!rows->owned[i]) {
        memset(A->values + k0, 0, (size_t)nc * sizeof *A->values);
        continue;
      }
      PetscInt g = rows->global[i];
      TRY(MatGetValues(x->M, 1, &g, nc, global_cols(x, rows, A, i), A->values + k0), "MatGetValues");
    }
    sl_csr_touch(A);
    ++rows_stats.matrix_calls;
  }
  if (!x->v) TRY(VecCreateMPI(PETSC_COMM_WORLD, nloc, rows->n, &x->v), "VecCreateMPI");
  TRY(VecSet(x->v, 0.0), "VecSet");
  for (int32_t i = 0; i < rows->n; ++i) {
    if (b[i] == 0.0) continue;
    PetscInt g = rows->global[i];
    TRY(VecSetValues(x->v, 1, &g, b + i, ADD_VALUES), "VecSetValues");
  }
  TRY(VecAssemblyBegin(x->v), "VecAssemblyBegin");
  TRY(VecAssemblyEnd(x->v), "VecAssemblyEnd");
  memset(b, 0, (size_t)rows->n * sizeof *b);
  const PetscScalar *v;
  TRY(VecGetArrayRead(x->v, &v), "VecGetArrayRead");
  for (int32_t k = 0; k < nloc; ++k) b[rows->local[k]] = v[k];
  TRY(VecRestoreArrayRead(x->v, &v), "VecRestoreArrayRead");
  ++rows_stats.calls;
  rows_stats.seconds += wall_now() - t0;
  return 0;
}

static int keep(char **level, const char *options, sl_diag *d) {
  free(*level);
  *level = NULL;
  if (!options || !*options) return 0;
  if (!(*level = strdup(options))) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  return 0;
}

int sl_linsolve_petsc_options(const char *options, sl_diag *d) { return keep(&user_options, options, d); }
int sl_linsolve_petsc_scene_options(const char *options, sl_diag *d) { return keep(&scene_options, options, d); }

static int insert_levels(sl_diag *d) {
  const char *levels[3] = {scene_options, user_options, getenv("PETSC_OPTIONS")};
  static const char *const names[3] = {"[solver.petsc]", "--petsc", "PETSC_OPTIONS"};
  for (int i = 0; i < 3; ++i) {
    if (!levels[i] || !*levels[i]) continue;
    PetscErrorCode e = PetscOptionsInsertString(NULL, levels[i]);
    if (e) return sl_diag_set(d, SL_EBADINPUT, "petsc: cannot read the options of %s (\"%s\")", names[i], levels[i]);
  }
  /* -log_view given after PetscInitialize: PETSc's logging must start now, or PetscFinalize fails */
  static int logging;
  PetscBool log_view = PETSC_FALSE;
  if (!logging && !PetscOptionsHasName(NULL, NULL, "-log_view", &log_view) && log_view) {
    PetscErrorCode e = PetscLogDefaultBegin();
    if (e) return petsc_fail(e, "starting PETSc's logging for -log_view", d);
    logging = 1;
  }
  return 0;
}

static int petsc_start(sl_diag *d) {
  if (petsc_started) return 0;
  PetscErrorCode e = PetscInitializeNoArguments();
  if (e) return sl_diag_set(d, SL_EFAILED, "petsc: PetscInitialize failed (error %d)", (int)e);
  petsc_started = 1;
  atexit(petsc_finish);
  return 0;
}

/* An option's default, unless the user gave it. The defaults are set in PETSc's global options only while one
 * solver is configured (cleared after its KSPSetUp), so each solver gets its own and a user's stays the user's. */
enum { MAX_DEFAULTS = 8 };
static const char *defaults_set[MAX_DEFAULTS];
static int n_defaults_set;

static PetscErrorCode option_default(const char *name, const char *value) {
  PetscBool set = PETSC_FALSE;
  PetscErrorCode e = PetscOptionsHasName(NULL, NULL, name, &set);
  if (e || set || n_defaults_set == MAX_DEFAULTS) return e;
  defaults_set[n_defaults_set++] = name;
  return PetscOptionsSetValue(NULL, name, value);
}

static void clear_defaults(void) {
  for (int i = 0; i < n_defaults_set; ++i) PetscOptionsClearValue(NULL, defaults_set[i]);
  n_defaults_set = 0;
}

static int petsc_create(void **backend, sl_diag *d) {
  int rc = petsc_start(d);
  if (rc) return rc;
  petsc_state *s = calloc(1, sizeof *s);
  if (!s) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  *backend = s;
  return 0;
}

static void petsc_release(petsc_state *s) {
  free(s->map.cols);
  s->map.cols = NULL, s->map.n_cols = 0, s->rows = NULL;
  if (s->to_all) VecScatterDestroy(&s->to_all);
  if (s->x_all) VecDestroy(&s->x_all);
  if (s->ksp) KSPDestroy(&s->ksp);
  if (s->A) MatDestroy(&s->A);
  if (s->b) VecDestroy(&s->b);
  if (s->x) VecDestroy(&s->x);
  s->configured = 0;
}

static void petsc_destroy(void *backend) {
  petsc_state *s = backend;
  if (!s) return;
  if (petsc_started) petsc_release(s);
  free(s);
}

static int petsc_set_blocks(void *backend, int32_t split, int transient, sl_diag *d) {
  (void)d;
  petsc_state *s = backend;
  s->split = split;
  s->transient = transient;
  s->configured = 0;
  return 0;
}

static int petsc_set_role(void *backend, int role, sl_diag *d) {
  petsc_state *s = backend;
  if (role < SL_LINSOLVE_ROLE_ANY || role > SL_LINSOLVE_ROLE_POISSON_NONSYM)
    return sl_diag_set(d, SL_EBADINPUT, "petsc: no solver role %d", role);
  s->role = role;
  s->configured = 0;
  return 0;
}

/* The options prefix of a role (without the leading dash), NULL for none. */
static const char *role_prefix(int role) {
  return role == SL_LINSOLVE_ROLE_VELOCITY                                             ? "velocity_"
         : role == SL_LINSOLVE_ROLE_POISSON || role == SL_LINSOLVE_ROLE_POISSON_NONSYM ? "poisson_"
                                                                                       : NULL;
}

/* A KSP for this solver, reading its options under its role's prefix. */
static int create_ksp(petsc_state *s, sl_diag *d) {
  TRY(KSPCreate(PETSC_COMM_WORLD, &s->ksp), "KSPCreate");
  if (role_prefix(s->role)) TRY(KSPSetOptionsPrefix(s->ksp, role_prefix(s->role)), "KSPSetOptionsPrefix");
  return 0;
}

/* Rows divided among the ranks: this rank's rows of the velocity (sluice rows below split) and of the pressure,
 * in the ranks' numbering (increasing there, as local[] is). */
static int field_sets(const petsc_state *s, IS *u, IS *p, sl_diag *d) {
  const sl_rows *r = s->rows;
  int32_t nloc = r->end - r->begin, nu = 0;
  PetscInt *iu = malloc(((size_t)nloc + 1) * sizeof *iu), *ip = malloc(((size_t)nloc + 1) * sizeof *ip);
  if (!iu || !ip) {
    free(iu), free(ip);
    return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  }
  for (int32_t k = 0; k < nloc; ++k) {
    if (r->local[k] < s->split) iu[nu++] = r->begin + k;
    else ip[k - nu] = r->begin + k;
  }
  PetscErrorCode e = ISCreateGeneral(PETSC_COMM_WORLD, nu, iu, PETSC_COPY_VALUES, u);
  if (!e) e = ISCreateGeneral(PETSC_COMM_WORLD, nloc - nu, ip, PETSC_COPY_VALUES, p);
  free(iu), free(ip);
  if (e) return petsc_fail(e, "ISCreateGeneral", d);
  return 0;
}

/* The KSP's type and preconditioner for the system's structure, then the user's options over them. */
static int configure(petsc_state *s, sl_diag *d) {
  int rc = insert_levels(d);
  if (rc) return rc;
  PC pc;
  TRY(KSPGetPC(s->ksp, &pc), "KSPGetPC");
  if (s->split > 0 && s->split < s->n) {
    PetscBool hypre = PETSC_FALSE;
    TRY(PetscHasExternalPackage("hypre", &hypre), "PetscHasExternalPackage");
    TRY(KSPSetType(s->ksp, KSPFGMRES), "KSPSetType");
    TRY(PCSetType(pc, PCFIELDSPLIT), "PCSetType");
    IS u, p;
    if (s->rows) { /* this rank's rows of each field, in the ranks' numbering */
      rc = field_sets(s, &u, &p, d);
      if (rc) return rc;
    } else { /* this rank's rows of each field */
      int32_t u0 = s->r0, u1 = s->r1 < s->split ? s->r1 : s->split, p0 = s->r0 > s->split ? s->r0 : s->split;
      TRY(ISCreateStride(PETSC_COMM_WORLD, u1 > u0 ? u1 - u0 : 0, u0, 1, &u), "ISCreateStride");
      TRY(ISCreateStride(PETSC_COMM_WORLD, s->r1 > p0 ? s->r1 - p0 : 0, p0, 1, &p), "ISCreateStride");
    }
    PetscErrorCode e = PCFieldSplitSetIS(pc, "u", u);
    if (!e) e = PCFieldSplitSetIS(pc, "p", p);
    ISDestroy(&u);
    ISDestroy(&p);
    if (e) return petsc_fail(e, "PCFieldSplitSetIS", d);
    TRY(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "PCFieldSplitSetType");
    TRY(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER), "PCFieldSplitSetSchurFactType");
    TRY(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, NULL), "PCFieldSplitSetSchurPre");
    TRY(option_default("-fieldsplit_u_ksp_type", "preonly"), "options");
    TRY(option_default("-fieldsplit_u_pc_type", hypre ? "hypre" : "gamg"), "options");
    /* BoomerAMG's default strength threshold (0.25, for 2-D scalar Laplacians) coarsens the coupled velocity block
     * of 2 mu D(u):D(v) badly: 359 FGMRES iterations on the 32 x 32 Stokes cavity, against 47 with 0.7, which
     * stays mesh-independent (47, 47, 49 at 32, 64, 128 cells a side) */
    if (hypre) TRY(option_default("-fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.7"), "options");
    TRY(option_default("-fieldsplit_p_ksp_type", "preonly"), "options");
    /* selfp is B diag(A)^-1 B^T. Steady (viscous) A: S = B A^-1 B^T is spectrally a pressure mass matrix over
     * mu, which Jacobi of selfp matches (47 iterations on the Stokes cavity at any mesh; BoomerAMG on selfp
     * does not converge there); a transient step's mass-dominated A makes S and selfp both a pressure
     * Laplacian, which needs AMG (16 iterations a solve on the boycott vessel; Jacobi does not converge) */
    TRY(option_default("-fieldsplit_p_pc_type", !s->transient ? "jacobi" : hypre ? "hypre" : "gamg"), "options");
  } else if (s->role == SL_LINSOLVE_ROLE_POISSON || s->role == SL_LINSOLVE_ROLE_POISSON_NONSYM) {
    /* the pressure Laplacian: one BoomerAMG V-cycle a Krylov iteration is mesh-independent (Elman, Silvester &
     * Wathen 2014, ch. 2); CG where the operator is symmetric positive definite */
    PetscBool hypre = PETSC_FALSE;
    TRY(PetscHasExternalPackage("hypre", &hypre), "PetscHasExternalPackage");
    TRY(KSPSetType(s->ksp, s->role == SL_LINSOLVE_ROLE_POISSON ? KSPCG : KSPGMRES), "KSPSetType");
    TRY(PCSetType(pc, hypre ? PCHYPRE : PCGAMG), "PCSetType");
  } else {
    /* ILU(0) is sequential in PETSc: on several ranks it runs on each rank's block of rows (block Jacobi) */
    TRY(KSPSetType(s->ksp, KSPGMRES), "KSPSetType");
    TRY(PCSetType(pc, s->size > 1 ? PCBJACOBI : PCILU), "PCSetType");
  }
  /* the tolerance is on the true residual: right preconditioning; CG takes the left side only, with the
   * unpreconditioned norm */
  TRY(KSPSetPCSide(s->ksp, s->role == SL_LINSOLVE_ROLE_POISSON && s->split == 0 ? PC_LEFT : PC_RIGHT), "KSPSetPCSide");
  TRY(KSPSetNormType(s->ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  PetscBool rtol_given = PETSC_FALSE, max_it_given = PETSC_FALSE;
  const char *prefix = role_prefix(s->role);
  TRY(PetscOptionsHasName(NULL, prefix, "-ksp_rtol", &rtol_given), "options");
  TRY(PetscOptionsHasName(NULL, prefix, "-ksp_max_it", &max_it_given), "options");
  s->user_tolerances = rtol_given || max_it_given;
  TRY(KSPSetTolerances(s->ksp, PETSC_EXACT_RTOL, 0.0, PETSC_DEFAULT, PETSC_EXACT_MAX_IT), "KSPSetTolerances");
  PetscErrorCode e = KSPSetFromOptions(s->ksp);
  if (!e) e = KSPSetUp(s->ksp); /* the field split's inner solvers read their options here */
  clear_defaults();
  if (e) return petsc_fail(e, "setting up the solver", d);
  s->configured = 1;
  return 0;
}

/* The rows of rank `rank` of `size`: contiguous, with about as many nonzeros each. */
static void owned_rows(const sl_csr *A, int rank, int size, int32_t *r0, int32_t *r1) {
  int32_t lo = 0, hi = A->n_rows;
  if (size > 1) {
    int64_t nnz = A->row_ptr[A->n_rows];
    int64_t want0 = nnz * rank / size, want1 = nnz * (rank + 1) / size;
    while (lo < A->n_rows && A->row_ptr[lo] < want0) ++lo;
    hi = lo;
    while (hi < A->n_rows && A->row_ptr[hi] < want1) ++hi;
    if (rank == size - 1) hi = A->n_rows;
  }
  *r0 = lo, *r1 = hi;
}

static int petsc_symbolic(void *backend, const sl_csr *A, sl_diag *d) {
  petsc_state *s = backend;
  petsc_release(s);
  s->n = A->n_rows;
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  s->size = size;
  if (A->rows) { /* each rank holds its own rows: they go to PETSc as they are */
    s->rows = A->rows;
    s->r0 = A->rows->begin, s->r1 = A->rows->end;
    int rc = rows_prepare(&s->map, A->rows, A, d);
    if (!rc) s->A = s->map.M, s->map.M = NULL;
    if (rc) return rc;
    TRY(VecCreateMPI(PETSC_COMM_WORLD, s->r1 - s->r0, A->n_rows, &s->b), "VecCreateMPI");
    TRY(VecDuplicate(s->b, &s->x), "VecDuplicate");
    TRY(VecScatterCreateToAll(s->x, &s->to_all, &s->x_all), "VecScatterCreateToAll");
    return create_ksp(s, d);
  }
  owned_rows(A, rank, size, &s->r0, &s->r1);
  int32_t nloc = s->r1 - s->r0;
  TRY(MatCreate(PETSC_COMM_WORLD, &s->A), "MatCreate");
  TRY(MatSetSizes(s->A, nloc, nloc, A->n_rows, A->n_cols), "MatSetSizes");
  if (size == 1) {
    TRY(MatSetType(s->A, MATSEQAIJ), "MatSetType");
    TRY(MatSeqAIJSetPreallocationCSR(s->A, (const PetscInt *)A->row_ptr, (const PetscInt *)A->col_idx, A->values),
        "MatSeqAIJSetPreallocationCSR");
  } else { /* every rank holds the whole system; each hands PETSc its own rows */
    PetscInt *ptr = malloc(((size_t)nloc + 1) * sizeof *ptr);
    if (!ptr) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
    for (int32_t i = 0; i <= nloc; ++i) ptr[i] = A->row_ptr[s->r0 + i] - A->row_ptr[s->r0];
    PetscErrorCode e = MatSetType(s->A, MATMPIAIJ);
    if (!e)
      e = MatMPIAIJSetPreallocationCSR(s->A, ptr, (const PetscInt *)A->col_idx + A->row_ptr[s->r0],
                                       A->values + A->row_ptr[s->r0]);
    free(ptr);
    if (e) return petsc_fail(e, "MatMPIAIJSetPreallocationCSR", d);
    TRY(VecCreateMPI(PETSC_COMM_WORLD, nloc, A->n_rows, &s->b), "VecCreateMPI");
    TRY(VecDuplicate(s->b, &s->x), "VecDuplicate");
    TRY(VecScatterCreateToAll(s->x, &s->to_all, &s->x_all), "VecScatterCreateToAll");
  }
  if (size == 1) TRY(MatCreateVecs(s->A, &s->x, &s->b), "MatCreateVecs");
  return create_ksp(s, d);
}

static int petsc_numeric(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d) {
  (void)st;
  petsc_state *s = backend;
  if (s->rows) { /* this rank's own rows, complete here */
    for (int32_t k = 0; k < s->r1 - s->r0; ++k) {
      int32_t i = s->rows->local[k];
      PetscInt g = s->r0 + k, k0 = A->row_ptr[i], nc = A->row_ptr[i + 1] - k0;
      TRY(MatSetValues(s->A, 1, &g, nc, global_cols(&s->map, s->rows, A, i), A->values + k0, INSERT_VALUES),
          "MatSetValues");
    }
    TRY(MatAssemblyBegin(s->A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    TRY(MatAssemblyEnd(s->A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  } else if (s->size == 1) {
    PetscScalar *v;
    TRY(MatSeqAIJGetArray(s->A, &v), "MatSeqAIJGetArray");
    memcpy(v, A->values, (size_t)A->nnz * sizeof *v); /* the same pattern, in the same order */
    TRY(MatSeqAIJRestoreArray(s->A, &v), "MatSeqAIJRestoreArray");
  } else {
    for (int32_t i = s->r0; i < s->r1; ++i) {
      PetscInt row = i, k0 = A->row_ptr[i], nc = A->row_ptr[i + 1] - k0;
      TRY(MatSetValues(s->A, 1, &row, nc, (const PetscInt *)A->col_idx + k0, A->values + k0, INSERT_VALUES),
          "MatSetValues");
    }
    TRY(MatAssemblyBegin(s->A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    TRY(MatAssemblyEnd(s->A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  }
  TRY(KSPSetOperators(s->ksp, s->A, s->A), "KSPSetOperators");
  if (!s->configured) return configure(s, d);
  return 0;
}

static int converged(petsc_state *s, double rtol, sl_diag *d);

/* Rows divided among the ranks: b's owned entries into PETSc's vector, the solution gathered on every rank (in
 * the ranks' numbering) and read back in sluice's, so that every rank goes on with the same state. */
static int solve_rows(petsc_state *s, const double *b, double *x, double rtol, sl_diag *d) {
  const sl_rows *r = s->rows;
  PetscScalar *v;
  TRY(VecGetArray(s->b, &v), "VecGetArray");
  for (int32_t k = 0; k < r->end - r->begin; ++k) v[k] = b[r->local[k]];
  TRY(VecRestoreArray(s->b, &v), "VecRestoreArray");
  TRY(KSPSolve(s->ksp, s->b, s->x), "KSPSolve");
  TRY(VecScatterBegin(s->to_all, s->x, s->x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  TRY(VecScatterEnd(s->to_all, s->x, s->x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar *all;
  TRY(VecGetArrayRead(s->x_all, &all), "VecGetArrayRead");
  for (int32_t i = 0; i < r->n; ++i) x[i] = all[r->global[i]];
  TRY(VecRestoreArrayRead(s->x_all, &all), "VecRestoreArrayRead");
  return converged(s, rtol, d);
}

static int solve_to(petsc_state *s, const double *b, double *x, double rtol, sl_diag *d) {
  if (!s->user_tolerances)
    TRY(KSPSetTolerances(s->ksp, rtol, 0.0, PETSC_DEFAULT, PETSC_EXACT_MAX_IT), "KSPSetTolerances");
  else KSPGetTolerances(s->ksp, &rtol, NULL, NULL, NULL);
  if (s->rows) return solve_rows(s, b, x, rtol, d);
  /* this rank's part of b (every rank has all of it); the solution gathered on every rank, so that every rank
   * goes on with the same state */
  TRY(VecPlaceArray(s->b, b + s->r0), "VecPlaceArray");
  if (s->size == 1) TRY(VecPlaceArray(s->x, x), "VecPlaceArray");
  PetscErrorCode e = KSPSolve(s->ksp, s->b, s->x);
  VecResetArray(s->b);
  if (s->size == 1) VecResetArray(s->x);
  if (e) return petsc_fail(e, "KSPSolve", d);
  if (s->size > 1) {
    TRY(VecScatterBegin(s->to_all, s->x, s->x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    TRY(VecScatterEnd(s->to_all, s->x, s->x_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar *all;
    TRY(VecGetArrayRead(s->x_all, &all), "VecGetArrayRead");
    memcpy(x, all, (size_t)s->n * sizeof *x);
    TRY(VecRestoreArrayRead(s->x_all, &all), "VecRestoreArrayRead");
  }
  return converged(s, rtol, d);
}

static int converged(petsc_state *s, double rtol, sl_diag *d) {
  KSPConvergedReason why;
  PetscInt its = 0;
  TRY(KSPGetConvergedReason(s->ksp, &why), "KSPGetConvergedReason");
  TRY(KSPGetIterationNumber(s->ksp, &its), "KSPGetIterationNumber");
  s->iterations += its;
  if (why < 0) {
    KSPType type;
    KSPGetType(s->ksp, &type);
    return sl_diag_set(d, SL_EFAILED, "petsc: %s did not converge to %g in %d iterations (%s)", type, rtol, (int)its,
                       KSPConvergedReasons[why]);
  }
  return 0;
}

static int petsc_solve(void *backend, const sl_csr *A, const double *b, double *x, sl_diag *d) {
  (void)A;
  return solve_to(backend, b, x, PETSC_EXACT_RTOL, d);
}

static int petsc_solve_rtol(void *backend, const sl_csr *A, const double *b, double *x, double rtol, sl_diag *d) {
  (void)A;
  return solve_to(backend, b, x, rtol > PETSC_EXACT_RTOL ? rtol : PETSC_EXACT_RTOL, d);
}

static void petsc_describe(void *backend, char *buf, size_t len) {
  petsc_state *s = backend;
  KSPType kt = NULL;
  PCType pt = NULL;
  PC pc;
  if (s->ksp && !KSPGetType(s->ksp, &kt) && !KSPGetPC(s->ksp, &pc)) PCGetType(pc, &pt);
  int k = snprintf(buf, len, "%s/%s, %ld iterations", kt ? kt : "?", pt ? pt : "?", s->iterations);
  if (s->size > 1 && k >= 0 && (size_t)k < len) snprintf(buf + k, len - (size_t)k, ", %d ranks", s->size);
}

const sl_linsolve_ops sl_linsolve_petsc_ops = {.name = "petsc",
                                               .description = "PETSc KSP (Krylov with a preconditioner)",
                                               .create = petsc_create,
                                               .symbolic = petsc_symbolic,
                                               .numeric = petsc_numeric,
                                               .solve = petsc_solve,
                                               .destroy = petsc_destroy,
                                               .solve_rtol = petsc_solve_rtol,
                                               .set_blocks = petsc_set_blocks,
                                               .describe = petsc_describe,
                                               .set_role = petsc_set_role};

/* ---- the cells' partition --------------------------------------------------------------------------------- */

int sl_linsolve_partition(int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs, int32_t n_dofs, int ranks,
                          int32_t *part, sl_diag *d) {
  int rc = petsc_start(d);
  if (rc) return rc;
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size != ranks || n_elem < ranks)
    return sl_diag_set(d, SL_EBADINPUT, "petsc: %d cells cannot be divided among %d ranks (launched on %d)",
                       (int)n_elem, ranks, (int)size);
  const int dpe = dofs_per_elem;
  /* dof -> its cells (CSR), every rank the whole of it */
  int32_t *dptr = calloc((size_t)n_dofs + 2, sizeof *dptr), *dcell = malloc(((size_t)n_elem * dpe + 1) * sizeof *dcell);
  int32_t *stamp = malloc(((size_t)n_elem + 1) * sizeof *stamp), *weight = calloc((size_t)n_elem + 1, sizeof *weight);
  if (!dptr || !dcell || !stamp || !weight) {
    free(dptr), free(dcell), free(stamp), free(weight);
    return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory for the cells' graph");
  }
  for (int64_t k = 0; k < (int64_t)n_elem * dpe; ++k)
    if (elem_dofs[k] >= 0 && elem_dofs[k] < n_dofs) ++dptr[elem_dofs[k] + 2];
  for (int32_t i = 0; i < n_dofs; ++i) dptr[i + 2] += dptr[i + 1];
  for (int32_t e = 0; e < n_elem; ++e)
    for (int a = 0; a < dpe; ++a) {
      int32_t i = elem_dofs[(size_t)e * dpe + a];
      if (i >= 0 && i < n_dofs) dcell[dptr[i + 1]++] = e;
    }
  for (int32_t e = 0; e < n_elem; ++e) stamp[e] = -1;
  /* The graph's rows of this rank: the cells [n r / N, n (r + 1) / N); two cells are neighbours when they share
   * an unknown, the edge weighted by how many they share (the entries a cut between them puts on the border). */
  int32_t e0 = (int32_t)((int64_t)n_elem * rank / size), e1 = (int32_t)((int64_t)n_elem * (rank + 1) / size);
  PetscInt *ai = NULL, *aj = NULL, *aw = NULL, nnz = 0;
  PetscErrorCode e = 0;
  for (int pass = 0; pass < 2 && !e; ++pass) {
    nnz = 0;
    for (int32_t c = e0; c < e1; ++c) {
      if (pass) ai[c - e0] = nnz;
      PetscInt r0 = nnz;
      for (int a = 0; a < dpe; ++a) {
        int32_t i = elem_dofs[(size_t)c * dpe + a];
        if (i < 0 || i >= n_dofs) continue;
        for (int32_t q = dptr[i]; q < dptr[i + 1]; ++q) {
          int32_t f = dcell[q];
          if (f == c) continue;
          if (stamp[f] != c) {
            stamp[f] = c, weight[f] = 0;
            if (pass) aj[nnz] = f;
            ++nnz;
          }
          ++weight[f];
        }
      }
      if (!pass) continue;
      /* sorted columns (insertion: a few tens a row), with their weights */
      for (PetscInt k = r0; k < nnz; ++k) aw[k] = weight[aj[k]];
      for (PetscInt k = r0 + 1; k < nnz; ++k)
        for (PetscInt m = k; m > r0 && aj[m - 1] > aj[m]; --m) {
          PetscInt t = aj[m];
          aj[m] = aj[m - 1], aj[m - 1] = t, t = aw[m], aw[m] = aw[m - 1], aw[m - 1] = t;
        }
    }
    if (!pass) {
      for (int32_t c = 0; c < n_elem; ++c) stamp[c] = -1;
      e = PetscMalloc1(e1 - e0 + 1, &ai);
      if (!e) e = PetscMalloc1(nnz + 1, &aj);
      if (!e) e = PetscMalloc1(nnz + 1, &aw);
    } else {
      ai[e1 - e0] = nnz;
    }
  }
  free(dptr), free(dcell), free(stamp), free(weight);
  if (e) {
    PetscFree(ai), PetscFree(aj), PetscFree(aw);
    return petsc_fail(e, "allocating the cells' graph", d);
  }
  Mat adj = NULL;
  MatPartitioning mp = NULL;
  IS is = NULL, all = NULL;
  /* MatCreateMPIAdj takes ai, aj, aw (freed with adj) */
  e = MatCreateMPIAdj(PETSC_COMM_WORLD, e1 - e0, n_elem, ai, aj, aw, &adj);
  if (e) PetscFree(ai), PetscFree(aj), PetscFree(aw);
  if (!e) e = MatPartitioningCreate(PETSC_COMM_WORLD, &mp);
  if (!e) e = MatPartitioningSetAdjacency(mp, adj);
  if (!e) e = MatPartitioningSetNParts(mp, size);
  /* PT-Scotch: the graph partitioner Debian's PETSc is built with (no ParMETIS there) */
  if (!e) e = MatPartitioningSetType(mp, MATPARTITIONINGPTSCOTCH);
  if (!e) e = MatPartitioningSetFromOptions(mp);
  if (!e) e = MatPartitioningApply(mp, &is);
  if (!e) e = ISAllGather(is, &all);
  const PetscInt *p = NULL;
  if (!e) e = ISGetIndices(all, &p);
  if (!e) {
    for (int32_t c = 0; c < n_elem; ++c) part[c] = (int32_t)p[c];
    e = ISRestoreIndices(all, &p);
  }
  if (all) ISDestroy(&all);
  if (is) ISDestroy(&is);
  if (mp) MatPartitioningDestroy(&mp);
  if (adj) MatDestroy(&adj);
  if (e) return petsc_fail(e, "partitioning the cells", d);
  return 0;
}
