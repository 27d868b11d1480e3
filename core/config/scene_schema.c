#include "core/config/scene_schema.h"

#include <math.h>
#include <string.h>

static const sl_key_spec scene_keys[] = {
    {"model", SL_KEY_CHOICE, 1, 0, 0, "navier_stokes|mixture|two_fluid", "the physical model"},
    {"title", SL_KEY_STRING, 0, 0, 0, NULL, "a one-line title"},
    {"geometry", SL_KEY_CHOICE, 0, 0, 0, "line|planar|axisymmetric", "1-D line, 2-D planar or axisymmetric (r, z)"},
};
static const sl_key_spec fluid_keys[] = {
    {"density", SL_KEY_REAL, 0, 1e-3, 1e5, NULL, "fluid density, kg m^-3"},
    {"viscosity", SL_KEY_REAL, 0, 1e-7, 1e7, NULL, "fluid dynamic viscosity, Pa s"},
};
static const sl_key_spec solid_keys[] = {
    {"density", SL_KEY_REAL, 0, 1e-3, 1e5, NULL, "solid density, kg m^-3"},
    {"diameter", SL_KEY_REAL, 0, 1e-9, 1.0, NULL, "particle diameter, m"},
    {"phi_max", SL_KEY_REAL, 0, 0.01, 1.0, NULL, "maximum packing fraction"},
    {"sphericity", SL_KEY_REAL, 0, 0.01, 1.0, NULL, "particle sphericity"},
    {"porosity_max", SL_KEY_REAL, 0, 0.0, 0.99, NULL, "alternative to phi_max: 1 - phi_max"},
    {"viscosity", SL_KEY_REAL, 0, 0.0, 1e7, NULL, "two_fluid shear layer: a constant solids viscosity, Pa s"},
};
static const sl_key_spec time_keys[] = {
    {"end", SL_KEY_REAL, 0, 0.0, 1e12, NULL, "end time, s"},
    {"dt", SL_KEY_REAL, 0, 1e-15, 1e9, NULL, "first (or fixed) time step, s"},
    {"scheme", SL_KEY_CHOICE, 0, 0, 0, "bdf1|bdf2|steady", "time integration"},
    {"tolerance", SL_KEY_REAL, 0, 1e-14, 1.0, NULL, "local error tolerance of adaptive steps"},
    {"adaptive", SL_KEY_BOOL, 0, 0, 0, NULL, "adapt the step to the error estimate"},
    {"dt_min", SL_KEY_REAL, 0, 0.0, 1e9, NULL, "smallest step before the run gives up, s"},
    {"dt_max", SL_KEY_REAL, 0, 1e-15, 1e12, NULL, "largest step, s"},
    {"max_steps", SL_KEY_INT, 0, 1, 1e8, NULL, "stop (with a checkpoint) after this many steps"},
};
static const sl_key_spec solver_keys[] = {
    {"linear", SL_KEY_CHOICE, 0, 0, 0, "umfpack|klu|cholmod", "sparse direct solver"},
    {"ordering", SL_KEY_CHOICE, 0, 0, 0, "auto|amd|colamd|metis", "klu's fill-reducing ordering (auto: AMD, METIS from 30 000 unknowns)"},
    {"reuse", SL_KEY_CHOICE, 0, 0, 0, "auto|never", "Newton's corrections by FGMRES with an older factorisation (auto) or a factorisation per changed matrix (never)"},
    {"nonlinear_tolerance", SL_KEY_REAL, 0, 1e-16, 1.0, NULL, "relative tolerance of Newton/Picard"},
    {"max_iterations", SL_KEY_INT, 0, 1, 1000, NULL, "nonlinear iterations per step"},
    {"nonlinear", SL_KEY_CHOICE, 0, 0, 0, "newton|picard", "Newton (line search, Picard fallback) or Picard only"},
    {"picard_first", SL_KEY_INT, 0, 0, 1000, NULL, "Picard iterations before Newton (far initial guesses)"},
    {"continuation", SL_KEY_STRING, 0, 0, 0, NULL, "steady: approach section.key's value in stages"},
    {"continuation_from", SL_KEY_REAL, 0, -1e300, 1e300, NULL, "first value of the continuation parameter"},
    {"continuation_steps", SL_KEY_INT, 0, 1, 1000, NULL, "continuation stages (geometric when both ends > 0)"},
};
static const sl_key_spec flow_keys[] = {
    {"third_component", SL_KEY_BOOL, 0, 0, 0, NULL, "solve the out-of-plane velocity (planar, line) or the swirl (axisymmetric)"},
    {"convection", SL_KEY_BOOL, 0, 0, 0, NULL, "include rho (u.grad)u (false: Stokes flow)"},
    {"gravity", SL_KEY_LIST, 0, 0, 0, NULL, "gravitational acceleration per component, m s^-2"},
    {"body_force", SL_KEY_LIST, 0, 0, 0, NULL, "body force per unit volume per component, N m^-3 (e.g. -dp/dz)"},
    {"rotation", SL_KEY_REAL, 0, -1e6, 1e6, NULL, "angular velocity of the frame, rad s^-1"},
    {"rotation_centre", SL_KEY_LIST, 0, 0, 0, NULL, "planar: the rotation axis x, y"},
};
static const sl_key_spec mesh_keys[] = {
    {"generator", SL_KEY_CHOICE, 0, 0, 0, "interval|rectangle|annulus|inclined_box|gmsh", "how the mesh is made"},
    {"x", SL_KEY_LIST, 0, 0, 0, NULL, "x0, x1 (interval, rectangle)"},
    {"y", SL_KEY_LIST, 0, 0, 0, NULL, "y0, y1 (rectangle)"},
    {"shear", SL_KEY_REAL, 0, -10.0, 10.0, NULL, "rectangle: x moves by shear (y - y0), a parallelogram"},
    {"r", SL_KEY_LIST, 0, 0, 0, NULL, "r0, r1 (annulus)"},
    {"z", SL_KEY_LIST, 0, 0, 0, NULL, "z0, z1 (annulus)"},
    {"origin", SL_KEY_LIST, 0, 0, 0, NULL, "lower-left corner (inclined_box)"},
    {"width", SL_KEY_REAL, 0, 1e-12, 1e12, NULL, "inclined_box width, m"},
    {"height", SL_KEY_REAL, 0, 1e-12, 1e12, NULL, "inclined_box height, m"},
    {"angle", SL_KEY_REAL, 0, -7.0, 7.0, NULL, "inclined_box rotation, rad"},
    {"cells", SL_KEY_LIST, 0, 0, 0, NULL, "cells per direction: n or nx, ny"},
    {"cell_type", SL_KEY_CHOICE, 0, 0, 0, "quad|tri", "quadrilaterals or triangles"},
    {"diagonal", SL_KEY_CHOICE, 0, 0, 0, "right|left|union_jack", "how quads are split into triangles"},
    {"grading_x", SL_KEY_STRING, 0, 0, 0, NULL, "geometric:RATIO or symmetric:RATIO along x (r)"},
    {"grading_y", SL_KEY_STRING, 0, 0, 0, NULL, "geometric:RATIO or symmetric:RATIO along y (z)"},
    {"file", SL_KEY_STRING, 0, 0, 0, NULL, "Gmsh file (2.2 or 4.1), relative to the scene"},
};
static const sl_key_spec output_keys[] = {
    {"file", SL_KEY_STRING, 0, 0, 0, NULL, "HDF5 output file"},
    {"every", SL_KEY_REAL, 0, 0.0, 1e12, NULL, "output interval, s"},
    {"fields", SL_KEY_LIST, 0, 0, 0, NULL, "fields to write"},
    {"interface", SL_KEY_LIST, 0, 0, 0, NULL, "mixture: levels of phi whose heights are written"},
};
static const sl_key_spec transport_keys[] = {
    {"order", SL_KEY_INT, 0, 1, 2, NULL, "1: Godunov, 2: MUSCL (second order)"},
    {"limiter", SL_KEY_CHOICE, 0, 0, 0, "mc|minmod", "slope limiter of order 2"},
    {"cfl", SL_KEY_REAL, 0, 1e-3, 1.0, NULL, "fraction of the stable explicit sub-step"},
    {"table_points", SL_KEY_INT, 0, 17, 1000001, NULL, "nodes of the settling-flux table"},
};
static const sl_key_spec mixture_keys[] = {
    {"slip_acceleration", SL_KEY_BOOL, 0, 0, 0, NULL,
     "the slip follows g - Dj/Dt (Nigam 1999 eq 2.25), not only gravity and the frame's centrifugal force"},
    {"reference_acceleration", SL_KEY_REAL, 0, 1e-12, 1e12, NULL,
     "the acceleration the settling closure is evaluated at, m s^-2 (default |g|, else the frame's largest "
     "centrifugal one, else 1)"},
    {"diffusivity", SL_KEY_REAL, 0, 0.0, 1e6, NULL, "particle diffusivity eps: the flux -eps grad(phi), m^2 s^-1"},
    {"relative_flux_stress", SL_KEY_BOOL, 0, 0, 0, NULL,
     "the momentum carries the stress rho_f j_R j_R / (phi (1 - phi)) of the settling flux (Nigam 1999 eq 2.16)"},
};
static const sl_key_spec two_fluid_keys[] = {
    {"iterations", SL_KEY_INT, 0, 1, 1000, NULL, "two_fluid: most iterations of one implicit step before it is retried smaller"},
    {"tolerance", SL_KEY_REAL, 0, 1e-15, 1e-2, NULL,
     "two_fluid: a step has converged when the solids velocity changes by less than this times its scale"},
    {"cfl", SL_KEY_REAL, 0, 1e-3, 1.0, NULL, "two_fluid: fraction of the stable sub-step of the solids transport"},
    {"steady_tolerance", SL_KEY_REAL, 0, 0.0, 1.0, NULL,
     "two_fluid: stop when max |dphi/dt| falls below this, s^-1 (0: run to [time] end)"},
    {"diffusivity", SL_KEY_REAL, 0, 0.0, 1e3, NULL,
     "two_fluid: particle diffusivity D, the extra solids flux -D dphi/dx, m^2 s^-1 (default 0)"},
    {"order", SL_KEY_INT, 0, 1, 2, NULL, "two_fluid: solids transport, 1: upwind, 2: MUSCL (limited, Heun sub-steps)"},
    {"limiter", SL_KEY_CHOICE, 0, 0, 0, "minmod|mc", "two_fluid: the slope limiter of order 2"},
    {"case", SL_KEY_INT, 0, 0, 1000000, NULL,
     "two_fluid: a number the [initial] and inlet expressions read as `case` (several variants in one scene)"},
    {"motion", SL_KEY_CHOICE, 0, 0, 0, "column|shear",
     "two_fluid: column (the phases move along the line) or shear (across it, between two walls; phi held)"},
    {"cross_section", SL_KEY_CHOICE, 0, 0, 0, "planar|annular",
     "two_fluid shear layer: a planar gap, or coaxial cylinders with x the radius"},
    {"granular_temperature", SL_KEY_CHOICE, 0, 0, 0, "transport|algebraic",
     "two_fluid shear layer with [closure.granular]: theta's transport equation or its local balance"},
    {"interphase_dissipation", SL_KEY_BOOL, 0, 0, 0, NULL,
     "two_fluid shear layer: the sink -3 K theta of granular energy by the drag (default true)"},
    {"acceleration", SL_KEY_CHOICE, 0, 0, 0, "none|anderson",
     "two_fluid 2-D: Anderson acceleration of the step's iteration (default anderson with [closure.granular], "
     "else none)"},
    {"kinetic_pressure", SL_KEY_BOOL, 0, 0, 0, NULL,
     "two_fluid 2-D: the kinetic theory's p_s(phi, theta) joins the solids pressure (default true with a "
     "transported theta when [closure.granular] gives p_s)"},
};
static const sl_key_spec plugins_keys[] = {
    {"path", SL_KEY_LIST, 0, 0, 0, NULL, "folders searched first for closure libraries"},
};

