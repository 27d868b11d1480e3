/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The scene fuzz target's entry point (fuzz_scene.c), shared by the libFuzzer
 * binary and the replay tests. */
#ifndef SLUICE_TESTS_FUZZ_SCENE_H
#define SLUICE_TESTS_FUZZ_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include <sluice/sluice.h>

/* What one input may need: [mesh] memory_limit is set to this for every
 * scene with a [mesh] section (over the scene's own value), so that the
 * mesh's memory estimate (core/scene/mesh.c, 16 kB a 2-D cell) refuses more
 * than 4096 cells and one input takes milliseconds. */
#define SL_FUZZ_SCENE_MEMORY_LIMIT "67108864"

/* `sluice run --check` of the scene text in this process, with the fuzz
 * limit: sluice_open_text, then sluice_check (closures found through the
 * plugin index, the mesh built, the model set up; no file written). `name`
 * stands for the scene file (the base of relative includes and meshes).
 * Returns SLUICE_OK, SLUICE_FAILED or SLUICE_BAD_INPUT; e says why. */
int sl_fuzz_scene_check(const uint8_t *data, size_t size, const char *name, sluice_error *e);

#endif
