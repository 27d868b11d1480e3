/* SPDX-License-Identifier: GPL-2.0-or-later */
/* In-house INI parser (see ini.h for the syntax).
 *
 * Design notes:
 * - The input is checked line by line before it is parsed: lines over 64 KiB,
 *   NUL bytes, control characters and invalid UTF-8 are refused with their
 *   position, so the rest of the parser only ever sees valid text.
 * - Columns count UTF-8 characters (1-based), as editors show them.
 * - `include = other.ini` is only allowed before the first section header. The
 *   included file is parsed into the same configuration first, so the keys of
 *   the including file that follow replace the included ones. Two includes in
 *   one file: the later one wins where they overlap.
 * - Duplicate keys and repeated section headers are errors only within one
 *   file; overriding across files is the point of includes.
 * - Allocation failures return SL_EFAILED ("out of memory"); every other
 *   failure is bad input (SL_EBADINPUT). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif

#include "core/config/ini.h"

#include "core/config/expr.h"
#include "core/config/parameters.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

enum {
  INI_MAX_LINE = 65536,            /* bytes per line (64 KiB), without the newline */
  INI_MAX_DEPTH = 16,              /* nested includes */
  INI_MAX_PARSES = 256,            /* files read for one configuration (bounds diamond includes) */
  INI_MAX_FILE = 16 * 1024 * 1024, /* a scene is small; this also stops /proc-style endless files */
  INI_MAX_OVERRIDE = 16384         /* keeps a written override line under INI_MAX_LINE */
};

static const char CMDLINE_FILE[] = "<command line>";

/* ---------------------------------------------------------------- helpers */

static char *dup_range(const char *s, size_t n) {
  char *p = malloc(n + 1);
  if (!p) return NULL;
  if (n) memcpy(p, s, n);
  p[n] = '\0';
  return p;
}

/* Grows an array to hold `need` elements; the old block stays valid on failure. */
static void *grow_array(void *p, int *cap, int need, size_t elem) {
  if (need <= *cap) return p;
  if (need > INT_MAX / 2) return NULL;
  int ncap = *cap > 0 ? *cap : 4;
  while (ncap < need) ncap *= 2;
  void *np = realloc(p, (size_t)ncap * elem);
  if (!np) return NULL;
  *cap = ncap;
  return np;
}

static int is_blank(char ch) { return ch == ' ' || ch == '\t'; }
static int is_comment(char ch) { return ch == ';' || ch == '#'; }
/* ASCII only on purpose: <ctype.h> depends on the locale. */
static int is_key_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
}
static int is_section_char(char ch) { return is_key_char(ch) || ch == '.'; }

/* 1-based column of p in the line starting at ls, counted in UTF-8 characters. */
static int col_at(const char *ls, const char *p) {
  int col = 1;
  for (; ls < p; ++ls)
    if (((unsigned char)*ls & 0xC0) != 0x80) ++col;
  return col;
}

/* Length of the valid UTF-8 sequence at s (n bytes available), 0 when invalid. */
static size_t utf8_len(const unsigned char *s, size_t n) {
  unsigned c = s[0];
  size_t len;
  unsigned long cp, min;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) {
    len = 2, cp = c & 0x1F, min = 0x80;
  } else if (c >= 0xE0 && c <= 0xEF) {
    len = 3, cp = c & 0x0F, min = 0x800;
  } else if (c >= 0xF0 && c <= 0xF4) {
    len = 4, cp = c & 0x07, min = 0x10000;
  } else {
    return 0;
  }
  if (n < len) return 0;
  for (size_t k = 1; k < len; ++k) {
    if ((s[k] & 0xC0) != 0x80) return 0;
    cp = cp << 6 | (s[k] & 0x3F);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0; /* overlong, surrogate */
  return len;
}

/* Offset of the first byte that is not acceptable text (NUL, control
 * character other than tab, invalid UTF-8), or n when all is well. */
static size_t check_text(const char *s, size_t n, char *why, size_t why_size) {
  const unsigned char *u = (const unsigned char *)s;
  size_t i = 0;
  while (i < n) {
    unsigned c = u[i];
    if (c == 0) {
      snprintf(why, why_size, "NUL byte: this looks like a binary file, not INI text");
      return i;
    }
    if ((c < 0x20 && c != '\t') || c == 0x7F) {
      snprintf(why, why_size, "control character 0x%02X is not allowed", c);
      return i;
    }
    size_t len = utf8_len(u + i, n - i);
    if (len == 0) {
      snprintf(why, why_size, "invalid UTF-8 byte 0x%02X (the file must be UTF-8 text)", c);
      return i;
    }
    i += len;
  }
  return n;
}

/* One (valid UTF-8) character at p for messages: "x", or an escape for tab. */
static const char *show_char(const char *p, char buf[8]) {
  if (*p == '\t') return "\\t";
  size_t len = utf8_len((const unsigned char *)p, 4);
  if (len == 0) len = 1;
  memcpy(buf, p, len);
  buf[len] = '\0';
  return buf;
}

/* Shortest "%g" form that reads back to the same double, with a compact
 * exponent ("1e6", "1e-12") as people write them in INI files. */
static const char *fmt_real(double v, char buf[40]) {
  if (isnan(v)) return "nan";
  if (isinf(v)) return v > 0 ? "inf" : "-inf";
  for (int prec = 1; prec <= 17; ++prec) {
    snprintf(buf, 40, "%.*g", prec, v);
    if (strtod(buf, NULL) == v) break;
  }
  char *e = strchr(buf, 'e');
  if (e) {
    char *src = e + 1, *dst = e + 1;
    if (*src == '+') ++src;
    else if (*src == '-') *dst++ = *src++;
    while (*src == '0' && src[1] != '\0') ++src;
    memmove(dst, src, strlen(src) + 1);
  }
  return buf;
}

/* "FILE:LINE:COL: error: MESSAGE"; line 0 (command line) gives "FILE: error: ...". */
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
static int
err_at(sl_diag *d, const char *file, int line, int col, const char *fmt, ...) {
  char msg[sizeof d->msg];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (line <= 0) return sl_diag_set(d, SL_EBADINPUT, "%s: error: %s", file, msg);
  if (col <= 0) return sl_diag_set(d, SL_EBADINPUT, "%s:%d: error: %s", file, line, msg);
  return sl_diag_set(d, SL_EBADINPUT, "%s:%d:%d: error: %s", file, line, col, msg);
}

