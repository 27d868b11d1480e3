/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice bench end to end, through the sluice command as a user runs it:
 *  - a small Kynch study (Godunov and MUSCL on 50, 100, 200 cells against
 *    the exact solution): one CSV row per run with its measurements, errors
 *    that fall at a plausible order, a valid PNG;
 *  - a run that fails (an adaptive step that cannot get below its
 *    tolerance without going under dt_min) is recorded and the study goes on;
 *  - a closure comparison (two drag laws on the fluidised bed): the
 *    profiles side by side, the bed at its drag law's equilibrium;
 *  - the fluidised bed against its equilibrium porosity (exact =
 *    fluidized_bed) at two steady tolerances: the exact porosity
 *    (U/u_t)^(1/n) announced, errors below the tolerance that fall with it;
 *  - the other measures: the cavity's centreline minimum against a value
 *    (the same number bench/cavity_work_precision recorded), the Kynch
 *    interface height against a reference file of the exact top shock over
 *    time, and against the finest run of the sweep;
 *  - bad study files: exit status 2 with file:line, the key and a
 *    did-you-mean, and nothing written;
 *  - the studies of configs/bench/ pass --check. */
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench/png_check.h"
#include "core/study/kynch_exact.h"
#include "testing.h"

static char exe[4096], configs[4096];
static char output[1 << 16]; /* the last command's stdout and stderr */

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  (void)st, (void)flag, (void)ftw;
  return remove(path);
}

/* Runs sluice with args (NULL-terminated); returns its exit status. The
 * folder after "-o" is emptied first: each test starts from nothing. */
static int sluice(const char *const *args) {
  for (int i = 0; args[i] && args[i + 1]; ++i)
    if (!strcmp(args[i], "-o")) nftw(args[i + 1], remove_entry, 16, FTW_DEPTH | FTW_PHYS);
  const char *argv[32];
  int n = 0;
  argv[n++] = exe;
  for (int i = 0; args[i] && n < 31; ++i) argv[n++] = args[i];
  argv[n] = NULL;
  fflush(NULL);
  pid_t pid = fork();
  if (pid == 0) {
    int fd = open("command.out", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) _exit(127);
    dup2(fd, STDOUT_FILENO), dup2(fd, STDERR_FILENO);
    execv(exe, (char *const *)argv);
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  FILE *f = fopen("command.out", "r");
  size_t k = f ? fread(output, 1, sizeof output - 1, f) : 0;
  output[k] = '\0';
  if (f) fclose(f);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  CHECK_MSG(f != NULL, "%s: %s", path, strerror(errno));
  if (!f) return;
  fputs(text, f);
  fclose(f);
}

static int exists(const char *path) {
  struct stat st;
  return stat(path, &st) == 0;
}

/* ---- a small CSV reader (quoted fields, no line breaks inside) ---- */

enum { MAX_ROWS = 64, MAX_COLS = 32, CELL = 512 };
typedef struct csv {
  int rows, cols; /* rows after the header */
  char head[MAX_COLS][CELL];
  char cell[MAX_ROWS][MAX_COLS][CELL];
} csv;

static int split_csv(const char *line, char out[][CELL]) {
  int n = 0;
  const char *p = line;
  while (n < MAX_COLS) {
    char *o = out[n++];
    size_t k = 0;
    if (*p == '"') {
      for (++p; *p && !(*p == '"' && p[1] != '"'); ++p) {
        if (*p == '"') ++p;
        if (k + 1 < CELL) o[k++] = *p;
      }
      if (*p == '"') ++p;
    } else {
      for (; *p && *p != ',' && *p != '\n'; ++p)
        if (k + 1 < CELL) o[k++] = *p;
    }
    o[k] = '\0';
    if (*p != ',') break;
    ++p;
  }
  return n;
}

static int read_csv(const char *path, csv *c) {
  memset(c, 0, sizeof *c);
  FILE *f = fopen(path, "r");
  CHECK_MSG(f != NULL, "%s: %s", path, strerror(errno));
  if (!f) return -1;
  char line[8192];
  int first = 1;
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\r\n")] = '\0';
    if (first) c->cols = split_csv(line, c->head), first = 0;
    else if (c->rows < MAX_ROWS) {
      int n = split_csv(line, c->cell[c->rows]);
      CHECK_MSG(n == c->cols, "%s: row %d has %d fields, the header %d", path, c->rows + 1, n, c->cols);
      ++c->rows;
    }
  }
  fclose(f);
  return 0;
}

