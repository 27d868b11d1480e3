/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Exact solutions from a run's scene (see exact.h). */
#include "core/study/exact.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plugin/closure_ini.h"
#include "core/plugin/instance.h"
#include "core/study/bingham_exact.h"
#include "core/study/fluidized_bed_exact.h"
#include "core/study/kynch_exact.h"

typedef enum { EXACT_KYNCH, EXACT_BINGHAM, EXACT_FLUIDIZED_BED } exact_kind;

struct sl_bench_exact {
  exact_kind kind;
  double x0, x1;
  kynch k;
  bingham_channel b;
  double bed_phi; /* fluidized_bed: the equilibrium solids fraction, 1 - porosity */
  char description[512];
};

static int refuse(sl_diag *d, const char *name, const char *why) {
  return sl_diag_set(d, SL_EBADINPUT, "exact = %s: %s", name, why);
}

static int get_text(const sl_ini *ini, const char *sec, const char *key, const char *def, const char **v, sl_diag *d) {
  return sl_ini_get_string(ini, sec, key, 0, def, v, d);
}

/* A 1-D interval column: [scene] geometry = line, [mesh] generator = interval, x = a, b. */
static int column(const char *name, const sl_ini *ini, double *x0, double *x1, sl_diag *d) {
  const char *geometry, *generator;
  int rc = get_text(ini, "scene", "geometry", "planar", &geometry, d);
  if (!rc) rc = get_text(ini, "mesh", "generator", "", &generator, d);
  if (rc) return rc;
  if (strcmp(geometry, "line") || strcmp(generator, "interval"))
    return refuse(d, name, "needs a 1-D scene: [scene] geometry = line and [mesh] generator = interval");
  double x[2];
  int n = 0;
  if ((rc = sl_ini_get_real_list(ini, "mesh", "x", 1, x, 2, &n, d))) return rc;
  if (n != 2 || !(x[1] > x[0])) return refuse(d, name, "[mesh] x must be two increasing numbers");
  *x0 = x[0], *x1 = x[1];
  return 0;
}

/* Every boundary section is a wall (sections left out are walls too). */
static int walls(const char *name, const sl_ini *ini, sl_diag *d) {
  for (int i = 0; i < ini->n_sections; ++i) {
    const sl_ini_section *s = &ini->sections[i];
    if (strncmp(s->name, "boundary.", 9)) continue;
    const sl_ini_entry *t = sl_ini_find(ini, s->name, "type");
    if (t && strcmp(t->value, "wall")) {
      char why[300];
      snprintf(why, sizeof why, "needs walls at both ends; [%s] type = %s", s->name, t->value);
      return refuse(d, name, why);
    }
  }
  return 0;
}

static int zero_or_absent(const char *name, const sl_ini *ini, const char *sec, const char *key, sl_diag *d) {
  double v = 0.0;
  int rc = sl_ini_get_real(ini, sec, key, 0, 0.0, -1e300, 1e300, &v, d);
  if (rc) return rc;
  if (v != 0.0) {
    char why[200];
    snprintf(why, sizeof why, "does not cover [%s] %s = %g", sec, key, v);
    return refuse(d, name, why);
  }
  return 0;
}

static double param(const sl_closure *c, const char *key, char *text, size_t n) {
  int i = sl_params_find(c->desc, key);
  double v = NAN;
  text[0] = '\0';
  if (i < 0) return NAN;
  sl_params_format_value(c->desc, c->params, i, text, n);
  if (sl_parse_real(text, &v)) v = NAN;
  return v;
}

/* ---- Kynch ------------------------------------------------------------------- */

/* The settling velocity of the closure at n values of phi, its other inputs
 * bound to the scene as the mixture model binds them. */