static int oom(sl_diag *d) {
  return sl_diag_set(d, SL_ENOMEM, "error: out of memory while handling the configuration");
}

/* ------------------------------------------------------- configuration data */

/* The stored copy of a file name (added when new); NULL when out of memory. */
static const char *intern_file(sl_ini *ini, const char *name) {
  for (int i = 0; i < ini->n_files; ++i)
    if (strcmp(ini->files[i], name) == 0) return ini->files[i];
  char **nf = grow_array(ini->files, &ini->cap_files, ini->n_files + 1, sizeof *ini->files);
  if (!nf) return NULL;
  ini->files = nf;
  char *copy = dup_range(name, strlen(name));
  if (!copy) return NULL;
  ini->files[ini->n_files++] = copy;
  return copy;
}

static int find_section_n(const sl_ini *ini, const char *name, size_t n) {
  for (int i = 0; i < ini->n_sections; ++i) {
    const char *s = ini->sections[i].name;
    if (strncmp(s, name, n) == 0 && s[n] == '\0') return i;
  }
  return -1;
}

static int add_section(sl_ini *ini, const char *name, size_t n, const char *file, int line) {
  sl_ini_section *ns = grow_array(ini->sections, &ini->cap_sections, ini->n_sections + 1, sizeof *ns);
  if (!ns) return -1;
  ini->sections = ns;
  char *copy = dup_range(name, n);
  if (!copy) return -1;
  sl_ini_section *s = &ini->sections[ini->n_sections];
  memset(s, 0, sizeof *s);
  s->name = copy;
  s->file = file;
  s->line = line;
  return ini->n_sections++;
}

static int find_entry_n(const sl_ini_section *s, const char *key, size_t n) {
  for (int i = 0; i < s->n_entries; ++i)
    if (strncmp(s->entries[i].key, key, n) == 0 && s->entries[i].key[n] == '\0') return i;
  return -1;
}

/* Sets key = value (value is taken over, also on failure) in section s;
 * returns the entry index or -1 when out of memory. */
static int set_entry(sl_ini_section *s, const char *key, size_t klen, char *value, int quoted, const char *file,
                     int line, int col, int value_col) {
  int i = find_entry_n(s, key, klen);
  if (i < 0) {
    sl_ini_entry *ne = grow_array(s->entries, &s->cap_entries, s->n_entries + 1, sizeof *ne);
    if (!ne) {
      free(value);
      return -1;
    }
    s->entries = ne;
    char *kcopy = dup_range(key, klen);
    if (!kcopy) {
      free(value);
      return -1;
    }
    i = s->n_entries++;
    memset(&s->entries[i], 0, sizeof s->entries[i]);
    s->entries[i].key = kcopy;
  }
  sl_ini_entry *e = &s->entries[i];
  free(e->value);
  e->value = value;
  e->quoted = quoted;
  e->file = file;
  e->line = line;
  e->col = col;
  e->value_col = value_col;
  return i;
}

void sl_ini_free(sl_ini *ini) {
  if (!ini) return;
  for (int i = 0; i < ini->n_sections; ++i) {
    sl_ini_section *s = &ini->sections[i];
    for (int j = 0; j < s->n_entries; ++j) {
      free(s->entries[j].key);
      free(s->entries[j].value);
    }
    free(s->entries);
    free(s->name);
  }
  free(ini->sections);
  for (int i = 0; i < ini->n_files; ++i) free(ini->files[i]);
  free(ini->files);
  sl_ini_params_free(ini->params);
  free(ini);
}

const sl_ini_section *sl_ini_find_section(const sl_ini *ini, const char *section) {
  if (!ini || !section) return NULL;
  int i = find_section_n(ini, section, strlen(section));
  return i < 0 ? NULL : &ini->sections[i];
}

sl_ini_entry *sl_ini_find(const sl_ini *ini, const char *section, const char *key) {
  const sl_ini_section *s = sl_ini_find_section(ini, section);
  if (!s || !key) return NULL;
  int i = find_entry_n(s, key, strlen(key));
  return i < 0 ? NULL : &s->entries[i];
}

int sl_ini_entry_from_command_line(const sl_ini_entry *e) { return e && e->file && !strcmp(e->file, CMDLINE_FILE); }

void sl_ini_drop_entries(sl_ini *ini, const char *section, int (*keep)(const sl_ini_entry *, void *), void *ctx) {
  if (!ini || !section) return;
  int si = find_section_n(ini, section, strlen(section));
  if (si < 0) return;
  sl_ini_section *sec = &ini->sections[si];
  int kept = 0;
  for (int i = 0; i < sec->n_entries; ++i) {
    if (keep(&sec->entries[i], ctx)) {
      sec->entries[kept++] = sec->entries[i];
      continue;
    }
    free(sec->entries[i].key);
    free(sec->entries[i].value);
  }
  sec->n_entries = kept;
}

/* Why [s, s+n) is not a valid section name (NULL when it is); *bad is the offset to point at. */
static const char *bad_section_name(const char *s, size_t n, size_t *bad) {
  *bad = 0;
  if (n == 0) return "empty section name";
  for (size_t i = 0; i < n; ++i) {
    if (!is_section_char(s[i])) {
      *bad = i;
      return "invalid character in section name (allowed: letters, digits, '_', '.', '-')";
    }
  }
  for (size_t i = 0; i < n; ++i) {
    if (s[i] == '.' && (i == 0 || i + 1 == n || s[i + 1] == '.')) {
      *bad = i;
      return "empty part in dotted section name";
    }
  }
  return NULL;
}

/* ------------------------------------------------------------------ reading */

typedef struct {
  int has_id;
  dev_t dev;
  ino_t ino;
} file_id;

/* Reads a whole regular file. Returns 0, or an errno value (EISDIR etc.), or
 * EFBIG when larger than INI_MAX_FILE, ENOMEM when out of memory. */
