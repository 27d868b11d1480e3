/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The transport driven through real hindered_settling plug-ins (loaded by
 * the registry, created through core/plugin/instance.h): the batch callback
 * of core/transport/flux.h bound to a closure.
 *  - richardson_zaki with packing_cutoff: its flux table equals the
 *    analytic law to round-off, a run through it equals a run on the
 *    analytic law, and in SI units (Stokes u_t of a 0.1 mm sand grain, a
 *    0.5 m column) the fronts move at the exact Kynch speeds within 1 %.
 *  - nigam: the exact Kynch construction for Nigam's (1999) flux, eq 2.36
 *    (top 0.61808, phi* 0.5299, shock 0.12289, meeting at t = 1.3496, z = 0.1659)
 *    and the scheme's fronts match within 1 %.
 *  - refusals: richardson_zaki without the cut-off (settling does not stop
 *    at phi_max) and a closure refusing part of [0, phi_max] stop the set-up
 *    with the closure's own message. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "closure_test.h"
#include "kynch_run.h"
#include "testing.h"

/* ---- the binding ----------------------------------------------------------- */

/* Inputs other than phi take fixed values (the closure's typical ones unless
 * set); the derivative by phi is asked for. */
typedef struct binding {
  sl_closure *c;
  int in_phi, out_u;
  double fixed[32];
} binding;

static void binding_init(binding *b, sl_closure *c) {
  memset(b, 0, sizeof *b);
  b->c = c;
  b->in_phi = sl_closure_input(c->desc, "phi");
  b->out_u = sl_closure_output(c->desc, "settling_velocity");
  for (int i = 0; i < c->desc->n_in && i < 32; ++i) b->fixed[i] = c->desc->in[i].typical;
}

static void binding_set(binding *b, const char *input, double v) {
  int i = sl_closure_input(b->c->desc, input);
  if (i < 0) {
    fprintf(stderr, "no input %s\n", input);
    exit(1);
  }
  b->fixed[i] = v;
}

static double *aligned(size_t n) {
  size_t bytes = (n * sizeof(double) + 63) / 64 * 64;
  return aligned_alloc(64, bytes ? bytes : 64);
}

static int closure_settling(void *user, int n, const double *phi, double *u, double *du, sl_diag *d) {
  const binding *b = user;
  const sl_closure_desc *c = b->c->desc;
  int n_in = c->n_in, n_out = c->n_out, rc = 0;
  if (n_in > 32 || n_out > 8) return sl_diag_set(d, SL_EFAILED, "closure %s: too many fields", c->name);
  double *in[32] = {0}, *out[8] = {0}, *dout[8 * 32] = {0};
  /* Every differentiable input of the settling output gets a slot (ABI rule). */
  for (int i = 0; i < n_in; ++i) {
    in[i] = aligned((size_t)n);
    if (c->in[i].flags & SL_FIELD_DIFF) dout[b->out_u * n_in + i] = aligned((size_t)n);
  }
  out[b->out_u] = aligned((size_t)n);
  for (int i = 0; i < n_in; ++i)
    if (!in[i] || ((c->in[i].flags & SL_FIELD_DIFF) && !dout[b->out_u * n_in + i])) rc = 1;
  if (rc || !out[b->out_u]) {
    rc = sl_diag_set(d, SL_EFAILED, "out of memory");
    goto done;
  }
  for (int i = 0; i < n_in; ++i)
    for (int q = 0; q < n; ++q) in[i][q] = i == b->in_phi ? phi[q] : b->fixed[i];
  sl_error err;
  sl_eval_args a = {.Q = n, .in = (const double *const *)in, .out = out, .dout = dout, .err = &err};
  int erc = sl_closure_evaluate(b->c, &a);
  if (erc) {
    rc = sl_diag_set(d, SL_EBADINPUT, "hindered_settling/%s %s at phi = %g: %s", c->name,
                     erc > 0 ? "is outside its validity" : "failed", err.point >= 0 ? phi[err.point] : NAN, err.msg);
    goto done;
  }
  for (int q = 0; q < n; ++q) u[q] = out[b->out_u][q], du[q] = dout[b->out_u * n_in + b->in_phi][q];
done:
  for (int i = 0; i < n_in; ++i) free(in[i]), free(dout[b->out_u * n_in + i]);
  free(out[b->out_u]);
  return rc;
}

/* ---- helpers --------------------------------------------------------------- */

/* Fronts by level crossings at 12 times in [0.2, 0.9] t1, lines fitted: the
 * relative speed errors of the top interface and the bottom shock. */
static void fit_fronts(kr_run *r, const kynch *k, double *e_top, double *e_bot) {
  enum { NT = 12 };
  double st = 0, sz = 0, stt = 0, szt = 0, sb = 0, sbt = 0;
  for (int i = 0; i < NT; ++i) {
    double t = k->t1 * (0.2 + 0.7 * i / (NT - 1));
    kr_advance(r, t);
    int mid = kr_cell(r, 0.5 * (k->sigma * t + k->H - k->v0 * t));
    double zt = kr_crossing(r, mid, +1, 0.5 * k->phi0), zb = kr_crossing(r, mid, -1, 0.5 * (k->phi0 + k->phis));
    st += t, stt += t * t, sz += zt, szt += zt * t, sb += zb, sbt += zb * t;
  }
  double den = NT * stt - st * st;
  *e_top = -(NT * szt - st * sz) / den / k->v0 - 1;
  *e_bot = (NT * sbt - st * sb) / den / k->sigma - 1;
}

