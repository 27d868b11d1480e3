/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Lagrange reference elements: partition of unity, Kronecker property at
 * the nodes, gradients against central differences, exact reproduction of
 * the polynomials of the element's order. */
#include <math.h>

#include "core/fe/element.h"
#include "testing.h"

static const sl_cell_type cells[] = {SL_CELL_LINE2, SL_CELL_TRI3, SL_CELL_QUAD4};

/* A few points inside the reference cell, deterministic. */
static void sample_point(sl_cell_type t, int k, double xi[2]) {
  double a = 0.5 * (1.0 + sin(1.3 * k + 0.2)), b = 0.5 * (1.0 + cos(2.1 * k + 0.7)); /* in [0, 1] */
  if (t == SL_CELL_TRI3) {
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    xi[0] = a, xi[1] = b;
  } else {
    xi[0] = 2.0 * a - 1.0, xi[1] = t == SL_CELL_LINE2 ? 0.0 : 2.0 * b - 1.0;
  }
}

static void test_partition_of_unity(const sl_element *e) {
  double worst = 0.0, worst_grad = 0.0;
  for (int k = 0; k < 20; ++k) {
    double xi[2], phi[SL_ELEMENT_MAX_BASIS], dphi[SL_ELEMENT_MAX_BASIS][2], s = 0.0, g[2] = {0.0, 0.0};
    sample_point(e->cell, k, xi);
    e->eval(xi, phi, dphi);
    for (int b = 0; b < e->n_basis; ++b) s += phi[b], g[0] += dphi[b][0], g[1] += dphi[b][1];
    worst = fmax(worst, fabs(s - 1.0));
    worst_grad = fmax(worst_grad, fabs(g[0]) + fabs(g[1]));
  }
  CHECK_MSG(worst < 1e-14, "%s on %s: sum of basis functions off by %g", e->name, sl_cell_type_name(e->cell), worst);
  CHECK_MSG(worst_grad < 1e-13, "%s: gradients do not sum to zero (%g)", e->name, worst_grad);
}

static void test_kronecker(const sl_element *e) {
  double worst = 0.0;
  for (int i = 0; i < e->n_basis; ++i) {
    double phi[SL_ELEMENT_MAX_BASIS];
    e->eval(e->nodes[i], phi, NULL);
    for (int b = 0; b < e->n_basis; ++b) worst = fmax(worst, fabs(phi[b] - (b == i ? 1.0 : 0.0)));
  }
  CHECK_MSG(worst < 1e-15, "%s on %s: phi_b(node_i) off delta_bi by %g", e->name, sl_cell_type_name(e->cell), worst);
}

static void test_gradient_fd(const sl_element *e) {
  const double h = 1e-6;
  double worst = 0.0;
  for (int k = 0; k < 10; ++k) {
    double xi[2], dphi[SL_ELEMENT_MAX_BASIS][2];
    sample_point(e->cell, k, xi);
    e->eval(xi, NULL, dphi);
    for (int dir = 0; dir < e->dim; ++dir) {
      double p[2] = {xi[0], xi[1]}, m[2] = {xi[0], xi[1]}, fp[SL_ELEMENT_MAX_BASIS], fm[SL_ELEMENT_MAX_BASIS];
      p[dir] += h, m[dir] -= h;
      e->eval(p, fp, NULL);
      e->eval(m, fm, NULL);
      for (int b = 0; b < e->n_basis; ++b) worst = fmax(worst, fabs((fp[b] - fm[b]) / (2 * h) - dphi[b][dir]));
    }
  }
  CHECK_MSG(worst < 1e-8, "%s on %s: gradient vs central difference off by %g", e->name, sl_cell_type_name(e->cell),
            worst);
}

/* The interpolant of a polynomial of the element's order is the polynomial. */
static double poly(int order, const double x[2]) {
  return order == 1 ? 0.3 + 1.7 * x[0] - 0.4 * x[1]
                    : 0.3 + 1.7 * x[0] - 0.4 * x[1] + 0.9 * x[0] * x[0] - 1.1 * x[1] * x[1];
}

static void test_reproduction(const sl_element *e) {
  double worst = 0.0;
  for (int k = 0; k < 10; ++k) {
    double xi[2], phi[SL_ELEMENT_MAX_BASIS], s = 0.0;
    sample_point(e->cell, k, xi);
    e->eval(xi, phi, NULL);
    for (int b = 0; b < e->n_basis; ++b) s += phi[b] * poly(e->order, e->nodes[b]);
    worst = fmax(worst, fabs(s - poly(e->order, xi)));
  }
  CHECK_MSG(worst < 1e-14, "%s on %s: order-%d polynomial not reproduced (%g)", e->name, sl_cell_type_name(e->cell),
            e->order, worst);
  if (e->order == 2 && e->dim == 2) { /* xy is in P2 and Q2 */
    double xi[2] = {0.2, 0.3}, phi[SL_ELEMENT_MAX_BASIS], s = 0.0;
    e->eval(xi, phi, NULL);
    for (int b = 0; b < e->n_basis; ++b) s += phi[b] * e->nodes[b][0] * e->nodes[b][1];
    CHECK_CLOSE(s, 0.06, 1e-14);
  }
}

/* The node conventions the dof maps rely on: vertices first, then face
 * midpoints of local face k = (k, k+1). */
static void test_node_order(const sl_element *e) {
  int nv = (int)e->cell;
  if (e->order != 2 || e->dim != 2) return;
  for (int k = 0; k < nv; ++k) {
    const double *a = e->nodes[k], *b = e->nodes[(k + 1) % nv], *m = e->nodes[nv + k];
    CHECK(m[0] == 0.5 * (a[0] + b[0]) && m[1] == 0.5 * (a[1] + b[1]));
  }
}

int main(void) {
  int count = 0;
  for (int c = 0; c < 3; ++c)
    for (int order = 1; order <= 2; ++order) {
      const sl_element *e = sl_element_lagrange(cells[c], order);
      CHECK(e != NULL);
      if (!e) continue;
      ++count;
      CHECK(e->cell == cells[c] && e->order == order);
      test_partition_of_unity(e);
      test_kronecker(e);
      test_gradient_fd(e);
      test_reproduction(e);
      test_node_order(e);
    }
  CHECK(count == 6);
  CHECK(sl_element_lagrange(SL_CELL_TRI3, 3) == NULL);
  CHECK(sl_element_lagrange(SL_CELL_QUAD4, 2)->n_basis == 9);
  CHECK(sl_element_lagrange(SL_CELL_TRI3, 2)->n_basis == 6);
  CHECK(sl_element_lagrange(SL_CELL_LINE2, 2)->n_basis == 3);
  return sl_test_summary();
}
