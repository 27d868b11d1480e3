/* SPDX-License-Identifier: GPL-2.0-or-later */
/* From a scene's [closure.<role>] section to a created closure. The role is
 * the kind, optionally followed by a qualifier: [closure.viscosity],
 * [closure.wall_stress.inner]. Keys: `model` (the closure name), optional
 * `library` (which library wins when two provide the name), and the closure's
 * own parameters, each checked against its schema with file:line errors. */
#ifndef SLUICE_PLUGIN_CLOSURE_INI_H
#define SLUICE_PLUGIN_CLOSURE_INI_H

#include "core/config/ini.h"
#include "core/plugin/instance.h"

/* The kind of a [closure.<role>] section name. */
int sl_closure_section_kind(const char *section, sl_kind *kind, sl_diag *d);

/* Creates the closure a section names. */
int sl_closure_from_ini(const sl_registry *r, const sl_ini *ini, const char *section, sl_closure **out, sl_diag *d);
/* Finds the closure and checks its parameters, without creating it: the
 * errors of sl_closure_from_ini except a refusal by the closure's create. */
int sl_closure_check_ini(const sl_registry *r, const sl_ini *ini, const char *section, sl_diag *d);

/* A closure section whose `model` becomes another closure: the keys its
 * files gave (parameters, `library`) were the old closure's and are dropped,
 * so that the new one starts from its defaults; keys given on the command
 * line stay (they were meant for the new one). Nothing when the model is the
 * same or the section is not a closure's. */
void sl_closure_ini_replace_model(sl_ini *ini, const char *section, const char *model);

/* sl_ini_apply_override with the rule above: what `--set` does to a scene. */
int sl_closure_ini_apply_override(sl_ini *ini, const char *assignment, sl_diag *d);

/* A scene may name folders of closure libraries only when the command line
 * allows it (docs/trust-plugins.md): 0, or SL_EBADINPUT naming the key, its
 * file:line and the flag. */
int sl_plugin_dirs_allowed(const sl_ini *ini, int allow, sl_diag *d);

/* Search folders named in the scene: [plugins] path = dir, dir (relative to
 * the scene file). Free the result with sl_plugin_dirs_free. */
int sl_plugin_dirs_from_ini(const sl_ini *ini, char ***dirs, int *n, sl_diag *d);
void sl_plugin_dirs_free(char **dirs, int n);

#endif
