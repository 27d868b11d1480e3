/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The files of an output and what may replace them: a file sluice did not
 * write is refused (the scene file always), a scene's path stays in its
 * folder or the working folder, a run that fails before its first output
 * time leaves the earlier result byte for byte; the .xmf is one Uniform grid
 * for one output time, a temporal collection after, extended in place with
 * the scalars as Center="Grid" attributes; OUT_scalars.csv has one row per
 * output time with the units in the header; strings are variable-length
 * UTF-8, every field has units, cell centres are the cells' centroids. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/io/output.h"
#include "io_util.h"
#include "testing.h"

/* A quadrilateral that is not a parallelogram and a triangle:
 *  3-------2
 *  |        \      quad (0,1,2,3): (0,0) (2,0) (3,2) (0,2)
 *  0---------1     triangle (1,4,2): (2,0) (4,0) (3,2) */
static const double xy[5 * 2] = {0, 0, 2, 0, 3, 2, 0, 2, 4, 0};
static const int32_t quad[4] = {0, 1, 2, 3};

static int write_file(const char *path, const sl_output_opts *opts, int n_steps, int fail_before_end, sl_diag *d) {
  sl_output *o = NULL;
  int rc = sl_output_open_opts(&o, path, opts, d);
  if (rc) return rc;
  rc = sl_output_write_mesh(o, 2, 4, xy, 1, 4, quad, "Quadrilateral", d);
  for (int k = 0; !rc && k < n_steps; ++k) {
    const double phi[1] = {0.1 * k}, u[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    rc = sl_output_begin_step(o, 0.25 * k, d);
    if (!rc) rc = sl_output_write_field(o, "phi", SL_CENTRE_CELL, 1, phi, d);
    if (!rc) rc = sl_output_write_field(o, "velocity", SL_CENTRE_NODE, 2, u, d);
    if (!rc) rc = sl_output_write_field_unit(o, "concentration", "kg/m^3", SL_CENTRE_CELL, 1, phi, d);
    if (!rc) rc = sl_output_write_scalar(o, "solids_inventory", 1.5 + k, d);
    if (!rc) rc = sl_output_write_scalar(o, "interface_height_0", k == 1 ? NAN : 0.5 * k, d);
    if (!rc && k >= 2) rc = sl_output_write_scalar_unit(o, "torque_inner", "N m/m", -2.0 * k, d);
    if (!rc && !(fail_before_end && k == 0)) rc = sl_output_end_step(o, d);
    if (fail_before_end && k == 0) {
      sl_output_abort(o);
      return SL_EFAILED;
    }
  }
  if (rc) {
    sl_output_abort(o);
    return rc;
  }
  return sl_output_close(o, d);
}

static void write_text(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  if (f) fputs(text, f), fclose(f);
}

static int count(const char *s, const char *what) {
  int n = 0;
  for (const char *p = s; p && (p = strstr(p, what)); p += strlen(what)) ++n;
  return n;
}

static void test_refuse_foreign(void) {
  sl_diag d = {{0}};
  write_text("of_notes.h5", "my notes\n");
  CHECK(write_file("of_notes.h5", NULL, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "'of_notes.h5' exists and was not written by sluice");
  CHECK_CONTAINS(d.msg, "--overwrite");
  char *s = slurp("of_notes.h5");
  CHECK(s && strcmp(s, "my notes\n") == 0);
  free(s);
  struct stat sb;
  CHECK(stat("of_notes.h5.tmp", &sb) != 0);
  /* the sidecars too: a user's .xmf or CSV of the same stem */
  unlink("of_side.h5");
  write_text("of_side.xmf", "<?xml version=\"1.0\" ?>\n<Xdmf><Domain/></Xdmf>\n");
  CHECK(write_file("of_side.h5", NULL, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "of_side.xmf' exists and was not written by sluice");
  unlink("of_side.xmf");
  write_text("of_side_scalars.csv", "a,b\n1,2\n");
  CHECK(write_file("of_side.h5", NULL, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "of_side_scalars.csv' exists");
  unlink("of_side_scalars.csv");
  /* with overwrite the file is replaced; sluice's own files are replaced without */
  sl_output_opts ow = {.overwrite = 1};
  CHECK(write_file("of_notes.h5", &ow, 1, 0, &d) == 0);
  CHECK(write_file("of_notes.h5", NULL, 2, 0, &d) == 0);
  int n = 0;
  double *t = NULL;
  CHECK(sl_output_read_times("of_notes.h5", &n, &t, &d) == 0 && n == 2);
  free(t);
  /* a symbolic link is not followed */
  unlink("of_link.h5");
  CHECK(symlink("of_notes.h5", "of_link.h5") == 0);
  CHECK(write_file("of_link.h5", NULL, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "not a regular file (a symbolic link)");
  unlink("of_link.h5");
}

static void test_protect_scene(void) {
  sl_diag d = {{0}};
  write_text("of_scene.ini", "[scene]\nmodel = mixture\n");
  sl_output_opts o = {.overwrite = 1, .protect = "of_scene.ini"};
  CHECK(write_file("of_scene.ini", &o, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "is the scene file 'of_scene.ini' itself: it is never replaced");
  /* also when reached by another name */
  unlink("of_scene_link.ini");
  CHECK(symlink("of_scene.ini", "of_scene_link.ini") == 0);
  sl_output_opts o2 = {.overwrite = 1, .protect = "of_scene_link.ini"};
  CHECK(write_file("./of_scene.ini", &o2, 1, 0, &d) == SL_EBADINPUT);
  char *s = slurp("of_scene.ini");
  CHECK(s && strcmp(s, "[scene]\nmodel = mixture\n") == 0);
  free(s);
  unlink("of_scene_link.ini");
}

static void test_scene_folders(void) {
  sl_diag d = {{0}};
  mkdir("of_scene_dir", 0755);
  mkdir("of_scene_dir/results", 0755);
  char tmpl[] = "/tmp/sluice_of_XXXXXX";
  char *other = mkdtemp(tmpl);
  CHECK(other != NULL);
  if (!other) return;
  char path[512];
  snprintf(path, sizeof path, "%s/out.h5", other);
  sl_output_opts o = {.from_scene = 1, .scene_dir = "of_scene_dir"};
  CHECK(sl_output_check_path(path, &o, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "is outside the scene's folder of_scene_dir and the working folder");
  CHECK_CONTAINS(d.msg, "-o on the command line");
  /* the same path from the command line (not from the scene) is the user's choice */
  sl_output_opts cli = {.from_scene = 0, .scene_dir = "of_scene_dir"};
  CHECK(sl_output_check_path(path, &cli, &d) == 0);
  /* the scene's folder, below it, the working folder; ".." out of them is not */
  CHECK(sl_output_check_path("of_scene_dir/results/out.h5", &o, &d) == 0);
  CHECK(sl_output_check_path("of_wd.h5", &o, &d) == 0);
  CHECK(sl_output_check_path("of_scene_dir/../of_wd.h5", &o, &d) == 0);
  char up[512];
  snprintf(up, sizeof up, "%s/../out.h5", other);
  CHECK(sl_output_check_path(up, &o, &d) == SL_EBADINPUT);
  CHECK(sl_output_check_path("", &o, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "empty");
  rmdir(other);
}

/* A run that fails before its first complete output time leaves the earlier
 * result as it was, byte for byte, and no temporary. */
static void test_failure_keeps_old(void) {
  sl_diag d = {{0}};
  CHECK(write_file("of_keep.h5", NULL, 3, 0, &d) == 0);
  char *h5 = NULL, *xmf = slurp("of_keep.xmf"), *csv = slurp("of_keep_scalars.csv");
  struct stat before, after;
  CHECK(stat("of_keep.h5", &before) == 0);
  h5 = run_capture("cmp -s of_keep.h5 of_keep.h5 && md5sum < of_keep.h5");
  CHECK(write_file("of_keep.h5", NULL, 3, 1, &d) == SL_EFAILED);
  CHECK(stat("of_keep.h5", &after) == 0 && after.st_ino == before.st_ino && after.st_size == before.st_size);
  char *h5b = run_capture("md5sum < of_keep.h5"), *xmfb = slurp("of_keep.xmf"), *csvb = slurp("of_keep_scalars.csv");
  CHECK(h5 && h5b && strcmp(h5, h5b) == 0);
  CHECK(xmf && xmfb && strcmp(xmf, xmfb) == 0);
  CHECK(csv && csvb && strcmp(csv, csvb) == 0);
  struct stat sb;
  CHECK(stat("of_keep.h5.tmp", &sb) != 0 && errno == ENOENT);
  int n = 0;
  double *t = NULL;
  CHECK(sl_output_read_times("of_keep.h5", &n, &t, &d) == 0 && n == 3);
  free(t);
  free(h5), free(h5b), free(xmf), free(xmfb), free(csv), free(csvb);
  /* while a run writes its set-up, OUT.h5 is the old file; a kill leaves the
   * temporary, which the next run (recognising it as sluice's) replaces */
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "of_keep.h5", &d) == 0);
  CHECK(stat("of_keep.h5.tmp", &sb) == 0);
  CHECK(sl_output_read_times("of_keep.h5", &n, &t, &d) == 0 && n == 3);
  free(t);
  sl_output_abort(o);
  CHECK(stat("of_keep.h5.tmp", &sb) != 0);
}

static void test_sidecars(void) {
  sl_diag d = {{0}};
  /* one output time: a single Uniform grid, no <Time> and no collection (meshio.read) */
  CHECK(write_file("of_one.h5", NULL, 1, 0, &d) == 0);
  char *x = slurp("of_one.xmf");
  CHECK(x && !strstr(x, "Collection") && !strstr(x, "<Time") && count(x, "<Grid ") == 1);
  CHECK(x && strstr(x, "<Grid Name=\"step_000000\" GridType=\"Uniform\">"));
  CHECK(x && strstr(x, "<!-- written by sluice -->"));
  free(x);
  int st = xmllint_status("of_one.xmf");
  if (st != -2) CHECK(st == 0);

  /* five: a temporal collection, every grid with its time and scalars */
  CHECK(write_file("of_five.h5", NULL, 5, 0, &d) == 0);
  x = slurp("of_five.xmf");
  CHECK(x && strstr(x, "CollectionType=\"Temporal\""));
  CHECK(x && count(x, "GridType=\"Uniform\"") == 5 && count(x, "<Time Value=") == 5);
  CHECK(x && strstr(x, "<Time Value=\"1\"/>"));
  CHECK(x && count(x, "<Attribute Name=\"solids_inventory\" AttributeType=\"Scalar\" Center=\"Grid\">") == 5);
  CHECK(x && strstr(x, "Format=\"XML\">5.5</DataItem>"));
  CHECK(x && !strstr(x, "nan") && count(x, "Name=\"interface_height_0\"") == 4); /* NaN at t = 0.25 left out */
  CHECK(x && count(x, "Name=\"torque_inner\"") == 3);
  CHECK(x && count(x, "</Xdmf>") == 1);
  st = xmllint_status("of_five.xmf");
  if (st != -2) CHECK(st == 0);
  free(x);
  /* extended in place: the same file (inode), the text before the closing
   * tags kept, one grid more per output time */
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "of_grow.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 1, 4, quad, "Quadrilateral", &d) == 0);
  char *prev = NULL;
  ino_t ino = 0;
  const char *tail = "  </Grid>\n </Domain>\n</Xdmf>\n";
  for (int k = 0; k < 6; ++k) {
    const double phi[1] = {0.5};
    CHECK(sl_output_begin_step(o, k, &d) == 0);
    CHECK(sl_output_write_field(o, "phi", SL_CENTRE_CELL, 1, phi, &d) == 0);
    CHECK(sl_output_end_step(o, &d) == 0);
    char *now = slurp("of_grow.xmf");
    struct stat sb;
    CHECK(now && stat("of_grow.xmf", &sb) == 0);
    if (k >= 2 && prev && now) {
      size_t keep = strlen(prev) - strlen(tail);
      CHECK(sb.st_ino == ino && strncmp(prev, now, keep) == 0 && strcmp(prev + keep, tail) == 0);
      CHECK(count(now, "<Time Value=") == k + 1);
    }
    ino = sb.st_ino;
    free(prev);
    prev = now;
  }
  free(prev);
  CHECK(sl_output_close(o, &d) == 0);
  struct stat sb;
  CHECK(stat("of_five.xmf.tmp", &sb) != 0 && stat("of_grow.xmf.tmp", &sb) != 0);

  /* the CSV: a row per output time, units in the header, the column that
   * appears at the third output time empty before it, NaN as nan */
  char *c = slurp("of_five_scalars.csv");
  CHECK(c != NULL);
  if (c) {
    CHECK_MSG(strncmp(c, "time [s],solids_inventory [m^2],interface_height_0 [m],torque_inner [N m/m]\n",
                      strlen("time [s],solids_inventory [m^2],interface_height_0 [m],torque_inner [N m/m]\n")) == 0,
              "header: %.120s", c);
    CHECK(strstr(c, "\n0,1.5,0,\n0.25,2.5,nan,\n0.5,3.5,1,-4\n0.75,4.5,1.5,-6\n1,5.5,2,-8\n") != NULL);
    CHECK(count(c, "\n") == 6);
  }
  free(c);

  /* the reader sees the same */
  sl_output_scalars s;
  CHECK(sl_output_read_scalars("of_five.h5", &s, &d) == 0);
  CHECK(s.n_names == 3 && s.n_times == 5);
  if (s.n_names == 3 && s.n_times == 5) {
    CHECK(strcmp(s.names[0], "solids_inventory") == 0 && strcmp(s.units[0], "m^2") == 0);
    CHECK(strcmp(s.names[2], "torque_inner") == 0 && strcmp(s.units[2], "N m/m") == 0);
    CHECK(s.values[0 * 3 + 2] != s.values[0 * 3 + 2]); /* absent at t = 0 */
    CHECK(s.values[4 * 3 + 2] == -8.0 && s.values[4 * 3 + 0] == 5.5 && isnan(s.values[1 * 3 + 1]));
    CHECK(s.times[4] == 1.0);
  }
  sl_output_scalars_free(&s);
}

static char *attr_text(hid_t f, const char *obj, const char *name, int *vl) {
  hid_t a = H5Aopen_by_name(f, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) return NULL;
  hid_t t = H5Aget_type(a);
  *vl = H5Tis_variable_str(t) > 0 && H5Tget_cset(t) == H5T_CSET_UTF8;
  H5Tclose(t);
  H5Aclose(a);
  char *s = NULL;
  char full[256];
  snprintf(full, sizeof full, "%s@%s", obj, name);
  sl_diag d;
  (void)f;
  return sl_output_read_text("of_five.h5", full, &s, &d) == 0 ? s : NULL;
}

static void test_hdf5_layout(void) {
  hid_t f = H5Fopen("of_five.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CHECK(f >= 0);
  if (f < 0) return;
  int vl = 0;
  char *s = attr_text(f, "/", "format", &vl);
  CHECK(s && strcmp(s, "sluice-output 1") == 0 && vl);
  free(s);
  const char *fields[3][2] = {{"phi", "1"}, {"velocity", "m/s"}, {"concentration", "kg/m^3"}};
  for (int i = 0; i < 3; ++i) {
    char obj[64];
    snprintf(obj, sizeof obj, "/step_000002/%s", fields[i][0]);
    s = attr_text(f, obj, "units", &vl);
    CHECK_MSG(s && strcmp(s, fields[i][1]) == 0 && vl, "%s units '%s'", obj, s ? s : "(none)");
    free(s);
  }
  s = attr_text(f, "/mesh/topology", "topology_type", &vl);
  CHECK(s && strcmp(s, "Quadrilateral") == 0 && vl);
  free(s);
  s = attr_text(f, "/scalar_units", "interface_height_0", &vl);
  CHECK(s && strcmp(s, "m") == 0);
  free(s);
  /* the centroid of the trapezoid (0,0) (2,0) (3,2) (0,2): area 5,
   * x = (1/A) sum over its two triangles: (2*(5/3) + 3*(1))/5 = 19/15,
   * y = (2*(2/3) + 3*(4/3))/5 = 16/15 */
  double c[3] = {0, 0, 0};
  hid_t ds = H5Dopen2(f, "/mesh/cell_centres", H5P_DEFAULT);
  CHECK(ds >= 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, c) >= 0);
  if (ds >= 0) H5Dclose(ds);
  CHECK_MSG(fabs(c[0] - 19.0 / 15.0) < 1e-15 && fabs(c[1] - 16.0 / 15.0) < 1e-15 && c[2] == 0.0,
            "centre (%.17g, %.17g, %g)", c[0], c[1], c[2]);
  H5Fclose(f);

  /* a triangle's centroid is the mean of its vertices; 1-D the midpoint */
  sl_diag d = {{0}};
  sl_output *o = NULL;
  const int32_t tri[3] = {1, 4, 2};
  CHECK(sl_output_open(&o, "of_tri.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, 5, xy, 1, 3, tri, "Triangle", &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  const double x1[3] = {0.0, 0.3, 1.0};
  const int32_t seg[4] = {0, 1, 1, 2};
  CHECK(sl_output_open(&o, "of_line.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 1, 3, x1, 2, 2, seg, "Polyline", &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  double ct[3], cl[6];
  f = H5Fopen("of_tri.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  ds = f >= 0 ? H5Dopen2(f, "/mesh/cell_centres", H5P_DEFAULT) : -1;
  CHECK(ds >= 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ct) >= 0);
  CHECK(fabs(ct[0] - 3.0) < 1e-15 && fabs(ct[1] - 2.0 / 3.0) < 1e-15);
  if (ds >= 0) H5Dclose(ds);
  if (f >= 0) H5Fclose(f);
  f = H5Fopen("of_line.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  ds = f >= 0 ? H5Dopen2(f, "/mesh/cell_centres", H5P_DEFAULT) : -1;
  CHECK(ds >= 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, cl) >= 0);
  CHECK(cl[0] == 0.15 && cl[3] == 0.65 && cl[1] == 0.0);
  if (ds >= 0) H5Dclose(ds);
  if (f >= 0) H5Fclose(f);
}

/* Files of earlier versions: fixed-length strings, no format attribute.
 * They read as before, and count as sluice's (their provenance says so). */
static void test_older_files(void) {
  hid_t f = H5Fcreate("of_old.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  hid_t g = f >= 0 ? H5Gcreate2(f, "provenance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
  hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR);
  H5Tset_size(t, 6);
  H5Tset_strpad(t, H5T_STR_NULLTERM);
  hid_t a = g >= 0 ? H5Acreate2(g, "sluice_version", t, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
  CHECK(a >= 0 && H5Awrite(a, t, "0.0.9") >= 0);
  H5Aclose(a), H5Sclose(sp), H5Tclose(t), H5Gclose(g);
  CHECK(f >= 0 && H5Fclose(f) >= 0);
  sl_diag d = {{0}};
  char *s = NULL;
  CHECK(sl_output_read_text("of_old.h5", "/provenance@sluice_version", &s, &d) == 0 && s && strcmp(s, "0.0.9") == 0);
  free(s);
  CHECK_MSG(write_file("of_old.h5", NULL, 1, 0, &d) == 0, "%s", d.msg); /* replaced without --overwrite */
  s = NULL;
  CHECK(sl_output_read_text("of_old.h5", "/@format", &s, &d) == 0 && s && strcmp(s, "sluice-output 1") == 0);
  free(s);
  /* an HDF5 file of another program is not sluice's */
  f = H5Fcreate("of_other.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  CHECK(f >= 0 && H5Fclose(f) >= 0);
  CHECK(write_file("of_other.h5", NULL, 1, 0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "was not written by sluice");
}

int main(void) {
  test_refuse_foreign();
  test_protect_scene();
  test_scene_folders();
  test_failure_keeps_old();
  test_sidecars();
  test_hdf5_layout();
  test_older_files();
  return sl_test_summary();
}
