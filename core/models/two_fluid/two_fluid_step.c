/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One implicit step of the 1-D two-fluid model (two_fluid.h): the solids
 * momentum at the faces with implicit drag and solids pressure, iterated
 * with the bounded transport of phi until both agree.
 *
 * Face k lies between cells k-1 and k. Its momentum equation (two_fluid.h)
 * is written for phi_f = the cell on its gravity side ("below"), or the
 * inside cell at the ends, so that a fluidised bed under clear fluid is a
 * steady state cell by cell (a mean of the two cells would let a partly
 * filled top cell drain into the bed for ever). The equation is multiplied
 * by the dual length L_k (centre to centre), which makes the implicit
 * solids-pressure operator column diagonally dominant on any mesh, so the
 * tridiagonal system is solved without pivoting (Golub & Van Loan 2013,
 * Matrix Computations, 4th ed., Theorem 3.4.3).
 *
 * Iteration k (u^0 = u^n, phi^0 = T(phi^n, u^n)), delta = u - u^k:
 *   drag:   D(u) = K s / eps, s = (j - u)/eps, linearised by Newton,
 *           dD/du = -(K + dK/dslip |s|) / eps^2;
 *   p_s:    P_c = p_s(phi^k_c) + p_s'(phi^k_c) dphi_c(delta),
 *           dphi_c = -(dt/h_c)(w_{c+1} delta_{c+1} - w_c delta_c), w the
 *           upwind phi^k: the Taylor expansion of Pringle (2001) eq 4.31
 *           about the latest iterate, i.e. Newton on the transported phi;
 *   then phi^(k+1) = T(phi^n, u^(k+1)), until max |delta| <= tol v_ref.
 * T is first-order upwind, sub-stepped within CFL and limited so that no
 * cell exceeds phi_max: unconditionally bounded and conservative. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/models/two_fluid/two_fluid_impl.h"

/* Faces with (nearly) no solids still get an equation: that of one particle
 * in clear fluid (every term is proportional to phi). */
static const double PHI_FLOOR = 1e-6;

/* A drag law with a jump in phi (drag/pringle's hard switch at porosity 0.6,
 * Pringle 2001 section 3.1) can leave the step's fixed point without a
 * solution: a face whose phi crosses the switch gets the other K, which
 * sends phi back; long steps converge slowly for the same reason. After
 * this many iterations the drag takes phi from the start of the step
 * (semi-implicit in phi, as Pringle lagged his drag; the slip stays
 * implicit and p_s coupled), which has a solution. */
enum { TF_FREEZE_PHI_AFTER = 8 };

int tf_equilibrium_velocity(tf_column *c, double porosity, double *U, sl_diag *d) {
  /* The steady homogeneous state of the solids equation (two_fluid.h) with u_s = 0 and
   * dp_s/dx = 0: K s / eps = phi (rho_s - rho_f) |g| (Pringle 2001, eq 4.20 at steady state: beta V_r = n (1 - n)
   * (rho_s - rho_f) g). K s grows with s for every drag law, so bisection on s between 0 (where
   * K s - weight < 0) and a bound doubled until it is positive finds the one root. */
  const double phi = fmax(1.0 - porosity, PHI_FLOOR), eps = 1.0 - phi;
  const double weight = phi * eps * (c->rho_s - c->rho_f) * fabs(c->g);
  double lo = 0.0, hi = c->v_ref, K, dK, s;
  int rc;
  for (int grow = 0;; ++grow) {
    s = hi;
    if ((rc = tf_closure_eval(&c->drag, 1, &phi, &s, &K, &dK, d))) return rc;
    if (K * hi > weight) break;
    if (grow == 60)
      return sl_diag_set(d, SL_EFAILED, "no superficial velocity below %.3g m/s holds a bed at porosity %g", eps * hi,
                         porosity);
    lo = hi, hi *= 2.0;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    s = 0.5 * (lo + hi);
    if ((rc = tf_closure_eval(&c->drag, 1, &phi, &s, &K, &dK, d))) return rc;
    if (K * s > weight) hi = s;
    else lo = s;
  }
  *U = eps * 0.5 * (lo + hi);
  return 0;
}

