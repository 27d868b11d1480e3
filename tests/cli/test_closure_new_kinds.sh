#!/usr/bin/env bash
# Every kind `sluice closure kinds` lists has a template (`sluice closure new
# KIND NAME`) that compiles warning-free as C11 and passes every check of the
# conformance battery as written. Arguments: SLUICE INCLUDE_DIR WORK_DIR CC.
set -u
sluice=$1 inc=$2 work=$3 cc=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
pass=0 fail=0
kinds=$("$sluice" closure kinds | sed -n 's/^\([a-z_]*\): .*/\1/p')
n_kinds=$(wc -w <<<"$kinds")
[ "$n_kinds" -ge 8 ] || { echo "expected every kind (8 or more), got: $kinds"; exit 1; }
for k in $kinds; do
  if "$sluice" closure new "$k" "t_$k" -o "t_$k" > /dev/null &&
     "$cc" -std=c11 -Wall -Wextra -Werror -pedantic -shared -fPIC -fvisibility=hidden -I"$inc" "t_$k/t_$k.c" \
       -o "t_$k/t_$k.so" -lm > "t_$k.build.log" 2>&1 &&
     "$sluice" check-closure "t_$k/t_$k.so" > "t_$k.check.log" &&
     grep -q "^10 passed, 0 failed$" "t_$k.check.log" && grep -q "^ok   $k/t_$k  *reference values: 1 values" "t_$k.check.log"; then
    pass=$((pass+1))
  else
    fail=$((fail+1)); echo "failed: the $k template"; cat "t_$k.build.log" "t_$k.check.log" 2>/dev/null
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
