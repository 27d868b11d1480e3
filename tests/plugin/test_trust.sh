#!/usr/bin/env bash
# Libraries and closures under the trust model (docs/trust-plugins.md), each
# check a reproducer of issue 25 that failed before:
#  - a scene's [plugins] path is refused (exit 2, file:line, the key) unless
#    --allow-plugin-path is given;
#  - a look-up opens only the library that holds the name (the folder's
#    closures.index), a misspelt name none; --check and --print-config run
#    library code only in a child process (a crashing constructor: exit 1,
#    the signal named, sluice itself survives);
#  - a closure that segfaults, divides by zero, calls exit(0), loops (call time
#    limit, Ctrl-C) or returns a fatal code stops the run at once with exit 1,
#    the closure and its section named, the last good state saved;
#  - the closures see the time level and the step (t, dt);
#  - check-closure names the closure, the check and the signal of a crash, a
#    hang (time limit) and an exit().
# Arguments: SLUICE FAULTY_DIR UNINDEXED_DIR CHECKFAULTS_DIR SOURCE_DIR WORK_DIR
set -u
sluice=$1 faulty=$2 unindexed=$3 checkfaults=$4 src=$5 work=$6
rm -rf "$work"; mkdir -p "$work"; cd "$work"
pass=0 fail=0
ok() { pass=$((pass+1)); }
bad() { fail=$((fail+1)); echo "failed: $1"; [ -f out.log ] && sed 's/^/    /' out.log | tail -5; }
# expect NAME STATUS REGEX -- command...: the exit status and a line of stdout+stderr
expect() {
  local name=$1 want=$2 re=$3; shift 4
  "$@" > out.log 2>&1; local got=$?
  if [ "$got" = "$want" ] && grep -Eq -- "$re" out.log; then ok; else bad "$name (exit $got, wanted $want and /$re/)"; fi
}
scene() { # scene FILE FAULT AFTER [extra lines]
  cat > "$1" <<INI
[scene]
model = navier_stokes
geometry = line

[mesh]
generator = interval
x = -1, 1
cells = 20

[fluid]
density = 1

[closure.viscosity]
model = faulty
fault = $2
after = $3

[flow]
third_component = true
convection = false
body_force = 0, 1

[time]
scheme = bdf1
adaptive = false
dt = 0.05
end = 0.5

[output]
every = 0.05
$4
INI
}
last_time() { "$sluice" sample "$1" --list 2>/dev/null | sed -n 's/^times ([0-9]* steps): .*, \([^,]*\)$/t = \1/p'; }

# ---- the scene may not name a folder of libraries ---------------------------------------------------
scene pathscene.ini none 0 $'\n[plugins]\npath = '"$faulty"
line=$(grep -n '^path = ' pathscene.ini | cut -d: -f1)
expect "[plugins] path refused" 2 "pathscene.ini:$line: error: \[plugins\] path = .*--allow-plugin-path" -- \
  "$sluice" run pathscene.ini --check
expect "[plugins] path refused under --print-config" 2 "pathscene.ini:$line: error: \[plugins\] path" -- \
  "$sluice" run pathscene.ini --print-config
expect "[plugins] path refused for a run, nothing written" 2 "\[plugins\] path" -- "$sluice" run pathscene.ini -o p.h5
[ ! -e p.h5 ] && ok || bad "no output file for a refused scene"
expect "--allow-plugin-path" 0 "scene valid; 1 closure resolved" -- "$sluice" run pathscene.ini --check --allow-plugin-path

# a study's scene the same (its runs too: they are child processes of bench)
cat > study.ini <<INI
[study]
scene = pathscene.ini

[points.time]
end = 0.1 | 0.2

[measure]
field = velocity
component = 2
line = -1:1
n = 3
reduce = max
value = 0
INI
expect "bench: [plugins] path refused" 2 "pathscene.ini:$line: error: \[plugins\] path" -- "$sluice" bench study.ini --check
expect "bench --allow-plugin-path, its runs too" 0 "2 of 2 runs measured" -- "$sluice" bench study.ini -o bench_out --allow-plugin-path