int tf_mixture_flux(tf_column *c, double t, double *j, sl_diag *d) {
  *j = 0.0;
  if (!c->inlet && !c->inlet_porosity) return 0;
  const double vars[2] = {t, c->case_index};
  double v;
  if (c->inlet) {
    v = sl_expr_eval(c->inlet, vars);
    if (!isfinite(v))
      return sl_diag_set(d, SL_EFAILED, "the inlet velocity is not a finite number (%g) at t = %g", v, t);
  } else {
    double n = sl_expr_eval(c->inlet_porosity, vars);
    if (!(n > 1.0 - c->phi_max && n <= 1.0))
      return sl_diag_set(d, SL_EFAILED, "the inlet porosity is %g at t = %g: allowed 1 - phi_max < porosity <= 1, "
                                        "phi_max = %g", n, t, c->phi_max);
    int k = c->eq_porosity[0] == n ? 0 : c->eq_porosity[1] == n ? 1 : -1;
    if (k < 0) {
      int rc = tf_equilibrium_velocity(c, n, &v, d);
      if (rc) return sl_diag_prefix(d, rc, "the inlet at porosity %g (t = %g)", n, t);
      k = c->eq_next, c->eq_next = 1 - c->eq_next;
      c->eq_porosity[k] = n, c->eq_velocity[k] = v;
    }
    v = c->eq_velocity[k];
  }
  *j = c->inlet_side == 0 ? v : -v;
  return 0;
}

int tf_closure_eval(tf_closure *b, int n, const double *phi, const double *slip, double *value, double *dvalue,
                    sl_diag *d) {
  const double *values[9] = {phi, slip, NULL, NULL, NULL, NULL, NULL, NULL, b->nbar};
  sl_point_request rq = {b->out, value, dvalue, b->wrt};
  return sl_point_eval(&b->pc, n, values, &rq, 1, d);
}

/* The limited slope of cell i (per metre) for a second-order face value:
 * minmod (Roe 1986) or monotonised central (van Leer 1977) of the one-sided
 * differences to the neighbours (Sweby 1984; LeVeque 2002, Finite Volume
 * Methods, section 6.12); 0 in the end cells, which keeps nothing from
 * entering through a wall. */
static double limited_slope(const tf_column *c, const double *phi, int i) {
  if (i == 0 || i == c->n - 1) return 0.0;
  double a = (phi[i] - phi[i - 1]) / c->dual[i], b = (phi[i + 1] - phi[i]) / c->dual[i + 1];
  if (a * b <= 0.0) return 0.0;
  double m = fabs(a) < fabs(b) ? a : b;
  if (c->limiter == TF_LIMITER_MC) {
    double centred = 0.5 * (a + b);
    m = fabs(centred) < 2.0 * fabs(m) ? centred : 2.0 * m;
  }
  return m;
}

/* One forward-Euler stage of the bounded transport from phi over ds into
 * next (next may be phi); the volume per unit area that left through the
 * ends is added to *out. Face values are upwind (order 1) or the upwind
 * cell's limited reconstruction (order 2: MUSCL, van Leer 1979), plus the
 * diffusive flux -D dphi/dx; then the packing limiter. */
