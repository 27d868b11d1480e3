/* SPDX-License-Identifier: GPL-2.0-or-later */
/* See svg_plot.h. */
#include "svg_plot.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

enum { MARGIN_LEFT = 70, MARGIN_RIGHT = 18, MARGIN_TOP = 30, MARGIN_BOTTOM = 50, FIG_TITLE = 28 };

static const char *const default_colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                              "#e377c2", "#7f7f7f"};

static int plottable(double x, double y) { return isfinite(x) && isfinite(y) && x > 0.0 && y > 0.0; }

/* Text with the XML specials escaped. */
static void put_text(FILE *f, const char *s) {
  for (; *s; ++s) {
    switch (*s) {
    case '<': fputs("&lt;", f); break;
    case '>': fputs("&gt;", f); break;
    case '&': fputs("&amp;", f); break;
    case '"': fputs("&quot;", f); break;
    default: fputc(*s, f);
    }
  }
}

/* A rough width of s in pixels at font size px (sans-serif, mostly digits
 * and lower case): for sizing the legend box. */
static double text_width(const char *s, double px) {
  double w = 0.0;
  for (; *s; ++s) {
    unsigned char c = (unsigned char)*s;
    if ((c & 0xC0) == 0x80) continue; /* UTF-8 continuation byte */
    w += (c == ' ' || c == '.' || c == ',' || c == 'i' || c == 'l' || c == '(' || c == ')') ? 0.34
         : (c >= 'A' && c <= 'Z') || c == 'm' || c == 'w'                                 ? 0.8
                                                                                            : 0.62;
  }
  return w * px;
}

typedef struct axis {
  int lo, hi;      /* decades: the axis runs from 10^lo to 10^hi */
  double p0, p1;   /* pixel positions of 10^lo and 10^hi */
} axis;

static double axis_pos(const axis *a, double v) { return a->p0 + (log10(v) - a->lo) / (a->hi - a->lo) * (a->p1 - a->p0); }

/* Decade range covering [vmin, vmax] with at least 0.04 decade to spare. */
static void axis_range(double vmin, double vmax, axis *a) {
  a->lo = (int)floor(log10(vmin) - 0.04);
  a->hi = (int)ceil(log10(vmax) + 0.04);
  if (a->hi <= a->lo) a->hi = a->lo + 1;
}

/* 10^k as a tick label: plain decimals when the whole axis lies within
 * 10^-2 .. 10^4, a power of ten otherwise. */
static void tick_label(FILE *f, const axis *a, int k, double x, double y, const char *anchor) {
  fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">", x, y, anchor);
  if (a->lo >= -2 && a->hi <= 4) {
    if (k >= 0) fprintf(f, "%.0f", pow(10.0, k));
    else fprintf(f, "%.*f", -k, pow(10.0, k));
  } else {
    fprintf(f, "10<tspan dy=\"-6\" font-size=\"9\">%s%d</tspan>", k < 0 ? "&#8722;" : "", k < 0 ? -k : k);
  }
  fputs("</text>\n", f);
}

static void marker(FILE *f, svgp_marker m, double x, double y, const char *colour) {
  const double r = 3.8;
  switch (m) {
  case SVGP_SQUARE:
    fprintf(f, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n", x - r * 0.85, y - r * 0.85,
            1.7 * r, 1.7 * r, colour);
    break;
  case SVGP_TRIANGLE:
    fprintf(f, "<path d=\"M%.2f,%.2fL%.2f,%.2fL%.2f,%.2fZ\" fill=\"%s\"/>\n", x, y - 1.2 * r, x + 1.05 * r,
            y + 0.65 * r, x - 1.05 * r, y + 0.65 * r, colour);
    break;
  case SVGP_DIAMOND:
    fprintf(f, "<path d=\"M%.2f,%.2fL%.2f,%.2fL%.2f,%.2fL%.2f,%.2fZ\" fill=\"%s\"/>\n", x, y - 1.2 * r, x + 1.2 * r, y,
            x, y + 1.2 * r, x - 1.2 * r, y, colour);
    break;
  default: fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"/>\n", x, y, r, colour);
  }
}

static const char *colour_of(const svgp_series *s, int k) {
  return s->colour ? s->colour : default_colours[k % (int)(sizeof default_colours / sizeof *default_colours)];
}

