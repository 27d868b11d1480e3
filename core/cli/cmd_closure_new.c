/* SPDX-License-Identifier: GPL-2.0-or-later */
/* sluice closure new KIND NAME [-o DIR]: writes DIR/NAME.c, a closure of the
 * kind with its descriptor, parameter schema, inputs and outputs from the
 * registry of kinds (core/plugin/kinds.c), range checks, a check point and
 * an evaluate() whose law is a marked placeholder, and DIR/CMakeLists.txt
 * that builds it with the installed package's sluice_add_closure() and
 * registers `sluice check-closure` on it as a ctest. As written, each
 * template builds and passes the conformance battery; the author replaces the
 * placeholder law (and its formula, reference, check point). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/cli/cli.h"
#include "core/plugin/kinds.h"

const char sl_closure_new_usage[] =
    "usage: sluice closure new KIND NAME [-o DIR]\n"
    "Writes DIR/NAME.c (default DIR: ./NAME), a closure of kind KIND with the kind's\n"
    "inputs and outputs, a parameter schema, range checks, a check point and a\n"
    "placeholder law between marked lines, and DIR/CMakeLists.txt that builds it with\n"
    "find_package(sluice) and registers `sluice check-closure` on it as a test. The\n"
    "template builds and passes the battery as written; replace the placeholder law,\n"
    "build the folder with CMake (CMAKE_PREFIX_PATH: the sluice install prefix) and run\n"
    "its test. Existing files are not overwritten (exit status 2).\n"
    "`sluice closure kinds` lists the kinds and their contracts.";

typedef struct tparam {
  const char *name;
  double def, min, max;
  const char *units, *help;
} tparam;

enum { T_MAX_IN = 4, T_MAX_OUT = 6, T_MAX_PARAMS = 5 };

/* The placeholder of one kind: the inputs it declares (bit i of diff: input i
 * differentiable), the outputs, parameters, the law as C lines (`setup`
 * before the loop over points, `law` in it) and one value of the law. */
typedef struct ttemplate {
  sl_kind kind;
  const char *in[T_MAX_IN];
  unsigned diff;
  const char *out[T_MAX_OUT];
  tparam params[T_MAX_PARAMS];
  const char *setup, *law;
  const char *formula, *reference, *validity;
  double check_in[T_MAX_IN];
  double expected;
  const char *source;
} ttemplate;

