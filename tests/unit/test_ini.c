/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Unit tests of the INI parser (core/config/ini.c): syntax, includes, typed
 * getters, overrides, unknown-name checks, writing and every malformed input
 * the issue lists. Error cases check the exit code and the exact
 * "file:line:col:" prefix, since users navigate by it. Include files are
 * written into the working directory (the test's build folder) at run time. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/config/ini.h"
#include "testing.h"

#define DIR "ini_tmp"

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "wb");
  CHECK_MSG(f != NULL, "cannot write %s", path);
  if (!f) return;
  fputs(text, f);
  fclose(f);
}

static int parse_str(const char *text, const char *name, sl_ini **ini, sl_diag *d) {
  return sl_ini_parse_string(text, strlen(text), name, ini, d);
}

/* The message starts with `prefix` and contains `part`; a macro so that a
 * failure names the line of the case. */
#define CHECK_ERR(rc, d, prefix, part)                                                                       \
  do {                                                                                                       \
    CHECK_MSG((rc) == SL_EBADINPUT, "rc = %d, expected 2 (message: %s)", (rc), (d).msg);                     \
    CHECK_MSG(strncmp((d).msg, (prefix), strlen(prefix)) == 0, "\"%s\" does not start with \"%s\"", (d).msg, \
              (prefix));                                                                                     \
    CHECK_CONTAINS((d).msg, (part));                                                                         \
  } while (0)

#define CHECK_PARSE_ERR_N(text, len, prefix, part)                       \
  do {                                                                   \
    sl_ini *ini_ = NULL;                                                 \
    sl_diag d_ = {{0}};                                                  \
    int rc_ = sl_ini_parse_string((text), (len), "bad.ini", &ini_, &d_); \
    CHECK_ERR(rc_, d_, prefix, part);                                    \
    CHECK(ini_ == NULL);                                                 \
    sl_ini_free(ini_);                                                   \
  } while (0)

#define CHECK_PARSE_ERR(text, prefix, part) CHECK_PARSE_ERR_N((text), strlen(text), prefix, part)

#define CHECK_FILE_ERR(path, prefix, part)           \
  do {                                               \
    sl_ini *ini_ = NULL;                             \
    sl_diag d_ = {{0}};                              \
    int rc_ = sl_ini_parse_file((path), &ini_, &d_); \
    CHECK_ERR(rc_, d_, prefix, part);                \
    CHECK(ini_ == NULL);                             \
    sl_ini_free(ini_);                               \
  } while (0)

static const char *value_of(const sl_ini *ini, const char *section, const char *key) {
  const sl_ini_entry *e = sl_ini_find(ini, section, key);
  return e ? e->value : "(missing)";
}

/* ------------------------------------------------------------- syntax */