static int panel(FILE *f, const svgp_panel *p, int id, double ox, double oy, double w, double h) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (int s = 0; s < p->n_series; ++s)
    for (int i = 0; i < p->series[s].n; ++i) {
      double x = p->series[s].x[i], y = p->series[s].y[i];
      if (!plottable(x, y)) continue;
      xmin = fmin(xmin, x), xmax = fmax(xmax, x), ymin = fmin(ymin, y), ymax = fmax(ymax, y);
    }
  if (!(xmin <= xmax)) return -1;
  for (int k = 0; k < 2; ++k) {
    if (p->xspan[k] > 0.0 && isfinite(p->xspan[k])) xmin = fmin(xmin, p->xspan[k]), xmax = fmax(xmax, p->xspan[k]);
    if (p->yspan[k] > 0.0 && isfinite(p->yspan[k])) ymin = fmin(ymin, p->yspan[k]), ymax = fmax(ymax, p->yspan[k]);
  }
  const double x0 = ox + MARGIN_LEFT, x1 = ox + w - MARGIN_RIGHT, y0 = oy + MARGIN_TOP, y1 = oy + h - MARGIN_BOTTOM;
  axis ax = {.p0 = x0, .p1 = x1}, ay = {.p0 = y1, .p1 = y0};
  axis_range(xmin, xmax, &ax);
  axis_range(ymin, ymax, &ay);

  fprintf(f, "<g>\n<clipPath id=\"clip%d\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/></clipPath>\n", id,
          x0, y0, x1 - x0, y1 - y0);
  if (p->title) {
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-weight=\"bold\" font-size=\"13\">",
            0.5 * (x0 + x1), oy + 18.0);
    put_text(f, p->title);
    fputs("</text>\n", f);
  }
  /* grid (minor lines at 2..9 x 10^k only when the axis spans at most 8
   * decades, then the interior decades over them) and ticks */
  fputs("<g stroke-width=\"1\">\n", f);
  for (int pass = 0; pass < 3; ++pass)
    for (int dim = 0; dim < 2; ++dim) {
      const axis *a = dim ? &ay : &ax;
      for (int k = a->lo; k <= a->hi; ++k)
        for (int m = 1; m <= 9 && (m == 1 || k < a->hi); ++m) {
          double q = axis_pos(a, m * pow(10.0, k));
          if (pass == 2) { /* tick */
            double len = m == 1 ? 6.0 : 3.0;
            fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#000\"/>\n", dim ? x0 : q,
                    dim ? q : y1, dim ? x0 + len : q, dim ? q : y1 - len);
          } else if (pass == 0 ? m > 1 && a->hi - a->lo <= 8 : m == 1 && k > a->lo && k < a->hi) {
            fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\"/>\n", dim ? x0 : q,
                    dim ? q : y0, dim ? x1 : q, dim ? q : y1, pass == 0 ? "#eeeeee" : "#d0d0d0");
          }
        }
    }
  fputs("</g>\n", f);
  fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#000\"/>\n", x0, y0,
          x1 - x0, y1 - y0);
  for (int dim = 0; dim < 2; ++dim) {
    const axis *a = dim ? &ay : &ax;
    int every = a->hi - a->lo > 8 ? 2 : 1;
    for (int k = a->lo; k <= a->hi; ++k) {
      if ((k - a->lo) % every) continue;
      double q = axis_pos(a, pow(10.0, k));
      if (dim) tick_label(f, a, k, x0 - 6.0, q + 4.0, "end");
      else tick_label(f, a, k, q, y1 + 17.0, "middle");
    }
  }
  if (p->xlabel) {
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">", 0.5 * (x0 + x1), y1 + 37.0);
    put_text(f, p->xlabel);
    fputs("</text>\n", f);
  }
  if (p->ylabel) {
    double cx = ox + 16.0, cy = 0.5 * (y0 + y1);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">", cx, cy, cx,
            cy);
    put_text(f, p->ylabel);
    fputs("</text>\n", f);
  }

  /* series: lines (broken at unplottable points, clipped to the frame),
   * markers, annotations */
  fprintf(f, "<g clip-path=\"url(#clip%d)\">\n", id);
  for (int s = 0; s < p->n_series; ++s) {
    const svgp_series *se = &p->series[s];
    const char *c = colour_of(se, s);
    int open = 0;
    for (int i = 0; i < se->n; ++i) {
      if (!plottable(se->x[i], se->y[i])) {
        if (open) fputs("\"/>\n", f);
        open = 0;
        continue;
      }
      if (!open)
        fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.6\"%s points=\"", c,
                se->dashed ? " stroke-dasharray=\"5 3\"" : "");
      fprintf(f, "%s%.2f,%.2f", open ? " " : "", axis_pos(&ax, se->x[i]), axis_pos(&ay, se->y[i]));
      open = 1;
    }
    if (open) fputs("\"/>\n", f);
  }
  fputs("</g>\n", f);
  for (int s = 0; s < p->n_series; ++s) /* unclipped: a point on the frame keeps its whole marker */
    for (int i = 0; i < p->series[s].n; ++i) {
      const svgp_series *se = &p->series[s];
      if (plottable(se->x[i], se->y[i]))
        marker(f, se->marker, axis_pos(&ax, se->x[i]), axis_pos(&ay, se->y[i]), colour_of(se, s));
    }
  fputs("<g font-size=\"10\" fill=\"#333\">\n", f);
  for (int s = 0; s < p->n_series; ++s) {
    const svgp_series *se = &p->series[s];
    if (!se->labels) continue;
    for (int i = 0; i < se->n; ++i) {
      if (!se->labels[i] || !plottable(se->x[i], se->y[i])) continue;
      /* above right of the point; left of it near the right edge, below it
       * near the top */
      double px = axis_pos(&ax, se->x[i]), py = axis_pos(&ay, se->y[i]);
      int left = px + 6.0 + text_width(se->labels[i], 10.0) > x1;
      fprintf(f, "<text x=\"%.1f\" y=\"%.1f\"%s>", left ? px - 6.0 : px + 6.0, py - 6.0 < y0 + 12.0 ? py + 14.0 : py - 6.0,
              left ? " text-anchor=\"end\"" : "");
      put_text(f, se->labels[i]);
      fputs("</text>\n", f);
    }
  }
  fputs("</g>\n", f);

  /* legend */
  int entries = 0;
  double lw = 0.0;
  for (int s = 0; s < p->n_series; ++s)
    if (p->series[s].name) ++entries, lw = fmax(lw, text_width(p->series[s].name, 11.0));
  if (entries && p->legend != SVGP_NO_LEGEND) {
    const double row = 16.0, bw = lw + 44.0, bh = entries * row + 8.0;
    int left = p->legend == SVGP_TOP_LEFT || p->legend == SVGP_BOTTOM_LEFT;
    int top = p->legend == SVGP_TOP_LEFT || p->legend == SVGP_TOP_RIGHT;
    double bx = left ? x0 + 8.0 : x1 - 8.0 - bw, by = top ? y0 + 8.0 : y1 - 8.0 - bh;
    fprintf(f,
            "<g font-size=\"11\">\n<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fff\" "
            "fill-opacity=\"0.9\" stroke=\"#999\"/>\n",
            bx, by, bw, bh);
    int r = 0;
    for (int s = 0; s < p->n_series; ++s) {
      const svgp_series *se = &p->series[s];
      if (!se->name) continue;
      const char *c = colour_of(se, s);
      double yy = by + 4.0 + row * (r++ + 0.5);
      fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.6\"%s/>\n",
              bx + 6.0, yy, bx + 30.0, yy, c, se->dashed ? " stroke-dasharray=\"5 3\"" : "");
      marker(f, se->marker, bx + 18.0, yy, c);
      fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", bx + 36.0, yy + 4.0);
      put_text(f, se->name);
      fputs("</text>\n", f);
    }
    fputs("</g>\n", f);
  }
  fputs("</g>\n", f);
  return 0;
}

