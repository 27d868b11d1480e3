/* Closure libraries: the search path, loading with dlopen, validation of
 * every descriptor against the ABI, and look-up by (kind, name).
 *
 * Search order (closure-abi.md rule 10): folders named by the scene, then
 * SLUICE_PLUGIN_PATH (colon-separated), then the plugin folder that belongs
 * to this sluice (the build tree's when run from it, else the install's).
 *
 * Two ways to fill a registry: sl_registry_scan loads every library of the
 * search path (listings, `closure describe`); sl_registry_index only lists
 * the files, and sl_registry_find then loads what a look-up needs (a run: the
 * closures a scene does not name are not loaded). A file named
 * <kind>_<name>.so after a known kind (the built-in closures' names) is taken
 * to provide that closure and is opened only for it; any other library is
 * opened at the first look-up, since only its descriptors say what it holds.
 * A name found nowhere that way loads the rest of the path before the
 * look-up is refused, so both ways find the same closures. */
#ifndef SLUICE_PLUGIN_REGISTRY_H
#define SLUICE_PLUGIN_REGISTRY_H

#include <sluice/closure.h>

#include "core/util/diag.h"

/* What the closures of one descriptor did during a run (profile): folded in
 * when an instance is destroyed. */
typedef struct sl_closure_usage {
  long instances;                /* created */
  unsigned long long calls;      /* batched evaluations */
  unsigned long long points;     /* points evaluated */
  double seconds;                /* wall seconds inside evaluate, when timed (sl_registry_set_timing) */
} sl_closure_usage;

typedef struct sl_library {
  char *path;   /* as found on the search path */
  void *handle; /* dlopen handle */
  int32_t n_closures;
  const sl_closure_desc *const *closures;
  int n_in_use; /* closures created from this library */
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
