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
  /* sl_system_init_ranks on several ranks: this rank's elements lie in [elem_begin, elem_end) (else all are
   * its own), elem_local[e] the place of element e among them (-1: another rank's), and the rows it owns
   * (A.rows points here: the system must not be moved) */
  int32_t elem_begin, elem_end;
  int32_t *elem_local;
  int distributed;
  sl_rows rows;
} sl_system;

/* Builds the pattern and the element map. elem_dofs must outlive the
 * system. Returns 0, SL_EBADINPUT (dof out of range) or SL_EFAILED. */
int sl_system_init(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                   sl_diag *d);
/* As sl_system_init, without the local pairs (a, b) of every element with keep[a * dofs_per_elem + b] == 0 in
 * the pattern (a block the caller knows to be zero): sl_system_add_element drops those entries of Ke. keep
 * NULL: sl_system_init. */
int sl_system_init_kept(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                        const unsigned char *keep, sl_diag *d);
void sl_system_free(sl_system *s);
/* A = 0 and b = 0, pattern kept. */
void sl_system_zero(sl_system *s);
/* A += Ke (row-major, element dof order) and b += be (either may be NULL). An element another rank assembles
 * (sl_system_init_ranks) adds nothing. */
int sl_system_add_element(sl_system *s, int32_t e, const double *Ke, const double *be, sl_diag *d);

/* ---- partitioned assembly (several ranks, mpirun) ------------------------- */

/* The elements of rank `rank` of `ranks`: a contiguous block of the element numbering, [n e / N, n (e + 1) / N)
 * for e = rank, N = ranks (the mesh generators number the cells row by row, gmsh front by front, so that a
 * block is a compact piece of the domain). */
void sl_system_partition(int32_t n_elem, int rank, int ranks, int32_t *begin, int32_t *end);
/* As sl_system_init, for rank `rank` of `ranks` (one rank: sl_system_init). On several ranks the system is
 * distributed: this rank assembles its own elements only (the graph partition's part, sl_linsolve_partition;
 * sl_system_partition's block where a part would be empty), and owns the rows of the dofs
 * whose lowest-numbered element is one of its own (so a rank owns the rows of its part of the domain, a dof
 * on the border between two parts going to the lower rank). Its matrix holds only the rows its elements touch
 * and the complete pattern of the rows it owns; A.rows says which those are and numbers every rank's rows
 * contiguously, in the sluice order within a rank (core/solve/sparse.h). */
int sl_system_init_ranks(sl_system *s, int32_t n_dofs, int32_t n_elem, int dofs_per_elem, const int32_t *elem_dofs,
                         int rank, int ranks, sl_diag *d);
/* The range holding the elements this rank assembles: [*begin, *end) (all of them on one rank); the others in it
 * add nothing (sl_system_add_element). */
void sl_system_elements(const sl_system *s, int32_t *begin, int32_t *end);
/* The first run of consecutive elements this rank assembles at or after `from`: [*begin, *end) (empty,
 * *begin == *end, when there is none); on one rank [from, n_elem). */
void sl_system_next_run(const sl_system *s, int32_t from, int32_t *begin, int32_t *end);
/* After the elements are added, before the constraints: on several ranks each rank holds only its own
 * elements' part; this adds the parts of every row into the rank that owns it (PETSc's MatSetValues with
 * ADD_VALUES and its VecSetValues: a row another rank owns travels there, sl_linsolve_rows_complete), so that
 * each rank holds its own rows complete (b, and A's values with `matrix`) and zeros in the others. Nothing on
 * one rank. Collective: every rank calls it, with the same `matrix`. */
int sl_system_complete(sl_system *s, int matrix, sl_diag *d);
/* Collective on a distributed system: rc when every rank's rc is 0 or this rank failed itself; otherwise the
 * largest rank's failure, with a message that another rank failed (so that no rank waits in a later exchange
 * for one that stopped). rc itself on one rank. */
int sl_system_agree(const sl_system *s, int rc, sl_diag *d);

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