static int col(const csv *c, const char *name) {
  for (int k = 0; k < c->cols; ++k)
    if (!strcmp(c->head[k], name)) return k;
  CHECK_MSG(0, "no column '%s'", name);
  return 0;
}

static double num(const csv *c, int row, const char *name) {
  const char *s = c->cell[row][col(c, name)];
  char *end;
  double v = strtod(s, &end);
  return *s && !*end ? v : NAN;
}

/* ---- the studies ---- */

static void kynch_study(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/kynch_settling.ini\ntitle = \"Kynch, small\"\n"
           "[set.time]\nend = 60\n[set.output]\nevery = 60\n"
           "[points.mesh]\ncells = 50, 100, 200\n"
           "[variants]\nnames = Godunov, MUSCL\n[variants.transport]\norder = 1, 2\n"
           "[measure]\nexact = kynch\ntime = 60\nnorm = l1\n",
           configs);
  write_file("kynch_small.ini", text);
  const char *args[] = {"bench", "kynch_small.ini", "-o", "kynch_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  CHECK_CONTAINS(output, "[6/6] MUSCL; cells = 200");
  csv c;
  if (read_csv("kynch_out/kynch_small.csv", &c)) return;
  CHECK(c.rows == 6);
  static const char *const columns[] = {
      "variant",     "transport.order", "point",          "mesh.cells", "status",   "exit_status", "cpu_s", "wall_s",
      "peak_rss_mb", "steps",           "rejected_steps", "time",       "quantity", "error",       "order", "message"};
  CHECK(c.cols == (int)(sizeof columns / sizeof columns[0]));
  for (int k = 0; k < c.cols && k < (int)(sizeof columns / sizeof columns[0]); ++k)
    CHECK_MSG(!strcmp(c.head[k], columns[k]), "column %d is '%s', expected '%s'", k, c.head[k], columns[k]);
  const int cells[3] = {50, 100, 200};
  for (int r = 0; r < c.rows; ++r) {
    CHECK_MSG(!strcmp(c.cell[r][col(&c, "status")], "ok"), "row %d: %s", r + 1, c.cell[r][col(&c, "status")]);
    CHECK(!strcmp(c.cell[r][col(&c, "variant")], r < 3 ? "Godunov" : "MUSCL"));
    CHECK(num(&c, r, "mesh.cells") == cells[r % 3] && num(&c, r, "transport.order") == 1 + r / 3);
    CHECK(num(&c, r, "time") == 60.0);
    CHECK(num(&c, r, "steps") == 60 && num(&c, r, "rejected_steps") == 0); /* dt = 1, not adaptive */
    CHECK(num(&c, r, "cpu_s") > 0 && num(&c, r, "wall_s") > 0 && num(&c, r, "peak_rss_mb") > 1.0);
    CHECK(num(&c, r, "error") > 0);
  }
  /* First-order Godunov: the top shock's L1 error falls as h, the contact
   * shock at the bottom smears like a linear discontinuity, over
   * (h t)^(1/2) (Harten 1977), so the observed order lies between 1/2 and 1. */
  for (int r = 1; r < 3; ++r) {
    double p = num(&c, r, "order"), expect = log(num(&c, r - 1, "error") / num(&c, r, "error")) / log(2.0);
    printf("Kynch study: Godunov %d -> %d cells: L1 error %.4g -> %.4g, observed order %.3f\n", cells[r - 1], cells[r],
           num(&c, r - 1, "error"), num(&c, r, "error"), p);
    CHECK_MSG(p > 0.5 && p <= 1.0, "Godunov observed order %.3f outside (0.5, 1]", p);
    CHECK_MSG(fabs(p - expect) < 2e-3, "the order column %.3f is not log2 of the error ratio %.3f", p, expect);
  }
  /* MUSCL is the more accurate on every mesh */
  for (int r = 0; r < 3; ++r)
    CHECK_MSG(num(&c, r + 3, "error") < num(&c, r, "error"), "%d cells: MUSCL %.3g, Godunov %.3g", cells[r],
              num(&c, r + 3, "error"), num(&c, r, "error"));
  int w = 0, h = 0;
  unsigned char *rgb = NULL;
  const char *why = png_check_file("kynch_out/kynch_small.png", &w, &h, &rgb);
  CHECK_MSG(why == NULL, "kynch_small.png: %s", why ? why : "");
  CHECK(w >= 640 && h >= 480);
  free(rgb);
  CHECK_MSG(!exists("kynch_out/kynch_small.runs"), "the run outputs are left behind");
}

