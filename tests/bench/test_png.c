/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The PNG encoder, the bitmap font and the chart (core/study/): checksums
 * against their published check values, encoded images read back by an
 * independent reader and inflater (tests/bench/png_check.h) pixel for
 * pixel, for data with few repeats, one colour, stripes and a row longer
 * than the deflate window, the compression of plots, and a chart whose
 * series land in the image. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/png_check.h"
#include "core/study/chart.h"
#include "core/study/font.h"
#include "core/study/png.h"
#include "testing.h"

/* Check values: CRC-32 of "123456789" is 0xCBF43926 (the catalogue's "check"
 * of CRC-32/ISO-HDLC); Adler-32 of "Wikipedia" is 0x11E60398 (RFC 1950's
 * definition worked by hand: a = 920 = 0x398, b = 4582 = 0x11E6). */
static void checksums(void) {
  const unsigned char *digits = (const unsigned char *)"123456789", *wiki = (const unsigned char *)"Wikipedia";
  CHECK(sl_crc32(0, digits, 9) == 0xCBF43926u);
  CHECK(sl_crc32(sl_crc32(0, digits, 4), digits + 4, 5) == 0xCBF43926u); /* in pieces */
  CHECK(sl_adler32(1, wiki, 9) == 0x11E60398u);
  CHECK(sl_adler32(sl_adler32(1, wiki, 3), wiki + 3, 6) == 0x11E60398u);
  /* long input: the encoder's modulo every 5552 bytes against the test's every byte */
  enum { N = 100000 };
  unsigned char *p = malloc(N);
  for (int i = 0; i < N; ++i) p[i] = (unsigned char)(255 - i % 7);
  CHECK(sl_adler32(1, p, N) == pc_adler32(p, N));
  CHECK(sl_crc32(0, p, N) == pc_crc32(p, N));
  free(p);
}

/* pattern 0: bytes with little repetition (literals of both code lengths);
 * 1: one colour (matches of the longest length, 258); 2: horizontal
 * stripes of a few rows (matches at the distance of a row). */
static size_t round_trip_pattern(int w, int h, int pattern) {
  unsigned char *img = malloc((size_t)w * (size_t)h * 3);
  for (int i = 0; i < w * h * 3; ++i)
    img[i] = pattern == 0   ? (unsigned char)(i * 37 + i / 11)
             : pattern == 1 ? (unsigned char)200
                            : (unsigned char)(((i / (3 * w)) / 3) % 2 ? 30 + i % 3 : 250);
  unsigned char *png = NULL, *back = NULL;
  size_t len = 0;
  CHECK(sl_png_encode(img, w, h, &png, &len) == 0);
  int rw = 0, rh = 0;
  const char *why = png_check(png, len, &rw, &rh, &back);
  CHECK_MSG(why == NULL, "%d x %d: %s", w, h, why ? why : "");
  CHECK(rw == w && rh == h);
  CHECK_MSG(back && memcmp(back, img, (size_t)w * (size_t)h * 3) == 0, "%d x %d: pixels differ", w, h);
  size_t raw = (size_t)(3 * w + 1) * (size_t)h;
  /* signature, IHDR, IDAT (zlib header, at most 9 bits a byte, Adler-32), IEND */
  CHECK_MSG(len <= 8 + 25 + 12 + 2 + raw + raw / 8 + 3 + 4 + 12, "%d x %d: %zu bytes", w, h, len);
  /* a corrupted byte is caught by the chunk CRC */
  png[len / 2] ^= 0x40;
  unsigned char *bad = NULL;
  CHECK(png_check(png, len, &rw, &rh, &bad) != NULL);
  free(bad);
  free(back), free(png), free(img);
  return len;
}

static void round_trip(int w, int h) { round_trip_pattern(w, h, 0); }

