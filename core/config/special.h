/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Special functions of the expression language (expr.h): Bessel functions
 * of the first and second kind and the integrals of J0 and Y0, as the
 * rotating-cylinder travelling waves of Nigam (1999, eqs 4.179-4.193) need
 * them. Real arguments; NaN outside the domain (x < 0 where the function is
 * complex or undefined there, a non-integer order), never an error.
 *
 *   sl_bessel_j0, j1, y0, y1    J0, J1, Y0, Y1 (Y: x > 0; Y(0) = -inf)
 *   sl_bessel_jn(n, x), yn      integer order n (|n| <= 10000)
 *   sl_bessel_jhalf(x)          J_{1/2}(x) = sqrt(2/(pi x)) sin x
 *                               (Abramowitz & Stegun 1964, 10.1.11 with 10.1.1), x >= 0
 *   sl_bessel_int_j0(x)         int_0^x J0(t) dt (odd in x)
 *   sl_bessel_int_y0(x)         int_0^x Y0(t) dt, x >= 0
 *
 * J and Y of integer order are the C library's (POSIX j0, j1, jn, y0, y1,
 * yn). The integrals: the power series integrated term by term up to x = 8
 * (Abramowitz & Stegun 9.1.12 and 9.1.13 for J0 and Y0), beyond it 16-point
 * Gauss-Legendre panels of width at most 1 on the library's J0 or Y0 (about
 * 16 x evaluations; 1e-14 relative or better where the integral is not
 * near a zero). */
#ifndef SLUICE_CONFIG_SPECIAL_H
#define SLUICE_CONFIG_SPECIAL_H

double sl_bessel_j0(double x);
double sl_bessel_j1(double x);
double sl_bessel_y0(double x);
double sl_bessel_y1(double x);
double sl_bessel_jn(double n, double x);
double sl_bessel_yn(double n, double x);
double sl_bessel_jhalf(double x);
double sl_bessel_int_j0(double x);
double sl_bessel_int_y0(double x);

#endif
