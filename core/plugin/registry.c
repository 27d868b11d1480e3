/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/registry.h"

#include <dirent.h>
#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/plugin/guard.h"
#include "core/plugin/isolate.h"
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
  if (!dirs) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  r->dirs = dirs;
  if (!(r->dirs[r->n_dirs] = dup_str(dir))) return sl_diag_set(d, SL_ENOMEM, "out of memory");
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
  if (strcmp(exe, SLUICE_BUILD_BIN_DIR) == 0) snprintf(dir, sizeof dir, "%s", SLUICE_BUILD_PLUGIN_DIR);
  else
    snprintf(dir, sizeof dir, "%.*s/../%s", (int)(sizeof dir - sizeof SLUICE_PLUGIN_SUBDIR - 8), exe,
             SLUICE_PLUGIN_SUBDIR);
  return dir;
}

int sl_registry_create(sl_registry **out, const char *const *scene_dirs, int n_scene_dirs, sl_diag *d) {
  *out = NULL;
  sl_registry *r = calloc(1, sizeof *r);
  if (!r) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  int rc = 0;
  for (int i = 0; i < n_scene_dirs && !rc; ++i) rc = push_dir(r, scene_dirs[i], d);
  const char *env = getenv("SLUICE_PLUGIN_PATH");
  if (env && !rc) {
    char *copy = dup_str(env);
    if (!copy) rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
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
  free(lib->usage);
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
  for (int i = 0; i < r->n_files; ++i) free(r->files[i]);
  free(r->files);
  free(r->file_tried);
  free(r->file_dir);
  free(r->dir_indexed);
  for (int i = 0; i < r->n_index; ++i) free(r->index[i].name), free(r->index[i].path);
  free(r->index);
  free(r);
}

/* Opens and validates one library; on success *out owns the handle.
 * *n_dlopen counts the libraries dlopen'ed, refused ones included. */
static int open_library(const char *path, sl_library **out, long *n_dlopen, sl_diag *d) {
  *out = NULL;
  /* A name without a slash is a file in the working folder, as on the
     command line; dlopen would look for it on the system's library path. */
  char local[PATH_MAX];
  const char *open_path = path;
  if (!strchr(path, '/')) {
    if (snprintf(local, sizeof local, "./%s", path) >= (int)sizeof local)
      return sl_diag_set(d, SL_EBADINPUT, "%s: path too long", path);
    open_path = local;
  }
  dlerror();
  void *h = dlopen(open_path, SL_DLOPEN_FLAGS);
  if (!h) {
    const char *why = dlerror();
    return sl_diag_set(d, SL_EBADINPUT, "%s: cannot load: %s", path, why ? why : "unknown dlopen error");
  }
  ++*n_dlopen;
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
  if (!lib || !(lib->path = dup_str(path)) || !(lib->usage = calloc((size_t)n, sizeof *lib->usage))) {
    if (lib) free(lib->path);
    free(lib);
    dlclose(h);
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
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
  int rc = open_library(path, &lib, &r->n_dlopen, d);
  if (rc) return rc;
  lib->timing = r->timing;
  if (r->n_libraries == r->cap_libraries) {
    int cap = r->cap_libraries ? 2 * r->cap_libraries : 16;
    sl_library **libs = realloc(r->libraries, (size_t)cap * sizeof *libs);
    if (!libs) {
      library_free(lib);
      return sl_diag_set(d, SL_ENOMEM, "out of memory");
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
      return sl_diag_set(d, SL_ENOMEM, "out of memory");
    }
    r->entries = e;
    r->cap_entries = cap;
  }
  r->libraries[r->n_libraries++] = lib;
  for (int32_t i = 0; i < lib->n_closures; ++i) r->entries[r->n_entries++] = (sl_closure_entry){lib->closures[i], lib};
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

/* The *.so files of one folder, sorted (a deterministic order); a folder
 * that does not exist has none. */
static int list_libraries(const char *dir_path, char ***out, int *n_out) {
  *out = NULL;
  *n_out = 0;
  DIR *dir = opendir(dir_path);
  if (!dir) return 0; /* a folder on the path that does not exist is not an error */
  int n = 0, cap = 0, rc = 0;
  char **names = NULL;
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
  if (!rc && n > 1) qsort(names, (size_t)n, sizeof *names, cmp_str);
  if (rc) {
    for (int k = 0; k < n; ++k) free(names[k]);
    free(names);
    return rc;
  }
  *out = names;
  *n_out = n;
  return 0;
}

/* Loads one file of the search path; a library that fails validation is
 * kept in r->problems, not an error. */
static int load_from_path(sl_registry *r, const char *path) {
  sl_diag why;
  int rc = sl_registry_add_library(r, path, NULL, &why);
  if (rc == SL_EBADINPUT) return add_problem(r, why.msg);
  return rc;
}

int sl_registry_scan(sl_registry *r, sl_diag *d) {
  if (r->lazy) { /* an index: load what it has not loaded yet */
    for (int i = 0; i < r->n_files; ++i) {
      if (r->file_tried[i]) continue;
      r->file_tried[i] = 1;
      if (load_from_path(r, r->files[i]))
        return sl_diag_set(d, SL_ENOMEM, "out of memory while loading %s", r->files[i]);
    }
    return 0;
  }
  for (int i = 0; i < r->n_dirs; ++i) {
    char **names;
    int n, rc = list_libraries(r->dirs[i], &names, &n);
    for (int k = 0; k < n && !rc; ++k) {
      char path[PATH_MAX];
      snprintf(path, sizeof path, "%s/%s", r->dirs[i], names[k]);
      rc = load_from_path(r, path);
    }
    for (int k = 0; k < n; ++k) free(names[k]);
    free(names);
    if (rc) return sl_diag_set(d, SL_ENOMEM, "out of memory while scanning %s", r->dirs[i]);
  }
  return 0;
}

static int index_add(sl_registry *r, sl_kind kind, const char *name, const char *path) {
  if (r->n_index == r->cap_index) {
    int cap = r->cap_index ? 2 * r->cap_index : 64;
    struct sl_index_entry *e = realloc(r->index, (size_t)cap * sizeof *e);
    if (!e) return SL_ENOMEM;
    r->index = e, r->cap_index = cap;
  }
  struct sl_index_entry *e = &r->index[r->n_index];
  e->kind = kind;
  e->name = dup_str(name), e->path = dup_str(path);
  if (!e->name || !e->path) {
    free(e->name), free(e->path);
    return SL_ENOMEM;
  }
  r->n_index++;
  return 0;
}

/* Reads DIR/closures.index: lines "kind name file", '#' comments; the file
 * is one in that folder. *found is 0 when the folder has no index. */
static int read_index(sl_registry *r, const char *dir, int *found, sl_diag *d) {
  char path[PATH_MAX];
  *found = 0;
  if (snprintf(path, sizeof path, "%s/%s", dir, SL_PLUGIN_INDEX_FILE) >= (int)sizeof path) return 0;
  FILE *f = fopen(path, "r");
  if (!f) return 0;
  *found = 1;
  char line[1024];
  int rc = 0;
  for (int ln = 1; !rc && fgets(line, sizeof line, f); ++ln) {
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char kind_s[128], name[256], file[256], extra[2];
    int n = sscanf(line, "%127s %255s %255s %1s", kind_s, name, file, extra);
    if (n <= 0) continue;
    sl_kind kind;
    sl_diag why;
    if (n != 3) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: error: expected 'kind name library.so'", path, ln);
    } else if (sl_kind_from_name(kind_s, &kind, &why)) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: error: %s", path, ln, why.msg);
    } else if (strchr(file, '/') || !has_so_suffix(file)) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: error: '%s' is not a library file in that folder (name.so)", path, ln,
                       file);
    } else {
      char lib[PATH_MAX];
      if (snprintf(lib, sizeof lib, "%s/%s", dir, file) >= (int)sizeof lib)
        rc = sl_diag_set(d, SL_EBADINPUT, "%s:%d: error: path too long", path, ln);
      else if (index_add(r, kind, name, lib)) rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
    }
  }
  fclose(f);
  return rc;
}

