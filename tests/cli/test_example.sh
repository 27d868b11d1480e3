#!/usr/bin/env bash
# Installs sluice into a scratch prefix, builds examples/my_closure against
# it as a third party would, and uses the closure by name through
# SLUICE_PLUGIN_PATH; builds examples/embed against the installed library
# and runs a scene through it. Arguments: BUILD_DIR SOURCE_DIR WORK_DIR.
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
# ...with the index beside them (docs/trust-plugins.md)
check "the plugin index is installed" '[ -n "$(find "$work/prefix" -path "*/sluice/plugins/closures.index" -size +1k)" ]'
# ...and the new closure only through the search path.
check "not found without the path" '! "$sluice" closure describe my_power_law > /dev/null 2>&1'
export SLUICE_PLUGIN_PATH="$work/example"
check "listed with the path" '"$sluice" closures | grep -q "^viscosity *my_power_law"'
# consistency 0.5, n 0.6: 0.5 * 32^-0.4 = 0.125 exactly.
out=$("$sluice" closure eval my_power_law --set consistency=0.5 --set n=0.6 --at "shear_rate=32")
check "evaluated by name: 0.5 * 32^-0.4 = 0.125" '[ "$(tail -n 1 <<<"$out")" = "32,0.125" ]'
check "closure index lists it" '"$sluice" closure index "$work/example" > /dev/null && grep -qx "viscosity my_power_law my_closure.so" "$work/example/closures.index"'
check "passes the conformance battery" '"$sluice" check-closure "$work/example/my_closure.so" > "$work/check.log"'
# sluice_add_closure_test(my_closure) in the example registers the battery as its ctest.
check "the example's ctest runs the battery" 'ctest --test-dir "$work/example" > "$work/example_ctest.log" 2>&1 && grep -q "my_closure_check_closure .* Passed" "$work/example_ctest.log"'
# A program embedding the core through sluice/sluice.h, built with the installed pkg-config file: the Stokes
# cavity in 4 fixed BDF1 steps of 0.1 to t = 0.4.
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig:$work/prefix/lib64/pkgconfig:$work/prefix/lib/x86_64-linux-gnu/pkgconfig"
unset SLUICE_PLUGIN_PATH
check "embedding program builds with pkg-config" \
  'cc "$src/examples/embed/embed.c" $(pkg-config --cflags --libs sluice) -o "$work/embed" 2> "$work/embed_build.log"'
out=$("$work/embed" "$src/configs/cavity_stokes.ini" "$work/embed.h5" mesh.cells=4 time.scheme=bdf1 time.adaptive=false \
      time.dt=0.1 time.end=0.4 output.every=0 2>&1 || true)
check "embedded run: 4 steps, each seen by the progress callback" 'grep -q "4 steps (4 seen by the progress callback), 0 rejected; reached the end time t = 0.4" <<<"$out"'
check "embedded run: its output file, two output times" 'grep -q "embed.h5: 2 output times" <<<"$out"'
# The installed tree is complete: the scenes run from it, the documentation, the licences, the man page and the
# bash completion are there.
share="$work/prefix/share"
check "an installed scene runs" \
  '(cd "$work" && "$sluice" run "$share/sluice/configs/cavity_stokes.ini" --set mesh.cells=4 -o "$work/installed_scene.h5" > "$work/installed_scene.log" 2>&1)'
check "the documentation and licences" \
  '[ -f "$share/doc/sluice/README.md" ] && [ -f "$share/doc/sluice/scenes.md" ] && [ -f "$share/doc/sluice/models/mixture.md" ] && [ -f "$share/doc/sluice/COPYING" ] && [ -f "$share/doc/sluice/COPYING.MIT" ] && [ -f "$share/doc/sluice/CHANGELOG.md" ] && [ -f "$share/doc/sluice/CITATION.cff" ]'
check "the examples" '[ -f "$share/sluice/examples/embed/embed.c" ] && [ -f "$share/sluice/examples/my_closure/CMakeLists.txt" ]'
check "the man page names every command" \
  'for c in run model closures closure check-closure sample bench version; do grep -q "^\.SS $c\$" "$share/man/man1/sluice.1" || exit 1; done'
check "the bash completion completes a command" \
  '[ "$(bash -c "source \"$share/bash-completion/completions/sluice\"; COMP_WORDS=(sluice che); COMP_CWORD=1; _sluice; echo \${COMPREPLY[*]}")" = "check-closure" ]'
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