int svgp_write(const char *path, const svgp_figure *fig) {
  if (!path || !fig || fig->n_panels <= 0 || !fig->panels) {
    errno = EINVAL;
    return -1;
  }
  const double pw = fig->panel_width > 0 ? fig->panel_width : 400, ph = fig->panel_height > 0 ? fig->panel_height : 330;
  int note_lines = 0;
  if (fig->note) {
    note_lines = 1;
    for (const char *p = fig->note; (p = strchr(p, '\n')); ++p) ++note_lines;
  }
  const double top = fig->title ? FIG_TITLE : 0, bottom = note_lines ? 8.0 + 14.0 * note_lines : 0;
  const int cols = fig->columns > 0 && fig->columns < fig->n_panels ? fig->columns : fig->n_panels;
  const int rows = (fig->n_panels + cols - 1) / cols;
  const double W = pw * cols, H = top + ph * rows + bottom;
  FILE *f = fopen(path, "w");
  if (!f) return -1;
  fprintf(f,
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
          "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" "
          "font-size=\"12\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n",
          W, H, W, H);
  if (fig->title) {
    fprintf(f, "<text x=\"%.1f\" y=\"20\" text-anchor=\"middle\" font-weight=\"bold\" font-size=\"15\">", 0.5 * W);
    put_text(f, fig->title);
    fputs("</text>\n", f);
  }
  int rc = 0;
  for (int k = 0; k < fig->n_panels && !rc; ++k)
    rc = panel(f, &fig->panels[k], k, (k % cols) * pw, top + (k / cols) * ph, pw, ph);
  for (int l = 0; l < note_lines && !rc; ++l) {
    fprintf(f, "<text x=\"10\" y=\"%.1f\" font-size=\"11\" fill=\"#444\">", top + ph * rows + 15.0 + 14.0 * l);
    const char *p = fig->note;
    for (int k = 0; k < l; ++k) p = strchr(p, '\n') + 1;
    size_t len = strcspn(p, "\n");
    char line[1024];
    snprintf(line, sizeof line, "%.*s", (int)(len < sizeof line ? len : sizeof line - 1), p);
    put_text(f, line);
    fputs("</text>\n", f);
  }
  fputs("</svg>\n", f);
  int werr = ferror(f);
  if (fclose(f) || werr) return -1;
  if (rc) {
    remove(path);
    errno = EINVAL;
    return -1;
  }
  return 0;
}