int sl_registry_index(sl_registry *r, sl_diag *d) {
  if (!(r->dir_indexed = calloc((size_t)(r->n_dirs > 0 ? r->n_dirs : 1), 1)))
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
  for (int i = 0; i < r->n_dirs; ++i) {
    int found, rc = read_index(r, r->dirs[i], &found, d);
    if (rc) return rc;
    r->dir_indexed[i] = (unsigned char)found;
    char **names;
    int n;
    rc = list_libraries(r->dirs[i], &names, &n);
    if (!rc && n > 0) {
      char **files = realloc(r->files, (size_t)(r->n_files + n) * sizeof *files);
      if (files) r->files = files;
      unsigned char *tried = files ? realloc(r->file_tried, (size_t)(r->n_files + n)) : NULL;
      if (tried) r->file_tried = tried;
      int *fdir = tried ? realloc(r->file_dir, (size_t)(r->n_files + n) * sizeof *fdir) : NULL;
      if (fdir) r->file_dir = fdir;
      if (!files || !tried || !fdir) rc = SL_EFAILED;
      for (int k = 0; k < n && !rc; ++k) {
        size_t len = strlen(r->dirs[i]) + strlen(names[k]) + 2;
        char *path = malloc(len);
        if (!path) {
          rc = SL_EFAILED;
          break;
        }
        snprintf(path, len, "%s/%s", r->dirs[i], names[k]);
        r->files[r->n_files] = path;
        r->file_dir[r->n_files] = i;
        r->file_tried[r->n_files++] = 0;
      }
    }
    for (int k = 0; k < n; ++k) free(names[k]);
    free(names);
    if (rc) return sl_diag_set(d, SL_ENOMEM, "out of memory while listing %s", r->dirs[i]);
  }
  r->lazy = 1;
  return 0;
}

