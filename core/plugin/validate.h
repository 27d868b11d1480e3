/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Validation of a closure descriptor against ABI v1: versions and sizes,
 * schema sanity (unique names, defaults inside bounds, offsets inside the
 * struct), input names from the host dictionary, and the kind's contract. */
#ifndef SLUICE_PLUGIN_VALIDATE_H
#define SLUICE_PLUGIN_VALIDATE_H

#include <sluice/closure.h>

#include "core/util/diag.h"

/* Returns 0 or SL_EBADINPUT with a message (without the library name). */
int sl_validate_descriptor(const sl_closure_desc *desc, sl_diag *d);

/* Size of the parameter type in the closure's struct. */
size_t sl_param_type_size(sl_param_type type);

#endif
