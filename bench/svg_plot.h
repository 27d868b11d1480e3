/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A small SVG writer for the benchmarks' plots: one figure of panels in a
 * grid (row by row), each a log-log plot of series drawn as markers joined by lines,
 * with decade ticks and labels (minor ticks at 2..9), grid, axis titles,
 * optional point annotations and a legend.
 *
 * Points with a non-finite or non-positive coordinate cannot be placed on a
 * log axis: they are left out and the series' line breaks there. */
#ifndef SLUICE_BENCH_SVG_PLOT_H
#define SLUICE_BENCH_SVG_PLOT_H

typedef enum svgp_marker { SVGP_CIRCLE, SVGP_SQUARE, SVGP_TRIANGLE, SVGP_DIAMOND } svgp_marker;

typedef enum svgp_corner { SVGP_NO_LEGEND, SVGP_TOP_LEFT, SVGP_TOP_RIGHT, SVGP_BOTTOM_LEFT, SVGP_BOTTOM_RIGHT } svgp_corner;

typedef struct svgp_series {
  const char *name; /* legend entry; NULL: not in the legend */
  int n;
  const double *x, *y;
  const char *const *labels; /* an annotation beside each point, or NULL (entries may be NULL) */
  const char *colour;        /* any SVG colour; NULL: a default by position */
  svgp_marker marker;
  int dashed;
} svgp_series;

typedef struct svgp_panel {
  const char *title, *xlabel, *ylabel; /* each may be NULL */
  int n_series;
  const svgp_series *series;
  svgp_corner legend;
  double xspan[2], yspan[2]; /* values the axes must also cover (e.g. to share
                                a range between panels); 0, 0: the data only */
} svgp_panel;

typedef struct svgp_figure {
  const char *title; /* above the panels; may be NULL */
  const char *note;  /* small print below them, lines separated by '\n'; may be NULL */
  int n_panels;
  const svgp_panel *panels;
  int columns;                   /* panels per row; 0: all in one row */
  int panel_width, panel_height; /* pixels; 0 takes 400 x 330 */
} svgp_figure;

/* Writes the figure to path. Returns 0, or -1 with errno set (a panel without
 * a single plottable point is EINVAL). */
int svgp_write(const char *path, const svgp_figure *f);

#endif
