/* SPDX-License-Identifier: GPL-2.0-or-later */
/* libFuzzer target for the INI parser. Any input must parse or fail cleanly
 * (no crash, leak or UB under ASan+UBSan). Inputs that parse must also
 * survive the write/re-parse round trip unchanged: that property is cheap to
 * check here and catches quoting bugs in the writer. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/config/ini.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  sl_ini *ini = NULL;
  sl_diag d;
  /* "fuzz.ini": relative includes resolve in the working directory. */
  if (sl_ini_parse_string((const char *)data, size, "fuzz.ini", &ini, &d) != 0) {
    if (ini) abort(); /* a failed parse must not hand anything out */
    return 0;
  }
  char *text = sl_ini_to_string(ini);
  if (text) {
    sl_ini *again = NULL;
    if (sl_ini_parse_string(text, strlen(text), "written.ini", &again, &d) != 0 || !same_config(ini, again)) abort();
    sl_ini_free(again);
    free(text);
  }
  sl_ini_free(ini);
  return 0;
}
