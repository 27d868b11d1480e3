/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Unit tests of the expression language (core/config/expr.c).
 *
 * Values are compared bit for bit (NaN with NaN) against the same formula
 * written in C: the compiler folds constants and fuses operands, but must
 * compute with exactly the operations the formula names, in its order. The
 * inputs of the C side go through rt() (a volatile round trip) so that the C
 * compiler cannot fold libm calls at compile time with its own, differently
 * rounded, arithmetic. Error cases check the code, that nothing is handed out
 * and the message's "column N:" start. The randomized part generates
 * well-formed expressions from the grammar (printed with the fewest
 * parentheses precedence allows, plus random extra ones and blanks) together
 * with their value computed by a tree walk in C. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/expr.h"
#include "testing.h"

static const char *const XYT[] = {"x", "y", "t"};

static double rt(double v) {
  volatile double s = v;
  return s;
}

/* Bitwise-equal values (same sign of zero), or both NaN. */
static int same(double a, double b) {
  if (isnan(a) || isnan(b)) return isnan(a) && isnan(b);
  return a == b && signbit(a) == signbit(b);
}

static double g_vals[3];

static void expect_value(int line, const char *text, double ref) {
  sl_expr *e = NULL;
  sl_diag d = {{0}};
  int rc = sl_expr_compile(text, XYT, 3, &e, &d);
  CHECK_MSG(rc == 0 && e != NULL, "line %d: '%s' does not compile: %s", line, text, d.msg);
  if (!e) return;
  double v = sl_expr_eval(e, g_vals);
  CHECK_MSG(same(v, ref), "line %d: '%s' = %.17g, C gives %.17g", line, text, v, ref);
  sl_expr_free(e);
}
#define EXPECT(text, ref) expect_value(__LINE__, (text), (ref))

/* The message starts with `prefix` and contains `part`. */
static void expect_error(int line, const char *text, const char *prefix, const char *part) {
  sl_expr *e = (sl_expr *)&e; /* any non-NULL value: compile must reset it */
  sl_diag d = {{0}};
  int rc = sl_expr_compile(text, XYT, 3, &e, &d);
  CHECK_MSG(rc == SL_EBADINPUT, "line %d: '%s' gives rc %d, expected SL_EBADINPUT", line, text, rc);
  CHECK_MSG(e == NULL, "line %d: '%s' failed but handed out a program", line, text);
  if (rc == 0 && e) sl_expr_free(e);
  CHECK_MSG(strncmp(d.msg, prefix, strlen(prefix)) == 0, "line %d: '%s': \"%s\" does not start with \"%s\"", line, text,
            d.msg, prefix);
  CHECK_MSG(strstr(d.msg, part) != NULL, "line %d: '%s': \"%s\" does not contain \"%s\"", line, text, d.msg, part);
}
#define EXPECT_ERR(text, prefix, part) expect_error(__LINE__, (text), (prefix), (part))

static double c_sign(double a) { return a > 0 ? 1.0 : a < 0 ? -1.0 : a; }
static double c_min(double a, double b) { return isnan(a) || isnan(b) ? NAN : a < b ? a : b; }
static double c_max(double a, double b) { return isnan(a) || isnan(b) ? NAN : a > b ? a : b; }

static const double PI = 3.14159265358979323846, E = 2.71828182845904523536;

/* ------------------------------------------------------------ values */

static void test_numbers(void) {
  EXPECT("1", 1.0);
  EXPECT("1.5", 1.5);
  EXPECT(".5", 0.5);
  EXPECT("1.", 1.0);
  EXPECT("1e-3", 1e-3);
  EXPECT("2.5E+4", 2.5e4);
  EXPECT("2.5e4", 2.5e4);
  EXPECT("0.1", 0.1);
  EXPECT("007", 7.0);
  EXPECT("123456789012345678901234567890", 123456789012345678901234567890.0);
  EXPECT("1e-400", 0.0); /* underflow is fine */
  EXPECT("4.9e-324", 4.9e-324);
  EXPECT("1.7976931348623157e308", 1.7976931348623157e308);
  EXPECT("pi", PI);
  EXPECT("e", E);
  EXPECT("  \t1 +\n 2\r\n ", 3.0);
  EXPECT("(((((1)))))", 1.0);
}

static void test_arithmetic(void) {
  double x = rt(g_vals[0]), y = rt(g_vals[1]), t = rt(g_vals[2]);
  EXPECT("x", x);
  EXPECT("y", y);
  EXPECT("t", t);
  EXPECT("1 + 2 * 3", 7.0);
  EXPECT("(1 + 2) * 3", 9.0);
  EXPECT("7 / 2", 3.5);
  EXPECT("1 - 2 - 3", -4.0);
  EXPECT("2 / 4 / 8", 0.0625);
  EXPECT("x - y - t", (x - y) - t);
  EXPECT("x - (y - t)", x - (y - t));
  EXPECT("x / y / t", (x / y) / t);
  EXPECT("x / (y / t)", x / (y / t));
  EXPECT("x - y + t", (x - y) + t);
  EXPECT("x + y * t", x + y * t);
  EXPECT("x * y / t", (x * y) / t);
  EXPECT("x / y * t", (x / y) * t);
  EXPECT("x*y + y*t - t*x", x * y + y * t - t * x);
  EXPECT("0.1 + 0.2 + x", (0.1 + 0.2) + x);
  EXPECT("x + 0.1 + 0.2", (x + 0.1) + 0.2); /* no reassociation */
  EXPECT("x * 3 / 7", (x * 3) / 7);
  /* every fused form of the non-commutative operators */
  EXPECT("x - 1", x - 1);
  EXPECT("1 - x", 1 - x);
  EXPECT("x - y", x - y);
  EXPECT("x - y*t", x - y * t);
  EXPECT("y*t - x", y * t - x);
  EXPECT("2 - y*t", 2 - y * t);
  EXPECT("y*t - 2", y * t - 2);
  EXPECT("(x + y) - (y * t)", (x + y) - (y * t));
  EXPECT("x / 3", x / 3);
  EXPECT("3 / x", 3 / x);
  EXPECT("x / t", x / t);
  EXPECT("x / (y + t)", x / (y + t));
  EXPECT("(y + t) / x", (y + t) / x);
  EXPECT("3 / (y + t)", 3 / (y + t));
  EXPECT("(x + y) / (y * t)", (x + y) / (y * t));
  EXPECT("2 * x", 2 * x);
  EXPECT("x * 2", x * 2);
  EXPECT("x * y", x * y);
  EXPECT("x + 1", x + 1);
  EXPECT("1 + x", 1 + x);
  EXPECT("16*x^2*(1-x)^2", 16 * (x * x) * ((1 - x) * (1 - x)));
  EXPECT("0.5*(1 + tanh((y - 0.3)/0.01))", 0.5 * (1 + tanh((y - 0.3) / 0.01)));
  EXPECT("4*x*(1-x)", 4 * x * (1 - x));
  /* IEEE results are values, not errors */
  EXPECT("1/0", INFINITY);
  EXPECT("-1/0", -INFINITY);
  EXPECT("0/0", NAN);
  EXPECT("x/0", x / rt(0.0));
  EXPECT("-0", -0.0);
  EXPECT("0 * -1", -0.0);
  EXPECT("1e308 * 10", INFINITY);
}

