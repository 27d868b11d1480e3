/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Closure libraries: the search path, loading with dlopen, validation of
 * every descriptor against the ABI, and look-up by (kind, name).
 *
 * Search order (closure-abi.md rule 10): folders named by the scene, then
 * SLUICE_PLUGIN_PATH (colon-separated), then the plugin folder that belongs
 * to this sluice (the build tree's when run from it, else the install's).
 *
 * Two ways to fill a registry: sl_registry_scan loads every library of the
 * search path (listings, `closure describe`); sl_registry_index only reads
 * what each folder holds, and sl_registry_find then opens the one library
 * that holds the closure looked up, and nothing else (docs/trust-plugins.md):
 *  - a folder with an index file (closures.index, written by the build and
 *    the install; `sluice closure index DIR` for any other) says which file
 *    holds which (kind, name): look-ups read it and open only that file;
 *  - in a folder without one, a file named <kind>_<name>.so after a known
 *    kind is taken to hold that closure; what any other library holds is
 *    read in a child process (its code never runs in sluice itself) the
 *    first time a name is not found otherwise.
 * A name found nowhere is refused with a did-you-mean over the names the
 * indexes list, with no library opened. */
#ifndef SLUICE_PLUGIN_REGISTRY_H
#define SLUICE_PLUGIN_REGISTRY_H

#include <sluice/closure.h>

#include "core/util/diag.h"

/* What the closures of one descriptor did during a run (profile): folded in
 * when an instance is destroyed. */
typedef struct sl_closure_usage {
  long instances;            /* created */
  unsigned long long calls;  /* batched evaluations */
  unsigned long long points; /* points evaluated */
  double seconds;            /* wall seconds inside evaluate, when timed (sl_registry_set_timing) */
} sl_closure_usage;

typedef struct sl_library {
  char *path;   /* as found on the search path */
  void *handle; /* dlopen handle */
  int32_t n_closures;
  const sl_closure_desc *const *closures;
  int n_in_use;            /* closures created from this library */
  sl_closure_usage *usage; /* [n_closures] */
  int timing;              /* instances created from now on time their evaluations */
} sl_library;

typedef struct sl_closure_entry {
  const sl_closure_desc *desc;
  sl_library *library;
} sl_closure_entry;

typedef struct sl_registry {
  int n_dirs;
  char **dirs;
  int n_libraries, cap_libraries;
  sl_library **libraries;
  int n_entries, cap_entries;
  sl_closure_entry *entries;
  int n_problems; /* libraries on the search path that could not be used */
  char **problems;
  /* sl_registry_index: the library files of the search path, in search
   * order, and whether each has been opened yet */
  int lazy;
  int n_files;
  char **files;
  unsigned char *file_tried;
  int *file_dir;              /* the folder of each file (index into dirs) */
  unsigned char *dir_indexed; /* [n_dirs]: the folder has an index file */
  int children_listed;        /* the unindexed libraries were listed in a child */
  int n_index, cap_index;     /* what the indexes (and the child listings) say */
  struct sl_index_entry {
    sl_kind kind;
    char *name, *path;
  } * index;
  long n_dlopen; /* libraries dlopen'ed (kept or refused) */
  int timing;    /* see sl_registry_set_timing */
} sl_registry;

/* An empty registry with the search path built from `scene_dirs` (may be
 * NULL), SLUICE_PLUGIN_PATH and the default folder. */
int sl_registry_create(sl_registry **out, const char *const *scene_dirs, int n_scene_dirs, sl_diag *d);
void sl_registry_destroy(sl_registry *r);

/* Loads every *.so of the search path. A library that fails validation is not
 * added; its message is kept in r->problems (listed by `sluice closures`). */
int sl_registry_scan(sl_registry *r, sl_diag *d);

/* Lists the *.so files of the search path without loading any: look-ups
 * load them as needed (see the top of this file). */
int sl_registry_index(sl_registry *r, sl_diag *d);

/* Loads one library, strictly: any problem is an error (SL_EBADINPUT) whose
 * message names the file and what is wrong. *lib may be NULL. Loading the
 * same file twice returns the library already loaded. */
int sl_registry_add_library(sl_registry *r, const char *path, sl_library **lib, sl_diag *d);

/* Looks up (kind, name). When two libraries provide it, `library` (a path or
 * a file name, may be NULL) says which one wins; without it that is an error.
 * Unknown names get a did-you-mean among the closures of that kind.
 * After sl_registry_index the look-up may load libraries: the registry is a
 * cache of what it has loaded, and *entry is valid until the next look-up. */
int sl_registry_find(const sl_registry *r, sl_kind kind, const char *name, const char *library,
                     const sl_closure_entry **entry, sl_diag *d);

/* The index file of a plugin folder. */
#define SL_PLUGIN_INDEX_FILE "closures.index"

/* Writes DIR/closures.index for the libraries in DIR, read in a child
 * process; *n_closures is the number of closures listed. Libraries that
 * cannot be used are named in d's message when nothing could be listed. */
int sl_registry_write_index(const char *dir, int *n_closures, sl_diag *d);

/* The default plugin folder of this sluice (static storage). */
const char *sl_registry_default_dir(void);

/* Number of libraries with at least one closure in use. */
int sl_registry_libraries_in_use(const sl_registry *r);

/* Closures created after this call time each evaluation (two clock reads per
 * batch, into sl_closure_usage.seconds); off by default. */
void sl_registry_set_timing(sl_registry *r, int on);

/* The library file names on the search path: sl_registry_index's count, or
 * after a scan the libraries found (loaded or refused). */
int sl_registry_files_on_path(const sl_registry *r);

#endif
