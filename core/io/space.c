/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Room for the next write (h5util.h): HDF5 1.10 does not recover from a
 * write that fails for want of space (a full disk, the file size limit of
 * `ulimit -f`): the dataset or file whose flush failed cannot be closed, and
 * the library crashes in its exit handler (SIGSEGV). So each write is
 * checked first against the space the file can still take, with a margin
 * for HDF5's own metadata, and refused with a message instead. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/statvfs.h>

#include "core/io/h5util.h"

/* What HDF5 writes beside the values: object headers, B-trees, the
 * superblock and the metadata flushed at close. */
enum { SPACE_MARGIN = 256 * 1024 };

static int space_check(const sl_output *o, double bytes, const char *what, sl_diag *d) {
  double need = bytes * 1.125 + SPACE_MARGIN;
  const char *file = o->committed ? o->path : o->tmp_path;
  hsize_t size = 0;
  if (o->file >= 0 && H5Fget_filesize(o->file, &size) < 0) {
    H5Eclear2(H5E_DEFAULT);
    size = 0;
  }
  struct rlimit rl;
  if (getrlimit(RLIMIT_FSIZE, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY) {
    double left = (double)rl.rlim_cur - (double)size;
    if (need > left)
      return sl_diag_set(d, SL_EFAILED,
                         "%s: no room to write %s: it needs about %.3g MB and the file size limit (ulimit -f, "
                         "%.3g MB) leaves %.3g MB",
                         o->path, what, need / 1e6, (double)rl.rlim_cur / 1e6, left > 0 ? left / 1e6 : 0.0);
  }
  char dir[4096];
  snprintf(dir, sizeof dir, "%s", file);
  char *slash = strrchr(dir, '/');
  if (slash) slash == dir ? (void)(slash[1] = 0) : (void)(*slash = 0);
  else snprintf(dir, sizeof dir, ".");
  struct statvfs vs;
  /* cannot tell (or a file system that reports no size, as some network and
   * FUSE ones do): let the write say */
  if (statvfs(dir, &vs) != 0 || vs.f_blocks == 0) return 0;
  double left = (double)vs.f_bavail * (double)vs.f_frsize;
  if (need > left)
    return sl_diag_set(d, SL_EFAILED, "%s: no room to write %s: it needs about %.3g MB and the disk has %.3g MB free",
                       o->path, what, need / 1e6, left / 1e6);
  return 0;
}

/* Collective: rank 0 decides for every rank (the ranks would otherwise see
 * the disk at different moments, and one stop where the others write). */
int sl_io_space_check(const sl_output *o, double bytes, const char *what, sl_diag *d) {
  int rc = sl_io_rank0(o) ? space_check(o, bytes, what, d) : 0;
  int all = sl_io_agree(o, rc);
  if (all && !rc) rc = sl_diag_set(d, all, "%s: no room to write %s (rank 0 found)", o->path, what);
  return rc;
}

void sl_io_process_start(void) { H5dont_atexit(); }
