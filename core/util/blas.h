/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Which BLAS the process runs on: UMFPACK's and CHOLMOD's supernodal
 * kernels call it, and an optimised one (OpenBLAS) halves UMFPACK's
 * factorisation time against the reference BLAS. Found from the shared
 * objects the process has loaded (dl_iterate_phdr), their resolved paths
 * (Debian's libblas.so.3 is an alternative: /etc/alternatives names the
 * provider), and OpenBLAS's own openblas_get_config where it is present. */
#ifndef SLUICE_UTIL_BLAS_H
#define SLUICE_UTIL_BLAS_H

/* e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH NO_AFFINITY Haswell SINGLE_THREADED
 * (/usr/lib/x86_64-linux-gnu/openblas-serial/libblas.so.3)", "reference
 * BLAS (/usr/lib/x86_64-linux-gnu/blas/libblas.so.3)", or "none loaded".
 * A static string, computed at the first call. */
const char *sl_blas_description(void);

#endif
