/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A small arithmetic expression language for scene values: boundary values
 * and initial fields written as numbers or formulas of (x, y, t), e.g.
 *   velocity = 16*x^2*(1-x)^2, 0
 *   value    = 0.5*(1 + tanh((y - 0.3)/0.01))
 *
 * Syntax, loosest binding first:
 *   c ? a : b                ternary (right-associative; only the chosen branch runs)
 *   ||   &&                  logical or / and, 1 or 0 (non-zero is true)
 *   == !=                    equality, 1 or 0 (does not chain: a == b == c is an error)
 *   < <= > >=                comparison, 1 or 0 (does not chain: 0 < x < 1 is an error)
 *   + -                      left-associative
 *   * /                      left-associative
 *   unary - + !              -x^2 = -(x^2); !a = (a == 0)
 *   ^                        power, right-associative: 2^3^2 = 2^9; 2^-1 = 0.5
 *   numbers, names, f(...), ( ... )
 * Numbers: 1, 1.5, .5, 1., 1e-3, 2.5E+4 (decimal only). Names: the caller's
 * variables, the constants pi and e, and the functions
 *   sin cos tan asin acos atan sinh cosh tanh exp log log10 sqrt abs floor
 *   ceil sign step (1 argument), atan2 pow (2), min max (2 or more), and the
 *   Bessel functions j0 j1 y0 y1 jhalf (J_{1/2}) int_j0 int_y0 (the integrals
 *   from 0 to x of J0 and Y0) (1), jn(n, x) yn(n, x) (integer n) (2); see
 *   special.h for their domains (NaN outside).
 * log is the natural logarithm; sign(x) is -1, 0 or 1 (NaN for NaN);
 * step(x) = (x >= 0); min and max return NaN when any argument is NaN.
 * Whitespace (blanks, tabs, newlines) is allowed anywhere between tokens.
 * Arithmetic is IEEE double: division by zero and the like give inf or NaN,
 * which the caller checks. Sub-expressions without variables are folded at
 * compile time with the same operations evaluation would use. */
#ifndef SLUICE_CONFIG_EXPR_H
#define SLUICE_CONFIG_EXPR_H

#include "core/util/diag.h"

enum {
  SL_EXPR_MAX_LEN = 4096, /* characters of text */
  SL_EXPR_MAX_STACK = 64, /* evaluation stack slots */
  SL_EXPR_MAX_NEST = 200, /* nesting of parentheses, unary operators, powers, ternaries */
  SL_EXPR_MAX_VARS = 64,
  SL_EXPR_MAX_CONSTANTS = 64 /* named constants of sl_expr_compile_with */
};

/* Named constants an expression may use beside its variables: a scene's
 * [parameters] (core/config/ini.h, sl_ini_parameters). A name is looked up
 * after the variables and before the built-in constants pi and e; it
 * compiles to its value, so an expression of constants only is folded to a
 * number. */
typedef struct sl_expr_constants {
  const char *const *names;
  const double *values;
  int n; /* at most SL_EXPR_MAX_CONSTANTS */
} sl_expr_constants;

typedef struct sl_expr sl_expr;

/* Compiles `text` with the named variables (vars[0..n_vars), valid
 * identifiers that are not built-in names, e.g. {"x", "y", "t"}). On success
 * *out owns the program (free with sl_expr_free) and 0 is returned. On error
 * *out is NULL and SL_EBADINPUT is returned with d->msg like
 *   column 7: unknown name 'sinn'; did you mean 'sin'?
 * (1-based column in UTF-8 characters within `text`); the caller prefixes
 * file:line:key. */
int sl_expr_compile(const char *text, const char *const *vars, int n_vars, sl_expr **out, sl_diag *d);

/* The same with the named constants k (NULL: none). */
int sl_expr_compile_with(const char *text, const char *const *vars, int n_vars, const sl_expr_constants *k,
                         sl_expr **out, sl_diag *d);
/* 1 when name is a built-in function or constant (sin, pi, ...). */
int sl_expr_is_builtin(const char *name);

/* Value with values[i] for vars[i] (values may be NULL when no variable is
 * used). Does not allocate or modify e: safe to call from several threads. */
double sl_expr_eval(const sl_expr *e, const double *values);

/* 1 when no variable appears (the whole expression was folded to a number),
 * with the number in *value (when value is not NULL); 0 otherwise. */
int sl_expr_is_constant(const sl_expr *e, double *value);

/* 1 when vars[var] appears in the compiled program, 0 otherwise (also for an
 * index out of range). A variable only in a branch folded away does not count. */
int sl_expr_uses(const sl_expr *e, int var);

void sl_expr_free(sl_expr *e);

/* Compiles a comma list "a, b, c" (commas inside parentheses belong to
 * their expression, as in min(a, b)) into out[0..*n), at most max of them.
 * On error nothing is left allocated and SL_EBADINPUT names the component
 * ("component 2 ('...'): ...") for the caller to prefix. */
int sl_expr_compile_list(const char *text, const char *const *vars, int n_vars, int max, sl_expr **out, int *n,
                         sl_diag *d);
int sl_expr_compile_list_with(const char *text, const char *const *vars, int n_vars, const sl_expr_constants *k,
                              int max, sl_expr **out, int *n, sl_diag *d);

#endif