static void test_syntax(void) {
  const char *text =
      "; a scene\n"
      "# with comments of both kinds\n"
      "\n"
      "[scene]\n"
      "model = mixture   ; trailing comment\n"
      "title = \"a ; b # c \\\"q\\\" \\\\ end\"  # comment after a quoted string\n"
      "geometry=planar\n"
      "\t path = C:\\data\\run \n"
      "\n"
      "[closure.drag]\n"
      "model = ergun\n"
      "  n = 4.65#no blank before the comment\n"
      "[ closure.hindered-settling_2 ]   ; blanks inside the brackets\n"
      "flag = yes\n"
      "[mesh]\n"
      "sizes = 1, 2.5 ,1e-3\n"
      "count = 42\n"
      "blank = \"\"\n"
      "nothing =\n"
      "unicode = \xC3\xA9t\xC3\xA9 \xE2\x86\x92 \xF0\x9F\x8C\x8A\n"
      "[empty]\n";
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = parse_str(text, "pos.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (!ini) return;
  CHECK(ini->n_sections == 5);
  CHECK(strcmp(ini->sections[0].name, "scene") == 0);
  CHECK(strcmp(ini->sections[1].name, "closure.drag") == 0);
  CHECK(strcmp(ini->sections[2].name, "closure.hindered-settling_2") == 0);
  CHECK(strcmp(ini->sections[4].name, "empty") == 0 && ini->sections[4].n_entries == 0);
  CHECK(ini->sections[1].line == 10);
  CHECK(strcmp(value_of(ini, "scene", "model"), "mixture") == 0);
  CHECK(strcmp(value_of(ini, "scene", "title"), "a ; b # c \"q\" \\ end") == 0);
  CHECK(strcmp(value_of(ini, "scene", "geometry"), "planar") == 0);
  CHECK(strcmp(value_of(ini, "scene", "path"), "C:\\data\\run") == 0);
  CHECK(strcmp(value_of(ini, "closure.drag", "n"), "4.65") == 0);
  CHECK(strcmp(value_of(ini, "closure.hindered-settling_2", "flag"), "yes") == 0);
  CHECK(strcmp(value_of(ini, "mesh", "blank"), "") == 0);
  CHECK(strcmp(value_of(ini, "mesh", "nothing"), "") == 0);
  CHECK(strcmp(value_of(ini, "mesh", "unicode"), "\xC3\xA9t\xC3\xA9 \xE2\x86\x92 \xF0\x9F\x8C\x8A") == 0);

  const sl_ini_entry *e = sl_ini_find(ini, "scene", "title");
  CHECK(e && e->quoted == 1 && e->line == 6 && e->col == 1 && e->value_col == 9);
  CHECK(e && strcmp(e->file, "pos.ini") == 0);
  e = sl_ini_find(ini, "closure.drag", "n");
  CHECK(e && e->quoted == 0 && e->line == 12 && e->col == 3 && e->value_col == 7);
  e = sl_ini_find(ini, "mesh", "blank");
  CHECK(e && e->quoted == 1);
  e = sl_ini_find(ini, "mesh", "nothing");
  CHECK(e && e->quoted == 0);
  CHECK(sl_ini_find(ini, "scene", "nope") == NULL);
  CHECK(sl_ini_find(ini, "nope", "model") == NULL);
  CHECK(sl_ini_find_section(ini, "closure") == NULL);

  /* Typed look-up of the syntax forms. */
  double v[4];
  int n = 0;
  CHECK(sl_ini_get_real_list(ini, "mesh", "sizes", 1, v, 4, &n, &d) == 0);
  CHECK(n == 3);
  CHECK_CLOSE(v[0], 1.0, 0);
  CHECK_CLOSE(v[1], 2.5, 0);
  CHECK_CLOSE(v[2], 1e-3, 1e-15);
  long count = 0;
  CHECK(sl_ini_get_int(ini, "mesh", "count", 1, 0, 0, 100, &count, &d) == 0 && count == 42);
  int flag = 0;
  CHECK(sl_ini_get_bool(ini, "closure.hindered-settling_2", "flag", 1, 0, &flag, &d) == 0 && flag == 1);
  const char *s = NULL;
  CHECK(sl_ini_get_string(ini, "mesh", "blank", 1, "def", &s, &d) == 0 && s && s[0] == '\0');
  sl_ini_free(ini);

  /* Byte-order mark, CRLF line ends, no newline at the end. */
  ini = NULL;
  rc = parse_str("\xEF\xBB\xBF[a]\r\nk = v\r\n\r\n[b]\r\nx = \"1\"\r\ny=2", "crlf.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (ini) {
    CHECK(strcmp(value_of(ini, "a", "k"), "v") == 0);
    CHECK(strcmp(value_of(ini, "b", "x"), "1") == 0);
    CHECK(strcmp(value_of(ini, "b", "y"), "2") == 0);
    CHECK(ini->sections[0].line == 1);
  }
  sl_ini_free(ini);

  /* A line of exactly 64 KiB is accepted. */
  size_t len = 65536;
  char *big = malloc(len + 8);
  CHECK(big != NULL);
  if (big) {
    memcpy(big, "[a]\nk = ", 8);
    memset(big + 8, 'x', len - 4);
    ini = NULL;
    rc = sl_ini_parse_string(big, 4 + len, "big.ini", &ini, &d);
    CHECK_MSG(rc == 0, "64 KiB line refused: %s", d.msg);
    CHECK(ini && strlen(value_of(ini, "a", "k")) == len - 4);
    sl_ini_free(ini);
    free(big);
  }
}

/* -------------------------------------------------------- malformed input */

static void test_malformed(void) {
  /* Unterminated section header: points where ']' was expected. */
  CHECK_PARSE_ERR("[scene]\nmodel = x\n[time\n", "bad.ini:3:6: error: ", "unterminated section header");
  CHECK_PARSE_ERR("[scene]\n[time ; comment]\n", "bad.ini:2:7: error: ", "unterminated section header");
  CHECK_PARSE_ERR("[", "bad.ini:1:2: error: ", "unterminated section header");
  /* Missing '='. */
  CHECK_PARSE_ERR("[scene]\nmodel mixture\n", "bad.ini:2:7: error: ", "missing '=' after key 'model'");
  CHECK_PARSE_ERR("[scene]\n  model   ; no value\n", "bad.ini:2:11: error: ", "missing '=' after key 'model'");
  CHECK_PARSE_ERR("[scene]\n = x\n", "bad.ini:2:2: error: ", "missing key before '='");
  /* Duplicate key in one section of one file names the first line. */
  CHECK_PARSE_ERR("[time]\ndt = 1\nend = 2\n\ndt = 3\n",
                  "bad.ini:5:1: error: ", "duplicate key 'dt' in [time] (first set at line 2)");
  /* Duplicate section header in one file. */
  CHECK_PARSE_ERR("[a]\nx = 1\n[b]\ny = 2\n[a]\nz = 3\n",
                  "bad.ini:5:1: error: ", "section [a] already opened at line 1");
  /* A 100 kB line: refused with its size, no crash. */
  {
    size_t n = 100 * 1024;
    char *t = malloc(n + 16);
    CHECK(t != NULL);
    if (t) {
      memcpy(t, "[a]\nk = ", 8);
      memset(t + 8, 'v', n - 4);
      memcpy(t + 4 + n, "\nx = 1\n", 7);
      CHECK_PARSE_ERR_N(t, n + 11, "bad.ini:2:1: error: ", "line is 102400 bytes long; lines are limited to 64 KiB");
      free(t);
    }
  }
  /* Binary garbage: NUL bytes, control characters, invalid UTF-8. */
  CHECK_PARSE_ERR_N("[a]\nk = v\0w\n", 12, "bad.ini:2:6: error: ", "NUL byte");
  CHECK_PARSE_ERR_N("\0\0\0\x01\x02", 5, "bad.ini:1:1: error: ", "NUL byte");
  CHECK_PARSE_ERR("[a]\nk = a\x1b[0m\n", "bad.ini:2:6: error: ", "control character 0x1B");
  CHECK_PARSE_ERR("[a]\nk = a\rb\n", "bad.ini:2:6: error: ", "control character 0x0D");
  CHECK_PARSE_ERR("[a]\nk = \xff\n", "bad.ini:2:5: error: ", "invalid UTF-8 byte 0xFF");
  CHECK_PARSE_ERR("[a]\nk = \xC3\xA9\xC3\n", "bad.ini:2:6: error: ", "invalid UTF-8 byte 0xC3");
  CHECK_PARSE_ERR("[a]\nk = \xC0\xAF\n", "bad.ini:2:5: error: ", "invalid UTF-8");         /* overlong '/' */
  CHECK_PARSE_ERR("[a]\nk = \xED\xA0\x80\n", "bad.ini:2:5: error: ", "invalid UTF-8");     /* surrogate */
  CHECK_PARSE_ERR("[a]\nk = \xF4\x90\x80\x80\n", "bad.ini:2:5: error: ", "invalid UTF-8"); /* > U+10FFFF */
  CHECK_PARSE_ERR(
      "\x7f"
      "ELF\x02\x01",
      "bad.ini:1:1: error: ", "control character 0x7F");
  /* Empty file, blank file, comments only. */
  CHECK_PARSE_ERR("", "bad.ini:1:1: error: ", "file is empty");
  CHECK_PARSE_ERR(" \n\t\r\n\n", "bad.ini:1:1: error: ", "file is empty");
  CHECK_PARSE_ERR("\xEF\xBB\xBF", "bad.ini:1:1: error: ", "file is empty");
  CHECK_PARSE_ERR("; just\n# comments\n", "bad.ini:1:1: error: ", "no sections");
  {
    sl_ini *ini = NULL;
    sl_diag d = {{0}};
    CHECK_ERR(sl_ini_parse_string(NULL, 0, NULL, &ini, &d), d, "<string>:1:1: error: ", "file is empty");
  }
  /* Quoted strings. */
  CHECK_PARSE_ERR("[a]\nk = \"abc\n", "bad.ini:2:5: error: ", "unterminated quoted string");
  CHECK_PARSE_ERR("[a]\nk = \"abc\\\"\n", "bad.ini:2:5: error: ", "unterminated quoted string");
  CHECK_PARSE_ERR("[a]\nk = \"a\\nb\"\n", "bad.ini:2:7: error: ", "unknown escape '\\n'");
  CHECK_PARSE_ERR("[a]\nk = \"abc\" def\n", "bad.ini:2:11: error: ", "unexpected 'd' after the quoted string");
  CHECK_PARSE_ERR("[a]\nk = ab\"c\n", "bad.ini:2:7: error: ", "'\"' inside an unquoted value");
  /* Section headers. */
  CHECK_PARSE_ERR("[a] junk\n", "bad.ini:1:5: error: ", "unexpected 'j' after section header [a]");
  CHECK_PARSE_ERR("[a]]\n", "bad.ini:1:4: error: ", "unexpected ']' after section header [a]");
  CHECK_PARSE_ERR("[a]\n[sc@ne]\n", "bad.ini:2:4: error: ", "invalid character '@' in section name");
  CHECK_PARSE_ERR("[a]\n[sc ne]\n", "bad.ini:2:5: error: ", "expected ']' after section name, found 'n'");
  CHECK_PARSE_ERR("[]\n", "bad.ini:1:2: error: ", "empty section name");
  CHECK_PARSE_ERR("[closure..drag]\n", "bad.ini:1:9: error: ", "empty part in dotted section name");
  CHECK_PARSE_ERR("[.drag]\n", "bad.ini:1:2: error: ", "empty part in dotted section name");
  CHECK_PARSE_ERR("[closure.]\n", "bad.ini:1:9: error: ", "empty part in dotted section name");
  /* Keys. */
  CHECK_PARSE_ERR("model = x\n[a]\n", "bad.ini:1:1: error: ", "key 'model' comes before any [section] header");
  CHECK_PARSE_ERR("[a]\ndrag.model = x\n", "bad.ini:2:5: error: ", "invalid character '.' in key");
  CHECK_PARSE_ERR("[a]\n\xC3\xA9t\xC3\xA9 = x\n", "bad.ini:2:1: error: ", "expected a key, a [section] header");
  CHECK_PARSE_ERR("[a]\nk\xC3\xA9 = x\n", "bad.ini:2:2: error: ", "invalid character '\xC3\xA9' in key");
  CHECK_PARSE_ERR("[a]\nx = 1\ninclude = b.ini\n",
                  "bad.ini:3:1: error: ", "'include' must come before the first [section] header");
  CHECK_PARSE_ERR("include =\n[a]\n", "bad.ini:1:10: error: ", "include needs a file name");
  /* Columns count characters, not bytes. */
  CHECK_PARSE_ERR("[a]\nk = \xE2\x86\x92\xE2\x86\x92 \"\n", "bad.ini:2:8: error: ", "'\"' inside an unquoted value");

  /* Reading files that are not there or not files. */
  CHECK_FILE_ERR(DIR "/does-not-exist.ini", DIR "/does-not-exist.ini: error: ", "No such file or directory");
  CHECK_FILE_ERR(DIR, DIR ": error: ", "cannot read configuration file");
  {
    sl_ini *ini = NULL;
    sl_diag d = {{0}};
    CHECK(sl_ini_parse_file(NULL, &ini, &d) == SL_EBADINPUT && ini == NULL);
  }
}

/* ---------------------------------------------------------------- includes */

static void test_includes(void) {
  write_file(DIR "/base.ini",
             "; the base scene\n"
             "[scene]\n"
             "model = mixture\n"
             "title = base\n"
             "[time]\n"
             "dt = 1e-3\n"
             "end = 10\n");
  write_file(DIR "/variants/fast.ini",
             "include = ../base.ini   ; relative to this file\n"
             "\n"
             "[time]\n"
             "dt = 1e-2\n"
             "[output]\n"
             "every = 5\n");
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = sl_ini_parse_file(DIR "/variants/fast.ini", &ini, &d);
  CHECK_MSG(rc == 0, "include failed: %s", d.msg);
  if (ini) {
    CHECK(ini->n_sections == 3);
    CHECK(strcmp(ini->sections[0].name, "scene") == 0);
    CHECK(strcmp(ini->sections[1].name, "time") == 0);
    CHECK(strcmp(ini->sections[2].name, "output") == 0);
    CHECK(strcmp(value_of(ini, "time", "dt"), "1e-2") == 0); /* the including file wins */
    CHECK(strcmp(value_of(ini, "time", "end"), "10") == 0);  /* the rest comes from the base */
    const sl_ini_entry *e = sl_ini_find(ini, "time", "dt");
    CHECK(e && strcmp(e->file, DIR "/variants/fast.ini") == 0 && e->line == 4);
    e = sl_ini_find(ini, "scene", "model");
    CHECK(e && strcmp(e->file, DIR "/variants/../base.ini") == 0 && e->line == 3);
    CHECK(ini->n_files == 2);
    CHECK(ini->n_files >= 1 && strcmp(ini->files[0], DIR "/variants/fast.ini") == 0);
    /* Provenance of range errors names the file the value came from. */
    double dt;
    rc = sl_ini_get_real(ini, "time", "end", 1, 0, 0, 5, &dt, &d);
    CHECK_ERR(rc, d, DIR "/variants/../base.ini:7:7: error: ", "[time] end = 10 is outside the allowed range [0, 5]");
  }
  sl_ini_free(ini);

  /* Two includes: the later one overrides the earlier one; diamonds are fine. */
  write_file(DIR "/left.ini", "include = base.ini\n[time]\ndt = 2\n[left]\nx = 1\n");
  write_file(DIR "/right.ini", "include = base.ini\n[time]\ndt = 3\n[right]\ny = 1\n");
  write_file(DIR "/top.ini", "include = left.ini\ninclude = \"right.ini\"\n[scene]\ntitle = top\n");
  ini = NULL;
  rc = sl_ini_parse_file(DIR "/top.ini", &ini, &d);
  CHECK_MSG(rc == 0, "diamond include failed: %s", d.msg);
  if (ini) {
    CHECK(strcmp(value_of(ini, "time", "dt"), "3") == 0);
    CHECK(strcmp(value_of(ini, "scene", "title"), "top") == 0);
    CHECK(strcmp(value_of(ini, "left", "x"), "1") == 0);
    CHECK(strcmp(value_of(ini, "right", "y"), "1") == 0);
    CHECK(ini->n_files == 4);
  }
  sl_ini_free(ini);

  /* Include from text in memory: relative to the name given. */
  ini = NULL;
  rc = parse_str("include = base.ini\n[time]\ndt = 5\n", DIR "/memory.ini", &ini, &d);
  CHECK_MSG(rc == 0, "include from a string failed: %s", d.msg);
  CHECK(ini && strcmp(value_of(ini, "time", "dt"), "5") == 0 &&
        strcmp(value_of(ini, "scene", "model"), "mixture") == 0);
  sl_ini_free(ini);

  /* Loops name the chain. */
  write_file(DIR "/loop_a.ini", "include = loop_b.ini\n[a]\nx = 1\n");
  write_file(DIR "/loop_b.ini", "; b\ninclude = loop_a.ini\n[b]\nx = 1\n");
  CHECK_FILE_ERR(DIR "/loop_a.ini", DIR "/loop_b.ini:2:11: error: ",
                 "include loop: " DIR "/loop_a.ini -> " DIR "/loop_b.ini -> " DIR "/loop_a.ini");
  write_file(DIR "/self.ini", "include = ./self.ini\n[a]\n");
  CHECK_FILE_ERR(DIR "/self.ini",
                 DIR "/self.ini:1:11: error: ", "include loop: " DIR "/self.ini -> " DIR "/./self.ini");

  /* Depth limit 16: sixteen nested includes are fine, seventeen are not. */
  for (int i = 0; i <= 17; ++i) {
    char path[64], text[128];
    snprintf(path, sizeof path, DIR "/depth_%d.ini", i);
    if (i < 17) snprintf(text, sizeof text, "include = depth_%d.ini\n[d%d]\nx = %d\n", i + 1, i, i);
    else snprintf(text, sizeof text, "[d%d]\nx = %d\n", i, i);
    write_file(path, text);
  }
  ini = NULL;
  rc = sl_ini_parse_file(DIR "/depth_1.ini", &ini, &d);
  CHECK_MSG(rc == 0, "16 nested includes refused: %s", d.msg);
  CHECK(ini && ini->n_sections == 17 && strcmp(ini->sections[0].name, "d17") == 0);
  sl_ini_free(ini);
  CHECK_FILE_ERR(DIR "/depth_0.ini", DIR "/depth_16.ini:1:11: error: ", "includes are nested more than 16 deep: ");

  /* A missing include, and an error inside an included file, point at the right file. */
  write_file(DIR "/missing_inc.ini", "# x\ninclude = nothere.ini\n[a]\n");
  CHECK_FILE_ERR(DIR "/missing_inc.ini", DIR "/missing_inc.ini:2:11: error: ",
                 "cannot read included file '" DIR "/nothere.ini': No such file or directory");
  write_file(DIR "/broken.ini", "[a]\nx = 1\nx = 2\n");
  write_file(DIR "/uses_broken.ini", "include = broken.ini\n[b]\n");
  CHECK_FILE_ERR(DIR "/uses_broken.ini",
                 DIR "/broken.ini:3:1: error: ", "duplicate key 'x' in [a] (first set at line 2)");
  write_file(DIR "/inc_dir.ini", "include = variants\n[b]\n");
  CHECK_FILE_ERR(DIR "/inc_dir.ini", DIR "/inc_dir.ini:1:11: error: ", "cannot read included file");
  write_file(DIR "/only_comments.ini", "; nothing\n");
  write_file(DIR "/uses_only_comments.ini", "include = only_comments.ini\n[b]\n");
  CHECK_FILE_ERR(DIR "/uses_only_comments.ini", DIR "/only_comments.ini:1:1: error: ", "no sections");
  /* Keys of one section may repeat across files, not within the including one. */
  write_file(DIR "/dup_after_inc.ini", "include = base.ini\n[time]\ndt = 1\ndt = 2\n");
  CHECK_FILE_ERR(DIR "/dup_after_inc.ini", DIR "/dup_after_inc.ini:4:1: error: ", "duplicate key 'dt'");
}

/* ----------------------------------------------------------- typed getters */

static const char *scene_text =
    "[scene]\n"                    /* 1 */
    "model = mixture\n"            /* 2 */
    "\n"                           /* 3 */
    "[mesh]\n"                     /* 4 */
    "nx = 10\n"                    /* 5 */
    "ny = abc\n"                   /* 6 */
    "sizes = 1, x, 3\n"            /* 7 */
    "\n"                           /* 8 */
    "[time]\n"                     /* 9 */
    "end = 5\n"                    /* 10 */
    "adaptive = maybe\n"           /* 11 */
    "dt  = -1\n"                   /* 12 */
    "empty =\n"                    /* 13 */
    "scheme = bdf3\n"              /* 14 */
    "big = 99999999999999999999\n" /* 15 */
    "name = \"bdf2\"\n"            /* 16 */
    "on = ON\n"                    /* 17 */
    "list = 1,,2\n"                /* 18 */
    "tol = 1e-3\n"                 /* 19 */
    "huge = 1e999\n"               /* 20 */
    "word = inf\n";                /* 21 */

static void test_getters(void) {
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = parse_str(scene_text, "scene.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (!ini) return;
  double x = 0;
  long l = 0;
  int b = -1, c = -1, n = -1;
  const char *s = NULL;
  double v[8];

  /* The example, exactly. */
  rc = sl_ini_get_real(ini, "time", "dt", 1, 0, 1e-12, 1e6, &x, &d);
  CHECK(rc == SL_EBADINPUT);
  CHECK_MSG(strcmp(d.msg, "scene.ini:12:7: error: [time] dt = -1 is outside the allowed range [1e-12, 1e6]") == 0,
            "got \"%s\"", d.msg);

  CHECK(sl_ini_get_real(ini, "time", "end", 1, 0, 0, 100, &x, &d) == 0);
  CHECK_CLOSE(x, 5.0, 0);
  CHECK(sl_ini_get_real(ini, "time", "tol", 1, 0, 0, 1, &x, &d) == 0);
  CHECK_CLOSE(x, 1e-3, 1e-15);
  /* Defaults when absent and not required; the default is not range-checked. */
  x = 0;
  CHECK(sl_ini_get_real(ini, "time", "missing", 0, 0.25, 0, 1, &x, &d) == 0);
  CHECK_CLOSE(x, 0.25, 0);
  CHECK(sl_ini_get_real(ini, "nosection", "missing", 0, 7.5, 0, 1, &x, &d) == 0);
  CHECK_CLOSE(x, 7.5, 0);
  CHECK(sl_ini_get_int(ini, "mesh", "nz", 0, 3, 1, 10, &l, &d) == 0 && l == 3);
  CHECK(sl_ini_get_bool(ini, "mesh", "flag", 0, 1, &b, &d) == 0 && b == 1);
  CHECK(sl_ini_get_string(ini, "mesh", "label", 0, "none", &s, &d) == 0 && s && strcmp(s, "none") == 0);
  CHECK(sl_ini_get_choice(ini, "mesh", "kind", 0, 2, "a|b|c", &c, &d) == 0 && c == 2);
  CHECK(sl_ini_get_real_list(ini, "mesh", "other", 0, v, 8, &n, &d) == 0 && n == 0);

  /* Required but absent. */
  rc = sl_ini_get_real(ini, "time", "tolerance", 1, 0, 0, 1, &x, &d);
  CHECK_ERR(rc, d, "scene.ini:9:1: error: ", "[time] is missing the required key 'tolerance'");
  rc = sl_ini_get_string(ini, "output", "file", 1, NULL, &s, &d);
  CHECK_ERR(rc, d, "scene.ini: error: ", "missing section [output] (it needs the key 'file')");

  /* Bad numbers say what was expected. */
  rc = sl_ini_get_int(ini, "mesh", "ny", 1, 0, 0, 100, &l, &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "scene.ini:6:6: error: [mesh] ny = abc: expected an integer") == 0,
            "got \"%s\"", d.msg);
  rc = sl_ini_get_real(ini, "mesh", "ny", 1, 0, 0, 100, &x, &d);
  CHECK_ERR(rc, d, "scene.ini:6:6: error: ", "[mesh] ny = abc: expected a real number");
  rc = sl_ini_get_int(ini, "time", "tol", 1, 0, 0, 100, &l, &d);
  CHECK_ERR(rc, d, "scene.ini:19:7: error: ", "[time] tol = 1e-3: expected an integer");
  rc = sl_ini_get_int(ini, "time", "big", 1, 0, 0, 100, &l, &d);
  CHECK_ERR(rc, d, "scene.ini:15:7: error: ", "expected an integer");
  rc = sl_ini_get_real(ini, "time", "huge", 1, 0, 0, 100, &x, &d);
  CHECK_ERR(rc, d, "scene.ini:20:8: error: ", "[time] huge = 1e999: expected a real number");
  rc = sl_ini_get_real(ini, "time", "word", 1, 0, 0, 100, &x, &d);
  CHECK_ERR(rc, d, "scene.ini:21:8: error: ", "expected a real number");
  rc = sl_ini_get_bool(ini, "time", "adaptive", 1, 0, &b, &d);
  CHECK_ERR(rc, d, "scene.ini:11:12: error: ",
            "[time] adaptive = maybe: expected a boolean (true/false, yes/no, on/off, 1/0)");
  CHECK(sl_ini_get_bool(ini, "time", "on", 1, 0, &b, &d) == 0 && b == 1);
  rc = sl_ini_get_int(ini, "mesh", "nx", 1, 0, 11, 20, &l, &d);
  CHECK_MSG(rc == SL_EBADINPUT &&
                strcmp(d.msg, "scene.ini:5:6: error: [mesh] nx = 10 is outside the allowed range [11, 20]") == 0,
            "got \"%s\"", d.msg);
  CHECK(sl_ini_get_int(ini, "mesh", "nx", 1, 0, 1, 20, &l, &d) == 0 && l == 10);

  /* Empty values where one is required. */
  rc = sl_ini_get_real(ini, "time", "empty", 0, 1.0, 0, 10, &x, &d);
  CHECK_MSG(rc == SL_EBADINPUT &&
                strcmp(d.msg, "scene.ini:13:8: error: [time] empty has no value; expected a real number") == 0,
            "got \"%s\"", d.msg);
  rc = sl_ini_get_int(ini, "time", "empty", 1, 0, 0, 10, &l, &d);
  CHECK_ERR(rc, d, "scene.ini:13:8: error: ", "expected an integer");
  rc = sl_ini_get_bool(ini, "time", "empty", 1, 0, &b, &d);
  CHECK_ERR(rc, d, "scene.ini:13:8: error: ", "expected a boolean");
  rc = sl_ini_get_string(ini, "time", "empty", 1, NULL, &s, &d);
  CHECK_ERR(rc, d, "scene.ini:13:8: error: ", "[time] empty has no value; expected a string");
  rc = sl_ini_get_choice(ini, "time", "empty", 1, 0, "bdf1|bdf2", &c, &d);
  CHECK_ERR(rc, d, "scene.ini:13:8: error: ", "expected one of: bdf1, bdf2");
  rc = sl_ini_get_real_list(ini, "time", "empty", 1, v, 8, &n, &d);
  CHECK_ERR(rc, d, "scene.ini:13:8: error: ", "expected a comma-separated list of real numbers");

  /* Choices, with a did-you-mean. */
  rc = sl_ini_get_choice(ini, "time", "scheme", 1, 0, "bdf1|bdf2|steady", &c, &d);
  CHECK_MSG(
      rc == SL_EBADINPUT && strcmp(d.msg,
                                   "scene.ini:14:10: error: [time] scheme = bdf3 is not one of: bdf1, bdf2, steady; "
                                   "did you mean 'bdf1'?") == 0,
      "got \"%s\"", d.msg);
  rc = sl_ini_get_choice(ini, "scene", "model", 1, 0, "navier_stokes|two_fluid", &c, &d);
  CHECK_ERR(rc, d, "scene.ini:2:9: error: ", "[scene] model = mixture is not one of: navier_stokes, two_fluid");
  CHECK(strstr(d.msg, "did you mean") == NULL);
  CHECK(sl_ini_get_choice(ini, "time", "name", 1, 0, "bdf1|bdf2|steady", &c, &d) == 0 && c == 1);
  CHECK(sl_ini_get_choice(ini, "scene", "model", 1, 0, "navier_stokes|mixture|two_fluid", &c, &d) == 0 && c == 1);

  /* Lists: the bad item is pointed at. */
  rc = sl_ini_get_real_list(ini, "mesh", "sizes", 1, v, 8, &n, &d);
  CHECK_MSG(rc == SL_EBADINPUT &&
                strcmp(d.msg,
                       "scene.ini:7:12: error: [mesh] sizes = 1, x, 3: item 2 ('x') is not a real number or a constant "
                       "expression: column 1: unknown name 'x' (this value takes no variables)") == 0,
            "got \"%s\"", d.msg);
  rc = sl_ini_get_real_list(ini, "time", "list", 1, v, 8, &n, &d);
  CHECK_ERR(rc, d, "scene.ini:18:10: error: ", "[time] list = 1,,2: item 2 is empty");
  rc = sl_ini_get_real_list(ini, "time", "tol", 1, v, 0, &n, &d);
  CHECK_ERR(rc, d, "scene.ini:19:7: error: ", "more than 0 values");
  CHECK(sl_ini_get_real_list(ini, "time", "end", 1, v, 1, &n, &d) == 0 && n == 1);

  /* Getters mark what they read; the rest can be reported as unused. */
  CHECK(sl_ini_find(ini, "time", "end")->used == 1);
  CHECK(sl_ini_find(ini, "scene", "model")->used == 1);
  CHECK(sl_ini_find(ini, "time", "on")->used == 1);
  CHECK(sl_ini_find(ini, "mesh", "nx")->used == 1);
  sl_ini_free(ini);

  /* Shared number parsing. */
  double r;
  long li;
  int bo;
  CHECK(sl_parse_real("1e-3", &r) == 0 && r == 1e-3);
  CHECK(sl_parse_real("-.5", &r) == 0 && r == -0.5);
  CHECK(sl_parse_real("+2.", &r) == 0 && r == 2.0);
  CHECK(sl_parse_real("", &r) != 0);
  CHECK(sl_parse_real(" 1", &r) != 0);
  CHECK(sl_parse_real("1 ", &r) != 0);
  CHECK(sl_parse_real("nan", &r) != 0);
  CHECK(sl_parse_real("inf", &r) != 0);
  CHECK(sl_parse_real("0x10", &r) != 0);
  CHECK(sl_parse_real("1e999", &r) != 0);
  CHECK(sl_parse_real("1e", &r) != 0);
  CHECK(sl_parse_real("1,5", &r) != 0);
  CHECK(sl_parse_long("-42", &li) == 0 && li == -42);
  CHECK(sl_parse_long("4.0", &li) != 0);
  CHECK(sl_parse_long("1e3", &li) != 0);
  CHECK(sl_parse_long("", &li) != 0);
  CHECK(sl_parse_long("99999999999999999999", &li) != 0);
  const char *yes[] = {"true", "yes", "on", "1", "TRUE", "Yes"}, *no[] = {"false", "no", "off", "0", "Off"};
  for (size_t i = 0; i < sizeof yes / sizeof *yes; ++i) CHECK(sl_parse_bool(yes[i], &bo) == 0 && bo == 1);
  for (size_t i = 0; i < sizeof no / sizeof *no; ++i) CHECK(sl_parse_bool(no[i], &bo) == 0 && bo == 0);
  CHECK(sl_parse_bool("y", &bo) != 0);
  CHECK(sl_parse_bool("", &bo) != 0);
  CHECK(sl_parse_bool("truee", &bo) != 0);
}

/* ------------------------------------------------------- unknown names */

static void test_unknown(void) {
  const char *text =
      "[scene]\n"
      "model = mixture\n"
      "[time]\n"
      "dt = 1\n"
      "  dtt = 2\n"
      "[closure.drag]\n"
      "model = ergun\n"
      "[scnee]\n"
      "[clousre.drag]\n"
      "[zzzzzz]\n";
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = parse_str(text, "u.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (!ini) return;
  const char *known[] = {"scene", "time", "mesh", "scnee", "clousre.drag", "zzzzzz"};
  const char *prefixes[] = {"closure.", "boundary."};
  CHECK(sl_ini_check_sections(ini, known, 6, prefixes, 2, &d) == 0);
  rc = sl_ini_check_sections(ini, known, 3, prefixes, 2, &d);
  CHECK_MSG(
      rc == SL_EBADINPUT && strcmp(d.msg, "u.ini:8:1: error: unknown section [scnee]; did you mean [scene]?") == 0,
      "got \"%s\"", d.msg);
  const char *known2[] = {"scene", "time", "mesh", "scnee"};
  rc = sl_ini_check_sections(ini, known2, 4, prefixes, 2, &d);
  CHECK_MSG(rc == SL_EBADINPUT &&
                strcmp(d.msg, "u.ini:9:1: error: unknown section [clousre.drag]; did you mean [closure.drag]?") == 0,
            "got \"%s\"", d.msg);
  const char *known3[] = {"scene", "time", "mesh", "scnee", "clousre.drag"};
  rc = sl_ini_check_sections(ini, known3, 5, prefixes, 2, &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "u.ini:10:1: error: unknown section [zzzzzz]") == 0, "got \"%s\"",
            d.msg);
  /* "closure." alone is not a prefix match: a name must follow it. */
  rc = sl_ini_check_sections(ini, known3, 5, NULL, 0, &d);
  CHECK_ERR(rc, d, "u.ini:6:1: error: ", "unknown section [closure.drag]");

  const char *time_keys[] = {"dt", "end", "scheme"};
  rc = sl_ini_check_keys(ini, "time", time_keys, 3, &d);
  CHECK_MSG(
      rc == SL_EBADINPUT && strcmp(d.msg, "u.ini:5:3: error: unknown key 'dtt' in [time]; did you mean 'dt'?") == 0,
      "got \"%s\"", d.msg);
  const char *drag_keys[] = {"correlation", "n"};
  rc = sl_ini_check_keys(ini, "closure.drag", drag_keys, 2, &d);
  CHECK_MSG(
      rc == SL_EBADINPUT &&
          strcmp(d.msg, "u.ini:7:1: error: unknown key 'model' in [closure.drag] (known keys: correlation, n)") == 0,
      "got \"%s\"", d.msg);
  const char *scene_keys[] = {"model", "title"};
  CHECK(sl_ini_check_keys(ini, "scene", scene_keys, 2, &d) == 0);
  CHECK(sl_ini_check_keys(ini, "absent", scene_keys, 2, &d) == 0);
  sl_ini_free(ini);
}

/* --------------------------------------------------------------- overrides */

static void test_overrides(void) {
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = parse_str("[time]\ndt = 1e-3\n[closure.drag]\nmodel = ergun\n", "o.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (!ini) return;
  CHECK(sl_ini_apply_override(ini, "closure.drag.model=wen_yu", &d) == 0);
  CHECK(strcmp(value_of(ini, "closure.drag", "model"), "wen_yu") == 0);
  const sl_ini_entry *e = sl_ini_find(ini, "closure.drag", "model");
  CHECK(e && strcmp(e->file, "<command line>") == 0 && e->line == 0);
  CHECK(sl_ini_apply_override(ini, "time.dt=2e-3", &d) == 0);
  CHECK(strcmp(value_of(ini, "time", "dt"), "2e-3") == 0);
  CHECK(sl_ini_find_section(ini, "time")->n_entries == 1);
  /* New keys and new (dotted) sections are created; blanks and quotes as in a file. */
  CHECK(sl_ini_apply_override(ini, "time.end = 10", &d) == 0);
  CHECK(strcmp(value_of(ini, "time", "end"), "10") == 0);
  CHECK(sl_ini_apply_override(ini, "closure.hindered_settling.n=4.65", &d) == 0);
  CHECK(strcmp(value_of(ini, "closure.hindered_settling", "n"), "4.65") == 0);
  CHECK(sl_ini_apply_override(ini, "output.title=\"run \\\"A\\\"; v2\"", &d) == 0);
  CHECK(strcmp(value_of(ini, "output", "title"), "run \"A\"; v2") == 0);
  CHECK(sl_ini_apply_override(ini, "output.note=a;b#c", &d) == 0); /* no comments on the command line */
  CHECK(strcmp(value_of(ini, "output", "note"), "a;b#c") == 0);
  CHECK(sl_ini_apply_override(ini, "output.empty=", &d) == 0);
  CHECK(strcmp(value_of(ini, "output", "empty"), "") == 0);
  CHECK(ini->n_sections == 4);
  CHECK(strcmp(ini->sections[3].name, "output") == 0 && ini->sections[3].line == 0);

  /* Diagnostics about an overridden value name the command line. */
  CHECK(sl_ini_apply_override(ini, "time.dt=-5", &d) == 0);
  double x;
  rc = sl_ini_get_real(ini, "time", "dt", 1, 0, 1e-12, 1e6, &x, &d);
  CHECK_MSG(rc == SL_EBADINPUT &&
                strcmp(d.msg, "<command line>: error: [time] dt = -5 is outside the allowed range [1e-12, 1e6]") == 0,
            "got \"%s\"", d.msg);
  const char *known[] = {"time"};
  const char *prefixes[] = {"closure."};
  rc = sl_ini_check_sections(ini, known, 1, prefixes, 1, &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "<command line>: error: unknown section [output]") == 0, "got \"%s\"",
            d.msg);

  /* Malformed overrides name the text. */
  rc = sl_ini_apply_override(ini, "closure.drag", &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "--set closure.drag: expected section.key=value") == 0, "got \"%s\"",
            d.msg);
  rc = sl_ini_apply_override(ini, "nodot=1", &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "--set nodot=1: expected section.key=value") == 0, "got \"%s\"", d.msg);
  rc = sl_ini_apply_override(ini, "time.=1", &d);
  CHECK_MSG(rc == SL_EBADINPUT && strcmp(d.msg, "--set time.=1: expected section.key=value") == 0, "got \"%s\"", d.msg);
  rc = sl_ini_apply_override(ini, ".dt=1", &d);
  CHECK_ERR(rc, d, "--set .dt=1: ", "expected section.key=value");
  rc = sl_ini_apply_override(ini, "=1", &d);
  CHECK_ERR(rc, d, "--set =1: ", "expected section.key=value");
  rc = sl_ini_apply_override(ini, "", &d);
  CHECK_ERR(rc, d, "--set : ", "expected section.key=value");
  rc = sl_ini_apply_override(ini, "ti me.dt=1", &d);
  CHECK_ERR(rc, d, "--set ti me.dt=1: ", "invalid character in section name");
  rc = sl_ini_apply_override(ini, "a..b.c=1", &d);
  CHECK_ERR(rc, d, "--set a..b.c=1: ", "empty part in dotted section name");
  rc = sl_ini_apply_override(ini, "time.d@t=1", &d);
  CHECK_ERR(rc, d, "--set time.d@t=1: ", "invalid character in key");
  rc = sl_ini_apply_override(ini, "time.dt=\"1", &d);
  CHECK_ERR(rc, d, "--set time.dt=\"1: ", "unterminated quoted value");
  rc = sl_ini_apply_override(ini, "time.dt=\"1\" 2", &d);
  CHECK_ERR(rc, d, "--set time.dt=\"1\" 2: ", "unexpected text after the quoted value");
  rc = sl_ini_apply_override(ini, "time.dt=a\x01", &d);
  CHECK_ERR(rc, d, "--set time.dt=a\x01: ", "control character 0x01");
  rc = sl_ini_apply_override(ini, "time.include=x.ini", &d);
  CHECK_ERR(rc, d, "--set time.include=x.ini: ", "'include' cannot be set");
  CHECK(strcmp(value_of(ini, "time", "dt"), "-5") == 0); /* failures change nothing */
  sl_ini_free(ini);
}

