# bash completion for sluice (installed as share/bash-completion/completions/sluice).
# Commands, their options, scene and output files; after --set, the sections
# of the scene on the line; after `closure describe|eval`, the closure names.
_sluice() {
  local cur prev cmd
  cur=${COMP_WORDS[COMP_CWORD]}
  prev=${COMP_WORDS[COMP_CWORD-1]}
  cmd=${COMP_WORDS[1]}
  local commands="run model closures closure check-closure sample bench version help"
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "$commands --help" -- "$cur"))
    return
  fi
  case $cmd in
    run)
      case $prev in
        -o|--restart) COMPREPLY=($(compgen -f -X '!*.h5' -- "$cur")); return ;;
        --closure-time-limit) return ;;
        --summary-json) COMPREPLY=($(compgen -f -- "$cur")); return ;;
        --set)
          local scene w
          for w in "${COMP_WORDS[@]:2}"; do case $w in *.ini) scene=$w ;; esac; done
          if [ -n "$scene" ] && [ -r "$scene" ]; then
            COMPREPLY=($(compgen -W "$(sed -n 's/^\[\(.*\)\].*/\1./p' "$scene")" -- "$cur"))
            compopt -o nospace 2>/dev/null
          fi
          return ;;
      esac
      COMPREPLY=($(compgen -W "--set --print-config --check --profile --monitor --petsc --restart -o --overwrite --summary-json --allow-plugin-path --closure-time-limit --help" -- "$cur"))
      [[ $cur != -* ]] && COMPREPLY+=($(compgen -f -X '!*.ini' -- "$cur") $(compgen -d -- "$cur"))
      ;;
    sample)
      COMPREPLY=($(compgen -W "--field --time --line --n --point --list --scalars --help" -- "$cur"))
      [[ $cur != -* ]] && COMPREPLY+=($(compgen -f -X '!*.h5' -- "$cur") $(compgen -d -- "$cur"))
      ;;
    bench)
      [ "$prev" = -o ] && { COMPREPLY=($(compgen -d -- "$cur")); return; }
      COMPREPLY=($(compgen -W "-o --keep --check --allow-plugin-path --help" -- "$cur"))
      [[ $cur != -* ]] && COMPREPLY+=($(compgen -f -X '!*.ini' -- "$cur") $(compgen -d -- "$cur"))
      ;;
    model)
      if [ "$COMP_CWORD" -eq 2 ]; then
        COMPREPLY=($(compgen -W "list describe --help" -- "$cur"))
      else
        COMPREPLY=($(compgen -W "$(sluice model list 2>/dev/null | awk '{print $1}') --variant --markdown --all" -- "$cur"))
      fi
      ;;
    closure)
      if [ "$COMP_CWORD" -eq 2 ]; then
        COMPREPLY=($(compgen -W "describe eval kinds new index --help" -- "$cur"))
      elif [ "${COMP_WORDS[2]}" = kinds ] || { [ "${COMP_WORDS[2]}" = new ] && [ "$COMP_CWORD" -eq 3 ]; }; then
        COMPREPLY=($(compgen -W "$(sluice closure kinds 2>/dev/null | sed -n 's/^\([a-z_]*\): .*/\1/p') --markdown" -- "$cur"))
      elif [ "${COMP_WORDS[2]}" = new ]; then
        [ "$prev" = -o ] && { COMPREPLY=($(compgen -d -- "$cur")); return; }
        COMPREPLY=($(compgen -W "-o" -- "$cur"))
      else
        COMPREPLY=($(compgen -W "$(sluice closures 2>/dev/null | awk 'NR > 1 {print $2}') --all --markdown --at --set --deriv -o" -- "$cur"))
      fi
      ;;
    check-closure)
      COMPREPLY=($(compgen -W "--quiet --time-limit --help" -- "$cur"))
      [[ $cur != -* ]] && COMPREPLY+=($(compgen -f -X '!*.so' -- "$cur") $(compgen -d -- "$cur"))
      ;;
  esac
}
complete -F _sluice sluice