static int read_file(const char *path, char **buf, size_t *len, file_id *id) {
  *buf = NULL;
  *len = 0;
  /* O_NONBLOCK: opening a FIFO must not hang; it is refused just below. */
  int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return errno ? errno : EIO;
  struct stat st;
  if (fstat(fd, &st) != 0) {
    int e = errno;
    close(fd);
    return e ? e : EIO;
  }
  if (!S_ISREG(st.st_mode)) {
    close(fd);
    return S_ISDIR(st.st_mode) ? EISDIR : EINVAL;
  }
  if (st.st_size > INI_MAX_FILE) {
    close(fd);
    return EFBIG;
  }
  size_t cap = (size_t)st.st_size + 1, n = 0;
  char *b = malloc(cap);
  if (!b) {
    close(fd);
    return ENOMEM;
  }
  for (;;) {
    if (n == cap) { /* the file grew or reports no size (/proc) */
      if (cap > INI_MAX_FILE) {
        free(b);
        close(fd);
        return EFBIG;
      }
      char *nb = realloc(b, cap * 2);
      if (!nb) {
        free(b);
        close(fd);
        return ENOMEM;
      }
      b = nb;
      cap *= 2;
    }
    ssize_t r = read(fd, b + n, cap - n);
    if (r < 0) {
      if (errno == EINTR) continue;
      int e = errno ? errno : EIO;
      free(b);
      close(fd);
      return e;
    }
    if (r == 0) break;
    n += (size_t)r;
  }
  close(fd);
  if (n > INI_MAX_FILE) {
    free(b);
    return EFBIG;
  }
  id->has_id = 1;
  id->dev = st.st_dev;
  id->ino = st.st_ino;
  *buf = b;
  *len = n;
  return 0;
}

static const char *read_error_text(int e) {
  if (e == EFBIG) return "file is larger than 16 MiB; a scene file should be small";
  if (e == EINVAL) return "not a regular file";
  return strerror(e);
}

/* ------------------------------------------------------------------ parsing */

typedef struct {
  const char *name; /* interned */
  file_id id;
} chain_link;

typedef struct {
  sl_ini *ini;
  sl_diag *d;
  chain_link chain[INI_MAX_DEPTH + 1]; /* files being parsed, root first */
  int depth;                           /* number of active includes */
  int n_parses;
} parse_ctx;

typedef struct {
  int index, line;
} mark;

/* Per-file state: what this file has opened and set, for duplicate checks. */
typedef struct {
  const char *file;
  int cur; /* current section index, -1 before the first header */
  int n_headers, n_includes;
  mark *opened; /* sections opened in this file */
  int n_opened, cap_opened;
  mark *set; /* entries set under the current header */
  int n_set, cap_set;
} file_state;

static int parse_text(parse_ctx *c, const char *text, size_t len, const char *file);

static int push_mark(mark **arr, int *n, int *cap, int index, int line) {
  mark *na = grow_array(*arr, cap, *n + 1, sizeof *na);
  if (!na) return -1;
  *arr = na;
  na[*n].index = index;
  na[*n].line = line;
  ++*n;
  return 0;
}

/* The value after '=' (p, blanks skipped) up to the end of line e. On success
 * *out is a malloc'ed string: unquoted and unescaped, comment stripped. */
static int parse_value(parse_ctx *c, const char *file, int lineno, const char *ls, const char *p, const char *e,
                       char **out, int *quoted) {
  char cb[8];
  *out = NULL;
  *quoted = 0;
  if (p < e && *p == '"') {
    char *buf = malloc((size_t)(e - p));
    if (!buf) return oom(c->d);
    size_t n = 0;
    const char *q = p + 1;
    for (;;) {
      if (q >= e) {
        free(buf);
        return err_at(c->d, file, lineno, col_at(ls, p), "unterminated quoted string (no closing '\"' on this line)");
      }
      if (*q == '"') break;
      if (*q == '\\') {
        if (q + 1 < e && (q[1] == '"' || q[1] == '\\')) {
          buf[n++] = q[1];
          q += 2;
          continue;
        }
        free(buf);
        if (q + 1 >= e)
          return err_at(c->d, file, lineno, col_at(ls, p), "unterminated quoted string (no closing '\"' on this line)");
        return err_at(c->d, file, lineno, col_at(ls, q),
                      "unknown escape '\\%s' in quoted string (only \\\" and \\\\ are allowed)", show_char(q + 1, cb));
      }
      buf[n++] = *q++;
    }
    buf[n] = '\0';
    ++q; /* closing quote */
    while (q < e && is_blank(*q)) ++q;
    if (q < e && !is_comment(*q)) {
      free(buf);
      return err_at(c->d, file, lineno, col_at(ls, q), "unexpected '%s' after the quoted string", show_char(q, cb));
    }
    *out = buf;
    *quoted = 1;
    return 0;
  }
  const char *v = p;
  while (v < e && !is_comment(*v)) {
    if (*v == '"')
      return err_at(c->d, file, lineno, col_at(ls, v), "'\"' inside an unquoted value; quote the whole value");
    ++v;
  }
  while (v > p && is_blank(v[-1])) --v;
  *out = dup_range(p, (size_t)(v - p));
  return *out ? 0 : oom(c->d);
}

char *sl_ini_path_relative(const char *file, const char *rel) {
  const char *slash = strrchr(file, '/');
  if (rel[0] == '/' || !slash) return dup_range(rel, strlen(rel));
  size_t dlen = (size_t)(slash - file) + 1, rlen = strlen(rel);
  char *p = malloc(dlen + rlen + 1);
  if (!p) return NULL;
  memcpy(p, file, dlen);
  memcpy(p + dlen, rel, rlen + 1);
  return p;
}

/* "a.ini -> b.ini -> last" for include diagnostics. */
static void chain_text(const parse_ctx *c, const char *last, char *buf, size_t size) {
  size_t n = 0;
  buf[0] = '\0';
  for (int i = 0; i <= c->depth + 1; ++i) {
    const char *name = i <= c->depth ? c->chain[i].name : last;
    int w = snprintf(buf + n, size - n, "%s%s", i ? " -> " : "", name);
    if (w < 0 || (size_t)w >= size - n) return; /* truncated: the message stays readable */
    n += (size_t)w;
  }
}