static int settling_velocity(sl_closure *c, const sl_ini *ini, double g, int n, const double *phi, double *u,
                             sl_diag *d) {
  const sl_closure_desc *desc = c->desc;
  int n_in = desc->n_in, n_out = desc->n_out, out_u = sl_closure_output(desc, "settling_velocity");
  if (out_u < 0 || sl_closure_input(desc, "phi") < 0)
    return refuse(d, "kynch", "the hindered-settling closure does not map phi to a settling_velocity");
  double *work = calloc((size_t)(n_in + n_out) * (size_t)n, sizeof *work);
  const double **in = calloc((size_t)n_in, sizeof *in);
  double **out = calloc((size_t)n_out, sizeof *out), **dout = calloc((size_t)n_in * (size_t)n_out, sizeof *dout);
  int rc = 0;
  if (!work || !in || !out || !dout) rc = sl_diag_set(d, SL_ENOMEM, "exact = kynch: out of memory");
  for (int i = 0; i < n_in && !rc; ++i) {
    const char *name = desc->in[i].name;
    double *col = work + (size_t)i * (size_t)n, v = 0.0;
    if (!strcmp(name, "phi")) {
      memcpy(col, phi, (size_t)n * sizeof *col);
      in[i] = col;
      continue;
    }
    if (!strcmp(name, "d_p")) rc = sl_ini_get_real(ini, "solid", "diameter", 1, 0, 1e-9, 1.0, &v, d);
    else if (!strcmp(name, "sphericity")) rc = sl_ini_get_real(ini, "solid", "sphericity", 0, 1.0, 0.01, 1.0, &v, d);
    else if (!strcmp(name, "rho_s")) rc = sl_ini_get_real(ini, "solid", "density", 1, 0, 1e-3, 1e5, &v, d);
    else if (!strcmp(name, "rho_f")) rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, &v, d);
    else if (!strcmp(name, "mu_f")) rc = sl_ini_get_real(ini, "fluid", "viscosity", 0, 1e-3, 1e-7, 1e7, &v, d);
    else if (!strcmp(name, "gravity")) v = g;
    else if (!strcmp(name, "d_vessel")) v = HUGE_VAL;
    else {
      char why[200];
      snprintf(why, sizeof why, "the settling closure needs the input '%s'", name);
      rc = refuse(d, "kynch", why);
    }
    for (int k = 0; k < n; ++k) col[k] = v;
    in[i] = col;
  }
  for (int k = 0; k < n_out && !rc; ++k) out[k] = work + (size_t)(n_in + k) * (size_t)n;
  if (!rc) {
    sl_error err;
    sl_eval_args a = {.Q = n, .in = in, .out = out, .dout = dout, .err = &err};
    if (sl_closure_evaluate(c, &a)) {
      char why[600];
      snprintf(why, sizeof why, "the settling closure refused phi = %g: %s",
               err.point >= 0 && err.point < n ? phi[err.point] : NAN, err.msg);
      rc = refuse(d, "kynch", why);
    } else {
      memcpy(u, out[out_u], (size_t)n * sizeof *u);
    }
  }
  free(work), free(in), free(out), free(dout);
  return rc;
}

