/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice sample OUT.h5: a field of an output file at points along a line or
 * at one point, as CSV; --list says what the file holds. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/config/ini.h"
#include "core/io/sample.h"

static const char sample_usage[] =
    "usage: sluice sample OUT.h5 --field F [--time T] --line x0,y0:x1,y1 [--n N]\n"
    "       sluice sample OUT.h5 --field F [--time T] --point x,y\n"
    "       sluice sample OUT.h5 --list\n"
    "       sluice sample OUT.h5 --scalars\n"
    "Prints field F of an output file at points, as CSV: a header line, then one\n"
    "row per point: its coordinates x,y (only x on a 1-D mesh), its arc length s\n"
    "from the start of the line, and the value (F) or the components of a vector\n"
    "(F_0,F_1,F_2).\n"
    "  --field F     the field to sample (--list shows the fields)\n"
    "  --time T      the output time nearest to T; T must lie between the first and\n"
    "                the last output time (default: the last output)\n"
    "  --line A:B    N points evenly spaced from A to B, both ends included;\n"
    "                x0,y0:x1,y1, or x0:x1 on a 1-D mesh\n"
    "  --n N         points on the line, N >= 1 (default 101)\n"
    "  --point P     one point: x,y, or x on a 1-D mesh\n"
    "  --list        the mesh, the fields, the output times and the scalars\n"
    "  --scalars     the model's scalars (solids inventory, interface heights, wall\n"
    "                stresses, ...) of every output time as CSV: time, then one\n"
    "                column per scalar, the units in the header (as OUT_scalars.csv)\n"
    "Node fields are interpolated with their cell's own basis (linear or quadratic\n"
    "Lagrange); cell fields are constant on each cell. A point outside the mesh\n"
    "gets nan and a warning on stderr; it is not an error.";

enum { DEFAULT_N = 101, MAX_N = 10000000 };

/* "x" or "x,y" (blanks around the numbers allowed); *n_coords is 1 or 2. */
static int parse_point(const char *s, double p[2], int *n_coords) {
  char buf[256];
  if (strlen(s) >= sizeof buf) return SL_EBADINPUT;
  snprintf(buf, sizeof buf, "%s", s);
  char *parts[3];
  int n = 0;
  for (char *q = buf, *comma; n < 3; q = comma + 1) {
    comma = strchr(q, ',');
    parts[n++] = q;
    if (!comma) break;
    *comma = '\0';
  }
  if (n > 2) return SL_EBADINPUT;
  p[1] = 0.0;
  for (int i = 0; i < n; ++i) {
    char *a = parts[i], *e = a + strlen(a);
    while (*a == ' ') ++a;
    while (e > a && e[-1] == ' ') *--e = '\0';
    if (sl_parse_real(a, &p[i])) return SL_EBADINPUT;
  }
  *n_coords = n;
  return 0;
}

/* --line A:B with both ends of the same dimension. */
static int parse_line(const char *s, double a[2], double b[2], int *n_coords) {
  const char *colon = strchr(s, ':');
  char first[256];
  int na = 0, nb = 0;
  if (!colon || strchr(colon + 1, ':') || (size_t)(colon - s) >= sizeof first) return SL_EBADINPUT;
  snprintf(first, sizeof first, "%.*s", (int)(colon - s), s);
  if (parse_point(first, a, &na) || parse_point(colon + 1, b, &nb) || na != nb) return SL_EBADINPUT;
  *n_coords = na;
  return 0;
}

static void print_number(double v) {
  if (isnan(v)) fputs("nan", stdout);
  else printf("%.12g", v);
}

/* Times as a comma list wrapped to about 78 columns. */
static void print_times(const double *t, int n) {
  int col = printf("times (%d step%s):", n, n == 1 ? "" : "s");
  for (int i = 0; i < n; ++i) {
    char num[32];
    int len = snprintf(num, sizeof num, "%.10g%s", t[i], i + 1 < n ? "," : "");
    if (col + 1 + len > 78) col = printf("\n ");
    col += printf(" %s", num);
  }
  printf("\n");
}

