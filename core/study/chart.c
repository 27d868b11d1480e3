/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Line charts as SVG or PNG through one layout (see chart.h). Everything is
 * placed in output pixels on a canvas that is either an SVG file or an
 * image SS times the size, averaged down to the output at the end (a box
 * filter: the raster's anti-aliasing). */
#include "core/study/chart.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/study/font.h"
#include "core/study/png.h"

enum { MAX_TICKS = 96, MAX_RUNS = 32, SS = 3 };

/* text sizes in pixels (the font's em) */
static const double TITLE = 17, SUB = 12, LABEL = 14, TICKS = 13, SMALL = 11, HEAD = 14;
static const uint32_t INK = 0x202020, GRID = 0xE2E2E2, MINOR_GRID = 0xF1F1F1, FRAME = 0x505050, WHITE = 0xFFFFFF,
                      NOTE = 0x606060;

uint32_t sl_chart_colour(int k) {
  static const uint32_t palette[] = {0x1F77B4, 0xD62728, 0x2CA02C, 0xFF7F0E, 0x9467BD,
                                     0x8C564B, 0xE377C2, 0x7F7F7F, 0xBCBD22, 0x17BECF};
  return palette[(k < 0 ? -k : k) % (int)(sizeof palette / sizeof palette[0])];
}

static uint32_t series_colour(const sl_chart_series *s, int k) {
  const char *c = s->colour;
  if (c && c[0] == '#' && strlen(c) == 7) {
    char *end;
    unsigned long v = strtoul(c + 1, &end, 16);
    if (*end == '\0') return (uint32_t)v;
  }
  return sl_chart_colour(k);
}

static sl_chart_marker series_marker(const sl_chart_series *s, int k) {
  return s->marker != SL_CHART_MARK_AUTO ? s->marker : (sl_chart_marker)(SL_CHART_MARK_CIRCLE + k % 5);
}

/* ---- marked-up text ------------------------------------------------------- */

typedef struct run {
  const char *s;
  size_t n;
  int level; /* 0, +1 superscript, -1 subscript */
} run;

/* Splits text at "^{", "_{" and the closing '}'. */
static int runs_of(const char *text, run *r) {
  int n = 0;
  const char *p = text ? text : "";
  while (*p && n < MAX_RUNS) {
    if ((p[0] == '^' || p[0] == '_') && p[1] == '{') {
      const char *close = strchr(p + 2, '}');
      if (close) {
        r[n++] = (run){p + 2, (size_t)(close - p - 2), p[0] == '^' ? 1 : -1};
        p = close + 1;
        continue;
      }
    }
    const char *q = p + 1;
    while (*q && !((q[0] == '^' || q[0] == '_') && q[1] == '{')) ++q;
    r[n++] = (run){p, (size_t)(q - p), 0};
    p = q;
  }
  return n;
}

static double run_size(const run *r, double size) { return r->level ? 0.7 * size : size; }
static double run_shift(const run *r, double size) {
  return r->level > 0 ? -0.42 * size : r->level < 0 ? 0.22 * size : 0.0;
}

/* The advance of one character in em: the bitmap font's 0.6 for all, or a
 * sans-serif face's (DejaVu Sans, Helvetica) by class of character. */
static double advance(unsigned char c, int proportional) {
  if (!proportional) return 0.6;
  if (c == ' ' || c == '.' || c == ',' || c == ':' || c == ';' || c == 'i' || c == 'l' || c == 'j' || c == '(' ||
      c == ')' || c == '|' || c == '\'' || c == 'f' || c == 't' || c == 'r')
    return 0.34;
  if ((c >= 'A' && c <= 'Z') || c == 'm' || c == 'w' || c == '%') return 0.78;
  return 0.62;
}

/* The width of text at a size: proportional 0 gives the bitmap font's
 * (where the PNG's glyphs go), 1 the room it takes in either file (the
 * larger of the font's and a sans-serif face's), for boxes and wrapping. */
static double text_width_of(const char *text, double size, int proportional) {
  run r[MAX_RUNS];
  int n = runs_of(text, r);
  double w = 0.0;
  for (int i = 0; i < n; ++i)
    for (size_t k = 0; k < r[i].n; ++k) {
      unsigned char c = (unsigned char)r[i].s[k];
      if ((c & 0xC0) == 0x80) continue; /* UTF-8 continuation */
      double a = c >= 0x80 ? 0.62 : advance(c, proportional);
      w += (proportional ? fmax(0.6, a) : a) * run_size(&r[i], size);
    }
  return w;
}

static double text_width(const char *text, double size) { return text_width_of(text, size, 1); }

/* ---- the canvas: SVG or a supersampled image ------------------------------ */

typedef struct canvas {
  FILE *f;      /* SVG, or NULL */
  sl_image *im; /* SS times the output */
  int clip, clip_id;
  double cx0, cy0, cx1, cy1;
} canvas;

static void svg_hex(FILE *f, uint32_t c) { fprintf(f, "#%06X", (unsigned)(c & 0xFFFFFFu)); }

static void svg_escaped(FILE *f, const char *s, size_t n, int minus) {
  for (size_t i = 0; i < n; ++i) switch (s[i]) {
      case '<':
        fputs("&lt;", f);
        break;
      case '>':
        fputs("&gt;", f);
        break;
      case '&':
        fputs("&amp;", f);
        break;
      case '"':
        fputs("&quot;", f);
        break;
      case '-':
        if (minus) {
          fputs("\xE2\x88\x92", f);
          break;
        }
        /* fall through */
      default:
        fputc(s[i], f);
    }
}

static int round_px(double v) { return (int)lround(v * SS); }

/* Liang-Barsky: the part of the segment inside the clip rectangle; 0 when none. */
static int clip_segment(const canvas *cv, double *x0, double *y0, double *x1, double *y1) {
  if (!cv->clip) return 1;
  double t0 = 0.0, t1 = 1.0, dx = *x1 - *x0, dy = *y1 - *y0;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {*x0 - cv->cx0, cv->cx1 - *x0, *y0 - cv->cy0, cv->cy1 - *y0};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return 0;
      continue;
    }
    double r = q[i] / p[i];
    if (p[i] < 0.0) t0 = fmax(t0, r);
    else t1 = fmin(t1, r);
    if (t0 > t1) return 0;
  }
  double ax = *x0 + t0 * dx, ay = *y0 + t0 * dy, bx = *x0 + t1 * dx, by = *y0 + t1 * dy;
  *x0 = ax, *y0 = ay, *x1 = bx, *y1 = by;
  return 1;
}

