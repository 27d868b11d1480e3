/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Byrne (1991) densification of a sand under cyclic shear, the
 * Martin-Finn-Seed (1975) idea in one exponential: the volumetric strain a
 * drained sample would take in one cycle of shear strain amplitude gamma,
 *   d eps_vd / gamma = C1 exp(-C2 eps_vd / gamma),   strains in percent,
 *   C1 = 7600 Dr^-2.5 (Dr the relative density in percent),  C2 = 0.4 / C1,
 * Byrne, P.M. (1991) "A cyclic shear-volume coupling and pore pressure model
 * for sand", 2nd Int. Conf. on Recent Advances in Geotechnical Earthquake
 * Engineering and Soil Dynamics, St Louis, paper 1.24, eqs 4-6.
 *
 * The host calls this at every step; between strain reversals
 * strain_amplitude is 0 and nothing changes. At a reversal it is the
 * amplitude of the half-cycle that ended (half its strain excursion), and
 * the half-cycle takes `half_cycle_share` (default 1/2) of the cycle's
 * increment. The drained volume change becomes the sand's new reference
 * porosity (Pringle 2001 section 3.3, Figure 3.14: "a tendency to compact is
 * modelled as a drop nbar0 -> nbar1"): the reference solids fraction grows
 * by the volume lost,
 *   1 - nbar_new = (1 - nbar) / (1 - d eps_vd). */
#include <math.h>
#include <sluice/closure.h>

typedef struct byrne_params {
  double relative_density; /* Dr, percent */
  double c1, c2;           /* 0: from Dr */
  double half_cycle_share;
} byrne_params;

enum { IN_NBAR, IN_AMP, IN_EPS, N_IN };
enum { OUT_NBAR, OUT_DEPS, N_OUT };

static const sl_param_desc params[] = {
    SL_PARAM_REAL_OF(byrne_params, relative_density, 40.0, 5.0, 100.0, "%",
                     "relative density Dr in percent (C1 = 7600 Dr^-2.5)"),
    SL_PARAM_REAL_OF(byrne_params, c1, 0.0, 0.0, 100.0, "1", "C1 (0: 7600 Dr^-2.5)"),
    SL_PARAM_REAL_OF(byrne_params, c2, 0.0, 0.0, 100.0, "1", "C2 (0: 0.4/C1)"),
    SL_PARAM_REAL_OF(byrne_params, half_cycle_share, 0.5, 0.0, 1.0, "1",
                     "the share of a cycle's increment one half-cycle (reversal to reversal) takes"),
};

static const sl_field_desc inputs[] = {
    {"nbar", "1", 0, 0.45, 0.01, 0.99, "reference porosity of the sand"},
    {"strain_amplitude", "1", 0, 1e-3, 0.0, 1.0, "amplitude of the half-cycle just ended (0: no reversal)"},
    {"volumetric_strain", "1", 0, 0.0, 0.0, 0.5, "densification strain accumulated so far (drained)"},
};

static const sl_field_desc outputs[] = {
    {"nbar_new", "1", 0, 0, 0, 0, "reference porosity after the half-cycle"},
    {"volumetric_strain_increment", "1", SL_FIELD_OPTIONAL, 0, 0, 0, "the half-cycle's densification strain"},
};

/* By hand from the formula (Dr = 40: C1 = 0.751041, C2 = 0.532594). */
static const double check_in_0[N_IN] = {0.45, 1e-3, 0.0};  /* gamma 0.1 %, eps 0 */
static const double check_in_1[N_IN] = {0.45, 2e-3, 1e-2}; /* gamma 0.2 %, eps 1 % */
static const double check_in_2[N_IN] = {0.45, 0.0, 1e-2};  /* no reversal */
static const sl_check_point checks[] = {
    {check_in_0, OUT_NBAR, 0.4497933861525907, 1e-12,
     "Byrne (1991): 1 - 0.55/(1 - 0.5 x 0.1 x 0.751041 / 100), by hand"},
    {check_in_1, OUT_NBAR, 0.44997119050882484, 1e-12,
     "Byrne (1991): 0.5 x 0.2 x 0.751041 exp(-0.532594 x 1/0.2) = 0.0052378 %, by hand"},
    {check_in_2, OUT_NBAR, 0.45, 1e-15, "no reversal: nbar unchanged"},
};

static int evaluate(const void *state, const sl_eval_args *a) {
  const byrne_params *p = state;
  const double c1 = p->c1 > 0.0 ? p->c1 : 7600.0 * pow(p->relative_density, -2.5);
  const double c2 = p->c2 > 0.0 ? p->c2 : 0.4 / c1;
  const double *nbar = a->in[IN_NBAR], *amp = a->in[IN_AMP], *eps = a->in[IN_EPS];
  double *out = a->out[OUT_NBAR], *deps = a->out[OUT_DEPS];
  for (int32_t q = 0; q < a->Q; ++q) {
    for (int i = 0; i < N_IN; ++i) {
      double v = a->in[i][q];
      if (!(v >= inputs[i].valid_min && v <= inputs[i].valid_max))
        return sl_fail(a->err, SL_RECOVERABLE, q, "%s = %g outside [%g, %g]", inputs[i].name, v, inputs[i].valid_min,
                       inputs[i].valid_max);
    }
    double d = 0.0;
    if (amp[q] > 0.0) {
      double g = 100.0 * amp[q], e = 100.0 * eps[q]; /* percent */
      d = 0.01 * p->half_cycle_share * g * c1 * exp(-c2 * e / g);
    }
    if (!(d < 1.0)) return sl_fail(a->err, SL_RECOVERABLE, q, "a half-cycle of amplitude %g compacts by %g", amp[q], d);
    out[q] = 1.0 - (1.0 - nbar[q]) / (1.0 - d);
    if (deps) deps[q] = d;
  }
  return SL_OK;
}

static const sl_closure_desc byrne = {
    SL_CLOSURE_DESC_HEADER,
    .kind = SL_KIND_DENSIFICATION,
    .name = "byrne",
    .version = "1.0.0",
    .summary = "Byrne (1991) cyclic densification of sand, per half-cycle of shear strain, as a drop of nbar",
    .formula =
        "d eps_vd = share gamma C1 exp(-C2 eps_vd/gamma)  (strains in percent, gamma the half-cycle amplitude)\n"
        "C1 = 7600 Dr^-2.5, C2 = 0.4/C1, share = 1/2;  1 - nbar_new = (1 - nbar)/(1 - d eps_vd)",
    .reference =
        "Byrne (1991), 2nd Int. Conf. Recent Adv. Geotech. Earthquake Eng., paper 1.24, eqs 4-6; "
        "Martin, Finn & Seed (1975); nbar as the state: Pringle (2001) section 3.3",
    .validity = "clean sands, 5 <= Dr <= 100 %; the drained volumetric strain of uniform cyclic shear",
    .n_params = SL_COUNT_OF(params),
    .params = params,
    .params_size = sizeof(byrne_params),
    .n_in = N_IN,
    .in = inputs,
    .n_out = N_OUT,
    .out = outputs,
    .n_checks = SL_COUNT_OF(checks),
    .checks = checks,
    .create = NULL,
    .evaluate = evaluate,
    .destroy = NULL,
};

static const sl_closure_desc *const all[] = {&byrne};

SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {
  *count = SL_COUNT_OF(all);
  return all;
}
