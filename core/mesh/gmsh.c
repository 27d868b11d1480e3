/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Reader for Gmsh MSH 2.2 (ASCII) and 4.1 (ASCII and binary) files (our
 * own: linking libgmsh would tie the core to Gmsh's GPL and to
 * OpenCASCADE). The formats: Gmsh reference manual, sec. 9.1 "MSH file
 * format" (Geuzaine & Remacle 2009; version 4.8).
 *
 * The file is read line by line (binary sections: as packed records) into
 * plain arrays (nodes, elements, physical names, 4.1 entities), then turned
 * into a sl_mesh_spec: nodes and elements sorted by their Gmsh tags,
 * physical groups resolved (per element in 2.2, through $Entities in 4.1),
 * cells oriented, the face and centre nodes of second-order cells passed as
 * the mesh's second-order geometry. sl_mesh_create does the rest, with
 * file:line in its diagnostics (file: byte N in a binary file). */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/mesh/mesh.h"

typedef struct g_node {
  long tag;
  double x, y, z;
  int line;
} g_node;

typedef struct g_elem {
  long tag;
  int type;    /* Gmsh element type code */
  long entity; /* elementary entity tag */
  long phys;   /* physical group tag, 0 when none */
  int line;
  const struct g_entity *multi; /* 4.1: its entity when that is in several physical groups */
  int nn;
  long nodes[9]; /* node tags, then (after mapping) node indices */
} g_elem;

typedef struct g_name {
  int dim;
  long tag;
  char *name;
  int line;
} g_name;

typedef struct g_entity {
  long tag;
  int nphys;
  long phys[2]; /* the first two physical tags (more than one is refused) */
  int line;
} g_entity;

typedef struct gmsh {
  const char *name, *text;
  size_t len, pos;
  int line;  /* number of the line last read (binary sections: -1 - the byte offset) */
  char *buf; /* that line, NUL-terminated, without the end of line */
  size_t cap;
  int version;      /* 22 or 41 */
  int binary, swap; /* a binary 4.1 file; swap: written big-endian */
  g_node *nodes;
  int n_nodes, cap_nodes;
  g_elem *el;
  int n_el, cap_el;
  g_name *names;
  int n_names, cap_names, have_names;
  g_entity *ent[4];
  int n_ent[4];
  sl_diag *d;
} gmsh;

