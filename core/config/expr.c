/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The expression language of expr.h: a recursive-descent parser that emits a
 * flat postfix program while it parses, folding constants and fusing
 * operands as it goes, and a switch-dispatched stack interpreter.
 *
 * Emission keeps one invariant that makes folding local: a sub-expression
 * without variables always ends up as exactly one OP_CONST instruction. So
 * when an operator is emitted, its operands are constant exactly when their
 * code is a single OP_CONST, and folding replaces them with the result. The
 * same test finds operands that are a single constant or variable, which are
 * fused into the operator (x*2 is one OP_MUL_K, 1-x one OP_K_SUB, x*y one
 * OP_MUL_V), halving the instruction count of typical formulas.
 *
 * Folding and evaluation share one definition of every operator (the
 * SL_UNOPS / SL_BINOPS tables), so a folded result is bit-for-bit what the
 * interpreter would have computed. One rule is applied at compile time on
 * purpose: a power whose exponent folds to exactly 2 is computed as a*a
 * (correctly rounded, and much faster than pow). The ternary compiles to
 * jumps, so only the chosen branch runs; a constant condition keeps only the
 * chosen branch. Jumps are relative, so moving a block of code keeps them
 * valid. */
#include "core/config/expr.h"
#include "core/config/special.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ operators */

static double sl_sign(double a) { return a > 0 ? 1.0 : a < 0 ? -1.0 : a; /* 0, -0 and NaN as they are */ }
static double sl_min2(double a, double b) { return isnan(a) || isnan(b) ? a + b : a < b ? a : b; }
static double sl_max2(double a, double b) { return isnan(a) || isnan(b) ? a + b : a > b ? a : b; }

/* X(name, value of a) */
#define SL_UNOPS(X)              \
  X(NEG, -a)                     \
  X(NOT, (double)(a == 0))       \
  X(SQUARE, a *a)                \
  X(SIN, sin(a))                 \
  X(COS, cos(a))                 \
  X(TAN, tan(a))                 \
  X(ASIN, asin(a))               \
  X(ACOS, acos(a))               \
  X(ATAN, atan(a))               \
  X(SINH, sinh(a))               \
  X(COSH, cosh(a))               \
  X(TANH, tanh(a))               \
  X(EXP, exp(a))                 \
  X(LOG, log(a))                 \
  X(LOG10, log10(a))             \
  X(SQRT, sqrt(a))               \
  X(ABS, fabs(a))                \
  X(FLOOR, floor(a))             \
  X(CEIL, ceil(a))               \
  X(SIGN, sl_sign(a))            \
  X(STEP, (double)(a >= 0))      \
  X(J0, sl_bessel_j0(a))         \
  X(J1, sl_bessel_j1(a))         \
  X(Y0, sl_bessel_y0(a))         \
  X(Y1, sl_bessel_y1(a))         \
  X(JHALF, sl_bessel_jhalf(a))   \
  X(INT_J0, sl_bessel_int_j0(a)) \
  X(INT_Y0, sl_bessel_int_y0(a))

/* X(name, value of a and b) */
#define SL_BINOPS(X)                 \
  X(ADD, a + b)                      \
  X(SUB, a - b)                      \
  X(MUL, a *b)                       \
  X(DIV, a / b)                      \
  X(POW, pow(a, b))                  \
  X(LT, (double)(a < b))             \
  X(LE, (double)(a <= b))            \
  X(GT, (double)(a > b))             \
  X(GE, (double)(a >= b))            \
  X(EQ, (double)(a == b))            \
  X(NE, (double)(a != b))            \
  X(AND, (double)(a != 0 && b != 0)) \
  X(OR, (double)(a != 0 || b != 0))  \
  X(ATAN2, atan2(a, b))              \
  X(MIN, sl_min2(a, b))              \
  X(MAX, sl_max2(a, b))              \
  X(JN, sl_bessel_jn(a, b))          \
  X(YN, sl_bessel_yn(a, b))

/* Every binary operator comes in five forms, in this order:
 *   OP_f     a = second from top, b = top      (pops one)
 *   OP_f_K   a = top, b = constant k
 *   OP_f_V   a = top, b = variable arg
 *   OP_K_f   a = constant k, b = top
 *   OP_V_f   a = variable arg, b = top */
enum { BIN_SS, BIN_SK, BIN_SV, BIN_KS, BIN_VS, BIN_FORMS };

enum {
  OP_END,
  OP_CONST, /* push k */
  OP_VAR,   /* push values[arg] */
  OP_JZ,    /* pop; when zero, jump by arg (relative to this instruction) */
  OP_JMP,   /* jump by arg */
#define X(name, val) OP_##name,
  SL_UNOPS(X)
#undef X
      OP_BIN_START,
  OP_BIN_START_ = OP_BIN_START - 1,
#define X(name, val) OP_##name, OP_##name##_K, OP_##name##_V, OP_K_##name, OP_V_##name,
  SL_BINOPS(X)
#undef X
      OP_COUNT
};

