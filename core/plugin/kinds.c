/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/plugin/kinds.h"

#include <math.h>
#include <string.h>

static const char *const kind_names[] = {"drag",
                                         "hindered_settling",
                                         "viscosity",
                                         "solids_pressure",
                                         "wall_stress",
                                         "granular",
                                         "migration",
                                         "turbulence",
                                         "densification",
                                         "lift",
                                         "turbulent_dispersion",
                                         "turbulence_modulation"};

/* The host's field dictionary (closure.h, "Canonical input names"): what the
 * models can supply, with the range they supply it in. The typical values are
 * those of the shipped closures (water, 1 mm sand). */
static const sl_input_info inputs[] = {
    {"phi", "1", "solids volume fraction", 0.3, 0.0, 1.0},
    {"slip", "m s^-1", "slip speed |u_f - u_s|", 0.01, 0.0, HUGE_VAL},
    {"shear_rate", "s^-1", "shear-rate magnitude sqrt(2 D:D)", 1.0, 0.0, 1e8},
    {"theta", "m^2 s^-2", "granular temperature", 1e-3, 1e-12, 1e4},
    {"rho_f", "kg m^-3", "fluid density", 1000.0, 1e-3, 1e5},
    {"mu_f", "Pa s", "fluid dynamic viscosity", 1e-3, 1e-7, 1e5},
    {"rho_s", "kg m^-3", "solid (particle) density", 2650.0, 1e-3, 1e5},
    {"d_p", "m", "particle diameter", 1e-3, 1e-8, 1.0},
    {"sphericity", "1", "particle sphericity", 1.0, 0.01, 1.0},
    {"density", "kg m^-3", "local mixture (or fluid) density", 1000.0, 1e-3, 1e5},
    {"gravity", "m s^-2", "magnitude of the effective body force per unit mass", 9.81, 0.0, 1e5},
    {"d_vessel", "m", "vessel (pipe, column) diameter; infinite when the scene gives none", 0.1, 1e-6, HUGE_VAL},
    {"wall_distance", "m", "distance of the first node off the wall from the wall", 1e-3, 1e-9, 10.0},
    {"slip_wall", "m s^-1", "tangential solids speed at the first node off the wall", 1.0, 0.0, 100.0},
    {"normal_stress", "Pa", "normal stress of the solids on the wall (their pressure at the first node off it)", 100.0,
     0.0, 1e9},
    {"u_t", "m s^-1", "terminal settling velocity of one particle", 1e-3, 0.0, 100.0},
    {"pressure", "Pa", "local pressure", 1e5, -1e12, 1e12},
    {"k", "m^2 s^-2", "turbulent kinetic energy", 1e-2, 1e-30, 1e6},
    {"epsilon", "m^2 s^-3", "dissipation rate of the turbulent kinetic energy", 1e-1, 1e-30, 1e9},
    {"nbar", "1", "reference porosity of a sand (Pringle 2001 eq 4.30), a state", 0.45, 0.01, 0.99},
    {"strain_amplitude", "1",
     "shear strain amplitude of the half-cycle ended at a strain reversal (0 between reversals)", 1e-3, 0.0, 1.0},
    {"strain_increment", "1", "|change of shear strain| over the step", 1e-4, 0.0, 1.0},
    {"strain_total", "1", "accumulated |shear strain| path", 1e-2, 0.0, 1e6},
    {"volumetric_strain", "1", "densification strain accumulated so far", 0.0, 0.0, 0.5},
    {"nu_t", "m^2 s^-1", "the fluid's eddy (turbulent) kinematic viscosity mu_t/rho_f", 1e-4, 0.0, 1e6},
    {"t_fs", "s", "eddy-particle interaction time with the crossing-trajectory effect (Csanady 1963)", 1e-2, 0.0, 1e9},
    {"k_fs", "m^2 s^-2", "fluid-particle velocity covariance <u_f'.u_s'>", 1e-2, 0.0, 1e6},
    {"drag_coefficient", "kg m^-3 s^-1", "the drag's momentum-exchange coefficient K (F_s = K (u_f - u_s))", 1e3, 0.0,
     1e12},
};
enum { N_INPUTS = (int)(sizeof inputs / sizeof inputs[0]) };
/* The same names in the same order, for suggestions (sl_input_names). */
static const char *const input_names[] = {"phi",
                                          "slip",
                                          "shear_rate",
                                          "theta",
                                          "rho_f",
                                          "mu_f",
                                          "rho_s",
                                          "d_p",
                                          "sphericity",
                                          "density",
                                          "gravity",
                                          "d_vessel",
                                          "wall_distance",
                                          "slip_wall",
                                          "normal_stress",
                                          "u_t",
                                          "pressure",
                                          "k",
                                          "epsilon",
                                          "nbar",
                                          "strain_amplitude",
                                          "strain_increment",
                                          "strain_total",
                                          "volumetric_strain",
                                          "nu_t",
                                          "t_fs",
                                          "k_fs",
                                          "drag_coefficient"};
