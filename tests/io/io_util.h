/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Helpers for the I/O tests: external tools, file contents. */
#ifndef SLUICE_TESTS_IO_UTIL_H
#define SLUICE_TESTS_IO_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 1 when `tool` is on PATH. */
static inline int have_tool(const char *tool) {
  char cmd[256];
  snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", tool);
  return system(cmd) == 0;
}

/* Exit status of a shell command (output discarded), -1 when it did not run. */
static inline int run_quiet(const char *cmd) {
  char full[1024];
  snprintf(full, sizeof full, "%s >/dev/null 2>&1", cmd);
  int st = system(full);
  if (st == -1) return -1;
  return (st & 0xff) == 0 ? (st >> 8) & 0xff : -1; /* WEXITSTATUS without <sys/wait.h> macros */
}

/* stdout of a shell command, malloc'ed (NULL on failure). */
static inline char *run_capture(const char *cmd) {
  FILE *p = popen(cmd, "r");
  if (!p) return NULL;
  size_t cap = 4096, len = 0;
  char *s = malloc(cap);
  size_t k;
  while (s && (k = fread(s + len, 1, cap - len - 1, p)) > 0) {
    len += k;
    if (cap - len < 2) {
      char *t = realloc(s, cap *= 2);
      if (!t) free(s);
      s = t;
    }
  }
  if (pclose(p) != 0) {
    free(s);
    return NULL;
  }
  if (s) s[len] = 0;
  return s;
}

static inline char *slurp(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *s = malloc((size_t)n + 1);
  if (s && fread(s, 1, (size_t)n, f) != (size_t)n) {
    free(s);
    s = NULL;
  }
  if (s) s[n] = 0;
  fclose(f);
  return s;
}

/* xmllint --noout, or a printed reason and no verdict when it is missing. */
static inline int xmllint_status(const char *xmf) {
  if (!have_tool("xmllint")) {
    printf("skipped: xmllint not found (install libxml2-utils) - %s not validated\n", xmf);
    return -2;
  }
  char cmd[512];
  snprintf(cmd, sizeof cmd, "xmllint --noout '%s'", xmf);
  return run_quiet(cmd);
}

#endif