static void test_power_unary(void) {
  double x = rt(g_vals[0]), y = rt(g_vals[1]), t = rt(g_vals[2]);
  EXPECT("2^3", 8.0);
  EXPECT("2^3^2", 512.0); /* right-associative: 2^(3^2) */
  EXPECT("(2^3)^2", 64.0);
  EXPECT("-2^2", -4.0); /* ^ binds tighter than unary minus */
  EXPECT("(-2)^2", 4.0);
  EXPECT("-x^2", -(x * x));
  EXPECT("2^-1", 0.5);
  EXPECT("2^-x", pow(2, -x));
  EXPECT("2^-x^2", pow(2, -(x * x)));
  EXPECT("t^x^t", pow(t, pow(x, t)));
  EXPECT("x^2", x * x);
  EXPECT("x^(1+1)", x * x); /* exponent folded to 2: squared */
  EXPECT("pow(x, 2)", x * x);
  EXPECT("x^3", pow(x, 3));
  EXPECT("x^0.5", pow(x, 0.5));
  EXPECT("x^y", pow(x, y));
  EXPECT("2^x", pow(2, x));
  EXPECT("(x+t)^y", pow(x + t, y));
  EXPECT("x^(y+t)", pow(x, y + t));
  EXPECT("(x+t)^(y+t)", pow(x + t, y + t));
  EXPECT("e^x", pow(E, x));
  EXPECT("y^0.5", pow(y, 0.5)); /* NaN */
  EXPECT("-x", -x);
  EXPECT("--x", x);
  EXPECT("- -x", x);
  EXPECT("-+-x", x);
  EXPECT("+x", x);
  EXPECT("-(x + y)", -(x + y));
  EXPECT("2 * -x", 2 * -x);
  EXPECT("2 - -x", 2 - -x);
  EXPECT("-x * y", -x * y);
  EXPECT("-x^2 + 1", -(x * x) + 1);
  EXPECT("!x", 0.0);
  EXPECT("!0", 1.0);
  EXPECT("!!y", 1.0);
  EXPECT("!(0/0)", 0.0);
  EXPECT("!x + 1", 1.0);
  EXPECT("-2^-2", -0.25);
}

static void test_logic(void) {
  double x = rt(g_vals[0]), y = rt(g_vals[1]), t = rt(g_vals[2]);
  EXPECT("x < y", (double)(x < y));
  EXPECT("x > y", (double)(x > y));
  EXPECT("x <= x", 1.0);
  EXPECT("x >= t", (double)(x >= t));
  EXPECT("x == x", 1.0);
  EXPECT("x != x", 0.0);
  EXPECT("x < 1", 1.0);
  EXPECT("1 < x", 0.0);
  EXPECT("x < y + t", (double)(x < y + t));
  EXPECT("y + t < x", (double)(y + t < x));
  EXPECT("(x+y) < (t*x)", (double)((x + y) < (t * x)));
  EXPECT("0/0 == 0/0", 0.0);
  EXPECT("0/0 != 0/0", 1.0);
  EXPECT("1 + 2 < 4", 1.0);
  EXPECT("x < y == t < x", (double)((x < y) == (t < x)));
  EXPECT("y < x && x < t", 1.0);
  EXPECT("x > t || y > t", 0.0);
  EXPECT("1 || 0 && 0", 1.0); /* && binds tighter */
  EXPECT("(1 || 0) && 0", 0.0);
  EXPECT("2 && -3", 1.0);
  EXPECT("0 || 0/0", 1.0);
  EXPECT("x && 0", 0.0);
  EXPECT("1 ? 2 : 3", 2.0);
  EXPECT("0 ? 2 : 3", 3.0);
  EXPECT("0/0 ? 2 : 3", 2.0); /* NaN is not zero */
  EXPECT("x > 0 ? sin(x) : cos(x)", x > 0 ? sin(x) : cos(x));
  EXPECT("x < 0 ? sin(x) : cos(x)", x < 0 ? sin(x) : cos(x));
  EXPECT("x > 1 ? 1 : x > 0 ? 2 : 3", 2.0); /* right-associative */
  EXPECT("x < 0.5 ? x < 0.2 ? 1 : 2 : 3", 2.0);
  EXPECT("x > 0 ? 1 : 0 + 5", 1.0);
  EXPECT("0 ? 1 : 2 + 3", 5.0);
  EXPECT("1 + (x > 0 ? 1 : 2)", 2.0);
  EXPECT("(x > 0 ? x : y) * 2", x * 2);
  EXPECT("y > 0 ? x : y < -1 ? t : 0", t);
  EXPECT("1 ? x : y", x);
  EXPECT("0 ? x : y", y);
  EXPECT("x ? y : t", y);
  EXPECT("x - x ? y : t", t);
  EXPECT("(x > 0) + (y > 0) + (t > 0)", 2.0);
  EXPECT("step(x) * step(t - x)", 1.0);
}

