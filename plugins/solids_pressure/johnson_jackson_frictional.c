/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The frictional pressure of Johnson & Jackson (1987) as a solids pressure p_s(phi): the normal stress of
 * particles in enduring contact near packing,
 *   p_s = Fr (phi - phi_min)^r / (phi_max - phi)^s   for phi_min < phi <= phi_max - delta, 0 at and below phi_min,
 * continued by its tangent line above phi_max - delta (finite and C1 at and beyond packing). Johnson & Jackson
 * (1987, J. Fluid Mech. 176:67) fitted Fr = 0.05 Pa, r = 2, s = 5 with phi_min = 0.5 for their glass beads; phi_max
 * 0.63 here as in Krampa (2009). The same law as granular/johnson_jackson_frictional's p_fr (the formula is
 * granular/frictional.h's, shared), in the kind a model with a [closure.solids_pressure] reads: the pipe model
 * puts it in its radial balance and, with a wall closure that takes the solids' normal stress
 * (wall_stress/coulomb), on the wall. */
#include <math.h>
#include <sluice/closure.h>

#include "granular/frictional.h"

static const sl_param_desc params[] = {FR_JJ_PRESSURE_PARAMS};

enum { IN_PHI, N_IN };
enum { OUT_P_S, N_OUT };

static const sl_field_desc inputs[] = {
    {"phi", "1", SL_FIELD_DIFF, 0.55, 0.0, 0.74, "solids volume fraction"},
};

static const sl_field_desc outputs[] = {
    {"p_s", "Pa", 0, 0, 0, 0, "frictional (contact) pressure of the solids"},
};

/* Defaults at phi = 0.55: 0.05 0.05^2/0.08^5 = 38.14697265625 Pa (as granular/johnson_jackson_frictional); below
   phi_min exactly 0. */
static const double check_in[N_IN] = {0.55};
static const double check_dilute[N_IN] = {0.45};
static const sl_check_point checks[] = {
    {check_in, OUT_P_S, 38.14697265625, 1e-12,
     "Johnson & Jackson (1987) Fr (phi-phi_min)^r/(phi_max-phi)^s with 0.05, 2, 5, 0.5, 0.63 at phi = 0.55, "
     "hand-evaluated"},
    {check_dilute, OUT_P_S, 0.0, 0.0, "no contact pressure below phi_min (Johnson & Jackson 1987)"},
};

static int create(const sl_host_api *api, const void *par, void **state, sl_error *err) {
  return fr_create(api, par, state, err, FR_JOHNSON_JACKSON);
}

static int evaluate(const void *state, const sl_eval_args *a) {
  const fr_params *p = state;
  int rc = gr_check_inputs(a, inputs, N_IN);
  if (rc) return rc;
  const double *phi = a->in[IN_PHI];
  double *ps = a->out[OUT_P_S], *dps = sl_dout(a, N_IN, OUT_P_S, IN_PHI);
  for (int32_t q = 0; q < a->Q; ++q) {
    double dp, v = fr_pressure(p, FR_JOHNSON_JACKSON, phi[q], &dp);
    ps[q] = v;
    gr_set(dps, q, dp);
  }
  return SL_OK;
}

static void destroy(const sl_host_api *api, void *state) { fr_destroy(api, state); }

static const sl_closure_desc johnson_jackson_frictional = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_SOLIDS_PRESSURE,
    .name = "johnson_jackson_frictional",
    .version = "1.0.0",
    .summary = "Johnson & Jackson (1987) frictional (contact) pressure near packing as a solids pressure",
    .formula =
        "p_s = fr (phi - phi_min)^r / (phi_max - phi)^s for phi_min < phi <= phi_max - delta, tangent line above, "
        "0 at and below phi_min",
    .reference = "Johnson & Jackson (1987) J. Fluid Mech. 176:67-93",
    .validity =
        "dense granular material in enduring contact, phi > phi_min (zero below); 0 <= phi <= 0.74 (beyond "
        "phi_max - delta the C1 linear continuation, not physics)",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(fr_params),
    .n_in = N_IN,
    .in = inputs,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = create,
    .evaluate = evaluate,
    .destroy = destroy,
};

static const sl_closure_desc *const all[] = {&johnson_jackson_frictional};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