static const char *base_name(const char *path) {
  const char *slash = strrchr(path, '/');
  return slash ? slash + 1 : path;
}

/* Does a file name follow the built-in naming <kind>_<name>.so? */
static int conventional_name(const char *base) {
  int n;
  const char *const *kinds = sl_kind_names(&n);
  for (int k = 0; k < n; ++k) {
    size_t len = strlen(kinds[k]);
    if (strncmp(base, kinds[k], len) == 0 && base[len] == '_' && strlen(base + len + 1) > 3) return 1;
  }
  return 0;
}

static int file_matches(const char *path, const char *library) {
  if (!library) return 1;
  return strchr(library, '/') ? same_file(path, library) : strcmp(base_name(path), library) == 0;
}

/* Opens one file of the search path, once. */
static int open_listed(sl_registry *r, const char *path, sl_diag *d) {
  for (int i = 0; i < r->n_files; ++i) {
    if (strcmp(r->files[i], path) != 0) continue;
    if (r->file_tried[i]) return 0;
    r->file_tried[i] = 1;
    break;
  }
  for (int i = 0; i < r->n_libraries; ++i)
    if (strcmp(r->libraries[i]->path, path) == 0) return 0;
  if (load_from_path(r, path)) return sl_diag_set(d, SL_ENOMEM, "out of memory while loading %s", path);
  return 0;
}

/* Opens the files that hold (kind, name): those the indexes name for it and,
 * in a folder without an index, the one named <kind>_<name>.so; with
 * `library`, only among the files it names. Nothing else is opened. */
