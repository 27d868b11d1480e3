/* SPDX-License-Identifier: GPL-2.0-or-later */
/* One output file written by every rank of a run on several (mpirun,
 * parallel HDF5). All ranks open the file together with the MPI-IO driver
 * (H5Pset_fapl_mpio) and make the same calls in the same order, so that
 * HDF5's metadata (groups, datasets, attributes) is created collectively,
 * as parallel HDF5 requires (HDF5 User's Guide, "Parallel HDF5": every
 * call that modifies the file's structure is collective); each rank writes
 * its own block of rows of each dataset, [r n / N, (r + 1) n / N) for rank
 * r of N, in one collective transfer (H5FD_MPIO_COLLECTIVE). The .xmf and
 * the CSV beside the file, the rename and the removals are rank 0's.
 *
 * HDF5 1.10 writes no variable-length data through the MPI-IO driver
 * ("Parallel IO does not support writing VL or region reference datatypes
 * yet"): the provenance's string datasets are written by rank 0 alone
 * into the file the ranks closed for it (sl_io_serial_interlude), and the
 * ranks then open it again together. Built against serial HDF5 (the
 * default build), a collective output is refused and none of this is
 * compiled. */
#include <stdlib.h>
#include <string.h>

#include "core/io/h5util.h"

#ifdef H5_HAVE_PARALLEL

int sl_io_collective_start(sl_output *o, sl_diag *d) {
  int init = 0;
  if (MPI_Initialized(&init) != MPI_SUCCESS || !init)
    return sl_diag_set(d, SL_EBADINPUT, "%s: a collective output needs MPI started", o->path);
  if (MPI_Comm_rank(MPI_COMM_WORLD, &o->rank) != MPI_SUCCESS || MPI_Comm_size(MPI_COMM_WORLD, &o->ranks) != MPI_SUCCESS)
    return sl_diag_set(d, SL_EFAILED, "%s: cannot ask MPI for the ranks", o->path);
  o->collective = 1;
  return 0;
}

hid_t sl_io_fapl(const sl_output *o) {
  hid_t p = H5Pcreate(H5P_FILE_ACCESS);
  if (p < 0) return -1;
  if (o->collective && H5Pset_fapl_mpio(p, MPI_COMM_WORLD, MPI_INFO_NULL) < 0) {
    H5Pclose(p);
    return -1;
  }
  return p;
}

int sl_io_agree(const sl_output *o, int rc) {
  if (!o->collective) return rc;
  int all = rc;
  if (MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD) != MPI_SUCCESS) return rc ? rc : SL_EFAILED;
  return all;
}

void sl_io_barrier(const sl_output *o) {
  if (o->collective) MPI_Barrier(MPI_COMM_WORLD);
}

#else

int sl_io_collective_start(sl_output *o, sl_diag *d) {
  return sl_diag_set(d, SL_EBADINPUT, "%s: this build's HDF5 is serial: no collective output (parallel HDF5 needed)",
                     o->path);
}

hid_t sl_io_fapl(const sl_output *o) {
  (void)o;
  return H5Pcreate(H5P_FILE_ACCESS);
}

int sl_io_agree(const sl_output *o, int rc) {
  (void)o;
  return rc;
}

void sl_io_barrier(const sl_output *o) { (void)o; }

#endif

int sl_io_rank0(const sl_output *o) { return !o->collective || o->rank == 0; }

int sl_io_write_rows(sl_output *o, hid_t ds, hid_t mtype, size_t elem, hsize_t n, hsize_t width, const void *buf) {
  o->bytes_all += (double)n * (double)width * (double)elem;
  if (!o->collective) {
    if (H5Dwrite(ds, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0) return -1;
    o->bytes_here += (double)n * (double)width * (double)elem;
    return 0;
  }
#ifdef H5_HAVE_PARALLEL
  /* rank r's block of rows; the dataset's rank (1 or 2) is the file's */
  hsize_t lo = n * (hsize_t)o->rank / (hsize_t)o->ranks, hi = n * (hsize_t)(o->rank + 1) / (hsize_t)o->ranks;
  hid_t fs = H5Dget_space(ds), ms = -1, x = H5Pcreate(H5P_DATASET_XFER);
  int rank = fs >= 0 ? H5Sget_simple_extent_ndims(fs) : -1, rc = -1;
  if (fs < 0 || x < 0 || rank < 1 || rank > 2 || H5Pset_dxpl_mpio(x, H5FD_MPIO_COLLECTIVE) < 0) goto done;
  hsize_t start[2] = {lo, 0}, count[2] = {hi - lo, width}, one[2] = {1, width};
  if (hi > lo) {
    ms = H5Screate_simple(rank, count, NULL);
    if (ms < 0 || H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) < 0) goto done;
  } else { /* no rows here: the rank still takes part in the transfer */
    ms = H5Screate_simple(rank, one, NULL);
    if (ms < 0 || H5Sselect_none(ms) < 0 || H5Sselect_none(fs) < 0) goto done;
  }
  const char *from = (const char *)buf + (size_t)(lo * width) * elem;
  if (H5Dwrite(ds, mtype, ms, fs, x, hi > lo ? from : buf) < 0) goto done;
  H5D_mpio_actual_io_mode_t mode = H5D_MPIO_NO_COLLECTIVE;
  if (H5Pget_mpio_actual_io_mode(x, &mode) >= 0 && mode != H5D_MPIO_NO_COLLECTIVE) ++o->n_collective;
  o->bytes_here += (double)(hi - lo) * (double)width * (double)elem;
  rc = 0;
done:
  if (ms >= 0) H5Sclose(ms);
  if (fs >= 0) H5Sclose(fs);
  if (x >= 0) H5Pclose(x);
  return rc;
#else
  (void)mtype, (void)elem, (void)n, (void)width, (void)buf;
  return -1;
#endif
}

int sl_io_serial_interlude(sl_output *o, int (*fn)(sl_output *, const void *, sl_diag *), const void *arg, sl_diag *d) {
  if (!o->collective) return fn(o, arg, d);
  if (o->in_step) return sl_diag_set(d, SL_EBADINPUT, "%s: step %d is still open", o->path, o->next_index);
  const char *name = o->committed ? o->path : o->tmp_path;
  int rc = 0;
  /* collective: the file complete on disk, every rank's handle gone */
  if (sl_h5_close_all(o->file) < 0) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "the file");
  o->file = -1;
  rc = sl_io_agree(o, rc);
  if (!rc && o->rank == 0) {
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    o->file = fapl >= 0 ? H5Fopen(name, H5F_ACC_RDWR, fapl) : -1;
    if (fapl >= 0) H5Pclose(fapl);
    if (o->file < 0) {
      rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot open again", "the file");
    } else {
      o->collective = 0; /* rank 0 alone, for fn's writes */
      rc = fn(o, arg, d);
      o->collective = 1;
      if (H5Fclose(o->file) < 0 && !rc) rc = sl_h5_fail(d, SL_EFAILED, o->path, "cannot close", "the file");
      o->file = -1;
    }
  }
  int all = sl_io_agree(o, rc);
  if (all && !rc) rc = sl_diag_set(d, all, "%s: rank 0 could not write into the file", o->path);
  if (rc) return rc;
  hid_t fapl = sl_io_fapl(o);
  o->file = fapl >= 0 ? H5Fopen(name, H5F_ACC_RDWR, fapl) : -1;
  if (fapl >= 0) H5Pclose(fapl);
  if (o->file < 0) return sl_h5_fail(d, SL_EFAILED, o->path, "cannot open again", "the file");
  return 0;
}