/* The adaptive variant fails: the channel accelerating from rest cannot be followed to a tolerance of 1e-12
 * without steps below dt_min. */
static void failing_run(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/bingham_channel.ini\n"
           "[set.mesh]\ncells = 20\n[set.time]\nscheme = bdf1\nend = 2\ndt = 1\ntolerance = 1e-12\ndt_min = 0.5\n"
           "[set.output]\nevery = 2\n[set.closure.viscosity]\neps = 0.1\n"
           "[variants]\nnames = adaptive, fixed\n[variants.time]\nadaptive = true, false\n"
           "[measure]\nexact = bingham\ntime = 2\n",
           configs);
  write_file("failing.ini", text);
  const char *args[] = {"bench", "failing.ini", "-o", "failing_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 1, "exit status %d (1 expected: a run failed):\n%s", rc, output);
  CHECK_CONTAINS(output, "[1/2] adaptive: failed (exit 1)");
  CHECK_CONTAINS(output, "[2/2] fixed: CPU");
  csv c;
  if (read_csv("failing_out/failing.csv", &c)) return;
  CHECK(c.rows == 2);
  CHECK(!strcmp(c.cell[0][col(&c, "status")], "failed") && num(&c, 0, "exit_status") == 1);
  CHECK_CONTAINS(c.cell[0][col(&c, "message")], "dt_min");
  CHECK(isnan(num(&c, 0, "error")));
  CHECK(!strcmp(c.cell[1][col(&c, "status")], "ok") && num(&c, 1, "error") > 0);
  CHECK(!strcmp(c.cell[1][col(&c, "message")], ""));
  /* the failed run's log is kept, the successful one's is not */
  FILE *f = fopen("failing_out/failing.runs/v01_p01.log", "r");
  CHECK_MSG(f != NULL, "the failed run's log is missing");
  if (f) {
    char buf[4096];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    CHECK_CONTAINS(buf, "dt_min");
  }
  CHECK(!exists("failing_out/failing.runs/v02_p01.log") && !exists("failing_out/failing.runs/v01_p01.h5"));
  int w, h;
  unsigned char *rgb = NULL;
  const char *why = png_check_file("failing_out/failing.png", &w, &h, &rgb);
  CHECK_MSG(why == NULL, "failing.png: %s", why ? why : "");
  free(rgb);
}

/* Two drag laws on the fluidised bed: a closure comparison. The scene's
 * drag section holds richardson_zaki_consistent's parameters; the study's
 * model change drops them. wen_yu's equilibrium porosity at U = 10 mm/s is
 * 0.6815 (docs/verification.md, two-fluid scenes: bisection on the published law). */
static void drag_comparison(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/fluidized_bed.ini\n[set.mesh]\ncells = 20\n"
           "[variants.closure.drag]\nmodel = ergun, wen_yu\n[measure]\nfield = phi\nn = 11\n",
           configs);
  write_file("drag.ini", text);
  const char *args[] = {"bench", "drag.ini", "-o", "drag_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  csv c;
  if (read_csv("drag_out/drag.csv", &c)) return;
  CHECK(c.rows == 2 && !strcmp(c.cell[0][col(&c, "status")], "ok") && !strcmp(c.cell[1][col(&c, "status")], "ok"));
  if (read_csv("drag_out/drag_compare.csv", &c)) return;
  CHECK(c.cols == 3 && c.rows == 11);
  CHECK(!strcmp(c.head[0], "s") && !strcmp(c.head[1], "model = ergun") && !strcmp(c.head[2], "model = wen_yu"));
  double most = 0.0;
  for (int r = 0; r < c.rows; ++r) {
    CHECK(fabs(num(&c, r, "s") - 0.1 * r) < 1e-12);
    double a = num(&c, r, "model = ergun"), b = num(&c, r, "model = wen_yu");
    CHECK(a >= 0.0 && a <= 0.64 && b >= 0.0 && b <= 0.64);
    most = fmax(most, fabs(a - b));
  }
  double porosity = 1.0 - num(&c, 0, "model = wen_yu");
  printf("drag comparison: wen_yu bed porosity %.5f (equilibrium 0.6815); largest difference from ergun %.4f\n",
         porosity, most);
  CHECK_MSG(fabs(porosity - 0.6815) < 5e-4, "wen_yu bed porosity %.5f", porosity);
  CHECK_MSG(most > 1e-3, "ergun and wen_yu give the same bed (%.3g)", most);
  int w, h;
  unsigned char *rgb = NULL;
  const char *why = png_check_file("drag_out/drag.png", &w, &h, &rgb);
  CHECK_MSG(why == NULL, "drag.png: %s", why ? why : "");
  free(rgb);
}

