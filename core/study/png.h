/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A PNG encoder for 8-bit RGB images (PNG: ISO/IEC 15948:2004): the rows,
 * filter type 0, go into one zlib stream written by zlib's compress2 at
 * the best compression level. */
#ifndef SLUICE_PLOT_PNG_H
#define SLUICE_PLOT_PNG_H

#include <stddef.h>
#include <stdint.h>

#include "core/util/diag.h"

/* CRC-32 of ISO 3309 / ITU-T V.42 (reflected polynomial 0xEDB88320), as PNG
 * chunks carry it (zlib's crc32): start with crc = 0, feed pieces in order. */
uint32_t sl_crc32(uint32_t crc, const unsigned char *p, size_t n);
/* Adler-32 of RFC 1950 section 8.2 (zlib's adler32): start with 1, feed pieces in order. */
uint32_t sl_adler32(uint32_t adler, const unsigned char *p, size_t n);

/* The PNG file of a w x h image, rows top to bottom, 3 bytes (R, G, B) a
 * pixel, into a malloc'ed buffer. Returns 0, or -1 (out of memory, or a size
 * outside 1..2^24). */
int sl_png_encode(const unsigned char *rgb, int w, int h, unsigned char **png, size_t *len);
/* The same, written to path. Returns 0 or SL_EFAILED with d set. */
int sl_png_write(const char *path, const unsigned char *rgb, int w, int h, sl_diag *d);

#endif
