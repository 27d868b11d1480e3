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
#include "core/util/blas.h"
#include "core/io/output.h"

static const struct {
  const char *name;
  int nodes;
} topologies[] = {
    /* Edge_3 is the 1-D P2 cell: the 2 end vertices, then the midpoint. */
    {"Polyline", 2},      {"Edge_3", 3},     {"Triangle", 3},
    {"Quadrilateral", 4}, {"Triangle_6", 6}, {"Quadrilateral_9", 9},
};
enum { N_TOPOLOGIES = (int)(sizeof topologies / sizeof topologies[0]) };

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  char *c = malloc(n);
  if (c) memcpy(c, s, n);
  return c;
}

/* printf into a growing buffer (the sidecar text). */
typedef struct sbuf {
  char *s;
  size_t len, cap;
  int oom;
} sbuf;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void
sb_printf(sbuf *b, const char *fmt, ...) {
  if (b->oom) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    size_t room = b->cap - b->len;
    int k = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? room : 0, fmt, ap);
    va_end(ap);
    if (k < 0) {
      b->oom = 1;
      return;
    }
    if ((size_t)k < room) {
      b->len += (size_t)k;
      return;
    }
    size_t cap = b->cap ? b->cap : 1024;
    while (cap - b->len <= (size_t)k) cap *= 2;
    char *s = realloc(b->s, cap);
    if (!s) {
      b->oom = 1;
      return;
    }
    b->s = s, b->cap = cap;
  }
}

/* XML text and attribute escaping (names are checked, but the file name is
 * the user's). */
static void sb_xml(sbuf *b, const char *s) {
  for (; *s; ++s) {
    switch (*s) {
      case '&': sb_printf(b, "&amp;"); break;
      case '<': sb_printf(b, "&lt;"); break;
      case '>': sb_printf(b, "&gt;"); break;
      case '"': sb_printf(b, "&quot;"); break;
      case '\'': sb_printf(b, "&apos;"); break;
      default: sb_printf(b, "%c", *s);
    }
  }
}

static void free_fields(sl_output *o) {
  for (int i = 0; i < o->n_fields; ++i) free(o->fields[i].name);
  o->n_fields = 0;
}

static void free_output(sl_output *o) {
  free_fields(o);
  free(o->fields);
  for (int i = 0; i < o->n_steps; ++i) free(o->steps[i].xml);
  free(o->steps);
  free(o->path);
  free(o->xmf_path);
  free(o->xmf_tmp);
  free(o);
}

