/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Schaeffer (1987) frictional (plastic, Coulomb) solids stress for dense,
 * slowly sheared granular material: a frictional pressure p_fr(phi) and the
 * viscosity that puts the deviatoric stress on the Coulomb yield surface,
 *   mu_fr = p_fr sin(phi_f) / (2 sqrt(I_2D)) = p_fr sin(phi_f) / shear_rate,
 * I_2D = (1/2) D':D', shear_rate = sqrt(2 D:D) (equal for traceless D).
 *
 * Schaeffer (1987) J. Differential Equations 66:19-50 (instability of the
 * equations of granular flow); the pressure law p_fr = 1e25 (phi - phi_min)^10
 * Pa is the one MFIX pairs with it (Syamlal, Rogers & O'Brien 1993, with
 * phi_min = 1 - eps_g*); pressure = johnson_jackson selects the Johnson &
 * Jackson (1987) law instead (the OpenFOAM "JohnsonJacksonSchaeffer"
 * combination). Krampa (2009) eq 4.68 gives the generic frictional stress
 * p_f I + F(p_f, phi) S^/|S^| but does not implement one.
 * Formulas, continuation and the radians convention: frictional.h.
 * The theta input is required by the granular kind contract and not used. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/frictional.h"

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(fr_params, friction_angle, 0.52359877559829887, 0.0, 1.5707963267948966, "rad",
                     "angle of internal friction phi_f in RADIANS (30 degrees = 0.5236)"),
    SL_PARAM_ENUM_OF(fr_params, pressure, FR_POWER_LAW, "power_law|johnson_jackson",
                     "frictional pressure: power_law p_coefficient (phi-phi_min)^p_exponent, or "
                     "johnson_jackson fr (phi-phi_min)^r/(phi_max-phi)^s"),
    SL_PARAM_REAL_OF(fr_params, p_coefficient, 1e25, 0.0, 1e30, "Pa", "power_law coefficient"),
    SL_PARAM_REAL_OF(fr_params, p_exponent, 10.0, 1.0, 20.0, "1", "power_law exponent"),
    SL_PARAM_REAL_OF(fr_params, fr, 0.05, 0.0, 1e8, "Pa", "johnson_jackson coefficient Fr"),
    SL_PARAM_REAL_OF(fr_params, r, 2.0, 1.0, 10.0, "1", "johnson_jackson exponent of (phi - phi_min)"),
    SL_PARAM_REAL_OF(fr_params, s, 5.0, 0.0, 10.0, "1", "johnson_jackson exponent of (phi_max - phi)"),
    SL_PARAM_REAL_OF(fr_params, phi_min, 0.5, 0.0, 0.74, "1", "solids fraction where friction starts"),
    SL_PARAM_REAL_OF(fr_params, phi_max, 0.63, 0.3, 0.74, "1", "maximum packing (johnson_jackson pressure)"),
    SL_PARAM_REAL_OF(fr_params, delta, 0.01, 1e-4, 0.1, "1",
                     "johnson_jackson pressure continued by its tangent line above phi_max - delta"),
    SL_PARAM_REAL_OF(fr_params, shear_rate_reg, 1e-4, 1e-12, 1.0, "s^-1",
                     "regularisation: mu_fr = p_fr sin(phi_f)/sqrt(shear_rate^2 + shear_rate_reg^2)"),
};

static const sl_field_desc inputs[] = FR_INPUTS;
static const sl_field_desc outputs[] = FR_OUTPUTS;

/* Defaults: power_law 1e25 (phi - 0.5)^10, 30 degrees. */
static const double check_in[FR_N_IN] = {0.6, 0.0, 1.0};
static const sl_check_point checks[] = {
    {check_in, FR_OUT_P_FR, 1e15, 1e-12,
     "Syamlal et al. (1993) MFIX frictional pressure 1e25 (phi - phi_min)^10 at "
     "phi - phi_min = 0.1, hand-evaluated"},
    {check_in, FR_OUT_MU_FR, 0.5e15, 1e-8,
     "Coulomb limit of Schaeffer (1987): shear stress mu_fr shear_rate = p_fr sin(30 deg) = p_fr/2 at "
     "shear_rate = 1 s^-1 (regularisation 1e-4 changes it by 5e-9)"},
};

static int create(const sl_host_api *api, const void *par, void **state, sl_error *err) {
  const fr_params *p = par;
  return fr_create(api, par, state, err, p->pressure);
}

static int evaluate(const void *state, const sl_eval_args *a) {
  const fr_params *p = state;
  return fr_evaluate(p, p->pressure, inputs, a);
}

static const sl_closure_desc schaeffer = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_GRANULAR,
    .name = "schaeffer",
    .version = "1.0.0",
    .summary = "Schaeffer (1987) frictional stress: p_fr and Coulomb viscosity mu_fr",
    .formula =
        "p_fr = p_coefficient (phi - phi_min)^p_exponent (power_law, default) or\n"
        "p_fr = fr (phi - phi_min)^r / (phi_max - phi)^s (johnson_jackson, tangent line above "
        "phi_max - delta); p_fr = 0 for phi <= phi_min\n"
        "mu_fr = p_fr sin(friction_angle) / (2 sqrt(I_2D)) = p_fr sin(friction_angle) / "
        "sqrt(shear_rate^2 + shear_rate_reg^2)",
    .reference =
        "Schaeffer (1987) J. Differential Equations 66:19; Syamlal, Rogers & O'Brien (1993) MFIX "
        "documentation DOE/METC-94/1004; Johnson & Jackson (1987) J. Fluid Mech. 176:67",
    .validity =
        "dense, slowly deforming granular material at phi > phi_min (zero below); friction_angle in "
        "radians; 0 <= phi <= 0.74; theta is not used",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(fr_params),
    .n_in = FR_N_IN,
    .in = inputs,
    .n_out = FR_N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = create,
    .evaluate = evaluate,
    .destroy = fr_destroy,
};

static const sl_closure_desc *const all[] = {&schaeffer};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
