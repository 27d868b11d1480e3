/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The schemas of the two-fluid model's variants: the 1-D column, the 2-D
 * model on a staggered grid, the shear layer (two_fluid.h). */
#include "core/models/two_fluid/two_fluid.h"

#include "core/models/two_fluid/shear_layer.h"
#include "core/models/two_fluid/two_fluid_impl.h"
#include "core/models/two_fluid/two_fluid_plane_impl.h"
#include "core/scene/keys.h"
#include "core/scene/solver.h"

#define TABLE(name, keys) static const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}
#define C(field) SL_AT_MODEL(tf_config, field)
#define ON(t) (1u << (t))

/* ---- shared by the variants ---------------------------------------------------------- */

static const sl_key geometry_keys[] = {
    {.section = "scene",
     .name = "geometry",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(geometry),
     .choices = "line|planar|axisymmetric",
     .help = "line: the 1-D column or the shear layer; planar or "
             "axisymmetric: the 2-D model"},
};
TABLE(tf_geometry_keys, geometry_keys);

#define SOLID_KEYS(phi_max_def)                                                                                 \
  {.section = "solid",                                                                                          \
   .name = "density",                                                                                           \
   .type = SL_KEY_REAL,                                                                                         \
   SL_AT_SCENE(solid.density),                                                                                  \
   .flags = SL_KEY_REQUIRED,                                                                                    \
   .min = 1e-3,                                                                                                 \
   .max = 1e5,                                                                                                  \
   .units = "kg m^-3",                                                                                          \
   .help = "particle density"},                                                                                 \
      {.section = "solid",                                                                                      \
       .name = "diameter",                                                                                      \
       .type = SL_KEY_REAL,                                                                                     \
       SL_AT_SCENE(solid.diameter),                                                                             \
       .flags = SL_KEY_REQUIRED,                                                                                \
       .min = 1e-9,                                                                                             \
       .max = 1.0,                                                                                              \
       .units = "m",                                                                                            \
       .help = "particle diameter"},                                                                            \
      {.section = "solid",                                                                                      \
       .name = "sphericity",                                                                                    \
       .type = SL_KEY_REAL,                                                                                     \
       SL_AT_SCENE(solid.sphericity),                                                                           \
       .def = 1.0,                                                                                              \
       .min = 0.01,                                                                                             \
       .max = 1.0,                                                                                              \
       .help = "particle sphericity"},                                                                          \
  {                                                                                                             \
    .section = "solid", .name = "phi_max", .type = SL_KEY_REAL, SL_AT_SCENE(solid.phi_max), .def = phi_max_def, \
    .min = 0.01, .max = 0.99, .help = "maximum packing fraction"                                                \
  }

static const sl_key solid_column_keys[] = {
    SOLID_KEYS(0.64),
    {.section = "solid",
     .name = "porosity_max",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.porosity_max),
     .min = 0.01,
     .max = 0.99,
     .def_doc = "1 - phi_max",
     .help = "the loosest porosity: another way to give phi_max"},
};
TABLE(tf_solid_column_keys, solid_column_keys);

static const sl_key solid_plane_keys[] = {
    SOLID_KEYS(0.64),
    {.section = "solid",
     .name = "porosity_max",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.porosity_max),
     .min = 0.01,
     .max = 0.99,
     .def_doc = "1 - phi_max",
     .help = "the loosest porosity: another way to give phi_max"},
    {.section = "solid",
     .name = "viscosity",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.viscosity),
     .min = 0.0,
     .max = 1e7,
     .units = "Pa s",
     .help = "a constant solids viscosity (added to the closures')"},
};
TABLE(tf_solid_plane_keys, solid_plane_keys);

static const sl_key solid_shear_keys[] = {
    SOLID_KEYS(0.63),
    {.section = "solid",
     .name = "viscosity",
     .type = SL_KEY_REAL,
     SL_AT_SCENE(solid.viscosity),
     .min = 0.0,
     .max = 1e7,
     .units = "Pa s",
     .help = "a constant solids viscosity (added to the closures')"},
};
TABLE(tf_solid_shear_keys, solid_shear_keys);