typedef struct {
  int op;
  int arg;  /* variable index or relative jump */
  double k; /* constant */
} sl_ins;

struct sl_expr {
  int n_code;    /* instructions before the final OP_END */
  int max_stack; /* slots the program needs */
  int n_vars;
  int is_const;
  double value; /* when is_const */
  unsigned char uses[SL_EXPR_MAX_VARS];
  sl_ins code[]; /* n_code + 1 (OP_END) */
};

static double unop_apply(int op, double a) {
  switch (op) {
#define X(name, val) \
  case OP_##name:    \
    return val;
    SL_UNOPS(X)
#undef X
    default:
      return NAN;
  }
}

static double binop_apply(int op, double a, double b) {
  switch (op) {
#define X(name, val) \
  case OP_##name:    \
    return val;
    SL_BINOPS(X)
#undef X
    default:
      return NAN;
  }
}

static int is_binop(int op) { return op >= OP_BIN_START && op < OP_COUNT; }
static int bin_form(int op) { return (op - OP_BIN_START) % BIN_FORMS; }

/* ------------------------------------------------------------ names */

typedef struct {
  const char *name;
  int op;    /* unary or binary (plain form) operator */
  int nargs; /* 1, 2, or -2 for "2 or more" */
} sl_func;

static const sl_func funcs[] = {
    {"sin", OP_SIN, 1},     {"cos", OP_COS, 1},       {"tan", OP_TAN, 1},       {"asin", OP_ASIN, 1},
    {"acos", OP_ACOS, 1},   {"atan", OP_ATAN, 1},     {"atan2", OP_ATAN2, 2},   {"sinh", OP_SINH, 1},
    {"cosh", OP_COSH, 1},   {"tanh", OP_TANH, 1},     {"exp", OP_EXP, 1},       {"log", OP_LOG, 1},
    {"log10", OP_LOG10, 1}, {"sqrt", OP_SQRT, 1},     {"abs", OP_ABS, 1},       {"min", OP_MIN, -2},
    {"max", OP_MAX, -2},    {"pow", OP_POW, 2},       {"floor", OP_FLOOR, 1},   {"ceil", OP_CEIL, 1},
    {"sign", OP_SIGN, 1},   {"step", OP_STEP, 1},     {"j0", OP_J0, 1},         {"j1", OP_J1, 1},
    {"y0", OP_Y0, 1},       {"y1", OP_Y1, 1},         {"jn", OP_JN, 2},         {"yn", OP_YN, 2},
    {"jhalf", OP_JHALF, 1}, {"int_j0", OP_INT_J0, 1}, {"int_y0", OP_INT_Y0, 1},
};
enum { N_FUNCS = (int)(sizeof funcs / sizeof funcs[0]) };

static const struct {
  const char *name;
  double value;
} consts[] = {{"pi", 3.14159265358979323846}, {"e", 2.71828182845904523536}};
enum { N_CONSTS = (int)(sizeof consts / sizeof consts[0]) };

static int name_is(const char *s, int len, const char *name) {
  return (int)strlen(name) == len && memcmp(s, name, (size_t)len) == 0;
}
static int find_func(const char *s, int len) {
  for (int i = 0; i < N_FUNCS; ++i)
    if (name_is(s, len, funcs[i].name)) return i;
  return -1;
}
static int find_const(const char *s, int len) {
  for (int i = 0; i < N_CONSTS; ++i)
    if (name_is(s, len, consts[i].name)) return i;
  return -1;
}

/* ASCII only on purpose: <ctype.h> depends on the locale. */
static int is_digit(char c) { return c >= '0' && c <= '9'; }
static int is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
static int is_name_char(char c) { return is_name_start(c) || is_digit(c); }
static int is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/* ------------------------------------------------------------ lexer */

typedef enum {
  T_END,
  T_NUM,
  T_NAME,
  T_PLUS,
  T_MINUS,
  T_STAR,
  T_SLASH,
  T_CARET,
  T_LT,
  T_LE,
  T_GT,
  T_GE,
  T_EQ,
  T_NE,
  T_AND,
  T_OR,
  T_NOT,
  T_LPAREN,
  T_RPAREN,
  T_COMMA,
  T_QUESTION,
  T_COLON
} tok_kind;

typedef struct {
  tok_kind kind;
  const char *s; /* start in the text */
  int len;       /* bytes */
  int col;       /* 1-based, UTF-8 characters */
  double num;
} token;

typedef struct {
  const char *p; /* lexer position */
  int col;       /* column of p */
  token tok;     /* current token */
  token prev;    /* the one before (kind T_END before the first) */
  const char *const *vars;
  int n_vars;
  const sl_expr_constants *named; /* the caller's named constants (NULL: none) */
  sl_ins *code;
  int n, cap;
  int nest;
  sl_diag *d;
  char numbuf[SL_EXPR_MAX_LEN + 1];
} parser;