static void cv_line(canvas *cv, double x0, double y0, double x1, double y1, double width, uint32_t col, int dashed) {
  if (cv->f) {
    fprintf(cv->f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"", x0, y0, x1, y1);
    svg_hex(cv->f, col);
    fprintf(cv->f, "\" stroke-width=\"%.2g\"%s/>\n", width, dashed ? " stroke-dasharray=\"6,4\"" : "");
    return;
  }
  if (!clip_segment(cv, &x0, &y0, &x1, &y1)) return;
  int w = (int)lround(width * SS);
  sl_image_line(cv->im, x0 * SS, y0 * SS, x1 * SS, y1 * SS, w < 1 ? 1 : w, col, dashed ? 5 * SS : 0);
}

static void cv_polyline(canvas *cv, int n, const double *x, const double *y, double width, uint32_t col, int dashed) {
  if (n < 2) return;
  if (cv->f) {
    fputs("<polyline fill=\"none\" stroke-linejoin=\"round\" stroke=\"", cv->f);
    svg_hex(cv->f, col);
    fprintf(cv->f, "\" stroke-width=\"%.2g\"%s points=\"", width, dashed ? " stroke-dasharray=\"7,4\"" : "");
    for (int i = 0; i < n; ++i) fprintf(cv->f, "%s%.2f,%.2f", i ? " " : "", x[i], y[i]);
    fputs("\"/>\n", cv->f);
    return;
  }
  for (int i = 1; i < n; ++i) cv_line(cv, x[i - 1], y[i - 1], x[i], y[i], width, col, dashed);
}

/* fill or stroke < 0: none */
static void cv_rect(canvas *cv, double x0, double y0, double x1, double y1, long fill, long stroke) {
  if (cv->f) {
    fprintf(cv->f, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"", x0, y0, x1 - x0, y1 - y0);
    if (fill >= 0) svg_hex(cv->f, (uint32_t)fill);
    else fputs("none", cv->f);
    if (stroke >= 0)
      fputs("\" stroke=\"", cv->f), svg_hex(cv->f, (uint32_t)stroke), fputs("\" stroke-width=\"1", cv->f);
    fputs("\"/>\n", cv->f);
    return;
  }
  if (fill >= 0) sl_image_fill(cv->im, round_px(x0), round_px(y0), round_px(x1) - 1, round_px(y1) - 1, (uint32_t)fill);
  if (stroke >= 0) {
    cv_line(cv, x0, y0, x1, y0, 1, (uint32_t)stroke, 0), cv_line(cv, x0, y1, x1, y1, 1, (uint32_t)stroke, 0);
    cv_line(cv, x0, y0, x0, y1, 1, (uint32_t)stroke, 0), cv_line(cv, x1, y0, x1, y1, 1, (uint32_t)stroke, 0);
  }
}

static void cv_marker(canvas *cv, double x, double y, sl_chart_marker m, double r, uint32_t col) {
  if (m == SL_CHART_MARK_NONE || m == SL_CHART_MARK_AUTO) return;
  if (cv->f) {
    FILE *f = cv->f;
    switch (m) {
      case SL_CHART_MARK_SQUARE:
        fprintf(f, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"", x - 0.85 * r, y - 0.85 * r, 1.7 * r,
                1.7 * r);
        break;
      case SL_CHART_MARK_TRIANGLE:
        fprintf(f, "<path d=\"M%.2f,%.2fL%.2f,%.2fL%.2f,%.2fZ\"", x, y - 1.2 * r, x + 1.05 * r, y + 0.65 * r,
                x - 1.05 * r, y + 0.65 * r);
        break;
      case SL_CHART_MARK_DIAMOND:
        fprintf(f, "<path d=\"M%.2f,%.2fL%.2f,%.2fL%.2f,%.2fL%.2f,%.2fZ\"", x, y - 1.2 * r, x + 1.2 * r, y, x,
                y + 1.2 * r, x - 1.2 * r, y);
        break;
      case SL_CHART_MARK_CROSS:
        fprintf(f, "<path d=\"M%.2f,%.2fL%.2f,%.2fM%.2f,%.2fL%.2f,%.2f\" fill=\"none\" stroke-width=\"1.6\" stroke=\"",
                x - r, y - r, x + r, y + r, x - r, y + r, x + r, y - r);
        svg_hex(f, col);
        fputs("\"/>\n", f);
        return;
      default:
        fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"", x, y, r);
    }
    fputs(" fill=\"", f), svg_hex(f, col), fputs("\"/>\n", f);
    return;
  }
  sl_image_marker(cv->im, x * SS, y * SS, (sl_marker)(m - SL_CHART_MARK_CIRCLE), (int)lround(r * SS), col);
}

typedef enum anchor { START, MIDDLE, END } anchor;

/* Text with its baseline at y; vertical: turned a quarter turn anticlockwise about (x, y). */
static void cv_text(canvas *cv, double x, double y, const char *text, double size, anchor a, int vertical, uint32_t col,
                    int bold, const char *cls) {
  if (!text || !*text) return;
  run r[MAX_RUNS];
  int n = runs_of(text, r);
  if (cv->f) {
    static const char *const anchors[] = {"start", "middle", "end"};
    FILE *f = cv->f;
    fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.3g\" text-anchor=\"%s\"", x, y, size, anchors[a]);
    if (bold) fputs(" font-weight=\"bold\"", f);
    if (col != INK) fputs(" fill=\"", f), svg_hex(f, col), fputc('"', f);
    if (cls) fprintf(f, " class=\"%s\"", cls);
    if (vertical) fprintf(f, " transform=\"rotate(-90 %.2f %.2f)\"", x, y);
    fputc('>', f);
    double shift = 0.0;
    for (int i = 0; i < n; ++i) {
      double target = run_shift(&r[i], size);
      if (target == shift && !r[i].level) svg_escaped(f, r[i].s, r[i].n, 0);
      else {
        fprintf(f, "<tspan dy=\"%.2f\"", target - shift);
        if (r[i].level) fprintf(f, " font-size=\"%.3g\"", run_size(&r[i], size));
        fputc('>', f);
        svg_escaped(f, r[i].s, r[i].n, r[i].level > 0);
        fputs("</tspan>", f);
        shift = target;
      }
    }
    fputs("</text>\n", f);
    return;
  }
  double w = text_width_of(text, size, 0), start = a == START ? 0.0 : a == MIDDLE ? -0.5 * w : -w;
  for (int pass = 0; pass <= (bold ? 1 : 0); ++pass) {
    double along = start;
    for (int i = 0; i < n; ++i) {
      double sz = run_size(&r[i], size), u = sz / 10.0 * SS, down = run_shift(&r[i], size) * SS;
      const char *p = r[i].s, *end = r[i].s + r[i].n;
      double at = along * SS;
      while (p < end) {
        uint32_t cp = sl_utf8_next(&p);
        if (cp == '-' && r[i].level > 0) cp = 0x2212;
        for (int row = 0; row < SL_FONT_H; ++row) {
          unsigned bits = sl_font_row_cp(cp, row);
          for (int c = 0; c < SL_FONT_W; ++c) {
            if (!(bits >> (SL_FONT_W - 1 - c) & 1u)) continue;
            double a0 = at + c * u + pass * 0.45 * u, a1 = a0 + u, b0 = down + (row - 7) * u, b1 = b0 + u;
            int X0, X1, Y0, Y1;
            if (vertical) {
              X0 = (int)lround(x * SS + b0), X1 = (int)lround(x * SS + b1) - 1;
              Y0 = (int)lround(y * SS - a1), Y1 = (int)lround(y * SS - a0) - 1;
            } else {
              X0 = (int)lround(x * SS + a0), X1 = (int)lround(x * SS + a1) - 1;
              Y0 = (int)lround(y * SS + b0), Y1 = (int)lround(y * SS + b1) - 1;
            }
            if (X1 < X0) X1 = X0;
            if (Y1 < Y0) Y1 = Y0;
            sl_image_fill(cv->im, X0, Y0, X1, Y1, col);
          }
        }
        at += 0.6 * sz * SS;
      }
      along = at / SS;
    }
  }
}

