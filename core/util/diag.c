/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/util/diag.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int sl_diag_set(sl_diag *d, int code, const char *fmt, ...) {
  if (d) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(d->msg, sizeof d->msg, fmt, ap);
    va_end(ap);
  }
  return code;
}

int sl_diag_prefix(sl_diag *d, int code, const char *fmt, ...) {
  if (d) {
    char head[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    /* Shift the old message right and put "head: " in front of it. */
    size_t hl = strlen(head) + 2, cap = sizeof d->msg;
    if (hl >= cap) hl = cap - 1;
    size_t ol = strnlen(d->msg, cap - 1);
    if (hl + ol >= cap) ol = cap - 1 - hl;
    memmove(d->msg + hl, d->msg, ol);
    d->msg[hl + ol] = '\0';
    memcpy(d->msg, head, hl - 2);
    d->msg[hl - 2] = ':';
    d->msg[hl - 1] = ' ';
  }
  return code;
}

int sl_edit_distance(const char *a, const char *b) {
  size_t la = strlen(a), lb = strlen(b);
  if (la > 64 || lb > 64) return 99; /* names are short; long words get no suggestion */
  int row[65];
  for (size_t j = 0; j <= lb; ++j) row[j] = (int)j;
  for (size_t i = 1; i <= la; ++i) {
    int diag = row[0];
    row[0] = (int)i;
    for (size_t j = 1; j <= lb; ++j) {
      int up = row[j];
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      int best = diag + cost;
      if (up + 1 < best) best = up + 1;
      if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
      row[j] = best;
      diag = up;
    }
  }
  return row[lb];
}

const char *sl_suggest(const char *word, const char *const *candidates, int n) {
  const char *best = NULL;
  int best_d = 99;
  for (int i = 0; i < n; ++i) {
    int dist = sl_edit_distance(word, candidates[i]);
    if (dist < best_d) {
      best_d = dist;
      best = candidates[i];
    }
  }
  /* Close enough: at most a third of the word's letters differ (and at least one may). */
  size_t len = strlen(word);
  int limit = (int)(len / 3) > 1 ? (int)(len / 3) : 1;
  if (len >= 4 && limit < 2) limit = 2;
  return best_d <= limit ? best : NULL;
}
