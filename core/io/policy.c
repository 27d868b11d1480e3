/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What an output path may replace (output.h, sl_output_opts): the folders a
 * scene file may write into and the files sluice recognises as its own. */
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/io/h5util.h"

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  char *c = malloc(n);
  if (c) memcpy(c, s, n);
  return c;
}

int sl_io_is_sluice_h5(const char *path) {
  sl_h5_quiet();
  htri_t ok = H5Fis_hdf5(path);
  H5Eclear2(H5E_DEFAULT);
  if (ok <= 0) return 0;
  hid_t f;
  sl_diag d;
  if (sl_h5_open_read(path, &f, &d)) return 0;
  int yes = 0;
  char buf[64] = "";
  if (H5Aexists(f, "format") > 0 && sl_h5_read_attr_string(f, "format", buf, sizeof buf, path, "/", &d) == 0)
    yes = strncmp(buf, "sluice-output", 13) == 0;
  else if (H5Lexists(f, "provenance", H5P_DEFAULT) > 0) /* written before the format attribute */
    yes = H5Aexists_by_name(f, "provenance", "sluice_version", H5P_DEFAULT) > 0;
  H5Eclear2(H5E_DEFAULT);
  H5Fclose(f);
  return yes;
}

/* The first `len` bytes of a file (NUL-terminated), or "" when unreadable. */
static void head(const char *path, char *buf, size_t len) {
  buf[0] = 0;
  FILE *f = fopen(path, "rb");
  if (!f) return;
  size_t n = fread(buf, 1, len - 1, f);
  buf[n] = 0;
  fclose(f);
}

/* An .xmf sluice wrote: it says so, or (older ones) its first grid points at
 * h5_name's mesh. */
static int is_sluice_xmf(const char *path, const char *h5_name) {
  char buf[4096];
  head(path, buf, sizeof buf);
  if (strncmp(buf, "<?xml", 5) != 0 || !strstr(buf, "<Xdmf")) return 0;
  if (strstr(buf, "<!-- written by sluice")) return 1;
  char want[1024];
  snprintf(want, sizeof want, ">%s:/mesh/topology<", h5_name);
  return strstr(buf, want) != NULL;
}

static int is_sluice_csv(const char *path) {
  char buf[16];
  head(path, buf, sizeof buf);
  return strncmp(buf, "time [s]", 8) == 0;
}

/* Is dir (a real path) the folder base or below it? */
static int inside(const char *dir, const char *base) {
  size_t n = strlen(base);
  if (n == 1 && base[0] == '/') return 1;
  return strncmp(dir, base, n) == 0 && (dir[n] == 0 || dir[n] == '/');
}

enum { KIND_H5, KIND_XMF, KIND_CSV };

/* May `file` (one of the files the output consists of) be replaced? */
static int may_replace(const char *file, int kind, const char *h5_name, const sl_output_opts *o, sl_diag *d) {
  struct stat sb;
  if (lstat(file, &sb) != 0) {
    if (errno == ENOENT) return 0;
    return sl_diag_set(d, SL_EBADINPUT, "cannot write output '%s': %s", file, strerror(errno));
  }
  for (int i = -1; i < o->n_protect_more; ++i) {
    const char *p = i < 0 ? o->protect : o->protect_more ? o->protect_more[i] : NULL;
    struct stat pb;
    if (p && stat(p, &pb) == 0 && stat(file, &sb) == 0 && pb.st_dev == sb.st_dev && pb.st_ino == sb.st_ino)
      return sl_diag_set(d, SL_EBADINPUT,
                         "output '%s' is the scene file '%s'%s: it is never replaced (name another output file "
                         "with -o OUT.h5)",
                         file, p, i < 0 ? " itself" : ", which the scene includes");
  }
  if (lstat(file, &sb) != 0) return 0;
  if (S_ISDIR(sb.st_mode)) return sl_diag_set(d, SL_EBADINPUT, "cannot write output '%s': it is a directory", file);
  if (o->overwrite) return 0;
  if (!S_ISREG(sb.st_mode))
    return sl_diag_set(d, SL_EBADINPUT,
                       "output '%s' exists and is not a regular file (%s); refusing to replace it "
                       "(run with --overwrite to replace it)",
                       file, S_ISLNK(sb.st_mode) ? "a symbolic link" : "a device, FIFO or socket");
  int ours = kind == KIND_H5    ? sl_io_is_sluice_h5(file)
             : kind == KIND_XMF ? is_sluice_xmf(file, h5_name)
                                : is_sluice_csv(file);
  if (!ours)
    return sl_diag_set(d, SL_EBADINPUT,
                       "output '%s' exists and was not written by sluice; refusing to replace it (choose another "
                       "output file, or run with --overwrite to replace it)",
                       file);
  return 0;
}

