/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The cavity's reference centreline profile (centreline_profile.h). */
#include "centreline_profile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int centreline_profile_read(const char *path, centreline_profile *p) {
  FILE *f = fopen(path, "r");
  if (!f) return fprintf(stderr, "%s: %s\n", path, strerror(errno)), -1;
  char line[1024];
  int cy = -1, cu = -1, header = 0, bad = 0;
  p->n = 0;
  while (!bad && fgets(line, sizeof line, f)) {
    if (line[0] == '#' || line[0] == '\n') continue;
    int k = 0;
    double vy = NAN, vu = NAN;
    for (char *tok = strtok(line, ",\n"); tok; tok = strtok(NULL, ",\n"), ++k) {
      if (!header) {
        if (!strcmp(tok, "y")) cy = k;
        if (!strcmp(tok, "velocity_0")) cu = k;
      } else if (k == cy) vy = strtod(tok, NULL);
      else if (k == cu) vu = strtod(tok, NULL);
    }
    if (!header) {
      header = 1;
      bad = cy < 0 || cu < 0;
      continue;
    }
    bad = p->n == CENTRELINE_MAX_POINTS || !isfinite(vy) || !isfinite(vu) || (p->n && !(vy > p->y[p->n - 1]));
    if (!bad) p->y[p->n] = vy, p->u[p->n++] = vu;
  }
  fclose(f);
  if (bad || !header || p->n < 2) {
    fprintf(stderr, "%s: not a profile (columns y, velocity_0; 2 to %d rows, y ascending)\n", path,
            CENTRELINE_MAX_POINTS);
    return -1;
  }
  return 0;
}

int centreline_profile_error(const centreline_profile *ref, const double *u, double *emax, double *el2) {
  double m = 0.0, q = 0.0, dprev = 0.0;
  for (int k = 0; k < ref->n; ++k) {
    double d = u[k] - ref->u[k];
    if (!isfinite(d)) {
      *emax = *el2 = NAN;
      return -1;
    }
    m = fmax(m, fabs(d));
    if (k) q += 0.5 * (ref->y[k] - ref->y[k - 1]) * (d * d + dprev * dprev);
    dprev = d;
  }
  *emax = m, *el2 = sqrt(q);
  return 0;
}