/* [two_fluid] keys of every variant */
#define NUMERIC_KEYS                                                                                            \
  {.section = "two_fluid",                                                                                      \
   .name = "iterations",                                                                                        \
   .type = SL_KEY_INT,                                                                                          \
   C(iterations),                                                                                               \
   .def = 50,                                                                                                   \
   .min = 1,                                                                                                    \
   .max = 1000,                                                                                                 \
   .help = "most iterations of one implicit step before it is retried smaller"},                                \
      {.section = "two_fluid",                                                                                  \
       .name = "tolerance",                                                                                     \
       .type = SL_KEY_REAL,                                                                                     \
       C(tolerance),                                                                                            \
       .def = 1e-9,                                                                                             \
       .min = 1e-15,                                                                                            \
       .max = 1e-2,                                                                                             \
       .help = "a step has converged when the velocities change by less than this times their scale"},          \
      {.section = "two_fluid",                                                                                  \
       .name = "steady_tolerance",                                                                              \
       .type = SL_KEY_REAL,                                                                                     \
       C(steady_tolerance),                                                                                     \
       .min = 0.0,                                                                                              \
       .max = 1.0,                                                                                              \
       .units = "s^-1",                                                                                         \
       .help =                                                                                                  \
           "stop when the largest rate of change falls below this (0: run to [time] "                           \
           "end)"},                                                                                             \
  {                                                                                                             \
    .section = "two_fluid", .name = "motion", .type = SL_KEY_CHOICE, C(motion), .choices = "column|shear",      \
    .help =                                                                                                     \
        "column (the phases move along the line, or in 2-D) or shear (across the line, between two walls; phi " \
        "held)"                                                                                                 \
  }

/* [two_fluid] keys of the column and the 2-D model */
#define TRANSPORT_KEYS                                                                                    \
  {.section = "two_fluid",                                                                                \
   .name = "cfl",                                                                                         \
   .type = SL_KEY_REAL,                                                                                   \
   C(cfl),                                                                                                \
   .def = 0.9,                                                                                            \
   .min = 1e-3,                                                                                           \
   .max = 1.0,                                                                                            \
   .help = "fraction of the stable sub-step of the solids transport"},                                    \
      {.section = "two_fluid",                                                                            \
       .name = "diffusivity",                                                                             \
       .type = SL_KEY_REAL,                                                                               \
       C(diffusivity),                                                                                    \
       .min = 0.0,                                                                                        \
       .max = 1e3,                                                                                        \
       .units = "m^2 s^-1",                                                                               \
       .help = "particle diffusivity D: the extra solids flux -D grad(phi)"},                             \
      {.section = "two_fluid",                                                                            \
       .name = "order",                                                                                   \
       .type = SL_KEY_INT,                                                                                \
       C(order),                                                                                          \
       .def = 1,                                                                                          \
       .min = 1,                                                                                          \
       .max = 2,                                                                                          \
       .help = "solids transport: 1 upwind, 2 MUSCL (limited, Heun sub-steps)"},                          \
      {.section = "two_fluid",                                                                            \
       .name = "limiter",                                                                                 \
       .type = SL_KEY_CHOICE,                                                                             \
       C(limiter),                                                                                        \
       .choices = "minmod|mc",                                                                            \
       .help = "the slope limiter of order 2"},                                                           \
  {                                                                                                       \
    .section = "two_fluid", .name = "case", .type = SL_KEY_INT, C(case_index), .min = 0, .max = 1000000,  \
    .help = "a number the [initial] and inlet expressions read as `case` (several variants in one scene)" \
  }

/* ---- the 1-D column ---------------------------------------------------------------------- */

