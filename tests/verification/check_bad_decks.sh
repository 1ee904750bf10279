#!/usr/bin/env bash
# Every malformed deck makes `kessler check` exit with code 1 and a single line on stderr that
# starts with "kessler: error:" and names the deck file and a line number.
set -uo pipefail
kessler=$1 dir=$2
failures=0 count=0
for deck in "$dir"/bad_*.yaml; do
  count=$((count + 1))
  err=$("$kessler" check "$deck" 2>&1 >/dev/null); code=$?
  lines=$(printf '%s\n' "$err" | wc -l)
  name=$(basename "$deck")
  if [ "$code" -ne 1 ] || [ "$lines" -ne 1 ] || ! printf '%s' "$err" | grep -q "^kessler: error: .*$name:[0-9]"; then
    echo "FAIL $name (exit $code, $lines lines): $err"; failures=$((failures + 1))
  fi
done
echo "$((count - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