static void cv_clip_begin(canvas *cv, double x0, double y0, double x1, double y1) {
  cv->clip = 1, cv->cx0 = x0, cv->cy0 = y0, cv->cx1 = x1, cv->cy1 = y1;
  if (cv->f) {
    ++cv->clip_id;
    fprintf(cv->f, "<clipPath id=\"clip%d\"><rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"/></clipPath>\n",
            cv->clip_id, x0, y0, x1 - x0, y1 - y0);
    fprintf(cv->f, "<g clip-path=\"url(#clip%d)\">\n", cv->clip_id);
  }
}

static void cv_clip_end(canvas *cv) {
  cv->clip = 0;
  if (cv->f) fputs("</g>\n", cv->f);
}

/* ---- axes ----------------------------------------------------------------- */

typedef struct tick {
  double v; /* axis coordinate: the value, or its log10 */
  int major;
  char label[48];
} tick;

typedef struct axis {
  sl_axis_scale scale;
  double lo, hi; /* axis coordinates at the two ends */
  int n_ticks;
  tick ticks[MAX_TICKS];
} axis;

static int plottable(sl_axis_scale s, double v) { return isfinite(v) && (s == SL_AXIS_LINEAR || v > 0.0); }
static double coord(sl_axis_scale s, double v) { return s == SL_AXIS_LOG ? log10(v) : v; }

static void add_tick(axis *a, double v, int major, const char *label) {
  if (a->n_ticks == MAX_TICKS) return;
  tick *t = &a->ticks[a->n_ticks++];
  t->v = v, t->major = major;
  snprintf(t->label, sizeof t->label, "%s", label ? label : "");
}

/* A decimal number with the minus sign; very large or small ones as m x 10^e. */
static void number_label(char *buf, size_t n, double v, int decimals) {
  if (v != 0.0 && (fabs(v) >= 1e5 || fabs(v) < 1e-3)) {
    int e = (int)floor(log10(fabs(v)) + 1e-9);
    double m = v / pow(10.0, e);
    char mb[32];
    snprintf(mb, sizeof mb, "%.3g", fabs(m));
    if (!strcmp(mb, "1")) snprintf(buf, n, "%s10^{%d}", v < 0 ? "\xE2\x88\x92" : "", e);
    else
      snprintf(buf, n,
               "%s%s\xC3\x97"
               "10^{%d}",
               v < 0 ? "\xE2\x88\x92" : "", mb, e);
    return;
  }
  char b[40];
  snprintf(b, sizeof b, "%.*f", decimals, fabs(v));
  snprintf(buf, n, "%s%s", v < 0 ? "\xE2\x88\x92" : "", b);
}

/* m 10^e on a log axis: plain decimals when the axis lies within 10^-2 .. 10^4. */
static void decade_label(char *buf, size_t n, int m, int e, int plain) {
  if (plain) snprintf(buf, n, "%.*f", e < 0 ? -e : 0, m * pow(10.0, e));
  else if (m == 1) snprintf(buf, n, "10^{%d}", e);
  else
    snprintf(buf, n,
             "%d\xC3\x97"
             "10^{%d}",
             m, e);
}

static void linear_ticks(axis *a, double lo, double hi, int log_positions) {
  double raw = (hi - lo) / 6.0, p = pow(10.0, floor(log10(raw))), step = 10.0 * p;
  if (raw <= p) step = p;
  else if (raw <= 2.0 * p) step = 2.0 * p;
  else if (raw <= 5.0 * p) step = 5.0 * p;
  int decimals = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
  for (double k = ceil(lo / step - 1e-9); k * step <= hi * (1 + 1e-12) + 1e-12 * step && a->n_ticks < MAX_TICKS;
       k += 1.0) {
    double v = k * step;
    if (fabs(v) < 1e-9 * step) v = 0.0;
    if (log_positions && v <= 0.0) continue;
    char buf[48];
    number_label(buf, sizeof buf, v, decimals);
    add_tick(a, log_positions ? log10(v) : v, 1, buf);
  }
}

/* The axis over [lo, hi] (data values), 4 % of the span added each side. */
/* margin: the fraction of the span added at each end */
static void make_axis(axis *a, sl_axis_scale s, double lo, double hi, double margin) {
  memset(a, 0, sizeof *a);
  a->scale = s;
  if (s == SL_AXIS_LOG) {
    double L = log10(lo), H = log10(hi);
    if (!(H - L > 1e-9)) L -= 0.5, H += 0.5;
    double pad = margin * (H - L);
    a->lo = L - pad, a->hi = H + pad;
    int e0 = (int)ceil(a->lo - 1e-9), e1 = (int)floor(a->hi + 1e-9), decades = (int)ceil(a->hi) - (int)floor(a->lo);
    int plain = floor(a->lo) >= -2 && ceil(a->hi) <= 4;
    int majors = e1 - e0 + 1, every = majors > 8 ? (majors + 7) / 8 : 1;
    for (int e = (int)floor(a->lo); e <= (int)ceil(a->hi); ++e) {
      char buf[48];
      if (e >= e0 && e <= e1) {
        decade_label(buf, sizeof buf, 1, e, plain);
        add_tick(a, e, 1, (e - e0) % every == 0 ? buf : NULL);
      }
      if (decades > 6) continue;
      for (int m = 2; m <= 9; ++m) {
        double v = e + log10(m);
        if (v < a->lo || v > a->hi) continue;
        int label = majors <= 0 || a->hi - a->lo < 0.7 ||
                    (majors == 1 && decades <= 2 && (m == 2 || m == 3 || m == 5)) ||
                    (majors == 2 && a->hi - a->lo <= 2.5 && (m == 2 || m == 5));
        decade_label(buf, sizeof buf, m, e, plain);
        add_tick(a, v, 0, label ? buf : NULL);
      }
    }
    int labelled = 0;
    for (int k = 0; k < a->n_ticks; ++k) labelled += a->ticks[k].label[0] != '\0';
    if (labelled < 2) { /* less than a decade with few ticks: round numbers instead */
      a->n_ticks = 0;
      linear_ticks(a, pow(10.0, a->lo), pow(10.0, a->hi), 1);
    }
    return;
  }
  if (!(hi > lo)) {
    double pad = lo != 0.0 ? 0.1 * fabs(lo) : 1.0;
    lo -= pad, hi += pad;
  }
  double pad = margin * (hi - lo);
  a->lo = lo - pad, a->hi = hi + pad;
  linear_ticks(a, a->lo, a->hi, 0);
}

