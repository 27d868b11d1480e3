/* SPDX-License-Identifier: MIT */
/* A program that runs a sluice scene through the embedding API: the Stokes
 * cavity with its mesh and output set from here, reporting its progress and
 * what the run did. Build against an installed sluice:
 *   cc embed.c $(pkg-config --cflags --libs sluice) -o embed
 * Usage: embed SCENE.ini OUT.h5 [section.key=value]... */
#include <stdio.h>

#include "sluice/sluice.h"

static void progress(void *user, double t, double dt, long step, int iterations) {
  long *steps = user;
  *steps = step;
  (void)t, (void)dt, (void)iterations;
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: embed SCENE.ini OUT.h5 [section.key=value]...\n");
    return 2;
  }
  sluice *s = NULL;
  sluice_error e;
  sluice_open_opts oo = {.sets = (const char *const *)argv + 3};
  int rc = sluice_open(argv[1], &oo, &s, &e);
  if (!rc) rc = sluice_check(s, NULL, &e);
  long steps = 0;
  sluice_summary sum;
  sluice_run_opts ro = {.output = argv[2], .progress = progress, .progress_user = &steps};
  if (!rc) rc = sluice_run(s, &ro, &sum, &e);
  if (rc) {
    fprintf(stderr, "embed: %s\n", e.msg);
  } else {
    printf("model %s: %ld steps (%ld seen by the progress callback), %ld rejected; %s\n", sluice_model(s), sum.steps,
           steps, sum.rejected_steps, sum.stop_reason);
    printf("output %s: %ld output times\n", sum.output_path, sum.output_times);
  }
  sluice_close(s);
  return rc;
}
