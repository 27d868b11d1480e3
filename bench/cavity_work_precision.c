/* Work-precision of the flow engine on configs/cavity_stokes.ini: the
 * minimum of u on the vertical centreline (401 samples refined by golden
 * section) against the value on the finest mesh, versus CPU time, with the
 * split into assembly, factorisation and solve, and the peak memory.
 * Each mesh runs in its own process so that its peak resident set is its own.
 *
 *   bench_cavity_work_precision [SOURCE_DIR] [n ...]     (default 8 16 32 64 128)
 * CSV on stdout. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/config/scene_schema.h"
#include "core/io/sample.h"
#include "core/models/navier_stokes.h"

static double cpu(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double u_at(const char *file, double y) {
  double xy[2] = {0.5, y};
  sl_sample s;
  if (sl_sample_points(file, "velocity", INFINITY, 1, xy, &s, NULL)) return NAN;
  double v = s.values[0];
  sl_sample_free(&s);
  return v;
}

static double centreline_min(const char *file) {
  enum { N = 401 };
  double xy[2 * N];
  for (int k = 0; k < N; ++k) xy[2 * k] = 0.5, xy[2 * k + 1] = (double)k / (N - 1);
  sl_sample s;
  if (sl_sample_points(file, "velocity", INFINITY, N, xy, &s, NULL)) return NAN;
  int best = 1;
  for (int k = 1; k < N - 1; ++k)
    if (s.values[3 * k] < s.values[3 * best]) best = k;
  sl_sample_free(&s);
  const double g = 0.5 * (sqrt(5.0) - 1.0);
  double a = (best - 1.0) / (N - 1), b = (best + 1.0) / (N - 1);
  double c = b - g * (b - a), e = a + g * (b - a), fc = u_at(file, c), fe = u_at(file, e);
  while (b - a > 1e-10) {
    if (fc < fe) b = e, e = c, fe = fc, c = b - g * (b - a), fc = u_at(file, c);
    else a = c, c = e, fc = fe, e = a + g * (b - a), fe = u_at(file, e);
  }
  return fmin(fc, fe);
}

/* Runs one mesh; writes "umin cpu assembly factorisation solve rss_kb dofs" to fd. */
static int child(const char *src, int n, FILE *out) {
  char path[4096], set[64], file[64];
  snprintf(path, sizeof path, "%s/configs/cavity_stokes.ini", src);
  snprintf(set, sizeof set, "mesh.cells=%d", n);
  snprintf(file, sizeof file, "/tmp/sluice_bench_cavity_%d.h5", n);
  sl_diag d;
  sl_ini *ini = NULL;
  sl_registry *reg = NULL;
  int rc = sl_ini_parse_file(path, &ini, &d);
  if (!rc) rc = sl_ini_apply_override(ini, set, &d);
  if (!rc) rc = sl_scene_validate(ini, &d);
  if (!rc) rc = sl_registry_create(&reg, NULL, 0, &d);
  sl_ns_result res;
  sl_ns_run_opts o = {.scene_path = path, .output = file, .sluice_version = "bench"};
  double t0 = cpu();
  if (!rc) rc = sl_ns_run(ini, reg, &o, &res, &d);
  double t = cpu() - t0;
  if (rc) {
    fprintf(stderr, "n = %d: %s\n", n, d.msg);
    return rc;
  }
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  int dofs = 2 * (2 * n + 1) * (2 * n + 1) + (n + 1) * (n + 1);
  fprintf(out, "%.15g %.6g %.6g %.6g %.6g %ld %d %s\n", centreline_min(file), t, res.assembly, res.factorisation,
          res.solve, ru.ru_maxrss, dofs, res.linear_summary);
  remove(file);
  sl_registry_destroy(reg);
  sl_ini_free(ini);
  return 0;
}

int main(int argc, char **argv) {
  const char *src = argc > 1 ? argv[1] : ".";
  int ns[16] = {8, 16, 32, 64, 128}, nn = 5;
  if (argc > 2) {
    nn = 0;
    for (int i = 2; i < argc && nn < 16; ++i) ns[nn++] = atoi(argv[i]);
  }
  double umin[16], t[16], ta[16], tf[16], ts[16];
  long rss[16];
  int dofs[16];
  char lin[16][256];
  for (int k = 0; k < nn; ++k) {
    int fd[2];
    if (pipe(fd)) return 1;
    pid_t pid = fork();
    if (pid == 0) {
      close(fd[0]);
      FILE *f = fdopen(fd[1], "w");
      int rc = child(src, ns[k], f);
      fclose(f);
      _exit(rc);
    }
    close(fd[1]);
    FILE *f = fdopen(fd[0], "r");
    int got = fscanf(f, "%lf %lf %lf %lf %lf %ld %d %255[^\n]", &umin[k], &t[k], &ta[k], &tf[k], &ts[k], &rss[k],
                     &dofs[k], lin[k]);
    fclose(f);
    int status;
    waitpid(pid, &status, 0);
    if (got != 8 || !WIFEXITED(status) || WEXITSTATUS(status)) {
      fprintf(stderr, "n = %d failed\n", ns[k]);
      return 1;
    }
  }
  printf("n,dofs,umin,error_vs_finest,cpu_s,assembly_s,factorisation_s,solve_s,assembly_share,peak_rss_mb,linear\n");
  for (int k = 0; k < nn; ++k)
    printf("%d,%d,%.10f,%.3e,%.3f,%.3f,%.3f,%.3f,%.3f,%.1f,%s\n", ns[k], dofs[k], umin[k],
           k == nn - 1 ? 0.0 : fabs(umin[k] - umin[nn - 1]), t[k], ta[k], tf[k], ts[k], ta[k] / t[k], rss[k] / 1024.0,
           lin[k]);
  return 0;
}