static const sl_key column_keys[] = {
    NUMERIC_KEYS,
    TRANSPORT_KEYS,
    {.section = "flow",
     .name = "gravity",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(flow.gravity),
     .max_n = 3,
     .def_list = (const double[]){-9.81},
     .n_def = 1,
     .units = "m s^-2",
     .help = "gravity along x (x is the height when gravity is negative)"},
    {.section = "output",
     .name = "interface",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(output.interface),
     .max_n = SL_REALS_MAX,
     .min = 0.0,
     .max = 1.0,
     .help = "levels of phi whose heights are written as interface_height_K"},
    {.section = "initial",
     .name = "phi",
     .type = SL_KEY_EXPR,
     C(phi),
     .vars = "x,y,case",
     .def_doc = "required (or porosity)",
     .help = "the initial solids fraction"},
    {.section = "initial",
     .name = "porosity",
     .type = SL_KEY_EXPR,
     C(porosity),
     .vars = "x,y,case",
     .help = "the initial porosity 1 - phi (instead of phi)"},
    {.section = "initial",
     .name = "from",
     .type = SL_KEY_STRING,
     C(from),
     .def_text = "",
     .help = "start from the last output of this file (its phi, and nbar when it has it): e.g. a deposit another run "
             "settled; relative to the working folder"},
    {.section = "initial",
     .name = "nbar",
     .type = SL_KEY_EXPR,
     C(nbar),
     .vars = "x,y,case",
     .def_doc = "required with a solids pressure of nbar",
     .help = "the reference porosity of each cell (Pringle 2001 "
             "eq 4.30), a state [closure.densification] evolves"},
    {.section = "shaking",
     .name = "record",
     .type = SL_KEY_STRING,
     C(lq.record),
     .def_text = "",
     .help = "the base acceleration: a CSV of time (s), acceleration (relative to the scene file)"},
    {.section = "shaking",
     .name = "units",
     .type = SL_KEY_CHOICE,
     C(lq.units),
     .choices = "g|si",
     .help = "the record's acceleration in g (9.81 m/s^2) or m/s^2"},
    {.section = "shaking",
     .name = "peak",
     .type = SL_KEY_REAL,
     C(lq.peak),
     .min = 0.0,
     .max = 10.0,
     .units = "g",
     .help = "scale the record to this peak |a| (0: as given)"},
    {.section = "shaking",
     .name = "start",
     .type = SL_KEY_REAL,
     C(lq.start),
     .min = 0.0,
     .max = 1e9,
     .units = "s",
     .help = "the run time at which the record's t = 0 falls"},
    {.section = "shaking",
     .name = "k2max",
     .type = SL_KEY_REAL,
     C(lq.k2max),
     .def = 50.0,
     .min = 1.0,
     .max = 300.0,
     .help = "Seed & Idriss (1970): G0 = 220 K2max sqrt(P_s) kPa, P_s in kPa; 30-70 for sands (Pringle's 0.4-0.6 is "
             "an erratum)"},
    {.section = "shaking",
     .name = "shear_modulus",
     .type = SL_KEY_REAL,
     C(lq.shear_modulus),
     .min = 0.0,
     .max = 1e12,
     .units = "Pa",
     .help = "a linear elastic deposit of this constant modulus instead of K2max's law and the modulus reduction (0: "
             "those; a verification)"},
    {.section = "shaking",
     .name = "friction_angle",
     .type = SL_KEY_REAL,
     C(lq.friction_angle),
     .def = 33.0,
     .min = 1.0,
     .max = 60.0,
     .units = "deg",
     .help = "tau_max = P_s tan(angle): Hardin & Drnevich's reference strain "
             "tau_max/G0"},
    {.section = "shaking",
     .name = "damping",
     .type = SL_KEY_REAL,
     C(lq.damping),
     .def = 0.05,
     .min = 0.0,
     .max = 1.0,
     .help = "viscous damping ratio xi at damping_frequency: eta = 2 xi G0 / omega"},
    {.section = "shaking",
     .name = "damping_frequency",
     .type = SL_KEY_REAL,
     C(lq.damping_frequency),
     .def = 2.0,
     .min = 1e-3,
     .max = 1e3,
     .units = "Hz",
     .help = "the frequency at which the damping ratio holds"},
    {.section = "shaking",
     .name = "residual_viscosity",
     .type = SL_KEY_REAL,
     C(lq.residual_viscosity),
     .min = 0.0,
     .max = 1e9,
     .units = "Pa s",
     .help = "a viscosity the sand keeps when P_s vanishes (liquefied)"},
    {.section = "shaking",
     .name = "mass",
     .type = SL_KEY_CHOICE,
     C(lq.mass),
     .choices = "mixture|solid",
     .help = "the density of the horizontal equation: the mixture's, or rho_s as printed (thesis eq 5.13)"},
    {.section = "deposit",
     .name = "settle",
     .type = SL_KEY_REAL,
     C(lq.settle),
     .min = 0.0,
     .max = 1e12,
     .units = "s",
     .help = "let [initial]'s state settle and consolidate for up to this long before t = 0 (0: start as given)"},
    {.section = "deposit",
     .name = "settle_dt",
     .type = SL_KEY_REAL,
     C(lq.settle_dt),
     .def = 1.0,
     .min = 1e-9,
     .max = 1e9,
     .units = "s",
     .help = "the step of the settling"},
    {.section = "deposit",
     .name = "settle_tolerance",
     .type = SL_KEY_REAL,
     C(lq.settle_tolerance),
     .def = 1e-9,
     .min = 0.0,
     .max = 1.0,
     .units = "s^-1",
     .help = "the settling ends when max |dphi/dt| falls below this"},
    {.section = "deposit",
     .name = "phi_min",
     .type = SL_KEY_REAL,
     C(lq.deposit_phi),
     .def = 0.3,
     .min = 1e-3,
     .max = 0.99,
     .help = "the cells from the base up with phi at least this at t = 0 are the deposit"},
    {.section = "deposit",
     .name = "liquefied_ratio",
     .type = SL_KEY_REAL,
     C(lq.liquefied_ratio),
     .def = 0.05,
     .min = 0.0,
     .max = 1.0,
     .help = "a cell is liquefied while P_s is below this fraction of its value at t = 0"},
    {.section = "deposit",
     .name = "nbar_drop",
     .type = SL_KEY_REAL,
     C(lq.nbar_drop),
     .min = -0.5,
     .max = 0.5,
     .help = "lower nbar in the deposit by this at t = 0 (an instantaneous load: Terzaghi's consolidation)"},
    {.section = "deposit",
     .name = "nbar_min",
     .type = SL_KEY_REAL,
     C(lq.nbar_min),
     .min = 0.01,
     .max = 0.99,
     .def_doc = "the nbar whose P_s at phi_max is twice the deposit's largest",
     .help = "the densest reference "
             "porosity densification may reach"},
    {.section = "solver",
     .name = "linear",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.linear),
     .choices = SL_SCENE_LINEAR_CHOICES,
     .help = "the coupled system's solver: auto, the banded LU of the column's n "
             "x 1 grid; a named one, the general sparse factorisation"},
    {.section = "boundary",
     .name = "type",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(tfc_boundary, type),
     .choices = "wall|inlet|outlet",
     .help = "wall (closed), inlet (fluid enters, solids held), outlet (a pressure; "
             "solids leave when carried)"},
    {.section = "boundary",
     .name = "velocity",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(tfc_boundary, velocity),
     .vars = "t,case",
     .units = "m s^-1",
     .when_type = ON(TF_INLET),
     .when_doc = "an inlet",
     .help = "the superficial fluid velocity entering"},
    {.section = "boundary",
     .name = "porosity",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(tfc_boundary, porosity),
     .vars = "t,case",
     .when_type = ON(TF_INLET),
     .when_doc = "an inlet",
     .help =
         "instead of velocity: the porosity of the homogeneous bed the inflow holds at rest (its drag equilibrium)"},
    {.section = "boundary",
     .name = "pressure",
     .type = SL_KEY_REAL,
     SL_AT_BOUNDARY(tfc_boundary, pressure),
     .min = -1e12,
     .max = 1e12,
     .units = "Pa",
     .when_type = ON(TF_OUTLET),
     .when_doc = "an outlet",
     .help = "the outlet's pressure"},
};
TABLE(tf_column_keys, column_keys);

