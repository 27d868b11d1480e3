/* SPDX-License-Identifier: GPL-2.0-or-later */
/* HDF5 + XDMF output: write a 2-triangle mesh and two steps, read everything
 * back bit for bit, validate the sidecar and the file with the external
 * tools, survive a crash (fork + _exit without closing), read while the
 * writer is still running, and report bad paths and bad calls clearly. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/io/output.h"
#include "core/util/blas.h"
#include "io_util.h"
#include "testing.h"

/*  2---3
 *  | \ |   coordinates with inexact binary values, to see bit-exact reads
 *  0---1 */
static const double xy[4 * 2] = {0.0, 0.0, 1.0 / 3.0, 0.1, 0.2, 2.0 / 3.0, 1.0 / 3.0 + 0.1, 0.7};
static const int32_t tri[2 * 3] = {0, 1, 2, 1, 3, 2};

/* Node scalar, node 2-D vector, cell scalar at step k. */
static void step_data(int k, double phi[4], double vel[8], double pres[2]) {
  for (int i = 0; i < 4; ++i) phi[i] = 0.1 * (i + 1) + k / 7.0;
  for (int i = 0; i < 8; ++i) vel[i] = sin(1.0 + i + k) / 3.0;
  pres[0] = 101325.0 + k / 3.0;
  pres[1] = -0.0;
}

/* Writes the mesh and n_steps steps; closes the file unless keep is given. */
static int write_run(const char *path, int n_steps, sl_output **keep, sl_diag *d) {
  sl_output *o = NULL;
  int rc = sl_output_open(&o, path, d);
  if (!rc) rc = sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Triangle", d);
  for (int k = 0; !rc && k < n_steps; ++k) {
    double phi[4], vel[8], pres[2];
    step_data(k, phi, vel, pres);
    rc = sl_output_begin_step(o, 0.5 * k, d);
    if (!rc) rc = sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, phi, d);
    if (!rc) rc = sl_output_write_field(o, "velocity", SL_CENTRE_NODE, 2, vel, d);
    if (!rc) rc = sl_output_write_field(o, "pressure", SL_CENTRE_CELL, 1, pres, d);
    if (!rc && k == 1) {
      const double vs[6] = {1, 2, 3, 4, 5, 6};
      rc = sl_output_write_field(o, "velocity_solid", SL_CENTRE_CELL, 3, vs, d);
    }
    if (!rc) rc = sl_output_end_step(o, d);
  }
  if (keep) {
    *keep = o;
    return rc;
  }
  int rc2 = sl_output_close(o, d);
  return rc ? rc : rc2;
}

/* Everything written by write_run(path, n_steps) reads back identically. */
static void check_contents(const char *path, int n_steps) {
  sl_diag d = {{0}};
  sl_output_mesh m;
  int rc = sl_output_read_mesh(path, &m, &d);
  CHECK_MSG(rc == 0, "%s", d.msg);
  if (rc) return;
  CHECK(m.dim == 2 && m.n_vertices == 4 && m.n_cells == 2 && m.nodes_per_cell == 3);
  CHECK(strcmp(m.topology, "Triangle") == 0);
  int same = 1;
  for (int v = 0; v < 4; ++v) {
    same &= memcmp(&m.coords[3 * v], &xy[2 * v], 2 * sizeof(double)) == 0;
    same &= m.coords[3 * v + 2] == 0.0;
  }
  CHECK(same);
  CHECK(memcmp(m.cells, tri, sizeof tri) == 0);
  sl_output_mesh_free(&m);

  int n = 0;
  double *times = NULL;
  CHECK(sl_output_read_times(path, &n, &times, &d) == 0);
  CHECK_MSG(n == n_steps, "%d steps, expected %d", n, n_steps);
  for (int k = 0; k < n && k < n_steps; ++k) CHECK(times[k] == 0.5 * k);
  free(times);

  for (int k = 0; k < n_steps; ++k) {
    double phi[4], vel[8], pres[2];
    step_data(k, phi, vel, pres);
    sl_output_field f;
    CHECK(sl_output_read_field(path, "phi", 0.5 * k + 0.1, &f, &d) == 0);
    CHECK(f.step == k && f.time == 0.5 * k && f.components == 1 && f.n == 4 && f.centring == SL_CENTRE_NODE);
    CHECK(f.values && memcmp(f.values, phi, sizeof phi) == 0);
    sl_output_field_free(&f);
    CHECK(sl_output_read_field(path, "velocity", 0.5 * k, &f, &d) == 0);
    CHECK(f.components == 3 && f.n == 4);
    int ok = f.values != NULL;
    for (int i = 0; ok && i < 4; ++i)
      ok = memcmp(&f.values[3 * i], &vel[2 * i], 2 * sizeof(double)) == 0 && f.values[3 * i + 2] == 0.0;
    CHECK(ok);
    sl_output_field_free(&f);
    CHECK(sl_output_read_field(path, "pressure", 0.5 * k, &f, &d) == 0);
    CHECK(f.centring == SL_CENTRE_CELL && f.n == 2 && f.components == 1);
    CHECK(f.values && memcmp(f.values, pres, sizeof pres) == 0 && signbit(f.values[1]));
    sl_output_field_free(&f);
  }
}