static int do_include(parse_ctx *c, const char *file, int lineno, int vcol, const char *value) {
  char chain[1200];
  if (value[0] == '\0') return err_at(c->d, file, lineno, vcol, "include needs a file name");
  char *path = sl_ini_path_relative(file, value);
  if (!path) return oom(c->d);
  int rc;
  if (c->depth >= INI_MAX_DEPTH) {
    chain_text(c, path, chain, sizeof chain);
    rc = err_at(c->d, file, lineno, vcol, "includes are nested more than %d deep: %s", INI_MAX_DEPTH, chain);
    free(path);
    return rc;
  }
  if (c->n_parses >= INI_MAX_PARSES) {
    rc = err_at(c->d, file, lineno, vcol, "more than %d files read through includes", INI_MAX_PARSES);
    free(path);
    return rc;
  }
  char *text;
  size_t len;
  file_id id = {0};
  int e = read_file(path, &text, &len, &id);
  if (e == ENOMEM) {
    free(path);
    return oom(c->d);
  }
  if (e) {
    rc = err_at(c->d, file, lineno, vcol, "cannot read included file '%s': %s", path, read_error_text(e));
    free(path);
    return rc;
  }
  /* A loop: the same file (by identity, or by name when parsed from memory)
   * is already being parsed further up the chain. */
  for (int i = 0; i <= c->depth; ++i) {
    const chain_link *l = &c->chain[i];
    if ((l->id.has_id && l->id.dev == id.dev && l->id.ino == id.ino) || strcmp(l->name, path) == 0) {
      chain_text(c, path, chain, sizeof chain);
      rc = err_at(c->d, file, lineno, vcol, "include loop: %s", chain);
      free(text);
      free(path);
      return rc;
    }
  }
  const char *name = intern_file(c->ini, path);
  free(path);
  if (!name) {
    free(text);
    return oom(c->d);
  }
  ++c->depth;
  ++c->n_parses;
  c->chain[c->depth].name = name;
  c->chain[c->depth].id = id;
  rc = parse_text(c, text, len, name);
  --c->depth;
  free(text);
  return rc;
}

static int parse_header(parse_ctx *c, file_state *fs, int lineno, const char *ls, const char *p, const char *e) {
  char cb[8];
  const char *open = p;
  ++p;
  while (p < e && is_blank(*p)) ++p;
  const char *ns = p;
  while (p < e && is_section_char(*p)) ++p;
  const char *ne = p;
  while (p < e && is_blank(*p)) ++p;
  if (p >= e || is_comment(*p))
    return err_at(c->d, fs->file, lineno, col_at(ls, p), "unterminated section header: expected ']'");
  if (*p != ']') {
    if (p == ne)
      return err_at(c->d, fs->file, lineno, col_at(ls, p),
                    "invalid character '%s' in section name (allowed: letters, digits, '_', '.', '-')",
                    show_char(p, cb));
    return err_at(c->d, fs->file, lineno, col_at(ls, p), "expected ']' after section name, found '%s'",
                  show_char(p, cb));
  }
  size_t bad;
  const char *why = bad_section_name(ns, (size_t)(ne - ns), &bad);
  if (why) return err_at(c->d, fs->file, lineno, col_at(ls, ns == ne ? p : ns + bad), "%s", why);
  const char *q = p + 1;
  while (q < e && is_blank(*q)) ++q;
  if (q < e && !is_comment(*q))
    return err_at(c->d, fs->file, lineno, col_at(ls, q), "unexpected '%s' after section header [%.*s]",
                  show_char(q, cb), (int)(ne - ns), ns);

  int idx = find_section_n(c->ini, ns, (size_t)(ne - ns));
  if (idx >= 0) {
    for (int i = 0; i < fs->n_opened; ++i)
      if (fs->opened[i].index == idx)
        return err_at(c->d, fs->file, lineno, col_at(ls, open), "section [%s] already opened at line %d",
                      c->ini->sections[idx].name, fs->opened[i].line);
  } else {
    idx = add_section(c->ini, ns, (size_t)(ne - ns), fs->file, lineno);
    if (idx < 0) return oom(c->d);
  }
  if (push_mark(&fs->opened, &fs->n_opened, &fs->cap_opened, idx, lineno)) return oom(c->d);
  fs->cur = idx;
  fs->n_set = 0;
  ++fs->n_headers;
  return 0;
}

static int parse_assignment(parse_ctx *c, file_state *fs, int lineno, const char *ls, const char *p, const char *e) {
  char cb[8];
  const char *ks = p;
  while (p < e && is_key_char(*p)) ++p;
  const char *ke = p;
  size_t klen = (size_t)(ke - ks);
  if (klen == 0) {
    if (*p == '=') return err_at(c->d, fs->file, lineno, col_at(ls, p), "missing key before '='");
    return err_at(c->d, fs->file, lineno, col_at(ls, p), "expected a key, a [section] header or a comment, found '%s'",
                  show_char(p, cb));
  }
  while (p < e && is_blank(*p)) ++p;
  if (p >= e || is_comment(*p))
    return err_at(c->d, fs->file, lineno, col_at(ls, p), "missing '=' after key '%.*s'", (int)klen, ks);
  if (*p != '=') {
    if (p == ke)
      return err_at(c->d, fs->file, lineno, col_at(ls, p),
                    "invalid character '%s' in key (allowed: letters, digits, '_', '-')", show_char(p, cb));
    return err_at(c->d, fs->file, lineno, col_at(ls, p), "missing '=' after key '%.*s' (found '%s')", (int)klen, ks,
                  show_char(p, cb));
  }
  ++p;
  while (p < e && is_blank(*p)) ++p;
  int kcol = col_at(ls, ks), vcol = col_at(ls, p);
  int is_include = klen == 7 && memcmp(ks, "include", 7) == 0;

  if (fs->cur < 0 && !is_include)
    return err_at(c->d, fs->file, lineno, kcol, "key '%.*s' comes before any [section] header (only 'include' may)",
                  (int)klen, ks);
  if (fs->cur >= 0 && is_include)
    return err_at(c->d, fs->file, lineno, kcol, "'include' must come before the first [section] header");

  char *value;
  int quoted, rc = parse_value(c, fs->file, lineno, ls, p, e, &value, &quoted);
  if (rc) return rc;
  if (is_include) {
    ++fs->n_includes;
    rc = do_include(c, fs->file, lineno, vcol, value);
    free(value);
    return rc;
  }

  sl_ini_section *s = &c->ini->sections[fs->cur];
  int ei = find_entry_n(s, ks, klen);
  if (ei >= 0) {
    for (int i = 0; i < fs->n_set; ++i)
      if (fs->set[i].index == ei) {
        free(value);
        return err_at(c->d, fs->file, lineno, kcol, "duplicate key '%.*s' in [%s] (first set at line %d)", (int)klen,
                      ks, s->name, fs->set[i].line);
      }
  }
  ei = set_entry(s, ks, klen, value, quoted, fs->file, lineno, kcol, vcol);
  if (ei < 0) return oom(c->d);
  if (push_mark(&fs->set, &fs->n_set, &fs->cap_set, ei, lineno)) return oom(c->d);
  return 0;
}

