/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The plots of sluice bench and of the benchmark programs: line charts, one
 * panel or a figure of panels in a grid, written as SVG (vector, real text)
 * or as PNG (rasterised here, anti-aliased by supersampling, compressed
 * by zlib; png.h). Both go through the same layout, so the two files show
 * the same axes, ticks, labels and legend.
 *
 * A panel has linear or logarithmic axes fitted to the data (a margin of 4 %
 * of the span each side; log axes ticked at the decades with minor ticks at
 * 2..9, labelled as powers of ten or plain decimals), tick labels, axis
 * titles, series drawn as markers joined by lines, optional labels beside
 * the points, optional reference slopes (a triangle whose hypotenuse has
 * the least-squares slope of a series' last points, labelled with it) and
 * a legend in the corner where it hides the fewest points.
 *
 * Text (titles, axis titles, legend entries, labels) is UTF-8 with two
 * marks: "^{...}" raises its contents as a superscript and "_{...}" lowers
 * them as a subscript ("10^{-4}", "u_{z}"); a '-' inside a superscript is
 * shown as the minus sign. The PNG's bitmap font knows printable ASCII and
 * the Greek letters and signs font.h lists.
 *
 * Points with a non-finite coordinate, or a non-positive one on a log axis,
 * are left out; a series' line breaks there. A panel with no plottable
 * point is still drawn (frame and a note saying so). */
#ifndef SLUICE_PLOT_CHART_H
#define SLUICE_PLOT_CHART_H

#include <stdint.h>

#include "core/study/image.h"
#include "core/util/diag.h"

typedef enum sl_axis_scale { SL_AXIS_LINEAR, SL_AXIS_LOG } sl_axis_scale;

typedef enum sl_legend_place {
  SL_LEGEND_AUTO, /* the corner that hides the fewest points */
  SL_LEGEND_NONE,
  SL_LEGEND_TOP_LEFT,
  SL_LEGEND_TOP_RIGHT,
  SL_LEGEND_BOTTOM_LEFT,
  SL_LEGEND_BOTTOM_RIGHT
} sl_legend_place;

typedef enum sl_chart_marker {
  SL_CHART_MARK_AUTO, /* by the series' position */
  SL_CHART_MARK_CIRCLE,
  SL_CHART_MARK_SQUARE,
  SL_CHART_MARK_TRIANGLE,
  SL_CHART_MARK_DIAMOND,
  SL_CHART_MARK_CROSS,
  SL_CHART_MARK_NONE
} sl_chart_marker;

typedef struct sl_chart_series {
  const char *name; /* legend entry; NULL: not in the legend */
  int n;
  const double *x, *y;
  const char *const *labels; /* beside each point, or NULL (entries may be NULL) */
  int dashed;
  int marker_every, marker_offset; /* markers on points offset, offset + every, ... (every 0 or 1: all) */
  const char *colour;              /* "#RRGGBB"; NULL: by position (sl_chart_colour) */
  sl_chart_marker marker;
  /* slope_points >= 2 (log-log panels): a reference triangle for the
   * least-squares slope of log y on log x over the last slope_points
   * plottable points, labelled with slope_format (printf, one double;
   * NULL: "slope %.2f") applied to the slope, negated when slope_negate
   * (an error falling as N^-p is "order p"). No triangle for a slope under
   * 0.1 in magnitude, nor for a rising curve when slope_negate. */
  int slope_points;
  const char *slope_format;
  int slope_negate;
} sl_chart_series;

/* A heat map drawn under the series: cell (i, j) spans x_edges[i] ..
 * x_edges[i + 1] by y_edges[j] .. y_edges[j + 1] (nx + 1 and ny + 1 edges,
 * ascending) and is filled with the colour of values[j nx + i] on
 * sl_chart_heat_colour's scale from lo (0) to hi (1), clamped; a non-finite
 * value is left blank. A colour bar right of the panel, titled label, shows
 * the scale. The axes span the edges without margin; no grid is drawn over
 * the map. */
typedef struct sl_chart_heatmap {
  int nx, ny;
  const double *x_edges, *y_edges;
  const double *values;
  double lo, hi;
  const char *label;
} sl_chart_heatmap;

typedef struct sl_chart {
  const char *title, *subtitle, *xlabel, *ylabel, *note; /* each may be NULL; note: small print at the bottom */
  sl_axis_scale xscale, yscale;
  int n_series;
  const sl_chart_series *series;
  sl_legend_place legend;
  double xspan[2], yspan[2]; /* values the axes must also cover (a range shared between panels); unused when equal */
  const sl_chart_heatmap *heatmap; /* or NULL */
} sl_chart;

/* Panels in a grid, row by row, under one title. A panel's title heads it;
 * its subtitle and note are not drawn (the figure's are). */
typedef struct sl_figure {
  const char *title, *subtitle, *note; /* note: small print below the panels, lines split at '\n' */
  int n_panels;
  const sl_chart *panels;
  int columns;                   /* panels a row; 0: all in one row */
  int panel_width, panel_height; /* pixels; 0 takes 480 x 360 */
} sl_figure;

/* The colour of series k (0xRRGGBB), as the legend shows it. */
uint32_t sl_chart_colour(int k);

/* A heat map's colour (0xRRGGBB) for t in [0, 1] (clamped): white, yellow,
 * orange, red, dark red, linear between those five stops at t = 0, 1/4,
 * 1/2, 3/4, 1. Lightness falls monotonically, so the scale reads in grey. */
uint32_t sl_chart_heat_colour(double t);

/* The least-squares slope of log10 y on log10 x over the last `points`
 * plottable points of s (all when points < 2 or more than there are), as the
 * reference triangle shows it. Returns 0, or -1 with fewer than two points
 * or no spread in x. */
int sl_chart_slope(const sl_chart_series *s, int points, double *slope);

/* One chart in w x h pixels: drawn into im (allocated here; free with
 * sl_image_free), or written as PNG or SVG. */
int sl_chart_draw(const sl_chart *c, int w, int h, sl_image *im, sl_diag *d);
int sl_chart_write_png(const char *path, const sl_chart *c, int w, int h, sl_diag *d);
int sl_chart_write_svg(const char *path, const sl_chart *c, int w, int h, sl_diag *d);

/* A figure of panels. Return 0 or an SL_E* code with d set. */
int sl_figure_draw(const sl_figure *f, sl_image *im, sl_diag *d);
int sl_figure_write_png(const char *path, const sl_figure *f, sl_diag *d);
int sl_figure_write_svg(const char *path, const sl_figure *f, sl_diag *d);
/* PNG when path ends in ".png", SVG otherwise. */
int sl_figure_write(const char *path, const sl_figure *f, sl_diag *d);

#endif