static int load_candidates(sl_registry *r, sl_kind kind, const char *name, const char *library, sl_diag *d) {
  for (int i = 0; i < r->n_index; ++i) {
    const struct sl_index_entry *e = &r->index[i];
    if (e->kind != kind || strcmp(e->name, name) != 0 || !file_matches(e->path, library)) continue;
    int rc = open_listed(r, e->path, d);
    if (rc) return rc;
  }
  char want[512];
  snprintf(want, sizeof want, "%s_%s.so", sl_kind_name(kind), name);
  for (int i = 0; i < r->n_files; ++i) {
    if (r->file_tried[i] || r->dir_indexed[r->file_dir[i]]) continue;
    if (strcmp(base_name(r->files[i]), want) != 0 || !file_matches(r->files[i], library)) continue;
    int rc = open_listed(r, r->files[i], d);
    if (rc) return rc;
  }
  return 0;
}

/* ---- what unindexed libraries hold, read in a child process ---- */

typedef struct child_list {
  sl_registry *r;
  const char *const *files;
  int n;
  char current[PATH_MAX]; /* the file the child was reading */
  int rc;
} child_list;

static int list_in_child(void *user, int fd) {
  child_list *cl = user;
  for (int i = 0; i < cl->n; ++i) {
    sl_isolate_say(fd, "@%s", cl->files[i]);
    sl_library *lib;
    sl_diag why;
    long n_open = 0;
    if (open_library(cl->files[i], &lib, &n_open, &why)) {
      sl_isolate_say(fd, "!%s", why.msg);
      continue;
    }
    for (int32_t k = 0; k < lib->n_closures; ++k)
      sl_isolate_say(fd, "=%s %s", sl_kind_name(lib->closures[k]->kind), lib->closures[k]->name);
  }
  return 0;
}

static void list_line(void *user, const char *line) {
  child_list *cl = user;
  if (cl->rc) return;
  if (line[0] == '@') {
    snprintf(cl->current, sizeof cl->current, "%s", line + 1);
  } else if (line[0] == '!') {
    if (add_problem(cl->r, line + 1)) cl->rc = SL_ENOMEM;
  } else if (line[0] == '=') {
    char kind_s[128], name[256];
    sl_kind kind;
    sl_diag why;
    if (sscanf(line + 1, "%127s %255s", kind_s, name) == 2 && !sl_kind_from_name(kind_s, &kind, &why))
      if (index_add(cl->r, kind, name, cl->current)) cl->rc = SL_ENOMEM;
  }
}

/* Reads the descriptors of `files` in a child process, into r->index (and
 * r->problems for the libraries that cannot be used). */
static int list_files_in_child(sl_registry *r, const char *const *files, int n, sl_diag *d) {
  if (n == 0) return 0;
  child_list cl = {.r = r, .files = files, .n = n};
  sl_child_outcome o;
  /* a library that hangs in its constructor: 10 s without news */
  if (sl_isolate(list_in_child, &cl, list_line, &cl, 10.0, &o))
    return sl_diag_set(d, SL_EFAILED, "cannot start a process to read the closure libraries: %s", strerror(errno));
  if (cl.rc) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  if (o.signal || o.timed_out || (o.exited && o.status)) {
    char msg[PATH_MAX + 200];
    if (o.timed_out)
      snprintf(msg, sizeof msg, "%s: did not finish loading within 10 s (read in a child process, stopped)",
               cl.current);
    else if (o.signal)
      snprintf(msg, sizeof msg, "%s: crashed with %s while loading (read in a child process)", cl.current,
               sl_signal_name(o.signal));
    else snprintf(msg, sizeof msg, "%s: called exit(%d) while loading (read in a child process)", cl.current, o.status);
    if (add_problem(r, msg)) return sl_diag_set(d, SL_ENOMEM, "out of memory");
    /* the files after the one that failed: read them on their own */
    int at = 0;
    while (at < n && strcmp(files[at], cl.current) != 0) ++at;
    if (at + 1 < n) return list_files_in_child(r, files + at + 1, n - at - 1, d);
  }
  return 0;
}

