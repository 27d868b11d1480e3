/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A minimal test harness: each test program counts checks and prints
 * "N passed, N failed" at the end; a non-zero exit marks failure for CTest. */
#ifndef SLUICE_TESTS_TESTING_H
#define SLUICE_TESTS_TESTING_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int sl_test_passed, sl_test_failed;

#define CHECK(cond)                                                            \
  do {                                                                         \
    if (cond) {                                                                \
      ++sl_test_passed;                                                        \
    } else {                                                                   \
      ++sl_test_failed;                                                        \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
    }                                                                          \
  } while (0)

#define CHECK_MSG(cond, ...)                                        \
  do {                                                              \
    if (cond) {                                                     \
      ++sl_test_passed;                                             \
    } else {                                                        \
      ++sl_test_failed;                                             \
      fprintf(stderr, "%s:%d: check failed: ", __FILE__, __LINE__); \
      fprintf(stderr, __VA_ARGS__);                                 \
      fputc('\n', stderr);                                          \
    }                                                               \
  } while (0)

/* |a - b| <= rtol * max(|a|, |b|) (+ a tiny absolute floor for zeros). */
#define CHECK_CLOSE(a, b, rtol)                                                                                       \
  do {                                                                                                                \
    double sl_a_ = (a), sl_b_ = (b);                                                                                  \
    double sl_s_ = fabs(sl_a_) > fabs(sl_b_) ? fabs(sl_a_) : fabs(sl_b_);                                             \
    CHECK_MSG(fabs(sl_a_ - sl_b_) <= (rtol)*sl_s_ + 1e-300, "%s = %.17g, %s = %.17g (rtol %g)", #a, sl_a_, #b, sl_b_, \
              (double)(rtol));                                                                                        \
  } while (0)

#define CHECK_CONTAINS(haystack, needle) \
  CHECK_MSG(strstr((haystack), (needle)) != NULL, "\"%s\" does not contain \"%s\"", (haystack), (needle))

/* Reads the file at rel (relative to $SLUICE_SOURCE_DIR, else the working
 * directory) into buf, NUL-terminated; 0 on success, a failed check if not. */
static inline int sl_test_read_source(const char *rel, char *buf, size_t cap) {
  const char *src = getenv("SLUICE_SOURCE_DIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", src ? src : ".", rel);
  FILE *f = fopen(path, "rb");
  size_t n = f ? fread(buf, 1, cap - 1, f) : 0;
  if (f) fclose(f);
  buf[n] = '\0';
  CHECK_MSG(n > 0, "cannot read %s", path);
  return n > 0 ? 0 : 1;
}

static inline int sl_test_summary(void) {
  printf("%d passed, %d failed\n", sl_test_passed, sl_test_failed);
  return sl_test_failed == 0 && sl_test_passed > 0 ? 0 : 1;
}

#endif