static int err(gmsh *g, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int err(gmsh *g, int line, const char *fmt, ...) {
  char msg[1536];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (line < 0) return sl_diag_set(g->d, SL_EBADINPUT, "%s: byte %d: %s", g->name, -line - 1, msg);
  if (line == 0) return sl_diag_set(g->d, SL_EBADINPUT, "%s: %s", g->name, msg);
  return sl_diag_set(g->d, SL_EBADINPUT, "%s:%d: %s", g->name, line, msg);
}

static int oom(gmsh *g) { return sl_diag_set(g->d, SL_ENOMEM, "%s: out of memory", g->name); }

/* Grows *p (elements of `size` bytes) to hold at least `need`. */
static int grow(void **p, int *cap, int need, size_t size) {
  if (need <= *cap) return 0;
  int c = *cap ? *cap : 64;
  while (c < need) {
    if (c > 0x3fffffff / 2) return -1;
    c *= 2;
  }
  void *q = realloc(*p, (size_t)c * size);
  if (!q) return -1;
  *p = q;
  *cap = c;
  return 0;
}

/* The next line, or NULL at the end of the text. */
static const char *next_line(gmsh *g) {
  if (g->pos >= g->len) return NULL;
  size_t start = g->pos, end = start;
  while (end < g->len && g->text[end] != '\n') ++end;
  g->pos = end < g->len ? end + 1 : end;
  size_t n = end - start;
  if (n > 0 && g->text[start + n - 1] == '\r') --n;
  if (n + 1 > g->cap) {
    size_t c = g->cap ? g->cap : 256;
    while (c < n + 1) c *= 2;
    char *q = realloc(g->buf, c);
    if (!q) return NULL; /* reported as a truncated file; only under memory exhaustion */
    g->buf = q;
    g->cap = c;
  }
  memcpy(g->buf, g->text + start, n);
  g->buf[n] = '\0';
  /* An embedded NUL ends the line: binary data is caught by the number parsers. */
  if (g->binary) g->line = -1 - (int)start; /* a binary file has no useful line numbers: its byte offsets */
  else ++g->line;
  return g->buf;
}

/* A line inside `section`; at the end of the file, a truncation error. */
static int need_line(gmsh *g, const char *section, const char **out) {
  *out = next_line(g);
  if (!*out) return err(g, g->line, "unexpected end of file in %s (the file is truncated)", section);
  return 0;
}

static int is_end(char c) { return c == '\0' || isspace((unsigned char)c); }

static int get_long(const char **p, long *v) {
  char *end;
  errno = 0;
  long x = strtol(*p, &end, 10);
  if (end == *p || errno || !is_end(*end)) return -1;
  *p = end;
  *v = x;
  return 0;
}

static int get_int(const char **p, int *v) {
  long x;
  if (get_long(p, &x) || x < -0x7fffffffL || x > 0x7fffffffL) return -1;
  *v = (int)x;
  return 0;
}

static int get_double(const char **p, double *v) {
  char *end;
  errno = 0;
  double x = strtod(*p, &end);
  if (end == *p || !is_end(*end) || !isfinite(x)) return -1;
  *p = end;
  *v = x;
  return 0;
}

/* The section's closing line must follow. */
static int expect_end(gmsh *g, const char *section, const char *end) {
  const char *l;
  int rc = need_line(g, section, &l);
  if (rc) return rc;
  while (isspace((unsigned char)*l)) ++l;
  if (strncmp(l, end, strlen(end)) != 0 || !is_end(l[strlen(end)])) {
    if (l[0] == '$' || strcmp(section, "$MeshFormat") == 0)
      return err(g, g->line, "expected %s, found \"%.40s\"", end, l);
    return err(g, g->line, "expected %s, found \"%.40s\" (the counts in %s do not match its contents)", end, l,
               section);
  }
  return 0;
}

/* ---- element types ------------------------------------------------------ */

static int nodes_of_type(int type) {
  switch (type) {
    case 1:
      return 2;
    case 2:
      return 3;
    case 3:
      return 4;
    case 8:
      return 3;
    case 9:
      return 6;
    case 10:
      return 9;
    case 15:
      return 1;
    case 16:
      return 8;
  }
  return 0;
}

static int is_tri(int type) { return type == 2 || type == 9; }
static int is_quad(int type) { return type == 3 || type == 10 || type == 16; }
static int is_line(int type) { return type == 1 || type == 8; }
static int second_order(int type) { return type == 8 || type == 9 || type == 10 || type == 16; }

static const char *type_name(int type) {
  switch (type) {
    case 1:
      return "2-node line";
    case 2:
      return "3-node triangle";
    case 3:
      return "4-node quadrangle";
    case 4:
      return "4-node tetrahedron";
    case 5:
      return "8-node hexahedron";
    case 6:
      return "6-node prism";
    case 7:
      return "5-node pyramid";
    case 8:
      return "3-node line";
    case 9:
      return "6-node triangle";
    case 10:
      return "9-node quadrangle";
    case 11:
      return "10-node tetrahedron";
    case 15:
      return "point";
    case 16:
      return "8-node quadrangle";
    case 21:
      return "10-node triangle";
  }
  return "unknown type";
}

static int unsupported_type(gmsh *g, int line, long tag, int type) {
  int solid = type == 4 || type == 5 || type == 6 || type == 7 || type == 11 || (type >= 12 && type <= 14) ||
              (type >= 17 && type <= 19);
  return err(g, line,
             "element %ld has type %d (%s), which is not supported%s; supported types: 1 (2-node line), "
             "2 (3-node triangle), 3 (4-node quadrangle), 8 (3-node line), 9 (6-node triangle), 10 (9-node "
             "quadrangle), 16 (8-node quadrangle), 15 (point, ignored)%s",
             tag, type, type_name(type), solid ? ": 3-D meshes are not supported" : "",
             solid ? "" : "; generate a mesh of order 1 or 2 (gmsh -order 2)");
}

/* ---- sections ----------------------------------------------------------- */

static int read_format(gmsh *g) {
  const char *l;
  int rc = need_line(g, "$MeshFormat", &l);
  if (rc) return rc;
  const int line = g->line;
  char version[32] = "";
  int file_type = -1, data_size = 0;
  if (sscanf(l, "%31s %d %d", version, &file_type, &data_size) != 3)
    return err(g, line, "malformed $MeshFormat line \"%.40s\" (expected: version file-type data-size)", l);
  if (strcmp(version, "2.2") == 0) g->version = 22;
  else if (strcmp(version, "4.1") == 0) g->version = 41;
  else
    return err(g, line,
               "MSH format version %s is not supported; sluice reads ASCII MSH 2.2 and 4.1 "
               "(write with gmsh -format msh41 or -format msh22)",
               version);
  if (file_type != 0 && file_type != 1)
    return err(g, line, "file type %d in $MeshFormat: 0 (ASCII) or 1 (binary) expected", file_type);
  if (file_type == 1) {
    if (g->version != 41)
      return err(g, line,
                 "binary MSH 2.2 files are not supported; sluice reads binary MSH 4.1 and ASCII 2.2 and 4.1 "
                 "(write with -format msh41)");
    if (data_size != 8)
      return err(g, line, "data size %d in $MeshFormat: binary files with 8-byte sizes are supported", data_size);
    /* the integer 1 in the writer's byte order, then the end of the line */
    if (g->len - g->pos < 4) return err(g, line, "unexpected end of file in $MeshFormat (the file is truncated)");
    const unsigned char *b = (const unsigned char *)g->text + g->pos;
    uint32_t le = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
    uint32_t be = (uint32_t)b[3] | (uint32_t)b[2] << 8 | (uint32_t)b[1] << 16 | (uint32_t)b[0] << 24;
    if (le != 1 && be != 1) return err(g, line, "binary $MeshFormat: the byte-order mark is not the integer 1");
    g->swap = le != 1; /* the file is big-endian */
    g->binary = 1;
    g->pos += 4;
    if (g->pos < g->len && g->text[g->pos] == '\n') ++g->pos;
  }
  return expect_end(g, "$MeshFormat", "$EndMeshFormat");
}

static int read_physical_names(gmsh *g) {
  const char *l;
  int rc = need_line(g, "$PhysicalNames", &l);
  if (rc) return rc;
  long n;
  if (get_long(&l, &n) || n < 0) return err(g, g->line, "malformed number of physical names");
  if (n > 10000) return err(g, g->line, "%ld physical names: at most 10000 are supported", n);
  g->have_names = 1;
  for (long i = 0; i < n; ++i) {
    if ((rc = need_line(g, "$PhysicalNames", &l))) return rc;
    int dim;
    long tag;
    if (get_int(&l, &dim) || get_long(&l, &tag))
      return err(g, g->line, "malformed physical name (expected: dimension tag \"name\")");
    const char *q = strchr(l, '"'), *e = q ? strchr(q + 1, '"') : NULL;
    if (!q || !e || e == q + 1)
      return err(g, g->line, "malformed physical name (expected: dimension tag \"name\", with a non-empty name)");
    if (dim < 0 || dim > 3) return err(g, g->line, "physical group dimension %d outside 0..3", dim);
    for (int j = 0; j < g->n_names; ++j)
      if (g->names[j].dim == dim && g->names[j].tag == tag)
        return err(g, g->line, "physical group %ld of dimension %d is named twice (first on line %d)", tag, dim,
                   g->names[j].line);
    if (grow((void **)&g->names, &g->cap_names, g->n_names + 1, sizeof *g->names)) return oom(g);
    g_name *nm = g->names + g->n_names;
    size_t len = (size_t)(e - q - 1);
    /* the name a scene addresses ("left wall" -> left_wall, sl_mesh_scene_name) */
    char *raw = malloc(len + 1);
    if (!raw || !(nm->name = malloc(len + 1))) return free(raw), oom(g);
    memcpy(raw, q + 1, len);
    raw[len] = '\0';
    sl_mesh_scene_name(raw, nm->name, len + 1);
    for (int j = 0; j < g->n_names; ++j)
      if (g->names[j].dim == dim && strcmp(g->names[j].name, nm->name) == 0) {
        int rc2 = err(g, g->line,
                      "physical name \"%s\" is addressed in a scene as %s, and so is the name of physical group %ld "
                      "(line %d): rename one (a scene addresses a name with every character other than a letter, "
                      "digit, '_', '-' or '.' written as '_')",
                      raw, nm->name, g->names[j].tag, g->names[j].line);
        free(raw), free(nm->name);
        return rc2;
      }
    free(raw);
    nm->dim = dim;
    nm->tag = tag;
    nm->line = g->line;
    ++g->n_names;
  }
  return expect_end(g, "$PhysicalNames", "$EndPhysicalNames");
}

static int read_entities(gmsh *g) {
  const char *l;
  if (g->ent[0] || g->ent[1] || g->ent[2] || g->ent[3]) return err(g, g->line, "a second $Entities section");
  int rc = need_line(g, "$Entities", &l);
  if (rc) return rc;
  long count[4];
  for (int k = 0; k < 4; ++k)
    if (get_long(&l, &count[k]) || count[k] < 0 || count[k] > (long)(g->len - g->pos))
      return err(g, g->line,
                 "malformed $Entities header (expected: numPoints numCurves numSurfaces numVolumes, each at most "
                 "the number of lines that follow)");
  for (int dim = 0; dim < 4; ++dim) {
    if (count[dim] > 0 && !(g->ent[dim] = calloc((size_t)count[dim], sizeof *g->ent[dim]))) return oom(g);
    for (long i = 0; i < count[dim]; ++i) {
      if ((rc = need_line(g, "$Entities", &l))) return rc;
      g_entity *e = g->ent[dim] + i;
      double box;
      long np;
      int ok = get_long(&l, &e->tag) == 0;
      for (int k = 0; ok && k < (dim == 0 ? 3 : 6); ++k) ok = get_double(&l, &box) == 0;
      ok = ok && get_long(&l, &np) == 0 && np >= 0;
      for (long k = 0; ok && k < np; ++k) {
        long t;
        ok = get_long(&l, &t) == 0;
        if (ok && k < 2) e->phys[k] = labs(t); /* a negative tag only flips the orientation */
      }
      if (!ok) return err(g, g->line, "malformed entity of dimension %d in $Entities", dim);
      e->nphys = (int)(np > 1000000 ? 1000000 : np);
      e->line = g->line;
      g->n_ent[dim] = (int)i + 1;
    }
  }
  return expect_end(g, "$Entities", "$EndEntities");
}

static g_node *add_node(gmsh *g) {
  if (grow((void **)&g->nodes, &g->cap_nodes, g->n_nodes + 1, sizeof *g->nodes)) return NULL;
  return g->nodes + g->n_nodes++;
}

static int read_nodes(gmsh *g) {
  const char *l;
  int rc = need_line(g, "$Nodes", &l);
  if (rc) return rc;
  if (g->version == 22) {
    long n;
    if (get_long(&l, &n) || n < 0) return err(g, g->line, "malformed number of nodes");
    for (long i = 0; i < n; ++i) {
      if ((rc = need_line(g, "$Nodes", &l))) return rc;
      g_node *p = add_node(g);
      if (!p) return oom(g);
      if (get_long(&l, &p->tag) || get_double(&l, &p->x) || get_double(&l, &p->y) || get_double(&l, &p->z))
        return err(g, g->line, "malformed node (expected: tag x y z)");
      p->line = g->line;
    }
    return expect_end(g, "$Nodes", "$EndNodes");
  }
  long blocks, total, mintag, maxtag;
  if (get_long(&l, &blocks) || get_long(&l, &total) || get_long(&l, &mintag) || get_long(&l, &maxtag) || blocks < 0 ||
      total < 0)
    return err(g, g->line, "malformed $Nodes header (expected: numEntityBlocks numNodes minNodeTag maxNodeTag)");
  long seen = 0;
  for (long b = 0; b < blocks; ++b) {
    if ((rc = need_line(g, "$Nodes", &l))) return rc;
    int edim, param;
    long etag, n;
    if (get_int(&l, &edim) || get_long(&l, &etag) || get_int(&l, &param) || get_long(&l, &n) || n < 0)
      return err(g, g->line, "malformed node block header (expected: entityDim entityTag parametric numNodesInBlock)");
    int first = g->n_nodes;
    for (long i = 0; i < n; ++i) { /* the tags, then the coordinates */
      if ((rc = need_line(g, "$Nodes", &l))) return rc;
      g_node *p = add_node(g);
      if (!p) return oom(g);
      if (get_long(&l, &p->tag)) return err(g, g->line, "malformed node tag");
    }
    for (long i = 0; i < n; ++i) {
      if ((rc = need_line(g, "$Nodes", &l))) return rc;
      g_node *p = g->nodes + first + i;
      /* Parametric nodes carry u (v) after x y z: ignored. */
      if (get_double(&l, &p->x) || get_double(&l, &p->y) || get_double(&l, &p->z))
        return err(g, g->line, "malformed node coordinates (expected: x y z)");
      p->line = g->line;
    }
    seen += n;
  }
  if (seen != total) return err(g, g->line, "$Nodes announces %ld nodes but its blocks hold %ld", total, seen);
  return expect_end(g, "$Nodes", "$EndNodes");
}

/* Reads the node tags of an element of a supported type from *l. */
static int read_element_nodes(gmsh *g, const char **l, g_elem *e) {
  e->nn = nodes_of_type(e->type);
  for (int k = 0; k < e->nn; ++k)
    if (get_long(l, &e->nodes[k]))
      return err(g, g->line, "element %ld (%s) needs %d node tags, found %d", e->tag, type_name(e->type), e->nn, k);
  return 0;
}

static g_elem *add_elem(gmsh *g) {
  if (grow((void **)&g->el, &g->cap_el, g->n_el + 1, sizeof *g->el)) return NULL;
  g_elem *e = g->el + g->n_el++;
  memset(e, 0, sizeof *e);
  return e;
}

static int read_elements(gmsh *g) {
  const char *l;
  int rc = need_line(g, "$Elements", &l);
  if (rc) return rc;
  if (g->version == 22) {
    long n;
    if (get_long(&l, &n) || n < 0) return err(g, g->line, "malformed number of elements");
    for (long i = 0; i < n; ++i) {
      if ((rc = need_line(g, "$Elements", &l))) return rc;
      g_elem *e = add_elem(g);
      if (!e) return oom(g);
      int ntags;
      e->line = g->line;
      if (get_long(&l, &e->tag) || get_int(&l, &e->type) || get_int(&l, &ntags) || ntags < 0)
        return err(g, g->line, "malformed element (expected: tag type numTags tags... nodes...)");
      for (int k = 0; k < ntags; ++k) {
        long t;
        if (get_long(&l, &t)) return err(g, g->line, "element %ld announces %d tags but has fewer", e->tag, ntags);
        if (k == 0) e->phys = t;
        if (k == 1) e->entity = t;
      }
      if (!nodes_of_type(e->type)) return unsupported_type(g, g->line, e->tag, e->type);
      if ((rc = read_element_nodes(g, &l, e))) return rc;
    }
    return expect_end(g, "$Elements", "$EndElements");
  }
  long blocks, total, mintag, maxtag;
  if (get_long(&l, &blocks) || get_long(&l, &total) || get_long(&l, &mintag) || get_long(&l, &maxtag) || blocks < 0 ||
      total < 0)
    return err(g, g->line,
               "malformed $Elements header (expected: numEntityBlocks numElements minElementTag maxElementTag)");
  long seen = 0;
  for (long b = 0; b < blocks; ++b) {
    if ((rc = need_line(g, "$Elements", &l))) return rc;
    int edim, type;
    long etag, n;
    if (get_int(&l, &edim) || get_long(&l, &etag) || get_int(&l, &type) || get_long(&l, &n) || n < 0 || edim < 0 ||
        edim > 3)
      return err(g, g->line,
                 "malformed element block header (expected: entityDim entityTag elementType numElementsInBlock)");
    /* Physical membership lives on the entity (4.1). */
    const g_entity *ent = NULL;
    for (int k = 0; k < g->n_ent[edim]; ++k)
      if (g->ent[edim][k].tag == etag) ent = g->ent[edim] + k;
    int header = g->line;
    for (long i = 0; i < n; ++i) {
      if ((rc = need_line(g, "$Elements", &l))) return rc;
      g_elem *e = add_elem(g);
      if (!e) return oom(g);
      e->line = g->line;
      e->type = type;
      e->entity = etag;
      if (get_long(&l, &e->tag)) return err(g, g->line, "malformed element tag");
      if (!nodes_of_type(type)) return unsupported_type(g, header, e->tag, type);
      if ((rc = read_element_nodes(g, &l, e))) return rc;
      e->phys = ent && ent->nphys > 0 ? ent->phys[0] : 0;
      if (ent && ent->nphys > 1) e->multi = ent; /* refused in build() if the element is used */
    }
    seen += n;
  }
  if (seen != total) return err(g, g->line, "$Elements announces %ld elements but its blocks hold %ld", total, seen);
  return expect_end(g, "$Elements", "$EndElements");
}

/* ---- binary MSH 4.1 sections --------------------------------------------- */

/* n bytes at the cursor, or a truncation error naming the section. */
static int b_bytes(gmsh *g, size_t n, const char *section, const unsigned char **p) {
  *p = NULL;
  if (n > g->len - g->pos)
    return err(g, -1 - (int)g->pos, "unexpected end of file in %s (the file is truncated)", section);
  *p = (const unsigned char *)g->text + g->pos;
  g->pos += n;
  return 0;
}

static uint64_t b_decode(const gmsh *g, const unsigned char *p, int n) {
  uint64_t v = 0;
  for (int k = 0; k < n; ++k) v |= (uint64_t)p[g->swap ? n - 1 - k : k] << (8 * k);
  return v;
}

static int b_int(gmsh *g, const char *section, long *v) {
  const unsigned char *p = NULL;
  int rc = b_bytes(g, 4, section, &p);
  if (rc) return rc;
  *v = (long)(int32_t)(uint32_t)b_decode(g, p, 4);
  return 0;
}

/* A size_t count or tag (8 bytes); at most `max` (the bytes left bound every count). */
static int b_size(gmsh *g, const char *section, const char *what, long max, long *v) {
  const unsigned char *p = NULL;
  int at = -1 - (int)g->pos, rc = b_bytes(g, 8, section, &p);
  if (rc) return rc;
  uint64_t x = b_decode(g, p, 8);
  if (x > (uint64_t)max) return err(g, at, "%s %llu in %s is out of range", what, (unsigned long long)x, section);
  *v = (long)x;
  return 0;
}

static int b_double(gmsh *g, const char *section, double *v) {
  const unsigned char *p = NULL;
  int at = -1 - (int)g->pos, rc = b_bytes(g, 8, section, &p);
  if (rc) return rc;
  uint64_t x = b_decode(g, p, 8);
  memcpy(v, &x, sizeof *v);
  if (!isfinite(*v)) return err(g, at, "a coordinate in %s is not a finite number", section);
  return 0;
}

/* The newline after the binary data, then the closing line. */
static int b_end(gmsh *g, const char *section, const char *end) {
  if (g->pos < g->len && g->text[g->pos] == '\n') ++g->pos;
  return expect_end(g, section, end);
}

static long b_left(const gmsh *g) { return (long)(g->len - g->pos); }

static int read_entities_bin(gmsh *g) {
  const char *S = "$Entities";
  if (g->ent[0] || g->ent[1] || g->ent[2] || g->ent[3]) return err(g, g->line, "a second $Entities section");
  long count[4];
  int rc;
  for (int k = 0; k < 4; ++k)
    if ((rc = b_size(g, S, "an entity count", b_left(g) / 4, &count[k]))) return rc;
  for (int dim = 0; dim < 4; ++dim) {
    if (count[dim] > 0 && !(g->ent[dim] = calloc((size_t)count[dim], sizeof *g->ent[dim]))) return oom(g);
    for (long i = 0; i < count[dim]; ++i) {
      g_entity *e = g->ent[dim] + i;
      e->line = -1 - (int)g->pos;
      long np, t;
      double box;
      if ((rc = b_int(g, S, &e->tag))) return rc;
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
        if ((rc = b_double(g, S, &box))) return rc;
      if ((rc = b_size(g, S, "a number of physical tags", b_left(g) / 4, &np))) return rc;
      for (long k = 0; k < np; ++k) {
        if ((rc = b_int(g, S, &t))) return rc;
        if (k < 2) e->phys[k] = labs(t);
      }
      e->nphys = (int)(np > 1000000 ? 1000000 : np);
      if (dim > 0) { /* the bounding entities: not needed */
        long nb;
        const unsigned char *p;
        if ((rc = b_size(g, S, "a number of bounding entities", b_left(g) / 4, &nb))) return rc;
        if ((rc = b_bytes(g, 4 * (size_t)nb, S, &p))) return rc;
      }
      g->n_ent[dim] = (int)i + 1;
    }
  }
  return b_end(g, S, "$EndEntities");
}

static int read_nodes_bin(gmsh *g) {
  const char *S = "$Nodes";
  long blocks, total, lo, hi, seen = 0;
  int rc;
  if ((rc = b_size(g, S, "the number of node blocks", b_left(g) / 20, &blocks)) ||
      (rc = b_size(g, S, "the number of nodes", b_left(g) / 32, &total)) ||
      (rc = b_size(g, S, "the smallest node tag", LONG_MAX, &lo)) ||
      (rc = b_size(g, S, "the largest node tag", LONG_MAX, &hi)))
    return rc;
  for (long b = 0; b < blocks; ++b) {
    long edim, etag, param, n;
    if ((rc = b_int(g, S, &edim)) || (rc = b_int(g, S, &etag)) || (rc = b_int(g, S, &param)) ||
        (rc = b_size(g, S, "the number of nodes in a block", b_left(g) / 32, &n)))
      return rc;
    if (edim < 0 || edim > 3) return err(g, g->line, "node block %ld: entity dimension %ld outside 0..3", b, edim);
    int first = g->n_nodes;
    for (long i = 0; i < n; ++i) {
      g_node *p = add_node(g);
      if (!p) return oom(g);
      p->line = -1 - (int)g->pos;
      if ((rc = b_size(g, S, "a node tag", LONG_MAX, &p->tag))) return rc;
    }
    int stride = 3 + (param ? (int)edim : 0); /* parametric nodes carry u (v) after x y z: ignored */
    for (long i = 0; i < n; ++i) {
      g_node *p = g->nodes + first + i;
      double uv;
      if ((rc = b_double(g, S, &p->x)) || (rc = b_double(g, S, &p->y)) || (rc = b_double(g, S, &p->z))) return rc;
      for (int k = 3; k < stride; ++k)
        if ((rc = b_double(g, S, &uv))) return rc;
    }
    seen += n;
  }
  if (seen != total) return err(g, -1 - (int)g->pos, "$Nodes announces %ld nodes but its blocks hold %ld", total, seen);
  return b_end(g, S, "$EndNodes");
}

static int read_elements_bin(gmsh *g) {
  const char *S = "$Elements";
  long blocks, total, lo, hi, seen = 0;
  int rc;
  if ((rc = b_size(g, S, "the number of element blocks", b_left(g) / 20, &blocks)) ||
      (rc = b_size(g, S, "the number of elements", b_left(g) / 16, &total)) ||
      (rc = b_size(g, S, "the smallest element tag", LONG_MAX, &lo)) ||
      (rc = b_size(g, S, "the largest element tag", LONG_MAX, &hi)))
    return rc;
  for (long b = 0; b < blocks; ++b) {
    long edim, etag, type, n;
    int header = -1 - (int)g->pos;
    if ((rc = b_int(g, S, &edim)) || (rc = b_int(g, S, &etag)) || (rc = b_int(g, S, &type)) ||
        (rc = b_size(g, S, "the number of elements in a block", b_left(g) / 16, &n)))
      return rc;
    if (edim < 0 || edim > 3) return err(g, header, "element block %ld: entity dimension %ld outside 0..3", b, edim);
    const g_entity *ent = NULL;
    for (int k = 0; k < g->n_ent[edim]; ++k)
      if (g->ent[edim][k].tag == etag) ent = g->ent[edim] + k;
    int nn = nodes_of_type((int)type);
    if (!nn) {
      long tag = 0;
      if (n > 0 && (rc = b_size(g, S, "an element tag", LONG_MAX, &tag))) return rc;
      return unsupported_type(g, header, tag, (int)type);
    }
    for (long i = 0; i < n; ++i) {
      g_elem *e = add_elem(g);
      if (!e) return oom(g);
      e->line = -1 - (int)g->pos;
      e->type = (int)type;
      e->entity = etag;
      e->nn = nn;
      if ((rc = b_size(g, S, "an element tag", LONG_MAX, &e->tag))) return rc;
      for (int k = 0; k < nn; ++k)
        if ((rc = b_size(g, S, "a node tag", LONG_MAX, &e->nodes[k]))) return rc;
      e->phys = ent && ent->nphys > 0 ? ent->phys[0] : 0;
      if (ent && ent->nphys > 1) e->multi = ent;
    }
    seen += n;
  }
  if (seen != total)
    return err(g, -1 - (int)g->pos, "$Elements announces %ld elements but its blocks hold %ld", total, seen);
  return b_end(g, S, "$EndElements");
}

/* Skips an unknown section up to its $End line. */
static int skip_section(gmsh *g, const char *line) {
  char end[128], head[104];
  snprintf(head, sizeof head, "%.100s", line); /* line is the line buffer, which the next line may move */
  snprintf(end, sizeof end, "$End%.100s", head + 1);
  size_t n = strcspn(end, " \t");
  end[n] = '\0';
  int start = g->line;
  const char *l;
  while ((l = next_line(g)))
    if (strncmp(l, end, n) == 0 && is_end(l[n])) return 0;
  if (start < 0)
    return err(g, g->line, "unexpected end of file: section %.100s opened at byte %d has no %s", head, -start - 1, end);
  return err(g, g->line, "unexpected end of file: section %.100s opened on line %d has no %s", head, start, end);
}

static int parse(gmsh *g) {
  const char *l;
  int rc, have_format = 0, nodes_line = 0, elements_line = 0;
  while ((l = next_line(g))) {
    while (isspace((unsigned char)*l)) ++l;
    if (!*l) continue;
    if (!have_format && strncmp(l, "$MeshFormat", 11) != 0)
      return err(g, g->line, "not a Gmsh MSH file: expected $MeshFormat, found \"%.40s\"", l);
    if (strncmp(l, "$MeshFormat", 11) == 0 && is_end(l[11])) {
      if (have_format) return err(g, g->line, "a second $MeshFormat section");
      if ((rc = read_format(g))) return rc;
      have_format = 1;
    } else if (strncmp(l, "$PhysicalNames", 14) == 0 && is_end(l[14])) {
      if ((rc = read_physical_names(g))) return rc;
    } else if (strncmp(l, "$Entities", 9) == 0 && is_end(l[9]) && g->version == 41) {
      if ((rc = g->binary ? read_entities_bin(g) : read_entities(g))) return rc;
    } else if (strncmp(l, "$Nodes", 6) == 0 && is_end(l[6])) {
      if (nodes_line) return err(g, g->line, "a second $Nodes section (the first is on line %d)", nodes_line);
      nodes_line = g->line;
      if ((rc = g->binary ? read_nodes_bin(g) : read_nodes(g))) return rc;
    } else if (strncmp(l, "$Elements", 9) == 0 && is_end(l[9])) {
      if (elements_line) return err(g, g->line, "a second $Elements section (the first is on line %d)", elements_line);
      elements_line = g->line;
      if ((rc = g->binary ? read_elements_bin(g) : read_elements(g))) return rc;
    } else if (strncmp(l, "$End", 4) == 0) {
      return err(g, g->line, "%.40s without a matching section start", l);
    } else if (l[0] == '$') {
      if ((rc = skip_section(g, l))) return rc;
    } else {
      return err(g, g->line, "expected a section header ($Name), found \"%.40s\"", l);
    }
  }
  if (!have_format) return err(g, g->line, "empty file: not a Gmsh MSH file");
  if (!nodes_line) return err(g, g->line, "unexpected end of file: no $Nodes section");
  if (!elements_line) return err(g, g->line, "unexpected end of file: no $Elements section");
  return 0;
}

/* ---- building the mesh -------------------------------------------------- */

static int cmp_node(const void *a, const void *b) {
  long x = ((const g_node *)a)->tag, y = ((const g_node *)b)->tag;
  return (x > y) - (x < y);
}

static int cmp_elem_ptr(const void *a, const void *b) {
  const g_elem *x = *(const g_elem *const *)a, *y = *(const g_elem *const *)b;
  if (x->tag != y->tag) return (x->tag > y->tag) - (x->tag < y->tag);
  return (x->line > y->line) - (x->line < y->line);
}

static long find_node(const gmsh *g, long tag) {
  long a = 0, b = g->n_nodes;
  while (a < b) {
    long m = a + (b - a) / 2;
    if (g->nodes[m].tag < tag) a = m + 1;
    else b = m;
  }
  return a < g->n_nodes && g->nodes[a].tag == tag ? a : -1;
}

/* Index of the named group (dim, tag) among the names of that dimension. */
static int group_index(const gmsh *g, int dim, long tag) {
  int k = 0;
  for (int i = 0; i < g->n_names; ++i) {
    if (g->names[i].dim != dim) continue;
    if (g->names[i].tag == tag) return k;
    ++k;
  }
  return -1;
}

/* A physical tag must have a name in $PhysicalNames; errors point at the element. */
static int resolve_group(gmsh *g, const g_elem *e, int dim, int *index) {
  *index = group_index(g, dim, e->phys);
  if (*index < 0)
    return err(g, e->line, "element %ld is in physical group %ld of dimension %d, which has no name in $PhysicalNames",
               e->tag, e->phys, dim);
  return 0;
}

static int build(gmsh *g, const sl_gmsh_opts *opts, sl_mesh **out) {
  int rc = 0, dim = 0, cell_type = 0, first_cell_line = 0;
  /* Dimension and cell type from the elements present. */
  for (int i = 0; i < g->n_el; ++i)
    if (is_tri(g->el[i].type) || is_quad(g->el[i].type)) dim = 2;
  if (!dim)
    for (int i = 0; i < g->n_el; ++i)
      if (is_line(g->el[i].type)) dim = 1;
  if (!dim) return err(g, g->line, "the mesh has no cells (no lines, triangles or quadrangles in $Elements)");

  g_elem **cells = NULL, **sides = NULL;
  int n_cells = 0, n_sides = 0;
  double *xy = NULL, *emid = NULL, *centre = NULL;
  int *cv = NULL, *cell_line = NULL, *cell_region = NULL, *sv = NULL, *side_tag = NULL, *side_line = NULL;
  long *vmap = NULL;
  const char **bnames = NULL, **rnames = NULL;
  int n_bnames = 0, n_rnames = 0;

  cells = malloc((size_t)g->n_el * sizeof *cells);
  sides = malloc((size_t)g->n_el * sizeof *sides);
  if (!cells || !sides) {
    rc = oom(g);
    goto done;
  }
  for (int i = 0; i < g->n_el; ++i) {
    g_elem *e = g->el + i;
    int is_cell = dim == 2 ? (is_tri(e->type) || is_quad(e->type)) : is_line(e->type);
    int is_side = dim == 2 ? is_line(e->type) : e->type == 15;
    if ((is_cell || is_side) && e->phys != 0 && !g->have_names) {
      rc = err(g, e->line,
               "element %ld is in physical group %ld but the file has no $PhysicalNames section: boundaries and "
               "regions need names (in the .geo: Physical %s(\"name\") = {...})",
               e->tag, e->phys,
               e->type == 15      ? "Point"
               : is_line(e->type) ? "Curve"
                                  : "Surface");
      goto done;
    }
    if ((is_cell || is_side) && e->multi) {
      const g_entity *ent = e->multi;
      rc = err(g, ent->line,
               "%s %ld is in %d physical groups (tags %ld, %ld%s); each boundary %s or cell %s may be in only one",
               dim == 2 ? (is_cell ? "surface" : "curve") : (is_cell ? "curve" : "point"), e->entity, ent->nphys,
               ent->phys[0], ent->phys[1], ent->nphys > 2 ? ", ..." : "", dim == 2 ? "curve" : "point",
               dim == 2 ? "surface" : "curve");
      goto done;
    }
    if (is_cell) {
      if (!cell_type) {
        cell_type = e->type;
        first_cell_line = e->line;
      } else if (dim == 2 && is_tri(e->type) != is_tri(cell_type) && !opts->split_quads) {
        char where_first[64];
        if (first_cell_line < 0) snprintf(where_first, sizeof where_first, "byte %d", -first_cell_line - 1);
        else snprintf(where_first, sizeof where_first, "line %d", first_cell_line);
        rc = err(g, e->line,
                 "element %ld is a %s but the cells before it are %ss (%s): a mesh of both triangles and "
                 "quadrangles is not supported (sluice's meshes have one cell type, and its Taylor-Hood pairs are "
                 "P2/P1 on triangles or Q2/Q1 on quadrangles); set [mesh] split_quads = true to split each "
                 "quadrangle into two triangles, or make all cells quadrangles (Mesh.RecombineAll = 1; "
                 "Mesh.SubdivisionAlgorithm = 1 subdivides what does not recombine) or all triangles (no Recombine)",
                 e->tag, type_name(e->type), type_name(cell_type), where_first);
        goto done;
      }
      cells[n_cells++] = e;
    } else if (is_side) {
      if (e->phys == 0) {
        if (dim == 1) continue; /* untagged points: only physical points name boundaries */
        rc = err(g, e->line,
                 "line element %ld is in no physical group: every boundary curve must be in a named physical "
                 "group (Physical Curve(\"name\") = {...})%s",
                 e->tag, g->version == 22 ? "; MSH 2.2 files written with -save_all lose all physical tags" : "");
        goto done;
      }
      sides[n_sides++] = e;
    }
    /* Anything else (points in 2-D) is ignored. */
  }

  /* Sorting by tag makes 2.2 and 4.1 files of one mesh agree; 2.2 repeats an
   * element once per physical group, which we refuse like 4.1's entities. */
  qsort(cells, (size_t)n_cells, sizeof *cells, cmp_elem_ptr);
  qsort(sides, (size_t)n_sides, sizeof *sides, cmp_elem_ptr);
  for (int pass = 0; pass < 2; ++pass) {
    g_elem **list = pass ? sides : cells;
    int n = pass ? n_sides : n_cells;
    for (int i = 0; i < n; ++i) {
      if (i > 0 && list[i]->tag == list[i - 1]->tag) {
        rc = err(g, list[i]->line, "element tag %ld is used twice (also on line %d)", list[i]->tag, list[i - 1]->line);
        goto done;
      }
    }
  }
  if (g->version == 22) /* duplicates come one after the other in the file */
    for (int i = 1; i < g->n_el; ++i) {
      const g_elem *a = g->el + i - 1, *b = g->el + i;
      if (a->type == b->type && a->entity == b->entity && a->type != 15 &&
          memcmp(a->nodes, b->nodes, sizeof a->nodes) == 0) {
        rc = err(g, b->line,
                 "element %ld repeats element %ld (line %d) with physical group %ld besides %ld: each boundary curve "
                 "or cell surface may be in only one physical group",
                 b->tag, a->tag, a->line, b->phys, a->phys);
        goto done;
      }
    }

  /* Nodes by tag; then vertex numbers for the corner nodes of the cells. */
  /* split_quads: every quadrangle becomes two triangles (split in the cell loop below) */
  int n_quads = 0, curved = 0;
  for (int c = 0; c < n_cells && dim == 2; ++c)
    curved |= second_order(cells[c]->type), n_quads += is_quad(cells[c]->type);
  const int split = dim == 2 && opts->split_quads && n_quads > 0;
  const int nvc = dim == 2 ? (split || is_tri(cell_type) ? 3 : 4) : 2, per_side = dim == 2 ? 2 : 1;
  const int n_out = n_cells + (split ? n_quads : 0);
  qsort(g->nodes, (size_t)g->n_nodes, sizeof *g->nodes, cmp_node);
  for (int i = 1; i < g->n_nodes; ++i)
    if (g->nodes[i].tag == g->nodes[i - 1].tag) {
      int l1 = g->nodes[i].line, l0 = g->nodes[i - 1].line;
      rc =
          err(g, l1 > l0 ? l1 : l0, "node tag %ld is used twice (also on line %d)", g->nodes[i].tag, l1 > l0 ? l0 : l1);
      goto done;
    }
  vmap = malloc(((size_t)g->n_nodes + 1) * sizeof *vmap);
  if (!vmap) {
    rc = oom(g);
    goto done;
  }
  for (int i = 0; i < g->n_nodes; ++i) vmap[i] = -1;
  for (int pass = 0; pass < 2; ++pass) {
    g_elem **list = pass ? sides : cells;
    int n = pass ? n_sides : n_cells;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < list[i]->nn; ++k) {
        long idx = find_node(g, list[i]->nodes[k]);
        if (idx < 0) {
          rc = err(g, list[i]->line, "element %ld refers to node %ld, which is not in $Nodes", list[i]->tag,
                   list[i]->nodes[k]);
          goto done;
        }
        list[i]->nodes[k] = idx;
        /* the corners are the vertices; face and centre nodes are not */
        if (!pass && k < (dim == 1 ? 2 : is_tri(list[i]->type) ? 3 : 4)) vmap[idx] = 0;
      }
  }
  int nv = 0;
  for (int i = 0; i < g->n_nodes; ++i)
    if (vmap[i] == 0) vmap[i] = nv++;
  for (int i = 0; i < n_sides; ++i)
    for (int k = 0; k < per_side; ++k)
      if (vmap[sides[i]->nodes[k]] < 0) {
        rc = err(g, sides[i]->line,
                 "%s element %ld (physical group %ld) is not on any cell: node %ld is a vertex of no cell",
                 dim == 2 ? "line" : "point", sides[i]->tag, sides[i]->phys, g->nodes[sides[i]->nodes[k]].tag);
        goto done;
      }

  /* Coordinates: planar meshes only (constant z); 1-D on the x axis. */
  xy = malloc(2 * ((size_t)nv + 1) * sizeof *xy);
  if (!xy) {
    rc = oom(g);
    goto done;
  }
  double scale = 0, z0 = 0;
  int have_z = 0;
  for (int i = 0; i < g->n_nodes; ++i)
    if (vmap[i] >= 0) {
      const g_node *p = g->nodes + i;
      scale = fmax(scale, fmax(fabs(p->x), fmax(fabs(p->y), fabs(p->z))));
      if (!have_z) z0 = p->z, have_z = 1;
    }
  for (int i = 0; i < g->n_nodes; ++i) {
    if (vmap[i] < 0) continue;
    const g_node *p = g->nodes + i;
    if (fabs(p->z - z0) > 1e-10 * scale) {
      rc = err(g, p->line, "node %ld has z = %g but others z = %g: only planar meshes (constant z) are supported",
               p->tag, p->z, z0);
      goto done;
    }
    double y = p->y;
    if (dim == 1) {
      if (fabs(y) > 1e-12 * scale) {
        rc = err(g, p->line, "node %ld has y = %g: a 1-D mesh must lie on the x axis", p->tag, y);
        goto done;
      }
      y = 0;
    }
    xy[2 * vmap[i]] = p->x;
    xy[2 * vmap[i] + 1] = y;
  }

  /* Names of the groups of each role, in $PhysicalNames order. */
  bnames = malloc(((size_t)g->n_names + 1) * sizeof *bnames);
  rnames = malloc(((size_t)g->n_names + 1) * sizeof *rnames);
  if (!bnames || !rnames) {
    rc = oom(g);
    goto done;
  }
  for (int i = 0; i < g->n_names; ++i) {
    if (g->names[i].dim == dim - 1) bnames[n_bnames++] = g->names[i].name;
    if (g->names[i].dim == dim) rnames[n_rnames++] = g->names[i].name;
  }

  cv = malloc((size_t)n_out * nvc * sizeof *cv);
  cell_line = malloc((size_t)n_out * sizeof *cell_line);
  cell_region = malloc((size_t)n_out * sizeof *cell_region);
  if (curved) {
    emid = malloc(2 * (size_t)n_out * nvc * sizeof *emid);
    centre = malloc(2 * (size_t)n_out * sizeof *centre);
  }
  sv = malloc(2 * ((size_t)n_sides + 1) * sizeof *sv);
  side_tag = malloc(((size_t)n_sides + 1) * sizeof *side_tag);
  side_line = malloc(((size_t)n_sides + 1) * sizeof *side_line);
  if (!cv || !cell_line || !cell_region || !sv || !side_tag || !side_line || (curved && (!emid || !centre))) {
    rc = oom(g);
    goto done;
  }
  /* The cells, their face nodes (straight midpoints for first-order cells among second-order ones) and the centres
   * of quadrangles (an 8-node quad's: its serendipity map at the reference centre, -1/4 sum corners + 1/2 sum face
   * nodes; Zienkiewicz & Taylor 2000, sec. 8.5). Split quadrangles: two triangles along the shorter diagonal, whose
   * node is the quad's centre (second-order) or the diagonal's midpoint. */
  int any_region = 0, oc = 0;
  for (int c = 0; c < n_cells; ++c) {
    const g_elem *e = cells[c];
    const int nve = dim == 1 ? 2 : is_tri(e->type) ? 3 : 4;
    int v[4];
    double m[4][2] = {{0, 0}}, ce[2] = {0, 0};
    for (int k = 0; k < nve; ++k) v[k] = (int)vmap[e->nodes[k]];
    int region = -1;
    if (e->phys != 0) {
      if ((rc = resolve_group(g, e, dim, &region))) goto done;
      any_region = 1;
    }
    if (curved) {
      for (int k = 0; k < nve; ++k) {
        if (second_order(e->type)) {
          const g_node *p = g->nodes + e->nodes[nve + k];
          if (fabs(p->z - z0) > 1e-10 * scale) {
            rc = err(g, p->line, "node %ld has z = %g but others z = %g: only planar meshes (constant z) are supported",
                     p->tag, p->z, z0);
            goto done;
          }
          m[k][0] = p->x, m[k][1] = p->y;
        } else {
          const double *a = xy + 2 * v[k], *b = xy + 2 * v[(k + 1) % nve];
          m[k][0] = 0.5 * (a[0] + b[0]), m[k][1] = 0.5 * (a[1] + b[1]);
        }
      }
      if (e->type == 10) {
        ce[0] = g->nodes[e->nodes[8]].x, ce[1] = g->nodes[e->nodes[8]].y;
      } else if (nve == 4) {
        double w = e->type == 16 ? -0.25 : 0.25;
        for (int k = 0; k < 4; ++k) {
          ce[0] += w * xy[2 * v[k]], ce[1] += w * xy[2 * v[k] + 1];
          if (e->type == 16) ce[0] += 0.5 * m[k][0], ce[1] += 0.5 * m[k][1];
        }
      }
    }
    /* the output cells of this element: itself, or (split) two triangles given by their corners k of the quad and
       the quad's face of each triangle edge (-1: the diagonal) */
    int tri[2][3], face[2][3], n_tri = 1;
    if (nve == 4 && split) {
      double d02 = hypot(xy[2 * v[2]] - xy[2 * v[0]], xy[2 * v[2] + 1] - xy[2 * v[0] + 1]);
      double d13 = hypot(xy[2 * v[3]] - xy[2 * v[1]], xy[2 * v[3] + 1] - xy[2 * v[1] + 1]);
      static const int t02[2][3] = {{0, 1, 2}, {0, 2, 3}}, f02[2][3] = {{0, 1, -1}, {-1, 2, 3}};
      static const int t13[2][3] = {{0, 1, 3}, {1, 2, 3}}, f13[2][3] = {{0, -1, 3}, {1, 2, -1}};
      memcpy(tri, d02 <= d13 ? t02 : t13, sizeof tri);
      memcpy(face, d02 <= d13 ? f02 : f13, sizeof face);
      n_tri = 2;
    } else {
      for (int k = 0; k < 3; ++k) tri[0][k] = k, face[0][k] = k;
    }
    for (int t = 0; t < n_tri; ++t, ++oc) {
      const int nk = n_tri == 2 ? 3 : nve;
      for (int k = 0; k < nk; ++k) cv[oc * nvc + k] = n_tri == 2 ? v[tri[t][k]] : v[k];
      cell_line[oc] = e->line;
      cell_region[oc] = region;
      if (!curved) continue;
      double *em = emid + 2 * (size_t)oc * nvc;
      for (int k = 0; k < nk; ++k) {
        int f = n_tri == 2 ? face[t][k] : k;
        if (f >= 0) {
          em[2 * k] = m[f][0], em[2 * k + 1] = m[f][1];
        } else if (second_order(e->type)) {
          em[2 * k] = ce[0], em[2 * k + 1] = ce[1];
        } else { /* the straight diagonal */
          const double *a = xy + 2 * cv[oc * nvc + k], *b = xy + 2 * cv[oc * nvc + (k + 1) % 3];
          em[2 * k] = 0.5 * (a[0] + b[0]), em[2 * k + 1] = 0.5 * (a[1] + b[1]);
        }
      }
      centre[2 * (size_t)oc] = ce[0], centre[2 * (size_t)oc + 1] = ce[1];
    }
  }
  n_cells = n_out;
  for (int i = 0; i < n_sides; ++i) {
    const g_elem *e = sides[i];
    for (int k = 0; k < per_side; ++k) sv[i * per_side + k] = (int)vmap[e->nodes[k]];
    side_line[i] = e->line;
    if ((rc = resolve_group(g, e, dim - 1, &side_tag[i]))) goto done;
  }
  if (n_sides == 0) {
    rc = err(g, g->line,
             "the mesh has no boundary elements in a named physical group: define a physical %s for every boundary "
             "(Physical %s(\"name\") = {...})",
             dim == 2 ? "curve" : "point", dim == 2 ? "Curve" : "Point");
    goto done;
  }

  /* Orientation: 1-D cells towards +x; 2-D cells counter-clockwise. A mesh
   * whose cells all turn clockwise (surface normal -z) is flipped as a whole;
   * a mix is left for sl_mesh_create to refuse as inverted cells. */
  if (dim == 1) {
    for (int c = 0; c < n_cells; ++c)
      if (xy[2 * cv[2 * c + 1]] < xy[2 * cv[2 * c]]) {
        int t = cv[2 * c];
        cv[2 * c] = cv[2 * c + 1];
        cv[2 * c + 1] = t;
      }
  } else {
    double total = 0;
    for (int c = 0; c < n_cells; ++c) {
      const int *q = cv + c * nvc;
      for (int k = 0; k < nvc; ++k) { /* shoelace, relative to the first vertex */
        const double *a = xy + 2 * q[k], *b = xy + 2 * q[(k + 1) % nvc], *o = xy + 2 * q[0];
        total += 0.5 * ((a[0] - o[0]) * (b[1] - o[1]) - (b[0] - o[0]) * (a[1] - o[1]));
      }
    }
    if (total < 0)
      for (int c = 0; c < n_cells; ++c) {
        int *q = cv + c * nvc; /* reverse the order after vertex 0 */
        int t = q[1];
        q[1] = q[nvc - 1];
        q[nvc - 1] = t;
        if (!emid) continue;
        /* new face k joins new vertices k, k + 1 = old nvc - k, nvc - k - 1: the old face nvc - 1 - k */
        double *em = emid + 2 * (size_t)c * nvc;
        for (int k = 0; k < nvc / 2; ++k)
          for (int i = 0; i < 2; ++i) {
            double u = em[2 * k + i];
            em[2 * k + i] = em[2 * (nvc - 1 - k) + i];
            em[2 * (nvc - 1 - k) + i] = u;
          }
      }
  }

  sl_mesh_spec s = {.dim = dim,
                    .cell_type = dim == 1   ? SL_CELL_LINE2
                                 : nvc == 3 ? SL_CELL_TRI3
                                            : SL_CELL_QUAD4,
                    .n_vertices = nv,
                    .xy = xy,
                    .n_cells = n_cells,
                    .cell_vertices = cv,
                    .n_boundaries = n_bnames,
                    .boundary_names = bnames,
                    .n_sides = n_sides,
                    .side_vertices = sv,
                    .side_tag = side_tag,
                    .n_regions = any_region ? n_rnames : 0,
                    .region_names = rnames,
                    .cell_region = cell_region,
                    .source = g->name,
                    .cell_line = g->binary ? NULL : cell_line,
                    .side_line = g->binary ? NULL : side_line,
                    .edge_mid = emid,
                    .cell_centre = emid && nvc == 4 ? centre : NULL};
  rc = sl_mesh_create(&s, out, g->d);
done:
  free(emid);
  free(centre);
  free(cells);
  free(sides);
  free(vmap);
  free(xy);
  free(bnames);
  free(rnames);
  free(cv);
  free(cell_line);
  free(cell_region);
  free(sv);
  free(side_tag);
  free(side_line);
  return rc;
}

