/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/validate.h"

#include <ctype.h>
#include <math.h>
#include <string.h>

#include "core/plugin/kinds.h"

/* The v1.0 descriptor ends with destroy; anything shorter was not built
 * against this header. */
#define SL_DESC_V1_0_SIZE (offsetof(sl_closure_desc, destroy) + sizeof(void (*)(void)))

size_t sl_param_type_size(sl_param_type type) {
  switch (type) {
    case SL_PARAM_REAL:
      return sizeof(double);
    case SL_PARAM_INT:
    case SL_PARAM_BOOL:
    case SL_PARAM_ENUM:
      return sizeof(int32_t);
  }
  return 0;
}

static int is_snake_name(const char *s) {
  if (!s || !*s || !islower((unsigned char)s[0])) return 0;
  for (; *s; ++s)
    if (!(islower((unsigned char)*s) || isdigit((unsigned char)*s) || *s == '_')) return 0;
  return 1;
}

static int count_choices(const char *choices) {
  if (!choices || !*choices) return 0;
  int n = 1;
  for (const char *c = choices; *c; ++c) n += *c == '|';
  return n;
}

static int validate_params(const sl_closure_desc *c, sl_diag *d) {
  if (c->n_params < 0 || (c->n_params > 0 && !c->params))
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s': n_params = %d but no parameter table", c->name,
                       (int)c->n_params);
  if (c->n_params > 0 && c->params_size == 0)
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s': params_size is 0 with %d parameters", c->name, (int)c->n_params);
  for (int32_t i = 0; i < c->n_params; ++i) {
    const sl_param_desc *p = &c->params[i];
    if (!is_snake_name(p->name))
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter %d has no lower_snake_case name", c->name, (int)i);
    if (strcmp(p->name, "model") == 0 || strcmp(p->name, "library") == 0)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter name '%s' is reserved for the scene file", c->name,
                         p->name);
    for (int32_t j = 0; j < i; ++j)
      if (strcmp(c->params[j].name, p->name) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter '%s' is declared twice", c->name, p->name);
    size_t sz = sl_param_type_size(p->type);
    if (sz == 0)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter '%s' has unknown type %d", c->name, p->name,
                         (int)p->type);
    if (p->offset + sz > c->params_size || p->offset % sz != 0)
      return sl_diag_set(d, SL_EBADINPUT,
                         "closure '%s': parameter '%s' at offset %zu does not fit a %zu-byte parameter struct", c->name,
                         p->name, p->offset, c->params_size);
    if (p->type == SL_PARAM_ENUM) {
      int nc = count_choices(p->choices);
      if (nc == 0 || p->def < 0 || p->def >= nc || p->def != floor(p->def))
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': enum parameter '%s' has a bad default or no choices",
                           c->name, p->name);
    } else {
      if (isnan(p->def) || isnan(p->min) || isnan(p->max) || p->min > p->max || p->def < p->min || p->def > p->max)
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter '%s' default %g is outside [%g, %g]", c->name,
                           p->name, p->def, p->min, p->max);
      if (p->type != SL_PARAM_REAL && p->def != floor(p->def))
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': integer parameter '%s' has default %g", c->name, p->name,
                           p->def);
    }
    if (!p->units || !p->help)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': parameter '%s' lacks units or help", c->name, p->name);
  }
  return 0;
}

static int validate_fields(const sl_closure_desc *c, const sl_field_desc *f, int32_t n, int inputs, sl_diag *d) {
  const char *what = inputs ? "input" : "output";
  if (n < (inputs ? 0 : 1) || (n > 0 && !f))
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s': bad %s table (n = %d)", c->name, what, (int)n);
  for (int32_t i = 0; i < n; ++i) {
    if (!f[i].name || !*f[i].name || !f[i].units)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': %s %d lacks a name or units", c->name, what, (int)i);
    for (int32_t j = 0; j < i; ++j)
      if (strcmp(f[j].name, f[i].name) == 0)
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': %s '%s' is declared twice", c->name, what, f[i].name);
    if (inputs) {
      if (!sl_input_is_known(f[i].name)) {
        int nn;
        const char *const *names = sl_input_names(&nn);
        const char *s = sl_suggest(f[i].name, names, nn);
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': input '%s' is not a field the host knows%s%s%s", c->name,
                           f[i].name, s ? " (did you mean '" : "", s ? s : "", s ? "'?)" : "");
      }
      if (!(f[i].valid_min <= f[i].typical && f[i].typical <= f[i].valid_max) || !isfinite(f[i].typical))
        return sl_diag_set(d, SL_EBADINPUT, "closure '%s': input '%s' typical value %g is outside [%g, %g]", c->name,
                           f[i].name, f[i].typical, f[i].valid_min, f[i].valid_max);
    }
  }
  return 0;
}

int sl_validate_descriptor(const sl_closure_desc *c, sl_diag *d) {
  if (c->struct_size < SL_DESC_V1_0_SIZE)
    return sl_diag_set(d, SL_EBADINPUT, "descriptor size %u is smaller than the ABI 1.0 descriptor (%zu)",
                       (unsigned)c->struct_size, (size_t)SL_DESC_V1_0_SIZE);
  if (c->abi_major != SL_CLOSURE_ABI_MAJOR)
    return sl_diag_set(d, SL_EBADINPUT, "closure built for closure ABI %u.%u; this sluice speaks ABI %u.%u",
                       (unsigned)c->abi_major, (unsigned)c->abi_minor, SL_CLOSURE_ABI_MAJOR, SL_CLOSURE_ABI_MINOR);
  if (c->real_size != sizeof(double) || c->index_size != sizeof(int32_t))
    return sl_diag_set(d, SL_EBADINPUT,
                       "closure built with %u-byte reals and %u-byte indices; this sluice uses %zu and %zu",
                       (unsigned)c->real_size, (unsigned)c->index_size, sizeof(double), sizeof(int32_t));
  if (!is_snake_name(c->name)) return sl_diag_set(d, SL_EBADINPUT, "a closure has no lower_snake_case name");
  if (!sl_kind_name(c->kind))
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s' has unknown kind %d", c->name, (int)c->kind);
  if (!c->evaluate) return sl_diag_set(d, SL_EBADINPUT, "closure '%s' has no evaluate function", c->name);
  if ((c->create == NULL) != (c->destroy == NULL))
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s' must give both create and destroy, or neither", c->name);
  if (!c->version || !c->summary || !c->reference || !c->validity || !c->formula)
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s' lacks version, summary, formula, reference or validity", c->name);
  int rc = validate_params(c, d);
  if (!rc) rc = validate_fields(c, c->in, c->n_in, 1, d);
  if (!rc) rc = validate_fields(c, c->out, c->n_out, 0, d);
  if (rc) return rc;
  if (c->n_checks < 0 || (c->n_checks > 0 && !c->checks))
    return sl_diag_set(d, SL_EBADINPUT, "closure '%s': bad check-point table", c->name);
  for (int32_t i = 0; i < c->n_checks; ++i)
    if (!c->checks[i].in || c->checks[i].out < 0 || c->checks[i].out >= c->n_out || !c->checks[i].source)
      return sl_diag_set(d, SL_EBADINPUT, "closure '%s': check point %d is malformed", c->name, (int)i);
  return sl_kind_check_contract(c, d);
}
