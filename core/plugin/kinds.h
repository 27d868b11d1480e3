/* Closure kinds: their names and contracts (closure-abi.md, "Kind contracts"),
 * and the dictionary of input names the host knows how to supply. */
#ifndef SLUICE_PLUGIN_KINDS_H
#define SLUICE_PLUGIN_KINDS_H

#include <sluice/closure.h>

#include "core/util/diag.h"

#define SL_KIND_FIRST SL_KIND_DRAG
#define SL_KIND_LAST SL_KIND_DENSIFICATION

/* "drag", "hindered_settling", ...; NULL for an unknown kind. */
const char *sl_kind_name(sl_kind kind);
/* Kind from its name, with a did-you-mean on failure. */
int sl_kind_from_name(const char *name, sl_kind *kind, sl_diag *d);
/* All kind names, for suggestions and listings. */
const char *const *sl_kind_names(int *n);

/* Is `name` in the host's dictionary of input fields? */
int sl_input_is_known(const char *name);
const char *const *sl_input_names(int *n);

/* Checks a descriptor against its kind's contract: required inputs present
 * (and differentiable where the contract says so), required outputs present.
 * Returns 0 or SL_EBADINPUT with a message naming what is missing. */
int sl_kind_check_contract(const sl_closure_desc *desc, sl_diag *d);

#endif
