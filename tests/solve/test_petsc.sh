#!/usr/bin/env bash
# test_petsc.sh SLUICE CONFIGS: the PETSc backend against the direct solvers, its options and the scene's limits.
# The Stokes cavity (steady saddle point: FGMRES, Schur field split, BoomerAMG) against KLU along both centre
# lines; the boycott vessel (the mixture, transient steps) with fixed steps against KLU; the options given
# on the command line, in [solver.petsc] and in PETSC_OPTIONS, in that order of precedence; what a scene
# may not set; and under mpirun: 1, 2, 3 (and 4) ranks against the serial answer, each rank assembling 1/N of the
# cells (the closure points rank 0 evaluates) and keeping only its own rows, the ranks writing the one output file
# together (parallel HDF5, each its block of every dataset), a failure to open the output stopping every rank, a
# restart on another number of ranks.
set -u
sluice=$1 configs=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
pass=0 fail=0
check() { # check NAME CONDITION...
  local name=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "failed: $name"; fi
}
# the largest difference of two sample tables' value columns (from column 4), relative to the largest value
max_diff() {
  paste -d, "$1" "$2" | awk -F, -v n="$3" 'NR > 1 {
      for (c = 4; c <= n; ++c) { a = $c; b = $(c + n); d = a - b; if (d < 0) d = -d; if (d > m) m = d;
        if (a < 0) a = -a; if (a > s) s = a } }
      END { printf "%.3g\n", (s > 0 ? m / s : m) }'
}
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

cav=$configs/cavity_stokes.ini
"$sluice" run "$cav" --set solver.linear=klu -o klu.h5 > klu.log 2>&1
"$sluice" run "$cav" --set solver.linear=petsc -o petsc.h5 > petsc.log 2>&1
check "cavity: petsc ran its default (fgmres/fieldsplit)" grep -q "fgmres/fieldsplit" petsc.log
# the velocity on x = 1/2, the pressure on y = 3/4 (it is odd about x = 1/2)
"$sluice" sample klu.h5 --field velocity --line 0.5,0:0.5,1 --n 65 > k_velocity.csv 2>/dev/null
"$sluice" sample petsc.h5 --field velocity --line 0.5,0:0.5,1 --n 65 > p_velocity.csv 2>/dev/null
"$sluice" sample klu.h5 --field pressure --line 0,0.75:1,0.75 --n 65 > k_pressure.csv 2>/dev/null
"$sluice" sample petsc.h5 --field pressure --line 0,0.75:1,0.75 --n 65 > p_pressure.csv 2>/dev/null
cp k_velocity.csv k_velocity_cav.csv
dv=$(max_diff k_velocity.csv p_velocity.csv 6) dp=$(max_diff k_pressure.csv p_pressure.csv 4)
echo "cavity: velocity on x = 1/2 differs by $dv, pressure on y = 3/4 by $dp (relative to the largest value)"
check "cavity velocity agrees to the solver tolerance ($dv)" below "$dv" 1e-8
# the residual's 1e-10 bounds the pressure's error only through the inf-sup constant (measured 4.5e-8 here)
check "cavity pressure agrees to the solver tolerance ($dp)" below "$dp" 1e-7

box=$configs/boycott.ini
# the monolithic step on every rank count (the split step is compared apart below): the comparisons are of the
# linear solvers and the ranks, not of the schemes
args=(--set mesh.cells=12,16 --set time.end=0.05 --set output.every=0.05 --set time.adaptive=false --set flow.scheme=monolithic)
"$sluice" run "$box" "${args[@]}" --set solver.linear=klu -o bk.h5 > bk.log 2>&1
"$sluice" run "$box" "${args[@]}" --set solver.linear=petsc -o bp.h5 > bp.log 2>&1
for f in velocity phi; do
  "$sluice" sample bk.h5 --field $f --line 0.5,0.1:1.2,0.9 --n 41 > k_$f.csv 2>/dev/null
  "$sluice" sample bp.h5 --field $f --line 0.5,0.1:1.2,0.9 --n 41 > p_$f.csv 2>/dev/null
