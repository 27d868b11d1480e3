/* SPDX-License-Identifier: GPL-2.0-or-later */
/* An independent reader of the PNG files sluice writes, for the tests: it
 * checks the signature, every chunk's CRC-32 (bit by bit, not the
 * encoder's table), the IHDR fields, the zlib header, the deflate blocks
 * (stored: LEN against NLEN; fixed Huffman codes: decoded from the code
 * ranges of RFC 1951 3.2.6, distances within the data and the window;
 * BFINAL on the last) and the Adler-32 trailer, and returns the RGB pixels.
 * Only what the encoder writes is accepted: 8-bit RGB, filter type 0 on
 * every row, stored or fixed-code blocks. */
#ifndef SLUICE_TESTS_BENCH_PNG_CHECK_H
#define SLUICE_TESTS_BENCH_PNG_CHECK_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* The next n bits, least significant first (deflate's bit order), or -1. */
static int pc_bits(const unsigned char *z, size_t zn, size_t *bit, int n) {
  int v = 0;
  for (int i = 0; i < n; ++i, ++*bit) {
    size_t byte = 2 + *bit / 8;
    if (byte >= zn) return -1;
    v |= ((z[byte] >> (*bit % 8)) & 1) << i;
  }
  return v;
}

/* A Huffman code's next bit: codes are packed most significant bit first. */
static int pc_code_bit(const unsigned char *z, size_t zn, size_t *bit, int code) {
  int b = pc_bits(z, zn, bit, 1);
  return b < 0 ? -1 : code << 1 | b;
}

/* One block of fixed codes, decoded from the code ranges of RFC 1951
 * section 3.2.6 (7 bits 0000000-0010111: 256-279; 8 bits 00110000-10111111:
 * 0-143, 11000000-11000111: 280-287; 9 bits 110010000-111111111: 144-255). */
static const char *pc_inflate_fixed(const unsigned char *z, size_t zn, size_t *bit, unsigned char *out, size_t cap,
                                    size_t *got) {
  static const int lbase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  static const int lext[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  static const int dbase[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                                193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
  static const int dext[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
  for (;;) {
    int code = 0, sym = -1;
    for (int i = 0; i < 7 && code >= 0; ++i) code = pc_code_bit(z, zn, bit, code);
    if (code < 0) return "truncated fixed-code block";
    if (code <= 23) sym = 256 + code;
    else {
      code = pc_code_bit(z, zn, bit, code);
      if (code < 0) return "truncated fixed-code block";
      if (code >= 0x30 && code <= 0xBF) sym = code - 0x30;
      else if (code >= 0xC0 && code <= 0xC7) sym = 280 + code - 0xC0;
      else {
        code = pc_code_bit(z, zn, bit, code);
        if (code < 0x190 || code > 0x1FF) return "bad fixed literal/length code";
        sym = 144 + code - 0x190;
      }
    }
    if (sym < 256) {
      if (*got >= cap) return "more image data than the image holds";
      out[(*got)++] = (unsigned char)sym;
    } else if (sym == 256) {
      return NULL;
    } else {
      if (sym > 285) return "bad length symbol";
      int e = pc_bits(z, zn, bit, lext[sym - 257]), dcode = 0;
      if (e < 0) return "truncated length";
      int length = lbase[sym - 257] + e;
      for (int i = 0; i < 5 && dcode >= 0; ++i) dcode = pc_code_bit(z, zn, bit, dcode);
      if (dcode < 0 || dcode > 29) return "bad distance code";
      int de = pc_bits(z, zn, bit, dext[dcode]);
      if (de < 0) return "truncated distance";
      size_t dist = (size_t)(dbase[dcode] + de);
      if (dist > *got || dist > 32768) return "distance before the start of the data or beyond the window";
      if (*got + (size_t)length > cap) return "more image data than the image holds";
      for (int i = 0; i < length; ++i, ++*got) out[*got] = out[*got - dist];
    }
  }
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
  int final = 0;
  size_t bit = 0; /* position in bits from z + 2 */
  while (!final) {
    p = 2 + (bit + 7) / 8;
    int btype = pc_bits(z, zn, &bit, 3);
    if (btype < 0) return free(z), free(raw), "truncated deflate block";
    final = btype & 1, btype >>= 1;
    if (btype == 0) { /* stored: byte-aligned LEN, NLEN, data */
      p = 2 + (bit + 7) / 8;
      if (p + 4 > zn) return free(z), free(raw), "truncated deflate block";
      unsigned n = (unsigned)z[p] | (unsigned)z[p + 1] << 8, nn = (unsigned)z[p + 2] | (unsigned)z[p + 3] << 8;
      if ((n ^ 0xFFFFu) != nn) return free(z), free(raw), "LEN and NLEN disagree";
      p += 4;
      if (p + n > zn || got + n > raw_n) return free(z), free(raw), "stored block too long";
      memcpy(raw + got, z + p, n);
      p += n, got += n, bit = 8 * (p - 2);
    } else if (btype == 1) { /* the fixed Huffman codes of RFC 1951 3.2.6 */
      const char *why = pc_inflate_fixed(z, zn, &bit, raw, raw_n, &got);
      if (why) return free(z), free(raw), why;
      p = 2 + (bit + 7) / 8;
    } else {
      return free(z), free(raw), "a deflate block type the encoder does not write";
    }
  }
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
