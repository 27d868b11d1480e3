/* SPDX-License-Identifier: GPL-2.0-or-later */
/* HDF5 writer and XDMF sidecar. Layout and guarantees: see output.h. */
#include <errno.h>
#include <libgen.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/io/h5util.h"
#include "core/io/output.h"
#include "core/util/blas.h"

static const struct {
  const char *name;
  int nodes;
} topologies[] = {
    /* Edge_3 is the 1-D P2 cell: the 2 end vertices, then the midpoint. */
    {"Polyline", 2}, {"Edge_3", 3}, {"Triangle", 3}, {"Quadrilateral", 4}, {"Triangle_6", 6}, {"Quadrilateral_9", 9},
};
enum { N_TOPOLOGIES = (int)(sizeof topologies / sizeof topologies[0]) };

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  char *c = malloc(n);
  if (c) memcpy(c, s, n);
  return c;
}

static void free_fields(sl_output *o) {
  for (int i = 0; i < o->n_fields; ++i) free(o->fields[i].name);
  o->n_fields = 0;
}

static void free_scalars(sl_output *o) {
  for (int i = 0; i < o->n_scalars; ++i) free(o->scalars[i].name);
  o->n_scalars = 0;
}

static void free_output(sl_output *o) {
  free_fields(o);
  free(o->fields);
  free_scalars(o);
  free(o->scalars);
  sl_sidecar_free(o);
  free(o->path);
  free(o->tmp_path);
  free(o->xmf_path);
  free(o->csv_path);
  free(o);
}

int sl_output_open(sl_output **out, const char *path, sl_diag *d) { return sl_output_open_opts(out, path, NULL, d); }

int sl_output_open_opts(sl_output **out, const char *path, const sl_output_opts *opts, sl_diag *d) {
  *out = NULL;
  sl_h5_quiet();
  int rc = sl_output_check_path(path, opts, d);
  if (rc && !(opts && opts->collective)) return rc; /* collective: every rank learns of it below */
  sl_output *o = calloc(1, sizeof *o);
  if (!o) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  o->file = o->step_group = -1;
  o->ck_current = -1;
  o->xmf_fd = o->csv_fd = -1;
  o->path = dup_str(path);
  if (!o->path || sl_io_output_names(path, &o->xmf_path, &o->csv_path, &o->tmp_path)) {
    free_output(o);
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
  }
  const char *base = strrchr(o->path, '/');
  o->h5_name = base ? base + 1 : o->path;
  o->ranks = 1;
  if (opts && opts->collective) {
    int started = sl_io_collective_start(o, d);
    if (started) {
      free_output(o);
      return rc ? rc : started;
    }
  }
  /* a temporary of a run that was killed (sluice's own, checked above) */
  if (!rc && sl_io_rank0(o) && unlink(o->tmp_path) != 0 && errno != ENOENT)
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot remove the stale temporary '%s': %s", o->tmp_path, strerror(errno));
  int all = sl_io_agree(o, rc); /* every rank's path check, then rank 0's removal, before the collective create */
  if (all) {
    if (!rc) rc = sl_diag_set(d, all, "%s: another rank could not open the output", o->path);
    free_output(o);
    return rc;
  }
  hid_t fapl = sl_io_fapl(o);
  o->file = fapl >= 0 ? H5Fcreate(o->tmp_path, H5F_ACC_EXCL, H5P_DEFAULT, fapl) : -1;
  if (fapl >= 0) H5Pclose(fapl);
  if (o->file < 0) {
    rc = sl_h5_fail(d, SL_EBADINPUT, o->tmp_path, "cannot create", "the output file");
    free_output(o);
    return rc;
  }
  rc = sl_h5_attr_string(o->file, "format", "sluice-output 1", o->path, "/", d);
  /* on disk at once: the temporary of a run killed now is known as sluice's */
  if (!rc && H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0) rc = sl_h5_fail(d, SL_EFAILED, o->tmp_path, "cannot flush", "/");
  if (rc) {
    H5Fclose(o->file);
    if (sl_io_rank0(o)) unlink(o->tmp_path);
    free_output(o);
    return rc;
  }
  *out = o;
  return 0;
}