static int parse_text(parse_ctx *c, const char *text, size_t len, const char *file) {
  file_state fs;
  memset(&fs, 0, sizeof fs);
  fs.file = file;
  fs.cur = -1;
  if (len > INI_MAX_FILE) return err_at(c->d, file, 0, 0, "file is larger than 16 MiB; a scene file should be small");

  size_t pos = 0;
  if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) pos = 3; /* UTF-8 byte-order mark from some editors */
  size_t k = pos;
  while (k < len && (is_blank(text[k]) || text[k] == '\n' || text[k] == '\r')) ++k;
  if (k == len) return err_at(c->d, file, 1, 1, "file is empty");

  int rc = 0, lineno = 0;
  while (pos < len && rc == 0) {
    ++lineno;
    const char *ls = text + pos;
    const char *nl = memchr(ls, '\n', len - pos);
    size_t n = nl ? (size_t)(nl - ls) : len - pos;
    pos += n + (nl ? 1 : 0);
    if (n > INI_MAX_LINE) {
      rc = err_at(c->d, file, lineno, 1, "line is %zu bytes long; lines are limited to 64 KiB (%d bytes)", n,
                  INI_MAX_LINE);
      break;
    }
    if (n > 0 && ls[n - 1] == '\r') --n; /* CRLF line ends */
    char why[128];
    size_t bad = check_text(ls, n, why, sizeof why);
    if (bad < n) {
      rc = err_at(c->d, file, lineno, col_at(ls, ls + bad), "%s", why);
      break;
    }
    const char *e = ls + n, *p = ls;
    while (p < e && is_blank(*p)) ++p;
    if (p == e || is_comment(*p)) continue;
    if (*p == '[') rc = parse_header(c, &fs, lineno, ls, p, e);
    else rc = parse_assignment(c, &fs, lineno, ls, p, e);
  }
  if (rc == 0 && fs.n_headers == 0 && fs.n_includes == 0)
    rc = err_at(c->d, file, 1, 1, "no sections: the file has only comments and blank lines");
  free(fs.opened);
  free(fs.set);
  return rc;
}

/* Parses the root text; on failure nothing is returned and *out is NULL. */
static int parse_root(const char *text, size_t len, const char *name, file_id id, sl_ini **out, sl_diag *d) {
  sl_ini *ini = calloc(1, sizeof *ini);
  if (!ini) return oom(d);
  const char *iname = intern_file(ini, name);
  if (!iname) {
    sl_ini_free(ini);
    return oom(d);
  }
  parse_ctx c;
  memset(&c, 0, sizeof c);
  c.ini = ini;
  c.d = d;
  c.chain[0].name = iname;
  c.chain[0].id = id;
  c.n_parses = 1;
  int rc = parse_text(&c, text ? text : "", text ? len : 0, iname);
  if (rc) {
    sl_ini_free(ini);
    return rc;
  }
  *out = ini;
  return 0;
}

int sl_ini_parse_string(const char *text, size_t len, const char *name, sl_ini **out, sl_diag *d) {
  if (!out) return sl_diag_set(d, SL_EBADINPUT, "error: sl_ini_parse_string: no output pointer");
  *out = NULL;
  file_id id = {0};
  return parse_root(text, len, name ? name : "<string>", id, out, d);
}

int sl_ini_parse_file(const char *path, sl_ini **out, sl_diag *d) {
  if (!out) return sl_diag_set(d, SL_EBADINPUT, "error: sl_ini_parse_file: no output pointer");
  *out = NULL;
  if (!path || !*path) return sl_diag_set(d, SL_EBADINPUT, "error: no configuration file name given");
  char *text;
  size_t len;
  file_id id = {0};
  int e = read_file(path, &text, &len, &id);
  if (e == ENOMEM) return oom(d);
  if (e) return err_at(d, path, 0, 0, "cannot read configuration file: %s", read_error_text(e));
  int rc = parse_root(text, len, path, id, out, d);
  free(text);
  return rc;
}

/* ---------------------------------------------------------------- overrides */

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static int
override_err(sl_diag *d, const char *assignment, const char *fmt, ...) {
  char msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  return sl_diag_set(d, SL_EBADINPUT, "--set %.900s: %s", assignment, msg);
}

int sl_ini_apply_override(sl_ini *ini, const char *a, sl_diag *d) {
  if (!a) return sl_diag_set(d, SL_EBADINPUT, "--set: expected section.key=value");
  if (!ini) return override_err(d, a, "no configuration to apply it to");
  size_t alen = strlen(a);
  if (alen > INI_MAX_OVERRIDE) return override_err(d, a, "longer than %d bytes", INI_MAX_OVERRIDE);
  char why[128];
  if (check_text(a, alen, why, sizeof why) < alen) return override_err(d, a, "%s", why);

  const char *eq = strchr(a, '=');
  if (!eq) return override_err(d, a, "expected section.key=value");
  const char *ls = a, *le = eq;
  while (ls < le && is_blank(*ls)) ++ls;
  while (le > ls && is_blank(le[-1])) --le;
  const char *dot = NULL;
  for (const char *q = ls; q < le; ++q)
    if (*q == '.') dot = q;
  if (!dot || dot == ls || dot + 1 == le) return override_err(d, a, "expected section.key=value");

  size_t bad;
  const char *bad_why = bad_section_name(ls, (size_t)(dot - ls), &bad);
  if (bad_why) return override_err(d, a, "%s: '%.*s'", bad_why, (int)(dot - ls), ls);
  for (const char *q = dot + 1; q < le; ++q)
    if (!is_key_char(*q))
      return override_err(d, a, "invalid character in key '%.*s' (allowed: letters, digits, '_', '-')",
                          (int)(le - dot - 1), dot + 1);
  if (le - dot - 1 == 7 && memcmp(dot + 1, "include", 7) == 0)
    return override_err(d, a, "'include' cannot be set from the command line");

  /* The value: surrounding blanks dropped; "..." is unquoted as in a file.
   * No comments on the command line: ';' and '#' are kept. */
  const char *vs = eq + 1, *ve = a + alen;
  while (vs < ve && is_blank(*vs)) ++vs;
  while (ve > vs && is_blank(ve[-1])) --ve;
  char *value;
  int quoted = 0;
  if (vs < ve && *vs == '"') {
    value = malloc((size_t)(ve - vs));
    if (!value) return oom(d);
    size_t n = 0;
    const char *q = vs + 1;
    while (q < ve && *q != '"') {
      if (*q == '\\' && q + 1 < ve && (q[1] == '"' || q[1] == '\\')) ++q;
      else if (*q == '\\') {
        free(value);
        return override_err(d, a, "unknown escape in quoted value (only \\\" and \\\\ are allowed)");
      }
      value[n++] = *q++;
    }
    if (q + 1 != ve) {
      free(value);
      return override_err(d, a, "%s", q >= ve ? "unterminated quoted value" : "unexpected text after the quoted value");
    }
    value[n] = '\0';
    quoted = 1;
  } else {
    value = dup_range(vs, (size_t)(ve - vs));
    if (!value) return oom(d);
  }

  const char *file = intern_file(ini, CMDLINE_FILE);
  if (!file) {
    free(value);
    return oom(d);
  }
  int si = find_section_n(ini, ls, (size_t)(dot - ls));
  if (si < 0) si = add_section(ini, ls, (size_t)(dot - ls), file, 0);
  if (si < 0) {
    free(value);
    return oom(d);
  }
  if (set_entry(&ini->sections[si], dot + 1, (size_t)(le - dot - 1), value, quoted, file, 0, 0, 0) < 0) return oom(d);
  return 0;
}

