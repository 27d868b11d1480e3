#!/usr/bin/env bash
# Installs sluice into a scratch prefix, builds examples/my_closure against
# it as a third party would, and uses the closure by name through
# SLUICE_PLUGIN_PATH. Arguments: BUILD_DIR SOURCE_DIR WORK_DIR.
set -eu
build=$1 src=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$src/examples/my_closure" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/example" > "$work/build.log"
sluice="$work/prefix/bin/sluice"
pass=0 fail=0
check() { if eval "$2"; then pass=$((pass+1)); else fail=$((fail+1)); echo "failed: $1"; fi; }
# The installed command finds its own built-in closures...
check "installed sluice lists ergun" '"$sluice" closures | grep -q "^drag *ergun"'
# ...and the new closure only through the search path.
check "not found without the path" '! "$sluice" closure describe my_power_law > /dev/null 2>&1'
export SLUICE_PLUGIN_PATH="$work/example"
check "listed with the path" '"$sluice" closures | grep -q "^viscosity *my_power_law"'
# consistency 0.5, n 0.6: 0.5 * 32^-0.4 = 0.125 exactly.
out=$("$sluice" closure eval my_power_law --set consistency=0.5 --set n=0.6 --at "shear_rate=32")
check "evaluated by name: 0.5 * 32^-0.4 = 0.125" '[ "$(tail -n 1 <<<"$out")" = "32,0.125" ]'
check "passes the conformance battery" '"$sluice" check-closure "$work/example/my_closure.so" > "$work/check.log"'
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
