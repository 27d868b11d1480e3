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
#include "svg_query.h"
#include "testing.h"

/* The tick labels of axis ("x" or "y") of the first panel, joined by '|'. */
static void tick_labels(const char *file, const char *axis, char *out, size_t n) {
  out[0] = '\0';
  for (int k = 1; k < 40; ++k) {
    char expr[256], buf[128];
    snprintf(expr, sizeof expr, "string((//*[@data-axis='%s'])[1]/*[@class='tick'][%d])", axis, k);
    svg_xpath(file, expr, buf, sizeof buf);
    if (!buf[0]) break;
    size_t used = strlen(out);
    snprintf(out + used, n - used, "%s%s", used ? "|" : "", buf);
  }
}

/* log-log, 1 <= x <= 4, 1/32 <= y <= 1: 4 % of each log span added, so the
 * ends are 10^(-0.04 log10 4) and 4 x 10^(0.04 log10 4) on x; decades and
 * the 2 and 5 between labelled (every tick on an axis under 0.7 decade),
 * plain decimals inside 10^-2 .. 10^4. */
static void svg_log_axes(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {.name = "error", .n = 3, .x = x, .y = y};
  sl_chart c = {.title = "t",
                .xlabel = "cells",
                .ylabel = "error in \xCF\x86",
                .xscale = SL_AXIS_LOG,
                .yscale = SL_AXIS_LOG,
                .n_series = 1,
                .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_log.svg", &c, 640, 480, &d) == 0);
  CHECK(system("xmllint --noout plot_log.svg") == 0); /* well-formed XML */
  double xlo = svg_xpath_number("plot_log.svg", "string((//*[@data-axis='x'])[1]/@data-lo)");
  double xhi = svg_xpath_number("plot_log.svg", "string((//*[@data-axis='x'])[1]/@data-hi)");
  double ylo = svg_xpath_number("plot_log.svg", "string((//*[@data-axis='y'])[1]/@data-lo)");
  double yhi = svg_xpath_number("plot_log.svg", "string((//*[@data-axis='y'])[1]/@data-hi)");
  double px = 0.04 * log10(4.0), py = 0.04 * log10(32.0);
  CHECK_MSG(fabs(xlo - pow(10.0, -px)) < 1e-8 && fabs(xhi - 4.0 * pow(10.0, px)) < 1e-8, "x axis %.10g .. %.10g", xlo,
            xhi);
  CHECK_MSG(fabs(ylo - pow(10.0, -py) / 32.0) < 1e-9 && fabs(yhi - pow(10.0, py)) < 1e-8, "y axis %.10g .. %.10g", ylo,
            yhi);
  char ticks[512];
  tick_labels("plot_log.svg", "x", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "1|2|3|4"), "x ticks %s", ticks); /* under 0.7 decade: every integer labelled */
  tick_labels("plot_log.svg", "y", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "0.05|0.1|0.2|0.5|1"), "y ticks %s", ticks);
  char text[256];
  svg_xpath("plot_log.svg", "string(//*[@class='ylabel'])", text, sizeof text);
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
  CHECK_MSG(!strcmp(ticks,
                    "10\xE2\x88\x92"
                    "6|10\xE2\x88\x92"
                    "5|10\xE2\x88\x92"
                    "4|10\xE2\x88\x92"
                    "3"),
            "x ticks %s", ticks);
  char n[64];
  svg_xpath("plot_pow.svg", "count((//*[@data-axis='x'])[1]/*[@class='tick']/*[local-name()='tspan'])", n, sizeof n);
  CHECK_MSG(!strcmp(n, "4"), "%s superscripts", n);
}

/* Linear: 0 <= x <= 10 and -1 <= y <= 3, 4 % added: steps of 2 and 1. */
static void svg_linear(void) {
  const double x[2] = {0, 10}, y[2] = {-1, 3};
  sl_chart_series s = {.n = 2, .x = x, .y = y};
  sl_chart c = {.n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_lin.svg", &c, 640, 480, &d) == 0);
  double xlo = svg_xpath_number("plot_lin.svg", "string((//*[@data-axis='x'])[1]/@data-lo)");
  double yhi = svg_xpath_number("plot_lin.svg", "string((//*[@data-axis='y'])[1]/@data-hi)");
  CHECK_MSG(fabs(xlo + 0.4) < 1e-12 && fabs(yhi - 3.16) < 1e-12, "x from %.10g, y to %.10g", xlo, yhi);
  char ticks[512];
  tick_labels("plot_lin.svg", "x", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks, "0|2|4|6|8|10"), "x ticks %s", ticks);
  tick_labels("plot_lin.svg", "y", ticks, sizeof ticks);
  CHECK_MSG(!strcmp(ticks,
                    "\xE2\x88\x92"
                    "1|0|1|2|3"),
            "y ticks %s", ticks);
}

/* The slope through (1, 1), (2, 1/4), (4, 1/32): log2 y = 0, -2, -5 at log2 x
 * = 0, 1, 2; least squares: sum (x - 1)(y + 7/3) / sum (x - 1)^2 = -5 / 2. */