static int list_file(const char *path) {
  sl_diag d;
  sl_output_mesh m;
  sl_output_contents c;
  int rc = sl_output_read_mesh(path, &m, &d);
  if (rc) return sl_cli_error(rc, "sample: %s", d.msg);
  rc = sl_output_read_contents(path, &c, &d);
  if (rc) {
    sl_output_mesh_free(&m);
    return sl_cli_error(rc, "sample: %s", d.msg);
  }
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int32_t v = 0; v < m.n_vertices; ++v)
    for (int k = 0; k < 3; ++k) {
      double x = m.coords[3 * (size_t)v + k];
      lo[k] = fmin(lo[k], x), hi[k] = fmax(hi[k], x);
    }
  printf("%s: %d-D mesh, %d nodes, %d cells (%s)", path, m.dim, (int)m.n_vertices, (int)m.n_cells, m.topology);
  for (int k = 0; k < m.dim && k < 3 && m.n_vertices > 0; ++k)
    printf("%s%c in [%.10g, %.10g]", k ? ", " : "; ", "xyz"[k], lo[k], hi[k]);
  printf("\n");
  int w = 5;
  for (int i = 0; i < c.n_fields; ++i) w = (int)strlen(c.fields[i].name) > w ? (int)strlen(c.fields[i].name) : w;
  printf("fields:%s\n", c.n_fields ? "" : " (none)");
  for (int i = 0; i < c.n_fields; ++i) {
    const sl_output_field_info *f = &c.fields[i];
    char kind[32];
    if (f->components == 1) snprintf(kind, sizeof kind, "scalar");
    else if (f->components == 3) snprintf(kind, sizeof kind, "vector");
    else snprintf(kind, sizeof kind, "%d components", f->components);
    printf("  %-*s  %s  %-6s  ", w, f->name, f->centring == SL_CENTRE_NODE ? "node" : "cell", kind);
    if (f->n_steps == 1) printf("1 step, t = %.10g\n", f->t_first);
    else printf("%d steps, t = %.10g .. %.10g\n", f->n_steps, f->t_first, f->t_last);
  }
  print_times(c.times, c.n_steps);
  sl_output_scalars sc;
  if (sl_output_read_scalars(path, &sc, &d) == 0) {
    int col = printf("scalars (%d; --scalars prints them):", sc.n_names);
    if (sc.n_names == 0) printf(" none");
    for (int i = 0; i < sc.n_names; ++i) {
      char item[300];
      int len = snprintf(item, sizeof item, "%s%s%s%s%s", sc.names[i], sc.units[i][0] ? " [" : "", sc.units[i],
                         sc.units[i][0] ? "]" : "", i + 1 < sc.n_names ? "," : "");
      if (col + 1 + len > 78) col = printf("\n ");
      col += printf(" %s", item);
    }
    printf("\n");
    sl_output_scalars_free(&sc);
  }
  sl_output_contents_free(&c);
  sl_output_mesh_free(&m);
  if (fflush(stdout) != 0 || ferror(stdout)) return sl_cli_error(SL_EFAILED, "sample: cannot write the listing");
  return 0;
}

static int print_scalars(const char *path) {
  sl_diag d;
  sl_output_scalars s;
  int rc = sl_output_read_scalars(path, &s, &d);
  if (rc) return sl_cli_error(rc, "sample: %s", d.msg);
  if (s.n_names == 0) fprintf(stderr, "sluice: sample: %s holds no scalars (only the output times)\n", path);
  fputs("time [s]", stdout);
  for (int c = 0; c < s.n_names; ++c) {
    printf(",%s", s.names[c]);
    if (s.units[c][0]) printf(" [%s]", s.units[c]);
  }
  putchar('\n');
  for (int i = 0; i < s.n_times; ++i) {
    printf("%.17g", s.times[i]);
    for (int c = 0; c < s.n_names; ++c) {
      putchar(',');
      double v = s.values[(size_t)i * s.n_names + c];
      if (isnan(v)) fputs("nan", stdout);
      else printf("%.17g", v);
    }
    putchar('\n');
  }
  sl_output_scalars_free(&s);
  if (fflush(stdout) != 0 || ferror(stdout)) return sl_cli_error(SL_EFAILED, "sample: cannot write the scalars");
  return 0;
}