static const char *const column_fields[] = {"phi",          "velocity_solid", "velocity_fluid",  "pressure",
                                            "nbar",         "stress_ratio",   "excess_pressure", "pore_pressure_ratio",
                                            "shear_strain", "solids_pressure"};

const sl_schema sl_two_fluid_column_schema = {
    .model = "two_fluid",
    .variant = "motion = column, geometry = line",
    .title = "1-D column",
    .summary =
        "Fluid and solids momentum with one pressure, implicit drag and solids pressure (Pringle 2001; "
        "Gidaspow 1994 model A) in a vertical column: fluidised and settling beds, inflow steps, bounded "
        "conservative transport of phi.",
    .when = {{"two_fluid", "motion", "column", "column"}, {"scene", "geometry", "line", "line"}},
    .n_when = 2,
    .tables = {&sl_keys_scene, &tf_geometry_keys, &sl_keys_mesh, &sl_keys_fluid, &tf_solid_column_keys,
               &sl_keys_time_steps, &sl_keys_output, &sl_keys_plugins, &tf_column_keys},
    .n_tables = 9,
    .roles = {{"drag", 1, "the interphase drag K(phi, slip) (e.g. model = wen_yu)"},
              {"solids_pressure", 0, "the solids pressure p_s(phi) of the particles in contact (or p_s(phi, nbar))"},
              {"densification", 0, "a shaken deposit: nbar from the cell's cyclic shear (e.g. model = byrne)"}},
    .n_roles = 3,
    .config_size = sizeof(tf_config),
    .boundary_size = sizeof(tfc_boundary),
    .fields = column_fields,
    .n_fields = 10,
};

