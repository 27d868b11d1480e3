/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Readers of sluice output files: mesh, output times, a field at the step
 * nearest a time, string provenance, the list of fields and times. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/h5util.h"
#include "core/io/output.h"
#include "core/io/sample.h"

/* Reads a whole dataset of rank 1 or 2 into a new buffer. */
static int read_array(const char *path, hid_t loc, const char *name, hid_t mtype, size_t elem, int *rank,
                      hsize_t dims[2], void **buf, sl_diag *d) {
  *buf = NULL;
  hid_t ds = H5Dopen2(loc, name, H5P_DEFAULT);
  if (ds < 0) return sl_h5_fail(d, SL_EBADINPUT, path, "cannot open dataset", name);
  hid_t sp = H5Dget_space(ds);
  int rc = 0;
  dims[0] = dims[1] = 1;
  int r = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
  if (r < 1 || r > 2 || H5Sget_simple_extent_dims(sp, dims, NULL) != r) {
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: dataset %s is not a 1-D or 2-D array", path, name);
  } else {
    *rank = r;
    size_t count = (size_t)dims[0] * (r == 2 ? (size_t)dims[1] : 1);
    *buf = malloc(count * elem + 1);
    if (!*buf) rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory reading %s", path, name);
    else if (count > 0 && H5Dread(ds, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, *buf) < 0)
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot read dataset", name);
  }
  if (sp >= 0) H5Sclose(sp);
  H5Dclose(ds);
  if (rc) {
    free(*buf);
    *buf = NULL;
  }
  return rc;
}

int sl_output_read_mesh(const char *path, sl_output_mesh *m, sl_diag *d) {
  memset(m, 0, sizeof *m);
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  int rank_c = 0, rank_t = 0;
  hsize_t dc[2], dt[2];
  void *coords = NULL, *cells = NULL;
  rc = read_array(path, f, "/mesh/coordinates", H5T_NATIVE_DOUBLE, sizeof(double), &rank_c, dc, &coords, d);
  if (!rc) rc = read_array(path, f, "/mesh/topology", H5T_NATIVE_INT32, sizeof(int32_t), &rank_t, dt, &cells, d);
  if (!rc && (rank_c != 2 || dc[1] != 3 || rank_t != 2))
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: /mesh/coordinates or /mesh/topology has an unexpected shape", path);
  if (!rc) {
    hid_t top = H5Dopen2(f, "/mesh/topology", H5P_DEFAULT);
    int64_t dim = 0;
    if (top < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open dataset", "/mesh/topology");
    } else {
      rc = sl_h5_read_attr_string(top, "topology_type", m->topology, sizeof m->topology, path, "/mesh/topology", d);
      if (!rc) rc = sl_h5_read_attr_int64(top, "dim", &dim, path, "/mesh/topology", d);
      H5Dclose(top);
    }
    m->dim = (int)dim;
  }
  H5Fclose(f);
  if (rc) {
    free(coords), free(cells);
    memset(m, 0, sizeof *m);
    return rc;
  }
  m->coords = coords;
  m->cells = cells;
  m->n_vertices = (int32_t)dc[0];
  m->n_cells = (int32_t)dt[0];
  m->nodes_per_cell = (int)dt[1];
  return 0;
}

void sl_output_mesh_free(sl_output_mesh *m) {
  if (!m) return;
  free(m->coords);
  free(m->cells);
  memset(m, 0, sizeof *m);
}

typedef struct step_entry {
  int index;
  double time;
  char name[32];
} step_entry;

static int cmp_steps(const void *a, const void *b) {
  const step_entry *x = a, *y = b;
  return (x->index > y->index) - (x->index < y->index);
}