static void test_write_read(void) {
  sl_diag d = {{0}};
  const char *path = "io_tri.h5";
  CHECK(write_run(path, 2, NULL, &d) == 0);
  check_contents(path, 2);

  /* nearest step: ties go to the earlier one, +inf to the last */
  sl_output_field f;
  CHECK(sl_output_read_field(path, "phi", 0.25, &f, &d) == 0 && f.step == 0);
  sl_output_field_free(&f);
  CHECK(sl_output_read_field(path, "phi", 0.26, &f, &d) == 0 && f.step == 1);
  sl_output_field_free(&f);
  CHECK(sl_output_read_field(path, "phi", INFINITY, &f, &d) == 0 && f.step == 1);
  sl_output_field_free(&f);
  CHECK(sl_output_read_field(path, "phi", -5, &f, &d) == 0 && f.step == 0);
  sl_output_field_free(&f);
  /* only step 1 holds velocity_solid, so it is the nearest for t = 0 */
  CHECK(sl_output_read_field(path, "velocity_solid", 0.0, &f, &d) == 0);
  CHECK(f.step == 1 && f.components == 3 && f.n == 2 && f.values[5] == 6.0);
  sl_output_field_free(&f);
  CHECK(sl_output_read_field(path, "phii", 0.0, &f, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no field 'phii'");
  CHECK_CONTAINS(d.msg, "did you mean 'phi'?");
  CHECK(f.values == NULL);
  CHECK(sl_output_read_field(path, "../phi", 0.0, &f, &d) == SL_EBADINPUT);
}

static void test_provenance(void) {
  sl_diag d = {{0}};
  const char *path = "io_prov.h5";
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, path, &d) == 0);
  const sl_provenance_closure cl[1] = {
      {"closure.hindered_settling", "hindered_settling", "richardson_zaki", "1.0.0", "/opt/x/rz.so", "n = 4.65\n"}};
  const char *ini = "[scene]\nmodel = mixture ; \"quoted\" & <odd>\n";
  const sl_provenance prov = {"0.1.0", ini, 1, cl};
  CHECK(sl_output_write_provenance(o, &prov, &d) == 0);
  CHECK(sl_output_write_provenance(o, &prov, &d) == 0); /* a second call replaces the first */
  CHECK(sl_output_close(o, &d) == 0);
  char *s = NULL;
  CHECK(sl_output_read_text(path, "/provenance/ini", &s, &d) == 0 && s && strcmp(s, ini) == 0);
  free(s);
  CHECK(sl_output_read_text(path, "/provenance@sluice_version", &s, &d) == 0 && s && strcmp(s, "0.1.0") == 0);
  free(s);
  /* the BLAS the process runs on ("none loaded" here: this program calls no solver) */
  CHECK(sl_output_read_text(path, "/provenance@blas", &s, &d) == 0 && s && strcmp(s, sl_blas_description()) == 0);
  free(s);
  CHECK(sl_output_read_text(path, "/provenance/closures/closure_000@library", &s, &d) == 0 && s &&
        strcmp(s, "/opt/x/rz.so") == 0);
  free(s);
  CHECK(sl_output_read_text(path, "/provenance/closures/closure_000/parameters", &s, &d) == 0 && s &&
        strcmp(s, "n = 4.65\n") == 0);
  free(s);
  CHECK(sl_output_read_text(path, "/provenance@nothing", &s, &d) == SL_EBADINPUT && s == NULL);
  CHECK_CONTAINS(d.msg, "no attribute");
  /* No steps were written: no sidecar either, and the reader says so. */
  struct stat sb;
  CHECK(stat("io_prov.xmf", &sb) != 0);
  sl_output_field f;
  CHECK(sl_output_read_field(path, "phi", 0, &f, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "no output steps");
}

static void test_sidecar_and_tools(void) {
  char *x = slurp("io_tri.xmf");
  CHECK(x != NULL);
  if (x) {
    CHECK_CONTAINS(x, "CollectionType=\"Temporal\"");
    CHECK_CONTAINS(x, "<Time Value=\"0.5\"/>");
    CHECK_CONTAINS(x, "TopologyType=\"Triangle\" NumberOfElements=\"2\"");
    CHECK_CONTAINS(
        x, "Dimensions=\"4 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">io_tri.h5:/mesh/coordinates");
    CHECK_CONTAINS(x, "<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">");
    CHECK_CONTAINS(x, "<Attribute Name=\"pressure\" AttributeType=\"Scalar\" Center=\"Cell\">");
    CHECK_CONTAINS(x, "io_tri.h5:/step_000001/velocity_solid");
  }
  free(x);
  struct stat sb;
  CHECK(stat("io_tri.xmf.tmp", &sb) != 0); /* the temporary was renamed */
  int st = xmllint_status("io_tri.xmf");
  if (st != -2) CHECK_MSG(st == 0, "xmllint --noout io_tri.xmf: status %d", st);

  if (have_tool("h5dump")) {
    CHECK(run_quiet("h5dump io_tri.h5") == 0);
    CHECK(run_quiet("h5dump io_prov.h5") == 0);
    char *out = run_capture("h5dump -m %.17g -d /step_000000/pressure io_tri.h5");
    CHECK(out != NULL);
    if (out) CHECK_CONTAINS(out, "101325");
    free(out);
    out = run_capture("h5dump -H io_tri.h5");
    if (out) {
      CHECK_CONTAINS(out, "H5T_IEEE_F64LE");
      CHECK_CONTAINS(out, "H5T_STD_I32LE");
    }
    CHECK(out != NULL);
    free(out);
  } else {
    printf("skipped: h5dump not found (install hdf5-tools)\n");
  }
}

/* A child writes two steps, starts a third, and dies without closing the
 * file: the two complete steps are there, the third is not listed. */
static void test_crash(void) {
  sl_diag d = {{0}};
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    sl_output *o = NULL;
    const double phi[4] = {9, 9, 9, 9};
    int rc = write_run("io_crash.h5", 2, &o, &d);
    if (!rc) rc = sl_output_begin_step(o, 1.0, &d);
    if (!rc) rc = sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, phi, &d);
    _exit(rc == 0 ? 0 : 3); /* no close, no atexit handlers, no HDF5 shutdown */
  }
  int status = 0;
  CHECK(pid > 0 && waitpid(pid, &status, 0) == pid);
  CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  check_contents("io_crash.h5", 2);
  char *x = slurp("io_crash.xmf");
  CHECK(x && strstr(x, "step_000001") && !strstr(x, "step_000002"));
  free(x);
  int st = xmllint_status("io_crash.xmf");
  if (st != -2) CHECK(st == 0);
  if (have_tool("h5dump")) CHECK(run_quiet("h5dump io_crash.h5") == 0);

  /* The unfinished step never reached the disk here (no flush). Had the
   * metadata cache written it, the group would lack the "complete" mark:
   * add such a group by hand and check the readers skip it. */
  hid_t f = H5Fopen("io_crash.h5", H5F_ACC_RDWR, H5P_DEFAULT);
  hid_t g = f >= 0 ? H5Gcreate2(f, "/step_000002", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
  hid_t sp = H5Screate(H5S_SCALAR);
  const double t2 = 1.0;
  hid_t a = g >= 0 ? H5Acreate2(g, "time", H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
  CHECK(a >= 0 && H5Awrite(a, H5T_NATIVE_DOUBLE, &t2) >= 0);
  H5Aclose(a), H5Sclose(sp), H5Gclose(g);
  CHECK(H5Fclose(f) >= 0);
  int n = 0;
  double *times = NULL;
  CHECK(sl_output_read_times("io_crash.h5", &n, &times, &d) == 0 && n == 2);
  free(times);
  sl_output_field fl;
  CHECK(sl_output_read_field("io_crash.h5", "phi", 1.0, &fl, &d) == 0 && fl.step == 1);
  sl_output_field_free(&fl);
}

/* A child writes two steps and waits; the parent reads the file while the
 * writer still has it open, then lets it write a third step and close. */
static void test_live(void) {
  int up[2], down[2];
  CHECK(pipe(up) == 0 && pipe(down) == 0);
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    sl_diag d = {{0}};
    sl_output *o = NULL;
    int rc = sl_output_open(&o, "io_live.h5", &d);
    if (!rc) rc = sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Triangle", &d);
    for (int k = 0; !rc && k < 3; ++k) {
      double phi[4], vel[8], pres[2];
      step_data(k, phi, vel, pres);
      if (k == 2) {
        char c;
        if (write(up[1], "w", 1) != 1 || read(down[0], &c, 1) != 1) rc = 1; /* wait for the reader */
      }
      if (!rc) rc = sl_output_begin_step(o, 0.5 * k, &d);
      if (!rc) rc = sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, phi, &d);
      if (!rc) rc = sl_output_write_field(o, "velocity", SL_CENTRE_NODE, 2, vel, &d);
      if (!rc) rc = sl_output_write_field(o, "pressure", SL_CENTRE_CELL, 1, pres, &d);
      if (!rc) rc = sl_output_end_step(o, &d);
    }
    int rc2 = sl_output_close(o, &d);
    if (rc || rc2) fprintf(stderr, "child: %s\n", d.msg);
    _exit(rc || rc2 ? 3 : 0);
  }
  char c = 0;
  CHECK(pid > 0 && read(up[0], &c, 1) == 1 && c == 'w');
  sl_diag d = {{0}};
  int n = 0;
  double *times = NULL;
  int rc = sl_output_read_times("io_live.h5", &n, &times, &d);
  CHECK_MSG(rc == 0 && n == 2, "while the writer runs: rc %d, %d steps: %s", rc, n, d.msg);
  free(times);
  sl_output_field f;
  double phi[4], vel[8], pres[2];
  step_data(1, phi, vel, pres);
  CHECK(sl_output_read_field("io_live.h5", "phi", 1.0, &f, &d) == 0 && f.step == 1 &&
        memcmp(f.values, phi, sizeof phi) == 0);
  sl_output_field_free(&f);
  int st = xmllint_status("io_live.xmf");
  if (st != -2) CHECK(st == 0);
  CHECK(write(down[1], "g", 1) == 1);
  int status = 0;
  CHECK(waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0);
  CHECK(sl_output_read_times("io_live.h5", &n, &times, &d) == 0 && n == 3);
  free(times);
  close(up[0]), close(up[1]), close(down[0]), close(down[1]);
}

static void test_other_topologies(void) {
  sl_diag d = {{0}};
  /* 1-D: 3 vertices, 2 segments */
  const double x[3] = {0.0, 0.25, 1.0};
  const int32_t seg[4] = {0, 1, 1, 2};
  const double u[3] = {1, 2, 3}, c[2] = {0.5, 0.6};
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "io_line.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 1, 3, x, 2, 2, seg, "Polyline", &d) == 0);
  CHECK(sl_output_begin_step(o, 0.0, &d) == 0);
  CHECK(sl_output_write_field(o, "u", SL_CENTRE_NODE, 1, u, &d) == 0);
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_CELL, 1, c, &d) == 0);
  CHECK(sl_output_end_step(o, &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  char *s = slurp("io_line.xmf");
  CHECK(s && strstr(s, "TopologyType=\"Polyline\" NumberOfElements=\"2\" NodesPerElement=\"2\""));
  free(s);
  int st = xmllint_status("io_line.xmf");
  if (st != -2) CHECK(st == 0);
  sl_output_mesh m;
  CHECK(sl_output_read_mesh("io_line.h5", &m, &d) == 0 && m.dim == 1 && m.coords[3] == 0.25 && m.coords[4] == 0.0);
  sl_output_mesh_free(&m);

  /* One Q9 cell on a 3 x 3 grid of nodes. */
  double q[9 * 2];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) q[2 * (3 * j + i)] = 0.5 * i, q[2 * (3 * j + i) + 1] = 0.5 * j;
  const int32_t q9[9] = {0, 2, 8, 6, 1, 5, 7, 3, 4};
  CHECK(sl_output_open(&o, "io_q9.h5", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, 9, q, 1, 9, q9, "Quadrilateral_9", &d) == 0);
  CHECK(sl_output_begin_step(o, 1.0, &d) == 0);
  CHECK(sl_output_write_field(o, "velocity", SL_CENTRE_NODE, 2, q, &d) == 0);
  CHECK(sl_output_end_step(o, &d) == 0);
  CHECK(sl_output_close(o, &d) == 0);
  st = xmllint_status("io_q9.xmf");
  if (st != -2) CHECK(st == 0);
}

