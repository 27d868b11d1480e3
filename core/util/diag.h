/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Diagnostics shared by the whole core: a message buffer and the exit codes.
 * Functions that can fail take an sl_diag and return 0 or one of the codes. */
#ifndef SLUICE_UTIL_DIAG_H
#define SLUICE_UTIL_DIAG_H

#include <stddef.h>

enum {
  SL_EXIT_OK = 0,
  SL_EFAILED = 1,   /* the simulation failed; the last good state is kept */
  SL_EBADINPUT = 2, /* bad usage or bad input: nothing was written */
  SL_ENOMEM = 3     /* out of memory: the run stops (a smaller step would not help); a failed run to the user */
};

/* The process exit status of a code: out of memory is a failed run (1). */
static inline int sl_exit_status(int code) { return code == SL_ENOMEM ? SL_EFAILED : code; }

typedef struct sl_diag {
  char msg[2048];
} sl_diag;

/* Formats into d->msg (when d is not NULL) and returns `code`. */
int sl_diag_set(sl_diag *d, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* Prefixes the existing message: "context: <old message>". */
int sl_diag_prefix(sl_diag *d, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Levenshtein distance, capped: the did-you-mean helper. */
int sl_edit_distance(const char *a, const char *b);
/* The candidate closest to `word`, or NULL when none is close enough. */
const char *sl_suggest(const char *word, const char *const *candidates, int n);

#endif