static const ttemplate templates[] = {
    {SL_KIND_DRAG,
     {"phi", "slip", "mu_f", "d_p"},
     3u,
     {"K"},
     {{"stokes_factor", 18.0, 0.0, 1e4, "1", "K = stokes_factor mu_f phi / d_p^2 (18: Stokes drag)"}},
     "  double *K = a->out[OUT_K];\n"
     "  double *dK_dphi = sl_dout(a, N_IN, OUT_K, IN_PHI), *dK_dslip = sl_dout(a, N_IN, OUT_K, IN_SLIP);\n",
     "    const double phi = a->in[IN_PHI][q], mu_f = a->in[IN_MU_F][q], d_p = a->in[IN_D_P][q];\n"
     "    K[q] = p->stokes_factor * mu_f * phi / (d_p * d_p);\n"
     "    if (dK_dphi) dK_dphi[q] = p->stokes_factor * mu_f / (d_p * d_p);\n"
     "    if (dK_dslip) dK_dslip[q] = 0.0; /* Stokes drag is linear in the slip: K does not depend on it */\n",
     "K = 18 mu_f phi / d_p^2",
     "Stokes (1851): 3 pi mu_f d_p slip on one sphere, phi / (pi d_p^3 / 6) spheres per unit volume",
     "dilute suspensions (phi below about 0.01), particle Reynolds number below about 0.1",
     {0.1, 0.01, 1e-3, 1e-3},
     1800.0,
     "18 * 1e-3 * 0.1 / (1e-3)^2"},
    {SL_KIND_HINDERED_SETTLING,
     {"phi"},
     1u,
     {"settling_velocity"},
     {{"terminal_velocity", 1e-3, 0.0, 100.0, "m s^-1", "settling velocity u_t of one particle"},
      {"n", 4.65, 1.0, 20.0, "1", "Richardson-Zaki exponent (4.65 in the Stokes regime)"},
      {"phi_max", 0.64, 0.3, 1.0, "1",
       "packing fraction: settling stops there (the mixture compares [solid] phi_max)"}},
     "  double *u = a->out[OUT_SETTLING_VELOCITY], *du_dphi = sl_dout(a, N_IN, OUT_SETTLING_VELOCITY, IN_PHI);\n",
     "    const double phi = a->in[IN_PHI][q];\n"
     "    if (phi >= p->phi_max) { /* a packed bed does not settle: the flux vanishes at phi_max */\n"
     "      u[q] = 0.0;\n"
     "      if (du_dphi) du_dphi[q] = 0.0;\n"
     "      continue;\n"
     "    }\n"
     "    const double f = pow(1.0 - phi, p->n), c = 1.0 - phi / p->phi_max;\n"
     "    u[q] = p->terminal_velocity * f * c;\n"
     "    if (du_dphi) du_dphi[q] = p->terminal_velocity * (-p->n * pow(1.0 - phi, p->n - 1.0) * c - f / "
     "p->phi_max);\n",
     "settling_velocity = terminal_velocity (1 - phi)^n (1 - phi/phi_max), 0 for phi >= phi_max",
     "Richardson & Zaki (1954), eq. 17, with a multiplicative packing cut-off",
     "uniform spheres, 0 <= phi <= phi_max",
     {0.5},
     8.712816788315266e-06,
     "1e-3 * 2^-4.65 * (1 - 0.5/0.64)"},
    {SL_KIND_VISCOSITY,
     {"phi", "mu_f"},
     1u,
     {"viscosity"},
     {{"intrinsic_viscosity", 2.5, 0.0, 100.0, "1", "intrinsic viscosity [mu] (2.5 for spheres)"}},
     "  double *mu = a->out[OUT_VISCOSITY], *dmu_dphi = sl_dout(a, N_IN, OUT_VISCOSITY, IN_PHI);\n",
     "    const double phi = a->in[IN_PHI][q], mu_f = a->in[IN_MU_F][q];\n"
     "    mu[q] = mu_f * (1.0 + p->intrinsic_viscosity * phi);\n"
     "    if (dmu_dphi) dmu_dphi[q] = mu_f * p->intrinsic_viscosity;\n",
     "viscosity = mu_f (1 + intrinsic_viscosity phi)",
     "Einstein (1906)",
     "dilute suspensions of rigid spheres (phi below about 0.02)",
     {0.02, 1e-3},
     1.05e-3,
     "1e-3 * (1 + 2.5 * 0.02)"},
    {SL_KIND_SOLIDS_PRESSURE,
     {"phi"},
     1u,
     {"p_s"},
     {{"modulus", 100.0, 0.0, 1e9, "Pa", "p_s = modulus phi^2"}},
     "  double *ps = a->out[OUT_P_S], *dps_dphi = sl_dout(a, N_IN, OUT_P_S, IN_PHI);\n",
     "    const double phi = a->in[IN_PHI][q];\n"
     "    ps[q] = p->modulus * phi * phi;\n"
     "    if (dps_dphi) dps_dphi[q] = 2.0 * p->modulus * phi;\n",
     "p_s = modulus phi^2",
     "a placeholder, not a published law: replace it",
     "0 <= phi <= 1",
     {0.5},
     25.0,
     "100 * 0.5^2"},
    {SL_KIND_WALL_STRESS,
     {"slip_wall"},
     1u,
     {"tau_w"},
     {{"friction", 10.0, 0.0, 1e9, "Pa s m^-1", "tau_w = friction slip_wall"}},
     "  double *tau = a->out[OUT_TAU_W], *dtau_dslip = sl_dout(a, N_IN, OUT_TAU_W, IN_SLIP_WALL);\n",
     "    const double slip_wall = a->in[IN_SLIP_WALL][q];\n"
     "    tau[q] = p->friction * slip_wall;\n"
     "    if (dtau_dslip) dtau_dslip[q] = p->friction;\n",
     "tau_w = friction slip_wall",
     "Navier (1823): partial slip, stress proportional to the slip",
     "0 <= slip_wall <= 100 m/s",
     {0.5},
     5.0,
     "10 * 0.5"},
    {SL_KIND_GRANULAR,
     {"phi", "theta", "rho_s", "d_p"},
     3u,
     {"mu_s", "kappa", "gamma"},
     {{"c_mu", 1.0, 0.0, 1e3, "1", "mu_s = c_mu rho_s d_p phi sqrt(theta)"},
      {"c_kappa", 2.0, 0.0, 1e3, "1", "kappa = c_kappa rho_s d_p phi sqrt(theta)"},
      {"c_gamma", 3.0, 0.0, 1e3, "1", "gamma = c_gamma rho_s phi^2 theta^1.5 / d_p"}},
     "  double *mu = a->out[OUT_MU_S], *kap = a->out[OUT_KAPPA], *gam = a->out[OUT_GAMMA];\n"
     "  double *dmu_dphi = sl_dout(a, N_IN, OUT_MU_S, IN_PHI), *dmu_dth = sl_dout(a, N_IN, OUT_MU_S, IN_THETA);\n"
     "  double *dkap_dphi = sl_dout(a, N_IN, OUT_KAPPA, IN_PHI), *dkap_dth = sl_dout(a, N_IN, OUT_KAPPA, IN_THETA);\n"
     "  double *dgam_dphi = sl_dout(a, N_IN, OUT_GAMMA, IN_PHI), *dgam_dth = sl_dout(a, N_IN, OUT_GAMMA, IN_THETA);\n",
     "    const double phi = a->in[IN_PHI][q], th = a->in[IN_THETA][q];\n"
     "    const double rho_s = a->in[IN_RHO_S][q], d_p = a->in[IN_D_P][q], s = sqrt(th);\n"
     "    mu[q] = p->c_mu * rho_s * d_p * phi * s;\n"
     "    kap[q] = p->c_kappa * rho_s * d_p * phi * s;\n"
     "    gam[q] = p->c_gamma * rho_s * phi * phi * th * s / d_p;\n"
     "    if (dmu_dphi) dmu_dphi[q] = p->c_mu * rho_s * d_p * s;\n"
     "    if (dmu_dth) dmu_dth[q] = 0.5 * p->c_mu * rho_s * d_p * phi / s;\n"
     "    if (dkap_dphi) dkap_dphi[q] = p->c_kappa * rho_s * d_p * s;\n"
     "    if (dkap_dth) dkap_dth[q] = 0.5 * p->c_kappa * rho_s * d_p * phi / s;\n"
     "    if (dgam_dphi) dgam_dphi[q] = 2.0 * p->c_gamma * rho_s * phi * th * s / d_p;\n"
     "    if (dgam_dth) dgam_dth[q] = 1.5 * p->c_gamma * rho_s * phi * phi * s / d_p;\n",
     "mu_s = c_mu rho_s d_p phi sqrt(theta),  kappa = c_kappa rho_s d_p phi sqrt(theta),\n"
     "gamma = c_gamma rho_s phi^2 theta^1.5 / d_p",
     "a placeholder with the kinetic-theory scalings, not a published law: replace it",
     "0 <= phi <= 1, theta > 0",
     {0.5, 0.04, 1000.0, 1e-3},
     0.1,
     "1 * 1000 * 1e-3 * 0.5 * sqrt(0.04)"},
    {SL_KIND_MIGRATION,
     {"phi", "shear_rate", "d_p"},
     0u,
     {"D_c", "D_mu"},
     {{"k_c", 0.41, 0.0, 100.0, "1", "collision coefficient K_c"},
      {"k_mu", 0.62, 0.0, 100.0, "1", "viscosity-gradient coefficient K_mu"}},
     "  double *D_c = a->out[OUT_D_C], *D_mu = a->out[OUT_D_MU];\n",
     "    const double phi = a->in[IN_PHI][q], g = a->in[IN_SHEAR_RATE][q], r = 0.5 * a->in[IN_D_P][q];\n"
     "    D_c[q] = p->k_c * r * r * phi;\n"
     "    D_mu[q] = p->k_mu * r * r * g * phi * phi;\n",
     "a = d_p / 2;  D_c = k_c a^2 phi,  D_mu = k_mu a^2 shear_rate phi^2",
     "Phillips et al. (1992), eqs 7 and 8",
     "0 <= phi <= packing, shear_rate >= 0",
     {0.5, 1.0, 2e-3},
     2.05e-7,
     "0.41 * (1e-3)^2 * 0.5"},
    {SL_KIND_TURBULENCE,
     {"k", "epsilon", "rho_f"},
     0u,
     {"mu_t", "mu_t_k", "mu_t_eps", "eps_production", "eps_sink", "c_mu"},
     {{"c_mu", 0.09, 1e-3, 1.0, "1", "C_mu of the eddy viscosity"},
      {"c_eps1", 1.44, 0.1, 5.0, "1", "C_eps1, on the production in the epsilon equation"},
      {"c_eps2", 1.92, 0.1, 5.0, "1", "C_eps2, on the destruction in the epsilon equation"},
      {"sigma_k", 1.0, 0.1, 10.0, "1", "turbulent Prandtl number of k"},
      {"sigma_eps", 1.3, 0.1, 10.0, "1", "turbulent Prandtl number of epsilon"}},
     "  double *mu_t = a->out[OUT_MU_T], *mu_t_k = a->out[OUT_MU_T_K], *mu_t_eps = a->out[OUT_MU_T_EPS];\n"
     "  double *eps_production = a->out[OUT_EPS_PRODUCTION], *eps_sink = a->out[OUT_EPS_SINK];\n"
     "  double *c_mu = a->out[OUT_C_MU];\n",
     "    const double k = a->in[IN_K][q], eps = a->in[IN_EPSILON][q], rho = a->in[IN_RHO_F][q];\n"
     "    mu_t[q] = p->c_mu * rho * k * k / eps;\n"
     "    mu_t_k[q] = mu_t[q] / p->sigma_k;\n"
     "    mu_t_eps[q] = mu_t[q] / p->sigma_eps;\n"
     "    eps_production[q] = p->c_eps1 * eps / k;\n"
     "    eps_sink[q] = p->c_eps2 * rho * eps / k;\n"
     "    c_mu[q] = p->c_mu;\n",
     "mu_t = c_mu rho_f k^2 / epsilon,  mu_t_k = mu_t / sigma_k,  mu_t_eps = mu_t / sigma_eps,\n"
     "eps_production = c_eps1 epsilon / k,  eps_sink = c_eps2 rho_f epsilon / k",
     "Launder & Spalding (1974), the standard k-epsilon model",
     "fully turbulent flow away from walls (high Reynolds number)",
     {1.0, 0.09, 1.0},
     1.0,
     "0.09 * 1 * 1^2 / 0.09"},
    {SL_KIND_DENSIFICATION,
     {"nbar", "strain_amplitude"},
     0u,
     {"nbar_new"},
     {{"compaction", 0.01, 0.0, 0.5, "1", "volumetric strain of a half-cycle per unit strain amplitude"}},
     "  double *nbar_new = a->out[OUT_NBAR_NEW];\n",
     "    const double nbar = a->in[IN_NBAR][q], amp = a->in[IN_STRAIN_AMPLITUDE][q];\n"
     "    const double d = p->compaction * amp; /* 0 between reversals: nbar unchanged */\n"
     "    const double n1 = 1.0 - (1.0 - nbar) / (1.0 - d); /* the solids keep their volume */\n"
     "    if (!(n1 > 0.0)) return sl_fail(a->err, SL_RECOVERABLE, q, \"a half-cycle of amplitude %g compacts nbar = %g "
     "to %g\", amp, nbar, n1);\n"
     "    nbar_new[q] = n1;\n",
     "d = compaction strain_amplitude,  1 - nbar_new = (1 - nbar) / (1 - d)",
     "a placeholder, not a published law (the shipped byrne closure is Byrne 1991): replace it",
     "0.01 <= nbar <= 0.99, strain amplitude up to 1",
     {0.45, 0.1},
     0.4494494494494494,
     "1 - 0.55 / (1 - 0.01 * 0.1)"},
    {SL_KIND_LIFT,
     {"shear_rate"},
     0u,
     {"C_L"},
     {{"coefficient", 0.5, -10.0, 10.0, "1", "the lift coefficient C_L"}},
     "  double *C_L = a->out[OUT_C_L];\n",
     "    (void)a->in[IN_SHEAR_RATE][q]; /* a constant coefficient: the shear rate does not enter */\n"
     "    C_L[q] = p->coefficient;\n",
     "C_L = coefficient",
     "Auton (1987) J. Fluid Mech. 183:199: C_L = 1/2 for a sphere in a weak inviscid shear",
     "a weak shear of an inviscid flow",
     {10.0},
     0.5,
     "C_L = 0.5"},
    {SL_KIND_TURBULENT_DISPERSION,
     {"nu_t"},
     0u,
     {"D_t"},
     {{"schmidt", 1.0, 1e-3, 1e3, "1", "the turbulent Schmidt number sigma of the solids"}},
     "  double *D_t = a->out[OUT_D_T];\n",
     "    D_t[q] = a->in[IN_NU_T][q] / p->schmidt;\n",
     "D_t = nu_t / schmidt",
     "Krampa (2009) eq 4.59: the gradient form with Schmidt number 1",
     "solids that follow the fluid's eddies",
     {2.5e-3},
     2.5e-3,
     "D_t = 2.5e-3 / 1"},
    {SL_KIND_TURBULENCE_MODULATION,
     {"drag_coefficient"},
     0u,
     {"exchange", "c_eps3"},
     {{"c_eps3", 1.2, 0.0, 10.0, "1", "C_eps3 of the epsilon equation's modulation"}},
     "  double *exchange = a->out[OUT_EXCHANGE], *c_eps3 = a->out[OUT_C_EPS3];\n",
     "    exchange[q] = a->in[IN_DRAG_COEFFICIENT][q];\n"
     "    c_eps3[q] = p->c_eps3;\n",
     "exchange = K, c_eps3 = 1.2",
     "Simonin (1996); Krampa (2009) eq 4.80, Table 4.1: the exchange coefficient is the drag's K",
     "particles smaller than the energetic eddies",
     {1500.0},
     1500.0,
     "exchange = K = 1500"},
};

