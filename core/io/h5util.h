/* Private to core/io: HDF5 helpers that turn failures into sl_diag messages
 * naming the file and the object, and the writer's state shared by the
 * output and checkpoint code. */
#ifndef SLUICE_IO_H5UTIL_H
#define SLUICE_IO_H5UTIL_H

#include <hdf5.h>
#include <stdint.h>

#include "core/io/output.h"
#include "core/util/diag.h"

/* HDF5 prints its error stack by default; we report through sl_diag. */
void sl_h5_quiet(void);

/* "<file>: <what> <object> (HDF5: <innermost message>)"; clears the stack. */
int sl_h5_fail(sl_diag *d, int code, const char *file, const char *what, const char *object);

/* Object names: letters, digits, '_', '-', '.', not starting with '.', at
 * most max_len bytes (safe as an HDF5 link and inside XDMF paths). */
int sl_io_check_name(const char *name, int max_len, const char *what, sl_diag *d);

/* Scalar attributes, replacing an existing one of the same name. */
int sl_h5_attr_double(hid_t loc, const char *name, double v, const char *file, const char *obj, sl_diag *d);
int sl_h5_attr_int64(hid_t loc, const char *name, int64_t v, const char *file, const char *obj, sl_diag *d);
int sl_h5_attr_int32(hid_t loc, const char *name, int32_t v, const char *file, const char *obj, sl_diag *d);
int sl_h5_attr_string(hid_t loc, const char *name, const char *s, const char *file, const char *obj, sl_diag *d);
/* A scalar fixed-length string dataset (NULL-terminated, UTF-8). */
int sl_h5_dataset_string(hid_t loc, const char *name, const char *s, const char *file, const char *obj, sl_diag *d);

int sl_h5_read_attr_double(hid_t loc, const char *name, double *v, const char *file, const char *obj, sl_diag *d);
int sl_h5_read_attr_int64(hid_t loc, const char *name, int64_t *v, const char *file, const char *obj, sl_diag *d);
/* Reads a string attribute into buf (truncated to len - 1). */
int sl_h5_read_attr_string(hid_t loc, const char *name, char *buf, size_t len, const char *file, const char *obj,
                           sl_diag *d);

/* Read-only open without HDF5's file lock (see output.h). */
int sl_h5_open_read(const char *path, hid_t *file, sl_diag *d);

/* Names of the links in a group, in name order. Free with sl_io_free_names. */
int sl_h5_list(hid_t group, char ***names, int *n, const char *file, const char *obj, sl_diag *d);
void sl_io_free_names(char **names, int n);

/* The writer (output.c); checkpoint.c writes into the same file. */
typedef struct sl_out_step {
  int index;
  double time;
  char *xml; /* this step's <Grid> for the sidecar */
} sl_out_step;

typedef struct sl_out_field {
  char *name;
  sl_centring centring;
  int components; /* as stored: 1 or 3 */
  int32_t n;
} sl_out_field;

struct sl_output {
  char *path, *xmf_path, *xmf_tmp;
  const char *h5_name; /* base name of path, used inside the sidecar */
  hid_t file;
  int have_mesh, dim, nodes_per_cell;
  int32_t n_vertices, n_cells;
  char topology[32];
  int in_step, next_index;
  double step_time;
  hid_t step_group;
  int n_fields, cap_fields; /* the fields of the open step */
  sl_out_field *fields;
  int n_steps, cap_steps; /* completed steps, for the sidecar */
  sl_out_step *steps;
  int ck_current; /* slot of the last complete checkpoint, -1 for none */
  long n_datasets; /* fields written, over all steps */
  double bytes;    /* their values, as stored */
};

#endif
