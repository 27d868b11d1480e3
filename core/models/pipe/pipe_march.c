/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The developing pipe (`[pipe] length`, pipe.h): flow from uniform inlet profiles along a pipe of length L
 * (Krampa 2009 section 3.1: CFX-4's D = 0.04 m, L = 4 m, 50 axial x 40 radial cells, steady, axisymmetric),
 * on the 2-D axisymmetric staggered grid of the shared layer (core/fv/grid.h: the radial cells of the fully
 * developed pipe, graded towards the wall, times [pipe] axial_cells uniform along z).
 *
 * The solve is parabolic: a march along z, station by station (the cell centres of the grid's rows), each
 * station's radial problem solved to convergence by the fully developed pipe's iteration (pipe_converge: the
 * same k-epsilon, wall function and closures) with the axial convection of the last station added. This is the
 * boundary-layer (thin shear layer) approximation of the steady axisymmetric equations (Patankar & Spalding
 * 1972, Int. J. Heat Mass Transfer 15:1787; Pope 2000, Turbulent Flows, section 5.2): axial diffusion dropped
 * against radial (it is O((D/L_dev)^2) of it, L_dev some 40 D), the pressure uniform across each section (the
 * radial momentum equation reduced to dp/dr = 0), its axial gradient G(z) the unknown that keeps the flow rate
 * (the fully developed pipe's bordered system). Valid where the flow does not recirculate (u_f > 0 everywhere:
 * a uniform inlet in a straight pipe); its cost is the 1-D solve's times the stations, against CFX-4's
 * elliptic SIMPLEC iterations on the whole grid.
 *
 * Each phase's conservative axial momentum between station j-1 and j (h apart), per unit volume,
 *   [(c rho u u)_j - (c rho u u)_{j-1}]/h + (1/r) d/dr(r rho F_r u) = (fully developed pipe's terms),
 * the first linearised about the iterate (c rho u*)_j u_j (Picard), the radial convection upwind with the
 * phase's radial volume flux F_r from its continuity, [(c u)_j - (c u)_{j-1}]/h + (1/r) d/dr(r F_r) = 0,
 * integrated outwards from the axis (F_r = 0 there; it vanishes at the wall to round-off because the flow
 * rate is held). k and epsilon likewise, in the fluid's mass form (c_f rho_f u_f k convected), the radial
 * convection upwind on the shared cell-scalar solver (core/fv/cell_scalar.h) beside the fully developed
 * pipe's pseudo-time term, which vanishes at each station's convergence.
 *
 * Inlet (Krampa 2009 section 3.1, the CFX-4 command file): u = V, k = 1.5 (TI V)^2 with TI = [pipe]
 * inlet_intensity (0.1), epsilon = C_mu^(3/4) k^(3/2)/l with l = [pipe] inlet_length_scale (0.007 D: the
 * command file's; Table 5.1 prints 0.007 d_p, digest erratum 11).
 *
 * A slurry enters uniform, phi = [pipe] solids_fraction with u_s = u_f = V, and the radial solids balance of
 * the fully developed pipe gains the solids' axial convection and the radial convection by the mixture's
 * volume flux (pipe_march_solids): the inlet's solids flux is carried along, no inventory is imposed, and the
 * outlet's section-mean (in-situ) fraction is an output. A transported theta (`granular_temperature =
 * transport`) gains the solids' axial and radial convection of (3/2) rho_s phi theta; it enters at
 * theta = (2/3) k of the inlet (isotropic; Krampa's command file prints T_s = 1.5 k_s, digest erratum 12).
 * Model C's transported k_s and k_fs (`solids_turbulence = transported`, pipe_ksfs.c) gain the solids' axial and
 * radial convection of c_s rho_s k_s and c_s rho_s k_fs; they enter with the fluid's: k_s = k, k_fs = 2k.
 * Measured (tests/models/test_pipe_developing.c): the
 * outlet against the fully developed pipe within 1e-4 (water at Re 4e4-2e5) and 7e-4 (0.5 mm beads at 25 %
 * with the kinetic pressure, 75 D) and 1e-10 (P1 with no-slip solids and the kinetic viscosity).
 *
 * The drag of a station takes its solids fraction from the last station (pipe_march_drag): with the fraction
 * implicit, a drag law that jumps in phi (Gidaspow's switch) leaves a station with no solution where its wall
 * cell has to sit at the switch, and the iteration cycles there (P1 with no-slip solids, measured below).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/models/granular.h"
#include "core/models/pipe/pipe.h"
#include "core/models/pipe/pipe_impl.h"

void pipe_march_release(pipe *p) {
  pipe_march *m = &p->march;
  double **a[] = {&m->uf_up,  &m->us_up,  &m->phi_up, &m->k_up,   &m->eps_up, &m->theta_up, &m->ff,
                  &m->fs,     &m->rff,    &m->rfs,    &m->cap,    &m->s_old,  &m->G,        &m->tau_fw,
                  &m->tau_sw, &m->y_plus, &m->ks_up,  &m->kfs_up, &m->rs};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i) free(*a[i]), *a[i] = NULL;
  for (int k = 0; k < PIPE_NFIELDS; ++k) free(m->field[k]), m->field[k] = NULL;
  sl_fv_grid_free(&m->g);
  sl_tensor_grid_free(&m->tg);
  sl_mesh_destroy(m->mesh);
  m->mesh = NULL;
}

/* The grid's radial lines are the fully developed pipe's (the same grading), its rows [pipe] axial_cells. */
int pipe_march_setup(pipe *p, sl_diag *d) {
  pipe_march *m = &p->march;
  const pipe_config *c = p->cfg;
  const int n = p->n, nz = (int)c->axial_cells;
  m->on = 1, m->nz = nz;
  const sl_fv_grid *g1 = &p->g;
  /* the radial lines of the row's grid */
  double ratio = g1->hx[n - 1] / g1->hx[0];
  sl_grid_opts o = {.cell_type = SL_CELL_QUAD4, .grade_x = {SL_GRADE_GEOMETRIC, ratio}};
  if (fabs(ratio - 1.0) < 1e-12) o.grade_x.kind = SL_GRADE_UNIFORM;
  int rc = sl_mesh_rectangle(0.0, p->R, 0.0, c->length, n, nz, &o, &m->mesh, d);
  if (!rc) rc = sl_tensor_grid_from_mesh(m->mesh, &m->tg, d);
  const int periodic[2] = {0, 0};
  if (!rc) rc = sl_fv_grid_build(&m->g, &m->tg, 1, periodic, d);
  if (rc) return rc;
  for (int i = 0; i < n; ++i)
    if (fabs(m->g.xc[i] - g1->xc[i]) > 1e-12 * p->R)
      return sl_diag_set(d, SL_EFAILED, "pipe: the developing pipe's radial cells differ from the row's at %d", i);
  double **a[] = {&m->uf_up,    &m->us_up, &m->phi_up, &m->k_up, &m->eps_up,
                  &m->theta_up, &m->ks_up, &m->kfs_up, &m->cap,  &m->s_old};
  for (size_t i = 0; i < sizeof a / sizeof a[0]; ++i)
    if (!(*a[i] = calloc((size_t)n, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  double **b[] = {&m->ff, &m->fs, &m->rff, &m->rfs, &m->rs};
  for (size_t i = 0; i < sizeof b / sizeof b[0]; ++i)
    if (!(*b[i] = calloc((size_t)g1->nf, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  double **e[] = {&m->G, &m->tau_fw, &m->tau_sw, &m->y_plus};
  for (size_t i = 0; i < sizeof e / sizeof e[0]; ++i)
    if (!(*e[i] = calloc((size_t)nz, sizeof(double)))) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  for (int k = 0; k < PIPE_NFIELDS; ++k)
    if (!(m->field[k] = calloc((size_t)n * (size_t)nz, sizeof(double))))
      return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  /* the inlet (Krampa 2009 section 3.1) */
  const double V = c->bulk_velocity, k0 = 1.5 * (c->inlet_intensity * V) * (c->inlet_intensity * V);
  const double l0 = sl_scene_given(p->sc, &c->inlet_length_scale) ? c->inlet_length_scale : 0.007 * c->diameter;
  for (int i = 0; i < n; ++i) {
    m->uf_up[i] = m->us_up[i] = V, m->phi_up[i] = c->solids_fraction;
    m->k_up[i] = k0, m->eps_up[i] = pow(0.09, 0.75) * pow(k0, 1.5) / l0;
    m->theta_up[i] = 2.0 * k0 / 3.0;           /* isotropic, the solids' fluctuations the fluid's (digest erratum 12) */
    m->ks_up[i] = k0, m->kfs_up[i] = 2.0 * k0; /* model C's likewise: u_s' = u_f' at the inlet */
  }
  return 0;
}

/* The radial volume flux of each phase through the row's faces (x-faces 1..n-1 inside, 0 the axis, n the
   wall) from its continuity between the last station and the iterate, integrated outwards. */
void pipe_march_fluxes(pipe *p) {
  pipe_march *m = &p->march;
  const sl_fv_grid *g = &p->g;
  const int n = p->n;
  memset(m->ff, 0, (size_t)g->nf * sizeof *m->ff), memset(m->fs, 0, (size_t)g->nf * sizeof *m->fs);
  memset(m->rff, 0, (size_t)g->nf * sizeof *m->rff), memset(m->rfs, 0, (size_t)g->nf * sizeof *m->rfs);
  for (int i = 0; i < n; ++i) {
    double cs = p->phi[i], cs0 = m->phi_up[i], q = g->vol[i] / m->h;
    m->ff[i + 1] = m->ff[i] - ((1.0 - cs) * p->uf[i] - (1.0 - cs0) * m->uf_up[i]) * q;
    m->fs[i + 1] = m->fs[i] - (cs * p->us[i] - cs0 * m->us_up[i]) * q;
  }
  for (int f = 0; f <= n; ++f)
    m->rff[f] = p->rho_f * m->ff[f], m->rfs[f] = sl_theta_capacity(p->rho_s, m->fs[f]), m->rs[f] = p->rho_s * m->fs[f];
}

static void add(sl_csr *A, int i, int j, double v) { A->values[sl_csr_find(A, i, j)] += v; }

/* The axial convection of the momentum of each phase (row 2 i for the fluid, 2 i + 1 for the solids) and the
   radial convection upwind, into the fully developed pipe's bordered system (pipe_momentum.c). */
void pipe_march_momentum(const pipe *p, sl_csr *A, double *b) {
  const pipe_march *m = &p->march;
  const sl_fv_grid *g = &p->g;
  const int n = p->n;
  for (int ph = 0; ph < (p->two_phase ? 2 : 1); ++ph) {
    const double rho = ph ? p->rho_s : p->rho_f, *u = ph ? p->us : p->uf, *u0 = ph ? m->us_up : m->uf_up;
    const double *F = ph ? m->fs : m->ff;
    for (int i = 0; i < n; ++i) {
      double c = ph ? p->phi[i] : 1.0 - p->phi[i], c0 = ph ? m->phi_up[i] : 1.0 - m->phi_up[i];
      double q = g->vol[i] / m->h;
      add(A, 2 * i + ph, 2 * i + ph, c * rho * fmax(u[i], 0.0) * q);
      b[2 * i + ph] += c0 * rho * u0[i] * u0[i] * q;
    }
    for (int i = 0; i + 1 < n; ++i) { /* the face between i and i + 1: what leaves a cell takes its velocity */
      double out = rho * F[i + 1];
      int lo = 2 * i + ph, hi = 2 * (i + 1) + ph;
      if (out > 0.0) add(A, lo, lo, out), add(A, hi, lo, -out);
      else add(A, hi, hi, -out), add(A, lo, hi, out);
    }
  }
}

/* The march's storage of k or epsilon (the fluid's mass form) beside the pseudo-time's: m->cap and m->s_old
   for sl_cell_scalar_terms with dt = 1, the radial convection m->rff. */
void pipe_march_scalar(pipe *p, const double *cap_pseudo, const double *s_iter, const double *s_up) {
  pipe_march *m = &p->march;
  for (int i = 0; i < p->n; ++i) {
    double mf = (1.0 - p->phi[i]) * p->rho_f * fmax(p->uf[i], 0.0) / m->h;
    double mf0 = (1.0 - m->phi_up[i]) * p->rho_f * m->uf_up[i] / m->h;
    m->cap[i] = cap_pseudo[i] + mf;
    m->s_old[i] = (cap_pseudo[i] * s_iter[i] + mf0 * s_up[i]) / m->cap[i];
  }
}

/* The solids' march (pipe_solids.c): the radial balance of the fully developed pipe, phi v - D phi' (v the
   kinetic pressure's drift in flux), gains the axial convection, [(phi u_s)_j - (phi u_s)_{j-1}]/h, as cap
   u_s/h and m->s_old, and the radial convection by the mixture's volume flux j = F_f + F_s, added to flux:
     [(phi u_s)_j - (phi u_s)_{j-1}]/h + (1/r) d/dr(r (phi (j + v) - D phi')) = 0,
   the solids' continuity with their radial flux phi j plus the drift relative to the mixture. */
void pipe_march_solids(pipe *p, double *cap, double *flux) {
  pipe_march *m = &p->march;
  for (int i = 0; i < p->n; ++i) {
    double us = fmax(p->us[i], 1e-12 * p->cfg->bulk_velocity);
    cap[i] = us / m->h;
    m->s_old[i] = m->phi_up[i] * m->us_up[i] / us;
  }
  for (int f = 1; f < p->n; ++f) flux[f] += m->ff[f] + m->fs[f];
}

/* The drag of a station. Its closure is evaluated at the last station's solids fraction (the inlet's at the
   first), and the coefficient scaled to this station's, K = (phi/phi_up) K(phi_up, slip): the drag per unit
   volume of solids, K/phi, is taken one station upstream, as Patankar & Spalding's (1970, Heat and Mass Transfer
   in Boundary Layers, 2nd ed., ch. 6) march takes its coefficients from the upstream station; the slip stays
   implicit (Newton-linearised, pipe_solids.c). The error is O(h dphi/dz), first order as the march's backward
   differences, and nil where the flow has developed (the outlet equals the fully developed pipe).
   Why (measured): a drag law with a jump in phi, Gidaspow's hard switch from Wen-Yu to Ergun at c_f = 0.8
   (Gidaspow 1994; 36,675 -> 135,232 kg/(m3 s), x3.69, at the slip of 1.31 m/s of 3.4 mm PVC), makes the station's
   equations insoluble where the wall cell's fraction has to sit at the switch: with no-slip solids and the
   kinetic viscosity (Krampa's P1, configs/pvc_pipe.ini with solids_wall = no_slip), 40 mm from the uniform inlet
   the wall cell's solids decelerate from 2.25 to 0.16 m/s and gather to phi = 0.2; above it Ergun's drag carries
   them off, below it Wen-Yu's lets them gather. The iterates cycle across the switch (phi_w 0.198-0.2007) with a
   period of 2.4/relaxation iterations (3, 6, 10, 17, 26 at 0.8, 0.4, 0.2, 0.1, 0.05) that no relaxation ends
   (0.01 tried); holding phi, or the Huilin & Gidaspow (2003) blend, converges. Lagged, the drag of a station does
   not depend on its own phi but through the factor phi/phi_up (continuous), and the switch is crossed between
   stations: P1's wall cell phi 0.214, 0.127, 0.177, 0.168 at the first four stations, then smooth. */
const double *pipe_march_drag_fraction(const pipe *p, double *phi_arg) {
  for (int i = 0; i < p->n; ++i) phi_arg[i] = p->march.phi_up[i] > 0.0 ? p->march.phi_up[i] : p->phi[i];
  return phi_arg;
}

void pipe_march_drag(pipe *p, const double *phi_arg, double *dK) {
  for (int i = 0; i < p->n; ++i) {
    double r = p->phi[i] / phi_arg[i];
    p->K[i] *= r, dK[i] *= r;
  }
}

/* The march's storage of theta's transport (pipe_theta.c, the granular energy (3/2) rho_s phi theta convected
   by the solids, its capacity every model's: core/models/granular.h): m->cap and m->s_old beside the steady solve's, the radial convection m->rfs. */
void pipe_march_theta(pipe *p, const double *cap_pseudo) {
  pipe_march *m = &p->march;
  for (int i = 0; i < p->n; ++i) {
    double ms = sl_theta_capacity(p->rho_s, fmax(p->phi[i], 1e-6)) * fmax(p->us[i], 0.0) / m->h;
    double ms0 = sl_theta_capacity(p->rho_s, fmax(m->phi_up[i], 1e-6)) * m->us_up[i] / m->h;
    m->cap[i] = cap_pseudo[i] * 1e-30 + ms; /* the steady solve's pseudo-step is 1e30 */
    m->s_old[i] = (cap_pseudo[i] * 1e-30 * p->theta[i] + ms0 * m->theta_up[i]) / m->cap[i];
  }
}

/* The march's storage of model C's k_s or k_fs (pipe_ksfs.c: c_s rho_s k convected by the solids, Krampa eqs
   5.20 and 5.23's left sides): m->cap and m->s_old beside the steady solve's, the radial convection m->rs. */
void pipe_march_ksfs(pipe *p, const double *s_iter, const double *s_up) {
  pipe_march *m = &p->march;
  for (int i = 0; i < p->n; ++i) {
    double c = p->rho_s * fmax(p->phi[i], 1e-6), ms = c * fmax(p->us[i], 0.0) / m->h;
    double ms0 = p->rho_s * fmax(m->phi_up[i], 1e-6) * m->us_up[i] / m->h;
    m->cap[i] = c * 1e-30 + ms; /* the steady solve's pseudo-step is 1e30 */
    m->s_old[i] = (c * 1e-30 * s_iter[i] + ms0 * s_up[i]) / m->cap[i];
  }
}

/* The drift work of the particles' modulation of the fluid's turbulence (Krampa 2009 eqs 4.80-4.82, Simonin 1996;
   digest section 1.4), per unit volume in every cell of the station, W = A [nu_t grad(c_f).(U_f - U_s) + (U_f -
   U_s).U_d]: the drift-work term of the k equation 4.82, (c_s rho_s/(t_p rho_f)) mu_t grad(c_f).(U_f - U_s) with
   c_s rho_s/t_p = K = A, and the drift part of c_f rho_f Pi_kf (eq 4.80), A (U_f - U_s).U_d, with the drift velocity
   of eq 4.81, U_d = D (grad(c_f)/c_f - grad(c_s)/c_s), D the dispersivity of [closure.turbulent_dispersion] (eq 4.81's
   t_fs k_fs/3 with model = simonin). With grad c_s = -grad c_f, U_d = D grad(c_f)/(c_f c_s), so that
     W = A g (nu_t + D/(c_f c_s)),  g = grad(c_f).(U_f - U_s) = -(dphi/dz)(u_f - u_s) - (dphi/dr)(v_f - v_s),
   A the closure's exchange coefficient (Simonin's: K). The axial part from the march's backward difference
   (phi - phi_up)/h; the radial part at the interior faces, v_f and v_s the phases' radial velocities of their
   volume fluxes (pipe_march_fluxes) over their fractions, averaged to the cells (nothing crosses the axis or the
   wall). In the fully developed pipe the slip is axial and the gradients radial: g = 0 and W = 0; likewise here
   where the station equals the last (phi = phi_up, no radial fluxes), to round-off (tests/models/test_pipe_ksfs.c).
   W > 0 where the solids thin downstream while they lag the fluid (dphi/dz < 0, u_f > u_s): the fluid's
   turbulent flux of solids works against the slip. A, Dt and W are [n]. */
void pipe_march_drift_work(const pipe *p, const double *A, const double *Dt, double *W) {
  const pipe_march *m = &p->march;
  const sl_fv_grid *g = &p->g;
  const int n = p->n;
  for (int i = 0; i < n; ++i) {
    W[i] = 0.0;
    if (!m->on || !(A[i] > 0.0)) continue;
    const double cs = fmax(p->phi[i], 1e-12), cf = 1.0 - p->phi[i];
    double gr = 0.0; /* the radial part, the mean of the cell's two faces */
    for (int f = i; f <= i + 1; ++f) {
      if (f < 1 || f >= n) continue;
      const double pf = 0.5 * (p->phi[f - 1] + p->phi[f]), a = g->area[f];
      const double vf = m->ff[f] / ((1.0 - pf) * a), vs = m->fs[f] / (fmax(pf, 1e-12) * a);
      gr -= 0.5 * (p->phi[f] - p->phi[f - 1]) / g->dist[f] * (vf - vs);
    }
    const double gz = -(p->phi[i] - m->phi_up[i]) / m->h * (p->uf[i] - p->us[i]);
    W[i] = A[i] * (gz + gr) * (p->mu_t[i] / p->rho_f + Dt[i] / (cf * cs));
  }
}

/* The station's fields into the 2-D arrays (row j). */
static void store(pipe *p, int j) {
  pipe_march *m = &p->march;
  const double *f[PIPE_NFIELDS] = {p->uf, p->us, p->phi, p->k, p->eps, p->mu_t, p->theta, p->ks, p->kfs, p->eps_s};
  for (int k = 0; k < PIPE_NFIELDS; ++k)
    memcpy(m->field[k] + (size_t)j * (size_t)p->n, f[k], (size_t)p->n * sizeof(double));
  m->G[j] = p->G, m->tau_fw[j] = p->tau_fw, m->tau_sw[j] = p->tau_sw, m->y_plus[j] = p->y_plus;
}

int pipe_march_solve(pipe *p, sl_diag *d) {
  pipe_march *m = &p->march;
  const int n = p->n;
  const sl_fv_grid *g2 = &m->g;
  /* the first iterate: the inlet */
  memcpy(p->uf, m->uf_up, (size_t)n * sizeof(double)), memcpy(p->us, m->us_up, (size_t)n * sizeof(double));
  memcpy(p->k, m->k_up, (size_t)n * sizeof(double)), memcpy(p->eps, m->eps_up, (size_t)n * sizeof(double));
  memcpy(p->phi, m->phi_up, (size_t)n * sizeof(double));
  if (p->cfg->granular_temperature == PIPE_THETA_TRANSPORT) memcpy(p->theta, m->theta_up, (size_t)n * sizeof(double));
  if (p->cfg->solids_turbulence == PIPE_SOLIDS_TURBULENCE_TRANSPORTED) {
    memcpy(p->ks, m->ks_up, (size_t)n * sizeof(double)), memcpy(p->kfs, m->kfs_up, (size_t)n * sizeof(double));
    p->ksfs_started = 1;
  }
  m->iterations = 0, m->worst_station_iterations = 0, m->pressure_drop = 0.0;
  p->G = 0.0;
  double z_last = 0.0;
  int rc = 0;
  for (int j = 0; j < m->nz && !rc; ++j) {
    m->j = j;
    double z = g2->yc[j];
    m->h = z - z_last;
    rc = pipe_converge(p, d);
    m->iterations += p->iterations;
    if (p->iterations > m->worst_station_iterations) m->worst_station_iterations = p->iterations;
    if (rc) return sl_diag_prefix(d, rc, "pipe: the developing pipe's station %d at z = %g m", j, z);
    if (!p->converged) {
      snprintf(p->stop_reason, sizeof p->stop_reason,
               "not converged at the station z = %g m (%d of %d): %ld iterations ([pipe] iterations) changed the "
               "state by %.3g > tolerance %.3g, most in %s",
               z, j + 1, m->nz, p->iterations, p->change, p->cfg->tolerance, p->change_field ? p->change_field : "?");
      p->iterations = m->iterations;
      store(p, j); /* the saved state shows where it stopped */
      return sl_diag_set(d, SL_EFAILED, "pipe: %s", p->stop_reason);
    }
    /* the wall stress of the converged station */
    if ((rc = pipe_turbulence_coefficients(p, d)) || (rc = pipe_wall_function(p, d))) return rc;
    if (p->two_phase && (rc = pipe_solids_coefficients(p, d))) return rc;
    if (p->two_phase) p->tau_sw = p->a_sw * p->us[n - 1];
    store(p, j);
    m->pressure_drop -= p->G * m->h;
    memcpy(m->uf_up, p->uf, (size_t)n * sizeof(double)), memcpy(m->us_up, p->us, (size_t)n * sizeof(double));
    memcpy(m->k_up, p->k, (size_t)n * sizeof(double)), memcpy(m->eps_up, p->eps, (size_t)n * sizeof(double));
    memcpy(m->phi_up, p->phi, (size_t)n * sizeof(double));
    memcpy(m->theta_up, p->theta, (size_t)n * sizeof(double));
    memcpy(m->ks_up, p->ks, (size_t)n * sizeof(double)), memcpy(m->kfs_up, p->kfs, (size_t)n * sizeof(double));
    z_last = z;
  }
  m->pressure_drop -= p->G * (p->cfg->length - z_last); /* the outlet's half cell at the last gradient */
  p->iterations = m->iterations;
  p->converged = 1;
  return 0;
}

/* The 2-D fields on the grid's mesh cells, and the march's own scalars (the others are the outlet's). */
int pipe_march_write(pipe *p, sl_output *out, unsigned mask, sl_diag *d) {
  pipe_march *m = &p->march;
  const int nc = p->n * m->nz;
  double *v = malloc((size_t)nc * sizeof *v);
  if (!v) return sl_diag_set(d, SL_ENOMEM, "pipe: out of memory");
  int rc = 0;
  for (int k = 0; k < PIPE_NFIELDS && !rc; ++k) {
    if (!(mask >> k & 1u)) continue;
    for (int c = 0; c < nc; ++c) v[m->tg.mesh_cell[c]] = m->field[k][c];
    rc = sl_output_write_field(out, sl_pipe_schema.fields[k], SL_CENTRE_CELL, 1, v, d);
  }
  free(v);
  const double V = p->cfg->bulk_velocity, q = 0.5 * p->rho_f * V * V;
  /* the pressure drop beyond the outlet's friction: the inlet's excess, in dynamic heads (the weight apart) */
  const double weight = -p->rho_f * p->gz * p->cfg->length;
  const double excess =
      (m->pressure_drop - weight - 4.0 * m->tau_fw[m->nz - 1] / p->cfg->diameter * p->cfg->length) / q;
  if (!rc) rc = sl_output_write_scalar(out, "pressure_drop", m->pressure_drop, d);
  if (!rc) rc = sl_output_write_scalar(out, "inlet_excess_head", excess, d);
  if (!rc) rc = sl_output_write_scalar(out, "stations", (double)m->nz, d);
  if (!rc) rc = sl_output_write_scalar(out, "station_iterations_max", (double)m->worst_station_iterations, d);
  return rc;
}