#define SPEC(n, open, k) {n, open, k, (int)(sizeof k / sizeof k[0])}
static const sl_section_spec sections[] = {
    SPEC("scene", 0, scene_keys),   SPEC("fluid", 0, fluid_keys),   SPEC("solid", 0, solid_keys),
    SPEC("time", 0, time_keys),     SPEC("solver", 0, solver_keys), SPEC("output", 0, output_keys),
    SPEC("plugins", 0, plugins_keys), SPEC("flow", 0, flow_keys), SPEC("mesh", 0, mesh_keys), SPEC("transport", 0, transport_keys),
    SPEC("mixture", 0, mixture_keys), SPEC("two_fluid", 0, two_fluid_keys), {"initial", 1, NULL, 0},        {"boundary.", 1, NULL, 0},
    {"closure.", 1, NULL, 0}, /* checked against each closure's own schema */
};

const sl_section_spec *sl_scene_sections(int *n) {
  *n = (int)(sizeof sections / sizeof sections[0]);
  return sections;
}

static int check_value(const sl_ini *ini, const char *section, const sl_key_spec *k, sl_diag *d) {
  switch (k->type) {
    case SL_KEY_REAL: {
      double v;
      return sl_ini_get_real(ini, section, k->name, k->required, k->min, k->min, k->max, &v, d);
    }
    case SL_KEY_INT: {
      long v;
      return sl_ini_get_int(ini, section, k->name, k->required, (long)k->min, (long)k->min, (long)k->max, &v, d);
    }
    case SL_KEY_BOOL: {
      int v;
      return sl_ini_get_bool(ini, section, k->name, k->required, 0, &v, d);
    }
    case SL_KEY_CHOICE: {
      int v;
      return sl_ini_get_choice(ini, section, k->name, k->required, 0, k->choices, &v, d);
    }
    case SL_KEY_STRING:
    case SL_KEY_LIST: {
      const char *v;
      return sl_ini_get_string(ini, section, k->name, k->required, "", &v, d);
    }
  }
  return 0;
}

int sl_scene_validate(const sl_ini *ini, sl_diag *d) {
  const char *known[32], *prefixes[8];
  int nk = 0, np = 0;
  for (size_t i = 0; i < sizeof sections / sizeof sections[0]; ++i) {
    size_t l = strlen(sections[i].name);
    if (sections[i].name[l - 1] == '.') prefixes[np++] = sections[i].name;
    else known[nk++] = sections[i].name;
  }
  int rc = sl_ini_check_sections(ini, known, nk, prefixes, np, d);
  if (rc) return rc;
  for (size_t i = 0; i < sizeof sections / sizeof sections[0]; ++i) {
    const sl_section_spec *s = &sections[i];
    if (s->open) continue;
    const char *names[32];
    for (int k = 0; k < s->n_keys; ++k) names[k] = s->keys[k].name;
    int present = sl_ini_find_section(ini, s->name) != NULL;
    if (present && (rc = sl_ini_check_keys(ini, s->name, names, s->n_keys, d))) return rc;
    for (int k = 0; k < s->n_keys; ++k) {
      if (!present && !s->keys[k].required) continue;
      if ((rc = check_value(ini, s->name, &s->keys[k], d))) return rc;
    }
  }
  return 0;
}
