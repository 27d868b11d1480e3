/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A study's table and CSV (see report.h; the plots: bench_plot.c). */
#include "core/study/report.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int sl_bench_table_init(sl_bench_table *t, const sl_study *s) {
  memset(t, 0, sizeof *t);
  t->study = s;
  t->n_rows = s->n_variants * s->n_points;
  t->rows = calloc((size_t)t->n_rows, sizeof *t->rows);
  if (!t->rows) return -1;
  for (int v = 0; v < s->n_variants; ++v)
    for (int p = 0; p < s->n_points; ++p) {
      sl_bench_row *r = sl_bench_table_row(t, v, p);
      r->variant = v, r->point = p, r->error = r->order = NAN;
      r->run.status = SL_RUN_NOT_RUN;
      r->run.cpu = r->run.wall = r->run.peak_rss_mb = NAN;
    }
  return 0;
}

void sl_bench_table_free(sl_bench_table *t) {
  for (int i = 0; i < t->n_rows; ++i) sl_bench_measured_free(&t->rows[i].m);
  free(t->rows);
  t->rows = NULL, t->n_rows = 0;
}

sl_bench_row *sl_bench_table_row(sl_bench_table *t, int variant, int point) {
  return &t->rows[variant * t->study->n_points + point];
}

void sl_bench_errors(sl_bench_table *t) {
  const sl_study *s = t->study;
  const sl_study_measure *sm = &s->m;
  for (int v = 0; v < s->n_variants; ++v) {
    const sl_bench_row *fin = sl_bench_table_row(t, v, s->n_points - 1);
    for (int p = 0; p < s->n_points; ++p) {
      sl_bench_row *r = sl_bench_table_row(t, v, p);
      r->error = r->order = NAN;
      if (!r->measured) continue;
      const sl_bench_measured *m = &r->m;
      switch (sm->against) {
        case SL_AGAINST_EXACT:
        case SL_AGAINST_REFERENCE:
          if (m->is_profile && m->ref) r->error = sl_bench_norm(sm->norm, m->n, m->w, m->v, m->ref);
          break;
        case SL_AGAINST_VALUE:
          r->error = fabs(m->scalar - sm->value);
          break;
        case SL_AGAINST_FINEST:
          if (!fin->measured) break;
          if (!m->is_profile) r->error = fabs(m->scalar - fin->m.scalar);
          else if (fin->m.n == m->n) r->error = sl_bench_norm(sm->norm, m->n, m->w, m->v, fin->m.v);
          break;
        case SL_AGAINST_NONE:
          break;
      }
    }
    for (int p = 1; p < s->n_points; ++p) {
      sl_bench_row *r = sl_bench_table_row(t, v, p);
      const sl_bench_row *q = sl_bench_table_row(t, v, p - 1);
      double x = s->point_x[p], xq = s->point_x[p - 1];
      if (r->error > 0 && q->error > 0 && x > 0 && xq > 0 && x != xq)
        r->order = log(q->error / r->error) / fabs(log(x / xq));
    }
  }
}

/* ---- words ------------------------------------------------------------------ */

static const char *norm_name(sl_study_norm n) { return n == SL_NORM_L1 ? "L1" : n == SL_NORM_L2 ? "L2" : "max"; }

static void line_text(const sl_study_measure *sm, char *buf, size_t len) {
  if (!sm->has_line) snprintf(buf, len, "the whole mesh");
  else if (sm->line_dim == 1) snprintf(buf, len, "%g:%g", sm->line[0], sm->line[2]);
  else snprintf(buf, len, "%g,%g:%g,%g", sm->line[0], sm->line[1], sm->line[2], sm->line[3]);
}

void sl_bench_quantity_label(const sl_study *s, char *buf, size_t len) {
  const sl_study_measure *sm = &s->m;
  if (sm->label) {
    snprintf(buf, len, "%s", sm->label);
    return;
  }
  char name[300], where[128];
  if (!sm->scalar && sm->against != SL_AGAINST_EXACT && sm->component > 0)
    snprintf(name, sizeof name, "%s[%d]", sm->name, sm->component);
  else if (sm->against == SL_AGAINST_EXACT && sm->component > 0)
    snprintf(name, sizeof name, "%s[%d]", sm->name, sm->component);
  else snprintf(name, sizeof name, "%s", sm->name);
  line_text(sm, where, sizeof where);
  if (sm->reduce != SL_REDUCE_NONE)
    snprintf(buf, len, "%s %s along %s", sm->reduce == SL_REDUCE_MIN ? "min" : "max", name, where);
  else snprintf(buf, len, "%s", name);
}

