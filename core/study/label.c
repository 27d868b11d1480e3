/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Plot words (see label.h). */
#include "core/study/label.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct known {
  const char *field, *words, *symbol, *unit;
  int vector;
} known;

static const known fields[] = {
    {"phi", "solids volume fraction", "\xCF\x86", "", 0},
    {"alpha", "volume fraction", "\xCE\xB1", "", 0},
    {"porosity", "porosity", "\xCE\xB5", "", 0},
    {"velocity", "velocity", "u", "m/s", 1},
    {"solids_velocity", "solids velocity", "u_{s}", "m/s", 1},
    {"fluid_velocity", "fluid velocity", "u_{f}", "m/s", 1},
    {"pressure", "pressure", "p", "Pa", 0},
    {"p", "pressure", "p", "Pa", 0},
    {"psi", "stream function", "\xCF\x88", "m\xC2\xB2/s", 0},
    {"stream_function", "stream function", "\xCF\x88", "m\xC2\xB2/s", 0},
    {"temperature", "temperature", "T", "K", 0},
    {"excess_pore_pressure", "excess pore pressure", "u_{e}", "Pa", 0},
    {"height", "height", "h", "m", 0},
};

static const known *lookup(const char *field) {
  for (size_t k = 0; field && k < sizeof fields / sizeof fields[0]; ++k)
    if (!strcmp(fields[k].field, field)) return &fields[k];
  return NULL;
}

static const char *axis_name(int component) { return component == 0 ? "x" : component == 1 ? "y" : "z"; }

void sl_plot_symbol(const char *field, int component, char *buf, size_t n) {
  const known *k = lookup(field);
  if (!k) {
    if (component >= 0) snprintf(buf, n, "%s[%d]", field ? field : "?", component);
    else snprintf(buf, n, "%s", field ? field : "?");
    return;
  }
  if (k->vector && component >= 0) {
    size_t len = strlen(k->symbol);
    if (len > 2 && k->symbol[len - 1] == '}') /* "u_{s}": "u_{s,x}" */
      snprintf(buf, n, "%.*s,%s}", (int)(len - 1), k->symbol, axis_name(component));
    else snprintf(buf, n, "%s_{%s}", k->symbol, axis_name(component));
  } else snprintf(buf, n, "%s", k->symbol);
}

const char *sl_plot_unit(const char *field) {
  const known *k = lookup(field);
  return k ? k->unit : "";
}

void sl_plot_quantity(const char *field, int component, char *buf, size_t n) {
  const known *k = lookup(field);
  if (!k) {
    sl_plot_symbol(field, component, buf, n);
    return;
  }
  char sym[64];
  sl_plot_symbol(field, component, sym, sizeof sym);
  if (k->unit[0]) snprintf(buf, n, "%s %s (%s)", k->words, sym, k->unit);
  else snprintf(buf, n, "%s %s", k->words, sym);
}

static const struct {
  const char *word, *greek;
} greek[] = {{"phi", "\xCF\x86"}, {"eps", "\xCE\xB5"}, {"mu", "\xCE\xBC"},
             {"rho", "\xCF\x81"}, {"tau", "\xCF\x84"}, {"nu", "\xCE\xBD"}};

/* A number in e-notation at s (digits, optional point, e, sign, digits), its length or 0. */
static size_t e_number(const char *s, double *v, int *e, char *mant, size_t mn) {
  size_t i = 0, digits = 0;
  while (isdigit((unsigned char)s[i])) ++i, ++digits;
  if (s[i] == '.') {
    ++i;
    while (isdigit((unsigned char)s[i])) ++i, ++digits;
  }
  if (!digits || (s[i] != 'e' && s[i] != 'E')) return 0;
  size_t m = i++;
  if (s[i] == '+' || s[i] == '-') ++i;
  if (!isdigit((unsigned char)s[i])) return 0;
  while (isdigit((unsigned char)s[i])) ++i;
  if (isalnum((unsigned char)s[i]) || s[i] == '_') return 0;
  *v = strtod(s, NULL);
  *e = atoi(s + m + 1);
  snprintf(mant, mn, "%.*s", (int)m, s);
  return i;
}

void sl_plot_pretty(const char *in, char *out, size_t n) {
  if (!n) return;
  size_t o = 0;
  out[0] = '\0';
#define PUT(...)                                                      \
  do {                                                                \
    if (o < n) {                                                      \
      int k_ = snprintf(out + o, n - o, __VA_ARGS__);                 \
      o = k_ < 0 ? o : (o + (size_t)k_ < n ? o + (size_t)k_ : n - 1); \
    }                                                                 \
  } while (0)
  for (size_t i = 0; in && in[i];) {
    int word_start = i == 0 || !(isalnum((unsigned char)in[i - 1]) || in[i - 1] == '_' || in[i - 1] == '.');
    if (word_start && isdigit((unsigned char)in[i])) {
      double v;
      int e;
      char mant[32];
      size_t len = e_number(in + i, &v, &e, mant, sizeof mant);
      if (len) {
        double m = strtod(mant, NULL);
        if (m == 1.0) PUT("10^{%d}", e);
        else
          PUT("%s\xC3\x97"
              "10^{%d}",
              mant, e);
        i += len;
        continue;
      }
    }
    int done = 0;
    for (size_t g = 0; word_start && g < sizeof greek / sizeof greek[0] && !done; ++g) {
      size_t wl = strlen(greek[g].word);
      if (strncmp(in + i, greek[g].word, wl)) continue;
      const char *after = in + i + wl;
      size_t sub = 0;
      if (*after == '_') { /* phi_max */
        while (isalnum((unsigned char)after[1 + sub])) ++sub;
        if (!sub || after[1 + sub] == '_') continue;
        PUT("%s_{%.*s}", greek[g].greek, (int)sub, after + 1);
        i += wl + 1 + sub, done = 1;
      } else if (isdigit((unsigned char)*after)) { /* phi0 */
        while (isdigit((unsigned char)after[sub])) ++sub;
        if (isalpha((unsigned char)after[sub])) continue;
        PUT("%s_{%.*s}", greek[g].greek, (int)sub, after);
        i += wl + sub, done = 1;
      } else if (!isalnum((unsigned char)*after) && *after != '_' && *after != '.' && *after != '[') {
        PUT("%s", greek[g].greek);
        i += wl, done = 1;
      }
    }
    if (done) continue;
    PUT("%c", in[i]);
    ++i;
  }
#undef PUT
}
