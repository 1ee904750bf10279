#!/usr/bin/env bash
# `kessler run` across ranks against one process (docs/parallel.md): the same deck, and bitwise the
# same results (every field file, history.csv, points.xdmf and nodes.xdmf; compare_runs).
#   ranks_run_test.sh RANKS MPIEXEC KESSLER COMPARE_RUNS DECK WORK [--set ...]
# RANKS 1 writes the one-process reference, WORK/one (the fixture of the others). RANKS `restart`
# stops a 2-rank run halfway (solver.max_steps) and finishes it on one process from its checkpoint.
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
  dir=$work/restart
  rm -rf "$dir"
  half=$(($(json "$work/one" steps) / 2))
  "$mpiexec" -np 2 --oversubscribe "$kessler" run "$deck" --out "$dir" --quiet --threads 1 "$@" \
    --set solver.max_steps=$half
  [ "$(json "$dir" status)" = stopped ] || fail "the 2-rank run did not stop at step $half: $(json "$dir" status)"
  "$kessler" run --restart "$dir" --quiet --threads 1 --set solver.max_steps=0
  [ "$(json "$dir" status)" = completed ] || fail "the restarted run did not complete: $(json "$dir" status)"
  "$compare" "$work/one" "$dir" --min-eroded 20 || fail "2 ranks then one process differ from one process"
  exit 0
fi
dir=$work/ranks$ranks
rm -rf "$dir"
"$mpiexec" -np "$ranks" --oversubscribe "$kessler" run "$deck" --out "$dir" --quiet --threads 1 "$@"
[ "$(json "$dir" status)" = completed ] || fail "the run did not complete: $(json "$dir" status)"
[ "$(json "$dir" ranks)" = "$ranks" ] || fail "summary.json says $(json "$dir" ranks) ranks"
# The test must exercise failure, release and debris: eroded points in the last output.
"$compare" "$work/one" "$dir" --min-eroded 20 || fail "the results differ from one process's"
