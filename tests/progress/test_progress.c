/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The run summary (a fixed example verbatim, percentages adding up to
 * 100 over random splits, one line, truncation) and the progress line (off
 * when not a terminal, SLUICE_PROGRESS, at most 10 redraws per second on a
 * fake clock, the time-left estimate, clearing), and the clocks. */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/cli/progress.h"
#include "testing.h"

/* ---- summary ------------------------------------------------------------- */

/* Sum of the "(N %)" figures of a summary line; -1 when there are none. */
static int percent_sum(const char *s) {
  int sum = -1, v, n;
  for (const char *p = s; (p = strchr(p, '(')) != NULL; ++p)
    if (sscanf(p, "(%d %%)%n", &v, &n) == 1 && n > 0) sum = (sum < 0 ? 0 : sum) + v;
  return sum;
}

static void test_summary(void) {
  char buf[512];
  sl_run_summary s = {.steps = 120,
                      .rejected_steps = 3,
                      .nonlinear_iterations = 410,
                      .nonlinear_name = "Newton",
                      .wall_seconds = 12.5,
                      .cpu_seconds = 12.3,
                      .assembly = 1.2,
                      .factorisation = 8.1,
                      .solve = 1.9,
                      .output = 0.6,
                      .step_limit = "error estimate"};
  sl_run_summary_format(&s, buf, sizeof buf);
  CHECK_MSG(strcmp(buf,
                   "sluice: 120 steps (3 rejected), 410 Newton iterations; CPU 12.3 s, wall 12.5 s (wall: "
                   "assembly 1.2 s (9 %), factorisation 8.1 s (65 %), solve 1.9 s (15 %), output 0.6 s (5 %), "
                   "other 0.7 s (6 %)); step limited by error estimate") == 0,
            "got: %s", buf);
  printf("%s\n", buf);

  /* Random splits, also with parts adding up to more than the total. */
  unsigned r = 7u;
  int bad = 0, lines = 0;
  for (int k = 0; k < 2000; ++k) {
    double v[5];
    for (int i = 0; i < 5; ++i) {
      r = r * 1103515245u + 12345u;
      v[i] = ((r >> 8) & 0xffff) / 6553.5 * (i == 1 ? 10.0 : 1.0);
    }
    sl_run_summary t = {.steps = k,
                        .wall_seconds = v[0],
                        .assembly = v[1],
                        .factorisation = k % 3 ? v[2] : 0.0,
                        .solve = v[3],
                        .output = k % 5 ? v[4] : 0.0};
    sl_run_summary_format(&t, buf, sizeof buf);
    bad += percent_sum(buf) != 100;
    lines += strchr(buf, '\n') != NULL;
  }
  CHECK_MSG(bad == 0, "%d of 2000 summaries whose percentages do not add up to 100", bad);
  CHECK(lines == 0);

  /* Nothing timed: no split, no percentages; defaults for the names. */
  sl_run_summary z = {.steps = 1, .nonlinear_iterations = 1};
  sl_run_summary_format(&z, buf, sizeof buf);
  CHECK_MSG(strcmp(buf, "sluice: 1 step (0 rejected), 1 nonlinear iteration; CPU 0.0 s, wall 0.0 s") == 0, "got: %s",
            buf);

  /* Caller strings cannot break the line. */
  sl_run_summary c = {.steps = 2, .wall_seconds = 1.0, .solve = 1.0, .step_limit = "CFL\nlimit\r"};
  sl_run_summary_format(&c, buf, sizeof buf);
  CHECK(strchr(buf, '\n') == NULL && strchr(buf, '\r') == NULL);
  CHECK_CONTAINS(buf, "solve 1.0 s (100 %), output 0.0 s (0 %), other 0.0 s (0 %)); step limited by CFL limit ");

  /* Truncated, always terminated. */
  char full[512], small[40];
  sl_run_summary_format(&s, full, sizeof full);
  memset(small, 'x', sizeof small);
  sl_run_summary_format(&s, small, sizeof small);
  CHECK(strlen(small) == sizeof small - 1 && strncmp(small, full, sizeof small - 1) == 0);
  char one[1] = {'x'};
  sl_run_summary_format(&s, one, 1);
  CHECK(one[0] == '\0');
}

/* ---- progress line ------------------------------------------------------- */

