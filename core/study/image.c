/* SPDX-License-Identifier: GPL-2.0-or-later */
/* RGB raster drawing (see image.h). */
#include "core/study/image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int sl_image_init(sl_image *im, int w, int h, uint32_t background) {
  im->w = im->h = 0;
  im->rgb = NULL;
  if (w < 1 || h < 1 || w > 16384 || h > 16384) return -1;
  im->rgb = malloc((size_t)w * (size_t)h * 3);
  if (!im->rgb) return -1;
  im->w = w, im->h = h;
  sl_image_fill(im, 0, 0, w - 1, h - 1, background);
  return 0;
}

void sl_image_free(sl_image *im) {
  free(im->rgb);
  im->rgb = NULL;
  im->w = im->h = 0;
}

void sl_image_set(sl_image *im, int x, int y, uint32_t colour) {
  if (x < 0 || y < 0 || x >= im->w || y >= im->h) return;
  unsigned char *p = im->rgb + 3 * ((size_t)y * (size_t)im->w + (size_t)x);
  p[0] = (unsigned char)(colour >> 16), p[1] = (unsigned char)(colour >> 8), p[2] = (unsigned char)colour;
}

uint32_t sl_image_get(const sl_image *im, int x, int y) {
  if (x < 0 || y < 0 || x >= im->w || y >= im->h) return 0;
  const unsigned char *p = im->rgb + 3 * ((size_t)y * (size_t)im->w + (size_t)x);
  return (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
}

void sl_image_fill(sl_image *im, int x0, int y0, int x1, int y1, uint32_t colour) {
  if (x0 > x1) {
    int t = x0;
    x0 = x1, x1 = t;
  }
  if (y0 > y1) {
    int t = y0;
    y0 = y1, y1 = t;
  }
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 >= im->w) x1 = im->w - 1;
  if (y1 >= im->h) y1 = im->h - 1;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) sl_image_set(im, x, y, colour);
}

static void pen(sl_image *im, int x, int y, int width, uint32_t colour) {
  int lo = -(width - 1) / 2, hi = width / 2;
  sl_image_fill(im, x + lo, y + lo, x + hi, y + hi, colour);
}

void sl_image_line(sl_image *im, double x0, double y0, double x1, double y1, int width, uint32_t colour, int dash) {
  if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1)) return;
  /* far outside the image: nothing to draw, and the step count stays bounded */
  double big = 4.0 * (im->w + im->h);
  if (fabs(x0) > big || fabs(x1) > big || fabs(y0) > big || fabs(y1) > big) return;
  if (width < 1) width = 1;
  double dx = x1 - x0, dy = y1 - y0;
  int steps = (int)ceil(fmax(fabs(dx), fabs(dy)));
  if (steps < 1) steps = 1;
  double length = hypot(dx, dy);
  for (int k = 0; k <= steps; ++k) {
    double f = (double)k / steps;
    if (dash > 0 && (int)floor(f * length / dash) % 2 == 1) continue;
    pen(im, (int)lround(x0 + f * dx), (int)lround(y0 + f * dy), width, colour);
  }
}

void sl_image_marker(sl_image *im, double x, double y, sl_marker m, int r, uint32_t colour) {
  if (!isfinite(x) || !isfinite(y)) return;
  int cx = (int)lround(x), cy = (int)lround(y);
  if (m == SL_MARK_CROSS) {
    sl_image_line(im, cx - r, cy - r, cx + r, cy + r, 2, colour, 0);
    sl_image_line(im, cx - r, cy + r, cx + r, cy - r, 2, colour, 0);
    return;
  }
  for (int v = -r; v <= r; ++v)
    for (int u = -r; u <= r; ++u) {
      int in;
      switch (m) {
        case SL_MARK_SQUARE:
          in = 1;
          break;
        case SL_MARK_DIAMOND:
          in = abs(u) + abs(v) <= r;
          break;
        case SL_MARK_TRIANGLE:
          in = 2 * abs(u) <= v + r;
          break; /* apex up: v = -r at the apex */
        default:
          in = u * u + v * v <= r * r + r;
          break;
      }
      if (in) sl_image_set(im, cx + u, cy + v, colour);
    }
}