static void transport_stage(tf_column *c, const double *phi, const double *u, double ds, double *next, double *out) {
  const int n = c->n;
  double *F = c->flux, *alpha = c->alpha, *slope = c->slope;
  if (c->order == 2)
    for (int i = 0; i < n; ++i) slope[i] = limited_slope(c, phi, i);
  /* solids entering through an end are none (clear fluid) */
  for (int k = 0; k <= n; ++k) {
    if (u[k] > 0.0) F[k] = k > 0 ? u[k] * (phi[k - 1] + (c->order == 2 ? 0.5 * c->h[k - 1] * slope[k - 1] : 0.0)) : 0.0;
    else F[k] = k < n ? u[k] * (phi[k] - (c->order == 2 ? 0.5 * c->h[k] * slope[k] : 0.0)) : 0.0;
  }
  if (c->diffusivity > 0.0)
    for (int k = 1; k < n; ++k) F[k] -= c->diffusivity * (phi[k] - phi[k - 1]) / c->dual[k];
  /* packing limiter: what enters a cell is scaled so that it cannot pass phi_max (what leaves is bounded by
     the CFL condition, so phi stays >= 0) */
  for (int i = 0; i < n; ++i) {
    double in = fmax(F[i], 0.0) + fmax(-F[i + 1], 0.0);
    alpha[i] = in > 0.0 ? fmin(1.0, fmax(0.0, (c->phi_max - phi[i]) * c->h[i] / (ds * in))) : 1.0;
  }
  for (int k = 0; k <= n; ++k) {
    int to = F[k] > 0.0 ? k : k - 1;
    if (to >= 0 && to < n) F[k] *= alpha[to];
  }
  *out += ds * (fmax(F[n], 0.0) - fmin(F[0], 0.0));
  for (int i = 0; i < n; ++i) {
    double v = phi[i] - ds / c->h[i] * (F[i + 1] - F[i]);
    next[i] = v < 0.0 ? 0.0 : v > c->phi_max ? c->phi_max : v; /* round-off only */
  }
}

static int transport_run(tf_column *c, const double *phi0, const double *u, double dt, double *phi, long *substeps,
                         double *outflow, sl_diag *d) {
  const int n = c->n;
  double rmax = 0.0;
  for (int i = 0; i < n; ++i) {
    double out = (fmax(u[i + 1], 0.0) + fmax(-u[i], 0.0)) / c->h[i];
    if (c->diffusivity > 0.0) /* the diffusive outflow through interior faces */
      out += c->diffusivity * ((i > 0 ? 1.0 / c->dual[i] : 0.0) + (i < n - 1 ? 1.0 / c->dual[i + 1] : 0.0)) / c->h[i];
    rmax = fmax(rmax, out);
  }
  /* a limited second-order stage is positive at half the first-order step (a face value may be up to twice
     the cell's mean) */
  double cfl = c->order == 2 ? 0.5 * c->cfl : c->cfl;
  double ns = ceil(dt * rmax / cfl);
  if (!(ns <= 1e7))
    return sl_diag_set(d, SL_EFAILED, "solids transport would need %.3g sub-steps (solids speed %.3g m/s)", ns,
                       rmax * c->h[0]);
  /* An iterate far from the last accepted step's speeds (a Newton iterate
   * overshooting at a long step) would spend its sub-steps on a state that
   * is thrown away: refuse it, and the step is retried smaller. */
  double cap = fmax(1e3, 50.0 * (double)c->accepted_substeps);
  if (c->accepted_substeps > 0 && ns > cap)
    return sl_diag_set(d, SL_EFAILED, "solids transport of this iterate would need %.3g sub-steps, more than 50 "
                                      "times the last step's %ld (solids speed %.3g m/s)", ns, c->accepted_substeps,
                       rmax * c->h[0]);
  long m = ns < 1.0 ? 1 : (long)ns;
  c->last_substeps = m;
  double ds = dt / (double)m, out = 0.0;
  memcpy(phi, phi0, (size_t)n * sizeof *phi);
  for (long s = 0; s < m; ++s) {
    if (c->order == 1) {
      transport_stage(c, phi, u, ds, phi, &out);
      continue;
    }
    /* Heun's method, the two-stage strong-stability-preserving Runge-Kutta scheme (Shu & Osher 1988, eq
       2.15): the mean of the start and two Euler stages, so bounds and conservation carry over */
    double *st = c->stage, o1 = 0.0, o2 = 0.0;
    transport_stage(c, phi, u, ds, st, &o1);
    transport_stage(c, st, u, ds, st, &o2);
    for (int i = 0; i < n; ++i) phi[i] = 0.5 * (phi[i] + st[i]);
    out += 0.5 * (o1 + o2);
  }
  *substeps += m;
  *outflow = out;
  return 0;
}

