/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/io/h5util.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void sl_h5_quiet(void) { H5Eset_auto2(H5E_DEFAULT, NULL, NULL); }

typedef struct h5_walk {
  char text[400];
} h5_walk;

static herr_t walk_cb(unsigned n, const H5E_error2_t *e, void *data) {
  h5_walk *w = data;
  if (n == 0 && e->desc && *e->desc) snprintf(w->text, sizeof w->text, "%s", e->desc);
  return 0;
}

int sl_h5_fail(sl_diag *d, int code, const char *file, const char *what, const char *object) {
  h5_walk w = {{0}};
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, walk_cb, &w); /* the most specific message first */
  H5Eclear2(H5E_DEFAULT);
  if (w.text[0]) return sl_diag_set(d, code, "%s: %s %s (HDF5: %s)", file, what, object, w.text);
  return sl_diag_set(d, code, "%s: %s %s", file, what, object);
}

int sl_io_check_name(const char *name, int max_len, const char *what, sl_diag *d) {
  if (!name || !*name) return sl_diag_set(d, SL_EBADINPUT, "%s name is empty", what);
  size_t len = strlen(name);
  if ((int)len > max_len)
    return sl_diag_set(d, SL_EBADINPUT, "%s name '%.40s...' is longer than %d", what, name, max_len);
  if (name[0] == '.') return sl_diag_set(d, SL_EBADINPUT, "%s name '%s' starts with '.'", what, name);
  for (const char *c = name; *c; ++c) {
    int ok = (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') || *c == '_' ||
             *c == '-' || *c == '.';
    if (!ok)
      return sl_diag_set(d, SL_EBADINPUT, "%s name '%s' contains '%c' (allowed: letters, digits, '_', '-', '.')", what,
                         name, *c);
  }
  return 0;
}

/* Creates attribute `name` on loc (replacing an old one) and writes it. */
static int attr_write(hid_t loc, const char *name, hid_t ftype, hid_t mtype, const void *buf, const char *file,
                      const char *obj, sl_diag *d) {
  char where[512];
  snprintf(where, sizeof where, "%s@%s", obj, name);
  htri_t ex = H5Aexists(loc, name);
  if (ex < 0) return sl_h5_fail(d, SL_EFAILED, file, "cannot query attribute", where);
  if (ex > 0 && H5Adelete(loc, name) < 0) return sl_h5_fail(d, SL_EFAILED, file, "cannot replace attribute", where);
  hid_t space = H5Screate(H5S_SCALAR);
  if (space < 0) return sl_h5_fail(d, SL_EFAILED, file, "cannot create dataspace for", where);
  /* Report before any other HDF5 call: each API call clears the error stack. */
  hid_t a = H5Acreate2(loc, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT);
  int rc = a < 0 ? sl_h5_fail(d, SL_EFAILED, file, "cannot create attribute", where) : 0;
  H5Sclose(space);
  if (rc) return rc;
  if (H5Awrite(a, mtype, buf) < 0) rc = sl_h5_fail(d, SL_EFAILED, file, "cannot write attribute", where);
  if (H5Aclose(a) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, file, "cannot close attribute", where);
  return rc;
}

int sl_h5_attr_double(hid_t loc, const char *name, double v, const char *file, const char *obj, sl_diag *d) {
  return attr_write(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v, file, obj, d);
}
int sl_h5_attr_int64(hid_t loc, const char *name, int64_t v, const char *file, const char *obj, sl_diag *d) {
  return attr_write(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &v, file, obj, d);
}
int sl_h5_attr_int32(hid_t loc, const char *name, int32_t v, const char *file, const char *obj, sl_diag *d) {
  return attr_write(loc, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &v, file, obj, d);
}

/* Variable-length UTF-8: h5dump prints it as text, h5py returns a str
 * (fixed-length strings come back as bytes). */
static hid_t string_type(void) {
  hid_t t = H5Tcopy(H5T_C_S1);
  if (t < 0) return t;
  if (H5Tset_size(t, H5T_VARIABLE) < 0 || H5Tset_cset(t, H5T_CSET_UTF8) < 0) {
    H5Tclose(t);
    return -1;
  }
  return t;
}

int sl_h5_attr_string(hid_t loc, const char *name, const char *s, const char *file, const char *obj, sl_diag *d) {
  if (!s) s = "";
  hid_t t = string_type();
  if (t < 0) return sl_h5_fail(d, SL_EFAILED, file, "cannot make a string type for", obj);
  int rc = attr_write(loc, name, t, t, &s, file, obj, d);
  H5Tclose(t);
  return rc;
}

int sl_h5_dataset_string(hid_t loc, const char *name, const char *s, const char *file, const char *obj, sl_diag *d) {
  if (!s) s = "";
  hid_t t = string_type(), space = H5Screate(H5S_SCALAR), ds = -1;
  int rc = 0;
  if (t < 0 || space < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, file, "cannot make a string type for", obj);
    goto done;
  }
  ds = H5Dcreate2(loc, name, t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, file, "cannot create dataset", obj);
    goto done;
  }
  if (H5Dwrite(ds, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &s) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, file, "cannot write dataset", obj);