static int kynch_create(sl_bench_exact *e, const sl_ini *ini, const sl_registry *reg, sl_diag *d) {
  int rc = column("kynch", ini, &e->x0, &e->x1, d);
  if (rc) return rc;
  const char *model;
  if ((rc = get_text(ini, "scene", "model", "", &model, d))) return rc;
  if (strcmp(model, "mixture")) return refuse(d, "kynch", "needs a mixture scene ([scene] model = mixture)");
  if ((rc = walls("kynch", ini, d))) return rc;
  double g[3] = {0, 0, 0};
  int ng = 0;
  if ((rc = sl_ini_get_real_list(ini, "flow", "gravity", 0, g, 3, &ng, d))) return rc;
  if (!(g[0] < 0.0)) return refuse(d, "kynch", "needs gravity along -x ([flow] gravity < 0): the sediment at x0");
  if ((rc = zero_or_absent("kynch", ini, "flow", "rotation", d))) return rc;
  if ((rc = zero_or_absent("kynch", ini, "mixture", "diffusivity", d))) return rc;
  int slip = 0;
  if ((rc = sl_ini_get_bool(ini, "mixture", "slip_acceleration", 0, 0, &slip, d))) return rc;
  if (slip) return refuse(d, "kynch", "does not cover [mixture] slip_acceleration = true");
  double gref = -g[0];
  if ((rc = sl_ini_get_real(ini, "mixture", "reference_acceleration", 0, gref, 1e-12, 1e12, &gref, d))) return rc;
  if (gref != -g[0]) return refuse(d, "kynch", "needs [mixture] reference_acceleration = |g| (or left out)");
  if (sl_ini_find_section(ini, "closure.migration")) return refuse(d, "kynch", "does not cover [closure.migration]");
  const sl_ini_entry *init = sl_ini_find(ini, "initial", "phi");
  double phi0;
  if (!init || sl_parse_real(init->value, &phi0) || !(phi0 > 0.0))
    return refuse(d, "kynch", "needs a uniform suspension: [initial] phi = a number above 0");
  if (!sl_ini_find_section(ini, "closure.hindered_settling"))
    return refuse(d, "kynch", "needs a [closure.hindered_settling]");
  sl_closure *c = NULL;
  if ((rc = sl_closure_from_ini(reg, ini, "closure.hindered_settling", &c, d))) return rc;
  char text[64], law_text[200];
  kx_law law;
  const char *cname = c->desc->name;
  if (!strcmp(cname, "richardson_zaki")) {
    char exponent[64], cutoff[64];
    param(c, "exponent", exponent, sizeof exponent);
    param(c, "packing_cutoff", cutoff, sizeof cutoff);
    double n = param(c, "n", text, sizeof text), pm = param(c, "phi_max", text, sizeof text);
    if (strcmp(exponent, "given") || strcmp(cutoff, "true")) {
      sl_closure_destroy(c);
      return refuse(d, "kynch",
                    "covers richardson_zaki with exponent = given and packing_cutoff = true (the flux "
                    "must vanish at phi_max)");
    }
    law = kx_richardson_zaki(1.0, n, pm);
    snprintf(law_text, sizeof law_text, "Richardson-Zaki n = %g, cut-off at %g", n, pm);
  } else if (!strcmp(cname, "nigam")) {
    double pm = param(c, "phi_max", text, sizeof text), K = param(c, "intrinsic_viscosity", text, sizeof text);
    law = kx_nigam(1.0, K, pm);
    snprintf(law_text, sizeof law_text, "Nigam K = %g, alpha_m = %g", K, pm);
  } else {
    char why[300];
    snprintf(why, sizeof why, "covers the settling closures richardson_zaki and nigam, not %s", cname);
    sl_closure_destroy(c);
    return refuse(d, "kynch", why);
  }
  /* u_t is the closure's velocity at phi = 0 (f(0) = 1 for both laws); the
   * law must then be the closure's at every phi */
  enum { NP = 9 };
  double phi[NP], u[NP];
  phi[0] = 0.0;
  for (int i = 1; i < NP; ++i) phi[i] = law.c * i / NP;
  rc = settling_velocity(c, ini, -g[0], NP, phi, u, d);
  sl_closure_destroy(c);
  if (rc) return rc;
  law.u_t = u[0];
  if (!(law.u_t > 0.0))
    return refuse(d, "kynch", "needs particles that sink (a positive settling velocity at phi = 0)");
  for (int i = 1; i < NP; ++i) {
    double mine = kx_F(&law, phi[i]) / phi[i];
    if (!(fabs(mine - u[i]) <= 1e-9 * law.u_t)) {
      char why[600];
      snprintf(why, sizeof why, "the closure's settling velocity at phi = %g is %.10g, the law (%s) gives %.10g",
               phi[i], u[i], law_text, mine);
      return refuse(d, "kynch", why);
    }
  }
  if (!(phi0 < law.c)) return refuse(d, "kynch", "needs [initial] phi below the packing fraction");
  if (kx_init(&e->k, law, e->x1 - e->x0, phi0))
    return refuse(d, "kynch", "this flux and phi0 fall outside the construction (see the message above)");
  snprintf(e->description, sizeof e->description,
           "exact Kynch solution: %s, u_t = %.4g m/s, phi0 = %g, column %g m; the fronts meet at t = %.4g s", law_text,
           law.u_t, phi0, e->x1 - e->x0, e->k.t1);
  return 0;
}

