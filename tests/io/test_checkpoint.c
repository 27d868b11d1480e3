/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Checkpoints: bit-for-bit round trip (special values included), the latest
 * one wins, arrays may change size or disappear, the file does not grow when
 * the shapes stay, and a crash after the slot write but before it is
 * declared current leaves the previous checkpoint. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/io/output.h"
#include "testing.h"

static void fill(double *v, int64_t n, unsigned seed) {
  uint64_t s = 0x9E3779B97F4A7C15ull * (seed + 1);
  for (int64_t i = 0; i < n; ++i) {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17; /* xorshift: arbitrary bit patterns of finite doubles */
    v[i] = ((double)(s >> 11) / 9007199254740992.0 - 0.5) * pow(10.0, (double)(int)(s % 40) - 20);
  }
  if (n >= 6) {
    v[0] = -0.0;
    v[1] = DBL_MIN / 3; /* subnormal */
    v[2] = DBL_MAX;
    v[3] = -INFINITY;
    v[4] = NAN;
    v[5] = 0.1 + 0.2;
  }
}

static int same_bits(const double *a, const double *b, int64_t n) { return memcmp(a, b, (size_t)n * sizeof *a) == 0; }

static void set_int(sl_checkpoint *ck, const char *name, int64_t v) {
  snprintf(ck->int_names[ck->n_ints], SL_CHECKPOINT_NAME_MAX, "%s", name);
  ck->ints[ck->n_ints++] = v;
}

/* The reader's result equals what was written (arrays in name order). */
static void check_equal(const sl_checkpoint *w, const sl_checkpoint *r) {
  CHECK(memcmp(&w->time, &r->time, sizeof w->time) == 0);
  CHECK(memcmp(&w->dt, &r->dt, sizeof w->dt) == 0);
  CHECK(w->step == r->step);
  CHECK(w->n_ints == r->n_ints);
  for (int i = 0; i < w->n_ints; ++i) {
    int found = 0;
    for (int j = 0; j < r->n_ints; ++j)
      if (strcmp(w->int_names[i], r->int_names[j]) == 0) found = r->ints[j] == w->ints[i];
    CHECK_MSG(found, "integer %s", w->int_names[i]);
  }
  CHECK(w->n_arrays == r->n_arrays);
  for (int i = 0; i < w->n_arrays; ++i) {
    const sl_checkpoint_array *a = sl_checkpoint_find(r, w->arrays[i].name);
    CHECK_MSG(a && a->n == w->arrays[i].n && (a->n == 0 || same_bits(a->data, w->arrays[i].data, a->n)), "array %s",
              w->arrays[i].name);
  }
}

static long file_size(const char *path) {
  struct stat sb;
  return stat(path, &sb) == 0 ? (long)sb.st_size : -1;
}

