/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The SI unit of the fields and scalars the models write, by name, for the
 * writers that do not pass one (output.h). A model with a name not listed
 * here passes its unit (sl_output_write_field_unit, ..._scalar_unit). */
#include <string.h>

#include "core/io/h5util.h"

static const struct {
  const char *name, *unit;
} exact[] = {
    {"velocity", "m/s"},
    {"velocity_solid", "m/s"},
    {"velocity_fluid", "m/s"},
    {"u_theta", "m/s"},
    {"pressure", "Pa"},
    {"solids_pressure", "Pa"},
    {"shear_rate", "1/s"},
    {"viscosity", "Pa s"},
    {"yielded", "1"},
    {"phi", "1"},
    {"theta", "m^2/s^2"}, /* granular temperature */
    {"stream_function", "m^2/s"},
    {"value", "1"},
    {"mixture_flux", "m/s"},
    {"solids_conservation_error", "1"},
    {"balance_error", "1"},
};

/* Scalars named PREFIX_<boundary or number>. */
static const struct {
  const char *prefix, *unit;
} prefixed[] = {
    {"wall_shear_stress_", "Pa"}, {"wall_slip_", "m/s"},      {"torque_", "N m/m"},
    {"bagnold_number_", "1"},     {"interface_height_", "m"}, {"interface_level_", "1"},
};

const char *sl_io_default_unit(const char *name) {
  if (!name) return "";
  for (size_t i = 0; i < sizeof exact / sizeof exact[0]; ++i)
    if (strcmp(name, exact[i].name) == 0) return exact[i].unit;
  for (size_t i = 0; i < sizeof prefixed / sizeof prefixed[0]; ++i)
    if (strncmp(name, prefixed[i].prefix, strlen(prefixed[i].prefix)) == 0) return prefixed[i].unit;
  return "";
}
