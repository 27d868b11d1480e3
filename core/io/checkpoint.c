/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Checkpoints: /checkpoint/slot_0 and slot_1, written alternately; the
 * attribute /checkpoint@current names the last complete one and is written
 * (and flushed) only after the slot itself, so a crash while checkpointing
 * leaves the previous checkpoint usable. Datasets of the same size are
 * overwritten in place, so the file does not grow from one checkpoint to the
 * next. Doubles are stored as F64LE and come back bit for bit. */
#include <stdlib.h>
#include <string.h>

#include "core/io/h5util.h"
#include "core/io/output.h"

static hid_t open_or_create_group(hid_t loc, const char *name) {
  htri_t ex = H5Lexists(loc, name, H5P_DEFAULT);
  if (ex < 0) return -1;
  return ex ? H5Gopen2(loc, name, H5P_DEFAULT) : H5Gcreate2(loc, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
}

static int check_checkpoint(const sl_output *o, const sl_checkpoint *ck, sl_diag *d) {
  if (ck->n_ints < 0 || ck->n_ints > SL_CHECKPOINT_MAX_INTS)
    return sl_diag_set(d, SL_EBADINPUT, "%s: checkpoint has %d integers (at most %d)", o->path, ck->n_ints,
                       SL_CHECKPOINT_MAX_INTS);
  if (ck->n_arrays < 0 || (ck->n_arrays > 0 && !ck->arrays))
    return sl_diag_set(d, SL_EBADINPUT, "%s: checkpoint arrays missing", o->path);
  for (int i = 0; i < ck->n_ints; ++i) {
    int rc = sl_io_check_name(ck->int_names[i], SL_CHECKPOINT_NAME_MAX - 1, "checkpoint integer", d);
    if (rc) return sl_diag_prefix(d, rc, "%s", o->path);
    for (int j = 0; j < i; ++j)
      if (strcmp(ck->int_names[i], ck->int_names[j]) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s: checkpoint integer '%s' given twice", o->path, ck->int_names[i]);
  }
  for (int i = 0; i < ck->n_arrays; ++i) {
    const sl_checkpoint_array *a = &ck->arrays[i];
    int rc = sl_io_check_name(a->name, SL_CHECKPOINT_NAME_MAX - 1, "checkpoint array", d);
    if (rc) return sl_diag_prefix(d, rc, "%s", o->path);
    if (a->n < 0 || (a->n > 0 && !a->data))
      return sl_diag_set(d, SL_EBADINPUT, "%s: checkpoint array '%s' has no data", o->path, a->name);
    for (int j = 0; j < i; ++j)
      if (strcmp(a->name, ck->arrays[j].name) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "%s: checkpoint array '%s' given twice", o->path, a->name);
  }
  return 0;
}

/* Writes one array into `arrays`, reusing a dataset of the right size. */
static int put_array(sl_output *o, hid_t arrays, const char *slot, const sl_checkpoint_array *a, sl_diag *d) {
  char full[160];
  snprintf(full, sizeof full, "%s/arrays/%s", slot, a->name);
  hid_t ds = -1, space = -1;
  htri_t ex = H5Lexists(arrays, a->name, H5P_DEFAULT);
  if (ex < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot query", full);
  if (ex > 0) {
    ds = H5Dopen2(arrays, a->name, H5P_DEFAULT);
    if (ds < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot open dataset", full);
    hid_t s = H5Dget_space(ds);
    hsize_t dims[2] = {0, 0};
    int rank = s >= 0 ? H5Sget_simple_extent_dims(s, dims, NULL) : -1;
    if (s >= 0) H5Sclose(s);
    if (rank != 1 || dims[0] != (hsize_t)a->n) { /* shape changed: replace */
      H5Dclose(ds);
      ds = -1;
      if (H5Ldelete(arrays, a->name, H5P_DEFAULT) < 0)
        return sl_h5_fail(d, SL_EFAILED, o->path, "cannot replace", full);
    }
  }
  if (ds < 0) {
    hsize_t dim = (hsize_t)a->n;
    space = H5Screate_simple(1, &dim, NULL);
    if (space < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot create dataspace for", full);
    /* collective: the ranks' blocks cover it, no fill values written first (collective.c) */
    hid_t dcpl = o->collective ? H5Pcreate(H5P_DATASET_CREATE) : H5P_DEFAULT;
    if (dcpl >= 0 && o->collective && H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER) < 0) H5Pclose(dcpl), dcpl = -1;
    ds = dcpl >= 0 ? H5Dcreate2(arrays, a->name, H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT) : -1;
    int rc = ds < 0 ? sl_h5_fail(d, SL_EFAILED, o->path, "cannot create dataset", full) : 0;
    if (o->collective && dcpl >= 0) H5Pclose(dcpl);
    H5Sclose(space);
    if (rc) return rc;
  }
  int rc = 0;
  if (a->n > 0 && sl_io_write_rows(o, ds, H5T_NATIVE_DOUBLE, sizeof(double), (hsize_t)a->n, 1, a->data) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot write dataset", full);
  if (H5Dclose(ds) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close dataset", full);
  return rc;
}

typedef struct attr_names {
  char (*names)[SL_CHECKPOINT_NAME_MAX];
  int n, max, overflow;
} attr_names;

static herr_t attr_cb(hid_t loc, const char *name, const H5A_info_t *info, void *data) {
  (void)loc, (void)info;
  attr_names *a = data;
  if (a->n == a->max || strlen(name) >= SL_CHECKPOINT_NAME_MAX) return (a->overflow = 1), -1;
  snprintf(a->names[a->n++], SL_CHECKPOINT_NAME_MAX, "%s", name);
  return 0;
}

static int write_slot(sl_output *o, hid_t slot, const char *sname, const sl_checkpoint *ck, sl_diag *d) {
  const char *path = o->path;
  int rc = sl_h5_attr_double(slot, "time", ck->time, path, sname, d);
  if (!rc) rc = sl_h5_attr_double(slot, "dt", ck->dt, path, sname, d);
  if (!rc) rc = sl_h5_attr_int64(slot, "step", ck->step, path, sname, d);
  if (rc) return rc;

  char full[96];
  snprintf(full, sizeof full, "%s/ints", sname);
  hid_t ints = open_or_create_group(slot, "ints");
  if (ints < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot open group", full);
  /* Integers of an older checkpoint that this one lacks must go; the others
   * are replaced in the object header, which keeps the file size steady. */
  char old_ints[SL_CHECKPOINT_MAX_INTS][SL_CHECKPOINT_NAME_MAX];
  attr_names an = {old_ints, 0, SL_CHECKPOINT_MAX_INTS, 0};
  hsize_t idx = 0;
  if (H5Aiterate2(ints, H5_INDEX_NAME, H5_ITER_INC, &idx, attr_cb, &an) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, path, "cannot list attributes of", full);
  for (int i = 0; !rc && i < an.n; ++i) {
    int keep = 0;
    for (int j = 0; j < ck->n_ints && !keep; ++j) keep = strcmp(old_ints[i], ck->int_names[j]) == 0;
    if (!keep && H5Adelete(ints, old_ints[i]) < 0) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot delete", full);
  }
  for (int i = 0; !rc && i < ck->n_ints; ++i) rc = sl_h5_attr_int64(ints, ck->int_names[i], ck->ints[i], path, full, d);
  if (H5Gclose(ints) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot close group", full);
  if (rc) return rc;

  snprintf(full, sizeof full, "%s/arrays", sname);
  hid_t arrays = open_or_create_group(slot, "arrays");
  if (arrays < 0) return sl_h5_fail(d, SL_EFAILED, path, "cannot open group", full);
  /* Arrays of an older checkpoint that this one lacks must go. */
  char **old = NULL;
  int n_old = 0;
  rc = sl_h5_list(arrays, &old, &n_old, path, full, d);
  for (int i = 0; !rc && i < n_old; ++i) {
    int keep = 0;
    for (int j = 0; j < ck->n_arrays && !keep; ++j) keep = strcmp(old[i], ck->arrays[j].name) == 0;
    if (!keep && H5Ldelete(arrays, old[i], H5P_DEFAULT) < 0)
      rc = sl_h5_fail(d, SL_EFAILED, path, "cannot delete", old[i]);
  }
  sl_io_free_names(old, n_old);
  for (int i = 0; !rc && i < ck->n_arrays; ++i) rc = put_array(o, arrays, sname, &ck->arrays[i], d);
  if (H5Gclose(arrays) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, path, "cannot close group", full);
  return rc;
}

int sl_output_write_checkpoint(sl_output *o, const sl_checkpoint *ck, sl_diag *d) {
  int rc = check_checkpoint(o, ck, d);
  if (rc) return rc;
  double bytes = 0.0;
  for (int i = 0; i < ck->n_arrays; ++i) bytes += 8.0 * (double)ck->arrays[i].n;
  if ((rc = sl_io_space_check(o, bytes, "the checkpoint", d))) return rc;
  int s = o->ck_current == 0 ? 1 : 0;
  char sname[32], rel[16];
  snprintf(rel, sizeof rel, "slot_%d", s);
  snprintf(sname, sizeof sname, "/checkpoint/%s", rel);
  hid_t top = open_or_create_group(o->file, "checkpoint");
  if (top < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot open group", "/checkpoint");
  hid_t slot = open_or_create_group(top, rel);
  if (slot < 0) {
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot open group", sname);
  } else {
    rc = write_slot(o, slot, sname, ck, d);
    if (H5Gclose(slot) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close group", sname);
  }
  /* The slot must be on disk before it is declared current. */
  if (!rc && H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush", sname);
  if (!rc) rc = sl_h5_attr_int32(top, "current", s, o->path, "/checkpoint", d);
  if (H5Gclose(top) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close group", "/checkpoint");
  if (!rc && H5Fflush(o->file, H5F_SCOPE_GLOBAL) < 0)
    rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot flush", "/checkpoint");
  if (!rc) o->ck_current = s;
  if (!rc) rc = sl_output_commit(o, d); /* a restartable state is a result */
  return rc;
}

static int read_slot(const char *path, hid_t slot, const char *sname, sl_checkpoint *ck, sl_diag *d) {
  int rc = sl_h5_read_attr_double(slot, "time", &ck->time, path, sname, d);
  if (!rc) rc = sl_h5_read_attr_double(slot, "dt", &ck->dt, path, sname, d);
  if (!rc) rc = sl_h5_read_attr_int64(slot, "step", &ck->step, path, sname, d);
  if (rc) return rc;

  char full[96];
  snprintf(full, sizeof full, "%s/ints", sname);
  hid_t ints = H5Gopen2(slot, "ints", H5P_DEFAULT);
  if (ints < 0) return sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", full);
  attr_names an = {ck->int_names, 0, SL_CHECKPOINT_MAX_INTS, 0};
  hsize_t idx = 0;
  if (H5Aiterate2(ints, H5_INDEX_NAME, H5_ITER_INC, &idx, attr_cb, &an) < 0)
    rc = an.overflow ? sl_diag_set(d, SL_EBADINPUT, "%s: %s holds too many or too long names", path, full)
                     : sl_h5_fail(d, SL_EBADINPUT, path, "cannot list attributes of", full);
  ck->n_ints = an.n;
  for (int i = 0; !rc && i < an.n; ++i) rc = sl_h5_read_attr_int64(ints, ck->int_names[i], &ck->ints[i], path, full, d);
  H5Gclose(ints);
  if (rc) return rc;

  snprintf(full, sizeof full, "%s/arrays", sname);
  hid_t arrays = H5Gopen2(slot, "arrays", H5P_DEFAULT);
  if (arrays < 0) return sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", full);
  char **names = NULL;
  int n = 0;
  rc = sl_h5_list(arrays, &names, &n, path, full, d);
  if (!rc && n > 0 && !(ck->arrays = calloc((size_t)n, sizeof *ck->arrays)))
    rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory reading %s", path, full);
  for (int i = 0; !rc && i < n; ++i) {
    sl_checkpoint_array *a = &ck->arrays[i];
    char dname[160];
    snprintf(dname, sizeof dname, "%s/%s", full, names[i]);
    snprintf(a->name, sizeof a->name, "%s", names[i]);
    ck->n_arrays = i + 1;
    hid_t ds = H5Dopen2(arrays, names[i], H5P_DEFAULT);
    if (ds < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open dataset", dname);
      break;
    }
    hid_t sp = H5Dget_space(ds);
    hsize_t dim = 0;
    if (sp < 0 || H5Sget_simple_extent_ndims(sp) != 1 || H5Sget_simple_extent_dims(sp, &dim, NULL) != 1) {
      rc = sl_diag_set(d, SL_EBADINPUT, "%s: %s is not a 1-D array", path, dname);
    } else if (dim > 0) {
      double *buf = malloc((size_t)dim * sizeof *buf);
      if (!buf) rc = sl_diag_set(d, SL_ENOMEM, "%s: out of memory reading %s", path, dname);
      else if (H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0)
        rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot read dataset", dname);
      a->data = buf;
    }
    a->n = (int64_t)dim;
    if (sp >= 0) H5Sclose(sp);
    H5Dclose(ds);
  }
  sl_io_free_names(names, n);
  H5Gclose(arrays);
  return rc;
}

int sl_checkpoint_read(const char *path, sl_checkpoint *ck, sl_diag *d) {
  memset(ck, 0, sizeof *ck);
  hid_t f;
  int rc = sl_h5_open_read(path, &f, d);
  if (rc) return rc;
  if (H5Lexists(f, "checkpoint", H5P_DEFAULT) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    H5Fclose(f);
    return sl_diag_set(d, SL_EBADINPUT, "%s: no checkpoint in this file (no /checkpoint group)", path);
  }
  hid_t top = H5Gopen2(f, "checkpoint", H5P_DEFAULT);
  int64_t cur = -1;
  if (top < 0) rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", "/checkpoint");
  else if (H5Aexists(top, "current") <= 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: no complete checkpoint (/checkpoint@current is missing)", path);
  else rc = sl_h5_read_attr_int64(top, "current", &cur, path, "/checkpoint", d);
  if (!rc && cur != 0 && cur != 1)
    rc = sl_diag_set(d, SL_EBADINPUT, "%s: /checkpoint@current is %lld, not 0 or 1", path, (long long)cur);
  if (!rc) {
    char rel[16], sname[32];
    snprintf(rel, sizeof rel, "slot_%d", (int)cur);
    snprintf(sname, sizeof sname, "/checkpoint/%s", rel);
    hid_t slot = H5Gopen2(top, rel, H5P_DEFAULT);
    if (slot < 0) {
      rc = sl_h5_fail(d, SL_EBADINPUT, path, "cannot open group", sname);
    } else {
      rc = read_slot(path, slot, sname, ck, d);
      H5Gclose(slot);
    }
  }
  if (top >= 0) H5Gclose(top);
  H5Fclose(f);
  if (rc) sl_checkpoint_free(ck);
  return rc;
}

void sl_checkpoint_free(sl_checkpoint *ck) {
  if (!ck) return;
  for (int i = 0; ck->arrays && i < ck->n_arrays; ++i) free((void *)ck->arrays[i].data);
  free(ck->arrays);
  memset(ck, 0, sizeof *ck);
}

const sl_checkpoint_array *sl_checkpoint_find(const sl_checkpoint *ck, const char *name) {
  for (int i = 0; i < ck->n_arrays; ++i)
    if (strcmp(ck->arrays[i].name, name) == 0) return &ck->arrays[i];
  return NULL;
}