static void test_round_trip(void) {
  sl_diag d = {{0}};
  const char *path = "io_ck.h5";
  double *u = malloc(1000 * sizeof *u), *phi = malloc(250 * sizeof *phi), *u2 = malloc(1200 * sizeof *u2);
  fill(u, 1000, 1);
  fill(phi, 250, 2);
  fill(u2, 1200, 3);

  sl_output *o = NULL;
  CHECK(sl_output_open(&o, path, &d) == 0);
  sl_checkpoint_array arr1[3] = {{"u", 1000, u}, {"phi", 250, phi}, {"empty", 0, NULL}};
  sl_checkpoint c1 = {.time = 1.0 / 3.0, .dt = 1e-3 * 3.14159265358979, .step = 42, .n_arrays = 3, .arrays = arr1};
  set_int(&c1, "rejected", 3);
  set_int(&c1, "order", 2);
  set_int(&c1, "big", INT64_MIN + 1);
  CHECK(sl_output_write_checkpoint(o, &c1, &d) == 0);

  /* Readable while the writer is open (flushed), and bit for bit. */
  sl_checkpoint r;
  int rc = sl_checkpoint_read(path, &r, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  check_equal(&c1, &r);
  CHECK(sl_checkpoint_find(&r, "nope") == NULL);
  sl_checkpoint_free(&r);

  /* The second replaces it: u grows, phi changes values, empty goes away,
   * an integer goes away. */
  fill(phi, 250, 4);
  sl_checkpoint_array arr2[2] = {{"u", 1200, u2}, {"phi", 250, phi}};
  sl_checkpoint c2 = {.time = 2.5, .dt = 0.125, .step = 43, .n_arrays = 2, .arrays = arr2};
  set_int(&c2, "rejected", 4);
  set_int(&c2, "order", 1);
  CHECK(sl_output_write_checkpoint(o, &c2, &d) == 0);
  CHECK(sl_checkpoint_read(path, &r, &d) == 0);
  check_equal(&c2, &r);
  sl_checkpoint_free(&r);

  /* Same shapes from here on: the file must not keep growing. */
  long sizes[6];
  for (int k = 0; k < 6; ++k) {
    fill(u2, 1200, 10 + (unsigned)k);
    c2.step = 44 + k;
    c2.time += 0.125;
    CHECK(sl_output_write_checkpoint(o, &c2, &d) == 0);
    sizes[k] = file_size(path);
  }
  CHECK_MSG(sizes[5] == sizes[3] && sizes[4] == sizes[2], "file sizes %ld %ld %ld %ld", sizes[2], sizes[3], sizes[4],
            sizes[5]);
  printf("checkpoint file size after 8 checkpoints: %ld bytes\n", sizes[5]);
  CHECK(sl_checkpoint_read(path, &r, &d) == 0);
  check_equal(&c2, &r);
  sl_checkpoint_free(&r);
  CHECK(sl_output_close(o, &d) == 0);

  /* and after closing */
  CHECK(sl_checkpoint_read(path, &r, &d) == 0);
  check_equal(&c2, &r);
  sl_checkpoint_free(&r);
  free(u), free(phi), free(u2);
}

/* A child writes a checkpoint and dies without closing the file: the
 * checkpoint is there. Then a half-written second checkpoint (its slot
 * started, "current" not yet switched, as when a run dies while
 * checkpointing) is simulated with the HDF5 API: the reader still returns
 * the first one. */
static void test_crash(void) {
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    sl_diag d = {{0}};
    sl_output *o = NULL;
    double a[3] = {1.5, -2.5, 3.25};
    sl_checkpoint_array arr = {"state", 3, a};
    sl_checkpoint ck = {.time = 7.0, .dt = 0.5, .step = 14, .n_arrays = 1, .arrays = &arr};
    int rc = sl_output_open(&o, "io_ck_crash.h5", &d);
    if (!rc) rc = sl_output_write_checkpoint(o, &ck, &d);
    _exit(rc ? 3 : 0);
  }
  int status = 0;
  CHECK(pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0);
  sl_diag d = {{0}};
  sl_checkpoint r;
  for (int pass = 0; pass < 2; ++pass) {
    int rc = sl_checkpoint_read("io_ck_crash.h5", &r, &d);
    CHECK_MSG(rc == 0, "%s", d.msg);
    const sl_checkpoint_array *s = rc ? NULL : sl_checkpoint_find(&r, "state");
    CHECK(s && s->n == 3 && s->data[2] == 3.25 && r.step == 14 && r.time == 7.0);
    sl_checkpoint_free(&r);
    if (pass == 0) { /* start a second checkpoint in the other slot, then "die" */
      hid_t f = H5Fopen("io_ck_crash.h5", H5F_ACC_RDWR, H5P_DEFAULT);
      hid_t g = f >= 0 ? H5Gcreate2(f, "/checkpoint/slot_1", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
      hid_t sp = H5Screate(H5S_SCALAR);
      double t = 999.0;
      hid_t at = g >= 0 ? H5Acreate2(g, "time", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
      CHECK(at >= 0 && H5Awrite(at, H5T_NATIVE_DOUBLE, &t) >= 0);
      H5Aclose(at), H5Sclose(sp), H5Gclose(g);
      CHECK(H5Fclose(f) >= 0);
    }
  }
}

static void test_errors(void) {
  sl_diag d = {{0}};
  sl_checkpoint r;
  /* a file without a checkpoint */
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "io_ck_none.h5", &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  CHECK(sl_checkpoint_read("io_ck_none.h5", &r, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no checkpoint");
  CHECK(r.arrays == NULL && r.n_arrays == 0);
  CHECK(sl_checkpoint_read("io_ck_missing.h5", &r, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "io_ck_missing.h5");

  CHECK(sl_output_open(&o, "io_ck_bad.h5", &d) == 0);
  double a[2] = {1, 2};
  sl_checkpoint_array arr[2] = {{"x", 2, a}, {"x", 2, a}};
  sl_checkpoint ck = {.n_arrays = 2, .arrays = arr};
  CHECK(sl_output_write_checkpoint(o, &ck, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'x' given twice");
  snprintf(arr[1].name, sizeof arr[1].name, "a b");
  CHECK(sl_output_write_checkpoint(o, &ck, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "contains ' '");
  ck.n_arrays = 1;
  ck.n_ints = SL_CHECKPOINT_MAX_INTS + 1;
  CHECK(sl_output_write_checkpoint(o, &ck, &d) == SL_EBADINPUT);
  ck.n_ints = 0;
  CHECK(sl_output_write_checkpoint(o, &ck, &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
}

int main(void) {
  test_round_trip();
  test_crash();
  test_errors();
  return sl_test_summary();
}
