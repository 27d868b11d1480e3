#include "core/plugin/registry.h"

#include <dirent.h>
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/plugin/kinds.h"
#include "core/plugin/validate.h"

#ifndef SLUICE_BUILD_BIN_DIR
#error "SLUICE_BUILD_BIN_DIR must be defined by the build"
#endif

/* Sanitizer builds keep libraries mapped after dlclose so that leak reports
 * still name the plugin's frames. */
#if defined(__SANITIZE_ADDRESS__)
#define SL_DLOPEN_FLAGS (RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SL_DLOPEN_FLAGS (RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)
#endif
#endif
#ifndef SL_DLOPEN_FLAGS
#define SL_DLOPEN_FLAGS (RTLD_NOW | RTLD_LOCAL)
#endif

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  char *p = malloc(n);
  if (p) memcpy(p, s, n);
  return p;
}

static int push_dir(sl_registry *r, const char *dir, sl_diag *d) {
  if (!*dir) return 0;
  for (int i = 0; i < r->n_dirs; ++i)
    if (strcmp(r->dirs[i], dir) == 0) return 0;
  char **dirs = realloc(r->dirs, (size_t)(r->n_dirs + 1) * sizeof *dirs);
  if (!dirs) return sl_diag_set(d, SL_EFAILED, "out of memory");
  r->dirs = dirs;
  if (!(r->dirs[r->n_dirs] = dup_str(dir))) return sl_diag_set(d, SL_EFAILED, "out of memory");
  r->n_dirs++;
  return 0;
}

const char *sl_registry_default_dir(void) {
  static char dir[PATH_MAX];
  char exe[PATH_MAX - 64];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) {
    snprintf(dir, sizeof dir, "%s", SLUICE_BUILD_PLUGIN_DIR);
    return dir;
  }
  exe[n] = '\0';
  char *slash = strrchr(exe, '/');
  if (slash) *slash = '\0';
  /* Run from the build tree: use its plugins; else the install's, relative
   * to the executable so that the installed tree may be moved. */
  if (strcmp(exe, SLUICE_BUILD_BIN_DIR) == 0)
    snprintf(dir, sizeof dir, "%s", SLUICE_BUILD_PLUGIN_DIR);
  else
    snprintf(dir, sizeof dir, "%.*s/../%s", (int)(sizeof dir - sizeof SLUICE_PLUGIN_SUBDIR - 8), exe,
             SLUICE_PLUGIN_SUBDIR);
  return dir;
}

int sl_registry_create(sl_registry **out, const char *const *scene_dirs, int n_scene_dirs, sl_diag *d) {
  *out = NULL;
  sl_registry *r = calloc(1, sizeof *r);
  if (!r) return sl_diag_set(d, SL_EFAILED, "out of memory");
  int rc = 0;
  for (int i = 0; i < n_scene_dirs && !rc; ++i) rc = push_dir(r, scene_dirs[i], d);
  const char *env = getenv("SLUICE_PLUGIN_PATH");
  if (env && !rc) {
    char *copy = dup_str(env);
    if (!copy) rc = sl_diag_set(d, SL_EFAILED, "out of memory");
    for (char *save = NULL, *tok = copy ? strtok_r(copy, ":", &save) : NULL; tok && !rc;
         tok = strtok_r(NULL, ":", &save))
      rc = push_dir(r, tok, d);
    free(copy);
  }
  if (!rc) rc = push_dir(r, sl_registry_default_dir(), d);
  if (rc) {
    sl_registry_destroy(r);
    return rc;
  }
  *out = r;
  return 0;
}

static void library_free(sl_library *lib) {
  if (!lib) return;
  if (lib->handle) dlclose(lib->handle);
  free(lib->path);
  free(lib);
}

void sl_registry_destroy(sl_registry *r) {
  if (!r) return;
  for (int i = 0; i < r->n_dirs; ++i) free(r->dirs[i]);
  free(r->dirs);
  for (int i = 0; i < r->n_libraries; ++i) library_free(r->libraries[i]);
  free(r->libraries);
  free(r->entries);
  for (int i = 0; i < r->n_problems; ++i) free(r->problems[i]);
  free(r->problems);
  free(r);
}