/* ---- reference slopes ----------------------------------------------------- */

int sl_chart_slope(const sl_chart_series *s, int points, double *slope) {
  int n = 0;
  for (int i = 0; i < s->n; ++i) n += plottable(SL_AXIS_LOG, s->x[i]) && plottable(SL_AXIS_LOG, s->y[i]);
  int first = points >= 2 && points < n ? n - points : 0, k = 0, m = 0;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < s->n; ++i) {
    if (!plottable(SL_AXIS_LOG, s->x[i]) || !plottable(SL_AXIS_LOG, s->y[i])) continue;
    if (k++ < first) continue;
    double X = log10(s->x[i]), Y = log10(s->y[i]);
    sx += X, sy += Y, sxx += X * X, sxy += X * Y, ++m;
  }
  if (m < 2) return -1;
  double den = m * sxx - sx * sx;
  if (!(fabs(den) > 1e-12 * (m * sxx + 1e-300))) return -1;
  *slope = (m * sxy - sx * sy) / den;
  return 0;
}

typedef struct triangle {
  int on;
  double x[3], y[3]; /* log10 coordinates: the two ends of the hypotenuse, the right angle */
  char label[64];
} triangle;

/* The triangle below the fitted line over the middle half of the points' span. */
static void make_triangle(const sl_chart_series *s, double yspan_decades, triangle *t) {
  memset(t, 0, sizeof *t);
  double slope;
  if (s->slope_points < 2 || sl_chart_slope(s, s->slope_points, &slope)) return;
  /* no triangle for a flat curve, nor for an order that is not one (an error growing with N) */
  if (fabs(slope) < 0.1 || (s->slope_negate && slope > 0.0)) return;
  int n = 0;
  for (int i = 0; i < s->n; ++i) n += plottable(SL_AXIS_LOG, s->x[i]) && plottable(SL_AXIS_LOG, s->y[i]);
  int first = s->slope_points < n ? n - s->slope_points : 0, k = 0;
  double xlo = INFINITY, xhi = -INFINITY, sy = 0, sx = 0;
  int m = 0;
  for (int i = 0; i < s->n; ++i) {
    if (!plottable(SL_AXIS_LOG, s->x[i]) || !plottable(SL_AXIS_LOG, s->y[i])) continue;
    if (k++ < first) continue;
    double X = log10(s->x[i]);
    xlo = fmin(xlo, X), xhi = fmax(xhi, X), sx += X, sy += log10(s->y[i]), ++m;
  }
  double b = sy / m - slope * sx / m, drop = 0.12 * fmax(yspan_decades, 0.5);
  double xa = xlo + 0.25 * (xhi - xlo), xb = xlo + 0.75 * (xhi - xlo);
  t->on = 1;
  t->x[0] = xa, t->y[0] = b + slope * xa - drop;
  t->x[1] = xb, t->y[1] = b + slope * xb - drop;
  if (slope < 0) t->x[2] = xa, t->y[2] = t->y[1];
  else t->x[2] = xb, t->y[2] = t->y[0];
  snprintf(t->label, sizeof t->label, s->slope_format ? s->slope_format : "slope %.2f",
           s->slope_negate ? -slope : slope);
}

/* ---- panels --------------------------------------------------------------- */

typedef struct panel {
  const sl_chart *c;
  double x0, y0, x1, y1; /* the plot area */
  axis ax, ay;
  int any;
  triangle *tri; /* one a series */
} panel;

static double px(const panel *p, double v) {
  return p->x0 + (coord(p->ax.scale, v) - p->ax.lo) / (p->ax.hi - p->ax.lo) * (p->x1 - p->x0);
}
static double py(const panel *p, double v) {
  return p->y1 - (coord(p->ay.scale, v) - p->ay.lo) / (p->ay.hi - p->ay.lo) * (p->y1 - p->y0);
}
static double pxc(const panel *p, double c) { return p->x0 + (c - p->ax.lo) / (p->ax.hi - p->ax.lo) * (p->x1 - p->x0); }
static double pyc(const panel *p, double c) { return p->y1 - (c - p->ay.lo) / (p->ay.hi - p->ay.lo) * (p->y1 - p->y0); }

static int point_ok(const sl_chart *c, double x, double y) {
  return plottable(c->xscale, x) && plottable(c->yscale, y);
}

/* Axes over the data, the spans asked for and the reference triangles. */
static int fit_axes(panel *p) {
  const sl_chart *c = p->c;
  double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
  for (int k = 0; k < c->n_series; ++k)
    for (int i = 0; i < c->series[k].n; ++i) {
      double x = c->series[k].x[i], y = c->series[k].y[i];
      if (!point_ok(c, x, y)) continue;
      xlo = fmin(xlo, x), xhi = fmax(xhi, x), ylo = fmin(ylo, y), yhi = fmax(yhi, y);
    }
  const sl_chart_heatmap *hm = c->heatmap;
  if (hm && hm->nx > 0 && hm->ny > 0) /* the map's extent */
    for (int k = 0; k < 2; ++k) {
      double x = hm->x_edges[k ? hm->nx : 0], y = hm->y_edges[k ? hm->ny : 0];
      if (point_ok(c, x, y)) xlo = fmin(xlo, x), xhi = fmax(xhi, x), ylo = fmin(ylo, y), yhi = fmax(yhi, y);
    }
  int any = xlo <= xhi;
  if (any) {
    for (int k = 0; k < 2; ++k) {
      if (c->xspan[0] != c->xspan[1] && plottable(c->xscale, c->xspan[k]))
        xlo = fmin(xlo, c->xspan[k]), xhi = fmax(xhi, c->xspan[k]);
      if (c->yspan[0] != c->yspan[1] && plottable(c->yscale, c->yspan[k]))
        ylo = fmin(ylo, c->yspan[k]), yhi = fmax(yhi, c->yspan[k]);
    }
    if (c->xscale == SL_AXIS_LOG && c->yscale == SL_AXIS_LOG)
      for (int k = 0; k < c->n_series; ++k) {
        make_triangle(&c->series[k], log10(yhi) - log10(ylo), &p->tri[k]);
        if (!p->tri[k].on) continue;
        double span = fmax(log10(yhi) - log10(ylo), 0.5);
        for (int j = 0; j < 3; ++j) ylo = fmin(ylo, pow(10.0, p->tri[k].y[j] - 0.1 * span)); /* room for the label */
      }
  } else {
    xlo = c->xscale == SL_AXIS_LOG ? 1.0 : 0.0, xhi = c->xscale == SL_AXIS_LOG ? 10.0 : 1.0;
    ylo = xlo, yhi = xhi;
    if (c->yscale != c->xscale) ylo = c->yscale == SL_AXIS_LOG ? 1.0 : 0.0, yhi = c->yscale == SL_AXIS_LOG ? 10.0 : 1.0;
  }
  double margin = hm ? 0.0 : 0.04;
  make_axis(&p->ax, c->xscale, xlo, xhi, margin);
  make_axis(&p->ay, c->yscale, ylo, yhi, margin);
  return any;
}