/* The fluidised bed run to steady at two tolerances on max |dphi/dt|,
 * measured against the equilibrium porosity of its drag
 * (richardson_zaki_consistent: (U/u_t)^(1/4.65) = 0.6421852193 at U = 10
 * mm/s, u_t = 78.4 mm/s from Stokes' law) over the bed below its top. The
 * discrete steady state is that equilibrium, so the error is what the
 * stopping test leaves: below the tolerance, and falling with it. */
static void fluidized_bed_study(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/fluidized_bed.ini\n[set.mesh]\ncells = 50\n"
           "[points.two_fluid]\nsteady_tolerance = 1e-3, 1e-7\n[measure]\nexact = fluidized_bed\nnorm = l1\n",
           configs);
  write_file("bed.ini", text);
  const char *args[] = {"bench", "bed.ini", "-o", "bed_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  const double u_t = (2600.0 - 998.2) * 9.81 * 3e-4 * 3e-4 / (18.0 * 1.002e-3), porosity = pow(0.010 / u_t, 1.0 / 4.65);
  char expect[128];
  snprintf(expect, sizeof expect, "equilibrium porosity of the fluidised bed: %.10f", porosity);
  CHECK_CONTAINS(output, expect);
  csv c;
  if (read_csv("bed_out/bed.csv", &c)) return;
  CHECK(c.rows == 2);
  const double tolerance[2] = {1e-3, 1e-7};
  for (int r = 0; r < c.rows && r < 2; ++r) {
    double e = num(&c, r, "error");
    printf("fluidized_bed study, 50 cells, steady_tolerance %g: L1 porosity error %.3g, steady at t = %g s\n",
           tolerance[r], e, num(&c, r, "time"));
    CHECK(!strcmp(c.cell[r][col(&c, "status")], "ok"));
    CHECK_MSG(e >= 0.0 && e < tolerance[r], "steady_tolerance %g: porosity error %.3g", tolerance[r], e);
    CHECK_MSG(num(&c, r, "time") < 599.0, "steady_tolerance %g: not steady by the end", tolerance[r]);
  }
  CHECK_MSG(num(&c, 1, "error") < 1e-3 * num(&c, 0, "error"), "the error fell from %.3g to %.3g only",
            num(&c, 0, "error"), num(&c, 1, "error"));
}

/* The minimum of u on x = 1/2 of the Stokes cavity against u*: on 8 x 8
 * cells bench/cavity_work_precision (its own run and golden-section search,
 * bench/results/cavity_work_precision.csv) found -0.2084992238. */
static void cavity_value(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/cavity_stokes.ini\n[points.mesh]\ncells = 4, 4 | 8, 8\n"
           "[measure]\nfield = velocity\ncomponent = 0\nline = 0.5,0:0.5,1\nn = 401\nreduce = min\n"
           "value = -0.207755897\n",
           configs);
  write_file("cavity_value.ini", text);
  const char *args[] = {"bench", "cavity_value.ini", "-o", "cavity_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  csv c;
  if (read_csv("cavity_out/cavity_value.csv", &c)) return;
  CHECK(c.rows == 2 && !strcmp(c.cell[1][col(&c, "mesh.cells")], "8, 8"));
  double q = num(&c, 1, "quantity");
  printf("cavity: min u on x = 1/2, 8 x 8 cells: %.10f (bench/cavity_work_precision: -0.2084992238)\n", q);
  CHECK_MSG(fabs(q - -0.2084992238) < 1e-9, "min u %.12f", q);
  for (int r = 0; r < 2; ++r) CHECK_CLOSE(num(&c, r, "error"), fabs(num(&c, r, "quantity") + 0.207755897), 1e-6);
  CHECK(num(&c, 1, "error") < num(&c, 0, "error"));
}

/* The written interface height (phi = 0.05 coming down from the top)
 * against the exact top shock z = H - v0 t at t = 20, 40, 60 s, given as a
 * reference file. A captured compressive shock is smeared over a few cells
 * about its exact place, so the half-level crossing lies within a cell of
 * it: the error stays below h. */
