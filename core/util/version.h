/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The version of this build: the release number and, for a build from a git
 * work tree, the commit ("0.1.0+g5504671c2a", ".dirty" with uncommitted
 * changes), as `sluice version` prints it and every output's provenance
 * records it. */
#ifndef SLUICE_UTIL_VERSION_H
#define SLUICE_UTIL_VERSION_H

const char *sl_version(void);

#endif
