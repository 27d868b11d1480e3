/* SPDX-License-Identifier: GPL-2.0-or-later */
/* HDF5 output with an XDMF sidecar that ParaView opens as is, a CSV of the
 * per-output scalars, provenance, checkpoints for restart, and readers.
 *
 * Takes plain arrays, not a mesh struct. File layout (all 0-based; docs/output.md):
 *   /                           attribute format = "sluice-output 1" (how sluice knows its own files)
 *   /mesh/coordinates           n_vertices x 3, F64LE (1-D and 2-D padded with 0); attribute units
 *   /mesh/topology              n_cells x nodes_per_cell, I32LE; attributes topology_type, dim
 *   /mesh/cell_centres          n_cells x 3, F64LE: the centroid of each cell's corner polygon
 *   /step_NNNNNN/<field>        n or n x 3, F64LE; attributes centring, components, units
 *   /step_NNNNNN                attributes time (F64LE), index (I32LE), complete, and the scalars (F64LE)
 *   /scalar_units               one string attribute per scalar name: its unit
 *   /provenance                 attributes sluice_version, blas (which BLAS ran); dataset ini; closures/closure_NNN
 *   /checkpoint                 two slots, attribute current: the last complete one
 * Strings are variable-length UTF-8.
 *
 * Safe replacement: the file is written as OUT.h5.tmp and renamed to OUT.h5
 * when its first output time is complete, so a run that fails before that
 * (set-up, a restart that does not fit, a full disk) leaves an earlier
 * OUT.h5, OUT.xmf and OUT_scalars.csv as they were. From then on every
 * complete output time is flushed: a run killed between output times leaves
 * a file that h5dump and ParaView read (a crash in the middle of a step can
 * still leave an unreadable file: HDF5 1.10 without SWMR gives no stronger
 * guarantee).
 *
 * OUT.xmf (next to OUT.h5, same stem): one Uniform grid while the file has
 * one output time (what meshio.read opens), a temporal collection from the
 * second on; it is extended in place at each output time (no temporary
 * file), the scalars as Center="Grid" attributes. OUT_scalars.csv: one row
 * per output time, one column per scalar, the units in the header; written
 * when the model has scalars.
 *
 * Every function returns 0 or an SL_E* code with a message naming the file
 * and the dataset: SL_EBADINPUT for caller mistakes and bad paths (nothing
 * written), SL_EFAILED for I/O failures during the run. */
#ifndef SLUICE_IO_OUTPUT_H
#define SLUICE_IO_OUTPUT_H

#include <stdint.h>

#include "core/util/diag.h"

typedef enum sl_centring { SL_CENTRE_NODE = 0, SL_CENTRE_CELL = 1 } sl_centring;

typedef struct sl_output sl_output;

enum { SL_OUTPUT_UNIT_MAX = 32 };

/* What a run may write (the trust model, docs/output.md). A file that
 * exists is replaced only when sluice wrote it (an output file, its .xmf or
 * its CSV) or with overwrite; `protect` (the scene file) and `protect_more`
 * (the files it includes) never. A path from
 * the scene file (from_scene) must lie in scene_dir or the working folder,
 * or below them. */
typedef struct sl_output_opts {
  int from_scene;
  const char *scene_dir; /* NULL: the working folder only */
  int overwrite;
  const char *protect; /* may be NULL */
  /* more files never replaced (the files the scene includes) */
  const char *const *protect_more;
  int n_protect_more;
  /* every rank of MPI_COMM_WORLD opens the file together and writes its
   * block of each dataset's rows (parallel HDF5; collective.c); the ranks
   * make the same calls with the same values. The PETSc build only. */
  int collective;
} sl_output_opts;

/* The checks sl_output_open_opts makes, creating nothing (SL_EBADINPUT with
 * the reason and what to do). */
int sl_output_check_path(const char *path, const sl_output_opts *opts, sl_diag *d);

/* Checks the path (above) and creates the HDF5 file under its temporary
 * name. A missing directory is SL_EBADINPUT with a message saying so. */
