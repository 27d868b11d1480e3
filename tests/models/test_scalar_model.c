/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The scalar model (core/models/scalar): the smallest model on the shared
 * layers, run through the embedding API, against exact solutions:
 *  - steady diffusion between two given values: the linear profile, exact;
 *  - a sine diffusing on a periodic grid: exp(-D k^2 t) sin(k x), second
 *    order in space (dt ~ h^2);
 *  - steady convection-diffusion across a channel: the exponential boundary
 *    layer, first order (upwind);
 *  - a closed box stirred by a velocity field: the inventory conserved;
 *  - a run stopped and restarted ends bit for bit where the whole one does;
 *  - the time loop's services the model did not write: progress once per
 *    accepted step, the profile's counts, the output times. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "sluice/sluice.h"
#include "testing.h"

static const double PI = 3.14159265358979323846;

static int run_text(const char *text, const char *const *sets, const char *out, const char *restart,
                    sluice_summary *sum) {
  sluice *s = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.sets = sets};
  sluice_run_opts ro = {.output = out, .restart = restart, .version = "test"};
  sluice_summary local;
  int rc = sluice_open_text(text, strlen(text), "scalar.ini", &oo, &s, &e);
  if (!rc) rc = sluice_run(s, &ro, sum ? sum : &local, &e);
  CHECK_MSG(rc == 0, "%s", e.msg);
  sluice_close(s);
  return rc;
}

/* The last output's value field and the cell centres of the mesh (n cells). */
static double *values(const char *out, double *xc, double *yc, int *n) {
  sl_output_field f;
  sl_output_mesh m;
  sl_diag d = {{0}};
  if (sl_output_read_field(out, "value", INFINITY, &f, &d) || sl_output_read_mesh(out, &m, &d)) {
    CHECK_MSG(0, "%s: %s", out, d.msg);
    return NULL;
  }
  *n = f.n;
  for (int c = 0; c < f.n; ++c) {
    double x = 0, y = 0;
    for (int k = 0; k < m.nodes_per_cell; ++k) {
      int v = m.cells[c * m.nodes_per_cell + k];
      x += m.coords[3 * v] / m.nodes_per_cell, y += m.coords[3 * v + 1] / m.nodes_per_cell;
    }
    if (xc) xc[c] = x;
    if (yc) yc[c] = y;
  }
  sl_output_mesh_free(&m);
  return f.values;
}

/* A scene: the mesh's keys, the [time] keys, the other sections. */
static const char *box(char *buf, size_t len, const char *mesh, const char *time, const char *body) {
  snprintf(buf, len, "[scene]\nmodel = scalar\n[mesh]\ngenerator = rectangle\n%s\n[time]\n%s\n%s\n", mesh, time, body);
  return buf;
}

static void steady_diffusion(void) {
  char text[2048];
  box(text, sizeof text, "x = 0, 2\ny = 0, 1\ncells = 10, 3\ngrading_x = geometric:1.3", "end = 200\ndt = 5",
      "[scalar]\ndiffusivity = 1\n[initial]\nvalue = 0\n[boundary.left]\ntype = value\nvalue = 1\n"
      "[boundary.right]\ntype = value\nvalue = 3\n");
  if (run_text(text, NULL, "scalar_steady.h5", NULL, NULL)) return;
  double xc[64];
  int n;
  double *v = values("scalar_steady.h5", xc, NULL, &n);
  if (!v) return;
  double err = 0.0;
  for (int c = 0; c < n; ++c) err = fmax(err, fabs(v[c] - (1.0 + xc[c])));
  printf("steady diffusion on a graded grid: max |c - (1 + x)| = %.2e\n", err);
  CHECK_MSG(err < 1e-11, "the linear profile is exact for the scheme: error %.3e", err);
  free(v);
}