/* ---- Bingham ----------------------------------------------------------------- */

static int bingham_create(sl_bench_exact *e, const sl_ini *ini, const sl_registry *reg, sl_diag *d) {
  int rc = column("bingham", ini, &e->x0, &e->x1, d);
  if (rc) return rc;
  const char *model;
  if ((rc = get_text(ini, "scene", "model", "", &model, d))) return rc;
  if (strcmp(model, "navier_stokes")) return refuse(d, "bingham", "needs [scene] model = navier_stokes");
  int third = 0;
  if ((rc = sl_ini_get_bool(ini, "flow", "third_component", 0, 0, &third, d))) return rc;
  if (!third) return refuse(d, "bingham", "needs [flow] third_component = true (the axial velocity)");
  if ((rc = walls("bingham", ini, d))) return rc;
  if ((rc = zero_or_absent("bingham", ini, "flow", "rotation", d))) return rc;
  double rho = 1000.0, f[3] = {0, 0, 0}, g[3] = {0, 0, 0};
  int nf = 0, ng = 0;
  if ((rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, &rho, d))) return rc;
  if ((rc = sl_ini_get_real_list(ini, "flow", "body_force", 0, f, 3, &nf, d))) return rc;
  if ((rc = sl_ini_get_real_list(ini, "flow", "gravity", 0, g, 3, &ng, d))) return rc;
  if (f[0] != 0.0 || g[0] != 0.0) return refuse(d, "bingham", "needs no force across the channel (first components 0)");
  const sl_ini_entry *vm = sl_ini_find(ini, "closure.viscosity", "model");
  if (!vm || strcmp(vm->value, "bingham")) return refuse(d, "bingham", "needs [closure.viscosity] model = bingham");
  sl_closure *c = NULL;
  if ((rc = sl_closure_from_ini(reg, ini, "closure.viscosity", &c, d))) return rc;
  char text[64];
  e->b.mu_p = param(c, "plastic_viscosity", text, sizeof text);
  e->b.tau0 = param(c, "yield_stress", text, sizeof text);
  sl_closure_destroy(c);
  if (!(e->b.mu_p > 0.0) || !(e->b.tau0 >= 0.0)) return refuse(d, "bingham", "needs plastic_viscosity > 0");
  e->b.G = f[1] + rho * g[1];
  e->b.centre = 0.5 * (e->x0 + e->x1), e->b.half_width = 0.5 * (e->x1 - e->x0);
  snprintf(
      e->description, sizeof e->description,
      "exact Bingham channel flow: mu_p = %g Pa s, tau0 = %g Pa, G = %g Pa/m, plug |y - %g| < %g, w_plug = %.6g m/s",
      e->b.mu_p, e->b.tau0, e->b.G, e->b.centre, e->b.G != 0.0 ? e->b.tau0 / fabs(e->b.G) : INFINITY,
      bingham_channel_velocity(&e->b, e->b.centre));
  return 0;
}

/* ---- fluidised bed ------------------------------------------------------------ */

enum { DRAG_MAX_FIELDS = 32 };

/* The scene's drag closure with its inputs other than phi and slip bound as
 * the two_fluid model binds them (core/models/two_fluid.c). */
typedef struct drag_binding {
  sl_closure *c;
  int in_phi, in_slip, out_K;
  double fixed[DRAG_MAX_FIELDS];
  double failed_phi, failed_slip; /* where the closure refused, NaN: it did not */
  char failure[400];
} drag_binding;

