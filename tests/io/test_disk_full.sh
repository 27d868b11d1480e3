#!/usr/bin/env bash
# test_disk_full.sh SLUICE SOURCE_DIR WORK: a disk that fills up at the first
# checkpoint, simulated by the file size limit (ulimit -f, with SIGXFSZ
# ignored, so writes fail with EFBIG as on a full disk). The run exits 1 (not
# 139: HDF5 1.10 crashed in its exit handler after a failed write), says
# what did not fit, and leaves a readable file with the output time it
# wrote. A limit reached while writing the mesh removes the new file and
# leaves the earlier result as it was.
set -u
S=$1; SRC=$2; W=$3
rm -rf "$W"; mkdir -p "$W" && cd "$W" || exit 1
scene="$SRC/configs/cavity_stokes.ini"
pass=0; fail=0
check() { if eval "$2"; then pass=$((pass + 1)); else echo "FAILED: $1"; fail=$((fail + 1)); fi; }
run_limited() { # KiB, then the run's arguments
  local kib=$1; shift
  bash -c 'trap "" XFSZ; ulimit -f "$0"; exec "$@"' "$kib" "$S" run "$scene" --set mesh.cells=64 "$@"
}
# 64 x 64 Q9 cells: about 1.2 MB after the first output time, 0.6 MB more for its checkpoint
run_limited 1700 -o full.h5 > full.txt 2>&1; rc=$?
check "exit 1, not a crash (got $rc)" '[ $rc = 1 ]'
check "the message names what did not fit" 'grep -q "no room to write the checkpoint: it needs about .* MB and the file size limit" full.txt'
check "the file is readable, with t = 0" '"$S" sample full.h5 --list 2>/dev/null | grep -q "^times (1 step): 0$"'
check "h5dump reads it" '! command -v h5dump > /dev/null || h5dump -H full.h5 > /dev/null'
check "its .xmf lists it" 'grep -q "step_000000" full.xmf'

"$S" run "$scene" --set mesh.cells=8 -o kept.h5 > /dev/null 2>&1
sum0=$(cksum < kept.h5)
run_limited 400 -o kept.h5 > kept.txt 2>&1; rc=$?
check "limit at the mesh: exit 1 (got $rc)" '[ $rc = 1 ] && grep -q "no room to write the mesh" kept.txt'
check "the message does not claim a saved state" '! grep -q "last state saved" kept.txt'
check "the earlier result is as it was" '[ "$(cksum < kept.h5)" = "$sum0" ] && [ ! -e kept.h5.tmp ]'
echo "$pass passed, $fail failed"
[ $fail = 0 ]