static void draw_axes(canvas *cv, const panel *p, double ox, double oy, double head_y) {
  const sl_chart *c = p->c;
  (void)oy;
  for (int k = 0; k < p->ax.n_ticks && !c->heatmap; ++k) {
    const tick *t = &p->ax.ticks[k];
    double x = pxc(p, t->v);
    cv_line(cv, x, p->y0, x, p->y1, 1, t->major ? GRID : MINOR_GRID, 0);
  }
  for (int k = 0; k < p->ay.n_ticks && !c->heatmap; ++k) {
    const tick *t = &p->ay.ticks[k];
    double y = pyc(p, t->v);
    cv_line(cv, p->x0, y, p->x1, y, 1, t->major ? GRID : MINOR_GRID, 0);
  }
  if (cv->f)
    fprintf(cv->f, "<g class=\"axis\" data-axis=\"x\" data-lo=\"%.10g\" data-hi=\"%.10g\">\n",
            p->ax.scale == SL_AXIS_LOG ? pow(10.0, p->ax.lo) : p->ax.lo,
            p->ax.scale == SL_AXIS_LOG ? pow(10.0, p->ax.hi) : p->ax.hi);
  for (int k = 0; k < p->ax.n_ticks; ++k) {
    const tick *t = &p->ax.ticks[k];
    double x = pxc(p, t->v);
    cv_line(cv, x, p->y1, x, p->y1 - (t->major ? 6 : 3.5), 1, FRAME, 0);
    cv_text(cv, x, p->y1 + 6 + TICKS, t->label, TICKS, MIDDLE, 0, INK, 0, "tick");
  }
  if (cv->f) fputs("</g>\n", cv->f);
  double widest = 0;
  if (cv->f)
    fprintf(cv->f, "<g class=\"axis\" data-axis=\"y\" data-lo=\"%.10g\" data-hi=\"%.10g\">\n",
            p->ay.scale == SL_AXIS_LOG ? pow(10.0, p->ay.lo) : p->ay.lo,
            p->ay.scale == SL_AXIS_LOG ? pow(10.0, p->ay.hi) : p->ay.hi);
  for (int k = 0; k < p->ay.n_ticks; ++k) {
    const tick *t = &p->ay.ticks[k];
    double y = pyc(p, t->v);
    cv_line(cv, p->x0, y, p->x0 + (t->major ? 6 : 3.5), y, 1, FRAME, 0);
    cv_text(cv, p->x0 - 6, y + 0.35 * TICKS, t->label, TICKS, END, 0, INK, 0, "tick");
    widest = fmax(widest, text_width(t->label, TICKS));
  }
  if (cv->f) fputs("</g>\n", cv->f);
  cv_rect(cv, p->x0, p->y0, p->x1, p->y1, -1, FRAME);
  /* axis titles longer than their axis are set smaller (down to 9 px) */
  if (c->xlabel) {
    double size = fmax(9.0, fmin(LABEL, LABEL * (p->x1 - p->x0) / fmax(text_width(c->xlabel, LABEL), 1.0)));
    cv_text(cv, 0.5 * (p->x0 + p->x1), p->y1 + 6 + TICKS + 8 + LABEL, c->xlabel, size, MIDDLE, 0, INK, 0, "xlabel");
  }
  if (c->ylabel) {
    double size = fmax(9.0, fmin(LABEL, LABEL * (p->y1 - p->y0) / fmax(text_width(c->ylabel, LABEL), 1.0)));
    cv_text(cv, ox + 10 + LABEL, 0.5 * (p->y0 + p->y1), c->ylabel, size, MIDDLE, 1, INK, 0, "ylabel");
  }
  if (head_y > 0 && c->title)
    cv_text(cv, 0.5 * (p->x0 + p->x1), head_y, c->title, HEAD, MIDDLE, 0, INK, 1, "panel-title");
}

