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
 *  - any other system by GMRES(30) with ILU(0), right-preconditioned.
 * The tolerance is on the true residual, |b - A x| <= rtol |b| (right
 * preconditioning): 1e-10 for a solve that must be exact to Newton's eye,
 * the caller's for an inexact Newton correction. A solve that does not
 * converge is SL_EFAILED with PETSc's reason. */
#include <petscksp.h>
#include <stdlib.h>
#include <string.h>

#include "core/solve/linsolve.h"

_Static_assert(sizeof(PetscInt) == sizeof(int32_t), "PETSc built with 32-bit indices, as sluice's CSR");
_Static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc built with real double scalars");

enum { PETSC_EXACT_MAX_IT = 10000 };
#define PETSC_EXACT_RTOL 1e-10

typedef struct petsc_state {
  Mat A;
  KSP ksp;
  Vec b, x;
  int32_t n, split; /* split > 0: unknowns [0, split) and [split, n) are a saddle point's two fields */
  int configured;   /* the KSP has its type and options */
  long iterations;
} petsc_state;

static int petsc_started;

static void petsc_finish(void) {
  if (petsc_started) PetscFinalize();
  petsc_started = 0;
}

static int petsc_fail(PetscErrorCode e, const char *what, sl_diag *d) {
  const char *text = NULL;
  PetscErrorMessage(e, &text, NULL);
  return sl_diag_set(d, SL_EFAILED, "petsc: %s failed (error %d: %s)", what, (int)e, text ? text : "unknown");
}

#define TRY(call, what)                           \
  do {                                            \
    PetscErrorCode e_ = (call);                   \
    if (e_) return petsc_fail(e_, (what), d);     \
  } while (0)

/* Options given by sl_linsolve_petsc_options before PETSc starts. */
static char *pending_options;

int sl_linsolve_petsc_options(const char *options, sl_diag *d) {
  if (!options || !*options) return 0;
  if (petsc_started) {
    PetscErrorCode e = PetscOptionsInsertString(NULL, options);
    return e ? petsc_fail(e, "reading the options", d) : 0;
  }
  size_t have = pending_options ? strlen(pending_options) : 0, add = strlen(options);
  char *p = realloc(pending_options, have + add + 2);
  if (!p) return sl_diag_set(d, SL_ENOMEM, "petsc: out of memory");
  if (have) p[have++] = ' ';
  memcpy(p + have, options, add + 1);
  pending_options = p;
  return 0;
}

static int petsc_start(sl_diag *d) {
  if (petsc_started) return 0;
  /* PETSC_OPTIONS (the environment) is read by PetscInitialize */
  PetscErrorCode e = PetscInitialize(NULL, NULL, NULL, NULL);
  if (e) return sl_diag_set(d, SL_EFAILED, "petsc: PetscInitialize failed (error %d)", (int)e);
  petsc_started = 1;
  atexit(petsc_finish);
  if (pending_options) {
    e = PetscOptionsInsertString(NULL, pending_options);
    free(pending_options);
    pending_options = NULL;
    if (e) return petsc_fail(e, "reading the options", d);
  }
  return 0;
}

/* An option's default, unless the user gave it. */
static PetscErrorCode option_default(const char *name, const char *value) {
  PetscBool set = PETSC_FALSE;
  PetscErrorCode e = PetscOptionsHasName(NULL, NULL, name, &set);
  if (e || set) return e;
  return PetscOptionsSetValue(NULL, name, value);
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

static int petsc_set_blocks(void *backend, int32_t split, sl_diag *d) {
  (void)d;
  petsc_state *s = backend;
  s->split = split;
  s->configured = 0;
  return 0;
}

/* The KSP's type and preconditioner for the system's structure, then the user's options over them. */
static int configure(petsc_state *s, sl_diag *d) {
  PC pc;
  TRY(KSPGetPC(s->ksp, &pc), "KSPGetPC");
  if (s->split > 0 && s->split < s->n) {
    PetscBool hypre = PETSC_FALSE;
    TRY(PetscHasExternalPackage("hypre", &hypre), "PetscHasExternalPackage");
    TRY(KSPSetType(s->ksp, KSPFGMRES), "KSPSetType");
    TRY(PCSetType(pc, PCFIELDSPLIT), "PCSetType");
    IS u, p;
    TRY(ISCreateStride(PETSC_COMM_SELF, s->split, 0, 1, &u), "ISCreateStride");
    TRY(ISCreateStride(PETSC_COMM_SELF, s->n - s->split, s->split, 1, &p), "ISCreateStride");
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
    TRY(option_default("-fieldsplit_p_ksp_type", "preonly"), "options");
    TRY(option_default("-fieldsplit_p_pc_type", "jacobi"), "options");
  } else {
    TRY(KSPSetType(s->ksp, KSPGMRES), "KSPSetType");
    TRY(PCSetType(pc, PCILU), "PCSetType");
  }
  TRY(KSPSetPCSide(s->ksp, PC_RIGHT), "KSPSetPCSide");
  TRY(KSPSetNormType(s->ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  TRY(KSPSetFromOptions(s->ksp), "KSPSetFromOptions");
  s->configured = 1;
  return 0;
}

static int petsc_symbolic(void *backend, const sl_csr *A, sl_diag *d) {
  petsc_state *s = backend;
  petsc_release(s);
  s->n = A->n_rows;
  TRY(MatCreate(PETSC_COMM_SELF, &s->A), "MatCreate");
  TRY(MatSetSizes(s->A, A->n_rows, A->n_cols, A->n_rows, A->n_cols), "MatSetSizes");
  TRY(MatSetType(s->A, MATSEQAIJ), "MatSetType");
  TRY(MatSeqAIJSetPreallocationCSR(s->A, (const PetscInt *)A->row_ptr, (const PetscInt *)A->col_idx, A->values),
      "MatSeqAIJSetPreallocationCSR");
  TRY(MatCreateVecs(s->A, &s->x, &s->b), "MatCreateVecs");
  TRY(KSPCreate(PETSC_COMM_SELF, &s->ksp), "KSPCreate");
  return 0;
}

static int petsc_numeric(void *backend, const sl_csr *A, sl_linsolve_stats *st, sl_diag *d) {
  (void)st;
  petsc_state *s = backend;
  PetscScalar *v;
  TRY(MatSeqAIJGetArray(s->A, &v), "MatSeqAIJGetArray");
  memcpy(v, A->values, (size_t)A->nnz * sizeof *v); /* the same pattern, in the same order */
  TRY(MatSeqAIJRestoreArray(s->A, &v), "MatSeqAIJRestoreArray");
  TRY(KSPSetOperators(s->ksp, s->A, s->A), "KSPSetOperators");
  if (!s->configured) return configure(s, d);
  return 0;
}

static int solve_to(petsc_state *s, const double *b, double *x, double rtol, sl_diag *d) {
  TRY(KSPSetTolerances(s->ksp, rtol, 0.0, PETSC_DEFAULT, PETSC_EXACT_MAX_IT), "KSPSetTolerances");
  TRY(VecPlaceArray(s->b, b), "VecPlaceArray");
  TRY(VecPlaceArray(s->x, x), "VecPlaceArray");
  PetscErrorCode e = KSPSolve(s->ksp, s->b, s->x);
  VecResetArray(s->b);
  VecResetArray(s->x);
  if (e) return petsc_fail(e, "KSPSolve", d);
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
  snprintf(buf, len, "%s/%s, %ld iterations", kt ? kt : "?", pt ? pt : "?", s->iterations);
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
                                               .describe = petsc_describe};