int sl_output_open_opts(sl_output **out, const char *path, const sl_output_opts *opts, sl_diag *d);
/* With the default opts: not from a scene, no overwrite. */
int sl_output_open(sl_output **out, const char *path, sl_diag *d);
/* The run failed: closes and frees. Before the first complete output time
 * (or checkpoint) the new file is removed and what was there before stays:
 * returns 0 then, 1 when the file was kept. */
int sl_output_abort(sl_output *out);

/* Once, before the first step. coords: n_vertices x dim (dim 1..3), cells:
 * n_cells x nodes_per_cell, 0-based. topology: the XDMF name, one of
 * "Polyline" (2 nodes), "Triangle" (3), "Quadrilateral" (4), "Triangle_6",
 * "Quadrilateral_9"; it must match nodes_per_cell. */
int sl_output_write_mesh(sl_output *out, int dim, int32_t n_vertices, const double *coords, int32_t n_cells,
                         int nodes_per_cell, const int32_t *cells, const char *topology, sl_diag *d);

/* One output time: begin, write the fields, end (flush + sidecar). */
int sl_output_begin_step(sl_output *out, double t, sl_diag *d);
/* values: n x components, row-major, n = n_vertices (node) or n_cells (cell).
 * components 1 (scalar), 2 (stored padded to 3) or 3 (vector). */
int sl_output_write_field(sl_output *out, const char *name, sl_centring centring, int components, const double *values,
                          sl_diag *d);
/* The same with its unit (SI, e.g. "m/s", "Pa", "1" for a pure number);
 * sl_output_write_field takes the unit known for the name (units.c). */
int sl_output_write_field_unit(sl_output *out, const char *name, const char *unit, sl_centring centring, int components,
                               const double *values, sl_diag *d);
int sl_output_end_step(sl_output *out, sl_diag *d);
/* A number belonging to the open output time (an attribute of its group):
 * diagnostics such as the solids inventory. */
int sl_output_write_scalar(sl_output *out, const char *name, double value, sl_diag *d);
int sl_output_write_scalar_unit(sl_output *out, const char *name, const char *unit, double value, sl_diag *d);
/* The scalar `name` of the output time nearest t (sl_output_read_field's
 * choice of time). */
int sl_output_read_scalar(const char *path, const char *name, double t, double *value, double *t_found, sl_diag *d);

/* Provenance. Written when called (at the start of a run, so an interrupted
 * run has it); calling again replaces it. */
typedef struct sl_provenance_closure {
  const char *role; /* INI section, e.g. "closure.drag" (may be NULL) */
  const char *kind;
  const char *name;
  const char *version;
  const char *library;    /* path of the shared object */
  const char *parameters; /* resolved parameters as text, e.g. "n = 4.65\n" */
} sl_provenance_closure;

typedef struct sl_provenance {
  const char *sluice_version;
  const char *ini_text; /* the resolved INI, overrides applied */
  int n_closures;
  const sl_provenance_closure *closures;
} sl_provenance;

int sl_output_write_provenance(sl_output *out, const sl_provenance *p, sl_diag *d);

/* Checkpoint: named double arrays plus scalars, enough to restart. */
enum { SL_CHECKPOINT_MAX_INTS = 16, SL_CHECKPOINT_NAME_MAX = 64 };

typedef struct sl_checkpoint_array {
  char name[SL_CHECKPOINT_NAME_MAX];
  int64_t n;
  const double *data; /* writer: the caller's; reader: allocated, freed by sl_checkpoint_free */
} sl_checkpoint_array;

typedef struct sl_checkpoint {
  double time, dt;
  int64_t step;
  int n_ints;
  char int_names[SL_CHECKPOINT_MAX_INTS][SL_CHECKPOINT_NAME_MAX];
  int64_t ints[SL_CHECKPOINT_MAX_INTS];
  int n_arrays;
  sl_checkpoint_array *arrays; /* writer: the caller's; reader: allocated */
} sl_checkpoint;

