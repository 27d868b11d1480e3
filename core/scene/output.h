/* A scene's output: the file (the command line's -o, else [output] file,
 * else the scene file's name with .h5 for .ini, in the current folder) and
 * the fields chosen in [output] fields. */
#ifndef SLUICE_MODELS_SCENE_OUTPUT_H
#define SLUICE_MODELS_SCENE_OUTPUT_H

#include <stddef.h>

#include "core/config/ini.h"
#include "core/io/output.h"
#include "core/plugin/instance.h"

/* override: -o (NULL: none); scene_path: the scene file (NULL: "sluice").
 * Writes the path into path[cap]. Returns 0 or the error of reading
 * [output] file (d set). */
int sl_scene_output_path(const sl_ini *ini, const char *override, const char *scene_path, char *path, size_t cap,
                         sl_diag *d);

/* [output] fields = a, b, ...: bit k of *mask for names[k]; an empty or
 * absent list gives default_mask. An unknown name is SL_EBADINPUT with its
 * file:line, a suggestion and the known names. */
int sl_scene_output_fields(const sl_ini *ini, const char *const *names, int n_names, unsigned default_mask,
                           unsigned *mask, sl_diag *d);

/* The provenance record of a closure in use under [role]: its kind, name,
 * version, library and parameters, the parameters written into buf[len]
 * as "key = value" lines (buf must live until the record is written). */
sl_provenance_closure sl_scene_closure_provenance(const sl_closure *cl, const char *role, char *buf, size_t len);

#endif
