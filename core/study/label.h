/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Words for plots: a field's name as a reader of a paper expects it (a
 * symbol and its unit instead of "velocity[2]") and text with numbers in
 * e-notation and Greek names written out as chart.h's marked-up text
 * ("eps = 1e-4" becomes "ε = 10^{-4}"). */
#ifndef SLUICE_STUDY_LABEL_H
#define SLUICE_STUDY_LABEL_H

#include <stddef.h>

/* The quantity a field (and component, when component >= 0 and the field is
 * a vector) stands for, with its unit in parentheses when it has one:
 * "solids volume fraction φ", "velocity u_{z} (m/s)". A name it does not
 * know is given as it is. */
void sl_plot_quantity(const char *field, int component, char *buf, size_t n);

/* The symbol alone, for formulas in labels ("φ", "u_{z}", or the name). */
void sl_plot_symbol(const char *field, int component, char *buf, size_t n);

/* The unit of a field ("m/s"), or "" for a number without one or unknown. */
const char *sl_plot_unit(const char *field);

/* in rewritten for a chart: numbers such as 1e-4 or 2.5e+03 as 10^{-4} and
 * 2.5×10^{3}; the words phi, eps, mu, rho, tau, nu as Greek letters, with
 * what follows an underscore or a trailing digit as a subscript (phi0: φ_{0},
 * phi_max: φ_{max}). Other text is kept. */
void sl_plot_pretty(const char *in, char *out, size_t n);

#endif
