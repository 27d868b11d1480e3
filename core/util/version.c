/* SPDX-License-Identifier: GPL-2.0-or-later */
#include "core/util/version.h"

#include "sluice_version_full.h"

const char *sl_version(void) { return SLUICE_VERSION_FULL; }