static double fake_now;
static double fake_clock(void) { return fake_now; }

/* What was written to f so far (malloc'ed). */
static char *contents(FILE *f) {
  CHECK(fflush(f) == 0);
  long n = ftell(f);
  char *s = malloc((size_t)(n > 0 ? n : 0) + 1);
  if (!s) return NULL;
  rewind(f);
  size_t got = n > 0 ? fread(s, 1, (size_t)n, f) : 0;
  s[got] = '\0';
  CHECK(fseek(f, 0, SEEK_END) == 0);
  return s;
}

static int count_char(const char *s, char c) {
  int n = 0;
  for (; s && *s; ++s) n += *s == c;
  return n;
}

static void test_progress_off(void) {
  FILE *f = tmpfile();
  CHECK(f != NULL);
  if (!f) return;
  sl_progress p;
  /* a file is no terminal: a log line every interval, each ending in a newline, none before the first interval */
  CHECK(unsetenv("SLUICE_PROGRESS") == 0);
  CHECK(setenv("SLUICE_PROGRESS_EVERY", "5", 1) == 0);
  sl_progress_begin(&p, f, 0.0, 1.0);
  CHECK(p.enabled == 1 && p.lines == 1 && p.interval == 5.0);
  p.now = fake_clock;
  const double at[6] = {0.0, 1.0, 4.9, 5.0, 7.0, 10.5};
  for (int k = 0; k < 6; ++k) fake_now = at[k], sl_progress_update(&p, 0.1 * (k + 1), 0.1, k + 1, 2);
  sl_progress_end(&p);
  char log[1024] = "";
  rewind(f);
  size_t got = fread(log, 1, sizeof log - 1, f);
  log[got] = '\0';
  CHECK_MSG(count_char(log, '\n') == 2 && count_char(log, '\r') == 0, "log: %s", log);
  CHECK_CONTAINS(log, "sluice: t = 0.4 of 1 s (40.0 %), step 4, dt 0.1 s, 2 iterations; 5 s spent, ");
  CHECK_CONTAINS(log, "sluice: t = 0.6 of 1 s (60.0 %), step 6, dt 0.1 s, 2 iterations; 11 s spent, ");
  CHECK(unsetenv("SLUICE_PROGRESS_EVERY") == 0);
  f = freopen(NULL, "w+", f);
  CHECK(f != NULL);
  if (!f) return;
  CHECK(setenv("SLUICE_PROGRESS", "0", 1) == 0);
  sl_progress_begin(&p, f, 0.0, 1.0);
  CHECK(p.enabled == 0);
  sl_progress_begin(&p, NULL, 0.0, 1.0);
  CHECK(p.enabled == 0);
  fclose(f);

  /* a terminal: on by default, SLUICE_PROGRESS=0 turns it off */
  int m = posix_openpt(O_RDWR | O_NOCTTY);
  if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) {
    printf("skipped: no pseudo-terminal here, the terminal cases are not run\n");
    if (m >= 0) close(m);
    return;
  }
  const char *name = ptsname(m);
  int sfd = name ? open(name, O_RDWR | O_NOCTTY) : -1;
  FILE *tty = sfd >= 0 ? fdopen(sfd, "w") : NULL;
  CHECK(tty != NULL);
  if (tty) {
    CHECK(unsetenv("SLUICE_PROGRESS") == 0);
    sl_progress_begin(&p, tty, 0.0, 1.0);
    CHECK(p.enabled == 1);
    sl_progress_update(&p, 0.5, 0.1, 5, 2);
    CHECK(p.width > 0);
    sl_progress_end(&p);
    CHECK(setenv("SLUICE_PROGRESS", "0", 1) == 0);
    sl_progress_begin(&p, tty, 0.0, 1.0);
    CHECK(p.enabled == 0);
    fclose(tty);
  } else if (sfd >= 0) {
    close(sfd);
  }
  close(m);
}

