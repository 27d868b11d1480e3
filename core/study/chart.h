/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A line chart rendered to an RGB image and written as PNG: one panel with
 * linear or logarithmic axes, ticks and tick labels, axis titles, a title
 * and subtitle, series drawn as markers joined by lines (colour and marker
 * by position), optional labels beside the points, and a legend in the
 * corner where it hides the fewest points.
 *
 * Points with a non-finite coordinate, or a non-positive one on a log axis,
 * are left out; a series' line breaks there. A chart with no plottable
 * point is still drawn (frame and a note saying so). */
#ifndef SLUICE_PLOT_CHART_H
#define SLUICE_PLOT_CHART_H

#include "core/study/image.h"
#include "core/util/diag.h"

typedef enum sl_axis_scale { SL_AXIS_LINEAR, SL_AXIS_LOG } sl_axis_scale;

typedef struct sl_chart_series {
  const char *name; /* legend entry; NULL: not in the legend */
  int n;
  const double *x, *y;
  const char *const *labels; /* beside each point, or NULL (entries may be NULL) */
  int dashed;
  int marker_every, marker_offset; /* markers on points offset, offset + every, ... (every 0 or 1: all) */
} sl_chart_series;

typedef struct sl_chart {
  const char *title, *subtitle, *xlabel, *ylabel, *note; /* each may be NULL; note: small print at the bottom */
  sl_axis_scale xscale, yscale;
  int n_series;
  const sl_chart_series *series;
} sl_chart;

/* The colour of series k (0xRRGGBB), as the legend shows it. */
uint32_t sl_chart_colour(int k);

/* Draws the chart into im (allocated here, w x h; free with sl_image_free). */
int sl_chart_draw(const sl_chart *c, int w, int h, sl_image *im, sl_diag *d);
/* Draws it and writes a PNG file. */
int sl_chart_write_png(const char *path, const sl_chart *c, int w, int h, sl_diag *d);

#endif
