/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A reader of the PNG files sluice writes, for the tests: it checks the
 * signature, every chunk's CRC-32 (bit by bit, not zlib's table), the IHDR
 * fields, the zlib header, inflates the image data with zlib's uncompress
 * (which checks the blocks and the Adler-32 trailer), checks the trailer
 * again bit by bit and returns the RGB pixels. Only what the encoder writes
 * is accepted: 8-bit RGB, filter type 0 on every row. */
#ifndef SLUICE_TESTS_BENCH_PNG_CHECK_H
#define SLUICE_TESTS_BENCH_PNG_CHECK_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static uint32_t pc_crc32(const unsigned char *p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

static uint32_t pc_adler32(const unsigned char *p, size_t n) {
  uint32_t a = 1, b = 0;
  for (size_t i = 0; i < n; ++i) a = (a + p[i]) % 65521u, b = (b + a) % 65521u;
  return b << 16 | a;
}

static uint32_t pc_be32(const unsigned char *p) {
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Returns NULL on success with *rgb (malloc'ed, w x h x 3), else what is wrong. */
static const char *png_check(const unsigned char *png, size_t len, int *w, int *h, unsigned char **rgb) {
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  *rgb = NULL;
  if (len < 8 || memcmp(png, sig, 8)) return "bad signature";
  unsigned char *z = NULL;
  size_t zn = 0, at = 8;
  int seen_ihdr = 0, seen_iend = 0;
  while (at < len) {
    if (len - at < 12) return "truncated chunk";
    uint32_t n = pc_be32(png + at);
    if (n > len - at - 12) return "chunk longer than the file";
    const unsigned char *type = png + at + 4, *data = png + at + 8;
    if (pc_crc32(type, n + 4) != pc_be32(data + n)) return "chunk CRC mismatch";
    if (!memcmp(type, "IHDR", 4)) {
      if (at != 8 || n != 13) return "IHDR not first or not 13 bytes";
      *w = (int)pc_be32(data), *h = (int)pc_be32(data + 4);
      if (*w < 1 || *h < 1 || data[8] != 8 || data[9] != 2 || data[10] || data[11] || data[12]) return "IHDR fields";
      seen_ihdr = 1;
    } else if (!memcmp(type, "IDAT", 4)) {
      unsigned char *nz = realloc(z, zn + n + 1);
      if (!nz) return free(z), "out of memory";
      z = nz;
      memcpy(z + zn, data, n);
      zn += n;
    } else if (!memcmp(type, "IEND", 4)) {
      if (n != 0 || at + 12 != len) return "IEND not empty or not last";
      seen_iend = 1;
    }
    at += 12 + n;
  }
  if (!seen_ihdr || !seen_iend || !z) return free(z), "missing IHDR, IDAT or IEND";
  /* zlib: CM 8, a header that is a multiple of 31, no preset dictionary */
  if (zn < 6 || (z[0] & 0x0F) != 8 || (z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20)) return free(z), "zlib header";
  size_t row = 3 * (size_t)*w + 1, raw_n = row * (size_t)*h, got = 0, p = 2;
  unsigned char *raw = malloc(raw_n);
  if (!raw) return free(z), "out of memory";
  /* zlib's inflate: the deflate blocks of any type, the window, the Adler-32 trailer */
  uLongf got_z = (uLongf)raw_n;
  int zrc = uncompress(raw, &got_z, z, (uLong)zn);
  if (zrc != Z_OK)
    return free(z), free(raw), zrc == Z_BUF_ERROR ? "more image data than the image holds" : "bad zlib stream";
  got = (size_t)got_z, p = zn - 4;
  if (got != raw_n) return free(z), free(raw), "image data of the wrong size";
  if (p + 4 != zn) return free(z), free(raw), "data after the Adler-32 trailer";
  if (pc_be32(z + p) != pc_adler32(raw, raw_n)) return free(z), free(raw), "Adler-32 mismatch";
  free(z);
  *rgb = malloc(raw_n);
  if (!*rgb) return free(raw), "out of memory";
  for (int y = 0; y < *h; ++y) {
    if (raw[(size_t)y * row] != 0) return free(raw), free(*rgb), *rgb = NULL, "row filter is not 0";
    memcpy(*rgb + (size_t)y * (row - 1), raw + (size_t)y * row + 1, row - 1);
  }
  free(raw);
  return NULL;
}

/* Reads a file and checks it. */
static const char *png_check_file(const char *path, int *w, int *h, unsigned char **rgb) {
  FILE *f = fopen(path, "rb");
  if (!f) return "cannot open the file";
  unsigned char *buf = NULL;
  size_t n = 0, cap = 0;
  for (;;) {
    if (n == cap) {
      cap = cap ? 2 * cap : 1 << 16;
      unsigned char *nb = realloc(buf, cap);
      if (!nb) return free(buf), fclose(f), "out of memory";
      buf = nb;
    }
    size_t k = fread(buf + n, 1, cap - n, f);
    n += k;
    if (k == 0) break;
  }
  fclose(f);
  const char *why = png_check(buf, n, w, h, rgb);
  free(buf);
  return why;
}

#endif