static int fail(parser *P, int col, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int fail(parser *P, int col, const char *fmt, ...) {
  char msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return sl_diag_set(P->d, SL_EBADINPUT, "column %d: %s", col, msg);
}

/* Advance the lexer by n bytes, keeping the column. */
static void skip(parser *P, int n) {
  for (int i = 0; i < n; ++i, ++P->p)
    if (((unsigned char)*P->p & 0xC0) != 0x80) ++P->col;
}

/* "'text'" of a token (shortened), or "the end of the expression". */
static const char *describe(const token *t, char *buf, size_t size) {
  if (t->kind == T_END) return "the end of the expression";
  if (t->len > 40) snprintf(buf, size, "'%.37s...'", t->s);
  else snprintf(buf, size, "'%.*s'", t->len, t->s);
  return buf;
}

/* Length of the UTF-8 character at s, 1 when it is not valid UTF-8. */
static int char_len(const char *s) {
  unsigned c = (unsigned char)s[0];
  int len = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 1;
  if (c >= 0xF5) len = 1;
  for (int k = 1; k < len; ++k)
    if (((unsigned char)s[k] & 0xC0) != 0x80) return 1;
  return len;
}

static int lex_number(parser *P) {
  const char *s = P->p, *q = s;
  while (is_digit(*q)) ++q;
  if (*q == '.') {
    ++q;
    while (is_digit(*q)) ++q;
  }
  /* An exponent only when digits follow: "2e" is the number 2 and the name e. */
  if (*q == 'e' || *q == 'E') {
    const char *r = q + 1;
    if (*r == '+' || *r == '-') ++r;
    if (is_digit(*r)) {
      while (is_digit(*r)) ++r;
      q = r;
    } else if (r != q + 1) {
      return fail(P, P->col, "malformed number '%.*s': expected digits after '%.*s'", (int)(r - s), s, (int)(r - q), q);
    }
  }
  size_t len = (size_t)(q - s);
  memcpy(P->numbuf, s, len); /* len <= SL_EXPR_MAX_LEN: the whole text is that short */
  P->numbuf[len] = '\0';
  char *end;
  double v = strtod(P->numbuf, &end);
  if (end != P->numbuf + len) return fail(P, P->col, "malformed number '%.*s'", (int)len, s);
  if (isinf(v)) return fail(P, P->col, "number '%.*s' is too large", (int)(len > 40 ? 40 : len), s);
  P->tok.kind = T_NUM;
  P->tok.num = v;
  skip(P, (int)len);
  return 0;
}

/* Reads the next token into P->tok (the current one moves to P->prev). */
static int advance(parser *P) {
  P->prev = P->tok;
  while (is_space(*P->p)) skip(P, 1);
  token *t = &P->tok;
  t->s = P->p;
  t->col = P->col;
  t->num = 0;
  char c = *P->p, c2 = c ? P->p[1] : '\0';
  int n = 1;
  if (c == '\0') {
    t->kind = T_END;
    n = 0;
  } else if (is_digit(c) || (c == '.' && is_digit(c2))) {
    int rc = lex_number(P);
    t->len = (int)(P->p - t->s);
    return rc;
  } else if (is_name_start(c)) {
    while (is_name_char(P->p[n])) ++n;
    t->kind = T_NAME;
  } else {
    switch (c) {
      case '+':
        t->kind = T_PLUS;
        break;
      case '-':
        t->kind = T_MINUS;
        break;
      case '*':
        t->kind = T_STAR;
        break;
      case '/':
        t->kind = T_SLASH;
        break;
      case '^':
        t->kind = T_CARET;
        break;
      case '(':
        t->kind = T_LPAREN;
        break;
      case ')':
        t->kind = T_RPAREN;
        break;
      case ',':
        t->kind = T_COMMA;
        break;
      case '?':
        t->kind = T_QUESTION;
        break;
      case ':':
        t->kind = T_COLON;
        break;
      case '<':
        t->kind = c2 == '=' ? T_LE : T_LT;
        n = c2 == '=' ? 2 : 1;
        break;
      case '>':
        t->kind = c2 == '=' ? T_GE : T_GT;
        n = c2 == '=' ? 2 : 1;
        break;
      case '!':
        t->kind = c2 == '=' ? T_NE : T_NOT;
        n = c2 == '=' ? 2 : 1;
        break;
      case '=':
        if (c2 != '=') return fail(P, P->col, "unexpected '='; did you mean '=='?");
        t->kind = T_EQ;
        n = 2;
        break;
      case '&':
        if (c2 != '&') return fail(P, P->col, "unexpected '&'; did you mean '&&'?");
        t->kind = T_AND;
        n = 2;
        break;
      case '|':
        if (c2 != '|') return fail(P, P->col, "unexpected '|'; did you mean '||'?");
        t->kind = T_OR;
        n = 2;
        break;
      default: {
        unsigned char u = (unsigned char)c;
        if (u < 0x20 || u == 0x7F) return fail(P, P->col, "unexpected control character 0x%02X", u);
        int cl = char_len(P->p);
        if (u >= 0x80 && cl == 1) return fail(P, P->col, "unexpected byte 0x%02X (not UTF-8 text)", u);
        if (c == '.') return fail(P, P->col, "unexpected '.': a number needs a digit before or after the point");
        return fail(P, P->col, "unexpected character '%.*s'", cl, P->p);
      }
    }
  }
  t->len = n;
  skip(P, n);
  return 0;
}

/* ------------------------------------------------------------ emission */

static int emit(parser *P, int op, int arg, double k) {
  if (P->n == P->cap) {
    int ncap = P->cap * 2;
    sl_ins *nc = realloc(P->code, (size_t)ncap * sizeof *nc);
    if (!nc) return sl_diag_set(P->d, SL_EBADINPUT, "out of memory compiling an expression");
    P->code = nc;
    P->cap = ncap;
  }
  P->code[P->n].op = op;
  P->code[P->n].arg = arg;
  P->code[P->n].k = k;
  ++P->n;
  return 0;
}

/* Whether code[from, to) is a single instruction `op`. */
static int single(const parser *P, int from, int to, int op) { return to == from + 1 && P->code[from].op == op; }

/* Unary operator on the code from s0 to the end. */
static int emit_unary(parser *P, int op, int s0) {
  if (single(P, s0, P->n, OP_CONST)) {
    P->code[s0].k = unop_apply(op, P->code[s0].k);
    return 0;
  }
  return emit(P, op, 0, 0);
}

/* Binary operator (plain form `op`): left operand code[l0, r0), right
 * operand code[r0, n). */
static int emit_binary(parser *P, int op, int l0, int r0) {
  int n = P->n;
  int lk = single(P, l0, r0, OP_CONST), lv = single(P, l0, r0, OP_VAR);
  int rk = single(P, r0, n, OP_CONST), rv = single(P, r0, n, OP_VAR);
  sl_ins *c = P->code;
  if (op == OP_POW && rk && c[r0].k == 2) {
    P->n = r0;
    return emit_unary(P, OP_SQUARE, l0);
  }
  if (lk && rk) {
    c[l0].k = binop_apply(op, c[l0].k, c[r0].k);
    P->n = l0 + 1;
    return 0;
  }
  if (rk || rv) {
    c[r0].op = op + (rk ? BIN_SK : BIN_SV);
    return 0;
  }
  if (lk || lv) {
    sl_ins left = c[l0];
    memmove(c + l0, c + r0, (size_t)(n - r0) * sizeof *c);
    P->n = n - 1;
    return emit(P, op + (lk ? BIN_KS : BIN_VS), left.arg, left.k);
  }
  return emit(P, op, 0, 0);
}

/* ------------------------------------------------------------ parser */

static int parse_ternary(parser *P);
static int parse_unary(parser *P);

static int enter(parser *P) {
  if (++P->nest > SL_EXPR_MAX_NEST)
    return fail(P, P->tok.col, "expression nested too deeply (more than %d levels)", SL_EXPR_MAX_NEST);
  return 0;
}

static int expected_operand(parser *P) {
  char b1[64], b2[64];
  const char *found = describe(&P->tok, b1, sizeof b1);
  const char *hint = P->prev.kind == T_STAR && P->tok.kind == T_STAR ? "; use '^' for powers" : "";
  if (P->prev.kind == T_END) /* nothing before: only whitespace was skipped */
    return fail(P, P->tok.col, "expected a number, a name or '(', found %s%s", found, hint);
  return fail(P, P->tok.col, "expected a number, a name or '(' after %s, found %s%s", describe(&P->prev, b2, sizeof b2),
              found, hint);
}

static int unknown_name(parser *P, const token *t, int as_function) {
  char name[80];
  snprintf(name, sizeof name, "%.*s", t->len > 64 ? 64 : t->len, t->s);
  const char *cand[N_FUNCS + N_CONSTS + SL_EXPR_MAX_VARS + SL_EXPR_MAX_CONSTANTS];
  int n = 0;
  /* Prefer names of the same kind: functions before '(', values elsewhere. */
  if (as_function)
    for (int i = 0; i < N_FUNCS; ++i) cand[n++] = funcs[i].name;
  for (int i = 0; i < P->n_vars; ++i) cand[n++] = P->vars[i];
  for (int i = 0; i < N_CONSTS; ++i) cand[n++] = consts[i].name;
  for (int i = 0; P->named && i < P->named->n && i < SL_EXPR_MAX_CONSTANTS; ++i) cand[n++] = P->named->names[i];
  const char *best = sl_suggest(name, cand, n);
  if (!best && !as_function) {
    for (int i = 0; i < N_FUNCS; ++i) cand[i] = funcs[i].name;
    best = sl_suggest(name, cand, N_FUNCS);
  }
  /* Nothing in common ('z' for 'x') is no suggestion; the list below helps more. */
  if (best && sl_edit_distance(name, best) >= (int)strlen(name)) best = NULL;
  if (best) return fail(P, t->col, "unknown name '%s'; did you mean '%s'?", name, best);
  if (as_function) return fail(P, t->col, "unknown function '%s'", name);
  char list[512] = "";
  size_t used = 0;
  for (int i = 0; i < P->n_vars && used < sizeof list; ++i) {
    int w = snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", P->vars[i]);
    if (w < 0) break;
    used += (size_t)w;
  }
  if (P->n_vars == 0) return fail(P, t->col, "unknown name '%s' (this value takes no variables)", name);
  return fail(P, t->col, "unknown name '%s' (variables: %s)", name, list);
}

static int parse_call(parser *P, int fi) {
  const sl_func *f = &funcs[fi];
  token name = P->tok;
  char b[64];
  int rc = advance(P);
  if (rc) return rc;
  if (P->tok.kind != T_LPAREN)
    return fail(P, P->tok.col, "expected '(' after function '%s', found %s", f->name, describe(&P->tok, b, sizeof b));
  token open = P->tok;
  if ((rc = enter(P)) || (rc = advance(P))) return rc;
  int a0 = P->n, a1 = -1, nargs = 0;
  if (P->tok.kind != T_RPAREN) {
    for (;;) {
      int s = P->n;
      if ((rc = parse_ternary(P))) return rc;
      ++nargs;
      if (nargs == 2) a1 = s;
      if (nargs >= 2 && f->nargs == -2 && (rc = emit_binary(P, f->op, a0, s))) return rc;
      if (P->tok.kind == T_RPAREN) break;
      if (P->tok.kind != T_COMMA)
        return fail(P, P->tok.col, "expected ',' or ')' to close the '(' at column %d, found %s", open.col,
                    describe(&P->tok, b, sizeof b));
      if ((rc = advance(P))) return rc;
    }
  }
  --P->nest;
  if (f->nargs == -2 && nargs < 2) return fail(P, name.col, "%s takes at least 2 arguments, got %d", f->name, nargs);
  if (f->nargs > 0 && nargs != f->nargs)
    return fail(P, name.col, "%s takes %d argument%s, got %d", f->name, f->nargs, f->nargs == 1 ? "" : "s", nargs);
  if ((rc = advance(P))) return rc;
  if (f->nargs == 1) return emit_unary(P, f->op, a0);
  if (f->nargs == 2) return emit_binary(P, f->op, a0, a1);
  return 0;
}

static int parse_primary(parser *P) {
  token t = P->tok;
  char b[64];
  int rc;
  switch (t.kind) {
    case T_NUM:
      if ((rc = emit(P, OP_CONST, 0, t.num))) return rc;
      return advance(P);
    case T_LPAREN:
      if ((rc = enter(P)) || (rc = advance(P)) || (rc = parse_ternary(P))) return rc;
      if (P->tok.kind != T_RPAREN)
        return fail(P, P->tok.col, "expected ')' to close the '(' at column %d, found %s", t.col,
                    describe(&P->tok, b, sizeof b));
      --P->nest;
      return advance(P);
    case T_NAME: {
      for (int i = 0; i < P->n_vars; ++i)
        if (name_is(t.s, t.len, P->vars[i])) {
          if ((rc = emit(P, OP_VAR, i, 0)) || (rc = advance(P))) return rc;
          if (P->tok.kind == T_LPAREN) return fail(P, t.col, "'%s' is a variable, not a function", P->vars[i]);
          return 0;
        }
      for (int i = 0; P->named && i < P->named->n; ++i)
        if (name_is(t.s, t.len, P->named->names[i])) {
          if ((rc = emit(P, OP_CONST, 0, P->named->values[i])) || (rc = advance(P))) return rc;
          if (P->tok.kind == T_LPAREN) return fail(P, t.col, "'%s' is a parameter, not a function", P->named->names[i]);
          return 0;
        }
      int ci = find_const(t.s, t.len);
      if (ci >= 0) {
        if ((rc = emit(P, OP_CONST, 0, consts[ci].value)) || (rc = advance(P))) return rc;
        if (P->tok.kind == T_LPAREN) return fail(P, t.col, "'%s' is a constant, not a function", consts[ci].name);
        return 0;
      }
      int fi = find_func(t.s, t.len);
      if (fi >= 0) return parse_call(P, fi);
      if ((rc = advance(P))) return rc;
      return unknown_name(P, &t, P->tok.kind == T_LPAREN);
    }
    default:
      return expected_operand(P);
  }
}

/* power: primary ('^' unary)? -- right-associative through unary, so
 * 2^3^2 = 2^(3^2) and 2^-1 works; -x^2 is -(x^2) since unary is looser. */
static int parse_power(parser *P) {
  int b0 = P->n, rc;
  if ((rc = parse_primary(P))) return rc;
  if (P->tok.kind != T_CARET) return 0;
  if ((rc = enter(P)) || (rc = advance(P))) return rc;
  int e0 = P->n;
  if ((rc = parse_unary(P))) return rc;
  --P->nest;
  return emit_binary(P, OP_POW, b0, e0);
}

static int parse_unary(parser *P) {
  tok_kind k = P->tok.kind;
  if (k != T_MINUS && k != T_PLUS && k != T_NOT) return parse_power(P);
  int s0 = P->n, rc;
  if ((rc = enter(P)) || (rc = advance(P)) || (rc = parse_unary(P))) return rc;
  --P->nest;
  if (k == T_MINUS) return emit_unary(P, OP_NEG, s0);
  if (k == T_NOT) return emit_unary(P, OP_NOT, s0);
  return 0;
}

static int parse_mul(parser *P) {
  int l0 = P->n, rc;
  if ((rc = parse_unary(P))) return rc;
  while (P->tok.kind == T_STAR || P->tok.kind == T_SLASH) {
    int op = P->tok.kind == T_STAR ? OP_MUL : OP_DIV;
    if ((rc = advance(P))) return rc;
    int r0 = P->n;
    if ((rc = parse_unary(P)) || (rc = emit_binary(P, op, l0, r0))) return rc;
  }
  return 0;
}

static int parse_add(parser *P) {
  int l0 = P->n, rc;
  if ((rc = parse_mul(P))) return rc;
  while (P->tok.kind == T_PLUS || P->tok.kind == T_MINUS) {
    int op = P->tok.kind == T_PLUS ? OP_ADD : OP_SUB;
    if ((rc = advance(P))) return rc;
    int r0 = P->n;
    if ((rc = parse_mul(P)) || (rc = emit_binary(P, op, l0, r0))) return rc;
  }
  return 0;
}

static int comparison_op(tok_kind k, int equality) {
  if (equality) return k == T_EQ ? OP_EQ : k == T_NE ? OP_NE : -1;
  switch (k) {
    case T_LT:
      return OP_LT;
    case T_LE:
      return OP_LE;
    case T_GT:
      return OP_GT;
    case T_GE:
      return OP_GE;
    default:
      return -1;
  }
}

/* Comparisons do not chain: "0 < x < 1" would silently mean (0 < x) < 1. */
static int parse_compare(parser *P, int equality) {
  int l0 = P->n, rc;
  if ((rc = equality ? parse_compare(P, 0) : parse_add(P))) return rc;
  int op = comparison_op(P->tok.kind, equality);
  if (op < 0) return 0;
  token first = P->tok;
  if ((rc = advance(P))) return rc;
  int r0 = P->n;
  if ((rc = equality ? parse_compare(P, 0) : parse_add(P))) return rc;
  if (comparison_op(P->tok.kind, equality) >= 0)
    return fail(P, P->tok.col, "comparisons do not chain: write 'a %.*s b && b %.*s c' instead of 'a %.*s b %.*s c'",
                first.len, first.s, P->tok.len, P->tok.s, first.len, first.s, P->tok.len, P->tok.s);
  return emit_binary(P, op, l0, r0);
}

static int parse_and(parser *P) {
  int l0 = P->n, rc;
  if ((rc = parse_compare(P, 1))) return rc;
  while (P->tok.kind == T_AND) {
    if ((rc = advance(P))) return rc;
    int r0 = P->n;
    if ((rc = parse_compare(P, 1)) || (rc = emit_binary(P, OP_AND, l0, r0))) return rc;
  }
  return 0;
}

static int parse_or(parser *P) {
  int l0 = P->n, rc;
  if ((rc = parse_and(P))) return rc;
  while (P->tok.kind == T_OR) {
    if ((rc = advance(P))) return rc;
    int r0 = P->n;
    if ((rc = parse_and(P)) || (rc = emit_binary(P, OP_OR, l0, r0))) return rc;
  }
  return 0;
}

/* ternary: or ('?' ternary ':' ternary)? -- compiled as
 *   cond JZ(else) then JMP(end) else
 * or, when cond folded to a constant, as the chosen branch alone. */
static int parse_ternary(parser *P) {
  int c0 = P->n, rc;
  if ((rc = parse_or(P))) return rc;
  if (P->tok.kind != T_QUESTION) return 0;
  token q = P->tok;
  char b[64];
  if ((rc = enter(P)) || (rc = advance(P))) return rc;
  int jz = P->n;
  if ((rc = emit(P, OP_JZ, 0, 0)) || (rc = parse_ternary(P))) return rc;
  if (P->tok.kind != T_COLON)
    return fail(P, P->tok.col, "expected ':' to complete the '?' at column %d, found %s", q.col,
                describe(&P->tok, b, sizeof b));
  if ((rc = advance(P))) return rc;
  int jmp = P->n;
  if ((rc = emit(P, OP_JMP, 0, 0)) || (rc = parse_ternary(P))) return rc;
  --P->nest;
  int end = P->n;
  if (single(P, c0, jz, OP_CONST)) {
    int from = P->code[c0].k != 0 ? jz + 1 : jmp + 1, to = P->code[c0].k != 0 ? jmp : end;
    memmove(P->code + c0, P->code + from, (size_t)(to - from) * sizeof *P->code);
    P->n = c0 + (to - from);
    return 0;
  }
  P->code[jz].arg = jmp + 1 - jz;
  P->code[jmp].arg = end - jmp;
  return 0;
}

/* Stack slots the program needs. Code is structured: both branches of a
 * ternary leave one value, so a linear pass that lets JMP drop the then-value
 * (the else-branch starts from the depth before it) gives the exact maximum. */
static int stack_need(const sl_ins *code, int n) {
  int depth = 0, most = 0;
  for (int i = 0; i < n; ++i) {
    int op = code[i].op;
    if (op == OP_CONST || op == OP_VAR) ++depth;
    else if (op == OP_JZ || op == OP_JMP || (is_binop(op) && bin_form(op) == BIN_SS)) --depth;
    if (depth > most) most = depth;
  }
  return most;
}

static int check_vars(const char *const *vars, int n_vars, sl_diag *d) {
  if (n_vars < 0 || n_vars > SL_EXPR_MAX_VARS || (n_vars > 0 && !vars))
    return sl_diag_set(d, SL_EBADINPUT, "expression: bad variable list (%d variables, at most %d)", n_vars,
                       SL_EXPR_MAX_VARS);
  for (int i = 0; i < n_vars; ++i) {
    const char *v = vars[i];
    int ok = v && is_name_start(v[0]);
    for (const char *q = v ? v : ""; ok && *q; ++q) ok = is_name_char(*q);
    if (!ok) return sl_diag_set(d, SL_EBADINPUT, "expression: variable %d has an invalid name", i);
    int len = (int)strlen(v);
    if (find_func(v, len) >= 0 || find_const(v, len) >= 0)
      return sl_diag_set(d, SL_EBADINPUT, "expression: variable name '%s' is a built-in name", v);
    for (int j = 0; j < i; ++j)
      if (strcmp(vars[j], v) == 0) return sl_diag_set(d, SL_EBADINPUT, "expression: variable '%s' is listed twice", v);
  }
  return 0;
}

int sl_expr_compile(const char *text, const char *const *vars, int n_vars, sl_expr **out, sl_diag *d) {
  return sl_expr_compile_with(text, vars, n_vars, NULL, out, d);
}

int sl_expr_is_builtin(const char *name) {
  int len = (int)strlen(name);
  return find_func(name, len) >= 0 || find_const(name, len) >= 0;
}

int sl_expr_compile_with(const char *text, const char *const *vars, int n_vars, const sl_expr_constants *named,
                         sl_expr **out, sl_diag *d) {
  if (out) *out = NULL;
  if (!text || !out) return sl_diag_set(d, SL_EBADINPUT, "expression: no text or no output");
  int rc = check_vars(vars, n_vars, d);
  if (rc) return rc;
  size_t len = strnlen(text, (size_t)SL_EXPR_MAX_LEN + 1);
  if (len > SL_EXPR_MAX_LEN)
    return sl_diag_set(d, SL_EBADINPUT, "expression is too long (more than %d characters)", SL_EXPR_MAX_LEN);

  parser *P = malloc(sizeof *P);
  if (!P) return sl_diag_set(d, SL_EBADINPUT, "out of memory compiling an expression");
  memset(P, 0, offsetof(parser, numbuf));
  P->p = text;
  P->col = 1;
  P->vars = vars;
  P->n_vars = n_vars;
  P->named = named && named->n > 0 ? named : NULL;
  P->d = d;
  P->cap = 16;
  P->code = malloc((size_t)P->cap * sizeof *P->code);
  P->tok.kind = T_END;
  if (!P->code) {
    rc = sl_diag_set(d, SL_EBADINPUT, "out of memory compiling an expression");
  } else if (!(rc = advance(P))) {
    if (P->tok.kind == T_END) {
      rc = sl_diag_set(d, SL_EBADINPUT, "empty expression: expected a number, a name or '('");
    } else if (!(rc = parse_ternary(P)) && P->tok.kind != T_END) {
      char b[64];
      const char *found = describe(&P->tok, b, sizeof b);
      tok_kind pk = P->prev.kind, tk = P->tok.kind;
      if (tk == T_RPAREN) rc = fail(P, P->tok.col, "unmatched ')'");
      else if ((pk == T_NUM || pk == T_NAME || pk == T_RPAREN) && (tk == T_NUM || tk == T_NAME || tk == T_LPAREN))
        rc = fail(P, P->tok.col, "expected an operator or the end of the expression, found %s; write '*' to multiply",
                  found);
      else rc = fail(P, P->tok.col, "expected an operator or the end of the expression, found %s", found);
    }
  }
  if (!rc) {
    int need = stack_need(P->code, P->n);
    if (need > SL_EXPR_MAX_STACK)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "expression too complex: needs %d evaluation stack slots, at most %d (nest less deeply)", need,
                       SL_EXPR_MAX_STACK);
    sl_expr *e = rc ? NULL : malloc(sizeof *e + (size_t)(P->n + 1) * sizeof(sl_ins));
    if (!rc && !e) rc = sl_diag_set(d, SL_EBADINPUT, "out of memory compiling an expression");
    if (!rc) {
      e->n_code = P->n;
      e->max_stack = need;
      e->n_vars = n_vars;
      e->is_const = P->n == 1 && P->code[0].op == OP_CONST;
      e->value = e->is_const ? P->code[0].k : 0;
      memset(e->uses, 0, sizeof e->uses);
      memcpy(e->code, P->code, (size_t)P->n * sizeof(sl_ins));
      e->code[P->n].op = OP_END;
      e->code[P->n].arg = 0;
      e->code[P->n].k = 0;
      for (int i = 0; i < P->n; ++i) {
        int op = e->code[i].op;
        if (op == OP_VAR || (is_binop(op) && (bin_form(op) == BIN_SV || bin_form(op) == BIN_VS)))
          e->uses[e->code[i].arg] = 1;
      }
      *out = e;
    }
  }
  free(P->code);
  free(P);
  return rc;
}