/* ---- the 2-D model ---------------------------------------------------------------------------- */

static const sl_key plane_keys[] = {
    NUMERIC_KEYS,
    TRANSPORT_KEYS,
    {.section = "two_fluid",
     .name = "granular_temperature",
     .type = SL_KEY_CHOICE,
     C(granular_temperature),
     .def = 1,
     .choices = "transport|algebraic",
     .help = "with [closure.granular]: theta's transport equation or its local "
             "balance"},
    {.section = "two_fluid",
     .name = "interphase_dissipation",
     .type = SL_KEY_BOOL,
     C(interphase_dissipation),
     .def = 1,
     .help = "with [closure.granular]: the sink -3 K theta of granular energy by the drag"},
    {.section = "two_fluid",
     .name = "acceleration",
     .type = SL_KEY_CHOICE,
     C(acceleration),
     .choices = "none|anderson",
     .def_doc = "anderson with [closure.granular], else none",
     .help = "Anderson acceleration of the step's iteration"},
    {.section = "two_fluid",
     .name = "kinetic_pressure",
     .type = SL_KEY_BOOL,
     C(kinetic_pressure),
     .def_doc = "true with a transported theta when [closure.granular] gives p_s",
     .help = "the kinetic theory's p_s(phi, theta) joins the solids pressure"},
    {.section = "two_fluid",
     .name = "column_form",
     .type = SL_KEY_BOOL,
     C(column_form),
     .help = "a grid one cell across, gravity along it: the 1-D column's equations (no fluid viscous stress, the "
             "weight's phi that of the drag, the fluid's inertia and the pressure from the mixture flux)"},
    {.section = "two_fluid",
     .name = "turbulence_k",
     .type = SL_KEY_EXPR,
     C(turb_k),
     .vars = "x,y,case",
     .units = "m^2 s^-2",
     .def_doc = "required with [closure.turbulence]",
     .help = "the fluid's turbulent kinetic energy, as the scene states it, for [closure.turbulence]'s eddy viscosity "
             "that disperses the solids"},
    {.section = "two_fluid",
     .name = "turbulence_epsilon",
     .type = SL_KEY_EXPR,
     C(turb_eps),
     .vars = "x,y,case",
     .units = "m^2 s^-3",
     .def_doc = "required with [closure.turbulence]",
     .help = "its dissipation rate"},
    {.section = "two_fluid",
     .name = "turbophoresis",
     .type = SL_KEY_BOOL,
     C(turbophoresis),
     .help = "with [closure.turbulence]: the solids' drift -phi tau_p grad(2k/3) down the turbulent intensity, "
             "tau_p = phi rho_s/K of the drag (turbophoresis; Young & Leeming 1997), added to the dispersion's "
             "flux"},
    {.section = "two_fluid",
     .name = "swirl",
     .type = SL_KEY_BOOL,
     C(swirl),
     .help = "axisymmetric: both phases' azimuthal velocities, driven by walls' angular_velocity (carried by the "
             "meridional flow; its centrifugal force acts back on it with centrifugal = true)"},
    {.section = "two_fluid",
     .name = "centrifugal",
     .type = SL_KEY_BOOL,
     C(centrifugal),
     .help = "with swirl: the centrifugal force rho alpha u_theta^2 / r of each phase in its radial momentum (a "
             "two-way swirl)"},
    {.section = "body",
     .name = "box",
     .type = SL_KEY_REALS,
     C(body_box),
     .max_n = 4,
     .min = -1e6,
     .max = 1e6,
     .flags = SL_KEY_NAMED,
     .units = "m",
     .def_doc = "none (no body)",
     .help = "a solid body: x0, x1, y0, y1 (r and z when axisymmetric) of the box it fills; the cells whose centres "
             "lie inside are removed, its edges inside the domain on grid lines; its faces are no-slip walls"},
    {.section = "body",
     .name = "angular_velocity",
     .type = SL_KEY_REAL,
     C(body_omega),
     .min = -1e6,
     .max = 1e6,
     .flags = SL_KEY_NAMED,
     .units = "rad s^-1",
     .help = "with [two_fluid] swirl: the body's rotation about the axis (a rotor)"},
    {.section = "flow",
     .name = "gravity",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(flow.gravity),
     .max_n = 3,
     .def_list = (const double[]){0.0, -9.81},
     .n_def = 2,
     .units = "m s^-2",
     .help = "gravity (x, y)"},
    {.section = "flow",
     .name = "convection",
     .type = SL_KEY_BOOL,
     SL_AT_SCENE(flow.convection),
     .help = "the phases' convective acceleration rho alpha (u.grad)u"},
    {.section = "solver",
     .name = "linear",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.linear),
     .def = 2,
     .choices = SL_SCENE_LINEAR_CHOICES,
     .help = "the sparse direct solver of the coupled system (auto on a grid one "
             "cell across: banded LU)"},
    {.section = "solver",
     .name = "ordering",
     .type = SL_KEY_CHOICE,
     SL_AT_SCENE(solver.ordering),
     .def = 2,
     .choices = SL_SCENE_ORDERING_CHOICES,
     .help = "klu's fill-reducing ordering"},
    {.section = "initial",
     .name = "phi",
     .type = SL_KEY_EXPR,
     C(phi),
     .vars = "x,y,case",
     .def_doc = "required (or porosity)",
     .help = "the initial solids fraction"},
    {.section = "initial",
     .name = "porosity",
     .type = SL_KEY_EXPR,
     C(porosity),
     .vars = "x,y,case",
     .help = "the initial porosity 1 - phi (instead of phi)"},
    {.section = "initial",
     .name = "velocity_fluid",
     .type = SL_KEY_EXPRS,
     C(velocity_fluid),
     .vars = "x,y,case",
     .max_n = 2,
     .units = "m s^-1",
     .help = "the fluid's velocity, two components (default at rest)"},
    {.section = "initial",
     .name = "velocity_solid",
     .type = SL_KEY_EXPRS,
     C(velocity_solid),
     .vars = "x,y,case",
     .max_n = 2,
     .units = "m s^-1",
     .help = "the solids' velocity, two components (default at rest)"},
    {.section = "initial",
     .name = "theta",
     .type = SL_KEY_EXPR,
     C(theta),
     .vars = "x,y,case",
     .units = "m^2 s^-2",
     .def_doc = "1e-6",
     .help = "a transported granular temperature"},
    {.section = "boundary",
     .name = "type",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(tfp_boundary, type),
     .choices = "wall|slip|axis|inlet|outlet|periodic",
     .help = "wall, slip (both phases), axis (r = 0), inlet (fluid enters; solids held, or entering with "
             "solids_flux), outlet (a pressure), periodic (both opposite sides)"},
    {.section = "boundary",
     .name = "velocity",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(tfp_boundary, velocity),
     .vars = "x,y,t,case",
     .units = "m s^-1",
     .when_type = ON(TFP_WALL) | ON(TFP_INLET),
     .when_doc = "an inlet (the inflow) or a wall (its speed along itself)",
     .help = "inlet: the superficial fluid velocity entering; wall: its speed along itself (+x along the bottom and "
             "top, +y along the sides)"},
    {.section = "boundary",
     .name = "pressure",
     .type = SL_KEY_REAL,
     SL_AT_BOUNDARY(tfp_boundary, pressure),
     .min = -1e12,
     .max = 1e12,
     .units = "Pa",
     .when_type = ON(TFP_OUTLET),
     .when_doc = "an outlet",
     .help = "the outlet's pressure"},
    {.section = "boundary",
     .name = "solids",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(tfp_boundary, solids),
     .choices = "no_slip|free_slip|wall_stress",
     .when_type = ON(TFP_WALL),
     .when_doc = "a wall",
     .help = "the solids at a wall (wall_stress: [closure.wall_stress] against their slip)"},
    {.section = "boundary",
     .name = "angular_velocity",
     .type = SL_KEY_REAL,
     SL_AT_BOUNDARY(tfp_boundary, angular_velocity),
     .min = -1e6,
     .max = 1e6,
     .units = "rad s^-1",
     .when_type = ON(TFP_WALL),
     .when_doc = "a wall",
     .help = "with [two_fluid] swirl: the wall's rotation about the "
             "axis (u_theta = omega r)"},
    {.section = "boundary",
     .name = "solids_flux",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(tfp_boundary, solids_flux),
     .vars = "x,y,t,case",
     .units = "m s^-1",
     .when_type = ON(TFP_INLET),
     .when_doc = "an inlet",
     .def_doc = "none (the solids are held)",
     .help = "the superficial solids velocity entering (solids volume flux per area: G_s / rho_s), with the fluid"},
};
TABLE(tf_plane_keys, plane_keys);

