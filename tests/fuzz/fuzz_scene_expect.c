/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Replays scene files through the scene fuzz target's entry point
 * (sl_fuzz_scene_check) and checks what each gives:
 *   fuzz_scene_expect 0 DIR...   every file is a valid scene (the seeds: they
 *                                reach the mesh and the model's set-up);
 *   fuzz_scene_expect 2 DIR...   every file is bad input (exit status 2) with a
 *                                message that names the file and a line of it
 *                                ("FILE:LINE") and contains the text of each
 *                                of the file's "; expect: TEXT" lines.
 * A directory means every regular file in it, in name order. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tests/fuzz/fuzz_scene.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);

static char *slurp(const char *path, size_t *n) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 4096;
  char *buf = malloc(cap + 1);
  *n = 0;
  while (buf) {
    size_t got = fread(buf + *n, 1, cap - *n, f);
    *n += got;
    if (*n < cap) break;
    char *nb = realloc(buf, 2 * cap + 1);
    if (!nb) free(buf);
    buf = nb, cap *= 2;
  }
  if (ferror(f)) free(buf), buf = NULL;
  fclose(f);
  if (buf) buf[*n] = '\0';
  return buf;
}

/* "PATH:" followed by a line number somewhere in the message */
static int names_line(const char *msg, const char *path) {
  size_t len = strlen(path);
  for (const char *p = strstr(msg, path); p; p = strstr(p + 1, path))
    if (p[len] == ':' && p[len + 1] >= '1' && p[len + 1] <= '9') return 1;
  return 0;
}

static int check_file(const char *path, int want) {
  size_t n;
  char *text = slurp(path, &n);
  if (!text) {
    fprintf(stderr, "FAIL %s: cannot read it\n", path);
    return 1;
  }
  sluice_error e;
  int rc = sl_fuzz_scene_check((const uint8_t *)text, n, path, &e);
  int bad = rc != want;
  if (!bad && want == SLUICE_BAD_INPUT) {
    if (!names_line(e.msg, path)) {
      fprintf(stderr, "FAIL %s: the message does not name %s:LINE\n", path, path);
      bad = 1;
    }
    for (const char *p = strstr(text, "; expect: "); p; p = strstr(p + 1, "; expect: ")) {
      char want_text[512];
      size_t k = strcspn(p + 10, "\r\n");
      snprintf(want_text, sizeof want_text, "%.*s", (int)k, p + 10);
      if (!strstr(e.msg, want_text)) {
        fprintf(stderr, "FAIL %s: the message lacks '%s'\n", path, want_text);
        bad = 1;
      }
    }
  }
  if (bad) fprintf(stderr, "FAIL %s: status %d (expected %d): %s\n", path, rc, want, e.msg);
  else printf("ok   %s: %d%s%s\n", path, rc, rc ? ": " : "", rc ? e.msg : "");
  free(text);
  return bad;
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

int main(int argc, char **argv) {
  if (argc < 3 || (strcmp(argv[1], "0") != 0 && strcmp(argv[1], "2") != 0)) {
    fprintf(stderr, "usage: %s 0|2 FILE_OR_DIR...\n", argv[0]);
    return 2;
  }
  LLVMFuzzerInitialize(&argc, &argv);
  int want = atoi(argv[1]), count = 0, failures = 0;
  for (int i = 2; i < argc; ++i) {
    struct stat st;
    if (stat(argv[i], &st) != 0) {
      fprintf(stderr, "FAIL no such file or directory: %s\n", argv[i]);
      ++failures;
      continue;
    }
    if (!S_ISDIR(st.st_mode)) {
      failures += check_file(argv[i], want), ++count;
      continue;
    }
    DIR *dir = opendir(argv[i]);
    if (!dir) {
      fprintf(stderr, "FAIL cannot open directory %s\n", argv[i]);
      ++failures;
      continue;
    }
    char **names = NULL;
    int n = 0, cap = 0;
    struct dirent *ent;
    while ((ent = readdir(dir)) != NULL) {
      if (ent->d_name[0] == '.') continue;
      if (n == cap) {
        char **nn = realloc(names, (size_t)(cap = cap ? 2 * cap : 64) * sizeof *nn);
        if (!nn) break;
        names = nn;
      }
      size_t len = strlen(argv[i]) + strlen(ent->d_name) + 2;
      if (!(names[n] = malloc(len))) break;
      snprintf(names[n++], len, "%s/%s", argv[i], ent->d_name);
    }
    closedir(dir);
    if (n) qsort(names, (size_t)n, sizeof *names, by_name);
    for (int k = 0; k < n; ++k) {
      if (stat(names[k], &st) == 0 && S_ISREG(st.st_mode)) failures += check_file(names[k], want), ++count;
      free(names[k]);
    }
    free(names);
  }
  printf("%d scene files, %d failed\n", count, failures);
  return failures == 0 && count > 0 ? 0 : 1;
}
