#!/bin/sh
# Fuzz the INI parser with libFuzzer (clang, ASan+UBSan).
#   tests/fuzz/run_fuzz.sh BUILD_DIR [SECONDS]      (default 60 s)
# Configures a clang build with -DSLUICE_FUZZ=ON in BUILD_DIR, builds fuzz_ini
# and fuzzes from the seed corpus. New inputs go to BUILD_DIR/fuzz/ini-corpus
# (the seed folder in the source tree is read only); a crash leaves its input in
# BUILD_DIR/fuzz/artifacts/ and makes this script fail. Replay a crasher with
# BUILD_DIR/bin/fuzz_ini_replay FILE (in any build).
set -eu

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [SECONDS]" >&2
  exit 2
fi
build=$1
seconds=${2:-60}
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)

cmake -S "$src" -B "$build" -DSLUICE_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target fuzz_ini -j2
build=$(cd "$build" && pwd)

work="$build/fuzz/ini-corpus"
artifacts="$build/fuzz/artifacts"
mkdir -p "$work" "$artifacts"
# Run where relative includes cannot reach the source tree.
cd "$build/fuzz"
"$build/bin/fuzz_ini" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -dict="$here/ini.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
  "$work" "$here/corpus/ini"