/* fb_drag_fn (core/study/fluidized_bed_exact.h): K at one point. */
static int drag_at(void *user, double phi, double slip, double *K) {
  drag_binding *b = user;
  const sl_closure_desc *desc = b->c->desc;
  double in_values[DRAG_MAX_FIELDS], out_values[DRAG_MAX_FIELDS];
  const double *in[DRAG_MAX_FIELDS];
  double *out[DRAG_MAX_FIELDS];
  for (int i = 0; i < desc->n_in; ++i) {
    in_values[i] = i == b->in_phi ? phi : i == b->in_slip ? slip : b->fixed[i];
    in[i] = &in_values[i];
  }
  for (int k = 0; k < desc->n_out; ++k) out[k] = &out_values[k];
  sl_error err;
  sl_eval_args a = {.Q = 1, .in = in, .out = out, .dout = NULL, .err = &err};
  if (sl_closure_evaluate(b->c, &a)) {
    b->failed_phi = phi, b->failed_slip = slip;
    snprintf(b->failure, sizeof b->failure, "%s", err.msg);
    return -1;
  }
  *K = out_values[b->out_K];
  return 0;
}

/* The two_fluid model's defaults: fluid 1000 kg/m3 and 1e-3 Pa s, sphericity 1, phi_max 0.64 (or 1 -
 * porosity_max), gravity -9.81 along x. */
static int bed_physics(const sl_ini *ini, double *rho_f, double *mu_f, double *rho_s, double *d_p, double *sphericity,
                       double *phi_max, double *g, sl_diag *d) {
  int rc = sl_ini_get_real(ini, "fluid", "density", 0, 1000.0, 1e-3, 1e5, rho_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "fluid", "viscosity", 0, 1e-3, 1e-7, 1e7, mu_f, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "density", 1, 0, 1e-3, 1e5, rho_s, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "diameter", 1, 0, 1e-9, 1.0, d_p, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "sphericity", 0, 1.0, 0.01, 1.0, sphericity, d);
  if (!rc) rc = sl_ini_get_real(ini, "solid", "phi_max", 0, 0.64, 0.01, 0.99, phi_max, d);
  if (rc) return rc;
  if (sl_ini_find(ini, "solid", "porosity_max")) {
    double n_min;
    if ((rc = sl_ini_get_real(ini, "solid", "porosity_max", 0, 0.36, 0.01, 0.99, &n_min, d))) return rc;
    *phi_max = 1.0 - n_min;
  }
  double gl[3] = {-9.81, 0, 0};
  int ng = 0;
  if ((rc = sl_ini_get_real_list(ini, "flow", "gravity", 0, gl, 3, &ng, d))) return rc;
  *g = gl[0];
  return 0;
}

/* The inlet: [boundary.left] type = inlet with a constant velocity U > 0, the other end an outlet. */
static int bed_inlet(const sl_ini *ini, double *U, sl_diag *d) {
  const sl_ini_entry *left = sl_ini_find(ini, "boundary.left", "type");
  const sl_ini_entry *right = sl_ini_find(ini, "boundary.right", "type");
  if (!left || strcmp(left->value, "inlet"))
    return refuse(d, "fluidized_bed", "needs the fluid to enter at the bottom: [boundary.left] type = inlet");
  if (!right || strcmp(right->value, "outlet"))
    return refuse(d, "fluidized_bed", "needs an outlet at the top: [boundary.right] type = outlet");
  if (sl_ini_find(ini, "boundary.left", "porosity"))
    return refuse(d, "fluidized_bed",
                  "the inlet gives the bed's porosity itself ([boundary.left] porosity); give its "
                  "superficial velocity instead");
  const sl_ini_entry *v = sl_ini_find(ini, "boundary.left", "velocity");
  if (!v || sl_parse_real(v->value, U) || !(*U > 0.0))
    return refuse(d, "fluidized_bed", "needs a constant inflow: [boundary.left] velocity = a number above 0 (m/s)");
  return 0;
}