void sl_bench_describe_measure(const sl_bench_table *t, char *buf, size_t len) {
  const sl_study *s = t->study;
  const sl_study_measure *sm = &s->m;
  char q[400], when[64] = "", where[128];
  sl_bench_quantity_label(s, q, sizeof q);
  line_text(sm, where, sizeof where);
  if (sm->has_time) snprintf(when, sizeof when, " at t = %g", sm->time);
  else if (!(sm->scalar && sm->against == SL_AGAINST_REFERENCE)) snprintf(when, sizeof when, " at the last output");
  int one_number = sm->scalar ? sm->against != SL_AGAINST_REFERENCE : sm->reduce != SL_REDUCE_NONE;
  int exact_kynch = sm->against == SL_AGAINST_EXACT && !strcmp(sm->exact, "kynch");
  int exact_bed = sm->against == SL_AGAINST_EXACT && !strcmp(sm->exact, "fluidized_bed");
  const char *over = exact_kynch  ? "cell averages, whole column"
                     : exact_bed  ? "cells of the bed below its top"
                     : sm->scalar ? "over the reference's times"
                                  : where;
  char profile[1024];
  if (one_number) snprintf(profile, sizeof profile, "%s%s", q, when);
  else snprintf(profile, sizeof profile, "%s error of %s (%s)%s", norm_name(sm->norm), q, over, when);
  switch (sm->against) {
    case SL_AGAINST_EXACT:
      snprintf(buf, len, "%s against the exact solution (%s)", profile, sm->exact);
      break;
    case SL_AGAINST_REFERENCE:
      snprintf(buf, len, "%s against %s", profile, sm->reference);
      break;
    case SL_AGAINST_VALUE:
      snprintf(buf, len, "|%s - (%.10g)|", profile, sm->value);
      break;
    case SL_AGAINST_FINEST:
      snprintf(buf, len, "%s against the finest run of each variant", profile);
      break;
    case SL_AGAINST_NONE:
      if (one_number) snprintf(buf, len, "%s, compared", profile);
      else snprintf(buf, len, "%s along %s%s, compared", q, where, when);
      break;
  }
}

/* ---- CSV ------------------------------------------------------------------ */

/* A CSV field: quoted when it holds a comma, a quote or a line break. */
static void csv_text(FILE *f, const char *s) {
  if (!strpbrk(s, ",\"\n\r")) {
    fputs(s, f);
    return;
  }
  fputc('"', f);
  for (; *s; ++s) {
    if (*s == '"') fputc('"', f);
    fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
  }
  fputc('"', f);
}

static void csv_number(FILE *f, double v, const char *fmt) {
  if (isfinite(v)) fprintf(f, fmt, v);
}

static FILE *open_out(const char *path, sl_diag *d) {
  FILE *f = fopen(path, "w");
  if (!f) sl_diag_set(d, SL_EFAILED, "%s: %s", path, strerror(errno));
  return f;
}

static int close_out(FILE *f, const char *path, sl_diag *d) {
  int bad = ferror(f);
  bad |= fclose(f) != 0;
  return bad ? sl_diag_set(d, SL_EFAILED, "%s: write failed", path) : 0;
}

