/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The two-fluid model's closure quantities (quantities.h). */
#include "core/models/two_fluid/quantities.h"

const char *const tf_quantity_names[TF_Q_N] = {"phi",           "slip",       "theta",      "rho_f",   "mu_f",
                                               "rho_s",         "d_p",        "sphericity", "gravity", "slip_wall",
                                               "wall_distance", "shear_rate", "density"};
