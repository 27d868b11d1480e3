/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The files beside OUT.h5 (output.h): OUT.xmf for ParaView and meshio, and
 * OUT_scalars.csv for pandas. Both are brought up to date at every complete
 * output time at a cost that does not grow with the run: the .xmf is
 * written whole for the first two output times (one Uniform grid, then a
 * temporal collection) and afterwards extended in place, the new grid
 * written over the closing tags together with new closing tags; the CSV
 * gets one row appended (written whole again only when a scalar appears
 * that earlier output times did not have). No temporary files. */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/io/h5util.h"

/* printf into a growing buffer. */
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
      case '&':
        sb_printf(b, "&amp;");
        break;
      case '<':
        sb_printf(b, "&lt;");
        break;
      case '>':
        sb_printf(b, "&gt;");
        break;
      case '"':
        sb_printf(b, "&quot;");
        break;
      case '\'':
        sb_printf(b, "&apos;");
        break;
      default:
        sb_printf(b, "%c", *s);
    }
  }
}

static void sb_number(sbuf *b, double v) {
  if (isnan(v)) sb_printf(b, "nan");
  else if (isinf(v)) sb_printf(b, "%sinf", v < 0 ? "-" : "");
  else sb_printf(b, "%.17g", v);
}

char *sl_sidecar_grid(const sl_output *o, int index) {
  sbuf b = {0};
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
    if (f->components == 1) sb_printf(&b, "     <DataItem Dimensions=\"%d\"", (int)f->n);
    else sb_printf(&b, "     <DataItem Dimensions=\"%d 3\"", (int)f->n);
    sb_printf(&b, " NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">");
    sb_xml(&b, o->h5_name);
    sb_printf(&b, ":/step_%06d/", index);
    sb_xml(&b, f->name);
    sb_printf(&b, "</DataItem>\n    </Attribute>\n");
  }
  /* ParaView's XDMF readers show these as field data of the time step; a
   * value that is not finite (an interface that is not there) is left out:
   * XML readers differ on "nan" (the CSV and the HDF5 file have it) */
  for (int i = 0; i < o->n_scalars; ++i) {
    const sl_out_scalar *s = &o->scalars[i];
    if (!isfinite(s->value)) continue;
    sb_printf(&b, "    <Attribute Name=\"");
    sb_xml(&b, s->name);
    sb_printf(&b, "\" AttributeType=\"Scalar\" Center=\"Grid\">\n");
    sb_printf(&b, "     <DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">");
    sb_number(&b, s->value);
    sb_printf(&b, "</DataItem>\n    </Attribute>\n");
  }
  if (b.oom) {
    free(b.s);
    return NULL;
  }
  return b.s;
}

static const char xmf_head[] =
    "<?xml version=\"1.0\" ?>\n<!-- written by sluice -->\n<Xdmf Version=\"3.0\">\n <Domain>\n";
static const char xmf_tail[] = "  </Grid>\n </Domain>\n</Xdmf>\n";

static void grid_in_collection(sbuf *b, int index, double t, const char *body) {
  sb_printf(b, "   <Grid Name=\"step_%06d\" GridType=\"Uniform\">\n    <Time Value=\"", index);
  sb_number(b, t);
  sb_printf(b, "\"/>\n%s   </Grid>\n", body);
}

/* Writes all of buf at offset (retrying short writes). */
static int put(int fd, const char *buf, size_t len, long offset) {
  while (len > 0) {
    ssize_t k = pwrite(fd, buf, len, (off_t)offset);
    if (k < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    buf += k, len -= (size_t)k, offset += (long)k;
  }
  return 0;
}

static int open_side(const char *path) {
  return open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
}

static int xmf_step(sl_output *o, char *body, int index, double t, sl_diag *d) {
  sbuf b = {0};
  long tail_at = -1;
  int whole = 1;
  if (o->n_steps == 1) { /* one grid, no time: what meshio.read opens */
    sb_printf(&b, "%s  <Grid Name=\"step_%06d\" GridType=\"Uniform\">\n%s", xmf_head, index, body);
    sb_printf(&b, "%s", xmf_tail);
  } else if (o->n_steps == 2) {
    sb_printf(&b, "%s  <Grid Name=\"solution\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", xmf_head);
    grid_in_collection(&b, o->first_index, o->first_time, o->first_grid ? o->first_grid : "");
    grid_in_collection(&b, index, t, body);
    tail_at = (long)b.len;
    sb_printf(&b, "%s", xmf_tail);
  } else {
    whole = 0;
    grid_in_collection(&b, index, t, body);
    tail_at = o->xmf_tail + (long)b.len;
    sb_printf(&b, "%s", xmf_tail);
  }
  if (b.oom) {
    free(b.s);
    free(body);
    return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->xmf_path);
  }
  int rc = 0;
  if (o->xmf_fd < 0 && (o->xmf_fd = open_side(o->xmf_path)) < 0) {
    rc = sl_diag_set(d, SL_EFAILED, "cannot write the sidecar '%s': %s", o->xmf_path, strerror(errno));
  } else if (put(o->xmf_fd, b.s, b.len, whole ? 0 : o->xmf_tail) != 0 ||
             (whole && ftruncate(o->xmf_fd, (off_t)b.len) != 0)) {
    rc = sl_diag_set(d, SL_EFAILED, "cannot write the sidecar '%s': %s", o->xmf_path, strerror(errno));
  }
  free(b.s);
  if (o->n_steps == 1) {
    free(o->first_grid);
    o->first_grid = body, o->first_index = index, o->first_time = t;
  } else {
    free(body);
    free(o->first_grid);
    o->first_grid = NULL;
  }
  if (!rc) o->xmf_tail = tail_at;
  return rc;
}

/* /scalar_units@NAME = unit, once for each scalar name. */
static int note_unit(sl_output *o, const char *name, const char *unit, sl_diag *d) {
  htri_t ex = H5Lexists(o->file, "scalar_units", H5P_DEFAULT);
  hid_t g = ex > 0    ? H5Gopen2(o->file, "scalar_units", H5P_DEFAULT)
            : ex == 0 ? H5Gcreate2(o->file, "scalar_units", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
                      : -1;
  if (g < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot open group", "/scalar_units");
  int rc = sl_h5_attr_string(g, name, unit, o->path, "/scalar_units", d);
  if (H5Gclose(g) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close group", "/scalar_units");
  return rc;
}

/* The CSV's columns grow to hold this step's scalars; *grew when they did. */
static int add_columns(sl_output *o, int *grew, sl_diag *d) {
  *grew = 0;
  for (int i = 0; i < o->n_scalars; ++i) {
    const sl_out_scalar *s = &o->scalars[i];
    int known = 0;
    for (int c = 0; c < o->n_cols && !known; ++c) known = strcmp(o->col_names[c], s->name) == 0;
    if (known) continue;
    if (o->n_cols == o->cap_cols) {
      int cap = o->cap_cols ? 2 * o->cap_cols : 8;
      char **n = realloc(o->col_names, (size_t)cap * sizeof *n);
      if (!n) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
      o->col_names = n;
      char(*u)[SL_OUTPUT_UNIT_MAX] = realloc(o->col_units, (size_t)cap * sizeof *u);
      if (!u) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
      o->col_units = u;
      /* the rows get the wider stride, the new columns absent (NaN) */
      int stride = 1 + cap;
      if (o->n_rows > 0) {
        double *r = malloc((size_t)o->n_rows * (size_t)stride * sizeof *r);
        if (!r) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
        for (long k = 0; k < o->n_rows; ++k)
          for (int j = 0; j < stride; ++j)
            r[k * stride + j] = j < o->row_stride ? o->rows[k * o->row_stride + j] : -NAN;
        free(o->rows);
        o->rows = r, o->cap_rows = o->n_rows;
      }
      o->row_stride = stride, o->cap_cols = cap;
    }
    size_t len = strlen(s->name) + 1;
    if (!(o->col_names[o->n_cols] = malloc(len))) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
    memcpy(o->col_names[o->n_cols], s->name, len);
    memcpy(o->col_units[o->n_cols], s->unit, SL_OUTPUT_UNIT_MAX);
    ++o->n_cols;
    *grew = 1;
    int rc = note_unit(o, s->name, s->unit, d);
    if (rc) return rc;
  }
  return 0;
}

/* A CSV field: the number, "nan", or nothing for a scalar this output time lacks. */
static void csv_row(sbuf *b, const sl_output *o, long k) {
  const double *r = o->rows + k * o->row_stride;
  sb_number(b, r[0]);
  for (int c = 0; c < o->n_cols; ++c) {
    sb_printf(b, ",");
    /* absent is stored as a NaN with the sign bit set; a written NaN without */
    if (!(isnan(r[1 + c]) && signbit(r[1 + c]))) sb_number(b, r[1 + c]);
  }
  sb_printf(b, "\n");
}

static int csv_step(sl_output *o, double t, sl_diag *d) {
  if (o->row_stride == 0) o->row_stride = 1;
  int grew = 0, rc = add_columns(o, &grew, d);
  if (rc) return rc;
  if (o->n_rows == o->cap_rows) {
    long cap = o->cap_rows ? 2 * o->cap_rows : 64;
    double *r = realloc(o->rows, (size_t)cap * (size_t)o->row_stride * sizeof *r);
    if (!r) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
    o->rows = r, o->cap_rows = cap;
  }
  double *row = o->rows + o->n_rows * o->row_stride;
  row[0] = t;
  for (int c = o->n_cols; c + 1 < o->row_stride; ++c) row[1 + c] = -NAN; /* columns to come */
  for (int c = 0; c < o->n_cols; ++c) {
    row[1 + c] = -NAN;
    for (int i = 0; i < o->n_scalars; ++i)
      if (strcmp(o->scalars[i].name, o->col_names[c]) == 0)
        row[1 + c] = isnan(o->scalars[i].value) ? fabs(o->scalars[i].value) : o->scalars[i].value;
  }
  ++o->n_rows;
  if (o->n_cols == 0 || !sl_io_rank0(o)) return 0; /* no scalars (yet): no CSV; rank 0's alone (collective.c) */
  sbuf b = {0};
  int whole = grew || o->csv_fd < 0;
  if (whole) {
    sb_printf(&b, "time [s]");
    for (int c = 0; c < o->n_cols; ++c) {
      sb_printf(&b, ",%s", o->col_names[c]);
      if (o->col_units[c][0]) sb_printf(&b, " [%s]", o->col_units[c]);
    }
    sb_printf(&b, "\n");
    for (long k = 0; k < o->n_rows; ++k) csv_row(&b, o, k);
  } else {
    csv_row(&b, o, o->n_rows - 1);
  }
  if (b.oom) {
    free(b.s);
    return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->csv_path);
  }
  if (o->csv_fd < 0 && (o->csv_fd = open_side(o->csv_path)) < 0) {
    rc = sl_diag_set(d, SL_EFAILED, "cannot write '%s': %s", o->csv_path, strerror(errno));
  } else if (put(o->csv_fd, b.s, b.len, whole ? 0 : o->csv_end) != 0 ||
             (whole && ftruncate(o->csv_fd, (off_t)b.len) != 0)) {
    rc = sl_diag_set(d, SL_EFAILED, "cannot write '%s': %s", o->csv_path, strerror(errno));
  } else {
    o->csv_end = (whole ? 0 : o->csv_end) + (long)b.len;
  }
  free(b.s);
  return rc;
}

int sl_sidecar_step(sl_output *o, sl_diag *d) {
  /* a collective output's .xmf is rank 0's; every rank notes the scalars' units in the file */
  if (!sl_io_rank0(o)) return csv_step(o, o->step_time, d);
  int index = o->next_index - 1;
  char *body = sl_sidecar_grid(o, index);
  if (!body) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", o->path);
  int rc = xmf_step(o, body, index, o->step_time, d);
  if (!rc) rc = csv_step(o, o->step_time, d);
  return rc;
}

void sl_sidecar_free(sl_output *o) {
  if (o->xmf_fd >= 0) close(o->xmf_fd);
  if (o->csv_fd >= 0) close(o->csv_fd);
  o->xmf_fd = o->csv_fd = -1;
  free(o->first_grid);
  o->first_grid = NULL;
  for (int c = 0; c < o->n_cols; ++c) free(o->col_names[c]);
  free(o->col_names);
  free(o->col_units);
  free(o->rows);
  o->col_names = NULL, o->col_units = NULL, o->rows = NULL;
  o->n_cols = o->cap_cols = 0;
  o->n_rows = o->cap_rows = 0;
}