done:
  if (ds >= 0 && H5Dclose(ds) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, file, "cannot close dataset", obj);
  if (space >= 0) H5Sclose(space);
  if (t >= 0) H5Tclose(t);
  return rc;
}

int sl_h5_read_string(hid_t obj, int is_attr, char **text) {
  *text = NULL;
  hid_t ft = is_attr ? H5Aget_type(obj) : H5Dget_type(obj);
  if (ft < 0) return -1;
  int rc = -1;
  if (H5Tget_class(ft) == H5T_STRING) {
    htri_t vl = H5Tis_variable_str(ft);
    if (vl > 0) {
      hid_t mt = H5Tcopy(H5T_C_S1);
      char *p = NULL;
      if (mt >= 0 && H5Tset_size(mt, H5T_VARIABLE) >= 0 && H5Tset_cset(mt, H5Tget_cset(ft)) >= 0 &&
          (is_attr ? H5Aread(obj, mt, &p) : H5Dread(obj, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, &p)) >= 0) {
        size_t n = p ? strlen(p) : 0;
        if ((*text = malloc(n + 1))) {
          if (n) memcpy(*text, p, n);
          (*text)[n] = 0;
          rc = 0;
        }
        if (p) H5free_memory(p);
      }
      if (mt >= 0) H5Tclose(mt);
    } else if (vl == 0) { /* fixed length: files of sluice before 0.2 */
      size_t sz = H5Tget_size(ft);
      char *buf = malloc(sz + 1);
      if (buf && (is_attr ? H5Aread(obj, ft, buf) : H5Dread(obj, ft, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf)) >= 0) {
        buf[sz] = 0;
        *text = buf;
        rc = 0;
      } else {
        free(buf);
      }
    }
  }
  H5Tclose(ft);
  return rc;
}

static int attr_read(hid_t loc, const char *name, hid_t mtype, void *buf, const char *file, const char *obj,
                     sl_diag *d) {
  char where[512];
  snprintf(where, sizeof where, "%s@%s", obj, name);
  htri_t ex = H5Aexists(loc, name);
  if (ex <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return sl_diag_set(d, SL_EBADINPUT, "%s: attribute %s is missing", file, where);
  }
  hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  if (a < 0) return sl_h5_fail(d, SL_EBADINPUT, file, "cannot open attribute", where);
  int rc = H5Aread(a, mtype, buf) < 0 ? sl_h5_fail(d, SL_EBADINPUT, file, "cannot read attribute", where) : 0;
  H5Aclose(a);
  return rc;
}

int sl_h5_read_attr_double(hid_t loc, const char *name, double *v, const char *file, const char *obj, sl_diag *d) {
  return attr_read(loc, name, H5T_NATIVE_DOUBLE, v, file, obj, d);
}
int sl_h5_read_attr_int64(hid_t loc, const char *name, int64_t *v, const char *file, const char *obj, sl_diag *d) {
  return attr_read(loc, name, H5T_NATIVE_INT64, v, file, obj, d);
}

