#!/usr/bin/env bash
# The closure author's path (docs/writing-a-closure.md): `sluice closure new`
# writes a template for two kinds; each builds with its own CMakeLists.txt
# against the build tree's package (find_package(sluice), sluice_add_closure,
# sluice_add_closure_test) and its ctest runs the conformance battery. The
# hindered_settling template's placeholder law (Richardson & Zaki 1954) is used
# as written, evaluated and run in a scene; the viscosity template's law is
# replaced by sed with Batchelor (1977), first with a wrong derivative (the
# battery must fail) and then right (it must pass).
# Arguments: SLUICE PACKAGE_DIR WORK_DIR SOURCE_DIR.
set -u
sluice=$1 pkg=$2 work=$3 src=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
pass=0 fail=0
check() { if eval "$2"; then pass=$((pass+1)); else fail=$((fail+1)); echo "failed: $1"; fi; }
build() { # DIR: configure, build and run the folder's ctest
  cmake -S "$1" -B "$1/build" -DCMAKE_PREFIX_PATH="$pkg" -DCMAKE_C_FLAGS="-Wall -Wextra -Werror" > "$1/configure.log" 2>&1 &&
    cmake --build "$1/build" > "$1/build.log" 2>&1 && ctest --test-dir "$1/build" --output-on-failure > "$1/ctest.log" 2>&1
}

check "new writes the settling template" '"$sluice" closure new hindered_settling my_settling -o my_settling > new.log && [ -f my_settling/my_settling.c ] && [ -f my_settling/CMakeLists.txt ]'
check "new refuses to overwrite (exit 2)" '"$sluice" closure new hindered_settling my_settling -o my_settling 2> over.log; [ $? = 2 ] && grep -q "exists; not overwritten" over.log'
check "new: an unknown kind with a did-you-mean (exit 2)" '"$sluice" closure new viscosty x 2> kind.log; [ $? = 2 ] && grep -q "did you mean .viscosity." kind.log && [ ! -e x ]'
check "new: a name that is not lower_snake_case (exit 2)" '"$sluice" closure new drag My-Drag 2> name.log; [ $? = 2 ] && grep -q "lower_snake_case" name.log && [ ! -e My-Drag ]'
check "the placeholder is marked" 'grep -q "PLACEHOLDER LAW: replace from here" my_settling/my_settling.c'
check "the settling template builds and passes the battery (its ctest)" 'build my_settling && grep -q "100% tests passed" my_settling/ctest.log'
export SLUICE_PLUGIN_PATH="$work/my_settling/build"
# u = u_t (1 - phi)^n (1 - phi/phi_max), u_t = 1e-3, n = 4.65, phi_max = 0.64: at phi = 0.5,
# 1e-3 * 2^-4.65 * 0.21875 = 8.71281678832e-06; 0 at and above phi_max.
check "evaluated by name: 1e-3 * 2^-4.65 * (1 - 0.5/0.64)" '[ "$("$sluice" closure eval my_settling --at phi=0.5 | tail -n 1)" = "0.5,8.71281678832e-06" ]'
check "evaluated by name: 0 at phi_max" '[ "$("$sluice" closure eval my_settling --at phi=0.64 | tail -n 1)" = "0.64,0" ]'
check "used in a scene: the Kynch column with --set closure.hindered_settling.model" \
  '"$sluice" run "$src/configs/kynch_settling.ini" --set closure.hindered_settling.model=my_settling --set time.end=5 -o settle.h5 > run.log 2>&1'
# Kynch (1952): the top of the suspension (phi0 = 0.1 below clear fluid) falls at u(phi0) = 1e-3 * 0.9^4.65 *
# (1 - 0.1/0.64) = 5.16957e-4 m/s, from 0.5 m to 0.4974152 m at t = 5 s; the scene's 200 cells are 2.5 mm, and
# the interface (phi = 0.05) must be within half a cell of it.
check "the interface falls at the closure's u(phi0) (Kynch 1952), within half a cell" \
  '"$sluice" sample settle.h5 --scalars | awk -F, '"'"'$1 == 5 { e = 0.5 - 5 * 1e-3 * 0.9^4.65 * (1 - 0.1/0.64); d = $4 - e; ok = (d < 0 ? -d : d) < 1.25e-3 } END { exit !ok }'"'"''
unset SLUICE_PLUGIN_PATH

check "new writes the viscosity template" '"$sluice" closure new viscosity my_viscosity -o my_viscosity > /dev/null'
# Batchelor (1977): mu = mu_f (1 + 2.5 phi + 6.2 phi^2); at phi = 0.02, mu_f = 1e-3: 1.05248e-3.
sed -i -e 's/mu\[q\] = mu_f \* (1.0 + p->intrinsic_viscosity \* phi);/mu[q] = mu_f * (1.0 + p->intrinsic_viscosity * phi + 6.2 * phi * phi);/' \
       -e 's/OUT_VISCOSITY, 0.00105,/OUT_VISCOSITY, 0.00105248,/' my_viscosity/my_viscosity.c
check "the law was replaced" 'grep -q "6.2 \* phi \* phi" my_viscosity/my_viscosity.c && grep -q "0.00105248" my_viscosity/my_viscosity.c'
check "the old derivative fails the battery's derivative check" \
  '! build my_viscosity && grep -q "FAIL .*derivatives: dviscosity/dphi" my_viscosity/ctest.log'
sed -i 's/dmu_dphi\[q\] = mu_f \* p->intrinsic_viscosity;/dmu_dphi[q] = mu_f * (p->intrinsic_viscosity + 12.4 * phi);/' my_viscosity/my_viscosity.c
check "with its derivative the law passes the battery" 'build my_viscosity && grep -q "100% tests passed" my_viscosity/ctest.log'
check "check-closure on the library: every check passed" \
  '"$sluice" check-closure my_viscosity/build/my_viscosity.so > check.log && grep -q "^10 passed, 0 failed" check.log'
export SLUICE_PLUGIN_PATH="$work/my_viscosity/build"
check "evaluated: Batchelor (1977) at phi = 0.02, 1.05248e-3" '[ "$("$sluice" closure eval my_viscosity --at phi=0.02,mu_f=1e-3 | tail -n 1)" = "0.02,0.001,0.00105248" ]'
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
