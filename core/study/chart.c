/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Line charts on a raster (see chart.h). */
#include "core/study/chart.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/study/font.h"
#include "core/study/png.h"

enum { TEXT = 2, SMALL = 1, MAX_TICKS = 64 }; /* font scales: titles, labels and ticks; point labels */

static const uint32_t INK = 0x202020, GRID = 0xE4E4E4, MINOR_GRID = 0xF2F2F2, FRAME = 0x606060, WHITE = 0xFFFFFF;

uint32_t sl_chart_colour(int k) {
  static const uint32_t palette[] = {0x1F77B4, 0xD62728, 0x2CA02C, 0xFF7F0E, 0x9467BD,
                                     0x8C564B, 0xE377C2, 0x7F7F7F, 0xBCBD22, 0x17BECF};
  return palette[(k < 0 ? -k : k) % (int)(sizeof palette / sizeof palette[0])];
}

/* ---- axes ------------------------------------------------------------------ */

typedef struct tick {
  double v;
  int major;
  char label[24];
} tick;

typedef struct axis {
  sl_axis_scale scale;
  double lo, hi; /* data range mapped to the panel: values (linear) or log10 of them */
  int n_ticks;
  tick ticks[MAX_TICKS];
} axis;

static int imax(int a, int b) { return a > b ? a : b; }
static int plottable(sl_axis_scale s, double v) { return isfinite(v) && (s == SL_AXIS_LINEAR || v > 0.0); }
static double coord(const axis *a, double v) { return a->scale == SL_AXIS_LOG ? log10(v) : v; }

/* m 10^e as text: plain decimals for moderate exponents, "2e-5" otherwise. */
static void decade_label(char *buf, size_t n, int m, int e) {
  if (e >= -3 && e <= 4) snprintf(buf, n, "%.*f", e < 0 ? -e : 0, m * pow(10.0, e));
  else snprintf(buf, n, "%de%d", m, e);
}

static void add_tick(axis *a, double v, int major, const char *label) {
  if (a->n_ticks == MAX_TICKS) return;
  tick *t = &a->ticks[a->n_ticks++];
  t->v = v, t->major = major;
  snprintf(t->label, sizeof t->label, "%s", label ? label : "");
}

static void log_axis(axis *a, double lo, double hi) {
  int e0 = (int)floor(log10(lo) + 1e-9), e1 = (int)ceil(log10(hi) - 1e-9);
  if (e1 <= e0) e1 = e0 + 1;
  a->lo = e0, a->hi = e1;
  /* a tick at every decade (every few when there are many), labelled; the
   * 2..9 between them when there are few, labelled at 2 and 5 over one or two */
  int decades = e1 - e0, every = decades > 10 ? (decades + 9) / 10 : 1;
  for (int e = e0; e <= e1; e += every) {
    char buf[24];
    decade_label(buf, sizeof buf, 1, e);
    add_tick(a, e, 1, buf);
    if (decades > 6 || e == e1) continue;
    for (int m = 2; m <= 9; ++m) {
      decade_label(buf, sizeof buf, m, e);
      add_tick(a, e + log10(m), 0, decades <= 2 && (m == 2 || m == 5) ? buf : NULL);
    }
  }
}

static void linear_axis(axis *a, double lo, double hi) {
  if (!(hi > lo)) {
    double pad = lo != 0.0 ? 0.1 * fabs(lo) : 1.0;
    lo -= pad, hi += pad;
  }
  double raw = (hi - lo) / 6.0, p = pow(10.0, floor(log10(raw))), step = 10.0 * p;
  if (raw <= p) step = p;
  else if (raw <= 2.0 * p) step = 2.0 * p;
  else if (raw <= 5.0 * p) step = 5.0 * p;
  double first = floor(lo / step + 1e-9), last = ceil(hi / step - 1e-9);
  a->lo = first * step, a->hi = last * step;
  int decimals = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
  for (double k = first; k <= last + 0.5 && a->n_ticks < MAX_TICKS; k += 1.0) {
    char buf[24];
    double v = k * step;
    if (fabs(v) < 1e-12 * step) v = 0.0; /* no "-0" */
    if (fabs(v) >= 1e5 || (v != 0.0 && fabs(v) < 1e-4)) snprintf(buf, sizeof buf, "%.3g", v);
    else snprintf(buf, sizeof buf, "%.*f", decimals, v);
    add_tick(a, v, 1, buf);
  }
}

