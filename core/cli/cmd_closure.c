/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice closure describe | eval: a closure's documentation from its own
 * metadata, and its values at chosen states without a mesh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/cli/cli.h"
#include "core/config/ini.h"
#include "core/plugin/instance.h"
#include "core/plugin/kinds.h"

static const char describe_usage[] =
    "usage: sluice closure describe NAME|KIND/NAME [--markdown]\n"
    "       sluice closure describe --all [--markdown]\n"
    "Prints a closure's formula, reference, validity, parameters (units, default,\n"
    "allowed range), inputs and outputs, and an INI stanza to copy into a scene.\n"
    "--all describes every closure; --markdown writes the same as Markdown.";

static const char eval_usage[] =
    "usage: sluice closure eval NAME[,NAME...] [--set p=v]... --at SPEC [--deriv]\n"
    "Evaluates a closure at a table of states and prints CSV on stdout: one column\n"
    "per input, per output and, with --deriv, per derivative d(out)/d(in).\n"
    "Several closures (a comma list, NAME or KIND/NAME) are compared at the same\n"
    "states: their outputs are suffixed [name]; a --set goes to each closure\n"
    "that has the parameter.\n"
    "SPEC is a comma list of input=value or input=first:last:count (a uniform\n"
    "sweep); several sweeps form a grid, the first varying slowest. Inputs not\n"
    "given take their typical values (see describe).\n"
    "examples: sluice closure eval ergun --at \"phi=0:0.6:13,slip=0.01\" --deriv\n"
    "          sluice closure eval drag/ergun,drag/wen_yu --at \"phi=0.05:0.6:12,slip=0.01\"";

/* Finds NAME or KIND/NAME; a bare name given by two kinds is ambiguous. */
static int lookup(const sl_registry *r, const char *spec, const sl_closure_entry **out) {
  *out = NULL;
  sl_diag d;
  const char *slash = strchr(spec, '/');
  if (slash) {
    char kind_name[64];
    snprintf(kind_name, sizeof kind_name, "%.*s", (int)(slash - spec), spec);
    sl_kind kind;
    if (sl_kind_from_name(kind_name, &kind, &d) || sl_registry_find(r, kind, slash + 1, NULL, out, &d))
      return sl_cli_error(SL_EBADINPUT, "%s", d.msg);
    return 0;
  }
  const sl_closure_entry *found = NULL;
  for (int i = 0; i < r->n_entries; ++i) {
    const sl_closure_entry *e = &r->entries[i];
    if (strcmp(e->desc->name, spec) != 0) continue;
    if (found && found->desc->kind != e->desc->kind)
      return sl_cli_error(SL_EBADINPUT, "'%s' names a %s and a %s closure; write %s/%s or %s/%s", spec,
                          sl_kind_name(found->desc->kind), sl_kind_name(e->desc->kind), sl_kind_name(found->desc->kind),
                          spec, sl_kind_name(e->desc->kind), spec);
    if (found)
      return sl_cli_error(SL_EBADINPUT, "%s closure '%s' is provided by both %s and %s", sl_kind_name(e->desc->kind),
                          spec, found->library->path, e->library->path);
    found = e;
  }
  if (found) {
    *out = found;
    return 0;
  }
  const char *cands[512];
  int n = 0;
  for (int i = 0; i < r->n_entries && n < 512; ++i) cands[n++] = r->entries[i].desc->name;
  const char *s = sl_suggest(spec, cands, n);
  if (s) return sl_cli_error(SL_EBADINPUT, "no closure '%s'; did you mean '%s'?", spec, s);
  return sl_cli_error(SL_EBADINPUT, "no closure '%s' (`sluice closures` lists them)", spec);
}

static const char *type_name(const sl_param_desc *p) {
  switch (p->type) {
    case SL_PARAM_REAL:
      return "real";
    case SL_PARAM_INT:
      return "integer";
    case SL_PARAM_BOOL:
      return "boolean";
    case SL_PARAM_ENUM:
      return "choice";
  }
  return "?";
}