done
dv=$(max_diff k_velocity.csv p_velocity.csv 6) dphi=$(max_diff k_phi.csv p_phi.csv 4)
echo "boycott, 50 fixed steps: velocity differs by $dv, phi by $dphi"
check "boycott ran to its end with petsc" grep -q "reached the end time\|end time" bp.log
check "boycott velocity agrees ($dv)" below "$dv" 1e-9
check "boycott phi agrees ($dphi)" below "$dphi" 1e-9

# options: the command line over the scene, PETSC_OPTIONS over both
cat > scene.ini <<INI
include = $cav
[solver]
linear = petsc
[solver.petsc]
ksp_type = gmres
ksp_gmres_restart = 100
INI
"$sluice" run scene.ini -o s.h5 > s.log 2>&1
check "[solver.petsc] ksp_type = gmres is used" grep -q "(gmres/fieldsplit" s.log
"$sluice" run scene.ini -o s.h5 --petsc "-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps" > m.log 2>&1
check "--petsc wins over the scene (MUMPS)" grep -q "(preonly/lu" m.log
PETSC_OPTIONS="-ksp_type bcgs" "$sluice" run scene.ini -o s.h5 --petsc "-ksp_type preonly" > e.log 2>&1
check "PETSC_OPTIONS wins over both" grep -q "(bcgs/fieldsplit" e.log
"$sluice" run "$cav" --set solver.linear=petsc -o u.h5 --petsc "-ksp_monitor" > mon.log 2>&1
check "--petsc -ksp_monitor prints PETSc's residuals" grep -q "KSP Residual norm" mon.log

"$sluice" run "$cav" --set solver.linear=petsc -o u.h5 --petsc "-log_view :log_view.txt" > lv.log 2>&1
check "--petsc -log_view writes PETSc's performance summary (exit 0)" grep -q "^KSPSolve" log_view.txt

# a scene may not write or print through PETSc, nor pass anything but a solver option
for bad in "ksp_monitor = true" "log_view = true" "ksp_view = ascii:/tmp/x" "fieldsplit_u_ksp_view_solution = binary" \
           "options_file = x" "on_error_attach_debugger = gdb" "pc_type = lu:x"; do
  printf 'include = %s\n[solver]\nlinear = petsc\n[solver.petsc]\n%s\n' "$cav" "$bad" > bad.ini
  out=$("$sluice" run bad.ini -o bad.h5 2>&1); rc=$?
  check "refused from a scene: $bad (exit $rc)" test "$rc" = 2
  check "its message names the file and line: $bad" grep -q "bad.ini:5" <<<"$out"
  check "nothing written for: $bad" test ! -e bad.h5
