#!/usr/bin/env bash
# `kessler run` across ranks against one process (docs/parallel.md): the same deck, and bitwise the
# same results (every field file, history.csv, points.xdmf and nodes.xdmf; compare_runs).
#   ranks_run_test.sh RANKS MPIEXEC KESSLER COMPARE_RUNS DECK WORK [--set ...]
# RANKS 1 writes the one-process reference, WORK/one (the fixture of the others). RANKS `restart`
# runs it in four parts (solver.max_steps), each restarted from the last one's checkpoint on another
# number of ranks: 1, 2, 3, then 1.
set -euo pipefail
ranks=$1 mpiexec=$2 kessler=$3 compare=$4 deck=$5 work=$6
shift 6
fail() { echo "FAIL ($ranks ranks): $*" >&2; exit 1; }
json() { sed -n "s/^  \"$2\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$1/summary.json"; }

if [ "$ranks" = 1 ]; then
  rm -rf "$work/one"
  "$kessler" run "$deck" --out "$work/one" --quiet --threads 1 "$@"
  [ "$(json "$work/one" status)" = completed ] || fail "the one-process run did not complete"
  exit 0
fi
if [ "$ranks" = restart ]; then
  # A checkpoint restarts on any number of ranks: one process stops at a quarter of the steps, 2 ranks
  # go on to half, 3 ranks to three quarters, and one process finishes.
  dir=$work/restart
  rm -rf "$dir"
  steps=$(json "$work/one" steps)
  "$kessler" run "$deck" --out "$dir" --quiet --threads 1 "$@" --set solver.max_steps=$((steps / 4))
  [ "$(json "$dir" status)" = stopped ] || fail "the first quarter did not stop: $(json "$dir" status)"
  for n in 2 3; do
    until=$((steps * n / 4))
    "$mpiexec" -np $n --oversubscribe "$kessler" run --restart "$dir" --quiet --threads 1 --set solver.max_steps=$until
    [ "$(json "$dir" status)" = stopped ] && [ "$(json "$dir" steps)" = $until ] ||
      fail "the restart on $n ranks did not stop at step $until: $(json "$dir" status)"
  done
  "$kessler" run --restart "$dir" --quiet --threads 1 --set solver.max_steps=0
  [ "$(json "$dir" status)" = completed ] || fail "the restarted run did not complete: $(json "$dir" status)"
  "$compare" "$work/one" "$dir" --min-eroded 20 || fail "restarted on 1, 2, 3 and 1 ranks, the run differs from one process"
  exit 0
fi
dir=$work/ranks$ranks
rm -rf "$dir"
"$mpiexec" -np "$ranks" --oversubscribe "$kessler" run "$deck" --out "$dir" --quiet --threads 1 "$@"
[ "$(json "$dir" status)" = completed ] || fail "the run did not complete: $(json "$dir" status)"
[ "$(json "$dir" ranks)" = "$ranks" ] || fail "summary.json says $(json "$dir" ranks) ranks"
# The helper programs run outside the job: with pvpython installed, the ParaView state is written
# (pvpython, linked with MPI, once joined the job, failed and hung its ranks in MPI_Finalize).
if command -v pvpython >/dev/null; then
  [ -f "$dir/kessler.pvsm" ] || fail "no kessler.pvsm: $(tail -3 "$dir/plots/paraview.log" 2>/dev/null)"
fi
# The test must exercise failure, release and debris: eroded points in the last output.
"$compare" "$work/one" "$dir" --min-eroded 20 || fail "the results differ from one process's"