/* The axis over every plottable value of one coordinate of all series. */
static int make_axis(axis *a, sl_axis_scale s, const sl_chart *c, int use_y) {
  memset(a, 0, sizeof *a);
  a->scale = s;
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < c->n_series; ++k) {
    const sl_chart_series *sr = &c->series[k];
    for (int i = 0; i < sr->n; ++i) {
      double x = sr->x[i], y = sr->y[i];
      if (!plottable(c->xscale, x) || !plottable(c->yscale, y)) continue;
      double v = use_y ? y : x;
      lo = fmin(lo, v), hi = fmax(hi, v);
    }
  }
  int any = lo <= hi;
  if (!any) lo = s == SL_AXIS_LOG ? 1.0 : 0.0, hi = s == SL_AXIS_LOG ? 10.0 : 1.0;
  if (s == SL_AXIS_LOG) log_axis(a, lo, hi);
  else linear_axis(a, lo, hi);
  return any;
}

/* ---- drawing ---------------------------------------------------------------- */

typedef struct frame {
  int x0, y0, x1, y1; /* the plot area, pixels, inclusive */
  axis ax, ay;
} frame;

static double px(const frame *f, double v) {
  return f->x0 + (coord(&f->ax, v) - f->ax.lo) / (f->ax.hi - f->ax.lo) * (f->x1 - f->x0);
}
static double py(const frame *f, double v) {
  return f->y1 - (coord(&f->ay, v) - f->ay.lo) / (f->ay.hi - f->ay.lo) * (f->y1 - f->y0);
}

/* Text cut to fit `room` pixels, with "..." when cut. */
static void fit_text(char *buf, size_t n, const char *text, int scale, int room) {
  snprintf(buf, n, "%s", text ? text : "");
  size_t len = strlen(buf);
  if (sl_font_width(buf, scale) <= room) return;
  while (len > 3 && sl_font_width(buf, scale) > room) {
    buf[--len] = '\0';
    memcpy(buf + len - 3, "...", 3);
  }
}

static void centred_text(sl_image *im, int cx, int y, const char *text, int scale, uint32_t colour) {
  char buf[512];
  fit_text(buf, sizeof buf, text, scale, im->w - 8);
  sl_font_draw(im, cx - sl_font_width(buf, scale) / 2, y, buf, scale, colour, 0);
}

