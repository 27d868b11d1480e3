/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The figure of a study (see report.h): built from the table, drawn by
 * chart.c as SVG or PNG. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/study/chart.h"
#include "core/study/label.h"
#include "core/study/report.h"

static const char *norm_text(sl_study_norm n) { return n == SL_NORM_L1 ? "L_{1}" : n == SL_NORM_L2 ? "L_{2}" : "max"; }

static int failed_runs(const sl_bench_table *t) {
  int n = 0;
  for (int i = 0; i < t->n_rows; ++i) n += !t->rows[i].measured;
  return n;
}

/* The measured quantity in words with its symbol and unit. */
static void quantity_text(const sl_study *s, char *buf, size_t n) {
  const sl_study_measure *sm = &s->m;
  if (sm->label) {
    sl_plot_pretty(sm->label, buf, n);
    return;
  }
  char q[300];
  sl_plot_quantity(sm->name, sm->component, q, sizeof q);
  if (sm->reduce == SL_REDUCE_NONE) {
    snprintf(buf, n, "%s", q);
    return;
  }
  const char *m = sm->reduce == SL_REDUCE_MIN ? "minimum" : "maximum";
  if (!sm->has_line) snprintf(buf, n, "%s of %s", m, q);
  else if (sm->line_dim == 1) snprintf(buf, n, "%s of %s on %g < x < %g", m, q, sm->line[0], sm->line[2]);
  else
    snprintf(buf, n, "%s of %s on (%g, %g)\xE2\x80\x93(%g, %g)", m, q, sm->line[0], sm->line[1], sm->line[2],
             sm->line[3]);
}

/* The axis title of the first points key: known keys in words with units. */
static void point_key_text(const sl_study *s, char *buf, size_t n, int *is_cells) {
  const char *key = s->points[0].key;
  *is_cells = !strcmp(key, "cells") || !strcmp(key, "nx") || !strcmp(key, "n");
  int pair = strchr(s->points[0].values[0], ',') != NULL;
  if (*is_cells) snprintf(buf, n, pair ? "cells per side" : "cells");
  else if (!strcmp(key, "dt")) snprintf(buf, n, "time step \xCE\x94t (s)");
  else if (!strcmp(key, "bulk_velocity")) snprintf(buf, n, "bulk velocity (m/s)");
  else {
    char words[200];
    snprintf(words, sizeof words, "%s", key);
    for (char *p = words; *p; ++p)
      if (*p == '_') *p = ' ';
    sl_plot_pretty(words, buf, n);
  }
}

typedef struct build {
  sl_chart panels[2];
  sl_chart_series *series;
  double *xs, *ys;
  char (*names)[300];
  const char **labels;
  char (*label_text)[64];
  int max_n, n_series;
} build;

static void build_free(build *b) {
  free(b->series), free(b->xs), free(b->ys), free(b->names), free(b->labels), free(b->label_text);
}