static void test_functions(void) {
  double x = rt(g_vals[0]), y = rt(g_vals[1]), t = rt(g_vals[2]);
  EXPECT("sin(x)", sin(x));
  EXPECT("cos(x)", cos(x));
  EXPECT("tan(x)", tan(x));
  EXPECT("asin(x)", asin(x));
  EXPECT("acos(x)", acos(x));
  EXPECT("atan(y)", atan(y));
  EXPECT("atan2(y, x)", atan2(y, x));
  EXPECT("atan2(1, x + y)", atan2(1, x + y));
  EXPECT("atan2(x + y, 1)", atan2(x + y, 1));
  EXPECT("atan2(x, y + t)", atan2(x, y + t));
  EXPECT("sinh(y)", sinh(y));
  EXPECT("cosh(y)", cosh(y));
  EXPECT("tanh(y)", tanh(y));
  EXPECT("exp(y)", exp(y));
  EXPECT("log(t)", log(t));
  EXPECT("log10(t)", log10(t));
  EXPECT("sqrt(t)", sqrt(t));
  EXPECT("abs(y)", fabs(y));
  EXPECT("min(x, y)", c_min(x, y));
  EXPECT("max(x, y)", c_max(x, y));
  EXPECT("max(x, y, t)", c_max(c_max(x, y), t));
  EXPECT("min(t, x, y, 0)", c_min(c_min(c_min(t, x), y), 0));
  EXPECT("min(0/0, 1)", NAN);
  EXPECT("max(1, 0/0)", NAN);
  EXPECT("max(x, 0/0)", NAN);
  EXPECT("pow(t, x)", pow(t, x));
  EXPECT("floor(y)", floor(y));
  EXPECT("ceil(y)", ceil(y));
  EXPECT("sign(y)", -1.0);
  EXPECT("sign(x)", 1.0);
  EXPECT("sign(0)", 0.0);
  EXPECT("sign(-0)", -0.0);
  EXPECT("sign(0/0)", NAN);
  EXPECT("step(y)", 0.0);
  EXPECT("step(0)", 1.0);
  EXPECT("step(-0)", 1.0);
  EXPECT("step(x)", 1.0);
  EXPECT("sqrt(-1)", NAN);
  EXPECT("log(0)", -INFINITY);
  EXPECT("log(-1)", NAN);
  /* folded at compile time with the same libm calls */
  EXPECT("sin(0.5)", sin(rt(0.5)));
  EXPECT("exp(1)", exp(rt(1.0)));
  EXPECT("sin(pi/6)", sin(rt(PI) / 6));
  EXPECT("atan2(1, 2)", atan2(rt(1.0), rt(2.0)));
  EXPECT("2*pi*x", 2 * PI * x);
  EXPECT("sin(2*pi*x)*exp(-t)", sin(2 * PI * x) * exp(-t));
  EXPECT("sqrt(x^2 + y^2)", sqrt(x * x + y * y));
  EXPECT("sign(y) * sign(x)", c_sign(y) * c_sign(x));
  EXPECT("cos(sin(cos(x)))", cos(sin(cos(x))));
  EXPECT("max(min(x, t), min(y, t))", c_max(c_min(x, t), c_min(y, t)));
}