static void kynch_reference(void) {
  const double H = 0.5, ut = (2650.0 - 1000.0) * 9.81 * 1e-8 / (18.0 * 1e-3);
  kynch k;
  CHECK(kx_init(&k, kx_richardson_zaki(ut, 4.65, 0.64), H, 0.1) == 0);
  FILE *f = fopen("kynch_top.csv", "w");
  if (!f) return;
  fprintf(f, "t,interface_height\n");
  for (int j = 1; j <= 3; ++j) fprintf(f, "%g,%.12g\n", 20.0 * j, H - k.v0 * 20.0 * j);
  fclose(f);
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/kynch_settling.ini\n[set.time]\nend = 60\n[set.output]\nevery = 20\n"
           "[points.mesh]\ncells = 50, 100\n[measure]\nscalar = interface_height_0\nreference = kynch_top.csv\n"
           "norm = max\n",
           configs);
  write_file("kynch_reference.ini", text);
  const char *args[] = {"bench", "kynch_reference.ini", "-o", "reference_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  csv c;
  if (read_csv("reference_out/kynch_reference.csv", &c)) return;
  CHECK(c.rows == 2);
  for (int r = 0; r < c.rows; ++r) {
    double h = H / num(&c, r, "mesh.cells"), e = num(&c, r, "error");
    printf(
        "Kynch top interface, %g cells: largest distance from the exact shock over t = 20, 40, 60: %.3g m (h = %g)\n",
        num(&c, r, "mesh.cells"), e, h);
    CHECK_MSG(e > 0 && e < h, "%g cells: interface off by %.3g, more than a cell", num(&c, r, "mesh.cells"), e);
  }
}

/* Against the finest run: the interface height at t = 60 on 25, 50, 100
 * cells; the error is the distance from the 100-cell value. */
static void kynch_finest(void) {
  char text[8192];
  snprintf(text, sizeof text,
           "[study]\nscene = %s/kynch_settling.ini\n[set.time]\nend = 60\n[set.output]\nevery = 60\n"
           "[points.mesh]\ncells = 25, 50, 100\n[measure]\nscalar = interface_height_0\ntime = 60\nfinest = true\n",
           configs);
  write_file("kynch_finest.ini", text);
  const char *args[] = {"bench", "kynch_finest.ini", "-o", "finest_out", NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 0, "exit status %d:\n%s", rc, output);
  csv c;
  if (read_csv("finest_out/kynch_finest.csv", &c)) return;
  CHECK(c.rows == 3);
  double fin = num(&c, 2, "quantity");
  CHECK(num(&c, 2, "error") == 0.0);
  for (int r = 0; r < 2; ++r) CHECK_CLOSE(num(&c, r, "error"), fabs(num(&c, r, "quantity") - fin), 1e-5);
  CHECK(fin > 0.1 && fin < 0.5);
}

/* A bad study file: exit status 2, the message matches, nothing written. */
static void bad_study(const char *name, const char *body, const char *expect1, const char *expect2) {
  char file[256], text[8192], out[256], csvp[600];
  snprintf(file, sizeof file, "%s.ini", name);
  snprintf(out, sizeof out, "bad_out_%s", name);
  snprintf(text, sizeof text, body, configs);
  write_file(file, text);
  const char *args[] = {"bench", file, "-o", out, NULL};
  int rc = sluice(args);
  CHECK_MSG(rc == 2, "%s: exit status %d (2 expected):\n%s", name, rc, output);
  CHECK_MSG(strstr(output, expect1) != NULL, "%s: no '%s' in:\n%s", name, expect1, output);
  if (expect2) CHECK_MSG(strstr(output, expect2) != NULL, "%s: no '%s' in:\n%s", name, expect2, output);
  snprintf(csvp, sizeof csvp, "%s/%s.csv", out, name);
  CHECK_MSG(!exists(csvp) && !exists(out), "%s: something was written", name);
}

