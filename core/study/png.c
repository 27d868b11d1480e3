/* SPDX-License-Identifier: GPL-2.0-or-later */
/* PNG encoder over zlib (see png.h). */
#include "core/study/png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

uint32_t sl_crc32(uint32_t crc, const unsigned char *p, size_t n) {
  uLong c = crc;
  while (n > 0) { /* zlib takes uInt lengths */
    uInt k = n > 0x40000000u ? 0x40000000u : (uInt)n;
    c = crc32(c, p, k), p += k, n -= k;
  }
  return (uint32_t)c;
}

uint32_t sl_adler32(uint32_t adler, const unsigned char *p, size_t n) {
  uLong a = adler;
  while (n > 0) {
    uInt k = n > 0x40000000u ? 0x40000000u : (uInt)n;
    a = adler32(a, p, k), p += k, n -= k;
  }
  return (uint32_t)a;
}

static void put32(unsigned char *q, uint32_t v) {
  q[0] = (unsigned char)(v >> 24), q[1] = (unsigned char)(v >> 16), q[2] = (unsigned char)(v >> 8),
  q[3] = (unsigned char)v;
}

/* A chunk of n data bytes at q: length, type, data (already at q + 8), CRC. */
static size_t chunk(unsigned char *q, const char *type, size_t n) {
  put32(q, (uint32_t)n);
  memcpy(q + 4, type, 4);
  put32(q + 8 + n, sl_crc32(0, q + 4, n + 4));
  return n + 12;
}

int sl_png_encode(const unsigned char *rgb, int w, int h, unsigned char **png, size_t *len) {
  *png = NULL, *len = 0;
  if (w < 1 || h < 1 || w > (1 << 24) || h > (1 << 24)) return -1;
  size_t row = 3 * (size_t)w + 1, raw_n = row * (size_t)h;
  if (raw_n / row != (size_t)h || raw_n > 0xFFFFFFFFu / 2) return -1;
  unsigned char *raw = malloc(raw_n);
  uLong bound = compressBound((uLong)raw_n);
  unsigned char *out = malloc(8 + 25 + 12 + bound + 12);
  if (!raw || !out) return free(raw), free(out), -1;
  for (int y = 0; y < h; ++y) { /* filter type 0 (None) on every row */
    raw[(size_t)y * row] = 0;
    memcpy(raw + (size_t)y * row + 1, rgb + (size_t)y * (row - 1), row - 1);
  }
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  memcpy(out, sig, 8);
  size_t at = 8;
  unsigned char *ihdr = out + at + 8;
  put32(ihdr, (uint32_t)w), put32(ihdr + 4, (uint32_t)h);
  ihdr[8] = 8, ihdr[9] = 2,
  ihdr[10] = ihdr[11] = ihdr[12] = 0; /* 8 bits, RGB, deflate, adaptive filters, no interlace */
  at += chunk(out + at, "IHDR", 13);
  uLongf zn = bound;
  int zrc = compress2(out + at + 8, &zn, raw, (uLong)raw_n, Z_BEST_COMPRESSION); /* a zlib stream (RFC 1950) */
  free(raw);
  if (zrc != Z_OK) return free(out), -1;
  at += chunk(out + at, "IDAT", (size_t)zn);
  at += chunk(out + at, "IEND", 0);
  *png = out, *len = at;
  return 0;
}

int sl_png_write(const char *path, const unsigned char *rgb, int w, int h, sl_diag *d) {
  unsigned char *png;
  size_t len;
  if (sl_png_encode(rgb, w, h, &png, &len))
    return sl_diag_set(d, SL_EFAILED, "%s: cannot encode a %d x %d image", path, w, h);
  FILE *f = fopen(path, "wb");
  if (!f) {
    int e = errno;
    free(png);
    return sl_diag_set(d, SL_EFAILED, "%s: %s", path, strerror(e));
  }
  size_t wrote = fwrite(png, 1, len, f);
  int bad = wrote != len || ferror(f);
  bad |= fclose(f) != 0;
  free(png);
  if (bad) {
    remove(path);
    return sl_diag_set(d, SL_EFAILED, "%s: write failed", path);
  }
  return 0;
}