/* The libraries of unindexed folders whose names say nothing, read once. */
static int list_unindexed(sl_registry *r, sl_diag *d) {
  if (r->children_listed) return 0;
  r->children_listed = 1;
  const char **files = malloc((size_t)(r->n_files > 0 ? r->n_files : 1) * sizeof *files);
  if (!files) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  int n = 0;
  for (int i = 0; i < r->n_files; ++i)
    if (!r->dir_indexed[r->file_dir[i]] && !conventional_name(base_name(r->files[i]))) files[n++] = r->files[i];
  int rc = list_files_in_child(r, files, n, d);
  free(files);
  return rc;
}

int sl_registry_write_index(const char *dir, int *n_closures, sl_diag *d) {
  *n_closures = 0;
  sl_registry *r;
  int rc = sl_registry_create(&r, NULL, 0, d);
  if (rc) return rc;
  char **names = NULL;
  int n = 0;
  if (list_libraries(dir, &names, &n)) {
    sl_registry_destroy(r);
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
  }
  char **paths = calloc((size_t)(n > 0 ? n : 1), sizeof *paths);
  for (int k = 0; k < n && paths; ++k) {
    size_t len = strlen(dir) + strlen(names[k]) + 2;
    if ((paths[k] = malloc(len))) snprintf(paths[k], len, "%s/%s", dir, names[k]);
  }
  if (!paths) rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
  for (int k = 0; k < n && !rc; ++k)
    if (!paths[k]) rc = sl_diag_set(d, SL_ENOMEM, "out of memory");
  if (!rc) rc = list_files_in_child(r, (const char *const *)paths, n, d);
  char tmp[PATH_MAX], final[PATH_MAX];
  snprintf(final, sizeof final, "%s/%s", dir, SL_PLUGIN_INDEX_FILE);
  snprintf(tmp, sizeof tmp, "%s/.%s.tmp", dir, SL_PLUGIN_INDEX_FILE);
  FILE *f = NULL;
  if (!rc && !(f = fopen(tmp, "w"))) rc = sl_diag_set(d, SL_EFAILED, "%s: cannot write: %s", tmp, strerror(errno));
  if (!rc) {
    fprintf(f, "# sluice closure index: kind name library (in this folder); written by `sluice closure index`\n");
    for (int i = 0; i < r->n_index; ++i)
      fprintf(f, "%s %s %s\n", sl_kind_name(r->index[i].kind), r->index[i].name, base_name(r->index[i].path));
    if (fclose(f) != 0) rc = sl_diag_set(d, SL_EFAILED, "%s: cannot write", tmp);
    else if (rename(tmp, final) != 0) rc = sl_diag_set(d, SL_EFAILED, "%s: cannot write: %s", final, strerror(errno));
    if (rc) remove(tmp);
  }
  if (!rc) {
    *n_closures = r->n_index;
    size_t at = 0;
    d->msg[0] = '\0';
    for (int i = 0; i < r->n_problems && at < sizeof d->msg; ++i)
      at += (size_t)snprintf(d->msg + at, sizeof d->msg - at, "%sskipped %s", i ? "\n" : "", r->problems[i]);
  }
  for (int k = 0; k < n; ++k) free(names[k]), free(paths ? paths[k] : NULL);
  free(names), free(paths);
  sl_registry_destroy(r);
  return rc;
}

static int library_matches(const sl_library *lib, const char *library) {
  if (!library) return 1;
  if (strchr(library, '/')) return same_file(lib->path, library);
  const char *base = strrchr(lib->path, '/');
  base = base ? base + 1 : lib->path;
  return strcmp(base, library) == 0;
}

static int find_loaded(const sl_registry *r, sl_kind kind, const char *name, const char *library,
                       const sl_closure_entry **entry, sl_diag *d);

