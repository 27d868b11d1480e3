/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Robustness of the Gmsh reader: thousands of deterministic mutations of
 * the checked-in files (lines dropped, doubled or swapped, bytes changed,
 * the file cut short) must each either read into a valid mesh or fail with
 * SL_EBADINPUT and a "file:line" message; never crash or leak (the ASan
 * build runs this too). */
#include <stdint.h>

#include "mesh_checks.h"

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static unsigned next_rand(void) { /* xorshift64*, fixed seed: reproducible */
  rng ^= rng >> 12;
  rng ^= rng << 25;
  rng ^= rng >> 27;
  return (unsigned)((rng * 0x2545f4914f6cdd1dull) >> 33);
}

static char *slurp(const char *file, size_t *len) {
  char path[1024];
  const char *src = getenv("SLUICE_SOURCE_DIR");
  if (src) snprintf(path, sizeof path, "%s/tests/mesh/data/%s", src, file);
  else snprintf(path, sizeof path, "%s/%s", SLUICE_MESH_DATA, file);
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  char *buf = malloc(1 << 16);
  *len = buf ? fread(buf, 1, (1 << 16) - 1, f) : 0;
  fclose(f);
  return buf;
}

/* Byte offsets of line starts. */
static int line_starts(const char *t, size_t len, size_t *starts, int cap) {
  int n = 0;
  for (size_t i = 0; i < len && n < cap; ++i)
    if (i == 0 || t[i - 1] == '\n') starts[n++] = i;
  return n;
}

static void mutate(const char *t, size_t len, char *out, size_t *olen) {
  size_t st[512];
  int nl = line_starts(t, len, st, 512);
  int kind = (int)(next_rand() % 5);
  int a = (int)(next_rand() % (unsigned)nl);
  size_t a0 = st[a], a1 = a + 1 < nl ? st[a + 1] : len;
  size_t k = 0;
  switch (kind) {
    case 0: /* drop a line */
      memcpy(out, t, a0);
      memcpy(out + a0, t + a1, len - a1);
      k = len - (a1 - a0);
      break;
    case 1: /* double a line */
      memcpy(out, t, a1);
      memcpy(out + a1, t + a0, a1 - a0);
      memcpy(out + a1 + (a1 - a0), t + a1, len - a1);
      k = len + (a1 - a0);
      break;
    case 2: { /* change a byte to a digit, a sign, a space or a letter */
      static const char pool[] = "0123456789-. \n$xE";
      memcpy(out, t, len);
      out[next_rand() % len] = pool[next_rand() % (sizeof pool - 1)];
      k = len;
      break;
    }
    case 3: /* cut the file short */
      k = next_rand() % len;
      memcpy(out, t, k);
      break;
    default: { /* swap two lines */
      int b = (int)(next_rand() % (unsigned)nl);
      if (b < a) {
        int s = a;
        a = b;
        b = s;
      }
      size_t x0 = st[a], x1 = a + 1 < nl ? st[a + 1] : len, y0 = st[b], y1 = b + 1 < nl ? st[b + 1] : len;
      if (a == b || x1 > y0) {
        memcpy(out, t, len);
        k = len;
        break;
      }
      memcpy(out, t, x0);
      k = x0;
      memcpy(out + k, t + y0, y1 - y0), k += y1 - y0;
      memcpy(out + k, t + x1, y0 - x1), k += y0 - x1;
      memcpy(out + k, t + x0, x1 - x0), k += x1 - x0;
      memcpy(out + k, t + y1, len - y1), k += len - y1;
    }
  }
  *olen = k;
}

int main(void) {
  const char *files[] = {"box_tri_22.msh", "box_tri_41.msh", "box_quad_22.msh", "box_quad_41.msh",   "line_22.msh",
                         "line_41.msh",    "box_cw_41.msh",  "ring_p2_41.msh",  "ring_p2_41_bin.msh"};
  static char out[1 << 17];
  for (size_t f = 0; f < sizeof files / sizeof *files; ++f) {
    size_t len = 0;
    char *t = slurp(files[f], &len);
    CHECK_MSG(t && len > 0, "cannot read %s", files[f]);
    if (!t || !len) {
      free(t);
      continue;
    }
    int ok = 0, refused = 0, bad = 0, invalid = 0;
    for (int i = 0; i < 1500; ++i) {
      size_t olen;
      mutate(t, len, out, &olen);
      sl_mesh *m;
      sl_diag d;
      d.msg[0] = '\0';
      int rc = sl_mesh_read_gmsh_string(out, olen, "m.msh", &m, &d);
      if (rc == 0) {
        ++ok;
        if (sl_mesh_check(m, &d) != 0) ++invalid;
        sl_mesh_destroy(m);
      } else if (rc == SL_EBADINPUT && m == NULL && strncmp(d.msg, "m.msh", 5) == 0) {
        ++refused;
      } else {
        ++bad;
        fprintf(stderr, "%s mutation %d: rc %d, message \"%s\"\n", files[f], i, rc, d.msg);
      }
    }
    CHECK(bad == 0);
    CHECK(invalid == 0);
    CHECK(refused > 0);
    printf("%s: %d read, %d refused\n", files[f], ok, refused);
    free(t);
  }
  return sl_test_summary();
}