/* The step groups of an open file, in index order. */
static int list_steps(const char *path, hid_t f, step_entry **out, int *n_out, sl_diag *d) {
  char **names = NULL;
  int n = 0, k = 0;
  *out = NULL;
  *n_out = 0;
  int rc = sl_h5_list(f, &names, &n, path, "/", d);
  if (rc) return rc;
  step_entry *s = malloc(((size_t)n + 1) * sizeof *s);
  if (!s) rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
  for (int i = 0; !rc && i < n; ++i) {
    int idx, len = 0;
    if (sscanf(names[i], "step_%d%n", &idx, &len) != 1 || names[i][len] != 0 || strlen(names[i]) >= 32) continue;
    hid_t g = H5Gopen2(f, names[i], H5P_DEFAULT);
    if (g < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", names[i]);
      break;
    }
    htri_t done = H5Aexists(g, "complete"); /* begun but never ended: a run died mid-step */
    if (done > 0) {
      s[k].index = idx;
      snprintf(s[k].name, sizeof s[k].name, "%s", names[i]);
      rc = sl_h5_read_attr_double(g, "time", &s[k].time, path, names[i], d);
      ++k;
    } else if (done < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot query attributes of", names[i]);
    }
    H5Gclose(g);
  }
  sl_io_free_names(names, n);
  if (rc) {
    free(s);
    return rc;
  }
  qsort(s, (size_t)k, sizeof *s, cmp_steps);
  *out = s;
  *n_out = k;
  return 0;
}

int sl_output_read_times(const char *path, int *n_steps, double **times, sl_diag *d) {
  *n_steps = 0;
  *times = NULL;
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  step_entry *s = NULL;
  int n = 0;
  rc = list_steps(path, f, &s, &n, d);
  H5Fclose(f);
  if (rc) return rc;
  if (n > 0) {
    *times = malloc((size_t)n * sizeof **times);
    if (!*times) {
      free(s);
      return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
    }
    for (int i = 0; i < n; ++i) (*times)[i] = s[i].time;
  }
  *n_steps = n;
  free(s);
  return 0;
}

/* "no field" message with the fields of the last step and a did-you-mean. */
static int unknown_field(const char *path, hid_t f, const step_entry *s, int n, const char *name, sl_diag *d) {
  if (n == 0) return sl_diag_set(d, SL_EBADINPUT, "%s: no output steps in this file", path);
  char **names = NULL;
  int k = 0;
  hid_t g = H5Gopen2(f, s[n - 1].name, H5P_DEFAULT);
  if (g >= 0) {
    sl_diag tmp;
    if (sl_h5_list(g, &names, &k, path, s[n - 1].name, &tmp)) k = 0;
    H5Gclose(g);
  }
  H5Eclear2(H5E_DEFAULT);
  char list[512] = "";
  size_t len = 0;
  for (int i = 0; i < k && len < sizeof list; ++i)
    len += (size_t)snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "", names[i]);
  const char *hint = k > 0 ? sl_suggest(name, (const char *const *)names, k) : NULL;
  int rc;
  if (hint)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no field '%s' in any output step (did you mean '%s'?); fields: %s", path,
                     name, hint, list);
  else
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no field '%s' in any output step; fields: %s", path, name,
                     k ? list : "(none)");
  sl_io_free_names(names, k);
  return rc;
}

static int read_step_field(const char *path, hid_t f, const step_entry *st, const char *name, sl_output_field *fld,
                           sl_diag *d);

int sl_output_read_field(const char *path, const char *name, double t, sl_output_field *fld, sl_diag *d) {
  memset(fld, 0, sizeof *fld);
  int rc = sl_io_check_name(name, 200, "field", d);
  if (rc) return rc;
  if (isnan(t)) return sl_diag_set(d, SL_EBADINPUT, "%s: requested time is NaN", path);
  hid_t f;
  rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  step_entry *s = NULL;
  int n = 0;
  rc = list_steps(path, f, &s, &n, d);
  if (rc) {
    H5Fclose(f);
    return rc;
  }
  /* nearest step holding the field; the earlier on a tie, the last for +inf */
  int best = -1;
  double best_dist = INFINITY;
  for (int i = 0; i < n; ++i) {
    char link[256];
    snprintf(link, sizeof link, "%s/%s", s[i].name, name);
    if (H5Lexists(f, link, H5P_DEFAULT) <= 0) continue;
    double dist = fabs(s[i].time - t);
    if (best < 0 || dist < best_dist || (isinf(t) && t > 0)) best = i, best_dist = dist;
  }
  H5Eclear2(H5E_DEFAULT);
  if (best < 0) {
    rc = unknown_field(path, f, s, n, name, d);
    free(s);
    H5Fclose(f);
    return rc;
  }
  rc = read_step_field(path, f, &s[best], name, fld, d);
  free(s);
  H5Fclose(f);
  return rc;
}