/* The names the output consists of: OUT.h5 -> OUT.xmf, OUT_scalars.csv,
 * OUT.h5.tmp. Each malloc'ed; NULL on no memory. */
int sl_io_output_names(const char *path, char **xmf, char **csv, char **tmp) {
  size_t len = strlen(path);
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t stem = dot && dot != base ? (size_t)(dot - path) : len;
  *xmf = malloc(stem + 5);
  *csv = malloc(stem + 13);
  *tmp = malloc(len + 5);
  if (!*xmf || !*csv || !*tmp) {
    free(*xmf), free(*csv), free(*tmp);
    *xmf = *csv = *tmp = NULL;
    return SL_ENOMEM;
  }
  snprintf(*xmf, stem + 5, "%.*s.xmf", (int)stem, path);
  snprintf(*csv, stem + 13, "%.*s_scalars.csv", (int)stem, path);
  snprintf(*tmp, len + 5, "%s.tmp", path);
  return 0;
}

int sl_output_check_path(const char *path, const sl_output_opts *opts, sl_diag *d) {
  static const sl_output_opts none = {0};
  const sl_output_opts *o = opts ? opts : &none;
  if (!path || !*path) return sl_diag_set(d, SL_EBADINPUT, "output file name is empty");
  size_t len = strlen(path);
  if (path[len - 1] == '/') return sl_diag_set(d, SL_EBADINPUT, "output file '%s' names a directory", path);
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  if (strchr(base, ':'))
    return sl_diag_set(d, SL_EBADINPUT,
                       "output file '%s': the name must not contain ':' (XDMF uses it to separate file and dataset)",
                       path);

  /* A missing directory is the common mistake: say so plainly. */
  char *tmp = dup_str(path);
  if (!tmp) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  const char *dir = dirname(tmp);
  struct stat sb;
  int rc = 0;
  if (stat(dir, &sb) != 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': directory '%s' %s", path, dir,
                     errno == ENOENT ? "does not exist" : strerror(errno));
  else if (!S_ISDIR(sb.st_mode))
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': '%s' is not a directory", path, dir);
  else if (access(dir, W_OK | X_OK) != 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "cannot create output file '%s': directory '%s' is not writable", path, dir);
  if (!rc && o->from_scene) {
    /* a scene of unknown origin writes only where the user looks: its own
     * folder or the working folder (or below them) */
    char real_dir[PATH_MAX], real_scene[PATH_MAX], real_cwd[PATH_MAX];
    int in_scene =
        o->scene_dir && realpath(o->scene_dir, real_scene) && realpath(dir, real_dir) && inside(real_dir, real_scene);
    int in_cwd = getcwd(real_cwd, sizeof real_cwd) && realpath(dir, real_dir) && inside(real_dir, real_cwd);
    if (!in_scene && !in_cwd)
      rc = sl_diag_set(d, SL_EBADINPUT,
                       "[output] file = %s is outside the scene's folder%s%s and the working folder: a scene file "
                       "may write only there (name the file with -o on the command line to write elsewhere)",
                       path, o->scene_dir ? " " : "", o->scene_dir ? o->scene_dir : "");
  }
  free(tmp);
  if (rc) return rc;

  char *xmf = NULL, *csv = NULL, *tmpname = NULL;
  if (sl_io_output_names(path, &xmf, &csv, &tmpname)) return sl_diag_set(d, SL_ENOMEM, "out of memory");
  if (strcmp(xmf, path) == 0)
    rc = sl_diag_set(d, SL_EBADINPUT, "output file '%s': an .xmf name is reserved for the sidecar; use .h5", path);
  if (!rc) rc = may_replace(path, KIND_H5, base, o, d);
  if (!rc) rc = may_replace(xmf, KIND_XMF, base, o, d);
  if (!rc) rc = may_replace(csv, KIND_CSV, base, o, d);
  if (!rc) rc = may_replace(tmpname, KIND_H5, base, o, d);
  free(xmf), free(csv), free(tmpname);
  return rc;
}

void sl_output_remove(const char *path) {
  char *xmf = NULL, *csv = NULL, *tmp = NULL;
  remove(path);
  if (sl_io_output_names(path, &xmf, &csv, &tmp)) return;
  if (strcmp(xmf, path) != 0) remove(xmf);
  remove(csv);
  remove(tmp);
  free(xmf), free(csv), free(tmp);
}