/* ----------------------------------------------------------- number parsing */

int sl_parse_real(const char *s, double *out) {
  if (!s || !*s) return SL_EBADINPUT;
  /* Only decimal notation: strtod would also take "inf", "nan", hex and blanks. */
  for (const char *p = s; *p; ++p)
    if (!((*p >= '0' && *p <= '9') || *p == '+' || *p == '-' || *p == '.' || *p == 'e' || *p == 'E'))
      return SL_EBADINPUT;
  char *end;
  errno = 0;
  double v = strtod(s, &end);
  if (end == s || *end != '\0' || !isfinite(v)) return SL_EBADINPUT;
  if (out) *out = v;
  return 0;
}

int sl_parse_real_expr(const char *s, double *out, char *why, size_t why_len) {
  return sl_parse_real_expr_with(s, NULL, out, why, why_len);
}

int sl_parse_real_expr_with(const char *s, const sl_expr_constants *k, double *out, char *why, size_t why_len) {
  if (why && why_len) why[0] = '\0';
  if (sl_parse_real(s, out) == 0) return 0;
  if (!s || !*s) return SL_EBADINPUT;
  sl_expr *e = NULL;
  sl_diag d;
  if (sl_expr_compile_with(s, NULL, 0, k, &e, &d)) {
    /* A long message may be cut to the caller's buffer; that is intended. */
    if (why && snprintf(why, why_len, "%s", d.msg) >= (int)why_len) why[why_len - 1] = '\0';
    return SL_EBADINPUT;
  }
  double v = sl_expr_eval(e, NULL);
  sl_expr_free(e);
  if (!isfinite(v)) {
    if (why) snprintf(why, why_len, "its value %g is not finite", v);
    return SL_EBADINPUT;
  }
  if (out) *out = v;
  return 0;
}

int sl_parse_long(const char *s, long *out) {
  if (!s || !*s) return SL_EBADINPUT;
  for (const char *p = s; *p; ++p)
    if (!((*p >= '0' && *p <= '9') || *p == '+' || *p == '-')) return SL_EBADINPUT;
  char *end;
  errno = 0;
  long v = strtol(s, &end, 10);
  if (end == s || *end != '\0' || errno == ERANGE) return SL_EBADINPUT;
  if (out) *out = v;
  return 0;
}

static int ascii_ieq(const char *a, const char *b) {
  for (; *a && *b; ++a, ++b) {
    char x = *a >= 'A' && *a <= 'Z' ? (char)(*a - 'A' + 'a') : *a;
    if (x != *b) return 0;
  }
  return *a == *b;
}

int sl_parse_bool(const char *s, int *out) {
  static const char *const yes[] = {"true", "yes", "on", "1"}, *const no[] = {"false", "no", "off", "0"};
  if (!s) return SL_EBADINPUT;
  for (int i = 0; i < 4; ++i) {
    if (ascii_ieq(s, yes[i])) {
      if (out) *out = 1;
      return 0;
    }
    if (ascii_ieq(s, no[i])) {
      if (out) *out = 0;
      return 0;
    }
  }
  return SL_EBADINPUT;
}

/* ------------------------------------------------------------ typed getters */

/* The entry, or NULL: then *rc is 0 (use the default) or an error when required. */
static sl_ini_entry *lookup(const sl_ini *ini, const char *section, const char *key, int required, sl_diag *d,
                            int *rc) {
  *rc = 0;
  sl_ini_entry *e = sl_ini_find(ini, section, key);
  if (e) {
    e->used = 1;
    return e;
  }
  if (!required) return NULL;
  const sl_ini_section *s = sl_ini_find_section(ini, section);
  if (s) {
    *rc = err_at(d, s->file, s->line, 1, "[%s] is missing the required key '%s'", section, key ? key : "");
  } else {
    const char *root = ini && ini->n_files > 0 ? ini->files[0] : "<configuration>";
    *rc = err_at(d, root, 0, 0, "missing section [%s] (it needs the key '%s')", section ? section : "", key ? key : "");
  }
  return NULL;
}

