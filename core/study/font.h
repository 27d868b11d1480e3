/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A built-in 5 x 8 bitmap font (printable ASCII and a few Greek letters
 * and signs: 7 rows for capitals and
 * digits, the 8th for descenders) to label plots without a font library. */
#ifndef SLUICE_PLOT_FONT_H
#define SLUICE_PLOT_FONT_H

#include <stdint.h>

#include "core/study/image.h"

enum { SL_FONT_W = 5, SL_FONT_H = 8, SL_FONT_ADVANCE = 6 }; /* pixels at scale 1; advance includes the gap */

/* Row r (0 top .. 7) of character ch as 5 bits, the leftmost in bit 4.
 * Characters outside printable ASCII show as '?'. */
unsigned sl_font_row(char ch, int r);

/* Row r of the glyph of Unicode code point cp: printable ASCII, and the few
 * Greek letters and signs labels use (phi, rho, mu, tau, epsilon, theta,
 * psi, nu, gamma, omega, Delta, minus, times, middle dot, squared, cubed,
 * degree, en dash, almost equal, proportional to); '?' for anything else. */
unsigned sl_font_row_cp(uint32_t cp, int r);
/* The code point at *s (UTF-8), advancing *s past it; '?' for a bad byte. */
uint32_t sl_utf8_next(const char **s);

/* Width and height in pixels of text drawn at an integer scale. */
int sl_font_width(const char *text, int scale);
int sl_font_height(int scale);

/* Draws text with its top-left corner at (x, y). vertical: turned a quarter
 * turn anticlockwise, reading upwards from y; the glyphs' tops face left,
 * so the text covers x .. x + height - 1 and y - width + 1 .. y. */
void sl_font_draw(sl_image *im, int x, int y, const char *text, int scale, uint32_t colour, int vertical);

#endif
