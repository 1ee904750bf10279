#!/usr/bin/env bash
# Restart, kill-and-resume, signal and failure tests of `kessler run` (docs/running.md).
#   restart_test.sh MODE KESSLER COMPARE_RUNS DECK WORK
# MODE:
#   reference    the uninterrupted run, WORK/reference (the fixture of the other modes)
#   equivalence  stop at half the steps (solver.max_steps), restart, compare bitwise
#   kill         SIGKILL at a random moment after the first checkpoint, restart, compare bitwise
#   sigterm      SIGTERM: exit code 143, a final checkpoint, status "interrupted"; restart, compare
#   sigint       the same with SIGINT and exit code 130
#   failure      a forced failure (solver.min_dt_fraction near 1): a one-line diagnosis, exit
#                code 1, the failed state as the last output, summary status "failed"
set -euo pipefail
mode=$1 kessler=$2 compare=$3 deck=$4 work=$5
reference=$work/reference
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}

fail() { echo "FAIL ($mode): $*" >&2; exit 1; }
json() { sed -n "s/^  \"$2\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$1/summary.json"; }
# The minimum number of eroded points the final state must have: the test must exercise erosion.
min_eroded=1

run_reference() {
  rm -rf "$reference"
  "$kessler" run "$deck" --out "$reference" --quiet
  [ "$(json "$reference" status)" = completed ] || fail "reference run did not complete"
}

restart_and_compare() {
  local dir=$1
  "$kessler" run --restart "$dir" --quiet --set solver.max_steps=0
  [ "$(json "$dir" status)" = completed ] || fail "restarted run did not complete: $(json "$dir" status)"
  "$compare" "$reference" "$dir" --min-eroded "$min_eroded" || fail "restarted run differs from the reference"
}

# Starts a run in the background into $1; sets $pid.
start_background() {
  rm -rf "$1"
  "$kessler" run "$deck" --out "$1" --quiet --set checkpoint.every=0.02us &
  pid=$!
}

# Waits until file $1 exists while $pid runs.
wait_for() {
  while [ ! -f "$1" ]; do
    kill -0 "$pid" 2>/dev/null || fail "the run ended before $1 appeared"
    sleep 0.02
  done
}

case "$mode" in
  reference)
    run_reference
    ;;
  equivalence)
    steps=$(json "$reference" steps)
    dir=$work/split
    rm -rf "$dir"
    "$kessler" run "$deck" --out "$dir" --quiet --set solver.max_steps=$((steps / 2))
    [ "$(json "$dir" status)" = stopped ] || fail "run with max_steps did not stop: $(json "$dir" status)"
    [ "$(json "$dir" steps)" = $((steps / 2)) ] || fail "stopped at step $(json "$dir" steps), not $((steps / 2))"
    restart_and_compare "$dir"
    echo "stopped at step $((steps / 2)) of $steps, restarted: bitwise identical"
    ;;
  kill)
    wall=$(json "$reference" wall_time_s)
    seed=${KILL_SEED:-$RANDOM}
    dir=$work/killed
    for attempt in 1 2 3; do
      start_background "$dir"
      wait_for "$dir/checkpoint.h5"
      # A random moment in the first 80% of the run (the seed is printed to reproduce a failure).
      delay=$(awk -v s="$seed" -v w="$wall" -v a="$attempt" \
        'BEGIN { srand(s + a); printf "%.3f", rand() * 0.8 * w / a }')
      sleep "$delay"
      kill -KILL "$pid" 2>/dev/null || true
      wait "$pid" 2>/dev/null && code=0 || code=$?
      [ "$code" -eq 137 ] && break
      echo "attempt $attempt: the run ended (exit $code) before the kill after ${delay} s; trying sooner"
    done
    [ "$code" -eq 137 ] || fail "could not kill the run while it was running"
    killed_at=$(ls "$dir/fields" | tail -1)
    restart_and_compare "$dir"
    echo "killed after ${delay} s (seed $seed; last output on disk $killed_at), restarted: bitwise identical"
    ;;
  sigterm | sigint)
    signal=${mode#sig}
    signal=${signal^^}
    expected=$([ "$signal" = TERM ] && echo 143 || echo 130)
    dir=$work/$mode
    start_background "$dir"
    # Once the second output is on disk the run is inside its time loop, with about three
    # quarters of its steps to go (a fixed delay after the first output raced a fast machine).
    while [ "$(ls "$dir/fields" 2>/dev/null | wc -l)" -lt 2 ]; do
      kill -0 "$pid" 2>/dev/null || fail "the run ended before its second output"
      sleep 0.01
    done
    kill -"$signal" "$pid"
    wait "$pid" && code=0 || code=$?
    [ "$code" -eq "$expected" ] || fail "exit code $code after SIG$signal, expected $expected"
    [ "$(json "$dir" status)" = interrupted ] || fail "status $(json "$dir" status), expected interrupted"
    [ -f "$dir/checkpoint.h5" ] || fail "no final checkpoint"
    grep -q "stopped by SIG$signal at step" "$dir/summary.json" || fail "summary.json does not say why it stopped"
    echo "SIG$signal at step $(json "$dir" steps): exit code $code, final checkpoint written"
    restart_and_compare "$dir"
    echo "restarted: bitwise identical"
    ;;
  failure)
    dir=$work/failure
    rm -rf "$dir"
    set +e
    err=$("$kessler" run "$deck" --out "$dir" --quiet --set solver.min_dt_fraction=0.999999 2>&1 >/dev/null)
    code=$?
    set -e
    echo "$err"
    [ "$code" -eq 1 ] || fail "exit code $code, expected 1"
    [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "the diagnosis is not one line"
    pattern="^kessler: error: step ([0-9]+), t = [^ ]+ s: material point [0-9]+ of body '[a-z]+' "
    pattern+="at \([^)]+\) m: time step collapsed: dt = "
    [[ "$err" =~ $pattern ]] || fail "the diagnosis does not name step, time, point, body, position and quantity"
    step=${BASH_REMATCH[1]}
    [ "$(json "$dir" status)" = failed ] || fail "summary status $(json "$dir" status), expected failed"
    [ -f "$dir/fields/$(printf 'fields_%08d.h5' "$step")" ] || fail "the failed state (step $step) was not written"
    grep -q "$(printf 'fields_%08d.h5' "$step")" "$dir/points.xdmf" || fail "points.xdmf does not list the failed state"
    ;;
  *)
    fail "unknown mode"
    ;;
esac