/* Writes into the slot not holding the last checkpoint, flushes, then marks
 * it current: a crash while checkpointing leaves the previous one intact. */
int sl_output_write_checkpoint(sl_output *out, const sl_checkpoint *ck, sl_diag *d);

/* What has been written so far: complete output times, field datasets and
 * the bytes of their values. */
void sl_output_stats(const sl_output *out, long *times, long *datasets, double *bytes);
/* The bytes of values (fields, mesh, checkpoints) this rank wrote, those
 * all ranks wrote, and in how many collective transfers this rank's went
 * (0 when not collective). */
void sl_output_rank_stats(const sl_output *out, double *here, double *all, long *collective);

/* Flushes, closes and frees (also after failures); a file with no complete
 * output time yet is renamed to its name now. */
int sl_output_close(sl_output *out, sl_diag *d);

/* Removes an output: OUT.h5, OUT.xmf, OUT_scalars.csv and a temporary
 * OUT.h5.tmp (those that exist). */
void sl_output_remove(const char *path);

/* For a program's main(), before any other HDF5 call: HDF5's exit handler
 * is not installed (every file sluice opens it closes; after a failed write
 * HDF5 1.10 crashes in that handler). */
void sl_io_process_start(void);

/* ---- readers: each opens the file read-only and closes it again. They do
 * not take HDF5's file lock, so a running simulation's output can be read
 * between its steps. */

/* The last complete checkpoint, bit for bit. Free with sl_checkpoint_free. */
int sl_checkpoint_read(const char *path, sl_checkpoint *ck, sl_diag *d);
void sl_checkpoint_free(sl_checkpoint *ck);
/* The array called name, or NULL. */
const sl_checkpoint_array *sl_checkpoint_find(const sl_checkpoint *ck, const char *name);

typedef struct sl_output_mesh {
  int dim;
  int32_t n_vertices;
  double *coords; /* n_vertices x 3 */
  int32_t n_cells;
  int nodes_per_cell;
  int32_t *cells; /* n_cells x nodes_per_cell */
  char topology[32];
} sl_output_mesh;

int sl_output_read_mesh(const char *path, sl_output_mesh *m, sl_diag *d);
void sl_output_mesh_free(sl_output_mesh *m);

/* Output times in step order; *times is malloc'ed (NULL when there are none). */
int sl_output_read_times(const char *path, int *n_steps, double **times, sl_diag *d);

typedef struct sl_output_field {
  int step;    /* index of the step read */
  double time; /* its time */
  sl_centring centring;
  int components; /* as stored: 1 or 3 */
  int32_t n;      /* entities (vertices or cells) */
  double *values; /* n x components */
} sl_output_field;

/* Field `name` at the step nearest to time t among the steps holding it
 * (the earlier one on a tie). An unknown name gets a did-you-mean. */
int sl_output_read_field(const char *path, const char *name, double t, sl_output_field *f, sl_diag *d);
/* Field `name` of the k-th complete step (0-based, in step order, as
 * sl_output_read_times lists them); SL_EBADINPUT when that step lacks it. */
int sl_output_read_field_at(const char *path, const char *name, int k, sl_output_field *f, sl_diag *d);
void sl_output_field_free(sl_output_field *f);

/* The scalars of every complete output time: names[n_names], units[n_names]
 * ("" when unknown), times[n_times], values[n_times x n_names] (NaN where an
 * output time lacks the scalar). Free with sl_output_scalars_free. */
typedef struct sl_output_scalars {
  int n_names, n_times;
  char **names;
  char (*units)[SL_OUTPUT_UNIT_MAX];
  double *times, *values;
} sl_output_scalars;
int sl_output_read_scalars(const char *path, sl_output_scalars *s, sl_diag *d);
void sl_output_scalars_free(sl_output_scalars *s);

/* A string dataset or attribute, e.g. "/provenance/ini" or
 * "/provenance@sluice_version" (object@attribute). *text is malloc'ed. */
int sl_output_read_text(const char *path, const char *what, char **text, sl_diag *d);

#endif