/* -------------------------------------------------------------- round trip */

/* Same sections, keys and values, in the same order. */
static int same_config(const sl_ini *a, const sl_ini *b) {
  if (a->n_sections != b->n_sections) return 0;
  for (int i = 0; i < a->n_sections; ++i) {
    const sl_ini_section *x = &a->sections[i], *y = &b->sections[i];
    if (strcmp(x->name, y->name) != 0 || x->n_entries != y->n_entries) return 0;
    for (int j = 0; j < x->n_entries; ++j)
      if (strcmp(x->entries[j].key, y->entries[j].key) != 0 || strcmp(x->entries[j].value, y->entries[j].value) != 0)
        return 0;
  }
  return 1;
}

static void round_trip(const sl_ini *ini, const char *what) {
  char *text = sl_ini_to_string(ini);
  CHECK(text != NULL);
  if (!text) return;
  sl_ini *again = NULL;
  sl_diag d = {{0}};
  int rc = sl_ini_parse_string(text, strlen(text), "written.ini", &again, &d);
  CHECK_MSG(rc == 0, "%s: the written INI does not parse: %s", what, d.msg);
  CHECK_MSG(again && same_config(ini, again), "%s: round trip changed the configuration:\n%.2000s", what, text);
  /* Writing is stable: the second generation is byte-identical. */
  char *text2 = again ? sl_ini_to_string(again) : NULL;
  CHECK(text2 && strcmp(text, text2) == 0);
  free(text2);
  sl_ini_free(again);
  free(text);
}

