#!/usr/bin/env bash
# test_output_files.sh SLUICE SOURCE_DIR WORK: what `sluice run` may write.
# A file sluice did not write is refused (exit 2, left as it was) unless
# --overwrite; -o SCENE.ini never destroys the scene, not even with
# --overwrite; a scene's [output] file outside its folder and the working
# folder is refused, the same path with -o is not; [output] file = "" is
# refused; --summary-json writes the run's summary; `sample --scalars`
# prints what OUT_scalars.csv holds.
set -u
S=$1; SRC=$2; W=$3
rm -rf "$W"; mkdir -p "$W/scenes" && cd "$W" || exit 1
cp "$SRC/configs/fluidized_bed.ini" scenes/bed.ini
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAILED: $1"; fail=$((fail + 1)); fi; }

echo "my notes" > notes.h5
"$S" run scenes/bed.ini -o notes.h5 > out1.txt 2>&1; rc=$?
check "a foreign file is refused with exit 2" '[ $rc = 2 ] && grep -q "notes.h5. exists and was not written by sluice" out1.txt'
check "and left as it was" '[ "$(cat notes.h5)" = "my notes" ] && [ ! -e notes.h5.tmp ] && [ ! -e notes.xmf ]'
"$S" run scenes/bed.ini -o notes.h5 --overwrite > out2.txt 2>&1; rc=$?
check "--overwrite replaces it" '[ $rc = 0 ] && "$S" sample notes.h5 --list > /dev/null'
"$S" run scenes/bed.ini -o notes.h5 > out3.txt 2>&1; rc=$?
check "sluice's own output is replaced without the flag" '[ $rc = 0 ]'

cp scenes/bed.ini keep.ini
for flag in "" --overwrite; do
  "$S" run scenes/bed.ini -o scenes/bed.ini $flag > out4.txt 2>&1; rc=$?
  check "-o SCENE.ini $flag refused" '[ $rc = 2 ] && grep -q "is the scene file .* itself: it is never replaced" out4.txt'
  check "-o SCENE.ini $flag leaves the scene" 'cmp -s scenes/bed.ini keep.ini'
done

printf '[output]\nevery = 10\n' > scenes/common.ini
printf 'include = common.ini\n' | cat - scenes/bed.ini > scenes/with_include.ini
cp scenes/common.ini common_keep.ini
"$S" run scenes/with_include.ini -o scenes/common.ini --overwrite > out4b.txt 2>&1; rc=$?
check "-o an included file refused, also with --overwrite" \
  '[ $rc = 2 ] && grep -q "which the scene includes: it is never replaced" out4b.txt && cmp -s scenes/common.ini common_keep.ini'

other=$(mktemp -d)
"$S" run scenes/bed.ini --set "output.file=$other/bed.h5" > out5.txt 2>&1; rc=$?
check "[output] file outside the scene's folder and the working folder refused" \
  '[ $rc = 2 ] && grep -q "outside the scene.s folder scenes and the working folder" out5.txt && [ ! -e "$other/bed.h5" ]'
"$S" run scenes/bed.ini -o "$other/bed.h5" > out6.txt 2>&1; rc=$?
check "the same path with -o is the user's choice" '[ $rc = 0 ] && [ -e "$other/bed.h5" ]'
"$S" run scenes/bed.ini --set "output.file=$other/bed2.h5" --check > out5b.txt 2>&1; rc=$?
check "--check finds it too" '[ $rc = 2 ] && grep -q "outside the scene.s folder" out5b.txt'
rm -rf "$other"
"$S" run scenes/bed.ini --set "output.file=scenes/bed_out.h5" > out7.txt 2>&1; rc=$?
check "[output] file in the scene's folder" '[ $rc = 0 ] && [ -e scenes/bed_out.h5 ] && [ -e scenes/bed_out_scalars.csv ]'
"$S" run scenes/bed.ini --set 'output.file=""' > out8.txt 2>&1; rc=$?
check "[output] file = \"\" refused" '[ $rc = 2 ] && grep -q "\[output\] file = \"\": the file name is empty" out8.txt'

"$S" run scenes/bed.ini -o bed.h5 --summary-json bed.json > out9.txt 2>&1; rc=$?
check "--summary-json" '[ $rc = 0 ] && grep -q "\"status\": \"done\"" bed.json && grep -q "\"output\": \"bed.h5\"" bed.json'
if command -v python3 > /dev/null; then
  check "--summary-json is JSON" 'python3 -c "import json,sys; d=json.load(open(\"bed.json\")); sys.exit(0 if d[\"exit_code\"] == 0 and d[\"steps\"] > 0 else 1)"'
fi
"$S" run scenes/bed.ini -o bed2.h5 --set two_fluid.nosuch=1 --summary-json bad.json > /dev/null 2>&1; rc=$?
check "--summary-json of bad input" '[ $rc = 2 ] && grep -q "\"status\": \"bad input\"" bad.json && grep -q "nosuch" bad.json'
"$S" sample bed.h5 --scalars > scalars.txt 2> /dev/null; rc=$?
check "sample --scalars prints OUT_scalars.csv" '[ $rc = 0 ] && cmp -s scalars.txt bed_scalars.csv'
check "sample --list names the scalars" '"$S" sample bed.h5 --list | grep -q "^scalars (3; --scalars prints them): solids_inventory \[m\],"'
check "the scalars' header has units" 'head -1 bed_scalars.csv | grep -q "^time \[s\],solids_inventory \[m\],"'
check "the .xmf has the scalars as grid attributes" 'grep -q "Name=\"solids_inventory\" AttributeType=\"Scalar\" Center=\"Grid\"" bed.xmf'
check "no temporaries left" '[ -z "$(ls *.tmp scenes/*.tmp 2> /dev/null)" ]'
echo "$pass passed, $fail failed"
[ $fail = 0 ]