/* The sine's error at t = 0.05 on n cells across, dt = h^2 / 4. */
static double sine_error(int n) {
  char text[2048], mesh[128];
  double h = 1.0 / n, dt = 0.25 * h * h;
  snprintf(mesh, sizeof mesh, "x = 0, 1\ny = 0, 0.25\ncells = %d, 1", n);
  char time[128];
  snprintf(time, sizeof time, "end = 0.05\ndt = %.17g", dt);
  box(text, sizeof text, mesh, time,
      "[scalar]\ndiffusivity = 0.5\n[initial]\nvalue = sin(2*pi*x)\n[boundary.left]\ntype = periodic\n"
      "[boundary.right]\ntype = periodic\n");
  char out[64];
  snprintf(out, sizeof out, "scalar_sine_%d.h5", n);
  if (run_text(text, NULL, out, NULL, NULL)) return NAN;
  double xc[512];
  int m;
  double *v = values(out, xc, NULL, &m);
  if (!v) return NAN;
  double err = 0.0, decay = exp(-0.5 * 4.0 * PI * PI * 0.05);
  for (int c = 0; c < m; ++c) err = fmax(err, fabs(v[c] - decay * sin(2.0 * PI * xc[c])));
  free(v);
  return err;
}

static void periodic_sine(void) {
  double e1 = sine_error(16), e2 = sine_error(32), e3 = sine_error(64);
  double p1 = log2(e1 / e2), p2 = log2(e2 / e3);
  printf("periodic sine, 16/32/64 cells: max errors %.3e %.3e %.3e, orders %.2f %.2f\n", e1, e2, e3, p1, p2);
  CHECK_MSG(p1 > 1.9 && p2 > 1.9 && p2 < 2.1, "second order in space with dt ~ h^2: %.3f %.3f", p1, p2);
}

/* Steady convection-diffusion across a channel, c(0) = 0, c(1) = 1, u = 1, D = 0.1: c = (e^(x/D) - 1)/(e^(1/D) - 1). */
static double layer_error(int n) {
  char text[2048], mesh[128];
  snprintf(mesh, sizeof mesh, "x = 0, 1\ny = 0, 0.1\ncells = %d, 1", n);
  box(text, sizeof text, mesh, "end = 50\ndt = 1",
      "[scalar]\ndiffusivity = 0.1\nvelocity = 1, 0\n[initial]\nvalue = 0\n[boundary.left]\ntype = value\n"
      "value = 0\n[boundary.right]\ntype = value\nvalue = 1\n");
  char out[64];
  snprintf(out, sizeof out, "scalar_layer_%d.h5", n);
  if (run_text(text, NULL, out, NULL, NULL)) return NAN;
  double xc[1024];
  int m;
  double *v = values(out, xc, NULL, &m);
  if (!v) return NAN;
  double err = 0.0;
  for (int c = 0; c < m; ++c) err += fabs(v[c] - (exp(xc[c] / 0.1) - 1.0) / (exp(10.0) - 1.0)) / m;
  free(v);
  return err;
}

static void boundary_layer(void) {
  double e1 = layer_error(40), e2 = layer_error(80), e3 = layer_error(160);
  double p1 = log2(e1 / e2), p2 = log2(e2 / e3);
  printf("convection-diffusion layer (Pe = 10), 40/80/160 cells: L1 errors %.3e %.3e %.3e, orders %.2f %.2f\n", e1, e2,
         e3, p1, p2);
  CHECK_MSG(p2 > 0.85 && p2 < 1.15 && e3 < 1e-2, "first order (upwind): %.3f %.3f", p1, p2);
}

static void closed_box(void) {
  char text[2048];
  box(text, sizeof text, "x = 0, 1\ny = 0, 1\ncells = 12, 12", "end = 2\ndt = 0.05",
      "[scalar]\ndiffusivity = 1e-3\nvelocity = sin(pi*x)*cos(pi*y), -cos(pi*x)*sin(pi*y)\nsource = 0\n"
      "[initial]\nvalue = exp(-20*((x-0.3)^2 + (y-0.5)^2))\n[output]\nevery = 1\n");
  sluice_summary sum;
  if (run_text(text, NULL, "scalar_box.h5", NULL, &sum)) return;
  double err = NAN, t;
  sl_diag d;
  CHECK(sl_output_read_scalar("scalar_box.h5", "balance_error", 2.0, &err, &t, &d) == 0);
  printf("stirred closed box: %ld steps, inventory balance error %.2e\n", sum.steps, err);
  CHECK_MSG(fabs(err) < 1e-13 && sum.steps == 40, "conserved to round-off: %.3e (%ld steps)", err, sum.steps);
}