static const char *const plane_fields[] = {"phi",   "velocity_solid", "velocity_fluid", "pressure", "solids_pressure",
                                           "theta", "swirl_fluid",    "swirl_solid"};

/* The keys that chose the solids' turbulent dispersion before it was a closure. */
static const sl_moved_key plane_moved[] = {
    {"two_fluid", "dispersion",
     "[closure.turbulent_dispersion] model = gradient (and [two_fluid] turbophoresis = true for the turbophoretic "
     "drift)"},
    {"two_fluid", "dispersion_schmidt", "[closure.turbulent_dispersion] model = gradient with schmidt = ..."},
};

const sl_schema sl_two_fluid_plane_schema = {
    .model = "two_fluid",
    .variant = "motion = column, geometry = planar | axisymmetric",
    .title = "2-D model",
    .summary =
        "The two-fluid equations on a staggered (MAC) grid of a planar or axisymmetric rectangle: walls with "
        "solids wall-stress closures, inlets, outlets, periodic sides; solids viscosity and kinetic theory "
        "(transported or algebraic granular temperature), Anderson-accelerated implicit steps.",
    .when = {{"two_fluid", "motion", "column", "column"}, {"scene", "geometry", "planar|axisymmetric", "line"}},
    .n_when = 2,
    .tables = {&sl_keys_scene, &tf_geometry_keys, &sl_keys_mesh, &sl_keys_fluid, &tf_solid_plane_keys,
               &sl_keys_time_steps, &sl_keys_output, &sl_keys_plugins, &tf_plane_keys},
    .n_tables = 9,
    .roles = {{"drag", 1, "the interphase drag K(phi, slip) (e.g. model = wen_yu)"},
              {"solids_pressure", 0, "the solids pressure p_s(phi) of the particles in contact"},
              {"viscosity", 0, "a suspension viscosity: the solids' share of it"},
              {"granular", 0, "kinetic theory: the solids viscosity, conductivity, dissipation and pressure of theta"},
              {"wall_stress", 0, "the solids' stress at walls with solids = wall_stress"},
              {"turbulence", 0, "the eddy viscosity mu_t(k, epsilon) that disperses the solids (model = k_epsilon)"},
              {"turbulent_dispersion", 0,
               "with [closure.turbulence]: the solids' turbulent dispersivity D_t at each face's nu_t (model = "
               "gradient: nu_t/sigma; without it nu_t, the gradient form with Schmidt number 1; simonin's t_fs and "
               "k_fs are not computed here)"}},
    .n_roles = 7,
    .config_size = sizeof(tf_config),
    .boundary_size = sizeof(tfp_boundary),
    .fields = plane_fields,
    .n_fields = 8,
    .moved = plane_moved,
    .n_moved = (int)(sizeof plane_moved / sizeof plane_moved[0]),
};

