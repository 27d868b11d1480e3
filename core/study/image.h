/* SPDX-License-Identifier: GPL-2.0-or-later */
/* An RGB image in memory and the few drawing operations plots need:
 * filled rectangles, lines of a given width (solid or dashed) and markers.
 * Colours are 0xRRGGBB; pixel (0, 0) is the top-left corner; anything drawn
 * outside the image is clipped. */
#ifndef SLUICE_PLOT_IMAGE_H
#define SLUICE_PLOT_IMAGE_H

#include <stdint.h>

typedef struct sl_image {
  int w, h;
  unsigned char *rgb; /* w x h x 3, rows top to bottom */
} sl_image;

/* Allocates the image filled with `background`. Returns 0 or -1. */
int sl_image_init(sl_image *im, int w, int h, uint32_t background);
void sl_image_free(sl_image *im);

void sl_image_set(sl_image *im, int x, int y, uint32_t colour);
uint32_t sl_image_get(const sl_image *im, int x, int y); /* 0 outside */
/* The rectangle [x0, x1] x [y0, y1], corners included, in either order. */
void sl_image_fill(sl_image *im, int x0, int y0, int x1, int y1, uint32_t colour);
/* A straight line between pixel centres, `width` pixels wide (square pen).
 * dash > 0: drawn `dash` pixels, skipped `dash`, from the start. */
void sl_image_line(sl_image *im, double x0, double y0, double x1, double y1, int width, uint32_t colour, int dash);

typedef enum sl_marker {
  SL_MARK_CIRCLE,
  SL_MARK_SQUARE,
  SL_MARK_TRIANGLE,
  SL_MARK_DIAMOND,
  SL_MARK_CROSS,
  SL_MARK_COUNT
} sl_marker;
/* A filled marker of radius r pixels centred at (x, y) (a cross is drawn with lines). */
void sl_image_marker(sl_image *im, double x, double y, sl_marker m, int r, uint32_t colour);

#endif
