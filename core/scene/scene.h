/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The typed scene, built once from the INI file and the model's schema
 * (core/scene/schema.h): every key the model reads, validated and
 * defaulted, in structs; the mesh; the boundaries; the closures by role.
 * Models read only this; nothing under core/models sees the INI.
 *
 * Building a scene finds every input error before anything is written: an
 * unknown section or key (with a did-you-mean, and the model or variant it
 * belongs to when it is another's), a value of the wrong type or out of
 * range, a missing required key or closure, an expression that does not
 * compile, a boundary the mesh does not have, a key that does not apply to
 * a boundary's type. */
#ifndef SLUICE_SCENE_SCENE_H
#define SLUICE_SCENE_SCENE_H

#include <signal.h>
#include <stddef.h>

#include "core/config/ini.h"
#include "core/io/output.h"
#include "core/mesh/mesh.h"
#include "core/plugin/instance.h"
#include "core/scene/schema.h"
#include "core/time/time_config.h"

/* [mesh] */
typedef struct sl_mesh_config {
  int generator; /* interval | rectangle | annulus | inclined_box | gmsh */
  sl_reals x, y, r, z, origin, cells;
  double shear, width, height, angle;
  int cell_type, diagonal;
  const char *grading_x, *grading_y, *file;
  double memory_limit; /* bytes a run may need (0: the machine's memory) */
  int split_quads;     /* gmsh: split quadrangles into triangles */
} sl_mesh_config;

/* [solver] */
typedef struct sl_solver_config {
  int linear;    /* 0 auto, then umfpack | klu | cholmod | petsc (SL_SCENE_LINEAR_CHOICES) */
  int ordering;  /* auto | amd | colamd | metis */
  int nonlinear; /* newton | picard */
  double nonlinear_tolerance;
  long max_iterations, picard_first;
  const char *continuation; /* "section.key", "" for none */
  double continuation_from;
  long continuation_steps;
  double continuation_tolerance; /* Newton's tolerance at the stages before the last (0: nonlinear_tolerance) */
  int skip_known;                /* skip the solves whose result is known (a flow at rest, at a fixed point) */
  int reuse;                     /* factorisation reuse: 0 auto, 1 never */
  char *petsc_options;           /* [solver.petsc] as PETSc options ("-ksp_type gmres ..."), NULL: none */
} sl_solver_config;

/* [output] */
typedef struct sl_output_config {
  const char *file, *fields;
  sl_reals interface; /* levels of phi whose heights are written */
} sl_output_config;

/* One nonlinear iteration, as a run reports it (`sluice run --monitor`, the
 * progress of a steady solve): the time the step ends at (steady: 0), the
 * continuation stage (0 of 0 without), the iteration (from 1), whether it
 * is a Picard one, its relative correction, the residual at its start and
 * the scale the solution's terms set for it (core/solve/newton.h). */
typedef struct sl_nl_report {
  double t;
  long stage, n_stages;
  int iteration, picard;
  double correction, residual, terms;
} sl_nl_report;

/* What a run gives the model besides the scene: where to report the
 * nonlinear iterations (NULL: nowhere), and the interrupt flag a steady
 * solve checks between iterations and stages (NULL: none). */
typedef struct sl_run_hooks {
  void (*nonlinear)(void *user, const sl_nl_report *r);
  void *user;
  volatile sig_atomic_t *interrupt;
  int checking; /* `run --check`: a model's set-up validates and skips what only integrates (settling a deposit) */
} sl_run_hooks;

/* Where a value or a section of the scene came from. */
typedef struct sl_src {
  const char *file;
  int line;
  const char *section; /* its section, "boundary.top" */
  const char *key;     /* NULL for a section */
  const char *value;
} sl_src;

typedef struct sl_scene {
  const sl_schema *schema;
  sl_ini *ini; /* the source, for provenance, locations and continuation (not for models) */
  /* [scene] */
  const char *model, *title;
  int geometry; /* line | planar | axisymmetric */
  sl_mesh_config mesh_config;
  struct {
    double density, viscosity;
  } fluid;
  struct {
    double density, diameter, phi_max, sphericity, porosity_max, viscosity;
    double vessel_diameter; /* the mixture: D of a settling law's wall term d/D (0: none given, D infinite) */
  } solid;
  struct {
    int third_component, convection;
    int scheme; /* 0 monolithic, 1 projection (core/models/navier_stokes/projection.h) */
    sl_reals gravity, rotation_centre;
    sl_scene_exprs body_force; /* of x, y, t */
    double rotation;
  } flow;
  sl_time_config time; /* [time] and [output] every */
  sl_solver_config solver;
  sl_output_config output;
  const char *plugins_path; /* [plugins] path (core/plugin reads it before the scene is built) */
  /* built */
  sl_mesh *mesh;
  void *config;     /* the model's struct (schema->config_size bytes) */
  void *boundaries; /* one struct per mesh boundary (schema->boundary_size bytes each), in the mesh's order */
  int n_boundaries;
  sl_closure *closures[SL_SCHEMA_MAX_ROLES]; /* by the schema's role index; NULL: not in the scene */
  const char *closure_sections[SL_SCHEMA_MAX_ROLES];
  /* where each typed value came from, and each boundary's section */
  struct sl_scene_src *src;
  int n_src, cap_src;
  sl_src *boundary_src; /* [n_boundaries]; file NULL: the scene has no section for it */
  int *boundary_order;  /* [n_boundaries]: the boundaries in the order of their sections in the file, then the
                           others in the mesh's order (what pairs them, e.g. periodic sides, is read in that order) */
  const sl_registry *registry;
  sl_expr **exprs; /* the compiled expressions the scene owns */
  int n_exprs;
  sl_run_hooks hooks; /* set by the run before the model's setup */
} sl_scene;

/* Key declarations: where a value goes. */
#define SL_AT_SCENE(field) .target = SL_IN_SCENE, .offset = offsetof(sl_scene, field)
#define SL_AT_MODEL(type, field) .target = SL_IN_MODEL, .offset = offsetof(type, field)
#define SL_AT_BOUNDARY(type, field) .target = SL_IN_BOUNDARY, .offset = offsetof(type, field)

/* Everything a scene needs to be built. */
typedef struct sl_scene_opts {
  const sl_registry *registry;     /* for the closures (NULL: they are not looked up) */
  int create_closures;             /* create them (a run); 0: look them up and check their parameters only */
  int build_mesh;                  /* build the mesh and the boundaries (0: the keys only, as --print-config) */
  const sl_schema *const *schemas; /* every model's, for "it is a key of model = X" in the messages */
  int n_schemas;
} sl_scene_opts;

/* The schema a scene file asks for: [scene] model among the schemas'
 * models (an unknown name is SL_EBADINPUT with a did-you-mean), then the
 * first of that model's variants whose `when` rules the file matches (the
 * first variant when none does: its keys then say what is wrong). */
int sl_scene_select(const sl_ini *ini, const sl_schema *const *schemas, int n, int *index, sl_diag *d);

/* The most output times a transient scene may ask for ([output] every against [time] end). */
#define SL_SCENE_OUTPUT_TIMES_MAX 100000

/* Builds the scene of `ini` for the schema. 0 or SL_EBADINPUT with
 * file:line; SL_EFAILED for memory. *out is NULL on failure. */
int sl_scene_build(sl_ini *ini, const sl_schema *schema, const sl_scene_opts *o, sl_scene **out, sl_diag *d);
void sl_scene_free(sl_scene *sc);

/* Where the value at `field` (the address of a typed value in the scene,
 * the model's config or a boundary struct) came from: its INI entry, or NULL
 * when the key was not given (its default holds). */
const sl_src *sl_scene_src(const sl_scene *sc, const void *field);
static inline int sl_scene_given(const sl_scene *sc, const void *field) { return sl_scene_src(sc, field) != NULL; }
/* "file:line: [section] key" of the value at `field` into buf (or
 * "[section] key" when it was not given); returns buf. */
const char *sl_scene_where(const sl_scene *sc, const void *field, char *buf, size_t len);
/* 0 when the key of `field` was given; else the located "missing the
 * required key" error (SL_EBADINPUT), for keys that a model requires only in
 * some cases. */
int sl_scene_require(const sl_scene *sc, const void *field, sl_diag *d);

/* A bad-input message (rc == SL_EBADINPUT) that names a section or key ("[boundary.top] velocity: ...")
 * but not where it is gets the file:line of that key, else of the section; rc is returned. */
int sl_scene_locate(const sl_scene *sc, int rc, sl_diag *d);
/* 1 when the scene file has the section (e.g. "time"). */
int sl_scene_has_section(const sl_scene *sc, const char *section);
/* The i-th [family.NAME] section of the scene (a named family: its keys flagged SL_KEY_NAMED), in the file's
 * order: 1 with *name its NAME and *where the section's location, 0 past the last. Its keys were checked against
 * the family's. */
int sl_scene_named(const sl_scene *sc, const char *family, int i, const char **name, sl_src *where);
/* Key `key` of the i-th [family.NAME], read by the family's schema key (its type, count and range): up to max
 * numbers into v, *n of them (0 when the key is absent, where->file NULL then); where is the key's location. */
int sl_scene_named_reals(const sl_scene *sc, const char *family, int i, const char *key, double *v, int max, int *n,
                         sl_src *where, sl_diag *d);

/* Boundary i's struct, and its name. */
static inline void *sl_scene_boundary(const sl_scene *sc, int i) {
  return (char *)sc->boundaries + (size_t)i * sc->schema->boundary_size;
}
/* The [boundary.NAME] section of boundary i, or NULL when the scene has none for it. */
const sl_src *sl_scene_boundary_section(const sl_scene *sc, int i);

/* The closure of [closure.<role>], or NULL when the scene has none. */
sl_closure *sl_scene_closure(const sl_scene *sc, const char *role);
/* Its section's location "file:line: [closure.role]" (or "[closure.role]"). */
const char *sl_scene_closure_where(const sl_scene *sc, const char *role, char *buf, size_t len);

/* [output] fields as a mask over the schema's fields (bit k: fields[k]);
 * absent or empty: default_mask. */
int sl_scene_output_fields(const sl_scene *sc, unsigned default_mask, unsigned *mask, sl_diag *d);
/* The output file: override (the command line's -o), else [output] file,
 * else the scene file's name with .h5 (in the working folder). */
void sl_scene_output_path(const sl_scene *sc, const char *override, const char *scene_path, char *path, size_t cap);

/* The provenance of the run: the resolved INI and every closure with its
 * role and parameters. The strings live until sl_scene_provenance_free. */
typedef struct sl_scene_provenance {
  sl_provenance pv;
  sl_provenance_closure closures[SL_SCHEMA_MAX_ROLES];
  char params[SL_SCHEMA_MAX_ROLES][2048];
  char *ini_text;
} sl_scene_provenance;
int sl_scene_provenance_make(const sl_scene *sc, const char *sluice_version, sl_scene_provenance *p, sl_diag *d);
void sl_scene_provenance_free(sl_scene_provenance *p);

/* Continuation (the steady solver's): sets the scene's value of `key`
 * ("section.key", a real key of the schema or a closure parameter) to v,
 * re-creating that closure. 0, or SL_EBADINPUT (not a real key the model
 * reads) or the closure's refusal. The scene's INI is not changed. */
int sl_scene_set_real(sl_scene *sc, const char *key, double v, sl_diag *d);
/* Checks that `key` is something sl_scene_set_real can set, and gives its
 * current value. */
int sl_scene_get_real(const sl_scene *sc, const char *key, double *v, sl_diag *d);

#endif
