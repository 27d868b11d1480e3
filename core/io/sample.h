/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Sampling of output files: a field's value at arbitrary points, and what a
 * file holds (for `sluice sample`).
 *
 * A node field is interpolated with the Lagrange basis of its cell
 * (core/fe/element.h): linear/quadratic on lines (Polyline, Edge_3) and
 * triangles (Triangle, Triangle_6), bilinear/biquadratic on quadrilaterals
 * (Quadrilateral, Quadrilateral_9). The geometry map is the linear/bilinear
 * one of the cell's corner vertices, so higher-order nodes must sit where
 * that map puts them (straight edges, Q9 centre at the corners' mean). A
 * cell field is constant on each cell; on a face shared by two cells a point
 * takes the value of the cell found first. Points of 1-D meshes use x only. */
#ifndef SLUICE_IO_SAMPLE_H
#define SLUICE_IO_SAMPLE_H

#include "core/io/output.h"

typedef struct sl_sample {
  int step;    /* index of the output step sampled */
  double time; /* its time */
  sl_centring centring;
  int dim;        /* of the mesh: 1 or 2 */
  int components; /* values per point: 1, or 3 for vectors (as stored) */
  int n_points;
  int n_outside;  /* points in no cell */
  double *values; /* n_points x components; NaN at points outside the mesh */
} sl_sample;

/* Field `field` at the points xy (n_points x 2, x then y) at the output
 * step nearest to t among those holding it; t = +INFINITY takes the last.
 * A finite t outside [first, last] output time is SL_EBADINPUT (the message
 * gives the range and the nearest time); so are an unknown field (with a
 * did-you-mean) and a mesh that cannot be sampled. Points outside the mesh
 * are not an error: NaN and counted in n_outside. Free with sl_sample_free. */
int sl_sample_points(const char *path, const char *field, double t, int n_points, const double *xy, sl_sample *s,
                     sl_diag *d);
void sl_sample_free(sl_sample *s);

/* ---- what a file holds (defined in read.c, beside the other readers) ---- */

typedef struct sl_output_field_info {
  char name[256];
  sl_centring centring;
  int components;         /* as stored: 1 or 3 */
  int n_steps;            /* steps holding the field */
  double t_first, t_last; /* times of the first and last of them */
} sl_output_field_info;

typedef struct sl_output_contents {
  int n_steps;
  double *times; /* n_steps, step order */
  int n_fields;
  sl_output_field_info *fields; /* name order */
} sl_output_contents;

/* Complete steps only, as the other readers. Free with sl_output_contents_free. */
int sl_output_read_contents(const char *path, sl_output_contents *c, sl_diag *d);
void sl_output_contents_free(sl_output_contents *c);

#endif
