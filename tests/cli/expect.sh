#!/usr/bin/env bash
# expect.sh CODE PATTERN [PATTERN...] -- COMMAND [ARG...]
# Runs COMMAND; passes when it exits with CODE and its output (stdout and
# stderr together) matches every extended-regex PATTERN.
set -u
code=$1; shift
patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do patterns+=("$1"); shift; done
shift
out=$("$@" 2>&1); rc=$?
fail=0
if [ "$rc" != "$code" ]; then echo "exit status $rc, expected $code"; fail=1; fi
for p in "${patterns[@]}"; do
  if ! grep -Eq -- "$p" <<<"$out"; then echo "output does not match: $p"; fail=1; fi
done
if [ $fail = 1 ]; then printf -- '--- command: %s\n--- output:\n%s\n' "$*" "$out"; echo "0 passed, 1 failed"; exit 1; fi
echo "1 passed, 0 failed"
