/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A linear system assembled element by element: the CSR matrix whose
 * pattern comes from the element dof lists, the element-to-CSR position map
 * built once with it (the hot loop does no searching), and the right-hand
 * side. Dirichlet constraints are collected per dof and applied once.
 *
 * Typical use:
 *   sl_system_init(&s, n_dofs, n_cells, dofs_per_cell, cell_dofs, d);
 *   sl_system_zero(&s); sl_assemble_...(&s, ...);       (operators.h)
 *   sl_constraints_apply(&bc, &s, 1, d);
 *   sl_linsolve_solve(ls, &s.A, s.b, x, d);
 * Re-assembling with the same pattern keeps the symbolic factorisation. */
#ifndef SLUICE_ASSEMBLY_SYSTEM_H
#define SLUICE_ASSEMBLY_SYSTEM_H

#include <stdint.h>

#include "core/fe/dofmap.h"
#include "core/fe/field.h"
#include "core/solve/sparse.h"
#include "core/util/diag.h"

typedef struct sl_system {
  int32_t n_dofs;
  int32_t n_elem;
  int dofs_per_elem;
  const int32_t *elem_dofs; /* borrowed: [n_elem * dofs_per_elem] */
  sl_csr A;
  sl_csr_elem_map map;
  double *b; /* [n_dofs] */
  /* sl_system_own_elements: this rank's elements [elem_begin, elem_end) (else all) */
  int32_t elem_begin, elem_end;
  int distributed;
} sl_system;

/* Builds the pattern and the element map. elem_dofs must outlive the
 * system. Returns 0, SL_EBADINPUT (dof out of range) or SL_EFAILED. */
int sl_system_init(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                   sl_diag *d);
void sl_system_free(sl_system *s);
/* A = 0 and b = 0, pattern kept. */
void sl_system_zero(sl_system *s);
/* A += Ke (row-major, element dof order) and b += be (either may be NULL). An element another rank owns
 * (sl_system_own_elements) adds nothing. */
int sl_system_add_element(sl_system *s, int32_t e, const double *Ke, const double *be, sl_diag *d);

/* ---- partitioned assembly (several ranks, mpirun) ------------------------- */

/* The elements of rank `rank` of `ranks`: a contiguous block of the element numbering, [n e / N, n (e + 1) / N)
 * for e = rank, N = ranks (the mesh generators number the cells row by row, gmsh front by front, so that a
 * block is a compact piece of the domain). */
void sl_system_partition(int32_t n_elem, int rank, int ranks, int32_t *begin, int32_t *end);
/* From now on the system is assembled on several ranks, each adding its own elements [begin, end) only
 * (an assembly loop asks sl_system_elements which those are); sl_system_complete sums the ranks' parts. */
void sl_system_own_elements(sl_system *s, int32_t begin, int32_t end);
/* The elements this rank assembles: [*begin, *end) (all of them unless sl_system_own_elements). */
void sl_system_elements(const sl_system *s, int32_t *begin, int32_t *end);
/* After the elements are added, before the constraints: a system assembled on several ranks holds on each
 * only its own elements' part; this sums the parts over the ranks (b, and A's values with `matrix`), so that
 * every rank holds the whole assembled system, the same on every rank (one MPI_Allreduce). Nothing on one
 * rank. */
int sl_system_complete(sl_system *s, int matrix, sl_diag *d);

/* ---- Dirichlet constraints ---------------------------------------------- */

typedef struct sl_constraints {
  int32_t n_dofs;
  int32_t n_fixed;      /* distinct fixed dofs */
  unsigned char *fixed; /* [n_dofs] */
  double *value;        /* [n_dofs] */
} sl_constraints;

int sl_constraints_init(sl_constraints *bc, int32_t n_dofs, sl_diag *d);
void sl_constraints_free(sl_constraints *bc);
/* Fixes dof i to v. A dof fixed twice keeps the later value, so the order of
 * calls decides shared corners (e.g. walls after a moving lid). */
void sl_constraints_fix(sl_constraints *bc, int32_t i, double v);
/* Fixes every dof of the named boundary of dm, shifted by `offset` (the
 * block of a velocity component: sl_th_vel_dof(th, c, 0)), to g(node) or,
 * with g NULL, to `value`. */
int sl_constraints_fix_boundary(sl_constraints *bc, const sl_dofmap *dm, const char *boundary, int32_t offset,
                                sl_exact_fn g, void *user, double value, sl_diag *d);
/* Applies all constraints to the assembled system in one call (applying
 * them boundary by boundary would eliminate a shared column twice with
 * different values). `symmetric` also eliminates the columns, keeping a
 * symmetric matrix symmetric. */
int sl_constraints_apply(const sl_constraints *bc, sl_system *s, int symmetric, sl_diag *d);
/* u[i] = value[i] for every fixed dof (initial guesses, Newton updates). */
void sl_constraints_impose(const sl_constraints *bc, double *u);

#endif