export SLUICE_PLUGIN_PATH="$faulty" SLUICE_TEST_MARKER="$work/marker"
# ---- a look-up opens the library that holds the name, and no other ---------------------------------
scene s.ini none 0 ""
rm -f marker
expect "the named closure resolved" 0 "viscosity +faulty .*viscosity_faulty.so" -- "$sluice" run s.ini --check
[ ! -e marker ] && ok || bad "marked.so (not named) was not opened: $(cat marker 2>/dev/null)"
expect "a run opens it too" 0 "reached the end time" -- "$sluice" run s.ini -o none.h5
[ ! -e marker ] && ok || bad "marked.so was not opened by the run"
sed 's/^model = faulty$/model = fauty/' s.ini > typo.ini
line=$(grep -n '^model = fauty' typo.ini | cut -d: -f1)
expect "a misspelt name: did you mean" 2 "typo.ini:$line:[0-9]+: error: no viscosity closure 'fauty'; did you mean 'faulty'\?" -- \
  "$sluice" run typo.ini --check
[ ! -e marker ] && ok || bad "a misspelt name opened no library"
# `library = FILE` outside the plugin path adds no library
sed 's|^model = faulty$|model = marked\nlibrary = '"$unindexed"'/marked.so|' s.ini > lib.ini
expect "library = a file off the path" 2 "lib.ini:[0-9]+:[0-9]+: error: library = .*unindexed/marked.so is not a library on the plugin search path" -- \
  "$sluice" run lib.ini -o lib.h5
[ ! -e marker ] && [ ! -e lib.h5 ] && ok || bad "library = off the path opened nothing, wrote nothing"
# ---- --check and --print-config: library code only in a child process --------------------------------
cat > m.ini <<INI
$(sed 's/^model = faulty$/model = marked/' s.ini)
INI
"$sluice" run m.ini --check > out.log 2>&1 & pid=$!; wait $pid; st=$?
if [ $st = 0 ] && grep -q "constructor of marked ran in pid" marker && ! grep -q "pid $pid\$" marker; then ok
else bad "--check ran the constructor in a child (sluice pid $pid; marker: $(cat marker 2>/dev/null))"; fi
rm -f marker
"$sluice" run m.ini --print-config > out.log 2>&1 & pid=$!; wait $pid; st=$?
if [ $st = 0 ] && grep -q "model = marked" out.log && grep -q "ran in pid" marker && ! grep -q "pid $pid\$" marker; then ok
else bad "--print-config ran the constructor in a child (sluice pid $pid; marker: $(cat marker 2>/dev/null))"; fi
SLUICE_TEST_CONSTRUCTOR_CRASH=1 expect "a crashing constructor under --check" 1 \
  "m.ini: --check stopped by SIGSEGV while checking the scene" -- "$sluice" run m.ini --check
rm -f marker

