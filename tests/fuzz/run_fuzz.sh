#!/bin/sh
# Fuzz with libFuzzer (clang, ASan+UBSan): the INI parser (ini), the
# expression language (expr) and the model layer (scene: a scene checked as
# `sluice run --check` checks it, fuzz_scene.c).
#   tests/fuzz/run_fuzz.sh BUILD_DIR [SECONDS [TARGET...]]
# SECONDS for each target (default 60); TARGETs default to ini expr scene.
# Configures a clang build with -DSLUICE_FUZZ=ON in BUILD_DIR, builds the
# targets (and the closure plugins that fuzz_scene loads through their index)
# and fuzzes each from its seed corpus with its dictionary. New inputs go to
# BUILD_DIR/fuzz/TARGET-corpus (the seed folders in the source tree are read
# only); a crash, leak or UB report leaves its input in BUILD_DIR/fuzz/artifacts/
# and makes this script fail. Replay a crasher in any build with
# BUILD_DIR/bin/fuzz_ini_replay FILE, fuzz_expr_replay FILE or
# fuzz_scene_expect 2 FILE.
set -eu

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [SECONDS [ini|expr|scene]...]" >&2
  exit 2
fi
build=$1
seconds=${2:-60}
[ $# -gt 2 ] && shift 2 || set -- ini expr scene
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)

cmake -S "$src" -B "$build" -DSLUICE_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
targets=""
for t in "$@"; do targets="$targets fuzz_$t"; done
# shellcheck disable=SC2086
cmake --build "$build" --target $targets -j2
build=$(cd "$build" && pwd)
artifacts="$build/fuzz/artifacts"
mkdir -p "$artifacts"

for t in "$@"; do
  case $t in
    ini) seeds="$here/corpus/ini" dict="$here/ini.dict" max_len=4096 ;;
    expr) seeds="$here/corpus/expr" dict="$here/expr.dict" max_len=512 ;;
    scene) seeds="$here/corpus/scene" dict="$here/scene.dict" max_len=8192 ;;
    *) echo "$0: unknown target '$t' (ini, expr, scene)" >&2; exit 2 ;;
  esac
  work="$build/fuzz/$t-corpus"
  mkdir -p "$work" "$build/fuzz/$t-run"
  echo "== fuzz_$t for $seconds s"
  # Run in an empty folder, where relative includes and meshes reach nothing;
  # SLUICE_PLUGIN_PATH is ignored (fuzz_scene loads this build's plugins only).
  (cd "$build/fuzz/$t-run" && "$build/bin/fuzz_$t" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 \
    -rss_limit_mb=2048 -dict="$dict" -artifact_prefix="$artifacts/$t-" -print_final_stats=1 "$work" "$seeds")
  # the scene target writes no file
  if [ -n "$(ls -A "$build/fuzz/$t-run")" ]; then
    echo "$0: fuzz_$t left files in its working folder:" >&2
    ls -A "$build/fuzz/$t-run" >&2
    exit 1
  fi
done
