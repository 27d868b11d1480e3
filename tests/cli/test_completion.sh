#!/usr/bin/env bash
# Every command `sluice --help` lists and every option each command's --help
# prints is offered by the bash completion (core/cli/completion.bash), and
# every command has a section in the man page. Arguments: SLUICE COMPLETION MANPAGE.
set -u
sluice=$1 completion=$2 man=$3
source "$completion"
fail=0 n=0
complete_words() { COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); COMPREPLY=(); _sluice; echo " ${COMPREPLY[*]} "; }
commands=$("$sluice" --help | sed -n 's/^  \([a-z-]*\) .*/\1/p' | sort -u)
for c in $commands; do
  n=$((n + 1))
  case $(complete_words sluice "") in *" $c "*) ;; *) echo "command $c not completed"; fail=1 ;; esac
  grep -q "^\.SS $c\$" "$man" || { echo "command $c has no section in the man page"; fail=1; }
  for o in $("$sluice" "$c" --help | grep -oE '(^|[ [])--?[a-z][a-z-]*' | tr -d ' [' | sort -u); do
    n=$((n + 1))
    case $c in model|closure) first=$([ "$c" = model ] && echo describe || echo eval) ;; *) first="" ;; esac
    if [ -n "$first" ]; then got=$(complete_words sluice "$c" "$first" "-"); else got=$(complete_words sluice "$c" "-"); fi
    case $got in *" $o "*) ;; *) echo "sluice $c: option $o not completed"; fail=1 ;; esac
  done
done
echo "$n names checked"
[ $fail = 0 ] && echo "1 passed, 0 failed" || { echo "0 passed, 1 failed"; exit 1; }