static void bad_studies(void) {
  static const char kynch_study_head[] = "[study]\nscene = %s/kynch_settling.ini\n";
  char body[8192];
  snprintf(body, sizeof body, "%s[measure]\nexact = kynch\nnrom = l1\n", kynch_study_head);
  bad_study("bad_measure_key", body, "bad_measure_key.ini:5:1: error: unknown key 'nrom' in [measure]",
            "did you mean 'norm'?");
  snprintf(body, sizeof body, "%s[points.mesh]\ncels = 10, 20\n[measure]\nexact = kynch\n", kynch_study_head);
  bad_study("bad_scene_key", body, "bad_scene_key.ini:4:", "unknown key 'cels' in [mesh]; did you mean 'cells'?");
  snprintf(body, sizeof body, "%s[set.time]\nend = -5\n[measure]\nexact = kynch\n", kynch_study_head);
  bad_study("bad_range", body, "bad_range.ini:4:", "allowed range");
  bad_study("bad_scene_file", "[study]\nscene = %s/no_such_scene.ini\n[measure]\nexact = kynch\n",
            "bad_scene_file.ini:2:", "no_such_scene.ini");
  snprintf(body, sizeof body, "%s[measur]\nexact = kynch\n", kynch_study_head);
  bad_study("bad_section", body, "bad_section.ini:3:", "did you mean [measure]?");
  bad_study("bad_exact", "[study]\nscene = %s/cavity_stokes.ini\n[measure]\nexact = kynch\n",
            "bad_exact.ini:4:", "needs a 1-D scene");
  snprintf(body, sizeof body, "%s[measure]\nexact = kinch\n", kynch_study_head);
  bad_study("bad_exact_name", body, "bad_exact_name.ini:4:", "did you mean 'kynch'?");
  bad_study("bad_bed_line", "[study]\nscene = %s/fluidized_bed.ini\n[measure]\nexact = fluidized_bed\nline = 0:0.5\n",
            "bad_bed_line.ini:5:", "the cells of the bed below its top; drop 'line'");
  bad_study("bad_bed_scene", "[study]\nscene = %s/kynch_settling.ini\n[measure]\nexact = fluidized_bed\n",
            "bad_bed_scene.ini:4:", "needs a two-fluid scene");
  snprintf(body, sizeof body,
           "%s[variants]\nnames = a, b\n[variants.transport]\norder = 1, 2, 2\n[measure]\nexact = kynch\n",
           kynch_study_head);
  bad_study("bad_names", body, "bad_names.ini:4:", "2 names for 3 values");
  snprintf(body, sizeof body, "%s[measure]\nfield = phi\nvalue = 0.1\n", kynch_study_head);
  bad_study("bad_value", body, "bad_value.ini:5:", "compares one number");
  snprintf(
      body, sizeof body,
      "%s[set.mesh]\ncells = 10\n[set.time]\nend = 4\n[set.output]\nevery = 2\n[measure]\nexact = kynch\ntime = 3\n",
      kynch_study_head);
  bad_study("bad_time", body, "bad_time.ini:9:", "no output at t = 3 (the nearest is t = 2)");
  bad_study("bad_geometry_line", "[study]\nscene = %s/cavity_stokes.ini\n[measure]\nfield = velocity\n",
            "bad_geometry_line.ini:3:", "give line = x0,y0:x1,y1");
}

static void help(void) {
  const char *bench_help[] = {"bench", "--help", NULL}, *top_help[] = {"--help", NULL}, *no_study[] = {"bench", NULL};
  CHECK(sluice(bench_help) == 0);
  CHECK_CONTAINS(output, "usage: sluice bench STUDY.ini");
  CHECK(sluice(top_help) == 0);
  CHECK_CONTAINS(output, "bench STUDY.ini");
  CHECK(sluice(no_study) == 2);
  CHECK_CONTAINS(output, "which study?");
}

/* The studies shipped in configs/bench/ stay valid as the scenes change. */
static void shipped_studies(void) {
  static const char *const names[] = {
      "kynch_settling", "cavity_stokes", "bingham_channel", "fluidized_bed_drag", "migration_couette_viscosity",
      "fluidized_bed"};
  for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k) {
    char path[4200];
    snprintf(path, sizeof path, "%s/bench/%s.ini", configs, names[k]);
    const char *args[] = {"bench", path, "--check", NULL};
    int rc = sluice(args);
    CHECK_MSG(rc == 0 && strstr(output, "study valid"), "%s: exit status %d:\n%s", names[k], rc, output);
  }
}

int main(void) {
  const char *src = getenv("SLUICE_SOURCE_DIR"), *e = getenv("SLUICE_EXE"), *bin = getenv("SLUICE_BINARY_DIR");
  if (!src || (!e && !bin)) {
    fprintf(stderr, "set SLUICE_SOURCE_DIR and SLUICE_EXE (or SLUICE_BINARY_DIR)\n");
    return 1;
  }
  snprintf(configs, sizeof configs, "%s/configs", src);
  if (e) snprintf(exe, sizeof exe, "%s", e);
  else snprintf(exe, sizeof exe, "%s/bin/sluice", bin);
  help();
  shipped_studies();
  kynch_study();
  failing_run();
  drag_comparison();
  fluidized_bed_study();
  cavity_value();
  kynch_reference();
  kynch_finest();
  bad_studies();
  return sl_test_summary();
}
