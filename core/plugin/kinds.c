#include "core/plugin/kinds.h"

#include <string.h>

static const char *const kind_names[] = {"drag",        "hindered_settling", "viscosity", "solids_pressure",
                                         "wall_stress", "granular",          "migration",       "turbulence",
                                         "densification"};

/* The host's field dictionary (architecture.md section 4, closure.h). */
static const char *const input_names[] = {
    "phi",      "slip",    "shear_rate", "theta",    "rho_f",         "mu_f",      "rho_s", "d_p",
    "sphericity", "density", "gravity",  "d_vessel", "wall_distance", "slip_wall", "u_t",   "pressure", "k",     "epsilon",
    "nbar",     "strain_amplitude", "strain_increment", "strain_total", "volumetric_strain"};

typedef struct contract {
  const char *inputs[3];      /* required inputs */
  unsigned diff_mask;         /* bit i: inputs[i] must be differentiable */
  const char *outputs[2];     /* required outputs */
  int any_output;             /* at least one output, names free (granular, migration) */
} contract;

static const contract contracts[] = {
    [SL_KIND_DRAG] = {{"phi", "slip", NULL}, 3u, {"K", NULL}, 0},
    [SL_KIND_HINDERED_SETTLING] = {{"phi", NULL, NULL}, 1u, {"settling_velocity", NULL}, 0},
    [SL_KIND_VISCOSITY] = {{NULL, NULL, NULL}, 0u, {"viscosity", NULL}, 0},
    [SL_KIND_SOLIDS_PRESSURE] = {{"phi", NULL, NULL}, 1u, {"p_s", NULL}, 0},
    [SL_KIND_WALL_STRESS] = {{"slip_wall", NULL, NULL}, 1u, {"tau_w", NULL}, 0},
    [SL_KIND_GRANULAR] = {{"phi", "theta", NULL}, 0u, {NULL, NULL}, 1},
    [SL_KIND_MIGRATION] = {{"phi", NULL, NULL}, 0u, {NULL, NULL}, 1},
    [SL_KIND_TURBULENCE] = {{"k", "epsilon", NULL}, 0u, {"mu_t", NULL}, 0},
    [SL_KIND_DENSIFICATION] = {{"nbar", NULL, NULL}, 0u, {"nbar_new", NULL}, 0},
};

const char *sl_kind_name(sl_kind kind) {
  if (kind < SL_KIND_FIRST || kind > SL_KIND_LAST) return NULL;
  return kind_names[kind - SL_KIND_FIRST];
}

const char *const *sl_kind_names(int *n) {
  *n = (int)(sizeof kind_names / sizeof kind_names[0]);
  return kind_names;
}

int sl_kind_from_name(const char *name, sl_kind *kind, sl_diag *d) {
  for (int k = SL_KIND_FIRST; k <= SL_KIND_LAST; ++k) {
    if (strcmp(name, kind_names[k - SL_KIND_FIRST]) == 0) {
      *kind = (sl_kind)k;
      return 0;
    }
  }
  int n;
  const char *const *names = sl_kind_names(&n);
  const char *s = sl_suggest(name, names, n);
  if (s) return sl_diag_set(d, SL_EBADINPUT, "unknown closure kind '%s'; did you mean '%s'?", name, s);
  return sl_diag_set(d, SL_EBADINPUT,
                     "unknown closure kind '%s' (kinds: drag, hindered_settling, viscosity, solids_pressure, "
                     "wall_stress, granular, migration, turbulence, densification)",
                     name);
}

int sl_input_is_known(const char *name) {
  for (size_t i = 0; i < sizeof input_names / sizeof input_names[0]; ++i)
    if (strcmp(name, input_names[i]) == 0) return 1;
  return 0;
}

const char *const *sl_input_names(int *n) {
  *n = (int)(sizeof input_names / sizeof input_names[0]);
  return input_names;
}

static int find_field(const sl_field_desc *f, int n, const char *name) {
  for (int i = 0; i < n; ++i)
    if (f[i].name && strcmp(f[i].name, name) == 0) return i;
  return -1;
}

int sl_kind_check_contract(const sl_closure_desc *desc, sl_diag *d) {
  const char *kname = sl_kind_name(desc->kind);
  if (!kname) return sl_diag_set(d, SL_EBADINPUT, "closure '%s' has unknown kind %d", desc->name, (int)desc->kind);
  const contract *c = &contracts[desc->kind];
  for (int i = 0; i < 3 && c->inputs[i]; ++i) {
    int at = find_field(desc->in, desc->n_in, c->inputs[i]);
    if (at < 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' lacks the required input '%s'", kname, desc->name,
                         c->inputs[i]);
    if ((c->diff_mask >> i & 1u) && !(desc->in[at].flags & SL_FIELD_DIFF))
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' must mark input '%s' differentiable", kname,
                         desc->name, c->inputs[i]);
  }
  for (int k = 0; k < 2 && c->outputs[k]; ++k) {
    if (find_field(desc->out, desc->n_out, c->outputs[k]) < 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' lacks the required output '%s'", kname, desc->name,
                         c->outputs[k]);
  }
  if (c->any_output && desc->n_out < 1)
    return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' has no output", kname, desc->name);
  return 0;
}
