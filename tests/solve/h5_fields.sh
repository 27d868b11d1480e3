# h5_fields.sh (sourced by test_petsc.sh): two sluice output files compared dataset by dataset with h5dump.
#
# h5_layout A B           exit 0 when both files have the same groups, datasets, types, shapes and attribute names
#                         (h5dump -H: the layout without the values)
# h5_field_diff A PA B PB the largest difference between dataset PA of A and PB of B, relative to the largest
#                         value of PA (its size: a field near zero somewhere is measured against the field, not
#                         against itself); "inf" when the shapes differ, "text" for a non-float dataset whose
#                         values differ (those must be equal)
# h5_files_diff A B [GA GB]  the largest h5_field_diff over every float dataset under group GA of A (default /)
#                         against the same path under GB of B, printed as "DIFF PATH" (the worst first)
# h5_checkpoint FILE      the group of FILE's current checkpoint (/checkpoint/slot_0 or slot_1)

h5_layout() {
  diff <(h5dump -H "$1" | tail -n +2) <(h5dump -H "$2" | tail -n +2) > /dev/null
}

h5__values() { # FILE PATH OUT: the values, one a line, 17 digits
  h5dump -d "$2" -y -w 0 -m %.17g -o "$3" "$1" > /dev/null 2>&1 || return 1
  tr -d ' ,' < "$3" | grep -v '^$' > "$3.v" && mv "$3.v" "$3"
}

h5_field_diff() {
  local t=${TMPDIR:-/tmp}/h5f.$$
  if ! h5__values "$1" "$2" "$t.a" || ! h5__values "$3" "$4" "$t.b"; then echo inf; rm -f "$t.a" "$t.b"; return; fi
  if ! h5dump -H -d "$2" "$1" | grep -q "H5T_IEEE_F64"; then
    if cmp -s "$t.a" "$t.b"; then echo 0; else echo text; fi
  else
    paste -d' ' "$t.a" "$t.b" | awk 'NF != 2 { bad = 1 }
        { d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d; a = $1 < 0 ? -$1 : $1; if (a > s) s = a }
        END { if (bad) print "inf"; else printf "%.3g\n", (s > 0 ? m / s : m) }'
  fi
  rm -f "$t.a" "$t.b"
}

h5_files_diff() {
  local a=$1 b=$2 ga=${3:-/} gb=${4:-/} p q worst=0 at=none r
  ga=${ga%/} gb=${gb%/}
  while read -r p; do
    q=$gb${p#"$ga"}
    r=$(h5_field_diff "$a" "$p" "$b" "$q")
    case $r in
    inf | text) echo "$r $p"; return ;;
    esac
    if awk -v x="$r" -v y="$worst" 'BEGIN { exit !(x + 0 > y + 0) }'; then worst=$r at=$p; fi
  done < <(h5ls -r "$a$ga" 2>/dev/null | awk '$2 == "Dataset" { print $1 }' | sed "s|^|$ga|; s|^//|/|")
  echo "$worst $at"
}

h5_checkpoint() {
  echo "/checkpoint/slot_$(h5dump -a /checkpoint/current "$1" 2> /dev/null | sed -n 's/^ *(0): *\([01]\) *$/\1/p')"
}