int sl_bench_write_plot(const sl_bench_table *t, const char *path, sl_diag *d) {
  const sl_study *s = t->study;
  int nv = s->n_variants, np = s->n_points, comparison = s->m.against == SL_AGAINST_NONE;
  int profile = 0, max_n = 2 * np; /* room for the breaks of a sweep that turns back */
  for (int i = 0; i < t->n_rows; ++i)
    if (t->rows[i].measured && t->rows[i].m.is_profile)
      profile = 1, max_n = t->rows[i].m.n > max_n ? t->rows[i].m.n : max_n;
  int all_x = s->n_point_keys > 0 && np > 1;
  for (int p = 0; p < np; ++p) all_x &= isfinite(s->point_x[p]) && s->point_x[p] > 0.0;
  build b = {.max_n = max_n};
  b.n_series = comparison && profile ? t->n_rows : 2 * nv; /* error studies: two panels of nv */
  b.series = calloc((size_t)b.n_series, sizeof *b.series);
  b.xs = calloc((size_t)b.n_series * (size_t)max_n, sizeof *b.xs);
  b.ys = calloc((size_t)b.n_series * (size_t)max_n, sizeof *b.ys);
  b.names = calloc((size_t)b.n_series, sizeof *b.names);
  b.labels = calloc((size_t)nv * (size_t)np, sizeof *b.labels);
  b.label_text = calloc((size_t)np, sizeof *b.label_text);
  if (!b.series || !b.xs || !b.ys || !b.names || !b.labels || !b.label_text) {
    build_free(&b);
    return sl_diag_set(d, SL_ENOMEM, "%s: out of memory", path);
  }
  char quantity[400], title[600], subtitle[1600], raw_sub[1600], xlabel[2][400], ylabel[2][800], note[600], sym[64];
  quantity_text(s, quantity, sizeof quantity);
  sl_plot_symbol(s->m.name, s->m.component, sym, sizeof sym);
  sl_bench_describe_measure(t, raw_sub, sizeof raw_sub);
  if (t->exact[0]) { /* the exact solution's parameters on a second line */
    size_t used = strlen(raw_sub);
    snprintf(raw_sub + used, sizeof raw_sub - used, "\n%s", t->exact);
  }
  /* the measure in words: the quantity's internal name ("velocity[2]") and the norm's as the axes give them */
  char internal[400];
  sl_bench_quantity_label(s, internal, sizeof internal);
  char *at = internal[0] && !s->m.label ? strstr(raw_sub, internal) : NULL;
  if (at) {
    char rest[1600];
    snprintf(rest, sizeof rest, "%s", at + strlen(internal));
    snprintf(at, sizeof raw_sub - (size_t)(at - raw_sub), "%s%s", quantity, rest);
  }
  for (int k = 1; k <= 2; ++k) { /* "L1 error" as L_{1} */
    char word[8], *w;
    snprintf(word, sizeof word, "L%d ", k);
    if ((w = strstr(raw_sub, word)) && (w == raw_sub || w[-1] == ' ') && strlen(raw_sub) + 3 < sizeof raw_sub) {
      memmove(w + 5, w + 2, strlen(w + 2) + 1);
      w[1] = '_', w[2] = '{', w[3] = (char)('0' + k), w[4] = '}';
    }
  }
  sl_plot_pretty(raw_sub, subtitle, sizeof subtitle);
  sl_plot_pretty(s->title ? s->title : s->name, title, sizeof title);
  for (int i = 0; i < b.n_series && i < nv; ++i) sl_plot_pretty(s->variant_names[i], b.names[i], sizeof b.names[i]);
  int n_panels = 1;
  if (!comparison) {
    const char *unit = s->m.label ? "" : sl_plot_unit(s->m.name);
    char err[700];
    if (s->m.against == SL_AGAINST_VALUE)
      snprintf(err, sizeof err, "|%s %s %.10g|%s%s%s", s->m.label ? quantity : sym,
               s->m.value < 0 ? "+" : "\xE2\x88\x92", fabs(s->m.value), unit[0] ? " (" : "", unit, unit[0] ? ")" : "");
    else if (s->m.reduce != SL_REDUCE_NONE || (s->m.scalar && s->m.against != SL_AGAINST_REFERENCE))
      snprintf(err, sizeof err, "error in the %s", quantity);
    else snprintf(err, sizeof err, "%s error in %s", norm_text(s->m.norm), quantity);
    int is_cells = 0;
    if (all_x) point_key_text(s, xlabel[0], sizeof xlabel[0], &is_cells);
    for (int p = 0; p < np; ++p) sl_plot_pretty(s->points[0].values[p], b.label_text[p], sizeof b.label_text[p]);
    /* panel 0 (when the points are numbers): error against them, the observed order over the last three;
     * then error against CPU time */
    int first = all_x ? 0 : 1;
    for (int q = first; q < 2; ++q) {
      sl_chart *c = &b.panels[q - first];
      sl_chart_series *sr = b.series + q * nv;
      *c = (sl_chart){.xscale = SL_AXIS_LOG,
                      .yscale = SL_AXIS_LOG,
                      .n_series = nv,
                      .series = sr,
                      .xlabel = q ? "CPU time of the run (s)" : xlabel[0],
                      .ylabel = ylabel[q]};
      snprintf(ylabel[q], sizeof ylabel[q], "%s", err);
      c->title = q ? "work against precision" : "convergence";
      for (int v = 0; v < nv; ++v) {
        double *x = b.xs + (size_t)(q * nv + v) * max_n, *y = b.ys + (size_t)(q * nv + v) * max_n;
        for (int p = 0; p < np; ++p) {
          const sl_bench_row *r = &t->rows[v * np + p];
          x[p] = q ? (r->measured ? r->run.cpu : NAN) : s->point_x[p];
          y[p] = r->measured ? r->error : NAN;
          b.labels[v * np + p] = q && s->n_point_keys && v == 0 ? b.label_text[p] : NULL; /* one curve labelled */
        }
        sr[v] = (sl_chart_series){.name = b.names[v], .n = np, .x = x, .y = y, .labels = q ? b.labels + v * np : NULL};
        if (!q && nv <= 4 && np >= 3) { /* the observed order over the last three points */
          sr[v].slope_points = 3;
          sr[v].slope_format = is_cells ? "order %.2f" : "slope %.2f";
          sr[v].slope_negate = is_cells;
        }
      }
    }
    n_panels = 2 - first;
  } else if (profile) {
    sl_chart *c = &b.panels[0];
    *c = (sl_chart){.xscale = SL_AXIS_LINEAR,
                    .yscale = SL_AXIS_LINEAR,
                    .n_series = t->n_rows,
                    .series = b.series,
                    .xlabel = xlabel[0],
                    .ylabel = ylabel[0]};
    const sl_bench_row *first = NULL;
    for (int i = 0; i < t->n_rows && !first; ++i)
      if (t->rows[i].measured) first = &t->rows[i];
    const double *l = first ? first->m.line : NULL;
    if (s->m.scalar) snprintf(xlabel[0], sizeof xlabel[0], "time t (s)");
    else if (!l) snprintf(xlabel[0], sizeof xlabel[0], "distance along the line (m)");
    else if (l[1] == 0.0 && l[3] == 0.0 && l[2] > l[0])
      snprintf(xlabel[0], sizeof xlabel[0], "x \xE2\x88\x92 %g (m)", l[0]);
    else if (l[0] == l[2] && l[3] > l[1])
      snprintf(xlabel[0], sizeof xlabel[0], "y \xE2\x88\x92 %g (m), along x = %g m", l[1], l[0]);
    else if (l[1] == l[3] && l[2] > l[0])
      snprintf(xlabel[0], sizeof xlabel[0], "x \xE2\x88\x92 %g (m), along y = %g m", l[0], l[1]);
    else snprintf(xlabel[0], sizeof xlabel[0], "distance from (%g, %g) towards (%g, %g) (m)", l[0], l[1], l[2], l[3]);
    snprintf(ylabel[0], sizeof ylabel[0], "%s", quantity);
    for (int i = 0; i < t->n_rows; ++i) {
      const sl_bench_row *r = &t->rows[i];
      int n = r->measured ? r->m.n : 0;
      for (int k = 0; k < n; ++k) b.xs[(size_t)i * max_n + k] = r->m.s[k], b.ys[(size_t)i * max_n + k] = r->m.v[k];
      char raw[300];
      if (np > 1) snprintf(raw, sizeof raw, "%s; %s", s->variant_names[r->variant], s->point_names[r->point]);
      else snprintf(raw, sizeof raw, "%s", s->variant_names[r->variant]);
      sl_plot_pretty(raw, b.names[i], sizeof b.names[i]);
      /* about 20 markers a curve, staggered between curves so that they do not hide each other */
      int every = n > 30 ? n / 20 : 1;
      b.series[i] = (sl_chart_series){.name = b.names[i],
                                      .n = n,
                                      .x = b.xs + (size_t)i * max_n,
                                      .y = b.ys + (size_t)i * max_n,
                                      .marker_every = every,
                                      .marker_offset = every * i / (t->n_rows > 0 ? t->n_rows : 1)};
    }
  } else {
    sl_chart *c = &b.panels[0];
    *c = (sl_chart){.xscale = SL_AXIS_LINEAR,
                    .yscale = SL_AXIS_LINEAR,
                    .n_series = nv,
                    .series = b.series,
                    .xlabel = xlabel[0],
                    .ylabel = ylabel[0]};
    int is_cells;
    if (all_x) point_key_text(s, xlabel[0], sizeof xlabel[0], &is_cells);
    else snprintf(xlabel[0], sizeof xlabel[0], "point");
    snprintf(ylabel[0], sizeof ylabel[0], "%s", quantity);
    for (int v = 0; v < nv; ++v) {
      /* points in sweeps (tables): the line breaks where x turns back, so
       * that only the points of one sweep are joined */
      double *x = b.xs + (size_t)v * max_n, *y = b.ys + (size_t)v * max_n;
      int m = 0, dir = 0;
      for (int p = 0; p < np; ++p) {
        const sl_bench_row *r = &t->rows[v * np + p];
        double xp = all_x ? s->point_x[p] : p;
        if (m > 0 && isfinite(x[m - 1])) {
          int d_now = xp > x[m - 1] ? 1 : xp < x[m - 1] ? -1 : 0;
          if (dir && d_now && d_now != dir) x[m] = y[m] = NAN, ++m, d_now = 0;
          dir = d_now;
        }
        x[m] = xp, y[m] = r->measured ? r->m.scalar : NAN, ++m;
      }
      b.series[v] = (sl_chart_series){.name = b.names[v], .n = m, .x = x, .y = y};
    }
  }
  int failed = failed_runs(t);
  if (failed)
    snprintf(note, sizeof note, "sluice bench %s: %d of %d runs not plotted (failed or not measured; see %s.csv)",
             s->path, failed, t->n_rows, s->name);
  else snprintf(note, sizeof note, "sluice bench %s: %d runs, each in its own process", s->path, t->n_rows);
  sl_figure f = {.title = title,
                 .subtitle = subtitle,
                 .note = note,
                 .n_panels = n_panels,
                 .panels = b.panels,
                 .columns = n_panels,
                 .panel_width = n_panels > 1 ? 560 : 960,
                 .panel_height = n_panels > 1 ? 440 : 520};
  if (n_panels == 1) b.panels[0].title = NULL;
  int rc = sl_figure_write(path, &f, d);
  build_free(&b);
  return rc;
}