int sl_output_read_field_at(const char *path, const char *name, int k, sl_output_field *fld, sl_diag *d) {
  memset(fld, 0, sizeof *fld);
  int rc = sl_io_check_name(name, 200, "field", d);
  if (rc) return rc;
  hid_t f;
  if ((rc = sl_h5_open_read(path, &f, d))) return rc;
  step_entry *s = NULL;
  int n = 0;
  rc = list_steps(path, f, &s, &n, d);
  if (!rc && (k < 0 || k >= n))
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no output step %d (the file has %d complete steps)", path, k, n);
  if (!rc) {
    char link[256];
    snprintf(link, sizeof link, "%s/%s", s[k].name, name);
    if (H5Lexists(f, link, H5P_DEFAULT) <= 0) {
      H5Eclear2(H5E_DEFAULT);
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: output step %d (t = %g) holds no field '%s'", path, k, s[k].time, name);
    }
  }
  if (!rc) rc = read_step_field(path, f, &s[k], name, fld, d);
  free(s);
  H5Fclose(f);
  return rc;
}

/* The dataset `name` of one step of an open file. */
static int read_step_field(const char *path, hid_t f, const step_entry *st, const char *name, sl_output_field *fld,
                           sl_diag *d) {
  char link[256];
  snprintf(link, sizeof link, "/%s/%s", st->name, name);
  int rc, rank = 0;
  hsize_t dims[2];
  void *buf = NULL;
  rc = read_array(path, f, link, H5T_NATIVE_DOUBLE, sizeof(double), &rank, dims, &buf, d);
  char centring[16] = "node";
  if (!rc) {
    hid_t ds = H5Dopen2(f, link, H5P_DEFAULT);
    if (ds < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open dataset", link);
    } else {
      rc = sl_h5_read_attr_string(ds, "centring", centring, sizeof centring, path, link, d);
      H5Dclose(ds);
    }
  }
  if (!rc) {
    fld->step = st->index;
    fld->time = st->time;
    fld->centring = strcmp(centring, "cell") == 0 ? SL_CENTRE_CELL : SL_CENTRE_NODE;
    fld->components = rank == 1 ? 1 : (int)dims[1];
    fld->n = (int32_t)dims[0];
    fld->values = buf;
  } else {
    free(buf);
  }
  return rc;
}

void sl_output_field_free(sl_output_field *f) {
  if (!f) return;
  free(f->values);
  memset(f, 0, sizeof *f);
}

int sl_output_read_text(const char *path, const char *what, char **text, sl_diag *d) {
  *text = NULL;
  char obj[512];
  snprintf(obj, sizeof obj, "%s", what);
  char *at = strchr(obj, '@');
  if (at) *at++ = 0;
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  hid_t o = H5Oopen(f, obj[0] ? obj : "/", H5P_DEFAULT), a = -1, type = -1;
  if (o < 0) {
    rc = sl_h5_fail(d, SL_EBADINPUT, path, "no object", obj);
    H5Fclose(f);
    return rc;
  }
  if (at) {
    a = H5Aexists(o, at) > 0 ? H5Aopen(o, at, H5P_DEFAULT) : -1;
    if (a < 0) {
      H5Eclear2(H5E_DEFAULT);
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: no attribute %s", path, what);
    } else {
      type = H5Aget_type(a);
    }
  } else if (H5Iget_type(o) != H5I_DATASET) {
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: %s is not a dataset", path, what);
  } else {
    type = H5Dget_type(o);
  }
  if (!rc && (type < 0 || H5Tget_class(type) != H5T_STRING))
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: %s is not a string", path, what);
  if (!rc && sl_h5_read_string(at ? a : o, at != NULL, text) != 0)
    rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot read", what);
  if (type >= 0) H5Tclose(type);
  if (a >= 0) H5Aclose(a);
  H5Oclose(o);
  H5Fclose(f);
  return rc;
}

static int cmp_field_info(const void *a, const void *b) {
  return strcmp(((const sl_output_field_info *)a)->name, ((const sl_output_field_info *)b)->name);
}

/* Adds one dataset of a step to the field list (a new entry or one more step
 * of a known field). */