# ---- closures that fail inside a run -----------------------------------------------------------------
# the fault from t = 0.175 on: steps of 0.05, the last good state at t = 0.15
for f in segv:"crashed with SIGSEGV" fpe:"crashed with SIGFPE" fatal:"the test closure gives up at t = 0.2"; do
  name=${f%%:*} msg=${f#*:}
  scene $name.ini $name 0.175 ""
  expect "$name: exit 1, the closure named" 1 \
    "run failed at t = 0.15; the last accepted state, t = 0.15, is saved in $name.h5: at t = 0.15: closure viscosity/faulty \[closure.viscosity\] failed \(fatal, code -3\): $msg" \
    -- "$sluice" run $name.ini -o $name.h5
  grep -q "3 steps (0 rejected)" out.log && ok || bad "$name: stopped at once, no step retried"
  [ "$(last_time $name.h5)" = "t = 0.15" ] && ok || bad "$name: the last good state t = 0.15 saved (got '$(last_time $name.h5)')"
done
scene exit.ini exit 0.175 ""
expect "exit(0) inside a closure: exit 1" 1 \
  "closure viscosity/faulty \[closure.viscosity\] called exit\(\) inside its evaluation; the run did not finish" -- \
  "$sluice" run exit.ini -o exit.h5
scene loop.ini loop 0.175 ""
start=$SECONDS
expect "a looping closure stopped by the call time limit" 1 \
  "closure viscosity/faulty \[closure.viscosity\] failed \(fatal, code -3\): did not return within the call time limit of 0.5 s" \
  -- timeout 60 "$sluice" run loop.ini -o loop.h5 --closure-time-limit 0.5
[ $((SECONDS - start)) -lt 20 ] && ok || bad "the time limit acted within seconds"
[ "$(last_time loop.h5)" = "t = 0.15" ] && ok || bad "loop: the last good state saved"
"$sluice" run loop.ini -o loopint.h5 > out.log 2>&1 & pid=$!
sleep 2; kill -INT $pid; for _ in $(seq 50); do kill -0 $pid 2> /dev/null || break; sleep 0.2; done
if kill -0 $pid 2> /dev/null; then kill -KILL $pid; bad "Ctrl-C stops a looping closure"
else wait $pid; st=$?; [ $st != 0 ] && grep -q "interrupted by SIGINT inside its evaluation" out.log && ok || bad "Ctrl-C: exit $st"; fi
# a steady solve: the same, the state reached saved
scene steady.ini segv 0 ""
sed -i '/^\[time\]/,/^end = /d' steady.ini
expect "steady: a segfault fails the solve by name" 1 \
  "closure viscosity/faulty \[closure.viscosity\] failed \(fatal, code -3\): crashed with SIGSEGV" -- \
  "$sluice" run steady.ini -o steady.h5
# ---- t and dt: the time level being solved and its step ----------------------------------------------
scene clock.ini clock 0 ""
expect "the closure sees t and dt" 0 "closure info: t = 0.5 dt = 0.05" -- "$sluice" run clock.ini -o clock.h5
for t in 0.05 0.1 0.15 0.2 0.25 0.3 0.35 0.4 0.45; do grep -q "closure info: t = $t dt = 0.05\$" out.log || bad "t = $t seen"; done
# the mixture model too (the Kynch column of configs/, 3 steps of 1 s)
sed -e 's/^end = 120/end = 3/' -e 's/^every = 10/every = 1/' -e 's/^cells = 200/cells = 20/' \
  "$src/../../configs/kynch_settling.ini" > mix.ini
printf '\n[closure.viscosity]\nmodel = faulty\nfault = clock\nmu0 = 1e-3\n' >> mix.ini
expect "mixture: the closure sees t and dt" 0 "closure info: t = 3 dt = 1" -- "$sluice" run mix.ini -o mix.h5
grep -q "closure info: t = 1 dt = 1$" out.log && grep -q "closure info: t = 2 dt = 1$" out.log && ok || bad "mixture: t = 1, 2"

# ---- check-closure isolates the battery --------------------------------------------------------------
expect "check-closure: a segfault named" 1 "FAIL viscosity/segv +outputs written: crashed with SIGSEGV \(signal 11\)" -- \
  "$sluice" check-closure "$checkfaults/segv.so"
expect "check-closure: SIGFPE" 1 "FAIL viscosity/fpe +outputs written: crashed with SIGFPE" -- \
  "$sluice" check-closure "$checkfaults/fpe.so"
expect "check-closure: exit(0)" 1 "FAIL viscosity/exit +outputs written: called exit\(0\)" -- \
  "$sluice" check-closure "$checkfaults/exit.so"
expect "check-closure: a hang" 1 "FAIL viscosity/loop +outputs written: did not finish within the time limit of 1 s" -- \
  timeout 60 "$sluice" check-closure "$checkfaults/loop.so" --time-limit 1
expect "check-closure: the good one passes" 0 "^10 passed, 0 failed" -- "$sluice" check-closure "$faulty/viscosity_faulty.so"
# ---- a folder without an index: what its libraries hold is read in a child -------------------------
SLUICE_PLUGIN_PATH="$unindexed" expect "unindexed folder: found by its descriptors" 0 "viscosity +marked .*marked.so" -- \
  "$sluice" run m.ini --check
mkdir -p ix && cp "$unindexed/marked.so" ix/
expect "closure index writes the folder's index" 0 "ix/closures.index: 1 closure" -- "$sluice" closure index ix
grep -qx "viscosity marked marked.so" ix/closures.index && ok || bad "the index line"
rm -f marker
SLUICE_PLUGIN_PATH="$work/ix" expect "an indexed folder: a misspelt name" 2 "did you mean 'marked'" -- \
  "$sluice" run m.ini --check --set closure.viscosity.model=marke
[ ! -e marker ] && ok || bad "no library opened for a misspelt name in an indexed folder"
# an index that names a library that is not there, or does not hold the name
mkdir -p stale && cp "$unindexed/marked.so" stale/
printf 'viscosity marked gone.so\nviscosity other marked.so\n' > stale/closures.index
SLUICE_PLUGIN_PATH="$work/stale" expect "a stale index: the missing library named" 2 \
  "viscosity closure 'marked': its index names .*stale/gone.so, which cannot be used: cannot load" -- "$sluice" run m.ini --check
sed 's/^model = marked$/model = other/' m.ini > other.ini
SLUICE_PLUGIN_PATH="$work/stale" expect "a stale index: the library does not hold it" 2 \
  "viscosity closure 'other': its index names .*stale/marked.so, which does not hold it" -- "$sluice" run other.ini --check
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