/* ------------------------------------------------------------ evaluation */

double sl_expr_eval(const sl_expr *e, const double *values) {
  if (e->is_const) return e->value;
  double stack[SL_EXPR_MAX_STACK];
  double *sp = stack; /* one past the top */
  const double *v = values;
  const sl_ins *pc = e->code;
  for (;;) {
    const sl_ins *i = pc++;
    switch (i->op) {
      case OP_END:
        return sp[-1];
      case OP_CONST:
        *sp++ = i->k;
        break;
      case OP_VAR:
        *sp++ = v[i->arg];
        break;
      case OP_JZ:
        if (*--sp == 0) pc = i + i->arg;
        break;
      case OP_JMP:
        pc = i + i->arg;
        break;
#define X(name, val)   \
  case OP_##name: {    \
    double a = sp[-1]; \
    sp[-1] = val;      \
    break;             \
  }
        SL_UNOPS(X)
#undef X
#define X(name, val)      \
  case OP_##name: {       \
    double a = sp[-2];    \
    double b = sp[-1];    \
    --sp;                 \
    sp[-1] = val;         \
    break;                \
  }                       \
  case OP_##name##_K: {   \
    double a = sp[-1];    \
    double b = i->k;      \
    sp[-1] = val;         \
    break;                \
  }                       \
  case OP_##name##_V: {   \
    double a = sp[-1];    \
    double b = v[i->arg]; \
    sp[-1] = val;         \
    break;                \
  }                       \
  case OP_K_##name: {     \
    double a = i->k;      \
    double b = sp[-1];    \
    sp[-1] = val;         \
    break;                \
  }                       \
  case OP_V_##name: {     \
    double a = v[i->arg]; \
    double b = sp[-1];    \
    sp[-1] = val;         \
    break;                \
  }
        SL_BINOPS(X)
