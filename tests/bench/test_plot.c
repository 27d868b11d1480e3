/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The plots (core/study/chart.c) read back from the files: the SVG parsed by
 * xmllint (libxml2) for the axis ranges, the tick labels and the reference
 * slope's label of data sets whose values are known in closed form; the PNG
 * decompressed by zlib for its size, chunk CRCs and pixels, a marker's
 * pixel found where the SVG of the same chart places it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "core/study/chart.h"
#include "core/study/label.h"
#include "testing.h"

/* xmllint's answer to an XPath string expression, or "" */
static void xpath(const char *file, const char *expr, char *out, size_t n) {
  char cmd[1024];
  snprintf(cmd, sizeof cmd, "xmllint --xpath \"%s\" %s 2>/dev/null", expr, file);
  out[0] = '\0';
  FILE *p = popen(cmd, "r");
  if (!p) return;
  size_t got = fread(out, 1, n - 1, p);
  out[got] = '\0';
  pclose(p);
  while (got > 0 && (out[got - 1] == '\n' || out[got - 1] == ' ')) out[--got] = '\0';
}

static double xpath_number(const char *file, const char *expr) {
  char buf[256];
  xpath(file, expr, buf, sizeof buf);
  char *end;
  double v = strtod(buf, &end);
  return end == buf ? NAN : v;
}

/* The tick labels of axis ("x" or "y") of the first panel, joined by '|'. */
static void tick_labels(const char *file, const char *axis, char *out, size_t n) {
  out[0] = '\0';
  for (int k = 1; k < 40; ++k) {
    char expr[256], buf[128];
    snprintf(expr, sizeof expr, "string((//*[@data-axis='%s'])[1]/*[@class='tick'][%d])", axis, k);
    xpath(file, expr, buf, sizeof buf);
    if (!buf[0]) break;
    size_t used = strlen(out);
    snprintf(out + used, n - used, "%s%s", used ? "|" : "", buf);
  }
}

static int have_xmllint(void) { return system("xmllint --version >/dev/null 2>&1") == 0; }

/* log-log, 1 <= x <= 4, 1/32 <= y <= 1: 4 % of each log span added, so the
 * ends are 10^(-0.04 log10 4) and 4 x 10^(0.04 log10 4) on x; decades and
 * the 2 and 5 between labelled (every tick on an axis under 0.7 decade),
 * plain decimals inside 10^-2 .. 10^4. */
static void svg_log_axes(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {.name = "error", .n = 3, .x = x, .y = y};
  sl_chart c = {.title = "t", .xlabel = "cells", .ylabel = "error in \xCF\x86", .xscale = SL_AXIS_LOG,
                .yscale = SL_AXIS_LOG, .n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_log.svg", &c, 640, 480, &d) == 0);
  CHECK(system("xmllint --noout plot_log.svg") == 0); /* well-formed XML */
  double xlo = xpath_number("plot_log.svg", "string((//*[@data-axis='x'])[1]/@data-lo)");
  double xhi = xpath_number("plot_log.svg", "string((//*[@data-axis='x'])[1]/@data-hi)");
  double ylo = xpath_number("plot_log.svg", "string((//*[@data-axis='y'])[1]/@data-lo)");
  double yhi = xpath_number("plot_log.svg", "string((//*[@data-axis='y'])[1]/@data-hi)");
  double px = 0.04 * log10(4.0), py = 0.04 * log10(32.0);
  CHECK_MSG(fabs(xlo - pow(10.0, -px)) < 1e-8 && fabs(xhi - 4.0 * pow(10.0, px)) < 1e-8, "x axis %.10g .. %.10g", xlo, xhi);
  CHECK_MSG(fabs(ylo - pow(10.0, -py) / 32.0) < 1e-9 && fabs(yhi - pow(10.0, py)) < 1e-8, "y axis %.10g .. %.10g", ylo, yhi);
  char ticks[512];
  tick_labels("plot_log.svg", "x", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "1|2|3|4"), "x ticks %s", ticks); /* under 0.7 decade: every integer labelled */
  tick_labels("plot_log.svg", "y", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "0.05|0.1|0.2|0.5|1"), "y ticks %s", ticks);
  char text[256];
  xpath("plot_log.svg", "string(//*[@class='ylabel'])", text, sizeof text);
  CHECK_MSG(!strcmp(text, "error in \xCF\x86"), "y label %s", text); /* phi as the letter */
}