static void draw_series(canvas *cv, const panel *p) {
  const sl_chart *c = p->c;
  cv_clip_begin(cv, p->x0, p->y0, p->x1, p->y1);
  for (int k = 0; k < c->n_series; ++k) {
    const sl_chart_series *s = &c->series[k];
    uint32_t col = series_colour(s, k);
    double *xs = malloc(sizeof *xs * (size_t)(s->n > 0 ? s->n : 1)),
           *ys = malloc(sizeof *ys * (size_t)(s->n > 0 ? s->n : 1));
    if (!xs || !ys) {
      free(xs), free(ys);
      continue;
    }
    int m = 0;
    for (int i = 0; i <= s->n; ++i) {
      if (i < s->n && point_ok(c, s->x[i], s->y[i])) {
        xs[m] = px(p, s->x[i]), ys[m] = py(p, s->y[i]), ++m;
        continue;
      }
      cv_polyline(cv, m, xs, ys, 1.8, col, s->dashed); /* the line breaks at a point left out */
      m = 0;
    }
    free(xs), free(ys);
  }
  cv_clip_end(cv);
  for (int k = 0; k < c->n_series; ++k) {
    const sl_chart_series *s = &c->series[k];
    uint32_t col = series_colour(s, k);
    int every = s->marker_every > 1 ? s->marker_every : 1;
    for (int i = 0; i < s->n; ++i) {
      if (!point_ok(c, s->x[i], s->y[i])) continue;
      double x = px(p, s->x[i]), y = py(p, s->y[i]);
      if ((i - s->marker_offset) % every == 0) cv_marker(cv, x, y, series_marker(s, k), 3.8, col);
      if (s->labels && s->labels[i]) { /* right of the point, or left of it where it would leave the frame */
        int left = x + 6 + text_width(s->labels[i], SMALL) > p->x1;
        cv_text(cv, left ? x - 6 : x + 6, y + 4 + SMALL, s->labels[i], SMALL, left ? END : START, 0, INK, 0, "point");
      }
    }
  }
  enum { MAX_PLACED = 16 };
  double placed[MAX_PLACED][3]; /* the slope labels drawn: centre, baseline, half width */
  int n_placed = 0;
  for (int k = 0; k < c->n_series; ++k) {
    const triangle *t = &p->tri[k];
    if (!t->on) continue;
    int same = 0; /* a curve on top of an earlier one: its triangle once */
    for (int j = 0; j < k && !same; ++j)
      same = p->tri[j].on && !strcmp(p->tri[j].label, t->label) && fabs(p->tri[j].y[0] - t->y[0]) < 0.05 &&
             fabs(p->tri[j].x[0] - t->x[0]) < 0.05;
    if (same) continue;
    double X[4], Y[4];
    for (int j = 0; j < 3; ++j) X[j] = pxc(p, t->x[j]), Y[j] = pyc(p, t->y[j]);
    /* hypotenuse, then the legs through the right angle */
    double lx[4] = {X[0], X[1], X[2], X[0]}, ly[4] = {Y[0], Y[1], Y[2], Y[0]};
    uint32_t col = series_colour(&c->series[k], k);
    if (cv->f) fputs("<g class=\"slope-triangle\">\n", cv->f);
    cv_polyline(cv, 4, lx, ly, 1.2, col, 0);
    double bottom = fmax(Y[0], Y[1]);
    double half = 0.5 * text_width(t->label, SMALL + 1), at = 0.5 * (X[0] + X[1]); /* inside the frame */
    at = fmax(p->x0 + half + 2, fmin(at, p->x1 - half - 2));
    double base = bottom + 4 + SMALL;
    for (int j = 0; j < n_placed; ++j) /* below a label already there */
      if (fabs(placed[j][0] - at) < placed[j][2] + half && fabs(placed[j][1] - base) < SMALL + 2)
        base = placed[j][1] + SMALL + 3, j = -1;
    if (n_placed < MAX_PLACED) placed[n_placed][0] = at, placed[n_placed][1] = base, placed[n_placed++][2] = half;
    cv_text(cv, at, base, t->label, SMALL + 1, MIDDLE, 0, col, 0, "slope");
    if (cv->f) fputs("</g>\n", cv->f);
  }
}

static void draw_legend(canvas *cv, const panel *p) {
  const sl_chart *c = p->c;
  if (c->legend == SL_LEGEND_NONE) return;
  int n = 0;
  double text_w = 0;
  for (int k = 0; k < c->n_series; ++k)
    if (c->series[k].name) ++n, text_w = fmax(text_w, text_width(c->series[k].name, LABEL - 1));
  if (!n) return;
  const double line_w = 30, row_h = LABEL + 6, pad = 7;
  double bw = pad + line_w + 7 + text_w + pad, bh = pad + n * row_h - 2;
  if (bw > p->x1 - p->x0 - 12) bw = p->x1 - p->x0 - 12;
  int corner = 0;
  if (c->legend == SL_LEGEND_AUTO) { /* 0 top right, 1 top left, 2 bottom right, 3 bottom left */
    int best_count = -1;
    for (int q = 0; q < 4; ++q) {
      double bx = q % 2 ? p->x0 + 8 : p->x1 - 8 - bw, by = q < 2 ? p->y0 + 8 : p->y1 - 8 - bh;
      int count = 0;
      for (int k = 0; k < c->n_series; ++k)
        for (int i = 0; i < c->series[k].n; ++i) {
          const sl_chart_series *s = &c->series[k];
          if (!point_ok(c, s->x[i], s->y[i])) continue;
          double x = px(p, s->x[i]), y = py(p, s->y[i]);
          count += x >= bx - 6 && x <= bx + bw + 6 && y >= by - 6 && y <= by + bh + 6;
        }
      if (best_count < 0 || count < best_count) corner = q, best_count = count;
    }
  } else {
    corner = c->legend == SL_LEGEND_TOP_RIGHT      ? 0
             : c->legend == SL_LEGEND_TOP_LEFT     ? 1
             : c->legend == SL_LEGEND_BOTTOM_RIGHT ? 2
                                                   : 3;
  }
  double bx = corner % 2 ? p->x0 + 8 : p->x1 - 8 - bw, by = corner < 2 ? p->y0 + 8 : p->y1 - 8 - bh;
  if (cv->f) fputs("<g class=\"legend\">\n", cv->f);
  cv_rect(cv, bx, by, bx + bw, by + bh, WHITE, 0xB0B0B0);
  int row = 0;
  for (int k = 0; k < c->n_series; ++k) {
    const sl_chart_series *s = &c->series[k];
    if (!s->name) continue;
    double y = by + pad + row * row_h + 0.5 * (LABEL - 1) - 2;
    uint32_t col = series_colour(s, k);
    cv_line(cv, bx + pad, y, bx + pad + line_w, y, 1.8, col, s->dashed);
    cv_marker(cv, bx + pad + 0.5 * line_w, y, series_marker(s, k), 3.8, col);
    cv_text(cv, bx + pad + line_w + 7, y + 0.35 * (LABEL - 1), s->name, LABEL - 1, START, 0, INK, 0, "legend-entry");
    ++row;
  }
  if (cv->f) fputs("</g>\n", cv->f);
}

/* The panel in the box (ox, oy, w, h). */
/* ---- heat maps ------------------------------------------------------------ */

uint32_t sl_chart_heat_colour(double t) {
  static const double stop[5][3] = {{255, 255, 255}, {255, 230, 120}, {250, 150, 40}, {215, 40, 30}, {110, 0, 20}};
  double r = (isfinite(t) ? fmin(fmax(t, 0.0), 1.0) : 0.0) * 4.0;
  int k = (int)fmin(floor(r), 3.0);
  double w = r - k, col[3];
  for (int j = 0; j < 3; ++j) col[j] = stop[k][j] + w * (stop[k + 1][j] - stop[k][j]);
  return (uint32_t)lround(col[0]) << 16 | (uint32_t)lround(col[1]) << 8 | (uint32_t)lround(col[2]);
}

static double heat_fraction(const sl_chart_heatmap *hm, double v) {
  return hm->hi > hm->lo ? (v - hm->lo) / (hm->hi - hm->lo) : 0.5;
}

enum { BAR_GAP = 14, BAR_W = 14, BAR_STRIPS = 64 };

/* The width right of the plot area the colour bar takes: gap, bar, ticks and labels, title. */
static double colourbar_width(const sl_chart_heatmap *hm, const axis *bar) {
  double w = 0;
  for (int k = 0; k < bar->n_ticks; ++k) w = fmax(w, text_width(bar->ticks[k].label, TICKS));
  return BAR_GAP + BAR_W + 6 + w + (hm->label ? 8 + LABEL : 0) + 4;
}