static void format_range(const sl_param_desc *p, char *buf, size_t n) {
  if (p->type == SL_PARAM_ENUM) {
    snprintf(buf, n, "%s", p->choices);
    for (char *c = buf; *c; ++c)
      if (*c == '|') *c = ',';
  } else if (p->type == SL_PARAM_BOOL) {
    snprintf(buf, n, "true, false");
  } else {
    snprintf(buf, n, "[%g, %g]", p->min, p->max);
  }
}

static void format_bound(double v, char *buf, size_t n) {
  if (isinf(v)) snprintf(buf, n, "%sinf", v < 0 ? "-" : "");
  else snprintf(buf, n, "%g", v);
}

static void print_formula(FILE *f, const char *formula, const char *indent) {
  for (const char *s = formula; *s;) {
    size_t l = strcspn(s, "\n");
    fprintf(f, "%s%.*s\n", indent, (int)l, s);
    s += l + (s[l] == '\n');
  }
}

static void describe_text(const sl_closure_entry *e, const void *defaults) {
  const sl_closure_desc *c = e->desc;
  char buf[512], lo[32], hi[32];
  printf("%s/%s %s: %s\n", sl_kind_name(c->kind), c->name, c->version, c->summary);
  printf("library:   %s\n", e->library->path);
  printf("reference: %s\n", c->reference);
  printf("validity:  %s\n", c->validity);
  printf("formula:\n");
  print_formula(stdout, c->formula, "  ");
  printf("parameters:\n");
  if (c->n_params == 0) printf("  (none)\n");
  for (int32_t i = 0; i < c->n_params; ++i) {
    const sl_param_desc *p = &c->params[i];
    char def[64];
    sl_params_format_value(c, defaults, i, def, sizeof def);
    format_range(p, buf, sizeof buf);
    printf("  %-20s %-8s default %-12s range %-22s %-14s %s\n", p->name, type_name(p), def, buf,
           p->units[0] ? p->units : "-", p->help);
  }
  printf("inputs (* differentiable):\n");
  for (int32_t i = 0; i < c->n_in; ++i) {
    const sl_field_desc *f = &c->in[i];
    format_bound(f->valid_min, lo, sizeof lo);
    format_bound(f->valid_max, hi, sizeof hi);
    printf("  %-14s%s %-14s typical %-10g valid [%s, %s]  %s\n", f->name, (f->flags & SL_FIELD_DIFF) ? "*" : " ",
           f->units, f->typical, lo, hi, f->help ? f->help : "");
  }
  printf("outputs:\n");
  for (int32_t k = 0; k < c->n_out; ++k)
    printf("  %-15s %-14s %s%s\n", c->out[k].name, c->out[k].units, c->out[k].help ? c->out[k].help : "",
           (c->out[k].flags & SL_FIELD_OPTIONAL) ? " (optional)" : "");
  printf("INI stanza:\n  [closure.%s]\n  model = %s\n", sl_kind_name(c->kind), c->name);
  for (int32_t i = 0; i < c->n_params; ++i) {
    char def[64];
    sl_params_format_value(c, defaults, i, def, sizeof def);
    format_range(&c->params[i], buf, sizeof buf);
    printf("  %s = %s    ; %s, %s\n", c->params[i].name, def, c->params[i].units[0] ? c->params[i].units : "choice",
           buf);
  }
}

static void md_escape(const char *s) {
  for (; *s; ++s) {
    if (*s == '|') fputs("\\|", stdout);
    else if (*s == '\n') fputs(" ", stdout);
    else putchar(*s);
  }
}