static void test_variables(void) {
  /* other names, and no variables at all */
  static const char *const polar[] = {"r", "theta", "_t0"};
  sl_expr *e = NULL;
  sl_diag d = {{0}};
  double r = rt(2.0), th = rt(0.7), t0 = rt(-1.25);
  double vals[3] = {r, th, t0};
  CHECK(sl_expr_compile("r*cos(theta) + _t0", polar, 3, &e, &d) == 0);
  if (e) {
    CHECK(same(sl_expr_eval(e, vals), r * cos(th) + t0));
    CHECK(sl_expr_uses(e, 0) && sl_expr_uses(e, 1) && sl_expr_uses(e, 2));
    sl_expr_free(e);
  }
  CHECK(sl_expr_compile("2 + 3", NULL, 0, &e, &d) == 0);
  if (e) {
    CHECK(same(sl_expr_eval(e, NULL), 5.0));
    sl_expr_free(e);
  }
  e = (sl_expr *)&e;
  CHECK(sl_expr_compile("x", NULL, 0, &e, &d) == SL_EBADINPUT);
  CHECK(e == NULL);
  CHECK_CONTAINS(d.msg, "column 1: unknown name 'x' (this value takes no variables)");

  /* bad variable lists are the caller's bug, but still reported */
  static const char *const twice[] = {"x", "x"}, *const builtin[] = {"x", "sin"}, *const cnst[] = {"e"},
                           *const digit[] = {"1a"}, *const blank[] = {""}, *const none[] = {NULL};
  CHECK(sl_expr_compile("1", twice, 2, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK_CONTAINS(d.msg, "'x' is listed twice");
  CHECK(sl_expr_compile("1", builtin, 2, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK_CONTAINS(d.msg, "'sin' is a built-in name");
  CHECK(sl_expr_compile("1", cnst, 1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK_CONTAINS(d.msg, "'e' is a built-in name");
  CHECK(sl_expr_compile("1", digit, 1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK_CONTAINS(d.msg, "variable 0 has an invalid name");
  CHECK(sl_expr_compile("1", blank, 1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile("1", none, 1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile("1", NULL, 2, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile("1", XYT, -1, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile(NULL, XYT, 3, &e, &d) == SL_EBADINPUT && e == NULL);
  CHECK(sl_expr_compile("1", XYT, 3, NULL, &d) == SL_EBADINPUT);
  CHECK(sl_expr_compile("1 +", XYT, 3, &e, NULL) == SL_EBADINPUT && e == NULL); /* d may be NULL */
  sl_expr_free(NULL);
}

/* ------------------------------------------------------------ folding */

static void expect_folding(int line, const char *text, int is_const, double value, int ux, int uy, int ut) {
  sl_expr *e = NULL;
  sl_diag d = {{0}};
  CHECK_MSG(sl_expr_compile(text, XYT, 3, &e, &d) == 0, "line %d: '%s': %s", line, text, d.msg);
  if (!e) return;
  double v = -12345;
  int c = sl_expr_is_constant(e, &v);
  CHECK_MSG(c == is_const, "line %d: '%s': is_constant %d, expected %d", line, text, c, is_const);
  if (is_const) {
    CHECK_MSG(same(v, value), "line %d: '%s': constant %.17g, expected %.17g", line, text, v, value);
    CHECK_MSG(same(sl_expr_eval(e, NULL), value), "line %d: '%s': eval without values", line, text);
    CHECK(sl_expr_is_constant(e, NULL) == 1);
  } else {
    CHECK_MSG(v == -12345, "line %d: '%s': is_constant wrote a value", line, text);
  }
  int u[3] = {ux, uy, ut};
  for (int i = 0; i < 3; ++i)
    CHECK_MSG(sl_expr_uses(e, i) == u[i], "line %d: '%s': uses(%s) = %d", line, text, XYT[i], sl_expr_uses(e, i));
  CHECK(sl_expr_uses(e, -1) == 0 && sl_expr_uses(e, 3) == 0);
  sl_expr_free(e);
}
#define EXPECT_FOLD(text, c, v, ux, uy, ut) expect_folding(__LINE__, (text), (c), (v), (ux), (uy), (ut))

static void test_folding(void) {
  EXPECT_FOLD("1 + 2 * 3", 1, 7.0, 0, 0, 0);
  EXPECT_FOLD("-(3)", 1, -3.0, 0, 0, 0);
  EXPECT_FOLD("2*pi", 1, 2 * PI, 0, 0, 0);
  EXPECT_FOLD("sin(pi/2)", 1, sin(rt(PI) / 2), 0, 0, 0);
  EXPECT_FOLD("max(1, 2, 3)", 1, 3.0, 0, 0, 0);
  EXPECT_FOLD("1 > 0 && 2 > 1", 1, 1.0, 0, 0, 0);
  EXPECT_FOLD("1 ? 2 : x", 1, 2.0, 0, 0, 0); /* the branch with x is dropped */
  EXPECT_FOLD("0 ? y : 2^3", 1, 8.0, 0, 0, 0);
  EXPECT_FOLD("0 ? 2 : x", 0, 0, 1, 0, 0);
  EXPECT_FOLD("1 < 2 ? t : y", 0, 0, 0, 0, 1);
  EXPECT_FOLD("x * 0", 0, 0, 1, 0, 0); /* no algebra: x may be inf */
  EXPECT_FOLD("x - x", 0, 0, 1, 0, 0);
  EXPECT_FOLD("(2^2)^x", 0, 0, 1, 0, 0);
  EXPECT_FOLD("x + t", 0, 0, 1, 0, 1);
  EXPECT_FOLD("y ? 1 : 2", 0, 0, 0, 1, 0);
  EXPECT_FOLD("min(1, t, 3)", 0, 0, 0, 0, 1);
  EXPECT_FOLD("atan2(y, 1)", 0, 0, 0, 1, 0);
  EXPECT_FOLD("1/0", 1, INFINITY, 0, 0, 0);
  EXPECT_FOLD("0/0", 1, NAN, 0, 0, 0);
  EXPECT_FOLD("16*2^2*(1-2)^2", 1, 64.0, 0, 0, 0);
  EXPECT_FOLD("(1 + 2) * x", 0, 0, 1, 0, 0);
}

/* ------------------------------------------------------------ errors */

static void test_errors(void) {
  EXPECT_ERR("", "empty expression", "expected a number, a name or '('");
  EXPECT_ERR("  \t\n ", "empty expression", "");
  EXPECT_ERR("2*x + sinn(x)", "column 7: ", "unknown name 'sinn'; did you mean 'sin'?");
  EXPECT_ERR("sinn(x)", "column 1: ", "unknown name 'sinn'; did you mean 'sin'?");
  EXPECT_ERR("Sin(x)", "column 1: ", "did you mean 'sin'?");
  EXPECT_ERR("atan3(x, y)", "column 1: ", "did you mean 'atan'?");
  EXPECT_ERR("xx + 1", "column 1: ", "unknown name 'xx'; did you mean 'x'?");
  EXPECT_ERR("1 + pii", "column 5: ", "did you mean 'pi'?");
  EXPECT_ERR("1 + sqr", "column 5: ", "did you mean 'sqrt'?"); /* no '(': values first, then functions */
  EXPECT_ERR("foo + 1", "column 1: ", "unknown name 'foo' (variables: x, y, t)");
  EXPECT_ERR("x + z", "column 5: ", "unknown name 'z' (variables: x, y, t)");
  EXPECT_ERR("frobnicate(1)", "column 1: ", "unknown function 'frobnicate'");
  EXPECT_ERR("2 *(x + y  t)", "column 12: ", "expected ')' to close the '(' at column 4, found 't'");
  EXPECT_ERR("(1 + 2", "column 7: ", "expected ')' to close the '(' at column 1, found the end of the expression");
  EXPECT_ERR("((1 + 2)", "column 9: ", "to close the '(' at column 1");
  EXPECT_ERR("atan2(1)", "column 1: ", "atan2 takes 2 arguments, got 1");
  EXPECT_ERR("x + atan2(1, 2, 3)", "column 5: ", "atan2 takes 2 arguments, got 3");
  EXPECT_ERR("sin(1, 2)", "column 1: ", "sin takes 1 argument, got 2");
  EXPECT_ERR("1 + sin()", "column 5: ", "sin takes 1 argument, got 0");
  EXPECT_ERR("min(1)", "column 1: ", "min takes at least 2 arguments, got 1");
  EXPECT_ERR("max()", "column 1: ", "max takes at least 2 arguments, got 0");
  EXPECT_ERR("pow(2)", "column 1: ", "pow takes 2 arguments, got 1");
  EXPECT_ERR("sin(1, 2", "column 9: ", "expected ',' or ')' to close the '(' at column 4, found the end");
  EXPECT_ERR("atan2(1 2)", "column 9: ", "expected ',' or ')' to close the '(' at column 6, found '2'");
  EXPECT_ERR("sin x", "column 5: ", "expected '(' after function 'sin', found 'x'");
  EXPECT_ERR("1 + sin", "column 8: ", "expected '(' after function 'sin', found the end of the expression");
  EXPECT_ERR("x(2)", "column 1: ", "'x' is a variable, not a function");
  EXPECT_ERR("1 + pi(2)", "column 5: ", "'pi' is a constant, not a function");
  EXPECT_ERR("1 + 2 )", "column 7: ", "unmatched ')'");
  EXPECT_ERR("1 2",
             "column 3: ", "expected an operator or the end of the expression, found '2'; write '*' to multiply");
  EXPECT_ERR("2x", "column 2: ", "found 'x'; write '*' to multiply");
  EXPECT_ERR("2 (x)", "column 3: ", "found '('; write '*' to multiply");
  EXPECT_ERR("(x) y", "column 5: ", "write '*' to multiply");
  EXPECT_ERR("1e", "column 2: ", "found 'e'; write '*' to multiply");
  EXPECT_ERR("1.2.3", "column 4: ", "found '.3'");
  EXPECT_ERR("x , y", "column 3: ", "expected an operator or the end of the expression, found ','");
  EXPECT_ERR("x : 1", "column 3: ", "found ':'");
  EXPECT_ERR("1 +", "column 4: ", "expected a number, a name or '(' after '+', found the end of the expression");
  EXPECT_ERR("* 2", "column 1: ", "expected a number, a name or '(', found '*'");
  EXPECT_ERR("2**3", "column 3: ", "after '*', found '*'; use '^' for powers");
  EXPECT_ERR("()", "column 2: ", "after '(', found ')'");
  EXPECT_ERR("sin(,1)", "column 5: ", "after '(', found ','");
  EXPECT_ERR("max(1,)", "column 7: ", "after ',', found ')'");
  EXPECT_ERR("x ? 1", "column 6: ", "expected ':' to complete the '?' at column 3, found the end of the expression");
  EXPECT_ERR("x ? 1 , 2", "column 7: ", "expected ':' to complete the '?' at column 3, found ','");
  EXPECT_ERR("x ? : 2", "column 5: ", "after '?', found ':'");
  EXPECT_ERR("0 < x < 1", "column 7: ", "comparisons do not chain: write 'a < b && b < c'");
  EXPECT_ERR("x == y != t", "column 8: ", "comparisons do not chain: write 'a == b && b != c'");
  EXPECT_ERR("x = 1", "column 3: ", "unexpected '='; did you mean '=='?");
  EXPECT_ERR("x & y", "column 3: ", "unexpected '&'; did you mean '&&'?");
  EXPECT_ERR("x | y", "column 3: ", "unexpected '|'; did you mean '||'?");
  EXPECT_ERR("1 # 2", "column 3: ", "unexpected character '#'");
  EXPECT_ERR("x % 2", "column 3: ", "unexpected character '%'");
  EXPECT_ERR("x \xc3\x97 2", "column 3: ", "unexpected character '\xc3\x97'");
  EXPECT_ERR("\xc3\xa9t\xc3\xa9 + \xff", "column 1: ", "unexpected character '\xc3\xa9'");
  EXPECT_ERR("1 + \xff", "column 5: ", "unexpected byte 0xFF");
  EXPECT_ERR("1 + \x01", "column 5: ", "unexpected control character 0x01");
  EXPECT_ERR("1e+", "column 1: ", "malformed number '1e+': expected digits after 'e+'");
  EXPECT_ERR("x + 2.5E-", "column 5: ", "malformed number '2.5E-'");
  EXPECT_ERR("1e999", "column 1: ", "number '1e999' is too large");
  EXPECT_ERR(". 5", "column 1: ", "unexpected '.'");
  EXPECT_ERR("1 + inf", "column 5: ", "unknown name 'inf'");
  EXPECT_ERR("0x10", "column 2: ", "found 'x10'");

  /* limits: length, nesting, stack */
  char *buf = malloc(3 * SL_EXPR_MAX_LEN + 16);
  CHECK(buf != NULL);
  if (!buf) return;
  size_t n = 0;
  while (n < SL_EXPR_MAX_LEN) {
    buf[n++] = '1';
    buf[n++] = '+';
  }
  buf[n++] = '1';
  buf[n] = '\0';
  EXPECT_ERR(buf, "expression is too long", "more than 4096 characters");
  buf[SL_EXPR_MAX_LEN - 1] = '\0'; /* "1+1+...+1", 4095 characters: fine */
  EXPECT(buf, (double)(SL_EXPR_MAX_LEN / 2));

  n = 0;
  for (int i = 0; i < SL_EXPR_MAX_NEST; ++i) buf[n++] = '(';
  buf[n++] = 'x';
  for (int i = 0; i < SL_EXPR_MAX_NEST; ++i) buf[n++] = ')';
  buf[n] = '\0';
  EXPECT(buf, g_vals[0]); /* 200 levels: fine */
  memmove(buf + 1, buf, n + 1);
  buf[0] = '(';
  strcat(buf, ")");
  EXPECT_ERR(buf, "column 201: ", "nested too deeply (more than 200 levels)");
  n = 0;
  for (int i = 0; i < 300; ++i) buf[n++] = '-';
  strcpy(buf + n, "x");
  EXPECT_ERR(buf, "column 201: ", "nested too deeply");
  n = 0;
  for (int i = 0; i < 300; ++i) {
    buf[n++] = '2';
    buf[n++] = '^';
  }
  strcpy(buf + n, "1");
  EXPECT_ERR(buf, "column 402: ", "nested too deeply");
  n = 0;
  for (int i = 0; i < 300; ++i) {
    memcpy(buf + n, "x?", 2);
    n += 2;
  }
  strcpy(buf + n, "1");
  EXPECT_ERR(buf, "column 402: ", "nested too deeply");

  /* (x+y)*((x+y)*(...)): every level keeps one value on the stack. */
  for (int levels = 60; levels <= 70; levels += 10) {
    n = 0;
    for (int i = 0; i < levels; ++i) {
      memcpy(buf + n, "(x+y)*(", 7);
      n += 7;
    }
    buf[n++] = 't';
    for (int i = 0; i < levels; ++i) buf[n++] = ')';
    buf[n] = '\0';
    double s = g_vals[0] + g_vals[1], ref = g_vals[2];
    for (int i = 0; i < levels; ++i) ref = s * ref;
    if (levels == 60) EXPECT(buf, ref);
    else EXPECT_ERR(buf, "expression too complex", "evaluation stack slots, at most 64");
  }
  free(buf);
}

/* ------------------------------------------------------------ randomized round trip */

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static uint64_t rng(void) { /* xorshift64* */
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return rng_state * 2685821657736338717ull;
}
static int rnd(int n) { return (int)(rng() % (uint64_t)n); }

enum { N_NUM, N_VAR, N_PI, N_E, N_NEG, N_POS, N_NOT, N_BIN, N_TERN, N_FUNC };
enum { B_ADD, B_SUB, B_MUL, B_DIV, B_POW, B_LT, B_LE, B_GT, B_GE, B_EQ, B_NE, B_AND, B_OR, N_BINS };
static const char *const bin_text[N_BINS] = {"+", "-", "*", "/", "^", "<", "<=", ">", ">=", "==", "!=", "&&", "||"};
static const int bin_prec[N_BINS] = {6, 6, 7, 7, 9, 5, 5, 5, 5, 4, 4, 3, 2};

typedef struct {
  const char *name;
  int nargs; /* -1: 2 to 4 */
} rfunc;
static const rfunc rfuncs[] = {{"sin", 1},   {"cos", 1},  {"tan", 1},  {"asin", 1}, {"acos", 1}, {"atan", 1},
                               {"atan2", 2}, {"sinh", 1}, {"cosh", 1}, {"tanh", 1}, {"exp", 1},  {"log", 1},
                               {"log10", 1}, {"sqrt", 1}, {"abs", 1},  {"min", -1}, {"max", -1}, {"pow", 2},
                               {"floor", 1}, {"ceil", 1}, {"sign", 1}, {"step", 1}};
enum { N_RFUNCS = (int)(sizeof rfuncs / sizeof rfuncs[0]) };

typedef struct node {
  int kind, op, nkids;
  double num;
  char text[40]; /* how a number is written */
  int kid[4];
} node;

typedef struct {
  node nodes[256];
  int n;
  int budget;
} tree;

static double c_func(int f, const double *a, int n) {
  switch (f) {
    case 0:
      return sin(a[0]);
    case 1:
      return cos(a[0]);
    case 2:
      return tan(a[0]);
    case 3:
      return asin(a[0]);
    case 4:
      return acos(a[0]);
    case 5:
      return atan(a[0]);
    case 6:
      return atan2(a[0], a[1]);
    case 7:
      return sinh(a[0]);
    case 8:
      return cosh(a[0]);
    case 9:
      return tanh(a[0]);
    case 10:
      return exp(a[0]);
    case 11:
      return log(a[0]);
    case 12:
      return log10(a[0]);
    case 13:
      return sqrt(a[0]);
    case 14:
      return fabs(a[0]);
    case 15:
    case 16: {
      double r = a[0];
      for (int i = 1; i < n; ++i) r = f == 15 ? c_min(r, a[i]) : c_max(r, a[i]);
      return r;
    }
    case 17:
      return pow(a[0], a[1]);
    case 18:
      return floor(a[0]);
    case 19:
      return ceil(a[0]);
    case 20:
      return c_sign(a[0]);
    default:
      return (double)(a[0] >= 0);
  }
}

static int gen(tree *T, int depth) {
  int id = T->n++;
  node *nd = &T->nodes[id];
  memset(nd, 0, sizeof *nd);
  int leaf = depth <= 0 || T->budget <= 0 || T->n > 200 || rnd(5) == 0;
  --T->budget;
  if (leaf) {
    int r = rnd(10);
    if (r < 4) {
      nd->kind = N_NUM;
      static const char *const lits[] = {"0", "1", "2", "3", "0.5", ".5", "1.", "1e-3", "2.5E+4", "1e2", "10", "0.1"};
      int form = rnd(3);
      if (form == 0) {
        snprintf(nd->text, sizeof nd->text, "%s", lits[rnd((int)(sizeof lits / sizeof lits[0]))]);
      } else if (form == 1) {
        snprintf(nd->text, sizeof nd->text, "%d", rnd(10));
      } else {
        snprintf(nd->text, sizeof nd->text, "%.17g", (double)(rng() >> 11) / 9007199254740992.0 * 4.0);
      }
      nd->num = strtod(nd->text, NULL);
    } else if (r < 8) {
      nd->kind = N_VAR;
      nd->op = rnd(3);
    } else {
      nd->kind = r == 8 ? N_PI : N_E;
    }
    return id;
  }
  int r = rnd(20);
  if (r < 2) {
    nd->kind = r == 0 ? N_NEG : rnd(2) ? N_POS : N_NOT;
    nd->nkids = 1;
  } else if (r < 14) {
    nd->kind = N_BIN;
    nd->op = rnd(N_BINS);
    nd->nkids = 2;
  } else if (r < 16) {
    nd->kind = N_TERN;
    nd->nkids = 3;
  } else {
    nd->kind = N_FUNC;
    nd->op = rnd(N_RFUNCS);
    nd->nkids = rfuncs[nd->op].nargs > 0 ? rfuncs[nd->op].nargs : 2 + rnd(3);
  }
  for (int k = 0; k < nd->nkids; ++k) {
    int kid = gen(T, depth - 1);
    T->nodes[id].kid[k] = kid; /* nd may not move (fixed array), but be explicit */
  }
  return id;
}

static int prec(const tree *T, int id) {
  const node *nd = &T->nodes[id];
  switch (nd->kind) {
    case N_TERN:
      return 1;
    case N_BIN:
      return bin_prec[nd->op];
    case N_NEG:
    case N_POS:
    case N_NOT:
      return 8;
    default:
      return 10;
  }
}

/* Appends with a random blank before and after. */
static void put(char *buf, size_t *len, size_t cap, const char *s) {
  const char *blanks[] = {"", "", "", " ", "  ", "\t"};
  int w = snprintf(buf + *len, cap - *len, "%s%s", blanks[rnd(6)], s);
  if (w > 0) *len += (size_t)w < cap - *len ? (size_t)w : cap - *len - 1;
}

static void print(const tree *T, int id, char *buf, size_t *len, size_t cap);

static void print_kid(const tree *T, int id, int need_parens, char *buf, size_t *len, size_t cap) {
  int parens = need_parens || rnd(12) == 0;
  if (parens) put(buf, len, cap, "(");
  print(T, id, buf, len, cap);
  if (parens) put(buf, len, cap, ")");
}

/* The fewest parentheses the grammar needs (plus random extra ones). */
static void print(const tree *T, int id, char *buf, size_t *len, size_t cap) {
  const node *nd = &T->nodes[id];
  static const char *const vars[] = {"x", "y", "t"};
  /* a blank between two tokens that would otherwise merge ("2" "e", "-" "-") is added by put() only at
     random, so keep names, numbers and signs apart explicitly */
  switch (nd->kind) {
    case N_NUM:
      put(buf, len, cap, " ");
      put(buf, len, cap, nd->text);
      break;
    case N_VAR:
      put(buf, len, cap, vars[nd->op]);
      break;
    case N_PI:
      put(buf, len, cap, "pi");
      break;
    case N_E:
      put(buf, len, cap, " e");
      break;
    case N_NEG:
    case N_POS:
    case N_NOT:
      put(buf, len, cap, nd->kind == N_NEG ? "-" : nd->kind == N_POS ? "+" : "!");
      print_kid(T, nd->kid[0], prec(T, nd->kid[0]) < 8, buf, len, cap);
      break;
    case N_BIN: {
      int p = bin_prec[nd->op], pl = prec(T, nd->kid[0]), pr = prec(T, nd->kid[1]);
      int lp, rpar;
      if (nd->op == B_POW) {
        lp = pl < 10;  /* the base is a primary */
        rpar = pr < 8; /* the exponent is a unary */
      } else if (p == 4 || p == 5) {
        lp = pl <= p; /* comparisons do not chain */
        rpar = pr <= p;
      } else {
        lp = pl < p;
        rpar = pr <= p;
      }
      print_kid(T, nd->kid[0], lp, buf, len, cap);
      put(buf, len, cap, " ");
      put(buf, len, cap, bin_text[nd->op]);
      put(buf, len, cap, " ");
      print_kid(T, nd->kid[1], rpar, buf, len, cap);
      break;
    }
    case N_TERN:
      print_kid(T, nd->kid[0], prec(T, nd->kid[0]) <= 1, buf, len, cap);
      put(buf, len, cap, "?");
      print_kid(T, nd->kid[1], 0, buf, len, cap);
      put(buf, len, cap, ":");
      print_kid(T, nd->kid[2], 0, buf, len, cap);
      break;
    default:
      put(buf, len, cap, rfuncs[nd->op].name);
      put(buf, len, cap, "(");
      for (int k = 0; k < nd->nkids; ++k) {
        if (k) put(buf, len, cap, ",");
        print_kid(T, nd->kid[k], 0, buf, len, cap);
      }
      put(buf, len, cap, ")");
  }
}

/* Whether the compiler folds the node to one constant: no variable, or a
 * constant condition choosing a constant branch. */
static int is_const(const tree *T, int id, const double *vals);
static double value(const tree *T, int id, const double *vals);

static int is_const(const tree *T, int id, const double *vals) {
  const node *nd = &T->nodes[id];
  if (nd->kind == N_VAR) return 0;
  if (nd->kind == N_TERN) {
    if (!is_const(T, nd->kid[0], vals)) return 0;
    return is_const(T, nd->kid[value(T, nd->kid[0], vals) != 0 ? 1 : 2], vals);
  }
  for (int k = 0; k < nd->nkids; ++k)
    if (!is_const(T, nd->kid[k], vals)) return 0;
  return 1;
}

static int uses(const tree *T, int id, int var, const double *vals) {
  const node *nd = &T->nodes[id];
  if (nd->kind == N_VAR) return nd->op == var;
  if (nd->kind == N_TERN && is_const(T, nd->kid[0], vals))
    return uses(T, nd->kid[value(T, nd->kid[0], vals) != 0 ? 1 : 2], var, vals);
  for (int k = 0; k < nd->nkids; ++k)
    if (uses(T, nd->kid[k], var, vals)) return 1;
  return 0;
}

/* x^c with c folding to exactly 2 is a*a, as documented. */
static double power(const tree *T, int base, int expo, const double *vals) {
  double a = value(T, base, vals), b = value(T, expo, vals);
  if (is_const(T, expo, vals) && b == 2) return a * a;
  return pow(a, b);
}

static double value(const tree *T, int id, const double *vals) {
  const node *nd = &T->nodes[id];
  switch (nd->kind) {
    case N_NUM:
      return nd->num;
    case N_VAR:
      return vals[nd->op];
    case N_PI:
      return PI;
    case N_E:
      return E;
    case N_NEG:
      return -value(T, nd->kid[0], vals);
    case N_POS:
      return value(T, nd->kid[0], vals);
    case N_NOT:
      return (double)(value(T, nd->kid[0], vals) == 0);
    case N_TERN:
      return value(T, nd->kid[value(T, nd->kid[0], vals) != 0 ? 1 : 2], vals);
    case N_BIN: {
      if (nd->op == B_POW) return power(T, nd->kid[0], nd->kid[1], vals);
      double a = value(T, nd->kid[0], vals), b = value(T, nd->kid[1], vals);
      switch (nd->op) {
        case B_ADD:
          return a + b;
        case B_SUB:
          return a - b;
        case B_MUL:
          return a * b;
        case B_DIV:
          return a / b;
        case B_LT:
          return (double)(a < b);
        case B_LE:
          return (double)(a <= b);
        case B_GT:
          return (double)(a > b);
        case B_GE:
          return (double)(a >= b);
        case B_EQ:
          return (double)(a == b);
        case B_NE:
          return (double)(a != b);
        case B_AND:
          return (double)(a != 0 && b != 0);
        default:
          return (double)(a != 0 || b != 0);
      }
    }
    default: {
      if (nd->op == 17) return power(T, nd->kid[0], nd->kid[1], vals);
      double a[4];
      for (int k = 0; k < nd->nkids; ++k) a[k] = value(T, nd->kid[k], vals);
      return c_func(nd->op, a, nd->nkids);
    }
  }
}

static void test_random(void) {
  enum { ROUNDS = 20000 };
  static const double points[][3] = {{0.3, -1.7, 2.5}, {0, 0, 0}, {-0.75, 1, 3}, {1, 2, 0.5}, {-2, -0.5, 1e-3}};
  enum { N_POINTS = (int)(sizeof points / sizeof points[0]) };
  tree *T = malloc(sizeof *T);
  char *buf = malloc(SL_EXPR_MAX_LEN + 1);
  CHECK(T != NULL && buf != NULL);
  if (!T || !buf) {
    free(T);
    free(buf);
    return;
  }
  int bad_compile = 0, bad_value = 0, bad_const = 0, bad_uses = 0, evaluated = 0;
  for (int round = 0; round < ROUNDS; ++round) {
    T->n = 0;
    T->budget = 4 + rnd(60);
    int root = gen(T, 2 + rnd(6));
    size_t len = 0;
    buf[0] = '\0';
    print(T, root, buf, &len, SL_EXPR_MAX_LEN + 1);
    sl_expr *e = NULL;
    sl_diag d = {{0}};
    if (sl_expr_compile(buf, XYT, 3, &e, &d) != 0) {
      if (++bad_compile <= 5) fprintf(stderr, "random: '%s' does not compile: %s\n", buf, d.msg);
      continue;
    }
    /* constness and uses are the same at every point (they do not depend on variables) */
    int c = sl_expr_is_constant(e, NULL);
    if (c != is_const(T, root, points[0]) && ++bad_const <= 5)
      fprintf(stderr, "random: '%s': is_constant %d\n", buf, c);
    for (int v = 0; v < 3; ++v)
      if (sl_expr_uses(e, v) != uses(T, root, v, points[0]) && ++bad_uses <= 5)
        fprintf(stderr, "random: '%s': uses(%d) = %d\n", buf, v, sl_expr_uses(e, v));
    for (int p = 0; p < N_POINTS; ++p) {
      double vals[3] = {rt(points[p][0]), rt(points[p][1]), rt(points[p][2])};
      double got = sl_expr_eval(e, vals), want = value(T, root, vals);
      ++evaluated;
      if (!same(got, want) && ++bad_value <= 5)
        fprintf(stderr, "random: '%s' at (%g, %g, %g) = %.17g, tree gives %.17g\n", buf, vals[0], vals[1], vals[2], got,
                want);
    }
    sl_expr_free(e);
  }
  CHECK_MSG(bad_compile == 0, "%d of %d random expressions did not compile", bad_compile, ROUNDS);
  CHECK_MSG(bad_value == 0, "%d of %d random evaluations differ", bad_value, evaluated);
  CHECK_MSG(bad_const == 0, "%d random expressions with a wrong is_constant", bad_const);
  CHECK_MSG(bad_uses == 0, "%d wrong uses() answers", bad_uses);
  CHECK(evaluated == ROUNDS * N_POINTS);
  printf("random round trip: %d expressions, %d evaluations\n", ROUNDS, evaluated);
  free(T);
  free(buf);
}

int main(void) {
  g_vals[0] = rt(0.3);
  g_vals[1] = rt(-1.7);
  g_vals[2] = rt(2.5);
  test_numbers();
  test_arithmetic();
  test_power_unary();
  test_logic();
  test_functions();
  test_variables();
  test_folding();
  test_errors();
  test_random();
  return sl_test_summary();
}