static int fluidized_bed_create(sl_bench_exact *e, const sl_ini *ini, const sl_registry *reg, sl_diag *d) {
  const char *name = "fluidized_bed", *model;
  int rc = column(name, ini, &e->x0, &e->x1, d);
  if (!rc) rc = get_text(ini, "scene", "model", "", &model, d);
  if (rc) return rc;
  if (strcmp(model, "two_fluid")) return refuse(d, name, "needs a two-fluid scene ([scene] model = two_fluid)");
  double rho_f, mu_f, rho_s, d_p, sphericity, phi_max, g, U;
  if ((rc = bed_physics(ini, &rho_f, &mu_f, &rho_s, &d_p, &sphericity, &phi_max, &g, d))) return rc;
  if (!(g < 0.0)) return refuse(d, name, "needs gravity along -x ([flow] gravity < 0): the inlet at the bottom, x0");
  if (!(rho_s > rho_f)) return refuse(d, name, "needs particles denser than the fluid");
  if ((rc = bed_inlet(ini, &U, d))) return rc;
  if (!sl_ini_find_section(ini, "closure.drag")) return refuse(d, name, "needs a [closure.drag]");
  drag_binding b;
  memset(&b, 0, sizeof b);
  b.failed_phi = b.failed_slip = NAN;
  if ((rc = sl_closure_from_ini(reg, ini, "closure.drag", &b.c, d))) return rc;
  const sl_closure_desc *desc = b.c->desc;
  b.in_phi = sl_closure_input(desc, "phi"), b.in_slip = sl_closure_input(desc, "slip");
  b.out_K = sl_closure_output(desc, "K");
  if (b.in_phi < 0 || b.in_slip < 0 || b.out_K < 0 || desc->n_in > DRAG_MAX_FIELDS || desc->n_out > DRAG_MAX_FIELDS)
    rc = refuse(d, name, "the drag closure does not map phi and slip to K");
  for (int i = 0; i < desc->n_in && !rc; ++i) {
    const char *in = desc->in[i].name;
    if (i == b.in_phi || i == b.in_slip) continue;
    if (!strcmp(in, "rho_f")) b.fixed[i] = rho_f;
    else if (!strcmp(in, "mu_f")) b.fixed[i] = mu_f;
    else if (!strcmp(in, "rho_s")) b.fixed[i] = rho_s;
    else if (!strcmp(in, "d_p")) b.fixed[i] = d_p;
    else if (!strcmp(in, "sphericity")) b.fixed[i] = sphericity;
    else if (!strcmp(in, "gravity")) b.fixed[i] = fabs(g);
    else {
      char why[200];
      snprintf(why, sizeof why, "the drag closure needs the input '%s'", in);
      rc = refuse(d, name, why);
    }
  }
  fb_bed bed = {.rho_f = rho_f, .rho_s = rho_s, .g = fabs(g), .U = U, .phi_max = phi_max};
  double porosity = NAN;
  fb_status st = rc ? FB_OK : fb_equilibrium_porosity(&bed, drag_at, &b, &porosity);
  char label[128], why[800];
  sl_closure_label(desc, label, sizeof label);
  sl_closure_destroy(b.c);
  if (rc) return rc;
  if (st == FB_DRAG_FAILED) {
    snprintf(why, sizeof why, "the drag closure %s refused phi = %g, slip = %g m/s: %s", label, b.failed_phi,
             b.failed_slip, b.failure);
    return refuse(d, name, why);
  }
  if (st == FB_PACKED || st == FB_BLOWN_OUT) {
    snprintf(why, sizeof why, "no fluidised bed: U = %g m/s is %s with the drag closure %s", U,
             st == FB_PACKED ? "below the minimum fluidisation velocity (the bed stays packed at phi_max)"
                             : "above the terminal velocity (the bed is blown out)",
             label);
    return refuse(d, name, why);
  }
  e->bed_phi = 1.0 - porosity;
  snprintf(e->description, sizeof e->description,
           "equilibrium porosity of the fluidised bed: %.10f (phi = %.10f) at U = %g m/s with the drag closure %s; "
           "compared in the cells below the top of the bed at rest",
           porosity, e->bed_phi, U, label);
  return 0;
}

