/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Replays inputs through LLVMFuzzerTestOneInput without libFuzzer, so every
 * build (plain and ASan+UBSan) runs the seed corpus and any saved crashers.
 * Usage: fuzz_ini_replay FILE_OR_DIR...  (a directory means every file in it). */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) {
    fprintf(stderr, "fuzz_ini_replay: cannot open %s\n", path);
    return -1;
  }
  size_t cap = 4096, n = 0;
  uint8_t *buf = malloc(cap);
  while (buf) {
    if (n == cap) {
      uint8_t *nb = realloc(buf, cap * 2);
      if (!nb) {
        free(buf);
        buf = NULL;
        break;
      }
      buf = nb;
      cap *= 2;
    }
    size_t got = fread(buf + n, 1, cap - n, f);
    n += got;
    if (got == 0) break;
  }
  int bad = ferror(f);
  fclose(f);
  if (!buf || bad) {
    free(buf);
    fprintf(stderr, "fuzz_ini_replay: cannot read %s\n", path);
    return -1;
  }
  /* A private copy of exactly n bytes, so ASan catches reads past the end. */
  uint8_t *exact = malloc(n ? n : 1);
  if (!exact) {
    free(buf);
    return -1;
  }
  if (n) memcpy(exact, buf, n);
  free(buf);
  LLVMFuzzerTestOneInput(exact, n);
  free(exact);
  return 0;
}

int main(int argc, char **argv) {
  int count = 0, failures = 0;
  if (argc < 2) {
    fprintf(stderr, "usage: %s FILE_OR_DIR...\n", argv[0]);
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    struct stat st;
    if (stat(argv[i], &st) != 0) {
      fprintf(stderr, "fuzz_ini_replay: no such file or directory: %s\n", argv[i]);
      ++failures;
      continue;
    }
    if (!S_ISDIR(st.st_mode)) {
      failures += replay_file(argv[i]) != 0;
      ++count;
      continue;
    }
    DIR *dir = opendir(argv[i]);
    if (!dir) {
      fprintf(stderr, "fuzz_ini_replay: cannot open directory %s\n", argv[i]);
      ++failures;
      continue;
    }
    struct dirent *ent;
    while ((ent = readdir(dir)) != NULL) {
      char path[4096];
      if (ent->d_name[0] == '.') continue; /* ".", ".." and hidden files */
      snprintf(path, sizeof path, "%s/%s", argv[i], ent->d_name);
      if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) continue;
      failures += replay_file(path) != 0;
      ++count;
    }
    closedir(dir);
  }
  printf("replayed %d inputs, %d unreadable\n", count, failures);
  /* An empty corpus would make the test pass without testing anything. */
  return failures == 0 && count > 0 ? 0 : 1;
}