static const ttemplate *template_of(sl_kind k) {
  for (size_t i = 0; i < sizeof templates / sizeof templates[0]; ++i)
    if (templates[i].kind == k) return &templates[i];
  return NULL;
}

static const sl_kind_output *kind_output(const sl_kind_info *info, const char *name) {
  for (int i = 0; i < SL_KIND_MAX_OUTPUTS && info->outputs[i].name; ++i)
    if (strcmp(info->outputs[i].name, name) == 0) return &info->outputs[i];
  return NULL;
}

/* IN_SLIP_WALL from "slip_wall". */
static void enum_name(const char *prefix, const char *name, char *buf, size_t n) {
  size_t k = (size_t)snprintf(buf, n, "%s", prefix);
  for (; *name && k + 1 < n; ++name) buf[k++] = (char)(*name >= 'a' && *name <= 'z' ? *name - 'a' + 'A' : *name);
  buf[k] = '\0';
}

static void real(FILE *f, double v) {
  if (isinf(v)) fprintf(f, "%sHUGE_VAL", v < 0 ? "-" : "");
  else fprintf(f, "%.15g", v);
}

/* A C string literal of plain text (no quotes or backslashes in the registry's texts). */
static void c_string(FILE *f, const char *s) {
  fputc('"', f);
  for (; *s; ++s) {
    if (*s == '\n') fputs("\\n\"\n    \"", f);
    else if (*s == '"' || *s == '\\') fprintf(f, "\\%c", *s);
    else fputc(*s, f);
  }
  fputc('"', f);
}