int sl_cmd_sample(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(sample_usage);
    return 0;
  }
  const char *path = NULL, *field = NULL, *time_arg = NULL, *line_arg = NULL, *n_arg = NULL, *point_arg = NULL;
  int list = 0, scalars = 0;
  for (int i = 0; i < argc; ++i) {
    const char *a = argv[i];
    const char **slot = strcmp(a, "--field") == 0   ? &field
                        : strcmp(a, "--time") == 0  ? &time_arg
                        : strcmp(a, "--line") == 0  ? &line_arg
                        : strcmp(a, "--n") == 0     ? &n_arg
                        : strcmp(a, "--point") == 0 ? &point_arg
                                                    : NULL;
    if (slot && i + 1 < argc) {
      if (*slot) return sl_cli_error(SL_EBADINPUT, "sample: %s given twice", a);
      *slot = argv[++i];
    } else if (strcmp(a, "--list") == 0) {
      list = 1;
    } else if (strcmp(a, "--scalars") == 0) {
      scalars = 1;
    } else if (a[0] == '-' && a[1] != '\0') {
      return sl_cli_error(SL_EBADINPUT, "sample: unknown option or missing value '%s' (sluice sample --help)", a);
    } else if (!path) {
      path = a;
    } else {
      return sl_cli_error(SL_EBADINPUT, "sample: one file at a time ('%s' and '%s')", path, a);
    }
  }
  if (!path) return sl_cli_error(SL_EBADINPUT, "sample: which output file?\n%s", sample_usage);
  if (list) return list_file(path);
  if (scalars) return print_scalars(path);
  if (!field) return sl_cli_error(SL_EBADINPUT, "sample: which field? (--field F; --list shows them)");
  if (!line_arg == !point_arg)
    return sl_cli_error(SL_EBADINPUT, "sample: give either --line x0,y0:x1,y1 or --point x,y (sluice sample --help)");
  if (n_arg && !line_arg) return sl_cli_error(SL_EBADINPUT, "sample: --n goes with --line");

  double t = INFINITY; /* the last output */
  if (time_arg && sl_parse_real(time_arg, &t))
    return sl_cli_error(SL_EBADINPUT, "sample: --time '%s' is not a number", time_arg);
  long n = line_arg ? DEFAULT_N : 1;
  if (n_arg && (sl_parse_long(n_arg, &n) || n < 1 || n > MAX_N))
    return sl_cli_error(SL_EBADINPUT, "sample: --n '%s': expected a whole number from 1 to %d", n_arg, MAX_N);
  double a[2], b[2];
  int n_coords = 0;
  if (line_arg && parse_line(line_arg, a, b, &n_coords))
    return sl_cli_error(SL_EBADINPUT, "sample: --line '%s': expected x0,y0:x1,y1 (2-D) or x0:x1 (1-D)", line_arg);
  if (point_arg && parse_point(point_arg, a, &n_coords))
    return sl_cli_error(SL_EBADINPUT, "sample: --point '%s': expected x,y (2-D) or x (1-D)", point_arg);
  if (point_arg) b[0] = a[0], b[1] = a[1];

  double *xy = malloc(2 * (size_t)n * sizeof *xy), *s = malloc((size_t)n * sizeof *s);
  if (!xy || !s) {
    free(xy), free(s);
    return sl_cli_error(SL_EFAILED, "sample: out of memory for %ld points", n);
  }
  double len = hypot(b[0] - a[0], b[1] - a[1]);
  for (long i = 0; i < n; ++i) {
    double f = n > 1 ? (double)i / (double)(n - 1) : 0.0;
    int last = n > 1 && i == n - 1; /* the end exactly as given */
    xy[2 * i] = last ? b[0] : a[0] + f * (b[0] - a[0]);
    xy[2 * i + 1] = last ? b[1] : a[1] + f * (b[1] - a[1]);
    s[i] = last ? len : f * len;
  }
  sl_diag d;
  sl_sample smp;
  int rc = sl_sample_points(path, field, t, (int)n, xy, &smp, &d);
  if (rc) {
    rc = sl_cli_error(rc, "sample: %s", d.msg);
  } else if (smp.dim != n_coords) {
    const char *want =
        smp.dim == 1 ? (line_arg ? "--line x0:x1" : "--point x") : (line_arg ? "--line x0,y0:x1,y1" : "--point x,y");
    rc = sl_cli_error(SL_EBADINPUT, "sample: %s has a %d-D mesh: give %s", path, smp.dim, want);
  } else {
    if (time_arg && fabs(smp.time - t) > 1e-9 * fmax(1.0, fabs(t)))
      fprintf(stderr, "sluice: sample: no output at t = %.10g; sampled the nearest, t = %.10g (step %d)\n", t, smp.time,
              smp.step);
    if (smp.n_outside > 0) {
      long first = 0;
      while (!isnan(smp.values[first * smp.components])) ++first;
      char where[80];
      if (smp.dim == 2) snprintf(where, sizeof where, "(%.10g, %.10g)", xy[2 * first], xy[2 * first + 1]);
      else snprintf(where, sizeof where, "x = %.10g", xy[2 * first]);
      fprintf(stderr, "sluice: warning: %d of %ld point%s outside the mesh (the first at %s); %s nan\n", smp.n_outside,
              n, n == 1 ? " lies" : "s lie", where, smp.n_outside == 1 ? "its value is" : "their values are");
    }
    fputs(smp.dim == 2 ? "x,y,s" : "x,s", stdout);
    for (int k = 0; k < smp.components; ++k) {
      if (smp.components == 1) printf(",%s", field);
      else printf(",%s_%d", field, k);
    }
    putchar('\n');
    for (long i = 0; i < n; ++i) {
      print_number(xy[2 * i]);
      if (smp.dim == 2) {
        putchar(',');
        print_number(xy[2 * i + 1]);
      }
      putchar(',');
      print_number(s[i]);
      for (int k = 0; k < smp.components; ++k) {
        putchar(',');
        print_number(smp.values[i * smp.components + k]);
      }
      putchar('\n');
    }
    if (fflush(stdout) != 0 || ferror(stdout)) rc = sl_cli_error(SL_EFAILED, "sample: cannot write the output");
  }
  sl_sample_free(&smp);
  free(xy), free(s);
  return rc;
}