/* The first output time is complete: the new file takes the name. */
int sl_output_commit(sl_output *o, sl_diag *d) {
  if (o->committed) return 0;
  if (H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush", "the file");
  int rc = 0, renamed = 0;
  if (sl_io_rank0(o)) {
    if (rename(o->tmp_path, o->path) != 0)
      rc = sl_diag_set(d, SL_EFAILED, "cannot rename '%s' to '%s': %s", o->tmp_path, o->path, strerror(errno));
    else renamed = 1;
    /* the old sidecars would point into the new file */
    if (!rc && unlink(o->xmf_path) != 0 && errno != ENOENT)
      rc = sl_diag_set(d, SL_EFAILED, "cannot remove the old sidecar '%s': %s", o->xmf_path, strerror(errno));
    if (!rc && unlink(o->csv_path) != 0 && errno != ENOENT)
      rc = sl_diag_set(d, SL_EFAILED, "cannot remove the old '%s': %s", o->csv_path, strerror(errno));
  }
  int all = sl_io_agree(o, rc); /* the file has its name on every rank from here on */
  if (all && !rc) rc = sl_diag_set(d, all, "%s: rank 0 could not rename the output", o->path);
  if (renamed || (o->rank > 0 && !all)) o->committed = 1;
  return rc;
}

/* Link-creation property list that creates missing parent groups. */
static hid_t lcpl_parents(void) {
  hid_t l = H5Pcreate(H5P_LINK_CREATE);
  if (l >= 0 && H5Pset_create_intermediate_group(l, 1) < 0) {
    H5Pclose(l);
    return -1;
  }
  return l;
}

/* Creates and writes a dataset of rank 1 or 2 at `name` (relative to loc). */
static int write_array(sl_output *o, hid_t loc, const char *name, const char *full, hid_t ftype, hid_t mtype, int rank,
                       const hsize_t *dims, const void *buf, hid_t *keep, sl_diag *d) {
  hid_t lcpl = lcpl_parents(), space = H5Screate_simple(rank, dims, NULL), ds = -1;
  hid_t dcpl = o->collective ? H5Pcreate(H5P_DATASET_CREATE) : H5P_DEFAULT;
  int rc = 0;
  /* collective: the blocks cover the dataset, no fill values written first */
  if (lcpl < 0 || space < 0 || dcpl < 0 || (o->collective && H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER) < 0)) {
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot prepare dataset", full);
    goto done;
  }
  ds = H5Dcreate2(loc, name, ftype, space, lcpl, dcpl, H5P_DEFAULT);
  if (ds < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot create dataset", full);
    goto done;
  }
  if (sl_io_write_rows(o, ds, mtype, H5Tget_size(mtype), dims[0], rank == 2 ? dims[1] : 1, buf) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot write dataset", full);
done:
  if (ds >= 0) {
    if (!rc && keep) {
      *keep = ds;
    } else if (H5Dclose(ds) < 0 && !rc) {
      rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close dataset", full);
    }
  }
  if (space >= 0) H5Sclose(space);
  if (lcpl >= 0) H5Pclose(lcpl);
  if (dcpl > 0 && dcpl != H5P_DEFAULT) H5Pclose(dcpl);
  return rc;
}

/* /mesh/cell_centres: the centroid of the polygon through each cell's
 * corner nodes (the first 2, 3 or 4 of its nodes), from the shoelace
 * formula; the midpoint in 1-D. Where cell fields are given. */
static int cell_centres(sl_output *o, int dim, const double *coords, int32_t n_cells, int nodes_per_cell,
                        const int32_t *cells, const char *topology, sl_diag *d) {
  int corners = strncmp(topology, "Triangle", 8) == 0 ? 3 : strncmp(topology, "Quadrilateral", 13) == 0 ? 4 : 2;
  double *c = calloc((size_t)n_cells * 3, sizeof *c);
  if (!c) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory for the cell centres", o->path);
  for (int32_t e = 0; e < n_cells; ++e) {
    const int32_t *v = cells + (size_t)e * nodes_per_cell;
    double mean[3] = {0, 0, 0};
    for (int k = 0; k < corners; ++k)
      for (int j = 0; j < dim; ++j) mean[j] += coords[(size_t)v[k] * dim + j] / corners;
    double *out = c + 3 * (size_t)e;
    for (int j = 0; j < dim; ++j) out[j] = mean[j];
    if (dim == 2 && corners >= 3) {
      double a = 0, cx = 0, cy = 0;
      for (int k = 0; k < corners; ++k) {
        const double *p = coords + 2 * (size_t)v[k], *q = coords + 2 * (size_t)v[(k + 1) % corners];
        /* relative to the mean: no cancellation far from the origin */
        double px = p[0] - mean[0], py = p[1] - mean[1], qx = q[0] - mean[0], qy = q[1] - mean[1];
        double w = px * qy - qx * py;
        a += w, cx += (px + qx) * w, cy += (py + qy) * w;
      }
      if (a != 0.0) out[0] = mean[0] + cx / (3.0 * a), out[1] = mean[1] + cy / (3.0 * a);
    }
  }
  hsize_t dims[2] = {(hsize_t)n_cells, 3};
  hid_t ds = -1;
  int rc = write_array(o, o->file, "/mesh/cell_centres", "/mesh/cell_centres", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 2,
                       dims, c, &ds, d);
  free(c);
  if (!rc) rc = sl_h5_attr_string(ds, "units", "m", o->path, "/mesh/cell_centres", d);
  if (ds >= 0 && H5Dclose(ds) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "/mesh/cell_centres");
  return rc;
}

int sl_output_write_mesh(sl_output *o, int dim, int32_t n_vertices, const double *coords, int32_t n_cells,
                         int nodes_per_cell, const int32_t *cells, const char *topology, sl_diag *d) {
  if (o->have_mesh) return sl_diag_set(d, SL_EBADINPUT, "%s: the mesh is already written", o->path);
  if (dim < 1 || dim > 3) return sl_diag_set(d, SL_EBADINPUT, "%s: mesh dimension %d is not 1, 2 or 3", o->path, dim);
  if (!coords || !cells) return sl_diag_set(d, SL_EBADINPUT, "%s: mesh coordinates or cells missing", o->path);
  if (n_vertices <= 0 || n_cells <= 0)
    return sl_diag_set(d, SL_EBADINPUT, "%s: empty mesh (%d vertices, %d cells)", o->path, (int)n_vertices,
                       (int)n_cells);
  int t = -1;
  for (int i = 0; i < N_TOPOLOGIES; ++i)
    if (topology && strcmp(topology, topologies[i].name) == 0) t = i;
  if (t < 0) {
    const char *names[N_TOPOLOGIES];
    for (int i = 0; i < N_TOPOLOGIES; ++i) names[i] = topologies[i].name;
    const char *hint = topology ? sl_suggest(topology, names, N_TOPOLOGIES) : NULL;
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: unknown XDMF topology '%s'%s%s%s; known: Polyline, Edge_3, Triangle, Quadrilateral, "
                       "Triangle_6, Quadrilateral_9",
                       o->path, topology ? topology : "(null)", hint ? " (did you mean '" : "", hint ? hint : "",
                       hint ? "'?)" : "");
  }
  if (topologies[t].nodes != nodes_per_cell)
    return sl_diag_set(d, SL_EBADINPUT, "%s: topology %s has %d nodes per cell, not %d", o->path, topology,
                       topologies[t].nodes, nodes_per_cell);
  for (int64_t k = 0; k < (int64_t)n_cells * nodes_per_cell; ++k)
    if (cells[k] < 0 || cells[k] >= n_vertices)
      return sl_diag_set(d, SL_EBADINPUT, "%s: cell %lld refers to vertex %d, outside [0, %d) (0-based)", o->path,
                         (long long)(k / nodes_per_cell), (int)cells[k], (int)n_vertices);

  /* ParaView wants XYZ: pad 1-D and 2-D coordinates with zeros. */
  /* coordinates, cell centres, topology */
  int src = sl_io_space_check(o, 24.0 * n_vertices + (24.0 + 4.0 * nodes_per_cell) * n_cells, "the mesh", d);
  if (src) return src;
  double *xyz = malloc((size_t)n_vertices * 3 * sizeof *xyz);
  if (!xyz) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory for the mesh", o->path);
  for (int32_t v = 0; v < n_vertices; ++v)
    for (int c = 0; c < 3; ++c) xyz[3 * (size_t)v + c] = c < dim ? coords[(size_t)v * dim + c] : 0.0;
  hsize_t dc[2] = {(hsize_t)n_vertices, 3}, dt[2] = {(hsize_t)n_cells, (hsize_t)nodes_per_cell};
  hid_t top = -1;
  hid_t cds = -1;
  int rc = write_array(o, o->file, "/mesh/coordinates", "/mesh/coordinates", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 2, dc,
                       xyz, &cds, d);
  free(xyz);
  if (!rc) rc = sl_h5_attr_string(cds, "units", "m", o->path, "/mesh/coordinates", d);
  if (cds >= 0 && H5Dclose(cds) < 0 && !rc)
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "/mesh/coordinates");
  if (!rc)
    rc = write_array(o, o->file, "/mesh/topology", "/mesh/topology", H5T_STD_I32LE, H5T_NATIVE_INT32, 2, dt, cells,
                     &top, d);
  if (!rc) rc = cell_centres(o, dim, coords, n_cells, nodes_per_cell, cells, topology, d);
  if (!rc) rc = sl_h5_attr_string(top, "topology_type", topology, o->path, "/mesh/topology", d);
  if (!rc) rc = sl_h5_attr_int32(top, "dim", dim, o->path, "/mesh/topology", d);
  if (top >= 0 && H5Dclose(top) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "/mesh/topology");
  if (!rc && H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush", "the file");
  if (rc) return rc;
  o->have_mesh = 1;
  o->dim = dim;
  o->n_vertices = n_vertices;
  o->n_cells = n_cells;
  o->nodes_per_cell = nodes_per_cell;
  snprintf(o->topology, sizeof o->topology, "%s", topology);
  return 0;
}