_Static_assert(sizeof input_names / sizeof input_names[0] == sizeof inputs / sizeof inputs[0],
               "one name per input of the dictionary");

/* The kinds' contracts (`sluice closure kinds`, docs/closure-kinds.md); what
 * the models in core/models read is checked where they bind the closure. */
static const sl_kind_info contracts[] = {
    [SL_KIND_DRAG] =
        {"momentum-exchange coefficient K between fluid and solids: the force on the solids per unit volume is "
         "F_s = K (u_f - u_s)",
         {"phi", "slip"},
         3u,
         {"rho_f", "mu_f", "d_p", "sphericity", "rho_s", "gravity"},
         {{"K", "kg m^-3 s^-1", "momentum-exchange coefficient, F_s = K (u_f - u_s)", 1}},
         0,
         "phi outside [0, the law's packing limit] (a dense law diverges as the fluid fraction goes to 0); "
         "slip < 0; a material input (rho_f, mu_f, d_p) outside its declared range; any NaN",
         "two_fluid (1-D column, 2-D model, shear layer): K and dK/dslip at each point; the shear layer gives no "
         "shear_rate; pipe: K of the fluid-solids exchange"},
    [SL_KIND_HINDERED_SETTLING] =
        {"settling speed of the solids relative to the mixture as a function of the solids fraction (positive "
         "along gravity)",
         {"phi"},
         1u,
         {"d_p", "sphericity", "rho_s", "rho_f", "mu_f", "gravity"},
         {{"settling_velocity", "m s^-1", "hindered settling speed u(phi); the Kynch flux is phi u(phi)", 1},
          {"hindrance", "1", "f(phi) = u(phi)/u_t (optional)", 0},
          {"terminal_velocity", "m s^-1", "u_t of one particle (optional)", 0}},
         0,
         "phi outside [0, 1] (or above the closure's phi_max parameter, which the mixture model compares with "
         "[solid] phi_max); any NaN. The settling velocity must vanish at phi_max (the mixture model refuses a "
         "flux that does not: the sediment would pack beyond it); the closure takes no shear_rate",
         "mixture: the settling flux phi u(phi) and its derivative in phi; d_p, sphericity, rho_s, rho_f, mu_f, "
         "gravity and d_vessel ([solid] vessel_diameter) are the scene's constants"},
    [SL_KIND_VISCOSITY] =
        {"effective dynamic viscosity of a non-Newtonian fluid or of the suspension (or of the solids phase)",
         {NULL},
         0u,
         {"shear_rate", "phi", "mu_f", "rho_f", "density"},
         {{"viscosity", "Pa s", "effective dynamic viscosity", 1}},
         0,
         "shear_rate < 0; phi outside [0, the law's maximum packing) where the law diverges (Krieger & Dougherty "
         "1959); any NaN",
         "navier_stokes: viscosity of shear_rate (with d/dshear_rate when the input is differentiable), mu_f, "
         "rho_f and density constant; mixture (solids riding the flow): also of phi and density; migration: a "
         "viscosity of phi, differentiable; two_fluid 2-D and shear layer: the solids' viscosity"},
    [SL_KIND_SOLIDS_PRESSURE] =
        {"solids (particle) pressure p_s(phi) that holds a dense or packed bed",
         {"phi"},
         1u,
         {"nbar", "rho_f", "mu_f", "rho_s", "d_p", "gravity"},
         {{"p_s", "Pa", "solids pressure", 1}},
         0,
         "phi outside [0, 1] (or beyond the law's own limit); any NaN. The closure takes no slip",
         "two_fluid (1-D column and 2-D model): p_s and dp_s/dphi, of nbar too in a liquefaction column (the "
         "reference porosity the densification closure lowers); pipe: p_s when the scene has one"},
    [SL_KIND_WALL_STRESS] =
        {"shear stress the wall exerts on the solids as a function of their tangential slip at the wall",
         {"slip_wall"},
         1u,
         {"phi", "theta", "wall_distance", "rho_s", "mu_f", "d_p", "normal_stress"},
         {{"tau_w", "Pa", "solids wall shear stress (magnitude, opposing the slip)", 1},
          {"bagnold_number", "1", "Bagnold number at the wall (optional, written to the output)", 0},
          {"theta_flux", "kg s^-3", "granular-energy flux through the wall (optional, with a transported theta)", 0},
          {"u_tau", "m s^-1", "friction velocity (a fluid wall function, pipe model)", 0},
          {"y_plus", "1", "the node's distance in wall units (a fluid wall function)", 0}},
         0,
         "slip_wall < 0; phi outside [0, packing]; wall_distance <= 0; any NaN. The closure takes no shear_rate "
         "(slip_wall and wall_distance give the wall's shear rate)",
         "two_fluid 2-D model and shear layer, on walls with solids = wall_stress: tau_w and dtau_w/dslip_wall; "
         "pipe: [closure.wall_stress.solids] the same (normal_stress: the solids pressures of the wall cell, "
         "[closure.solids_pressure] and the kinetic theory's), and [closure.wall_stress.fluid] the fluid's wall "
         "function "
         "(u_tau, y_plus, k_wall, epsilon_wall besides tau_w)"},
    [SL_KIND_GRANULAR] =
        {"kinetic-theory coefficients of the solids phase as functions of the solids fraction and the granular "
         "temperature",
         {"phi", "theta"},
         0u,
         {"rho_s", "d_p", "rho_f", "mu_f"},
         {{"mu_s", "Pa s", "solids shear viscosity", 0},
          {"kappa", "kg m^-1 s^-1", "granular-energy conductivity (not read with an algebraic theta)", 0},
          {"gamma", "kg m^-1 s^-3", "collisional dissipation rate", 0},
          {"p_s", "Pa", "solids (kinetic + collisional) pressure (optional)", 0},
          {"g0", "1", "radial distribution function at contact (optional)", 0}},
         1,
         "phi outside [0, phi_max) where the radial distribution function diverges; theta <= 0; any NaN",
         "two_fluid 2-D model and shear layer: mu_s, gamma and kappa of (phi, theta) (the 2-D model with the "
         "algebraic theta reads no kappa); p_s when present (the kinetic pressure); pipe: mu_s, gamma and p_s"},
    [SL_KIND_MIGRATION] =
        {"diffusion coefficients of the shear-induced migration of the solids, the collision and the "
         "viscosity-gradient fluxes (Phillips et al. 1992)",
         {"phi"},
         0u,
         {"shear_rate", "d_p"},
         {{"D_c", "m^2", "N_c = -D_c grad(shear_rate phi)", 0}, {"D_mu", "m^2 s^-1", "N_mu = -D_mu grad(ln mu)", 0}},
         1,
         "phi outside [0, packing]; shear_rate < 0; any NaN",
         "mixture: D_c and D_mu of phi and shear_rate (and d_p), with [closure.viscosity] as the viscosity of phi"},
    [SL_KIND_TURBULENCE] =
        {"eddy viscosity of the fluid and the coefficients of a two-equation turbulence model as functions of the "
         "turbulent kinetic energy k and its dissipation rate epsilon",
         {"k", "epsilon"},
         0u,
         {"rho_f", "mu_f", "phi"},
         {{"mu_t", "Pa s", "eddy viscosity", 1},
          {"mu_t_k", "Pa s", "turbulent diffusivity of k, mu_t/sigma_k", 0},
          {"mu_t_eps", "Pa s", "turbulent diffusivity of epsilon, mu_t/sigma_eps", 0},
          {"eps_production", "s^-1", "the epsilon source per unit production of k, C_eps1 eps/k", 0},
          {"eps_sink", "kg m^-3 s^-1", "the epsilon destruction over epsilon, C_eps2 rho eps/k", 0},
          {"c_mu", "1", "C_mu, for the wall function's k and epsilon", 0}},
         0,
         "k <= 0 or epsilon <= 0 (the eddy viscosity k^2/eps and eps/k diverge); any NaN",
         "pipe (Krampa 2009): mu_t, mu_t_k, mu_t_eps, eps_production, eps_sink and c_mu of (k, epsilon) in the "
         "k-epsilon equations; two_fluid 2-D model: mu_t of the k and epsilon the scene states, the eddy "
         "viscosity of the solids' turbulent dispersion"},
    [SL_KIND_DENSIFICATION] =
        {"new reference porosity nbar of a sand after a half-cycle of shear strain (cyclic densification, the "
         "source of liquefaction)",
         {"nbar"},
         0u,
         {"strain_amplitude", "strain_increment", "strain_total", "volumetric_strain"},
         {{"nbar_new", "1", "reference porosity after the step (the host keeps it at or below nbar)", 1},
          {"volumetric_strain_increment", "1", "the step's densification strain (optional)", 0}},
         0,
         "nbar outside (0, 1); a strain input < 0; a compaction that would take nbar_new to 0 or below; any NaN. "
         "Between strain reversals (strain_amplitude = 0) nbar_new = nbar",
         "two_fluid 1-D column under [shaking] (liquefaction): nbar_new at every step, bounded by [deposit] "
         "nbar_min and the current nbar"},
    [SL_KIND_LIFT] =
        {"lift coefficient C_L of the shear-induced lift on the solids: the force on them per unit volume is "
         "F_L = C_L rho_f phi (u_f - u_s) x curl u_f (Drew & Lahey 1979; Auton 1987)",
         {"shear_rate"},
         0u,
         {"slip", "phi", "wall_distance", "rho_f", "mu_f", "d_p"},
         {{"C_L", "1", "lift coefficient of F_L = C_L rho_f phi (u_f - u_s) x curl u_f", 1}},
         0,
         "shear_rate or slip < 0, or outside the law's declared range (Saffman's C_L diverges as shear_rate^(-1/2) "
         "at zero shear, where the force C_L shear_rate vanishes); wall_distance <= 0; any NaN",
         "pipe: [closure.lift] C_L at the radial faces (shear_rate |du_f/dr| there, slip |u_f - u_s|, "
         "wall_distance R - r), the radial lift phi rho_f C_L (u_f - u_s) du_f/dr in the radial solids balance"},
    [SL_KIND_TURBULENT_DISPERSION] =
        {"turbulent dispersivity D_t of the solids by the fluid's eddies: the turbulent (drift) flux of the solids "
         "is -D_t grad(phi) (Krampa 2009 eqs 4.57-4.63; Burns et al. 2004's F_TD = -K D_t (grad c_s/c_s - grad "
         "c_f/c_f))",
         {NULL},
         0u,
         {"nu_t", "t_fs", "k_fs", "k", "epsilon", "phi", "drag_coefficient", "rho_f"},
         {{"D_t", "m^2 s^-1", "the solids' turbulent dispersivity", 1}},
         0,
         "an input outside its declared range (nu_t, t_fs, k_fs < 0); any NaN",
         "pipe: [closure.turbulent_dispersion] D_t in every cell (nu_t = mu_t/rho_f of [closure.turbulence], t_fs "
         "of Krampa's eq 4.61 with [pipe] crossing_trajectory, k_fs Tchen's equilibrium or model C's transported "
         "one), the radial solids balance's diffusivity D_t + c_s c_f^2 (dp_s/dphi)/K; without the section D_t = "
         "nu_t (the gradient form with Schmidt number 1, eq 4.59); two_fluid (2-D): D_t at each face's nu_t (the "
         "harmonic mean of its cells'), inputs nu_t and rho_f only (a closure that reads t_fs or k_fs is refused)"},
    [SL_KIND_TURBULENCE_MODULATION] =
        {"particles' modulation of the fluid's turbulence: an exchange coefficient A of the fluid's k "
         "equation, c_f rho_f Pi_kf = A [k_fs - 2 k + (u_f - u_s).U_d] (and the drift work A nu_t grad(c_f).(u_f - "
         "u_s)), and C_eps3 of the epsilon equation, C_eps3 (eps/k) times the same (Krampa 2009 eqs 4.80-4.83; "
         "Simonin 1996)",
         {"drag_coefficient"},
         0u,
         {"phi", "k", "epsilon", "rho_f", "rho_s", "d_p"},
         {{"exchange", "kg m^-3 s^-1", "the exchange coefficient A (Simonin: the drag's K; 0: no modulation)", 1},
          {"c_eps3", "1", "C_eps3 of the epsilon equation's modulation", 1}},
         0,
         "drag_coefficient < 0, or an input outside its declared range; any NaN. exchange >= 0 (an attenuation of "
         "k towards k_fs/2)",
         "pipe: [closure.turbulence_modulation] in every cell with solids: with Tchen's k_fs = 2 k eta/(1 + eta) "
         "the implicit sink 2 A/(1 + eta) of k, with model C's transported k_fs the source A k_fs and the sink 2 A; "
         "in the developing pipe the drift work A g (nu_t + D_t/(c_f c_s)), g = grad(c_f).(u_f - u_s) (zero in the "
         "fully developed pipe); C_eps3 (eps/k) times each in epsilon; without the section, none"},
};