/* Opens and validates one library; on success *out owns the handle. */
static int open_library(const char *path, sl_library **out, sl_diag *d) {
  *out = NULL;
  dlerror();
  void *h = dlopen(path, SL_DLOPEN_FLAGS);
  if (!h) {
    const char *why = dlerror();
    return sl_diag_set(d, SL_EBADINPUT, "%s: cannot load: %s", path, why ? why : "unknown dlopen error");
  }
  sl_closure_entry_fn entry = NULL;
  void *sym = dlsym(h, SL_CLOSURE_ENTRY_SYMBOL);
  memcpy(&entry, &sym, sizeof entry); /* object-to-function pointer without a cast warning */
  if (!entry) {
    /* Name the ABI a library was built for when it has a different entry. */
    char other[64];
    for (int v = 0; v < 10; ++v) {
      snprintf(other, sizeof other, "sl_closure_entry_v%d", v);
      if (v != (int)SL_CLOSURE_ABI_MAJOR && dlsym(h, other)) {
        dlclose(h);
        return sl_diag_set(d, SL_EBADINPUT, "%s: built for closure ABI %d (it exports %s); this sluice speaks ABI %u",
                           path, v, other, SL_CLOSURE_ABI_MAJOR);
      }
    }
    dlclose(h);
    return sl_diag_set(d, SL_EBADINPUT, "%s: not a sluice closure library: no symbol %s", path,
                       SL_CLOSURE_ENTRY_SYMBOL);
  }
  int32_t n = -1;
  const sl_closure_desc *const *descs = entry(&n);
  if (!descs || n < 1) {
    dlclose(h);
    return sl_diag_set(d, SL_EBADINPUT, "%s: %s returned no closures", path, SL_CLOSURE_ENTRY_SYMBOL);
  }
  for (int32_t i = 0; i < n; ++i) {
    if (!descs[i]) {
      dlclose(h);
      return sl_diag_set(d, SL_EBADINPUT, "%s: descriptor %d is NULL", path, (int)i);
    }
    int rc = sl_validate_descriptor(descs[i], d);
    if (rc) {
      dlclose(h);
      return sl_diag_prefix(d, rc, "%s", path);
    }
    for (int32_t j = 0; j < i; ++j) {
      if (descs[j]->kind == descs[i]->kind && strcmp(descs[j]->name, descs[i]->name) == 0) {
        /* The message reads the descriptor: write it before unloading. */
        int dup_rc = sl_diag_set(d, SL_EBADINPUT, "%s: two closures named %s '%s' in one library", path,
                             sl_kind_name(descs[i]->kind), descs[i]->name);
        dlclose(h);
        return dup_rc;
      }
    }
  }
  sl_library *lib = calloc(1, sizeof *lib);
  if (!lib || !(lib->path = dup_str(path))) {
    free(lib);
    dlclose(h);
    return sl_diag_set(d, SL_EFAILED, "out of memory");
  }
  lib->handle = h;
  lib->n_closures = n;
  lib->closures = descs;
  *out = lib;
  return 0;
}

static int same_file(const char *a, const char *b) {
  char ra[PATH_MAX], rb[PATH_MAX];
  if (!realpath(a, ra) || !realpath(b, rb)) return strcmp(a, b) == 0;
  return strcmp(ra, rb) == 0;
}

int sl_registry_add_library(sl_registry *r, const char *path, sl_library **out, sl_diag *d) {
  if (out) *out = NULL;
  for (int i = 0; i < r->n_libraries; ++i) {
    if (same_file(r->libraries[i]->path, path)) {
      if (out) *out = r->libraries[i];
      return 0;
    }
  }
  sl_library *lib;
  int rc = open_library(path, &lib, d);
  if (rc) return rc;
  if (r->n_libraries == r->cap_libraries) {
    int cap = r->cap_libraries ? 2 * r->cap_libraries : 16;
    sl_library **libs = realloc(r->libraries, (size_t)cap * sizeof *libs);
    if (!libs) {
      library_free(lib);
      return sl_diag_set(d, SL_EFAILED, "out of memory");
    }
    r->libraries = libs;
    r->cap_libraries = cap;
  }
  if (r->n_entries + lib->n_closures > r->cap_entries) {
    int cap = r->cap_entries ? 2 * r->cap_entries : 64;
    while (cap < r->n_entries + lib->n_closures) cap *= 2;
    sl_closure_entry *e = realloc(r->entries, (size_t)cap * sizeof *e);
    if (!e) {
      library_free(lib);
      return sl_diag_set(d, SL_EFAILED, "out of memory");
    }
    r->entries = e;
    r->cap_entries = cap;
  }
  r->libraries[r->n_libraries++] = lib;
  for (int32_t i = 0; i < lib->n_closures; ++i)
    r->entries[r->n_entries++] = (sl_closure_entry){lib->closures[i], lib};
  if (out) *out = lib;
  return 0;
}