/* ---- the shear layer ------------------------------------------------------------------------- */

static const sl_key shear_keys[] = {
    NUMERIC_KEYS,
    {.section = "two_fluid",
     .name = "cross_section",
     .type = SL_KEY_CHOICE,
     C(cross_section),
     .choices = "planar|annular",
     .help = "a planar gap, or coaxial cylinders with x the radius"},
    {.section = "two_fluid",
     .name = "granular_temperature",
     .type = SL_KEY_CHOICE,
     C(granular_temperature),
     .choices = "transport|algebraic",
     .help = "with [closure.granular]: theta's transport equation or its local "
             "balance"},
    {.section = "two_fluid",
     .name = "interphase_dissipation",
     .type = SL_KEY_BOOL,
     C(interphase_dissipation),
     .def = 1,
     .help = "with [closure.granular]: the sink -3 K theta of granular energy by the drag"},
    {.section = "flow",
     .name = "gravity",
     .type = SL_KEY_REALS,
     SL_AT_SCENE(flow.gravity),
     .max_n = 3,
     .def_list = (const double[]){-9.81},
     .n_def = 1,
     .units = "m s^-2",
     .help = "gravity: only its magnitude enters (the closures' input)"},
    {.section = "initial",
     .name = "phi",
     .type = SL_KEY_EXPR,
     C(sh_phi),
     .vars = "x",
     .def_doc = "required",
     .help = "the solids fraction (held)"},
    {.section = "initial",
     .name = "theta",
     .type = SL_KEY_EXPR,
     C(sh_theta),
     .vars = "x",
     .def_text = "1e-6",
     .units = "m^2 s^-2",
     .help = "the granular temperature (with [closure.granular])"},
    {.section = "initial",
     .name = "velocity_fluid",
     .type = SL_KEY_EXPR,
     C(sh_uf),
     .vars = "x",
     .def_text = "0",
     .units = "m s^-1",
     .help = "the fluid's velocity across the line"},
    {.section = "initial",
     .name = "velocity_solid",
     .type = SL_KEY_EXPR,
     C(sh_us),
     .vars = "x",
     .def_text = "0",
     .units = "m s^-1",
     .help = "the solids' velocity across the line"},
    {.section = "boundary",
     .name = "type",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(sh_boundary, type),
     .choices = "wall",
     .help = "both ends are walls"},
    {.section = "boundary",
     .name = "velocity",
     .type = SL_KEY_EXPR,
     SL_AT_BOUNDARY(sh_boundary, velocity),
     .vars = "t",
     .def_text = "0",
     .units = "m s^-1",
     .help = "the wall's speed (annular: its surface speed, omega r)"},
    {.section = "boundary",
     .name = "solids",
     .type = SL_KEY_CHOICE,
     SL_AT_BOUNDARY(sh_boundary, solids),
     .choices = "no_slip|free_slip|wall_stress",
     .help = "the solids at the wall (wall_stress: [closure.wall_stress])"},
};
TABLE(tf_shear_keys, shear_keys);