/* "LOC: error: [section] key = VALUE<tail>", pointing at the value (or at col). */
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
static int
value_err(const sl_ini_entry *e, const char *section, int col, sl_diag *d, const char *fmt, ...) {
  char tail[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(tail, sizeof tail, fmt, ap);
  va_end(ap);
  const char *q = e->quoted ? "\"" : "";
  return err_at(d, e->file, e->line, col > 0 ? col : e->value_col, "[%s] %s = %s%.600s%s%s", section, e->key, q,
                e->value, q, tail);
}

/* An unquoted empty value where a typed one is needed. */
static int empty_err(const sl_ini_entry *e, const char *section, sl_diag *d, const char *expected) {
  return err_at(d, e->file, e->line, e->value_col, "[%s] %s has no value; expected %s", section, e->key, expected);
}

int sl_ini_get_real(const sl_ini *ini, const char *section, const char *key, int required, double def, double min,
                    double max, double *out, sl_diag *d) {
  int rc;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) {
    if (!rc && out) *out = def;
    return rc;
  }
  if (!e->value[0] && !e->quoted) return empty_err(e, section, d, "a real number");
  double v;
  char why[200];
  if (sl_parse_real_expr_with(e->value, sl_ini_constants(ini), &v, why, sizeof why))
    return value_err(e, section, 0, d,
                     ": expected a real number or a constant expression (like 2, 0.5, 1e-3 or 2*pi)%s%s",
                     why[0] ? ": " : "", why);
  if (v < min || v > max) {
    char a[40], b[40];
    return value_err(e, section, 0, d, " is outside the allowed range [%s, %s]", fmt_real(min, a), fmt_real(max, b));
  }
  if (out) *out = v;
  return 0;
}

int sl_ini_get_int(const sl_ini *ini, const char *section, const char *key, int required, long def, long min, long max,
                   long *out, sl_diag *d) {
  int rc;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) {
    if (!rc && out) *out = def;
    return rc;
  }
  if (!e->value[0] && !e->quoted) return empty_err(e, section, d, "an integer");
  long v;
  if (sl_parse_long(e->value, &v)) return value_err(e, section, 0, d, ": expected an integer");
  if (v < min || v > max) return value_err(e, section, 0, d, " is outside the allowed range [%ld, %ld]", min, max);
  if (out) *out = v;
  return 0;
}

int sl_ini_get_bool(const sl_ini *ini, const char *section, const char *key, int required, int def, int *out,
                    sl_diag *d) {
  int rc;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) {
    if (!rc && out) *out = def;
    return rc;
  }
  if (!e->value[0] && !e->quoted) return empty_err(e, section, d, "a boolean");
  int v;
  if (sl_parse_bool(e->value, &v))
    return value_err(e, section, 0, d, ": expected a boolean (true/false, yes/no, on/off, 1/0)");
  if (out) *out = v;
  return 0;
}

int sl_ini_get_string(const sl_ini *ini, const char *section, const char *key, int required, const char *def,
                      const char **out, sl_diag *d) {
  int rc;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) {
    if (!rc && out) *out = def;
    return rc;
  }
  /* `key =` is taken as a forgotten value; an intended empty string is "". */
  if (!e->value[0] && !e->quoted) return empty_err(e, section, d, "a string (write \"\" for an empty one)");
  if (out) *out = e->value;
  return 0;
}

int sl_ini_get_choice(const sl_ini *ini, const char *section, const char *key, int required, int def,
                      const char *choices, int *out, sl_diag *d) {
  int rc;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) {
    if (!rc && out) *out = def;
    return rc;
  }
  if (!choices) choices = "";
  /* Split "a|b|c" into a private copy, for matching and for sl_suggest. */
  int n = 1;
  for (const char *p = choices; *p; ++p) n += *p == '|';
  char *copy = dup_range(choices, strlen(choices));
  const char **list = malloc((size_t)n * sizeof *list);
  if (!copy || !list) {
    free(copy);
    free(list);
    return oom(d);
  }
  n = 0;
  list[n++] = copy;
  for (char *p = copy; *p; ++p)
    if (*p == '|') {
      *p = '\0';
      list[n++] = p + 1;
    }
  int found = -1;
  for (int i = 0; i < n && found < 0; ++i)
    if (strcmp(list[i], e->value) == 0) found = i;
  if (found >= 0) {
    if (out) *out = found;
    rc = 0;
  } else {
    char names[700];
    size_t len = 0;
    names[0] = '\0';
    for (int i = 0; i < n && len < sizeof names; ++i) {
      int w = snprintf(names + len, sizeof names - len, "%s%s", i ? ", " : "", list[i]);
      if (w < 0) break;
      len += (size_t)w;
    }
    if (!e->value[0] && !e->quoted) {
      char expected[720];
      snprintf(expected, sizeof expected, "one of: %s", names);
      rc = empty_err(e, section, d, expected);
    } else {
      const char *hint = sl_suggest(e->value, (const char *const *)list, n);
      char hint_text[128] = "";
      if (hint) snprintf(hint_text, sizeof hint_text, "; did you mean '%.80s'?", hint);
      rc = value_err(e, section, 0, d, " is not one of: %s%s", names, hint_text);
    }
  }
  free(list);
  free(copy);
  return rc;
}

int sl_ini_get_real_list(const sl_ini *ini, const char *section, const char *key, int required, double *vals, int cap,
                         int *n, sl_diag *d) {
  int rc;
  if (n) *n = 0;
  sl_ini_entry *e = lookup(ini, section, key, required, d, &rc);
  if (!e) return rc;
  if (!e->value[0] && !e->quoted) return empty_err(e, section, d, "a comma-separated list of real numbers");
  const char *v = e->value;
  int count = 0;
  for (const char *p = v;;) {
    const char *end = p; /* the next comma outside parentheses: atan2(1, 2) is one item */
    for (int depth = 0; *end && !(*end == ',' && depth == 0); ++end) depth += *end == '(' ? 1 : *end == ')' ? -1 : 0;
    const char *s = p, *t = end;
    while (s < t && is_blank(*s)) ++s;
    while (t > s && is_blank(t[-1])) --t;
    /* Point at the item in unquoted values (the stored text is the source text). */
    int col = e->quoted ? 0 : e->value_col + col_at(v, s) - 1;
    if (s == t) return value_err(e, section, col, d, ": item %d is empty", count + 1);
    if (count >= cap)
      return value_err(e, section, col, d, ": more than %d values (at most %d are allowed)", cap < 0 ? 0 : cap,
                       cap < 0 ? 0 : cap);
    char item[256], why[200];
    size_t len = (size_t)(t - s);
    double x;
    if (len >= sizeof item) return value_err(e, section, col, d, ": item %d is not a real number", count + 1);
    memcpy(item, s, len);
    item[len] = '\0';
    if (sl_parse_real_expr_with(item, sl_ini_constants(ini), &x, why, sizeof why))
      return value_err(e, section, col, d, ": item %d ('%s') is not a real number or a constant expression%s%s",
                       count + 1, item, why[0] ? ": " : "", why);
    if (vals) vals[count] = x;
    ++count;
    if (*end == '\0') break;
    p = end + 1;
  }
  if (n) *n = count;
  return 0;
}