int sl_mesh_read_gmsh_string_opts(const char *text, size_t len, const char *name, const sl_gmsh_opts *opts,
                                  sl_mesh **out, sl_diag *d) {
  static const sl_gmsh_opts none = {0};
  if (!opts) opts = &none;
  *out = NULL;
  gmsh g;
  memset(&g, 0, sizeof g);
  g.name = name ? name : "<gmsh>";
  g.text = text;
  g.len = len;
  g.d = d;
  int rc = parse(&g);
  if (!rc) rc = build(&g, opts, out);
  free(g.buf);
  free(g.nodes);
  free(g.el);
  for (int i = 0; i < g.n_names; ++i) free(g.names[i].name);
  free(g.names);
  for (int k = 0; k < 4; ++k) free(g.ent[k]);
  return rc;
}

/* The size limit: SL_MESH_GMSH_MAX_BYTES, or SLUICE_MESH_MAX_BYTES. */
static long max_bytes(void) {
  const char *e = getenv("SLUICE_MESH_MAX_BYTES");
  if (e && *e) {
    char *end;
    double v = strtod(e, &end);
    if (*end == '\0' && v >= 1 && v <= 2147483647.0) return (long)v;
  }
  return SL_MESH_GMSH_MAX_BYTES;
}

int sl_mesh_read_gmsh_string(const char *text, size_t len, const char *name, sl_mesh **out, sl_diag *d) {
  return sl_mesh_read_gmsh_string_opts(text, len, name, NULL, out, d);
}