static void draw_heatmap(canvas *cv, const panel *p) {
  const sl_chart *c = p->c;
  const sl_chart_heatmap *hm = c->heatmap;
  if (cv->f)
    fprintf(cv->f, "<g class=\"heatmap\" shape-rendering=\"crispEdges\" data-lo=\"%.10g\" data-hi=\"%.10g\">\n", hm->lo,
            hm->hi);
  cv_clip_begin(cv, p->x0, p->y0, p->x1, p->y1);
  for (int j = 0; j < hm->ny; ++j)
    for (int i = 0; i < hm->nx; ++i) {
      double v = hm->values[(size_t)j * (size_t)hm->nx + (size_t)i];
      if (!isfinite(v) || !point_ok(c, hm->x_edges[i], hm->y_edges[j]) ||
          !point_ok(c, hm->x_edges[i + 1], hm->y_edges[j + 1]))
        continue;
      double x0 = px(p, hm->x_edges[i]), x1 = px(p, hm->x_edges[i + 1]);
      double y0 = py(p, hm->y_edges[j + 1]), y1 = py(p, hm->y_edges[j]);
      cv_rect(cv, fmin(x0, x1), fmin(y0, y1), fmax(x0, x1), fmax(y0, y1), sl_chart_heat_colour(heat_fraction(hm, v)),
              -1);
    }
  cv_clip_end(cv);
  if (cv->f) fputs("</g>\n", cv->f);
}

static void draw_colourbar(canvas *cv, const panel *p, const axis *bar) {
  const sl_chart_heatmap *hm = p->c->heatmap;
  double x0 = p->x1 + BAR_GAP, x1 = x0 + BAR_W, y0 = p->y0, y1 = p->y1;
  if (cv->f)
    fprintf(cv->f, "<g class=\"colourbar\" shape-rendering=\"crispEdges\" data-lo=\"%.10g\" data-hi=\"%.10g\">\n",
            bar->lo, bar->hi);
  for (int k = 0; k < BAR_STRIPS; ++k) { /* from lo at the bottom, each strip the colour of its middle */
    double v = bar->lo + (k + 0.5) / BAR_STRIPS * (bar->hi - bar->lo);
    double ya = y1 - (double)(k + 1) / BAR_STRIPS * (y1 - y0), yb = y1 - (double)k / BAR_STRIPS * (y1 - y0);
    cv_rect(cv, x0, ya, x1, yb, sl_chart_heat_colour(heat_fraction(hm, v)), -1);
  }
  cv_rect(cv, x0, y0, x1, y1, -1, FRAME);
  double widest = 0;
  for (int k = 0; k < bar->n_ticks; ++k) {
    const tick *t = &bar->ticks[k];
    double y = y1 - (t->v - bar->lo) / (bar->hi - bar->lo) * (y1 - y0);
    cv_line(cv, x1, y, x1 + 4, y, 1, FRAME, 0);
    cv_text(cv, x1 + 6, y + 0.35 * TICKS, t->label, TICKS, START, 0, INK, 0, "tick");
    widest = fmax(widest, text_width(t->label, TICKS));
  }
  if (hm->label) {
    double size = fmax(9.0, fmin(LABEL, LABEL * (y1 - y0) / fmax(text_width(hm->label, LABEL), 1.0)));
    cv_text(cv, x1 + 6 + widest + 8 + 0.8 * LABEL, 0.5 * (y0 + y1), hm->label, size, MIDDLE, 1, INK, 0, "barlabel");
  }
  if (cv->f) fputs("</g>\n", cv->f);
}

static int draw_panel(canvas *cv, const sl_chart *c, double ox, double oy, double w, double h, int heading,
                      sl_diag *d) {
  panel p = {.c = c};
  p.tri = calloc((size_t)(c->n_series > 0 ? c->n_series : 1), sizeof *p.tri);
  if (!p.tri) return sl_diag_set(d, SL_ENOMEM, "plot: out of memory");
  p.any = fit_axes(&p);
  double label_w = 0;
  for (int k = 0; k < p.ay.n_ticks; ++k) label_w = fmax(label_w, text_width(p.ay.ticks[k].label, TICKS));
  double top = oy + 8 + (heading && c->title ? HEAD + 8 : 0);
  p.x0 = ox + 10 + (c->ylabel ? LABEL + 10 : 0) + label_w + 8;
  p.x1 = ox + w - 18;
  axis bar;
  if (c->heatmap) {
    make_axis(&bar, SL_AXIS_LINEAR, c->heatmap->lo, c->heatmap->hi, 0.0);
    p.x1 -= colourbar_width(c->heatmap, &bar);
  }
  p.y0 = top + 4;
  p.y1 = oy + h - (6 + TICKS + 8 + (c->xlabel ? LABEL + 8 : 0) + 4);
  if (p.x1 - p.x0 < 50 || p.y1 - p.y0 < 50) {
    free(p.tri);
    return sl_diag_set(d, SL_EBADINPUT, "plot: a %.0f x %.0f pixel panel leaves no room for the plot", w, h);
  }
  if (c->heatmap) draw_heatmap(cv, &p);
  draw_axes(cv, &p, ox, oy, heading ? oy + 8 + HEAD : 0);
  if (c->heatmap) draw_colourbar(cv, &p, &bar);
  draw_series(cv, &p);
  draw_legend(cv, &p);
  if (!p.any)
    cv_text(cv, 0.5 * (p.x0 + p.x1), 0.5 * (p.y0 + p.y1), "no point to plot", LABEL, MIDDLE, 0, 0xA00000, 0, NULL);
  free(p.tri);
  return 0;
}

/* ---- figures -------------------------------------------------------------- */

/* Draws text line by line (at '\n', and at spaces where a line is wider than
 * width) from baseline y; cv NULL: only counts. Returns the number of lines. */
static int draw_lines(canvas *cv, const char *text, double x, double y, double size, double width, anchor a,
                      uint32_t col, const char *cls) {
  int lines = 0;
  for (const char *p = text; p && *p;) {
    const char *nl = strchr(p, '\n');
    size_t n = nl ? (size_t)(nl - p) : strlen(p);
    char buf[1024];
    snprintf(buf, sizeof buf, "%.*s", (int)(n < sizeof buf ? n : sizeof buf - 1), p);
    char *q = buf;
    while (*q) {
      char *cut = NULL;
      if (text_width(q, size) > width) /* the last space where the line still fits */
        for (char *sp = strchr(q, ' '); sp; sp = strchr(sp + 1, ' ')) {
          *sp = '\0';
          int fits = text_width(q, size) <= width;
          *sp = ' ';
          if (!fits) break;
          cut = sp;
        }
      if (cut) *cut = '\0';
      if (cv) cv_text(cv, x, y, q, size, a, 0, col, 0, cls);
      y += size + 4, ++lines;
      q = cut ? cut + 1 : q + strlen(q);
    }
    p = nl ? nl + 1 : p + n;
  }
  return lines;
}

