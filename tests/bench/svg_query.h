/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Reading a written SVG back through xmllint (libxml2-utils): the plotting
 * tests query axis ranges, ticks and labels by XPath. */
#ifndef SLUICE_TESTS_SVG_QUERY_H
#define SLUICE_TESTS_SVG_QUERY_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* xmllint's answer to an XPath string expression on file, or "" */
static inline void svg_xpath(const char *file, const char *expr, char *out, size_t n) {
  char cmd[2048];
  snprintf(cmd, sizeof cmd, "xmllint --xpath \"%s\" %s 2>/dev/null", expr, file);
  out[0] = '\0';
  FILE *p = popen(cmd, "r");
  if (!p) return;
  size_t got = fread(out, 1, n - 1, p);
  out[got] = '\0';
  pclose(p);
  while (got > 0 && (out[got - 1] == '\n' || out[got - 1] == ' ')) out[--got] = '\0';
}

/* the expression's answer as a number; NaN if it is not one */
static inline double svg_xpath_number(const char *file, const char *expr) {
  char buf[256], *end;
  svg_xpath(file, expr, buf, sizeof buf);
  double v = strtod(buf, &end);
  return end == buf ? NAN : v;
}

static inline int svg_have_xmllint(void) { return system("xmllint --version >/dev/null 2>&1") == 0; }

#endif