int tf_transport(tf_column *c, const double *phi0, const double *u, double dt, double *phi, long *substeps,
                 double *outflow, sl_diag *d) {
  double t0 = (double)clock() / CLOCKS_PER_SEC;
  int rc = transport_run(c, phi0, u, dt, phi, substeps, outflow, d);
  c->transport_cpu += (double)clock() / CLOCKS_PER_SEC - t0;
  return rc;
}

/* The face's solids fraction: its gravity-side cell, the inside one at the ends. */
static double face_phi(const tf_column *c, const double *phi, int k) {
  int cell = k == 0 ? 0 : k == c->n ? c->n - 1 : (c->below ? k - 1 : k);
  return fmax(phi[cell], PHI_FLOOR);
}

/* K and dK/dslip at every face for the velocities u and the cells' phi. */
static int face_drag(tf_column *c, const double *phi, const double *u, double j, sl_diag *d) {
  for (int k = 0; k <= c->n; ++k) {
    c->phif[k] = face_phi(c, phi, k);
    c->slip[k] = fabs(j - u[k]) / (1.0 - c->phif[k]);
  }
  int rc = tf_closure_eval(&c->drag, c->n + 1, c->phif, c->slip, c->K, c->dK, d);
  return rc ? sl_diag_prefix(d, rc, "drag") : 0;
}

