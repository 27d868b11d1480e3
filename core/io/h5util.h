/* SPDX-License-Identifier: GPL-2.0-or-later */
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
/* A scalar string dataset (variable-length UTF-8). */
int sl_h5_dataset_string(hid_t loc, const char *name, const char *s, const char *file, const char *obj, sl_diag *d);

int sl_h5_read_attr_double(hid_t loc, const char *name, double *v, const char *file, const char *obj, sl_diag *d);
int sl_h5_read_attr_int64(hid_t loc, const char *name, int64_t *v, const char *file, const char *obj, sl_diag *d);
/* A string attribute (is_attr) or dataset, variable or fixed length, into a
 * malloc'ed text; -1 when obj holds no string (the HDF5 error stack is left
 * for sl_h5_fail). */
int sl_h5_read_string(hid_t obj, int is_attr, char **text);
/* Reads a string attribute into buf (truncated to len - 1). */
int sl_h5_read_attr_string(hid_t loc, const char *name, char *buf, size_t len, const char *file, const char *obj,
                           sl_diag *d);

/* Read-only open without HDF5's file lock (see output.h). */
int sl_h5_open_read(const char *path, hid_t *file, sl_diag *d);

/* Names of the links in a group, in name order. Free with sl_io_free_names. */
int sl_h5_list(hid_t group, char ***names, int *n, const char *file, const char *obj, sl_diag *d);
void sl_io_free_names(char **names, int n);

/* The writer (output.c); checkpoint.c writes into the same file, sidecar.c
 * the XDMF and CSV files beside it, policy.c decides what may be replaced. */
typedef struct sl_out_field {
  char *name;
  sl_centring centring;
  int components; /* as stored: 1 or 3 */
  int32_t n;
} sl_out_field;

typedef struct sl_out_scalar {
  char *name;
  char unit[SL_OUTPUT_UNIT_MAX];
  double value;
} sl_out_scalar;

struct sl_output {
  char *path;     /* the name the user gave: messages, the final name */
  char *tmp_path; /* written under this name until the first output time is complete */
  char *xmf_path, *csv_path;
  const char *h5_name; /* base name of path, used inside the sidecar */
  int committed;       /* renamed to path: the old result is gone */
  int collective;      /* every rank writes this file (collective.c); rank, ranks then MPI_COMM_WORLD's */
  int rank, ranks;
  double bytes_here, bytes_all; /* of the values (fields, mesh, checkpoints): this rank's, all ranks' */
  long n_collective;            /* of those writes HDF5 made collectively */
  hid_t file;
  int have_mesh, dim, nodes_per_cell;
  int32_t n_vertices, n_cells;
  char topology[32];
  int in_step, next_index;
  double step_time;
  hid_t step_group;
  int n_fields, cap_fields; /* the fields of the open step */
  sl_out_field *fields;
  int n_scalars, cap_scalars; /* the scalars of the open step */
  sl_out_scalar *scalars;
  long n_steps;    /* completed steps */
  int ck_current;  /* slot of the last complete checkpoint, -1 for none */
  long n_datasets; /* fields written, over all steps */
  double bytes;    /* their values, as stored */
  /* sidecar.c: the .xmf, rewritten whole only for its first two output
   * times, then extended in place; the CSV of the scalars */
  int xmf_fd;
  long xmf_tail;    /* offset of the closing tags */
  char *first_grid; /* the first output time's grid body, until the second */
  double first_time;
  int first_index;
  int csv_fd;
  int n_cols, cap_cols; /* scalar names of all output times, in order of appearance */
  char **col_names;
  char (*col_units)[SL_OUTPUT_UNIT_MAX];
  long n_rows, cap_rows; /* one row per output time: time, then n_cols values (NaN: absent) */
  double *rows;
  int row_stride; /* of rows: 1 + n_cols when they were stored */
  long csv_end;
};

/* Closes every object of the file still open, then the file (after a
 * failed write a dataset whose close failed stays open); H5Fclose's status. */
herr_t sl_h5_close_all(hid_t file);

/* collective.c: one file written by every rank (parallel HDF5) */
/* Makes o collective: rank and ranks from MPI_COMM_WORLD (SL_EBADINPUT
 * when HDF5 is serial or MPI is not started). */
int sl_io_collective_start(sl_output *o, sl_diag *d);
/* A file-access property list: the MPI-IO driver when collective; close it. */
hid_t sl_io_fapl(const sl_output *o);
/* The largest of the ranks' codes, on every rank (rc when not collective). */
int sl_io_agree(const sl_output *o, int rc);
void sl_io_barrier(const sl_output *o);
/* This process writes the sidecars and renames and removes files. */
int sl_io_rank0(const sl_output *o);
/* Writes a dataset of n rows of width elements of elem bytes (rank 1: width
 * 1) from buf, all n rows: the whole when not collective, else this rank's
 * block [r n / N, (r + 1) n / N) in one collective transfer. < 0 on failure. */
int sl_io_write_rows(sl_output *o, hid_t ds, hid_t mtype, size_t elem, hsize_t n, hsize_t width, const void *buf);
/* fn(o, arg, d) on rank 0 alone, into the file the ranks closed for it (what
 * parallel HDF5 cannot write: variable-length strings); then every rank
 * opens it again. Just fn when not collective. */
int sl_io_serial_interlude(sl_output *o, int (*fn)(sl_output *, const void *, sl_diag *), const void *arg, sl_diag *d);

/* output.c: the file takes its name (the first complete output time or
 * checkpoint); the old sidecars go. */
int sl_output_commit(sl_output *o, sl_diag *d);

/* sidecar.c */
/* The open step's grid body (Topology, Geometry, Attributes), NULL on no memory. */
char *sl_sidecar_grid(const sl_output *o, int index);
/* After a step is complete: the .xmf and the CSV brought up to date. */
int sl_sidecar_step(sl_output *o, sl_diag *d);
void sl_sidecar_free(sl_output *o);

/* policy.c */
/* Files sluice wrote: an HDF5 file with the root attribute format =
 * "sluice-output ..." (or, older, /provenance@sluice_version), an .xmf
 * naming itself written by sluice or pointing at its h5, a CSV whose header
 * starts "time [s]". */
int sl_io_is_sluice_h5(const char *path);
/* OUT.h5 -> OUT.xmf, OUT_scalars.csv and the temporary OUT.h5.tmp, each
 * malloc'ed; SL_ENOMEM (all NULL) on no memory. */
int sl_io_output_names(const char *path, char **xmf, char **csv, char **tmp);

/* space.c: SL_EFAILED with a message when the file system or the file size
 * limit has no room for `bytes` more (what: "the mesh", "field 'phi'", ...). */
int sl_io_space_check(const sl_output *o, double bytes, const char *what, sl_diag *d);

/* units.c: the unit of a field or scalar known by name, "" if not known. */
const char *sl_io_default_unit(const char *name);

#endif
