/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The BLAS of the process (see blas.h). */
#define _GNU_SOURCE
#include "core/util/blas.h"

#include <dlfcn.h>
#include <limits.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct found {
  char path[PATH_MAX]; /* the first loaded object whose file name says BLAS */
} found;

static int is_blas(const char *base) {
  return strstr(base, "blas") || strstr(base, "mkl_rt") || strstr(base, "blis") || strstr(base, "atlas");
}

static int visit(struct dl_phdr_info *info, size_t size, void *user) {
  (void)size;
  found *f = user;
  const char *name = info->dlpi_name;
  if (!name || !*name || f->path[0]) return 0;
  const char *base = strrchr(name, '/');
  base = base ? base + 1 : name;
  if (!is_blas(base)) return 0;
  char real[PATH_MAX];
  snprintf(f->path, sizeof f->path, "%s", realpath(name, real) ? real : name);
  return 0;
}

const char *sl_blas_description(void) {
  static char text[768];
  if (text[0]) return text;
  found f = {{0}};
  dl_iterate_phdr(visit, &f);
  /* OpenBLAS names itself, whichever interface library (libblas.so.3, libopenblas.so.0) loaded it */
  typedef char *(*config_fn)(void);
  config_fn config = (config_fn)dlsym(RTLD_DEFAULT, "openblas_get_config");
  const char *p = f.path;
  if (config && config())
    snprintf(text, sizeof text, "%.200s%s%.500s%s", config(), p[0] ? " (" : "", p, p[0] ? ")" : "");
  else if (!p[0]) snprintf(text, sizeof text, "none loaded");
  else if (strstr(p, "mkl")) snprintf(text, sizeof text, "Intel MKL (%.500s)", p);
  else if (strstr(p, "blis")) snprintf(text, sizeof text, "BLIS (%.500s)", p);
  else if (strstr(p, "atlas")) snprintf(text, sizeof text, "ATLAS (%.500s)", p);
  else if (strstr(p, "/blas/")) snprintf(text, sizeof text, "reference BLAS (%.500s)", p);
  else snprintf(text, sizeof text, "%.500s", p);
  return text;
}