done
# several ranks (mpirun): the linear solves shared, the file written by all ranks; the same answer as KLU on one rank
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  for n in 1 2 3; do
    mpirun -n $n "$sluice" run "$cav" --set solver.linear=petsc -o c$n.h5 --profile > c$n.log 2>&1
    "$sluice" sample c$n.h5 --field velocity --line 0.5,0:0.5,1 --n 65 > c$n.csv 2>/dev/null
    dv=$(max_diff k_velocity_cav.csv c$n.csv 6)
    echo "cavity on $n rank(s): velocity differs from KLU's by $dv"
    check "cavity on $n rank(s) agrees with KLU ($dv)" below "$dv" 1e-7
    mpirun -n $n "$sluice" run "$box" "${args[@]}" --set solver.linear=petsc -o b$n.h5 > b$n.log 2>&1
    "$sluice" sample b$n.h5 --field phi --line 0.5,0.1:1.2,0.9 --n 41 > b$n.csv 2>/dev/null
    "$sluice" sample b$n.h5 --field velocity --line 0.5,0.1:1.2,0.9 --n 41 > bu$n.csv 2>/dev/null
    dphi=$(max_diff k_phi.csv b$n.csv 4)
    echo "boycott on $n rank(s): phi differs from KLU's by $dphi"
    check "boycott on $n rank(s) agrees with KLU ($dphi)" below "$dphi" 1e-9
  done
  # against the 1-rank PETSc run, to the serial comparisons' tolerances: the cavity's velocity, the boycott's
  # velocity (each rank holding only its own rows, Newton's norms summed over the ranks)
  for n in 2 3; do
    dv=$(max_diff c1.csv c$n.csv 6) dbu=$(max_diff bu1.csv bu$n.csv 6)
    echo "on $n ranks against 1 rank: cavity velocity differs by $dv, boycott velocity by $dbu"
    check "cavity on $n ranks agrees with 1 rank ($dv)" below "$dv" 1e-8
    check "boycott velocity on $n ranks agrees with 1 rank ($dbu)" below "$dbu" 1e-9
  done
  # each rank keeps only its own rows: the rows the ranks own hold together exactly the entries of the serial
  # matrix (PETSc's on one rank, -ksp_view; none lost, none counted twice), and rank 0's matrix is its share,
  # 1/N of them and its border with rank 1 (under 10 % more on this 32 x 32 mesh), not the whole
  "$sluice" run "$cav" --set solver.linear=petsc -o kv.h5 --petsc "-ksp_view" > kv.log 2>&1
  nnz1=$(sed -n 's/^ *total: nonzeros=\([0-9]*\),.*/\1/p' kv.log | tail -n 1)
  rows1=$(sed -n 's/^ *rows=\([0-9]*\), cols=.*/\1/p' kv.log | tail -n 1)
  for n in 2 3; do
    line=$(grep "profile: rows on $n ranks" c$n.log)
    own=$(sed -n 's/.*this rank owns \([0-9]*\) of \([0-9]*\) rows.*/\1 \2/p' <<<"$line")
    ent=$(sed -n 's/.*its matrix \([0-9]*\) entries, \([0-9]*\) of them in its rows, of \([0-9]*\) in all.*/\1 \3/p' <<<"$line")
    read -r own_rows all_rows <<<"$own"
    read -r here all <<<"$ent"
    echo "cavity on $n ranks: rank 0 owns ${own_rows:-?} of ${all_rows:-?} rows, holds ${here:-?} of ${all:-?} entries (serial: ${rows1:-?} rows, ${nnz1:-?} entries)"
    check "$n ranks: the ranks' own rows hold the serial matrix's ${nnz1:-?} entries (${all:-?})" \
      test -n "$nnz1" -a "${all:-x}" = "$nnz1" -a "${all_rows:-x}" = "$rows1"
    check "$n ranks: rank 0 holds its share of the entries (${here:-?} of ${all:-?})" \
      test -n "$here" -a "$((10 * n * ${here:-0}))" -lt "$((11 * ${all:-0}))" -a "$((10 * n * ${own_rows:-0}))" -lt "$((11 * ${all_rows:-0}))"
  done
  # the cells partitioned by their graph (PT-Scotch through PETSc's MatPartitioning) against the blocks of the
  # numbering (strips of rows; -mat_partitioning_type current keeps each cell on the rank its graph row is
  # on): on 4 ranks of the 32 x 32 cavity the border (the owned rows' entries in other ranks' columns, summed
  # over the ranks) is under 0.8 of the strips' (a square's quadrants against 3 cuts across it: 2/3), and the
  # velocity is the 1-rank run's to the same tolerance as on 2 and 3 ranks
  border() { sed -n 's/.*border: [0-9]* of its rows. entries in other ranks. columns, \([0-9]*\) on all ranks.*/\1/p' "$1"; }
  mpirun -n 4 "$sluice" run "$cav" --set solver.linear=petsc -o c4.h5 --profile > c4.log 2>&1
  PETSC_OPTIONS="-mat_partitioning_type current" \
    mpirun -n 4 "$sluice" run "$cav" --set solver.linear=petsc -o c4s.h5 --profile > c4s.log 2>&1
  "$sluice" sample c4.h5 --field velocity --line 0.5,0:0.5,1 --n 65 > c4.csv 2>/dev/null
  b4=$(border c4.log) b4s=$(border c4s.log) dv=$(max_diff c1.csv c4.csv 6)
  echo "cavity on 4 ranks: border ${b4:-?} entries partitioned, ${b4s:-?} in strips; velocity differs from 1 rank's by $dv"
  check "4 ranks: the partition's border is under 0.8 of the strips' (${b4:-?} of ${b4s:-?})" \
    test -n "$b4" -a -n "$b4s" -a "$((10 * ${b4:-0}))" -lt "$((8 * ${b4s:-0}))"
  check "cavity on 4 ranks agrees with 1 rank ($dv)" below "$dv" 1e-8
  # partitioned assembly: each rank assembles its own part of the cells and calls the closures there alone. The
  # Bingham cavity at 12 x 12 cells (144, divisible by 2 and 3), one continuation stage, no cell fields: rank
  # 0's viscosity points (--profile) are exactly 1/N of the serial run's, and the velocity is the serial one's
  # to the solver tolerance
  bq=(--set solver.linear=petsc --set mesh.cells=12,12 --set closure.viscosity.eps=0.5
      --set solver.continuation_steps=1 --set solver.continuation_from=0.5 --set output.fields=velocity,pressure)
  points() { sed -n "s|.*closure $1.* \([0-9][0-9]*\) points .*|\1|p" "$2"; }
  for n in 1 2 3; do
    mpirun -n $n "$sluice" run "$configs/bingham_cavity.ini" "${bq[@]}" -o bq$n.h5 --profile > bq$n.log 2>&1
    "$sluice" sample bq$n.h5 --field velocity --line 0.5,0:0.5,1 --n 33 > bq$n.csv 2>/dev/null
  done
  # points per assembly (matrix and right-hand side), should the ranks' Newton take a different number
  per_assembly() {
    local p a
    p=$(points "$1" "$2")
    a=$(sed -n "s|.*assemblies: \([0-9]*\) matrix, \([0-9]*\) right-hand-side.*|\1 + \2|p" "$2" | head -n 1)
    a=$(( ${a:-0} ))
    echo $(( ${p:-0} / (a > 0 ? a : 1) ))
  }
  p1=$(per_assembly viscosity/bingham bq1.log) p2=$(per_assembly viscosity/bingham bq2.log)
  p3=$(per_assembly viscosity/bingham bq3.log)
  echo "bingham cavity: viscosity points per assembly on rank 0: $p1 (1 rank), $p2 (2 ranks), $p3 (3 ranks)"
  check "1 rank evaluates the viscosity at 144 cells x 9 points an assembly ($p1)" test "$p1" = 1296
  check "2 ranks: rank 0 evaluates half the viscosity points ($p2 of $p1)" test "$((2 * p2))" = "$p1"
  check "3 ranks: rank 0 evaluates a third ($p3 of $p1)" test "$((3 * p3))" = "$p1"
  for n in 2 3; do
    dv=$(max_diff bq1.csv bq$n.csv 6)
    echo "bingham cavity on $n ranks: velocity differs from 1 rank's by $dv"
    check "bingham cavity on $n ranks agrees with 1 rank ($dv)" below "$dv" 1e-8
  done
  # the mixture (boycott): its flow's viscosity closure, V = A / N + F on rank 0 (A: the assembly's points, F:
  # the passes over every cell for the written cell fields): A and F from 2 and 3 ranks give 1 rank's count
  for n in 1 2 3; do
    mpirun -n $n "$sluice" run "$box" "${args[@]}" --set solver.linear=petsc -o bv$n.h5 --profile > bv$n.log 2>&1
  done
  v1=$(points viscosity/krieger bv1.log) v2=$(points viscosity/krieger bv2.log) v3=$(points viscosity/krieger bv3.log)
  a=$((6 * (${v2:-0} - ${v3:-0}))) f=$((${v2:-0} - 3 * (${v2:-0} - ${v3:-0})))
  echo "boycott: viscosity points on rank 0: $v1, $v2, $v3 on 1, 2, 3 ranks (assembly $a, other passes $f)"
  check "boycott: rank 0 assembles 1/N of the cells' viscosity (A + F = $((a + f)), 1 rank $v1)" \
    test "$((a + f))" = "${v1:-x}" -a "$a" -gt "$((10 * f))"
  # a checkpoint written on one rank continues on two: the same state as the run without a stop
  "$sluice" run "$box" "${args[@]/time.end=0.05/time.end=0.1}" -o whole.h5 > whole.log 2>&1
  "$sluice" run "$box" "${args[@]}" -o half.h5 > half.log 2>&1
  mpirun -n 2 "$sluice" run "$box" "${args[@]/time.end=0.05/time.end=0.1}" --restart half.h5 -o cont.h5 > cont.log 2>&1
  "$sluice" sample whole.h5 --field phi --line 0.5,0.1:1.2,0.9 --n 41 > whole.csv 2>/dev/null
  "$sluice" sample cont.h5 --field phi --line 0.5,0.1:1.2,0.9 --n 41 > cont.csv 2>/dev/null
  dphi=$(max_diff whole.csv cont.csv 4)
  check "restart of a 1-rank checkpoint on 2 ranks continues the run ($dphi)" below "$dphi" 1e-9
  check "... on 2 ranks" grep -q "2 ranks)" cont.log
  check "no rank wrote a private folder" test -z "$(ls -A | grep sluice-rank)"
  # the ranks write the one file together (parallel HDF5): rank 0 wrote its block of every dataset's rows, 1/N
  # of the values' bytes (fields, mesh, checkpoints) within 2 % (its blocks are the floors of n / N), in
  # collective transfers; before, rank 0 wrote all of them alone
  for n in 2 3; do
    read -r here all coll <<<"$(sed -n "s/.*output on $n ranks: this rank wrote \([0-9]*\) of the \([0-9]*\) bytes.* in \([0-9]*\) collective.*/\1 \2 \3/p" c$n.log)"
    echo "cavity on $n ranks: rank 0 wrote ${here:-?} of the ${all:-?} bytes of values, in ${coll:-?} collective transfers"
    check "$n ranks: rank 0 wrote 1/$n of the file's values (${here:-?} of ${all:-?})" \
      test -n "$here" -a "$((50 * (n * ${here:-0} - ${all:-0})))" -le "${all:-0}" -a "$((50 * (${all:-0} - n * ${here:-0})))" -le "${all:-0}"
    check "$n ranks: in collective transfers (${coll:-?})" test "${coll:-0}" -gt 0
  done
  # the ranks write no more files than one does: a run on 2 ranks in a folder of its own leaves the files a run on 1 leaves, with
  # the same contents (h5diff: every value within a relative 1e-8, the solver's tolerance; the sidecar the same
  # text, the scalars' CSV within 1e-8)
  mkdir one two
  (cd one && "$sluice" run "$box" "${args[@]}" --set solver.linear=petsc -o b.h5 > ../one.log 2>&1)
  (cd two && mpirun -n 2 "$sluice" run "$box" "${args[@]}" --set solver.linear=petsc -o b.h5 > ../two.log 2>&1)
  check "2 ranks: the files of 1 rank and no others ($(ls -A two | tr '\n' ' '))" \
    test "$(ls -A one)" = "$(ls -A two)" -a "$(ls -A one | tr '\n' ' ')" = "b.h5 b.xmf b_scalars.csv "
  if command -v h5diff > /dev/null; then
    check "2 ranks: the output equals 1 rank's (h5diff -p 1e-8)" h5diff -p 1e-8 one/b.h5 two/b.h5
  fi
  check "2 ranks: the same sidecar" cmp -s one/b.xmf two/b.xmf
  # 1 when two scalar tables differ anywhere by more than a relative 1e-8, 0 when not
  scalars_differ() {
    paste -d, "$1" "$2" | awk -F, 'NR == 1 { n = NF / 2; next }
      { for (c = 1; c <= n; ++c) { a = $c; b = $(c + n); d = a - b; if (d < 0) d = -d; if (a < 0) a = -a;
          if (d > 1e-8 * a && d > 1e-300) m = 1 } } END { print m + 0 }'
  }
  ds=$(scalars_differ one/b_scalars.csv two/b_scalars.csv)
  check "2 ranks: the same scalars (within a relative 1e-8)" test "$ds" = 0 -a "$(wc -l < one/b_scalars.csv)" = 3
  check "2 ranks say so in the summary" grep -q "2 ranks)" c2.log
  # one file, the serial one's layout: the output of 2 and 3 ranks has the groups, datasets, types, shapes and
  # attributes of the 1-rank run's (h5dump -H), and every dataset (fields at every output time, checkpoint,
  # mesh) its values to the solver tolerance, relative to the dataset's largest value: the Stokes cavity (steady
  # navier_stokes, to its pressure's 1e-7 above), the boycott vessel (the mixture, 1e-9) and the cavity at Re = 100
  # in time (transient navier_stokes, BDF2, fixed steps, 1e-9). Then restarts on another number of ranks: a
  # 2-rank checkpoint continued on 3 ranks and on 1 (no mpirun, the default direct solver) ends where the
  # uninterrupted run ends, in its last fields and its checkpoint, to the same tolerance
  if command -v h5dump > /dev/null && command -v h5ls > /dev/null; then
    . "$(dirname "$0")/h5_fields.sh"
    last_step() { h5ls "$1" | awk '/^step_/ { s = $1 } END { print "/" s }'; }
    ck_time() { h5dump -a "$(h5_checkpoint "$1")/time" "$1" | sed -n 's/^ *(0): *//p'; }
    ns=(--set time.scheme=bdf2 --set time.dt=0.05 --set time.adaptive=false --set output.every=0.1
        --set mesh.cells=16,16 --set solver.linear=petsc)
    for n in 1 2 3; do
      mpirun -n $n "$sluice" run "$configs/cavity_re100.ini" "${ns[@]}" --set time.end=0.2 -o ns$n.h5 > ns$n.log 2>&1
    done
    for n in 2 3; do
      for pair in "c 1e-7 stokes cavity" "b 1e-9 boycott" "ns 1e-9 re100 cavity in time"; do
        read -r f tol what <<<"$pair"
        check "$what on $n ranks: the 1-rank file's layout" h5_layout $f"1.h5" $f$n.h5
        read -r dd at <<<"$(h5_files_diff $f"1.h5" $f$n.h5)"
        echo "$what on $n ranks against 1 rank: largest difference $dd (in $at)"
        check "$what on $n ranks: every dataset within $tol of 1 rank's ($dd in $at)" below "$dd" "$tol"
        check "$what on $n ranks: the 1-rank sidecar (ParaView's .xmf), but for the file's name" \
          cmp -s <(sed "s/$f$n\.h5/${f}1.h5/g" $f$n.xmf) $f"1.xmf"
        if [ -e $f"1_scalars.csv" ]; then
          check "$what on $n ranks: the 1-rank scalars (within a relative 1e-8)" \
            test -s $f$n"_scalars.csv" -a "$(scalars_differ $f"1_scalars.csv" $f$n"_scalars.csv")" = 0
        fi
      done
    done
    # restarts: the 2-rank checkpoints at half time, continued on 3 ranks and serially
    mpirun -n 2 "$sluice" run "$configs/cavity_re100.ini" "${ns[@]}" --set time.end=0.1 -o nh2.h5 > nh2.log 2>&1
    mpirun -n 3 "$sluice" run "$configs/cavity_re100.ini" "${ns[@]}" --set time.end=0.2 --restart nh2.h5 \
      -o nc3.h5 > nc3.log 2>&1
    "$sluice" run "$configs/cavity_re100.ini" "${ns[@]}" --set solver.linear=auto --set time.end=0.2 \
      --restart nh2.h5 -o nc1.h5 > nc1.log 2>&1
    mpirun -n 3 "$sluice" run "$box" "${args[@]/time.end=0.05/time.end=0.1}" --set solver.linear=petsc \
      --restart b2.h5 -o bc3.h5 > bc3.log 2>&1
    "$sluice" run "$box" "${args[@]/time.end=0.05/time.end=0.1}" --restart b2.h5 -o bc1.h5 > bc1.log 2>&1
    check "the re100 restart ran on 3 ranks" grep -q "3 ranks)" nc3.log
    check "the boycott restart ran on 3 ranks" grep -q "3 ranks)" bc3.log
    for pair in "ns1 nc3 re100 cavity, 2 ranks then 3" "ns1 nc1 re100 cavity, 2 ranks then serial" \
                "whole bc3 boycott, 2 ranks then 3" "whole bc1 boycott, 2 ranks then serial"; do
      read -r w c what <<<"$pair"
      read -r df at <<<"$(h5_files_diff $w.h5 $c.h5 "$(last_step $w.h5)" "$(last_step $c.h5)")"
      # the kept factorisation (arrays/linsolve_*) records how a run reached its state, not the state: a restart
      # on another number of ranks starts from a fresh one
      read -r dk atk <<<"$(h5_files_diff $w.h5 $c.h5 "$(h5_checkpoint $w.h5)" "$(h5_checkpoint $c.h5)" '/arrays/linsolve_')"
      echo "restart, $what: the last fields differ from the uninterrupted run's by $df ($at), the checkpoint by $dk"
      check "restart, $what: the last fields within 1e-9 ($df in $at)" below "$df" 1e-9
      check "restart, $what: the checkpoint within 1e-9 ($dk in $atk)" below "$dk" 1e-9
      check "restart, $what: the checkpoint at the same time" test -n "$(ck_time $c.h5)" -a "$(ck_time $c.h5)" = "$(ck_time $w.h5)"
    done
  else
    echo "h5dump not found: the files of several ranks are not compared dataset by dataset"
  fi
  # an output that may not be replaced: every rank stops (exit 2), none waits for another
  echo "not sluice's" > foreign.h5
  out=$(timeout 120 mpirun -n 2 "$sluice" run "$cav" --set mesh.cells=8,8 -o foreign.h5 2>&1); rc=$?
  check "2 ranks, an output rank 0 may not replace: exit 2 on every rank (exit $rc)" test "$rc" = 2
  check "... saying why" grep -q "was not written by sluice" <<<"$out"
  check "... and the file is as it was" grep -q "not sluice's" foreign.h5
  mpirun -n 2 "$sluice" run "$cav" -o auto.h5 > auto.log 2>&1
  check "linear = auto on 2 ranks is petsc" grep -q "(fgmres/fieldsplit, [0-9]* iterations, 2 ranks)" auto.log
  out=$(mpirun -n 2 "$sluice" run "$cav" --set solver.linear=klu -o no.h5 2>&1); rc=$?
  check "a direct solver on 2 ranks is refused (exit $rc)" test "$rc" != 0
  check "... saying why" grep -q "the linear solves must be PETSc's" <<<"$out"
  check "... before anything is written" test ! -e no.h5
  # the split step (projection.c) distributed: its velocity block and Poisson operator assembled on each rank's
  # cells and solved on its rows (GMRES with block Jacobi/ILU(0), CG with BoomerAMG), against the serial split
  # step with KLU (FGMRES with the diagonal blocks), 50 fixed steps with the solves tight so that the comparison
  # is of the ranks and not of the tolerances; then a 2-rank checkpoint continued on 1 rank (KLU) and on 3
  pj=(--set mesh.cells=12,16 --set output.every=0.05 --set time.adaptive=false --set flow.scheme=projection
    --set solver.nonlinear_tolerance=1e-12)
  tight=(--petsc "-velocity_ksp_rtol 1e-14 -poisson_ksp_rtol 1e-14")
  "$sluice" run "$box" "${pj[@]}" --set time.end=0.1 --set solver.linear=klu -o pk.h5 > pk.log 2>&1
  "$sluice" run "$box" "${pj[@]}" --set time.end=0.1 --set solver.linear=petsc "${tight[@]}" -o pp.h5 > pp.log 2>&1
  for n in 2 3; do
    mpirun -n $n "$sluice" run "$box" "${pj[@]}" --set time.end=0.1 --set solver.linear=petsc "${tight[@]}" \
      -o pm$n.h5 > pm$n.log 2>&1
  done
  mpirun -n 2 "$sluice" run "$box" "${pj[@]}" --set time.end=0.05 --set solver.linear=petsc "${tight[@]}" \
    -o ph.h5 > ph.log 2>&1
  "$sluice" run "$box" "${pj[@]}" --set time.end=0.1 --set solver.linear=klu --restart ph.h5 -o pc1.h5 > pc1.log 2>&1
  mpirun -n 3 "$sluice" run "$box" "${pj[@]}" --set time.end=0.1 --set solver.linear=petsc "${tight[@]}" \
    --restart ph.h5 -o pc3.h5 > pc3.log 2>&1
  check "split step on 2 ranks: both of its solves distributed" \
    grep -q "velocity 98 solves (petsc, gmres/bjacobi, [0-9]* iterations, 2 ranks); pressure Poisson 98 solves (petsc, cg/hypre" pm2.log
  for f in pk pp pm2 pm3 pc1 pc3; do
    "$sluice" sample $f.h5 --field velocity --line 0.5,0.1:1.2,0.9 --n 41 > ${f}_v.csv 2>/dev/null
    "$sluice" sample $f.h5 --field phi --line 0.5,0.1:1.2,0.9 --n 41 > ${f}_phi.csv 2>/dev/null
    "$sluice" sample $f.h5 --field pressure --line 0.5,0.1:1.2,0.9 --n 41 > ${f}_p.csv 2>/dev/null
  done
  for f in pp pm2 pm3 pc1 pc3; do
    dv=$(max_diff pk_v.csv ${f}_v.csv 6) dphi=$(max_diff pk_phi.csv ${f}_phi.csv 4) dp=$(max_diff pk_p.csv ${f}_p.csv 4)
    echo "split step, $f: velocity differs from KLU's serial run by $dv, phi by $dphi, pressure by $dp"
    check "split step, $f: velocity within 1e-10 ($dv)" below "$dv" 1e-10
    check "split step, $f: phi within 1e-10 ($dphi)" below "$dphi" 1e-10
    check "split step, $f: pressure within 1e-10 ($dp)" below "$dp" 1e-10
  done
  # linear = auto on 2 ranks: the scheme auto chooses does not depend on the number of ranks
  mpirun -n 2 "$sluice" run "$box" --set mesh.cells=12,16 --set time.end=0.02 --set output.every=0.02 \
    -o pa.h5 > pa.log 2>&1
  check "boycott on 2 ranks takes the split step, as on one (scheme = auto)" grep -q "projection: velocity" pa.log
else
  echo "mpirun not found: the runs on several ranks are not checked"
fi
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
