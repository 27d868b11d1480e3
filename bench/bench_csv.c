/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "bench_csv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int bench_csv_column(const char *header, const char *name) {
  int k = 0;
  size_t len = strlen(name);
  for (const char *s = header; *s; ++k) {
    const char *e = strpbrk(s, ",\r\n");
    size_t w = e ? (size_t)(e - s) : strlen(s);
    if (w == len && strncmp(s, name, len) == 0) return k;
    if (!e || *e != ',') break;
    s = e + 1;
  }
  return -1;
}

void bench_csv_field(const char *line, int k, char *buf, size_t cap) {
  const char *s = line;
  for (int i = 0; i < k && s; ++i) s = strchr(s, ','), s = s ? s + 1 : NULL;
  buf[0] = '\0';
  if (!s) return;
  size_t w = strcspn(s, ",\r\n");
  snprintf(buf, cap, "%.*s", (int)(w < cap ? w : cap - 1), s);
}

double bench_csv_number(const char *line, int k) {
  char buf[64], *end;
  bench_csv_field(line, k, buf, sizeof buf);
  if (!buf[0]) return NAN;
  double v = strtod(buf, &end);
  return *end ? NAN : v;
}