static void write_comment_wrapped(FILE *f, const char *text) {
  /* " * " lines of at most about 76 columns */
  const char *s = text;
  while (*s) {
    size_t len = strlen(s), cut = len;
    if (len > 73) {
      cut = 73;
      while (cut > 0 && s[cut] != ' ') --cut;
      if (cut == 0) cut = 73;
    }
    fprintf(f, " * %.*s\n", (int)cut, s);
    s += cut;
    while (*s == ' ') ++s;
  }
}

static void write_source(FILE *f, const ttemplate *t, const char *name) {
  const sl_kind_info *info = sl_kind_info_of(t->kind);
  const char *kind = sl_kind_name(t->kind);
  char e[64];
  int n_in = 0, n_out = 0, n_par = 0;
  while (n_in < T_MAX_IN && t->in[n_in]) ++n_in;
  while (n_out < T_MAX_OUT && t->out[n_out]) ++n_out;
  while (n_par < T_MAX_PARAMS && t->params[n_par].name) ++n_par;
  fprintf(f, "/* %s: a %s closure for sluice.\n *\n", name, kind);
  char buf[1024];
  snprintf(buf, sizeof buf,
           "A %s closure gives the %s (`sluice closure kinds %s` prints the contract; "
           "docs/closure-kinds.md).",
           kind, info->summary, kind);
  write_comment_wrapped(f, buf);
  fprintf(f, " *\n");
  snprintf(buf, sizeof buf,
           "Written by `sluice closure new %s %s`. The law between the PLACEHOLDER LAW lines of "
           "evaluate() is a stand-in (%s; %s): replace it, and with it the formula, reference and "
           "validity of the descriptor, the parameters, the inputs' validity ranges and the check "
           "point. Then build and run the conformance battery:",
           kind, name, t->formula, t->reference);
  for (char *c = buf; *c; ++c)
    if (*c == '\n') *c = ' ';
  write_comment_wrapped(f, buf);
  fprintf(f,
          " *   cmake -S . -B build -DCMAKE_PREFIX_PATH=<sluice install prefix>\n"
          " *   cmake --build build && ctest --test-dir build   (runs sluice check-closure build/%s.so)\n"
          " * and use it in a scene with SLUICE_PLUGIN_PATH=$PWD/build:\n"
          " *   [closure.%s]\n *   model = %s\n */\n",
          name, kind, name);
  fprintf(f, "#include <math.h>\n#include <sluice/closure.h>\n\n");
  /* parameters */
  fprintf(f,
          "/* The parameters: the host validates them against the schema below before\n"
          " * evaluate() sees them (the battery checks that values outside [min, max] are\n"
          " * refused). */\ntypedef struct %s_params {\n",
          name);
  for (int i = 0; i < n_par; ++i) fprintf(f, "  double %s; /* %s */\n", t->params[i].name, t->params[i].units);
  fprintf(f, "} %s_params;\n\nstatic const sl_param_desc params[] = {\n", name);
  for (int i = 0; i < n_par; ++i) {
    const tparam *p = &t->params[i];
    fprintf(f, "    SL_PARAM_REAL_OF(%s_params, %s, ", name, p->name);
    real(f, p->def);
    fputs(", ", f);
    real(f, p->min);
    fputs(", ", f);
    real(f, p->max);
    fprintf(f, ", \"%s\", \"%s\"),\n", p->units, p->help);
  }
  fprintf(f, "};\n\n");
  /* inputs and outputs */
  fprintf(f, "enum {");
  for (int i = 0; i < n_in; ++i) {
    enum_name("IN_", t->in[i], e, sizeof e);
    fprintf(f, " %s,", e);
  }
  fprintf(f, " N_IN };\nenum {");
  for (int k = 0; k < n_out; ++k) {
    enum_name("OUT_", t->out[k], e, sizeof e);
    fprintf(f, " %s,", e);
  }
  fprintf(f, " N_OUT };\n\n");
  fprintf(f,
          "/* Inputs: name, units, flags (SL_FIELD_DIFF: evaluate() returns the outputs'\n"
          " * derivatives in it), a typical value, the closed validity range [min, max]\n"
          " * and a meaning. The host supplies the inputs by name (`sluice closure kinds`\n"
          " * lists them); narrow each range to where the law holds. */\n");
  fprintf(f, "static const sl_field_desc inputs[N_IN] = {\n");
  for (int i = 0; i < n_in; ++i) {
    const sl_input_info *in = sl_input_find(t->in[i]);
    fprintf(f, "    {\"%s\", \"%s\", %s, ", in->name, in->units, (t->diff >> i & 1u) ? "SL_FIELD_DIFF" : "0");
    real(f, in->typical);
    fputs(", ", f);
    real(f, in->min);
    fputs(", ", f);
    real(f, in->max);
    fprintf(f, ", \"%s\"},\n", in->meaning);
  }
  fprintf(f, "};\nstatic const sl_field_desc outputs[N_OUT] = {\n");
  for (int k = 0; k < n_out; ++k) {
    const sl_kind_output *o = kind_output(info, t->out[k]);
    fprintf(f, "    {\"%s\", \"%s\", 0, 0, 0, 0, \"%s\"},\n", o->name, o->units, o->meaning);
  }
  fprintf(f, "};\n\n");
  /* check point */
  enum_name("OUT_", t->out[0], e, sizeof e);
  fprintf(f,
          "/* A value of the law at one state, parameters at their defaults: the battery\n"
          " * compares it. Give a published value (a table, a figure) for the real law. */\n");
  fprintf(f, "static const double check_in[N_IN] = {");
  for (int i = 0; i < n_in; ++i) {
    fputs(i ? ", " : "", f);
    real(f, t->check_in[i]);
  }
  fprintf(f, "};\nstatic const sl_check_point checks[] = {{check_in, %s, ", e);
  real(f, t->expected);
  fprintf(f, ", 1e-12, \"%s\"}};\n\n", t->source);
  /* evaluate */
  fprintf(f,
          "static int evaluate(const void *state, const sl_eval_args *a) {\n"
          "  const %s_params *p = state;\n%s",
          name, t->setup);
  fprintf(f, "  for (int32_t q = 0; q < a->Q; ++q) {\n");
  snprintf(buf, sizeof buf, "Range checks. A %s closure refuses %s.", kind, info->range_checks);
  fprintf(f, "    /*\n");
  {
    /* the wrapped text, indented as the loop's body */
    const char *s = buf;
    while (*s) {
      size_t len = strlen(s), cut = len;
      if (len > 70) {
        cut = 70;
        while (cut > 0 && s[cut] != ' ') --cut;
        if (cut == 0) cut = 70;
      }
      fprintf(f, "     * %.*s\n", (int)cut, s);
      s += cut;
      while (*s == ' ') ++s;
    }
  }
  fprintf(f,
          "     * Here: every input outside its declared range, or NaN, returns\n"
          "     * SL_RECOVERABLE with the point (the host may cut the step); narrow the\n"
          "     * ranges above rather than removing this loop. */\n"
          "    for (int32_t i = 0; i < N_IN; ++i) {\n"
          "      const double v = a->in[i][q];\n"
          "      if (!(v >= inputs[i].valid_min && v <= inputs[i].valid_max))\n"
          "        return sl_fail(a->err, SL_RECOVERABLE, q, \"%%s = %%g outside [%%g, %%g]\", inputs[i].name, v,\n"
          "                       inputs[i].valid_min, inputs[i].valid_max);\n"
          "    }\n");
  fprintf(f, "    /* ==== PLACEHOLDER LAW: replace from here ... ==== */\n%s", t->law);
  fprintf(f, "    /* ==== ... to here (end of the placeholder law) ==== */\n  }\n  return SL_OK;\n}\n\n");
  /* descriptor */
  fprintf(f,
          "static const sl_closure_desc closure = {\n"
          "    SL_CLOSURE_DESC_HEADER,\n"
          "    .kind = SL_KIND_");
  enum_name("", kind, e, sizeof e);
  fprintf(f, "%s,\n    .name = \"%s\",\n    .version = \"0.1.0\",\n    .summary = ", e, name);
  snprintf(buf, sizeof buf, "%s closure %s (template: placeholder law)", kind, name);
  c_string(f, buf);
  fprintf(f, ",\n    .formula = ");
  c_string(f, t->formula);
  fprintf(f, ",\n    .reference = ");
  c_string(f, t->reference);
  fprintf(f, ",\n    .validity = ");
  c_string(f, t->validity);
  fprintf(f,
          ",\n"
          "    .n_params = SL_COUNT_OF(params),\n"
          "    .params = params,\n"
          "    .params_size = sizeof(%s_params),\n"
          "    .n_in = N_IN,\n"
          "    .in = inputs,\n"
          "    .n_out = N_OUT,\n"
          "    .out = outputs,\n"
          "    .n_checks = SL_COUNT_OF(checks),\n"
          "    .checks = checks,\n"
          "    .evaluate = evaluate,\n"
          "};\n\n"
          "static const sl_closure_desc *const all[] = {&closure};\n\n"
          "SL_EXPORT const sl_closure_desc *const *sl_closure_entry_v1(int32_t *count) {\n"
          "  *count = SL_COUNT_OF(all);\n"
          "  return all;\n"
          "}\n",
          name);
}