int sl_bench_write_csv(const sl_bench_table *t, const char *path, sl_diag *d) {
  const sl_study *s = t->study;
  FILE *f = open_out(path, d);
  if (!f) return SL_EFAILED;
  fputs("variant", f);
  for (int k = 0; k < s->n_variant_keys; ++k) fprintf(f, ",%s.%s", s->variants[k].section, s->variants[k].key);
  fputs(",point", f);
  for (int k = 0; k < s->n_point_keys; ++k) fprintf(f, ",%s.%s", s->points[k].section, s->points[k].key);
  fputs(",status,exit_status,cpu_s,wall_s,peak_rss_mb,steps,rejected_steps,time,quantity,error,order,message\n", f);
  for (int i = 0; i < t->n_rows; ++i) {
    const sl_bench_row *r = &t->rows[i];
    csv_text(f, s->variant_names[r->variant]);
    for (int k = 0; k < s->n_variant_keys; ++k) fputc(',', f), csv_text(f, s->variants[k].values[r->variant]);
    fputc(',', f), csv_text(f, s->point_names[r->point]);
    for (int k = 0; k < s->n_point_keys; ++k) fputc(',', f), csv_text(f, s->points[k].values[r->point]);
    const char *status =
        r->run.status == SL_RUN_OK && !r->measured ? "measure_failed" : sl_bench_status_name(r->run.status);
    fprintf(f, ",%s,", status);
    if (r->run.status != SL_RUN_NOT_RUN) {
      if (r->run.signal_number) fprintf(f, "signal %d", r->run.signal_number);
      else fprintf(f, "%d", r->run.exit_code);
    }
    fputc(',', f), csv_number(f, r->run.cpu, "%.4g");
    fputc(',', f), csv_number(f, r->run.wall, "%.4g");
    fputc(',', f), csv_number(f, r->run.peak_rss_mb, "%.1f");
    fputc(',', f);
    if (r->run.status == SL_RUN_OK || r->run.status == SL_RUN_FAILED)
      fprintf(f, "%ld,%ld", r->run.steps, r->run.rejected_steps);
    else fputc(',', f);
    fputc(',', f);
    if (r->measured) csv_number(f, r->m.time, "%.10g");
    fputc(',', f);
    if (r->measured && !r->m.is_profile) csv_number(f, r->m.scalar, "%.12g");
    fputc(',', f), csv_number(f, r->error, "%.6e");
    fputc(',', f), csv_number(f, r->order, "%.3f");
    fputc(',', f), csv_text(f, r->run.message);
    fputc('\n', f);
  }
  return close_out(f, path, d);
}

int sl_bench_write_compare_csv(const sl_bench_table *t, const char *path, sl_diag *d) {
  const sl_study *s = t->study;
  FILE *f = open_out(path, d);
  if (!f) return SL_EFAILED;
  char name[600];
  int profile = 0;
  const sl_bench_row *first = NULL;
  for (int i = 0; i < t->n_rows && !first; ++i)
    if (t->rows[i].measured) first = &t->rows[i], profile = first->m.is_profile;
  if (profile) {
    fputs(s->m.scalar ? "t" : "s", f);
    for (int i = 0; i < t->n_rows; ++i) {
      const sl_bench_row *r = &t->rows[i];
      if (s->n_points > 1)
        snprintf(name, sizeof name, "%s; %s", s->variant_names[r->variant], s->point_names[r->point]);
      else snprintf(name, sizeof name, "%s", s->variant_names[r->variant]);
      fputc(',', f), csv_text(f, name);
    }
    fputc('\n', f);
    for (int k = 0; k < first->m.n; ++k) {
      fprintf(f, "%.10g", first->m.s[k]);
      for (int i = 0; i < t->n_rows; ++i) {
        const sl_bench_row *r = &t->rows[i];
        fputc(',', f);
        if (r->measured && r->m.n == first->m.n && r->m.s[k] == first->m.s[k]) fprintf(f, "%.10g", r->m.v[k]);
      }
      fputc('\n', f);
    }
  } else {
    fputs("point", f);
    for (int k = 0; k < s->n_point_keys; ++k) fprintf(f, ",%s.%s", s->points[k].section, s->points[k].key);
    for (int v = 0; v < s->n_variants; ++v) fputc(',', f), csv_text(f, s->variant_names[v]);
    fputc('\n', f);
    for (int p = 0; p < s->n_points; ++p) {
      csv_text(f, s->point_names[p]);
      for (int k = 0; k < s->n_point_keys; ++k) fputc(',', f), csv_text(f, s->points[k].values[p]);
      for (int v = 0; v < s->n_variants; ++v) {
        const sl_bench_row *r = &t->rows[v * s->n_points + p];
        fputc(',', f);
        if (r->measured) fprintf(f, "%.12g", r->m.scalar);
      }
      fputc('\n', f);
    }
  }
  return close_out(f, path, d);
}