int sl_mesh_read_gmsh(const char *path, sl_mesh **out, sl_diag *d) {
  return sl_mesh_read_gmsh_opts(path, NULL, out, d);
}

int sl_mesh_read_gmsh_opts(const char *path, const sl_gmsh_opts *opts, sl_mesh **out, sl_diag *d) {
  *out = NULL;
  /* O_NONBLOCK: opening a FIFO without a writer must not wait; the type is checked before any read */
  int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return sl_diag_set(d, SL_EBADINPUT, "%s: cannot open the mesh file: %s", path, strerror(errno));
  struct stat st;
  if (fstat(fd, &st) != 0) {
    int e = errno;
    close(fd);
    return sl_diag_set(d, SL_EBADINPUT, "%s: cannot read the mesh file: %s", path, strerror(e));
  }
  if (!S_ISREG(st.st_mode)) {
    close(fd);
    const char *what = S_ISFIFO(st.st_mode)   ? "a FIFO (named pipe)"
                       : S_ISCHR(st.st_mode)  ? "a character device"
                       : S_ISBLK(st.st_mode)  ? "a block device"
                       : S_ISDIR(st.st_mode)  ? "a directory"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a regular file";
    return sl_diag_set(d, SL_EBADINPUT, "%s: the mesh file is %s; a Gmsh mesh must be a regular file", path, what);
  }
  long limit = max_bytes();
  if (st.st_size > limit) {
    close(fd);
    return sl_diag_set(d, SL_EBADINPUT,
                       "%s: the mesh file has %.0f bytes, more than the limit of %ld (SLUICE_MESH_MAX_BYTES sets "
                       "another, up to 2147483647)",
                       path, (double)st.st_size, limit);
  }
  int flags = fcntl(fd, F_GETFL);
  if (flags >= 0) (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  FILE *f = fdopen(fd, "rb");
  if (!f) {
    int e = errno;
    close(fd);
    return sl_diag_set(d, SL_EBADINPUT, "%s: cannot read the mesh file: %s", path, strerror(e));
  }
  /* the size from fstat, and a bound in case the file grows while read */
  size_t cap = (size_t)st.st_size + 1, len = 0;
  char *text = malloc(cap);
  if (!text) {
    fclose(f);
    return sl_diag_set(d, SL_ENOMEM, "%s: out of memory reading the mesh file (%.0f bytes)", path, (double)st.st_size);
  }
  for (;;) {
    size_t n = fread(text + len, 1, cap - len, f);
    len += n;
    if (n == 0 || len == cap) break;
  }
  int bad = ferror(f);
  fclose(f);
  if (bad || len > (size_t)st.st_size) {
    free(text);
    return sl_diag_set(d, SL_EBADINPUT, "%s: %s", path, bad ? "read error" : "the mesh file grew while it was read");
  }
  int rc = sl_mesh_read_gmsh_string_opts(text, len, path, opts, out, d);
  free(text);
  return rc;
}