static const char *const shear_fields[] = {"phi", "velocity_fluid", "velocity_solid", "theta", "solids_pressure"};

const sl_schema sl_two_fluid_shear_schema = {
    .model = "two_fluid",
    .variant = "motion = shear",
    .title = "shear layer",
    .summary =
        "Fluid and solids moving across a 1-D mesh between two walls, planar or annular: drag, solids "
        "viscosity (constant, a suspension viscosity's share, kinetic theory), the granular temperature's "
        "balance, wall-stress closures (Bagnold, Johnson & Jackson, Navier slip).",
    .when = {{"two_fluid", "motion", "shear", "column"}},
    .n_when = 1,
    .tables = {&sl_keys_scene, &tf_geometry_keys, &sl_keys_mesh, &sl_keys_fluid, &tf_solid_shear_keys,
               &sl_keys_time_steps, &sl_keys_output, &sl_keys_plugins, &tf_shear_keys},
    .n_tables = 9,
    .roles = {{"drag", 1, "the interphase drag K(phi, slip) (e.g. model = wen_yu)"},
              {"granular", 0, "kinetic theory: mu_s, kappa and gamma of (phi, theta)"},
              {"wall_stress", 0, "the solids' stress at walls with solids = wall_stress"},
              {"viscosity", 0, "a suspension viscosity: the solids' share of it"}},
    .n_roles = 4,
    .config_size = sizeof(tf_config),
    .boundary_size = sizeof(sh_boundary),
    .fields = shear_fields,
    .n_fields = 5,
};
