/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The pipe model's schema: every key it reads (pipe.h). */
#include "core/models/pipe/pipe.h"

#include "core/models/pipe/pipe_impl.h"
#include "core/scene/keys.h"

#define TABLE(name, keys) static const sl_key_table name = {keys, (int)(sizeof keys / sizeof keys[0])}
#define C(field) SL_AT_MODEL(pipe_config, field)

static const sl_key pipe_keys[] = {
    {.section = "pipe", .name = "diameter", .type = SL_KEY_REAL, C(diameter), .flags = SL_KEY_REQUIRED, .min = 1e-4,
     .max = 10.0, .units = "m", .help = "the pipe's inner diameter D"},
    {.section = "pipe", .name = "bulk_velocity", .type = SL_KEY_REAL, C(bulk_velocity), .flags = SL_KEY_REQUIRED,
     .min = 1e-3, .max = 100.0, .units = "m s^-1",
     .help = "the mixture's bulk velocity V = Q/A along the flow (the pressure gradient is what meets it)"},
    {.section = "pipe", .name = "solids_fraction", .type = SL_KEY_REAL, C(solids_fraction), .min = 0.0, .max = 0.73,
     .help = "the section-mean solids fraction, held (0: water alone); with length: the inlet's, uniform"},
    {.section = "pipe", .name = "cells", .type = SL_KEY_INT, C(cells), .def = 40, .min = 4, .max = 4000,
     .help = "radial cells"},
    {.section = "pipe", .name = "wall_cell", .type = SL_KEY_REAL, C(wall_cell), .min = 1e-9, .max = 5.0, .units = "m",
     .def_doc = "R / cells (uniform)",
     .help = "the width of the cell at the wall; the others grow geometrically towards the axis (its centre is the "
             "wall function's node: y+ of 30-200)"},
    {.section = "pipe", .name = "wall_y_plus", .type = SL_KEY_REAL, C(wall_y_plus), .min = 1.0, .max = 1e4,
     .help = "instead of wall_cell: the wall cell's centre at this y+ of water alone at the bulk velocity (u_tau from "
             "Churchill's 1977 smooth-pipe friction factor)"},
    {.section = "pipe", .name = "iterations", .type = SL_KEY_INT, C(iterations), .def = 5000, .min = 1, .max = 1000000,
     .help = "most outer iterations of the steady solve"},
    {.section = "pipe", .name = "tolerance", .type = SL_KEY_REAL, C(tolerance), .def = 1e-8, .min = 1e-14,
     .max = 1e-2, .help = "converged when an iteration changes u, k, epsilon and phi by less than this (relative)"},
    {.section = "pipe", .name = "relaxation", .type = SL_KEY_REAL, C(relaxation), .def = 0.8, .min = 0.01, .max = 1.0,
     .help = "under-relaxation of the velocities between iterations"},
    {.section = "pipe", .name = "pseudo_step", .type = SL_KEY_REAL, C(pseudo_step), .def = 5.0, .min = 1e-3,
     .max = 1e6, .help = "the pseudo-time step of k and epsilon in units of the local k/epsilon"},
    {.section = "pipe", .name = "solids_wall", .type = SL_KEY_CHOICE, C(solids_wall),
     .choices = "no_slip|free_slip|wall_stress", .def = PIPE_FREE_SLIP,
     .help = "the solids at the wall (wall_stress: [closure.wall_stress.solids] against their slip)"},
    {.section = "pipe", .name = "kinetic_pressure", .type = SL_KEY_BOOL, C(kinetic_pressure), .def = 1,
     .help = "with [closure.granular]: its p_s(phi, theta) in the radial solids balance (false: its viscosity only)"},
    {.section = "pipe", .name = "granular_temperature", .type = SL_KEY_CHOICE, C(granular_temperature),
     .choices = "algebraic|transport", .def = PIPE_THETA_ALGEBRAIC,
     .help = "with [closure.granular]: theta from its local balance, or its transport equation with conduction "
             "(Krampa 2009 eq 5.10 in the standard form; the wall adiabatic, or the solids' wall closure's "
             "theta_flux)"},
    {.section = "pipe", .name = "modulation", .type = SL_KEY_CHOICE, C(modulation), .choices = "none|simonin",
     .help = "the particles' modulation of the fluid's k and epsilon: none (Krampa's models A, B) or Simonin's "
             "K (k_fs - 2k) with Tchen's equilibrium k_fs (his model C, eqs 4.80-4.83, the drift terms zero here)"},
    {.section = "pipe", .name = "c_eps3", .type = SL_KEY_REAL, C(c_eps3), .def = 1.2, .min = 0.0, .max = 10.0,
     .help = "modulation = simonin: C_eps3 of the epsilon equation's C_eps3 (eps/k) times the k modulation "
             "(Krampa 2009 Table 4.1: 1.2)"},
    {.section = "pipe", .name = "solids_viscosity", .type = SL_KEY_CHOICE, C(solids_viscosity),
     .choices = "eddy|peirano_leckner",
     .help = "the solids' turbulent viscosity: the dispersed phase's eddy viscosity c_s rho_s nu_t/sigma (eddy), or "
             "Peirano & Leckner's kinetic and collisional viscosity with Tchen's equilibrium k_s and k_fs "
             "(Krampa 2009 model C, eqs 5.15-5.19; replaces [closure.granular])"},
    {.section = "pipe", .name = "solids_turbulence", .type = SL_KEY_CHOICE, C(solids_turbulence),
     .choices = "equilibrium|transported", .def = PIPE_SOLIDS_TURBULENCE_EQUILIBRIUM,
     .help = "solids_viscosity = peirano_leckner: model C's k_s and k_fs from Tchen's equilibrium, or from their "
             "transport equations (Krampa 2009 eqs 5.20, 5.23; Simonin 1996), which then also feed modulation and "
             "dispersion = simonin"},
    {.section = "pipe", .name = "covariance_schmidt", .type = SL_KEY_REAL, C(covariance_schmidt), .def = 1.0,
     .min = 1e-3, .max = 1e3,
     .help = "solids_turbulence = transported: sigma_kfs of the k_fs diffusion c_s rho_s nu_fs/sigma, nu_fs = k_fs "
             "t_fs/3 (Krampa 2009 eq 5.23 gives none)"},
    {.section = "pipe", .name = "restitution", .type = SL_KEY_REAL, C(restitution), .def = 0.9, .min = 0.0,
     .max = 1.0, .help = "solids_viscosity = peirano_leckner: the particles' restitution coefficient e"},
    {.section = "pipe", .name = "solids_schmidt", .type = SL_KEY_REAL, C(solids_schmidt), .def = 1.0, .min = 1e-3,
     .max = 1e3, .help = "sigma of the solids' eddy viscosity c_s rho_s nu_t/sigma (Krampa 2009 eq 6.20)"},
    {.section = "pipe", .name = "dispersion_schmidt", .type = SL_KEY_REAL, C(dispersion_schmidt), .def = 1.0,
     .min = 1e-3, .max = 1e3, .help = "sigma of the turbulent dispersion nu_t/sigma (Krampa 2009 eq 4.59: 1)"},
    {.section = "pipe", .name = "dispersion", .type = SL_KEY_CHOICE, C(dispersion), .choices = "gradient|simonin",
     .help = "the turbulent dispersivity: nu_t/sigma (gradient) or t_fs k_fs/3 with the crossing-trajectory time "
             "(simonin; Krampa 2009 eqs 4.61-4.63)"},
    {.section = "pipe", .name = "crossing_trajectory", .type = SL_KEY_REAL, C(crossing_trajectory), .def = 0.45,
     .min = 0.0, .max = 10.0,
     .help = "simonin: C_beta of t_fs (Csanady 1963: 1.8 - 1.35 cos^2, the slip along the mean motion)"},
    {.section = "pipe", .name = "length", .type = SL_KEY_REAL, C(length), .min = 1e-3, .max = 1e4, .units = "m",
     .def_doc = "none: fully developed",
     .help = "a developing pipe of this length from uniform inlet profiles, marched along z (Krampa 2009's CFX-4 "
             "set-up: 4 m); the outputs' scalars are the outlet's"},
    {.section = "pipe", .name = "axial_cells", .type = SL_KEY_INT, C(axial_cells), .def = 50, .min = 1,
     .max = 100000, .help = "with length: the uniform cells along z (Krampa 2009: 50), each centre a station"},
    {.section = "pipe", .name = "inlet_intensity", .type = SL_KEY_REAL, C(inlet_intensity), .def = 0.1, .min = 1e-4,
     .max = 1.0, .help = "with length: the inlet's turbulence intensity TI, k = 1.5 (TI V)^2 (Krampa 2009: 0.1)"},
    {.section = "pipe", .name = "inlet_length_scale", .type = SL_KEY_REAL, C(inlet_length_scale), .min = 1e-9,
     .max = 10.0, .units = "m", .def_doc = "0.007 D",
     .help = "with length: the inlet's epsilon = C_mu^(3/4) k^(3/2)/l (Krampa 2009's command file: 0.007 D)"},
    {.section = "solid", .name = "density", .type = SL_KEY_REAL, SL_AT_SCENE(solid.density), .def = 2500.0,
     .min = 1e-3, .max = 1e5, .units = "kg m^-3", .help = "particle density"},
    {.section = "solid", .name = "diameter", .type = SL_KEY_REAL, SL_AT_SCENE(solid.diameter), .def = 5e-4,
     .min = 1e-9, .max = 1.0, .units = "m", .help = "particle diameter"},
    {.section = "solid", .name = "sphericity", .type = SL_KEY_REAL, SL_AT_SCENE(solid.sphericity), .def = 1.0,
     .min = 0.01, .max = 1.0, .help = "particle sphericity"},
    {.section = "solid", .name = "phi_max", .type = SL_KEY_REAL, SL_AT_SCENE(solid.phi_max), .def = 0.63, .min = 0.3,
     .max = 0.74, .help = "maximum packing (the solids fraction is held below phi_max - 0.01)"},
    {.section = "solid", .name = "viscosity", .type = SL_KEY_REAL, SL_AT_SCENE(solid.viscosity), .min = 0.0,
     .max = 1e4, .units = "Pa s",
     .help = "a constant solids viscosity added to the others (Krampa 2009 model A: 1e-8)"},
    {.section = "flow", .name = "gravity", .type = SL_KEY_REALS, SL_AT_SCENE(flow.gravity), .max_n = 1,
     .def_list = (const double[]){-9.81}, .n_def = 1, .units = "m s^-2",
     .help = "gravity along the flow: negative in up-flow, positive in down-flow"},
    {.section = "time", .name = "scheme", .type = SL_KEY_CHOICE, SL_AT_SCENE(time.scheme), .choices = "steady",
     .help = "the steady solve (the model has no other)"},
};
TABLE(pipe_key_table, pipe_keys);

