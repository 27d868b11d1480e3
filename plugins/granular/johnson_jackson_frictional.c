/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Johnson & Jackson (1987) frictional stress for dense granular material: the
 * frictional normal stress
 *   p_fr = Fr (phi - phi_min)^r / (phi_max - phi)^s,   phi > phi_min,
 * with Fr = 0.05 Pa (N m^-2), r = 2, s = 5, phi_min = 0.5 for their glass
 * beads (they used phi_max = 0.65; the default here is 0.63, as in the other
 * granular closures), and the Coulomb frictional shear stress p_fr sin(phi_f) (angle of
 * internal friction 28.5 degrees = 0.4974 rad for the same beads), written
 * as a viscosity
 *   mu_fr = p_fr sin(phi_f) / shear_rate,  shear_rate = sqrt(2 D:D),
 * which is JJ's sqrt(2) p_f sin(phi_f) S/|S| for traceless S.
 *
 * Johnson & Jackson (1987) J. Fluid Mech. 176:67-93, "Frictional-collisional
 * constitutive relations for granular materials, with application to plane
 * shearing"; the same law is OpenFOAM's "JohnsonJackson" frictional stress
 * (Fr 0.05, eta 2, p 5), there with the C0 guard max(phi_max - phi, delta).
 * Above phi_max - delta the pressure is continued by its tangent
 * line (C1, finite beyond packing); see frictional.h. The theta input is
 * required by the granular kind contract and not used. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/frictional.h"

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(fr_params, friction_angle, 0.49741883681838395, 0.0, 1.5707963267948966, "rad",
                     "angle of internal friction phi_f in RADIANS (28.5 degrees = 0.4974)"),
    FR_JJ_PRESSURE_PARAMS,
    SL_PARAM_REAL_OF(fr_params, shear_rate_reg, 1e-4, 1e-12, 1.0, "s^-1",
                     "regularisation: mu_fr = p_fr sin(phi_f)/sqrt(shear_rate^2 + shear_rate_reg^2)"),
};

static const sl_field_desc inputs[] = FR_INPUTS;
static const sl_field_desc outputs[] = FR_OUTPUTS;

/* Defaults: Fr = 0.05, r = 2, s = 5, phi_min = 0.5, phi_max = 0.63. At
 * phi = 0.55: 0.05 * 0.05^2 / 0.08^5 = 38.14697265625 Pa. */
static const double check_in[FR_N_IN] = {0.55, 0.0, 1.0};
static const sl_check_point checks[] = {
    {check_in, FR_OUT_P_FR, 38.14697265625, 1e-12,
     "Johnson & Jackson (1987) Fr (phi-phi_min)^r/(phi_max-phi)^s with 0.05, 2, 5, 0.5, 0.63 at phi = 0.55, "
     "hand-evaluated"},
    {check_in, FR_OUT_MU_FR, 38.14697265625 * 0.47715876025960842, 1e-8,
     "Coulomb limit: mu_fr shear_rate = p_fr sin(28.5 deg) at shear_rate = 1 s^-1"},
};

static int create(const sl_host_api *api, const void *par, void **state, sl_error *err) {
  return fr_create(api, par, state, err, FR_JOHNSON_JACKSON);
}

static int evaluate(const void *state, const sl_eval_args *a) {
  return fr_evaluate(state, FR_JOHNSON_JACKSON, inputs, a);
}

static const sl_closure_desc johnson_jackson_frictional = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_GRANULAR,
    .name = "johnson_jackson_frictional",
    .version = "1.0.0",
    .summary = "Johnson & Jackson (1987) frictional pressure and Coulomb viscosity",
    .formula =
        "p_fr = fr (phi - phi_min)^r / (phi_max - phi)^s for phi_min < phi <= phi_max - delta, "
        "tangent line above, 0 below phi_min\n"
        "mu_fr = p_fr sin(friction_angle) / sqrt(shear_rate^2 + shear_rate_reg^2)",
    .reference = "Johnson & Jackson (1987) J. Fluid Mech. 176:67-93",
    .validity =
        "dense, slowly deforming granular material at phi > phi_min (zero below); friction_angle in "
        "radians; 0 <= phi <= 0.74 (beyond phi_max - delta the C1 linear continuation, not physics); "
        "theta is not used",
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

static const sl_closure_desc *const all[] = {&johnson_jackson_frictional};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
