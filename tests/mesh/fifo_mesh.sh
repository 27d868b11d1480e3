#!/usr/bin/env bash
# fifo_mesh.sh SLUICE SCENE FOLDER: runs SCENE --check with a FIFO (no writer) as its mesh file; sluice must refuse
# it at once (exit 2), not wait for a writer. The exit status is sluice's (124 when it hung for 20 s).
f="$3/mesh.fifo"
rm -f "$f"
mkfifo "$f" || exit 1
timeout 20 "$1" run "$2" --check --set mesh.file="$f"
rc=$?
rm -f "$f"
exit $rc