static void describe_markdown(const sl_closure_entry *e, const void *defaults) {
  const sl_closure_desc *c = e->desc;
  char buf[512], lo[32], hi[32];
  printf("### %s/%s\n\n", sl_kind_name(c->kind), c->name);
  printf("%s (version %s).\n\n", c->summary, c->version);
  printf("```\n");
  print_formula(stdout, c->formula, "");
  printf("```\n\n");
  printf("- Reference: %s\n- Validity: %s\n\n", c->reference, c->validity);
  if (c->n_params > 0) {
    printf("| parameter | type | default | range | units | meaning |\n|---|---|---|---|---|---|\n");
    for (int32_t i = 0; i < c->n_params; ++i) {
      const sl_param_desc *p = &c->params[i];
      char def[64];
      sl_params_format_value(c, defaults, i, def, sizeof def);
      format_range(p, buf, sizeof buf);
      printf("| `%s` | %s | %s | %s | %s | ", p->name, type_name(p), def, buf, p->units[0] ? p->units : "-");
      md_escape(p->help);
      printf(" |\n");
    }
    printf("\n");
  }
  printf("| input | units | typical | valid range | derivative |\n|---|---|---|---|---|\n");
  for (int32_t i = 0; i < c->n_in; ++i) {
    const sl_field_desc *f = &c->in[i];
    format_bound(f->valid_min, lo, sizeof lo);
    format_bound(f->valid_max, hi, sizeof hi);
    printf("| `%s` | %s | %g | [%s, %s] | %s |\n", f->name, f->units, f->typical, lo, hi,
           (f->flags & SL_FIELD_DIFF) ? "yes" : "no");
  }
  printf("\n| output | units | meaning |\n|---|---|---|\n");
  for (int32_t k = 0; k < c->n_out; ++k) {
    printf("| `%s` | %s | ", c->out[k].name, c->out[k].units);
    md_escape(c->out[k].help ? c->out[k].help : "");
    printf("%s |\n", (c->out[k].flags & SL_FIELD_OPTIONAL) ? " (optional)" : "");
  }
  printf("\n```ini\n[closure.%s]\nmodel = %s\n", sl_kind_name(c->kind), c->name);
  for (int32_t i = 0; i < c->n_params; ++i) {
    char def[64];
    sl_params_format_value(c, defaults, i, def, sizeof def);
    printf("%s = %s\n", c->params[i].name, def);
  }
  printf("```\n\n");
}

static int describe_one(const sl_closure_entry *e, int markdown) {
  void *defaults;
  sl_diag d;
  if (sl_params_new(e->desc, &defaults, &d)) return sl_cli_error(SL_EFAILED, "%s", d.msg);
  if (markdown) describe_markdown(e, defaults);
  else describe_text(e, defaults);
  sl_params_free(defaults);
  return 0;
}

static int cmp_entry(const void *a, const void *b) {
  const sl_closure_entry *x = a, *y = b;
  if (x->desc->kind != y->desc->kind) return (int)x->desc->kind - (int)y->desc->kind;
  return strcmp(x->desc->name, y->desc->name);
}

