/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The benchmark programs' --replot: the shipped figures redrawn from the
 * shipped CSVs (bench/results/), running nothing. The SVGs are read back by
 * xmllint: the axes cover the recorded values and the reference slopes carry
 * the observed orders, which are the least-squares slopes of log error on
 * log n over the CSV's finest meshes:
 *  - cavity_work_precision.csv, n = 64, 128, 256 (errors 5.093e-7, 1.317e-7,
 *    3.407e-8): 1.95, the same as log2|r| of the Richardson extrapolation the
 *    errors are measured against (r = -3.866), as it must be: against that
 *    extrapolation the three errors are in geometric progression of ratio |r|;
 *  - cavity_vs_freefem.csv, n = 64..128: sluice 2.91 (max-norm), 2.90 (L2),
 *    FreeFEM 2.62 and 2.17 (computed from the CSV's columns independently).
 * A CSV with a row the program did not write is refused with file:line and
 * exit status 2. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "svg_query.h"
#include "testing.h"

static int run(const char *cmd) {
  int st = system(cmd);
  return st == -1 || !WIFEXITED(st) ? -1 : WEXITSTATUS(st);
}

/* panel k's axis a ("x" or "y") covers lo..hi */
static void covers(const char *file, int k, const char *a, double lo, double hi) {
  char e[128];
  snprintf(e, sizeof e, "string((//*[@data-axis='%s'])[%d]/@data-lo)", a, k);
  double l = svg_xpath_number(file, e);
  snprintf(e, sizeof e, "string((//*[@data-axis='%s'])[%d]/@data-hi)", a, k);
  double h = svg_xpath_number(file, e);
  CHECK_MSG(l <= lo && h >= hi, "%s panel %d: %s axis %g .. %g does not cover %g .. %g", file, k, a, l, h, lo, hi);
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR"), *cwp = getenv("BENCH_CAVITY_WORK_PRECISION"),
             *cvf = getenv("BENCH_CAVITY_VS_FREEFEM");
  if (!src || !cwp || !cvf) return printf("SKIP: SLUICE_SOURCE_DIR, BENCH_CAVITY_* not set\n"), sl_test_summary();
  if (run("xmllint --version >/dev/null 2>&1")) return printf("SKIP: no xmllint\n"), sl_test_summary();
  char cmd[4096], out[4096];

  snprintf(cmd, sizeof cmd, "%s --replot %s/bench/results/cavity_work_precision.csv --svg replot_cwp.svg", cwp, src);
  CHECK(run(cmd) == 0);
  CHECK(run("xmllint --noout replot_cwp.svg") == 0);
  svg_xpath("replot_cwp.svg", "string(//*[@class='slope'])", out, sizeof out);
  CHECK_MSG(!strcmp(out, "order 1.95"), "slope: %s", out);
  CHECK(svg_xpath_number("replot_cwp.svg", "count(//*[@class='slope'])") == 1.0);
  covers("replot_cwp.svg", 1, "x", 8, 256); /* error against n */
  covers("replot_cwp.svg", 1, "y", 3.407e-8, 7.433e-4);
  covers("replot_cwp.svg", 2, "x", 0.01053, 279.4); /* against CPU time */
  covers("replot_cwp.svg", 2, "y", 3.407e-8, 7.433e-4);
  covers("replot_cwp.svg", 3, "y", 9.2, 3108.5); /* peak memory */
  /* umfpack's n = 256 failed: said in the note */
  svg_xpath("replot_cwp.svg", "string(//*[contains(text(), 'Not plotted')])", out, sizeof out);
  CHECK_MSG(strstr(out, "umfpack, n = 256 failed") != NULL, "note: %s", out);

  snprintf(cmd, sizeof cmd, "%s --replot %s/bench/results/cavity_vs_freefem.csv --svg replot_cvf.svg", cvf, src);
  CHECK(run(cmd) == 0);
  CHECK(run("xmllint --noout replot_cvf.svg") == 0);
  static const char *const orders[4] = {"order 2.91", "order 2.62", "order 2.90", "order 2.17"};
  for (int k = 0; k < 4; ++k) {
    char e[96];
    snprintf(e, sizeof e, "string((//*[@class='slope'])[%d])", k + 1);
    svg_xpath("replot_cvf.svg", e, out, sizeof out);
    CHECK_MSG(!strcmp(out, orders[k]), "slope %d: %s, expected %s", k + 1, out, orders[k]);
  }
  CHECK(svg_xpath_number("replot_cvf.svg", "count(//*[@class='slope'])") == 4.0);
  covers("replot_cvf.svg", 1, "y", 5.4471e-07, 4.3460e-03); /* max-norm against n */
  covers("replot_cvf.svg", 2, "x", 0.01058, 43.79);         /* against CPU time */
  covers("replot_cvf.svg", 3, "y", 2.207e-08, 7.433e-04);   /* |min u - u*| */
  covers("replot_cvf.svg", 4, "y", 1.5417e-07, 1.4704e-03); /* L2 against n */
  covers("replot_cvf.svg", 6, "x", 659, 148739);            /* memory against unknowns */

  /* a row the program did not write: file:line, exit 2 */
  FILE *f = fopen("replot_bad.csv", "w");
  CHECK(f != NULL);
  if (f) {
    fputs(
        "# reference min u* = -0.2: given\nsolver,n,unknowns,umin,error,cpu_s,wall_s,assembly_s,symbolic_s,numeric_s,"
        "solve_s,peak_rss_mb,tr_step_s,tr_step_assembly_s\nklu,eight,659,-0.2,0,1,1,1,1,1,1,1,,\n",
        f);
    fclose(f);
  }
  snprintf(cmd, sizeof cmd, "%s --replot replot_bad.csv --svg replot_bad.svg 2>replot_bad.err", cwp);
  CHECK(run(cmd) == 2);
  f = fopen("replot_bad.err", "r");
  out[0] = '\0';
  if (f) {
    if (!fgets(out, sizeof out, f)) out[0] = '\0';
    fclose(f);
  }
  CHECK_MSG(!strncmp(out, "replot_bad.csv:3: ", 18), "message: %s", out);
  snprintf(cmd, sizeof cmd, "%s --replot replot_bad.csv --svg replot_bad.svg 2>replot_bad.err", cvf);
  CHECK(run(cmd) == 2); /* not its columns either */
  return sl_test_summary();
}