/* ------------------------------------------------------ unknown names checks */

int sl_ini_check_sections(const sl_ini *ini, const char *const *known, int n_known, const char *const *known_prefixes,
                          int n_prefixes, sl_diag *d) {
  if (!ini) return 0;
  for (int i = 0; i < ini->n_sections; ++i) {
    const sl_ini_section *s = &ini->sections[i];
    int ok = 0;
    for (int k = 0; k < n_known && !ok; ++k) ok = strcmp(s->name, known[k]) == 0;
    for (int k = 0; k < n_prefixes && !ok; ++k) {
      size_t pl = strlen(known_prefixes[k]);
      ok = strncmp(s->name, known_prefixes[k], pl) == 0 && s->name[pl] != '\0';
    }
    if (ok) continue;
    /* Suggest a known name, or a known prefix in place of a misspelt first part
     * ("[clousre.drag]" -> "[closure.drag]"). */
    char hint[300] = "";
    const char *h = sl_suggest(s->name, known, n_known);
    const char *dot = strchr(s->name, '.');
    if (h) {
      snprintf(hint, sizeof hint, "; did you mean [%.200s]?", h);
    } else if (dot && n_prefixes > 0) {
      char head[70];
      size_t hl = (size_t)(dot - s->name) + 1;
      if (hl < sizeof head) {
        memcpy(head, s->name, hl);
        head[hl] = '\0';
        const char *p = sl_suggest(head, known_prefixes, n_prefixes);
        if (p) snprintf(hint, sizeof hint, "; did you mean [%.80s%.200s]?", p, dot + 1);
      }
    }
    return err_at(d, s->file, s->line, s->line > 0 ? 1 : 0, "unknown section [%s]%s", s->name, hint);
  }
  return 0;
}

int sl_ini_check_keys(const sl_ini *ini, const char *section, const char *const *known, int n_known, sl_diag *d) {
  const sl_ini_section *s = sl_ini_find_section(ini, section);
  if (!s) return 0;
  for (int i = 0; i < s->n_entries; ++i) {
    const sl_ini_entry *e = &s->entries[i];
    int ok = 0;
    for (int k = 0; k < n_known && !ok; ++k) ok = strcmp(e->key, known[k]) == 0;
    if (ok) continue;
    const char *h = sl_suggest(e->key, known, n_known);
    if (h)
      return err_at(d, e->file, e->line, e->col, "unknown key '%s' in [%s]; did you mean '%s'?", e->key, s->name, h);
    char names[800];
    size_t len = 0;
    names[0] = '\0';
    for (int k = 0; k < n_known && len < sizeof names; ++k) {
      int w = snprintf(names + len, sizeof names - len, "%s%s", k ? ", " : "", known[k]);
      if (w < 0) break;
      len += (size_t)w;
    }
    return err_at(d, e->file, e->line, e->col, "unknown key '%s' in [%s] (known keys: %s)", e->key, s->name,
                  n_known ? names : "none");
  }
  return 0;
}

/* ------------------------------------------------------------------ writing */

typedef struct {
  char *s;
  size_t n, cap;
  int failed;
} sbuf;

static void sb_put(sbuf *b, const char *s, size_t n) {
  if (b->failed) return;
  if (b->n + n + 1 > b->cap) {
    size_t cap = b->cap ? b->cap : 256;
    while (cap < b->n + n + 1) {
      if (cap > SIZE_MAX / 2) {
        b->failed = 1;
        return;
      }
      cap *= 2;
    }
    char *ns = realloc(b->s, cap);
    if (!ns) {
      b->failed = 1;
      return;
    }
    b->s = ns;
    b->cap = cap;
  }
  memcpy(b->s + b->n, s, n);
  b->n += n;
  b->s[b->n] = '\0';
}

static void sb_str(sbuf *b, const char *s) { sb_put(b, s, strlen(s)); }

/* A value must be quoted to read back the same when it is (or was) quoted,
 * has blanks at either end, or holds a comment character or a quote. */
static int needs_quotes(const sl_ini_entry *e) {
  const char *v = e->value;
  size_t n = strlen(v);
  if (e->quoted) return 1;
  if (n && (is_blank(v[0]) || is_blank(v[n - 1]))) return 1;
  return strpbrk(v, ";#\"") != NULL;
}

static size_t quoted_len(const char *v) {
  size_t n = 2;
  for (; *v; ++v) n += (*v == '"' || *v == '\\') ? 2 : 1;
  return n;
}

char *sl_ini_to_string(const sl_ini *ini) {
  sbuf b = {0};
  sb_put(&b, "", 0); /* an empty configuration still gives "" */
  for (int i = 0; ini && i < ini->n_sections; ++i) {
    const sl_ini_section *s = &ini->sections[i];
    if (i) sb_str(&b, "\n");
    sb_str(&b, "[");
    sb_str(&b, s->name);
    sb_str(&b, "]\n");
    for (int j = 0; j < s->n_entries; ++j) {
      const sl_ini_entry *e = &s->entries[j];
      int q = needs_quotes(e);
      size_t vlen = q ? quoted_len(e->value) : strlen(e->value);
      /* Drop the blanks around '=' when they would push a line that was
       * within the limit when read over it, so the output always reads back. */
      int compact = strlen(e->key) + 3 + vlen > INI_MAX_LINE;
      sb_str(&b, e->key);
      sb_str(&b, compact ? "=" : (e->value[0] || q ? " = " : " ="));
      if (q) {
        sb_str(&b, "\"");
        for (const char *v = e->value; *v; ++v) {
          if (*v == '"' || *v == '\\') sb_put(&b, "\\", 1);
          sb_put(&b, v, 1);
        }
        sb_str(&b, "\"");
      } else {
        sb_str(&b, e->value);
      }
      sb_str(&b, "\n");
    }
  }
  if (b.failed) {
    free(b.s);
    return NULL;
  }
  return b.s;
}

int sl_ini_write(const sl_ini *ini, FILE *f) {
  if (!f) return SL_EFAILED;
  char *s = sl_ini_to_string(ini);
  if (!s) return SL_EFAILED;
  size_t n = strlen(s);
  int rc = fwrite(s, 1, n, f) == n ? 0 : SL_EFAILED;
  free(s);
  return rc;
}
