/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Look-ups in a model's schema and its description (schema.h). */
#include "core/scene/schema.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* [section], or [section.NAME] for a key of a named family (SL_KEY_NAMED) */
static int section_matches(const sl_key *k, const char *section) {
  if (strcmp(k->section, section) == 0) return 1;
  size_t n = strlen(k->section);
  return (k->flags & SL_KEY_NAMED) && strncmp(section, k->section, n) == 0 && section[n] == '.' && section[n + 1];
}

const sl_key *sl_schema_key(const sl_schema *s, const char *section, const char *name) {
  for (int t = 0; t < s->n_tables; ++t)
    for (int i = 0; i < s->tables[t]->n; ++i) {
      const sl_key *k = &s->tables[t]->keys[i];
      if (section_matches(k, section) && strcmp(k->name, name) == 0) return k;
    }
  return NULL;
}

int sl_schema_has_section(const sl_schema *s, const char *section) {
  for (int t = 0; t < s->n_tables; ++t)
    for (int i = 0; i < s->tables[t]->n; ++i)
      if (section_matches(&s->tables[t]->keys[i], section)) return 1;
  return 0;
}

const sl_role *sl_schema_role(const sl_schema *s, const char *role) {
  for (int r = 0; r < s->n_roles; ++r)
    if (strcmp(s->roles[r].role, role) == 0) return &s->roles[r];
  return NULL;
}

/* The k-th choice of "a|b|c" into buf. */
static const char *choice_name(const char *choices, int k, char *buf, size_t len) {
  const char *p = choices ? choices : "";
  for (int i = 0; i < k && p; ++i) {
    p = strchr(p, '|');
    if (p) ++p;
  }
  if (!p) p = "";
  const char *q = strchr(p, '|');
  snprintf(buf, len, "%.*s", q ? (int)(q - p) : (int)strlen(p), p);
  return buf;
}

void sl_key_default_text(const sl_key *k, char *buf, size_t len) {
  if (k->flags & SL_KEY_REQUIRED) {
    snprintf(buf, len, "required");
    return;
  }
  if (k->def_doc) {
    snprintf(buf, len, "%s", k->def_doc);
    return;
  }
  switch (k->type) {
    case SL_KEY_REAL:
      snprintf(buf, len, "%g", k->def);
      return;
    case SL_KEY_INT:
      snprintf(buf, len, "%.15g", k->def);
      return;
    case SL_KEY_BOOL:
      snprintf(buf, len, "%s", k->def != 0.0 ? "true" : "false");
      return;
    case SL_KEY_CHOICE:
      choice_name(k->choices, (int)k->def, buf, len);
      return;
    case SL_KEY_REALS: {
      if (k->n_def == 0) {
        snprintf(buf, len, "none");
        return;
      }
      size_t at = 0;
      for (int i = 0; i < k->n_def && at < len; ++i)
        at += (size_t)snprintf(buf + at, len - at, "%s%g", i ? ", " : "", k->def_list[i]);
      return;
    }
    case SL_KEY_STRING:
    case SL_KEY_EXPR:
    case SL_KEY_EXPRS:
      snprintf(buf, len, "%s", k->def_text && *k->def_text ? k->def_text : "none");
      return;
  }
}

void sl_key_range_text(const sl_key *k, char *buf, size_t len) {
  switch (k->type) {
    case SL_KEY_REAL:
      snprintf(buf, len, "real in [%g, %g]", k->min, k->max);
      return;
    case SL_KEY_INT:
      snprintf(buf, len, "integer in [%.15g, %.15g]", k->min, k->max);
      return;
    case SL_KEY_BOOL:
      snprintf(buf, len, "true | false");
      return;
    case SL_KEY_CHOICE:
      snprintf(buf, len, "%s", k->choices);
      return;
    case SL_KEY_STRING:
      snprintf(buf, len, "text");
      return;
    case SL_KEY_REALS:
      if (k->min == 0.0 && k->max == 0.0) snprintf(buf, len, "up to %d reals", k->max_n);
      else snprintf(buf, len, "up to %d reals in [%g, %g]", k->max_n, k->min, k->max);
      return;
    case SL_KEY_EXPR:
      snprintf(buf, len, "expression of %s", k->vars && *k->vars ? k->vars : "nothing (a number)");
      return;
    case SL_KEY_EXPRS:
      snprintf(buf, len, "up to %d expressions of %s", k->max_n, k->vars && *k->vars ? k->vars : "nothing");
      return;
  }
}

/* The type choices a boundary key applies to, "inlet, outlet" (all: "any"). */
static void when_text(const sl_schema *s, const sl_key *k, char *buf, size_t len) {
  const sl_key *type = sl_schema_key(s, "boundary", "type");
  if (!k->when_type || !type || k == type) {
    snprintf(buf, len, "any");
    return;
  }
  size_t at = 0;
  buf[0] = '\0';
  for (int c = 0; c < 31 && at < len; ++c) {
    if (!(k->when_type & (1u << c))) continue;
    char name[64];
    choice_name(type->choices, c, name, sizeof name);
    if (!*name) break;
    at += (size_t)snprintf(buf + at, len - at, "%s%s", at ? ", " : "", name);
  }
}

