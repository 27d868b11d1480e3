#!/usr/bin/env python3
"""Writes the scene fuzz target's seed corpus (tests/fuzz/corpus/scene) from
configs/*.ini: each scene as `sluice run --print-config` resolves it (its
includes flattened), with its mesh made small (at most 256 cells in 2-D, 32
in 1-D) so that one input takes milliseconds. Scenes that need another file
(a Gmsh mesh, a record) are left out: it would not be beside the seed; each
seed kept passes `sluice run --check`.
Usage: tests/fuzz/make_scene_seeds.py BUILD_DIR   (from the source tree's root)"""
import math
import os
import re
import subprocess
import sys

build = sys.argv[1] if len(sys.argv) > 1 else "build"
sluice = os.path.join(build, "bin", "sluice")
out = os.path.join("tests", "fuzz", "corpus", "scene")
os.makedirs(out, exist_ok=True)
for f in os.listdir(out):
    os.remove(os.path.join(out, f))
env = dict(os.environ, SLUICE_PLUGIN_PATH="")


def config(path, sets):
    cmd = [sluice, "run", "--print-config", path]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout


def small(counts):
    if len(counts) == 1:
        return [min(counts[0], 32)]
    f = max(1.0, math.sqrt(counts[0] * counts[1] / 256.0))
    return [max(1, round(c / f)) for c in counts]


for name in sorted(os.listdir("configs")):
    if not name.endswith(".ini"):
        continue
    path = os.path.join("configs", name)
    text = config(path, [])
    if re.search(r"^generator = gmsh", text, re.M):
        continue
    mesh = re.search(r"^\[mesh\]\n((?:[^\[\n].*\n)*)", text, re.M)
    cells = re.search(r"^cells = (.*)$", mesh.group(1), re.M) if mesh else None
    if cells:
        counts = [int(float(c)) for c in cells.group(1).split(",")]
        text = config(path, ["mesh.cells=" + ", ".join(str(c) for c in small(counts))])
    seed = os.path.join(out, name)
    with open(seed, "w") as f:
        f.write(text)
    check = subprocess.run([sluice, "run", "--check", seed], capture_output=True, text=True, env=env)
    if check.returncode != 0:
        print("left out %s: %s" % (name, check.stderr.strip()))
        os.remove(seed)