/* Decades outside 10^-2 .. 10^4 are powers of ten with a superscript (a
 * tspan) and the minus sign U+2212. */
static void svg_powers(void) {
  const double x[2] = {1e-6, 1e-3}, y[2] = {1e-6, 1e-3};
  sl_chart_series s = {.n = 2, .x = x, .y = y};
  sl_chart c = {.xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_pow.svg", &c, 640, 480, &d) == 0);
  char ticks[512];
  tick_labels("plot_pow.svg", "x", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "10\xE2\x88\x92" "6|10\xE2\x88\x92" "5|10\xE2\x88\x92" "4|10\xE2\x88\x92" "3"), "x ticks %s", ticks);
  char n[64];
  xpath("plot_pow.svg", "count((//*[@data-axis='x'])[1]/*[@class='tick']/*[local-name()='tspan'])", n, sizeof n);
  CHECK_MSG(!strcmp(n, "4"), "%s superscripts", n);
}

/* Linear: 0 <= x <= 10 and -1 <= y <= 3, 4 % added: steps of 2 and 1. */
static void svg_linear(void) {
  const double x[2] = {0, 10}, y[2] = {-1, 3};
  sl_chart_series s = {.n = 2, .x = x, .y = y};
  sl_chart c = {.n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_lin.svg", &c, 640, 480, &d) == 0);
  double xlo = xpath_number("plot_lin.svg", "string((//*[@data-axis='x'])[1]/@data-lo)");
  double yhi = xpath_number("plot_lin.svg", "string((//*[@data-axis='y'])[1]/@data-hi)");
  CHECK_MSG(fabs(xlo + 0.4) < 1e-12 && fabs(yhi - 3.16) < 1e-12, "x from %.10g, y to %.10g", xlo, yhi);
  char ticks[512];
  tick_labels("plot_lin.svg", "x", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "0|2|4|6|8|10"), "x ticks %s", ticks);
  tick_labels("plot_lin.svg", "y", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "\xE2\x88\x92" "1|0|1|2|3"), "y ticks %s", ticks);
}

/* The slope through (1, 1), (2, 1/4), (4, 1/32): log2 y = 0, -2, -5 at log2 x
 * = 0, 1, 2; least squares: sum (x - 1)(y + 7/3) / sum (x - 1)^2 = -5 / 2. */