static int note_field(const char *path, hid_t g, const step_entry *st, const char *name, sl_output_contents *c,
                      int *cap, sl_diag *d) {
  char full[320];
  snprintf(full, sizeof full, "/%s/%s", st->name, name);
  hid_t ds = H5Dopen2(g, name, H5P_DEFAULT);
  if (ds < 0) return sl_h5_fail(d, SL_EBADINPUT, path, "cannot open dataset", full);
  char centring[16];
  int64_t components = 0;
  int rc = sl_h5_read_attr_string(ds, "centring", centring, sizeof centring, path, full, d);
  if (!rc) rc = sl_h5_read_attr_int64(ds, "components", &components, path, full, d);
  H5Dclose(ds);
  if (rc) return rc;
  sl_output_field_info *fi = NULL;
  for (int i = 0; i < c->n_fields && !fi; ++i)
    if (strcmp(c->fields[i].name, name) == 0) fi = &c->fields[i];
  if (!fi) {
    if (c->n_fields == *cap) {
      int ncap = *cap ? 2 * *cap : 8;
      sl_output_field_info *nf = realloc(c->fields, (size_t)ncap * sizeof *nf);
      if (!nf) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
      c->fields = nf, *cap = ncap;
    }
    fi = &c->fields[c->n_fields++];
    memset(fi, 0, sizeof *fi);
    snprintf(fi->name, sizeof fi->name, "%s", name);
    fi->centring = strcmp(centring, "cell") == 0 ? SL_CENTRE_CELL : SL_CENTRE_NODE;
    fi->components = (int)components;
    fi->t_first = st->time;
  }
  ++fi->n_steps;
  fi->t_last = st->time;
  return 0;
}

int sl_output_read_contents(const char *path, sl_output_contents *c, sl_diag *d) {
  memset(c, 0, sizeof *c);
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  step_entry *s = NULL;
  int n = 0, cap = 0;
  rc = list_steps(path, f, &s, &n, d);
  if (!rc && n > 0 && !(c->times = malloc((size_t)n * sizeof *c->times)))
    rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
  for (int i = 0; !rc && i < n; ++i) {
    c->times[i] = s[i].time;
    c->n_steps = i + 1;
    hid_t g = H5Gopen2(f, s[i].name, H5P_DEFAULT);
    if (g < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", s[i].name);
      break;
    }
    char **names = NULL;
    int k = 0;
    rc = sl_h5_list(g, &names, &k, path, s[i].name, d);
    for (int j = 0; !rc && j < k; ++j) rc = note_field(path, g, &s[i], names[j], c, &cap, d);
    sl_io_free_names(names, k);
    H5Gclose(g);
  }
  free(s);
  H5Fclose(f);
  if (rc) {
    sl_output_contents_free(c);
    return rc;
  }
  if (c->n_fields > 1) qsort(c->fields, (size_t)c->n_fields, sizeof *c->fields, cmp_field_info);
  return 0;
}

void sl_output_contents_free(sl_output_contents *c) {
  if (!c) return;
  free(c->times);
  free(c->fields);
  memset(c, 0, sizeof *c);
}

int sl_output_read_scalar(const char *path, const char *name, double t, double *value, double *t_found, sl_diag *d) {
  int rc = sl_io_check_name(name, 200, "scalar", d);
  if (rc) return rc;
  if (isnan(t)) return sl_diag_set(d, SL_EBADINPUT, "%s: requested time is NaN", path);
  hid_t f;
  if ((rc = sl_h5_open_read(path, &f, d))) return rc;
  step_entry *s = NULL;
  int n = 0;
  if ((rc = list_steps(path, f, &s, &n, d))) {
    H5Fclose(f);
    return rc;
  }
  int best = -1;
  double best_dist = INFINITY;
  for (int i = 0; i < n; ++i) {
    if (H5Aexists_by_name(f, s[i].name, name, H5P_DEFAULT) <= 0) continue;
    double dist = fabs(s[i].time - t);
    if (best < 0 || dist < best_dist || (isinf(t) && t > 0)) best = i, best_dist = dist;
  }
  H5Eclear2(H5E_DEFAULT);
  if (best < 0) {
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no output time holds the scalar '%s'", path, name);
  } else {
    hid_t g = H5Gopen2(f, s[best].name, H5P_DEFAULT);
    if (g < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", s[best].name);
    } else {
      rc = sl_h5_read_attr_double(g, name, value, path, s[best].name, d);
      H5Gclose(g);
    }
    if (!rc && t_found) *t_found = s[best].time;
  }
  free(s);
  H5Fclose(f);
  return rc;
}

/* ---- the scalars of every output time (sample --scalars) ---- */

typedef struct scalar_walk {
  sl_output_scalars *s;
  int oom;
} scalar_walk;