static void svg_slope(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {
      .name = "error", .n = 3, .x = x, .y = y, .slope_points = 3, .slope_format = "order %.2f", .slope_negate = 1};
  double slope = 0;
  CHECK(sl_chart_slope(&s, 3, &slope) == 0 && fabs(slope + 2.5) < 1e-12);
  CHECK(sl_chart_slope(&s, 2, &slope) == 0 && fabs(slope + 3.0) < 1e-12); /* the last two: log2(1/8) */
  sl_chart c = {.xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 1, .series = &s};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_slope.svg", &c, 640, 480, &d) == 0);
  char text[128];
  svg_xpath("plot_slope.svg", "string(//*[@class='slope'])", text, sizeof text);
  CHECK_MSG(!strcmp(text, "order 2.50"), "slope label %s", text);
  /* the triangle lies below the data: every corner under the fitted line */
  double ylo = svg_xpath_number("plot_slope.svg", "string((//*[@data-axis='y'])[1]/@data-lo)");
  CHECK_MSG(ylo < 1.0 / 32, "the axis (from %g) leaves room for the triangle", ylo);
}

/* Text kept inside the frame: the label of a point at the right end of the
 * x axis is set to its left (anchored at its end), the others to the right;
 * the slope labels of two curves whose triangles nearly coincide, y = x^-2.5
 * and y = 0.95 x^-2.4 over 1..4 (orders 2.50 and 2.40: least squares of
 * exact powers), are stacked a line apart, not drawn over each other. */
static void svg_text_in_frame(void) {
  const double x[3] = {1, 2, 4}, ya[3] = {1, pow(2, -2.5), pow(4, -2.5)};
  const double yb[3] = {0.95, 0.95 * pow(2, -2.4), 0.95 * pow(4, -2.4)};
  const char *const lab[3] = {"n=1", "n=2", "n=4"};
  sl_chart_series s[2] = {
      {.name = "a",
       .n = 3,
       .x = x,
       .y = ya,
       .labels = lab,
       .slope_points = 3,
       .slope_format = "order %.2f",
       .slope_negate = 1},
      {.name = "b", .n = 3, .x = x, .y = yb, .slope_points = 3, .slope_format = "order %.2f", .slope_negate = 1}};
  sl_chart c = {.xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 2, .series = s, .legend = SL_LEGEND_NONE};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_frame.svg", &c, 480, 360, &d) == 0);
  char a1[32], a3[32], t1[32], t2[32];
  svg_xpath("plot_frame.svg", "string((//*[@class='point'])[1]/@text-anchor)", a1, sizeof a1);
  svg_xpath("plot_frame.svg", "string((//*[@class='point'])[3]/@text-anchor)", a3, sizeof a3);
  CHECK_MSG(!strcmp(a1, "start") && !strcmp(a3, "end"), "point labels anchored %s .. %s", a1, a3);
  svg_xpath("plot_frame.svg", "string((//*[@class='slope'])[1])", t1, sizeof t1);
  svg_xpath("plot_frame.svg", "string((//*[@class='slope'])[2])", t2, sizeof t2);
  CHECK_MSG(!strcmp(t1, "order 2.50") && !strcmp(t2, "order 2.40"), "slope labels %s, %s", t1, t2);
  double y1 = svg_xpath_number("plot_frame.svg", "string((//*[@class='slope'])[1]/@y)");
  double y2 = svg_xpath_number("plot_frame.svg", "string((//*[@class='slope'])[2]/@y)");
  double x1 = svg_xpath_number("plot_frame.svg", "string((//*[@class='slope'])[1]/@x)");
  double x2 = svg_xpath_number("plot_frame.svg", "string((//*[@class='slope'])[2]/@x)");
  CHECK_MSG(fabs(y1 - y2) >= 12.0 || fabs(x1 - x2) >= 60.0, "slope labels at (%g, %g) and (%g, %g) overlap", x1, y1, x2,
            y2);
}

/* A heat map: the colour scale at its stops and half-way between two (linear
 * in each channel, rounded), the axes on the cells' edges exactly, the colour
 * bar over lo..hi, and a cell's middle pixel in the raster its value's colour. */