int sl_h5_read_attr_string(hid_t loc, const char *name, char *buf, size_t len, const char *file, const char *obj,
                           sl_diag *d) {
  char where[512];
  snprintf(where, sizeof where, "%s@%s", obj, name);
  hid_t a = H5Aexists(loc, name) > 0 ? H5Aopen(loc, name, H5P_DEFAULT) : -1;
  if (a < 0) {
    H5Eclear2(H5E_DEFAULT);
    return sl_diag_set(d, SL_EBADINPUT, "%s: attribute %s is missing", file, where);
  }
  char *text = NULL;
  int rc = 0;
  if (sl_h5_read_string(a, 1, &text) != 0)
    rc = sl_h5_fail(d, SL_EBADINPUT, file, "cannot read the string attribute", where);
  else snprintf(buf, len, "%s", text);
  free(text);
  H5Aclose(a);
  return rc;
}

int sl_h5_open_read(const char *path, hid_t *file, sl_diag *d) {
  sl_h5_quiet();
  *file = -1;
  struct stat sb;
  if (stat(path, &sb) != 0) return sl_diag_set(d, SL_EBADINPUT, "cannot open '%s': %s", path, strerror(errno));
  if (S_ISDIR(sb.st_mode)) return sl_diag_set(d, SL_EBADINPUT, "cannot open '%s': it is a directory", path);
#if H5_VERSION_GE(1, 10, 7)
  /* A running simulation (another process) holds the write lock; readers do
   * not need it. */
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot create", "a file access property list");
  if (H5Pset_file_locking(fapl, 0, 1) < 0) {
    int rc = sl_h5_fail(d, SL_EFAILED, path, "cannot disable", "file locking");
    H5Pclose(fapl);
    return rc;
  }
  sl_diag first;
  *file = H5Fopen(path, H5F_ACC_RDONLY, fapl);
  int rc = *file < 0 ? sl_h5_fail(&first, SL_EBADINPUT, path, "cannot open as HDF5", "file") : 0;
  H5Pclose(fapl);
  if (!rc) return 0;
  /* Open in this very process by the writer: HDF5 then shares the open file,
   * but only with the same locking setting as the writer's. */
  *file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (*file >= 0) return 0;
  H5Eclear2(H5E_DEFAULT);
  if (d) *d = first;
  return rc;
#else
  *file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (*file < 0) return sl_h5_fail(d, SL_EBADINPUT, path, "cannot open as HDF5", "file");
  return 0;
#endif
}

typedef struct name_list {
  char **v;
  int n, cap, oom;
} name_list;

static herr_t list_cb(hid_t g, const char *name, const H5L_info_t *info, void *data) {
  (void)g, (void)info;
  name_list *l = data;
  if (l->n == l->cap) {
    int cap = l->cap ? 2 * l->cap : 16;
    char **v = realloc(l->v, (size_t)cap * sizeof *v);
    if (!v) return (l->oom = 1), -1;
    l->v = v, l->cap = cap;
  }
  size_t len = strlen(name) + 1;
  if (!(l->v[l->n] = malloc(len))) return (l->oom = 1), -1;
  memcpy(l->v[l->n++], name, len);
  return 0;
}

int sl_h5_list(hid_t group, char ***names, int *n, const char *file, const char *obj, sl_diag *d) {
  name_list l = {0};
  hsize_t idx = 0;
  *names = NULL;
  *n = 0;
  if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &idx, list_cb, &l) < 0) {
    sl_io_free_names(l.v, l.n);
    if (l.oom) return sl_diag_set(d, SL_ENOMEM, "%s: out of memory listing %s", file, obj);
    return sl_h5_fail(d, SL_EBADINPUT, file, "cannot list group", obj);
  }
  *names = l.v;
  *n = l.n;
  return 0;
}

void sl_io_free_names(char **names, int n) {
  for (int i = 0; i < n; ++i) free(names[i]);
  free(names);
}