static sl_transport *open_or_die(const sl_mesh *m, double phi_max, sl_settling_fn fn, void *user, int n_table) {
  sl_diag d;
  sl_transport *t;
  sl_transport_opts o = {
      .phi_max = phi_max, .order = 2, .table_points = n_table, .settling = fn, .settling_user = user};
  if (sl_transport_create(m, &o, &t, &d)) {
    fprintf(stderr, "transport: %s\n", d.msg);
    exit(1);
  }
  return t;
}

/* ---- Richardson-Zaki ------------------------------------------------------- */

static void test_richardson_zaki(void) {
  sl_tc *tc = sl_tc_open("hindered_settling", "richardson_zaki", "exponent=given", "n=4.65", "packing_cutoff=true",
                         "phi_max=0.64", "terminal_velocity=given", "u_t=1", NULL);
  binding b;
  binding_init(&b, tc->c);
  kx_law law = kx_richardson_zaki(1.0, 4.65, 0.64);
  /* The table through the plug-in against the analytic law. */
  sl_diag d;
  sl_mesh *m;
  CHECK(sl_mesh_interval(0, 1, 200, NULL, &m, &d) == 0);
  sl_transport *tp = open_or_die(m, 0.64, closure_settling, &b, 0), *ta = open_or_die(m, 0.64, kx_settling, &law, 0);
  const sl_settling_table *xp = sl_transport_table(tp), *xa = sl_transport_table(ta);
  double worst = 0;
  for (int k = 0; k < xp->n; ++k) worst = fmax(worst, fmax(fabs(xp->F[k] - xa->F[k]), fabs(xp->D[k] - xa->D[k])));
  printf("richardson_zaki plug-in: flux table (%d nodes, one batch call) differs from the analytic law by %.1e\n",
         xp->n, worst);
  CHECK(worst < 1e-14);
  CHECK(tc->c->n_calls == 1 && tc->c->n_points == (unsigned long long)xp->n);
  sl_transport_destroy(tp);
  sl_transport_destroy(ta);
  sl_mesh_destroy(m);
  /* A run through the plug-in equals a run on the analytic law. */
  kynch k;
  CHECK(kx_init(&k, law, 1.0, 0.1) == 0);
  kr_run rp, ra;
  kr_open(&rp, 200, 1.0, 0.1, 2, SL_LIMITER_MC, closure_settling, &b, 0.64);
  kr_open(&ra, 200, 1.0, 0.1, 2, SL_LIMITER_MC, kx_settling, &law, 0.64);
  kr_advance(&rp, 1.3 * k.t1);
  kr_advance(&ra, 1.3 * k.t1);
  double diff = 0;
  for (int i = 0; i < 200; ++i) diff = fmax(diff, fabs(rp.phi[i] - ra.phi[i]));
  double l1 = kr_l1(&rp, &k);
  printf(
      "richardson_zaki plug-in, Kynch case A, 200 cells, t = 1.3 t1: max |phi_plugin - phi_analytic| = %.1e, "
      "L1 error %.3e\n",
      diff, l1);
  CHECK(diff < 1e-12 && l1 < 2e-3);
  kr_close(&rp);
  kr_close(&ra);
  sl_tc_close(tc);

  /* SI units: Stokes u_t of a 0.1 mm grain (2600 in water, 1e-3 Pa s),
   * n = 4.65, a 0.5 m column, phi0 = 0.1. */
  tc = sl_tc_open("hindered_settling", "richardson_zaki", "exponent=given", "n=4.65", "packing_cutoff=true",
                  "phi_max=0.64", "terminal_velocity=stokes", NULL);
  binding_init(&b, tc->c);
  binding_set(&b, "d_p", 1e-4), binding_set(&b, "rho_s", 2600), binding_set(&b, "rho_f", 1000);
  binding_set(&b, "mu_f", 1e-3), binding_set(&b, "gravity", 9.81);
  double ut = 1600 * 9.81 * 1e-8 / 18e-3;
  kx_law si = kx_richardson_zaki(ut, 4.65, 0.64);
  CHECK(kx_init(&k, si, 0.5, 0.1) == 0);
  for (int order = 1; order <= 2; ++order) {
    kr_open(&rp, 200, 0.5, 0.1, order, SL_LIMITER_MC, closure_settling, &b, 0.64);
    rp.dt_outer = 1.0; /* s: the engine's step; sub-cycled inside */
    double et, eb;
    fit_fronts(&rp, &k, &et, &eb);
    double mass = sl_transport_mass(rp.t, rp.phi);
    printf(
        "richardson_zaki plug-in, SI (u_t = %.4e m/s, 0.5 m, 200 cells), order %d: top %.4e m/s (%+.3f %%), "
        "bottom shock %.4e m/s (%+.3f %%), fronts meet at %.2f s, %.1f sub-steps per 1 s step, mass error %.1e\n",
        ut, order, k.v0, 100 * et, k.sigma, 100 * eb, k.t1, (double)rp.substeps / rp.outer_steps,
        (mass - rp.mass0) / rp.mass0);
    CHECK(fabs(et) < 0.01 && fabs(eb) < (order == 1 ? 0.04 : 0.01)); /* first order: the contact, see transport_kynch */
    CHECK(fabs(mass - rp.mass0) < 1e-13 * rp.mass0 && rp.max_phi <= 0.64 && rp.min_phi >= 0);
    kr_close(&rp);
  }
  sl_tc_close(tc);
}