static int cmd_describe(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(describe_usage);
    return 0;
  }
  int markdown = 0, all = 0;
  const char *name = NULL;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--markdown") == 0) markdown = 1;
    else if (strcmp(argv[i], "--all") == 0) all = 1;
    else if (argv[i][0] == '-') return sl_cli_error(SL_EBADINPUT, "closure describe: unknown option '%s'", argv[i]);
    else if (!name) name = argv[i];
    else return sl_cli_error(SL_EBADINPUT, "closure describe: one name at a time (or --all)");
  }
  if (!name && !all)
    return sl_cli_error(SL_EBADINPUT, "closure describe: which closure? (%s)", "sluice closures lists them");
  sl_registry *r;
  int rc = sl_cli_registry(&r, !markdown);
  if (rc) return rc;
  if (all) {
    /* Sorted by kind then name, independent of file-system order, so the
     * generated page is reproducible. */
    sl_closure_entry *sorted = malloc((size_t)r->n_entries * sizeof *sorted + 1);
    if (!sorted) rc = sl_cli_error(SL_EFAILED, "out of memory");
    if (sorted) {
      memcpy(sorted, r->entries, (size_t)r->n_entries * sizeof *sorted);
      qsort(sorted, (size_t)r->n_entries, sizeof *sorted, cmp_entry);
      if (markdown) {
        printf("# sluice closures\n\n");
        printf(
            "Generated by `sluice closure describe --all --markdown` from the closures' own\n"
            "metadata; do not edit by hand. Conventions: SI units, radians, dynamic\n"
            "viscosities; `phi` is the solids volume fraction; a drag closure returns K\n"
            "with the force on the solids F_s = K (u_f - u_s).\n\n");
        for (int k = SL_KIND_FIRST; k <= SL_KIND_LAST; ++k) {
          printf("- %s:", sl_kind_name((sl_kind)k));
          for (int i = 0; i < r->n_entries; ++i)
            if ((int)sorted[i].desc->kind == k)
              printf(" [%s](#%s%s)", sorted[i].desc->name, sl_kind_name((sl_kind)k), sorted[i].desc->name);
          printf("\n");
        }
        printf("\n");
      }
      int prev_kind = 0;
      for (int i = 0; i < r->n_entries && !rc; ++i) {
        if (markdown && (int)sorted[i].desc->kind != prev_kind) {
          prev_kind = (int)sorted[i].desc->kind;
          printf("## %s\n\n", sl_kind_name(sorted[i].desc->kind));
        }
        rc = describe_one(&sorted[i], markdown);
        if (!markdown) printf("\n");
      }
      free(sorted);
    }
  } else {
    const sl_closure_entry *e;
    rc = lookup(r, name, &e);
    if (!rc) rc = describe_one(e, markdown);
  }
  sl_registry_destroy(r);
  return rc;
}

/* ---- eval ---- */

typedef struct sweep {
  int input; /* index into the union of the closures' inputs */
  double first, last;
  long count;
} sweep;

enum { MAX_EVAL_CLOSURES = 16, MAX_EVAL_INPUTS = 64 };

/* The inputs of all closures compared, each once, in order of appearance. */
typedef struct input_union {
  int n;
  const sl_field_desc *field[MAX_EVAL_INPUTS];
} input_union;

static int union_find(const input_union *u, const char *name) {
  for (int i = 0; i < u->n; ++i)
    if (strcmp(u->field[i]->name, name) == 0) return i;
  return -1;
}

static int parse_at(const input_union *u, const char *spec, sweep *sw, int *n_sw, int cap) {
  *n_sw = 0;
  char *copy = strdup(spec);
  if (!copy) return sl_cli_error(SL_EFAILED, "out of memory");
  int rc = 0;
  for (char *save = NULL, *item = strtok_r(copy, ",", &save); item && !rc; item = strtok_r(NULL, ",", &save)) {
    while (*item == ' ') ++item;
    char *eq = strchr(item, '=');
    if (!eq) {
      rc = sl_cli_error(SL_EBADINPUT, "--at: '%s' is not input=value or input=first:last:count", item);
      break;
    }
    *eq = '\0';
    char *name = item, *val = eq + 1;
    for (char *end = name + strlen(name); end > name && end[-1] == ' ';) *--end = '\0';
    int i = union_find(u, name);
    if (i < 0) {
      const char *cands[MAX_EVAL_INPUTS];
      for (int k = 0; k < u->n; ++k) cands[k] = u->field[k]->name;
      const char *s = sl_suggest(name, cands, u->n);
      rc = s ? sl_cli_error(SL_EBADINPUT, "--at: no input '%s'; did you mean '%s'?", name, s)
             : sl_cli_error(SL_EBADINPUT, "--at: no input '%s' (`sluice closure describe NAME` lists them)", name);
      break;
    }
    for (int k = 0; k < *n_sw; ++k)
      if (sw[k].input == i) rc = sl_cli_error(SL_EBADINPUT, "--at: input '%s' given twice", name);
    if (rc) break;
    if (*n_sw == cap) {
      rc = sl_cli_error(SL_EBADINPUT, "--at: too many inputs");
      break;
    }
    sweep s = {i, 0, 0, 1};
    char *c1 = strchr(val, ':');
    if (!c1) {
      if (sl_parse_real(val, &s.first)) rc = sl_cli_error(SL_EBADINPUT, "--at: %s = '%s' is not a number", name, val);
      s.last = s.first;
    } else {
      char *c2 = strchr(c1 + 1, ':');
      *c1 = '\0';
      if (c2) *c2 = '\0';
      if (!c2 || sl_parse_real(val, &s.first) || sl_parse_real(c1 + 1, &s.last) || sl_parse_long(c2 + 1, &s.count) ||
          s.count < 1 || s.count > 1000000)
        rc = sl_cli_error(SL_EBADINPUT, "--at: %s: expected first:last:count with 1 <= count <= 1e6", name);
    }
    sw[(*n_sw)++] = s;
  }
  free(copy);
  return rc;
}

