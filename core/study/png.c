/* SPDX-License-Identifier: GPL-2.0-or-later */
/* PNG encoder with a fixed-Huffman deflate stream (see png.h). */
#include "core/study/png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

uint32_t sl_crc32(uint32_t crc, const unsigned char *p, size_t n) {
  static uint32_t table[256];
  static int ready;
  if (!ready) { /* idempotent: two threads racing here write the same values */
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = c & 1u ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
    ready = 1;
  }
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

uint32_t sl_adler32(uint32_t adler, const unsigned char *p, size_t n) {
  enum { MOD = 65521, CHUNK = 5552 }; /* the largest run whose sums cannot overflow 32 bits */
  uint32_t a = adler & 0xFFFFu, b = adler >> 16;
  while (n > 0) {
    size_t k = n < CHUNK ? n : CHUNK;
    n -= k;
    for (size_t i = 0; i < k; ++i) a += *p++, b += a;
    a %= MOD, b %= MOD;
  }
  return b << 16 | a;
}

typedef struct buf {
  unsigned char *p;
  size_t n;
} buf;

static void put32(buf *b, uint32_t v) {
  b->p[b->n++] = (unsigned char)(v >> 24), b->p[b->n++] = (unsigned char)(v >> 16);
  b->p[b->n++] = (unsigned char)(v >> 8), b->p[b->n++] = (unsigned char)v;
}

static void put(buf *b, const void *p, size_t n) {
  memcpy(b->p + b->n, p, n);
  b->n += n;
}

/* Length, type and data are in place from `start`; appends the CRC of type and data. */
static void end_chunk(buf *b, size_t start) {
  size_t len = b->n - start - 8;
  unsigned char *q = b->p + start;
  q[0] = (unsigned char)(len >> 24), q[1] = (unsigned char)(len >> 16), q[2] = (unsigned char)(len >> 8);
  q[3] = (unsigned char)len;
  put32(b, sl_crc32(0, q + 4, len + 4));
}

static size_t begin_chunk(buf *b, const char type[4]) {
  size_t start = b->n;
  b->n += 4; /* the length, filled in by end_chunk */
  put(b, type, 4);
  return start;
}

/* ---- deflate with the fixed Huffman codes (RFC 1951 sections 3.2.5-3.2.6) ---- */

typedef struct bitbuf {
  unsigned char *p;
  size_t n, cap;
  uint32_t acc; /* bits not yet written, least significant first */
  int nacc;
} bitbuf;

static void put_bits(bitbuf *b, uint32_t v, int n) {
  b->acc |= v << b->nacc, b->nacc += n;
  while (b->nacc >= 8) {
    if (b->n < b->cap) b->p[b->n] = (unsigned char)b->acc;
    ++b->n, b->acc >>= 8, b->nacc -= 8;
  }
}

/* A Huffman code goes most significant bit first (RFC 1951 3.1.1). */
static void put_code(bitbuf *b, uint32_t code, int len) {
  uint32_t r = 0;
  for (int i = 0; i < len; ++i) r |= ((code >> i) & 1u) << (len - 1 - i);
  put_bits(b, r, len);
}

/* Literal/length symbol v (0..287) in the fixed code. */
static void put_symbol(bitbuf *b, int v) {
  if (v < 144) put_code(b, 0x30u + (uint32_t)v, 8);
  else if (v < 256) put_code(b, 0x190u + (uint32_t)(v - 144), 9);
  else if (v < 280) put_code(b, (uint32_t)(v - 256), 7);
  else put_code(b, 0xC0u + (uint32_t)(v - 280), 8);
}

static const uint16_t len_base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                                       193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

static void put_match(bitbuf *b, int len, int dist) {
  int i = 28;
  while (len_base[i] > len) --i;
  put_symbol(b, 257 + i);
  put_bits(b, (uint32_t)(len - len_base[i]), len_extra[i]);
  int j = 29;
  while (dist_base[j] > dist) --j;
  put_code(b, (uint32_t)j, 5);
  put_bits(b, (uint32_t)(dist - dist_base[j]), dist_extra[j]);
}

enum { WINDOW = 32768, MAX_MATCH = 258, HASH_BITS = 15, MAX_CHAIN = 64 };

static uint32_t hash3(const unsigned char *p) {
  return ((uint32_t)p[0] << 10 ^ (uint32_t)p[1] << 5 ^ p[2]) & ((1u << HASH_BITS) - 1);
}

/* One final fixed-Huffman block of `raw` with greedy LZ77 matching over a
 * 32 KiB window (hash chains of the 3-byte prefixes). Plots are mostly
 * runs and repeated rows, which this shrinks by one to two orders of
 * magnitude. Returns 0 or -1 (out of memory). */
static int deflate_fixed(const unsigned char *raw, size_t n, bitbuf *b) {
  int32_t *head = malloc(sizeof(int32_t) << HASH_BITS), *prev = malloc((n ? n : 1) * sizeof(int32_t));
  if (!head || !prev) {
    free(head), free(prev);
    return -1;
  }
  for (size_t i = 0; i < (size_t)1 << HASH_BITS; ++i) head[i] = -1;
  put_bits(b, 1, 1); /* BFINAL */
  put_bits(b, 1, 2); /* BTYPE = 01, fixed codes */
  size_t i = 0;
  while (i < n) {
    int best = 0, dist = 0;
    if (i + 3 <= n) {
      uint32_t h = hash3(raw + i);
      int32_t cand = head[h];
      size_t limit = n - i < MAX_MATCH ? n - i : MAX_MATCH;
      for (int chain = 0; cand >= 0 && i - (size_t)cand <= WINDOW && chain < MAX_CHAIN; ++chain) {
        size_t l = 0;
        while (l < limit && raw[(size_t)cand + l] == raw[i + l]) ++l;
        if ((int)l > best) best = (int)l, dist = (int)(i - (size_t)cand);
        if (l == limit) break;
        cand = prev[cand];
      }
    }
    size_t step = best >= 3 ? (size_t)best : 1;
    if (best >= 3) put_match(b, best, dist);
    else put_symbol(b, raw[i]);
    for (size_t k = 0; k < step; ++k, ++i) /* every position of the match enters the chains */
      if (i + 3 <= n) {
        uint32_t h = hash3(raw + i);
        prev[i] = head[h], head[h] = (int32_t)i;
      }
  }
  put_symbol(b, 256); /* end of block */
  if (b->nacc > 0) put_bits(b, 0, 8 - b->nacc);
  free(head), free(prev);
  return 0;
}

int sl_png_encode(const unsigned char *rgb, int w, int h, unsigned char **png, size_t *len) {
  *png = NULL, *len = 0;
  if (!rgb || w < 1 || h < 1 || w > (1 << 24) || h > (1 << 24)) return -1;
  size_t row = 3 * (size_t)w + 1; /* a filter-type byte (0: none), then the pixels */
  size_t raw_n = row * (size_t)h;
  if (raw_n > 0x7FFFFFFFu / 2) return -1; /* a chunk's length is at most 2^31 - 1 */
  unsigned char *raw = malloc(raw_n);
  if (!raw) return -1;
  for (int y = 0; y < h; ++y) {
    raw[(size_t)y * row] = 0;
    memcpy(raw + (size_t)y * row + 1, rgb + (size_t)y * 3 * (size_t)w, row - 1);
  }
  /* fixed codes spend at most 9 bits a literal, so 9/8 of the data plus the block's ends bound the stream */
  size_t zcap = 2 + raw_n + raw_n / 8 + 16 + 4;
  bitbuf z = {malloc(zcap), 0, zcap, 0, 0};
  if (!z.p) {
    free(raw);
    return -1;
  }
  /* zlib header: CM = 8 (deflate), CINFO = 7 (32 KiB window), FLEVEL 0; 0x7801 is a multiple of 31 */
  z.p[z.n++] = 0x78, z.p[z.n++] = 0x01;
  int rc = deflate_fixed(raw, raw_n, &z);
  uint32_t adler = sl_adler32(1, raw, raw_n);
  free(raw);
  if (rc || z.n + 4 > z.cap) {
    free(z.p);
    return -1;
  }
  size_t total = 8 + (12 + 13) + (12 + z.n + 4) + 12;
  buf b = {malloc(total), 0};
  if (!b.p) {
    free(z.p);
    return -1;
  }
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  put(&b, signature, 8);

  size_t c = begin_chunk(&b, "IHDR");
  put32(&b, (uint32_t)w), put32(&b, (uint32_t)h);
  /* bit depth 8, colour type 2 (RGB), deflate, adaptive filtering, no interlace */
  static const unsigned char ihdr_tail[5] = {8, 2, 0, 0, 0};
  put(&b, ihdr_tail, 5);
  end_chunk(&b, c);

  c = begin_chunk(&b, "IDAT");
  put(&b, z.p, z.n);
  put32(&b, adler);
  end_chunk(&b, c);
  free(z.p);

  c = begin_chunk(&b, "IEND");
  end_chunk(&b, c);
  *png = b.p, *len = b.n;
  return 0;
}

int sl_png_write(const char *path, const unsigned char *rgb, int w, int h, sl_diag *d) {
  unsigned char *png;
  size_t len;
  if (sl_png_encode(rgb, w, h, &png, &len)) return sl_diag_set(d, SL_EFAILED, "%s: cannot encode a %d x %d image", path, w, h);
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