int sl_registry_find(const sl_registry *r, sl_kind kind, const char *name, const char *library,
                     const sl_closure_entry **entry, sl_diag *d) {
  if (!r->lazy) return find_loaded(r, kind, name, library, entry, d);
  /* The indexes open what the look-up needs: the registry is a cache behind
   * its const interface (registry.h). */
  sl_registry *cache = (sl_registry *)r;
  int rc = load_candidates(cache, kind, name, library, d);
  if (rc) return rc;
  sl_diag quiet;
  if (find_loaded(r, kind, name, library, entry, &quiet) == 0) return 0;
  /* What the unindexed libraries hold (read in a child), then once more. */
  if ((rc = list_unindexed(cache, d))) return rc;
  if ((rc = load_candidates(cache, kind, name, library, d))) return rc;
  if ((rc = find_loaded(r, kind, name, library, entry, d)) == 0) return 0;
  if (rc != SL_EBADINPUT || strstr(d->msg, "provided by two libraries")) return rc;
  /* `library` picks among the libraries of the search path, never adds one. */
  if (library) {
    int on_path = 0;
    for (int i = 0; i < r->n_files && !on_path; ++i) on_path = file_matches(r->files[i], library);
    if (!on_path)
      return sl_diag_set(d, SL_EBADINPUT,
                         "library = %s is not a library on the plugin search path (it only says which of the "
                         "libraries there provides %s closure '%s'; a scene cannot add one)",
                         library, sl_kind_name(kind), name);
  }
  /* An index names a library for it that could not be used: say why. */
  for (int i = 0; i < r->n_index; ++i) {
    const struct sl_index_entry *e = &r->index[i];
    if (e->kind != kind || strcmp(e->name, name) != 0 || !file_matches(e->path, library)) continue;
    size_t len = strlen(e->path);
    for (int k = 0; k < r->n_problems; ++k)
      if (!strncmp(r->problems[k], e->path, len) && r->problems[k][len] == ':')
        return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s': its index names %s, which cannot be used: %s",
                           sl_kind_name(kind), name, e->path, r->problems[k] + len + 2);
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s closure '%s': its index names %s, which does not hold it (write the "
                       "folder's index again: sluice closure index DIR)",
                       sl_kind_name(kind), name, e->path);
  }
  /* Refused with no further library opened: a did-you-mean over the names
   * the indexes list as well as those loaded. */
  const char *cands[512];
  int nc = 0;
  for (int i = 0; i < r->n_index && nc < 512; ++i)
    if (r->index[i].kind == kind && file_matches(r->index[i].path, library)) cands[nc++] = r->index[i].name;
  for (int i = 0; i < r->n_entries && nc < 512; ++i)
    if (r->entries[i].desc->kind == kind && library_matches(r->entries[i].library, library))
      cands[nc++] = r->entries[i].desc->name;
  const char *s = sl_suggest(name, cands, nc);
  if (library)
    rc = sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s' in library '%s'%s%s%s", sl_kind_name(kind), name, library,
                     s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
  else if (s) rc = sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s'; did you mean '%s'?", sl_kind_name(kind), name, s);
  else
    rc = sl_diag_set(d, SL_EBADINPUT, "no %s closure '%s' on the plugin search path (`sluice closures` lists them)",
                     sl_kind_name(kind), name);
  char want[512]; /* a library named for it that could not be used: say why */
  snprintf(want, sizeof want, "/%s_%s.so:", sl_kind_name(kind), name);
  for (int i = 0; i < r->n_problems; ++i)
    if (strstr(r->problems[i], want)) return sl_diag_prefix(d, rc, "%s; and", r->problems[i]);
  return rc;
}

static int find_loaded(const sl_registry *r, sl_kind kind, const char *name, const char *library,
                       const sl_closure_entry **entry, sl_diag *d) {
  *entry = NULL;
  const sl_closure_entry *first = NULL;
  int n_match = 0;
  for (int i = 0; i < r->n_entries; ++i) {
    const sl_closure_entry *e = &r->entries[i];
    if (e->desc->kind != kind || strcmp(e->desc->name, name) != 0 || !library_matches(e->library, library)) continue;
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

void sl_registry_set_timing(sl_registry *r, int on) {
  r->timing = on != 0;
  for (int i = 0; i < r->n_libraries; ++i) r->libraries[i]->timing = r->timing;
}

int sl_registry_files_on_path(const sl_registry *r) { return r->lazy ? r->n_files : r->n_libraries + r->n_problems; }