/* Liang-Barsky: clips the segment to the plot area; 0 when nothing is left. */
static int clip(const frame *f, double *x0, double *y0, double *x1, double *y1) {
  double t0 = 0.0, t1 = 1.0, dx = *x1 - *x0, dy = *y1 - *y0;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {*x0 - f->x0, f->x1 - *x0, *y0 - f->y0, f->y1 - *y0};
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

static void draw_axes(sl_image *im, const frame *f, const sl_chart *c) {
  /* grid, then ticks and their labels */
  for (int k = 0; k < f->ax.n_ticks; ++k) {
    const tick *t = &f->ax.ticks[k];
    int x = (int)lround(f->x0 + (t->v - f->ax.lo) / (f->ax.hi - f->ax.lo) * (f->x1 - f->x0));
    sl_image_line(im, x, f->y0, x, f->y1, 1, t->major ? GRID : MINOR_GRID, 0);
    sl_image_line(im, x, f->y1, x, f->y1 - (t->major ? 7 : 4), 1, FRAME, 0);
    if (t->label[0])
      sl_font_draw(im, x - sl_font_width(t->label, TEXT) / 2, f->y1 + 8, t->label, TEXT, INK, 0);
  }
  for (int k = 0; k < f->ay.n_ticks; ++k) {
    const tick *t = &f->ay.ticks[k];
    int y = (int)lround(f->y1 - (t->v - f->ay.lo) / (f->ay.hi - f->ay.lo) * (f->y1 - f->y0));
    sl_image_line(im, f->x0, y, f->x1, y, 1, t->major ? GRID : MINOR_GRID, 0);
    sl_image_line(im, f->x0, y, f->x0 + (t->major ? 7 : 4), y, 1, FRAME, 0);
    if (t->label[0])
      sl_font_draw(im, f->x0 - 8 - sl_font_width(t->label, TEXT), y - sl_font_height(TEXT) / 2, t->label, TEXT, INK, 0);
  }
  sl_image_line(im, f->x0, f->y0, f->x1, f->y0, 1, FRAME, 0);
  sl_image_line(im, f->x0, f->y1, f->x1, f->y1, 1, FRAME, 0);
  sl_image_line(im, f->x0, f->y0, f->x0, f->y1, 1, FRAME, 0);
  sl_image_line(im, f->x1, f->y0, f->x1, f->y1, 1, FRAME, 0);
  char buf[512];
  if (c->xlabel) {
    fit_text(buf, sizeof buf, c->xlabel, TEXT, f->x1 - f->x0);
    sl_font_draw(im, (f->x0 + f->x1 - sl_font_width(buf, TEXT)) / 2, f->y1 + 8 + sl_font_height(TEXT) + 10, buf, TEXT,
                 INK, 0);
  }
  if (c->ylabel) {
    fit_text(buf, sizeof buf, c->ylabel, TEXT, f->y1 - f->y0);
    sl_font_draw(im, 12, (f->y0 + f->y1 + sl_font_width(buf, TEXT)) / 2, buf, TEXT, INK, 1);
  }
}

static void draw_series(sl_image *im, const frame *f, const sl_chart *c) {
  for (int k = 0; k < c->n_series; ++k) {
    const sl_chart_series *s = &c->series[k];
    uint32_t col = sl_chart_colour(k);
    int have_prev = 0;
    double qx = 0, qy = 0;
    for (int i = 0; i < s->n; ++i) {
      if (!plottable(c->xscale, s->x[i]) || !plottable(c->yscale, s->y[i])) {
        have_prev = 0;
        continue;
      }
      double x = px(f, s->x[i]), y = py(f, s->y[i]);
      if (have_prev) {
        double a = qx, b = qy, cx = x, cy = y;
        if (clip(f, &a, &b, &cx, &cy)) sl_image_line(im, a, b, cx, cy, 2, col, s->dashed ? 6 : 0);
      }
      qx = x, qy = y, have_prev = 1;
    }
    int every = s->marker_every > 1 ? s->marker_every : 1;
    for (int i = 0; i < s->n; ++i) {
      if (!plottable(c->xscale, s->x[i]) || !plottable(c->yscale, s->y[i])) continue;
      double x = px(f, s->x[i]), y = py(f, s->y[i]);
      if ((i - s->marker_offset) % every == 0) sl_image_marker(im, x, y, (sl_marker)(k % SL_MARK_COUNT), 4, col);
      if (s->labels && s->labels[i]) sl_font_draw(im, (int)x + 7, (int)y + 3, s->labels[i], SMALL, INK, 0);
    }
  }
}

static void draw_legend(sl_image *im, const frame *f, const sl_chart *c) {
  int n = 0, text_w = 0;
  for (int k = 0; k < c->n_series; ++k)
    if (c->series[k].name) ++n, text_w = imax(text_w, sl_font_width(c->series[k].name, TEXT));
  if (!n) return;
  const int line_w = 34, row_h = sl_font_height(TEXT) + 8, pad = 8;
  int bw = pad + line_w + 8 + text_w + pad, bh = pad + n * row_h;
  int room = f->x1 - f->x0 - 16;
  if (bw > room) bw = room, text_w = bw - 2 * pad - line_w - 8;
  /* the corner whose box covers the fewest points */
  int best = 0, best_count = -1;
  for (int corner = 0; corner < 4; ++corner) {
    int bx = corner % 2 ? f->x0 + 8 : f->x1 - 8 - bw, by = corner < 2 ? f->y0 + 8 : f->y1 - 8 - bh, count = 0;
    for (int k = 0; k < c->n_series; ++k)
      for (int i = 0; i < c->series[k].n; ++i) {
        const sl_chart_series *s = &c->series[k];
        if (!plottable(c->xscale, s->x[i]) || !plottable(c->yscale, s->y[i])) continue;
        double x = px(f, s->x[i]), y = py(f, s->y[i]);
        count += x >= bx - 6 && x <= bx + bw + 6 && y >= by - 6 && y <= by + bh + 6;
      }
    if (best_count < 0 || count < best_count) best = corner, best_count = count;
  }
  int bx = best % 2 ? f->x0 + 8 : f->x1 - 8 - bw, by = best < 2 ? f->y0 + 8 : f->y1 - 8 - bh;
  sl_image_fill(im, bx, by, bx + bw, by + bh, WHITE);
  sl_image_line(im, bx, by, bx + bw, by, 1, FRAME, 0);
  sl_image_line(im, bx, by + bh, bx + bw, by + bh, 1, FRAME, 0);
  sl_image_line(im, bx, by, bx, by + bh, 1, FRAME, 0);
  sl_image_line(im, bx + bw, by, bx + bw, by + bh, 1, FRAME, 0);
  int row = 0;
  for (int k = 0; k < c->n_series; ++k) {
    if (!c->series[k].name) continue;
    int y = by + pad + row * row_h + sl_font_height(TEXT) / 2;
    uint32_t col = sl_chart_colour(k);
    sl_image_line(im, bx + pad, y, bx + pad + line_w, y, 2, col, c->series[k].dashed ? 6 : 0);
    sl_image_marker(im, bx + pad + line_w / 2, y, (sl_marker)(k % SL_MARK_COUNT), 4, col);
    char buf[512];
    fit_text(buf, sizeof buf, c->series[k].name, TEXT, text_w);
    sl_font_draw(im, bx + pad + line_w + 8, y - sl_font_height(TEXT) / 2, buf, TEXT, INK, 0);
    ++row;
  }
}

int sl_chart_draw(const sl_chart *c, int w, int h, sl_image *im, sl_diag *d) {
  if (w < 200 || h < 150) return sl_diag_set(d, SL_EBADINPUT, "chart: %d x %d pixels is too small", w, h);
  if (sl_image_init(im, w, h, WHITE)) return sl_diag_set(d, SL_ENOMEM, "chart: out of memory");
  frame f;
  int any = make_axis(&f.ax, c->xscale, c, 0);
  make_axis(&f.ay, c->yscale, c, 1);
  int label_w = 0;
  for (int k = 0; k < f.ay.n_ticks; ++k) label_w = imax(label_w, sl_font_width(f.ay.ticks[k].label, TEXT));
  int th = sl_font_height(TEXT);
  int top = 12, sub_lines = 0;
  if (c->title) top += th + 8;
  for (const char *p = c->subtitle; p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) ++sub_lines;
  top += sub_lines * (sl_font_height(SMALL) + 4) + (sub_lines ? 4 : 0);
  f.x0 = 12 + th + 12 + label_w + 8;
  f.x1 = w - 24;
  f.y0 = top + 8;
  f.y1 = h - (8 + th + 10 + th + 12 + (c->note ? sl_font_height(SMALL) + 6 : 0));
  if (f.x1 - f.x0 < 50 || f.y1 - f.y0 < 50) {
    sl_image_free(im);
    return sl_diag_set(d, SL_EBADINPUT, "chart: %d x %d pixels leave no room for the plot", w, h);
  }
  if (c->title) centred_text(im, w / 2, 12, c->title, TEXT, INK);
  int y = 12 + (c->title ? th + 8 : 0);
  for (const char *p = c->subtitle; p && *p; y += sl_font_height(SMALL) + 4) { /* one line each */
    const char *nl = strchr(p, '\n');
    size_t n = nl ? (size_t)(nl - p) : strlen(p);
    char buf[512];
    snprintf(buf, sizeof buf, "%.*s", (int)(n < sizeof buf ? n : sizeof buf - 1), p);
    centred_text(im, w / 2, y, buf, SMALL, INK);
    p = nl ? nl + 1 : p + n;
  }
  draw_axes(im, &f, c);
  draw_series(im, &f, c);
  draw_legend(im, &f, c);
  if (!any) centred_text(im, (f.x0 + f.x1) / 2, (f.y0 + f.y1) / 2, "no point to plot", TEXT, 0xA00000);
  if (c->note) {
    char buf[512];
    fit_text(buf, sizeof buf, c->note, SMALL, w - 16);
    sl_font_draw(im, 8, h - 6 - sl_font_height(SMALL), buf, SMALL, FRAME, 0);
  }
  return 0;
}

int sl_chart_write_png(const char *path, const sl_chart *c, int w, int h, sl_diag *d) {
  sl_image im;
  int rc = sl_chart_draw(c, w, h, &im, d);
  if (rc) return rc;
  rc = sl_png_write(path, im.rgb, im.w, im.h, d);
  sl_image_free(&im);
  return rc;
}