static void test_round_trip(void) {
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  int rc = parse_str(
      "[scene]\n"
      "model = mixture ; c\n"
      "title = \"  padded ; with # and \\\"quotes\\\" and \\\\ \"\n"
      "path = C:\\dir\\file\n"
      "empty_quoted = \"\"\n"
      "empty =\n"
      "unicode = \xC3\xA9t\xC3\xA9\n"
      "[closure.drag]\n"
      "model = ergun\n"
      "[nothing]\n"
      "[mesh]\n"
      "sizes = 1, 2, 3\n"
      "tab = \"a\tb\t\"\n",
      "rt.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (!ini) return;
  CHECK(sl_ini_apply_override(ini, "closure.drag.n=4.65", &d) == 0);
  CHECK(sl_ini_apply_override(ini, "extra.sec.v=x;y # z", &d) == 0);
  CHECK(sl_ini_apply_override(ini, "extra.sec.q=  \"  lead\"", &d) == 0);
  round_trip(ini, "mixed");

  /* The expected text for a simple case. */
  char *text = sl_ini_to_string(ini);
  CHECK(text != NULL);
  if (text) {
    CHECK_CONTAINS(text, "[scene]\nmodel = mixture\ntitle = \"  padded ; with # and \\\"quotes\\\" and \\\\ \"\n");
    CHECK_CONTAINS(text, "path = C:\\dir\\file\n");
    CHECK_CONTAINS(text, "empty_quoted = \"\"\nempty =\n");
    CHECK_CONTAINS(text, "\n\n[closure.drag]\nmodel = ergun\nn = 4.65\n\n[nothing]\n\n[mesh]\n");
    CHECK_CONTAINS(text, "[extra.sec]\nv = \"x;y # z\"\nq = \"  lead\"\n");
    /* sl_ini_write gives the same text. */
    FILE *f = tmpfile();
    CHECK(f != NULL);
    if (f) {
      CHECK(sl_ini_write(ini, f) == 0);
      long size = ftell(f);
      CHECK(size == (long)strlen(text));
      rewind(f);
      char *back = malloc((size_t)size + 1);
      if (back) {
        size_t got = fread(back, 1, (size_t)size, f);
        back[got] = '\0';
        CHECK(strcmp(back, text) == 0);
        free(back);
      }
      fclose(f);
    }
    free(text);
  }
  sl_ini_free(ini);

  /* Includes are flattened in the written form. */
  ini = NULL;
  rc = sl_ini_parse_file(DIR "/top.ini", &ini, &d);
  CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
  if (ini) round_trip(ini, "includes");
  sl_ini_free(ini);

  /* A 64 KiB line full of escapes still reads back after writing. */
  size_t n = 65536;
  char *t = malloc(n + 8);
  CHECK(t != NULL);
  if (t) {
    memcpy(t, "[a]\nk=\"", 7);
    memset(t + 7, '\\', n - 4);
    t[4 + n - 1] = '"';
    ini = NULL;
    rc = sl_ini_parse_string(t, 4 + n, "long.ini", &ini, &d);
    CHECK_MSG(rc == 0, "parse failed: %s", d.msg);
    if (ini) round_trip(ini, "long line");
    sl_ini_free(ini);
    free(t);
  }
}

/* Numbers written as constant expressions: exact values where the arithmetic is exact, the expression's own
 * error (with a did-you-mean) when it does not parse, refusal when the value is not finite; list items split at
 * commas outside parentheses. */
static void test_constant_expressions(void) {
  double v = 0.0;
  char why[200];
  CHECK(sl_parse_real_expr("0.125", &v, why, sizeof why) == 0 && v == 0.125);
  CHECK(sl_parse_real_expr("2*pi", &v, why, sizeof why) == 0 && v == 2.0 * 3.14159265358979323846);
  CHECK(sl_parse_real_expr("10^-4", &v, why, sizeof why) == 0 && v == 1e-4);
  CHECK(sl_parse_real_expr("3/4 + 1/8", &v, why, sizeof why) == 0 && v == 0.875);
  CHECK(sl_parse_real_expr("2*pie", &v, why, sizeof why) == SL_EBADINPUT && strstr(why, "did you mean 'pi'"));
  CHECK(sl_parse_real_expr("1/0", &v, why, sizeof why) == SL_EBADINPUT && strstr(why, "not finite"));
  CHECK(sl_parse_real_expr("x + 1", &v, why, sizeof why) == SL_EBADINPUT && strstr(why, "unknown name 'x'"));
  sl_ini *ini = NULL;
  sl_diag d = {{0}};
  CHECK(parse_str("[mesh]\nx = -pi, atan2(1, 1)*4, 2^3\nh = sqrt(2)/2\nbad = 1, 2*e3\n", "expr.ini", &ini, &d) == 0);
  double xs[4];
  int n = 0;
  CHECK(sl_ini_get_real_list(ini, "mesh", "x", 1, xs, 4, &n, &d) == 0 && n == 3);
  CHECK(n == 3 && xs[0] == -3.14159265358979323846 && xs[1] == 3.14159265358979323846 && xs[2] == 8.0);
  CHECK(sl_ini_get_real(ini, "mesh", "h", 1, 0.0, 0.0, 1.0, &v, &d) == 0 && v == sqrt(2.0) / 2.0);
  int rc = sl_ini_get_real_list(ini, "mesh", "bad", 1, xs, 4, &n, &d);
  CHECK_MSG(rc == SL_EBADINPUT && strstr(d.msg, "expr.ini:4:") && strstr(d.msg, "item 2 ('2*e3')") &&
                strstr(d.msg, "unknown name 'e3'"),
            "%s", d.msg);
  sl_ini_free(ini);
}

int main(void) {
  mkdir(DIR, 0777); /* may exist from an earlier run */
  mkdir(DIR "/variants", 0777);
  test_syntax();
  test_malformed();
  test_includes();
  test_getters();
  test_unknown();
  test_overrides();
  test_round_trip();
  test_constant_expressions();
  return sl_test_summary();
}