int tf_step(tf_column *c, double t, double dt, sl_diag *d) {
  const int n = c->n;
  double j0, j1;
  int rc = tf_mixture_flux(c, t, &j0, d);
  if (!rc) rc = tf_mixture_flux(c, t + dt, &j1, d);
  c->fatal = rc != 0;
  if (rc) return rc;
  const double djdt = (j1 - j0) / dt;
  const double drho = c->rho_s - c->rho_f;
  const int k_lo = c->bc[0] == TF_OUTLET ? 0 : 1, k_hi = c->bc[1] == TF_OUTLET ? n : n - 1;
  double *u = c->u_new;
  memcpy(u, c->u, (size_t)(n + 1) * sizeof *u);
  c->substeps_trial = 0, c->iterations_trial = 0;
  rc = tf_transport(c, c->phi, u, dt, c->phi_new, &c->substeps_trial, &c->outflow_trial, d);
  if (rc) return rc;
  int converged = 0;
  double last = 0.0;
  for (int it = 1; it <= c->max_iterations && !converged; ++it) {
    c->iterations_trial = it;
    /* after TF_FREEZE_PHI_AFTER iterations the drag takes phi from the step's start */
    if ((rc = face_drag(c, it > TF_FREEZE_PHI_AFTER ? c->phi : c->phi_new, u, j1, d))) return rc;
    if (c->ps.c) {
      if ((rc = tf_closure_eval(&c->ps, n, c->phi_new, NULL, c->ps_v, c->ps_d, d)))
        return sl_diag_prefix(d, rc, "solids pressure");
    } else {
      memset(c->ps_v, 0, (size_t)n * sizeof *c->ps_v), memset(c->ps_d, 0, (size_t)n * sizeof *c->ps_d);
    }
    for (int i = 0; i < n; ++i) c->ps_d[i] = fmax(c->ps_d[i], 0.0); /* a softening law would make it unstable */
    for (int k = 0; k <= n; ++k) {
      double below = k > 0 ? c->phi_new[k - 1] : 0.0, above = k < n ? c->phi_new[k] : 0.0;
      c->w[k] = u[k] > 0.0 ? below : u[k] < 0.0 ? above : fmax(below, above);
    }
    /* the linearised face equations, times L_k */
    for (int k = k_lo; k <= k_hi; ++k) {
      double ph = c->phif[k], eps = 1.0 - ph, L = c->dual[k];
      double m = ph * c->rho_s + ph * ph * c->rho_f / eps;
      double s = (j1 - u[k]) / eps;
      double D = c->K[k] * s / eps;
      double A = m / dt + (c->K[k] + c->dK[k] * fabs(s)) / (eps * eps);
      double Pp = k < n ? c->ps_v[k] : 0.0, Pm = k > 0 ? c->ps_v[k - 1] : 0.0;
      double R = -m * (u[k] - c->u[k]) / dt + D - (Pp - Pm) / L + ph * drho * c->g + ph * c->rho_f * djdt / eps;
      double diag = L * A, lo = 0.0, up = 0.0;
      if (k < n) {
        double cc = c->ps_d[k] * dt / c->h[k];
        diag += cc * c->w[k], up = -cc * c->w[k + 1];
      }
      if (k > 0) {
        double cc = c->ps_d[k - 1] * dt / c->h[k - 1];
        diag += cc * c->w[k], lo = -cc * c->w[k - 1];
      }
      c->lo[k] = k > k_lo ? lo : 0.0, c->up[k] = k < k_hi ? up : 0.0;
      c->di[k] = diag, c->rhs[k] = L * R;
    }
    /* Thomas: forward elimination, back substitution */
    for (int k = k_lo + 1; k <= k_hi; ++k) {
      double f = c->lo[k] / c->di[k - 1];
      c->di[k] -= f * c->up[k - 1], c->rhs[k] -= f * c->rhs[k - 1];
    }
    double dmax = 0.0, umax = 0.0;
    for (int k = k_hi; k >= k_lo; --k) {
      double delta = (c->rhs[k] - (k < k_hi ? c->up[k] * c->rhs[k + 1] : 0.0)) / c->di[k];
      c->rhs[k] = delta;
    }
    for (int k = k_lo; k <= k_hi; ++k) {
      u[k] += c->rhs[k];
      dmax = fmax(dmax, fabs(c->rhs[k])), umax = fmax(umax, fabs(u[k]));
    }
    if (!isfinite(dmax) || !isfinite(umax))
      return sl_diag_set(d, SL_EFAILED, "the solids momentum gave a non-finite velocity (iteration %d)", it);
    last = dmax;
    converged = dmax <= c->tolerance * fmax(c->v_ref, umax);
    if ((rc = tf_transport(c, c->phi, u, dt, c->phi_new, &c->substeps_trial, &c->outflow_trial, d))) return rc;
  }
  if (!converged)
    return sl_diag_set(d, SL_EFAILED,
                       "the implicit step did not converge in %d iterations (last velocity correction %.3g m/s, "
                       "tolerance %.3g)",
                       c->max_iterations, last, c->tolerance * c->v_ref);
  /* the fluid velocity and, from the fluid momentum, the pressure gradient at every face */
  if ((rc = face_drag(c, c->phi_new, u, j1, d))) return rc;
  for (int k = 0; k <= n; ++k) {
    double ph = c->phif[k], eps = 1.0 - ph;
    c->uf_new[k] = (j1 - ph * u[k]) / eps;
    double s = (j1 - u[k]) / eps;
    c->dpdx[k] = c->rho_f * c->g - c->K[k] * s / eps - c->rho_f * (c->uf_new[k] - c->uf[k]) / dt;
  }
  if (c->bc[0] == TF_OUTLET && c->bc[1] != TF_OUTLET) {
    c->p_new[0] = c->p_out + 0.5 * c->h[0] * c->dpdx[0];
    for (int i = 1; i < n; ++i) c->p_new[i] = c->p_new[i - 1] + c->dual[i] * c->dpdx[i];
  } else { /* from the top outlet, or p = 0 at the top of a closed column */
    c->p_new[n - 1] = (c->bc[1] == TF_OUTLET ? c->p_out : 0.0) - 0.5 * c->h[n - 1] * c->dpdx[n];
    for (int i = n - 2; i >= 0; --i) c->p_new[i] = c->p_new[i + 1] - c->dual[i + 1] * c->dpdx[i + 1];
  }
  for (int i = 0; i < n; ++i)
    if (!isfinite(c->p_new[i])) return sl_diag_set(d, SL_EFAILED, "the pressure is not finite in cell %d", i);
  return 0;
}