/* ---- Nigam ------------------------------------------------------------------ */

static void test_nigam(void) {
  sl_tc *tc = sl_tc_open("hindered_settling", "nigam", "terminal_velocity=given", "u_t=1", NULL);
  binding b;
  binding_init(&b, tc->c);
  kynch k;
  CHECK(kx_init(&k, kx_nigam(1.0, 2.5, 0.68), 1.0, 0.1) == 0);
  /* Kynch's construction for Nigam's (1999) flux, reference values (printed digits). */
  CHECK(fabs(k.v0 - 0.61808) < 5e-6 && fabs(k.phis - 0.5299) < 5e-5 && fabs(k.sigma - 0.12289) < 5e-6);
  CHECK(fabs(k.t1 - 1.3496) < 5e-5 && fabs(k.z1 - 0.1659) < 5e-5 && k.bottom == KX_CONTACT && k.sed == 0);
  CHECK(fabs(kx_F(&k.law, 0.1) / (0.68 - 0.1) - 0.10657) < 5e-6);
  CHECK(fabs(k.infl - 0.3485) < 1e-4); /* 0.34859: the reference truncates */
  printf(
      "nigam exact: top %.5f, phi* %.4f, bottom shock %.5f, fronts meet at t = %.4f z = %.4f, inflection %.4f "
      "(reference: 0.61808, 0.5299, 0.12289, 1.3496, 0.1659, 0.3485)\n",
      k.v0, k.phis, k.sigma, k.t1, k.z1, k.infl);
  for (int order = 1; order <= 2; ++order) {
    kr_run r;
    kr_open(&r, 200, 1.0, 0.1, order, SL_LIMITER_MC, closure_settling, &b, 0.68);
    double et, eb;
    fit_fronts(&r, &k, &et, &eb);
    kr_advance(&r, 2.0 * k.t1);
    double l1 = kr_l1(&r, &k), mass = sl_transport_mass(r.t, r.phi);
    printf(
        "nigam plug-in, 200 cells, order %d: top %+.3f %%, bottom shock %+.3f %%; at t = 2 t1 L1 %.3e, bottom "
        "cell %.5f (alpha_m = 0.68), mass error %.1e\n",
        order, 100 * et, 100 * eb, l1, r.phi[0], (mass - r.mass0) / r.mass0);
    CHECK(fabs(et) < 0.01 && fabs(eb) < (order == 1 ? 0.04 : 0.01));
    CHECK(l1 < (order == 1 ? 6e-3 : 3e-3));
    CHECK(fabs(mass - r.mass0) < 1e-13 * r.mass0 && r.max_phi <= 0.68 && r.min_phi >= 0);
    kr_close(&r);
  }
  sl_tc_close(tc);
}

/* ---- refusals ----------------------------------------------------------------- */

static void test_refusals(void) {
  sl_diag d;
  sl_mesh *m;
  CHECK(sl_mesh_interval(0, 1, 10, NULL, &m, &d) == 0);
  sl_transport *t = NULL;
  /* Settling that does not stop at phi_max. */
  sl_tc *tc = sl_tc_open("hindered_settling", "richardson_zaki", "terminal_velocity=given", "u_t=1", NULL);
  binding b;
  binding_init(&b, tc->c);
  sl_transport_opts o = {.phi_max = 0.64, .settling = closure_settling, .settling_user = &b};
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT && t == NULL);
  CHECK_CONTAINS(d.msg, "not zero");
  CHECK_CONTAINS(d.msg, "packing_cutoff");
  sl_tc_close(tc);
  /* The closure refuses phi above its own phi_max (0.6 < 0.64). */
  tc = sl_tc_open("hindered_settling", "richardson_zaki", "packing_cutoff=true", "phi_max=0.6",
                  "terminal_velocity=given", "u_t=1", NULL);
  binding_init(&b, tc->c);
  CHECK(sl_transport_create(m, &o, &t, &d) == SL_EBADINPUT && t == NULL);
  CHECK_CONTAINS(d.msg, "hindered_settling/richardson_zaki is outside its validity at phi = ");
  CHECK_CONTAINS(d.msg, "above phi_max");
  printf("refused: %s\n", d.msg);
  sl_tc_close(tc);
  sl_mesh_destroy(m);
}

int main(void) {
  test_richardson_zaki();
  test_nigam();
  test_refusals();
  return sl_test_summary();
}
