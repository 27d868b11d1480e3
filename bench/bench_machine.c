/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "bench_machine.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void bench_machine_describe(char *buf, size_t len) {
  char model[256] = "unknown CPU", line[512];
  FILE *f = fopen("/proc/cpuinfo", "r");
  if (f) {
    while (fgets(line, sizeof line, f))
      if (!strncmp(line, "model name", 10)) {
        const char *c = strchr(line, ':');
        if (c) {
          snprintf(model, sizeof model, "%s", c + 1 + (c[1] == ' '));
          model[strcspn(model, "\n")] = 0;
        }
        break;
      }
    fclose(f);
  }
  double load = NAN;
  f = fopen("/proc/loadavg", "r");
  if (f) {
    if (fscanf(f, "%lf", &load) != 1) load = NAN;
    fclose(f);
  }
  snprintf(buf, len, "%s, %ld cores, load %.2f at start", model, sysconf(_SC_NPROCESSORS_ONLN), load);
}