static void md_escape(FILE *f, const char *s) {
  for (; s && *s; ++s) {
    if (*s == '|') fputs("\\|", f);
    else fputc(*s, f);
  }
}

void sl_schema_describe(const sl_schema *s, FILE *f, int markdown) {
  const char *sections[64];
  int n_sections = 0;
  for (int t = 0; t < s->n_tables; ++t)
    for (int i = 0; i < s->tables[t]->n; ++i) {
      const char *sec = s->tables[t]->keys[i].section;
      int seen = 0;
      for (int j = 0; j < n_sections && !seen; ++j) seen = strcmp(sections[j], sec) == 0;
      if (!seen && n_sections < 64) sections[n_sections++] = sec;
    }
  if (markdown) {
    fprintf(f, "# Model `%s`%s%s%s\n\n", s->model, s->variant ? " (" : "", s->variant ? s->variant : "",
            s->variant ? ")" : "");
    fprintf(f, "%s\n\n", s->title);
    if (s->summary) fprintf(f, "%s\n\n", s->summary);
    fprintf(f,
            "Generated by `sluice model describe %s%s%s --markdown` from the model's schema: the defaults, "
            "units and ranges below are the ones the code uses.\n\n",
            s->model, s->variant ? " --variant " : "", s->variant ? s->variant : "");
  } else {
    fprintf(f, "model %s%s%s%s: %s\n", s->model, s->variant ? " (" : "", s->variant ? s->variant : "",
            s->variant ? ")" : "", s->title);
  }
  for (int j = 0; j < n_sections; ++j) {
    const char *sec = sections[j];
    int boundary = strcmp(sec, "boundary") == 0;
    if (markdown) {
      fprintf(f, "## [%s]\n\n", boundary ? "boundary.NAME" : sec);
      fprintf(f, "| key | type | default | units |%s description |\n|---|---|---|---|%s---|\n",
              boundary ? " types |" : "", boundary ? "---|" : "");
    } else {
      fprintf(f, "\n[%s]\n", boundary ? "boundary.NAME" : sec);
    }
    for (int t = 0; t < s->n_tables; ++t)
      for (int i = 0; i < s->tables[t]->n; ++i) {
        const sl_key *k = &s->tables[t]->keys[i];
        if (strcmp(k->section, sec) != 0) continue;
        char def[256], range[512], when[256];
        sl_key_default_text(k, def, sizeof def);
        sl_key_range_text(k, range, sizeof range);
        when_text(s, k, when, sizeof when);
        if (markdown) {
          fprintf(f, "| `%s` | ", k->name);
          md_escape(f, range);
          fputs(" | ", f);
          md_escape(f, def);
          fprintf(f, " | %s |", k->units ? k->units : "");
          if (boundary) {
            fputc(' ', f);
            md_escape(f, when);
            fputs(" |", f);
          }
          fputc(' ', f);
          md_escape(f, k->help);
          fputs(" |\n", f);
        } else {
          fprintf(f, "  %-22s %s; %s%s%s%s", k->name, range, (k->flags & SL_KEY_REQUIRED) ? "" : "default ", def,
                  k->units ? "; " : "", k->units ? k->units : "");
          if (boundary && k->when_type) fprintf(f, "; types %s", when);
          fprintf(f, "\n      %s\n", k->help);
        }
      }
    if (markdown) fputc('\n', f);
  }
  if (s->n_roles > 0) {
    if (markdown) fprintf(f, "## Closures\n\n| section | required | used for |\n|---|---|---|\n");
    else fprintf(f, "\nclosures\n");
    for (int r = 0; r < s->n_roles; ++r) {
      if (markdown) {
        fprintf(f, "| `[closure.%s]` | %s | ", s->roles[r].role, s->roles[r].required ? "yes" : "no");
        md_escape(f, s->roles[r].help);
        fputs(" |\n", f);
      } else {
        fprintf(f, "  [closure.%s]%s\n      %s\n", s->roles[r].role, s->roles[r].required ? " (required)" : "",
                s->roles[r].help);
      }
    }
    if (markdown) fputc('\n', f);
  }
  if (s->n_fields > 0) {
    if (markdown) fprintf(f, "## Output fields\n\n");
    else fprintf(f, "\noutput fields\n  ");
    for (int k = 0; k < s->n_fields; ++k) fprintf(f, markdown ? "%s`%s`" : "%s%s", k ? ", " : "", s->fields[k]);
    fputs(markdown ? "\n" : "\n", f);
  }
}
