/* PNG encoder with stored deflate blocks (see png.h). */
#include "core/plot/png.h"

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

int sl_png_encode(const unsigned char *rgb, int w, int h, unsigned char **png, size_t *len) {
  *png = NULL, *len = 0;
  if (!rgb || w < 1 || h < 1 || w > (1 << 24) || h > (1 << 24)) return -1;
  enum { STORED_MAX = 65535 };
  size_t row = 3 * (size_t)w + 1; /* a filter-type byte (0: none), then the pixels */
  size_t raw = row * (size_t)h;
  size_t blocks = raw / STORED_MAX + 1;
  size_t zlen = 2 + raw + 5 * blocks + 4;
  if (zlen > 0x7FFFFFFFu - 16) return -1; /* a chunk's length is at most 2^31 - 1 */
  size_t total = 8 + (12 + 13) + (12 + zlen) + 12;
  buf b = {malloc(total), 0};
  if (!b.p) return -1;
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  put(&b, signature, 8);

  size_t c = begin_chunk(&b, "IHDR");
  put32(&b, (uint32_t)w), put32(&b, (uint32_t)h);
  /* bit depth 8, colour type 2 (RGB), deflate, adaptive filtering, no interlace */
  static const unsigned char ihdr_tail[5] = {8, 2, 0, 0, 0};
  put(&b, ihdr_tail, 5);
  end_chunk(&b, c);

  c = begin_chunk(&b, "IDAT");
  /* zlib header: CM = 8 (deflate), CINFO = 7 (32 KiB window), FLEVEL 0; 0x7801 is a multiple of 31 */
  static const unsigned char zhead[2] = {0x78, 0x01};
  put(&b, zhead, 2);
  /* Adler-32 of the raw stream (filter bytes and pixels), row by row: the
   * stored blocks cut it wherever 65535 bytes are full. */
  static const unsigned char filter_none = 0;
  uint32_t adler = 1;
  size_t done = 0, in_block = 0, block_len = 0; /* raw bytes written; of the current block; its length */
  for (int y = 0; y < h; ++y) {
    const unsigned char *src = rgb + (size_t)y * 3 * (size_t)w;
    adler = sl_adler32(adler, &filter_none, 1);
    adler = sl_adler32(adler, src, 3 * (size_t)w);
    for (size_t k = 0; k < row; ++k) {
      if (in_block == block_len) { /* a new stored block: BFINAL, BTYPE = 00, byte-aligned LEN and NLEN */
        block_len = raw - done < STORED_MAX ? raw - done : STORED_MAX;
        unsigned char head[5] = {(unsigned char)(done + block_len == raw), (unsigned char)block_len,
                                 (unsigned char)(block_len >> 8), (unsigned char)~block_len,
                                 (unsigned char)(~block_len >> 8)};
        put(&b, head, 5);
        in_block = 0;
      }
      b.p[b.n++] = k == 0 ? filter_none : src[k - 1];
      ++in_block, ++done;
    }
  }
  put32(&b, adler);
  end_chunk(&b, c);

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
