# h5_fields.sh (sourced by test_petsc.sh): two sluice output files compared dataset by dataset with h5dump.
#
# h5_layout A B           exit 0 when both files have the same groups, datasets, types, shapes and attribute names
#                         (h5dump -H: the layout without the values)
# h5_files_diff A B [GA GB]  every dataset under group GA of A (default /) against the same path under GB of B:
#                         the largest difference of a float dataset's values relative to the dataset's largest
#                         value (its size: a field near zero somewhere is measured against the field, not against
#                         itself), printed as "DIFF PATH"; "inf PATH" when a dataset is missing or its shape
#                         differs, "text PATH" when a dataset that is not floats (integers, strings) differs at all
# h5_checkpoint FILE      the group of FILE's current checkpoint (/checkpoint/slot_0 or slot_1)

h5_layout() {
  diff <(h5dump -H "$1" | tail -n +2) <(h5dump -H "$2" | tail -n +2) > /dev/null
}

# h5__dump FILE GROUP: every dataset under GROUP in h5ls's order, a line each: "PATH f|t VALUES...", PATH relative
# to GROUP, f for 64-bit floats (then VALUES are the numbers to 17 digits), t for the rest (VALUES as h5dump prints
# them); one h5dump for all of them
h5__dump() {
  local g=${2%/} paths
  paths=$(h5ls -r "$1$g" 2> /dev/null | awk '$2 == "Dataset" { print $1 }' | sed "s|^|$g|")
  [ -n "$paths" ] || return 0
  # shellcheck disable=SC2046
  h5dump -y -w 0 -m %.17g $(printf -- '-d %s ' $paths) "$1" 2> /dev/null | awk -v g="$g" '
    /^DATASET "/ { p = $0; sub(/^DATASET "/, "", p); sub(/" {$/, "", p); p = substr(p, length(g) + 1); k = "t"; next }
    /^   DATATYPE  H5T_IEEE_F64/ { k = "f"; next }
    /^   DATA {$/ { d = 1; v = ""; next }
    d && /^   }$/ { d = 0; print p, k, v; next }
    d { if (k == "f") gsub(/,/, " "); v = v " " $0 }'
}

h5_files_diff() {
  local t=${TMPDIR:-/tmp}/h5f.$$
  h5__dump "$1" "${3:-/}" > "$t.a"
  h5__dump "$2" "${4:-/}" > "$t.b"
  awk -v B="$t.b" -v g="${3%/}" '
    { if ((getline lb < B) <= 0) { print "inf", $1; bad = 1; exit }
      na = split($0, a, " "); nb = split(lb, b, " ")
      if (a[1] != b[1] || a[2] != b[2] || (a[2] == "f" && na != nb)) { print "inf", $1; bad = 1; exit }
      if (a[2] == "t") { if ($0 != lb) { print "text", $1; bad = 1; exit } next }
      m = 0; s = 0
      for (i = 3; i <= na; ++i) { x = a[i] - b[i]; if (x < 0) x = -x; if (x > m) m = x; y = a[i] < 0 ? -a[i] : a[i]; if (y > s) s = y }
      r = s > 0 ? m / s : m
      if (r > worst || at == "") { worst = r; at = $1 } }
    END { if (bad) exit; if ((getline lb < B) > 0) { print "inf", "(B has more datasets)"; exit }
          if (at == "") print "inf (no datasets)"; else printf "%.3g %s%s\n", worst, g, at }' "$t.a"
  rm -f "$t.a" "$t.b"
}

h5_checkpoint() {
  echo "/checkpoint/slot_$(h5dump -a /checkpoint/current "$1" 2> /dev/null | sed -n 's/^ *(0): *\([01]\) *$/\1/p')"
}