static void write_cmake(FILE *f, const char *name) {
  fprintf(f,
          "# Builds %s.so, a sluice closure, against an installed sluice, and registers\n"
          "# the conformance battery (sluice check-closure) on it as a test:\n"
          "#   cmake -S . -B build -DCMAKE_PREFIX_PATH=<sluice install prefix>\n"
          "#   cmake --build build && ctest --test-dir build\n"
          "# Use it with SLUICE_PLUGIN_PATH=$PWD/build.\n"
          "cmake_minimum_required(VERSION 3.25)\n"
          "project(%s LANGUAGES C)\n"
          "find_package(sluice 0.1 REQUIRED)\n"
          "sluice_add_closure(%s %s.c)\n"
          "enable_testing()\n"
          "sluice_add_closure_test(%s)\n",
          name, name, name, name, name);
}

static int valid_name(const char *s) {
  if (!(*s >= 'a' && *s <= 'z')) return 0;
  size_t n = 0;
  for (; *s; ++s, ++n)
    if (!((*s >= 'a' && *s <= 'z') || (*s >= '0' && *s <= '9') || *s == '_')) return 0;
  return n <= 48;
}

static int exists(const char *path) {
  struct stat st;
  return stat(path, &st) == 0;
}

int sl_cmd_closure_new(int argc, char **argv) {
  if (sl_cli_wants_help(argc, argv)) {
    puts(sl_closure_new_usage);
    return 0;
  }
  const char *kind_name = NULL, *name = NULL, *dir = NULL;
  for (int i = 0; i < argc; ++i) {
    if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) dir = argv[++i];
    else if (argv[i][0] == '-')
      return sl_cli_error(SL_EBADINPUT, "closure new: unknown option or missing value '%s'", argv[i]);
    else if (!kind_name) kind_name = argv[i];
    else if (!name) name = argv[i];
    else
      return sl_cli_error(SL_EBADINPUT, "closure new: unexpected argument '%s' (sluice closure new KIND NAME [-o DIR])",
                          argv[i]);
  }
  if (!kind_name || !name)
    return sl_cli_error(SL_EBADINPUT,
                        "closure new: give a kind and a name (sluice closure new KIND NAME [-o DIR]; "
                        "`sluice closure kinds` lists the kinds)");
  sl_kind kind;
  sl_diag d;
  if (sl_kind_from_name(kind_name, &kind, &d)) return sl_cli_error(SL_EBADINPUT, "closure new: %s", d.msg);
  if (!valid_name(name))
    return sl_cli_error(SL_EBADINPUT,
                        "closure new: name '%s': lower_snake_case expected (a-z first, then a-z, 0-9, _; "
                        "at most 48 characters)",
                        name);
  const ttemplate *t = template_of(kind);
  if (!t) return sl_cli_error(SL_EFAILED, "closure new: no template for kind %s", kind_name);
  if (!dir) dir = name;
  char src[4096], cm[4096];
  if ((size_t)snprintf(src, sizeof src, "%s/%s.c", dir, name) >= sizeof src ||
      (size_t)snprintf(cm, sizeof cm, "%s/CMakeLists.txt", dir) >= sizeof cm)
    return sl_cli_error(SL_EBADINPUT, "closure new: -o %s: path too long", dir);
  if (exists(src)) return sl_cli_error(SL_EBADINPUT, "closure new: %s exists; not overwritten", src);
  if (exists(cm)) return sl_cli_error(SL_EBADINPUT, "closure new: %s exists; not overwritten", cm);
  if (!exists(dir) && mkdir(dir, 0777) != 0)
    return sl_cli_error(SL_EBADINPUT, "closure new: cannot create the folder %s: %s", dir, strerror(errno));
  FILE *f = fopen(src, "w");
  if (!f) return sl_cli_error(SL_EBADINPUT, "closure new: cannot write %s: %s", src, strerror(errno));
  write_source(f, t, name);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) return sl_cli_error(SL_EFAILED, "closure new: writing %s failed", src);
  f = fopen(cm, "w");
  if (!f) return sl_cli_error(SL_EBADINPUT, "closure new: cannot write %s: %s", cm, strerror(errno));
  write_cmake(f, name);
  bad = ferror(f);
  if (fclose(f) != 0 || bad) return sl_cli_error(SL_EFAILED, "closure new: writing %s failed", cm);
  printf(
      "wrote %s and %s: a %s closure '%s' with a placeholder law (%s)\n"
      "next: replace the law between the PLACEHOLDER LAW lines of %s, then\n"
      "  cmake -S %s -B %s/build -DCMAKE_PREFIX_PATH=<sluice install prefix>\n"
      "  cmake --build %s/build && ctest --test-dir %s/build\n",
      src, cm, kind_name, name, t->reference, src, dir, dir, dir, dir);
  return 0;
}