static void test_progress_on(void) {
  FILE *f = tmpfile();
  CHECK(f != NULL);
  if (!f) return;
  sl_progress p;
  CHECK(setenv("SLUICE_PROGRESS", "1", 1) == 0);
  sl_progress_begin(&p, f, 0.0, 100.0);
  CHECK(p.enabled == 1);
  p.now = fake_clock;

  fake_now = 10.0;
  sl_progress_update(&p, 1.0, 1.0, 1, 3); /* drawn, no rate yet */
  fake_now = 10.05;
  sl_progress_update(&p, 2.0, 1.0, 2, 3); /* too soon after the last */
  fake_now = 10.6;
  sl_progress_update(&p, 7.0, 5.0, 3, 4); /* 6 s simulated in 0.6 s: 10 per s, 93 s left */
  char *s = contents(f);
  CHECK(s && count_char(s, '\r') == 2 && count_char(s, '\n') == 0);
  if (s) {
    CHECK_CONTAINS(s, "\rt 1 / 100 s (1.0 %)  dt 1 s  step 1  iter 3  left --");
    CHECK_CONTAINS(s, "\rt 7 / 100 s (7.0 %)  dt 5 s  step 3  iter 4  left 9 s");
  }
  free(s);

  /* 1000 steps in 2 s: at most 10 redraws per second */
  long before = ftell(f);
  for (int k = 1; k <= 1000; ++k) {
    fake_now = 10.6 + 0.002 * k;
    sl_progress_update(&p, 7.0 + 0.01 * k, 0.01, 3 + k, 1);
  }
  s = contents(f);
  int draws = s ? count_char(s + before, '\r') : -1;
  CHECK_MSG(draws >= 19 && draws <= 21, "%d redraws in 2 s", draws);
  /* The rate moves towards the slower steps' 5 per s (0.01 per 2 ms) with
   * a time constant of 5 s: four samples of 0.5 s leave 5 + 5 e^-0.4. */
  CHECK_MSG(fabs(p.rate - (5.0 + 5.0 * exp(-0.4))) < 0.05, "rate %g", p.rate);
  if (s) CHECK_CONTAINS(s, "\rt 16.67 / 100 s (16.7 %)  dt 0.01 s  step 970  iter 1  left 10 s");
  free(s);

  /* A shorter line blanks the rest of the longer one; end clears the line. */
  fake_now = 20.0;
  sl_progress_update(&p, 99.0, 1e-3, 5000, 12);
  before = ftell(f);
  fake_now = 21.0;
  sl_progress_update(&p, 99.5, 1.0, 5, 1);
  s = contents(f);
  if (s) {
    const char *last = strrchr(s, '\r'), *prev = last;
    while (prev > s && *--prev != '\r') {
    }
    const char *end = last; /* the previous line's text, without its padding */
    while (end > prev && end[-1] == ' ') --end;
    CHECK(strlen(last) >= (size_t)(end - prev) && strlen(last) < (size_t)(end - prev) + 2);
    CHECK(last[strlen(last) - 1] == ' ');
  }
  free(s);
  sl_progress_end(&p);
  s = contents(f);
  if (s) {
    size_t n = strlen(s);
    CHECK(n > 2 && s[n - 1] == '\r');
  }
  free(s);
  CHECK(p.enabled == 0);
  before = ftell(f);
  fake_now = 30.0;
  sl_progress_update(&p, 100.0, 1.0, 6, 1); /* after end: nothing */
  CHECK(ftell(f) == before);

  /* No end time: no fraction, no estimate. */
  sl_progress_begin(&p, f, 0.0, 0.0);
  p.now = fake_clock;
  before = ftell(f);
  sl_progress_update(&p, 3.0, 0.5, 6, 2);
  s = contents(f);
  if (s) CHECK(strcmp(s + before, "\rt 3 s  dt 0.5 s  step 6  iter 2") == 0);
  free(s);
  fclose(f);
  CHECK(unsetenv("SLUICE_PROGRESS") == 0);
}

static void test_clocks(void) {
  double w0 = sl_wall_seconds(), c0 = sl_cpu_seconds();
  volatile double x = 0.0;
  for (long i = 0; i < 20000000; ++i) x += 1e-9 * (double)i;
  double w1 = sl_wall_seconds(), c1 = sl_cpu_seconds();
  CHECK(isfinite(w0) && isfinite(c0) && w1 >= w0 && c1 > c0);
  printf("busy loop: wall %.3f s, CPU %.3f s\n", w1 - w0, c1 - c0);
}

int main(void) {
  test_summary();
  test_progress_off();
  test_progress_on();
  test_clocks();
  return sl_test_summary();
}