#undef X
      default:
        return NAN;
    }
  }
}

int sl_expr_is_constant(const sl_expr *e, double *value) {
  if (!e || !e->is_const) return 0;
  if (value) *value = e->value;
  return 1;
}

int sl_expr_uses(const sl_expr *e, int var) {
  if (!e || var < 0 || var >= e->n_vars) return 0;
  return e->uses[var];
}

void sl_expr_free(sl_expr *e) { free(e); }

int sl_expr_compile_list(const char *text, const char *const *vars, int n_vars, int max, sl_expr **out, int *n,
                         sl_diag *d) {
  return sl_expr_compile_list_with(text, vars, n_vars, NULL, max, out, n, d);
}

int sl_expr_compile_list_with(const char *text, const char *const *vars, int n_vars, const sl_expr_constants *named,
                              int max, sl_expr **out, int *n, sl_diag *d) {
  *n = 0;
  const char *p = text;
  while (*p) {
    const char *q = p;
    int depth = 0;
    while (*q && !(*q == ',' && depth == 0)) depth += (*q == '(') - (*q == ')'), ++q;
    int rc = 0;
    if (*n == max) rc = sl_diag_set(d, SL_EBADINPUT, "more than %d components", max);
    char buf[4096];
    snprintf(buf, sizeof buf, "%.*s", (int)(q - p), p);
    sl_diag d2;
    if (!rc && sl_expr_compile_with(buf, vars, n_vars, named, &out[*n], &d2))
      rc = sl_diag_set(d, SL_EBADINPUT, "component %d ('%s'): %s", *n + 1, buf, d2.msg);
    if (rc) {
      for (int i = 0; i < *n; ++i) sl_expr_free(out[i]), out[i] = NULL;
      *n = 0;
      return rc;
    }
    ++*n;
    p = *q ? q + 1 : q;
  }
  return 0;
}