static void restart_bit_for_bit(void) {
  char text[2048];
  box(text, sizeof text, "x = 0, 1\ny = 0, 1\ncells = 8, 8", "end = 1\ndt = 0.1",
      "[scalar]\ndiffusivity = 0.01\nvelocity = 1, 0.5\nsource = sin(t)\n[initial]\nvalue = x*y\n"
      "[boundary.left]\ntype = value\nvalue = 1 + t\n");
  const char *first[] = {"time.max_steps=4", NULL};
  if (run_text(text, NULL, "scalar_whole.h5", NULL, NULL) || run_text(text, first, "scalar_first.h5", NULL, NULL) ||
      run_text(text, NULL, "scalar_second.h5", "scalar_first.h5", NULL))
    return;
  int n1, n2;
  double *a = values("scalar_whole.h5", NULL, NULL, &n1), *b = values("scalar_second.h5", NULL, NULL, &n2);
  CHECK_MSG(a && b && n1 == n2 && memcmp(a, b, (size_t)n1 * sizeof *a) == 0, "the restarted run ends elsewhere");
  free(a), free(b);
}

/* What the model gets from the shared time loop without a line of its own: progress after every accepted
 * step, the linear solver's counts that `--profile` prints, and an output every `every` seconds. */
typedef struct progress_log {
  long calls, last_step;
  double last_t;
  int monotone;
} progress_log;

static void log_progress(void *user, double t, double dt, long step, int nonlinear_iterations) {
  progress_log *p = user;
  (void)nonlinear_iterations;
  if (!(t > p->last_t) || step != p->last_step + 1 || !(dt > 0)) p->monotone = 0;
  ++p->calls, p->last_step = step, p->last_t = t;
}

static void loop_services(void) {
  char text[2048];
  box(text, sizeof text, "x = 0, 1\ny = 0, 1\ncells = 6, 6", "end = 1\ndt = 0.1",
      "[scalar]\ndiffusivity = 0.01\nvelocity = 1, 0\nsource = 0\n[initial]\nvalue = x\n[output]\nevery = 0.2\n");
  sluice *s = NULL;
  sluice_error e = {0, ""};
  sluice_open_opts oo = {.timing = 1};
  progress_log log = {0, 0, -1.0, 1};
  sluice_run_opts ro = {
      .output = "scalar_services.h5", .version = "test", .progress = log_progress, .progress_user = &log};
  sluice_summary sum;
  int rc = sluice_open_text(text, strlen(text), "scalar.ini", &oo, &s, &e);
  if (!rc) rc = sluice_run(s, &ro, &sum, &e);
  CHECK_MSG(rc == 0, "%s", e.msg);
  sluice_close(s);
  if (rc) return;
  printf(
      "time loop services: %ld progress calls for %ld steps (last t %.3g), %ld linear solves, %ld "
      "factorisations, %ld output times\n",
      log.calls, sum.steps, log.last_t, sum.linear.n_solves, sum.linear.n_numeric, sum.output_times);
  CHECK_MSG(log.calls == 10 && sum.steps == 10 && log.monotone && fabs(log.last_t - 1.0) < 1e-12,
            "progress once per accepted step: %ld calls, %ld steps, last t %.17g", log.calls, sum.steps, log.last_t);
  CHECK_MSG(
      sum.linear.n_solves >= sum.steps && sum.linear.n_numeric >= 1 && sum.linear.n_numeric <= sum.linear.n_solves,
      "profile counts: %ld solves, %ld factorisations", sum.linear.n_solves, sum.linear.n_numeric);
  CHECK_MSG(sum.output_times == 6, "outputs at t = 0, 0.2, ..., 1: %ld", sum.output_times);
}

static void bad_input(void) {
  char text[2048];
  box(text, sizeof text, "x = 0, 1\ny = 0, 1\ncells = 4, 4", "end = 1\ndt = 0.1",
      "[scalar]\ndiffusivity = 1\n[initial]\nvalue = 0\n[boundary.left]\ntype = wall\nvalue = 1\n");
  sluice *s = NULL;
  sluice_error e = {0, ""};
  int rc = sluice_open_text(text, strlen(text), "scalar.ini", NULL, &s, &e);
  if (!rc) rc = sluice_check(s, NULL, &e);
  CHECK_MSG(rc == SLUICE_BAD_INPUT && strstr(e.msg, "[boundary.left] value: only a boundary of type = value"),
            "rc %d, %s", rc, e.msg);
  sluice_close(s);
}

int main(void) {
  steady_diffusion();
  periodic_sine();
  boundary_layer();
  closed_box();
  restart_bit_for_bit();
  loop_services();
  bad_input();
  return sl_test_summary();
}