static void svg_slope(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {.name = "error", .n = 3, .x = x, .y = y, .slope_points = 3, .slope_format = "order %.2f",
                       .slope_negate = 1};
  double slope = 0;
  CHECK(sl_chart_slope(&s, 3, &slope) == 0 && fabs(slope + 2.5) < 1e-12);
  CHECK(sl_chart_slope(&s, 2, &slope) == 0 && fabs(slope + 3.0) < 1e-12); /* the last two: log2(1/8) */
  sl_chart c = {.xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_slope.svg", &c, 640, 480, &d) == 0);
  char text[128];
  xpath("plot_slope.svg", "string(//*[@class='slope'])", text, sizeof text);
  CHECK_MSG(!strcmp(text, "order 2.50"), "slope label %s", text);
  /* the triangle lies below the data: every corner under the fitted line */
  double ylo = xpath_number("plot_slope.svg", "string((//*[@data-axis='y'])[1]/@data-lo)");
  CHECK_MSG(ylo < 1.0 / 32, "the axis (from %g) leaves room for the triangle", ylo);
}

/* Labels in words: a vector component with its unit, numbers as powers. */
static void labels(void) {
  char buf[256];
  sl_plot_quantity("velocity", 2, buf, sizeof buf);
  CHECK_MSG(!strcmp(buf, "velocity u_{z} (m/s)"), "%s", buf);
  sl_plot_quantity("phi", 0, buf, sizeof buf);
  CHECK_MSG(!strcmp(buf, "solids volume fraction \xCF\x86"), "%s", buf);
  sl_plot_pretty("eps = 1e-4, phi0 = 0.1, 2.5e+03 cells, file_1e-4.ini", buf, sizeof buf);
  CHECK_MSG(!strcmp(buf, "\xCE\xB5 = 10^{-4}, \xCF\x86_{0} = 0.1, 2.5\xC3\x97" "10^{3} cells, file_1e-4.ini"), "%s", buf);
}

static uint32_t be32(const unsigned char *p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }

/* The PNG of the chart: chunks and CRCs walked here, the image data inflated
 * by zlib, pixels checked against the SVG's marker position. */
static void png(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {.name = "error", .n = 3, .x = x, .y = y, .marker = SL_CHART_MARK_SQUARE};
  sl_chart c = {.title = "T", .xlabel = "x", .ylabel = "y", .xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 1,
                .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_png("plot.png", &c, 400, 300, &d) == 0);
  CHECK(sl_chart_write_svg("plot_same.svg", &c, 400, 300, &d) == 0);
  FILE *f = fopen("plot.png", "rb");
  CHECK(f != NULL);
  if (!f) return;
  static unsigned char file[1 << 20];
  size_t len = fread(file, 1, sizeof file, f);
  fclose(f);
  CHECK(len > 8 && len < sizeof file && !memcmp(file, "\x89PNG\r\n\x1a\n", 8));
  unsigned char *z = malloc(len);
  size_t zn = 0, at = 8;
  int w = 0, h = 0, chunks = 0, crc_ok = 1;
  while (at + 12 <= len) {
    uint32_t n = be32(file + at);
    if (n > len - at - 12) break;
    crc_ok &= (uint32_t)crc32(0, file + at + 4, n + 4) == be32(file + at + 8 + n);
    if (!memcmp(file + at + 4, "IHDR", 4)) w = (int)be32(file + at + 8), h = (int)be32(file + at + 12);
    if (!memcmp(file + at + 4, "IDAT", 4)) memcpy(z + zn, file + at + 8, n), zn += n;
    ++chunks, at += 12 + n;
  }
  CHECK_MSG(at == len && crc_ok && chunks >= 3, "chunks %d, CRCs %s", chunks, crc_ok ? "good" : "bad");
  CHECK_MSG(w == 400 && h == 300, "%d x %d", w, h);
  uLongf raw_n = (uLongf)(3 * 400 + 1) * 300;
  unsigned char *raw = malloc(raw_n);
  CHECK(uncompress(raw, &raw_n, z, (uLong)zn) == Z_OK && raw_n == (uLongf)(3 * 400 + 1) * 300);
  printf("plot.png: %zu bytes for %lu bytes of rows\n", len, (unsigned long)raw_n);
  /* the pixel at the middle point's marker (from the SVG: same layout) is the series colour */
  double cx = xpath_number("plot_same.svg", "string((//*[local-name()='rect'][@width='6.46'])[2]/@x)") + 3.23;
  double cy = xpath_number("plot_same.svg", "string((//*[local-name()='rect'][@width='6.46'])[2]/@y)") + 3.23;
  CHECK_MSG(isfinite(cx) && isfinite(cy), "no marker in the SVG");
  if (isfinite(cx) && isfinite(cy)) {
    int X = (int)floor(cx), Y = (int)floor(cy);
    const unsigned char *q = raw + (size_t)Y * (3 * 400 + 1) + 1 + 3 * (size_t)X;
    uint32_t col = (uint32_t)q[0] << 16 | (uint32_t)q[1] << 8 | q[2];
    CHECK_MSG(col == sl_chart_colour(0), "pixel (%d, %d) is %06X", X, Y, (unsigned)col);
  }
  /* white corner; anti-aliased edges: blends of the series colour and white */
  CHECK(raw[0] == 0 && raw[1] == 255 && raw[2] == 255 && raw[3] == 255);
  int blends = 0;
  uint32_t c0 = sl_chart_colour(0);
  for (int yy = 0; yy < 300; ++yy)
    for (int xx = 0; xx < 400; ++xx) {
      const unsigned char *q = raw + (size_t)yy * (3 * 400 + 1) + 1 + 3 * (size_t)xx;
      int r = q[0], g = q[1], b = q[2];
      /* strictly between the series colour and white on every channel */
      blends += r > (int)(c0 >> 16) && r < 255 && g > (int)(c0 >> 8 & 0xFF) && g < 255 && b > (int)(c0 & 0xFF) && b < 255;
    }
  CHECK_MSG(blends > 50, "%d anti-aliased pixels", blends);
  free(raw), free(z);
}

int main(void) {
  labels();
  if (!have_xmllint()) {
    printf("SKIP: xmllint not found (Debian libxml2-utils)\n");
    return sl_test_summary();
  }
  svg_log_axes();
  svg_powers();
  svg_linear();
  svg_slope();
  png();
  return sl_test_summary();
}