int sl_output_begin_step(sl_output *o, double t, sl_diag *d) {
  if (!o->have_mesh) return sl_diag_set(d, SL_EBADINPUT, "%s: write the mesh before the first step", o->path);
  if (o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: step %d is still open", o->path, o->next_index);
  if (t != t) return sl_diag_set(d, SL_EBADINPUT, "%s: output time is NaN", o->path);
  char name[32];
  snprintf(name, sizeof name, "/step_%06d", o->next_index);
  /* the scalars' attributes keep the order they were written in (readers list them so) */
  hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
  if (gcpl < 0 || H5Pset_attr_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED) < 0) {
    if (gcpl >= 0) H5Pclose(gcpl);
    return sl_h5_fail(d, SL_EFAILED, o->path, "cannot prepare group", name);
  }
  hid_t g = H5Gcreate2(o->file, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
  H5Pclose(gcpl);
  if (g < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot create group", name);
  int rc = sl_h5_attr_double(g, "time", t, o->path, name, d);
  if (!rc) rc = sl_h5_attr_int32(g, "index", o->next_index, o->path, name, d);
  if (rc) {
    H5Gclose(g);
    return rc;
  }
  o->step_group = g;
  o->step_time = t;
  o->in_step = 1;
  free_fields(o);
  return 0;
}

int sl_output_write_field(sl_output *o, const char *name, sl_centring centring, int components, const double *values,
                          sl_diag *d) {
  return sl_output_write_field_unit(o, name, sl_io_default_unit(name), centring, components, values, d);
}

int sl_output_write_field_unit(sl_output *o, const char *name, const char *unit, sl_centring centring, int components,
                               const double *values, sl_diag *d) {
  if (!unit) unit = "";
  if (!o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' written outside a step", o->path, name);
  int rc = sl_io_check_name(name, 200, "field", d);
  if (rc) return sl_diag_prefix(d, rc, "%s", o->path);
  if (components < 1 || components > 3)
    return sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' has %d components (1, 2 or 3)", o->path, name, components);
  if (!values) return sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' has no values", o->path, name);
  if (centring != SL_CENTRE_NODE && centring != SL_CENTRE_CELL)
    return sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' has an unknown centring", o->path, name);
  for (int i = 0; i < o->n_fields; ++i)
    if (strcmp(o->fields[i].name, name) == 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s: field '%s' written twice in step %d", o->path, name, o->next_index);
  if (o->n_fields == o->cap_fields) {
    int cap = o->cap_fields ? 2 * o->cap_fields : 8;
    sl_out_field *f = realloc(o->fields, (size_t)cap * sizeof *f);
    if (!f) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
    o->fields = f, o->cap_fields = cap;
  }
  int32_t n = centring == SL_CENTRE_NODE ? o->n_vertices : o->n_cells;
  int stored = components == 1 ? 1 : 3;
  char full[256];
  snprintf(full, sizeof full, "/step_%06d/%s", o->next_index, name);
  /* No NaN or infinity goes into a file: the step stays incomplete, and
   * readers keep to the complete ones. */
  for (size_t i = 0; i < (size_t)n * (size_t)components; ++i)
    if (!isfinite(values[i]))
      return sl_diag_set(d, SL_EFAILED, "%s: field '%s' at t = %g holds %g (entity %lld, component %d): not written",
                         o->path, name, o->step_time, values[i], (long long)(i / (size_t)components),
                         (int)(i % (size_t)components));

  char what[300];
  snprintf(what, sizeof what, "field '%s'", name);
  if ((rc = sl_io_space_check(o, (double)n * stored * sizeof(double), what, d))) return rc;
  const double *buf = values;
  double *pad = NULL;
  if (components == 2) { /* ParaView's vectors have 3 components */
    pad = malloc((size_t)n * 3 * sizeof *pad);
    if (!pad) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory writing %s", o->path, full);
    for (int32_t i = 0; i < n; ++i) {
      pad[3 * (size_t)i] = values[2 * (size_t)i];
      pad[3 * (size_t)i + 1] = values[2 * (size_t)i + 1];
      pad[3 * (size_t)i + 2] = 0.0;
    }
    buf = pad;
  }
  hsize_t dims[2] = {(hsize_t)n, 3};
  hid_t ds = -1;
  rc = write_array(o, o->step_group, name, full, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, stored == 1 ? 1 : 2, dims, buf, &ds,
                   d);
  free(pad);
  if (!rc) rc = sl_h5_attr_string(ds, "centring", centring == SL_CENTRE_NODE ? "node" : "cell", o->path, full, d);
  if (!rc) rc = sl_h5_attr_int32(ds, "components", stored, o->path, full, d);
  if (!rc) rc = sl_h5_attr_string(ds, "units", unit, o->path, full, d);
  if (ds >= 0 && H5Dclose(ds) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close dataset", full);
  if (rc) return rc;
  sl_out_field *f = &o->fields[o->n_fields];
  if (!(f->name = dup_str(name))) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
  f->centring = centring;
  f->components = stored;
  f->n = n;
  ++o->n_fields;
  ++o->n_datasets;
  o->bytes += (double)n * stored * sizeof(double);
  return 0;
}

void sl_output_stats(const sl_output *o, long *times, long *datasets, double *bytes) {
  *times = o->n_steps, *datasets = o->n_datasets, *bytes = o->bytes;
}

void sl_output_rank_stats(const sl_output *o, double *here, double *all, long *collective) {
  *here = o->bytes_here, *all = o->bytes_all, *collective = o->n_collective;
}

int sl_output_end_step(sl_output *o, sl_diag *d) {
  if (!o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: no step is open", o->path);
  o->in_step = 0;
  int index = o->next_index++;
  char name[32];
  snprintf(name, sizeof name, "/step_%06d", index);
  /* Readers skip steps without this mark, as the sidecar does. */
  int rc = sl_h5_attr_int32(o->step_group, "complete", 1, o->path, name, d);
  if (rc) {
    H5Gclose(o->step_group);
    o->step_group = -1;
    return rc;
  }
  herr_t st = H5Gclose(o->step_group);
  o->step_group = -1;
  if (st < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot close group", name);
  if (H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush after", name);
  if ((rc = sl_output_commit(o, d))) return rc;
  ++o->n_steps;
  rc = sl_sidecar_step(o, d);
  free_fields(o);
  free_scalars(o);
  return rc;
}

static int provenance(sl_output *o, const void *arg, sl_diag *d) {
  const sl_provenance *p = arg;
  const char *path = o->path;
  if (!p || (p->n_closures > 0 && !p->closures) || p->n_closures < 0)
    return sl_diag_set(d, SL_EBADINPUT, "%s: provenance missing", path);
  htri_t ex = H5Lexists(o->file, "provenance", H5P_DEFAULT);
  if (ex < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot query", "/provenance");
  if (ex > 0 && H5Ldelete(o->file, "provenance", H5P_DEFAULT) < 0)
    return sl_h5_fail(d, SL_EFAILED, path, "cannot replace", "/provenance");
  double text = (double)strlen(p->ini_text ? p->ini_text : "");
  for (int i = 0; i < p->n_closures; ++i)
    text += 1024.0 + strlen(p->closures[i].parameters ? p->closures[i].parameters : "");
  int src = sl_io_space_check(o, text, "the provenance", d);
  if (src) return src;
  hid_t g = H5Gcreate2(o->file, "provenance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), cg = -1;
  if (g < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot create group", "/provenance");
  int rc = sl_h5_attr_string(g, "sluice_version", p->sluice_version, path, "/provenance", d);
  if (!rc) rc = sl_h5_attr_string(g, "blas", sl_blas_description(), path, "/provenance", d);
  if (!rc) rc = sl_h5_dataset_string(g, "ini", p->ini_text, path, "/provenance/ini", d);
  if (!rc && (cg = H5Gcreate2(g, "closures", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, path, "cannot create group", "/provenance/closures");
  for (int i = 0; !rc && i < p->n_closures; ++i) {
    const sl_provenance_closure *c = &p->closures[i];
    char name[32], full[64];
    snprintf(name, sizeof name, "closure_%03d", i);
    snprintf(full, sizeof full, "/provenance/closures/%s", name);
    hid_t h = H5Gcreate2(cg, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (h < 0) {
      rc = sl_h5_fail(d, SL_EFAILED, path, "cannot create group", full);
      break;
    }
    rc = sl_h5_attr_string(h, "role", c->role, path, full, d);
    if (!rc) rc = sl_h5_attr_string(h, "kind", c->kind, path, full, d);
    if (!rc) rc = sl_h5_attr_string(h, "name", c->name, path, full, d);
    if (!rc) rc = sl_h5_attr_string(h, "version", c->version, path, full, d);
    if (!rc) rc = sl_h5_attr_string(h, "library", c->library, path, full, d);
    if (!rc) rc = sl_h5_dataset_string(h, "parameters", c->parameters, path, full, d);
    if (H5Gclose(h) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot close group", full);
  }
  if (cg >= 0 && H5Gclose(cg) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot close", "/provenance/closures");
  if (H5Gclose(g) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot close", "/provenance");
  if (!rc && H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, path, "cannot flush after", "/provenance");
  return rc;
}

/* Its string datasets are variable-length: under a collective output rank
 * 0 writes them alone (collective.c). */
int sl_output_write_provenance(sl_output *o, const sl_provenance *p, sl_diag *d) {
  return sl_io_serial_interlude(o, provenance, p, d);
}

/* (A file whose close failed cannot be closed again: HDF5 1.10 crashes
 * trying, also in its exit handler; space.c keeps writes from failing,
 * main.c keeps the handler from running.) */
herr_t sl_h5_close_all(hid_t file) {
  herr_t st = 0;
  for (int pass = 0; pass < 1; ++pass) {
    ssize_t n =
        H5Fget_obj_count(file, H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE | H5F_OBJ_ATTR | H5F_OBJ_LOCAL);
    if (n > 0) {
      hid_t *ids = malloc((size_t)n * sizeof *ids);
      if (ids) {
        ssize_t k = H5Fget_obj_ids(
            file, H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE | H5F_OBJ_ATTR | H5F_OBJ_LOCAL, (size_t)n, ids);
        for (ssize_t i = 0; i < k; ++i) {
          H5I_type_t t = H5Iget_type(ids[i]);
          if (t == H5I_DATASET) H5Dclose(ids[i]);
          else if (t == H5I_GROUP) H5Gclose(ids[i]);
          else if (t == H5I_DATATYPE) H5Tclose(ids[i]);
          else if (t == H5I_ATTR) H5Aclose(ids[i]);
        }
        free(ids);
      }
    }
    st = H5Fclose(file);
    break;
  }
  H5Eclear2(H5E_DEFAULT);
  return st;
}

int sl_output_close(sl_output *o, sl_diag *d) {
  if (!o) return 0;
  int rc = 0;
  if (o->in_step) { /* an unfinished step stays out of the sidecar */
    H5Gclose(o->step_group);
    rc = sl_diag_set(d, SL_EFAILED, "%s: closed with step %d unfinished (not listed in %s)", o->path, o->next_index,
                     o->xmf_path);
  }
  if (o->file >= 0) {
    if (H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0 && !rc)
      rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush", "the file");
    if (!o->committed && !rc) rc = sl_output_commit(o, d);
    /* closed even when a flush failed (a full disk): HDF5 must not find the
     * file still open when the process exits */
    if (sl_h5_close_all(o->file) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "the file");
    o->file = -1;
  }
  if (!o->committed && sl_io_rank0(o)) unlink(o->tmp_path);
  free_output(o);
  return rc;
}

int sl_output_abort(sl_output *o) {
  if (!o) return 0;
  if (o->in_step) H5Gclose(o->step_group);
  o->in_step = 0;
  if (o->file >= 0) {
    if (o->committed) H5Fflush(o->file, H5F_SCOPE_GLOBAL);
    sl_h5_close_all(o->file);
    o->file = -1;
  }
  int kept = o->committed;
  if (!kept && sl_io_rank0(o)) unlink(o->tmp_path); /* the earlier result stays */
  free_output(o);
  return kept;
}

static int add_scalar(sl_output *o, const char *name, const char *unit, double value, sl_diag *d) {
  if (!o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: scalar '%s' written outside a step", o->path, name);
  int rc = sl_io_check_name(name, 200, "scalar", d);
  if (rc) return sl_diag_prefix(d, rc, "%s", o->path);
  if (strcmp(name, "time") == 0 || strcmp(name, "index") == 0 || strcmp(name, "complete") == 0)
    return sl_diag_set(d, SL_EBADINPUT, "%s: '%s' is reserved and cannot name a scalar", o->path, name);
  if (!unit && (strcmp(name, "solids_inventory") == 0 || strcmp(name, "inventory") == 0))
    /* the integral over the mesh: per unit cross-section in 1-D, per unit
     * depth in 2-D (axisymmetric models pass "m^3/rad") */
    unit = o->dim == 1 ? "m" : o->dim == 2 ? "m^2" : "m^3";
  if (!unit) unit = sl_io_default_unit(name);
  if (strlen(unit) >= SL_OUTPUT_UNIT_MAX)
    return sl_diag_set(d, SL_EBADINPUT, "%s: unit '%s' of scalar '%s' is longer than %d", o->path, unit, name,
                       SL_OUTPUT_UNIT_MAX - 1);
  for (int i = 0; i < o->n_scalars; ++i)
    if (strcmp(o->scalars[i].name, name) == 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s: scalar '%s' written twice in step %d", o->path, name, o->next_index);
  if (o->n_scalars == o->cap_scalars) {
    int cap = o->cap_scalars ? 2 * o->cap_scalars : 8;
    sl_out_scalar *v = realloc(o->scalars, (size_t)cap * sizeof *v);
    if (!v) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
    o->scalars = v, o->cap_scalars = cap;
  }
  char group[32];
  snprintf(group, sizeof group, "/step_%06d", o->next_index);
  if ((rc = sl_h5_attr_double(o->step_group, name, value, o->path, group, d))) return rc;
  sl_out_scalar *sc = &o->scalars[o->n_scalars];
  if (!(sc->name = dup_str(name))) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
  snprintf(sc->unit, sizeof sc->unit, "%s", unit);
  sc->value = value;
  ++o->n_scalars;
  return 0;
}

int sl_output_write_scalar(sl_output *o, const char *name, double value, sl_diag *d) {
  return add_scalar(o, name, NULL, value, d);
}

int sl_output_write_scalar_unit(sl_output *o, const char *name, const char *unit, double value, sl_diag *d) {
  return add_scalar(o, name, unit ? unit : "", value, d);
}