static void test_errors(void) {
  sl_diag d = {{0}};
  sl_output *o = NULL;
  CHECK(sl_output_open(&o, "no_such_dir/out.h5", &d) == SL_EBADINPUT && o == NULL);
  CHECK_CONTAINS(d.msg, "no_such_dir/out.h5");
  CHECK_CONTAINS(d.msg, "directory 'no_such_dir' does not exist");
  printf("missing directory: %s\n", d.msg);
  CHECK(sl_output_open(&o, "io_tri.h5/out.h5", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "is not a directory");
  CHECK(sl_output_open(&o, "io_err.xmf", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "reserved for the sidecar");

  CHECK(sl_output_open(&o, "io_err.h5", &d) == 0);
  const double v[4] = {0};
  CHECK(sl_output_begin_step(o, 0.0, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "mesh before");
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, v, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "outside a step");
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Triangel", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "did you mean 'Triangle'");
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Quadrilateral", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "4 nodes per cell");
  const int32_t bad[6] = {0, 1, 2, 1, 4, 2};
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 2, 3, bad, "Triangle", &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "cell 1 refers to vertex 4");
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Triangle", &d) == 0);
  CHECK(sl_output_write_mesh(o, 2, 4, xy, 2, 3, tri, "Triangle", &d) == SL_EBADINPUT);
  CHECK(sl_output_end_step(o, &d) == SL_EBADINPUT);
  CHECK(sl_output_begin_step(o, NAN, &d) == SL_EBADINPUT);
  CHECK(sl_output_begin_step(o, 0.0, &d) == 0);
  CHECK(sl_output_begin_step(o, 1.0, &d) == SL_EBADINPUT);
  CHECK(sl_output_write_field(o, "a/b", SL_CENTRE_NODE, 1, v, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "contains '/'");
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_NODE, 4, v, &d) == SL_EBADINPUT);
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, v, &d) == 0);
  CHECK(sl_output_write_field(o, "phi", SL_CENTRE_NODE, 1, v, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "written twice");
  /* closing with the step open reports it and still frees everything */
  CHECK(sl_output_close(o, &d) == SL_EFAILED);
  CHECK_CONTAINS(d.msg, "unfinished");

  /* readers: missing file, not an HDF5 file */
  int n;
  double *t;
  CHECK(sl_output_read_times("io_nothing.h5", &n, &t, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "io_nothing.h5");
  CHECK_CONTAINS(d.msg, "No such file");
  CHECK(sl_output_read_times("io_tri.xmf", &n, &t, &d) == SL_EBADINPUT);
  CHECK_CONTAINS(d.msg, "cannot open as HDF5");
  printf("not HDF5: %s\n", d.msg);
}

int main(void) {
  test_write_read();
  test_provenance();
  test_sidecar_and_tools();
  test_crash();
  test_live();
  test_other_topologies();
  test_errors();
  return sl_test_summary();
}