static int scalar_column(sl_output_scalars *s, const char *name) {
  for (int c = 0; c < s->n_names; ++c)
    if (strcmp(s->names[c], name) == 0) return c;
  return -1;
}

static herr_t scalar_name_cb(hid_t loc, const char *name, const H5A_info_t *info, void *data) {
  (void)loc, (void)info;
  scalar_walk *w = data;
  sl_output_scalars *s = w->s;
  if (strcmp(name, "time") == 0 || strcmp(name, "index") == 0 || strcmp(name, "complete") == 0) return 0;
  if (scalar_column(s, name) >= 0) return 0;
  char **n = realloc(s->names, ((size_t)s->n_names + 1) * sizeof *n);
  if (!n) return (w->oom = 1), -1;
  s->names = n;
  char(*u)[SL_OUTPUT_UNIT_MAX] = realloc(s->units, ((size_t)s->n_names + 1) * sizeof *u);
  if (!u) return (w->oom = 1), -1;
  s->units = u;
  size_t len = strlen(name) + 1;
  if (!(s->names[s->n_names] = malloc(len))) return (w->oom = 1), -1;
  memcpy(s->names[s->n_names], name, len);
  s->units[s->n_names][0] = 0;
  ++s->n_names;
  return 0;
}

int sl_output_read_scalars(const char *path, sl_output_scalars *s, sl_diag *d) {
  memset(s, 0, sizeof *s);
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  step_entry *st = NULL;
  int n = 0;
  if ((rc = list_steps(path, f, &st, &n, d))) {
    H5Fclose(f);
    return rc;
  }
  scalar_walk w = {s, 0};
  for (int i = 0; !rc && i < n; ++i) { /* the names, in order of first appearance */
    hid_t g = H5Gopen2(f, st[i].name, H5P_DEFAULT);
    hsize_t idx = 0;
    if (g < 0 || H5Aiterate2(g, H5_INDEX_CRT_ORDER, H5_ITER_INC, &idx, scalar_name_cb, &w) < 0) {
      /* without creation order tracked: name order */
      idx = 0;
      if (w.oom || g < 0 || H5Aiterate2(g, H5_INDEX_NAME, H5_ITER_INC, &idx, scalar_name_cb, &w) < 0)
        rc = w.oom ? sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path)
                   : sl_h5_fail(d, SL_EBADINPUT, path, "cannot list the attributes of", st[i].name);
    }
    H5Eclear2(H5E_DEFAULT);
    if (g >= 0) H5Gclose(g);
  }
  if (!rc && n > 0) {
    s->n_times = n;
    s->times = malloc((size_t)n * sizeof *s->times);
    s->values = malloc((size_t)n * (size_t)(s->n_names > 0 ? s->n_names : 1) * sizeof *s->values);
    if (!s->times || !s->values) rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
  }
  for (int i = 0; !rc && i < n; ++i) {
    s->times[i] = st[i].time;
    hid_t g = H5Gopen2(f, st[i].name, H5P_DEFAULT);
    if (g < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", st[i].name);
      break;
    }
    for (int c = 0; !rc && c < s->n_names; ++c) {
      double *v = &s->values[(size_t)i * s->n_names + c];
      *v = NAN;
      if (H5Aexists(g, s->names[c]) > 0) rc = sl_h5_read_attr_double(g, s->names[c], v, path, st[i].name, d);
    }
    H5Gclose(g);
  }
  /* units: /scalar_units (files before it have none) */
  if (!rc && H5Lexists(f, "scalar_units", H5P_DEFAULT) > 0) {
    hid_t g = H5Gopen2(f, "scalar_units", H5P_DEFAULT);
    for (int c = 0; g >= 0 && c < s->n_names; ++c)
      if (H5Aexists(g, s->names[c]) > 0 &&
          sl_h5_read_attr_string(g, s->names[c], s->units[c], SL_OUTPUT_UNIT_MAX, path, "/scalar_units", d))
        s->units[c][0] = 0;
    if (g >= 0) H5Gclose(g);
  }
  H5Eclear2(H5E_DEFAULT);
  free(st);
  H5Fclose(f);
  if (rc) sl_output_scalars_free(s);
  return rc;
}

void sl_output_scalars_free(sl_output_scalars *s) {
  if (!s) return;
  for (int c = 0; c < s->n_names; ++c) free(s->names[c]);
  free(s->names);
  free(s->units);
  free(s->times);
  free(s->values);
  memset(s, 0, sizeof *s);
}