/* ---- interface ---------------------------------------------------------------- */

int sl_bench_exact_create(const char *name, const sl_ini *ini, const sl_registry *reg, sl_bench_exact **out,
                          sl_diag *d) {
  *out = NULL;
  sl_bench_exact *e = calloc(1, sizeof *e);
  if (!e) return sl_diag_set(d, SL_ENOMEM, "exact: out of memory");
  int rc;
  if (!strcmp(name, "kynch")) e->kind = EXACT_KYNCH, rc = kynch_create(e, ini, reg, d);
  else if (!strcmp(name, "bingham")) e->kind = EXACT_BINGHAM, rc = bingham_create(e, ini, reg, d);
  else if (!strcmp(name, "fluidized_bed")) e->kind = EXACT_FLUIDIZED_BED, rc = fluidized_bed_create(e, ini, reg, d);
  else rc = sl_diag_set(d, SL_EBADINPUT, "no exact solution '%s' (known: kynch, bingham, fluidized_bed)", name);
  if (rc) {
    free(e);
    return rc;
  }
  *out = e;
  return 0;
}

void sl_bench_exact_free(sl_bench_exact *e) { free(e); }

const char *sl_bench_exact_describe(const sl_bench_exact *e) { return e->description; }

int sl_bench_exact_cell_averages(const sl_bench_exact *e) {
  return e->kind == EXACT_KYNCH || e->kind == EXACT_FLUIDIZED_BED;
}

void sl_bench_exact_domain(const sl_bench_exact *e, double *x0, double *x1) { *x0 = e->x0, *x1 = e->x1; }

void sl_bench_exact_compared_span(const sl_bench_exact *e, int n, const double *xa, const double *xb, const double *v,
                                  double *lo, double *hi) {
  *lo = e->x0, *hi = e->x1;
  if (e->kind != EXACT_FLUIDIZED_BED) return;
  /* the bed at rest holds the run's solids at bed_phi: its top is the inventory over bed_phi above x0 */
  double inventory = 0.0;
  for (int c = 0; c < n; ++c) inventory += v[c] * (xb[c] - xa[c]);
  *hi = e->x0 + fmin(inventory / e->bed_phi, e->x1 - e->x0);
}

void sl_bench_exact_values(const sl_bench_exact *e, double t, int n, const double *x, double *v) {
  if (e->kind == EXACT_FLUIDIZED_BED) { /* steady and uniform */
    for (int i = 0; i < n; ++i) v[i] = e->bed_phi;
    return;
  }
  if (e->kind == EXACT_BINGHAM) {
    for (int i = 0; i < n; ++i) v[i] = bingham_channel_velocity(&e->b, x[i]);
    return;
  }
  kx_profile p = kx_at(&e->k, t);
  for (int i = 0; i < n; ++i) v[i] = kx_value(&e->k, &p, x[i] - e->x0);
}

void sl_bench_exact_averages(const sl_bench_exact *e, double t, int n, const double *xa, const double *xb, double *v) {
  if (e->kind == EXACT_FLUIDIZED_BED) {
    for (int i = 0; i < n; ++i) v[i] = e->bed_phi;
    return;
  }
  if (e->kind == EXACT_BINGHAM) { /* compared at points, not this way; Simpson's rule for completeness */
    for (int i = 0; i < n; ++i) {
      double m = 0.5 * (xa[i] + xb[i]), x[3] = {xa[i], m, xb[i]}, w[3];
      sl_bench_exact_values(e, t, 3, x, w);
      v[i] = (w[0] + 4.0 * w[1] + w[2]) / 6.0;
    }
    return;
  }
  kx_profile p = kx_at(&e->k, t);
  for (int i = 0; i < n; ++i) v[i] = kx_integral(&e->k, &p, xa[i] - e->x0, xb[i] - e->x0) / (xb[i] - xa[i]);
}
