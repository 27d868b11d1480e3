/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The travelling wave of configs/rotating_waves.ini (Nigam 1999, section 4.4) from a run's output:
 *
 *   bench_rotating_waves_plot OUT.h5 [--svg PLOT.svg|.png] [--every T]
 *
 * reads the scalars stream_function_min and stream_function_phase ([output] stream_function_stats = true) and
 * draws, through core/study/chart.h, two panels: max|psi| / max|psi|_0 against t beside the geostrophic decay
 * reference exp(-t (E/sqrt|eps|)^(1/2)) = exp(-0.0316 t) of the thesis (eqs 4.194-4.196; a scaling, not a fit),
 * and the angle the pattern has turned (the phase of its first azimuthal mode, unwrapped) against c t, the
 * inviscid wave's (4.191: psi depends on theta - c t, c = 0.0324). It prints the same as a table every T (10).
 * Sluice's psi is the thesis's with the opposite sign (u = psi_y here), so max|psi| is -stream_function_min. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/io/output.h"
#include "core/study/chart.h"

#define WAVE_C 0.0324     /* the wave's angular speed (Nigam 1999, section 4.4, mode m = n = 1) */
#define DECAY_RATE 0.0316 /* (E/sqrt|eps|)^(1/2) with E = 1e-5, eps = 1e-4 (4.194-4.196) */

static int column(const sl_output_scalars *s, const char *name) {
  for (int k = 0; k < s->n_names; ++k)
    if (strcmp(s->names[k], name) == 0) return k;
  return -1;
}

int main(int argc, char **argv) {
  const char *out = NULL, *svg = NULL;
  double every = 10.0;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--svg") == 0 && i + 1 < argc) svg = argv[++i];
    else if (strcmp(argv[i], "--every") == 0 && i + 1 < argc) every = atof(argv[++i]);
    else if (argv[i][0] != '-' && !out) out = argv[i];
    else return fprintf(stderr, "usage: %s OUT.h5 [--svg PLOT.svg|.png] [--every T]\n", argv[0]), 2;
  }
  if (!out || !(every > 0.0))
    return fprintf(stderr, "usage: %s OUT.h5 [--svg PLOT.svg|.png] [--every T > 0]\n", argv[0]), 2;
  sl_diag d = {{0}};
  sl_output_scalars s = {0};
  if (sl_output_read_scalars(out, &s, &d)) return fprintf(stderr, "%s\n", d.msg), 2;
  int cmin = column(&s, "stream_function_min"), cph = column(&s, "stream_function_phase");
  if (cmin < 0 || cph < 0) {
    fprintf(stderr, "%s: no stream_function_min/_phase scalars (run with [output] stream_function_stats = true)\n",
            out);
    sl_output_scalars_free(&s);
    return 2;
  }
  int n = 0, rc = 0;
  double *t = malloc(4 * (size_t)s.n_times * sizeof *t), *amp = t + s.n_times, *turned = amp + s.n_times,
         *ct = turned + s.n_times;
  double tr[2], ref[2];
  if (!t) return fprintf(stderr, "out of memory\n"), 1;
  double a0 = NAN, prev = 0.0, unwrap = 0.0;
  for (int k = 0; k < s.n_times; ++k) {
    double a = -s.values[(size_t)k * s.n_names + cmin], p = s.values[(size_t)k * s.n_names + cph];
    if (!isfinite(a) || !isfinite(p)) continue;
    if (n == 0) a0 = a, prev = p;
    unwrap += remainder(p - prev, 2 * M_PI), prev = p;
    t[n] = s.times[k], amp[n] = a / a0, turned[n] = unwrap, ct[n] = WAVE_C * s.times[k];
    ++n;
  }
  if (n < 2) {
    fprintf(stderr, "%s: fewer than two output times with the stream function's scalars\n", out);
    free(t), sl_output_scalars_free(&s);
    return 2;
  }
  printf("t, max|psi|/max|psi|_0, exp(-%.4f t), turned (rad, unwrapped), c t, turned/(c t) - 1\n", DECAY_RATE);
  double next = 0.0;
  for (int k = 0; k < n; ++k) {
    if (t[k] + 1e-9 < next && k != n - 1) continue;
    printf("%7.2f  %.4f  %.4f  %+.5f  %.5f", t[k], amp[k], exp(-DECAY_RATE * t[k]), turned[k], ct[k]);
    if (t[k] > 0) printf("  %+.2f %%", 100 * (turned[k] / ct[k] - 1));
    printf("\n");
    while (next <= t[k] + 1e-9) next += every;
  }
  if (svg) {
    /* the reference curve on 101 points over the run */
    enum { NR = 101 };
    double rx[NR], ry[NR];
    for (int k = 0; k < NR; ++k) rx[k] = t[0] + (t[n - 1] - t[0]) * k / (NR - 1), ry[k] = exp(-DECAY_RATE * rx[k]);
    tr[0] = t[0], tr[1] = t[n - 1], ref[0] = WAVE_C * t[0], ref[1] = WAVE_C * t[n - 1];
    int every_mark = n > 40 ? n / 20 : 1;
    sl_chart_series sa[2] = {{.name = "sluice", .n = n, .x = t, .y = amp, .marker = SL_CHART_MARK_NONE},
                             {.name = "exp(\xE2\x88\x92"
                                      "0.0316 t) (Nigam 4.196)",
                              .n = NR,
                              .x = rx,
                              .y = ry,
                              .dashed = 1,
                              .marker = SL_CHART_MARK_NONE}};
    sl_chart_series sp[2] = {
        {.name = "sluice (m = 1 mode)",
         .n = n,
         .x = t,
         .y = turned,
         .marker_every = every_mark,
         .marker = SL_CHART_MARK_NONE},
        {.name = "c t, c = 0.0324", .n = 2, .x = tr, .y = ref, .dashed = 1, .marker = SL_CHART_MARK_NONE}};
    sl_chart panels[2] = {{.title = "amplitude",
                           .xlabel = "t (time unit 1/(|\xCE\xB5|^{1/2} Omega))",
                           .ylabel = "max|\xCF\x88| / max|\xCF\x88|_{0}",
                           .n_series = 2,
                           .series = sa},
                          {.title = "rotation relative to the container",
                           .xlabel = "t (time unit 1/(|\xCE\xB5|^{1/2} Omega))",
                           .ylabel = "angle turned (rad)",
                           .n_series = 2,
                           .series = sp}};
    char note[512];
    snprintf(note, sizeof note, "bench_rotating_waves_plot %s", out);
    sl_figure fig = {.title = "Travelling wave in a rotating cylinder (configs/rotating_waves.ini)",
                     .note = note,
                     .n_panels = 2,
                     .panels = panels,
                     .columns = 2,
                     .panel_width = 480,
                     .panel_height = 360};
    if (sl_figure_write(svg, &fig, &d)) fprintf(stderr, "%s\n", d.msg), rc = 1;
    else printf("wrote %s\n", svg);
  }
  free(t);
  sl_output_scalars_free(&s);
  return rc;
}