static void encoder(void) {
  round_trip(1, 1);
  round_trip(7, 5);
  round_trip(200, 120); /* 72,120 raw bytes */
  round_trip(21845, 1); /* one row of 65,536 bytes: matches reach across the 32 KiB window */
  /* one colour and stripes: the repeats compress (a 300 x 200 image holds 180,200 raw bytes) */
  size_t flat = round_trip_pattern(300, 200, 1), stripes = round_trip_pattern(300, 200, 2);
  printf("png: 300 x 200, one colour %zu bytes, stripes %zu bytes (raw 180200)\n", flat, stripes);
  CHECK_MSG(flat < 2000 && stripes < 4000, "one colour %zu bytes, stripes %zu", flat, stripes);
  unsigned char *png = NULL;
  size_t len = 0;
  unsigned char px[3] = {0, 0, 0};
  CHECK(sl_png_encode(px, 0, 1, &png, &len) == -1 && png == NULL);
  sl_diag d = {{0}};
  CHECK(sl_png_write("no_such_folder/x.png", px, 1, 1, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "no_such_folder/x.png");
}

static void font(void) {
  /* '1': a vertical stroke with a foot; 'g' reaches the descender row */
  CHECK(sl_font_row('1', 0) == 0x04 && sl_font_row('1', 6) == 0x0E);
  CHECK(sl_font_row('g', 7) != 0 && sl_font_row('A', 7) == 0);
  CHECK(sl_font_row('\t', 0) == sl_font_row('?', 0));
  int blank = 0;
  for (int r = 0; r < SL_FONT_H; ++r) blank |= sl_font_row(' ', r);
  CHECK(blank == 0);
  for (char ch = '!'; ch <= '~'; ++ch) {
    unsigned any = 0;
    for (int r = 0; r < SL_FONT_H; ++r) {
      any |= sl_font_row(ch, r);
      CHECK(sl_font_row(ch, r) < 32u);
    }
    CHECK_MSG(any != 0, "glyph '%c' is empty", ch);
  }
  CHECK(sl_font_width("abc", 2) == (3 * SL_FONT_ADVANCE - 1) * 2);
  sl_image im;
  CHECK(sl_image_init(&im, 40, 20, 0xFFFFFF) == 0);
  sl_font_draw(&im, 1, 1, "1", 1, 0x000000, 0);
  CHECK(sl_image_get(&im, 3, 1) == 0 && sl_image_get(&im, 1, 1) == 0xFFFFFF); /* the top of the stroke */
  sl_image_free(&im);
}

static int count_colour(const sl_image *im, uint32_t c) {
  int n = 0;
  for (int y = 0; y < im->h; ++y)
    for (int x = 0; x < im->w; ++x) n += sl_image_get(im, x, y) == c;
  return n;
}

static void chart(void) {
  const double x[4] = {0.01, 0.1, 1.0, 10.0}, y1[4] = {1e-2, 3e-3, 1e-3, 3e-4}, y2[4] = {5e-3, NAN, -1.0, 1e-4};
  sl_chart_series s[2] = {{.name = "first", .n = 4, .x = x, .y = y1},
                          {.name = "second", .n = 4, .x = x, .y = y2, .dashed = 1}};
  sl_chart c = {.title = "Title",
                .subtitle = "line one\nline two",
                .xlabel = "CPU time (s)",
                .ylabel = "error",
                .xscale = SL_AXIS_LOG,
                .yscale = SL_AXIS_LOG,
                .n_series = 2,
                .series = s};
  sl_image im;
  sl_diag d = {{0}};
  CHECK(sl_chart_draw(&c, 640, 480, &im, &d) == 0);
  CHECK(count_colour(&im, sl_chart_colour(0)) > 200); /* markers and lines of both series are drawn */
  CHECK(count_colour(&im, sl_chart_colour(1)) > 50);
  sl_image_free(&im);
  CHECK(sl_chart_write_png("chart.png", &c, 640, 480, &d) == 0);
  int w, h;
  unsigned char *rgb = NULL;
  const char *why = png_check_file("chart.png", &w, &h, &rgb);
  CHECK_MSG(why == NULL && w == 640 && h == 480, "chart.png: %s", why ? why : "size");
  FILE *f = fopen("chart.png", "rb");
  long bytes = -1;
  if (f && fseek(f, 0, SEEK_END) == 0) bytes = ftell(f);
  if (f) fclose(f);
  printf("png: a 640 x 480 chart in %ld bytes (raw 922080)\n", bytes);
  CHECK_MSG(bytes > 0 && bytes < 922080 / 20, "chart.png: %ld bytes", bytes); /* a plot is mostly background */
  free(rgb);
  /* nothing plottable: still a figure */
  const double bad[1] = {-1.0};
  sl_chart_series e = {.name = "none", .n = 1, .x = bad, .y = bad};
  sl_chart empty = {.xscale = SL_AXIS_LOG, .yscale = SL_AXIS_LOG, .n_series = 1, .series = &e};
  CHECK(sl_chart_draw(&empty, 300, 200, &im, &d) == 0);
  sl_image_free(&im);
  CHECK(sl_chart_draw(&c, 100, 100, &im, &d) == SL_EBADINPUT);
}

int main(void) {
  checksums();
  encoder();
  font();
  chart();
  return sl_test_summary();
}