int sl_output_open(sl_output **out, const char *path, sl_diag *d) {
  *out = NULL;
  sl_h5_quiet();
  if (!path || !*path) return sl_diag_set(d, SL_EBADINPUT, "output file name is empty");

  /* A missing directory is the common mistake: say so plainly. */
  char *tmp = dup_str(path);
  if (!tmp) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  const char *dir = dirname(tmp);
  struct stat sb;
  int rc = 0;
  if (stat(dir, &sb) != 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': directory '%s' %s", path, dir,
                     errno == ENOENT ? "does not exist" : strerror(errno));
  else if (!S_ISDIR(sb.st_mode))
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': '%s' is not a directory", path, dir);
  else if (access(dir, W_OK | X_OK) != 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': directory '%s' is not writable", path, dir);
  free(tmp);
  if (rc) return rc;

  sl_output *o = calloc(1, sizeof *o);
  if (!o) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  o->file = o->step_group = -1;
  o->ck_current = -1;
  o->path = dup_str(path);
  /* OUT.h5 -> OUT.xmf next to it: strip the extension of the base name */
  size_t len = strlen(path);
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t stem = dot && dot != base ? (size_t)(dot - path) : len;
  o->xmf_path = malloc(stem + 5);
  o->xmf_tmp = malloc(stem + 9);
  if (!o->path || !o->xmf_path || !o->xmf_tmp) {
    free_output(o);
    return sl_diag_set(d, SL_ENOMEM, "out of memory");
  }
  memcpy(o->xmf_path, path, stem);
  memcpy(o->xmf_path + stem, ".xmf", 5);
  memcpy(o->xmf_tmp, path, stem);
  memcpy(o->xmf_tmp + stem, ".xmf.tmp", 9);
  o->h5_name = o->path + (base - path);
  if (strcmp(o->xmf_path, path) == 0 || strchr(o->h5_name, ':')) {
    rc = sl_diag_set(d, SL_EBADINPUT, "output file '%s': %s", path,
                     strchr(o->h5_name, ':')
                         ? "the name must not contain ':' (XDMF uses it to separate file and dataset)"
                         : "an .xmf name is reserved for the sidecar; use .h5");
    free_output(o);
    return rc;
  }

  o->file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (o->file < 0) {
    rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot create", "the output file");
    free_output(o);
    return rc;
  }
  /* A sidecar from an earlier run would point into the truncated file. */
  if (unlink(o->xmf_path) != 0 && errno != ENOENT) {
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot remove the old sidecar '%s': %s", o->xmf_path, strerror(errno));
    H5Fclose(o->file);
    free_output(o);
    return rc;
  }
  *out = o;
  return 0;
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
static int write_array(const sl_output *o, hid_t loc, const char *name, const char *full, hid_t ftype, hid_t mtype,
                       int rank, const hsize_t *dims, const void *buf, hid_t *keep, sl_diag *d) {
  hid_t lcpl = lcpl_parents(), space = H5Screate_simple(rank, dims, NULL), ds = -1;
  int rc = 0;
  if (lcpl < 0 || space < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot prepare dataset", full);
    goto done;
  }
  ds = H5Dcreate2(loc, name, ftype, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot create dataset", full);
    goto done;
  }
  if (H5Dwrite(ds, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0)
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
  double *xyz = malloc((size_t)n_vertices * 3 * sizeof *xyz);
  if (!xyz) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory for the mesh", o->path);
  for (int32_t v = 0; v < n_vertices; ++v)
    for (int c = 0; c < 3; ++c) xyz[3 * (size_t)v + c] = c < dim ? coords[(size_t)v * dim + c] : 0.0;
  hsize_t dc[2] = {(hsize_t)n_vertices, 3}, dt[2] = {(hsize_t)n_cells, (hsize_t)nodes_per_cell};
  hid_t top = -1;
  int rc = write_array(o, o->file, "/mesh/coordinates", "/mesh/coordinates", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, 2, dc,
                       xyz, NULL, d);
  free(xyz);
  if (!rc)
    rc = write_array(o, o->file, "/mesh/topology", "/mesh/topology", H5T_STD_I32LE, H5T_NATIVE_INT32, 2, dt, cells,
                     &top, d);
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
  hid_t g = H5Gcreate2(o->file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
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

/* One <Grid> of the temporal collection. The mesh DataItems are repeated in
 * every step: they only reference the datasets. */
static char *render_step(const sl_output *o, int index, double t) {
  sbuf b = {0};
  sb_printf(&b, "   <Grid Name=\"step_%06d\" GridType=\"Uniform\">\n", index);
  sb_printf(&b, "    <Time Value=\"%.17g\"/>\n", t);
  sb_printf(&b, "    <Topology TopologyType=\"%s\" NumberOfElements=\"%d\"", o->topology, (int)o->n_cells);
  if (strcmp(o->topology, "Polyline") == 0) sb_printf(&b, " NodesPerElement=\"2\"");
  sb_printf(&b, ">\n     <DataItem Dimensions=\"%d %d\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">",
            (int)o->n_cells, o->nodes_per_cell);
  sb_xml(&b, o->h5_name);
  sb_printf(&b, ":/mesh/topology</DataItem>\n    </Topology>\n");
  sb_printf(&b, "    <Geometry GeometryType=\"XYZ\">\n");
  sb_printf(&b, "     <DataItem Dimensions=\"%d 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">",
            (int)o->n_vertices);
  sb_xml(&b, o->h5_name);
  sb_printf(&b, ":/mesh/coordinates</DataItem>\n    </Geometry>\n");
  for (int i = 0; i < o->n_fields; ++i) {
    const sl_out_field *f = &o->fields[i];
    sb_printf(&b, "    <Attribute Name=\"");
    sb_xml(&b, f->name);
    sb_printf(&b, "\" AttributeType=\"%s\" Center=\"%s\">\n", f->components == 1 ? "Scalar" : "Vector",
              f->centring == SL_CENTRE_NODE ? "Node" : "Cell");
    if (f->components == 1)
      sb_printf(&b, "     <DataItem Dimensions=\"%d\"", (int)f->n);
    else
      sb_printf(&b, "     <DataItem Dimensions=\"%d 3\"", (int)f->n);
    sb_printf(&b, " NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">");
    sb_xml(&b, o->h5_name);
    sb_printf(&b, ":/step_%06d/", index);
    sb_xml(&b, f->name);
    sb_printf(&b, "</DataItem>\n    </Attribute>\n");
  }
  sb_printf(&b, "   </Grid>\n");
  if (b.oom) {
    free(b.s);
    return NULL;
  }
  return b.s;
}

/* Temporary file + rename: a reader never sees a half-written sidecar. */
static int write_sidecar(const sl_output *o, sl_diag *d) {
  FILE *f = fopen(o->xmf_tmp, "w");
  if (!f) return sl_diag_set(d, SL_EFAILED, "cannot write the sidecar '%s': %s", o->xmf_tmp, strerror(errno));
  int bad = fputs(
                "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
                "  <Grid Name=\"solution\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                f) < 0;
  for (int i = 0; i < o->n_steps && !bad; ++i) bad = fputs(o->steps[i].xml, f) < 0;
  if (!bad) bad = fputs("  </Grid>\n </Domain>\n</Xdmf>\n", f) < 0;
  int err = errno;
  if (fclose(f) != 0 && !bad) bad = 1, err = errno;
  if (bad) {
    unlink(o->xmf_tmp);
    return sl_diag_set(d, SL_EFAILED, "cannot write the sidecar '%s': %s", o->xmf_tmp, strerror(err));
  }
  if (rename(o->xmf_tmp, o->xmf_path) != 0) {
    err = errno;
    unlink(o->xmf_tmp);
    return sl_diag_set(d, SL_EFAILED, "cannot rename '%s' to '%s': %s", o->xmf_tmp, o->xmf_path, strerror(err));
  }
  return 0;
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
  if (o->n_steps == o->cap_steps) {
    int cap = o->cap_steps ? 2 * o->cap_steps : 16;
    sl_out_step *s = realloc(o->steps, (size_t)cap * sizeof *s);
    if (!s) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
    o->steps = s, o->cap_steps = cap;
  }
  char *xml = render_step(o, index, o->step_time);
  if (!xml) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
  o->steps[o->n_steps].index = index;
  o->steps[o->n_steps].time = o->step_time;
  o->steps[o->n_steps].xml = xml;
  ++o->n_steps;
  free_fields(o);
  return write_sidecar(o, d);
}

int sl_output_write_provenance(sl_output *o, const sl_provenance *p, sl_diag *d) {
  const char *path = o->path;
  if (!p || (p->n_closures > 0 && !p->closures) || p->n_closures < 0)
    return sl_diag_set(d, SL_EBADINPUT, "%s: provenance missing", path);
  htri_t ex = H5Lexists(o->file, "provenance", H5P_DEFAULT);
  if (ex < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot query", "/provenance");
  if (ex > 0 && H5Ldelete(o->file, "provenance", H5P_DEFAULT) < 0)
    return sl_h5_fail(d, SL_EFAILED, path, "cannot replace", "/provenance");
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
    if (H5Fclose(o->file) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "the file");
  }
  if (!rc && o->n_steps > 0) rc = write_sidecar(o, d);
  free_output(o);
  return rc;
}

int sl_output_write_scalar(sl_output *o, const char *name, double value, sl_diag *d) {
  if (!o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: scalar '%s' written outside a step", o->path, name);
  int rc = sl_io_check_name(name, 200, "scalar", d);
  if (rc) return sl_diag_prefix(d, rc, "%s", o->path);
  char group[32];
  snprintf(group, sizeof group, "/step_%06d", o->next_index);
  return sl_h5_attr_double(o->step_group, name, value, o->path, group, d);
}