static int has_so_suffix(const char *name) {
  size_t n = strlen(name);
  return n > 3 && strcmp(name + n - 3, ".so") == 0;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

static int add_problem(sl_registry *r, const char *msg) {
  char **p = realloc(r->problems, (size_t)(r->n_problems + 1) * sizeof *p);
  if (!p) return SL_EFAILED;
  r->problems = p;
  if (!(r->problems[r->n_problems] = dup_str(msg))) return SL_EFAILED;
  r->n_problems++;
  return 0;
}

int sl_registry_scan(sl_registry *r, sl_diag *d) {
  for (int i = 0; i < r->n_dirs; ++i) {
    DIR *dir = opendir(r->dirs[i]);
    if (!dir) continue; /* a folder on the path that does not exist is not an error */
    int n = 0, cap = 0;
    char **names = NULL;
    int rc = 0;
    for (struct dirent *e; (e = readdir(dir)) != NULL;) {
      if (!has_so_suffix(e->d_name)) continue;
      if (n == cap) {
        cap = cap ? 2 * cap : 32;
        char **nn = realloc(names, (size_t)cap * sizeof *nn);
        if (!nn) {
          rc = SL_EFAILED;
          break;
        }
        names = nn;
      }
      if (!(names[n] = dup_str(e->d_name))) {
        rc = SL_EFAILED;
        break;
      }
      n++;
    }
    closedir(dir);
    if (!rc && n > 1) qsort(names, (size_t)n, sizeof *names, cmp_str); /* deterministic order (names is NULL when empty) */
    for (int k = 0; k < n && !rc; ++k) {
      char path[PATH_MAX];
      snprintf(path, sizeof path, "%s/%s", r->dirs[i], names[k]);
      sl_diag why;
      int lrc = sl_registry_add_library(r, path, NULL, &why);
      if (lrc == SL_EBADINPUT) rc = add_problem(r, why.msg);
      else if (lrc) rc = lrc;
    }
    for (int k = 0; k < n; ++k) free(names[k]);
    free(names);
    if (rc) return sl_diag_set(d, SL_EFAILED, "out of memory while scanning %s", r->dirs[i]);
  }
  return 0;
}

static int library_matches(const sl_library *lib, const char *library) {
  if (!library) return 1;
  if (strchr(library, '/')) return same_file(lib->path, library);
  const char *base = strrchr(lib->path, '/');
  base = base ? base + 1 : lib->path;
  return strcmp(base, library) == 0;
}

int sl_registry_find(const sl_registry *r, sl_kind kind, const char *name, const char *library,
                     const sl_closure_entry **entry, sl_diag *d) {
  *entry = NULL;
  const sl_closure_entry *first = NULL;
  int n_match = 0;
  for (int i = 0; i < r->n_entries; ++i) {
    const sl_closure_entry *e = &r->entries[i];
    if (e->desc->kind != kind || strcmp(e->desc->name, name) != 0 || !library_matches(e->library, library))
      continue;
    if (!first) first = e;
    else if (n_match == 1)
      return sl_diag_set(d, SL_EBADINPUT,
                         "%s closure '%s' is provided by two libraries, %s and %s; say which one with "
                         "`library = <file>` in its [closure.%s] section",
                         sl_kind_name(kind), name, first->library->path, e->library->path, sl_kind_name(kind));
    n_match++;
  }
  if (first) {
    *entry = first;
    return 0;
  }
  /* Not found: suggest among the closures of this kind. */
  const char *cands[256];
  int nc = 0;
  for (int i = 0; i < r->n_entries && nc < 256; ++i)
    if (r->entries[i].desc->kind == kind && library_matches(r->entries[i].library, library))
      cands[nc++] = r->entries[i].desc->name;
  const char *s = sl_suggest(name, cands, nc);
  if (library)
    return sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s' in library '%s'%s%s%s", sl_kind_name(kind), name, library,
                       s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
  if (s) return sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s'; did you mean '%s'?", sl_kind_name(kind), name, s);
  return sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s' on the plugin search path (`sluice closures` lists them)",
                     sl_kind_name(kind), name);
}

int sl_registry_libraries_in_use(const sl_registry *r) {
  int n = 0;
  for (int i = 0; i < r->n_libraries; ++i) n += r->libraries[i]->n_in_use > 0;
  return n;
}