static void svg_heatmap(void) {
  CHECK(sl_chart_heat_colour(0.0) == 0xFFFFFF && sl_chart_heat_colour(-1.0) == 0xFFFFFF);
  CHECK(sl_chart_heat_colour(0.25) == 0xFFE678 && sl_chart_heat_colour(0.5) == 0xFA9628);
  CHECK(sl_chart_heat_colour(1.0) == 0x6E0014 && sl_chart_heat_colour(2.0) == 0x6E0014);
  CHECK_MSG(sl_chart_heat_colour(0.125) == 0xFFF3BC, "%06X",
            (unsigned)sl_chart_heat_colour(0.125));                            /* (255, 242.5, 187.5) */
  const double xe[3] = {0, 1, 2}, ye[3] = {0, 0.5, 1}, v[4] = {0, 5, 7.5, 10}; /* row j = 0, then j = 1 */
  sl_chart_heatmap hm = {
      .nx = 2, .ny = 2, .x_edges = xe, .y_edges = ye, .values = v, .lo = 0, .hi = 10, .label = "value"};
  sl_chart c = {.xlabel = "x (m)", .ylabel = "y (m)", .legend = SL_LEGEND_NONE, .heatmap = &hm};
  sl_diag d = {{0}};
  CHECK(sl_chart_write_svg("plot_heat.svg", &c, 400, 300, &d) == 0);
  const char *f = "plot_heat.svg";
  CHECK(svg_xpath_number(f, "string((//*[@data-axis='x'])[1]/@data-lo)") == 0.0);
  CHECK(svg_xpath_number(f, "string((//*[@data-axis='x'])[1]/@data-hi)") == 2.0);
  CHECK(svg_xpath_number(f, "string((//*[@data-axis='y'])[1]/@data-hi)") == 1.0);
  CHECK(svg_xpath_number(f, "string(//*[@class='colourbar']/@data-lo)") == 0.0);
  CHECK(svg_xpath_number(f, "string(//*[@class='colourbar']/@data-hi)") == 10.0);
  /* the cells follow the clip path's rect: cell (1, 1), value 10, is the fifth */
  double x = svg_xpath_number(f, "string((//*[@class='heatmap']//*[local-name()='rect'])[5]/@x)");
  double y = svg_xpath_number(f, "string((//*[@class='heatmap']//*[local-name()='rect'])[5]/@y)");
  double w = svg_xpath_number(f, "string((//*[@class='heatmap']//*[local-name()='rect'])[5]/@width)");
  double h = svg_xpath_number(f, "string((//*[@class='heatmap']//*[local-name()='rect'])[5]/@height)");
  char fill[16];
  svg_xpath(f, "string((//*[@class='heatmap']//*[local-name()='rect'])[5]/@fill)", fill, sizeof fill);
  CHECK_MSG(!strcmp(fill, "#6E0014"), "cell (1, 1) filled %s", fill);
  sl_image im = {0};
  CHECK(sl_chart_draw(&c, 400, 300, &im, &d) == 0);
  if (im.rgb && isfinite(x + y + w + h)) {
    int X = (int)floor(x + 0.5 * w), Y = (int)floor(y + 0.5 * h);
    const unsigned char *q = im.rgb + 3 * ((size_t)Y * (size_t)im.w + (size_t)X);
    uint32_t col = (uint32_t)q[0] << 16 | (uint32_t)q[1] << 8 | q[2];
    CHECK_MSG(col == 0x6E0014, "pixel (%d, %d) is %06X", X, Y, (unsigned)col);
  }
  sl_image_free(&im);
}

/* Labels in words: a vector component with its unit, numbers as powers. */
static void labels(void) {
  char buf[256];
  sl_plot_quantity("velocity", 2, buf, sizeof buf);
  CHECK_MSG(!strcmp(buf, "velocity u_{z} (m/s)"), "%s", buf);
  sl_plot_quantity("phi", 0, buf, sizeof buf);
  CHECK_MSG(!strcmp(buf, "solids volume fraction \xCF\x86"), "%s", buf);
  sl_plot_pretty("eps = 1e-4, phi0 = 0.1, 2.5e+03 cells, file_1e-4.ini", buf, sizeof buf);
  CHECK_MSG(!strcmp(buf,
                    "\xCE\xB5 = 10^{-4}, \xCF\x86_{0} = 0.1, 2.5\xC3\x97"
                    "10^{3} cells, file_1e-4.ini"),
            "%s", buf);
}

static uint32_t be32(const unsigned char *p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The PNG of the chart: chunks and CRCs walked here, the image data inflated
 * by zlib, pixels checked against the SVG's marker position. */
static void png(void) {
  const double x[3] = {1, 2, 4}, y[3] = {1, 0.25, 1.0 / 32};
  sl_chart_series s = {.name = "error", .n = 3, .x = x, .y = y, .marker = SL_CHART_MARK_SQUARE};
  sl_chart c = {.title = "T",
                .xlabel = "x",
                .ylabel = "y",
                .xscale = SL_AXIS_LOG,
                .yscale = SL_AXIS_LOG,
                .n_series = 1,
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
  double cx = svg_xpath_number("plot_same.svg", "string((//*[local-name()='rect'][@width='6.46'])[2]/@x)") + 3.23;
  double cy = svg_xpath_number("plot_same.svg", "string((//*[local-name()='rect'][@width='6.46'])[2]/@y)") + 3.23;
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
      blends +=
          r > (int)(c0 >> 16) && r < 255 && g > (int)(c0 >> 8 & 0xFF) && g < 255 && b > (int)(c0 & 0xFF) && b < 255;
    }
  CHECK_MSG(blends > 50, "%d anti-aliased pixels", blends);
  free(raw), free(z);
}

int main(void) {
  labels();
  if (!svg_have_xmllint()) {
    printf("SKIP: xmllint not found (Debian libxml2-utils)\n");
    return sl_test_summary();
  }
  svg_log_axes();
  svg_powers();
  svg_linear();
  svg_slope();
  svg_text_in_frame();
  svg_heatmap();
  png();
  return sl_test_summary();
}