/* Applies the --set list: each parameter goes to every compared closure that
 * has it; a parameter none of them has is an error. */
static int apply_sets(sl_closure_entry const *const *e, int n_cl, void **params, const char *const *sets, int n_sets) {
  for (int i = 0; i < n_sets; ++i) {
    char key[128];
    const char *eq = strchr(sets[i], '=');
    if (!eq) return sl_cli_error(SL_EBADINPUT, "--set %s: expected parameter=value", sets[i]);
    snprintf(key, sizeof key, "%.*s", (int)(eq - sets[i]), sets[i]);
    int used = 0;
    sl_diag d;
    for (int k = 0; k < n_cl; ++k) {
      if (n_cl > 1 && sl_params_find(e[k]->desc, key) < 0) continue;
      int rc = sl_params_set(e[k]->desc, params[k], key, eq + 1, &d);
      if (rc) return sl_cli_error(rc, "--set %s: %s", sets[i], d.msg);
      used = 1;
    }
    if (!used)
      return sl_cli_error(SL_EBADINPUT, "--set %s: none of the closures compared has parameter '%s'", sets[i], key);
  }
  return 0;
}

static int cmd_eval(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(eval_usage);
    return 0;
  }
  const char *names = NULL, *at = NULL;
  int deriv = 0;
  enum { MAX_SETS = 64 };
  const char *sets[MAX_SETS];
  int n_sets = 0;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "--deriv") == 0) deriv = 1;
    else if (strcmp(argv[i], "--at") == 0 && i + 1 < argc) at = argv[++i];
    else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
      if (n_sets == MAX_SETS) return sl_cli_error(SL_EBADINPUT, "too many --set");
      sets[n_sets++] = argv[++i];
    } else if (argv[i][0] == '-')
      return sl_cli_error(SL_EBADINPUT, "closure eval: unknown option or missing value '%s'", argv[i]);
    else if (!names) names = argv[i];
    else return sl_cli_error(SL_EBADINPUT, "closure eval: unexpected argument '%s'", argv[i]);
  }
  if (!names) return sl_cli_error(SL_EBADINPUT, "closure eval: which closure?\n%s", eval_usage);
  sl_registry *r;
  int rc = sl_cli_registry(&r, 1);
  if (rc) return rc;
  const sl_closure_entry *e[MAX_EVAL_CLOSURES];
  sl_closure *cl[MAX_EVAL_CLOSURES] = {NULL};
  void *params[MAX_EVAL_CLOSURES] = {NULL};
  int n_cl = 0;
  double *data = NULL;
  char *list = strdup(names);
  sl_diag d;
  input_union u = {0, {NULL}};
  if (!list) {
    rc = sl_cli_error(SL_EFAILED, "out of memory");
    goto done;
  }
  /* NAME or a comma list of closures to compare at the same states. */
  for (char *save = NULL, *t = strtok_r(list, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
    if (n_cl == MAX_EVAL_CLOSURES) {
      rc = sl_cli_error(SL_EBADINPUT, "closure eval: at most %d closures at once", MAX_EVAL_CLOSURES);
      goto done;
    }
    if ((rc = lookup(r, t, &e[n_cl]))) goto done;
    if ((rc = sl_params_new(e[n_cl]->desc, &params[n_cl], &d))) {
      rc = sl_cli_error(rc, "%s", d.msg);
      goto done;
    }
    ++n_cl;
  }
  for (int k = 0; k < n_cl; ++k)
    for (int32_t i = 0; i < e[k]->desc->n_in; ++i)
      if (union_find(&u, e[k]->desc->in[i].name) < 0) {
        if (u.n == MAX_EVAL_INPUTS) {
          rc = sl_cli_error(SL_EBADINPUT, "closure eval: too many inputs");
          goto done;
        }
        u.field[u.n++] = &e[k]->desc->in[i];
      }
  if ((rc = apply_sets(e, n_cl, params, sets, n_sets))) goto done;
  for (int k = 0; k < n_cl; ++k) {
    rc = sl_closure_create(e[k], params[k], &cl[k], &d);
    params[k] = NULL; /* owned by the closure now, also on failure */
    if (rc) {
      rc = sl_cli_error(rc, "%s", d.msg);
      goto done;
    }
  }
  sweep sw[32];
  int n_sw = 0;
  if (at && (rc = parse_at(&u, at, sw, &n_sw, 32))) goto done;
  long Q = 1;
  for (int k = 0; k < n_sw; ++k) {
    if (Q > 10000000 / sw[k].count) {
      rc = sl_cli_error(SL_EBADINPUT, "--at: the grid has more than 1e7 points");
      goto done;
    }
    Q *= sw[k].count;
  }
  /* The states (one column per union input), then per closure its outputs
   * and derivatives, structure of arrays. */
  size_t nq = (size_t)Q, ncols = (size_t)u.n;
  for (int k = 0; k < n_cl; ++k) ncols += (size_t)e[k]->desc->n_out * (1 + (size_t)e[k]->desc->n_in);
  data = calloc(ncols * nq + 1, sizeof(double));
  if (!data) {
    rc = sl_cli_error(SL_EFAILED, "out of memory");
    goto done;
  }
  for (size_t q = 0; q < nq; ++q) {
    for (int i = 0; i < u.n; ++i) data[(size_t)i * nq + q] = u.field[i]->typical;
    long rest = (long)q;
    for (int k = n_sw - 1; k >= 0; --k) {
      long j = rest % sw[k].count;
      rest /= sw[k].count;
      double v = sw[k].count == 1 ? sw[k].first
                                  : sw[k].first + (sw[k].last - sw[k].first) * (double)j / (double)(sw[k].count - 1);
      data[(size_t)sw[k].input * nq + q] = v;
    }
  }
  double *outs[MAX_EVAL_CLOSURES][MAX_EVAL_INPUTS];
  double *douts[MAX_EVAL_CLOSURES][MAX_EVAL_INPUTS * MAX_EVAL_INPUTS];
  size_t col = (size_t)u.n;
  for (int k = 0; k < n_cl && !rc; ++k) {
    const sl_closure_desc *c = e[k]->desc;
    const double *in[MAX_EVAL_INPUTS];
    if (c->n_out > MAX_EVAL_INPUTS) {
      rc = sl_cli_error(SL_EFAILED, "closure %s has too many outputs", c->name);
      break;
    }
    for (int32_t i = 0; i < c->n_in; ++i) in[i] = data + (size_t)union_find(&u, c->in[i].name) * nq;
    for (int32_t o = 0; o < c->n_out; ++o) outs[k][o] = data + (col++) * nq;
    for (int32_t o = 0; o < c->n_out; ++o)
      for (int32_t i = 0; i < c->n_in; ++i)
        douts[k][o * c->n_in + i] = (c->in[i].flags & SL_FIELD_DIFF) ? data + (col++) * nq : NULL;
    sl_error err;
    sl_eval_args a = {.Q = (int32_t)Q, .in = in, .out = outs[k], .dout = deriv ? douts[k] : NULL, .err = &err};
    int erc = sl_closure_evaluate(cl[k], &a);
    if (erc != 0) {
      char pt[512] = "";
      size_t used = 0;
      for (int32_t i = 0; i < c->n_in && err.point >= 0 && used < sizeof pt; ++i)
        used += (size_t)snprintf(pt + used, sizeof pt - used, "%s%s=%g", i ? "," : "", c->in[i].name, in[i][err.point]);
      rc = sl_cli_error(SL_EFAILED, "%s/%s %s at %s: %s", sl_kind_name(c->kind), c->name,
                        erc > 0 ? "is outside its validity" : "failed", err.point >= 0 ? pt : "(no point)", err.msg);
    }
  }
  if (rc) goto done;
  /* Header: inputs, then outputs (suffixed [closure] when comparing). */
  for (int i = 0; i < u.n; ++i) printf("%s%s", i ? "," : "", u.field[i]->name);
  for (int k = 0; k < n_cl; ++k) {
    const sl_closure_desc *c = e[k]->desc;
    char tag[96] = "";
    if (n_cl > 1) snprintf(tag, sizeof tag, "[%s]", c->name);
    for (int32_t o = 0; o < c->n_out; ++o) printf(",%s%s", c->out[o].name, tag);
    if (deriv)
      for (int32_t o = 0; o < c->n_out; ++o)
        for (int32_t i = 0; i < c->n_in; ++i)
          if (douts[k][o * c->n_in + i]) printf(",d%s/d%s%s", c->out[o].name, c->in[i].name, tag);
  }
  printf("\n");
  for (size_t q = 0; q < nq; ++q) {
    for (int i = 0; i < u.n; ++i) printf("%s%.12g", i ? "," : "", data[(size_t)i * nq + q]);
    for (int k = 0; k < n_cl; ++k) {
      const sl_closure_desc *c = e[k]->desc;
      for (int32_t o = 0; o < c->n_out; ++o) printf(",%.12g", outs[k][o][q]);
      if (deriv)
        for (int32_t o = 0; o < c->n_out; ++o)
          for (int32_t i = 0; i < c->n_in; ++i)
            if (douts[k][o * c->n_in + i]) printf(",%.12g", douts[k][o * c->n_in + i][q]);
    }
    printf("\n");
  }
done:
  free(data);
  free(list);
  for (int k = 0; k < n_cl; ++k) {
    sl_closure_destroy(cl[k]);
    sl_params_free(params[k]);
  }
  sl_registry_destroy(r);
  return rc;
}