static double header_height(const sl_figure *f, double W) {
  return 6 + (f->title ? TITLE + 8 : 0) +
         draw_lines(NULL, f->subtitle, 0, 0, SUB, W - 16, MIDDLE, INK, NULL) * (SUB + 4) + 4;
}
static double footer_height(const sl_figure *f, double W) {
  return f->note ? draw_lines(NULL, f->note, 0, 0, SMALL, W - 16, START, NOTE, NULL) * (SMALL + 4) + 8 : 4;
}

static int render(canvas *cv, const sl_figure *f, double W, double H, double pw, double ph, int heading, sl_diag *d) {
  double y = 6;
  if (f->title) cv_text(cv, 0.5 * W, y + TITLE, f->title, TITLE, MIDDLE, 0, INK, 1, "title"), y += TITLE + 8;
  if (f->subtitle) draw_lines(cv, f->subtitle, 0.5 * W, y + SUB, SUB, W - 16, MIDDLE, INK, "subtitle");
  double top = header_height(f, W);
  int cols = f->columns > 0 ? f->columns : f->n_panels;
  for (int k = 0; k < f->n_panels; ++k) {
    int rc = draw_panel(cv, &f->panels[k], (k % cols) * pw, top + (k / cols) * ph, pw, ph, heading, d);
    if (rc) return rc;
  }
  if (f->note) draw_lines(cv, f->note, 8, H - footer_height(f, W) + 4 + SMALL, SMALL, W - 16, START, NOTE, "note");
  return 0;
}

static int figure_size(const sl_figure *f, double *W, double *H, double *pw, double *ph, sl_diag *d) {
  if (f->n_panels < 1) return sl_diag_set(d, SL_EBADINPUT, "plot: a figure without panels");
  int cols = f->columns > 0 ? f->columns : f->n_panels, rows = (f->n_panels + cols - 1) / cols;
  *pw = f->panel_width > 0 ? f->panel_width : 480, *ph = f->panel_height > 0 ? f->panel_height : 360;
  *W = cols * *pw, *H = header_height(f, *W) + rows * *ph + footer_height(f, *W);
  return 0;
}

/* A supersampled image, averaged down to w x h. */
static int raster(const sl_figure *f, int w, int h, double pw, double ph, int heading, sl_image *im, sl_diag *d) {
  sl_image big;
  if (sl_image_init(&big, w * SS, h * SS, WHITE)) return sl_diag_set(d, SL_ENOMEM, "plot: out of memory");
  canvas cv = {.im = &big};
  int rc = render(&cv, f, w, h, pw, ph, heading, d);
  if (!rc && sl_image_init(im, w, h, WHITE)) rc = sl_diag_set(d, SL_ENOMEM, "plot: out of memory");
  if (rc) {
    sl_image_free(&big);
    return rc;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        unsigned sum = 0;
        for (int j = 0; j < SS; ++j)
          for (int i = 0; i < SS; ++i)
            sum += big.rgb[(((size_t)(y * SS + j) * (size_t)big.w) + (size_t)(x * SS + i)) * 3 + ch];
        im->rgb[((size_t)y * (size_t)w + (size_t)x) * 3 + ch] = (unsigned char)((sum + SS * SS / 2) / (SS * SS));
      }
  sl_image_free(&big);
  return 0;
}

static int svg(const char *path, const sl_figure *f, double W, double H, double pw, double ph, int heading,
               sl_diag *d) {
  FILE *out = fopen(path, "w");
  if (!out) return sl_diag_set(d, SL_EFAILED, "%s: %s", path, strerror(errno));
  fprintf(out,
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
          "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n<rect width=\"100%%\" height=\"100%%\" "
          "fill=\"#FFFFFF\"/>\n",
          W, H, W, H);
  canvas cv = {.f = out};
  int rc = render(&cv, f, W, H, pw, ph, heading, d);
  fputs("</svg>\n", out);
  int bad = ferror(out);
  bad |= fclose(out) != 0;
  if (rc) return remove(path), rc;
  if (bad) return remove(path), sl_diag_set(d, SL_EFAILED, "%s: write failed", path);
  return 0;
}

int sl_figure_draw(const sl_figure *f, sl_image *im, sl_diag *d) {
  double W = 0, H = 0, pw = 0, ph = 0;
  int rc = figure_size(f, &W, &H, &pw, &ph, d);
  return rc ? rc : raster(f, (int)W, (int)H, pw, ph, 1, im, d);
}

int sl_figure_write_png(const char *path, const sl_figure *f, sl_diag *d) {
  sl_image im;
  int rc = sl_figure_draw(f, &im, d);
  if (rc) return rc;
  rc = sl_png_write(path, im.rgb, im.w, im.h, d);
  sl_image_free(&im);
  return rc;
}

int sl_figure_write_svg(const char *path, const sl_figure *f, sl_diag *d) {
  double W = 0, H = 0, pw = 0, ph = 0;
  int rc = figure_size(f, &W, &H, &pw, &ph, d);
  return rc ? rc : svg(path, f, W, H, pw, ph, 1, d);
}

int sl_figure_write(const char *path, const sl_figure *f, sl_diag *d) {
  size_t n = strlen(path);
  return n > 4 && !strcmp(path + n - 4, ".png") ? sl_figure_write_png(path, f, d) : sl_figure_write_svg(path, f, d);
}

/* A chart is a figure of one panel filling w x h under the chart's title. */
static int chart_figure(const sl_chart *c, int w, int h, sl_figure *f, double *ph, sl_diag *d) {
  if (w < 200 || h < 150) return sl_diag_set(d, SL_EBADINPUT, "chart: %d x %d pixels is too small", w, h);
  *f = (sl_figure){.title = c->title, .subtitle = c->subtitle, .note = c->note, .n_panels = 1, .panels = c};
  *ph = h - header_height(f, w) - footer_height(f, w);
  return 0;
}

int sl_chart_draw(const sl_chart *c, int w, int h, sl_image *im, sl_diag *d) {
  sl_figure f;
  double ph = 0;
  int rc = chart_figure(c, w, h, &f, &ph, d);
  return rc ? rc : raster(&f, w, h, w, ph, 0, im, d);
}

int sl_chart_write_png(const char *path, const sl_chart *c, int w, int h, sl_diag *d) {
  sl_image im;
  int rc = sl_chart_draw(c, w, h, &im, d);
  if (rc) return rc;
  rc = sl_png_write(path, im.rgb, im.w, im.h, d);
  sl_image_free(&im);
  return rc;
}

int sl_chart_write_svg(const char *path, const sl_chart *c, int w, int h, sl_diag *d) {
  sl_figure f;
  double ph = 0;
  int rc = chart_figure(c, w, h, &f, &ph, d);
  return rc ? rc : svg(path, &f, w, h, w, ph, 0, d);
}