const sl_kind_info *sl_kind_info_of(sl_kind kind) {
  if (kind < SL_KIND_FIRST || kind > SL_KIND_LAST) return NULL;
  return &contracts[kind];
}

const sl_input_info *sl_input_find(const char *name) {
  for (int i = 0; i < N_INPUTS; ++i)
    if (strcmp(name, inputs[i].name) == 0) return &inputs[i];
  return NULL;
}

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
                     "wall_stress, granular, migration, turbulence, densification, lift, turbulent_dispersion, "
                     "turbulence_modulation)",
                     name);
}

int sl_input_is_known(const char *name) { return sl_input_find(name) != NULL; }

const char *const *sl_input_names(int *n) {
  *n = N_INPUTS;
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
  const sl_kind_info *c = &contracts[desc->kind];
  for (int i = 0; i < SL_KIND_MAX_INPUTS && c->required[i]; ++i) {
    int at = find_field(desc->in, desc->n_in, c->required[i]);
    if (at < 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' lacks the required input '%s'", kname, desc->name,
                         c->required[i]);
    if ((c->diff_mask >> i & 1u) && !(desc->in[at].flags & SL_FIELD_DIFF))
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' must mark input '%s' differentiable", kname, desc->name,
                         c->required[i]);
  }
  for (int k = 0; k < SL_KIND_MAX_OUTPUTS && c->outputs[k].name; ++k) {
    if (c->outputs[k].required && find_field(desc->out, desc->n_out, c->outputs[k].name) < 0)
      return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' lacks the required output '%s'", kname, desc->name,
                         c->outputs[k].name);
  }
  if (c->any_output && desc->n_out < 1)
    return sl_diag_set(d, SL_EBADINPUT, "%s closure '%s' has no output", kname, desc->name);
  return 0;
}