int sl_cmd_closure(int argc, char **argv) {
  if (argc < 1 || strcmp(argv[0], "--help") == 0 || strcmp(argv[0], "-h") == 0) {
    printf("%s\n\n%s\n\n%s\n\n%s\n\n%s\n", describe_usage, eval_usage, sl_closure_kinds_usage, sl_closure_new_usage,
           sl_closure_index_usage);
    return argc < 1 ? SL_EBADINPUT : 0;
  }
  if (strcmp(argv[0], "describe") == 0) return cmd_describe(argc - 1, argv + 1);
  if (strcmp(argv[0], "eval") == 0) return cmd_eval(argc - 1, argv + 1);
  if (strcmp(argv[0], "index") == 0) return sl_cmd_closure_index(argc - 1, argv + 1);
  if (strcmp(argv[0], "kinds") == 0) return sl_cmd_closure_kinds(argc - 1, argv + 1);
  if (strcmp(argv[0], "new") == 0) return sl_cmd_closure_new(argc - 1, argv + 1);
  const char *subs[] = {"describe", "eval", "kinds", "new", "index"};
  const char *s = sl_suggest(argv[0], subs, 5);
  return sl_cli_error(SL_EBADINPUT, "closure: unknown subcommand '%s'%s%s%s (describe, eval, kinds, new or index)",
                      argv[0], s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
}