static const char *const pipe_fields[PIPE_NFIELDS] = {"velocity_fluid", "velocity_solid", "phi", "k",  "epsilon",
                                                        "mu_t",           "theta",          "k_s", "k_fs"};

const sl_schema sl_pipe_schema = {
    .model = "pipe",
    .title = "fully developed vertical pipe",
    .summary = "Turbulent flow of water or of a slurry in a vertical pipe, fully developed (1-D in r on an "
               "axisymmetric grid graded towards the wall): k-epsilon with wall functions, the two-fluid axial "
               "momentum with one pressure gradient at a given bulk velocity, the radial solids balance of turbulent "
               "dispersion and solids pressure at a fixed mean solids fraction; up-flow or down-flow by the sign of "
               "gravity (Krampa 2009). With [pipe] length: the developing pipe from uniform inlet profiles on the 2-D "
               "axisymmetric grid, marched along z.",
    .tables = {&sl_keys_scene, &sl_keys_fluid, &sl_keys_output, &sl_keys_plugins, &pipe_key_table},
    .n_tables = 5,
    .roles = {{"turbulence", 1, "the fluid's turbulence (model = k_epsilon)"},
              {"wall_stress.fluid", 1, "the fluid's wall function (model = log_law)"},
              {"drag", 0, "the interphase drag K(phi, slip), with solids (e.g. model = gidaspow)"},
              {"granular", 0, "kinetic theory: mu_s, p_s and gamma of (phi, theta); theta from its local balance"},
              {"solids_pressure", 0, "a solids pressure p_s(phi) in the radial balance"},
              {"wall_stress.solids", 0, "the solids' wall stress with [pipe] solids_wall = wall_stress"}},
    .n_roles = 6,
    .config_size = sizeof(pipe_config),
    .boundary_size = 0,
    .fields = pipe_fields,
    .n_fields = PIPE_NFIELDS,
};
